"""Field round 46 ("hidden decks", main 6e1fa3ef): write decks/NAME/ (in.deck and the files it reads) for the referee
(round 37's live37.py: each deck AS WRITTEN, its live pair's eps printed after its last line) and then the audit.
Self-contained (round 45's base lines written out here). Families:
- G: LAMMPS `pair_style granular` sub-models combined (dmt/jkr at cohesion 0 with tsuji/coeff_restitution/viscoelastic
  damping, rolling/twisting on a head-on pair, limit_damping, hooke with viscoelastic damping, per-pair `cutoff`,
  mixing of per-type lines, the older gran/* styles with limit_damping, pair_coeff order);
- T: types and sizes: type labels in set/group/velocity/create_atoms, `set type` ranges, a `set type` changing the
  pair's types, create_atoms random and lattice units (a size set later), atom_style sphere 0, hybrid sphere + others;
- W: walls: fix wall/gran `contacts`, `temperature`/heat, limit_damping, dmt, rolling, a wall model unlike the pair's,
  lattice-unit regions under hertz, a wall group by label, bounds `zplane 0 0.09`, `wiggle`/`shear`;
- I: insertion: fix pour diam poly / range / one and `mol` (one-atom and two-atom templates), fix deposit;
- D: read_data: `Pair Coeffs`, `PairIJ Coeffs`, nocoeff, Atom Type Labels, hybrid sphere column order, bpm/sphere,
  Velocities, add append;
- V: include chains with variables, `include ${f}`, `next` over a file variable, index given again inside an include,
  getenv beside shell putenv, `fix adapt` on the pair's coefficients at the start;
- L: LIGGGHTS generated: two coefficientRestitution fixes, rolling friction epsd/epsd2/cdt on a head-on pair,
  hooke/stiffness, a wall with its own model, read_data granular, include chains, coarse step;
- H: harmless controls.
The pair meets at step 100 and a contact lasts about 586 steps (hooke kn 2000: 0.413435; the floor 0.361743).
usage: python make_decks46.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
DECKS = {}

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
HZM = "hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3 damping coeff_restitution"


def RB(nt=2, coeff="pair_coeff * * " + HK + "\n", style="pair_style granular\n", head="", atom="atom_style sphere 1\n",
       box="region box block 0 0.04 0 0.04 0 0.1 units box\n", mid=""):
    return (head + "units si\n" + atom + "boundary p p f\ncomm_modify vel yes\n" + box + f"create_box {nt} box\n" + mid + style + coeff +
            "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")


def IN(t1=1, t2=2, d1=0.004, d2=0.006, r1=2500, r2=2500, v1=0.7714285714, v2=-0.2285714286):
    """The live pair: centres 5.1 mm apart (0.1 mm gap for 4 + 6 mm), approach 1 m/s along x."""
    return (f"create_atoms {t1} single 0.017950 0.02 0.05\ncreate_atoms {t2} single 0.023050 0.02 0.05\n"
            f"set atom 1 diameter {d1} density {r1}\nset atom 2 diameter {d2} density {r2}\n"
            f"group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set {v1} 0 0 units box\nvelocity lv2 set {v2} 0 0 units box\n")


H0 = 0.1e-3
VZ = math.sqrt(1 - 2 * 9.81 * H0)
FLOORP = (f"create_atoms 1 single 0.02 0.02 {0.002 + H0:.6f}\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
          f"velocity lv1 set 0 0 {-VZ:.10f} units box\n")
FLOOR = {"PAIR": "type 1 on wall floor"}


def L(name, desc, body="run 3000\n", pre=None, pair=None, live="last run", data=None, **meta):
    pre = RB() if pre is None else pre
    pair = IN() if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


# ---------------------------------------------------------------- LIGGGHTS base
def LBASE(e="0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", model="model hertz tangential history", extra="", wall=True, dt="1e-6"):
    return ("atom_style granular\natom_modify map array\nboundary p f f\nnewton off\ncommunicate single vel yes\nunits si\n"
            "region reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box\ncreate_box 3 reg\nneighbor 0.002 bin\nneigh_modify delay 0\n"
            "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
            "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
            f"fix m3 all property/global coefficientRestitution peratomtypepair 3 {e}\n" + extra +
            f"pair_style gran {model}\npair_coeff * *\n" +
            (f"fix wprim all wall/gran {model} primitive type 3 zplane 0.0\n" if wall else "") +
            f"timestep {dt}\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n")


LIN = ("create_atoms 1 single -0.002550 0 0.1 units box\ncreate_atoms 2 single 0.002550 0 0.1 units box\n"
       "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
       "velocity lv1 set 0.7714285714 0 0\nvelocity lv2 set -0.2285714286 0 0\n")
LFLOOR = (f"create_atoms 1 single 0.0 0 {0.002 + H0:.6f} units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
          f"velocity lv1 set 0 0 {-VZ:.10f}\n")


def LG(name, desc, body="run 3000\n", pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# LIGGGHTS: " + desc + "\n" + pre + pair + body, live, data or {}, meta)


PC = lambda spec, law: f"pair_coeff {spec} {law}\n"
GR = lambda coeff: RB(coeff=coeff)

# ================================================================ G: granular sub-models (LAMMPS)
L("G01_dmt_c0_tsuji", "dmt 1e6 0.5 0.3 0.0 (cohesion 0) damping tsuji", pre=GR(PC("* *", "dmt 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping tsuji")))
L("G02_jkr_c0_mass_velocity", "jkr 1e6 30 0.3 0.0 damping mass_velocity", pre=GR(PC("* *", "jkr 1e6 30 0.3 0.0 tangential linear_nohistory 1 0.3 damping mass_velocity")))
L("G03_dmt_c0_viscoelastic_limit", "dmt cohesion 0, damping viscoelastic 0.5, limit_damping",
  pre=GR(PC("* *", "dmt 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping viscoelastic limit_damping")))
L("G04_hertzmat_roll_twist_headon", "hertz/material coeff_restitution + rolling sds 500 200 0.5 + twisting marshall (head-on: no rolling)",
  pre=GR(PC("* *", "hertz/material 1e6 0.5 0.3 tangential mindlin NULL 1.0 0.3 rolling sds 500 200 0.5 twisting marshall damping coeff_restitution")))
L("G05_hooke_viscoelastic", "hooke 2000 0.5 with damping viscoelastic (reads the contact radius)",
  pre=GR(PC("* *", "hooke 2000 0.5 tangential linear_nohistory 1 0.3 damping viscoelastic")))
L("G06_hooke_mv_limit_damping", "hooke 2000 3000 mass_velocity limit_damping (end rule)", pre=GR(PC("* *", HK + " limit_damping")))
L("G07_hertz_velocity", "hertz 1e5 0.02 damping velocity (hertz not material)", pre=GR(PC("* *", "hertz 1e5 0.02 tangential linear_nohistory 1 0.3 damping velocity")))
L("G08_hertzmat_tsuji_limit", "hertz/material e 0.5 damping tsuji limit_damping", pre=GR(PC("* *", HZM.replace("coeff_restitution", "tsuji") + " limit_damping")))
L("G09_jkr_c0_viscoelastic", "jkr cohesion 0 damping viscoelastic", pre=GR(PC("* *", "jkr 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping viscoelastic")))
L("G10_dmt_cohesion", "dmt cohesion 0.05 viscoelastic (not mapped: refusal of the pair allowed)", pre=GR(PC("* *", "dmt 1e6 0.5 0.3 0.05 tangential linear_nohistory 1 0.3 damping viscoelastic")))
L("G11_cutoff_pair_below_contact", "pair_style granular; pair_coeff * * hooke ... cutoff 0.003 (below the 5 mm contact distance of the pair)",
  pre=GR(PC("* *", HK + " cutoff 0.003")))
L("G12_cutoff_pair_12_only", "pair_coeff * * hooke; pair_coeff 1 2 hooke 5000 ... cutoff 0.008 (above)", pre=GR(PC("* *", HK) + PC("1 2", HK.replace("2000", "5000") + " cutoff 0.008")))
L("G13_global_cutoff_small", "pair_style granular 0.002 (global cutoff below the contact distance)", pre=RB(style="pair_style granular 0.002\n"))
L("G14_mix_types_hooke_kn", "pair_coeff 1 1 hooke 1000 ..., 2 2 hooke 4000 ... (1 2 mixed: kn 2000)", pre=GR(PC("1 1", HK.replace("2000", "1000")) + PC("2 2", HK.replace("2000", "4000"))))
L("G15_mix_limit_damping_one_side", "1 1 hooke limit_damping, 2 2 hooke without (mixed 1 2 takes limit_damping?)",
  pre=GR(PC("1 1", HK + " limit_damping") + PC("2 2", HK)))
L("G16_mix_coeffrest_e", "hertz/material 1 1 e 0.3, 2 2 e 0.8 (1 2 mixed)", pre=GR(PC("1 1", HZM.replace("0.5 0.3", "0.3 0.3")) + PC("2 2", HZM.replace("0.5 0.3", "0.8 0.3"))))
L("G17_star_after_12", "pair_coeff 1 2 hooke 5000; then pair_coeff * * hooke 2000 (the later * * covers 1 2: 2000)", pre=GR(PC("1 2", HK.replace("2000", "5000")) + PC("* *", HK)))
L("G18_two_models_by_pair", "pair_coeff * * hooke; pair_coeff 1 2 hertz/material coeff_restitution 0.7", pre=GR(PC("* *", HK) + PC("1 2", HZM.replace("0.5 0.3", "0.7 0.3"))))
L("G19_gran_hooke_history_limit", "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1 limit_damping", pre=RB(style="pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1 limit_damping\n", coeff="pair_coeff * *\n"))
L("G20_gran_hertz_history_gamma", "pair_style gran/hertz/history 2e5 NULL 5e3 NULL 0.3 0", pre=RB(style="pair_style gran/hertz/history 2e5 NULL 5e3 NULL 0.3 0\n", coeff="pair_coeff * *\n"))
L("G21_gran_hooke_dampflag0", "pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0", pre=RB(style="pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n"))
L("G22_hybrid_two_granular", "pair_style hybrid granular granular: pair_coeff * * granular 1 hooke 2000; 1 2 granular 2 hooke 5000",
  pre=RB(style="pair_style hybrid granular granular\n", coeff="pair_coeff * * granular 1 " + HK + "\npair_coeff 1 2 granular 2 " + HK.replace("2000", "5000") + "\n"))
L("G23_hybrid_gran_hooke_granular", "pair_style hybrid gran/hooke 2000 NULL 3000 NULL 0.3 0 granular: 1 2 by granular hooke 5000",
  pre=RB(style="pair_style hybrid gran/hooke 2000 NULL 3000 NULL 0.3 0 granular\n", coeff="pair_coeff * * gran/hooke\npair_coeff 1 2 granular " + HK.replace("2000", "5000") + "\n"))
L("G24_hertzmat_mass_velocity", "hertz/material 1e6 3000 0.3 damping mass_velocity", pre=GR(PC("* *", "hertz/material 1e6 3000 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity")))
L("G25_tangential_mindlin_rescale", "hertz/material e 0.5 coeff_restitution, tangential mindlin_rescale/force NULL 1 0.3 (head-on)",
  pre=GR(PC("* *", "hertz/material 1e6 0.5 0.3 tangential mindlin_rescale/force NULL 1.0 0.3 damping coeff_restitution")))
L("G26_rolling_sds_floor", "hertz/material floor wall with rolling sds on the pair and the wall (a drop: head-on)",
  pre=RB(coeff=PC("* *", HZM + " rolling sds 500 200 0.5")).replace("fix integ", "fix floor all wall/gran granular " + HZM + " rolling sds 500 200 0.5 zplane 0 NULL\nfix integ"),
  pair=FLOORP, **FLOOR)
L("G27_coeffrest_e1_limit", "hooke coeff_restitution e 1.0 limit_damping", pre=GR(PC("* *", "hooke 2000 1.0 tangential linear_nohistory 1 0.3 damping coeff_restitution limit_damping")))
L("G28_hooke_tsuji", "hooke 2000 0.5 damping tsuji", pre=GR(PC("* *", "hooke 2000 0.5 tangential linear_nohistory 1 0.3 damping tsuji")))
L("G29_pair_coeff_repeat_keyword", "pair_coeff with damping given twice (mass_velocity then coeff_restitution? the last one)",
  pre=GR(PC("* *", "hooke 2000 0.5 damping mass_velocity tangential linear_nohistory 1 0.3 damping coeff_restitution")))
L("G30_heat_keyword_pair", "hooke with `heat area 1.0` (heat only) and fix heat/flow", pre=RB(mid="fix prop all property/atom temperature heatflow\n", coeff=PC("* *", HK + " heat area 1.0")),
  pair=IN() + "set group all temperature 300\nfix hf all heat/flow constant 1.0\n")

# ================================================================ T: types, labels, sizes
LB = lambda: RB(mid="labelmap atom 1 sm 2 bg\n")
L("T01_label_set_type", "labelmap atom 1 sm 2 bg; set type bg diameter 0.0058 (after set atom 2 0.006)", pre=LB(), pair=IN() + "set type bg diameter 0.0058\n")
L("T02_label_group_velocity", "group gs type sm; velocity gs set 0.7714 (the pair's speeds by label groups)", pre=LB(),
  pair=IN().replace("velocity lv1 set 0.7714285714 0 0 units box\n", "group gs type sm\nvelocity gs set 0.7714285714 0 0 units box\n"))
L("T03_label_create_atoms_pair_coeff", "create_atoms sm/bg by label, pair_coeff sm bg hooke 5000", pre=LB() + PC("sm bg", HK.replace("2000", "5000")),
  pair=IN().replace("create_atoms 1 single", "create_atoms sm single").replace("create_atoms 2 single", "create_atoms bg single"))
L("T04_set_type_change_pair", "create type 1 and 2; set atom 2 type 1 (the pair becomes 1 1); pair_coeff 1 1 hooke 5000", pre=GR(PC("* *", HK) + PC("1 1", HK.replace("2000", "5000"))),
  pair=IN() + "set atom 2 type 1\n", PAIR="types 1 1")
L("T05_set_type_range_diameter", "set type 1*2 diameter 0.004; then set atom 2 diameter 0.006 density 2500 (order)", pair=IN().replace("set atom 1 diameter", "set type 1*2 diameter 0.004 density 2500\nset atom 1 diameter"))
L("T06_set_type_after_atom", "set atom 2 diameter 0.006; then set type 2 diameter 0.0058 density 4000 (the later wins)",
  pair=IN().replace("group lv1", "set type 2 diameter 0.0058 density 4000\ngroup lv1"))
L("T07_create_atoms_random_sized_later", "create_atoms 1 random 3 4767 far region (type 1, far) then set type 1 diameter 0.003; the pair after (set atom keeps 4 mm)",
  pair="region far block 0.001 0.039 0.001 0.039 0.08 0.095 units box\ncreate_atoms 1 random 3 4767 far overlap 0.004 maxtry 200\nset type 1 diameter 0.003 density 2500\n"
  + IN().replace("create_atoms 1 single", "create_atoms 1 single").replace("set atom 1 ", "set atom 4 ").replace("set atom 2 ", "set atom 5 ").replace("group lv1 id 1", "group lv1 id 4").replace("group lv2 id 2", "group lv2 id 5"))
L("T08_create_atoms_random_size_after_pair", "pair first; then create_atoms 1 random 3 (far) and set type 1 diameter 0.003 (the live type 1 sphere shrinks too)",
  pair=IN() + "region far block 0.001 0.039 0.001 0.039 0.08 0.095 units box\ncreate_atoms 1 random 3 4767 far overlap 0.004 maxtry 200\nset type 1 diameter 0.003 density 2500\n")
LAT = ("units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nlattice sc 0.01\nregion box block 0 4 0 4 0 10\ncreate_box 2 box\n"
       "pair_style granular\npair_coeff * * " + HK + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")
L("T09_lattice_units_pair", "lattice sc 0.01; box and create_atoms single in lattice units; velocity in lattice units (77.14 = 0.7714 m/s)", pre=LAT,
  pair="create_atoms 1 single 1.795 2 5\ncreate_atoms 2 single 2.305 2 5\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
  "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 77.14285714 0 0\nvelocity lv2 set -22.85714286 0 0\n")
L("T10_lattice_hertz_velocity_lattice", "T09 under hertz/material (speed matters): velocity in lattice units", pre=LAT.replace("pair_coeff * * " + HK, "pair_coeff * * " + HZM),
  pair="create_atoms 1 single 1.795 2 5\ncreate_atoms 2 single 2.305 2 5\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
  "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 77.14285714 0 0\nvelocity lv2 set -22.85714286 0 0\n")
L("T11_create_atoms_region_lattice_sized_later", "lattice sc 0.01; the pair by single (lattice units); then create_atoms 1 region row (a far row of type 1) and set type 1 diameter 0.004",
  pre=LAT, pair="create_atoms 1 single 1.795 2 5\ncreate_atoms 2 single 2.305 2 5\nset atom 1 diameter 0.003 density 2500\nset atom 2 diameter 0.006 density 2500\n"
  "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n"
  "region row block 0 4 0 1 8 9\ncreate_atoms 1 region row\nset type 1 diameter 0.004 density 2500\n")
L("T12_atom_style_sphere0", "atom_style sphere 0 (radius constant); set diameter before the run", pre=RB(atom="atom_style sphere 0\n"))
L("T13_hybrid_sphere_dipole", "atom_style hybrid sphere 1 dipole (dipoles 0)", pre=RB(atom="atom_style hybrid sphere 1 dipole\n"))
L("T14_hybrid_dipole_sphere_order", "atom_style hybrid dipole sphere 1", pre=RB(atom="atom_style hybrid dipole sphere 1\n"))
L("T15_bpm_sphere", "atom_style bpm/sphere with pair granular", pre=RB(atom="atom_style bpm/sphere\n"))
L("T16_label_set_density_mass", "labels: set type bg density 5000 (after set atom 2 density 2500)", pre=LB(), pair=IN() + "set type bg density 5000\n")
L("T17_label_range_type_star", "5 types with labels; pair_coeff * bg hooke 5000 (1 2 covered: 5000)", pre=RB(nt=5, mid="labelmap atom 1 sm 2 bg 3 c 4 d 5 e\n") + PC("* bg", HK.replace("2000", "5000")))
L("T18_set_type_fraction_far", "5 types; set type 1 type/fraction 3 0.5 4767 (the live type 1 sphere may become 3; pair_coeff 3 2 5000)",
  pre=RB(nt=3) + PC("3 2", HK.replace("2000", "5000")), pair=IN() + "set type 1 type/fraction 3 0.5 4767\n", )
L("T19_group_type_velocity_range", "velocity by group type 1*2 then set lv2 again", pair=IN().replace("velocity lv1", "group both type 1 2\nvelocity both set 5 0 0 units box\nvelocity lv1"))
L("T20_set_mass_after_diameter", "set atom 2 diameter 0.006 density 2500; set atom 2 mass 1.1310e-3 (density x4)", pair=IN() + "set atom 2 mass 1.1310e-3\n")

# ================================================================ W: walls
WALLB = lambda wl, coeff="pair_coeff * * " + HK + "\n": RB(coeff=coeff).replace("fix integ", wl + "fix integ")
L("W01_wall_contacts_keyword", "fix floor wall/gran granular hooke ... zplane 0 NULL contacts", pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL contacts\n"), pair=FLOORP, **FLOOR)
L("W02_wall_limit_damping", "wall/gran granular hooke ... limit_damping zplane", pre=WALLB("fix floor all wall/gran granular " + HK + " limit_damping zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("W03_wall_dmt_c0", "wall/gran granular dmt cohesion 0 mass_velocity 30", pre=WALLB("fix floor all wall/gran granular dmt 1e6 30 0.3 0.0 tangential linear_nohistory 1 0.3 damping mass_velocity zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("W04_wall_own_model_hertz", "pair hooke, floor wall hertz/material e 0.7", pre=WALLB("fix floor all wall/gran granular " + HZM.replace("0.5 0.3", "0.7 0.3") + " zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("W05_wall_zplane_both", "floor wall zplane 0 0.09 (both bounds)", pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 0.09\n"), pair=FLOORP, **FLOOR)
L("W06_wall_shear", "floor wall with shear x 0.5 (tangential motion; head-on drop)", pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL shear x 0.5\n"), pair=FLOORP, **FLOOR)
L("W07_wall_wiggle", "floor wall wiggle z 1e-4 0.01 (moves)", pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL wiggle z 1e-4 0.01\n"), pair=FLOORP, **FLOOR)
L("W08_wall_group_label", "labels; group gs type sm; wall/gran on gs", pre=RB(mid="labelmap atom 1 sm 2 bg\n").replace("fix integ", "group gs type sm\nfix floor gs wall/gran granular " + HK.replace("2000", "5000") + " zplane 0 NULL\nfix integ"),
  pair=FLOORP, **FLOOR)
L("W09_wall_group_type_after_atoms", "wall on group gw type 1 defined after the sphere (kn 5000)", pre=RB(), pair=FLOORP + "group gw type 1\nfix floor gw wall/gran granular " + HK.replace("2000", "5000") + " zplane 0 NULL\n", **FLOOR)
L("W10_wall_old_hooke", "pair hooke granular; floor fix wall/gran hooke 4000 NULL 3000 NULL 0.3 0 (older model)", pre=WALLB("fix floor all wall/gran hooke 4000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("W11_wall_old_hertz_history_limit", "floor fix wall/gran hertz/history 2e5 NULL 5e3 NULL 0.3 0 limit_damping", pre=WALLB("fix floor all wall/gran hertz/history 2e5 NULL 5e3 NULL 0.3 0 limit_damping zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("W12_region_wall_lattice_cyl_hertz", "lattice sc 0.01; region cylinder z 2 2 1 0 10 (lattice units: radius 1 cm) wall/gran/region hertz/material; lv1 +x onto its side",
  pre=LAT.replace("pair_coeff * * " + HK, "pair_coeff * * " + HZM).replace("fix integ", "region cyl cylinder z 2 2 1 0 10 side in\nfix wc all wall/gran/region granular " + HZM + " region cyl\nfix integ"),
  pair="create_atoms 1 single 0.0279 0.02 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n",
  PAIR="type 1 on wall wc", WALLX="")
L("W13_region_wall_lattice_spacing_cyl", "lattice sc 0.02 (spacing 2 cm); region cylinder z 1 1 0.5 0 5 (radius 1 cm) hertz/material; lv1 +x",
  pre=LAT.replace("lattice sc 0.01", "lattice sc 0.02").replace("region box block 0 4 0 4 0 10", "region box block 0 2 0 2 0 5").replace("pair_coeff * * " + HK, "pair_coeff * * " + HZM)
  .replace("fix integ", "region cyl cylinder z 1 1 0.5 0 5 side in\nfix wc all wall/gran/region granular " + HZM + " region cyl\nfix integ"),
  pair="create_atoms 1 single 0.0279 0.02 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n",
  PAIR="type 1 on wall wc", WALLX="")
L("W14_region_sphere_out_hertz", "wall/gran/region hertz/material on a sphere region side out (R 5 mm) beside lv1 (+x)",
  pre=RB(coeff=PC("* *", HZM)).replace("fix integ", "region ball sphere 0.035 0.02 0.05 0.005 side out units box\nfix wc all wall/gran/region granular " + HZM + " region ball\nfix integ"),
  pair="create_atoms 1 single 0.0279 0.02 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n",
  PAIR="type 1 on wall wc", WALLX="")
L("W15_wall_before_box_atoms_all", "wall/gran on all given before create_atoms; hertz/material floor", pre=WALLB("fix floor all wall/gran granular " + HZM + " zplane 0 NULL\n", coeff=PC("* *", HZM)), pair=FLOORP, **FLOOR)
L("W16_wall_temperature_heat", "wall/gran granular hooke ... heat area 1.0 zplane 0 NULL temperature 300 (heat only)",
  pre=RB(atom="atom_style sphere 1\n", coeff=PC("* *", HK + " heat area 1.0")).replace("fix integ", "fix prop all property/atom temperature heatflow\nfix floor all wall/gran granular " + HK + " heat area 1.0 zplane 0 NULL temperature 300\nfix integ"),
  pair=FLOORP + "set atom 1 temperature 300\nfix hf all heat/flow constant 1.0\n", **FLOOR)
L("W17_wall_region_block_face_kn", "wall/gran/region hooke 5000 on a block region (floor face z 0)", pre=RB().replace("fix integ", "region flr block -1 1 -1 1 -1 0 side out units box\nfix floor all wall/gran/region granular " + HK.replace("2000", "5000") + " region flr\nfix integ"),
  pair=FLOORP, **FLOOR)
L("W18_wall_zcyl_hertz_limit", "hertz/material wall zcylinder 0.01 with limit_damping; lv1 +x inside (boundary f f p, box about the axis)", pre=RB(coeff=PC("* *", HZM), box="region box block -0.02 0.02 -0.02 0.02 0 0.1 units box\n").replace("boundary p p f", "boundary f f f").replace("fix integ", "fix wc all wall/gran granular " + HZM + " limit_damping zcylinder 0.01\nfix integ"),
  pair="create_atoms 1 single 0.0079 0.0 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n", PAIR="type 1 on wall wc", WALLX="")
L("W19_two_walls_same_plane_models", "floor wall hooke 2000 and a second wall/gran region plane at z 0 hooke 4000 (two walls at one surface)",
  pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion pl plane 0 0 0 0 0 1 units box\nfix w2 all wall/gran/region granular " + HK.replace("2000", "4000") + " region pl\n"), pair=FLOORP, **FLOOR)
L("W20_wall_xplane_lattice_units", "lattice sc 0.01; fix wall/gran ... xplane 3.5 NULL (LAMMPS: box units always? lv1 +x)",
  pre=LAT.replace("boundary p p f", "boundary f p f").replace("fix integ", "fix wx all wall/gran granular " + HK + " xplane NULL 0.035\nfix integ"),
  pair="create_atoms 1 single 0.0329 0.02 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n", PAIR="type 1 on wall wx", WALLX="")

# ================================================================ I: insertion
HZB = RB(coeff=PC("* *", HZM))
L("I01_pour_diam_poly_hooke", "fix pour type 1 diam poly 2 0.003 0.4 0.005 0.6 far; the pair (hooke: mass-dependent)",
  pair=IN() + "region pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 4 1 4767 region pr diam poly 2 0.003 0.4 0.005 0.6 dens 2500 2500\n")
L("I02_pour_mol_one_atom", "fix pour of a one-atom molecule template (Diameters 0.008) of type 2, far; the pair",
  pair=IN() + "molecule m1 m1.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 2 0 4767 region pr mol m1\n",
  data={"m1.mol": "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.008\n\nMasses\n\n1 2.68e-4\n"})
L("I03_pour_mol_two_atom", "fix pour of a two-atom template (refusal allowed: not single spheres)",
  pair=IN() + "molecule m2 m2.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 2 0 4767 region pr mol m2\n",
  data={"m2.mol": "# two spheres\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0.004 0 0\n\nTypes\n\n1 1\n2 1\n\nDiameters\n\n1 0.004\n2 0.004\n\nMasses\n\n1 8.38e-5\n2 8.38e-5\n"})
L("I04_pour_diam_one_type1_hertz", "hertz/material; fix pour type 1 diam one 0.004 (same as the pair's)", pre=HZB,
  pair=IN() + "region pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 3 1 4767 region pr diam one 0.004 dens 2500 2500\n")
L("I05_deposit_type2", "fix deposit 3 2 100 4767 region (type 2 atoms with the default diameter 1!)", pre=RB(),
  pair=IN() + "region dp block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix dp all deposit 3 2 500 4767 region dp near 0.01\n")
L("I06_pour_range_then_set", "pour of type 2 diam range 0.004 0.008 after the pair; then set type 2 diameter 0.006 (before the run: no poured atom yet)",
  pair=IN() + "region pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 3 2 4767 region pr diam range 0.004 0.008 dens 2500 2500\nset type 2 diameter 0.006\n")
L("I07_pour_poly_density_range_hertz", "hertz/material; fix pour of type 2, diam poly 2 0.006 0.5 0.009 0.5 density 2000 3000", pre=HZB,
  pair=IN() + "region pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 4 2 4767 region pr diam poly 2 0.006 0.5 0.009 0.5 dens 2000 3000\n")
L("I08_create_atoms_random_type2_default_size", "create_atoms 2 random 2 far (diameter 1 m default? no: set later none) then the pair",
  pair="region far block 0.001 0.039 0.001 0.039 0.08 0.095 units box\ncreate_atoms 2 random 2 4767 far\nset group all diameter 0.006 density 2500\n" +
  IN().replace("set atom 1 ", "set atom 3 ").replace("set atom 2 ", "set atom 4 ").replace("id 1\n", "id 3\n").replace("id 2\n", "id 4\n"))
L("I09_pour_mol_one_atom_hertz", "hertz/material; pour of a one-atom template type 1 with Diameters 0.003", pre=HZB,
  pair=IN() + "molecule m1 m1.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 2 0 4767 region pr mol m1\n",
  data={"m1.mol": "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.003\n\nMasses\n\n1 3.534e-5\n"})

# ================================================================ D: read_data
def DATA(atoms, extra="", header="", ntypes=2, velo=True, style="sphere"):
    v = "\nVelocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n" if velo else ""
    return (f"# data\n\n2 atoms\n{ntypes} atom types\n{header}\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n" + extra +
            f"\nAtoms # {style}\n\n" + atoms + v)


AS = "1 1 0.004 2500 0.017950 0.02 0.05\n2 2 0.006 2500 0.023050 0.02 0.05\n"
RD = lambda data_line, style="pair_style granular\n", atom="atom_style sphere 1\n", after="": ("units si\n" + atom + "boundary p p f\ncomm_modify vel yes\n" + style + data_line + after +
                                     "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")
RDP = "group lv1 id 1\ngroup lv2 id 2\n"
L("D01_pair_coeffs_section", "read_data with Pair Coeffs (1 hooke 1000, 2 hooke 4000: 1 2 mixed 2000)", pre=RD("read_data d.data\n"), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPair Coeffs # granular\n\n1 " + HK.replace("2000", "1000") + "\n2 " + HK.replace("2000", "4000") + "\n")})
L("D02_pairij_coeffs_section", "read_data with PairIJ Coeffs (1 1, 1 2 hooke 5000, 2 2)", pre=RD("read_data d.data\n"), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + HK.replace("2000", "5000") + "\n2 2 " + HK + "\n")})
L("D03_pair_coeffs_then_deck_override", "Pair Coeffs in the data file (kn 5000), then pair_coeff 1 2 hooke 2000 in the deck", pre=RD("read_data d.data\n", after=PC("1 2", HK)), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPair Coeffs # granular\n\n1 " + HK.replace("2000", "5000") + "\n2 " + HK.replace("2000", "5000") + "\n")})
L("D04_nocoeff", "read_data d.data nocoeff (its Pair Coeffs kn 5000 skipped); pair_coeff * * hooke 2000 in the deck", pre=RD("read_data d.data nocoeff\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPair Coeffs # granular\n\n1 " + HK.replace("2000", "5000") + "\n2 " + HK.replace("2000", "5000") + "\n")})
L("D05_type_labels_section", "Atom Type Labels section (1 sm 2 bg); pair_coeff sm bg hooke 5000", pre=RD("read_data d.data\n", after=PC("* *", HK) + PC("sm bg", HK.replace("2000", "5000"))), pair=RDP,
  data={"d.data": DATA(AS, extra="\nAtom Type Labels\n\n1 sm\n2 bg\n")})
L("D06_hybrid_sphere_dipole_columns", "atom_style hybrid sphere 1 dipole; Atoms: id type x y z diameter density q mux muy muz", pre=RD("read_data d.data\n", atom="atom_style hybrid sphere 1 dipole\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA("1 1 0.017950 0.02 0.05 0.004 2500 0 0 0 0\n2 2 0.023050 0.02 0.05 0.006 2500 0 0 0 0\n", style="hybrid sphere dipole")
        .replace("Velocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n", "Velocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n")})
L("D07_hybrid_dipole_sphere_columns", "atom_style hybrid dipole sphere 1; Atoms: id type x y z q mux muy muz diameter density", pre=RD("read_data d.data\n", atom="atom_style hybrid dipole sphere 1\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA("1 1 0.017950 0.02 0.05 0 0 0 0 0.004 2500\n2 2 0.023050 0.02 0.05 0 0 0 0 0.006 2500\n", style="hybrid dipole sphere")})
L("D08_bpm_sphere_data", "atom_style bpm/sphere; Atoms: id mol type diameter density x y z", pre=RD("read_data d.data\n", atom="atom_style bpm/sphere\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA("1 1 1 0.004 2500 0.017950 0.02 0.05\n2 2 2 0.006 2500 0.023050 0.02 0.05\n", style="bpm/sphere")})
L("D09_sphere_density_column_big", "atom_style sphere; Atoms with density 8000 for atom 2 (heavier)", pre=RD("read_data d.data\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA(AS.replace("0.006 2500", "0.006 8000"))})
L("D10_read_data_add_append", "read_data a.data (atom 1), read_data b.data add append (atom 2, 8 mm)", pre=RD("read_data a.data\nread_data b.data add append\n", after=PC("* *", HK)), pair=RDP,
  data={"a.data": "# a\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.017950 0.02 0.05\n\nVelocities\n\n1 0.7714285714 0 0 0 0 0\n",
        "b.data": "# b\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.008 2500 0.024050 0.02 0.05\n\nVelocities\n\n1 -0.2285714286 0 0 0 0 0\n"})
L("D11_pair_coeffs_hertz_mixed", "Pair Coeffs hertz/material 1 E 1e6 e 0.3, 2 E 4e6 e 0.8 (1 2 mixed)", pre=RD("read_data d.data\n"), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPair Coeffs # granular\n\n1 " + HZM.replace("0.5 0.3", "0.3 0.3") + "\n2 " + HZM.replace("1e6 0.5 0.3", "4e6 0.8 0.3") + "\n")})
L("D12_data_offset_types", "read_data a.data (types 1 1) then b.data add append offset 1 0 0 0 0 (its type 1 becomes 2)", pre=RD("read_data a.data extra/atom/types 1\nread_data b.data add append offset 1 0 0 0 0\n", after=PC("* *", HK) + PC("1 2", HK.replace("2000", "5000"))), pair=RDP,
  data={"a.data": "# a\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.017950 0.02 0.05\n\nVelocities\n\n1 0.7714285714 0 0 0 0 0\n",
        "b.data": "# b\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.006 2500 0.023050 0.02 0.05\n\nVelocities\n\n1 -0.2285714286 0 0 0 0 0\n"})
L("D13_pair_coeffs_before_pair_style_label_map", "labelmap in the deck, data file Pair Coeffs by type number, then set type bg diameter",
  pre=RD("read_data d.data\nlabelmap atom 1 sm 2 bg\nset type bg diameter 0.0058\n"), pair=RDP,
  data={"d.data": DATA(AS, extra="\nPair Coeffs # granular\n\n1 " + HK + "\n2 " + HK + "\n")})

# ================================================================ V: include / variables / next / adapt
L("V01_include_chain_index", "variable k index 5000; include a.in (variable k index 3000: ignored; include b.in: pair_coeff 1 2 ${k})",
  pre=RB() + "variable k index 5000\ninclude a.in\n", data={"a.in": "variable k index 3000\ninclude b.in\n", "b.in": "pair_coeff 1 2 " + HK.replace("2000", "${k}") + "\n"})
L("V02_include_var_name", "variable f index b.in; include ${f} (b.in: kn 5000)", pre=RB() + "variable f index b.in\ninclude ${f}\n", data={"b.in": PC("1 2", HK.replace("2000", "5000"))})
L("V03_include_var_name_loop", "variable f index p1.in p2.in; label l; include ${f}; next f; jump SELF l (p2 last: kn 5000)",
  pre=RB() + "variable f index p1.in p2.in\nlabel l\ninclude ${f}\nnext f\njump SELF l\n", data={"p1.in": PC("1 2", HK.replace("2000", "3000")), "p2.in": PC("1 2", HK.replace("2000", "5000"))})
L("V04_next_file_variable_loop", "variable k file kn.txt (3000 4000 5000); loop: pair_coeff ${k}; next k; jump SELF l (5000 last)",
  pre=RB() + "variable k file kn.txt\nlabel l\n" + PC("1 2", HK.replace("2000", "${k}")) + "next k\njump SELF l\n", data={"kn.txt": "# kn\n3000\n4000\n5000\n"})
L("V05_next_file_two_vars", "variable i loop 2; variable k file kn.txt; next i k together: pair_coeff from k after 2 passes (4000)",
  pre=RB() + "variable i loop 2\nvariable k file kn.txt\nlabel l\n" + PC("1 2", HK.replace("2000", "${k}")) + "next i k\njump SELF l\n", data={"kn.txt": "3000\n4000\n5000\n"})
L("V06_include_defines_then_redef_equal", "include a.in (variable e equal 0.7, pair_coeff hertz e ${e}); variable e equal 0.3 after (no effect)",
  pre=RB(coeff="") + "include a.in\nvariable e equal 0.3\n", data={"a.in": "variable e equal 0.7\n" + PC("* *", HZM.replace("0.5 0.3", "${e} 0.3"))})
L("V07_shell_putenv_getenv", "shell putenv F46KN=5000; variable k getenv F46KN; pair_coeff 1 2 hooke ${k}", pre=RB() + "shell putenv F46KN=5000\nvariable k getenv F46KN\n" + PC("1 2", HK.replace("2000", "${k}")))
L("V08_include_in_if_var", "variable m index hz; if \"${m} == hz\" then \"include hz.in\" else \"include hk.in\" (hz: hertz e 0.7)",
  pre=RB() + "variable m index hz\nif \"${m} == hz\" then \"include hz.in\" else \"include hk.in\"\n", data={"hz.in": PC("* *", HZM.replace("0.5 0.3", "0.7 0.3")), "hk.in": PC("* *", HK)})
L("V09_fix_adapt_pair_granular", "fix adapt 1 all pair granular ... (LAMMPS: granular has no adapt parameters?)", pre=RB() + "variable kk equal 5000\nfix ad all adapt 1 pair granular kn 1 2 v_kk\n")
L("V10_fix_adapt_gran_hooke", "pair_style gran/hooke; fix adapt pair gran/hooke? (engine decides)", pre=RB(style="pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n") + "variable kk equal 5000\nfix ad all adapt 1 pair gran/hooke kn * * v_kk\n")
L("V11_fix_adapt_diameter_start", "fix adapt 1 all atom diameter v_d (d 0.006 for all, reset no) from the start", pre=RB() + "variable d equal 0.006\nfix ad all adapt 1 atom diameter v_d\n")
L("V12_variable_string_model", "variable law string \"hertz/material 1e6 0.7 0.3\"; pair_coeff * * ${law} tangential ... damping coeff_restitution",
  pre=RB(coeff="") + "variable law string \"hertz/material 1e6 0.7 0.3\"\npair_coeff * * ${law} tangential linear_nohistory 1 0.3 damping coeff_restitution\n")
L("V13_include_relative_subdir", "include sub/a.in which includes sub/b.in by the path from the deck's folder", pre=RB() + "include sub/a.in\n",
  data={"sub/a.in": "include sub/b.in\n", "sub/b.in": PC("1 2", HK.replace("2000", "5000"))})
L("V14_label_loop_ke_exit", "loop: run 100; if \"$(step) >= 600\" then \"jump SELF done\"; pair_coeff 1 2 kn by pass; jump SELF l (kn changes mid-contact)",
  body="variable i loop 20\nlabel l\nrun 100\n" + PC("1 2", HK.replace("2000", "$(2000+200*v_i)")) + "if \"$(step) >= 600\" then \"jump SELF done\"\nnext i\njump SELF l\nlabel done\nrun 2000\n")
L("V15_python_var_absent", "variable k python (no python: engine decides)", pre=RB() + "variable k python f\n")

# ================================================================ L: LIGGGHTS generated
LG("L01_two_restitution_fixes", "coefficientRestitution given by fix m3 (0.5 for 1 2) and a second fix m3b (0.8 everywhere)",
   pre=LBASE(extra="fix m3b all property/global coefficientRestitution peratomtypepair 3 0.8 0.8 0.8 0.8 0.8 0.8 0.8 0.8 0.8\n"))
LG("L02_rolling_epsd2_headon", "model hertz tangential history rolling_friction epsd2 (coefficientRollingFriction 0.5) head-on",
   pre=LBASE(model="model hertz tangential history rolling_friction epsd2", extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"))
LG("L03_rolling_cdt_headon", "rolling_friction cdt", pre=LBASE(model="model hertz tangential history rolling_friction cdt", extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"))
LG("L04_rolling_epsd_headon", "rolling_friction epsd (needs coefficientRollingViscousDamping)", pre=LBASE(model="model hertz tangential history rolling_friction epsd",
   extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\nfix m9 all property/global coefficientRollingViscousDamping peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n"))
LG("L05_wall_own_model_hooke", "pair hertz; the floor wall model hooke (e for (1,3) 0.7)", pre=LBASE(extra="fix m10 all property/global characteristicVelocity scalar 1.0\n").replace("fix wprim all wall/gran model hertz tangential history", "fix wprim all wall/gran model hooke tangential history"),
   pair=LFLOOR, PAIR="type 1 on wall wprim")
LG("L06_hooke_stiffness", "model hooke/stiffness with kn/gamman peratomtypepair", pre=LBASE(model="model hooke/stiffness tangential history",
   extra="fix m10 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix m11 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
   "fix m12 all property/global gamman peratomtypepair 3 3000 3000 3000 3000 3000 3000 3000 3000 3000\nfix m13 all property/global gammat peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"))
LG("L07_read_data_granular", "read_data (atom_style granular: id type diameter density x y z) into the box", pre=LBASE().replace("region reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box\ncreate_box 3 reg\n", "read_data d.data\n"),
   pair="group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0\nvelocity lv2 set -0.2285714286 0 0\n",
   data={"d.data": "# data\n\n2 atoms\n3 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.01 0.15 zlo zhi\n\nAtoms\n\n1 1 0.004 2500 -0.002550 0 0.1\n2 2 0.008 2500 0.003550 0 0.1\n"})
LG("L08_include_materials_var", "materials in mat.in via include, e from ${e12} (0.3)", pre=LBASE().replace("fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n", "variable e12 equal 0.3\ninclude mat.in\n"),
   data={"mat.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 ${e12} 0.7 ${e12} 0.4 0.45 0.7 0.45 0.8\n"})
LG("L09_coarse_step_hertz", "timestep 2e-5 (coarse: about 12 steps per contact)", pre=LBASE(dt="2e-5"), body="run 200\n")
LG("L10_limitforce_pair", "model hertz ... limitForce on (pair only; the wall without)", pre=LBASE(model="model hertz tangential history limitForce on").replace("wall/gran model hertz tangential history limitForce on", "wall/gran model hertz tangential history"))
LG("L11_tangential_no_history", "model hertz tangential no_history", pre=LBASE(model="model hertz tangential no_history"))
LG("L12_rolling_epsd2_floor", "rolling_friction epsd2 on the wall and pair; sphere dropped on the floor", pre=LBASE(model="model hertz tangential history rolling_friction epsd2", extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"),
   pair=LFLOOR, PAIR="type 1 on wall wprim")
LG("L13_restitution_redefined_same_id", "fix m3 given again (same ID) with 0.8 for 1 2 before the run", pre=LBASE() + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\n")
LG("L14_atomtypepair_alias", "coefficientRestitution atomtypepair 3 ... (alias)", pre=LBASE().replace("coefficientRestitution peratomtypepair", "coefficientRestitution atomtypepair"))
LG("L15_set_type_diameter_label_free", "set type 2 diameter 0.0058 after set atom", pair=LIN + "set type 2 diameter 0.0058\n")
LG("L16_variable_dt_include", "timestep ${dt} from a file variable", pre=LBASE().replace("timestep 1e-6\n", "variable dt file dt.txt\ntimestep ${dt}\n"), data={"dt.txt": "5e-7\n"}, body="run 6000\n")
LG("L17_hertz_stiffness", "model hertz/stiffness with kn/gamman", pre=LBASE(model="model hertz/stiffness tangential history",
   extra="fix m10 all property/global kn peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\nfix m11 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
   "fix m12 all property/global gamman peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix m13 all property/global gammat peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"))
LG("L18_cohesion_sjkr_zero", "cohesion sjkr with cohesionEnergyDensity 0", pre=LBASE(model="model hertz tangential history cohesion sjkr", extra="fix m14 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"))
LG("L19_pair_after_create", "pair_style given after the atoms (materials before)", pre=LBASE().replace("pair_style gran model hertz tangential history\npair_coeff * *\n", ""),
   pair=LIN + "pair_style gran model hertz tangential history\npair_coeff * *\n")
LG("L20_insert_single_template", "fix particletemplate/sphere type 2 radius 0.004 + insert/pack far (once) and the pair", pair=LIN +
   "fix pts all particletemplate/sphere 15485863 atom_type 2 density constant 2500 radius constant 0.004\nfix pdd all particledistribution/discrete 15485867 1 pts 1.0\n"
   "region ins block -0.04 0.04 -0.04 0.04 0.12 0.14 units box\nfix ins all insert/pack seed 32452843 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 3 region ins\n")

# ================================================================ H: harmless controls
L("H01_rolling_twist_hooke_control", "hooke + rolling sds + twisting sds (head-on: 0.4134)", pre=GR(PC("* *", HK.replace("tangential linear_nohistory 1 0.3", "tangential linear_history 2000 1 0.3") + " rolling sds 500 200 0.5 twisting sds 100 50 0.5")))
L("H02_wall_contacts_region_control", "fix wall/gran/region hooke on a plane region far from the pair + `contacts` (the pair 0.4134)",
  pre=RB().replace("fix integ", "region pl plane 0 0 0 0 0 1 units box\nfix wr all wall/gran/region granular " + HK + " region pl contacts\nfix integ"))
L("H03_include_empty_chain", "include a.in (includes b.in, both comments)", pre=RB() + "include a.in\n", data={"a.in": "# a\ninclude b.in\n", "b.in": "# b\n"})
L("H04_labels_everywhere", "labels in set/group/velocity/pair_coeff, all consistent (0.4134)", pre=LB() + PC("sm bg", HK),
  pair=IN().replace("create_atoms 1 single", "create_atoms sm single").replace("create_atoms 2 single", "create_atoms bg single").replace("set atom 1 ", "set type sm ").replace("set atom 2 ", "set type bg "))
L("H05_pour_far_same_size", "fix pour of type 1 diam one 0.004 (the pair's size) far", pair=IN() + "region pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 3 1 4767 region pr diam one 0.004 dens 2500 2500\n")
L("H06_read_data_plain", "read_data with the pair's atoms and velocities (no coefficients in the file)", pre=RD("read_data d.data\n", after=PC("* *", HK)), pair=RDP, data={"d.data": DATA(AS)})
LG("H07_lig_include_same", "LIGGGHTS: materials through include (same values)", pre=LBASE().replace("fix m3 all", "include m3.in\n#fix m3 all"), data={"m3.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n"})
L("H08_dmt_c0_viscoelastic", "dmt cohesion 0 viscoelastic 0.5 (as hertz/material)", pre=GR(PC("* *", "dmt 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping viscoelastic")))

# ================================================================ X (set 2, written while the first audit ran, before reading it)
HKND = "hooke 2000 3000 tangential linear_nohistory 1 0.3"
L("X01_hooke_no_damping_keyword", "pair_coeff * * hooke 2000 3000 tangential ... (no damping keyword: LAMMPS' default viscoelastic)", pre=GR(PC("* *", HKND)))
L("X02_hertzmat_no_damping_keyword", "hertz/material 1e6 0.5 0.3 without damping (default viscoelastic, damp 0.5)", pre=GR(PC("* *", "hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3")))
L("X03_wall_no_damping_keyword", "floor wall/gran granular hooke 2000 3000 with no damping keyword (viscoelastic); the pair mass_velocity",
  pre=WALLB("fix floor all wall/gran granular " + HKND + " zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("X04_star_then_22_changed", "pair_coeff * * hooke 2000; pair_coeff 2 2 hooke 8000 (1 2 stays explicit 2000, not mixed 4000)", pre=GR(PC("* *", HK) + PC("2 2", HK.replace("2000", "8000"))))
L("X05_11_22_then_11_again", "pair_coeff 1 1 hooke 1000; 2 2 hooke 4000; 1 1 hooke 4000 again (1 2 mixed at init: 4000)", pre=GR(PC("1 1", HK.replace("2000", "1000")) + PC("2 2", HK.replace("2000", "4000")) + PC("1 1", HK.replace("2000", "4000"))))
L("X06_12_explicit_then_11_22", "pair_coeff 1 2 hooke 5000 explicit; then 1 1 and 2 2 hooke 1000 (1 2 stays 5000)", pre=GR(PC("1 2", HK.replace("2000", "5000")) + PC("1 1", HK.replace("2000", "1000")) + PC("2 2", HK.replace("2000", "1000"))))
L("X07_reversed_indices", "pair_coeff 2 1 hooke 5000 (i > j) after * * 2000", pre=GR(PC("* *", HK) + PC("2 1", HK.replace("2000", "5000"))))
L("X08_number_forms", "pair_coeff * * hooke 2.0E+03 3.e3 damping mass_velocity tangential linear_nohistory 1. .3", pre=GR(PC("* *", "hooke 2.0E+03 3.e3 damping mass_velocity tangential linear_nohistory 1. .3")))
L("X09_quoted_words", "pair_coeff * * hooke \"5000\" 3000 ... (a quoted number)", pre=GR('pair_coeff * * hooke "5000" 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n'))
L("X10_triple_quoted_if", "if \"1 > 0\" then \"\"\"pair_coeff 1 2 hooke 5000 ...\"\"\" (triple quotes)", pre=RB() + 'if "1 > 0" then """pair_coeff 1 2 ' + HK.replace("2000", "5000") + '"""\n')
L("X11_suffix_omp_old_style", "suffix omp; pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1 (the /omp variant, if built)", pre=RB(style="suffix omp\npair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1\n", coeff="pair_coeff * *\n"))
L("X12_mix_pair_modify_arithmetic", "pair_modify mix arithmetic; 1 1 hooke 1000, 2 2 hooke 4000 (granular mixes geometrically: 2000, or 2500?)",
  pre=GR(PC("1 1", HK.replace("2000", "1000")) + PC("2 2", HK.replace("2000", "4000")) + "pair_modify mix arithmetic\n"))
L("X13_mix_viscoelastic_damp", "hertz/material viscoelastic 1 1 damp 200, 2 2 damp 800 (1 2 mixed)",
  pre=GR(PC("1 1", "hertz/material 1e6 200 0.3 tangential linear_nohistory 1 0.3 damping viscoelastic") + PC("2 2", "hertz/material 1e6 800 0.3 tangential linear_nohistory 1 0.3 damping viscoelastic")))
L("X14_mix_hertzmat_E_nu", "hertz/material coeff_restitution e 0.5: 1 1 E 1e6 nu 0.1, 2 2 E 9e6 nu 0.45 (1 2 mixed E*)",
  pre=GR(PC("1 1", "hertz/material 1e6 0.5 0.1 tangential linear_nohistory 1 0.3 damping coeff_restitution") + PC("2 2", "hertz/material 9e6 0.5 0.45 tangential linear_nohistory 1 0.3 damping coeff_restitution")))
L("X15_hertz_viscoelastic", "hertz 1e5 200 damping viscoelastic", pre=GR(PC("* *", "hertz 1e5 200 tangential linear_nohistory 1 0.3 damping viscoelastic")))
L("X16_hooke_velocity_damping", "hooke 2000 0.2 damping velocity (force/velocity)", pre=GR(PC("* *", "hooke 2000 0.2 tangential linear_nohistory 1 0.3 damping velocity")))
L("X17_mdr_model", "pair_coeff * * mdr (new LAMMPS model: not mapped, refusal allowed)", pre=GR(PC("* *", "mdr 5e6 0.4 1.9e5 2 0.5 0.5 damping none tangential linear_nohistory 1 0.3")))
L("X18_gravity_on_lv1_along_x", "fix g2 lv1 gravity 500 vector 1 0 0 (a push on lv1 into lv2, the pair only)", pair=IN() + "fix g2 lv1 gravity 500 vector 1 0 0\n")
L("X19_wall_hooke_history_old_limit", "pair hooke; floor fix wall/gran hooke/history 2000 NULL 3000 NULL 0.3 1 limit_damping", pre=WALLB("fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 1 limit_damping zplane 0 NULL\n"), pair=FLOORP, **FLOOR)
L("X20_gran_hertz_history_kt_numeric", "pair_style gran/hertz/history 2e5 1e5 5e3 NULL 0.3 1", pre=RB(style="pair_style gran/hertz/history 2e5 1e5 5e3 NULL 0.3 1\n", coeff="pair_coeff * *\n"))
L("X21_create_atoms_mol_template", "create_atoms 0 single ... mol m1 (a one-atom template of type 2, Diameters 0.006, Masses 2x): lv2 from the template",
  pair="molecule m1 m1.mol\ncreate_atoms 1 single 0.017950 0.02 0.05\ncreate_atoms 0 single 0.023050 0.02 0.05 mol m1 4767\nset atom 1 diameter 0.004 density 2500\n"
  "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n",
  data={"m1.mol": "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 5.6549e-4\n"})
LG("X22_lig_e_forms", "coefficientRestitution values as 5e-1 and .5 and 0.50", pre=LBASE(e="0.6 5e-1 0.7 .5 0.4 0.45 0.7 0.45 0.8"))
LG("X23_lig_model_keyword_order", "pair_style gran tangential history model hertz (keywords reordered)", pre=LBASE().replace("pair_style gran model hertz tangential history", "pair_style gran tangential history model hertz"))
LG("X24_lig_hooke_limitforce_cv", "model hooke + limitForce on, characteristicVelocity 2.0", pre=LBASE(model="model hooke tangential history limitForce on", extra="fix m10 all property/global characteristicVelocity scalar 2.0\n"))
LG("X25_lig_continuation_comments", "coefficientRestitution over & lines with a comment line between", pre=LBASE().replace("coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8",
   "coefficientRestitution peratomtypepair 3 &\n    0.6 0.3 0.7 &\n    0.3 0.4 0.45 &\n    0.7 0.45 0.8"))
LG("X26_lig_tangential_damping_off", "model hertz tangential history tangential_damping off", pre=LBASE(model="model hertz tangential history tangential_damping off"))
LG("X27_lig_hooke_absolute_damping", "hooke/stiffness absolute_damping on with gamman_abs", pre=LBASE(model="model hooke/stiffness tangential history absolute_damping on",
   extra="fix m10 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix m11 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
   "fix m12 all property/global gamman_abs peratomtypepair 3 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2\nfix m13 all property/global gammat_abs peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"))
LG("X28_lig_wall_limitforce_only", "pair hertz without limitForce; the floor wall with limitForce on", pre=LBASE().replace("fix wprim all wall/gran model hertz tangential history", "fix wprim all wall/gran model hertz tangential history limitForce on"),
   pair=LFLOOR, PAIR="type 1 on wall wprim")
L("X29_two_wall_fixes_group_split", "floor walls: wall/gran hooke 5000 on group of type 1 (after atoms), another hooke 2000 on type 2 group", pre=RB(),
  pair=FLOORP + "group g1 type 1\ngroup g2 type 2\nfix floor g1 wall/gran granular " + HK.replace("2000", "5000") + " zplane 0 NULL\nfix floor2 g2 wall/gran granular " + HK + " zplane 0 NULL\n", **FLOOR)
L("X30_damping_before_normal_keywords", "pair_coeff * * hooke 2000 3000 tangential linear_nohistory 1 0.3 limit_damping damping mass_velocity (keywords reordered)",
  pre=GR(PC("* *", "hooke 2000 3000 tangential linear_nohistory 1 0.3 limit_damping damping mass_velocity")))

# set 2b: runnable forms of X24 X26 X27 (LIGGGHTS takes those model keywords on the pair style, not on the wall line;
# written after the engine stopped on them, before any audit of set 2)
LWALLPLAIN = "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
LG("X31_lig_hooke_limitforce_cv_paironly", "X24 with the wall line plain hertz: model hooke + limitForce on, characteristicVelocity 2.0 (pair)",
   pre=LBASE(model="model hooke tangential history limitForce on", extra="fix m10 all property/global characteristicVelocity scalar 2.0\n", wall=False) + LWALLPLAIN)
LG("X32_lig_tangential_damping_off_paironly", "X26 with the wall line plain: pair model hertz tangential history tangential_damping off",
   pre=LBASE(model="model hertz tangential history tangential_damping off", wall=False) + LWALLPLAIN)
LG("X33_lig_hooke_absolute_damping_paironly", "X27 with the wall line plain hertz: hooke/stiffness absolute_damping on, gamman_abs 0.2",
   pre=LBASE(model="model hooke/stiffness tangential history absolute_damping on", wall=False,
   extra="fix m10 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix m11 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
   "fix m12 all property/global gamman_abs peratomtypepair 3 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2\nfix m13 all property/global gammat_abs peratomtypepair 3 0 0 0 0 0 0 0 0 0\n") + LWALLPLAIN)

# ================================================================ Y (set 3): binary STL meshes (written after reading the first audit:
# P06's audit said LIGGGHTS stops on its binary Pipe.stl, which LIGGGHTS reads; these find which bytes matter)
import struct  # noqa: E402


def STL(attr=0, header=b"binary test".ljust(80, b" "), z=0.0):
    """A binary STL floor (two triangles, z = z, 8 cm square), each triangle's attribute count `attr`."""
    tris = [((0, 0, 1), (-0.04, -0.04, z), (0.04, -0.04, z), (0.04, 0.04, z)), ((0, 0, 1), (-0.04, -0.04, z), (0.04, 0.04, z), (-0.04, 0.04, z))]
    b = header + struct.pack("<I", len(tris))
    for t in tris:
        b += struct.pack("<12f", *[c for v in t for c in v]) + struct.pack("<H", attr)
    return b


