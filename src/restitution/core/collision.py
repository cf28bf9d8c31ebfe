"""Reference integration of the scaled collision equation.

    x'' + Omega x^alpha + s x^gamma x' = 0,   x(0) = x_start, x'(0) = 1,

with s = +1 for the forward collision and s = -1 for the paper's "inverse" collision (time run
backwards, so the damping pumps energy in).

x^alpha and x^gamma are not smooth at x = 0, which costs a plain integrator in tau its order
exactly where contact starts (and where a separation end finishes). With alpha = q_alpha/p and
gamma = q_gamma/p, the variable u = x^(1/p) turns the equation into a polynomial one,

    dv/du   = -p u^(p-1) (Omega u^q_alpha + s u^q_gamma v) / v,     dtau/du = p u^(p-1) / v,

smooth at u = 0 but singular where v = 0. So a collision is integrated in up to four legs:

1. ``rise``      in u from u_start while v is large (stops when v falls to V_HANDOFF),
2. ``compress``  in tau up to maximum compression (v = 0),
3. ``release``   in tau until the force vanishes or x falls below SWITCH_FRACTION * x_b,
4. ``land``      in u down to u = 0 (separation) unless the force vanishes first.

That is the "force" end rule. Under the "overlap" rule (``end="overlap"``: contact lasts until x is
back to 0, the force turning attractive on the way, as in DEM codes without a force limit) the zero
of the force is no event: legs 3 and 4 run on to u = 0. Once the force pulls, leg 4 carries the force
alone and takes x' from it (_land_pulling), so that an eps many decades below the creep speed keeps
its relative accuracy. A return proved to creep to x = x' = 0 without ever separating (core.sticking)
is reported as StickError; nothing else is.

In the forward legs 3 and 4 the force f = Omega x^(alpha-gamma) + v is carried as a state of its
own. When Omega is small, v creeps along -Omega x^(alpha-gamma) and f is a tiny difference of two
nearly equal numbers: computing it by subtraction would make tau_c (and, for alpha <= gamma, the
whole creeping return) only as accurate as rtol / Omega. Integrated directly, f keeps its own
relative accuracy.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .errors import ParameterError, number_in, require_positive_finite
from .energy import NEAR_ELASTIC, dissipated, one_minus_eps
from .law import ForceForm, Law, PullForm
from .model import at_most_one
from .conditioning import conditioning, plain_accuracy
from .results import Collision, InverseCollision, Trajectory, end_rule  # noqa: F401  (part of this module's interface)
from .sampling import Piece, sample
from .problem import Problem, as_problem
# StickError, stick_bound and stick_reason are part of this module's interface (every method refuses sticking alike)
from .sticking import StickError, Trap, check_separates, stick_bound, stick_reason  # noqa: F401

#: Accepted range of the relative tolerance.
RTOL_MIN, RTOL_MAX = 1e-14, 1e-3
#: solve_ivp refuses anything tighter than this (it warns and clips); we clip quietly.
SOLVER_RTOL_FLOOR = 100 * np.finfo(float).eps
#: Loosest rtol the overlap rule is integrated at (a looser request runs at this one, and its bound
#: is this one's). make fuzz found eps of (3/2, 1/2) at Omega = 2.5e-3 with rtol 9.5e-8 off by 36
#: rtol (3.4e-6, 1.8 times its bound); against rtol 1e-12 runs, 20 Omegas in 1e-3..1e-2 and 13
#: rtols in 1e-9..1e-6 gave up to 16 rtol between 3e-8 and 2e-7, and four pairs ((3/2, 1/2),
#: (1, 1/2), (3/2, 1), (2, 3/4)) at 9 Omegas in 3e-4..3e-2 at most 0.8 rtol for rtol <= 1e-8. The
#: compiled integrator caps its rtol the same way (fast.integrator.OVERLAP_RTOL_MAX).
OVERLAP_RTOL_MAX = 1e-8
#: atol = ATOL_MARGIN * rtol * (typical size of the component), so that the relative tolerance
#: governs even when the component is a small fraction of its typical size (e.g. v near tau_b).
ATOL_MARGIN = 1e-3
#: Leg 1 hands over to tau when v has fallen to this: far enough from v = 0 for dv/du to stay
#: tame, and reached while x is still a sizeable fraction of x_b.
V_HANDOFF = 0.5
#: Legs in u take at least this many steps (see _integrate).
U_STEPS_MIN = 16
#: Leg 3 hands over to u when x < SWITCH_FRACTION * x_b.
SWITCH_FRACTION = 0.25
#: At and above this 1 - eps, 1 - eps is taken by subtraction (see collide).
BY_SUBTRACTION = 0.25
#: Above this ratio of creeping time to relaxation time the release is stiff (only when
#: alpha <= gamma does the release creep all the way back); there we use Radau instead of DOP853.
STIFFNESS_LIMIT = 1.0e3
#: An inverse run still rising this many times above all its natural scales is declared a runaway.
RUNAWAY_FACTOR = 1.0e12


class RunawayError(ParameterError):
    """The inverse collision never turns around: x~ grows without bound for these parameters."""


class UnresolvedError(ParameterError):
    """eps exists but lies below what the method resolves for these parameters."""


class IntegrationError(RuntimeError):
    """solve_ivp failed or a leg did not end the way the physics says it must (a bug, not bad input)."""


# ----------------------------------------------------------------------------------- legs
@dataclass(frozen=True)
class _State:
    tau: float
    x: float
    v: float
    f: float | None = None   # the carried force, forward release only


def _event(fun, *, terminal: bool = True, direction: float = 0.0):
    """A plain callable tagged the way solve_ivp expects an event (wrapped: methods take no tags)."""
    def event(t, y):
        return fun(t, y)
    event.terminal = terminal
    event.direction = direction
    return event


def _integrate(fun, span, y0, *, rtol, atol, events=(), jac=None, stiff=False, in_u=False):
    # imported here: scipy.integrate costs more than a command-line call that never integrates with it
    from scipy.integrate import solve_ivp

    from .radau import Radau

    kwargs = {"method": Radau, "jac": jac} if stiff else {"method": "DOP853"}
    if in_u:
        # Near u = 0 the right-hand side is flat (a factor u^(p-1)), so the first steps grow
        # large before the error estimate sees the curvature further out; capping them keeps the
        # global error near rtol for p >= 3 at no extra cost.
        kwargs["max_step"] = abs(span[1] - span[0]) / U_STEPS_MIN
    # A trial stage of a long step may land at x < 0 (only ever past the x_switch event). Its
    # fractional powers are then NaN, which makes solve_ivp reject and shrink the step: what we
    # want, so the warning is noise. Set once here, not in each call of the right-hand side, where
    # entering the context cost a third of the function's time.
    with np.errstate(invalid="ignore"):
        sol = solve_ivp(fun, span, np.asarray(y0, float), rtol=max(rtol, SOLVER_RTOL_FLOOR),
                        atol=np.asarray(atol, float), events=list(events) or None, dense_output=True,
                        **kwargs)
    if sol.status < 0:
        raise IntegrationError(f"solve_ivp failed on {span}: {sol.message}")
    return sol


def _fired(sol, i: int) -> bool:
    return sol.status == 1 and sol.t_events[i].size > 0


def _rise(law: Law, x_start: float, x_stop: float, rtol: float, pieces: list) -> _State:
    """Leg 1: leave x = x_start in u until v has fallen to V_HANDOFF or x reaches x_stop."""
    u0, u1 = x_start ** (1.0 / law.p), x_stop ** (1.0 / law.p)
    if u1 <= u0:
        return _State(0.0, x_start, 1.0)
    handoff = _event(lambda u, y: y[0] - V_HANDOFF, direction=-1)
    sol = _integrate(law.du_rhs, (u0, u1), [1.0, 0.0], rtol=rtol,
                     atol=ATOL_MARGIN * rtol * np.array([1.0, x_stop]), events=[handoff], in_u=True)
    u, (v, tau) = sol.t[-1], sol.y[:, -1]
    pieces.append(Piece(True, sol.sol, u0, u, law.p))
    return _State(tau, u ** law.p, v)


def _compress(law: Law, start: _State, rtol: float, pieces: list) -> _State:
    """Leg 2: in tau up to maximum compression, v = 0.

    Forward, v' < -Omega x^alpha < 0 while v > 0, so the turn must come. Inverse, the damping pumps
    energy in and the turn may never come: see _Runaway.
    """
    top = _event(lambda t, y: y[1], direction=-1)
    events = [top]
    runaway = _Runaway(law, start.x) if law.sign < 0 else None
    if runaway is not None:
        runaway.check_start(start)
        events += [_event(runaway.trapped, direction=1), _event(runaway.too_far, direction=1)]
    atol = ATOL_MARGIN * rtol * np.array([start.x, law.velocity_scale(start.x)])
    sol = _integrate(law.dtau_rhs, (start.tau, start.tau + _time_guard(law, start.x)), [start.x, start.v],
                     rtol=rtol, atol=atol, events=events)
    if runaway is not None and not _fired(sol, 0):
        # Trapped, too far, or (on the separatrix itself) still rising at the time guard.
        runaway.fail(sol.y[0, -1], proved=_fired(sol, 1))
    if not _fired(sol, 0):
        raise IntegrationError("maximum compression not reached within the time guard")
    pieces.append(Piece(False, sol.sol, start.tau, sol.t[-1], law.p))
    return _State(sol.t[-1], sol.y[0, -1], sol.y[1, -1])


class _Runaway:
    """Detect an inverse collision that never turns around.

    Above the nullcline v = Omega x^(alpha-gamma) the negative damping speeds the motion up. On the
    curve v = 2 Omega x^(alpha-gamma), dv/dx = x^gamma / 2, which is steeper than the curve itself
    wherever x^(2 gamma + 1 - alpha) >= 4 Omega (alpha - gamma). So once v >= 2 Omega x^(alpha-gamma)
    at such an x, v can never come back down to 0: the run is proved to escape (this needs
    alpha <= 2 gamma + 1; for alpha > 2 gamma + 1, v <= 1 + x^(gamma+1)/(gamma+1) means the elastic
    force always wins in the end). E.g. alpha = 1, gamma = 0 from x~ = 0 escapes iff Omega~ <= 1/4.
    Near that threshold the turn can come at astronomically large x~ (e^(pi/(2w))/w for the linear
    case), so a bound far beyond every natural scale stops the run as well.
    """

    def __init__(self, law: Law, x_start: float):
        self.law = law
        self.d = law.alpha - law.gamma
        self.excess = 2.0 * law.gamma + 1.0 - law.alpha
        scales = [1.0, x_start, law.elastic_scale()]
        if law.qa != law.qg:
            scales.append(law.omega ** (-1.0 / self.d))
        if self.excess < 0:
            scales.append(((law.gamma + 1.0) / law.omega) ** (-1.0 / self.excess))
        self.x_far = RUNAWAY_FACTOR * max(scales)

    def trapped(self, tau, y) -> float:
        """>= 0 exactly inside the escape region described in the class docstring."""
        if self.excess < 0:
            return -1.0
        x, v = y
        above = v - 2.0 * self.law.omega * x ** self.d
        far_enough = x ** self.excess - 4.0 * self.law.omega * self.d
        return min(above, far_enough)

    def too_far(self, tau, y) -> float:
        return y[0] - self.x_far

    def check_start(self, start: _State) -> None:
        if self.trapped(start.tau, [start.x, start.v]) >= 0.0:
            self.fail(start.x, proved=True)

    def fail(self, x: float, *, proved: bool) -> None:
        if proved:
            why = (f"x~' >= 2 Omega~ x~^(alpha-gamma) at x~ = {x:.3g}, from where negative damping "
                   "outruns the elastic force for good")
        else:
            why = (f"still rising at x~ = {x:.3g}, beyond {RUNAWAY_FACTOR:g} times every natural scale "
                   "or after a time no returning run comes near")
        raise RunawayError("omega_tilde", self.law.omega,
                           f"the inverse collision does not turn around: {why}")


def _time_guard(law: Law, x: float) -> float:
    """A bound on any leg's duration that no legitimate run comes near (it only stops bugs)."""
    return 1e6 * (1.0 + x / max(law.velocity_scale(x), 1e-300))


