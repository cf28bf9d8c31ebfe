"""Field round 15: write the LIGGGHTS decks (decks/NAME/in.deck, a LIGGGHTS marker file, G, STL files),
with round 14's header and materials (now tests/fieldkit/decks.py). usage: python make_ldecks.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import ATOMS, E3, HERTZ, MAT3, STIFF3, WALL3, lhead as head, RUN2000 as RUN  # noqa: E402,F401  (round 14's)

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")

DECKS = {}


def deck(name, text, g=1, files=None, data=None):
    DECKS[name] = (text, g, files or {}, data or {})


INT = "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
E3B = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.35 0.4 0.35 0.45 0.5 0.4 0.5 0.55\n"
deck("L01_restart_clear_new_e", "# write_restart, clear, read_restart, then materials given again with other e (0.3 ...): audited at the new e\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "write_restart f15.restart\nclear\nnewton off\nread_restart f15.restart\n"
     "neighbor 0.002 bin\nneigh_modify delay 0\ncommunicate single vel yes\n" + MAT3 + E3B
     + "pair_style gran model hertz tangential history\npair_coeff * *\n" + WALL3 + INT + "run 100\n")
deck("L02_restart_pair_style_changed", "# restart read back, then pair style hooke (not hertz) with the same e: audited as hooke\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "write_restart f15.restart\nclear\nnewton off\nread_restart f15.restart\n"
     "neighbor 0.002 bin\nneigh_modify delay 0\ncommunicate single vel yes\n" + MAT3 + E3
     + "fix m11 all property/global characteristicVelocity scalar 1.0\npair_style gran model hooke tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + INT + "run 100\n")
deck("L03_restart_resized_after_read", "# restart read back, then set type 2 diameter 0.008: the new size\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "write_restart f15.restart\nclear\nnewton off\nread_restart f15.restart\n"
     "neighbor 0.002 bin\nneigh_modify delay 0\ncommunicate single vel yes\n" + MAT3 + E3 + HERTZ + WALL3
     + "set type 2 diameter 0.008 density 1500\n" + INT + "run 100\n")
TPL = """fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003
fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.03 0.03 -0.03 0.03 0.02 0.1 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins
"""
deck("L04_insert_pack_two_templates_one_type", "# insert/pack with two templates of type 1 (r 2 and 3 mm): one type, two sizes\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + TPL + RUN)
deck("L05_distribution_weights_three_templates", "# particledistribution/discrete weights 0.1 0.3 0.6 over three templates of types 1, 2, 2 (2 at two densities)\n"
     + head() + MAT3 + E3 + "fix m11 all property/global characteristicVelocity scalar 1.0\n" + "pair_style gran model hooke tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n"
     + TPL.replace("atom_type 1 density constant 2500 radius constant 0.003", "atom_type 2 density constant 1000 radius constant 0.003")
     .replace("fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5",
              "fix pts3 all particletemplate/sphere 15485917 atom_type 2 density constant 3000 radius constant 0.003\n"
              "fix pdd all particledistribution/discrete 32452843 3 pts1 0.1 pts2 0.3 pts3 0.6") + RUN)
deck("L06_cohesion_sjkr2", "# cohesion sjkr2 with an energy density on 1 1 only\n" + head() + MAT3 + E3
     + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 300000 0 0 0 0 0 0 0 0\n"
     + "pair_style gran model hertz tangential history cohesion sjkr2\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history cohesion sjkr2 primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L07_hertzstiff_rolling_cdt", "# model hertz/stiffness with rolling_friction cdt\n" + head() + MAT3 + STIFF3
     + "fix m10 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hertz/stiffness tangential history rolling_friction cdt\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz/stiffness tangential history rolling_friction cdt primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L08_hooke_tangential_damping_off", "# model hooke, tangential_damping off (head-on: no effect)\n" + head() + MAT3 + E3
     + "pair_style gran model hooke tangential history tangential_damping off\npair_coeff * *\n"
     + "fix m11 all property/global characteristicVelocity scalar 1.0\n" + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L09_hooke_limitforce_absolute_damping", "# model hooke/stiffness with limitForce on and absolute_damping on (gamman not scaled by the mass)\n"
     + head() + MAT3 + STIFF3 + "fix m12 all property/global gamman_abs peratomtypepair 3 0.3 0.2 0.1 0.2 0.25 0.15 0.1 0.15 0.2\nfix m13 all property/global gammat_abs peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hooke/stiffness tangential history limitForce on absolute_damping on\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L10_mesh_move_mesh_vibrating", "# a mesh floor moved by move/mesh wiggle (vibrated): named?\n" + head() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3\n"
     + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + "fix mv all move/mesh mesh cad wiggle amplitude 0 0 0.0005 period 0.01\n" + ATOMS + RUN,
     files={"plane0.stl": ("plane", "0", "0.04")})
deck("L11_mesh_move_mesh_linear_tangential", "# a mesh floor moved in its plane (move/mesh linear 0.1 0 0)\n" + head() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3\n"
     + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + "fix mv all move/mesh mesh cad linear 0.1 0 0\n" + ATOMS + RUN,
     files={"plane0.stl": ("plane", "0", "0.04")})
deck("L12_adapt_growth_count_read", "# LIGGGHTS fix adapt growth, a count read in an if after the run (runs made), unfix, run\n"
     + head() + MAT3 + STIFF3 + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + ATOMS.replace("0.006 density 1500", "0.004 density 2500") + INT
     + "variable dgrow equal 0.004+0.02*time\nfix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\n"
     'variable n equal count(all)\nif "${n} < 1" then "quit"\nunfix ad\nrun 100\n')
deck("L13_restart_after_insertion", "# insert/pack once, write_restart, clear, read_restart: the inserted atoms from the restart\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + TPL.replace("atom_type 1 density constant 2500 radius constant 0.003", "atom_type 2 density constant 1000 radius constant 0.003")
     + RUN + "write_restart f15.restart\nclear\nnewton off\nread_restart f15.restart\n"
     "neighbor 0.002 bin\nneigh_modify delay 0\ncommunicate single vel yes\n" + MAT3 + E3 + HERTZ + WALL3 + INT + "run 100\n")
deck("L14_hertz_e_from_variable_after_step", "# e of 1 1 from step after a run (0.3 + step/10000 = 0.5)\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN + "variable e11 equal 0.3+step/10000\n"
     "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${e11} 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\nrun 100\n")

deck("L15_neigh_stale_lists", "# LIGGGHTS with neighbor 1e-5 bin and neigh_modify delay 0 every 200 check no (lists rebuilt every 2 ms)\n"
     + head().replace("neighbor 0.002 bin\nneigh_modify delay 0", "neighbor 1e-5 bin\nneigh_modify delay 0 every 200 check no")
     + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)

deck("L16_neigh_exclude_type_12", "# LIGGGHTS neigh_modify exclude type 1 2: no 1-2 contact\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "neigh_modify exclude type 1 2\n" + RUN)


def write(name):
    text, g, files, data = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=True, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
