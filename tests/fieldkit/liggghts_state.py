"""Field rounds 13, 20, 21: run a LIGGGHTS deck to its end (scratch copy, nested so ../ stays inside) and print what the
engine holds: per atom type the distinct (radius, mass) pairs, the atom count and z range, the step and time.
No import from the project. usage: python liggghts_stateNN.py DECKDIR DECK"""
import os, shutil, subprocess, tempfile


def main(argv):
    """Print the end state of deck folder ``argv[0]`` run with deck file ``argv[1]``."""
    d, deck = argv[0], argv[1]
    top = tempfile.mkdtemp(prefix="field13-lstate."); tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp)
    with open(os.path.join(tmp, deck), "a") as fh:
        fh.write("\nvariable f13s equal step\nvariable f13t equal time\n"
                 "dump f13final all custom 1 f13final.txt id type radius mass z\n"
                 "run 0\nprint \"F13STATE ${f13s} ${f13t}\"\n")
    p = subprocess.run(["liggghts", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
    seen, zs, n = {}, [], 0
    try:
        lines = open(os.path.join(tmp, "f13final.txt")).read().splitlines()
        k = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        for l in lines[k + 1:]:
            i, t, r, m, z = l.split()
            seen.setdefault(int(t), set()).add((float(r), float(m))); zs.append(float(z)); n += 1
    except (OSError, ValueError) as e:
        print("no final dump:", e, p.stdout[-800:])
    for t in sorted(seen):
        print(f"type {t}: " + ", ".join(f"r {a:.6g} m {b:.8g}" for a, b in sorted(seen[t])))
    print("atoms", n, "z range", min(zs) if zs else None, max(zs) if zs else None)
    print([l for l in p.stdout.splitlines() if l.startswith("F13STATE")][-1:] or p.stdout[-500:])
    shutil.rmtree(top)