def _release_forward(law: Law, top: _State, rtol: float, pieces: list, stiff: bool, end: str):
    """Leg 3, forward: (x, v, f) in tau until f = 0 (force end) or x < SWITCH_FRACTION x_b.

    Under the overlap rule f = 0 is not an end: f turns negative (the contact pulls) and the leg
    runs on to x_switch."""
    form = ForceForm(law)
    x_switch = SWITCH_FRACTION * top.x
    f0 = law.omega * top.x ** (law.alpha - law.gamma) + top.v
    vs = law.velocity_scale(top.x)
    atol = ATOL_MARGIN * rtol * np.array([top.x, vs, _force_scale(law, top.x)])
    low = _event(lambda t, y: y[0] - x_switch, direction=-1)
    events = [low]
    if law.qa > law.qg and end == "force":
        # Only then can f reach 0: at f = 0, f' = Omega (alpha-gamma) x^(alpha-gamma-1) v has the
        # sign of (alpha - gamma) (v < 0). For alpha <= gamma f stays positive but may decay far
        # below atol, where an event on it would fire on noise.
        events.append(_event(form.dtau_force, direction=-1))
    tau, y = top.tau, [top.x, top.v, f0]
    t_guard = top.tau + _time_guard(law, top.x)
    if stiff:
        # Radau is slow at tight tolerances while the fast relaxation of f is still visible, and
        # DOP853 is cheap there; hand over to Radau once that transient has decayed below atol.
        t_relax = tau + (math.log(1.0 / rtol) + math.log1p(1.0 / law.omega) + 5.0) / top.x ** law.gamma
        sol = _integrate(form.dtau_rhs, (tau, t_relax), y, rtol=rtol, atol=atol, events=events)
        pieces.append(Piece(False, sol.sol, tau, sol.t[-1], law.p))
        tau, y = sol.t[-1], sol.y[:, -1]
    if not stiff or sol.status == 0:
        sol = _integrate(form.dtau_rhs, (tau, t_guard), y, rtol=rtol, atol=atol, events=events,
                         jac=form.dtau_jac, stiff=stiff)
        pieces.append(Piece(False, sol.sol, tau, sol.t[-1], law.p))
    x, v, f = sol.y[:, -1]
    state = _State(sol.t[-1], x, v, f)
    if len(events) > 1 and _fired(sol, 1):
        return "force", state
    if _fired(sol, 0):
        return "switch", state
    raise IntegrationError("release ended neither at zero force nor near x = 0 within the time guard")


