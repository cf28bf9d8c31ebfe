"""Field round 16: write the LAMMPS decks (decks/NAME/in.deck, G, ARGS, extra files) on round 15's header
(tests/field15/make_decks.py: head, HK, HM, TWO, TWO4, GRAV, FLOOR, TAIL). Each deck's first comment says what
it tries. usage: python make_decks16.py [NAME ...]"""
import importlib.util, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
_s = importlib.util.spec_from_file_location("md15", os.path.join(HERE, "..", "field15", "make_decks.py"))
M = importlib.util.module_from_spec(_s)
_s.loader.exec_module(M)
head, HK, HM, TWO, TWO4, GRAV, FLOOR, TAIL = M.head, M.HK, M.HM, M.TWO, M.TWO4, M.GRAV, M.FLOOR, M.TAIL
BASE = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
BASEH = head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
DECKS = {}


def deck(name, text, g=1, args=None, extra=None):
    DECKS[name] = (text, g, args, extra or {})


# ---------------------------------------------------------------- neighbour lists rebuilt every K steps
NB = "neighbor 1e-4 bin\n"
deck("n01_every10_checkyes_below", "# every 10 check yes, skin 1e-4, dt 1e-5: the audit's bound skin/(K dt) = 1 m/s; all speeds below it\n"
     + BASE + TWO4 + NB + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.05 0.1 0.3 0.5 0.9")
deck("n02_every10_checkno_near", "# every 10 check no, skin 1e-4, dt 1e-5: bound 1 m/s; speeds just below and above\n"
     + BASE + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n03_delay10_every1_checkyes_near", "# LAMMPS' older default delay 10 every 1 check yes, skin 1e-4: bound 1 m/s\n"
     + BASE + TWO4 + NB + "neigh_modify delay 10 every 1 check yes\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n04_every2_checkyes_skin2e-5", "# every 2 check yes, skin 2e-5: bound 1 m/s; speeds below\n"
     + BASE + TWO4 + "neighbor 2e-5 bin\nneigh_modify every 2 delay 0 check yes\nrun 1000\n", g="0.2 0.5 0.9")
deck("n05_once_yes", "# neigh_modify once yes: lists built once per run, never rebuilt during it\n"
     + BASE + TWO4 + "neigh_modify once yes\nrun 1000\n", g=1)
deck("n06_include_group_type1", "# neigh_modify include g1 (type 1 first): pairs of two type-2 atoms are in no list\n"
     + BASE + TWO4 + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.004 density 2500\ngroup g1 type 1\natom_modify first g1\nneigh_modify include g1\nrun 1000\n", g=1)
deck("n07_skin_cut_in_stage2", "# stage 1 default lists; stage 2 neighbor 1e-5 and every 20 check no (bound 0.05 m/s)\n"
     + BASE + TWO4 + "run 1000\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 1000\n", g=1)
deck("n08_wallgran_stale_lists", "# every 50 check no, skin 1e-5 (bound 0.02 m/s); LAMMPS' fix wall/gran uses no list: walls keep eps\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify every 50 delay 0 check no\nrun 1000\n", g=1)
deck("n09_wallregion_stale_lists", "# wall/gran/region block under every 50 check no, skin 1e-5\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + "region bx block 0 0.04 0 0.04 0 0.08 side in units box\n"
     + f"fix wr all wall/gran/region granular {HK} region bx\n" + TAIL + TWO4
     + "neighbor 1e-5 bin\nneigh_modify every 50 delay 0 check no\nrun 1000\n", g=1)
deck("n10_granhookehistory_stale", "# pair gran/hooke/history 2000 NULL 30 NULL 0.5 1, every 10 check no, skin 1e-4: bound 1 m/s\n"
     + head() + "pair_style gran/hooke/history 2000 NULL 30 NULL 0.5 1\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 2000 NULL 30 NULL 0.5 1 zplane 0 NULL\n" + TAIL + TWO4 + NB
     + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n11_hertzmaterial_stale", "# hertz/material viscoelastic, every 10 check no, skin 1e-4: bound 1 m/s\n"
     + BASEH + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n12_neigh_from_variables", "# every ${k}, skin $(1e-4): the values LAMMPS substitutes\n"
     + BASE + TWO4 + "variable k equal 10\nvariable sk equal 1e-4\nneighbor ${sk} bin\nneigh_modify every ${k} delay 0 check no\nrun 1000\n",
     g="0.5 2")
deck("n13_neigh_after_last_run", "# every 20 check no set after the last run: used by no run\n"
     + BASE + TWO4 + "run 1000\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\n", g=1)
deck("n14_skin_zero_every5", "# neighbor 0.0 bin with every 5 check no: only overlapping pairs listed at a build\n"
     + BASE + TWO4 + "neighbor 0.0 bin\nneigh_modify every 5 delay 0 check no\nrun 1000\n", g=1)
deck("n15_delay_not_multiple", "# every 3 delay 4: LAMMPS stops at the run's set-up (delay must be 0 or a multiple of every)\n"
     + BASE + TWO4 + NB + "neigh_modify every 3 delay 4 check no\nrun 1000\n", g=1)
deck("n16_loop_every_changes", "# a loop of three passes, each with every 5*i check no, skin 1e-4 (bounds 2, 1, 0.67 m/s)\n"
     + BASE + TWO4 + NB + "variable i loop 3\nlabel top\nneigh_modify every $(5*v_i) delay 0 check no\nrun 500\nnext i\njump SELF top\n",
     g="0.5 0.8 1.5")
deck("n17_every10_checkyes_partner_still", "# every 10 check yes, skin 1e-4; type 2 held still by no integrator (fix on type 1 only)\n"
     + BASE.replace("fix integ all nve/sphere\n", "") + TWO4 + "group mv type 1\nfix integ mv nve/sphere\n" + NB
     + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.3 0.6 0.9")
deck("n18_nsq_every10_checkno", "# neighbor 1e-4 nsq with every 10 check no: bound 1 m/s as bin\n"
     + BASE + TWO4 + "neighbor 1e-4 nsq\nneigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.9 1.1")
deck("n19_every1_delay5_checkno", "# every 1 delay 5 check no: rebuilt every 5 steps; skin 1e-4 -> bound 2 m/s\n"
     + BASE + TWO4 + NB + "neigh_modify every 1 delay 5 check no\nrun 1000\n", g="1.5 1.9 2.1")
deck("n20_hybrid_granular_stale", "# pair_style hybrid granular granular under every 10 check no, skin 1e-4\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff * * granular 1 {HK}\npair_coeff 2 2 granular 2 {HM}\n" + GRAV + FLOOR + TAIL
     + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.9 1.1")


# ---------------------------------------------------------------- fix set (LAMMPS 2025), atom/swap, set in loops
deck("s01_fixset_mass_unfix", "# fix set every 10 steps: type 1 mass 2e-4 from an atom-style variable (hooke reads the mass); unfix; run\n"
     + BASE + TWO + "variable mm atom 2e-4\nfix fs all set 10 0 type 1 mass v_mm\nrun 100\nunfix fs\nrun 100\n")
deck("s02_fixset_type_of_atom1", "# fix set turns atom 1 (type 1, d 4 mm) into type 2 (d 6 mm): type 2 holds two sizes, type 1 none\n"
     + BASE + TWO + "fix fs all set 10 0 atom 1 type 2\nrun 100\nunfix fs\nrun 100\n")
deck("s03_fixset_diameter_grows_in_time", "# fix set every 100 steps: type 1 diameter from an equal-style variable of time (grows during the run), kept\n"
     + BASE + TWO + "variable d equal 0.004+0.2*time\nfix fs all set 100 0 type 1 diameter v_d\nrun 1000\nrun 1000\n")
deck("s04_fixset_region_diameter", "# fix set on a region: spheres above z = 0.005 get diameter 0.005 every 10 steps; both start above, fall\n"
     + BASE + TWO4 + "region top block INF INF INF INF 0.005 INF units box\nfix fs all set 10 0 region top diameter 0.005\nrun 2000\nunfix fs\nrun 100\n")
deck("s05_fixset_type_fraction", "# fix set every 50 steps: type/fraction 2 0.5 of type 1 (random retyping), 10 type-1 spheres\n"
     + BASE + "create_atoms 1 random 10 4567 NULL overlap 0.005 maxtry 100\ncreate_atoms 2 single 0.01 0.01 0.01\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nfix fs all set 50 0 type 1 type/fraction 2 0.5 8765\nrun 200\nunfix fs\nrun 100\n")
deck("s06_set_diameter_loop", "# a loop of three passes: set type 1 diameter $(0.002+0.001*v_i), run (hertz/material reads the size)\n"
     + BASEH + TWO + "variable i loop 3\nlabel top\nset type 1 diameter $(0.002+0.001*v_i)\nrun 100\nnext i\njump SELF top\n")
deck("s07_set_mass_loop", "# a loop: set type 2 mass $(1e-4*v_i) (hooke reads the mass), run\n"
     + BASE + TWO + "variable i loop 3\nlabel top\nset type 2 mass $(1e-4*v_i)\nrun 100\nnext i\njump SELF top\n")
deck("s08_atom_swap_accepted", "# fix atom/swap types 1 2 every 10 steps, spheres apart (no energy): swaps accepted; then unfix and run\n"
     + BASE.replace("comm_modify vel yes\n", "comm_modify vel yes\natom_modify map yes\n") + TWO
     + "fix sw all atom/swap 10 1 12345 1.0 types 1 2\nrun 15\nunfix sw\nrun 100\n")
deck("s09_atom_swap_odd_count_loop", "# atom/swap every 10 steps over a loop of runs of 10: after an odd number of passes the types stand swapped\n"
     + BASE.replace("comm_modify vel yes\n", "comm_modify vel yes\natom_modify map yes\n") + TWO
     + "fix sw all atom/swap 10 1 12345 1.0 types 1 2\nvariable i loop 3\nlabel top\nrun 10\nnext i\njump SELF top\nunfix sw\nrun 100\n")
deck("s10_set_type_in_loop_by_variable", "# a loop sets type ${t} diameter, t = 1 then 2, via an index variable\n"
     + BASEH + TWO + "variable t index 1 2\nlabel top\nset type ${t} diameter 0.005\nrun 100\nnext t\njump SELF top\n")

# ---------------------------------------------------------------- rigid bodies beside other integrators
MOL = """# two-sphere clump of type 1
2 atoms

Coords

1 -0.0021 0 0
2 0.0021 0 0

Types

1 1
2 1

Diameters

1 0.004
2 0.004

Masses

1 8.377580e-05
2 8.377580e-05
"""
RIGB = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + "timestep 1e-5\n"
deck("b01_rigid_small_mol_plus_free", "# clumps of type 1 from a molecule file under fix rigid/small; free type 2 spheres under nve/sphere\n"
     + RIGB.replace("atom_style sphere 1", "atom_style sphere 1\natom_modify map array") .replace("atom_style sphere 1", "atom_style hybrid sphere 1 molecular")
     + "molecule clump clump.mol\ncreate_atoms 0 single 0.02 0.02 0.02 mol clump 4321\ncreate_atoms 0 single 0.01 0.03 0.02 mol clump 4322\n"
     + "create_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.01 0.01\nset type 2 diameter 0.006 density 2500\n"
     + "group bodies type 1\ngroup free type 2\nneigh_modify exclude molecule/intra bodies\nfix rb bodies rigid/small molecule\nfix fr free nve/sphere\nrun 500\n",
     extra={"clump.mol": MOL})
deck("b02_rigid_type_shared_with_free", "# fix rigid on two type-1 spheres (one body); a third type-1 sphere free under nve/sphere\n"
     + RIGB + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.0242 0.02 0.01\ncreate_atoms 1 single 0.01 0.01 0.03\n"
     + "create_atoms 2 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "group body id 1 2\ngroup free id 3 4\nfix rb body rigid single\nfix fr free nve/sphere\nneigh_modify exclude group body body\nrun 500\n")
deck("b03_rigid_then_unfix", "# stage 1: type 1 pairs in one rigid body; stage 2: unfix, every sphere under nve/sphere\n"
     + RIGB + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.0242 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup body type 1\ngroup free type 2\n"
     + "fix rb body rigid single\nfix fr free nve/sphere\nrun 200\nunfix rb\nunfix fr\nfix all2 all nve/sphere\nrun 200\n")
deck("b04_rigid_nve_region_group", "# fix rigid/nve on a region group (atoms in a box at the start), free spheres outside under nve/sphere\n"
     + RIGB + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.0242 0.02 0.01\ncreate_atoms 1 single 0.005 0.005 0.01\n"
     + "create_atoms 2 single 0.01 0.03 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "region rb block 0.015 0.03 0.015 0.03 0 0.02 units box\ngroup body region rb\ngroup free subtract all body\n"
     + "fix rb body rigid/nve single\nfix fr free nve/sphere\nrun 300\n")

# ---------------------------------------------------------------- averaging fixes feeding variables and ifs
AV = BASE + TWO
deck("v01_avechunk_if_stiffness", "# ave/chunk of vz by type; after the run an if on type 1's mean vz picks the stiffness\n"
     + AV + "compute ct all chunk/atom type\nfix ac all ave/chunk 10 10 100 ct vz\nrun 100\nvariable vz1 equal f_ac[1][3]\n"
     + 'if "${vz1} < -0.001" then "pair_coeff * * hooke 8000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')
deck("v02_aveatom_set_diameter", "# ave/atom of vz; after the run, diameters from an atom-style variable of it (falling spheres get 5 mm)\n"
     + BASEH + TWO + "fix aa all ave/atom 1 10 100 vz\nrun 100\nvariable dd atom 0.004+0.001*(f_aa<0)\nset group all diameter v_dd\nrun 100\n")
deck("v03_avecorrelate_if", "# ave/correlate of the kinetic energy; an if on its first correlation picks the damping\n"
     + AV + "compute ke all ke\nvariable k equal c_ke\nfix cor all ave/correlate 10 5 100 v_k\nrun 100\n"
     + 'if "$(f_cor[2][3]) > 0" then "pair_coeff * * hooke 2000 6000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')
deck("v04_fix_vector_if", "# fix vector of the mean z; an if on its last entry picks the stiffness\n"
     + AV + "variable zc equal xcm(all,z)\nfix vec all vector 10 v_zc\nrun 100\n"
     + 'if "$(f_vec[10]) < 0.01" then "pair_coeff * * hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')
deck("v05_avetime_running_loop", "# a loop until the running mean of the kinetic energy from ave/time passes a bound, then the damping changes\n"
     + AV + "compute ke all ke\nfix at all ave/time 10 10 100 c_ke ave running\nlabel top\nrun 100\n"
     + 'if "$(f_at) < 1e-7" then "jump SELF top"\npair_coeff * * hooke 2000 1500 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n')
deck("v06_avehisto_if", "# ave/histo of vz; an if on the count in its first bin picks the stiffness\n"
     + AV + "fix hh all ave/histo 10 10 100 -1 1 4 vz mode atom\nrun 100\n"
     + 'if "$(f_hh[2][3]) > 0" then "pair_coeff * * hooke 6000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')
deck("v07_avetime_file_outside", "# ave/time with file ../../../f16_avetime.txt (outside the folder), its value read after the run\n"
     + AV + "compute ke all ke\nfix at all ave/time 10 10 100 c_ke file ../../../f16_avetime.txt\nrun 100\n"
     + 'if "$(f_at) > 0" then "pair_coeff * * hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')

# ---------------------------------------------------------------- walls: moving, on groups, stale lists
deck("w01_wallgran_wiggle", "# fix wall/gran zplane with wiggle z (the floor oscillates): moving wall\n"
     + BASE.replace("zplane 0 NULL", "zplane 0 NULL wiggle z 0.0005 0.01") + TWO + "run 100\n")
deck("w02_wallgran_shear", "# fix wall/gran zplane with shear x 0.1 (the floor slides in its plane): head-on unchanged?\n"
     + BASE.replace("zplane 0 NULL", "zplane 0 NULL shear x 0.1") + TWO + "run 100\n")
deck("w03_wall_group_then_retyped", "# the floor on group g1 (type 1's atom); then atom 1 is set to type 2: the wall acts on a type-2 sphere, not on the other\n"
     + BASE.replace(FLOOR, "") + TWO + "group g1 type 1\n" + FLOOR.replace(" all ", " g1 ") + "set atom 1 type 2\nrun 100\n")
deck("w04_two_walls_disjoint_groups", "# two floors at z = 0, one on type 1 (hooke), one on type 2 (hertz/material): each sphere meets one\n"
     + BASE.replace(FLOOR, "") + TWO + "group g1 type 1\ngroup g2 type 2\n" + FLOOR.replace(" all ", " g1 ")
     + f"fix floor2 g2 wall/gran granular {HM} zplane 0 NULL\nrun 100\n")
deck("w05_wallregion_moving_normal", "# wall/gran/region of a plane region moving up at 0.05 m/s (move v_z): the floor rises into the spheres\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + TAIL + TWO
     + "variable z equal 0.05*time\nregion fl plane 0 0 0 0 0 1 move NULL NULL v_z units box\n"
     + f"fix wr all wall/gran/region granular {HK} region fl\nrun 100\n")
deck("w06_wallgran_stale_lists_and_region", "# every 100 check no, skin 1e-5 (bound 0.01 m/s), a zplane wall/gran and a region block wall at z 0.1\n"
     + BASE + TWO4 + "region roof block INF INF INF INF INF 0.1 side in units box\n"
     + f"fix wr all wall/gran/region granular {HM} region roof\nneighbor 1e-5 bin\nneigh_modify every 100 delay 0 check no\nrun 100\n")
deck("w07_wallgran_group_variable_types", "# the floor on a group defined by an atom-style variable (type == 2 by variable): named?\n"
     + BASE.replace(FLOOR, "") + TWO + "variable is2 atom type==2\ngroup g2 variable is2\n" + FLOOR.replace(" all ", " g2 ") + "run 100\n")
deck("w08_wallgran_xplane_both_sides", "# an xplane wall with lo and hi (0 and 0.04) in a periodic-free x: a wall row per face?\n"
     + head(bnd="f p f") + f"pair_style granular\npair_coeff * * {HK}\n" + f"fix xw all wall/gran granular {HM} xplane 0 0.04\n" + TAIL + TWO + "run 100\n")

deck("s02b_fixset_type_atomvar", "# fix set turns atom 1 (type 1, d 4 mm) into type 2 through an atom-style variable: type 2 two sizes, type 1 none\n"
     + BASE + TWO + "variable t2 atom 2\nfix fs all set 10 0 atom 1 type v_t2\nrun 100\nunfix fs\nrun 100\n")
deck("s03b_fixset_diameter_atomvar_time", "# fix set every 100 steps: type 1 diameter from an atom-style variable of time (grows during the run), kept\n"
     + BASE + TWO + "variable d atom 0.004+0.2*time\nfix fs all set 100 0 type 1 diameter v_d\nrun 1000\nrun 1000\n")
deck("s04b_fixset_region_diameter_atomvar", "# fix set on a region: spheres above z = 0.005 get diameter 0.005 every 10 steps; both start above and fall\n"
     + BASE + TWO4 + "region top block INF INF INF INF 0.005 INF units box\nvariable d5 atom 0.005\nfix fs all set 10 0 region top diameter v_d5\nrun 2000\nunfix fs\nrun 100\n")
deck("s11_fixset_density_never_unfixed", "# fix set density 4000 on type 2 every 10 steps, never unfixed; two runs\n"
     + BASE + TWO + "variable rho atom 4000\nfix fs all set 10 0 type 2 density v_rho\nrun 100\nrun 100\n")
deck("v01b_avechunk_if_stiffness", "# ave/chunk of vz by type; after the run an if on type 1's mean vz (column 2) picks the stiffness\n"
     + AV + "compute ct all chunk/atom type\nfix ac all ave/chunk 10 10 100 ct vz\nrun 100\nvariable vz1 equal f_ac[1][2]\n"
     + 'if "${vz1} < -0.001" then "pair_coeff * * hooke 8000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')
deck("v06b_avehisto_if", "# ave/histo of the per-atom vz; an if on the count in its second bin picks the stiffness\n"
     + AV + "fix hh all ave/histo 10 10 100 -1 1 4 vz\nrun 100\n"
     + 'if "$(f_hh[2][3]) > 0" then "pair_coeff * * hooke 6000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\nrun 100\n')

deck("s03c_fixset_diameter_grows_hertz", "# as s03b under hertz/material (the size enters eps): fix set diameter from time every 100 steps, never unfixed\n"
     + BASEH + TWO + "variable d atom 0.004+0.2*time\nfix fs all set 100 0 type 1 diameter v_d\nrun 1000\nrun 1000\n")


# ---------------------------------------------------------------- the sandbox
deck("x01_jump_to_file_with_shell", "# jump to another file beside the deck, which runs shell, print to a file above, write_data to /tmp and a run\n"
     + BASE + TWO + "jump part2.in\n",
     extra={"part2.in": "shell touch f16_jumped.txt\nprint \"x\" file ../../f16_jump_print.txt\nwrite_data /tmp/f16_jump.data\nrun 100\n"})
deck("x02_include_proc_environ", "# include /proc/self/environ (a file of size 0 that reads the environment)\n"
     + BASE + TWO + "include /proc/self/environ\nrun 100\n")
deck("x03_variable_python", "# a python-style variable whose function writes /tmp/f16_pyvar.txt, used in pair_coeff\n"
     + BASE + TWO + 'python f return v_p format f here """\ndef f():\n    open("/tmp/f16_pyvar.txt", "w").write("x")\n    return 2000.0\n"""\n'
     + "variable p python f\npair_coeff * * hooke ${p} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("x04_molecule_dev_zero_absolute", "# molecule file /dev/zero by its absolute path\n" + BASE + TWO + "molecule m /dev/zero\nrun 100\n")
deck("x05_write_restart_parent_then_read", "# write_restart ../f16_parent.restart, clear, read_restart of it, new coefficients\n"
     + BASE + TWO + "run 100\nwrite_restart ../f16_parent.restart\nclear\nread_restart ../f16_parent.restart\n"
     + "pair_style granular\npair_coeff * * hooke 3000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "fix integ all nve/sphere\ncomm_modify vel yes\nrun 100\n")
deck("x06_shell_putenv_getenv", "# shell putenv F16K=4000 (a builtin the engine does), then a getenv variable in pair_coeff\n"
     + BASE + TWO + "shell putenv F16K=4000\nvariable k getenv F16K\npair_coeff * * hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("x07_include_self_recursion", "# include loop.in, which includes itself: LAMMPS' own nesting limit\n"
     + BASE + TWO + "include loop.in\nrun 100\n", extra={"loop.in": "include loop.in\n"})
deck("x08_infinite_jump_loop", "# label and jump SELF for ever, no run: the engine by hand never ends\n"
     + BASE + TWO + "label spin\nvariable a equal 1\njump SELF spin\nrun 100\n", args="--budget 5")
deck("x09_fix_ave_time_file_proc", "# fix ave/time with its file in /proc/self/fd/1 and a fix print to /dev/full\n"
     + BASE + TWO + "compute ke all ke\nfix at all ave/time 10 10 100 c_ke file /proc/self/fd/1\nfix pr all print 10 \"x\" file /dev/full\nrun 100\n")
deck("x10_include_dotdot_chain", "# include ../../../etc/hostname (four folders up by ..)\n" + BASE + TWO + "include ../../../../etc/hostname\nrun 100\n")
deck("x11_read_dump_of_own_dump_via_rerun", "# rerun of a dump the deck names (rerun is skipped): then run\n"
     + BASE + TWO + "rerun nothere.dump dump x y z\nrun 100\n")
deck("x12_fix_print_file_then_include", "# fix print writes a pair_coeff line to f16p.in during a run; the deck then includes it\n"
     + BASE + TWO + 'fix pr all print 1 "pair_coeff * * hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3" file f16p.in screen no\nrun 1\nunfix pr\ninclude f16p.in\nrun 100\n')

deck("n21_every5_checkyes_default_skin", "# a usual-looking deck: default skin (1 mm in si), neigh_modify every 5 delay 0 check yes: audit's bound 20 m/s\n"
     + BASE + TWO4 + "neigh_modify every 5 delay 0 check yes\nrun 1000\n", g=1)
deck("n22_every2_delay10_checkyes", "# neigh_modify every 2 delay 10 check yes, skin 1e-4: audit's bound skin/(10 dt) = 1 m/s\n"
     + BASE + TWO4 + NB + "neigh_modify every 2 delay 10 check yes\nrun 1000\n", g="0.3 0.6 0.9")

deck("t01_timestep_raised_stage2", "# run 1 at dt 1e-5, then timestep 1e-4 (contact settings unchanged), run 2: 4.7 steps per contact there\n"
     + BASE + TWO4 + "run 1000\ntimestep 1e-4\nrun 1000\n", g=1)
deck("t02_timestep_raised_with_stale_lists", "# every 10 check no, skin 1e-4, run 1 at dt 1e-6 (bound 10 m/s); timestep 1e-5 for run 2 (bound 1 m/s)\n"
     + BASE.replace("timestep 1e-5", "timestep 1e-6") + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\ntimestep 1e-5\nrun 1000\n", g="0.5 2 5")

deck("s12_fixset_mass_beyond_step_budget", "# fix set type 1 mass 2e-4 every 10 steps in a run of 2e7 steps (beyond the audit's 1e7), unfix, run\n"
     + BASE + TWO + "variable mm atom 2e-4\nfix fs all set 10 0 type 1 mass v_mm\nrun 20000000\nunfix fs\nrun 100\n")
deck("s13_atom_swap_beyond_step_budget", "# atom/swap types 1 2 every 10 steps in a run of 2e7+5 steps (beyond 1e7), unfix, run\n"
     + BASE.replace("comm_modify vel yes\n", "comm_modify vel yes\natom_modify map yes\n") + TWO
     + "fix sw all atom/swap 10 1 12345 1.0 types 1 2\nrun 20000005\nunfix sw\nrun 100\n")

deck("n23_hertzmaterial_every10_checkyes", "# hertz/material viscoelastic, every 10 delay 0 check yes, skin 1e-4 (audit's bound 1 m/s)\n"
     + BASEH + TWO4 + NB + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.1 0.5")
deck("n24_granhertzhistory_every10_checkyes", "# pair gran/hertz/history 2e7 NULL 3000 NULL 0.5 1, every 10 delay 0 check yes, skin 1e-4 (bound 1 m/s)\n"
     + head() + "pair_style gran/hertz/history 2e7 NULL 3000 NULL 0.5 1\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hertz/history 2e7 NULL 3000 NULL 0.5 1 zplane 0 NULL\n" + TAIL + TWO4 + NB
     + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.1 0.5")

deck("p01_rolling_none_twisting_none", "# pair_coeff and wall with rolling none and twisting none (LAMMPS 2025 accepts none for either)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK} rolling none twisting none\n" + GRAV
     + f"fix floor all wall/gran granular {HK} rolling none twisting none zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("p02_damping_none_heat_none", "# hooke with damping none (LAMMPS: no normal damping) and heat none on the pair\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 0 damping none tangential linear_nohistory 1 0.3 heat none\n" + GRAV
     + "fix floor all wall/gran granular hooke 2000 0 damping none tangential linear_nohistory 1 0.3 zplane 0 NULL\n" + TAIL + TWO + "run 100\n")

deck("x13_shell_rm_mv_mkdir_outside", "# shell builtins aimed at real files: rm a file beside the deck and one in a sibling deck folder, mv the deck,\n"
     "# mkdir above; then run. The files must still be there after the audit.\n"
     + BASE + TWO + "shell rm victim.txt\nshell rm ../x12_fix_print_file_then_include/G\nshell mkdir ../../f16_made_dir\nshell mv in.deck gone.deck\nrun 100\n",
     extra={"victim.txt": "keep me\n"})

deck("n25_run_every_neigh_modify", "# run 1000 every 500 \"neigh_modify every 10 delay 0 check no\": from the second part on lists every 10 steps (bound 1)\n"
     + BASE + TWO4 + NB + 'run 1000 every 500 "neigh_modify every 10 delay 0 check no"\n', g="0.5 2")
deck("n26_if_branch_neigh_after_count", "# after a run, an if on a count sets every 20 check no and skin 1e-5 (bound 0.05); run 2 with the same contact\n"
     + BASE + TWO4 + 'run 100\nvariable n equal count(all)\nif "${n} > 1" then "neighbor 1e-5 bin" "neigh_modify every 20 delay 0 check no"\nrun 1000\n', g=1)

deck("x14_write_data_into_usr_then_read", "# write_data /usr/f16_x14.data, clear, read_data of it (a system folder the view binds read-only)\n"
     + BASE + TWO + "run 10\nwrite_data /usr/f16_x14.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n"
     + "read_data /usr/f16_x14.data\npair_style granular\npair_coeff * * hooke 3000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     + "fix integ all nve/sphere\ntimestep 1e-5\nrun 10\n")

deck("n27_cutoff_keyword_widens_lists", "# pair_coeff ... cutoff 0.006 (contact at 0.004): lists hold pairs within cutoff + skin; every 10 check no, skin 1e-4\n"
     + head() + f"pair_style granular\npair_coeff * * {HK} cutoff 0.006\n" + GRAV + FLOOR + TAIL + TWO4 + NB
     + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 2 5")


def write(name):
    text, g, args, extra = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, args=args, data=extra)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
