"""The linear spring-dashpot (hooke with velocity or mass_velocity damping) in closed form: what
the deck tests hold the audit's numbers for such a pair against."""

from __future__ import annotations

import math


def dashpot_eps(p):
    """eps of the linear spring-dashpot (hooke + velocity or mass_velocity) under the overlap rule."""
    zeta = p["D2"] / (2.0 * math.sqrt(p["D1"]))
    return math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta ** 2))


def damped_overlap(p, g):
    """The linear damped oscillator's largest overlap (closed form), under- or overdamped."""
    w = math.sqrt(p["D1"])
    zeta = p["D2"] / (2.0 * w)
    if zeta < 1.0:
        wd = w * math.sqrt(1.0 - zeta ** 2)
        t = math.atan2(math.sqrt(1.0 - zeta ** 2), zeta) / wd
        return g / wd * math.exp(-zeta * w * t) * math.sin(wd * t)
    if zeta == 1.0:
        return g / (w * math.e)
    r1, r2 = -zeta * w + w * math.sqrt(zeta ** 2 - 1.0), -zeta * w - w * math.sqrt(zeta ** 2 - 1.0)
    t = math.log(r2 / r1) / (r1 - r2)
    return g * (math.exp(r1 * t) - math.exp(r2 * t)) / (r1 - r2)
