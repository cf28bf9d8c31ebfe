# %% [markdown]
# # The engine runs, listed
#
# The arXiv bundle carries every engine run behind an engine number of the article: the LAMMPS runs
# behind its LAMMPS figure and each engine's runs behind the typed-e table. This script lists them
# with their SHA-256 checksums (the manifest travels in the bundle), counts them per engine for the
# supplement's data section, and typesets one LAMMPS deck there as it was run. It reads the files the
# runs wrote and computes nothing about the physics.

# %%
import hashlib
from collections import Counter
from pathlib import Path

from restitution_workflow.latex import esc
from restitution_workflow.pipeline import start, write_text

start(snakemake)
inputs = snakemake.input
# one width for the typeset deck: wider lines are continued with LAMMPS' own "&", so the deck printed
# is still one LAMMPS reads
WIDTH = 96

# %% The manifest: checksum, size and path of every file, in path order
files = sorted(Path(f).as_posix() for f in [*inputs.lammps, *inputs.typed])
lines = [f"{hashlib.sha256(Path(f).read_bytes()).hexdigest()}  {Path(f).stat().st_size:>8d}  {f}" for f in files]
write_text(snakemake.output.manifest, "# sha256, bytes, path of every engine run file in the arXiv bundle\n"
           + "\n".join(lines) + "\n")

# %% Counts per engine: LAMMPS' figure runs (deck and screen each) and each engine's typed-e runs
lammps_decks = [f for f in inputs.lammps if f.endswith(".in")]
typed = Counter(Path(f).parts[3] for f in inputs.typed if len(Path(f).parts) == 5)
if set(typed) != {"lammps", "liggghts", "yade", "kratos"}:
    raise SystemExit(f"typed-e runs of an unexpected set of engines: {sorted(typed)}")
# the figure's decks are named <rule>_g<speed>_n<steps per contact>: how many time steps each rule and speed
# was run at, read from the names (one number, or the supplement's sentence would be wrong for some)
steps_per_case = Counter(Path(f).stem.rsplit("_n", 1)[0] for f in lammps_decks)
if len(set(steps_per_case.values())) != 1:
    raise SystemExit(f"the LAMMPS figure's cases have different numbers of time steps: {dict(steps_per_case)}")
fig_steps = sorted({int(Path(f).stem.rsplit("_n", 1)[1]) for f in lammps_decks})
macros = {
    "EngineRunFiles": str(len(files)),
    "EngineLammpsFigDecks": str(len(lammps_decks)),
    "EngineLammpsFigStepsPerCase": str(next(iter(steps_per_case.values()))),
    "EngineLammpsFigSteps": ", ".join(map(str, fig_steps)),
    "EngineTypedLammpsFiles": str(typed["lammps"]), "EngineTypedLiggghtsFiles": str(typed["liggghts"]),
    "EngineTypedYadeFiles": str(typed["yade"]), "EngineTypedKratosFiles": str(typed["kratos"]),
    "EngineSampleDeck": esc(Path(snakemake.params.sample).name),
    "EngineChecksum": f"SHA-{hashlib.sha256().digest_size * 8}",
    # the typed-e runs' pair of spheres, in mm and kg/m^3, for the article's table caption
    "EngineTypedRadiusA": f"{1e3 * snakemake.params.collision['radii'][0]:g}",
    "EngineTypedRadiusB": f"{1e3 * snakemake.params.collision['radii'][1]:g}",
    "EngineTypedDensityA": f"{snakemake.params.collision['densities'][0]:g}",
    "EngineTypedDensityB": f"{snakemake.params.collision['densities'][1]:g}",
}
write_text(snakemake.output.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()) + "\n")


# %% One deck as run, wrapped with LAMMPS' continuation character
def wrapped(line: str) -> list[str]:
    out = []
    while len(line) > WIDTH:
        cut = line.rfind(" ", 0, WIDTH - 2)
        out.append(line[:cut] + " &")
        line = "    " + line[cut + 1:]
    return out + [line]


# its comment lines left out (they speak of the software that ran it; the supplement says what the
# commands after the run do), every command kept as it was run
deck = [line for line in Path(snakemake.params.sample).read_text().splitlines() if not line.lstrip().startswith("#")]
body = [w for line in deck for w in wrapped(line)]
write_text(snakemake.output.deck, "{\\footnotesize\n\\begin{verbatim}\n" + "\n".join(body) + "\n\\end{verbatim}\n}\n")
