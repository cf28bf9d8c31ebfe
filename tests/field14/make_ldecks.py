"""Field round 14: write the LIGGGHTS decks (decks/NAME/in.deck, a LIGGGHTS marker file, G, STL files).
usage: python make_ldecks.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import ATOMS, E3, HERTZ, MAT3, STIFF3, WALL3, lhead as head, RUN2000 as RUN  # noqa: E402,F401

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")


DECKS = {}


def deck(name, text, g=1, files=None, data=None):
    DECKS[name] = (text, g, files or {}, data or {})


deck("L01_e_one_everywhere", "# coefficientRestitution 1.0 for every pair and the wall: eps 1?\n" + head() + MAT3
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 1 1 1 1 1 1 1 1 1\n" + HERTZ + WALL3 + ATOMS + RUN)
deck("L02_e_tiny_1e-4", "# coefficientRestitution 0.0001 on 1 1 (LIGGGHTS demands e > 0.05)\n" + head() + MAT3
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.0001 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
deck("L03_variable_count_alias", "# the count of peratomtypepair from a variable, the atomtypepair alias, values from variables\n" + head()
     + "variable nt equal 3\nvariable e12 equal 0.55\n"
     + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair ${nt} 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
     + "fix m3 all property/global coefficientRestitution atomtypepair ${nt} 0.6 ${e12} 0.7 ${e12} 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
deck("L04_sjkr_one_pair_22", "# cohesion sjkr with energy density only on 2 2: 2 2 named, 1 1, 1 2 and the wall audited\n" + head() + MAT3 + E3
     + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 300000 0 0 0 0\n"
     + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history cohesion sjkr primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L05_sjkr_wall_pair_only", "# cohesion sjkr with energy density only on (1, wall type 3): the wall for type 1 named, the rest audited\n" + head() + MAT3 + E3
     + "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 300000 0 0 0 300000 0 0\n"
     + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history cohesion sjkr primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L06_hookestiff_two_templates_two_types", "# hooke/stiffness; a distribution of two templates of types 1 and 2 (r 2 mm rho 2500, r 3 mm rho 1000), inserted once\n"
     + head() + MAT3 + STIFF3 + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + """fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1000 radius constant 0.003
fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5
region ins block -0.03 0.03 -0.03 0.03 0.02 0.1 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins
""" + RUN)
deck("L07_rolling_epsd2_tangential_damping_off", "# hertz e with rolling_friction epsd2 and tangential_damping off: head-on eps unchanged?\n" + head() + MAT3 + E3
     + "fix m10 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hertz tangential history rolling_friction epsd2 tangential_damping off\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential history rolling_friction epsd2 primitive type 3 zplane 0.0\n" + ATOMS + RUN)
deck("L08_hertzstiff_coarse_dt", "# hertz/stiffness at a coarse time step (few steps per contact): eps_at_dt\n" + head() + MAT3 + STIFF3.replace("kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000", "kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5").replace("gamman peratomtypepair 3 3000 2000 1000 2000 2500 1500 1000 1500 2000", "gamman peratomtypepair 3 3e5 3e5 3e5 3e5 3e5 3e5 3e5 3e5 3e5")
     + "pair_style gran model hertz/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN.replace("timestep 1e-5", "timestep 2e-4"))
deck("L09_mesh_scale_rotate_move", "# a mesh floor given in mm, scaled, rotated about z and moved to z = 0.001\n" + head() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane_mm.stl type 3 scale 0.001 rotate axis 0 0 1 angle 30 move 0 0 0.001\n"
     + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n" + ATOMS + RUN,
     files={"plane_mm.stl": ("plane", "0", "30")})
deck("L10_mesh_plane_and_primitive_1e-4", "# a mesh plane at z = 0 and a primitive plane at z = 1e-4, both under the spheres\n" + head() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface file plane0.stl type 3\n"
     + "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0001\n" + ATOMS + RUN,
     files={"plane0.stl": ("plane", "0", "0.04")})
deck("L11_two_primitive_planes_1e-4", "# two primitive planes in two fixes, z = 0 and z = 1e-4, both under the spheres\n" + head() + MAT3 + E3 + HERTZ
     + WALL3 + "fix wprim2 all wall/gran model hertz tangential history primitive type 3 zplane 0.0001\n" + ATOMS + RUN)
deck("L12_soft_particles_low_E", "# soft_particles yes with E = 1e5 (below LIGGGHTS' 5e6 check)\n" + head()
     + "soft_particles yes\n" + MAT3.replace("5e6 5e6 5e6", "1e5 1e5 1e5") + E3 + HERTZ + WALL3 + ATOMS + RUN)
deck("L13_hertz_limitforce_pair_only", "# limitForce on for the pair style, the wall without it; e 0.2 for 1 1 so the limit matters\n" + head() + MAT3
     + E3.replace("0.6 0.5 0.7", "0.2 0.5 0.7") + "pair_style gran model hertz tangential history limitForce on\npair_coeff * *\n"
     + WALL3 + ATOMS + RUN)

ADAPTL = (head() + MAT3 + STIFF3 + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + ATOMS.replace("0.006 density 1500", "0.004 density 2500") + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n")
deck("L14_adapt_growth_hookestiff", "# LIGGGHTS fix adapt grows every diameter from 4 to 6 mm in the run (reset no), then unfix and run again\n"
     + ADAPTL + "variable dgrow equal 0.004+0.02*time\nfix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\nunfix ad\nrun 100\n")
deck("L15_adapt_scale_hookestiff", "# LIGGGHTS fix adapt, diameter scaled by a constant 1.5 (scale yes, reset no), then unfix and run again\n"
     + ADAPTL + "variable s equal 1.5\nfix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 1000\nunfix ad\nrun 100\n")

deck("L16_adapt_ramp_hookestiff", "# LIGGGHTS fix adapt, the diameter ramped from 4 to 6 mm over the run by ramp() (reset no), then unfix and run again\n"
     + ADAPTL + "variable dgrow equal ramp(0.004,0.006)\nfix ad all adapt 1 atom diameter v_dgrow reset no\nrun 10000\nunfix ad\nrun 100\n")

deck("L17_wall_on_region_group_same_plane", "# a second primitive floor at z = 0 on a group picked by region (holding the type-2 sphere), beside the floor on all\n"
     + head() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + "region left block -0.02 0 INF INF INF INF units box\ngroup gl region left\n"
     + "fix wl gl wall/gran model hertz tangential history primitive type 3 zplane 0.0\n" + RUN)

deck("L18_template_radius_gaussian", "# a particle template with radius gaussian (LIGGGHTS-PUBLIC 3.8.0 has only constant)\n" + head() + MAT3 + E3 + HERTZ + WALL3
     + """fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius gaussian number 0.002 0.0002
fix pdd all particledistribution/discrete 32452843 1 pts1 1.0
region ins block -0.03 0.03 -0.03 0.03 0.02 0.1 units box
fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins
""" + RUN)

deck("L19_read_data_granular_columns", "# LIGGGHTS read_data (atom_style granular: id type diameter density x y z), hooke/stiffness (sizes matter)\n"
     + """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
read_data data.L19
neighbor 0.002 bin
neigh_modify delay 0
""" + MAT3 + STIFF3 + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n" + RUN,
     data={"data.L19": """L19

2 atoms
3 atom types

-0.05 0.05 xlo xhi
-0.05 0.05 ylo yhi
-0.01 0.15 zlo zhi

Atoms

1 1 0.005 1200 0.01 0 0.01
2 2 0.003 7800 -0.01 0 0.01
"""})


def write(name):
    text, g, files, data = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=True, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
