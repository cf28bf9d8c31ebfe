"""Field round 45, R family: public LIGGGHTS decks of ParticulateFlow/LIGGGHTS-PFM (examples/LIGGGHTS/PFM, commit
d075b977, GPL; not used by rounds 1-44) copied at run time into decks/R*/ (git ignores their text: SOURCES names them)
with the files they read. Each is run AS PUBLISHED (the engine is LIGGGHTS-PUBLIC 3.8.0, which refuses several PFM-only
settings: the audit must stop where it stops) and, where that helps the referee, as a variant whose edits are listed
here (EDITS: text replacements, nothing else changed; the runs shortened only where said). The referee (pubref45.py)
appends REF's text after the deck's last line, or reads the file REFFILE the deck itself writes.
usage: python pubdecks45.py MIRROR-GIT-DIR   (the fetched snapshot of ParticulateFlow/LIGGGHTS-PFM)"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
COMMIT = "d075b977"
PFM = "examples/LIGGGHTS/PFM/"
CH = PFM + "tests/contact_models/chung/"
HARD = ("atom_style      granular", "hard_particles yes\natom_style      granular")   # LIGGGHTS-PUBLIC: E > 1e9 needs it
HIST = ("index incremental_history", "index history")                                # a PFM-only tangential model
PRIMES = ["15485863", "15485867", "32452843", "32452867", "49979687", "49979693", "67867967", "67867979", "86028121",
          "86028157", "104395301", "104395303"]


def p45(expr, before="fix     output"):
    """A variable P45 = expr defined before the deck's own output fix, and ${P45} put first in its printed line."""
    return [(before, f"variable P45 equal {expr}\n{before}"), ('print 1 "', 'print 1 "${P45} ')]


def primes(text):
    """Every particletemplate/distribution/insert seed made a prime above 10000 (LIGGGHTS-PUBLIC refuses the PFM decks' 1, 451, ...)."""
    it = iter(PRIMES * 4)
    return re.sub(r"(particletemplate/sphere|particledistribution/discrete|seed)(\s+)(\d+\.?\d*)", lambda m: m.group(1) + m.group(2) + next(it), text)


