"""Both directions between a LAMMPS setting and eps, for a modeller:

* audit: "these pair_coeff settings give this eps(v)" (:func:`lammps_audit`), including how far the
  e typed into LAMMPS' tsuji damping is from the eps it produces (:func:`tsuji_audit`);
* design: "these settings reach eps at v" (:func:`lammps_design`): the calibrated damping written
  as a ready ``pair_coeff`` line.
"""

from __future__ import annotations

from .calibrate import calibrate
from .codes import Pair, lammps_contact, lammps_eta_n0, lammps_pair_coeff, tsuji_a
from .contact import Contact

__all__ = ["lammps_audit", "lammps_design", "tsuji_audit"]


def lammps_audit(pair: Pair, speeds, **setting) -> dict:
    """eps(v) of a LAMMPS setting (keywords of codes.lammps_contact) at the given impact speeds."""
    contact = lammps_contact(pair, **setting)
    return {"pair_coeff": lammps_pair_coeff(**setting), **contact.as_dict(),
            "rows": [{"g": float(g), "eps": contact.eps(g), "contact_time": contact.contact_time(g)}
                     for g in speeds]}


def lammps_design(pair: Pair, *, eps: float, g: float, normal: str, damping: str, limit_damping: bool,
                  k_n=None, E=None, nu=None) -> dict:
    """The damping of ``damping`` that gives ``eps`` at impact speed ``g``, as a pair_coeff line."""
    stiffness = {"normal": normal, "k_n": k_n, "E": E, "nu": nu}
    base = lammps_contact(pair, damping=damping, eta_n0=0.5 if damping == "tsuji" else 1.0,
                          limit_damping=limit_damping, **stiffness)
    cal = calibrate(base.alpha, base.gamma, D1=base.D1, eps=eps, g=g, end=base.end)
    eta = lammps_eta_n0(pair, damping, cal.contact)
    setting = {**stiffness, "damping": damping, "eta_n0": eta, "limit_damping": limit_damping}
    return {"pair_coeff": lammps_pair_coeff(**setting), "eta_n0": eta, "eps": cal.eps[0], "g": g,
            **cal.contact.as_dict(), "contact_time": cal.contact.contact_time(g)}


def tsuji_audit(es, exponents=("3/2", "1/4")) -> list[dict]:
    """For LAMMPS' tsuji damping the e typed in is meant to be eps. Since D2 = A(e) sqrt(D1), Omega
    = 1 / A(e)^2 whatever the speed and the particles, so one row per e covers every contact:
    the eps LAMMPS really produces under each end rule."""
    alpha, gamma = exponents
    rows = []
    for e in es:
        a = tsuji_a(e)
        got = {end: Contact(alpha, gamma, 1.0, a, end).eps(1.0) for end in ("force", "overlap")}
        rows.append({"e": float(e), "A": a, "eps_limit_damping": got["force"], "eps_default": got["overlap"]})
    return rows