MESHW = "fix fl all mesh/surface file floor.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes fl\n"
for nm, attr, what in (("Y01_stl_binary_plain", 0, "attribute bytes 0"), ("Y02_stl_binary_cr", 0x000d, "an attribute byte 0x0d (a CR)"),
                       ("Y03_stl_binary_crlf", 0x0a0d, "attribute bytes CR LF"), ("Y04_stl_binary_lf", 0x000a, "an attribute byte 0x0a (a LF)")):
    LG(nm, f"a binary STL floor mesh (two triangles, {what}) as the wall; one sphere dropped on it", pre=LBASE(wall=False) + MESHW, pair=LFLOOR,
       data={"floor.stl": STL(attr)}, PAIR="type 1 on wall wm")
LG("Y05_stl_binary_header_solid", "a binary STL whose 80-byte header begins with 'solid' (read as ASCII by some readers)", pre=LBASE(wall=False) + MESHW, pair=LFLOOR,
   data={"floor.stl": STL(0, header=b"solid binary".ljust(80, b" "))}, PAIR="type 1 on wall wm")



def STL_RANDOM(n=96, seed=1):
    """STL()'s floor followed by n - 2 triangles of seeded random coordinates high above it (z 5-6 cm): binary
    bytes of every value, as a CAD export's are (the public WEAR deck's Pipe.stl: its first 46 triangles suffice)."""
    import random
    rnd = random.Random(seed)
    b = STL()
    tris = b""
    for _ in range(n - 2):
        v = [rnd.uniform(-0.04, 0.04) for _ in range(9)]
        for k in (2, 5, 8):
            v[k] = rnd.uniform(0.05, 0.06)
        tris += struct.pack("<12f", 0, 0, 1, *v) + struct.pack("<H", rnd.randrange(65536))
    return b[:80] + struct.pack("<I", n) + b[84:] + tris


