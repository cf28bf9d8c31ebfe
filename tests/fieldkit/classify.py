"""The field rounds' outcome tables (the class of each deck folder, for FINDINGS.md).

`by_prefix` (classifyNN.py, rounds 18-23): the round's dict {class: folder-name prefixes}, checked to name every folder
of its decks/ exactly once, printed as table rows. `judged` and `key` (rounds 26, 27): the classes judged by hand, read
from the round's judgedNN.txt (lines ``CLASS => NAME ...``), and the name a folder is judged under.
"""
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
