"""The time step that keeps eps within a tolerance, set against the time step at which explicit
integration becomes unstable, for the exact family alpha = 2 gamma + 1 (hooke with velocity damping,
hertz with tsuji's damping): the docs' table (docs/howto/dem.md), as ratios.

    .venv/bin/python benchmarks/dt_vs_stability.py

Accuracy: :func:`restitution.dem.timestep.recommended_dt` (velocity Verlet, the damping on the
half-step velocity, run and refined until its own error is within tol). Stability: the linearised
undamped estimate dt_crit = 2 / omega_max, omega_max^2 = alpha D1 delta_max^(alpha - 1) the contact's
stiffness per unit mass at the undamped largest overlap delta_max = (g^2 (alpha+1) / (2 D1))^(1/(alpha+1))
(an upper bound on the damped one, so omega_max is too, and dt_crit a lower estimate). Both are given
per contact time: steps per contact N = t_c / dt. eps, and so each ratio, does not depend on g in
this family; D1 = g = 1.
"""

from __future__ import annotations

import math

from restitution.dem.contact import Contact
from restitution.dem.timestep import recommended_dt

LAWS = (("hooke, velocity damping", 1, 0), ("hertz, tsuji damping", "3/2", "1/4"))
DAMPINGS = (0.2, 0.8, 1.4)
TOLS = (1e-2, 1e-3)


def rows() -> list[dict]:
    out = []
    for name, alpha, gamma in LAWS:
        for end in ("overlap", "force"):
            for d2 in DAMPINGS:
                c = Contact(alpha, gamma, 1.0, d2, end)
                a = float(c.alpha)
                t_c = c.contact_time(1.0)
                reach = ((a + 1.0) / 2.0) ** (1.0 / (a + 1.0))
                dt_crit = 2.0 / math.sqrt(a * reach ** (a - 1.0))
                row = {"law": name, "end": end, "D2": d2, "eps": c.eps(1.0), "N_crit": t_c / dt_crit}
                for tol in TOLS:
                    step = recommended_dt(c, 1.0, tol)
                    row[f"N_{tol:g}"] = step.steps_per_contact
                    row[f"dt_{tol:g}/dt_crit"] = step.dt / dt_crit
                out.append(row)
    return out


def main() -> int:
    table = rows()
    head = list(table[0])
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in table:
        print("| " + " | ".join(f"{v:.3g}" if isinstance(v, float) else str(v) for v in r.values()) + " |")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
