"""Field round 16: write the LIGGGHTS decks (decks/NAME/in.deck, a LIGGGHTS marker file, G, STL files) on round
14's header and materials (now tests/fieldkit/decks.py). usage: python make_ldecks16.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import ATOMS, E3, HERTZ, MAT3, STIFF3, WALL3, lhead as head, RUN2000 as RUN  # noqa: E402,F401  (round 14's)

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
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


# ---------------------------------------------------------------- run lengths from variables, loops, restarts, meshes
INT = "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
deck("L10_run_var_lengths", "# run ${n} with n equal 1500, then run ${m} with m = 2*n; a set between them reads nothing of the runs\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + INT + "variable n equal 1500\nvariable m equal 2*${n}\nrun ${n}\nset type 2 diameter 0.008\nrun ${m}\n")
deck("L11_loop_e_from_index", "# a loop over e = 0.3, 0.6, 0.9 for 1 1 (index variable), the matrix given again each pass, run 500 each\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + INT + "variable e index 0.3 0.6 0.9\nlabel top\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\nrun 500\nnext e\njump SELF top\n")
deck("L12_restart_in_loop", "# a loop of two passes: run, write_restart, clear, read_restart, materials again with e from the pass\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + INT + "run 300\nvariable k loop 2\nlabel top\nwrite_restart f16.restart\nclear\n"
     + "newton off\nread_restart f16.restart\nneighbor 0.002 bin\nneigh_modify delay 0\ncommunicate single vel yes\n" + MAT3
     + "variable e11 equal 0.3+0.2*${k}\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e11} 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n"
     + HERTZ + WALL3 + INT + "run 300\nnext k\njump SELF top\n")
deck("L13_two_meshes_one_wall", "# one fix wall/gran over two meshes: a floor at z = 0 and a roof at z = 0.1, both type 3\n"
     + head() + MAT3 + E3 + HERTZ + "fix cad1 all mesh/surface file plane0.stl type 3\nfix cad2 all mesh/surface file roof.stl type 3\n"
     + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 2 meshes cad1 cad2\n" + ATOMS + RUN,
     files={"plane0.stl": ("plane", "0", "0.04"), "roof.stl": ("plane", "0.1", "0.04")})
deck("L14_peratomtype_from_variables", "# E, nu, e from equal-style variables substituted in the property/global lines\n"
     + head() + "variable E1 equal 5e6\nvariable E2 equal 2*v_E1\nvariable nu equal 0.25\nvariable e12 equal 0.55\n"
     + "fix m1 all property/global youngsModulus peratomtype ${E1} ${E2} ${E1}\nfix m2 all property/global poissonsRatio peratomtype ${nu} ${nu} ${nu}\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 ${e12} 0.7 ${e12} 0.4 0.45 0.7 0.45 0.8\n"
     + "pair_style gran model hooke tangential history\npair_coeff * *\nfix m11 all property/global characteristicVelocity scalar 1.0\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L15_coarsegraining_2", "# coarsegraining 2 (LIGGGHTS scales the contact for coarse-grained particles)\n"
     + head().replace("create_box 3 reg\n", "create_box 3 reg\ncoarsegraining 2\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
deck("L16_contact_distance_factor", "# neigh_modify contact_distance_factor 1.5 (larger lists), delay 0\n"
     + nhead("neighbor 0.002 bin\nneigh_modify delay 0 contact_distance_factor 1.5\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
deck("L17_hooke_stiffness_peratomtype_loop", "# hooke/stiffness with kn from a loop variable: kn of 1 1 = 1000*i, i = 1..2\n"
     + head() + MAT3 + STIFF3 + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + INT
     + "variable i loop 2\nlabel top\nvariable k equal 1000*${i}\n"
     + "fix m4 all property/global kn peratomtypepair 3 ${k} 2500 3000 2500 4000 3500 3000 3500 5000\nrun 300\nnext i\njump SELF top\n")
deck("L18_run_every_print", "# run 2000 every 500 with a print between the parts\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + INT + 'run 2000 every 500 "print hello"\n')
deck("L19_set_loop_diameter", "# set type 1 diameter from an index variable in a loop (hertz: size enters nothing in eps but the steps)\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + INT + "variable d index 0.003 0.005\nlabel top\nset type 1 diameter ${d}\nrun 200\nnext d\njump SELF top\n")
deck("L20_mesh_stale_check_no_every5", "# a mesh floor with neigh_modify delay 0 every 5 check no, skin 1e-4 (bound 2 m/s)\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0 every 5 check no\n") + MAT3 + E3 + HERTZ + MESH + ATOMS + RUN, g="1 1.5 1.9", files=PL)

deck("L21_timestep_raised_stage2", "# LIGGGHTS: run at dt 1e-5, then timestep 5e-5 with nothing else changed, run again\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "timestep 5e-5\nrun 1000\n")

deck("L22_neigh_include_group", "# LIGGGHTS atom_modify first g1 + neigh_modify include g1 (g1 = type 1): pairs of two type-2 spheres in no list\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "create_atoms 2 single -0.03 0 0.01 units box\nset type 2 diameter 0.006 density 1500\n"
     + "group g1 type 1\natom_modify first g1\nneigh_modify include g1\n" + RUN)
deck("L23_delay5_skin1e-4_near", "# LIGGGHTS neigh_modify delay 5 (every 1 check yes), skin 1e-4: bound 2 m/s; speeds near it\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 5\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN, g="1.5 1.9 2.1")

deck("L24_clear_restores_delay10", "# skin 1e-4 and delay 0 in stage 1; write_restart, clear, read_restart, skin 1e-4 again without neigh_modify\n"
     "# (LIGGGHTS' delay 10 is back: bound 1 m/s) and e changed (a new stage)\n"
     + nhead("neighbor 1e-4 bin\nneigh_modify delay 0\n") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN
     + "write_restart f16.restart\nclear\nnewton off\nread_restart f16.restart\nneighbor 1e-4 bin\ncommunicate single vel yes\n" + MAT3
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n"
     + HERTZ + WALL3 + INT + "run 100\n", g="0.5 2")


def write(name):
    text, g, files, data = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=True, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
