"""Field round 26: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker, with round 23's
helpers (now tests/fieldkit/decks.py). Classes of all earlier rounds mixed in new combinations. Prefixes: F formats
$(expr:%fmt) feeding ifs/includes/loops, T type ranges and labels with hybrid, S set order and size distributions,
W walls, U units other than si, D time step, K fixes that change eps, C control flow, V variable styles, R restyles
and clear and files the deck writes, H runs the engine stops or ends, L LIGGGHTS, X engine examples, E public decks.
usage: python make_decks26.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from fieldkit import decks as m  # noqa: E402  (round 23's helpers, tests/fieldkit/decks.py)

m.D = os.path.join(HERE, "decks")
deck, L, BASE, TWO, hk, HK, K, TL, head = m.deck, m.L, m.BASE, m.TWO, m.hk, m.HK, m.K, m.TL, m.head
GRAV, FLOOR, TAIL = m.GRAV, m.FLOOR, m.TAIL
rr = lambda name, comment, lines, **kw: deck(name, "# " + comment + "\n" + BASE() + TWO + lines, g=kw.pop("g", 1), **kw)
K5 = "pair_coeff * * " + hk(5000) + "\n"
K8 = "pair_coeff * * " + hk(8000) + "\n"
KN5 = {"kn.in": K5}
HM = m.HM
INS = "region ins block 0.005 0.035 0.005 0.035 0.05 0.09 units box\n"
# three types: 1 4 mm, 2 6 mm, 3 8 mm, all 2500
THREE = TWO + "create_atoms 3 single 0.03 0.03 0.012\nset type 3 diameter 0.008 density 2500\n"
B3 = lambda model=HK: head(3) + m.G1(model) + GRAV + f"fix floor all wall/gran granular {model} zplane 0 NULL\n" + TAIL
r3 = lambda name, comment, lines, **kw: deck(name, "# " + comment + "\n" + B3() + THREE + lines, g=1, **kw)
# a deck body without its pair lines (for hybrid decks)
NOPAIR = lambda nt=2: head(nt) + GRAV + FLOOR + TAIL


def hy(name, comment, pair_lines, nt=2, atoms=None, **kw):
    deck(name, "# " + comment + "\n" + head(nt) + pair_lines + GRAV + FLOOR + TAIL + (atoms or (THREE if nt == 3 else TWO)) + "run 100\n", g=1, **kw)


# ---------------------------------------------------------------- F: formats $(expr:%fmt) feeding ifs, includes, loops
rr("F01_format_include_name", "include kn$(v_k*3:%.0f).in with k = 5000/3: kn5000.in", "variable k equal 5000/3\ninclude kn$(v_k*3:%.0f).in\nrun 100\n",
   data={"kn5000.in": K5, "kn4999.in": K8})
rr("F02_format_if_rounding", "if \"$(0.6649:%.2f) == 0.66\" then kn 5000 else kn 8000 (rounded: true)",
   "if \"$(0.6649:%.2f) == 0.66\" then \"" + K5.strip() + "\" else \"" + K8.strip() + "\"\nrun 100\n")
rr("F03_format_loop_count", "variable n equal 2.7; loop $(v_n:%.0f) = 3 passes; pass 3 sets kn 8000, pass 2 kn 5000",
   "variable n equal 2.7\nvariable i loop $(v_n:%.0f)\nlabel l\nif \"$i == 2\" then \"" + K5.strip() + "\" elif \"$i == 3\" \"" + K8.strip() + "\"\nrun 50\nnext i\njump SELF l\n")
rr("F04_format_style_var", "variable kf format k %.3f (k = 4999.9996 -> 5000.000): pair_coeff hooke ${kf}",
   "variable k equal 4999.9996\nvariable kf format k %.3f\npair_coeff * * hooke ${kf} 3000 " + K + "\nrun 100\n")
rr("F05_format_in_if_in_loop", "loop of 3; if \"$(v_i*2500:%.0f) == 5000\" includes kn.in on pass 2 only",
   "variable i loop 3\nlabel l\nif \"$(v_i*2500:%.0f) == 5000\" then \"include kn.in\"\nrun 50\nnext i\njump SELF l\n", data=KN5)
rr("F06_format_e_notation", "pair_coeff hooke $(v_k:%10.2e) with k 5000 -> ' 5.00e+03'", "variable k equal 5000\npair_coeff * * hooke $(v_k:%.2e) 3000 " + K + "\nrun 100\n")
rr("F07_format_timestep_g", "timestep $(1e-5*3:%g) (3e-05)", "timestep $(1e-5*3:%g)\nrun 100\n")
rr("F08_format_set_diameter", "set type 2 diameter $(0.006*1.5:%.4f) = 0.0090", "set type 2 diameter $(0.006*1.5:%.4f)\nrun 100\n")
rr("F09_format_truncates_value", "kn $(5000.7:%.0f) -> 5001 (rounded, not truncated)", "pair_coeff * * hooke $(5000.7:%.0f) 3000 " + K + "\nrun 100\n")
rr("F10_format_label_jump", "jump SELF L$(v_m:%.0f) with m = 2.2: label L2 sets kn 5000, L3 kn 8000",
   "variable m equal 2.2\njump SELF L$(v_m:%.0f)\nlabel L3\n" + K8 + "jump SELF end\nlabel L2\n" + K5 + "label end\nrun 100\n")
rr("F11_format_percent_d", "$(5000:%d) (an integer format for a double: engine decides)", "pair_coeff * * hooke $(5000:%d) 3000 " + K + "\nrun 100\n")
rr("F12_format_var_in_loop_next", "variable ie equal v_i*1000+2000; variable f format ie %.1f; loop of 3 runs with pair_coeff ${f} (last 5000)",
   "variable i loop 3\nvariable ie equal v_i*1000+2000\nvariable f format ie %.1f\nlabel l\npair_coeff * * hooke ${f} 3000 " + K + "\nrun 50\nnext i\njump SELF l\n")
rr("F13_format_include_loop_pad", "loop i 2 pad... include k$(v_i*1:%02.0f).in: k01 kn 5000, k02 kn 8000",
   "variable i loop 2\nlabel l\ninclude k$(v_i:%02.0f).in\nrun 50\nnext i\njump SELF l\n", data={"k01.in": K5, "k02.in": K8})
rr("F14_format_density_if", "rho = $(7800/3:%.1f) = 2600.0; if rho > 2599.99 then set type 2 density ${rho}",
   "variable rho string $(7800/3:%.1f)\nif \"${rho} > 2599.99\" then \"set type 2 density ${rho}\"\nrun 100\n")
rr("F15_format_nested_immediate", "$(v_a:%.3f) where a = $(1/3) -> kn 5000*$(...)*3 via a string", "variable a equal $(1/3)\nvariable k string $(v_a*15000:%.3f)\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 100\n")
rr("F16_format_if_string_compare", "if \"$(v_x:%.1f) == 2.5\" (x 2.46 -> 2.5 true) then include kn.in", "variable x equal 2.46\nif \"$(v_x:%.1f) == 2.5\" then \"include kn.in\"\nrun 100\n", data=KN5)

# ---------------------------------------------------------------- T: type ranges and labels with hybrid
G_ = "pair_style granular\n"
hy("T01_hybrid_two_granular_ranges", "hybrid granular granular; pair_coeff 1*3 1*3 granular 1 kn 2000; pair_coeff 2* 2* granular 2 kn 8000",
   "pair_style hybrid granular granular\npair_coeff 1*3 1*3 granular 1 " + HK + "\npair_coeff 2* 2* granular 2 " + hk(8000) + "\n", nt=3)
hy("T02_hybrid_labels_two_styles", "labelmap small/big; hybrid granular gran/hooke/history: small small granular kn 2000, small big gran/hooke/history, big big granular kn 8000",
   "labelmap atom 1 small 2 big\npair_style hybrid granular gran/hooke/history 4000 NULL 3000 NULL 0.5 1\npair_coeff small small granular " + HK + "\npair_coeff small big gran/hooke/history\npair_coeff big big granular " + hk(8000) + "\n")
hy("T03_hybrid_overlay_granular_zero", "hybrid/overlay granular zero: zero adds no force (granular kn 5000 acts)",
   "pair_style hybrid/overlay granular zero 0.01\npair_coeff * * granular " + hk(5000) + "\npair_coeff * * zero\n")
hy("T04_ranges_star_two", "3 types: pair_coeff * * kn 2000, then *2 2* kn 8000 (1 2, 1 3?, 2 2, 2 3: I<=2, J>=2)",
   "pair_style granular\npair_coeff * * " + HK + "\npair_coeff *2 2* " + hk(8000) + "\n", nt=3)
hy("T05_label_star", "labelmap small big huge; pair_coeff * big kn 8000 (1 2, 2 2, 2 3)",
   "labelmap atom 1 small 2 big 3 huge\npair_style granular\npair_coeff * * " + HK + "\npair_coeff * big " + hk(8000) + "\n", nt=3)
hy("T06_hybrid_range_old_style", "hybrid granular gran/hertz/history: 1*2 3 by gran/hertz/history, rest granular",
   "pair_style hybrid granular gran/hertz/history 1e6 NULL 3000 NULL 0.5 1\npair_coeff * * granular " + HK + "\npair_coeff 1*2 3 gran/hertz/history\n", nt=3)
hy("T07_hybrid_none_label", "hybrid granular; pair_coeff small big none (labels): 1 2 no force",
   "labelmap atom 1 small 2 big\npair_style hybrid granular\npair_coeff * * granular " + HK + "\npair_coeff small big none\n")
hy("T08_hybrid_override_22", "hybrid granular gran/hooke: * * granular, then 2 2 gran/hooke (kn 8000)",
   "pair_style hybrid granular gran/hooke 8000 NULL 3000 NULL 0.5 1\npair_coeff * * granular " + HK + "\npair_coeff 2 2 gran/hooke\n")
hy("T09_range_two_passes", "3 types: 1*3 1*3 kn 2000, then 2*3 2*3 kn 5000 (1 2 and 1 3 stay 2000)",
   "pair_style granular\npair_coeff 1*3 1*3 " + HK + "\npair_coeff 2*3 2*3 " + hk(5000) + "\n", nt=3)
hy("T10_label_from_string_var", "variable a string big; labelmap atom 2 ${a}; pair_coeff ${a} ${a} kn 8000",
   "variable a string big\nlabelmap atom 1 small 2 ${a}\npair_style granular\npair_coeff * * " + HK + "\npair_coeff ${a} ${a} " + hk(8000) + "\n")
hy("T11_reversed_numeric", "pair_coeff 2 1 kn 8000 (I > J: engine decides)", "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 2 1 " + hk(8000) + "\n")
hy("T12_reversed_labels", "labelmap small big; pair_coeff big small kn 8000 (labels in reverse order: engine decides)",
   "labelmap atom 1 small 2 big\npair_style granular\npair_coeff * * " + HK + "\npair_coeff big small " + hk(8000) + "\n")
hy("T13_hybrid_two_granular_labels_mixed", "hybrid granular granular with labels: 1*2 1*2 granular 1 kn 2000; big huge granular 2 kn 5000; huge huge granular 2 kn 8000",
   "labelmap atom 1 small 2 big 3 huge\npair_style hybrid granular granular\npair_coeff 1*3 1*3 granular 1 " + HK + "\npair_coeff big huge granular 2 " + hk(5000) + "\npair_coeff huge huge granular 2 " + hk(8000) + "\n", nt=3)
hy("T14_hybrid_none_then_redefined", "hybrid granular: 1 2 none, then pair_coeff 1 2 granular kn 5000 again",
   "pair_style hybrid granular\npair_coeff * * granular " + HK + "\npair_coeff 1 2 none\npair_coeff 1 2 granular " + hk(5000) + "\n")
hy("T15_hybrid_overlay_two_granular_range", "hybrid/overlay granular granular on 1*2 1*2 (two laws summed: engine decides)",
   "pair_style hybrid/overlay granular granular\npair_coeff 1*2 1*2 granular 1 " + HK + "\npair_coeff 1*2 1*2 granular 2 " + hk(3000) + "\n")
hy("T16_type_range_set_labels", "labelmap; set type 1*2 density 7800 then set type big density 2500", "labelmap atom 1 small 2 big\npair_style granular\npair_coeff * * " + HK + "\n",
   atoms=TWO + "set type 1*2 density 7800\nset type big density 2500\n")

# ---------------------------------------------------------------- S: set order, set atom/mol/region, size distributions
rr("S01_density_then_diameter", "set type 2 density 7800 then set type 2 diameter 0.008 (mass after?)", "set type 2 density 7800\nset type 2 diameter 0.008\nrun 100\n")
rr("S02_create_after_set_default", "create_atoms 2 single after set: the new type 2 atom keeps the default size (1 m, rho 1)? engine decides",
   "create_atoms 2 single 0.03 0.03 0.05\nrun 10\n")
rr("S03_set_atom_ids", "set atom 2 diameter 0.008 density 7800 (id 2 = type 2)", "set atom 2 diameter 0.008 density 7800\nrun 100\n")
deck("S04_set_mol", "# fix property/atom mol; set atom 2 mol 5; set mol 5 density 7800 (type 2)\n" + BASE() + "fix pm all property/atom mol ghost yes\n" + TWO
     + "set atom 2 mol 5\nset mol 5 density 7800\nrun 100\n", g=1)
rr("S05_set_region_after_move", "displace_atoms type 2 by +0.02 in x, set region x > 0.025 density 7800 (only type 2 now there? type 1 is at 0.02)",
   "group t2 type 2\ndisplace_atoms t2 move 0.02 0 0 units box\nregion rt block 0.025 INF INF INF INF INF units box\nset region rt density 7800\nrun 100\n")
rr("S06_set_group_id", "group g id 1; set group g diameter 0.008", "group g id 1\nset group g diameter 0.008\nrun 100\n")
rr("S07_pour_range_then_set", "fix pour type 2 diam range 0.003 0.005 dens 2000 3000 in run 1; unfix; set type 2 diameter 0.006 density 2500 (all type 2) run 2",
   INS + "fix p all pour 4 2 4767 region ins diam range 0.003 0.005 dens 2000 3000\nrun 1000\nunfix p\nset type 2 diameter 0.006 density 2500\nrun 100\n")
rr("S08_pour_poly_three_then_density", "pour type 1 diam poly 3 0.002 0.3 0.004 0.3 0.006 0.4; run; set type 1 density 7800",
   INS + "fix p all pour 6 1 4767 region ins diam poly 3 0.002 0.3 0.004 0.3 0.006 0.4 dens 2500 2500\nrun 3000\nset type 1 density 7800\nrun 100\n")
rr("S09_set_density_then_create", "set type 2 density 7800 before a second create_atoms 2 (new atom default size)", "set type 2 density 7800\ncreate_atoms 2 single 0.03 0.01 0.01\nset atom 3 diameter 0.002\nrun 100\n")
rr("S10_lattice_fill_then_set_type", "create_atoms 1 region of lattice 3 atoms; set type 1 diameter 0.003 (all type 1 incl. the first)",
   "lattice sc 0.01\nregion lay block 0.005 0.035 0.015 0.016 0.05 0.051 units box\ncreate_atoms 1 region lay\nset type 1 diameter 0.003\nrun 100\n")
rr("S11_type_fraction", "set type/fraction 1 2 1.0 4711 (the type 1 atom becomes type 2; size kept 4 mm)", "set type/fraction 1 2 1.0 4711\nrun 100\n")
rr("S12_type_ratio_subset", "region fill of 10 type 1 atoms; set type/ratio 1 2 0.5; set type/subset 2 1 3 ... (engine decides sizes)",
   "region fill block 0.005 0.035 0.005 0.035 0.03 0.09 units box\ncreate_atoms 1 random 10 4242 fill overlap 0.007\nset type 1 diameter 0.004 density 2500\nset type/ratio 1 2 0.5 777\nrun 100\n")
rr("S13_set_atom_var_type", "variable d atom 0.004+0.004*(type==2): set group all diameter v_d (type 2 -> 8 mm)", "variable d atom 0.004+0.004*(type==2)\nset group all diameter v_d\nrun 100\n")
rr("S14_set_atom_star", "set atom * density 7800", "set atom * density 7800\nrun 100\n")
rr("S15_set_region_in_if_include", "an if's include defines the region; set region in the deck", "if 1 then \"include r.in\"\nset region lo density 7800\nrun 100\n",
   data={"r.in": "region lo block INF INF INF INF INF 0.011 units box\n"})
rr("S16_mass_then_diameter", "set type 2 mass 1e-3; set type 2 diameter 0.008 (mass stays? engine decides)", "set type 2 mass 1e-3\nset type 2 diameter 0.008\nrun 100\n")
rr("S17_deposit_loop_set", "fix deposit type 2 in a loop; each pass sets type 2 diameter 0.005 density 3000",
   INS + "fix dp all deposit 3 2 200 5331 region ins near 0.008 vz -0.5 -0.5\nvariable i loop 3\nlabel l\nrun 200\nset type 2 diameter 0.005 density 3000\nnext i\njump SELF l\nrun 100\n")
rr("S18_pour_dens_range_include_loop", "fix pour type 1 diam one 0.003 dens 1000 5000 made in an included file on pass 1 of a loop",
   "variable i loop 2\nlabel l\nif \"$i == 1\" then \"include p.in\"\nrun 2000\nnext i\njump SELF l\n",
   data={"p.in": INS + "fix p all pour 4 1 4767 region ins diam one 0.003 dens 1000 5000\n"})
rr("S19_set_diameter_zero_density", "set type 2 density 0.0 (engine decides)", "set type 2 density 0.0\nrun 10\n")
rr("S20_set_type_labels_region_group", "labelmap; group big type big; set group big diameter 0.01", "labelmap atom 1 small 2 big\ngroup big type big\nset group big diameter 0.01\nrun 100\n")
rr("S21_create_atoms_random_set_after_run", "create_atoms 1 random 4 after a run, set type 1 diameter 0.005 (all type 1)",
   "run 100\nregion top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\ncreate_atoms 1 random 4 999 top overlap 0.006\nset type 1 diameter 0.005 density 2500\nrun 100\n")

# ---------------------------------------------------------------- W: walls
ww = lambda name, comment, wall, extra="", model=HK, nt=2: deck(name, "# " + comment + "\n" + head(nt) + m.G1(model) + GRAV + wall + "\n" + TAIL + (THREE if nt == 3 else TWO) + extra + "run 100\n", g=1)
ww("W01_region_cylinder_side_in", "wall/gran/region cylinder side in kn 5000, plus floor kn 2000",
   "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nfix cw all wall/gran/region granular " + hk(5000) + " region cyl")
ww("W02_zcylinder_kn_var", "wall/gran zcylinder with kn from a variable in an if", "variable kw equal 8000\nif \"${kw} > 5000\" then \"fix cw all wall/gran granular hooke ${kw} 3000 " + K + " zcylinder 0.019\"\nfix floor all wall/gran granular " + HK + " zplane 0 NULL")
ww("W03_region_cone", "wall/gran/region cone (a hopper) hertz/material", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion cone cone z 0.02 0.02 0.005 0.019 0 0.1 side in units box\nfix cw all wall/gran/region granular " + HM + " region cone")
ww("W04_xplane_both", "wall/gran xplane 0 0.04 kn 8000 (boundary p p f with x walls inside)", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nfix xw all wall/gran granular " + hk(8000) + " xplane 0.001 0.039")
ww("W05_region_cylinder_open_faces", "region cylinder open 1 open 2 side in; wall/gran/region kn 5000", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in open 1 open 2 units box\nfix cw all wall/gran/region granular " + hk(5000) + " region cyl")
ww("W06_region_block_container", "region block side in as the only wall (kn 5000), no zplane", "region con block 0 0.04 0 0.04 0 0.1 side in units box\nfix cw all wall/gran/region granular " + hk(5000) + " region con")
ww("W07_region_sphere_obstacle_out", "region sphere side out (a ball obstacle) kn 8000 + floor", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion ball sphere 0.03 0.01 0.05 0.005 side out units box\nfix bw all wall/gran/region granular " + hk(8000) + " region ball")
ww("W08_wall_group_type3_only", "3 types; floor on group of type 3 only kn 8000, another floor for types 1 2 kn 2000", "group t3 type 3\ngroup t12 type 1 2\nfix floor t12 wall/gran granular " + HK + " zplane 0 NULL\nfix f3 t3 wall/gran granular " + hk(8000) + " zplane 0 NULL", nt=3)
ww("W09_wall_region_in_loop_include", "a loop whose pass 2 includes a file that unfixes the floor and adds a region plane floor kn 8000",
   "fix floor all wall/gran granular " + HK + " zplane 0 NULL", extra="variable i loop 2\nlabel l\nif \"$i == 2\" then \"include w.in\"\nrun 50\nnext i\njump SELF l\n")
ww("W10_wall_region_moving_plane", "a region plane floor moving with a variable; wall/gran/region kn 5000",
   "variable zz equal 0.0\nregion fl plane 0 0 0 0 0 1 side in move NULL NULL v_zz units box\nfix floor all wall/gran/region granular " + hk(5000) + " region fl")
ww("W11_wall_hertzmat_pair_hooke", "pair hooke, wall hertz/material viscoelastic", "fix floor all wall/gran granular " + HM + " zplane 0 NULL")
ww("W12_wall_labels_group", "labelmap; group by label; wall on group big only (type 1 has no wall)", "labelmap atom 1 small 2 big\ngroup gb type big\nfix floor gb wall/gran granular " + hk(5000) + " zplane 0 NULL")
ww("W13_wall_yplane_kn_format", "wall yplane with kn $(2500*2:%.0f)", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nfix yw all wall/gran granular hooke $(2500*2:%.0f) 3000 " + K + " yplane 0.001 0.039")
ww("W14_region_cylinder_rotating", "region cylinder rotating (rotate) wall kn 5000", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in rotate v_th 0.02 0.02 0 0 0 1 units box\nvariable th equal 0.1*time\nfix cw all wall/gran/region granular " + hk(5000) + " region cyl")
# the include of W09
m.DECKS["W09_wall_region_in_loop_include"] = m.DECKS["W09_wall_region_in_loop_include"][:2] + ({"w.in": "unfix floor\nregion fl plane 0 0 0 0 0 1 side in units box\nfix floor all wall/gran/region granular " + hk(8000) + " region fl\n"},) + m.DECKS["W09_wall_region_in_loop_include"][3:]

# ---------------------------------------------------------------- U: units other than si with --g
ub = m.ubase
CGS_HK = "hooke 2e6 3000 " + K
deck("U01_cgs_hooke_g100", "# units cgs hooke (= the si base); --g 100 (cm/s)\n" + ub("cgs", CGS_HK, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n", g="100")
deck("U02_cgs_hertzmat_g100_loop", "# units cgs hertz/material, kn via loop (last E 2e8), --g 100\n" + ub("cgs", "hertz/material 1e8 1.4e5 0.3 damping viscoelastic " + TL, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5))
     + "timestep 1e-5\nvariable i loop 2\nlabel l\npair_coeff * * hertz/material $(v_i*1e8) 1.4e5 0.3 damping viscoelastic " + TL + "\nrun 50\nnext i\njump SELF l\n", g="100")
deck("U03_lj_hooke_g05", "# units lj hooke kn 2000 gamma 3; --g 0.5\n" + ub("lj", "hooke 2000 3 " + K, "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "timestep 1e-4\nrun 100\n", g="0.5")
deck("U04_micro_hertzmat", "# units micro (um, pg, us): hertz/material E 1e4, 40/60 um, --g 1 (um/us = m/s)\n"
     + ub("micro", "hertz/material 1e4 1.4e-5 0.3 damping viscoelastic " + TL, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\nrun 100\n", g="1")
deck("U05_nano_hooke", "# units nano (nm, ag, ns): hooke kn 1 gamma 1, 40/60 nm, rho 2.5e-6 ag/nm3, --g 1 (nm/ns = m/s)\n"
     + ub("nano", "hooke 1 1 " + K, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\nrun 100\n", g="1")
deck("U06_cgs_dt_coarse_g100", "# units cgs hooke, timestep 2e-4 (few steps per contact), --g 100\n" + ub("cgs", CGS_HK, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 2e-4\nrun 100\n", g="100")
deck("U07_lj_if_include_kn", "# units lj; kn from an if's include (kn 5000), --g 1\n" + ub("lj", "hooke 2000 3 " + K, "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "timestep 1e-4\nif 1 then \"include k.in\"\nrun 100\n",
     g="1", data={"k.in": "pair_coeff * * hooke 5000 3 " + K + "\n"})
deck("U08_micro_hooke_wall", "# units micro hooke kn 1e-2? (force pg um/us2 = 1e-6 N... engine decides), wall the same, --g 2\n"
     + ub("micro", "hooke 0.1 0.05 " + K, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-2\nrun 100\n", g="2")
deck("U09_nano_hertzmat", "# units nano hertz/material E 1e-2 (ag/(nm ns2) = 1e9 Pa... engine decides), --g 1\n"
     + ub("nano", "hertz/material 0.01 1e-4 0.3 damping viscoelastic " + TL, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\nrun 100\n", g="1")
deck("U10_cgs_clear_si", "# units cgs deck run, then clear and an si deck (kn 5000): --g 1 is m/s for the last\n"
     + ub("cgs", CGS_HK, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\nclear\n" + BASE().replace(HK, hk(5000)) + TWO + "run 100\n", g="1")

# ---------------------------------------------------------------- D: time step
rr("D01_dt_coarse_1e4", "timestep 1e-4 (~4.7 steps per 1 1 contact)", "timestep 1e-4\nrun 100\n")
rr("D02_dt_between_runs_loop", "loop: timestep 1e-5 then 5e-5 (pass 2), kn 5000 on pass 2", "variable i loop 2\nlabel l\nif \"$i == 2\" then \"timestep 5e-5\" \"" + K5.strip() + "\"\nrun 50\nnext i\njump SELF l\n")
rr("D03_dt_in_else_include", "if 0 ... else include of a file setting timestep 2e-4", "if 0 then \"print no\" else \"include ts.in\"\nrun 100\n", data={"ts.in": "timestep 2e-4\n"})
rr("D04_dt_reset_fix", "fix dt/reset 10 1e-7 1e-4 1e-5 (dt by motion)", "fix dtr all dt/reset 10 1e-7 1e-4 1e-5 units box\nrun 100\n")
rr("D05_dt_format_var", "variable dt format d %.1e with d equal 8e-5: timestep ${dt}", "variable d equal 8e-5\nvariable dt format d %.1e\ntimestep ${dt}\nrun 100\n")
rr("D06_dt_tiny", "timestep 1e-8 (fine)", "timestep 1e-8\nrun 100\n")
rr("D07_dt_lost_contact", "timestep 1e-3 (the contact lasts < 1 step: the engine passes through? note)", "timestep 1e-3\nrun 10\n")

# ---------------------------------------------------------------- K: fixes that change eps
rr("K01_viscous_all", "fix viscous all 0.0005", "fix v all viscous 0.0005\nrun 100\n")
rr("K02_langevin_drag", "fix langevin all 0 0 0.001 4711 (a pure drag at T 0)", "fix lg all langevin 0.0 0.0 0.001 4711\nrun 100\n")
deck("K03_nve_limit_tight", "# fix nve/limit 1e-7 instead of nve/sphere (vmax 0.01 m/s: contact slowed)\n" + BASE().replace("fix integ all nve/sphere", "fix integ all nve/limit 1e-7") + TWO + "run 100\n", g=1)
deck("K04_nve_limit_loose", "# fix nve/limit 0.01 (no effect at g 1 and dt 1e-5)\n" + BASE().replace("fix integ all nve/sphere", "fix integ all nve/limit 0.01") + TWO + "run 100\n", g=1)
rr("K05_freeze_label", "labelmap; group by label; fix freeze on big", "labelmap atom 1 small 2 big\ngroup gb type big\nfix fz gb freeze\nrun 100\n")
rr("K06_setforce_in_loop", "loop pass 2 adds fix setforce 0 0 NULL on type 1 (x,y forces zeroed)", "group t1 type 1\nvariable i loop 2\nlabel l\nif \"$i == 2\" then \"fix sf t1 setforce 0 0 NULL\"\nrun 50\nnext i\njump SELF l\n")
rr("K07_adapt_diameter", "fix adapt 1 atom diameter v_d (d from 1 to 1.5 x over the run; mass scaled)", "variable d equal 1.0+0.5*elapsed/100\nfix ad all adapt 1 atom diameter v_d\nrun 100\n")
rr("K08_damping_cundall", "fix damping/cundall 0.5 0.5 (local damping)", "fix dc all damping/cundall 0.5 0.5\nrun 100\n")
rr("K09_viscous_sphere", "fix viscous/sphere 1e-7 (rotation only: head-on no part?)", "fix vs all viscous/sphere 1e-7\nrun 100\n")
rr("K10_nve_not_sphere", "unfix integ; fix integ all nve (no rotation: head-on no part)", "unfix integ\nfix integ all nve\nrun 100\n")
rr("K11_move_type2", "fix move linear on type 2 (prescribed velocity): 1 2 pair is a sphere on a moving body", "group t2 type 2\nfix mv t2 move linear 0 0 0\nrun 100\n")
rr("K12_addforce_type1", "fix addforce 0 0 -1e-3 on type 1", "group t1 type 1\nfix af t1 addforce 0 0 -1e-3\nrun 100\n")
rr("K13_spring_self", "fix spring/self 10 on all (tethers)", "fix ss all spring/self 10.0\nrun 100\n")
rr("K14_viscous_scale_type", "fix viscous 0.0005 scale 2 3 (type 2 x3)", "fix v all viscous 0.0005 scale 2 3.0\nrun 100\n")
rr("K15_viscous_in_elif_then_unfix", "elif adds viscous, unfixed before the last run", "if 0 then \"print a\" elif 1 \"fix v all viscous 0.001\"\nrun 100\nunfix v\n" + K5 + "run 100\n")
rr("K16_gravity_changed_direction", "fix grav redefined along x (gravity along the head-on axis of the audit?)", "unfix grav\nfix grav all gravity 9.81 vector 1 0 0\nrun 100\n")
rr("K17_nve_sphere_disc", "fix nve/sphere update dipole? no: nve/sphere disc in 3d (engine decides)", "unfix integ\nfix integ all nve/sphere disc\nrun 100\n")
rr("K18_langevin_group_zero_T_in_include", "fix langevin on type 2 by an if's include", "if 1 then \"include lg.in\"\nrun 100\n", data={"lg.in": "group t2 type 2\nfix lg t2 langevin 0 0 0.002 99\n"})

# ---------------------------------------------------------------- C: control flow
rr("C01_loop_skip_by_jump", "loop of 3; on pass 2 'jump SELF skip' skips the kn 8000 line; kn 8000 met on passes 1 and 3",
   "variable i loop 3\nlabel l\nif \"$i == 2\" then \"jump SELF skip\"\n" + K8 + "label skip\nrun 50\nnext i\njump SELF l\n" + K5.replace("5000", "6000") + "run 10\n")
rr("C02_include_loops_itself", "the included file loops on its own label with jump SELF; ends; deck goes on (kn 5000 in the include's pass 2)",
   "include lp.in\nrun 100\n", data={"lp.in": "variable j loop 2\nlabel a\nif \"$j == 2\" then \"" + K5.strip() + "\"\nrun 20\nnext j\njump SELF a\n"})
rr("C03_string_if_elif", "variable mode string soft; if hard ... elif soft kn 5000 else kn 8000", "variable mode string soft\nif \"${mode} == hard\" then \"" + K8.strip() + "\" elif \"${mode} == soft\" \"" + K5.strip() + "\" else \"print none\"\nrun 100\n")
rr("C04_three_nested_if_includes", "a.in if-includes b.in, b.in if-includes c.in, c.in sets kn 5000", "if 1 then \"include a.in\"\nrun 100\n",
   data={"a.in": "if 1 then \"include b.in\"\n", "b.in": "variable q equal 1\nif \"$q == 1\" then \"include c.in\"\n", "c.in": K5})
rr("C05_include_next_jump_deck_label", "the loop's body is in an include that does next and jumps back to the deck's label",
   "variable i loop 3\nlabel top\ninclude body.in\n" + K5 + "run 10\n",
   data={"body.in": "run 20\nif \"$i == 3\" then \"" + K8.strip() + "\"\nnext i\njump in.deck top\n"})
rr("C06_logic_ops", "if \"(1 > 2) || !(3 < 2) && 1\" then kn 5000", "if \"(1 > 2) || !(3 < 2) && 1\" then \"" + K5.strip() + "\"\nrun 100\n")
rr("C07_nested_loops", "i loop 2 x j loop 2; kn = 2000 + 1000*(i+j) -> last 6000", "variable i loop 2\nlabel li\nvariable j loop 2\nlabel lj\npair_coeff * * hooke $(2000+1000*(v_i+v_j)) 3000 " + K + "\nrun 10\nnext j\njump SELF lj\nvariable j delete\nnext i\njump SELF li\n")
rr("C08_jump_forward_skip", "jump SELF later skips kn 8000", "jump SELF later\n" + K8 + "label later\nrun 100\n")
rr("C09_jump_file_no_return", "jump j.in (kn 5000, run); lines after the jump in the deck never run (kn 8000)", "jump j.in\n" + K8 + "run 100\n", data={"j.in": K5 + "run 100\n"})
rr("C10_include_in_loop_with_next", "loop body includes b.in that calls next and jumps SELF?? (next in include, jump in deck)", "variable i loop 3\nlabel l\nrun 10\ninclude b.in\njump SELF l\n" + K5 + "run 10\n",
   data={"b.in": "if \"$i == 2\" then \"" + K8.strip() + "\"\nnext i\n"})
rr("C11_is_file_condition", "if $(is_file(kn.in)) then include kn.in", "if $(is_file(kn.in)) then \"include kn.in\"\nrun 100\n", data=KN5)
rr("C12_is_file_absent", "if $(is_file(none.in)) then include none.in else kn 8000", "if $(is_file(none.in)) then \"include none.in\" else \"" + K8.strip() + "\"\nrun 100\n")
rr("C13_last_pass_include_dt_pair", "loop of 2; last pass includes a file with timestep 2e-5 and kn 5000", "variable i loop 2\nlabel l\nif \"$i == 2\" then \"include last.in\"\nrun 50\nnext i\njump SELF l\n",
   data={"last.in": "timestep 2e-5\n" + K5})
rr("C14_duplicate_labels", "two 'label a' lines; jump SELF a goes to the first", "variable n loop 2\nlabel a\nif \"$n == 2\" then \"jump SELF done\"\nnext n\njump SELF a\nlabel a\n" + K8 + "label done\n" + K5 + "run 100\n")
rr("C15_if_elif_include_in_loop_in_include", "deck includes main.in which loops 2 passes; pass 2's elif includes kn.in", "include main.in\nrun 10\n",
   data={"main.in": "variable i loop 2\nlabel l\nif \"$i == 1\" then \"print one\" elif \"$i == 2\" \"include kn.in\"\nrun 10\nnext i\njump SELF l\n", **KN5})
rr("C16_is_active", "if $(is_active(pair,granular)) then kn 5000", "if $(is_active(pair,granular)) then \"" + K5.strip() + "\"\nrun 100\n")
rr("C17_label_in_include_jump_self", "include with a label after an if: if 1 then 'jump SELF x' inside the include skips its kn 8000", "include s.in\nrun 100\n",
   data={"s.in": "if 1 then \"jump SELF x\"\n" + K8 + "label x\n" + K5})
rr("C18_quit_in_loop_include", "loop; pass 2's include quits; kn 8000 after the loop never reached", "variable i loop 3\nlabel l\nrun 20\nif \"$i == 2\" then \"include q.in\"\n" + K5 + "next i\njump SELF l\n" + K8 + "run 10\n", data={"q.in": "quit 0\n"})
rr("C19_next_exhaust_skip", "next on an index of 2 items after the loop is exhausted: the jump after next is skipped", "variable k index 5000 8000\nlabel l\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 20\nnext k\njump SELF l\nrun 10\n")
rr("C20_if_multiple_commands_mixed", "if 1 then \"variable a equal 5000\" \"pair_coeff * * hooke ${a} ...\" (the ${a} in a quoted cmd expanded when run)",
   "if 1 then \"variable a equal 5000\" \"pair_coeff * * hooke ${a} 3000 " + K + "\"\nrun 100\n")

# ---------------------------------------------------------------- V: variable styles
rr("V01_delayed_equal", "variable a equal 2000; variable k equal v_a*2.5; a redefined 3200; pair_coeff $(v_k) -> 8000", "variable a equal 2000\nvariable k equal v_a*2.5\nvariable a equal 3200\npair_coeff * * hooke $(v_k) 3000 " + K + "\nrun 100\n")
rr("V02_immediate_frozen", "variable a equal 2000; variable k equal ${a}*2.5 (frozen 5000); a redefined", "variable a equal 2000\nvariable k equal ${a}*2.5\nvariable a equal 3200\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 100\n")
rr("V03_getenv_putenv_include", "shell putenv F26F=kn.in; variable f getenv F26F; include ${f}", "shell putenv F26F=kn.in\nvariable f getenv F26F\ninclude ${f}\nrun 100\n", data=KN5)
rr("V04_file_var_loop", "variable k file ks.txt (2000 5000 8000) looped with next/jump; a run each", "variable k file ks.txt\nlabel l\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 10\nnext k\njump SELF l\n", data={"ks.txt": "2000\n# c\n5000\n8000\n"})
rr("V05_atomfile_after_create", "variable d atomfile d.txt (ids 1 2 3: 0.005 0.007 0.003), third atom made after", "create_atoms 1 single 0.03 0.03 0.02\nvariable d atomfile d.txt\nset group all diameter v_d\nrun 100\n",
   data={"d.txt": "# sizes\n3\n1 0.005\n2 0.007\n3 0.003\n"})
rr("V06_loop_pad_include", "variable i loop 2 pad (01..02)? loop 10 pad -> 01; include k${i}.in for i 1 2 then break", "variable i loop 10 pad\nlabel l\ninclude k${i}.in\nrun 10\nif \"$i == 2\" then \"jump SELF out\"\nnext i\njump SELF l\nlabel out\n",
   data={"k01.in": K5, "k02.in": K8})
rr("V07_count_function", "pair_coeff hooke $(2500*count(all)) -> 5000 (2 atoms)", "pair_coeff * * hooke $(2500*count(all)) 3000 " + K + "\nrun 100\n")
rr("V08_string_law", "variable law string \"hooke 5000 3000 ...\"; pair_coeff * * ${law}", "variable law string \"" + hk(5000) + "\"\npair_coeff * * ${law}\nrun 100\n")
rr("V09_set_density_equal_var", "set type 2 density v_rho with an equal-style rho (engine decides)", "variable rho equal 7800\nset type 2 density v_rho\nrun 100\n")
rr("V10_internal", "variable k internal 5000; pair_coeff ${k}", "variable k internal 5000\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 100\n")
rr("V11_loop_start_end", "variable i loop 3 5; kn = 1000*i at the last (5000)", "variable i loop 3 5\nlabel l\npair_coeff * * hooke $(1000*v_i) 3000 " + K + "\nrun 10\nnext i\njump SELF l\n")
rr("V12_single_char_var", "variable s string hooke; pair_coeff * * $s 5000 ...", "variable s string hooke\npair_coeff * * $s 5000 3000 " + K + "\nrun 100\n")
rr("V13_ternary", "pair_coeff hooke $(ternary(count(all)>1,5000,8000))", "pair_coeff * * hooke $(ternary(count(all)>1,5000,8000)) 3000 " + K + "\nrun 100\n")
rr("V14_uloop_two", "variable i uloop 2; loop; pass 2 kn 5000", "variable i uloop 2\nlabel l\nif \"$i == 2\" then \"" + K5.strip() + "\"\nrun 10\nnext i\njump SELF l\n")
rr("V15_atomfile_in_loop_next", "atomfile with 2 sets; next d in pass 2 of a loop; set diameter each pass", "variable d atomfile d.txt\nvariable i loop 2\nlabel l\nset group all diameter v_d\nrun 10\nnext d\nnext i\njump SELF l\n",
   data={"d.txt": "2\n1 0.004\n2 0.006\n2\n1 0.004\n2 0.009\n"})
rr("V16_equal_mass_function", "kn = $(2000*mass(all)/mass(all)*2.5) (5000)", "pair_coeff * * hooke $(2000*mass(all)/mass(all)*2.5) 3000 " + K + "\nrun 100\n")
rr("V17_getenv_unset_default_if", "variable e getenv F26_NOT_SET; if \"${e} == \"\" \" ... (empty) kn 5000", "variable e getenv F26_NOT_SET_X\nif \"x${e}x == xx\" then \"" + K5.strip() + "\" else \"" + K8.strip() + "\"\nrun 100\n")
rr("V18_index_in_include_next_in_deck", "index defined in an include, next in the deck; kn ${k} -> 8000", "include v.in\nnext k\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 100\n", data={"v.in": "variable k index 5000 8000\n"})

# ---------------------------------------------------------------- R: restyles, clear, files the deck writes
rr("R01_restyle_gran_hooke_history", "run 100; pair_style gran/hooke/history 5000 NULL 3000 NULL 0.5 1; run 100", "run 100\npair_style gran/hooke/history 5000 NULL 3000 NULL 0.5 1\npair_coeff * *\nrun 100\n")
rr("R02_clear_then_cgs", "run 100; clear; units cgs deck (hooke 5e6); --g 100", "run 100\nclear\n" + m.ubase("cgs", "hooke 5e6 3000 " + K, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n", g="100")
rr("R03_write_read_restart_pair_after", "write_restart; clear; read_restart; pair_coeff kn 5000 after", "run 100\nwrite_restart a.restart\nclear\nread_restart a.restart\n" + K5 + "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\nrun 100\n")
rr("R04_write_data_nocoeff_read", "write_data nocoeff; clear; read_data; pair granular kn 8000", "run 100\nwrite_data a.data nocoeff\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data a.data\npair_style granular\n" + K8 + GRAV + "fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL\n" + TAIL + "run 100\n")
rr("R05_restart_in_loop_read_last", "loop writes restart files; read_restart of the last one", "variable i loop 2\nlabel l\nrun 50\nwrite_restart r$i.restart\nnext i\njump SELF l\nclear\nread_restart r2.restart\n" + K5 + GRAV + FLOOR + "fix integ all nve/sphere\nrun 100\n")
rr("R06_pair_none_then_granular", "pair_style none; run; pair_style granular kn 5000; run", "pair_style none\nrun 50\npair_style granular\n" + K5 + "run 100\n")
rr("R07_clear_in_if", "if 1 then clear (then rebuild with kn 8000)", "run 10\nif 1 then \"clear\"\n" + BASE().replace(HK, hk(8000)) + TWO + "run 100\n")
rr("R08_read_data_write_data_labels", "labelmap; write_data with labels; clear; read_data; pair_coeff big big kn 8000", "labelmap atom 1 small 2 big\nwrite_data l.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data l.data\npair_style granular\npair_coeff * * " + HK + "\npair_coeff big big " + hk(8000) + "\n" + GRAV + FLOOR + TAIL + "run 100\n")
rr("R09_restyle_gran_hooke_then_granular", "pair_style gran/hooke 8000 ..., run, then pair_style granular kn 5000", "pair_style gran/hooke 8000 NULL 3000 NULL 0.5 1\npair_coeff * *\nrun 50\npair_style granular\n" + K5 + "run 50\n")
rr("R10_read_restart_restyle", "write_restart; clear; read_restart; pair_style granular again kn 5000", "run 50\nwrite_restart b.restart\nclear\nread_restart b.restart\npair_style granular\n" + K5 + GRAV + FLOOR + "fix integ all nve/sphere\nrun 50\n")
rr("R11_write_data_pair_ij_read", "write_data (with PairIJ coeffs); clear; read_data restores coeffs; no pair_coeff after (engine decides)", "pair_coeff 1 2 " + hk(5000) + "\nrun 10\nwrite_data p.data pair ij\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data p.data\n" + GRAV + FLOOR + TAIL + "run 100\n")
rr("R12_read_dump_own", "dump in run 1, read_dump replaces positions (known B class? dump; max 1)", "dump d all custom 50 a.dump id type x y z vx vy vz\nrun 50\nundump d\nread_dump a.dump 50 x y z vx vy vz\n" + K5 + "run 50\n")

# ---------------------------------------------------------------- H: runs the engine stops or ends, run arguments
rr("H01_lost_atoms_run2", "run 1 fine; velocity type 2 up 100 m/s; run 2 loses it (Lost atoms); kn 5000 after", "run 50\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 200\n" + K5 + "run 50\n")
rr("H02_halt_soft_then_runs", "fix halt error soft met (step>=50): later runs skipped; kn 5000 never in a run", "fix h all halt 10 v_s >= 50 error soft\nvariable s equal step\nrun 100\n" + K5 + "run 100\n")
rr("H03_halt_continue_then_runs", "fix halt error continue met in run 1; unfix; kn 5000; run", "variable s equal step\nfix h all halt 10 v_s >= 50 error continue\nrun 100\nunfix h\n" + K5 + "run 100\n")
rr("H04_timer_timeout_long_run", "timer timeout 0:00:01; run 3000000 (ends by timeout); kn 5000; run 100 (skipped? engine)", "timer timeout 0:00:01 every 1000\nrun 3000000\n" + K5 + "run 100\n")
rr("H05_run_every_variable", "run 200 every 100 \"variable x equal 1\" (known A; one case)", "run 200 every 100 \"variable x equal 1\"\n" + K5 + "run 100\n")
rr("H06_lost_ignore_type2_gone", "thermo_modify lost ignore; type 2 thrown out; kn 5000; rows for 2?", "thermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 300\n" + K5 + "run 50\n")
rr("H07_halt_tlimit_continue", "fix halt tlimit > 1e6 (never); three runs", "fix h all halt 10 tlimit > 1000000 error hard\nrun 50\nrun 50\n" + K5 + "run 50\n")
rr("H08_upto_below_current", "run 200; run 100 upto (below the current step: engine decides)", "run 200\n" + K5 + "run 100 upto\n")
rr("H09_halt_hard_in_loop", "loop of 4 runs; fix halt error hard met on pass 3 (step >= 250)", "variable s equal step\nfix h all halt 10 v_s >= 250 error hard\nvariable i loop 4\nlabel l\nrun 100\nnext i\njump SELF l\n" + K5 + "run 10\n")
rr("H10_lost_in_loop_if_count", "loop; pass 2 throws type 2 out (lost ignore); if count(all) < 2 then kn 5000", "thermo_modify lost ignore\ngroup t2 type 2\nvariable i loop 2\nlabel l\nif \"$i == 2\" then \"velocity t2 set 0 0 100\"\nrun 200\nnext i\njump SELF l\nif \"$(count(all)) < 2\" then \"" + K5.strip() + "\"\nrun 10\n")
rr("H11_run_start_stop_after_upto", "run 100 upto; run 100 start 0 stop 400; kn 5000; run 200 start 0 stop 400", "run 100 upto\nrun 100 start 0 stop 400\n" + K5 + "run 200 start 0 stop 400\n")
rr("H12_run_every_null_halt", "run 500 every 100 NULL with a soft halt met at 250", "variable s equal step\nfix h all halt 10 v_s >= 250 error soft\nrun 500 every 100 NULL\n" + K5 + "run 100\n")
rr("H13_run_pre_no_first", "run 0 post no; run 100 pre no; kn 5000; run 100 pre no post no", "run 0 post no\nrun 100 pre no\n" + K5 + "run 100 pre no post no\n")
rr("H14_halt_message_no_soft", "fix halt error soft message no met; later run skipped", "variable s equal step\nfix h all halt 10 v_s >= 20 error soft message no\nrun 100\n" + K5 + "run 100\n")
rr("H15_lost_error_fff", "boundary f f f: type 2 thrown out sideways in run 2; Lost atoms", "change_box all boundary f f f\nrun 10\ngroup t2 type 2\nvelocity t2 set 100 0 0\nrun 200\n" + K5 + "run 10\n")
rr("H16_halt_continue_upto", "halt continue at step 60 in run 1 (100); run 200 upto after", "variable s equal step\nfix h all halt 10 v_s >= 60 error continue\nrun 100\nunfix h\n" + K5 + "run 200 upto\n")

# ---------------------------------------------------------------- L: LIGGGHTS
LH2 = lambda: m.lhead(nt=2) + ("fix m1 all property/global youngsModulus peratomtype 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3\n"
                              "fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n")
E2 = lambda a, b, c: f"fix m3 all property/global coefficientRestitution peratomtypepair 2 {a} {b} {b} {c}\n"
A1 = "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
W2 = "fix wprim all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n"
LR = m.LRUN + "run 1000\n"
L("L01_walls_type2_primitive", "# LIGGGHTS: type 2 only for walls (primitive floor); atoms type 1; e 0.7 (1 1), 0.4 (1 2 = wall)\n" + LH2() + E2(0.7, 0.4, 0.9) + m.HERTZ + W2 + A1 + LR, g=1)
STL = ("solid f\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 -0.05 0\nvertex 0.05 0.05 0\nendloop\nendfacet\n"
       "facet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 0.05 0\nvertex -0.05 0.05 0\nendloop\nendfacet\nendsolid f\n")
L("L02_walls_type2_mesh", "# LIGGGHTS: mesh floor of type 2 (walls-only type), hertz, e 0.7/0.4\n" + LH2() + E2(0.7, 0.4, 0.9) + m.HERTZ
  + "fix cad all mesh/surface file floor.stl type 2\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n" + A1 + LR, g=1, data={"floor.stl": STL})
L("L03_e_format_immediate", "# LIGGGHTS: e matrix from $(0.3*2) etc.\n" + LH2() + "fix m3 all property/global coefficientRestitution peratomtypepair 2 $(0.3*2) $(0.25+0.2) $(0.25+0.2) 0.8\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L04_hooke_e_one_walls_type2", "# LIGGGHTS hooke e 1.0 everywhere, walls type 2\n" + LH2() + E2(1.0, 1.0, 1.0) + "fix m4 all property/global characteristicVelocity scalar 2.\n" + m.HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)
L("L05_hertz_limitForce_on", "# LIGGGHTS hertz limitForce on (no attraction at the end: eps above e?), e 0.3\n" + LH2() + E2(0.3, 0.3, 0.3)
  + "pair_style gran model hertz tangential history limitForce on\npair_coeff * *\n" + W2 + A1 + LR, g=1)
L("L06_hooke_limitForce_on", "# LIGGGHTS hooke limitForce on, e 0.3\n" + LH2() + E2(0.3, 0.3, 0.3) + "fix m4 all property/global characteristicVelocity scalar 2.\n"
  + "pair_style gran model hooke tangential history limitForce on\npair_coeff * *\nfix wprim all wall/gran model hooke tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)
L("L07_insert_pack_gaussian", "# LIGGGHTS insert/pack with radius gaussian template (type 1), walls type 2, e 0.6/0.5\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2
  + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius gaussian number 0.003 0.0005\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + "region bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n" + m.LRUN + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 15 region bc\nrun 1000\n", g=1)
L("L08_insert_stream_e_index_next", "# LIGGGHTS insert/stream; e from index var after next (0.35)\n" + LH2() + "variable e index 0.8 0.35\nnext e\nfix m3 all property/global coefficientRestitution peratomtypepair 2 ${e} ${e} ${e} ${e}\n" + m.HERTZ + W2
  + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + "fix inface all mesh/surface file face.stl type 2\n" + m.LRUN
  + "fix ins all insert/stream seed 32452867 distributiontemplate pdd nparticles 10 massrate 0.1 insert_every 200 overlapcheck yes all_in no vel constant 0 0 -1 insertion_face inface extrude_length 0.02\nrun 1000\n",
  g=1, data={"face.stl": "solid f\nfacet normal 0 0 -1\nouter loop\nvertex -0.03 -0.03 0.1\nvertex 0.03 0.03 0.1\nvertex 0.03 -0.03 0.1\nendloop\nendfacet\nfacet normal 0 0 -1\nouter loop\nvertex -0.03 -0.03 0.1\nvertex -0.03 0.03 0.1\nvertex 0.03 0.03 0.1\nendloop\nendfacet\nendsolid f\n"})
L("L09_cohesion_sjkr_walls2", "# LIGGGHTS hertz cohesion sjkr, walls type 2\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m5 all property/global cohesionEnergyDensity peratomtypepair 2 1e5 1e5 1e5 1e5\n"
  + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n" + W2 + A1 + LR, g=1)
L("L10_rolling_cdt", "# LIGGGHTS rolling_friction cdt (head-on no part), e 0.6\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m8 all property/global coefficientRollingFriction peratomtypepair 2 0.1 0.1 0.1 0.1\n"
  + "pair_style gran model hertz tangential history rolling_friction cdt\npair_coeff * *\n" + W2 + A1 + LR, g=1)
L("L11_e_if_loop_var", "# LIGGGHTS: loop of 2 runs; pass 2 sets e 0.25 by an if with a format\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + m.LRUN
  + "variable i loop 2\nlabel l\nif \"$(v_i:%.0f) == 2\" then \"" + E2(0.25, 0.25, 0.25).strip() + "\"\nrun 100\nnext i\njump SELF l\n", g=1)
L("L12_include_per_pass", "# LIGGGHTS: loop including e$i.in each pass (e1: 0.5, e2: 0.2)\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + m.LRUN
  + "variable i loop 2\nlabel l\ninclude e$i.in\nrun 100\nnext i\njump SELF l\n", g=1, data={"e1.in": E2(0.5, 0.5, 0.5), "e2.in": E2(0.2, 0.2, 0.2)})
L("L13_cgs_g100", "# LIGGGHTS units cgs hertz e typed; --g 100\n" + m.lhead(nt=2, units="cgs", box="-5 5 -5 5 -1 15").replace("neighbor 0.002", "neighbor 0.2")
  + "fix m1 all property/global youngsModulus peratomtype 5e7 5e7\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3\nfix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n"
  + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 1 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\n"
  + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n", g="100")
L("L14_move_mesh_type2", "# LIGGGHTS moving mesh floor (move/mesh linear) of type 2, e 0.7/0.4\n" + LH2() + E2(0.7, 0.4, 0.9) + m.HERTZ
  + "fix cad all mesh/surface file floor.stl type 2\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\nfix mv all move/mesh mesh cad linear 0. 0. 0.01\n" + A1 + LR, g=1, data={"floor.stl": STL})
L("L15_two_wall_types", "# LIGGGHTS 3 types: floor type 2 (e13?), cylinder type 3; atoms type 1: wall rows e12 0.5 and e13 0.7\n" + m.lhead() + m.MAT3 + m.E3 + m.HERTZ
  + "fix wf all wall/gran model hertz tangential history primitive type 2 zplane 0.0\nfix wc all wall/gran model hertz tangential history primitive type 3 zcylinder 0.04 0 0\n" + A1 + LR, g=1)
L("L16_e_one_diag_matrix_vars", "# LIGGGHTS e 1.0 for 1 1, 0.5 for 1 2 through variables\n" + LH2() + "variable a equal 1.0\nvariable b equal 0.5\nfix m3 all property/global coefficientRestitution peratomtypepair 2 ${a} ${b} ${b} ${a}\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L17_freeze_type1_liggghts", "# LIGGGHTS fix freeze on a group of one sphere\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + "group g1 id 1\nfix fz g1 freeze\n" + LR, g=1)
L("L18_viscous_liggghts", "# LIGGGHTS fix viscous 0.0005\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + "fix v all viscous 0.0005\n" + LR, g=1)
L("L19_set_density_after_insert", "# LIGGGHTS hooke (eps = e: sizes no part), set density after insert/pack\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m4 all property/global characteristicVelocity scalar 2.\n" + m.HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 2 zplane 0.0\n"
  + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + "region bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n" + m.LRUN + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 10 region bc\nrun 500\nset type 1 density 7800\nrun 500\n", g=1)
L("L20_hooke_viscous_on", "# LIGGGHTS hooke viscous on (Stokes-number e: needs more properties; engine decides)\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m4 all property/global characteristicVelocity scalar 2.\n"
  + "pair_style gran model hooke tangential history viscous on\npair_coeff * *\nfix wprim all wall/gran model hooke tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)
L("L21_tangential_damping_off", "# LIGGGHTS hertz tangential_damping off (head-on no part), e 0.45\n" + LH2() + E2(0.45, 0.45, 0.45)
  + "pair_style gran model hertz tangential history tangential_damping off\npair_coeff * *\n" + W2 + A1 + LR, g=1)
L("L22_e_string_matrix", "# LIGGGHTS e matrix as one string variable: ${m} = '0.55 0.4 0.4 0.3'\n" + LH2() + "variable m string \"0.55 0.4 0.4 0.3\"\nfix m3 all property/global coefficientRestitution peratomtypepair 2 ${m}\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L23_hooke_ktToKn", "# LIGGGHTS hooke ktToKnUser on (tangential only), e 0.6\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m4 all property/global characteristicVelocity scalar 2.\n"
  + "pair_style gran model hooke tangential history ktToKnUser on\npair_coeff * *\nfix wprim all wall/gran model hooke tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)
L("L24_jump_label_loop_e", "# LIGGGHTS jump SELF loop with index e 0.7 0.45 0.2 and a run each: last 0.2\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + m.LRUN
  + "variable e index 0.7 0.45 0.2\nlabel l\nfix m3 all property/global coefficientRestitution peratomtypepair 2 ${e} ${e} ${e} ${e}\nrun 50\nnext e\njump SELF l\n", g=1)
L("L25_halt_lost_liggghts", "# LIGGGHTS f f f box: a sphere thrown out (LIGGGHTS loses it? error?), e 0.3 after\n" + LH2() + E2(0.6, 0.5, 0.5) + m.HERTZ + W2 + A1 + m.LRUN
  + "run 100\ngroup g1 id 1\nvelocity g1 set 0 0 50\nrun 1000\n" + E2(0.3, 0.3, 0.3) + "run 100\n", g=1)
L("L26_hertz_e_low_cohesion_off_sjkr2", "# LIGGGHTS cohesion sjkr2 with cohesionEnergyDensity 0 (no cohesion)\n" + LH2() + E2(0.6, 0.5, 0.5) + "fix m5 all property/global cohesionEnergyDensity peratomtypepair 2 0 0 0 0\n"
  + "pair_style gran model hertz tangential history cohesion sjkr2\npair_coeff * *\n" + W2 + A1 + LR, g=1)
L("L27_insert_pack_two_types_walls3", "# LIGGGHTS insert/pack two templates types 1 2, wall type 3 (E3 matrix)\n" + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + m.WALL3
  + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\nfix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\n"
  + "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n" + m.LRUN
  + "fix ins all insert/pack seed 32452867 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 20 region bc\nrun 1000\n", g=1)


# ================================================================ second set (round 26, after batch 1)
# N: the engine stops at the set-up of a run (neighbor list overflow, neighbor bins after read_restart)
LAY = "lattice sc 0.004\nregion lay block 0.005 0.03 0.005 0.03 0.03 0.045 units box\ncreate_atoms 1 region lay\nset type 1 diameter 0.0042\n"
rr("N01_neigh_overflow_last_run", "touching lattice of 4.2 mm spheres at 4 mm spacing; neigh_modify one 2: overflow at the last run's set-up", LAY + "neigh_modify page 100 one 2\nrun 100\n")
rr("N02_neigh_overflow_then_run", "same overflow in a run followed by another (kn 5000)", LAY + "neigh_modify page 100 one 2\nrun 100\n" + K5 + "run 100\n")
rr("N03_restart_cycle_no_pair", "run; write_restart; clear; read_restart; run (LAMMPS: neighbor bins error at set-up)", "run 10\nwrite_restart r.bin\nclear\nread_restart r.bin\nrun 10\n")
rr("N04_restart_cycle_then_run", "R03 with a second run after the read_restart run", "run 100\nwrite_restart a.restart\nclear\nread_restart a.restart\n" + K5 + "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\nrun 100\n" + K8 + "run 100\n")
rr("N05_restart_cycle_neighbor_set", "R03 with neighbor 0.001 bin after read_restart (engine decides)", "run 100\nwrite_restart a.restart\nclear\nread_restart a.restart\nneighbor 0.001 bin\ncomm_modify vel yes\n" + K5 + "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\nrun 100\n")
rr("N06_big_default_sphere_then_set", "create_atoms 2 single (default 1 m) then set it to 6 mm before the run (engine runs?)", "create_atoms 2 single 0.03 0.03 0.05\nset atom 3 diameter 0.006 density 2500\nrun 10\n")
rr("N07_overflow_in_if_include", "the overflow set-up comes from an if's include (neigh_modify one 2)", LAY + "if 1 then \"include n.in\"\nrun 100\n", data={"n.in": "neigh_modify page 100 one 2\n"})
rr("N08_pour_then_overflow_loop", "a loop of runs; pass 2 sets neigh_modify one 2 (overflow on the lattice at pass 2's run)", LAY + "variable i loop 2\nlabel l\nif \"$i == 2\" then \"neigh_modify page 100 one 2\"\nrun 50\nnext i\njump SELF l\n")

# G: 2d decks: density/disc, enforce2d
def base2d(model=HK, extra=""):
    return ("units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.005 0.005 units box\ncreate_box 2 box\n"
            "pair_style granular\npair_coeff * * " + model + "\nfix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + model + " yplane 0 NULL\nfix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-5\n"
            "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\n" + extra)
deck("G01_2d_density_disc", "# 2d: set type 1 diameter 0.004 density/disc 2500, type 2 density 2500 (3d mass)\n" + base2d(extra="set type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density 2500\n") + "run 100\n", g=1)
deck("G02_2d_density_plain", "# 2d: set density 2500 (LAMMPS: 3d sphere mass unless density/disc)\n" + base2d(extra="set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n") + "run 100\n", g=1)
deck("G03_2d_pour", "# 2d fix pour diam range 0.003 0.005 (disc? sphere mass) type 2\n" + base2d(extra="set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nregion ins block 0.005 0.035 0.05 0.09 -0.005 0.005 units box\nfix p all pour 4 2 4767 region ins diam range 0.003 0.005 dens 2500 2500\n") + "run 2000\n", g=1)
deck("G04_2d_density_disc_if_include", "# 2d: density/disc set in an if's include\n" + base2d(extra="set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nif 1 then \"include d.in\"\n") + "run 100\n", g=1, data={"d.in": "set type 2 density/disc 2500\n"})
deck("G05_2d_hertz_material_disc", "# 2d: hertz/material viscoelastic with density/disc\n" + base2d(model=HM, extra="set type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density/disc 2500\n") + "run 100\n", g=1)

# A: fix adapt with a constant size factor, and other adapt forms
rr("A01_adapt_constant_reset_no", "fix adapt 1 atom diameter v_d with d equal 1.5 (constant), reset no", "variable d equal 1.5\nfix ad all adapt 1 atom diameter v_d reset no\nrun 100\n")
rr("A02_adapt_then_unfix", "fix adapt diameter 1.5 in run 1, unfix (reset no keeps the sizes), kn 5000 run 2", "variable d equal 1.5\nfix ad all adapt 1 atom diameter v_d reset no\nrun 100\nunfix ad\n" + K5 + "run 100\n")
rr("A03_adapt_reset_yes_unfix", "fix adapt diameter 1.5 reset yes (sizes restored at the end of the run), then run 2", "variable d equal 1.5\nfix ad all adapt 1 atom diameter v_d\nrun 100\nunfix ad\n" + K5 + "run 100\n")
rr("A04_adapt_pair_granular", "fix adapt pair granular? (engine decides)", "variable k equal 5000\nfix ad all adapt 1 pair granular kn * * v_k\nrun 100\n")

# P: shell cd and relative paths
rr("P01_shell_cd_include", "shell cd sub; include kn.in opens sub/kn.in (kn 5000), not ./kn.in (kn 8000)", "shell cd sub\ninclude kn.in\nrun 100\n", data={"sub/kn.in": K5, "kn.in": K8})
rr("P02_shell_cd_back", "shell cd sub; shell cd ..; include kn.in (./kn.in kn 8000)", "shell cd sub\nshell cd ..\ninclude kn.in\nrun 100\n", data={"sub/kn.in": K5, "kn.in": K8})
rr("P03_jump_var_label", "variable lab string L5; jump SELF ${lab}", "variable lab string L5\njump SELF ${lab}\nlabel L8\n" + K8 + "jump SELF end\nlabel L5\n" + K5 + "label end\nrun 100\n")
rr("P04_next_two_vars", "next i j on two loops at once; kn 1000*(i+j)+1000: last i 2 j 2 -> 5000", "variable i loop 2\nvariable j loop 2\nlabel l\npair_coeff * * hooke $(1000*(v_i+v_j)+1000) 3000 " + K + "\nrun 10\nnext i j\njump SELF l\n")
rr("P05_include_clear_rebuild_in_loop", "pass 2 of a loop includes a file that clears and rebuilds the deck with kn 8000 (the loop variable survives clear)",
   "variable i loop 2\nlabel l\nif \"$i == 2\" then \"include new.in\"\nrun 50\nnext i\njump SELF l\n", data={"new.in": "clear\n" + BASE().replace(HK, hk(8000)) + TWO})

# M: atomfile with a map (redo of V05/V15), mol sets, mixed
MAP = lambda: BASE().replace("comm_modify vel yes\n", "comm_modify vel yes\natom_modify map array\n")
deck("M01_atomfile_with_map", "# atom_modify map array; variable d atomfile (ids 1 2 3: 5, 7, 3 mm); set group all diameter v_d\n" + MAP() + TWO + "create_atoms 1 single 0.03 0.03 0.02\nvariable d atomfile d.txt\nset group all diameter v_d\nrun 100\n",
     g=1, data={"d.txt": "# sizes\n3\n1 0.005\n2 0.007\n3 0.003\n"})
deck("M02_atomfile_next_loop_map", "# map; atomfile with 2 sets; next d in a loop; type 2 9 mm in pass 2\n" + MAP() + TWO + "variable d atomfile d.txt\nvariable i loop 2\nlabel l\nset group all diameter v_d\nrun 10\nnext d\nnext i\njump SELF l\n",
     g=1, data={"d.txt": "2\n1 0.004\n2 0.006\n2\n1 0.004\n2 0.009\n"})
deck("M03_atomfile_density", "# map; atomfile density (id 2 7800) via set density v_r\n" + MAP() + TWO + "variable r atomfile r.txt\nset group all density v_r\nrun 100\n", g=1, data={"r.txt": "2\n1 2500\n2 7800\n"})
rr("M04_set_mol_region", "fix property/atom mol; set region mol 3; set mol 3 diameter 0.008 (type 1 at x 0.02, region x > 0.015)", "fix pm all property/atom mol ghost yes\nregion rt block 0.015 INF INF INF INF INF units box\nset region rt mol 3\nset mol 3 diameter 0.008\nrun 100\n")

# Q: more hybrid / labels / restyle mixes
hy("Q01_hybrid_labels_limit_damping", "hybrid granular: small big with limit_damping, gamma 30000 (sticky without it)",
   "labelmap atom 1 small 2 big\npair_style hybrid granular\npair_coeff * * granular " + HK + "\npair_coeff small big granular hooke 2000 30000 " + K + " limit_damping\n")
hy("Q02_hybrid_gran_hooke_history_labels_range", "hybrid granular gran/hooke/history: * big gran/hooke/history (1 2, 2 2)",
   "labelmap atom 1 small 2 big\npair_style hybrid granular gran/hooke/history 5000 NULL 3000 NULL 0.5 1\npair_coeff * * granular " + HK + "\npair_coeff * big gran/hooke/history\n")
hy("Q03_restyle_hybrid_to_granular", "hybrid granular zero then pair_style granular kn 5000 (restyle clears hybrid)",
   "pair_style hybrid granular zero 0.01\npair_coeff * * granular " + HK + "\npair_coeff 1 2 zero\npair_style granular\n" + K5)
hy("Q04_tsuji_labels_mixed", "labels; hertz/material tsuji e 0.5 for small big, hooke for the rest",
   "labelmap atom 1 small 2 big\npair_style granular\npair_coeff * * " + HK + "\npair_coeff small big hertz/material 1e7 0.5 0.3 damping tsuji " + TL + "\n")
hy("Q05_coeff_rest_range_three", "3 types: hooke coeff_restitution 0.3 on 1*2 3, mass_velocity elsewhere",
   "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 1*2 3 hooke 2000 0.3 damping coeff_restitution " + TL + "\n", nt=3)
hy("Q06_mixing_hertz_material_ranges", "3 types: hertz/material E by type range (1*2 1*2 E 1e7, 3 3 E 5e7): 1 3 and 2 3 mixed",
   "pair_style granular\npair_coeff 1*2 1*2 " + HM + "\npair_coeff 3 3 hertz/material 5e7 1.4e7 0.3 damping viscoelastic " + TL + "\n", nt=3)

# Y: runs stopped or not, more forms
rr("Y01_halt_soft_in_include_loop", "loop; pass 2 includes a file adding a soft halt met at once; kn 5000 after the loop", "variable s equal step\nvariable i loop 3\nlabel l\nif \"$i == 2\" then \"include h.in\"\nrun 50\nnext i\njump SELF l\n" + K5 + "run 50\n",
   data={"h.in": "fix h all halt 5 v_s >= 0 error soft\n"})
rr("Y02_lost_ignore_then_create", "lost ignore; type 2 thrown out in run 1; create_atoms 2 (default size) + set 8 mm; run", "thermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.008 density 2500\nrun 50\n")
rr("Y03_timer_timeout_loop_passes", "timer timeout 0:00:01 then a loop of 3 long runs (the first ends by timeout)", "timer timeout 0:00:01 every 1000\nvariable i loop 3\nlabel l\nrun 3000000\nnext i\njump SELF l\n")
rr("Y04_run_upto_after_halt_continue", "halt continue at 60; run 200 upto; kn 5000; run 300 upto", "variable s equal step\nfix h all halt 10 v_s >= 60 error continue\nrun 100\nunfix h\nrun 200 upto\n" + K5 + "run 300 upto\n")
rr("Y05_run_every_print_in_loop", "loop of 2 with run 100 every 50 \"print $i\"; kn 5000 on pass 2", "variable i loop 2\nlabel l\nif \"$i == 2\" then \"" + K5.strip() + "\"\nrun 100 every 50 \"print 'pass $i'\"\nnext i\njump SELF l\n")
rr("Y06_halt_hard_never_met_many", "fix halt error hard never met over a loop of 5 runs; kn 5000 last", "variable s equal step\nfix h all halt 10 v_s > 100000 error hard\nvariable i loop 5\nlabel l\nrun 40\nnext i\njump SELF l\n" + K5 + "run 10\n")
rr("Y07_lost_error_pff_loop", "boundary with f: a loop whose pass 2 throws type 2 up (Lost atoms at pass 2)", "group t2 type 2\nvariable i loop 3\nlabel l\nif \"$i == 2\" then \"velocity t2 set 0 0 100\"\nrun 200\nnext i\njump SELF l\n")

# Z: units with walls, gravity and format
deck("Z01_cgs_wall_gravity_g100", "# units cgs hooke pair and wall kn 5e6, gravity 981; --g 100\n" + ub("cgs", "hooke 5e6 3000 " + K, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "fix grav all gravity 981 vector 0 0 -1\ntimestep 1e-5\nrun 100\n", g="100")
deck("Z02_lj_format_kn", "# units lj, kn $(4000/2:%.0f) = 2000, --g 1\n" + ub("lj", "hooke 2000 3 " + K, "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "pair_coeff * * hooke $(5000/2:%.0f) 3 " + K + "\ntimestep 1e-4\nrun 100\n", g="1")
deck("Z03_micro_include_if_dt", "# units micro hertz/material; timestep from an if's include (2e-2: coarse?)\n" + ub("micro", "hertz/material 1e4 1.4e-5 0.3 damping viscoelastic " + TL, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\nif 1 then \"include t.in\"\nrun 100\n", g="1", data={"t.in": "timestep 2e-2\n"})
deck("Z04_cgs_tsuji_g_list", "# units cgs hertz/material tsuji e 0.5 (eps depends on speed? no: tsuji), --g '10 100 1000'\n" + ub("cgs", "hertz/material 1e8 0.5 0.3 damping tsuji " + TL, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n", g="10 100 1000")
deck("Z05_lj_pour_range", "# units lj: pour diam range 0.5 1.0 type 2, hooke kn 2000 gamma 3 mass_velocity, --g 1\n" + ub("lj", "hooke 2000 3 " + K, "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "fix grav all gravity 1 vector 0 0 -1\nregion ins block 1 9 1 9 10 18 units box\nfix p all pour 5 2 4767 region ins diam range 0.5 1.0 dens 1 1\ntimestep 1e-3\nrun 3000\n", g="1")

# LIGGGHTS, second set
LT2 = lambda e=(0.6, 0.5, 0.5): LH2() + E2(*e)
L("L28_include_e_file_walls2", "# LIGGGHTS: e matrix in an include (plain), walls type 2, e 0.35/0.8\n" + LH2() + "include mat.in\n" + m.HERTZ + W2 + A1 + LR, g=1, data={"mat.in": E2(0.35, 0.8, 0.9)})
L("L29_unfix_wall_liggghts", "# LIGGGHTS: wall e12 0.4; unfix wprim; new wall type 2 hooke? no: hertz again, e via matrix 0.4; run 2 (engine decides)\n" + LT2((0.6, 0.4, 0.9)) + m.HERTZ + W2 + A1 + m.LRUN + "run 100\nunfix wprim\nfix wp2 all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n" + E2(0.6, 0.25, 0.9) + "run 100\n", g=1)
L("L30_exclude_liggghts_type1", "# LIGGGHTS: neigh_modify exclude type 1 1 (atoms type 1 only): 1 1 cannot meet; wall row stays\n" + LT2() + "neigh_modify exclude type 1 1\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L31_hooke_stiffness_matrices", "# LIGGGHTS hooke/stiffness: kn 2000 gamman 3000? (engine decides eps)\n" + LH2() + "fix k1 all property/global kn peratomtypepair 2 2000 2000 2000 2000\nfix k2 all property/global kt peratomtypepair 2 2000 2000 2000 2000\n"
  + "fix k3 all property/global gamman peratomtypepair 2 10 10 10 10\nfix k4 all property/global gammat peratomtypepair 2 10 10 10 10\npair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
  + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)
L("L32_if_string_compare_liggghts", "# LIGGGHTS: variable mode string soft; if \"${mode} == soft\" then e 0.3 (string compare in LIGGGHTS' if?)\n" + LT2() + "variable mode string soft\nif \"${mode} == soft\" then \"" + E2(0.3, 0.3, 0.3).strip() + "\"\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L33_run_upto_e_change", "# LIGGGHTS: run 300 upto, e 0.3, run 600 upto\n" + LT2() + m.HERTZ + W2 + A1 + m.LRUN + "run 300 upto\n" + E2(0.3, 0.3, 0.3) + "run 600 upto\n", g=1)
L("L34_e_matrix_continuation", "# LIGGGHTS: e matrix split over lines with &\n" + LH2() + "fix m3 all property/global coefficientRestitution peratomtypepair 2 &\n  0.65 0.45 &\n  0.45 0.9\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L35_mesh_type3_and_primitive_type2", "# LIGGGHTS 3 types: mesh floor type 3 (e13 0.7), primitive cylinder type 2 (e12 0.5), atoms type 1\n" + m.lhead() + m.MAT3 + m.E3 + m.HERTZ
  + "fix cad all mesh/surface file floor.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\nfix wc all wall/gran model hertz tangential history primitive type 2 zcylinder 0.04 0 0\n" + A1 + LR, g=1, data={"floor.stl": STL})
L("L36_freeze_then_unfix", "# LIGGGHTS: fix freeze on atom 1 in run 1, unfixed for run 2 with e 0.3\n" + LT2() + m.HERTZ + W2 + A1 + m.LRUN + "group g1 id 1\nfix fz g1 freeze\nrun 100\nunfix fz\n" + E2(0.3, 0.3, 0.3) + "run 100\n", g=1)
L("L37_hertz_limitForce_loop", "# LIGGGHTS: loop of 2 runs; pass 2 restyles the pair with limitForce on (e 0.3)\n" + LT2((0.3, 0.3, 0.3)) + m.HERTZ + W2 + A1 + m.LRUN
  + "variable i loop 2\nlabel l\nif \"$i == 2\" then \"pair_style gran model hertz tangential history limitForce on\" \"pair_coeff * *\"\nrun 100\nnext i\njump SELF l\n", g=1)
L("L38_e_one_hertz_walls_mesh", "# LIGGGHTS hertz e 1.0 with a mesh wall type 2\n" + LT2((1.0, 1.0, 1.0)) + m.HERTZ + "fix cad all mesh/surface file floor.stl type 2\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n" + A1 + LR, g=1, data={"floor.stl": STL})
L("L39_variable_e_equal_delayed", "# LIGGGHTS: variable a equal 0.2; e matrix ${a}; a redefined 0.7 after (no effect)\n" + LH2() + "variable a equal 0.2\nfix m3 all property/global coefficientRestitution peratomtypepair 2 ${a} ${a} ${a} ${a}\nvariable a equal 0.7\n" + m.HERTZ + W2 + A1 + LR, g=1)
L("L40_two_atom_types_insert_walls3_cohesion_off", "# LIGGGHTS types 1 2 atoms, wall type 3, hooke characteristicVelocity, e matrix E3\n" + m.lhead() + m.MAT3 + m.E3 + "fix m4 all property/global characteristicVelocity scalar 2.\n" + m.HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + m.ATOMS + LR, g=1)


# ================================================================ third set: hybrid with one granular sub-style, none (after T07/T14)
HN = "pair_style hybrid granular\npair_coeff * * granular " + HK + "\n"
hy("T17_hybrid_one_none_numeric", "hybrid granular (one sub-style); pair_coeff 1 2 none (numeric)", HN + "pair_coeff 1 2 none\n")
hy("T18_hybrid_one_none_11", "hybrid granular (one sub-style); pair_coeff 1 1 none", HN + "pair_coeff 1 1 none\n")
hy("T19_hybrid_overlay_one_none", "hybrid/overlay granular (one sub-style); pair_coeff 1 2 none", "pair_style hybrid/overlay granular\npair_coeff * * granular " + HK + "\npair_coeff 1 2 none\n")
hy("T20_hybrid_one_star_none_then_11", "hybrid granular; pair_coeff * * none then 1 1 and 2 2 granular (1 2 never granular: engine decides)",
   "pair_style hybrid granular\npair_coeff * * none\npair_coeff 1 1 granular " + HK + "\npair_coeff 2 2 granular " + hk(8000) + "\n")
hy("T21_hybrid_one_none_in_if_include", "hybrid granular; 1 2 none from an if's include", HN + "if 1 then \"include n.in\"\n", data={"n.in": "pair_coeff 1 2 none\n"})
hy("T22_hybrid_one_none_3types", "3 types, hybrid granular; pair_coeff 2*3 3 none (2 3 and 3 3)", HN + "pair_coeff 2*3 3 none\n", nt=3)
hy("T23_hybrid_two_styles_none_reassigned", "hybrid granular gran/hooke: 1 2 none then 1 2 gran/hooke (kn 5000)", "pair_style hybrid granular gran/hooke 5000 NULL 3000 NULL 0.5 1\npair_coeff * * granular " + HK + "\npair_coeff 1 2 none\npair_coeff 1 2 gran/hooke\n")
hy("T24_hybrid_one_none_exclude_none", "hybrid granular; 1 2 none; neigh_modify exclude type 1 2 then exclude none", HN + "pair_coeff 1 2 none\nneigh_modify exclude type 1 2\nneigh_modify exclude none\n")
hy("T25_hybrid_one_gran_hooke_none", "hybrid gran/hooke/history (one old sub-style); pair_coeff 1 2 none", "pair_style hybrid gran/hooke/history 2000 NULL 3000 NULL 0.5 1\npair_coeff * * gran/hooke/history\npair_coeff 1 2 none\n")
hy("T26_hybrid_one_restyle_plain", "hybrid granular with 1 2 none, then pair_style granular (restyle) kn 5000", HN + "pair_coeff 1 2 none\npair_style granular\n" + K5)
rr("T27_hybrid_one_none_between_runs", "run with plain granular; then pair_style hybrid granular with 1 2 none; run", "run 50\n" + HN + "pair_coeff 1 2 none\nrun 50\n")


# ================================================================ fourth set: lattice units of regions (wall curvature), mixing of unlike models
HMW = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic " + TL
def fbase(extra_wall, lat="", model=HMW):
    return ("units si\natom_style sphere 1\nboundary f f f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n" + lat
            + "pair_style granular\npair_coeff * * " + model + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + model + " zplane 0 NULL\n"
            + extra_wall + "\nfix integ all nve/sphere\ntimestep 1e-5\n"
            + "create_atoms 1 single 0.02 0.02 0.01 units box\ncreate_atoms 2 single 0.012 0.02 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("RU01_cyl_region_lattice_units", "# lattice sc 0.5 (scale 0.5); region cylinder z 0.04 0.04 0.038 0 0.2 in lattice units (= 0.02 0.02 r 0.019 box); wall/gran/region hertz/material\n"
     + fbase("region cyl cylinder z 0.04 0.04 0.038 0 0.2 side in\nfix cw all wall/gran/region granular " + HMW + " region cyl", lat="lattice sc 0.5\n"), g=1)
deck("RU02_cyl_region_box_units", "# RU01 with the region in box units (control)\n"
     + fbase("region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nfix cw all wall/gran/region granular " + HMW + " region cyl"), g=1)
deck("RU03_sphere_region_lattice_units", "# lattice sc 0.5; region sphere 0.04 0.04 0.1 0.1 side in (lattice units: centre 0.02 0.02 0.05 r 0.05); wall hertz/material\n"
     + fbase("region ball sphere 0.04 0.04 0.1 0.1 side in\nfix bw all wall/gran/region granular " + HMW + " region ball", lat="lattice sc 0.5\n"), g=1)
deck("RU04_zcylinder_hertz", "# fix wall/gran zcylinder 0.019 (box f f f) hertz/material: curvature 0.019 m\n"
     + fbase("fix cw all wall/gran granular " + HMW + " zcylinder 0.019").replace("create_atoms 1 single 0.02 0.02", "create_atoms 1 single 0.025 0.02"), g=1)
deck("RU05_cyl_lattice_fcc", "# lattice fcc 0.4 (si: the lattice constant 0.4, scale for regions 0.4); region cylinder 0.05 0.05 0.0475 in lattice units -> 0.02 0.02 0.019\n"
     + fbase("region cyl cylinder z 0.05 0.05 0.0475 0 0.25 side in\nfix cw all wall/gran/region granular " + HMW + " region cyl", lat="lattice fcc 0.4\n"), g=1)
deck("RU06_sphere_obstacle_out_hertz", "# region sphere side out (a 5 mm ball obstacle) hertz/material, units box\n"
     + fbase("region ball sphere 0.03 0.03 0.06 0.005 side out units box\nfix bw all wall/gran/region granular " + HMW + " region ball"), g=1)
deck("RU07_cyl_lattice_in_include", "# the lattice command in an if's include; region cylinder in lattice units in the deck\n"
     + fbase("if 1 then \"include lat.in\"\nregion cyl cylinder z 0.04 0.04 0.038 0 0.2 side in\nfix cw all wall/gran/region granular " + HMW + " region cyl"), g=1, data={"lat.in": "lattice sc 0.5\n"})
deck("RU08_cyl_lattice_changed_after", "# region cylinder defined in lattice units of lattice sc 0.5; a later lattice sc 2 does not move it\n"
     + fbase("region cyl cylinder z 0.04 0.04 0.038 0 0.2 side in\nlattice sc 2\nfix cw all wall/gran/region granular " + HMW + " region cyl", lat="lattice sc 0.5\n"), g=1)
hy("MX01_mixed_damping_models", "pair_coeff 1 1 hooke mass_velocity, 2 2 hooke tsuji 0.5: 1 2 mixed? (engine decides)",
   "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 hooke 2000 0.5 damping tsuji " + TL + "\n")
hy("MX02_mixed_normal_models", "pair_coeff 1 1 hooke, 2 2 hertz/material: 1 2 mixed? (engine decides)",
   "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HMW + "\n")
hy("MX03_mixed_hertzmat_poisson", "pair_coeff 1 1 hertz/material E 1e7 nu 0.3, 2 2 E 1e7 nu 0.45: 1 2 mixed",
   "pair_style granular\npair_coeff 1 1 " + HMW + "\npair_coeff 2 2 hertz/material 1e7 1.4e7 0.45 damping viscoelastic " + TL + "\n")
hy("MX04_mixed_coeff_rest", "pair_coeff 1 1 hooke coeff_restitution 0.3, 2 2 hooke coeff_restitution 0.8: 1 2 mixed (geometric 0.49?)",
   "pair_style granular\npair_coeff 1 1 hooke 2000 0.3 damping coeff_restitution " + TL + "\npair_coeff 2 2 hooke 8000 0.8 damping coeff_restitution " + TL + "\n")


# ================================================================ fifth set: more set-up errors of the last run
rr("N09_set_z_outside_last_run", "set atom 2 z 0.5 (outside the f face at 0.1) before the last run: lost at its set-up", "set atom 2 z 0.5\nrun 100\n")
rr("N10_set_z_outside_then_run", "N09 with another run after", "set atom 2 z 0.5\nrun 100\n" + K5 + "run 100\n")
rr("N11_set_z_outside_lost_ignore", "N09 with thermo_modify lost ignore (LAMMPS drops it and runs)", "thermo_modify lost ignore\nset atom 2 z 0.5\nrun 100\n")
rr("N12_big_default_sphere_lost_ignore", "S02 with thermo_modify lost ignore", "thermo_modify lost ignore\ncreate_atoms 2 single 0.03 0.03 0.05\nrun 10\n")
rr("N13_restart_cycle_comm_only", "R03 with comm_modify vel yes after read_restart (no neighbor command)", "run 100\nwrite_restart a.restart\nclear\nread_restart a.restart\ncomm_modify vel yes\n" + K5 + "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\nrun 100\n")
rr("N14_restart_cycle_neighbor_only", "R03 with neighbor 0.001 bin after read_restart (no comm_modify)", "run 100\nwrite_restart a.restart\nclear\nread_restart a.restart\nneighbor 0.001 bin\n" + K5 + "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\nrun 100\n")

rr("N15_set_big_sphere_lost_ignore", "lost ignore; set atom 2 diameter 0.5 (a 0.5 m sphere in a 4 cm periodic box); run", "thermo_modify lost ignore\nset atom 2 diameter 0.5\nrun 10\n")
rr("N16_set_big_sphere", "set atom 2 diameter 0.5; run (engine decides)", "set atom 2 diameter 0.5\nrun 10\n")
rr("N17_big_sphere_fff_lost_ignore", "box f f f, lost ignore, set atom 2 diameter 0.5; run", "change_box all boundary f f f\nthermo_modify lost ignore\nset atom 2 diameter 0.5\nrun 10\n")
rr("N18_big_sphere_lost_ignore_then_run", "N15 then kn 5000 and another run", "thermo_modify lost ignore\nset atom 2 diameter 0.5\nrun 10\n" + K5 + "run 10\n")

rr("N19_deposit_default_size_lost_ignore", "lost ignore; fix deposit of type 2 without a size (LAMMPS default diameter 1 m) across two runs; kn 5000 last", "thermo_modify lost ignore\n" + INS + "fix dp all deposit 2 2 100 12345 region ins near 0.007 vz -0.1 -0.1\nrun 300\n" + K5 + "run 100\n")
rr("N20_random_default_size_lost_ignore", "lost ignore; create_atoms 2 random 2 with no set (1 m default); one run", "thermo_modify lost ignore\nregion top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\ncreate_atoms 2 random 2 777 top\nrun 10\n")


# ================================================================ sixth set: cutoffs smaller than the contact, hybrid one sub-style with excludes
hy("CU01_pair_cutoff_small_12", "pair_coeff 1 2 hooke ... cutoff 0.001 (below the 5 mm contact distance): engine decides whether 1 2 meet",
   "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 1 2 " + HK + " cutoff 0.001\n")
hy("CU02_global_cutoff_small", "pair_style granular 0.001 (a global cutoff below every contact distance)", "pair_style granular 0.001\npair_coeff * * " + HK + "\n")
hy("CU03_pair_cutoff_large", "pair_coeff * * ... cutoff 0.02 (above the contact)", "pair_style granular\npair_coeff * * " + HK + " cutoff 0.02\n")
hy("CU04_cutoff_small_in_if_include", "cutoff 0.001 for 2 2 from an if's include", "pair_style granular\npair_coeff * * " + HK + "\nif 1 then \"include c.in\"\n", data={"c.in": "pair_coeff 2 2 " + HK + " cutoff 0.001\n"})
hy("CU05_gran_hooke_history_no_cutoff_kw", "gran/hooke/history with limit_damping (control for CU)", "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.5 1 limit_damping\npair_coeff * *\n")
hy("CU06_hybrid_one_exclude_11", "hybrid granular (one sub-style) + neigh_modify exclude type 1 1", HN + "neigh_modify exclude type 1 1\n")
hy("CU07_hybrid_two_granular_none_labels_loop", "hybrid granular granular; labels; none on small big set in pass 2 of a loop", "labelmap atom 1 small 2 big\npair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff 2 2 granular 2 " + hk(5000) + "\n",
   atoms=TWO + "variable i loop 2\nlabel l\nif \"$i == 2\" then \"pair_coeff small big none\"\nrun 20\nnext i\njump SELF l\n")

rr("CU08_neigh_include_group", "atom_modify first g1? no: neigh_modify include g1 (group of type 1): pairs only with atoms of g1 (engine decides 1 2, 2 2)",
   "group g1 type 1\nneigh_modify include g1\nrun 100\n")
deck("CU09_neigh_include_first", "# atom_modify first g1 before the box, neigh_modify include g1 (the documented way)\n" + BASE().replace("boundary p p f\n", "boundary p p f\natom_modify first g1\n") + TWO + "group g1 type 1\nneigh_modify include g1\nrun 100\n", g=1)


# ================================================================ seventh set: neighbour settings (pairs found late)
rr("NB01_skin_zero_every20_nocheck", "neighbor 0.0 bin; neigh_modify every 20 delay 0 check no: pairs found up to 20 steps late", "neighbor 0.0 bin\nneigh_modify every 20 delay 0 check no\nrun 100\n")
rr("NB02_skin_small_check_yes", "neighbor 0.0001 bin; neigh_modify every 1 delay 0 check yes (fine)", "neighbor 0.0001 bin\nneigh_modify every 1 delay 0 check yes\nrun 100\n")
rr("NB03_every50_nocheck_default_skin", "neigh_modify every 50 delay 0 check no (skin 0.001 default)", "neigh_modify every 50 delay 0 check no\nrun 100\n")
rr("NB04_once", "neigh_modify once yes (lists built once per run)", "neigh_modify once yes\nrun 100\n")
rr("NB05_skin_zero_in_if_include", "neighbor 0.0 bin + every 20 check no from an if's include", "if 1 then \"include nb.in\"\nrun 100\n", data={"nb.in": "neighbor 0.0 bin\nneigh_modify every 20 delay 0 check no\n"})


# ================================================================ eighth set: research-like decks mixing the classes
TSU = "hertz/material 1e8 0.6 0.3 damping tsuji tangential mindlin NULL 1.0 0.5"
CR = "hertz/material 1e8 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.5 limit_damping"
deck("RL01_pour_two_types_cylinder_three_runs", "# pour of 2 types (diam poly) into a cylinder region wall (tsuji), floor coeff_restitution, 3 runs: pour, settle, wiggle floor\n"
     "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.12 units box\ncreate_box 2 box\nneighbor 0.001 bin\nneigh_modify delay 0\n"
     "pair_style granular\npair_coeff * * " + TSU + "\npair_coeff 2 2 " + TSU.replace("0.6 0.3", "0.8 0.3") + "\n"
     "region cyl cylinder z 0.02 0.02 0.018 0 0.12 side in open 1 open 2 units box\nfix cw all wall/gran/region granular " + TSU + " region cyl\n"
     "fix floor all wall/gran granular " + CR + " zplane 0 NULL\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 2e-6\n"
     "region ins cylinder z 0.02 0.02 0.014 0.06 0.11 units box\nfix p1 all pour 20 1 4767 region ins diam poly 2 0.002 0.5 0.003 0.5 dens 2500 2500\nfix p2 all pour 10 2 4768 region ins diam one 0.004 dens 7800 7800\n"
     "run 20000\nunfix p1\nunfix p2\nrun 10000\nunfix floor\nfix floor all wall/gran granular " + CR + " zplane 0 NULL wiggle z 0.0005 0.01\nrun 5000\n", g="0.3 1 3")
deck("RL02_read_data_labels_hybrid_loop_index", "# read_data with type labels (glass, steel), hybrid granular granular, a loop over kn by an index variable, region block wall\n"
     "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style hybrid granular granular\n"
     "variable kn index 3000 6000\nlabel l\npair_coeff * * granular 1 hooke ${kn} 3000 " + K + "\npair_coeff steel steel granular 2 hooke 9000 3000 " + K + "\n"
     "region con block 0 0.04 0 0.04 0 0.1 side in units box\nfix cw all wall/gran/region granular " + HK + " region con\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-5\nrun 200\nunfix cw\nnext kn\njump SELF l\n",
     g=1, data={"d.data": "# spheres\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 glass\n2 steel\n\nAtoms # sphere\n\n1 glass 0.004 2500 0.01 0.02 0.02\n2 steel 0.006 7800 0.03 0.02 0.02\n3 glass 0.005 2500 0.02 0.03 0.03\n"})
deck("RL03_drum_rotating_cylinder", "# rotating drum: region cylinder y rotating (variable defined first), hertz/material tsuji wall, box f f f\n"
     "units si\natom_style sphere 1\nboundary f f f\ncomm_modify vel yes\nregion box block 0 0.06 0 0.02 0 0.06 units box\ncreate_box 2 box\n"
     "pair_style granular\npair_coeff * * " + TSU + "\nvariable th equal 2*PI*0.5*time\nregion drum cylinder y 0.03 0.03 0.028 0 0.02 side in rotate v_th 0.03 0 0.03 0 1 0 units box\n"
     "fix dw all wall/gran/region granular " + TSU + " region drum\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 2e-6\n"
     "region fill block 0.015 0.045 0.002 0.018 0.01 0.03 units box\ncreate_atoms 1 random 20 4242 fill overlap 0.005\ncreate_atoms 2 random 10 4343 fill overlap 0.005\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.003 density 7800\nrun 2000\n", g=1)
deck("RL04_type_fraction_then_sizes", "# lattice of type 1, set type 1 type/fraction 2 0.5 (half become type 2), then sizes per type, chute gravity, yplane wall\n"
     "units si\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.05 0 0.1 0 0.01 units box\ncreate_box 2 box\nlattice sc 0.006\nregion lay block 0.003 0.047 0.01 0.05 0.003 0.007 units box\ncreate_atoms 1 region lay\n"
     "set type 1 type/fraction 2 0.5 12393\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.005 density 2500\n"
     "pair_style granular\npair_coeff * * " + CR + "\nfix grav all gravity 9.81 chute 20\nfix wall all wall/gran granular " + CR + " yplane 0 NULL\nfix integ all nve/sphere\ntimestep 2e-6\nrun 1000\n", g=1)
deck("RL05_cgs_realistic_region_walls", "# units cgs: hertz/material E 1e9 dyne/cm2 tsuji, gravity 981, region cylinder wall, pour diam range 0.2 0.4 cm; --g '30 100 300'\n"
     "units cgs\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 4 0 4 0 12 units box\ncreate_box 1 box\nneighbor 0.05 bin\n"
     "pair_style granular\npair_coeff * * hertz/material 1e9 0.6 0.3 damping tsuji tangential mindlin NULL 1.0 0.5\nregion cyl cylinder z 2 2 1.9 0 12 side in open 1 open 2 units box\n"
     "fix cw all wall/gran/region granular hertz/material 1e9 0.6 0.3 damping tsuji tangential mindlin NULL 1.0 0.5 region cyl\nfix floor all wall/gran granular hertz/material 1e9 0.6 0.3 damping tsuji tangential mindlin NULL 1.0 0.5 zplane 0 NULL\n"
     "fix grav all gravity 981 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 2e-6\nregion ins cylinder z 2 2 1.5 6 11 units box\nfix p all pour 30 1 4767 region ins diam range 0.2 0.4 dens 2.5 2.5\nrun 5000\n", g="30 100 300")
deck("RL06_write_data_read_pour_more", "# a settle run, write_data, clear, read_data (pair coeffs from the file? no: nocoeff) + a new pour of type 2, kn 5000\n"
     + BASE() + TWO + "run 100\nwrite_data s.data nocoeff\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data s.data\npair_style granular\n" + K5 + GRAV + FLOOR + TAIL
     + INS + "fix p all pour 3 2 4767 region ins diam one 0.003 dens 7800 7800\nrun 2000\n", g=1)
L("RL07_liggghts_three_materials_mesh", "# LIGGGHTS: 3 types, types 1 2 particles (insert/pack), type 3 mesh floor and primitive cylinder, e matrix via variables, settle then mesh moves\n"
  + m.lhead() + m.MAT3 + "variable e11 equal 0.55\nvariable e12 equal 0.45\nvariable e22 equal 0.35\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e11} ${e12} 0.7 ${e12} ${e22} 0.6 0.7 0.6 0.9\n"
  + m.HERTZ + "fix cad all mesh/surface file floor.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\nfix wc all wall/gran model hertz tangential history primitive type 3 zcylinder 0.045 0 0\n"
  + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\nfix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 7800 radius constant 0.003\n"
  + "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n" + m.LRUN
  + "fix ins all insert/pack seed 32452867 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 20 region bc\nrun 2000\nfix mv all move/mesh mesh cad linear 0. 0. 0.01\nrun 1000\n",
  g="0.5 1 2", data={"floor.stl": STL})
deck("RL08_labels_three_types_tsuji_mixing_walls", "# labels a b c: per-pair tsuji e (a a 0.9, b b 0.5, c c 0.3) and explicit a c 0.6; b c mixed by LAMMPS; zplane wall with coeff_restitution\n"
     + head(3) + "labelmap atom 1 a 2 b 3 c\npair_style granular\npair_coeff a a " + TSU.replace("0.6 0.3", "0.9 0.3") + "\npair_coeff b b " + TSU.replace("0.6 0.3", "0.5 0.3") + "\npair_coeff c c " + TSU.replace("0.6 0.3", "0.3 0.3") + "\npair_coeff a b " + TSU.replace("0.6 0.3", "0.7 0.3") + "\npair_coeff a c " + TSU + "\n"
     + GRAV + "fix floor all wall/gran granular " + CR + " zplane 0 NULL\n" + TAIL + THREE + "run 100\n", g="0.3 1 3")


# ================================================================ ninth set: a pour after clear (after RL06)
POUR7800 = INS + "fix p all pour 3 2 4767 region ins diam one 0.003 dens 7800 7800\n"
REBUILD = lambda model=HK: "clear\n" + BASE(model) + TWO
rr("CL01_clear_rebuild_pour_last_run", "run; clear; the deck rebuilt by commands (kn 2000); fix pour of 3 type 2 spheres 3 mm 7800 in the last run", "run 100\n" + REBUILD() + POUR7800 + "run 2000\n")
rr("CL02_clear_read_data_pour_last_run", "run; write_data; clear; read_data; fix pour type 2 3 mm 7800 in the last run (RL06 without the kn change)", "run 100\nwrite_data s.data nocoeff\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data s.data\npair_style granular\npair_coeff * * " + HK + "\n" + GRAV + FLOOR + TAIL + POUR7800 + "run 2000\n")
rr("CL03_clear_pour_then_run", "CL01 with one more run after the pour run (made for real)", "run 100\n" + REBUILD() + POUR7800 + "run 2000\nrun 100\n")
rr("CL04_clear_pour_type1_range", "run; clear; rebuild; fix pour of type 1 diam range 0.002 0.006 dens 1000 7800 in the last run", "run 100\n" + REBUILD() + INS + "fix p all pour 4 1 4767 region ins diam range 0.002 0.006 dens 1000 7800\nrun 2000\n")
rr("CL05_clear_in_if_include_pour", "an if's include clears and rebuilds; the deck then pours type 2 (3 mm 7800) in its last run", "run 100\nif 1 then \"include new.in\"\n" + POUR7800 + "run 2000\n", data={"new.in": REBUILD()})
rr("CL06_no_clear_pour_control", "control: the same pour in the last run without clear", "run 100\n" + POUR7800 + "run 2000\n")
rr("CL07_clear_pour_in_first_sim_only", "a pour in the first simulation, clear, rebuild without a pour: the pour must not leak into the second", POUR7800 + "run 2000\n" + REBUILD() + "run 100\n")

LCL = lambda: LT2((0.6, 0.5, 0.5)) + m.HERTZ + W2 + A1 + m.LRUN
L("CL08_liggghts_clear_insert_type2", "# LIGGGHTS: run; clear; rebuild (3 types: e 0.6 0.5 0.7 / 0.5 0.4 0.45 ...); insert/pack of type 2 spheres in the last run\n" + LCL() + "run 100\nclear\n"
  + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  + "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\nfix pdd all particledistribution/discrete 32452843 1 pts2 1.0\nregion bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n"
  + m.LRUN + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 5 region bc\nrun 1000\n", g=1)
L("CL09_liggghts_insert_type2_no_clear", "# control of CL08 without clear\n" + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  + "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\nfix pdd all particledistribution/discrete 32452843 1 pts2 1.0\nregion bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n"
  + m.LRUN + "run 100\nfix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 5 region bc\nrun 1000\n", g=1)
rr("CL10_clear_deposit_last_run", "run; clear; rebuild; fix deposit of type 2 (diameter set by a set in the first run? no: default) then set type 2 diameter after a short run", "run 100\n" + REBUILD() + INS + "fix dp all deposit 2 2 50 777 region ins near 0.007 vz -0.1 -0.1\nrun 120\nset type 2 diameter 0.003 density 7800\nrun 500\n")
rr("CL11_clear_create_random_last_run", "run; clear; rebuild; create_atoms 2 random 3 (3 mm 7800 by set) before the last run (the pass makes them)", "run 100\n" + REBUILD() + "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\ncreate_atoms 2 random 3 999 top overlap 0.004\nset type 2 diameter 0.003 density 7800\nrun 100\n")

MOL2 = m.MOL(2, 0.003, m.mass(0.003, 7800))
rr("CL12_clear_deposit_mol_last_run", "run; clear; rebuild; molecule (type 2, 3 mm, 7800); fix deposit mol in the last run", "run 100\n" + REBUILD() + "molecule m2 m2.mol\n" + INS + "fix dp all deposit 3 0 100 777 region ins near 0.007 mol m2 vz -0.5 -0.5\nrun 400\n", data={"m2.mol": MOL2})
rr("CL13_clear_region_wall_second", "run; clear; rebuild; a region cylinder wall kn 8000 in the second simulation", "run 100\n" + REBUILD() + "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in open 1 open 2 units box\nfix cw all wall/gran/region granular " + hk(8000) + " region cyl\nrun 100\n")
rr("CL14_clear_labels_second", "labelmap a b in sim 1 (pair a b kn 8000); clear; sim 2 with labelmap b a (swapped) and pair b b kn 5000", "labelmap atom 1 a 2 b\npair_coeff a b " + hk(8000) + "\nrun 100\n" + REBUILD() + "labelmap atom 1 b 2 a\npair_coeff b b " + hk(5000) + "\nrun 100\n")
rr("CL15_clear_exclude_first_only", "neigh_modify exclude type 1 2 in sim 1; clear; sim 2 without it (1 2 meets)", "neigh_modify exclude type 1 2\nrun 100\n" + REBUILD() + "run 100\n")
rr("CL16_clear_viscous_first_only", "fix viscous in sim 1; clear; sim 2 without it", "fix v all viscous 0.001\nrun 100\n" + REBUILD() + "run 100\n")
rr("CL17_clear_timestep_default", "timestep 1e-5 in sim 1; clear; sim 2 without a timestep line (LAMMPS' si default)", "run 100\n" + REBUILD().replace("timestep 1e-5\n", "") + "run 100\n")
rr("CL18_clear_units_default_lj", "sim 1 si; clear; sim 2 without a units line (lj by default) and lj-sized numbers", "run 100\nclear\n" + m.head(2, box="0 10 0 10 0 20").replace("units si\n", "") + m.G1("hooke 2000 3 " + K) + "fix floor all wall/gran granular hooke 2000 3 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\ncreate_atoms 1 single 5 5 2\ncreate_atoms 2 single 2 2 2\nset type 1 diameter 1 density 1\nset type 2 diameter 1.5 density 1\nrun 100\n")
rr("CL19_clear_pour_type2_in_loop_pass", "a loop of 2 passes, each: clear, rebuild, pour of type 2 (3 mm 7800), run", "variable i loop 2\nlabel l\n" + REBUILD() + POUR7800 + "run 1500\nnext i\njump SELF l\n")

LJS = lambda ts: (m.head(2, box="0 10 0 10 0 20", units="lj") + m.G1("hooke 2000 3 " + K) + "fix floor all wall/gran granular hooke 2000 3 " + K + " zplane 0 NULL\nfix integ all nve/sphere\n" + ts
                  + "create_atoms 1 single 5 5 2\ncreate_atoms 2 single 2 2 2\nset type 1 diameter 1 density 1\nset type 2 diameter 1.5 density 1\n")
deck("CL20_clear_lj_timestep_default_coarse", "# units lj, timestep 1e-4, run; clear; the same deck without its timestep line: LAMMPS' lj default 0.005 (about 7 steps per contact)\n" + LJS("timestep 1e-4\n") + "run 100\nclear\n" + LJS("") + "run 100\n", g=1)
deck("CL21_lj_no_timestep_control", "# control: units lj without a timestep line at all (default 0.005)\n" + LJS("") + "run 100\n", g=1)


# ================================================================ tenth set: LIGGGHTS property fixes given twice
E2id = lambda fid, a, b, c: f"fix {fid} all property/global coefficientRestitution peratomtypepair 2 {a} {b} {b} {c}\n"
L("LQ01_two_e_fixes_ids", "# LIGGGHTS: coefficientRestitution by fix m3 (0.6) then by fix m3b (0.3): which does LIGGGHTS use?\n" + LH2() + E2id("m3", 0.6, 0.6, 0.6) + E2id("m3b", 0.3, 0.3, 0.3) + m.HERTZ + W2 + A1 + LR, g=1)
L("LQ02_two_e_fixes_ids_reversed", "# LIGGGHTS: m3b (0.3) first, m3 (0.6) second\n" + LH2() + E2id("m3b", 0.3, 0.3, 0.3) + E2id("m3", 0.6, 0.6, 0.6) + m.HERTZ + W2 + A1 + LR, g=1)
L("LQ03_e_fix_unfixed_redefined_other_id", "# LIGGGHTS: m3 (0.6); run; unfix m3; fix m9 (0.3); run\n" + LH2() + E2id("m3", 0.6, 0.6, 0.6) + m.HERTZ + W2 + A1 + m.LRUN + "run 100\nunfix m3\n" + E2id("m9", 0.3, 0.3, 0.3) + "run 100\n", g=1)
L("LQ04_second_e_fix_after_run", "# LIGGGHTS: m3 (0.6); run; fix m3b (0.3) added (m3 kept); run\n" + LH2() + E2id("m3", 0.6, 0.6, 0.6) + m.HERTZ + W2 + A1 + m.LRUN + "run 100\n" + E2id("m3b", 0.3, 0.3, 0.3) + "run 100\n", g=1)
L("LQ05_two_youngs_hooke_stiffness", "# LIGGGHTS hooke/stiffness kn given twice by two fixes (k1 2000, k1b 8000): which kn?\n" + LH2() + "fix k1 all property/global kn peratomtypepair 2 2000 2000 2000 2000\nfix k1b all property/global kn peratomtypepair 2 8000 8000 8000 8000\nfix k2 all property/global kt peratomtypepair 2 2000 2000 2000 2000\n"
  + "fix k3 all property/global gamman peratomtypepair 2 10 10 10 10\nfix k4 all property/global gammat peratomtypepair 2 10 10 10 10\npair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
  + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0\n" + A1 + LR, g=1)

deck("CL22_clear_first_line_pour", "# clear as the deck's first line, then the base deck, a fix pour of type 2 (3 mm 7800) in its only run\nclear\n" + BASE() + TWO + POUR7800 + "run 2000\n", g=1)
deck("CL24_clear_top_pour_only", "# a pour-only deck that starts with clear (as generated scripts often do): hertz/material tsuji, 2 mm to 4 mm spheres\nclear\n"
     + head(1) + "pair_style granular\npair_coeff * * " + TSU + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + TSU + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 2e-6\n"
     + INS + "fix p all pour 20 1 4767 region ins diam range 0.002 0.004 dens 2500 2500\nrun 20000\n", g=1)

H10L = "thermo_modify lost ignore\ngroup t2 type 2\nvariable i loop 2\nlabel l\nif \"$i == 2\" then \"velocity t2 set 0 0 100\"\nrun 200\nnext i\njump SELF l\nif \"$(count(all)) < 2\" then \"" + K5.strip() + "\"\nrun 10\n"
deck("CL25_clear_first_H10", "# H10 (lost ignore; pass 2 of a loop throws type 2 out; an if on count(all) sets kn 5000) with clear on its first line\nclear\n" + BASE() + TWO + H10L, g=1)
deck("CL26_clear_first_H06", "# H06 (lost ignore; type 2 thrown out in run 1; kn 5000; run 2) with clear on its first line\nclear\n" + BASE() + TWO + "thermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 300\n" + K5 + "run 50\n", g=1)
deck("CL27_clear_first_loop_lost", "# clear first; a loop of 2 runs; pass 1 throws type 2 out (lost ignore); kn 5000 after the loop\nclear\n" + BASE() + TWO + "thermo_modify lost ignore\ngroup t2 type 2\nvariable i loop 2\nlabel l\nif \"$i == 1\" then \"velocity t2 set 0 0 100\"\nrun 200\nnext i\njump SELF l\n" + K5 + "run 10\n", g=1)

deck("CL28_clear_first_N19", "# N19 (lost ignore; fix deposit of 1 m default spheres across two runs: LAMMPS loses every atom) with clear on its first line\nclear\n" + BASE() + TWO + "thermo_modify lost ignore\n" + INS + "fix dp all deposit 2 2 100 12345 region ins near 0.007 vz -0.1 -0.1\nrun 300\n" + K5 + "run 100\n", g=1)


def copy_examples():
    m.copy_examples([("X01_lammps_pour_drum", "granular", "in.pour.drum"), ("X02_lammps_pour", "pour", "in.pour"),
                     ("X03_lammps_pour_2d", "pour", "in.pour.2d"),
                     ("X04_lammps_pour_2d_molecule", "pour", "in.pour.2d.molecule"),
                     ("X05_lammps_pour_flatwall", "granular", "in.pour.flatwall"),
                     ("X06_lammps_granregion_box", "granregion", "in.granregion.box"),
                     ("X07_lammps_granregion_funnel", "granregion", "in.granregion.funnel"),
                     ("X08_lammps_granregion_mixer", "granregion", "in.granregion.mixer"),
                     ("CL23_lammps_pour_example_clear_first", "pour", "in.pour")],
                    [("packing", "in.packing"), ("insert_stream", "in.insert_stream"), ("cohesion", "in.cohesion"),
                     ("contactModels", "in.newModels"), ("conveyor", "in.conveyor"), ("cohesion", "in.noCohesion"),
                     ("hysteresis", "in.noHysteresis"), ("movingMeshGran", "in.movingMeshGran"),
                     ("chute_wear", "in.chute_wear"), ("meshGran", "in.meshGran"), ("heatTransfer_1", "in.heatGran"),
                     ("heatTransfer_2", "in.heatGran"), ("hydrogel_multicontact", "in.hydrogel_default"),
                     ("hydrogel_multicontact", "in.hydrogel_multicontact"), ("mesh_tet", "in.mesh_tet"),
                     ("multisphere_stone_restitution", "in.multisphere"), ("superquadric", "in.particle_particle"),
                     ("sph_1", "in.sph_1")],
                    first={"CL23_lammps_pour_example_clear_first": "clear\n"})


if __name__ == "__main__":
    for n in (sys.argv[1:] or m.DECKS):
        m.write(n)
    if not sys.argv[1:]:
        copy_examples()
    print(len(m.DECKS), "decks")
