"""Field round 31 (spot check of main's answers to round 30's SW-A..SW-F): write decks/NAME/in.deck with round 30's
helpers (make_decks30.py: kn 2000, dt 1e-6, the live pair 4 mm type 1 / 6 mm type 2 meeting at 1 m/s), refereed by
live31.py (the deck run as written). Prefixes: X growth by atoms made again at a deleted ID, K atom_modify id no,
A fix adapt (include in a loop, two groups, shrink then grow), L LIGGGHTS exclusion + type/fraction, Q quoted names
with spaces (read_data add, molecule, variable file), T the time step note with a heavily damped pair.
usage: python make_decks31.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field30"))
import make_decks30 as p  # noqa: E402

m, q = p.m, p.q
m.DECKS.clear(); p.LIVE.clear(); p.EXTRA.clear()
m.D = os.path.join(HERE, "decks")
E, Ld, vic, extra, BL, B3, HK, hk = p.E, p.Ld, p.vic, p.extra, p.BL, p.B3, p.HK, p.hk
g11, g41 = p.g11, p.g41
V26 = p.V26

# lv2 (ID 2) deleted and made again at its place and speed; with no other atom above ID 1 the new atom takes ID 2 again
REMAKE = lambda d, cmp="", grp="group lv2 id 2\n", idn=2: (
    "variable xx equal $(x[2])\nvariable zz equal $(z[2])\nvariable vz equal $(vz[2])\n"
    f"delete_atoms group lv2{cmp}\ncreate_atoms 2 single ${{xx}} 0.02 ${{zz}} units box\n"
    f"set atom {idn} diameter {d} density 2500\n" + grp + f"velocity lv2 set -0.2285714286 0 ${{vz}} units box\n")

# ------------------------------------------------------------ X: ID reuse before run pre no (x[2] needs an atom map)
MAP = BL().replace("atom_style sphere 1\n", "atom_style sphere 1\natom_modify map array\n")
E("X01_delete_remake_id2_bigger_pre_no", "run 1000; delete lv2 (ID 2), create it again (ID 2 again) 12 mm; run 3000 pre no",
  "run 1000\n" + REMAKE(0.012) + "run 3000 pre no\n", gap=g41, sep=0.008, pre=MAP)
E("X02_delete_remake_id2_bigger_control", "X01 without pre no", "run 1000\n" + REMAKE(0.012) + "run 3000\n", gap=g41, sep=0.008, pre=MAP)
E("X03_delete_remake_id2_same_pre_no", "X01 with the same 6 mm (no growth)", "run 1000\n" + REMAKE(0.006) + "run 3000 pre no\n", gap=p.g11, pre=MAP)
E("X04_delete_remake_compress_victims_pre_no", "victims 12, 6 mm (IDs 3, 4); delete lv2: compress renumbers them 2, 3; the new 12 mm lv2 takes ID 4; run 3000 pre no",
  V26 + "run 1000\n" + REMAKE(0.012, grp="group lv2 id 4\n", idn=4) + "run 3000 pre no\n", gap=g41, sep=0.008, pre=MAP)
E("X05_delete_remake_nocompress_victims_pre_no", "X04 with compress no (the new lv2 takes ID 5)",
  V26 + "run 1000\n" + REMAKE(0.012, cmp=" compress no", grp="group lv2 id 5\n", idn=5) + "run 3000 pre no\n", gap=g41, sep=0.008, pre=MAP)
E("X06_delete_victim_remake_id_pre_no", "victim ID 3 (6 mm, type 2) deleted, a 12 mm type 2 made far away takes ID 3; lv2 grows to 12 mm; run 3000 pre no",
  vic(2, 0.006, 0.006) + "group v4 id 4\nrun 1000\ndelete_atoms group v4\ncreate_atoms 2 single 0.03 0.01 0.012\nset atom 4 diameter 0.012 density 2500\nset group lv2 diameter 0.012\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP)
RDA = ("# lv2 again\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
       "2 2 0.012 2500 0.024821 0.02 0.049995095\n\nVelocities\n\n2 -0.2285714286 0 -0.00981 0 0 0\n")
E("X07_delete_read_data_add_merge_id2_pre_no", 'run 1000; delete lv2; read_data "new  lv2.data" add merge (ID 2, 12 mm, 0.1 mm from lv1); run 3000 pre no',
  "run 1000\ndelete_atoms group lv2\nread_data \"new  lv2.data\" add merge\ngroup lv2 id 2\nrun 3000 pre no\n", gap=g41, sep=0.008, data={"new  lv2.data": RDA}, pre=MAP)
E("X08_delete_read_data_add_merge_id2_control", "X07 without pre no", "run 1000\ndelete_atoms group lv2\nread_data \"new  lv2.data\" add merge\ngroup lv2 id 2\nrun 3000\n",
  gap=g41, sep=0.008, data={"new  lv2.data": RDA}, pre=MAP)
E("X09_remake_in_include_tab_pre_no", "X01 with the delete/create in include \"a\\tb.in\" (a tab)", "run 1000\ninclude \"a\tb.in\"\nrun 3000 pre no\n", gap=g41, sep=0.008,
  data={"a\tb.in": REMAKE(0.012)}, pre=MAP)
E("X10_remake_twice_shrink_grow_pre_no", "lv2 remade 12 mm, run 100 pre no, remade 6 mm, remade 12 mm again; run 3000 pre no",
  "run 1000\n" + REMAKE(0.012) + "run 100 pre no\n" + REMAKE(0.006) + REMAKE(0.012) + "run 3000 pre no\n", gap=g41 + 0.1e-3, sep=0.008, pre=MAP)

# ------------------------------------------------------------ K: atom_modify id no (no IDs)
KP = ("create_atoms 1 single 0.01595 0.02 0.05\ncreate_atoms 2 single 0.02505 0.02 0.05\n"
      "region r1 block 0.0 0.019 0.0 0.04 0.0 0.1 units box\nregion r2 block 0.021 0.04 0.0 0.04 0.0 0.1 units box\n"
      "group lv1 region r1\ngroup lv2 region r2\nset group lv1 diameter 0.004 density 2500\nset group lv2 diameter 0.006 density 2500\n"
      "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
KB = lambda: BL().replace("atom_style sphere 1\n", "atom_style sphere 1\natom_modify id no\n")
E("K01_id_no_plain", "atom_modify id no; the live pair by regions; run 5000", "run 5000\n", pair=KP, pre=KB(), gap=2.1e-3)
E("K02_id_no_grow_pre_no", "atom_modify id no; run 1000; set group lv2 diameter 0.012; run 3000 pre no", "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", pair=KP, pre=KB(), sep=0.008)
E("K03_id_no_victims_grow_pre_no", "K02 with type 2 victims of 12 and 6 mm (by region)",
  "create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\nregion rv1 sphere 0.01 0.01 0.012 0.001 units box\nregion rv2 sphere 0.03 0.03 0.012 0.001 units box\n"
  "set region rv1 diameter 0.012 density 2500\nset region rv2 diameter 0.006 density 2500\nrun 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", pair=KP, pre=KB(), sep=0.008)

# ------------------------------------------------------------ A: fix adapt of atom diameter
DD = "variable dd equal 0.012\n"
AD = "fix ad lv2 adapt 1 atom diameter v_dd reset no\n"
E("A01_adapt_include_loop_run0", "loop 2: include ad.in (fix adapt lv2 12 mm); run 0; then run 3000", DD + "variable i loop 2\nlabel l\ninclude ad.in\nrun 0\nnext i\njump SELF l\nrun 3000\n",
  gap=g41, sep=0.008, data={"ad.in": AD})
E("A02_adapt_include_loop_run0_pre_no", "A01 with run 1000 first and run 3000 pre no last", DD + "run 1000\nvariable i loop 2\nlabel l\ninclude ad.in\nrun 0\nnext i\njump SELF l\nrun 3000 pre no\n",
  gap=g41, sep=0.008, data={"ad.in": AD})
E("A03_adapt_two_groups", "fix adapt lv1 to 8 mm and lv2 to 12 mm from the first run", "variable d1 equal 0.008\n" + DD + "fix a1 lv1 adapt 1 atom diameter v_d1 reset no\n" + AD + "run 4000\n",
  gap=g41 + 2e-3, sep=0.010)
E("A04_adapt_two_groups_after_run_unfix", "run 1000; fix adapt lv1 8 mm, lv2 12 mm; run 0; unfix both; run 3000 (sized before the lists)",
  "variable d1 equal 0.008\n" + DD + "run 1000\nfix a1 lv1 adapt 1 atom diameter v_d1 reset no\n" + AD + "run 0\nunfix a1\nunfix ad\nrun 3000\n", gap=g41 + 2e-3, sep=0.010)
E("A05_adapt_shrink_then_grow", "fix adapt lv2 v_dd: 12 mm in run 1000, dd 6 mm in run 1000, dd 12 mm in run 3000 (no unfix)",
  DD + AD + "run 1000\nvariable dd equal 0.006\nrun 1000\nvariable dd equal 0.012\nrun 4000\n", gap=g41 + 1e-3 + 3e-3, sep=0.008)
E("A06_adapt_shrink_then_grow_unfix", "A05 with unfix ad before the last run (sizes left 12 mm at its set-up? no: 6 mm)",
  DD + AD + "run 1000\nvariable dd equal 0.006\nrun 1000\nvariable dd equal 0.012\nrun 0\nunfix ad\nrun 3000\n", gap=g41 + 1e-3, sep=0.008)
E("A07_adapt_other_group_only", "fix adapt of a far victim (group v) 12 mm; the live pair 6 mm untouched; run 3000", vic(2, 0.006, 0.006) + "group v id 3\n" + DD +
  "fix ad v adapt 1 atom diameter v_dd reset no\nrun 3000\n", gap=2.1e-3)
E("A08_adapt_grown_group_by_create", "group g type 2 dynamic? no: static g type 2; fix adapt g 12 mm; lv2 created after as type 2 added to g by group g type 2 again; run 3000",
  "group g type 2\n" + DD + "fix ad g adapt 1 atom diameter v_dd reset no\nrun 0\n" + vic(2, 0.006, 0.006) + "group g type 2\nrun 3000\n", gap=g41, sep=0.008)

# ------------------------------------------------------------ L: LIGGGHTS exclusion + retype by type/fraction
Ld("L01_exclude_fraction_pre_no", "LIGGGHTS neigh_modify exclude type 1 2; run 1000; set group lv2 type/fraction 3 1.0 7; run 3000 pre no (e 1 3 0.7)",
   "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type/fraction 3 1.0 7\nrun 3000 pre no\n", gap=g11, pair="types 1 3")
Ld("L02_exclude_fraction_control", "L01 without pre no", "neigh_modify exclude type 1 2\nrun 1000\nset group lv2 type/fraction 3 1.0 7\nrun 3000\n", gap=g11, pair="types 1 3")
Ld("L03_exclude_group_retype_pre_no", "LIGGGHTS neigh_modify exclude group lv1 lv2? no: exclude type 1 3; set type 2 -> 3 by fraction 0.0 (none); run 3000 pre no",
   "neigh_modify exclude type 1 3\nrun 1000\nset group lv2 type/fraction 3 0.0 7\nrun 3000 pre no\n", gap=g11)

# ------------------------------------------------------------ Q: quoted names with spaces
Q5 = p.P5() + "\n"
E("Q01_variable_file_two_spaces", 'variable k file "k  v.txt" (kn 5000); pair_coeff 1 2 hooke ${k}; "k v.txt" beside (8000)',
  'variable k file "k  v.txt"\npair_coeff 1 2 hooke ${k} 3000 ' + p.K + "\nrun 3000\n", gap=0.1e-3, data={"k  v.txt": "5000\n", "k v.txt": "8000\n"})
E("Q02_variable_file_grow_pre_no", 'variable d file "d  d.txt" (0.012); run 1000; set group lv2 diameter ${d}; run 3000 pre no',
  'variable d file "d  d.txt"\nrun 1000\nset group lv2 diameter ${d}\nrun 3000 pre no\n', gap=g41, sep=0.008, data={"d  d.txt": "0.012\n", "d d.txt": "0.006\n"})
MOL = "# big\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.012\n\nMasses\n\n1 0.0022619467\n"
E("Q03_molecule_two_spaces_victim_pre_no", 'molecule m "m  b.mol" (one 12 mm type 2); create_atoms 0 single far mol m; lv2 grows 12 mm; run 3000 pre no',
  'molecule m "m  b.mol"\ncreate_atoms 0 single 0.01 0.01 0.012 mol m 4711\nrun 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n', gap=g41, sep=0.008, data={"m  b.mol": MOL})
E("Q04_include_if_tab_grow_pre_no", 'if "1 > 0" then "include \'g\tg.in\'" (set lv2 12 mm); run 3000 pre no', 'run 1000\nif "1 > 0" then "include \'g\tg.in\'"\nrun 3000 pre no\n',
  gap=g41, sep=0.008, data={"g\tg.in": "set group lv2 diameter 0.012\n", "g g.in": "print none\n"})

# ------------------------------------------------------------ T: the time step note (heavily damped: damping 6000)
HD = "hooke 2000 6000 damping mass_velocity tangential linear_nohistory 1 0.3"
for nm, dt, gp in (("T01_60steps", 1.12e-5, 0.1e-3), ("T02_60steps_phase", 1.12e-5, 0.1057e-3), ("T03_300steps", 2.24e-6, 0.1e-3), ("T04_300steps_phase", 2.24e-6, 0.1013e-3),
                   ("T05_900steps", 7.5e-7, 0.1e-3), ("T06_1100steps", 6.1e-7, 0.1e-3), ("T07_150steps_phase", 4.5e-6, 0.1029e-3), ("T08_52steps", 1.29e-5, 0.1031e-3)):
    E(nm + "_damped", f"damping 6000 (eps ~0.13); timestep {dt:g} (~{nm.split('_')[1]} per contact); gap {gp:g}", f"timestep {dt:g}\nrun {int(2.5e-3 / dt)}\n", gap=gp, pre=BL(HD))

# ------------------------------------------------------------ Y (wave 2): X05's neighbours, a sphere made at a new ID before pre no
X5 = lambda make, grp="group lv2 id 5\n", idn=5, d=0.012, pre="": (V26 + pre + "run 1000\n" + "variable xx equal $(x[2])\nvariable zz equal $(z[2])\nvariable vz equal $(vz[2])\n"
    "delete_atoms group lv2 compress no\n" + make + (f"set atom {idn} diameter {d} density 2500\n" if d else "") + grp + "velocity lv2 set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n")
CA = "create_atoms 2 single ${xx} 0.02 ${zz} units box\n"
RAP = ("# new\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
       "1 2 0.012 2500 0.024821 0.02 0.049995095\n")
E("Y01_new_id_read_data_append_pre_no", 'X05 with read_data "n  a.data" add append (file ID 1 -> 5, 12 mm)', X5('read_data "n  a.data" add append\n', d=None),
  gap=g41, sep=0.008, pre=MAP, data={"n  a.data": RAP})
E("Y02_new_id_molecule_pre_no", 'X05 with molecule "m  b.mol" (12 mm type 2) made by create_atoms 0 single ... mol', X5('molecule m "m  b.mol"\ncreate_atoms 0 single ${xx} 0.02 ${zz} mol m 4711 units box\n', d=None),
  gap=g41, sep=0.008, pre=MAP, data={"m  b.mol": MOL})
E("Y03_new_id_same_size_6mm_pre_no", "X05 with the new sphere 6 mm (no growth: a new ID, the lists by index)", X5(CA, d=0.006), gap=p.g11, pre=MAP)
E("Y04_new_id_12mm_no_victims_pre_no", "X05 without victims (type 2 held only 6 mm: the new 12 mm is new to it); new ID 3", X5(CA, grp="group lv2 id 3\n", idn=3).replace(V26, ""), gap=g41, sep=0.008, pre=MAP)
E("Y05_new_id_12mm_control", "X05 without pre no", X5(CA).replace("run 3000 pre no", "run 3000"), gap=g41, sep=0.008, pre=MAP)
E("Y06_new_id_in_include_quoted_pre_no", 'X05 with the delete/create in include "x  y.in"', V26 + 'run 1000\ninclude "x  y.in"\nrun 3000 pre no\n', gap=g41, sep=0.008, pre=MAP,
  data={"x  y.in": X5(CA).replace(V26 + "run 1000\n", "").replace("run 3000 pre no\n", "")})
E("Y07_new_id_victims_12_12_pre_no", "X05 with both victims 12 mm (type 2 held 6 and 12 mm at set-up; after: 12 12 12)", X5(CA).replace(V26, vic(2, 0.012, 0.012)), gap=g41, sep=0.008, pre=MAP)
E("Y08_new_id_loop_pre_no", "X05 with the delete/create in a loop's second pass (run 500 twice)", V26 + 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "include mk.in"\nnext i\njump SELF l\nrun 3000 pre no\n',
  gap=g41, sep=0.008, pre=MAP, data={"mk.in": X5(CA).replace(V26 + "run 1000\n", "").replace("run 3000 pre no\n", "")})
E("Y09_new_id_type1_victim_pre_no", "type 1 holds a 12 mm victim; lv1 deleted (compress no), made again 4 mm at a new ID (type 1 radii 2 and 6 mm)",
  vic(1, 0.012, 0.004) + "run 1000\nvariable xx equal $(x[1])\nvariable zz equal $(z[1])\nvariable vz equal $(vz[1])\ndelete_atoms group lv1 compress no\ncreate_atoms 1 single ${xx} 0.02 ${zz} units box\n"
  "set atom 5 diameter 0.004 density 2500\ngroup lv1 id 5\nvelocity lv1 set 0.7714285714 0 ${vz} units box\nrun 3000 pre no\n", gap=p.g11, pre=MAP)

# ------------------------------------------------------------ Z (wave 3): the new-ID class's edges
E("Z01_new_id_run0_then_pre_no_control", "X05 with run 0 (a set-up) before run 3000 pre no", X5(CA).replace("run 3000 pre no", "run 0\nrun 3000 pre no"), gap=g41, sep=0.008, pre=MAP)
E("Z02_new_id_run10_pre_no_twice", "X05 with run 10 pre no before run 3000 pre no (stale over two runs)", X5(CA).replace("run 3000 pre no", "run 10 pre no\nrun 3000 pre no"), gap=g41 + 0.01e-3, sep=0.008, pre=MAP)
E("Z03_new_id_create_random_pre_no", "X05 by create_atoms 2 random 1 in a 0.02 mm cube at lv2's place (new ID 5)",
  X5("region nb block $(v_xx-1e-5) $(v_xx+1e-5) 0.01999 0.02001 $(v_zz-1e-5) $(v_zz+1e-5) units box\ncreate_atoms 2 random 1 4711 nb\n"), gap=g41, sep=0.008, pre=MAP)
E("Z04_new_id_delete_region_pre_no", "X05 with lv2 deleted by region (compress no)",
  X5(CA).replace("delete_atoms group lv2 compress no", "region dl sphere ${xx} 0.02 ${zz} 0.001 units box\ndelete_atoms region dl compress no"), gap=g41, sep=0.008, pre=MAP)
E("Z05_new_id_9mm_new_radius_pre_no", "X05 with the new sphere 9 mm (a radius type 2 never held: caught?)", X5(CA, d=0.009), gap=2.6e-3, sep=0.0065, pre=MAP)
E("Z06_new_id_density_pre_no", "X05 with the new sphere 12 mm density 7800 (heavier, same radius)", X5(CA).replace("set atom 5 diameter 0.012 density 2500", "set atom 5 diameter 0.012 density 7800"),
  gap=g41, sep=0.008, pre=MAP)

# ------------------------------------------------------------ K (wave 4): atom_modify id no with a sphere made again before pre no
KV = ("create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\nregion rv1 sphere 0.01 0.01 0.012 0.001 units box\nregion rv2 sphere 0.03 0.03 0.012 0.001 units box\n"
      "set region rv1 diameter 0.012 density 2500\nset region rv2 diameter 0.006 density 2500\n")
KR = lambda d: ("run 1000\nvariable xx equal $(xcm(lv2,x))\nvariable zz equal $(xcm(lv2,z))\nvariable vz equal $(vcm(lv2,z))\ndelete_atoms group lv2\n"
                "create_atoms 2 single ${xx} 0.02 ${zz} units box\nregion rn sphere ${xx} 0.02 ${zz} 0.0005 units box\ngroup lv2 region rn\n"
                f"set group lv2 diameter {d} density 2500\nvelocity lv2 set -0.2285714286 0 ${{vz}} units box\nrun 3000 pre no\n")
E("K04_id_no_remade_12mm_victims_pre_no", "atom_modify id no; victims 12, 6 mm; lv2 deleted and made again 12 mm; run 3000 pre no", KV + KR(0.012), pair=KP, pre=KB(), gap=g41, sep=0.008)
E("K05_id_no_remade_6mm_victims_pre_no", "K04 with the new sphere 6 mm (no growth)", KV + KR(0.006), pair=KP, pre=KB(), gap=g41)
E("K06_id_no_remade_12mm_control", "K04 without pre no", KV + KR(0.012).replace("run 3000 pre no", "run 3000"), pair=KP, pre=KB(), gap=g41, sep=0.008)

E("K07_id_no_moved_new_12mm_victims_pre_no", "atom_modify id no; victims 12, 6 mm; lv2 moved far (set x y) and stopped, a new 12 mm type 2 made at its place; run 3000 pre no",
  KV + KR(0.012).replace("delete_atoms group lv2\n", "set group lv2 x 0.035 y 0.035\nvelocity lv2 set 0 0 0 units box\ngroup lv2 clear\n"), pair=KP, pre=KB(), gap=g41, sep=0.008)
E("K08_id_no_moved_new_12mm_control", "K07 without pre no", KV + KR(0.012).replace("delete_atoms group lv2\n", "set group lv2 x 0.035 y 0.035\nvelocity lv2 set 0 0 0 units box\ngroup lv2 clear\n").replace("run 3000 pre no", "run 3000"),
  pair=KP, pre=KB(), gap=g41, sep=0.008)

# ------------------------------------------------------------ wave 5: SW-G with type 1, and with lists built every step
E("Y10_new_id_type1_12mm_victim_pre_no", "type 1 holds a 12 mm victim; lv1 deleted (compress no), made again 12 mm at a new ID (5); run 3000 pre no",
  vic(1, 0.012, 0.004) + "run 1000\nvariable xx equal $(x[1])\nvariable zz equal $(z[1])\nvariable vz equal $(vz[1])\ndelete_atoms group lv1 compress no\ncreate_atoms 1 single $(v_xx-0.004) 0.02 ${zz} units box\n"
  "set atom 5 diameter 0.012 density 2500\ngroup lv1 id 5\nvelocity lv1 set 0.7714285714 0 ${vz} units box\nrun 5000 pre no\n", gap=3.1e-3, sep=0.009, pre=MAP)
E("Y11_new_id_skin_big_pre_no", "X05 with neighbor 0.01 bin from the start", X5(CA), gap=g41, sep=0.008, pre=MAP + "neighbor 0.01 bin\n")
E("Y12_new_id_check_no_every1_pre_no", "X05 with neigh_modify every 1 delay 0 check no (lists built every step)", X5(CA), gap=g41, sep=0.008, pre=MAP + "neigh_modify every 1 delay 0 check no\n")


def write_all(names):
    m.write_live(names, p.LIVE, p.EXTRA)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")
