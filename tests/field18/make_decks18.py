"""Field round 18: write the LAMMPS decks (p* pair models and mixing, s* sizes and masses, u* units and atom
styles, w* walls, k* kinematics, partners and time) and the LIGGGHTS decks (G*) as decks/NAME/in.deck with G (the
speeds), extra files and a LIGGGHTS marker. The headers are written out here (the shape of rounds 14 and 15's).
Each deck's first comment says what it tries. usage: python make_decks18.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the deck-folder writer of every round)
from fieldkit.decks import (ATOMS, E3, FLOOR, GRAV, HERTZ, HK, MAT3, TAIL, TL, TWO, TWO4, WALL3, head, lhead,  # noqa: E402
                            RUN2000 as RUN)  # the same lines as there

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
K = "damping mass_velocity tangential linear_nohistory 1 0.3"
HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"


BASEH = lambda model: head() + f"pair_style granular\npair_coeff * * {model}\n" + GRAV + FLOOR.replace(HK, model) + TAIL
DECKS = {}


def deck(name, text, g=1, files=None, data=None, liggghts=False):
    DECKS[name] = (text, g, files or {}, data or {}, liggghts)


# ================================================================ LAMMPS: pair models and mixing
deck("p01_mix_hertzmaterial_viscoelastic_E", "# 1 1 and 2 2 hertz/material viscoelastic with other E and nu; 1 2 mixed by LAMMPS (E* from both, eta geometric): eps depends on E*\n"
     + head() + "pair_style granular\n"
     + f"pair_coeff 1 1 hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}\n"
     + f"pair_coeff 2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}\n" + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("p02_mix_tsuji_e", "# 1 1 and 2 2 hertz/material tsuji with e 0.3 and 0.9; 1 2 mixed (e geometric?)\n"
     + head() + "pair_style granular\n"
     + f"pair_coeff 1 1 hertz/material 1e7 0.3 0.3 damping tsuji {TL}\n"
     + f"pair_coeff 2 2 hertz/material 5e7 0.9 0.2 damping tsuji {TL}\n" + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("p03_dmt_zero_cohesion", "# normal dmt with surface energy 0 (the Hertz force), damping viscoelastic\n"
     + BASEH(f"dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p04_dmt_cohesion", "# normal dmt with surface energy 0.05 J/m^2 (an attraction): not the model's law\n"
     + BASEH(f"dmt 1e7 1.4e7 0.3 0.05 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p05_jkr_cohesion", "# normal jkr with surface energy 0.05: hysteresis, the contact ends below zero overlap\n"
     + BASEH(f"jkr 1e7 1.4e7 0.3 0.05 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p06_hooke_viscoelastic", "# hooke normal with viscoelastic damping (alpha 1, gamma 1/2)\n"
     + BASEH(f"hooke 2000 300 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p07_hertz_velocity", "# hertz k_n with damping velocity (eta / m_eff)\n"
     + BASEH(f"hertz 1e6 0.05 damping velocity {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p08_hooke_tsuji_limit", "# hooke with damping tsuji 0.6 and limit_damping\n"
     + BASEH(f"hooke 2000 0.6 damping tsuji {TL} limit_damping") + TWO + "run 100\n", g="0.1 1")
deck("p09_hertz_coeffrest_limit", "# hertz k_n with coeff_restitution 0.5 and limit_damping (eps != e: the force rule)\n"
     + BASEH(f"hertz 1e6 0.5 damping coeff_restitution {TL} limit_damping") + TWO + "run 100\n", g="0.1 1")
deck("p10_hertz_mass_velocity", "# hertz k_n with mass_velocity (gamma 0 with alpha 3/2)\n"
     + BASEH(f"hertz 1e6 30 damping mass_velocity {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p11_ranges_three_types_labels", "# three types with labels; pair_coeff * b, then b* c* ranges by number, and a c a line reversed\n"
     + head(3) + "labelmap atom 1 a 2 b 3 c\npair_style granular\npair_coeff * * " + HK + "\n"
     + f"pair_coeff * b hooke 4000 3000 {K}\npair_coeff 2*3 3 hooke 8000 3000 {K}\npair_coeff c a hooke 16000 3000 {K}\n"
     + GRAV + FLOOR + TAIL + TWO4 + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.004 density 2500\nrun 100\n", g=1)
deck("p12_hybrid_overlay_two_granular", "# pair_style hybrid/overlay granular granular: two granular sub-styles on every pair, their forces add\n"
     + head() + "pair_style hybrid/overlay granular granular\n"
     + f"pair_coeff * * granular 1 {HK}\npair_coeff * * granular 2 hooke 6000 1000 {K}\n"
     + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("p13_hybrid_overlay_granular_soft", "# hybrid/overlay granular + soft (a repulsion that acts at the contact): another force on the pair\n"
     + head() + "pair_style hybrid/overlay granular soft 0.004\n"
     + f"pair_coeff * * granular {HK}\npair_coeff * * soft 0.5\n" + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("p14_hybrid_granular_by_type", "# pair_style hybrid: 1 1 and 2 2 granular hooke, 1 2 gran/hooke (one setting for all its pairs)\n"
     + head() + "pair_style hybrid granular gran/hooke 4000 NULL 50 NULL 0.5 0\n"
     + f"pair_coeff 1 1 granular {HK}\npair_coeff 2 2 granular {HK}\npair_coeff 1 2 gran/hooke\n" + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("p15_gran_hertz_history_limit", "# pair_style gran/hertz/history with limit_damping\n"
     + head() + "pair_style gran/hertz/history 1e6 NULL 2000 NULL 0.5 0 limit_damping\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hertz/history 1e6 NULL 2000 NULL 0.5 0 zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g="0.1 1")
deck("p16_restyle_keeps_coeffs", "# pair_style granular re-issued after a run: LAMMPS keeps the coefficients? (stage 2 as stage 1)\n"
     + BASEH(HK) + TWO4 + "run 100\npair_style granular\npair_coeff 1 1 hooke 9000 3000 " + K + "\nrun 100\n", g=1)
deck("p17_restyle_gran_hooke", "# pair granular for run 1, pair gran/hooke/history for run 2 (a new style: all coefficients new)\n"
     + BASEH(HK) + TWO4 + "run 100\npair_style gran/hooke/history 4000 NULL 50 NULL 0.5 0\npair_coeff * *\nrun 100\n", g=1)
deck("p18_hertzmaterial_nu_half", "# hertz/material with nu = 0.5 (E* = 2E/3), viscoelastic\n"
     + BASEH(f"hertz/material 1e7 1.4e7 0.5 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p19_full_submodels", "# hertz/material tsuji with mindlin tangential, sds rolling, marshall twisting (none act head-on)\n"
     + head() + "pair_style granular\npair_coeff * * hertz/material 1e7 0.7 0.3 damping tsuji tangential mindlin NULL 1.0 0.4 "
     "rolling sds 1e4 1.0 0.1 twisting marshall\n" + GRAV
     + "fix floor all wall/gran granular hertz/material 1e7 0.7 0.3 damping tsuji tangential mindlin NULL 1.0 0.4 zplane 0 NULL\n"
     + TAIL + TWO + "run 100\n", g="0.1 1")
deck("p20_coeff_per_pair_then_star", "# 1 2 hertz, then * 1 (sets 1 1 only in LAMMPS' range rule: i over *, j from max(1,i)) hooke; 2 2 never set -> LAMMPS mixes? \n"
     + head() + "pair_style granular\n" + f"pair_coeff 2 2 {HK}\npair_coeff 1 2 hooke 6000 3000 {K}\npair_coeff * 1 hooke 3000 3000 {K}\n"
     + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("p21_hooke_velocity_unlike_mass", "# hooke with damping velocity on unlike masses (eta / m_eff) and a mixed 1 2 from 1 1 and 2 2\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 hooke 2000 0.05 damping velocity {TL}\npair_coeff 2 2 hooke 8000 0.2 damping velocity {TL}\n"
     + GRAV + TAIL + TWO.replace("0.006 density 2500", "0.006 density 7800") + "run 100\n", g=1)
deck("p22_mix_hertzmaterial_coeffrest_limit", "# 1 1 and 2 2 hertz/material coeff_restitution (e 0.4, 0.9) with limit_damping on both, E unlike\n"
     + head() + "pair_style granular\n"
     + f"pair_coeff 1 1 hertz/material 1e7 0.4 0.3 damping coeff_restitution {TL} limit_damping\n"
     + f"pair_coeff 2 2 hertz/material 9e7 0.9 0.25 damping coeff_restitution {TL} limit_damping\n" + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("p23_gran_hooke_point_mass_type", "# gran/hooke with one type of point particles (diameter 0)? no: two sizes and gamma_n 0 (elastic)\n"
     + head() + "pair_style gran/hooke 2000 NULL 0 NULL 0.5 0\npair_coeff * *\n" + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p24_mdr_normal", "# normal mdr (LAMMPS 2025's Zunker-Kamrin model): not mapped -> refused?\n"
     + head().replace("comm_modify", "newton off\ncomm_modify") + "pair_style granular\npair_coeff * * mdr 5e6 0.4 1.9e5 2 0.5 0.5 damping mdr 1 tangential linear_nohistory 1 0.3\n"
     + GRAV + TAIL + TWO + "run 100\n", g=1)
deck("p25_pair_coeff_labels_star_range", "# labels mixed with a numeric star range: pair_coeff big * (1 1 and 1 2), and 2 2 untouched from * *\n"
     + head() + "labelmap atom 1 big 2 small\npair_style granular\npair_coeff * * " + HK + "\n"
     + f"pair_coeff big * hooke 7000 3000 {K}\n" + GRAV + FLOOR + TAIL
     + "create_atoms big single 0.02 0.02 0.01\ncreate_atoms small single 0.01 0.01 0.01\nset type big diameter 0.006 density 2500\nset type small diameter 0.004 density 2500\nrun 100\n", g=1)

# ================================================================ LAMMPS: sizes and masses
deck("s01_pour_density_range", "# fix pour of type 1, diam one 0.004, dens 1500 3500 (masses vary at one size): hooke mass-dependent law\n"
     + head(2, box="0 0.04 0 0.04 0 0.1") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 10 1 4767548 region slab diam one 0.004 dens 1500 3500\n"
     + "create_atoms 2 single 0.01 0.01 0.01\nset type 2 diameter 0.006 density 2500\nrun 2000\n", g=1)
deck("s02_pour_diam_poly", "# fix pour diam poly 2 0.003 0.3 0.005 0.7 of type 1, hertz/material viscoelastic (size-dependent)\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 10 1 4767548 region slab diam poly 2 0.003 0.3 0.005 0.7 dens 2500 2500\nrun 2000\n", g="0.1 1")
deck("s03_deposit_default_size", "# fix deposit of type 2 in lj units: deposited atoms get LAMMPS' defaults (diameter 1, density 1); type 1 set to diameter 2 density 3\n"
     + head(box="0 20 0 20 0 40", units="lj") + "pair_style granular\npair_coeff * * hooke 2e4 30 " + K + "\n"
     + "fix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e4 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 10 10 2\nset type 1 diameter 2 density 3\nregion top block 2 18 2 18 20 30 units box\n"
     + "fix dep all deposit 5 2 100 12345 region top vz -1 -1 units box\nrun 1000\n", g="1 10")
deck("s04_deposit_mol_template", "# fix deposit of a one-atom molecule template with Diameters and Masses sections\n"
     + head(box="0 0.04 0 0.04 0 0.1") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n"
     + "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix dep all deposit 5 0 200 12345 region top mol ball vz -1 -1 units box\nrun 2000\n",
     g=1, data={"ball.mol": "# one sphere of type 2\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0005\n"})
deck("s05_create_random_then_set_then_more", "# create_atoms random 5 of type 1, set type 1 diameter/density, then 3 more random of type 1 (LAMMPS' defaults: 1 m, density 1)\n"
     + head(box="-2 2 -2 2 0 4", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n" + TAIL
     + "region ins block -0.5 0.5 -0.5 0.5 0.5 3.5 units box\ncreate_atoms 1 random 5 4567 ins overlap 0.01\nset type 1 diameter 0.004 density 2500\n"
     + "create_atoms 1 random 3 7654 ins overlap 1.0\nrun 100\n", g=1)
deck("s06_set_mass_after_diameter", "# set type 2 mass 0.001 after its diameter and density: the mass is what it says\n"
     + BASEH(HK) + TWO + "set type 2 mass 0.001\nrun 100\n", g=1)
deck("s07_set_diameter_atom_variable", "# set type 1 diameter v_d with an atom-style random diameter: several sizes in one type, hertz/material\n"
     + BASEH(HM) + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\n"
     + "variable d atom 0.003+0.003*(id-1)/2\nset type 1 diameter v_d\nset type 1 density 2500\nrun 100\n", g="0.1 1")
deck("s08_set_type_fraction", "# 6 atoms of type 1 (two sizes by id), then set type/fraction 1 2 0.5: type 2 inherits both sizes\n"
     + BASEH(HM) + "".join(f"create_atoms 1 single {0.005+0.005*i} 0.02 0.01\n" for i in range(6))
     + "set type 1 density 2500\ngroup small id 1:3\ngroup large id 4:6\nset group small diameter 0.003\nset group large diameter 0.005\n"
     + "set type 1 type/fraction 2 0.5 12345\nrun 100\n", g="0.1 1")
deck("s09_read_data_velocities", "# read_data with per-atom diameter and density and a Velocities section, two sizes in type 1\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data spheres.data\n"
     + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL + "run 100\n", g="0.1 1",
     data={"spheres.data": "spheres\n\n3 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
           "1 1 0.004 2500 0.01 0.01 0.01\n2 1 0.006 2500 0.02 0.02 0.01\n3 2 0.005 7800 0.03 0.03 0.01\n\nVelocities\n\n"
           "1 0 0 -0.5 0 0 0\n2 0 0 -0.2 0 0 0\n3 0 0 0 0 0 0\n"})
deck("s10_delete_type2_between_runs", "# run 1 with types 1 and 2; delete_atoms group t2; run 2: 1 2 cannot happen in stage 2\n"
     + BASEH(HK) + TWO + "run 100\ngroup t2 type 2\ndelete_atoms group t2\nrun 100\n", g=1)
deck("s11_create_mol_template", "# create_atoms single with a molecule template of two spheres with Diameters and Masses (not rigid: each is free)\n"
     + head(box="0 0.04 0 0.04 0 0.1", style="sphere 1") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule pair2 two.mol\ncreate_atoms 0 single 0.02 0.02 0.02 mol pair2 4567\nrun 100\n", g=1,
     data={"two.mol": "# two spheres\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0.01 0 0\n\nTypes\n\n1 1\n2 2\n\nDiameters\n\n1 0.004\n2 0.006\n\nMasses\n\n1 0.00008\n2 0.0004\n"})
deck("s12_pour_2d", "# 2d: fix pour of discs (diam one 0.004, dens 2500): the mass LAMMPS gives a poured 2d particle\n"
     + head(box="0 0.04 0 0.1 -0.001 0.001", bnd="p f p", dim=2) + f"pair_style granular\npair_coeff * * {HK}\n"
     + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-5\n"
     + "region slab block 0.005 0.035 0.05 0.09 -0.001 0.001 units box\nfix p all pour 10 1 4767548 region slab diam one 0.004 dens 2500 2500\n"
     + "create_atoms 2 single 0.01 0.01 0\nset type 2 diameter 0.006 density 2500\nrun 2000\n", g=1)
deck("s13_deposit_2d_set_after", "# 2d: create_atoms of type 2, set density/disc, a deposit of type 1 with a one-atom template of given diameter and no mass\n"
     + head(box="0 0.04 0 0.1 -0.001 0.001", bnd="p f p", dim=2) + f"pair_style granular\npair_coeff * * {HK}\n"
     + "fix grav all gravity 9.81 vector 0 -1 0\nfix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 2 single 0.01 0.01 0\nset type 2 diameter 0.006 density/disc 2500\nmolecule b b.mol\n"
     + "region top block 0.005 0.035 0.05 0.09 -0.001 0.001 units box\nfix dep all deposit 4 0 200 12345 region top mol b vy -1 -1 units box\nrun 2000\n",
     g=1, data={"b.mol": "# one disc of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.004\n"})
deck("s14_pour_dens_range_walls_only_type", "# type 3 has no particles (walls only); pour of type 1 and 2 from two pours, dens ranges, hooke\n"
     + head(3) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p1 all pour 6 1 4767548 region slab diam range 0.003 0.005 dens 2500 2500\n"
     + "fix p2 all pour 6 2 4767550 region slab diam one 0.004 dens 7000 8000\nrun 2000\n", g=1)
deck("s15_set_group_region", "# set region sizes: atoms of type 1 in a region get 6 mm; the rest 4 mm (several sizes in one type)\n"
     + BASEH(HM) + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.02 0.01 0.01\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\nregion right block 0.025 0.04 0 0.04 0 0.1 units box\nset region right diameter 0.006\nrun 100\n", g="0.1 1")

# ================================================================ LAMMPS: units and atom styles
deck("u01_units_micro", "# units micro (um, pg, us): hooke kn in pN/um, spheres of 4 um, density 2.5 pg/um^3\n"
     + head(box="0 40 0 40 0 100", units="micro") + f"pair_style granular\npair_coeff * * hooke 2000 2.8 damping mass_velocity {TL}\n"
     + "fix integ all nve/sphere\ntimestep 1e-3\ncreate_atoms 1 single 20 20 10\ncreate_atoms 2 single 10 10 10\nset type 1 diameter 4 density 2.5\nset type 2 diameter 6 density 2.5\nrun 100\n", g="0.1 1")
deck("u02_units_nano_hertzmaterial", "# units nano: hertz/material with E in attogram/(nm ns^2), viscoelastic\n"
     + head(box="0 400 0 400 0 1000", units="nano") + "pair_style granular\npair_coeff * * hertz/material 1e4 0.05 0.3 damping viscoelastic " + TL + "\n"
     + "fix integ all nve/sphere\ntimestep 1e-2\ncreate_atoms 1 single 200 200 100\ncreate_atoms 2 single 100 100 100\nset type 1 diameter 40 density 2.5\nset type 2 diameter 60 density 2.5\nrun 100\n", g="0.1 1")
deck("u03_units_metal_granular", "# units metal with pair granular hooke (eV/A; mass g/mol; ps): LAMMPS' force-to-acceleration factor applies\n"
     + head(box="0 100 0 100 0 200", units="metal") + "pair_style granular\npair_coeff * * hooke 20 0.003 damping mass_velocity " + TL + "\n"
     + "fix integ all nve/sphere\ntimestep 0.0005\ncreate_atoms 1 single 50 50 20\ncreate_atoms 2 single 20 20 20\nset type 1 diameter 4 density 2\nset type 2 diameter 6 density 2\nrun 100\n", g="1 10")
deck("u04_units_real_hertzmaterial", "# units real with hertz/material (E in atm) viscoelastic: pressure and force conversions\n"
     + head(box="0 100 0 100 0 200", units="real") + "pair_style granular\npair_coeff * * hertz/material 1e5 500 0.3 damping viscoelastic " + TL + "\n"
     + "fix integ all nve/sphere\ntimestep 1.0\ncreate_atoms 1 single 50 50 20\ncreate_atoms 2 single 20 20 20\nset type 1 diameter 4 density 2\nset type 2 diameter 6 density 2\nrun 100\n", g="0.001 0.01")
deck("u05_hybrid_sphere_dipole", "# atom_style hybrid sphere dipole (extra per-atom fields), hertz/material\n"
     + head(style="hybrid sphere dipole") + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM)
     + "fix integ all nve/sphere update dipole\ntimestep 1e-5\n" + TWO + "set type 1 dipole 0 0 0\nrun 100\n", g="0.1 1")
deck("u06_hybrid_sphere_charge_coul", "# atom_style hybrid sphere charge with charges and hybrid/overlay granular coul/cut: Coulomb adds a force\n"
     + head(style="hybrid sphere charge") + "pair_style hybrid/overlay granular coul/cut 0.02\n"
     + f"pair_coeff * * granular {HK}\npair_coeff * * coul/cut\n" + GRAV + FLOOR + TAIL + TWO4 + "set type 1 charge 1e-9\nset type 2 charge 1e-9\nrun 100\n", g=1)
deck("u07_bpm_sphere_atom_style", "# atom_style bpm/sphere (molecular sphere style) with pair granular, no bonds\n"
     + head(style="bpm/sphere").replace("create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 2")
     + f"pair_style granular\npair_coeff * * {HM}\nbond_style zero\nbond_coeff 1\n" + GRAV + FLOOR.replace(HK, HM) + TAIL + TWO + "run 100\n", g="0.1 1")
deck("u08_2d_hertzmaterial_disc", "# 2d granular, hertz/material viscoelastic, set density/disc (pi r^2 rho masses), enforce2d, nve/sphere disc\n"
     + head(box="0 0.04 0 0.1 -0.001 0.001", bnd="p f p", dim=2) + f"pair_style granular\npair_coeff * * {HM}\n"
     + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HM + " yplane 0 NULL\nfix integ all nve/sphere disc\nfix e2 all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.02 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density/disc 5\nset type 2 diameter 0.006 density/disc 5\nrun 100\n", g="0.1 1")
deck("u09_lj_hertzmaterial", "# units lj with hertz/material viscoelastic\n"
     + head(box="0 20 0 20 0 40", units="lj") + "pair_style granular\npair_coeff * * hertz/material 1e5 1 0.3 damping viscoelastic " + TL + "\n"
     + "fix integ all nve/sphere\ntimestep 1e-4\ncreate_atoms 1 single 10 10 5\ncreate_atoms 2 single 5 5 5\nset type 1 diameter 1 density 1\nset type 2 diameter 1.5 density 2\nrun 100\n", g="0.1 1")
deck("u10_cgs_gran_hertz_history", "# units cgs, pair gran/hertz/history (Kn in dyne/cm^2)\n"
     + head(box="0 4 0 4 0 10", units="cgs") + "pair_style gran/hertz/history 2e8 NULL 5000 NULL 0.5 0\npair_coeff * *\n"
     + "fix integ all nve/sphere\ntimestep 1e-6\ncreate_atoms 1 single 2 2 1\ncreate_atoms 2 single 1 1 1\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 2.5\nrun 100\n", g="10 100")

# ================================================================ LAMMPS: walls
deck("w01_xplane_lo_hi", "# fix wall/gran xplane with both lo and hi walls, hertz/material viscoelastic\n"
     + head(bnd="f p f") + f"pair_style granular\npair_coeff * * {HM}\n" + f"fix xw all wall/gran granular {HM} xplane 0 0.04\n" + TAIL + TWO + "run 100\n", g="0.1 1")
deck("w02_region_sphere_inside", "# fix wall/gran/region on a sphere region, spheres inside (a concave wall), hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 -0.03 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region ball sphere 0 0 0 0.02 side in units box\n" + f"fix bw all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w03_region_sphere_outside", "# fix wall/gran/region on a sphere region of radius 5 mm, spheres outside (a convex obstacle), hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 -0.03 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region ball sphere 0 0 0 0.005 side out units box\n" + f"fix bw all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0.015\ncreate_atoms 2 single 0.015 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w04_region_cylinder_pillar", "# fix wall/gran/region on a z-cylinder region of radius 3 mm, side out (a pillar), hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 0 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region pil cylinder z 0 0 0.003 0 0.03 side out units box\n" + f"fix pw all wall/gran/region granular {HM} region pil\n" + TAIL
     + "create_atoms 1 single 0.01 0 0.01\ncreate_atoms 2 single -0.01 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w05_region_cone", "# fix wall/gran/region on a cone region (a hopper), side in, hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 0 0.06", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region hop cone z 0 0 0.005 0.025 0 0.05 side in units box\n" + f"fix hw all wall/gran/region granular {HM} region hop\n" + TAIL
     + "create_atoms 1 single 0 0 0.03\ncreate_atoms 2 single 0.005 0 0.04\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w06_region_rotating_drum", "# a rotating drum: region cylinder y rotating (rotate v_theta), wall/gran/region on it\n"
     + head(box="-0.03 0.03 0 0.02 -0.03 0.03", bnd="f p f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "variable theta equal 2*PI*elapsed*dt/0.5\nregion drum cylinder y 0 0 0.025 0 0.02 side in rotate v_theta 0 0 0 0 1 0 units box\n"
     + f"fix dw all wall/gran/region granular {HM} region drum\n" + GRAV.replace("0 0 -1", "0 0 -1") + TAIL
     + "create_atoms 1 single 0 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w07_region_union_box_sphere", "# a region union (block floor + sphere bump) as a wall/gran/region, hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 0 0.06", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region b1 block -0.03 0.03 -0.03 0.03 -1 0.002 side in units box\nregion s1 sphere 0 0 0.002 0.006 units box\nregion un union 2 b1 s1 side out\n"
     + f"fix uw all wall/gran/region granular {HM} region un\n" + GRAV + TAIL
     + "create_atoms 1 single 0.015 0 0.01\ncreate_atoms 2 single 0 0 0.02\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w08_wall_hertz_history_pair_granular", "# pair granular hooke, floor fix wall/gran hertz/history (the old style) of other stiffness and damping\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + "fix floor all wall/gran hertz/history 1e6 NULL 2000 NULL 0.5 0 zplane 0 NULL\n"
     + TAIL + TWO + "run 100\n", g="0.1 1")
deck("w09_wall_tsuji_limit_temperature", "# wall/gran granular hertz/material tsuji limit_damping with the heat sub-model and temperature keyword (atom_style sphere + temperature)\n"
     + head() + "fix prop all property/atom temperature heatflow\npair_style granular\npair_coeff * * hertz/material 1e7 0.6 0.3 damping tsuji " + TL + " heat area 1.0\n"
     + "fix floor all wall/gran granular hertz/material 1e7 0.6 0.3 damping tsuji " + TL + " limit_damping heat area 1.0 zplane 0 NULL temperature 300\n"
     + GRAV + "fix integ all nve/sphere\nfix ht all heat/flow constant 1.0\ntimestep 1e-5\n" + TWO + "set type 1 temperature 400\nset type 2 temperature 300\nrun 100\n", g="0.1 1")
deck("w10_wiggle_tangential", "# a floor wiggling along x (in its own plane): the normal contact unchanged?\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + f"fix floor all wall/gran granular {HK} zplane 0 NULL wiggle x 0.001 0.01\n"
     + TAIL + TWO + "run 100\n", g=1)
deck("w11_region_block_moving_v", "# a block region moving down at constant speed (move NULL NULL v_z) as a lid: a moving wall\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n"
     + "variable z equal -0.2*time\nregion lid block 0 0.04 0 0.04 0.08 0.2 move NULL NULL v_z side out units box\n"
     + f"fix lw all wall/gran/region granular {HM} region lid\n" + FLOOR.replace(HK, HM) + TAIL + TWO + "run 100\n", g="0.1 1")
deck("w12_region_plane_tilted", "# region plane (a tilted floor) as wall/gran/region, hertz/material\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region ramp plane 0 0 0 0.2 0 1 side in units box\n" + f"fix rw all wall/gran/region granular {HM} region ramp\n" + GRAV + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.02 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w13_zcylinder_hooke_outside_no", "# fix wall/gran zcylinder with hertz (k_n) viscoelastic? no: hertz mass_velocity, spheres inside\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + "pair_style granular\npair_coeff * * hertz 1e6 30 " + K + "\n"
     + "fix cyl all wall/gran granular hertz 1e6 30 " + K + " zcylinder 0.015\n" + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.006 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w14_region_prism_triclinic", "# a prism region as wall/gran/region in an orthogonal box: its faces are flat\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "region pr prism -0.04 0.04 -0.04 0.04 -0.04 0.04 0.01 0 0 side in units box\n" + f"fix pw all wall/gran/region granular {HM} region pr\n" + TAIL
     + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.02 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("w15_region_sphere_open_radius_var", "# a sphere region whose radius is an equal-style variable (v_r, constant 0.02), side in\n"
     + head(box="-0.03 0.03 -0.03 0.03 -0.03 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "variable r equal 0.02\nregion ball sphere 0 0 0 v_r side in units box\n" + f"fix bw all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")

# ================================================================ LAMMPS: kinematics, partners, time
deck("k01_rigid_small_dimers_both_types", "# dimers of like spheres in both types, each held by fix rigid/small molecule: the contact uses the body mass\n"
     + head(style="hybrid sphere molecular") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + "timestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.024 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.014 0.01 0.01\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\nset atom 1*2 mol 1\nset atom 3*4 mol 2\nneigh_modify exclude molecule/intra all\nfix rb all rigid/small molecule\ncompute_modify thermo_temp extra/dof 0\nrun 100\n", g=1)
deck("k02_freeze_partner_holding_velocity", "# type 2 under fix freeze and not integrated, holding a velocity (0 0 0.3) from velocity set\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nvelocity t2 set 0 0 0.3\nfix fr t2 freeze\nfix integ t1 nve/sphere\ntimestep 1e-5\nrun 100\n", g=1)
deck("k03_setforce_partner_moving", "# type 2 integrated with fix setforce 0 0 0: it keeps its velocity (0 0 -0.5) and never slows\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t2 type 2\nvelocity t2 set 0 0 -0.5\nfix sf t2 setforce 0 0 0\n" + TAIL + "run 100\n", g=1)
deck("k04_move_rotate_partner", "# type 2 moved by fix move rotate about a z axis (circles at 0.2 m/s)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix integ t1 nve/sphere\nfix mv t2 move rotate 0.02 0.02 0.01 0 0 1 0.3\ntimestep 1e-5\nrun 100\n", g=1)
deck("k05_timestep_change_between_runs", "# run 1 at dt 1e-5, then timestep 1e-4 and run 2 (3.x steps per contact at g 1)\n"
     + BASEH(HM) + TWO + "run 100\ntimestep 1e-4\nrun 100\n", g="0.1 1")
deck("k06_run_upto_start_stop_pre_post", "# run 100; run 300 upto; run 100 start 0 stop 1000 pre no post no; timestep 2e-5 between\n"
     + BASEH(HK) + TWO4 + "run 100\nrun 300 upto\ntimestep 2e-5\nrun 100 start 0 stop 1000 pre no post no\n", g=1)
deck("k07_velocity_dist_loop_rot", "# velocity all create with dist gaussian loop geom rot yes mom yes sum yes: all integrated, nothing held\n"
     + BASEH(HK) + TWO4 + "velocity all create 1e-20 4928459 dist gaussian loop geom rot yes mom yes\nvelocity all set 0 0 -0.1 sum yes\nrun 100\n", g=1)
deck("k08_viscous_sphere_only", "# fix viscous/sphere (damps rotation only): the head-on eps unchanged\n"
     + BASEH(HK) + TWO4 + "fix vs all viscous/sphere 0.001\nrun 100\n", g=1)
deck("k09_nve_point_integrator_type2", "# type 2 integrated by fix nve (translation only), type 1 by nve/sphere: both free for a head-on contact\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nfix i1 t1 nve/sphere\nfix i2 t2 nve\ntimestep 1e-5\nrun 100\n", g=1)
deck("k10_once_yes_short_runs_loop", "# neigh_modify once yes with run 10 in a 100-pass loop (lists rebuilt every 10 steps: bound skin/(10 dt))\n"
     + BASEH(HK) + TWO4 + "neighbor 1e-4 bin\nneigh_modify once yes\nvariable i loop 100\nlabel l\nrun 10\nnext i\njump SELF l\n", g="0.5 2")
deck("k11_freeze_partner_integrated_moving", "# type 2 under fix freeze and nve/sphere, with velocity 0 0 0.3: it moves at constant speed (force zeroed)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + FLOOR + TWO4
     + "group t2 type 2\nvelocity t2 set 0 0 0.3\nfix fr t2 freeze\n" + TAIL + "run 100\n", g=1)
deck("k12_rigid_small_dimers", "# dimers of two spheres each held by fix rigid/small molecule: the contact uses the body mass\n"
     + head(style="hybrid sphere molecular") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + "timestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.024 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\nset atom 1 mol 1\nset atom 2 mol 1\nset atom 3 mol 2\nneigh_modify exclude molecule/intra all\ngroup t1 type 1\ngroup t2 type 2\nfix rb t1 rigid/small molecule\nfix i2 t2 nve/sphere\nrun 100\n", g=1)
deck("k13_move_variable_partner", "# type 2 moved by fix move variable with a constant velocity -0.2 along z (NULL displacements, v given)\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nvariable vz equal -0.2\nvariable dz equal -0.2*time\nfix integ t1 nve/sphere\nfix mv t2 move variable NULL NULL v_dz NULL NULL v_vz\ntimestep 1e-5\nrun 100\n", g=1)
deck("k14_langevin_zero_damp_huge", "# fix langevin at T 0 with damp 1e9 (a relaxation time far longer than the run): almost no effect\n"
     + BASEH(HK) + TWO4 + "fix lv all langevin 0 0 1e9 48279\nrun 100\n", g=1)
deck("k15_addforce_on_type2_energy", "# fix addforce on type 2 only (a constant force along z)\n"
     + BASEH(HK) + TWO4 + "group t2 type 2\nfix af t2 addforce 0 0 -0.01\nrun 100\n", g=1)
deck("k16_deform_remap_v", "# fix deform of a periodic x with remap v (a shearing box): no effect on a head-on contact\n"
     + BASEH(HK) + TWO4 + "fix df all deform 1 x scale 1.1 remap v\nrun 100\nunfix df\nchange_box all x scale 0.9 remap\ndisplace_atoms all move 0 0 0.001 units box\nrun 100\n", g=1)
deck("k17_velocity_on_moved_partner", "# type 2 held by fix move linear 0 0 0 after velocity t2 set 0.3 0.3 0.3: fix move sets v every step\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "group t1 type 1\ngroup t2 type 2\nvelocity t2 set 0.3 0.3 0.3\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 0\ntimestep 1e-5\nrun 100\n", g=1)
deck("k18_respa_granular", "# run_style respa 2 2 with pair granular: the dt -> 0 value, and steps per contact?\n"
     + BASEH(HK) + TWO4 + "run_style respa 2 2 pair 2\nrun 100\n", g=1)
deck("k19_nve_sphere_group_region_partner_fixed_later", "# stage 1 all integrated; stage 2 unfix integ and integrate type 1 only: type 2 still with velocity from stage 1?\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO4
     + "group t1 type 1\nvelocity all set 0 0 -0.3\nrun 100\nunfix integ\nfix integ1 t1 nve/sphere\nrun 100\n", g=1)
deck("k20_momentum_zero", "# fix momentum every 1 linear 1 1 1 (zeroes the total momentum): a contact of two free spheres unchanged\n"
     + BASEH(HK) + TWO4 + "fix mo all momentum 1 linear 1 1 1\nrun 100\n", g=1)


# ================================================================ LIGGGHTS


LB = MAT3 + E3 + HERTZ + WALL3 + ATOMS
PLANE = {"plane0.stl": ("plane", "0", "0.04")}

deck("G01_hertz_unlike_young_poisson", "# LIGGGHTS hertz: Young's moduli 5e6, 5e7, 1e8 and Poisson 0.3, 0.45, 0.25 by type (Y* mixed); e per pair\n"
     + lhead() + "fix m1 all property/global youngsModulus peratomtype 5e6 5e7 1e8\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.45 0.25\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + WALL3 + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G02_hooke_characteristic_velocity", "# LIGGGHTS hooke (kn from Young's modulus and characteristicVelocity 2), e per pair\n"
     + lhead() + MAT3 + E3 + "fix m5 all property/global characteristicVelocity scalar 2.0\npair_style gran model hooke tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G03_hookestiffness_absolute_damping", "# LIGGGHTS hooke/stiffness with absolute_damping on (gamman a force/velocity, not per mass)\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000\n"
     + "fix m5 all property/global gamman_abs peratomtypepair 3 0.3 0.2 0.1 0.2 0.25 0.15 0.1 0.15 0.2\n"
     + "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
     + "fix m8 all property/global gammat_abs peratomtypepair 3 0.05 0.05 0.05 0.05 0.05 0.05 0.05 0.05 0.05\n"
     + "pair_style gran model hooke/stiffness tangential history absolute_damping on\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0 absolute_damping on\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G04_hertzstiffness", "# LIGGGHTS hertz/stiffness (kn, gamman per type pair)\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5\n"
     + "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
     + "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
     + "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
     + "pair_style gran model hertz/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G05_primitive_zcylinder_inside", "# LIGGGHTS primitive zcylinder of radius 0.03 (spheres inside): the curvature LIGGGHTS uses?\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix wcyl all wall/gran model hertz tangential history primitive type 3 zcylinder 0.03 0. 0.\n"
     + ATOMS.replace("0.01 0 0.01", "0.02 0 0.01") + RUN, g="0.1 1", liggghts=True)
deck("G06_primitive_xplane_yplane", "# LIGGGHTS primitive xplane and yplane walls (two fixes) besides the floor\n"
     + lhead() + LB + "fix wx all wall/gran model hertz tangential history primitive type 3 xplane -0.04\n"
     + "fix wy all wall/gran model hertz tangential history primitive type 3 yplane 0.04\n" + RUN, g="0.1 1", liggghts=True)
deck("G07_mesh_scale_mm", "# LIGGGHTS mesh in mm scaled by 0.001 (scale keyword), offset by move\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix cad all mesh/surface file plane_mm.stl type 3 scale 0.001 move 0 0 -0.001\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + ATOMS + RUN, g="0.1 1", files={"plane_mm.stl": ("plane", "1", "40")}, liggghts=True)
deck("G08_mesh_rotate_static", "# LIGGGHTS mesh rotated at load by 10 deg about x (rotate axis 1 0 0 angle 10): a tilted static floor\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix cad all mesh/surface file plane0.stl type 3 rotate axis 1. 0. 0. angle 10.\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + ATOMS + RUN, g="0.1 1", files=PLANE, liggghts=True)
deck("G09_move_mesh_wiggle", "# LIGGGHTS move/mesh wiggle of the floor along z (a shaker): a moving wall\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix cad all mesh/surface file plane0.stl type 3\nfix wm all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
     + "fix shk all move/mesh mesh cad wiggle amplitude 0 0 0.001 period 0.02\n" + ATOMS + RUN, g="0.1 1", files=PLANE, liggghts=True)
deck("G10_insert_stream_two_densities", "# LIGGGHTS insert/stream of type 1 from two templates with other densities (1500, 3500), same radius; hertz\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 1500 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 3500 radius constant 0.002\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
     + "fix ins all mesh/surface file face.stl type 3\n"
     + "fix is all insert/stream seed 32452867 distributiontemplate pdd nparticles 20 massrate 0.1 overlapcheck yes vel constant 0 0 -0.5 insertion_face ins extrude_length 0.02\n"
     + RUN, g="0.1 1", files={"face.stl": ("plane", "0.12", "0.03")}, liggghts=True)
deck("G11_insert_rate_region_three_templates", "# LIGGGHTS insert/rate/region of type 1 from three templates (radii 1.5, 2, 3 mm), hooke/stiffness (mass-dependent)\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
     + "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
     + "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
     + "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
     + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pts3 all particletemplate/sphere 49979687 atom_type 1 density constant 2500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 3 pts1 0.3 pts2 0.3 pts3 0.4\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.05 0.1 units box\n"
     + "fix is all insert/rate/region seed 32452867 distributiontemplate pdd nparticles 30 particlerate 3000 insert_every 100 overlapcheck yes vel constant 0 0 -0.5 region ins\n"
     + RUN, g="0.1 1", liggghts=True)
deck("G12_multisphere_template", "# LIGGGHTS particletemplate/multisphere (two-sphere clumps) with fix multisphere: clumps, not single spheres\n"
     + lhead() + LB.replace(ATOMS, "")
     + "fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 2 ntry 1000000 spheres 0 0 0 0.002 0.002 0 0 0.002 type 1\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\nfix ms all multisphere\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.05 0.1 units box\n"
     + "fix is all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nrun 2000\n", g=1, liggghts=True)
deck("G13_atom_style_sphere", "# LIGGGHTS atom_style sphere (not granular)\n"
     + lhead(style="sphere") + LB + RUN, g="0.1 1", liggghts=True)
deck("G14_e_one_pair", "# LIGGGHTS coefficientRestitution 1.0 for pair 1 1 (LIGGGHTS accepts it) and 0.2 for 2 2\n"
     + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 1.0 0.5 0.7 0.5 0.2 0.45 0.7 0.45 0.8\n"
     + HERTZ + WALL3 + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G15_four_types_wall_type4", "# LIGGGHTS four material types; walls of type 4 with their own Young's modulus; type 3 unused\n"
     + lhead(nt=4) + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6 2e8\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3 0.2\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 4 " + " ".join(["0.5"] * 16) + "\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 4 0.6 0.5 0.5 0.9 0.5 0.4 0.4 0.3 0.5 0.4 0.4 0.3 0.9 0.3 0.3 0.3\n"
     + HERTZ + "fix wprim all wall/gran model hertz tangential history primitive type 4 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G16_units_cgs", "# LIGGGHTS units cgs: Young's modulus in Ba, sizes in cm\n"
     + lhead(units="cgs", box="-5 5 -5 5 -1 15", neigh="neighbor 0.2 bin\nneigh_modify delay 0\n")
     + "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n" + E3 + HERTZ + WALL3
     + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\n"
     + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 2000\n", g="10 100", liggghts=True)
deck("G17_store_force_temperature", "# LIGGGHTS primitive wall with store_force yes and temperature 300 (no heat model): no effect on eps\n"
     + lhead() + MAT3 + E3 + HERTZ + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0 store_force yes\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G18_nve_limit", "# LIGGGHTS fix nve/limit (a speed cap): named?\n"
     + lhead() + LB + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/limit absolute 0.3\nrun 2000\n", g="0.1 1", liggghts=True)
deck("G19_freeze_partner_velocity", "# LIGGGHTS type 2 frozen (fix freeze) holding a velocity 0 0 0.3 given before\n"
     + lhead() + LB + "group t2 type 2\nvelocity t2 set 0 0 0.3 units box\nfix fr t2 freeze\n" + RUN, g=1, liggghts=True)
deck("G20_two_pair_styles_stages", "# LIGGGHTS run 1 with hertz, then pair_style gran model hooke (characteristicVelocity) and run 2\n"
     + lhead() + LB + "fix m5 all property/global characteristicVelocity scalar 2.0\n" + RUN
     + "pair_style gran model hooke tangential history\npair_coeff * *\nrun 1000\n", g="0.1 1", liggghts=True)
deck("G21_lid_primitive_two_walls", "# LIGGGHTS a floor and a lid (zplane 0.1) as two primitive walls of one fix each, other types\n"
     + lhead(nt=4) + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6 5e7\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3 0.3\n"
     + "fix m7 all property/global coefficientFriction peratomtypepair 4 " + " ".join(["0.5"] * 16) + "\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 4 0.6 0.5 0.7 0.3 0.5 0.4 0.45 0.35 0.7 0.45 0.8 0.2 0.3 0.35 0.2 0.5\n"
     + HERTZ + WALL3 + "fix wlid all wall/gran model hertz tangential history primitive type 4 zplane 0.1\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G22_hookestiffness_two_densities_same_type", "# LIGGGHTS hooke/stiffness (mass-dependent) with type 1 from two templates of other density; insert/pack\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
     + "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
     + "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
     + "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
     + "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 1000 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 8000 radius constant 0.002\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.02 0.08 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 20 region ins\n"
     + RUN, g="0.1 1", liggghts=True)
deck("G23_read_data", "# LIGGGHTS read_data with per-atom diameter and density (atom_style granular columns), two sizes in type 1\n"
     + "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\nread_data spheres.data\n"
     + "neighbor 0.002 bin\nneigh_modify delay 0\n" + MAT3 + E3 + HERTZ + WALL3 + RUN, g="0.1 1",
     data={"spheres.data": "spheres\n\n3 atoms\n3 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.01 0.15 zlo zhi\n\nAtoms\n\n"
           "1 1 0.004 2500 0.01 0 0.01\n2 1 0.006 2500 -0.01 0 0.01\n3 2 0.005 1500 0.02 0.02 0.01\n"}, liggghts=True)
deck("G24_mesh_stress_and_plain", "# LIGGGHTS mesh/surface/stress floor (force output) and a plain mesh wall, two meshes in one wall fix\n"
     + lhead() + MAT3 + E3 + HERTZ
     + "fix cad all mesh/surface/stress file plane0.stl type 3\nfix side all mesh/surface file side.stl type 3\n"
     + "fix wm all wall/gran model hertz tangential history mesh n_meshes 2 meshes cad side\n" + ATOMS + RUN, g="0.1 1",
     files={"plane0.stl": ("plane", "0", "0.04"), "side.stl": ("plane", "0.12", "0.04")}, liggghts=True)
deck("G25_wall_model_hooke_pair_hertz", "# LIGGGHTS the wall fix with model hooke (characteristicVelocity) while the pair style is hertz\n"
     + lhead() + MAT3 + E3 + "fix m5 all property/global characteristicVelocity scalar 2.0\n" + HERTZ
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G26_rolling_cdt_tangential_no_history", "# LIGGGHTS hertz tangential no_history rolling_friction cdt (nothing acts head-on)\n"
     + lhead() + MAT3 + E3 + "fix m9 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
     + "pair_style gran model hertz tangential no_history rolling_friction cdt\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz tangential no_history rolling_friction cdt primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G27_set_mass_liggghts", "# LIGGGHTS set type 2 mass after diameter and density (density column then follows?)\n"
     + lhead() + LB + "set type 2 mass 0.0005\n" + RUN, g="0.1 1", liggghts=True)
deck("G28_viscous_liggghts", "# LIGGGHTS fix viscous on all: named with its size?\n"
     + lhead() + LB + "fix visc all viscous 0.0005\n" + RUN, g="0.1 1", liggghts=True)
deck("G29_hooke_limitforce_stage", "# LIGGGHTS hooke with limitForce on (the force clipped at zero: the force rule), characteristicVelocity\n"
     + lhead() + MAT3 + E3 + "fix m5 all property/global characteristicVelocity scalar 2.0\npair_style gran model hooke tangential history limitForce on\npair_coeff * *\n"
     + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0 limitForce on\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G30_periodic_neighbor_across", "# LIGGGHTS periodic x with the two spheres meeting across the boundary (ghost velocities: communicate vel yes)\n"
     + lhead(bnd="p p f") + MAT3 + E3 + HERTZ + WALL3
     + "create_atoms 1 single 0.047 0 0.01 units box\ncreate_atoms 2 single -0.046 0 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
     + RUN, g="0.1 1", liggghts=True)


# ================================================================ batch 2: lattice units, molecule offsets, defaults, LIGGGHTS set semantics
deck("b01_region_sphere_lattice_units", "# lattice sc 0.01, then a sphere region of radius 2 in lattice units (0.02 m) as a concave wall, hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 -0.03 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "lattice sc 0.01\nregion ball sphere 0 0 0 2 side in\n" + f"fix bw all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0 units box\ncreate_atoms 2 single 0.01 0 0 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b02_region_cylinder_lattice_pillar", "# lattice sc 0.001, a z-cylinder pillar of radius 3 lattice units (3 mm), side out, hertz/material\n"
     + head(box="-0.03 0.03 -0.03 0.03 0 0.03", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "lattice sc 0.001\nregion pil cylinder z 0 0 3 0 30 side out\n" + f"fix pw all wall/gran/region granular {HM} region pil\n" + TAIL
     + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b03_create_mol_type_offset", "# create_atoms 1 single ... mol: the template's types are offset by 1 (its type-1 sphere becomes type 2)\n"
     + head(ntypes=3) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.02 mol ball 4567\ncreate_atoms 1 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nrun 100\n", g=1,
     data={"ball.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("b04_deposit_mol_type_offset", "# fix deposit type 1 with a molecule whose sphere is type 1: inserted spheres are type 2 (offset 1), 6 mm, 0.0009 kg\n"
     + head(ntypes=2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n"
     + "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix dep all deposit 5 1 200 12345 region top mol ball vz -1 -1 units box\nrun 2000\n", g=1,
     data={"ball.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("b05_pour_mol_no_rigid", "# fix pour type 0 with a one-sphere molecule template (Diameters, Masses), no rigid: single spheres of type 2\n"
     + head(ntypes=2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n"
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 0 4767548 region slab mol ball\nrun 2000\n", g=1,
     data={"ball.mol": "# one sphere of type 2\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("b06_default_damping_viscoelastic", "# pair_coeff without a damping keyword: LAMMPS' default damping is viscoelastic (eta_n0 3000 read as viscoelastic's)\n"
     + head() + f"pair_style granular\npair_coeff * * hooke 2000 300 {TL}\n" + GRAV
     + f"fix floor all wall/gran granular hertz/material 1e7 1.4e7 0.3 {TL} zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g="0.1 1")
deck("b07_explicit_unlike_models", "# 1 1 hooke, 2 2 hertz/material, 1 2 given explicitly as hertz (no mixing needed): each pair its own model\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 {HK}\npair_coeff 2 2 {HM}\npair_coeff 1 2 hertz 1e6 30 {K}\n"
     + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")
deck("b08_no_comm_vel", "# no comm_modify vel yes: LAMMPS' pair granular needs ghost velocities and stops at the run\n"
     + head().replace("comm_modify vel yes\n", "") + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g=1)
deck("b09_read_restart_shipped", "# read_restart of a restart file shipped beside the deck (made by LAMMPS from make_restart.in): sizes and masses from it\n"
     + "read_restart shipped.restart\n" + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + "run 100\n", g=1,
     data={"make_restart.in": head() + TWO.replace("0.006 density 2500", "0.005 density 6000") + "write_restart shipped.restart\n"})
deck("b10_wall_default_damping_old_style_mix", "# the floor without a damping keyword (viscoelastic by default), hertz/material, spheres hertz/material with damping tsuji\n"
     + head() + f"pair_style granular\npair_coeff * * hertz/material 1e7 0.5 0.3 damping tsuji {TL}\n" + GRAV
     + f"fix floor all wall/gran granular hertz/material 1e7 1.4e7 0.3 {TL} zplane 0 NULL\n" + TAIL + TWO + "run 100\n", g="0.1 1")
deck("b11_region_variable_radius_sphere", "# a sphere region whose radius is v_r = 0.02 + 0.01*step/1000 (grows in the run), side in: a moving wall\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "variable r equal 0.02+0.01*step/1000\nregion ball sphere 0 0 0 v_r side in units box\n" + f"fix bw all wall/gran/region granular {HM} region ball\n" + TAIL
     + "create_atoms 1 single 0 0 0\ncreate_atoms 2 single 0.01 0 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b12_lattice_create_box_region", "# the box region and a block wall region in lattice units (lattice sc 0.001): the wall region's faces are flat; sizes by set\n"
     + "units si\natom_style sphere 1\nboundary f f f\ncomm_modify vel yes\nlattice sc 0.001\nregion box block 0 40 0 40 0 100\ncreate_box 2 box\n"
     + f"pair_style granular\npair_coeff * * {HM}\nregion bx block 0 40 0 40 0 100 side in\nfix bw all wall/gran/region granular {HM} region bx\n" + TAIL
     + "create_atoms 1 single 20 20 10\ncreate_atoms 2 single 10 10 10\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b13_set_diameter_then_create_then_set_density", "# type 1: set diameter 0.004 (1 m spheres' mass kept), then density 2500: LAMMPS' mass is 4/3 pi r^3 2500 at the new radius\n"
     + BASEH(HK) + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004\nset type 1 density 2500\nset type 2 density 2500\nset type 2 diameter 0.004\nrun 100\n", g=1)
deck("b14_molecule_no_diameters", "# create_atoms with a molecule template that has Masses but no Diameters: the spheres' radius is LAMMPS' default\n"
     + head(box="-1 1 -1 1 -1 1", bnd="f f f") + f"pair_style granular\npair_coeff * * {HK}\n" + TAIL
     + "molecule ball ball.mol\ncreate_atoms 0 single 0 0 0 mol ball 4567\ncreate_atoms 1 single 0.5 0.5 0.5\nset type 1 diameter 0.004 density 2500\nrun 100\n", g=1,
     data={"ball.mol": "# one sphere of type 2 without a diameter\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nMasses\n\n1 0.0009\n"})
deck("b15_wall_region_lattice_offset_plane", "# lattice sc 0.01 and a plane region given in lattice units through (0,0,1) (z = 0.01 m), hertz/material\n"
     + head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + "lattice sc 0.01\nregion fl plane 0 0 1 0 0 1 side in\n" + f"fix rw all wall/gran/region granular {HM} region fl\n" + TAIL
     + "create_atoms 1 single 0 0 0.03 units box\ncreate_atoms 2 single 0.02 0 0.03 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")

# ---------------------------------------------------------------- LIGGGHTS batch 2
deck("G31_asymmetric_e_matrix", "# LIGGGHTS coefficientRestitution matrix not symmetric (e12 0.5, e21 0.3): which does LIGGGHTS use?\n"
     + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.3 0.4 0.45 0.7 0.45 0.8\n"
     + HERTZ + WALL3 + ATOMS + RUN, g="0.1 1", liggghts=True)
LST = ("fix m4 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
       "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300\n"
       "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
       "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
       "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
       "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n")
deck("G32_set_density_then_diameter", "# LIGGGHTS hooke/stiffness (mass-dependent): set type 2 density 8000, then set type 2 diameter 0.006 (does the mass follow?)\n"
     + lhead() + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 density 8000\nset type 2 diameter 0.006\n" + RUN, g="0.1 1", liggghts=True)
deck("G33_set_diameter_shrink_later", "# LIGGGHTS hooke/stiffness: set type 2 diameter 0.006 density 1500, later set type 2 diameter 0.003\n"
     + lhead() + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\nset type 2 diameter 0.003\n" + RUN, g="0.1 1", liggghts=True)
deck("G34_set_mass_hookestiffness", "# LIGGGHTS hooke/stiffness: set type 2 mass 0.0005 after its diameter and density\n"
     + lhead() + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\n"
     + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\nset type 2 mass 0.0005\n" + RUN, g="0.1 1", liggghts=True)
deck("G35_create_no_set_defaults", "# LIGGGHTS hooke/stiffness: type 2 created without set (LIGGGHTS' default diameter and density)\n"
     + lhead(box="-2 2 -2 2 -1 3") + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -1 0 1 units box\n"
     + "set type 1 diameter 0.004 density 2500\n" + RUN, g="0.1 1", liggghts=True)
deck("G36_zcylinder_hertzstiffness", "# LIGGGHTS primitive zcylinder radius 0.03 under hertz/stiffness (size-dependent): the curvature LIGGGHTS uses\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5\n"
     + "fix m5 all property/global gamman peratomtypepair 3 30000 30000 30000 30000 30000 30000 30000 30000 30000\n"
     + "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
     + "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
     + "pair_style gran model hertz/stiffness tangential history\npair_coeff * *\n"
     + "fix wcyl all wall/gran model hertz/stiffness tangential history primitive type 3 zcylinder 0.03 0. 0.\n"
     + ATOMS.replace("0.01 0 0.01", "0.02 0 0.01") + RUN, g="0.1 1", liggghts=True)
deck("G37_hertzstiffness_damped", "# LIGGGHTS hertz/stiffness with strong gamman (eps well below 1), on a primitive floor\n"
     + lhead() + MAT3 + "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5\n"
     + "fix m5 all property/global gamman peratomtypepair 3 30000 20000 10000 20000 25000 15000 10000 15000 20000\n"
     + "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
     + "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50\n"
     + "pair_style gran model hertz/stiffness tangential history\npair_coeff * *\n"
     + "fix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN, g="0.1 1", liggghts=True)
deck("G38_hooke_stiffness_tangential_damping_off", "# LIGGGHTS hooke/stiffness with tangential_damping off and absolute_damping off (nothing head-on)\n"
     + lhead() + MAT3 + LST.replace("tangential history\npair_coeff", "tangential history tangential_damping off\npair_coeff") + ATOMS + RUN, g="0.1 1", liggghts=True)


# ================================================================ batch 3: offsets, hybrid instances and scaling, group walls, dynamic groups, LIGGGHTS 2d and two-type distributions
deck("b16_pour_mol_type_offset", "# fix pour type 1 with a one-sphere molecule whose sphere is type 1: inserted spheres are type 2 (offset 1)\n"
     + head(ntypes=2) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n"
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 1 4767548 region slab mol ball\nrun 2000\n", g=1,
     data={"ball.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("b17_hybrid_two_granular_instances", "# pair_style hybrid granular granular (not overlay): 1 1 and 1 2 by instance 1, 2 2 by instance 2\n"
     + head() + "pair_style hybrid granular granular\n"
     + f"pair_coeff 1 1 granular 1 {HK}\npair_coeff 1 2 granular 1 {HK}\npair_coeff 2 2 granular 2 hooke 8000 1000 {K}\n"
     + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("b18_hybrid_scaled_granular", "# pair_style hybrid/scaled 2.0 granular: LAMMPS multiplies the granular force (spring and damping) by 2\n"
     + head() + "pair_style hybrid/scaled 2.0 granular\n" + f"pair_coeff * * granular {HK}\n" + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("b19_wall_on_group", "# the floor acts on type 1 only (fix floor t1 wall/gran): type 2 falls through it\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + TWO + "group t1 type 1\n" + FLOOR.replace("floor all", "floor t1") + TAIL + "run 100\n", g=1)
deck("b20_dynamic_group_integrator", "# the integrator on a dynamic group (atoms inside a region, updated every step): spheres outside do not move\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TWO4
     + "region low block 0 0.04 0 0.04 0 0.05 units box\ngroup low dynamic all region low every 1\nfix integ low nve/sphere\ntimestep 1e-5\nrun 100\n", g=1)
deck("b21_hybrid_scaled_two_granular", "# pair_style hybrid/scaled 0.5 granular 0.5 granular with the same coefficients: the sum is the one contact\n"
     + head() + "pair_style hybrid/scaled 0.5 granular 0.5 granular\n" + f"pair_coeff * * granular 1 {HK}\npair_coeff * * granular 2 {HK}\n" + GRAV + FLOOR + TAIL + TWO4 + "run 100\n", g=1)
deck("G39_wall_on_group", "# LIGGGHTS the primitive floor acts on type 1 only (fix wprim t1 wall/gran)\n"
     + lhead() + MAT3 + E3 + HERTZ + ATOMS + "group t1 type 1\n" + WALL3.replace("wprim all", "wprim t1") + RUN, g="0.1 1", liggghts=True)
deck("G40_2d_liggghts_set_density", "# LIGGGHTS in 2d (dimension 2, enforce2d) with set density and hooke/stiffness (mass-dependent)\n"
     + "dimension 2\n" + lhead(bnd="f f p", box="-0.05 0.05 -0.01 0.15 -0.001 0.001") + MAT3 + LST.replace("primitive type 3 zplane 0.0", "primitive type 3 yplane 0.0")
     + "create_atoms 1 single 0.01 0.01 0 units box\ncreate_atoms 2 single -0.01 0.01 0 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
     + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere\nfix e2 all enforce2d\nrun 2000\n", g="0.1 1", liggghts=True)
deck("G41_distribution_two_types", "# LIGGGHTS insert/pack from templates of type 1 (2 mm) and type 2 (3 mm, density 1500): hooke/stiffness\n"
     + lhead() + MAT3 + LST
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.02 0.08 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 20 region ins\n"
     + RUN, g="0.1 1", liggghts=True)


# ================================================================ batch 4: commands after an insertion run act on atoms the skipped runs never made
POUR2 = ("region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\n"
         "fix p all pour 6 2 4767548 region slab diam one 0.004 dens 2500 2500\n")
deck("b22_set_after_pour_run", "# fix pour of type 2 (4 mm), run, then set type 2 diameter 0.006: LAMMPS changes the poured atoms (radius 3 mm, mass kept)\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2 + "run 2000\nunfix p\nset type 2 diameter 0.006\nrun 1000\n", g="0.1 1")
deck("b23_group_after_pour_run", "# pour of type 2, run, then group mob type 2 and the integrator on it only: in LAMMPS the poured spheres move, type 1 does not\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2
     + "run 2000\nunfix p\nunfix integ\ngroup mob type 2\nfix integ2 mob nve/sphere\nrun 1000\n", g=1)
deck("b24_delete_after_pour_run", "# pour of type 2, run, delete_atoms group of type 2: stage 2 has no type 2; then set type 1 density 5000\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2
     + "run 2000\nunfix p\ngroup t2 type 2\ndelete_atoms group t2\nset type 1 density 5000\nrun 1000\n", g=1)
deck("b25_set_density_after_deposit_run", "# fix deposit of type 2 (LAMMPS' default 1 m spheres, lj units), run, then set type 2 diameter 0.5 density 2\n"
     + head(box="0 20 0 20 0 40", units="lj") + "pair_style granular\npair_coeff * * hooke 2e4 30 " + K + "\n"
     + "fix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e4 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 10 10 2\nset type 1 diameter 2 density 3\nregion top block 2 18 2 18 20 30 units box\n"
     + "fix dep all deposit 5 2 100 12345 region top vz -1 -1 units box\nrun 1000\nunfix dep\nset type 2 diameter 0.5 density 2\nrun 1000\n", g="1 10")
deck("b26_freeze_group_after_pour", "# pour of type 2, run, then group t2 type 2 and fix freeze on it: the poured spheres are frozen in stage 2\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2
     + "run 2000\nunfix p\ngroup t2 type 2\nfix fr t2 freeze\nrun 1000\n", g=1)
deck("G42_set_density_after_insert_run", "# LIGGGHTS insert/pack of type 1 (2 mm, 2500), run, then set type 1 density 8000 (hooke/stiffness): stage 2 masses\n"
     + lhead() + MAT3 + LST
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.02 0.08 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 20 region ins\n"
     + RUN + "unfix ins\nset type 1 density 8000\nrun 1000\n", g="0.1 1", liggghts=True)
deck("G43_group_after_insert_run", "# LIGGGHTS insert/pack of type 2, run, then integrate only group mob type 2 (type 1 static) in run 2\n"
     + lhead() + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + RUN + "unfix ins\nunfix integr\ngroup mob type 2\nfix integr2 mob nve/sphere\nrun 1000\n", g="0.1 1", liggghts=True)


# ================================================================ batch 5: 2025 keywords and models
deck("b27_synchronized_verlet_coarse", "# pair_coeff ... synchronized_verlet (LAMMPS 2025: another velocity-Verlet variant for the force), hooke mass_velocity at dt 5e-5 (about 9 steps per contact)\n"
     + (head() + "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1.0 0.3 synchronized_verlet\n" + GRAV + FLOOR + TAIL).replace("timestep 1e-5", "timestep 5e-5") + TWO4 + "run 100\n", g=1)
deck("b28_plain_verlet_coarse", "# the same deck as b27 without synchronized_verlet (the reference for its time-step claims)\n"
     + BASEH("hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1.0 0.3").replace("timestep 1e-5", "timestep 5e-5") + TWO4 + "run 100\n", g=1)
deck("b30_synchronized_verlet_hertz_fine", "# synchronized_verlet with hertz/material viscoelastic at the usual dt (40+ steps per contact): dt -> 0 eps unchanged?\n"
     + head() + "pair_style granular\npair_coeff * * hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_history 1000 1.0 0.3 synchronized_verlet\n" + GRAV + FLOOR + TAIL + TWO + "run 100\n", g="0.1 1")
deck("b31_mindlin_force_tangential", "# tangential mindlin/force and mindlin_rescale/force and linear_history/static (2025 tangential models; nothing head-on)\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential mindlin/force NULL 1.0 0.4\n"
     + f"pair_coeff 2 2 hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential mindlin/force NULL 1.0 0.4\n"
     + f"pair_coeff 1 2 hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential mindlin_rescale/force NULL 1.0 0.4\n" + GRAV + TAIL + TWO + "run 100\n", g="0.1 1")


# ================================================================ batch 6: values read after runs (LIGGGHTS runs one step long in the audit's pass), property redefinitions, wall motions
deck("G44_e_from_step_after_run", "# LIGGGHTS: after run 2000, e = 0.5 + step/10000 = 0.7 for every pair (a value the run changes), then run 1000\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN
     + "variable e equal 0.5+step/10000\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\nrun 1000\n", g="0.1 1", liggghts=True)
deck("G45_property_redefined_between_runs", "# LIGGGHTS: coefficientRestitution redefined (same fix ID) after run 1: stage 2 has the new e\n"
     + lhead() + LB + RUN
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.8 0.7 0.8 0.85 0.45 0.7 0.45 0.8\nrun 1000\n", g="0.1 1", liggghts=True)
deck("G46_e_from_time_elapsed", "# LIGGGHTS: e from elapsed steps after a run: variable e equal 0.3+elapsed/10000 read in the second run's set-up? (immediate $() after run 1)\n"
     + lhead() + LB + RUN
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 $(0.3+step/10000) 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\nrun 1000\n", g="0.1 1", liggghts=True)
deck("b32_zcylinder_shear_theta", "# fix wall/gran zcylinder with shear theta 0.5 (a turning drum wall: tangential only for a radial contact)\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.015 shear theta 0.5\n" + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.006 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b33_k_from_time_after_run", "# LAMMPS: after run 1000 (time 0.01), the stiffness $(2000+1e5*time) = 3000, then run 100\n"
     + BASEH(HK) + TWO4 + "run 1000\npair_coeff * * hooke $(2000+1e5*time) 3000 " + K + "\nrun 100\n", g=1)
deck("b34_zcylinder_wiggle_axial", "# fix wall/gran zcylinder wiggling along its own axis (z): for a radial contact the wall moves in its plane\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + f"pair_style granular\npair_coeff * * {HM}\n"
     + f"fix cyl all wall/gran granular {HM} zcylinder 0.015 wiggle z 0.001 0.01\n" + TAIL
     + "create_atoms 1 single 0 0 0.05\ncreate_atoms 2 single 0.006 0 0.05\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")


# ================================================================ batch 7: units conversions of the older styles, extreme speeds
deck("u11_real_gran_hertz_history", "# units real with pair gran/hertz/history (Kn in pressure units: LAMMPS divides by nktv2p) and a wall of the same style\n"
     + head(box="0 100 0 100 0 200", units="real") + "pair_style gran/hertz/history 1e6 NULL 20 NULL 0.5 0\npair_coeff * *\n"
     + "fix floor all wall/gran hertz/history 1e6 NULL 20 NULL 0.5 0 zplane 0 NULL\n"
     + "fix integ all nve/sphere\ntimestep 1.0\ncreate_atoms 1 single 50 50 20\ncreate_atoms 2 single 20 20 20\nset type 1 diameter 4 density 2\nset type 2 diameter 6 density 2\nrun 100\n", g="0.001 0.01")
deck("u12_metal_gran_hooke_history", "# units metal with pair gran/hooke/history (Kn in force/distance, gamma_n in 1/time)\n"
     + head(box="0 100 0 100 0 200", units="metal") + "pair_style gran/hooke/history 20 NULL 0.003 NULL 0.5 0\npair_coeff * *\n"
     + "fix integ all nve/sphere\ntimestep 0.0005\ncreate_atoms 1 single 50 50 20\ncreate_atoms 2 single 20 20 20\nset type 1 diameter 4 density 2\nset type 2 diameter 6 density 2\nrun 100\n", g="1 10")
deck("x01_extreme_speeds_hertz", "# hertz/material viscoelastic at speeds from 1e-6 to 1e3 m/s (nearly elastic to heavily damped)\n"
     + BASEH(HM) + TWO + "run 100\n", g="1e-6 1e-3 100 1000")
deck("x02_near_critical_hooke", "# hooke mass_velocity near critical damping (zeta about 0.95 for 1 1): eps tiny but not 0\n"
     + BASEH(f"hooke 2000 13000 {K}") + TWO4 + "run 100\n", g=1)


# ================================================================ batch 8: integrators twice, momentum on a type, jkr at zero cohesion
deck("b35_integrated_twice", "# type 1 integrated twice (fix integ all nve/sphere and fix extra t1 nve/sphere): LAMMPS warns and moves it two steps per step\n"
     + BASEH(HK) + TWO4 + "group t1 type 1\nfix extra t1 nve/sphere\nrun 100\n", g=1)
deck("b36_momentum_on_type_group", "# fix momentum every 1 linear 1 1 1 on group t1 (the type-1 spheres only): their common velocity is zeroed each step\n"
     + BASEH(HK) + TWO4 + "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\ngroup t1 type 1\nfix mo t1 momentum 1 linear 1 1 1\nrun 100\n", g=1)
deck("p27_jkr_zero_cohesion_tsuji", "# normal jkr at surface energy 0 (Hertz's force) with tsuji damping\n"
     + BASEH(f"jkr 1e7 0.6 0.3 0.0 damping tsuji {TL}") + TWO + "run 100\n", g="0.1 1")
deck("p28_jkr_zero_cohesion_viscoelastic", "# normal jkr at surface energy 0 with viscoelastic damping (the contact radius is JKR's)\n"
     + BASEH(f"jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}") + TWO + "run 100\n", g="0.1 1")
deck("b37_nve_and_nve_sphere", "# type 2 integrated by fix nve and by fix nve/sphere (translation twice)\n"
     + BASEH(HK) + TWO4 + "group t2 type 2\nfix extra t2 nve\nrun 100\n", g=1)


# ================================================================ batch 9: several molecule templates in one pour, a large deck's cost
deck("b38_pour_two_mol_templates", "# molecule ID with two files (spheres of type 1 and 2, Diameters and Masses), fix pour type 0 with molfrac 0.5 0.5\n"
     + head(ntypes=3) + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "molecule tmpl a.mol b.mol\ncreate_atoms 3 single 0.02 0.02 0.01\nset type 3 diameter 0.004 density 2500\n"
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 6 0 4767548 region slab mol tmpl molfrac 0.5 0.5\nrun 2000\n", g=1,
     data={"a.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.003\n\nMasses\n\n1 0.00004\n",
           "b.mol": "# one sphere of type 2\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("x03_large_lattice_cost", "# 64 000 spheres on a lattice (create_atoms box), sizes by set: the audit's cost beside LAMMPS' own skip-run pass\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nlattice sc 0.005\nregion box block 0 40 0 40 0 45\ncreate_box 2 box\n"
     + "region fill block 0 40 0 40 1 41\ncreate_atoms 1 region fill\nset type 1 diameter 0.004 density 2500\nset type 1 type/fraction 2 0.5 4567\n"
     + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL + "run 1000\n", g="0.1 1")


# ================================================================ batch 10: a long finite loop, then the production settings
deck("b39_long_finite_loop_then_change", "# a finite loop of 12000 short runs (settling), then the stiffness changes and the production run: LAMMPS ends it\n"
     + BASEH(HK) + TWO4 + "variable i loop 12000\nlabel l\nvariable s equal ${i}*3\nrun 10\nnext i\njump SELF l\n"
     + "pair_coeff * * hooke 9000 3000 " + K + "\nrun 1000\n", g=1)

deck("b40_long_loop_echo_then_change", "# a finite loop of 10000 passes with twelve commands each (as a pouring tutorial's), then the stiffness changes for the production run\n"
     + BASEH(HK) + TWO4 + "variable i loop 10000\nlabel l\n"
     + "".join(f"variable seed{k} equal floor(${{i}}*{34512 + 1000 * k}/10000) # a seed per pass, as the pouring tutorials do\n" for k in range(10))
     + "run 10 # a short run each pass\nnext i\njump SELF l\n"
     + "pair_coeff * * hooke 9000 3000 " + K + "\nrun 1000\n", g=1)

deck("b41_many_types_120", "# 120 atom types (one per size class, as polydisperse decks with neighbor multi do); atoms of types 1, 60 and 120\n"
     + head(ntypes=120) + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 60 single 0.02 0.02 0.01\ncreate_atoms 120 single 0.03 0.03 0.01\n"
     + "set type 1 diameter 0.003 density 2500\nset type 60 diameter 0.004 density 2500\nset type 120 diameter 0.005 density 2500\nrun 100\n", g="0.1 1")

deck("b42_old_hertz_history_zcylinder", "# the older wall style hertz/history on a zcylinder (spheres inside): the curvature it uses\n"
     + head(box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + "pair_style gran/hertz/history 1e6 NULL 2000 NULL 0.5 0\npair_coeff * *\n"
     + "fix cyl all wall/gran hertz/history 1e6 NULL 2000000 NULL 0.5 0 zcylinder 0.015\n" + TAIL
     + "create_atoms 1 single 0 0 0.01\ncreate_atoms 2 single 0.006 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g="0.1 1")
deck("b43_old_hooke_history_wall_limit_damping", "# the older wall style hooke/history with limit_damping (heavy damping: the force rule), pair gran/hooke/history without\n"
     + head() + "pair_style gran/hooke/history 2000 NULL 60000 NULL 0.5 0\npair_coeff * *\n" + GRAV
     + "fix floor all wall/gran hooke/history 2000 NULL 60000 NULL 0.5 0 zplane 0 NULL limit_damping\n" + TAIL + TWO4 + "run 100\n", g=1)

deck("b44_retype_after_pour_run", "# pour of type 2, run, set type 2 type 3 (the poured spheres become type 3, whose pairs have their own stiffness), run\n"
     + head(ntypes=3) + f"pair_style granular\npair_coeff * * {HK}\npair_coeff * 3 hooke 9000 3000 {K}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2 + "run 2000\nunfix p\nset type 2 type 3\nrun 1000\n", g=1)

deck("G47_long_loop_then_change", "# LIGGGHTS: a finite loop of 3000 short runs (settling), then coefficientRestitution changes for the production run\n"
     + lhead() + LB + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
     + "variable i loop 3000\nlabel l\nrun 10\nnext i\njump SELF l\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.8 0.7 0.8 0.85 0.45 0.7 0.45 0.8\nrun 1000\n", g="0.1 1", liggghts=True)

deck("b45_delete_after_deposit_run", "# fix deposit of type 2 (lj, default 1-unit spheres), run, delete_atoms of group type 2: stage 2 has type 1 only\n"
     + head(box="0 20 0 20 0 40", units="lj") + "pair_style granular\npair_coeff * * hooke 2e4 30 " + K + "\n"
     + "fix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e4 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 10 10 2\ncreate_atoms 1 single 5 5 2\nset type 1 diameter 2 density 3\nregion top block 2 18 2 18 20 30 units box\n"
     + "fix dep all deposit 5 2 100 12345 region top vz -1 -1 units box\nrun 1000\nunfix dep\ngroup t2 type 2\ndelete_atoms group t2\n"
     + "pair_coeff 1 1 hooke 4e4 30 " + K + "\nrun 1000\n", g="1 10")
deck("G48_delete_after_insert_run", "# LIGGGHTS insert/pack of type 2, run, delete_atoms of group type 2, then e changes: stage 2 has type 1 only\n"
     + lhead() + MAT3 + E3 + HERTZ + WALL3 + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 1 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.003\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n"
     + RUN + "unfix ins\ngroup t2 type 2\ndelete_atoms group t2\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\nrun 1000\n", g="0.1 1", liggghts=True)

deck("b46_set_group_after_pour_run", "# pour of type 2 (4 mm), run, group t2 type 2, set group t2 diameter 0.006 (LAMMPS: the poured spheres 3 mm, mass kept), run\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2 + "run 2000\nunfix p\ngroup t2 type 2\nset group t2 diameter 0.006\nrun 1000\n", g="0.1 1")
deck("b47_set_region_after_pour_run", "# pour of type 2 (4 mm), run, set region low diameter 0.006 (the poured spheres that have landed), run\n"
     + head() + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2
     + "run 20000\nunfix p\nregion low block 0 0.04 0 0.04 0 0.03 units box\nset region low diameter 0.006\nrun 1000\n", g="0.1 1")
deck("b48_delete_region_after_pour_run", "# pour of type 2, run, delete_atoms region high (those still falling), run: some poured spheres stay\n"
     + head() + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\n" + POUR2
     + "run 3000\nunfix p\nregion high block 0 0.04 0 0.04 0.03 0.1 units box\ndelete_atoms region high\nrun 1000\n", g=1)
deck("b49_set_group_density_after_deposit_run", "# deposit of type 2 (lj default unit spheres), run, group t2 type 2, set group t2 density 5, run: the mass of the deposited spheres\n"
     + head(box="0 20 0 20 0 40", units="lj") + "pair_style granular\npair_coeff * * hooke 2e4 30 " + K + "\n"
     + "fix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e4 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms 1 single 10 10 2\nset type 1 diameter 2 density 3\nregion top block 2 18 2 18 20 30 units box\n"
     + "fix dep all deposit 5 2 100 12345 region top vz -1 -1 units box\nrun 1000\nunfix dep\ngroup t2 type 2\nset group t2 density 5\nrun 1000\n", g="1 10")

deck("b50_two_floors_same_plane", "# two fix wall/gran on the same plane z = 0 (a floor given twice, as an include may do): LAMMPS adds both forces\n"
     + BASEH(HK) + "fix floor2 all wall/gran granular " + HK + " zplane 0 NULL\n" + TWO4 + "run 100\n", g=1)
deck("G49_two_floors_same_plane", "# LIGGGHTS two primitive floors on the same plane z = 0 (two fixes): LIGGGHTS adds both forces\n"
     + lhead() + LB + "fix wprim2 all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n" + RUN, g="0.1 1", liggghts=True)

deck("G50_long_loop_time_budget", "# LIGGGHTS: a finite loop of 15000 short runs, then coefficientRestitution changes for the production run (the audit's time budget)\n"
     + lhead() + LB + "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
     + "variable i loop 15000\nlabel l\nrun 10\nnext i\njump SELF l\n"
     + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.9 0.8 0.7 0.8 0.85 0.45 0.7 0.45 0.8\nrun 1000\n", g="0.1 1", liggghts=True)

deck("b51_pour_type_label", "# type labels; fix pour of type 'small' given by its label (6 mm, density 7800), type 'big' made by create_atoms\n"
     + head() + "labelmap atom 1 big 2 small\n" + f"pair_style granular\npair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL
     + "create_atoms big single 0.02 0.02 0.01\nset type big diameter 0.004 density 2500\n"
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 6 small 4767548 region slab diam one 0.006 dens 7800 7800\nrun 2000\n", g=1)
deck("b52_deposit_type_label", "# type labels; fix deposit of type 'small' by its label (LAMMPS' default 1-unit size, lj)\n"
     + head(box="0 20 0 20 0 40", units="lj") + "labelmap atom 1 big 2 small\npair_style granular\npair_coeff * * hooke 2e4 30 " + K + "\n"
     + "fix grav all gravity 1 vector 0 0 -1\nfix floor all wall/gran granular hooke 2e4 30 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-4\n"
     + "create_atoms big single 10 10 2\nset type big diameter 2 density 3\nregion top block 2 18 2 18 20 30 units box\n"
     + "fix dep all deposit 5 small 100 12345 region top vz -1 -1 units box\nrun 1000\n", g="1 10")

deck("b53_deposit_mol_offset_type_present", "# type 2 spheres of 4 mm made by create_atoms, and fix deposit type 1 of a one-sphere molecule (its type 1, 6 mm, 0.0009 kg): LAMMPS adds 6 mm type-2 spheres\n"
     + head(ntypes=2) + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\n"
     + "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix dep all deposit 5 1 200 12345 region top mol ball vz -1 -1 units box\nrun 2000\n", g="0.1 1",
     data={"ball.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})

deck("b54_pour_mol_offset_type_present", "# as b53 with fix pour instead of deposit: type 2 has 4 mm spheres and the pour's template adds 6 mm 0.0009 kg ones\n"
     + head(ntypes=2) + f"pair_style granular\npair_coeff * * {HM}\n" + GRAV + FLOOR.replace(HK, HM) + TAIL
     + "molecule ball ball.mol\ncreate_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.004 density 2500\n"
     + "region slab block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 1 4767548 region slab mol ball\nrun 2000\n", g="0.1 1",
     data={"ball.mol": "# one sphere of type 1\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0.006\n\nMasses\n\n1 0.0009\n"})
deck("G51_insert_into_type_present", "# LIGGGHTS: type 2 has a 6 mm sphere (density 1500) made by create_atoms; insert/pack adds 3 mm type-2 spheres (density 1500), hooke/stiffness\n"
     + lhead() + MAT3 + LST + "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
     + "fix pts1 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.0015\n"
     + "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
     + "region ins block -0.03 0.03 -0.03 0.03 0.04 0.1 units box\n"
     + "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 10 region ins\n" + RUN, g="0.1 1", liggghts=True)

deck("b55_evaporate_type2", "# fix evaporate removes every type-2 sphere in the box during run 1 (group t2); stage 2 has type 1 only, with a new stiffness\n"
     + BASEH(HK) + TWO + "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\ngroup t2 type 2\nregion everywhere block 0 0.04 0 0.04 0 0.1 units box\n"
     + "fix ev t2 evaporate 1 10 everywhere 4567\nrun 100\nunfix ev\npair_coeff * * hooke 9000 3000 " + K + "\nrun 100\n", g=1)


def write(name):
    text, g, files, data, lig = DECKS[name]
    kit.write_folder(os.path.join(D, name), text, g, liggghts=lig, data=data, stl=files)


if __name__ == "__main__":
    kit.make(DECKS, write, sys.argv[1:])
