"""Field round 29: write the decks as decks/NAME/in.deck (G, LIVE, SEP, PAIR, ARGS, extra files, LIGGGHTS marker), with
round 27/28's helpers (base: kn 2000 everywhere, dt 1e-6; the LIVE pair: two spheres far above the floor approaching at
1 m/s, timed to meet in the run named in LIVE, refereed by live29.py running the deck as written).
Prefixes: Q run pre no after growth / coefficient / neighbor changes, N a granular cutoff's reach (nsq, boundaries,
change_box, read_data/read_restart boxes), R set type/fraction, type/ratio, type/subset after a run, V run-dependent
substitutions in commands other than outputs, I quoted include names, L LIGGGHTS.   usage: python make_decks29.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field28"))
import make_decks28 as r  # noqa: E402

m = r.m
m.DECKS.clear(); r.LIVE.clear(); r.EXTRA.clear()
m.D = os.path.join(HERE, "decks")
E, W, Ll, BL, lv, lvi, P5, P8, HK, K, hk, CU, HM = r.E, r.W, r.Ll, r.BL, r.lv, r.lvi, r.P5, r.P8, r.HK, r.K, r.hk, r.CU, r.HM
XA0, XA1, IFS, VS, R3, E3x, DB, KF, LKF, POUR3 = r.XA0, r.XA1, r.IFS, r.VS, r.R3, r.E3x, r.DB, r.KF, r.LKF, r.POUR3
LIVE, EXTRA = r.LIVE, r.EXTRA
g11, g41 = 1.1e-3, 4.1e-3
FFF = lambda s: s.replace("boundary p p f", "boundary f f f")
B3 = lambda: BL(nt=3)


def pairA(gap, da=0.004, db=0.006, ta=1, tb=2, ia=None, ib=None, t=1e-3, z=0.049995095, x0=0.02):
    """the live pair made AFTER a run of t seconds, timed to meet gap/1 m/s after it; ids ia, ib for the groups"""
    xa, xb = x0 - da / 2 - gap / 2, x0 + db / 2 + gap / 2
    va, vb = db ** 3 / (da ** 3 + db ** 3), -da ** 3 / (da ** 3 + db ** 3)
    return (f"create_atoms {ta} single {xa:.9g} 0.02 {z}\ncreate_atoms {tb} single {xb:.9g} 0.02 {z}\n"
            f"set atom {ia} diameter {da} density 2500\nset atom {ib} diameter {db} density 2500\n"
            f"group lv1 id {ia}\ngroup lv2 id {ib}\nvelocity lv1 set {va:.10f} 0 0 units box\nvelocity lv2 set {vb:.10f} 0 0 units box\n")


def extra(name, **files):
    EXTRA.setdefault(name, {}).update(files)


# ------------------------------------------------------------ Q: run pre no after growth (create_atoms, read_data, fix adapt, pour), run 0, every, emptied types
VICQ = "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.03 0.01\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
PA12 = pairA(0.1e-3, db=0.012, ia=3, ib=4)
E("Q01_create_big_after_run_pre_no", "victims 4, 6 mm; run 1000; the live pair made after it, lv2 12 mm (bigger than any at set-up); run 3000 pre no",
  "run 1000\n" + PA12 + "run 3000 pre no\n", pre=B3() + VICQ, pair="", sep=0.008)
E("Q02_create_big_after_run_control", "Q01 without pre no", "run 1000\n" + PA12 + "run 3000\n", pre=B3() + VICQ, pair="", sep=0.008)
E("Q03_create_same_size_pre_no", "Q01 with lv2 6 mm (no growth: the sizes held at set-up)", "run 1000\n" + pairA(0.1e-3, ia=3, ib=4) + "run 3000 pre no\n", pre=B3() + VICQ, pair="")
RDX = lambda d: f"# lv2\n\n1 atoms\n3 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 {d} 2500 {0.02 + d / 2 + 0.00005:.9g} 0.02 0.049995095\n"
RDL = ("run 1000\ncreate_atoms 1 single 0.01795 0.02 0.049995095\nset atom 3 diameter 0.004 density 2500\ngroup lv1 id 3\n"
       "read_data lv2.data add append\ngroup lv2 id 4\nvelocity lv1 set {:.10f} 0 0 units box\nvelocity lv2 set {:.10f} 0 0 units box\n")
va12, vb12 = 0.012 ** 3 / (0.004 ** 3 + 0.012 ** 3), -0.004 ** 3 / (0.004 ** 3 + 0.012 ** 3)
E("Q04_read_data_big_pre_no", "victims; run 1000; lv2 (12 mm) by read_data add append; run 3000 pre no", RDL.format(va12, vb12) + "run 3000 pre no\n",
  pre=B3() + VICQ, pair="", sep=0.008, data={"lv2.data": RDX(0.012)})
E("Q05_read_data_big_control", "Q04 without pre no", RDL.format(va12, vb12) + "run 3000\n", pre=B3() + VICQ, pair="", sep=0.008, data={"lv2.data": RDX(0.012)})
AD = "variable dia equal 0.006+0.006*step/1000\nfix ad lv2 adapt 1 atom diameter v_dia reset no\nrun 1000\nunfix ad\n"
E("Q06_fix_adapt_grow_pre_no", "fix adapt grows lv2 6 -> 12 mm in run 1000 (reset no); unfix; run 3000 pre no", AD + "run 3000 pre no\n", gap=6.1e-3, sep=0.008)
E("Q07_fix_adapt_grow_control", "Q06 without pre no", AD + "run 3000\n", gap=6.1e-3, sep=0.008)
POUR12 = "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 1 2 4767 region ins diam one 0.012 dens 2500 2500\n"
E("Q08_pour_big_then_set_grow_pre_no", "a pour of one 12 mm type-2 sphere in run 1000; set group lv2 diameter 0.012; run 3000 pre no (the pour's size held)",
  POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q09_pour_big_unfix_set_grow_pre_no", "Q08 with the pour unfixed before the set", POUR12 + "run 1000\nunfix p\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q10_pour_big_in_run_then_pre_no", "a pour of one 12 mm type-2 sphere in run 1000, nothing else; run 3000 pre no (the pour's spheres are not growth)",
  POUR12 + "run 1000\nrun 3000 pre no\n", gap=g11)
NEW2 = lambda t, d: (f"create_atoms {t} single {XA1(g11) + 0.002 + d / 2 + 0.0001:.9g} 0.02 0.049995095\nset atom 2 diameter {d} density 2500\n"
                     f"group lv2 delete\ngroup lv2 id 2\nvelocity lv2 set -0.2285714286 0 0 units box\n")
E("Q11_type_emptied_refilled_bigger_pre_no", "run 1000; delete lv2 (type 2 emptied); create a 12 mm type-2 lv2 0.1 mm ahead of lv1; run 3000 pre no",
  "run 1000\ndelete_atoms group lv2\n" + NEW2(2, 0.012) + "run 3000 pre no\n", gap=g11, sep=0.008)
E("Q12_type_emptied_refilled_bigger_control", "Q11 without pre no", "run 1000\ndelete_atoms group lv2\n" + NEW2(2, 0.012) + "run 3000\n", gap=g11, sep=0.008)
E("Q13_new_type3_big_pre_no", "type 3 holds no atom at set-up; run 1000; delete lv2; a 12 mm type-3 lv2; run 3000 pre no",
  "run 1000\ndelete_atoms group lv2\n" + NEW2(3, 0.012) + "run 3000 pre no\n", gap=g11, sep=0.008, pre=B3())
extra("Q13_new_type3_big_pre_no", PAIR="types 1 3")
E("Q14_grow_run0_pre_no", "run 1000; set type 2 diameter 0.012; run 0; run 3000 pre no (set up again by run 0)", "run 1000\nset type 2 diameter 0.012\nrun 0\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q15_grow_run0_pre_no_pre_no", "run 1000; set type 2 diameter 0.012; run 0 pre no; run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 0 pre no\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q16_grow_every_pre_no_part3", "run 3000 pre no every 1000 set group lv2 diameter $(0.006+step*2e-6) (8 then 10 mm); pair meets in part 3",
  'run 3000 pre no every 1000 "set group lv2 diameter $(0.006+step*2e-6)"\n', gap=4.1e-3, sep=0.007)
E("Q17_create_every_pre_no", "run 2000 pre no every 1000 create_atoms a 12 mm sphere far above; the pair (6 mm) meets in part 2",
  'run 2000 pre no every 1000 "create_atoms 2 single 0.02 0.02 0.085" "set type 2 diameter 0.012"\n', gap=1.1e-3, sep=0.008, live="part 2")
E("Q18_grow_then_shrink_back_pre_no", "run 1000; set type 2 diameter 0.012; set type 2 diameter 0.006; run 3000 pre no (net unchanged)",
  "run 1000\nset type 2 diameter 0.012\nset type 2 diameter 0.006\nrun 3000 pre no\n", gap=g11)
E("Q19_grow_setup_then_pre_no", "run 1000; set type 2 diameter 0.012; run 100 (set up); run 3000 pre no (nothing since)",
  "run 1000\nset type 2 diameter 0.012\nrun 100\nrun 3000 pre no\n", gap=g41 + 0.1e-3, sep=0.008)
E("Q20_grow_atom_var_pre_no", "run 1000; variable d atom 0.012*(type==2)+0.004*(type==1); set group all diameter v_d; run 3000 pre no",
  "run 1000\nvariable d atom 0.012*(type==2)+0.004*(type==1)\nset group all diameter v_d\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q21_grow_quoted_include_pre_no", 'run 1000; include "g.in" (set type 2 diameter 0.012); run 3000 pre no', 'run 1000\ninclude "g.in"\nrun 3000 pre no\n', gap=g41, sep=0.008,
  data={"g.in": "set type 2 diameter 0.012\n"})
E("Q22_grow_if_pre_no", "run 1000; if 1 then set type 2 diameter 0.012; run 3000 pre no", 'run 1000\nif "1 > 0" then "set type 2 diameter 0.012"\nrun 3000 pre no\n', gap=g41, sep=0.008)
E("Q23_grow_loop_pre_no", "loop 2: run 500; set type 2 diameter 0.012 (second pass); then run 3000 pre no",
  'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "set type 2 diameter 0.012"\nnext i\njump SELF l\nrun 3000 pre no\n', gap=g41, sep=0.008)
E("Q24_pair_coeff_range_pre_no", "run 1000; pair_coeff 1*2 1*2 kn 5000; run 3000 pre no", "run 1000\npair_coeff 1*2 1*2 " + hk(5000) + "\nrun 3000 pre no\n", gap=g11)
E("Q25_pair_coeff_21_pre_no", "run 1000; pair_coeff 2 1 kn 5000 (reversed); run 3000 pre no", "run 1000\npair_coeff 2 1 " + hk(5000) + "\nrun 3000 pre no\n", gap=g11)
E("Q26_like_mixed_pre_no", "1 1, 2 2 only (1 2 mixed); run 1000; pair_coeff 1 1 kn 8000; run 3000 pre no (live 1 2)", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n",
  gap=g11, pre=r.r.MIX)
E("Q27_like_mixed_other_type_empty_pre_no", "1 1, 2 2, 3 3 only; run 1000; pair_coeff 3 3 kn 8000 (type 3 holds no atom); run 3000 pre no",
  "run 1000\n" + P8("3", "3") + "\nrun 3000 pre no\n", gap=g11,
  pre=m.head(3) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\npair_coeff 3 3 " + HK + "\n" + m.GRAV + r.FL() + r.TAILL)
E("Q28_neighbor_same_pre_no", "run 1000; neighbor 0.001 bin (the default, unchanged); run 3000 pre no", "run 1000\nneighbor 0.001 bin\nrun 3000 pre no\n", gap=g11)
E("Q29_neighbor_nsq_pre_no", "run 1000; neighbor 0.001 nsq; run 3000 pre no", "run 1000\nneighbor 0.001 nsq\nrun 3000 pre no\n", gap=g11)
E("Q30_exclude_pre_no", "run 1000; neigh_modify exclude type 1 2; run 3000 pre no", "run 1000\nneigh_modify exclude type 1 2\nrun 3000 pre no\n", gap=g11)
E("Q31_restyle_pre_no", "run 1000; pair_style granular; pair_coeff * * kn 5000; run 3000 pre no", "run 1000\npair_style granular\npair_coeff * * " + hk(5000) + "\nrun 3000 pre no\n", gap=g11)
E("Q32_grow_type1_mass_set_pre_no", "run 1000; set type 1 diameter 0.010 density 1000; run 3000 pre no", "run 1000\nset type 1 diameter 0.010 density 1000\nrun 3000 pre no\n", gap=4.1e-3, sep=0.008)
E("Q33_grow_label_every_pre_no", "labelmap; run 3000 pre no every 1000 set type big diameter 0.012; pair meets in part 3",
  'labelmap atom 1 small 2 big\nrun 3000 pre no every 1000 "set type big diameter 0.012"\n', gap=5.1e-3, sep=0.008)
Ll("L01_pre_no_create_big", "LIGGGHTS run 1000; a 12 mm type-2 sphere made far away; set lv2 to 12 mm; run 3000 pre no",
   "run 1000\ncreate_atoms 2 single 0.03 0.03 0.12 units box\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=4.1e-3)
Ll("L02_pre_no_grow_run0", "LIGGGHTS run 1000; set type 2 diameter 0.012; run 0; run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 0\nrun 3000 pre no\n", gap=4.1e-3)
Ll("L03_pre_no_grow_every", "LIGGGHTS run 3000 pre no every 1000 set type 2 diameter 0.012 (meets part 3)", 'run 3000 pre no every 1000 "set type 2 diameter 0.012"\n', gap=5.1e-3)
for n in ("L01_pre_no_create_big", "L02_pre_no_grow_run0", "L03_pre_no_grow_every"):
    extra(n, SEP="0.008")

# ------------------------------------------------------------ N: a granular cutoff's reach (cutoff 0.001 everywhere: 1 2 contact 5 mm)
C1 = CU(0.001)
E("N01_nsq_fff", "boundary f f f; every cutoff 0.001; neighbor 0.001 nsq (all pairs: LAMMPS meets it)", "neighbor 0.001 nsq\nrun 3000\n", pre=FFF(C1), gap=0.1e-3)
E("N02_nsq_ppf_middle", "N01 with boundary p p f, the pair in the middle", "neighbor 0.001 nsq\nrun 3000\n", pre=C1, gap=0.1e-3)
E("N03_nsq_mmf", "N01 with boundary m m f (shrink-wrapped, not periodic)", "neighbor 0.001 nsq\nrun 3000\n", pre=C1.replace("boundary p p f", "boundary m m f"), gap=0.1e-3)
E("N04_nsq_fpf_middle", "N01 with boundary f p f (periodic in y only; the pair along x in the middle)", "neighbor 0.001 nsq\nrun 3000\n", pre=C1.replace("boundary p p f", "boundary f p f"), gap=0.1e-3)
STR = lvi(0.1e-3, (1, 2), x0=0.0, remap=" remap yes")
E("N05_fff_then_change_box_p_straddle", "f f f; nsq; run 100; change_box all boundary p p f; the pair made straddling x = 0 (remap); run 3000",
  "neighbor 0.001 nsq\nrun 100\nchange_box all boundary p p f\n" + STR + "run 3000\n", pre=FFF(C1), pair="", gap=0.1e-3)
E("N06_ppf_then_change_box_f_middle", "p p f; nsq; run 1000; change_box all boundary f f f; run 3000 (pair in the middle)",
  "neighbor 0.001 nsq\nrun 1000\nchange_box all boundary f f f\nrun 3000\n", pre=C1, gap=g11)
E("N07_fff_change_box_include", "f f f; nsq; run 100; include cb.in (change_box p p f); straddling pair; run 3000",
  "neighbor 0.001 nsq\nrun 100\ninclude cb.in\n" + STR + "run 3000\n", pre=FFF(C1), pair="", gap=0.1e-3, data={"cb.in": "change_box all boundary p p f\n"})
RDB = lambda xa, xb: (f"# box and the pair\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
                      f"1 1 0.004 2500 {xa:.9g} 0.02 0.05\n2 2 0.006 2500 {xb:.9g} 0.02 0.05\n\nVelocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n")
RDD = lambda bnd: ("units si\natom_style sphere 1\n" + bnd + "comm_modify vel yes\nread_data box.data\npair_style granular\npair_coeff * * " + HK + " cutoff 0.001\n"
                   + m.GRAV + r.FL() + r.TAILL + "group lv1 id 1\ngroup lv2 id 2\nneighbor 0.001 nsq\nrun 3000\n")
E("N08_read_data_default_ppp_straddle", "read_data (no boundary command: p p p) the pair straddling x = 0; nsq; run 3000",
  RDD("boundary p p f\n"), pre="\n", pair="", gap=0.1e-3, data={"box.data": RDB(0.04 - 0.00205, 0.00305)})
E("N09_read_data_fff_middle", "boundary f f f; read_data the pair in the middle; nsq", RDD("boundary f f f\n"), pre="\n", pair="", gap=0.1e-3,
  data={"box.data": RDB(0.01795, 0.02305)})
RSTR = ("neighbor 0.001 nsq\nwrite_restart a.rst\nclear\nboundary f f f\nread_restart a.rst\nneighbor 0.001 nsq\n" + m.GRAV + r.FL() + r.TAILL + "run 3000\n")
E("N10_restart_ppf_boundary_fff_before", "p p f, the pair straddling x = 0; write_restart; clear; boundary f f f; read_restart (its p p f); nsq",
  RSTR, pre=C1, pair=STR, gap=0.1e-3)
E("N11_restart_fff_boundary_ppf_before", "f f f, pair in the middle; write_restart; clear; boundary p p f; read_restart (its f f f); nsq",
  RSTR.replace("boundary f f f", "boundary p p f"), pre=FFF(C1), gap=0.1e-3)
E("N12_nsq_then_bin_fff", "f f f; neighbor 0.001 nsq; run 1000; neighbor 0.001 bin; run 3000 (bins of the small reach in the run the pair meets)",
  "neighbor 0.001 nsq\nrun 1000\nneighbor 0.001 bin\nrun 3000\n", pre=FFF(C1), gap=g11)
E("N13_bin_then_nsq_fff", "f f f; run 1000 (bin); neighbor 0.001 nsq; run 3000", "run 1000\nneighbor 0.001 nsq\nrun 3000\n", pre=FFF(C1), gap=g11)
E("N14_nsq_every_fff", "f f f; run 3000 every 1000 neighbor 0.001 nsq (pair meets in part 3)", R3.format("neighbor 0.001 nsq"), pre=FFF(C1), gap=2.1e-3)
E("N15_bin_every_after_nsq_fff", "f f f; nsq; run 3000 every 1000 neighbor 0.001 bin (part 3 bin)", "neighbor 0.001 nsq\n" + R3.format("neighbor 0.001 bin"), pre=FFF(C1), gap=2.1e-3)
E("N16_nsq_include_quoted_fff", 'f f f; include "nb.in" (neighbor 0.001 nsq)', 'include "nb.in"\nrun 3000\n', pre=FFF(C1), gap=0.1e-3, data={"nb.in": "neighbor 0.001 nsq\n"})
GC = FFF(BL()).replace("pair_style granular\n", "pair_style granular 0.001\n")
E("N17_global_cutoff_nsq_fff", "pair_style granular 0.001 (global cutoff); f f f; nsq", "neighbor 0.001 nsq\nrun 3000\n", pre=GC, gap=0.1e-3)
E("N18_global_cutoff_bin_fff", "pair_style granular 0.001 (global cutoff); f f f; bin", "run 3000\n", pre=GC, gap=0.1e-3)
E("N19_one_pair_small_cutoff", "only 1 2 has cutoff 0.001 (1 1, 2 2 default): the largest cutoff holds the lists", "pair_coeff 1 2 " + HK + " cutoff 0.001\nrun 3000\n", gap=0.1e-3)
E("N20_skin_big_then_small", "cutoff 0.001; neighbor 0.01 bin; run 1000; neighbor 0.001 bin; run 3000 (round 28 N19)", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 3000\n", pre=C1, gap=g11)
E("N21_skin_small_then_big", "cutoff 0.001; run 1000; neighbor 0.01 bin; run 3000 (round 28 N15)", "run 1000\nneighbor 0.01 bin\nrun 3000\n", pre=C1, gap=g11)
E("N22_multi_fff", "f f f; cutoff 0.001; neighbor 0.001 multi", "neighbor 0.001 multi\nrun 3000\n", pre=FFF(C1), gap=0.1e-3)
E("N23_nsq_fff_then_clear_ppf_straddle", "f f f nsq run; clear; a p p f deck (nsq) with the pair straddling", "neighbor 0.001 nsq\nrun 100\nclear\n" + C1 + STR + "neighbor 0.001 nsq\nrun 3000\n",
  pre=FFF(C1), gap=0.1e-3, live="the run after clear")
E("N24_skin_var_step", "cutoff 0.001; neighbor 0.01 bin; run 3000; neighbor $(0.006-step*2e-6) bin (LAMMPS skin 0); run 1000",
  "neighbor 0.01 bin\nrun 3000\nneighbor $(0.006-step*2e-6) bin\nrun 1000\n", pre=C1, gap=3.1e-3)
Ll("L04_nsq_small_skin_after_run", "LIGGGHTS run 1000; neighbor 0.0001 nsq; run 3000", "run 1000\nneighbor 0.0001 nsq\nrun 3000\n", gap=g11)

# ------------------------------------------------------------ R: set type/fraction, type/ratio, type/subset after a run (runs made for real)
RF = lambda kw, seed, who="group lv1": f"run 1000\nset {who} {kw} {seed}\n" + P8("2", "3") + "\nrun 3000\n"
Rk = dict(gap=g11, pre=B3(), pair=lvi(g11, (1, 2)))
for seed in (2, 5, 7, 11):
    E(f"R0{seed if seed < 10 else 9}_fraction_seed{seed}", f"run 1000; set group lv1 type/fraction 3 0.5 {seed}; 2 3 kn 8000", RF("type/fraction 3 0.5", seed), **Rk)
E("R10_fraction_budget0", "R02 (seed 2) with --run-budget 0 (must refuse)", RF("type/fraction 3 0.5", 2), **Rk)
extra("R10_fraction_budget0", ARGS="--run-budget 0")
E("R11_ratio_budget0", "type/ratio after a run with --run-budget 0", RF("type/ratio 3 0.5", 9, "type 1"), gap=g11, pre=r.DB2(), pair=lvi(g11))
extra("R11_ratio_budget0", ARGS="--run-budget 0")
E("R12_fraction_every", "run 2000 every 1000 set group lv1 type/fraction 3 0.5 2; run 3000", 'run 2000 every 1000 "set group lv1 type/fraction 3 0.5 2"\n' + P8("2", "3") + "\nrun 3000\n",
  gap=2.1e-3, pre=B3(), pair=lvi(2.1e-3, (1, 2)))
E("R13_fraction_pour", "a pour of 2 type-1 spheres in run 1000; set type 1 type/fraction 3 0.5 2", POUR3.replace("pour 1 3", "pour 2 1") + RF("type/fraction 3 0.5", 2, "type 1"), **Rk)
E("R14_fraction_then_delete_random", "set group lv1 type/fraction 3 0.5 2 then delete_atoms random (victims only)", "create_atoms 3 single 0.01 0.01 0.08\ncreate_atoms 3 single 0.03 0.01 0.08\nset atom 3*4 diameter 0.004 density 2500\ngroup vv id 3 4\n"
  + "run 1000\nset group lv1 type/fraction 3 0.5 2\ndelete_atoms random fraction 0.5 no vv NULL 77\n" + P8("2", "3") + "\nrun 3000\n", **Rk)
E("R15_fraction_include_quoted", 'include "t.in" (type/fraction after a run)', 'run 1000\ninclude "t.in"\n' + P8("2", "3") + "\nrun 3000\n", data={"t.in": "set group lv1 type/fraction 3 0.5 2\n"}, **Rk)
E("R16_fraction_loop", "loop 2 passes: run 500; set group lv1 type/fraction 3 0.5 2", 'variable i loop 2\nlabel l\nrun 500\nset group lv1 type/fraction 3 0.5 2\nnext i\njump SELF l\n' + P8("2", "3") + "\nrun 3000\n", **Rk)
E("R17_fraction_if", "run 1000; if 1 then set group lv1 type/fraction 3 0.5 2", 'run 1000\nif "1 > 0" then "set group lv1 type/fraction 3 0.5 2"\n' + P8("2", "3") + "\nrun 3000\n", **Rk)
E("R18_fraction_run0", "run 0 first, then the set (runs of 0 steps: nothing moves)", "run 0\nset group lv1 type/fraction 3 0.5 2\n" + P8("2", "3") + "\nrun 4000\n", **Rk)
E("R19_fraction_pre_no", "set type/fraction after run 1000; run 3000 pre no", "run 1000\nset group lv1 type/fraction 3 0.5 2\n" + P8("2", "3") + "\nrun 3000 pre no\n", **Rk)
E("R20_subset_every", "run 2000 every 1000 set type 1 type/subset 3 1 4 (2 mm victim)", 'run 2000 every 1000 "set type 1 type/subset 3 1 4"\n' + P8("2", "3") + "\nrun 3000\n", gap=2.1e-3, pre=r.DB2(), pair=lvi(2.1e-3))
E("R21_ratio_pour", "a pour of 2 type-1 spheres; set type 1 type/ratio 3 0.5 3", POUR3.replace("pour 1 3", "pour 2 1") + RF("type/ratio 3 0.5", 3, "type 1"), gap=g11, pre=r.DB2(), pair=lvi(g11))
E("R22_fraction_every_budget0", "R12 with --run-budget 0", 'run 2000 every 1000 "set group lv1 type/fraction 3 0.5 2"\n' + P8("2", "3") + "\nrun 3000\n", gap=2.1e-3, pre=B3(), pair=lvi(2.1e-3, (1, 2)))
extra("R22_fraction_every_budget0", ARGS="--run-budget 0")
Ll("L05_fraction_after_run", "LIGGGHTS run 1000; set group lv1 type/fraction 3 0.5 2 (e 1 3/2 3 = 0.7/0.45)", "run 1000\nset group lv1 type/fraction 3 0.5 2\nrun 3000\n", gap=g11)

# ------------------------------------------------------------ V: run-dependent substitutions in commands other than outputs
g31 = 3.1e-3
E("V01_include_step", "run 3000; include k$(step).in (round 28 V81)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=g31, data=KF)
E("V02_include_step_quoted", 'run 3000; include "k$(step).in"', 'run 3000\ninclude "k$(step).in"\nrun 1000\n', gap=g31, data=KF)
E("V03_jump_label_step", "run 3000; jump SELF L$(step)", "run 3000\njump SELF L$(step)\nlabel L0\n" + P8() + "\njump SELF end\nlabel L3000\n" + P5() + "\nlabel end\nrun 1000\n", gap=g31)
E("V04_jump_file_step", "run 3000; jump j$(step).in (the deck goes on there)", "run 3000\njump j$(step).in\n", gap=g31, data={"j3000.in": P5() + "\nrun 1000\n", "j0.in": P8() + "\nrun 1000\n"})
E("V05_label_name_step", "run 3000; jump SELF L3000 to a label L$(step)", "run 3000\njump SELF L3000\nlabel L0\n" + P8() + "\njump SELF end\nlabel L$(step)\n" + P5() + "\nlabel end\nrun 1000\n", gap=g31)
E("V06_group_id_step", "run 3000; group g id $(step/1500) (lv2); set group g type 3; 1 3 kn 8000", "run 3000\ngroup g id $(step/1500)\nset group g type 3\n" + P8("1", "3") + "\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
extra("V06_group_id_step", PAIR="types 1 3")
E("V07_group_name_step", "run 3000; group g$(step) id 2; set group g3000 type 3", "run 3000\ngroup g$(step) id 2\nset group g3000 type 3\n" + P8("1", "3") + "\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
extra("V07_group_name_step", PAIR="types 1 3")
E("V08_delete_group_step", "g0 = lv1 (the only type-1 sphere), g3000 = a type-3 victim; run 3000; delete_atoms group g$(step)",
  "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g0 id 1\ngroup g3000 id 3\nrun 3000\ndelete_atoms group g$(step)\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
E("V09_displace_group_step", "run 3000; displace_atoms g$(step) move 0 0 0.01 (g3000 a victim; no g0)", "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3000 id 3\nrun 3000\ndisplace_atoms g$(step) move 0 0 0.01 units box\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
E("V10_read_data_name_step", "run 3000; read_data d$(step).data add append (only d3000.data: a far sphere)", "run 3000\nread_data d$(step).data add append\nrun 1000\n", gap=g31,
  data={"d3000.data": "# far\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01 0.01 0.08\n"})
E("V11_fix_id_step_unfix", "run 3000; fix w$(step) all wall/gran kn 8000 zplane 0.001; unfix w3000", "run 3000\nfix w$(step) all wall/gran granular " + hk(8000) + " zplane 0.001 NULL\nunfix w3000\nrun 1000\n", gap=g31)
E("V12_region_name_step_wall", "run 3000; region c$(step) cylinder; fix rw wall/gran/region ... region c3000", "run 3000\nregion c$(step) cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nfix rw all wall/gran/region granular " + HK + " region c3000\nrun 1000\n", gap=g31)
E("V13_compute_name_step", "run 3000; compute c$(step) all count/type atom?  (compute n$(step) all reduce sum x); variable x equal c_n3000; if", 
  "run 3000\ncompute n$(step) all reduce sum x\nvariable x equal c_n3000\n" + IFS("${x} > 0") + "run 1000\n", gap=g31)
E("V14_exclude_type_step", "run 3000; neigh_modify exclude type 1 $(1+step/3000) (LAMMPS: 1 2, the pair passes through)", "run 3000\nneigh_modify exclude type 1 $(1+step/3000)\nrun 1000\n", gap=g31)
E("V15_create_type_step", "lv1 only; run 3000; lv2 made as type $(1+step/3000) (2); 1 2 kn 5000, 1 1 kn 2000",
  P5() + "\nrun 3000\n" + f"create_atoms $(1+step/3000) single {XA1(g11, 3e-3) + 0.002 + 0.003 + 0.0001:.9g} 0.02 {0.05 - 0.5 * 9.81 * 9e-6:.9g}\nset atom 2 diameter 0.006 density 2500\ngroup lv2 id 2\nvelocity lv2 set -0.2285714286 0 0 units box\nrun 1000\n",
  gap=g11, pair=f"create_atoms 1 single {XA0(g11):.9g} 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 0.7714285714 0 0 units box\n")
E("V16_prior_def_every_include", "variable s equal 1; run 3000 every 1000 variable s equal $(step); include k${s}.in", "variable s equal 1\n" + VS + "include k${s}.in\nrun 1000\n", gap=g31, data=KF)
E("V17_prior_def_every_jump", "variable s equal 1; every redefines it from the step; jump SELF L${s}", "variable s equal 1\n" + VS + "jump SELF L${s}\nlabel L1\n" + P8() + "\njump SELF end\nlabel L3000\n" + P5() + "\nlabel end\nrun 1000\n", gap=g31)
E("V18_prior_def_every_group", "variable s equal 1; every s = $(step/1500); group g id ${s}; set group g type 3", "variable s equal 1\n" + R3.format("variable s equal $(step/1500)") + "group g id ${s}\nset group g type 3\n" + P8("1", "3") + "\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
extra("V18_prior_def_every_group", PAIR="types 1 3")
E("V19_prior_def_every_coeff", "variable s equal 1; every redefine; if s == 3000 kn 5000 else 8000 (round 28 V63)", "variable s equal 1\n" + VS + IFS("${s} == 3000") + "run 1000\n", gap=g31)
E("V20_prior_def_every_exclude", "variable s equal 1; every s = $(1+step/3000); neigh_modify exclude type 1 ${s}", "variable s equal 1\n" + R3.format("variable s equal $(1+step/3000)") + "neigh_modify exclude type 1 ${s}\nrun 1000\n", gap=g31)
E("V21_prior_def_every_delete", "variable s equal 1; every redefine; delete_atoms group g${s} (g1 lv1, g3000 a victim)",
  "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g1 id 1\ngroup g3000 id 3\nvariable s equal 1\n" + VS + "delete_atoms group g${s}\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
E("V22_time_include", "run 3000; include k$(time*1e6:%.0f).in", "run 3000\ninclude k$(time*1e6:%.0f).in\nrun 1000\n", gap=g31, data=KF)
E("V23_include_step_nested", "run 3000; include a.in, which includes k$(step).in", "run 3000\ninclude a.in\nrun 1000\n", gap=g31, data=dict(KF, **{"a.in": "include k$(step).in\n"}))
E("V24_include_step_in_loop", "loop 3: run 1000; include k$(step).in (last k3000)", "variable i loop 3\nlabel l\nrun 1000\ninclude k$(step).in\nnext i\njump SELF l\nrun 1000\n", gap=g31, data=KF)
E("V25_count_pour_include_lazy", "a pour of 2; variable n equal count(all); run 1000; include k${n}.in (4 atoms: kn 5000)",
  POUR3.replace("pour 1 3", "pour 2 3") + "variable n equal count(all)\nrun 1000\ninclude k${n}.in\nrun 3000\n", gap=g11, pre=B3(), pair=lvi(g11, (1, 2)),
  data={"k4.in": P5() + "\n", "k2.in": P8() + "\n", "k3.in": P8() + "\n"})
E("V26_xcm_include", "run 1000; include k$(xcm(lv1,x)>0.018).in (LAMMPS k1.in kn 5000; at the start k0.in kn 8000)", "run 1000\ninclude k$(xcm(lv1,x)>0.018).in\nrun 3000\n", gap=g11,
  data={"k1.in": P5() + "\n", "k0.in": P8() + "\n"})
W("V27_wall_kn_step", "wall live: run 3000; fix floor kn $(step+5000) (8000); run 1000", "run 3000\nfix floor all wall/gran granular hooke $(step+5000) 3000 " + K + " zplane 0 NULL\nrun 1000\n", gap=g31)
E("V28_set_atom_step", "run 3000; set atom $(step/1500) type 3 (lv2); 1 3 kn 8000", "run 3000\nset atom $(step/1500) type 3\n" + P8("1", "3") + "\nrun 1000\n", gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
extra("V28_set_atom_step", PAIR="types 1 3")
E("V29_velocity_group_step", "run 3000; velocity g$(step) set 0 0 0 (g3000 = lv2: the pair stops short... no contact)", "group g3000 id 2\nrun 3000\nvelocity g$(step) set 0 0 0 units box\nrun 1000\n", gap=g31)
E("V30_variable_string_step_include", "run 3000; variable f string k$(step).in; include ${f}", "run 3000\nvariable f string k$(step).in\ninclude ${f}\nrun 1000\n", gap=g31, data=KF)
E("V31_if_then_include_step", "run 3000; if 1 then 'include k$(step).in'", "run 3000\nif \"1 > 0\" then 'include k$(step).in'\nrun 1000\n", gap=g31, data=KF)
E("V32_label_time_jump", "run 3000; jump SELF T$(time*1e3:%.0f)", "run 3000\njump SELF T$(time*1e3:%.0f)\nlabel T0\n" + P8() + "\njump SELF end\nlabel T3\n" + P5() + "\nlabel end\nrun 1000\n", gap=g31)
E("V33_include_step_only_real", "run 3000; include k$(step).in with only k3000.in (round 28 V88)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=g31, data={"k3000.in": P5() + "\n"})
E("V34_mass_region_step", "run 3000; region r$(step) block ... (whole box); set region r3000 type 3", "run 3000\nregion r$(step) block 0 0.04 0 0.04 0 0.1 units box\nset region r3000 type 3\n" + P8("3", "3") + "\nrun 1000\n",
  gap=g31, pre=B3(), pair=lvi(g31, (1, 2)))
extra("V34_mass_region_step", PAIR="types 3 3")
E("V35_timestep_step", "run 3000; timestep $(1e-6+step*1e-10) (1.3e-6); pair meets after", "run 3000\ntimestep $(1e-6+step*1e-10)\nrun 1000\n", gap=g31)
Ll("L06_include_step", "LIGGGHTS run 3000; include k$(step).in (round 28 L26)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=g31)
m.DECKS["L06_include_step"] = (m.DECKS["L06_include_step"][0], 1, LKF, True, "in.deck")
Ll("L07_include_step_only_real", "LIGGGHTS run 3000; include k$(step).in, only k3000.in (round 28 L27)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=g31)
m.DECKS["L07_include_step_only_real"] = (m.DECKS["L07_include_step_only_real"][0], 1, {"k3000.in": E3x(0.9) + "\n"}, True, "in.deck")
Ll("L08_jump_label_step", "LIGGGHTS run 3000; jump SELF L$(step)", "run 3000\njump SELF L$(step)\nlabel L1\n" + E3x(0.2) + "\njump SELF end\nlabel L3000\n" + E3x(0.9) + "\nlabel end\nrun 1000\n", gap=g31)

# ------------------------------------------------------------ I: quoted include names
KIN = {"k.in": P5() + "\n"}
E("I01_include_dq", 'run 1000; include "k.in" (kn 5000); run 3000', 'run 1000\ninclude "k.in"\nrun 3000\n', gap=g11, data=KIN)
E("I02_include_sq", "run 1000; include 'k.in'", "run 1000\ninclude 'k.in'\nrun 3000\n", gap=g11, data=KIN)
E("I03_include_tq", 'run 1000; include """k.in"""', 'run 1000\ninclude """k.in"""\nrun 3000\n', gap=g11, data=KIN)
E("I04_include_space_name", 'run 1000; include "sub dir/k.in"', 'run 1000\ninclude "sub dir/k.in"\nrun 3000\n', gap=g11, data={"sub dir/k.in": P5() + "\n"})
E("I05_include_in_if", "run 1000; if 1 then 'include \"k.in\"'", "run 1000\nif \"1 > 0\" then 'include \"k.in\"'\nrun 3000\n", gap=g11, data=KIN)
E("I06_include_in_every", "run 3000 every 1000 'include \"k.in\"' (part 3 kn 5000)", "run 3000 every 1000 'include \"k.in\"'\n", gap=2.1e-3, data=KIN)
E("I07_include_var_quoted", 'variable f string k.in; include "${f}"', 'variable f string k.in\nrun 1000\ninclude "${f}"\nrun 3000\n', gap=g11, data=KIN)
E("I08_include_nested_quoted", 'include "a.in" which includes "k.in"', 'run 1000\ninclude "a.in"\nrun 3000\n', gap=g11, data=dict(KIN, **{"a.in": 'include "k.in"\n'}))
E("I09_include_quoted_comment", 'include "k.in" # with a comment', 'run 1000\ninclude "k.in" # kn 5000 here\nrun 3000\n', gap=g11, data=KIN)
E("I10_include_quoted_hash_name", 'include "k#1.in" (a # inside quotes)', 'run 1000\ninclude "k#1.in"\nrun 3000\n', gap=g11, data={"k#1.in": P5() + "\n", "k": P8() + "\n"})
E("I11_include_quoted_skin", 'cutoff 0.001; neighbor 0.01 bin; run 1000; include "nb.in" (neighbor 0.001 bin); run 3000', 'neighbor 0.01 bin\nrun 1000\ninclude "nb.in"\nrun 3000\n',
  pre=C1, gap=g11, data={"nb.in": "neighbor 0.001 bin\n"})
E("I12_include_quoted_same_name_other", 'include "k.in" where a file named k.in" does not exist; plain k.in kn 5000 and "k.in"? (quotes stripped)', 'run 1000\ninclude "k.in"\nrun 3000\n',
  gap=g11, data={"k.in": P5() + "\n", '"k.in"': P8() + "\n"})
E("I13_jump_quoted_file", 'run 1000; jump "j.in" (deck goes on there)', 'run 1000\njump "j.in"\n', gap=g11, data={"j.in": P5() + "\nrun 3000\n"})
Ll("L09_include_dq", 'LIGGGHTS run 1000; include "k.in" (e 1 2 0.9)', 'run 1000\ninclude "k.in"\nrun 3000\n', gap=g11)
m.DECKS["L09_include_dq"] = (m.DECKS["L09_include_dq"][0], 1, {"k.in": E3x(0.9) + "\n"}, True, "in.deck")

# ------------------------------------------------------------ wave 2: around the first wave's silently wrong decks (quoted includes not followed; pre no after growth with a pour)
SUB = {"sub dir/k.in": P5() + "\n"}
E("I14_include_space_no_run", 'include "sub dir/k.in" (kn 5000) before the only run', 'include "sub dir/k.in"\nrun 3000\n', gap=0.1e-3, data=SUB)
E("I15_include_space_sq", "include 'sub dir/k.in' before the only run", "include 'sub dir/k.in'\nrun 3000\n", gap=0.1e-3, data=SUB)
E("I16_include_var_index", 'variable i index 5; include "k${i}.in" before the only run', 'variable i index 5\ninclude "k${i}.in"\nrun 3000\n', gap=0.1e-3, data={"k5.in": P5() + "\n"})
E("I17_include_immediate", 'include "k$(2+3).in" before the only run', 'include "k$(2+3).in"\nrun 3000\n', gap=0.1e-3, data={"k5.in": P5() + "\n"})
E("I18_include_var_string", 'variable f string k.in; include "${f}" before the only run', 'variable f string k.in\ninclude "${f}"\nrun 3000\n', gap=0.1e-3, data=KIN)
E("I19_include_var_unquoted", "variable f string k.in; include ${f} (control)", "variable f string k.in\ninclude ${f}\nrun 3000\n", gap=0.1e-3, data=KIN)
E("I20_include_var_in_if", "variable f string k.in; if 1 then 'include \"${f}\"'", "variable f string k.in\nif \"1 > 0\" then 'include \"${f}\"'\nrun 3000\n", gap=0.1e-3, data=KIN)
E("I21_include_var_space", 'variable f string "sub dir/k.in"; include "${f}"', 'variable f string "sub dir/k.in"\ninclude "${f}"\nrun 3000\n', gap=0.1e-3, data=SUB)
E("I22_include_space_grow_pre_no", 'run 1000; include "sub dir/g.in" (set type 2 diameter 0.012); run 3000 pre no', 'run 1000\ninclude "sub dir/g.in"\nrun 3000 pre no\n', gap=g41, sep=0.008,
  data={"sub dir/g.in": "set type 2 diameter 0.012\n"})
E("I23_include_var_exclude", 'variable f string x.in; include "${f}" (neigh_modify exclude type 1 2: the pair passes through)', 'variable f string x.in\ninclude "${f}"\nrun 3000\n', gap=0.1e-3,
  data={"x.in": "neigh_modify exclude type 1 2\n"})
E("I24_include_var_run_inside", 'variable f string k.in; include "${f}", which holds the coefficient and the run', 'variable f string kr.in\ninclude "${f}"\n', gap=0.1e-3, data={"kr.in": P5() + "\nrun 3000\n"})
E("I25_include_dot_var", 'variable d string .; include "${d}/k.in"', 'variable d string .\ninclude "${d}/k.in"\nrun 3000\n', gap=0.1e-3, data=KIN)
E("I26_include_var_loop", 'variable f index a.in k.in; label l; include "${f}"; next f; jump SELF l (last k.in)', 'variable f index a.in k.in\nlabel l\ninclude "${f}"\nnext f\njump SELF l\nrun 3000\n', gap=0.1e-3,
  data=dict(KIN, **{"a.in": P8() + "\n"}))
E("I27_include_var_skin", 'cutoff 0.001; neighbor 0.01 bin; variable f string nb.in; include "${f}" (neighbor 0.001 bin) before the only run', 'neighbor 0.01 bin\nvariable f string nb.in\ninclude "${f}"\nrun 3000\n',
  pre=C1, gap=1.1e-3, data={"nb.in": "neighbor 0.001 bin\n"})
E("I28_jump_var_quoted", 'variable f string j.in; jump "${f}" (the deck goes on there)', 'variable f string j.in\njump "${f}"\n', gap=0.1e-3, data={"j.in": P5() + "\nrun 3000\n"})
Ll("L10_include_var_quoted", 'LIGGGHTS variable f string k.in; include "${f}" (e 1 2 0.9)', 'variable f string k.in\ninclude "${f}"\nrun 3000\n', gap=0.1e-3)
m.DECKS["L10_include_var_quoted"] = (m.DECKS["L10_include_var_quoted"][0], 1, {"k.in": E3x(0.9) + "\n"}, True, "in.deck")
Ll("L11_include_space", 'LIGGGHTS include "sub dir/k.in" (e 1 2 0.9)', 'include "sub dir/k.in"\nrun 3000\n', gap=0.1e-3)
m.DECKS["L11_include_space"] = (m.DECKS["L11_include_space"][0], 1, {"sub dir/k.in": E3x(0.9) + "\n"}, True, "in.deck")
E("V36_jump_quoted_label_step", 'run 3000; jump SELF "L$(step)"', 'run 3000\njump SELF "L$(step)"\nlabel L0\n' + P8() + "\njump SELF end\nlabel L3000\n" + P5() + "\nlabel end\nrun 1000\n", gap=g31)
E("V37_prior_def_every_include_quoted", 'variable s equal 1; every redefine from the step; include "k${s}.in"', "variable s equal 1\n" + VS + 'include "k${s}.in"\nrun 1000\n', gap=g31, data=dict(KF, **{"k1.in": P8() + "\n"}))
E("Q34_pour_big_then_set_grow_control", "Q08 without pre no", POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008)
E("Q35_pour_small_then_set_grow_pre_no", "a pour of one 3 mm type-2 sphere; set group lv2 diameter 0.012; run 3000 pre no",
  POUR12.replace("diam one 0.012", "diam one 0.003") + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q36_pour_type3_then_grow_pre_no", "a pour of one 12 mm type-3 sphere; set group lv2 (type 2) diameter 0.012; run 3000 pre no",
  POUR12.replace("pour 1 2", "pour 1 3") + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("Q37_step_read_grow_pre_no", "a step read after the run (runs made for real); set type 2 diameter 0.012; run 3000 pre no",
  'run 1000\nif "$(step) > 0" then "print yes"\nset type 2 diameter 0.012\nrun 3000 pre no\n', gap=g41, sep=0.008)
E("Q38_fraction_victim_grow_pre_no", "a type-3 victim drawn by type/fraction after the run (made for real); set type 2 diameter 0.012; run 3000 pre no",
  "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup vv id 3\nrun 1000\nset group vv type/fraction 1 0.5 2\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=B3())
E("Q39_pour_big_grow_include_pre_no", "Q08 with the set in an include", POUR12 + "run 1000\ninclude g.in\nrun 3000 pre no\n", gap=g41, sep=0.008, data={"g.in": "set group lv2 diameter 0.012\n"})
E("Q40_pour_unrelated_grow_type1_pre_no", "a pour of one 3 mm type-2 sphere; set group lv1 (type 1) diameter 0.010; run 3000 pre no",
  POUR12.replace("diam one 0.012", "diam one 0.003") + "run 1000\nset group lv1 diameter 0.010\nrun 3000 pre no\n", gap=4.1e-3, sep=0.008)
E("Q41_pour_done_grow_pre_no", "a pour of one 12 mm type-2 sphere; run 1000; run 1000 (pour done); set lv2 diameter 0.012; run 3000 pre no",
  POUR12 + "run 1000\nrun 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=5.1e-3, sep=0.008)
E("Q42_step_read_grow_pre_no_control", "Q37 without pre no", 'run 1000\nif "$(step) > 0" then "print yes"\nset type 2 diameter 0.012\nrun 3000\n', gap=g41, sep=0.008)
E("N25_restart_fff_plain", "f f f, pair in the middle; write_restart; clear; read_restart (no boundary command); nsq", RSTR.replace("boundary f f f\n", ""), pre=FFF(C1), gap=0.1e-3)

# ------------------------------------------------------------ wave 3: what a quoted include with a variable carries (coefficients vs engine state), and SW-B's neighbours
FV = 'variable f string x.in\ninclude "${f}"\n'
XI = lambda name, comment, inc, lines="run 3000\n", **kw: E(name, comment, FV + lines, data={"x.in": inc}, **kw)
XI("I29_var_include_density", 'include "${f}" holding set type 2 density 7800', "set type 2 density 7800\n", gap=0.1e-3)
XI("I30_var_include_delete_lv1", 'include "${f}" holding delete_atoms group lv1 (no 1 2 pair)', "delete_atoms group lv1\n", gap=0.1e-3)
XI("I31_var_include_timestep", 'include "${f}" holding timestep 2e-5 (dt 20x: eps at dt)', "timestep 2e-5\n", lines="run 150\n", gap=0.1e-3)
XI("I32_var_include_restyle_hm", 'include "${f}" holding pair_style granular + hertz/material', "pair_style granular\npair_coeff * * " + HM + "\n", gap=0.1e-3)
W("I33_var_include_wall", 'wall live: include "${f}" holding fix floor kn 8000', FV + "run 3000\n", gap=0.1e-3, data={"x.in": "fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL\n"})
XI("I34_var_include_retype", 'include "${f}" holding set group lv1 type 3 (2 3 kn 8000)', "set group lv1 type 3\n" + P8("2", "3") + "\n", gap=0.1e-3, pre=B3())
extra("I34_var_include_retype", PAIR="types 2 3")
XI("I35_var_include_hybrid_none", 'hybrid granular zero; include "${f}" holding pair_coeff 1 2 zero (passes through)', "pair_coeff 1 2 zero\n", gap=0.1e-3,
   pre=r.HYB("hybrid granular zero 0.01", r.GG))
E("I36_if_dq_include_var", 'variable f string k.in; if 1 then "include ${f}"', 'variable f string k.in\nif "1 > 0" then "include ${f}"\nrun 3000\n', gap=0.1e-3, data=KIN)
E("I37_var_include_every", 'run 3000 every 1000 with the file name from a variable: include "${f}" (part 3 kn 5000)', "variable f string k.in\nrun 3000 every 1000 'include \"${f}\"'\n", gap=2.1e-3, data=KIN)
E("I38_var_include_after_clear", 'clear; base; include "${f}" (variables survive clear)', "variable f string k.in\nrun 100\nclear\n" + BL() + lv(0.1e-3) + 'include "${f}"\nrun 3000\n', gap=0.1e-3, data=KIN, live="the run after clear")
E("I39_var_include_labels", 'labelmap; include "${f}" holding pair_coeff small big kn 5000', 'labelmap atom 1 small 2 big\nvariable f string k.in\ninclude "${f}"\nrun 3000\n', gap=0.1e-3,
  data={"k.in": "pair_coeff small big " + hk(5000) + "\n"})
E("I40_space_include_cutoff_every", 'include "sub dir/c.in" holding pair_coeff * * ... cutoff 0.001 (the reach: LAMMPS never meets the pair? bin)', 'include "sub dir/c.in"\nrun 3000\n', gap=1.1e-3,
  data={"sub dir/c.in": "pair_coeff * * " + HK + " cutoff 0.001\n"})
E("I41_var_include_unquoted_next_line", "include ${f} where f holds a space-free name with $ in the file (k$.in? no: kk.in) (control)", 'variable f string kk.in\ninclude ${f}\nrun 3000\n', gap=0.1e-3, data={"kk.in": P5() + "\n"})
E("Q43_pour_range_grow_pre_no", "a pour of type-2 spheres diam range 0.004 0.012; set group lv2 diameter 0.010; run 3000 pre no",
  POUR12.replace("pour 1 2", "pour 2 2").replace("diam one 0.012", "diam range 0.004 0.012") + "run 1000\nset group lv2 diameter 0.010\nrun 3000 pre no\n", gap=3.1e-3, sep=0.007)
E("Q44_pour_big_grow_every_pre_no", "a pour of one 12 mm type-2 sphere; run 3000 pre no every 1000 set group lv2 diameter 0.012 (pair meets in part 3)",
  POUR12 + 'run 3000 pre no every 1000 "set group lv2 diameter 0.012"\n', gap=5.1e-3, sep=0.008)
E("Q45_pour_big_grow_type_pre_no", "Q08 by set type 2 diameter 0.012 (the poured sphere too)", POUR12 + "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q46_pour_big_grow_hertz_pre_no", "Q08 with hertz/material", POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL(HM))
E("Q47_pour_big_grow_hertz_control", "Q46 without pre no", POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008, pre=BL(HM))
E("Q48_pour_big_grow_density_pre_no", "Q08 with set group lv2 diameter 0.012 density 2500 (mass up 8x)", POUR12 + "run 1000\nset group lv2 diameter 0.012 density 2500\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q49_pour_big_grow_density_control", "Q48 without pre no", POUR12 + "run 1000\nset group lv2 diameter 0.012 density 2500\nrun 3000\n", gap=g41, sep=0.008)
E("Q50_pour_big_grow_skin_pre_no", "Q08 with neighbor 0.01 bin from the start (skin covers the growth: LAMMPS right?)", POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008,
  pre=BL() + "neighbor 0.01 bin\n")

# ------------------------------------------------------------ wave 4: quoted names without spaces or variables, step reads inside includes, LIGGGHTS insertion then growth under pre no
E("I42_include_subdir_dq", 'include "sub/k.in" (a path, no space, no variable)', 'include "sub/k.in"\nrun 3000\n', gap=0.1e-3, data={"sub/k.in": P5() + "\n"})
E("I43_include_subdir_plain", "include sub/k.in (control)", "include sub/k.in\nrun 3000\n", gap=0.1e-3, data={"sub/k.in": P5() + "\n"})
E("I44_include_dq_dollar_escape", 'include "k.in" after a variable of the same name defined (f), no substitution in the name', 'variable k string zz.in\ninclude "k.in"\nrun 3000\n', gap=0.1e-3, data=KIN)
E("I45_include_var_mixed", 'variable d string sub; include "${d}/k.in" (no space)', 'variable d string sub\ninclude "${d}/k.in"\nrun 3000\n', gap=0.1e-3, data={"sub/k.in": P5() + "\n"})
E("I46_include_var_unquoted_mixed", "variable d string sub; include ${d}/k.in (control)", "variable d string sub\ninclude ${d}/k.in\nrun 3000\n", gap=0.1e-3, data={"sub/k.in": P5() + "\n"})
E("V38_include_holds_step", "run 3000; include k.in holding pair_coeff 1 2 hooke $(step+2000) (kn 5000)", "run 3000\ninclude ks.in\nrun 1000\n", gap=g31, data={"ks.in": "pair_coeff 1 2 hooke $(step+2000) 3000 " + K + "\n"})
E("V39_quoted_include_holds_lazy_step", 'variable k equal step; run 3000; include "ks.in" holding pair_coeff 1 2 hooke $(v_k+2000)', 'variable k equal step\nrun 3000\ninclude "ks.in"\nrun 1000\n', gap=g31,
  data={"ks.in": "pair_coeff 1 2 hooke $(v_k+2000) 3000 " + K + "\n"})
E("V40_exclude_via_var_step", "run 3000; variable t equal $(1+step/3000); neigh_modify exclude type 1 ${t} (1 2: passes)", "run 3000\nvariable t equal $(1+step/3000)\nneigh_modify exclude type 1 ${t}\nrun 1000\n", gap=g31)
E("V41_include_name_var_from_step", "run 3000; variable n equal $(step); include k${n}.in", "run 3000\nvariable n equal $(step)\ninclude k${n}.in\nrun 1000\n", gap=g31, data=KF)
LINS = ("fix pts3 all particletemplate/sphere 15485863 atom_type 2 density constant 2500 radius constant 0.006\n"
        "fix pdd3 all particledistribution/discrete 32452843 1 pts3 1.0\nregion ins block 0.02 0.045 0.02 0.045 0.115 0.145 units box\n"
        "fix ins all insert/pack seed 49979687 distributiontemplate pdd3 insert_every once overlapcheck yes all_in yes particles_in_region 1 region ins\n")
Ll("L12_insert_big_grow_pre_no", "LIGGGHTS insert/pack of one 12 mm type-2 sphere; run 1000; set group lv2 diameter 0.012; run 3000 pre no", LINS + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=4.1e-3)
Ll("L13_insert_big_grow_control", "L12 without pre no", LINS + "run 1000\nset group lv2 diameter 0.012\nrun 3000\n", gap=4.1e-3)
Ll("L14_grow_pre_no_plain", "LIGGGHTS run 1000; set group lv2 diameter 0.012; run 3000 pre no (no insertion; round 28 L13)", "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=4.1e-3)
for n in ("L12_insert_big_grow_pre_no", "L13_insert_big_grow_control", "L14_grow_pre_no_plain"):
    extra(n, SEP="0.008")
E("Q51_pour_big_grow_run0_prenono", "Q08 with run 0 pre no between (still no set-up)", POUR12 + "run 1000\nset group lv2 diameter 0.012\nrun 0 pre no\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q52_pour_big_grow_labels", "Q08 with labels (type big)", "labelmap atom 1 small 2 big\n" + POUR12.replace("pour 1 2", "pour 1 big") + "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q53_pour_big_two_types_grow_pre_no", "pour of 12 mm type 2 (one); lv1 (type 1) grows to 12 mm (no pour of type 1)", POUR12 + "run 1000\nset group lv1 diameter 0.012\nrun 3000 pre no\n", gap=6.1e-3, sep=0.009)

E("I47_jump_space_file", 'jump "sub dir/j.in" (the deck goes on there: kn 5000 and the run)', 'jump "sub dir/j.in"\n', gap=0.1e-3, data={"sub dir/j.in": P5() + "\nrun 3000\n"})


def write_all(names):
    m.write_live(names, LIVE, EXTRA)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")
