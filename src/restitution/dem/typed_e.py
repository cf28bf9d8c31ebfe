"""What engines do with a typed restitution coefficient e and a pair of elastic moduli, shared by
several of them: the check that e is one, the linear dashpot's damping ratio beta(e) and its
inverse, the effective modulus E* of two materials, the linear spring-dashpot set from a
contact time and e, and Thornton's fit of the Hertz damping ratio to e (Yade, Kratos)."""

from __future__ import annotations

import math

from ..core.errors import ParameterError, require_positive_finite
from .contact import Contact

__all__ = ["unit_e", "beta_of_e", "e_of_beta", "effective_modulus", "linear_from_time_and_e", "time_and_e_of_linear", "require_linear",
           "thornton_betan", "THORNTON_H"]


def unit_e(name: str, e: float) -> float:
    """``e`` as a float, refused outside (0, 1).

    Parameters
    ----------
    name : str
        The field, as the refusal names it.
    e : float
        The restitution coefficient typed.

    Returns
    -------
    float

    Raises
    ------
    ParameterError
        Where ``e`` is not in (0, 1).

    Examples
    --------
    >>> unit_e("e", 0.5)
    0.5
    """
    if not 0.0 < e < 1.0:
        raise ParameterError(name, e, "must be a restitution coefficient in (0, 1)")
    return float(e)


def beta_of_e(e: float) -> float:
    """beta = -ln e / sqrt(ln^2 e + pi^2): the damping ratio whose linear dashpot gives eps = e.

    Parameters
    ----------
    e : float
        The restitution coefficient, in (0, 1).

    Returns
    -------
    float
        beta, in (0, 1).

    Raises
    ------
    ParameterError
        Where e is not in (0, 1); the refusal names the field "e" (call :func:`unit_e` first to
        name another).

    Examples
    --------
    >>> round(beta_of_e(0.5), 6)
    0.215454
    """
    ln_e = math.log(unit_e("e", e))
    return -ln_e / math.sqrt(ln_e ** 2 + math.pi ** 2)


def e_of_beta(beta: float) -> float:
    """The inverse of :func:`beta_of_e`.

    Parameters
    ----------
    beta : float
        The damping ratio, in (0, 1).

    Returns
    -------
    float
        e, in (0, 1).

    Raises
    ------
    ParameterError
        For a beta outside (0, 1), which no e in (0, 1) gives; the refusal names the field "D2",
        the contact value beta is derived from.

    Examples
    --------
    >>> round(e_of_beta(beta_of_e(0.5)), 12)
    0.5
    """
    if not 0.0 < beta < 1.0:
        raise ParameterError("D2", beta, "needs beta = -ln e / sqrt(ln^2 e + pi^2) in (0, 1)")
    return math.exp(-math.pi * beta / math.sqrt(1.0 - beta ** 2))


def effective_modulus(E: float, nu: float, names: tuple[str, str] = ("E", "nu")) -> float:
    """E* = E / (2 (1 - nu^2)) of two like particles of Young's modulus E and Poisson ratio nu.

    Parameters
    ----------
    E : float
        Young's modulus, finite and > 0.
    nu : float
        Poisson ratio, in (-1, 0.5].
    names : tuple of str, optional
        The fields a refusal names (("E2", "nu2") for a second material).

    Returns
    -------
    float

    Raises
    ------
    ParameterError
        Where E is not finite and > 0 or nu is not in (-1, 0.5], naming the field as ``names`` says.

    Examples
    --------
    >>> round(effective_modulus(1e7, 0.3))
    5494505
    """
    E = require_positive_finite(names[0], E)
    if nu is None or not -1.0 < nu <= 0.5:
        raise ParameterError(names[1], nu, "must be a Poisson ratio in (-1, 0.5]")
    return E / (2.0 * (1.0 - nu ** 2))


def linear_from_time_and_e(name_t: str, t_c: float, name_e: str, e: float, end: str) -> Contact:
    """The linear spring-dashpot of contact time t_c and restitution e under the overlap rule:
    k = m (pi^2 + ln^2 e) / t_c^2, eta = -2 m ln e / t_c, so D1 = k / m, D2 = eta / m.

    Parameters
    ----------
    name_t : str
        The contact time's field, as a refusal names it.
    t_c : float
        Contact time, finite and > 0.
    name_e : str
        The restitution coefficient's field.
    e : float
        Restitution coefficient, in (0, 1).
    end : str
        The end-of-contact rule of the Contact returned.

    Returns
    -------
    Contact
        alpha = 1, gamma = 0.

    Examples
    --------
    >>> c = linear_from_time_and_e("t_c", 1e-3, "e", 0.5, "overlap")
    >>> round(c.eps(1.0), 9)       # integrated: the e asked
    0.5
    """
    t_c = require_positive_finite(name_t, t_c)
    ln_e = math.log(unit_e(name_e, e))
    return Contact("1", "0", (math.pi ** 2 + ln_e ** 2) / t_c ** 2, -2.0 * ln_e / t_c, end)


