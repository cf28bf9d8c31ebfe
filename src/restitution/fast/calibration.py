"""The calibration bundle of the method ladder: the master curve and the measured errors of the
cheap rungs on its grid, built once per pair of exponents and cached (:mod:`restitution.fast.cache`).

Relation rungs evaluate eps = (Omega~/Omega)^((gamma+1)/(alpha-1-2gamma)) with
Omega~ = c0 + c1 Omega + c2 Omega^2; each is a :class:`Relation`: a name and where its c0-c2 come
from. This layer knows one, ``fitted-c`` (least squares on the exact connection); the paper's own
c's are added from the audit layer by :mod:`restitution.api`.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from typing import Callable

import numpy as np

from ..core.connection import eps_from_connection, fit_quadratic, rebound_omega
from ..core.exponents import Exponents, as_exponents
from ..core.uniform import UniformForm
from .master import MasterCurve, MasterSettings, build_master, reference_eps
from .uniform_build import build_uniform

__all__ = ["Calibration", "Relation", "RelationUnavailable", "FITTED_C", "build_calibration", "pade_mp2011",
           "MUELLER_POESCHEL_PADE", "CALIBRATION_VERSION"]

#: Version of the calibration bundle (master curve + profiles); bump to invalidate caches.
CALIBRATION_VERSION = 3
#: Omega range of the c0-c2 fit (the claims ledger fits the paper's material over g in [0.01, 1],
#: i.e. Omega in [0.098, 3.1]).
FIT_OMEGA = (0.1, 3.0, 41)
#: Mueller & Poeschel, PRE 84, 021302 (2011), alpha = 3/2, gamma = 1/2:
#: eps = (1 + a v) / (1 + a v + b2 v^2 + b3 v^3 + b4 v^4), v = Omega^(-3/10) (their sqrt(beta) g^(1/10)
#: in our scaling). Coefficients as used in a public implementation; we could not read the paper
#: itself. They are consistent with the exact expansion: the v^2 term is -C1, the v^3 term vanishes
#: (b3 = a b2 to 6 digits) and the v^4 term is C2 = (3/5) C1^2 to 6 digits (checked in the tests).
MUELLER_POESCHEL_PADE = {"a": 0.501086, "b2": 1.15345, "b3": 0.577977, "b4": 0.532178}


def pade_mp2011(omega) -> np.ndarray:
    """Mueller & Poeschel's Pade approximant (alpha = 3/2, gamma = 1/2) in our Omega."""
    c = MUELLER_POESCHEL_PADE
    v = np.asarray(omega, dtype=float) ** -0.3
    return (1.0 + c["a"] * v) / (1.0 + v * (c["a"] + v * (c["b2"] + v * (c["b3"] + v * c["b4"]))))


def _rel_err(approx: np.ndarray, ref: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore", divide="ignore"):
        e = np.abs(approx / ref - 1.0)
    return np.where(np.isfinite(e), e, np.inf)


class RelationUnavailable(Exception):
    """A relation rung has no c0-c2 for these exponents; the message says why."""


@dataclass(frozen=True)
class Relation:
    """A relation rung: its name and ``coefficients(ex, progress) -> (c0-c2, source)``, which raises
    :class:`RelationUnavailable` where the relation does not exist."""

    name: str
    coefficients: Callable


def _fitted_c(ex: Exponents, progress) -> tuple:
    lo, hi, n = FIT_OMEGA
    om = np.geomspace(lo, hi, n)
    try:
        eps = reference_eps(ex, None, om, 1e-13)
        fit = fit_quadratic(om, rebound_omega(ex, om, eps))
    except Exception as exc:  # noqa: BLE001 - a rung that cannot be built is reported, not fatal
        raise RelationUnavailable(f"fit failed: {exc}") from exc
    return fit.c, f"least squares on Omega in [{lo}, {hi}], {n} points"


FITTED_C = Relation("fitted-c", _fitted_c)


def _relations_for(ex: Exponents, relations, progress) -> tuple[dict, dict]:
    """c0-c2 of each relation rung, or why it has none."""
    rel, missing = {}, {}
    if ex.omega_exponent == 0:
        reason = "alpha - 1 - 2 gamma = 0: Omega~ = Omega whatever eps is, the relation is empty"
        return rel, {r.name: reason for r in relations}
    for r in relations:
        try:
            c, source = r.coefficients(ex, progress)
        except RelationUnavailable as exc:
            missing[r.name] = str(exc)
            continue
        rel[r.name] = {"c": [float(x) for x in c], "source": source}
    return rel, missing


# ------------------------------------------------------------------------------------- calibration
@dataclass
class Calibration:
    """Master curve + measured error profiles of the approximate rungs on the calibration grid."""

    master: MasterCurve
    profiles: dict            # rung -> np.ndarray of relative errors on master.grid_log10_omega
    relations: dict           # rung -> {"c": [c0, c1, c2], "source": str}
    unavailable: dict         # rung -> reason
    uniform: UniformForm | None = None   # the uniform closed form (alpha > gamma)

    def as_dict(self) -> dict:
        return {"version": CALIBRATION_VERSION, "master": self.master.as_dict(),
                "profiles": {k: [None if not np.isfinite(x) else float(x) for x in v]
                             for k, v in self.profiles.items()},
                "relations": self.relations, "unavailable": self.unavailable,
                "uniform": None if self.uniform is None else self.uniform.as_dict()}

    @classmethod
    def from_dict(cls, d: dict) -> "Calibration":
        if d.get("version") != CALIBRATION_VERSION:
            raise ValueError("calibration version mismatch")
        prof = {k: np.array([np.inf if x is None else x for x in v], dtype=float)
                for k, v in d["profiles"].items()}
        uni = d.get("uniform")
        return cls(MasterCurve.from_dict(d["master"]), prof, d["relations"], d["unavailable"],
                   None if uni is None else UniformForm.from_dict(uni))


def build_calibration(alpha, gamma, settings: MasterSettings | None = None, progress=None,
                      relations=(FITTED_C,)) -> Calibration:
    """The master curve, and each cheap rung's relative error on its grid (``relations``: the relation rungs)."""
    ex = as_exponents(alpha, gamma)
    say = progress or (lambda m: None)
    master = build_master(ex, None, settings, progress=say)
    grid = 10.0 ** master.grid_log10_omega
    ref = master.grid_eps
    rel, missing = _relations_for(ex, relations, say)
    profiles = {name: _rel_err(eps_from_connection(ex, None, grid, r["c"]), ref) for name, r in rel.items()}
    if ex.alpha == Fraction(3, 2) and ex.gamma == Fraction(1, 2):
        profiles["pade-mp2011"] = _rel_err(pade_mp2011(grid), ref)
    else:
        missing["pade-mp2011"] = "the Pade form is for alpha = 3/2, gamma = 1/2 only"
    profiles["viscous"] = _rel_err(master.viscous_eps(grid), ref)
    profiles["elastic"] = _rel_err(master.elastic.eps(grid, 2), ref)
    uniform = build_uniform(ex, None, say) if ex.alpha > ex.gamma else None
    return Calibration(master, profiles, rel, missing, uniform)

