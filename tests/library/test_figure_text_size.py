"""Every text of a manuscript figure prints at 7 pt or more (issue 53, third referee reading): the
size is read from the PDF's own text operators (restitution_workflow.pdf_text), mathtext exponents
and subscripts included, at the width the manuscript prints the figure; save_figure(width=...)
narrows a figure until that holds and refuses when it cannot."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from restitution_workflow.engine_record import lammps_version  # noqa: E402
from restitution_workflow.pdf_text import measure  # noqa: E402
from restitution_workflow.pipeline import (MIN_PRINTED_PT, STYLE, printed_text_sizes,  # noqa: E402
                                           save_figure)


def _figure(width_in=5.6, tick=12, title_pt=10):
    plt.rcdefaults()
    plt.rcParams.update(STYLE)
    plt.rcParams.update({"xtick.labelsize": tick, "ytick.labelsize": tick})
    fig, ax = plt.subplots(figsize=(width_in, 3.8))
    ax.loglog([1e-3, 1e2], [1e-4, 1e1], label=r"$C_1\mu$")
    ax.set_title("a title", fontsize=title_pt)
    ax.legend()
    fig.set_layout_engine("tight")
    return fig


def test_a_pdf_exponent_is_measured_at_seven_tenths_of_its_tick_label(tmp_path):
    fig = _figure()
    fig.savefig(tmp_path / "f.pdf")
    sizes = sorted({round(s, 2) for _, _, s, _ in measure((tmp_path / "f.pdf").read_bytes(), inside_forms=False)})
    # tick labels at 12 pt, their exponents at 0.7 of that, the legend's subscript at 0.7 of 10 pt
    assert 12.0 in sizes and 8.4 in sizes and 7.0 in sizes
    plt.close(fig)


def test_the_printed_size_scales_with_the_width_in_print():
    fig = _figure()
    small, scale = printed_text_sizes(fig, 0.5)
    large, scale_full = printed_text_sizes(fig, 1.0)
    assert scale_full == pytest.approx(2 * scale) and large == pytest.approx(2 * small)
    plt.close(fig)


def test_save_figure_narrows_a_figure_until_its_smallest_text_is_seven_points(tmp_path):
    fig = _figure(width_in=7.5)
    assert printed_text_sizes(fig, 0.75)[0] < MIN_PRINTED_PT   # as drawn, too small in print
    save_figure(fig, tmp_path / "f.pdf", tmp_path / "f.png", width=0.75)
    data = (tmp_path / "f.pdf").read_bytes()
    import re
    box = [float(x) for x in re.search(rb"/MediaBox\s*\[([^\]]*)\]", data).group(1).split()]
    scale = 0.75 * 160 / 25.4 * 72 / (box[2] - box[0])
    assert min(s for _, _, s, _ in measure(data, inside_forms=False)) * scale >= MIN_PRINTED_PT
    plt.close(fig)


def test_save_figure_refuses_text_too_wide_to_print_large_enough(tmp_path):
    fig = _figure()
    fig.suptitle("a title far too long to be made to fit " * 4, fontsize=8)   # its width does not shrink
    with pytest.raises(RuntimeError, match="pt"):
        save_figure(fig, tmp_path / "f.pdf", tmp_path / "f.png", width=0.5)
    assert not (tmp_path / "f.pdf").exists()
    plt.close(fig)


def test_lammps_version_is_read_from_the_screen_and_must_agree():
    screen = "LAMMPS (22 Jul 2025 - Update 4)\n  using 1 OpenMP thread(s)\n"
    assert lammps_version([screen, screen]) == "22 Jul 2025 - Update 4"
    with pytest.raises(ValueError, match="different"):
        lammps_version([screen, screen.replace("Update 4", "Update 3")])
    with pytest.raises(ValueError, match="version line"):
        lammps_version(["Created orthogonal box\n"])
