"""The deck-writing helpers of field rounds 21-28 (round 23's make_decks23.py, which rounds 24-28 imported): the
contact strings, a LAMMPS and a LIGGGHTS head, the atoms and run tails the decks share, the registry the round's
decks go into (`deck`, `L`) and the writer of a deck folder (decks/NAME/DECKFILE with G, DECK, a LIGGGHTS marker and
its extra files). A round's make_decksNN.py sets `D` (its decks folder), registers its decks and calls `main`.
"""
import math, os, shutil, subprocess, sys

D = None  # the round's decks folder, set by its make_decksNN.py

TL = "tangential linear_nohistory 1 0.3"
K = f"damping mass_velocity {TL}"
HK = f"hooke 2000 3000 {K}"
HM = f"hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}"


def hk(k, gam=3000):
    return f"hooke {k} {gam} {K}"


def head(ntypes=2, box="0 0.04 0 0.04 0 0.1", bnd="p p f", style="sphere 1", units="si", dim=3, extra=""):
    return (f"units {units}\n" + (f"dimension {dim}\n" if dim != 3 else "") + f"atom_style {style}\nboundary {bnd}\n"
            f"comm_modify vel yes\n{extra}region box block {box} units box\ncreate_box {ntypes} box\n")


GRAV = "fix grav all gravity 9.81 vector 0 0 -1\n"
FLOOR = f"fix floor all wall/gran granular {HK} zplane 0 NULL\n"
TAIL = "fix integ all nve/sphere\ntimestep 1e-5\n"
TWO = ("create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\n"
       "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n")
TWO4 = TWO.replace("0.006 density", "0.004 density")  # both spheres 4 mm (rounds 15-20)
G1 = lambda model: "pair_style granular\npair_coeff * * " + model + "\n"
BASE = lambda model=HK, nt=2: head(nt) + G1(model) + GRAV + f"fix floor all wall/gran granular {model} zplane 0 NULL\n" + TAIL
# a deck that reads its two spheres from a data file (round 23, and round 28 through round 27's generator)
RD = lambda f="d.data", kw="": "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data " + f + kw + "\n" + G1(HK) + GRAV + FLOOR + TAIL
PRB = 'print "PROBE kn ${kn}"\n'
DECKS = {}


def deck(name, text, g="0.1 1", data=None, liggghts=False, deckname="in.deck"):
    DECKS[name] = (text, g, data or {}, liggghts, deckname)


def lhead(nt=3, extra="", units="si", box="-0.05 0.05 -0.05 0.05 -0.01 0.15", bnd="f f f", style="granular",
          neigh="neighbor 0.002 bin\nneigh_modify delay 0\n"):
    """The head of a LIGGGHTS deck (round 14's, with the keywords rounds 18-19 added): `nt` types, then `extra`."""
    return (f"atom_style {style}\natom_modify map array\nboundary {bnd}\nnewton off\ncommunicate single vel yes\nunits {units}\n"
            f"region reg block {box} units box\ncreate_box {nt} reg\n{neigh}{extra}")


MAT3 = ("fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n")
E3 = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8\n"
HERTZ = "pair_style gran model hertz tangential history\npair_coeff * *\n"
HOOKE = "pair_style gran model hooke tangential history\npair_coeff * *\n"
WALL3 = "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
ATOMS = "create_atoms 1 single 0.01 0 0.01 units box\ncreate_atoms 2 single -0.01 0 0.01 units box\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 1500\n"
LRUN = "timestep 1e-5\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
RUN = LRUN + "run 1000\n"
RUN2000 = LRUN + "run 2000\n"  # rounds 14-19's LIGGGHTS run
# round 14's hooke/stiffness lines (rounds 14-16)
STIFF3 = """fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000
fix m5 all property/global gamman peratomtypepair 3 3000 2000 1000 2000 2500 1500 1000 1500 2000
fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000
fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50
"""
LB = lambda: lhead() + MAT3 + E3 + HERTZ + WALL3
E3b = lambda e: "fix m3 all property/global coefficientRestitution peratomtypepair 3 " + " ".join([str(e)] * 9) + "\n"


def L(name, text, **kw):
    deck(name, text, liggghts=True, **kw)


# names the decks of rounds 23-27 share, defined among round 23's decks
RUN1 = "run 100\n"
CGS_HK = f"hooke 2e6 3000 {K}"
CGS_HM = "hertz/material 1e8 1.4e5 0.3 damping viscoelastic " + TL  # 1e7 Pa, 1.4e7 1/(m s) in cgs


def ubase(units, model, box, sizes, g="1"):
    """A two-type deck head in `units` with a floor of `model`, spheres of diameters and densities `sizes`."""
    d1, d2, r1, r2 = sizes
    return (head(2, box=box, units=units) + G1(model) + f"fix floor all wall/gran granular {model} zplane 0 NULL\nfix integ all nve/sphere\n"
            + f"create_atoms 1 single {d1*5} {d1*5} {d1*2.5}\ncreate_atoms 2 single {d1*2.5} {d1*2.5} {d1*2.5}\nset type 1 diameter {d1} density {r1}\nset type 2 diameter {d2} density {r2}\n")


MOL = lambda t, d, m: f"# one sphere\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 {t}\n\nDiameters\n\n1 {d}\n\nMasses\n\n1 {m}\n"
mass = lambda d, rho: f"{rho * math.pi / 6 * d ** 3:.9g}"
PTS = ("fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
       "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1500 radius constant 0.003\n"
       "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\n"
       "region bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n")
