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
# # The study on a SLURM cluster
#
# A grid of variants or a dense sweep runs unchanged on a SLURM cluster, through Snakemake's
# executor plugin and the profile `workflow/profiles/slurm/config.yaml`. On the cluster's login
# node, in a clone of the repository:
#
# ```sh
# make venv
# .venv/bin/pip install -c constraints.txt snakemake-executor-plugin-slurm   # once, the tested version
# .venv/bin/snakemake --profile workflow/profiles/slurm \
#     $(for v in a b c; do echo results/$v/study.txt; done) --configfile sweep.yaml
# ```
#
# where `sweep.yaml` holds the materials as `extra_variants` (see the
# {doc}`new-variant tutorial <new_variant>`). Set your site's account and partition in the profile or
# with `--default-resources slurm_account=... slurm_partition=...`.
#
# ## Is there a cluster here?

# %%
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import yaml

ROOT = Path(os.environ.get("RESTITUTION_DOCS_ROOT", Path.cwd().parents[1]))
sbatch = shutil.which("sbatch")
if sbatch:
    print("sbatch found:", subprocess.run([sbatch, "--version"], capture_output=True, text=True).stdout.strip())
else:
    print("sbatch is not installed on the machine that built this page: no job is submitted here. "
          "The rest of the page reads the profile and asks Snakemake, without a cluster, what it would submit.")

# %% [markdown]
# ## What the profile asks for
#
# Each rule gets a runtime (minutes) and memory per CPU; the defaults cover the rules not listed.
# Rules are grouped so that one SLURM job runs one variant's whole study (group `variant`) and one
# the stability atlas (group `stability`): every submission starts a Snakemake of its own and waits
# in the queue, which is dearer than most of the rules themselves.

# %%
profile = yaml.safe_load((ROOT / "workflow" / "profiles" / "slurm" / "config.yaml").read_text())
default = profile["default-resources"]
resources = profile["set-resources"]
print("default:", default)
print("groups:", {g: sorted(r for r, gg in profile["groups"].items() if gg == g) for g in set(profile["groups"].values())})

# %%
rules = sorted(resources, key=lambda r: resources[r].get("runtime", default["runtime"]))
colors = {"variant": "C0", "stability": "C1"}
fig, ax = plt.subplots(figsize=(6, 3.8))
ax.barh(rules, [resources[r].get("runtime", default["runtime"]) for r in rules],
        color=[colors.get(profile["groups"].get(r), "C7") for r in rules])
ax.set_xlabel("runtime asked of SLURM (minutes)")
ax.set_title("blue: group 'variant', orange: 'stability', grey: ungrouped", fontsize=9)
fig.tight_layout()

# %% [markdown]
# ## What would be submitted
#
# A dry run through the same profile with its executor switched to the local one (the groups and
# resources stay), in a clean copy of the project, for the one-off variant `flat`:

# %%
# the pipeline's tool that copies the project as a fresh clone has it (a script, not a package)
spec = importlib.util.spec_from_file_location("rebuild", ROOT / "workflow" / "tools" / "rebuild.py")
rebuild = importlib.util.module_from_spec(spec)
spec.loader.exec_module(rebuild)

work = Path(tempfile.mkdtemp(prefix="restitution-slurm-"))
tree = rebuild.copy_tree(work / "tree")
local = work / "profile"
local.mkdir()
text = (ROOT / "workflow" / "profiles" / "slurm" / "config.yaml").read_text()
(local / "config.yaml").write_text(text.replace("executor: slurm", "executor: local", 1))
extra = ('extra_variants=[{name: flat, alpha: "2", gamma: "1/2", D1: 0.01, D2: 0.1, '
         'g_range: {min: 0.01, max: 10, points: 5}, readings: [P-N2-K2-Dprinted]}]')
dry = subprocess.run([str(Path(sys.executable).with_name("snakemake")), "--profile", str(local), "--dry-run",
                      "results/flat/study.txt", "--config", extra], cwd=tree, capture_output=True, text=True)
shutil.rmtree(work, ignore_errors=True)
if dry.returncode != 0:
    raise RuntimeError(dry.stderr[-2000:])
# a group job's rules are listed indented under its "Group job NAME" line; the rest run alone
submitted, alone, current = [], [], None
for line in dry.stdout.splitlines():
    if "Group job" in line:
        current = (line.split("Group job")[1].split("(")[0].strip(), [])
        submitted.append(current)
    elif line.strip().startswith("rule ") and line.strip().endswith(":"):
        rule = line.strip()[5:-1]
        (current[1] if current and line.startswith(" ") else alone).append(rule)
for name, rules in submitted:
    print(f"one SLURM job for group {name!r}: {len(rules)} rules ({', '.join(sorted(rules))})")
print(f"outside any group (one job each, or on the submitting host if local rules): {', '.join(alone)}")

# %% [markdown]
# `make slurm` runs the same for real, as root, on a one-node cluster of the machine it runs on
# (Debian's SLURM packages, started and stopped around the run); `tests/pipeline/test_slurm.py`
# does so in `make test` and checks that the results are byte-identical to a local build. How the
# grouping was chosen, and what the plugin does between submissions: [the pipeline](../howto/pipeline.md).
