"""Field round 28: public decks (copied at run time into PUB/, not committed; SOURCES names repository, path and
commit) and variants with this round's mechanisms, written into decks/PUB*. Each restitution variant keeps the
deck's own pair (groups a1, a2, approaching along z at 2 m/s) and its PUBLIVE file names the referee's groups.
usage: python pubdecks28.py"""
import os
H = os.path.dirname(os.path.abspath(__file__)); D = os.path.join(H, "decks")
rest = open(os.path.join(H, "PUB", "in.restitution")).read()
pour = open(os.path.join(H, "PUB", "in.pour.granular")).read()
# this LAMMPS refuses tsuji damping with jkr (engine and audit alike): the jkr line keeps its default damping
pour = pour.replace("twisting marshall damping tsuji\n", "twisting marshall\n")
RUN = "run\t\t        1000000"
assert RUN in rest
E5 = "pair_coeff * * hertz/material 1e6 0.5 0.4 tangential mindlin NULL 0.0 0.5 damping coeff_restitution"
v = {
    "PUB01_restitution": rest,
    "PUB02_restitution_step_var_if": rest.replace(RUN, 'run 40000 every 10000 "variable s equal $(step)"\nif "${s} == 40000" then "' + E5 + '"\nrun 960000'),
    "PUB03_restitution_every_e_part2": rest.replace(RUN, f'run 1000000 every 40000 "{E5}"'),
    "PUB04_restitution_clear_every": "clear\n" + rest.replace(RUN, 'run 40000 every 20000 "variable s equal $(step)"\nif "${s} == 40000" then "' + E5 + '"\nrun 960000'),
    "PUB05_restitution_type_fraction_seed2": rest.replace(RUN, "run 20000\nset group a1 type/fraction 2 0.5 2\npair_coeff 1 2 hertz/material 1e6 0.3 0.4 tangential mindlin NULL 0.0 0.5 damping coeff_restitution\nrun 980000"),
    "PUB06_restitution_type_fraction_seed5": rest.replace(RUN, "run 20000\nset group a1 type/fraction 2 0.5 5\npair_coeff 1 2 hertz/material 1e6 0.3 0.4 tangential mindlin NULL 0.0 0.5 damping coeff_restitution\nrun 980000"),
    "PUB07_restitution_type_fraction_seed7": rest.replace(RUN, "run 20000\nset group a1 type/fraction 2 0.5 7\npair_coeff 1 2 hertz/material 1e6 0.3 0.4 tangential mindlin NULL 0.0 0.5 damping coeff_restitution\nrun 980000"),
    "PUB08_restitution_pre_no_grow": rest.replace(RUN, "run 40000\nset group all diameter 0.00406\nrun 960000 pre no"),
    "PUB09_pour_granular_trim": pour.replace("run\t\t150000", "run 20000").replace("dump\t\t1", "#dump\t\t1").replace("log\t\tpour", "#log\t\tpour"),
    "PUB10_pour_granular_pre_no_grow": pour.replace("run\t\t150000", "run 10000\nset type 1 diameter 1.2\nrun 10000 pre no").replace("dump\t\t1", "#dump\t\t1").replace("log\t\tpour", "#log\t\tpour"),
    "PUB11_pour_granular_skin_after": pour.replace("run\t\t150000", "run 10000\nneighbor 0.01 bin\nrun 10000").replace("dump\t\t1", "#dump\t\t1").replace("log\t\tpour", "#log\t\tpour"),
    "PUB12_pour_granular_every_step": pour.replace("run\t\t150000", 'run 20000 every 5000 "variable s equal $(step)"\nif "${s} == 20000" then "pair_coeff 1 1 hertz/material 2e5 1e3 0.3 tangential mindlin NULL 1.0 0.5"\nrun 5000').replace("dump\t\t1", "#dump\t\t1").replace("log\t\tpour", "#log\t\tpour"),
}
for n, t in v.items():
    d = os.path.join(D, n); os.makedirs(d, exist_ok=True)
    fn = "in.restitution" if "restitution" in n else "in.pour.granular"
    open(os.path.join(d, fn), "w").write(t); open(os.path.join(d, "DECK"), "w").write(fn + "\n"); open(os.path.join(d, "G"), "w").write("2\n" if "restitution" in n else "1\n")
    if "restitution" in n:
        open(os.path.join(d, "PUBLIVE"), "w").write("a1 a2 z\n")
print(len(v))
