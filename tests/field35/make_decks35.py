"""Field round 35: write decks/NAME/in.deck (and the files a deck reads) for the referee live35.py and the audit.

A spot check of the rules changed on main 68254516: `run N every M` made as its parts where the commands read the
step, the time, a variable or an include (E decks, L01-L08 in LIGGGHTS); pairs held through ghost atoms after
re-ghosting before `run N pre no`, nsq lists short of the contact and read_restart without pair_style given again,
left out in any box (N decks); replicate then `run N pre no` refused (R decks); ordinary modeller decks shortened (O,
their sources in FINDINGS.md). The live pair as in rounds 32-34 (a copy of make_decks34.py's helpers): type 1 of 4 mm
(group lv1) and type 2 of 6 mm (group lv2), 2500 kg/m3, LAMMPS hooke kn 2000 damping 3000 mass_velocity, dt 1e-6 s,
approaching at 1 m/s (momentum zero) from a gap timed so that they meet in the run or part named in the LIVE file
(gap 0.1 mm + 1 mm per earlier part of 1000 steps). A WALL deck: one type 1 sphere (lv1) falling onto the floor z = 0
at 1 m/s at touching. LIGGGHTS decks: hertz with typed e (1 2: 0.5, 1 on the wall of type 3: 0.7).
Folder files: DECK, G, LIVE, AXIS, NP, LIGGGHTS, PAIR, SEP as in round 34.
usage: python make_decks35.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
DECKS = {}

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
HK5 = "hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
WHK = "granular " + HK


def BASE(boundary="p p f", nt=2, pstyle="pair_style granular\n", coeff="pair_coeff * * " + HK + "\n", head="", box="0 0.04 0 0.04 0 0.1",
         wall=True, integ=True):
    return (head + "units si\natom_style sphere 1\nboundary " + boundary + "\ncomm_modify vel yes\n"
            f"region box block {box} units box\ncreate_box {nt} box\n" + pstyle + coeff +
            "fix grav all gravity 9.81 vector 0 0 -1\n" +
            ("fix floor all wall/gran " + WHK + " zplane 0 NULL\n" if wall else "") +
            ("fix integ all nve/sphere\n" if integ else "") + "timestep 1e-6\n")


V1, V2 = 216 / 280, -64 / 280      # momentum zero: m1 : m2 = 4^3 : 6^3


def IN(gap, xc=0.02, y=0.02, z=0.05, t1=1, t2=2, ax="x"):
    """The live pair inside the box, along `ax`, its touching point at xc (x) or z (z)."""
    s = 0.005 + gap
    if ax == "x":
        a, b = f"{xc - 0.002 - gap / 2:.6f} {y} {z}", f"{xc + 0.003 + gap / 2:.6f} {y} {z}"
        va, vb = f"{V1:.10f} 0 0", f"{V2:.10f} 0 0"
    else:
        a, b = f"{xc} {y} {z - 0.002 - gap / 2:.6f}", f"{xc} {y} {z + 0.003 + gap / 2:.6f}"
        va, vb = f"0 0 {V1:.10f}", f"0 0 {V2:.10f}"
    return (f"create_atoms {t1} single {a}\ncreate_atoms {t2} single {b}\nset atom 1 diameter 0.004 density 2500\n"
            f"set atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {va} units box\nvelocity lv2 set {vb} units box\n")


def PER(gap):
    """The live pair across the periodic x boundary of the 0.04 box (round 33's PER)."""
    x2 = 0.00355 - (0.0011 - gap) / 2
    x1 = 0.03745 + (0.0011 - gap) / 2
    return (f"create_atoms 1 single {x1:.6f} 0.02 0.05\ncreate_atoms 2 single {x2:.6f} 0.02 0.05\n"
            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\n")


H0 = 1e-4


def WALLP(h=H0, x=0.02, y=0.02):
    """One type 1 sphere falling onto the floor, 1 m/s at touching."""
    v = math.sqrt(1 - 2 * 9.81 * h)
    return (f"create_atoms 1 single {x} {y} {0.002 + h:.6f}\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
            f"velocity lv1 set 0 0 {-v:.10f} units box\n")


def L(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    """A LAMMPS deck: # desc, `pre` (BASE()), `pair` (IN(0.1e-3)), `body`."""
    pre = BASE() if pre is None else pre
    pair = IN(0.1e-3) if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


def RAW(name, desc, text, live="last run", data=None, **meta):
    DECKS[name] = ("# " + desc + "\n" + text, live, data or {}, meta)


# ---------------------------------------------------------------- LIGGGHTS base (round 33's LPB, the pair inside the box)
def LBASE(boundary="p f f", nt=3, e="0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", head="", model="hertz", wall=True, extra=""):
    return (head + "atom_style granular\natom_modify map array\nboundary " + boundary + "\nnewton off\ncommunicate single vel yes\n"
            "units si\nregion reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box\n" + f"create_box {nt} reg\n" +
            "neighbor 0.002 bin\nneigh_modify delay 0\n" +
            f"fix m1 all property/global youngsModulus peratomtype {' '.join(['5e6'] * nt)}\n"
            f"fix m2 all property/global poissonsRatio peratomtype {' '.join(['0.3'] * nt)}\n"
            f"fix m7 all property/global coefficientFriction peratomtypepair {nt} {' '.join(['0.5'] * nt * nt)}\n"
            f"fix m3 all property/global coefficientRestitution peratomtypepair {nt} {e}\n" + extra +
            f"pair_style gran model {model} tangential history\npair_coeff * *\n" +
            (f"fix wprim all wall/gran model {model} tangential history primitive type {nt} zplane 0.0\n" if wall else "") +
            "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n")


def LIN(gap, z=0.1, xc=0.0, t1=1, t2=2):
    s = 0.005 + gap
    return (f"create_atoms {t1} single {xc - s / 2:.6f} 0 {z} units box\ncreate_atoms {t2} single {xc + s / 2:.6f} 0 {z} units box\n"
            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {V1:.10f} 0 0\nvelocity lv2 set {V2:.10f} 0 0\n")


def LWALL(h=H0, x=0.0, t=1):
    v = math.sqrt(1 - 2 * 9.81 * h)
    return (f"create_atoms {t} single {x} 0 {0.002 + h:.6f} units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
            f"velocity lv1 set 0 0 {-v:.10f}\n")


def LG(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN(0.1e-3) if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


G11 = 1.1e-3
VZ = dict(AXIS="z")
WALL = dict(PAIR="type 1 on wall floor")
NP4 = dict(NP="1 4")
NP1 = dict(NP="1")

# ================================================================ E: run every made as its parts (round 35 rule 1)
PC = "pair_coeff 1 2 hooke {k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
PCs = lambda k: PC.format(k=k)
G = lambda part: 0.1e-3 + (part - 1) * 1e-3      # gap: meet 0.1 ms into part `part` of parts of 1000 steps
EV = lambda *cmds: "run 4000 every 1000 " + " ".join('"' + c + '"' for c in cmds) + "\n"
L("E01_step_part2", "every \"pair_coeff 1 2 hooke $(2000+step)\", meets in part 2 (kn 3000)", EV(PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E02_step_part3", "E01 meeting in part 3 (kn 4000)", EV(PCs("$(2000+step)")), pair=IN(G(3)), live="part 3")
L("E03_step_part4", "E01 meeting in part 4 (kn 5000)", EV(PCs("$(2000+step)")), pair=IN(G(4)), live="part 4")
L("E04_same_words_const_then_step", "two pair_coeff 1 2 in the every: a constant (5000) then $(2000+step): the last wins (3000 in part 2)",
  EV(PCs("5000"), PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E05_same_words_step_then_const", "two pair_coeff 1 2: $(2000+step) then a constant 5000 (the constant wins: 5000)", EV(PCs("$(2000+step)"), PCs("5000")), pair=IN(G(2)), live="part 2")
L("E06_star_const_then_12_step", "pair_coeff * * kn 5000 (constant) then pair_coeff 1 2 $(2000+step) (3000 in part 3? no: part 2)",
  EV("pair_coeff * * " + HK5, PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E07_var_redefined_read_after", "variable kn equal 2000; run 3000 every 1000 \"variable kn equal $(2000+step)\"; pair_coeff 1 2 ${kn} after the run (5000); meets in run 2",
  'variable kn equal 2000\nrun 3000 every 1000 "variable kn equal $(2000+step)"\n' + PCs("${kn}") + "\nrun 3000\n", pair=IN(3.1e-3), live="run 2")
L("E08_var_self_increment", "variable kn equal 2000; every \"variable kn equal $(v_kn+1000)\" \"pair_coeff ${kn}\" (4000 in part 3)",
  'variable kn equal 2000\n' + EV("variable kn equal $(v_kn+1000)", PCs("${kn}")), pair=IN(G(3)), live="part 3")
L("E09_string_var_redefined_read_after", "variable kn string 2000; every \"variable kn string $(2000+step)\"; after the run pair_coeff ${kn} (6000); meets in run 2",
  'variable kn string 2000\nrun 4000 every 1000 "variable kn string $(2000+step)"\n' + PCs("${kn}") + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2")
IFE = ("'if \"$(step) < 1500\" then \"" + PCs("3000") + "\" elif \"$(step) < 2500\" \"" + PCs("4000") + "\" else \"" + PCs("5000") + "\"'")
L("E10_if_elif_else_part2", "every if/elif/else on $(step): part 2 kn 3000", "run 4000 every 1000 " + IFE + "\n", pair=IN(G(2)), live="part 2")
L("E11_if_elif_else_part3", "E10 meeting in part 3: kn 4000", "run 4000 every 1000 " + IFE + "\n", pair=IN(G(3)), live="part 3")
L("E12_if_elif_else_part4", "E10 meeting in part 4: kn 5000", "run 4000 every 1000 " + IFE + "\n", pair=IN(G(4)), live="part 4")
L("E13_if_var_step_else", "variable s equal step; every 'if \"${s} > 2500\" then \"pair_coeff 5000\" else \"pair_coeff 3000\"' (part 3: 3000)",
  "variable s equal step\nrun 4000 every 1000 'if \"${s} > 2500\" then \"" + PCs("5000") + "\" else \"" + PCs("3000") + "\"'\n", pair=IN(G(3)), live="part 3")
L("E14_include_nested_two", "every \"include a.in\"; a.in includes b.in; b.in: pair_coeff $(2000+step) (part 3: 4000)", EV("include a.in"), pair=IN(G(3)), live="part 3",
  data={"a.in": "include b.in\n", "b.in": PCs("$(2000+step)") + "\n"})
L("E15_include_defines_var", "every \"include v.in\"; v.in: variable kk equal $(2000+step), pair_coeff ${kk}; after the run pair_coeff ${kk} again (6000), meets in run 2",
  EV("include v.in") + PCs("${kk}") + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2",
  data={"v.in": "variable kk equal $(2000+step)\n" + PCs("${kk}") + "\n"})
L("E16_include_defines_var_part2", "E15's include, meeting in part 2 (3000)", EV("include v.in"), pair=IN(G(2)), live="part 2",
  data={"v.in": "variable kk equal $(2000+step)\n" + PCs("${kk}") + "\n"})
L("E17_include_with_if", "every \"include c.in\"; c.in holds an if on $(step) (control flow in the include)", EV("include c.in"), pair=IN(G(3)), live="part 3",
  data={"c.in": 'if "$(step) >= 2000" then "' + PCs("4000") + '" else "' + PCs("3000") + '"\n'})
L("E18_time_timestep_in_every_part3", "every \"timestep 5e-7\" \"pair_coeff $(2000+1e6*time)\": time 0.0015 after part 2 (kn 3500, dt 5e-7 in part 3)",
  EV("timestep 5e-7", PCs("$(2000+1e6*time)")), pair=IN(1.6e-3), live="part 3")
L("E19_time_timestep_in_every_part2", "E18 meeting in part 2 (kn 3000 at time 0.001; dt 5e-7)", EV("timestep 5e-7", PCs("$(2000+1e6*time)")), pair=IN(G(2)), live="part 2")
L("E20_time_after_dt_change_before", "timestep 2e-6; run 500; timestep 1e-6; run 3000 every 1000 \"pair_coeff $(1000+1e6*time)\" (time 0.002 after part 1: 3000)",
  "timestep 2e-6\nrun 500\ntimestep 1e-6\nrun 3000 every 1000 \"" + PCs("$(1000+1e6*time)") + "\"\n", pair=IN(2.1e-3), live="part 2 of run 2")
L("E21_time_var_timestep_between_parts", "variable kt equal 2000+1e6*time; every \"timestep 2e-6\" \"pair_coeff ${kt}\": part 3 kn 2000+3000=5000 (dt 2e-6: step error larger)",
  "variable kt equal 2000+1e6*time\n" + EV("timestep 2e-6", PCs("${kt}")), pair=IN(3.1e-3), live="part 3")
L("E22_start_stop", "run 4000 start 0 stop 8000 every 1000 \"pair_coeff $(2000+step)\" (part 2: 3000)",
  'run 4000 start 0 stop 8000 every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(G(2)), live="part 2")
L("E23_start_stop_offset", "run 500; run 4000 start 0 stop 6000 every 1000 \"pair_coeff $(1500+step)\" (part 2 of run 2: step 1500: 3000)",
  'run 500\nrun 4000 start 0 stop 6000 every 1000 "' + PCs("$(1500+step)") + '"\n', pair=IN(2.1e-3 - 0.5e-3), live="part 2 of run 2")
L("E24_start_stop_ramp_var", "REFUSE: variable r equal ramp(2000,6000); run 4000 start 0 stop 4000 every 1000 \"pair_coeff ${r}\"",
  'variable r equal ramp(2000,6000)\nrun 4000 start 0 stop 4000 every 1000 "' + PCs("${r}") + '"\n', pair=IN(G(2)), live="part 2")
L("E25_pre_no_part2", "run 4000 pre no every 1000 \"pair_coeff $(2000+step)\" (3000)", 'run 4000 pre no every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(G(2)), live="part 2")
L("E26_pre_no_part3_after_run", "run 1000; run 3000 pre no every 1000 \"pair_coeff $(2000+step)\" (part 2 of run 2: step 2000: 4000)",
  'run 1000\nrun 3000 pre no every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(2.1e-3), live="part 2 of run 2")
POUR = ("region pr block 0.002 0.012 0.002 0.012 0.07 0.095 units box\n"
        "fix ins all pour 6 1 4767 region pr diam one 0.004 dens 2500 2500 vel 0 0 0 0 0\n")
L("E27_fix_pour_step", "fix pour (6 spheres far off) in the deck; every \"pair_coeff $(2000+step)\" (part 2: 3000; runs made for real)",
  POUR + EV(PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E28_fix_pour_step_part3", "E27 meeting in part 3 (4000)", POUR + EV(PCs("$(2000+step)")), pair=IN(G(3)), live="part 3")
L("E29_fix_pour_x1", "fix pour; every \"pair_coeff $(2000+1e6*(x[1]-0.017))\" (x of atom 1 after part 1: 0.018221: kn 3221)",
  POUR + EV(PCs("$(2000+1e6*(x[1]-0.017))")), pair=IN(G(2)), live="part 2")
MOL = "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.004\n\nMasses\n\n1 8.37758e-5\n"
DEP = "molecule sph sph.mol\nregion pr block 0.002 0.012 0.002 0.012 0.07 0.095 units box\nfix dep all deposit 3 0 1000 4711 region pr near 0.005 mol sph vz -0.1 -0.1 units box\n"
L("E30_fix_deposit_step", "fix deposit (a sphere every 1000 steps, far off); every \"pair_coeff $(2000+step)\" (part 2: 3000)",
  DEP + EV(PCs("$(2000+step)")), pair=IN(G(2)), live="part 2", data={"sph.mol": MOL})
L("E31_loop_around_every", "variable i loop 2; label lp; run 2000 every 1000 \"pair_coeff $(2000+step)\"; next i; jump SELF lp (meets at step 2100: 4000)",
  'variable i loop 2\nlabel lp\nrun 2000 every 1000 "' + PCs("$(2000+step)") + '"\nnext i\njump SELF lp\n', pair=IN(G(3)), live="part 1 of pass 2")
L("E32_loop_around_every_part2", "E31 meeting at step 1100 (pass 1 part 2: 3000)",
  'variable i loop 2\nlabel lp\nrun 2000 every 1000 "' + PCs("$(2000+step)") + '"\nnext i\njump SELF lp\n', pair=IN(G(2)), live="part 2 of pass 1")
L("E33_x1_position", "every \"pair_coeff $(2000+1e6*(x[1]-0.017))\": atom 1's x after part 1 (0.018221: 3221; unmoved 0.01745: 2450)",
  EV(PCs("$(2000+1e6*(x[1]-0.017))")), pair=IN(G(2)), live="part 2")
L("E34_xcm_group", "every \"pair_coeff $(2000+1e6*(xcm(lv1,x)-0.017))\" (group function: 3221)", EV(PCs("$(2000+1e6*(xcm(lv1,x)-0.017))")), pair=IN(G(2)), live="part 2")
L("E35_atom_var_indexed", "variable ax atom x; variable kk equal 2000+1e6*(v_ax[1]-0.017); every \"pair_coeff ${kk}\" (3221)",
  "variable ax atom x\nvariable kk equal 2000+1e6*(v_ax[1]-0.017)\n" + EV(PCs("${kk}")), pair=IN(G(2)), live="part 2")
L("E36_vz_gravity", "every \"pair_coeff $(2000-1e6*vz[1])\" (vz after part 1 under gravity: -0.00981: kn 11810)", EV(PCs("$(2000-1e6*vz[1])")), pair=IN(G(2)), live="part 2")
L("E37_format_v_1f", "variable kx equal 2000+1.37*step; every \"pair_coeff $(v_kx:%.1f)\" (3370.0)", "variable kx equal 2000+1.37*step\n" + EV(PCs("$(v_kx:%.1f)")), pair=IN(G(2)), live="part 2")
L("E38_format_e0_rounds", "every \"pair_coeff $(2000+1.4*step:%.0e)\" (3400 printed 3e+03: kn 3000)", EV(PCs("$(2000+1.4*step:%.0e)")), pair=IN(G(2)), live="part 2")
L("E39_format_concat", "every \"pair_coeff $(2+step/1000:%.0f)000\" (text after the immediate: 3000)", EV(PCs("$(2+step/1000:%.0f)000")), pair=IN(G(2)), live="part 2")
L("E40_format_var_0f_part3", "variable kx equal 2000+0.75*step; every \"pair_coeff $(v_kx:%.0f)\" (part 3: 3500)", "variable kx equal 2000+0.75*step\n" + EV(PCs("$(v_kx:%.0f)")), pair=IN(G(3)), live="part 3")
L("E41_refuse_ramp_direct", "REFUSE: every \"pair_coeff $(ramp(2000,6000))\"", EV(PCs("$(ramp(2000,6000))")), pair=IN(G(2)), live="part 2")
L("E42_refuse_ramp_var", "REFUSE: variable r equal ramp(2000,6000); every \"pair_coeff ${r}\"", "variable r equal ramp(2000,6000)\n" + EV(PCs("${r}")), pair=IN(G(2)), live="part 2")
L("E43_refuse_swiggle", "REFUSE: every \"pair_coeff $(swiggle(3000,1000,0.004))\"", EV(PCs("$(swiggle(3000,1000,0.004))")), pair=IN(G(2)), live="part 2")
L("E44_refuse_elapsed", "REFUSE: variable ke equal 2000+elapsed; every \"pair_coeff ${ke}\"", "variable ke equal 2000+elapsed\n" + EV(PCs("${ke}")), pair=IN(G(2)), live="part 2")
L("E45_refuse_c_direct", "REFUSE: compute k all ke; every \"pair_coeff $(2000+1e9*c_k)\"", "compute k all ke\n" + EV(PCs("$(2000+1e9*c_k)")), pair=IN(G(2)), live="part 2")
L("E46_refuse_c_var", "REFUSE: compute k all ke; variable kk equal 2000+1e9*c_k; every \"pair_coeff ${kk}\"", "compute k all ke\nvariable kk equal 2000+1e9*c_k\n" + EV(PCs("${kk}")), pair=IN(G(2)), live="part 2")
L("E47_refuse_upto", "REFUSE: run 1000; run 5000 upto every 1000 \"pair_coeff $(2000+step)\"", 'run 1000\nrun 5000 upto every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(2.1e-3), live="part 2 of run 2")
L("E48_refuse_1001_parts", "REFUSE: run 2002 every 2 'if \"$(step) == 1000\" then \"pair_coeff 5000\"' (1001 parts)",
  "run 2002 every 2 'if \"$(step) == 1000\" then \"" + PCs("5000") + "\"'\n", pair=IN(G(2)), live="step 1100")
L("E49_1000_parts_if", "run 2000 every 2 'if \"$(step) == 1000\" then \"pair_coeff 5000\"' (1000 parts; meets at step 1100: 5000)",
  "run 2000 every 2 'if \"$(step) == 1000\" then \"" + PCs("5000") + "\"'\n", pair=IN(G(2)), live="step 1100")
L("E50_next_index_in_every", "variable kk index 3000 4000 5000; every \"pair_coeff ${kk}\" \"next kk\" (part 2: 3000, part 3: 4000)",
  "variable kk index 3000 4000 5000\n" + EV(PCs("${kk}"), "next kk"), pair=IN(G(3)), live="part 3")
L("E51_reset_timestep_in_every", "every \"reset_timestep $(step+1000)\" \"pair_coeff $(2000+step)\" (after part 1 the step is 2000: 4000)",
  EV("reset_timestep $(step+1000)", PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E52_set_density_step", "every \"set type 2 density $(2500+step)\" (3500 in part 2; round 34 E10 refused, LAMMPS 0.401076)", EV("set type 2 density $(2500+step)"), pair=IN(G(2)), live="part 2")
L("E53_wall_step", "WALL: every \"fix floor all wall/gran granular hooke $(2000+step) ...\" (round 34 E13: LAMMPS 0.441600)",
  EV("fix floor all wall/gran granular hooke $(2000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"), pair=WALLP(0.0011), live="part 2", **WALL)
L("E54_timestep_step", "every \"timestep $(1e-6*(1+step/2000))\" (round 34 E22: 0.413654)", EV("timestep $(1e-6*(1+step/2000))"), pair=IN(G(2)), live="part 2")
L("E55_if_set_type", "pair_coeff 1 1 kn 5000; every 'if \"$(step) >= 1000\" then \"set atom 2 type 1\"' (pair 1 1 from part 2: 0.578975)",
  "pair_coeff 1 1 " + HK5 + "\nrun 4000 every 1000 'if \"$(step) >= 1000\" then \"set atom 2 type 1\"'\n", pair=IN(G(2)), live="part 2", PAIR="types 1 1")
L("E56_two_every_runs_var_carried", "run 2000 every 1000 \"variable kn equal $(2000+step)\"; run 2000 every 1000 \"pair_coeff ${kn}\" (in run 2 part 1: kn 4000 from step 2000? no: part 2 of run 2: 5000 set at 3000 from kn of step... )",
  'run 2000 every 1000 "variable kn equal $(2000+step)"\nrun 2000 every 1000 "' + PCs("${kn}") + '"\n', pair=IN(G(4)), live="part 2 of run 2")
L("E57_const_fix_and_step_coeff", "every \"fix grav all gravity 9.81 vector 0 0 -1\" (constant, given again) \"pair_coeff $(2000+step)\" (3000)",
  EV("fix grav all gravity 9.81 vector 0 0 -1", PCs("$(2000+step)")), pair=IN(G(2)), live="part 2")
L("E58_v_ref_equal_in_every", "variable kk equal 2000+step; every \"pair_coeff $(v_kk)\" (part 3: 4000)", "variable kk equal 2000+step\n" + EV(PCs("$(v_kk)")), pair=IN(G(3)), live="part 3")
L("E59_every_reads_step_after_reset", "reset_timestep 5000 before; every \"pair_coeff $(step-3000)\" (part 2: step 6000: 3000)",
  "reset_timestep 5000\n" + EV(PCs("$(step-3000)")), pair=IN(G(2)), live="part 2")
L("E60_include_two_deep_defines_var_read_after", "every \"include a.in\" (a.in includes w.in: variable kw equal $(3000+step)); after run, pair_coeff ${kw} (7000), meets in run 2",
  EV("include a.in") + PCs("${kw}") + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2", data={"a.in": "include w.in\n", "w.in": "variable kw equal $(3000+step)\n"})
L("E61_wall_sphere_time", "WALL: variable kw equal 2000+1e6*time; every \"timestep 5e-7\" \"fix floor ... hooke ${kw}\" (part 3: 3500)",
  "variable kw equal 2000+1e6*time\n" + EV("timestep 5e-7", "fix floor all wall/gran granular hooke ${kw} 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"),
  pair=WALLP(0.0016), live="part 3", **WALL)

# ---- LIGGGHTS run every (no clocked pass: runs made for real)
LE = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 {e} 0.7 {e} 0.4 0.45 0.7 0.45 0.8"
LEV = lambda *cmds: "run 4000 every 1000 " + " ".join('"' + c + '"' for c in cmds) + "\n"
LG("L01_lig_every_var_step", "LIGGGHTS: variable e equal 0.5+step/10000; every \"fix m3 ... ${e}\" (part 2: 0.6)", "variable e equal 0.5+step/10000\n" + LEV(LE.format(e="${e}")),
   pair=LIN(G(2)), live="part 2")
LG("L02_lig_every_var_step_part3", "L01 meeting in part 3 (0.7)", "variable e equal 0.5+step/10000\n" + LEV(LE.format(e="${e}")), pair=LIN(G(3)), live="part 3")
LG("L03_lig_every_immediate_step", "LIGGGHTS: every \"fix m3 ... $(0.5+step/10000)\" (immediate, if LIGGGHTS has it)", LEV(LE.format(e="$(0.5+step/10000)")), pair=LIN(G(2)), live="part 2")
LG("L04_lig_every_if_step", "LIGGGHTS: variable s equal step; every 'if \"${s} >= 2000\" then \"fix m3 ... 0.8\"' (part 3: 0.8)",
   "variable s equal step\nrun 4000 every 1000 'if \"${s} >= 2000\" then \"" + LE.format(e="0.8") + "\"'\n", pair=LIN(G(3)), live="part 3")
LG("L05_lig_loop_every", "LIGGGHTS: a loop of 2 around run 2000 every 1000 \"fix m3 ... ${e}\" (e 0.5+step/10000; meets at 2100: 0.7)",
   "variable e equal 0.5+step/10000\nvariable i loop 2\nlabel lp\nrun 2000 every 1000 \"" + LE.format(e="${e}") + "\"\nnext i\njump SELF lp\n", pair=LIN(G(3)), live="pass 2")
LG("L06_lig_every_include", "LIGGGHTS: every \"include m.in\" (m.in: fix m3 ... ${e}, e of step) (part 2: 0.6)", "variable e equal 0.5+step/10000\n" + LEV("include m.in"),
   pair=LIN(G(2)), live="part 2", data={"m.in": LE.format(e="${e}") + "\n"})
LG("L07_lig_every_var_redefined_after", "LIGGGHTS: every \"variable ee equal ${e}\"... no: variable e0 string 0.5; every 'variable e0 string ${e}'; after run fix m3 ${e0} (0.9), run 2",
   "variable e equal 0.5+step/10000\nvariable e0 string 0.5\nrun 4000 every 1000 \"variable e0 string ${e}\"\n" + LE.format(e="${e0}") + "\nrun 3000\n", pair=LIN(4.1e-3), live="run 2")
LG("L08_lig_every_time", "LIGGGHTS: variable e equal 0.5+100*time; every \"fix m3 ... ${e}\" (part 3: 0.7)", "variable e equal 0.5+100*time\n" + LEV(LE.format(e="${e}")), pair=LIN(G(3)), live="part 3")

# ---- wave 2: the atom map given (LAMMPS stops on x[1] without it: E29 E33 E35 E36), parts of 2000 steps where dt is halved
# (E18 E19 E61 met in parts of 0.5 ms that end inside the contact)
MAP = BASE(head="atom_modify map array\n")
L("E62_map_x1_position", "E33 with atom_modify map array: every \"pair_coeff $(2000+1e6*(x[1]-0.017))\" (x[1] after part 1 0.018221: 3221)",
  EV(PCs("$(2000+1e6*(x[1]-0.017))")), pre=MAP, pair=IN(G(2)), live="part 2")
L("E63_map_vz_gravity", "E36 with the map: every \"pair_coeff $(2000-1e6*vz[1])\" (vz after part 1 -0.00981: 11810)", EV(PCs("$(2000-1e6*vz[1])")), pre=MAP, pair=IN(G(2)), live="part 2")
L("E64_map_atom_var_indexed", "E35 with the map: variable ax atom x; kk equal 2000+1e6*(v_ax[1]-0.017); every \"pair_coeff ${kk}\"",
  "variable ax atom x\nvariable kk equal 2000+1e6*(v_ax[1]-0.017)\n" + EV(PCs("${kk}")), pre=MAP, pair=IN(G(2)), live="part 2")
L("E65_map_pour_x1", "E29 with the map: fix pour; every \"pair_coeff $(2000+1e6*(x[1]-0.017))\"", POUR + EV(PCs("$(2000+1e6*(x[1]-0.017))")), pre=MAP, pair=IN(G(2)), live="part 2")
L("E66_map_x1_part3", "E62 meeting in part 3 (x[1] at step 2000: 0.018993: 3993)", EV(PCs("$(2000+1e6*(x[1]-0.017))")), pre=MAP, pair=IN(G(3)), live="part 3")
EV2 = lambda *cmds: "run 8000 every 2000 " + " ".join('"' + c + '"' for c in cmds) + "\n"
L("E67_time_dt_halved_part2", "run 8000 every 2000 \"timestep 5e-7\" \"pair_coeff $(2000+1e6*time)\": part 2 kn 4000 at dt 5e-7 (contact inside the part)",
  EV2("timestep 5e-7", PCs("$(2000+1e6*time)")), pair=IN(2.1e-3), live="part 2")
L("E68_time_dt_halved_part3", "E67 meeting in part 3 (time 0.003: kn 5000)", EV2("timestep 5e-7", PCs("$(2000+1e6*time)")), pair=IN(3.1e-3), live="part 3")
L("E69_wall_time_dt_halved", "WALL: variable kw equal 2000+1e6*time; run 8000 every 2000 \"timestep 5e-7\" \"fix floor ... ${kw}\" (part 3: 5000)",
  "variable kw equal 2000+1e6*time\n" + EV2("timestep 5e-7", "fix floor all wall/gran granular hooke ${kw} 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"),
  pair=WALLP(0.0031), live="part 3", **WALL)
L("E70_time_dt_halved_part2_early", "E19 met 10 steps into part 2 (kn 3000 at dt 5e-7; the contact ends inside the 0.5 ms part)",
  EV("timestep 5e-7", PCs("$(2000+1e6*time)")), pair=IN(1.005e-3), live="part 2")

# ================================================================ N: pairs held through ghosts, nsq, read_restart (round 35 rule 2)
FFF = BASE(boundary="f f f")
FFFX = BASE(boundary="f f f", head="processors * 1 1\n")
L("N01_fff_displace_pre_no_z", "f f f, no processors; the pair along z across z 0.05; run 1000; displace_atoms 0 0 0; run 3000 pre no (round 34 P63: SW-NP)",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=FFF, pair=IN(G11, ax="z"), **VZ)
L("N02_fff_balance_pre_no_x", "f f f, processors * 1 1; the pair across x 0.02; run 1000; balance 1.0 x uniform; run 3000 pre no (round 34 P47)",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
L("N03_fff_change_box_pre_no", "f f f, processors * 1 1; run 1000; change_box all x final 0 0.04 units box; run 3000 pre no",
  "run 1000\nchange_box all x final 0 0.04 units box\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
L("N04_fff_tiled_rcb_pre_no", "f f f; comm_style tiled; run 1000; balance 1.0 rcb; run 3000 pre no", "comm_style tiled\nrun 1000\nbalance 1.0 rcb\nrun 3000 pre no\n", pre=FFF, pair=IN(G11))
L("N05_fff_every_balance_pre_no", "f f f, processors * 1 1; run 4000 pre no every 1000 \"balance 1.0 x uniform\" (part 2)",
  'run 4000 pre no every 1000 "balance 1.0 x uniform"\n', pre=FFFX, pair=IN(G11), live="part 2")
L("N06_fff_wall_sphere_displace_pre_no", "WALL f f f: run 500; displace_atoms all move 0 0 0; run 3000 pre no (a wall contact: no ghost pair)",
  "run 500\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=FFF, pair=WALLP(0.0011), **WALL)
L("N07_fff_wall_and_pair_balance", "f f f processors * 1 1: the pair across x 0.02 and a type 1 sphere falling on the floor; balance; pre no (the wall row measured)",
  "run 500\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=FFFX, pair=WALLP(0.0011, x=0.01) + "create_atoms 1 single 0.015 0.02 0.05\ncreate_atoms 2 single 0.0205 0.02 0.05\nset atom 2*3 diameter 0.004 density 2500\n", **WALL)
L("N08_fff_pair_one_side_balance", "f f f processors * 1 1: the pair inside x < 0.02 (one sub-domain); balance; pre no (conservative if left out)",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11, xc=0.01))
L("N09_fff_nsq_short_pre_no", "f f f, neighbor 0.0001 nsq (the pair 1.1 mm apart: not in the list); run 1000; run 3000 pre no",
  "neighbor 0.0001 nsq\nrun 1000\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
L("N10_ppf_nsq_short", "p p f, neighbor 0.0001 nsq, one run of 3000 (the list rebuilt as they close)", "neighbor 0.0001 nsq\nrun 3000\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("N11_fff_nsq_short_one_run", "f f f, neighbor 0.0001 nsq, one run of 3000", "neighbor 0.0001 nsq\nrun 3000\n", pre=FFFX, pair=IN(G11))
L("N12_fff_nsq_big_skin", "f f f, neighbor 0.005 nsq (the contact inside the list), run 1000; run 3000 pre no", "neighbor 0.005 nsq\nrun 1000\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
RST = ("run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n{pair}"
       "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\nrun 3000\n")
L("N13_restart_no_pair_style_ppf", "p p f: run 1000; write_restart; clear; read_restart (pair granular from the file, not given again); run 3000", RST.format(pair=""),
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("N14_restart_no_pair_style_fff", "N13 in f f f", RST.format(pair=""), pre=FFFX, pair=IN(G11))
L("N15_restart_pair_style_again_fff", "N14 with pair_style and pair_coeff given again (control)", RST.format(pair="pair_style granular\npair_coeff * * " + HK + "\n"), pre=FFFX, pair=IN(G11))
L("N16_restart_no_pair_style_wall", "WALL p p f: the restart without pair_style given again; the floor sphere", RST.format(pair="").replace("run 1000", "run 500"), pair=WALLP(0.0011), **WALL)
L("N17_fff_include_every_displace", "f f f processors * 1 1; run 4000 pre no every 1000 \"include d.in\" (d.in: displace_atoms 0 0 0)",
  'run 4000 pre no every 1000 "include d.in"\n', pre=FFFX, pair=IN(G11), live="part 2", data={"d.in": "displace_atoms all move 0 0 0 units box\n"})
L("N18_fff_balance_then_run0_pre_no", "f f f processors * 1 1; run 1000; balance; run 0; run 3000 pre no (set up again: right)",
  "run 1000\nbalance 1.0 x uniform\nrun 0\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
L("N19_fff_balance_pre_no_then_run", "f f f processors * 1 1; run 500; balance; run 500 pre no; run 3000 (meets in the last run)",
  "run 500\nbalance 1.0 x uniform\nrun 500 pre no\nrun 3000\n", pre=FFFX, pair=IN(G11 + 0.0005))
L("N20_fff_comm_style_brick_again_pre_no", "f f f processors * 1 1; run 1000; comm_style brick (given again); run 3000 pre no",
  "run 1000\ncomm_style brick\nrun 3000 pre no\n", pre=FFFX, pair=IN(G11))
L("N21_fff_11_pair_across_balance", "f f f processors * 1 1, pair_coeff 1 1 kn 5000; the pair types 1 1 across x 0.02; balance; pre no",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=FFFX + "pair_coeff 1 1 " + HK5 + "\n", pair=IN(G11, t2=1), PAIR="types 1 1")
LG("N22_lig_fff_displace_pre_no", "LIGGGHTS f f f processors 2 1 1: run 1000; displace_atoms 0 0 0; run 3000 pre no (round 34 P66: 0.499928)",
   "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=LBASE(boundary="f f f", head="processors 2 1 1\n"), pair=LIN(G11), NP="2")

# ================================================================ R: replicate (round 35 rule 3)
RB = BASE(wall=False)
L("R01_replicate_pre_no", "run 1000; replicate 1 1 1; run 3000 pre no (refused now; LAMMPS moves no atom)", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("R02_replicate_run0_pre_no", "run 1000; replicate 1 1 1; run 0; run 3000 pre no (0.413435)", "run 1000\nreplicate 1 1 1\nrun 0\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("R03_replicate_in_include_pre_no", "run 1000; include r.in (replicate 1 1 1); run 3000 pre no", "run 1000\ninclude r.in\nrun 3000 pre no\n", pre=RB, pair=IN(G11),
  data={"r.in": "replicate 1 1 1\n"})
L("R04_replicate_in_every_pre_no", "run 4000 pre no every 1000 \"replicate 1 1 1\" (meets in part 2)", 'run 4000 pre no every 1000 "replicate 1 1 1"\n', pre=RB, pair=IN(G11), live="part 2")
L("R05_replicate_in_every", "run 4000 every 1000 \"replicate 1 1 1\" (each part set up)", 'run 4000 every 1000 "replicate 1 1 1"\n', pre=RB, pair=IN(G11), live="part 2")
L("R06_replicate_run0_postno_pre_no", "run 1000; replicate 1 1 1; run 0 post no; run 3000 pre no", "run 1000\nreplicate 1 1 1\nrun 0 post no\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("R07_replicate_run0_pre_no_pre_no", "run 1000; replicate 1 1 1; run 0 pre no; run 3000 pre no (run 0 not set up either)", "run 1000\nreplicate 1 1 1\nrun 0 pre no\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("R08_replicate_pre_yes", "run 1000; replicate 1 1 1; run 3000 pre yes", "run 1000\nreplicate 1 1 1\nrun 3000 pre yes\n", pre=RB, pair=IN(G11))
L("R09_replicate_pre_no_meets_later", "run 1000; replicate 1 1 1; run 1000 pre no (frozen); run 3000 (meets there: 0.413435, late)",
  "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11 + 1e-3))
L("R10_replicate_in_include_nested_pre_no", "run 1000; include a.in (includes r.in: replicate 1 1 1); run 3000 pre no", "run 1000\ninclude a.in\nrun 3000 pre no\n", pre=RB, pair=IN(G11),
  data={"a.in": "include r.in\n", "r.in": "replicate 1 1 1\n"})
L("R11_replicate_if_pre_no", "run 1000; if \"1 > 0\" then \"replicate 1 1 1\"; run 3000 pre no", "run 1000\nif \"1 > 0\" then \"replicate 1 1 1\"\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
L("R12_replicate_211_run0_pre_no", "run 1000; replicate 2 1 1; run 0; run 3000 pre no (ids 1 2 still the pair)", "run 1000\nreplicate 2 1 1\nrun 0\nrun 3000 pre no\n", pre=RB, pair=IN(G11))
LG("R13_lig_replicate_pre_no", "LIGGGHTS: run 1000; replicate 1 1 1; run 3000 pre no", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", pre=LBASE(wall=False), pair=LIN(G11))
LG("R14_lig_replicate_run", "LIGGGHTS: run 1000; replicate 1 1 1; run 3000", "run 1000\nreplicate 1 1 1\nrun 3000\n", pre=LBASE(wall=False), pair=LIN(G11))
LG("R15_lig_replicate_run0_pre_no", "LIGGGHTS: run 1000; replicate 1 1 1; run 0; run 3000 pre no", "run 1000\nreplicate 1 1 1\nrun 0\nrun 3000 pre no\n", pre=LBASE(wall=False), pair=LIN(G11))
L("R16_replicate_first_then_pre_no", "replicate 1 1 1 before any run; run 1000 pre no; run 3000 (a first run with pre no is set up anyway)",
  "replicate 1 1 1\nrun 1000 pre no\nrun 3000\n", pre=RB, pair=IN(G11))


# ---- wave 3: after SW-LI (LIGGGHTS runs an include named in run every only after the whole run), files the every
# writes, next in the every, exclusions and pair_style again on the step, reset_timestep with a time
LG("L09_lig_every_include_part3", "L06 meeting in part 3 (the audit: 0.7)", "variable e equal 0.5+step/10000\n" + LEV("include m.in"),
   pair=LIN(G(3)), live="part 3", data={"m.in": LE.format(e="${e}") + "\n"})
LG("L10_lig_every_include_nested", "LIGGGHTS every \"include a.in\" (a.in includes m.in), meets in part 2", "variable e equal 0.5+step/10000\n" + LEV("include a.in"),
   pair=LIN(G(2)), live="part 2", data={"a.in": "include m.in\n", "m.in": LE.format(e="${e}") + "\n"})
LG("L11_lig_every_include_then_run", "L06 then run 3000 where the pair meets (after the run LIGGGHTS runs the four includes at step 4000: e 0.9)",
   "variable e equal 0.5+step/10000\n" + LEV("include m.in") + "run 3000\n", pair=LIN(4.1e-3), live="run 2", data={"m.in": LE.format(e="${e}") + "\n"})
LG("L12_lig_every_include_const", "LIGGGHTS every \"include m.in\" with a constant e 0.8 in m.in (meets in part 2)", LEV("include m.in"),
   pair=LIN(G(2)), live="part 2", data={"m.in": LE.format(e="0.8") + "\n"})
LG("L13_lig_every_if_include", "LIGGGHTS every 'if \"${s} >= 1000\" then \"include m.in\"' (m.in: e 0.8), meets in part 2",
   "variable s equal step\nrun 4000 every 1000 'if \"${s} >= 1000\" then \"include m.in\"'\n", pair=LIN(G(2)), live="part 2", data={"m.in": LE.format(e="0.8") + "\n"})
LG("L14_lig_every_include_wall", "LIGGGHTS WALL (type 1 on the xplane-less floor, e 1-3 0.7): every \"include w.in\" (w.in: fix m3 with 1-3 0.9), meets in part 2",
   LEV("include w.in"), pair=LWALL(0.0011), live="part 2", data={"w.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.9 0.5 0.4 0.45 0.9 0.45 0.8\n"},
   PAIR="type 1 on wall wprim")
L("E71_next_index_five", "variable kk index 3000 4000 5000 6000 7000; every \"pair_coeff ${kk}\" \"next kk\" (part 3: 4000)",
  "variable kk index 3000 4000 5000 6000 7000\n" + EV(PCs("${kk}"), "next kk"), pair=IN(G(3)), live="part 3")
L("E72_print_file_then_include", "every \"print 'pair_coeff ... $(2000+step) ...' file k.in\" \"include k.in\" (a file the every writes; part 2: 3000)",
  "run 4000 every 1000 \"print '" + PCs("$(2000+step)") + "' file f35k.in screen no\" \"include f35k.in\"\n", pair=IN(G(2)), live="part 2")
L("E73_if_step_exclude", "every 'if \"$(step) >= 1000\" then \"neigh_modify exclude type 1 2\"' (from part 2 the pair is not seen)",
  "run 4000 every 1000 'if \"$(step) >= 1000\" then \"neigh_modify exclude type 1 2\"'\n", pair=IN(G(2)), live="part 2")
L("E74_pair_style_again_step", "every \"pair_style granular\" \"pair_coeff * * hooke $(2000+step) ...\" (part 2: 3000)",
  EV("pair_style granular", "pair_coeff * * hooke $(2000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3"), pair=IN(G(2)), live="part 2")
L("E75_reset_timestep_time", "reset_timestep 0 time 0.005; every \"pair_coeff $(1000+1e6*time)\" (time 0.006 after part 1: 7000)",
  "reset_timestep 0 time 0.005\n" + EV(PCs("$(1000+1e6*time)")), pair=IN(G(2)), live="part 2")
L("E76_time_var_after_run_dt_change", "run 2000 every 1000 \"timestep 2e-6\"; pair_coeff $(1000+1e6*time) after it (time 0.003: 4000); run 3000 meets",
  'run 2000 every 1000 "timestep 2e-6"\n' + PCs("$(1000+1e6*time)") + "\ntimestep 1e-6\nrun 3000\n", pair=IN(3.1e-3), live="run 2")
L("E77_every_include_print_var", "every \"include p.in\" (p.in: variable kk equal $(2000+step); print ${kk}); pair_coeff ${kk} after the run (6000)",
  EV("include p.in") + PCs("${kk}") + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2", data={"p.in": "variable kk equal $(2000+step)\nprint ${kk}\n"})
L("E78_if_elif_var_string", "variable kn string 2000; every 'if \"$(step) == 2000\" then \"variable kn string 5000\"' \"pair_coeff ${kn}\" (part 2: 2000, part 3: 5000)",
  "variable kn string 2000\nrun 4000 every 1000 'if \"$(step) == 2000\" then \"variable kn string 5000\"' \"" + PCs("${kn}") + "\"\n", pair=IN(G(3)), live="part 3")
L("N23_fff_nsq_cutoff_short", "f f f processors * 1 1: pair_style granular 0.0045 (a global cutoff short of the 5 mm contact), neighbor 0.0003 nsq; one run",
  "run 3000\n", pre=BASE(boundary="f f f", head="processors * 1 1\n", pstyle="pair_style granular 0.0045\n") + "neighbor 0.0003 nsq\n", pair=IN(G11))
L("N24_fff_bin_cutoff_short", "N23 with a bin list", "run 3000\n", pre=BASE(boundary="f f f", head="processors * 1 1\n", pstyle="pair_style granular 0.0045\n") + "neighbor 0.0003 bin\n", pair=IN(G11))
L("N25_ppf_nsq_pre_no_periodic", "p p f processors * 1 1, nsq; the pair across the periodic x boundary; run 1000; run 3000 pre no", "neighbor 0.001 nsq\nrun 1000\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=PER(G11))
L("N26_restart_no_pair_style_two_bins", "f f f processors * 1 1: restart without pair_style again, the pair 1.1 mm apart across a bin border and the sub-domain border (x 0.02)",
  RST.format(pair=""), pre=FFFX, pair=IN(G11, xc=0.0201))
L("R17_replicate_every_no_pre", "run 4000 every 1000 \"replicate 1 1 1\" \"run 0\"? no: replicate then run 0 post no in the every, pre no run (meets in part 2)",
  'run 4000 pre no every 1000 "replicate 1 1 1" "run 0 post no"\n', pre=RB, pair=IN(G11), live="part 2")

# ---- wave 5: an include under an if and with control flow in the every, time-dependent fixes (runs made for real),
# an adaptive time step, several processes with balance in the every
L("E79_if_then_include", "every 'if \"$(step) >= 1000\" then \"include m.in\"' (m.in: pair_coeff 5000), meets in part 2",
  "run 4000 every 1000 'if \"$(step) >= 1000\" then \"include m.in\"'\n", pair=IN(G(2)), live="part 2", data={"m.in": PCs("5000") + "\n"})
L("E80_include_with_jump", "every \"include j.in\" (j.in: jump SELF skip; a pair_coeff 5000 skipped; label skip; pair_coeff $(2000+step))",
  EV("include j.in"), pair=IN(G(2)), live="part 2", data={"j.in": "jump SELF skip\n" + PCs("5000") + "\nlabel skip\n" + PCs("$(2000+step)") + "\n"})
L("E81_wiggle_wall_time_fix", "WALL: fix floor ... wiggle z 0 1 (a time-dependent fix, amplitude 0); every \"pair_coeff 1 2 $(2000+step)\"; the pair meets in part 2",
  EV(PCs("$(2000+step)")), pre=BASE().replace("zplane 0 NULL\n", "zplane 0 NULL wiggle z 0.0 1.0\n"), pair=IN(G(2)), live="part 2")
L("E82_fix_move_far_sphere_time", "fix move linear on a far sphere (time-dependent); every \"pair_coeff $(2000+1e6*time)\" (part 3: 4000)",
  "create_atoms 2 single 0.005 0.005 0.03\nset atom 3 diameter 0.004 density 2500\ngroup far id 3\nfix mv far move linear 0.01 0 0\nunfix integ\ngroup rest id 1 2\nfix integ rest nve/sphere\n"
  + EV(PCs("$(2000+1e6*time)")), pair=IN(G(3)), live="part 3")
L("E83_dt_reset_time", "fix dt/reset 1 NULL NULL 5e-7 units box (dt from the fastest sphere: 6.5e-7); every \"pair_coeff $(2000+1e6*time)\" (part 2: 2648)",
  "fix dtr all dt/reset 1 NULL NULL 5e-7 units box\n" + EV(PCs("$(2000+1e6*time)")), pair=IN(0.70e-3), live="part 2")
L("E84_include_timestep_time", "every \"include t.in\" (t.in: timestep 5e-7; pair_coeff $(2000+1e6*time)) in parts of 2000 (part 3: 5000)",
  EV2("include t.in"), pair=IN(3.1e-3), live="part 3", data={"t.in": "timestep 5e-7\n" + PCs("$(2000+1e6*time)") + "\n"})
L("E85_fff_np_every_balance_step", "f f f processors * 1 1; the pair across x 0.02; run 4000 every 1000 \"balance 1.0 x uniform\" \"pair_coeff $(2000+step)\" (part 2: 3000)",
  EV("balance 1.0 x uniform", PCs("$(2000+step)")), pre=FFFX, pair=IN(G(2)), live="part 2")
L("E86_elaplong", "variable ke equal 2000+elaplong; every \"pair_coeff ${ke}\" (elaplong: steps since the run's first step, 3000 in part 2)",
  "variable ke equal 2000+elaplong\n" + EV(PCs("${ke}")), pair=IN(G(2)), live="part 2")
L("E87_elaplong_start", "run 500; variable ke equal 2000+elaplong; run 4000 start 0 stop 8000 every 1000 \"pair_coeff ${ke}\" (elaplong from start 0: 3500 in part 2 of run 2)",
  'run 500\nvariable ke equal 2000+elaplong\nrun 4000 start 0 stop 8000 every 1000 "' + PCs("${ke}") + '"\n', pair=IN(1.6e-3), live="part 2 of run 2")
LG("L15_lig_every_direct_then_include", "LIGGGHTS every \"fix m3 ... 0.8\" \"include m.in\" (m.in: e 0.6): LIGGGHTS 0.8 from part 2 (the include after the run)",
   LEV(LE.format(e="0.8"), "include m.in"), pair=LIN(G(2)), live="part 2", data={"m.in": LE.format(e="0.6") + "\n"})
LG("L16_lig_loop_every_include", "LIGGGHTS loop of 2 around run 2000 every 1000 \"include m.in\" (e of step), meets at step 2100 (the includes of pass 1 ran at 2000: e 0.7)",
   "variable e equal 0.5+step/10000\nvariable i loop 2\nlabel lp\nrun 2000 every 1000 \"include m.in\"\nnext i\njump SELF lp\n", pair=LIN(G(3)), live="pass 2",
   data={"m.in": LE.format(e="${e}") + "\n"})

# ---- wave 6: commands in the every whose effect hangs on where the spheres are after a part (a region lv2 enters
# during part 1: x 0.02355 at the start, 0.023321 after 1000 steps)
RG = "region R block 0.0230 0.0234 0 0.04 0 0.1 units box\n"
L("E88_set_region_type", "pair_coeff 1 1 kn 5000; every \"set region R type 1\" (R holds lv2 after part 1 only: the pair is 1 1 from part 2, 0.578975)",
  "pair_coeff 1 1 " + HK5 + "\n" + RG + EV("set region R type 1"), pair=IN(G(2)), live="part 2", PAIR="types 1 1")
L("E89_group_region_set", "pair_coeff 1 1 kn 5000; every \"group gr region R\" \"set group gr type 1\" (as E88 by a group)",
  "pair_coeff 1 1 " + HK5 + "\n" + RG + EV("group gr region R", "set group gr type 1"), pair=IN(G(2)), live="part 2", PAIR="types 1 1")
L("E90_count_region", "every \"pair_coeff 1 2 hooke $(2000+1000*count(all,R))\" (R holds lv2 after part 1: 3000)",
  RG + EV(PCs("$(2000+1000*count(all,R))")), pair=IN(G(2)), live="part 2")
L("E91_set_region_density", "every \"set region R density 5000\" (lv2 in R after part 1: its density doubled in part 2)",
  RG + EV("set region R density 5000"), pair=IN(G(2)), live="part 2")
L("E92_if_x_set_type", "pair_coeff 1 1 kn 5000; every 'if \"$(x[2]) < 0.0234\" then \"set atom 2 type 1\"' with the map (lv2 passes 0.0234 during part 1)",
  "pair_coeff 1 1 " + HK5 + "\nrun 4000 every 1000 'if \"$(x[2]) < 0.0234\" then \"set atom 2 type 1\"'\n", pre=MAP, pair=IN(G(2)), live="part 2", PAIR="types 1 1")
L("E93_set_region_type_pre_no", "E88 with pre no", "pair_coeff 1 1 " + HK5 + "\n" + RG + 'run 4000 pre no every 1000 "set region R type 1"\n', pair=IN(G(2)), live="part 2", PAIR="types 1 1")
L("E94_set_region_type_between_runs", "pair_coeff 1 1 kn 5000; run 1000; set region R type 1; run 3000 (the same as separate runs: control)",
  "pair_coeff 1 1 " + HK5 + "\n" + RG + "run 1000\nset region R type 1\nrun 3000\n", pair=IN(G(2)), PAIR="types 1 1")

# ---- wave 7: after a run every whose commands read the step (a clocked pass), a command whose effect hangs on where
# the spheres are (lv2 enters R2 only during the every run: x 0.02505 at the start, 0.024136 after 4000 steps)
RG2 = "region R2 block 0.0239 0.0243 0 0.04 0 0.1 units box\n"
CLK = 'run 4000 every 1000 "' + PCs("$(2000+0*step)") + '"\n'
L("E95_clocked_then_set_region", "every \"pair_coeff $(2000+0*step)\" (reads the step); then set region R2 type 1 (lv2 there after the run only); pair_coeff 1 1 kn 5000; run 3000 (0.578975)",
  RG2 + CLK + "set region R2 type 1\npair_coeff 1 1 " + HK5 + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2", PAIR="types 1 1")
L("E96_clocked_then_delete_region", "E95 with delete_atoms region R2 after the every run (lv2 gone: no contact)",
  RG2 + CLK + "delete_atoms region R2\nrun 3000\n", pair=IN(4.1e-3), live="run 2")
L("E97_clocked_then_group_region", "E95 by group gr region R2 / set group gr type 1", RG2 + CLK + "group gr region R2\nset group gr type 1\npair_coeff 1 1 " + HK5 + "\nrun 3000\n",
  pair=IN(4.1e-3), live="run 2", PAIR="types 1 1")
L("E98_clocked_then_if_x", "with the map: E95 by if \"$(x[2]) < 0.0243\" then \"set atom 2 type 1\" after the every run", CLK + "if \"$(x[2]) < 0.0243\" then \"set atom 2 type 1\"\npair_coeff 1 1 " + HK5 + "\nrun 3000\n",
  pre=MAP, pair=IN(4.1e-3), live="run 2", PAIR="types 1 1")
L("E99_time_clocked_then_set_region", "every \"pair_coeff $(2000+0*time)\"; then E95's set region R2 type 1", RG2 + 'run 4000 every 1000 "' + PCs("$(2000+0*time)") + '"\n'
  + "set region R2 type 1\npair_coeff 1 1 " + HK5 + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2", PAIR="types 1 1")
L("EA0_include_clocked_then_set_region", "every \"include k.in\" (k.in: pair_coeff $(2000+0*step)); then E95's set region", RG2 + EV("include k.in")
  + "set region R2 type 1\npair_coeff 1 1 " + HK5 + "\nrun 3000\n", pair=IN(4.1e-3), live="run 2", PAIR="types 1 1", data={"k.in": PCs("$(2000+0*step)") + "\n"})

# ---- wave 8: part lengths, post no, a single part, a loop variable read in the every
L("EB1_parts_uneven", "run 3500 every 1000 \"pair_coeff $(2000+step)\" (parts 1000 1000 1000 500?), meets in part 3 (4000)",
  'run 3500 every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(G(3)), live="part 3")
L("EB2_post_no", "run 4000 post no every 1000 \"pair_coeff $(2000+step)\" (part 2: 3000)", 'run 4000 post no every 1000 "' + PCs("$(2000+step)") + '"\n', pair=IN(G(2)), live="part 2")
L("EB3_single_part_then_run", "run 2000 every 2000 \"pair_coeff $(2000+step)\" (one part; 4000 after it); run 3000 meets (4000)",
  'run 2000 every 2000 "' + PCs("$(2000+step)") + '"\nrun 3000\n', pair=IN(2.1e-3), live="run 2")
L("EB4_loop_var_in_every", "variable i loop 3; label l; run 1000 every 500 \"pair_coeff $(1000+1000*v_i)\"; next i; jump SELF l (meets at step 1600: 3000)",
  'variable i loop 3\nlabel l\nrun 1000 every 500 "' + PCs("$(1000+1000*v_i)") + '"\nnext i\njump SELF l\n', pair=IN(1.6e-3), live="pass 2 part 2")
L("EB5_every_500_meets_part3", "run 2000 every 500 'if \"$(step) == 1000\" then \"pair_coeff 5000\"' (meets at step 1100: 5000)",
  "run 2000 every 500 'if \"$(step) == 1000\" then \"" + PCs("5000") + "\"'\n", pair=IN(G(2)), live="part 3")

L("EC1_reset_timestep0_time", "every \"reset_timestep 0\" \"pair_coeff $(2000+1e6*time)\" (the time goes on over the reset? part 3)",
  EV("reset_timestep 0", PCs("$(2000+1e6*time)")), pair=IN(G(3)), live="part 3")
L("EC2_reset_timestep0_time0", "every \"reset_timestep 0 time 0\" \"pair_coeff $(3000+1e6*time)\" (time 0 after each part: 3000)",
  EV("reset_timestep 0 time 0", PCs("$(3000+1e6*time)")), pair=IN(G(3)), live="part 3")

# ================================================================ O: ordinary modeller decks, shortened (sources in FINDINGS.md)
OD = os.path.join(HERE, "odecks")
F34 = os.path.join(HERE, "..", "field34", "decks")
O11 = {"PAIR": "types 1 1", "SEP": "1.0"}
DECKS["O01_mixer_granregion"] = (open(os.path.join(OD, "O01.in")).read(), "run 1", {}, dict(O11))
DECKS["O02_drum_pour"] = (open(os.path.join(OD, "O02.in")).read(), "run 2", {}, dict(O11))
DECKS["O03_funnel_granregion"] = (open(os.path.join(OD, "O03.in")).read(), "run 3", {}, dict(O11))
DECKS["O04_lig_simple_drop_np_every"] = (open(os.path.join(OD, "O04.in")).read(), "last run",
                                         {"10x10m-ground.stl": open(os.path.join(F34, "O03_lig_simple_drop_caesar", "10x10m-ground.stl")).read()},
                                         {"LIGGGHTS": "", "SEP": "0.5", "PAIR": "types 1 1"})
DECKS["O05_lig_snow_slope_np_every"] = (open(os.path.join(OD, "O05.in")).read(), "last run",
                                        {"slope.stl": open(os.path.join(F34, "O04_lig_snow_slope_kunwar", "slope.stl")).read()},
                                        {"LIGGGHTS": "", "SEP": "0.01", "PAIR": "types 1 1", "NP": "2"})


DECKS["O08_granregion_box"] = (open(os.path.join(OD, "O08.in")).read(), "run 1", {}, dict(O11))
DECKS["O09_pour_chute"] = (open(os.path.join(OD, "O09.in")).read(), "run 1", {}, dict(O11))
DECKS["O10_lig_contact_models"] = (open(os.path.join(OD, "O10.in")).read(), "run 1", {}, {"LIGGGHTS": "", "SEP": "0.005", "PAIR": "types 1 1"})
DECKS["O06_drum_pour_balance_after_pair"] = (open(os.path.join(OD, "O06.in")).read(), "run 2", {}, dict(O11))
DECKS["O07_pour_flatwall"] = (open(os.path.join(OD, "O07.in")).read(), "run 1", {}, {"PAIR": "types 2 2", "SEP": "1.0"})
RAW("X01_fix_balance_before_pair_history", "O02's stop made small: fix balance before pair_style granular with a history (linear_history); LAMMPS stops at the run",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
    "fix bal all balance 100 1.0 shift x 5 1.1\npair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3\n"
    "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n" + IN(0.1e-3) + "run 3000\n")
RAW("X02_fix_balance_after_pair_history", "X01 with fix balance after pair_style (control)",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
    "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3\nfix bal all balance 100 1.0 shift x 5 1.1\n"
    "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n" + IN(0.1e-3) + "run 3000\n")
RAW("X03_fix_wall_gran_history_before_pair", "a wall/gran with history given before pair_style (the order LAMMPS may refuse likewise)",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
    "fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3 zplane 0 NULL\n"
    "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1 0.3\n"
    "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n" + IN(0.1e-3) + "run 3000\n")

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
    print(len(DECKS), "decks")


if __name__ == "__main__":
    write(sys.argv[1:])
