"""What the method ladder builds for one pair of exponents, each piece on its own (issue 23: an
eps request builds only what it reads), cached and checked on load by :mod:`restitution.fast.ladder`:

* the master curve (``MASTER``, a tenth of a second to a few seconds) and, from its calibration
  grid, the measured errors of the rungs that need nothing else (the expansions, the Pade form):
  a :class:`Calibration`;
* one build per relation rung (``relation_build(name)``): its c0-c2 (the paper's perturbation
  route takes seconds an order); their errors are measured on the master curve's grid when loaded,
  so a stored c0-c2 is always quoted with the error it really has;
* the uniform approximation (``UNIFORM``, :mod:`restitution.fast.uniform_build`) and its overlap-rule
  twin (``UNIFORM_OVERLAP``, gamma < alpha < 2 gamma + 1);
* the master curve's check against the mpmath reference (``MPMATH``,
  :func:`restitution.fast.master.mpmath_check`), which can only widen the curve's bound.

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
           "MUELLER_POESCHEL_PADE", "CALIBRATION_VERSION", "MASTER", "UNIFORM", "UNIFORM_OVERLAP", "MPMATH", "relation_build",
           "relation_dict", "measure_master", "measure_relation", "merged"]

#: Version of the stored relation builds and mpmath checks; bump to invalidate caches.
CALIBRATION_VERSION = 4
#: Build names (what a rung's ``needs`` gives).
MASTER, UNIFORM, MPMATH = "master curve", "uniform form", "mpmath check"
UNIFORM_OVERLAP = "overlap rule's uniform form"


def relation_build(name: str) -> str:
    """The build name of the relation rung ``name``."""
    return f"{name} relation"
#: Omega range of the c0-c2 fit (the claims ledger fits the paper's material over g in [0.01, 1],
#: i.e. Omega in [0.098, 3.1]).
FIT_OMEGA = (0.1, 3.0, 41)
#: Mueller & Poeschel, PRE 84, 021302 (2011), alpha = 3/2, gamma = 1/2:
#: eps = (1 + a v) / (1 + a v + b2 v^2 + b3 v^3 + b4 v^4), v = Omega^(-3/10) (their sqrt(beta) g^(1/10)
#: in our scaling). Coefficients as Granulars.jl's getA.py implements them (a secondary source; they are not
#: compared with the numbers printed in the paper). They are consistent with the exact expansion: the v^2
#: term is -C1, the v^3 term vanishes (b3 = a b2 to 6 digits) and the v^4 term is C2 = (3/5) C1^2 to 6
#: digits (checked in the tests).
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
    #: Seconds to derive its c0-c2 on the 2-core machine (what the chooser prices it at before it
    #: has built one itself).
    build_seconds: float = 0.05


def _fitted_c(ex: Exponents, progress) -> tuple:
    lo, hi, n = FIT_OMEGA
    om = np.geomspace(lo, hi, n)
    try:
        eps = reference_eps(ex, om, 1e-13)
        fit = fit_quadratic(om, rebound_omega(ex, om, eps))
    except Exception as exc:  # noqa: BLE001 - a rung that cannot be built is reported, not fatal
        raise RelationUnavailable(f"fit failed: {exc}") from exc
    return fit.c, f"least squares on Omega in [{lo}, {hi}], {n} points"


FITTED_C = Relation("fitted-c", _fitted_c)


def relation_dict(ex: Exponents, relation: Relation, progress=None) -> dict:
    """The stored form of one relation rung: its c0-c2 and their source, or why it has none."""
    say = progress or (lambda m: None)
    d = {"version": CALIBRATION_VERSION, "alpha": str(ex.alpha), "gamma": str(ex.gamma), "name": relation.name}
    if ex.omega_exponent == 0:
        return {**d, "unavailable": "alpha - 1 - 2 gamma = 0: Omega~ = Omega whatever eps is, the relation is empty"}
    try:
        c, source = relation.coefficients(ex, say)
    except RelationUnavailable as exc:
        return {**d, "unavailable": str(exc)}
    return {**d, "c": [float(x) for x in c], "source": source}


# ------------------------------------------------------------------------------------- calibration
@dataclass
class Calibration:
    """A master curve with the measured errors (``profiles``, on ``master.grid_log10_omega``) of the
    rungs it measures, the relations' c0-c2 among them, and (when merged) the uniform form."""

    master: MasterCurve
    profiles: dict            # rung -> np.ndarray of relative errors on master.grid_log10_omega
    relations: dict           # rung -> {"c": [c0, c1, c2], "source": str}
    unavailable: dict         # rung -> reason
    uniform: UniformForm | None = None   # the uniform approximation (alpha > gamma)


def measure_master(master: MasterCurve) -> Calibration:
    """The expansions' and the Pade form's errors on the curve's grid (milliseconds)."""
    ex = as_exponents(master.alpha, master.gamma)
    grid = 10.0 ** master.grid_log10_omega
    ref = master.grid_eps
    profiles, missing = {}, {}
    if ex.alpha == Fraction(3, 2) and ex.gamma == Fraction(1, 2):
        profiles["pade-mp2011"] = _rel_err(pade_mp2011(grid), ref)
    else:
        missing["pade-mp2011"] = "the Pade form is for alpha = 3/2, gamma = 1/2 only"
    profiles["viscous"] = _rel_err(master.viscous_eps(grid), ref)
    profiles["elastic"] = _rel_err(master.elastic.eps(grid, 2), ref)
    return Calibration(master, profiles, {}, missing)


def measure_relation(master: MasterCurve, d: dict) -> Calibration:
    """One stored relation with its error on the curve's grid, computed from the c0-c2 it holds."""
    name = d["name"]
    if "c" not in d:
        return Calibration(master, {}, {}, {name: d["unavailable"]})
    c = [float(x) for x in d["c"]]
    if len(c) != 3:
        raise ValueError("a relation has three coefficients")
    ex = as_exponents(master.alpha, master.gamma)
    err = _rel_err(eps_from_connection(ex, 10.0 ** master.grid_log10_omega, c), master.grid_eps)
    return Calibration(master, {name: err}, {name: {"c": c, "source": d["source"]}}, {})


def merged(parts) -> Calibration:
    """One Calibration from the pieces built for one curve (what :meth:`Ladder.calibration` returns)."""
    parts = [p for p in parts if isinstance(p, Calibration)]
    out = Calibration(parts[0].master, {}, {}, {})
    for p in parts:
        out.profiles.update(p.profiles)
        out.relations.update(p.relations)
        out.unavailable.update(p.unavailable)
    return out


def build_calibration(problem, settings: MasterSettings | None = None, progress=None,
                      relations=(FITTED_C,)) -> Calibration:
    """Everything at once, without a cache (the benchmark times it): the master curve with its
    mpmath check (``settings.n_highprec`` points), each relation rung and the uniform form (none for
    alpha = 2 gamma + 1, whose exact-family rung answers exactly)."""
    ex = as_exponents(problem)
    say = progress or (lambda m: None)
    master = build_master(ex, settings, progress=say)
    cal = merged([measure_master(master), *(measure_relation(master, relation_dict(ex, r, say)) for r in relations)])
    # alpha = 2 gamma + 1 needs no fitted form: the exact-family rung answers to rounding
    fitted = ex.alpha > ex.gamma and ex.alpha != 2 * ex.gamma + 1
    cal.uniform = build_uniform(ex, say) if fitted else None
    return cal
