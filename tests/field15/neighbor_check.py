"""Field round 15, n02: the eps LAMMPS itself measures for deck n02's types 1 2 (hooke 2000/3000 mass_velocity,
r 2 and 3 mm, density 2500, as the engine holds them) at the deck's dt 1e-5, the spheres approaching at 1 m/s from
gaps of 0.2 ... 1.8 mm (so the contact begins at several phases of the list rebuilds), with the deck's neighbour
settings (`neighbor 1e-5 bin`, `neigh_modify every 200 delay 0 check no`) and with LAMMPS' defaults. eps = relative
normal speed after separation / before. No import from the project. usage: python neighbor_check.py"""
import math
import sys
import lammps

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def run(gap, neigh, g=1.0):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    r1, r2 = 0.002, 0.003
    m1, m2 = 2500 * 4 / 3 * math.pi * r1 ** 3, 2500 * 4 / 3 * math.pi * r2 ** 3
    for c in ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes", "atom_modify map array",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 2 box", "pair_style granular", f"pair_coeff * * {HK}",
              f"create_atoms 1 single {-r1 - gap / 2} 0 0", f"create_atoms 2 single {r2 + gap / 2} 0 0",
              f"set atom 1 diameter {2 * r1} density 2500", f"set atom 2 diameter {2 * r2} density 2500",
              "group a1 id 1", "group a2 id 2", f"velocity a1 set {g * m2 / (m1 + m2)} 0 0", f"velocity a2 set {-g * m1 / (m1 + m2)} 0 0",
              *neigh, "fix nve all nve/sphere", "timestep 1e-5", "thermo 0", "run 0"]:
        l.command(c)
    touched = False
    for k in range(20000):
        l.command("run 1 pre no post no")
        x = l.numpy.extract_atom("x"); v = l.numpy.extract_atom("v")
        d = x[1, 0] - x[0, 0]
        if d < r1 + r2:
            touched = True
        if touched and d > r1 + r2:
            e = (v[1, 0] - v[0, 0]) / g
            l.close()
            return e
    l.close()
    return float("nan")


if __name__ == "__main__" and "n10" not in sys.argv[1:]:
    deck = ["neighbor 1e-5 bin", "neigh_modify every 200 delay 0 check no"]
    for gap in (0.0002, 0.0006, 0.001, 0.0014, 0.0018):
        print(f"gap {gap:.4f} m: deck's lists eps {run(gap, deck):.6f}   LAMMPS' default lists eps {run(gap, []):.6f}")


def run_whole(gap, neigh, steps=600):
    """The same in one continuous run (no stepping by hand): the relative speed at its end."""
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    r1, r2 = 0.002, 0.003
    m1, m2 = 2500 * 4 / 3 * math.pi * r1 ** 3, 2500 * 4 / 3 * math.pi * r2 ** 3
    for c in ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes", "atom_modify map array",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 2 box", "pair_style granular", f"pair_coeff * * {HK}",
              f"create_atoms 1 single {-r1 - gap / 2} 0 0", f"create_atoms 2 single {r2 + gap / 2} 0 0",
              f"set atom 1 diameter {2 * r1} density 2500", f"set atom 2 diameter {2 * r2} density 2500",
              "group a1 id 1", "group a2 id 2", f"velocity a1 set {m2 / (m1 + m2)} 0 0", f"velocity a2 set {-m1 / (m1 + m2)} 0 0",
              *neigh, "fix nve all nve/sphere", "timestep 1e-5", "thermo 0", f"run {steps}"]:
        l.command(c)
    v = l.numpy.extract_atom("v")
    e = v[1, 0] - v[0, 0]
    l.close()
    return e


if __name__ == "__main__" and "n10" not in sys.argv[1:]:
    for gap in (0.0002, 0.001, 0.0018):
        print(f"one run of 600 steps, gap {gap:.4f} m: deck's lists eps {run_whole(gap, deck):.6f}   default {run_whole(gap, []):.6f}")


if __name__ == "__main__" and "n10" in sys.argv[1:]:
    for gap in (0.0002, 0.0011, 0.0023, 0.0037, 0.0049):
        print(f"n10, g 10, gap {gap:.4f} m: 'neigh_modify delay 10 every 1 check yes' eps {run(gap, ['neigh_modify delay 10 every 1 check yes'], 10.0):.6f}"
              f"   LAMMPS' default lists eps {run(gap, [], 10.0):.6f}")
