"""Field round 27: public decks (copied at run time, not committed; SOURCES names repository, path and commit) and
variants with this round's mechanisms. The text is fetched into PUB/ by hand (the search tools), then this script writes
decks/PUB*. usage: python pubdecks27.py"""
import os, re
H = os.path.dirname(os.path.abspath(__file__)); D = os.path.join(H, "decks")
rest = open(os.path.join(H, "PUB", "in.restitution")).read()
pour = open(os.path.join(H, "PUB", "input.lammps")).read()
NEW = "pair_coeff * * hertz/material 1e6 0.5 0.4 tangential mindlin NULL 0.0 0.5 damping coeff_restitution"
v = {
    "PUB01_restitution": rest,
    "PUB02_restitution_every_part1": rest.replace("run\t\t        1000000", f'run 1000000 every 250000 "{NEW}"'),
    "PUB03_restitution_every_part2": rest.replace("run\t\t        1000000", f'run 1000000 every 50000 "{NEW}"'),
    "PUB04_restitution_pre_no": rest.replace("run\t\t        1000000", f"run 10000\n{NEW}\nrun 990000 pre no"),
    "PUB05_restitution_clear_first": "clear\n" + rest,
    "PUB06_pour_trim_every": pour.replace("loop 10000", "loop 5").replace("run 2000 #", 'run 2000 every 1000 "print x" #').replace("run 2000000", "run 20000").replace("dump mydmp", "#dump mydmp"),
    "PUB07_pour_trim_pre_no": pour.replace("loop 10000", "loop 5").replace("run 2000000", "pair_coeff * * hooke 30000 500 tangential linear_nohistory 1.0 0.4 damping mass_velocity\nrun 20000 pre no").replace("dump mydmp", "#dump mydmp"),
    "PUB08_pour_trim": pour.replace("loop 10000", "loop 5").replace("run 2000000", "run 20000").replace("dump mydmp", "#dump mydmp"),
}
for n, t in v.items():
    d = os.path.join(D, n); os.makedirs(d, exist_ok=True)
    fn = "in.restitution" if "restitution" in n else "input.lammps"
    open(os.path.join(d, fn), "w").write(t); open(os.path.join(d, "DECK"), "w").write(fn + "\n"); open(os.path.join(d, "G"), "w").write("2\n")
print(len(v))
