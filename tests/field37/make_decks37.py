"""Field round 37: write decks/NAME/in.deck (and the files a deck reads) for the referee live37.py and the audit.

An adversarial check of branch next-every (d0aa2d13): `next` and `jump SELF` between a run's parts (N), LIGGGHTS'
includes of a run's every read after the run (I), files named by the step and reads of files skipped commands write
(R), `run N pre no every M` and the still run after replicate (P), scripts the copy may not map (F: links, moves,
hard links, big files, shell cd), the issue's nine classes again (K V Q Y W S T) and public decks shortened (O, sources
in FINDINGS.md). The live pair and the helpers are rounds 35 and 36's (make_decks36.py, imported): type 1 of 4 mm
(lv1) / type 2 of 6 mm (lv2), 2500 kg/m3, hooke kn 2000 damping 3000 mass_velocity, dt 1e-6 s, meeting at 1 m/s 0.1 ms
into the run or part named in LIVE. LAMMPS controls: kn 2000 0.413435, 3000 0.490898, 4000 0.542172, 5000 0.578975;
lv2 at 5000 kg/m3 0.390402. usage: python make_decks37.py [NAME-PREFIX ...]"""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field36"))
import make_decks36 as m6  # noqa: E402  (round 36's helpers, with round 35's; their DECKS are not written here)

m = m6.m
D = os.path.join(HERE, "decks")
DECKS = {}
BASE, IN, WALLP, LBASE, LIN, LWALL = m.BASE, m.IN, m.WALLP, m.LBASE, m.LIN, m.LWALL
HK, HK5, WHK, G, G11, PCs, EV, LE, LEV = m.HK, m.HK5, m.WHK, m.G, m.G11, m.PCs, m.EV, m.LE, m.LEV
VZ, WALL, HKk, RB, FFFX, MB, TAILR = m.VZ, m.WALL, m6.HKk, m6.RB, m6.FFFX, m6.MB, m6.TAILR
LINKS = {}      # name: [(link, target)]
HARD = {}       # name: [(link, target)]
GEN = {}        # name: callable(folder)


