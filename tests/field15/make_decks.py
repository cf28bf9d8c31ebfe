"""Field round 15: write the LAMMPS decks (decks/NAME/in.deck, G, ARGS) from round 14's shared header.
Each deck's first comment says what it tries. usage: python make_decks.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import FLOOR, GRAV, HK, HM, TAIL, TWO, TWO4  # noqa: E402  (the same lines as there)

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
JKR = "jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
DMT = "dmt 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"


def head(ntypes=2, box="0 0.04 0 0.04 0 0.1", bnd="p p f", style="sphere", units="si"):
    return f"""units {units}
atom_style {style}{" 1" if style == "sphere" else ""}
boundary {bnd}
comm_modify vel yes
region box block {box} units box
create_box {ntypes} box
"""


BASE = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
COUNT = 'variable n equal count(all)\nif "${n} < 1" then "pair_coeff * * hooke 9999 3000 damping mass_velocity tangential linear_nohistory 1 0.3"\n'

DECKS = {}


def deck(name, text, g=1, args=None, extra=None):
    DECKS[name] = (text, g, args, extra or {})


# ---------------------------------------------------------------- runs made for real (the marker's set-up removed)
deck("a01_adapt_N7_ramp_count_unfix", "# fix adapt every 7 steps, ramp 0.004 -> 0.006 over the run, a count read after it (runs made), unfix, run\n"
     + BASE + TWO4 + "variable d equal ramp(0.004,0.006)\nfix ad all adapt 7 atom diameter v_d reset no\nrun 10000\n" + COUNT
     + "unfix ad\nrun 100\n")
deck("a02_adapt_scale_const_two_runs_kept", "# scale yes by a constant 1.5, reset no, never unfixed: each run's set-up in LAMMPS may scale again\n"
     + BASE + TWO4 + "variable s equal 1.5\nfix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 1000\n" + COUNT + "run 1000\n")
deck("a03_adapt_reset_yes_count", "# fix adapt reset yes (sizes back at the run's end), a count read after the run, unfix, run\n"
     + BASE + TWO4 + "variable d equal ramp(0.004,0.006)\nfix ad all adapt 1 atom diameter v_d reset yes\nrun 1000\n" + COUNT
     + "unfix ad\nrun 100\n")
deck("a04_adapt_mass_no_constant_count", "# fix adapt diameter 0.006 constant, mass no (mass kept), count read, unfix, run: r 0.003 at the old mass\n"
     + BASE + TWO4 + "variable d equal 0.006\nfix ad all adapt 1 atom diameter v_d mass no reset no\nrun 1000\n" + COUNT
     + "unfix ad\nrun 100\n")
deck("a05_adapt_run_start_stop", "# ramp() over run 5000 start 0 stop 10000: half way at the run's end (d 0.005); unfix; count; run\n"
     + BASE + TWO4 + "variable d equal ramp(0.004,0.006)\nfix ad all adapt 1 atom diameter v_d reset no\nrun 5000 start 0 stop 10000\n"
     + "unfix ad\n" + COUNT + "run 100\n")
deck("a06_adapt_pre_no_post_no", "# ramp growth over run 1, then run 2 with pre no post no (no set-up: adapt not re-applied at start), unfix, run\n"
     + BASE + TWO4 + "variable d equal ramp(0.004,0.006)\nfix ad all adapt 1 atom diameter v_d reset no\nrun 2000\n" + COUNT
     + "run 2000 pre no post no\nunfix ad\nrun 100\n")
deck("a07_adapt_scale_yes_pre_no", "# scale yes constant 1.5 reset no; run 1; run 2 pre no (no second scaling by hand?), unfix, run\n"
     + BASE + TWO4 + "variable s equal 1.5\nfix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 1000\n" + COUNT
     + "run 1000 pre no\nunfix ad\nrun 100\n")
deck("a08_adapt_N_gt_run", "# fix adapt every 5000 steps on a run of 1000: LAMMPS applies it at set-up only? d 0.006; unfix; count; run\n"
     + BASE + TWO4 + "variable d equal 0.006\nfix ad all adapt 5000 atom diameter v_d reset no\nrun 1000\nunfix ad\n" + COUNT + "run 100\n")
deck("a09_adapt_time_var_group_type2_count_loop", "# type 2 grows with time in a loop of 3 runs of 1000, count read each pass; unfix; run\n"
     + BASE + TWO4 + "group t2 type 2\nvariable d equal 0.004+0.1*time\nfix ad t2 adapt 1 atom diameter v_d reset no\n"
     "variable i loop 3\nlabel l\nrun 1000\n" + COUNT + "next i\njump SELF l\nunfix ad\nrun 100\n")
deck("a10_deform_then_lz_diameter", "# fix deform shrinks z (final 0 0.05) over run 1; diameter = lz/10 set after, with a count read\n"
     + BASE + TWO4 + "fix df all deform 1 z final 0 0.05 units box\nrun 1000\nunfix df\n" + COUNT
     + "set type 1 diameter $(lz/10)\nrun 100\n")
deck("a11_var_after_run_k_from_step_pour", "# a pour defined; stiffness from step read after run 1 (runs made): k = 2000+step = 3000\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 1 4767548 region slab diam one 0.004 dens 2500 2500\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nrun 1000\nunfix p\n"
     "pair_coeff * * hooke $(2000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("a12_pour_loop_count_then_set", "# a pour loop until count(all) >= 6, then set type 1 diameter 0.005 (runs made)\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 6 1 4767548 region slab diam one 0.004 dens 2500 2500\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nlabel l\nrun 2000\n"
     'if "$(count(all)) < 7" then "jump SELF l"\nunfix p\nset type 1 diameter 0.005\nrun 100\n')
deck("a13_pour_loop_pe", "# a pour and a loop on pe (potential energy) after it, then the type-1 density set from the pass count\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 4 1 4767548 region slab diam one 0.004 dens 2500 2500\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nthermo 100\nvariable k equal 0\nlabel l\nrun 1000\n"
     'variable k equal ${k}+1\nif "$(ke) > 1e-7 && ${k} < 30" then "jump SELF l"\nunfix p\nset type 1 density $(1000*v_k)\nrun 100\n')
deck("a14_minimize_between_runs", "# a minimize between two runs (granular pair under minimize), count read after\n"
     + BASE + TWO4 + "run 1000\nminimize 1e-6 1e-8 100 1000\n" + COUNT + "run 100\n")
deck("a15_velocity_displace_between", "# velocity set, displace_atoms into a region, then set region resizes (pass with runs skipped suffices)\n"
     + BASE + TWO4 + "run 1000\nvelocity all set 0 0 -0.5\ngroup t2 type 2\ndisplace_atoms t2 move 0 0 0.05 units box\n"
     "region hi block EDGE EDGE EDGE EDGE 0.04 EDGE units box\nset region hi diameter 0.006\nrun 100\n")
deck("a16_create_random_after_run", "# create_atoms random of type 2 after a run, then set type 2 diameter 0.005\n"
     + BASE + TWO4 + "run 1000\nregion up block 0.005 0.035 0.005 0.035 0.05 0.09 units box\ncreate_atoms 2 random 3 4767 up\n"
     "set type 2 diameter 0.005 density 2000\nrun 100\n")
deck("a17_delete_overlap_after_fall", "# after the fall, a type-2 sphere made where type 1 lies; delete_atoms overlap; then set by count\n"
     + BASE + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nrun 3000\n"
     "create_atoms 2 single 0.02 0.02 0.0025\nset type 2 diameter 0.004 density 2500\ndelete_atoms overlap 0.003 all all\n"
     'if "$(count(all)) < 2" then "set type 1 diameter 0.006"\nrun 100\n')
deck("a18_deposit_then_set", "# fix deposit of type 2 (default size 1 m!), then set type 2 diameter after the run\n"
     + BASE + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n"
     "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix dep all deposit 3 2 100 4767 region slab near 0.005 vz -0.1 -0.1\n"
     "run 1000\nset type 2 diameter 0.005 density 2000\nrun 100\n")
deck("a19_deposit_no_set", "# fix deposit of type 2 left at LAMMPS' default size (diameter 1, density 1) while its runs go on\n"
     + head(2, box="0 4 0 4 0 10") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 2 2 1\nset type 1 diameter 0.5 density 2500\n"
     "region slab block 0.5 3.5 0.5 3.5 5 9 units box\nfix dep all deposit 2 2 100 4767 region slab near 1.1 vz -0.1 -0.1\nrun 1000\n")
deck("a25_type2_poured_in_second_run", "# type 2 only poured by a pour defined after run 1: stage 1 names it not yet poured\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nrun 1000\n"
     "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 4 2 4767548 region slab diam one 0.006 dens 2000 2000\nrun 2000\n")
deck("a26_read_dump_after_run", "# a dump written in run 1, read back with read_dump (positions), then a count read\n"
     + BASE + TWO + "dump d all custom 100 f15atoms.dump id type x y z\nrun 1000\nundump d\nread_dump f15atoms.dump 1000 x y z\n" + COUNT + "set type 2 density 1500\nrun 100\n")
deck("a20_pour_diam_range", "# fix pour diam range 0.003 0.005: type 1's sizes spread\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 8 1 4767548 region slab diam range 0.003 0.005 dens 2500 2500\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nrun 2000\n")
deck("a21_pour_diam_poly", "# fix pour diam poly 2 0.004 0.3 0.006 0.7, dens range\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 8 1 4767548 region slab diam poly 2 0.004 0.3 0.006 0.7 dens 2000 3000\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nrun 2000\n")
deck("a22_heat_gran", "# granular heat conduction: fix property/atom temperature heatflow, heat area, fix heat/flow\n"
     + head() + "fix pa all property/atom temperature heatflow\npair_style granular\n"
     f"pair_coeff * * {HK} heat area 1.0\n" + GRAV + FLOOR + TAIL + TWO
     + "set type 1 temperature 300\nset type 2 temperature 400\nfix hf all heat/flow constant 1.0\nrun 1000\n" + COUNT + "run 100\n")
deck("a23_wall_gran_shear", "# wall/gran zplane with shear x 0.1 (a floor moving in its plane)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"fix floor all wall/gran granular {HK} zplane 0 NULL shear x 0.1\n" + TAIL + TWO + "run 1000\n")
deck("a24_crash_in_real_runs", "# lost atoms (no floor, boundary f) after a count read: LAMMPS stops in the runs by hand\n"
     + head(bnd="p p f") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + TAIL + TWO
     + "thermo_modify lost error\nrun 100\n" + COUNT + "run 20000\n")

# ---------------------------------------------------------------- units, data files, atom styles
deck("u01_units_cgs", "# units cgs: hooke in dyne/cm, diameter 0.4 cm, density 2.5 g/cm^3, --g 100 cm/s\n"
     + head(box="0 4 0 4 0 10", units="cgs") + "pair_style granular\npair_coeff * * hooke 2e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     "fix grav all gravity 981 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     "fix integ all nve/sphere\ntimestep 1e-5\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\n"
     "set type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g=100)
deck("u02_units_micro", "# units micro (um, pg, us): hertz/material in pg/(um us^2), diameter 4 um, density 2.5 pg/um^3\n"
     + head(box="0 40 0 40 0 100", units="micro") + "pair_style granular\npair_coeff * * hertz/material 1e4 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3\n"
     "fix floor all wall/gran granular hertz/material 1e4 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     "fix integ all nve/sphere\ntimestep 1e-4\ncreate_atoms 1 single 20 20 10\ncreate_atoms 2 single 10 10 10\n"
     "set type 1 diameter 4 density 2.5e-12\nset type 2 diameter 6 density 2.5e-12\nrun 100\n", g=1)
deck("u03_units_nano_hooke", "# units nano: hooke, diameter 40 nm\n"
     + head(box="0 400 0 400 0 1000", units="nano") + "pair_style granular\npair_coeff * * hooke 1e-3 1e-6 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     "fix floor all wall/gran granular hooke 1e-3 1e-6 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n"
     "fix integ all nve/sphere\ntimestep 1e-3\ncreate_atoms 1 single 200 200 100\ncreate_atoms 2 single 100 100 100\n"
     "set type 1 diameter 40 density 2.5e-21\nset type 2 diameter 60 density 2.5e-21\nrun 100\n", g=1)
deck("u04_read_data_diameter_density", "# read_data atom_style sphere: per-atom diameter and density; type 1 at two sizes\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data atoms.data\n"
     f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + "run 100\n",
     extra={"atoms.data": "field 15 data\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
            "1 1 0.004 2500 0.02 0.02 0.01\n2 2 0.006 2000 0.01 0.01 0.01\n3 1 0.004 2500 0.03 0.03 0.01\n"})
deck("u05_hybrid_sphere_dipole_data", "# atom_style hybrid sphere dipole from a data file (diameter density columns in hybrid order)\n"
     + "units si\natom_style hybrid sphere dipole\nboundary p p f\ncomm_modify vel yes\nread_data atoms.data\n"
     f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + "run 100\n",
     extra={"atoms.data": "field 15 data\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # hybrid\n\n"
            "1 1 0.02 0.02 0.01 0.004 2500 0 0 0\n2 2 0.01 0.01 0.01 0.006 1500 0 0 0\n"})
deck("u06_hybrid_overlay_lj_11", "# hybrid/overlay granular + lj/cut on 1 1 only: 1 2 and 2 2 granular alone\n"
     + head() + f"pair_style hybrid/overlay granular lj/cut 0.01\npair_coeff * * granular {HK}\npair_coeff 1 1 lj/cut 1e-6 0.004\n"
     "pair_coeff 1 2 lj/cut 0 0.004\npair_coeff 2 2 lj/cut 0 0.004\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")
deck("u07_set_density_type_then_mass_atom", "# set type density, then set atom 2 mass (one sphere of type 2 heavier): type 2 at two masses\n"
     + BASE + TWO + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\nset atom 3 mass 0.001\nrun 100\n")
deck("u08_fix_property_atom_mol_set_by_var", "# diameters from an atom-style variable of a fix property/atom d_ column\n"
     + BASE + TWO + "fix pa all property/atom d_dd\nset type 1 d_dd 0.005\nset type 2 d_dd 0.007\nvariable dv atom d_dd\n"
     "set group all diameter v_dv\nrun 100\n")

# ---------------------------------------------------------------- rigid bodies
RIG = BASE.replace("fix integ all nve/sphere\n", "")
deck("b01_rigid_single_sphere_bodies", "# fix rigid bodystyle molecule, each sphere its own molecule (single-sphere bodies)\n"
     + RIG.replace("atom_style sphere 1", "atom_style hybrid sphere molecular").replace("create_box 2 box", "create_box 2 box")
     + TWO + "set atom 1 mol 1\nset atom 2 mol 2\nfix rb all rigid molecule\nrun 100\n")
deck("b02_rigid_clump_type1_shared", "# a clump of two type-1 spheres (rigid, group by id) and a free type-1 and type-2 sphere\n"
     + RIG + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.023 0.02 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     "group clump id 1 2\ngroup free subtract all clump\nfix rb clump rigid single\nfix integ free nve/sphere\nrun 100\n")
deck("b03_rigid_region_group_type2", "# a clump of two type-2 spheres picked by region; type 2 only in the body; type 1 free\n"
     + RIG + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     "region rr block 0 0.02 0 0.02 EDGE EDGE units box\ngroup clump region rr\ngroup free subtract all clump\n"
     "fix rb clump rigid single\nfix integ free nve/sphere\nrun 100\n")
deck("b04_rigid_small_custom_var", "# rigid/small bodystyle custom by an atom-style variable: atoms 1 and 2 (type 1, 2) one body, atom 3 (type 1) its own\n"
     + RIG + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.0245 0.02 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     "variable bid atom (id<3)+2*(id>=3)\nfix rb all rigid/small custom v_bid\nrun 100\n")
deck("b05_rigid_nve_group_bodystyle", "# rigid/nve bodystyle group: g1 a type-1 single sphere, g2 two type-2 spheres\n"
     + RIG + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     "group g1 type 1\ngroup g2 type 2\nfix rb all rigid/nve group 2 g1 g2\nrun 100\n")
deck("b06_rigid_mol_type2_single_type1_pair", "# rigid molecule: type 1 single-sphere bodies (mol 1, 2), type 2 two spheres in mol 3\n"
     + RIG.replace("atom_style sphere 1", "atom_style hybrid sphere molecular")
     + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 1 single 0.035 0.035 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nset atom 1 mol 1\nset atom 2 mol 2\nset atom 3 mol 3\nset atom 4 mol 3\n"
     "fix rb all rigid molecule\nrun 100\n")
deck("b07_rigid_after_set_type_change", "# a rigid clump of two type-1 spheres; after the rigid fix, set atom 1 type 2 (the body now holds types 1, 2)\n"
     + RIG + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.023 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup clump id 1 2\ngroup free id 3\n"
     "fix rb clump rigid single\nfix integ free nve/sphere\nrun 100\nset atom 1 type 2\nrun 100\n")

RIGM = RIG.replace("atom_style sphere 1", "atom_style hybrid sphere molecular").replace("comm_modify vel yes", "comm_modify vel yes\natom_modify map array")
deck("b08_rigid_small_single_and_pair_bodies", "# rigid/small molecule: type-1 spheres each their own body (mol 1, 2), two type-2 spheres one body (mol 3)\n"
     + RIGM + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 1 single 0.035 0.035 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nset atom 1 mol 1\nset atom 2 mol 2\nset atom 3 mol 3\nset atom 4 mol 3\n"
     "fix rb all rigid/small molecule\nrun 100\n")
deck("b09_rigid_type2_group_single", "# group g2 type 2 (two type-2 spheres) one rigid body; type 1 free\n"
     + RIG + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup g2 type 2\ngroup g1 type 1\n"
     "fix rb g2 rigid single\nfix integ g1 nve/sphere\nrun 100\n")
deck("b10_rigid_type1_group_then_set_type2", "# group gb type 1 (atoms 1, 2) one rigid body; then set atom 1 type 2: the body holds a type-2 sphere; atom 3 a free type-2 sphere\n"
     + RIG + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.023 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\ngroup gb type 1\ngroup gf type 2\n"
     "set atom 1 type 2\nfix rb gb rigid single\nfix integ gf nve/sphere\nrun 100\n")
deck("b11_rigid_type2_group_then_new_free_type2", "# group gb type 2 made before a second type-2 sphere is created: the new one is free (not in gb)\n"
     + RIG + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup gb type 2\n"
     "create_atoms 2 single 0.03 0.01 0.01\nset atom 4 diameter 0.006 density 2500\ngroup gf subtract all gb\n"
     "fix rb gb rigid single\nfix integ gf nve/sphere\nrun 100\n")
deck("b12_rigid_nve_small_type_group_molecule", "# rigid/nve/small molecule on group type 2 (two bodies of two type-2 spheres); type 1 free\n"
     + RIGM + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "create_atoms 2 single 0.01 0.03 0.01\ncreate_atoms 2 single 0.0145 0.03 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nset atom 2 mol 1\nset atom 3 mol 1\nset atom 4 mol 2\nset atom 5 mol 2\n"
     "group g2 type 2\ngroup g1 type 1\nfix rb g2 rigid/nve/small molecule\nfix integ g1 nve/sphere\nrun 100\n")
deck("b13_rigid_molecule_mol0_is_a_body", "# fix rigid molecule on all: type-2 spheres mol 1, type-1 spheres left at mol 0, which LAMMPS takes as one body too\n"
     + RIG.replace("atom_style sphere 1", "atom_style hybrid sphere molecular") + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 1 single 0.035 0.035 0.01\n"
     "create_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nset type 2 mol 1\nfix rb all rigid molecule\nrun 100\n")
deck("b14_rigid_small_group_type2_mol_ids_from_type", "# rigid/small molecule on group type 2, type 1 spheres free but in mol 1 with the type-2 ones (outside the group)\n"
     + RIGM + "create_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.0145 0.01 0.01\n"
     "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nset group all mol 1\n"
     "group g2 type 2\ngroup g1 type 1\nfix rb g2 rigid/small molecule\nfix integ g1 nve/sphere\nrun 100\n")

# ---------------------------------------------------------------- walls
deck("w01_variable_group_wall_same_plane", "# a second floor at z = 0 on a group made by an atom-style variable (z < 0.015): holds both spheres\n"
     + BASE + TWO + "variable low atom z<0.015\ngroup g variable low\n"
     f"fix floor2 g wall/gran granular {HK} zplane 0 NULL\nrun 100\n")
deck("w02_subtract_group_wall_same_plane", "# a second floor at z = 0 on a group made by subtract of an id group\n"
     + BASE + TWO + "group one id 1\ngroup g subtract all one\n"
     f"fix floor2 g wall/gran granular {HK} zplane 0 NULL\nrun 100\n")
deck("w03_region_group_wall_other_plane", "# a group-by-region wall at z = 0.1 top (no other wall there): named not audited?\n"
     + BASE + TWO + "region lo block 0 0.015 0 0.015 EDGE EDGE units box\ngroup g region lo\n"
     f"fix top g wall/gran granular {HK} zplane NULL 0.1\nrun 100\n")
deck("w04_region_group_wall_region_floor", "# floor is a region wall/gran/region; a second at z=0 on a region group\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"region pl plane 0 0 0 0 0 1 side in\nfix floor all wall/gran/region granular {HK} region pl\n" + TAIL + TWO
     + "region lo block 0 0.015 0 0.015 EDGE EDGE units box\ngroup g region lo\n"
     f"fix floor2 g wall/gran/region granular {HK} region pl\nrun 100\n")
deck("w05_block_variable_face_vibrating", "# a block region whose bottom face is a variable (vibrated floor), wall/gran/region\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable zl equal 0.0005*sin(2*PI*time/0.01)-0.05\nregion bx block -1 1 -1 1 v_zl 0 side out units box\n"
     f"fix floor all wall/gran/region granular {HK} region bx\n" + TAIL + TWO + "run 100\n")
deck("w06_block_variable_face_constant", "# a block region wall with a variable face that is constant (0)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable zl equal 0\nregion bx block -1 1 -1 1 -0.05 v_zl side out units box\n"
     f"fix floor all wall/gran/region granular {HK} region bx\n" + TAIL + TWO + "run 100\n")
deck("w07_cylinder_variable_radius", "# a zcylinder region wall with a growing variable radius, spheres inside\n"
     + head(bnd="f f f", box="-0.05 0.05 -0.05 0.05 0 0.1") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR
     + "variable rc equal 0.02+0.5*time\nregion cyl cylinder z 0 0 v_rc 0 0.1 side in units box\n"
     f"fix cw all wall/gran/region granular {HK} region cyl\n" + TAIL
     + "create_atoms 1 single 0.0 0.0 0.01\ncreate_atoms 2 single 0.01 0.0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("w08_plane_move_linear_tangential", "# the only floor a plane region moved in x by a variable (in its plane: normal eps the same)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable xw equal 0.1*time\nregion pl plane 0 0 0 0 0 1 side in move v_xw NULL NULL\n"
     f"fix floor all wall/gran/region granular {HK} region pl\n" + TAIL + TWO + "run 100\n")
deck("w09_plane_region_rotate_const_angle", "# a plane region rotated by a variable that is a constant 0 (never moves)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "variable th equal 0\nregion pl plane 0 0 0 0 0 1 side in rotate v_th 0 0 0 0 1 0\n"
     f"fix floor all wall/gran/region granular {HK} region pl\n" + TAIL + TWO + "run 100\n")
deck("w10_block_open_side_faces_floor", "# a block container open at its top (open 6) standing on nothing: its bottom face is the only floor\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + "region bx block 0.001 0.039 0.001 0.039 0 0.09 open 6 units box\n"
     f"fix cont all wall/gran/region granular {HK} region bx\n" + TAIL + TWO + "run 100\n")
deck("w11_block_open_bottom_plane_region_floor", "# a block open at bottom (open 5) on a plane-region floor at z = 0 (not zplane)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
     + f"region pl plane 0 0 0 0 0 1 side in\nfix floor all wall/gran/region granular {HK} region pl\n"
     "region bx block 0.001 0.039 0.001 0.039 0 0.09 open 5 units box\n"
     f"fix cont all wall/gran/region granular hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region bx\n" + TAIL + TWO + "run 100\n")
deck("w12_block_open_bottom_but_zplane_hi", "# a block open at top (open 6) whose bottom face z = 0 coincides with a zplane floor: a real second wall\n"
     + BASE + "region bx block 0.001 0.039 0.001 0.039 0 0.09 open 6 units box\n"
     f"fix cont all wall/gran/region granular hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region bx\n" + TWO + "run 100\n")

# ---------------------------------------------------------------- fix adapt/fep, mixing
deck("m01_adapt_fep_diameter_growth", "# fix adapt/fep atom diameter, type 2 grown 0.004 -> 0.006 by a time ramp, reset no, unfix, run\n"
     + BASE + TWO4 + "variable d equal 0.004+0.2*time\nfix ad all adapt/fep 1 atom diameter 2 v_d reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("m02_adapt_fep_diameter_kept", "# fix adapt/fep atom diameter of type 2 constant 0.006, never unfixed\n"
     + BASE + TWO4 + "variable d equal 0.006\nfix ad all adapt/fep 1 atom diameter 2 v_d reset no\nrun 1000\n")
deck("m03_dmt_coh_then_jkr_coh0_mixed", "# 1 1 dmt cohesion 0.5, 2 2 jkr cohesion 0: 1 2 mixed by LAMMPS\n"
     + head() + "pair_style granular\npair_coeff 1 1 dmt 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     "pair_coeff 2 2 jkr 2e7 3000 0.3 0 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")
deck("m04_jkr_both_cohesive_mixed", "# 1 1 jkr cohesion 0.5, 2 2 jkr cohesion 0.2: 1 2 mixed to cohesion 0.316 (not mapped)\n"
     + head() + "pair_style granular\npair_coeff 1 1 jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     "pair_coeff 2 2 jkr 2e7 3000 0.3 0.2 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")
deck("m05_dmt_coh0_and_hertzmat_mixed", "# 1 1 dmt cohesion 0, 2 2 hertz/material: 1 2 mixed across normal models\n"
     + head() + "pair_style granular\npair_coeff 1 1 dmt 1e7 3000 0.3 0 damping mass_velocity tangential linear_nohistory 1 0.3\n"
     "pair_coeff 2 2 hertz/material 2e7 3000 0.3 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")
deck("m06_jkr_coh0_mixed_damping_differs", "# 1 1 jkr coh 0 damping tsuji, 2 2 jkr coh 0.4 damping tsuji: 1 2 mixed\n"
     + head() + "pair_style granular\npair_coeff 1 1 jkr 1e7 0.5 0.3 0 damping tsuji tangential linear_nohistory 1 0.3\n"
     "pair_coeff 2 2 jkr 2e7 0.3 0.3 0.4 damping tsuji tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")

# ---------------------------------------------------------------- scratch copy
deck("x01_symlink_to_root_beside", "# links beside the deck: root -> /, tmpl -> /tmp (made by links.sh); writes through them\n" + BASE + TWO
     + "write_data root/tmp/f15canary_root.data\nwrite_data tmpl/f15canary_tmpl.data\nshell mkdir tmpl/f15canary_dir\n"
     "write_restart tmpl/f15canary.restart\nrun 100\n")
deck("x02_symlink_loop_beside", "# a symlink loop (self -> .) and a dangling link beside the deck (made by links.sh)\n" + BASE + TWO + "run 100\n")
deck("x03_link_named_as_output", "# out.restart and out.data are links to /tmp/f15canary_* (made by links.sh); the deck writes to them, then a count read makes the runs\n"
     + BASE + TWO + "write_restart out.restart\nwrite_data out.data\nrun 100\n" + COUNT + "write_restart out.restart\nrun 100\n")
deck("x04_deck_is_symlink", "# the deck file is a link (in.link -> sub/in.deck, made by links.sh) to a deck that includes a file beside its target\n"
     + BASE + TWO + "include inc.lmp\nrun 100\n", extra={"inc.lmp": "set type 2 density 1500\n"})
deck("x05_include_link_to_devzero", "# an include of a link to /dev/zero and a read_data of a link to /dev/urandom (made by links.sh)\n"
     + BASE + TWO + "include zero.lmp\nrun 100\n")
deck("x06_include_fifo", "# an include of a named pipe beside the deck (made by links.sh; nothing ever writes to it)\n"
     + BASE + TWO + "include pipe.lmp\nrun 100\n")
deck("x07_include_link_to_big_file", "# an include of a link to a 3 GB sparse file outside the folder (made by links.sh): the folder-size bound skips links\n"
     + BASE + TWO + "include big.lmp\nrun 100\n")
# ---------------------------------------------------------------- neighbour lists, fix set, 2d
deck("n01_neigh_exclude_type_12", "# neigh_modify exclude type 1 2: LAMMPS never computes a 1-2 contact (the spheres pass through)\n"
     + BASE + TWO + "neigh_modify exclude type 1 2\nrun 100\n")
deck("n02_neigh_stale_lists", "# neighbor 1e-5 bin, neigh_modify every 200 delay 0 check no: lists rebuilt every 2 ms, spheres at 1 m/s move 2 mm in between\n"
     + BASE + TWO + "neighbor 1e-5 bin\nneigh_modify every 200 delay 0 check no\nrun 100\n")
deck("n03_fix_set_diameter_every_step", "# fix set (LAMMPS 2025) applies 'set type 1 diameter 0.006' every step of the run: type 1 at r 0.003 throughout\n"
     + BASE + TWO + "variable dd atom 0.006\nfix fs all set 1 0 type 1 diameter v_dd\nrun 100\n")
deck("n04_fix_set_density_then_unfix", "# fix set sets type 2 density 8000 every 10 steps during run 1, unfixed; run 2 at the set mass\n"
     + BASE + TWO + "variable rho atom 8000\nfix fs all set 10 0 type 2 density v_rho\nrun 100\nunfix fs\nrun 100\n")
deck("n03b_fix_set_diameter_hertz", "# fix set diameter 0.006 on type 1 every step under hertz/material (the radius matters); run, unfix, run\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + TWO
     + "variable dd atom 0.006\nfix fs all set 1 0 type 1 diameter v_dd\nrun 100\nunfix fs\nrun 100\n")
deck("n04b_fix_set_density_count_read", "# n04 with a count read after the unfix (the runs are made for real)\n"
     + BASE + TWO + "variable rho atom 8000\nfix fs all set 10 0 type 2 density v_rho\nrun 100\nunfix fs\n" + COUNT + "run 100\n")
deck("n05_neigh_exclude_group", "# neigh_modify exclude group g1 g2 with g1 type 1, g2 type 2: no 1-2 contact\n"
     + BASE + TWO + "group g1 type 1\ngroup g2 type 2\nneigh_modify exclude group g1 g2\nrun 100\n")
deck("d01_2d_density_disc", "# dimension 2, set density/disc (mass = rho pi r^2), fix enforce2d\n"
     + BASE.replace("boundary p p f", "dimension 2\nboundary p f p").replace("0 0.04 0 0.04 0 0.1", "0 0.04 0 0.1 -0.001 0.001")
       .replace("vector 0 0 -1", "vector 0 -1 0").replace("zplane 0 NULL", "yplane 0 NULL")
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density/disc 2500\n"
       "fix e2d all enforce2d\nrun 100\n")
deck("n06_fix_evaporate_type2", "# fix evaporate removes the type-2 sphere in run 1; after it only type 1 (named?)\n"
     + BASE + TWO + "group g2 type 2\nregion all block EDGE EDGE EDGE EDGE EDGE EDGE units box\nfix ev g2 evaporate 10 5 all 4767\nrun 100\nunfix ev\nrun 100\n")

deck("n07_atom_swap_types", "# fix atom/swap swaps the types of type-1 and type-2 spheres in run 1 (sizes stay with the atoms); unfix; run 2\n"
     + BASE + TWO + "fix sw all atom/swap 10 1 4767 3000.0 types 1 2\nrun 100\nunfix sw\nrun 100\n")
deck("n08_atom_swap_count_read", "# n07 with a count read after the unfix (the runs made for real)\n"
     + BASE + TWO + "fix sw all atom/swap 10 1 4767 3000.0 types 1 2\nrun 100\nunfix sw\n" + COUNT + "run 100\n")

deck("n09_atom_swap_semigrand", "# fix atom/swap semi-grand: type-1 spheres may become type 2 (keeping r 2 mm) in run 1; unfix; run 2\n"
     + BASE + "create_atoms 1 random 6 4767 NULL\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     "fix sw all atom/swap 10 5 4767 3000.0 semi-grand yes types 1 2 mu 0.0 1.0e10\nrun 100\nunfix sw\nrun 100\n")

deck("n10_neigh_delay10_default_skin", "# neigh_modify delay 10 (LAMMPS' old default) with the default skin 1 mm: at g = 10 the spheres close 1 mm in 10 steps\n"
     + BASE + TWO + "neigh_modify delay 10 every 1 check yes\nrun 100\n", g=10)

# ---------------------------------------------------------------- the clock after skipped runs, fixes beside the contact
deck("c01_run_upto_step_read", "# run 1000, then run 1500 upto (500 more steps): the stiffness from $(1000+step) = 2500\n"
     + BASE + TWO + "run 1000\nrun 1500 upto\npair_coeff * * hooke $(1000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("c02_time_after_dt_change", "# dt 1e-5 for 1000 steps, then 2e-5 for 1000: time 0.03; stiffness 1000+1e5*time = 4000\n"
     + BASE + TWO + "run 1000\ntimestep 2e-5\nrun 1000\ntimestep 1e-5\npair_coeff * * hooke $(1000+1e5*time) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("c03_reset_timestep_time_kw", "# reset_timestep 0 time 0.5 after a run: stiffness 1000+2000*time = 2000 (LAMMPS' time after the reset)\n"
     + BASE + TWO + "run 1000\nreset_timestep 0 time 0.5\npair_coeff * * hooke $(1000+2000*time) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("c04_run_every_set", "# run 200 every 100 with a set of type 2's density in between (documented: refused)\n"
     + BASE + TWO + 'run 200 every 100 "set type 2 density 5000"\nrun 100\n')
deck("c05_step_in_loop_with_upto", "# a loop of run 300 upto 900 steps, stiffness from step after: 1000+step = 1900\n"
     + BASE + TWO + "variable i loop 3\nlabel l\nrun $(300*v_i) upto\nnext i\njump SELF l\npair_coeff * * hooke $(1000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
deck("f01_temp_rescale", "# fix temp/rescale every step on all (velocities rescaled during a contact)\n"
     + BASE + TWO + "fix tr all temp/rescale 1 0.0 0.0 0.0 1.0\nrun 100\n")
deck("f02_planeforce_x", "# fix planeforce 1 0 0: the x component of every force removed (a contact along x has none)\n"
     + BASE + TWO + "fix pf all planeforce 1 0 0\nrun 100\n")
deck("f03_momentum_linear", "# fix momentum 1 linear 1 1 1 (zeroes the total momentum each step: relative motion kept)\n"
     + BASE + TWO + "fix mo all momentum 1 linear 1 1 1\nrun 100\n")
deck("f04_wall_reflect_at_floor", "# fix wall/reflect zlo at the floor beside the granular floor\n"
     + BASE.replace("boundary p p f", "boundary p p f") + TWO + "fix wr all wall/reflect zlo EDGE\nrun 100\n")
deck("f05_move_type2_linear", "# fix move linear 0 0 0 on type 2 (held still) and no integrator on it\n"
     + BASE.replace("fix integ all nve/sphere", "group g1 type 1\nfix integ g1 nve/sphere") + TWO + "group g2 type 2\nfix mv g2 move linear 0 0 0\nrun 100\n")
deck("f06_nve_no_sphere", "# fix nve (no rotation) instead of nve/sphere\n"
     + BASE.replace("fix integ all nve/sphere", "fix integ all nve") + TWO + "run 100\n")
deck("f07_spring_self", "# fix spring/self 10 on type 1 (a tether)\n" + BASE + TWO + "group g1 type 1\nfix ss g1 spring/self 10.0\nrun 100\n")
deck("f08_heat_flow_only", "# integrator split: fix nve/sphere on type 1 only; type 2 never moves (no integrator, no fix)\n"
     + BASE.replace("fix integ all nve/sphere", "group g1 type 1\nfix integ g1 nve/sphere") + TWO + "run 100\n")

# ---------------------------------------------------------------- region combinations, new contact models
RW = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV
deck("w13_region_union_plane_block", "# a wall on a union of the z = 0 plane and a block on it (x < 0.015): a floor plus a box\n"
     + RW + "region pl plane 0 0 0 0 0 1 side in units box\nregion bk block 0 0.005 EDGE EDGE 0 0.03 side out units box\nregion un union 2 pl bk\n"
     f"fix floor all wall/gran/region granular {HK} region un\n" + TAIL + TWO + "run 100\n")
deck("w14_region_intersect_two_planes", "# a wall on the intersection of z >= 0 and x <= 0.035 (a floor with a side wall)\n"
     + RW + "region pl plane 0 0 0 0 0 1 side in units box\nregion px plane 0.035 0 0 -1 0 0 side in units box\nregion it intersect 2 pl px\n"
     f"fix floor all wall/gran/region granular {HK} region it\n" + TAIL + TWO + "run 100\n")
deck("w15_region_cone_side_in", "# a cone region (z axis, radius 0.03 at z = 0 to 0.01 at z = 0.05) as the container, with a zplane floor\n"
     + RW + FLOOR + "region cn cone z 0.02 0.02 0.03 0.01 0 0.05 side in units box\n"
     f"fix cw all wall/gran/region granular {HK} region cn\n" + TAIL + TWO + "run 100\n")
deck("w16_region_plane_tilted_only_floor", "# the only floor a plane region tilted 30 degrees (normal 0.5 0 0.866), gravity along -z\n"
     + RW + "region pl plane 0.02 0.02 0 0.5 0 0.8660254 side in units box\n"
     f"fix floor all wall/gran/region granular {HK} region pl\n" + TAIL + TWO + "run 100\n")
deck("p01_mdr_normal_model", "# pair granular normal model mdr (LAMMPS 2025) on 2 2, hooke elsewhere\n"
     + BASE + TWO + "pair_coeff 2 2 mdr 5e6 0.4 1.9e5 2 0.5 0.5 damping mdr 1 tangential linear_nohistory 1 0.3\nrun 100\n")
deck("p02_hooke_damping_tsuji", "# hooke with damping tsuji (allowed for hooke?)\n"
     + head() + f"pair_style granular\npair_coeff * * hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3\n" + GRAV
     + "fix floor all wall/gran granular hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("p03_hertz_damping_viscoelastic", "# normal hertz (not /material) with damping viscoelastic\n"
     + head() + f"pair_style granular\npair_coeff * * hertz 1e6 50 damping viscoelastic tangential linear_nohistory 1 0.3\n" + GRAV
     + "fix floor all wall/gran granular hertz 1e6 50 damping viscoelastic tangential linear_nohistory 1 0.3 zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("p04_granhooke_history_limit_damping", "# pair gran/hooke/history with limit_damping and a wall/gran hooke/history\n"
     + head() + "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1 limit_damping\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 1 zplane 0 NULL limit_damping\n" + TAIL + TWO + "run 100\n")

RWH = head(bnd="f f f", box="-0.05 0.05 -0.05 0.05 0 0.1") + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n"
ATC = "create_atoms 1 single 0.0 0.0 0.01\ncreate_atoms 2 single 0.001 0.0 0.03\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
deck("w17_region_cone_equal_radii_hertz", "# a region cone with equal radii (a cylinder of r 7.5 mm, z axis) as a hertz/material wall, spheres inside\n"
     + RWH + "region cn cone z 0 0 0.0075 0.0075 0 0.1 side in units box\n"
     f"fix cw all wall/gran/region granular {HM} region cn\n" + TAIL + ATC + "run 100\n")
deck("w18_region_cylinder_hertz", "# a region cylinder (r 7.5 mm, z axis) as a hertz/material wall, spheres inside\n"
     + RWH + "region cy cylinder z 0 0 0.0075 0 0.1 side in units box\n"
     f"fix cw all wall/gran/region granular {HM} region cy\n" + TAIL + ATC + "run 100\n")
deck("w19_region_cone_tapered_hertz", "# a tapered region cone (r 30 mm at z 0 to 10 mm at z 0.05) as a hertz/material wall\n"
     + RWH + "region cn cone z 0 0 0.03 0.01 0 0.05 side in units box\n"
     f"fix cw all wall/gran/region granular {HM} region cn\n" + TAIL + ATC + "run 100\n")

# ---------------------------------------------------------------- LAMMPS restarts written by the deck
deck("r01_restart_clear_read_no_pair_again", "# write_restart, clear, read_restart: pair granular's coefficients from the restart, no wall given again\n"
     + BASE + TWO + "run 100\nwrite_restart f15.restart\nclear\nread_restart f15.restart\ncomm_modify vel yes\n" + GRAV + TAIL + "run 100\n")
deck("r02_restart_then_pair_coeff_11", "# restart read back, then pair_coeff 1 1 changed to hooke 5000 and the floor given again\n"
     + BASE + TWO + "run 100\nwrite_restart f15.restart\nclear\nread_restart f15.restart\ncomm_modify vel yes\n"
     "pair_coeff 1 1 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" + GRAV + FLOOR + TAIL + "run 100\n")
deck("r03_restart_after_pour_then_set", "# a pour, write_restart, clear, read_restart, set type 1 density 1000: the poured atoms from the restart\n"
     + head(2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 1 4767548 region slab diam one 0.004 dens 2500 2500\n"
     "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nrun 2000\nwrite_restart f15.restart\nclear\nread_restart f15.restart\ncomm_modify vel yes\n"
     "set type 1 density 1000\n" + GRAV + FLOOR + TAIL + "run 100\n")

deck("r01b_restart_no_pair_again_count_read", "# r01 with a count read after the read_restart (the runs made for real)\n"
     + BASE + TWO + "run 100\nwrite_restart f15.restart\nclear\nread_restart f15.restart\ncomm_modify vel yes\n" + GRAV + TAIL + COUNT + "run 100\n")

D2B = (BASE.replace("boundary p p f", "dimension 2\nboundary p f p").replace("0 0.04 0 0.04 0 0.1", "0 0.04 0 0.1 -0.001 0.001")
       .replace("vector 0 0 -1", "vector 0 -1 0").replace("zplane 0 NULL", "yplane 0 NULL")
       + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.004 density/disc 2500\nfix e2d all enforce2d\n")
deck("d02_2d_adapt_diameter_disc", "# 2d, fix adapt atom diameter/disc 0.006 constant (mass from the disc area), reset no, unfix, run\n"
     + D2B + "variable d equal 0.006\nfix ad all adapt 1 atom diameter/disc v_d reset no\nrun 100\nunfix ad\nrun 100\n")
deck("d03_2d_adapt_diameter_not_disc", "# 2d, fix adapt atom diameter 0.006 (mass as a sphere's, LAMMPS' rule), reset no, unfix, run\n"
     + D2B + "variable d equal 0.006\nfix ad all adapt 1 atom diameter v_d reset no\nrun 100\nunfix ad\nrun 100\n")

deck("x08_read_data_link_to_urandom", "# read_data of a link to /dev/urandom (made by links.sh)\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data rnd.data\n" + f"pair_style granular\npair_coeff * * {HK}\n" + TAIL + "run 100\n")
deck("x09_include_a_directory", "# include of a folder beside the deck (LAMMPS: cannot open)\n" + BASE + TWO + "include sub\nrun 100\n", extra={"sub/keep": "x\n"})
deck("x10_molecule_fifo", "# molecule template read from a named pipe (made by links.sh)\n" + BASE + TWO + "molecule m mol.fifo\nrun 100\n")


def write(name):
    text, g, args, extra = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, args=args, data=extra)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
