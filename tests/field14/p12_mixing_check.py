"""Field round 14, p12: the 1 2 pair LAMMPS mixes from a jkr 1 1 line of cohesion 0.5 and a jkr 2 2 line of
cohesion 0, head-on in LAMMPS (round 10's referee's measure(), dt -> 0), against the same deck with 1 1's
cohesion set to 0 (every line then mapped): if the mixed cohesion is 0 (geometric mean), both agree.
usage: python p12_mixing_check.py"""
import importlib.util, os
here = os.path.dirname(os.path.abspath(__file__))
s = importlib.util.spec_from_file_location("R", os.path.join(here, "..", "field10", "referee.py"))
R = importlib.util.module_from_spec(s); s.loader.exec_module(R)
J = "damping mass_velocity tangential linear_nohistory 1 0.3"
chk = {"t1": 1, "t2": 2, "r1": 0.002, "m1": 8.3775804e-05, "r2": 0.003, "m2": 0.00028274334}
for coh in (0.5, 0.0):
    spec = {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff 1 1 jkr 1e7 3000 0.3 {coh} {J}",
                                          f"pair_coeff 2 2 jkr 2e7 3000 0.3 0 {J}"]}
    for g in (0.1, 1.0):
        m = R.measure(spec, chk, g, 1e-3)
        print(f"1 1 cohesion {coh}: types 1 2 mixed, g {g}: eps {m.get('eps0')} wobble {m.get('wobble')} sticks {m.get('sticks', False)}")
