"""Field round 19: write the decks (LAMMPS: a* multi-stage, v* variables in coefficients, f* fix adapt, h* hybrid
and non-granular styles beside granular, e* region and primitive walls moving, d* data files and size ranges, n*
neighbour/exclusion/communication settings, m* damping sub-models not tried before; LIGGGHTS: L*) as
decks/NAME/in.deck with G (the speeds), extra files and a LIGGGHTS marker. Each deck's first comment says what it
tries. usage: python make_decks19.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import (ATOMS, BASE, E3, FLOOR, G1, GRAV, HERTZ, HK, HM, K, MAT3, TAIL, TL, TWO, TWO4,  # noqa: E402
                            WALL3, head, lhead, RUN2000 as RUN)  # the same lines as there

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
DECKS = {}


def deck(name, text, g="0.1 1", files=None, data=None, liggghts=False):
    DECKS[name] = (text, g, files or {}, data or {}, liggghts)


# ================================================================ a*: multi-stage decks
deck("a01_three_stages_style_change", "# stage 1 hooke mass_velocity; stage 2 pair_style granular re-issued with hertz/material viscoelastic; stage 3 only 1 2 changed to hertz velocity\n"
     + BASE(HK) + TWO + "run 200\npair_style granular\npair_coeff * * " + HM + "\nrun 200\npair_coeff 1 2 hertz 1e6 0.05 damping velocity " + TL + "\nrun 200\n")
deck("a02_granular_to_gran_history_and_wall", "# stage 1 pair granular hertz/material + granular floor; stage 2 pair_style gran/hooke/history and an old-style floor after unfix\n"
     + BASE(HM) + TWO + "run 200\npair_style gran/hooke/history 3000 NULL 400 NULL 0.5 0\npair_coeff * *\nunfix floor\n"
     + "fix floor2 all wall/gran hooke/history 3000 NULL 400 NULL 0.5 0 zplane 0 NULL\nrun 200\n")
deck("a03_timestep_and_coeff_each_stage", "# three stages: dt 1e-5 hooke 2000; dt 2e-6 hooke 8000; dt 5e-7 hooke 50000: the steps per contact each stage\n"
     + BASE(HK) + TWO4 + "run 100\ntimestep 2e-6\npair_coeff * * hooke 8000 3000 " + K + "\nrun 100\ntimestep 5e-7\npair_coeff * * hooke 50000 3000 " + K + "\nrun 100\n", g=1)
deck("a04_type3_created_after_run", "# stage 1 types 1 2; after it create_atoms of type 3 (5 mm, 7800) and pair_coeff 3 3 with other stiffness; stage 2 has 1 3, 2 3, 3 3\n"
     + head(3) + G1(HK) + GRAV + FLOOR + TAIL + TWO + "run 200\ncreate_atoms 3 single 0.03 0.03 0.02\nset type 3 diameter 0.005 density 7800\n"
     + "pair_coeff 3 3 hooke 9000 3000 " + K + "\nrun 200\n", g=1)
deck("a05_to_hybrid_overlay_ljcut_zero", "# stage 1 granular; stage 2 hybrid/overlay granular lj/cut with epsilon 0 (no force): eps as stage 1\n"
     + BASE(HK) + TWO4 + "run 100\npair_style hybrid/overlay granular lj/cut 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0.0 0.004\nrun 100\n", g=1)
deck("a06_unfix_wall_then_region_wall", "# stage 1 zplane floor hooke; stage 2 floor unfixed and a wall/gran/region on a block (the box floor) with hertz/material\n"
     + BASE(HK) + "region bot block INF INF INF INF 0 0.1 side in units box\n" + TWO + "run 100\nunfix floor\n"
     + "fix rfloor all wall/gran/region granular " + HM + " region bot\nrun 100\n")
deck("a07_types_swapped_between_runs", "# stage 2: set type 1 type 2 and set type 2 type 1 via a group made before (the 4 mm sphere becomes type 2): pairs keep their coefficients by type\n"
     + head(2) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 hooke 9000 3000 " + K + "\npair_coeff 1 2 hooke 5000 3000 " + K + "\n"
     + GRAV + FLOOR + TAIL + TWO + "group g1 type 1\ngroup g2 type 2\nrun 100\nset group g1 type 2\nset group g2 type 1\nrun 100\n", g=1)
deck("a08_pair_modify_mix_arithmetic", "# pair_modify mix arithmetic after pair_coeff 1 1 and 2 2 hertz/material with other E: LAMMPS granular mixes by its own rule whatever pair_modify says?\n"
     + head() + f"pair_style granular\npair_coeff 1 1 hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}\npair_coeff 2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}\npair_modify mix arithmetic\n"
     + GRAV + TAIL + TWO + "run 100\n")
deck("a09_clear_and_new_box", "# clear between two complete simulations in one deck: the second (hertz/material, 3 mm) is what runs last\n"
     + BASE(HK) + TWO4 + "run 100\nclear\n" + BASE(HM) + TWO.replace("0.004 density", "0.003 density") + "run 100\n")
deck("a10_pair_style_none_then_granular", "# pair_style none for a settling stage, then granular: stage 1 has no sphere contact force\n"
     + head() + "pair_style none\n" + GRAV + FLOOR + TAIL + TWO + "run 100\npair_style granular\npair_coeff * * " + HM + "\nrun 100\n")
deck("a11_wall_moved_by_unfix_refix_model", "# stage 1 floor hooke; stage 2 same fix ID re-defined (unfix + fix floor) with hertz velocity; stage 3 with jkr cohesion 0\n"
     + BASE(HK) + TWO + "run 100\nunfix floor\nfix floor all wall/gran granular hertz 1e6 0.05 damping velocity " + TL + " zplane 0 NULL\nrun 100\n"
     + "unfix floor\nfix floor all wall/gran granular jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic " + TL + " zplane 0 NULL\nrun 100\n")
deck("a12_density_changed_between_runs", "# stage 2: set type 2 density 7800 (mass changes, radius kept): mass-dependent hooke eps changes\n"
     + BASE(HK) + TWO + "run 100\nset type 2 density 7800\nrun 100\n", g=1)
deck("a13_run_every", "# run N every M with a command that changes the contact between chunks (pair_coeff in the every string)\n"
     + BASE(HK) + TWO4 + f"variable kk equal 2000\nrun 300 every 100 \"pair_coeff * * hooke 7000 3000 {K}\"\n", g=1)
deck("a14_minimize_stage", "# a minimize stage before the run, then the contact changed: minimize is a stage too\n"
     + BASE(HK) + TWO4 + "minimize 1e-8 1e-8 10 100\npair_coeff * * hooke 6000 3000 " + K + "\nrun 100\n", g=1)

# ================================================================ v*: variables in coefficients
deck("v01_coeff_chain_of_variables", "# kn from E, R and a factor, each an equal-style variable of the others; gamma from a $(...) with a format\n"
     + head() + "variable E equal 1e5\nvariable R equal 0.002\nvariable f equal 2*v_R/0.004\nvariable kn equal v_E*v_R*v_f*10\n"
     + "pair_style granular\npair_coeff * * hooke ${kn} $(3000.0*v_f:%.1f) " + K + "\n" + GRAV + TAIL + TWO + "run 100\n")
deck("v02_coeff_from_step_after_run", "# after run 1000, kn = 2000 + step: LAMMPS makes the run, step = 1000, kn 3000; with runs skipped step may stay 0\n"
     + BASE(HK) + TWO4 + "run 1000\nvariable kn equal 2000+step\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("v03_coeff_from_atoms_after_pour", "# kn = 1000 * atoms after a fix pour run (LAMMPS inserts 20 spheres: kn 22000 with the two made before)\n"
     + head(box="0 0.04 0 0.04 0 0.2") + G1(HK) + GRAV + FLOOR + TAIL + TWO4
     + "region top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 20 1 4767 region top diam one 0.004 dens 2500 2500\nrun 2000\nunfix p\n"
     + "variable kn equal 1000*atoms\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("v04_coeff_from_ke_after_run", "# gamma_n from the kinetic energy after a falling run (a value the run changes): 3000*(1+1e4*ke)\n"
     + BASE(HK) + TWO4 + "velocity all set 0 0 -0.5\nrun 500\nvariable gn equal 3000*(1+1e4*ke)\nprint \"GN ${gn}\"\npair_coeff * * hooke 2000 ${gn} " + K + "\nrun 100\n", g=1)
deck("v05_coeff_from_time_after_two_runs_dt", "# kn from elapsed time after two runs at different dt: 2000 + 1e6*time (LAMMPS: time 0.003 -> 5000)\n"
     + BASE(HK) + TWO4 + "run 100\ntimestep 2e-5\nrun 100\nvariable kn equal 2000+1e6*time\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("v06_coeff_from_particle_z_after_run", "# kn from z of atom 1 after a falling run (z[1] changes in the run)\n"
     + BASE(HK) + TWO4.replace("0.02 0.02 0.01", "0.02 0.02 0.05") + "run 2000\nvariable kn equal 2000+1e5*z[1]\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("v07_index_variable_next_stages", "# an index variable over three stiffnesses with next/jump: three stages, the last 8000\n"
     + BASE(HK) + TWO4 + f"variable k index 2000 4000 8000\nlabel L\npair_coeff * * hooke $k 3000 {K}\nrun 100\nnext k\njump SELF L\n", g=1)
deck("v08_format_expression_in_coeff", "# $(...) with formats in E and nu: E $(1.234e7:%.2e) -> 1.23e+07, nu $(0.31234:%.2f) -> 0.31\n"
     + head() + "pair_style granular\npair_coeff * * hertz/material $(1.234e7:%.2e) 1.4e7 $(0.31234:%.2f) damping viscoelastic " + TL + "\n" + GRAV + TAIL + TWO + "run 100\n")
deck("v09_coeff_from_mass_of_atom", "# gamma_n for velocity damping scaled by the mass LAMMPS holds for atom 1 (mass[1]) after set\n"
     + head() + TWO + "variable gn equal 2e3*mass[1]\npair_style granular\npair_coeff * * hooke 2000 ${gn} damping velocity " + TL + "\n" + GRAV + TAIL + "run 100\n")
deck("v10_python_variable_coeff", "# a python-style variable in the coefficient: python is not executed by the audit (LAMMPS here has python?)\n"
     + head() + "variable kn python kfun\npython kfun return v_kn format f here \"def kfun(): return 2500.0\"\n"
     + "pair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO4 + "run 100\n", g=1)
deck("v11_getenv_coeff", "# kn from getenv with a default by if: the environment the deck reads\n"
     + head() + "variable kn getenv F19_KN\nif \"${kn} == ''\" then \"variable kn delete\" \"variable kn equal 4000\"\n"
     + "pair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO4 + "run 100\n", g=1)
deck("v12_vector_variable_index", "# kn from an element of a vector-style variable: v_kv[2]\n"
     + head() + "variable kv vector [1000,4000,9000]\nvariable kn equal v_kv[2]\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO4 + "run 100\n", g=1)
deck("v13_file_variable_coeff", "# kn read from a file-style variable (kn.txt, first line 6000): next advances to 7000 for stage 2\n"
     + BASE(HK) + TWO4 + "variable kn file kn.txt\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\nnext kn\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n",
     g=1, data={"kn.txt": "# stiffnesses\n6000\n7000\n"})
deck("v14_ternary_and_logic", "# E chosen by ternary(): ternary(v_a>1,5e7,1e7) with a = 2: 5e7\n"
     + head() + "variable a equal 2\nvariable E equal ternary(v_a>1,5e7,1e7)\npair_style granular\npair_coeff * * hertz/material ${E} 1.4e7 0.3 damping viscoelastic " + TL + "\n" + GRAV + TAIL + TWO + "run 100\n")
deck("v15_internal_variable", "# an internal-style variable set by the deck then used in pair_coeff\n"
     + head() + "variable kn internal 3500\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO4 + "run 100\n", g=1)
deck("v16_immediate_reference_redefined", "# variable a equal 2 ... kn equal 1000*v_a, then a redefined to 5 before pair_coeff ${kn}: kn evaluated at substitution (5000)\n"
     + head() + "variable a equal 2\nvariable kn equal 1000*v_a\nvariable a delete\nvariable a equal 5\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO4 + "run 100\n", g=1)

# ================================================================ f*: fix adapt
deck("f01_adapt_diameter_reset_no", "# fix adapt atom diameter ramps 4 mm -> 6 mm over run 1 (reset no: kept, mass scaled with it); stage 2 at 6 mm\n"
     + BASE(HK) + TWO4 + "variable dd equal ramp(0.004,0.006)\nfix ad all adapt 1 atom diameter v_dd reset no\nrun 1000\nunfix ad\nrun 100\n", g=1)
deck("f02_adapt_diameter_reset_yes", "# fix adapt atom diameter to 8 mm during run 1 with reset yes (restored at the end); stage 2 at 4 mm\n"
     + BASE(HM) + TWO4 + "variable dd equal 0.008\nfix ad all adapt 1 atom diameter v_dd reset yes\nrun 100\nunfix ad\nrun 100\n")
deck("f03_adapt_diameter_active_last_run", "# fix adapt atom diameter active in the last run: sizes change while contacts happen\n"
     + BASE(HM) + TWO4 + "variable dd equal ramp(0.004,0.002)\nfix ad all adapt 1 atom diameter v_dd\nrun 1000\n")
deck("f04_adapt_pair_granular", "# fix adapt on a pair granular coefficient (does LAMMPS granular have an adaptable parameter?)\n"
     + BASE(HK) + TWO4 + "variable kk equal ramp(2000,8000)\nfix ad all adapt 1 pair granular kn 1 1 v_kk\nrun 100\n", g=1)
deck("f05_adapt_pair_gran_hooke", "# fix adapt on pair gran/hooke (not adaptable either?)\n"
     + head() + "pair_style gran/hooke 2000 NULL 300 NULL 0.5 0\npair_coeff * *\n" + GRAV + TAIL + TWO4
     + "variable kk equal ramp(2000,8000)\nfix ad all adapt 1 pair gran/hooke kn * * v_kk\nrun 100\n", g=1)
deck("f06_adapt_diameter_type2_scale", "# fix adapt atom diameter on group t2 only with scale yes... (scale applies to pair params; atom diameter ignores it)\n"
     + BASE(HK) + TWO + "group t2 type 2\nvariable dd equal 0.008\nfix ad t2 adapt 1 atom diameter v_dd reset no\nrun 100\nunfix ad\nrun 100\n", g=1)

# ================================================================ h*: other styles beside granular
deck("h01_overlay_ljcut_attractive_22", "# hybrid/overlay granular + lj/cut with epsilon 1e-6 on 2 2 only (an attraction on that pair, others lj 0)\n"
     + head() + "pair_style hybrid/overlay granular lj/cut 0.012\npair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0.0 0.004\npair_coeff 2 2 lj/cut 1e-6 0.005\n"
     + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h02_hybrid_zero_12", "# pair_style hybrid granular zero: 1 2 by zero (no force at all: the spheres pass through)\n"
     + head() + "pair_style hybrid granular zero 0.01\npair_coeff 1 1 granular " + HK + "\npair_coeff 2 2 granular " + HK + "\npair_coeff 1 2 zero\n"
     + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h03_hybrid_none_12", "# pair_style hybrid with pair_coeff 1 2 none\n"
     + head() + "pair_style hybrid granular lj/cut 0.01\npair_coeff 1 1 granular " + HK + "\npair_coeff 2 2 granular " + HK + "\npair_coeff 1 2 none\n"
     + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h04_overlay_soft_zero_A", "# hybrid/overlay granular soft with A = 0 on all pairs (no extra force)\n"
     + head() + "pair_style hybrid/overlay granular soft 0.006\npair_coeff * * granular " + HM + "\npair_coeff * * soft 0.0\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n")
deck("h05_overlay_yukawa_colloid", "# hybrid/overlay granular yukawa/colloid (a repulsion reaching past contact, size-aware) on all pairs\n"
     + head() + "pair_style hybrid/overlay granular yukawa/colloid 2000 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * yukawa/colloid 1e-4\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h06_overlay_granular_then_scale_zero", "# hybrid/scaled? no: hybrid/overlay granular lj/cut where lj/cut is then set to 0 by pair_coeff * * lj/cut 0 (redefined)\n"
     + head() + "pair_style hybrid/overlay granular lj/cut 0.012\npair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 1e-5 0.004\npair_coeff * * lj/cut 0.0 0.004\n"
     + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h07_special_bonds_bonded_pair", "# two spheres joined by a harmonic bond with special_bonds lj 0 (default): the bonded pair has no granular contact; a third sphere does\n"
     + head(2, style="hybrid sphere bond", extra="") .replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 2 extra/special/per/atom 4")
     + G1(HK) + "bond_style harmonic\nbond_coeff 1 10.0 0.005\n" + GRAV + FLOOR + TAIL + TWO + "create_atoms 1 single 0.03 0.03 0.01\nset atom 3 diameter 0.004 density 2500\n"
     + "create_bonds single/bond 1 1 2\nrun 100\n", g=1)
deck("h08_pair_granular_cutoff_arg", "# pair_style granular with a global cutoff argument 0.02 and a per-pair cutoff keyword\n"
     + head() + "pair_style granular 0.02\npair_coeff * * " + HK + " cutoff 0.015\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("h09_overlay_lj_on_wall_type_only", "# hybrid/overlay granular lj/cut with epsilon on 1 2 (attraction) and zero elsewhere\n"
     + head() + "pair_style hybrid/overlay granular lj/cut 0.012\npair_coeff * * granular " + HM + "\npair_coeff * * lj/cut 0.0 0.004\npair_coeff 1 2 lj/cut 1e-5 0.0045\n"
     + GRAV + FLOOR + TAIL + TWO + "run 100\n")

# ================================================================ e*: walls, regions moving, wiggle and shear
deck("e01_region_sphere_moving", "# wall/gran/region on an inside sphere region that moves (move v_x NULL NULL): the wall moves at 0.05 m/s\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "variable x equal 0.05*elapsed*dt\nregion ball sphere 0 0 0 0.03 side in move v_x NULL NULL units box\n"
     + "fix bw all wall/gran/region granular " + HM + " region ball\n" + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e02_region_cylinder_rotating_drum", "# rotating drum: wall/gran/region on a cylinder (side in) with rotate about its axis (the wall moves tangentially only)\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "variable th equal 2*PI*elapsed*dt\nregion drum cylinder y 0 0 0.04 -0.02 0.02 side in rotate v_th 0 0 0 0 1 0 units box\n"
     + "fix dw all wall/gran/region granular " + HM + " region drum\n" + GRAV.replace("9.81", "9.81") + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e03_region_cone_side_in", "# wall/gran/region on a cone region (a hopper), side in: its faces are curved, their curvature varies along z\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.1", bnd="f f f") + G1(HM) + "region hop cone z 0 0 0.01 0.04 0 0.08 side in units box\n"
     + "fix hw all wall/gran/region granular " + HM + " region hop\n" + GRAV + TAIL + "create_atoms 1 single 0 0 0.05\ncreate_atoms 2 single 0.01 0 0.06\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e04_region_plane_inclined", "# wall/gran/region on an inclined plane region (normal 0.2 0 0.98): a flat face\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.1", bnd="f f f") + G1(HM) + "region incl plane 0 0 0 0.2 0 0.979796 side in units box\n"
     + "fix iw all wall/gran/region granular " + HM + " region incl\n" + GRAV + TAIL + "create_atoms 1 single 0 0 0.02\ncreate_atoms 2 single 0.015 0 0.02\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e05_region_intersect_funnel", "# wall/gran/region on an intersection of two planes and a slab (a funnel, as a public deck builds it)\n"
     + head(box="-0.05 0.05 -0.05 0.05 0 0.1", bnd="f f f") + G1(HM) + "region lh plane -0.02 0 0.03 0.7071 0 0.7071 side in units box\nregion rh plane 0.02 0 0.03 -0.7071 0 0.7071 side in units box\n"
     + "region slab block INF INF INF INF 0.03 0.09 units box open 5 open 6\nregion lw intersect 2 lh slab\nregion rw intersect 2 rh slab\n"
     + "fix lf all wall/gran/region granular " + HM + " region lw\nfix rf all wall/gran/region granular " + HM + " region rw\n"
     + GRAV + TAIL + "create_atoms 1 single 0 0 0.06\ncreate_atoms 2 single 0.01 0.01 0.07\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e06_zplane_wiggle_z", "# fix wall/gran granular zplane with wiggle z (amplitude 1 mm, period 0.01 s): the floor moves along its normal\n"
     + head() + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL wiggle z 0.001 0.01\n" + TAIL + TWO + "run 100\n")
deck("e07_xplane_wiggle_x_hooke", "# fix wall/gran granular xplane walls with wiggle x (the walls move along their normal), hooke mass_velocity\n"
     + head(bnd="f p f") + G1(HK) + GRAV + FLOOR + f"fix xw all wall/gran granular {HK} xplane 0 0.04 wiggle x 0.002 0.02\n" + TAIL + TWO + "run 100\n", g=1)
deck("e08_zcylinder_shear_z", "# fix wall/gran granular zcylinder with shear z 0.5 (tangential motion only): eps of the normal impact unchanged\n"
     + head(box="-0.05 0.05 -0.05 0.05 0 0.1", bnd="f f f") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n"
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.03 shear z 0.5\n" + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e09_old_style_wiggle_z", "# old style fix wall/gran hertz/history zplane with wiggle z\n"
     + head() + "pair_style gran/hertz/history 1e6 NULL 2000 NULL 0.5 0\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hertz/history 1e6 NULL 2000 NULL 0.5 0 zplane 0 NULL wiggle z 0.0005 0.005\n" + TAIL + TWO + "run 100\n")
deck("e10_region_block_obstacle_side_out", "# wall/gran/region on a block obstacle (side out) inside the box: flat faces, edges and corners\n"
     + head(box="-0.05 0.05 -0.05 0.05 0 0.1", bnd="f f f") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n"
     + "region obs block -0.01 0.01 -0.01 0.01 0 0.02 side out units box\nfix ow all wall/gran/region granular " + HM + " region obs\n" + TAIL
     + "create_atoms 1 single 0 0 0.03\ncreate_atoms 2 single 0.03 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e11_region_cylinder_move_linear", "# a cylinder pillar region moving with move (linear velocity along x): wall/gran/region sees a moving curved wall\n"
     + head(box="-0.05 0.05 -0.05 0.05 0 0.1", bnd="f f f") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n"
     + "variable px equal 0.2*elapsed*dt\nregion pil cylinder z 0 0 0.005 0 0.1 side out move v_px NULL NULL units box\nfix pw all wall/gran/region granular " + HM + " region pil\n" + TAIL
     + "create_atoms 1 single 0.02 0 0.01\ncreate_atoms 2 single -0.02 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e12_wall_region_ellipsoid", "# wall/gran/region on an ellipsoid region (curvature varies over the surface)\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "region el ellipsoid 0 0 0 0.04 0.03 0.02 side in units box\nfix ew all wall/gran/region granular " + HM + " region el\n"
     + GRAV + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("e13_wall_model_differs_from_pair", "# floor hertz/material with E 1e9 (stiffer than the spheres' 1e7) and nu 0.2: wall contact from the wall's own line\n"
     + head() + G1(HM) + GRAV + f"fix floor all wall/gran granular hertz/material 1e9 1.4e7 0.2 damping viscoelastic {TL} zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("e14_wall_gran_temperature_heat", "# pair granular with heat conduction (heat area) and a wall with temperature: thermal only, eps unchanged\n"
     + head(style="sphere 1") .replace("atom_style sphere 1", "atom_style hybrid sphere 1 temperature heatflow") + "pair_style granular\npair_coeff * * " + HM + " heat area 1.0\n"
     + GRAV + f"fix floor all wall/gran granular {HM} heat area 1.0 zplane 0 NULL temperature 400\n" + TAIL + "fix hf all heat/flow constant 1.0\n" + TWO + "set type 1 temperature 300\nset type 2 temperature 300\nrun 100\n")
deck("e15_region_sphere_rotating_about_offaxis", "# a sphere region (side out) rotating about an axis through a point off its centre: its surface moves along the normal\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "variable th equal 20*PI*elapsed*dt\nregion rb sphere 0.01 0 0 0.005 side out rotate v_th 0 0 0 0 0 1 units box\n"
     + "fix rw all wall/gran/region granular " + HM + " region rb\n" + TAIL + "create_atoms 1 single 0.02 0 0\ncreate_atoms 2 single -0.02 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")

# ================================================================ d*: data files, per-atom sizes, ranges
DATA1 = """LAMMPS data file: 7 spheres, sizes and densities per atom

