"""The scratch copy every field-round probe runs a deck in, and the engine call.

A deck folder is copied three levels down a fresh temporary folder (so ``../`` and ``shell cd ..`` in the deck stay
inside it), probe commands are appended to the file the deck ends in, byte for byte (lone CRs, NULs and Latin-1 as
the engine reads them), and the engine runs the deck there with no log file.
"""
import os
import shutil
import subprocess
import tempfile


def copy(d, round, kind):
    """Copy deck folder `d` to a scratch folder named for the round and the tool.

    Returns ``(deck, top, tmp)``: the deck's file name (from ``d/DECK``), the scratch folder to remove at the end
    and the copy's folder inside it.
    """
    deck = open(os.path.join(d, "DECK")).read().strip()
    top = tempfile.mkdtemp(prefix=f"field{round}-{kind}.")
    tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp)
    return deck, top, tmp


def commands(name):
    """The ;-separated commands an environment variable holds, one a line ('' when unset).

    Examples
    --------
    >>> os.environ["FIELDKIT_DOC"] = "unfix p;group t2 type 2"
    >>> commands("FIELDKIT_DOC")
    'unfix p\\ngroup t2 type 2'
    >>> commands("FIELDKIT_UNSET_DOC")
    ''
    """
    return os.environ.get(name, "").replace(";", "\n")


def one_sphere(grav, t, at, v, dia, rho, group=None):
    """The commands that leave a deck's end holding one sphere alone: its gravity fix `grav` removed, its atoms
    deleted, a sphere of type `t` made at `at` ("x y z", box units) in group `v` + 'a' (by type `t`, or `group`),
    with diameter `dia` and density `rho`; the wall probes then set it moving.

    Examples
    --------
    >>> print(one_sphere("grav", 2, "0 0 0.002", "f26", "0.004", "2500", group="id 1"), end="")
    <BLANKLINE>
    unfix grav
    delete_atoms group all
    create_atoms 2 single 0 0 0.002 units box
    group f26a id 1
    set group f26a diameter 0.004 density 2500
    """
    return f"""
unfix {grav}
delete_atoms group all
create_atoms {t} single {at} units box
group {v}a {group or f"type {t}"}
set group {v}a diameter {dia} density {rho}
"""


def append(tmp, target, tail):
    """Append `tail` to file `target` of the copy, keeping its bytes as they are (read and written as Latin-1)."""
    path = os.path.join(tmp, target)
    txt = open(path, newline="", encoding="latin-1").read()
    open(path, "w", newline="", encoding="latin-1").write(txt + tail)


def run(engine, tmp, deck, **kw):
    """Run `deck` in the copy with `engine` (``lmp`` or ``liggghts``), no log file; the finished process."""
    return subprocess.run([engine, "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True, **kw)


def name(d):
    """The deck folder's name, as the probes print it first.

    Examples
    --------
    >>> name("tests/field27/decks/G19_set_atom_type_first/")
    'G19_set_atom_type_first'
    """
    return os.path.basename(d.rstrip("/"))
