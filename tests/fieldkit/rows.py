"""The audit's rows for one pair or wall in every stage of a deck folder's audit.out (rows27.py, rows28.py, cmp.live):
the g rows (g = G, default 1) of the pair or wall NAME (default ``types 1 2``) in each stage, a range (rows
'smallest'/'largest' over the sizes present) printed lo..hi, '*' marking a row flagged 'does not happen here'.
usage: python rowsNN.py DECKDIR [NAME=types 1 2] [G=1]
"""
import re


def stages(d, want="types 1 2", G="1"):
    """The rows of `want` at g `G` in each stage of ``d/audit.out``, as ``s1:e s2:lo..hi (stages N)`` ('-' for none).

    Examples
    --------
    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> _ = open(os.path.join(d, "audit.out"), "w").write(
    ...     "# stage 1 of 2: run 1\\ntypes 1 2: hooke\\n  g 1   eps 0.41\\n  g 2   eps 0.40\\n"
    ...     "# stage 2 of 2: run 2\\ntypes 1 2 [does not happen here]: hooke\\n  g 1   eps 0.58\\n")
    >>> stages(d)
    's1:0.41 s2:0.58* (stages 2)'
    >>> import shutil; shutil.rmtree(d)
    """
    st, name, res, n_stages = 0, None, {}, 0
    for l in open(d + "/audit.out"):
        if l.startswith("# stage"):
            st += 1
            n_stages = int(l.split()[4].rstrip(":")) if l.split()[3] == "of" else n_stages
        elif not l.startswith(" "):
            m = re.match(r"(types \d+ \d+|type \d+ on wall [^:\s]+)", l)
            name = (m.group(1) + ("*" if "does not happen" in l else "")) if m else None
        elif l.split()[:2] == ["g", G] and name and name.rstrip("*") == want:
            res.setdefault(st, []).append(l.split()[3] + ("*" if name.endswith("*") else ""))
    last = max(n_stages, st)
    return (" ".join(f"s{k}:{'..'.join(v)}" for k, v in res.items()) or "-") + f" (stages {last})"


def main(argv):
    """Print the rows for command line `argv` (see the module's usage)."""
    print(stages(argv[0], *argv[1:3]))
