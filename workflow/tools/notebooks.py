"""The workflow scripts as notebooks: `make notebooks` writes notebooks/<script>.ipynb.

A script run by Snakemake gets its `snakemake` object from Snakemake; opened as a notebook it
replays the pipeline's last run of its rule instead (restitution_workflow.pipeline.replay, from the job that
`start(snakemake)` recorded under build/jobs/). That replay cell is added here, at conversion, so
the scripts themselves stay plain (imports first, no notebook-only code).

    python workflow/tools/notebooks.py [--to ipynb|py:percent] [--out DIR] [SCRIPT ...]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import jupytext
from nbformat.v4 import new_code_cell

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = ROOT / "workflow" / "scripts"

REPLAY = '''# Opened as a notebook: replay the pipeline's last run of this rule (run `make paper` first).
from restitution_workflow.pipeline import replay   # the workflow's helpers, installed with the package

snakemake = replay({rule!r})'''


def notebook(script: Path):
    """The script as a notebook, with the replay cell after its title (the rule is the script's name)."""
    nb = jupytext.read(script)
    at = 1 if nb.cells and nb.cells[0].cell_type == "markdown" else 0
    nb.cells.insert(at, new_code_cell(REPLAY.format(rule=script.stem)))
    return nb


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--to", default="ipynb", help="jupytext format (default ipynb)")
    parser.add_argument("--out", type=Path, default=ROOT / "notebooks")
    parser.add_argument("scripts", nargs="*", type=Path)
    args = parser.parse_args(argv)
    scripts = args.scripts or sorted(p for p in SCRIPTS.glob("*.py"))
    args.out.mkdir(parents=True, exist_ok=True)
    ext = ".ipynb" if args.to == "ipynb" else ".py"
    for script in scripts:
        jupytext.write(notebook(script), args.out / (script.stem + ext), fmt=args.to)
    print(f"{args.out}: {', '.join(s.stem + ext for s in scripts)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
