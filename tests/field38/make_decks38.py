"""Field round 38: write decks/NAME/ (in.deck and the files it reads) for live37.py (links kept) and the audit.
A quick round on next-every (5d9d00a7) against the session's file fixes: Scratch.aliases (links, hard links), writers
in a whole run's every, jump as a checked read, links copied as their files, % and * in restart names. Helpers are
round 37's (make_decks37.py, imported; its decks are not written). Live pair and controls as round 37 (FINDINGS.md).
usage: python make_decks38.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field37"))
import make_decks37 as m7  # noqa: E402

m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG, LINKS, HARD = m7.L, m7.LG, m7.LINKS, m7.HARD
PCs, PC3, PC4, PC5, LEe, LE, IN, LIN, G11, HK, TAILR, MB, RB = (m7.PCs, m7.PC3, m7.PC4, m7.PC5, m7.LEe, m7.LE, m7.IN, m7.LIN,
                                                             m7.G11, m7.HK, m7.TAILR, m7.MB, m7.RB)
MDH = m7.m6.MDH
P5 = lambda f, how="file": 'print "' + PCs(5000) + '" ' + how + " " + f + " screen no\n"
RR = lambda f: "clear\nread_restart " + f + "\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n"
STALE = {}   # name[:3]: [(file, kind)]  kind rst8000 / data8000 / pct8000 written by LAMMPS

# ---------------------------------------------------------------- A: links inside subfolders, chains, .., folder links, hard links across folders, case
L("A01_sublink_target_mv", "sub/link.in -> real.in (both in sub; 3000); shell mv sub/new.in sub/real.in (5000); include sub/link.in (LAMMPS 5000)",
  "shell mv sub/new.in sub/real.in\ninclude sub/link.in\nrun 3000\n", data={"sub/real.in": PC3, "sub/new.in": PC5})
LINKS["A01"] = [("sub/link.in", "real.in")]
L("A02_chain_print_append", "a.in -> b.in -> real.in (3000); print pc 5000 append real.in; include a.in (5000)", P5("real.in", "append") + "include a.in\nrun 3000\n", data={"real.in": PC3})
LINKS["A02"] = [("b.in", "real.in"), ("a.in", "b.in")]
L("A03_chain_via_sub_dotdot", "a.in -> sub/b.in -> ../real.in (3000); print pc 5000 file real.in; include a.in (5000)", P5("real.in") + "include a.in\nrun 3000\n",
  data={"real.in": PC3, "sub/keep.txt": "x\n"})
LINKS["A03"] = [("sub/b.in", "../real.in"), ("a.in", "sub/b.in")]
L("A04_link_above_folder_plain", "link.in -> ../../shared/pc5.in (outside the folder; 5000); include link.in", "include link.in\nrun 3000\n")
LINKS["A04"] = [("link.in", "../../shared/pc5.in")]
L("A05_link_above_folder_cp_onto", "link.in -> ../../shared/pc3.in (3000); shell cp new.in link.in (writes through the link: 5000); include link.in",
  "shell cp new.in link.in\ninclude link.in\nrun 3000\n", data={"new.in": PC5})
LINKS["A05"] = [("link.in", "../../shared/pc3.in")]
L("A06_dirlink_print_target", "sub -> real_sub; print pc 5000 file real_sub/pc.in; include sub/pc.in (stale 3000; LAMMPS 5000)", P5("real_sub/pc.in") + "include sub/pc.in\nrun 3000\n",
  data={"real_sub/pc.in": PC3})
LINKS["A06"] = [("sub", "real_sub")]
L("A07_dirlink_print_link_side", "sub -> real_sub; print pc 5000 file sub/pc.in; include real_sub/pc.in (stale 3000; LAMMPS 5000)", P5("sub/pc.in") + "include real_sub/pc.in\nrun 3000\n",
  data={"real_sub/pc.in": PC3})
LINKS["A07"] = [("sub", "real_sub")]
L("A08_hard_across_sub_append", "a/h.in a hard link of b/real.in (3000); print pc 5000 append b/real.in; include a/h.in (5000)", P5("b/real.in", "append") + "include a/h.in\nrun 3000\n",
  data={"b/real.in": PC3, "a/keep.txt": "x\n"})
HARD["A08"] = [("a/h.in", "b/real.in")]
L("A09_hard_across_sub_mv_onto", "a/h.in a hard link of b/real.in (3000); shell mv new.in b/real.in (a new inode: h.in keeps 3000); include a/h.in (LAMMPS 3000)",
  "shell mv new.in b/real.in\ninclude a/h.in\nrun 3000\n", data={"b/real.in": PC3, "new.in": PC5, "a/keep.txt": "x\n"})
HARD["A09"] = [("a/h.in", "b/real.in")]
L("A10_hard_cp_onto", "h.in a hard link of real.in (3000); shell cp new.in real.in (same inode: 5000); include h.in", "shell cp new.in real.in\ninclude h.in\nrun 3000\n",
  data={"real.in": PC3, "new.in": PC5})
HARD["A10"] = [("h.in", "real.in")]
L("A11_case_link_other_file", "link.in -> Real.in (3000); print pc 5000 file real.in (another file on Linux); include link.in (LAMMPS 3000)", P5("real.in") + "include link.in\nrun 3000\n",
  data={"Real.in": PC3})
LINKS["A11"] = [("link.in", "Real.in")]
L("A12_case_link_same_file", "LINK.in -> real.in (3000); print pc 5000 file real.in; include LINK.in (5000)", P5("real.in") + "include LINK.in\nrun 3000\n", data={"real.in": PC3})
LINKS["A12"] = [("LINK.in", "real.in")]
L("A13_cd_sub_print_link", "sub/l.in -> r.in (sub/r.in 3000); shell cd sub; print pc 5000 file r.in; shell cd ..; include sub/l.in (5000)",
  "shell cd sub\n" + P5("r.in") + "shell cd ..\ninclude sub/l.in\nrun 3000\n", data={"sub/r.in": PC3})
LINKS["A13"] = [("sub/l.in", "r.in")]
L("A14_cd_sub_include_link_dotdot", "sub/l.in -> ../real.in (3000); print pc 5000 file real.in; shell cd sub; include l.in; shell cd .. (5000)",
  P5("real.in") + "shell cd sub\ninclude l.in\nshell cd ..\nrun 3000\n", data={"real.in": PC3, "sub/keep.txt": "x\n"})
LINKS["A14"] = [("sub/l.in", "../real.in")]
L("A15_link_target_with_dotdot", "l.in -> sub/../real.in (3000); print pc 5000 file real.in; include l.in (5000)", P5("real.in") + "include l.in\nrun 3000\n",
  data={"real.in": PC3, "sub/keep.txt": "x\n"})
LINKS["A15"] = [("l.in", "sub/../real.in")]
L("A16_abs_path_write_link_read", "link.in -> real.in (3000); shell pwd-free: print pc 5000 file ./real.in; include ./link.in (5000)", P5("./real.in") + "include ./link.in\nrun 3000\n",
  data={"real.in": PC3})
LINKS["A16"] = [("link.in", "real.in")]

# ---------------------------------------------------------------- W: writers in if branches, loops, includes, every
L("W01_if_print_link", "link.in -> real.in (3000); if then 'print pc 5000 file real.in'; include link.in (5000)",
  "if \"1 > 0\" then '" + P5("real.in").strip() + "'\ninclude link.in\nrun 3000\n", data={"real.in": PC3})
LINKS["W01"] = [("link.in", "real.in")]
L("W02_loop_print_link", "loop 2: print pc 2000+1000*i file real.in; include link.in; run 1000 (pass 2: 4000)",
  "variable i loop 2\nlabel lp\nprint \"" + PCs("$(2000+1000*v_i)") + "\" file real.in screen no\ninclude link.in\nrun 1000\nnext i\njump SELF lp\n",
  pair=IN(G11), live="pass 2", data={"real.in": PC3})
LINKS["W02"] = [("link.in", "real.in")]
L("W03_include_writer_link", "include w.in (w.in: print pc 5000 file real.in); include link.in (5000)", "include w.in\ninclude link.in\nrun 3000\n",
  data={"real.in": PC3, "w.in": P5("real.in")})
LINKS["W03"] = [("link.in", "real.in")]
L("W04_every_print_link", "run 1000 every 1000 \"print pc 5000 file real.in\"; include link.in (stale 3000; 5000)",
  "run 1000 every 1000 \"" + P5("real.in").strip().replace('"', "'") + "\"\ninclude link.in\nrun 3000\n", pair=IN(G11), data={"real.in": PC3})
LINKS["W04"] = [("link.in", "real.in")]
L("W05_every_cp_hard", "h.in hard of real.in (3000); run 1000 every 1000 \"shell cp new.in real.in\"; include h.in (5000)",
  "run 1000 every 1000 \"shell cp new.in real.in\"\ninclude h.in\nrun 3000\n", pair=IN(G11), data={"real.in": PC3, "new.in": PC5})
HARD["W05"] = [("h.in", "real.in")]
L("W06_every_include_writer", "run 1000 every 1000 \"include w.in\" (w.in: print pc 5000 file pc.in); include pc.in (stale 3000; 5000)",
  "run 1000 every 1000 \"include w.in\"\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3, "w.in": P5("pc.in")})
L("W07_every_if_writer", "run 1000 every 1000 'if \"1 > 0\" then \"shell cp new.in pc.in\"'; include pc.in (stale 3000; 5000)",
  "run 1000 every 1000 'if \"1 > 0\" then \"shell cp new.in pc.in\"'\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3, "new.in": PC5})
L("W08_every_var_writer", "f string pc.in; run 1000 every 1000 \"shell cp new.in ${f}\"; include pc.in (stale 3000; 5000)",
  "variable f string pc.in\nrun 1000 every 1000 \"shell cp new.in ${f}\"\ninclude pc.in\nrun 3000\n", pair=IN(G11), data={"pc.in": PC3, "new.in": PC5})
L("W09_every_writer_dirlink", "sub -> real_sub; run 1000 every 1000 \"shell cp new.in sub/pc.in\"; include real_sub/pc.in (stale 3000; 5000)",
  "run 1000 every 1000 \"shell cp new.in sub/pc.in\"\ninclude real_sub/pc.in\nrun 3000\n", pair=IN(G11), data={"real_sub/pc.in": PC3, "new.in": PC5})
LINKS["W09"] = [("sub", "real_sub")]
L("W10_jump_link_printed", "j.in -> real.in (stale: 3000, run, jump back); print the 5000 script file real.in; jump j.in (5000)",
  'print "' + PCs(5000) + '" file real.in screen no\nprint "run 3000" append real.in screen no\nprint "jump in.deck back" append real.in screen no\njump j.in\nlabel back\n',
  data={"real.in": PC3 + "run 3000\njump in.deck back\n"})
LINKS["W10"] = [("j.in", "real.in")]
L("W11_cd_sub_writer_every", "run 1000 every 1000 \"shell cd sub\" \"shell cp new.in pc.in\" \"shell cd ..\"; include sub/pc.in (stale 3000; 5000)",
  "run 1000 every 1000 \"shell cd sub\" \"shell cp new.in pc.in\" \"shell cd ..\"\ninclude sub/pc.in\nrun 3000\n", pair=IN(G11),
  data={"sub/pc.in": PC3, "sub/new.in": PC5})

# ---------------------------------------------------------------- R: reads by read_data / read_dump / molecule / variable file; restarts
L("R01_read_data_sublink", "sub/l.data -> ../d.data (stale lv2 8000); run 1000; lv2 5000; write_data d.data; clear; read_data sub/l.data (5000)",
  "run 1000\nset atom 2 density 5000\nwrite_data d.data\nclear\n" + MDH.format(f="sub/l.data") + "run 3000\n", pair=IN(G11), data={"sub/keep.txt": "x\n"})
LINKS["R01"] = [("sub/l.data", "../d.data")]
STALE["R01"] = [("d.data", "data8000")]
L("R02_read_dump_link", "l.dump -> d.dump (stale: a 0-velocity lv2); run 1000; write_dump d.dump; velocity lv2 0; read_dump l.dump x v (LAMMPS: the velocities back)",
  "run 1000\nwrite_dump all custom d.dump id type x y z vx vy vz\nvelocity lv2 set 0 0 0 units box\nread_dump l.dump 1000 x y z vx vy vz\nrun 3000\n", pair=IN(G11))
LINKS["R02"] = [("l.dump", "d.dump")]
STALE["R02"] = [("d.dump", "dump0")]
mol = lambda dd, m: f"# {dd}\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 {dd}\n\nMasses\n\n1 {m}\n"
L("R03_molecule_link_cp", "m.mol -> s.mol (3 mm); shell cp b.mol s.mol (6 mm); molecule sm m.mol; create lv2 from it (create_atoms 0: the molecule's own type 2; LAMMPS: 6 mm)",
  "shell cp b.mol s.mol\nmolecule sm m.mol\ncreate_atoms 0 single 0.0235 0.02 0.05 mol sm 4567\ngroup lv2 type 2\nvelocity lv2 set " + f"{m7.m.V2:.10f}" + " 0 0 units box\nrun 3000\n",
  pair="create_atoms 1 single 0.0179500 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set " + f"{m7.m.V1:.10f}" + " 0 0 units box\n",
  pre=m7.BASE(wall=False, head="atom_modify map array\n"), data={"s.mol": mol(0.003, 3.534e-5), "b.mol": mol(0.006, 2.82743e-4)})
LINKS["R03"] = [("m.mol", "s.mol")]
L("R04_varfile_hard", "k.txt hard of real.txt (3000); print 5000 file real.txt; variable k file k.txt; kn ${k} (5000)",
  'print "5000" file real.txt screen no\nvariable k file k.txt\n' + PCs("${k}") + "\nrun 3000\n", data={"real.txt": "3000\n"})
HARD["R04"] = [("k.txt", "real.txt")]
L("R05_varfile_dirlink", "sub -> real_sub; print 5000 file real_sub/k.txt; variable k file sub/k.txt (stale 3000; 5000)",
  'print "5000" file real_sub/k.txt screen no\nvariable k file sub/k.txt\n' + PCs("${k}") + "\nrun 3000\n", data={"real_sub/k.txt": "3000\n"})
LINKS["R05"] = [("sub", "real_sub")]
L("R06_varfile_every_writer_dollar", "f string k.txt; run 1000 every 1000 \"print 5000 file ${f}\"; variable k file k.txt (stale 3000; 5000)",
  "variable f string k.txt\nrun 1000 every 1000 \"print '5000' file ${f} screen no\"\nvariable k file k.txt\n" + PCs("${k}") + "\nrun 3000\n", pair=IN(G11), data={"k.txt": "3000\n"})
L("R07_restart_pct_star_link", "restart 1000 r%.*; run 1000; read_restart l.rst where l.rst -> r%.1000 (stale r%.1000 files lv2 8000; LAMMPS: its own, 2500)",
  "restart 1000 r%.*\nrun 1000\n" + RR("l%.1000"), pre=MB, pair=IN(G11))
LINKS["R07"] = [("l%.1000", "r%.1000"), ("l0.1000", "r0.1000"), ("lbase.1000", "rbase.1000")]
STALE["R07"] = [("r%", "pct8000")]
L("R08_write_restart_pct_star_if_stale", "stale r%.1000 (8000); run 1000; if then \"write_restart r%.*\"; read_restart r%.1000 (LAMMPS 2500)",
  "run 1000\nif \"1 > 0\" then \"write_restart r%.*\"\n" + RR("r%.1000"), pre=MB, pair=IN(G11))
STALE["R08"] = [("r%", "pct8000")]
L("R09_write_restart_dollar_star_stale", "stale r.1000 (8000); variable s string r; run 1000; write_restart ${s}.*; read_restart r.1000 (LAMMPS 2500)",
  "variable s string r\nrun 1000\nwrite_restart ${s}.*\n" + RR("r.1000"), pair=IN(G11))
STALE["R09"] = [("r.1000", "rst8000")]
L("R10_loop_write_read_other_name", "stale a.rst (8000); loop pass 1: run 1000, lv2 5000, write_restart a.rst; pass 2: read_restart b.rst (-> a.rst) (LAMMPS 5000)",
  "variable i loop 2\nlabel lp\nif \"${i} == 2\" then \"jump SELF second\"\nrun 1000\nset atom 2 density 5000\nwrite_restart a.rst\nnext i\njump SELF lp\nlabel second\n" + RR("b.rst"),
  pair=IN(G11))
LINKS["R10"] = [("b.rst", "a.rst")]
STALE["R10"] = [("a.rst", "rst8000")]
L("R11_loop_write_read_by_index", "stale p1.rst (8000); loop pass 1: run 1000, lv2 5000, write_restart p${i}.rst; pass 2: read_restart p$(v_i-1).rst (LAMMPS 5000)",
  "variable i loop 2\nlabel lp\nif \"${i} == 2\" then \"jump SELF second\"\nrun 1000\nset atom 2 density 5000\nwrite_restart p${i}.rst\nnext i\njump SELF lp\nlabel second\n" + RR("p$(v_i-1).rst"),
  pair=IN(G11))
STALE["R11"] = [("p1.rst", "rst8000")]
L("R12_loop_star_read_other_pass", "stale r.1000 (8000); loop 2 passes: run 1000; pass 1 lv2 5000 write_restart r.* (r.1000)... pass 2 read_restart r.1000 (LAMMPS 5000)",
  "variable i loop 2\nlabel lp\nif \"${i} == 2\" then \"jump SELF second\"\nrun 1000\nset atom 2 density 5000\nwrite_restart r.*\nnext i\njump SELF lp\nlabel second\n" + RR("r.1000"),
  pair=IN(G11))
STALE["R12"] = [("r.1000", "rst8000")]
L("R13_include_writes_star_link_read", "stale r.1000 (8000); run 1000; lv2 5000; include w.in (write_restart r.*); read_restart l.rst (-> r.1000) (LAMMPS 5000)",
  "run 1000\nset atom 2 density 5000\ninclude w.in\n" + RR("l.rst"), pair=IN(G11), data={"w.in": "write_restart r.*\n"})
LINKS["R13"] = [("l.rst", "r.1000")]
STALE["R13"] = [("r.1000", "rst8000")]
L("R14_every_write_data_link", "stale d.data (8000); lv2 5000; run 1000 every 1000 \"write_data d.data\"; read_data l.data (-> d.data) (LAMMPS 5000)",
  "set atom 2 density 5000\nrun 1000 every 1000 \"write_data d.data\"\nclear\n" + MDH.format(f="l.data") + "run 3000\n", pair=IN(G11))
LINKS["R14"] = [("l.data", "d.data")]
STALE["R14"] = [("d.data", "data8000")]
L("R15_write_data_hard_sub", "a/h.data hard of b/d.data (stale 8000); run 1000; lv2 5000; write_data b/d.data; read_data a/h.data (write_data truncates in place? LAMMPS decides)",
  "run 1000\nset atom 2 density 5000\nwrite_data b/d.data\nclear\n" + MDH.format(f="a/h.data") + "run 3000\n", pair=IN(G11), data={"a/keep.txt": "x\n"})
HARD["R15"] = [("a/h.data", "b/d.data")]
STALE["R15"] = [("b/d.data", "data8000")]
L("R16_write_restart_cd_sub", "stale sub/r.rst (8000); run 1000; lv2 5000; shell cd sub; write_restart r.rst; shell cd ..; read_restart sub/r.rst (LAMMPS 5000)",
  "run 1000\nset atom 2 density 5000\nshell cd sub\nwrite_restart r.rst\nshell cd ..\n" + RR("sub/r.rst"), pair=IN(G11))
STALE["R16"] = [("sub/r.rst", "rst8000")]
L("R17_dollar_every_restart", "stale r.1000 (8000); variable s string r; restart 1000 ${s}.*; run 1000; read_restart r.1000 (LAMMPS 2500)",
  "variable s string r\nrestart 1000 ${s}.*\nrun 1000\n" + RR("r.1000"), pair=IN(G11))
STALE["R17"] = [("r.1000", "rst8000")]

# ---------------------------------------------------------------- L: LIGGGHTS forms
LG("L01_lig_link_print_file", "LIGGGHTS: link.in -> real.in (e 0.6); print e 0.8 file real.in; include link.in (0.8)",
   'print "' + LE.format(e="0.8") + '" file real.in screen no\ninclude link.in\nrun 3000\n', data={"real.in": LEe(0.6)})
LINKS["L01"] = [("link.in", "real.in")]
LG("L02_lig_hard_cp", "LIGGGHTS: h.in hard of real.in (0.6); shell cp new.in real.in (0.8, same inode); include h.in (0.8)",
   "shell cp new.in real.in\ninclude h.in\nrun 3000\n", data={"real.in": LEe(0.6), "new.in": LEe(0.8)})
HARD["L02"] = [("h.in", "real.in")]
LG("L03_lig_every_print_link", "LIGGGHTS: link.in -> real.in (0.6); run 1000 every 1000 \"print e 0.8 file real.in\"; include link.in (0.8)",
   "run 1000 every 1000 \"print '" + LE.format(e="0.8") + "' file real.in screen no\"\ninclude link.in\nrun 3000\n", pair=LIN(G11), data={"real.in": LEe(0.6)})
LINKS["L03"] = [("link.in", "real.in")]
LG("L04_lig_sublink_mv", "LIGGGHTS: sub/l.in -> ../real.in (0.6); shell mv new.in real.in (0.8); include sub/l.in (0.8)",
   "shell mv new.in real.in\ninclude sub/l.in\nrun 3000\n", data={"real.in": LEe(0.6), "new.in": LEe(0.8), "sub/keep.txt": "x\n"})
LINKS["L04"] = [("sub/l.in", "../real.in")]
LG("L05_lig_varfile_link", "LIGGGHTS: k.txt -> real.txt (0.6); print 0.8 file real.txt; variable e file k.txt; e ${e} (0.8)",
   'print "0.8" file real.txt screen no\nvariable e file k.txt\n' + LE.format(e="${e}") + "\nrun 3000\n", data={"real.txt": "0.6\n"})
LINKS["L05"] = [("k.txt", "real.txt")]
LG("L06_lig_jump_link", "LIGGGHTS: j.in -> real.in (stale e 0.6 + run + jump back); print the 0.8 script file real.in; jump j.in (0.8)",
   'print "' + LE.format(e="0.8") + '" file real.in screen no\nprint "run 3000" append real.in screen no\nprint "jump in.deck back" append real.in screen no\njump j.in\nlabel back\n',
   data={"real.in": LEe(0.6) + "run 3000\njump in.deck back\n"})
LINKS["L06"] = [("j.in", "real.in")]

# ---------------------------------------------------------------- C: controls (plain decks; links left alone)
L("C01_plain_kn5000", "plain: kn 5000 (0.578975)", PC5 + "run 3000\n")
L("C02_link_untouched", "link.in -> real.in (5000), nothing writes it; include link.in", "include link.in\nrun 3000\n", data={"real.in": PC5})
LINKS["C02"] = [("link.in", "real.in")]
L("C03_hard_untouched_sub", "a/h.in hard of b/real.in (5000); include a/h.in", "include a/h.in\nrun 3000\n", data={"b/real.in": PC5, "a/keep.txt": "x\n"})
HARD["C03"] = [("a/h.in", "b/real.in")]
L("C04_dirlink_untouched", "sub -> real_sub (pc.in 5000); include sub/pc.in", "include sub/pc.in\nrun 3000\n", data={"real_sub/pc.in": PC5})
LINKS["C04"] = [("sub", "real_sub")]
LG("C05_lig_plain_e07", "LIGGGHTS plain: e 0.7 (0.700061)", LEe(0.7) + "run 3000\n")
L("C06_star_restart_plain", "run 1000; lv2 5000; write_restart r.*; read_restart r.1000 (5000: 0.390402)", "run 1000\nset atom 2 density 5000\nwrite_restart r.*\n" + RR("r.1000"), pair=IN(G11))

# ---------------------------------------------------------------- X: neighbours added after the first audits (A13 A14's copy error; R07's link)
L("A17_cd_sub_link_untouched", "sub/l.in -> r.in (sub/r.in 5000), nothing writes it; shell cd sub; include l.in; shell cd .. (5000)",
  "shell cd sub\ninclude l.in\nshell cd ..\nrun 3000\n", data={"sub/r.in": PC5})
LINKS["A17"] = [("sub/l.in", "r.in")]
L("A18_cd_sub_link_unread", "sub/other.in -> r.in (a link the deck never names); shell cd sub; include pc.in (sub/pc.in 5000); shell cd ..",
  "shell cd sub\ninclude pc.in\nshell cd ..\nrun 3000\n", data={"sub/r.in": PC3, "sub/pc.in": PC5})
LINKS["A18"] = [("sub/other.in", "r.in")]
L("A19_cd_dotdot_link_top", "top l.in -> r.in (5000); shell cd sub; include ../l.in; shell cd .. (5000)",
  "shell cd sub\ninclude ../l.in\nshell cd ..\nrun 3000\n", data={"r.in": PC5, "sub/keep.txt": "x\n"})
LINKS["A19"] = [("l.in", "r.in")]
L("R18_restart_star_link_stale", "restart 1000 r.*; run 1000; read_restart l.rst (-> r.1000; stale r.1000 lv2 8000; LAMMPS: its own, 2500)",
  "restart 1000 r.*\nrun 1000\n" + RR("l.rst"), pair=IN(G11))
LINKS["R18"] = [("l.rst", "r.1000")]
STALE["R18"] = [("r.1000", "rst8000")]
L("R19_restart_pct_star_hard", "restart 1000 r%.*; run 1000; read_restart l%.1000 where lbase.1000 / l0.1000 are hard links of the stale r%.1000 files (8000; LAMMPS: restart opens anew, the links keep 8000)",
  "restart 1000 r%.*\nrun 1000\n" + RR("l%.1000"), pre=MB, pair=IN(G11))
HARD["R19"] = [("l0.1000", "r0.1000"), ("lbase.1000", "rbase.1000")]
STALE["R19"] = [("r%", "pct8000")]
L("R20_write_restart_pct_plain_link", "stale r%.1000 (8000); run 1000; write_restart r%.*; read_restart l%.1000 (links to r%.1000 files; LAMMPS 2500)",
  "run 1000\nwrite_restart r%.*\n" + RR("l%.1000"), pre=MB, pair=IN(G11))
LINKS["R20"] = [("l0.1000", "r0.1000"), ("lbase.1000", "rbase.1000")]
STALE["R20"] = [("r%", "pct8000")]
L("R21_restart_pct_star_plain", "restart 1000 r%.*; run 1000; read_restart r%.1000 (stale r%.1000 8000: round 37's R07 again; LAMMPS 2500)",
  "restart 1000 r%.*\nrun 1000\n" + RR("r%.1000"), pre=MB, pair=IN(G11))
STALE["R21"] = [("r%", "pct8000")]
L("R22_restart_link_above", "restart 1000 r.*; run 1000; read_restart l.rst where l.rst -> ../../shared/r.1000 (outside; the engine reads the shared stale 8000 file; LAMMPS 0.3809)",
  "restart 1000 r.*\nrun 1000\n" + RR("l.rst"), pair=IN(G11))
LINKS["R22"] = [("l.rst", "../../shared/r.1000")]
L("R23_restart_pct_star_link_np2", "R07 with a link for a second process's file too (l1.1000 -> r1.1000, dangling until the engine on 2 processes writes it); 1 and 2 processes (LAMMPS 2500 on both)",
  "restart 1000 r%.*\nrun 1000\n" + RR("l%.1000"), pre=MB, pair=IN(G11), NP="1 2")
LINKS["R23"] = [("l0.1000", "r0.1000"), ("l1.1000", "r1.1000"), ("lbase.1000", "rbase.1000")]
STALE["R23"] = [("r%", "pct8000")]
L("R24_restart_star_hardlink_stale", "restart 1000 r.*; run 1000; read_restart l.rst, a hard link of the stale r.1000 (8000; LAMMPS: restart truncates in place, 2500)",
  "restart 1000 r.*\nrun 1000\n" + RR("l.rst"), pair=IN(G11))
HARD["R24"] = [("l.rst", "r.1000")]
STALE["R24"] = [("r.1000", "rst8000")]
L("R25_if_write_restart_pct_link", "stale r%.1000 (8000); run 1000; if then \"write_restart r%.*\"; read_restart l%.1000 (links lbase/l0 -> rbase/r0; LAMMPS 2500)",
  "run 1000\nif \"1 > 0\" then \"write_restart r%.*\"\n" + RR("l%.1000"), pre=MB, pair=IN(G11))
LINKS["R25"] = [("l0.1000", "r0.1000"), ("lbase.1000", "rbase.1000")]
STALE["R25"] = [("r%", "pct8000")]
L("R26_write_restart_pct_fixed_name_link", "stale rbase.rst/r0.rst... : run 1000; write_restart r%.rst (no *); read_restart l%.rst (links; LAMMPS 2500)",
  "run 1000\nwrite_restart r%.rst\n" + RR("l%.rst"), pre=MB, pair=IN(G11))
LINKS["R26"] = [("l0.rst", "r0.rst"), ("lbase.rst", "rbase.rst")]
STALE["R26"] = [("r%", "pct8000rst")]
L("W12_jump_deck_via_link_loop", "l.deck -> in.deck; loop of 2 passes by jump l.deck lp: kn 3000 then 5000, run 1000 each (pass 2: 5000)",
  "variable i loop 2\nlabel lp\n" + PCs("$(1000+2000*v_i)") + "\nrun 1000\nnext i\njump l.deck lp\n", pair=IN(G11), live="pass 2")
LINKS["W12"] = [("l.deck", "in.deck")]
L("A20_link_loop_unnamed", "the folder holds a link loop (a.in -> b.in -> a.in) the deck never names; plain kn 5000", PC5 + "run 3000\n")
LINKS["A20"] = [("a.in", "b.in"), ("b.in", "a.in")]
L("A21_dangling_link_unnamed", "the folder holds a dangling link (x.in -> gone.in) the deck never names; plain kn 5000", PC5 + "run 3000\n")
LINKS["A21"] = [("x.in", "gone.in")]
L("A22_link_to_parent_unnamed", "the folder holds up -> .. (its parent) the deck never names; plain kn 5000", PC5 + "run 3000\n")
LINKS["A22"] = [("up", "..")]
L("A23_link_to_self_dir", "the folder holds here -> . ; include here/pc.in (5000)", "include here/pc.in\nrun 3000\n", data={"pc.in": PC5})
LINKS["A23"] = [("here", ".")]
L("R27_write_restart_pct_link_nostale", "R26 without the stale rbase.rst and r0.rst: the links lbase.rst, l0.rst dangle until write_restart r%.rst (LAMMPS 2500: 0.413435)",
  "run 1000\nwrite_restart r%.rst\n" + RR("l%.rst"), pre=MB, pair=IN(G11))
LINKS["R27"] = [("l0.rst", "r0.rst"), ("lbase.rst", "rbase.rst")]
L("R28_restart_pct_dirlink", "d -> real_d (a folder link); stale real_d/r%.1000 (8000); restart 1000 real_d/r%.*; run 1000; read_restart d/r%.1000 (LAMMPS 2500)",
  "restart 1000 real_d/r%.*\nrun 1000\n" + RR("d/r%.1000"), pre=MB, pair=IN(G11))
LINKS["R28"] = [("d", "real_d")]
STALE["R28"] = [("real_d/r%", "pct8000")]
L("R29_restart_pct_star_read_star_link", "stale r%.1000 (8000); restart 1000 r%.*; run 1000; read_restart l%.* (lbase.1000 -> rbase.1000, l0.1000 -> r0.1000; LAMMPS 2500)",
  "restart 1000 r%.*\nrun 1000\n" + RR("l%.*"), pre=MB, pair=IN(G11))
LINKS["R29"] = [("l0.1000", "r0.1000"), ("lbase.1000", "rbase.1000")]
STALE["R29"] = [("r%", "pct8000")]
L("A24_link_loop_in_sub_unnamed", "sub holds a link loop (sub/a.in -> b.in -> a.in) the deck never names; plain kn 5000", PC5 + "run 3000\n", data={"sub/keep.txt": "x\n"})
LINKS["A24"] = [("sub/a.in", "b.in"), ("sub/b.in", "a.in")]
L("A25_include_link_loop", "include a.in where a.in -> b.in -> a.in (a loop: LAMMPS stops, Cannot open); kn 5000 before", PC5 + "include a.in\nrun 3000\n")
LINKS["A25"] = [("a.in", "b.in"), ("b.in", "a.in")]
L("A26_self_link_unnamed", "the folder holds x.in -> x.in (a link to itself) the deck never names; plain kn 5000", PC5 + "run 3000\n")
LINKS["A26"] = [("x.in", "x.in")]

D8000 = m7.D8000


def stale(d, f, kind):
    os.makedirs(os.path.dirname(os.path.join(d, f)), exist_ok=True)
    if kind == "rst8000" and not os.path.exists(os.path.join(d, f)):
        m7.lmp_gen(D8000 + "run 1000\nwrite_restart x.rst\n", [("x.rst", f)], d)
    if kind == "data8000" and not os.path.exists(os.path.join(d, f)):
        m7.lmp_gen(D8000 + "run 1000\nwrite_data x.data\n", [("x.data", f)], d)
    if kind == "pct8000" and f != "r%":      # in a subfolder: sub/r%
        sub = os.path.join(d, os.path.dirname(f))
        return stale(sub, "r%", kind)
    if kind == "pct8000" and not os.path.exists(os.path.join(d, "rbase.1000")):
        m7.lmp_gen(MB + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")
                   + "run 1000\nwrite_restart r%.*\n", [("rbase.1000", "rbase.1000"), ("r0.1000", "r0.1000")], d)
    if kind == "pct8000rst" and not os.path.exists(os.path.join(d, "rbase.rst")):
        m7.lmp_gen(MB + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")
                   + "run 1000\nwrite_restart r%.rst\n", [("rbase.rst", "rbase.rst"), ("r0.rst", "r0.rst")], d)
    if kind == "dump0" and not os.path.exists(os.path.join(d, f)):
        m7.lmp_gen(RB + IN(G11) + "run 1000\nvelocity lv2 set 0 0 0 units box\nwrite_dump all custom x.dump id type x y z vx vy vz\n", [("x.dump", f)], d)


def write(only=()):
    names = [n for n in m7.DECKS if not only or any(n.startswith(p) for p in only)]
    for n in names:        # subfolders the links need
        for a, b in LINKS.get(n[:3], []) + HARD.get(n[:3], []):
            os.makedirs(os.path.dirname(os.path.join(m7.D, n, a)), exist_ok=True)
            os.makedirs(os.path.dirname(os.path.join(m7.D, n, b)), exist_ok=True)
        for f, k in STALE.get(n[:3], []):
            stale(os.path.join(m7.D, n), f, k)
    m7.write(only)
    sh = os.path.join(HERE, "shared")
    os.makedirs(sh, exist_ok=True)
    open(os.path.join(sh, "pc5.in"), "w").write(PC5)
    open(os.path.join(sh, "pc3.in"), "w").write(PC3)
    stale(sh, "r.1000", "rst8000")


if __name__ == "__main__":
    write(sys.argv[1:])
