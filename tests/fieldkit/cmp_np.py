"""The live pair's eps measured by the engine beside the audit's rows, rounds 35-38 (live_np.py's logs: the deck
as written, on 1 process and on 2).

`main(folder, tag=..., match=True)` (cmpNN.py; round 34's without `match=`): for each deck folder of the round in ``folder``, the audit's rows for the pair in
every stage, the engine's values by process count (their lines start with ``tag``), a flag for the last stage's row
against the 1-process value (within 0.004, the step error at dt 1e-6 s being 0.0015), NPDIFF where the process counts
disagree, and `match=`: the stages whose row is within 0.004 of the 1-process value (a run every is made as its parts,
so the pair meets in a stage before the last: that stage is judged by hand in the round's judgedNN.txt).
"""
import glob
import os
import re

from . import rows


def _f(d, name, default=None):
    p = os.path.join(d, name)
    return open(p).read().strip() if os.path.exists(p) else default


def main(folder, *, tag, match=True):
    live = {}
    for f in sorted(glob.glob(os.path.join(folder, "live*.log"))):
        for l in open(f):
            p = l.strip().split(" | ")
            if len(p) > 1:
                live[p[0]] = p[1:]
    for n in sorted(live):
        d = os.path.join(folder, "decks", n)
        if not os.path.exists(d + "/audit.rc"):
            print(n, "not audited"); continue
        rc = open(d + "/audit.rc").read().strip()
        pair = _f(d, "PAIR", "types 1 2")
        got = rows.stages(d, pair)
        vals = {}
        for part in live[n]:
            m = re.match(r"np=(\d+) (.*)", part)
            e = re.search(rf"{tag} eps (\S+)", m.group(2))
            vals[int(m.group(1))] = float(e.group(1)) if e else None
        mm = re.search(r"\(stages (\d+)\)", got); ns = mm.group(1) if mm else "0"
        lastrow = dict(x.split(":", 1) for x in got.split() if x.startswith("s") and ":" in x).get("s" + ns)
        e = vals.get(1) if vals.get(1) is not None else next((v for v in vals.values() if v is not None), None)
        flag = ""
        if rc == "0" and e is not None:
            if lastrow is not None and not all(x.rstrip("*").replace(".", "", 1).isdigit() for x in lastrow.split("..")):
                flag = "noeps-row(" + ("engine passes" if e < 0 else "engine collides") + ")"
            elif lastrow is None or lastrow.endswith("*"):
                flag = "ok(no contact)" if e < 0 else "CHECK(no row, engine collides)"
            else:
                v = [float(x.rstrip("*")) for x in lastrow.split("..")]
                flag = "ok" if min(v) - 0.004 <= e <= max(v) + 0.004 else ("CHECK(row, engine passes)" if e < 0 else "CHECK")
        elif rc == "0":
            flag = "ENGINE-STOPS"
        got_np = [v for v in vals.values()]
        if rc == "0" and len(got_np) > 1 and (None in got_np and any(v is not None for v in got_np) or
                                              (None not in got_np and max(got_np) - min(got_np) > 0.002)):
            flag += " NPDIFF"
        if match:
            st = dict(x.split(":", 1) for x in got.split() if x.startswith("s") and ":" in x)
            near = [k for k, r in st.items() if e is not None and all(y.rstrip("*").replace(".", "", 1).isdigit() for y in r.split(".."))
                    and min(float(y.rstrip("*")) for y in r.split("..")) - 0.004 <= e <= max(float(y.rstrip("*")) for y in r.split("..")) + 0.004]
            flag += " match=" + (",".join(near) or "none")
        err = open(d + "/audit.err").read().strip().splitlines()
        lv = " ".join(f"np{k}={v}" for k, v in sorted(vals.items()))
        print(f"{n} rc={rc} {flag} | live {lv} | audit {pair}: {got} | {err[-1][:220] if rc != '0' and err else ''}")

