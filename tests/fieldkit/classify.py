"""The field rounds' outcome tables (the class of each deck folder, for FINDINGS.md).

`by_prefix` (classifyNN.py, rounds 18-23): the round's dict {class: folder-name prefixes}, checked to name every folder
of its decks/ exactly once, printed as table rows. `judged` and `key` (rounds 26-28): the classes judged by hand, read
from the round's judgedNN.txt (lines ``CLASS => NAME ...``), and the name a folder is judged under. `outcome`
(classifyNN.py, rounds 27, 28): the table of every folder of decks/, judgedNN.txt first, then the live pair's
agreement in cmpNN.out (fieldkit.cmp.live).
"""
import collections
import os


def by_prefix(C, decks):
    """Check that the prefixes of `C` name each folder of `decks` once; print the table rows."""
    folders = sorted(os.listdir(decks))
    seen = {}
    for cat, names in C.items():
        for n in names.split():
            hits = [f for f in folders if f.split("_")[0] == n]
            assert len(hits) == 1, (n, hits)
            assert hits[0] not in seen, (n, seen.get(hits[0]))
            seen[hits[0]] = cat
    missing = [f for f in folders if f not in seen]
    assert not missing, missing
    for cat, names in C.items():
        print(f"| {cat} | {len(names.split())} | {names} |")
    print(f"| total | {len(folders)} | |")


def judged(path):
    """The hand-judged classes of file `path`: {name: class}; blank lines and # comments skipped.

    A class may itself hold ' => ': the names are what follows the last one.
    """
    J = {}
    for line in open(path):
        if line.strip() and not line.startswith("#"):
            cls, names = line.rsplit(" => ", 1)
            for n in names.split():
                J[n] = cls.strip()
    return J


def key(n):
    """The name deck folder `n` is judged under: its prefix, or the whole name for a LIGGGHTS tutorial copy.

    Examples
    --------
    >>> key("G19_set_atom_type_first"), key("X_lig_chute_wear")
    ('G19', 'X_lig_chute_wear')
    """
    return n if n.startswith("X_lig") else n.split("_")[0]


def outcome(H, *, round, order):
    """Print the outcome table of round folder `H`: each class, its count and names; then the total.

    A folder's class is its judged one (``H/judgedNN.txt``), else correct where ``H/cmpNN.out`` flags its live pair
    ok, else a LIGGGHTS tutorial or UNJUDGED. Rows are sorted by the first of `order` (class-name prefixes, a tuple
    of prefixes ranking alike) the class starts with, worst first, then the rest; by name within a rank.
    """
    J = judged(os.path.join(H, f"judged{round}.txt"))
    ok = set()
    for l in open(os.path.join(H, f"cmp{round}.out")):
        p = l.split()
        if len(p) > 2 and p[2] in ("ok", "ok(no"):
            ok.add(p[0])
    table = collections.defaultdict(list)
    for n in sorted(os.listdir(os.path.join(H, "decks"))):
        k = key(n)
        if k in J:
            table[J[k]].append(k)
        elif n in ok:
            table["correct, engine-checked (live pair)"].append(k)
        elif n.startswith("X_lig"):
            table["LIGGGHTS tutorial (see FINDINGS)"].append(n[6:])
        else:
            table["UNJUDGED"].append(k)
    rank = lambda c: next((i for i, p in enumerate(order) if c.startswith(p)), len(order))
    for cls, names in sorted(table.items(), key=lambda x: (rank(x[0]), x[0])):
        print(f"| {cls} | {len(names)} | {' '.join(names)} |")
    print("total", sum(len(v) for v in table.values()))
