"""Trajectory samples from the legs of the reference integrator (:mod:`restitution.core.collision`).

Each leg keeps solve_ivp's dense output; legs in u = x^(1/p) are sampled at requested tau by
inverting tau(u), which is monotone on such a leg.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np

from .results import Trajectory


@dataclass(frozen=True)
class Piece:
    """One leg's dense output, for sampling the trajectory. In u legs the state is (v, tau, ...)."""

    in_u: bool
    sol: Callable
    lo: float   # independent-variable range, sorted
    hi: float
    p: int



def sample(pieces: Sequence[Piece], t_eval: np.ndarray, tau_end: float) -> Trajectory:
    t_eval = t_eval[t_eval <= tau_end]
    x = np.full(t_eval.shape, np.nan)
    v = np.full(t_eval.shape, np.nan)
    for piece in pieces:
        if piece.in_u:
            t_lo, t_hi = sorted(piece.sol(np.array([piece.lo, piece.hi]))[1])
        else:
            t_lo, t_hi = piece.lo, piece.hi
        mask = (t_eval >= t_lo) & (t_eval <= t_hi) & np.isnan(x)
        if not mask.any():
            continue
        if piece.in_u:
            u = _invert_tau(piece, t_eval[mask])
            x[mask] = u ** piece.p
            v[mask] = piece.sol(u)[0]
        else:
            y = piece.sol(t_eval[mask])
            x[mask], v[mask] = y[0], y[1]
    return Trajectory(_frozen(t_eval), _frozen(x), _frozen(v))


_EPS = float(np.finfo(float).eps)
_BISECTION_STEPS = 120


def _invert_tau(piece: Piece, tau: np.ndarray) -> np.ndarray:
    """u with tau(u) = tau on a u leg, by vectorised bisection (tau is monotone in u there)."""
    lo = np.full(tau.shape, piece.lo)
    hi = np.full(tau.shape, piece.hi)
    rising = piece.sol(np.array([piece.hi]))[1, 0] >= piece.sol(np.array([piece.lo]))[1, 0]
    for _ in range(_BISECTION_STEPS):
        if np.all(hi - lo <= 4.0 * _EPS * hi):
            break
        mid = 0.5 * (lo + hi)
        below = piece.sol(mid)[1] < tau
        go_up = below if rising else ~below
        lo = np.where(go_up, mid, lo)
        hi = np.where(go_up, hi, mid)
    closer_lo = np.abs(piece.sol(lo)[1] - tau) <= np.abs(piece.sol(hi)[1] - tau)
    u = np.where(closer_lo, lo, hi)
    # Exact at the leg's u = 0 end, where tau(u) ~ u^p is too flat for bisection to reach 0.
    tau_at_lo = piece.sol(np.array([piece.lo]))[1, 0]
    at_lo = tau <= tau_at_lo if rising else tau >= tau_at_lo
    return np.where(at_lo, piece.lo, u)


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.asarray(a, float)
    a.setflags(write=False)
    return a
