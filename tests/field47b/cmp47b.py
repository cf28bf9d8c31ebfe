"""Field round 47b: the live pair's eps measured by the engine (live*.log: round 37's live37.py for B/O/H, LIVE37 lines;
pubref46.py for the public P decks, PUB46 lines, or the deck's own output file) beside the audit's rows for that pair
or wall in every stage (audit.out, tests/fieldkit/rows.py). The kit's cmp_np flags: the last stage's row against the
engine's value (within 0.004), `ok`, `ok(no contact)`, `CHECK`, `noeps-row`, `ENGINE-STOPS` (rc 0 where the engine
stopped), and `match=` the stages whose row is within 0.004. A deck whose engine value is a file of several (a loop of
passes) is flagged FILE and judged by hand (judged46.txt).
usage: python cmp47b.py > cmp47b.out"""
import glob
import os
import re
import sys

H = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(H, ".."))
from fieldkit import rows  # noqa: E402


def _f(d, name, default=None):
    p = os.path.join(d, name)
    return open(p).read().strip() if os.path.exists(p) else default


live = {}
for f in sorted(glob.glob(os.path.join(H, "live*.log"))):
    for l in open(f):
        p = l.strip().split(" | ")
        if len(p) > 1:
            live[p[0]] = p[1:]
for n in sorted(live):
    d = os.path.join(H, "decks", n)
    if not os.path.isdir(d):
        continue   # a folder rewritten before any audit (live3.log has its new form)
    if not os.path.exists(d + "/audit.rc"):
        print(n, "not audited"); continue
    rc = open(d + "/audit.rc").read().strip()
    pair = _f(d, "PAIR", "types 1 2")
    got = rows.stages(d, pair, _f(d, "G", "1"))
    e, filevals, stopped = None, None, False
    for part in live[n]:
        m = re.search(r"(LIVE37|PUB46) eps (\S+)", part)
        if m and part.startswith("np=1"):
            e = float(m.group(2))
        if part.startswith("np=1") and ("ERROR" in part or "TIMEOUT" in part or "rc=1" in part):
            stopped = True
        if part.startswith("file:"):
            filevals = part[5:].strip()
    mm = re.search(r"\(stages (\d+)\)", got); ns = mm.group(1) if mm else "0"
    st = dict(x.split(":", 1) for x in got.split() if x.startswith("s") and ":" in x)
    lastrow = st.get("s" + ns)
    isnum = lambda r: all(y.rstrip("*").replace(".", "", 1).isdigit() for y in r.split(".."))
    flag = ""
    if filevals and filevals != "(none)":
        flag = "FILE"
    elif rc == "0" and e is not None:
        if lastrow is not None and not isnum(lastrow):
            flag = "noeps-row(" + ("engine passes" if e < 0 else "engine collides") + ")"
        elif lastrow is None or lastrow.endswith("*"):
            flag = "ok(no contact)" if e < 0 else "CHECK(no row, engine collides)"
        else:
            v = [float(x.rstrip("*")) for x in lastrow.split("..")]
            flag = "ok" if min(v) - 0.004 <= e <= max(v) + 0.004 else ("CHECK(row, engine passes)" if e < 0 else "CHECK")
    elif rc == "0" and stopped:
        flag = "ENGINE-STOPS"
    elif rc == "0":
        flag = "NO-REFEREE-VALUE"
    elif stopped:
        flag = "both-stop"
    else:
        flag = "AUDIT-STOPS(engine runs)"
    near = [k for k, r in st.items() if e is not None and isnum(r) and
            min(float(y.rstrip("*")) for y in r.split("..")) - 0.004 <= e <= max(float(y.rstrip("*")) for y in r.split("..")) + 0.004]
    flag += " match=" + (",".join(near) or "none")
    err = open(d + "/audit.err").read().strip().splitlines()
    ref = f"np1={e}" + (f" file[{filevals[:160]}]" if filevals else "") + (" engine-stops" if stopped else "")
    print(f"{n} rc={rc} {flag} | live {ref} | audit {pair}: {got} | {err[-1][:220] if rc != '0' and err else ''}")
