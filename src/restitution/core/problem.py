"""The physics problem as one value: the exponents of the contact law and the end-of-contact rule.

Every function that needs the pair (alpha, gamma) takes the problem as its first argument: a
:class:`Problem`, an :class:`~restitution.core.exponents.Exponents` (the force rule), or an
``(alpha, gamma)`` pair as :meth:`Exponents.parse` reads it. One value travels instead of two
numbers and a rule beside them, and no caller passes None for gamma to say "the pair is in the
first argument". (``Law`` in :mod:`restitution.core.law` is something else: the force law at
one Omega, with its numbers, in one direction.)
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from .errors import ParameterError
from .exponents import Exponents, as_exponents, read_through
from .results import end_rule

__all__ = ["Problem", "as_problem"]


@dataclass(frozen=True)
class Problem:
    """The scaled collision x'' + Omega x^alpha + x^gamma x' = 0 up to Omega: exponents and end rule.

    Parameters
    ----------
    ex : Exponents
        alpha (elastic) and gamma (dissipative) as exact rationals.
    end : {"force", "overlap"}, optional
        The end-of-contact rule asked for (:data:`restitution.core.results.END_RULES`): "force"
        (default) ends contact where the total force vanishes, "overlap" where x returns to 0.

    Returns
    -------
    Problem
        A frozen, hashable value (usable as a cache key).

    Raises
    ------
    ParameterError
        If ``ex`` is not an :class:`Exponents` or ``end`` is not one of END_RULES.

    See Also
    --------
    Problem.of : the same from anything :meth:`Exponents.parse` reads.
    as_problem : a Problem from a Problem, an Exponents or an (alpha, gamma) pair.

    Examples
    --------
    >>> from restitution import Problem
    >>> p = Problem.of("3/2", 1, end="overlap")
    >>> p
    Problem(alpha=3/2, gamma=1, end='overlap')
    >>> p.alpha, p.p, p.rules_differ, p.effective_end
    (Fraction(3, 2), 2, True, 'overlap')
    >>> Problem.of(1, 2, end="overlap").effective_end   # alpha <= gamma: the force never pulls
    'force'
    >>> p.with_end("force") == Problem.of(1.5, "1")
    True
    >>> Problem.of("3/2", 1, end="later")
    Traceback (most recent call last):
    ...
    restitution.core.errors.ParameterError: end = 'later': must be one of force, overlap
    """

    ex: Exponents
    end: str = "force"

    def __post_init__(self):
        if not isinstance(self.ex, Exponents):
            raise ParameterError("ex", self.ex, "must be an Exponents (Problem.of reads numbers and text)")
        object.__setattr__(self, "end", end_rule(self.end))

    @classmethod
    def of(cls, alpha, gamma, end: str = "force") -> "Problem":
        """The problem for exponents as :meth:`Exponents.parse` reads them, under ``end``."""
        return cls(Exponents.parse(alpha, gamma), end)

    alpha = read_through("ex", "alpha")
    gamma = read_through("ex", "gamma")
    p = read_through("ex", "p", "Least common denominator of alpha and gamma.")

    @property
    def rules_differ(self) -> bool:
        """The force can vanish during contact (alpha > gamma): the two end rules differ."""
        return self.ex.alpha > self.ex.gamma

    @property
    def effective_end(self) -> str:
        """The rule whose numbers apply: "overlap" only where it differs from the force rule."""
        return "overlap" if self.end == "overlap" and self.rules_differ else "force"

    def with_end(self, end: str) -> "Problem":
        """The same exponents under another end rule."""
        return replace(self, end=end)

    def __repr__(self) -> str:
        return f"Problem(alpha={self.ex.alpha}, gamma={self.ex.gamma}, end={self.end!r})"

    def __str__(self) -> str:
        return f"{self.ex}, end={self.end}"


def as_problem(problem) -> Problem:
    """A :class:`Problem` from a Problem, an Exponents (the force rule) or an ``(alpha, gamma)`` pair.

    The public entry points call it once; below them every function takes the Problem itself.

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The problem, or exponents that stand for their force rule.

    Returns
    -------
    Problem
        ``problem`` itself when it is one.

    Raises
    ------
    ParameterError
        For exponents :meth:`Exponents.parse` refuses.

    Examples
    --------
    >>> p = Problem.of("3/2", 1, end="overlap")
    >>> as_problem(p) is p, as_problem(("3/2", 1))
    (True, Problem(alpha=3/2, gamma=1, end='force'))
    """
    if isinstance(problem, Problem):
        return problem
    return Problem(as_exponents(problem))
