"""Field round 37 referee: the deck run AS WRITTEN on 1 process and on several (tests/fieldkit/live_np.py says how).
Round 37 keeps what the deck's folder is made of: its symbolic links stay links (the kit's copy made each a file,
which changes a deck that writes or moves the file a link points to), a folder's HARDLINKS file ("LINK TARGET" lines)
names hard links made again in the copy, and a link leaving the folder to ../../shared finds round 37's shared folder
there, as in the deck's own place.
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


scratch.copy = copy

if __name__ == "__main__":
    live_np.main(sys.argv[1:], round=37, var="L37", tag="LIVE37")
