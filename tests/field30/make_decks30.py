"""Field round 30: write the decks as decks/NAME/in.deck (G, LIVE, SEP, PAIR, ARGS, extra files, LIGGGHTS marker), with
rounds 27-29's helpers (base: kn 2000 everywhere, dt 1e-6; the LIVE pair: two spheres far above the floor approaching at
1 m/s, timed to meet in the run named in LIVE, refereed by live30.py running the deck as written).
Prefixes: G growth before run pre no that the sizes held per type do not show (victims of both sizes, retypes, empty
types), A fix adapt without unfix, N per-run reach, V step-dependent substitutions, R set type/fraction, type/ratio,
type/subset after runs, I quoted include names, C the issue's named classes, L LIGGGHTS.
usage: python make_decks30.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field29"))
import make_decks29 as q  # noqa: E402

r = q.r
m = q.m
m.DECKS.clear(); q.LIVE.clear(); q.EXTRA.clear()
m.D = os.path.join(HERE, "decks")
E, W, Ll, BL, lv, P5, P8, HK, K, hk = q.E, q.W, q.Ll, q.BL, q.lv, q.P5, q.P8, q.HK, q.K, q.hk
R3, E3x, CU, B3, pairA, extra, LIVE, EXTRA = q.R3, q.E3x, q.CU, q.B3, q.pairA, q.extra, q.LIVE, q.EXTRA
g11, g31, g41 = 1.1e-3, 3.1e-3, 4.1e-3
FFF = q.FFF


def Ld(name, comment, lines, data=None, sep=None, pair=None, **kw):
    """a LIGGGHTS deck (round 27's Ll) with extra files, SEP and PAIR"""
    Ll(name, comment, lines, **kw)
    t = m.DECKS[name]
    m.DECKS[name] = (t[0], t[1], data or {}, True, "in.deck")
    if sep:
        extra(name, SEP=str(sep))
    if pair:
        extra(name, PAIR=pair)


def vic(t, da, db, ids=(3, 4), t2=None):
    """two victims of type t (t2 for the second) far from the live pair, on the floor's side: diameters da, db"""
    return (f"create_atoms {t} single 0.01 0.01 0.012\ncreate_atoms {t2 or t} single 0.03 0.03 0.012\n"
            f"set atom {ids[0]} diameter {da} density 2500\nset atom {ids[1]} diameter {db} density 2500\n")


GROW = "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n"
GROWC = "run 1000\nset group lv2 diameter 0.012\nrun 3000\n"
V26 = vic(2, 0.012, 0.006)   # type 2 holds lv2's 3 mm radius twice and the 6 mm one at the set-up: lv2's growth leaves the set

# ------------------------------------------------------------ G: growth before pre no that the radii held per type hide
E("G01_victims_both_sizes_grow_pre_no", "type 2 holds 6 and 12 mm victims; lv2 6 -> 12 mm; run 3000 pre no (radii per type unchanged)", V26 + GROW, gap=g41, sep=0.008)
E("G02_victims_both_sizes_grow_control", "G01 without pre no", V26 + GROWC, gap=g41, sep=0.008)
E("G03_swap_sizes_pre_no", "victims 12, 12 mm; the first shrinks to 6 mm as lv2 grows to 12 mm; run 3000 pre no",
  vic(2, 0.012, 0.012) + "run 1000\nset atom 3 diameter 0.006\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G04_retype_grow_empty_type3_pre_no", "type 3 holds no atom; run 1000; set group lv2 type 3 diameter 0.012; run 3000 pre no (pair 1 3)",
  "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("G05_retype_grow_empty_type3_control", "G04 without pre no", "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008, pre=B3())
E("G06_retype_grow_type3_held_pre_no", "type 3 holds two 12 mm victims; lv2 retyped 3 and grown to 12 mm; run 3000 pre no",
  vic(3, 0.012, 0.012) + "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("G07_retype_only_empty_type3_pre_no", "type 3 empty; run 1000; set group lv2 type 3 (no growth); run 3000 pre no",
  "run 1000\nset group lv2 type 3\nrun 3000 pre no\n", gap=g11, pre=B3())
E("G08_grow_then_retype_pre_no", "type-2 victim of 6 mm stays; lv2 grown to 12 mm then retyped 3 (empty); run 3000 pre no",
  vic(2, 0.006, 0.006) + "run 1000\nset group lv2 diameter 0.012\nset group lv2 type 3\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("G09_type1_victims_grow_lv1_pre_no", "type 1 holds 4 and 8 mm victims; lv1 4 -> 8 mm; run 3000 pre no",
  vic(1, 0.008, 0.004) + "run 1000\nset group lv1 diameter 0.008\nrun 3000 pre no\n", gap=g31, sep=0.007)
E("G10_victims_set_atom_pre_no", "G01 by set atom 2 diameter 0.012", V26 + "run 1000\nset atom 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G11_victims_include_pre_no", "G01 with the set in an include", V26 + "run 1000\ninclude g.in\nrun 3000 pre no\n", gap=g41, sep=0.008, data={"g.in": "set group lv2 diameter 0.012\n"})
E("G12_victims_quoted_space_include_pre_no", 'G01 with the set in include "sub dir/g.in"', V26 + 'run 1000\ninclude "sub dir/g.in"\nrun 3000 pre no\n', gap=g41, sep=0.008,
  data={"sub dir/g.in": "set group lv2 diameter 0.012\n"})
E("G13_victims_loop_pre_no", "G01 with the set in a loop's second pass", V26 + 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "set group lv2 diameter 0.012"\nnext i\njump SELF l\nrun 3000 pre no\n',
  gap=g41, sep=0.008)
E("G14_victims_region_pre_no", "G01 by set region (a block around lv2 only)", V26 + "region rg block 0.021 0.04 0.015 0.025 0.04 0.06 units box\nrun 1000\nset region rg diameter 0.012\nrun 3000 pre no\n",
  gap=g41, sep=0.008)
E("G15_victims_atom_var_pre_no", "G01 by an atom-style variable of x (lv2 only)", V26 + "run 1000\nvariable dd atom 0.006+0.006*(x>0.021)*(z>0.04)*(type==2)\nset type 2 diameter v_dd\nrun 3000 pre no\n",
  gap=g41, sep=0.008)
E("G16_victims_every_pre_no", "victims; run 3000 pre no every 1000 set group lv2 diameter 0.012 (pair meets in part 3)",
  V26 + 'run 3000 pre no every 1000 "set group lv2 diameter 0.012"\n', gap=5.1e-3, sep=0.008)
E("G17_victims_run_pre_no_twice", "G01 with run 100 pre no between (stale since)", V26 + "run 1000\nset group lv2 diameter 0.012\nrun 100 pre no\nrun 3000 pre no\n", gap=g41 + 0.1e-3, sep=0.008)
E("G18_victims_run0_pre_yes_control", "G01 with run 0 (set up) between", V26 + "run 1000\nset group lv2 diameter 0.012\nrun 0\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G19_victims_step_diameter_pre_no", "G01 with set group lv2 diameter $(0.006+step*6e-6) (12 mm)", V26 + "run 1000\nset group lv2 diameter $(0.006+step*6e-6)\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G20_victims_density_too_pre_no", "G01 with set group lv2 diameter 0.012 density 2500", V26 + "run 1000\nset group lv2 diameter 0.012 density 2500\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G21_victims_hertz_pre_no", "G01 with hertz/material", V26 + GROW, gap=g41, sep=0.008, pre=BL(q.HM))
E("G22_victims_type13_unrelated_pre_no", "live pair 1 3; a type-2 victim grows 6 -> 12 mm (type 2 holds both); run 3000 pre no (1 3 printed: right?)",
  vic(2, 0.012, 0.006) + "run 1000\nset atom 4 diameter 0.012\nrun 3000 pre no\n", gap=g11, pre=B3(), pair=lv(g11, 1, 3))
extra("G22_victims_type13_unrelated_pre_no", PAIR="types 1 3")
E("G23_retype_grow_empty_in_include_pre_no", "G04 with the set in an include", "run 1000\ninclude g.in\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3(),
  data={"g.in": "set group lv2 type 3\nset group lv2 diameter 0.012\n"})
E("G24_retype_type_fraction_grow_pre_no", "type 3 empty; run 1000; set group lv2 type/fraction 3 1.0 7; set type 3 diameter 0.012; run 3000 pre no",
  "run 1000\nset group lv2 type/fraction 3 1.0 7\nset type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("G25_retype_grow_empty_every_pre_no", "type 3 empty; run 3000 pre no every 1000 set group lv2 type 3 diameter 0.012 (meets part 3)",
  'run 3000 pre no every 1000 "set group lv2 type 3 diameter 0.012"\n', gap=5.1e-3, sep=0.008, pre=B3())
E("G26_victims_shrink_other_grow_pre_no", "type 2: lv2 6, victims 12 and 6 mm; the 12 mm victim shrinks to 6 and lv2 grows to 9 mm (a new radius)",
  V26 + "run 1000\nset atom 3 diameter 0.006\nset group lv2 diameter 0.009\nrun 3000 pre no\n", gap=2.6e-3, sep=0.0065)
E("G27_victims_grow_skin_big_pre_no", "G01 with neighbor 0.01 bin from the start (the skin covers the growth)", V26 + GROW, gap=g41, sep=0.008, pre=BL() + "neighbor 0.01 bin\n")
E("G28_victims_grow_check_no_every1", "G01 with neigh_modify every 1 delay 0 check no (built every step)", V26 + GROW, gap=g41, sep=0.008, pre=BL() + "neigh_modify every 1 delay 0 check no\n")
E("G29_victims_create_pour_size_pre_no", "a type-2 victim of 6 mm; pour of one 12 mm type 2; lv2 grows to 12; pre no (round 29 Q08 with a victim of the old size)",
  vic(2, 0.006, 0.006) + q.POUR12 + GROW, gap=g41, sep=0.008)
E("G30_victims_labels_pre_no", "G01 with labels: set type big diameter (all type 2 grow: held radii change)",
  "labelmap atom 1 small 2 big\n" + V26 + "run 1000\nset type big diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
W("G31_wall_victims_grow_pre_no", "wall live (type 1 onto the floor); a type-2 victim grows; pre no (wall row: no list)",
  vic(2, 0.012, 0.006, ids=(2, 3)) + "run 1000\nset atom 3 diameter 0.012\nrun 3000 pre no\n", gap=g31)
E("G32_retype_grow_type2_to_1_pre_no", "lv1 and lv2 both type... lv2 retyped to type 1 (holding a 12 mm victim) and grown; pair 1 1",
  vic(1, 0.012, 0.012) + "run 1000\nset group lv2 type 1 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
extra("G32_retype_grow_type2_to_1_pre_no", PAIR="types 1 1")

# ------------------------------------------------------------ A: fix adapt without unfix
DD = "variable dd equal 0.012\n"
E("A01_adapt_const_from_start", "fix adapt lv2 diameter 0.012 (constant, reset no) from the first run (sizes set at set-up)",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g31, sep=0.008)
E("A02_adapt_after_run_pre_no", "run 1000; fix adapt lv2 diameter 0.012 (reset no); run 3000 pre no (no unfix)",
  DD + "run 1000\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("A03_adapt_after_run_control", "A02 without pre no", DD + "run 1000\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 3000\n", gap=g41, sep=0.008)
E("A04_adapt_run1_then_pre_no", "fix adapt 12 mm in run 1000 (reset no, kept); run 3000 pre no (sizes as left)",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nrun 3000 pre no\n", gap=g41 + 3e-3, sep=0.008)
E("A05_adapt_reset_yes_then_run", "fix adapt 12 mm in run 100 (reset yes: back to 6 mm at its end); no unfix; run 4000",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset yes\nrun 100\nrun 4000\n", gap=g31 + 0.1e-3, sep=0.008)
E("A06_adapt_growing_then_pre_no", "fix adapt growing 6 -> 12 mm over run 1000 (reset no); run 3000 pre no",
  "variable dd equal 0.006+0.006*step/1000*(step<=1000)+0.006*(step>1000)\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("A07_adapt_victims_pre_no", "victims 12, 6 mm; fix adapt lv2 to 12 after run 1000; run 3000 pre no", V26 + DD + "run 1000\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("A08_adapt_every_parts", "run 3000 every 1000 fix adapt lv2 12 mm (defined in part 1's commands)", DD + R3.format("fix ad lv2 adapt 1 atom diameter v_dd reset no"), gap=g41 + 1e-3, sep=0.008)
E("A09_adapt_nevery_big_pre_no", "fix adapt every 100000 steps (acts only at set-up) after run 1000; run 3000 pre no",
  DD + "run 1000\nfix ad lv2 adapt 100000 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g11)
E("A10_adapt_type3_retyped_pre_no", "fix adapt on group lv2 (retyped to empty type 3) 12 mm; run 3000 pre no (pair 1 3)",
  DD + "run 1000\nset group lv2 type 3\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
extra("A10_adapt_type3_retyped_pre_no", PAIR="types 1 3")
for n in ("G04_retype_grow_empty_type3_pre_no", "G05_retype_grow_empty_type3_control", "G06_retype_grow_type3_held_pre_no", "G07_retype_only_empty_type3_pre_no",
          "G08_grow_then_retype_pre_no", "G23_retype_grow_empty_in_include_pre_no", "G24_retype_type_fraction_grow_pre_no", "G25_retype_grow_empty_every_pre_no"):
    extra(n, PAIR="types 1 3")

# ------------------------------------------------------------ N: per-run reach
C1 = CU(0.001)
E("N01_cutoff_quoted_space_include", 'include "sub dir/c.in" (pair_coeff * * cutoff 0.001) after run 1000; neighbor 0.001 bin', 'run 1000\ninclude "sub dir/c.in"\nrun 3000\n', gap=g11,
  data={"sub dir/c.in": "pair_coeff * * " + HK + " cutoff 0.001\n"})
E("N02_cutoff_loop_pass2", "loop 2: run 500; pass 2 pair_coeff * * cutoff 0.001 (bin, skin 0.001)", 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "pair_coeff * * ' + HK + ' cutoff 0.001"\nnext i\njump SELF l\nrun 3000\n', gap=g11)
E("N03_global_cutoff_restyle_after_run", "run 1000; pair_style granular 0.001 + pair_coeff * * (a global cutoff from the second run)", "run 1000\npair_style granular 0.001\npair_coeff * * " + HK + "\nrun 3000\n", gap=g11)
E("N04_global_cutoff_big_skin_every", "pair_style granular 0.001 from the start; run 3000 every 1000 neighbor 0.01 bin (parts 2, 3 reach)", R3.format("neighbor 0.01 bin"), gap=2.1e-3,
  pre=r.head(2) + "pair_style granular 0.001\npair_coeff * * " + HK + "\n" + r.GRAV + r.FL() + r.TAILL)
E("N05_cutoff_every_nsq_part2", "cutoff 0.001; run 3000 every 1000 neighbor 0.001 nsq (f f f); pair meets in part 3", R3.format("neighbor 0.001 nsq"), gap=2.1e-3, pre=FFF(C1))
E("N06_change_box_every_fff", "p p f, cutoff 0.001, nsq; run 3000 every 1000 change_box all boundary f f f (pair in the middle, part 3)", "neighbor 0.001 nsq\n" + R3.format("change_box all boundary f f f"), gap=2.1e-3, pre=C1)
E("N07_change_box_every_ppf", "f f f, cutoff 0.001, nsq; run 3000 every 1000 change_box all boundary p p f (pair in the middle)", "neighbor 0.001 nsq\n" + R3.format("change_box all boundary p p f"), gap=2.1e-3, pre=FFF(C1))
E("N08_restart_fff_read_again", "f f f, nsq, cutoff 0.001; write_restart; clear; read_restart; nsq (round 29 N25 again)", q.RSTR.replace("boundary f f f\n", ""), pre=FFF(C1), gap=0.1e-3)
E("N09_restart_fff_boundary_ppf_before", "round 29 N11 again (boundary p p f before read_restart of an f f f box)", q.RSTR.replace("boundary f f f", "boundary p p f"), pre=FFF(C1), gap=0.1e-3)
E("N10_restart_fff_change_box_p", "f f f restart read, then change_box all boundary p p f; nsq; pair in the middle", q.RSTR.replace("boundary f f f\n", "").replace("read_restart a.rst\n", "read_restart a.rst\nchange_box all boundary p p f\n"),
  pre=FFF(C1), gap=0.1e-3)
E("N11_multi_collection_nsq", "neighbor 0.001 multi/old? (multi) with collection/type; nsq style", "neighbor 0.001 multi\nneigh_modify collection/type 2 1 2\ncomm_modify mode multi\nrun 3000\n", gap=0.1e-3)
E("N12_neighbor_include_if_pass", "cutoff 0.001; if 1 then include nb.in (neighbor 0.01 bin) after run 1000", 'run 1000\nif "1 > 0" then "include nb.in"\nrun 3000\n', gap=g11, pre=C1, data={"nb.in": "neighbor 0.01 bin\n"})
E("N13_neighbor_step_value", "cutoff 0.001, neighbor 0.01 bin; run 1000; neighbor $(step*1e-6) bin (0.001: the pair never found)", "neighbor 0.01 bin\nrun 1000\nneighbor $(step*1e-6) bin\nrun 3000\n", gap=g11, pre=C1)
E("N14_cutoff_step_value", "run 1000; pair_coeff * * ... cutoff $(step*1e-6) (0.001)", "run 1000\npair_coeff * * " + HK + " cutoff $(step*1e-6)\nrun 3000\n", gap=g11)
E("N15_change_box_shrink_x_every", "f p f, cutoff 0.001 nsq; run 3000 every 1000 change_box all x final 0 0.04 boundary p p f (periodic again)",
  "neighbor 0.001 nsq\n" + R3.format("change_box all x final 0 0.04 boundary p p f"), gap=2.1e-3, pre=C1.replace("boundary p p f", "boundary f p f"))
E("N16_cutoff_12_only_every", "pair_coeff 1 2 cutoff 0.001 in every parts; neighbor 0.001 bin", R3.format("pair_coeff 1 2 " + HK + " cutoff 0.001"), gap=2.1e-3)
E("N17_nsq_then_bin_include_quoted", 'cutoff 0.001 f f f nsq; run 1000; include "n b.in" (neighbor 0.001 bin)', 'neighbor 0.001 nsq\nrun 1000\ninclude "n b.in"\nrun 3000\n', gap=g11, pre=FFF(C1),
  data={"n b.in": "neighbor 0.001 bin\n"})
E("N18_read_data_box_fff_then_p", "read_data (f f f by boundary), pair in the middle; change_box all boundary p p f; nsq cutoff 0.001",
  q.RDD("boundary f f f\n").replace("neighbor 0.001 nsq\n", "change_box all boundary p p f\nneighbor 0.001 nsq\n"), pre="\n", pair="", gap=0.1e-3, data={"box.data": q.RDB(0.01795, 0.02305)})

# ------------------------------------------------------------ V: step-dependent substitutions in watched commands
E("V01_step_diameter_control", "run 1000; set group lv2 diameter $(0.006+step*6e-6) (12 mm); run 3000", "run 1000\nset group lv2 diameter $(0.006+step*6e-6)\nrun 3000\n", gap=g41, sep=0.008)
E("V02_every_density_step", "run 3000 every 1000 set group lv2 density $(2500+step) (part 3 5500)", R3.format("set group lv2 density $(2500+step)"), gap=2.1e-3)
E("V03_group_name_step", "run 1000; group g$(step) id 2; set group g1000 diameter 0.012; run 3000", "run 1000\ngroup g$(step) id 2\nset group g1000 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008)
E("V04_region_name_step_type", "run 1000; region r$(step) block around lv1; set region r1000 type 3; 1 3 kn 8000 (pair 2 3)",
  P8("2", "3") + "\nrun 1000\nregion r$(step) block 0.01 0.019 0.015 0.025 0.04 0.06 units box\nset region r1000 type 3\nrun 3000\n", gap=g11, pre=B3())
extra("V04_region_name_step_type", PAIR="types 2 3")
W("V05_wall_fix_id_step", "wall live: run 1000; unfix floor; fix fl$(step) wall kn 8000; run 3000", "run 1000\nunfix floor\nfix fl$(step) all wall/gran granular " + hk(8000) + " zplane 0 NULL\nrun 3000\n", gap=g11 + 1e-3)
E("V06_every_jump_label_step", "every variable s; jump SELF L${s} (L3000 kn 5000)", R3.format("variable s equal $(step)") + "jump SELF L${s}\nlabel L1000\n" + P8() + "\njump SELF e\nlabel L3000\n" + P5() + "\nlabel e\nrun 1000\n", gap=g31)
E("V07_every_if_time", "run 3000 every 1000 if time > 0.0015 then kn 5000 (after parts 2, 3)", 'run 3000 every 1000 \'if "$(time) > 0.0015" then "' + P5() + '"\'\n', gap=2.1e-3)
E("V08_every_if_time_part2", "V07 with the pair meeting in part 2 (after part 1: time 0.001 no change)", 'run 3000 every 1000 \'if "$(time) > 0.0015" then "' + P5() + '"\'\n', gap=g11, live="part 2")
E("V09_lazy_step_every_coeff", "variable s equal step (lazy); run 3000 every 1000 pair_coeff 1 2 hooke $(v_s+2000)", "variable s equal step\n" + R3.format("pair_coeff 1 2 hooke $(v_s+2000) 3000 " + K), gap=2.1e-3)
E("V10_timestep_step_value", "run 1000; timestep $(step*2e-8) (2e-5); run 300", "run 1000\ntimestep $(step*2e-8)\nrun 300\n", gap=g11)
E("V11_type_fraction_seed_step", "run 1000; set group lv2 type/fraction 3 1.0 $(step+1); 2 3 ... pair 1 3 kn 5000", P5("1", "3") + "\nrun 1000\nset group lv2 type/fraction 3 1.0 $(step+1)\nrun 3000\n", gap=g11, pre=B3())
extra("V11_type_fraction_seed_step", PAIR="types 1 3")
E("V12_delete_group_step", "group g1000 = lv1; run 1000; delete_atoms group g$(step) (no 1 2 pair)", "group g1000 id 1\nrun 1000\ndelete_atoms group g$(step)\nrun 3000\n", gap=g11)
E("V13_every_exclude_step_several", "run 3000 every 1000 neigh_modify exclude type 1 $(1+step/3000) (after part 1 exclude 1 1, after part 2 exclude 1 2: passes)",
  R3.format("neigh_modify exclude type 1 $(1+floor(step/2000))"), gap=2.1e-3)
E("V14_every_group_step_set_type", "run 3000 every 1000 group g$(step) id 2 + set group g$(step) type 3 after part 2 only if step==2000",
  'run 3000 every 1000 "group g$(step) id 2" \'if "$(step) == 2000" then "set group g2000 type 3"\'\n' + "run 10\n", gap=2.1e-3 + 1e-5, pre=B3() + "pair_coeff 1 3 " + hk(5000) + "\n")
extra("V14_every_group_step_set_type", PAIR="types 1 3")
E("V15_budget_out_step_if", "--run-budget 1: an atomless run 3000000; if $(step) > 2999999 kn 5000 else 8000; the pair made after",
  "run 3000000\n" + q.IFS("$(step) > 2999999") + pairA(g11, ia=1, ib=2) + "run 3000\n", gap=g11, pair="")
extra("V15_budget_out_step_if", ARGS="--run-budget 1")
E("V16_budget_enough_step_if", "V15 at the default budget (60 s)", "run 3000000\n" + q.IFS("$(step) > 2999999") + pairA(g11, ia=1, ib=2) + "run 3000\n", gap=g11, pair="")
E("V17_over_1e7_steps_step_if", "an atomless run 20000000 (over the pass's 1e7 steps); if $(step) ... kn", "run 20000000\n" + q.IFS("$(step) > 19999999") + pairA(g11, ia=1, ib=2) + "run 3000\n", gap=g11, pair="")
E("V18_every_include_name_time", "run 3000 every 1000 variable t equal $(time*1e6:%.0f); include k${t}.in", R3.format("variable t equal $(time*1e6:%.0f)") + "include k${t}.in\nrun 1000\n", gap=g31, data=q.KF)
E("V19_velocity_step_group_every", "every velocity g$(step) set 0 0 0 where only g1000 exists (lv1 stops in part 2: LAMMPS errors? group missing)",
  "group g1000 id 1\n" + R3.format("velocity g$(step) set 0 0 0 units box"), gap=g31)
E("V20_set_atom_id_every", "run 3000 every 1000 set atom $(step/1000+1) type 3 (after part 1 lv2 -> type 3; 1 3 kn 5000)",
  P5("1", "3") + "\n" + R3.format("set atom $(step/1000+1) type 3"), gap=2.1e-3, pre=B3())
extra("V20_set_atom_id_every", PAIR="types 1 3")

# ------------------------------------------------------------ R: set type/fraction, type/ratio, type/subset after runs
P13 = P5("1", "3") + "\n"
E("R01_subset_pre_no", "1 3 kn 5000; run 1000; set group lv2 type/subset 3 1 7; run 3000 pre no (retype: lists by atom)", P13 + "run 1000\nset group lv2 type/subset 3 1 7\nrun 3000 pre no\n", gap=g11, pre=B3())
E("R02_fraction_every", "1 3 kn 5000; run 3000 every 1000 set group lv2 type/fraction 3 1.0 $(step+3)", P13 + R3.format("set group lv2 type/fraction 3 1.0 $(step+3)"), gap=2.1e-3, pre=B3())
E("R03_ratio_loop_seed", "1 3 kn 5000; loop 2: run 500; set group lv2 type/ratio 3 1.0 ${i}1", P13 + "variable i loop 2\nlabel l\nrun 500\nset group lv2 type/ratio 3 1.0 ${i}1\nnext i\njump SELF l\nrun 3000\n", gap=g11, pre=B3())
E("R04_subset_include_quoted", '1 3 kn 5000; run 1000; include "sub dir/t.in" (type/subset 3 1 5)', P13 + 'run 1000\ninclude "sub dir/t.in"\nrun 3000\n', gap=g11, pre=B3(),
  data={"sub dir/t.in": "set group lv2 type/subset 3 1 5\n"})
E("R05_fraction_half_two", "victims of type 2; 1 3 kn 5000; run 1000; set type 2 type/fraction 3 0.5 11 (which ones: the engine's draw)", vic(2, 0.006, 0.006) + P13 + "run 1000\nset type 2 type/fraction 3 0.5 11\nrun 3000\n", gap=g11, pre=B3())
E("R06_ratio_pre_no_exclude", "neigh_modify exclude type 1 3; run 1000; set group lv2 type/ratio 3 1.0 9; run 3000 pre no (lists built with types)",
  "neigh_modify exclude type 1 3\nrun 1000\nset group lv2 type/ratio 3 1.0 9\nrun 3000 pre no\n", gap=g11, pre=B3())
E("R07_fraction_exclude_control", "R06 without pre no (excluded: passes)", "neigh_modify exclude type 1 3\nrun 1000\nset group lv2 type/ratio 3 1.0 9\nrun 3000\n", gap=g11, pre=B3())
E("R08_subset_budget0", "R01 without pre no, --run-budget 0", P13 + "run 1000\nset group lv2 type/subset 3 1 7\nrun 3000\n", gap=g11, pre=B3())
extra("R08_subset_budget0", ARGS="--run-budget 0")
for n in ("R01_subset_pre_no", "R02_fraction_every", "R03_ratio_loop_seed", "R04_subset_include_quoted", "R05_fraction_half_two", "R06_ratio_pre_no_exclude",
          "R07_fraction_exclude_control", "R08_subset_budget0"):
    extra(n, PAIR="types 1 3")

# ------------------------------------------------------------ I: quoted include names
KIN5, KIN8 = P5() + "\n", P8() + "\n"
E("I01_nested_relative_cwd", 'include "sub dir/a.in" which includes k.in (LAMMPS opens k.in from the run folder: kn 5000; sub dir/k.in kn 8000)', 'include "sub dir/a.in"\nrun 3000\n', gap=0.1e-3,
  data={"sub dir/a.in": "include k.in\n", "k.in": KIN5, "sub dir/k.in": KIN8})
E("I02_nested_quoted_both", 'include "a a.in" which includes "b b.in"', 'include "a a.in"\nrun 3000\n', gap=0.1e-3, data={"a a.in": 'include "b b.in"\n', "b b.in": KIN5})
E("I03_triple_quoted_space", 'include """k k.in"""', 'include """k k.in"""\nrun 3000\n', gap=0.1e-3, data={"k k.in": KIN5})
E("I04_single_quoted_var", "variable f string k.in; include '${f}'", "variable f string k.in\ninclude '${f}'\nrun 3000\n", gap=0.1e-3, data={"k.in": KIN5})
E("I05_double_space_name", 'include "k  k.in" (two spaces; "k k.in" kn 8000 beside it)', 'include "k  k.in"\nrun 3000\n', gap=0.1e-3, data={"k  k.in": KIN5, "k k.in": KIN8})
E("I06_leading_space_name", 'include " k.in" (k.in kn 8000, " k.in" kn 5000)', 'include " k.in"\nrun 3000\n', gap=0.1e-3, data={" k.in": KIN5, "k.in": KIN8})
E("I07_trailing_space_name", 'include "k.in " (k.in kn 8000, "k.in " kn 5000)', 'include "k.in "\nrun 3000\n', gap=0.1e-3, data={"k.in ": KIN5, "k.in": KIN8})
E("I08_two_vars_space", 'variable d string "s d"; variable f string k.in; include "${d}/${f}"', 'variable d string "s d"\nvariable f string k.in\ninclude "${d}/${f}"\nrun 3000\n', gap=0.1e-3,
  data={"s d/k.in": KIN5})
E("I09_three_deep_run_inside", 'include "a a.in" -> include "b/${f}" -> pair_coeff and run', 'variable f string "c c.in"\ninclude "a a.in"\n', gap=0.1e-3,
  data={"a a.in": 'include "b/${f}"\n', "b/c c.in": KIN5 + "run 3000\n"})
E("I10_every_include_space", "run 3000 every 1000 include \"sub dir/k.in\" (design: refused)", "run 3000 every 1000 'include \"sub dir/k.in\"'\n", gap=2.1e-3, data={"sub dir/k.in": KIN5})
E("I11_jump_space_file_label", 'jump "sub dir/j.in" go (a label inside it)', 'jump "sub dir/j.in" go\n', gap=0.1e-3, data={"sub dir/j.in": P8() + "\nlabel go\n" + P5() + "\nrun 3000\n"})
E("I12_include_step_format_quoted", 'run 3000; include "k $(step/1000:%.0f).in" (k 3.in kn 5000)', 'run 3000\ninclude "k $(step/1000:%.0f).in"\nrun 1000\n', gap=g31,
  data={"k 3.in": KIN5, "k 0.in": KIN8})
E("I13_loop_index_space_names", 'variable f index "k 1.in" "k 2.in"; label l; include "${f}"; next f; jump SELF l (last k 2.in kn 5000)',
  'variable f index "k 1.in" "k 2.in"\nlabel l\ninclude "${f}"\nnext f\njump SELF l\nrun 3000\n', gap=0.1e-3, data={"k 1.in": KIN8, "k 2.in": KIN5})
E("I14_jump_self_inside_include", "include a.in, which jumps SELF to its own label lab (main file has a label lab too)", "include a.in\nrun 3000\njump SELF end\nlabel lab\n" + P8() + "\nlabel end\n",
  gap=0.1e-3, data={"a.in": "jump SELF lab\n" + P8() + "\nlabel lab\n" + P5() + "\n"})
E("I15_comment_quoted_after", 'include "k.in" # include "x x.in"', 'include "k.in" # include "x x.in"\nrun 3000\n', gap=0.1e-3, data={"k.in": KIN5, "x x.in": KIN8})
E("I16_var_single_quoted_def", "variable f string 'sub dir/k.in'; include \"${f}\"", "variable f string 'sub dir/k.in'\ninclude \"${f}\"\nrun 3000\n", gap=0.1e-3, data={"sub dir/k.in": KIN5})
E("I17_unquoted_var_with_space", 'variable f string "sub dir/k.in"; include ${f} (two words: LAMMPS stops?)', 'variable f string "sub dir/k.in"\ninclude ${f}\nrun 3000\n', gap=0.1e-3, data={"sub dir/k.in": KIN5})
E("I18_dollar_name_no_var", 'include "k$x.in" (a one-letter variable x = 1: k1.in)', 'variable x string 1\ninclude "k$x.in"\nrun 3000\n', gap=0.1e-3, data={"k1.in": KIN5, "k$x.in": KIN8})
E("I19_growth_victims_quoted_var", 'victims; run 1000; include "${g}" (g = "g g.in": set lv2 diameter 0.012); run 3000 pre no', V26 + 'variable g string "g g.in"\nrun 1000\ninclude "${g}"\nrun 3000 pre no\n',
  gap=g41, sep=0.008, data={"g g.in": "set group lv2 diameter 0.012\n"})
E("I20_include_inside_include_after_run", 'run 1000; include "a a.in" holding run 1000 and include "k k.in"; run 2000', 'run 1000\ninclude "a a.in"\nrun 2000\n', gap=2.1e-3,
  data={"a a.in": 'run 1000\ninclude "k k.in"\n', "k k.in": KIN5})
E("I21_if_single_include_space", "if 1 then 'include \"k k.in\"'", "if \"1 > 0\" then 'include \"k k.in\"'\nrun 3000\n", gap=0.1e-3, data={"k k.in": KIN5})
E("I22_jump_quoted_var_space_label", 'variable f string "j j.in"; jump "${f}" go', 'variable f string "j j.in"\njump "${f}" go\n', gap=0.1e-3, data={"j j.in": P8() + "\nlabel go\n" + P5() + "\nrun 3000\n"})
E("I23_include_then_clear_same_name", 'include "k k.in"; run 100; clear; base; include "k k.in" again (file unchanged)', 'include "k k.in"\nrun 100\nclear\n' + BL() + lv(0.1e-3) + 'include "k k.in"\nrun 3000\n',
  gap=0.1e-3, data={"k k.in": KIN5}, live="the run after clear")

# ------------------------------------------------------------ C: the named classes, fresh cases
E("C01_range_23_12", "3 types; pair_coeff 2*3 1*2 kn 5000 (LAMMPS sets 2 2 only: 1 2 stays 2000)", "pair_coeff 2*3 1*2 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3, pre=B3())
E("C02_range_star_2", "pair_coeff * 2 kn 5000 (1 2 and 2 2)", "pair_coeff * 2 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3, pre=B3())
E("C03_range_2_star", "pair_coeff 2 * kn 5000 (2 2, 2 3: 1 2 stays 2000)", "pair_coeff 2 * " + hk(5000) + "\nrun 3000\n", gap=0.1e-3, pre=B3())
E("C04_range_1star1_2star2", "pair_coeff 1*1 2*2 kn 5000", "pair_coeff 1*1 2*2 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C05_range_2star2_1star1", "pair_coeff 2*2 1*1 kn 5000 (a range: not swapped; LAMMPS sets nothing: error?)", "pair_coeff 2*2 1*1 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C06_labels_reversed", "labels small big; pair_coeff big small kn 5000 (swapped?)", "labelmap atom 1 small 2 big\npair_coeff big small " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C07_range_star2_2star", "3 types; pair_coeff *2 2* kn 5000 (1 2, 1 3, 2 2, 2 3)", "pair_coeff *2 2* " + hk(5000) + "\nrun 3000\n", gap=0.1e-3, pre=B3())
E("C08_range_3star_star1", "pair_coeff 2* *1 kn 5000 (none: LAMMPS errors?)", "pair_coeff 2* *1 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3, pre=B3())
E("C09_format_f1", "pair_coeff 1 2 hooke $(2500*2:%.1f)", "pair_coeff 1 2 hooke $(2500*2:%.1f) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C10_if_format_03", 'if "$(0.1+0.2:%.1f) == 0.3" then kn 5000 else kn 8000', q.IFS("$(0.1+0.2:%.1f) == 0.3") + "run 3000\n", gap=0.1e-3)
E("C11_if_immediate_03", 'if "$(0.1+0.2) == 0.3" (immediate %.15g) then kn 5000 else 8000', q.IFS("$(0.1+0.2) == 0.3") + "run 3000\n", gap=0.1e-3)
E("C12_if_equal_var_03", 'variable a equal 0.1+0.2; if "${a} == 0.3"', "variable a equal 0.1+0.2\n" + q.IFS("${a} == 0.3") + "run 3000\n", gap=0.1e-3)
E("C13_if_v_a_03", 'variable a equal 0.1+0.2; if "v_a == 0.3" (evaluated in double: false)', "variable a equal 0.1+0.2\n" + q.IFS("v_a == 0.3") + "run 3000\n", gap=0.1e-3)
E("C14_name_2_not_20", "variable n equal 2.0; include k${n}.in (k2.in kn 5000, k2.0.in kn 8000)", "variable n equal 2.0\ninclude k${n}.in\nrun 3000\n", gap=0.1e-3, data={"k2.in": KIN5, "k2.0.in": KIN8})
E("C15_round_half", "pair_coeff 1 2 hooke $(round(2.5)*1000+2000) (C round: 5000)", "pair_coeff 1 2 hooke $(round(2.5)*1000+2000) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C16_modulo_negative", "pair_coeff 1 2 hooke $(5000+(-7%5)*500) (fmod: 4000)", "pair_coeff 1 2 hooke $(5000+(-7%5)*500) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C17_set_density_then_diameter", "set group lv2 density 2500 diameter 0.012 (mass of the 6 mm)", "set group lv2 density 2500 diameter 0.012\nrun 3000\n", gap=g31, sep=0.008)
E("C18_set_diameter_then_density", "set group lv2 diameter 0.012 density 2500 (mass of the 12 mm)", "set group lv2 diameter 0.012 density 2500\nrun 3000\n", gap=g31, sep=0.008)
E("C19_set_mass_then_diameter", "set group lv2 mass 1e-4 diameter 0.012", "set group lv2 mass 1e-4 diameter 0.012\nrun 3000\n", gap=g31, sep=0.008)
E("C20_format_width_coeff", "pair_coeff 1 2 hooke $(5000:%10.0f) (leading spaces)", "pair_coeff 1 2 hooke $(5000:%10.0f) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C21_format_e_coeff", "pair_coeff 1 2 hooke $(5000:%.3e)", "pair_coeff 1 2 hooke $(5000:%.3e) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C22_loop_name_var_formula", "variable i loop 2; variable j equal ${i}*1.0; include k${j}.in in the loop (k1.in, k2.in)", "variable i loop 2\nlabel l\nvariable j equal ${i}*1.0\ninclude k${j}.in\nnext i\njump SELF l\nrun 3000\n",
  gap=0.1e-3, data={"k1.in": KIN8, "k2.in": KIN5})
E("C24_pour_poly_type2", "pour type 2 diam poly 2 0.004 0.5 0.012 0.5; live pair 1 2 (6 mm) meets after", "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 3 2 4767 region ins diam poly 2 0.004 0.5 0.012 0.5 dens 2500 2500\nrun 3000\n", gap=g11)
E("C25_ternary_round_coeff", "pair_coeff 1 2 hooke $(ternary(round(0.5)==1,5000,8000)) (C round(0.5) = 1)", "pair_coeff 1 2 hooke $(ternary(round(0.5)==1,5000,8000)) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C26_if_format_g_equal", 'if "$(1/3:%.3g) == 0.333" kn 5000 else 8000', q.IFS("$(1/3:%.3g) == 0.333") + "run 3000\n", gap=0.1e-3)
E("C27_labels_range_star", "labels; pair_coeff small * kn 5000 (1 1, 1 2)", "labelmap atom 1 small 2 big\npair_coeff small * " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C28_timestep_note_every", "run 3000 every 1000 timestep $(dt*2) (2e-6, 4e-6, 8e-6 in part 3? after 2: 4e-6)", R3.format("timestep $(dt*2)"), gap=3.5e-3)

# ------------------------------------------------------------ L: LIGGGHTS
Ld("L01_retype_grow_type3_pre_no", "LIGGGHTS type 3 (wall type, no atom); run 1000; set group lv2 type 3 diameter 0.012; run 3000 pre no (pair 1 3)",
   "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pair="types 1 3")
Ld("L02_retype_grow_type3_control", "L01 without pre no", "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008, pair="types 1 3")
LV = "create_atoms 2 single 0.03 0.03 0.02 units box\ncreate_atoms 2 single -0.03 -0.03 0.02 units box\nset atom 3 diameter 0.012 density 2500\nset atom 4 diameter 0.006 density 2500\n"
Ld("L03_victims_grow_pre_no", "LIGGGHTS type-2 victims of 12 and 6 mm; lv2 grows to 12; run 3000 pre no", LV + GROW, gap=g41, sep=0.008)
Ld("L04_victims_grow_control", "L03 without pre no", LV + GROWC, gap=g41, sep=0.008)
Ld("L05_include_nested_space", 'LIGGGHTS include "a.in" holding include "sub dir/k.in" (e 1 2 0.9)', "include a.in\nrun 3000\n", gap=0.1e-3,
   data={"a.in": 'include "sub dir/k.in"\n', "sub dir/k.in": E3x(0.9) + "\n"})
Ld("L06_include_single_quoted_space", "LIGGGHTS include 'sub dir/k.in'", "include 'sub dir/k.in'\nrun 3000\n", gap=0.1e-3, data={"sub dir/k.in": E3x(0.9) + "\n"})
CV = "fix m5 all property/global characteristicVelocity scalar 1.0\n"
Ld("L07_limitforce_restyle", "LIGGGHTS hooke limitForce on in run 1000, restyle plain hooke before the meeting run", "run 1000\npair_style gran model hooke tangential history\npair_coeff * *\nrun 3000\n", gap=g11,
   head_=m.lhead() + m.MAT3 + m.E3 + CV + "pair_style gran model hooke tangential history limitForce on\npair_coeff * *\n" + m.WALL3)
Ld("L08_limitforce_on_after", "LIGGGHTS plain hooke in run 1000, restyle with limitForce on before the meeting run", "run 1000\npair_style gran model hooke tangential history limitForce on\npair_coeff * *\nrun 3000\n", gap=g11,
   head_=m.lhead() + m.MAT3 + m.E3 + CV + "pair_style gran model hooke tangential history\npair_coeff * *\n" + m.WALL3)
Ld("L09_grow_type1_victim_hidden_pre_no", "LIGGGHTS type-1 victims of 8 and 4 mm; lv1 grows 4 -> 8 mm; run 3000 pre no",
   "create_atoms 1 single 0.03 0.03 0.02 units box\ncreate_atoms 1 single -0.03 -0.03 0.02 units box\nset atom 3 diameter 0.008 density 2500\nset atom 4 diameter 0.004 density 2500\n"
   + "run 1000\nset group lv1 diameter 0.008\nrun 3000 pre no\n", gap=g31, sep=0.007)
Ld("L10_if_format_e", 'LIGGGHTS variable a equal 0.1+0.2; if "${a} == 0.3" then e 1 2 0.9 else 0.2', "variable a equal 0.1+0.2\nif \"${a} == 0.3\" then \"" + E3x(0.9) + "\" else \"" + E3x(0.2) + "\"\nrun 3000\n", gap=0.1e-3)
Ld("L11_type_subset_pre_no", "LIGGGHTS run 1000; set group lv2 type/subset 3 1 7? (retype lv2 to 3: e 1 3 0.7); run 3000 pre no", "run 1000\nset group lv2 type 3\nrun 3000 pre no\n", gap=g11, pair="types 1 3")

# ------------------------------------------------------------ wave 2: around the first wave's wrong rows (hidden growth, retype into an empty type, fix adapt at set-up)
E("G33_victim_deleted_then_grow_pre_no", "type 2 holds lv2 6, a 12 mm and a 6 mm victim; the 12 mm one deleted after run 1000; lv2 grows to 12; run 3000 pre no",
  V26 + "group big id 3\nrun 1000\ndelete_atoms group big\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("G34_victims_far_gap_pre_no", "G01 with the pair 3 mm apart after the growth (the lists' next build finds it in time?)", V26 + GROW.replace("run 3000 pre no", "run 6000 pre no"), gap=7.1e-3, sep=0.008)
E("G35_retype_grow_type3_small_held_pre_no", "type 3 holds a 4 mm victim at set-up; lv2 retyped 3 and grown to 12 mm (a new radius: seen)",
  vic(3, 0.004, 0.004) + "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("G36_retype_grow_empty_wall_row", "wall live (type 1 falls); type 3 empty; run 1000; a type-2 victim retyped 3 and grown; pre no (wall row right)",
  "create_atoms 2 single 0.01 0.01 0.012\nset atom 2 diameter 0.006 density 2500\nrun 1000\nset atom 2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g31, pre=B3(), pair=q.r.lvw(g31))
LIVE["G36_retype_grow_empty_wall_row"] = "last run\nWALL"
E("G37_retype_grow_empty_type3_hertz_pre_no", "G04 with hertz/material", "run 1000\nset group lv2 type 3 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL(q.HM, nt=3))
E("G38_retype_grow_empty_type4_coeff_pre_no", "4 types; 1 4 kn 5000 set before run 1; lv2 retyped 4 and grown to 12 mm; pre no", "pair_coeff 1 4 " + hk(5000) + "\nrun 1000\nset group lv2 type 4 diameter 0.012\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=BL(nt=4))
E("G39_victims_grow_lv2_small_step_pre_no", "type 2 holds 6.6 and 6 mm victims; lv2 grows 6 -> 6.6 mm (a 0.3 mm growth, inside the skin)",
  vic(2, 0.0066, 0.006) + "run 1000\nset group lv2 diameter 0.0066\nrun 3000 pre no\n", gap=1.4e-3, sep=0.0053)
for n in ("G35_retype_grow_type3_small_held_pre_no", "G37_retype_grow_empty_type3_hertz_pre_no"):
    extra(n, PAIR="types 1 3")
extra("G38_retype_grow_empty_type4_coeff_pre_no", PAIR="types 1 4")
E("A11_adapt_const_far", "A01 with the pair 2.1 mm apart after the growth (found at a later build, before touching)", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 5000\n", gap=5.1e-3, sep=0.008)
E("A12_adapt_const_run0_first", "A01 with run 0 first (the set-up sizes the spheres; the next run's lists see 12 mm)", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 0\nrun 4000\n", gap=g31, sep=0.008)
E("A13_adapt_growing_no_pre_no", "fix adapt growing 6 -> 12 mm over steps 0-1000 (then held); run 4000 (no pre no)",
  "variable dd equal 0.006+0.006*step/1000*(step<=1000)+0.006*(step>1000)\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g41, sep=0.008)
E("A14_adapt_lv1_type1_const", "fix adapt lv1 (type 1) diameter 0.008 from the start (reset no)", "variable dd equal 0.008\nfix ad lv1 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=2.1e-3, sep=0.007)
E("A15_adapt_const_big_skin", "A01 with neighbor 0.01 bin (the skin covers the growth)", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g31, sep=0.008, pre=BL() + "neighbor 0.01 bin\n")
E("A16_adapt_shrink_const", "fix adapt lv2 diameter 0.004 from the start (a shrink: lists hold it)", "variable dd equal 0.004\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=0.1e-3, sep=0.004)
E("A17_adapt_const_same", "fix adapt lv2 diameter 0.006 (its own size) from the start", "variable dd equal 0.006\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=0.1e-3)
E("A18_adapt_include_quoted", 'A01 with the fix adapt in include "a d.in"', DD + 'include "a d.in"\nrun 4000\n', gap=g31, sep=0.008, data={"a d.in": "fix ad lv2 adapt 1 atom diameter v_dd reset no\n"})

# ------------------------------------------------------------ wave 3: quoted names the audit did not follow (I05 two spaces, I21 in an if), exclusions changed under pre no, the time step
E("I24_if_single_include_subdir_space", "if 1 then 'include \"sub dir/k.in\"'", "if \"1 > 0\" then 'include \"sub dir/k.in\"'\nrun 3000\n", gap=0.1e-3, data={"sub dir/k.in": KIN5})
E("I25_if_double_include_sq_space", "if 1 then \"include 'k k.in'\"", "if \"1 > 0\" then \"include 'k k.in'\"\nrun 3000\n", gap=0.1e-3, data={"k k.in": KIN5})
E("I26_three_spaces_name", 'include "k   k.in" (three spaces)', 'include "k   k.in"\nrun 3000\n', gap=0.1e-3, data={"k   k.in": KIN5, "k k.in": KIN8})
E("I27_jump_two_spaces", 'jump "j  j.in" (two spaces; the deck goes on there)', 'jump "j  j.in"\n', gap=0.1e-3, data={"j  j.in": KIN5 + "run 3000\n"})
E("I28_if_single_include_nospace", "if 1 then 'include \"k.in\"' (control)", "if \"1 > 0\" then 'include \"k.in\"'\nrun 3000\n", gap=0.1e-3, data={"k.in": KIN5})
E("I29_if_single_include_var_space", "variable f string \"k k.in\"; if 1 then 'include \"${f}\"'", "variable f string \"k k.in\"\nif \"1 > 0\" then 'include \"${f}\"'\nrun 3000\n", gap=0.1e-3, data={"k k.in": KIN5})
E("I30_quote_char_in_name", "include \"k'k.in\" (a single quote inside)", "include \"k'k.in\"\nrun 3000\n", gap=0.1e-3, data={"k'k.in": KIN5})
E("I31_if_after_run_include_space", "run 1000; if 1 then 'include \"k k.in\"'; run 3000", "run 1000\nif \"1 > 0\" then 'include \"k k.in\"'\nrun 3000\n", gap=g11, data={"k k.in": KIN5})
E("I32_if_include_space_in_include", "include a.in holding if 1 then 'include \"k k.in\"'", "include a.in\nrun 3000\n", gap=0.1e-3, data={"a.in": "if \"1 > 0\" then 'include \"k k.in\"'\n", "k k.in": KIN5})
E("I33_if_triple_include_space", 'if 1 then """include "k k.in" """ (triple quotes)', 'if "1 > 0" then """include "k k.in" """\nrun 3000\n', gap=0.1e-3, data={"k k.in": KIN5})
E("I34_two_spaces_subdir", 'include "sub  dir/k.in" (two spaces in the folder name)', 'include "sub  dir/k.in"\nrun 3000\n', gap=0.1e-3, data={"sub  dir/k.in": KIN5, "sub dir/k.in": KIN8})
E("I35_if_include_space_growth_pre_no", "victims; run 1000; if 1 then 'include \"g g.in\"' (lv2 to 12 mm); run 3000 pre no", V26 + "run 1000\nif \"1 > 0\" then 'include \"g g.in\"'\nrun 3000 pre no\n",
  gap=g41, sep=0.008, data={"g g.in": "set group lv2 diameter 0.012\n"})
Ld("L12_if_include_space", "LIGGGHTS if 1 then 'include \"k k.in\"' (e 1 2 0.9)", "if \"1 > 0\" then 'include \"k k.in\"'\nrun 3000\n", gap=0.1e-3, data={"k k.in": E3x(0.9) + "\n"})
Ld("L13_two_spaces_name", 'LIGGGHTS include "k  k.in" (e 1 2 0.9)', 'include "k  k.in"\nrun 3000\n', gap=0.1e-3, data={"k  k.in": E3x(0.9) + "\n", "k k.in": E3x(0.2) + "\n"})
E("R09_exclude_12_retype_pre_no", "neigh_modify exclude type 1 2; run 1000; set group lv2 type 3; run 3000 pre no (the lists left lv2 out)", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type 3\nrun 3000 pre no\n", gap=g11, pre=B3())
E("R10_exclude_12_retype_control", "R09 without pre no", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type 3\nrun 3000\n", gap=g11, pre=B3())
E("R11_exclude_group_cleared_pre_no", "group ex id 2; neigh_modify exclude group lv1 ex; run 1000; group ex clear; run 3000 pre no", "group ex id 2\nneigh_modify exclude group lv1 ex\nrun 1000\ngroup ex clear\nrun 3000 pre no\n", gap=g11)
E("R12_exclude_group_filled_pre_no", "group ex empty; neigh_modify exclude group lv1 ex; run 1000; group ex id 2; run 3000 pre no", "group ex empty\nneigh_modify exclude group lv1 ex\nrun 1000\ngroup ex id 2\nrun 3000 pre no\n", gap=g11)
E("R13_exclude_group_cleared_control", "R11 without pre no", "group ex id 2\nneigh_modify exclude group lv1 ex\nrun 1000\ngroup ex clear\nrun 3000\n", gap=g11)
for n in ("R09_exclude_12_retype_pre_no", "R10_exclude_12_retype_control"):
    extra(n, PAIR="types 1 3")
E("C29_dt_4e6_plain", "timestep 4e-6 (147 steps per contact, above the note's 50)", "timestep 4e-6\nrun 1000\n", gap=0.1e-3)
E("C30_dt_8e6_plain", "timestep 8e-6 (73 steps per contact)", "timestep 8e-6\nrun 500\n", gap=0.1e-3)
E("C31_dt_11e6_plain", "timestep 1.1e-5 (53 steps per contact)", "timestep 1.1e-5\nrun 400\n", gap=0.1e-3)
E("C32_dt_2e5_plain", "timestep 2e-5 (29 steps: the note)", "timestep 2e-5\nrun 200\n", gap=0.1e-3)

# ------------------------------------------------------------ wave 4: what the every refusals key on; fix adapt's keywords; LIGGGHTS adapt; pair_coeff ranges without the swap; %.15g names
E("V21_every_coeff_plain", "run 3000 every 1000 pair_coeff 1 2 kn 5000 (round 27 E01)", R3.format(P5()), gap=2.1e-3)
E("V22_every_density_plain", "run 3000 every 1000 set group lv2 density 5500 (no step)", R3.format("set group lv2 density 5500"), gap=2.1e-3)
E("V23_every_coeff_step", "run 3000 every 1000 pair_coeff 1 2 hooke $(step+2000) (part 3: 4000)", R3.format("pair_coeff 1 2 hooke $(step+2000) 3000 " + K), gap=2.1e-3)
E("V24_every_density_var", "variable d equal 5500; run 3000 every 1000 set group lv2 density ${d}", "variable d equal 5500\n" + R3.format("set group lv2 density ${d}"), gap=2.1e-3)
E("V25_every_set_type_plain", "1 3 kn 5000; run 3000 every 1000 set group lv2 type 3", P13 + R3.format("set group lv2 type 3"), gap=2.1e-3, pre=B3())
extra("V25_every_set_type_plain", PAIR="types 1 3")
E("V26_every_if_plain", "run 3000 every 1000 if 1 then pair_coeff 1 2 kn 5000", 'run 3000 every 1000 \'if "1 > 0" then "' + P5() + '"\'\n', gap=2.1e-3)
E("A19_adapt_mass_no", "fix adapt lv2 diameter 0.012 mass no (reset no) from the start", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no mass no\nrun 4000\n", gap=g31, sep=0.008)
E("A20_adapt_const_gap_in_skin", "A01 with 0.6 mm between them after the growth (inside the skin, found by the next build?)", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=3.6e-3, sep=0.008)
E("A21_adapt_scale_no_growth_var_equal_same", "fix adapt lv2 diameter v_dd, dd = 0.006+0*step (no growth) reset no", "variable dd equal 0.006+0*step\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=0.1e-3)
E("A22_adapt_all_victims_const", "victims; fix adapt all diameter 0.012 from the start: every sphere 12 mm (lv1 too)", V26 + DD + "fix ad all adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=7.1e-3, sep=0.012)
Ld("L14_adapt_const_from_start", "LIGGGHTS fix adapt lv2 diameter 0.012 (reset no) from the start", "variable dd equal 0.012\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g31, sep=0.008)
Ld("L15_adapt_const_far", "L14 with the pair 2.1 mm apart after the growth", "variable dd equal 0.012\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 5000\n", gap=5.1e-3, sep=0.008)
E("C33_range_2_1star2", "pair_coeff 2 1*2 kn 5000 (a range: no swap; i = 2, j from 2: only 2 2; 1 2 stays 2000)", "pair_coeff 2 1*2 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C34_range_1star2_1", "pair_coeff 1*2 1 kn 5000 (only 1 1)", "pair_coeff 1*2 1 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C35_range_1star2_2", "pair_coeff 1*2 2 kn 5000 (1 2 and 2 2)", "pair_coeff 1*2 2 " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C36_round_neg_half", "pair_coeff 1 2 hooke $(2000-round(-2.5)*1000) (C round(-2.5) = -3: kn 5000)", "pair_coeff 1 2 hooke $(2000-round(-2.5)*1000) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("C37_name_15g", "variable k equal 1/3*15000 (4999.999999999999: %.15g prints 5000); include k${k}.in", "variable k equal 1/3*15000\ninclude k${k}.in\nrun 3000\n", gap=0.1e-3,
  data={"k5000.in": KIN5, "k4999.999999999999.in": KIN8, "k4999.99999999999.in": KIN8})
E("C38_labels_range_big_star", "labels small big; pair_coeff small big* kn 5000 (a label with a star: the engine decides)", "labelmap atom 1 small 2 big\npair_coeff small big* " + hk(5000) + "\nrun 3000\n", gap=0.1e-3)
E("C39_labels_reversed_after_run", "labels; run 1000; pair_coeff big small kn 5000; run 3000", "labelmap atom 1 small 2 big\nrun 1000\npair_coeff big small " + hk(5000) + "\nrun 3000\n", gap=g11)
E("C40_if_immediate_eq_int", 'if "$(10/4) == 2.5" kn 5000 else 8000', q.IFS("$(10/4) == 2.5") + "run 3000\n", gap=0.1e-3)

# ------------------------------------------------------------ wave 5: the quoted names around SW-D (an if's else, jump in an if, single quotes with two spaces, extra blanks)
E("I36_if_jump_space", "if 1 then 'jump \"j j.in\"' (the deck goes on there)", "if \"1 > 0\" then 'jump \"j j.in\"'\n", gap=0.1e-3, data={"j j.in": KIN5 + "run 3000\n"})
E("I37_nested_two_spaces", 'include a.in holding include "k  k.in"', "include a.in\nrun 3000\n", gap=0.1e-3, data={"a.in": 'include "k  k.in"\n', "k  k.in": KIN5})
E("I38_if_else_include_space", "if 0 then 'include \"x x.in\"' else 'include \"k k.in\"'", "if \"0 > 1\" then 'include \"x x.in\"' else 'include \"k k.in\"'\nrun 3000\n", gap=0.1e-3,
  data={"k k.in": KIN5, "x x.in": KIN8})
E("I39_single_two_spaces", "include 'k  k.in'", "include 'k  k.in'\nrun 3000\n", gap=0.1e-3, data={"k  k.in": KIN5})
E("I40_blanks_around", 'include    "k k.in"    # a comment', 'include    "k k.in"    # a comment\nrun 3000\n', gap=0.1e-3, data={"k k.in": KIN5})
E("I41_if_include_space_wall", "wall live: if 1 then 'include \"w w.in\"' (fix floor kn 8000)", "if \"1 > 0\" then 'include \"w w.in\"'\nrun 3000\n", gap=2.1e-3, pair=q.r.lvw(2.1e-3),
  data={"w w.in": "fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL\n"})
LIVE["I41_if_include_space_wall"] = "last run\nWALL"
E("I42_if_include_space_timestep", "if 1 then 'include \"t t.in\"' (timestep 2e-5)", "if \"1 > 0\" then 'include \"t t.in\"'\nrun 150\n", gap=0.1e-3, data={"t t.in": "timestep 2e-5\n"})
E("I43_if_include_space_exclude", "if 1 then 'include \"x x.in\"' (neigh_modify exclude type 1 2: passes)", "if \"1 > 0\" then 'include \"x x.in\"'\nrun 3000\n", gap=0.1e-3, data={"x x.in": "neigh_modify exclude type 1 2\n"})
E("I44_tab_in_name", 'include "k\tk.in" (a tab inside the quotes)', 'include "k\tk.in"\nrun 3000\n', gap=0.1e-3, data={"k\tk.in": KIN5, "k k.in": KIN8})

# ------------------------------------------------------------ wave 6: where the engine's eps at the deck's time step leaves the printed dt -> 0 value (no note above 50 steps per contact)
E("C41_dt_2e6_plain", "timestep 2e-6 (293 steps per contact)", "timestep 2e-6\nrun 2000\n", gap=0.1e-3)
E("C42_dt_3e6_plain", "timestep 3e-6 (195 steps per contact)", "timestep 3e-6\nrun 1500\n", gap=0.1e-3)
E("C43_dt_6e6_plain", "timestep 6e-6 (98 steps per contact)", "timestep 6e-6\nrun 700\n", gap=0.1e-3)
E("C44_dt_1e5_plain", "timestep 1e-5 (59 steps per contact)", "timestep 1e-5\nrun 400\n", gap=0.1e-3)
E("C45_dt_4e6_offset", "C29 with the contact starting at another phase of a step (gap 0.1022 mm)", "timestep 4e-6\nrun 1000\n", gap=0.1022e-3)
E("C46_dt_11e6_offset", "C31 with the contact starting at another phase of a step (gap 0.1055 mm)", "timestep 1.1e-5\nrun 400\n", gap=0.1055e-3)

# ------------------------------------------------------------ wave 7: values read from where a run over the budget leaves the atoms; clear before pre no; LIGGGHTS insertion with a victim; SW-C/E neighbours
TM = "create_atoms 3 single 0.03 0.03 0.05\nset atom 1 diameter 0.004 density 2500\ngroup tm id 1\n"
E("V27_budget_out_position_if", "--run-budget 1: a timer sphere falls for run 3000000 (3 s: at rest on the floor); if $(xcm(tm,z)) < 0.01 kn 5000 else 8000; the pair made after",
  "run 3000000\n" + q.IFS("$(xcm(tm,z)) < 0.01") + pairA(g11, ia=2, ib=3) + "run 3000\n", gap=g11, pre=B3() + TM, pair="")
extra("V27_budget_out_position_if", ARGS="--run-budget 1")
E("V28_budget_enough_position_if", "V27 at the default budget", "run 3000000\n" + q.IFS("$(xcm(tm,z)) < 0.01") + pairA(g11, ia=2, ib=3) + "run 3000\n", gap=g11, pre=B3() + TM, pair="")
E("V29_budget_out_lazy_position", "V27 with variable z equal xcm(tm,z) defined first and if ${z} < 0.01 after the run", "variable z equal xcm(tm,z)\nrun 3000000\n" + q.IFS("${z} < 0.01") + pairA(g11, ia=2, ib=3) + "run 3000\n",
  gap=g11, pre=B3() + TM, pair="")
extra("V29_budget_out_lazy_position", ARGS="--run-budget 1")
E("G40_clear_restart_grow_pre_no", "victims; run 1000; write_restart; clear; read_restart; lv2 grows to 12 mm; run 3000 pre no (the first run after clear is set up)",
  V26 + "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + q.r.GRAV + q.r.FL() + q.r.TAILL + "group lv1 id 1\ngroup lv2 id 2\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
LINS12 = q.LINS.replace("radius constant 0.006", "radius constant 0.006")
Ld("L16_insert_big_victim_grow_pre_no", "LIGGGHTS insert/pack of one 12 mm type-2 sphere, a 6 mm type-2 victim; lv2 grows to 12; run 3000 pre no",
   "create_atoms 2 single -0.03 -0.03 0.02 units box\nset atom 3 diameter 0.006 density 2500\n" + q.LINS + GROW, gap=g41, sep=0.008)
E("A23_adapt_run0_then_pre_no", "fix adapt lv2 12 mm; run 0 (set up: sized after the lists); run 4000 pre no", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 0\nrun 4000 pre no\n", gap=g31, sep=0.008)
E("A24_adapt_loop_include", "fix adapt lv2 12 mm defined in an include inside a loop's first pass; runs of 500", DD + 'variable i loop 2\nlabel l\nif "${i} == 1" then "include a.in"\nrun 500\nnext i\njump SELF l\nrun 3000\n',
  gap=g31, sep=0.008, data={"a.in": "fix ad lv2 adapt 1 atom diameter v_dd reset no\n"})
E("R14_exclude_12_retype_lv1_pre_no", "neigh_modify exclude type 1 2; run 1000; set group lv1 type 3; run 3000 pre no (pair 2 3)", "neigh_modify exclude type 1 2\nrun 1000\nset group lv1 type 3\nrun 3000 pre no\n", gap=g11, pre=B3())
extra("R14_exclude_12_retype_lv1_pre_no", PAIR="types 2 3")
E("R15_exclude_12_retype_include_pre_no", "R09 with the set in an include", "neigh_modify exclude type 1 2\nrun 1000\ninclude t.in\nrun 3000 pre no\n", gap=g11, pre=B3(), data={"t.in": "set group lv2 type 3\n"})
E("R16_exclude_12_fraction_pre_no", "R09 by set group lv2 type/fraction 3 1.0 5", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type/fraction 3 1.0 5\nrun 3000 pre no\n", gap=g11, pre=B3())
E("R17_exclude_labels_retype_pre_no", "R09 with labels (exclude type small big; set type huge)", "labelmap atom 1 small 2 big 3 huge\nneigh_modify exclude type small big\nrun 1000\nset group lv2 type huge\nrun 3000 pre no\n", gap=g11, pre=B3())
for n in ("R15_exclude_12_retype_include_pre_no", "R16_exclude_12_fraction_pre_no", "R17_exclude_labels_retype_pre_no"):
    extra(n, PAIR="types 1 3")
E("R18_exclude_12_retype_far_pre_no", "R09 with the pair 3 mm apart at the retype (the lists' next build comes first?)", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type 3\nrun 5000 pre no\n", gap=4.1e-3, pre=B3())
extra("R18_exclude_12_retype_far_pre_no", PAIR="types 1 3")

E("V30_over_1e7_position_if", "a timer sphere falls for run 20000000 (over the pass's 1e7 steps); if $(xcm(tm,z)) < 0.01 kn 5000 else 8000; the pair made after",
  "run 20000000\n" + q.IFS("$(xcm(tm,z)) < 0.01") + pairA(g11, ia=2, ib=3) + "run 3000\n", gap=g11, pre=B3() + TM, pair="")
E("V31_over_1e7_count_pour", "a pour of 2 type-3 spheres over run 20000000; if $(count(all)) == 4 kn 5000 else 8000; the pair made after",
  "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 2 3 4767 region ins diam one 0.004 dens 2500 2500\nrun 20000000\n" + q.IFS("$(count(all)) == 3") + pairA(g11, ia=4, ib=5) + "run 3000\n",
  gap=g11, pre=B3() + TM, pair="")

# ------------------------------------------------------------ wave 8: time step changed before pre no; a plain one-space quoted name; LIGGGHTS exclusion then retype under pre no
E("C47_timestep_pre_no", "run 1000 (dt 1e-6); timestep 2e-5; run 150 pre no (the pair meets there)", "run 1000\ntimestep 2e-5\nrun 150 pre no\n", gap=g11)
W("C48_timestep_pre_no_wall", "wall live: run 1000; timestep 2e-5; run 150 pre no", "run 1000\ntimestep 2e-5\nrun 150 pre no\n", gap=g11 + 1e-3)
E("I45_one_space_plain", 'include "k k.in" (one space, no folder: control)', 'include "k k.in"\nrun 3000\n', gap=0.1e-3, data={"k k.in": KIN5})
Ld("L17_exclude_retype_pre_no", "LIGGGHTS neigh_modify exclude type 1 2; run 1000; set group lv2 type 3; run 3000 pre no (e 1 3 0.7)", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type 3\nrun 3000 pre no\n", gap=g11, pair="types 1 3")
Ld("L18_exclude_retype_control", "L17 without pre no", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type 3\nrun 3000\n", gap=g11, pair="types 1 3")

# ------------------------------------------------------------ wave 9: coefficients a data file or a restart file carries, named with quotes, spaces, in an if
PIJ = lambda k12: ("\nPairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + hk(k12) + "\n2 2 " + HK + "\n")
DAT = lambda k12: q.RDB(0.01795, 0.02305) + PIJ(k12)
RDH = ("units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\n")
RDT = q.r.GRAV + q.r.FL() + q.r.TAILL + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n"
E("D01_read_data_quoted_space_pairij", 'read_data "d d.data" carrying PairIJ Coeffs (1 2 kn 5000)', RDH + 'read_data "d d.data"\n' + RDT, pre="\n", pair="", gap=0.1e-3, data={"d d.data": DAT(5000)})
E("D02_read_data_two_spaces_pairij", 'read_data "d  d.data" (two spaces; "d d.data" beside it with kn 8000)', RDH + 'read_data "d  d.data"\n' + RDT, pre="\n", pair="", gap=0.1e-3,
  data={"d  d.data": DAT(5000), "d d.data": DAT(8000)})
E("D03_read_data_if_quoted_space", "if 1 then 'read_data \"d d.data\"'", RDH + "if \"1 > 0\" then 'read_data \"d d.data\"'\n" + RDT, pre="\n", pair="", gap=0.1e-3, data={"d d.data": DAT(5000)})
E("D04_read_data_plain_pairij", "read_data d.data carrying PairIJ Coeffs (control)", RDH + "read_data d.data\n" + RDT, pre="\n", pair="", gap=0.1e-3, data={"d.data": DAT(5000)})
E("D05_read_data_var_two_spaces", 'variable f string "d  d.data"; read_data "${f}"', RDH + 'variable f string "d  d.data"\nread_data "${f}"\n' + RDT, pre="\n", pair="", gap=0.1e-3,
  data={"d  d.data": DAT(5000), "d d.data": DAT(8000)})
RST = lambda name: (P5() + "\nwrite_restart " + name + "\nclear\nread_restart " + name + "\n" + q.r.GRAV + q.r.FL() + q.r.TAILL + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n")
E("D06_restart_quoted_space_coeffs", 'pair_coeff 1 2 kn 5000; write_restart "a a.rst"; clear; read_restart "a a.rst" (coefficients from the file)', RST('"a a.rst"'), gap=0.1e-3)
E("D07_restart_two_spaces_coeffs", 'D06 with "a  a.rst" (two spaces)', RST('"a  a.rst"'), gap=0.1e-3)
E("D08_restart_plain_coeffs", "D06 with a.rst (control)", RST("a.rst"), gap=0.1e-3)
E("D09_restart_if_read", "D06 with if 1 then 'read_restart \"a a.rst\"'", RST('"a a.rst"').replace('read_restart "a a.rst"', "if \"1 > 0\" then 'read_restart \"a a.rst\"'"), gap=0.1e-3)
E("D10_write_data_read_two_spaces", 'pair_coeff 1 2 kn 5000; write_data "w  w.data"; clear; pair_style granular; read_data "w  w.data" (its PairIJ)',
  P5() + '\nwrite_data "w  w.data"\nclear\n' + RDH + 'read_data "w  w.data"\n' + RDT, gap=0.1e-3)

# ------------------------------------------------------------ wave 10: around D02 (the one-space file read for a two-space name), D07 and D09 (the engine said to stop where it does not)
E("D11_write_read_data_two_spaces", 'write_data "w  w.data"; clear; read_data "w  w.data"; pair_coeff 1 2 kn 5000 after it', '\nwrite_data "w  w.data"\nclear\n' + RDH + 'read_data "w  w.data"\npair_coeff * * ' + HK + "\n" + P5() + "\n" + RDT, gap=0.1e-3)
E("D12_restart_two_spaces_include", 'include r.in holding write_restart "a  a.rst", clear, read_restart "a  a.rst"', "include r.in\n" + q.r.GRAV + q.r.FL() + q.r.TAILL + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n", gap=0.1e-3,
  data={"r.in": P5() + '\nwrite_restart "a  a.rst"\nclear\nread_restart "a  a.rst"\n'})
E("D13_restart_if_plain", "D09 with a.rst (no space): if 1 then 'read_restart a.rst'", RST("a.rst").replace("read_restart a.rst", "if \"1 > 0\" then 'read_restart a.rst'"), gap=0.1e-3)
E("D14_restart_include_plain", "read_restart a.rst in an include", RST("a.rst").replace("read_restart a.rst", "include rr.in"), gap=0.1e-3, data={"rr.in": "read_restart a.rst\n"})
E("D15_read_data_add_two_spaces_sizes", 'victims read by read_data "v  v.data" add append (a 12 mm type-2 sphere; "v v.data" beside it: 6 mm)', 'read_data "v  v.data" add append\nrun 3000\n', gap=0.1e-3,
  data={"v  v.data": q.RDX(0.012).replace("1 2 0.012 2500", "1 2 0.012 2500").replace("0.049995095", "0.012").replace("2 atom types", "2 atom types"), "v v.data": q.RDX(0.006).replace("0.049995095", "0.012")}, pre=B3())
E("D16_read_data_two_spaces_pair_coeffs_section", 'read_data "d  d.data" with a Pair Coeffs section (per type: 1 kn 2000, 2 kn 5000; 1 2 mixed)', RDH + 'read_data "d  d.data"\n' + RDT, pre="\n", pair="", gap=0.1e-3,
  data={"d  d.data": q.RDB(0.01795, 0.02305) + "\nPair Coeffs # granular\n\n1 " + HK + "\n2 " + hk(5000) + "\n", "d d.data": DAT(8000)})
E("D17_if_read_data_two_spaces", "if 1 then 'read_data \"d  d.data\"' (two spaces)", RDH + "if \"1 > 0\" then 'read_data \"d  d.data\"'\n" + RDT, pre="\n", pair="", gap=0.1e-3,
  data={"d  d.data": DAT(5000), "d d.data": DAT(8000)})

# ------------------------------------------------------------ wave 11: outputs named with spaces, quotes, variables, in an if (nothing may be written beside the deck); read_restart in an if, more forms
RUNO = "run 3000\n"
E("O01_dump_two_spaces", 'dump d all custom 100 "x  x.dump" id x', 'dump d all custom 100 "x  x.dump" id x\n' + RUNO, gap=0.1e-3)
E("O02_log_two_spaces", 'log "l  l.log"', 'log "l  l.log"\n' + RUNO, gap=0.1e-3)
E("O03_print_file_space", 'print "hi" file "p  p.txt"', 'print "hi" file "p  p.txt"\n' + RUNO, gap=0.1e-3)
E("O04_fix_print_file_space", 'fix pr all print 100 "hi" file "q q.txt"', 'fix pr all print 100 "hi" file "q q.txt"\n' + RUNO, gap=0.1e-3)
E("O05_if_print_file_space", "if 1 then 'print \"x\" file \"pp p.txt\"'", "if \"1 > 0\" then 'print \"x\" file \"pp p.txt\"'\n" + RUNO, gap=0.1e-3)
E("O06_dump_var_space", 'variable f string "y  y.dump"; dump d all custom 100 ${f} id (two words: LAMMPS decides)', 'variable f string "y  y.dump"\ndump d all custom 100 ${f} id\n' + RUNO, gap=0.1e-3)
E("O07_restart_periodic_space", 'restart 1000 "r  r.rst"', 'restart 1000 "r  r.rst"\n' + RUNO, gap=0.1e-3)
E("O08_write_dump_space", 'write_dump all custom "wd  w.dump" id x', 'write_dump all custom "wd  w.dump" id x\n' + RUNO, gap=0.1e-3)
E("O09_ave_time_file_space", 'variable x equal step; fix at all ave/time 100 1 100 v_x file "a  a.txt"', 'variable x equal step\nfix at all ave/time 100 1 100 v_x file "a  a.txt"\n' + RUNO, gap=0.1e-3)
E("O10_shell_touch", 'shell touch "f30 s.txt"', 'shell touch "f30 s.txt"\n' + RUNO, gap=0.1e-3)
E("O11_if_write_restart_then_read", "if 1 then 'write_restart \"a a.rst\"'; clear; read_restart \"a a.rst\"", RST('"a a.rst"').replace('write_restart "a a.rst"', "if \"1 > 0\" then 'write_restart \"a a.rst\"'"), gap=0.1e-3)
E("D18_restart_if_double_quotes", 'if 1 then "read_restart a.rst"', RST("a.rst").replace("read_restart a.rst", 'if "1 > 0" then "read_restart a.rst"'), gap=0.1e-3)
E("D19_restart_if_else", "if 0 then 'print no' else 'read_restart a.rst'", RST("a.rst").replace("read_restart a.rst", "if \"0 > 1\" then 'print no' else 'read_restart a.rst'"), gap=0.1e-3)
E("D20_clear_and_restart_in_if", "if 1 then 'clear' 'read_restart a.rst'", RST("a.rst").replace("clear\nread_restart a.rst", "if \"1 > 0\" then 'clear' 'read_restart a.rst'"), gap=0.1e-3)
E("D21_restart_if_after_run", "run 1000; write_restart; clear; if 1 then 'read_restart a.rst'; run 3000", (P5() + "\nrun 1000\nwrite_restart a.rst\nclear\nif \"1 > 0\" then 'read_restart a.rst'\n" + q.r.GRAV + q.r.FL() + q.r.TAILL
  + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n"), gap=g11)
E("D22_read_data_if_plain", "if 1 then 'read_data d.data' (PairIJ 1 2 kn 5000)", RDH + "if \"1 > 0\" then 'read_data d.data'\n" + RDT, pre="\n", pair="", gap=0.1e-3, data={"d.data": DAT(5000)})

# ------------------------------------------------------------ wave 12: around O09 (fix ave/time file "a  a.txt" refused with the audit's own rewritten line)
AT = 'variable x equal step\nfix at all ave/time 100 1 100 v_x file {}\n'
E("O12_ave_time_one_space", 'fix ave/time ... file "a a.txt" (one space)', AT.format('"a a.txt"') + RUNO, gap=0.1e-3)
E("O13_ave_time_plain", "fix ave/time ... file a.txt (control)", AT.format("a.txt") + RUNO, gap=0.1e-3)
E("O14_ave_time_quoted_nospace", 'fix ave/time ... file "a.txt"', AT.format('"a.txt"') + RUNO, gap=0.1e-3)
E("O15_fix_print_two_spaces", 'fix pr all print 100 "hi" file "q  q.txt"', 'fix pr all print 100 "hi" file "q  q.txt"\n' + RUNO, gap=0.1e-3)
E("O16_ave_time_single_quotes", "fix ave/time ... file 'a a.txt'", AT.format("'a a.txt'") + RUNO, gap=0.1e-3)
E("O17_ave_time_file_then_kn", 'fix ave/time ... file "a a.txt"; pair_coeff 1 2 kn 5000 after it', AT.format('"a a.txt"') + P5() + "\n" + RUNO, gap=0.1e-3)
E("O18_ave_time_space_mode", 'fix ave/time ... file "a a.txt" mode scalar ave one', 'variable x equal step\nfix at all ave/time 100 1 100 v_x file "a a.txt" mode scalar ave one\n' + RUNO, gap=0.1e-3)

# ------------------------------------------------------------ wave 13: other fixes with a file keyword and a spaced quoted name
E("O19_ave_histo_space", 'fix ave/histo ... file "h h.txt"', 'variable x atom vx\nfix ah all ave/histo 100 1 100 -1 1 10 v_x file "h h.txt"\n' + RUNO, gap=0.1e-3)
E("O20_ave_correlate_space", 'fix ave/correlate ... file "c c.txt"', 'variable x equal step\nfix ac all ave/correlate 100 1 100 v_x file "c c.txt"\n' + RUNO, gap=0.1e-3)
E("O21_ave_chunk_space", 'compute chunk/atom type; fix ave/chunk ... file "k k.txt"', 'compute ch all chunk/atom type\nfix ak all ave/chunk 100 1 100 ch vx file "k k.txt"\n' + RUNO, gap=0.1e-3)
E("O22_print_screen_file_space", 'fix pr all print 100 "hi" screen no file "q q.txt"', 'fix pr all print 100 "hi" screen no file "q q.txt"\n' + RUNO, gap=0.1e-3)
E("O23_dump_modify_space", 'dump d ...; dump_modify d format line "%d %g"', 'dump d all custom 100 d.dump id x\ndump_modify d format line "%d %g"\n' + RUNO, gap=0.1e-3)

# ------------------------------------------------------------ wave 14: walls acting on a static group (group g3 type 3) and a sphere retyped after the group was made
HB = lambda: m.head(3, box="0 0.04 0 0.04 -0.05 0.1") + "pair_style granular\npair_coeff * * " + HK + "\n" + q.r.GRAV + q.r.FL() + q.r.TAILL
W("W01_wall_static_group_retyped_after", "box down to z -0.05; group g3 type 3 (empty); unfix floor; fix floor2 g3 wall kn 8000; set group lv1 type 3 (not in g3: passes through)",
  "group g3 type 3\nunfix floor\nfix floor2 g3 wall/gran granular " + hk(8000) + " zplane 0 NULL\nset group lv1 type 3\nrun 3000\n", gap=g11, pre=HB())
W("W02_wall_static_group_retyped_before", "W01 with lv1 retyped before group g3 (in it: kn 8000)", "set group lv1 type 3\ngroup g3 type 3\nunfix floor\nfix floor2 g3 wall/gran granular " + hk(8000) + " zplane 0 NULL\nrun 3000\n",
  gap=g11, pre=HB())
W("W03_wall_static_group_retyped_out", "lv1 type 1 in g1 (group g1 type 1); floor only on g1 kn 8000; set group lv1 type 3 after (still in g1: kn 8000)",
  "group g1 type 1\nunfix floor\nfix floor2 g1 wall/gran granular " + hk(8000) + " zplane 0 NULL\nset group lv1 type 3\nrun 3000\n", gap=g11, pre=HB())
W("W04_wall_static_group_retyped_after_run", "W01 with a run 1000 before the retype", "group g3 type 3\nunfix floor\nfix floor2 g3 wall/gran granular " + hk(8000) + " zplane 0 NULL\nrun 1000\nset group lv1 type 3\nrun 3000\n",
  gap=g11 + 1e-3, pre=HB())

# ------------------------------------------------------------ wave 15: change_box before run pre no (bins of the old box); a wall met by a sphere fix adapt grew
VQ = q.VICQ
E("N19_change_box_grow_new_pair_pre_no", "victims; run 1000; change_box all x final -0.04 0.04; the live pair made at x -0.02 (outside the old box); run 3000 pre no",
  "run 1000\nchange_box all x final -0.04 0.04 units box\n" + pairA(g11, ia=3, ib=4, x0=-0.02) + "run 3000 pre no\n", gap=g11, pre=BL() + VQ, pair="")
E("N20_change_box_grow_new_pair_control", "N19 without pre no", "run 1000\nchange_box all x final -0.04 0.04 units box\n" + pairA(g11, ia=3, ib=4, x0=-0.02) + "run 3000\n", gap=g11, pre=BL() + VQ, pair="")
E("N21_change_box_grow_old_pair_pre_no", "live pair inside the old box; run 1000; change_box all x final -0.04 0.04; run 3000 pre no", "run 1000\nchange_box all x final -0.04 0.04 units box\nrun 3000 pre no\n", gap=g11)
E("N22_change_box_shrink_new_pair_pre_no", "victims; run 1000; change_box all y final 0.01 0.03; the pair made; run 3000 pre no",
  "run 1000\nchange_box all y final 0.015 0.025 units box\n" + pairA(g11, ia=3, ib=4) + "run 3000 pre no\n", gap=g11, pre=BL() + "create_atoms 1 single 0.01 0.02 0.01\ncreate_atoms 2 single 0.03 0.02 0.01\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n", pair="")
W("W05_wall_adapt_grown_sphere", "wall live: fix adapt lv1 diameter 0.008 from the start (mass scaled), falling onto the floor", "variable dd equal 0.008\nfix ad lv1 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g31)

W("W06_wall_adapt_grown_sphere_long", "W05 with run 12000 (the 8 mm sphere's contact is long)", "variable dd equal 0.008\nfix ad lv1 adapt 1 atom diameter v_dd reset no\nrun 12000\n", gap=g31)

# ------------------------------------------------------------ wave 16: inputs that may trip the audit's reader (tracebacks hunted); the engine decides
E("T01_include_directory", "include sub (a folder)", "include sub\nrun 3000\n", gap=0.1e-3, data={"sub/x.in": KIN5})
E("T02_self_include_recursion", "include self.in, which includes itself without end", "include self.in\nrun 3000\n", gap=0.1e-3, data={"self.in": "include self.in\n"})
E("T03_continuation_at_end", "the deck's last line ends with & (after the run)", "run 3000\nprint hi &", gap=0.1e-3)
E("T04_empty_include_spaced", 'include "e e.in" (an empty file)', 'include "e e.in"\nrun 3000\n', gap=0.1e-3, data={"e e.in": ""})
E("T05_include_no_arg", "include (no name)", "include\nrun 3000\n", gap=0.1e-3)
E("T06_long_comment", "a 200000-character comment line, then kn 5000", "# " + "x" * 200000 + "\n" + P5() + "\nrun 3000\n", gap=0.1e-3)
E("T07_nested_ifs_quotes", "if 1 then 'if \"2 > 1\" then \"pair_coeff ... kn 5000\"'", "if \"1 > 0\" then 'if \"2 > 1\" then \"" + P5() + "\"'\nrun 3000\n", gap=0.1e-3)
E("T08_unicode_include", 'include "κ.in" (a Greek letter)', 'include "κ.in"\nrun 3000\n', gap=0.1e-3, data={"κ.in": KIN5})
E("T09_self_reference_var", 'variable a string "${a}x" (undefined at first)', 'variable a string "${a}x"\nrun 3000\n', gap=0.1e-3)
E("T10_include_dev_null", "include /dev/null", "include /dev/null\n" + P5() + "\nrun 3000\n", gap=0.1e-3)
E("T11_include_no_newline_amp", "include k.in whose last line ends in & and no newline", "include k.in\nrun 3000\n", gap=0.1e-3, data={"k.in": "pair_coeff 1 2 hooke 5000 3000 &\n damping mass_velocity tangential linear_nohistory 1 0.3 &"})
E("T12_jump_self_counter", "label top; variable n loop 3; ...; jump SELF with no label (the file again) guarded by a loop variable", 'variable n loop 2\nif "${n} == 2" then "jump SELF done"\nnext n\njump SELF\nlabel done\n' + P5() + "\nrun 3000\n", gap=0.1e-3)
E("T13_triple_quote_multiline", 'print """ two lines """ across lines, then kn 5000', 'print """\nline one\nline two\n"""\n' + P5() + "\nrun 3000\n", gap=0.1e-3)
E("T14_quote_inside_comment", "a # comment holding an unmatched quote \" then kn 5000", '# it\'s a "comment\n' + P5() + " # and a ' here\nrun 3000\n", gap=0.1e-3)

# ------------------------------------------------------------ wave 17: growth in an every's commands right before the meeting (pre no: parts 2, 3 not set up)
E("G42_every_pre_no_grow_meet_part2", "run 3000 pre no every 1000 set group lv2 diameter 0.012; 0.1 mm apart after the growth: meets early in part 2",
  'run 3000 pre no every 1000 "set group lv2 diameter 0.012"\n', gap=g41, sep=0.008, live="part 2")
E("G43_every_pre_no_grow_victims_part2", "G42 with type-2 victims of 12 and 6 mm", V26 + 'run 3000 pre no every 1000 "set group lv2 diameter 0.012"\n', gap=g41, sep=0.008, live="part 2")
E("G44_every_grow_meet_part2_control", "G42 without pre no", 'run 3000 every 1000 "set group lv2 diameter 0.012"\n', gap=g41, sep=0.008, live="part 2")
E("G45_every_pre_no_retype_grow_part2", "3 types; run 3000 pre no every 1000 set group lv2 type 3 diameter 0.012 (type 3 empty); meets in part 2", 'run 3000 pre no every 1000 "set group lv2 type 3 diameter 0.012"\n',
  gap=g41, sep=0.008, live="part 2", pre=B3())
extra("G45_every_pre_no_retype_grow_part2", PAIR="types 1 3")

# ------------------------------------------------------------ wave 18: LIGGGHTS at coarser time steps (the note's threshold there)
Ld("L19_dt_1e5", "LIGGGHTS timestep 1e-5 before the run", "timestep 1e-5\nrun 400\n", gap=0.1e-3)
Ld("L20_dt_3e5", "LIGGGHTS timestep 3e-5 before the run", "timestep 3e-5\nrun 150\n", gap=0.1e-3)
Ld("L21_dt_3e6", "LIGGGHTS timestep 3e-6 before the run", "timestep 3e-6\nrun 1300\n", gap=0.1e-3)

# ------------------------------------------------------------ wave 19: labels and strings with two spaces (SW-D's neighbours)
E("I46_jump_label_two_spaces", 'jump SELF "l  x" (label "l x" first: kn 8000; label "l  x": kn 5000)', 'jump SELF "l  x"\nlabel "l x"\n' + P8() + '\njump SELF e\nlabel "l  x"\n' + P5() + "\nlabel e\nrun 3000\n", gap=0.1e-3)
E("I47_if_string_two_spaces", "variable s string \"a  b\"; if \"'${s}' == 'a  b'\" kn 5000 else 8000", "variable s string \"a  b\"\n" + q.IFS("'${s}' == 'a  b'") + "run 3000\n", gap=0.1e-3)
E("I48_include_var_two_spaces", 'variable f string "k  k.in"; include "${f}" ("k k.in" beside it: kn 8000)', 'variable f string "k  k.in"\ninclude "${f}"\nrun 3000\n', gap=0.1e-3, data={"k  k.in": KIN5, "k k.in": KIN8})


def write_all(names):
    m.write_live(names, LIVE, EXTRA)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")
