"""Field round 46: the referee of the public decks (R folders, pubdecks46.py) and of the M decks (whose own print
says PUB46): each deck run AS WRITTEN by its engine (LIGGGHTS where the folder has a LIGGGHTS file, else LAMMPS)
on 1 process in a scratch copy of its folder, with the folder's REF text appended after its last line (its print says
PUB46 eps ...), or, where the deck itself writes the measured eps (REFFILE: a file the deck writes, its first column
the ${P46} put into the deck's own output line by the variant's edit, or for chung03 calcCoeffRes), that file's lines.
Timeout 900 s. usage: python pubref45.py DECKDIR ...   prints NAME | np=1 PUB46 eps ... | file: ...
"""
import os
import shutil
import subprocess
import sys
import tempfile


def _f(d, n):
    p = os.path.join(d, n)
    return open(p).read().strip() if os.path.exists(p) else None


for d in sys.argv[1:]:
    d = d.rstrip("/")
    name = os.path.basename(d)
    top = tempfile.mkdtemp(prefix="field46-pub.")
    tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp, symlinks=True)
    for f in os.listdir(tmp):
        if f.startswith("audit.") or f == "escape.txt":
            os.remove(os.path.join(tmp, f))
    deck = _f(d, "DECK")
    ref = _f(d, "REF")
    if ref:
        with open(os.path.join(tmp, deck), "a", encoding="latin-1") as fh:
            fh.write("\n" + ref + "\n")
    try:
        eng = "liggghts" if os.path.exists(os.path.join(d, "LIGGGHTS")) else "lmp"
        p = subprocess.run(["stdbuf", "-o0", "-e0", eng, "-in", deck, "-log", "none"], cwd=tmp, capture_output=True,
                           text=True, errors="replace", timeout=900)
        out = [l.strip() for l in (p.stdout + p.stderr).splitlines() if l.startswith("PUB46") or "ERROR" in l][:2]
        rc = p.returncode
    except subprocess.TimeoutExpired:
        out, rc = ["TIMEOUT"], "timeout"
    parts = [name, f"np=1 rc={rc} " + (" ; ".join(out) or "(no line)")]
    rf = _f(d, "REFFILE")
    if rf:
        p_ = os.path.join(tmp, rf)
        parts.append("file: " + (" / ".join(l.split()[0] + " " + " ".join(l.split()[1:2]) for l in open(p_) if l.strip()) if os.path.exists(p_) else "(none)"))
    print(" | ".join(parts), flush=True)
    shutil.rmtree(top)
