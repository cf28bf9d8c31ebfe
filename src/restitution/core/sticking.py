"""When the overlap rule's return sticks: the bodies never separate, x and x' creep to 0 together.

Under the "overlap" end rule the force turns attractive on the way back, and for alpha >= 2 gamma + 1
it can stop the return altogether (eps = 0). Two proofs decide it: :func:`stick_bound`, an Omega at or
below which sticking is certain without integrating, and :class:`Trap`, a region of the (x, x') plane
that a return, once inside it, never leaves before x = 0 (checked during the integration of
:mod:`restitution.core.collision`). Every method refuses a proved sticking with the one
:class:`StickError`; nothing unproved is called sticking.
"""

from __future__ import annotations

from .errors import ParameterError
from .exponents import as_exponents
from .law import Law

__all__ = ["StickError", "Trap", "stick_bound", "stick_reason", "check_separates"]


class StickError(ParameterError):
    """Under the overlap rule the bodies never separate: x and x' creep to 0 together (eps = 0)."""

    @classmethod
    def at(cls, omega: float, why: str) -> "StickError":
        """The one error every method raises for a proved sticking at ``omega`` (``why``: the proof)."""
        return cls("omega", omega, "under the overlap rule contact never ends here: the attractive phase stops "
                                   f"the return and the bodies stay together (eps = 0; {why}); use end=force")


class Trap:
    """Where a pulling return provably sticks (x and x' go to 0 together, contact never ends).

    With s = -x' > 0 and d = alpha - gamma, along a return ds/dx = x^gamma - Omega x^alpha / s. On the
    curve s = 2 Omega x^d that slope is x^gamma / 2, at least the curve's own 2 Omega d x^(d-1)
    wherever x^(2 gamma + 1 - alpha) >= 4 Omega d. So once s <= 2 Omega x^d at such an x, s stays
    below the curve all the way down, and x' ~ x^d with d >= 1 never brings x to 0. Only
    alpha >= 2 gamma + 1 has such x (for alpha = 2 gamma + 1 exactly when Omega <= 1/(4 (gamma+1)),
    the case check_separates refuses at once); for alpha < 2 gamma + 1 the return always separates.
    """

    def __init__(self, law: Law):
        self.law = law
        self.excess = law.qa - 2 * law.qg - law.p       # p (alpha - 2 gamma - 1)
        self.d = law.alpha - law.gamma
        self.possible = self.excess > 0

    def holds(self, u, y) -> float:
        """>= 0 exactly inside the trap (g = f = Omega x^d + x', so s <= 2 Omega x^d is g >= -Omega x^d)."""
        if not self.possible:
            return -1.0
        L = self.law
        below = y[0] + L.omega * u ** L.k
        if u <= 0.0:
            return below
        return min(below, u ** (-self.excess) - 4.0 * L.omega * self.d)

    def why(self, x: float) -> str:
        return (f"at x = {x:.3g} the return is slower than 2 Omega x^(alpha-gamma), from where it "
                "creeps to 0 without ever separating")


def stick_bound(problem) -> float:
    """The Omega at or below which the bodies provably never separate under the overlap rule,
    without integrating: 0 where they always separate (alpha < 2 gamma + 1).

    With e = alpha - 2 gamma - 1 >= 0 and d = alpha - gamma, the trap of Trap closes over every
    x <= x_b once x_b^e <= 1/(4 Omega d), and at maximum compression s = 0 lies inside it. The
    spring only shortens the damped-only compression, x' <= 1 - x^(gamma+1)/(gamma+1), so x_b <= X =
    (gamma+1)^(1/(gamma+1)), and Omega <= 1/(4 d X^e) suffices: the trap holds from x_b on, and the
    return creeps to x = 0 without reaching it. For e = 0 this is 1/(4 (gamma+1)), the self-similar
    case's real fixed points (w = x'/x^(gamma+1) obeys an autonomous equation there whose fixed points
    solve (gamma+1) w^2 + w + Omega = 0: the overdamped linear dashpot, and LAMMPS' tsuji damping for
    e below about 0.1). Above this bound sticking is still claimed where Trap catches it during the
    return, and only there.

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents.

    Returns
    -------
    float
        The bound (0.0 where the return always separates).

    Examples
    --------
    >>> stick_bound(("2", "1/2"))            # alpha = 2 gamma + 1: 1/(4 (gamma+1))
    0.16666666666666666
    >>> stick_bound(("3/2", "1"))            # alpha < 2 gamma + 1: always separates
    0.0
    """
    ex = as_exponents(problem)
    e = ex.alpha - 2 * ex.gamma - 1
    if e < 0:
        return 0.0
    g = float(ex.gamma)
    return 1.0 / (4.0 * float(ex.alpha - ex.gamma) * (g + 1.0) ** (float(e) / (g + 1.0)))


def stick_reason(problem) -> str:
    """stick_bound's proof in one line, for StickError (collide and the method ladder).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        As for :func:`stick_bound`.

    Returns
    -------
    str
        The bound with the argument that proves it, in words.

    Examples
    --------
    >>> stick_reason((1, 0))
    'Omega <= 1/(4 (gamma+1)) = 0.25 for alpha = 2 gamma + 1'
    """
    ex = as_exponents(problem)
    bound = stick_bound(ex)
    if ex.alpha == 2 * ex.gamma + 1:
        return f"Omega <= 1/(4 (gamma+1)) = {bound:.6g} for alpha = 2 gamma + 1"
    return (f"Omega <= {bound:.6g} = 1/(4 (alpha-gamma) X^(alpha-2gamma-1)), X = (gamma+1)^(1/(gamma+1)): "
            "the return is trapped from maximum compression on")


def check_separates(problem, law: Law) -> None:
    """Refuse the overlap rule where the bodies provably never separate (stick_bound).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents (exact: the bound differs at alpha = 2 gamma + 1).
    law : Law
        The scaled force law at one Omega.

    Raises
    ------
    StickError
        Where ``law.omega <= stick_bound``.
    """
    if law.omega <= stick_bound(problem):
        raise StickError.at(law.omega, stick_reason(problem))
