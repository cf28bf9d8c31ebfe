"""Field round 27: for a LAMMPS deck folder, the engine's end state (state26) then probe26 for every pair of the types the
engine holds at the end (sizes of the first atom of each type), beside the audit's last-stage g rows. PROBE_ARGS (env):
G Z XC DT for decks in other units (G also picks the audit row). usage: python referee26.py DECKDIR ..."""
import itertools, os, re, subprocess, sys
H = os.path.dirname(os.path.abspath(__file__))
ARGS = os.environ.get("PROBE_ARGS", "").split()  # G Z XC DT for decks in other units
G = ARGS[0] if ARGS else "1"
for d in sys.argv[1:]:
    st = subprocess.run([sys.executable, os.path.join(H, "state27.py"), d], capture_output=True, text=True).stdout
    size = {}
    for m in re.finditer(r"type (\d+) radius (\S+) mass \S+ rho (\S+)", st):
        size.setdefault(m.group(1), (2 * float(m.group(2)), float(m.group(3))))
    if not size:
        print(os.path.basename(d.rstrip("/")), "no state:", st.strip()[-300:]); continue
    rows, name = {}, None
    for l in open(os.path.join(d, "audit.out")):
        if l.startswith("# stage"):
            rows = {}
        elif not l.startswith(" "):
            name = l.split(":")[0].split(" [")[0]
        elif l.split()[:1] == ["g"] and abs(float(l.split()[1]) - float(G)) < 1e-9 * max(1, float(G)):
            rows[name] = l.split()[3]
    for t, u in itertools.combinations_with_replacement(sorted(size, key=int), 2):
        (dd, rho), (dd2, rho2) = size[t], size[u]
        p = subprocess.run([sys.executable, os.path.join(H, "probe27.py"), d, t, u, str(dd), str(rho), str(dd2), str(rho2)] + ARGS, capture_output=True, text=True).stdout.strip()
        print(p, "| audit", rows.get(f"types {t} {u}"), "| engine sizes", dd, rho, dd2, rho2, flush=True)