def shorten(k):
    """Every run N (with or without upto) divided by k (at least 1): the runs shortened, nothing else."""
    return lambda text: re.sub(r"(?m)^(\s*run\s+)(\d+)", lambda m: m.group(1) + str(max(1, int(m.group(2)) // k)), text)


# name: (source folder, deck file, edits [(old, new)] or callables, meta {G, PAIR, REF | REFFILE})
R = {
    "R01_chung01_asis": (CH + "test01", "in.elastic_normal_impact_2_spheres", [], {"G": "20", "PAIR": "types 1 1"}),
    "R02_chung02_asis": (CH + "test02", "in.elastic_normal_impact_sphere_plane", [], {"G": "0.2"}),
    "R03_chung03_asis": (CH + "test03", "in.inelastic_normal_impact_sphere_plane", [], {"G": "3.9"}),
    "R04_chung04_asis": (CH + "test04", "in.oblique_impact_on_wall", [], {"G": "3.9"}),
    "R05_chung05_asis": (CH + "test05", "in.oblique_impact_on_wall", [], {"G": "5"}),
    "R06_chung06_asis": (CH + "test06", "in.impact_on_wall", [], {"G": "0.2"}),
    "R07_chung07_asis": (CH + "test07", "in.impact_2_spheres", [], {"G": "0.4", "PAIR": "types 1 1"}),
    "R08_chung08_asis": (CH + "test08", "in.impact_2_spheres", [], {"G": "0.2", "PAIR": "types 1 1"}),
    "R09_thornton_asis": (PFM + "tests/contact_models/thornton", "in.oblique_impact_on_wall", [], {"G": "5"}),
    # variants the public engine runs
    "R10_chung01_pair": (CH + "test01", "in.elastic_normal_impact_2_spheres", [HARD, HIST],
                         {"G": "20", "PAIR": "types 1 1", "REF": 'variable P45 equal (vx[2]-vx[1])/20\nprint "PUB45 eps ${P45}"\n'}),
    "R11_chung02_wall": (CH + "test02", "in.elastic_normal_impact_sphere_plane", [HARD, HIST],
                         {"G": "0.2", "PAIR": "type 1 on wall mesh_walls", "REF": 'variable P45 equal vz[1]/0.2\nprint "PUB45 eps ${P45}"\n'}),
    "R12_chung03_loop": (CH + "test03", "in.inelastic_normal_impact_sphere_plane", [HARD, HIST],
                         {"G": "3.9", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/restitution_hertz_4000.txt"}),
    "R13_chung03_one_e": (CH + "test03", "in.inelastic_normal_impact_sphere_plane",
                          [HARD, HIST, ("universe 0.2 0.4 0.6 0.8 1.0", "universe 0.6")],
                          {"G": "3.9", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/restitution_hertz_4000.txt"}),
    "R14_chung07_loop": (CH + "test07", "in.impact_2_spheres", [HARD] + p45("(vz[1]-vz[2])/0.4"),
                         {"G": "0.4", "PAIR": "types 1 1", "REFFILE": "post/hertz_rebound_properties.txt"}),
    "R15_chung08_loop": (CH + "test08", "in.impact_2_spheres", [HARD] + p45("(vz[1]-vz[2])/0.2"),
                         {"G": "0.2", "PAIR": "types 1 1", "REFFILE": "post/hertz_rebound_properties.txt"}),
    "R16_chung06_loop": (CH + "test06", "in.impact_on_wall", [HARD] + p45("vz[1]/0.2"),
                         {"G": "0.2", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/hertz_rebound_properties.txt"}),
    "R17_chung04_loop": (CH + "test04", "in.oblique_impact_on_wall", [HARD] + p45("vz[1]/(3.9*cos(PI/180*${Theta}))"),
                         {"G": "3.9", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/hertz_rebound_properties.txt"}),
    "R18_chung05_loop": (CH + "test05", "in.oblique_impact_on_wall", [HARD, HIST] + p45("vz[1]/5.0"),
                         {"G": "5", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/hertz_rebound_properties.txt"}),
    "R19_thornton_loop": (PFM + "tests/contact_models/thornton", "in.oblique_impact_on_wall", [HARD, HIST] + p45("vz[1]/abs(${velz})"),
                          {"G": "5", "PAIR": "type 1 on wall mesh_walls", "REFFILE": "post/hertz_rebound_properties.txt"}),
    # the other PFM decks as published
    "R20_hopper_funnel_asis": (PFM + "hopper_discharge_flow_regimes", "in.CylindricalHopperFunnelFlow", [], {"G": "1", "PAIR": "types 1 1"}),
    "R21_hopper_mass_asis": (PFM + "hopper_discharge_flow_regimes", "in.CylindricalHopperMassFlow", [], {"G": "1", "PAIR": "types 1 1"}),
    "R22_brazilnut_asis": (PFM + "segregation/brazil_nut_effect/showcase", "in.brazilNut", [], {"G": "1", "PAIR": "types 1 1"}),
    "R23_epsd_tc0_asis": (PFM + "epsd_rollFric/tc0_inclindedWall", "in.epsd_tc0_inclinedWall", [], {"G": "1"}),
    "R24_epsd_tc1_asis": (PFM + "epsd_rollFric/tc1", "in.epsd_tc1", [], {"G": "1"}),
    "R25_epsd_tc2_asis": (PFM + "epsd_rollFric/tc2", "in.epsd_tc2", [], {"G": "1"}),
    "R26_repose_asis": (PFM + "epsd_rollFric/tc3_AngleOfRepose", "in.repose", [], {"G": "1"}),
    "R27_exclude_asis": (PFM + "exclude_neighs", "in.exclude", [], {"G": "1"}),
    "R28_settle_asis": (PFM + "loadbalancing_slow_gran_flow", "in.settle", [], {"G": "1"}),
    "R29_speedcontrol_asis": (PFM + "speedControl", "in.speedControl", [], {"G": "1"}),
    "R30_scale_asis": (PFM + "scale_diameter", "in.scale", [], {"G": "1"}),
    "R31_servowall_asis": (PFM + "servoWall_1", "in.servoWall", [], {"G": "1"}),
    "R32_stressbox_asis": (PFM + "Stress_box", "in.stressbox", [], {"G": "1", "PAIR": "types 1 1"}),
    # seeds made prime (and runs shortened) so the public engine runs them
    "R33_hopper_funnel_primes": (PFM + "hopper_discharge_flow_regimes", "in.CylindricalHopperFunnelFlow", [primes, shorten(1000)],
                                 {"G": "1", "PAIR": "types 1 1"}),
    "R34_brazilnut_primes": (PFM + "segregation/brazil_nut_effect/showcase", "in.brazilNut", [primes, shorten(1000)],
                             {"G": "1", "PAIR": "types 1 1"}),
    "R35_stressbox_primes": (PFM + "Stress_box", "in.stressbox", [primes, shorten(10)], {"G": "1", "PAIR": "types 1 1"}),
    "R36_exclude_primes": (PFM + "exclude_neighs", "in.exclude", [primes, shorten(100)], {"G": "1", "PAIR": "types 1 1"}),
}

# reduced to a measurable pair: the deck's own lines up to its pair_coeff (materials, pair style, step), then two of
# its spheres approaching at 1 m/s along x, far from every wall (the deck's later lines are not used)
PAIRTAIL = ("create_atoms 1 single {x1} 0 {z} units box\ncreate_atoms 1 single {x2} 0 {z} units box\n"
            "set atom 1 diameter {d1} density {r1}\nset atom 2 diameter {d2} density {r2}\ngroup p1 id 1\ngroup p2 id 2\n"
            "velocity p1 set {v1} 0 0\nvelocity p2 set {v2} 0 0\nfix integr all nve/sphere\nrun {n}\n")
RED = {
    "R37_hopper_pair_reduced": (PFM + "hopper_discharge_flow_regimes", "in.CylindricalHopperFunnelFlow", "timestep",
                                dict(x1=-0.00501, x2=0.00501, z=-0.2, d1=0.01, d2=0.01, r1=2505, r2=2505, v1=0.5, v2=-0.5, n=2000)),
    "R38_brazil_pair_reduced": (PFM + "segregation/brazil_nut_effect/showcase", "in.brazilNut", "timestep",
                                dict(x1=-0.00576, x2=0.00576, z=0.1, d1=0.015, d2=0.008, r1=1500, r2=2500, v1=0.4015, v2=-0.5985, n=400)),
    "R39_stressbox_pair_reduced": (PFM + "Stress_box", "in.stressbox", "timestep",
                                   dict(x1=-0.0201, x2=0.0201, z=0.5, d1=0.04, d2=0.04, r1=3000, r2=3000, v1=0.5, v2=-0.5, n=300)),
    "R40_exclude_pair_reduced": (PFM + "exclude_neighs", "in.exclude", "timestep",
                                 dict(x1=-0.00201, x2=0.00201, z=0.1, d1=0.004, d2=0.004, r1=2500, r2=2500, v1=0.5, v2=-0.5, n=2000)),
}


def files(mirror, folder):
    out = subprocess.run(["git", "-C", mirror, "ls-tree", "-r", "--name-only", COMMIT, folder], capture_output=True, text=True).stdout.split()
    return [f for f in out if "/post/" not in f]


def show(mirror, path):
    return subprocess.run(["git", "-C", mirror, "show", f"{COMMIT}:{path}"], capture_output=True).stdout


def write(mirror):
    for name, (folder, deck, edits, meta) in R.items():
        d = os.path.join(HERE, "decks", name)
        os.makedirs(os.path.join(d, "post"), exist_ok=True)
        for f in files(mirror, folder):
            rel = f[len(folder) + 1:]
            if rel.endswith((".m", ".pdf", "run.config", "postscript", "script")) or (rel.startswith("in.") and rel != deck):
                continue
            os.makedirs(os.path.dirname(os.path.join(d, rel)) or d, exist_ok=True)
            open(os.path.join(d, rel), "wb").write(show(mirror, f))
        text = open(os.path.join(d, deck), encoding="latin-1").read()
        for e in edits:
            text = e(text) if callable(e) else text.replace(*e)
        open(os.path.join(d, deck), "w", encoding="latin-1").write(text)
        meta = dict(meta, DECK=deck, LIGGGHTS="", NP="1")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + ("" if v.endswith("\n") else "\n"))
    for name, (folder, deck, upto, kw) in RED.items():
        d = os.path.join(HERE, "decks", name)
        os.makedirs(os.path.join(d, "post"), exist_ok=True)
        src = show(mirror, f"{folder}/{deck}").decode("latin-1")
        lines = src.splitlines(keepends=True)
        k = next(i for i, l in enumerate(lines) if l.split()[:1] == [upto])
        head = "".join(lines[:k + 1])
        open(os.path.join(d, "in.deck"), "w", encoding="latin-1").write(head + "neigh_modify delay 0\n" + PAIRTAIL.format(**kw))
        meta = {"DECK": "in.deck", "LIGGGHTS": "", "NP": "1", "G": "1", "PAIR": "types 1 1",
                "REF": 'variable P45 equal vx[2]-vx[1]\nprint "PUB45 eps ${P45}"\n'}
        for k_, v in meta.items():
            open(os.path.join(d, k_), "w").write(v + ("" if v.endswith("\n") else "\n"))
    print(len(R) + len(RED), "public deck folders")


if __name__ == "__main__":
    write(sys.argv[1])