7 atoms
2 atom types

0 0.04 xlo xhi
0 0.04 ylo yhi
0 0.1 zlo zhi

Atoms # sphere

1 1 0.002 2500 0.005 0.005 0.01
2 1 0.003 2500 0.015 0.005 0.01
3 1 0.004 2500 0.025 0.005 0.01
4 2 0.005 1500 0.005 0.02 0.01
5 2 0.006 7800 0.015 0.02 0.01
6 2 0.005 7800 0.025 0.02 0.01
7 1 0.004 1200 0.035 0.03 0.01
"""
deck("d01_read_data_sizes_densities_hertzmat", "# read_data with per-atom diameters (2-6 mm) and densities (1200-7800) in two types; hertz/material viscoelastic (eps depends on size and mass): smallest/largest ends\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n" + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + "run 100\n",
     data={"spheres.data": DATA1})
deck("d02_read_data_hooke_mass_range", "# the same data with hooke mass_velocity (eps depends on mass only)\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": DATA1})
deck("d03_read_data_type_offset", "# read_data twice: the second file's types offset by 1 (read_data ... add append offset 1 0 0 0 0): its type 1 becomes 2\n"
     + head(3) + "read_data a.data add append\nread_data a.data add append offset 1 0 0 0 0 shift 0 0 0.03\n" + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + "run 100\n",
     data={"a.data": "spheres\n\n2 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.003 2500 0.01 0.01 0.01\n2 1 0.005 2500 0.03 0.03 0.01\n"})
deck("d04_read_data_type_labels", "# a data file with Atom Type Labels (glass, steel) and pair_coeff by label\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data lab.data\npair_style granular\npair_coeff glass glass " + HK + "\npair_coeff steel steel hooke 9000 3000 " + K + "\npair_coeff glass steel hooke 4000 3000 " + K + "\n" + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"lab.data": "labels\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 steel\n2 glass\n\nAtoms # sphere\n\n1 glass 0.004 2500 0.01 0.01 0.01\n2 steel 0.004 7800 0.03 0.03 0.01\n"})
deck("d05_read_data_point_particle", "# a data file with a diameter-0 atom (a point particle: its density is its mass) of type 2 beside 4 mm type 1\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data pt.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"pt.data": "point\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01 0.01 0.01\n2 2 0.0 0.001 0.03 0.03 0.01\n"})
deck("d06_read_data_then_set_diameter_atom", "# read_data, then set atom 3 diameter 0.008 (density kept: mass grows): the range's largest end\n"
     + "units si\natom_style sphere\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\nset atom 3 diameter 0.008\n" + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + "run 100\n",
     data={"spheres.data": DATA1})
deck("d07_read_data_2d_discs", "# 2d: read_data of discs (dimension 2: mass pi r^2 rho per unit thickness)\n"
     + "units si\ndimension 2\natom_style sphere\nboundary p p p\ncomm_modify vel yes\nread_data discs.data\n" + G1(HM) + "fix 2d all enforce2d\n" + TAIL + "run 100\n",
     data={"discs.data": "discs\n\n3 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n-0.001 0.001 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01 0.01 0\n2 1 0.008 2500 0.03 0.01 0\n3 1 0.006 2500 0.02 0.03 0\n"})
deck("d08_create_atoms_random_set_fraction_sizes", "# create_atoms random then set type 1 fraction 0.5 diameter 0.006: two sizes in type 1 by chance\n"
     + head() + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
     + "region r block 0 0.04 0 0.04 0.01 0.09 units box\ncreate_atoms 1 random 30 4357 r overlap 0.006 maxtry 100\nset type 1 diameter 0.004 density 2500\nset type/fraction 1 0.5 9871 diameter 0.006\nrun 100\n")
deck("d09_atom_variable_diameter_by_x", "# set diameter from an atom-style variable of x (a size gradient): the size range from LAMMPS\n"
     + head() + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
     + "lattice sc 0.01\nregion r block 0 0.04 0 0.01 0.01 0.02 units box\ncreate_atoms 1 region r\nvariable dd atom 0.002+0.1*x\nset type 1 density 2500\nset type 1 diameter v_dd\nrun 100\n")
deck("d10_pour_diam_poly_hertzmat_ends", "# fix pour diam poly 3 (2, 4, 6 mm) with dens range 2000-3000 into type 2; hertz/material: ends of the range\n"
     + head(box="0 0.04 0 0.04 0 0.2") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
     + "region top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 30 2 4767 region top diam poly 3 0.002 0.3 0.004 0.3 0.006 0.4 dens 2000 3000\nrun 1000\n")

# ================================================================ n*: neighbour, exclusion, communication
deck("n01_neigh_exclude_type_12", "# neigh_modify exclude type 1 2: LAMMPS never computes a 1 2 contact (the spheres pass through)\n"
     + BASE(HK) + TWO + "neigh_modify exclude type 1 2\nrun 100\n", g=1)
deck("n02_neigh_exclude_group", "# neigh_modify exclude group ga gb: the 4 mm type-1 sphere (group ga) never touches the type-2 sphere\n"
     + BASE(HK) + TWO + "group ga id 1\ngroup gb type 2\nneigh_modify exclude group ga gb\nrun 100\n", g=1)
deck("n03_neigh_exclude_molecule_intra", "# two-sphere molecules (create_atoms mol) with neigh_modify exclude molecule/intra all: spheres of one molecule never touch; of two do\n"
     + head(style="hybrid sphere molecular").replace("create_box 2 box", "create_box 2 box") + "molecule dimer dimer.mol\n" + G1(HK) + GRAV + FLOOR + TAIL
     + "create_atoms 0 single 0.01 0.01 0.01 mol dimer 3456\ncreate_atoms 0 single 0.03 0.03 0.01 mol dimer 3456\nneigh_modify exclude molecule/intra all\nrun 100\n", g=1,
     data={"dimer.mol": "dimer\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0.005 0 0\n\nTypes\n\n1 1\n2 2\n\nDiameters\n\n1 0.004\n2 0.004\n\nMasses\n\n1 8.4e-5\n2 8.4e-5\n"})
deck("n04_newton_off_processors_map_hash", "# newton off, processors 1 1 1, atom_modify map hash, comm_modify cutoff: bookkeeping only\n"
     + "units si\natom_style sphere\natom_modify map hash\nboundary p p f\nnewton off\nprocessors 1 1 1\ncomm_modify vel yes cutoff 0.02\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
     + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("n05_neighbor_multi_comm_multi", "# neighbor multi and comm_modify mode multi (a polydisperse setup)\n"
     + head() + "neighbor 0.001 multi\ncomm_modify mode multi vel yes\n" + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("n06_exclude_type_then_none", "# neigh_modify exclude type 2 2 during stage 1, then exclude none for stage 2\n"
     + BASE(HK) + TWO + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\nneigh_modify exclude type 2 2\nrun 100\nneigh_modify exclude none\nrun 100\n", g=1)
deck("n07_run_on_two_procs_grid", "# processors 2 1 1 asked while one process runs it (LAMMPS stops: the grid does not fit)\n"
     + "units si\natom_style sphere\nboundary p p f\nprocessors 2 1 1\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n" + G1(HK) + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("n08_neigh_exclude_type_wall_unaffected", "# neigh_modify exclude type 1 1 (pair contacts of like type-1 spheres off; walls are fixes, not affected)\n"
     + BASE(HM) + TWO + "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nneigh_modify exclude type 1 1\nrun 100\n")

# ================================================================ m*: damping and normal sub-models not tried
deck("m01_hooke_coeffrest_no_limit", "# hooke k with damping coeff_restitution 0.5 and no limit_damping (the overlap end rule)\n"
     + BASE(f"hooke 2000 0.5 damping coeff_restitution {TL}") + TWO + "run 100\n")
deck("m02_hertzmat_mass_velocity", "# hertz/material with damping mass_velocity (alpha 3/2, gamma 0, D2 = eta)\n"
     + BASE(f"hertz/material 1e7 30 0.3 damping mass_velocity {TL}") + TWO + "run 100\n")
deck("m03_dmt_tsuji_zero_cohesion", "# dmt with cohesion 0 and damping tsuji limit_damping\n"
     + BASE(f"dmt 1e7 0.6 0.3 0.0 damping tsuji {TL} limit_damping") + TWO + "run 100\n")
deck("m04_hertz_tsuji_rolling_twisting", "# hertz k_n with tsuji 0.7, rolling sds and twisting marshall (the normal law untouched)\n"
     + BASE(f"hertz 1e6 0.7 damping tsuji tangential mindlin NULL 1.0 0.5 rolling sds 100 10 0.1 twisting marshall") + TWO + "run 100\n")
deck("m05_hooke_velocity_mixed_three_types", "# three types hooke velocity with k and eta per type: 1 2, 1 3, 2 3 mixed (geometric), masses unlike\n"
     + head(3) + "pair_style granular\npair_coeff 1 1 hooke 2000 0.05 damping velocity " + TL + "\npair_coeff 2 2 hooke 8000 0.2 damping velocity " + TL + "\npair_coeff 3 3 hooke 4000 0.1 damping velocity " + TL + "\n"
     + GRAV + TAIL + TWO + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 7800\nrun 100\n", g=1)
deck("m06_coeffrest_e_one", "# hertz/material with coeff_restitution e = 1.0 and limit_damping: no damping (eps 1)\n"
     + BASE(f"hertz/material 1e7 1.0 0.3 damping coeff_restitution {TL} limit_damping") + TWO + "run 100\n")
deck("m07_tsuji_e_small", "# tsuji with e = 0.05 (near the polynomial's low end) and limit_damping\n"
     + BASE(f"hertz/material 1e7 0.05 0.3 damping tsuji {TL} limit_damping") + TWO + "run 100\n")
deck("m08_jkr_zero_cohesion_limit", "# jkr with surface energy 0 and limit_damping (Hertz force; does jkr's pull-off rule change the end?)\n"
     + BASE(f"jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL} limit_damping") + TWO + "run 100\n")
deck("m09_gran_hooke_dampflag_limit", "# pair gran/hooke (no history) with limit_damping and its wall\n"
     + head() + "pair_style gran/hooke 2000 NULL 300 NULL 0.5 1 limit_damping\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke 2000 NULL 300 NULL 0.5 1 limit_damping zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("m10_granular_units_lj_hertzmat", "# units lj with hertz/material and unit spheres (diameter 1, density 1), plus a wall\n"
     + head(units="lj", box="0 20 0 20 0 40") + G1(f"hertz/material 1e4 1e3 0.3 damping viscoelastic {TL}") + "fix grav all gravity 1.0 vector 0 0 -1\n"
     + f"fix floor all wall/gran granular hertz/material 1e4 1e3 0.3 damping viscoelastic {TL} zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 5 5 2\ncreate_atoms 2 single 10 10 2\nset type 1 diameter 1 density 1\nset type 2 diameter 1.5 density 1\nrun 100\n")
deck("m11_units_cgs_granular_tsuji", "# units cgs, pair granular hertz/material tsuji limit_damping (E in dyne/cm^2)\n"
     + head(units="cgs", box="0 4 0 4 0 10") + G1(f"hertz/material 1e8 0.6 0.3 damping tsuji {TL} limit_damping") + "fix grav all gravity 981 vector 0 0 -1\n"
     + f"fix floor all wall/gran granular hertz/material 1e8 0.6 0.3 damping tsuji {TL} limit_damping zplane 0 NULL\n" + TAIL
     + "create_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g="10 100")
deck("m12_pair_coeff_damping_before_normal_order", "# keywords in another order: damping and tangential before ... (LAMMPS requires the normal model first?)\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 3000 tangential linear_nohistory 1 0.3 damping mass_velocity rolling none twisting none\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("m13_units_real_granular_hooke_velocity", "# units real, pair granular hooke velocity\n"
     + head(units="real", box="0 40 0 40 0 100") + G1(f"hooke 20 0.5 damping velocity {TL}") + f"fix floor all wall/gran granular hooke 20 0.5 damping velocity {TL} zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1\n"
     + "create_atoms 1 single 10 10 5\ncreate_atoms 2 single 30 30 5\nset type 1 diameter 4 density 2\nset type 2 diameter 6 density 2\nrun 100\n", g="0.001 0.01")

# ================================================================ r*: re-checks of round 18's fixed classes
deck("r01_deposit_mol_offset_recheck", "# round 18 D1 re-check: fix deposit with mol (template sphere 6 mm, 0.0009 kg, its type 1) offset 1 -> type 2; type 2 also has a 4 mm sphere\n"
     + BASE(HM) + TWO4 + "molecule ball ball.mol\nregion top block 0 0.04 0 0.04 0.05 0.09 units box\nfix dep all deposit 3 1 200 12345 region top mol ball vz -1 -1 units box\nrun 1000\n",
     data={"ball.mol": "ball\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("r02_long_loop_then_change_recheck", "# round 18 D5 re-check: a 20000-pass loop of print-free runs, then the contact changes (hooke 9000)\n"
     + BASE(HK) + TWO4 + "variable i loop 20000\nlabel L\nvariable s1 equal floor(${i}*7/3)\nvariable s2 equal floor(${i}*11/3)\nvariable s3 equal floor(${i}*13/3)\nrun 1\nnext i\njump SELF L\n"
     + "pair_coeff * * hooke 9000 3000 " + K + "\nrun 100\n", g=1)

# ================================================================ LIGGGHTS


PLANE = {"plane0.stl": ("plane", "0", "0.04")}
LST = """fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000
fix m5 all property/global gamman peratomtypepair 3 300 200 100 200 250 150 100 150 200
fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000
fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
"""
LW = lambda model: f"fix wprim all wall/gran model {model} primitive type 3 zplane 0.0\n"

deck("L01_hertz_cohesion_sjkr", "# LIGGGHTS hertz with cohesion sjkr (cohesionEnergyDensity 1e4): an attraction in contact\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4\n"
     + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n" + LW("hertz tangential history cohesion sjkr") + ATOMS + RUN, liggghts=True)
deck("L02_hertz_rolling_cdt", "# LIGGGHTS hertz with rolling_friction cdt (a torque only): normal eps e per pair\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hertz tangential history rolling_friction cdt\npair_coeff * *\n" + LW("hertz tangential history rolling_friction cdt") + ATOMS + RUN, liggghts=True)
deck("L03_hertz_rolling_epsd2", "# LIGGGHTS hertz with rolling_friction epsd2\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hertz tangential history rolling_friction epsd2\npair_coeff * *\n" + LW("hertz tangential history rolling_friction epsd2") + ATOMS + RUN, liggghts=True)
deck("L04_hooke_tangential_no_history", "# LIGGGHTS hooke with tangential no_history\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global characteristicVelocity scalar 2.0\npair_style gran model hooke tangential no_history\npair_coeff * *\n"
     + LW("hooke tangential no_history") + ATOMS + RUN, liggghts=True)
deck("L05_two_meshes_curvature_and_primitive", "# LIGGGHTS two meshes in one wall fix (a floor type 3 with curvature 1e-5, a cylinder side) and a primitive zplane ceiling\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 3 curvature 1e-5\nfix cy all mesh/surface file cyl.stl type 3 curvature 1e-5\n"
     + "fix wm all wall/gran model hertz tangential history mesh n_meshes 2 meshes fl cy\nfix top all wall/gran model hertz tangential history primitive type 3 zplane 0.12\n" + ATOMS + RUN,
     files={"floor.stl": ("plane", "0", "0.04"), "cyl.stl": ("cylinder", "0.035", "0", "0.12", "48")}, liggghts=True)
deck("L06_mesh_curvature_tolerant", "# LIGGGHTS a coarse cylinder mesh (12 facets) with curvature_tolerant yes: spheres inside hit flat facets\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + "fix cy all mesh/surface file cyl.stl type 3 curvature_tolerant yes\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cy\n" + ATOMS + RUN,
     files={"cyl.stl": ("cylinder", "0.03", "0", "0.12", "12")}, liggghts=True)
deck("L07_mesh_type_2_particles_type_2", "# LIGGGHTS a mesh of type 2 while type 2 also has particles: mesh contact 1-2 and 2-2 with e per pair\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 2\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes fl\n" + ATOMS + RUN,
     files={"floor.stl": ("plane", "0", "0.04")}, liggghts=True)
deck("L08_hooke_stiffness_insert_radius_range", "# LIGGGHTS hooke/stiffness (eps depends on mass) with three templates 2, 3, 4 mm into type 1: ends of the range\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history")
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003\n"
     + "fix pts3 all particletemplate/sphere 32452843 atom_type 1 density constant 2500 radius constant 0.004\n"
     + "fix pdd all particledistribution/discrete 32452867 3 pts1 0.3 pts2 0.3 pts3 0.4\nregion ins block -0.03 0.03 -0.03 0.03 0.04 0.12 units box\n"
     + "fix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 30 region ins\n" + RUN, liggghts=True)
deck("L09_read_data_sizes_hookestiffness", "# LIGGGHTS read_data with per-atom diameters and densities (granular style: id type diameter density x y z) and hooke/stiffness\n"
     + "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\nread_data sph.data\nneighbor 0.002 bin\nneigh_modify delay 0\n"
     + MAT3 + LST + LW("hooke/stiffness tangential history") + RUN, liggghts=True,
     data={"sph.data": "spheres\n\n5 atoms\n3 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.01 0.15 zlo zhi\n\nAtoms\n\n1 1 0.004 2500 0.01 0 0.01\n2 1 0.008 2500 -0.01 0 0.01\n3 2 0.006 1500 0.02 0.02 0.01\n4 2 0.003 7800 -0.02 -0.02 0.01\n5 1 0.004 1000 0.03 0.0 0.02\n"})
deck("L10_hertz_units_cgs", "# LIGGGHTS units cgs with hertz (Y in dyne/cm^2)\n"
     + lhead(units="cgs", box="-5 5 -5 5 -1 15", neigh="neighbor 0.2 bin\nneigh_modify delay 0\n")
     + "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + WALL3
     + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\n"
     + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 2000\n", g="10 100", liggghts=True)
deck("L11_coeffrest_atomtypepair_keyword", "# LIGGGHTS coefficientRestitution given as 'atomtypepair' (not peratomtypepair), as a public deck writes it\n"
     + lhead(nt=1) + "fix m1 all property/global youngsModulus peratomtype 5e7\nfix m2 all property/global poissonsRatio peratomtype 0.25\n"
     + "fix m3 all property/global coefficientRestitution atomtypepair 1 0.5\nfix m4 all property/global coefficientFriction atomtypepair 1 0.4\n" + HERTZ
     + "fix wprim all wall/gran model hertz tangential history primitive type 1 zplane 0.0\ncreate_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + RUN, liggghts=True)
deck("L12_multi_stage_property_change", "# LIGGGHTS: stage 1 e 0.6...; the restitution fix re-defined (unfix m3, new values) and the pair_style re-issued for stage 2\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "unfix m3\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n"
     + HERTZ + "run 1000\n", liggghts=True)
deck("L13_move_mesh_rotate", "# LIGGGHTS a rotating drum mesh (move/mesh rotate, tangential motion only)\n"
     + lhead(box="-0.06 0.06 -0.06 0.06 -0.06 0.06") + MAT3 + E3 + HERTZ + "fix dr all mesh/surface file drum.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes dr\n"
     + "fix rot all move/mesh mesh dr rotate origin 0 0 0 axis 1 0 0 period 1.0\n" + ATOMS.replace("0.01 units box", "0.0 units box") + RUN,
     files={"drum.stl": ("xcylinder", "0.04", "0", "0", "-0.03", "0.03", "48")}, liggghts=True)
deck("L14_hertz_limitforce_tangential_off", "# LIGGGHTS hertz tangential no_history with limitForce on (force rule), wall too\n"
     + lhead() + MAT3 + E3 + "pair_style gran model hertz tangential no_history limitForce on\npair_coeff * *\n" + "fix wprim all wall/gran model hertz tangential no_history primitive type 3 zplane 0.0 limitForce on\n" + ATOMS + RUN, liggghts=True)
deck("L15_hooke_hysteresis", "# LIGGGHTS hooke/hysteresis (an elastic-plastic law): not the model's law\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global characteristicVelocity scalar 2.0\nfix m10 all property/global loadingStiffness peratomtypepair 3 1 1 1 1 1 1 1 1 1\n"
     + "fix m11 all property/global unloadingStiffness peratomtypepair 3 1.5 1.5 1.5 1.5 1.5 1.5 1.5 1.5 1.5\nfix m12 all property/global coefficientAdhesionStiffness peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"
     + "fix m14 all property/global coefficientMaxElasticStiffness peratomtypepair 3 2 2 2 2 2 2 2 2 2\nfix m13 all property/global coefficientPlasticityDepth peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hooke/hysteresis tangential history\npair_coeff * *\n" + LW("hooke/hysteresis tangential history") + ATOMS + RUN, liggghts=True)
deck("L16_variables_in_properties", "# LIGGGHTS material values from variables (Y from two variables, e from a $(...) expression)\n"
     + lhead() + "variable Y0 equal 2.5e6\nvariable Y equal 2*v_Y0\nvariable e0 equal 0.3\n"
     + "fix m1 all property/global youngsModulus peratomtype ${Y} ${Y} ${Y}\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 $(v_e0*2) 0.5 0.7 0.5 $(v_e0+0.1) 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN, liggghts=True)
deck("L17_set_type_after_insert_run", "# LIGGGHTS insert/pack of type 2 (3 mm), run, then set type 2 density 7800 (hooke/stiffness: mass-dependent), second run\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + RUN + "set type 2 density 7800\nrun 1000\n", liggghts=True)
deck("L18_primitive_walls_every_style", "# LIGGGHTS primitive walls: xplane, yplane, zplane, zcylinder inside, all hooke/stiffness (kn from type 3)\n"
     + lhead() + MAT3 + LST + "fix w1 all wall/gran model hooke/stiffness tangential history primitive type 3 xplane -0.04\n"
     + "fix w2 all wall/gran model hooke/stiffness tangential history primitive type 3 yplane 0.04\nfix w3 all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + "fix w4 all wall/gran model hooke/stiffness tangential history primitive type 3 zcylinder 0.045 0 0\n" + ATOMS + RUN, liggghts=True)
deck("L19_mesh_wiggle_normal", "# LIGGGHTS a floor mesh moved with move/mesh linear along its normal (0.2 m/s up): the wall moves at impact\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes fl\n"
     + "fix mv all move/mesh mesh fl linear 0 0 0.2\n" + ATOMS + RUN, files={"floor.stl": ("plane", "0", "0.04")}, liggghts=True)
deck("L20_hertz_per_pair_e_asymmetric_order", "# LIGGGHTS 2 types, coefficientRestitution 0.9 0.3 / 0.3 0.5 and a wall of type 1 (particles also type 1)\n"
     + lhead(nt=2) + "fix m1 all property/global youngsModulus peratomtype 5e6 2e7\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.25\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.9 0.3 0.3 0.5\nfix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n" + HERTZ
     + "fix wprim all wall/gran model hertz tangential history primitive type 1 zplane 0.0\n" + ATOMS + RUN, liggghts=True)
deck("L21_hertz_stiffness_tangential_damping", "# LIGGGHTS hertz/stiffness with tangential_damping off and viscous damping absolute? (gamman per pair)\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 1e6 1e6 1e6 1e6 2e6 2e6 1e6 2e6 3e6\nfix m5 all property/global gamman peratomtypepair 3 2e4 2e4 2e4 2e4 3e4 3e4 2e4 3e4 4e4\n"
     + "fix m6 all property/global kt peratomtypepair 3 1e6 1e6 1e6 1e6 1e6 1e6 1e6 1e6 1e6\nfix m8 all property/global gammat peratomtypepair 3 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4\n"
     + "pair_style gran model hertz/stiffness tangential history tangential_damping off\npair_coeff * *\n" + "fix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0 tangential_damping off\n" + ATOMS + RUN, liggghts=True)
deck("L22_loop_runs_mesh", "# LIGGGHTS a 50-pass loop of short runs with a mesh floor, then the restitution changes\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes fl\n" + ATOMS
     + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nvariable i loop 50\nlabel L\nrun 20\nnext i\njump SELF L\n"
     + "unfix m3\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2\n" + HERTZ + "run 100\n",
     files={"floor.stl": ("plane", "0", "0.04")}, liggghts=True)
deck("L23_radius_gaussian_template", "# LIGGGHTS particletemplate/sphere with radius gaussian (mu 3 mm, sigma 0.5 mm), hooke/stiffness\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history")
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius gaussian 0.003 0.0005\nfix pdd all particledistribution/discrete 32452867 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.12 units box\nfix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 30 region ins\n" + RUN, liggghts=True)
deck("L24_hooke_viscoelastic_off", "# LIGGGHTS hooke with viscoelastic damping? (tangential history, coefficientRestitution; 'dampingtype'?) and a region-type wall fix wall/region/sph? no: primitive zplane with 'shear'\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global characteristicVelocity scalar 2.0\npair_style gran model hooke tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0 shear x 0.1\n" + ATOMS + RUN, liggghts=True)

# ================================================================ b*: groups, fix IDs, order (second batch)
deck("b01_static_group_before_atoms_wall", "# group g1 type 1 made before the atoms exist (a static group: empty); the floor acts on g1 only, so on no sphere\n"
     + head() + G1(HK) + GRAV + "group g1 type 1\n" + f"fix floor g1 wall/gran granular {HK} zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g=1)
deck("b02_static_group_before_atoms_integrator", "# fix nve/sphere on a group made before the atoms exist (empty): type-1 spheres are never integrated (held); type 2 integrated by a second fix\n"
     + head() + G1(HK) + GRAV + FLOOR + "group g1 type 1\nfix integ g1 nve/sphere\ntimestep 1e-5\n" + TWO + "group g2 type 2\nfix integ2 g2 nve/sphere\nrun 100\n", g=1)
deck("b03_fix_redefined_same_id", "# fix floor re-issued with the same ID and no unfix (LAMMPS replaces it): stage 2's floor is hertz/material\n"
     + BASE(HK) + TWO + "run 100\n" + f"fix floor all wall/gran granular {HM} zplane 0 NULL\nrun 100\n")
deck("b04_coeff_after_last_run", "# pair_coeff and a new floor after the last run: nothing runs with them\n"
     + BASE(HK) + TWO + "run 100\npair_coeff * * hooke 9000 3000 " + K + "\nunfix floor\nfix floor2 all wall/gran granular " + HM + " zplane 0 NULL\n")
deck("b05_limit_damping_mixed", "# 1 1 hertz/material viscoelastic with limit_damping, 2 2 without: LAMMPS' mixed 1 2 (limit or not?)\n"
     + head() + f"pair_style granular\npair_coeff 1 1 {HM} limit_damping\npair_coeff 2 2 {HM}\n" + GRAV + TAIL + TWO + "run 100\n")
deck("b06_pour_rigid_dimer", "# fix pour of a two-sphere molecule as rigid bodies (rigid/small): a clump, not a sphere\n"
     + head(style="sphere", box="0 0.04 0 0.04 0 0.2") + "molecule dimer dimer.mol\n" + G1(HK) + GRAV + FLOOR + "timestep 1e-5\n"
     + "fix rb all rigid/small molecule mol dimer\nregion top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 5 0 4767 region top mol dimer rigid rb\nrun 1000\n", g=1,
     data={"dimer.mol": "dimer\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0.004 0 0\n\nTypes\n\n1 1\n2 2\n\nDiameters\n\n1 0.004\n2 0.004\n\nMasses\n\n1 8.4e-5\n2 8.4e-5\n"})
deck("b07_coeff_from_xcm_after_run", "# kn from the centre of mass height after a falling run: 2000 + 1e5*xcm(all,z)\n"
     + BASE(HK) + TWO4.replace("0.02 0.02 0.01", "0.02 0.02 0.05") + "run 2000\nvariable kn equal 2000+1e5*xcm(all,z)\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("b08_if_on_ke_branch", "# if the kinetic energy after a falling run is above 1e-9 then hooke 9000 else hooke 2000\n"
     + BASE(HK) + TWO4.replace("0.02 0.02 0.01", "0.02 0.02 0.05") + "run 500\nvariable e equal ke\nif \"${e} > 1e-9\" then \"pair_coeff * * hooke 9000 3000 " + K + "\" else \"pair_coeff * * hooke 2000 3000 " + K + "\"\nrun 100\n", g=1)
deck("b09_static_group_before_pour_wall", "# group t1 type 1 made after create_atoms but before fix pour adds type-1 spheres (not in t1); the floor acts on t1 only\n"
     + head(box="0 0.04 0 0.04 0 0.2") + G1(HK) + GRAV + TAIL + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\ngroup t1 type 1\n"
     + f"fix floor t1 wall/gran granular {HK} zplane 0 NULL\n" + "region top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 10 1 4767 region top diam one 0.006 dens 2500 2500\nrun 1000\n", g=1)
deck("b10_coeff_change_then_run0", "# the coefficients change, then run 0 (no step): the last contacts happen under the first run's settings\n"
     + BASE(HK) + TWO + "run 100\npair_coeff * * hooke 9000 3000 " + K + "\nrun 0\n", g=1)
deck("b11_type_set_after_group_wall", "# floor on group g1 (type 1 at its making); then set group g1 type 2: the wall now acts on type-2 spheres (g1's)\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + "group g1 type 1\n" + f"fix floor g1 wall/gran granular {HK} zplane 0 NULL\nset group g1 type 2\nrun 100\n", g=1)
deck("b12_delete_atoms_overlap_setup", "# delete_atoms overlap removes the type-2 sphere overlapping a type-1 one before the run: type 2 left with none\n"
     + head() + G1(HK) + GRAV + FLOOR + TAIL + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.021 0.02 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "group t1 type 1\ngroup t2 type 2\ndelete_atoms overlap 0.004 t2 t1\nrun 100\n", g=1)
deck("L25_property_redefined_same_id", "# LIGGGHTS: fix m3 coefficientRestitution re-issued with the same ID (no unfix) between runs: 0.3 everywhere for stage 2\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 1000\n", liggghts=True)
deck("L26_integrate_type1_only", "# LIGGGHTS: nve/sphere on type 1 only: type-2 spheres are held (never move)\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "group t1 type 1\ntimestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr t1 nve/sphere\nrun 2000\n", liggghts=True)
deck("L27_static_group_before_insert_wall", "# LIGGGHTS: group t1 type 1 made before insert/pack adds type-1 spheres; the floor acts on t1 (the one create_atoms sphere) only\n"
     + lhead() + MAT3 + E3 + HERTZ + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\ngroup t1 type 1\n"
     + "fix wprim t1 wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.003\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)
deck("L28_pair_model_changed_walls_kept", "# LIGGGHTS: stage 2 pair_style gran model hooke (characteristicVelocity) while the wall keeps hertz\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global characteristicVelocity scalar 2.0\n" + HERTZ + WALL3 + ATOMS + RUN + "pair_style gran model hooke tangential history\npair_coeff * *\nrun 1000\n", liggghts=True)

# ================================================================ c*: third batch (2d insertion masses, extreme e, default dt, cohesion mixing)
H2D = ("units si\ndimension 2\natom_style sphere\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.2 -0.001 0.001 units box\ncreate_box 2 box\n")
deck("c01_2d_pour_disc_masses", "# 2d: fix pour of 4 mm discs (dens 2500) into type 2 beside a created 4 mm type-1 disc (set density): the masses LAMMPS gives each\n"
     + H2D + G1(HM) + "fix grav all gravity 9.81 vector 0 -1 0\n" + f"fix floor all wall/gran granular {HM} yplane 0 NULL\nfix integ all nve/sphere\nfix 2d all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.01 0\nset type 1 diameter 0.004 density 2500\nregion top block 0 0.04 0.1 0.19 -0.001 0.001 units box\n"
     + "fix p all pour 10 2 4767 region top diam one 0.004 dens 2500 2500\nrun 1000\n")
deck("c02_2d_density_disc", "# 2d: set density/disc (mass pi r^2 rho) on type 2, density (4/3 pi r^3 rho) on type 1\n"
     + H2D + G1(HM) + f"fix floor all wall/gran granular {HM} yplane 0 NULL\nfix integ all nve/sphere\nfix 2d all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.01 0.01 0\ncreate_atoms 2 single 0.03 0.01 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density/disc 2500\nrun 100\n")
deck("c03_2d_deposit_default", "# 2d: fix deposit of LAMMPS' default spheres (diameter 1, density 1) into type 2, units lj, hooke\n"
     + "units lj\ndimension 2\natom_style sphere\nboundary p f p\ncomm_modify vel yes\nregion box block 0 20 0 40 -0.5 0.5 units box\ncreate_box 2 box\n"
     + G1(f"hooke 2e4 30 {K}") + f"fix floor all wall/gran granular hooke 2e4 30 {K} yplane 0 NULL\nfix integ all nve/sphere\nfix 2d all enforce2d\ntimestep 1e-4\n"
     + "create_atoms 1 single 5 2 0\nset type 1 diameter 1.5 density 1\nregion top block 0 20 20 38 -0.5 0.5 units box\nfix dep all deposit 5 2 100 12345 region top vy -1 -1 units box\nrun 600\n", g="0.1 1")
deck("c04_liggghts_hertz_e_low_high", "# LIGGGHTS hertz with e 0.05 (1 1), 0.99 (2 2), 0.02 (1 2) and a wall e 0.01: is eps e at the ends of the range?\n"
     + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.05 0.02 0.01 0.02 0.99 0.5 0.01 0.5 0.5\n" + HERTZ + WALL3 + ATOMS + RUN, liggghts=True)
deck("c05_lammps_coeffrest_e_low", "# LAMMPS hertz/material coeff_restitution e 0.05 without limit_damping (the overlap rule) and hooke coeff_restitution 0.05\n"
     + head() + f"pair_style granular\npair_coeff 1 1 hertz/material 1e7 0.05 0.3 damping coeff_restitution {TL}\npair_coeff 2 2 hooke 2000 0.05 damping coeff_restitution {TL}\npair_coeff 1 2 hertz/material 1e7 0.95 0.3 damping coeff_restitution {TL}\n"
     + GRAV + TAIL + TWO + "run 100\n")
deck("c06_no_timestep_units_lj", "# units lj with no timestep command (LAMMPS' default 0.005): hooke 2e4 with mass_velocity, unit spheres: few steps per contact\n"
     + head(units="lj", box="0 20 0 20 0 40") + G1(f"hooke 200 5 {K}") + "fix grav all gravity 1.0 vector 0 0 -1\n" + f"fix floor all wall/gran granular hooke 200 5 {K} zplane 0 NULL\nfix integ all nve/sphere\n"
     + "create_atoms 1 single 5 5 2\ncreate_atoms 2 single 10 10 2\nset type 1 diameter 1 density 1\nset type 2 diameter 1 density 1\nrun 100\n", g="0.1 1")
deck("c07_dmt_cohesion_mixed_to_zero", "# dmt: 1 1 surface energy 0, 2 2 surface energy 0.05; LAMMPS mixes 1 2 (geometric: 0?)\n"
     + head() + f"pair_style granular\npair_coeff 1 1 dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}\npair_coeff 2 2 dmt 1e7 1.4e7 0.3 0.05 damping viscoelastic {TL}\n"
     + GRAV + TAIL + TWO + "run 100\n")
deck("c08_timestep_before_units_reset", "# timestep 1e-6 given before units si (which resets dt to its default 1e-8): the deck's dt\n"
     + "timestep 1e-6\n" + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/sphere\n" + TWO4 + "run 100\n", g=1)
deck("c09_run0_then_runs_in_loop", "# the settings change, run 0, then change back and run 100: the last run's settings are the first's\n"
     + BASE(HK) + TWO + "run 100\npair_coeff * * hooke 9000 3000 " + K + "\nrun 0\npair_coeff * * " + HK + "\nrun 100\n", g=1)
deck("c10_run_upto_zero_steps", "# run 200 upto after run 200 (0 steps: LAMMPS runs none) with changed settings, as the deck's last run\n"
     + BASE(HK) + TWO + "run 200\npair_coeff * * hooke 9000 3000 " + K + "\nrun 200 upto\n", g=1)
deck("c11_pour_diam_range_dens_range_hertzmat", "# fix pour diam range 2-6 mm and dens range 1500-7800 (hertz/material): the extreme eps over a continuum\n"
     + head(box="0 0.04 0 0.04 0 0.2") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
     + "region top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 30 1 4767 region top diam range 0.002 0.006 dens 1500 7800\nrun 1000\n")
deck("c12_liggghts_insert_2d", "# LIGGGHTS 2d (dimension 2) with insert/pack of 3 mm discs: LIGGGHTS' masses in 2d\n"
     + "atom_style granular\natom_modify map array\ndimension 2\nboundary f f p\nnewton off\ncommunicate single vel yes\nunits si\nregion reg block -0.05 0.05 -0.01 0.15 -0.002 0.002 units box\ncreate_box 3 reg\nneighbor 0.002 bin\nneigh_modify delay 0\n"
     + MAT3 + LST + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 yplane 0.0\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 0.04 0.1 -0.002 0.002 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere\nfix e2d all enforce2d\nrun 2000\n", liggghts=True)

deck("c19_star_then_22_no_mix", "# pair_coeff * * hertz/material E 1e7, then pair_coeff 2 2 with E 8e7: 1 2 was set by * * and keeps E 1e7 (LAMMPS mixes only pairs never set)\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\npair_coeff 2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}\n" + GRAV + TAIL + TWO + "run 100\n")
deck("c20_integrator_static_group_before_pour", "# fix nve/sphere on group t1 (type 1 at its making: one created sphere); fix pour then adds type-1 spheres that no fix integrates\n"
     + head(box="0 0.04 0 0.04 0 0.2") + G1(HK) + GRAV + FLOOR + "timestep 1e-5\ncreate_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\ngroup t1 type 1\nfix integ t1 nve/sphere\n"
     + "region top block 0 0.04 0 0.04 0.1 0.2 units box\nfix p all pour 10 1 4767 region top diam one 0.006 dens 2500 2500\nrun 1000\n", g=1)
deck("L32_integrator_static_group_before_insert", "# LIGGGHTS: nve/sphere on group t1 made before insert/pack adds type-1 spheres (not integrated)\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\ngroup t1 type 1\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.003\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr t1 nve/sphere\nrun 2000\n", liggghts=True)

POURB = head(box="0 0.04 0 0.04 0 0.2") + G1(HM) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nregion top block 0 0.04 0 0.04 0.1 0.2 units box\n"
deck("c21_set_atom_all_after_pour_run", "# set atom * diameter 0.005 after a pour run (every atom, poured ones too; mass kept)\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.003 dens 2500 2500\nrun 1000\nunfix p\nset atom * diameter 0.005\nrun 100\n")
deck("c22_two_pour_stages_same_type", "# pour 3 mm spheres into type 2, run; unfix; pour 6 mm spheres into type 2 again, run: stage 2 holds both sizes\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.003 dens 2500 2500\nrun 1000\nunfix p\nfix p2 all pour 10 2 5867 region top diam one 0.006 dens 2500 2500\nrun 1000\n")
deck("c23_deposit_run_shorter_than_interval", "# fix deposit 5 atoms every 500 steps into type 2, but the only run is 100 steps: does LAMMPS insert any?\n"
     + POURB + "fix dep all deposit 5 2 500 12345 region top vz -1 -1 units box\nrun 100\n")

MOLS = {"small.mol": "small\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.003\n\nMasses\n\n1 0.0001\n",
        "big.mol": "big\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"}
deck("c24_deposit_two_templates_molfrac", "# fix deposit of a two-template molecule (3 mm 1e-4 kg, 6 mm 9e-4 kg) with molfrac 0.5 0.5, offset to type 2\n"
     + POURB.replace("create_box 2", "create_box 2") + "molecule two small.mol big.mol\nfix dep all deposit 10 1 50 12345 region top mol two molfrac 0.5 0.5 vz -1 -1 units box\nrun 1000\n",
     data=MOLS)
deck("c25_region_cylinder_x_axis", "# wall/gran/region on a static cylinder along x (side in): its curvature is in the y-z plane\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "region drum cylinder x 0 0 0.03 -0.04 0.04 side in units box\n"
     + "fix dw all wall/gran/region granular " + HM + " region drum\n" + GRAV + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("c26_gran_hertz_history_omp_typed", "# pair_style gran/hertz/history/omp typed (the OpenMP variant) with its wall: same forces as gran/hertz/history\n"
     + "package omp 1\n" + head() + "pair_style gran/hertz/history/omp 1e6 NULL 2000 NULL 0.5 0\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hertz/history 1e6 NULL 2000 NULL 0.5 0 zplane 0 NULL\n" + TAIL + TWO + "run 100\n")
deck("c27_suffix_omp", "# suffix omp before pair_style gran/hooke/history: LAMMPS uses the /omp variant if built with it\n"
     + "package omp 1\nsuffix omp\n" + head() + "pair_style gran/hooke/history 3000 NULL 400 NULL 0.5 0\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 3000 NULL 400 NULL 0.5 0 zplane 0 NULL\n" + TAIL + TWO + "run 100\n")

deck("c28_deposit_interval_longer_than_run", "# fix deposit of a 6 mm template (mol) every 1000 steps into type 2, run 500: does LAMMPS insert any?\n"
     + POURB + "molecule big big.mol\nfix dep all deposit 5 1 1000 12345 region top mol big vz -1 -1 units box\nrun 500\n", data=MOLS)
deck("L33_insert_start_after_run", "# LIGGGHTS insert/pack of 3 mm type-2 spheres with start 100000, the only run 2000 steps: LIGGGHTS inserts none\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every 1000 start 100000 overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)
deck("L34_insert_rate_region_start_after_run", "# LIGGGHTS insert/rate/region of 3 mm type-2 spheres starting at step 5000, the only run 2000 steps\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/rate/region seed 32452867 distributiontemplate pdd nparticles 10 particlerate 1000 insert_every 1000 start 5000 overlapcheck yes region ins\n" + RUN, liggghts=True)
deck("c29_pour_then_run0_only", "# fix pour into type 2, and the deck's only run is run 0: no sphere is poured\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.006 dens 2500 2500\nrun 0\n")

deck("c30_pour_unfixed_before_run", "# fix pour into type 2 defined and unfixed before the first run: nothing is poured\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.006 dens 2500 2500\nunfix p\nrun 500\n")
deck("L35_insert_unfixed_before_run", "# LIGGGHTS insert/pack of type-2 spheres defined and unfixed before the first run: nothing is inserted\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\nunfix ins\n" + RUN, liggghts=True)
deck("L36_insert_start_in_second_run", "# LIGGGHTS insert/pack of type-2 spheres starting at step 3000: run 2000 (none yet), then run 2000 (inserted)\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every 1000 start 3000 overlapcheck yes particles_in_region 10 region ins\n" + RUN
     + "fix m5 all property/global gamman peratomtypepair 3 300 100 100 100 100 150 100 150 200\nrun 2000\n", liggghts=True)

deck("c31_pour_poly_zero_probability", "# fix pour diam poly 2 with probability 0 for 2 mm and 1 for 6 mm: LAMMPS pours 6 mm spheres only\n"
     + POURB + "fix p all pour 10 2 4767 region top diam poly 2 0.002 0.0 0.006 1.0 dens 2500 2500\nrun 1000\n")
deck("L37_distribution_weight_zero", "# LIGGGHTS particledistribution/discrete with weights 0 (2 mm) and 1 (3 mm) into type 2\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.001\nfix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.0015\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.0 pts2 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)

deck("c32_deposit_near_impossible", "# fix deposit of a 6 mm template with near 0.5 (no site in the region is that far from every atom): every attempt fails, nothing deposited\n"
     + POURB + "molecule big big.mol\nfix dep all deposit 3 1 100 12345 region top mol big near 0.5 attempt 5 vz -1 -1 units box\nrun 500\n", data=MOLS)
deck("L38_insert_region_too_small", "# LIGGGHTS insert/pack of 3 mm spheres into a region 2 mm tall (all_in yes): no sphere fits, none inserted\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.05 0.052 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 10 region ins\n" + RUN, liggghts=True)

deck("c34_set_density_before_pour_runs", "# set type 2 density 7800 issued after fix pour but before the run: no type-2 atom exists then, so the poured spheres keep dens 2500\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.006 dens 2500 2500\nset type 2 density 7800\nrun 1000\n")
deck("c35_set_density_between_pour_runs", "# pour 6 mm (dens 2500) into type 2, run 500; set type 2 density 7800 (the poured so far); run 500 more with the pour still on (later ones 2500)\n"
     + POURB + "fix p all pour 10 2 4767 region top diam one 0.006 dens 2500 2500\nrun 500\nset type 2 density 7800\nrun 500\n")

deck("c36_pour_mol_molfrac_zero", "# fix pour of a two-template molecule (3 mm, 6 mm) with molfrac 0.0 1.0 into type 2 (offset 1): only 6 mm spheres poured\n"
     + POURB + "molecule two small.mol big.mol\nfix p all pour 10 1 4767 region top mol two molfrac 0.0 1.0\nrun 1000\n", data=MOLS)
deck("c37_deposit_mol_molfrac_zero", "# fix deposit of the same two-template molecule with molfrac 0.0 1.0: only 6 mm spheres deposited\n"
     + POURB + "molecule two small.mol big.mol\nfix dep all deposit 5 1 100 12345 region top mol two molfrac 0.0 1.0 vz -1 -1 units box\nrun 600\n", data=MOLS)
deck("L39_unused_template", "# LIGGGHTS: a 1 mm type-2 template defined but not in the distribution (only the 1.5 mm one is)\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.001\nfix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.0015\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts2 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)
deck("L40_distribution_zero_weight_other_type", "# LIGGGHTS: a distribution of a type-2 template (weight 1) and a type-3 template (weight 0): no type-3 sphere is made\n"
     + lhead(nt=4) + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 4 " + " ".join(["0.5"]*16) + "\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 4 0.6 0.5 0.7 0.5 0.5 0.4 0.45 0.45 0.7 0.45 0.8 0.3 0.5 0.45 0.3 0.9\n" + HERTZ
     + "fix wprim all wall/gran model hertz tangential history primitive type 4 zplane 0.0\ncreate_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pts2 all particletemplate/sphere 15485867 atom_type 3 density constant 1500 radius constant 0.001\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 1.0 pts2 0.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)

deck("c38_create_atoms_multi_template", "# create_atoms with a molecule ID holding two templates (3 mm, 6 mm): which does LAMMPS create?\n"
     + POURB + "molecule two small.mol big.mol\ncreate_atoms 1 single 0.01 0.01 0.03 mol two 3456\ncreate_atoms 1 single 0.03 0.03 0.03 mol two 3457\nrun 100\n", data=MOLS)
deck("L41_distribution_not_inserted", "# LIGGGHTS: two distributions, pdd1 (1 mm type 2) used by no insertion, pdd2 (1.5 mm type 2) inserted\n"
     + lhead() + MAT3 + LST + LW("hooke/stiffness tangential history") + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.001\nfix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.0015\n"
     + "fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0\nfix pdd2 all particledistribution/discrete 49979687 1 pts2 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\nfix ins all insert/pack seed 32452867 distributiontemplate pdd2 insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, liggghts=True)

deck("v17_coeff_from_elaplong_after_runs", "# kn from elaplong after two runs (300 and 700 steps): LAMMPS' value between runs, used in pair_coeff\n"
     + BASE(HK) + TWO4 + "run 300\nrun 700\nvariable kn equal 2000+elaplong\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("v18_coeff_from_step_after_reset_and_upto", "# reset_timestep 5000 then run 6000 upto (1000 steps): kn = step - 3000 = 3000 after it\n"
     + BASE(HK) + TWO4 + "reset_timestep 5000\nrun 6000 upto\nvariable kn equal step-3000\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)

deck("c39_region_cylinder_open_ends", "# wall/gran/region on a z cylinder (side in) with both flat ends open (open 1 open 2): only its curved side is a wall\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HM) + "region tube cylinder z 0 0 0.03 -0.04 0.04 side in open 1 open 2 units box\n"
     + "fix tw all wall/gran/region granular " + HM + " region tube\n" + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("c40_region_block_open_top", "# wall/gran/region on a block (side in) with its top face open (open 6): five flat faces\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + G1(HK) + "region bx block -0.03 0.03 -0.03 0.03 -0.03 0.03 side in open 6 units box\n"
     + "fix bw all wall/gran/region granular " + HK + " region bx\n" + GRAV + TAIL + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)


def write(name):
    text, g, files, data, lig = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=lig, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