def _force_scale(law: Law, x_b: float) -> float:
    """Size of f where it matters. For small Omega, f sinks from Omega x_b^(alpha-gamma) to the level
    Omega (alpha-gamma) x^(alpha-gamma-1) v / x^gamma ~ v_scale^2 / x_b^(gamma+1) set by its drift
    term, where it crosses zero (alpha > gamma) or settles (alpha < gamma); errors below that level
    also keep v = integral of -x^gamma f accurate over the creeping return."""
    vs = law.velocity_scale(x_b)
    return vs * min(1.0, vs / x_b ** (law.gamma + 1.0))


def _land_forward(law: Law, start: _State, x_b: float, rtol: float, pieces: list, stiff: bool,
                  end: str):
    """Leg 4, forward: (v, tau, g) in u from x_switch down to u = 0 unless the force vanishes
    (under the overlap rule, down to u = 0 regardless; once the force pulls, see _land_pulling)."""
    if end == "overlap" and law.qa > law.qg and start.f < 0.0:
        # (for alpha <= gamma the force never pulls; a negative f there is rounding of a vanishing one)
        return _land_pulling(law, start, rtol, pieces, stiff)
    form = ForceForm(law)
    u0 = start.x ** (1.0 / law.p)
    g0 = form.g_from_f(u0, start.f)
    g_scale = _force_scale(law, x_b) * u0 ** form.m
    atol = ATOL_MARGIN * rtol * np.array([abs(start.v), start.tau, g_scale])
    events = [_event(form.du_force, direction=0)] if law.qa > law.qg and end == "force" else []
    sol = _integrate(form.du_rhs, (u0, 0.0), [start.v, start.tau, g0], rtol=rtol, atol=atol,
                     events=events, jac=form.du_jac, stiff=stiff, in_u=True)
    u, (v, tau, _) = sol.t[-1], sol.y[:, -1]
    pieces.append(Piece(True, sol.sol, u, u0, law.p))
    if events and _fired(sol, 0):
        return "force", _State(tau, u ** law.p, v)
    return "separation", _State(tau, 0.0, v)


