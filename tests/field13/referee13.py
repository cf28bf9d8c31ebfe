"""Field round 13's referee: round 10's head-on referee (tests/field10/referee.py, imported unchanged), with
two additions a staged audit needs: a check may name the stage whose rows it compares ("stage": k, 1-based,
from the audit's "stages"; default the last, which is "pairs"/"walls"), and a text the row's model must hold
("match", in its model, its "sizes" or its "at": e.g. "smallest" for the row at the smallest eps over the sizes
present). No import from the project:
the engine decides. Sizes and masses in spec.json are the engine's own (engine_state.txt beside the deck).

usage: python referee13.py DECKDIR   (reads DECKDIR/spec.json and audit.json, writes DECKDIR/referee.txt)
"""
import importlib.util
import json
import os
import sys

_here = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("referee10", os.path.join(_here, "..", "field10", "referee.py"))
R = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(R)


def rows_for(audit, chk):
    st = chk.get("stage")
    src = audit if st is None else audit["stages"][st - 1]
    sub = {"pairs": src.get("pairs", []), "walls": src.get("walls", [])}
    if chk.get("match"):
        key = "walls" if "wall" in chk else "pairs"
        sub[key] = [r for r in sub[key] if chk["match"] in r.get("model", "") + " " + str(r.get("sizes", "")) + " " + json.dumps(r.get("at", ""))]
    return R.audit_rows(sub, chk)


def main(d):
    spec = json.load(open(os.path.join(d, "spec.json")))
    spec["_dir"] = d
    audit = json.load(open(os.path.join(d, "audit.json")))
    out, worst = [], 0.0
    for chk in spec["checks"]:
        row = rows_for(audit, chk)
        label = chk.get("label") or (f"wall {chk.get('wall_id')} type {chk['t1']}" if "wall" in chk
                                     else f"types {chk['t1']} {chk['t2']}")
        if chk.get("stage"):
            label += f" (stage {chk['stage']})"
        if row is None:
            out.append(f"{label}: NO AUDIT ROW")
            continue
        sp = chk.get("spec_override")
        s2 = dict(spec, **sp) if sp else spec
        for k in chk.get("speed_idx", range(len(row["speeds"]))):
            g, ea = row["speeds"][k], row["eps"][k]
            spc = (row.get("steps_per_contact") or [None] * len(row["speeds"]))[k]
            dt = row.get("dt")
            tc_guess = chk.get("tc") or (spc * dt if spc and dt else 1e-4)
            m = R.measure(s2, chk, g, tc_guess)
            if m.get("sticks"):
                verdict = "agree" if (ea in (None, 0.0) or row["sticks"][k]) else "DISAGREE"
                out.append(f"{label} g {g:.6g}: audit eps {ea} sticks={row['sticks'][k]}; engine sticks  [{verdict}]")
                continue
            diff = None if ea is None else ea - m["eps0"]
            tol = max(2e-5, 5 * m["wobble"])
            verdict = "agree" if diff is not None and abs(diff) <= tol else "DISAGREE"
            if diff is not None:
                worst = max(worst, abs(diff))
            if chk.get("at_dt") and row.get("eps_at_dt") and row["eps_at_dt"][k] is not None:
                run = R._lammps_run if s2["engine"] == "lammps" else R._liggghts_run
                e_dt, n_dt, _ = run(s2, chk, g, dt, 100000)
                spr = (row.get("eps_at_dt_spread") or [None] * len(row["speeds"]))[k]
                ok = abs(e_dt - row["eps_at_dt"][k]) < 1e-5
                out.append(f"{label} g {g:.6g}: at the deck's dt {dt}: audit eps_at_dt {row['eps_at_dt'][k]} "
                           f"(spread {spr}); engine touching on a step {e_dt:.8f} after {n_dt} steps  "
                           f"[{'agree' if ok else 'DISAGREE'}]")
            out.append(f"{label} g {g:.6g}: audit eps {ea} ; engine {m['eps0']:.8f} (wobble {m['wobble']:.1e}; "
                       f"dt->0 from {', '.join('%.8f' % v for v in m['vals'])} at tc/{R.NSTEPS}) "
                       f"tc {m['tc']:.4g} ; diff {diff if diff is None else '%.2e' % diff}  [{verdict}]")
    txt = "\n".join(out) + f"\nworst |audit - engine| = {worst:.2e}\n"
    open(os.path.join(d, "referee.txt"), "w").write(txt)
    print(txt)


if __name__ == "__main__":
    main(sys.argv[1])