def L(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    pre = RB if pre is None else pre
    pair = IN(0.1e-3) if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


def LG(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN(0.1e-3) if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


PC5, PC3, PC4 = PCs(5000) + "\n", PCs(3000) + "\n", PCs(4000) + "\n"
LEe = lambda e: LE.format(e=e) + "\n"
STEP = PCs("$(2000+step)")

# ================================================================ N: next / jump SELF between a run's parts (LAMMPS)
L("N01_next_index_every", "a index 3000 4000 5000; every \"pc ${a}\" \"next a\" (part 3 meets: 4000)",
  "variable a index 3000 4000 5000\nrun 4000 every 1000 \"" + PCs("${a}") + "\" \"next a\"\n", pair=IN(G(3)), live="part 3")
L("N02_next_exhausts_skips_deck_jump", "a index 3000 4000; run 2000 every \"pc ${a}\" \"next a\" (exhausted after part 2: the deck's next jump is skipped); jump SELF skip; pc 5000; label skip; run 3000 (LAMMPS: 5000)",
  "variable a index 3000 4000\nrun 2000 every 1000 \"" + PCs("${a}") + "\" \"next a\"\njump SELF skip\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)))
L("N03_next_loop_exhausts_skip", "a loop 2; run 2000 every \"next a\"; jump SELF skip skipped; pc 5000; run 3000",
  "variable a loop 2\nrun 2000 every 1000 \"next a\"\njump SELF skip\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)))
L("N04_next_every_vs_deck_loop", "loop i 2 around: j loop 2; run 2000 every \"next j\" (exhausts: arms the skip); next i; jump SELF lp (skipped: one pass); pc 5000; run 3000 (meets at step 2100: 5000)",
  "variable i loop 2\nlabel lp\nvariable j loop 2\nrun 2000 every 1000 \"next j\"\nnext i\njump SELF lp\n" + PC5 + "run 3000\n", pair=IN(G(3)))
L("N05_include_loop_in_file", "every \"include k.in\"; k.in a loop of 2 (q) setting kn 2000+1000*q (4000 after each part; part 2)",
  "run 3000 every 1000 \"include k.in\"\n", pair=IN(G(2)), live="part 2",
  data={"k.in": "variable q loop 2\nlabel kl\n" + PCs("$(2000+1000*v_q)") + "\nnext q\njump SELF kl\n"})
L("N06_include_jump_missing_label", "every \"include k.in\"; k.in: jump SELF nolabel (no such label: LAMMPS stops)",
  "run 3000 every 1000 \"include k.in\"\n", pair=IN(G(2)), live="part 2", data={"k.in": PC5 + "jump SELF nolabel\n"})
L("N07_include_jump_other_file", "every \"include k.in\"; k.in: jump o.in (o.in: kn 5000); part 2",
  "run 3000 every 1000 \"include k.in\"\n", pair=IN(G(2)), live="part 2", data={"k.in": PC3 + "jump o.in\n" + PC4, "o.in": PC5})
L("N08_nested_include_step", "every \"include a.in\"; a.in includes b.in; b.in: pc $(2000+step) (part 2: 3000)",
  "run 3000 every 1000 \"include a.in\"\n", pair=IN(G(2)), live="part 2", data={"a.in": "include b.in\n", "b.in": STEP + "\n"})
L("N09_include_next_then_deck_jump", "q loop 2; every \"include k.in\" (k.in: next q): exhausted after part 2; jump SELF skip skipped; pc 5000; run 3000",
  "variable q loop 2\nrun 2000 every 1000 \"include k.in\"\njump SELF skip\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)), data={"k.in": "next q\n"})
L("N10_every_own_jump", "every \"jump SELF lb\" in the run's own commands (LAMMPS: searches the deck for lb; the rest skipped); pc 5000 after lb",
  "run 3000 every 1000 \"jump SELF lb\"\n" + PC3 + "label lb\n" + PC5 + "run 3000\n", pair=IN(G(4)))
L("N11_next_file_variable", "a file vals.txt (3000 4000 5000); every \"pc ${a}\" \"next a\" (part 3: 4000)",
  "variable a file vals.txt\nrun 4000 every 1000 \"" + PCs("${a}") + "\" \"next a\"\n", pair=IN(G(3)), live="part 3", data={"vals.txt": "3000\n4000\n5000\n"})
L("N12_next_two_vars_one_exhausts", "a loop 2, b index 3000 4000 5000; every \"next a\" \"pc ${b}\" \"next b\"? no: a exhausts after part 2 and stays armed through part 3's nexts? ; jump SELF skip; pc 5000; label skip; run 3000",
  "variable a loop 2\nvariable b index 3000 4000 5000\nrun 2000 every 1000 \"next a\" \"" + PCs("${b}") + "\" \"next b\"\njump SELF skip\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)))
L("N13_include_selfjump_loop_step", "every \"include k.in\" where k.in loops twice (jump SELF) adding 500 to kn each time from $(step) (part 2: 2000+1000+1000?)",
  "variable kk equal 2000\nrun 3000 every 1000 \"include k.in\"\n", pair=IN(G(2)), live="part 2",
  data={"k.in": "variable q loop 2\nlabel kl\nvariable kk equal $(v_kk+500)\nnext q\njump SELF kl\n" + PCs("${kk}") + "\n"})
L("N14_next_every_np2_fff", "f f f processors * 1 1: a index 3000 4000 5000; every pc ${a}, next a (part 3: 4000), 1 and 2 processes",
  "variable a index 3000 4000 5000\nrun 4000 every 1000 \"" + PCs("${a}") + "\" \"next a\"\n", pre=BASE(boundary="f f f", head="processors * 1 1\n", wall=False), pair=IN(G(3)), live="part 3")
L("N15_include_label_and_jump_in_if", "every \"include k.in\"; k.in: if ${s} > 1500 then jump SELF hi; pc 3000; jump SELF end; label hi; pc 5000; label end (s = step) (part 2: 3000, part 3: 5000)",
  "variable s equal step\nrun 4000 every 1000 \"include k.in\"\n", pair=IN(G(3)), live="part 3",
  data={"k.in": "if \"${s} > 1500\" then \"jump SELF hi\"\n" + PC3 + "jump SELF end\nlabel hi\n" + PC5 + "label end\n"})
L("N16_next_in_if_every", "a index 3000 4000 5000; every 'if \"1 > 0\" then \"next a\"' \"pc ${a}\" (part 2: pc 4000 after part 1... part 3: 5000)",
  "variable a index 3000 4000 5000\nrun 4000 every 1000 'if \"1 > 0\" then \"next a\"' \"" + PCs("${a}") + "\"\n", pair=IN(G(3)), live="part 3")
L("N17_loop_deck_next_every_wall", "WALL: a index 3000 5000; every \"fix floor ... ${a}\" \"next a\" (falls in part 2: wall kn 3000)",
  "unfix floor\nvariable a index 3000 5000 6000\nrun 3000 every 1000 \"fix floor all wall/gran granular " + HKk("${a}") + " zplane 0 NULL\" \"next a\"\n",
  pre=BASE(), pair=WALLP(1.1e-3), live="part 2", **WALL)

# ================================================================ I: LIGGGHTS, a file a run's every includes read after the run
LPart = lambda p: LIN(G(p))
LG("I01_lig_inc_holds_run", "LIGGGHTS: run 3000 every 1000 \"include a.in\"; a.in: e 0.8, run 2000 (read after the run, 3 times; the pair meets in the first such run: 0.8)",
   "run 3000 every 1000 \"include a.in\"\n", pair=LPart(4), data={"a.in": LEe(0.8) + "run 2000\n"})
LG("I02_lig_inc_holds_run_meets_in_parts", "LIGGGHTS: a.in: e 0.8, run 500; the pair meets in part 2 (0.5: nothing read yet)",
   "run 3000 every 1000 \"include a.in\"\n", pair=LPart(2), live="part 2", data={"a.in": LEe(0.8) + "run 500\n"})
LG("I03_lig_inc_holds_jump_loop", "LIGGGHTS: a.in loops twice (jump SELF) setting e; after the run 0.8; run 3000 (meets there)",
   "run 2000 every 1000 \"include a.in\"\nrun 3000\n", pair=LPart(3),
   data={"a.in": "variable q loop 2\nlabel al\n" + LE.format(e="$(0.6+0.1*v_q)") + "\nnext q\njump SELF al\n"})
LG("I04_lig_inc_nested", "LIGGGHTS: a.in includes b.in (e 0.8); the pair meets in part 2 (0.5) ... after the run 0.8",
   "run 3000 every 1000 \"include a.in\"\n", pair=LPart(2), live="part 2", data={"a.in": "include b.in\n", "b.in": LEe(0.8)})
LG("I05_lig_inc_nested_after", "LIGGGHTS: I04 with the pair meeting in the run after (0.8)",
   "run 2000 every 1000 \"include a.in\"\nrun 3000\n", pair=LPart(3), data={"a.in": "include b.in\n", "b.in": LEe(0.8)})
LG("I06_lig_if_include_part2", "LIGGGHTS: every 'if \"$(step) == 1000\" then \"include a.in\"' (a.in: e 0.8): read only after the run; part 2 and 3 keep 0.5",
   "run 3000 every 1000 'if \"$(step) == 1000\" then \"include a.in\"'\n", pair=LPart(2), live="part 2", data={"a.in": LEe(0.8)})
LG("I07_lig_if_include_after", "LIGGGHTS: I06 with the pair meeting in the run after (0.8)",
   "run 2000 every 1000 'if \"$(step) == 1000\" then \"include a.in\"'\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I08_lig_inc_mixed_direct", "LIGGGHTS: every \"include a.in\" \"fix m3 ... 0.7\" (the direct one after each part: part 2 0.7; a.in 0.8 after the run)",
   "run 3000 every 1000 \"include a.in\" \"" + LE.format(e="0.7") + "\"\n", pair=LPart(2), live="part 2", data={"a.in": LEe(0.8)})
LG("I09_lig_inc_mixed_direct_after", "LIGGGHTS: I08 with the pair in the run after: 0.8 (the include read last)",
   "run 2000 every 1000 \"include a.in\" \"" + LE.format(e="0.7") + "\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I10_lig_inc_var_name", "LIGGGHTS: every \"include ${f}\" (f a.in): refused by design",
   "variable f string a.in\nrun 2000 every 1000 \"include ${f}\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I11_lig_inc_every_ge_n", "LIGGGHTS: run 1000 every 2000 \"include a.in\" (one part); run 3000 meets (0.8)",
   "run 1000 every 2000 \"include a.in\"\nrun 3000\n", pair=LPart(2), data={"a.in": LEe(0.8)})
LG("I12_lig_inc_several_runs_after", "LIGGGHTS: run 2000 every 1000 \"include a.in\" (a.in: e 0.8); run 1000; run 3000 (meets in the second run after: 0.8)",
   "run 2000 every 1000 \"include a.in\"\nrun 1000\nrun 3000\n", pair=LPart(4), data={"a.in": LEe(0.8)})
LG("I13_lig_two_files_order", "LIGGGHTS: every \"include a.in\" \"include b.in\" (a 0.7, b 0.8): read b a b a after the run; last a: 0.7 in the run after",
   "run 2000 every 1000 \"include a.in\" \"include b.in\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.7), "b.in": LEe(0.8)})
LG("I14_lig_inc_quoted_name", "LIGGGHTS: every \"include 'a.in'\" (a quoted name); run 3000 (0.8)",
   "run 2000 every 1000 \"include 'a.in'\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I15_lig_inc_trailing_comment", "LIGGGHTS: every \"include a.in # e\" (a comment after the name); run 3000 (0.8)",
   "run 2000 every 1000 \"include a.in # e\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I16_lig_inc_upto", "LIGGGHTS: run 2000 upto every 1000 \"include a.in\"; run 3000 (0.8)",
   "run 2000 upto every 1000 \"include a.in\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I17_lig_inc_in_deck_loop", "LIGGGHTS: loop i 2 { run 1000 every 500 \"include a.in\" } (a.in: e 0.5+0.1*i... ); run 3000 (meets: last a.in value 0.7)",
   "variable i loop 2\nlabel lp\nrun 1000 every 500 \"include a.in\"\nnext i\njump SELF lp\nrun 3000\n", pair=LPart(3),
   data={"a.in": LE.format(e="$(0.5+0.1*v_i)") + "\n"})
LG("I18_lig_inc_holds_every_run", "LIGGGHTS: a.in: e 0.8; run 1000 every 500 \"include b.in\" (b.in e 0.6); pair meets in a.in's run (0.8), first read",
   "run 1000 every 1000 \"include a.in\"\nrun 100\n", pair=LPart(2), live="a.in's run",
   data={"a.in": LEe(0.8) + "run 1000 every 500 \"include b.in\"\n", "b.in": LEe(0.6)})
LG("I19_lig_inc_np2", "LIGGGHTS processors 2 1 1: every \"include a.in\" (e 0.8); run 3000 (0.8), 1 and 2 processes",
   "run 2000 every 1000 \"include a.in\"\nrun 3000\n", pre=LBASE(head="processors 2 1 1\n"), pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I20_lig_inc_wall", "LIGGGHTS WALL: every \"include w.in\" (w.in: e 1-3 0.9); falls in the run after (0.9)",
   "run 2000 every 1000 \"include w.in\"\nrun 3000\n", pair=LWALL(2.1e-3), PAIR="type 1 on wall wprim",
   data={"w.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.9 0.5 0.4 0.45 0.9 0.45 0.8\n"})
LG("I21_lig_inc_holds_quit", "LIGGGHTS: a.in: e 0.8; run 3000; quit (the pair meets in that run: 0.8)",
   "run 1000 every 1000 \"include a.in\"\nrun 100\n", pair=LPart(2), live="a.in's run", data={"a.in": LEe(0.8) + "run 3000\n"})
LG("I22_lig_inc_then_print_file", "LIGGGHTS: every \"print 'x' file p.txt\" \"include a.in\"; run 3000 (0.8)",
   "run 2000 every 1000 \"print 'x' file p.txt\" \"include a.in\"\nrun 3000\n", pair=LPart(3), data={"a.in": LEe(0.8)})
LG("I23_lig_inc_sets_var_read_by_direct", "LIGGGHTS: e0 = 0.6; every \"include a.in\" (a.in: variable e0 equal 0.8) \"fix m3 ${e0}\": parts see 0.6 (the include not read yet); part 2 0.6",
   "variable e0 equal 0.6\nrun 3000 every 1000 \"include a.in\" \"" + LE.format(e="${e0}") + "\"\n", pair=LPart(2), live="part 2",
   data={"a.in": "variable e0 equal 0.8\n"})
LG("I24_lig_inc_next_deck_jump", "LIGGGHTS: q loop 1? a.in: next q (q loop 2): read 2 times after the run, exhausting q: the deck's jump SELF skip skipped; e 0.8; run 3000",
   "variable q loop 2\nrun 2000 every 1000 \"include a.in\"\njump SELF skip\n" + LEe(0.8) + "label skip\nrun 3000\n", pair=LPart(3), data={"a.in": "next q\n"})
LG("I25_lig_last_part_if_step", "LIGGGHTS: every 'if \"$(step) >= 3000\" then \"include a.in\"' (only after the last part); run 3000 (0.8)",
   "run 3000 every 1000 'if \"$(step) >= 3000\" then \"include a.in\"'\nrun 3000\n", pair=LPart(4), data={"a.in": LEe(0.8)})
LG("I26_lig_next_index_every", "LIGGGHTS: e index 0.6 0.7 0.8 0.9; every \"fix m3 ${e}\" \"next e\" (part 2 0.6, part 3 0.7)",
   "variable e index 0.6 0.7 0.8 0.9\nrun 4000 every 1000 \"" + LE.format(e="${e}") + "\" \"next e\"\n", pair=LPart(3), live="part 3")
LG("I27_lig_next_exhausts_skips_jump", "LIGGGHTS: a loop 2; run 2000 every \"next a\" (exhausted: the skip armed); jump SELF skip (skipped); e 0.8; label skip; run 3000 (0.8)",
   "variable a loop 2\nrun 2000 every 1000 \"next a\"\njump SELF skip\n" + LEe(0.8) + "label skip\nrun 3000\n", pair=LPart(3))

# ================================================================ R: files named by the step; reads of what skipped commands write
RS = lambda w1, w2, rd: ("run 1000\nset atom 2 density 5000\n" + w1 + "\nreset_timestep 0\nset atom 2 density 2500\n" + w2 + "\nclear\n" + rd + "\n"
                         "pair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n")
L("R01_write_restart_in_if", "run 1000; lv2 5000; if then \"write_restart r.*\" (r.1000); reset 0; 2500; write_restart r.*; read_restart r.* (LAMMPS r.1000: 0.390402)",
  RS("if \"1 > 0\" then \"write_restart r.*\"", "write_restart r.*", "read_restart r.*"), pair=IN(G11))
L("R02_write_restart_var_name", "R01 with the name from a variable: variable f string r.*; write_restart ${f}",
  "variable f string r.*\n" + RS("write_restart ${f}", "write_restart ${f}", "read_restart r.*"), pair=IN(G11))
L("R03_write_restart_loop", "a loop of 2 runs of 500, lv2 density 2500*(i+1) then write_restart r.* (r.500, r.1000); read_restart r.500 (lv2 5000)",
  "variable i loop 2\nlabel lp\nrun 500\nset atom 2 density $(2500*(v_i+1))\nwrite_restart r.*\nnext i\njump SELF lp\nclear\nread_restart r.500\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pair=IN(G11))
L("R04_write_data_in_if", "run 1000; lv2 5000; if then write_data d.*; reset 0; 2500; write_data d.0; clear; read_data d.1000 (5000)",
  "run 1000\nset atom 2 density 5000\nif \"1 > 0\" then \"write_data d.*\"\nreset_timestep 0\nset atom 2 density 2500\nwrite_data d.0\nclear\n"
  + m6.MDH.format(f="d.1000") + "run 3000\n", pair=IN(G11))
L("R05_dump_star_read_dump", "dump d.* every 500 (x v); run 1000; set lv2 velocity 0; read_dump d.1000 x y z vx vy vz (LAMMPS restores the velocities)",
  "dump dd all custom 500 d.* id type x y z vx vy vz\nrun 1000\nvelocity lv2 set 0 0 0 units box\nread_dump d.1000 1000 x y z vx vy vz\nrun 3000\n", pair=IN(G11))
L("R06_write_dump_star_read_dump", "run 1000; write_dump all custom d.* (d.1000); velocity lv2 0; read_dump d.1000 x v",
  "run 1000\nwrite_dump all custom d.* id type x y z vx vy vz\nvelocity lv2 set 0 0 0 units box\nread_dump d.1000 1000 x y z vx vy vz\nrun 3000\n", pair=IN(G11))
L("R07_restart_percent_star_stale", "restart 1000 r%.* in the run (r%.1000: r0.1000, rbase.1000); read_restart r%.1000; the folder holds stale r%.1000 files (lv2 8000)",
  "restart 1000 r%.*\nrun 1000\nclear\nread_restart r%.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("R08_restart_percent_star_nostale", "R07 without the stale files", "restart 1000 r%.*\nrun 1000\nclear\nread_restart r%.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pre=MB, pair=IN(G11))
L("R09_restart_stale_larger_step", "the folder holds a stale r.2000 (lv2 8000); write_restart r.* at step 1000; read_restart r.* (the largest: the stale r.2000 in LAMMPS too)",
  "run 1000\nwrite_restart r.*\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R10_two_stages_star", "run 1000; write_restart r.* (2500); run 500; lv2 5000; write_restart r.* (r.1500); read_restart r.1000 (2500)",
  "run 1000\nwrite_restart r.*\nrun 500\nset atom 2 density 5000\nwrite_restart r.*\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pair=IN(G(3)))
L("R11_reset_timestep_big_star", "run 1000; reset_timestep 7000; lv2 5000; write_restart r.* (r.8000? no: r.7000); read_restart r.7000",
  "run 1000\nreset_timestep 7000\nset atom 2 density 5000\nwrite_restart r.*\nclear\nread_restart r.7000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R12_write_restart_in_include", "run 1000 in an include; lv2 5000; include w.in (write_restart r.*); reset 0; 2500; write_restart r.*; read_restart r.*",
  "include r.in\nset atom 2 density 5000\ninclude w.in\nreset_timestep 0\nset atom 2 density 2500\nwrite_restart r.*\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pair=IN(G11), data={"r.in": "run 1000\n", "w.in": "write_restart r.*\n"})
L("R13_fix_print_star", "fix print 500 ... file p.* (no * substitution: a file named p.*); include p.* ? refused or read", 
  "fix fp all print 1000 \"" + PCs(5000) + "\" file p.in screen no\nrun 1000\nunfix fp\ninclude p.in\nrun 3000\n", pair=IN(G11), data={"p.in": PC3})
L("R14_restart_toggle_stale_a", "restart 500 ra rb; the folder holds a stale ra (lv2 8000); read_restart ra (LAMMPS' own: written at step 1000, 2500)",
  "restart 500 ra rb\nrun 1000\nclear\nread_restart ra\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R15_write_restart_minimize_star", "run 1000; minimize (steps unknown ahead); lv2 5000; write_restart r.*; reset 0; 2500; write r.*; read_restart r.* (the minimize's step: 5000)",
  "run 1000\nminimize 0 0 3 3\nset atom 2 density 5000\nwrite_restart r.*\nreset_timestep 0\nset atom 2 density 2500\nwrite_restart r.*\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pair=IN(G11 + 0.1e-3))
L("R16_shell_cp_restart", "run 1000; write_restart a.rst; shell cp a.rst b.rst; read_restart b.rst (the copy skips cp: refused?)",
  "run 1000\nwrite_restart a.rst\nshell cp a.rst b.rst\nclear\nread_restart b.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R17_shell_mv_restart_star", "run 1000; lv2 5000; write_restart r.*; shell mv r.1000 keep.rst; read_restart keep.rst (5000)",
  "run 1000\nset atom 2 density 5000\nwrite_restart r.*\nshell mv r.1000 keep.rst\nclear\nread_restart keep.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R18_shell_mv_restart_stale", "R17 with a stale keep.rst in the folder (lv2 8000)",
  "run 1000\nset atom 2 density 5000\nwrite_restart r.*\nshell mv r.1000 keep.rst\nclear\nread_restart keep.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R19_write_restart_upto", "run 1000; run 1500 upto (step 1500); lv2 5000; write_restart r.*; read_restart r.1500",
  "run 1000\nrun 1500 upto\nset atom 2 density 5000\nwrite_restart r.*\nclear\nread_restart r.1500\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G(3) - 0.5e-3))
L("R20_write_data_star_stale_named", "the folder holds a stale d.1000 (lv2 8000); run 1000; 5000; write_data d.*; read_data d.1000 (LAMMPS: its own, 5000)",
  "run 1000\nset atom 2 density 5000\nwrite_data d.*\nclear\n" + m6.MDH.format(f="d.1000") + "run 3000\n", pair=IN(G11))
LG("R21_lig_restart_in_if", "LIGGGHTS: run 1000; lv2 5000; if then write_restart r.*; reset 0; 2500; write_restart r.*; read_restart r.* (r.1000: the mass of 5000; hertz e 0.5 any mass: marks the file by kn? e)",
   "run 1000\n" + LEe(0.8) + "if \"1 > 0\" then \"write_restart r.*\"\nreset_timestep 0\n" + LEe(0.6) + "write_restart r.*\nclear\nread_restart r.*\n"
   "communicate single vel yes\nneighbor 0.002 bin\nneigh_modify delay 0\npair_style gran model hertz tangential history\npair_coeff * *\ntimestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 3000\n",
   pair=LIN(G11))
L("R22_restart_every_stale_star_read", "restart 1000 r.*; run 1000; read_restart r.* with a stale r.500 in the folder (LAMMPS: its own r.1000, 2500)",
  "restart 1000 r.*\nrun 1000\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R23_dump_star_include", "dump of custom text d.* then include d.1000? (LAMMPS stops: not a script); fair", "dump dd all custom 1000 d.* id\nrun 1000\nundump dd\ninclude d.1000\nrun 3000\n", pair=IN(G11))
L("R24_write_restart_star_before_run_only", "write_restart r.* at step 0 (no run before: step 0 alike), lv2 5000 after; run 1000; read r.0 (2500)",
  "write_restart r.*\nset atom 2 density 5000\nrun 1000\nclear\nread_restart r.0\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R25_write_data_in_if_stale", "R04 with a stale d.1000 in the folder (lv2 8000): run 1000; 5000; if then write_data d.*; reset 0; 2500; write_data d.0; read_data d.1000 (LAMMPS: its own, 5000)",
  "run 1000\nset atom 2 density 5000\nif \"1 > 0\" then \"write_data d.*\"\nreset_timestep 0\nset atom 2 density 2500\nwrite_data d.0\nclear\n"
  + m6.MDH.format(f="d.1000") + "run 3000\n", pair=IN(G11))
L("R26_write_restart_in_if_stale_named", "a stale r.1000 (lv2 8000); run 1000; if then write_restart r.* (LAMMPS r.1000, 2500); read_restart r.1000",
  "run 1000\nif \"1 > 0\" then \"write_restart r.*\"\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R27_write_restart_var_stale_named", "a stale r.1000 (lv2 8000); variable f string r.*; run 1000; write_restart ${f} (LAMMPS r.1000, 2500); read_restart r.1000",
  "variable f string r.*\nrun 1000\nwrite_restart ${f}\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("R28_write_restart_in_include_stale", "a stale r.1000 (lv2 8000); run 1000; include w.in (write_restart r.*); read_restart r.1000 (LAMMPS: its own, 2500)",
  "run 1000\ninclude w.in\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11), data={"w.in": "write_restart r.*\n"})
L("R29_write_dump_var_read_dump", "run 1000; variable f string d.*; write_dump all custom ${f} ... (d.1000); velocity lv2 0; read_dump d.1000 (refused?)",
  "variable f string d.*\nrun 1000\nwrite_dump all custom ${f} id type x y z vx vy vz\nvelocity lv2 set 0 0 0 units box\nread_dump d.1000 1000 x y z vx vy vz\nrun 3000\n", pair=IN(G11))
L("R30_restart_percent_var_stale", "R07 with the restart name from a variable (f string r%.*) and the stale r%.1000 files", 
  "variable f string r%.*\nrestart 1000 ${f}\nrun 1000\nclear\nread_restart r%.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
LHSp = m6.LHS.replace("fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n", "").replace("fix gravi all gravity 9.81 vector 0.0 0.0 -1.0\n", "")
LRD = "clear\natom_modify map array\nnewton off\ncommunicate single vel yes\nread_restart {f}\nneighbor 0.002 bin\n" + m6.LHSR + "timestep 1e-6\nrun 3000\n"
LG("R31_lig_restart_in_if_star", "LIGGGHTS hooke/stiffness: run 1000; lv2 5000; if then write_restart r.*; reset 0; 2500; write_restart r.0; read_restart r.* (LIGGGHTS: r.1000, 5000)",
   "run 1000\nset atom 2 density 5000\nif \"1 > 0\" then \"write_restart r.*\"\nreset_timestep 0\nset atom 2 density 2500\nwrite_restart r.0\n" + LRD.format(f="r.*"), pre=LHSp, pair=LIN(G11))
LG("R32_lig_restart_var_star", "LIGGGHTS hooke/stiffness: variable f string r.*; run 1000; 5000; write_restart ${f}; reset 0; 2500; write_restart ${f}; read_restart r.* (r.1000: 5000)",
   "variable f string r.*\nrun 1000\nset atom 2 density 5000\nwrite_restart ${f}\nreset_timestep 0\nset atom 2 density 2500\nwrite_restart ${f}\n" + LRD.format(f="r.*"), pre=LHSp, pair=LIN(G11))
LG("R33_lig_restart_cmd_stale", "LIGGGHTS hooke/stiffness: restart 1000 r.*; run 1000; read_restart r.1000 (refused: a skipped restart writes it)",
   "restart 1000 r.*\nrun 1000\n" + LRD.format(f="r.1000"), pre=LHSp, pair=LIN(G11))

# ================================================================ P: run N pre no every M; the still run after replicate
L("P01_rep_pc_preno_every_meets_part1", "run 1000; replicate; pc 5000; run 2000 pre no every 1000 \"print x\" (set up at part 1: meets there, 5000)",
  "run 1000\nreplicate 1 1 1\n" + PC5 + "run 2000 pre no every 1000 \"print P\"\n", pair=IN(G11), live="part 1")
L("P02_rep_pc_preno_preno_run", "run 1000; replicate; pc 5000; run 1000 pre no; run 1000 pre no; run 3000 (5000)",
  "run 1000\nreplicate 1 1 1\n" + PC5 + "run 1000 pre no\nrun 1000 pre no\nrun 3000\n", pair=IN(G11))
L("P03_rep_pc_preno_then_preno_every", "run 1000; replicate; pc 5000; run 1000 pre no (still); run 3000 pre no every 1000 \"print x\" (set up: 5000)",
  "run 1000\nreplicate 1 1 1\n" + PC5 + "run 1000 pre no\nrun 3000 pre no every 1000 \"print P\"\n", pair=IN(G11), live="part 1")
L("P04_preno_every_no_rep_pc", "run 1000; pc 5000; run 3000 pre no every 1000 \"print x\" (set up at part 1: 5000; meets in part 2)",
  "run 1000\n" + PC5 + "run 3000 pre no every 1000 \"print P\"\n", pair=IN(G(3)), live="part 2")
L("P05_preno_every_one_part", "run 1000; pc 5000; run 1000 pre no every 1000 \"print x\" (one part; set up: 5000)",
  "run 1000\n" + PC5 + "run 3000 pre no every 5000 \"print P\"\n", pair=IN(G11))
L("P06_preno_every_null", "run 1000; pc 5000; run 3000 pre no every 1000 NULL (set up: 5000)", "run 1000\n" + PC5 + "run 3000 pre no every 1000 NULL\n", pair=IN(G11))
L("P07_rep_exclude_preno_run", "run 1000; replicate; neigh_modify exclude type 1 2; run 1000 pre no; run 3000 (LAMMPS: no contact?)",
  "run 1000\nreplicate 1 1 1\nneigh_modify exclude type 1 2\nrun 1000 pre no\nrun 3000\n", pair=IN(G11 + 1e-3))
L("P08_rep_create_pair_preno", "replicate with no atoms? run 1000 (a far atom only); replicate; create the live pair; run 3000 pre no (does it move?); run 3000",
  "create_atoms 1 single 0.005 0.005 0.08\nset atom 1 diameter 0.004 density 2500\nrun 1000\nreplicate 1 1 1\n" +
  IN(0.1e-3).replace("set atom 1 ", "set atom 2 ").replace("set atom 2 diameter 0.006", "set atom 3 diameter 0.006").replace("group lv1 id 1", "group lv1 id 2").replace("group lv2 id 2", "group lv2 id 3") +
  "run 3000 pre no\nrun 3000\n", pair="")
L("P09_rep_restyle_preno", "run 1000; replicate; pair_style granular + pair_coeff * * kn 5000; run 1000 pre no (still); run 3000 (5000)",
  "run 1000\nreplicate 1 1 1\npair_style granular\npair_coeff * * " + HK5 + "\nrun 1000 pre no\nrun 3000\n", pair=IN(G(3)))
L("P10_rep_unfix_integ_preno", "run 1000; replicate; unfix integ; run 1000 pre no; fix integ again; run 3000", 
  "run 1000\nreplicate 1 1 1\nunfix integ\nrun 1000 pre no\nfix integ all nve/sphere\nrun 3000\n", pair=IN(G11 + 1e-3))
L("P11_rep_twice_preno", "run 1000; replicate; run 1000 pre no; replicate; pc 5000; run 1000 pre no; run 3000 (5000)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nreplicate 1 1 1\n" + PC5 + "run 1000 pre no\nrun 3000\n", pair=IN(G11 + 1e-3))
L("P12_rep_pc_preno_every_step", "run 1000; replicate; run 3000 pre no every 1000 \"pc $(2000+step)\" (set up at part 1; meets in part 2: kn 4000)",
  "run 1000\nreplicate 1 1 1\nrun 3000 pre no every 1000 \"" + STEP + "\"\n", pair=IN(G(3)), live="part 2")
LG("P13_lig_preno_every_e_changed", "LIGGGHTS: run 1000; e 0.8; run 3000 pre no every 1000 \"print x\" (set up at part 1: 0.8, meets in part 2)",
   "run 1000\n" + LEe(0.8) + "run 3000 pre no every 1000 \"print P\"\n", pair=LIN(G(3)), live="part 2")
LG("P14_lig_preno_no_every_e_changed", "LIGGGHTS: run 1000; e 0.8; run 3000 pre no (not set up: refused or 0.5)",
   "run 1000\n" + LEe(0.8) + "run 3000 pre no\n", pair=LIN(G(2)))
L("P15_rep_wall_preno_wall_deck", "WALL: run 500; replicate; unfix floor; fix floor kn 5000; run 1000 pre no (still); run 3000 (falls: 5000)",
  "run 500\nreplicate 1 1 1\nunfix floor\nfix floor all wall/gran granular " + HK5 + " zplane 0 NULL\nrun 1000 pre no\nrun 3000\n", pre=BASE(), pair=WALLP(0.0006), **WALL)
L("P16_rep_preno_upto_every", "run 1000; replicate; pc 5000; run 3000 upto pre no every 1000 \"print x\" (set up at part 1; meets in part 1: 5000)",
  "run 1000\nreplicate 1 1 1\n" + PC5 + "run 3000 upto pre no every 1000 \"print P\"\n", pair=IN(G11), live="part 1")
L("P17_rep_preno_pc_in_every_first", "run 1000; replicate; run 2000 pre no every 1000 \"pc 5000\" (set up at part 1 with 2000; part 2: 5000)",
  "run 1000\nreplicate 1 1 1\nrun 2000 pre no every 1000 \"" + PCs(5000) + "\"\n", pair=IN(G(3)), live="part 2")
L("P18_rep_dens_preno_every", "run 1000; replicate; lv2 density 5000; run 2000 pre no every 1000 \"print x\" (meets part 1: lv2 5000)",
  "run 1000\nreplicate 1 1 1\nset atom 2 density 5000\nrun 2000 pre no every 1000 \"print P\"\n", pair=IN(G11), live="part 1")

# ================================================================ F: scripts the copy may not map
LINK_MV = "shell mv new.in real.in\ninclude link.in\nrun 3000\n"
L("F01_link_target_moved", "link.in -> real.in (kn 3000); shell mv new.in real.in (kn 5000); include link.in (LAMMPS: through the link, 5000)", LINK_MV,
  data={"real.in": PC3, "new.in": PC5})
LINKS["F01"] = [("link.in", "real.in")]
L("F02_hardlink_print_append", "h.in a hard link of real.in (kn 3000); print pc 5000 append real.in; include h.in (LAMMPS: the same file, 5000)",
  'print "' + PCs(5000) + '" append real.in screen no\ninclude h.in\nrun 3000\n', data={"real.in": PC3})
HARD["F02"] = [("h.in", "real.in")]
L("F03_symlink_print_append", "link.in -> real.in (kn 3000); print pc 5000 append real.in; include link.in (LAMMPS 5000)",
  'print "' + PCs(5000) + '" append real.in screen no\ninclude link.in\nrun 3000\n', data={"real.in": PC3})
LINKS["F03"] = [("link.in", "real.in")]
L("F04_symlink_print_file_target", "link.in -> real.in (kn 3000); print pc 5000 file real.in; include link.in (LAMMPS 5000)",
  'print "' + PCs(5000) + '" file real.in screen no\ninclude link.in\nrun 3000\n', data={"real.in": PC3})
LINKS["F04"] = [("link.in", "real.in")]
L("F05_link_rm_target", "link.in -> real.in (kn 5000); shell rm real.in; include link.in (LAMMPS: a dangling link, stops)", "shell rm real.in\ninclude link.in\nrun 3000\n",
  data={"real.in": PC5})
LINKS["F05"] = [("link.in", "real.in")]
L("F06_link_replaced_by_mv", "link.in -> real.in (kn 3000); shell mv other.in link.in (5000); include link.in", "shell mv other.in link.in\ninclude link.in\nrun 3000\n",
  data={"real.in": PC3, "other.in": PC5})
LINKS["F06"] = [("link.in", "real.in")]
L("F07_dirlink_outside", "ext -> ../../shared (a folder outside the deck's); include ext/mat.in (kn 5000)", "include ext/mat.in\nrun 3000\n")
LINKS["F07"] = [("ext", "../../shared")]
L("F08_dir_moved_include", "shell mv dA dB (a folder holding pc.in kn 5000); include dB/pc.in; the top pc.in kn 3000 not read",
  "shell mv dA dB\ninclude dB/pc.in\nrun 3000\n", data={"dA/pc.in": PC5, "pc.in": PC3})
L("F09_dir_moved_unmapped_name", "shell mv dA dB (dA holds x.txt: kn 5000, named nowhere else); include dB/x.txt",
  "shell mv dA dB\ninclude dB/x.txt\nrun 3000\n", data={"dA/x.txt": PC5})
L("F10_mkdir_mv_into_dir", "shell mkdir sub; shell mv new.in sub (into the folder); include sub/new.in (5000)",
  "shell mkdir sub\nshell mv new.in sub/new.in\ninclude sub/new.in\nrun 3000\n", data={"new.in": PC5})
L("F11_cd_sub_include", "shell cd sub; include pc.in (sub/pc.in kn 5000; top pc.in 3000)", "shell cd sub\ninclude pc.in\nshell cd ..\nrun 3000\n",
  data={"sub/pc.in": PC5, "pc.in": PC3})
L("F12_cd_sub_include_dotdot", "shell cd sub; include ../pc.in (kn 5000)", "shell cd sub\ninclude ../pc.in\nshell cd ..\nrun 3000\n", data={"pc.in": PC5})
L("F13_dotdot_path_inside", "include sub/../pc.in (kn 5000)", "include sub/../pc.in\nrun 3000\n", data={"pc.in": PC5, "sub/keep.txt": "x\n"})
L("F14_absolute_tmp_include", "include /tmp/field37_abs_pc.in (kn 5000; written by make_decks37.py)", "include /tmp/field37_abs_pc.in\nrun 3000\n")
L("F15_if_shell_mv_include", "if then \"shell mv new.in pc.in\"; include pc.in (5000; a stale pc.in 3000)", "if \"1 > 0\" then \"shell mv new.in pc.in\"\ninclude pc.in\nrun 3000\n",
  data={"pc.in": PC3, "new.in": PC5})
L("F16_every_shell_mv_include", "run 1000 every 1000 \"shell mv new.in pc.in\"; include pc.in; run 3000 (5000; a stale pc.in 3000)",
  "run 1000 every 1000 \"shell mv new.in pc.in\"\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3, "new.in": PC5})
L("F17_include_shell_mv_in_file", "include m.in (m.in: shell mv new.in pc.in); include pc.in (5000; stale 3000)", "include m.in\ninclude pc.in\nrun 3000\n",
  data={"pc.in": PC3, "new.in": PC5, "m.in": "shell mv new.in pc.in\n"})
L("F18_var_name_mv", "variable f string pc.in; shell mv new.in ${f}; include ${f} (5000; stale 3000)", "variable f string pc.in\nshell mv new.in ${f}\ninclude ${f}\nrun 3000\n",
  data={"pc.in": PC3, "new.in": PC5})
L("F19_case_differs", "include PC.in where the folder holds pc.in only (Linux: LAMMPS stops)", "include PC.in\nrun 3000\n", data={"pc.in": PC5})
L("F20_big_by_variable", "variable f string big.in; include ${f} (22 MB: comments then kn 5000; big.in written by make_decks37.py, not committed)",
  "variable f string big.in\ninclude ${f}\nrun 3000\n")
L("F21_big_through_link", "include link.in -> big.in (22 MB; kn 5000 at its end)", "include link.in\nrun 3000\n")
LINKS["F21"] = [("link.in", "big.in")]
JB = "jump in.deck back\n"
L("F22_jump_moved_file", "shell mv new.in j.in; jump j.in (j.in: kn 5000, run 3000, jump back to the deck's label back)", "shell mv new.in j.in\njump j.in\nlabel back\n",
  data={"new.in": PC5 + "run 3000\n" + JB})
L("F23_link_chain", "a.in -> b.in -> real.in (kn 5000); include a.in", "include a.in\nrun 3000\n", data={"real.in": PC5})
LINKS["F23"] = [("b.in", "real.in"), ("a.in", "b.in")]
L("F24_shell_mv_link_itself", "shell mv link.in x.in (a link to real.in, kn 5000); include x.in", "shell mv link.in x.in\ninclude x.in\nrun 3000\n", data={"real.in": PC5})
LINKS["F24"] = [("link.in", "real.in")]
L("F25_shell_rm_then_mv_link", "link.in -> real.in (3000); include link.in; run 1000; shell rm link.in; shell mv other.in link.in (5000); include link.in; run 3000",
  "include link.in\nrun 1000\nshell rm link.in\nshell mv other.in link.in\ninclude link.in\nrun 3000\n", pair=IN(G11), data={"real.in": PC3, "other.in": PC5})
LINKS["F25"] = [("link.in", "real.in")]
L("F26_dirlink_inside_mv_target", "sub -> real_sub (a folder link); shell mv new.in real_sub/pc.in; include sub/pc.in (5000; a stale real_sub/pc.in 3000)",
  "shell mv new.in real_sub/pc.in\ninclude sub/pc.in\nrun 3000\n", data={"real_sub/pc.in": PC3, "new.in": PC5})
LINKS["F26"] = [("sub", "real_sub")]
L("F27_cd_sub_mv_dotdot", "shell cd sub; shell mv ../new.in ../pc.in; shell cd ..; include pc.in (5000; stale 3000)",
  "shell cd sub\nshell mv ../new.in ../pc.in\nshell cd ..\ninclude pc.in\nrun 3000\n", data={"pc.in": PC3, "new.in": PC5, "sub/keep.txt": "x\n"})
LG("F28_lig_link_target_moved", "LIGGGHTS: link.in -> real.in (e 0.6); shell mv new.in real.in (0.8); include link.in", LINK_MV, data={"real.in": LEe(0.6), "new.in": LEe(0.8)})
LINKS["F28"] = [("link.in", "real.in")]
LG("F29_lig_hardlink_print_append", "LIGGGHTS: h.in hard link of real.in (e 0.6); print e 0.8 append real.in; include h.in (0.8)",
   'print "' + LE.format(e="0.8") + '" append real.in screen no\ninclude h.in\nrun 3000\n', data={"real.in": LEe(0.6)})
HARD["F29"] = [("h.in", "real.in")]
L("F30_symlink_write_coeff_target", "link.in -> wc.in (stale kn 3000); pc 5000; write_coeff wc.in; pair_coeff * * 2000; include link.in (LAMMPS 5000)",
  PC5 + "write_coeff wc.in\npair_coeff * * " + HK + "\ninclude link.in\nrun 3000\n", data={"wc.in": PC3})
LINKS["F30"] = [("link.in", "wc.in")]
L("F31_link_to_mv_source", "link.in -> new.in (kn 5000); shell mv new.in gone.in; include link.in (LAMMPS: dangling, stops)", "shell mv new.in gone.in\ninclude link.in\nrun 3000\n",
  data={"new.in": PC5})
LINKS["F31"] = [("link.in", "new.in")]
L("F32_hardlink_fix_print", "h.in a hard link of p.in (stale 3000); fix print 1000 pc 5000 file p.in in run 1; include h.in; run 3000 (5000)",
  'fix fp all print 1000 "' + PCs(5000) + '" file p.in screen no title "# p"\nrun 1000\nunfix fp\ninclude h.in\nrun 3000\n', pair=IN(G11), data={"p.in": PC3})
HARD["F32"] = [("h.in", "p.in")]
L("F33_molecule_after_mv", "shell mv big.mol s.mol (a 6 mm sphere); molecule s s.mol; create_atoms 2 single ... mol s (the folder's s.mol: 3 mm)",
  "shell mv b.mol s.mol\nmolecule sm s.mol\ncreate_atoms 2 single 0.0235 0.02 0.05 mol sm 4567\ngroup lv2 type 2\nvelocity lv2 set " + f"{m.V2:.10f}" + " 0 0 units box\nrun 3000\n",
  pair="create_atoms 1 single 0.0179500 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set " + f"{m.V1:.10f}" + " 0 0 units box\n",
  pre=BASE(wall=False, head="atom_modify map array\n"),
  data={"s.mol": "# 3 mm\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.003\n\nMasses\n\n1 3.534e-5\n",
        "b.mol": "# 6 mm\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 2.82743e-4\n"})
L("F34_read_data_after_mv_stale", "shell mv new.data d.data (lv2 5000); read_data d.data; a stale d.data (lv2 8000) in the folder",
  "", pre="", pair=m6.MDH.replace("read_data {f}", "shell mv new.data d.data\nread_data d.data") + "run 3000\n")
GEN["F34"] = "data"

L("F35_every_print_file_include", "run 1000 every 500 \"print 'pc 5000' file pc.in\" (after each part); include pc.in (a stale pc.in 3000; LAMMPS 5000)",
  "run 1000 every 500 \"print '" + PCs(5000) + "' file pc.in screen no\"\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3})
L("F36_every_shell_cp_include", "run 1000 every 1000 \"shell cp new.in pc.in\"; include pc.in (stale 3000; LAMMPS 5000)",
  "run 1000 every 1000 \"shell cp new.in pc.in\"\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3, "new.in": PC5})
LG("F37_lig_every_shell_mv_include", "LIGGGHTS: run 1000 every 1000 \"shell mv new.in m.in\"; include m.in (stale e 0.6; LIGGGHTS 0.8)",
   "run 1000 every 1000 \"shell mv new.in m.in\"\ninclude m.in\nrun 3000\n", pair=LIN(G11), data={"m.in": LEe(0.6), "new.in": LEe(0.8)})
L("F38_every_write_coeff_include", "pc 5000; run 1000 every 1000 \"write_coeff wc.in\"; pair_coeff * * 2000; include wc.in (stale 3000; LAMMPS 5000)",
  PC5 + "run 1000 every 1000 \"write_coeff wc.in\"\npair_coeff * * " + HK + "\ninclude wc.in\nrun 3000\n", pair=IN(G11), data={"wc.in": PC3})
L("F39_every_shell_mv_split", "run 2000 every 1000 \"shell mv new.in pc.in\" \"pc $(2000+step)\" (split: part 2 kn 3000); include pc.in after (5000; stale 3000 ... the mv runs after part 1)",
  "run 2000 every 1000 \"shell mv new.in pc.in\" \"" + STEP + "\"\ninclude pc.in\nrun 3000\n", pair=IN(G(3)), data={"pc.in": PC3, "new.in": PC5})
L("F40_print_file_jump", "print pc 5000 file j.in; print run 3000 append j.in; jump j.in (a stale j.in: kn 3000, run 3000)",
  'print "' + PCs(5000) + '" file j.in screen no\nprint "run 3000" append j.in screen no\nprint "jump in.deck back" append j.in screen no\njump j.in\nlabel back\n', data={"j.in": PC3 + "run 3000\n" + JB})
L("F41_shell_mv_jump_stale", "shell mv new.in j.in (kn 5000 + run 3000); jump j.in; a stale j.in (3000 + run 3000)", "shell mv new.in j.in\njump j.in\nlabel back\n",
  data={"j.in": PC3 + "run 3000\n" + JB, "new.in": PC5 + "run 3000\n" + JB})
L("F42_jump_big_file", "jump big.in (22 MB: comments, then kn 5000 and run 3000; written by make_decks37.py, not committed)", "jump big.in\nlabel back\n")
L("F43_include_in_if_after_mv", "shell mv new.in pc.in; if then \"include pc.in\" (5000; stale 3000)", "shell mv new.in pc.in\nif \"1 > 0\" then \"include pc.in\"\nrun 3000\n",
  data={"pc.in": PC3, "new.in": PC5})
L("F44_shell_cp_jump", "shell cp new.in j.in (kn 5000 + run 3000); jump j.in (stale j.in 3000)", "shell cp new.in j.in\njump j.in\nlabel back\n",
  data={"j.in": PC3 + "run 3000\n" + JB, "new.in": PC5 + "run 3000\n" + JB})
L("F45_include_jump_moved_inside_include", "include a.in where a.in: shell mv new.in j.in; jump j.in (j.in kn 5000, then the deck's run: jump ends a.in)",
  "include a.in\nrun 3000\n", data={"a.in": "shell mv new.in j.in\njump j.in\n", "new.in": PC5})
L("F46_write_data_read_through_link", "link.data -> d.data (a stale d.data: lv2 8000); run 1000; lv2 5000; write_data d.data; clear; read_data link.data (LAMMPS: the new file, 5000)",
  "run 1000\nset atom 2 density 5000\nwrite_data d.data\nclear\n" + m6.MDH.format(f="link.data") + "run 3000\n", pair=IN(G11))
LINKS["F46"] = [("link.data", "d.data")]
L("F47_write_restart_read_through_link", "link.rst -> a.rst (a stale a.rst: lv2 8000); run 1000; write_restart a.rst (2500); clear; read_restart link.rst (LAMMPS 2500)",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart link.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pair=IN(G11))
LINKS["F47"] = [("link.rst", "a.rst")]
L("F48_jump_deck_by_name_loop", "a loop by jump in.deck lp (the deck names itself): 2 passes of run 1000, kn 3000 then 5000 (the pair meets in pass 2: 5000)",
  "variable i loop 2\nlabel lp\n" + PCs("$(1000+2000*v_i)") + "\nrun 1000\nnext i\njump in.deck lp\n", pair=IN(G11), live="pass 2")
L("F49_variable_file_through_link", "k.txt -> real.txt (3000); print 5000 file real.txt; variable k file k.txt; kn ${k} (LAMMPS 5000)",
  'print "5000" file real.txt screen no\nvariable k file k.txt\n' + PCs("${k}") + "\nrun 3000\n", data={"real.txt": "3000\n"})
LINKS["F49"] = [("k.txt", "real.txt")]

# ================================================================ K V Q Y W S T: the nine classes, fresh variants
B3 = BASE(nt=3, wall=False)
PCk = lambda spec, k: f"pair_coeff {spec} " + HKk(k) + "\n"
L("K01_range_1x3_star", "pair_coeff 1*3 * kn 5000 then pair_coeff 2 3 kn 3000 (1 2: 5000)", PCk("1*3 *", 5000) + PCk("2 3", 3000) + "run 3000\n", pre=B3)
L("K02_range_star_lo", "pair_coeff *1 2* kn 5000 (1 2 and 1 3): 5000", PCk("*1 2*", 5000) + "run 3000\n", pre=B3)
L("K03_label_range_mix", "labelmap atom 1 s 2 b 3 r; pair_coeff s 2*3 kn 4000 (1 2 = 4000)", "labelmap atom 1 s 2 b 3 r\n" + PCk("s 2*3", 4000) + "run 3000\n", pre=B3)
L("K04_label_then_numeric_override", "labelmap; pair_coeff b s kn 5000; pair_coeff 1 2 kn 3000 (3000)", "labelmap atom 1 s 2 b\n" + PCk("b s", 5000) + PCk("1 2", 3000) + "run 3000\n")
L("K05_range_reverse_star", "pair_coeff 2* *1 kn 5000 (i > j everywhere: LAMMPS? 1 2 swapped? or nothing)", PCk("2* *1", 5000) + "run 3000\n", pre=B3)
L("K06_label_quoted", "labelmap atom 1 'a b'? no: labelmap atom 2 big; pair_coeff \"big\" 1 kn 5000", "labelmap atom 2 big\npair_coeff \"big\" 1 " + HKk(5000) + "\nrun 3000\n")
L("K07_range_var", "variable t equal 2; pair_coeff 1 ${t}*3 kn 4000 (1 2)", "variable t equal 2\n" + PCk("1 ${t}*3", 4000) + "run 3000\n", pre=B3)
L("K08_types_retyped_label", "labelmap atom 1 s 2 b; set atom 1 type b; pc 2 2 kn 5000 (the live pair 2 2)", "labelmap atom 1 s 2 b\nset atom 1 type b\n" + PCk("2 2", 5000) + "run 3000\n", PAIR="types 2 2")
L("V01_fmt_g", "k = 4999.9 printed with %.3g: 5e+03 (5000)", "variable kk equal 4999.9\nvariable k format kk %.3g\n" + PCs("${k}") + "\nrun 3000\n")
L("V02_round_in_dollar", "kn $(1000*round(3.5)+500) (round half away: 4500)", PCs("$(1000*round(3.5)+500)") + "\nrun 3000\n")
L("V03_15g_large", "a = 3000.0000000000005; kn ${a} at %.15g (3000)", "variable a equal 3000.0000000000005\n" + PCs("${a}") + "\nrun 3000\n")
L("V04_if_15g_equal", "a = 0.1+0.2; if \"${a} == 0.3\" (at %.15g: true) then kn 5000 else 3000", "variable a equal 0.1+0.2\nif \"${a} == 0.3\" then \"" + PCs(5000) + "\" else \"" + PCs(3000) + "\"\nrun 3000\n")
L("V05_immediate_fmt_int", "kn $(4999.5:%.0f) (5000? printf banker: 4999.5 -> 5000 even? 4999.5 -> 5000)", PCs("$(4999.5:%.0f)") + "\nrun 3000\n")
L("V06_round_negative", "kn 5000+1000*round(-1.5) (away from zero: -2: 3000)", "variable k equal 5000+1000*round(-1.5)\n" + PCs("${k}") + "\nrun 3000\n")
L("V07_format_then_math", "variable kk equal 2499.96; k format kk %.1f (2500.0); kn $(2*v_k)? (v_k of a format: 4999.9? )", "variable kk equal 2499.96\nvariable k format kk %.1f\n" + PCs("$(2*${k})") + "\nrun 3000\n")
L("Q01_set_diameter_type_then_atom_density", "set type 2 diameter 0.006; set atom 2 density 5000; set type 2 diameter 0.006 again (mass kept at 5000)",
  "set type 2 diameter 0.006\nset atom 2 density 5000\nset type 2 diameter 0.006\nrun 3000\n")
L("Q02_density_area", "set atom 2 density/disc? no: set atom 2 mass 2.82743e-4*2 (mass doubled: 5000-equivalent)", "set atom 2 mass 5.65487e-4\nrun 3000\n")
L("Q03_set_group_region_order", "region right x > 0.021; set region right density 5000 (lv2); then set atom 2 diameter 0.006 (mass kept)",
  "region rr block 0.021 0.04 0 0.04 0 0.1 units box\nset region rr density 5000\nset atom 2 diameter 0.006\nrun 3000\n")
L("Q04_set_type_after_pc", "pair_coeff 2 3 kn 5000; set atom 2 type 3 (the pair 1 3: kn 2000) ... pc 1 3 4000", PCk("2 3", 5000) + PCk("1 3", 4000) + "set atom 2 type 3\nrun 3000\n", pre=B3, PAIR="types 1 3")
L("Y01_restyle_hybrid_granular", "pair_style hybrid granular? no: pair_style granular then gran/hooke/history then granular again with 1 1 2 2 only (mixed 2000)",
  "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\npair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK5 + "\nrun 3000\n")
L("Y02_restyle_between_runs", "run 1000; pair_style gran/hooke 5000 NULL 3000 NULL 0.3 0; run 3000 (5000)", "run 1000\npair_style gran/hooke 5000 NULL 3000 NULL 0.3 0\npair_coeff * *\nrun 3000\n", pair=IN(G11))
LG("Y03_lig_limitforce_e_low_wall", "LIGGGHTS WALL limitForce on, e 1-3 0.1", "run 3000\n",
   pre=LBASE(e="0.6 0.5 0.1 0.5 0.4 0.45 0.1 0.45 0.8").replace("tangential history\npair_coeff", "tangential history limitForce on\npair_coeff").replace("model hertz tangential history primitive", "model hertz tangential history limitForce on primitive"),
   pair=LWALL(1e-4), PAIR="type 1 on wall wprim")
LG("Y04_lig_limitforce_off_explicit", "LIGGGHTS hertz limitForce off (explicit), e 0.2", "run 3000\n",
   pre=LBASE(e="0.6 0.2 0.7 0.2 0.4 0.45 0.7 0.45 0.8").replace("tangential history\npair_coeff", "tangential history limitForce off\npair_coeff"))
LG("Y05_lig_limitforce_hooke", "LIGGGHTS hooke limitForce on, e 0.15 (characteristicVelocity 1)", "run 3000\n",
   pre=LBASE(model="hooke", e="0.6 0.15 0.7 0.15 0.4 0.45 0.7 0.45 0.8", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n").replace("tangential history\npair_coeff", "tangential history limitForce on\npair_coeff"))
LG("W01_lig_wall_type2_of_3_unused_in_pair", "LIGGGHTS WALL: walls type 2 (spheres type 1 only); e 1-2 0.65", "run 3000\n",
   pre=LBASE(e="0.6 0.65 0.7 0.65 0.4 0.45 0.7 0.45 0.8").replace("primitive type 3", "primitive type 2"), pair=LWALL(1e-4), PAIR="type 1 on wall wprim")
L("W02_lammps_wall_granular_kn5000", "LAMMPS WALL: the floor kn 5000 given again (fix floor re-made)", "unfix floor\nfix floor all wall/gran granular " + HK5 + " zplane 0 NULL\nrun 3000\n",
  pre=BASE(), pair=WALLP(), **WALL)
L("W03_lammps_wall_region", "LAMMPS WALL: wall/gran/region on a block region (hooke kn 4000)", "run 3000\n",
  pre=BASE(wall=False) + "region flr block 0 0.04 0 0.04 0 0.05 side out units box\nfix floor all wall/gran/region granular " + HKk(4000) + " region flr\n", pair=WALLP(), **WALL)
L("W05_lammps_wall_region_side_in", "LAMMPS WALL: wall/gran/region on the box's block region, side in (hooke kn 4000): the sphere falls on its bottom face", "run 3000\n",
  pre=BASE(wall=False) + "region flr block 0 0.04 0 0.04 0 0.1 side in units box\nfix floor all wall/gran/region granular " + HKk(4000) + " region flr\n", pair=WALLP(), **WALL)
L("S01_create_two_sizes_type2", "a far type 2 sphere of 8 mm (type 2 sizes 6 and 8 mm)", "create_atoms 2 single 0.005 0.005 0.08\nset atom 3 diameter 0.008 density 2500\nrun 3000\n")
L("S02_pour_type2_range", "fix pour type 2 diam range 0.005 0.007 + the 6 mm lv2", m6.POUR("diam range 0.005 0.007").replace(" 1 4767548", " 2 4767548") + "run 3000\n")
L("S03_set_type_diameter_random", "set type 1 diameter then a far type 1 of 3 mm and density 1000: sizes and masses", "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.003 density 1000\nrun 3000\n")
L("T01_dt3e-5_wall", "WALL dt 3e-5 (few steps)", m6.TD(3e-5, 2000, wall=True)[1], pre=m6.TD(3e-5, 2000, wall=True)[0], pair=WALLP(0.11e-3), **WALL)
L("T02_dt1.2e-4_kn4000", "dt 1.2e-4 kn 4000", m6.TD(1.2e-4, 4000, 0.21e-3)[1], pre=m6.TD(1.2e-4, 4000, 0.21e-3)[0], pair=IN(0.21e-3))
LG("T03_lig_dt4e-5", "LIGGGHTS hertz e 0.5 dt 4e-5", "run 300\n", pre=LBASE().replace("timestep 1e-6", "timestep 4e-5"), pair=LIN(0.13e-3))
L("T04_dt_changed_in_every", "run 2000 every 1000 \"timestep 8e-5\" (the pair meets in part 2 at dt 8e-5)", "run 2000 every 1000 \"timestep 8e-5\"\n", pair=IN(1.1e-3 + 60 * 8e-5), live="part 2")

L("V08_round_tie_literal", "kn 1000*round(4.4999999999999999) (the literal is 4.5 in double: 5000)", PCs("$(1000*round(4.4999999999999999))") + "\nrun 3000\n")
L("V09_ternary", "variable k equal ternary(1>0,5000,3000)", "variable k equal ternary(1>0,5000,3000)\n" + PCs("${k}") + "\nrun 3000\n")
L("V10_logical_sum", "kn 2000*(1+(2>1)) (4000)", PCs("$(2000*(1+(2>1)))") + "\nrun 3000\n")
L("V11_string_quoted", "variable k string \"4000\" (quoted)", "variable k string \"4000\"\n" + PCs("${k}") + "\nrun 3000\n")
L("V12_immediate_fmt_3f", "kn $(4999.9996:%.3f) (5000.000)", PCs("$(4999.9996:%.3f)") + "\nrun 3000\n")
L("V13_index_next_before", "variable k index 3000 5000; next k; kn ${k} (5000)", "variable k index 3000 5000\nnext k\n" + PCs("${k}") + "\nrun 3000\n")
L("V14_equal_15g_roundtrip", "a = 1/3*15000 (4999.999999999999); b = ${a} (5000 at %.15g); if b == 5000 then kn 5000 else 3000",
  "variable a equal 1/3*15000\nvariable b equal ${a}\nif \"${b} == 5000\" then \"" + PCs(5000) + "\" else \"" + PCs(3000) + "\"\nrun 3000\n")
L("Q05_set_density_then_diameter_type", "set type 2 density 5000 (6 mm) then set type 2 diameter 0.006 again (mass kept)", "set type 2 density 5000\nset type 2 diameter 0.006\nrun 3000\n")
L("Q06_set_one_command_order", "set atom 2 density 5000 diameter 0.006 (one command: density first)", "set atom 2 density 5000 diameter 0.006\nrun 3000\n")
L("Q07_set_all_density_then_diameter_bigger", "set group all density 2500; set atom 2 diameter 0.008 (mass kept at 6 mm's? the contact at 8 mm)", "set group all density 2500\nset atom 2 diameter 0.008\nrun 3000\n",
  pair=IN(0.1e-3).replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.024050"))
LG("Y06_lig_restyle_hooke_stiffness", "LIGGGHTS: restyle to hooke/stiffness (kn 2000 gamman 500 typed), e ignored", "run 3000\n", pre=m6.LHS)
LG("Y07_lig_e_from_variable_later", "LIGGGHTS: e given again from a variable set after (0.75)", "variable ee equal 0.75\n" + LE.format(e="${ee}") + "\nrun 3000\n")
L("S04_pour_type2_poly", "fix pour type 2 diam poly 2 0.005 0.5 0.007 0.5 + the 6 mm lv2", m6.POUR("diam poly 2 0.005 0.5 0.007 0.5").replace(" 1 4767548", " 2 4767548") + "run 3000\n")
LG("S05_lig_templates_type2_range", "LIGGGHTS: type 2 inserted with radii 2 and 4 mm (the 3 mm lv2 between), hertz e 0.5", m6.INS(0.002, 0.004).replace("atom_type 1", "atom_type 2") + "run 3000\n")
LG("T05_lig_hooke_dt6e-5", "LIGGGHTS hooke (characteristicVelocity 1) e 0.5 at dt 6e-5", "run 300\n",
   pre=LBASE(model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n").replace("timestep 1e-6", "timestep 6e-5"), pair=LIN(0.13e-3))
LG("W04_lig_wall_xplane_type2", "LIGGGHTS WALLX: an xplane wall of type 2 only (e 1-2 0.5 ... the pair 1-2 e 0.5; the wall 0.65)", "run 3000\n",
   pre=LBASE(e="0.6 0.65 0.7 0.65 0.4 0.45 0.7 0.45 0.8").replace("primitive type 3 zplane 0.0", "primitive type 2 xplane 0.0"),
   pair="create_atoms 1 single 0.0021 0 0.1 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set -0.9990185184 0 0\nfix nog all gravity 9.81 vector 0 0 -1\n",
   PAIR="type 1 on wall wprim", WALLX="")
L("P19_rep_preno_every_null_meets", "run 1000; replicate; pc 5000; run 2000 pre no every 1000 NULL (set up at part 1: meets there, 5000)",
  "run 1000\nreplicate 1 1 1\n" + PC5 + "run 2000 pre no every 1000 NULL\n", pair=IN(G11), live="part 1")
LG("P20_lig_first_run_preno_every_e", "LIGGGHTS: e 0.8 before the first run, run 3000 pre no every 1000 \"fix m3 e 0.7\" (part 1 0.8; part 2 0.7)",
   LEe(0.8) + "run 3000 pre no every 1000 \"" + LE.format(e="0.7") + "\"\n", pair=LIN(G(2)), live="part 2")
L("N18_next_every_skip_consumed_by_if_jump", "a loop 2; run 2000 every \"next a\" (armed); if then \"jump SELF skip\" (the skip consumed there); pc 5000; label skip; run 3000 (5000)",
  "variable a loop 2\nrun 2000 every 1000 \"next a\"\nif \"1 > 0\" then \"jump SELF skip\"\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)))
L("N19_next_every_skip_consumed_in_include", "a loop 2; run 2000 every \"next a\" (armed); include j.in (j.in: jump SELF e, which is skipped; pc 4000; label e); run 3000 (4000)",
  "variable a loop 2\nrun 2000 every 1000 \"next a\"\ninclude j.in\nrun 3000\n", pair=IN(G(3)), data={"j.in": "jump SELF e\n" + PC4 + "label e\n"})
L("N20_next_every_then_next_deck_exhaust", "a loop 2, b loop 1; run 2000 every \"next a\" (armed); next b (exhausts too); jump SELF skip (skipped); pc 5000; label skip; run 3000",
  "variable a loop 2\nvariable b loop 1\nrun 2000 every 1000 \"next a\"\nnext b\njump SELF skip\n" + PC5 + "label skip\nrun 3000\n", pair=IN(G(3)))

# ================================================================ O: public decks, shortened (sources in FINDINGS.md and each file's head)
OD = os.path.join(HERE, "odecks")
OMETA = {"O01_siddhant_pour_2d": {"PAIR": "types 2 3"}, "O02_siddhant_compress_loop_2d": {"PAIR": "types 2 3"},
         "O03_sungwonla_pouring_star_files": {"PAIR": "types 2 3"}, "O04_sungwonla_shearing_jkr": {"PAIR": "types 2 3"},
         "O05_haydnrogan_sphere_impact_cgs": {"PAIR": "types 2 4", "SEP": "2.0"}, "O06_caesar_simple_drop_lig": {"PAIR": "types 1 1", "LIGGGHTS": ""},
         "O07_caesar_random_diameter_lig": {"PAIR": "types 1 1", "LIGGGHTS": ""}, "O08_caesar_drop_on_mesh_lig": {"PAIR": "type 1 on wall walls", "LIGGGHTS": ""}}
STL = ("solid ground\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 10 0 0\n   vertex 10 10 0\n  endloop\n endfacet\n"
       " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 10 10 0\n   vertex 0 10 0\n  endloop\n endfacet\nendsolid ground\n")
for n, meta in OMETA.items():
    DECKS[n] = (open(os.path.join(OD, n[:3] + ".in")).read(), "last run", {"10x10m-ground.stl": STL} if n.startswith("O08") else {}, meta)

# ================================================================ write
def big(path, tail=""):
    with open(path, "w") as f:
        f.write(("# " + "x" * 98 + "\n") * 220000 + PCs(5000) + "\n" + tail)


def lmp_gen(text, outs, d):
    t = tempfile.mkdtemp()
    open(os.path.join(t, "g.in"), "w").write(text)
    subprocess.run(["lmp", "-in", "g.in", "-log", "none"], cwd=t, capture_output=True)
    for o, n in outs:
        os.replace(os.path.join(t, o), os.path.join(d, n))
    shutil.rmtree(t)


D8000 = RB + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")


def write(only=()):
    for name, (text, live, data, meta) in sorted(DECKS.items()):
        if only and not any(name.startswith(p) for p in only):
            continue
        d = os.path.join(D, name)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(text)
        open(os.path.join(d, "DECK"), "w").write("in.deck\n")
        open(os.path.join(d, "G"), "w").write("1\n")
        open(os.path.join(d, "LIVE"), "w").write(("WALL " if "PAIR" in meta and "wall" in meta["PAIR"] else "") + live + "\n")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + "\n")
        for f, t in data.items():
            p = os.path.join(d, f)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            open(p, "w").write(t)
        k3 = name[:3]
        for a, b in LINKS.get(k3, []):
            if not os.path.lexists(os.path.join(d, a)):
                os.symlink(b, os.path.join(d, a))
        for a, b in HARD.get(k3, []):
            if not os.path.exists(os.path.join(d, a)):
                os.link(os.path.join(d, b), os.path.join(d, a))
            open(os.path.join(d, "HARDLINKS"), "w").write("".join(f"{x} {y}\n" for x, y in HARD[k3]))
        if k3 in ("F20", "F21", "F42") and not os.path.exists(os.path.join(d, "big.in")):
            big(os.path.join(d, "big.in"), "run 3000\n" + JB if k3 == "F42" else "")
        if k3 == "R07" and not os.path.exists(os.path.join(d, "rbase.1000")):
            lmp_gen(MB + IN(G11).replace("density 2500\ngroup lv1", "density 2500\ngroup lv1").replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")
                    + "run 1000\nwrite_restart r%.*\n", [("rbase.1000", "rbase.1000"), ("r0.1000", "r0.1000")], d)
        if k3 == "F46" and not os.path.exists(os.path.join(d, "d.data")):
            lmp_gen(D8000 + "run 1000\nwrite_data d.data\n", [("d.data", "d.data")], d)
        if k3 == "F47" and not os.path.exists(os.path.join(d, "a.rst")):
            lmp_gen(D8000 + "run 1000\nwrite_restart a.rst\n", [("a.rst", "a.rst")], d)
        if k3 in ("R25",) and not os.path.exists(os.path.join(d, "d.1000")):
            lmp_gen(D8000 + "run 1000\nwrite_data d.1000\n", [("d.1000", "d.1000")], d)
        if k3 in ("R26", "R27", "R28") and not os.path.exists(os.path.join(d, "r.1000")):
            lmp_gen(D8000 + "run 1000\nwrite_restart r.*\n", [("r.1000", "r.1000")], d)
        if k3 == "R30" and not os.path.exists(os.path.join(d, "rbase.1000")):
            lmp_gen(MB + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")
                    + "run 1000\nwrite_restart r%.*\n", [("rbase.1000", "rbase.1000"), ("r0.1000", "r0.1000")], d)
        if k3 == "R09" and not os.path.exists(os.path.join(d, "r.2000")):
            lmp_gen(D8000 + "run 2000\nwrite_restart r.*\n", [("r.2000", "r.2000")], d)
        if k3 == "R14" and not os.path.exists(os.path.join(d, "ra")):
            lmp_gen(D8000 + "run 1000\nwrite_restart ra\n", [("ra", "ra")], d)
        if k3 == "R18" and not os.path.exists(os.path.join(d, "keep.rst")):
            lmp_gen(D8000 + "run 1000\nwrite_restart keep.rst\n", [("keep.rst", "keep.rst")], d)
        if k3 == "R20" and not os.path.exists(os.path.join(d, "d.1000")):
            lmp_gen(D8000 + "run 1000\nwrite_data d.1000\n", [("d.1000", "d.1000")], d)
        if k3 == "R22" and not os.path.exists(os.path.join(d, "r.500")):
            lmp_gen(D8000 + "run 500\nwrite_restart r.*\n", [("r.500", "r.500")], d)
        if k3 == "F34" and not os.path.exists(os.path.join(d, "d.data")):
            lmp_gen(D8000.replace("density 8000", "density 5000") + "write_data new.data\n", [("new.data", "new.data")], d)
            lmp_gen(D8000 + "write_data d.data\n", [("d.data", "d.data")], d)
        if k3 == "O02" and not os.path.exists(os.path.join(d, "Original_data.pour")):
            txt = open(os.path.join(OD, "O01.in")).read().split("create_atoms     2 single")[0]
            lmp_gen(txt + "run 3000\nwrite_data Original_data.pour\n", [("Original_data.pour", "Original_data.pour")], d)
        if k3 == "O04" and not os.path.exists(os.path.join(d, "packing-3000.restart")):
            lmp_gen(open(os.path.join(OD, "O03.in")).read(), [("packing-3000.restart", "packing-3000.restart")], d)
    if not os.path.exists("/tmp/field37_abs_pc.in"):
        open("/tmp/field37_abs_pc.in", "w").write(PC5)
    print(len(DECKS), "decks")


if __name__ == "__main__":
    write(sys.argv[1:])