#: Evaluations after which the pulling leg's Radau counts as stalled (about 7 s).
PULL_MAX_CALLS = 500_000


def _land_pulling(law: Law, start: _State, rtol: float, pieces: list, stiff: bool):
    """Leg 4 under the overlap rule with the force already pulling: (g, tau) in u down to u = 0.

    Here eps may be a factor Omega^2 below the creep speed it starts from (eps = C Omega^3 for
    alpha = 3/2, gamma = 1/2), so g is held to a purely relative tolerance and x' is computed from
    it without cancellation (PullForm). A return caught by the trap of core.sticking.Trap provably sticks.
    """
    form = PullForm(law)
    u0 = start.x ** (1.0 / law.p)
    trap = Trap(law)
    if trap.holds(u0, [start.f]) >= 0.0:
        raise StickError.at(law.omega, trap.why(start.x))
    events = [_event(trap.holds, direction=1)] if trap.possible else []
    # The leg's own time, from 0 and held to a relative tolerance: a tau_b + (a creep of ~1/Omega)
    # in the state, or a loose absolute tolerance on it, lets Radau take steps over which its
    # Newton iteration fails at small Omega. (TINY itself would overflow its first-step estimate.)
    atol = np.array([TINY, TIME_MARGIN * rtol * start.x / abs(start.v)])
    calls = 0

    def rhs(u, y):
        # Radau can stall with its step collapsed, short of u = 0 (make fuzz: 25/4, 9/2 at Omega =
        # 1e-12, rtol 1e-11, u stuck at 9.13e-7 for 3 million calls); successful legs take < 6e4
        nonlocal calls
        calls += 1
        if calls > PULL_MAX_CALLS:
            raise IntegrationError(f"Radau stalled at u = {u:.3g} after {PULL_MAX_CALLS} evaluations")
        return form.du_rhs(u, y)

    try:
        with np.errstate(divide="ignore", over="ignore", invalid="ignore"):   # an overflow is refused below
            sol = _integrate(rhs, (u0, 0.0), [start.f, 0.0], rtol=rtol, atol=atol, events=events,
                             jac=form.du_jac, stiff=stiff, in_u=True)
    except IntegrationError:
        if not trap.possible:   # no sticking to blame (alpha < 2 gamma + 1): Radau lost its way in the creep
            raise UnresolvedError("rtol", rtol, "under the overlap rule the creeping return defeated the integrator "
                                  f"at Omega = {law.omega:g} (measured: alpha = 1, gamma = 1/2 at 1e-11 and 1e-10 "
                                  "with rtol 1e-12); another rtol answers, or restitution.epsilon") from None
        # Right at a sticking boundary the return stalls short of x = 0 before the trap can prove
        # it stays: whether the bodies separate is not decided in double precision there.
        raise UnresolvedError("omega", law.omega, "under the overlap rule the return stalls at the edge of "
                              f"sticking (x = {start.x:.3g}): eps = 0 or below what a double-precision "
                              "integration resolves; move Omega away from the sticking boundary") from None
    except ValueError:
        # scipy's check of the Jacobian: 1/v^2 overflows once the rebound speed v falls below ~1e-154
        # (alpha = 23/12, gamma = 1/2 at Omega = 1e-10: eps = 6e-170)
        raise UnresolvedError("omega", law.omega, "under the overlap rule eps lies below what a double-precision "
                              "integration resolves here (the return's Jacobian overflows); restitution.epsilon "
                              "answers from the limit law eps = C Omega^k at Omega <= 1e-8") from None
    u, (g, tau) = sol.t[-1], sol.y[:, -1] + [0.0, start.tau]
    if events and _fired(sol, 0):
        raise StickError.at(law.omega, trap.why(u ** law.p))
    v = form.speed(u, g)
    if not (u == 0.0 and g < 0.0 and math.isfinite(tau)):
        raise UnresolvedError("omega", law.omega, f"under the overlap rule eps is below what the reference "
                              f"integrator resolves here (x' = {v:.3g} at x = {u ** law.p:.3g}); "
                              "try method highprec")
    pieces.append(Piece(True, _SpeedView(sol.sol, form, start.tau), u, u0, law.p))
    return "separation", _State(tau, 0.0, v)


