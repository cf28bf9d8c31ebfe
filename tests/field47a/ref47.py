"""Field round 47a referee: each deck folder run AS WRITTEN by LIGGGHTS (1 process) in a scratch copy, from the
deck's own folder, with the folder's REF text (if any) appended after its last line. Prints rc, the PUB47 line (the
pair's eps: relative normal speed after / before; the floor's rebound speed from energy / impact speed), the first
ERROR line, and the number of `Loop time` lines (runs made). Timeout 300 s.
usage: python ref47.py DECKDIR ..."""
import os
import shutil
import subprocess
import sys
import tempfile

for d in sys.argv[1:]:
    d = d.rstrip("/")
    top = tempfile.mkdtemp(prefix="field47a-ref.")
    tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp, ignore=shutil.ignore_patterns("audit.*", "escape.txt"))
    deck = open(os.path.join(d, "DECK")).read().strip()
    ref = os.path.join(d, "REF")
    if os.path.exists(ref):
        with open(os.path.join(tmp, deck), "a", encoding="latin-1") as fh:
            fh.write("\n" + open(ref).read())
    cwd = os.path.join(tmp, os.path.dirname(deck))
    try:
        p = subprocess.run(["stdbuf", "-o0", "-e0", "liggghts", "-in", os.path.basename(deck), "-log", "none"], cwd=cwd, capture_output=True,
                           text=True, errors="replace", timeout=300, stdin=subprocess.DEVNULL)
        txt = p.stdout + p.stderr
        rc = p.returncode
    except subprocess.TimeoutExpired as e:
        txt = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        rc = "timeout"
    lines = txt.splitlines()
    pub = [l.strip() for l in lines if l.startswith("PUB47")][:1]
    err = [l.strip() for l in lines if "ERROR" in l][:1]
    loops = sum(l.startswith("Loop time") for l in lines)
    print(os.path.basename(d), "| rc", rc, "| runs", loops, "|", " ; ".join(pub + err) or "(no line)", flush=True)
    shutil.rmtree(top)
