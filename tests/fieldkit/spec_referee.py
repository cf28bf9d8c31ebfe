"""The spec referee of field rounds 13, 20 and 21: round 10's head-on referee (tests/field10/referee.py), imported and run unchanged,
one check at a time, with two additions a staged audit needs: a check may name the stage whose rows it compares
("stage": k, 1-based, from the audit's "stages"; default the last, which is "pairs"/"walls"), a text the row
must hold ("match", in its model, its "sizes" or its "at": e.g. "smallest" for the row at the smallest eps over
the sizes present), and spec keys of its own ("spec_override", e.g. a second wall in "post"). For each check a
scratch folder gets the one-check spec.json and an audit.json cut to the rows it names, and round 10's main()
referees it there. No import from the project: the engine decides. Sizes and masses in spec.json are the
engine's own (engine_state.txt beside the deck).

usage: python refereeNN.py DECKDIR   (reads DECKDIR/spec.json and audit.json, writes DECKDIR/referee.txt)
"""
import contextlib
import importlib.util
import io
import json
import os
import shutil
import tempfile

_here = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("referee10", os.path.join(_here, "..", "field10", "referee.py"))
R = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(R)


def cut_audit(audit, chk):
    """The audit's rows a check compares: its stage's, and among them those holding its "match"."""
    st = chk.get("stage")
    src = audit if st is None else audit["stages"][st - 1]
    sub = {"pairs": src.get("pairs", []), "walls": src.get("walls", [])}
    if chk.get("match"):
        key = "walls" if "wall" in chk else "pairs"
        sub[key] = [r for r in sub[key] if chk["match"] in r.get("model", "") + " " + str(r.get("sizes", ""))
                    + " " + json.dumps(r.get("at", ""))]
    return sub


def main(d):
    """Referee deck folder `d` check by check; write d/referee.txt and print it."""
    spec = json.load(open(os.path.join(d, "spec.json")))
    audit = json.load(open(os.path.join(d, "audit.json")))
    out, worst = [], 0.0
    for chk in spec["checks"]:
        one = {k: v for k, v in spec.items() if k != "checks"}
        one.update(chk.get("spec_override", {}))
        c = {k: v for k, v in chk.items() if k not in ("spec_override", "stage", "match")}
        base = chk.get("label") or (f"wall {chk.get('wall_id')} type {chk['t1']}" if "wall" in chk
                                    else f"types {chk['t1']} {chk['t2']}")
        c["label"] = base + (f" (stage {chk['stage']})" if chk.get("stage") else "")
        one["checks"] = [c]
        with tempfile.TemporaryDirectory(prefix="field13-ref.") as tmp:
            for f in spec.get("files", []):
                shutil.copy(os.path.join(d, f), tmp)
            json.dump(one, open(os.path.join(tmp, "spec.json"), "w"))
            json.dump(cut_audit(audit, chk), open(os.path.join(tmp, "audit.json"), "w"))
            with contextlib.redirect_stdout(io.StringIO()):
                R.main(tmp)
            lines = open(os.path.join(tmp, "referee.txt")).read().splitlines()
        worst = max(worst, float(lines[-1].split("=")[-1]))
        out += lines[:-1]
    txt = "\n".join(out) + f"\nworst |audit - engine| = {worst:.2e}\n"
    open(os.path.join(d, "referee.txt"), "w").write(txt)
    print(txt)

