# %% [markdown]
# # The engine runs behind the typed-e table
#
# Every row of the typed-e table names the engine that confirms it: the row is run in that engine
# at each e of TYPED_E_ENGINE_ES (three time steps, extrapolated to dt = 0) and must give the
# table's eps to TYPED_E_ENGINE_RTOL. The engine tests do this; here the same runs
# (restitution.dem.engines.typed_e_table.typed_e_engine_cases) are made once more with what each engine
# was given and printed kept (restitution_workflow.engine_record), so that a reader can run them
# again, and the eps each run gave is tabulated beside the table's. This script only calls the
# library and writes what it returns; it stops, writing nothing, where an engine is missing or a
# row is not confirmed.

# %%
import importlib
import re
from pathlib import Path

import pandas as pd
from restitution_workflow.engine_record import LammpsRecorder, ProcessRecorder, lammps_version
from restitution_workflow.latex import esc, sci
from restitution_workflow.pipeline import start, write_csv, write_text

from restitution.dem.engines import ENGINES
from restitution.dem.pair import Pair
from restitution.dem.engines.typed_e_table import (TYPED_E_ENGINE_ES, TYPED_E_ENGINE_REFINEMENTS, TYPED_E_ENGINE_RTOL,
                                           typed_e_engine_cases, typed_e_engine_results)

start(snakemake)
P = snakemake.params
HERE = Path(snakemake.output.readme).parent
pair = Pair.spheres(*P.radii, *P.densities)


def slug(row: str) -> str:
    """A row label as a file name: the engine's name dropped, words joined by underscores."""
    return re.sub(r"[^a-z0-9]+", "_", row.split(" ", 1)[1].lower()).strip("_")


# %% Run each engine's rows, recorded
rows, files, lines = [], {}, []
for name in P.engines:
    entry = ENGINES[name]
    runner = importlib.import_module(entry.runner_module)
    if not runner.available():
        raise SystemExit(f"{entry.label} is not installed ({entry.install_hint}): the typed-e table's runs need it")
    cases = typed_e_engine_cases(name, pair, P.material, P.g, TYPED_E_ENGINE_ES)
    recorder = LammpsRecorder() if name == "lammps" else ProcessRecorder(runner)
    with recorder.active():
        eps = runner.eps_runs(pair, [run for c in cases for run in c["runs"]])
    results = typed_e_engine_results(cases, eps)
    bad = [r for r in results if abs(r["relative_deviation"]) > TYPED_E_ENGINE_RTOL]
    if bad:
        raise SystemExit(f"{entry.label} does not confirm the typed-e table to {TYPED_E_ENGINE_RTOL:g}: {bad}")
    if name == "lammps":
        # one LAMMPS instance per run, in the order of the cases and their steps
        names = [f"{name}/{slug(c['row'])}_e{c['e']:g}_n{n}" for c in cases for n in c["steps"]]
        assert len(recorder.runs) == len(names)
        for stem, run in zip(names, recorder.runs):
            files[f"{stem}.in"], files[f"{stem}.out"] = run["deck"], run["output"]
        where = [[f"{name}/{slug(c['row'])}_e{c['e']:g}_n{n}.in" for n in c["steps"]] for c in cases]
    else:
        # one process for every run of the engine
        assert len(recorder.runs) == 1
        run = recorder.runs[0]
        for fname, text in run["files"].items():
            files[f"{name}/{fname}"] = text
        files[f"{name}/command.txt"] = run["command"] + "\n"
        files[f"{name}/output.txt"] = run["output"]
        where = [[f"{name}/command.txt"] * len(c["steps"]) for c in cases]
    for r, c, w in zip(results, cases, where):
        rows.append({"engine": entry.version, **r, "runs": " ".join(dict.fromkeys(w))})

# %% Write them
declared = {Path(f).relative_to(HERE).as_posix() for f in snakemake.output.runs}
if set(files) != declared:
    raise SystemExit(f"the runs wrote {sorted(set(files) ^ declared)} unlike the rule declares")
for rel, text in files.items():
    write_text(HERE / rel, text)
write_csv(snakemake.output.csv, pd.DataFrame(rows))
# what the text says of these runs: LAMMPS' release as its screens print it, the one impact speed, and each
# engine's release once, in the order of the registry (the article's data statement): LAMMPS' as its screens
# print it (the Python module's label, 2025.7.22, leaves out the update), the others' by their version label
screens = [text for rel, text in files.items() if rel.startswith("lammps/") and rel.endswith(".out")]
lammps_release = lammps_version(screens) if screens else "none"
releases = [f"LAMMPS ({lammps_release})" if name == "lammps" else ENGINES[name].version for name in P.engines]
write_text(snakemake.output.values, "\n".join([
    rf"\newcommand{{\TypedERunsLammpsVersion}}{{{esc(lammps_release)}}}",
    rf"\newcommand{{\TypedERunsSpeed}}{{{sci(P.g, 2)}}}",
    rf"\newcommand{{\TypedEReleases}}{{{', '.join(esc(r) for r in releases)}}}"]))
steps = {name: [ENGINES[name].typed_e_steps * k for k in TYPED_E_ENGINE_REFINEMENTS] for name in P.engines}
write_text(snakemake.output.readme, f"""\
The engine runs behind the typed-e table (typed_e.csv, the article's table of the e typed into each
code against the eps it gives): each row run in the engine named for it, at e = {', '.join(f'{e:g}' for e in TYPED_E_ENGINE_ES)},
two unlike spheres (radii {P.radii[0]:g} and {P.radii[1]:g} m, densities {P.densities[0]:g} and {P.densities[1]:g} kg/m^3;
E = {P.material['E']:g} Pa, nu = {P.material['nu']:g} where a row's stiffness reads them) meeting head-on at g = {P.g:g} m/s.
Each case is run at three time steps, t_c / n for n = {'; '.join(f'{ENGINES[name].label} {", ".join(map(str, s))}' for name, s in steps.items())}
(t_c the library's contact time), and extrapolated to dt = 0 (two Richardson levels removing the
orders dt and dt^2, or dt^(1 + gamma) for a damping exponent 0 < gamma < 1).

typed_e_runs.csv: per row and e, the table's eps (eps_table), the engine's at t_c / n, t_c / 2n and
t_c / 4n (eps_dt1, eps_dt2, eps_dt4), its extrapolation (eps_engine), their relative deviation (at
most {TYPED_E_ENGINE_RTOL:g} is demanded), and the files of the runs.

lammps/<option>_e<e>_n<n>.in and .out: one LAMMPS deck and its screen per run; rerun one with
    lmp -log none -in <file>.in
Its last lines print each atom's position and velocity; eps = -(vx of atom 1 - vx of atom 2) / g.

liggghts/, yade/, kratos/: the engine was run once for all its cases, in the directory holding the
input (in.collide, collide.py), with the command of command.txt; output.txt is what it printed.
LIGGGHTS prints one line "RESTITUTION-RESULT <case> <v1 - v2> <centre distance> <atoms before> <after>"
per case, Yade and Kratos one line "RESTITUTION-RESULT " followed by a JSON list of the final relative
velocity v1 - v2 ("rel") per case; eps = -rel / g. The cases are in the order of typed_e_runs.csv, each
row and e at its three time steps from the coarsest. What an engine prints that changes from one run to
the next (timings, dates, Yade's port) is replaced by "(time)", "(date)" or "(port)".
""")
