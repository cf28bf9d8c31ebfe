"""Field round 27: write the decks as decks/NAME/in.deck (G, LIVE, extra files, LIGGGHTS marker), with round 23's helpers.
Most decks carry a LIVE pair (groups lv1, lv2): two spheres approaching at 1 m/s, timed to meet in the run named in the
LIVE file, refereed by live27.py (the deck run as written). Prefixes: E run N every M, P run pre no after a change,
Y hybrid with one sub-style and none, CU per-pair cutoffs, CL clear and losses, M mixed older classes, L LIGGGHTS.
usage: python make_decks27.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from fieldkit import decks as m  # noqa: E402  (round 23's helpers, tests/fieldkit/decks.py)

m.D = os.path.join(HERE, "decks")
deck, hk, HK, K, TL, head, GRAV = m.deck, m.hk, m.HK, m.K, m.TL, m.head, m.GRAV
LIVE = {}
FL = lambda model=HK: f"fix floor all wall/gran granular {model} zplane 0 NULL\n"
TAILL = "fix integ all nve/sphere\ntimestep 1e-6\n"


def lv(gap, ta=1, tb=2, da=0.004, db=0.006, rev=False, z=0.05):
    """the live pair: type ta (diameter da) on the left, tb on the right, gap (m) apart, approaching at 1 m/s (gap/1e-6 steps)"""
    xa, xb = 0.02 - da / 2 - gap / 2, 0.02 + db / 2 + gap / 2
    va, vb = db ** 3 / (da ** 3 + db ** 3), -da ** 3 / (da ** 3 + db ** 3)
    a = f"create_atoms {ta} single {xa:.9g} 0.02 {z}\n"; b = f"create_atoms {tb} single {xb:.9g} 0.02 {z}\n"
    ia, ib = ("2", "1") if rev else ("1", "2")
    return ((b + a) if rev else (a + b)) + (f"set atom {ia} diameter {da} density 2500\nset atom {ib} diameter {db} density 2500\n"
            f"group lv1 id {ia}\ngroup lv2 id {ib}\nvelocity lv1 set {va:.10f} 0 0 units box\nvelocity lv2 set {vb:.10f} 0 0 units box\n")


BL = lambda model=HK, nt=2: head(nt) + "pair_style granular\npair_coeff * * " + model + "\n" + GRAV + FL(model.split(" cutoff")[0]) + TAILL


def E(name, comment, lines, gap=2.1e-3, live="last run", pre=None, data=None, pair=None, sep=None, **kw):
    """a LAMMPS deck: base (kn 2000 everywhere, dt 1e-6), the live pair, then lines"""
    body = (pre or BL()) + (pair if pair is not None else lv(gap)) + lines
    deck(name, "# " + comment + "\n" + body, g=1, data=data, **kw)
    LIVE[name] = live + (f"\nSEP {sep}" if sep else "")


P5 = lambda i="1", j="2", k=5000: f"pair_coeff {i} {j} {hk(k)}"
P8 = lambda i="1", j="2": P5(i, j, 8000)
R3 = 'run 3000 every 1000 "{}"\n'

# ------------------------------------------------------------ E: run N every M with every kind of command
E("E01_pair_coeff", "every pair_coeff 1 2 kn 5000: live pair meets in part 3 (kn 5000)", R3.format(P5()))
E("E02_pair_coeff_part2", "every pair_coeff 1 2 kn 5000: live pair meets in part 2 (after 1 change: kn 5000)", R3.format(P5()), gap=1.1e-3, live="part 2")
E("E03_part1_before_change", "every pair_coeff 1 2 kn 5000: live pair meets in part 1 (kn 2000, before any change)", R3.format(P5()), gap=0.1e-3, live="part 1")
E("E04_not_multiple", "run 2500 every 1000 (parts 1000 1000 500): live pair meets in the 500-step part (kn 5000)", 'run 2500 every 1000 "' + P5() + '"\n', gap=2.05e-3)
E("E05_N_zero", "run 0 every 1 pair_coeff 1 2 kn 5000, then run 3000: live pair in the last run", 'run 0 every 1 "' + P5() + '"\nrun 3000\n', gap=0.1e-3)
E("E06_two_commands", "every 'pair_coeff 1 2 kn 5000' 'pair_coeff 1 2 kn 8000': last wins (8000)", 'run 3000 every 1000 "' + P5() + '" "' + P8() + '"\n')
E("E07_set_density", "every set type 2 density 7800: sizes change (live pair meets in part 3 with 7800)", R3.format("set type 2 density 7800"))
E("E08_set_diameter_step", "every set type 2 diameter $(0.006+step*1e-7): 6.2 mm in part 3 (live pair gap for 6.2 mm)", R3.format("set type 2 diameter $(0.006+step*1e-7)"), sep=0.0051)
E("E09_unfix_refix_floor", "every unfix floor + fix floor kn 8000: wall changes; pair unchanged (kn 2000)", 'run 3000 every 1000 "unfix floor" "fix floor all wall/gran granular ' + hk(8000) + ' zplane 0 NULL"\n')
E("E10_fix_redefine", "every fix floor (same id, same style) kn 8000: replaces the wall", R3.format("fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL"))
E("E11_group_set", "every group g2 type 2 + set group g2 density 5000", 'run 3000 every 1000 "group g2 type 2" "set group g2 density 5000"\n')
E("E12_delete_create", "every delete_atoms region far + create_atoms 1 single far away (a sphere made each part, 4 mm)", "region far block 0 0.04 0 0.04 0.08 0.1 units box\n" + 'run 3000 every 1000 "delete_atoms region far" "create_atoms 1 single 0.01 0.01 0.09"\n')
E("E13_velocity", "every velocity lv1 set 0.7714285714 0 0 (the live pair's own speed reset each part)", R3.format("velocity lv1 set 0.7714285714 0 0 units box"))
E("E14_timestep", "every timestep 5e-7 (dt halves after part 1; live pair meets in part 3)", R3.format("timestep 5e-7"), gap=1.05e-3)
E("E15_timestep_dt", "every timestep $(dt*0.5): 1e-6, 5e-7, 2.5e-7", R3.format("timestep $(dt*0.5)"), gap=1.02e-3)
E("E16_neigh_exclude", "every neigh_modify exclude type 1 2: live pair passes through in part 3", R3.format("neigh_modify exclude type 1 2"))
E("E17_neigh_exclude_none", "neigh_modify exclude type 1 2 before, every neigh_modify exclude none: live pair collides in part 3", "neigh_modify exclude type 1 2\n" + R3.format("neigh_modify exclude none"))
E("E18_displace", "every displace_atoms lv2 move 0 0 0.001 (the pair still meets)", R3.format("displace_atoms lv2 move 0 0 0.001 units box"))
E("E19_change_box", "every change_box all z final 0 0.2 units box", R3.format("change_box all z final 0 0.2 units box"))
E("E20_region_wall", "every fix w all wall/gran/region granular kn 8000 region cyl (same id): cylinder wall", "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\n" + R3.format("fix w all wall/gran/region granular " + hk(8000) + " region cyl"))
E("E21_region_reuse", "every region r2 block ... (the second part reuses the region id: LAMMPS decides)", R3.format("region r2 block 0 0.01 0 0.01 0 0.01 units box"))
E("E22_start_stop", "run 3000 start 0 stop 6000 every 1000 pair_coeff 1 2 kn 5000", 'run 3000 start 0 stop 6000 every 1000 "' + P5() + '"\n')
E("E23_pre_no", "run 3000 pre no every 1000 pair_coeff 1 2 kn 5000 (parts 2, 3 without set-up)", 'run 3000 pre no every 1000 "' + P5() + '"\n')
E("E23b_pre_no_rev", "E23 with the type-2 sphere made first (atom order 2 1)", 'run 3000 pre no every 1000 "' + P5() + '"\n', pair=lv(2.1e-3, rev=True))
E("E24_post_no", "run 3000 post no every 1000 pair_coeff 1 2 kn 5000", 'run 3000 post no every 1000 "' + P5() + '"\n')
E("E25_upto", "run 3000 upto every 1000 (upto: refused before, engine decides)", 'run 3000 upto every 1000 "' + P5() + '"\n')
E("E26_include_file", "the every run inside an included file", "include r.in\n", data={"r.in": R3.format(P5())})
E("E27_in_loop", "loop of 2: each pass run 1500 every 500 pair_coeff 1 2 kn $(1000*v_i+3000) hmm no: kn 5000 then kn 8000 by if before", 'variable i loop 2\nlabel l\nif "$i == 2" then "' + P8() + '"\nrun 1500 every 500 "print hi"\nnext i\njump SELF l\n', gap=2.1e-3)
E("E28_in_if", "if then run every (triple quotes)", 'if "1 > 0" then """run 3000 every 1000 "' + P5() + '" """\n')
E("E29_step_var_if", "every 'variable s equal $(step)'; after the run if s == 3000 then kn 5000; run 1000 (live pair there)", R3.format("variable s equal $(step)") + 'if "${s} == 3000" then "' + P5() + '" else "' + P8() + '"\nrun 1000\n', gap=3.1e-3)
E("E30_step_coeff", "every pair_coeff 1 2 hooke $(step) 3000 ...: kn 1000 after part 1, 2000 after part 2 (part 3: kn 2000)", R3.format("pair_coeff 1 2 hooke $(step) 3000 " + K))
E("E31_step_coeff_part2", "E30 with the live pair in part 2 (kn 1000)", R3.format("pair_coeff 1 2 hooke $(step) 3000 " + K), gap=1.1e-3, live="part 2")
E("E32_unfix_twice", "every unfix floor (part 2's unfix finds no fix: LAMMPS stops)", R3.format("unfix floor"))
E("E33_delete_live", "every delete_atoms group lv1 (the left sphere deleted after part 1: no 1 2 contact)", R3.format("delete_atoms group lv1"))
E("E34_write_data", "every write_data d.data (files the deck writes)", R3.format("write_data d.data"))
E("E35_lost_ignore", "every thermo_modify lost ignore", R3.format("thermo_modify lost ignore"))
E("E36_dollar_var", "every pair_coeff 1 2 hooke ${k} (a substitution: refused before)", "variable k equal 5000\n" + R3.format("pair_coeff 1 2 hooke ${k} 3000 " + K))
E("E37_include_cmd", "every include kn.in (include excluded)", R3.format("include kn.in"), data={"kn.in": P5() + "\n"})
E("E38_1001_parts", "run 1001 every 1 print x (1001 parts)", 'run 1001 every 1 "print x"\nrun 2000\n', gap=1.1e-3)
E("E39_1000_parts", "run 1000 every 1 pair_coeff 1 2 kn 5000 (1000 parts), then run 2000", 'run 1000 every 1 "' + P5() + '"\nrun 2000\n', gap=1.1e-3)
E("E40_M_gt_N", "run 500 every 1000 (M > N: LAMMPS decides)", 'run 500 every 1000 "' + P5() + '"\nrun 3000\n', gap=0.6e-3)
E("E41_two_every_runs", "two every runs: kn 5000 then kn 8000 in the second (live pair in the last part)", R3.format(P5()) + R3.format(P8()), gap=5.1e-3)
E("E42_pair_style_restyle", "every pair_style granular + pair_coeff * * kn 5000", 'run 3000 every 1000 "pair_style granular" "pair_coeff * * ' + hk(5000) + '"\n')
E("E43_fix_adapt_var", "every fix ad all adapt 1 atom diameter v_d (a variable reference)", "variable d equal 0.006\n" + R3.format("fix ad all adapt 1 atom diameter v_d"))
E("E44_property_atom", "every set type 1 mass 1e-4 (mass set directly)", R3.format("set type 1 mass 1e-4"))
E("E45_labels", "labelmap atom 1 small 2 big; every pair_coeff small big kn 5000", "labelmap atom 1 small 2 big\n" + R3.format(P5("small", "big")))
E("E46_range_every", "every pair_coeff 1*2 2 kn 5000 (1 2 and 2 2)", R3.format(P5("1*2", "2")))
E("E47_exclude_group", "every neigh_modify exclude group lv1 lv2", R3.format("neigh_modify exclude group lv1 lv2"))
E("E48_pour_across", "fix pour of 4 mm type 1 spheres in a band above, run 20000 every 5000 print: the pour runs across parts", "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 5 1 4767 region ins diam one 0.003 dens 7800 7800\n" + 'run 20000 every 5000 "print part"\n', gap=15.1e-3)
E("E49_create_set_size", "every create_atoms 1 single ... + set type 1 diameter 0.005 (the live sphere grows too)", 'run 3000 every 1000 "create_atoms 1 single 0.01 0.01 0.09" "set type 1 diameter 0.005"\n', sep=0.0055)
E("E50_nested_every_include", "include r.in twice (each an every run with another kn)", "include r.in\ninclude r2.in\n", data={"r.in": R3.format(P5()), "r2.in": R3.format(P8())}, gap=5.1e-3)
E("E51_every_in_jump_file", "jump to a file whose every run changes kn", "jump r.in\n", data={"r.in": R3.format(P5())})
E("E52_time_print", "every print $(time) $(dt) (only printing)", R3.format("print 't $(time) dt $(dt)'"))
E("E53_every_then_pre_no", "every run changes kn 5000, then run 1000 pre no (no change since the last set-up)", R3.format(P5()) + "run 1000 pre no\n", gap=3.1e-3)
E("E54_every_pair_none_hybrid", "hybrid granular granular; every pair_coeff 1 2 none", 'run 3000 every 1000 "pair_coeff 1 2 none"\n', pre=head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\n" + GRAV + FL() + TAILL)
E("E55_every_hybrid_back", "hybrid granular granular; 1 2 none, every pair_coeff 1 2 granular 2 kn 5000", 'pair_coeff 1 2 none\nrun 3000 every 1000 "pair_coeff 1 2 granular 2 ' + hk(5000) + '"\n', pre=head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\n" + GRAV + FL() + TAILL)
E("E56_every_fix_viscous", "every fix v all viscous 1e-4 (a damping fix)", R3.format("fix v all viscous 1e-4"))
E("E57_every_unfix_integ", "every unfix integ + fix integ all nve/sphere", 'run 3000 every 1000 "unfix integ" "fix integ all nve/sphere"\n')
E("E58_every_reset_timestep", "every reset_timestep 0", R3.format("reset_timestep 0"))
E("E59_every_comm", "every comm_modify cutoff 0.02", R3.format("comm_modify cutoff 0.02"))
E("E60_every_kspace_dielectric", "every pair_coeff 1 2 hertz/material (model change in every)", R3.format("pair_coeff 1 2 " + m.HM))

# ------------------------------------------------------------ P: run pre no after a contact change
E("P01_pair12_pre_no", "run 1000, pair_coeff 1 2 kn 5000, run 3000 pre no (live pair there)", "run 1000\n" + P5() + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P02_pair12_pre_no_rev", "P01 with the type-2 sphere made first", "run 1000\n" + P5() + "\nrun 3000 pre no\n", gap=1.1e-3, pair=lv(1.1e-3, rev=True))
E("P03_pair11_pre_no", "run 1000, pair_coeff 1 1 kn 5000, run 3000 pre no; live pair two type-1 spheres", "run 1000\n" + P5("1", "1") + "\nrun 3000 pre no\n", gap=1.1e-3, pair=lv(1.1e-3, 1, 1, 0.004, 0.004), sep=0.004)
E("P04_set_pre_no", "run 1000, set type 2 density 7800, run 3000 pre no", "run 1000\nset type 2 density 7800\nrun 3000 pre no\n", gap=1.1e-3)
E("P05_starstar_pre_no", "run 1000, pair_coeff * * kn 5000, run 3000 pre no", "run 1000\npair_coeff * * " + hk(5000) + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P06_wall_pre_no", "run 1000, fix floor kn 8000 (same id), run 3000 pre no", "run 1000\n" + FL(hk(8000)) + "run 3000 pre no\n", gap=1.1e-3)
E("P07_restyle_pre_no", "run 1000, pair_style granular + * * kn 5000, run 3000 pre no", "run 1000\npair_style granular\npair_coeff * * " + hk(5000) + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P08_run0_between", "run 1000, pair_coeff 1 2 kn 5000, run 0, run 3000 pre no (set up by run 0)", "run 1000\n" + P5() + "\nrun 0\nrun 3000 pre no\n", gap=1.1e-3)
E("P09_labels_pre_no", "labels small big; run 1000; pair_coeff big small kn 5000; run pre no", "labelmap atom 1 small 2 big\nrun 1000\n" + P5("big", "small") + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P10_reversed_pre_no", "pair_coeff 2 1 kn 5000 then run pre no", "run 1000\n" + P5("2", "1") + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P11_change_run_then_pre_no", "change, run 1000 (set up), run 3000 pre no", "run 1000\n" + P5() + "\nrun 1000\nrun 3000 pre no\n", gap=2.1e-3)
E("P12_exclude_pre_no", "run 1000, neigh_modify exclude type 1 2, run 3000 pre no", "run 1000\nneigh_modify exclude type 1 2\nrun 3000 pre no\n", gap=1.1e-3)
E("P13_pair22_pre_no", "run 1000, pair_coeff 2 2 kn 5000, run 3000 pre no; live pair 1 2 (unchanged)", "run 1000\n" + P5("2", "2") + "\nrun 3000 pre no\n", gap=1.1e-3)
E("P14_first_run_pre_no", "pair_coeff 1 2 kn 5000, then the deck's FIRST run with pre no (LAMMPS sets up the first run anyway)", P5() + "\nrun 3000 pre no\n", gap=0.1e-3)
E("P15_pre_no_in_include", "the change and the pre no run in an include", "run 1000\ninclude c.in\n", gap=1.1e-3, data={"c.in": P5() + "\nrun 3000 pre no\n"})
E("P16_unfix_floor_pre_no", "run 1000, unfix floor, run 3000 pre no", "run 1000\nunfix floor\nrun 3000 pre no\n", gap=1.1e-3)
E("P17_timestep_pre_no", "run 1000, timestep 5e-7, run 3000 pre no", "run 1000\ntimestep 5e-7\nrun 6000 pre no\n", gap=2.1e-3)
E("P18_hertz_pre_no", "hertz/material base; run 1000; pair_coeff 1 2 other E; run pre no", "run 1000\npair_coeff 1 2 hertz/material 3e7 1.4e7 0.3 damping viscoelastic " + TL + "\nrun 3000 pre no\n", gap=1.1e-3, pre=BL(m.HM))
E("P19_mixed_pre_no", "run 1000; pair_coeff 1 1 kn 8000 (the 1 2 pair mixes from 1 1 and 2 2? explicit * * first); run pre no", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", gap=1.1e-3, pre=head(2) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\n" + GRAV + FL() + TAILL)

# ------------------------------------------------------------ Y: hybrid with one sub-style and none
HY = lambda lines, nt=2, sub="granular": head(nt) + f"pair_style hybrid {sub}\n" + lines + GRAV + FL() + TAILL
GG = "pair_coeff * * granular " + HK + "\n"
E("Y01_none12", "hybrid granular, * * granular, 1 2 none (LAMMPS collides 1 2)", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\n"), gap=0.1e-3)
E("Y02_none_then_back", "1 2 none then pair_coeff 1 2 granular kn 5000", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\npair_coeff 1 2 granular " + hk(5000) + "\n"), gap=0.1e-3)
E("Y03_none11_and_12", "1 1 none and 1 2 none", "run 3000\n", pre=HY(GG + "pair_coeff 1 1 none\npair_coeff 1 2 none\n"), gap=0.1e-3)
E("Y04_star2_none", "pair_coeff * 2 none (1 2 and 2 2)", "run 3000\n", pre=HY(GG + "pair_coeff * 2 none\n"), gap=0.1e-3)
E("Y05_none12_then_22", "1 2 none, then 2 2 none (j j none later)", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\npair_coeff 2 2 none\n"), gap=0.1e-3)
E("Y06_overlay_one_none", "hybrid/overlay granular, * * granular, 1 2 none", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\n", sub="overlay granular".replace("overlay ", "")).replace("hybrid granular", "hybrid/overlay granular"), gap=0.1e-3)
E("Y07_none_restyle_plain", "1 2 none, then pair_style granular + * * kn 5000", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\npair_style granular\npair_coeff * * " + hk(5000) + "\n"), gap=0.1e-3)
E("Y08_none_after_run", "run 1000 (collides), then 1 2 none, run 3000", "run 1000\npair_coeff 1 2 none\nrun 3000\n", pre=HY(GG), gap=1.1e-3)
E("Y09_three_13_none", "3 types; 1 3 none; live pair 1 3", "run 3000\n", pre=HY(GG + "pair_coeff 1 3 none\n", nt=3), pair=lv(0.1e-3, 1, 3, 0.004, 0.006), gap=0.1e-3)
E("Y10_three_22_none_12", "3 types; 2 2 none then 1 2 none (j j none)", "run 3000\n", pre=HY(GG + "pair_coeff 2 2 none\npair_coeff 1 2 none\n", nt=3), gap=0.1e-3)
E("Y11_none_per_type_only", "pair_coeff 1 1 granular, 2 2 granular (no * *), 1 2 none: LAMMPS mixes?", "run 3000\n", pre=HY("pair_coeff 1 1 granular " + HK + "\npair_coeff 2 2 granular " + hk(8000) + "\npair_coeff 1 2 none\n"), gap=0.1e-3)
E("Y12_hooke_history_none", "hybrid gran/hooke/history one sub-style, 1 2 none", "run 3000\n", pre=HY("pair_coeff * * gran/hooke/history\npair_coeff 1 2 none\n", sub="gran/hooke/history 2000 NULL 3000 NULL 0.5 1"), gap=0.1e-3)
E("Y13_none_exclude", "1 2 none and neigh_modify exclude type 1 2", "neigh_modify exclude type 1 2\nrun 3000\n", pre=HY(GG + "pair_coeff 1 2 none\n"), gap=0.1e-3)
E("Y14_none_every_back", "1 2 none, run 3000 every 1000 pair_coeff 1 2 granular kn 5000", 'run 3000 every 1000 "pair_coeff 1 2 granular ' + hk(5000) + '"\n', pre=HY(GG + "pair_coeff 1 2 none\n"))
E("Y15_none_label_range", "labels; pair_coeff small big* none (range with labels? engine decides)", "run 3000\n", pre=HY("labelmap atom 1 small 2 big\n" + GG + "pair_coeff small big none\n"), gap=0.1e-3)

# ------------------------------------------------------------ CU: per-pair cutoffs
CUt = lambda c: f" cutoff {c}"
E("CU01_all_small", "pair_coeff * * ... cutoff 0.001 (every cutoff small)", "run 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU02_one_small", "pair_coeff 1 2 ... cutoff 0.001, others default", "run 3000\n", pre=BL() + "pair_coeff 1 2 " + HK + CUt(0.001) + "\n", gap=0.1e-3)
E("CU03_all_small_big_skin", "every cutoff 0.001, neighbor 0.01 bin (skin larger than the gap)", "neighbor 0.01 bin\nrun 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU04_global_small_one_big", "pair_style granular 0.001 (global), pair_coeff 1 1 cutoff 0.02", "run 3000\n", pre=head(2) + "pair_style granular 0.001\npair_coeff * * " + HK + "\npair_coeff 1 1 " + HK + CUt(0.02) + "\n" + GRAV + FL() + TAILL, gap=0.1e-3)
E("CU05_all_small_then_restyle", "every cutoff small, then pair_coeff * * default (no cutoff) after", "pair_coeff * * " + HK + "\nrun 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU06_cutoff_every", "every pair_coeff * * ... cutoff 0.001 (all small after part 1)", R3.format("pair_coeff * * " + HK + CUt(0.001)))
E("CU07_all_small_approach", "every cutoff 0.004 (below 0.005), default skin 0.001: 0.005 total", "run 3000\n", pre=BL(HK + CUt(0.004)), gap=0.1e-3)
E("CU08_cutoff_exact", "every cutoff 0.005 (= the contact distance)", "run 3000\n", pre=BL(HK + CUt(0.005)), gap=0.1e-3)

# ------------------------------------------------------------ CL: clear and losses
CLB = lambda: BL()
POUR = "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 3 2 4767 region ins diam one 0.003 dens 7800 7800\n"
E("CL01_clear_pour", "run 100, clear, base again, live pair, pour of 3 mm type 2 7800, run 20000", "run 100\nclear\n" + CLB() + lv(15.1e-3) + POUR + "run 20000\n")
E("CL02_clear_first_pour_only", "clear first line, pour-only deck (was refused: give --radius)", "", pre="clear\n" + head(1) + "pair_style granular\npair_coeff * * " + HK + "\n" + GRAV + FL() + TAILL + "region ins block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 20 1 4767 region ins diam range 0.002 0.004\nrun 20000\n", pair="", live="none")
E("CL03_clear_read_data", "write_data, clear, read_data, kn 5000, run", "write_data d.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + hk(5000) + "\n" + GRAV + FL() + TAILL + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n", gap=0.1e-3)
E("CL04_clear_restart", "write_restart, clear, read_restart, pair_coeff kn 5000, run", "write_restart a.rst\nclear\nread_restart a.rst\npair_coeff * * " + hk(5000) + "\n" + GRAV + FL() + TAILL + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n", gap=0.1e-3)
E("CL05_lost_ignore_setup", "thermo_modify lost ignore; a 0.5 m type-2 sphere made: LAMMPS loses others at set-up", "thermo_modify lost ignore\ncreate_atoms 2 single 0.03 0.03 0.05\nset atom 3 diameter 0.5\nrun 3000\n", gap=0.1e-3)
E("CL06_lost_warn_setup", "CL05 with lost warn", "thermo_modify lost warn\ncreate_atoms 2 single 0.03 0.03 0.05\nset atom 3 diameter 0.5\nrun 3000\n", gap=0.1e-3)
E("CL07_clear_lost_ignore", "clear first; CL05", "thermo_modify lost ignore\ncreate_atoms 2 single 0.03 0.03 0.05\nset atom 3 diameter 0.5\nrun 3000\n", pre="clear\n" + BL(), gap=0.1e-3)
E("CL08_lost_in_include", "lost ignore in an include, loss at set-up", "include l.in\ncreate_atoms 2 single 0.03 0.03 0.05\nset atom 3 diameter 0.5\nrun 3000\n", data={"l.in": "thermo_modify lost ignore\n"}, gap=0.1e-3)
E("CL09_clear_deposit", "clear, base, fix deposit of 3 mm type 2 spheres", "run 100\nclear\n" + CLB() + lv(15.1e-3) + "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix dep all deposit 3 2 5000 4767 region ins near 0.004\nset type 2 diameter 0.006\nrun 20000\n")
E("CL10_clear_loop_pour", "loop 2: clear, base, pour type 2 (3 mm then 5 mm by if), run", "", pair="", live="none", pre='variable i loop 2\nlabel l\nclear\n' + BL() + lv(15.1e-3) + 'region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nif "$i == 1" then "fix p all pour 3 2 4767 region ins diam one 0.003 dens 7800 7800" else "fix p all pour 3 2 4767 region ins diam one 0.005 dens 7800 7800"\nrun 20000\nnext i\njump SELF l\n')
E("CL11_lost_in_every", "lost ignore; every set atom 3 diameter 0.5 (a sphere grows: other atoms lost in part 2)", "thermo_modify lost ignore\ncreate_atoms 2 single 0.03 0.03 0.05\n" + R3.format("set atom 3 diameter 0.5"))
E("CL12_lost_ignore_outside", "lost ignore; a type-2 sphere made outside the f face by displace: lost at set-up", "thermo_modify lost ignore\ncreate_atoms 2 single 0.03 0.03 0.05\ndisplace_atoms lv2 move 0 0 0.2 units box\nrun 3000\n", gap=0.1e-3)

# ------------------------------------------------------------ M: older classes mixed with the new ones
E("M01_every_units_cgs", "units cgs version of E01 (hooke 2e6, g 100 cm/s) ... live in cm", "", pair="", live="none", pre=head(2, box="0 4 0 4 0 10", units="cgs") + "pair_style granular\npair_coeff * * hooke 2e6 3000 " + K + "\nfix grav all gravity 981 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e6 3000 " + K + " zplane 0 NULL\n" + TAILL + "create_atoms 1 single 1.5 2 5\ncreate_atoms 2 single 2.5 2 5\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\n" + 'run 3000 every 1000 "pair_coeff 1 2 hooke 5e6 3000 ' + K + '"\n')
E("M02_every_jump_label_after", "every run followed by a jump to a label that changes kn, then run", R3.format(P5()) + "jump SELF x\n" + P8() + "\nlabel x\nrun 1000\n", gap=3.1e-3)
E("M03_every_format_if", "every variable s equal $(step); if $(v_s:%.0f) == 3000 then include kn8.in", R3.format("variable s equal $(step)") + 'if "$(v_s:%.0f) == 3000" then "include kn8.in"\nrun 1000\n', gap=3.1e-3, data={"kn8.in": P8() + "\n"})
E("M04_every_with_halt", "fix halt on step > 1500 error continue, run 3000 every 1000 kn 5000, then run 2000", "variable st equal step\nfix h all halt 1 v_st > 1500 error continue\n" + R3.format(P5()) + "unfix h\nrun 2000\n", gap=2.2e-3)
E("M05_every_then_set_order", "every set type 2 diameter 0.008; then set type 2 density 7800", R3.format("set type 2 diameter 0.008") + "set type 2 density 7800\nrun 1000\n", gap=3.1e-3, sep=0.006)
E("M06_every_timer_timeout", "timer timeout 1000 (s), every run; nothing stops", "timer timeout 1000\n" + R3.format(P5()))
E("M07_every_next_loop_var", "loop i 3 with every run inside printing $(step); kn changes by if on i", 'variable i loop 3\nlabel l\nif "$i == 3" then "' + P5() + '"\nrun 1000 every 500 "print $(step)"\nnext i\njump SELF l\n', gap=2.1e-3)
E("M08_every_lj", "units lj; dt 0.005 default; every pair_coeff", "", pair="", live="none", pre=head(2, units="lj", box="0 40 0 40 0 100") + "pair_style granular\npair_coeff * * hooke 2000 30 " + K + "\nfix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2000 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ncreate_atoms 1 single 10 20 5\ncreate_atoms 2 single 20 20 5\nset type 1 diameter 1 density 1\nset type 2 diameter 1.5 density 1\n" + 'run 3000 every 1000 "pair_coeff 1 2 hooke 5000 30 ' + K + '"\n')
E("M09_every_2d", "dimension 2 every set type 2 density 7800", "", pair="", live="none", pre=head(2, dim=2, box="0 0.04 0 0.1 -0.001 0.001", bnd="p f p") + "pair_style granular\npair_coeff * * " + HK + "\nfix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix e2 all enforce2d\n" + TAILL + "create_atoms 1 single 0.01 0.01 0\ncreate_atoms 2 single 0.03 0.01 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n" + R3.format("set type 2 density 7800"))
E("M10_every_restyle_hooke_history", "every pair_style gran/hooke/history 5000 ...: restyle in parts", R3.format("pair_style gran/hooke/history 5000 NULL 3000 NULL 0.5 1") [:-2] + '" "pair_coeff * *"\n')
E("M11_every_quit", "every quit (quit excluded: refused? engine stops after part 1)", R3.format("quit"))
E("M12_every_clear", "every clear (LAMMPS decides)", R3.format("clear"))
E("M13_every_label", "every label x (LAMMPS decides)", R3.format("label x"))
E("M14_every_if_cmd", "every if 1 then pair_coeff (if excluded)", 'run 3000 every 1000 "if 1 then \'' + P5() + '\'"\n')
E("M15_every_semicolon_quote", "every 'pair_coeff ...' with single quotes", "run 3000 every 1000 '" + P5() + "'\n")
E("M16_every_dt_timestep_fixdt", "fix dt/reset + every print", "fix dtr all dt/reset 10 NULL 1e-6 1e-6 units box\n" + R3.format("print hi"))
E("M17_every_read_data_add", "every read_data add append of one sphere file (LAMMPS decides)", R3.format("read_data one.data add append"), data={"one.data": "# one\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01 0.01 0.09\n"})
E("M18_every_velocity_all_zero", "every velocity all set 0 0 0 (the live pair stops: no contact)", R3.format("velocity all set 0 0 0"))
E("M19_every_molecule", "every group + set group lv2 diameter 0.008 (live sphere grows)", R3.format("set group lv2 diameter 0.008"), sep=0.006, gap=2.1e-3)
E("M20_every_fix_freeze", "every fix fr lv2 freeze (the right sphere frozen in parts 2,3)", R3.format("fix fr lv2 freeze"))

# ------------------------------------------------------------ L: LIGGGHTS (typed e: 1 1 0.6, 1 2 0.5, 2 2 0.4; wall type 3)
E3b = m.E3b


def Ll(name, comment, lines, gap=2.1e-3, live="last run", head_=None):
    xa, xb = -0.002 - gap / 2, 0.003 + gap / 2
    va, vb = 27 / 35, -8 / 35
    pair = (f"create_atoms 1 single {xa:.9g} 0 0.1 units box\ncreate_atoms 2 single {xb:.9g} 0 0.1 units box\n"
            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {va:.10f} 0 0\nvelocity lv2 set {vb:.10f} 0 0\n")
    body = (head_ or m.LB()) + pair + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n" + lines
    m.L(name, "# LIGGGHTS: " + comment + "\n" + body, g=1)
    LIVE[name] = live


E3x = lambda e12: f"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 {e12} 0.7 {e12} 0.4 0.45 0.7 0.45 0.8"
Ll("L01_every_property_e", "every fix m3 property/global e 1 2 = 0.9 (same id)", R3.format(E3x(0.9)))
Ll("L02_every_set_density", "every set type 2 density 5000", R3.format("set type 2 density 5000"))
Ll("L03_every_print", "every print hi (nothing changes)", R3.format("print hi"))
Ll("L04_pre_no_property", "run 1000, fix m3 e 1 2 = 0.9, run 3000 pre no", "run 1000\n" + E3x(0.9) + "\nrun 3000 pre no\n", gap=1.1e-3)
Ll("L05_every_wall", "every unfix wprim + fix wprim hooke (wall)", 'run 3000 every 1000 "unfix wprim" "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0"\n')
Ll("L06_every_neigh_exclude", "every neigh_modify exclude type 1 2", R3.format("neigh_modify exclude type 1 2"))
Ll("L07_every_two_runs", "every e 0.9 then second every run e 0.2", R3.format(E3x(0.9)) + R3.format(E3x(0.2)), gap=5.1e-3)
Ll("L08_every_step_coeff", "every fix m3 with e 1 2 $(0.1+step/10000) (0.3 in part 3)", R3.format("fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 $(0.1+step/10000) 0.7 $(0.1+step/10000) 0.4 0.45 0.7 0.45 0.8"))
Ll("L09_every_insert", "an insertion fix runs across parts (particletemplate, insert/pack)", m.PTS + "region ins block -0.04 0.04 -0.04 0.04 0.11 0.14 units box\nfix ins all insert/pack seed 32452843 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 3 region ins\n" + R3.format("print hi"))
Ll("L10_every_restyle", "every pair_style gran model hooke + pair_coeff * *", 'run 3000 every 1000 "pair_style gran model hooke tangential history" "pair_coeff * *"\n')



# ------------------------------------------------------------ batch 2: holes around the first batch's findings
def lvw(gap, t=1, d=0.004):
    """a live sphere for walls: type t falling onto the floor at 1 m/s from gap above it (group lv1; lv2 = the same atom)"""
    return f"create_atoms {t} single 0.02 0.02 {d / 2 + gap:.9g}\nset atom 1 diameter {d} density 2500\ngroup lv1 id 1\ngroup lv2 id 1\nvelocity lv1 set 0 0 -1 units box\n"


def W(name, comment, lines, gap=2.1e-3, live="last run", pre=None, **kw):
    E(name, comment, lines, pair=lvw(gap), pre=pre, live=live, **kw)
    LIVE[name] = live + "\nWALL"


E("CU09_all_small_skin5", "every cutoff 0.001, neighbor 0.005 bin (cutoff+skin 0.006 >= 0.005)", "neighbor 0.005 bin\nrun 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU10_all_0035", "every cutoff 0.0035, default skin 0.001 (0.0045 < 0.005)", "run 3000\n", pre=BL(HK + CUt(0.0035)), gap=0.1e-3)
E("CU11_all_small_skin4", "every cutoff 0.001, neighbor 0.004 bin (0.005 = the 1 2 contact distance)", "neighbor 0.004 bin\nrun 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU12_all_small_comm", "every cutoff 0.001, comm_modify cutoff 0.05 (ghost cutoff only)", "comm_modify cutoff 0.05\nrun 3000\n", pre=BL(HK + CUt(0.001)), gap=0.1e-3)
E("CU13_hybrid_all_small", "hybrid granular granular, every cutoff 0.001", "run 3000\n", pre=head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + CUt(0.001) + "\npair_coeff 1 2 granular 2 " + hk(5000) + CUt(0.001) + "\n" + GRAV + FL() + TAILL, gap=0.1e-3)
E("CU14_all_small_skin_in_every", "every cutoff 0.001; run 3000 every 1000 neighbor 0.01 bin", R3.format("neighbor 0.01 bin"), pre=BL(HK + CUt(0.001)))
E("CU15_all_small_bigger_sphere", "every cutoff 0.001, neighbor 0.01 bin; live pair 4 mm and 20 mm (0.012 > 0.011)", "neighbor 0.01 bin\nrun 3000\n", pre=BL(HK + CUt(0.001)), pair=lv(0.1e-3, 1, 2, 0.004, 0.02), sep=0.012, gap=0.1e-3)
E("E61_start_stop_pre_no", "run 3000 start 0 stop 3000 pre no every 1000 kn 5000", 'run 3000 start 0 stop 3000 pre no every 1000 "' + P5() + '"\n')
E("E62_every_NULL", "run 3000 every 1000 NULL (no commands)", "run 3000 every 1000 NULL\n")
E("E63_every_vref", "every pair_coeff 1 2 hooke $(v_k) (a variable read: refused before)", "variable k equal 5000\n" + R3.format("pair_coeff 1 2 hooke $(v_k) 3000 " + K))
E("E64_step_expr", "every pair_coeff 1 2 hooke $(step*2+1000): part 3 kn 5000", R3.format("pair_coeff 1 2 hooke $(step*2+1000) 3000 " + K))
E("E65_step_var_then_coeff", "every variable s equal $(step); then pair_coeff 1 2 hooke ${s} (kn 3000), run 1000", R3.format("variable s equal $(step)") + "pair_coeff 1 2 hooke ${s} 3000 " + K + "\nrun 1000\n", gap=3.1e-3)
E("E66_step_jump_loop", "loop: run 1000 every 500 variable s equal $(step); if s >= 2000 jump out; kn 5000 after", 'label l\nrun 1000 every 500 "variable s equal $(step)"\nif "${s} >= 2000" then "jump SELF out"\njump SELF l\nlabel out\n' + P5() + "\nrun 1000\n", gap=2.1e-3)
E("E67_exclude_pre_no_every", "run 3000 pre no every 1000 neigh_modify exclude type 1 2 (parts 2, 3 without set-up)", 'run 3000 pre no every 1000 "neigh_modify exclude type 1 2"\n')
E("E68_one_part", "run 1000 every 1000 kn 5000, then run 2000", 'run 1000 every 1000 "' + P5() + '"\nrun 2000\n', gap=1.1e-3)
E("E69_delete_pre_no", "run 3000 pre no every 1000 delete_atoms group lv1", 'run 3000 pre no every 1000 "delete_atoms group lv1"\n')
E("E70_set_diam_pre_no", "run 3000 pre no every 1000 set type 2 density 7800", 'run 3000 pre no every 1000 "set type 2 density 7800"\n')
E("E71_every_restyle_pre_no", "run 3000 pre no every 1000 pair_style granular + * * kn 5000", 'run 3000 pre no every 1000 "pair_style granular" "pair_coeff * * ' + hk(5000) + '"\n')
E("E72_every_hybrid_none_one", "hybrid granular (one sub-style); every pair_coeff 1 2 none", 'run 3000 every 1000 "pair_coeff 1 2 none"\n', pre=HY(GG))
E("E73_every_cutoff12", "every pair_coeff 1 2 ... cutoff 0.001 (one pair small)", R3.format("pair_coeff 1 2 " + HK + CUt(0.001)))
E("E74_every_lost", "lost ignore; every displace_atoms lv2 move 0 0 0.2 (lv2 lost in part 2)", "thermo_modify lost ignore\n" + R3.format("displace_atoms lv2 move 0 0 0.2 units box"))
E("E75_every_clear_after", "every run, then clear, base, live pair, run (the every before a clear)", R3.format(P5()) + "clear\n" + BL() + lv(0.1e-3) + "run 3000\n")
E("E76_every_in_loop_include", "loop 2 passes, each include r.in (an every run)", "variable i loop 2\nlabel l\ninclude r.in\nnext i\njump SELF l\n", data={"r.in": 'run 1500 every 500 "' + P5() + '"\n'}, gap=2.1e-3)
P21 = "run 1000\nset type 1 diameter 0.005\nrun 3000 pre no\n"
E("P20_exclude_none_pre_no", "neigh_modify exclude type 1 2; run 1000; exclude none; run 3000 pre no", "neigh_modify exclude type 1 2\nrun 1000\nneigh_modify exclude none\nrun 3000 pre no\n", gap=1.1e-3)
E("P21_diameter_pre_no", "run 1000, set type 1 diameter 0.005, run pre no (sizes: not refused)", P21, gap=2.1e-3, sep=0.0055)
E("P22_hybrid_pre_no", "hybrid granular granular; run 1000; pair_coeff 1 2 granular 2 kn 5000; run pre no", "run 1000\npair_coeff 1 2 granular 2 " + hk(5000) + "\nrun 3000 pre no\n", pre=head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff 2 2 granular 2 " + HK + "\n" + GRAV + FL() + TAILL, gap=1.1e-3)
E("P23_hybrid_none_pre_no", "hybrid granular granular; run 1000; pair_coeff 1 2 none; run pre no", "run 1000\npair_coeff 1 2 none\nrun 3000 pre no\n", pre=head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff 2 2 granular 2 " + HK + "\n" + GRAV + FL() + TAILL, gap=1.1e-3)
E("P24_pre_no_every_first", "pair_coeff 1 2 kn 5000, then run 3000 pre no every 1000 print (first part sets up)", P5() + '\nrun 3000 pre no every 1000 "print x"\n', gap=0.1e-3)
E("P25_two_pre_no", "run 1000; kn 5000; run 1000 pre no; kn 8000; run 3000 pre no", "run 1000\n" + P5() + "\nrun 1000 pre no\n" + P8() + "\nrun 3000 pre no\n", gap=2.1e-3)
E("P26_exclude_type_pre_no_11", "run 1000; neigh_modify exclude type 1 1; run pre no (live pair 1 2)", "run 1000\nneigh_modify exclude type 1 1\nrun 3000 pre no\n", gap=1.1e-3)
W("W01_every_floor_redefine", "wall live: every fix floor kn 8000 (same id)", R3.format("fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL"))
W("W02_pre_no_floor", "wall live: run 1000, fix floor kn 8000, run 3000 pre no", "run 1000\n" + FL(hk(8000)) + "run 3000 pre no\n", gap=1.1e-3)
W("W03_every_unfix_fix_floor", "wall live: every unfix floor + fix floor kn 8000", 'run 3000 every 1000 "unfix floor" "fix floor all wall/gran granular ' + hk(8000) + ' zplane 0 NULL"\n')
W("W04_pre_no_unfix_floor", "wall live: run 1000, unfix floor, run 3000 pre no (no wall)", "run 1000\nunfix floor\nrun 3000 pre no\n", gap=1.1e-3)
W("W05_every_pre_no_floor", "wall live: run 3000 pre no every 1000 fix floor kn 8000", 'run 3000 pre no every 1000 "fix floor all wall/gran granular ' + hk(8000) + ' zplane 0 NULL"\n')
W("W06_plain_control", "wall live control: floor kn 2000, run 3000", "run 3000\n", gap=0.1e-3)
W("W07_plain_control_8000", "wall live control: floor kn 8000 from the start", FL(hk(8000)) + "run 3000\n", gap=0.1e-3)
E("Y16_reversed_none", "hybrid granular; pair_coeff 2 1 none", "run 3000\n", pre=HY(GG + "pair_coeff 2 1 none\n"), gap=0.1e-3)
E("Y17_three_all_unlike_none", "3 types, 1 2, 1 3, 2 3 none; live 1 2", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\npair_coeff 1 3 none\npair_coeff 2 3 none\n", nt=3), gap=0.1e-3)
E("Y18_star_none_star_back", "* * none then * * granular kn 5000", "run 3000\n", pre=HY("pair_coeff * * none\npair_coeff * * granular " + hk(5000) + "\n"), gap=0.1e-3)
E("Y19_range_none_then_11", "1*2 1*2 none then 1 1 granular (2 2 none)", "run 3000\n", pre=HY("pair_coeff 1*2 1*2 none\npair_coeff 1 1 granular " + HK + "\n"), gap=0.1e-3)
E("Y20_none_12_then_11none", "1 2 none, then 1 1 none later", "run 3000\n", pre=HY(GG + "pair_coeff 1 2 none\npair_coeff 1 1 none\n"), gap=0.1e-3)
E("Y21_none_in_if", "1 2 none given by an if", 'if "1 > 0" then "pair_coeff 1 2 none"\nrun 3000\n', pre=HY(GG), gap=0.1e-3)
E("Y22_none_22_three", "3 types; 2 2 none only; live 1 2", "run 3000\n", pre=HY(GG + "pair_coeff 2 2 none\n", nt=3), gap=0.1e-3)

MIX = head(2) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\n" + GRAV + FL() + TAILL
E("P27_mixed_then_explicit_pre_no", "1 1 and 2 2 only (1 2 mixed); run 1000; pair_coeff 1 2 kn 5000; run pre no", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P28_mixed_then_explicit_pre_no_rev", "P27 with the type-2 sphere made first", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pre=MIX, pair=lv(1.1e-3, rev=True), gap=1.1e-3)
E("P29_mixed_11_change_pre_no", "1 1 and 2 2 only; run 1000; pair_coeff 1 1 kn 8000 (mixed 1 2 would change); run pre no", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P30_mixed_11_change_run", "control of P29 without pre no (the mixed 1 2 follows 1 1)", "run 1000\n" + P8("1", "1") + "\nrun 3000\n", pre=MIX, gap=1.1e-3)
E("E77_step_in_set", "every set type 2 density $(2500+step) (3500 in part 2, 4500 in part 3)", R3.format("set type 2 density $(2500+step)"))
E("E78_step_timestep", "every timestep $(1e-6/(1+step/1000)) (dt 5e-7 then 3.33e-7)", R3.format("timestep $(1e-6/(1+step/1000))"), gap=1.55e-3)
E("E79_step_pair_coeff_after_run", "run 2000 then every pair_coeff 1 2 hooke $(step): part 2 of run 2000 every 1000 sees kn 3000", "run 2000\n" + 'run 2000 every 1000 "pair_coeff 1 2 hooke $(step) 3000 ' + K + '"\n', gap=3.1e-3)
E("E80_time_coeff", "every pair_coeff 1 2 hooke $(time*2.5e6) (kn 2500, 5000)", R3.format("pair_coeff 1 2 hooke $(time*2.5e6) 3000 " + K))

E("P31_newton_off_pre_no", "newton off; run 1000; pair_coeff 1 2 kn 5000; run 3000 pre no", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pre=head(2, extra="newton off\n") + "pair_style granular\npair_coeff * * " + HK + "\n" + GRAV + FL() + TAILL, gap=1.1e-3)
E("P32_newton_off_pre_no_rev", "P31 with the type-2 sphere first", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pre=head(2, extra="newton off\n") + "pair_style granular\npair_coeff * * " + HK + "\n" + GRAV + FL() + TAILL, pair=lv(1.1e-3, rev=True), gap=1.1e-3)
E("P33_history_pre_no_rev", "tangential linear_history; type-2 sphere first; run 1000; pair_coeff 1 2 kn 5000; run pre no", "run 1000\npair_coeff 1 2 hooke 5000 3000 damping mass_velocity tangential linear_history 1000 1 0.3\nrun 3000 pre no\n", pre=BL("hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3"), pair=lv(1.1e-3, rev=True), gap=1.1e-3)
E("P34_old_style_pre_no_rev", "gran/hooke/history restyle kn 5000 then pre no; type-2 first", "run 1000\npair_style gran/hooke/history 5000 NULL 3000 NULL 0.5 1\npair_coeff * *\nrun 3000 pre no\n", pair=lv(1.1e-3, rev=True), gap=1.1e-3)
E("P35_three_types_pre_no", "3 types (live 1 3, type-3 first); run 1000; pair_coeff 1 3 kn 5000; run pre no", "run 1000\n" + P5("1", "3") + "\nrun 3000 pre no\n", pre=BL(nt=3), pair=lv(1.1e-3, 1, 3, rev=True), gap=1.1e-3)

E("P36_left2_pre_no", "type-2 sphere on the LEFT (made first); run 1000; pair_coeff 1 2 kn 5000; run 3000 pre no", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pair=lv(1.1e-3, 2, 1, 0.006, 0.004), gap=1.1e-3)
E("P37_left2_second_pre_no", "type-2 sphere on the LEFT made second", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pair=lv(1.1e-3, 2, 1, 0.006, 0.004, rev=True), gap=1.1e-3)
E("E23c_pre_no_left2", "run 3000 pre no every 1000 pair_coeff 1 2 kn 5000, type-2 sphere on the left", 'run 3000 pre no every 1000 "' + P5() + '"\n', pair=lv(2.1e-3, 2, 1, 0.006, 0.004))
E("P38_left2_mixed_explicit", "P27 (1 2 mixed, then explicit) with the type-2 sphere on the left", "run 1000\n" + P5() + "\nrun 3000 pre no\n", pre=MIX, pair=lv(1.1e-3, 2, 1, 0.006, 0.004), gap=1.1e-3)
E("P39_left2_plain_control", "control: type-2 sphere on the left, kn 5000 by a run with set-up", "run 1000\n" + P5() + "\nrun 3000\n", pair=lv(1.1e-3, 2, 1, 0.006, 0.004), gap=1.1e-3)

E("E81_step_expr_then_run", "E64 followed by run 1000 (the every run made for real); pair meets in part 3", R3.format("pair_coeff 1 2 hooke $(step*2+1000) 3000 " + K) + "run 1000\n", live="part 3 of the every run")
E("E82_step_set_then_run", "E77 followed by run 1000; pair meets in part 3", R3.format("set type 2 density $(2500+step)") + "run 1000\n", live="part 3 of the every run")

MIXHM = head(2) + "pair_style granular\npair_coeff 1 1 " + m.HM + "\npair_coeff 2 2 " + m.HM + "\n" + GRAV + FL(m.HM) + TAILL
E("P40_mixed_22_change_pre_no", "1 1, 2 2 only; run 1000; pair_coeff 2 2 kn 8000; run pre no (live 1 2, mixed)", "run 1000\n" + P8("2", "2") + "\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P41_mixed_hertz_pre_no", "hertz/material 1 1, 2 2 only; run 1000; pair_coeff 1 1 E 3e7; run pre no (live 1 2, mixed E)", "run 1000\npair_coeff 1 1 hertz/material 3e7 1.4e7 0.3 damping viscoelastic " + TL + "\nrun 3000 pre no\n", pre=MIXHM, gap=1.1e-3)
E("P42_mixed_every_pre_no", "1 1, 2 2 only; run 3000 pre no every 1000 pair_coeff 1 1 kn 8000 (live 1 2 in part 3)", 'run 3000 pre no every 1000 "' + P8("1", "1") + '"\n', pre=MIX)
E("P43_mixed_every_control", "P42 without pre no", 'run 3000 every 1000 "' + P8("1", "1") + '"\n', pre=MIX)
E("P44_mixed_left2_pre_no", "P29 with the type-2 sphere on the left", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", pre=MIX, pair=lv(1.1e-3, 2, 1, 0.006, 0.004), gap=1.1e-3)
GB = lambda: m.BASE() + m.TWO
def G(name, comment, lines):
    deck(name, "# " + comment + "\n" + GB() + lines, g=1)
G("G01_group_id_delete", "group a id 1; run 100; delete_atoms group a; run 100", "group a id 1\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G02_group_id_range_delete", "group a id 1:1; delete_atoms group a; run 100", "group a id 1:1\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G03_group_idlt_delete", "group a id < 2; delete_atoms group a", "group a id < 2\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G04_group_region_delete", "region r around atom 1; group a region r; delete_atoms group a", "region r sphere 0.02 0.02 0.01 0.003 units box\ngroup a region r\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G05_group_subtract_delete", "group b type 2; group a subtract all b; delete_atoms group a", "group b type 2\ngroup a subtract all b\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G06_group_id_delete_last", "group a id 2 (the 6 mm sphere); delete_atoms group a; run 100", "group a id 2\ndelete_atoms group a\nrun 100\n")
G("G07_group_variable_delete", "variable v atom id==1; group a variable v; delete_atoms group a", "variable v atom id==1\ngroup a variable v\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G08_group_type_control", "control: group a type 1; delete_atoms group a", "group a type 1\nrun 100\ndelete_atoms group a\nrun 100\n")
G("G09_group_id_every_delete", "group a id 1; run 300 every 100 delete_atoms group a (second part: the group is empty)", 'group a id 1\nrun 300 every 100 "delete_atoms group a"\n')
G("G10_delete_atoms_atom_id", "delete_atoms group from group a id 1 with compress no", "group a id 1\nrun 100\ndelete_atoms group a compress no\nrun 100\n")

E("E83_dt_coeff", "every pair_coeff 1 2 hooke $(dt*5e9) (dt 1e-6: kn 5000 each time)", R3.format("pair_coeff 1 2 hooke $(dt*5e9) 3000 " + K))
E("E84_step_print_only", "every print $(step) and pair_coeff 1 2 kn 5000 (the step only printed)", 'run 3000 every 1000 "print $(step)" "' + P5() + '"\n')
E("E85_step_in_fix_wall", "every fix floor kn $(step+7000) (wall from step)", R3.format("fix floor all wall/gran granular hooke $(step+7000) 3000 " + K + " zplane 0 NULL"))
E("E86_step_not_last", "E64 then clear and a new simulation with its own run (the every run not the last of the deck)", R3.format("pair_coeff 1 2 hooke $(step*2+1000) 3000 " + K) + "clear\n" + BL() + lv(0.1e-3) + "run 3000\n", live="the run after clear")
G("G11_group_after_run", "run 100; group a id 1; delete_atoms group a; run 100", "run 100\ngroup a id 1\ndelete_atoms group a\nrun 100\n")
G("G12_delete_overlap", "a third sphere overlapping atom 1 (type 1); delete_atoms overlap 0.003 all all after a run", "create_atoms 1 single 0.021 0.02 0.01\nset atom 3 diameter 0.004 density 2500\nrun 100\ndelete_atoms overlap 0.003 all all\nrun 100\n")
G("G13_group_id_delete_then_create", "group a id 1; run; delete_atoms group a; create_atoms 1 single (type 1 made again); run", "group a id 1\nrun 100\ndelete_atoms group a\ncreate_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nrun 100\n")
G("G14_group_id_in_include", "the delete by an id group inside an include", "group a id 1\nrun 100\ninclude del.in\nrun 100\n")
m.DECKS["G14_group_id_in_include"] = (m.DECKS["G14_group_id_in_include"][0], 1, {"del.in": "delete_atoms group a\n"}, False, "in.deck")
E("P45_mixed_set_pre_no", "1 1, 2 2 only (1 2 mixed); run 1000; set type 2 density 7800; run pre no (sizes: the mix does not read them)", "run 1000\nset type 2 density 7800\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P46_mixed_like_back_same", "1 1, 2 2 only; run 1000; pair_coeff 1 1 with the SAME law again; run pre no", "run 1000\npair_coeff 1 1 " + HK + "\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P47_mixed_like_then_run0", "P29 with run 0 before the pre no run (set up again)", "run 1000\n" + P8("1", "1") + "\nrun 0\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3)
E("P48_mixed_like_include", "P29 with the like change in an include", "run 1000\ninclude c.in\nrun 3000 pre no\n", pre=MIX, gap=1.1e-3, data={"c.in": P8("1", "1") + "\n"})
E("CL13_every_clear_every", "every run; clear; base again; every run with kn 8000", R3.format(P5()) + "clear\n" + BL() + lv(2.1e-3) + R3.format(P8()))
E("CL14_lost_warn_every", "lost warn; every displace lv2 up (lost in part 2)", "thermo_modify lost warn\n" + R3.format("displace_atoms lv2 move 0 0 0.2 units box"))
Ll("L11_pre_no_every", "LIGGGHTS run 3000 pre no every 1000 e 1 2 0.9", 'run 3000 pre no every 1000 "' + E3x(0.9) + '"\n')
Ll("L12_every_include", "LIGGGHTS every run in an include", "include r.in\n")
m.DECKS["L12_every_include"] = (m.DECKS["L12_every_include"][0], 1, {"r.in": R3.format(E3x(0.9))}, True, "in.deck")
Ll("L13_every_delete_group_id", "LIGGGHTS every delete_atoms group lv1 (id group)", R3.format("delete_atoms group lv1"))
Ll("L14_every_set_diameter", "LIGGGHTS every set type 2 diameter 0.008", R3.format("set type 2 diameter 0.008"), gap=3.1e-3)

W("W08_every_floor_step", "wall live: every fix floor hooke $(step+7000) (kn 8000 in part 2, 9000 in part 3; sphere hits in part 3)", R3.format("fix floor all wall/gran granular hooke $(step+7000) 3000 " + K + " zplane 0 NULL"))
W("W09_floor_9000_control", "wall live control: floor kn 9000, the sphere hits after 2.1 mm", FL(hk(9000)) + "run 3000\n")

G("G15_set_group_id_type", "group a id 1; run; set group a type 2 (type 1 now empty); run", "group a id 1\nrun 100\nset group a type 2\nrun 100\n")
G("G16_set_atom_type", "run; set atom 1 type 2; run", "run 100\nset atom 1 type 2\nrun 100\n")
G("G17_set_type_type", "run; set type 1 type 2; run (control, a type group)", "run 100\nset type 1 type 2\nrun 100\n")
G("G18_set_group_id_fraction", "group a id 1; run; set group a type/fraction 2 1.0 12345; run", "group a id 1\nrun 100\nset group a type/fraction 2 1.0 12345\nrun 100\n")
G("G19_set_atom_type_first", "set atom 1 type 2 before the only run", "set atom 1 type 2\nrun 100\n")

HY2 = head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff 2 2 granular 2 " + HK + "\n" + GRAV + FL() + TAILL
E("E87_every_none_two_sub", "hybrid granular granular (both used); every pair_coeff 1 2 none (LAMMPS keeps none with two sub-styles)", 'run 3000 every 1000 "pair_coeff 1 2 none"\n', pre=HY2)
E("E88_every_back_two_sub", "hybrid granular granular; 1 2 none; every pair_coeff 1 2 granular 2 kn 5000", 'pair_coeff 1 2 none\nrun 3000 every 1000 "pair_coeff 1 2 granular 2 ' + hk(5000) + '"\n', pre=HY2)
E("E89_every_none_then_pre_no", "hybrid granular granular; run 1000; 1 2 none; run 3000 pre no (LAMMPS decides)", "run 1000\npair_coeff 1 2 none\nrun 3000 pre no\n", pre=HY2, gap=1.1e-3)

E("E90_1001_parts_coeff", "run 1001 every 1 pair_coeff 1 2 kn 5000 (1001 parts), then run 2000", 'run 1001 every 1 "' + P5() + '"\nrun 2000\n', gap=1.1e-3)
E("E91_every_2000_parts_set", "run 2000 every 1 set type 2 density 7800 (2000 parts), live pair in part 1100-1700", 'run 2000 every 1 "set type 2 density 7800"\n', gap=1.1e-3, live="part ~1100")

def write_all(names):
    m.write_live(names, LIVE)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")
