"""Field round 14: write the LAMMPS decks (decks/NAME/in.deck, G, ARGS) from a shared header.
Each deck's first comment says what it tries. usage: python make_decks.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import FLOOR, GRAV, HK, HM, TAIL, TWO  # noqa: E402  (the same lines as there)

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
JKR = "jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
DMT = "dmt 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"


def head(ntypes=2, box="0 0.04 0 0.04 0 0.1", bnd="p p f", style="sphere"):
    return f"""units si
atom_style {style}
boundary {bnd}
comm_modify vel yes
region box block {box} units box
create_box {ntypes} box
"""


THREE = TWO + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2000\n"

DECKS = {}


def deck(name, text, g=1, args=None, extra=None):
    DECKS[name] = (text, g, args, extra or {})


# ---------------------------------------------------------------- partial audits (unmapped lines)
deck("p01_star_after_jkr_overrides", "# An unmapped jkr line for 1 2, then pair_coeff * * again: LAMMPS' last line wins for every pair\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\npair_coeff 1 2 {JKR}\n"
     f"pair_coeff * * hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p02_range_jkr_then_specific", "# 1 * jkr over three types, then 1 1 given a mapped line again: 1 1 mapped (5000), 1 2 and 1 3 not\n"
     + head(3) + f"pair_style granular\npair_coeff * * {HK}\npair_coeff 1 * {JKR}\n"
     "pair_coeff 1 1 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + THREE + "run 1000\n")
deck("p03_labels_reversed_dmt", "# type labels; the unmapped dmt line names its pair by labels in reverse order (steel glass = 2 1)\n"
     + head() + "labelmap atom 1 glass 2 steel\npair_style granular\n"
     f"pair_coeff glass glass {HK}\npair_coeff steel steel hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     f"pair_coeff steel glass {DMT}\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p04_hybrid_instances_jkr_22", "# hybrid of two granular instances: * * to instance 1, then 2 2 to instance 2 with jkr: 2 2 not audited, 1 1 / 1 2 from instance 1\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff * * granular 1 {HK}\n"
     f"pair_coeff 2 2 granular 2 {JKR}\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p04b_hybrid_instances_mapped_22", "# hybrid of two granular instances: * * to instance 1 (hooke 2000), 2 2 to instance 2 (hooke 5000)\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff * * granular 1 {HK}\n"
     "pair_coeff 2 2 granular 2 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p12_mixed_from_unmapped_jkr", "# 1 1 jkr with cohesion 0.5 (unmapped), 2 2 jkr with cohesion 0 (mapped as hertz/material), 1 2 left to LAMMPS' mixing\n"
     + head() + "pair_style granular\n"
     f"pair_coeff 1 1 {JKR}\npair_coeff 2 2 jkr 2e7 3000 0.3 0 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV
     + "fix floor all wall/gran granular hertz/material 1e7 3000 0.3 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n" + TAIL + TWO + "run 1000\n")
deck("p04c_hybrid_jkr_then_star_reassigns", "# hybrid of two granular instances: 2 2 to instance 2 (jkr) first, then * * to instance 1 (hooke 2000) takes 2 2 back\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff 2 2 granular 2 {JKR}\npair_coeff * * granular 1 {HK}\n"
     + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p05_cutoff_keyword_near_contact", "# pair_coeff cutoff keyword: 1 1 cutoff 0.0039 (+ skin 0.001 covers contact at 0.004); 2 2 cutoff 0.001 (contact at 0.006 seen late)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n"
     f"pair_coeff 1 1 {HK} cutoff 0.0039\npair_coeff 2 2 {HK} cutoff 0.001\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p06_range_rule_empty_second", "# pair_coeff 2*3 1*2 jkr sets only 2 2 (j from max(jlo,i)); 1 2, 2 3 stay hooke; then * 1 hooke 3000 sets only 1 1\n"
     + head(3) + f"pair_style granular\npair_coeff * * {HK}\npair_coeff 2*3 1*2 {JKR}\n"
     "pair_coeff * 1 hooke 3000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + THREE + "run 1000\n")
deck("p07_jkr_then_later_mapped_same_pair", "# 1 2 jkr in a first stage, then 1 2 hooke 6000 for a second stage: stage 1 names 1 2, stage 2 audits it\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\npair_coeff 1 2 {JKR}\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n"
     "pair_coeff 1 2 hooke 6000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 1000\n")
deck("p08_dmt_22_limit_damping_others", "# hertz/material with limit_damping for * *, then 2 2 dmt (LAMMPS refuses limit_damping with dmt, so none there)\n"
     + head() + f"pair_style granular\npair_coeff * * {HM} limit_damping\npair_coeff 2 2 {DMT}\n" + GRAV
     + f"fix floor all wall/gran granular {HM} limit_damping zplane 0 NULL\n" + TAIL + TWO + "run 1000\n")

deck("p09_hybrid_granular_and_granhooke_jkr11", "# hybrid of granular (jkr for 1 1) and the older gran/hooke/history (every other pair)\n"
     + head() + "pair_style hybrid granular gran/hooke/history 2000 NULL 3000 NULL 0.3 1\npair_coeff * * gran/hooke/history\n"
     f"pair_coeff 1 1 granular {JKR}\n" + GRAV + FLOOR + TAIL + TWO + "run 1000\n")
deck("p10_labels_star_with_label_jkr", "# type labels; pair_coeff * c (a star with a label): 1 3, 2 3, 3 3 get the unmapped jkr line\n"
     + head(3) + "labelmap atom 1 a 2 b 3 c\npair_style granular\n"
     f"pair_coeff * * {HK}\npair_coeff * c {JKR}\n" + GRAV + FLOOR + TAIL + THREE + "run 1000\n")
deck("p11_data_pairij_jkr_row", "# read_data with a PairIJ Coeffs section: 1 2 is jkr there, a later pair_coeff 1 1 overrides one row\n"
     + """units si
