"""LIGGGHTS 3.8 ``pair_style gran`` <-> the model (alpha, gamma, D1, D2, end rule), for two particles.

``model hertz`` (Hertz with coefficientRestitution e, youngsModulus, poissonsRatio; its documented
damping gamma_n = 2 sqrt(5/6) beta sqrt(S_n m), S_n = 2 E* sqrt(R delta), beta = -ln e /
sqrt(ln^2 e + pi^2)): alpha = 3/2, D1 = (4/3) E* sqrt(R)/m, gamma = 1/4, D2 = sqrt(5) beta
sqrt(D1); ``limitForce off`` (default) = "overlap", ``on`` = "force".

``model hooke`` (checked against the engine in tests/library/test_dem_liggghts.py): k_n = (16/15)
sqrt(R) E* (15 m V^2 / (16 sqrt(R) E*))^(1/5) with V the ``characteristicVelocity``, gamma_n = 2
beta sqrt(m k_n): alpha = 1, gamma = 0, D1 = k_n/m, D2 = 2 beta sqrt(D1). With ``limitForce off``
eps is e exactly at every speed; with ``on`` it is higher (the force rule on a linear dashpot).

``model hooke/stiffness`` and ``model hertz/stiffness`` take the stiffness and the damping as
typed, per type pair (``fix property/global kn``, ``gamman`` or, with hooke/stiffness's
``absolute_damping on``, ``gamman_abs``, each ``peratomtypepair``): LIGGGHTS 3.8.0's force is
F = k_n delta + m gamma_n delta' for hooke/stiffness (F = k_n delta + gamma_n_abs delta' with
absolute_damping), and F = sqrt(R delta) (k_n delta + m gamma_n delta') for hertz/stiffness, m and
R the effective mass and radius (the sphere's own against a wall, whatever its shape). So
hooke/stiffness is alpha = 1, gamma = 0, D1 = k_n/m, D2 = gamma_n (gamma_n_abs/m), and
hertz/stiffness alpha = 3/2, gamma = 1/2, D1 = k_n sqrt(R)/m, D2 = gamma_n sqrt(R), whose eps
depends on speed and size. k_n is divided by the unit style's nktv2p, 1 in the styles LIGGGHTS'
granular decks can use (si, cgs, lj: STIFFNESS_UNITS). Checked against the engine in
tests/library/test_dem_deck_liggghts_stiffness.py.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ....core.errors import ParameterError, one_of, require_positive_finite
from ...contact import Contact, ElasticContact
from ...pair import Pair
from ...typed_e import beta_of_e, e_of_beta, effective_modulus

__all__ = ["liggghts_contact", "liggghts_stiffness_contact", "liggghts_e", "liggghts_accepts_e", "LIGGGHTS_MODELS",
           "STIFFNESS_MODELS", "STIFFNESS_UNITS", "LIGGGHTS_E", "LIGGGHTS_NU", "LIGGGHTS_MODULUS",
           "LIGGGHTS_MODEL_TYPES"]

LIGGGHTS_MODELS = ("hertz", "hooke")
#: The normal models whose stiffness and damping are typed per type pair (kn, gamman)
STIFFNESS_MODELS = ("hertz/stiffness", "hooke/stiffness")
#: The unit styles whose nktv2p, by which LIGGGHTS divides k_n, is 1 (LIGGGHTS 3.8.0, update.cpp);
#: pair gran stops on the others ("Please use si,cgs or lj", checked)
STIFFNESS_UNITS = ("si", "cgs", "lj")
#: LIGGGHTS' own checks on the materials, which stop its run before the first step (3.8.0,
#: global_properties.cpp; each confirmed with the engine): 0.05 < coefficientRestitution <= 1,
#: 0 <= poissonsRatio <= 0.5, and Young's modulus within these bounds per unit style
#: (soft_particles yes lifts the lower one, hard_particles yes the upper).
LIGGGHTS_E = (0.05, 1.0)
LIGGGHTS_NU = (0.0, 0.5)
LIGGGHTS_MODULUS = {"si": (5e6, 1e9), "cgs": (5e7, 1e10)}
#: LIGGGHTS' model_type/model_name pairs, in the order pair_style gran and fix wall/gran take them
#: (fix wall/gran puts the wall style after them, then the model keywords such as limitForce).
LIGGGHTS_MODEL_TYPES = ("model", "tangential", "cohesion", "rolling_friction", "surface")


def liggghts_accepts_e(e: float) -> bool:
    """Whether LIGGGHTS runs a coefficientRestitution of ``e`` (LIGGGHTS_E: above 0.05, at most 1).

    Parameters
    ----------
    e : float
        A coefficientRestitution.

    Returns
    -------
    bool

    Examples
    --------
    >>> liggghts_accepts_e(0.05), liggghts_accepts_e(0.9), liggghts_accepts_e(1.0)
    (False, True, True)
    """
    return LIGGGHTS_E[0] < e <= LIGGGHTS_E[1]


def _liggghts_d1(pair: Pair, model: str, E: float, nu: float, characteristic_velocity, E2=None, nu2=None) -> float:
    model = one_of("model", model, LIGGGHTS_MODELS)
    e_star = effective_modulus(E, nu)
    if E2 is not None or nu2 is not None:    # unlike materials: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
        e_star = 1.0 / (1.0 / (2.0 * e_star) + 1.0 / (2.0 * effective_modulus(E2, nu2, ("E2", "nu2"))))
    if model == "hertz":
        return 4.0 / 3.0 * e_star * math.sqrt(pair.R) / pair.m
    v = require_positive_finite("characteristic_velocity", characteristic_velocity)
    sr = math.sqrt(pair.R)
    return 16.0 / 15.0 * sr * e_star * (15.0 * pair.m * v ** 2 / (16.0 * sr * e_star)) ** 0.2 / pair.m


def liggghts_contact(pair: Pair, *, E: float, nu: float, e: float, limit_force: bool = False, model: str = "hertz",
                     characteristic_velocity: float | None = None, E2: float | None = None,
                     nu2: float | None = None) -> Contact | ElasticContact:
    """LIGGGHTS ``model hertz`` or ``model hooke`` with coefficientRestitution e (E2, nu2: the
    second particle's material where it differs).

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    E, nu : float
        youngsModulus and poissonsRatio.
    e : float
        coefficientRestitution (1: no damping, an ElasticContact).
    limit_force : bool, optional
        limitForce on (the force rule); off by default (the overlap rule).
    model : str, optional
        "hertz" (default) or "hooke".
    characteristic_velocity : float, optional
        characteristicVelocity, which hooke's stiffness needs.
    E2, nu2 : float, optional
        The second particle's material, where it differs.

    Returns
    -------
    Contact or ElasticContact
        An ElasticContact where e = 1 (LIGGGHTS does not damp); else hertz (3/2, 1/4) or hooke
        (1, 0). The force rule where ``limit_force``, else the overlap rule.

    Raises
    ------
    ParameterError
        Another model; E or E2 not finite and positive, nu or nu2 outside (-1, 0.5]; e outside
        (0, 1]; hooke without a finite, positive characteristic_velocity.

    Examples
    --------
    >>> pair = Pair.spheres(0.0025, 0.0025, 2500.0)
    >>> c = liggghts_contact(pair, E=5e6, nu=0.45, e=0.9)
    >>> str(c.alpha), str(c.gamma), c.end, round(c.eps(1.0), 12)      # hertz, limitForce off: eps = e
    ('3/2', '1/4', 'overlap', 0.9)
    """
    D1 = _liggghts_d1(pair, model, E, nu, characteristic_velocity, E2, nu2)
    end = "force" if limit_force else "overlap"
    if e == 1.0:
        # LIGGGHTS takes e = 1 (LIGGGHTS_E): beta = 0, no damping at all
        return ElasticContact("3/2" if model == "hertz" else "1", D1, end)
    if model == "hertz":
        return Contact("3/2", "1/4", D1, math.sqrt(5.0) * beta_of_e(e) * math.sqrt(D1), end)
    return Contact("1", "0", D1, 2.0 * beta_of_e(e) * math.sqrt(D1), end)


def liggghts_e(contact: Contact) -> float:
    """The coefficientRestitution that gives this contact's D2 (the inverse of liggghts_contact's
    damping: D2 / sqrt(D1) = sqrt(5) beta for hertz, 2 beta for hooke).

    Parameters
    ----------
    contact : Contact
        Hertz (3/2, 1/4) or hooke (1, 0).

    Returns
    -------
    float
        The e to type.

    Examples
    --------
    >>> c = liggghts_contact(Pair.spheres(0.0025, 0.0025, 2500.0), E=5e6, nu=0.45, e=0.9, limit_force=True)
    >>> round(liggghts_e(c), 12)
    0.9
    """
    factor = math.sqrt(5.0) if contact.alpha == Fraction(3, 2) else 2.0
    return e_of_beta(contact.D2 / math.sqrt(contact.D1) / factor)


def liggghts_stiffness_contact(pair: Pair, *, model: str, kn: float, gamman: float, absolute_damping: bool = False,
                               limit_force: bool = False) -> Contact | ElasticContact:
    """LIGGGHTS ``model hooke/stiffness`` or ``hertz/stiffness`` with the type pair's kn and
    gamman (gamman_abs where ``absolute_damping``, which only hooke/stiffness takes).

    Parameters
    ----------
    pair : Pair
        The colliding pair (a sphere and a wall: :meth:`~restitution.dem.pair.Pair.wall`).
    model : {"hooke/stiffness", "hertz/stiffness"}
        The normal model.
    kn, gamman : float
        The entries of the kn and gamman (or gamman_abs) matrices for the pair, in a unit style of
        STIFFNESS_UNITS; gamman = 0: no damping, an ElasticContact.
    absolute_damping : bool, optional
        hooke/stiffness's absolute_damping on: the damping force is gamman_abs delta', not m
        gamman delta'.
    limit_force : bool, optional
        limitForce on (the force rule); off by default (the overlap rule).

    Returns
    -------
    Contact or ElasticContact
        An ElasticContact where gamman = 0; else hooke/stiffness (1, 0) or hertz/stiffness
        (3/2, 1/2). The force rule where ``limit_force``, else the overlap rule.

    Raises
    ------
    ParameterError
        Another model, absolute_damping with hertz/stiffness (LIGGGHTS stops on it), kn not
        positive or gamman negative.

    Examples
    --------
    >>> pair = Pair.spheres(0.005, 0.005, 2500.0)
    >>> c = liggghts_stiffness_contact(pair, model="hooke/stiffness", kn=2000.0, gamman=20.0)
    >>> str(c.alpha), str(c.gamma), c.D2, round(c.eps(1.0), 6)       # a linear dashpot: eps at every speed
    ('1', '0', 20.0, 0.982189)
    >>> c = liggghts_stiffness_contact(pair, model="hertz/stiffness", kn=2e6, gamman=2e3)
    >>> str(c.alpha), str(c.gamma), round(c.D2, 6)
    ('3/2', '1/2', 100.0)
    """
    model = one_of("model", model, STIFFNESS_MODELS)
    require_positive_finite("kn", kn)
    if not (math.isfinite(gamman) and gamman >= 0.0):
        raise ParameterError("gamman", gamman, "must be finite and >= 0 (a negative one feeds energy in)")
    if absolute_damping and model != "hooke/stiffness":
        raise ParameterError("absolute_damping", "on", "LIGGGHTS 3.8.0 takes it with model hooke/stiffness only")
    end = "force" if limit_force else "overlap"
    if model == "hooke/stiffness":
        D1, D2, alpha, gamma = kn / pair.m, gamman / pair.m if absolute_damping else gamman, "1", "0"
    else:
        root = math.sqrt(pair.R)
        D1, D2, alpha, gamma = kn * root / pair.m, gamman * root, "3/2", "1/2"
    if D2 == 0.0:
        return ElasticContact(alpha, D1, end)
    return Contact(alpha, gamma, D1, D2, end)
