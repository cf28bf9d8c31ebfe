"""Field round 20: write the decks as decks/NAME/in.deck with G (the speeds), extra files and a LIGGGHTS marker.
Prefixes: x* number formats and substitution, p* pair_coeff ranges/labels/restyling, s* sizes and set order, t* time
step, i* LAMMPS pour/deposit, w* walls, m* damping, h* hybrid/omp/none/clear, L* LIGGGHTS. Each deck's first
comment says what it tries and what the engine does (PROBE lines print the engine's own values).
usage: python make_decks20.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import (ATOMS, BASE, E3, FLOOR, G1, GRAV, HERTZ, HK, HM, HOOKE, K, LB, LRUN, MAT3, RUN,  # noqa: E402
                            TAIL, TL, TWO, TWO4, WALL3, head, hk, lhead)  # the same lines as there

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
DECKS = {}


def deck(name, text, g="0.1 1", files=None, data=None, liggghts=False):
    DECKS[name] = (text, g, files or {}, data or {}, liggghts)


# ================================================================ x*: formats, substitution, if
deck("x01_format_0f_half_even", "# kn $(2500.5:%.0f): C printf rounds half to even -> 2500; gamma $(3001.5:%.0f) -> 3002\n"
     + head() + "pair_style granular\npair_coeff * * hooke $(2500.5:%.0f) $(3001.5:%.0f) " + K + "\nprint \"PROBE kn $(2500.5:%.0f) g $(3001.5:%.0f)\"\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x02_format_if_on_rounded", "# if \"$(v_x:%.0f) == 3\" with x = 2.5: printf gives 2 -> else branch (kn 2000); half-up rounding would take 9000\n"
     + head() + "variable x equal 2.5\nif \"$(v_x:%.0f) == 3\" then \"variable kn equal 9000\" else \"variable kn equal 2000\"\nprint \"PROBE kn ${kn}\"\n"
     + "pair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x03_format_1f_binary_half", "# nu $(0.35:%.1f): 0.35 is 0.34999.. in binary -> 0.3; E $(1.25e7:%.1e) -> 1.2e+07 (exact half, to even)\n"
     + head() + "pair_style granular\npair_coeff * * hertz/material $(1.25e7:%.1e) 1.4e7 $(0.35:%.1f) damping viscoelastic " + TL + "\nprint \"PROBE E $(1.25e7:%.1e) nu $(0.35:%.1f)\"\n" + GRAV + TAIL + TWO + "run 100\n")
deck("x04_if_string_vs_double", "# a = 0.1+0.2: ${a} substitutes %.15g -> 0.3, so if \"${a} == 0.3\" is true (kn 7000); if \"v_a == 0.3\" compares doubles, false (gamma 3000 stays)\n"
     + head() + "variable a equal 0.1+0.2\nvariable kn equal 2000\nvariable gn equal 3000\nif \"${a} == 0.3\" then \"variable kn equal 7000\"\nif \"v_a == 0.3\" then \"variable gn equal 100\"\n"
     + "print \"PROBE kn ${kn} gn ${gn}\"\npair_style granular\npair_coeff * * hooke ${kn} ${gn} " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x05_immediate_no_format_20g", "# $(0.1+0.2) without format is %.20g (0.30000000000000004441): if \"$(0.1+0.2) == 0.3\" false -> kn 2000\n"
     + head() + "variable kn equal 2000\nif \"$(0.1+0.2) == 0.3\" then \"variable kn equal 8000\"\nprint \"PROBE kn ${kn} imm $(0.1+0.2)\"\n"
     + "pair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x06_include_name_from_equal", "# n equal 4/2 substitutes as 2 (%.15g), so include in.${n} reads in.2 (kn 3000), not in.2.0 (kn 9000)\n"
     + head() + "variable n equal 4/2\ninclude in.${n}\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"in.2": "pair_style granular\npair_coeff * * " + hk(3000) + "\n", "in.2.0": "pair_style granular\npair_coeff * * " + hk(9000) + "\n"})
deck("x07_loop_jump_coeff_last", "# loop i 3 with run 0 each pass and pair_coeff kn 1000*i: the last stage kn 3000 then a real run\n"
     + BASE(HK) + TWO + f"variable i loop 3\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 {K}\nrun 0\nnext i\njump SELF lp\nrun 100\n", g=1)
deck("x08_loop_float_pad", "# loop with pad: i = 01..03; kn ${i}000 -> 3000 at the end (pad makes 03000)\n"
     + BASE(HK) + TWO + f"variable i loop 3 pad\nlabel lp\npair_coeff * * hooke ${{i}}000 3000 {K}\nnext i\njump SELF lp\nrun 100\n", g=1)
deck("x09_format_e_in_variable_string", "# a string variable holding $(v_E:%.3e) of E = 1.23456e7 -> 1.235e+07, used later as ${Es}\n"
     + head() + "variable E equal 1.23456e7\nvariable Es string $(v_E:%.3e)\nprint \"PROBE Es ${Es}\"\npair_style granular\npair_coeff * * hertz/material ${Es} 1.4e7 0.3 damping viscoelastic " + TL + "\n" + GRAV + TAIL + TWO + "run 100\n")
deck("x10_format_width_and_g", "# $(v_k:%10.4g) of 2345.678 -> '     2346' (width pads spaces), a word after splitting\n"
     + head() + "variable k equal 2345.678\npair_style granular\npair_coeff * * hooke $(v_k:%10.4g) 3000 " + K + "\nprint \"PROBE k $(v_k:%10.4g)\"\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x11_if_elif_chain_on_format", "# if/elif on $(v_r:%.2f) with r = 0.125 -> 0.12 (half-even of exact .125): elif branch kn 5000\n"
     + head() + "variable r equal 0.125\nif \"$(v_r:%.2f) == 0.13\" then \"variable kn equal 9000\" elif \"$(v_r:%.2f) == 0.12\" \"variable kn equal 5000\" else \"variable kn equal 1000\"\n"
     + "print \"PROBE kn ${kn}\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x12_large_int_15g", "# kn equal 123456789012345678 substitutes %.15g -> 1.23456789012346e+17; gamma tiny: eps ~1\n"
     + head() + "variable kn equal 2000*1.00000000000000001\nvariable gn equal 3000/3*3\nprint \"PROBE kn ${kn} gn ${gn}\"\npair_style granular\npair_coeff * * hooke ${kn} ${gn} " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x13_variable_restyled_equal_to_string", "# kn first equal 1000*3, then deleted and redefined as string 5000: pair_coeff uses 5000\n"
     + head() + "variable kn equal 1000*3\nvariable kn delete\nvariable kn string 5000\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x14_index_not_redefined", "# an index variable cannot be redefined: variable kn index 2000 then variable kn index 8000 keeps 2000\n"
     + head() + "variable kn index 2000\nvariable kn index 8000\nprint \"PROBE kn ${kn}\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x15_equal_redefined_lazy", "# kn equal v_a*1000 with a equal 2, then a redefined equal 6 (equal may be redefined): ${kn} -> 6000\n"
     + head() + "variable a equal 2\nvariable kn equal v_a*1000\nvariable a equal 6\nprint \"PROBE kn ${kn}\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x16_format_in_set_diameter", "# set diameter $(0.00449:%.3f) -> 0.004 (not 0.0045): the size the engine holds\n"
     + head() + GRAV + TAIL + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * diameter $(0.00449:%.3f)\nset type * density 2500\n"
     + G1(HK) + FLOOR + "run 100\n", g=1)
deck("x17_dollar_single_letter", "# $k single-letter substitution next to text: $k0 is ${k}0 (k=300 -> 3000)\n"
     + head() + "variable k equal 300\npair_style granular\npair_coeff * * hooke $k0 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x18_quote_triple", "# pair_coeff inside an if with triple quotes and a ${} evaluated at if time (kn 4000)\n"
     + head() + "variable kn equal 4000\npair_style granular\nif \"1 > 0\" then \"\"\"pair_coeff * * hooke ${kn} 3000 " + K + "\"\"\"\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x19_round_function", "# kn = round(2500.5) in a LAMMPS formula (rounds half away from zero: 2501) vs %.0f (2500)\n"
     + head() + "variable kn equal round(2500.5)\nprint \"PROBE kn ${kn}\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x20_label_skip_pair_coeff", "# jump SELF past a pair_coeff: the skipped kn 9000 line never runs (kn 2000)\n"
     + head() + "pair_style granular\npair_coeff * * " + HK + "\njump SELF after\npair_coeff * * " + hk(9000) + "\nlabel after\n" + GRAV + TAIL + TWO + "run 100\n", g=1)

# ================================================================ p*: pair_coeff ranges, labels, restyle
deck("p01_star2_then_11", "# pair_coeff * 2 (1-1? no: i 1..2, j max(1,i)..2: 1 1, 1 2, 2 2) kn 4000, then 1 1 kn 8000\n"
     + head() + "pair_style granular\npair_coeff * 2 " + hk(4000) + "\npair_coeff 1 1 " + hk(8000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p02_range_23_12_sets_22_only", "# pair_coeff 2*3 1*2 sets only 2 2 (j runs from max(jlo,i)): 1 2, 1 3, 2 3 keep the * * kn 2000\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 2*3 1*2 " + hk(9000) + "\n" + GRAV + TAIL + TWO
     + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2500\nrun 100\n", g=1)
deck("p03_labels_reversed", "# labelmap 1 glass 2 steel; pair_coeff steel glass (2 1 by labels) kn 6000: LAMMPS swaps to 1 2\n"
     + head() + "labelmap atom 1 glass 2 steel\npair_style granular\npair_coeff * * " + HK + "\npair_coeff steel glass " + hk(6000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p04_reversed_numeric", "# pair_coeff 2 1 (numeric, reversed) kn 6000: LAMMPS swaps to 1 2\n"
     + head() + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\npair_coeff 2 1 " + hk(6000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p05_range_star3_2star", "# three types: * * kn 2000, then *2 2* kn 5000 -> 1 2, 1 3, 2 2, 2 3 (not 1 1, 3 3)\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff *2 2* " + hk(5000) + "\n" + GRAV + TAIL + TWO
     + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2500\nrun 100\n", g=1)
deck("p06_restyle_granular_drops_coeffs", "# pair_style granular again after coeffs: LAMMPS keeps coefficients when the style is the same (no re-setting needed)\n"
     + head() + "pair_style granular\npair_coeff * * " + hk(4000) + "\npair_style granular\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p07_mixed_pair_from_two_types", "# only 1 1 and 2 2 (hooke 2000 and 8000): 1 2 mixed (geometric kn 4000; damping mixed)\n"
     + head() + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 hooke 8000 1000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p08_type_label_range_3types", "# type labels for three types and a numeric star range after: pair_coeff 2* 2* changes 2 2, 2 3, 3 3\n"
     + head(3) + "labelmap atom 1 a 2 b 3 c\npair_style granular\npair_coeff * * " + HK + "\npair_coeff 2* 2* " + hk(7000) + "\npair_coeff a c " + hk(500) + "\n" + GRAV + TAIL + TWO
     + "create_atoms c single 0.03 0.03 0.01\nset type c diameter 0.005 density 2500\nrun 100\n", g=1)
deck("p09_gran_hooke_history_restyle", "# pair_style gran/hooke/history then pair_style granular: the old style's settings are gone, granular coeffs used\n"
     + head() + "pair_style gran/hooke/history 9000 NULL 400 NULL 0.5 0\npair_coeff * *\npair_style granular\npair_coeff * * " + HK + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p10_pair_coeff_in_loop_types", "# pair_coeff $i $i in a loop i 1..2: kn 1000*i each, 1 2 mixed\n"
     + head() + "pair_style granular\nvariable i loop 2\nlabel lp\npair_coeff $i $i hooke $(1000*v_i) 3000 " + K + "\nnext i\njump SELF lp\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p11_star_star_after_specific", "# 1 2 kn 9000 then * * kn 2000: the later * * overwrites 1 2\n"
     + head() + "pair_style granular\npair_coeff 1 2 " + hk(9000) + "\npair_coeff * * " + HK + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p12_labels_in_set_and_create", "# labels in create_atoms and set type: set type steel diameter 0.006\n"
     + head() + "labelmap atom 1 glass 2 steel\npair_style granular\npair_coeff * * " + HK + "\n" + GRAV + TAIL
     + "create_atoms glass single 0.02 0.02 0.01\ncreate_atoms steel single 0.01 0.01 0.01\nset type glass diameter 0.004 density 2500\nset type steel diameter 0.006 density 7800\nrun 100\n", g=1)

# ================================================================ s*: sizes, set order
deck("s01_density_before_diameter", "# set density 2500 then set diameter 0.004: LAMMPS set diameter keeps the mass from diameter 1 (1309 kg)\n"
     + BASE(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * density 2500\nset type * diameter 0.004\nrun 100\n", g=1)
deck("s02_density_diameter_one_line", "# set type * density 2500 diameter 0.004 in one line (keywords in order: mass from d = 1)\n"
     + BASE(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * density 2500 diameter 0.004\nrun 100\n", g=1)
deck("s03_set_before_create", "# set before create_atoms sets nothing: the spheres keep d 1, density 1 (mass 0.5236)\n"
     + head(box="0 4 0 4 0 10") + G1(HK) + GRAV + FLOOR + TAIL + "set type * diameter 0.004\nset type * density 2500\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nrun 100\n", g=1)
deck("s04_set_group_subset_region", "# type 1: 4 spheres, a region sets two of them to 6 mm: two sizes in type 1\n"
     + BASE(HK) + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 1 single 0.015 0.005 0.01\ncreate_atoms 1 single 0.025 0.025 0.01\ncreate_atoms 1 single 0.035 0.025 0.01\n"
     + "create_atoms 2 single 0.02 0.035 0.01\nset type * diameter 0.004 density 2500\nregion hi block 0.02 0.04 INF INF INF INF units box\ngroup hi region hi\nset group hi diameter 0.006 density 2500\nrun 100\n", g=1)
deck("s05_set_atom_range", "# set atom 2*3 diameter 0.006: atoms 2 (type 2) and 3 (type 1) -> type 1 has 4 and 6 mm\n"
     + BASE(HK) + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 2 single 0.015 0.005 0.01\ncreate_atoms 1 single 0.025 0.025 0.01\nset type * diameter 0.004 density 2500\nset atom 2*3 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("s06_set_mass_then_diameter", "# set mass 1e-4 then set diameter 0.004: mass kept 1e-4\n"
     + BASE(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * mass 1e-4\nset type * diameter 0.004\nrun 100\n", g=1)
deck("s07_atom_variable_diameter", "# diameter from an atom-style variable by id: 4 mm for odd ids, 6 mm for even (type 1 has both)\n"
     + BASE(HK) + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 1 single 0.015 0.005 0.01\ncreate_atoms 2 single 0.025 0.025 0.01\n"
     + "variable dd atom 0.004+0.002*(id%2==0)\nset type * diameter v_dd\nset type * density 2500\nrun 100\n", g=1)
deck("s08_data_file_sizes", "# read_data with per-atom diameter and density: type 1 d 0.004/0.002 dens 2500/7800\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": "spheres\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.005 0.005 0.01\n2 1 0.002 7800 0.015 0.005 0.01\n3 2 0.006 2500 0.025 0.025 0.01\n"})
deck("s09_data_then_set_density_type", "# read_data sizes then set type 1 density 1000: masses rescale with each diameter\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\nset type 1 density 1000\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": "spheres\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.005 0.005 0.01\n2 1 0.002 7800 0.015 0.005 0.01\n3 2 0.006 2500 0.025 0.025 0.01\n"})
deck("s10_2d_disc_density", "# 2d: set density on discs gives mass pi r^2 rho (per unit thickness) in LAMMPS\n"
     + head(dim=2, bnd="p f p", box="0 0.04 0 0.1 -0.001 0.001") + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix e2 all enforce2d\n" + TAIL
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type * diameter 0.004 density 2500\nrun 100\n", g=1)
deck("s11_adapt_reset_no_scale_type2", "# fix adapt diameter v_d on type 2 only (group), reset no, ramps 4 -> 8 mm in run 1; run 2 at 8 mm\n"
     + BASE(HK) + TWO4 + "group t2 type 2\nvariable dd equal ramp(0.004,0.008)\nfix ad t2 adapt 1 atom diameter v_dd reset no\nrun 200\nunfix ad\nrun 100\n", g=1)
deck("s12_adapt_constant_reset_no", "# fix adapt diameter to a constant 5 mm (reset no) then unfix: 5 mm kept\n"
     + BASE(HK) + TWO4 + "variable dd equal 0.005\nfix ad all adapt 1 atom diameter v_dd reset no\nrun 100\nunfix ad\nrun 100\n", g=1)
deck("s13_set_diameter_zero", "# set diameter 0 for type 2 (point particles): no contacts for type 2 in LAMMPS? radius 0 -> no overlap ever\n"
     + BASE(HK) + TWO + "set type 2 diameter 0.0\nrun 100\n", g=1)
deck("s14_several_sizes_create_random", "# create_atoms random then set by fraction: type 1 has 4 and 5 mm\n"
     + BASE(HK) + "create_atoms 1 random 10 4711 NULL\nset type 1 diameter 0.004 density 2500\nset type 1 type/fraction 2 0.5 99\nset type 2 diameter 0.005 density 2500\nrun 0\n", g=1)
deck("s15_data_diameter_zero_point", "# read_data with a diameter 0 atom of type 2 (a point mass: LAMMPS takes density as mass): only 1 1 has spheres\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": "spheres\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.005 0.005 0.01\n2 1 0.004 2500 0.015 0.005 0.01\n3 2 0.0 0.01 0.025 0.025 0.01\n"})
deck("s16_set_density_area_2d_keyword", "# 2d: set density/disc 2500 (LAMMPS density/disc: mass pi r^2 rho) in a 2d box\n"
     + head(dim=2, bnd="p f p", box="0 0.04 0 0.1 -0.001 0.001") + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix e2 all enforce2d\n" + TAIL
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type * diameter 0.004\nset type * density/disc 2500\nrun 100\n", g=1)
deck("s17_3d_density_disc_keyword", "# 3d box with set density/disc: LAMMPS refuses density/disc in 3d? (engine says)\n"
     + BASE(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * diameter 0.004\nset type * density/disc 2500\nrun 100\n", g=1)
deck("s18_adapt_reset_yes_scale_off_run", "# fix adapt reset yes to 8 mm on a run then unfix: LAMMPS restores 4 mm (mass restored too) for the last run\n"
     + BASE(HK) + TWO4 + "variable dd equal 0.008\nfix ad all adapt 1 atom diameter v_dd reset yes\nrun 100\nunfix ad\nrun 100\n", g=1)
deck("s19_set_type_subset_to_type3", "# set group of two type-1 atoms to type 3 (three types): 1 3 and 3 3 pairs appear; 3 3 own coeffs\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 3 3 " + hk(9000) + "\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 1 single 0.015 0.005 0.01\ncreate_atoms 2 single 0.025 0.025 0.01\nset type * diameter 0.004 density 2500\ngroup g1 id 2\nset group g1 type 3\nrun 100\n", g=1)
deck("s20_mass_then_density", "# set type 1 mass 1e-3 then density 2500: density recomputes mass from the radius (8.4e-5)\n"
     + BASE(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type * diameter 0.004\nset type * mass 1e-3\nset type * density 2500\nrun 100\n", g=1)

# ================================================================ t*: time step
deck("t01_dt_reset_fix", "# fix dt/reset changes dt during the run (emax): the deck's timestep is not the one used\n"
     + BASE(HK) + TWO + "fix dtr all dt/reset 1 1e-7 1e-4 1e-6 units box\nrun 200\n", g=1)
deck("t02_timestep_between_runs_coeff_kept", "# dt 1e-5 run, then dt 2e-4 run (same contact): contact ~ few steps at the last dt\n"
     + BASE(HK) + TWO + "run 100\ntimestep 2e-4\nrun 100\n", g=1)
deck("t03_units_after_timestep", "# timestep 1e-5 then units cgs: units resets dt to cgs default 1e-8 s\n"
     + "timestep 1e-5\n" + head(units="cgs", box="0 4 0 4 0 10") + "pair_style granular\npair_coeff * * hooke 2e6 3000 " + K + "\nfix grav all gravity 981 vector 0 0 -1\nfix integ all nve/sphere\n"
     + "create_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type * diameter 0.4 density 2.5\nrun 100\n", g="10 100")
deck("t04_timestep_variable_equal", "# timestep v_dt with dt equal 2e-6*2: 4e-6\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/sphere\nvariable dt equal 2e-6*2\ntimestep ${dt}\n" + TWO + "run 100\n", g=1)
deck("t05_run_0_after_timestep_change", "# run 100 at 1e-5, timestep 1e-3 then run 0 only: no step is made at 1e-3 (run 0)\n"
     + BASE(HK) + TWO + "run 100\ntimestep 1e-3\nrun 0\n", g=1)
deck("t06_few_steps_per_contact", "# dt 2e-4 for a hooke contact of ~1e-3 s: ~5 steps per contact\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/sphere\ntimestep 2e-4\n" + TWO + "run 100\n", g=1)
deck("t07_dt_reset_then_unfix", "# fix dt/reset in run 1 then unfixed: run 2 starts at the dt dt/reset left (not the timestep typed)\n"
     + BASE(HK) + TWO + "velocity all set 0 0 -1\nfix dtr all dt/reset 1 1e-7 1e-4 2e-5 units box\nrun 200\nunfix dtr\nvariable dtn equal dt\nprint \"PROBE dt ${dtn}\"\nrun 100\n", g=1)
deck("t08_timestep_in_run_every", "# run 200 every 100 \"timestep 2e-6\": dt changes after the first chunk\n"
     + BASE(HK) + TWO + "run 200 every 100 \"timestep 2e-6\"\n", g=1)
deck("t09_units_lj_default_dt", "# units lj without timestep: dt 0.005 tau; granular hooke in lj units\n"
     + head(units="lj", box="0 40 0 40 0 100") + "pair_style granular\npair_coeff * * hooke 2000 50 " + K + "\nfix grav all gravity 1 vector 0 0 -1\nfix integ all nve/sphere\n"
     + "create_atoms 1 single 20 20 1\ncreate_atoms 2 single 10 10 1\nset type * diameter 1.0 density 1.0\nrun 100\n", g="0.1 1")
deck("t10_reset_timestep_time", "# reset_timestep 0 time 5.0 between runs; dt kept 1e-5\n"
     + BASE(HK) + TWO + "run 100\nreset_timestep 0 time 5.0\nrun 100\n", g=1)

# ================================================================ i*: pour / deposit
POURBOX = head(box="0 0.04 0 0.04 0 0.2") + G1(HK) + GRAV + FLOOR + TAIL + "region top block 0 0.04 0 0.04 0.1 0.2 units box\n"
deck("i01_pour_two_runs", "# fix pour 20 spheres d 3 mm dens 2500 across two runs of 1000 steps: all inserted by run 2\n"
     + POURBOX + "fix p all pour 20 1 4767 region top diam one 0.003 dens 2500 2500\nrun 1000\nrun 1000\n", g=1)
deck("i02_pour_run0_only", "# fix pour then run 0 only: LAMMPS inserts nothing (no step)\n"
     + POURBOX + "create_atoms 2 single 0.02 0.02 0.01\nset type 2 diameter 0.004 density 2500\nfix p all pour 20 1 4767 region top diam one 0.003 dens 2500 2500\nrun 0\n", g=1)
deck("i03_pour_then_delete_type", "# pour type 1 then delete_atoms region covering everything of type 1 after the run (region top: those still up)\n"
     + POURBOX + "create_atoms 2 single 0.02 0.02 0.01\nset type 2 diameter 0.004 density 2500\nfix p all pour 10 1 4767 region top diam one 0.003 dens 2500 2500\nrun 300\nunfix p\ngroup g1 type 1\ndelete_atoms group g1\nrun 100\n", g=1)
deck("i04_deposit_near_attempt", "# fix deposit type 2 every 100 steps near 0.005 attempt 5, 5 atoms, run 1000\n"
     + POURBOX + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nfix dp all deposit 5 2 100 4711 region top near 0.005 attempt 5 vz -0.5 -0.5\nrun 1000\n", g=1)
deck("i05_deposit_default_then_set", "# deposit type 2 (default d 1, density 1) then after run set type 2 diameter/density (LAMMPS has the atoms: set applies)\n"
     + POURBOX + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nfix dp all deposit 3 2 100 4711 region top near 0.005 vz -0.5 -0.5\nrun 400\nset type 2 diameter 0.005 density 2500\nrun 100\n", g=1)
deck("i06_pour_poly_three", "# pour diam poly 3 2 mm 0.3 3 mm 0.5 5 mm 0.2: three sizes in type 1\n"
     + POURBOX + "fix p all pour 30 1 4767 region top diam poly 3 0.002 0.3 0.003 0.5 0.005 0.2 dens 2500 2500\nrun 1000\n", g=1)
deck("i07_pour_range_dens_range", "# pour diam range 2-4 mm dens range 1000-3000\n"
     + POURBOX + "fix p all pour 30 1 4767 region top diam range 0.002 0.004 dens 1000 3000\nrun 1000\n", g=1)
deck("i08_pour_unfixed_after_run_then_run", "# pour in run 1 (inserts), unfix, run 2: the poured spheres stay\n"
     + POURBOX + "fix p all pour 10 1 4767 region top diam one 0.003 dens 2500 2500\nrun 300\nunfix p\nrun 100\n", g=1)
deck("i09_pour_type2_id_reused", "# fix p pour type 1, unfix, then fix p (same ID) pour type 2 with 5 mm in run 2\n"
     + POURBOX + "fix p all pour 5 1 4767 region top diam one 0.003 dens 2500 2500\nrun 300\nunfix p\nfix p all pour 5 2 4768 region top diam one 0.005 dens 2500 2500\nrun 300\n", g=1)
deck("i10_pour_run_upto", "# pour then run 500 upto after a run 200: one real run of 300 steps\n"
     + POURBOX + "create_atoms 2 single 0.02 0.02 0.01\nset type 2 diameter 0.004 density 2500\nrun 200\nfix p all pour 5 1 4767 region top diam one 0.003 dens 2500 2500\nrun 500 upto\n", g=1)
deck("i11_deposit_mol_template", "# deposit a two-sphere molecule template (type 1 and 2 sizes in the file) with rigid/small\n"
     + "units si\natom_style hybrid sphere molecular\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.2 units box\ncreate_box 2 box bond/types 0 extra/special/per/atom 2\n"
     + "molecule dimer dimer.mol\n" + G1(HK) + GRAV + FLOOR + "timestep 1e-5\nregion top block 0.01 0.03 0.01 0.03 0.1 0.18 units box\n"
     + "fix dp all deposit 3 0 200 4711 region top mol dimer near 0.01 vz -0.5 -0.5 rigid rb\nfix rb all rigid/small molecule mol dimer\nrun 600\n", g=1,
     data={"dimer.mol": "dimer\n\n2 atoms\n\nCoords\n\n1 -0.0025 0 0\n2 0.0025 0 0\n\nTypes\n\n1 1\n2 2\n\nDiameters\n\n1 0.004\n2 0.006\n\nMasses\n\n1 8.37758e-5\n2 2.82743e-4\n"})
deck("i12_pour_then_set_density_type", "# set type 1 density 7800 after a pour run (the poured spheres change mass): left class in round 19?\n"
     + POURBOX + "fix p all pour 10 1 4767 region top diam one 0.003 dens 2500 2500\nrun 300\nset type 1 density 7800\nrun 100\n", g=1)
deck("i13_pour_in_loop_runs", "# a loop of three runs of 200 with fix pour on: insertion spread across them\n"
     + POURBOX + "fix p all pour 10 1 4767 region top diam one 0.003 dens 2500 2500\nvariable i loop 3\nlabel lp\nrun 200\nnext i\njump SELF lp\n", g=1)
deck("i14_deposit_global_attempt_fail", "# deposit with near larger than the region: fails to insert; LAMMPS warns, the run goes on\n"
     + POURBOX + "create_atoms 2 single 0.02 0.02 0.01\nset type 2 diameter 0.004 density 2500\nfix dp all deposit 2 1 100 4711 region top near 0.5 attempt 2 vz -0.5 -0.5\nrun 300\n", g=1)
deck("i15_pour_id_max_then_create", "# pour then create_atoms type 2 after the run\n"
     + POURBOX + "fix p all pour 5 1 4767 region top diam one 0.003 dens 2500 2500\nrun 300\nunfix p\ncreate_atoms 2 single 0.02 0.02 0.15\nset type 2 diameter 0.006 density 7800\nrun 100\n", g=1)

# ================================================================ w*: walls
deck("w01_region_cone_wall", "# wall/gran/region on a cone region (z axis) hooke 5000\n"
     + BASE(HK) + "region cn cone z 0.02 0.02 0.005 0.02 0 0.1 units box\nfix cw all wall/gran/region granular " + hk(5000) + " region cn\n" + TWO + "run 100\n", g=1)
deck("w02_region_cylinder_wall", "# wall/gran/region on a z cylinder: hertz/material\n"
     + BASE(HK) + "region cy cylinder z 0.02 0.02 0.019 0 0.1 units box\nfix cw all wall/gran/region granular " + HM + " region cy\n" + TWO + "run 100\n")
deck("w03_region_sphere_wall", "# wall/gran/region on a sphere region (left class: not audited?)\n"
     + BASE(HK) + "region sp sphere 0.02 0.02 0.05 0.05 units box\nfix sw all wall/gran/region granular " + hk(6000) + " region sp\n" + TWO + "run 100\n", g=1)
deck("w04_moving_zplane_wiggle", "# wall/gran zplane wiggle z: a moving wall changes the impact speed; named?\n"
     + head() + G1(HK) + GRAV + f"fix floor all wall/gran granular {HK} zplane 0 NULL wiggle z 0.001 0.01\n" + TAIL + TWO + "run 100\n", g=1)
deck("w05_wall_type_only_types", "# wall on group of type 2 only: type 1 never meets the floor\n"
     + head() + G1(HK) + GRAV + "group t2 type 2\n" + TAIL + TWO + f"group t2 type 2\nfix floor t2 wall/gran granular {hk(7000)} zplane 0 NULL\nrun 100\n", g=1)
deck("w06_region_block_moving", "# wall/gran/region on a block region moving with a variable (move v_z): a moving floor\n"
     + BASE(HK) + "variable zz equal 0.001*sin(100*time)\nregion bl block INF INF INF INF 0 0.1 move NULL NULL v_zz units box\nfix rw all wall/gran/region granular " + hk(5000) + " region bl\n" + TWO + "run 100\n", g=1)
deck("w07_wall_limit_damping_only", "# floor with limit_damping, pair without: the wall ends by force rule\n"
     + head() + G1(f"hooke 2000 0.5 damping velocity {TL}") + GRAV + f"fix floor all wall/gran granular hooke 2000 0.5 damping velocity {TL} limit_damping zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g=1)
deck("w08_wall_two_planes_same_fix", "# zplane 0 0.1 (two planes in one fix) with hertz\n"
     + head() + G1(HK) + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 0.1\n" + TAIL + TWO + "run 100\n")
deck("w09_region_prism_wall", "# wall/gran/region on a prism region (left class)\n"
     + BASE(HK) + "region pr prism 0 0.04 0 0.04 0 0.1 0.01 0 0 units box\nfix pw all wall/gran/region granular " + hk(5000) + " region pr\n" + TWO + "run 100\n", g=1)
deck("w10_wall_xcylinder_hooke_history", "# old-style wall/gran hooke/history on a zcylinder with pair granular\n"
     + head() + G1(HK) + GRAV + "fix cyl all wall/gran hooke/history 4000 NULL 300 NULL 0.5 0 zcylinder 0.019\n" + TAIL
     + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
deck("w11_wall_gran_region_unfix_refix", "# region wall on a block, unfixed after run 1, refixed on a cylinder\n"
     + BASE(HK) + "region bl block INF INF INF INF 0 0.1 units box\nfix rw all wall/gran/region granular " + hk(5000) + " region bl\n" + TWO + "run 100\nunfix rw\n"
     + "region cy cylinder z 0.02 0.02 0.019 0 0.1 units box\nfix rw all wall/gran/region granular " + hk(9000) + " region cy\nrun 100\n", g=1)
deck("w12_wall_gran_temperature_keyword", "# wall/gran granular with contacts keyword and temperature? a plain granular wall with rolling and twisting\n"
     + head() + G1(HK) + GRAV + f"fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3 rolling sds 100 1 0.1 twisting marshall zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g=1)

# ================================================================ m*: damping and integrators
deck("m01_viscous_fix", "# fix viscous 0.001 on all: a drag during contacts; named?\n"
     + BASE(HK) + TWO + "fix visc all viscous 0.001\nrun 100\n", g=1)
deck("m02_langevin", "# fix langevin on spheres (temperature 0, damp 0.1)\n"
     + BASE(HK) + TWO + "fix lg all langevin 0 0 0.1 48279\nrun 100\n", g=1)
deck("m03_freeze_type2", "# fix freeze on type 2: its spheres hold still (and no rotation)\n"
     + BASE(HK) + TWO + "group t2 type 2\nfix fz t2 freeze\nrun 100\n", g=1)
deck("m04_setforce_type2", "# fix setforce 0 0 0 on type 2: the contact force on type 2 removed\n"
     + BASE(HK) + TWO + "group t2 type 2\nfix sf t2 setforce 0 0 0\nrun 100\n", g=1)
deck("m05_nve_limit", "# fix nve/limit instead of nve/sphere (no rotation, displacement capped)\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/limit 1e-6\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)
deck("m06_tsuji_e1", "# hertz/material tsuji e = 1.0: damping 0 -> eps 1\n"
     + head() + G1(f"hertz/material 1e7 1.0 0.3 damping tsuji {TL}") + GRAV + TAIL + TWO + "run 100\n")
deck("m07_coeffrest_e_tiny", "# hertz coeff_restitution e = 0.001\n"
     + head() + G1(f"hertz/material 1e7 0.001 0.3 damping coeff_restitution {TL}") + GRAV + TAIL + TWO + "run 100\n")
deck("m08_velocity_damping_hertz", "# hertz 1e6 damping velocity 0.05 (not limit): the overlap rule\n"
     + head() + G1(f"hertz 1e6 0.05 damping velocity {TL}") + GRAV + TAIL + TWO + "run 100\n")
deck("m09_temp_rescale", "# fix temp/rescale on all: velocities rescaled every 10 steps (left class)\n"
     + BASE(HK) + TWO + "compute tg all temp/sphere\nfix tr all temp/rescale 10 0 0 0.01 1.0\nrun 100\n", g=1)
deck("m10_nve_sphere_update_dipole_and_nvt", "# fix nvt/sphere (thermostat on spheres)\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nvt/sphere temp 1 1 0.01\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)
deck("m11_hooke_viscoelastic", "# hooke with damping viscoelastic\n"
     + head() + G1(f"hooke 2000 50 damping viscoelastic {TL}") + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("m12_jkr_cohesion_zero_tsuji", "# jkr with cohesion 0 and tsuji damping\n"
     + head() + G1(f"jkr 1e7 0.5 0.3 0.0 damping tsuji {TL}") + GRAV + TAIL + TWO + "run 100\n")
deck("m13_fix_move_type2", "# type 2 moved by fix move linear 0 0 0 (held still, no nve for it)\n"
     + head() + G1(HK) + GRAV + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 0\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)
deck("m14_damping_none_keyword", "# damping keyword omitted: the default viscoelastic\n"
     + head() + G1("hertz/material 1e7 1.4e7 0.3 tangential linear_nohistory 1 0.3") + GRAV + TAIL + TWO + "run 100\n")
deck("m15_nve_sphere_disc", "# nve/sphere disc in 2d (moment of inertia of a disc), with enforce2d\n"
     + head(dim=2, bnd="p f p", box="0 0.04 0 0.1 -0.001 0.001") + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\nfix e2 all enforce2d\nfix integ all nve/sphere disc\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type * diameter 0.004 density 2500\nrun 100\n", g=1)
deck("m16_fix_spring_self", "# fix spring/self on type 2 (tethers): a force beside the contact\n"
     + BASE(HK) + TWO + "group t2 type 2\nfix ss t2 spring/self 10.0\nrun 100\n", g=1)
deck("m17_fix_addforce", "# fix addforce on all: a constant force 0 0 -1e-3\n"
     + BASE(HK) + TWO + "fix af all addforce 0 0 -1e-3\nrun 100\n", g=1)
deck("m18_nve_sphere_group_type1_only", "# nve/sphere on type 1 only, type 2 not integrated (held still, keeps velocity 0)\n"
     + head() + G1(HK) + GRAV + "group t1 type 1\nfix integ t1 nve/sphere\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)

# ================================================================ h*: hybrid, omp, none, clear
deck("h01_hybrid_granular_lj", "# pair_style hybrid granular lj/cut: granular on 1 1 only, lj on 1 2 and 2 2\n"
     + head() + "pair_style hybrid granular lj/cut 0.01\npair_coeff 1 1 granular " + HK + "\npair_coeff 1 2 lj/cut 0.0 0.004\npair_coeff 2 2 lj/cut 0.0 0.004\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h02_hybrid_two_granular", "# pair_style hybrid granular granular: instance 1 on 1 1 (kn 2000), 2 on 2 2 and 1 2 (kn 8000)\n"
     + head() + "pair_style hybrid granular granular\npair_coeff 1 1 granular 1 " + HK + "\npair_coeff 1 2 granular 2 " + hk(8000) + "\npair_coeff 2 2 granular 2 " + hk(8000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h03_hybrid_overlay_granular_granular", "# hybrid/overlay granular granular on * *: two contact forces add (kn 2000 + 3000)\n"
     + head() + "pair_style hybrid/overlay granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff * * granular 2 " + hk(3000, 1000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h04_gran_hertz_history_omp", "# pair_style gran/hertz/history/omp with package omp 1\n"
     + head(extra="package omp 1\n") + "pair_style gran/hertz/history/omp 2e6 NULL 300 NULL 0.5 0\npair_coeff * *\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h05_suffix_omp_command", "# suffix omp then pair_style gran/hooke (becomes gran/hooke/omp)\n"
     + head(extra="package omp 1\nsuffix omp\n") + "pair_style gran/hooke 2000 NULL 300 NULL 0.5 0\npair_coeff * *\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h06_pair_none_settle_then_granular", "# pair_style none settling run then granular (left class: refused?)\n"
     + head() + "pair_style none\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n" + G1(HK) + "run 100\n", g=1)
deck("h07_clear_second_box_types3", "# clear: first box 2 types hooke, second 3 types hertz with 3 3 own E\n"
     + BASE(HK) + TWO + "run 100\nclear\n" + head(3) + G1(HM) + "pair_coeff 3 3 hertz/material 5e7 1.4e7 0.3 damping viscoelastic " + TL + "\n" + GRAV + TAIL + TWO
     + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2500\nrun 100\n")
deck("h08_pair_granular_then_none_last", "# granular in run 1 then pair_style none for run 2: no sphere contact at the end\n"
     + BASE(HK) + TWO + "run 100\npair_style none\nrun 100\n", g=1)
deck("h09_hybrid_granular_zero", "# hybrid granular zero: zero on 2 2 (no force), granular on 1 1 and 1 2\n"
     + head() + "pair_style hybrid granular zero 0.01\npair_coeff 1 1 granular " + HK + "\npair_coeff 1 2 granular " + hk(5000) + "\npair_coeff 2 2 zero\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h10_hybrid_none_sub", "# hybrid granular with pair_coeff 2 2 none: 2 2 no interaction\n"
     + head() + "pair_style hybrid granular\npair_coeff * * granular " + HK + "\npair_coeff 2 2 none\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("h11_neigh_exclude_type", "# neigh_modify exclude type 1 2: 1 2 never collide\n"
     + BASE(HK) + TWO + "neigh_modify exclude type 1 2\nrun 100\n", g=1)
deck("h12_special_clear_in_include", "# clear inside an included file, the second box there (hertz 1e8)\n"
     + BASE(HK) + TWO + "run 100\ninclude in.second\n", data={"in.second": "clear\n" + BASE(HM.replace("1e7", "1e8")) + TWO + "run 100\n"})

# ================================================================ L*: LIGGGHTS


WALLH = "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n"
LST = ("fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000\n"
       "fix m5 all property/global gamman peratomtypepair 3 300 200 100 200 250 150 100 150 200\n"
       "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
       "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
       "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n")
LWST = "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
INSREG = "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\n"
T2 = "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
PACK = "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"


def L(name, text, **kw):
    deck(name, text, liggghts=True, **kw)


L("L01_start_equal_step_after_reset", "# reset_timestep 5000 then insert/pack start 5000 (the step reached): LIGGGHTS inserts at 5000\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + "reset_timestep 5000\n"
  + PACK.replace("insert_every once", "insert_every 1000 start 5000") + RUN)
L("L02_start_between_two_runs", "# start 1500 with runs of 1000 and 1000: inserts in run 2 (2 2 and 1 2 appear only at the end)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 1500") + RUN + "run 1000\n")
L("L03_start_after_runs_upto", "# start 3000 with run 1000 then run 2500 upto: the last step is 2500, nothing inserted\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 3000") + RUN + "run 2500 upto\n")
L("L04_insert_stream", "# insert/stream of type 2 through a face mesh into the box over run 2000\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2
  + "fix inface all mesh/surface file face.stl type 1\nfix ins all insert/stream seed 32452867 distributiontemplate pdd nparticles 20 massrate 0.1 insert_every 500 overlapcheck yes vel constant 0. 0. -0.5 insertion_face inface extrude_length 0.02\n"
  + LRUN + "run 2000\n", files={"face.stl": ("plane", "0.12", "0.02")})
L("L05_insert_rate_region", "# insert/rate/region of type 2 at 0.01 kg/s, run 2000\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + "fix ins all insert/rate/region seed 32452867 distributiontemplate pdd nparticles 10 massrate 0.01 insert_every 500 overlapcheck yes vel constant 0 0 -0.2 region ins\n" + LRUN + "run 2000\n")
L("L06_massbased_two_templates", "# two templates (2 mm type 1 density 2500, 4 mm type 2 density 1500) weights 0.9/0.1 massbased\n"
  + LB() + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001\n"
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.002\n"
  "fix pdd all particledistribution/discrete/massbased 32452843 2 pts1 0.9 pts2 0.1\n" + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L07_numberbased_two_templates_same_type", "# two templates of type 2 (1.5 mm and 3 mm), numberbased: two sizes in type 2\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\n"
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\n"
  "fix pdd all particledistribution/discrete/numberbased 32452843 2 pts1 0.5 pts2 0.5\n" + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L08_template_radius_uniform", "# template radius uniform 1-2 mm (a distribution of radius)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius distribution uniform 0.001 0.002\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L09_run0_in_loop_with_insert", "# insert/pack once then a loop of run 0 three times and a real run 500\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + LRUN
  + "variable i loop 3\nlabel lp\nrun 0\nnext i\njump SELF lp\nrun 500\n")
L("L10_unfix_insert_before_run", "# insert/pack defined then unfixed before any run: nothing inserted; type 2 has no sphere\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + "unfix ins\n" + RUN)
L("L11_hooke_e_one", "# hooke with e = 1.0 for every pair: no damping, eps 1\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0\n" + HOOKE + WALLH + ATOMS + RUN)
L("L12_hertz_e_small", "# hertz e = 0.01 for every pair (and limitForce off): eps 0.01\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.01 0.01 0.01 0.01 0.01 0.01 0.01 0.01 0.01\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L13_limitforce_restyle", "# pair_style gran hertz limitForce on, then pair_style gran hertz again without limitForce: which end rule runs?\n"
  + lhead() + MAT3 + E3 + "pair_style gran model hertz tangential history limitForce on\npair_coeff * *\n" + WALL3 + ATOMS + RUN
  + "pair_style gran model hertz tangential history\npair_coeff * *\nrun 1000\n")
L("L14_peratomtypepair_n_equal", "# peratomtypepair ${n} with n equal 6/2 (substitutes 3)\n"
  + lhead() + MAT3 + "variable n equal 6/2\nfix m3 all property/global coefficientRestitution peratomtypepair ${n} 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L15_liggghts_if_string_15g", "# LIGGGHTS: e equal 1/3 substituted: if \"${e} == 0.333333333333333\" (the 15g text) picks the 0.3 branch\n"
  + lhead() + MAT3 + "variable e equal 1/3\nif \"${e} == 0.333333333333333\" then \"variable ee equal 0.3\" else \"variable ee equal 0.9\"\nprint \"PROBE e ${e} ee ${ee}\"\n"
  "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee}\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L16_liggghts_immediate_format", "# LIGGGHTS $(...) with format: E $(5.123e6:%.2e) (engine prints)\n"
  + lhead() + "fix m1 all property/global youngsModulus peratomtype $(5.123e6:%.2e) 5e6 5e6\nprint \"PROBE E $(5.123e6:%.2e)\"\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
  "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L17_gaussian_template", "# template radius gaussian mu 1.5 mm sigma 0.2 mm\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius distribution gaussian 0.0015 0.0002\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L18_mesh_moving_linear", "# a mesh floor moving up (move/mesh linear 0 0 0.1): wall speed adds to impact\n"
  + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 3\nfix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes fl\nfix mv all move/mesh mesh fl linear 0 0 0.1\n" + ATOMS.replace("0.01 units", "0.03 units") + RUN,
  files={"floor.stl": ("plane", "0", "0.04")})
L("L19_set_type_subset_after_run", "# after a run, set a region of type 1 to type 2 (LIGGGHTS has them)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + RUN
  + "region left block -0.05 0 INF INF INF INF units box\nset region left type 2\nrun 500\n")
L("L20_insert_pack_two_fixes_types", "# two insert/pack fixes: type 1 2 mm once, type 2 3 mm start 500 in a run of 1000\n"
  + LB() + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001\nfix pd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.0015\nfix pd2 all particledistribution/discrete 32452847 1 pts2 1.0\n" + INSREG
  + "fix ins1 all insert/pack seed 32452867 distributiontemplate pd1 insert_every once overlapcheck yes particles_in_region 10 region ins\n"
  "fix ins2 all insert/pack seed 32452869 distributiontemplate pd2 insert_every 10000 start 500 overlapcheck yes particles_in_region 20 region ins\n" + RUN)
L("L21_insert_unfixed_between_runs", "# insert/pack insert_every 300 with runs 500, unfix, run 500: inserted in run 1 only\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 300") + LRUN + "run 500\nunfix ins\nrun 500\n")
L("L22_timestep_after_units", "# LIGGGHTS: timestep 1e-5 before units si... (units after create_box? units first here) timestep set twice, last 5e-6\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\ntimestep 5e-6\nrun 1000\n")
L("L23_hooke_stiffness_e_absent", "# hooke/stiffness with absolute_damping on: gamman in absolute units\n"
  + lhead() + MAT3 + LST.replace("hooke/stiffness tangential history\n", "hooke/stiffness tangential history absolute_damping on\n") + LWST.replace("history primitive", "history absolute_damping on primitive") + ATOMS + RUN)
L("L24_hertz_set_density_after_run", "# set type 2 density 7800 after run 1: hertz eps is mass independent (e typed) anyway; hooke/stiffness changes\n"
  + lhead() + MAT3 + LST + LWST + ATOMS + RUN + "set type 2 density 7800\nrun 500\n")
L("L25_insert_pack_massbased_weights", "# particledistribution massbased with weights 1 and 3 of two templates of type 2 (2 and 1 mm)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.002\n"
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.001\n"
  "fix pdd all particledistribution/discrete/massbased 32452843 2 pts1 0.25 pts2 0.75\n" + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L26_start_once_combo", "# insert_every once with start 2000 > the run 1000: nothing inserted\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every once start 2000") + RUN)
L("L27_stiffness_e_hertz_stiffness", "# hertz/stiffness with kn/gamman peratomtypepair\n"
  + lhead() + MAT3 + LST.replace("hooke/stiffness", "hertz/stiffness") + LWST.replace("hooke/stiffness", "hertz/stiffness") + ATOMS + RUN)
L("L28_two_meshes_types_cyl", "# a mesh floor of type 3 and a mesh cylinder of type 2 (mesh material type 2)\n"
  + lhead() + MAT3 + E3 + HERTZ + "fix fl all mesh/surface file floor.stl type 3\nfix cy all mesh/surface file cyl.stl type 2\nfix walls all wall/gran model hertz tangential history mesh n_meshes 2 meshes fl cy\n"
  + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + RUN,
  files={"floor.stl": ("plane", "0", "0.04"), "cyl.stl": ("cylinder", "0.035", "0", "0.12", "48")})
L("L29_loop_coeff_restitution", "# index loop over e 0.9 0.6 0.3, the property fix redefined and a run 200 each pass: last e 0.3 for all\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n" + HERTZ + WALL3 + ATOMS + LRUN
  + "variable ev index 0.9 0.6 0.3\nlabel lp\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${ev} ${ev} ${ev} ${ev} ${ev} ${ev} ${ev} ${ev} ${ev}\nrun 200\nnext ev\njump SELF lp\n")
L("L30_freeze_type2", "# LIGGGHTS fix freeze on type 2\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "group t2 type 2\nfix fz t2 freeze\n" + RUN)
L("L31_viscous_liggghts", "# LIGGGHTS fix viscous 0.001 beside the contact\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "fix visc all viscous 0.001\n" + RUN)
L("L32_wall_primitive_zcylinder_moving", "# primitive zcylinder wall with a moving/rotating keyword? (shear z 0.1)\n"
  + lhead() + MAT3 + E3 + HERTZ + "fix cyl all wall/gran model hertz tangential history primitive type 3 zcylinder 0.04 0 0 shear z 0.1\n" + WALL3 + ATOMS + RUN)
L("L33_read_data_liggghts", "# LIGGGHTS read_data with diameters and densities per atom (atom_style granular)\n"
  + "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\nread_data spheres.data\nneighbor 0.002 bin\nneigh_modify delay 0\n"
  + MAT3 + E3 + HOOKE + WALLH + RUN,
  data={"spheres.data": "spheres\n\n3 atoms\n3 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.01 0.15 zlo zhi\n\nAtoms\n\n1 1 0.004 2500 0.01 0 0.01\n2 1 0.002 7800 0.02 0 0.01\n3 2 0.006 1500 -0.01 0 0.01\n"})
L("L34_hooke_limitforce_e_low", "# hooke limitForce on with e 0.1 typed for all\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
  + "pair_style gran model hooke tangential history limitForce on\npair_coeff * *\n" + WALLH.replace("zplane 0.0", "zplane 0.0 limitForce on") + ATOMS + RUN)
L("L35_start_several_runs_reset", "# reset_timestep 0 after a run, then insert start 500: step runs again from 0 (inserted in run 2)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + LRUN + "run 1000\nreset_timestep 0\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 500") + "run 1000\n")
L("L36_hooke_characteristic_velocity", "# hooke with characteristicVelocity 2.0 (stiffness from it): eps set by e anyway\n"
  + lhead() + MAT3 + E3 + "fix m9 all property/global characteristicVelocity scalar 2.0\n" + HOOKE + WALLH + ATOMS + RUN)
L("L37_set_diameter_template_atoms_after", "# after an insert run, set type 2 diameter 0.005: LIGGGHTS keeps mass? (set diameter in LIGGGHTS: density kept, mass rescaled)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + RUN + "set type 2 diameter 0.005\nrun 500\n")
L("L38_insert_pack_all_in_run0", "# insert/pack once then only run 0: LIGGGHTS inserts at setup? (engine says)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + LRUN + "run 0\n")
L("L39_run_upto_start", "# run 500 then insert start 1000 and run 1500 upto: inserted at 1000\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + LRUN + "run 500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 1000") + "run 1500 upto\n")
L("L40_e_peratomtypepair_asym_ok", "# hooke, coefficientRestitution 0.9 for 1 1 and 0.2 elsewhere; two types present\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.2 0.2 0.2 0.2 0.2 0.2 0.2 0.2\n" + HOOKE + WALLH + ATOMS + RUN)


# ================================================================ second batch: fixed LIGGGHTS variants and further traps
L("L41_insert_stream_fixed", "# insert/stream of type 2 (1.5 mm) through a face mesh, no insert_every: inserted in the run\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2
  + "fix inface all mesh/surface file face.stl type 1\nfix ins all insert/stream seed 32452867 distributiontemplate pdd nparticles 20 massrate 0.1 overlapcheck yes vel constant 0. 0. -0.5 insertion_face inface extrude_length 0.02\n"
  + LRUN + "run 2000\n", files={"face.stl": ("plane", "0.12", "0.02")})
L("L42_hooke_e_one_cv", "# hooke with e = 1.0 for every pair and characteristicVelocity 1: no damping, eps 1\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0\nfix m9 all property/global characteristicVelocity scalar 1.0\n" + HOOKE + WALLH + ATOMS + RUN)
L("L43_hertz_e_0051", "# hertz e = 0.051 (just above LIGGGHTS' lower bound 0.05) for every pair: eps 0.051\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.051 0.051 0.051 0.051 0.051 0.051 0.051 0.051 0.051\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L44_two_property_fixes_same_name", "# coefficientRestitution given by two fixes (m3 all 0.5, m3b all 0.9): LIGGGHTS uses the first it finds\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
  "fix m3b all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L45_variable_redefined_after_fix", "# e from ${e} = 0.5 at the fix; e redefined 0.9 afterwards with no new fix: LIGGGHTS keeps 0.5\n"
  + lhead() + MAT3 + "variable e equal 0.5\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nvariable e equal 0.9\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L46_gaussian_template_fixed", "# template radius distribution normal? (LIGGGHTS: gaussian mu sigma) for type 2 (1.5 mm, sigma 0.1 mm)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius gaussian number 0.0015 0.0001\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L47_template_radius_uniform_fixed", "# template radius uniform number 1 2 mm for type 2\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius uniform number 0.001 0.002\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L48_hooke_stiffness_density_template_range", "# hooke/stiffness with a template density uniform? (density distribution) for type 2\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density uniform 1000 3000 radius constant 0.0015\nfix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
  + INSREG + PACK.replace("particles_in_region 10", "particles_in_region 30") + RUN)
L("L49_start_in_second_of_three_runs_loop", "# insert start 1200 with a loop of three runs of 500: inserts in run 3 (steps 1000-1500)\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 1200") + LRUN + "variable i loop 3\nlabel lp\nrun 500\nnext i\njump SELF lp\n")
L("L50_hooke_stiffness_set_density_after", "# hooke/stiffness: set type 2 density 7800 after run 1 (mass changes, eps changes)\n"
  + lhead() + MAT3 + LST + LWST + ATOMS + RUN + "set type 2 density 7800\nrun 500\n")
L("L51_limitforce_pair_only", "# pair limitForce on, wall primitive without: wall by overlap rule\n"
  + lhead() + MAT3 + E3 + "pair_style gran model hooke tangential history limitForce on\npair_coeff * *\nfix m9 all property/global characteristicVelocity scalar 2.0\n" + WALLH + ATOMS + RUN)
L("L52_timestep_between_runs", "# LIGGGHTS: run 1000 at 1e-5, timestep 1e-4, run 500: the last runs at 1e-4\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "timestep 1e-4\nrun 500\n")
L("L53_insert_pack_run_upto_zero_steps", "# insert/pack once, run 1000, then run 1000 upto (zero steps): nothing more\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + RUN + "run 1000 upto\n")
L("L54_radius_per_type_set_region", "# set region of type 1 atoms to diameter 6 mm: two sizes in type 1 (hertz: eps independent of size)\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\ncreate_atoms 2 single 0 0.02 0.01 units box\n"
  "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.003 density 2500\nregion lft block -0.05 0 INF INF INF INF units box\nset region lft diameter 0.006\n" + RUN)
deck("p13_pair_coeff_32_swapped", "# pair_coeff 3 2 (numeric, reversed) kn 7000 in 3 types: swapped to 2 3\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 3 2 " + hk(7000) + "\n" + GRAV + TAIL + TWO
     + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2500\nrun 100\n", g=1)
deck("p14_star_range_upper_beyond_wildcard", "# pair_coeff 1*3 3 (i 1..3, j 3): 1 3, 2 3, 3 3 kn 7000\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 1*3 3 " + hk(7000) + "\n" + GRAV + TAIL + TWO
     + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.005 density 2500\nrun 100\n", g=1)
deck("p15_2star_1_sets_none_error", "# pair_coeff 2* 1 sets no pair (j from max(1,i) .. 1): LAMMPS: Incorrect args\n"
     + head(3) + "pair_style granular\npair_coeff * * " + HK + "\npair_coeff 2* 1 " + hk(7000) + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p16_kn_redefined_after_pair_coeff", "# pair_coeff uses ${kn} = 2000; kn redefined 9000 afterwards with no new pair_coeff: 2000 stays\n"
     + head() + "variable kn equal 2000\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\nvariable kn equal 9000\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p17_jump_other_file", "# jump to another file (in.part2) that sets kn 6000 and runs: lines after the jump in in.deck never run\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + "jump in.part2\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1,
     data={"in.part2": "pair_coeff * * " + hk(6000) + "\nrun 100\n"})
deck("p18_include_loop_label_in_include", "# an include with its own loop (label/jump SELF inside the included file): kn 1000*i, last 3000\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + "include in.loop\nrun 100\n", g=1,
     data={"in.loop": f"variable i loop 3\nlabel lp\npair_coeff * * hooke $(1000*v_i) 3000 {K}\nnext i\njump SELF lp\n"})
deck("p19_if_quit_before_pair_coeff", "# an if on a variable that is true skips to a label past a pair_coeff kn 9000 (jump SELF label)\n"
     + head() + G1(HK) + "variable skip equal 1\nif \"${skip} == 1\" then \"jump SELF past\"\npair_coeff * * " + hk(9000) + "\nlabel past\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p20_mixed_limit_damping_one_type", "# limit_damping only on 2 2's line; 1 2 mixed (LAMMPS: limit_damping of either applies)\n"
     + head() + "pair_style granular\npair_coeff 1 1 hooke 2000 0.5 damping velocity " + TL + "\npair_coeff 2 2 hooke 8000 0.5 damping velocity " + TL + " limit_damping\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("s21_set_diameter_before_density_type_label", "# labels: set type glass density 2500 then diameter 0.004 (mass from d 1 kept)\n"
     + head() + "labelmap atom 1 glass 2 steel\n" + G1(HK) + GRAV + FLOOR + TAIL
     + "create_atoms glass single 0.02 0.02 0.01\ncreate_atoms steel single 0.01 0.01 0.01\nset type glass density 2500\nset type glass diameter 0.004\nset type steel diameter 0.004 density 2500\nrun 100\n", g=1)
deck("s22_create_atoms_after_set", "# set type 1 diameter/density, then a second create_atoms 1: the new sphere is d 1, density 1\n"
     + head(box="0 4 0 4 0 10") + G1(HK) + GRAV + FLOOR + TAIL + "create_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type * diameter 0.004 density 2500\ncreate_atoms 1 single 3 3 1\nrun 100\n", g=1)
deck("s23_adapt_diameter_reset_yes_last_run", "# fix adapt diameter to 6 mm reset yes active in the only run: during the run the spheres are 6 mm\n"
     + BASE(HK) + TWO4 + "variable dd equal 0.006\nfix ad all adapt 1 atom diameter v_dd reset yes\nrun 100\n", g=1)
deck("s24_set_density_region_after_run", "# after run 1 spheres falling: set region low density 7800 (which spheres are low depends on the run)\n"
     + BASE(HK) + TWO4.replace("0.01 0.01 0.01", "0.01 0.01 0.05") + "run 2000\nregion low block INF INF INF INF 0 0.02 units box\nset region low density 7800\nrun 100\n", g=1)
deck("t11_timestep_in_include_after_run", "# timestep 2e-6 set in an include after run 1; run 2 at 2e-6\n"
     + BASE(HK) + TWO + "run 100\ninclude in.dt\nrun 100\n", g=1, data={"in.dt": "timestep 2e-6\n"})
deck("t12_timestep_from_variable_of_mass", "# dt = 0.01*sqrt(mass[1]/2000) from the atom's mass (LAMMPS holds 8.38e-5): 2.05e-6\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/sphere\n" + TWO + "variable dt equal 0.01*sqrt(mass[1]/2000)\ntimestep ${dt}\nprint \"PROBE dt ${dt}\"\nrun 100\n", g=1)
deck("w13_wall_region_side_out_sphere", "# wall/gran/region sphere side out (an obstacle ball in the box): type 1 and 2 on its outside\n"
     + BASE(HK) + "region ob sphere 0.02 0.02 0.05 0.01 side out units box\nfix ow all wall/gran/region granular " + hk(6000) + " region ob\n" + TWO + "run 100\n", g=1)
deck("w14_wall_gran_region_block_open", "# wall/gran/region block with open faces (open 5 = zlo open): floor missing\n"
     + head() + G1(HK) + GRAV + TAIL + "region bl block 0 0.04 0 0.04 0 0.1 open 5 units box\nfix rw all wall/gran/region granular " + hk(5000) + " region bl\n" + TWO + "run 100\n", g=1)
deck("m19_freeze_then_unfreeze", "# fix freeze on type 2 in run 1, unfixed for run 2\n"
     + BASE(HK) + TWO + "group t2 type 2\nfix fz t2 freeze\nrun 100\nunfix fz\nrun 100\n", g=1)
deck("m20_nve_sphere_for_t1_and_t2_separately", "# two integrators: nve/sphere on t1, nve/limit on t2\n"
     + head() + G1(HK) + GRAV + FLOOR + "group t1 type 1\ngroup t2 type 2\nfix i1 t1 nve/sphere\nfix i2 t2 nve/limit 1e-5\ntimestep 1e-5\n" + TWO + "run 100\n", g=1)
deck("h13_exclude_then_delete_exclude", "# neigh_modify exclude type 1 2 in run 1, then exclude none for run 2\n"
     + BASE(HK) + TWO + "neigh_modify exclude type 1 2\nrun 100\nneigh_modify exclude none\nrun 100\n", g=1)
deck("h14_hybrid_granular_lj_on_all_overlay", "# hybrid/overlay granular lj/cut with lj epsilon nonzero on 1 2: a force beside the contact\n"
     + head() + "pair_style hybrid/overlay granular lj/cut 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0.0 0.004\npair_coeff 1 2 lj/cut 1e-6 0.004\n" + GRAV + TAIL + TWO + "run 100\n", g=1)


# ================================================================ third batch: run every, groups after atoms, LIGGGHTS set order
deck("e01_run_every_set_diameter", "# run 200 every 100 \"set type 2 diameter 0.008\": after chunk 1 type 2 is 8 mm (mass kept) for chunk 2\n"
     + BASE(HK) + TWO4 + "run 200 every 100 \"set type 2 diameter 0.008\"\n", g=1)
deck("e02_run_every_set_density", "# run 200 every 100 \"set type 2 density 7800\": after chunk 1 type 2 is steel for chunk 2\n"
     + BASE(HK) + TWO4 + "run 200 every 100 \"set type 2 density 7800\"\n", g=1)
deck("e03_run_every_unfix_floor", "# run 200 every 100 \"unfix floor\" ... (fails on the second chunk's end: unfix twice? engine says)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix floor\"\nrun 100\n", g=1)
deck("e04_run_every_variable_then_coeff", "# run 200 every 100 \"variable kn equal 9000\" then pair_coeff ${kn} after the run (kn 9000 for run 2)\n"
     + BASE(HK) + TWO4 + "variable kn equal 2000\nrun 200 every 100 \"variable kn equal 9000\"\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("e05_run_pre_no_post_no", "# run 100 then run 100 pre no post no: plain two runs\n"
     + BASE(HK) + TWO + "run 100\nrun 100 pre no post no\n", g=1)
deck("e06_run_start_stop_ramp", "# fix adapt-free deck with run 100 start 0 stop 1000 and a ramp() in kn read after (ramp at step 100 of 0..1000)\n"
     + BASE(HK) + TWO4 + "variable kr equal ramp(2000,12000)\nrun 100 start 0 stop 1000\nvariable kn equal ${kr}\nprint \"PROBE kn ${kn}\"\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n", g=1)
deck("m21_fix_move_type2_groups_after", "# type 2 held by fix move linear 0 0 0 (groups made after the atoms), type 1 integrated: a wall-like partner\n"
     + head() + G1(HK) + GRAV + TWO + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 0\ntimestep 1e-5\nrun 100\n", g=1)
deck("m22_nve_type1_only_groups_after", "# nve/sphere on type 1 only (group after atoms): type 2 never moves, keeps its velocity 0\n"
     + head() + G1(HK) + GRAV + TWO + "group t1 type 1\nfix integ t1 nve/sphere\ntimestep 1e-5\nrun 100\n", g=1)
deck("m23_viscous_scale_type2", "# fix viscous 0.001 scale 2 10 (type 2 drag 10x)\n"
     + BASE(HK) + TWO + "fix visc all viscous 0.001 scale 2 10\nrun 100\n", g=1)
deck("m24_rigid_single_type2_bodies", "# fix rigid/small molecule? no: fix rigid single on type 2 group (each a body of one sphere)\n"
     + head() + G1(HK) + GRAV + TWO + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix rb t2 rigid single\ntimestep 1e-5\nrun 100\n", g=1)
deck("x21_while_loop_counter", "# a while-style loop: c equal ${c}+1 until c = 4; kn 1000*c (last 4000)\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + f"variable c equal 1\nlabel lp\nvariable c equal $(v_c+1)\npair_coeff * * hooke $(1000*v_c) 3000 {K}\nif \"${{c}} < 4\" then \"jump SELF lp\"\nprint \"PROBE c ${{c}}\"\nrun 100\n", g=1)
deck("x22_format_style_variable", "# variable kf format kn %.1e: kn 2345 -> 2.3e+03 = 2300 used in pair_coeff\n"
     + head() + "variable kn equal 2345\nvariable kf format kn %.1e\nprint \"PROBE kf ${kf}\"\npair_style granular\npair_coeff * * hooke ${kf} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x23_self_reference_immediate", "# variable kn equal 2000 then variable kn equal ${kn}*2 (immediate: 4000)\n"
     + head() + "variable kn equal 2000\nvariable kn equal ${kn}*2\nprint \"PROBE kn ${kn}\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x24_quoted_expression_spaces", "# variable kn equal \"2000 + 500 * 2\" (spaces in quotes): 3000\n"
     + head() + "variable kn equal \"2000 + 500 * 2\"\npair_style granular\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x25_next_exhausted_skips", "# index variable k 5000 exhausted by next: the jump after next is skipped, the run once with kn 5000\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + f"variable k index 5000\nlabel lp\npair_coeff * * hooke $k 3000 {K}\nrun 50\nnext k\njump SELF lp\nrun 50\n", g=1)
deck("x26_int_truncation_in_coeff", "# kn = floor(2999.9) = 2999 via floor(); gamma = ceil(2000.1) = 2001\n"
     + head() + "variable kn equal floor(2999.9)\nvariable gn equal ceil(2000.1)\npair_style granular\npair_coeff * * hooke ${kn} ${gn} " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x27_label_in_if_jump_other_label", "# if/else chooses a label by a format of 0.5: $(0.5:%.0f) = 0 -> label L0 (kn 3000), L1 would be kn 9000\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + f"jump SELF L$(0.5:%.0f)\nlabel L1\npair_coeff * * {hk(9000)}\njump SELF done\nlabel L0\npair_coeff * * {hk(3000)}\nlabel done\nrun 100\n", g=1)
L("L55_unfix_property_refix_new_id", "# unfix m3 after run 1 and define e 0.3 under a new ID m3x: run 2 at e 0.3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "unfix m3\nfix m3x all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 500\n")
L("L56_set_density_then_diameter", "# LIGGGHTS keeps a per-atom density: set density 2500 then set diameter 0.004 gives 4/3 pi r^3 2500 (unlike LAMMPS) - hooke/stiffness\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 density 2500\nset type 1 diameter 0.004\nset type 2 diameter 0.006 density 1500\n" + RUN)
L("L57_diameter_only_default_density", "# LIGGGHTS create_atoms then set diameter only (density default 1): mass 4/3 pi r^3 - hooke/stiffness\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 diameter 0.004\nset type 2 diameter 0.006 density 1500\n" + RUN)
L("L58_set_mass_then_diameter", "# LIGGGHTS set mass 1e-4 then set diameter 0.004: mass recomputed from density? (engine state says) - hooke/stiffness\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 mass 1e-4\nset type 1 diameter 0.004\nset type 2 diameter 0.006 density 1500\n" + RUN)
L("L59_run_every_set_density", "# LIGGGHTS run 1000 every 500 \"set type 2 density 7800\" - hooke/stiffness: chunk 2 with steel type 2\n"
  + lhead() + MAT3 + LST + LWST + ATOMS + LRUN + "run 1000 every 500 \"set type 2 density 7800\"\n")
L("L60_insert_pack_template_then_set_density_type", "# insert/pack of type 2 (1.5 mm, 1500) run, then set type 2 density 7800 - hooke/stiffness\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG + PACK + RUN + "set type 2 density 7800\nrun 500\n")


# ================================================================ fourth batch: curved region walls with Hertz, fixed LIGGGHTS decks
deck("w15_region_sphere_hertz_inside", "# wall/gran/region on a sphere region (inside, R 0.05) with hertz/material: LAMMPS uses the region's curvature in R_eff\n"
     + head(box="0 0.12 0 0.12 0 0.12", bnd="f f f") + G1(HM) + GRAV + TAIL + "region sp sphere 0.06 0.06 0.06 0.05 units box\nfix sw all wall/gran/region granular " + HM + " region sp\n"
     + "create_atoms 1 single 0.06 0.06 0.03\ncreate_atoms 2 single 0.07 0.06 0.06\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("w16_region_prism_hertz", "# wall/gran/region on a prism region (tilted sides) with hertz/material: flat faces, R_eff = R\n"
     + head(box="0 0.04 0 0.04 0 0.1", bnd="f f f") + G1(HM) + GRAV + TAIL + "region pr prism 0 0.04 0 0.04 0 0.1 0.01 0 0 units box\nfix pw all wall/gran/region granular " + HM + " region pr\n"
     + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.03 0.02 0.05\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("w17_region_cone_hertz", "# wall/gran/region on a cone (inside, radii 0.005 to 0.02) with hertz/material: curvature varies along the cone\n"
     + head(box="0 0.04 0 0.04 0 0.1", bnd="f f f") + G1(HM) + GRAV + TAIL + "region cn cone z 0.02 0.02 0.005 0.02 0 0.1 units box\nfix cw all wall/gran/region granular " + HM + " region cn\n"
     + "create_atoms 1 single 0.02 0.02 0.05\ncreate_atoms 2 single 0.025 0.02 0.08\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("w18_region_sphere_hertz_outside", "# wall/gran/region on a sphere region side out (a ball obstacle R 0.01) with hertz/material: convex, R_eff = r R/(r+R)\n"
     + head(box="0 0.06 0 0.06 0 0.06", bnd="f f f") + G1(HM) + GRAV + TAIL + "region ob sphere 0.03 0.03 0.02 0.01 side out units box\nfix ow all wall/gran/region granular " + HM + " region ob\n"
     + "create_atoms 1 single 0.03 0.03 0.04\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
deck("w19_zcylinder_wall_gran_hertz", "# fix wall/gran granular hertz/material zcylinder 0.019 (non-periodic x y): concave, R_eff from the cylinder\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + G1(HM) + GRAV + TAIL + "fix cyl all wall/gran granular " + HM + " zcylinder 0.019\n"
     + "create_atoms 1 single 0 0 0.05\ncreate_atoms 2 single 0.01 0 0.05\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n")
L("L61_read_data_liggghts_cv", "# LIGGGHTS read_data with diameters and densities per atom, hooke/stiffness (mass dependent)\n"
  + "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\nread_data spheres.data\nneighbor 0.002 bin\nneigh_modify delay 0\n"
  + MAT3 + LST + LWST + RUN,
  data={"spheres.data": "spheres\n\n3 atoms\n3 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.01 0.15 zlo zhi\n\nAtoms\n\n1 1 0.004 2500 0.01 0 0.01\n2 1 0.002 7800 0.02 0 0.01\n3 2 0.006 1500 -0.01 0 0.01\n"})
L("L62_hooke_limitforce_e_low_cv", "# hooke limitForce on with e 0.1 typed for all, characteristicVelocity 2\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\nfix m9 all property/global characteristicVelocity scalar 2.0\n"
  + "pair_style gran model hooke tangential history limitForce on\npair_coeff * *\n" + WALLH.replace("zplane 0.0", "zplane 0.0 limitForce on") + ATOMS + RUN)
L("L63_two_insert_fixes_primes", "# two insert/pack fixes: type 1 2 mm once, type 2 3 mm start 500 in a run of 1000 (prime seeds)\n"
  + LB() + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001\nfix pd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.0015\nfix pd2 all particledistribution/discrete 49979687 1 pts2 1.0\n" + INSREG
  + "fix ins1 all insert/pack seed 32452867 distributiontemplate pd1 insert_every once overlapcheck yes particles_in_region 10 region ins\n"
  "fix ins2 all insert/pack seed 67867967 distributiontemplate pd2 insert_every 10000 start 500 overlapcheck yes particles_in_region 20 region ins\n" + RUN)
L("L64_absolute_damping_fixed_order", "# hooke/stiffness absolute_damping on (pair and wall, keyword order as LIGGGHTS wants): gamman absolute\n"
  + lhead() + MAT3 + LST.replace("hooke/stiffness tangential history\n", "hooke/stiffness tangential history absolute_damping on\n")
  + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0 absolute_damping on\n" + ATOMS + RUN)


# ================================================================ fifth batch: fixed substitution decks
deck("x28_if_15g_vs_20g", "# a = 0.1*3: ${a} is %.15g -> 0.3, so if \"${a} == 0.3\" is true (kn 7000); $(v_a) is %.20g -> 0.30000000000000004441, so if \"$(v_a) == 0.3\" is false (gamma 3000 kept)\n"
     + head() + "variable a equal 0.1*3\nvariable kn equal 2000\nvariable gn equal 3000\nif \"${a} == 0.3\" then \"variable kn equal 7000\"\nif \"$(v_a) == 0.3\" then \"variable gn equal 100\"\n"
     + "print \"PROBE kn ${kn} gn ${gn}\"\npair_style granular\npair_coeff * * hooke ${kn} ${gn} " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x29_include_name_from_equal_after_box", "# n equal 4/2 substitutes as 2 (%.15g): include in.${n} reads in.2 (kn 3000), not in.2.0 (kn 9000)\n"
     + head() + "variable n equal 4/2\ninclude in.${n}\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"in.2": "pair_style granular\npair_coeff * * " + hk(3000) + "\n", "in.2.0": "pair_style granular\npair_coeff * * " + hk(9000) + "\n"})
deck("x30_include_name_immediate_20g", "# include in.$(4/2) : immediate %.20g gives 2 (an integer prints without decimals): in.2 (kn 3000)\n"
     + head() + "include in.$(4/2)\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"in.2": "pair_style granular\npair_coeff * * " + hk(3000) + "\n", "in.2.0": "pair_style granular\npair_coeff * * " + hk(9000) + "\n"})
deck("x31_liggghts_like_format_loop_dt", "# timestep $(1/3*1e-5) (%.20g, 3.3333333333333333e-06) and a run: dt as substituted\n"
     + head() + G1(HK) + GRAV + FLOOR + "fix integ all nve/sphere\ntimestep $(1/3*1e-5)\n" + TWO + "run 100\n", g=1)
L("L65_liggghts_include_name_from_equal", "# LIGGGHTS: n equal 4/2 substitutes (its own format) in include in.${n}: in.2 (e 0.3) or in.2.0 (e 0.9)\n"
  + lhead() + MAT3 + "variable n equal 4/2\ninclude in.${n}\n" + HERTZ + WALL3 + ATOMS + RUN,
  data={"in.2": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n",
        "in.2.0": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n"})
L("L66_liggghts_if_on_10g", "# LIGGGHTS: e equal 0.1*3 substituted: if \"${e} == 0.3\" (true if its format rounds) picks e 0.3 else 0.9\n"
  + lhead() + MAT3 + "variable e equal 0.1*3\nif \"${e} == 0.3\" then \"variable ee equal 0.3\" else \"variable ee equal 0.9\"\nprint \"PROBE e ${e} ee ${ee}\"\n"
  "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee} ${ee}\n" + HERTZ + WALL3 + ATOMS + RUN)


# ================================================================ sixth batch: parsing quirks, respa, LIGGGHTS 2d and sphere style
deck("x32_single_quoted_dollar_lazy", "# variable s string '${kn}' (quotes stop substitution), kn redefined 5000, pair_coeff ${s}: LAMMPS re-scans the inserted text (engine prints)\n"
     + head() + "variable kn equal 3000\nvariable s string '${kn}'\nvariable kn equal 5000\nprint \"PROBE s ${s}\"\npair_style granular\npair_coeff * * hooke ${s} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x33_crlf_line_ends", "# the deck with CRLF line ends (a file from Windows): pair_coeff kn 4000, gamma 3000\r\n"
     + (head() + G1(hk(4000)) + GRAV + TAIL + TWO + "run 100\n").replace("\n", "\r\n"), g=1)
deck("x34_continuation_ampersand", "# pair_coeff split over three lines with & (kn 4500 on the second line)\n"
     + head() + "pair_style granular\npair_coeff * * hooke &\n   4500 3000 &\n   " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x35_tabs_and_plus_sign", "# tabs between words and a '+' sign and E exponent: hooke\t+2.5E3\t3e+03\n"
     + head() + "pair_style\tgranular\npair_coeff\t*\t*\thooke\t+2.5E3\t3e+03\t" + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x36_damping_keyword_twice", "# damping given twice in one pair_coeff (mass_velocity then velocity 0.5): which one LAMMPS keeps (engine decides)\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 0.5 damping mass_velocity " + TL + " damping velocity\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x37_leading_dot_number", "# numbers with a leading dot and trailing dot: hooke .2e4 3000.\n"
     + head() + "pair_style granular\npair_coeff * * hooke .2e4 3000. " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("x38_comment_after_continuation", "# a # comment on a line ending the pair_coeff, and a $ inside a # comment (not substituted)\n"
     + head() + "pair_style granular\npair_coeff * * hooke 3500 3000 " + K + " # kn ${undefined_var} here\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("t13_run_style_respa", "# run_style respa 2 4 (pair on the outer level? gran styles on inner?): steps per contact at dt or dt/4 (engine decides)\n"
     + head() + "pair_style gran/hooke 2000 NULL 300 NULL 0.5 0\npair_coeff * *\n" + GRAV + TAIL + "run_style respa 2 4\n" + TWO + "run 100\n", g=1)
deck("h15_newton_on", "# newton on with pair granular (engine decides whether it runs)\n"
     + head(extra="newton on\n") + G1(HK) + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("p21_limit_damping_cleared_by_later_star", "# * * with limit_damping then 1 1 without: 1 1 overlap rule, 1 2 and 2 2 force rule\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 0.5 damping velocity " + TL + " limit_damping\npair_coeff 1 1 hooke 2000 0.5 damping velocity " + TL + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p22_tangential_twice", "# tangential given twice (linear_nohistory then linear_history): normal law unchanged\n"
     + head() + "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity " + TL + " tangential linear_history 1000 1 0.3\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
L("L67_liggghts_2d_set_density", "# LIGGGHTS 2d box: set density on discs (LIGGGHTS' own mass rule), hooke/stiffness\n"
  + "dimension 2\n" + lhead(box="-0.05 0.05 -0.01 0.15 -0.001 0.001", bnd="f f p") + MAT3 + LST
  + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 yplane 0.0\nfix e2 all enforce2d\n"
  + "create_atoms 1 single 0.01 0.01 0 units box\ncreate_atoms 2 single -0.01 0.01 0 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
  + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere\nrun 1000\n")
L("L68_liggghts_atom_style_sphere", "# LIGGGHTS with atom_style sphere (not granular): set diameter/density, hooke/stiffness\n"
  + lhead().replace("atom_style granular", "atom_style sphere") + MAT3 + LST + LWST + ATOMS + RUN)
L("L69_liggghts_newton_on", "# LIGGGHTS newton on (engine decides), hertz\n"
  + lhead().replace("newton off", "newton on") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)


# ================================================================ seventh batch: commands run between the parts of run ... every
deck("e07_run_every_refix_floor_stiffer", "# run 100 every 100 \"unfix floor\" \"fix floor ... hooke 9000\", then run 100: the last run's floor has kn 9000\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix floor\" \"fix floor all wall/gran granular " + hk(9000) + " zplane 0 NULL\"\nrun 100\n", g=1)
deck("e08_run_every_include_coeff", "# run 100 every 100 \"include in.change\" (in.change: pair_coeff * * hooke 9000), then run 100 at kn 9000\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"include in.change\"\nrun 100\n", g=1, data={"in.change": "pair_coeff * * " + hk(9000) + "\n"})
deck("e09_run_every_add_viscous", "# run 100 every 100 \"fix visc all viscous 0.05\", then run 100 with that drag\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"fix visc all viscous 0.05\"\nrun 100\n", g=1)
deck("e10_run_every_exclude", "# run 100 every 100 \"neigh_modify exclude type 1 2\", then run 100: 1 2 never collide there\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"neigh_modify exclude type 1 2\"\nrun 100\n", g=1)
deck("e11_run_every_pair_style", "# run 100 every 100 \"pair_style gran/hooke 9000 NULL 300 NULL 0.5 0\" \"pair_coeff * *\", then run 100 with gran/hooke\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"pair_style gran/hooke 9000 NULL 300 NULL 0.5 0\" \"pair_coeff * *\"\nrun 100\n", g=1)
deck("e12_run_every_timestep_then_run", "# run 100 every 100 \"timestep 2e-6\", then run 1000: the last run at dt 2e-6\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"timestep 2e-6\"\nrun 1000\n", g=1)
deck("e13_run_every_unfix_integ", "# run 100 every 100 \"unfix integ\" \"fix integ all nve/limit 1e-7\": the last run integrated by nve/limit (speed cap 0.01)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix integ\" \"fix integ all nve/limit 1e-7\"\nrun 100\n", g=1)
deck("e14_run_every_fix_adapt", "# run 100 every 100 \"fix ad all adapt 1 atom diameter v_dd reset no\" (dd 0.006), then run 100: spheres 6 mm\n"
     + BASE(HK) + TWO4 + "variable dd equal 0.006\nrun 100 every 100 \"fix ad all adapt 1 atom diameter v_dd reset no\"\nrun 100\n", g=1)
L("L70_run_every_refix_e", "# LIGGGHTS run 500 every 500 \"fix m3 all property/global coefficientRestitution ... 0.3\", then run 500 at e 0.3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\"\nrun 500\n")
L("L71_run_every_unfix_wall", "# LIGGGHTS run 500 every 500 \"unfix wprim\", then run 500 without the wall\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"unfix wprim\"\nrun 500\n")
L("L72_run_every_timestep", "# LIGGGHTS run 500 every 500 \"timestep 1e-4\", then run 500 at dt 1e-4\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"timestep 1e-4\"\nrun 500\n")


# ================================================================ eighth batch: settings changed after the last run (no step uses them)
deck("z01_trailing_pair_coeff", "# run 100 at kn 2000, then pair_coeff * * kn 9000 after the last run: no step uses kn 9000\n"
     + BASE(HK) + TWO4 + "run 100\npair_coeff * * " + hk(9000) + "\n", g=1)
deck("z02_trailing_timestep", "# run 100 at dt 1e-5, then timestep 5e-4 after the last run: no step at 5e-4\n"
     + BASE(HK) + TWO4 + "run 100\ntimestep 5e-4\n", g=1)
deck("z03_trailing_set_density", "# run 100, then set type 2 density 7800 after the last run: no step with steel spheres\n"
     + BASE(HK) + TWO4 + "run 100\nset type 2 density 7800\n", g=1)
deck("z04_trailing_unfix_wall_and_new_wall", "# run 100 with floor kn 2000, then unfix floor and a floor kn 9000 after the last run\n"
     + BASE(HK) + TWO4 + "run 100\nunfix floor\nfix floor all wall/gran granular " + hk(9000) + " zplane 0 NULL\n", g=1)
deck("z05_trailing_pair_style_change", "# run 100 granular hooke, then pair_style gran/hooke/history 9000 ... after the last run\n"
     + BASE(HK) + TWO4 + "run 100\npair_style gran/hooke/history 9000 NULL 400 NULL 0.5 0\npair_coeff * *\n", g=1)
deck("z06_trailing_create_atoms_type3", "# run 100 with types 1 2, then create_atoms type 3 (7800) and pair_coeff 3 3 after the last run\n"
     + head(3) + G1(HK) + GRAV + FLOOR + TAIL + TWO4 + "run 100\ncreate_atoms 3 single 0.03 0.03 0.02\nset type 3 diameter 0.005 density 7800\npair_coeff 3 3 " + hk(9000) + "\n", g=1)
deck("z07_trailing_run0_after_change", "# run 100 at kn 2000, pair_coeff kn 9000 then run 0 (no step) at the end\n"
     + BASE(HK) + TWO4 + "run 100\npair_coeff * * " + hk(9000) + "\nrun 0\n", g=1)
deck("z08_trailing_minimize_after_change", "# run 100 at kn 2000, pair_coeff kn 9000 then minimize (steps, but no dynamics)\n"
     + BASE(HK) + TWO4 + "run 100\npair_coeff * * " + hk(9000) + "\nminimize 1e-8 1e-8 10 100\n", g=1)
L("L73_trailing_property_change", "# LIGGGHTS run 1000 at e table E3, then coefficientRestitution 0.3 for all after the last run: no step uses it\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n")
L("L74_trailing_timestep", "# LIGGGHTS run 1000 at 1e-5, then timestep 1e-4 after the last run\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "timestep 1e-4\n")
L("L75_trailing_set_density_stiffness", "# LIGGGHTS hooke/stiffness run, then set type 2 density 7800 after the last run\n"
  + lhead() + MAT3 + LST + LWST + ATOMS + RUN + "set type 2 density 7800\n")
L("L76_trailing_run0_after_change", "# LIGGGHTS run 1000, then e 0.3 and a run 0 (no step)\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 0\n")


# ================================================================ ninth batch: commands of run ... every the audit may not refuse
deck("e15_run_every_timestep_coarser", "# run 100 every 100 \"timestep 2e-4\", then run 100: the last run at dt 2e-4 (2-5 steps per contact)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"timestep 2e-4\"\nrun 100\n", g=1)
deck("e16_run_every_unfix_floor_then_floor2", "# run 100 every 100 \"unfix floor\", then fix floor2 (kn 9000, same plane) and run 100: the last run has floor2 only\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix floor\"\nfix floor2 all wall/gran granular " + hk(9000) + " zplane 0 NULL\nrun 100\n", g=1)
deck("e18_run_every_delete_type2", "# run 100 every 100 \"delete_atoms group t2\" (group of type 2), then run 100: no type 2 sphere left\n"
     + BASE(HK) + TWO4 + "group t2 type 2\nrun 100 every 100 \"delete_atoms group t2\"\nrun 100\n", g=1)
deck("e19_run_every_if_pair_coeff", "# run 100 every 100 \"if '1 > 0' then 'pair_coeff * * hooke 9000 ...'\", then run 100 at kn 9000\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"if '1 > 0' then 'pair_coeff * * " + hk(9000) + "'\"\nrun 100\n", g=1)
deck("e20_run_every_unfix_grav", "# run 100 every 100 \"unfix grav\", then run 100 without gravity (the audit's gravity notes are for run 1)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix grav\"\nrun 100\n", g=1)
deck("e21_run_every_unfix_freeze", "# type 2 frozen by fix fz; run 100 every 100 \"unfix fz\", then run 100 with type 2 free (1 2 eps is the contact's own)\n"
     + BASE(HK) + TWO + "group t2 type 2\nfix fz t2 freeze\nrun 100 every 100 \"unfix fz\"\nrun 100\n", g=1)
L("L77_run_every_if_property", "# LIGGGHTS run 500 every 500 \"if '1 > 0' then 'fix m3 ... 0.3'\", then run 500 at e 0.3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"if '1 > 0' then 'fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3'\"\nrun 500\n")
L("L78_run_every_unfix_wall_refix_other", "# LIGGGHTS run 500 every 500 \"unfix wprim\", then a wall wp2 of type 2 and run 500: the last run has wp2 only\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"unfix wprim\"\nfix wp2 all wall/gran model hertz tangential history primitive type 2 zplane 0.0\nrun 500\n")


# ================================================================ tenth batch: more commands of run ... every
deck("e22_run_every_next_index", "# variable k index 2000 9000; run 100 every 100 \"next k\"; pair_coeff kn $k; run 100: LAMMPS uses kn 9000\n"
     + BASE(HK) + TWO4 + "variable k index 2000 9000\nrun 100 every 100 \"next k\"\npair_coeff * * hooke $k 3000 " + K + "\nprint \"PROBE k $k\"\nrun 100\n", g=1)
deck("e23_run_every_group_grows_wall", "# wall acts on group lows (type 2); run 100 every 100 \"group lows type 1\" adds type 1: in run 2 type 1 meets the wall too\n"
     + head() + G1(HK) + GRAV + TAIL + TWO4 + "group lows type 2\nfix floor lows wall/gran granular " + hk(5000) + " zplane 0 NULL\nrun 100 every 100 \"group lows type 1\"\nrun 100\n", g=1)
deck("e24_run_every_unfix_integ_only", "# run 100 every 100 \"unfix integ\", then run 100: nothing is integrated in run 2 (no sphere moves)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"unfix integ\"\nrun 100\n", g=1)
deck("e25_run_every_next_file_variable", "# variable k file kn.txt (2000 then 9000); run 100 every 100 \"next k\"; pair_coeff kn ${k}; run 100: kn 9000\n"
     + BASE(HK) + TWO4 + "variable k file kn.txt\nrun 100 every 100 \"next k\"\npair_coeff * * hooke ${k} 3000 " + K + "\nrun 100\n", g=1, data={"kn.txt": "2000\n9000\n"})
L("L79_run_every_next_index_e", "# LIGGGHTS variable e index 0.9 0.3; run 500 every 500 \"next e\"; fix m3 with ${e}; run 500: LIGGGHTS uses e 0.3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "variable e index 0.9 0.3\nrun 500 every 500 \"next e\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nprint \"PROBE e ${e}\"\nrun 500\n")
deck("e26_run_every_next_loop_variable_timestep", "# variable d index 1e-5 2e-4; run 100 every 100 \"next d\"; timestep $d; run 100: the last run at 2e-4\n"
     + BASE(HK) + TWO4 + "variable d index 1e-5 2e-4\nrun 100 every 100 \"next d\"\ntimestep $d\nrun 100\n", g=1)


# ================================================================ eleventh batch: quit, files written by the deck and read back
deck("z09_trailing_unknown_command", "# run 100 then an unknown command after the last run: LAMMPS stops with an error after making its run\n"
     + BASE(HK) + TWO4 + "run 100\nbogus_command 1 2 3\n", g=1)
deck("z10_quit_before_change", "# run 100 at kn 2000, quit, then pair_coeff kn 9000 and run 100 that never happen\n"
     + BASE(HK) + TWO4 + "run 100\nquit\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("z11_if_quit_before_change", "# if \"1 > 0\" then quit after run 100: the kn 9000 stage never happens\n"
     + BASE(HK) + TWO4 + "run 100\nif \"1 > 0\" then quit\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("z12_print_file_then_include", "# print writes gen.in (kn 9000) with the file keyword, include gen.in: a stale gen.in (kn 2500) sits in the folder\n"
     + head() + "pair_style granular\nprint \"pair_coeff * * " + hk(9000) + "\" file gen.in\ninclude gen.in\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"gen.in": "pair_coeff * * " + hk(2500) + "\n"})
deck("z13_shell_echo_then_include", "# shell writes gen.in (kn 9000), include gen.in: a stale gen.in (kn 2500) sits in the folder\n"
     + head() + "pair_style granular\nshell echo \"pair_coeff * * " + hk(9000) + "\" > gen.in\ninclude gen.in\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"gen.in": "pair_coeff * * " + hk(2500) + "\n"})
deck("z14_print_append_then_include", "# print ... append gen.in adds a pair_coeff kn 9000 after the stale kn 2500 line: the include ends at kn 9000\n"
     + head() + "pair_style granular\nprint \"pair_coeff * * " + hk(9000) + "\" append gen.in\ninclude gen.in\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"gen.in": "pair_coeff * * " + hk(2500) + "\n"})
deck("z15_print_file_no_stale", "# print writes gen.in (kn 9000), include gen.in, no gen.in in the folder beforehand\n"
     + head() + "pair_style granular\nprint \"pair_coeff * * " + hk(9000) + "\" file gen.in\ninclude gen.in\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("z16_variable_file_written_by_print", "# print writes kn.txt (9000), variable k file kn.txt reads it: a stale kn.txt (2500) sits in the folder\n"
     + head() + "print \"9000\" file kn.txt\nvariable k file kn.txt\npair_style granular\npair_coeff * * hooke ${k} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"kn.txt": "2500\n"})
L("L80_liggghts_print_file_include", "# LIGGGHTS print writes e.in (e 0.3 for all) with file, include e.in: a stale e.in (e 0.9) sits in the folder\n"
  + lhead() + MAT3 + "print \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\" file e.in\ninclude e.in\n" + HERTZ + WALL3 + ATOMS + RUN,
  data={"e.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n"})
L("L81_liggghts_quit", "# LIGGGHTS run 1000, quit, then e 0.3 and run 500 that never happen (if LIGGGHTS knows quit)\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "quit\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 500\n")
L("L82_liggghts_fix_adapt_diameter", "# LIGGGHTS fix adapt atom diameter to 6 mm (reset no) in run 1, unfix, run 2 - hooke/stiffness (mass by its density)\n"
  + lhead() + MAT3 + LST + LWST + ATOMS.replace("0.006 density", "0.004 density") + LRUN + "variable dd equal 0.006\nfix ad all adapt 1 atom diameter v_dd reset no\nrun 500\nunfix ad\nrun 500\n")


# ================================================================ twelfth batch: files written during runs and read after them
deck("z17_fix_print_file_read_after_run", "# fix print writes kn.txt (9000) during run 1; variable k file kn.txt after it; pair_coeff ${k}; run 2: kn 9000. A stale kn.txt (2500) sits in the folder\n"
     + BASE(HK) + TWO4 + "fix pr all print 50 \"9000\" file kn.txt screen no\nrun 100\nunfix pr\nvariable k file kn.txt\npair_coeff * * hooke ${k} 3000 " + K + "\nprint \"PROBE k ${k}\"\nrun 100\n", g=1,
     data={"kn.txt": "2500\n"})
deck("z18_fix_ave_time_file_include", "# fix print writes a pair_coeff line into gen.in during run 1; include gen.in after it; stale gen.in (kn 2500) in the folder\n"
     + BASE(HK) + TWO4 + "fix pr all print 50 \"pair_coeff * * " + hk(9000) + "\" file gen.in screen no title \"# generated\"\nrun 100\nunfix pr\ninclude gen.in\nrun 100\n", g=1,
     data={"gen.in": "pair_coeff * * " + hk(2500) + "\n"})
L("L83_liggghts_fix_print_file_include", "# LIGGGHTS fix print writes e.in (e 0.3) during run 1; include e.in after it; stale e.in (e 0.9) in the folder\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "fix pr all print 500 \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\" file e.in screen no title \"# generated\"\nrun 1000\nunfix pr\ninclude e.in\nrun 500\n",
  data={"e.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n"})


# ================================================================ thirteenth batch: LIGGGHTS quit and clear
L("L84_liggghts_if_quit", "# LIGGGHTS run 1000, if \"1 > 0\" then quit, then e 0.3 and run 500 that never happen\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "if \"1 > 0\" then quit\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 500\n")
L("L85_liggghts_quit_in_include", "# LIGGGHTS run 1000, include in.stop (quit), then e 0.3 and run 500 that never happen\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "include in.stop\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 500\n",
  data={"in.stop": "quit\n"})
L("L86_liggghts_quit_minimal", "# minimal: LIGGGHTS run 1000 at e 0.5 (one type), quit, e 0.3 and run 1000 never happen\n"
  + lhead(nt=1) + "fix m1 all property/global youngsModulus peratomtype 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3\n"
  "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5\nfix m7 all property/global coefficientFriction peratomtypepair 1 0.5\n" + HERTZ
  + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + RUN
  + "quit\nfix m3 all property/global coefficientRestitution peratomtypepair 1 0.3\nrun 1000\n")
L("L87_liggghts_clear_second_box", "# LIGGGHTS clear between two simulations: the second (e 0.3 for all) is what runs last\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "clear\n" + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n" + HERTZ + WALL3 + ATOMS + RUN)
deck("z19_quit_in_include", "# LAMMPS run 100, include in.stop (quit), then kn 9000 and run 100 that never happen\n"
     + BASE(HK) + TWO4 + "run 100\ninclude in.stop\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1, data={"in.stop": "quit\n"})


# ================================================================ fourteenth batch: duplicate labels, LIGGGHTS units lj default
deck("z21_duplicate_label_first_wins", "# two 'label target': jump SELF target goes to the first in the file (LAMMPS scans from the top): kn 9000, not the 3000 after the jump\n"
     + head() + G1(HK) + GRAV + TAIL + TWO + "variable c equal 0\nlabel target\nvariable c equal $(v_c+1)\nif \"${c} > 1\" then \"jump SELF done\"\npair_coeff * * " + hk(9000)
     + "\njump SELF target\nlabel target\npair_coeff * * " + hk(3000) + "\nlabel done\nprint \"PROBE c ${c}\"\nrun 100\n", g=1)
L("L88_liggghts_duplicate_label", "# LIGGGHTS: two 'label target', jump SELF target: the first in the file (e 0.3), not the second (e 0.9)\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "variable c equal 0\nlabel target\nvariable c equal ${c}+1\nif \"${c} > 1\" then \"jump SELF done\"\n"
  "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\njump SELF target\nlabel target\n"
  "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\nlabel done\nprint \"PROBE c ${c}\"\n" + RUN)
L("L89_liggghts_no_units_lj", "# LIGGGHTS deck without a units command: units lj (default), dt default 0.005? hertz in lj numbers\n"
  + lhead().replace("units si\n", "").replace("-0.05 0.05 -0.05 0.05 -0.01 0.15", "-50 50 -50 50 -10 150").replace("neighbor 0.002 bin", "neighbor 0.2 bin")
  + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
  "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ
  + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\ncreate_atoms 1 single 10 0 10 units box\ncreate_atoms 2 single -10 0 10 units box\n"
  "set type 1 diameter 4 density 2.5\nset type 2 diameter 6 density 1.5\nfix gravi all gravity 1 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n", g="0.1 1")


# ================================================================ fifteenth batch: shell cd changes where later files are read
deck("z22_shell_cd_then_include", "# shell cd sub, then include in.x: the engine reads sub/in.x (kn 9000), not ./in.x (kn 2500)\n"
     + head() + "pair_style granular\nshell cd sub\ninclude in.x\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"in.x": "pair_coeff * * " + hk(2500) + "\n", "sub/in.x": "pair_coeff * * " + hk(9000) + "\n"})
deck("z23_shell_cd_then_read_data", "# shell cd sub, then read_data spheres.data: the engine reads sub/spheres.data (6 mm spheres), not ./spheres.data (4 mm)\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nshell cd sub\nread_data spheres.data\n" + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"spheres.data": "spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.005 0.005 0.01\n2 2 0.004 2500 0.015 0.005 0.01\n",
           "sub/spheres.data": "spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.006 2500 0.005 0.005 0.01\n2 2 0.006 2500 0.015 0.005 0.01\n"})
L("L90_liggghts_shell_cd_then_include", "# LIGGGHTS shell cd sub, then include e.in: the engine reads sub/e.in (e 0.3), not ./e.in (e 0.9)\n"
  + lhead() + MAT3 + "shell cd sub\ninclude e.in\n" + HERTZ + WALL3 + ATOMS + RUN,
  data={"e.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9 0.9\n",
        "sub/e.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n"})
deck("z24_variable_file_after_shell_cd", "# shell cd sub, variable k file kn.txt: sub/kn.txt (9000), not ./kn.txt (2500)\n"
     + head() + "shell cd sub\nvariable k file kn.txt\npair_style granular\npair_coeff * * hooke ${k} 3000 " + K + "\n" + GRAV + TAIL + TWO + "run 100\n", g=1,
     data={"kn.txt": "2500\n", "sub/kn.txt": "9000\n"})


# ================================================================ sixteenth batch: run ... every against LIGGGHTS insertions
L("L91_run_every_reset_timestep_insert_start", "# insert start 1500; run 1000 every 500 \"reset_timestep 0\" then run 1000: steps restart at 0, 1500 is never reached: no type 2\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 1500") + LRUN + "run 1000 every 500 \"reset_timestep 0\"\nrun 1000\n")
L("L92_run_every_unfix_insert_before_start", "# insert start 700; run 1000 every 500 \"unfix ins\": the fix is gone at step 500, before its start: no type 2\n"
  + LB() + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n" + T2 + INSREG
  + PACK.replace("insert_every once", "insert_every 10000 start 700") + LRUN + "run 1000 every 500 \"unfix ins\"\nrun 500\n")
deck("i16_run_every_unfix_pour_first_chunk", "# fix pour (type 2, 5 mm) unfixed by run 100 every 100 \"unfix p\" after the first chunk; pour inserts on its first step anyway\n"
     + POURBOX + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nfix p all pour 10 2 4767 region top diam one 0.005 dens 2500 2500\nrun 200 every 100 \"unfix p\"\n", g=1)


# ================================================================ seventeenth batch: quit and jump inside run ... every
deck("e27_run_every_quit", "# run 100 every 100 \"quit\": LAMMPS ends the deck after the run; the kn 9000 stage after it never runs\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"quit\"\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("e28_run_every_jump", "# run 100 every 100 \"jump SELF end\": the deck continues at label end (skipping the kn 9000 line)\n"
     + BASE(HK) + TWO4 + "run 100 every 100 \"jump SELF end\"\npair_coeff * * " + hk(9000) + "\nlabel end\nrun 100\n", g=1)
L("L93_run_every_quit", "# LIGGGHTS run 500 every 500 \"quit\": the deck ends; e 0.3 and run 500 after it never run\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "run 500 every 500 \"quit\"\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\nrun 500\n")
L("L94_liggghts_quit_in_loop_end", "# LIGGGHTS loop of two runs with e from an index variable, quit after the first pass (if on the loop counter)\n"
  + lhead() + MAT3 + HERTZ + WALL3 + ATOMS + LRUN + "variable e index 0.9 0.3\nvariable n loop 2\nlabel lp\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 300\n"
  "if \"${n} == 1\" then \"jump SELF stop\"\nnext e\nnext n\njump SELF lp\nlabel stop\nquit\n")


# ================================================================ eighteenth batch: runs inside if, halt, timer timeout
deck("z25_run_inside_if", "# if \"1 > 0\" then \"pair_coeff * * hooke 9000 ...\" \"run 100\": a stage at kn 9000 made inside the if, after run 100 at kn 2000\n"
     + BASE(HK) + TWO4 + "run 100\nif \"1 > 0\" then \"pair_coeff * * " + hk(9000) + "\" \"run 100\"\n", g=1)
deck("z26_fix_halt_error_hard", "# fix halt at step 1 with error hard ends LAMMPS in run 1: the kn 9000 stage never runs (engine exits with an error)\n"
     + BASE(HK) + TWO4 + "variable one equal 1\nfix h all halt 1 v_one == 1 error hard\nrun 100\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("z27_fix_halt_error_continue", "# fix halt error continue: run 1 stops at step 1, the deck goes on: the kn 9000 stage runs\n"
     + BASE(HK) + TWO4 + "variable one equal 1\nfix h all halt 1 v_one == 1 error continue\nrun 100\nunfix h\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("z28_timer_timeout_zero", "# timer timeout 0 (no time left): LAMMPS skips the runs' steps; every run makes 0 steps? (engine says)\n"
     + BASE(HK) + TWO4 + "timer timeout 0\nrun 100\npair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
L("L95_liggghts_run_inside_if", "# LIGGGHTS if \"1 > 0\" then \"fix m3 ... 0.3\" \"run 500\": a stage at e 0.3 made inside the if\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "if \"1 > 0\" then \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\" \"run 500\"\n")


# ================================================================ nineteenth batch: LIGGGHTS if with contact commands
L("L96_liggghts_if_fix_property", "# LIGGGHTS if \"1 > 0\" then \"fix m3 ... 0.3\" before the only run: e 0.3 for all\n"
  + lhead() + MAT3 + E3 + "if \"1 > 0\" then \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\"\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L97_liggghts_if_else_run", "# LIGGGHTS if/else choosing which run length to make (run 500 or run 800): one stage, e table E3\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + LRUN + "variable a equal 1\nif \"${a} > 0\" then \"run 500\" else \"run 800\"\n")
deck("z29_if_else_run_lammps", "# LAMMPS if/else choosing which run length to make: one stage kn 2000\n"
     + BASE(HK) + TWO4 + "variable a equal 1\nif \"${a} > 0\" then \"run 100\" else \"run 200\"\n", g=1)


# ================================================================ twentieth batch: partition (skipped by the audit) runs its command on partition 1
deck("z30_partition_yes_1_pair_coeff", "# partition yes 1 pair_coeff * * hooke 9000: with one partition LAMMPS runs it (kn 9000)\n"
     + BASE(HK) + TWO4 + "partition yes 1 pair_coeff * * " + hk(9000) + "\nrun 100\n", g=1)
deck("z31_partition_no_2_set_density", "# partition no 2 set type 2 density 7800: partition 1 runs it (steel type 2)\n"
     + BASE(HK) + TWO4 + "partition no 2 set type 2 density 7800\nrun 100\n", g=1)
deck("z32_partition_yes_1_timestep", "# partition yes 1 timestep 2e-4: the run at 2e-4\n"
     + BASE(HK) + TWO4 + "partition yes 1 timestep 2e-4\nrun 100\n", g=1)
L("L98_liggghts_partition_yes_1_property", "# LIGGGHTS partition yes 1 fix m3 ... e 0.3 (one partition: it runs)\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "partition yes 1 fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n" + RUN)


# ================================================================ twenty-first batch: skipped commands that read or write what later lines use
deck("z33_write_data_clear_read_data", "# set sizes 6 mm, write_data state.data, clear, read_data state.data: the engine reads 6 mm spheres; a stale state.data (4 mm) sits in the folder\n"
     + BASE(HK) + TWO4 + "set type * diameter 0.006 density 2500\nwrite_data state.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data state.data\n"
     + G1(HK) + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"state.data": "stale\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.02 0.01\n2 2 0.004 2500 0.01 0.01 0.01\n"})
deck("z34_ndx2group_then_set", "# group g2 empty, ndx2group groups.ndx g2 (atoms 2 and 3), set group g2 type 2 diameter 0.006: two type-2 6 mm spheres\n"
     + BASE(HK) + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 1 single 0.015 0.005 0.01\ncreate_atoms 1 single 0.025 0.025 0.01\nset type * diameter 0.004 density 2500\n"
     + "group g2 empty\nndx2group groups.ndx g2\nset group g2 type 2\nset group g2 diameter 0.006 density 2500\nrun 100\n", g=1,
     data={"groups.ndx": "[ g2 ]\n2 3\n"})
deck("z35_ndx2group_wall_group", "# the floor acts on group low, filled by ndx2group (atom 1 only): type 2 never meets the floor\n"
     + head() + G1(HK) + GRAV + TAIL + TWO4 + "group low empty\nndx2group groups.ndx low\nfix floor low wall/gran granular " + hk(5000) + " zplane 0 NULL\nrun 100\n", g=1,
     data={"groups.ndx": "[ low ]\n1\n"})

MAPBASE = lambda model: head(extra="atom_modify map array\n") + G1(model) + GRAV + f"fix floor all wall/gran granular {model} zplane 0 NULL\n" + TAIL
deck("z36_ndx2group_then_set_mapped", "# atom map on; group g2 empty, ndx2group groups.ndx g2 (atoms 2 and 3), set group g2 type 2, diameter 6 mm: two type-2 6 mm spheres\n"
     + MAPBASE(HK) + "create_atoms 1 single 0.005 0.005 0.01\ncreate_atoms 1 single 0.015 0.005 0.01\ncreate_atoms 1 single 0.025 0.025 0.01\nset type * diameter 0.004 density 2500\n"
     + "group g2 empty\nndx2group groups.ndx g2\nset group g2 type 2\nset group g2 diameter 0.006 density 2500\nrun 100\n", g=1,
     data={"groups.ndx": "[ g2 ]\n2 3\n"})
deck("z37_ndx2group_wall_group_mapped", "# atom map on; the floor acts on group low, filled by ndx2group (atom 1 only): type 2 never meets the floor\n"
     + head(extra="atom_modify map array\n") + G1(HK) + GRAV + TAIL + TWO4 + "group low empty\nndx2group groups.ndx low\nfix floor low wall/gran granular " + hk(5000) + " zplane 0 NULL\nrun 100\n", g=1,
     data={"groups.ndx": "[ low ]\n1\n"})

deck("z38_write_coeff_include_back", "# write_coeff coeffs.in (kn 2000), pair_coeff kn 9000, include coeffs.in: kn 2000 again; a stale coeffs.in (kn 5000) in the folder\n"
     + BASE(HK) + TWO4 + "write_coeff coeffs.in\npair_coeff * * " + hk(9000) + "\ninclude coeffs.in\nrun 100\n", g=1,
     data={"coeffs.in": "pair_coeff * * " + hk(5000) + "\n"})
deck("z39_fix_ttm_drag", "# fix ttm (two-temperature model: a Langevin-like drag gamma_p and a random force on every atom) beside the contact\n"
     + BASE(HK) + TWO4 + "fix tt all ttm 48279 1.0 1.0 1.0 1e-3 0.0 0.0 2 2 2 set 1e-30\nrun 100\n", g=1)

deck("z40_fix_ttm_drag_periodic", "# periodic box, fix ttm (Langevin-like drag gamma_p 1e-3 and a random force of T 1e-30 on every atom) beside the contact\n"
     + head(bnd="p p p") + G1(HK) + TAIL + TWO4 + "fix tt all ttm 48279 1.0 1.0 1.0 1e-3 0.0 0.0 2 2 2 set 1e-30\nrun 100\n", g=1)

deck("z41_fix_tmd_pull", "# fix tmd (targeted MD: each step constrains the atoms toward target positions) beside the contact (LAMMPS runs it; it changes the collision)\n"
     + head(bnd="p p p", extra="atom_modify map array\n") + G1(HK) + TAIL + "create_atoms 1 single 0.018 0.02 0.05\ncreate_atoms 1 single 0.022 0.02 0.05\nset type * diameter 0.004 density 2500\n"
     + "fix tm all tmd 0.0 target.txt 0\nrun 100\n", g=1,
     data={"target.txt": "# target\nxlo xhi 0 0.04\nylo yhi 0 0.04\nzlo zhi 0 0.1\n1 0.010 0.02 0.05\n2 0.030 0.02 0.05\n"})

L("L99_liggghts_if_set_density", "# LIGGGHTS if \"1 > 0\" then \"set type 2 density 7800\" before the only run - hooke/stiffness (steel type 2)\n"
  + lhead() + MAT3 + LST + LWST + ATOMS + "if \"1 > 0\" then \"set type 2 density 7800\"\n" + RUN)
L("L100_liggghts_if_create_atoms", "# LIGGGHTS if \"1 > 0\" then \"create_atoms 2 single ...\" \"set type 2 ...\": type 2 exists - hooke/stiffness\n"
  + lhead() + MAT3 + LST + LWST + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
  + "if \"1 > 0\" then \"create_atoms 2 single -0.01 0 0.01 units box\" \"set type 2 diameter 0.006 density 1500\"\n" + RUN)
deck("z42_if_set_density", "# LAMMPS if \"1 > 0\" then \"set type 2 density 7800\": steel type 2\n"
     + BASE(HK) + TWO4 + "if \"1 > 0\" then \"set type 2 density 7800\"\nrun 100\n", g=1)


def write(name):
    text, g, files, data, lig = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, deck_file=True, liggghts=lig, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
