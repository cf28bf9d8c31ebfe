"""Both directions between a LAMMPS ``pair_style granular`` setting and eps: the eps(v) of a
pair_coeff setting (:func:`lammps_audit`), how far the e typed into tsuji damping is from the eps it
produces (:func:`tsuji_audit`), and the damping that reaches an eps at a speed, as a ready
``pair_coeff`` line (:func:`lammps_design`)."""

from __future__ import annotations

from ...calibrate import calibrate
from ...contact import Contact
from ...design import refuse_passing_through
from ...pair import Pair
from .contact import base_eta_n0, lammps_contact, lammps_eta_n0, lammps_pair_coeff, restitution_b, tsuji_a

__all__ = ["lammps_audit", "lammps_design", "tsuji_audit", "TYPED_E"]


def lammps_audit(pair: Pair, speeds, **setting) -> dict:
    """eps(v) of a LAMMPS setting (keywords of codes.lammps_contact) at the given impact speeds; at a
    speed where the spheres' centres would meet (Contact.reaches R1 + R2) no eps and no t_c:
    ``passes_through`` instead.

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    speeds : iterable of float
        Impact speeds g.
    **setting
        The keywords of :func:`~restitution.dem.engines.lammps.contact.lammps_contact`.

    Returns
    -------
    dict
        {"pair_coeff", the contact's fields, "overlap_limit", "rows": one {"g", "eps",
        "contact_time", "passes_through"} per speed}.

    Raises
    ------
    ParameterError
        Where the setting is not one LAMMPS takes.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> res = lammps_audit(pair, [1.0], normal="hertz", damping="tsuji", eta_n0=0.5, limit_damping=False, k_n=1e6)
    >>> round(res["rows"][0]["eps"], 6), res["rows"][0]["passes_through"]
    (0.616076, False)
    """
    contact = lammps_contact(pair, **setting)
    rows = []
    for g in speeds:
        through = contact.reaches(g, pair.R1 + pair.R2)
        rows.append({"g": float(g), "eps": None if through else contact.eps(g),
                     "contact_time": None if through else contact.contact_time(g), "passes_through": through})
    return {"pair_coeff": lammps_pair_coeff(**setting), **contact.as_dict(), "overlap_limit": pair.R1 + pair.R2,
            "rows": rows}


def lammps_design(pair: Pair, *, eps: float, g: float, normal: str, damping: str, limit_damping: bool,
                  k_n=None, E=None, nu=None) -> dict:
    """The damping of ``damping`` that gives ``eps`` at impact speed ``g``, as a pair_coeff line.

    Parameters
    ----------
    pair, eps : Pair, float
        The pair, and the eps to reach (as :meth:`~restitution.dem.engine.Engine.design` takes them).
    g : float
        The impact speed it is reached at.
    normal, damping, limit_damping, k_n, E, nu
        As :func:`~restitution.dem.engines.lammps.contact.lammps_contact` takes them (the damping
        model whose eta_n0 is sought).

    Returns
    -------
    dict
        {"pair_coeff", "eta_n0", "eps", "g", the contact's fields, "contact_time"}.

    Raises
    ------
    ParameterError
        Where no eta_n0 reaches eps, or the spheres would pass through each other at g.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> d = lammps_design(pair, eps=0.7, g=1.0, normal="hertz", damping="viscoelastic", limit_damping=True, k_n=1e6)
    >>> d["pair_coeff"]
    'pair_coeff * * hertz 1000000 8882138.73725 damping viscoelastic tangential linear_nohistory 0 0 limit_damping'
    >>> round(d["eps"], 9)
    0.7
    """
    stiffness = {"normal": normal, "k_n": k_n, "E": E, "nu": nu}
    base = lammps_contact(pair, damping=damping, eta_n0=base_eta_n0(damping),
                          limit_damping=limit_damping, **stiffness)
    cal = calibrate(base.alpha, base.gamma, D1=base.D1, eps=eps, g=g, end=base.end)
    refuse_passing_through(cal.contact, pair, eps, g, "LAMMPS")
    eta = lammps_eta_n0(pair, damping, cal.contact)
    setting = {**stiffness, "damping": damping, "eta_n0": eta, "limit_damping": limit_damping}
    return {"pair_coeff": lammps_pair_coeff(**setting), "eta_n0": eta, "eps": cal.eps[0], "g": g,
            **cal.contact.as_dict(), "contact_time": cal.contact.contact_time(g)}


def tsuji_audit(es, exponents=("3/2", "1/4")) -> list[dict]:
    """For LAMMPS' tsuji damping the e typed in is meant to be eps. Since D2 = A(e) sqrt(D1), Omega
    = 1 / A(e)^2 whatever the speed and the particles, so one row per e covers every contact:
    the eps LAMMPS really produces under each end rule.

    Parameters
    ----------
    es : iterable of float
        The typed e, each in (0, 1).
    exponents : tuple of str, optional
        (alpha, gamma) of the normal model: hertz's by default.

    Returns
    -------
    list of dict
        One {"e", "A", "eps_limit_damping" (the force rule), "eps_default" (the overlap rule)} per e.

    Examples
    --------
    >>> [(r["e"], round(r["eps_limit_damping"], 4), round(r["eps_default"], 4)) for r in tsuji_audit([0.5, 0.9])]
    [(0.5, 0.6458, 0.6161), (0.9, 0.9294, 0.9284)]
    """
    alpha, gamma = exponents
    rows = []
    for e in es:
        a = tsuji_a(e)
        got = {end: Contact(alpha, gamma, 1.0, a, end).eps(1.0) for end in ("force", "overlap")}
        rows.append({"e": float(e), "A": a, "eps_limit_damping": got["force"], "eps_default": got["overlap"]})
    return rows


#: The settings whose damping is set from a typed e: each row's contact as a function of e (D2 /
#: sqrt(D1) depends on e only, and Omega = D1 / D2^2 for these exponents)
TYPED_E = {
    "LAMMPS hertz + damping tsuji, limit_damping": lambda e: Contact("3/2", "1/4", 1.0, tsuji_a(e), "force"),
    "LAMMPS hertz + damping tsuji (default)": lambda e: Contact("3/2", "1/4", 1.0, tsuji_a(e), "overlap"),
    "LAMMPS hertz + damping coeff_restitution, limit_damping":
        lambda e: Contact("3/2", "1/4", 1.0, restitution_b(e, "3/2"), "force"),
    "LAMMPS hertz + damping coeff_restitution (default)":
        lambda e: Contact("3/2", "1/4", 1.0, restitution_b(e, "3/2"), "overlap"),
}
