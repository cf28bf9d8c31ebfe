"""Both directions between a DEM code's setting and eps, for a modeller: one import for every
engine's designer (each lives with its engine, in restitution.dem.engines):

* audit: "these pair_coeff settings give this eps(v)" (:func:`lammps_audit`), including how far the
  e typed into LAMMPS' tsuji damping is from the eps it produces (:func:`tsuji_audit`);
* design: "these settings reach eps at v" (:func:`lammps_design`): the calibrated damping written
  as a ready ``pair_coeff`` line; :func:`liggghts_design` and :func:`yade_design` the same for the
  coefficientRestitution of LIGGGHTS and the ViscElMat / Hertz-Mindlin values of Yade;
* the typed e against the eps it really gives, for every registered engine whose damping is set
  from an e (:func:`typed_e_table`, rows from each engine's ``typed_e``).
"""

from __future__ import annotations

from .engines import ENGINES
from .engines.lammps.design import lammps_audit, lammps_design, tsuji_audit
from .engines.liggghts.design import liggghts_design
from .engines.yade.design import yade_design

__all__ = ["lammps_audit", "lammps_design", "tsuji_audit", "liggghts_design", "yade_design", "typed_e_table",
           "typed_e_codes", "TYPED_E_CODES", "TYPED_E_ENGINES", "TYPED_E_ENGINE_ES", "TYPED_E_ENGINE_RTOL"]


def typed_e_codes() -> dict:
    """{row: (function of e -> Contact, engine version)} of every registered engine, in registry
    order: each row gives eps as a function of e alone (D2 / sqrt(D1) depends on e only and Omega =
    D1 / D2^2 for these exponents), whatever the particles and the speed."""
    return {row: entry for engine in ENGINES.values() for row, entry in engine.typed_e.items()}


#: The codes whose damping is set from a typed restitution coefficient e (the shipped engines'
#: rows), and the engine (and the version run) that confirms each: the engine tests run every row
#: in its engine at each e of TYPED_E_ENGINE_ES and demand the row's eps to TYPED_E_ENGINE_RTOL
#: (relative, engine extrapolated to dt = 0). The manuscript's table prints these three, so the
#: claim it makes is the one the tests enforce.
TYPED_E_CODES = {row: law for row, (law, _) in typed_e_codes().items()}
TYPED_E_ENGINES = {row: version for row, (_, version) in typed_e_codes().items()}
#: Both ends of the table's range and its middle: the clamp matters most at small e, Thornton's fit
#: fails near e = 1.
TYPED_E_ENGINE_ES = (0.1, 0.5, 0.99)
TYPED_E_ENGINE_RTOL = 1e-6


def typed_e_table(es, codes=None) -> list[dict]:
    """For each typed e, the eps each code really gives (relative accuracy 1e-10: the library's
    reference integration at rtol 1e-12); ``codes``: the rows to give, every registered one by
    default."""
    laws = {row: law for row, (law, _) in typed_e_codes().items()}
    codes = list(laws) if codes is None else codes
    return [{"e": float(e), **{c: laws[c](float(e)).eps(1.0) for c in codes}} for e in es]