def require_linear(contact: Contact, form: str) -> None:
    """Refuse a contact that is not the linear spring-dashpot (alpha = 1, gamma = 0).

    A code's linear form (a contact time and e, or kn and cn) read from a Hertz or other contact
    would be a setting that gives a different collision, so it is refused rather than returned.

    Parameters
    ----------
    contact : Contact
        The contact a linear setting is sought for.
    form : str
        What the refusal calls the form asked.

    Returns
    -------
    None
        The contact is linear.

    Raises
    ------
    ParameterError
        Where alpha != 1 or gamma != 0.

    Examples
    --------
    >>> require_linear(Contact(1, 0, D1=1e6, D2=10.0), "the (t_c, e) form")
    >>> require_linear(Contact("3/2", "1/2", D1=1e6, D2=10.0), "the (t_c, e) form")
    Traceback (most recent call last):
    ...
    restitution.core.errors.ParameterError: (alpha, gamma) = (1.5, 0.5): the (t_c, e) form needs the linear contact (alpha = 1, gamma = 0)
    """
    if contact.alpha != 1 or contact.gamma != 0:
        raise ParameterError("(alpha, gamma)", (float(contact.alpha), float(contact.gamma)),
                             f"{form} needs the linear contact (alpha = 1, gamma = 0)")


def time_and_e_of_linear(contact: Contact, form: str = "the (t_c, e) form") -> tuple[float, float]:
    """(t_c, e) of :func:`linear_from_time_and_e` that give ``contact`` (alpha = 1, gamma = 0): D2 =
    -2 ln e / t_c and D1 = (pi^2 + ln^2 e)/t_c^2, so zeta = D2 / (2 sqrt D1) = -ln e / sqrt(pi^2 + ln^2 e).

    Parameters
    ----------
    contact : Contact
        A linear spring-dashpot.
    form : str
        What the refusal calls the form asked.

    Returns
    -------
    tuple of float
        (t_c, e).

    Raises
    ------
    ParameterError
        Where the contact is not linear (alpha = 1, gamma = 0): no (t_c, e) gives it; or where the
        dashpot is not underdamped (D2 >= 2 sqrt(D1)).

    Examples
    --------
    >>> c = linear_from_time_and_e("t_c", 1e-3, "e", 0.5, "overlap")
    >>> [round(x, 12) for x in time_and_e_of_linear(c)]
    [0.001, 0.5]
    """
    require_linear(contact, form)
    zeta = contact.D2 / (2.0 * math.sqrt(contact.D1))
    if not 0.0 < zeta < 1.0:
        raise ParameterError("D2", contact.D2, f"needs D2 < 2 sqrt(D1): {form} is underdamped")
    ln_e = -math.pi * zeta / math.sqrt(1.0 - zeta ** 2)
    return -2.0 * ln_e / contact.D2, math.exp(ln_e)


#: Thornton, Cummins and Cleary (2013), Table 2: the coefficients h_1..h_10 of the polynomial in
#: (B7), with which Yade and Kratos turn e into the Hertz-Mindlin damping ratio beta_n (B6).
THORNTON_H = (-6.918798, -16.41105, 146.8049, -796.4559, 2928.711, -7206.864, 11494.29, -11342.18, 6276.757,
              -1489.915)


def thornton_betan(en: float) -> float:
    """beta_n = sqrt(1 / (1 - (1 + en)^2 exp(a(en))) - 1), a(en) = sum h_k en^k (their (B6)-(B7)).

    Parameters
    ----------
    en : float
        The normal restitution coefficient typed, in (0, 1).

    Returns
    -------
    float
        The Hertz-Mindlin damping ratio beta_n.

    Examples
    --------
    >>> round(thornton_betan(0.5), 6)
    0.233025
    """
    en = unit_e("en", en)
    a = sum(h * en ** (k + 1) for k, h in enumerate(THORNTON_H))
    return math.sqrt(1.0 / (1.0 - (1.0 + en) ** 2 * math.exp(a)) - 1.0)
