"""Field round 47a: public CFDEM-coupling DEM decks (LIGGGHTS), copied at run time into decks/<ID>/ in their
repository layout (the tutorial's DEM folder, and the folders beside it that the deck names), text not committed
(.gitignore; SOURCES names repository, commit, path). Forms:
  AS   as published, every `run N` made `run 20` (the rest of the line kept); edits, where any, named in SOURCES
       (the `processors` line dropped where it asks for more than one process, except in the folders that keep it);
  PAIR the deck's own lines with insertion, runs, dumps, loops, restarts and coupling removed, then two of its
       own spheres approaching head-on at relative speed V along x, far from its walls (REF prints the eps);
  FLOOR the same head, one sphere of the deck dropped on its floor at 1 m/s (REF: sqrt(vz^2+2g h)/V).
usage: MIRRORS=DIR python make47.py restart   (DIR holds the fetched mirrors, owner+name/repo)"""
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
MIR = os.environ.get("MIRRORS", ".") + "/"  # the folder holding the fetched mirrors (owner+name/repo)
REPOS = {
    "PUB": ("CFDEMproject/CFDEMcoupling-PUBLIC", MIR + "CFDEMproject+CFDEMcoupling-PUBLIC/repo"),
    "PFM": ("ParticulateFlow/CFDEMcoupling-PFM", MIR + "ParticulateFlow+CFDEMcoupling-PFM/repo"),
    "ABH": ("abhirup-roy/cfdem-fl-bed-cases", MIR + "abhirup-roy+cfdem-fl-bed-cases/repo"),
    "ZCL": ("zclk9000/cfdem_packing_density", MIR + "zclk9000+cfdem_packing_density/repo"),
}


def git(gd, *a):
    return subprocess.run(["git", "--git-dir", gd] + list(a), capture_output=True, check=True).stdout


def commit(key):
    return git(REPOS[key][1], "rev-parse", "HEAD").decode().strip()


def shorten(t):
    return re.sub(r"(?m)^(\s*run\s+)(\d+)", lambda m: m.group(1) + "20", t)


def noproc(t):
    return re.sub(r"(?m)^\s*processors\s.*\n", "", t)


def sub(a, b):
    return lambda t: t.replace(a, b)


DROP = re.compile(r"^\s*(run|dump|undump|write_restart|read_restart|label|if|jump|unfix|delete_atoms|write_dump|"
                  r"set\s+region|restart|processors|fix\s+\S+\s+\S+\s+(insert/\S+|particletemplate/\S+|particledistribution/\S+|"
                  r"couple/\S+|print|ave/\S+|check/timestep/gran|nve/sphere|buoyancy|massflow/\S+|"
                  r"property/atom/polydispparcel)|region\s+\S+\s+delete|group\s+\S+\s+region|"
                  r"compute\s+\S+\s+\S+\s+reduce|variable\s+\S+\s+equal\s+.*(c_|f_|count)|thermo_style|thermo\b|print\b)")


def reduce_(t):
    """Drop insertion, runs, dumps, loops, restarts, coupling and integration lines (with & continuations)."""
    out, skip = [], False
    for l in t.split("\n"):
        l += "\n"
        if skip:
            skip = l.rstrip().endswith("&"); continue
        if DROP.match(l):
            skip = l.rstrip().endswith("&"); continue
        out.append(l)
    return "".join(out)


def upto(pat):
    def f(t):
        ls = t.split("\n")
        for i, l in enumerate(ls):
            if re.match(pat, l):
                return "\n".join(ls[:i + 1]) + "\n"
        raise SystemExit("no line " + pat)
    return f


