"""The field rounds' LAMMPS referee (rounds 22-27): for each deck folder, the engine's end state (the round's
stateNN.py), then the round's probeNN.py for pairs of the types the engine holds at the end (sizes of the first atom
of each type), printed beside the audit's last-stage rows at speed G. PROBE_ARGS (env): G Z XC DT for decks in other
units (G also picks the audit row).
usage: python refereeNN.py DECKDIR ...
"""
import itertools
import os
import re
import subprocess
import sys


def audit_rows(path, g="1"):
    """The audit's last-stage rows at speed `g` in text output `path`: {row name: eps as written}."""
    rows, name = {}, None
    for l in open(path):
        if l.startswith("# stage"):
            rows = {}
        elif not l.startswith(" "):
            name = l.split(":")[0].split(" [")[0]
        elif l.split()[:1] == ["g"] and abs(float(l.split()[1]) - float(g)) < 1e-9 * max(1, float(g)):
            rows[name] = l.split()[3]
    return rows


def main(argv, *, state, probe, pairs=None):
    """Referee deck folders `argv` with the round's `state` and `probe` scripts.

    `pairs`: the type pairs probed, e.g. ``(("1", "1"), ("1", "2"), ("2", "2"))``; None (from round 26) for every
    pair of the types the engine holds.
    """
    args = os.environ.get("PROBE_ARGS", "").split()  # G Z XC DT for decks in other units
    g = args[0] if args else "1"
    for d in argv:
        st = subprocess.run([sys.executable, state, d], capture_output=True, text=True).stdout
        size = {}
        for m in re.finditer(r"type (\d+) radius (\S+) mass \S+ rho (\S+)", st):
            size.setdefault(m.group(1), (2 * float(m.group(2)), float(m.group(3))))
        if not size:
            print(os.path.basename(d.rstrip("/")), "no state:", st.strip()[-300:]); continue
        rows = audit_rows(os.path.join(d, "audit.out"), g)
        for t, u in pairs or itertools.combinations_with_replacement(sorted(size, key=int), 2):
            if t not in size or u not in size:
                print(os.path.basename(d.rstrip("/")), t, u, "no atom of this type in the engine", "| audit", rows.get(f"types {t} {u}")); continue
            (dd, rho), (dd2, rho2) = size[t], size[u]
            p = subprocess.run([sys.executable, probe, d, t, u, str(dd), str(rho), str(dd2), str(rho2)] + args, capture_output=True, text=True).stdout.strip()
            print(p, "| audit", rows.get(f"types {t} {u}"), "| engine sizes", dd, rho, dd2, rho2, flush=True)
