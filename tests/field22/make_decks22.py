"""Field round 22: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker (helpers as round 21).
Prefixes: t* run-time values (ramp/vdisplace/swiggle/timer/internal/getenv/file/next), s* state commands (change_box,
displace_atoms, group dynamic, reset_atoms, region variables), q* characters (CR, tabs, &, triple quotes), x* misc LAMMPS
(processors, newton, suffix, package), N* LIGGGHTS. Each deck first comment says what it tries. usage: python make_decks22.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the helpers rounds 21-27 share)
from fieldkit.decks import (ATOMS, BASE, DECKS, E3, E3b, FLOOR, G1, GRAV, HERTZ, HK, HM, HOOKE, K, L, LB,  # noqa: E402,F401
                            LRUN, MAT3, PRB, RUN, TAIL, TL, TWO, WALL3, deck, head, hk, lhead)

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
kit.D = D


# ==== decks
# ================================================================ t*: run-time values read after runs (LAMMPS)
RUN3 = "run 300\n"
deck("t01_ramp_between_runs", "# kn = ramp(2000,8000) read by ${} between runs: LAMMPS may refuse ramp outside a run (engine says)\n"
     + BASE() + TWO + RUN3 + "variable kn equal ramp(2000,8000)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t02_ramp_in_run_every", "# run 300 every 100 with a pair_coeff kn $(v_kn) where kn = ramp(2000,8000): the last one at step 300 (kn 8000)\n"
     + BASE() + TWO + "variable kn equal ramp(2000,8000)\nrun 300 every 100 \"pair_coeff * * hooke $(v_kn) 3000 " + K + "\"\nprint \"PROBE end\"\n", g=1)
deck("t03_time_after_timestep_change", "# kn = 2000 + 1e6*time after run 100 at 1e-5 then run 100 at 2e-5: time 3e-3 -> kn 5000\n"
     + BASE() + TWO + "run 100\ntimestep 2e-5\nrun 100\nvariable kn equal 2000+1e6*time\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\ntimestep 1e-5\nrun 100\n", g=1)
deck("t04_elapsed_after_run", "# kn = 2000 + 10*elapsed after run 300: elapsed between runs is the last run's steps? (engine says)\n"
     + BASE() + TWO + RUN3 + "variable kn equal 2000+10*elapsed\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t05_step_after_run_upto", "# run 200, run 500 upto: step 500 -> kn 2000+10*step = 7000\n"
     + BASE() + TWO + "run 200\nrun 500 upto\nvariable kn equal 2000+10*step\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t06_file_var_next_in_run_every", "# variable kn file (2000 3000 4000 5000); run 300 every 100 \"next kn\": three nexts -> kn 5000\n"
     + BASE() + TWO + "variable kn file kn.txt\nrun 300 every 100 \"next kn\"\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1,
     data={"kn.txt": "2000\n3000\n4000\n5000\n"})
deck("t07_index_next_in_run_every_pre", "# variable kn index 2000 4000 6000; run 200 every 100 pre no \"next kn\": two nexts -> 6000\n"
     + BASE() + TWO + "variable kn index 2000 4000 6000\nrun 200 every 100 \"next kn\"\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t08_internal_var", "# variable kn internal 4500 (a style set by commands like fix controller): pair_coeff ${kn}\n"
     + BASE() + TWO + "variable kn internal 4500\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t09_getenv_default", "# variable kn getenv F22KN (unset): empty string; then variable kn2 equal ... uses is_defined? engine says\n"
     + BASE() + TWO + "variable e getenv F22KN_UNSET\nif \"'${e}' == ''\" then \"variable kn equal 4500\" else \"variable kn equal ${e}\"\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t10_fix_ave_time_value", "# fix ave/time of a constant v_one=1 written at step 100; after run kn = 2000+3000*f_av -> 5000\n"
     + BASE() + TWO + "variable one equal 1\nfix av all ave/time 10 10 100 v_one\nrun 100\nvariable kn equal 2000+3000*f_av\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t11_fix_vector_length", "# fix vector stores a value every 10 steps: after run 100, 11 rows; kn = 1000*f_vec[11]? use count through v_ and step\n"
     + BASE() + TWO + "variable s equal step\nfix vec all vector 10 v_s\nrun 100\nvariable kn equal 2000+10*f_vec[11]\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t12_lost_atoms_count", "# an atom thrown up 100 m/s leaves a p p f box (thermo_modify lost ignore): after run count(all)=1 -> kn 2000*count+1000 = 3000\n"
     + BASE() + TWO + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\nvariable kn equal 2000*count(all)+1000\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t13_lost_atoms_only_type_left", "# type 2 atom lost during run; then 'set type 2 density 7800' sets nobody, and create_atoms 2 after with density 1000 (engine says)\n"
     + BASE() + TWO + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\nset type 2 density 7800\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.006\nrun 100\n", g=1)
deck("t14_group_region_after_fall", "# both atoms fall 5000 steps to the floor; group low region (z<0.004) after: only the small type 1 (r 0.002) is low? set group low density 7800\n"
     + BASE() + TWO + "run 5000\nregion low block INF INF INF INF 0 0.0025 units box\ngroup low region low\nset group low density 7800\nrun 100\n", g=1)
deck("t15_group_variable_z_after_fall", "# atom-style variable z<0.0025 after a fall; group low variable; set group low density 7800 (type 1 only)\n"
     + BASE() + TWO + "run 5000\nvariable lowz atom z<0.0025\ngroup low variable lowz\nset group low density 7800\nrun 100\n", g=1)
deck("t16_group_dynamic_set", "# group dynamic with a region: set group of a dynamic group (LAMMPS may refuse set on dynamic? engine says)\n"
     + BASE() + TWO + "region hi block INF INF INF INF 0.005 INF units box\ngroup hi dynamic all region hi\nrun 5000\nset group hi density 7800\nrun 100\n", g=1)
deck("t17_kn_from_xcm_after_fall", "# kn from the height the atoms reach: 2000+1e6*xcm(all,z) after falling (engine says)\n"
     + BASE() + TWO + "run 5000\nvariable kn equal round(2000+1e6*xcm(all,z))\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t18_kn_from_ke_zero_then_run", "# kn from ke after run (nonzero): 2000 if ke==0 else 6000\n"
     + BASE() + TWO + "run 300\nvariable kn equal (ke==0)*2000+(ke>0)*6000\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t19_fix_adapt_diameter_reset_no", "# fix adapt atom diameter v_d reset no, d = ramp(0.004,0.008) over run 100: type 1 grows to 0.008 (mass kept? LAMMPS 'mass yes' default keeps density)\n"
     + BASE() + TWO + "group one type 1\nvariable d equal ramp(0.004,0.008)\nfix grow one adapt 1 atom diameter v_d reset no\nrun 100\nunfix grow\nrun 100\n", g=1)
deck("t20_fix_adapt_diameter_scale", "# fix adapt atom diameter v_s scale yes reset no (s = 1.5 constant): diameter 0.004 -> 0.006 for type 1 at run start\n"
     + BASE() + TWO + "group one type 1\nvariable s equal 1.5\nfix grow one adapt 1 atom diameter v_s scale yes reset no\nrun 100\nunfix grow\nrun 100\n", g=1)
deck("t21_fix_adapt_diameter_no_mass", "# fix adapt atom diameter 0.008 mass no reset no: diameter grows, mass kept (density drops by 8)\n"
     + BASE() + TWO + "group one type 1\nvariable d equal 0.008\nfix grow one adapt 1 atom diameter v_d mass no reset no\nrun 100\nunfix grow\nrun 100\n", g=1)
deck("t22_fix_adapt_pair_granular", "# fix adapt pair granular? (LAMMPS says whether pair granular exposes kn to adapt)\n"
     + BASE() + TWO + "variable k equal 6000\nfix ad all adapt 1 pair granular kn * * v_k reset no\nrun 100\nunfix ad\nrun 100\n", g=1)
deck("t23_displace_random_then_group", "# displace_atoms random (seed) moves atoms, then group by region and set density (deterministic; no run)\n"
     + BASE() + TWO + "displace_atoms all random 0.01 0.01 0 8812 units box\nregion left block 0 0.02 INF INF INF INF units box\ngroup left region left\nset group left density 7800\nrun 100\n", g=1)
deck("t24_change_box_remap_group", "# change_box x final 0 0.08 remap: atom x doubles (0.02 -> 0.04); group right region x>0.03 -> type 1; density 7800\n"
     + BASE() + TWO + "change_box all x final 0 0.08 remap units box\nregion right block 0.03 INF INF INF INF INF units box\ngroup right region right\nset group right density 7800\nrun 100\n", g=1)
deck("t25_velocity_loop_geom_kn", "# velocity create loop geom: kn from vcm of type 1 after velocity create (no run): sign picks kn\n"
     + BASE() + TWO + "velocity all create 1e-3 4928 loop geom\ngroup one type 1\nvariable kn equal (vcm(one,x)>0)*6000+(vcm(one,x)<=0)*2500\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t26_create_atoms_random_count", "# create_atoms 1 random 20 seed with overlap 0.004 maxtry 5: the count made decides kn (engine says)\n"
     + BASE() + TWO + "create_atoms 1 random 20 1234 NULL overlap 0.004 maxtry 5\nvariable kn equal 1000+100*count(all)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t27_create_atoms_random_after_run", "# create_atoms random with overlap after the atoms fell: count depends on where they are (engine says)\n"
     + BASE() + TWO + "run 5000\ncreate_atoms 1 random 30 1234 NULL overlap 0.006 maxtry 3\nvariable kn equal 1000+100*count(all)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t28_region_with_variable", "# region sphere with a variable radius v_r (read at run time); group by it before runs\n"
     + BASE() + TWO + "variable r equal 0.005\nregion s sphere 0.02 0.02 0.01 v_r side in units box\ngroup ins region s\nset group ins density 7800\nrun 100\n", g=1)
deck("t29_region_move_after_run", "# region moving with v_ in z (v_zz = 0.5*time): group by it after run 300 (time 3e-3 -> region at 0.0015)\n"
     + BASE() + TWO + "variable zz equal 10*time\nregion m block INF INF INF INF -0.005 0.005 move NULL NULL v_zz units box\nrun 300\ngroup mv region m\nset group mv density 7800\nrun 100\n", g=1)
deck("t30_step_reset_timestep", "# reset_timestep 1000 then kn = 2000+step -> 3000\n"
     + BASE() + TWO + "run 200\nreset_timestep 1000\nvariable kn equal 2000+step\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t31_swiggle_between_runs", "# kn = 4000 + 1000*swiggle(0,1,1e-3) between runs: LAMMPS may refuse outside run (engine says)\n"
     + BASE() + TWO + RUN3 + "variable kn equal 4000+1000*swiggle(0,1,1e-3)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t32_fix_dt_reset_then_run", "# fix dt/reset changes dt during run 300; after unfix, the next run keeps the reset dt (steps per contact note)\n"
     + BASE() + TWO + "fix dtr all dt/reset 1 1e-7 1e-4 1e-3 units box\nrun 300\nunfix dtr\nvariable d equal dt\nprint \"PROBE dt $(dt)\"\nrun 100\n", g=1)
deck("t33_kn_from_dt_after_dtreset", "# kn = 1e8*dt after fix dt/reset ran (engine says dt)\n"
     + BASE() + TWO + "fix dtr all dt/reset 1 1e-7 1e-4 1e-3 units box\nrun 300\nunfix dtr\nvariable kn equal round(1e8*dt)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t34_atom_var_sum_after_run", "# kn from the count of atoms with vz<0 after run (both fall): 2000+2000*count\n"
     + BASE() + TWO + "run 300\nvariable neg atom vz<0\ncompute cn all reduce sum v_neg\nthermo_style custom step c_cn\nrun 0\nvariable kn equal 2000+2000*c_cn\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("t35_mass_after_set_in_run_every", "# run 200 every 100 \"set type 2 density 7800\" then run 100\n"
     + BASE() + TWO + "run 200 every 100 \"set type 2 density 7800\"\nrun 100\n", g=1)
deck("t36_pair_coeff_in_run_every_pre", "# run 200 every 100 \"pair_coeff * * hooke 6000 ...\": the last stage kn 6000\n"
     + BASE() + TWO + "run 200 every 100 \"pair_coeff * * " + hk(6000) + "\"\nrun 100\n", g=1)
# ================================================================ q*: characters
_b = BASE() + TWO
deck("q01_crlf_whole_deck", "# the whole deck with CRLF line ends (Windows); pair_coeff kn 5000 before the run\n"
     .replace("\n", "\r\n") + (_b + "pair_coeff * * " + hk(5000) + "\nrun 100\n").replace("\n", "\r\n"), g=1)
deck("q02_cr_only_deck", "# old-Mac CR-only line ends: LAMMPS reads one long line, a comment (engine says)\n"
     .replace("\n", "\r") + (_b + "pair_coeff * * " + hk(5000) + "\nrun 100\n").replace("\n", "\r"), g=1)
deck("q03_amp_trailing_spaces", "# continuation & followed by trailing spaces: LAMMPS joins (kn 5000 with damping on the next line)\n"
     + _b + "pair_coeff * * hooke 5000 3000 &   \n  " + K + "\nrun 100\n", g=1)
deck("q04_amp_crlf_in_lf_deck", "# one pair_coeff line ending '&\\r\\n' in an LF deck: does LAMMPS continue it? (engine says)\n"
     + _b + "pair_coeff * * hooke 5000 3000 &\r\n  " + K + "\nrun 100\n", g=1)
deck("q05_amp_then_comment", "# 'pair_coeff ... & # note' then the next line: the & is not last, LAMMPS does not join (engine says)\n"
     + _b + "pair_coeff * * " + hk(5000) + " # & note\npair_coeff 1 1 " + hk(7000) + "\nrun 100\n", g=1)
deck("q06_triple_quote_if_hash", "# if with a triple-quoted body holding a # comment line and two commands (kn 5500 for all, 1 1 kn 8000)\n"
     + _b + "if \"1 > 0\" then \"\"\"\n# stiffer\npair_coeff * * " + hk(5500) + "\npair_coeff 1 1 " + hk(8000) + "\n\"\"\"\nrun 100\n", g=1)
deck("q07_quoted_var_late_subst", "# variable a string \"${kn}\" (quoted: substituted late); kn redefined to 7000 before ${a} is used -> 7000\n"
     + _b + "variable kn equal 3000\nvariable a string \"${kn}\"\nvariable kn delete\nvariable kn equal 7000\nprint \"PROBE a ${a}\"\npair_coeff * * hooke ${a} 3000 " + K + "\nrun 100\n", g=1)
deck("q08_hash_in_single_quotes_if", "# if with a single-quoted body holding #: 'pair_coeff ... 6000 # x' runs with kn 6000\n"
     + _b + "if \"1 > 0\" then 'pair_coeff * * " + hk(6000) + " # x'\nrun 100\n", g=1)
deck("q09_tab_before_hash", "# a tab then # starts a comment mid-line: pair_coeff ...\\t# 9000 (kn 5000)\n"
     + _b + "pair_coeff * * " + hk(5000) + "\t# was hooke 9000\nrun 100\n", g=1)
deck("q10_amp_comment_amp", "# a comment line ending in & after a continued pair_coeff: 'pair_coeff ... &' / '# comment &' / 'tangential ...'? (engine says)\n"
     + _b + "pair_coeff * * hooke 5000 3000 damping mass_velocity &\n# the tangential part &\ntangential linear_nohistory 1 0.3\nrun 100\n", g=1)
deck("q11_dollar_immediate_in_quotes", "# print with $() inside quotes; variable kn string \"$(2000*3)\" (quoted: literal until used) -> 6000\n"
     + _b + "variable kn string \"$(2000*3)\"\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("q12_label_crlf_jump", "# jump SELF skip with a CRLF 'label skip\\r': LAMMPS finds the label? (engine says; kn 5000 skipped to keep 2000)\n"
     + _b + "jump SELF skip\npair_coeff * * " + hk(5000) + "\nlabel skip\r\nrun 100\n", g=1)
deck("q13_nested_quotes_if_variable", "# if with a nested quoted variable: if \"${a} == 1\" then \"variable kn equal 6000\" 'print x'\n"
     + _b + "variable a equal 1\nvariable kn equal 2000\nif \"${a} == 1\" then \"variable kn delete\" \"variable kn equal 6000\" 'print \"PROBE took\"'\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("q14_formfeed_vtab", "# a form feed and vertical tab between words (whitespace to LAMMPS? engine says); kn 5000\n"
     + _b + "pair_coeff * *\fhooke\v5000 3000 " + K + "\nrun 100\n", g=1)
deck("q15_utf8_minus_in_number", "# Unicode minus U+2212 in the gravity vector (a copied PDF): LAMMPS maps it to '-'? (engine says)\n"
     + head() + G1(HK) + "fix grav all gravity 9.81 vector 0 0 \u22121\n" + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("q16_nbsp_in_number_kn", "# kn written '5\u00a0000' (NBSP as thousands separator): LAMMPS splits into 5 and 000? (engine says)\n"
     + _b + "pair_coeff * * hooke 5\u00a0000 3000 " + K + "\nrun 100\n", g=1)
deck("q17_include_crlf", "# an included file with CRLF ends holding pair_coeff kn 5000\n"
     + _b + "include in.c\nrun 100\n", g=1, data={"in.c": ("pair_coeff * * " + hk(5000) + "\n").replace("\n", "\r\n")})
deck("q18_multi_line_if_amp", "# an if split by & over three lines with then/else bodies: else sets 4500\n"
     + _b + "if \"0 > 1\" &\n then \"pair_coeff * * " + hk(7000) + "\" &\n else \"pair_coeff * * " + hk(4500) + "\"\nrun 100\n", g=1)

# ================================================================ x*: misc LAMMPS settings
deck("x01_processors_newton_on", "# processors * * 1 and newton on; kn 5000\n"
     + head(extra="processors * * 1\nnewton on\n") + G1(hk(5000)) + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("x02_suffix_omp_package", "# package omp 1 + suffix omp: pair granular/omp? (engine says); kn 5000\n"
     + "package omp 1\nsuffix omp\n" + head() + G1(hk(5000)) + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("x03_suffix_off_on", "# suffix omp, then suffix off before pair_style; kn 5000\n"
     + "package omp 1\nsuffix omp\n" + head() + "suffix off\n" + G1(hk(5000)) + "suffix on\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("x04_wall_wiggle", "# a floor that wiggles in z (amplitude 1 mm, period 1e-3 s): wall speed up to 6 m/s (engine says; audit should name it)\n"
     + head() + G1(HK) + GRAV + f"fix floor all wall/gran granular {HK} zplane 0 NULL wiggle z 0.001 1e-3\n" + TAIL + TWO + "run 100\n", g=1)
deck("x05_pair_granular_two_types_coeff_after_run_every", "# pair_coeff 1 2 changed in a run every with an if on step: at step 200 kn 8000 for 1 2\n"
     + BASE() + TWO + "variable s equal step\nrun 200 every 100 \"if '${s} >= 200' then 'pair_coeff 1 2 " + hk(8000) + "'\"\nrun 100\n", g=1)
deck("x06_atom_style_hybrid_sphere", "# atom_style hybrid sphere bond? (sphere with a second style) kn 5000\n"
     + head(style="hybrid sphere 1 molecular") .replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1") + G1(hk(5000)) + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("x07_set_mass_sphere", "# set type 2 mass 1e-4 (sphere: per-atom rmass set directly): m2 = 1e-4 kg\n"
     + BASE() + TWO + "set type 2 mass 1e-4\nrun 100\n", g=1)
deck("x08_set_diameter_by_variable_atom", "# set type 2 diameter v_d with an atom-style d = 0.002+0.1*z (z=0.01 -> 0.003)\n"
     + BASE() + TWO + "variable d atom 0.002+0.1*z\nset type 2 diameter v_d\nrun 100\n", g=1)
deck("x09_set_diameter_atom_var_after_run", "# set type 2 diameter v_d with d = 0.002+0.1*z AFTER atoms fell (z=0.003 -> 0.0023; then radius changed) (engine says)\n"
     + BASE() + TWO + "run 5000\nvariable d atom 0.002+0.1*z\nset type 2 diameter v_d\nrun 100\n", g=1)
deck("x10_set_density_atom_var_vz", "# set type 2 density v_r with r = 2500+1e4*abs(vz) after a run 300 (type 2 falls at 0.03 m/s -> 2800) (engine says)\n"
     + BASE() + TWO + "run 300\nvariable r atom 2500+1e4*abs(vz)\nset type 2 density v_r\nrun 100\n", g=1)
deck("x11_set_type_fraction", "# set type 1 type/fraction 2 0.5 seed: which atoms change type (one atom of type 1) (engine says)\n"
     + BASE() + TWO + "set type 1 type/fraction 2 0.5 4321\nrun 100\n", g=1)
deck("x12_set_type_after_run_region", "# after falling, set region low type 2: the small sphere (type 1, 4 mm) becomes type 2 (then 'set type 2 diameter 0.006' not repeated)\n"
     + BASE() + TWO + "run 5000\nregion low block INF INF INF INF 0 0.0025 units box\nset region low type 2\nrun 100\n", g=1)
# ================================================================ N*: LIGGGHTS
L("N01_crlf_liggghts", "# LIGGGHTS deck with CRLF line ends; e matrix 0.6/0.5/0.4 (engine says if it runs)\n".replace("\n", "\r\n")
  + (LB() + ATOMS + RUN).replace("\n", "\r\n"))
L("N02_nbsp_end_of_e_line", "# LIGGGHTS: a NBSP at the end of the e matrix line ('0.8\u00a0'): LIGGGHTS reads 0.8? (engine says)\n"
  + lhead() + MAT3 + E3.replace("0.8\n", "0.8\u00a0\n") + HERTZ + WALL3 + ATOMS + RUN)
L("N03_utf8_comment", "# LIGGGHTS: a comment with UTF-8 (é, µ, →) and a trailing comment on the e line: e 0.6/0.5/0.4\n"
  + lhead() + MAT3 + E3.replace("\n", " # e für Glas → µ\n") + HERTZ + WALL3 + ATOMS + RUN)
L("N04_e_from_step_after_run", "# LIGGGHTS: e = 0.2+0.0001*step after run 1000 -> 0.3 everywhere for the next run\n"
  + LB() + ATOMS + LRUN + "run 1000\nvariable e equal 0.2+0.0001*step\nprint \"PROBE e ${e}\"\n" + "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\n")
L("N05_rolling_friction_cdt", "# LIGGGHTS hertz with rolling_friction cdt (coefficientRollingFriction): no part in the normal eps (0.6/0.5/0.4)\n"
  + lhead() + MAT3 + E3 + "fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
  + "pair_style gran model hertz tangential history rolling_friction cdt\npair_coeff * *\n" + WALL3 + ATOMS + RUN)
L("N06_modify_timing_contact_distance", "# LIGGGHTS modify_timing on and neigh_modify contact_distance_factor 1.2: no effect on eps\n"
  + lhead() + "modify_timing on\nneigh_modify contact_distance_factor 1.2\n" + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("N07_processors_liggghts", "# LIGGGHTS processors * * 1 (one process): e as typed\n"
  + lhead().replace("units si\n", "units si\nprocessors * * 1\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("N08_dimension2_liggghts", "# LIGGGHTS 2d (dimension 2, boundary p p p? f f p): hertz typed e 0.6/0.5/0.4 (engine says)\n"
  + "dimension 2\n" + lhead(box="-0.05 0.05 -0.01 0.15 -0.005 0.005", bnd="f f p") + MAT3 + E3 + HERTZ
  + "fix wprim all wall/gran model hertz tangential history primitive type 3 yplane 0.0\nfix e2d all enforce2d\n"
  + "create_atoms 1 single 0.01 0.01 0 units box\ncreate_atoms 2 single -0.01 0.01 0 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
  + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere\nrun 1000\n")
L("N09_mesh_wall_curving_angle", "# LIGGGHTS mesh wall (a square floor from an STL, curvature_tolerant / curving angle) type 3: e 0.7 for 1 on wall\n"
  + lhead() + MAT3 + E3 + HERTZ
  + "fix cad all mesh/surface file floor.stl type 3 curvature 1e-5\nfix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n" + ATOMS + RUN,
  data={"floor.stl": "solid f\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 -0.05 0\nvertex 0.05 0.05 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 0.05 0\nvertex -0.05 0.05 0\nendloop\nendfacet\nendsolid f\n"})
L("N10_heat_gran", "# LIGGGHTS fix heat/gran with thermal properties: no part in eps\n"
  + lhead() + MAT3 + E3 + "fix ftco all property/global thermalConductivity peratomtype 1 1 1\nfix ftca all property/global thermalCapacity peratomtype 1 1 1\n"
  + HERTZ + WALL3 + ATOMS + "fix heattransfer all heat/gran initial_temperature 300\n" + RUN)
L("N11_e_redefined_in_include_after_run", "# LIGGGHTS: run 1000, include in.e (e 0.3), run 100: the last stage e 0.3\n"
  + LB() + ATOMS + LRUN + "run 1000\ninclude in.e\nrun 100\n", data={"in.e": E3b(0.3)})
L("N12_e_index_next_jump_loop", "# LIGGGHTS: loop over e (index 0.3 0.5 0.7) with run 100 / next / jump: the last stage e 0.7\n"
  + LB() + ATOMS + LRUN + "variable e index 0.3 0.5 0.7\nlabel lp\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\nnext e\njump SELF lp\n")
L("N13_e_tabs_amp", "# LIGGGHTS: the e matrix over three lines with & and tabs (row per line): 0.6/0.5/0.4\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 &\n\t0.6 0.5 0.7 &\n\t0.5 0.4 0.45 &\n\t0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N14_e_amp_comment_line_between", "# LIGGGHTS: e matrix continued with & and a comment line between rows: LIGGGHTS joins the comment (the rest is a comment)? (engine says)\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 &\n0.6 0.5 0.7 &\n# row 2 &\n0.5 0.4 0.45 &\n0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N15_e_from_count_after_run_lost", "# LIGGGHTS: an atom thrown out of a f f f box (thermo_modify lost ignore); e = 0.2*count(all) after -> 0.2\n"
  + LB() + ATOMS + LRUN + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 200\nrun 1000\nvariable e equal 0.2*count(all)\nprint \"PROBE e ${e}\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\n")
L("N16_e_from_fix_ave_time", "# LIGGGHTS: fix ave/time of v_one (=1) at step 100; e = 0.3*f_av after run -> 0.3\n"
  + LB() + ATOMS + LRUN + "variable one equal 1\nfix av all ave/time 10 10 100 v_one\nrun 100\nvariable e equal 0.3*f_av\nprint \"PROBE e ${e}\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\n")
L("N17_hooke_stiffness_ramp_no", "# LIGGGHTS hooke/stiffness with kn/kt/gamman typed (absolute_damping off): eps from kn, gamman, masses (audit computes)\n"
  + lhead() + MAT3 + "fix k1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix k2 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
  + "fix k3 all property/global gamman peratomtypepair 3 500 500 500 500 500 500 500 500 500\nfix k4 all property/global gammat peratomtypepair 3 500 500 500 500 500 500 500 500 500\n"
  + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\nfix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("N18_e_if_on_step_after_run", "# LIGGGHTS: run 1000, then if \"${s} > 500\" then (e 0.3 matrix): s equal step -> e 0.3\n"
  + LB() + ATOMS + LRUN + "variable s equal step\nrun 1000\nif \"${s} > 500\" then \"" + E3b(0.3).strip() + "\"\nrun 100\n")


# ================================================================ w*: variants of the round's finds (added after the first 84)
RHI = "region hi block INF INF INF INF 0.005 INF units box\n"
deck("w01_group_dynamic_set_before_run", "# group dynamic then set group at once (no run yet): LAMMPS' membership before any run (engine says)\n"
     + BASE() + TWO + RHI + "group hi dynamic all region hi\nset group hi density 7800\nrun 100\n", g=1)
deck("w02_group_dynamic_var_every", "# group dynamic all var v_up every 10 (atom-style z>0.005); run 5000 (falls); set group up density 7800 (nobody in the engine)\n"
     + BASE() + TWO + "variable up atom z>0.005\ngroup up dynamic all var up every 10\nrun 5000\nset group up density 7800\nrun 100\n", g=1)
deck("w03_group_union_of_dynamic", "# a static group copied (union) from a dynamic group after the fall: empty in the engine; set density 7800\n"
     + BASE() + TWO + RHI + "group hi dynamic all region hi\nrun 5000\ngroup cp union hi\nset group cp density 7800\nrun 100\n", g=1)
deck("w04_group_dynamic_static_after", "# dynamic group after the fall, then group hi static (freezes the engine's membership: empty), set density 7800\n"
     + BASE() + TWO + RHI + "group hi dynamic all region hi\nrun 5000\ngroup hi static\nset group hi density 7800\nrun 100\n", g=1)
deck("w05_group_dynamic_pair_stage", "# dynamic group after the fall used by set group ... type 2 (the engine changes nobody's type)\n"
     + BASE() + TWO + RHI + "group hi dynamic all region hi\nrun 5000\nset group hi type 2\nset type 2 density 7800\nrun 100\n", g=1)
deck("w06_lost_then_new_atom_own_density", "# type 2 sphere lost (thermo_modify lost ignore); a new type 2 with diameter 0.006 density 1000 set by atom id 3\n"
     + BASE() + TWO + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset atom 3 diameter 0.006 density 1000\nrun 100\n", g=1)
deck("w07_lost_then_set_type_density", "# the type 2 sphere lost; a new type 2 atom made; set type 2 diameter 0.008 density 1000 (both in the audit's pass, one in the engine)\n"
     + BASE() + TWO + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.008 density 1000\nrun 100\n", g=1)
deck("w08_lost_boundary_m_shrinkwrap", "# boundary p p m: the thrown sphere stays (shrink-wrapped box grows); kn from count 2 -> 5000 (no loss)\n"
     + head(bnd="p p m") + G1(HK) + GRAV + FLOOR + TAIL + TWO + "group up type 2\nvelocity up set 0 0 100\nrun 300\nvariable kn equal 2000*count(all)+1000\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("w09_fix_halt_continue_step", "# fix halt at step > 150 (continue): run 300 stops at 160; kn = 2000+10*step -> 3600 in the engine\n"
     + BASE() + TWO + "variable s equal step\nfix h all halt 10 v_s > 150 error continue\nrun 300\nunfix h\nvariable kn equal 2000+10*step\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("w10_dt_reset_time", "# fix dt/reset during run 300 then kn = 2000+1e5*time (time accumulates with the varying dt)\n"
     + BASE() + TWO + "fix dtr all dt/reset 1 1e-7 1e-4 1e-3 units box\nrun 300\nunfix dtr\ntimestep 1e-5\nvariable kn equal round(2000+1e5*time)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("w11_fix_halt_continue_if_step", "# fix halt stops run 300 at 160; if \"${s} < 300\" then pair_coeff kn 6000 (the engine takes it)\n"
     + BASE() + TWO + "variable s equal step\nfix h all halt 10 v_s > 150 error continue\nrun 300\nunfix h\nif \"${s} < 300\" then \"pair_coeff * * " + hk(6000) + "\"\nrun 100\n", g=1)
deck("w12_lost_atoms_dynamic_region_delete", "# lost atom (p p f, lost ignore), then 'set type 2 density 7800' and a new type 2 atom with default density 1 and diameter 1 -> set diameter only\n"
     + BASE() + TWO + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\nset type 2 density 7800\ncreate_atoms 2 single 0.01 0.01 0.05\nset atom 3 diameter 0.006 density 2500\nrun 100\n", g=1)


# ================================================================ y*: more variants (line separators, losses, region walls)
_b = BASE() + TWO
deck("y01_comment_lone_cr_command", "# a comment line ending in a lone CR (no LF) before pair_coeff kn 5000: LAMMPS reads one comment line (kn 2000 stays)\n"
     + _b + "# stiffer contacts\rpair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("y02_trailing_comment_lone_cr", "# pair_coeff kn 5000 # old: ...<CR>pair_coeff kn 2000: LAMMPS strips the comment and the CR'd rest (kn 5000)\n"
     + _b + "pair_coeff * * " + hk(5000) + " # old value\rpair_coeff * * " + hk(2000) + "\nrun 100\n", g=1)
deck("y03_comment_u2028_command", "# a comment, U+2028 LINE SEPARATOR, then pair_coeff kn 5000 (one line to LAMMPS: a comment; kn 2000)\n"
     + _b + "# stiffer\u2028pair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("y04_comment_nel_command", "# a comment, U+0085 NEXT LINE, then pair_coeff kn 5000 (one line to LAMMPS: a comment; kn 2000)\n"
     + _b + "# stiffer\u0085pair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("y05_include_cr_only", "# an include whose lines end in CR alone: '# settings<CR>pair_coeff kn 5000<CR>' is one comment line to LAMMPS (kn 2000)\n"
     + _b + "include in.c\nrun 100\n", g=1, data={"in.c": "# settings\rpair_coeff * * " + hk(5000) + "\r"})
deck("y06_comment_formfeed_command", "# a comment, form feed, then pair_coeff kn 5000 (one line to LAMMPS: a comment; kn 2000)\n"
     + _b + "# stiffer\fpair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("y07_comment_vt_u2029", "# a comment, U+2029 PARAGRAPH SEPARATOR, then pair_coeff kn 5000 (kn 2000 in LAMMPS)\n"
     + _b + "# stiffer\u2029pair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("y08_fix_evaporate_then_set", "# fix evaporate removes the type 2 sphere during the run (region around it); then create_atoms 2 + set atom 3 / set type 2 density 1000\n"
     + _b + "region ev block 0 0.015 0 0.015 INF INF units box\nfix ev all evaporate 10 1 ev 4711\nrun 100\nunfix ev\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.006 density 1000\nrun 100\n", g=1)
deck("y09_lost_type_gone_stage", "# the only type 2 sphere lost (lost ignore); pair_coeff 1 2 changes to kn 8000 for the next run: no 1 2 pair in the engine\n"
     + _b + "thermo_modify lost ignore\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\npair_coeff 1 2 " + hk(8000) + "\nrun 100\n", g=1)
deck("y10_wall_gran_region", "# fix wall/gran/region granular hooke kn 2000 on the box's region (flat faces) instead of a zplane wall\n"
     + head() + G1(HK) + GRAV + f"region wb block 0 0.04 0 0.04 0 0.1 side in units box\nfix floor all wall/gran/region granular {HK} region wb\n" + TAIL + TWO + "run 100\n", g=1)
deck("y11_group_dynamic_delete_atoms", "# delete_atoms group hi (dynamic, empty after the fall): the engine deletes nobody\n"
     + _b + "region hi block INF INF INF INF 0.005 INF units box\ngroup hi dynamic all region hi\nrun 5000\ndelete_atoms group hi\nset type 2 density 7800\nrun 100\n", g=1)
deck("y12_group_dynamic_set_diameter", "# set group hi diameter 0.008 (dynamic, after the fall: nobody in the engine)\n"
     + _b + "region hi block INF INF INF INF 0.005 INF units box\ngroup hi dynamic all region hi\nrun 5000\nset group hi diameter 0.008\nrun 100\n", g=1)
deck("y13_group_dynamic_run_every_refresh", "# dynamic group in a region the spheres fall INTO (z<0.005): empty at definition, both at the end; set group low density 7800\n"
     + _b + "region low block INF INF INF INF 0 0.005 units box\ngroup low dynamic all region low\nrun 5000\nset group low density 7800\nrun 100\n", g=1)
L("y14_liggghts_comment_lone_cr", "# LIGGGHTS: a comment ending in a lone CR before the e 0.2 matrix: one comment line to LIGGGHTS (e 0.6 ... stays)\n"
  + lhead() + MAT3 + E3 + "# softer\r" + E3b(0.2) + HERTZ + WALL3 + ATOMS + RUN)


# ================================================================ z*: bytes (NUL, Latin-1), atom ids after runs
_b = BASE() + TWO
deck("z01_nul_before_pair_coeff", "# a NUL byte opens the pair_coeff kn 5000 line: LAMMPS reads the line as empty (kn 2000) (engine says)\n"
     + _b + "\0pair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("z02_latin1_comment", "# Durchmesser f\u00fcr Glas (this comment in Latin-1 bytes, not UTF-8): kn 5000 after it\n"
     + _b + "pair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
L("z03_latin1_comment_liggghts", "# LIGGGHTS: Durchmesser f\u00fcr Glas (Latin-1 bytes) and e 0.2 after it\n"
  + lhead() + MAT3 + E3b(0.2) + HERTZ + WALL3 + ATOMS + RUN)
deck("z04_reset_atoms_sort_after_run", "# type 1 moves from y 0.03 to y 0.005 in run 100; reset_atoms id sort yes renumbers by place: set atom 1 density 7800 hits type 1 in the engine (type 2 before the run)\n"
     + head() + G1(HK) + FLOOR + TAIL + "create_atoms 1 single 0.01 0.03 0.01\ncreate_atoms 2 single 0.03 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "group one type 1\nvelocity one set 0 -25 0\nrun 100\nvelocity all set 0 0 0\nreset_atoms id sort yes\nset atom 1 density 7800\nrun 100\n", g=1)
deck("z05_lost_then_reset_atoms_id", "# atom 1 (type 1) lost in the run (lost ignore); reset_atoms id renumbers the type 2 atom to 1; set atom 1 density 7800 (type 2 in the engine)\n"
     + _b + "thermo_modify lost ignore\ngroup one type 1\nvelocity one set 0 0 100\nrun 300\nreset_atoms id\nset atom 1 density 7800\ncreate_atoms 1 single 0.03 0.03 0.05\nset type 1 diameter 0.004 density 2500\nrun 100\n", g=1)
deck("z06_lost_warn_set_type", "# thermo_modify lost warn: the type 2 sphere lost with a warning; then create_atoms 2 and set atom 2 density 1000 (the new atom has id 2 in the engine)\n"
     + _b + "thermo_modify lost warn\ngroup up type 2\nvelocity up set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.006 density 2500\nset atom 2 density 1000\nrun 100\n", g=1)

# ================================================================ v*: last variants (discharge, atom/swap, CR mid-command)
deck("v01_discharge_lost_big_sphere", "# hopper-like discharge: no floor in run 1 (10000 steps), the 8 mm type 1 sphere falls out of the open bottom (lost ignore), the 4 mm one is held; then a floor and run 2: only 4 mm type 1 spheres remain\n"
     + head() + G1(HK) + GRAV + TAIL + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.01 0.01 0.05\nset atom 1 diameter 0.008 density 2500\nset atom 2 diameter 0.004 density 2500\n"
     + "create_atoms 2 single 0.03 0.03 0.05\nset type 2 diameter 0.006 density 2500\nthermo_modify lost ignore\ngroup held id 2 3\nfix hold held setforce 0 0 0\nrun 10000\nunfix hold\n"
     + f"fix floor all wall/gran granular {HK} zplane 0 NULL\nrun 100\n", g=1)
deck("v02_atom_swap_then_set_type", "# fix atom/swap (MC) swaps the types of the 4 mm (type 1) and 6 mm (type 2) spheres once (run 10, every 10); then set type 2 density 7800 hits the 4 mm sphere in the engine\n"
     + BASE() + TWO + "fix sw all atom/swap 10 1 1234 1.0 types 1 2\nrun 10\nunfix sw\nset type 2 density 7800\nrun 100\n", g=1)
deck("v03_lone_cr_mid_command", "# a lone CR inside a pair_coeff (between damping and tangential): whitespace to LAMMPS (kn 5000 runs)\n"
     + BASE() + TWO + "pair_coeff * * hooke 5000 3000 damping mass_velocity\rtangential linear_nohistory 1 0.3\nrun 100\n", g=1)
deck("v04_lone_cr_after_amp", "# 'pair_coeff ... damping mass_velocity &<CR>tangential ...<LF>': to LAMMPS the & is not last (CR follows) (engine says)\n"
     + BASE() + TWO + "pair_coeff * * hooke 5000 3000 damping mass_velocity &\rtangential linear_nohistory 1 0.3\nrun 100\n", g=1)

deck("z07_reset_atoms_sort_order_flips", "# type 1 (id 1) at y 0.01, type 2 (id 2) at y 0.03 moving to y 0.005 in run 100; reset_atoms id sort yes gives id 1 to the type 2 sphere; set atom 1 density 7800 (type 2 in the engine)\n"
     + head() + G1(HK) + FLOOR + TAIL + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "group two type 2\nvelocity two set 0 -25 0\nrun 100\nvelocity all set 0 0 0\nreset_atoms id sort yes\nset atom 1 density 7800\nrun 100\n", g=1)
deck("z08_evaporate_then_reset_ids", "# fix evaporate removes the type 1 sphere (id 1) in run 1; reset_atoms id makes the type 2 sphere id 1; set atom 1 density 7800 (type 2 in the engine)\n"
     + BASE() + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
     + "region ev block 0 0.015 0 0.015 INF INF units box\nfix ev all evaporate 10 1 ev 4711\nrun 100\nunfix ev\nreset_atoms id\nset atom 1 density 7800\ncreate_atoms 1 single 0.01 0.01 0.05\nset type 1 diameter 0.004 density 2500\nrun 100\n", g=1)

L("y15_liggghts_include_cr_only", "# LIGGGHTS: an include whose lines end in CR alone ('# softer<CR>fix m3 ... e 0.2<CR>'): one comment line to LIGGGHTS (e 0.6 ... stays)\n"
  + lhead() + MAT3 + E3 + "include in.e\n" + HERTZ + WALL3 + ATOMS + RUN, data={"in.e": "# softer\r" + E3b(0.2).strip() + "\r"})
L("y16_liggghts_trailing_comment_cr", "# LIGGGHTS: 'fix m3 ... e 0.2 # old<CR>fix m3 ... e 0.6 matrix': LIGGGHTS strips the comment and the rest (e 0.2)\n"
  + lhead() + MAT3 + E3b(0.2).strip() + " # old\r" + E3 + HERTZ + WALL3 + ATOMS + RUN)

kit.LATIN1.update({"z02_latin1_comment", "z03_latin1_comment_liggghts"})  # written in Latin-1 bytes (an old editor)


if __name__ == "__main__":
    kit.main(sys.argv[1:])