def pair(x, y, z, d, rho, V=1.0, t1=1, t2=1, n=2000, dt=None):
    h = d / 2 + d / 20  # gap d/10 at the start
    s = (f"\nneigh_modify delay 0\n" + (f"timestep {dt}\n" if dt else "") +
         f"create_atoms {t1} single {x - h:.9g} {y} {z} units box\ncreate_atoms {t2} single {x + h:.9g} {y} {z} units box\n"
         f"set atom 1 diameter {d} density {rho}\nset atom 2 diameter {d} density {rho}\n"
         f"group p1 id 1\ngroup p2 id 2\nvelocity p1 set {V / 2} 0 0\nvelocity p2 set {-V / 2} 0 0\n"
         f"fix f47int all nve/sphere\nrun {n}\n")
    ref = f'variable P47 equal (vx[2]-vx[1])/{V}\nvariable G47 equal x[2]-x[1]-{d}\nprint "PUB47 eps ${{P47}} gap ${{G47}}"\n'
    return s, ref


def floor(x, y, zf, d, rho, V=1.0, g=9.81, t1=1, n=3000, dt=None):
    r = d / 2
    z = zf + r + d / 20
    vz = -(V * V - 2 * g * (d / 20)) ** 0.5
    s = ("\nneigh_modify delay 0\n" + (f"timestep {dt}\n" if dt else "") +
         f"create_atoms {t1} single {x} {y} {z:.9g} units box\nset atom 1 diameter {d} density {rho}\n"
         f"group p1 id 1\nvelocity p1 set 0 0 {vz:.10f}\nfix f47int all nve/sphere\nrun {n}\n")
    ref = (f'variable P47 equal sqrt(vz[1]^2+2*{g}*(z[1]-{zf + r}))/{V}\n'
           f'print "PUB47 eps ${{P47}} vz $(vz[1]) h $(z[1]-{zf + r})"\n')
    return s, ref


PRIMES = [15485863, 15485867, 32452843, 32452867, 49979687, 49979693, 67867967, 67867979, 86028121, 86028157]


def primes(t):
    """The edit LIGGGHTS-PUBLIC needs: every template, distribution and insertion seed made a prime above 10000."""
    k = iter(PRIMES)
    t = re.sub(r"(particletemplate/\S+\s+)(\S+)", lambda m: m.group(1) + str(next(k)), t)
    t = re.sub(r"(particledistribution/discrete\s+)(\S+)", lambda m: m.group(1) + str(next(k)), t)
    return re.sub(r"(\bseed\s+)(\d+)", lambda m: m.group(1) + str(next(k)), t)


def soft(t):
    """LIGGGHTS-PUBLIC wants youngsModulus >= 5e6 in si units unless `soft_particles yes` (PFM does not ask)."""
    return "soft_particles yes\n" + t


def hist(t):
    return t.replace("incremental_history", "history")


def dropl(pat):
    return lambda t: re.sub(r"(?m)^\s*" + pat + r".*\n", "", t)


T = "tutorials/"
ERG = T + "cfdemSolverPiso/ErgunTestMPI/"
# ID: (repo, tutorial dir (copied: its DEM folders), deck path inside it, edits, (tail, ref) or None, meta)
D = {}


def add(i, key, top, deck, edits, tail=None, **meta):
    D[i] = (key, top, deck, edits, tail, meta)