LG("Y06_stl_binary_random_bytes", "a binary STL floor mesh with 94 more triangles of random coordinates above (z 5-6 cm); one sphere dropped on the floor",
   pre=LBASE(wall=False) + MESHW, pair=LFLOOR, data={"floor.stl": STL_RANDOM()}, PAIR="type 1 on wall wm")
LG("Y07_stl_binary_random_no_mesh_fix", "Y06's floor.stl in the folder but not read by the deck (the primitive floor instead)", pair=LFLOOR,
   data={"floor.stl": STL_RANDOM()}, PAIR="type 1 on wall wprim")

LG("Y08_stl_binary_cr_include_var", "Y02 (a binary STL floor, an attribute byte 0x0d) with an include ${f} of a harmless file (a file named by a variable)",
   pre=LBASE(wall=False) + "variable f index extra.in\ninclude ${f}\n" + MESHW, pair=LFLOOR, data={"floor.stl": STL(0x000d), "extra.in": "# nothing\n"}, PAIR="type 1 on wall wm")
LG("Y09_stl_unread_cr_include_var", "a binary STL with a lone CR byte in the folder, not read; the deck's include ${f} (the primitive floor)", pre=LBASE() + "variable f index extra.in\ninclude ${f}\n",
   pair=LFLOOR, data={"floor.stl": STL(0x000d), "extra.in": "# nothing\n"}, PAIR="type 1 on wall wprim")
