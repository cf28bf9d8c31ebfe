"""Field round 39: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py, links kept)
and the audit. An adversarial round on main bacc15ed in families little attacked before: pair_coeff ranges whose i > j
half LAMMPS drops and type labels (K); formats and variables in if conditions, file names, restyles, `$x` one-letter
names, round() at .5 (V); set order, ids renumbered by delete_atoms compress, set type/ratio, set region after
displace_atoms (Q); pair_style hybrid, hybrid/overlay, hybrid/scaled (H); fixes that change the pair's motion: freeze,
setforce, viscous, langevin, nve/limit, a second integrator, one integrated sphere, fix move, fix adapt diameter,
neigh_modify exclude (D); runs in parts, minimize, replicate, change_box, displace_atoms, velocity, processors (U);
LAMMPS walls (types with no atoms, region cylinder/plane walls, shear, two floors) (W); sizes (S); LIGGGHTS
property/global forms, e 1.0 and near 0, limitForce, tangential_damping, rolling_friction, cohesion, insert/pack,
insert/stream, mesh walls from an STL written here, freeze, exclude, two e fixes (G); plain controls (C).
Helpers are rounds 35-37's (make_decks37.py imported; its decks are not written). Live pair and controls as round 37
(FINDINGS.md): LAMMPS kn 2000 0.413435, 3000 0.490898, 4000 0.542172, 5000 0.578975; lv2 5000 kg/m3 0.390402;
LIGGGHTS e 0.5 0.499928, 0.8 0.800005.
usage: python make_decks39.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field37"))
import make_decks37 as m7  # noqa: E402

m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG = m7.L, m7.LG
PCs, PC3, PC4, PC5, LEe, LE, IN, LIN, G, G11, HK, HK5, TAILR, RB, HKk = (m7.PCs, m7.PC3, m7.PC4, m7.PC5, m7.LEe, m7.LE, m7.IN,
                                                                    m7.LIN, m7.G, m7.G11, m7.HK, m7.HK5, m7.TAILR, m7.RB, m7.HKk)
m = m7.m
BASE, LBASE, LWALL, WALLP, WALL = m.BASE, m.LBASE, m.LWALL, m.WALLP, m.WALL
V1, V2 = m.V1, m.V2
B3 = BASE(nt=3, wall=False)
PCk = lambda spec, k: f"pair_coeff {spec} " + HKk(k) + "\n"
# the live pair with lv1 at 1 m/s and lv2 at rest (a pair whose lv2 is held)
IN10 = lambda gap=0.1e-3: IN(gap).replace(f"velocity lv1 set {V1:.10f} 0 0", "velocity lv1 set 1.0 0 0").replace(f"velocity lv2 set {V2:.10f} 0 0", "velocity lv2 set 0 0 0")
STLP = lambda z=0.0, a=0.05: (f"solid floor\n facet normal 0 0 1\n  outer loop\n   vertex {-a} {-a} {z}\n   vertex {a} {-a} {z}\n   vertex {a} {a} {z}\n  endloop\n endfacet\n"
                             f" facet normal 0 0 1\n  outer loop\n   vertex {-a} {-a} {z}\n   vertex {a} {a} {z}\n   vertex {-a} {a} {z}\n  endloop\n endfacet\nendsolid floor\n")
STLF = lambda x0, x1, y0, y1, z: (f"solid face\n facet normal 0 0 -1\n  outer loop\n   vertex {x0} {y0} {z}\n   vertex {x1} {y1} {z}\n   vertex {x1} {y0} {z}\n  endloop\n endfacet\n"
                                  f" facet normal 0 0 -1\n  outer loop\n   vertex {x0} {y0} {z}\n   vertex {x0} {y1} {z}\n   vertex {x1} {y1} {z}\n  endloop\n endfacet\nendsolid face\n")
LW = dict(PAIR="type 1 on wall wprim")

# ================================================================ K: pair_coeff ranges (LAMMPS sets i <= j only) and labels
L("K01_range_2x3_1x2_only_22", "3 types: pair_coeff 2*3 1*2 kn 5000 sets only 2 2 (j from max(jlo,i)): 1 2 stays kn 2000 (0.413)", PCk("2*3 1*2", 5000) + "run 3000\n", pre=B3)
L("K02_star_1_only_11", "pair_coeff * 1 kn 5000 sets only 1 1: 1 2 stays 2000", PCk("* 1", 5000) + "run 3000\n")
L("K03_star_2_sets_12", "pair_coeff * 2 kn 5000 sets 1 2 and 2 2 (5000)", PCk("* 2", 5000) + "run 3000\n")
L("K04_2_1x2_only_22", "pair_coeff 2 1*2 kn 5000 sets only 2 2: 1 2 stays 2000", PCk("2 1*2", 5000) + "run 3000\n")
L("K05_label_swapped_names", "labelmap atom 1 big 2 small (names the wrong way round); pair_coeff small big kn 5000 (2 1: reordered to 1 2: 5000)",
  "labelmap atom 1 big 2 small\n" + PCk("small big", 5000) + "run 3000\n")
L("K06_1x2_then_22", "pair_coeff 1*2 1*2 kn 5000; pair_coeff 2 2 kn 3000 (1 2: 5000)", PCk("1*2 1*2", 5000) + PCk("2 2", 3000) + "run 3000\n")
L("K07_lo_star_hi_star", "3 types: pair_coeff *2 2* kn 4000 (1 2, 1 3, 2 2, 2 3: 4000)", PCk("*2 2*", 4000) + "run 3000\n", pre=B3)
L("K08_numeric_reorder_13", "3 types, lv2 of type 3: pair_coeff 3 1 kn 5000 (reordered to 1 3: 5000)", PCk("3 1", 5000) + "run 3000\n", pre=B3, pair=IN(0.1e-3, t2=3), PAIR="types 1 3")
L("K09_label_in_set_type", "labelmap atom 1 a 2 b; set type b density 5000 (lv2: 0.390)", "labelmap atom 1 a 2 b\nset type b density 5000\nrun 3000\n")
L("K10_var_range_only_22", "variable lo equal 2; pair_coeff ${lo}*3 1*2 kn 5000 (only 2 2: 2000)", "variable lo equal 2\n" + PCk("${lo}*3 1*2", 5000) + "run 3000\n", pre=B3)
L("K11_2_star_only_22", "2 types: pair_coeff 2 * kn 5000 (\"type 2 with all\": only 2 2; 1 2 stays 2000)", PCk("2 *", 5000) + "run 3000\n")
L("K12_star_1x2", "pair_coeff * 1*2 kn 5000 (1 1, 1 2, 2 2: 5000)", PCk("* 1*2", 5000) + "run 3000\n")
L("K13_2x3_1_none", "3 types: pair_coeff 2*3 1 kn 5000 (no pair i <= j: LAMMPS stops)", PCk("2*3 1", 5000) + "run 3000\n", pre=B3)
L("K14_label_range_mixed_swap", "3 types, labelmap atom 1 s 2 b 3 r; lv2 of type 3; pair_coeff r s kn 4000 (reordered 1 3: 4000)",
  "labelmap atom 1 s 2 b 3 r\n" + PCk("r s", 4000) + "run 3000\n", pre=B3, pair=IN(0.1e-3, t2=3), PAIR="types 1 3")
L("K15_label_then_relabel", "labelmap atom 2 b; pair_coeff 1 b kn 5000; labelmap atom 2 c (a second label for 2? or rename); pair_coeff 1 c kn 3000 (3000 if accepted)",
  "labelmap atom 2 b\n" + PCk("1 b", 5000) + "labelmap atom 2 c\n" + PCk("1 c", 3000) + "run 3000\n")

PCm = lambda model: "pair_coeff 1 2 " + model + "\n"
L("K21_default_damping", "pair_coeff 1 2 hooke 2000 3000 tangential ... (no damping keyword: viscoelastic, LAMMPS' default)", PCm("hooke 2000 3000 tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K22_damping_velocity", "pair_coeff 1 2 hooke 2000 0.2 damping velocity (a force 0.2 v, no mass)", PCm("hooke 2000 0.2 damping velocity tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K23_hooke_tsuji", "pair_coeff 1 2 hooke 2000 0.5 damping tsuji (the damping from e 0.5)", PCm("hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K24_hooke_coeff_restitution", "pair_coeff 1 2 hooke 2000 0.5 damping coeff_restitution (e 0.5)", PCm("hooke 2000 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K25_hertz_material_tsuji", "pair_coeff 1 2 hertz/material 1e7 0.5 0.3 damping tsuji", PCm("hertz/material 1e7 0.5 0.3 damping tsuji tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K26_hertz_mass_velocity", "pair_coeff 1 2 hertz 1e6 3000 damping mass_velocity", PCm("hertz 1e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K27_damping_before_tangential_order", "pair_coeff 1 2 hooke 5000 3000 tangential ... damping mass_velocity (damping given last: 5000)", PCm("hooke 5000 3000 tangential linear_nohistory 1 0.3 damping mass_velocity") + "run 3000\n")
L("K28_dmt", "pair_coeff 1 2 dmt 1e7 0.5 0.3 0.0 damping tsuji (an adhesion 0: as hertz/material?)", PCm("dmt 1e7 0.5 0.3 0.0 damping tsuji tangential linear_nohistory 1 0.3") + "run 3000\n")
L("K29_limit_damping_pair", "pair_coeff 1 2 hooke 2000 3000 damping mass_velocity ... limit_damping", PCm("hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 limit_damping") + "run 3000\n")
L("K30_gran_hertz_history", "pair_style gran/hertz/history 2e6 NULL 3000 NULL 0.3 0", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style gran/hertz/history 2e6 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n"))
L("K16_star_then_ii_jj", "pair_coeff * * kn 2000; pair_coeff 1 1 kn 5000; pair_coeff 2 2 kn 5000 (1 2 set by * *: 2000)", PCk("1 1", 5000) + PCk("2 2", 5000) + "run 3000\n")
L("K17_ii_jj_only_mixed", "pair_style granular with only 1 1 kn 2000 and 2 2 kn 5000 given (1 2 mixed)", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK5 + "\n"))
L("K18_restyle_same_keeps", "pc 5000; pair_style granular again (same style: coefficients kept); run (5000)", PC5 + "pair_style granular\nrun 3000\n")
L("K19_gran_hooke_history_resettings", "pair_style gran/hooke/history 2000 ...; pair_coeff * *; pair_style gran/hooke/history 5000 ... again (5000)",
  "pair_style gran/hooke/history 5000 NULL 3000 NULL 0.3 0\nrun 3000\n", pre=BASE(wall=False, pstyle="pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n"))
L("K20_restyle_granular_cutoff", "pc 5000; pair_style granular 0.01 (same style, a cutoff: coefficients kept? 5000)", PC5 + "pair_style granular 0.01\nrun 3000\n")
L("Q16_set_density_atom_var", "variable rho atom 2500+2500*(x>0.02); set group all density v_rho (lv2 right of 0.02: 5000: 0.390)",
  "variable rho atom 2500+2500*(x>0.02)\nset group all density v_rho\nrun 3000\n")
L("Q17_set_diameter_atom_var_mass", "variable m atom 2.82743e-4*(1+(type==2)); set type 2 mass v_m (lv2 mass doubled: 0.390)",
  "variable m atom 2.82743e-4*(1+(type==2))\nset type 2 mass v_m\nrun 3000\n")
L("Q18_set_density_equal_var_of_mass", "variable r equal 2*mass(lv2)/(PI/6*0.006^3) (5000); set atom 2 density ${r} (0.390)",
  "variable r equal 2*mass(lv2)/(PI/6*0.006^3)\nset atom 2 density ${r}\nrun 3000\n")
L("Q19_read_data_then_set_diameter", "write_data d.data; clear; read_data d.data; set type 2 diameter 0.006 (mass kept); set type 2 density 5000 (0.390)",
  "write_data d.data\nclear\n" + m7.m6.MDH.format(f="d.data") + "set type 2 diameter 0.006\nset type 2 density 5000\nrun 3000\n")

# ================================================================ V: formats, variables, if conditions, file names
IFE = lambda cond, a, b: f'if "{cond}" then "' + PCs(a) + '" else "' + PCs(b) + '"\n'
L("V01_if_fmt_e", "if \"$(5000:%e) == 5000\" (5.000000e+03 == 5000: true: 5000)", IFE("$(5000:%e) == 5000", 5000, 3000) + "run 3000\n")
L("V02_if_fmt_1f", "if \"$(4999.96:%.1f) == 5000\" (5000.0: true: 5000)", IFE("$(4999.96:%.1f) == 5000", 5000, 3000) + "run 3000\n")
L("V03_if_fmt_0f_false", "if \"$(4999.4:%.0f) == 5000\" (4999: false: 3000)", IFE("$(4999.4:%.0f) == 5000", 5000, 3000) + "run 3000\n")
L("V04_if_fmt_17g", "if \"$(0.1+0.2:%.17g) == 0.3\" (0.30000000000000004: false: 3000)", IFE("$(0.1+0.2:%.17g) == 0.3", 5000, 3000) + "run 3000\n")
L("V05_if_immediate_default", "if \"$(0.1+0.2) == 0.3\" (the immediate's own format: 3000 if 0.30000000000000004)", IFE("$(0.1+0.2) == 0.3", 5000, 3000) + "run 3000\n")
L("V06_elif_fmt_e", "k = 4500; if k < 3000 ... elif \"$(v_k:%.2e) == 4.50e+03\" kn 4000 else 5000 (4000)",
  "variable k equal 4500\nif \"${k} < 3000\" then \"" + PCs(3000) + "\" elif \"$(v_k:%.2e) == 4.50e+03\" \"" + PCs(4000) + "\" else \"" + PCs(5000) + "\"\nrun 3000\n")
L("V07_if_unary_plus", "if \"+1 > 0\" then kn 5000 else 3000", IFE("+1 > 0", 5000, 3000) + "run 3000\n")
L("V08_if_not_paren", "if \"!(1 > 2)\" then kn 5000 else 3000", IFE("!(1 > 2)", 5000, 3000) + "run 3000\n")
L("V09_round_2p5", "variable k equal 1000*round(2.5)+2000 (half away from zero: 5000; half even: 4000)", "variable k equal 1000*round(2.5)+2000\n" + PCs("${k}") + "\nrun 3000\n")
L("V10_round_immediate_neg", "kn $(6000+1000*round(-0.5)) (-1: 5000; -0: 6000)", PCs("$(6000+1000*round(-0.5))") + "\nrun 3000\n")
L("V11_fmt_0e_half_even", "kn $(4500:%.0e) (4e+03: 4000; 5e+03 if half up)", PCs("$(4500:%.0e)") + "\nrun 3000\n")
L("V12_fmt_0e_35", "kn $(3500:%.0e) (4e+03: 4000)", PCs("$(3500:%.0e)") + "\nrun 3000\n")
L("V13_15g_file_name", "k = 0.1*3*10000 (3000.0000000000005; %.15g: 3000): include pc${k}.in (pc3000.in: kn 3000; a pc3000.0000000000005.in of 5000 beside)",
  "variable k equal 0.1*3*10000\ninclude pc${k}.in\nrun 3000\n", data={"pc3000.in": PC3, "pc3000.0000000000005.in": PC5})
L("V14_15g_third_file", "n = 1/3: include k${n}.in (k0.333333333333333.in: 4000; k0.3333333333333333.in: 5000)",
  "variable n equal 1/3\ninclude k${n}.in\nrun 3000\n", data={"k0.333333333333333.in": PC4, "k0.3333333333333333.in": PC5})
L("V15_immediate_file_name", "include k$(1/3).in (the immediate's format: %.20g? k0.33333333333333331483.in: 4000; %.15g name: 5000)",
  "include k$(1/3).in\nrun 3000\n", data={"k0.33333333333333331483.in": PC4, "k0.333333333333333.in": PC5})
L("V16_index_redefined_ignored", "variable k index 3000; variable k index 5000 (ignored: 3000)", "variable k index 3000\nvariable k index 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V17_delete_then_index", "variable k equal 3000; variable k delete; variable k index 5000 (5000)", "variable k equal 3000\nvariable k delete\nvariable k index 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V18_equal_dollar_frozen", "kk = 3000; k equal ${kk} (3000 then); kk = 5000; kn ${k} (3000)", "variable kk equal 3000\nvariable k equal ${kk}\nvariable kk equal 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V19_equal_vref_live", "kk = 3000; k equal v_kk; kk = 5000; kn ${k} (5000)", "variable kk equal 3000\nvariable k equal v_kk\nvariable kk equal 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V20_string_redefined", "variable k string 3000; variable k string 5000 (5000)", "variable k string 3000\nvariable k string 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V21_one_letter_dollar", "variable k equal 5; kn $k000 ($k then 000: 5000)", "variable k equal 5\n" + PCs("$k000") + "\nrun 3000\n")
L("V22_format_of_later_value", "kk 3000; k format kk %.0f; kk = 4999.7; kn ${k} (5000)", "variable kk equal 3000\nvariable k format kk %.0f\nvariable kk equal 4999.7\n" + PCs("${k}") + "\nrun 3000\n")
L("V23_internal_redefined", "variable k internal 3000; variable k internal 5000 (5000)", "variable k internal 3000\nvariable k internal 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V24_triple_quoted_if", "if \"1 > 0\" then \"\"\"pair_coeff 1 2 kn 5000\"\"\" (5000)", 'if "1 > 0" then """' + PCs(5000) + '"""\nrun 3000\n')
L("V25_continuation_amp", "pair_coeff 1 2 hooke 5000 & (continued on the next line) (5000)", PCs(5000).replace(" 3000 damping", " &\n 3000 damping") + "\nrun 3000\n")
L("V26_index_style_change_error", "variable k string 3000; variable k index 5000 (another style: LAMMPS stops)", "variable k string 3000\nvariable k index 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("V27_loop_pad_file", "variable i loop 8 10 pad (08 09 10); each pass includes pc${i}.in and runs 1000; meets in pass 2 (pc09.in: 4000; a pc9.in of 3000 beside)",
  "variable i loop 8 10 pad\nlabel lp\ninclude pc${i}.in\nrun 1000\nnext i\njump SELF lp\n", pair=IN(G(2)), live="pass 2",
  data={"pc08.in": PC3, "pc09.in": PC4, "pc10.in": PC5, "pc8.in": PC5, "pc9.in": PC3})
L("V28_if_string_compare", "variable s string abc; if \"${s} == abc\" then kn 5000 else 3000", "variable s string abc\n" + IFE("${s} == abc", 5000, 3000) + "run 3000\n")
L("V29_equal_15g_in_if_file", "variable k equal 2.5e3*2 (5000); if \"${k} > 4999\" then \"include hi.in\" else \"include lo.in\" (hi.in 5000)",
  "variable k equal 2.5e3*2\nif \"${k} > 4999\" then \"include hi.in\" else \"include lo.in\"\nrun 3000\n", data={"hi.in": PC5, "lo.in": PC3})
L("V30_fmt_g_in_if", "if \"$(49999.5/10:%g) == 5000\" (%g: 4999.95 -> 4999.95: false: 3000)", IFE("$(49999.5/10:%g) == 5000", 5000, 3000) + "run 3000\n")
L("V31_fmt_3g_in_if", "if \"$(4999.5:%.3g) == 5000\" (5e+03: true: 5000)", IFE("$(4999.5:%.3g) == 5000", 5000, 3000) + "run 3000\n")
L("V32_next_two_vars", "a index 3000 4000 5000, b index x y; next a b (both); kn ${a} (4000)", "variable a index 3000 4000 5000\nvariable b index x y\nnext a b\n" + PCs("${a}") + "\nrun 3000\n")

# ================================================================ Q: set order, ids renumbered, type/ratio, set region after a move
FAR3 = ("create_atoms 1 single 0.005 0.005 0.08\ncreate_atoms 1 single 0.017950 0.02 0.05\ncreate_atoms 2 single 0.023050 0.02 0.05\n"
        "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.004 density 2500\nset atom 3 diameter 0.006 density 2500\n")
VEL = f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\n"
L("Q01_delete_compress_renumber", "a far atom id 1, lv1 id 2, lv2 id 3; delete_atoms group far compress yes (ids made 1 2 again in LAMMPS' order); set atom 2 density 5000 (lv1 or lv2?); groups by region",
  "group far id 1\ndelete_atoms group far compress yes\nset atom 2 density 5000\nregion lft block 0 0.02 0 0.04 0 0.1 units box\nregion rgt block 0.02 0.04 0 0.04 0 0.1 units box\n"
  "group lv1 region lft\ngroup lv2 region rgt\n" + VEL + "run 3000\n", pair=FAR3)
L("Q02_delete_no_compress", "Q01 with compress no: set atom 2 density 5000 hits lv1 (id 2)",
  "group far id 1\ndelete_atoms group far compress no\nset atom 2 density 5000\ngroup lv1 id 2\ngroup lv2 id 3\n" + VEL + "run 3000\n", pair=FAR3)
L("Q03_set_type_ratio", "3 types: set type 2 type/ratio 3 1.0 (lv2 -> type 3); set type 2 density 5000 (nobody); pair 1 3 kn 4000 (0.542)",
  "set type 2 type/ratio 3 1.0 482793\nset type 2 density 5000\n" + PCk("1 3", 4000) + "run 3000\n", pre=B3, PAIR="types 1 3")
L("Q04_set_type_fraction_1", "3 types: set type 2 type/fraction 3 1.0 (all); set type 3 density 5000 (lv2 now type 3: 0.390)",
  "set type 2 type/fraction 3 1.0 482793\nset type 3 density 5000\nrun 3000\n", pre=B3, PAIR="types 1 3")
L("Q05_set_atom_type_then_type_density", "3 types: set atom 2 type 3; set type 2 density 5000 (nobody); 1 3 kn 2000 (0.413)",
  "set atom 2 type 3\nset type 2 density 5000\nrun 3000\n", pre=B3, PAIR="types 1 3")
L("Q06_set_region_after_displace", "region rr x > 0.021 (lv2 there at first); displace_atoms all move -0.01 0 0; set region rr density 5000 (nobody now: 0.413)",
  "region rr block 0.021 0.04 0 0.04 0 0.1 units box\ndisplace_atoms all move -0.01 0 0 units box\nset region rr density 5000\nrun 3000\n")
L("Q07_group_region_static_after_displace", "group right region rr (lv2); displace_atoms all -0.01; set group right density 5000 (still lv2: 0.390)",
  "region rr block 0.021 0.04 0 0.04 0 0.1 units box\ngroup right region rr\ndisplace_atoms all move -0.01 0 0 units box\nset group right density 5000\nrun 3000\n")
L("Q08_set_region_picks_lv1_after_move", "displace_atoms all move 0.005 (lv1 now at x 0.02295); region rr x 0.021..0.025; set region rr density 5000 (lv1 only: lv1 5000)",
  "displace_atoms all move 0.005 0 0 units box\nregion rr block 0.021 0.025 0 0.04 0 0.1 units box\nset region rr density 5000\nrun 3000\n")
L("Q09_mass_then_diameter", "set atom 2 mass 5.65487e-4 (2x); set atom 2 diameter 0.006 (mass kept or remade?)", "set atom 2 mass 5.65487e-4\nset atom 2 diameter 0.006\nrun 3000\n")
L("Q10_set_atom_range_density", "set atom 1*2 density 5000 (both: 5000 each)", "set atom 1*2 density 5000\nrun 3000\n")
L("Q11_set_atom_star_density", "set atom * density 5000 (both)", "set atom * density 5000\nrun 3000\n")
L("Q12_set_type_before_create", "set type 2 diameter 0.006 density 5000 before lv2 exists; lv2 created; set atom 2 diameter 0.006 only (lv2's density: the default?)",
  "run 3000\n", pair="create_atoms 1 single 0.017950 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 5000\n"
  "create_atoms 2 single 0.023050 0.02 0.05\nset atom 2 diameter 0.006\ngroup lv1 id 1\ngroup lv2 id 2\n" + VEL)
L("Q13_set_density_var_fmt", "variable d equal 2500*2; set type 2 density $(v_d:%e) (5.000000e+03: 0.390)", "variable d equal 2500*2\nset type 2 density $(v_d:%e)\nrun 3000\n")
L("Q14_set_group_by_type_after_retype", "group two type 2 (lv2); set atom 2 type 1; set group two density 5000 (still lv2, now type 1: pair 1 1 at 5000)",
  "group two type 2\nset atom 2 type 1\nset group two density 5000\nrun 3000\n", PAIR="types 1 1")
L("Q15_create_atoms_after_delete_reuses_id", "delete lv2 (id 2); create lv2 again (id 2 reused: atom_modify map; a 6 mm of default size?); set atom 2 diameter 0.006 density 5000",
  "group gone id 2\ndelete_atoms group gone\ncreate_atoms 2 single 0.023050 0.02 0.05\nset atom 2 diameter 0.006 density 5000\ngroup lv2b id 2\nvelocity lv2b set " + f"{V2:.10f}" + " 0 0 units box\nrun 3000\n",
  GROUPS="lv1 lv2b")

L("Q20_region_lattice_units_forgot_box", "lattice sc 0.01; region rr block 0.021 0.04 0 0.04 0 0.1 (no units box: lattice units, 0.00021..0.0004 m: nobody); set region rr density 5000 (0.413)",
  "lattice sc 0.01\nregion rr block 0.021 0.04 0 0.04 0 0.1\nset region rr density 5000\nrun 3000\n")
L("Q21_region_lattice_units_scaled", "lattice sc 0.01; region rr block 2.1 4 0 4 0 10 (lattice units: 0.021..0.04 m: lv2); set region rr density 5000 (0.390)",
  "lattice sc 0.01\nregion rr block 2.1 4 0 4 0 10\nset region rr density 5000\nrun 3000\n")
L("Q22_region_moving_var", "run 1000 (no contact yet); region rr block 0.011 0.03 ... move v_dx NULL NULL (dx = 1e-5*step: +0.01 at step 1000: 0.021..0.04, lv2 only); set region rr density 5000; run 3000 (0.390)",
  "run 1000\nvariable dx equal 1e-5*step\nregion rr block 0.011 0.03 0 0.04 0 0.1 move v_dx NULL NULL units box\nset region rr density 5000\nrun 3000\n", pair=IN(G11))
L("Q23_region_side_out", "region rr block 0 0.02 0 0.04 0 0.1 side out units box (x > 0.02: lv2); set region rr density 5000 (0.390)",
  "region rr block 0 0.02 0 0.04 0 0.1 side out units box\nset region rr density 5000\nrun 3000\n")
L("Q24_region_union", "region a sphere at lv2's centre r 1 mm; region b block x < 0.02 (lv1); region u union 2 a b; set region u density 5000 (both: 0.273)",
  "region a sphere 0.02305 0.02 0.05 0.001 units box\nregion b block 0 0.02 0 0.04 0 0.1 units box\nregion u union 2 a b\nset region u density 5000\nrun 3000\n")
L("Q25_region_intersect_none", "region a (lv2's sphere) intersect b (x < 0.02): none (0.413)",
  "region a sphere 0.02305 0.02 0.05 0.001 units box\nregion b block 0 0.02 0 0.04 0 0.1 units box\nregion i intersect 2 a b\nset region i density 5000\nrun 3000\n")
L("Q26_region_cylinder_x", "region c cylinder x 0.02 0.05 0.001 0.021 0.03 units box (lv2's centre inside); set region c density 5000 (0.390)",
  "region c cylinder x 0.02 0.05 0.001 0.021 0.03 units box\nset region c density 5000\nrun 3000\n")
L("Q27_region_plane", "region p plane 0.02 0 0 1 0 0 units box (side in: x >= 0.02: lv2); set region p density 5000 (0.390)",
  "region p plane 0.02 0 0 1 0 0 units box\nset region p density 5000\nrun 3000\n")
L("Q28_group_variable", "variable sel atom x>0.02; group right variable sel (lv2); set group right density 5000 (0.390)",
  "variable sel atom x>0.02\ngroup right variable sel\nset group right density 5000\nrun 3000\n")
L("Q29_group_subtract", "group left region b (x < 0.02: lv1); group right subtract all left (lv2); set group right density 5000 (0.390)",
  "region b block 0 0.02 0 0.04 0 0.1 units box\ngroup left region b\ngroup right subtract all left\nset group right density 5000\nrun 3000\n")
L("Q30_displace_lattice_units", "lattice sc 0.5; displace_atoms all move 0.01 0 0 (lattice units: +0.005 m: lv1 at 0.02295); region rr block 0.021 0.025 units box; set region rr density 5000 (lv1: 0.316)",
  "lattice sc 0.5\ndisplace_atoms all move 0.01 0 0\nregion rr block 0.021 0.025 0 0.04 0 0.1 units box\nset region rr density 5000\nrun 3000\n")
L("Q31_region_rotate_block", "region rr block 0.021 0.025 ... rotate v_a 0.02 0.02 0.05 0 0 1 (a = 180 deg at step 0: the block turned about x 0.02: 0.015..0.019: lv1); set region rr density 5000 (0.316)",
  "variable a equal PI\nregion rr block 0.021 0.025 0.0 0.04 0.0 0.1 rotate v_a 0.02 0.02 0.05 0 0 1 units box\nset region rr density 5000\nrun 3000\n")
L("Q32_read_data_offset_type", "lv1 created (type 1); read_data l2.data add append offset 1 0 0 0 0 (its type 1 atom becomes type 2: 6 mm 5000 kg/m3); groups; run (0.390)",
  "run 3000\n", pair="create_atoms 1 single 0.017950 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nread_data l2.data add append offset 1 0 0 0 0\ngroup lv1 id 1\ngroup lv2 id 2\n" + VEL,
  data={"l2.data": "lv2 at 5000 kg/m3, as type 1 of its own file\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.006 5000 0.023050 0.02 0.05\n"})
L("Q33_read_data_shift", "read_data l2.data add append shift 0.001 0 0 (lv2 type 2 5000 kg/m3, 1 mm further: meets 1 ms later: 0.390)",
  "run 3000\n", pair="create_atoms 1 single 0.017950 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nread_data l2.data add append shift 0.001 0 0\ngroup lv1 id 1\ngroup lv2 id 2\n" + VEL,
  data={"l2.data": "lv2 at 5000 kg/m3\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 5000 0.022050 0.02 0.05\n"})
LG("G37_lig_hooke_stiffness_set_region", "LIGGGHTS hooke/stiffness (mass dependent): region x > 0 (lv2); set region rr density 5000",
   "region rr block 0.0 0.05 -0.05 0.05 -0.01 0.15 units box\nset region rr density 5000\nrun 3000\n", pre=m7.m6.LHS)
LG("G38_lig_hooke_stiffness_region_lattice", "LIGGGHTS hooke/stiffness: lattice sc 0.01; region rr block 0 5 -5 5 -1 15 (lattice units: x > 0: lv2); set region rr density 5000",
   "lattice sc 0.01\nregion rr block 0 5 -5 5 -1 15\nset region rr density 5000\nrun 3000\n", pre=m7.m6.LHS)
LG("G39_lig_hooke_stiffness_control", "LIGGGHTS hooke/stiffness control (lv2 2500)", "run 3000\n", pre=m7.m6.LHS)

# ================================================================ H: pair_style hybrid forms
HY = lambda ps, coeffs: BASE(wall=False, pstyle=f"pair_style {ps}\n", coeff=coeffs)
L("H01_hybrid_zero_12", "pair_style hybrid granular zero 0.01: * * granular; 1 2 zero (no contact: the pair passes)", "run 3000\n",
  pre=HY("hybrid granular zero 0.01", "pair_coeff * * granular " + HK + "\npair_coeff 1 2 zero\n"))
L("H02_hybrid_none_12", "pair_style hybrid granular: 1 1 and 2 2 granular, 1 2 none (no contact)", "run 3000\n",
  pre=HY("hybrid granular zero 0.01", "pair_coeff 1 1 granular " + HK + "\npair_coeff 2 2 granular " + HK + "\npair_coeff 1 2 none\n"))
L("H03_overlay_two_granular", "hybrid/overlay granular granular: 1 and 2 both kn 2000 on all pairs (forces add: kn 4000 damping 6000?)", "run 3000\n",
  pre=HY("hybrid/overlay granular granular", "pair_coeff * * granular 1 " + HK + "\npair_coeff * * granular 2 " + HK + "\n"))
L("H04_scaled_2", "pair_style hybrid/scaled 2.0 granular (forces doubled)", "run 3000\n", pre=HY("hybrid/scaled 2.0 granular", "pair_coeff * * granular " + HK + "\n"))
L("H05_scaled_1", "pair_style hybrid/scaled 1.0 granular (as plain: 0.413)", "run 3000\n", pre=HY("hybrid/scaled 1.0 granular", "pair_coeff * * granular " + HK + "\n"))
L("H06_overlay_granular_lj", "hybrid/overlay granular lj/cut 0.01; pair_coeff 1 2 lj/cut 1e-5 0.005 (an extra force on the pair)", "run 3000\n",
  pre=HY("hybrid/overlay granular lj/cut 0.01", "pair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0 0.005\npair_coeff 1 2 lj/cut 1e-5 0.005\n"))
L("H07_hybrid_gran_hooke_on_12", "hybrid granular gran/hooke 5000 NULL 3000 NULL 0.3 0: 1 2 by gran/hooke (5000)", "run 3000\n",
  pre=HY("hybrid granular gran/hooke 5000 NULL 3000 NULL 0.3 0", "pair_coeff * * granular " + HK + "\npair_coeff 1 2 gran/hooke\n"))
L("H08_hybrid_soft_others_gran_12", "hybrid granular soft 0.01: * * soft 0; 1 2 granular kn 5000 (5000)", "run 3000\n",
  pre=HY("hybrid granular soft 0.01", "pair_coeff * * soft 0.0\npair_coeff 1 2 granular " + HK5 + "\n"))
L("H09_overlay_soft_zero", "hybrid/overlay granular soft 0.01; soft 0.0 on all (adds nothing: 0.413)", "run 3000\n",
  pre=HY("hybrid/overlay granular soft 0.01", "pair_coeff * * granular " + HK + "\npair_coeff * * soft 0.0\n"))
L("H10_hybrid_granular_twice", "hybrid granular granular: 1 1, 2 2 granular 1 (2000); 1 2 granular 2 kn 5000 (5000)", "run 3000\n",
  pre=HY("hybrid granular granular", "pair_coeff 1 1 granular 1 " + HK + "\npair_coeff 2 2 granular 1 " + HK + "\npair_coeff 1 2 granular 2 " + HK5 + "\n"))
L("H11_overlay_zero_all", "hybrid/overlay granular zero 0.01; zero on all (adds nothing: 0.413)", "run 3000\n",
  pre=HY("hybrid/overlay granular zero 0.01", "pair_coeff * * granular " + HK + "\npair_coeff * * zero\n"))
L("H12_scaled_var", "variable s equal 0.5; hybrid/scaled v_s granular (forces halved)", "run 3000\n",
  pre="variable s equal 0.5\n" + HY("hybrid/scaled v_s granular", "pair_coeff * * granular " + HK + "\n"))
L("H13_scaled_two_granular", "hybrid/scaled 0.5 granular 0.5 granular (halves of the same: kn 2000 total: 0.413?)", "run 3000\n",
  pre=HY("hybrid/scaled 0.5 granular 0.5 granular", "pair_coeff * * granular 1 " + HK + "\npair_coeff * * granular 2 " + HK + "\n"))
L("H14_hybrid_restyle_to_plain", "hybrid granular zero (1 2 zero); then pair_style granular; pair_coeff * * kn 5000 (5000)", "pair_style granular\npair_coeff * * " + HK5 + "\nrun 3000\n",
  pre=HY("hybrid granular zero 0.01", "pair_coeff * * granular " + HK + "\npair_coeff 1 2 zero\n"))

# ================================================================ D: fixes that change the pair's motion
L("D01_freeze_lv2", "fix freeze lv2 (lv2 at rest, lv1 at 1 m/s): pair granular takes meff = m1 for a frozen partner", "fix fz lv2 freeze\nrun 3000\n", pair=IN10())
L("D02_setforce_lv2_zero", "fix setforce lv2 0 0 0 (lv2 at rest, lv1 1 m/s; lv2 held, meff still m1 m2/(m1+m2))", "fix sf lv2 setforce 0.0 0.0 0.0\nrun 3000\n", pair=IN10())
L("D03_setforce_z_only", "fix setforce lv2 NULL NULL 0.0 (z only: the x contact as ever: 0.413)", "fix sf lv2 setforce NULL NULL 0.0\nrun 3000\n")
L("D04_viscous_all", "fix viscous all 0.01 (drag through the contact)", "fix visc all viscous 0.01\nrun 3000\n")
L("D05_viscous_zero", "fix viscous all 0.0 (no drag: 0.413)", "fix visc all viscous 0.0\nrun 3000\n")
L("D06_langevin_t0", "fix langevin all 0 0 0.001 48279 (T 0: a drag of damp 1 ms)", "fix lang all langevin 0.0 0.0 0.001 48279\nrun 3000\n")
L("D07_nve_limit_loose", "unfix integ; fix integ all nve/limit 0.01 (never limits: 0.413)", "unfix integ\nfix integ all nve/limit 0.01\nrun 3000\n")
L("D08_nve_limit_tight", "unfix integ; fix integ all nve/limit 2e-7 (limits 0.77 m/s steps of 7.7e-7 m)", "unfix integ\nfix integ all nve/limit 2e-7\nrun 3000\n")
L("D09_second_integrator_lv2", "fix integ all nve/sphere and fix i2 lv2 nve (lv2 moved twice a step)", "fix i2 lv2 nve\nrun 3000\n")
L("D10_only_lv1_integrated", "unfix integ; fix integ lv1 nve/sphere (lv2 at rest never moves; lv1 at 1 m/s)", "unfix integ\nfix integ lv1 nve/sphere\nrun 3000\n", pair=IN10())
L("D11_move_lv2_still", "unfix integ; fix integ lv1 nve/sphere; fix mv lv2 move linear 0 0 0 (lv2 held by fix move; lv1 at 1 m/s)",
  "unfix integ\nfix integ lv1 nve/sphere\nfix mv lv2 move linear 0 0 0\nrun 3000\n", pair=IN10())
L("D12_adapt_diameter_mass", "variable d equal 0.008; fix adapt lv2 atom diameter v_d (mass yes: lv2 8 mm 2500 kg/m3 in the run; neighbor skin 3 mm so the larger sphere is seen in time)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d\nrun 3000\n", pair=IN(1.1e-3), SEP="0.006")
L("D13_adapt_diameter_no_mass", "fix adapt lv2 atom diameter v_d mass no (8 mm, the 6 mm mass: 0.413)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d mass no\nrun 3000\n", pair=IN(1.1e-3), SEP="0.006")
L("D14_exclude_type_12", "neigh_modify exclude type 1 2 (no contact: the pair passes)", "neigh_modify exclude type 1 2\nrun 3000\n")
L("D15_exclude_then_none", "neigh_modify exclude type 1 2; neigh_modify exclude none (contact: 0.413)", "neigh_modify exclude type 1 2\nneigh_modify exclude none\nrun 3000\n")
L("D16_exclude_group", "neigh_modify exclude group lv1 lv2 (no contact)", "neigh_modify exclude group lv1 lv2\nrun 3000\n")
L("D17_nve_plain", "unfix integ; fix integ all nve (no rotation: head-on 0.413)", "unfix integ\nfix integ all nve\nrun 3000\n")
L("D18_two_nve_sphere", "a second fix nve/sphere on all (every sphere moved twice)", "fix integ2 all nve/sphere\nrun 3000\n")
L("D19_freeze_lv2_moving", "fix freeze lv2 with lv2 moving at -0.2286 m/s (freeze zeroes force, keeps velocity)", "fix fz lv2 freeze\nrun 3000\n")
L("D20_adapt_diameter_reset_then_run", "fix adapt diameter 8 mm (mass yes, reset yes) in run 1 (no contact), unfix; run 2 (meets, 6 mm again?)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d\nrun 100\nunfix ad\nrun 3000\n", pair=IN(1.1e-3))
L("D23_adapt_scale_yes", "fix adapt lv2 atom diameter v_f scale yes (f = 4/3: 8 mm, mass yes: 0.386)",
  "neighbor 0.003 bin\nvariable f equal 4/3\nfix ad lv2 adapt 0 atom diameter v_f scale yes\nrun 3000\n", pair=IN(1.1e-3), SEP="0.006")
L("D24_adapt_reset_no_then_set_density", "fix adapt lv2 diameter 8 mm mass no reset no; run 100 (no contact); unfix; set atom 2 density 2500 (now from the 8 mm volume); run 3000 (0.386?)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d mass no reset no\nrun 100\nunfix ad\nset atom 2 density 2500\nrun 3000\n", pair=IN(1.2e-3), SEP="0.006")
L("D25_adapt_reset_yes_then_set_density", "D24 with reset yes (the diameter back to 6 mm after run 1; set density: the 6 mm mass; 0.413?)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d mass no reset yes\nrun 100\nunfix ad\nset atom 2 density 2500\nrun 3000\n", pair=IN(1.2e-3))
L("D26_adapt_reset_no_mass_yes_then_write_data", "fix adapt lv2 8 mm (mass yes, reset no); run 100; unfix; write_data d.data; clear; read_data d.data; run 3000 (8 mm 2500: 0.386)",
  "neighbor 0.003 bin\nvariable d equal 0.008\nfix ad lv2 adapt 0 atom diameter v_d reset no\nrun 100\nunfix ad\nwrite_data d.data\nclear\n" + m7.m6.MDH.format(f="d.data") + "neighbor 0.003 bin\nrun 3000\n",
  pair=IN(1.2e-3), SEP="0.006")
L("D21_addforce_lv1", "fix addforce lv1 0.05 0 0 (a push toward lv2 through the contact)", "fix af lv1 addforce 0.05 0.0 0.0\nrun 3000\n")
L("D22_exclude_in_every", "run 2000 every 1000 \"neigh_modify exclude type 1 2\" (exclusion after part 1; meets in part 2: passes)",
  "run 2000 every 1000 \"neigh_modify exclude type 1 2\"\n", pair=IN(G(2)), live="part 2")

# ================================================================ U: runs in parts, minimize, replicate, change_box, displace, velocity
L("U01_start_stop_then_pc", "run 1000 start 0 stop 5000; pc 5000; run 3000 (5000)", "run 1000 start 0 stop 5000\n" + PC5 + "run 3000\n", pair=IN(G11))
L("U02_minimize_before", "min_style cg; minimize 0 0 10 10 (no overlap); run 3000 (0.413)", "min_style cg\nminimize 0 0 10 10\nrun 3000\n")
L("U03_every_set_density", "run 2000 every 1000 \"set atom 2 density 5000\" (meets in part 2: 0.390)", "run 2000 every 1000 \"set atom 2 density 5000\"\n", pair=IN(G(2)), live="part 2")
L("U04_every_set_density_step", "run 3000 every 1000 \"set atom 2 density $(2500+2.5*step)\" (part 2: 5000)", "run 3000 every 1000 \"set atom 2 density $(2500+2.5*step)\"\n", pair=IN(G(2)), live="part 2")
L("U05_replicate_211", "run 0; replicate 2 1 1 (a copy 0.04 away); run 3000 (0.413)", "run 0\nreplicate 2 1 1\nrun 3000\n")
L("U06_change_box_final", "change_box all x final 0 0.05 units box; run 3000", "change_box all x final 0 0.05 units box\nrun 3000\n")
L("U07_change_box_boundary", "change_box all boundary f f f; run 3000", "change_box all boundary f f f\nrun 3000\n")
L("U08_displace_lv2", "displace_atoms lv2 move 0.001 0 0 (meets 1 ms later: 0.413)", "displace_atoms lv2 move 0.001 0 0 units box\nrun 3000\n")
L("U09_velocity_null", "velocity lv1 set NULL 0 0 units box (x kept)", "velocity lv1 set NULL 0 0 units box\nrun 3000\n")
L("U10_processors", "processors 1 1 1 first; run 3000", "run 3000\n", pre=BASE(wall=False, head="processors 1 1 1\n"))
L("U11_clear_second_pass", "a first deck with kn 2000 run 100; clear; the same deck again with kn 5000 (5000)",
  "run 100\nclear\n" + BASE(wall=False, coeff="pair_coeff * * " + HK5 + "\n") + IN(0.1e-3) + "run 3000\n", pair=IN(5e-3))
L("U12_restart_remap", "run 1000; write_restart a.rst; clear; read_restart a.rst remap; pair again kn 5000 (5000)",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst remap\npair_style granular\npair_coeff * * " + HK5 + "\n" + TAILR + "run 3000\n", pair=IN(G11))
L("U13_run_post_no_pre_no", "run 500 post no; pc 5000; run 3000 pre no (pre no after a pair_coeff: LAMMPS sets up? kn 5000 or 2000)",
  "run 500 post no\n" + PC5 + "run 3000 pre no\n", pair=IN(0.6e-3))
L("U14_every_null_preno_loop", "loop 2 { run 1000 every 500 NULL }; pc 5000; run 3000 (5000)", "variable i loop 2\nlabel lp\nrun 1000 every 500 NULL\nnext i\njump SELF lp\n" + PC5 + "run 3000\n",
  pair=IN(2.1e-3))
L("U15_delete_overlap_none", "delete_atoms overlap 0.0045 all all (none that close: 0.413)", "delete_atoms overlap 0.0045 all all\nrun 3000\n")
L("U16_reset_timestep_if_step", "run 1000; reset_timestep 0; if \"$(step) < 500\" then pc 5000 else pc 3000 (5000)",
  "run 1000\nreset_timestep 0\n" + IFE("$(step) < 500", 5000, 3000) + "run 3000\n", pair=IN(G11))
L("U17_velocity_zero_linear", "velocity all zero linear (momentum already 0: 0.413)", "velocity all zero linear\nrun 3000\n")
L("U18_upto_after_reset", "reset_timestep 5000; run 8000 upto (3000 steps; 0.413)", "reset_timestep 5000\nrun 8000 upto\n")
L("U19_run_every_pc_then_restart", "run 2000 every 1000 \"pc 5000\"; write_restart a.rst; clear; read_restart a.rst (pair_coeff kept in the file? pair granular writes its coeffs); run 3000",
  "run 2000 every 1000 \"" + PCs(5000) + "\"\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + TAILR + "run 3000\n", pair=IN(2.1e-3 + 1e-3))
L("U20_timestep_change_between", "run 1000; timestep 2e-6; run 2000 (meets at dt 2e-6: 0.413)", "run 1000\ntimestep 2e-6\nrun 2000\n", pair=IN(G11 + 0.1e-3))

# ================================================================ W: LAMMPS walls
WB = lambda nt=2, wall="", wall_coeff=HK: BASE(nt=nt, wall=False, coeff="pair_coeff * * " + wall_coeff + "\n") + wall
L("W01_type3_no_atoms_floor_kn5000", "3 types (type 3 has no atoms), floor wall/gran granular kn 5000 (WALL)", "run 3000\n",
  pre=WB(3, "fix floor all wall/gran granular " + HK5 + " zplane 0 NULL\n"), pair=WALLP(), **WALL)
L("W02_cylinder_region_side_in", "WALLX: wall/gran/region on a z cylinder (r 0.015 about 0.02 0.02), lv1 moving +x at 1 m/s into it", "run 3000\n",
  pre=WB(2, "region cyl cylinder z 0.02 0.02 0.015 0 0.1 side in units box\nfix cw all wall/gran/region granular " + HKk(4000) + " region cyl\n"),
  pair="create_atoms 1 single 0.0329 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\n",
  PAIR="type 1 on wall cw", WALLX="")
L("W03_floor_shear_x", "WALL: floor wall/gran zplane with shear x 0.1 (normal as ever)", "run 3000\n",
  pre=WB(2, "fix floor all wall/gran granular " + HK + " zplane 0 NULL shear x 0.1\n"), pair=WALLP(), **WALL)
L("W04_plane_region_floor", "WALL: wall/gran/region on a plane region (point 0 0 0, normal 0 0 1), kn 4000", "run 3000\n",
  pre=WB(2, "region pl plane 0 0 0 0 0 1 side in units box\nfix floor all wall/gran/region granular " + HKk(4000) + " region pl\n"), pair=WALLP(), **WALL)
L("W05_two_floors", "WALL: two floors at z 0 (fix floor and fix floor2, kn 2000 each: forces add)", "run 3000\n",
  pre=WB(2, "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nfix floor2 all wall/gran granular " + HK + " zplane 0 NULL\n"), pair=WALLP(), **WALL)
L("W06_floor_limit_damping", "WALL: floor hooke kn 2000 with limit_damping", "run 3000\n",
  pre=WB(2, "fix floor all wall/gran granular " + HK + " limit_damping zplane 0 NULL\n"), pair=WALLP(), **WALL)
L("W07_floor_group_lv2_only", "WALL: floor fix on group lv2 only (lv1 falls through: no wall contact for lv1)", "group lv2x id 2\nfix floor lv2x wall/gran granular " + HK + " zplane 0 NULL\nrun 3000\n",
  pre=WB(2), pair=WALLP(), **WALL)
L("W08_floor_wiggle", "WALL: floor wiggle z 1e-6 0.01 (a tiny motion)", "run 3000\n",
  pre=WB(2, "fix floor all wall/gran granular " + HK + " zplane 0 NULL wiggle z 1e-6 0.01\n"), pair=WALLP(), **WALL)
L("W09_floor_gran_hooke_history", "WALL: wall/gran hooke/history 5000 NULL 3000 NULL 0.3 0 (the old style)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n") +
  "fix floor all wall/gran hooke/history 5000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n", pair=WALLP(), **WALL)

L("W10_region_harmonic_near_floor", "WALL: fix wall/region on a region filling the box, harmonic eps 20 cutoff 2.5 mm (a soft push within 2.5 mm of the floor the granular floor stands on)",
  "region cage block 0 0.04 0 0.04 0 0.1 units box\nfix soft all wall/region cage harmonic 20.0 0.0 0.0025\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
L("W11_region_harmonic_near_floor_weak", "WALL: W10 with eps 0.02 (a weak push: about the floor's own)",
  "region cage block 0 0.04 0 0.04 0 0.1 units box\nfix soft all wall/region cage harmonic 0.02 0.0 0.0025\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
L("W12_region_lj93_near_floor", "WALL: fix wall/region cage lj93 1e-4 0.001 0.0025 (an LJ 9-3 container wall at the floor)",
  "region cage block 0 0.04 0 0.04 0 0.1 units box\nfix soft all wall/region cage lj93 1e-4 0.001 0.0025\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
L("W13_wall_harmonic_zlo", "WALL: fix wall/harmonic zlo EDGE 20.0 0.0 0.0025 (the same push from a plain wall fix)",
  "fix soft all wall/harmonic zlo EDGE 20.0 0.0 0.0025\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
L("W14_region_harmonic_pair_near_face", "the pair beside a region face: region block x < 0.0265 (lv2's centre 3.45 mm inside), harmonic eps 5 cutoff 5 mm on lv2",
  "region cage block 0 0.0265 0 0.04 0 0.1 units box\nfix soft all wall/region cage harmonic 5.0 0.0 0.005\nrun 3000\n")
L("W15_region_cylinder_lj93_pair", "the pair inside a z cylinder region (r 6 mm about lv2's centre... about 0.0205 0.02), fix wall/region lj93 1e-4 0.001 0.0025",
  "region cyl cylinder z 0.0205 0.02 0.006 0 0.1 units box\nfix soft all wall/region cyl lj93 1e-4 0.001 0.0025\nrun 3000\n")
L("W17_region_cylinder_lj93_pair_near", "the pair inside a z cylinder region of radius 4.5 mm about 0.0205 0.02 (each centre 1.95 mm from its face), fix wall/region lj93 1e-4 0.001 0.0025",
  "region cyl cylinder z 0.0205 0.02 0.0045 0 0.1 units box\nfix soft all wall/region cyl lj93 1e-4 0.001 0.0025\nrun 3000\n")
L("W18_region_sphere_out_obstacle_floor", "WALL: a spherical obstacle region side out (centre 0.02 0.02 -0.0475, r 0.048: its top 0.5 mm above the floor under lv1), fix wall/region harmonic 20 0 0.002",
  "region obs sphere 0.02 0.02 -0.0475 0.048 side out units box\nfix soft all wall/region obs harmonic 20.0 0.0 0.002\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
LG("W19_lig_region_lj93_pair", "LIGGGHTS: the pair inside a z cylinder region of radius 4.5 mm about its contact point, fix wall/region lj93 1e-4 0.001 0.0025 (e 0.5)",
   "region cyl cylinder z -0.0005 0 0.0045 -0.01 0.15 units box\nfix soft all wall/region cyl lj93 1e-4 0.001 0.0025\nrun 3000\n")
L("W20_region_harmonic_floor_minimal", "WALL (minimal): lv1 starts 1 mm above the floor (above the 2.5 mm reach of the region wall's push); fix wall/region on the box's block, harmonic 20 0 0.0025",
  "region cage block 0 0.04 0 0.04 0 0.1 units box\nfix soft all wall/region cage harmonic 20.0 0.0 0.0025\nrun 4000\n", pre=BASE(), pair=WALLP(1e-3), **WALL)
LG("W16_lig_region_lj93_near_floor", "LIGGGHTS WALL: primitive floor (type 3, e 0.7) and fix wall/region lj93 on a box-filling region near it",
   "region cage block -0.05 0.05 -0.05 0.05 0.0 0.15 units box\nfix soft all wall/region cage lj93 1e-4 0.001 0.0025\nrun 3000\n", pair=LWALL(1e-4), **LW)

# ================================================================ S: sizes
POUR = lambda spec, t=1: ("region pr block 0.005 0.035 0.005 0.035 0.08 0.095 units box\n"
                          f"fix p all pour 5 {t} 4767548 region pr {spec}\n")
L("S01_pour_range_type2", "fix pour type 2 diam range 0.004 0.008 dens 2500 2500 + the 6 mm lv2", POUR("diam range 0.004 0.008 dens 2500 2500", 2) + "run 3000\n")
L("S02_create_random_type2_set_type", "create_atoms 2 random 3 seed in a far region; set type 2 diameter 0.006 density 2500 (all alike: 0.413)",
  "region far block 0.002 0.012 0.002 0.012 0.08 0.095 units box\ncreate_atoms 2 random 3 48271 far\nset type 2 diameter 0.006 density 2500\nrun 3000\n")
L("S03_far_heavy_type2", "a far type 2 of 6 mm at density 8000 (type 2 masses 2500 and 8000)", "create_atoms 2 single 0.005 0.005 0.08\nset atom 3 diameter 0.006 density 8000\nrun 3000\n")
L("S04_pour_dens_range_type2", "fix pour type 2 diam one 0.006 dens 1000 8000 (masses vary)", POUR("diam one 0.006 dens 1000 8000", 2) + "run 3000\n")
L("S05_set_region_far_density", "a far type 2 at 6 mm; set region far density 5000 (only the far one: lv2 2500)",
  "create_atoms 2 single 0.005 0.005 0.08\nset atom 3 diameter 0.006 density 2500\nregion far block 0 0.01 0 0.01 0.07 0.09 units box\nset region far density 5000\nrun 3000\n")

# ================================================================ G: LIGGGHTS
LB = lambda e=None, **kw: LBASE(e=e or "0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", **kw)
LG("G01_e_one", "LIGGGHTS e 1 2 = 1.0", "run 3000\n", pre=LB("0.6 1.0 0.7 1.0 0.4 0.45 0.7 0.45 0.8"))
LG("G02_e_0999", "LIGGGHTS e 1 2 = 0.999", "run 3000\n", pre=LB("0.6 0.999 0.7 0.999 0.4 0.45 0.7 0.45 0.8"))
LG("G03_e_006", "LIGGGHTS e 1 2 = 0.06 (very low; 0.05 is refused by LIGGGHTS)", "run 3000\n", pre=LB("0.6 0.06 0.7 0.06 0.4 0.45 0.7 0.45 0.8"))
LG("G04_n_from_var", "LIGGGHTS peratomtypepair ${n} (n equal 3), e 1 2 0.8", "run 3000\n",
   pre="variable n equal 3\n" + LB("0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8").replace("coefficientRestitution peratomtypepair 3", "coefficientRestitution peratomtypepair ${n}"))
LG("G05_entries_from_vars", "LIGGGHTS matrix entries ${e12} (0.8)", "run 3000\n",
   pre="variable e12 equal 0.8\n" + LB("0.6 ${e12} 0.7 ${e12} 0.4 0.45 0.7 0.45 0.8"))
LG("G06_asymmetric_matrix", "LIGGGHTS e 1 2 = 0.6, e 2 1 = 0.8 (an asymmetric matrix)", "run 3000\n", pre=LB("0.6 0.6 0.7 0.8 0.4 0.45 0.7 0.45 0.8"))
LG("G07_rows_as_strings", "LIGGGHTS rows from string variables r1 r2 r3 (e 1 2 0.8)", "run 3000\n",
   pre='variable r1 string "0.6 0.8 0.7"\nvariable r2 string "0.8 0.4 0.45"\nvariable r3 string "0.7 0.45 0.8"\n' + LB("${r1} ${r2} ${r3}"))
LG("G08_tangential_damping_off", "LIGGGHTS hertz tangential history tangential_damping off (normal e 0.5)", "run 3000\n",
   pre=LB().replace("pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history tangential_damping off\n"))
LG("G09_rolling_cdt", "LIGGGHTS rolling_friction cdt (coefficientRollingFriction 0.1): e 0.5", "run 3000\n",
   pre=LB(extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n").replace(
       "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history rolling_friction cdt\n"))
LG("G10_rolling_epsd2", "LIGGGHTS rolling_friction epsd2: e 0.5", "run 3000\n",
   pre=LB(extra="fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n").replace(
       "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history rolling_friction epsd2\n"))
LG("G11_cohesion_sjkr", "LIGGGHTS cohesion sjkr, cohesionEnergyDensity 20000 (an attraction: eps below e)", "run 3000\n",
   pre=LB(extra="fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 20000 20000 20000 20000 20000 20000 20000 20000 20000\n").replace(
       "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history cohesion sjkr\n"))
LG("G12_cohesion_sjkr_zero", "LIGGGHTS cohesion sjkr with cohesionEnergyDensity 0 (e 0.5)", "run 3000\n",
   pre=LB(extra="fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 0 0 0 0 0\n").replace(
       "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history cohesion sjkr\n"))
LG("G13_limitforce_e05", "LIGGGHTS hertz limitForce on, e 0.5", "run 3000\n",
   pre=LB().replace("pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history limitForce on\n"))
LG("G14_hooke_e_one", "LIGGGHTS hooke (characteristicVelocity 1), e 1 2 = 1.0", "run 3000\n",
   pre=LB("0.6 1.0 0.7 1.0 0.4 0.45 0.7 0.45 0.8", model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n"))
LG("G15_insert_pack_type1_range", "LIGGGHTS insert/pack of type 1 radii 1.5 and 3 mm far above (hertz e 0.5)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003\n"
   "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion bc block -0.04 0.04 -0.04 0.04 0.13 0.145 units box\n"
   "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 6 region bc\nrun 3000\n")
LG("G16_insert_stream_face", "LIGGGHTS insert/stream from an STL face far from the pair (types 1 and 2 templates; e 0.5)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2500 radius constant 0.0025\n"
   "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
   "fix inface all mesh/surface file face.stl type 1\n"
   "fix ins all insert/stream seed 32452867 distributiontemplate pdd1 nparticles 4 massrate 0.1 overlapcheck yes vel constant 0 0 -0.1 insertion_face inface extrude_length 0.01\nrun 3000\n",
   data={"face.stl": STLF(0.02, 0.045, -0.045, -0.02, 0.14)})
LG("G17_three_templates_type2", "LIGGGHTS three templates of type 2 (radii 1, 3, 5 mm; weights 0.2 0.3 0.5), insert/pack far above (e 0.5)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 2500 radius constant 0.001\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1000 radius constant 0.003\n"
   "fix pts3 all particletemplate/sphere 49979693 atom_type 2 density constant 2500 radius constant 0.005\n"
   "fix pdd1 all particledistribution/discrete 32452843 3 pts1 0.2 pts2 0.3 pts3 0.5\nregion bc block -0.04 0.04 -0.04 0.04 0.13 0.145 units box\n"
   "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 6 region bc\nrun 3000\n")
MESHW = lambda t=3, f="floor.stl", extra="": (f"fix cad all mesh/surface file {f} type {t}{extra}\n"
                                             "fix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")
LG("G18_mesh_floor_type3", "LIGGGHTS WALL: lv1 falls on a mesh floor (STL at z 0) of type 3: e 1 3 0.7", MESHW() + "run 3000\n",
   pre=LB(wall=False), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("G19_mesh_type2_walls_only", "LIGGGHTS WALL: mesh of type 2 (walls-only type; spheres type 1): e 1 2 0.65", MESHW(2) + "run 3000\n",
   pre=LB("0.6 0.65 0.7 0.65 0.4 0.45 0.7 0.45 0.8", wall=False), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("G20_mesh_scale_mm", "LIGGGHTS WALL: a floor STL in mm, scale 0.001 (e 1 3 0.7)", MESHW(3, "floor_mm.stl", " scale 0.001") + "run 3000\n",
   pre=LB(wall=False), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor_mm.stl": STLP(0.0, 50)})
LG("G21_mesh_plus_primitive", "LIGGGHTS WALL: mesh floor and primitive zplane 0 both (type 3; forces add?)", MESHW() + "run 3000\n",
   pre=LB(), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("G22_freeze_lv2", "LIGGGHTS fix freeze lv2 (lv2 at rest, lv1 1 m/s; e 0.5)", "fix fz lv2 freeze\nrun 3000\n",
   pair=LIN(0.1e-3).replace(f"velocity lv1 set {V1:.10f} 0 0", "velocity lv1 set 1.0 0 0").replace(f"velocity lv2 set {V2:.10f} 0 0", "velocity lv2 set 0 0 0"))
LG("G23_exclude_type_12", "LIGGGHTS neigh_modify exclude type 1 2 (no contact)", "neigh_modify exclude type 1 2\nrun 3000\n")
LG("G24_two_e_fixes", "LIGGGHTS a second coefficientRestitution fix (m3b, e 1 2 0.8) beside m3 (0.5): which one?", LEe(0.8).replace("fix m3 ", "fix m3b ") + "run 3000\n")
LG("G25_e_refix_between_runs", "LIGGGHTS run 100 (no contact); unfix m3; fix m3 e 1 2 0.8; run 3000 (0.8)", "run 100\nunfix m3\n" + LEe(0.8) + "run 3000\n", pair=LIN(0.2e-3))
LG("G26_e_continuation", "LIGGGHTS coefficientRestitution matrix over three lines with & (e 1 2 0.8)", "run 3000\n",
   pre=LB().replace("coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", "coefficientRestitution peratomtypepair 3 &\n 0.6 0.8 0.7 &\n 0.8 0.4 0.45 &\n 0.7 0.45 0.8"))
LG("G27_viscous", "LIGGGHTS fix viscous all 0.01 (drag)", "fix visc all viscous 0.01\nrun 3000\n")
LG("G28_set_density_hertz", "LIGGGHTS set atom 2 density 5000 (hertz e 0.5 any mass)", "set atom 2 density 5000\nrun 3000\n")
LG("G29_e_fmt_immediate", "LIGGGHTS e 1 2 $(0.85:%.1f) (0.8: 0.85 is 0.8499999 in binary)", "run 3000\n", pre=LB("0.6 $(0.85:%.1f) 0.7 $(0.85:%.1f) 0.4 0.45 0.7 0.45 0.8"))
LG("G30_atomtypepair_form", "LIGGGHTS coefficientRestitution atomtypepair 3 (the older keyword) e 1 2 0.8", "run 3000\n",
   pre=LB("0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8").replace("coefficientRestitution peratomtypepair", "coefficientRestitution atomtypepair"))
LG("G31_hooke_limitforce_e_low", "LIGGGHTS hooke limitForce on (characteristicVelocity 1), e 1 2 0.3", "run 3000\n",
   pre=LB("0.6 0.3 0.7 0.3 0.4 0.45 0.7 0.45 0.8", model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n").replace(
       "pair_style gran model hooke tangential history\n", "pair_style gran model hooke tangential history limitForce on\n"))
LG("G32_e_in_if", "LIGGGHTS if \"1 > 0\" then \"fix m3 ... e 0.8\" (0.8)", "if \"1 > 0\" then \"" + LE.format(e="0.8") + "\"\nrun 3000\n")
LG("G33_e_loop_last", "LIGGGHTS loop i 3: e 1 2 $(0.5+0.1*v_i) then run 200 (meets in pass 3: 0.8)",
   "variable i loop 3\nlabel lp\n" + LE.format(e="$(0.5+0.1*v_i)") + "\nrun 1000\nnext i\njump SELF lp\n", pair=LIN(G(3)), live="pass 3")
LG("G34_insert_pack_type2_sizes", "LIGGGHTS insert/pack of type 2 radii 2 and 4 mm far above + the 3 mm lv2 (hooke: mass dependent? e fixed: 0.5)",
   m7.m6.INS(0.002, 0.004).replace("atom_type 1", "atom_type 2") + "run 3000\n",
   pre=LB(model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n"))
LG("G35_mesh_type_var", "LIGGGHTS WALL: mesh type ${wt} (wt 3) e 1 3 0.7", "variable wt equal 3\n" + MESHW("${wt}") + "run 3000\n",
   pre=LB(wall=False), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("G36_wall_type_label_primitive_type2", "LIGGGHTS WALL: primitive wall type 2 and e 1 2 0.65 (walls-only type 2; spheres type 1)", "run 3000\n",
   pre=LB("0.6 0.65 0.7 0.65 0.4 0.45 0.7 0.45 0.8").replace("primitive type 3", "primitive type 2"), pair=LWALL(1e-4), **LW)

# ================================================================ X: further fixes that act on the pair's atoms (flagged or not?)
L("X01_aveforce_all", "fix aveforce all 0.0 NULL NULL (x forces averaged over the pair: 0 each: no bounce)", "fix avf all aveforce 0.0 NULL NULL\nrun 3000\n")
L("X02_spring_self_lv2", "fix spring/self lv2 10.0 (a tether on lv2)", "fix ss lv2 spring/self 10.0\nrun 3000\n")
L("X03_temp_rescale", "fix temp/rescale 10 1e20 1e20 0.1 1.0 (rescales the pair's kinetic energy every 10 steps)", "fix tr all temp/rescale 10 1e20 1e20 0.1 1.0\nrun 3000\n")
L("X04_temp_berendsen", "fix temp/berendsen all 1e20 1e20 1e-4 (scales velocities every step)", "fix tb all temp/berendsen 1e20 1e20 1e-4\nrun 3000\n")
L("X05_nvt_sphere", "unfix integ; fix integ all nvt/sphere temp 1e20 1e20 1e-4 (a thermostatted integrator)", "unfix integ\nfix integ all nvt/sphere temp 1e20 1e20 1e-4\nrun 3000\n")
L("X06_planeforce_z", "fix planeforce all 0 0 1 (motion in xy only: the x contact as ever, gravity removed: 0.413)", "fix pf all planeforce 0 0 1\nrun 3000\n")
L("X07_lineforce_y", "fix lineforce all 0 1 0 (motion along y only: x forces removed: no bounce)", "fix lf all lineforce 0 1 0\nrun 3000\n")
L("X08_momentum_linear", "fix momentum 1 linear 1 1 1 (total momentum zero already: 0.413)", "fix mom all momentum 1 linear 1 1 1\nrun 3000\n")
L("X09_viscous_sphere", "fix viscous/sphere all 1e-3 (a torque drag only: head-on 0.413)", "fix vs all viscous/sphere 1e-3\nrun 3000\n")
L("X10_recenter", "fix recenter INIT INIT INIT (shifts the pair as a whole: 0.413)", "fix rc all recenter INIT INIT INIT\nrun 3000\n")
L("X11_spring_tether_lv1", "fix spring lv1 tether 50.0 0.01795 NULL NULL 0.0 (a spring on lv1's centre of mass)", "fix sp lv1 spring tether 50.0 0.01795 NULL NULL 0.0\nrun 3000\n")
L("X12_wall_reflect_between", "fix wall/reflect xlo 0.0205 on lv2 only (lv2 bounces off x = 0.0205 before lv1 meets it? lv2's left edge at 0.02005)",
  "group l2 id 2\nfix wr l2 wall/reflect xlo 0.0205 units box\nrun 3000\n")
L("X13_deform_remap_v", "fix deform 1 x scale 1.5 remap v (the box stretches in x with the velocities remapped)", "fix df all deform 1 x scale 1.5 remap v\nrun 3000\n")
L("X14_setforce_var_zero", "variable f equal 0; fix setforce lv2 v_f v_f v_f (forces set to zero by a variable; lv2 at rest, lv1 1 m/s)",
  "variable f equal 0\nfix sf lv2 setforce v_f v_f v_f\nrun 3000\n", pair=IN10())
L("X15_freeze_type2_group", "group t2 type 2; fix freeze t2 (lv2 at rest, lv1 1 m/s: meff = m1)", "group t2 type 2\nfix fz t2 freeze\nrun 3000\n", pair=IN10())
L("X16_nve_noforce_lv2", "unfix integ; fix integ lv1 nve/sphere; fix nf lv2 nve/noforce (lv2 moves at its own velocity, no force)",
  "unfix integ\nfix integ lv1 nve/sphere\nfix nf lv2 nve/noforce\nrun 3000\n", pair=IN10())
L("X17_rigid_small_lv2", "unfix integ; fix integ lv1 nve/sphere; fix rg lv2 rigid/small molecule? (rigid of one atom: LAMMPS stops?) -> fix rg lv2 rigid single",
  "unfix integ\nfix integ lv1 nve/sphere\nfix rg lv2 rigid single\nrun 3000\n")
L("X18_efield_no_charge", "fix efield 1 0 0 on atoms without charge (LAMMPS stops)", "fix ef all efield 1.0 0.0 0.0\nrun 3000\n")
L("X19_viscous_lv2_scale", "fix viscous lv2 0.0 scale 2 100? (gamma 0 on all types: 0.413)", "fix visc all viscous 0.0 scale 2 100.0\nrun 3000\n")
L("X20_gravity_x", "fix grav replaced by a gravity along x (the pair's axis: both fall alike: 0.413)", "unfix grav\nfix grav all gravity 9.81 vector 1 0 0\nrun 3000\n")
L("X21_freeze_in_if", "if \"1 > 0\" then \"fix fz lv2 freeze\" (lv2 at rest, lv1 1 m/s)", "if \"1 > 0\" then \"fix fz lv2 freeze\"\nrun 3000\n", pair=IN10())
L("X22_freeze_by_include", "include fz.in (fix fz lv2 freeze) (lv2 at rest, lv1 1 m/s)", "include fz.in\nrun 3000\n", pair=IN10(), data={"fz.in": "fix fz lv2 freeze\n"})
L("X23_freeze_in_every", "run 2000 every 1000 \"fix fz lv2 freeze\" (frozen after part 1; meets in part 2; lv2 at rest, lv1 1 m/s)",
  "run 2000 every 1000 \"fix fz lv2 freeze\"\n", pair=IN10(G(2)), live="part 2")
L("X24_viscous_by_variable_id", "variable s string viscous; fix visc all ${s} 0.01 (the style from a variable)", "variable s string viscous\nfix visc all ${s} 0.01\nrun 3000\n")
L("X25_setforce_unfixed_before", "fix setforce lv2 0 0 0; run 100 (no contact); unfix sf; run 3000 (0.413)", "fix sf lv2 setforce 0.0 0.0 0.0\nrun 100\nunfix sf\nrun 3000\n", pair=IN(0.2e-3))
L("X29_integ_redefined_same_id", "fix integ all nve/sphere, then fix integ lv1 nve/sphere (same id: replaced; lv2 at rest never moves; lv1 1 m/s)",
  "fix integ lv1 nve/sphere\nrun 3000\n", pair=IN10())
L("X30_viscous_redefined_zero", "fix visc all viscous 0.01, then fix visc all viscous 0.0 (same id: no drag: 0.413)", "fix visc all viscous 0.01\nfix visc all viscous 0.0\nrun 3000\n")
L("X31_freeze_unfixed_in_include", "fix fz lv2 freeze; include u.in (unfix fz): 0.413", "fix fz lv2 freeze\ninclude u.in\nrun 3000\n", data={"u.in": "unfix fz\n"})
L("X32_integ_replaced_by_limit", "fix integ all nve/limit 2e-7 over the base's fix integ (same id, no unfix)", "fix integ all nve/limit 2e-7\nrun 3000\n")
L("X33_freeze_type1_wall", "WALL: fix freeze on type 1 (the falling sphere: it never moves... LAMMPS: no fall)", "group t1 type 1\nfix fz t1 freeze\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
LG("X26_lig_addforce_lv1", "LIGGGHTS fix addforce lv1 0.05 0 0 (a push through the contact)", "fix af lv1 addforce 0.05 0.0 0.0\nrun 3000\n")
LG("X27_lig_aveforce_all", "LIGGGHTS fix aveforce all 0.0 NULL NULL (no bounce)", "fix avf all aveforce 0.0 NULL NULL\nrun 3000\n")
LG("X28_lig_setforce_lv2", "LIGGGHTS fix setforce lv2 0 0 0 (lv2 at rest, lv1 1 m/s)", "fix sf lv2 setforce 0.0 0.0 0.0\nrun 3000\n",
   pair=LIN(0.1e-3).replace(f"velocity lv1 set {V1:.10f} 0 0", "velocity lv1 set 1.0 0 0").replace(f"velocity lv2 set {V2:.10f} 0 0", "velocity lv2 set 0 0 0"))

# ================================================================ Y: fixes that act during the runs the audit skips
L("Y01_fix_set_density_every_step", "fix fs all set 1 0 atom 2 density 5000 (v_rho an atom variable 5000: a set command every step of the run: lv2 5000: 0.390)",
  "variable rho atom 5000\nfix fs all set 1 0 atom 2 density v_rho\nrun 3000\n")
L("Y02_fix_set_type_density_100", "fix fs all set 50 0 type 2 density 5000 (every 50 steps, before the pair meets at step 100: 0.390)",
  "variable rho atom 5000\nfix fs all set 50 0 type 2 density v_rho\nrun 3000\n")
L("Y03_fix_set_type_change", "3 types: fix fs all set 50 0 atom 2 type 3 (lv2 made type 3 at step 50; 1 3 kn 4000: 0.542)",
  "variable t3 atom 3\nfix fs all set 50 0 atom 2 type v_t3\n" + PCk("1 3", 4000) + "run 3000\n", pre=B3, PAIR="types 1 3")
L("Y04_fix_set_mass", "fix fs all set 1 0 atom 2 mass 5.65487e-4 (lv2's mass doubled in the run: 0.390)", "variable m2 atom 5.65487e-4\nfix fs all set 1 0 atom 2 mass v_m2\nrun 3000\n")
L("Y05_damping_cundall", "fix damping/cundall all 0.3 0.3 (Cundall's global damping)", "fix dc all damping/cundall 0.3 0.3\nrun 3000\n")
L("Y06_drag_point", "fix drag all 0.02 0.02 0.05 1e-3 0.0 (a drag toward a point)", "fix dr all drag 0.02 0.02 0.05 1e-3 0.0\nrun 3000\n")
L("Y07_propel_self_velocity", "fix propel/self velocity 0.01 (a force along each atom's velocity)", "fix ps all propel/self velocity 0.01\nrun 3000\n")
L("Y08_oneway_region", "fix oneway 1 on region x > 0.021 in +x (lv2 moving -x there is turned)", "region rr block 0.021 0.04 0 0.04 0 0.1 units box\nfix ow all oneway 1 rr x\nrun 3000\n")
L("Y09_indent_far", "fix indent sphere far away (no effect: 0.413)", "fix ind all indent 10.0 sphere 0.005 0.005 0.005 0.001 units box\nrun 3000\n")
L("Y10_temp_csvr", "fix temp/csvr all 1e20 1e20 1e-4 48279 (a stochastic thermostat)", "fix cs all temp/csvr 1e20 1e20 1e-4 48279\nrun 3000\n")
L("Y11_spring_rg", "fix spring/rg all 100 0.0 (pulls the pair together)", "fix sr all spring/rg 100.0 0.0\nrun 3000\n")
L("Y12_flow_gauss_x", "fix flow/gauss all 1 0 0 (the pair's net x force is zero anyway: 0.413)", "fix fg all flow/gauss 1 0 0\nrun 3000\n")
L("Y13_heat_remove", "fix heat all heat 1 -1e-9 (kinetic energy taken every step)", "fix ht all heat 1 -1e-9\nrun 3000\n")
L("Y14_addtorque", "fix addtorque all 0 0 1e-9 (a torque: head-on normal as ever: 0.413)", "fix at all addtorque 0.0 0.0 1e-9\nrun 3000\n")
L("Y15_viscosity_swap", "fix viscosity 1 x z 5 (momentum swaps between slabs)", "fix vs all viscosity 1 x z 20\nrun 3000\n")
L("Y16_adapt_diameter_growing", "fix adapt lv2 diameter 0.006+2e-6*step (mass yes: lv2 grows through the contact)",
  "neighbor 0.003 bin\nvariable d equal 0.006+2e-6*step\nfix ad lv2 adapt 1 atom diameter v_d\nrun 3000\n", pair=IN(0.3e-3))
L("Y17_nve_bpm_sphere", "unfix integ; fix integ all nve/bpm/sphere (the BPM integrator on plain spheres: 0.413?)", "unfix integ\nfix integ all nve/bpm/sphere\nrun 3000\n")
L("Y18_brownian_sphere", "unfix integ; fix integ all brownian/sphere 1e-20 48279 gamma_t 1e-3 gamma_r 1e-3 (an overdamped integrator)",
  "unfix integ\nfix integ all brownian/sphere 1e-20 48279 gamma_t 1e-3 gamma_r 1e-3\nrun 3000\n")
L("Y19_fix_set_in_include", "include s.in (fix fs all set 1 0 atom 2 density 5000): 0.390", "include s.in\nrun 3000\n", data={"s.in": "variable rho atom 5000\nfix fs all set 1 0 atom 2 density v_rho\n"})
L("Y20_fix_set_diameter_only", "fix fs all set 1 0 atom 2 diameter 0.006 (no change: 0.413)", "variable d atom 0.006\nfix fs all set 1 0 atom 2 diameter v_d\nrun 3000\n")
LG("Y21_lig_hooke_stiffness_fix_viscous_zero", "LIGGGHTS hooke/stiffness with fix viscous 0 (control)", "fix visc all viscous 0.0\nrun 3000\n", pre=m7.m6.LHS)

# ================================================================ Z: 2d decks; LIGGGHTS matrices of another size
Z2 = lambda extra="": ("units si\ndimension 2\natom_style sphere 1\nboundary p p p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 -0.001 0.001 units box\ncreate_box 2 box\n"
                       "pair_style granular\npair_coeff * * " + HK + "\nfix grav all gravity 9.81 vector 0 -1 0\nfix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-6\n" + extra)
P2 = lambda how="density": (f"create_atoms 1 single 0.017950 0.02 0.0\ncreate_atoms 2 single 0.023050 0.02 0.0\nset atom 1 diameter 0.004 {how} 2500\n"
                            f"set atom 2 diameter 0.006 {how} 2500\ngroup lv1 id 1\ngroup lv2 id 2\n" + VEL)
L("Z01_2d_density_sphere_mass", "dimension 2, set density (LAMMPS takes the sphere's volume: the 3d masses: 0.413)", "run 3000\n", pre=Z2(), pair=P2("density"))
L("Z02_2d_density_disc", "dimension 2, set density/disc (disc masses pi r^2 rho: ratio 4:9)", "run 3000\n", pre=Z2(), pair=P2("density/disc"))
L("Z03_2d_disc_then_type_density", "dimension 2, set density/disc for both, then set type 2 density 5000 (3d volume for lv2)", "set type 2 density 5000\nrun 3000\n", pre=Z2(), pair=P2("density/disc"))
L("Z04_2d_nve_sphere_disc", "dimension 2, fix nve/sphere disc, density/disc (0.? as Z02)", "run 3000\n", pre=Z2().replace("fix integ all nve/sphere\n", "fix integ all nve/sphere disc\n"), pair=P2("density/disc"))
LG("G40_lig_matrix_4_for_3_types", "LIGGGHTS 3 types, coefficientRestitution peratomtypepair 4 (16 numbers; 1 2 entry 0.8)", "run 3000\n",
   pre=LB().replace("coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", "coefficientRestitution peratomtypepair 4 0.6 0.8 0.7 0.9 0.8 0.4 0.45 0.9 0.7 0.45 0.8 0.9 0.9 0.9 0.9 0.9"))
LG("G41_lig_youngs_4_for_3_types", "LIGGGHTS 3 types, youngsModulus peratomtype with 4 values (e 0.5)", "run 3000\n",
   pre=LB().replace("youngsModulus peratomtype 5e6 5e6 5e6", "youngsModulus peratomtype 5e6 5e6 5e6 5e6"))

# ================================================================ N: neighbour lists built late or once; integrators by group
L("N01_skin_small_every_1000_nocheck", "neighbor 1e-5 bin; neigh_modify every 1000 delay 0 check no (gap 0.5 mm: the pair is listed only at step 1000, deep in overlap)",
  "neighbor 1e-5 bin\nneigh_modify every 1000 delay 0 check no\nrun 3000\n", pair=IN(0.5e-3))
L("N02_once_yes_far", "neigh_modify once yes (the list built at the run's start only; gap 2.1 mm > the skin 1 mm: never listed: the pair passes)",
  "neigh_modify once yes\nrun 4000\n", pair=IN(G(3)))
L("N03_once_yes_near", "neigh_modify once yes, gap 0.1 mm within the skin (listed: 0.413)", "neigh_modify once yes\nrun 3000\n")
L("N04_skin_02_every_1000_check", "neighbor 2e-4 bin; neigh_modify every 1000 delay 0 check yes (gap 0.5 mm: first checked at step 1000)",
  "neighbor 2e-4 bin\nneigh_modify every 1000 delay 0 check yes\nrun 3000\n", pair=IN(0.5e-3))
L("N05_delay_1000", "neighbor 2e-4 bin; neigh_modify delay 1000 every 1 check yes (gap 0.5 mm)", "neighbor 2e-4 bin\nneigh_modify delay 1000 every 1 check yes\nrun 3000\n", pair=IN(0.5e-3))
L("N06_zero_skin_every_step", "neighbor 0.0 bin; neigh_modify every 1 delay 0 check yes (0.413)", "neighbor 0.0 bin\nneigh_modify every 1 delay 0 check yes\nrun 3000\n")
LG("N07_lig_skin_small_every_1000", "LIGGGHTS neighbor 1e-5 bin; neigh_modify every 1000 delay 0 check no (gap 0.5 mm)",
   "neighbor 1e-5 bin\nneigh_modify every 1000 delay 0 check no\nrun 3000\n", pair=LIN(0.5e-3))
L("N08_two_integrators_by_group", "unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve/sphere (both move: 0.413)", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/sphere\nrun 3000\n")
L("N09_integrators_by_type_groups", "unfix integ; group t1 type 1; group t2 type 2; fix i1 t1 nve/sphere; fix i2 t2 nve/sphere (0.413)",
  "unfix integ\ngroup t1 type 1\ngroup t2 type 2\nfix i1 t1 nve/sphere\nfix i2 t2 nve/sphere\nrun 3000\n")
L("N10_skin_small_every_1000_np2", "N01 on 1 and 2 processes (processors * 1 1, f f f)", "neighbor 1e-5 bin\nneigh_modify every 1000 delay 0 check no\nrun 3000\n",
  pre=BASE(boundary="f f f", head="processors * 1 1\n", wall=False), pair=IN(0.5e-3), NP="1 2")

LHSX = m7.m6.LHS
LG("G42_lig_hooke_stiffness_absolute_damping", "LIGGGHTS hooke/stiffness absolute_damping on (gamman not scaled by the mass)", "run 3000\n",
   pre=LHSX.replace("pair_style gran model hooke/stiffness tangential history\n", "pair_style gran model hooke/stiffness tangential history absolute_damping on\n"))
LG("G43_lig_hertz_stiffness", "LIGGGHTS hertz/stiffness (kn gamman kt gammat as hooke/stiffness's; a soft contact of 12 ms: run 30000)", "run 30000\n",
   pre=LHSX.replace("model hooke/stiffness", "model hertz/stiffness"))
LG("G44_lig_cohesion_sjkr2_zero", "LIGGGHTS cohesion sjkr2 with cohesionEnergyDensity 0 (e 0.5)", "run 3000\n",
   pre=LB(extra="fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 0 0 0 0 0\n").replace(
       "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history cohesion sjkr2\n"))
LG("G45_lig_hooke_charvel_2", "LIGGGHTS hooke, characteristicVelocity 2.0, e 1 2 0.5 (the linear spring keeps e: 0.5)", "run 3000\n",
   pre=LB(model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 2.0\n"))
LG("G46_lig_hooke_stiffness_limitforce", "LIGGGHTS hooke/stiffness limitForce on", "run 3000\n",
   pre=LHSX.replace("pair_style gran model hooke/stiffness tangential history\n", "pair_style gran model hooke/stiffness tangential history limitForce on\n"))
LG("G47_lig_hooke_stiffness_absolute_damping_density", "LIGGGHTS hooke/stiffness absolute_damping on, lv2 density 5000", "set atom 2 density 5000\nrun 3000\n",
   pre=LHSX.replace("pair_style gran model hooke/stiffness tangential history\n", "pair_style gran model hooke/stiffness tangential history absolute_damping on\n"))
LG("G48_lig_set_type_pair_13", "LIGGGHTS set atom 2 type 3 (the pair 1 3: e 0.7)", "set atom 2 type 3\nrun 3000\n", PAIR="types 1 3")
LG("G49_lig_hooke_disable_bonded", "LIGGGHTS hooke disableNormalWhenBonded on (no bond model: e 0.5)", "run 3000\n",
   pre=LB(model="hooke", extra="fix m9 all property/global characteristicVelocity scalar 1.0\n").replace(
       "pair_style gran model hooke tangential history\n", "pair_style gran model hooke tangential history disableNormalWhenBonded on\n"))
LG("G50_lig_hertz_tangential_no_history", "LIGGGHTS hertz tangential no_history (e 0.5)", "run 3000\n",
   pre=LB().replace("model hertz tangential history", "model hertz tangential no_history"))

# ================================================================ E: a run's every shorter than a contact (the contact spans parts)
L("E01_every_200_kn_ramp", "run 2000 every 200 \"pc $(2000+2*step)\" (kn 2000, 2400, 2800, 3200 ...): the pair meets at step 100 in part 1; its contact (586 steps at kn 2000) spans parts 1-4",
  "run 2000 every 200 \"" + PCs("$(2000+2*step)") + "\"\n", live="part 1 (and 2-4)")
L("E02_every_200_density_ramp", "run 2000 every 200 \"set atom 2 density $(2500+5*step)\": lv2 heavier every 200 steps through the contact",
  "run 2000 every 200 \"set atom 2 density $(2500+5*step)\"\n", live="part 1 (and 2-4)")
L("E03_every_250_velocity_reset", "run 2000 every 250 \"velocity lv2 set V2 0 0\": lv2's velocity set back to its approach value at step 250, within the contact",
  "run 2000 every 250 \"velocity lv2 set " + f"{V2:.10f}" + " 0 0 units box\"\n", live="part 1 (and 2-3)")
L("E04_every_1000_kn_control", "run 4000 every 1000 \"pc $(2000+step)\" with the pair meeting at step 1100 (part 2, kn 3000, the contact inside it: 0.491)",
  "run 4000 every 1000 \"" + PCs("$(2000+step)") + "\"\n", pair=IN(G(2)), live="part 2")
L("E05_every_100_kn_small_ramp", "run 3000 every 100 \"pc $(2000+step)\": kn 2000 + the step, changed every 100 steps (the contact from step 100 to about 650)",
  "run 3000 every 100 \"" + PCs("$(2000+step)") + "\"\n", live="part 1 (and 2-6)")
L("E07_loop_runs_200_kn_ramp", "a loop of 10 runs of 200 steps, pc $(2000+400*(v_i-1)) before each: the contact from step 100 spans passes 1-4",
  "variable i loop 10\nlabel lp\n" + PCs("$(2000+400*(v_i-1))") + "\nrun 200\nnext i\njump SELF lp\n", live="pass 1 (and 2-4)")
L("E08_two_runs_split_contact", "run 300 (the pair meets at step 100); pc 5000; run 2000: the contact (586 steps at kn 2000) ends under kn 5000",
  "run 300\n" + PC5 + "run 2000\n", live="run 1 (and run 2)")
LG("E06_lig_every_200_e_ramp", "LIGGGHTS run 2000 every 200 \"fix m3 ... e $(0.5+0.0002*step)\" (e 0.5, 0.54, 0.58 ...): the contact (675 steps) spans parts",
   "run 2000 every 200 \"" + LE.format(e="$(0.5+0.0002*step)") + "\"\n", live="part 1 (and 2-4)")

# ================================================================ checks behind FINDINGS' "what held" (run by hand first)
BOND = lambda tail: (RB.replace("atom_style sphere 1", "atom_style hybrid sphere 1 bond").replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 1")
                     + IN(0.1e-3) + tail)
m7.DECKS["D27_bond_zero_excludes"] = ("# create_bonds single/bond 1 1 2 with bond_style zero (special lj 0: the bonded pair gets no contact: passes)\n" +
    BOND("bond_style zero\nbond_coeff 1 0.005\ncreate_bonds single/bond 1 1 2\nrun 3000\n"), "last run", {}, {})
m7.DECKS["D28_bond_harmonic"] = ("# create_bonds with a harmonic bond (no contact; the bond's spring)\n" +
    BOND("bond_style harmonic\nbond_coeff 1 5.0 0.0051\ncreate_bonds single/bond 1 1 2\nrun 3000\n"), "last run", {}, {})
m7.DECKS["D29_bond_zero_special_111"] = ("# bond_style zero with special_bonds lj 1 1 1 (the bonded pair keeps its contact: 0.413)\n" +
    BOND("bond_style zero\nbond_coeff 1 0.005\nspecial_bonds lj 1.0 1.0 1.0\ncreate_bonds single/bond 1 1 2\nrun 3000\n"), "last run", {}, {})
L("D30_exclude_molecule_intra", "fix property/atom mol; both atoms mol 7; neigh_modify exclude molecule/intra all (no contact)",
  "fix pa all property/atom mol\nset atom 1*2 mol 7\nneigh_modify exclude molecule/intra all\nrun 3000\n")
L("D31_exclude_molecule_inter", "fix property/atom mol ghost yes; mol 7 and 8; neigh_modify exclude molecule/inter all (no contact)",
  "fix pa all property/atom mol ghost yes\nset atom 1 mol 7\nset atom 2 mol 8\nneigh_modify exclude molecule/inter all\nrun 3000\n")
L("X34_nve_noforce_by_type", "unfix integ; type groups; nve/sphere on type 1, nve/noforce on type 2 (lv2 at its velocity through the contact)",
  "unfix integ\ngroup t1 type 1\ngroup t2 type 2\nfix i1 t1 nve/sphere\nfix i2 t2 nve/noforce\nrun 3000\n")
L("X35_move_by_type", "unfix integ; type groups; nve/sphere on type 1, fix move linear at lv2's velocity on type 2",
  "unfix integ\ngroup t1 type 1\ngroup t2 type 2\nfix i1 t1 nve/sphere\nfix i2 t2 move linear " + f"{V2:.10f}" + " 0 0 units box\nrun 3000\n")
m7.DECKS["X36_freeze_falling_periodic"] = ("# a periodic box with a plane region floor at z 0.05: fix freeze on the falling sphere's type (it keeps -1 m/s, goes through the floor)\n"
  "units si\natom_style sphere 1\nboundary p p p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\npair_style granular\n"
  "pair_coeff * * " + HK + "\nregion flr plane 0 0 0.05 0 0 1 side in units box\nfix floor all wall/gran/region granular " + HK + " region flr\n"
  "fix integ all nve/sphere\ntimestep 1e-6\ncreate_atoms 1 single 0.02 0.02 0.0521\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
  "velocity lv1 set 0 0 -1.0 units box\ngroup t1 type 1\nfix fz t1 freeze\nrun 3000\n", "last run", {}, {"PAIR": "type 1 on wall floor", "WALLX": ""})
CYL = lambda R: ("units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\npair_style granular\n"
                 "pair_coeff * * hertz/material 1e7 2.0 0.3 damping viscoelastic tangential linear_nohistory 1 0.3\nregion cyl cylinder z 0.02 0.02 " + str(R) + " 0 0.1 side in units box\n"
                 "fix cw all wall/gran/region granular hertz/material 1e7 2.0 0.3 damping viscoelastic tangential linear_nohistory 1 0.3 region cyl\nfix integ all nve/sphere\ntimestep 1e-7\n"
                 "create_atoms 1 single " + f"{0.02 + R - 0.0021:.6f}" + " 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1.0 0 0 units box\nrun 20000\n")
for nm, R in (("W21_cylinder_hertz_material_r15", 0.015), ("W22_cylinder_hertz_material_r3p5", 0.0035)):
    m7.DECKS[nm] = ("# WALLX: a hertz/material viscoelastic sphere into the inside of a cylinder region wall of radius " + str(R) + " (the curvature in the law)\n" + CYL(R),
                    "last run", {}, {"PAIR": "type 1 on wall cw", "WALLX": ""})

# ================================================================ C: controls
L("C01_plain_2000", "control: kn 2000 (0.413435)", "run 3000\n")
L("C02_plain_5000", "control: pc 5000 (0.578975)", PC5 + "run 3000\n")
L("C03_lv2_5000", "control: lv2 5000 kg/m3 (0.390402)", "set atom 2 density 5000\nrun 3000\n")
L("C04_wall", "control: WALL floor kn 2000", "run 3000\n", pre=BASE(), pair=WALLP(), **WALL)
LG("C05_lig_05", "control: LIGGGHTS e 0.5 (0.499928)", "run 3000\n")
LG("C06_lig_08", "control: LIGGGHTS e 0.8 (0.800005)", LEe(0.8) + "run 3000\n")
LG("C07_lig_wall", "control: LIGGGHTS WALL primitive type 3 (e 1 3 0.7)", "run 3000\n", pair=LWALL(1e-4), **LW)

NP2 = ["C01", "C05", "D01", "D12", "H04", "Q01", "G22", "G24", "N10", "W20", "E01", "W14", "W16", "E08"]   # also on 2 processes
if __name__ == "__main__":
    names = sys.argv[1:]
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1 2\n" if n[:3] in NP2 else "1\n")
