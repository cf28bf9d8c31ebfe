"""The eps of one head-on collision in LAMMPS at given time steps (field rounds 20, 21): round 10's referee run
function, unchanged, to set the time step a deck's last run really uses beside the one the audit states.
usage: python dtcheckNN.py DT [DT ...]   (types 1 1, 4 mm, 2500 kg/m3, hooke 2000 3000 mass_velocity, g = 1)"""
import importlib.util, math, os
here = os.path.dirname(os.path.abspath(__file__))
spec_ = importlib.util.spec_from_file_location("referee10", os.path.join(here, "..", "field10", "referee.py"))
R = importlib.util.module_from_spec(spec_); spec_.loader.exec_module(R)
m = 2500 * 4 / 3 * math.pi * 0.002 ** 3
spec = {"engine": "lammps", "lines": ["pair_style granular",
        "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"]}
chk = {"t1": 1, "t2": 1, "r1": 0.002, "m1": m, "r2": 0.002, "m2": m}


def main(argv):
    """Print the eps at each time step of `argv`."""
    for dt in map(float, argv):
        e, n, sep = R._lammps_run(spec, chk, 1.0, dt, 100000)
        print(f"dt {dt:g}: eps {e:.6f} after {n} steps (separated: {sep})")
