"""Plumbing shared by the workflow scripts: logging, deterministic output, notebook replay.

A notebook made by `make notebooks` (workflow/tools/notebooks.py) starts with a cell that calls
``replay(rule)`` to get the ``snakemake`` object; the scripts themselves have no such code. Under
Snakemake, ``start(snakemake)`` records the job (inputs, outputs, params) in
build/jobs/ so that the notebook rendered by ``make notebooks`` can replay it with the
same files and parameters. Nothing here does physics.
"""

from __future__ import annotations

import json
import logging
import math
import os
import pickle
import sys
from pathlib import Path

from .atomic import atomic_path  # a temporary name, then rename

#: The checkout this package is installed from (workflow/lib/restitution_workflow/ -> the project's root).
ROOT = Path(__file__).resolve().parents[3]


def _project_root() -> Path:
    """The project a notebook is opened in: the nearest folder at or above the working directory
    that holds a Snakefile (a copy of the tree replays its own runs, though the package it imports
    is installed from another checkout), else the checkout this package comes from."""
    here = Path.cwd().resolve()
    return next((d for d in (here, *here.parents) if (d / "Snakefile").is_file()), ROOT)
JOBS = Path("build") / "jobs"
_REPLAYED = False

# Fixed build date for every generated file (also exported by the Makefile and common.smk).
os.environ.setdefault("SOURCE_DATE_EPOCH", "1700000000")


def _job_file(rule: str, variant: str | None) -> Path:
    return JOBS / f"{rule}-{variant or 'all'}.pickle"


def start(snakemake) -> None:
    """Under Snakemake: send prints and warnings to the rule's log file and record the job
    (build/jobs/, scratch space outside results/) so the notebook can replay it.
    In a notebook (after replay()) this does nothing."""
    if not in_pipeline():
        return
    if snakemake.log:
        log = Path(snakemake.log[0])
        log.parent.mkdir(parents=True, exist_ok=True)
        stream = open(log, "w", buffering=1)
        sys.stdout = sys.stderr = stream
        logging.basicConfig(stream=stream, level=logging.INFO, force=True)
    variant = getattr(snakemake.wildcards, "variant", None)
    path = _job_file(snakemake.rule, variant)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        pickle.dump(snakemake, fh, protocol=4)


def replay(rule: str, variant: str | None = None):
    """The snakemake object of the pipeline's last run of ``rule`` (main variant by default).

    Changes the working directory to the project root, as under Snakemake.
    """
    global _REPLAYED
    _REPLAYED = True
    os.chdir(_project_root())
    if variant is None:
        import yaml

        with open("config.yaml") as fh:
            variant = yaml.safe_load(fh)["main_variant"]
    path = _job_file(rule, variant)
    if not path.exists():
        path = _job_file(rule, None)
    if not path.exists():
        raise SystemExit(f"no recorded run of rule {rule!r}: run `make paper` (or snakemake) first")
    with open(path, "rb") as fh:
        return pickle.load(fh)


def in_pipeline() -> bool:
    """False once replay() ran, i.e. in a notebook."""
    return not _REPLAYED


