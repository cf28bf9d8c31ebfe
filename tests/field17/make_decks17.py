"""Field round 17: write the LAMMPS (a*, m*, w*) and LIGGGHTS (G*) decks (decks/NAME/in.deck, G, extra files, a
LIGGGHTS marker) on round 15's LAMMPS header and round 14's LIGGGHTS header. Each deck's first comment says what it
tries. usage: python make_decks17.py [NAME ...]"""
import importlib.util, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import ATOMS, E3, HERTZ, MAT3, WALL3, lhead, RUN2000 as RUN  # noqa: E402  (round 14's LIGGGHTS lines)

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")


def _load(name, path):
    s = importlib.util.spec_from_file_location(name, os.path.join(HERE, "..", *path))
    m = importlib.util.module_from_spec(s)
    s.loader.exec_module(m)
    return m


M = _load("md15", ("field15", "make_decks.py"))
head, HK, HM, TWO, TWO4, GRAV, FLOOR, TAIL = M.head, M.HK, M.HM, M.TWO, M.TWO4, M.GRAV, M.FLOOR, M.TAIL
BASE = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
NB = "neighbor 1e-4 bin\n"
DECKS = {}


def deck(name, text, g=1, files=None, data=None, liggghts=False):
    DECKS[name] = (text, g, files or {}, data or {}, liggghts)


def nhead(neigh):
    """round 14's LIGGGHTS header with its neighbour lines replaced"""
    return lhead().replace("neighbor 0.002 bin\nneigh_modify delay 0\n", neigh)


# ---------------------------------------------------------------- LAMMPS: neighbour settings set in ways a reader may miss
deck("a01_neigh_in_include", "# neighbor 1e-5 and every 20 check no in an included file (bound 0.05 m/s)\n"
     + BASE + TWO4 + "include lists.in\nrun 1000\n", g=1,
     data={"lists.in": "neighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\n"})
deck("a02_neigh_in_if_before_run", "# the stale lists set in an if branch taken before the only run (bound 0.05 m/s)\n"
     + BASE + TWO4 + "variable fast equal 1\nif \"${fast} == 1\" then \"neighbor 1e-5 bin\" \"neigh_modify every 20 delay 0 check no\"\nrun 1000\n", g=1)
deck("a03_neigh_from_string_var", "# neigh_modify ${nm} with nm a string variable holding 'every 20 delay 0 check no', skin from an equal variable\n"
     + BASE + TWO4 + "variable nm string \"every 20 delay 0 check no\"\nvariable sk equal 0.5e-5*2\nneighbor ${sk} bin\nneigh_modify ${nm}\nrun 1000\n", g=1)
