"""Field round 23: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker (helpers as round 21).
Prefixes: a* labelmap, r* read_data/read_restart, m* molecule templates, p* pour/deposit ranges, b* box and atom edits,
u* units, d* damping models and older pair styles, n* pairs that cannot meet, w* walls, v* variable styles, R* run forms,
L* LIGGGHTS, e* re-checks of earlier rounds.  Each deck first comment says what it tries. usage: python make_decks23.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import decks as kit  # noqa: E402  (the helpers rounds 21-27 share; round 23 wrote them)
from fieldkit.decks import (ATOMS, BASE, CGS_HK, CGS_HM, DECKS, E3, E3b, FLOOR, G1, GRAV, HERTZ, HK, HM, HOOKE, HS, K, L, LB,  # noqa: E402,F401
                            LRUN, MAT3, MOL, PRB, PTS, RD, RUN, RUN1, TAIL, TL, TWO, WALL3, deck, head, hk, lhead, mass, ubase)

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
kit.D = D


# ==== decks (field round 23): a* labelmap, r* read_data/read_restart, m* molecule templates, p* fix pour/deposit ranges,
# b* replicate/change_box/displace/delete_atoms, u* units, d* damping models and older pair styles, n* exclusions,
# w* walls, v* variable styles, R* run forms/time step, L* LIGGGHTS, e* re-checks of earlier rounds' classes
SPH = lambda d, rho, x=0.02, y=0.02, z=0.01, t=1: f"create_atoms {t} single {x} {y} {z}\n"

def base2(model=HK, nt=2, extra="", units="si", box="0 0.04 0 0.04 0 0.1"):
    return head(nt, box=box, units=units, extra=extra) + G1(model) + GRAV + f"fix floor all wall/gran granular {model} zplane 0 NULL\n" + TAIL

# ---------------------------------------------------------------- a*: labelmap
LM = "labelmap atom 1 small 2 big\n"
deck("a01_labelmap_cross_pair", "# labelmap atom 1 small 2 big; pair_coeff small big hooke 8000: only the 1 2 pair stiffer\n"
     + BASE() + TWO + LM + f"pair_coeff small big {hk(8000)}\n" + RUN1, g=1)
deck("a02_labelmap_create_set", "# create_atoms big single / set type big density 7800 by label\n"
     + BASE() + LM + "create_atoms small single 0.02 0.02 0.01\ncreate_atoms big single 0.01 0.01 0.01\nset type small diameter 0.004 density 2500\nset type big diameter 0.006 density 7800\n" + RUN1, g=1)
deck("a03_labelmap_reversed_order", "# labelmap atom 2 small 1 big (labels not in type order): pair_coeff small small 8000 is type 2 2\n"
     + BASE() + TWO + "labelmap atom 2 small 1 big\n" + f"pair_coeff small small {hk(8000)}\n" + RUN1, g=1)
deck("a04_labelmap_mixed_numeric", "# pair_coeff 1 big (numeric and label): the 1 2 pair\n"
     + BASE() + TWO + LM + f"pair_coeff 1 big {hk(8000)}\n" + RUN1, g=1)
deck("a05_labelmap_group_type", "# group g type big; set group g density 7800\n"
     + BASE() + TWO + LM + "group g type big\nset group g density 7800\n" + RUN1, g=1)
deck("a06_labelmap_clear_redefine", "# labelmap atom 1 x; labelmap clear; labelmap atom 1 y 2 x; pair_coeff x x 8000 -> type 2 2\n"
     + BASE() + TWO + "labelmap atom 1 x\nlabelmap clear\nlabelmap atom 1 y 2 x\n" + f"pair_coeff x x {hk(8000)}\n" + RUN1, g=1)
deck("a07_label2type_variable", "# variable t equal label2type(atom,big); pair_coeff ${t} ${t} 8000 -> 2 2\n"
     + BASE() + TWO + LM + "variable t equal label2type(atom,big)\n" + f"pair_coeff $(v_t:%.0f) $(v_t:%.0f) {hk(8000)}\n" + RUN1, g=1)
deck("a08_labelmap_relabel", "# labelmap atom 1 a 2 b then labelmap atom 1 b 2 a? LAMMPS refuses a label used twice? (engine says)\n"
     + BASE() + TWO + "labelmap atom 1 a 2 b\nlabelmap atom 2 c\n" + f"pair_coeff c c {hk(8000)}\n" + RUN1, g=1)
deck("a09_labelmap_read_data_section", "# read_data with an Atom Type Labels section (1 small, 2 big); pair_coeff big big 8000\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\n" + G1(HK) + GRAV + FLOOR + TAIL
     + f"pair_coeff big big {hk(8000)}\n" + RUN1, g=1,
     data={"d.data": "# two spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 small\n2 big\n\nAtoms # sphere\n\n1 small 0.004 2500 0.02 0.02 0.01\n2 big 0.006 7800 0.01 0.01 0.01\n"})
deck("a10_labelmap_in_data_atoms_swapped", "# data file labels: 1 big 2 small; Atoms use labels; audit must map 'small' to type 2\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\n" + G1(HK) + GRAV + FLOOR + TAIL + RUN1, g=1,
     data={"d.data": "# two spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtom Type Labels\n\n1 big\n2 small\n\nAtoms # sphere\n\n1 small 0.004 2500 0.02 0.02 0.01\n2 big 0.006 7800 0.01 0.01 0.01\n"})
deck("a11_labelmap_set_type_range_labels", "# set type small diameter 0.008 after labelmap with types 1..3; pair_coeff * big\n"
     + base2(nt=3) + TWO + "labelmap atom 1 small 2 big 3 huge\nset type small diameter 0.008\n" + f"pair_coeff * big {hk(8000)}\n" + RUN1, g=1)
deck("a12_labelmap_script_file", "# labelmap atom in an include file (labels.in); pair_coeff big big\n"
     + BASE() + TWO + "include labels.in\n" + f"pair_coeff big big {hk(8000)}\n" + RUN1, g=1, data={"labels.in": LM})
# ---------------------------------------------------------------- r*: read_data / read_restart
DATA2 = "# two spheres\n\n2 atoms\n{nt} atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.02 0.01\n2 2 0.006 7800 0.01 0.01 0.01\n"
deck("r01_read_data_sphere", "# read_data: Atoms # sphere (4 mm rho 2500 type 1, 6 mm rho 7800 type 2)\n" + RD() + RUN1, g=1, data={"d.data": DATA2.format(nt=2)})
deck("r02_read_data_extra_types", "# read_data extra/atom/types 1; create_atoms 3 single; set type 3 diameter 0.008 density 1000\n"
     + RD(kw=" extra/atom/types 1") + "create_atoms 3 single 0.03 0.03 0.01\nset type 3 diameter 0.008 density 1000\n" + RUN1, g=1, data={"d.data": DATA2.format(nt=2)})
deck("r03_read_data_add_append_offset", "# second read_data add append offset 1 0 0 0 0 shift 0 0 0.03: its type 1 atom (8 mm rho 1000) becomes type 2\n"
     + RD(kw=" extra/atom/types 1") + "read_data e.data add append offset 1 0 0 0 0 shift 0 0 0.03\n" + RUN1, g=1,
     data={"d.data": DATA2.format(nt=2), "e.data": "# one\n\n1 atoms\n1 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.008 1000 0.03 0.03 0.01\n"})
deck("r04_read_data_group_kw", "# read_data e.data add append group late; set group late density 7800 (the late atom only)\n"
     + RD() + "read_data e.data add append group late\nset group late density 7800\n" + RUN1, g=1,
     data={"d.data": DATA2.format(nt=2).replace("7800", "2500"), "e.data": "# one\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.008 2500 0.03 0.03 0.05\n"})
deck("r05_read_data_pair_coeffs_section", "# data file with a PairIJ Coeffs section for pair granular (engine says whether it reads it)\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n" + "pair_style granular\nread_data d.data\n" + f"pair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + RUN1, g=1,
     data={"d.data": DATA2.format(nt=2) + "\nPairIJ Coeffs # granular\n\n1 1 hooke 5000 3000\n1 2 hooke 5000 3000\n2 2 hooke 5000 3000\n"})
deck("r06_write_data_read_back", "# write_data then clear + read_data of it (a file the deck writes and reads: refusal expected)\n"
     + BASE() + TWO + "run 10\nwrite_data f23.data\nclear\n" + RD("f23.data") + RUN1, g=1)
deck("r07_read_restart_own", "# write_restart then clear + read_restart (refusal expected)\n"
     + BASE() + TWO + "run 10\nwrite_restart f23.restart\nclear\nread_restart f23.restart\n" + G1(hk(5000)) + GRAV + FLOOR + TAIL + RUN1, g=1)
deck("r08_read_data_type3_absent", "# 3 atom types in the data file, no atom of type 3: pairs with type 3 cannot meet\n"
     + RD() + RUN1, g=1, data={"d.data": DATA2.format(nt=3)})
deck("r09_read_data_comments_image", "# data file with comments, blank lines, image flags, Masses-free sphere style; 3rd atom type 1 8 mm\n"
     + RD() + RUN1, g=1, data={"d.data": "LAMMPS data  # header\n\n3 atoms  # count\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.02 0.01 0 0 0 # small\n2 2 0.006 7800 0.01 0.01 0.01 0 0 0\n3 1 0.008 2500 0.03 0.03 0.02 0 0 0\n"})
deck("r10_read_data_then_replicate", "# read_data then replicate 2 1 1 (same sizes)\n" + RD() + "replicate 2 1 1\n" + RUN1, g=1, data={"d.data": DATA2.format(nt=2)})
deck("r11_read_data_diameter_zero", "# type 2 atom with diameter 0 (a point: density is its mass); pairs with it? (engine says)\n"
     + RD() + RUN1, g=1, data={"d.data": DATA2.format(nt=2).replace("2 2 0.006 7800", "2 2 0.0 0.001")})
deck("r12_read_data_velocities_section", "# data file with a Velocities section (sphere: vx vy vz wx wy wz): no eps effect\n"
     + RD() + RUN1, g=1, data={"d.data": DATA2.format(nt=2) + "\nVelocities\n\n1 0 0 -1 0 0 0\n2 0 0 -1 0 0 0\n"})
deck("r13_read_data_sphere_hybrid_style", "# atom_style hybrid sphere bond? no: atom_style sphere with 'Atoms # sphere' but columns in another order? data file says '# sphere'\n"
     + RD() + RUN1, g=1, data={"d.data": DATA2.format(nt=2).replace("Atoms # sphere", "Atoms")})
deck("r14_read_data_in_include_relative", "# read_data of a file in a subfolder via an include in that subfolder (paths relative to the working dir)\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\ninclude sub/rd.in\n" + G1(HK) + GRAV + FLOOR + TAIL + RUN1, g=1,
     data={"sub/rd.in": "read_data sub/d.data\n", "sub/d.data": DATA2.format(nt=2)})
# ---------------------------------------------------------------- m*: molecule templates
deck("m01_create_atoms_mol", "# molecule m1 (type 2, 6 mm, mass for rho 7800); create_atoms 0 single ... mol m1 1234\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m1 m1.mol\ncreate_atoms 0 single 0.01 0.01 0.01 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": MOL(2, 0.006, mass(0.006, 7800))})
deck("m02_deposit_two_mols", "# fix deposit with two one-sphere templates (type 1 4 mm rho 2500, type 2 6 mm rho 7800) molfrac 0.5 1\n"
     + BASE() + "molecule m1 m1.mol\nmolecule m2 m2.mol\nregion ins block 0.005 0.035 0.005 0.035 0.05 0.08 units box\n"
     + "molecule m12 m1.mol m2.mol\nfix dep all deposit 6 0 20 4711 region ins near 0.01 mol m12 molfrac 0.5 1.0 vz -1 -1\nrun 200\n", g=1,
     data={"m1.mol": MOL(1, 0.004, mass(0.004, 2500)), "m2.mol": MOL(2, 0.006, mass(0.006, 7800))})
deck("m03_pour_mol", "# fix pour with a one-sphere template (type 2, 6 mm, rho 7800)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m2 m2.mol\nregion ins block 0.005 0.035 0.005 0.035 0.05 0.08 units box\n"
     + "fix p all pour 3 0 4711 region ins mol m2\nrun 200\n", g=1, data={"m2.mol": MOL(2, 0.006, mass(0.006, 7800))})
deck("m04_mol_no_masses", "# molecule template without Masses (mass from diameter and density 1? engine says)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m1 m1.mol\ncreate_atoms 0 single 0.01 0.01 0.01 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": "# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n1 0.006\n"})
deck("m05_mol_scale", "# molecule m1 m1.mol scale 2 (6 mm -> 12 mm, mass x8): create_atoms mol\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m1 m1.mol scale 2\ncreate_atoms 0 single 0.01 0.01 0.02 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": MOL(2, 0.006, mass(0.006, 7800))})
deck("m06_mol_toff", "# molecule m1 m1.mol toff 1 (template type 1 -> 2)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m1 m1.mol toff 1\ncreate_atoms 0 single 0.01 0.01 0.02 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": MOL(1, 0.006, mass(0.006, 7800))})
deck("m07_mol_labels", "# molecule file Types by label (big) after labelmap\n"
     + BASE() + LM + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nmolecule m1 m1.mol\ncreate_atoms 0 single 0.01 0.01 0.02 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": MOL("big", 0.006, mass(0.006, 7800))})
# ---------------------------------------------------------------- p*: fix pour / deposit size and density ranges
INS = "region ins block 0.005 0.035 0.005 0.035 0.04 0.09 units box\n"
deck("p01_pour_poly_dens_range", "# fix pour diam poly 2 0.004 0.5 0.006 0.5 dens 2000 3000 (hooke mass_velocity: eps depends on mass)\n"
     + BASE() + INS + "fix p all pour 10 1 4767 region ins diam poly 2 0.004 0.5 0.006 0.5 dens 2000 3000\nrun 200\n", g=1)
deck("p02_pour_range", "# fix pour diam range 0.004 0.008 dens 2500 2500\n"
     + BASE() + INS + "fix p all pour 10 2 4767 region ins diam range 0.004 0.008 dens 2500 2500\nrun 200\n", g=1)
deck("p03_two_pours", "# fix pour type 1 diam one 0.004 dens 2500 2500; fix pour type 2 diam one 0.006 dens 7800 7800\n"
     + BASE() + INS + "region ins2 block 0.005 0.035 0.005 0.035 0.0 0.035 units box\nfix p1 all pour 5 1 4767 region ins diam one 0.004 dens 2500 2500\nfix p2 all pour 5 2 4768 region ins2 diam one 0.006 dens 7800 7800\nrun 200\n", g=1)
deck("p04_deposit_then_set", "# fix deposit type 2 in run 1 (default diameter 1? deposit sets no size), then set type 2 diameter 0.006 density 7800\n"
     + BASE() + TWO + INS + "fix d all deposit 3 2 20 4711 region ins near 0.01 vz -1 -1\nrun 100\nunfix d\nset type 2 diameter 0.006 density 7800\nrun 100\n", g=1)
deck("p05_pour_hertz_poly", "# hertz/material viscoelastic with pour diam poly 3 0.003 0.3 0.005 0.3 0.008 0.4 (eps depends on size and speed)\n"
     + BASE(HM) + INS + "fix p all pour 10 1 4767 region ins diam poly 3 0.003 0.3 0.005 0.3 0.008 0.4 dens 2500 2500\nrun 200\n", g=1)
deck("p06_pour_dens_range_walls", "# pour diam one 0.006 dens 1000 9000: the wall rows' range\n"
     + BASE() + INS + "fix p all pour 10 2 4767 region ins diam one 0.006 dens 1000 9000\nrun 200\n", g=1)
deck("p07_pour_ignore_id", "# fix pour with id next and ignore; unfix p before run 2; set type 1 density 7800 after\n"
     + BASE() + INS + "fix p all pour 5 1 4767 region ins diam one 0.004 dens 2500 2500 id next ignore\nrun 100\nunfix p\nset type 1 density 7800\nrun 100\n", g=1)
# ---------------------------------------------------------------- b*: replicate / change_box / displace / delete_atoms
deck("b01_replicate", "# replicate 2 2 1 of the two-type base\n" + BASE() + TWO + "replicate 2 2 1\n" + RUN1, g=1)
deck("b02_delete_overlap", "# delete_atoms overlap 0.006 all all: type 1 (4 mm) and type 2 (6 mm) 3 mm apart, one deleted (which? engine)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.023 0.02 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ndelete_atoms overlap 0.006 all all\n" + RUN1, g=1)
deck("b03_delete_porosity_region", "# delete_atoms porosity in a region around the only type 2 sphere, fraction 1.0 (engine deletes it?)\n"
     + BASE() + TWO + "region r2 sphere 0.01 0.01 0.01 0.005 units box\ndelete_atoms porosity r2 1.0 482793\n" + RUN1, g=1)
deck("b04_delete_overlap_typed_groups", "# delete_atoms overlap 0.006 g1 g2: deletes from g1 (type 1)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.023 0.02 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup g1 type 1\ngroup g2 type 2\ndelete_atoms overlap 0.006 g1 g2\ncreate_atoms 1 single 0.03 0.03 0.05\nset type 1 diameter 0.008 density 2500\n" + RUN1, g=1)
deck("b05_change_box_remap", "# change_box all x final 0 0.08 remap then set region (left half) density 7800\n"
     + BASE() + TWO + "change_box all x final 0 0.08 remap units box\nregion lft block 0 0.03 INF INF INF INF units box\nset region lft density 7800\n" + RUN1, g=1)
deck("b06_displace_then_region_set", "# displace_atoms all move 0.01 0 0, then set region x>0.025 density 7800 (type 1 now at x 0.03)\n"
     + BASE() + TWO + "displace_atoms all move 0.01 0 0 units box\nregion rt block 0.025 INF INF INF INF INF units box\nset region rt density 7800\n" + RUN1, g=1)
deck("b07_replicate_bbox_then_delete", "# replicate 2 1 1 then delete_atoms region of the second copy's type 2\n"
     + BASE() + TWO + "replicate 2 1 1\nregion far block 0.045 INF INF INF INF INF units box\ngroup far region far\ngroup t2 type 2\ngroup kill intersect far t2\nset group kill diameter 0.009\n" + RUN1, g=1)
deck("b08_delete_atoms_mol", "# delete_atoms random count 1 no all NULL 4711 (one of two spheres deleted: which? engine)\n"
     + BASE() + TWO + "delete_atoms random count 1 no all NULL 4711\n" + RUN1, g=1)
deck("b09_displace_rotate", "# displace_atoms all rotate about z (90 deg about 0.02 0.02): type 2 moves to x 0.03 y 0.01; set region\n"
     + BASE() + TWO + "displace_atoms all rotate 0.02 0.02 0 0 0 1 90 units box\nregion rt block 0.025 INF INF INF INF INF units box\nset region rt density 7800\n" + RUN1, g=1)
# ---------------------------------------------------------------- u*: units
deck("u01_cgs_hooke", "# units cgs: hooke kn 2e6 dyne/cm, gamma 3000 1/s, 0.4/0.6 cm rho 2.5 g/cm3 (= the si base)\n"
     + ubase("cgs", CGS_HK, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\n" + RUN1, g=1)
deck("u02_cgs_hertz_material", "# units cgs: hertz/material E 1e8 dyne/cm2 (1e7 Pa), viscoelastic: eps depends on speed: is g taken in m/s or cm/s?\n"
     + ubase("cgs", CGS_HM, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\n" + RUN1, g=1)
deck("u03_si_hertz_material_ref", "# units si twin of u02 (E 1e7 Pa, 4/6 mm, 2500)\n"
     + ubase("si", HM, "0 0.04 0 0.04 0 0.1", (0.004, 0.006, 2500, 2500)) + "timestep 1e-5\n" + RUN1, g=1)
deck("u04_lj_hooke", "# units lj: hooke kn 2000 gamma 3 mass_velocity, d 1 / 1.5, density 1\n"
     + ubase("lj", "hooke 2000 3 " + K, "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "timestep 1e-4\n" + RUN1, g=1)
deck("u05_micro_hertz", "# units micro (um, pg, us: velocity um/us = m/s): hertz/material E 1e7 Pa = 1e4 pg/(um us^2), eta_n0 1.4e-5, 4/6 um? sizes 40/60 um rho 2.5e-6 pg/um3\n"
     + ubase("micro", "hertz/material 1e4 1.4e-5 0.3 damping viscoelastic " + TL, "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\n" + RUN1, g=1)
deck("u06_metal_hooke", "# units metal with granular (velocity A/ps = 100 m/s): hooke kn 2000 (eV/A2), gamma 3 (1/ps), 4/6 A, density 2.5 g/cm3\n"
     + ubase("metal", "hooke 2000 3 " + K, "0 40 0 40 0 100", (4, 6, 2.5, 2.5)) + "timestep 1e-4\n" + RUN1, g=1)
deck("u07_cgs_hertz_wall_gravity", "# units cgs hertz/material with gravity 981 cm/s2\n"
     + ubase("cgs", CGS_HM, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "fix grav all gravity 981 vector 0 0 -1\ntimestep 1e-5\n" + RUN1, g=1)
deck("u08_real_hooke", "# units real with granular (A/fs = 1e5 m/s): hooke\n"
     + ubase("real", "hooke 2000 0.003 " + K, "0 40 0 40 0 100", (4, 6, 2.5, 2.5)) + "timestep 0.1\n" + RUN1, g=1)
# ---------------------------------------------------------------- d*: damping models and older pair styles
dd = lambda name, comment, model, g=1, extra="": deck(name, "# " + comment + "\n" + BASE(model) + TWO + extra + RUN1, g=g)
dd("d01_hertzmat_mass_velocity", "hertz/material E 1e7 nu 0.3 damping mass_velocity", "hertz/material 1e7 3000 0.3 damping mass_velocity " + TL)
dd("d02_hertzmat_tsuji", "hertz/material damping tsuji 0.5 (tsuji: coefficient is e)", "hertz/material 1e7 0.5 0.3 damping tsuji " + TL)
dd("d03_hertzmat_coeff_rest", "hertz/material damping coeff_restitution 0.7", "hertz/material 1e7 0.7 0.3 damping coeff_restitution " + TL)
dd("d04_hooke_coeff_rest", "hooke damping coeff_restitution 0.7", "hooke 2000 0.7 damping coeff_restitution " + TL)
dd("d05_hertz_viscoelastic", "hertz kn 1e5 damping viscoelastic 50", "hertz 1e5 50 damping viscoelastic " + TL)
dd("d06_dmt", "dmt E 1e7 eta 0.5 nu 0.3 work 0.01 (cohesion)", "dmt 1e7 0.5 0.3 0.01 damping tsuji " + TL)
dd("d07_jkr", "jkr E 1e7 eta 0.5 nu 0.3 work 0.01 (cohesion, end rule)", "jkr 1e7 0.5 0.3 0.01 damping tsuji " + TL)
dd("d08_hooke_limit_damping", "hooke 2000 gamma 30000 (big) with limit_damping: the attractive end force clipped", "hooke 2000 30000 " + K + " limit_damping")
dd("d09_hertzmat_visco_limit_damping", "hertz/material viscoelastic big eta with limit_damping", "hertz/material 1e7 1.4e8 0.3 damping viscoelastic " + TL + " limit_damping")
dd("d10_hooke_coeff_rest_one", "hooke coeff_restitution 1.0", "hooke 2000 1.0 damping coeff_restitution " + TL)
dd("d11_hertzmat_tsuji_zero", "hertz/material tsuji e 0.05 (near zero)", "hertz/material 1e7 0.05 0.3 damping tsuji " + TL)
deck("d12_mixed_models_explicit", "# pair_coeff 1 1 hooke, 2 2 hertz/material, 1 2 hertz/material explicit\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 {HK}\npair_coeff 2 2 {HM}\npair_coeff 1 2 hertz/material 2e7 1.4e7 0.3 damping viscoelastic {TL}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("d13_hertzmat_mixing_E", "# pair_coeff 1 1 hertz/material E 1e7, 2 2 E 5e7: 1 2 mixed by LAMMPS (effective modulus)\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 {HM}\npair_coeff 2 2 hertz/material 5e7 1.4e7 0.3 damping viscoelastic {TL}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("d14_hooke_mixing_kn_gamma", "# pair_coeff 1 1 hooke 2000 3000, 2 2 hooke 8000 1000: 1 2 mixed (geometric)\n"
     + head() + "pair_style granular\n" + f"pair_coeff 1 1 {HK}\npair_coeff 2 2 {hk(8000, 1000)}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
dd("d15_hooke_tsuji", "hooke kn 2000 damping tsuji 0.5", "hooke 2000 0.5 damping tsuji " + TL)
dd("d16_hertzmat_visco_rolling_twist", "hertz/material viscoelastic + tangential mindlin + rolling sds + twisting marshall (head-on: no part)",
   "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential mindlin NULL 1 0.4 rolling sds 1e3 50 0.1 twisting marshall")
def old(name, comment, style, coeff="", g=1, extra=""):
    deck(name, "# " + comment + "\n" + head() + f"pair_style {style}\npair_coeff * *{coeff}\n" + GRAV
         + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.5 1 zplane 0 NULL\n" + TAIL + TWO + extra + RUN1, g=g)
old("d17_gran_hooke_history", "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.5 1", "gran/hooke/history 2000 NULL 3000 NULL 0.5 1")
old("d18_gran_hooke_history_limit_damping", "gran/hooke/history gamma 30000 limit_damping", "gran/hooke/history 2000 NULL 30000 NULL 0.5 1 limit_damping")
old("d19_gran_hertz_history", "gran/hertz/history kn 1e6 gamman 3000", "gran/hertz/history 1e6 NULL 3000 NULL 0.5 1")
old("d20_gran_hooke_dampflag0", "gran/hooke kn 2000 gamman 3000 dampflag 0 (tangential damping off; normal stays)", "gran/hooke 2000 NULL 3000 NULL 0.5 0")
old("d21_gran_hertz_history_limit", "gran/hertz/history big gamma limit_damping", "gran/hertz/history 1e6 NULL 300000 NULL 0.5 1 limit_damping")
deck("d22_granular_cutoff", "# pair_style granular 0.02 (a global cutoff): no part in a contact\n"
     + head() + "pair_style granular 0.02\n" + f"pair_coeff * * {HK}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
dd("d23_hertzmat_coeff_rest_wall", "hertz/material coeff_restitution 0.4 pair and wall", "hertz/material 1e7 0.4 0.3 damping coeff_restitution " + TL)
dd("d24_hooke_coeff_rest_zero", "hooke coeff_restitution 0.0 (engine says)", "hooke 2000 0.0 damping coeff_restitution " + TL)
dd("d29_dmt_viscoelastic", "dmt E 1e7 eta 1.4e7 nu 0.3 work 0.01 damping viscoelastic (cohesion: refusal or mapped)", "dmt 1e7 1.4e7 0.3 0.01 damping viscoelastic " + TL)
dd("d30_jkr_viscoelastic", "jkr E 1e7 eta 1.4e7 nu 0.3 work 0.01 damping viscoelastic (cohesion, end rule)", "jkr 1e7 1.4e7 0.3 0.01 damping viscoelastic " + TL)
dd("d31_hertzmat_visco_no_limit", "twin of d09 without limit_damping", "hertz/material 1e7 1.4e8 0.3 damping viscoelastic " + TL)
dd("d25_dmt_zero_work", "dmt work 0 (no cohesion: hertz-like)", "dmt 1e7 0.5 0.3 0.0 damping tsuji " + TL)
dd("d26_jkr_zero_work", "jkr work 0 (engine says)", "jkr 1e7 0.5 0.3 0.0 damping tsuji " + TL)
dd("d27_hooke_viscoelastic", "hooke kn 2000 damping viscoelastic 3000 (hooke with a viscoelastic damping: factor a = delta*R?)", "hooke 2000 3000 damping viscoelastic " + TL)
dd("d28_hertz_mass_velocity", "hertz kn 1e6 damping mass_velocity 3000", "hertz 1e6 3000 damping mass_velocity " + TL)
# ---------------------------------------------------------------- n*: pairs that cannot meet
dd("n01_exclude_type_12", "neigh_modify exclude type 1 2: the 1 2 pair cannot meet", HK, extra="neigh_modify exclude type 1 2\n")
dd("n02_exclude_type_11", "neigh_modify exclude type 1 1", HK, extra="neigh_modify exclude type 1 1\n")
dd("n03_exclude_then_none", "neigh_modify exclude type 1 2 then exclude none: all meet again", HK, extra="neigh_modify exclude type 1 2\nneigh_modify exclude none\n")
dd("n04_exclude_group", "neigh_modify exclude group g1 g2 (g1 = type 1, g2 = type 2)", HK, extra="group g1 type 1\ngroup g2 type 2\nneigh_modify exclude group g1 g2\n")
deck("n05_hybrid_none", "# pair_style hybrid granular zero 0.01; pair_coeff 1 2 none: 1 2 no force\n"
     + head() + f"pair_style hybrid granular zero 0.01\npair_coeff * * granular {HK}\npair_coeff 1 2 none\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("n06_hybrid_zero_12", "# hybrid granular zero; pair_coeff 1 2 zero: 1 2 no force\n"
     + head() + f"pair_style hybrid granular zero 0.01\npair_coeff * * granular {HK}\npair_coeff 1 2 zero\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("n07_wall_group_type1", "# fix wall/gran on group of type 1 only: type 2 never meets the wall\n"
     + head() + G1(HK) + GRAV + "group g1 type 1\n" + TWO + "group g1 type 1\n" + f"fix floor g1 wall/gran granular {HK} zplane 0 NULL\n" + TAIL + RUN1, g=1)
dd("n08_exclude_type_in_run_every", "neigh_modify exclude after a run: run 10, then exclude type 2 2", HK, extra="run 10\nneigh_modify exclude type 2 2\n")
deck("n09_hybrid_overlay_two_granular", "# hybrid/overlay granular granular (two contact laws summed on all pairs? engine says)\n"
     + head() + f"pair_style hybrid/overlay granular granular\npair_coeff * * granular 1 {HK}\npair_coeff * * granular 2 {hk(4000)}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("n10_hybrid_two_granular_by_type", "# hybrid granular granular: 1 1 by sub-style 1 (kn 2000), 2 2 and 1 2 by sub-style 2 (kn 8000)\n"
     + head() + f"pair_style hybrid granular granular\npair_coeff 1 1 granular 1 {HK}\npair_coeff 1 2 granular 2 {hk(8000)}\npair_coeff 2 2 granular 2 {hk(8000)}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
dd("n11_exclude_molecule_intra", "atom_style sphere: neigh_modify exclude molecule/intra all (no molecule ids: all 0 -> every pair intra? engine says)", HK,
   extra="neigh_modify exclude molecule/intra all\n")
# ---------------------------------------------------------------- w*: walls
ww = lambda name, comment, wall, g=1, extra="", model=HK: deck(name, "# " + comment + "\n" + head() + G1(model) + GRAV + wall + "\n" + TAIL + TWO + extra + RUN1, g=g)
ww("w01_wall_hertzmat_tsuji", "fix wall/gran granular hertz/material damping tsuji (pair hooke)", f"fix floor all wall/gran granular hertz/material 1e7 0.5 0.3 damping tsuji {TL} zplane 0 NULL")
ww("w02_wall_region_moving", "fix wall/gran/region with a plane region moving up at 0.5 m/s (the relative speed is g)",
   f"variable zz equal 0.5*time\nregion fl plane 0 0 0.0 0 0 1 side in move NULL NULL v_zz units box\nfix floor all wall/gran/region granular {HK} region fl")
ww("w03_wall_old_hooke_history", "fix wall/gran hooke/history kn 5000 NULL 3000 NULL 0.5 1 (old syntax) beside pair granular", "fix floor all wall/gran hooke/history 5000 NULL 3000 NULL 0.5 1 zplane 0 NULL")
ww("w04_wall_wiggle", "fix wall/gran granular with wiggle z 0.001 0.01 (a moving wall)", f"fix floor all wall/gran granular {HK} zplane 0 NULL wiggle z 0.001 0.01")
ww("w05_wall_limit_damping", "fix wall/gran granular hooke 2000 30000 limit_damping", f"fix floor all wall/gran granular hooke 2000 30000 {K} limit_damping zplane 0 NULL")
ww("w06_wall_coeff_rest", "fix wall/gran granular hooke coeff_restitution 0.3", f"fix floor all wall/gran granular hooke 2000 0.3 damping coeff_restitution {TL} zplane 0 NULL")
ww("w07_wall_zcylinder", "fix wall/gran granular zcylinder 0.018 (a wall all spheres may meet)", f"fix floor all wall/gran granular {HK} zcylinder 0.018")
ww("w08_wall_region_sphere_inside", "fix wall/gran/region granular with a sphere region (concave wall, radius 0.05)",
   f"region ball sphere 0.02 0.02 0.05 0.05 side in units box\nfix floor all wall/gran/region granular hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL} region ball", model=HM)
ww("w09_wall_hertz_old", "fix wall/gran hertz/history kn 1e6 gamma 3000 (old syntax)", "fix floor all wall/gran hertz/history 1e6 NULL 3000 NULL 0.5 1 zplane 0 NULL")
ww("w10_wall_temperature_kw", "fix wall/gran granular ... contacts keyword", f"fix floor all wall/gran granular {HK} zplane 0 NULL contacts")
ww("w11_two_walls_diff", "two walls: floor kn 2000 and ceiling kn 8000 at 0.1", f"fix floor all wall/gran granular {HK} zplane 0 NULL\nfix ceil all wall/gran granular {hk(8000)} zplane NULL 0.1")
# ---------------------------------------------------------------- v*: variable styles
vv = lambda name, comment, lines, data=None: deck(name, "# " + comment + "\n" + BASE() + TWO + lines + RUN1, g=1, data=data)
vv("v01_atomfile_diameter", "variable d atomfile d.txt (id 1 0.008, id 2 0.006); set group all diameter v_d", "variable d atomfile d.txt\nset group all diameter v_d\n", {"d.txt": "# per atom\n2\n1 0.008\n2 0.006\n"})
vv("v02_getenv_unset", "variable e getenv F23_UNSET_NAME (empty); if \"x${e} == x\" then kn 6000", "variable e getenv F23_UNSET_NAME\nif \"x${e} == x\" then \"pair_coeff * * " + hk(6000) + "\"\n")
vv("v03_format_var", "variable k equal 4000.4; variable kf format k %.0f; pair_coeff ${kf}", "variable k equal 4000.4\nvariable kf format k %.0f\npair_coeff * * hooke ${kf} 3000 " + K + "\n")
vv("v04_universe_next", "variable kn universe 3000 5000 (one partition): kn 3000; next kn -> 5000", "variable kn universe 3000 5000\nnext kn\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v05_uloop_next", "variable i uloop 3 then next i (2): kn = 2000*i", "variable i uloop 3\nnext i\npair_coeff * * hooke $(2000*v_i) 3000 " + K + "\n")
vv("v06_index_redefine_ignored", "variable kn index 3000; variable kn index 6000 (ignored by LAMMPS: index may not be redefined): kn 3000", "variable kn index 3000\nvariable kn index 6000\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v07_string_redefine", "variable kn string 3000; variable kn string 6000 (string can be redefined): kn 6000", "variable kn string 3000\nvariable kn string 6000\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v08_delete_then_index", "variable kn index 3000; variable kn delete; variable kn index 6000: kn 6000", "variable kn index 3000\nvariable kn delete\nvariable kn index 6000\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v09_vector_element", "variable a vector [2000,5000]; pair_coeff hooke $(v_a[2])", "variable a vector [2000,5000]\npair_coeff * * hooke $(v_a[2]) 3000 " + K + "\n")
vv("v10_is_defined", "if $(is_defined(variable,kn)) false -> kn 7000", "if \"$(is_defined(variable,kn)) == 0\" then \"variable kn equal 7000\"\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v11_atom_var_diameter", "variable d atom 0.004+0.004*(x>0.015): set group all diameter v_d (type 1 at x 0.02 -> 8 mm)", "variable d atom 0.004+0.004*(x>0.015)\nset group all diameter v_d\n")
vv("v12_index_loop_jump", "label/jump SELF loop over kn index 3000 5000 7000 with a run each: the last kn 7000",
   "variable kn index 3000 5000 7000\nlabel lp\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 10\nnext kn\njump SELF lp\n")
vv("v13_loop_var_pad", "variable i loop 3 pad; label/jump; kn = 1000*i + 2000 -> last 5000",
   "variable i loop 3 pad\nlabel lp\npair_coeff * * hooke $(1000*v_i+2000) 3000 " + K + "\nrun 10\nnext i\njump SELF lp\n")
vv("v14_getenv_set_by_shell", "shell putenv F23KN=6000; variable k getenv F23KN; pair_coeff ${k}", "shell putenv F23KN=6000\nvariable k getenv F23KN\npair_coeff * * hooke ${k} 3000 " + K + "\n")
vv("v15_string_with_next", "variable kn string 3000; next kn (string may not be next'ed: engine says)", "variable kn string 3000\nnext kn\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v16_file_var_two_next", "variable kn file kn.txt (2000 4000 6000), next kn twice -> 6000", "variable kn file kn.txt\nnext kn\nnext kn\npair_coeff * * hooke ${kn} 3000 " + K + "\n", {"kn.txt": "# values\n2000\n4000\n6000\n"})
vv("v17_atomfile_next", "variable d atomfile d.txt with two sets; next d -> the second (8 mm for id 2)", "variable d atomfile d.txt\nnext d\nset group all diameter v_d\n", {"d.txt": "2\n1 0.004\n2 0.006\n2\n1 0.004\n2 0.008\n"})
vv("v18_immediate_in_index", "variable kn index $(2000+3000) (immediate inside index) -> 5000", "variable kn index $(2000+3000)\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v19_equal_self_reference_redefine", "variable kn equal 2000; variable kn equal ${kn}*3 (immediate, 6000)", "variable kn equal 2000\nvariable kn equal ${kn}*3\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
vv("v20_python_style_refused", "variable kn python f (no python function defined: engine says)", "variable kn python f\npair_coeff * * hooke ${kn} 3000 " + K + "\n")
# ---------------------------------------------------------------- R*: run forms, time step
rr = lambda name, comment, lines: deck(name, "# " + comment + "\n" + BASE() + TWO + lines, g=1)
rr("R01_run_start_stop", "run 100 start 0 stop 1000 then pair_coeff kn 5000, run 100 pre no post no", "run 100 start 0 stop 1000\npair_coeff * * " + hk(5000) + "\nrun 100 pre no post no\n")
rr("R02_run_upto_step_var", "run 100; run 300 upto; variable kn equal 2000+10*step (5000)", "run 100\nrun 300 upto\npair_coeff * * hooke $(2000+10*step) 3000 " + K + "\nrun 100\n")
rr("R03_timestep_var", "variable dt equal 1e-4; timestep ${dt} (few steps per contact: note expected)", "variable dt equal 1e-4\ntimestep ${dt}\nrun 100\n")
rr("R04_timestep_big_coarse", "timestep 3e-4: ~5 steps per contact for 1 2 (LAMMPS eps differs from the law's: note expected)", "timestep 3e-4\nrun 100\n")
rr("R05_fix_dt_reset", "fix dt/reset 1 1e-6 1e-3 0.0001 (dt from motion)", "fix dtr all dt/reset 1 1e-6 1e-3 0.0001 units box\nrun 100\n")
rr("R06_run_zero", "run 0 only (settings at the run)", "run 0\n")
rr("R07_run_every_fixed_command", "run 100 every 50 \"print hi\" (no contact change)", "run 100 every 50 \"print hi\"\n")
rr("R08_rerun_absent", "no run at all: pair_coeff set, no run (what the audit prints)", "")
rr("R09_timestep_after_pair", "timestep $(v_a*2) where a equal 5e-6", "variable a equal 5e-6\ntimestep $(v_a*2)\nrun 100\n")
rr("R10_minimize", "minimize before run (a granular system: engine says)", "min_style cg\nminimize 0 0 10 10\nrun 100\n")
# ---------------------------------------------------------------- L*: LIGGGHTS
L("L01_e_matrix_n_from_var", "# LIGGGHTS: variable n equal 3; coefficientRestitution peratomtypepair ${n} (0.6/0.5/0.4 matrix)\n"
  + lhead() + MAT3 + "variable n equal 3\n" + E3.replace("peratomtypepair 3", "peratomtypepair ${n}") + HERTZ + WALL3 + ATOMS + RUN)
L("L02_e_from_variables", "# LIGGGHTS: e11 0.3, e12 0.45, e22 0.55 from equal variables; e13 0.7 e23 0.65 e33 0.8\n"
  + lhead() + MAT3 + "variable e11 equal 0.3\nvariable e12 equal 0.45\nvariable e22 equal 0.3+0.25\n"
  + "fix m3 all property/global coefficientRestitution peratomtypepair 3 ${e11} ${e12} 0.7 ${e12} ${e22} 0.65 0.7 0.65 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L03_e_one", "# LIGGGHTS hertz e = 1.0 everywhere (engine says: no damping -> eps 1)\n" + lhead() + MAT3 + E3b(1.0) + HERTZ + WALL3 + ATOMS + RUN)
L("L04_insert_pack_discrete_two", "# LIGGGHTS insert/pack with particledistribution/discrete of two templates (type 1 2 mm r, type 2 3 mm r)\n"
  + LB() + PTS + LRUN + "fix ins all insert/pack seed 32452867 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 20 region bc\nrun 1000\n")
L("L05_mesh_floor_type3", "# LIGGGHTS mesh/surface floor (STL) of type 3 with hooke: e 0.7 for 1 on wall\n"
  + lhead() + MAT3 + E3 + "fix m4 all property/global characteristicVelocity scalar 2.\n" + HOOKE
  + "fix cad all mesh/surface file floor.stl type 3\nfix wmesh all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad\n" + ATOMS + RUN,
  data={"floor.stl": "solid f\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 -0.05 0\nvertex 0.05 0.05 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 0.05 0\nvertex -0.05 0.05 0\nendloop\nendfacet\nendsolid f\n"})
L("L06_old_wall_syntax", "# LIGGGHTS old wall syntax 'fix zwalls all wall/gran 266000.0 NULL 500.0 NULL 0.5 1 zplane 0.0 0.15' (as the tutorials' comments; engine says)\n"
  + lhead() + MAT3 + E3 + HERTZ + "fix zwalls all wall/gran 266000.0 NULL 500.0 NULL 0.5 1 zplane 0.0 0.15\n" + ATOMS + RUN)
L("L07_cohesion_sjkr", "# LIGGGHTS hertz with cohesion sjkr (cohesionEnergyDensity 1e5): eps below the typed e at low speed\n"
  + lhead() + MAT3 + E3 + "fix m5 all property/global cohesionEnergyDensity peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n"
  + "pair_style gran model hertz tangential history cohesion sjkr\npair_coeff * *\n" + WALL3 + ATOMS + RUN)
L("L08_rolling_epsd2", "# LIGGGHTS rolling_friction epsd2: no part head-on\n"
  + lhead() + MAT3 + E3 + "fix m8 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n"
  + "pair_style gran model hertz tangential history rolling_friction epsd2\npair_coeff * *\n" + WALL3 + ATOMS + RUN)
L("L09_hooke_characteristic_velocity", "# LIGGGHTS hooke with characteristicVelocity 2: e typed (linear: exact)\n"
  + lhead() + MAT3 + E3 + "fix m4 all property/global characteristicVelocity scalar 2.\n" + HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("L10_variable_if_liggghts", "# LIGGGHTS variable e equal 0.3+0.2, if ${e} > 0.4 then e matrix 0.5 else 0.2\n"
  + lhead() + MAT3 + E3 + "variable e equal 0.3+0.2\nif \"${e} > 0.4\" then \"" + E3b(0.5).strip() + "\" else \"" + E3b(0.2).strip() + "\"\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L11_asymmetric_e", "# LIGGGHTS asymmetric e matrix (e12 0.5, e21 0.3): engine says\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.3 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L12_e_zero", "# LIGGGHTS e 0.0 for 1 1 (engine says)\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.0 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L13_units_cgs_liggghts", "# LIGGGHTS units cgs: youngsModulus 5e7 (dyne/cm2), sizes 0.4/0.6 cm, density 2.5/1.5: hertz typed e\n"
  + lhead(units="cgs", box="-5 5 -5 5 -1 15").replace("neighbor 0.002", "neighbor 0.2") + MAT3.replace("5e6 5e6 5e6", "5e7 5e7 5e7") + E3 + HERTZ + WALL3
  + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\n"
  + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n")
L("L14_tangential_no_history", "# LIGGGHTS hertz tangential no_history: head-on e typed\n"
  + lhead() + MAT3 + E3 + "pair_style gran model hertz tangential no_history\npair_coeff * *\nfix wprim all wall/gran model hertz tangential no_history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("L15_hertz_stiffness", "# LIGGGHTS hertz/stiffness kn/kt/gamman/gammat typed (engine says)\n"
  + lhead() + MAT3 + "fix k1 all property/global kn peratomtypepair 3 " + " ".join(["1e6"] * 9) + "\nfix k2 all property/global kt peratomtypepair 3 " + " ".join(["1e6"] * 9)
  + "\nfix k3 all property/global gamman peratomtypepair 3 " + " ".join(["2000"] * 9) + "\nfix k4 all property/global gammat peratomtypepair 3 " + " ".join(["2000"] * 9)
  + "\npair_style gran model hertz/stiffness tangential history\npair_coeff * *\nfix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("L16_exclude_type_12", "# LIGGGHTS neigh_modify exclude type 1 2: the 1 2 pair cannot meet\n"
  + lhead() + "neigh_modify exclude type 1 2\n" + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L17_e_redefined_same_id_after_run", "# LIGGGHTS run 1000 then fix m3 redefined with e 0.3 (same id) and run 100: stage 2 e 0.3\n"
  + LB() + ATOMS + LRUN + "run 1000\n" + E3b(0.3) + "run 100\n")
L("L18_e_per_type_2types", "# LIGGGHTS 2 atom types, wall of type 2: e matrix 2x2 (0.6 0.5 0.5 0.4)\n"
  + lhead(nt=2) + "fix m1 all property/global youngsModulus peratomtype 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3\n"
  + "fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\nfix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4\n"
  + HERTZ + "fix wprim all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n" + ATOMS + RUN)
L("L19_youngs_per_type_differs", "# LIGGGHTS youngsModulus 5e6/5e7/5e6 per type: the eps of hertz stays e (typed)\n"
  + lhead() + MAT3.replace("5e6 5e6 5e6", "5e6 5e7 5e6") + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L20_index_next_e", "# LIGGGHTS variable e index 0.3 0.6; next e; e matrix ${e} -> 0.6\n"
  + lhead() + MAT3 + "variable e index 0.3 0.6\nnext e\nfix m3 all property/global coefficientRestitution peratomtypepair 3 ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e} ${e}\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L21_insert_stream_discrete", "# LIGGGHTS insert/stream from a mesh face with pdd of two templates\n"
  + LB() + PTS + "fix inface all mesh/surface file face.stl type 1\n" + LRUN
  + "fix ins all insert/stream seed 32452867 distributiontemplate pdd1 nparticles 20 massrate 0.1 insert_every 200 overlapcheck yes all_in no vel constant 0 0 -1 insertion_face inface extrude_length 0.02\nrun 1000\n",
  data={"face.stl": "solid f\nfacet normal 0 0 -1\nouter loop\nvertex -0.03 -0.03 0.1\nvertex 0.03 0.03 0.1\nvertex 0.03 -0.03 0.1\nendloop\nendfacet\nfacet normal 0 0 -1\nouter loop\nvertex -0.03 -0.03 0.1\nvertex -0.03 0.03 0.1\nvertex 0.03 0.03 0.1\nendloop\nendfacet\nendsolid f\n"})
L("L22_hooke_e_one", "# LIGGGHTS hooke e 1.0 with characteristicVelocity\n"
  + lhead() + MAT3 + E3b(1.0) + "fix m4 all property/global characteristicVelocity scalar 2.\n" + HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n" + ATOMS + RUN)
L("L23_e_peratomtype_wrong_style", "# LIGGGHTS coefficientRestitution given peratomtype (not pair): engine says\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtype 0.6 0.4 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L24_viscoelastic_off_tangential", "# LIGGGHTS pair_style gran model hertz tangential history with 'pair_coeff 1 1' only? (engine says)\n"
  + lhead() + MAT3 + E3 + "pair_style gran model hertz tangential history\npair_coeff 1 1\npair_coeff 2 2\npair_coeff 1 2\npair_coeff * 3\n" + WALL3 + ATOMS + RUN)
L("L25_wall_gran_region_liggghts", "# LIGGGHTS wall/gran with a primitive zcylinder of type 3 radius 0.04 (and floor)\n"
  + lhead() + MAT3 + E3 + HERTZ + WALL3 + "fix wcyl all wall/gran model hertz tangential history primitive type 3 zcylinder 0.04 0 0\n" + ATOMS + RUN)
# ---------------------------------------------------------------- e*: re-checks of earlier rounds' classes
ee = lambda name, comment, lines, g=1, data=None: deck(name, "# " + comment + "\n" + BASE() + TWO + lines, g=g, data=data)
ee("e01_immediate_format", "$(...) with format: pair_coeff hooke $(2000*2.5:%.1f)", "pair_coeff * * hooke $(2000*2.5:%.1f) 3000 " + K + "\nrun 100\n")
ee("e02_type_range_pair", "pair_coeff 1*2 2 (1 2 and 2 2) kn 8000", "pair_coeff 1*2 2 " + hk(8000) + "\nrun 100\n")
ee("e03_set_mass_after_diameter", "set type 2 mass 1e-3 after diameter (rho from mass)", "set type 2 mass 1e-3\nrun 100\n")
ee("e04_pair_restyle", "pair_style granular again with kn 6000 (restyle clears coeffs)", "pair_style granular\npair_coeff * * " + hk(6000) + "\nrun 100\n")
ee("e05_quit_before_change", "quit before a pair_coeff change: the run above is the last", "run 100\nquit\npair_coeff * * " + hk(8000) + "\nrun 100\n")
ee("e06_quit_in_if", "if \"1 > 0\" then quit, after run 100", "run 100\nif \"1 > 0\" then quit\npair_coeff * * " + hk(8000) + "\nrun 100\n")
ee("e07_set_range_ids", "set atom 1*1 diameter 0.008 (an id range)", "set atom 1*1 diameter 0.008\nrun 100\n")
ee("e08_typographic_quote", "print with typographic quotes (\u201chi\u201d) then pair_coeff 5000", "print \u201chi there\u201d\npair_coeff * * " + hk(5000) + "\nrun 100\n")
ee("e09_random_draw_kn", "kn = 2000 + floor(random(0,1,4711)*2)*3000 (engine draws)", "variable kn equal 2000+floor(random(0,1,4711)*2)*3000\nprint \"PROBE kn $(v_kn)\"\nvariable k2 equal ${kn}\npair_coeff * * hooke ${kn} 3000 " + K + "\nrun 100\n")
ee("e10_dynamic_group_set_after_run", "group hi dynamic region z>0.005; run 5000 (both fall); set group hi density 7800 (none in engine)",
   "region hi block INF INF INF INF 0.005 INF units box\ngroup hi dynamic all region hi\nrun 5000\nset group hi density 7800\nrun 100\n")
ee("e11_lost_ignore_then_set_type", "thermo_modify lost ignore; type 2 thrown out; create_atoms 2; set type 2 density 1000",
   "thermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset type 2 diameter 0.006 density 1000\nrun 100\n")
ee("e12_lone_cr_in_include", "include with a lone CR inside a comment line before a pair_coeff", "include inc.in\nrun 100\n",
   data={"inc.in": "# stiffer\rpair_coeff * * " + hk(5000) + "\n"})
ee("e13_restyle_wall_unfix", "unfix floor; fix floor wall/gran granular kn 8000", "unfix floor\nfix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL\nrun 100\n")
ee("e14_walls_only_type3", "3rd type never created; wall rows only for present types", "run 100\n")
ee("e15_timer_timeout", "timer timeout 0.0001 then run (engine may stop the run early; settings unchanged)", "timer timeout 1:00:00\nrun 100\n")
ee("e16_set_diameter_range_types", "set type 1*2 diameter 0.005", "set type 1*2 diameter 0.005\nrun 100\n")
ee("e17_run_every_unfix", "run 100 every 50 \"unfix grav\" (mapped: gravity gone)", "run 100 every 50 \"unfix grav\"\nrun 100\n")
ee("e18_if_quoted_triple", "if with triple quotes containing two commands (kn 5000 then 6000)", "if \"1 > 0\" then \"\"\"pair_coeff * * " + hk(5000) + "\npair_coeff * * " + hk(6000) + "\"\"\"\nrun 100\n")

# ---------------------------------------------------------------- f*: other fixes that change a two-body collision
HB = lambda: BASE(HM)
ff = lambda name, comment, lines, model=HK: deck(name, "# " + comment + "\n" + BASE(model) + TWO + lines + RUN1, g=1)
ff("f01_freeze_type2", "fix freeze on type 2 (force zeroed: a sphere that does not move): 1 2 is a sphere on a fixed sphere", "group t2 type 2\nfix fr t2 freeze\n")
ff("f02_setforce_type2", "fix setforce 0 0 0 on type 2 (keeps its velocity, no contact force)", "group t2 type 2\nfix sf t2 setforce 0.0 0.0 0.0\n")
ff("f03_nve_sphere_subgroup", "fix nve/sphere only on type 1 (type 2 never moves): integ replaced", "unfix integ\ngroup t1 type 1\nfix integ t1 nve/sphere\n")
ff("f04_move_linear_type2", "fix move linear 0 0 0 on type 2 (held in place, not integrated)", "group t2 type 2\nunfix integ\ngroup t1 type 1\nfix integ t1 nve/sphere\nfix mv t2 move linear 0 0 0\n")
ff("f05_double_integration", "type 2 integrated twice (nve/sphere on all plus nve/sphere on t2): LAMMPS warns; 1 2 changes", "group t2 type 2\nfix integ2 t2 nve/sphere\n")
ff("f06_viscous_sphere", "fix viscous/sphere 1e-4 (rotational only: no part head-on?)", "fix vs all viscous/sphere 1e-4\n")
ff("f07_damping_cundall", "fix damping/cundall 0.5 0.5 (local damping: changes eps)", "fix dc all damping/cundall 0.5 0.5\n")
ff("f08_addforce_type1", "fix addforce 0.01 0 0 on type 1 (a body force along x: changes a head-on x collision)", "group t1 type 1\nfix af t1 addforce 0.01 0.0 0.0\n")
ff("f09_spring_self_type2", "fix spring/self 1000 on type 2 (tethered)", "group t2 type 2\nfix ss t2 spring/self 1000.0\n")
ff("f10_rigid_small_pair", "fix rigid/small of a 2-sphere clump of type 2 (molecule ids needed: engine says)", "group t2 type 2\nfix rb t2 rigid/small molecule\n")
ff("f11_freeze_hertz", "fix freeze on type 2 with hertz/material", "group t2 type 2\nfix fr t2 freeze\n", model=HM)
ff("f12_gravity_group_only", "gravity on type 1 only (fix grav unfixed, fix g1 t1 gravity)", "unfix grav\ngroup t1 type 1\nfix g1 t1 gravity 9.81 vector 0 0 -1\n")
ff("f13_nve_limit", "fix nve/limit 1e-6 on all (integ replaced): velocities limited per step (engine decides)", "unfix integ\nfix integ all nve/limit 1e-6\n")
ff("f14_langevin_zero_t", "fix langevin 0 0 0.001 seed (friction toward rest: changes eps)", "fix lv all langevin 0.0 0.0 0.001 4711\n")
ff("f15_aveforce_type2", "fix aveforce 0 0 0 on type 2 (net force zeroed: a 1-atom group frozen in force)", "group t2 type 2\nfix avf t2 aveforce 0.0 0.0 0.0\n")
# ---------------------------------------------------------------- h*: size-sensitive twins with hertz/material (LAMMPS set diameter keeps the mass)
hh = lambda name, comment, lines, data=None: deck(name, "# " + comment + "\n" + BASE(HM) + TWO + lines + RUN1, g=1, data=data)
hh("h01_labelmap_set_diameter_hertz", "labelmap; set type big diameter 0.010 (mass kept): hertz sees the size", LM + "set type big diameter 0.010\n")
hh("h02_atom_var_diameter_hertz", "variable d atom 0.004+0.004*(x>0.015); set group all diameter v_d (type 1 -> 8 mm, type 2 -> 4 mm)", "variable d atom 0.004+0.004*(x>0.015)\nset group all diameter v_d\n")
hh("h03_displace_region_diameter_hertz", "displace_atoms move 0.01 0 0 then set region x>0.025 diameter 0.010", "displace_atoms all move 0.01 0 0 units box\nregion rt block 0.025 INF INF INF INF INF units box\nset region rt diameter 0.010\n")
hh("h04_set_density_then_diameter", "set type 2 density 7800 then diameter 0.010 (mass kept from 6 mm 7800)", "set type 2 density 7800\nset type 2 diameter 0.010\n")
hh("h05_set_diameter_then_density", "set type 2 diameter 0.010 then density 1000 (mass from 10 mm 1000)", "set type 2 diameter 0.010\nset type 2 density 1000\n")
hh("h06_read_data_hertz", "hertz read_data twin (r01 sizes)", "")
hh("h07_index_redefine_diameter", "variable d index 0.008; variable d index 0.010 (ignored); set type 2 diameter ${d}", "variable d index 0.008\nvariable d index 0.010\nset type 2 diameter ${d}\n")
hh("h08_set_type_fraction", "set type 1 type/fraction 2 1.0 4711 (all type 1 become type 2)", "set type 1 type/fraction 2 1.0 4711\n")
hh("h09_set_type_ratio", "set type 2 type/ratio 1 1.0 4711 (the type 2 atom becomes type 1)", "set type 2 type/ratio 1 1.0 4711\n")
hh("h10_set_region_type", "region around the type 1 sphere; set region r type 2", "region r sphere 0.02 0.02 0.01 0.003 units box\nset region r type 2\n")
hh("h11_velocity_then_diameter_var", "variable d equal 0.002*3; set type 1 diameter $d (single-letter variable without braces)", "variable d equal 0.002*3\nset type 1 diameter $d\n")
hh("h12_set_diameter_vzero", "set type 2 diameter 0.0 (a point: engine says)", "set type 2 diameter 0.0\n")

# ---------------------------------------------------------------- k*: more LAMMPS forms
kk = lambda name, comment, body, g=1, data=None: deck(name, "# " + comment + "\n" + body, g=g, data=data)
NODAMP = f"hooke 2000 3000 {TL}"
kk("k01_default_damping", "pair_coeff hooke 2000 3000 with no damping keyword (LAMMPS' default damping viscoelastic)", BASE(NODAMP) + TWO + RUN1)
kk("k02_hertzmat_mix_nu", "hertz/material 1 1 E 1e7 nu 0.3, 2 2 E 5e7 nu 0.45: 1 2 mixed from E and nu", head() + "pair_style granular\n"
   + f"pair_coeff 1 1 {HM}\npair_coeff 2 2 hertz/material 5e7 1.4e7 0.45 damping viscoelastic {TL}\n" + GRAV + FLOOR + TAIL + TWO + RUN1)
kk("k03_coeff_rest_mixed", "hertz/material coeff_restitution 1 1 e 0.8, 2 2 e 0.4: 1 2 mixed (geometric: 0.566?)", head() + "pair_style granular\n"
   + f"pair_coeff 1 1 hertz/material 1e7 0.8 0.3 damping coeff_restitution {TL}\npair_coeff 2 2 hertz/material 1e7 0.4 0.3 damping coeff_restitution {TL}\n" + GRAV + FLOOR + TAIL + TWO + RUN1)
kk("k04_dmt_zero_work_visco", "dmt work 0 damping viscoelastic (= hertz/material force)", BASE("dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic " + TL) + TWO + RUN1)
kk("k05_jkr_zero_work_visco", "jkr work 0 damping viscoelastic", BASE("jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic " + TL) + TWO + RUN1)
kk("k06_hertz_limit_damping", "hertz kn 1e6 gamma 3e5 mass_velocity limit_damping", BASE("hertz 1e6 3e5 damping mass_velocity " + TL + " limit_damping") + TWO + RUN1)
kk("k07_no_comm_vel", "no comm_modify vel yes (engine says)", BASE().replace("comm_modify vel yes\n", "") + TWO + RUN1)
kk("k08_exclude_type_labels", "neigh_modify exclude type small big (labels)", BASE() + TWO + LM + "neigh_modify exclude type small big\n" + RUN1)
kk("k09_group_type_compare", "group g type > 1; set group g density 7800", BASE() + TWO + "group g type > 1\nset group g density 7800\n" + RUN1)
kk("k10_set_type_open_range", "set type 2* density 7800", BASE() + TWO + "set type 2* density 7800\n" + RUN1)
kk("k11_pair_coeff_open_range", "pair_coeff 2* 2* kn 8000 (2 2 only)", BASE() + TWO + f"pair_coeff 2* 2* {hk(8000)}\n" + RUN1)
kk("k12_if_elif_else", "if 0 then kn 3000 elif 1 then kn 5000 else kn 7000 -> 5000", BASE() + TWO
   + f"if \"0 > 1\" then \"pair_coeff * * {hk(3000)}\" elif \"1 > 0\" \"pair_coeff * * {hk(5000)}\" else \"pair_coeff * * {hk(7000)}\"\n" + RUN1)
kk("k13_nested_var_name", "variable i equal 2; kn${i} (kn2 = 6000): pair_coeff ${kn${i}}? (engine says)", BASE() + TWO
   + "variable i equal 2\nvariable kn1 equal 3000\nvariable kn2 equal 6000\nvariable k equal v_kn${i}\n" + f"pair_coeff * * hooke $(v_k) 3000 {K}\n" + RUN1)
kk("k14_pour_type_label", "fix pour by type label big (type 2), diam one 0.006 dens 7800 7800", BASE() + LM + INS
   + "create_atoms small single 0.02 0.02 0.01\nset type small diameter 0.004 density 2500\nfix p all pour 5 big 4767 region ins diam one 0.006 dens 7800 7800\nrun 200\n")
kk("k15_create_atoms_basis", "lattice sc 0.01 with basis of 2 types? create_atoms 1 region r basis 1 2 (engine says): then set type 2 diameter 0.006 density 7800",
   BASE() + "lattice custom 0.01 a1 1 0 0 a2 0 1 0 a3 0 0 1 basis 0 0 0 basis 0.5 0.5 0.5\nregion r block 0 2 0 2 1 2\ncreate_atoms 1 region r basis 2 2\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 7800\n" + RUN1)
kk("k16_include_var_path", "include ${f} with variable f string kn.in (kn 6000)", BASE() + TWO + "variable f string kn.in\ninclude ${f}\n" + RUN1, data={"kn.in": f"pair_coeff * * {hk(6000)}\n"})
kk("k17_hertzmat_damping_first", "pair_coeff with damping before tangential and a rolling model after (order of keywords)", BASE(f"hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_history 1e3 1 0.3 rolling sds 1e3 50 0.1") + TWO + RUN1)
kk("k18_set_type_mass_hertz", "hertz: set type 2 mass 1e-3 (rho from mass, radius kept)", BASE(HM) + TWO + "set type 2 mass 1e-3\n" + RUN1)
kk("k19_variable_atom_set_density", "variable r atom 2500+5300*(type==2); set group all density v_r", BASE() + TWO + "variable r atom 2500+5300*(type==2)\nset group all density v_r\n" + RUN1)
kk("k20_units_cgs_g100", "the u02 cgs deck audited with --g 100 (1 m/s in cm/s): ARGS none, G 100", ubase("cgs", CGS_HM, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\n" + RUN1, g=100)
# ---------------------------------------------------------------- L26+: more LIGGGHTS
L("L26_E_too_big_no_hard", "# LIGGGHTS youngsModulus 1e10 without hard_particles yes (engine says)\n"
  + lhead() + MAT3.replace("5e6 5e6 5e6", "1e10 1e10 1e10") + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L27_E_big_hard_particles", "# LIGGGHTS youngsModulus 1e10 with hard_particles yes: hertz typed e\n"
  + lhead() + "hard_particles yes\n" + MAT3.replace("5e6 5e6 5e6", "1e10 1e10 1e10") + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L28_immediate_var_liggghts", "# LIGGGHTS: $(0.3+0.2) immediate form in the e matrix (LIGGGHTS 3.8 may not know $(...): engine says)\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 $(0.3+0.2) 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L29_if_elif_liggghts", "# LIGGGHTS if/elif/else: elif branch e 0.5\n"
  + lhead() + MAT3 + E3 + "if \"0 > 1\" then \"" + E3b(0.2).strip() + "\" elif \"1 > 0\" \"" + E3b(0.5).strip() + "\" else \"" + E3b(0.9).strip() + "\"\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L30_e_matrix_extra_value", "# LIGGGHTS e matrix with 10 values for 3 types (one extra: engine says)\n"
  + lhead() + MAT3 + E3.replace("0.8\n", "0.8 0.3\n") + HERTZ + WALL3 + ATOMS + RUN)
L("L31_e_number_forms", "# LIGGGHTS e values written .6 / 5e-1 / 0.40 (number forms)\n"
  + lhead() + MAT3 + "fix m3 all property/global coefficientRestitution peratomtypepair 3 .6 5e-1 0.7 5e-1 0.40 0.45 0.7 0.45 0.8\n" + HERTZ + WALL3 + ATOMS + RUN)
L("L32_e_matrix_short", "# LIGGGHTS e matrix with 8 values for 3 types (one missing: engine says)\n"
  + lhead() + MAT3 + E3.replace(" 0.8\n", "\n") + HERTZ + WALL3 + ATOMS + RUN)
L("L33_atom_style_sphere", "# LIGGGHTS atom_style sphere instead of granular (engine says)\n"
  + lhead().replace("atom_style granular", "atom_style sphere") + MAT3 + E3 + HERTZ + WALL3 + ATOMS + RUN)
L("L34_variable_e_vector_style", "# LIGGGHTS: e from a variable string 0.35 (string style)\n"
  + lhead() + MAT3 + "variable e string 0.35\n" + E3b("${e}") + HERTZ + WALL3 + ATOMS + RUN)
L("L35_units_cgs_hooke_charvel", "# LIGGGHTS units cgs hooke with characteristicVelocity 200 (cm/s): e typed\n"
  + lhead(units="cgs", box="-5 5 -5 5 -1 15").replace("neighbor 0.002", "neighbor 0.2") + MAT3.replace("5e6 5e6 5e6", "5e7 5e7 5e7") + E3 + "fix m4 all property/global characteristicVelocity scalar 200.\n" + HOOKE
  + "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0\n"
  + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\n"
  + "timestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n")

# ---------------------------------------------------------------- n12+: group-based exclusions and walls with groups made before later atoms
deck("n12_exclude_group_then_new_atom", "# group g1 type 1, g2 type 2, neigh_modify exclude group g1 g2; then create_atoms 1 (not in g1): the new type 1 sphere meets type 2\n"
     + BASE() + TWO + "group g1 type 1\ngroup g2 type 2\nneigh_modify exclude group g1 g2\ncreate_atoms 1 single 0.03 0.03 0.01\nset atom 3 diameter 0.004 density 2500\n" + RUN1, g=1)
deck("n13_exclude_group_then_pour", "# exclude group g1 g2 (by type at definition), then fix pour of type 1 (poured atoms in no group): 1 2 happens\n"
     + BASE() + TWO + INS + "group g1 type 1\ngroup g2 type 2\nneigh_modify exclude group g1 g2\nfix p all pour 5 1 4767 region ins diam one 0.004 dens 2500 2500\nrun 200\n", g=1)
deck("n14_wall_group_empty", "# fix wall/gran on group g1 defined (type 1) before any atom exists: the wall acts on nobody\n"
     + head() + G1(HK) + GRAV + "group g1 type 1\n" + f"fix floor g1 wall/gran granular {HK} zplane 0 NULL\n" + TAIL + TWO + RUN1, g=1)
deck("n15_exclude_group_dynamic", "# exclude group of a dynamic group (engine says)\n"
     + BASE() + TWO + "group g1 dynamic all var one\nvariable one atom type==1\ngroup g2 type 2\nneigh_modify exclude group g1 g2\n" + RUN1, g=1)
deck("n16_exclude_type_then_set_type", "# neigh_modify exclude type 1 2; then set atom 1 type 3 (3 types): the 3 2 pair meets\n"
     + base2(nt=3) + TWO + "neigh_modify exclude type 1 2\nset atom 1 type 3\n" + RUN1, g=1)

# ---------------------------------------------------------------- hybrid/scaled, hybrid atom styles in data files, read_dump add, 2d discs
deck("n17_hybrid_scaled_half", "# pair_style hybrid/scaled 0.5 granular: the contact force halved (kn and damping halved): eps changes\n"
     + head() + f"pair_style hybrid/scaled 0.5 granular\npair_coeff * * granular {HK}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("n18_hybrid_scaled_var", "# pair_style hybrid/scaled v_s granular with s equal 2.0\n"
     + head() + f"variable s equal 2.0\npair_style hybrid/scaled v_s granular\npair_coeff * * granular {HK}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
deck("n19_hybrid_scaled_two", "# pair_style hybrid/scaled 1.0 granular 1.0 granular: two granular sub-styles on different pairs\n"
     + head() + f"pair_style hybrid/scaled 0.5 granular 1.0 granular\npair_coeff 1 1 granular 1 {HK}\npair_coeff 1 2 granular 2 {HK}\npair_coeff 2 2 granular 2 {HK}\n" + GRAV + FLOOR + TAIL + TWO + RUN1, g=1)
HYB = "# hybrid\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # hybrid\n\n1 1 0.02 0.02 0.01 0.004 2500 7\n2 2 0.01 0.01 0.01 0.006 7800 8\n"
deck("r15_read_data_hybrid_sphere_molecular", "# atom_style hybrid sphere molecular? (sphere + bond: columns id type x y z diameter density molecule)\n"
     + "units si\natom_style hybrid sphere bond\nboundary p p f\ncomm_modify vel yes\nread_data d.data\n" + G1(HK) + GRAV + FLOOR + TAIL + RUN1, g=1, data={"d.data": HYB})
deck("r16_read_dump_add", "# read_dump of a given dump file adds a type 2 atom (add yes): its size the default (diameter 1?) (engine says)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nread_dump atoms.dump 0 x y z add yes box no\n" + RUN1, g=1,
     data={"atoms.dump": "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z\n5 2 0.01 0.01 0.01\n"})
deck("r17_read_dump_add_then_set", "# read_dump add yes (type 2), then set type 2 diameter 0.006 density 7800\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nread_dump atoms.dump 0 x y z add yes box no\nset type 2 diameter 0.006 density 7800\n" + RUN1, g=1,
     data={"atoms.dump": "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z\n5 2 0.01 0.01 0.01\n"})
deck("r18_read_dump_replace_type", "# read_dump of positions only (no add): moves atom 2 to x 0.03; then set region x>0.025 density 7800\n"
     + BASE() + TWO + "read_dump atoms.dump 0 x y z box no\nregion rt block 0.025 INF INF INF INF INF units box\nset region rt density 7800\n" + RUN1, g=1,
     data={"atoms.dump": "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z\n1 1 0.02 0.02 0.01\n2 2 0.03 0.01 0.01\n"})
D2 = lambda setlines, model=HK: ("units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.001 0.001 units box\ncreate_box 2 box\n"
     + G1(model) + "fix grav all gravity 9.81 vector 0 -1 0\n" + f"fix floor all wall/gran granular {model} yplane 0 NULL\nfix integ all nve/sphere disc\nfix e2 all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\n" + setlines + RUN1)
deck("x01_2d_density_disc", "# 2d: set type density/disc (mass = pi r^2 rho): 4 mm / 6 mm, rho 2500 (areal)\n"
     + D2("set type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density/disc 2500\n"), g=1)
deck("x02_2d_density_plain", "# 2d: set type density (LAMMPS: sphere volume even in 2d?)\n"
     + D2("set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"), g=1)
deck("x03_2d_density_disc_hertz", "# 2d hertz/material with density/disc\n"
     + D2("set type 1 diameter 0.004 density/disc 2500\nset type 2 diameter 0.006 density/disc 2500\n", model=HM), g=1)
deck("x04_2d_read_data", "# 2d read_data Atoms # sphere (density: LAMMPS 2d read_data makes mass from area? engine says)\n"
     + "units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nread_data d.data\n" + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\n"
     + f"fix floor all wall/gran granular {HK} yplane 0 NULL\nfix integ all nve/sphere disc\nfix e2 all enforce2d\ntimestep 1e-5\n" + RUN1, g=1,
     data={"d.data": "# 2d\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.1 ylo yhi\n-0.001 0.001 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.02 0.01 0\n2 2 0.006 2500 0.01 0.01 0\n"})
deck("x05_2d_pour", "# 2d fix pour (discs? engine says) diam one 0.004 dens 2500 2500\n"
     + "units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.001 0.001 units box\ncreate_box 2 box\n"
     + G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\n" + f"fix floor all wall/gran granular {HK} yplane 0 NULL\nfix integ all nve/sphere disc\nfix e2 all enforce2d\ntimestep 1e-5\n"
     + "region ins block 0.005 0.035 0.05 0.09 -0.001 0.001 units box\nfix p all pour 5 1 4767 region ins diam one 0.004 dens 2500 2500\nrun 200\n", g=1)

deck("r19_default_diameter_lost", "# a type 2 sphere of LAMMPS' default diameter 1 m in a 4 cm box (no set): does the engine stop (lost atoms) at the first run? (the read_dump of r16 without read_dump)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\ncreate_atoms 2 single 0.01 0.01 0.01\n" + RUN1, g=1)
deck("r20_read_dump_add_box_yes", "# r16 with the added atom given a size right after (set atom 5 diameter 0.006 density 7800) and read_dump ... add keep\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nread_dump atoms.dump 0 x y z add keep box no\nset atom 5 diameter 0.006 density 7800\n" + RUN1, g=1,
     data={"atoms.dump": "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z\n5 2 0.01 0.01 0.01\n"})

deck("r21_set_z_outside_box", "# set atom 2 z 0.2 (outside the p p f box): LAMMPS loses it at the run's setup (thermo_modify lost error, the default)\n"
     + BASE() + TWO + "set atom 2 z 0.2\n" + RUN1, g=1)
deck("r22_thrown_out_lost_error", "# the type 2 sphere thrown up at 200 m/s in a p p f box, run 1000, thermo 100: LAMMPS stops (Lost atoms) in the run\n"
     + BASE() + TWO + "group t2 type 2\nvelocity t2 set 0 0 200\nthermo 100\nrun 1000\npair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("r23_thrown_out_thermo_0", "# as r22 with thermo 0 (lost atoms only checked at the run's start and end)\n"
     + BASE() + TWO + "group t2 type 2\nvelocity t2 set 0 0 200\nthermo 0\nrun 1000\npair_coeff * * " + hk(5000) + "\nrun 100\n", g=1)
deck("r24_big_default_sphere_type1", "# both types sized, then a third atom of type 1 left at the default diameter 1 (no set after it)\n"
     + BASE() + TWO + "create_atoms 1 single 0.03 0.03 0.05\n" + RUN1, g=1)

L("L36_lost_atom_in_run_liggghts", "# LIGGGHTS: the type 2 sphere thrown up at 200 m/s in the f f f box, run 1000 (LIGGGHTS default: lost atoms error?), then e 0.3, run 100\n"
  + LB() + ATOMS + LRUN + "group up type 2\nvelocity up set 0 0 200\nrun 1000\n" + E3b(0.3) + "run 100\n")
rr("R11_fix_halt_hard", "fix halt 10 v_t > 0.0005 error hard: LAMMPS exits in run 1 (time passes 5e-4 at step 50); pair_coeff kn 5000 after never read",
   "variable t equal time\nfix h all halt 10 v_t > 0.0005 error hard\nrun 100\npair_coeff * * " + hk(5000) + "\nrun 100\n")
rr("R12_fix_halt_soft", "fix halt ... error soft: run 1 ends early, the deck goes on (kn 5000 for run 2)",
   "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\nrun 100\nunfix h\npair_coeff * * " + hk(5000) + "\nrun 100\n")
rr("R13_fix_halt_hard_never", "fix halt with a condition never true (error hard): the deck runs on (kn 5000)",
   "variable t equal time\nfix h all halt 10 v_t > 1.0 error hard\nrun 100\npair_coeff * * " + hk(5000) + "\nrun 100\n")

L("L37_lost_then_new_atom_id_liggghts", "# LIGGGHTS hooke/stiffness (eps depends on masses): the type 2 sphere (id 2) thrown out of the f f f box in run 1 (LIGGGHTS loses it without error), create_atoms 2 (engine id 2 = max+1), set atom 2 density 500\n"
  + lhead() + MAT3 + HS + ATOMS + LRUN + "group up type 2\nvelocity up set 0 0 200\nrun 1000\ncreate_atoms 2 single -0.01 0 0.05 units box\nset atom 2 diameter 0.006 density 500\nrun 100\n")
L("L38_lost_then_set_type_liggghts", "# LIGGGHTS hooke/stiffness: type 2 sphere lost in run 1; the only type 2 pairs left are none; then create_atoms 2 + set type 2 diameter 0.008\n"
  + lhead() + MAT3 + HS + ATOMS + LRUN + "group up type 2\nvelocity up set 0 0 200\nrun 1000\ncreate_atoms 2 single -0.01 0 0.05 units box\nset type 2 diameter 0.008 density 500\nrun 100\n")

# ---------------------------------------------------------------- z*: the working directory changed by shell cd; quoted labels; run_style respa
DATA_RHO = lambda rho: DATA2.format(nt=2).replace("7800", str(rho))
deck("z01_shell_cd_read_data", "# shell cd sub, then read_data d.data: LAMMPS reads sub/d.data (type 2 rho 7800), not ./d.data (rho 1000)\n"
     + "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nshell cd sub\nread_data d.data\n" + G1(HK) + GRAV + FLOOR + TAIL + RUN1, g=1,
     data={"d.data": DATA_RHO(1000), "sub/d.data": DATA_RHO(7800)})
deck("z02_shell_cd_include", "# shell cd sub, include kn.in: LAMMPS reads sub/kn.in (kn 8000), not ./kn.in (kn 3000)\n"
     + BASE() + TWO + "shell cd sub\ninclude kn.in\n" + RUN1, g=1, data={"kn.in": f"pair_coeff * * {hk(3000)}\n", "sub/kn.in": f"pair_coeff * * {hk(8000)}\n"})
deck("z03_shell_cd_file_var", "# shell cd sub, variable kn file kn.txt: LAMMPS reads sub/kn.txt (8000)\n"
     + BASE() + TWO + "shell cd sub\nvariable kn file kn.txt\npair_coeff * * hooke ${kn} 3000 " + K + "\n" + RUN1, g=1, data={"kn.txt": "3000\n", "sub/kn.txt": "8000\n"})
deck("z04_shell_cd_back", "# shell cd sub then shell cd .. then include kn.in: ./kn.in (kn 3000)\n"
     + BASE() + TWO + "shell cd sub\nshell cd ..\ninclude kn.in\n" + RUN1, g=1, data={"kn.in": f"pair_coeff * * {hk(3000)}\n", "sub/kn.in": f"pair_coeff * * {hk(8000)}\n"})
deck("z05_shell_cd_molecule", "# shell cd sub, molecule m1 m1.mol: LAMMPS reads sub/m1.mol (6 mm rho 7800), not ./m1.mol (6 mm rho 1000)\n"
     + BASE() + "create_atoms 1 single 0.02 0.02 0.01\nset type 1 diameter 0.004 density 2500\nshell cd sub\nmolecule m1 m1.mol\ncreate_atoms 0 single 0.01 0.01 0.01 mol m1 1234\n" + RUN1, g=1,
     data={"m1.mol": MOL(2, 0.006, mass(0.006, 1000)), "sub/m1.mol": MOL(2, 0.006, mass(0.006, 7800))})
deck("a13_labelmap_quoted", "# labelmap atom 1 'small' 2 \"big\" (quoted labels); pair_coeff big big 8000\n"
     + BASE() + TWO + "labelmap atom 1 'small' 2 \"big\"\n" + f"pair_coeff big big {hk(8000)}\n" + RUN1, g=1)
rr("R14_run_style_respa", "run_style respa 2 2 (pair on the outer level? engine says)", "run_style respa 2 2\nrun 100\n")
L("L39_shell_cd_include_liggghts", "# LIGGGHTS: shell cd sub, include in.e (sub/in.e: e 0.3; ./in.e: e 0.9)\n"
  + lhead() + MAT3 + E3 + "shell cd sub\ninclude in.e\n" + HERTZ + WALL3 + ATOMS + RUN, data={"in.e": E3b(0.9), "sub/in.e": E3b(0.3)})

# escapes: files a deck writes outside its own folder (the audit must keep them inside its scratch copy)
deck("z06_shell_cd_up_write_data", "# shell cd .. then write_data f23z06.data (LAMMPS writes beside the deck's folder)\n"
     + BASE() + TWO + "shell cd ..\nwrite_data f23z06.data\nshell cd z06_shell_cd_up_write_data\n" + RUN1, g=1)
deck("z07_log_up", "# log ../f23z07.log (a log file outside the deck's folder)\n" + BASE() + TWO + "log ../f23z07.log\n" + RUN1, g=1)
deck("z08_shell_cd_tmp_restart", "# shell cd /tmp then write_restart f23z08.restart\n" + BASE() + TWO + "shell cd /tmp\nwrite_restart f23z08.restart\n" + RUN1, g=1)
deck("z09_fix_print_up", "# fix print 10 to ../f23z09.txt during the run\n" + BASE() + TWO + "fix pr all print 10 \"step $(step)\" file ../f23z09.txt screen no\n" + RUN1, g=1)
deck("z10_write_coeff_up", "# write_coeff ../f23z10.coeff\n" + BASE() + TWO + "write_coeff ../f23z10.coeff\n" + RUN1, g=1)
deck("z11_write_dump_abs", "# write_dump all atom /tmp/f23z11.dump (absolute path)\n" + BASE() + TWO + "write_dump all atom /tmp/f23z11.dump\n" + RUN1, g=1)
deck("z12_shell_mkdir_touch", "# shell mkdir ../f23z12dir and shell touch ../f23z12.txt\n" + BASE() + TWO + "shell mkdir ../f23z12dir\nshell touch ../f23z12.txt\n" + RUN1, g=1)
deck("z13_fix_ave_time_file_up", "# fix ave/time ... file ../f23z13.txt (written during runs); then kn from it? no: just the file\n"
     + BASE() + TWO + "variable one equal 1\nfix av all ave/time 10 1 10 v_one file ../f23z13.txt\n" + RUN1, g=1)

rr("R15_timer_timeout_zero", "timer timeout 0 after run 1 (earlier rounds' class): run 2 makes no step? (engine says)",
   "run 100\ntimer timeout 0\npair_coeff * * " + hk(5000) + "\nrun 100\n")
rr("R16_halt_soft_then_timeout_off", "fix halt error soft in run 1, then timer timeout off: run 2 makes its steps (kn 5000)",
   "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\nrun 100\nunfix h\ntimer timeout off\npair_coeff * * " + hk(5000) + "\nrun 100\n")
rr("R17_halt_soft_three_runs", "fix halt error soft in run 1 (kn 2000), kn 5000 for run 2, kn 8000 for run 3: runs 2 and 3 skipped by LAMMPS",
   "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\nrun 100\nunfix h\npair_coeff * * " + hk(5000) + "\nrun 100\npair_coeff * * " + hk(8000) + "\nrun 100\n")
rr("R18_halt_continue", "fix halt error continue in run 1: the run ends, later runs go on (kn 5000)",
   "variable t equal time\nfix h all halt 10 v_t > 0.0005 error continue\nrun 100\nunfix h\npair_coeff * * " + hk(5000) + "\nrun 100\n")

L("L40_lost_error_liggghts", "# LIGGGHTS thermo_modify lost error, the type 2 sphere thrown out in run 1 (LIGGGHTS stops), then e 0.3 and run 100 (never reached)\n"
  + LB() + ATOMS + LRUN + "thermo_modify lost error\ngroup up type 2\nvelocity up set 0 0 200\nrun 1000\n" + E3b(0.3) + "run 100\n")
rr("R19_halt_tlimit_soft", "fix halt 10 tlimit > 0.0 error soft (wall-clock, met at the first check): later runs skipped",
   "fix h all halt 10 tlimit > 0.0 error soft\nrun 100\nunfix h\npair_coeff * * " + hk(5000) + "\nrun 100\n")
deck("R20_halt_soft_in_include", "# the soft halt set up in an include file (halt.in)\n" + BASE() + TWO + "include halt.in\nrun 100\nunfix h\npair_coeff * * " + hk(5000) + "\nrun 100\n", g=1, data={"halt.in": "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\n"})

rr("R21_timer_timeout_real", "timer timeout 0:00:01 every 100, then run 3000000 (longer than 1 s): LAMMPS ends it at the timeout and skips the later run (kn 5000)",
   "timer timeout 0:00:01 every 100\nrun 3000000\npair_coeff * * " + hk(5000) + "\nrun 100\n")
rr("R22_run_upto_past", "run 200, pair_coeff kn 5000, run 100 upto (the step is past 100: engine says)", "run 200\npair_coeff * * " + hk(5000) + "\nrun 100 upto\n")
rr("R23_run_stop_before_end", "run 100 start 0 stop 50 (engine says)", "pair_coeff * * " + hk(5000) + "\nrun 100 start 0 stop 50\n")
rr("R24_run_zero_between", "run 100 (kn 2000), kn 5000 with run 0, kn 8000 with run 100: the kn 5000 stage makes no step",
   "run 100\npair_coeff * * " + hk(5000) + "\nrun 0\npair_coeff * * " + hk(8000) + "\nrun 100\n")

rr("R25_run_start_after", "run 100 start 200 stop 300 at step 0 (LAMMPS: start after the run's start? engine says)", "pair_coeff * * " + hk(5000) + "\nrun 100 start 200 stop 300\n")
rr("R26_run_float_steps", "run 1e2 (a float step count: engine says)", "pair_coeff * * " + hk(5000) + "\nrun 1e2\n")
rr("R27_run_negative", "run -100 (engine says)", "pair_coeff * * " + hk(5000) + "\nrun -100\n")
rr("R28_run_every_zero", "run 100 every 0 \"print hi\" (engine says)", "pair_coeff * * " + hk(5000) + "\nrun 100 every 0 \"print hi\"\n")
rr("R29_run_bad_keyword", "run 100 pre maybe (engine says)", "pair_coeff * * " + hk(5000) + "\nrun 100 pre maybe\n")
rr("R30_run_upto_past_then_more", "run 200, kn 5000, run 100 upto (LAMMPS stops here), kn 8000, run 100", "run 200\npair_coeff * * " + hk(5000) + "\nrun 100 upto\npair_coeff * * " + hk(8000) + "\nrun 100\n")

# q*: commands the audit's pass does not execute (dump, print, timer, write_*), given arguments LAMMPS refuses
qq = lambda name, comment, line: deck(name, "# " + comment + "\n" + BASE() + TWO + "pair_coeff * * " + hk(5000) + "\n" + line + "\n" + RUN1, g=1)
qq("Q01_dump_every_zero", "dump d all custom 0 f23.dump id (N = 0: LAMMPS stops?)", "dump d all custom 0 f23.dump id type x y z")
qq("Q02_dump_modify_missing", "dump_modify of a dump that does not exist", "dump_modify nod sort id")
qq("Q03_undump_missing", "undump of a dump that does not exist", "undump nod")
qq("Q04_timer_bad", "timer with an unknown keyword", "timer sometimes")
qq("Q05_write_dump_bad_style", "write_dump all nosuchstyle f.txt", "write_dump all nosuchstyle f23.txt")
qq("Q06_print_undefined_var", "print \"${nope}\" (an undefined variable)", "print \"kn is ${nope}\"")
qq("Q07_dump_image_no_jpeg", "dump image (LAMMPS built without JPEG/PNG? engine says)", "dump im all image 100 f23.*.ppm type type")
qq("Q08_print_file_dir_missing", "print ... file nodir/f.txt (a folder that does not exist)", "print \"hi\" file nodir/f23.txt")
qq("Q09_fix_print_bad", "fix print 0 (N = 0)", "fix pr all print 0 \"hi\"")
qq("Q10_dump_bad_column", "dump custom with an unknown column", "dump d all custom 10 f23.dump id nosuchcol")
qq("Q11_thermo_bad_keyword", "thermo_style custom step nosuchkw", "thermo_style custom step nosuchkw")
qq("Q12_write_restart_bad_kw", "write_restart f23.restart nosuchkw", "write_restart f23.restart nosuchkw")
L("L41_run_float_liggghts", "# LIGGGHTS run 1e3 (engine says), e 0.3 before it\n" + LB() + ATOMS + LRUN.replace("", "") + E3b(0.3) + "run 1e3\n")

qq("Q13_log_dir_missing", "log nodir/f23.log (a folder that does not exist)", "log nodir/f23.log")
qq("Q14_echo_bad", "echo sometimes (an illegal echo mode)", "echo sometimes")
qq("Q15_fix_ave_time_file_dir_missing", "fix ave/time ... file nodir/f23.txt", "variable one equal 1\nfix av all ave/time 10 1 10 v_one file nodir/f23.txt")
qq("Q16_restart_dir_missing", "restart 50 nodir/f23.restart (written during the run)", "restart 50 nodir/f23.restart")
qq("Q17_info_bad", "info nosuchcategory", "info nosuchcategory")
qq("Q18_fix_ave_time_bad_nfreq", "fix ave/time 10 3 20 (Nfreq not a multiple of Nevery: LAMMPS stops?)", "variable one equal 1\nfix av all ave/time 10 3 20 v_one")

qq("Q19_jump_missing_label", "jump SELF nolabel (the label does not exist)", "jump SELF nolabel")
qq("Q20_fix_ave_time_missing_compute", "fix ave/time of c_nope (no such compute)", "fix av all ave/time 10 1 10 c_nope")
qq("Q21_fix_print_undefined_var", "fix print 10 \"x ${nope}\" (an undefined variable inside double quotes)", "fix pr all print 10 \"x ${nope}\"")
qq("Q22_thermo_undefined_var", "thermo_style custom step v_nope (checked at the run's setup)", "thermo_style custom step v_nope")
qq("Q23_include_missing", "include nofile.in", "include nofile.in")
qq("Q24_print_immediate_bad", "print \"$(v_nope+1)\" (an immediate of an undefined variable)", "print \"value $(v_nope+1)\"")
L("L42_print_undefined_var_liggghts", "# LIGGGHTS print \"${nope}\" before the run (e 0.3 matrix)\n" + lhead() + MAT3 + E3b(0.3) + HERTZ + WALL3 + ATOMS + "print \"e is ${nope}\"\n" + RUN)
L("L43_dump_every_zero_liggghts", "# LIGGGHTS dump every 0 (e 0.3 matrix)\n" + lhead() + MAT3 + E3b(0.3) + HERTZ + WALL3 + ATOMS + "dump d all custom 0 f23.dump id type x y z\n" + RUN)

# LIGGGHTS: fixes that change a collision (LAMMPS' f* tried above)
LF = lambda name, comment, lines: L(name, "# LIGGGHTS: " + comment + "\n" + LB() + ATOMS + "group t1 type 1\ngroup t2 type 2\n" + lines + RUN)
LF("L44_freeze_type2", "fix freeze on type 2: 1 2 is a sphere on a frozen sphere", "fix fr t2 freeze\n")
LF("L45_viscous_all", "fix viscous 0.001 on all (a drag)", "fix vs all viscous 0.001\n")
LF("L46_setforce_type2", "fix setforce 0 0 0 on type 2", "fix sf t2 setforce 0.0 0.0 0.0\n")
LF("L47_addforce_type1", "fix addforce 0.01 0 0 on type 1", "fix af t1 addforce 0.01 0.0 0.0\n")
LF("L48_langevin", "fix langevin 0 0 0.001", "fix lv all langevin 0.0 0.0 0.001 48279\n")
L("L49_nve_sphere_subgroup", "# LIGGGHTS: nve/sphere on type 1 only (type 2 never moves)\n"
  + LB() + ATOMS + "group t1 type 1\ntimestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr t1 nve/sphere\nrun 1000\n")

ee("e19_dynamic_group_var", "group up dynamic all var up every 10 (z > 0.005); run 5000 (both fall); set group up density 7800 (none in the engine)",
   "variable up atom z>0.005\ngroup up dynamic all var up every 10\nrun 5000\nset group up density 7800\nrun 100\n")
ee("e20_lost_warn_set_atom", "thermo_modify lost warn; type 2 thrown out; create_atoms 2 (engine id 2); set atom 2 diameter 0.006 density 1000",
   "thermo_modify lost warn\ngroup t2 type 2\nvelocity t2 set 0 0 100\nrun 300\ncreate_atoms 2 single 0.01 0.01 0.05\nset atom 2 diameter 0.006 density 1000\nrun 100\n")
ee("e21_quit_in_run_every", "run 100 every 50 \"quit\" (LAMMPS quits at step 50); kn 5000 after never read", "run 100 every 50 \"quit\"\npair_coeff * * " + hk(5000) + "\nrun 100\n")
ee("e22_partition_yes_1", "partition yes 1 pair_coeff kn 5000 (one partition: LAMMPS runs it)", "partition yes 1 pair_coeff * * " + hk(5000) + "\nrun 100\n")
ee("e23_dollar_format_in_set", "set type 2 density $(7800:%.0f)", "set type 2 density $(7800:%.0f)\nrun 100\n")
ee("e24_restyle_wall_region", "unfix floor; fix floor wall/gran/region granular kn 8000 on a plane region", "unfix floor\nregion pl plane 0 0 0 0 0 1 side in units box\nfix floor all wall/gran/region granular " + hk(8000) + " region pl\nrun 100\n")

qq("Q25_pair_write_granular", "pair_write 1 1 100 r 0.001 0.01 f23.table GRAN (pair granular may not support it: engine says)", "pair_write 1 1 100 r 0.001 0.01 f23.table GRAN")
qq("Q26_rerun_missing_dump", "rerun of a dump file that does not exist", "rerun nodump.txt dump x y z")
qq("Q27_python_command", "python source inline (LAMMPS built without Python?)", "python source here \"print(1)\"")
qq("Q28_plugin_load_missing", "plugin load of a missing library", "plugin load nosuch.so")
qq("Q29_fix_plumed", "fix plumed (package absent?)", "fix pl all plumed plumedfile plumed.dat outfile p.log")
qq("Q30_fix_ttm_bad", "fix ttm with too few arguments", "fix tt all ttm 4711")
qq("Q31_balance_bad", "balance with an unknown style", "balance 1.1 nosuchstyle")
qq("Q32_group2ndx", "group2ndx f23.ndx (a package command: engine says)", "group2ndx f23.ndx")
qq("Q33_write_data_bad_kw", "write_data f23.data nosuchkw", "write_data f23.data nosuchkw")
qq("Q34_restart_bad_args", "restart 0 then restart with a bad keyword", "restart 100 f23.restart nosuchkw")

kk("k21_fix_adapt_pair_granular", "fix adapt 1 pair granular kn ... (not supported by pair granular? engine says)", BASE() + TWO + "variable k equal 5000\nfix ad all adapt 1 pair granular kn * * v_k\n" + RUN1)
kk("k22_negative_kn", "hooke -2000 3000 (engine says)", BASE() + TWO + f"pair_coeff * * hooke -2000 3000 {K}\n" + RUN1)
kk("k23_negative_damping", "hooke 2000 -3000 (negative damping: engine says)", BASE() + TWO + f"pair_coeff * * hooke 2000 -3000 {K}\n" + RUN1)
kk("k24_hertz_tsuji", "hertz kn 1e6 damping tsuji 0.5", BASE("hertz 1e6 0.5 damping tsuji " + TL) + TWO + RUN1)
kk("k25_zero_damping", "hooke 2000 0 (no damping: eps 1)", BASE(f"hooke 2000 0 {K}") + TWO + RUN1)

qq("Q35_if_print_undefined", "if \"1 > 0\" then \"print '${nope}'\" (the branch LAMMPS runs prints an undefined variable)", "if \"1 > 0\" then \"print '${nope}'\"")
qq("Q36_print_divide_zero", "print \"$(1/0)\" (LAMMPS: divide by 0 in variable formula)", "print \"value $(1/0)\"")
L("L50_run_stop_before_end_liggghts", "# LIGGGHTS run 1000 start 0 stop 500 (engine says), e 0.3 before it\n" + LB() + ATOMS + LRUN + E3b(0.3) + "run 1000 start 0 stop 500\n")
L("L51_run_negative_liggghts", "# LIGGGHTS run -100 (engine says), e 0.3 before it\n" + LB() + ATOMS + LRUN + E3b(0.3) + "run -100\n")


if __name__ == "__main__":
    kit.main(sys.argv[1:])