#: An absolute tolerance that leaves the relative one in charge.
TINY = 1e-300
#: The pulling leg's time: absolute tolerance TIME_MARGIN rtol (x / |x'| at its start).
TIME_MARGIN = 1e-6


class _SpeedView:
    """A (g, tau) leg's dense output seen as (v, tau), the state the other u legs have."""

    def __init__(self, sol, form: PullForm, tau0: float):
        self.sol, self.form, self.tau0, self.ts = sol, form, tau0, sol.ts

    def __call__(self, u):
        g, tau = self.sol(u)
        return np.array([self.form.speed(np.asarray(u, float), g), tau + self.tau0])


def _release_inverse(law: Law, top: _State, rtol: float, pieces: list) -> _State:
    """Leg 3, inverse: (x, v) in tau until x < SWITCH_FRACTION x_b (v < 0 and falling throughout)."""
    x_switch = SWITCH_FRACTION * top.x
    low = _event(lambda t, y: y[0] - x_switch, direction=-1)
    atol = ATOL_MARGIN * rtol * np.array([top.x, law.velocity_scale(top.x)])
    sol = _integrate(law.dtau_rhs, (top.tau, top.tau + _time_guard(law, top.x)), [top.x, top.v],
                     rtol=rtol, atol=atol, events=[low])
    if not _fired(sol, 0):
        raise IntegrationError("inverse release did not come back near x~ = 0 within the time guard")
    pieces.append(Piece(False, sol.sol, top.tau, sol.t[-1], law.p))
    return _State(sol.t[-1], sol.y[0, -1], sol.y[1, -1])


