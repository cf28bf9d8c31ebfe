"""The atoms LAMMPS holds at a deck's end (id type radius mass density z): the deck run to its end in a scratch copy
with a write_dump appended; the atom count and the first atom of each type are printed. PROBE_PRE (env): commands,
;-separated, put before the dump; PROBE_FILE (env): the file the deck ends in. No import from the project.
usage: python stateNN.py DECKDIR   (`round`, `var` and `tag` as in fieldkit.probe)
"""
import math
import os
import shutil

from fieldkit import scratch


def main(argv, *, round, var, tag):
    """Print the end state of deck folder ``argv[0]``."""
    d = argv[0]
    deck, top, tmp = scratch.copy(d, round, "state")
    dump = f"{var}state.txt"
    tail = f"\nwrite_dump all custom {dump} id type radius mass z modify sort id\n"
    scratch.append(tmp, os.environ.get("PROBE_FILE", deck), scratch.commands("PROBE_PRE") + tail)
    p = scratch.run("lmp", tmp, deck)
    rows = []
    if os.path.exists(os.path.join(tmp, dump)):
        for l in open(os.path.join(tmp, dump)).read().split("ITEM: ATOMS")[1].splitlines()[1:]:
            i, ty, r, m, z = l.split()
            rows.append(f"{tag} id {i} type {ty} radius {r} mass {m} rho {float(m)/(4/3*math.pi*float(r)**3):.6g} z {z}")
    seen = {}
    for r in rows:
        seen.setdefault(r.split()[4], r)
    print(scratch.name(d), f"{len(rows)} atoms", *seen.values(), *[l for l in p.stdout.splitlines() if "ERROR" in l][:2], sep="\n  ")
    shutil.rmtree(top)
