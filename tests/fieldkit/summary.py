"""The field rounds' summaries of audited deck folders, in the three forms the rounds used.

`by_row` (summNN.py, rounds 18-21): one line per audited row of each deck (from audit.json), the rc, and stderr lines
other than the usual time-step, tsuji-version and gravity notes; ``detail=True`` (rounds 20, 21) adds D1, D2, alpha,
gamma and dt to each row. usage: python summNN.py DECKDIR ...
`by_block` (summNN.py, rounds 22-24): one block per deck folder of the round's decks/: engine rc/PROBE lines, audit rc,
the last stage's g = 1 rows, stderr notes (cut). usage: python summNN.py [NAME ...]
`by_line` (summNN.py, rounds 25, 26): one line per deck folder: audit rc, engine's line, last-stage g = 1 rows
(pair=eps), the last line of the audit's stderr when it refuses. usage: python summNN.py DECKDIR ...
"""
import json, os

SKIP = ("at the deck's time step", "tsuji damping as LAMMPS", "fix gravity (grav): a gravity on the sphere")


def by_row(argv, *, detail=False):
    """Print the rows of deck folders `argv` (see the module's docstring)."""
    for d in argv:
        d = d.rstrip("/")
        rc = open(os.path.join(d, "audit.rc")).read().strip()
        print(f"######## {os.path.basename(d)} rc={rc}")
        try:
            a = json.load(open(os.path.join(d, "audit.json")))
        except Exception:
            a = {}
        stages = a.get("stages") or [a]
        for k, st in enumerate(stages):
            for r in st.get("pairs", []) + st.get("walls", []):
                lab = ("pair " + " ".join(map(str, r["types"]))) if "wall" not in r else f"wall {r['wall']} t{r['types']}"
                eps = ", ".join(f"{g:g}:{'' if e is None else '%.8f' % e}" for g, e in zip(r["speeds"], r["eps"]))
                extra = f" sizes={r.get('sizes')}" if r.get("sizes") else ""
                if detail:
                    more = f"D1={r.get('D1')} D2={r.get('D2')} a={r.get('alpha')} g={r.get('gamma')} dt={r.get('dt')} | "
                    print(f"  s{k+1} {lab}: {r['model'][:90]} | {r.get('end')} | {more}{eps}{extra}"[:600])
                else:
                    print(f"  s{k+1} {lab}: {r['model'][:90]} | {r.get('end')} | {eps}{extra}"[:400])
        for ln in open(os.path.join(d, "audit.err")):
            if not any(s in ln for s in SKIP):
                print("  ERR " + ln.strip()[:420])


def by_block(argv, *, decks):
    """Print a block for each named deck folder of `decks` (all of them when `argv` is empty)."""
    for n in argv or sorted(os.listdir(decks)):
        d = os.path.join(decks, n)
        eng = open(os.path.join(d, "ENGINE.txt")).read().strip().replace("\n", " | ") if os.path.exists(os.path.join(d, "ENGINE.txt")) else "?"
        rc = open(os.path.join(d, "audit.rc")).read().strip()
        out = open(os.path.join(d, "audit.out")).read().splitlines()
        err = open(os.path.join(d, "audit.err")).read().splitlines()
        rows, cur = [], None
        for l in out:
            if l.startswith("# stage"):
                rows = []; cur = l[:40]
            elif not l.startswith(" "):
                cur2 = l.split(":")[0]
            elif l.strip().startswith("g 1 "):
                rows.append(f"{cur2}={l.split()[3]}")
        print(f"== {n}  audit rc={rc}\n  ENGINE: {eng[:400]}\n  AUDIT: {' ; '.join(rows)}")
        for l in err:
            if "fix gravity" in l or "steps per contact" in l or "a contact lasts" in l:
                continue
            print("  ERR:", l[:300])


def by_line(argv):
    """Print one line for each deck folder of `argv`."""
    for d in argv:
        n = os.path.basename(d.rstrip("/"))
        try:
            rc = open(os.path.join(d, "audit.rc")).read().strip()
        except OSError:
            print(n, "not audited"); continue
        eng = open(os.path.join(d, "ENGINE.txt")).readline().strip() if os.path.exists(os.path.join(d, "ENGINE.txt")) else "no engine"
        rows, name = {}, None
        for l in open(os.path.join(d, "audit.out")):
            if l.startswith("# stage"):
                rows = {}
            elif not l.startswith(" ") and not l.startswith("#"):
                name = l.split(":")[0].split(" [")[0].replace("types ", "").replace("type ", "t").replace(" on wall ", "@")
            elif l.split()[:2] == ["g", "1"]:
                rows[name] = l.split()[3][:8]
        err = open(os.path.join(d, "audit.err")).read()
        print(n, "rc", rc, "|", eng, "|", " ".join(f"{k}={v}" for k, v in rows.items()), "|", err.strip().splitlines()[-1][:200] if rc != "0" and err.strip() else "")