def _land_inverse(law: Law, start: _State, rtol: float, pieces: list) -> _State:
    """Leg 4, inverse: (v, tau) in u down to u = 0; both force terms push the same way, no event."""
    u0 = start.x ** (1.0 / law.p)
    atol = ATOL_MARGIN * rtol * np.array([abs(start.v), start.tau])
    sol = _integrate(law.du_rhs, (u0, 0.0), [start.v, start.tau], rtol=rtol, atol=atol, in_u=True)
    v, tau = sol.y[:, -1]
    pieces.append(Piece(True, sol.sol, 0.0, u0, law.p))
    return _State(tau, 0.0, v)


def _is_stiff(law: Law, x: float, end: str = "force") -> bool:
    """A creeping return from x (alpha <= gamma) lasts ~ x / v_scale while f relaxes at rate x^gamma.

    (In u the same ratio appears as the integral of |d(dv/du)/dv|.) When alpha > gamma the force
    vanishes a few relaxation times after tau_b instead, and nothing is stiff, unless the overlap
    rule carries the return on past that point: then it creeps as well.
    """
    if law.qa > law.qg and end == "force":
        return False
    return x ** (law.gamma + 1.0) / law.velocity_scale(x) > STIFFNESS_LIMIT


# ----------------------------------------------------------------------------------- validation
def _check_rtol(rtol) -> float:
    return number_in("rtol", rtol, RTOL_MIN, RTOL_MAX)


