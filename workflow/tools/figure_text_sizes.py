"""Print the smallest printed text size of every figure in a built PDF.

    python workflow/tools/figure_text_sizes.py results/paper/restitution.pdf [--min 7]

Sizes are read from the PDF's own text operators at the scale each figure is printed
(restitution_workflow.pdf_text). Exit status 1 when any text inside a figure is smaller than --min
points.
"""
from __future__ import annotations

import argparse
import sys

from restitution_workflow.pdf_text import measure


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pdf")
    parser.add_argument("--min", type=float, default=7.0, help="smallest allowed printed size, pt")
    args = parser.parse_args(argv)
    rows = measure(args.pdf)
    small = False
    for key in sorted({(p, f) for p, f, _, _ in rows}):
        sizes = [(s, t) for p, f, s, t in rows if (p, f) == key]
        low = min(s for s, _ in sizes)
        texts = sorted({t for s, t in sizes if s < low + 0.05})[:6]
        flag = "  < min" if low < args.min - 1e-6 else ""
        small |= bool(flag)
        print(f"page {key[0]:3d}  {key[1]:10s}  {len(sizes):4d} runs  smallest {low:5.2f} pt  "
              f"largest {max(s for s, _ in sizes):5.2f} pt  e.g. {texts}{flag}")
    return 1 if small else 0


if __name__ == "__main__":
    sys.exit(main())
