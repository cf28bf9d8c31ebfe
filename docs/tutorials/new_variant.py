# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Rebuild the paper, and add a new alpha, gamma variant
#
# The pipeline turns `config.yaml` into our reproduction article. From a clone of the repository:
#
# ```sh
# make paper          # the whole pipeline; prints the path of results/paper/restitution.pdf
# make check          # a clean rebuild in a temporary directory, compared with tests/expected/
# ```
#
# Every step is a cached Snakemake rule, so a second `make paper` does nothing. Running it inside
# this page would take too long; this tutorial shows what a new variant is, checks its
# configuration, and asks Snakemake what it would run for it (a dry run).
#
# ## The variants
#
# `config.yaml` lists the materials under `variants`; each gets the whole study in
# `results/<name>/`.

# %%
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import yaml

from restitution import Material, epsilon

ROOT = Path(os.environ.get("RESTITUTION_DOCS_ROOT", Path.cwd().parents[1]))
config = yaml.safe_load((ROOT / "config.yaml").read_text())
for v in config["variants"]:
    print(f"{v['name']:8s} alpha = {v['alpha']:4s} gamma = {v['gamma']:4s} D1 = {v['D1']:<9g} D2 = {v['D2']}")

# %% [markdown]
# ## A new material
#
# Say alpha = 2 and gamma = 1/2, with D1 = 0.01 and D2 = 0.1, at impact speeds from 0.01 to 10.
# A variant needs a name, the exponents (as exact fractions) and D1, D2; the rest has defaults.
# One reading of the paper's connection procedure keeps the study light.

# %%
flat = {"name": "flat", "alpha": "2", "gamma": "1/2", "D1": 0.01, "D2": 0.1,
        "g_range": {"min": 0.01, "max": 10, "points": 5}, "readings": ["P-N2-K2-Dprinted"]}

# %% [markdown]
# The pipeline validates its configuration against `workflow/schemas/config.schema.yaml` before it
# runs anything ([its fields](../reference/_generated/config.md)). The same check, here, on
# `config.yaml` with the new variant added for one run (`extra_variants`), then on a mistake:

# %%
from restitution_workflow.config import ConfigError, check_config   # the pipeline's own check

schema = str(ROOT / "workflow" / "schemas" / "config.schema.yaml")
checked = check_config({**config, "extra_variants": [dict(flat)]}, schema)
print("valid; the variant as the pipeline sees it, defaults filled in:")
print(yaml.safe_dump(checked["extra_variants"][0], sort_keys=False))
try:
    check_config({**yaml.safe_load((ROOT / "config.yaml").read_text()),
                  "extra_variants": [{**flat, "gamma": "-1/2"}]}, schema)
except ConfigError as err:
    print("refused:", err)

# %% [markdown]
# ## What Snakemake would run for it
#
# The one-off study of a new material, without editing any file (the target comes before
# `--config`, which takes the rest of the line):
#
# ```sh
# .venv/bin/snakemake --cores 2 results/flat/study.txt \
#     --config 'extra_variants=[{name: flat, alpha: "2", gamma: "1/2", D1: 0.01, D2: 0.1, g_range: {min: 0.01, max: 10, points: 5}, readings: [P-N2-K2-Dprinted]}]'
# ```
#
# Below, the same with `--dry-run`, in a clean copy of the project (so that nothing here is
# touched): the jobs it would run, by rule.

# %%
# the pipeline's tool that copies the project as a fresh clone has it (a script, not a package)
spec = importlib.util.spec_from_file_location("rebuild", ROOT / "workflow" / "tools" / "rebuild.py")
rebuild = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rebuild)

work = Path(tempfile.mkdtemp(prefix="restitution-variant-"))
tree = rebuild.copy_tree(work / "tree")
snakemake = str(Path(sys.executable).with_name("snakemake"))
extra = ('extra_variants=[{name: flat, alpha: "2", gamma: "1/2", D1: 0.01, D2: 0.1, '
         'g_range: {min: 0.01, max: 10, points: 5}, readings: [P-N2-K2-Dprinted]}]')
dry = subprocess.run([snakemake, "results/flat/study.txt", "--cores", "1", "--dry-run", "--config", extra],
                     cwd=tree, capture_output=True, text=True)
shutil.rmtree(work, ignore_errors=True)
if dry.returncode != 0:
    raise RuntimeError(dry.stderr[-2000:])
stats = dry.stdout[dry.stdout.index("Job stats:"):]
print(stats[:stats.index("\n\n", stats.index("total"))])

# %% [markdown]
# Run it for real by dropping `--dry-run`; its results go to `results/flat/` and nothing else is
# rerun. To keep the variant, add it under `variants` in `config.yaml` (or in a file passed with
# `--configfile`); `make paper` then adds its section to the article.
#
# ## A first look without the pipeline
#
# The library answers directly what the study's figure 4 will show: eps against impact speed,
# here beside the paper's case.

# %%
g = np.geomspace(0.01, 10, 80)
fig, ax = plt.subplots(figsize=(6, 3.6))
for v in [config["variants"][0], flat]:
    m = Material(alpha=v["alpha"], gamma=v["gamma"], D1=v["D1"], D2=v["D2"])
    r = epsilon(alpha=v["alpha"], gamma=v["gamma"], omega=m.omega(g), tol=1e-8)
    ax.semilogx(g, r.eps, label=f"{v['name']}: alpha = {v['alpha']}, gamma = {v['gamma']}")
ax.set_xlabel("impact speed g")
ax.set_ylabel("eps")
ax.legend()
fig.tight_layout()
