"""Field round 13: from each deck's escape.txt (files newer than a stamp made just before its audits), keep the
ones a deck or its engine could have written: the decks' canary names (f13*), engine logs (log.lammps,
log.liggghts, log.audit), the dumps and data they name (atoms.dump, audit.dump, audit.json outside the deck's
own audit files, plate.txt, post/, restart/, *.restart, *.bishear, *.vtk, *.cfg), and any new file in the deck's folder or
its parent; other developers' pytest folders and checkouts are left out. usage: python escape_check.py DECKDIR ...   (prints 'ESCAPE deck: path' lines, or 'clean deck')"""
import os, re, sys
PAT = re.compile(r"(^|/)(f13[^/]*|log\.lammps|log\.liggghts|log\.audit|atoms\.dump|audit\.dump|plate\.txt|"
                 r"[^/]*\.restart[^/]*|[^/]*\.bishear|[^/]*\.vtk|[^/]*\.cfg)$|/(post|restart)/")
for d in sys.argv[1:]:
    d = d.rstrip("/")
    name = os.path.basename(d)
    hits = []
    if not os.path.exists(os.path.join(d, "escape.txt")):
        continue
    for ln in open(os.path.join(d, "escape.txt")).read().splitlines():
        if ln.startswith(("/proc/", "/sys/", "/dev/", "/tmp/pytest-of-")) or "/fresh-dir/" in ln:
            continue
        own = ln.startswith(d + "/") or ln.startswith("decks/")
        if own and os.path.basename(ln) in ("engine_state.txt", "spec.json", "referee.txt", "ENGINE.txt", "README"):
            continue
        if PAT.search(ln) or (own and not os.path.basename(ln).startswith(("audit.", "escape"))):
            hits.append(ln)
    print("\n".join(f"ESCAPE {name}: {h}" for h in hits) if hits else f"clean {name}")
