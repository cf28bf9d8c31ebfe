"""Field round 37 referee: the deck run AS WRITTEN on 1 process and on several (tests/fieldkit/live_np.py says how).
Round 37 keeps what the deck's folder is made of: its symbolic links stay links (the kit's copy made each a file,
which changes a deck that writes or moves the file a link points to), a folder's HARDLINKS file ("LINK TARGET" lines)
names hard links made again in the copy, and a link leaving the folder to ../../shared finds round 37's shared folder
there, as in the deck's own place. Each process count runs in a fresh copy.
usage: python live37.py DECKDIR ...      prints NAME | np=1 LIVE37 eps ... | np=2 LIVE37 eps ..."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import live_np, scratch  # noqa: E402


def copy(d, round, kind):
    """scratch.copy with the folder's links kept (see the module's head)."""
    deck = open(os.path.join(d, "DECK")).read().strip()
    top = tempfile.mkdtemp(prefix=f"field{round}-{kind}.")
    tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp, symlinks=True)
    hard = os.path.join(d, "HARDLINKS")
    if os.path.exists(hard):
        for line in open(hard):
            if line.split():
                a, b = line.split()
                os.remove(os.path.join(tmp, a))
                os.link(os.path.join(tmp, b), os.path.join(tmp, a))
    shared = os.path.join(d, "..", "..", "shared")
    if os.path.isdir(shared):
        shutil.copytree(shared, os.path.join(top, "a", "shared"))
    return deck, top, tmp


def main(argv, tag="LIVE37"):
    """live_np.main's loop with a fresh copy for each process count (a deck that moves its own files, F08 F09,
    leaves the kit's shared copy without them for the second run)."""
    import subprocess
    for d in argv:
        parts = [scratch.name(d)]
        for n in [int(x) for x in live_np._f(d, "NP", "1 2").split()]:
            deck, top, tmp = copy(d, 37, "live")
            lig, t = live_np.tail(d, "L37", tag)
            scratch.append(tmp, deck, t)
            try:
                p = subprocess.run(live_np.cmd(lig, n, deck), cwd=tmp, capture_output=True, text=True, errors="replace", timeout=600)
                out = [l.strip() for l in (p.stdout + p.stderr).splitlines() if l.startswith(tag) or "ERROR" in l][:2]
            except subprocess.TimeoutExpired:
                out = ["TIMEOUT"]
            parts.append(f"np={n} " + (" ; ".join(out) or "(no line)"))
            shutil.rmtree(top)
        print(" | ".join(parts), flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