# --- as published, runs cut to 20 steps
add("A01_pub_ergun_init", "PUB", ERG, "DEM/in.liggghts_init", [shorten])
add("A02_pub_ergun_cgs_init", "PUB", T + "cfdemSolverPiso/ErgunTestMPI_cgs/", "DEM/in.liggghts_init", [shorten])
add("A03_pub_packedbedtemp_init", "PUB", T + "cfdemSolverPisoScalar/packedBedTemp/", "DEM/in.liggghts_init", [shorten, noproc])
add("A04_pub_fillcylinder_init", "PUB", T + "cfdemPostproc/fillCylinder/", "DEM/in.liggghts_init", [shorten, noproc])
add("A05_pub_periodicchannel_init", "PUB", T + "cfdemSolverPiso/periodicChannel/", "DEM/in.liggghts_init", [shorten, noproc])
add("A06_pub_settling_run", "PUB", T + "cfdemSolverPiso/settlingTestMPI/", "DEM/in.liggghts_run", [shorten, noproc])
add("A07_pub_twospheres_run", "PUB", T + "cfdemSolverIB/twoSpheresGlowinskiMPI/", "DEM/in.liggghts_run", [shorten, noproc])
add("A08_pub_voidfraction_run", "PUB", T + "cfdemSolverPiso/voidfractionTest/", "DEM/in.liggghts_run", [shorten, noproc])
add("A09_pfm_smallhearth_init", "PFM", T + "cfdemSolverMultiphaseScalar/small_hearth/", "DEM/in.liggghts_init", [shorten, noproc])
add("A10_pfm_dambreak_init", "PFM", T + "cfdemSolverMultiphase/damBreak/", "DEM/in.liggghts_init", [shorten, noproc])
add("A11_pfm_waterentry_init", "PFM", T + "cfdemSolverMultiphase/particlesWaterEntry/", "DEM/in.liggghts_init", [shorten, noproc])
add("A12_pfm_tankdrainage_init", "PFM", T + "cfdemSolverMultiphase/tankDrainage/", "DEM/in.liggghts_init", [shorten, noproc])
add("A13_pfm_periodicbox_init", "PFM", T + "cfdemSolverPimple/PeriodicBox/", "DEM/in.liggghts_init", [shorten, noproc])
add("A14_pfm_bubblingfb_init", "PFM", T + "cfdemSolverPiso/bubblingFluidizedBed/", "DEM/in.liggghts_init", [shorten, noproc])
add("A15_pfm_erguncg_init", "PFM", T + "cfdemSolverPiso/ErgunTestCG/", "DEM/in.liggghts_init", [shorten, noproc])
add("A16_pfm_rbc_poiseuille_init", "PFM", T + "cfdemSolverIBContinuousForcing/redBloodCellPoiseuilleFlow/", "DEM/in.liggghts_init", [shorten, noproc])
add("A17_pfm_finescolumn_kinetic_init", "PFM", T + "cfdemSolverRhoPimple/FinesColumnKinetic/", "DEM/in.liggghts_init", [shorten, noproc])
add("A18_pfm_finescolumn_sticky_bidisperse_init", "PFM", T + "cfdemSolverRhoPimple/FinesColumnStickyBidisperse/", "DEM/in.liggghts_init", [shorten, noproc])
add("A19_pfm_hoppertracer_init", "PFM", T + "rcfdemSolverBase/HopperTracer/", "DEM/in.liggghts_init", [shorten, noproc])
add("A20_pfm_polydisperse_fb_r1_init", "PFM", T + "cfdemSolverRhoPimpleChem/PolydisperseFluidizedBed/R1_FB/", "DEM/in.liggghts_init", [shorten, noproc])
add("A21_pfm_iso4695_init", "PFM", T + "cfdemSolverRhoPimpleChem/SingleParticleCases/ISO4695/", "DEM/in.liggghts_init", [shorten, noproc])
add("A22_pfm_hotblast_fill", "PFM", T + "rcfdemSolverRhoSteadyPimple/hotBlastFurnaceSlot/", "initLayerStructure/DEM/in.liggghts_fill", [shorten, noproc])
add("A23_pfm_heattransfer_ranzmarshall_run", "PFM", T + "cfdemSolverRhoPimple/HeatTransferRanzMarshall/", "DEM/in.liggghts_run", [shorten, noproc])
add("A24_pfm_vortexshedding_run", "PFM", T + "cfdemSolverRhoPimple/VortexShedding/", "DEM/in.liggghts_run", [shorten, noproc])
add("A25_pfm_fallingsphere_run", "PFM", T + "cfdemSolverIB/falling_sphere_two_way_coupling/", "DEM/in.liggghts_run", [shorten, noproc])
add("A26_pfm_heatsources_db1_run", "PFM", T + "rcfdemSolverCoupledHeatTransfer/FluidizedBed_HeatSources/db1/", "DEM/in.liggghts_run", [shorten, noproc])
add("A27_abh_main_init", "ABH", "", "DEM/in.liggghts_init", [shorten, noproc])
add("A28_abh_jkr_init", "ABH", "", "templates/jkr/in.liggghts_init", [shorten, noproc])
add("A29_abh_sjkr_init", "ABH", "", "templates/sjkr/in.liggghts_init", [shorten, noproc])
add("A30_zcl_packing_init", "ZCL", "", "DEM/in.liggghts_init", [shorten, noproc])
add("A31_pub_parscale_packedbed_init", "PUB", T + "ParScale/cfdemSolverPisoSTM/packedBedTempParScale/", "DEM/in.liggghts_init", [shorten, noproc])
add("A32_pfm_rbc_shear_init", "PFM", T + "cfdemSolverIBContinuousForcing/redBloodCellShearFlow/", "DEM/in.liggghts_init", [shorten, noproc])
add("A33_pfm_hotblast_cfddem", "PFM", T + "rcfdemSolverRhoSteadyPimple/hotBlastFurnaceSlot/", "CFDDEM/DEM/in.liggghts_CFDDEM", [shorten, noproc])
add("A34_pfm_smallhearth_keepproc", "PFM", T + "cfdemSolverMultiphaseScalar/small_hearth/", "DEM/in.liggghts_init", [shorten])