L("Y10_lammps_include_var_binary_file", "LAMMPS: include ${f} (a harmless file) and a binary file with a lone CR in the folder (not read)", pre=RB() + "variable f index extra.in\ninclude ${f}\n",
  data={"extra.in": "# nothing\n", "blob.bin": bytes(range(256)) * 4})

LG("Y11_stl_binary_header_line_dollar", "minimal: Y01's two-triangle binary floor whose 80-byte header holds a line feed then '$Revision 3 $'", pre=LBASE(wall=False) + MESHW, pair=LFLOOR,
   data={"floor.stl": STL(0, header=b"CAD export\n$Revision 3 $".ljust(80, b" "))}, PAIR="type 1 on wall wm")


# ================================================================ Z (set 4): text files the audit reads as scripts (after Y)
ASCII_STL = ("solid floor\n facet normal 0 0 1\n  outer loop\n   vertex -0.04 -0.04 0\n   vertex 0.04 -0.04 0\n   vertex 0.04 0.04 0\n  endloop\n endfacet\n"
             " facet normal 0 0 1\n  outer loop\n   vertex -0.04 -0.04 0\n   vertex 0.04 0.04 0\n   vertex -0.04 0.04 0\n  endloop\n endfacet\nendsolid floor\n")
LG("Z01_stl_ascii_crlf", "an ASCII STL floor with CRLF line ends", pre=LBASE(wall=False) + MESHW, pair=LFLOOR, data={"floor.stl": ASCII_STL.replace("\n", "\r\n").encode()}, PAIR="type 1 on wall wm")
LG("Z02_stl_ascii_crlf_include_var", "Z01 with an include ${f} (every file read as a script)", pre=LBASE(wall=False) + "variable f index extra.in\ninclude ${f}\n" + MESHW, pair=LFLOOR,
   data={"floor.stl": ASCII_STL.replace("\n", "\r\n").encode(), "extra.in": "# nothing\n"}, PAIR="type 1 on wall wm")
