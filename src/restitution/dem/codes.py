"""DEM codes' contact options <-> the model (alpha, gamma, D1, D2, end rule), for two particles.

Head-on, the overlap delta of two spheres obeys m delta'' + F_el + eta delta' = 0 with the effective
mass m = m1 m2 / (m1 + m2) and radius R = R1 R2 / (R1 + R2); dividing by m gives the model.

LAMMPS ``pair_style granular`` (normal model, damping model, ``limit_damping``), as the engine
applies them (checked against LAMMPS itself in tests/test_dem_lammps.py):

==================  =====  ==============================  =====  ===================================
option              alpha  D1                              gamma  D2
==================  =====  ==============================  =====  ===================================
hooke k_n           1      k_n / m
hertz k_n           3/2    k_n sqrt(R) / m
hertz/material E nu 3/2    (4/3) E* sqrt(R) / m
damping velocity                                           0      eta_n0 / m
damping mass_velocity                                      0      eta_n0
damping viscoelastic                                       1/2    eta_n0 sqrt(R)
damping tsuji e                                            (alpha-1)/2  A(e) sqrt(D1)
==================  =====  ==============================  =====  ===================================

E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (E / (2 (1 - nu^2)) for like particles); A(e) is the
polynomial LAMMPS documents for tsuji damping. ``limit_damping`` clips the normal force at zero:
the "force" end rule; without it (the default) contact lasts until delta = 0: "overlap".

LIGGGHTS ``model hertz`` (Hertz with coefficientRestitution e, youngsModulus, poissonsRatio; its
documented damping gamma_n = 2 sqrt(5/6) beta sqrt(S_n m), S_n = 2 E* sqrt(R delta),
beta = -ln e / sqrt(ln^2 e + pi^2)): alpha = 3/2, D1 = (4/3) E* sqrt(R)/m, gamma = 1/4,
D2 = sqrt(5) beta sqrt(D1); ``limitForce off`` (default) = "overlap", ``on`` = "force".
MercuryDPM's Hertzian viscoelastic species set from an elastic modulus and a restitution
coefficient uses the same Tsuji-type law; its LinearViscoelastic species set from a collision
time t_c and restitution e (setCollisionTimeAndRestitutionCoefficient with the effective mass)
gives k = m (pi^2 + ln^2 e) / t_c^2, eta = -2 m ln e / t_c: alpha = 1, gamma = 0, D1 = k/m,
D2 = eta/m. Both codes let the normal force turn attractive: "overlap". These two codes were not
run here; their rows follow their documentation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from scipy.optimize import brentq

from ..core.errors import ParameterError, derived_in_range, one_of, require_positive_finite
from .contact import Contact

__all__ = ["Pair", "tsuji_a", "lammps_contact", "lammps_pair_coeff", "liggghts_contact", "mercury_linear_contact",
           "NORMAL_MODELS", "DAMPING_MODELS"]

NORMAL_MODELS = ("hooke", "hertz", "hertz/material")
DAMPING_MODELS = ("velocity", "mass_velocity", "viscoelastic", "tsuji")
#: LAMMPS' documented fit for tsuji damping: eta_n = A(e) sqrt(m k), A a polynomial in e.
TSUJI_POLY = (1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218)


@dataclass(frozen=True)
class Pair:
    """Two particles: radii and masses (SI or any consistent units)."""

    R1: float
    R2: float
    m1: float
    m2: float
    #: the densities when built by :meth:`spheres`: named in messages instead of masses nobody typed
    densities: tuple | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        for name in ("R1", "R2", "m1", "m2"):
            require_positive_finite(name, getattr(self, name))

    @classmethod
    def spheres(cls, R1: float, R2: float, density1: float, density2: float | None = None) -> "Pair":
        d2 = density1 if density2 is None else density2
        for name, v in (("R1", R1), ("R2", R2), ("density1", density1), ("density2", d2)):
            require_positive_finite(name, v)
        vol = lambda r: 4.0 / 3.0 * math.pi * _pow(r, 3)   # noqa: E731
        # the masses are ours, not the user's: out of range, the message names radius and density
        m1, m2 = density1 * vol(R1), d2 * vol(R2)
        m1 = derived_in_range("the mass m1", m1, {"radius R1": R1, "density1": density1})
        m2 = derived_in_range("the mass m2", m2, {"radius R2": R2, "density2": d2})
        pair = cls(R1, R2, m1, m2, (density1, d2))
        derived_in_range("the effective mass", pair.m, {"radii": (R1, R2), "densities": (density1, d2)})
        derived_in_range("the effective radius", pair.R, {"radii": (R1, R2)})
        return pair

    @property
    def m(self) -> float:
        return _harmonic(self.m1, self.m2)

    @property
    def R(self) -> float:
        return _harmonic(self.R1, self.R2)


def _harmonic(a: float, b: float) -> float:
    """a b / (a + b); where the product leaves doubles (tiny or huge particles), a / (1 + a / b),
    which stays in range whenever the result does (the usual form kept for unchanged digits)."""
    prod = a * b
    if 2.2250738585072014e-308 <= prod < math.inf:
        return prod / (a + b)
    return a / (1.0 + a / b)


def _pow(a: float, b: float) -> float:
    """a ** b without OverflowError: inf instead (then named by derived_in_range)."""
    try:
        return a ** b
    except OverflowError:
        return math.inf


def tsuji_a(e: float) -> float:
    return sum(c * e ** k for k, c in enumerate(TSUJI_POLY))


def _e_from_tsuji_a(a: float) -> float:
    lo, hi = tsuji_a(1.0), tsuji_a(0.0)
    if not lo < a < hi:
        raise ParameterError("D2", a, f"needs A(e) = D2 / sqrt(D1) in ({lo:.4g}, {hi:.4g}), what tsuji's e in "
                                      "(0, 1) can give")
    return brentq(lambda e: tsuji_a(e) - a, 0.0, 1.0, xtol=1e-15)


def _d1(pair: Pair, normal: str, k_n: float | None, E: float | None, nu: float | None) -> tuple[str, float]:
    normal = one_of("normal", normal, NORMAL_MODELS)
    if normal == "hertz/material":
        E = require_positive_finite("E", E)
        if nu is None or not -1.0 < nu < 0.5:
            raise ParameterError("nu", nu, "must be a Poisson ratio in (-1, 0.5)")
        e_star = E / (2.0 * (1.0 - nu ** 2))
        d1 = 4.0 / 3.0 * e_star * math.sqrt(pair.R) / pair.m
        return "3/2", derived_in_range("the stiffness D1", d1, {"E": E, **_pair_inputs(pair)})
    k_n = require_positive_finite("k_n", k_n)
    d1 = k_n / pair.m if normal == "hooke" else k_n * math.sqrt(pair.R) / pair.m
    return "1" if normal == "hooke" else "3/2", derived_in_range("the stiffness D1", d1, {"k_n": k_n, **_pair_inputs(pair)})


def _pair_inputs(pair: Pair) -> dict:
    """The pair as the user gave it, for messages (radii; masses stand for radius and density)."""
    if pair.densities is not None:
        return {"radii": (pair.R1, pair.R2), "densities": pair.densities}
    return {"radii": (pair.R1, pair.R2), "masses": (pair.m1, pair.m2)}


def _damping_exponent(alpha: str, damping: str) -> str:
    return {"velocity": "0", "mass_velocity": "0", "viscoelastic": "1/2",
            "tsuji": "0" if alpha == "1" else "1/4"}[damping]


def lammps_contact(pair: Pair, *, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                   k_n: float | None = None, E: float | None = None, nu: float | None = None) -> Contact:
    """The model a LAMMPS ``pair_style granular`` setting gives for this pair (``eta_n0`` is e for tsuji)."""
    alpha, D1 = _d1(pair, normal, k_n, E, nu)
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping == "tsuji":
        if not 0.0 < eta_n0 < 1.0:
            raise ParameterError("eta_n0", eta_n0, "is tsuji's e: must be in (0, 1)")
        D2 = tsuji_a(eta_n0) * math.sqrt(D1)
    else:
        eta = require_positive_finite("eta_n0", eta_n0)
        D2 = {"velocity": eta / pair.m, "mass_velocity": eta, "viscoelastic": eta * math.sqrt(pair.R)}[damping]
        D2 = derived_in_range("the damping D2", D2, {"eta_n0": eta, **_pair_inputs(pair)})
    return Contact(alpha, _damping_exponent(alpha, damping), D1, D2, "force" if limit_damping else "overlap")


def lammps_eta_n0(pair: Pair, damping: str, contact: Contact) -> float:
    """The inverse of lammps_contact's damping column: eta_n0 (or tsuji's e) that gives contact.D2."""
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping == "tsuji":
        return _e_from_tsuji_a(contact.D2 / math.sqrt(contact.D1))
    eta = {"velocity": contact.D2 * pair.m, "mass_velocity": contact.D2,
           "viscoelastic": contact.D2 / math.sqrt(pair.R)}[damping]
    return derived_in_range("LAMMPS' eta_n0", eta, {"D2": contact.D2, **_pair_inputs(pair)})


def lammps_pair_coeff(*, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                      k_n: float | None = None, E: float | None = None, nu: float | None = None) -> str:
    """The ``pair_coeff`` line of that setting (frictionless tangential model: head-on contacts)."""
    args = f"{E:.12g} {eta_n0:.12g} {nu:.12g}" if normal == "hertz/material" else f"{k_n:.12g} {eta_n0:.12g}"
    line = f"pair_coeff * * {normal} {args} damping {damping} tangential linear_nohistory 0 0"
    return line + (" limit_damping" if limit_damping else "")


def liggghts_contact(pair: Pair, *, E: float, nu: float, e: float, limit_force: bool = False) -> Contact:
    """LIGGGHTS ``model hertz`` with coefficientRestitution e (like particles)."""
    _, D1 = _d1(pair, "hertz/material", None, E, nu)
    return Contact("3/2", "1/4", D1, math.sqrt(5.0) * _beta(e) * math.sqrt(D1), "force" if limit_force else "overlap")


def mercury_linear_contact(pair: Pair, *, t_c: float, e: float) -> Contact:
    """MercuryDPM LinearViscoelastic species from setCollisionTimeAndRestitutionCoefficient(t_c, e, m)."""
    t_c = require_positive_finite("t_c", t_c)
    ln_e = math.log(_unit("e", e))
    return Contact("1", "0", (math.pi ** 2 + ln_e ** 2) / t_c ** 2, -2.0 * ln_e / t_c, "overlap")


def _unit(name: str, e: float) -> float:
    if not 0.0 < e < 1.0:
        raise ParameterError(name, e, "must be a restitution coefficient in (0, 1)")
    return float(e)


def _beta(e: float) -> float:
    ln_e = math.log(_unit("e", e))
    return -ln_e / math.sqrt(ln_e ** 2 + math.pi ** 2)
