"""The numbers of the article's labels that the supplement reads (rule article_labels): the same bytes
whatever the pass found besides the source (pages, citations), and one line with exit status 2 for a
missing file."""

import subprocess
import sys
from pathlib import Path

from restitution_workflow.aux_labels import label_numbers

SCRIPT = Path(__file__).resolve().parents[2] / "workflow" / "lib" / "restitution_workflow" / "aux_labels.py"


def test_only_the_numbers_are_kept_so_pages_and_citations_do_not_matter():
    first = ("\\relax\n\\citation{kim}\n\\newlabel{fig:eps}{{4}{12}{Kim}{figure.caption.9}{}}\n"
             "\\newlabel{eq:a}{{{A.1}}{15}{App}{equation.A.1}{}}\n")
    # the same labels on other pages, with other citations and hyperref's bookkeeping
    second = ("\\relax\n\\newlabel{fig:eps}{{4}{13}{Kim}{figure.caption.9}{}}\n\\bibcite{kim}{1}\n"
              "\\newlabel{eq:a}{{{A.1}}{16}{App}{equation.A.1}{}}\n\\newlabel{eq:a@cref}{{[equation][1][]A.1}{16}}\n")
    assert label_numbers(first) == label_numbers(second) == (
        "\\newlabel{fig:eps}{{4}{}{}{}{}}\n\\newlabel{eq:a}{{{A.1}}{}{}{}{}}\n")


def test_a_missing_aux_is_one_line_and_exit_status_2(tmp_path):
    run = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "none.aux")], capture_output=True, text=True)
    assert run.returncode == 2 and run.stdout == ""
    assert len(run.stderr.strip().splitlines()) == 1 and "none.aux" in run.stderr
