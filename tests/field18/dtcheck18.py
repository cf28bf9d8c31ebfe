"""Field round 18: the eps LAMMPS gives at a deck's own time step, over where in a step the contact starts.
Two spheres (round 10's referee set-up, its LAMMPS runner reused unchanged) start apart by f g dt, f = 0, 1/N, ...,
so that first touch falls at fraction f of a step; each run is at the deck's dt. Prints min and max over f beside
the audit's "eps there A to B" spread (audit.json eps_at_dt_spread). No import from the project.
usage: python dtcheck18.py DECKDIR CHECK_INDEX SPEED_INDEX [N]   (spec.json's check, the audit row's speed)"""
import importlib.util, json, os, sys

_here = os.path.dirname(os.path.abspath(__file__))
_s = importlib.util.spec_from_file_location("referee10", os.path.join(_here, "..", "field10", "referee.py"))
R = importlib.util.module_from_spec(_s)
_s.loader.exec_module(R)


def main(d, ci, si, n=16):
    spec = json.load(open(os.path.join(d, "spec.json")))
    audit = json.load(open(os.path.join(d, "audit.json")))
    chk = dict(spec["checks"][ci])
    row = R.audit_rows(audit, chk)
    g, dt = row["speeds"][si], row["dt"]
    vals = []
    for k in range(n):
        c = dict(chk, gap=(k / n) * g * dt + 1e-12 * g, gapsteps=2)
        e, steps, sep = R._lammps_run(spec, c, g, dt, 200000)
        vals.append(e if sep else float("nan"))
    sp = (row.get("eps_at_dt_spread") or [None] * len(row["speeds"]))[si]
    spc = (row.get("steps_per_contact") or [None] * len(row["speeds"]))[si]
    out = (f"{os.path.basename(d.rstrip('/'))} types {chk['t1']} {chk.get('t2', 'wall')} g {g:g} dt {dt:g} ({spc} steps per contact): "
           f"LAMMPS over {n} start fractions {min(vals):.6f} to {max(vals):.6f}; audit spread {sp}; audit dt->0 {row['eps'][si]:.6f}")
    print(out)
    with open(os.path.join(d, "dtcheck.txt"), "a") as fh:
        fh.write(out + "\n")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]) if len(sys.argv) > 4 else 16)