HS = ("fix k1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix k2 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
      "fix k3 all property/global gamman peratomtypepair 3 500 500 500 500 500 500 500 500 500\nfix k4 all property/global gammat peratomtypepair 3 500 500 500 500 500 500 500 500 500\n"
      "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\nfix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n")
LATIN1 = set()  # decks written in Latin-1 bytes (an old editor)


STL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "field13", "stl.py")  # round 13's STL maker


def write_folder(d, text, g, *, deckname="in.deck", deck_file=False, args=None, liggghts=False, data=None, stl=None,
                 encoding="utf-8"):
    r"""Write a deck folder `d` as the field rounds lay it out.

    The deck file `deckname` holding `text`; G, the speeds `g` to audit at; DECK naming the deck file (`deck_file`,
    from round 20: else the scripts take the first in.*, and in.2 sorts before in.deck); ARGS, the audit's further
    arguments (`args`); the empty LIGGGHTS marker (`liggghts`); extra files `data` ({path: text}, folders made);
    STL files `stl` ({path: arguments of tests/field13/stl.py}).

    Examples
    --------
    >>> import tempfile
    >>> d = os.path.join(tempfile.mkdtemp(), "a01")
    >>> write_folder(d, "units si\n", "0.1 1", deck_file=True, data={"sub/x.data": "1\n"})
    >>> sorted(os.listdir(d)), open(os.path.join(d, "G")).read()
    (['DECK', 'G', 'in.deck', 'sub'], '0.1 1\n')
    """
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, deckname), "w", encoding=encoding).write(text)
    open(os.path.join(d, "G"), "w").write(f"{g}\n")
    if deck_file:
        open(os.path.join(d, "DECK"), "w").write(deckname + "\n")
    if args:
        open(os.path.join(d, "ARGS"), "w").write(args + "\n")
    if liggghts:
        open(os.path.join(d, "LIGGGHTS"), "w").write("")
    for f, t in (data or {}).items():
        os.makedirs(os.path.dirname(os.path.join(d, f)), exist_ok=True)
        open(os.path.join(d, f), "w").write(t)
    for f, a in (stl or {}).items():
        subprocess.run([sys.executable, STL, *a, os.path.join(d, f)], check=True)


def write(name):
    """Write registered deck `name`'s folder under `D` (its deck file, G, DECK, LIGGGHTS marker and extra files)."""
    text, g, data, lig, deckname = DECKS[name]
    write_folder(os.path.join(D, name), text, g, deckname=deckname, deck_file=True, liggghts=lig, data=data,
                 encoding="latin-1" if name in LATIN1 else "utf-8")


def write_live(names, live, extra=None):
    """Write registered decks `names` (`write`) with their live pair's files (rounds 27, 28): LIVE, the run the pair
    meets in (``live[name]``, up to a line ``SEP s``), SEP (the pair's touching distance, when given), and the files
    ``extra[name]`` names ({file: text}, e.g. PAIR); a deck with no live pair gets none of them."""
    for n in names:
        write(n)
        if n in live:
            open(os.path.join(D, n, "LIVE"), "w").write(live[n].split("\nSEP")[0] + "\n")
            for f, t in (extra or {}).get(n, {}).items():
                open(os.path.join(D, n, f), "w").write(t + "\n")
            if "\nSEP " in live[n]:
                open(os.path.join(D, n, "SEP"), "w").write(live[n].split("\nSEP ")[1] + "\n")


def copy_example(d, src, f, lig, first=""):
    """Copy an engine's example deck `f` from folder `src` to deck folder `d` (skipped when `d` exists), with G 1 and
    DECK: a LIGGGHTS example whole (and its marker), a LAMMPS one with its molecule files; `first` put before its
    first line."""
    if os.path.exists(d):
        return
    if lig:
        shutil.copytree(src, d)
        open(os.path.join(d, "LIGGGHTS"), "w").write("")
    else:
        os.makedirs(d)
        shutil.copy(os.path.join(src, f), d)
        for extra in os.listdir(src):
            if extra.startswith("molecule") or extra.endswith(".mol"):
                shutil.copy(os.path.join(src, extra), d)
    if first:
        txt = open(os.path.join(d, f)).read()
        open(os.path.join(d, f), "w").write(first + txt)
    open(os.path.join(d, "DECK"), "w").write(f + "\n")
    open(os.path.join(d, "G"), "w").write("1\n")


LAMMPS_EXAMPLES = "/usr/share/lammps/examples"  # the Debian packages' example decks
LIGGGHTS_TUTORIALS = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"


def copy_examples(lammps, tutorials, first=None):
    """Copy engine examples into deck folders under `D` (rounds 25, 26): `lammps` as (name, subfolder, deck),
    LIGGGHTS `tutorials` as (subfolder, deck), named X_lig_SUBFOLDER_DECK (less its 'in.'); `first`: {name: a line put
    first}."""
    ex = [(n, os.path.join(LAMMPS_EXAMPLES, sub), f, False) for n, sub, f in lammps]
    ex += [("X_lig_" + t + "_" + f[3:], os.path.join(LIGGGHTS_TUTORIALS, t), f, True) for t, f in tutorials]
    for name, src, f, lig in ex:
        copy_example(os.path.join(D, name), src, f, lig, (first or {}).get(name, ""))


def make(decks, write, argv):
    """Write the decks named in `argv` (every one of `decks` when it is empty) with `write`; print how many there are."""
    for n in (argv or decks):
        write(n)
    print(len(decks), "decks")


def main(argv):
    """Write the registered decks named in `argv` (all when it is empty) and print how many are registered."""
    make(DECKS, write, argv)
