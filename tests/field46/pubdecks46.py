"""Field round 46, P family: public LIGGGHTS decks no earlier round used (SOURCES names repository, commit, path; their
text is not committed: .gitignore), copied at run time into decks/P*/ with the files they read:
- idaholab/LIGGGHTS-INL (commit d69df361): the INL tutorial t01a (static angle of repose, mono-sphere: hertz,
  rolling_friction cdt, a mesh cylinder and a primitive floor stopper, dt 1e-6) and the INL example
  rolling_resistance_cdtnonlinear2 (INL-only models: LIGGGHTS-PUBLIC stops on them);
- Qin-jg-410/liggghts-code (commit faa6e536): LIGGGHTS_WEAR_problem (a silo of four meshes, hertz + rolling_friction
  epsd2, four radii in one type, dt 1e-4) and Brachistochrone (hertz + cohesion sjkr + rolling epsd2, seven radii).
Forms: AS (as published; runs shortened where said: every `run` made 20 steps), PAIR (reduced to a measurable pair: the
deck's own lines up to a named line, edits listed, then two of its spheres approaching at 1 m/s along x far from every
wall: REF prints vx[2]-vx[1]), FLOOR (the same head, one sphere of the deck dropped onto its floor at 1 m/s).
usage: python pubdecks46.py INL-MIRROR-GIT-DIR QIN-MIRROR-GIT-DIR"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
INL, QIN = "d69df361fc9b0a78ba09a50242bc76552d9bd71e", "faa6e5361872dbeec52ab1e6cf385516b96656e3"
T01 = "examples/LIGGGHTS/INL_tutorials/t01a_static_angle_of_repose_monosphere/"
RR = "examples/LIGGGHTS/INL/rolling_resistance_cdtnonlinear2/"
WEAR = "LIGGGHTS_WEAR_problem-main/LIGGGHTS_WEAR_problem-main/"
BRA = "Brachistochrone-LIGGGHTS-simulation-main/Brachistochrone-LIGGGHTS-simulation-main/"

PAIRTAIL = ("create_atoms 1 single {x1} 0 {z} units box\ncreate_atoms 1 single {x2} 0 {z} units box\n"
            "set atom 1 diameter {d} density {r}\nset atom 2 diameter {d} density {r}\ngroup p1 id 1\ngroup p2 id 2\n"
            "velocity p1 set 0.5 0 0\nvelocity p2 set -0.5 0 0\n{integ}run {n}\n")
FLOORTAIL = ("create_atoms 1 single 0 0 {z} units box\nset atom 1 diameter {d} density {r}\ngroup p1 id 1\n"
             "velocity p1 set 0 0 {vz}\n{integ}run {n}\n")


def shorten(text):
    return re.sub(r"(?m)^(\s*run\s+)(\S+)(.*)$", lambda m: m.group(1) + "20", text)


def drop(*prefixes):
    """Remove each line (with its & continuations) whose first words are one of prefixes."""
    def f(text):
        out, skip = [], False
        for l in text.splitlines(keepends=True):
            if skip:
                skip = l.rstrip().endswith("&"); continue
            if any(l.split()[:len(p.split())] == p.split() for p in prefixes):
                skip = l.rstrip().endswith("&"); continue
            out.append(l)
        return "".join(out)
    return f


def upto(word, nth=1):
    """The lines up to and including the nth line whose first word(s) are `word`."""
    def f(text):
        lines, k, seen = text.splitlines(keepends=True), None, 0
        for i, l in enumerate(lines):
            if l.split()[:len(word.split())] == word.split():
                seen += 1
                if seen == nth:
                    k = i; break
        return "".join(lines[:k + 1])
    return f


REF2 = 'variable P46 equal vcm(p2,x)-vcm(p1,x)\nprint "PUB46 eps ${P46}"\n'
# vz at the start: 1 m/s at touching after a fall of 0.1 mm
VZ = -(1 - 2 * 9.81 * 1e-4) ** 0.5
REFF = lambda rad: f'variable P46 equal sqrt(vz[1]^2+2*9.81*(z[1]-{rad}))\nprint "PUB46 eps ${{P46}}"\n'
# name: (mirror key, folder, deck, edits, tail or None, meta)
P = {
    "P01_inl_t01a_pair": ("INL", T01, "in.staticAOR_MonoSphere", [drop("fix ins"), upto("timestep")],
                          PAIRTAIL.format(x1=-0.00305, x2=0.00305, z=0.5, d=0.006, r=300, integ="", n=3000),
                          {"G": "1", "PAIR": "types 1 1", "REF": REF2}),
    "P02_inl_t01a_floor": ("INL", T01, "in.staticAOR_MonoSphere", [drop("fix ins"), upto("timestep")],
                           FLOORTAIL.format(z=0.0031, d=0.006, r=300, vz=f"{VZ:.10f}", integ="", n=3000),
                           {"G": "1", "PAIR": "type 1 on wall stopper_bot", "REF": REFF(0.003)}),
    "P03_inl_t01a_asis_short": ("INL", T01, "in.staticAOR_MonoSphere", [shorten], None, {"G": "1", "PAIR": "types 1 1"}),
    "P04_inl_rolling_cdtnonlinear2_asis": ("INL", RR, "in.rolling_resistance_cdtnonlinear2", [shorten], None, {"G": "1", "PAIR": "types 1 1"}),
    "P05_wear_pair": ("QIN", WEAR, "input.liggghts", [upto("fix m5")],
                      PAIRTAIL.format(x1=-0.0301, x2=0.0301, z=4.0, d=0.06, r=4000, integ="", n=1000),
                      {"G": "1", "PAIR": "types 1 1", "REF": REF2}),
    "P06_wear_asis_short": ("QIN", WEAR, "input.liggghts", [shorten], None, {"G": "1", "PAIR": "types 1 1"}),
    "P07_brachis_asis_layout": ("QIN", BRA, "brachis", [shorten], None, {"G": "1", "PAIR": "types 1 1"}),
    "P08_brachis_asis_mesh_dir": ("QIN", BRA, "brachis", [shorten], None, {"G": "1", "PAIR": "types 1 1", "MESHDIR": "mesh"}),
    "P09_brachis_pair": ("QIN", BRA, "brachis", [drop("fix ins", "fix ins2", "dump", "run"), upto("pair_coeff")],
                         "fix integrate all nve/sphere\ntimestep ${dt}\n" + PAIRTAIL.format(x1=-0.0251, x2=0.0251, z=8.0, d=0.05, r=800, integ="", n=400),
                         {"G": "1", "PAIR": "types 1 1", "REF": REF2, "MESHDIR": "mesh"}),
    "P10_wear_pair_nocohesion_control": ("QIN", WEAR, "input.liggghts", [upto("fix m5"), lambda t: t.replace("rolling_friction epsd2", "")],
                                         PAIRTAIL.format(x1=-0.0301, x2=0.0301, z=4.0, d=0.06, r=4000, integ="", n=1000),
                                         {"G": "1", "PAIR": "types 1 1", "REF": REF2}),
}


def git(mirror, *a):
    return subprocess.run(["git", "-C", mirror] + list(a), capture_output=True).stdout


def write(inl, qin):
    mir = {"INL": (inl, INL), "QIN": (qin, QIN)}
    for name, (key, folder, deck, edits, tail, meta) in P.items():
        m, c = mir[key]
        d = os.path.join(HERE, "decks", name)
        os.makedirs(os.path.join(d, "post"), exist_ok=True)
        for f in git(m, "ls-tree", "-r", "--name-only", c, folder).decode().split("\n"):
            rel = f[len(folder):]
            if not f or "/" in rel or rel.endswith((".txt", ".py")) or (rel != deck and (rel.startswith("in.") or rel.endswith(".liggghts") or rel == "brachis")):
                continue
            target = os.path.join(d, meta.get("MESHDIR", ""), rel) if rel.lower().endswith(".stl") else os.path.join(d, rel)
            os.makedirs(os.path.dirname(target), exist_ok=True)
            open(target, "wb").write(git(m, "show", f"{c}:{f}"))
        text = git(m, "show", f"{c}:{folder}{deck}").decode("latin-1")
        for e in edits:
            text = e(text)
        if tail:
            text = text + "\nneigh_modify delay 0\n" + tail
        open(os.path.join(d, deck), "w", encoding="latin-1").write(text)
        meta = {k: v for k, v in meta.items() if k != "MESHDIR"}
        meta.update(DECK=deck, LIGGGHTS="", NP="1")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + ("" if v.endswith("\n") else "\n"))
    print(len(P), "public deck folders")


if __name__ == "__main__":
    write(sys.argv[1], sys.argv[2])
