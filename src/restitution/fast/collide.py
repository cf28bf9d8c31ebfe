"""One collision by a named method, served by the rung registry (:mod:`restitution.fast.rungs`).

``epsilon`` and ``collide`` share the registry, and so the names: a rung that can run one whole
collision says so (``Rung.collides``) and does it (``Rung.collision``); ``collide`` picks the rung
of that name serving the problem's end rule. Adding a method is adding a rung.
"""

from __future__ import annotations

import sys

from ..core.errors import ParameterError
from ..core.results import Collision
from .rungs import RUNGS

__all__ = ["collide", "METHODS", "RENAMED", "ALIASES"]

#: Other names of a method, kept without a note: the exact family's collision is a genuine closed
#: form (for ``epsilon`` the name "closed-form" is the uniform approximation's old one, which differs).
ALIASES = {"closed-form": "exact-family"}
#: The names ``collide`` answers to, the default first.
METHODS: tuple[str, ...] = tuple(dict.fromkeys(
    ["reference", *(r.name for r in RUNGS if r.collides), *ALIASES]))
#: Old names still accepted, with a one-line note on stderr: scripts and command lines written
#: before the rename keep working, and say what to write instead.
RENAMED = {"fast": "integrator"}


def collide(problem, omega, *, method: str = "reference", rtol: float = 1e-12, t_eval=None,
            digits: int = 30, stream=None) -> Collision:
    """One forward collision of the Problem ``problem`` at
    ``omega`` by the rung named ``method`` (METHODS); see :func:`restitution.api.collide`."""
    if method in RENAMED:
        print(f'restitution: collide method "{method}" is now called "{RENAMED[method]}", as in epsilon; '
              f'"{method}" will go', file=sys.stderr if stream is None else stream, flush=True)
        method = RENAMED[method]
    if method not in METHODS:
        raise ParameterError("method", method, f"must be one of {', '.join(METHODS)}")
    method = ALIASES.get(method, method)
    named = [r for r in RUNGS if r.name == method and r.collides]
    if t_eval is not None and not any(r.trajectories for r in named):
        raise ParameterError("t_eval", "...", 'trajectories come from method "reference" only')
    # one name may be served by a rung per end rule (the integrator's two): the one for this rule
    rung = next((r for r in named if r.serves_rule(problem.end, problem.rules_differ)), named[0])
    return rung.collision(problem, omega, rtol=rtol, digits=digits, t_eval=t_eval)