# --- reduced to a pair (the deck's own material/contact lines; two of its spheres head-on) or a floor drop
SH = T + "cfdemSolverMultiphaseScalar/small_hearth/"
HT = T + "rcfdemSolverBase/HopperTracer/"
FK = T + "cfdemSolverRhoPimple/FinesColumnKinetic/"
DB = T + "rcfdemSolverCoupledHeatTransfer/FluidizedBed_HeatSources/db1/"
add("P01_ergun_pair", "PUB", ERG, "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.03, 0.001, 2000, n=400))
add("P02_ergun_floor", "PUB", ERG, "DEM/in.liggghts_init", [reduce_], floor(0, 0, 0.0, 0.001, 2000, n=2000))
add("P03_ergun_cgs_pair", "PUB", T + "cfdemSolverPiso/ErgunTestMPI_cgs/", "DEM/in.liggghts_init", [reduce_],
    pair(0, 0, 3.0, 0.1, 2.0, V=100.0, n=400))
add("P04_ergun_cgs_floor", "PUB", T + "cfdemSolverPiso/ErgunTestMPI_cgs/", "DEM/in.liggghts_init", [reduce_],
    floor(0, 0, 0.0, 0.1, 2.0, V=100.0, g=981.0, n=2000))
add("P05_smallhearth_pair", "PFM", SH, "DEM/in.liggghts_init", [upto(r"\s*include\s+in\.raceways"), reduce_],
    pair(0.3, 0, 0.5, 0.02, 900, n=400))
add("P06_smallhearth_floor_stl", "PFM", SH, "DEM/in.liggghts_init", [upto(r"\s*include\s+in\.raceways"), reduce_],
    floor(0.3, 0, 0.0, 0.02, 900, n=400))
add("P07_periodicbox_pair", "PFM", T + "cfdemSolverPimple/PeriodicBox/", "DEM/in.liggghts_init", [reduce_, hist, soft],
    pair(0, 0, 0.008, 7.5e-5, 1500, n=200))
add("P08_bubblingfb_pair_12", "PFM", T + "cfdemSolverPiso/bubblingFluidizedBed/", "DEM/in.liggghts_init", [reduce_],
    pair(0.0216, 0.005, 0.06, 0.0012, 1000, t1=1, t2=2, n=400))
add("P09_hoppertracer_pair_11_excluded", "PFM", HT, "DEM/in.liggghts_init", [reduce_, dropl(r"fix\s+\S+\s+all\s+balance")], pair(0, 0, 0.4, 0.002, 2500, n=600))
add("P10_hoppertracer_pair_22_kn0", "PFM", HT, "DEM/in.liggghts_init", [reduce_, dropl(r"fix\s+\S+\s+all\s+balance")], pair(0, 0, 0.4, 0.002, 2500, t1=2, t2=2, n=600))
add("P11_hoppertracer_floor_plug", "PFM", HT, "DEM/in.liggghts_init", [reduce_, dropl(r"fix\s+\S+\s+all\s+balance")], floor(0, 0, 0.0, 0.002, 2500, n=2000))
add("P12_finescolumn_pair", "PFM", FK, "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.3, 0.00368, 1732, n=200))
add("P13_finescolumn_floor", "PFM", FK, "DEM/in.liggghts_init", [reduce_], floor(0, 0, 0.0, 0.00368, 1732, n=2000))
add("P14_heatsources_pair", "PFM", DB, "DEM/in.liggghts_run", [reduce_], pair(0, 0, 0.2, 0.00099, 667, n=300))
add("P15_heatsources_floor", "PFM", DB, "DEM/in.liggghts_run", [reduce_], floor(0, 0, 0.0, 0.00099, 667, n=3000))
add("P16_zcl_pair_12", "ZCL", "", "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.5, 0.02, 2500, t1=1, t2=2, n=600))
add("P17_zcl_pair_22", "ZCL", "", "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.5, 0.02, 2500, t1=2, t2=2, n=600))
add("P18_abh_sjkr_pair", "ABH", "", "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.2, 0.000366, 1109, n=1000))
add("P19_polydisperse_pair_12_gravity_y", "PFM", T + "cfdemSolverRhoPimpleChem/PolydisperseFluidizedBed/R1_FB/", "DEM/in.liggghts_init",
    [reduce_, dropl("coarsegraining")], pair(0, 0.07, 0, 0.0005, 2630, t1=1, t2=2, n=400))
add("P20_iso4695_pair_dt1e-2", "PFM", T + "cfdemSolverRhoPimpleChem/SingleParticleCases/ISO4695/", "DEM/in.liggghts_init",
    [reduce_, lambda t: re.sub(r"(?m)^(create_atoms|set atom).*\n", "", t)], pair(0.75, 0.25, 0.25, 0.05, 2000, n=50))
add("P21_twospheres_pair_g981", "PUB", T + "cfdemSolverIB/twoSpheresGlowinskiMPI/", "DEM/in.liggghts_run",
    [reduce_, lambda t: re.sub(r"(?m)^(create_atoms|set atom).*\n", "", t)], pair(0.5, 0.5, 2.0, 0.167, 1.5, n=1000))
add("P22_erguncg_pair", "PFM", T + "cfdemSolverPiso/ErgunTestCG/", "DEM/in.liggghts_init", [reduce_, dropl("coarsegraining")], pair(0, 0, 0.03, 0.001, 2000, n=400))
add("P23_dambreak_floor", "PFM", T + "cfdemSolverMultiphase/damBreak/", "DEM/in.liggghts_init", [reduce_], floor(0.05, 0.05, 0.0, 0.004, 2500, n=2000))
add("P25_periodicbox_floor_limitforce_pair_only", "PFM", T + "cfdemSolverPimple/PeriodicBox/", "DEM/in.liggghts_init", [reduce_, hist, soft],
    floor(0, 0, 0.0, 7.5e-5, 1500, n=4000))
RBC = T + "cfdemSolverIBContinuousForcing/redBloodCellPoiseuilleFlow/"
RBCED = [reduce_, lambda t: re.sub(r"(?m)^atom_style.*$", "atom_style  granular", t),
         dropl(r"(bond_style|bond_coeff|neigh_modify\s+exclude)"),
         lambda t: re.sub(r"(?m)^compute\s+b1[^\n]*&\n(?:[^\n]*&\n)*[^\n]*\n", "", t)]
add("P26_rbc_micro_pair_12_e1e-3", "PFM", RBC, "DEM/in.liggghts_init", RBCED, pair(0, 0, 45, 3.91, 1.098, t1=1, t2=2, n=3000))
add("P27_rbc_micro_pair_11_e1e-6", "PFM", RBC, "DEM/in.liggghts_init", RBCED, pair(0, 0, 45, 3.91, 1.098, n=3000))
add("P28_rbc_micro_pair_12_run_deck_e", "PFM", RBC, "DEM/in.liggghts_init",
    RBCED + [sub("peratomtypepair 2 1e-06 1e-03 1e-03 1e-06", "peratomtypepair 2 0.9 0.85 0.85 0.9")],
    pair(0, 0, 45, 3.91, 1.098, t1=1, t2=2, n=3000))
add("P29_rbc_micro_pair_12_run_deck_e_no_thermo_log", "PFM", RBC, "DEM/in.liggghts_init",
    RBCED + [sub("peratomtypepair 2 1e-06 1e-03 1e-03 1e-06", "peratomtypepair 2 0.9 0.85 0.85 0.9"), dropl("thermo_log")],
    pair(0, 0, 45, 3.91, 1.098, t1=1, t2=2, n=3000))

def cyl(R, z, d, rho, n):
    """One sphere moving radially (+x) at 1 m/s into a zcylinder wall of radius R from inside (gap d/20)."""
    x = R - d / 2 - d / 20
    s = (f"\nneigh_modify delay 0\ncreate_atoms 1 single {x:.9g} 0 {z} units box\nset atom 1 diameter {d} density {rho}\n"
         f"group p1 id 1\nvelocity p1 set 1 0 0\nfix f47int all nve/sphere\nrun {n}\n")
    return s, 'variable P47 equal -vx[1]\nprint "PUB47 eps ${P47} x $(x[1])"\n'


add("P30_ergun_cylinder_wall", "PUB", ERG, "DEM/in.liggghts_init", [reduce_], cyl(0.01385, 0.03, 0.001, 2000, 200))
add("P31_finescolumn_cylinder_wall", "PFM", FK, "DEM/in.liggghts_init", [reduce_], cyl(0.05, 0.3, 0.00368, 1732, 100))
add("P24_fillcylinder_pair", "PFM", T + "cfdemPostproc/fillCylinder/", "DEM/in.liggghts_init", [reduce_], pair(0, 0, 0.03, 0.001, 2000, n=400))

# --- B: as published with the edits LIGGGHTS-PUBLIC needs (seeds made primes above 10000; incremental_history ->
# history; the PFM-only `coarsegraining` and `fix balance` lines dropped), every run 20 steps
add("B01_pfm_dambreak_init_primes", "PFM", T + "cfdemSolverMultiphase/damBreak/", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B02_pfm_tankdrainage_init_primes", "PFM", T + "cfdemSolverMultiphase/tankDrainage/", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B03_pfm_bubblingfb_init_primes", "PFM", T + "cfdemSolverPiso/bubblingFluidizedBed/", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B04_pfm_finescolumn_kinetic_init_primes", "PFM", FK, "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B05_pfm_finescolumn_sticky_bidisperse_init_primes", "PFM", T + "cfdemSolverRhoPimple/FinesColumnStickyBidisperse/", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B06_pfm_hoppertracer_init_primes", "PFM", HT, "DEM/in.liggghts_init", [shorten, noproc, primes, dropl(r"fix\s+\S+\s+all\s+balance")])
add("B07_pfm_heatsources_db1_run_primes", "PFM", DB, "DEM/in.liggghts_run", [shorten, noproc, primes])
add("B08_zcl_packing_init_primes", "ZCL", "", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B09_pfm_periodicbox_init_history", "PFM", T + "cfdemSolverPimple/PeriodicBox/", "DEM/in.liggghts_init", [shorten, noproc, hist, primes, soft])
add("B10_pfm_vortexshedding_run_history", "PFM", T + "cfdemSolverRhoPimple/VortexShedding/", "DEM/in.liggghts_run", [shorten, noproc, hist])
add("B11_pfm_erguncg_init_nocg", "PFM", T + "cfdemSolverPiso/ErgunTestCG/", "DEM/in.liggghts_init", [shorten, noproc, dropl("coarsegraining"), primes])
add("B12_pfm_polydisperse_fb_r1_init_nocg", "PFM", T + "cfdemSolverRhoPimpleChem/PolydisperseFluidizedBed/R1_FB/", "DEM/in.liggghts_init", [shorten, noproc, dropl("coarsegraining"), primes])
add("B13_pfm_waterentry_init_primes", "PFM", T + "cfdemSolverMultiphase/particlesWaterEntry/", "DEM/in.liggghts_init", [shorten, noproc, primes])
add("B14_pfm_hotblast_fill_primes", "PFM", T + "rcfdemSolverRhoSteadyPimple/hotBlastFurnaceSlot/", "initLayerStructure/DEM/in.liggghts_fill", [shorten, noproc, primes])


def write():
    rows = []
    for name, (key, top, deck, edits, tail, meta) in D.items():
        repo, gd = REPOS[key]
        c = commit(key)
        d = os.path.join(HERE, "decks", name)
        os.makedirs(d, exist_ok=True)
        files = git(gd, "ls-tree", "-r", "--name-only", c, *([top] if top else [])).decode().split("\n")
        for f in files:
            rel = f[len(top):]
            if not f or not re.match(r"^(DEM|CFDDEM/DEM|initLayerStructure/DEM|dataDrivenCFD/DEM|templates/\w+)/", rel):
                continue
            if re.search(r"(^|/)post/|dump|\.vtk$|\.m$|restart", rel):
                continue
            try:
                data = git(gd, "show", f"{c}:{f}")
            except subprocess.CalledProcessError:
                continue  # not stored (large file)
            t = os.path.join(d, rel)
            os.makedirs(os.path.dirname(t), exist_ok=True)
            open(t, "wb").write(data)
        ddir = os.path.dirname(os.path.join(d, deck))
        for p in ("post/restart", "../log"):
            os.makedirs(os.path.join(ddir, p), exist_ok=True)
        text = open(os.path.join(d, deck), encoding="latin-1").read()
        for e in edits:
            text = e(text)
        if tail:
            text = text + tail[0]
            open(os.path.join(d, "REF"), "w").write(tail[1])
        open(os.path.join(d, deck), "w", encoding="latin-1").write(text)
        open(os.path.join(d, "DECK"), "w").write(deck + "\n")
        open(os.path.join(d, "LIGGGHTS"), "w").write("\n")
        open(os.path.join(d, "G"), "w").write((("100 200" if "cgs" in name else "1 2") if tail else ("981" if "cgs" in name else "9.81")) + "\n")
        rows.append(f"{name:42s} {repo} {c[:12]} {top}{deck}")
    print("\n".join(rows))


if __name__ == "__main__":
    write()


# --- restart forms (R): the run deck as published reads the restart that its own init deck (run first by LIGGGHTS,
# when the folder is made: `python make47.py restart`) writes; R03/R04: the init deck reduced to the pair, cut 5 steps
# after the start (the spheres not yet touching) and written to the restart, then the run deck with `run 0` made
# `run 400` (its own materials, walls, coupling fixes), REF measuring the pair.
RUNS = {
    "R01_pub_ergun_run_restart": ("PUB", ERG, "DEM/in.liggghts_run", [shorten, noproc], None, "INIT"),
    "R03_pub_ergun_run_restart_pair": ("PUB", ERG, "DEM/in.liggghts_run", [noproc, sub("run             0", "run 400")],
                                       pair(0, 0, 0.03, 0.001, 2000, n=400)[1], "P01_ergun_pair"),
    "R04_pub_ergun_cgs_run_restart_pair": ("PUB", T + "cfdemSolverPiso/ErgunTestMPI_cgs/", "DEM/in.liggghts_run",
                                           [noproc, lambda t: re.sub(r"(?m)^run\s+1\s*$", "run 400", t)],
                                           pair(0, 0, 3.0, 0.1, 2.0, V=100.0, n=400)[1], "P03_ergun_cgs_pair"),
    # R05 R06: R03 R04 without the coupling fixes and the lines that read them (the restart read kept)
    "R05_pub_ergun_run_restart_pair_nocfd": ("PUB", ERG, "DEM/in.liggghts_run", [noproc, sub("run             0", "run 400"),
        dropl(r"(dump\s|fix\s+\S+\s+all\s+couple|compute\s+explDrag|variable\s+\S+\s+equal\s+(f_cfd|c_explDrag)|fix\s+extra|thermo_style)")],
        pair(0, 0, 0.03, 0.001, 2000, n=400)[1], "P01_ergun_pair"),
    "R06_pub_ergun_cgs_run_restart_pair_nocfd": ("PUB", T + "cfdemSolverPiso/ErgunTestMPI_cgs/", "DEM/in.liggghts_run",
        [noproc, lambda t: re.sub(r"(?m)^run\s+1\s*$", "run 400", t),
         dropl(r"(dump\s|fix\s+\S+\s+all\s+couple|variable\s+\S+\s+equal\s+f_cfd|thermo_style)")],
        pair(0, 0, 3.0, 0.1, 2.0, V=100.0, n=400)[1], "P03_ergun_cgs_pair"),
}


def restart():
    import shutil
    for name, (key, top, deck, edits, ref, init) in RUNS.items():
        repo, gd = REPOS[key]
        c = commit(key)
        d = os.path.join(HERE, "decks", name)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(os.path.join(d, "DEM", "post", "restart"))
        for f in git(gd, "ls-tree", "-r", "--name-only", c, top + "DEM").decode().split():
            rel = f[len(top):]
            if re.search(r"(^|/)post/|dump|restart", rel):
                continue
            open(os.path.join(d, rel), "wb").write(git(gd, "show", f"{c}:{f}"))
        if init == "INIT":
            prep = shorten(noproc(open(os.path.join(d, "DEM/in.liggghts_init"), encoding="latin-1").read()))
        else:
            prep = open(os.path.join(HERE, "decks", init, "DEM/in.liggghts_init"), encoding="latin-1").read()
            prep = re.sub(r"(?m)^run \d+\s*$", "run 5\nwrite_restart post/restart/liggghts.restart", prep)
        open(os.path.join(d, "DEM", "prep.in"), "w").write(prep)
        subprocess.run(["liggghts", "-in", "prep.in", "-log", "none"], cwd=os.path.join(d, "DEM"), capture_output=True,
                       timeout=300, stdin=subprocess.DEVNULL)
        os.remove(os.path.join(d, "DEM", "prep.in"))
        for f in os.listdir(os.path.join(d, "DEM", "post")):
            if f != "restart":
                os.remove(os.path.join(d, "DEM", "post", f))
        text = open(os.path.join(d, deck), encoding="latin-1").read()
        for e in edits:
            text = e(text)
        open(os.path.join(d, deck), "w", encoding="latin-1").write(text)
        if ref:
            open(os.path.join(d, "REF"), "w").write(ref)
        for k, v in (("DECK", deck), ("LIGGGHTS", ""), ("G", ("100 200" if "cgs" in name else "1 2") if ref else ("981" if "cgs" in name else "9.81"))):
            open(os.path.join(d, k), "w").write(v + "\n")
        print(f"{name:42s} {repo} {c} {top}{deck} (+ the restart its init deck writes: {init})")


if __name__ == "__main__" and len(__import__("sys").argv) > 1:
    restart()
