"""Field round 21: write the decks as decks/NAME/in.deck with G (the speeds), extra files and a LIGGGHTS marker.
Prefixes: a* comments/continuation/UTF-8 text, r* what runs change read back (energies, positions, counts, files),
v* variable styles and functions, l* labels and type labels, c* control flow (quit, jump, include, loops),
f* fixes beside the contact, u* units/2d/time step, k* shell/escape (files outside the scratch copy),
d* data files and restart round trips, N* LIGGGHTS. Each deck's first comment says what it tries and what the engine
does (PROBE lines print the engine's own values). usage: python make_decks21.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the helpers rounds 21-27 share)
from fieldkit.decks import (ATOMS, BASE, DECKS, E3, E3b, FLOOR, G1, GRAV, HERTZ, HK, HM, HOOKE, K, L, LB,  # noqa: E402,F401
                            LRUN, MAT3, PRB, RUN, TAIL, TL, TWO, WALL3, deck, head, hk, lhead)

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
kit.D = D

# ================================================================ a*: comments, continuation, UTF-8, quoting
deck("a01_comment_ending_amp_swallows_next", "# a comment line ending in & joins the next line to it: LAMMPS never runs the pair_coeff kn 9000 below (kn 2000 stays)\n"
     + BASE() + "# stiffer contacts for the production run &\npair_coeff * * " + hk(9000) + "\n" + TWO + "run 100\n", g=1)
deck("a02_trailing_comment_amp", "# a pair_coeff whose trailing comment ends in &: the next line (pair_coeff 1 1 kn 9000) joins the comment and never runs\n"
     + BASE() + "pair_coeff * * " + hk(3000) + "  # was 9000 for 1 1 &\npair_coeff 1 1 " + hk(9000) + "\n" + TWO + "run 100\n", g=1)
deck("a03_amp_then_blank_line", "# a pair_coeff ending in & followed by an empty line: LAMMPS joins the empty line and runs pair_coeff kn 5000\n"
     + BASE() + "pair_coeff * * " + hk(5000) + " &\n\n" + TWO + "run 100\n", g=1)
deck("a04_nbsp_in_pair_coeff", "# non-breaking spaces (UTF-8 C2 A0, from a PDF) between words: LAMMPS substitutes them by spaces (kn 6000)\n"
     + BASE() + "pair_coeff\u00a0*\u00a0*\u00a0hooke\u00a06000 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("a05_smart_quotes_if", "# if with typographic quotes (“ ” from a word processor): LAMMPS turns them into \" and takes the then branch (kn 7000)\n"
     + BASE() + "if \u201c1 > 0\u201d then \u201cpair_coeff * * " + hk(7000) + "\u201d\n" + TWO + "run 100\n", g=1)
deck("a06_smart_single_quotes_print", "# a variable defined with typographic single quotes ‘2000*4’: LAMMPS makes them ' and evaluates 8000\n"
     + BASE() + "variable kn equal \u20182000*4\u2019\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("a07_hash_inside_quotes", "# a # inside a quoted if command is not a comment: the then branch sets kn 6500 (the text after # is part of it)\n"
     + BASE() + "if \"1 > 0\" then \"pair_coeff * * " + hk(6500) + " # stiffer\"\n" + TWO + "run 100\n", g=1)
deck("a08_variable_with_hash_string", "# a string variable holding 'hooke 4000 3000' substituted into pair_coeff (words split after substitution)\n"
     + BASE() + "variable law string \"hooke 4000 3000\"\npair_coeff * * ${law} " + K + "\n" + TWO + "run 100\n", g=1)
deck("a09_tab_separated_and_amp_mid", "# tabs between words, a & continuation in the middle of the damping keywords (kn 4200)\n"
     + BASE() + "pair_coeff\t*\t*\thooke\t4200\t3000\tdamping &\n   mass_velocity tangential linear_nohistory 1 0.3\n" + TWO + "run 100\n", g=1)
deck("a10_amp_inside_triple_quotes", "# triple-quoted if body spanning lines: LAMMPS reads until the closing \"\"\" (pair_coeff kn 5500 in the then branch)\n"
     + BASE() + "if \"1 > 0\" then \"\"\"\npair_coeff * * " + hk(5500) + "\n\"\"\"\n" + TWO + "run 100\n", g=1)
deck("a11_comment_amp_before_run", "# a comment ending in & before the run swallows 'run 100' itself: the deck has only the last run (kn 9000)\n"
     + BASE() + TWO + "# first settle &\nrun 100\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)

deck("a12_smart_quotes_then_body_only", "# if \"1 > 0\" then “pair_coeff ... 7000”: only the body in typographic quotes; LAMMPS substitutes and runs it (kn 7000)\n"
     + BASE() + "if \"1 > 0\" then \u201cpair_coeff * * " + hk(7000) + "\u201d\n" + TWO + "run 100\n", g=1)
deck("a13_smart_quotes_condition_false", "# if “0 > 1” then “pair_coeff ... 7000” else “pair_coeff ... 5000”: LAMMPS takes the else branch (kn 5000)\n"
     + BASE() + "if \u201c0 > 1\u201d then \u201cpair_coeff * * " + hk(7000) + "\u201d else \u201cpair_coeff * * " + hk(5000) + "\u201d\n" + TWO + "run 100\n", g=1)
deck("a14_bom_first_line", "# the file starts with a UTF-8 byte-order mark (a Windows editor) before a comment line; kn 5000 in the deck\n"
     .replace("# the", "\ufeff# the") + BASE(hk(5000)) + TWO + "run 100\n", g=1)
deck("a15_smart_quotes_variable_string", "# variable kn string “6000” (typographic quotes): LAMMPS makes them \" -> kn 6000\n"
     + BASE() + "variable kn string \u201c6000\u201d\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("a16_thin_space_pair_coeff", "# thin and em spaces (U+2009, U+2003) between pair_coeff words: LAMMPS makes them spaces (kn 6000)\n"
     + BASE() + "pair_coeff * *\u2009hooke\u20036000 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("a17_smart_quotes_if_in_include", "# an included file with if “1 > 0” then “pair_coeff ... 7000” (typographic quotes): kn 7000\n"
     + BASE() + "include in.coeff\n" + TWO + "run 100\n", g=1, data={"in.coeff": "if \u201c1 > 0\u201d then \u201cpair_coeff * * " + hk(7000) + "\u201d\n"})
deck("a18_smart_quotes_if_set_density", "# if “1 > 0” then “set type 2 density 7800” (typographic quotes): steel type 2\n"
     + BASE() + TWO + "if \u201c1 > 0\u201d then \u201cset type 2 density 7800\u201d\nrun 100\n", g=1)
deck("a19_smart_quotes_if_timestep", "# if “1 > 0” then “timestep 2e-4” (typographic quotes): the run at dt 2e-4 (few steps per contact)\n"
     + BASE() + TWO + "if \u201c1 > 0\u201d then \u201ctimestep 2e-4\u201d\nrun 100\n", g=1)
deck("a20_smart_quotes_if_quit", "# run 100 at kn 2000; if “1 > 0” then quit (typographic quotes): the kn 9000 stage never runs\n"
     + BASE() + TWO + "run 100\nif \u201c1 > 0\u201d then quit\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("a21_smart_quotes_if_unfix_floor", "# if “1 > 0” then “unfix floor” “fix floor all wall/gran ... 9000 ...” (typographic quotes): the floor kn 9000\n"
     + BASE() + TWO + "if \u201c1 > 0\u201d then \u201cunfix floor\u201d \u201cfix floor all wall/gran granular " + hk(9000) + " zplane 0 NULL\u201d\nrun 100\n", g=1)
deck("a22_smart_single_quotes_if", "# if ‘1 > 0’ then ‘pair_coeff ... 7000’ (typographic single quotes): LAMMPS makes them ' and runs the branch (kn 7000)\n"
     + BASE() + "if \u20181 > 0\u2019 then \u2018pair_coeff * * " + hk(7000) + "\u2019\n" + TWO + "run 100\n", g=1)
deck("a23_smart_quotes_pair_coeff_line_itself", "# a typographic quote pair around a plain word in a pair_coeff line? (print “x” before; kn 4000 plain)\n"
     + BASE() + "print \u201cPROBE x\u201d\npair_coeff * * " + hk(4000) + "\n" + TWO + "run 100\n", g=1)
deck("a24_cmd_from_string_variable", "# a whole command from a string variable: variable c string \"pair_coeff * * hooke 7000 ...\", then a line ${c}: LAMMPS runs it (kn 7000)\n"
     + BASE() + "variable c string \"pair_coeff * * " + hk(7000) + "\"\n${c}\n" + TWO + "run 100\n", g=1)
deck("a25_run_from_string_variable", "# the run from a string variable: variable r string run; ${r} 100 at kn 2000, then kn 9000 and run 100: two stages\n"
     + BASE() + TWO + "variable r string run\n${r} 100\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)

deck("a26_nbsp_inside_ascii_if_body", "# an ASCII if whose body holds non-breaking spaces (UTF-8 C2 A0): LAMMPS makes them spaces and runs pair_coeff kn 7000\n"
     + BASE() + "if \"1 > 0\" then \"pair_coeff\u00a0*\u00a0*\u00a0hooke 7000 3000 " + K + "\"\n" + TWO + "run 100\n", g=1)
deck("a27_smart_quotes_run_every_body", "# run 100 every 50 “pair_coeff ... 9000” (typographic quotes around the every command) then run 100 at kn 9000\n"
     + BASE() + TWO + "run 100 every 50 \u201cpair_coeff * * " + hk(9000) + "\u201d\nrun 100\n", g=1)
deck("a28_smart_quotes_if_hertz_material", "# hertz/material E 1e7 (viscoelastic) and an if with typographic quotes raising E to 5e7: engine E 5e7\n"
     + BASE(HM) + TWO + "if \u201c1 > 0\u201d then \u201cpair_coeff * * " + HM.replace("1e7", "5e7") + "\u201d\nrun 100\n", g=1)
deck("a29_smart_quotes_if_labels", "# labelmap and an if with typographic quotes setting pair_coeff steel steel kn 8000 (type 2)\n"
     + head() + "labelmap atom 1 glass 2 steel\n" + G1(HK) + GRAV + FLOOR + TAIL + TWO + "if \u201c1 > 0\u201d then \u201cpair_coeff steel steel " + hk(8000) + "\u201d\nrun 100\n", g=1)
deck("a30_smart_quotes_if_then_run_stage", "# two runs; between them an if with typographic quotes sets kn 9000: stage 2 at kn 9000 in the engine\n"
     + BASE() + TWO + "run 100\nif \u201c1 > 0\u201d then \u201cpair_coeff * * " + hk(9000) + "\u201d\nrun 100\n", g=1)

# ================================================================ r*: what runs change, read back
deck("r01_ke_settle_loop", "# settling loop: run 200, if the kinetic energy is above 1e-12 jump back (LAMMPS loops until settled), then kn 9000 for the last run\n"
     + BASE() + TWO + "variable n loop 20\nlabel settle\nrun 200\nif \"$(ke) < 1e-12\" then \"jump SELF settled\"\nnext n\njump SELF settle\nlabel settled\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("r02_ke_equal_defined_before", "# variable e equal ke defined before the run, read after it through ${e} in an if: the spheres fall (ke > 0) so kn 9000\n"
     + BASE() + TWO + "variable e equal ke\nrun 300\nif \"${e} > 0\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE ke ${e}\"\nrun 100\n", g=1)
deck("r03_compute_ke_reduce", "# compute ke/atom + reduce: after the run c_kt > 0 -> kn 9000 (read through a compute, not a thermo keyword)\n"
     + BASE() + TWO + "compute ka all ke/atom\ncompute kt all reduce sum c_ka\nthermo_style custom step c_kt\nrun 300\nvariable kk equal c_kt\nif \"${kk} > 0\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE kt ${kk}\"\nrun 100\n", g=1)
deck("r04_xcm_after_fall", "# the centre of mass after a fall (xcm of the group): below 0.009 -> set type 2 density 7800\n"
     + BASE() + TWO + "run 2000\nvariable zc equal xcm(all,z)\nif \"${zc} < 0.009\" then \"set type 2 density 7800\"\nprint \"PROBE zc ${zc}\"\nrun 100\n", g=1)
deck("r05_atom_z_value", "# z[2] (atom 2's height) after the fall: the sphere has landed (z < 0.0035) -> kn 9000\n"
     + BASE() + TWO + "run 3000\nif \"$(z[2]) < 0.0035\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE z2 $(z[2])\"\nrun 100\n", g=1)
deck("r06_delete_overlap_after_run", "# two type-1/type-2 spheres 1.2 mm apart stack under gravity; delete_atoms overlap 0.0052 after the run deletes one of the touching pair in LAMMPS\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.0021\ncreate_atoms 2 single 0.02 0.02 0.00725\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\n"
     + "run 3000\ndelete_atoms overlap 0.0045 all all\nprint \"PROBE n $(count(all))\"\nset type 2 diameter 0.008\nrun 100\n", g=1)
deck("r07_fix_ave_time_read", "# fix ave/time of ke over the run, read after it as f_av: > 0 -> kn 9000\n"
     + BASE() + TWO + "variable e equal ke\nfix av all ave/time 10 10 100 v_e\nrun 300\nif \"$(f_av) > 0\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE av $(f_av)\"\nrun 100\n", g=1)
deck("r08_bound_after_fall", "# bound(all,zmax) after the fall: the top of the pile below 0.006 -> kn 9000\n"
     + BASE() + TWO + "run 3000\nvariable zt equal bound(all,zmax)\nif \"${zt} < 0.006\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE zt ${zt}\"\nrun 100\n", g=1)
deck("r09_time_after_dt_reset", "# fix dt/reset changes dt during run 1; time after it read by an if: time < 0.001 -> kn 9000, else kn 2000 stays\n"
     + BASE() + TWO + "fix dtr all dt/reset 1 1e-7 1e-5 1e-7 units box\nrun 100\nunfix dtr\nif \"$(time) < 0.001\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE time $(time) dt $(dt)\"\nrun 100\n", g=1)
deck("r10_dt_after_dt_reset", "# fix dt/reset sets dt during run 1 (sphere falls, xmax 1e-7 per step: dt shrinks); timestep ${d} afterwards keeps it for run 2\n"
     + BASE() + TWO + "fix dtr all dt/reset 1 1e-8 1e-5 1e-7 units box\nrun 2000\nunfix dtr\nvariable d equal dt\ntimestep ${d}\nprint \"PROBE dt ${d}\"\nrun 100\n", g=1)
deck("r11_group_variable_z", "# an atom-style variable of z after the fall groups the low spheres (all), and set group low density 7800\n"
     + BASE() + TWO + "run 3000\nvariable lo atom z<0.0035\ngroup low variable lo\nset group low density 7800\nprint \"PROBE nlow $(count(low))\"\nrun 100\n", g=1)
deck("r12_velocity_vz_read", "# vz[1] after a short fall (negative): if it is below -0.01 -> kn 9000\n"
     + BASE() + TWO + "run 500\nif \"$(vz[1]) < -0.01\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE vz1 $(vz[1])\"\nrun 100\n", g=1)
deck("r13_pe_from_gravity", "# pe (fix gravity energy with fix_modify energy yes) after the fall is lower: if pe < 0 -> kn 9000\n"
     + BASE() + TWO + "fix_modify grav energy yes\nthermo_style custom step pe\nrun 3000\nif \"$(pe) < 0\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE pe $(pe)\"\nrun 100\n", g=1)
deck("r14_fix_store_state_read", "# fix store/state 0 z stores z at definition; after the fall an atom variable compares: count of moved spheres 2 -> kn 9000\n"
     + BASE() + TWO + "fix st all store/state 0 z\nrun 3000\nvariable mv atom (f_st-z)>0.001\ncompute cm all reduce sum v_mv\nthermo_style custom step c_cm\nrun 0\nif \"$(c_cm) > 1\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE moved $(c_cm)\"\nrun 100\n", g=1)
deck("r15_fix_halt_shortens_stage", "# fix halt stops run 1 when ke > 1e-9 (a few steps in); the step reached decides an if: step < 500 -> kn 9000\n"
     + BASE() + TWO + "variable e equal ke\nfix h all halt 1 v_e > 1e-9 error continue\nrun 1000\nunfix h\nif \"$(step) < 500\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE step $(step)\"\nrun 100\n", g=1)
deck("r16_random_equal_draws", "# kn from an equal-style random(): each evaluation draws the next number of one RNG; the print draws first, pair_coeff second\n"
     + BASE() + "variable r equal random(1000,9000,4711)\nprint \"PROBE r1 ${r}\"\nvariable kn equal ${r}\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("r17_random_atom_diameter", "# diameters from an atom-style random(): sizes 3..5 mm spread over the type-1 spheres\n"
     + BASE() + "create_atoms 1 random 8 12345 NULL\ncreate_atoms 2 single 0.01 0.01 0.05\nvariable d atom random(0.003,0.005,777)\nset type 1 diameter v_d\nset type 1 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("r18_count_region_after_fall", "# count of spheres in a low region after the fall (group by region): 2 -> kn 9000\n"
     + BASE() + TWO + "run 3000\nregion low block INF INF INF INF 0 0.0035 units box\nvariable nl equal count(all,low)\nif \"${nl} > 1\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE nl ${nl}\"\nrun 100\n", g=1)

deck("r19_thermo_draws_random", "# thermo_style custom step v_r with random(): every thermo output of run 1 draws one number; kn = ${r} after the run is the next draw\n"
     + BASE() + TWO + "variable r equal random(1000,9000,4711)\nthermo_style custom step v_r\nthermo 10\nrun 100\nvariable kn equal ${r}\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("r20_random_diameter_loop_print", "# four type-1 spheres sized in a loop by an equal-style random() (3..6 mm), with a print of a random x each pass: the print draws too\n"
     + BASE() + "variable x equal random(0.005,0.035,1234)\nvariable d equal random(0.003,0.006,1234)\nvariable i loop 4\nlabel lp\nprint \"PROBE placing sphere $i at x ${x}\"\ncreate_atoms 1 single $(0.008*v_i) 0.02 0.01\nset atom $i diameter ${d} density 2500\nnext i\njump SELF lp\ncreate_atoms 2 single 0.03 0.03 0.05\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("r21_random_immediate_in_print", "# print \"$(random(0,1,99))\" draws from the same generator as v_r: kn = ${r} is the second draw\n"
     + BASE() + "variable r equal random(1000,9000,99)\nprint \"PROBE seed draw $(random(0,1,99))\"\nvariable kn equal ${r}\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("r22_fix_print_draws_random", "# fix print every 20 steps prints ${r} (a draw each time) during run 1; kn = ${r} after it\n"
     + BASE() + TWO + "variable r equal random(1000,9000,4711)\nfix pr all print 20 \"PROBE r ${r}\" screen yes\nrun 100\nunfix pr\nvariable kn equal ${r}\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("r23_shell_echo_draws_random", "# shell echo ${r} (the substitution draws even though the shell command is only a process): kn = ${r} next\n"
     + BASE() + "variable r equal random(1000,9000,4711)\nshell echo ${r}\nvariable kn equal ${r}\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("r24_random_type_choice_print", "# a loop makes 6 spheres; each pass prints a random number then picks type 2 if another draw < 0.5 (6 mm), else type 1 (4 mm)\n"
     + BASE() + "variable r equal random(0,1,2024)\nvariable i loop 6\nlabel lp\nprint \"PROBE pass $i draw ${r}\"\nif \"${r} < 0.5\" then \"create_atoms 2 single $(0.006*v_i) 0.02 0.01\" else \"create_atoms 1 single $(0.006*v_i) 0.02 0.01\"\nnext i\njump SELF lp\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 7800\nprint \"PROBE n2 $(count(all))\"\nrun 100\n", g=1)
deck("r25_thermo_draws_then_if", "# thermo output v_r during run 1 (11 draws), then if \"${r} > 5000\" picks kn 9000 else kn 500: the branch depends on the draw count\n"
     + BASE() + TWO + "variable r equal random(1000,9000,4711)\nthermo_style custom step v_r\nthermo 10\nrun 100\nif \"${r} > 5000\" then \"pair_coeff * * " + hk(9000) + "\" else \"pair_coeff * * " + hk(500) + "\"\nrun 100\n", g=1)
deck("u07_units_cgs_same_as_si", "# units cgs, the SI deck's contact in cgs: kn 2e6 dyn/cm, gamma 3000 1/s, 0.4/0.6 cm, 2.5 g/cm3: eps as the SI deck (p11 0.49726)\n"
     + head(units="cgs", box="0 4 0 4 0 10") + G1(hk("2e6")) + "fix grav all gravity 981 vector 0 0 -1\n" + f"fix floor all wall/gran granular {hk('2e6')} zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 1e-5\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g=100)
deck("u08_units_micro_same_as_si", "# units micro, the SI deck's contact: kn 2e6 pg/us^2, gamma 3e-3 1/us, 4000/6000 um, 2.5e-3 pg/um^3: eps as the SI deck (p11 0.49726)\n"
     + head(units="micro", box="0 40000 0 40000 0 100000") + G1(hk("2e6", "3e-3")) + "fix grav all gravity 9.81e-6 vector 0 0 -1\n" + f"fix floor all wall/gran granular {hk('2e6', '3e-3')} zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 10\ncreate_atoms 1 single 20000 20000 10000\ncreate_atoms 2 single 10000 10000 10000\nset type 1 diameter 4000 density 2.5e-3\nset type 2 diameter 6000 density 2.5e-3\nrun 100\n", g=1)
deck("u09_units_cgs_hertz_material_same_as_si", "# units cgs, hertz/material E 1e8 dyn/cm2 (1e7 Pa), eta 1.4e8 (1.4e7 Pa s in poise), 0.4/0.6 cm, 2.5 g/cm3\n"
     + head(units="cgs", box="0 4 0 4 0 10") + G1(HM.replace("1e7 1.4e7", "1e8 1.4e8")) + "fix grav all gravity 981 vector 0 0 -1\n" + f"fix floor all wall/gran granular {HM.replace('1e7 1.4e7', '1e8 1.4e8')} zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 1e-6\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g="10 100")

deck("r26_normal_draw_in_print_then_diameter", "# print of $(normal(0,1,77)) draws from the shared generator; set type 2 diameter from v_d = random(0.004,0.008,77) next\n"
     + BASE() + TWO + "variable d equal random(0.004,0.008,77)\nprint \"PROBE noise $(normal(0,1,77))\"\nset type 2 diameter ${d}\nrun 100\n", g=1)
deck("r27_thermo_random_then_set_density", "# thermo_style custom v_r in run 1 (random 2000..8000), then set type 2 density ${r} for run 2\n"
     + BASE() + TWO + "variable r equal random(2000,8000,4711)\nthermo_style custom step v_r\nthermo 25\nrun 100\nset type 2 density ${r}\nrun 100\n", g=1)

# ================================================================ v*: variable styles and functions
deck("v01_getenv_home", "# variable h getenv HOME: set in the engine's shell, so the if takes kn 9000; an empty HOME would keep kn 2000\n"
     + BASE() + "variable h getenv HOME\nif \"${h} != ''\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE home ${h}\"\n" + TWO + "run 100\n", g=1)
deck("v02_shell_putenv_getenv", "# shell putenv KN=9000 (a LAMMPS builtin, no process) then variable k getenv KN: kn 9000\n"
     + BASE() + "shell putenv F21KN=9000\nvariable kn getenv F21KN\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("v03_file_var_comments_blank", "# variable k file kn.txt whose first lines are a comment and a blank: LAMMPS skips them, k = 2500; next k -> 9000\n"
     + BASE() + "variable kn file kn.txt\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\nrun 0\nnext kn\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1,
     data={"kn.txt": "# stiffness values\n\n2500\n   # another comment\n9000\n"})
deck("v04_atomfile_diameters", "# variable d atomfile with per-atom diameters (atom 1 5 mm, atom 2 3 mm), set type * diameter v_d\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nvariable d atomfile dia.txt\nset type * diameter v_d\nset type * density 2500\nrun 100\n", g=1,
     data={"dia.txt": "# diameters\n2\n1 0.005\n2 0.003\n"})
deck("v05_uloop_next_jump", "# variable i uloop 3 (one partition: a plain loop; next writes tmp.lammps.variable in the cwd): kn 1000*i, the last 3000\n"
     + BASE() + TWO + "variable i uloop 3\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\nrun 0\nnext i\njump SELF lp\nrun 100\n", g=1)
deck("v06_universe_one_partition", "# variable u universe 4000 7000 with one partition: u = 4000, next u -> 7000 (file-locked next)\n"
     + BASE() + TWO + "variable u universe 4000 7000\nnext u\npair_coeff * * hooke ${u} 3000 " + K + "\nprint \"PROBE u ${u}\"\nrun 100\n", g=1)
deck("v07_internal_style", "# variable kn internal 2000 then variable kn internal 8000 (internal may be redefined): kn 8000\n"
     + BASE() + "variable kn internal 2000\nvariable kn internal 8000\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("v08_vector_style_element", "# variable k vector [2000,7500] and $(v_k[2]): kn 7500\n"
     + BASE() + "variable k vector [2000,7500]\npair_coeff * * hooke $(v_k[2]) 3000 " + K + "\nprint \"PROBE k2 $(v_k[2])\"\n" + TWO + "run 100\n", g=1)
deck("v09_string_redefined_index_not", "# index defined first then a string of the same name: LAMMPS errors? (engine says); here index then delete then string 6100\n"
     + BASE() + "variable kn index 2000\nvariable kn delete\nvariable kn string 6100\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("v10_loop_start_end_pad", "# variable i loop 3 5 (start at 3) -> kn 1000*i, ends 5000\n"
     + BASE() + TWO + "variable i loop 3 5\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\nnext i\njump SELF lp\nrun 100\n", g=1)
deck("v11_next_two_variables", "# next a b on two index variables of unequal length: when b runs out both are exhausted; the jump is skipped; kn from a's last value used\n"
     + BASE() + TWO + "variable a index 3000 4000 5000\nvariable b index x y\nlabel lp\npair_coeff * * hooke ${a} 3000 " + K + "\nnext a b\njump SELF lp\nprint \"PROBE a ${a}\"\nrun 100\n", g=1)
deck("v12_is_file_after_shell_rm", "# a stale override.in (kn 9000) sits in the folder; shell rm removes it; if is_file(override.in) include it: the engine keeps kn 2000\n"
     + BASE() + "shell rm override.in\nif \"$(is_file(override.in))\" then \"include override.in\"\n" + TWO + "run 100\n", g=1,
     data={"override.in": "pair_coeff * * " + hk(9000) + "\n"})
deck("v13_is_defined_fix", "# is_defined(fix,floor) true -> a second floor kn 9000 replaces it (unfix then fix)\n"
     + BASE() + "if \"$(is_defined(fix,floor))\" then \"unfix floor\" \"fix floor all wall/gran granular " + hk(9000) + " zplane 0 NULL\"\n" + TWO + "run 100\n", g=1)
deck("v14_version_function", "# if $(version()) >= 20250722 (LAMMPS 22 Jul 2025) kn 9000: the engine's version decides\n"
     + BASE() + "if \"$(version()) >= 20250722\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE version $(version())\"\n" + TWO + "run 100\n", g=1)
deck("v15_is_available_feature", "# is_available(command,pair_style) and is_active(pair,granular): true in the engine -> kn 7000\n"
     + BASE() + "if \"$(is_active(pair,granular))\" then \"pair_coeff * * " + hk(7000) + "\"\n" + TWO + "run 100\n", g=1)
deck("v16_extract_setting_nprocs", "# extract_setting(world_size) is 1: if > 1 kn 9000 else kn 2000 (serial engine)\n"
     + BASE() + "if \"$(extract_setting(world_size)) > 1\" then \"pair_coeff * * " + hk(9000) + "\"\nprint \"PROBE ws $(extract_setting(world_size))\"\n" + TWO + "run 100\n", g=1)
deck("v17_label2type_function", "# labelmap; variable t equal label2type(atom,steel) -> 2; pair_coeff ${t} ${t} kn 8000\n"
     + head() + "labelmap atom 1 glass 2 steel\nvariable t equal label2type(atom,steel)\npair_style granular\npair_coeff * * " + HK + "\npair_coeff ${t} ${t} " + hk(8000) + "\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("v18_format_var_then_string", "# variable f format k %.1f, then a string variable of ${f}: 2500.0 -> kn 2500\n"
     + BASE() + "variable k equal 2500\nvariable f format k %.1f\nvariable s string ${f}\npair_coeff * * hooke ${s} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("v19_timer_and_elapsed_free", "# variable st equal step after two runs of 100: 200 -> kn 9000 if step == 200 (no run state but the step count)\n"
     + BASE() + TWO + "run 100\nrun 100\nif \"$(step) == 200\" then \"pair_coeff * * " + hk(9000) + "\"\nrun 100\n", g=1)
deck("v20_ternary_and_logic", "# kn from ternary(1>0, 4000, 9000) and a logical xor: kn 4000\n"
     + BASE() + "variable kn equal ternary((1>0)|^(0>1),4000,9000)\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)
deck("v21_string_variable_nested_dollar", "# a string variable holding a $-reference: variable s string ${a} is substituted at definition (2000), later a changes to 9000: s stays 2000\n"
     + BASE() + "variable a string 2000\nvariable s string ${a}\nvariable a string 9000\npair_coeff * * hooke ${s} 3000 " + K + "\nprint \"PROBE s ${s}\"\n" + TWO + "run 100\n", g=1)
deck("v22_equal_lazy_through_string_ref", "# variable kn equal v_a where a is a string '3000+0*1' later redefined '6000': lazy, kn 6000 at use\n"
     + BASE() + "variable a string 3000\nvariable kn equal v_a\nvariable a string 6000\n" + PRB + "pair_coeff * * hooke ${kn} 3000 " + K + "\n" + TWO + "run 100\n", g=1)

# ================================================================ l*: labels and type labels
deck("l01_labelmap_swap_between_coeffs", "# labelmap 1 glass 2 steel, pair_coeff steel steel kn 8000 (type 2); labelmap atom 1 steel 2 glass is an error? (engine says)\n"
     + head() + "labelmap atom 1 glass 2 steel\npair_style granular\npair_coeff * * " + HK + "\npair_coeff steel steel " + hk(8000) + "\nlabelmap clear\nlabelmap atom 1 steel 2 glass\npair_coeff glass glass " + hk(500) + "\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("l02_labelmap_clear_then_new", "# labelmap clear drops the labels; new labels a b; pair_coeff b b kn 6000 (type 2)\n"
     + head() + "labelmap atom 1 glass 2 steel\nlabelmap clear\nlabelmap atom 1 a 2 b\npair_style granular\npair_coeff * * " + HK + "\npair_coeff b b " + hk(6000) + "\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("l03_data_type_labels_section", "# read_data with an Atom Type Labels section (1 big 2 small) and atoms typed by label; pair_coeff small big kn 6000\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n" + G1(HK) + "pair_coeff small big " + hk(6000) + "\n" + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": "spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 big\n2 small\n\nAtoms # sphere\n\n1 big 0.006 2500 0.02 0.02 0.01\n2 small 0.004 2500 0.01 0.01 0.01\n"})
deck("l04_label_in_loop_jump_label_name_var", "# jump SELF ${tgt} with the label name from a variable: goes to 'stiff' (kn 9000), skipping 'soft'\n"
     + BASE() + TWO + "variable tgt string stiff\njump SELF ${tgt}\nlabel soft\npair_coeff * * " + hk(500) + "\njump SELF done\nlabel stiff\npair_coeff * * " + hk(9000) + "\nlabel done\nrun 100\n", g=1)
deck("l05_jump_label_in_include", "# jump SELF inside an included file loops within that file (3 passes, kn 1000*i), then the main deck continues\n"
     + BASE() + TWO + "include in.loop\nrun 100\n", g=1,
     data={"in.loop": "variable i loop 3\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\nnext i\njump SELF lp\n"})
deck("l06_jump_named_file_is_self", "# jump in.deck lbl (the deck's own name instead of SELF): LAMMPS reopens the file and goes to lbl (kn 7000)\n"
     + BASE() + TWO + "jump in.deck lbl\npair_coeff * * " + hk(500) + "\nlabel lbl\npair_coeff * * " + hk(7000) + "\nrun 100\n", g=1)
deck("l07_label_after_jump_never_found_first", "# jump SELF lp goes to the first 'label lp' after a loop already passed: label defined twice, first above wins (kn 2000 loop runs twice)\n"
     + BASE() + TWO + "variable i loop 2\nlabel lp\npair_coeff * * hooke $(1000*v_i+1000) 3000 " + K + "\nnext i\njump SELF lp\nlabel lp\npair_coeff 1 1 " + hk(8000) + "\nrun 100\n", g=1)
deck("l08_type_label_in_neigh_exclude", "# neigh_modify exclude type glass steel by labels: 1 2 never collide\n"
     + head() + "labelmap atom 1 glass 2 steel\n" + G1(HK) + GRAV + FLOOR + TAIL + TWO + "neigh_modify exclude type glass steel\nrun 100\n", g=1)
deck("l09_type_label_set_type_change", "# set atom 1 type steel (by label): both spheres type 2 -> only 2 2 and walls of 2\n"
     + head() + "labelmap atom 1 glass 2 steel\n" + G1(HK) + GRAV + FLOOR + TAIL + TWO + "set atom 1 type steel\nrun 100\n", g=1)

# ================================================================ c*: control flow
deck("c01_lammps_if_quit_in_include_loop", "# a loop whose include quits on its 2nd pass: one stage at kn 1000, then the engine ends (kn 2000 never run)\n"
     + BASE() + TWO + "variable i loop 3\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\ninclude in.chk\nrun 100\nnext i\njump SELF lp\n", g=1,
     data={"in.chk": "if \"${i} == 2\" then quit\n"})
deck("c02_lammps_quit_with_status", "# quit 0 after one run: later kn 9000 stage never made\n"
     + BASE() + TWO + "run 100\nquit 0\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c03_lammps_if_elif_quit", "# if/elif: the elif branch quits (x = 2) after run 1\n"
     + BASE() + TWO + "variable x equal 2\nrun 100\nif \"${x} == 1\" then \"print one\" elif \"${x} == 2\" quit\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c04_lammps_quit_in_jumped_file", "# jump to another file that runs and quits: in.deck's later lines never run\n"
     + BASE() + TWO + "jump in.part2\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1,
     data={"in.part2": "pair_coeff * * " + hk(4000) + "\nrun 100\nquit\n"})
deck("c05_lammps_exit_via_halt_hard_step", "# fix halt error hard when step >= 50 ends LAMMPS in run 1 (exit status nonzero): kn 9000 stage never made\n"
     + BASE() + TWO + "variable s equal step\nfix h all halt 10 v_s >= 50 error hard\nrun 100\nunfix h\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c06_next_exhausted_skips_jump_then_quit", "# index exhausted: next skips the jump; then quit before the kn 9000 stage\n"
     + BASE() + TWO + "variable a index 3000 4000\nlabel lp\npair_coeff * * hooke ${a} 3000 " + K + "\nrun 100\nnext a\njump SELF lp\nquit\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c07_include_chain_relative_cwd", "# sub/in.a includes 'in.b': LAMMPS opens in.b relative to the working directory (./in.b kn 4000), not sub/in.b (kn 9000)\n"
     + BASE() + TWO + "include sub/in.a\nrun 100\n", g=1,
     data={"sub/in.a": "include in.b\n", "in.b": "pair_coeff * * " + hk(4000) + "\n", "sub/in.b": "pair_coeff * * " + hk(9000) + "\n"})
deck("c08_include_name_from_loop_var", "# include in.${i} for i = 1..2 in a loop: in.2 last (kn 6000)\n"
     + BASE() + TWO + "variable i loop 2\nlabel lp\ninclude in.$i\nnext i\njump SELF lp\nrun 100\n", g=1,
     data={"in.1": "pair_coeff * * " + hk(3000) + "\n", "in.2": "pair_coeff * * " + hk(6000) + "\n"})
deck("c09_run_every_include_quit", "# run 200 every 100 'include in.stop' where in.stop quits when step >= 200: the run ends, then quit; kn 9000 never\n"
     + BASE() + TWO + "run 200 every 100 \"include in.stop\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1,
     data={"in.stop": "if \"$(step) >= 200\" then quit\n"})
deck("c10_jump_self_no_label_restart", "# jump SELF without a label rereads the file from the top: guarded by a loop variable (two passes), kn 1000*i -> 2000\n"
     + "variable p loop 2\nclear\n" + BASE() + TWO + "pair_coeff * * hooke $(1000*v_p) 3000 " + K + "\nrun 100\nnext p\njump SELF\n", g=1)
deck("c11_include_self_guarded", "# the deck includes in.part which includes itself once more (guarded): kn ends 5000\n"
     + BASE() + TWO + "variable depth index 1 2\ninclude in.part\nrun 100\n", g=1,
     data={"in.part": "pair_coeff * * hooke $(2500*v_depth) 3000 " + K + "\nnext depth\nif \"${depth} == 2\" then \"include in.part\"\n"})
deck("c12_if_jump_out_of_loop", "# loop of 5 with an if jumping out at i == 3 (kn 3000): the loop is left early\n"
     + BASE() + TWO + "variable i loop 5\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\nif \"$i == 3\" then \"jump SELF out\"\nnext i\njump SELF lp\nlabel out\nrun 100\n", g=1)
deck("c13_clear_second_box_units_cgs", "# clear then a second box in units cgs (cm, g): hooke kn 2000 dyn/cm, 4 mm spheres 0.4 cm, 2.5 g/cm3\n"
     + BASE() + TWO + "run 100\nclear\n" + head(units="cgs", box="0 4 0 4 0 10") + G1(HK) + "fix grav all gravity 981 vector 0 0 -1\n" + f"fix floor all wall/gran granular {HK} zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 1e-5\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g=10)
deck("c14_run_every_set_via_include", "# run 200 every 100 'include in.grow': in.grow sets type 2 diameter 0.008 (mass kept): the last stage's type 2 is 8 mm\n"
     + BASE() + TWO + "run 200 every 100 \"include in.grow\"\nrun 100\n", g=1, data={"in.grow": "set type 2 diameter 0.008\n"})
deck("c15_run_every_variable_pair_coeff_late", "# run 200 every 100 \"variable kn equal 9000\"; a pair_coeff with v_kn evaluated when? pair_coeff ${kn} before the run uses 2000; after: 9000\n"
     + BASE() + TWO + "variable kn equal 2000\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 200 every 100 \"variable kn equal 9000\"\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + PRB + "run 100\n", g=1)
deck("c16_run_upto_zero_then_change", "# run 100 then run 100 upto (0 steps: already at 100), change kn 9000, run 100: two stages with steps (2000, 9000)\n"
     + BASE() + TWO + "run 100\nrun 100 upto\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c17_minimize_between", "# minimize between runs with granular pair (LAMMPS minimizes the overlap energy? granular has no energy): engine says\n"
     + BASE() + TWO + "run 100\nminimize 0 0 10 100\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c18_reset_timestep_then_pour_start", "# reset_timestep 0 after run 1; fix pour then inserts in run 2 (type 2 3 mm): 1 2 pair appears\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nrun 100\nreset_timestep 0\nregion ins block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 2 4767548 region ins diam one 0.003 dens 2500 2500\nrun 100\n", g=1)

deck("c19_quit_from_string_variable", "# run 100 at kn 2000, then ${q} with q string quit: the kn 9000 stage never runs\n"
     + BASE() + TWO + "variable q string quit\nrun 100\n${q}\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c20_set_from_string_variable", "# ${s} with s string 'set type 2 density 7800': steel type 2\n"
     + BASE() + TWO + "variable s string \"set type 2 density 7800\"\n${s}\nrun 100\n", g=1)
deck("c21_timestep_from_string_variable", "# ${t} with t string 'timestep 2e-4': the run at 2e-4\n"
     + BASE() + TWO + "variable t string \"timestep 2e-4\"\n${t}\nrun 100\n", g=1)
deck("c22_fix_wall_from_string_variable", "# the floor from a string variable: ${w} makes fix floor2 kn 9000 beside floor\n"
     + BASE() + TWO + "variable w string \"fix floor2 all wall/gran granular " + hk(9000) + " zplane 0 NULL\"\n${w}\nrun 100\n", g=1)
deck("c23_if_body_from_variable", "# if \"1 > 0\" then \"${c}\" with c holding pair_coeff kn 7000: LAMMPS substitutes at the if line (kn 7000)\n"
     + BASE() + "variable c string \"pair_coeff * * " + hk(7000) + "\"\nif \"1 > 0\" then \"${c}\"\n" + TWO + "run 100\n", g=1)
deck("c24_next_from_variable_loop", "# a loop whose pair_coeff line is ${pc${i}}-free: variable names built from i: v_k1 v_k2 (kn 3000, 6000): last 6000\n"
     + BASE() + TWO + "variable k1 equal 3000\nvariable k2 equal 6000\nvariable i loop 2\nlabel lp\npair_coeff * * hooke $(v_k${i}) 3000 " + K + "\nnext i\njump SELF lp\nrun 100\n", g=1)

deck("c25_run_every_if_quit_step", "# run 200 every 100 \"if '$(step) >= 100' then quit\": LAMMPS quits after the first part; the kn 9000 stage never runs\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) >= 100' then quit\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c26_run_every_if_quit_false_then_stage", "# run 200 every 100 \"if '$(step) > 5000' then quit\" (never true): the kn 9000 stage runs\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) > 5000' then quit\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)

deck("c27_run_every_if_quit_continued", "# R01's form: run 200 every 100 & / \"if '$(step) >= 100' then & / 'print done' & / 'quit'\" over continued lines: LAMMPS quits after part 1; the kn 9000 stage never runs\n"
     + BASE() + TWO + "run 200 every 100 &\n    \"if '$(step) >= 100' then &\n        'print PROBE-done' &\n        'quit'\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c28_run_every_if_quit_two_cmds_one_line", "# run 200 every 100 \"if '$(step) >= 100' then 'print x' 'quit'\" on one line: LAMMPS quits after part 1\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) >= 100' then 'print PROBE-done' 'quit'\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)

deck("c29_run_every_if_quit_quoted_single", "# run 200 every 100 \"if '$(step) >= 100' then 'quit'\" (the one command quoted): LAMMPS quits after part 1; kn 9000 never runs\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) >= 100' then 'quit'\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c30_run_every_if_else_quit", "# run 200 every 100 \"if '$(step) < 100' then 'print x' else 'quit'\": at step 100 the else branch quits\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) < 100' then 'print PROBE-x' else 'quit'\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c31_plain_if_print_then_quit", "# if \"1 > 0\" then \"print PROBE-bye\" \"quit\" after run 100 (no run every): the kn 9000 stage never runs\n"
     + BASE() + TWO + "run 100\nif \"1 > 0\" then \"print PROBE-bye\" \"quit\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c32_run_every_two_strings_second_quit", "# run 200 every 100 \"print PROBE-a\" \"quit\" (two every-commands, the second quit): LAMMPS quits after part 1\n"
     + BASE() + TWO + "run 200 every 100 \"print PROBE-a\" \"quit\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("c33_run_every_if_quit_with_exit_status", "# run 200 every 100 \"if '$(step) >= 100' then 'quit 0'\": quit with a status\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) >= 100' then 'quit 0'\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)

deck("c34_run_every_if_jump_quoted", "# run 200 every 100 \"if '$(step) >= 200' then 'jump SELF end'\": LAMMPS jumps to label end after the run, skipping kn 9000\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) >= 200' then 'jump SELF end'\"\npair_coeff * * " + hk(9000) + "\nlabel end\nrun 100\n", g=1)
deck("c35_run_every_if_unfix_floor_quoted", "# run 200 every 100 \"if '$(step) >= 100' then 'unfix floor' 'fix floor all wall/gran ... 9000 ...'\" at step 100: the floor is kn 9000 from part 2 on and in run 2\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) == 100' then 'unfix floor' 'fix floor all wall/gran granular " + hk(9000) + " zplane 0 NULL'\"\nrun 100\n", g=1)
deck("c36_run_every_if_timestep_quoted", "# run 200 every 100 \"if '$(step) == 100' then 'timestep 2e-4'\": dt 2e-4 from part 2 on and in run 2\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) == 100' then 'timestep 2e-4'\"\nrun 100\n", g=1)
deck("c37_run_every_if_pair_coeff_quoted", "# run 200 every 100 \"if '$(step) == 100' then 'pair_coeff * * hooke 9000 ...'\": kn 9000 from part 2 on and in run 2\n"
     + BASE() + TWO + "run 200 every 100 \"if '$(step) == 100' then 'pair_coeff * * " + hk(9000) + "'\"\nrun 100\n", g=1)
deck("r28_thermo_random_with_ke_read", "# thermo v_r during run 1; then if \"$(ke) > 0 && ${r} > 5000\" (a run-state read, so the audit makes the runs): kn 9000 or 500\n"
     + BASE() + TWO + "variable r equal random(1000,9000,4711)\nthermo_style custom step ke v_r\nthermo 10\nrun 100\nif \"$(ke) > 0 && ${r} > 5000\" then \"pair_coeff * * " + hk(9000) + "\" else \"pair_coeff * * " + hk(500) + "\"\nrun 100\n", g=1)

# ================================================================ f*: fixes beside the contact
deck("f01_temp_berendsen", "# fix temp/berendsen to T 0 rescales velocities every step (a thermostat on two spheres): eps not the contact's\n"
     + BASE() + TWO + "fix tb all temp/berendsen 1e-30 1e-30 1e-4\nrun 100\n", g=1)
deck("f02_temp_csvr", "# fix temp/csvr (stochastic velocity rescaling) to T 1e-30\n"
     + BASE() + TWO + "fix tc all temp/csvr 1e-30 1e-30 1e-4 12345\nrun 100\n", g=1)
deck("f03_lineforce_z", "# fix lineforce 0 0 1 keeps only the z part of every force: spheres meeting head-on along x feel no contact force in x\n"
     + BASE() + TWO + "fix lf all lineforce 0 0 1\nrun 100\n", g=1)
deck("f04_wall_lj93_beside_floor", "# fix wall/lj93 zlo at z = 0 beside the granular floor: an LJ push near the floor adds to the wall contact\n"
     + BASE() + TWO + "fix wl all wall/lj93 zlo 0.0 1e-9 0.003 0.0075 units box\nrun 100\n", g=1)
deck("f05_momentum_zero", "# fix momentum 1 linear 1 1 1 zeroes the total momentum every step (the falling pair stops falling)\n"
     + BASE() + TWO + "fix mom all momentum 1 linear 1 1 1\nrun 100\n", g=1)
deck("f06_efield_charges_hybrid", "# atom_style hybrid sphere charge; pair_style hybrid/overlay granular coul/cut: charged spheres repel\n"
     + head(style="hybrid sphere 1 charge") + "pair_style hybrid/overlay granular coul/cut 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * coul/cut\n" + GRAV
     + FLOOR + TAIL + TWO + "set type * charge 1e-9\nrun 100\n", g=1)
deck("f07_nve_sphere_and_nve_same_group", "# two integrators on the same atoms (nve/sphere and nve): each step advances twice: the engine warns; eps not the contact's\n"
     + BASE() + TWO + "fix integ2 all nve\nrun 100\n", g=1)
deck("f08_wall_reflect_inside", "# fix wall/reflect zlo 0.0021: reflects the 4 mm spheres' centres before the granular floor at 0 is met (r 2 mm): no floor contact for type 1\n"
     + BASE() + TWO + "fix wr all wall/reflect zlo 0.0021 units box\nrun 100\n", g=1)
deck("f09_spring_couple", "# fix spring couple between groups of type 1 and 2 (a spring pulling them together)\n"
     + BASE() + TWO + "group g1 type 1\ngroup g2 type 2\nfix sp g1 spring couple g2 100 0 0 0 0\nrun 100\n", g=1)
deck("f10_adapt_diameter_reset_no_between", "# fix adapt diameter (reset no) over run 1 grows type 2 to 8 mm and keeps it for run 2 (mass scaled by adapt)\n"
     + BASE() + TWO + "variable dd equal ramp(0.006,0.008)\ngroup t2 type 2\nfix ad t2 adapt 1 atom diameter v_dd reset no\nrun 100\nunfix ad\nrun 100\n", g=1)
deck("f11_nvt_sphere", "# fix nvt/sphere (Nose-Hoover on two spheres, T 1e-30) instead of nve/sphere\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nvt/sphere temp 1e-30 1e-30 1e-4\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)
deck("f12_smd_or_drag", "# fix drag pulls type 2 toward a point (0 0 0) with a force 1e-3 and damping delta 0.01\n"
     + BASE() + TWO + "group t2 type 2\nfix dr t2 drag 0 0 0 1e-3 0.01\nrun 100\n", g=1)
deck("f13_gravity_chute", "# fix gravity chute 30 (tilted gravity): no part in a head-on contact? gravity named as usual\n"
     + head() + G1(HK) + "fix grav all gravity 9.81 chute 30\n" + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("f14_wall_gran_region_moving_variable", "# fix wall/gran/region on a block region moving with a variable velocity (v_vz): a moving floor\n"
     + head() + G1(HK) + GRAV + "variable vz equal 0.01\nregion cup block 0 0.04 0 0.04 0 0.2 side in units box move NULL NULL v_zz\nvariable zz equal 0.0001*sin(time*100)\nfix floor all wall/gran/region granular " + HK + " region cup\n" + TAIL + TWO + "run 100\n", g=1)
deck("f15_viscous_sphere_only", "# fix viscous/sphere (rotational drag only): no part in a head-on contact\n"
     + BASE() + TWO + "fix vs all viscous/sphere 0.1\nrun 100\n", g=1)
deck("f16_heat_flux_less_fix_nve_noforce", "# type 2 integrated by nve/noforce (moves at constant velocity, ignores forces): a partner that does not recoil\n"
     + head() + G1(HK) + GRAV + FLOOR + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix in2 t2 nve/noforce\ntimestep 1e-5\n" + TWO.replace("create_atoms 1", "create_atoms 1").replace("", "") + "group t1 type 1\ngroup t2 type 2\nrun 100\n", g=1)

# ================================================================ u*: units, 2d, time step
deck("u01_units_micro", "# units micro (um, pg, us): 40 um spheres; hooke kn 2000 pg/us^2, gamma 3000 1/us\n"
     + head(units="micro", box="0 400 0 400 0 1000") + G1(HK) + "fix grav all gravity 9.81e-6 vector 0 0 -1\n" + FLOOR + "fix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 200 200 100\ncreate_atoms 2 single 100 100 100\nset type 1 diameter 40 density 2.5e-3\nset type 2 diameter 60 density 2.5e-3\nrun 100\n", g=1)
deck("u02_units_cgs_hertz", "# units cgs: hertz/material E 1e8 dyn/cm2, 4 mm = 0.4 cm spheres 2.5 g/cm3, g 10 cm/s\n"
     + head(units="cgs", box="0 4 0 4 0 10") + G1(HM.replace("1e7", "1e8")) + "fix grav all gravity 981 vector 0 0 -1\n" + f"fix floor all wall/gran granular {HM.replace('1e7', '1e8')} zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 1e-5\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g=10)
deck("u03_2d_density_keyword_order", "# 2d, set diameter then density: disc mass pi r^2 rho? LAMMPS set density in 2d gives 4/3 pi r^3 unless density/disc\n"
     + head(dim=2, bnd="p f p", box="0 0.04 0 0.1 -0.002 0.002") + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\n" + f"fix floor all wall/gran granular {HK} yplane 0 NULL\n"
     + "fix integ all nve/sphere disc\nfix e2 all enforce2d\ntimestep 1e-5\ncreate_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("u04_timestep_immediate_in_loop", "# timestep set inside a loop: 1e-5, 2e-5, 3e-5; the last run at 3e-5\n"
     + BASE() + TWO + "variable i loop 3\nlabel lp\ntimestep $(1e-5*v_i)\nrun 10\nnext i\njump SELF lp\n", g=1)
deck("u05_timestep_variable_lazy_dt", "# timestep v_? not allowed: timestep ${d} with d equal 2e-5*2 -> 4e-5\n"
     + BASE() + TWO + "variable d equal 2e-5*2\ntimestep ${d}\nrun 100\n", g=1)
deck("u06_units_real_granular", "# units real (A, g/mol, fs): a granular deck in real units, 40 A spheres, density 2.5 g/cm3\n"
     + head(units="real", box="0 400 0 400 0 1000") + G1(HK) + FLOOR + "fix integ all nve/sphere\ntimestep 1\n"
     + "create_atoms 1 single 200 200 100\ncreate_atoms 2 single 100 100 100\nset type 1 diameter 40 density 2.5\nset type 2 diameter 60 density 2.5\nrun 100\n", g=1e-3)

# ================================================================ k*: shell, files outside the scratch copy
deck("k01_log_absolute", "# log /tmp/f21k01.log switches the engine's log file to an absolute path (a file outside the deck's folder)\n"
     + BASE() + TWO + "log /tmp/f21k01.log\nrun 100\n", g=1)
deck("k02_info_out_file", "# info variables out log / out file ../f21k02.txt: writes a file beside the folder\n"
     + BASE() + TWO + "info variables out file ../f21k02.txt\nrun 100\n", g=1)
deck("k03_write_dump_absolute", "# write_dump all atom /tmp/f21k03.dump (written at once, no run needed)\n"
     + BASE() + TWO + "write_dump all atom /tmp/f21k03.dump\nrun 100\n", g=1)
deck("k04_write_data_parent", "# write_data ../f21k04.data then read back nothing: a file written outside the folder\n"
     + BASE() + TWO + "write_data ../f21k04.data\nrun 100\n", g=1)
deck("k05_shell_mkdir_touch", "# shell mkdir /tmp/f21k05dir (a LAMMPS builtin) and shell touch /tmp/f21k05.txt (a process)\n"
     + BASE() + TWO + "shell mkdir /tmp/f21k05dir\nshell touch /tmp/f21k05.txt\nrun 100\n", g=1)
deck("k06_print_append_absolute", "# print ... append /tmp/f21k06.txt (not read back)\n"
     + BASE() + TWO + "print \"hello\" append /tmp/f21k06.txt\nrun 100\n", g=1)
deck("k07_write_restart_abs", "# write_restart /tmp/f21k07.restart (not read back)\n"
     + BASE() + TWO + "run 100\nwrite_restart /tmp/f21k07.restart\n", g=1)
deck("k08_processors_file", "# processors * * * file /tmp/f21k08.txt (written at setup of the first run)\n"
     + "processors * * * file /tmp/f21k08.txt\n" + BASE() + TWO + "run 100\n", g=1)
deck("k09_geturl", "# geturl (downloads a file; this LAMMPS may lack curl): engine says\n"
     + BASE() + TWO + "geturl https://example.invalid/x.txt output f21k09.txt\nrun 100\n", g=1)
deck("k10_shell_sleep_long", "# shell sleep 30 (a process): the engine waits 30 s; the audit must not hang\n"
     + BASE() + TWO + "shell sleep 30\nrun 100\n", g=1)
deck("k11_write_coeff_absolute", "# write_coeff /tmp/f21k11.coeff\n"
     + BASE() + TWO + "write_coeff /tmp/f21k11.coeff\nrun 100\n", g=1)
deck("k12_shell_cd_absolute_then_write", "# shell cd /tmp then write_data f21k12.data: the file lands in /tmp\n"
     + BASE() + TWO + "shell cd /tmp\nwrite_data f21k12.data\nrun 100\n", g=1)
deck("k13_dump_image_less_dump_run", "# dump every 50 steps to /tmp/f21k13.dump during the run (written only when runs are made)\n"
     + BASE() + TWO + "dump d all atom 50 /tmp/f21k13.dump\nrun 100\n", g=1)

# ================================================================ d*: data, restart round trips, delete, groups
deck("d01_read_data_add_offset_types", "# read_data a second file with add append offset 1 0 0 0 0: its type-1 atoms become type 2 (8 mm)\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data a.data extra/atom/types 1\nread_data b.data add append offset 1 0 0 0 0\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"a.data": "a\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.02 0.01\n",
           "b.data": "b\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.008 2500 0.01 0.01 0.01\n"})
deck("d02_write_restart_clear_read", "# write_restart state.rst, clear, read_restart state.rst: engine reads 6 mm\n"
     + BASE() + TWO + "run 100\nwrite_restart state.rst\nclear\nread_restart state.rst\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1)
deck("d03_read_dump_changes_type", "# read_dump of a shipped dump changes atom 1's type to 2 (fields type): both spheres type 2 (4 and 6 mm)\n"
     + BASE() + TWO + "read_dump state.dump 0 x y z type box no\nrun 100\n", g=1,
     data={"state.dump": "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z\n1 2 0.02 0.02 0.01\n2 2 0.01 0.01 0.01\n"})
deck("d04_set_type_fraction", "# 10 type-1 spheres, set type/fraction 2 0.5 seed: about half become type 2 (4 mm, same size): 1 2 and 2 2 pairs appear\n"
     + BASE() + "create_atoms 1 random 10 4242 NULL\nset type 1 diameter 0.004 density 2500\nset type 1 type/fraction 2 0.5 8181\nprint \"PROBE n2 $(count(all))\"\nrun 100\n", g=1)
deck("d05_set_type_ratio_then_diameter", "# set type/ratio 2 0.3 then set type 2 diameter 0.008: the 8 mm spheres are type 2 only\n"
     + BASE() + "create_atoms 1 random 10 4242 NULL\nset type 1 diameter 0.004 density 2500\nset type 1 type/ratio 2 0.3 8181\nset type 2 diameter 0.008\nrun 100\n", g=1)
deck("d06_delete_atoms_random_all_type2", "# delete_atoms random fraction 1.0 yes on group t2: every type-2 sphere is deleted (no 1 2 contact)\n"
     + BASE() + TWO + "group t2 type 2\ndelete_atoms random fraction 1.0 yes t2 NULL 4242\nrun 100\n", g=1)
deck("d07_group_dynamic_wall", "# the floor acts on a dynamic group (z < 0.02: all spheres when the run starts)\n"
     + head() + G1(HK) + GRAV + "region lowr block INF INF INF INF INF 0.02 units box\ngroup low dynamic all region lowr every 1\nfix floor low wall/gran granular " + HK + " zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g=1)
deck("d08_create_atoms_overlap_after_run", "# after a run, create_atoms 2 random 3 with overlap 0.004: where they land depends on the run; sizes are 6 mm all the same\n"
     + BASE() + TWO + "run 100\ncreate_atoms 2 random 3 999 NULL overlap 0.004\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("d09_replicate_then_set", "# replicate 2 2 1 (4x atoms), then set atom 5 diameter 0.008 (a type-1 copy): type 1 has 4 and 8 mm\n"
     + BASE() + TWO + "replicate 2 2 1\nset atom 5 diameter 0.008\nrun 100\n", g=1)
deck("d10_write_data_pair_ij_read_back", "# write_data then clear and read_data: pair coeffs are not in a granular data file? (engine says); re-given after\n"
     + BASE() + TWO + "pair_coeff * * " + hk(7000) + "\nwrite_data state.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data state.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1)

# ================================================================ N*: LIGGGHTS


L("N01_settings_in_include_only", "# all LIGGGHTS markers (atom_style granular, property/global, pair_style gran model) in an include: the main file looks like LAMMPS; LIGGGHTS runs it (e 0.6/0.5/0.4)\n"
  + "include in.settings\ncreate_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
  + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n" + RUN,
  data={"in.settings": lhead() + MAT3 + E3 + HERTZ})
L("N02_comment_amp_swallows_property", "# a comment ending in & swallows the next line (fix m3 e 0.2): LIGGGHTS keeps the first e matrix (0.6 ...)\n"
  + lhead() + MAT3 + E3 + "# softer restitution for the test &\n" + E3b(0.2) + HERTZ + WALL3 + ATOMS + RUN)
L("N03_peratomtypepair_bigger_than_ntypes", "# create_box 2 but coefficientRestitution peratomtypepair 3 (9 values): LIGGGHTS reads the matrix as 3x3? (engine says) 1 2 = 0.5\n"
  + lhead(nt=2) + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3\n"
  + "fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + ATOMS + RUN)
L("N04_cohesion_sjkr", "# hertz with cohesion sjkr (cohesionEnergyDensity 1e5): an attraction in every contact, eps not hertz's\n"
  + lhead() + MAT3 + E3 + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
  + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n" + WALL3 + ATOMS + RUN)
L("N05_units_cgs_hertz", "# LIGGGHTS units cgs: E 5e7 dyn/cm2 (5e6 Pa), 0.4 cm spheres 2.5 g/cm3; eps from the typed e (0.6 ...)\n"
  + lhead(units="cgs", box="-5 5 -5 5 -1 15").replace("neighbor 0.002", "neighbor 0.2")
  + MAT3.replace("5e6", "5e7") + E3 + HERTZ + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
  + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\n"
  + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n", g="10 100")
L("N06_loop_run_every_next", "# LIGGGHTS loop of 2 passes, each redefining m3 with e = 0.3*i and running: last e 0.6\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "variable i loop 2\nlabel lp\nvariable e equal 0.3*$i\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\nnext i\njump SELF lp\n")
L("N07_write_restart_clear_read", "# LIGGGHTS write_restart, clear, read_restart; the property fixes given again with e 0.3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "write_restart st.rst\nclear\natom_style granular\natom_modify map array\nnewton off\ncommunicate single vel yes\nread_restart st.rst\nneighbor 0.002 bin\n"
  + MAT3 + E3b(0.3) + HERTZ + WALL3 + RUN)
L("N08_variable_delete_redefine_e", "# LIGGGHTS variable e delete then string 0.35: m3 uses ${e} = 0.35\n"
  + lhead() + MAT3 + "variable e string 0.9\nvariable e delete\nvariable e string 0.35\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N09_jump_label_var_name", "# LIGGGHTS jump SELF ${t} to 'hard' (e 0.8), skipping 'soft' (e 0.2)\n"
  + lhead() + MAT3 + "variable t string hard\njump SELF ${t}\nlabel soft\n" + E3b(0.2) + "jump SELF go\nlabel hard\n" + E3b(0.8) + "label go\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N10_neigh_exclude_type_12", "# LIGGGHTS neigh_modify exclude type 1 2: 1 2 never meet\n"
  + LB() + ATOMS + "neigh_modify exclude type 1 2\n" + RUN)
L("N11_set_type_type_change", "# LIGGGHTS set atom 1 type 2: both spheres type 2\n"
  + LB() + ATOMS + "set atom 1 type 2\n" + RUN)
L("N12_nbsp_in_property", "# a non-breaking space (UTF-8 C2 A0) inside the m3 line: LIGGGHTS 3.8 (no UTF-8 substitution) errors? (engine says)\n"
  + lhead() + MAT3 + E3.replace("peratomtypepair 3", "peratomtypepair\u00a03") + HERTZ + WALL3 + ATOMS + RUN)
L("N13_if_on_variable_then_property", "# LIGGGHTS if \"${k} > 1\" then the m3 with e 0.25 (no run inside the if)\n"
  + lhead() + MAT3 + E3 + "variable k equal 2\nif \"${k} > 1\" then \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25\"\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N14_include_relative_cwd", "# LIGGGHTS sub/in.a includes in.b: LIGGGHTS opens ./in.b (e 0.3) not sub/in.b (e 0.9)\n"
  + lhead() + MAT3 + E3 + "include sub/in.a\n" + HERTZ + WALL3 + ATOMS + RUN,
  data={"sub/in.a": "include in.b\n", "in.b": E3b(0.3), "sub/in.b": E3b(0.9)})
L("N15_file_variable_next", "# LIGGGHTS variable e file e.txt (comment line, 0.45, 0.65); next e between two runs: the second stage e 0.65\n"
  + lhead() + MAT3 + "variable e file e.txt\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\n" + HERTZ + WALL3 + ATOMS + LRUN
  + "run 100\nnext e\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\n",
  data={"e.txt": "# e values\n0.45\n0.65\n"})
L("N16_ke_settle_loop", "# LIGGGHTS settling loop on ke: run 500, if ke below 1e-10 leave; then e 0.2 for the last run (LIGGGHTS if only with jump, no run inside)\n"
  + LB() + ATOMS + LRUN + "variable k equal ke\nvariable n loop 10\nlabel lp\nrun 500\nif \"${k} < 1e-10\" then \"jump SELF out\"\nnext n\njump SELF lp\nlabel out\n" + E3b(0.2) + "run 100\n")
L("N17_fix_freeze_then_unfix", "# LIGGGHTS type 2 frozen for run 1, unfix for run 2: the last stage has 1 2 as two free spheres\n"
  + LB() + ATOMS + "group t2 type 2\nfix fz t2 freeze\n" + LRUN + "run 100\nunfix fz\nrun 100\n")
L("N18_hooke_e_via_variable_loop", "# LIGGGHTS hooke with characteristicVelocity from a variable equal 0.5*4 -> 2\n"
  + lhead() + MAT3 + E3 + "variable cv equal 0.5*4\nfix m9 all property/global characteristicVelocity scalar ${cv}\n" + HOOKE + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("N19_mesh_and_primitive_same_type", "# LIGGGHTS two walls: primitive zplane 0 (type 3) and a second primitive xplane -0.04 (type 3) in one fix? two fixes\n"
  + LB() + "fix wx all wall/gran model hertz tangential history primitive type 3 xplane -0.04\n" + ATOMS + RUN)
L("N20_quit_after_loop_jump", "# LIGGGHTS loop 2 then jump to a label after which quit: the e 0.2 stage after quit never runs\n"
  + LB() + ATOMS + LRUN + "variable i loop 2\nlabel lp\nrun 100\nnext i\njump SELF lp\nquit\n" + E3b(0.2) + "run 100\n")
L("N21_set_density_after_run_region", "# LIGGGHTS set region (left half) density 7800 after the run (positions not moved far): type 2 steel\n"
  + LB() + ATOMS + RUN + "region left block -0.05 0 -0.05 0.05 -0.01 0.15 units box\nset region left density 7800\nrun 100\n")
L("N22_timestep_variable_between", "# LIGGGHTS timestep from a variable 2e-6 between runs\n"
  + LB() + ATOMS + RUN + "variable d equal 2e-6\ntimestep ${d}\nrun 100\n")
L("N23_hertz_property_uppercase_e", "# LIGGGHTS youngsModulus via a variable in scientific notation '5.0E6'\n"
  + lhead() + "variable Y string 5.0E6\nfix m1 all property/global youngsModulus peratomtype ${Y} ${Y} ${Y}\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
  + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("N24_delete_atoms_region_type2", "# LIGGGHTS delete_atoms region (left half, type 2 only there): 1 2 gone for run 2\n"
  + LB() + ATOMS + RUN + "region left block -0.05 -0.005 -0.05 0.05 -0.01 0.15 units box\ndelete_atoms region left\nrun 100\n")
L("N25_liggghts_jump_other_file", "# LIGGGHTS jump in.part2 (e 0.3, run): in.deck's later e 0.9 never runs\n"
  + LB() + ATOMS + LRUN + "jump in.part2\n" + E3b(0.9) + "run 100\n", data={"in.part2": E3b(0.3) + "run 100\n"})

L("N26_run_from_string_variable", "# LIGGGHTS: variable r string run; ${r} 1000 (e 0.6 ...), then e 0.2 and run 100: two stages\n"
  + LB() + ATOMS + LRUN + "variable r string run\n${r} 1000\n" + E3b(0.2) + "run 100\n")
L("N27_property_from_string_variable", "# LIGGGHTS: the m3 line held in a string variable and run as ${c}: e 0.25 everywhere\n"
  + lhead() + MAT3 + E3 + "variable c string \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25\"\n${c}\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N28_run_continued_amp", "# LIGGGHTS: 'run &' with 1000 on the next line (e 0.6 ...), then e 0.2 and run 100: two stages\n"
  + LB() + ATOMS + LRUN + "run &\n  1000\n" + E3b(0.2) + "run 100\n")
L("N29_run_in_include", "# LIGGGHTS: the first run in an included file (in.run: run 1000), then e 0.2 and run 100: two stages\n"
  + LB() + ATOMS + LRUN + "include in.run\n" + E3b(0.2) + "run 100\n", data={"in.run": "run 1000\n"})
L("N30_comment_amp_swallows_run", "# LIGGGHTS: a comment ending in & swallows 'run 1000': the deck makes only the e 0.2 run\n"
  + LB() + ATOMS + LRUN + "# settle first &\nrun 1000\n" + E3b(0.2) + "run 100\n")
L("N31_property_line_continued", "# LIGGGHTS: the m3 line continued with & over two lines (0.6 0.5 0.7 / 0.5 0.4 0.45 ...)\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.35 0.5 0.7 &\n 0.5 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N32_run_tab_leading", "# LIGGGHTS: '\\trun\\t1000' with tabs, then e 0.2 and run 100: two stages\n"
  + LB() + ATOMS + LRUN + "\trun\t1000\n" + E3b(0.2) + "run 100\n")
L("N33_quit_from_string_variable", "# LIGGGHTS: run 1000 (e 0.6 ...), then ${q} with q string quit: the e 0.2 stage never runs\n"
  + LB() + ATOMS + LRUN + "variable q string quit\nrun 1000\n${q}\n" + E3b(0.2) + "run 100\n")
L("N34_jump_from_string_variable", "# LIGGGHTS: ${j} with j string 'jump SELF skip' skips the e 0.2 line (e stays 0.6 ...)\n"
  + LB() + ATOMS + LRUN + "variable j string \"jump SELF skip\"\n${j}\n" + E3b(0.2) + "label skip\nrun 1000\n")
L("N35_include_from_string_variable", "# LIGGGHTS: ${i} with i string 'include in.e' where in.e sets e 0.3\n"
  + LB() + ATOMS + LRUN + "variable i string \"include in.e\"\n${i}\nrun 1000\n", data={"in.e": E3b(0.3)})
L("N36_unfix_property_via_string", "# LIGGGHTS: the second wall's fix made from a string variable ${w} (xplane -0.04, type 3)\n"
  + LB() + ATOMS + "variable w string \"fix wx all wall/gran model hertz tangential history primitive type 3 xplane -0.04\"\n${w}\n" + RUN)
L("N37_smart_quotes_if_liggghts", "# LIGGGHTS 3.8 if with typographic quotes: no UTF-8 substitution in this LIGGGHTS (engine says)\n"
  + LB() + ATOMS + "if \u201c1 > 0\u201d then \u201cfix m3 all property/global coefficientRestitution peratomtypepair 3 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25 0.25\u201d\n" + RUN)
L("N38_run_every_liggghts_string", "# LIGGGHTS: a run from string variable with upto: ${r} 1000 upto; then e 0.2 and run 100\n"
  + LB() + ATOMS + LRUN + "variable r string \"run 1000 upto\"\n${r}\n" + E3b(0.2) + "run 100\n")

L("N39_random_e_after_print", "# LIGGGHTS: e from an equal-style random() (0.2..0.9); a print of ${r} draws first, so e is the second draw\n"
  + lhead() + MAT3 + "variable r equal random(0.2,0.9,32452843)\nprint \"PROBE first ${r}\"\nvariable e equal ${r}\nprint \"PROBE e ${e}\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\n" + HERTZ + WALL3 + ATOMS + RUN)
L("N40_random_e_thermo_draws", "# LIGGGHTS: thermo_style custom step v_r during run 1 draws; e = ${r} after it for run 2\n"
  + LB() + ATOMS + LRUN + "variable r equal random(0.2,0.9,32452843)\nthermo_style custom step v_r\nthermo 100\nrun 1000\nvariable e equal ${r}\nprint \"PROBE e ${e}\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 100\n")

L("N41_run_every_if_quit_liggghts", "# LIGGGHTS run 2000 every 1000 \"if '${s} >= 1000' then quit\" (s equal step): quits after the first part; the e 0.2 stage never runs\n"
  + LB() + ATOMS + LRUN + "variable s equal step\nrun 2000 every 1000 \"if '${s} >= 1000' then quit\"\n" + E3b(0.2) + "run 100\n")

L("N42_run_every_if_quit_continued_liggghts", "# LIGGGHTS, R01's form: run 2000 every 1000 & / \"if '${s} >= 1000' then & / 'print done' & / 'quit'\": quits after part 1; the e 0.2 stage never runs\n"
  + LB() + ATOMS + LRUN + "variable s equal step\nrun 2000 every 1000 &\n    \"if '${s} >= 1000' then &\n        'print PROBE-done' &\n        'quit'\"\n" + E3b(0.2) + "run 100\n")


if __name__ == "__main__":
    kit.main(sys.argv[1:])
