"""Field round 28: the live pair's eps (live*.log, the deck run as written) beside the audit's rows for that pair in every
stage (audit.out); flags where the last stage differs by more than 0.004 (the step error at dt 1e-6 s is 0.0015: controls
kn 2000 0.413435 / 0.414916, kn 5000 0.578975 / 0.580587). usage: python cmp28.py"""
import glob, os, re, subprocess, sys
H = os.path.dirname(os.path.abspath(__file__))
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
    pair = "type 1 on wall floor" if "WALL" in open(d + "/LIVE").read() else "types 1 2"
    if os.path.exists(d + "/PAIR"):
        pair = open(d + "/PAIR").read().strip()
    rows = subprocess.run([sys.executable, os.path.join(H, "rows28.py"), d, pair], capture_output=True, text=True).stdout.strip()
    m = re.search(r"LIVE28 eps (\S+)", live[n])
    flag = ""
    mm = re.search(r"\(stages (\d+)\)", rows); ns = mm.group(1) if mm else "0"
    lastrow = dict(x.split(":", 1) for x in rows.split() if x.startswith("s") and ":" in x).get("s" + ns)
    if rc == "0" and m:
        e = float(m.group(1))
        if "WALL" in open(d + "/LIVE").read():  # the end speed over the impact speed sqrt(1 + 2 g gap)
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
    print(f"{n} rc={rc} {flag} | live {live[n][:60]} | audit {pair}: {rows} | {err[-1][:200] if rc != '0' and err else ''}")
