"""Check the audit's eps_at_dt_spread: contacts that start at a fraction f of a step at the deck's dt.

usage: python spread_check.py DECKDIR CHECK_INDEX SPEED_INDEX   (uses DECKDIR/spec.json, audit.json)
"""
import json, sys, os
import referee
d, ci, si = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
spec = json.load(open(os.path.join(d, "spec.json")))
audit = json.load(open(os.path.join(d, "audit.json")))
chk = dict(spec["checks"][ci])
row = referee.audit_rows(audit, chk)
g, dt = row["speeds"][si], row["dt"]
lo, hi = row["eps_at_dt_spread"][si]
out = [f"{d} check {ci} g {g}: audit spread [{lo:.6f}, {hi:.6f}] at dt {dt}"]
vals = []
for k in range(10):
    f = k / 10.0
    chk["gap"] = g * dt * (1 - f) if k else 0.0   # first overlap after a fraction (1-f) of the first step
    chk["gapsteps"] = 2
    e, n, sep = referee._lammps_run(spec, chk, g, dt, 100000)
    vals.append(e)
    out.append(f"  start offset {f:.1f} of a step: engine eps {e:.6f}  {'inside' if lo - 1e-6 <= e <= hi + 1e-6 else 'OUTSIDE'}")
out.append(f"  engine range [{min(vals):.6f}, {max(vals):.6f}]")
print("\n".join(out))
open(os.path.join(d, "spread_check.txt"), "w").write("\n".join(out) + "\n")