atom_style sphere
boundary p p f
comm_modify vel yes
pair_style granular
read_data data.p11
pair_coeff 1 1 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
""" + GRAV + FLOOR + TAIL + "run 1000\n",
     extra={"data.p11": """p11

2 atoms
2 atom types

0 0.04 xlo xhi
0 0.04 ylo yhi
0 0.1 zlo zhi

PairIJ Coeffs # granular

1 1 hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
1 2 jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3
2 2 hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3

Atoms # sphere

1 1 0.004 2500 0.02 0.02 0.01
2 2 0.006 2500 0.01 0.01 0.01
"""})

# ---------------------------------------------------------------- runs made for real
ADAPT_BASE = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + """create_atoms 1 single 0.02 0.02 0.01
create_atoms 2 single 0.01 0.01 0.01
set type 1 diameter 0.004 density 2500
set type 2 diameter 0.004 density 2500
"""
deck("r01_adapt_diameter_mass_no", "# fix adapt diameter with mass no, reset no: radii grow to 0.003, masses stay those of d 0.004\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable dgrow equal 0.004+0.02*time\n"
     "fix ad all adapt 1 atom diameter v_dgrow reset no mass no\nrun 10000\nunfix ad\nrun 100\n")
deck("r02_adapt_diameter_scale_yes", "# fix adapt diameter scale yes (a factor 1 -> 1.5), reset no: radii 0.003 after the run\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable s equal 1+5*time\n"
     "fix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("r02b_adapt_scale_constant", "# fix adapt diameter scale yes by a constant 1.5, reset no, then unfix: radii 0.003 after the first run\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable s equal 1.5\n"
     "fix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 1000\nunfix ad\nrun 100\n")
deck("r06_adapt_fep_diameter", "# fix adapt/fep (FEP package) grows type 2's diameter by a time ramp, reset no\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable dgrow equal 0.004+0.02*time\n"
     "fix af all adapt/fep 1 atom diameter 2 v_dgrow reset no\nrun 10000\nunfix af\nrun 100\n")
deck("r07_adapt_pair_granular", "# fix adapt on a pair granular coefficient (does LAMMPS allow it?)\n"
     + ADAPT_BASE + "variable kk equal 2000+1e5*time\nfix ap all adapt 1 pair granular kn 1 1 v_kk reset no\nrun 1000\nunfix ap\nrun 100\n")
deck("r16_ramp_between_runs", "# a diameter from ramp() read between runs: LAMMPS ramps over the previous run, so after it the value is the end one\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "variable d equal ramp(0.004,0.002)\nrun 10000\nset type 1 diameter ${d}\nrun 100\n")
deck("r17_vdisplace_swiggle_between_runs", "# a density from vdisplace() and a stiffness from swiggle() read after the run (both use the time since the run began)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "variable rho equal vdisplace(1000,50000)\nvariable k equal swiggle(2000,1500,0.4)\nrun 10000\nset type 1 density ${rho}\n"
     "pair_coeff * * hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("r18_adapt_ramp_growth", "# growth by ramp(): diameter from ramp(0.004,0.006) over the run, reset no, then unfix and run\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable dgrow equal ramp(0.004,0.006)\n"
     "fix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("r19_adapt_ramp_no_unfix", "# ramp growth with fix adapt left defined over two runs (LAMMPS ramps again in the second run)\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable dgrow equal ramp(0.004,0.006)\n"
     "fix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\nrun 100\n")
deck("r20_adapt_elapsed_growth", "# fix adapt growth by elapsed (steps since the run began), reset no, then unfix and run\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "variable dgrow equal 0.004+2e-7*elapsed\n"
     "fix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("r03_adapt_group_type2_only", "# fix adapt on a type-2 group only, reset no: type 2 grows to 0.006, type 1 stays\n"
     + ADAPT_BASE.replace("atom_style sphere", "atom_style sphere 1") + "group g2 type 2\nvariable dgrow equal 0.004+0.02*time\n"
     "fix ad g2 adapt 1 atom diameter v_dgrow reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("r08_deform_lz_sets_diameter", "# fix deform halves the box height during the run; then the diameter is read from lz\n"
     + head(bnd="p p f") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "fix df all deform 1 z final 0 0.05\nrun 10000\nunfix df\nset type 1 diameter $(0.08*lz)\nrun 100\n")
deck("r09_bound_zmax_sets_density", "# after a fall, the density is read from bound(all,zmax)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "run 20000\nvariable rho equal 1000+1e5*bound(all,zmax)\nset type 1 density ${rho}\nrun 100\n")
deck("r10_ave_time_value_read", "# a fix ave/time's value (kinetic energy) read after the run into an if that changes a density\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "velocity all set 0 0 -1\ncompute k all ke\nfix at all ave/time 100 1 100 c_k\nrun 30000\n"
     'if "$(f_at) < 1e-7" then "set type 1 density 1000" else "set type 1 density 8000"\nrun 100\n')
deck("r11_temp_read_if", "# thermo temp read after the run (not ke): settled spheres have a small temp, the pass's the initial one\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "velocity all set 0 0 -1\nthermo_style custom step temp ke\nrun 30000\n"
     'if "$(temp) < 1e12" then "set type 1 density 1000" else "set type 1 density 8000"\nrun 100\n')
deck("r12_compute_ke_read_if", "# a compute's value (c_k, kinetic energy) read after the run\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "velocity all set 0 0 -1\ncompute k all ke\nthermo_style custom step c_k\nrun 30000\n"
     'if "$(c_k) < 1e-7" then "set type 1 density 1000" else "set type 1 density 8000"\nrun 100\n')
deck("r13_dt_reset_then_coeff_from_dt", "# fix dt/reset changes dt during the run; the stiffness of the next stage is read from dt\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "velocity all set 0 0 -1\nfix dtr all dt/reset 10 1e-7 1e-4 1e-5 units box\nrun 5000\nunfix dtr\n"
     "variable k equal 2000*1e-5/dt\npair_coeff * * hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("r14_vcm_read_if", "# the centre of mass velocity read after the run (group function vcm)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "velocity all set 0 0 -1\nrun 30000\n"
     'if "$(abs(vcm(all,z))) < 1e-4" then "set type 1 density 1000" else "set type 1 density 8000"\nrun 100\n')
deck("r15_deform_vol_if", "# fix deform shrinks the box; an if on vol after the run picks the density\n"
     + head(bnd="p p f") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "fix df all deform 1 x final 0 0.02 remap x\nrun 5000\nunfix df\n"
     'if "$(vol) < 1.2e-4" then "set type 1 density 1000" else "set type 1 density 8000"\nrun 100\n')

# ---------------------------------------------------------------- walls
deck("w01_zplane_lo_hi_one_fix_narrow", "# one fix, zplane 0 0.0041: its two faces are 0.0041 apart, a sphere of d 0.004 between them\n"
     + head(box="0 0.04 0 0.04 -0.001 0.01") + f"pair_style granular\npair_coeff * * {HK}\n"
     + f"fix w all wall/gran granular {HK} zplane 0 0.0041\n" + TAIL
     + "create_atoms 1 single 0.02 0.02 0.00205\nset type 1 diameter 0.004 density 2500\nvelocity all set 0 0 -0.5\nrun 2000\n", g=1)
deck("w02_yplane_hele_shaw_two_fixes", "# a quasi-2d cell: two yplane walls in two fixes, 0.0042 apart, spheres of d 0.004\n"
     + head(box="0 0.04 -0.003 0.003 0 0.1", bnd="p f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + f"fix wy1 all wall/gran granular {HK} yplane -0.0021 NULL\nfix wy2 all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 yplane NULL 0.0021\n"
     + GRAV + FLOOR + TAIL + "create_atoms 1 single 0.02 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 2000\n", g=1)
deck("w03_region_sphere_side_out_hertz", "# a ball obstacle: sphere region side out, hertz/material viscoelastic (reads the effective radius)\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region ball sphere 0 0 0 0.01 side out units box\n"
     + f"fix wb all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0.02\nset type 1 diameter 0.004 density 2500\nvelocity all set 0 0 -0.5\nrun 2000\n")
deck("w03b_region_sphere_side_out_coarse_dt", "# w03's ball obstacle (sphere region side out, hertz/material) at dt 1e-4 (few steps per contact)\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region ball sphere 0 0 0 0.01 side out units box\n"
     + f"fix wb all wall/gran/region granular {HM} region ball\n" + "fix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 0 0 0.02\nset type 1 diameter 0.004 density 2500\nvelocity all set 0 0 -0.5\nrun 200\n")
deck("w04b_zcylinder_coarse_dt", "# a zcylinder wall (R 0.0075) met from inside, hertz/material, at dt 1e-4\n"
     + head(box="-0.012 0.012 -0.012 0.012 0 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.0075\n" + "fix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 0 0 0.01\nset type 1 diameter 0.004 density 2500\nvelocity all set 0.5 0 0\nrun 200\n")
deck("w04_zcylinder_and_floor_edge", "# a zcylinder wall (R 0.01) and a zplane floor meet at an edge; hertz walls\n"
     + head(box="-0.012 0.012 -0.012 0.012 0 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.01\nfix floor all wall/gran granular {HM} zplane 0 NULL\n" + GRAV + TAIL
     + "create_atoms 1 single 0.0079 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 2000\n")
deck("w05_block_region_open_face_and_floor", "# a block region wall with its top open, and a separate floor 1e-4 above its bottom face\n"
     + head(box="-0.02 0.02 -0.02 0.02 -0.001 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + "region cup block -0.015 0.015 -0.015 0.015 0 0.04 open 6 units box\n"
     + f"fix wc all wall/gran/region granular {HK} region cup\n"
     + f"fix floor all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 1e-4 NULL\n" + GRAV + TAIL
     + "create_atoms 1 single 0 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 2000\n")
deck("w06_annulus_region_side_out_in_zcylinder", "# a Taylor-Couette gap: cylinder region side out (R 0.008) inside a zcylinder wall (R 0.0115): gap 0.0035 < d 0.004\n"
     + head(box="-0.012 0.012 -0.012 0.012 0 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region inner cylinder z 0 0 0.008 -1 1 side out units box\n"
     + f"fix wi all wall/gran/region granular {HM} region inner\nfix wo all wall/gran granular hertz/material 2e7 0.5 0.3 damping viscoelastic tangential linear_nohistory 1 0.3 zcylinder 0.0115\n" + TAIL
     + "create_atoms 1 single 0.00975 0 0.01\nset type 1 diameter 0.0035 density 2500\nrun 2000\n")
deck("w07_inclined_plane_region_meets_floor", "# a plane region inclined 45 degrees meets the floor at an edge (x = 0); hooke walls\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + "region slope plane 0 0 0 -0.70710678 0 0.70710678 side in units box\n"
     + f"fix ws all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region slope\n" + FLOOR + GRAV + TAIL
     + "create_atoms 1 single 0.005 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 2000\n")
deck("w08_wall_on_region_group", "# a wall on a group picked by region at the start (left half), floor for all\n"
     + head(box="0 0.04 0 0.04 0 0.1") + f"pair_style granular\npair_coeff * * {HK}\n"
     + TWO + "region left block 0 0.015 INF INF INF INF units box\ngroup gl region left\n"
     + f"fix wl gl wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     + f"fix wr all wall/gran granular {HK} zplane 0 NULL\n" + GRAV + TAIL + "run 1000\n")

deck("w09_plane_region_side_out_flipped_near_floor", "# a plane region with normal -z and side out (its wall faces +z) at z = 1e-4, over a zplane floor at 0\n"
     + head(box="-0.02 0.02 -0.02 0.02 -0.001 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + "region fl plane 0 0 1e-4 0 0 -1 side out units box\n"
     + "fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region fl\n"
     + FLOOR + TAIL + "create_atoms 1 single 0 0 0.01\nset type 1 diameter 0.004 density 2500\nvelocity all set 0 0 -0.5\nrun 2000\n")
deck("w10_block_side_out_top_near_floor", "# a block region side out (an obstacle slab from z = -0.01 to 1e-4) as a wall, over a zplane floor at 0\n"
     + head(box="-0.02 0.02 -0.02 0.02 -0.011 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + "region slab block -0.015 0.015 -0.015 0.015 -0.01 1e-4 side out units box\n"
     + "fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region slab\n"
     + FLOOR + TAIL + "create_atoms 1 single 0 0 0.01\nset type 1 diameter 0.004 density 2500\nvelocity all set 0 0 -0.5\nrun 2000\n")

deck("w11_jkr_wall_same_plane_as_floor", "# a jkr wall (not mapped) at the same zplane 0 as an audited hooke floor, both on all atoms\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR
     + f"fix wj all wall/gran granular {JKR} zplane 0 NULL\n" + TAIL + TWO + "run 1000\n")
deck("w12_wall_on_id_group_same_plane", "# a second floor at the same zplane 0 on a group defined by atom id (holding the type-2 atom)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "group g2 id 2\nfix wg g2 wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\nrun 1000\n")

deck("w13_moving_plane_region_same_plane", "# a plane region at z = 0 that 'moves' by a variable that stays 0, as a wall, beside the zplane floor at 0\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR
     + "variable zero equal 0*time\nregion pl plane 0 0 0 0 0 1 side in move NULL NULL v_zero units box\n"
     + "fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region pl\n"
     + TAIL + TWO + "run 1000\n")
deck("w14_wiggling_floor_same_plane", "# a second zplane floor at 0 that wiggles by 1e-6 in z, beside the still floor at 0\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR
     + "fix ww all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL wiggle z 1e-6 0.1\n"
     + TAIL + TWO + "run 1000\n")

deck("w15_oscillating_plane_region_hooke", "# the only floor is a plane region oscillating in z (amplitude 0.5 mm, period 10 ms) by a move variable; hooke wall law\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable zw equal 0.0005*sin(2*PI*time/0.01)\nregion pl plane 0 0 0 0 0 1 side in move NULL NULL v_zw units box\n"
     + "fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region pl\n"
     + TAIL + TWO + "run 1000\n")

deck("w15b_oscillating_plane_region_hertz", "# w15 with a hertz/material wall law (which reads the effective radius)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable zw equal 0.0005*sin(2*PI*time/0.01)\nregion pl plane 0 0 0 0 0 1 side in move NULL NULL v_zw units box\n"
     + f"fix rw all wall/gran/region granular {HM} region pl\n"
     + TAIL + TWO + "run 1000\n")

deck("w16_block_open_bottom_on_floor", "# a block region wall whose bottom face (5) is open, standing on a zplane floor at its bottom z = 0\n"
     + head(box="-0.02 0.02 -0.02 0.02 -0.001 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n"
     + "region cup block -0.015 0.015 -0.015 0.015 0 0.04 open 5 units box\n"
     + f"fix wc all wall/gran/region granular {HK} region cup\n"
     + "fix floor all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n" + GRAV + TAIL
     + "create_atoms 1 single 0 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 2000\n")

deck("w17_rocking_plane_region_hooke", "# the floor is a plane region rocked about the y axis (rotate by v_th, 0.05 rad amplitude, period 10 ms); hooke wall law\n"
     + head(box="-0.02 0.02 -0.02 0.02 -0.01 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable th equal 0.05*sin(2*PI*time/0.01)\nregion pl plane 0 0 0 0 0 1 side in rotate v_th 0 0 0 0 1 0 units box\n"
     + "fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region pl\n"
     + TAIL + "create_atoms 1 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nrun 1000\n")

# ---------------------------------------------------------------- particle properties
deck("q01_mass_cmd_on_sphere", "# mass command on atom_style sphere after set density\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO + "mass 1 1.0\nmass 2 1.0\nrun 1000\n")
deck("q02_hybrid_sphere_bond_read_data", "# atom_style hybrid bond sphere, read_data with molecule before diameter/density\n"
     + """units si