deck("a04_clear_then_default_lists", "# stale lists, run, clear, the same deck again without them: stage 2 has LAMMPS' defaults\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 100\nclear\n" + BASE + TWO4 + "run 100\n", g="0.02 1")
deck("a05_clear_then_stale_lists", "# default lists, run, clear, the deck again with stale lists: stage 2 bound 0.05 m/s\n"
     + BASE + TWO4 + "run 100\nclear\n" + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 100\n", g=1)
deck("a06_restart_keeps_lists", "# stale lists, run, write_restart, clear, read_restart, run: are the lists in the restart?\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 100\nwrite_restart f17.restart\nclear\n"
     + "read_restart f17.restart\npair_style granular\npair_coeff * * " + HK + "\n" + FLOOR + TAIL + "run 100\n", g="0.02 1")
deck("a07_once_yes_far_gap", "# neigh_modify once yes: lists built at the run's start only; spheres 1 cm apart\n"
     + BASE + TWO4 + "neigh_modify once yes\nrun 1000\n", g=1)
deck("a08_exclude_type_12", "# neigh_modify exclude type 1 2: pairs 1 2 never interact\n"
     + BASE + TWO4 + "neigh_modify exclude type 1 2\nrun 1000\n", g=1)
deck("a09_include_and_exclude", "# include g1 (type 1) and exclude type 1 1: no pair at all is listed except 1 2\n"
     + BASE + TWO4 + "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\ngroup g1 type 1\natom_modify first g1\n"
     + "neigh_modify include g1 exclude type 1 1\nrun 1000\n", g=1)
deck("a10_exclude_group", "# neigh_modify exclude group g2 g2 (type 2 among itself)\n"
     + BASE + TWO4 + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.004 density 2500\ngroup g2 type 2\nneigh_modify exclude group g2 g2\nrun 1000\n", g=1)
deck("a11_exclude_none_after", "# exclude type 1 2, then neigh_modify exclude none before the run: every pair listed again\n"
     + BASE + TWO4 + "neigh_modify exclude type 1 2\nneigh_modify exclude none\nrun 1000\n", g=1)
deck("a12_multi_every10_checkno", "# neighbor 1e-4 multi with every 10 check no (bound 1 m/s)\n"
     + BASE + TWO4 + "neighbor 1e-4 multi\nneigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 2")
deck("a13_every3_delay6_checkno", "# every 3 delay 6 check no: LAMMPS rebuilds every 6 steps (bound skin/(6 dt) = 1.667 m/s, not 3.33)\n"
     + BASE + TWO4 + NB + "neigh_modify every 3 delay 6 check no\nrun 1000\n", g="1.5 2.5")
deck("a14_jump_skips_neigh", "# a jump over the stale neigh_modify: LAMMPS never runs it; the lists are LAMMPS' defaults\n"
     + BASE + TWO4 + "jump SELF skip\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nlabel skip\nrun 1000\n", g=1)
deck("a15_page_one_binsize", "# neigh_modify page/one/binsize (no effect on when lists are built), every 1 delay 0 check yes\n"
     + BASE + TWO4 + "neigh_modify every 1 delay 0 check yes page 100000 one 2000 binsize 0.01\nrun 1000\n", g=1)
deck("a16_nsq_stale_var_every", "# neighbor nsq, every from an equal variable of another variable (every 20 check no, skin 1e-5)\n"
     + BASE + TWO4 + "variable base equal 4\nvariable k equal v_base*5\nneighbor 1e-5 nsq\nneigh_modify every ${k} delay 0 check no\nrun 1000\n", g=1)
deck("a17_sort_and_comm_cutoff", "# atom_modify sort and comm_modify cutoff: no effect on the contact\n"
     + BASE + TWO4 + "atom_modify sort 10 0.002\ncomm_modify cutoff 0.02\nrun 1000\n", g=1)
deck("a18_neigh_loop_if_branch", "# a two-pass loop: pass 2 sets stale lists in an if branch on the loop variable (bound 0.05 in pass 2)\n"
     + BASE + TWO4 + "variable i loop 2\nlabel top\nif \"${i} == 2\" then \"neighbor 1e-5 bin\" \"neigh_modify every 20 delay 0 check no\"\nrun 200\nnext i\njump SELF top\n", g=1)
deck("a19_dt_reset_raises_dt", "# fix dt/reset raises dt from 1e-6 up to 1e-4 during the run (neighbour bound at 1e-6 would be 100)\n"
     + BASE.replace("timestep 1e-5", "timestep 1e-6") + TWO4 + NB + "neigh_modify every 10 delay 0 check no\n"
     + "fix dtr all dt/reset 1 1e-7 1e-4 0.01 units box\nrun 1000\n", g="0.5 2 5")
deck("a20_dt_reset_plain", "# fix dt/reset (max 1e-4) with LAMMPS' default lists\n"
     + BASE.replace("timestep 1e-5", "timestep 1e-6") + TWO4 + "fix dtr all dt/reset 1 1e-7 1e-4 0.01 units box\nrun 1000\n", g=1)
# ---------------------------------------------------------------- LAMMPS: models, mixing, labels, adapt
deck("m01_mix_hertzmaterial_E", "# pair_coeff 1 1 and 2 2 hertz/material with other E, nu, e (coeff_restitution); 1 2 mixed by LAMMPS\n"
     + head() + "pair_style granular\n"
     + "pair_coeff 1 1 hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3\n"
     + "pair_coeff 2 2 hertz/material 4e7 0.8 0.2 damping coeff_restitution tangential linear_nohistory 1 0.3\n"
     + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("m02_mix_hooke_viscoelastic", "# hooke 1 1 and 2 2 with other kn and damping; 1 2 mixed (geometric mean)\n"
     + head() + "pair_style granular\n"
     + "pair_coeff 1 1 hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "pair_coeff 2 2 hooke 8000 1000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("m03_mix_unlike_models", "# 1 1 hooke and 2 2 hertz/material, no 1 2 line: LAMMPS cannot mix them\n"
     + head() + "pair_style granular\n"
     + "pair_coeff 1 1 hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + f"pair_coeff 2 2 {HM}\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("m04_mix_damping_unlike", "# 1 1 hertz/material viscoelastic, 2 2 hertz/material tsuji: same normal model, damping mixed?\n"
     + head() + "pair_style granular\n"
     + "pair_coeff 1 1 hertz/material 1e7 0.5 0.3 damping viscoelastic tangential linear_nohistory 1 0.3\n"
     + "pair_coeff 2 2 hertz/material 1e7 0.5 0.3 damping tsuji tangential linear_nohistory 1 0.3\n" + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("m05_limit_damping_one_pair", "# limit_damping on 1 1 only (hooke with strong damping), not on 2 2 nor the mixed 1 2\n"
     + head() + "pair_style granular\n"
     + "pair_coeff 1 1 hooke 2000 30000 damping mass_velocity tangential linear_nohistory 1 0.3 limit_damping\n"
     + "pair_coeff 2 2 hooke 2000 30000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("m06_labelmap_pair_coeff", "# type labels: pair_coeff by label, the 1 2 pair with its own coefficients\n"
     + head() + "labelmap atom 1 big 2 small\npair_style granular\npair_coeff * * " + HK + "\n"
     + "pair_coeff big small hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL
     + "create_atoms big single 0.02 0.02 0.01\ncreate_atoms small single 0.01 0.01 0.01\nset type big diameter 0.006 density 2500\nset type small diameter 0.004 density 2500\nrun 100\n", g=1)
deck("m07_adapt_pair_kn", "# fix adapt on pair granular's coefficients (if LAMMPS allows it)\n"
     + BASE + TWO4 + "variable k equal 2000+1e6*time\nfix ad all adapt 1 pair granular kn * * v_k\nrun 1000\n", g=1)
deck("m08_adapt_gran_hooke_history", "# pair gran/hooke/history and fix adapt diameter with reset yes (sizes change in the run)\n"
     + head() + "pair_style gran/hooke/history 2000 NULL 30 NULL 0.5 1\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 2000 NULL 30 NULL 0.5 1 zplane 0 NULL\n" + TAIL + TWO4
     + "variable dd atom 0.004+0.01*time\nfix ad all adapt 1 atom diameter v_dd reset yes\nrun 1000\n", g=1)
deck("m09_pair_coeff_order_override", "# pair_coeff 1 2 first, then pair_coeff * * later: the later * * overrides 1 2\n"
     + head() + "pair_style granular\npair_coeff 1 2 hooke 9000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + f"pair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("m10_units_cgs", "# units cgs: hooke kn in dyne/cm, radii in cm, speeds in cm/s\n"
     + head().replace("units si", "units cgs").replace("0 0.04 0 0.04 0 0.1", "0 4 0 4 0 10")
     + "pair_style granular\npair_coeff * * hooke 2e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "fix grav all gravity 981 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     + TAIL + "create_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.4 density 2.5\nrun 100\n", g=100)
# ---------------------------------------------------------------- LAMMPS: partners held or moved, walls
deck("w11_fix_move_partner", "# type 2 held by fix move linear 0 0 0 (a wall made of spheres), type 1 under nve/sphere\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 0\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w12_no_integrator_type2", "# type 2 under no integrator (static spheres), type 1 under nve/sphere\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\nfix integ t1 nve/sphere\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w13_velocity_set_partner_moving", "# type 2 moved by fix move linear 0 0 -0.5 (a moving piston of spheres)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 -0.5\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w14_wallgran_contacts_kw", "# fix wall/gran with the contacts keyword (per-atom contact output)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"fix floor all wall/gran granular {HK} zplane 0 NULL contacts\n" + TAIL + TWO4 + "run 100\n", g=1)
deck("w15_wallregion_moving_block", "# fix wall/gran/region on a block region moving with a velocity (region move v_z)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable zz equal 0.001+0.5*time\nregion lid block 0 0.04 0 0.04 -1 0.001 move NULL NULL v_zz side out units box\n"
     + f"fix lidw all wall/gran/region granular {HK} region lid\n" + TAIL + TWO4 + "run 100\n", g=1)
deck("w16_wallregion_open_cylinder", "# fix wall/gran/region on a cylinder with open ends (open 1 open 2)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR
     + "region cyl cylinder z 0.02 0.02 0.015 0 0.1 side in open 1 open 2 units box\n"
     + f"fix cw all wall/gran/region granular {HK} region cyl\n" + TAIL + TWO4 + "run 100\n", g=1)
deck("w17_wallgran_limit_damping_wall_only", "# limit_damping on the wall only (strong damping), not on the pair\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 30000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV
     + "fix floor all wall/gran granular hooke 2000 30000 damping mass_velocity tangential linear_nohistory 1 0.3 limit_damping zplane 0 NULL\n"
     + TAIL + TWO4 + "run 100\n", g=1)
deck("w18_wallgran_stale_every10_checkyes", "# LAMMPS wall/gran/region under every 10 check yes (the audit calls pairs late at any speed; the wall?)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + "region bx block 0 0.04 0 0.04 0 0.08 side in units box\n"
     + f"fix wr all wall/gran/region granular {HK} region bx\n" + TAIL + TWO4 + NB + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.5 2")
deck("w19_wallgran_variable_wall_position", "# fix wall/gran zplane with a wiggle of zero amplitude (a moving wall that does not move)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"fix floor all wall/gran granular {HK} zplane 0 NULL wiggle z 0.0 0.01\n" + TAIL + TWO4 + "run 100\n", g=1)
deck("w20_freeze_after_gravity", "# type 2 frozen (fix freeze) after gravity; the audit sizes it\n"
     + BASE + TWO4 + "group t2 type 2\nfix fr t2 freeze\nrun 100\n", g=1)

# ---------------------------------------------------------------- LIGGGHTS
LB = MAT3 + E3 + HERTZ + WALL3 + ATOMS
deck("G01_neigh_in_include", "# LIGGGHTS: neighbor 1e-5 and every 20 check no in an included file (bound 0.05 m/s)\n"
     + nhead("include lists.in\n") + LB + RUN, g=1, data={"lists.in": "neighbor 1e-5 bin\nneigh_modify delay 0 every 20 check no\n"}, liggghts=True)
deck("G02_neigh_in_if", "# LIGGGHTS: stale lists from an if branch\n"
     + nhead("variable fast equal 1\nneighbor 0.002 bin\nif \"${fast} == 1\" then \"neighbor 1e-5 bin\" \"neigh_modify delay 0 every 20 check no\"\n") + LB + RUN, g=1, liggghts=True)
deck("G03_exclude_type_12", "# LIGGGHTS: neigh_modify exclude type 1 2\n"
     + nhead("neighbor 0.002 bin\nneigh_modify delay 0 exclude type 1 2\n") + LB + RUN, g=1, liggghts=True)
deck("G04_no_integrator_type2", "# LIGGGHTS: nve/sphere on type 1 only; type 2 static\n"
     + lhead() + LB + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\ngroup t1 type 1\nfix integr t1 nve/sphere\nrun 2000\n", g=1, liggghts=True)
deck("G05_move_mesh_linear_stale", "# LIGGGHTS: a mesh lid moving down at 0.5 m/s (move/mesh linear) under delay 10 skin 1e-4\n"
     + nhead("neighbor 1e-4 bin\n") + MAT3 + E3 + HERTZ + WALL3
     + "fix lid all mesh/surface file plane0.stl type 3 move 0 0 0.03\nfix wl all wall/gran model hertz tangential history mesh n_meshes 1 meshes lid\n"
     + "fix mv all move/mesh mesh lid linear 0 0 -0.5\n" + ATOMS + RUN, g="0.2 0.4", files={"plane0.stl": ("plane", "0", "0.04")}, liggghts=True)
deck("G06_clear_loop_stale", "# LIGGGHTS: pass 1 usual lists, clear, pass 2 the deck with stale lists (every 20 check no, skin 1e-5)\n"
     + lhead() + LB + RUN + "clear\n" + nhead("neighbor 1e-5 bin\nneigh_modify delay 0 every 20 check no\n") + LB + RUN, g=1, liggghts=True)
deck("G07_distribution_two_sizes", "# LIGGGHTS: insert/pack with a two-template distribution (2 and 3 mm) of type 1\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.02 0.08 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 20 region ins\n"
     + RUN, g=1, liggghts=True)
deck("G08_freeze_partner", "# LIGGGHTS: type 2 frozen (fix freeze)\n"
     + lhead() + LB + "group t2 type 2\nfix fr t2 freeze\n" + RUN, g=1, liggghts=True)
deck("G09_neigh_var_every", "# LIGGGHTS: every from an equal variable (every 20 check no, skin 1e-5)\n"
     + nhead("variable k equal 4*5\nneighbor 1e-5 bin\nneigh_modify delay 0 every ${k} check no\n") + LB + RUN, g=1, liggghts=True)
deck("G10_mesh_rotating_stale", "# LIGGGHTS: a mesh floor rotating slowly about z (move/mesh rotate) under every 5 check no, skin 1e-4\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 5 check no\n") + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + "fix rot all move/mesh mesh cad rotate origin 0 0 0 axis 0 0 1 period 10\n" + ATOMS + RUN, g="0.5 0.9 1.5",
     files={"plane0.stl": ("plane", "0", "0.04")}, liggghts=True)

# ---------------------------------------------------------------- batch 2: neighbour keywords kept between lines, units, molecules, bonds
deck("a21_units_lj_default_skin", "# units lj: LAMMPS' default skin 0.3 sigma; every 20 check no, dt 1e-4 (bound 0.3/(20 dt) = 150)\n"
     + head().replace("units si", "units lj").replace("0 0.04 0 0.04 0 0.1", "0 20 0 20 0 50")
     + "pair_style granular\npair_coeff * * hooke 2e5 30 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "fix integ all nve/sphere\ntimestep 1e-4\ncreate_atoms 1 single 10 10 5\ncreate_atoms 2 single 5 5 5\nset type 1 diameter 1 density 1\nset type 2 diameter 1 density 1\n"
     + "neigh_modify every 20 delay 0 check no\nrun 100\n", g="100 300")
deck("a22_delay_kept_from_earlier_line", "# neigh_modify delay 10, then neigh_modify every 5 check no: LAMMPS keeps delay 10 (rebuild every 10 steps, bound 1 m/s)\n"
     + BASE + TWO4 + NB + "neigh_modify delay 10\nneigh_modify every 5 check no\nrun 1000\n", g="0.8 1.5")
deck("a23_exclude_molecule_intra", "# molecule IDs from fix property/atom mol; both spheres in molecule 1; exclude molecule/intra all\n"
     + BASE + TWO4 + "fix pm all property/atom mol\nset atom * mol 1\nneigh_modify exclude molecule/intra all\nrun 1000\n", g=1)
deck("a24_bonded_pair_special_zero", "# atom_style hybrid sphere bond; spheres 1 and 2 bonded (a harmonic bond of zero stiffness); special_bonds lj 0 0 0: the bonded pair has no pair force\n"
     + head().replace("atom_style sphere 1", "atom_style hybrid sphere 1 bond").replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 1")
     + f"pair_style granular\npair_coeff * * {HK}\nbond_style harmonic\nbond_coeff 1 0.0 0.01\nspecial_bonds lj 0 0 0\n" + GRAV + FLOOR + TAIL + TWO4
     + "create_bonds single/bond 1 1 2\nrun 1000\n", g=1)
deck("a25_checkno_then_every20_separate", "# neigh_modify check no, then neigh_modify every 20 delay 0 on another line: every 20 check no (bound 0.05 with skin 1e-5)\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify check no\nneigh_modify every 20 delay 0\nrun 1000\n", g="0.04 1")
deck("a26_once_yes_then_no", "# neigh_modify once yes, then once no before the run: lists rebuilt as usual\n"
     + BASE + TWO4 + "neigh_modify once yes\nneigh_modify once no\nrun 1000\n", g=1)
deck("a27_pair_style_granular_global_cutoff", "# pair_style granular 0.01: a global cutoff beyond contact; every 20 check no, skin 1e-5\n"
     + head() + f"pair_style granular 0.01\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO4
     + "neighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 1000\n", g="0.04 1")
deck("a28_once_yes_in_include", "# neigh_modify once yes in an included settings file\n"
     + BASE + TWO4 + "include settings.in\nrun 1000\n", g=1, data={"settings.in": "neigh_modify once yes\nthermo 100\n"})
deck("a29_units_micro", "# units micro: LAMMPS' default skin 0.1 micrometre; every 20 check no, dt 1e-3 microsecond\n"
     + head().replace("units si", "units micro").replace("0 0.04 0 0.04 0 0.1", "0 400 0 400 0 1000")
     + "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "fix integ all nve/sphere\ntimestep 1e-3\ncreate_atoms 1 single 200 200 100\ncreate_atoms 2 single 100 100 100\nset type 1 diameter 40 density 2.5e-12\nset type 2 diameter 40 density 2.5e-12\n"
     + "neigh_modify every 20 delay 0 check no\nrun 100\n", g="1 10")
deck("G11_once_yes_liggghts", "# LIGGGHTS: neigh_modify once yes (lists built at the run's start only)\n"
     + nhead("neighbor 0.002 bin\nneigh_modify delay 0 once yes\n") + LB + RUN, g=1, liggghts=True)
deck("G12_every5_checkno_default_delay", "# LIGGGHTS: neigh_modify every 5 check no, no delay given: LIGGGHTS' delay 10 stays (rebuild every 10 steps, bound 1 m/s)\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify every 5 check no\n") + LB + RUN, g="0.8 1.5", liggghts=True)
deck("G13_mesh_every5_checkno_default_delay", "# LIGGGHTS: a mesh floor, neigh_modify every 5 check no (delay 10 stays): mesh half bound 0.5\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify every 5 check no\n") + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n" + ATOMS + RUN,
     g="0.45 0.8", files={"plane0.stl": ("plane", "0", "0.04")}, liggghts=True)

# ---------------------------------------------------------------- batch 3: fixes that act on the atoms beside the contact, 2d masses, cohesion
FX = head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4 + "group t1 type 1\ngroup t2 type 2\n"
deck("a30_spring_self", "# fix spring/self 100 on every atom: a spring to each atom's start point acts during contacts\n"
     + FX + "fix integ all nve/sphere\nfix ss all spring/self 100.0\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a31_addforce_type2", "# fix addforce on type 2 only (a constant force on one body of the pair 1 2)\n"
     + FX + "fix integ all nve/sphere\nfix af t2 addforce 0.0 0.0 -0.01\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a32_temp_rescale", "# fix temp/rescale every 10 steps to a temperature: rescales the spheres' velocities\n"
     + FX + "fix integ all nve/sphere\nfix tr all temp/rescale 10 1e-20 1e-20 1e-21 1.0\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a33_gravity_type2_only", "# fix gravity on type 2 only: a field on one body of the pair 1 2\n"
     + FX + "fix integ all nve/sphere\nfix grav t2 gravity 9.81 vector 0 0 -1\ntimestep 1e-5\nrun 1000\n", g="0.1 1")
deck("a34_nve_noforce_type2", "# type 2 under fix nve/noforce (moves at its velocity, no force acts): like fix move\n"
     + FX + "fix integ t1 nve/sphere\nfix nf t2 nve/noforce\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a35_nvt_sphere", "# fix nvt/sphere on every atom (a Nose-Hoover thermostat on the spheres)\n"
     + FX + "fix integ all nvt/sphere temp 1e-20 1e-20 1e-3\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a36_momentum_angular", "# fix momentum every 5 steps, linear and angular, rescale\n"
     + FX + "fix integ all nve/sphere\nfix mom all momentum 5 linear 1 1 1 angular rescale\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a37_aveforce_type2", "# fix aveforce on type 2: each type-2 atom gets the group's average force\n"
     + FX + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.004 density 2500\ngroup t2 type 2\nfix integ all nve/sphere\nfix avf t2 aveforce NULL NULL NULL\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a38_wall_reflect", "# fix wall/reflect zlo EDGE beside the granular floor at z = 0\n"
     + FX + "fix integ all nve/sphere\nfix wr all wall/reflect zlo EDGE\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a39_efield_like_addforce_variable", "# fix addforce on all with a force from an atom-style variable of the type (type 2 pushed, type 1 not)\n"
     + FX + "fix integ all nve/sphere\nvariable fz atom -0.01*(type==2)\nfix af all addforce 0.0 0.0 v_fz\ntimestep 1e-5\nrun 1000\n", g=1)
D2 = ("units si\ndimension 2\natom_style sphere 1\nboundary p p p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 -0.001 0.001 units box\ncreate_box 2 box\n"
      + f"pair_style granular\npair_coeff * * {HK}\n" + "fix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-5\n"
      + "create_atoms 1 single 0.02 0.02 0\ncreate_atoms 2 single 0.01 0.01 0\n")
deck("d01_2d_set_density", "# dimension 2, set diameter and density (LAMMPS' mass: 4/3 pi r^3 rho, or pi r^2 rho in 2d?)\n"
     + D2 + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("d02_2d_set_density_disc", "# dimension 2, set density/disc (mass pi r^2 rho)\n"
     + D2 + "set type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density/disc 2500\nrun 100\n", g=1)
deck("d03_2d_read_data", "# dimension 2, atoms read from a data file with diameter and density columns\n"
     + D2.replace("create_box 2 box\n", "").replace("region box block 0 0.04 0 0.04 -0.001 0.001 units box\n", "read_data disks.data\n")
     .replace("create_atoms 1 single 0.02 0.02 0\ncreate_atoms 2 single 0.01 0.01 0\n", "") + "run 100\n", g=1,
     data={"disks.data": "disks\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n-0.001 0.001 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.02 0\n2 2 0.006 2500 0.01 0.01 0\n"})
deck("G14_cohesion_sjkr", "# LIGGGHTS: cohesion sjkr with a cohesion energy density: an attraction during contacts\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 5e4 5e4 5e4 5e4 5e4 5e4 5e4 5e4 5e4\n"
     + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history cohesion sjkr primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G15_nve_noforce_liggghts", "# LIGGGHTS: fix freeze-like partner via fix nve/noforce on type 2\n"
     + lhead() + LB + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\ngroup t1 type 1\ngroup t2 type 2\nfix integr t1 nve/sphere\nfix nf t2 nve/noforce\nrun 2000\n", g=1, liggghts=True)

# ---------------------------------------------------------------- batch 4: labels in neigh_modify, position groups, phantom velocities, size distributions
deck("a40_labelmap_exclude", "# type labels: neigh_modify exclude type big small (the pair 1 2 by its labels)\n"
     + head() + "labelmap atom 1 big 2 small\npair_style granular\npair_coeff * * " + HK + "\n" + GRAV + FLOOR + TAIL
     + "create_atoms big single 0.02 0.02 0.01\ncreate_atoms small single 0.01 0.01 0.01\nset type big diameter 0.006 density 2500\nset type small diameter 0.004 density 2500\n"
     + "neigh_modify exclude type big small\nrun 100\n", g=1)
deck("a41_exclude_region_group", "# neigh_modify exclude group low low, low a region group (atoms below z = 0.02): pairs of two low atoms never meet\n"
     + BASE + TWO4 + "region lo block INF INF INF INF INF 0.02 units box\ngroup low region lo\nneigh_modify exclude group low low\nrun 1000\n", g=1)
deck("w21_velocity_on_unintegrated_partner", "# type 2 under no integrator but given a velocity (velocity t2 set 0.3 0.3 0.3): it never moves, yet the contact's damping reads that velocity\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nvelocity t2 set 0.3 0.3 0.3\nfix integ t1 nve/sphere\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w22_region_group_integrator", "# three type-2 spheres, nve/sphere on type 1 and on a region group holding one type-2 sphere: type 2 is integrated in part\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "create_atoms 2 single 0.03 0.03 0.05\nset type 2 diameter 0.004 density 2500\nregion up block INF INF INF INF 0.03 INF units box\ngroup upper region up\ngroup t1 type 1\n"
     + "fix integ t1 nve/sphere\nfix integ2 upper nve/sphere\ntimestep 1e-5\nrun 1000\n", g=1)
deck("G16_hookestiffness_distribution", "# LIGGGHTS: hooke/stiffness (kn, gamman per type pair) with two templates of type 1 (2 and 3 mm): eps depends on size\n"
     + lhead() + "fix m1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
     + "fix m2 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
     + "fix m3 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
     + "fix m4 all property/global gammat peratomtypepair 3 100 100 100 100 100 100 100 100 100\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
     + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.02 0.08 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 20 region ins\n"
     + RUN, g=1, liggghts=True)
deck("G17_velocity_on_unintegrated_partner", "# LIGGGHTS: type 2 under no integrator but given a velocity (velocity t2 set 0.3 0.3 0.3)\n"
     + lhead() + LB + "group t1 type 1\ngroup t2 type 2\nvelocity t2 set 0.3 0.3 0.3\ntimestep 1e-5\nfix integr t1 nve/sphere\nrun 2000\n", g=1, liggghts=True)

# ---------------------------------------------------------------- batch 5: fix move with NULL components
deck("w23_fix_move_linear_null", "# type 2 under fix move linear NULL NULL NULL: LAMMPS integrates every component like nve (a free sphere, no rotation)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear NULL NULL NULL\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w24_fix_move_linear_z_null", "# type 2 under fix move linear 0 0 NULL: held in x and y, free along z\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 NULL\ntimestep 1e-5\nrun 1000\n", g=1)
deck("w25_fix_move_wiggle_partner", "# type 2 under fix move wiggle (an oscillating particle wall)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move wiggle 0 0 0.001 0.01\ntimestep 1e-5\nrun 1000\n", g=1)

# ---------------------------------------------------------------- batch 6: respa, a gaussian size template under a size-dependent law
deck("a42_run_style_respa", "# run_style respa 2 2 with pair granular (LAMMPS stops if it cannot)\n"
     + BASE + TWO4 + "run_style respa 2 2\nrun 100\n", g=1)
HS = ("fix m1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
      "fix m2 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
      "fix m3 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
      "fix m4 all property/global gammat peratomtypepair 3 100 100 100 100 100 100 100 100 100\n"
      "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
      "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
      "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n")
deck("G18_gaussian_radius_hookestiffness", "# LIGGGHTS: hooke/stiffness with a gaussian radius template (mu 2 mm, sigma 0.4 mm), 200 particles inserted at once\n"
     + lhead() + HS
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius gaussian 0.002 0.0004\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.04 0.04 -0.04 0.04 0.01 0.14 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 200 region ins\n"
     + RUN, g=1, liggghts=True)

# ---------------------------------------------------------------- batch 7: a floor of wall particles that got the pour's velocity
deck("w26_particle_floor_with_initial_velocity", "# a floor of type-2 particles (a lattice row) and type-1 spheres above; velocity all set 0 0 -1 before the groups are chosen; only type 1 is integrated\n"
     + head().replace("create_box 2 box", "create_box 2 box") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "lattice sc 0.004 origin 0.5 0.5 0.5\nregion fl block 0 0.04 0 0.04 0 0.004 units box\ncreate_atoms 2 region fl\n"
     + "region up block 0 0.04 0 0.04 0.02 0.03 units box\ncreate_atoms 1 region up\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\n"
     + "velocity all set 0 0 -1\ngroup mobile type 1\nfix integ mobile nve/sphere\ntimestep 1e-5\nrun 2000\n", g=1)

# ---------------------------------------------------------------- batch 8: a zero-size type, coeff_restitution on hooke, LIGGGHTS dt/reset
deck("m11_zero_diameter_type2", "# type 2 spheres of diameter 0 (point particles) with a mass: pairs with them\n"
     + BASE + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.0\nset type 2 mass 1e-4\nrun 100\n", g=1)
deck("m12_coeff_restitution_on_hooke", "# hooke normal model with damping coeff_restitution (its damping parameter read as e = 0.5)\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3\n"
     + "fix floor all wall/gran granular hooke 2000 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("G19_dt_reset_liggghts", "# LIGGGHTS: timestep 1e-6, fix dt/reset up to 1e-4, every 10 check no, skin 1e-4\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 10 check no\n") + LB
     + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nfix dtr all dt/reset 1 1e-7 1e-4 0.01 units box\nrun 2000\n",
     g="0.5 2 5", liggghts=True)

deck("G20_cohesion_one_pair", "# LIGGGHTS: cohesion sjkr with a cohesion energy density on 1 1 only (0 elsewhere): the other pairs and walls are audited\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 5e4 0 0 0 0 0 0 0 0\n"
     + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history cohesion sjkr primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)

# ---------------------------------------------------------------- batch 9: two integrators of different kinds, type labels from a data file
deck("a43_nve_plus_nve_sphere", "# fix nve/sphere on all and fix nve on type 1: type 1's translation integrated twice\n"
     + FX + "fix integ all nve/sphere\nfix integ2 t1 nve\ntimestep 1e-5\nrun 1000\n", g=1)
deck("a44_nve_sphere_plus_noforce", "# fix nve/sphere and fix nve/noforce on all: positions advanced twice, velocities by the force once\n"
     + FX + "fix integ all nve/sphere\nfix nf all nve/noforce\ntimestep 1e-5\nrun 1000\n", g=1)
deck("m13_data_type_labels", "# type labels from the data file's Atom Type Labels section; pair_coeff and set by label\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data labels.data\n"
     + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff glass steel hooke 6000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "set type steel density 7800\nfix integ all nve/sphere\ntimestep 1e-5\nrun 100\n", g=1,
     data={"labels.data": "labels\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 glass\n2 steel\n\nAtoms # sphere\n\n1 glass 0.004 2500 0.02 0.02 0.01\n2 steel 0.006 2500 0.01 0.01 0.01\n"})

# ---------------------------------------------------------------- batch 10: exclusions changed between runs
deck("a45_exclude_added_stage2", "# run; neigh_modify exclude type 1 2; run: the second run never lets 1 and 2 meet\n"
     + BASE + TWO4 + "run 500\nneigh_modify exclude type 1 2\nrun 500\n", g=1)
deck("a46_exclude_removed_stage2", "# exclude type 1 2; run; neigh_modify exclude none; run: 1 2 meet in the second run only\n"
     + BASE + TWO4 + "neigh_modify exclude type 1 2\nrun 500\nneigh_modify exclude none\nrun 500\n", g=1)
deck("a47_once_yes_stage2_only", "# run with LAMMPS' lists; neigh_modify once yes; run\n"
     + BASE + TWO4 + "run 500\nneigh_modify once yes\nrun 500\n", g=1)

# ---------------------------------------------------------------- batch 11: the line's form (continuation, keyword order, once from a variable)
deck("a48_cluster_keyword_order", "# neigh_modify cluster yes check no every 20 delay 0 (keywords in another order, cluster among them), skin 1e-5\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify cluster yes check no every 20 delay 0\nrun 1000\n", g="0.04 1")
deck("a49_continuation_line", "# neigh_modify split over two lines with & (every 20 delay 0 check no), skin 1e-5\n"
     + BASE + TWO4 + "neighbor 1e-5 &\n   bin\nneigh_modify every 20 &\n   delay 0 check no\nrun 1000\n", g="0.04 1")
deck("a50_once_from_variable", "# neigh_modify once ${o} with o a string variable yes\n"
     + BASE + TWO4 + "variable o string yes\nneigh_modify once ${o}\nrun 1000\n", g=1)
deck("G21_continuation_liggghts", "# LIGGGHTS: neigh_modify split over two lines with & (delay 0 every 20 check no), skin 1e-5\n"
     + nhead("neighbor 1e-5 bin\nneigh_modify delay 0 &\n every 20 check no\n") + LB + RUN, g="0.04 1", liggghts=True)

# ---------------------------------------------------------------- batch 12: a wall sheared along its own normal
deck("w27_wallgran_shear_along_normal", "# fix wall/gran zplane with shear z 0.5: a shear along the wall's own normal (the wall does not move)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"fix floor all wall/gran granular {HK} zplane 0 NULL shear z 0.5\n" + TAIL + TWO4 + "run 100\n", g=1)
deck("G22_primitive_shear_along_normal", "# LIGGGHTS: a primitive zplane with shear z 0.5 (along its own normal)\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0 shear z 0.5\n" + ATOMS + RUN, g=1, liggghts=True)

deck("G23_mesh_surface_vel_normal", "# LIGGGHTS: a mesh floor with surface_vel 0 0 0.5 (a conveyor velocity along the face's normal; the mesh does not move)\n"
     + lhead() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3 surface_vel 0. 0. 0.5\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + ATOMS + RUN, g=1, files={"plane0.stl": ("plane", "0", "0.04")}, liggghts=True)
deck("G24_mesh_surface_vel_tangential", "# LIGGGHTS: a mesh floor with surface_vel 0.5 0 0 (a conveyor belt in the face's plane)\n"
     + lhead() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3 surface_vel 0.5 0. 0.\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + ATOMS + RUN, g=1, files={"plane0.stl": ("plane", "0", "0.04")}, liggghts=True)

deck("w28_wallgran_zcylinder_hertz", "# fix wall/gran zcylinder 0.015 (inside of a cylinder) under hertz/material viscoelastic: a curved wall with a size-dependent law\n"
     + head().replace("boundary p p f", "boundary f f f").replace("0 0.04 0 0.04 0 0.1", "-0.02 0.02 -0.02 0.02 0 0.1")
     + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.015\n" + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.006 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)

deck("w29_group_before_create_atoms", "# group mobile type 1 and fix nve/sphere on it, then more type-1 atoms made: LAMMPS' groups are sets of atoms, the new ones are in no group but all and never move\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\ngroup mobile type 1\nfix integ mobile nve/sphere\n"
     + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\ntimestep 1e-5\nrun 1000\n", g=1)

deck("x01_log_dump_restart_outside", "# writers aimed outside the folder: log, dump, restart, write_dump, print file, fix ave/time file, thermo_modify ... (canary names f17*)\n"
     + BASE + TWO4 + "log /tmp/f17_log.lammps append\ndump d1 all atom 10 /tmp/f17_dump.atom\nrestart 50 /tmp/f17_a.restart /tmp/f17_b.restart\n"
     + "print \"canary\" file /tmp/f17_print.txt\nprint \"canary\" append ../f17_up.txt\nvariable t equal time\nfix at all ave/time 1 1 10 v_t file /tmp/f17_avetime.txt\n"
     + "run 100\nwrite_dump all atom /tmp/f17_wd.atom\nwrite_data /tmp/f17_wd.data\nlog none\n", g=1)
deck("G25_liggghts_writers_outside", "# LIGGGHTS: writers aimed outside the folder (log, dump, write_restart, print file)\n"
     + lhead() + LB + "log /tmp/f17_lig.log\ndump d1 all custom 10 /tmp/f17_lig.dump id x y z\nprint \"canary\" file /tmp/f17_lig_print.txt\n" + RUN
     + "write_restart /tmp/f17_lig.restart\n", g=1, liggghts=True)


def write(name):
    text, g, files, data, lig = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=lig, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