L("Z03_data_title_dollar", "read_data whose title line is '$Id: packing.data 7 $' (LAMMPS skips the title)", pre=RD("read_data d.data\n", after=PC("* *", HK)), pair=RDP,
  data={"d.data": DATA(AS).replace("# data\n", "$Id: packing.data 7 $\n", 1)})
L("Z04_mol_title_run", "a one-atom molecule template titled 'run 7 template' poured far (its first line a comment to LAMMPS)",
  pair=IN() + "molecule m1 m1.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 2 0 4767 region pr mol m1\n",
  data={"m1.mol": "run 7 template\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 2.8274e-4\n"})
L("Z05_data_title_run_include_var", "read_data title 'run 2 packing' and an include ${f} (every file a script)", pre=RD("read_data d.data\n", after=PC("* *", HK) + "variable f index extra.in\ninclude ${f}\n"), pair=RDP,
  data={"d.data": DATA(AS).replace("# data\n", "run 2 packing\n", 1), "extra.in": "# nothing\n"})
L("Z06_variable_file_values_include", "variable k file kn.txt whose first line is 'include kn5.in' read as a string; pair_coeff from a second file variable",
  pre=RB() + "variable k file kn.txt\nvariable n equal 5000\n" + PC("1 2", HK.replace("2000", "${n}")), data={"kn.txt": "include kn5.in\n3000\n", "kn5.in": PC("1 2", HK.replace("2000", "8000"))})