def clean(obj):
    """JSON-ready copy: numpy scalars to Python, NaN/inf to None."""
    try:
        import numpy as np
    except ImportError:  # pragma: no cover
        np = None
    if isinstance(obj, dict):
        return {str(k): clean(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [clean(v) for v in obj]
    if np is not None and isinstance(obj, np.ndarray):
        return [clean(v) for v in obj.tolist()]
    if np is not None and isinstance(obj, np.generic):
        obj = obj.item()
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


# Every writer below writes to a hidden temporary name in the output's directory and renames it
# into place (restitution_workflow.atomic.atomic_path), so a killed job never leaves a truncated output behind.

def write_json(path, obj) -> None:
    text = json.dumps(clean(obj), indent=2, allow_nan=False)
    with atomic_path(path) as tmp:
        tmp.write_text(text + "\n")


def read_json(path):
    with open(path) as fh:
        return json.load(fh)


def write_text(path, text: str) -> None:
    if not text.endswith("\n"):
        text += "\n"
    with atomic_path(path) as tmp:
        tmp.write_text(text)


def write_csv(path, frame) -> None:
    """A tidy table with full float precision and Unix newlines."""
    with atomic_path(path) as tmp:
        frame.to_csv(tmp, index=False, lineterminator="\n")


# ---------------------------------------------------------------------------------------------
# Figures
# ---------------------------------------------------------------------------------------------

#: One look for every figure: sized for a one-column article, readable when printed.
STYLE = {
    "figure.figsize": (5.6, 3.8),
    "figure.dpi": 100,
    "savefig.dpi": 200,
    "font.size": 10,
    # mathtext sets an exponent or index at 0.7 of its label; the printed size of both is what
    # save_figure(width=...) measures and guarantees (MIN_PRINTED_PT)
    "axes.labelsize": 12,
    "xtick.labelsize": 12,
    "ytick.labelsize": 12,
    "legend.fontsize": 10,   # its subscripts at 7 pt
    "axes.grid": True,
    "grid.alpha": 0.3,
    # one family for text, ticks and mathematics (Computer Modern mathematics beside DejaVu Sans text mixed two)
    "mathtext.fontset": "dejavusans",
    "svg.hashsalt": "restitution",
    "pdf.compression": 6,
    "path.simplify": False,
}

#: Metadata that would change from build to build (dates, versions) is dropped or fixed.
PDF_METADATA = {"Creator": "restitution pipeline", "Producer": "restitution pipeline",
                "CreationDate": None, "ModDate": None}
PNG_METADATA = {"Software": None}


def setup_matplotlib():
    import matplotlib

    if in_pipeline():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcdefaults()
    plt.rcParams.update(STYLE)
    return plt


#: Line styles, markers and colours of successive orders Omega^0, Omega^1, ...: consecutive orders often
#: coincide over most of the plot, so each differs from the others in all three. The colours are the
#: Okabe-Ito qualitative set (distinct hues, also for colour-blind readers): a sequential colour map gave
#: the highest orders near-identical green shades (referee r19). No two dash patterns alike.
ORDER_DASHES = ["--", "-.", (0, (1, 1.2)), (0, (6, 1.5, 1, 1.5, 1, 1.5)), (0, (9, 2.5))]
ORDER_MARKERS = ["o", "s", "^", "D", "v"]
ORDER_COLORS = ["#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7"]


def order_style(n: int, points: int) -> dict:
    """matplotlib keywords for the curve of order n, markers spread over ``points`` samples (offset
    per order so that markers of overlapping curves do not hide each other).

    Examples
    --------
    >>> style = order_style(4, 801)
    >>> style["marker"], style["color"], style["markevery"]
    ('v', '#CC79A7', (0, 100))
    """
    step = max(points // 8, 1)
    k = len(ORDER_MARKERS)
    return {"color": ORDER_COLORS[n % k], "ls": ORDER_DASHES[n % k], "marker": ORDER_MARKERS[n % k],
            "markersize": 4.0, "markevery": (step * (n % 4) // 4, step), "markerfacecolor": "none"}


#: The manuscripts' text width (A4 less two 2.5 cm margins), in TeX points (1/72.27 in).
TEXT_WIDTH_PT = 160 / 25.4 * 72.27
#: The smallest size of any text in a figure as printed, in points: tick labels, their mathtext
#: exponents, legend entries and their subscripts alike.
MIN_PRINTED_PT = 7.0


def printed_text_sizes(fig, width: float) -> tuple[float, float]:
    """(smallest printed text size in pt, printed scale) of ``fig`` included at ``width`` times the
    text width: measured in the PDF that savefig writes (its text operators, exponents included)."""
    import io
    import re

    from restitution_workflow.pdf_text import measure

    fig.savefig(in_memory := io.BytesIO(), format="pdf", metadata=PDF_METADATA, bbox_inches="tight")
    data = in_memory.getvalue()
    box = [float(x) for x in re.search(rb"/MediaBox\s*\[([^\]]*)\]", data).group(1).split()]
    # pdfTeX scales the figure's box to the requested width; TeX points vs PDF points: 72/72.27
    scale = width * TEXT_WIDTH_PT * 72 / 72.27 / (box[2] - box[0])
    sizes = [size for _, _, size, _ in measure(data, inside_forms=False)]
    return (min(sizes) * scale if sizes else float("inf")), scale


def fit_print_width(fig, width: float) -> float:
    """Narrow ``fig`` (fonts and height kept) until its smallest text is at least MIN_PRINTED_PT when printed at
    ``width`` times the text width; return that smallest size. Never enlarges the figure."""
    smallest, _ = printed_text_sizes(fig, width)
    for _ in range(8):
        if smallest >= MIN_PRINTED_PT + 0.05:
            break
        w, h = fig.get_size_inches()
        factor = max(smallest / (MIN_PRINTED_PT + 0.15), 0.6)
        fig.set_size_inches(w * factor, h)
        smallest, _ = printed_text_sizes(fig, width)
    if smallest < MIN_PRINTED_PT:
        raise RuntimeError(f"figure text would print at {smallest:.2f} pt (< {MIN_PRINTED_PT} pt) "
                           f"at {width} of the text width")
    return smallest


#: The PNGs' resolution: a figure drawn at 0.9 of the text width keeps more than 500 pixels on each
#: side, which the report shows without upscaling (at 200 dpi the dashpot variant's Fig. 4 had 484)
PNG_DPI = 250


def save_figure(fig, pdf, png, width: float | None = None) -> None:
    """Write the figure as PDF (for LaTeX) and PNG (for people), byte-reproducibly.

    ``width``: the fraction of the text width at which the manuscript includes the figure; the
    figure is then made small enough that every text in it prints at MIN_PRINTED_PT or more."""
    if width is not None:
        fit_print_width(fig, width)
    for path, metadata, dpi in ((pdf, PDF_METADATA, None), (png, PNG_METADATA, PNG_DPI)):
        with atomic_path(path) as tmp:
            # the format from the final name (the temporary one ends in .tmp.<ext> anyway)
            fig.savefig(tmp, format=Path(path).suffix[1:], metadata=metadata, bbox_inches="tight",
                        **({"dpi": dpi} if dpi else {}))
