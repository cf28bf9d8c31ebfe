"""Field round 16: write the LAMMPS decks (decks/NAME/in.deck, G, ARGS, extra files) on round 15's header
(tests/field15/make_decks.py: head, HK, HM, TWO, TWO4, GRAV, FLOOR, TAIL). Each deck's first comment says what
it tries. usage: python make_decks16.py [NAME ...]"""
import importlib.util, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
_s = importlib.util.spec_from_file_location("md15", os.path.join(HERE, "..", "field15", "make_decks.py"))
M = importlib.util.module_from_spec(_s)
_s.loader.exec_module(M)
head, HK, HM, TWO, TWO4, GRAV, FLOOR, TAIL = M.head, M.HK, M.HM, M.TWO, M.TWO4, M.GRAV, M.FLOOR, M.TAIL
BASE = head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
BASEH = head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + TAIL
DECKS = {}


def deck(name, text, g=1, args=None, extra=None):
    DECKS[name] = (text, g, args, extra or {})


# ---------------------------------------------------------------- neighbour lists rebuilt every K steps
NB = "neighbor 1e-4 bin\n"
deck("n01_every10_checkyes_below", "# every 10 check yes, skin 1e-4, dt 1e-5: the audit's bound skin/(K dt) = 1 m/s; all speeds below it\n"
     + BASE + TWO4 + NB + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.05 0.1 0.3 0.5 0.9")
deck("n02_every10_checkno_near", "# every 10 check no, skin 1e-4, dt 1e-5: bound 1 m/s; speeds just below and above\n"
     + BASE + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n03_delay10_every1_checkyes_near", "# LAMMPS' older default delay 10 every 1 check yes, skin 1e-4: bound 1 m/s\n"
     + BASE + TWO4 + NB + "neigh_modify delay 10 every 1 check yes\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n04_every2_checkyes_skin2e-5", "# every 2 check yes, skin 2e-5: bound 1 m/s; speeds below\n"
     + BASE + TWO4 + "neighbor 2e-5 bin\nneigh_modify every 2 delay 0 check yes\nrun 1000\n", g="0.2 0.5 0.9")
deck("n05_once_yes", "# neigh_modify once yes: lists built once per run, never rebuilt during it\n"
     + BASE + TWO4 + "neigh_modify once yes\nrun 1000\n", g=1)
deck("n06_include_group_type1", "# neigh_modify include g1 (type 1 first): pairs of two type-2 atoms are in no list\n"
     + BASE + TWO4 + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.004 density 2500\ngroup g1 type 1\natom_modify first g1\nneigh_modify include g1\nrun 1000\n", g=1)
deck("n07_skin_cut_in_stage2", "# stage 1 default lists; stage 2 neighbor 1e-5 and every 20 check no (bound 0.05 m/s)\n"
     + BASE + TWO4 + "run 1000\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 1000\n", g=1)
deck("n08_wallgran_stale_lists", "# every 50 check no, skin 1e-5 (bound 0.02 m/s); LAMMPS' fix wall/gran uses no list: walls keep eps\n"
     + BASE + TWO4 + "neighbor 1e-5 bin\nneigh_modify every 50 delay 0 check no\nrun 1000\n", g=1)
deck("n09_wallregion_stale_lists", "# wall/gran/region block under every 50 check no, skin 1e-5\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + "region bx block 0 0.04 0 0.04 0 0.08 side in units box\n"
     + f"fix wr all wall/gran/region granular {HK} region bx\n" + TAIL + TWO4
     + "neighbor 1e-5 bin\nneigh_modify every 50 delay 0 check no\nrun 1000\n", g=1)
deck("n10_granhookehistory_stale", "# pair gran/hooke/history 2000 NULL 30 NULL 0.5 1, every 10 check no, skin 1e-4: bound 1 m/s\n"
     + head() + "pair_style gran/hooke/history 2000 NULL 30 NULL 0.5 1\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 2000 NULL 30 NULL 0.5 1 zplane 0 NULL\n" + TAIL + TWO4 + NB
     + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n11_hertzmaterial_stale", "# hertz/material viscoelastic, every 10 check no, skin 1e-4: bound 1 m/s\n"
     + BASEH + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.5 0.9 1.1 2")
deck("n12_neigh_from_variables", "# every ${k}, skin $(1e-4): the values LAMMPS substitutes\n"
     + BASE + TWO4 + "variable k equal 10\nvariable sk equal 1e-4\nneighbor ${sk} bin\nneigh_modify every ${k} delay 0 check no\nrun 1000\n",
     g="0.5 2")
deck("n13_neigh_after_last_run", "# every 20 check no set after the last run: used by no run\n"
     + BASE + TWO4 + "run 1000\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\n", g=1)
deck("n14_skin_zero_every5", "# neighbor 0.0 bin with every 5 check no: only overlapping pairs listed at a build\n"
     + BASE + TWO4 + "neighbor 0.0 bin\nneigh_modify every 5 delay 0 check no\nrun 1000\n", g=1)
deck("n15_delay_not_multiple", "# every 3 delay 4: LAMMPS stops at the run's set-up (delay must be 0 or a multiple of every)\n"
     + BASE + TWO4 + NB + "neigh_modify every 3 delay 4 check no\nrun 1000\n", g=1)
deck("n16_loop_every_changes", "# a loop of three passes, each with every 5*i check no, skin 1e-4 (bounds 2, 1, 0.67 m/s)\n"
     + BASE + TWO4 + NB + "variable i loop 3\nlabel top\nneigh_modify every $(5*v_i) delay 0 check no\nrun 500\nnext i\njump SELF top\n",
     g="0.5 0.8 1.5")
deck("n17_every10_checkyes_partner_still", "# every 10 check yes, skin 1e-4; type 2 held still by no integrator (fix on type 1 only)\n"
     + BASE.replace("fix integ all nve/sphere\n", "") + TWO4 + "group mv type 1\nfix integ mv nve/sphere\n" + NB
     + "neigh_modify every 10 delay 0 check yes\nrun 1000\n", g="0.3 0.6 0.9")
deck("n18_nsq_every10_checkno", "# neighbor 1e-4 nsq with every 10 check no: bound 1 m/s as bin\n"
     + BASE + TWO4 + "neighbor 1e-4 nsq\nneigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.9 1.1")
deck("n19_every1_delay5_checkno", "# every 1 delay 5 check no: rebuilt every 5 steps; skin 1e-4 -> bound 2 m/s\n"
     + BASE + TWO4 + NB + "neigh_modify every 1 delay 5 check no\nrun 1000\n", g="1.5 1.9 2.1")
deck("n20_hybrid_granular_stale", "# pair_style hybrid granular granular under every 10 check no, skin 1e-4\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff * * granular 1 {HK}\npair_coeff 2 2 granular 2 {HM}\n" + GRAV + FLOOR + TAIL
     + TWO4 + NB + "neigh_modify every 10 delay 0 check no\nrun 1000\n", g="0.9 1.1")


def write(name):
    text, g, args, extra = DECKS[name]
    d = os.path.join(D, name)
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(text)
    open(os.path.join(d, "G"), "w").write(f"{g}\n")
    if args:
        open(os.path.join(d, "ARGS"), "w").write(args + "\n")
    for f, t in extra.items():
        os.makedirs(os.path.dirname(os.path.join(d, f)), exist_ok=True)
        open(os.path.join(d, f), "w").write(t)


if __name__ == "__main__":
    for n in (sys.argv[1:] or DECKS):
        write(n)
    print(len(DECKS), "decks")