L("Z07_data_title_print_file", "read_data title 'print done file pc.in' and, later, include pc.in (a file the deck has)", pre=RD("read_data d.data\n", after=PC("* *", HK) + "include pc.in\n"), pair=RDP,
  data={"d.data": DATA(AS).replace("# data\n", "print done file pc.in\n", 1), "pc.in": PC("1 2", HK.replace("2000", "5000"))})

# set 4b (after reading Z04): a molecule template's title read as a command, with valid run syntax
MOL = lambda title: title + "\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 2.8274e-4\n"
POURM = IN() + "molecule m1 m1.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 0.095 units box\nfix po all pour 2 0 4767 region pr mol m1\n"
L("Z08_mol_title_run0", "a one-atom template titled 'run 0' poured far", pair=POURM, data={"m1.mol": MOL("run 0")})
L("Z09_mol_title_run500_kn_after", "a template titled 'run 500'; pair_coeff 1 2 hooke 5000 after the molecule command (before the deck's only run)", pair=POURM + PC("1 2", HK.replace("2000", "5000")),
  data={"m1.mol": MOL("run 500")})
L("Z10_mol_title_print_file_include", "a template titled 'print x file pc.in', then include pc.in (the deck's own file: kn 5000)", pair=POURM + "include pc.in\n",
  data={"m1.mol": MOL("print x file pc.in"), "pc.in": PC("1 2", HK.replace("2000", "5000"))})
