"""Field round 16: write the LIGGGHTS decks (decks/NAME/in.deck, a LIGGGHTS marker file, G, STL files) on round
14's header and materials (tests/field14/make_ldecks.py). usage: python make_ldecks16.py [NAME ...]"""
import importlib.util, os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
_s = importlib.util.spec_from_file_location("ml14", os.path.join(HERE, "..", "field14", "make_ldecks.py"))
M = importlib.util.module_from_spec(_s)
_s.loader.exec_module(M)
head, MAT3, E3, HERTZ, WALL3, ATOMS, RUN, STIFF3 = M.head, M.MAT3, M.E3, M.HERTZ, M.WALL3, M.ATOMS, M.RUN, M.STIFF3
DECKS = {}


def deck(name, text, g=1, files=None, data=None):
    DECKS[name] = (text, g, files or {}, data or {})


def nhead(neigh):
    """round 14's header with its neighbour lines replaced"""
    return head().replace("neighbor 0.002 bin\nneigh_modify delay 0\n", neigh)


MESH = ("fix cad all mesh/surface file plane0.stl type 3\n"
        "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")
PL = {"plane0.stl": ("plane", "0", "0.04")}
# ---------------------------------------------------------------- neighbour lists
deck("L01_default_delay10_skin1e-4", "# no neigh_modify: LIGGGHTS' delay 10 every 1 check yes; skin 1e-4, dt 1e-5: bound 1 m/s\n"
     + nhead("neighbor 1e-4 bin\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN, g="0.5 0.9 1.1 2")
deck("L02_every10_checkyes_below", "# neigh_modify delay 0 every 10 check yes, skin 1e-4: the audit's bound 1 m/s; speeds below it\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 10 check yes\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN,
     g="0.05 0.3 0.6 0.7 0.9")
deck("L03_mesh_floor_delay10", "# a mesh floor under LIGGGHTS' default delay 10, skin 1e-4: bound 1 m/s\n"
     + nhead("neighbor 1e-4 bin\n") + MAT3 + E3 + HERTZ + MESH + ATOMS + RUN, g="0.5 0.9 1.1 2", files=PL)
deck("L04_every10_checkno_near", "# neigh_modify delay 0 every 10 check no, skin 1e-4: bound 1 m/s; just below and above\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 10 check no\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN, g="0.9 1.1")
deck("L05_lists_cut_in_stage2", "# stage 1 usual lists; stage 2 neighbor 1e-5 and every 20 check no (bound 0.05 m/s)\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "neighbor 1e-5 bin\nneigh_modify delay 0 every 20 check no\nrun 1000\n", g=1)
deck("L06_mesh_every10_checkyes_below", "# a mesh floor, delay 0 every 10 check yes, skin 1e-4; speeds below 1 m/s\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 10 check yes\n") + MAT3 + E3 + HERTZ + MESH + ATOMS + RUN,
     g="0.1 0.3 0.5 0.9", files=PL)


def write(name):
    text, g, files, data = DECKS[name]
    d = os.path.join(D, name)
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(text)
    open(os.path.join(d, "G"), "w").write(f"{g}\n")
    open(os.path.join(d, "LIGGGHTS"), "w").write("")
    for f, t in data.items():
        open(os.path.join(d, f), "w").write(t)
    for f, args in files.items():
        subprocess.run([sys.executable, os.path.join(HERE, "..", "field13", "stl.py"), *args, os.path.join(d, f)], check=True)


if __name__ == "__main__":
    for n in (sys.argv[1:] or DECKS):
        write(n)
    print(len(DECKS), "decks")
