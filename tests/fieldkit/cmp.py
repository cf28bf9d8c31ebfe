"""The engine's eps beside the audit's.

`main` (cmpNN.py, rounds 23-26): the referee lines (refereeNN.py output) where the engine's eps and the audit's differ
by more than 2e-5 (or either is missing). usage: python cmpNN.py referee*.log   (`tag`: the round's probe tag, e.g.
PROBE26)

`live` (cmp27.py, cmp28.py): the live pair's eps (the round's live*.log, the deck run as written: fieldkit.live) beside
the audit's rows for that pair in every stage (fieldkit.rows); the flag says whether the last stage's row is within
0.004 of the engine's (the step error at dt 1e-6 s is 0.0015: controls kn 2000 0.413435 / 0.414916, kn 5000 0.578975
/ 0.580587). usage: python cmpNN.py
"""
import glob
import os
import re

from fieldkit import rows


def main(argv, *, tag):
    """Print ok/DIFF for each referee line of the log files `argv`."""
    for f in argv:
        for l in open(f):
            m = re.match(rf"(\S+) (\d) (\d) {tag} eps (\S+) .*\| audit (\S+)", l)
            if not m:
                print("?", l.strip()[:220]); continue
            n, t, u, e, a = m.groups()
            try:
                ok = abs(float(e) - float(a)) <= 2e-5
            except ValueError:
                ok = False
            print(("ok  " if ok else "DIFF"), n, t, u, "engine", e, "audit", a)


def _pair(n):
    """Round 27's live pair by the folder's name: types 1 1 in its pair11 decks, types 1 3 in Y09, else types 1 2."""
    return "types 1 1" if "pair11" in n else ("types 1 3" if n.startswith("Y09") else "types 1 2")


def live(H, *, tag, pair=_pair, impact=True):
    """Print, for each deck folder named in ``H/live*.log``, its audit rc, the flag, the live line and the audit's rows.

    The pair is ``type 1 on wall floor`` for a WALL deck, else ``pair(name)`` unless the folder has a PAIR file.
    With `impact` a wall deck's live speed (the speed the sphere left the floor with) is divided by the speed it hit
    the floor with, sqrt(1 + 2 g gap) for a sphere set falling at 1 m/s from `gap` above touching (fieldkit.live
    prints the first alone), so that it is an eps (round 28).
    """
    live = {}
    for f in sorted(glob.glob(os.path.join(H, "live*.log"))):
        for l in open(f):
            p = l.split()
            if len(p) > 1:
                live[p[0]] = " ".join(p[1:])
    for n in sorted(live):
        d = os.path.join(H, "decks", n)
        if not os.path.exists(d + "/audit.rc"):
            print(n, "not audited"); continue
        rc = open(d + "/audit.rc").read().strip()
        wall = "WALL" in open(d + "/LIVE").read()
        name = "type 1 on wall floor" if wall else pair(n)
        if os.path.exists(d + "/PAIR"):
            name = open(d + "/PAIR").read().strip()
        got = rows.stages(d, name)
        m = re.search(rf"{tag} eps (\S+)", live[n])
        flag = ""
        mm = re.search(r"\(stages (\d+)\)", got); ns = mm.group(1) if mm else "0"
        lastrow = dict(x.split(":", 1) for x in got.split() if x.startswith("s") and ":" in x).get("s" + ns)
        if rc == "0" and m:
            e = float(m.group(1))
            if wall and impact:
                z = float(re.search(r"create_atoms 1 single 0.02 0.02 (\S+)", open(d + "/in.deck").read()).group(1))
                e = e / (1 + 2 * 9.81 * (z - 0.002)) ** 0.5
            if lastrow is not None and not all(x.rstrip("*").replace(".", "", 1).isdigit() for x in lastrow.split("..")):
                flag = "noeps-row(" + ("engine passes" if e < 0 else "engine collides") + ")"
            elif lastrow is None or lastrow.endswith("*"):
                flag = "ok(no contact)" if e < 0 else "CHECK(no row, engine collides)"
            else:
                v = [float(x.rstrip("*")) for x in lastrow.split("..")]
                flag = "ok" if min(v) - 0.004 <= e <= max(v) + 0.004 else ("CHECK(row, engine passes)" if e < 0 else "CHECK")
        err = open(d + "/audit.err").read().strip().splitlines()
        print(f"{n} rc={rc} {flag} | live {live[n][:60]} | audit {name}: {got} | {err[-1][:200] if rc != '0' and err else ''}")
