"""The sizes and masses LAMMPS holds after each run of a deck (field rounds 15, 16, 20, 21), by running the deck's lines one
at a time through the `lammps` module (in a scratch copy of the deck's folder) and reading the atoms after each
`run`/`minimize` line. Decks with `jump`/`label`/`next` are run whole (`file`) and only the end state is given.
No import from the project: the engine is the referee.
usage: python engine_stagesNN.py DECKDIR [DECK]   -> DECKDIR/engine_stages.json and a summary on stdout
"""
import json, os, re, shutil, tempfile


def state(l):
    """The sizes and masses the engine `l` holds: {type: sorted [(radius, mass), ...]}."""
    n = l.get_natoms()
    out = {}
    if n == 0:
        return out
    t = l.numpy.extract_atom("type"); r = l.numpy.extract_atom("radius"); m = l.numpy.extract_atom("rmass")
    for k in range(len(t)):
        out.setdefault(str(int(t[k])), set()).add((round(float(r[k]), 12), float(m[k])))
    return {k: sorted(v) for k, v in out.items()}


def main(argv, *, round):
    """Write DECKDIR/engine_stages.json for `argv` (DECKDIR [DECK]) and print the stages."""
    import lammps  # the engine, needed only here: the module imports without it
    d = argv[0].rstrip("/")
    deck = argv[1] if len(argv) > 1 else "in.deck"
    text = open(os.path.join(d, deck)).read()
    tmp = tempfile.mkdtemp(prefix=f"field{round}-st.")
    shutil.copytree(d, tmp, dirs_exist_ok=True)
    cwd = os.getcwd(); os.chdir(tmp)
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    stages = []
    try:
        if re.search(r"^\s*(jump|label|next)\b", text, re.M):
            l.file(deck)
            stages.append({"line": "end", "state": state(l), "time": l.get_thermo("time"), "dt": l.get_thermo("dt")})
        else:
            for i, ln in enumerate(text.splitlines(), 1):
                if not ln.strip() or ln.lstrip().startswith("#"):
                    continue
                l.command(ln)
                if re.match(r"\s*(run|minimize)\b", ln):
                    stages.append({"line": i, "state": state(l), "time": l.get_thermo("time"), "dt": l.get_thermo("dt")})
    except Exception as e:  # the engine's own stop
        stages.append({"line": "error", "error": str(e)})
    l.close(); os.chdir(cwd); shutil.rmtree(tmp)
    json.dump(stages, open(os.path.join(d, "engine_stages.json"), "w"), indent=1)
    for s in stages:
        print(s.get("line"), s.get("error") or "; ".join(f"type {k}: " + ", ".join(f"r {a:.6g} m {b:.6g}" for a, b in v)
                                                       for k, v in sorted(s["state"].items())), "dt", s.get("dt"))