atom_style hybrid bond sphere
boundary p p f
comm_modify vel yes
read_data data.q02
""" + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + "run 1000\n",
     extra={"data.q02": """q02

2 atoms
2 atom types
0 bond types

0 0.04 xlo xhi
0 0.04 ylo yhi
0 0.1 zlo zhi

Atoms # hybrid

1 1 0.02 0.02 0.01 1 0.004 2500
2 2 0.01 0.01 0.01 2 0.006 1000
"""})
deck("q03_set_mass_then_diameter", "# set mass, then set diameter: does LAMMPS keep the mass or the density?\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "set type 1 mass 1e-4\nset type 1 diameter 0.005\nrun 1000\n")

deck("q04_hybrid_sphere_bond_mass_cmd", "# atom_style hybrid sphere bond: the mass command is allowed (per-type masses, which LAMMPS does not use)\n"
     + head(style="hybrid sphere bond") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO + "mass * 1.0\nrun 1000\n")

# ---------------------------------------------------------------- time step
deck("t01_hertzmat_two_sizes_coarse_dt", "# hertz/material viscoelastic, two sizes, about 10 steps per contact\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV
     + f"fix floor all wall/gran granular {HM} zplane 0 NULL\nfix integ all nve/sphere\ntimestep 2e-4\n" + TWO + "run 100\n")
deck("t02_tsuji_unequal_masses_coarse_dt", "# hooke with tsuji damping, unequal masses, limit_damping, about 8 steps per contact\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 limit_damping\n" + GRAV
     + "fix floor all wall/gran granular hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 limit_damping zplane 0 NULL\nfix integ all nve/sphere\ntimestep 4e-4\n"
     + TWO.replace("0.006 density 2500", "0.006 density 8000") + "run 100\n")
deck("t03_coeffrest_hertz_limit_coarse", "# hertz/material coeff_restitution 0.5 limit_damping, 6 steps per contact\n"
     + head() + "pair_style granular\npair_coeff * * hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3 limit_damping\n" + GRAV
     + "fix floor all wall/gran granular hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3 limit_damping zplane 0 NULL\nfix integ all nve/sphere\ntimestep 3e-4\n"
     + TWO + "run 100\n")

# ---------------------------------------------------------------- degenerate values (crash hunt)
def _deg(pc, atoms=TWO):
    return head() + f"pair_style granular\npair_coeff * * {pc}\n" + GRAV + FLOOR + TAIL + atoms + "run 100\n"


deck("x02_hooke_k_zero", "# a hooke stiffness of 0 (no repulsion: the spheres pass through)\n"
     + _deg("hooke 0 3000 damping mass_velocity tangential linear_nohistory 1 0.3"))
deck("x03_negative_damping", "# a negative damping column (energy gain: eps > 1)\n"
     + _deg("hooke 2000 -3000 damping mass_velocity tangential linear_nohistory 1 0.3"))
deck("x04_density_zero", "# type 2 of density 0 (mass 0)\n" + _deg(HK, TWO.replace("0.006 density 2500", "0.006 density 0")))
deck("x05_diameter_zero", "# type 2 of diameter 0\n" + _deg(HK, TWO.replace("diameter 0.006 density 2500", "diameter 0 density 2500")))
deck("x07_run0_only_in_loop", "# only run 0 commands, in a loop that changes the stiffness each pass\n"
     + head() + "pair_style granular\n" + GRAV + FLOOR + TAIL + TWO
     + "variable k index 1000 2000 4000\nlabel l\npair_coeff * * hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 0\nnext k\njump SELF l\n")


# ---------------------------------------------------------------- sandbox
deck("x01_shell_devshm_proc_root", "# shell builtins at /dev/shm and /proc/1/root; write_coeff and write_data through them\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO
     + "shell mkdir /dev/shm/f14canary_dir\nshell rm /dev/shm/f14canary_rm\nshell mkdir /proc/1/root/tmp/f14canary_proc\n"
     "shell cd /dev/shm\nwrite_data f14canary_shm.data\nwrite_coeff f14canary_shm.coeff\nshell cd /proc/1/root/tmp\n"
     "write_data f14canary_proc.data\nwrite_restart f14canary_proc.restart\nrun 100\n")


def write(name):
    text, g, args, extra = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, args=args, data=extra)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