L("Z11_mol_title_quit", "a template titled 'quit' poured far (LAMMPS skips the title)", pair=POURM, data={"m1.mol": MOL("quit")})

L("Z12_mol_title_run500_if_step", "a template titled 'run 500', then if \"$(step) > 100\" then pair_coeff 1 2 hooke 5000 (the engine's step is 0: kn 2000)",
  pair=POURM + 'if "$(step) > 100" then "pair_coeff 1 2 ' + HK.replace("2000", "5000") + '"\n', data={"m1.mol": MOL("run 500")})
L("Z13_mol_title_run500_minimize_after", "a template titled 'run 500', then min_style fire and minimize 0 0 10 100 before the deck's run (no contact yet)",
  pair=POURM + "min_style fire\nminimize 0.0 0.0 10 100\n", data={"m1.mol": MOL("run 500")})

L("Z14_minimize_fire_before_any_run", "(after Z13) min_style fire; minimize 0 0 10 100 before the deck's only run (the pair 0.1 mm apart, moving)",
  pair=IN() + "min_style fire\nminimize 0.0 0.0 10 100\n")
L("Z15_minimize_cg_before_any_run", "(after Z13) minimize 0 0 10 100 (cg, the default) before the deck's only run", pair=IN() + "minimize 0.0 0.0 10 100\n")
L("Z16_minimize_quickmin_before_any_run", "(after Z13) min_style quickmin; minimize 0 0 10 100 before the deck's only run", pair=IN() + "min_style quickmin\nminimize 0.0 0.0 10 100\n")

L("Z17_minimize_fire_then_velocity_control", "(control for Z14) min_style fire; minimize before the velocities are set, then the velocity lines and the run",
  pair=IN().replace("velocity lv1", "min_style fire\nminimize 0.0 0.0 10 100\nvelocity lv1"))
L("Z18_floor_minimize_fire_before_run", "(after Z14) floor drop; min_style fire; minimize 0 0 10 100 before the only run", pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n"),
  pair=FLOORP + "min_style fire\nminimize 0.0 0.0 10 100\n", **FLOOR)

