"""Field round 46 (lists): TABLE.md from the probes' outputs (run.sh). usage: python table.py OUTDIR > TABLE.md
One row per case: where the command stands, the engine's eps, the audit's exit status and eps (types 1 2, the first
row: stage 1 where there are stages), whether its stderr names the command (notes beyond the deck's own), a verdict.
The named column says refused where the audit exits 2. Verdicts by rule: harmless (the engine's eps within 0.003 of the audit's), named (differs, and a note says so: a note
naming the command, a stage note, or the pair not audited), refused (exit 2; fairly where the engine's eps differs or
the engine stops too), SW (differs, exit 0, no note); then the overrides below, each with its reason."""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = ["lmp_between", "lmp_start", "lmp_every", "lmp_typed", "lmp_named", "lmp_misc", "lmp_python", "lmp_more",
         "lmp_preno", "lmp_integ", "lmp_integrators", "lig_cases", "lig_more", "lig_preno", "lig_integ", "lig_start",
         "lig_ms", "lig_excl", "lig_head"]
#: notes every deck of the probe gets (LIGGGHTS: the run after a run in a box with a fixed face)
BASE_NOTES = {"lmp": 0, "lig": 1}
OVERRIDES = {
    ("lmp_start", 32): "engine stops (processors after the box), audit exit 0 with eps: its note says processors is "
                       "'not executed' and not that LAMMPS stops there",
    ("lmp_python", 0): "named: the engine stops (no embedded Python); the note says python is not executed and that "
                       "the runs after a stop do not happen",
    ("lmp_python", 1): "named: as above",
    ("lmp_typed", 1): "harmless: type 2 held still, approach 0.7714 m/s: 0.358051 / 0.7714 = 0.4642, audit 0.4650",
    ("lmp_typed", 3): "named (not audited)",
    ("lmp_start", 12): "harmless; noisy: store/state called 'not understood: may add forces' from the start",
    ("lmp_integrators", 4): "harmless; noisy: nve/sphere/omp called 'not understood: may add forces'",
    ("lig_start", 0): "harmless: type 2 held still, approach 0.7714 m/s: 0.420936 / 0.7714 = 0.5457, audit 0.5458",
    ("lig_more", 6): "harmless eps, wrong note: multisphere with no clumps moves no sphere, the audit says each sphere "
                     "is integrated twice (a contact lasting half the steps)",
    ("lig_ms", 2): "harmless eps, wrong note: as lig_more 06",
    ("lig_ms", 0): "SW: multisphere, the only integrator, moves no single sphere (the pair never meets); audit 0.5, "
                   "no word (sw/S1)",
    ("lig_ms", 3): "SW: as lig_ms 00, the run with every",
    ("lig_integ", 3): "SW: as lig_ms 00",
    ("lig_ms", 1): "named (not audited), for a wrong reason (multisphere counted as integrating type 2)",
    ("lig_start", 5): "named (not audited), for a wrong reason (multisphere counted as an integrator)",
    ("lmp_preno", 16): "named (not audited; its reason speaks of grown spheres): reset_atoms id then pre no, the pair "
                       "across the periodic face: LAMMPS -3.7",
    ("lmp_between", 43): "refused fairly: read_dump of a file a line of the deck writes",
    ("lmp_between", 50): "refused fairly: include of a file a shell line writes",
    ("lig_more", 4): "refused: cohesion sjkr from the start (not mapped)",
    ("lmp_between", 18): "harmless: the pair is gone (the probe's vx[2] fails); the audit says type 2 has no particle",
    ("lmp_start", 21): "named (no eps: found late)",
    ("lmp_start", 22): "named (no eps: found late)",
    ("lig_cases", 31): "named (no eps: found late)",
    ("lmp_start", 24): "refused here (Lost atoms in the audit's own run); in three other runs rc0, the rows not "
                       "audited and named: flaky",
    ("lmp_named", 4): "named (the addforce note)",
}


def where(case):
    f = (case.split(" || ") + ["", "", "", ""])[:4]
    between, start, head, first = (x.strip() for x in f)
    if "every" in first:
        return "every"
    if between not in ("", "print x", "print hello"):
        return "between, pre no" if "pre no" in between else "between"
    return "start" if (start or head or first) else "-"


def rows(path, kind):
    out = []
    for line in open(path):
        m = re.match(r"(\d\d) \| (.*?) \| engine (.*?) \| audit rc(\d) (\S+) \| notes=(\d+)", line)
        if m:
            out.append(dict(n=int(m[1]), engine=m[3].strip(), rc=int(m[4]), eps=m[5], notes=int(m[6])))
    return out


def verdict(r, kind):
    named = r["notes"] > BASE_NOTES[kind]
    try:
        e = float(r["engine"])
    except ValueError:
        e = None
    if e is None:
        return named, ("refused fairly (the engine stops too)" if r["rc"] else "engine stops, audit prints")
    if r["rc"] and r.get("where") == "between, pre no":
        return named, "refused fairly (pre no: the engine does not take the change, as the refusal says)"
    if r["rc"]:
        return named, "refused fairly" if abs(e - (0.4149 if kind == "lmp" else 0.5)) > 0.003 else \
            "refused (the engine's eps is the deck's plain one)"
    try:
        a = float(r["eps"])
    except ValueError:
        return named, "named (pair not audited)"
    if abs(e - a) <= 0.003:
        return named, "harmless"
    return named, "named" if named else "SW"


def main(outdir):
    print("# Field round 46 (lists): the audit's harmless lists, engine-checked\n")
    print(open(os.path.join(HERE, "TABLE.head")).read())
    for f in FILES:
        kind = f[:3]
        cases = [l.rstrip("\n") for l in open(os.path.join(HERE, f + ".txt")) if l.strip() and not l.startswith("#")]
        title = [l[1:].strip() for l in open(os.path.join(HERE, f + ".txt")) if l.startswith("#")][:1]
        print(f"\n## {f} ({title[0] if title else ''})\n")
        print("| # | where | command (BETWEEN \\|\\| START \\|\\| HEAD \\|\\| FIRSTRUN) | engine eps | audit rc, eps | named | verdict |")
        print("|---|---|---|---|---|---|---|")
        for r in rows(os.path.join(outdir, f + ".out"), kind):
            case = cases[r["n"]]
            r["where"] = where(case)
            named, v = verdict(r, kind)
            v = OVERRIDES.get((f, r["n"]), v)
            cell = case.replace("|", "\\|")
            cell = cell if len(cell) < 160 else cell[:157] + "..."
            eng = r["engine"] if len(r["engine"]) < 60 else r["engine"][:57] + "..."
            print(f"| {r['n']:02d} | {where(case)} | `{cell}` | {eng} | rc{r['rc']} {r['eps']} | "
                  f"{'refused' if r['rc'] else 'yes' if named else 'no'} | {v} |")


if __name__ == "__main__":
    main(sys.argv[1])
