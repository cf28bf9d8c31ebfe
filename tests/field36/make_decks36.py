"""Field round 36: write decks/NAME/in.deck (and the files a deck reads) for the referee live36.py and the audit.

An adversarial check of main db6d9a8b: replicate then `run N pre no` (a still stage, left out; P decks), `run N every M`
made as its parts with commands that read nothing of the step mixed with ones that do (E), several processes with
write_restart/read_restart (M), LIGGGHTS' run every (L), the issue's nine classes again (K pair_coeff ranges and labels,
V variables and formats, Q set order, Y restyles, W walls-only material, S several sizes in a type, T the time-step
note) and public decks shortened (O, sources in FINDINGS.md). The live pair and its helpers are round 35's
(make_decks35.py, imported): type 1 of 4 mm (lv1) / type 2 of 6 mm (lv2), 2500 kg/m3, hooke kn 2000 damping 3000
mass_velocity, dt 1e-6 s, meeting at 1 m/s 0.1 ms into the run or part named in LIVE. Folder files as round 35's.
usage: python make_decks36.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field35"))
import make_decks35 as m  # noqa: E402  (round 35's helpers; its own DECKS are not written here)

D = os.path.join(HERE, "decks")
DECKS = {}
BASE, IN, WALLP, LBASE, LIN, LWALL, PER = m.BASE, m.IN, m.WALLP, m.LBASE, m.LIN, m.LWALL, m.PER
HK, HK5, WHK, G, G11, PCs, EV, LE, LEV = m.HK, m.HK5, m.WHK, m.G, m.G11, m.PCs, m.EV, m.LE, m.LEV
VZ, WALL = m.VZ, m.WALL
RB = BASE(wall=False)
FFFX = BASE(boundary="f f f", head="processors * 1 1\n")
HKk = lambda k: f"hooke {k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def L(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    """A LAMMPS deck: # desc, `pre` (BASE()), `pair` (IN(0.1e-3)), `body`."""
    pre = BASE() if pre is None else pre
    pair = IN(0.1e-3) if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


def RAW(name, desc, text, live="last run", data=None, **meta):
    DECKS[name] = ("# " + desc + "\n" + text, live, data or {}, meta)