L("Z19_run0_then_minimize_fire", "(after Z14) run 0, then min_style fire and minimize before the deck's run (run 0 makes no step)", pair=IN() + "run 0\nmin_style fire\nminimize 0.0 0.0 10 100\n")


# ================================================================ S (set 5, hidden: written before its referee and audit): what moves
# or grows during a run through a variable or a time-dependent keyword: gravity by a variable, spinning gravity, a LIGGGHTS
# mesh moved by linear/variable whose variables change through ramp() or through another variable
NOGRAV = lambda pre: pre.replace("fix grav all gravity 9.81 vector 0 0 -1\n", "")
L("S01_floor_gravity_var_grows", "floor drop; fix gravity v_g, g equal 9.81+2e4*(step>=150) (the push into the floor grows mid-contact)",
  pre=NOGRAV(WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")) + "variable g equal 9.81+2e4*(step>=150)\nfix grav all gravity v_g vector 0 0 -1\n", pair=FLOORP, **FLOOR)
L("S02_floor_gravity_spin", "floor drop; fix gravity 9.81 spin 0.004 1 0 0 (the field turns about x, period 4 ms)",
  pre=NOGRAV(WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")) + "fix grav all gravity 9.81 spin 0.004 1 0 0\n", pair=FLOORP, **FLOOR)
L("S03_floor_gravity_vector_var", "floor drop; fix gravity 9.81 vector 0 0 v_gz, gz equal -1-2000*(step>=150)",
  pre=NOGRAV(WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")) + "variable gz equal -1-2000*(step>=150)\nfix grav all gravity 9.81 vector 0 0 v_gz\n", pair=FLOORP, **FLOOR)
L("S04_floor_gravity_var_constant_control", "floor drop; fix gravity v_g, g equal 9.81 (constant: control)",
  pre=NOGRAV(WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")) + "variable g equal 9.81\nfix grav all gravity v_g vector 0 0 -1\n", pair=FLOORP, **FLOOR)
L("S05_pair_gravity_x_var_all_control", "the pair; fix gravity v_g vector 1 0 0 on all, g equal 1e4*(step>=150) (the same acceleration on both: control)",
  pre=NOGRAV(RB()) + "variable g equal 1e4*(step>=150)\nfix grav all gravity v_g vector 1 0 0\n")
L("S06_floor_gravity_ramp", "floor drop; fix gravity v_g, g equal ramp(9.81,2e4) over the run (no step word)",
  pre=NOGRAV(WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")) + "variable g equal ramp(9.81,2e4)\nfix grav all gravity v_g vector 0 0 -1\n", pair=FLOORP, **FLOOR)
L("S07_floor_addforce_var", "floor drop; fix addforce lv1 0 0 v_fz, fz equal -0.05*(step>=150) (pushed into the floor mid-contact)",
  pre=WALLB("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n"), pair=FLOORP + "variable fz equal -0.05*(step>=150)\nfix af lv1 addforce 0 0 v_fz\n", **FLOOR)
MOVEW = lambda vz, extra="": (LBASE(wall=False) + MESHW + extra + f"variable vx equal 0\nvariable vy equal 0\nvariable vz equal {vz}\n"
                              "fix mv all move/mesh mesh fl linear/variable v_vx v_vy v_vz\n")
LG("S08_lig_mesh_linvar_ramp", "a binary STL floor moved by move/mesh linear/variable, vz equal ramp(0,0.5) (no step word)", pre=MOVEW("ramp(0,0.5)"), pair=LFLOOR,
   data={"floor.stl": STL(0)}, PAIR="type 1 on wall wm")
LG("S09_lig_mesh_linvar_indirect_step", "the floor moved by linear/variable, vz equal v_a, a equal 0.5*(step>=150) (the step through another variable)",
   pre=MOVEW("v_a", "variable a equal 0.5*(step>=150)\n"), pair=LFLOOR, data={"floor.stl": STL(0)}, PAIR="type 1 on wall wm")
LG("S10_lig_mesh_linvar_const_control", "the floor moved by linear/variable, vz equal 0.0 (constant: control)", pre=MOVEW("0.0"), pair=LFLOOR,
   data={"floor.stl": STL(0)}, PAIR="type 1 on wall wm")
LG("S11_lig_gravity_var", "LIGGGHTS floor drop; fix gravity v_g, g equal 9.81+2e4*(step>=150)", pre=LBASE().replace("fix gravi all gravity 9.81 vector 0.0 0.0 -1.0\n",
   "variable g equal 9.81+2e4*(step>=150)\nfix gravi all gravity v_g vector 0.0 0.0 -1.0\n"), pair=LFLOOR, PAIR="type 1 on wall wprim")
LG("S12_lig_mesh_linvar_indirect_time", "the floor moved by linear/variable, vz equal v_b, b equal 0.5*(time>=1.5e-4)", pre=MOVEW("v_b", "variable b equal 0.5*(time>=1.5e-4)\n"), pair=LFLOOR,
   data={"floor.stl": STL(0)}, PAIR="type 1 on wall wm")
L("S13_region_wall_move_ramp", "LAMMPS: region plane moved by move NULL NULL v_dz, dz equal ramp(0,2e-4) (a floor region rising through the run)",
  pre=RB().replace("fix integ", "variable dz equal ramp(0,2e-4)\nregion flr plane 0 0 0 0 0 1 move NULL NULL v_dz units box\nfix floor all wall/gran/region granular " + HK + " region flr\nfix integ"), pair=FLOORP, **FLOOR)
L("S14_pair_viscous_by_type_control", "fix viscous all 0.0 scale 2 0.0 (zero drag: control)", pair=IN() + "fix vs all viscous 0.0 scale 2 0.0\n")


# ================================================================ Q (set 6, hidden): region walls with open faces, INF bounds and
# curved surfaces met from outside or along another axis (hertz/material reads the effective radius)
HZRB = RB(coeff=PC("* *", HZM))
XWP = lambda x="0.0279", y="0.02", v="1.0 0 0": (f"create_atoms 1 single {x} {y} 0.05 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
                                                 f"velocity lv1 set {v} units box\n")
RW = lambda reg: HZRB.replace("fix integ", reg + "fix wc all wall/gran/region granular " + HZM + " region cyl\nfix integ")
L("Q01_cyl_side_open3", "hertz region cylinder z 0.02 0.02 0.01 0 0.1 side in open 3 (its curved side open): lv1 +x at its side passes through",
  pre=RW("region cyl cylinder z 0.02 0.02 0.01 0 0.1 side in open 3 units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q02_cyl_ends_open_side_kept", "the same cylinder with open 1 open 2 (its ends open, the side kept): lv1 +x meets the side",
  pre=RW("region cyl cylinder z 0.02 0.02 0.01 0 0.1 side in open 1 open 2 units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q03_cyl_inf_bounds", "hertz region cylinder z 0.02 0.02 0.01 INF INF side in (no ends): lv1 +x meets the side",
  pre=RW("region cyl cylinder z 0.02 0.02 0.01 INF INF side in units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q04_cyl_side_out", "hertz region cylinder z 0.035 0.02 0.005 0 0.1 side out (a post): lv1 +x meets its convex side",
  pre=RW("region cyl cylinder z 0.035 0.02 0.005 0 0.1 side out units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q05_sphere_side_in", "hertz region sphere 0.02 0.02 0.05 0.01 side in (a spherical shell): lv1 +x meets it from inside",
  pre=RW("region cyl sphere 0.02 0.02 0.05 0.01 side in units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q06_cyl_x_axis_side", "hertz region cylinder x 0.02 0.05 0.01 0 0.04 side in (axis along x): lv1 +y meets the side",
  pre=RW("region cyl cylinder x 0.02 0.05 0.01 0 0.04 side in units box\n"), pair=XWP(x="0.02", y="0.0279", v="0 1.0 0"), PAIR="type 1 on wall wc", AXIS="y")
L("Q07_block_floor_open_top", "hooke wall/gran/region on a block floor (side out) with open 6: its top face open, the sphere falls through",
  pre=RB().replace("fix integ", "region flr block -1 1 -1 1 -1 0 side out open 6 units box\nfix floor all wall/gran/region granular " + HK.replace("2000", "5000") + " region flr\nfix integ"),
  pair=FLOORP, **FLOOR)
L("Q08_cyl_open3_control_closed", "Q01's cylinder closed (no open): control", pre=RW("region cyl cylinder z 0.02 0.02 0.01 0 0.1 side in units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q09_cyl_side_out_open3", "hertz post (Q04) with open 3: no side, lv1 +x passes", pre=RW("region cyl cylinder z 0.035 0.02 0.005 0 0.1 side out open 3 units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")
L("Q10_cone_region_hertz", "hertz region cone z 0.02 0.02 0.01 0.01 0 0.1 side in (a cone of equal radii: a cylinder)", pre=RW("region cyl cone z 0.02 0.02 0.01 0.01 0 0.1 side in units box\n"), pair=XWP(), PAIR="type 1 on wall wc", WALLX="")


def write(only=()):
    n = 0
    for name, (text, live, data, meta) in sorted(DECKS.items()):
        if only and not any(name.startswith(p) for p in only):
            continue
        d = os.path.join(D, name)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(text)
        open(os.path.join(d, "DECK"), "w").write("in.deck\n")
        open(os.path.join(d, "G"), "w").write("1\n")
        open(os.path.join(d, "NP"), "w").write("1\n")
        open(os.path.join(d, "LIVE"), "w").write(("WALL " if "wall" in meta.get("PAIR", "") else "") + live + "\n")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + "\n")
        for f, t in data.items():
            p = os.path.join(d, f)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            open(p, "wb" if isinstance(t, bytes) else "w").write(t)
        n += 1
    print(n, "decks")


if __name__ == "__main__":
    write(sys.argv[1:])
