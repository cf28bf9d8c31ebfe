"""Field round 45 ("hidden decks"): write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's
live37.py: each deck AS WRITTEN, its live pair's eps printed after its last line) and the audit. The public decks
(R family) are copied in at run time by pubdecks45.py (their text is not committed). Families here:
- O: the issue's original classes in combinations not tried before: `$(expr:%fmt)` and `%.Ng` into pair_coeff / if /
  loops, pair_coeff ranges and type labels on 5 types, set with v_ variables, mass then diameter, variable restyles
  (index given again, delete + equal, internal, format, file, universe/uloop), odd if comparisons, LAMMPS units cgs,
  several sizes per type with hertz, e = 1.0, region and cylinder walls (hertz: a curved wall), hybrid/scaled,
  fix viscous/langevin/setforce/nve/limit/freeze/adapt/spring/self/temp/rescale/lineforce/momentum from the start,
  coarse time steps, LIGGGHTS walls-only types and templates;
- B: changes between runs (and in a run's every) that the between-runs rule may miss: a group an exclusion names
  (neigh_modify exclude group, include), a molecule ID an exclusion reads (`set mol`), special_bonds with a bond
  between the pair, a region whose shape follows a variable (sphere centre v_cx: no `move` keyword) under a wall or a
  setforce, a dynamic group an exclusion names, a group function (gmask) in a force's atom-style variable;
- H: harmless controls (between runs and from the start) that must get no note.
The pair meets at step 100 and a contact lasts about 586 steps, so `run 300; X; run 2000` changes X mid-contact and
`run 50; X; run 3000` before the meeting. Helpers are rounds 35-44's (make_decks44.py imported; its decks are not
written). LAMMPS controls (round 37): kn 2000 0.413435, the floor 0.361743; LIGGGHTS e 0.5 0.499928.
usage: python make_decks45.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field44"))
import make_decks44 as m44  # noqa: E402

m7, m41, m43 = m44.m7, m44.m41, m44.m43
m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG = m7.L, m7.LG
S, B, SW, SG, BG = m41.S, m41.B, m41.SW, m41.SG, m41.BG
IN, LIN, HK, HKk = m41.IN, m41.LIN, m7.HK, m41.HKk
BASE, WALLP, WALL, LBASE, LWALL = m41.BASE, m41.WALLP, m41.WALL, m41.LBASE, m41.LWALL
RB, WG, LWK = m43.RB, m43.WG, m43.LWK
P = IN(0.1e-3)
PCK = lambda spec, k=2000: f"pair_coeff {spec} " + HKk(k) + "\n"
# every run with an every: the pair meets in its first part
EV = lambda cmd: f'run 2300 every 300 "{cmd}"\n'

# ================================================================ B: between runs / within a run
EXG = P + "group gx id 5\nneigh_modify exclude group lv1 gx\n"
S("B01_exclude_group_regrouped_mid", "neigh_modify exclude group lv1 gx (gx empty); run 300; group gx id 2 (the pair excluded mid-contact)",
  "group gx id 2\n", pair=EXG)
B("B02_exclude_group_regrouped_before", "neigh_modify exclude group lv1 gx (gx empty); run 50; group gx id 2 (excluded before the meeting: they pass)",
  "group gx id 2\n", pair=EXG)
L("B03_exclude_group_regrouped_every", "neigh_modify exclude group lv1 gx (gx empty); run 2300 every 300 \"group gx id 2\"", EV("group gx id 2"),
  pair=EXG, live="run 1")
EXM = P + "fix pm all property/atom mol ghost yes\nset atom 1 mol 1\nset atom 2 mol 2\nneigh_modify exclude molecule/intra all\n"
S("B04_exclude_molintra_set_mol_mid", "mol 1 and 2, exclude molecule/intra all; run 300; set atom 2 mol 1 (one molecule: excluded mid-contact)",
  "set atom 2 mol 1\n", pair=EXM)
B("B05_exclude_molintra_set_mol_before", "mol 1 and 2, exclude molecule/intra all; run 50; set atom 2 mol 1 (excluded before the meeting)",
  "set atom 2 mol 1\n", pair=EXM)
S("B06_exclude_molinter_set_mol_mid", "mol 1 and 1, exclude molecule/inter all; run 300; set atom 2 mol 2 (two molecules: excluded mid-contact)",
  "set atom 2 mol 2\n", pair=P + "fix pm all property/atom mol ghost yes\nset atom 1 mol 1\nset atom 2 mol 1\nneigh_modify exclude molecule/inter all\n")
L("B07_exclude_molintra_every_set_mol", "mol 1 and 2, exclude molecule/intra all; run 2300 every 300 \"set atom 2 mol 1\"", EV("set atom 2 mol 1"),
  pair=EXM, live="run 1")
BOND = (RB.replace("atom_style sphere 1", "atom_style hybrid sphere 1 bond")
        .replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 1"))
BONDP = P + "bond_style zero\nbond_coeff 1 0.005\nspecial_bonds lj 1.0 1.0 1.0\ncreate_bonds single/bond 1 1 2\n"
L("B08_special_lj0_mid", "a zero bond between the pair, special_bonds lj 1 1 1 (contact on); run 300; special_bonds lj 0 1 1 (the bonded pair loses its contact mid-way)",
  "run 300\nspecial_bonds lj 0.0 1.0 1.0\nrun 2000\n", pre=BOND, pair=BONDP, live="run 1 (and run 2)")
L("B09_special_lj0_before", "a zero bond, special_bonds lj 1 1 1; run 50; special_bonds lj 0 1 1 (no contact: they pass)",
  "run 50\nspecial_bonds lj 0.0 1.0 1.0\nrun 3000\n", pre=BOND, pair=BONDP, live="run 2")
L("B10_special_lj1_before", "a zero bond, special_bonds lj 0 1 1 (no contact); run 50; special_bonds lj 1 1 1 (the contact on before the meeting: 0.4134)",
  "run 50\nspecial_bonds lj 1.0 1.0 1.0\nrun 3000\n", pre=BOND, pair=BONDP.replace("lj 1.0 1.0 1.0", "lj 0.0 1.0 1.0"), live="run 2")
L("B11_special_every", "a zero bond, special_bonds lj 1 1 1; run 2300 every 300 \"special_bonds lj 0 1 1\"", EV("special_bonds lj 0.0 1.0 1.0"),
  pre=BOND, pair=BONDP, live="run 1")
INC = P + "group gx id 1 2\natom_modify first gx\nneigh_modify include gx\n"
S("B12_include_group_cleared_mid", "atom_modify first gx, neigh_modify include gx (gx both); run 300; group gx clear (no atom listed mid-contact)",
  "group gx clear\n", pair=INC)
B("B13_include_group_cleared_before", "neigh_modify include gx (gx both); run 50; group gx clear (no atom listed: they pass)", "group gx clear\n", pair=INC)
DYN = P + "variable k equal 0\nvariable vin atom (id==2)*v_k\ngroup gd dynamic all var vin every 1\nneigh_modify exclude group lv1 gd\n"
S("B14_exclude_dynamic_group_var_mid", "exclude group lv1 gd, gd dynamic by atom variable (id==2)*v_k, k 0; run 300; variable k equal 1",
  "variable k equal 1\n", pair=DYN)
B("B15_exclude_dynamic_group_var_before", "exclude group lv1 gd, gd dynamic by (id==2)*v_k, k 0; run 50; variable k equal 1", "variable k equal 1\n", pair=DYN)
GM = P + "group gx id 5\nvariable fa atom -0.5*gmask(gx)\nfix af all addforce v_fa 0.0 0.0\n"
S("B16_addforce_gmask_regrouped_mid", "fix af all addforce v_fa, fa atom -0.5*gmask(gx), gx empty; run 300; group gx id 2 (lv2 pushed mid-contact)",
  "group gx id 2\n", pair=GM)
# a region whose shape follows a variable (no move keyword)
BALL = lambda cx: (P + f"variable cx equal {cx}\nregion ball sphere v_cx 0.02 0.05 0.002 side out units box\n"
                   "fix w2 all wall/gran/region " + WG + " region ball\n")
L("B17_ball_wall_varshape_one_run", "a ball obstacle (wall/gran/region, sphere region side out, centre v_cx) moved by cx = 0.035-0.00705*(step>=300) onto lv2 mid-contact; one run",
  "run 3000\n", pair=BALL("0.035-0.00705*(step>=300)"))
S("B18_ball_wall_varshape_between", "the ball obstacle at cx 0.035; run 300; variable cx equal 0.02795 (onto lv2's far side)", "variable cx equal 0.02795\n",
  pair=BALL("0.035"))
L("B19_ball_wall_varshape_static_control", "the ball obstacle at cx 0.035 (never reached: control)", "run 3000\n", pair=BALL("0.035"))
SFV = P + "variable cx equal 0.1-0.07695*(step>=300)\nregion R sphere v_cx 0.02 0.05 0.0035 units box\nfix sf all setforce 0.0 0.0 0.0 region R\n"
L("B20_setforce_varshape_region_one_run", "setforce 0 0 0 region R, R a sphere centred v_cx = 0.1 then lv2's centre from step 300 (one run)", "run 3000\n", pair=SFV)
CYLV = lambda r: (BASE(wall=False) + f"variable rc equal {r}\nregion cyl cylinder z 0.02 0.02 v_rc 0 0.1 side in units box\n"
                  "fix wc all wall/gran/region " + WG + " region cyl\n")
L("B21_cylinder_varradius_one_run", "WALLX: one sphere lv1 moving +x at 1 m/s inside a cylinder wall (region radius v_rc = 0.0101, 0.05 mm less from step 400, mid-contact; one run)",
  "run 3000\n", pre=CYLV("0.0101-0.00005*(step>=400)"),
  pair="create_atoms 1 single 0.0279 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n",
  PAIR="type 1 on wall wc", WALLX="")
L("B22_exclude_type_then_label_swap", "labelmap atom 1 sm 2 bg; neigh_modify exclude type sm sm; run 300; labelmap atom 1 bg 2 sm (labels swapped mid-contact)",
  "run 300\nlabelmap atom 1 bg 2 sm\nrun 2000\n", pre=RB.replace("create_box 2 box\n", "create_box 2 box\nlabelmap atom 1 sm 2 bg\n"),
  pair=P + "neigh_modify exclude type sm sm\n", live="run 1 (and run 2)")
S("B23_exclude_molintra_group_regrouped", "mol 1 1, exclude molecule/intra gx (gx empty); run 300; group gx id 1 2", "group gx id 1 2\n",
  pair=P + "fix pm all property/atom mol ghost yes\nset atom 1 mol 1\nset atom 2 mol 1\ngroup gx id 5\nneigh_modify exclude molecule/intra gx\n")
L("B24_exclude_group_regrouped_every_include", "neigh_modify include gx (both); run 2300 every 300 \"group gx clear\"", EV("group gx clear"), pair=INC, live="run 1")
S("B25_special_coul_only_resets_lj", "a zero bond, special_bonds lj 1 1 1; run 300; special_bonds coul 0 0 0 (LAMMPS resets lj to its default 0 0 0)", "special_bonds coul 0.0 0.0 0.0\n",
  pre=BOND, pair=BONDP)
S("B26_set_mol_no_exclusion_control", "fix property/atom mol; run 300; set atom 2 mol 7 (no exclusion: control)", "set atom 2 mol 7\n",
  pair=P + "fix pm all property/atom mol ghost yes\n")
S("B27_exclude_group_other_regrouped_control", "exclude group lv1 gx (gx empty); run 300; group gq id 2 (another group: control)", "group gq id 2\n", pair=EXG)
B("B28_unfix_property_mol_exclusion", "mol 1 and 1, exclude molecule/inter all; run 50; set atom 1 mol 3 (inter: excluded before the meeting)",
  "set atom 1 mol 3\n", pair=P + "fix pm all property/atom mol ghost yes\nset atom 1 mol 1\nset atom 2 mol 1\nneigh_modify exclude molecule/inter all\n")
S("B29_spring_couple_group2_regrouped", "fix sp g3 spring couple gx 50 0 0 0 0 (g3 a far type 1 sphere, gx = it); run 300; group gx clear; group gx id 2 (lv2 pulled mid-contact)",
  "group gx clear\ngroup gx id 2\n",
  pair=P + "create_atoms 1 single 0.005 0.02 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\ngroup gx id 3\n"
  "fix sp g3 spring couple gx 50.0 0.0 0.0 0.0 0.0\n")
L("B30_exclude_group_two_sided_every", "exclude group gx gy (both empty); run 2300 every 300 \"group gx id 1\" then gy (two every commands)",
  'run 2300 every 300 "group gx id 1" "group gy id 2"\n', pair=P + "group gx id 5\ngroup gy id 5\nneigh_modify exclude group gx gy\n", live="run 1")

# ================================================================ O: original classes, new combinations
# formats and loops into pair_coeff
L("O01_fmt_3g_rounds_up", "pair_coeff * * hooke $(2049:%.3g) (the engine reads 2.05e+03 = 2050)", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * " + HK.replace("2000", "$(2049:%.3g)")))
L("O02_fmt_15g_sum", "variable a equal 1000.1+999.9; pair_coeff 1 2 hooke $(v_a:%.15g) (2000)", "run 3000\n",
  pre=RB + "variable a equal 1000.1+999.9\n" + PCK("1 2", "$(v_a:%.15g)"))
L("O03_fmt_e_kn5000", "pair_coeff 1 2 hooke $(5e3:%.2e) (5.00e+03)", "run 3000\n", pre=RB + PCK("1 2", "$(5e3:%.2e)"))
L("O04_fmt_width_spaces", "pair_coeff 1 2 hooke $(5000:%12.1f) (leading spaces inside the word)", "run 3000\n", pre=RB + PCK("1 2", "$(5000:%12.1f)"))
L("O05_loop_pair_coeff_last", "label l; variable i loop 3; pair_coeff 1 2 hooke $(1000*v_i+1000); next i; jump SELF l (the last pass: 4000)",
  "run 3000\n", pre=RB + "label l\nvariable i loop 3\n" + PCK("1 2", "$(1000*v_i+1000)") + "next i\njump SELF l\n")
L("O06_loop_pad_if_break", "variable i loop 5 pad; if \"${i} == 03\" then \"jump SELF out\"; pair_coeff kn 1000*i (the pass 03 jumps out: 2000 set at i=02)",
  "run 3000\n", pre=RB + "label l\nvariable i loop 5 pad\nif \"${i} == 03\" then \"jump SELF out\"\n" + PCK("1 2", "$(1000*v_i)") +
  "next i\njump SELF l\nlabel out\n")
L("O07_loop_universe_world", "variable k universe 5000 3000; pair_coeff 1 2 hooke ${k} (one partition: 5000)", "run 3000\n",
  pre=RB + "variable k universe 5000 3000\n" + PCK("1 2", "${k}"))
# odd comparisons in if
IFK = lambda cond: RB + f'if "{cond}" then "pair_coeff 1 2 {HKk(5000)}" else "pair_coeff 1 2 {HKk(3000)}"\n'
L("O08_if_e_notation_equal", "if \"2000 == 2.0e3\" (true: 5000)", "run 3000\n", pre=IFK("2000 == 2.0e3"))
L("O09_if_string_vs_number", "variable s string 02000; if \"${s} == 2000\" (numbers: true, 5000)", "run 3000\n",
  pre=RB.replace("timestep 1e-6\n", "timestep 1e-6\nvariable s string 02000\n") + IFK("${s} == 2000")[len(RB):])
L("O10_if_xor_not", "if \"!(1 |^ 1)\" (xor of true and true is false; not: true, 5000)", "run 3000\n", pre=IFK("!(1 |^ 1)"))
L("O11_if_fmt_compare", "variable e equal 1/3; if \"$(v_e:%.2f) == 0.33\" (true, 5000)", "run 3000\n",
  pre=RB + "variable e equal 1/3\n" + IFK("$(v_e:%.2f) == 0.33")[len(RB):])
L("O12_if_strings_unequal", "if \"abc != abd\" (strings: true, 5000)", "run 3000\n", pre=IFK("abc != abd"))
L("O13_if_precedence", "if \"1 || 0 && 0\" (&& first: true, 5000)", "run 3000\n", pre=IFK("1 || 0 && 0"))
# variable restyles
L("O14_index_given_again_ignored", "variable k index 3000; variable k index 5000 (ignored); pair_coeff 1 2 hooke ${k} (3000)", "run 3000\n",
  pre=RB + "variable k index 3000\nvariable k index 5000\n" + PCK("1 2", "${k}"))
L("O15_delete_then_equal", "variable k index 3000; variable k delete; variable k equal 5000; pair_coeff ${k} (5000)", "run 3000\n",
  pre=RB + "variable k index 3000\nvariable k delete\nvariable k equal 5000\n" + PCK("1 2", "${k}"))
L("O16_internal_redefined", "variable k internal 3000; variable k internal 5000; pair_coeff ${k}", "run 3000\n",
  pre=RB + "variable k internal 3000\nvariable k internal 5000\n" + PCK("1 2", "${k}"))
L("O17_format_variable", "variable q equal 4999.6; variable k format q %.0f; pair_coeff ${k} (5000)", "run 3000\n",
  pre=RB + "variable q equal 4999.6\nvariable k format q %.0f\n" + PCK("1 2", "${k}"))
L("O18_file_variable", "variable k file kn.txt (first line 5000; next k gives 3000 after); pair_coeff ${k}; next k; pair_coeff 1 1 ${k}",
  "run 3000\n", pre=RB + "variable k file kn.txt\n" + PCK("1 2", "${k}") + "next k\n" + PCK("1 1", "${k}"), data={"kn.txt": "# kn\n5000\n3000\n"})
L("O19_uloop_value", "variable k uloop 4; pair_coeff 1 2 hooke $(1000*v_k+2000) (1: 3000)", "run 3000\n",
  pre=RB + "variable k uloop 4\n" + PCK("1 2", "$(1000*v_k+2000)"))
# pair_coeff ranges and labels on 5 types (the pair: types 2 4)
R5 = RB.replace("create_box 2 box", "create_box 5 box")
L("O20_ranges_5types", "5 types; pair_coeff * * 2000; 1*2 3*5 5000; 4* 2*3 3000 (2 4 last set by 4* 2*3: 3000)", "run 3000\n",
  pre=R5 + PCK("1*2 3*5", 5000) + PCK("4* 2*3", 3000), pair=IN(0.1e-3, t1=2, t2=4), PAIR="types 2 4")
L("O21_labels_5types", "labelmap atom 1 a 2 b 3 c 4 d 5 e; pair_coeff d b 5000 (4 2); then * c 3000 (not 2 4)", "run 3000\n",
  pre=R5.replace("create_box 5 box\n", "create_box 5 box\nlabelmap atom 1 a 2 b 3 c 4 d 5 e\n") + PCK("d b", 5000) + PCK("* c", 3000),
  pair=IN(0.1e-3, t1=2, t2=4), PAIR="types 2 4")
L("O22_range_reversed_labels_create", "5 types; pair_coeff 4*5 1*2 5000 (i > j); create_atoms by label d and b", "run 3000\n",
  pre=R5.replace("create_box 5 box\n", "create_box 5 box\nlabelmap atom 1 a 2 b 3 c 4 d 5 e\n") + PCK("4*5 1*2", 5000),
  pair=IN(0.1e-3, t1=2, t2=4).replace("create_atoms 2 single", "create_atoms b single").replace("create_atoms 4 single", "create_atoms d single"), PAIR="types 2 4")
L("O23_mixed_types_hertz_ranges", "5 types hertz/material; 2 2 and 4 4 given (E 1e6 and 4e6), 2 4 mixed", "run 3000\n",
  pre=R5.replace("pair_coeff * * " + HK + "\n", "pair_coeff * * hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3 damping coeff_restitution\n"
                 "pair_coeff 4 4 hertz/material 4e6 0.8 0.2 tangential linear_nohistory 1 0.3 damping coeff_restitution\n"),
  pair=IN(0.1e-3, t1=2, t2=4), PAIR="types 2 4")
# set with variables, mass, order
L("O24_set_diameter_vd_then_redefined", "variable d equal 0.006; set atom 2 diameter v_d; variable d equal 0.009 (the set used 0.006)", "run 3000\n",
  pair=P.replace("set atom 2 diameter 0.006 density 2500", "variable d equal 0.006\nset atom 2 diameter v_d density 2500\nvariable d equal 0.009"))
L("O25_set_density_atomvar", "variable rho atom 2500+2500*(x>0.02); set atom * density v_rho (lv2 5000)", "run 3000\n",
  pair=P + "variable rho atom 2500+2500*(x>0.02)\nset atom * density v_rho\n")
L("O26_set_mass_then_diameter", "set atom 2 mass 2.8274e-4 (diameter 0.006, 2500); set atom 2 diameter 0.008 (density kept: heavier)", "run 3000\n",
  pair=P.replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 2500\nset atom 2 mass 5.6549e-4\nset atom 2 diameter 0.0059"))
L("O27_set_type_before_create", "set type 2 density 8000 before create_atoms (no atom yet); then the pair (2500 set on atom 2)", "run 3000\n",
  pair="set type 2 density 8000\n" + P)
L("O28_set_region_density", "region Rr block 0.021 0.03 0 0.04 0 0.1; set region Rr density 5000 (lv2)", "run 3000\n",
  pair=P + "region Rr block 0.021 0.03 0 0.04 0 0.1 units box\nset region Rr density 5000\n")
# units cgs: the same numbers mean another pair
CGS = ("units cgs\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 4 0 4 0 10 units box\ncreate_box 2 box\n"
       "pair_style granular\npair_coeff * * " + HK.replace("2000", "2000000") + "\nfix grav all gravity 981 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n"
       "create_atoms 1 single 1.7995 2 5\ncreate_atoms 2 single 2.3005 2 5\nset atom 1 diameter 0.4 density 2.5\nset atom 2 diameter 0.6 density 2.5\n"
       "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
L("O29_units_cgs_hooke", "units cgs: the pair 4 mm / 6 mm (0.4 / 0.6 cm, 2.5 g/cc) at 1 cm/s, hooke 2e6 dyne/cm = 2000 N/m, eta 3000: the si pair's 0.4134)", "run 3000\n",
  pre=CGS, pair="", SEP="0.5")
# several sizes per type, hertz
HZ = RB.replace("pair_coeff * * " + HK, "pair_coeff * * hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3 damping coeff_restitution")
L("O30_sizes_per_type_hertz", "hertz/material; type 1 has a second sphere (8 mm, far); the live pair 4 / 6 mm (a range of rows)", "run 3000\n",
  pre=HZ, pair=P + "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.008 density 2500\n")
L("O31_pour_poly_far_hertz", "hertz/material; fix pour of type 1, diam poly 2 0.003 0.5 0.005 0.5, far above; the live pair", "run 3000\n",
  pre=HZ.replace("boundary p p f", "boundary p p f"), pair=P + "region pr block 0.002 0.038 0.002 0.038 0.085 0.095 units box\n"
  "fix po all pour 5 1 4767 region pr diam poly 2 0.003 0.5 0.005 0.5 density 2500 2500\n")
L("O32_e_one_coeff_restitution", "hertz/material 1e6 e 1.0 damping coeff_restitution (no damping)", "run 3000\n",
  pre=HZ.replace(" 0.5 0.3 tangential", " 1.0 0.3 tangential"))
L("O33_e_one_hooke_zero_damping", "hooke 2000 0.0 damping mass_velocity (eta 0: 1.0)", "run 3000\n", pre=RB.replace("hooke 2000 3000", "hooke 2000 0.0"))
# region and cylinder walls, hertz: the wall's curvature
HZW = "granular hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3 damping coeff_restitution"
XW = "create_atoms 1 single 0.0279 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n"
L("O34_zcylinder_hertz_inside", "WALLX: hertz/material wall/gran zcylinder 0.01 (axis x = y = 0: the wall at x 0.01), lv1 at 1 m/s +x from x 0.0079",
  "run 3000\n", pre=HZ + "fix wc all wall/gran " + HZW + " zcylinder 0.01\n",
  pair=XW.replace("0.0279 0.02 0.05", "0.0079 0.0 0.05"), PAIR="type 1 on wall wc", WALLX="")
L("O35_region_cylinder_hertz_inside", "WALLX: hertz/material wall/gran/region on region cylinder z 0.02 0.02 0.01 side in, lv1 +x",
  "run 3000\n", pre=HZ + "region cyl cylinder z 0.02 0.02 0.01 0 0.1 side in units box\nfix wc all wall/gran/region " + HZW + " region cyl\n",
  pair=XW, PAIR="type 1 on wall wc", WALLX="")
L("O36_region_ball_hertz_outside", "WALLX: hertz/material wall/gran/region on a ball (sphere r 3 mm, side out) at x 0.0331, lv1 +x",
  "run 3000\n", pre=HZ + "region ball sphere 0.0331 0.02 0.05 0.003 side out units box\nfix wc all wall/gran/region " + HZW + " region ball\n",
  pair=XW, PAIR="type 1 on wall wc", WALLX="")
L("O37_region_plane_hertz_control", "WALLX: hertz/material wall/gran/region on a plane at x 0.03 (flat: control of O34-O36)",
  "run 3000\n", pre=HZ + "region pl plane 0.03 0 0 -1 0 0 units box\nfix wc all wall/gran/region " + HZW + " region pl\n",
  pair=XW, PAIR="type 1 on wall wc", WALLX="")
# hybrid/scaled
L("O38_hybrid_scaled_two", "pair_style hybrid/scaled 2.0 granular (forces doubled)", "run 3000\n",
  pre=RB.replace("pair_style granular\npair_coeff * * " + HK, "pair_style hybrid/scaled 2.0 granular\npair_coeff * * granular " + HK))
L("O39_hybrid_scaled_one", "pair_style hybrid/scaled 1.0 granular (control)", "run 3000\n",
  pre=RB.replace("pair_style granular\npair_coeff * * " + HK, "pair_style hybrid/scaled 1.0 granular\npair_coeff * * granular " + HK))
L("O40_hybrid_scaled_variable", "variable s equal 0.5; pair_style hybrid/scaled v_s granular (forces halved)", "run 3000\n",
  pre=RB.replace("pair_style granular\npair_coeff * * " + HK, "variable s equal 0.5\npair_style hybrid/scaled v_s granular\npair_coeff * * granular " + HK))
# fixes from the start
FX = lambda f: RB + f
L("O41_viscous_lv2", "fix viscous 0.001 on lv2 (from the start)", "run 3000\n", pair=P + "fix vis lv2 viscous 0.001\n")
L("O42_langevin_all", "fix langevin all 0 0 1e-4 48279 (a strong drag to 0 K from the start)", "run 3000\n", pair=P + "fix lg all langevin 0.0 0.0 1e-4 48279\n")
L("O43_setforce_x_zero", "fix setforce 0.0 NULL NULL on all (x forces zeroed: the pair passes)", "run 3000\n", pair=P + "fix sf all setforce 0.0 NULL NULL\n")
L("O44_nve_limit_small", "integ on lv1 only; lv2 moved by fix nve/limit 1e-7 (at most 1e-7 m a step: slower than its 2.3e-7)", "run 3000\n",
  pair=P + "unfix integ\nfix integ lv1 nve/sphere\nfix lim lv2 nve/limit 1e-7\n")
L("O45_freeze_type2", "fix freeze on lv2 (held: lv1 bounces off a held sphere)", "run 3000\n", pair=P + "fix fz lv2 freeze\n")
L("O46_adapt_diameter_start", "fix adapt 0 atom diameter v_d (d 0.008) on lv2: set at the run's start", "run 3000\n",
  pair=P + "variable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d\n")
L("O47_spring_self_lv2", "fix spring/self 10 on lv2 (tethered)", "run 3000\n", pair=P + "fix ss lv2 spring/self 10.0\n")
L("O48_temp_rescale", "fix temp/rescale 1 0 0 1e-9 1.0 (velocities rescaled to 0 K each step)", "run 3000\n", pair=P + "fix tr all temp/rescale 1 0.0 0.0 1e-9 1.0\n")
L("O49_lineforce_z", "fix lineforce 0 0 1 (forces only along z: the pair's x forces gone)", "run 3000\n", pair=P + "fix lf all lineforce 0 0 1\n")
L("O50_dt_reset", "fix dt/reset 1 NULL 2e-6 5e-8 units box (the step grows to 2e-6)", "run 3000\n", pair=P + "fix dtr all dt/reset 1 NULL 2e-6 5e-8 units box\n")
# coarse time steps
L("O51_dt_5e-5_hooke", "timestep 5e-5 (12 steps per contact)", "run 200\n", pre=RB.replace("timestep 1e-6", "timestep 5e-5"),
  pair=IN(0.1e-3))
L("O52_dt_2e-4_hooke", "timestep 2e-4 (3 steps per contact)", "run 100\n", pre=RB.replace("timestep 1e-6", "timestep 2e-4"), pair=IN(0.1e-3))
LHZ = LBASE()
LG("O53_lig_dt_1e-4", "LIGGGHTS hertz, timestep 1e-4", "run 100\n", pre=LBASE().replace("timestep 1e-6", "timestep 1e-4"))
# LIGGGHTS: walls-only types, templates, e 1.0
L5 = LBASE(nt=5, e=" ".join(["0.5"] * 25))
LG("O54_lig_5types_wallonly", "LIGGGHTS 5 types (4 and 5 walls only); e 1 2 0.5 set in a 5x5 matrix with other pairs 0.9", "run 3000\n",
   pre=LBASE(nt=5, e="0.9 0.5 0.9 0.9 0.9 0.5 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9"))
LG("O55_lig_e_one", "LIGGGHTS e 1 2 = 1.0 (hertz)", "run 3000\n", pre=LBASE(e="0.6 1.0 0.7 1.0 0.4 0.45 0.7 0.45 0.8"))
LG("O56_lig_templates_far_insertion", "LIGGGHTS: two templates of type 1 (r 1.5 and 2.5 mm) inserted far away once; the live pair", "run 3000\n",
   pre=LBASE() + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.0025\n"
   "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
   "region ins block -0.04 -0.02 -0.04 0.04 0.12 0.14 units box\n"
   "fix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 6 region ins\n")
LG("O57_lig_hooke_charvel_5types", "LIGGGHTS hooke with characteristicVelocity 1.0, 5 types", "run 3000\n",
   pre=LBASE(nt=5, model="hooke", e=" ".join(["0.5"] * 25), extra="fix cv all property/global characteristicVelocity scalar 1.0\n"))
LG("O58_lig_fmt_e", "LIGGGHTS: e 1 2 given as $(0.1+0.4:%.15g) in the matrix", "run 3000\n",
   pre=LBASE(e="0.6 $(0.1+0.4:%.15g) 0.7 $(0.1+0.4:%.15g) 0.4 0.45 0.7 0.45 0.8"))
L("O59_pour_range_type2_hertz", "hertz/material; fix pour type 2, diam range 0.005 0.007, far; the live pair (type 2 6 mm inside the range)", "run 3000\n",
  pre=HZ, pair=P + "region pr block 0.002 0.038 0.002 0.038 0.085 0.095 units box\n"
  "fix po all pour 4 2 4767 region pr diam range 0.005 0.007 density 2500 2500\n")
L("O60_lattice_create_units", "lattice sc 0.001; the pair made by create_atoms ... units lattice (x 17.95 and 23.05)", "run 3000\n",
  pair="lattice sc 0.001\n" + P.replace(" 0.02 0.05\n", " 20 50 units lattice\n").replace("0.017950", "17.95").replace("0.023050", "23.05"))

# ================================================================ H: harmless controls
HX = [
    ("set_mol_plain", "fix property/atom mol ghost yes (at start); set atom 2 mol 3", "set atom 2 mol 3\n", "fix pm all property/atom mol ghost yes\n"),
    ("special_same", "special_bonds lj 1 1 1 again (bonded pair)", "special_bonds lj 1.0 1.0 1.0\n", None),
    ("group_unused", "group gq id 2 (no fix, no exclusion)", "group gq id 2\n", ""),
    ("variable_captured", "variable k equal 5000 (pair_coeff took ${k} = 2000 at its line)", "variable k equal 5000\n", "variable k equal 2000\n" + PCK("1 2", "${k}")),
    ("lattice_box_region", "lattice sc 0.0074 (a wall region in box units far away)", "lattice sc 0.0074\n",
     "lattice sc 0.01\nregion a plane 0.035 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region a\n"),
    ("compute_modify", "compute_modify thermo_temp dynamic/dof yes", "compute_modify thermo_temp dynamic/dof yes\n", ""),
    ("thermo_lost_ignore", "thermo_modify lost ignore flush yes", "thermo_modify lost ignore flush yes\n", ""),
    ("write_data", "write_data h.data", "write_data h.data\n", ""),
    ("run0", "run 0", "run 0\n", ""),
    ("if_false_viscous", "if \"1 > 2\" then \"fix v all viscous 1\"", 'if "1 > 2" then "fix v all viscous 1"\n', ""),
    ("include_empty", "include e.in (empty)", "include e.in\n", ""),
    ("info", "info variables", "info variables\n", ""),
    ("neighbor_same", "neighbor 0.001 bin again", "neighbor 0.001 bin\n", ""),
    ("fix_ave_time", "fix at all ave/time 10 10 100 c_thermo_temp", "fix at all ave/time 10 10 100 c_thermo_temp\n", ""),
    ("fix_store_state", "fix st all store/state 0 x vx", "fix st all store/state 0 x vx\n", ""),
    ("group_union_unused", "group gu union lv1 lv2", "group gu union lv1 lv2\n", ""),
    ("exclude_group_other", "exclude group lv1 g3 (g3 a far sphere); run 300; group g3 id 3 again", "group g3 id 3\n",
     "create_atoms 1 single 0.005 0.02 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\nneigh_modify exclude group lv1 g3\n"),
    ("pair_coeff_same_range", "pair_coeff 1*2 1*2 the same law", "pair_coeff 1*2 1*2 " + HK + "\n", ""),
    ("gravity_same", "fix grav all gravity 9.81 vector 0 0 -1 (the same)", "fix grav all gravity 9.81 vector 0 0 -1\n", ""),
    ("dump_local", "dump d all custom 100 h.dump id x vx", "dump d all custom 100 h.dump id x vx\n", ""),
]
for i, (n, desc, x, extra) in enumerate(HX, 1):
    if extra is None:
        S(f"H{i:02d}_{n}_mid", f"run 300; {desc} (harmless: control)", x, pre=BOND, pair=BONDP)
    else:
        S(f"H{i:02d}_{n}_mid", f"run 300; {desc} (harmless: control)", x, pair=P + extra, data={"e.in": "\n"} if "include" in n else None)
L("H21_fix_setforce_absent_type", "fix setforce on type 3 (no atom of it; 3 types) from the start", "run 3000\n",
  pre=RB.replace("create_box 2 box", "create_box 3 box"), pair=P + "group t3 type 3\nfix sf t3 setforce 0.0 0.0 0.0\n")
L("H22_viscous_zero", "fix viscous 0.0 on all", "run 3000\n", pair=P + "fix vis all viscous 0.0\n")
L("H23_lineforce_x", "fix lineforce 1 0 0 (forces only along x: the pair's own)", "run 3000\n", pair=P + "fix lf all lineforce 1 0 0\n")
L("H24_momentum_linear", "fix momentum 1 linear 1 1 1 (the pair's momentum is 0 already)", "run 3000\n", pair=P + "fix mo all momentum 1 linear 1 1 1\n")
L("H25_nve_limit_large", "integ unfixed; fix nve/limit 1.0 on all (the limit never reached; no spin in a head-on contact)",
  "run 3000\n", pair=P + "unfix integ\nfix lim all nve/limit 1.0\n")
L("H26_every_print", "run 2300 every 300 \"print tick\" \"variable x equal 1\"", 'run 2300 every 300 "print tick" "variable x equal 1"\n', live="run 1")
SG("H27_lig_friction_same", "run 300; coefficientFriction the same values", "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n")
SG("H28_lig_thermo_dump", "run 300; thermo 10; dump of positions", "thermo 10\ndump d all custom 100 h.dump id x vx\n")
L("H29_planeforce_xy", "fix planeforce 0 0 1 (forces kept in the xy plane: the pair's x)", "run 3000\n", pair=P + "fix pf all planeforce 0 0 1\n")
L("H30_set_image", "set atom 2 image 0 0 0 from the start (no change)", "run 3000\n", pair=P + "set atom 2 image 0 0 0\n")

# ================================================================ after the first referee pass: engine-runnable forms of O20 O22 O24 O31 O34 O59, more B
L("O61_ranges_5types_ordered", "5 types; pair_coeff * * 2000; 1*2 3*5 5000; 2*3 4* 3000 (2 4 last set: 3000)", "run 3000\n",
  pre=R5 + PCK("1*2 3*5", 5000) + PCK("2*3 4*", 3000), pair=IN(0.1e-3, t1=2, t2=4), PAIR="types 2 4")
L("O62_set_diameter_atomvar_then_redefined", "variable d atom 0.006; set atom 2 diameter v_d; variable d atom 0.009 (the set used 0.006)", "run 3000\n",
  pair=P.replace("set atom 2 diameter 0.006 density 2500", "variable d atom 0.006\nset atom 2 diameter v_d density 2500\nvariable d atom 0.009"))
L("O63_pour_poly_far_hertz", "hertz/material; fix pour of type 1, diam poly 2 0.003 0.5 0.005 0.5, dens 2500 2500, far above; the live pair", "run 3000\n",
  pre=HZ, pair=P + "region pr block 0.002 0.038 0.002 0.038 0.085 0.095 units box\n"
  "fix po all pour 5 1 4767 region pr diam poly 2 0.003 0.5 0.005 0.5 dens 2500 2500\n")
L("O64_pour_range_type2_hertz", "hertz/material; fix pour type 2, diam range 0.005 0.007, far; the live pair (type 2 at 6 mm inside the range)", "run 3000\n",
  pre=HZ, pair=P + "region pr block 0.002 0.038 0.002 0.038 0.085 0.095 units box\n"
  "fix po all pour 4 2 4767 region pr diam range 0.005 0.007 dens 2500 2500\n")
HZF = HZ.replace("boundary p p f", "boundary f f f").replace("region box block 0 0.04 0 0.04 0 0.1", "region box block -0.02 0.04 -0.02 0.04 0 0.1")
L("O65_zcylinder_hertz_inside_fff", "WALLX: boundary f f f; hertz/material wall/gran zcylinder 0.01 (axis x = y = 0), lv1 at 1 m/s +x from x 0.0079",
  "run 3000\n", pre=HZF + "fix wc all wall/gran " + HZW + " zcylinder 0.01\n", pair=XW.replace("0.0279 0.02 0.05", "0.0079 0.0 0.05"),
  PAIR="type 1 on wall wc", WALLX="")
LEXG = LIN(0.1e-3) + "group gx id 5\nneigh_modify exclude group lv1 gx\n"
SG("B31_lig_exclude_group_regrouped_mid", "neigh_modify exclude group lv1 gx (gx empty); run 300; group gx id 2", "group gx id 2\n", pair=LEXG)
L("B32_fix_print_writes_include", "fix pp print 25 \"pair_coeff 1 2 hooke 5000 ...\" file kn.in (written during run 1); run 50; include kn.in; run 3000",
  "run 50\ninclude kn.in\nrun 3000\n", pair=P + 'fix pp all print 25 "pair_coeff 1 2 ' + HKk(5000) + '" file kn.in screen no title "# kn"\n',
  data={"kn.in": PCK("1 2", 3000)}, live="run 2")
L("B33_if_step_after_run", "run 50; if \"$(step) >= 50\" then \"pair_coeff 1 2 hooke 5000\" (true in the engine); run 3000",
  'run 50\nif "$(step) >= 50" then "pair_coeff 1 2 ' + HKk(5000) + '"\nrun 3000\n', live="run 2")
L("B34_if_position_after_run", "run 50; if \"$(xcm(lv2,x)) < 0.023045\" then \"pair_coeff 1 2 hooke 5000\" (lv2 moved 0.011 mm: true); run 3000",
  'run 50\nif "$(xcm(lv2,x)) < 0.023045" then "pair_coeff 1 2 ' + HKk(5000) + '"\nrun 3000\n', live="run 2")
S("B35_exclude_group_subtract_mid", "exclude group lv1 gx (gx empty); run 300; group gx subtract all lv1 (gx = lv2)", "group gx subtract all lv1\n", pair=EXG)
S("B36_exclude_group_by_type_mid", "exclude group lv1 gx (gx empty); run 300; group gx type 2", "group gx type 2\n", pair=EXG)
S("B37_special_lj_coul_form_mid", "a zero bond, special_bonds lj/coul 1 1 1; run 300; special_bonds lj/coul 0 1 1", "special_bonds lj/coul 0.0 1.0 1.0\n",
  pre=BOND, pair=BONDP.replace("special_bonds lj 1.0 1.0 1.0", "special_bonds lj/coul 1.0 1.0 1.0"))
S("B38_special_amber_mid", "a zero bond, special_bonds lj 1 1 1; run 300; special_bonds amber (lj 0 0 0.5: the 1-2 pair off)", "special_bonds amber\n",
  pre=BOND, pair=BONDP)

# ================================================================ set 2, written while the first audit ran (before reading it)
L("B39_indent_varshape_one_run", "fix indent 1e4 sphere v_cx 0.02 0.05 0.0055 (a point-force indenter: cx = 0.035, 0.02795 from step 300, lv2's centre 0.5 mm inside it mid-contact); one run",
  "run 3000\n", pair=P + "variable cx equal 0.035-0.00705*(step>=300)\nfix ind all indent 1e4 sphere v_cx 0.02 0.05 0.0055 units box\n")
L("B40_union_varshape_part_one_run", "wall/gran/region on union of a far plane and a ball (sphere centre v_cx, side out) moved onto lv2 at step 300; one run",
  "run 3000\n", pair=P + "variable cx equal 0.035-0.00705*(step>=300)\nregion ball sphere v_cx 0.02 0.05 0.002 side out units box\n"
  "region far plane 0.0395 0 0 -1 0 0 units box\nregion u intersect 2 ball far\nfix w2 all wall/gran/region " + WG + " region u\n")
L("B41_every_include_kn5000", "run 2300 every 300 \"include kn.in\" (kn.in: pair_coeff 1 2 hooke 5000: mid-contact)", EV("include kn.in"),
  data={"kn.in": PCK("1 2", 5000)}, live="run 1")
SG("B42_lig_unfix_e_new_id_mid", "run 300; unfix m3; fix m3b coefficientRestitution with 1 2 0.8 (another ID)",
   "unfix m3\nfix m3b all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\n")
L("O66_rigid_single_lv2", "lv2 a one-sphere rigid body (fix rigid single), lv1 nve/sphere", "run 3000\n",
  pair=P + "unfix integ\nfix integ lv1 nve/sphere\nfix rg lv2 rigid single\n")
L("O67_xplane_upper_wall", "WALLX: boundary f p f; wall/gran xplane NULL 0.03 (an upper x wall), lv1 at 1 m/s +x", "run 3000\n",
  pre=RB.replace("boundary p p f", "boundary f p f") + "fix wx all wall/gran " + WG + " xplane NULL 0.03\n", pair=XW, PAIR="type 1 on wall wx", WALLX="")
L("O68_loop_if_modulo", "label; variable i loop 4; if \"$(v_i%2) == 0\" then pair_coeff hooke $(1000*v_i+1000) (i 4 last: 5000)", "run 3000\n",
  pre=RB + "label l\nvariable i loop 4\nif \"$(v_i%2) == 0\" then \"pair_coeff 1 2 hooke $(1000*v_i+1000) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\"\n"
  "next i\njump SELF l\n")
L("O69_variable_self_capture", "variable k equal 2000; variable k equal ${k}+3000 (captured: 5000); pair_coeff $(v_k)", "run 3000\n",
  pre=RB + "variable k equal 2000\nvariable k equal ${k}+3000\n" + PCK("1 2", "$(v_k)"))
L("H31_nve_point_on_lv2", "lv1 nve/sphere, lv2 plain nve (no spin in a head-on contact: control)", "run 3000\n",
  pair=P + "unfix integ\nfix integ lv1 nve/sphere\nfix i2 lv2 nve\n")
SG("H32_lig_unfix_refix_same_e", "run 300; unfix m3; fix m3 the same values again (control)",
   "unfix m3\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n")
S("H33_special_same_with_angle", "a zero bond, special_bonds lj 1 1 1; run 300; special_bonds lj 1 1 1 angle no (lj as it was: control)",
  "special_bonds lj 1.0 1.0 1.0 angle no\n", pre=BOND, pair=BONDP)

# ================================================================ after reading the first audit's B results: the reach of B29 (a fix's second group)
SP3 = P + "create_atoms 1 single 0.005 0.02 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\n"
L("B43_spring_couple_lv2_from_start", "fix sp g3 spring couple lv2 50 0 0 0 0 (g3 a far type 1 sphere; lv2 pulled from the start); one run",
  "run 3000\n", pair=SP3 + "fix sp g3 spring couple lv2 50.0 0.0 0.0 0.0 0.0\n")
L("B44_smd_couple_lv2_from_start", "fix sm g3 smd cfor 0.5 couple lv2 auto auto auto 0.0 (steered MD pulling g3 and lv2 together); one run",
  "run 3000\n", pair=SP3 + "fix sm g3 smd cfor 0.5 couple lv2 auto auto auto 0.0\n")
B("B45_spring_couple_group2_regrouped_before", "fix sp g3 spring couple gx (gx = g3); run 50; group gx clear; group gx id 2 (lv2 pulled before the meeting)",
  "group gx clear\ngroup gx id 2\n", pair=SP3 + "group gx id 3\nfix sp g3 spring couple gx 50.0 0.0 0.0 0.0 0.0\n")
L("B46_spring_couple_small_k", "fix sp g3 spring couple lv2 0.05 0 0 0 0 (a weak pull: 1.5 mN on lv2 from the start); one run",
  "run 3000\n", pair=SP3 + "fix sp g3 spring couple lv2 0.05 0.0 0.0 0.0 0.0\n")

# ================================================================ after reading the first audit (all families): the reach of the classes found
PR = 'print "PUB45 eps $(vcm(lv2,x)-vcm(lv1,x):%.6f)"\n'
LPR = 'variable P45 equal vcm(lv2,x)-vcm(lv1,x)\nprint "PUB45 eps ${P45}"\n'
L("M01_clear_at_end", "the pair, run 3000, its own print, then clear as the deck's last line (the audit's dump after clear?)", "run 3000\n" + PR + "clear\n")
LG("M02_lig_clear_at_end", "LIGGGHTS: the pair, run 3000, its own print, clear as the last line", "run 3000\n" + LPR + "clear\n")
LG("M03_lig_loop_clear_jump", "LIGGGHTS: label l; variable e universe 0.5 0.7 (e 1 2); the pair; run 3000; print; next e; clear; jump SELF l",
   "run 3000\n" + LPR + "next e\nclear\njump SELF l\n", pre="label l\nvariable e universe 0.5 0.7\n" + LBASE(e="0.6 ${e} 0.7 ${e} 0.4 0.45 0.7 0.45 0.8"))
L("M04_jump_file_with_dump_glob", "dump d all custom 1000 dump_*.txt; variable i loop 2; label l; run 1500; next i; jump in.deck l (two passes)",
  "dump d all custom 1000 dump_*.txt id x vx\nvariable i loop 2\nlabel l\nrun 1500\nnext i\njump in.deck l\n")
L("M05_jump_file_no_dump", "variable i loop 2; label l; run 1500; next i; jump in.deck l (no dump: control of M04)",
  "variable i loop 2\nlabel l\nrun 1500\nnext i\njump in.deck l\n")
L("M06_jump_self_with_dump_glob", "dump d all custom 1000 dump_*.txt; the same loop with jump SELF l", "dump d all custom 1000 dump_*.txt id x vx\nvariable i loop 2\nlabel l\nrun 1500\nnext i\njump SELF l\n")
L("B47_union_varshape_part_one_run", "wall/gran/region on union of a far plane and a ball (sphere centre v_cx) moved onto lv2 at step 300; one run (B40 with union)",
  "run 3000\n", pair=P + "variable cx equal 0.035-0.00705*(step>=300)\nregion ball sphere v_cx 0.02 0.05 0.002 side out units box\n"
  "region far plane 0.0395 0 0 -1 0 0 units box\nregion u union 2 ball far\nfix w2 all wall/gran/region " + WG + " region u\n")
S("B48_intersect_varshape_between", "the intersect of B40 with cx 0.035; run 300; variable cx equal 0.02795 (between runs)", "variable cx equal 0.02795\n",
  pair=P + "variable cx equal 0.035\nregion ball sphere v_cx 0.02 0.05 0.002 side out units box\n"
  "region far plane 0.0395 0 0 -1 0 0 units box\nregion u intersect 2 ball far\nfix w2 all wall/gran/region " + WG + " region u\n")
L("B49_intersect_varradius_floor", "WALL: the floor a wall/gran/region on intersect of a plane at z 0 and a big ball whose radius v_r grows 0.2 mm from step 300 (mid-contact)",
  "run 3000\n", pre=BASE(wall=False) + "variable r equal 0.05+0.0002*(step>=300)\nregion ball sphere 0.02 0.02 -0.05 v_r side out units box\n"
  "region top plane 0 0 -1 0 0 1 units box\nregion fl intersect 2 ball top\nfix floor all wall/gran/region " + WG + " region fl\n", pair=WALLP(), **WALL)
L("O70_dt_reset_long_run", "fix dt/reset 1 NULL 2e-6 5e-8 units box; run 30000 (the contact ends in the run)", "run 30000\n",
  pair=P + "fix dtr all dt/reset 1 NULL 2e-6 5e-8 units box\n")

LOOPKE = ("run 1\ndump d all custom 500 post/dump_*.txt id x vx\nrun 500\nvariable ke equal ke\nlabel loop\n"
          "if \"${ke} < 1e-30\" then \"jump in.deck endloop\"\nrun 1000\nif \"$(step) > 2500\" then \"jump in.deck endloop\"\njump in.deck loop\nlabel endloop\n")
L("M07_ke_loop_jump_file_dump", "dump post/dump_*.txt; a settle loop on ke and step (jump in.deck loop, if ... jump in.deck endloop)", LOOPKE, data={"post/.keep": ""})
L("M08_ke_loop_jump_file_no_dump", "the settle loop of M07 without the dump (control)", LOOPKE.replace("dump d all custom 500 post/dump_*.txt id x vx\n", ""), data={"post/.keep": ""})
LG("M09_lig_ke_loop_jump_file_dump", "LIGGGHTS: the settle loop of M07 with its dump", LOOPKE.replace("variable ke equal ke", "compute cke all ke\nvariable ke equal c_cke")
   .replace('"$(step) > 2500"', '"${st} > 2500"').replace("run 1000\n", "run 1000\nvariable st equal step\n"), data={"post/.keep": ""})

LOOPKEL = ("compute cke all ke\nthermo_style custom step atoms c_cke\nthermo 500\nvariable dumpfreq equal 500\nrun 1\n"
           "dump dmp all custom ${dumpfreq} ./post/dump_*.liggghts id type x y z vx vy vz radius\nrun ${dumpfreq}\nvariable ke equal c_cke\n"
           "print \"ke ${ke}\"\nlabel loop\nif \"${ke} < 1e-30\" then \"jump in.deck endloop\"\nrun 1000\nvariable st equal step\n"
           "if \"${st} > 2500\" then \"jump in.deck endloop\"\njump in.deck loop\nlabel endloop\n")
LG("M10_lig_ke_loop_thermo_dump", "LIGGGHTS: R23's settle loop (ke from a thermo compute, jump in.deck loop) with its dump ./post/dump_*.liggghts", LOOPKEL,
   data={"post/.keep": ""})
LG("M11_lig_ke_loop_thermo_no_dump", "LIGGGHTS: M10 without the dump (control)", LOOPKEL.replace(
   "dump dmp all custom ${dumpfreq} ./post/dump_*.liggghts id type x y z vx vy vz radius\n", ""), data={"post/.keep": ""})

L("M12_ke_loop_jump_file_dump_var_every", "M07 with the dump's every given as ${df} (variable df equal 500)",
  "variable df equal 500\n" + LOOPKE.replace("dump d all custom 500 post/dump_*.txt", "dump d all custom ${df} post/dump_*.txt"), data={"post/.keep": ""})
LG("M13_lig_ke_loop_thermo_dump_literal", "LIGGGHTS: M10 with the dump's every written 500", LOOPKEL.replace("dump dmp all custom ${dumpfreq}", "dump dmp all custom 500"),
   data={"post/.keep": ""})

# ================================================================ the reach of B17/B40: other region styles placed by a variable, directly under the wall
L("B50_block_varface_one_run", "wall/gran/region on block 0 v_xh (xh = 0.035, 0.0259 from step 300: its face onto lv2 mid-contact); one run",
  "run 3000\n", pair=P + "variable xh equal 0.035-0.0091*(step>=300)\nregion a block 0 v_xh 0 0.04 0 0.1 units box\n"
  "fix w2 all wall/gran/region " + WG + " region a\n")
L("B51_ellipsoid_varcentre_one_run", "a ball obstacle as an ellipsoid (semi-axes 2 mm, side out) centred v_cx, onto lv2 at step 300; one run",
  "run 3000\n", pair=P + "variable cx equal 0.035-0.00705*(step>=300)\nregion ball ellipsoid v_cx 0.02 0.05 0.002 0.002 0.002 side out units box\n"
  "fix w2 all wall/gran/region " + WG + " region ball\n")
L("B52_prism_varface_one_run", "wall/gran/region on prism 0 v_xh ... 0 0 0 (a block as a prism, its face onto lv2 at step 300); one run",
  "run 3000\n", pair=P + "variable xh equal 0.035-0.0091*(step>=300)\nregion a prism 0 v_xh 0 0.04 0 0.1 0 0 0 units box\n"
  "fix w2 all wall/gran/region " + WG + " region a\n")
L("B53_block_varface_static_control", "wall/gran/region on block 0 v_xh with xh 0.035 always (never reached: control)", "run 3000\n",
  pair=P + "variable xh equal 0.035\nregion a block 0 v_xh 0 0.04 0 0.1 units box\nfix w2 all wall/gran/region " + WG + " region a\n")

L("B54_intersect_move_part_one_run", "wall/gran/region on intersect of a plane a (move v_dx, dx = -0.0091*(step>=300): onto lv2 mid-contact) and a far plane; one run",
  "run 3000\n", pair=P + "variable dx equal -0.0091*(step>=300)\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
  "region far plane 0.0 0.0 0.0 0 0 1 units box\nregion u intersect 2 a far\nfix w2 all wall/gran/region " + WG + " region u\n")
L("B55_union_move_part_floor", "WALL: the floor a wall/gran/region on union of a plane at z 0 moved by move v_dz (dz = 2e-4*(step>=300), mid-contact) and a far block",
  "run 3000\n", pre=BASE(wall=False) + "variable dz equal 2e-4*(step>=300)\nregion fl0 plane 0 0 0 0 0 1 move NULL NULL v_dz units box\n"
  "region far block 0 0.001 0 0.001 0 0.001 units box\nregion fl union 2 fl0 far\nfix floor all wall/gran/region " + WG + " region fl\n", pair=WALLP(), **WALL)

# an internal variable that a fix controller drives places the wall's region (a number when defined)
CTL = (P + "variable xh internal 0.0265\nvariable pv equal step\n"
       "fix ctl all controller 1 1.0 {kp} 0.0 0.0 v_pv 0.0 xh\n"
       "region a block 0 v_xh 0 0.04 0 0.1 units box\nfix w2 all wall/gran/region " + WG + " region a\n")
L("B56_controller_drives_region_variable", "xh internal 0.0265 (0.5 mm beyond lv2) moved by fix controller (pv = step, setpoint 0: xh falls 1.5e-6 a step) places block 0 v_xh under a wall; one run",
  "run 3000\n", pair=CTL.format(kp="1.0e-3"))
L("B57_controller_idle_control", "the same with Kp 0 (xh stays 0.0265, 0.5 mm beyond lv2: control)", "run 3000\n", pair=CTL.format(kp="0.0"))

# ================================================================ more harmless-listed commands with an option that matters (written after the first audit)
HBOND = BOND.replace("pair_style granular\npair_coeff * * " + HK, "pair_style hybrid granular\npair_coeff * * granular " + HK)
S("B58_pair_modify_special_hybrid_mid", "a zero bond, special_bonds lj 1 1 1, pair_style hybrid granular; run 300; pair_modify pair granular special lj 0 1 1 (the bonded pair off mid-contact)",
  "pair_modify pair granular special lj 0.0 1.0 1.0\n", pre=HBOND, pair=BONDP)
B("B59_pair_modify_special_hybrid_before", "the same before the meeting (no contact: they pass)", "pair_modify pair granular special lj 0.0 1.0 1.0\n", pre=HBOND, pair=BONDP)
S("B60_minimize_fire_mid", "run 300; min_style fire; minimize 0 0 200 2000 (mid-contact)", "min_style fire\nminimize 0.0 0.0 200 2000\n")
S("B61_minimize_quickmin_mid", "run 300; min_style quickmin; minimize 0 0 200 2000 (mid-contact)", "min_style quickmin\nminimize 0.0 0.0 200 2000\n")
S("B62_minimize_cg_mid_control", "run 300; minimize 0 0 200 2000 (cg: round 43's control)", "minimize 0.0 0.0 200 2000\n")

B("B63_minimize_fire_before", "run 50; min_style fire; minimize 0 0 200 2000 (before the meeting)", "min_style fire\nminimize 0.0 0.0 200 2000\n")
L("B64_minimize_quickmin_after_contact", "run 2000 (the contact over); min_style quickmin; minimize; run 1000 (the pair apart: control?)",
  "run 2000\nmin_style quickmin\nminimize 0.0 0.0 200 2000\nrun 1000\n", live="run 1")

# partition yes 1 CMD: one partition runs CMD (a harmless-listed command carrying any other)
S("B65_partition_viscous_mid", "run 300; partition yes 1 fix vis all viscous 0.05 (mid-contact)", "partition yes 1 fix vis all viscous 0.05\n")
B("B66_partition_pair_coeff_before", "run 50; partition yes 1 pair_coeff 1 2 hooke 5000 ... (before the meeting)", "partition yes 1 " + PCK("1 2", 5000))
S("B67_partition_set_vx_mid", "run 300; partition yes 1 set atom 2 vx 0.5 (mid-contact)", "partition yes 1 set atom 2 vx 0.5\n")
S("B68_partition_no_control", "run 300; partition no 1 fix vis all viscous 0.05 (not run: control)", "partition no 1 fix vis all viscous 0.05\n")
L("O71_partition_viscous_start", "partition yes 1 fix vis lv2 viscous 0.01 from the start", "run 3000\n", pair=P + "partition yes 1 fix vis lv2 viscous 0.01\n")
L("O72_partition_pair_coeff_start", "partition yes 1 pair_coeff 1 2 hooke 5000 ... from the start", "run 3000\n", pre=RB + "partition yes 1 " + PCK("1 2", 5000))

SW("B69_floor_minimize_fire_mid", "run 300; min_style fire; minimize 0 0 200 2000 (the floor contact mid-way)", "min_style fire\nminimize 0.0 0.0 200 2000\n")
SG("B70_lig_minimize_quickmin_mid", "run 300; min_style quickmin; minimize 0 0 200 2000 (mid-contact)", "min_style quickmin\nminimize 0.0 0.0 200 2000\n")

# ================================================================ O: a pair cutoff below the touching distance, other normal models (written after the first audit)
L("O73_pair_cutoff_below_contact", "pair_coeff 1 2 ... cutoff 0.003 (the 4 / 6 mm pair touches at 5 mm; neighbor 1 mm)", "run 3000\n", pre=RB + PCK("1 2") .replace("\n", " cutoff 0.003\n"))
L("O74_global_cutoff_below_contact", "pair_style granular 0.003 (a global cutoff below the 5 mm touching distance)", "run 3000\n",
  pre=RB.replace("pair_style granular\n", "pair_style granular 0.003\n"))
L("O75_viscoelastic_sizes", "hertz/material with damping viscoelastic (size-dependent); type 1 has a second, 8 mm sphere", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * hertz/material 1e6 0.5 0.3 tangential linear_nohistory 1 0.3 damping viscoelastic"),
  pair=P + "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.008 density 2500\n")
L("O76_dmt_zero_cohesion", "dmt 1e6 0.5 0.3 0.0 (no surface energy) damping coeff_restitution? dmt needs its own damping", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * dmt 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping tsuji"))
L("O77_jkr_small_cohesion", "jkr 1e6 0.5 0.3 0.01 damping tsuji (a small surface energy)", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * jkr 1e6 0.5 0.3 0.01 tangential mindlin NULL 1 0.3 damping tsuji"))
L("O78_neighbor_small_skin_cutoff", "neighbor 0.00005 bin with pair_coeff cutoff 0.0049 (the list reach 4.95 mm: below 5 mm)", "run 3000\n",
  pre=RB + "neighbor 0.00005 bin\n" + PCK("1 2").replace("\n", " cutoff 0.0049\n"))

L("O79_jkr_small_cohesion_mv", "jkr 1e6 0.5 0.3 0.01 damping mass_velocity (a small surface energy; O77 with a damping LAMMPS allows)", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * jkr 1e6 0.5 0.3 0.01 tangential mindlin NULL 1 0.3 damping mass_velocity"))
L("O80_dmt_zero_cohesion_visco", "dmt 1e6 0.5 0.3 0.0 damping viscoelastic (no surface energy)", "run 3000\n",
  pre=RB.replace("pair_coeff * * " + HK, "pair_coeff * * dmt 1e6 0.5 0.3 0.0 tangential linear_nohistory 1 0.3 damping viscoelastic"))

# charges: a granular pair overlaid with coul/cut, charges 0 at first
QB = RB.replace("atom_style sphere 1", "atom_style hybrid sphere 1 charge").replace(
    "pair_style granular\npair_coeff * * " + HK, "pair_style hybrid/overlay granular coul/cut 0.02\npair_coeff * * granular " + HK + "\npair_coeff * * coul/cut")
S("B71_set_charge_mid", "hybrid/overlay granular coul/cut, charges 0; run 300; set atom 1 charge 2e-7; set atom 2 charge 2e-7 (a repulsion mid-contact)",
  "set atom 1 charge 2e-7\nset atom 2 charge 2e-7\n", pre=QB)
B("B72_set_charge_before", "the same before the meeting", "set atom 1 charge 2e-7\nset atom 2 charge 2e-7\n", pre=QB)
L("B73_charge_zero_control", "hybrid/overlay granular coul/cut, charges 0 throughout (control)", "run 3000\n", pre=QB)
L("B74_efield_set_charge_mid", "fix efield 1e4 0 0 on all (charges 0); run 300; set atom 2 charge 1e-8 (pushed mid-contact)", "run 300\nset atom 2 charge 1e-8\nrun 2000\n",
  pre=RB.replace("atom_style sphere 1", "atom_style hybrid sphere 1 charge"), pair=P + "fix ef all efield 1e4 0.0 0.0\n", live="run 1 (and run 2)")

L("M14_jump_file_dump_var_every_static", "M04 (a two-pass loop by jump in.deck) with the dump's every given as ${df}",
  "variable df equal 1000\ndump d all custom ${df} dump_*.txt id x vx\nvariable i loop 2\nlabel l\nrun 1500\nnext i\njump in.deck l\n")
L("M15_include_after_dump_var_file", "dump d all custom ${df} d.txt ...; include k.in (a file in the folder, no loop)", "dump d all custom ${df} d.txt id x vx\ninclude k.in\nrun 3000\n",
  pair=P + "variable df equal 1000\n", data={"k.in": "print k\n"})

S("B75_pair_style_zero_mid", "run 300; pair_style zero 0.01; pair_coeff * * (the contact force gone mid-contact)", "pair_style zero 0.01\npair_coeff * *\n")
S("B76_pair_style_granular_again_control", "run 300; pair_style granular again, no pair_coeff (LAMMPS keeps the coefficients: control)", "pair_style granular\n")
B("B77_pair_style_gran_hooke_history_before", "run 50; pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1; pair_coeff * * (before the meeting)",
  "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 1\npair_coeff * *\n")
S("B78_minimize_fire_every", "run 2300 every 300 \"min_style fire\" \"minimize 0 0 200 2000\"? no: run 300; min_modify dmax 1e-6; min_style fire; minimize (dmax small)",
  "min_modify dmax 1e-6\nmin_style fire\nminimize 0.0 0.0 20 200\n")

L("B79_intersect_move_part_hertz", "B54 under hertz/material (a law that reads R_eff): wall on intersect(plane a moved by v_dx, far plane); one run",
  "run 3000\n", pre=HZ, pair=P + "variable dx equal -0.0091*(step>=300)\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
  "region far plane 0.0 0.0 0.0 0 0 1 units box\nregion u intersect 2 a far\nfix w2 all wall/gran/region " + HZW + " region u\n")

SG("B80_lig_minimize_fire_mid", "run 300; min_style fire; minimize 0 0 200 2000 (mid-contact, LIGGGHTS)", "min_style fire\nminimize 0.0 0.0 200 2000\n")
SG("B81_lig_minimize_cg_mid", "run 300; minimize 0 0 200 2000 (cg, mid-contact, LIGGGHTS)", "minimize 0.0 0.0 200 2000\n")

if __name__ == "__main__":
    names = sys.argv[1:]
    m7.big = lambda *a, **k: None
    m7.lmp_gen = lambda *a, **k: None
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1\n")