def LG(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN(0.1e-3) if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


# ================================================================ P: replicate then run N pre no (session 26 rule)
L("P01_rep_preno_then_run", "run 1000; replicate 1 1 1; run 1000 pre no (still); run 3000 (meets there: kn 2000)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P02_rep_preno_pc_then_run", "run 1000; replicate; run 1000 pre no; pair_coeff 1 2 kn 5000; run 3000 (meets: 5000)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\n" + PCs(5000) + "\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P03_rep_pc_preno_then_run", "run 1000; replicate; pair_coeff 1 2 kn 5000; run 1000 pre no (still); run 3000 (meets: 5000)",
  "run 1000\nreplicate 1 1 1\n" + PCs(5000) + "\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P04_rep_preno_preno_run", "run 1000; replicate; run 1000 pre no; run 1000 pre no; run 4000 (does the second pre no move?)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 1000 pre no\nrun 4000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P05_rep_loop_preno", "run 1000; a loop of 2: replicate; run 1000 pre no; then run 3000 (meets)",
  "run 1000\nvariable i loop 2\nlabel lp\nreplicate 1 1 1\nrun 1000 pre no\nnext i\njump SELF lp\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P06_rep_velocity_preno", "run 1000; replicate; velocity lv1 set (same); run 1000 pre no; run 3000",
  f"run 1000\nreplicate 1 1 1\nvelocity lv1 set {m.V1:.10f} 0 0 units box\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P07_rep_include_preno_run", "run 1000; include r.in (replicate); run 1000 pre no; run 3000", "run 1000\ninclude r.in\nrun 1000 pre no\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3), data={"r.in": "replicate 1 1 1\n"})
L("P08_rep_preno_every_print", "run 1000; replicate; run 3000 pre no every 1000 \"print x\" (LAMMPS sets up the first part of an every run: moves)",
  'run 1000\nreplicate 1 1 1\nrun 3000 pre no every 1000 "print P_$(step)"\n', pre=RB, pair=IN(G11))
L("P09_rep_preno_every_set", "run 1000; replicate; run 3000 pre no every 1000 \"set type 1 density 2500\" (split: part 1 set up; meets in part 1)",
  'run 1000\nreplicate 1 1 1\nrun 3000 pre no every 1000 "set type 1 density 2500"\n', pre=RB, pair=IN(G11), live="part 1")
L("P10_rep_preno_every_step_pc", "run 1000; replicate; run 3000 pre no every 1000 \"pair_coeff 1 2 $(2000+step)\" (meets in part 1: 2000)",
  'run 1000\nreplicate 1 1 1\nrun 3000 pre no every 1000 "' + PCs("$(2000+step)") + '"\n', pre=RB, pair=IN(G11), live="part 1")
L("P11_rep_211_preno_run", "run 1000; replicate 2 1 1; run 1000 pre no; run 3000 (copies 0.04 apart)",
  "run 1000\nreplicate 2 1 1\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P12_rep_if_preno_run", "run 1000; if then replicate; run 1000 pre no; run 3000", "run 1000\nif \"1 > 0\" then \"replicate 1 1 1\"\nrun 1000 pre no\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3))
L("P13_rep_preno_wall", "WALL: run 500; replicate; run 1000 pre no (still); run 3000 (falls on the floor there)",
  "run 500\nreplicate 1 1 1\nrun 1000 pre no\nrun 3000\n", pair=WALLP(0.0006), **WALL)
L("P14_rep_run0_preno_preno", "run 1000; replicate; run 0; run 1000 pre no; run 3000 pre no (set up by run 0: meets in run 4)",
  "run 1000\nreplicate 1 1 1\nrun 0\nrun 1000 pre no\nrun 3000 pre no\n", pre=RB, pair=IN(G11 + 1e-3))
L("P15_rep_every_last_then_preno", "run 2000 every 1000 \"replicate 1 1 1\"; run 1000 pre no (after replicate: still); run 3000",
  'run 2000 every 1000 "replicate 1 1 1"\nrun 1000 pre no\nrun 3000\n', pre=RB, pair=IN(2.1e-3))
L("P16_rep_neigh_preno_run", "run 1000; replicate; neigh_modify delay 0 every 1 check no; run 1000 pre no; run 3000",
  "run 1000\nreplicate 1 1 1\nneigh_modify delay 0 every 1 check no\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P17_rep_wallfix_preno_run", "run 1000; replicate; fix floor wall/gran added; run 1000 pre no; run 3000",
  "run 1000\nreplicate 1 1 1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("P18_rep_preno_startstop", "run 1000; replicate; run 1000 start 0 stop 5000 pre no; run 3000", "run 1000\nreplicate 1 1 1\nrun 1000 start 0 stop 5000 pre no\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3))
L("P19_rep_first_preno_then_preno", "replicate before any run; run 1000 pre no (first run: set up); run 3000 pre no (meets)",
  "replicate 1 1 1\nrun 1000 pre no\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("P20_rep_preno_meets_in_still", "run 1000; replicate; run 3000 pre no (the pair would meet here: LAMMPS moves nothing); run 3000",
  "run 1000\nreplicate 1 1 1\nrun 3000 pre no\nrun 3000\n", pre=RB, pair=IN(G11))
L("P21_rep_preno_np2_fff", "f f f processors * 1 1: run 1000; replicate; run 1000 pre no; run 3000 (1 and 2 processes)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 3000\n", pre=BASE(boundary="f f f", head="processors * 1 1\n", wall=False), pair=IN(G11 + 1e-3))
L("P22_rep_preno_set_region_after", "run 1000; replicate; run 1000 pre no (still); set region x<0.018 type 2 catches lv1 only where it did not move; run 3000",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nregion lft block 0 0.018 0 0.04 0 0.1 units box\nset region lft type 2\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3), PAIR="types 2 2")
L("P23_rep_preno_pc_every_after", "run 1000; replicate; run 1000 pre no; run 4000 every 1000 \"pair_coeff 1 2 $(2000+step)\" (meets in part 2: step 3000 -> kn 5000)",
  'run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 4000 every 1000 "' + PCs("$(2000+step)") + '"\n', pre=RB, pair=IN(G11 + 1e-3), live="part 2")
L("P24_rep_delete_preno_run", "run 1000; create a far sphere; replicate; delete_atoms the far one; run 1000 pre no; run 3000",
  "create_atoms 1 single 0.005 0.005 0.08\nrun 1000\nreplicate 1 1 1\ngroup far id 3\ndelete_atoms group far\nrun 1000 pre no\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3))
L("P25_rep_preno_every_whole_then_preno", "run 1000; replicate; run 1000 pre no every 500 \"print x\" (whole: LAMMPS sets it up); run 3000 pre no (meets)",
  'run 1000\nreplicate 1 1 1\nrun 1000 pre no every 500 "print Q_$(step)"\nrun 3000 pre no\n', pre=RB, pair=IN(G11 + 1e-3))
L("P26_rep_timestep_preno_run", "run 1000; replicate; timestep 1e-6 (again); run 1000 pre no; run 3000", "run 1000\nreplicate 1 1 1\ntimestep 1e-6\nrun 1000 pre no\nrun 3000\n",
  pre=RB, pair=IN(G11 + 1e-3))
L("P27_rep_every_preno_rep", "run 4000 pre no every 1000 \"replicate 1 1 1\" (R04 again: parts 2-4 still; meets in part 1)",
  'run 4000 pre no every 1000 "replicate 1 1 1"\n', pre=RB, pair=IN(0.1e-3), live="part 1")
L("P28_rep_preno_upto", "run 1000; replicate; run 2000 upto pre no; run 3000", "run 1000\nreplicate 1 1 1\nrun 2000 upto pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))

# P3x: other commands that remake or reorder the atoms before run N pre no (is replicate the only still maker?)
for n, c in [("P31_reset_atoms_id", "reset_atoms id"), ("P32_reset_atoms_id_sort", "reset_atoms id sort yes"),
             ("P33_unfix_refix_integ", "unfix integ\nfix integ2 all nve/sphere"), ("P34_atom_modify_sort", "atom_modify sort 1 0.002"),
             ("P35_change_box_remap", "change_box all x final 0 0.04 remap units box"), ("P36_delete_far_compress", "group far id 3\ndelete_atoms group far compress yes"),
             ("P37_create_far", "create_atoms 1 single 0.005 0.005 0.08"), ("P38_velocity_zero_far", "group far id 3\nvelocity far set 0 0 0 units box"),
             ("P39_fix_freeze_far", "group far id 3\nfix fr far freeze"), ("P40_set_type_far", "group far id 3\nset group far type 2")]:
    far = "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.004 density 2500\n" if n not in ("P37_create_far",) else ""
    L(n + "_preno", f"run 1000; {c.replace(chr(10), '; ')}; run 3000 pre no (meets there)", far + "run 1000\n" + c + "\nrun 3000 pre no\n", pre=RB, pair=IN(G11))

# ================================================================ E: run every made as parts, step readers mixed with commands that read nothing of it
STEP = PCs("$(2000+step)")
FAR = "create_atoms 1 single 0.005 0.005 0.08\ngroup far id 3\nset group far diameter 0.004 density 2500\n"
MIX = [
    ("E01_set_density_const", "set type 1 density 2500"),
    ("E02_velocity_far", "velocity far set 0 0 0 units box"),
    ("E03_displace_far", "displace_atoms far move 0 0 0 units box"),
    ("E04_fix_unfix", "fix tmp all viscous 0.0"),
    ("E05_group", "group t1 type 1"),
    ("E06_delete_far", "delete_atoms group far"),
    ("E07_change_box", "change_box all z final 0 0.1 units box"),
    ("E08_neigh_modify", "neigh_modify delay 0 every 1 check yes"),
    ("E09_pair_coeff_22", "pair_coeff 2 2 " + HK5),
    ("E10_wall_fix", "fix floor all wall/gran " + WHK + " zplane 0 NULL"),
    ("E11_timestep_same", "timestep 1e-6"),
    ("E12_set_diameter_far", "set group far diameter 0.003"),
]
for n, c in MIX:
    L(n + "_then_step", f"every \"{c}\" then the step's pair_coeff 1 2 (part 2: kn 3000)", FAR + EV(c, STEP), pair=IN(G(2)), live="part 2")
for n, c in MIX[:8]:
    nn = "E" + str(int(n[1:3]) + 20) + n[3:]
    L(nn + "_after_step", f"every the step's pair_coeff 1 2 then \"{c}\" (part 3: kn 4000)", FAR + EV(STEP, c), pair=IN(G(3)), live="part 3")
L("E31_pc_const_after_step", "every step pair_coeff then pair_coeff 1 2 kn 5000 then set density (part 2: 5000)", EV(STEP, PCs(5000), "set type 1 density 2500"),
  pair=IN(G(2)), live="part 2")
L("E32_set_density_step_and_const", "every \"set type 2 density $(2500+step)\" \"set type 2 density 2500\" (the constant last: 2500; part 2)",
  EV("set type 2 density $(2500+step)", "set type 2 density 2500"), pair=IN(G(2)), live="part 2")
L("E33_set_density_step", "every \"set atom 2 density $(2500+step)\" (part 2: density 3500 for lv2: mass up)",
  EV("set atom 2 density $(2500+step)"), pair=IN(G(2)), live="part 2")
L("E34_velocity_then_step", "every \"velocity far set 0 0 0\" \"variable k equal 2000+step\" \"pair_coeff 1 2 ${k}\" (part 3: 4000)",
  FAR + EV("velocity far set 0 0 0 units box", "variable k equal 2000+step", PCs("${k}")), pair=IN(G(3)), live="part 3")
L("E35_wall_step_mixed_unfix", "WALL: every \"unfix floor\" \"fix floor all wall/gran granular hooke $(2000+step) ...\" (falls in part 2: wall kn 3000)",
  EV("unfix floor", "fix floor all wall/gran granular " + HKk("$(2000+step)") + " zplane 0 NULL"), pair=WALLP(1.1e-3), live="part 2", **WALL)
L("E36_wall_step_set_far", "WALL: every \"set group far density 2500\" \"fix floor ... $(2000+step)\" (part 3: 4000)",
  FAR.replace("id 3", "id 2") + EV("set group far density 2500", "fix floor all wall/gran granular " + HKk("$(2000+step)") + " zplane 0 NULL"), pair=WALLP(2.1e-3), live="part 3", **WALL)
L("E37_excl_then_step", "every \"neigh_modify exclude none\" \"pair_coeff $(2000+step)\" (part 2: 3000)", EV("neigh_modify exclude none", STEP), pair=IN(G(2)), live="part 2")
L("E38_step_np2_fff", "f f f processors * 1 1, every \"displace_atoms far 0\" \"pair_coeff $(2000+step)\" (part 2, 2 processes)",
  FAR + EV("displace_atoms far move 0 0 0 units box", STEP), pre=FFFX, pair=IN(G(2)), live="part 2")
L("E39_preno_mix", "every pre no: \"set type 1 density 2500\" \"pair_coeff 1 2 $(2000+step)\" (part 2)", FAR + EV("set type 1 density 2500", STEP).replace("every", "pre no every"),
  pair=IN(G(2)), live="part 2")
L("E40_set_type_far_step", "every \"set group far type 2\" \"pair_coeff 1 2 $(2000+step)\" (part 3: 4000)", FAR + EV("set group far type 2", STEP), pair=IN(G(3)), live="part 3")
L("E41_delete_then_create", "every \"delete_atoms group far\" \"create_atoms 1 single 0.005 0.005 0.08\" \"group far id 3\"?: no, far made once; pair_coeff step (part 2)",
  FAR + EV("delete_atoms group far", STEP), pair=IN(G(2)), live="part 2")
L("E42_timestep_step_dt", "every \"timestep 1e-6\" \"pair_coeff 1 2 $(2000+1e6*time)\" (part 2: 3000)", EV("timestep 1e-6", PCs("$(2000+1e6*time)")), pair=IN(G(2)), live="part 2")
L("E43_uneven_parts_mix", "run 3500 every 1500 \"group t1 type 1\" \"pair_coeff $(2000+step)\" (meets at step 1600: kn 3500)",
  "run 3500 every 1500 \"group t1 type 1\" \"" + STEP + "\"\n", pair=IN(1.6e-3), live="part 2")
L("E44_every_pc_star_then_step_11", "every \"pair_coeff * * kn 5000\" \"pair_coeff 1 1 $(2000+step)\" (the 1 2 pair: 5000, part 2)",
  EV("pair_coeff * * " + HK5, "pair_coeff 1 1 " + HKk("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E45_change_box_boundary", "every \"change_box all boundary p p f\" \"pair_coeff $(2000+step)\" (part 2)", EV("change_box all boundary p p f", STEP), pair=IN(G(2)), live="part 2")

# ================================================================ M: several processes, write_restart / read_restart
MB = BASE(boundary="f f f", head="processors * 1 1\n", wall=False)
TAILR = "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\n"
L("M01_restart_pair_again_5000", "f f f: run 1000; write_restart; clear; read_restart; pair_style and pair_coeff kn 5000 again; run 3000",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\npair_style granular\npair_coeff * * " + HK5 + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M02_restart_pc_only_5000", "f f f: read_restart; pair_coeff 1 2 kn 5000 only (pair_style from the file); run 3000",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + PCs(5000) + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M03_restart_star_step_name", "write_restart r.* at step 1000 (kn 3000), reset_timestep 0, kn 5000, write_restart r.* (r.0); clear; read_restart r.* (the larger step: kn 3000)",
  "run 1000\n" + PCs(3000) + "\nwrite_restart r.*\nreset_timestep 0\n" + PCs(5000) + "\nwrite_restart r.*\nclear\nread_restart r.*\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(G11))
L("M04_restart_percent", "write_restart a.%.rst (one file a process); read_restart a.%.rst; pair_style again kn 4000", "run 1000\nwrite_restart a.%.rst\nclear\nread_restart a.%.rst\n"
  "pair_style granular\npair_coeff * * " + HKk(4000) + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M05_restart_cmd_periodic", "restart 500 r.* in the run; read_restart r.1000 (kn 2000 then); pair_style again kn 3000 after",
  "restart 500 r.*\nrun 1000\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HKk(3000) + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M06_restart_toggle_files", "restart 500 ra rb; run 1000 every 500 (kn 2000 then 3000 by the step); read_restart rb; run 3000 (pair_coeff from the file)",
  "restart 500 ra.rst rb.rst\nrun 1000 every 500 \"" + PCs("$(2000+step)") + "\"\nclear\nread_restart rb.rst\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M07_restart_star_step_name_every", "run 2000 every 1000 \"pair_coeff $(2000+step)\" \"write_restart r.*\"; read_restart r.1000 (kn 3000)",
  "run 2000 every 1000 \"" + PCs("$(2000+step)") + "\" \"write_restart r.*\"\nclear\nread_restart r.1000\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(2.1e-3))
L("M08_restart_hertz_again", "f f f: read_restart then pair_style granular hertz/material again; run 3000",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\npair_style granular\npair_coeff * * hertz/material 1e7 0.5 0.3 tangential linear_nohistory 1 0.3\n" + TAILR + "run 3000\n",
  pre=MB, pair=IN(G11))
L("M09_restart_no_comm_vel", "f f f: read_restart without comm_modify vel yes again (is it in the file?), pair_style again; run 3000 on 2 processes",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M10_write_restart_preno", "f f f: run 1000; write_restart a.rst (re-ghosts?); run 3000 pre no", "run 1000\nwrite_restart a.rst\nrun 3000 pre no\n", pre=MB, pair=IN(G11))
L("M11_restart_pair_style_other_types", "read_restart; pair_style again with pair_coeff 1 1, 2 2 kn 5000 (1 2 mixed: 5000)",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\npair_style granular\npair_coeff 1 1 " + HK5 + "\npair_coeff 2 2 " + HK5 + "\n" + TAILR + "run 3000\n", pre=MB, pair=IN(G11))
L("M12_restart_data_file", "run 1000; write_data d.data; clear; the head again; read_data d.data; pair again kn 4000; run 3000 (velocities kept)",
  "run 1000\nwrite_data d.data\nclear\nunits si\natom_style sphere 1\nboundary f f f\nprocessors * 1 1\ncomm_modify vel yes\nread_data d.data\n"
  "pair_style granular\npair_coeff * * " + HKk(4000) + "\ngroup lv1 id 1\ngroup lv2 id 2\n" + TAILR + "timestep 1e-6\nrun 3000\n", pre=MB, pair=IN(G11))
L("M13_restart_star_written_twice_same", "write_restart r.* twice at step 1000 (kn 3000 then 5000: the second overwrites); read_restart r.* (5000)",
  "run 1000\n" + PCs(3000) + "\nwrite_restart r.*\n" + PCs(5000) + "\nwrite_restart r.*\nclear\nread_restart r.*\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M14_restart_read_star_variable", "write_restart at step 1000 r.${s} with s = step (kn 3000); reset_timestep 0; kn 5000; write r.0; read_restart r.1000 named by a variable read before the reset",
  "run 1000\nvariable s equal step\nvariable f string r.${s}\n" + PCs(3000) + "\nwrite_restart ${f}\nreset_timestep 0\n" + PCs(5000) + "\nwrite_restart r.0\nclear\nread_restart ${f}\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(G11))

# ================================================================ L: LIGGGHTS run every beyond include
LEVn = lambda n, *cmds: f"run {n} every 1000 " + " ".join('"' + c + '"' for c in cmds) + "\n"
LG("L01_lig_every_next_index", "LIGGGHTS every \"fix m3 ... ${e}\" \"next e\" (e index 0.6 0.7 0.8 0.9 0.95; part 2: 0.7)",
   "variable e index 0.6 0.7 0.8 0.9 0.95\n" + LEV(LE.format(e="${e}"), "next e"), pair=LIN(G(2)), live="part 2")
LG("L02_lig_every_if_var", "LIGGGHTS every 'if \"${s} > 1500\" then \"fix m3 ... 0.8\"' with s = step (part 2 keeps 0.5, part 3 0.8)",
   "variable s equal step\nrun 4000 every 1000 'if \"${s} > 1500\" then \"" + LE.format(e="0.8") + "\"'\n", pair=LIN(G(3)), live="part 3")
LG("L03_lig_every_jump", "LIGGGHTS every \"jump SELF lb\": the jump skips the rest of the run's every and the deck to lb (e 0.8 after lb)",
   LEV("jump SELF lb", LE.format(e="0.7")) + LE.format(e="0.6") + "\nlabel lb\n" + LE.format(e="0.8") + "\nrun 3000\n", pair=LIN(G(5)), live="run 2")
LG("L04_lig_every_preno_changed", "LIGGGHTS: run 1000; fix m3 e 0.8; run 3000 pre no every 1000 \"print x\" (the first part set up: 0.8)",
   "run 1000\n" + LE.format(e="0.8") + '\nrun 3000 pre no every 1000 "print P_$(step)"\n', pair=LIN(G11))
LG("L05_lig_every_unfix_fix_wall", "LIGGGHTS WALL: every \"unfix wprim\" \"fix wprim ... \" with e 1-3 0.9 set before (falls in part 2)",
   LE.format(e="0.5").replace("0.7 0.5", "0.9 0.5").replace("0.7 0.45", "0.9 0.45") + "\n" +
   LEV("unfix wprim", "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0"), pair=LWALL(1.1e-3), live="part 2", PAIR="type 1 on wall wprim")
LG("L06_lig_every_set_density_step", "LIGGGHTS every \"set atom 2 density $(2500+step)\" (hertz e 0.5: any mass)", LEV("set atom 2 density $(2500+step)"), pair=LIN(G(2)), live="part 2")
LG("L07_lig_every_variable_then_include_after", "LIGGGHTS every \"variable e equal $(0.5+step/10000)\"; after the run fix m3 ${e} (0.9); run 3000",
   LEV("variable e equal $(0.5+step/10000)") + LE.format(e="${e}") + "\nrun 3000\n", pair=LIN(G(5)), live="run 2")
LG("L08_lig_every_mixed_group_e", "LIGGGHTS every \"group t1 type 1\" \"fix m3 ... ${e}\" (e of step; part 3: 0.7)",
   "variable e equal 0.5+step/10000\n" + LEV("group t1 type 1", LE.format(e="${e}")), pair=LIN(G(3)), live="part 3")
LG("L09_lig_every_print_file_then_direct", "LIGGGHTS every \"print 'x' file p.txt\" \"fix m3 ... ${e}\" (part 2: 0.6)",
   "variable e equal 0.5+step/10000\n" + LEV("print x file p.txt", LE.format(e="${e}")), pair=LIN(G(2)), live="part 2")
LG("L10_lig_every_pair_style_again", "LIGGGHTS every \"pair_style gran model hertz tangential history\" \"pair_coeff * *\" \"fix m3 ${e}\" (part 2: 0.6)",
   "variable e equal 0.5+step/10000\n" + LEV("pair_style gran model hertz tangential history", "pair_coeff * *", LE.format(e="${e}")), pair=LIN(G(2)), live="part 2")
LG("L11_lig_every_timestep", "LIGGGHTS every \"timestep 1e-6\" \"fix m3 ${e}\" (part 3: 0.7)", "variable e equal 0.5+step/10000\n" + LEV("timestep 1e-6", LE.format(e="${e}")),
   pair=LIN(G(3)), live="part 3")
LG("L12_lig_every_np2", "LIGGGHTS processors 2 1 1: every \"fix m3 ${e}\" (part 2: 0.6) on 2 processes",
   "variable e equal 0.5+step/10000\n" + LEV(LE.format(e="${e}")), pre=LBASE(head="processors 2 1 1\n"), pair=LIN(G(2)), live="part 2")
LG("L13_lig_every_write_restart", "LIGGGHTS every \"write_restart r.rst\" \"fix m3 ${e}\" (part 2: 0.6)", "variable e equal 0.5+step/10000\n" + LEV("write_restart r.rst", LE.format(e="${e}")),
   pair=LIN(G(2)), live="part 2")
LG("L14_lig_every_preno_e_step", "LIGGGHTS run 4000 pre no every 1000 \"fix m3 ${e}\" (part 2: 0.6?)", "variable e equal 0.5+step/10000\n" + LEV(LE.format(e="${e}")).replace("every", "pre no every"),
   pair=LIN(G(2)), live="part 2")


RSTD = lambda a, b: ("run 1000\nset atom 2 density " + a + "\nwrite_restart r.*\nreset_timestep 0\nset atom 2 density " + b + "\nwrite_restart r.*\nclear\nread_restart r.*\n"
                      "pair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n")
L("M15_restart_star_density", "write_restart r.* at step 1000 with lv2 density 5000, reset_timestep 0, density 2500, write r.0; read_restart r.* (LAMMPS: r.1000, 5000); pair given again",
  RSTD("5000", "2500"), pre=BASE(wall=False), pair=IN(G11))
L("M16_restart_star_density_rev", "M15 with 2500 at step 1000 and 5000 at step 0 (LAMMPS reads r.1000: 2500)", RSTD("2500", "5000"), pre=BASE(wall=False), pair=IN(G11))
L("M17_restart_named_step", "write_restart r.* at step 1000; read_restart r.1000 by name; pair given again (kn 4000)",
  "run 1000\nwrite_restart r.*\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HKk(4000) + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M18_restart_star_density_fff_np2", "M15 in f f f processors * 1 1 (1 and 2 processes)", RSTD("5000", "2500"), pre=MB, pair=IN(G11))

L("M19_restart_var_step_density", "M15 with the names r.${s} (s = step: 1000) and r.0 written explicitly; read_restart ${f} (r.1000: lv2 5000)",
  "run 1000\nvariable s equal step\nvariable f string r.${s}\nset atom 2 density 5000\nwrite_restart ${f}\nset atom 2 density 2500\nwrite_restart r.0\nclear\nread_restart ${f}\n"
  "pair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M20_restart_star_then_explicit_r0", "no reset_timestep: write_restart r.* at step 1000 (lv2 5000), then write_restart r.0 (2500); read_restart r.* (LAMMPS: r.1000, 5000)",
  "run 1000\nset atom 2 density 5000\nwrite_restart r.*\nset atom 2 density 2500\nwrite_restart r.0\nclear\nread_restart r.*\n"
  "pair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M21_restart_star_kn_after_read", "M15 with lv2 density 5000 in r.1000 and the law changed after the read (kn 5000): LAMMPS 5000 with lv2 5000",
  RSTD("5000", "2500").replace("pair_coeff * * " + HK, "pair_coeff * * " + HK5), pre=BASE(wall=False), pair=IN(G11))

L("M22_restart_periodic_and_star", "write_restart r.* at step 0 (lv2 2500); restart 1000 r.*; run 1000; set lv2 density 5000; run 1000 (r.2000: 5000); read_restart r.* (LAMMPS r.2000)",
  "write_restart r.*\nrestart 1000 r.*\nrun 1000\nset atom 2 density 5000\nrun 1000\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(2.1e-3))
L("M23_restart_star_every_step_density", "run 2000 every 1000 \"set atom 2 density $(2500+2.5*step)\" \"write_restart r.*\" (r.1000 5000, r.2000 7500); read_restart r.1000 by name",
  "run 2000 every 1000 \"set atom 2 density $(2500+2.5*step)\" \"write_restart r.*\"\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(2.1e-3))
L("M24_restart_star_every_read_star", "M23 read back by read_restart r.* (LAMMPS: r.2000, lv2 7500)",
  "run 2000 every 1000 \"set atom 2 density $(2500+2.5*step)\" \"write_restart r.*\"\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(2.1e-3))

L("M25_restart_star_old_file_shipped", "the folder holds r.500 (an older restart: lv2 density 8000); the deck writes r.* at step 1000 (2500) and reads r.* (LAMMPS: r.1000)",
  "run 1000\nwrite_restart r.*\nclear\nread_restart r.*\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
# r.500 of M25, made by LAMMPS itself when the folder is written (a binary file): the same pair, lv2 at density 8000, step 500
GEN_M25 = (BASE(wall=False) + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000") + "run 500\nwrite_restart r.*\n")

L("M26_restart_r0_then_star", "write_restart r.0 (lv2 2500) at step 0; run 1000; lv2 density 5000; write_restart r.* (LAMMPS r.1000; the pass: r.0 again); read_restart r.0 (LAMMPS: 2500)",
  "write_restart r.0\nrun 1000\nset atom 2 density 5000\nwrite_restart r.*\nclear\nread_restart r.0\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n",
  pre=BASE(wall=False), pair=IN(G11))
MDH = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data {f}\npair_style granular\npair_coeff * * " + HK + "\ngroup lv1 id 1\ngroup lv2 id 2\n" + TAILR + "timestep 1e-6\n"
L("M27_write_data_d0_then_star", "write_data d.0 (lv2 2500) at step 0; run 1000; lv2 density 5000; write_data d.* (LAMMPS d.1000; the pass: d.0 again); clear; read_data d.0 (LAMMPS: 2500)",
  "write_data d.0\nrun 1000\nset atom 2 density 5000\nwrite_data d.*\nclear\n" + MDH.format(f="d.0") + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
L("M28_write_data_star_read_named", "run 1000; lv2 density 5000; write_data d.*; clear; read_data d.1000 (LAMMPS 5000; the pass has no d.1000)",
  "run 1000\nset atom 2 density 5000\nwrite_data d.*\nclear\n" + MDH.format(f="d.1000") + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))

L("M29_restart_named_stale_file_shipped", "the folder holds a stale r.1000 (an older run: lv2 density 8000); the deck writes r.* at step 1000 (2500) and reads r.1000 (LAMMPS: its own, 2500)",
  "run 1000\nwrite_restart r.*\nclear\nread_restart r.1000\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
GEN_M29 = (BASE(wall=False) + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000") + "run 1000\nwrite_restart r.*\n")

L("M30_restart_toggle_stale_shipped", "restart 500 ra.rst rb.rst in the runs (rb.rst at step 1000: lv2 2500); the folder holds a stale rb.rst (lv2 8000); read_restart rb.rst (LAMMPS: its own)",
  "restart 500 ra.rst rb.rst\nrun 1000\nclear\nread_restart rb.rst\npair_style granular\npair_coeff * * " + HK + "\n" + TAILR + "run 3000\n", pre=BASE(wall=False), pair=IN(G11))
GEN_M30 = (BASE(wall=False) + IN(G11).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000") + "run 1000\nwrite_restart rb.rst\n")
# ================================================================ K: pair_coeff type ranges and labels (3 types)
B3 = BASE(nt=3, wall=False)
PCk = lambda spec, k: f"pair_coeff {spec} " + HKk(k) + "\n"
L("K01_range_23_12_live12", "pair_coeff 2*3 1*2 kn 5000: LAMMPS sets 2 2 only (i<=j); the 1 2 pair keeps 2000", PCk("2*3 1*2", 5000) + "run 3000\n", pre=B3)
L("K02_range_23_12_live23", "pair_coeff 2*3 1*2 kn 5000; the live pair types 2 3 (keeps 2000)", PCk("2*3 1*2", 5000) + "run 3000\n", pre=B3, pair=IN(0.1e-3, t1=2, t2=3), PAIR="types 2 3")
L("K03_star_2_live23", "pair_coeff * 2 kn 5000 sets 1 2 and 2 2 only; the live pair 2 3 keeps 2000", PCk("* 2", 5000) + "run 3000\n", pre=B3, pair=IN(0.1e-3, t1=2, t2=3), PAIR="types 2 3")
L("K04_star_2_live12", "pair_coeff * 2 kn 5000; the live pair 1 2 (5000)", PCk("* 2", 5000) + "run 3000\n", pre=B3)
L("K05_2_star_live12", "pair_coeff 2 * kn 5000 sets 2 2 and 2 3; 1 2 keeps 2000", PCk("2 *", 5000) + "run 3000\n", pre=B3)
L("K06_swapped_2_1", "pair_coeff 2 1 kn 5000 (swapped by LAMMPS: 1 2 = 5000)", PCk("2 1", 5000) + "run 3000\n", pre=B3)
L("K07_labels_swapped", "labelmap atom 1 small 2 big 3 rim; pair_coeff big small kn 5000 (1 2 = 5000)", "labelmap atom 1 small 2 big 3 rim\n" + PCk("big small", 5000) + "run 3000\n", pre=B3)
L("K08_labels_star_big", "labelmap; pair_coeff * big kn 5000 (1 2 and 2 2 = 5000)", "labelmap atom 1 small 2 big 3 rim\n" + PCk("* big", 5000) + "run 3000\n", pre=B3)
L("K09_range_mixed_from_own", "pair_coeff 1 1, 2 2, 3 3 only (kn 2000), then 2*3 1*2 kn 5000 (2 2 only): 1 2 mixed sqrt(2000*5000)",
  "", pre=BASE(nt=3, wall=False, coeff=PCk("1 1", 2000) + PCk("2 2", 2000) + PCk("3 3", 2000)), pair=IN(0.1e-3) + PCk("2*3 1*2", 5000) + "run 3000\n")
L("K10_range_12_23", "pair_coeff 1*2 2*3 kn 5000 (1 2, 1 3, 2 2, 2 3): 1 2 = 5000", PCk("1*2 2*3", 5000) + "run 3000\n", pre=B3)
L("K11_range_empty", "pair_coeff 3*3 1*1 kn 5000 (no pair: LAMMPS stops)", PCk("3*3 1*1", 5000) + "run 3000\n", pre=B3)
L("K12_range_open_low", "pair_coeff *2 * kn 5000 (1 1 1 2 1 3 2 2 2 3): 1 2 = 5000", PCk("*2 *", 5000) + "run 3000\n", pre=B3)
L("K13_labels_create_atoms", "labelmap atom 1 small 2 big; the live pair made by create_atoms with the labels; pair_coeff small big kn 4000",
  "", pre=BASE(nt=2, wall=False) + "labelmap atom 1 small 2 big\n" + PCk("small big", 4000),
  pair=IN(0.1e-3).replace("create_atoms 1 single", "create_atoms small single").replace("create_atoms 2 single", "create_atoms big single") + "run 3000\n")
L("K14_range_23_12_live22", "pair_coeff 2*3 1*2 kn 5000; the live pair types 2 2 (5000)", PCk("2*3 1*2", 5000) + "run 3000\n", pre=B3, pair=IN(0.1e-3, t1=2, t2=2), PAIR="types 2 2")

# ================================================================ V: formats, %.15g substitution, round()
L("V01_fmt_half_even", "pair_coeff 1 2 kn $(1000*$(4.5:%.0f)) (printf rounds 4.5 to 4: kn 4000)", PCs("$(1000*$(4.5:%.0f))") + "\nrun 3000\n")
L("V02_fmt_e_tie", "kn ${k} with k format of 4550 as %.1e, times 1 (4.5e+03 or 4.6e+03)", "variable a equal 4550\nvariable k format a %.1e\n" + PCs("${k}") + "\nrun 3000\n")
L("V03_round_half", "variable k equal 1000*round(2.5)+2000 (LAMMPS rounds half away: 5000)", "variable k equal 1000*round(2.5)+2000\n" + PCs("${k}") + "\nrun 3000\n")
L("V04_round_neg_half", "kn 5000+1000*round(-0.5) (away from zero: 4000)", "variable k equal 5000+1000*round(-0.5)\n" + PCs("${k}") + "\nrun 3000\n")
L("V05_if_on_15g", "a = 0.1*3 (0.30000000000000004); b = ${a} (0.3 at %.15g); if b == 0.3 then kn 5000 else 3000 (5000)",
  "variable a equal 0.1*3\nvariable b equal ${a}\nif \"${b} == 0.3\" then \"" + PCs(5000) + "\" else \"" + PCs(3000) + "\"\nrun 3000\n")
L("V06_if_on_vref", "a = 0.1*3; if v_a == 0.3 then kn 5000 else 3000 (3000: v_a is not 0.3)",
  "variable a equal 0.1*3\nif \"v_a == 0.3\" then \"" + PCs(5000) + "\" else \"" + PCs(3000) + "\"\nrun 3000\n")
L("V07_format_style", "variable kk equal 4999.6; variable k format kk %.0f (5000)", "variable kk equal 4999.6\nvariable k format kk %.0f\n" + PCs("${k}") + "\nrun 3000\n")
L("V08_width_fmt", "pair_coeff 1 2 hooke $(4000:%10.1f) (spaces in the value: 4000)", PCs("$(4000:%10.1f)") + "\nrun 3000\n")
L("V09_floor_15g", "x = 0.7*10 - 2 (5.000000000000001?); k = 1000*floor(${x}) vs floor(v_x)", "variable x equal 0.57*10-0.7\nvariable k equal 1000*floor(${x})\n" + PCs("${k}") + "\nrun 3000\n")
L("V10_ternary_ceil", "kn = 1000*ceil(${x}) with x 3.0000000000000004 printed 3 (3000 by ${x}; 4000 by v_x)", "variable x equal 0.1*30+4.440892098500626e-16\nvariable k equal 1000*ceil(${x})\n" + PCs("${k}") + "\nrun 3000\n")

# ================================================================ Q: set order
def PAIRQ(s1, s2, gap=0.1e-3):
    a = IN(gap).split("set atom 1")[0]
    rest = "group lv1 id 1\ngroup lv2 id 2\n" + IN(gap).split("group lv2 id 2\n")[1]
    return a + s1 + s2 + rest
L("Q01_density_then_diameter", "set atom 1 density 2500 then set atom 1 diameter 0.004 (mass from the default diameter 1: lv1 huge)",
  "run 3000\n", pair=PAIRQ("set atom 1 density 2500\nset atom 1 diameter 0.004\n", "set atom 2 diameter 0.006 density 2500\n"))
L("Q02_set_before_create", "set type 1 diameter 0.004 density 2500 before create_atoms (acts on none); then set atom 1 diameter 0.004 only (mass of diameter 1, density 1)",
  "run 3000\n", pre=BASE() + "set type 1 diameter 0.004 density 2500\n", pair=PAIRQ("set atom 1 diameter 0.004\n", "set atom 2 diameter 0.006 density 2500\n"))
L("Q03_type_fraction_all", "set group lv1 type/fraction 2 1.0 12345 (lv1 becomes type 2: pair 2 2)", "set group lv1 type/fraction 2 1.0 12345\nrun 3000\n", PAIR="types 2 2")
L("Q04_mass_then_diameter", "set atom 2 mass 1e-4 after diameter/density (mass wins)", "set atom 2 mass 1e-4\nrun 3000\n")
L("Q05_diameter_after_density_type", "set type 2 density 5000 then set type 2 diameter 0.005 (the mass stays that of 6 mm at 5000; the contact at 4.5 mm)",
  "set type 2 density 5000\nset type 2 diameter 0.005\nrun 3000\n", pair=IN(0.1e-3))
L("Q06_set_atom_range", "set atom 1*2 density 4000 (both)", "set atom 1*2 density 4000\nrun 3000\n")
L("Q07_type_ratio", "set group lv1 type/ratio 2 1.0 777 (lv1 type 2)", "set group lv1 type/ratio 2 1.0 777\nrun 3000\n", PAIR="types 2 2")
L("Q08_set_type_then_density_of_old_type", "set atom 2 type 1 then set type 2 density 5000 (acts on none): pair 1 1", "set atom 2 type 1\nset type 2 density 5000\nrun 3000\n", PAIR="types 1 1")

# ================================================================ Y: restyles
L("Y01_pair_style_again", "pair_style granular again then pair_coeff * * kn 5000", "pair_style granular\npair_coeff * * " + HK5 + "\nrun 3000\n")
L("Y02_pair_style_again_cut", "pair_style granular 0.01 again then pair_coeff * * kn 4000", "pair_style granular 0.01\npair_coeff * * " + HKk(4000) + "\nrun 3000\n")
L("Y03_gran_hooke_restyle", "restyle to pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0 (the same law: 0.4149)", "pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\nrun 3000\n")
L("Y04_variable_delete_restyle", "variable k equal 3000; variable k delete; variable k string 5000; kn ${k} (5000)", "variable k equal 3000\nvariable k delete\nvariable k string 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("Y05_index_not_redefined", "variable k index 3000; variable k index 5000 (ignored: 3000)", "variable k index 3000\nvariable k index 5000\n" + PCs("${k}") + "\nrun 3000\n")
L("Y06_equal_redefined_after_use", "variable k equal 3000; pair_coeff ${k}; variable k equal 5000 (the pair_coeff keeps 3000)", "variable k equal 3000\n" + PCs("${k}") + "\nvariable k equal 5000\nrun 3000\n")
L("Y07_pair_style_gran_hertz_history", "restyle to gran/hertz/history 2e7 NULL 3000 NULL 0.3 0", "pair_style gran/hertz/history 2e7 NULL 3000 NULL 0.3 0\npair_coeff * *\nrun 3000\n")
L("Y08_pair_style_again_no_coeff", "pair_style granular again and no pair_coeff (the same style keeps the coefficients: LAMMPS runs)", "pair_style granular\nrun 3000\n")
LE1 = lambda e: f"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 {e} 0.7 {e} 0.4 0.45 0.7 0.45 0.8\n"
LG("Y09_lig_limitforce_low_e", "LIGGGHTS hertz limitForce on, e 1 2 0.1", "run 3000\n", pre=LBASE(e="0.6 0.1 0.7 0.1 0.4 0.45 0.7 0.45 0.8").replace("tangential history\npair_coeff", "tangential history limitForce on\npair_coeff"))
LG("Y10_lig_no_limitforce_low_e", "LIGGGHTS hertz without limitForce, e 1 2 0.1 (control)", "run 3000\n", pre=LBASE(e="0.6 0.1 0.7 0.1 0.4 0.45 0.7 0.45 0.8"))
LG("Y11_lig_new_pair_style_then_e", "LIGGGHTS: pair_style gran hertz again, then property/global e 1 2 0.8 after it", "pair_style gran model hertz tangential history\npair_coeff * *\n" + LE1(0.8) + "run 3000\n")
LG("Y12_lig_restyle_hooke", "LIGGGHTS: restyle to gran model hooke (characteristicVelocity 1 given), e 1 2 0.5", "fix m9 all property/global characteristicVelocity scalar 1.0\npair_style gran model hooke tangential history\npair_coeff * *\nrun 3000\n")
LG("Y13_lig_limitforce_after_restyle", "LIGGGHTS: hertz, then pair_style again with limitForce on and e 0.1 set after", "pair_style gran model hertz tangential history limitForce on\npair_coeff * *\n" + LE1(0.1) + "run 3000\n")
LG("Y14_lig_e_before_and_after_wall", "LIGGGHTS WALL: e 1-3 0.7, then property/global given again with 1-3 0.9 after the wall fix (0.9)",
   "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.9 0.5 0.4 0.45 0.9 0.45 0.8\nrun 3000\n", pair=LWALL(1e-4), PAIR="type 1 on wall wprim")

L("Y15_same_style_keeps_explicit", "pair_coeff * * 2000 (1 2 explicit); pair_style granular again (same style: coefficients kept); pair_coeff 1 1 and 2 2 kn 5000 (1 2 stays 2000)",
  "pair_style granular\npair_coeff 1 1 " + HK5 + "\npair_coeff 2 2 " + HK5 + "\nrun 3000\n")
L("Y16_same_style_remix", "pair_coeff 1 1 and 2 2 only (1 2 mixed); pair_style granular again; 1 1 and 2 2 kn 5000 (1 2 mixed again: 5000)",
  "pair_style granular\npair_coeff 1 1 " + HK5 + "\npair_coeff 2 2 " + HK5 + "\nrun 3000\n", pre=BASE(coeff="pair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\n"))
L("Y17_other_style_then_back", "pair_style gran/hooke (resets), then pair_style granular with 1 1 and 2 2 kn 5000 only (1 2 mixed: 5000)",
  "pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\npair_style granular\npair_coeff 1 1 " + HK5 + "\npair_coeff 2 2 " + HK5 + "\nrun 3000\n")
L("Y18_same_style_between_runs", "run 1000 (2000); pair_style granular again; pair_coeff 2 2 kn 5000; run 3000 (1 2 stays 2000)",
  "run 1000\npair_style granular\npair_coeff 2 2 " + HK5 + "\nrun 3000\n", pair=IN(G11))
LG("Y19_lig_same_style_hooke_no_cv", "LIGGGHTS: pair_style gran again with model hooke and no characteristicVelocity (LIGGGHTS stops?)",
   "pair_style gran model hooke tangential history\npair_coeff * *\nrun 3000\n")

# ================================================================ W: walls-only material types
LG("W01_lig_wall_type3", "LIGGGHTS WALL: type 3 is the wall's only (e 1-3 0.7)", "run 3000\n", pair=LWALL(1e-4), PAIR="type 1 on wall wprim")
LG("W02_lig_wall_type2_of_2", "LIGGGHTS WALL: 2 types, the wall type 2 (e 1-2 0.65)", "run 3000\n",
   pre=LBASE(nt=2, e="0.6 0.65 0.65 0.4"), pair=LWALL(1e-4), PAIR="type 1 on wall wprim")
LG("W03_lig_wall_two_prims", "LIGGGHTS WALL: the floor of type 3, a far xplane of type 2 (e 1-3 0.7)", "fix wx all wall/gran model hertz tangential history primitive type 2 xplane -0.045\nrun 3000\n",
   pair=LWALL(1e-4), PAIR="type 1 on wall wprim")
L("W04_lammps_wall_hertz_material", "LAMMPS WALL: the floor hertz/material 1e7 0.3 0.3 damping viscoelastic, the pair hooke", "run 3000\n",
  pre=BASE(wall=False) + "fix floor all wall/gran granular hertz/material 1e7 0.5 0.3 damping viscoelastic tangential linear_nohistory 1 0.3 zplane 0 NULL\n", pair=WALLP(), **WALL)
LG("W05_lig_wall_type_only_in_mesh_free_type", "LIGGGHTS WALL: 4 types, walls type 4, e 1-4 0.55 (type 3 unused)", "run 3000\n",
   pre=LBASE(nt=4, e="0.6 0.5 0.7 0.55 0.5 0.4 0.45 0.5 0.7 0.45 0.8 0.5 0.55 0.5 0.5 0.5"), pair=LWALL(1e-4), PAIR="type 1 on wall wprim")

# ================================================================ S: several sizes in one type
POUR = lambda spec: ("region pr block 0.005 0.035 0.005 0.035 0.08 0.095 units box\n"
                     f"fix p all pour 5 1 4767548 region pr {spec}\n")
L("S01_pour_range_incl", "fix pour type 1 diam range 0.003 0.005 + the live pair (4 mm type 1): range row", POUR("diam range 0.003 0.005") + "run 3000\n")
L("S02_pour_range_below", "fix pour type 1 diam range 0.001 0.002 (all smaller than the created 4 mm): the row must cover 4 mm", POUR("diam range 0.001 0.002") + "run 3000\n")
L("S03_pour_poly", "fix pour type 1 diam poly 2 0.003 0.5 0.005 0.5 + 4 mm lv1", POUR("diam poly 2 0.003 0.5 0.005 0.5") + "run 3000\n")
L("S04_far_small_same_type", "a far type 1 sphere of 2 mm beside the 4 mm lv1 (sizes 2 and 4 mm)", "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.002 density 2500\nrun 3000\n")
L("S05_pour_dens_range", "fix pour type 1 diam one 0.004 dens 1000 4000 (masses differ): the 2500 lv1 inside", POUR("diam one 0.004 dens 1000 4000") + "run 3000\n")
L("S06_pour_range_above_hertzmat", "hertz/material viscoelastic pair, pour type 1 diam range 0.005 0.008; the live pair 4/6 mm",
  POUR("diam range 0.005 0.008") + "run 3000\n", pre=BASE(coeff="pair_coeff * * hertz/material 1e7 0.5 0.3 damping viscoelastic tangential linear_nohistory 1 0.3\n", wall=False))
L("S07_read_data_sizes", "a far type 2 sphere of 3 mm, density 1000 (type 2 sizes 6 and 3 mm)", "create_atoms 2 single 0.005 0.005 0.08\nset atom 3 diameter 0.003 density 1000\nrun 3000\n")
L("S08_pour_after_meet", "fix pour type 2 diam one 0.002 given after the run where they meet (the first stage's rows: one size)", "run 3000\n" + POUR("diam one 0.002").replace(" 1 4767548", " 2 4767548") + "run 100\n", live="run 1")
LG("S09_lig_templates_two_sizes", "LIGGGHTS: insert/pack of type 1 with radii 1 and 1.5 mm far above, + the live pair (e 0.5)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.0015\n"
   "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion bc block -0.04 0.04 -0.04 0.04 0.13 0.145 units box\n"
   "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 10 region bc\nrun 3000\n")

LHS = LBASE(model="hooke/stiffness", extra="fix k1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
             "fix k2 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
             "fix k3 all property/global gamman peratomtypepair 3 500 500 500 500 500 500 500 500 500\n"
             "fix k4 all property/global gammat peratomtypepair 3 500 500 500 500 500 500 500 500 500\n")
INS = lambda r1, r2: (f"fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant {r1}\n"
                      f"fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant {r2}\n"
                      "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion bc block -0.04 0.04 -0.04 0.04 0.13 0.145 units box\n"
                      "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 10 region bc\n")
LG("S10_lig_hooke_stiffness_templates_small", "LIGGGHTS hooke/stiffness (size-dependent), type 1 inserted with radii 1 and 1.5 mm, the live 4 mm type 1: the row must cover 4 mm",
   INS(0.001, 0.0015) + "run 3000\n", pre=LHS)
LG("S11_lig_hooke_stiffness_templates_incl", "LIGGGHTS hooke/stiffness, type 1 inserted with radii 1.5 and 2.5 mm (the 2 mm live sphere between)",
   INS(0.0015, 0.0025) + "run 3000\n", pre=LHS)
LG("S12_lig_hooke_stiffness_two_sizes_created", "LIGGGHTS hooke/stiffness, a far type 2 sphere of 2 mm (type 2 sizes 6 and 2 mm)",
   "create_atoms 2 single 0.04 0 0.12 units box\nset atom 3 diameter 0.002 density 2500\nrun 3000\n", pre=LHS)

# ================================================================ T: the time-step note (steps per contact)
def TD(dt, k=2000, gap=0.1e-3, steps=None, wall=False):
    n = steps or int(round((gap + 0.004) / dt)) + int(2e-3 / dt) + 10
    pre = BASE(wall=wall, coeff="pair_coeff * * " + HKk(k) + "\n").replace("timestep 1e-6", f"timestep {dt}")
    return pre, f"run {n}\n"
for name, dt, k, gap in [("T01_dt5e-5", 5e-5, 2000, 0.13e-3), ("T02_dt1e-4", 1e-4, 2000, 0.17e-3), ("T03_dt2e-4", 2e-4, 2000, 0.29e-3),
                         ("T04_dt2.5e-5", 2.5e-5, 2000, 0.11e-3), ("T05_dt1e-4_kn5000", 1e-4, 5000, 0.23e-3), ("T06_dt7e-5", 7e-5, 2000, 0.05e-3),
                         ("T07_dt1.5e-4", 1.5e-4, 2000, 0.31e-3), ("T08_dt3e-5_kn5000", 3e-5, 5000, 0.07e-3)]:
    pre, body = TD(dt, k, gap)
    L(name, f"dt {dt}, kn {k}: a contact of few steps (the note's range)", body, pre=pre, pair=IN(gap))
pre, body = TD(1e-4, 2000, wall=True)
L("T09_wall_dt1e-4", "WALL at dt 1e-4 (the floor row and note)", body, pre=pre, pair=WALLP(0.37e-3), **WALL)
L("T10_dt_changed_before_meet", "run 1000 at dt 1e-6, then timestep 1e-4 and run 60 (meets there)", "run 1000\ntimestep 1e-4\nrun 80\n", pair=IN(1.1e-3 + 0.13e-3))
LG("T11_lig_dt2e-5", "LIGGGHTS hertz e 0.5 at dt 2e-5", "run 500\n", pre=LBASE().replace("timestep 1e-6", "timestep 2e-5"), pair=LIN(0.13e-3))
LG("T12_lig_dt5e-5_wall", "LIGGGHTS WALL at dt 5e-5 (e 0.7)", "run 300\n", pre=LBASE().replace("timestep 1e-6", "timestep 5e-5"), pair=LWALL(0.17e-3), PAIR="type 1 on wall wprim")

L("T13_dt_reset_large", "fix dt/reset 1 1e-7 2e-4 0.001 units box (dt becomes 2e-4 in the run: 3 steps a contact); the deck's timestep 1e-6",
  "fix dtr all dt/reset 1 1e-7 2e-4 0.001 units box\nrun 40\n", pair=IN(0.29e-3))
L("T14_dt_reset_then_run", "fix dt/reset (dt up to 1e-4) in run 1, unfix, run 2 where they meet (the dt run 1 left: 1e-4)",
  "fix dtr all dt/reset 1 1e-7 1e-4 0.001 units box\nrun 5\nunfix dtr\nrun 60\n", pair=IN(0.1e-3 + 5 * 1e-4 * 1 + 0.07e-3))
L("T15_dt_reset_small_note", "fix dt/reset 1 1e-7 5e-5 0.001 units box (12 steps a contact)", "fix dtr all dt/reset 1 1e-7 5e-5 0.001 units box\nrun 100\n", pair=IN(0.13e-3))

# ================================================================ X: fix balance, which the copy now runs (session 26)
XH = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
XT = "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n" + IN(0.1e-3) + "run 3000\n"
HKH = "hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3"
RAW("X01_balance_out_nohistory", "fix balance ... out bal.txt before pair_style granular without history (LAMMPS runs; the file written only in the engine's run)",
    XH + "fix bal all balance 100 1.0 shift x 5 1.1 out bal.txt\npair_style granular\npair_coeff * * " + HK + "\n" + XT)
RAW("X02_balance_out_quoted_space", "fix balance out \"b a l.txt\" (a quoted name with spaces), after the pair (history)",
    XH + "pair_style granular\npair_coeff * * " + HKH + "\nfix bal all balance 100 1.0 shift x 5 1.1 out \"b a l.txt\"\n" + XT)
RAW("X03_balance_include_before_history", "fix balance in an include before pair_style granular with linear_history (LAMMPS stops)",
    XH + "include b.in\npair_style granular\npair_coeff * * " + HKH + "\n" + XT, data={"b.in": "fix bal all balance 100 1.0 shift x 5 1.1\n"})
RAW("X04_balance_then_restyle_history", "pair granular (history), fix balance, then pair_style granular given again (history) after it (LAMMPS stops?)",
    XH + "pair_style granular\npair_coeff * * " + HKH + "\nfix bal all balance 100 1.0 shift x 5 1.1\npair_style granular\npair_coeff * * " + HKH + "\n" + XT)
RAW("X05_balance_unfixed_before_run", "fix balance before the history pair, unfix bal before the run (LAMMPS runs?)",
    XH + "fix bal all balance 100 1.0 shift x 5 1.1\npair_style granular\npair_coeff * * " + HKH + "\nunfix bal\n" + XT)
LG("X06_lig_balance_before_history", "LIGGGHTS: fix balance before pair gran hertz tangential history",
   "run 3000\n", pre=LBASE().replace("pair_style gran", "fix bal all balance 100 1.0 shift x 5 1.1\npair_style gran"))
RAW("X07_balance_np2_fff_after", "f f f processors * 1 1: pair (history), fix balance shift x every 100, the pair across x 0.02 (1 and 2 processes)",
    XH.replace("p p f", "f f f") .replace("units si\n", "units si\nprocessors * 1 1\n") + "pair_style granular\npair_coeff * * " + HKH + "\nfix bal all balance 100 1.0 shift x 5 1.1\n" + XT)

LHSR = ("fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
        "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n"
        "fix k1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
        "fix k2 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
        "fix k3 all property/global gamman peratomtypepair 3 500 500 500 500 500 500 500 500 500\n"
        "fix k4 all property/global gammat peratomtypepair 3 500 500 500 500 500 500 500 500 500\n"
        "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\nfix integr all nve/sphere\n")
LG("L15_lig_restart_star_density", "LIGGGHTS hooke/stiffness: write_restart r.* at step 1000 (lv2 density 5000), reset_timestep 0, 2500, write r.0; read_restart r.* (LIGGGHTS: r.1000?)",
   "run 1000\nset atom 2 density 5000\nwrite_restart r.*\nreset_timestep 0\nset atom 2 density 2500\nwrite_restart r.*\nclear\natom_modify map array\nnewton off\ncommunicate single vel yes\nread_restart r.*\nneighbor 0.002 bin\n" + LHSR + "timestep 1e-6\nrun 3000\n",
   pre=LHS.replace("fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n", "").replace("fix gravi all gravity 9.81 vector 0.0 0.0 -1.0\n", ""), pair=LIN(G11))

# ================================================================ Z: group membership changed after the command that reads it; LIGGGHTS asymmetric e
FAR3 = "create_atoms 1 single 0.005 0.005 0.08\nset atom 3 diameter 0.004 density 2500\n"
L("Z01_exclude_group_grown", "neigh_modify exclude group g1 g2 with g2 = the far sphere; then group g2 id 2 (lv2 joins: the pair is excluded, LAMMPS passes)",
  FAR3 + "group g1 id 1\ngroup g2 id 3\nneigh_modify exclude group g1 g2\ngroup g2 id 2\nrun 3000\n")
L("Z02_integrator_group_grown", "fix integ on group mv (lv1 only), then group mv id 2 (lv2 joins: both integrated)",
  "unfix integ\ngroup mv id 1\nfix integ2 mv nve/sphere\ngroup mv id 2\nrun 3000\n")
L("Z03_freeze_group_grown", "fix freeze on group fz (the far sphere), then group fz id 2 (lv2 frozen from then on)",
  FAR3 + "group fz id 3\nfix fr fz freeze\ngroup fz id 2\nrun 3000\n")
L("Z04_exclude_group_shrunk", "neigh_modify exclude group g1 g2 with g2 = lv2; then group g2 clear (the pair meets again)",
  "group g1 id 1\ngroup g2 id 2\nneigh_modify exclude group g1 g2\ngroup g2 clear\nrun 3000\n")
L("Z05_exclude_group_grown_between_runs", "exclude group g1 g2 (g2 far), run 500, group g2 id 2, run 3000 (meets in run 2: excluded)",
  FAR3 + "group g1 id 1\ngroup g2 id 3\nneigh_modify exclude group g1 g2\nrun 500\ngroup g2 id 2\nrun 3000\n", pair=IN(0.6e-3))
L("Z06_setforce_group_grown", "fix setforce 0 0 0 on group sf (far), then group sf id 1 (lv1 gets no force: passes? it keeps its speed through lv2)",
  FAR3 + "group sf id 3\nfix sfx sf setforce 0.0 0.0 0.0\ngroup sf id 1\nrun 3000\n")
L("Z07_gravity_group_grown", "WALL: fix gravity on group gg (far only; the base gravity removed), group gg id 1 later (lv1 falls under gravity)",
  FAR3.replace("set atom 3", "set atom 2") + "unfix grav\ngroup gg id 2\nfix g2 gg gravity 9.81 vector 0 0 -1\ngroup gg id 1\nrun 3000\n", pair=WALLP(), **WALL)
L("Z11_freeze_group_first", "control of Z03: group fz id 2 before fix freeze (lv2 frozen throughout)", FAR3 + "group fz id 3\ngroup fz id 2\nfix fr fz freeze\nrun 3000\n")
L("Z12_setforce_group_first", "control of Z06: group sf id 1 before fix setforce", FAR3 + "group sf id 3\ngroup sf id 1\nfix sfx sf setforce 0.0 0.0 0.0\nrun 3000\n")
L("Z13_freeze_group_grown_between_runs", "fix freeze on fz (far), run 500, group fz id 2, run 3000 (lv2 frozen in run 2, where they meet)",
  FAR3 + "group fz id 3\nfix fr fz freeze\nrun 500\ngroup fz id 2\nrun 3000\n", pair=IN(0.6e-3))
L("Z14_freeze_by_region_group_grown", "group fz region (an empty block), fix freeze fz, then group fz id 2", "region rb block 0.001 0.002 0.001 0.002 0.001 0.002 units box\ngroup fz region rb\nfix fr fz freeze\ngroup fz id 2\nrun 3000\n")

LZ = lambda e12, e21: f"0.6 {e12} 0.7 {e21} 0.4 0.45 0.7 0.45 0.8"
LG("Z08_lig_asym_e", "LIGGGHTS e 1-2 0.5, 2-1 0.8 (asymmetric matrix)", "run 3000\n", pre=LBASE(e=LZ(0.5, 0.8)))
LG("Z09_lig_asym_e_swapped_order", "Z08 with type 2 made first (atom 1 of type 2)", "run 3000\n", pre=LBASE(e=LZ(0.5, 0.8)), pair=LIN(0.1e-3, t1=2, t2=1))
LG("Z10_lig_asym_e_np2", "Z08 with processors 2 1 1 (the pair across the border)", "run 3000\n", pre=LBASE(e=LZ(0.5, 0.8), head="processors 2 1 1\n"), NP="2")

# ================================================================ F: files the deck writes and reads back, a stale copy in the folder
STALE = PCs(3000) + "\n"     # the file as an earlier run left it (kn 3000)
L("F01_print_file_include_stale", "print \"pair_coeff ... 5000\" file pc.in; include pc.in (the folder holds a stale pc.in: kn 3000; LAMMPS writes it anew: 5000)",
  'print "' + PCs(5000) + '" file pc.in screen no\ninclude pc.in\nrun 3000\n', data={"pc.in": STALE})
L("F02_shell_cp_include_stale", "shell cp new.in pc.in; include pc.in (the folder holds new.in: 5000 and a stale pc.in: 3000)",
  "shell cp new.in pc.in\ninclude pc.in\nrun 3000\n", data={"pc.in": STALE, "new.in": PCs(5000) + "\n"})
L("F03_write_coeff_include_stale", "pair_coeff 1 2 kn 5000; write_coeff wc.in; pair_coeff * * 2000; include wc.in (a stale wc.in: 3000)",
  PCs(5000) + "\nwrite_coeff wc.in\npair_coeff * * " + HK + "\ninclude wc.in\nrun 3000\n", data={"wc.in": STALE})
L("F04_print_append_include_stale", "print ... append pc.in (a stale pc.in holding kn 3000: the append puts 5000 after it, the include ends at 5000)",
  'print "' + PCs(5000) + '" append pc.in screen no\ninclude pc.in\nrun 3000\n', data={"pc.in": STALE})
L("F05_fix_print_file_next_run", "fix print every 1000 writes pc.in in run 1 (\"pair_coeff ... 5000\"), unfix, include pc.in (a stale pc.in: 3000), run 2",
  'fix fp all print 1000 "' + PCs(5000) + '" file pc.in screen no title "# pc"\nrun 1000\nunfix fp\ninclude pc.in\nrun 3000\n', pair=IN(G11), data={"pc.in": STALE})
L("F06_shell_mv_include_stale", "shell mv new.in pc.in (LAMMPS' own mv); include pc.in", "shell mv new.in pc.in\ninclude pc.in\nrun 3000\n",
  data={"pc.in": STALE, "new.in": PCs(5000) + "\n"})
L("F07_print_file_no_stale", "F01 without a stale file (control: refused as round 35 E72?)", 'print "' + PCs(5000) + '" file pc.in screen no\ninclude pc.in\nrun 3000\n')
LG("F08_lig_print_file_include_stale", "LIGGGHTS: print \"fix m3 ... 0.8\" file m.in; include m.in (a stale m.in with 0.6)",
   'print "' + LE.format(e="0.8") + '" file m.in screen no\ninclude m.in\nrun 3000\n', data={"m.in": LE.format(e="0.6") + "\n"})

L("F09_shell_mv_include_no_stale", "shell mv new.in pc.in; include pc.in; shell mv pc.in new.in (no stale file; the folder as it was after the run)",
  "shell mv new.in pc.in\ninclude pc.in\nshell mv pc.in new.in\nrun 3000\n", data={"new.in": PCs(5000) + "\n"})
L("F10_shell_mv_include_between_runs", "run 1000; shell mv new.in pc.in; include pc.in (kn 5000); run 3000 (meets there)",
  "run 1000\nshell mv new.in pc.in\ninclude pc.in\nshell mv pc.in new.in\nrun 3000\n", pair=IN(G11), data={"new.in": PCs(5000) + "\n"})
L("F11_shell_mv_wall_include", "WALL: shell mv w.in wall.in; include wall.in (the floor made kn 5000)",
  "shell mv w.in wall.in\ninclude wall.in\nshell mv wall.in w.in\nrun 3000\n", pair=WALLP(), data={"w.in": "fix floor all wall/gran granular " + HK5 + " zplane 0 NULL\n"}, **WALL)
LG("F12_lig_shell_mv_include", "LIGGGHTS: shell mv new.in m.in; include m.in (e 1 2 0.8); shell mv back",
   "shell mv new.in m.in\ninclude m.in\nshell mv m.in new.in\nrun 3000\n", data={"new.in": LE.format(e="0.8") + "\n"})
L("F13_shell_mv_include_in_every", "run 4000 every 1000 \"include pc.in\" with pc.in made by shell mv before the run (kn 5000 from part 2; the pair meets in part 2)",
  "shell mv new.in pc.in\nrun 4000 every 1000 \"include pc.in\"\nshell mv pc.in new.in\n", pair=IN(G(2)), live="part 2", data={"new.in": PCs(5000) + "\n"})

L("F14_include_symlink_inside", "include link.in, link.in a symbolic link to real.in in the same folder (kn 5000)", "include link.in\nrun 3000\n",
  data={"real.in": PCs(5000) + "\n"})
L("F15_include_symlink_outside", "include link.in, a symbolic link to ../../shared/mat.in outside the deck's folder (kn 5000)", "include link.in\nrun 3000\n")
L("F16_include_symlink_between_runs", "run 1000; include link.in (symlink to real.in: kn 5000); run 3000", "run 1000\ninclude link.in\nrun 3000\n", pair=IN(G11),
  data={"real.in": PCs(5000) + "\n"})
LG("F17_lig_include_symlink", "LIGGGHTS: include link.in (symlink to real.in: fix m3 e 1 2 0.8)", "include link.in\nrun 3000\n", data={"real.in": LE.format(e="0.8") + "\n"})
L("F18_include_through_dir_symlink", "include sub/pc.in, sub a symbolic link to the folder real_sub (pc.in: kn 5000)", "include sub/pc.in\nrun 3000\n",
  data={"real_sub/pc.in": PCs(5000) + "\n"})
L("F19_include_over_20MB", "include big.in: 22 MB of comment lines, then pair_coeff 1 2 kn 5000 (big.in is written by make_decks36.py, not committed)",
  "include big.in\nrun 3000\n")
L("F20_fix_print_file_variable_stale", "fix print writes k.txt (5000) in run 1; variable k file k.txt; pair_coeff 1 2 ${k} (a stale k.txt: 3000)",
  'fix fp all print 1000 "5000" file k.txt screen no\nrun 1000\nunfix fp\nvariable k file k.txt\n' + PCs("${k}") + "\nrun 3000\n", pair=IN(G11), data={"k.txt": "3000\n"})
L("F21_print_file_variable_stale", "print \"5000\" file k.txt; variable k file k.txt; kn ${k} (a stale k.txt: 3000)",
  'print "5000" file k.txt screen no\nvariable k file k.txt\n' + PCs("${k}") + "\nrun 3000\n", data={"k.txt": "3000\n"})
L("F22_shell_mv_variable_file", "shell mv new.txt k.txt; variable k file k.txt; kn ${k} (new.txt: 5000)", "shell mv new.txt k.txt\nvariable k file k.txt\n" + PCs("${k}") + "\nshell mv k.txt new.txt\nrun 3000\n",
  data={"new.txt": "5000\n"})
L("F23_shell_mv_sweep_loop", "a parameter sweep: loop i 1..2: shell mv p_${i}.in p.in; include p.in; run 1000; shell mv p.in p_${i}.in (pass 2 kn 5000; the pair meets in pass 2)",
  "variable i loop 2\nlabel sweep\nshell mv p_${i}.in p.in\ninclude p.in\nrun 1000\nshell mv p.in p_${i}.in\nnext i\njump SELF sweep\n", pair=IN(G11), live="pass 2",
  data={"p_1.in": PCs(3000) + "\n", "p_2.in": PCs(5000) + "\n"})
SYMLINKS = {"D05": ("link.data", "d.data"), "F18": ("sub", "real_sub"), "F14": ("link.in", "real.in"), "F15": ("link.in", "../../shared/mat.in"), "F16": ("link.in", "real.in"), "F17": ("link.in", "real.in")}

LG("L16_lig_restart_stale_shipped", "LIGGGHTS hooke/stiffness: the folder holds a stale r.1000 (lv2 8000); the deck writes r.* at step 1000 and reads r.1000",
   "run 1000\nwrite_restart r.*\nclear\natom_modify map array\nnewton off\ncommunicate single vel yes\nread_restart r.1000\nneighbor 0.002 bin\n" + LHSR + "timestep 1e-6\nrun 3000\n",
   pre=LHS.replace("fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n", "").replace("fix gravi all gravity 9.81 vector 0.0 0.0 -1.0\n", ""), pair=LIN(G11))

# ================================================================ D: pair coefficients in a data file
def DDATA(sec, extra=""):
    return ("two spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\n" + sec +
            "Atoms # sphere\n\n1 1 0.004 2500 0.017450 0.02 0.05\n2 2 0.006 2500 0.022550 0.02 0.05\n\n"
            "Velocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n" + extra)
PIJ = lambda k12: ("PairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + HKk(k12) + "\n2 2 " + HK + "\n\n")
PII = lambda k: ("Pair Coeffs # granular\n\n1 " + HKk(k) + "\n2 " + HKk(k) + "\n\n")
DH = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\n"
DT = "group lv1 id 1\ngroup lv2 id 2\nfix integ all nve/sphere\ntimestep 1e-6\n"
RAW("D01_data_pairij_coeffs", "read_data with a PairIJ Coeffs section (1 2 kn 5000)", DH + "read_data d.data\n" + DT + "run 3000\n", data={"d.data": DDATA(PIJ(5000))})
RAW("D02_data_pair_coeffs_mixed", "read_data with Pair Coeffs (1 1 and 2 2 kn 5000): 1 2 mixed, 5000", DH + "read_data d.data\n" + DT + "run 3000\n", data={"d.data": DDATA(PII(5000))})
RAW("D03_data_coeffs_then_pair_coeff", "PairIJ Coeffs 1 2 kn 5000, then pair_coeff 1 2 kn 3000 in the deck (3000)", DH + "read_data d.data\n" + PCs(3000) + "\n" + DT + "run 3000\n",
    data={"d.data": DDATA(PIJ(5000))})
RAW("D04_data_nocoeff", "read_data d.data nocoeff (PairIJ 5000 ignored), pair_coeff * * kn 4000 in the deck", DH + "read_data d.data nocoeff\npair_coeff * * " + HKk(4000) + "\n" + DT + "run 3000\n",
    data={"d.data": DDATA(PIJ(5000))})
RAW("D05_data_symlink_coeffs", "read_data link.data, a symbolic link to d.data (PairIJ 1 2 kn 5000)", DH + "read_data link.data\n" + DT + "run 3000\n", data={"d.data": DDATA(PIJ(5000))})
RAW("D06_data_shell_mv_coeffs", "shell mv new.data d.data; read_data d.data (PairIJ 1 2 kn 5000 in the moved file)", DH + "shell mv new.data d.data\nread_data d.data\nshell mv d.data new.data\n" + DT + "run 3000\n",
    data={"new.data": DDATA(PIJ(5000))})

# ================================================================ O: public decks, shortened (sources in FINDINGS.md and each file's head)
OD = os.path.join(HERE, "odecks")
OMETA = {"O01_pour_loop_gravelle": ("pass 2", {"PAIR": "types 1 2", "SEP": "1.0"}),
         "O02_lig_uniaxial_bihani": ("run 2", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.02"}),
         "O03_lig_repose_sjkr_np2": ("run 1", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.005", "NP": "2"}),
         "O04_lig_drum_jkr_pici": ("run 1", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.003"}),
         "O05_lig_isocomp_limitforce": ("part 2", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.0004"}),
         "O06_lig_ballmill_chen": ("run 2", {"LIGGGHTS": "", "PAIR": "types 1 2", "SEP": "0.0925"}),
         "O07_lig_repose_inl": ("run 2", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.006"}),
         "O08_lig_seaice_bonds": ("run 2", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.02"}),
         "O09_lig_seaice_nobonds_drag": ("run 2", {"LIGGGHTS": "", "PAIR": "types 1 1", "SEP": "0.02"})}
for n, (live, meta) in OMETA.items():
    DECKS[n] = (open(os.path.join(OD, n[:3] + ".in")).read(), live, {}, dict(meta))

# ================================================================ write
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
        if name[:3] in SYMLINKS and not os.path.lexists(os.path.join(d, SYMLINKS[name[:3]][0])):
            os.symlink(SYMLINKS[name[:3]][1], os.path.join(d, SYMLINKS[name[:3]][0]))
        if name.startswith("F19") and not os.path.exists(os.path.join(d, "big.in")):
            with open(os.path.join(d, "big.in"), "w") as f:
                f.write(("# " + "x" * 98 + "\n") * 220000 + PCs(5000) + "\n")
        if name.startswith("M25") and not os.path.exists(os.path.join(d, "r.500")):
            import subprocess, tempfile
            t = tempfile.mkdtemp()
            open(os.path.join(t, "g.in"), "w").write(GEN_M25)
            subprocess.run(["lmp", "-in", "g.in", "-log", "none"], cwd=t, capture_output=True)
            os.replace(os.path.join(t, "r.500"), os.path.join(d, "r.500"))
        if name.startswith("M30") and not os.path.exists(os.path.join(d, "rb.rst")):
            import subprocess, tempfile
            t = tempfile.mkdtemp()
            open(os.path.join(t, "g.in"), "w").write(GEN_M30)
            subprocess.run(["lmp", "-in", "g.in", "-log", "none"], cwd=t, capture_output=True)
            os.replace(os.path.join(t, "rb.rst"), os.path.join(d, "rb.rst"))
        if name.startswith("L16") and not os.path.exists(os.path.join(d, "r.1000")):
            import subprocess, tempfile
            t = tempfile.mkdtemp()
            txt = DECKS[name][0].split("run 1000")[0].replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006 density 8000")
            open(os.path.join(t, "g.in"), "w").write(txt + "run 1000\nwrite_restart r.*\n")
            subprocess.run(["liggghts", "-in", "g.in", "-log", "none"], cwd=t, capture_output=True)
            os.replace(os.path.join(t, "r.1000"), os.path.join(d, "r.1000"))
        if name.startswith("M29") and not os.path.exists(os.path.join(d, "r.1000")):
            import subprocess, tempfile
            t = tempfile.mkdtemp()
            open(os.path.join(t, "g.in"), "w").write(GEN_M29)
            subprocess.run(["lmp", "-in", "g.in", "-log", "none"], cwd=t, capture_output=True)
            os.replace(os.path.join(t, "r.1000"), os.path.join(d, "r.1000"))
    print(len(DECKS), "decks")


if __name__ == "__main__":
    write(sys.argv[1:])