def _check_t_eval(t_eval) -> np.ndarray | None:
    if t_eval is None:
        return None
    allowed = "must be a 1-D non-decreasing array of finite tau >= 0"
    try:
        t = np.asarray(t_eval, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError("t_eval", t_eval, allowed) from None
    if t.ndim != 1 or not np.all(np.isfinite(t)) or (t.size and t[0] < 0) or np.any(np.diff(t) < 0):
        raise ParameterError("t_eval", t_eval, allowed)
    return t


def _check_x_start(x_start) -> float:
    allowed = "must be a finite number >= 0"
    try:
        value = float(x_start)
    except (TypeError, ValueError):
        raise ParameterError("x_start", x_start, allowed) from None
    if isinstance(x_start, bool) or not math.isfinite(value) or value < 0:
        raise ParameterError("x_start", x_start, allowed)
    return value


# ----------------------------------------------------------------------------------- public API
#: Omega for which the stated accuracy (relative 10 rtol + 1e-13 in eps, tau_b, x_b, tau_c) has
#: been verified (stability atlas, mpmath reference, closed forms). Beyond 1e10, 1 - eps for
#: alpha <= gamma falls below the absolute error of eps (eps > 1 was seen at 3e10); below 1e-12
#: contacts for alpha <= gamma last ~1/Omega and the integration breaks down. The asymptotic
#: rungs of restitution.epsilon cover both ends.
OMEGA_RANGE = (1e-12, 1e10)


def _check_omega(field: str, omega) -> float:
    value = require_positive_finite(field, omega)
    if not OMEGA_RANGE[0] <= value <= OMEGA_RANGE[1]:
        raise ParameterError(field, omega, f"must be in [{OMEGA_RANGE[0]:g}, {OMEGA_RANGE[1]:g}] for the "
                                           "reference integrator (restitution.epsilon covers the limits)")
    return value


def collide(problem: Problem, omega, *, rtol: float = 1e-12, t_eval=None) -> Collision:
    """Forward collision x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1, to end of contact.

    ``problem``: the exponents and the end-of-contact rule (results.END_RULES), the same relative
    accuracy for both however small eps (checked against mpmath down to eps = 5e-36); under
    "overlap" the bodies may provably never separate (StickError, see core.sticking).
    ``omega``: in OMEGA_RANGE. ``rtol`` in [1e-14, 1e-3] (solve_ivp clips below 2.2e-14; the overlap
    rule runs at OVERLAP_RTOL_MAX at most). ``t_eval``: tau samples for ``trajectory``. (Plain
    exponents, an Exponents or a pair, stand for their force rule.) Where Radau loses its way in the
    overlap rule's creeping return at ``rtol`` (UnresolvedError on rtol), the collision is integrated
    again at rtol / 10, then rtol / 100 (not below 1e-14): the result's ``rtol`` and ``error_bound``
    are those of the run that answered, within the ones asked for."""
    problem = as_problem(problem)
    omega = _check_omega("omega", omega)
    rtol = _check_rtol(rtol)
    t_eval = _check_t_eval(t_eval)
    if problem.end == "overlap":
        rtol = min(rtol, OVERLAP_RTOL_MAX)
    try:
        return _collide(problem, omega, rtol, t_eval)
    except UnresolvedError as exc:
        if exc.field != "rtol":
            raise
        first = exc
    # Radau lost its way in the creeping return at this rtol (seen: 3/2, 1 at Omega = 6.12e-11 with
    # rtol 1e-11, which 1e-12 and 1e-10 answered alike, within 2.3e-11). A tighter rtol is another
    # integration whose bound is below the one asked for; never a looser one: callers (the reference
    # rung among them) state the bound of the rtol they asked for.
    for other in (rtol / 10.0, rtol / 100.0):
        if other >= RTOL_MIN:
            try:
                return _collide(problem, omega, other, t_eval)
            except UnresolvedError as exc:
                if exc.field != "rtol":
                    raise
    raise first


def _collide(problem: Problem, omega: float, rtol: float, t_eval) -> Collision:
    """One integration of ``collide`` at ``rtol`` (checked inputs)."""
    ex = problem.ex
    rule = problem.end
    law = Law.of(ex, omega, +1)
    if rule == "overlap":
        check_separates(ex, law)

    pieces: list[Piece] = []
    risen = _rise(law, 0.0, min(1.0, law.elastic_scale()), rtol, pieces)
    top = _compress(law, risen, rtol, pieces)
    ended_by, last = _release_forward(law, top, rtol, pieces, _is_stiff(law, top.x, rule), rule)
    if ended_by == "switch":
        ended_by, last = _land_forward(law, last, top.x, rtol, pieces, _is_stiff(law, last.x, rule), rule)
    eps = -last.v
    if ended_by == "force":
        # At the event Omega x_c^(alpha-gamma) = eps exactly; this stays accurate when x_c is
        # far below what the located event time resolves (huge Omega).
        x_c = (eps / omega) ** (1.0 / (law.alpha - law.gamma))
    else:
        x_c = 0.0
    if not (0.0 < eps and math.isfinite(last.tau)):
        raise IntegrationError(f"unphysical end of contact: eps = {eps!r}, tau_c = {last.tau!r}")
    legs = pieces[:-1] + [_to_force_end(pieces[-1], law, x_c, last)] if ended_by == "force" else pieces
    loss = one_minus_eps(dissipated(legs, law), omega * x_c ** (law.alpha + 1.0) / (law.alpha + 1.0), eps)
    if 1.0 - eps >= BY_SUBTRACTION:
        # A large loss is as accurate by subtraction (eps / (1 - eps) <= 3 times eps's relative
        # error), and more than the quadrature of the dissipation on dense output, which the fuzz
        # found up to 2.9 times over 10 rtol + 1e-13 for alpha = gamma >= 14/5 at 1 - eps = 0.41.
        loss = 1.0 - eps
    elif loss < NEAR_ELASTIC:
        # eps from 1 - eps: -x'(tau_c) carries an absolute error ~ rtol that would swamp so small
        # a loss (and could even exceed 1); the loss itself is accurate to about rtol relative
        eps = 1.0 - loss
    trajectory = sample(pieces, t_eval, last.tau) if t_eval is not None else None
    plain = plain_accuracy(problem, max(rtol, SOLVER_RTOL_FLOOR))
    bound = plain * float(conditioning(problem, eps, omega))
    loss_bound = max(plain, bound * eps / loss) if 1.0 - eps >= BY_SUBTRACTION else plain
    return Collision(problem, omega, "forward", at_most_one(eps), float(top.tau), float(top.x),
                     float(last.tau), float(x_c), ended_by, rtol, trajectory, loss, bound, loss_bound)


def _to_force_end(piece: Piece, law: Law, x_c: float, last: _State) -> Piece:
    """The last leg, reaching exactly to the end of contact at x_c instead of the located event.

    solve_ivp locates an event to about 4 machine epsilon in tau or u, absolutely. That moves the
    dissipation D by |v| times as much while U_c is taken at x_c: enough to put 1 - eps of the
    linear dashpot 4e-12 off (relative) at Omega = 1e9 whatever rtol. In u, x = u^p, so the end is
    u_c = x_c^(1/p); in tau it is one Newton step on x from the event, (x_c - x) / v. (Only the
    dissipation reads it: the trajectory and tau_c stay those of the located event.)
    """
    if piece.in_u:
        return replace(piece, lo=x_c ** (1.0 / law.p))
    return replace(piece, hi=last.tau + (x_c - last.x) / last.v)


def inverse_collide(problem: Problem, omega_tilde, x_start: float = 0.0, *, rtol: float = 1e-12,
                    t_eval=None) -> InverseCollision:
    """Inverse collision x~'' + Omega~ x~^alpha - x~^gamma x~' = 0, x~(0) = x_start, x~'(0) = 1, for
    the exponents of ``problem`` (x~ = 0 ends it: no end rule applies); the public spelling with
    the exponents apart, and its documentation: :func:`restitution.inverse_collide`."""
    problem = as_problem(problem)
    ex = problem.ex
    omega = _check_omega("omega_tilde", omega_tilde)
    x_start = _check_x_start(x_start)
    rtol = _check_rtol(rtol)
    t_eval = _check_t_eval(t_eval)
    law = Law.of(ex, omega, -1)

    pieces: list[Piece] = []
    risen = _rise(law, x_start, min(1.0, law.elastic_scale()), rtol, pieces)
    top = _compress(law, risen, rtol, pieces)
    low = _release_inverse(law, top, rtol, pieces)
    last = _land_inverse(law, low, rtol, pieces)
    trajectory = sample(pieces, t_eval, last.tau) if t_eval is not None else None
    return InverseCollision(problem, omega, x_start, float(top.tau), float(top.x),
                            float(last.tau), float(last.v), rtol, trajectory)


def collide_many(problem: Problem, omegas, *, rtol: float = 1e-12) -> dict[str, np.ndarray]:
    """collide() over an array of Omega; returns arrays keyed eps, tau_b, x_b, tau_c, x_c, ended_by."""
    problem = as_problem(problem)
    omegas = np.asarray(omegas, dtype=float)
    if omegas.ndim != 1:
        raise ParameterError("omegas", omegas, "must be a 1-D array of finite numbers > 0")
    hits = [collide(problem, w, rtol=rtol) for w in omegas]
    out = {name: np.array([getattr(h, name) for h in hits], dtype=float)
           for name in ("eps", "tau_b", "x_b", "tau_c", "x_c")}
    out["ended_by"] = np.array([h.ended_by for h in hits], dtype=str)
    return out
