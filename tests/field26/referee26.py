"""Field round 26: for a LAMMPS deck folder, the engine's end state (state26) then probe26 for types 1 1 1 2 and 2 2 with the
sizes the engine holds (first atom of each type), beside the audit's last-stage g = 1 rows. usage: python referee22.py DECKDIR ..."""
import os, re, subprocess, sys
H = os.path.dirname(os.path.abspath(__file__))
ARGS = os.environ.get("PROBE_ARGS", "").split()  # G Z XC DT for decks in other units
for d in sys.argv[1:]:
    st = subprocess.run([sys.executable, os.path.join(H, "state26.py"), d], capture_output=True, text=True).stdout
    size = {}
    for m in re.finditer(r"type (\d+) radius (\S+) mass \S+ rho (\S+)", st):
        size.setdefault(m.group(1), (2 * float(m.group(2)), float(m.group(3))))
    rows, name = {}, None
    for l in open(os.path.join(d, "audit.out")):
        if l.startswith("# stage"):
            rows = {}
        elif not l.startswith(" "):
            name = l.split(":")[0].split(" [")[0]
        elif l.split()[:2] == ["g", "1"]:
            rows[name] = l.split()[3]
    for t, u in (("1", "1"), ("1", "2"), ("2", "2")):
        if t not in size or u not in size:
            print(os.path.basename(d.rstrip("/")), t, u, "no atom of this type in the engine", "| audit", rows.get(f"types {t} {u}")); continue
        (dd, rho), (dd2, rho2) = size[t], size[u]
        p = subprocess.run([sys.executable, os.path.join(H, "probe26.py"), d, t, u, str(dd), str(rho), str(dd2), str(rho2)] + ARGS, capture_output=True, text=True).stdout.strip()
        print(p, "| audit", rows.get(f"types {t} {u}"), "| engine sizes", dd, rho, dd2, rho2, flush=True)
