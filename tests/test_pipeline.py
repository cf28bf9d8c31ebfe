"""The paper pipeline end to end, in temporary copies of the project (never in the working tree).

One clean build per session (module fixture `built`) backs most tests; tests that change files
work on a copy of that build. Marked slow: the ones that need extra clean builds.
"""

from __future__ import annotations

import copy
import json
import os
import re
import shutil
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "workflow" / "tools"))

import rebuild  # noqa: E402  (workflow/tools/rebuild.py)

ENV = {**os.environ, **rebuild.ENV}
ALL = "all" if rebuild.have_tex() else "outputs"


def snakemake(tree: Path, *args: str, check: bool = True) -> subprocess.CompletedProcess:
    proc = subprocess.run([sys.executable, "-m", "snakemake", *args], cwd=tree, env=ENV,
                          capture_output=True, text=True)
    if check and proc.returncode != 0:
        raise AssertionError(f"snakemake {' '.join(args)} failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
    return proc


def planned(tree: Path, *targets: str) -> Counter:
    """Jobs a dry run would execute, by rule (the 'Job stats' table)."""
    out = snakemake(tree, *targets, "--dry-run", "--cores", "1").stdout
    if "Nothing to be done" in out:
        return Counter()
    table = out.split("Job stats:", 1)[1]
    jobs = Counter()
    for line in table.splitlines()[3:]:
        parts = line.split()
        if not parts or parts[0] == "total":
            break
        jobs[parts[0]] = int(parts[1])
    return jobs


def copy_built(src: Path, dest: Path) -> Path:
    """A copy of a built tree with outputs, timestamps and Snakemake's metadata."""
    shutil.copytree(src, dest, symlinks=True, ignore=shutil.ignore_patterns(".venv", ".git"))
    return dest


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> Path:
    tree = rebuild.copy_tree(tmp_path_factory.mktemp("built") / "tree")
    rebuild.run_pipeline(tree, cores=2, target=ALL)
    return tree


@pytest.fixture
def fresh(tmp_path) -> Path:
    """A clean copy of the project, nothing built."""
    return rebuild.copy_tree(tmp_path / "fresh")


# ------------------------------------------------------------------------------ configuration
@pytest.mark.parametrize("old, new, message", [
    ("D1: 0.000296", "D1: -1", "config error: variants[kim].D1 = -1: must be > 0"),
    ('alpha: "3/2"', 'alpha: "7/19"', "config error: variants[kim].alpha = '7/19': must be a rational"),
    ("points: 61", "points: 1", "config error: variants[kim].g_range.points = 1: must be >= 2"),
    ("main_variant: kim", "main_variant: nope", "config error: main_variant = 'nope': must be one of kim"),
    ("spacing: log", "spacing: cubic", "config error: variants[kim].g_range.spacing = 'cubic': must be one of"),
])
def test_bad_config_is_one_line_naming_the_field(fresh, old, new, message):
    cfg = fresh / "config.yaml"
    text = cfg.read_text()
    assert old in text
    cfg.write_text(text.replace(old, new, 1))
    proc = snakemake(fresh, "--dry-run", check=False)
    assert proc.returncode != 0
    errors = [line for line in proc.stderr.splitlines() if line.startswith("config error:")]
    assert len(errors) == 1 and errors[0].startswith(message), proc.stderr
    assert "Traceback" not in proc.stderr


def test_yaml_exponent_notation_is_read_as_a_number(fresh):
    cfg = fresh / "config.yaml"
    cfg.write_text(cfg.read_text().replace("D1: 0.000296", "D1: 2.96e-4"))
    snakemake(fresh, "--dry-run")


# ------------------------------------------------------------------------------ caching (dry runs)
def test_one_figure_target_runs_only_what_it_needs(fresh):
    assert planned(fresh, "results/figures/fig1.pdf") == Counter(
        {"reference_trajectories": 1, "fig1_forward": 1, "main_figure": 1})


def test_the_full_plan(fresh):
    jobs = planned(fresh, ALL)
    for rule in ("series", "series_table", "reference_trajectories", "reference_eps_curve",
                 "reference_accuracy", "fig1_forward", "fig2_inverse", "fig3_phase", "fig4_eps",
                 "values", "printed_relation"):
        assert jobs[rule] == 1, rule
    assert jobs["main_figure"] == 8
    assert jobs["manuscript"] == (1 if ALL == "all" else 0)


def test_nothing_to_do_after_a_build(built):
    assert planned(built, ALL) == Counter()


def test_touching_a_figure_script_reruns_that_figure_and_the_manuscript(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    (tree / "workflow/scripts/fig1_forward.py").touch()
    expected = {"fig1_forward": 1, "main_figure": 2, ALL: 1}
    if ALL == "all":
        expected["manuscript"] = 1
    assert planned(tree, ALL) == Counter(expected)


def test_changing_d1_reruns_what_depends_on_omega_only(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    cfg = tree / "config.yaml"
    cfg.write_text(cfg.read_text().replace("D1: 0.000296", "D1: 0.0003"))
    jobs = planned(tree, ALL)
    assert {"reference_trajectories", "reference_eps_curve", "reference_accuracy", "fig1_forward",
            "fig2_inverse", "fig4_eps", "values"} <= set(jobs)
    for untouched in ("series", "series_table", "fig3_phase", "printed_relation", "manuscript_inputs"):
        assert untouched not in jobs


def test_a_change_in_the_integrator_reruns_reference_rules_not_series(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    src = tree / "src/restitution/collision.py"
    src.write_text(src.read_text() + "\n# a change\n")
    jobs = planned(tree, ALL)
    assert {"reference_trajectories", "reference_eps_curve", "reference_accuracy"} <= set(jobs)
    for untouched in ("series", "series_table", "fig3_phase", "printed_relation"):
        assert untouched not in jobs


def test_a_change_in_the_series_module_does_not_rerun_integrations(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    src = tree / "src/restitution/series.py"
    src.write_text(src.read_text() + "\n# a change\n")
    jobs = planned(tree, ALL)
    assert {"series", "fig1_forward", "fig2_inverse", "values"} <= set(jobs)
    for untouched in ("reference_trajectories", "reference_eps_curve", "reference_accuracy", "fig3_phase"):
        assert untouched not in jobs


# ------------------------------------------------------------------------------ outputs
def test_outputs_match_the_committed_manifest(built):
    manifest = json.loads(rebuild.MANIFEST.read_text())
    assert rebuild.compare(built, manifest) == []


def test_an_altered_expected_value_fails_the_check(built):
    manifest = json.loads(rebuild.MANIFEST.read_text())
    values_file = next(iter(manifest["values"]))
    series_file = next(iter(manifest["rationals"]))
    hashed = next(iter(manifest["sha256"]))

    bad = copy.deepcopy(manifest)
    bad["values"][values_file]["OmegaAtG"]["value"] *= 1.001
    assert any("OmegaAtG" in p for p in rebuild.compare(built, bad))

    bad = copy.deepcopy(manifest)
    bad["rationals"][series_file]["1"][0][1] = "-5/35"
    assert any("coefficient of tau^7/2" in p and "-5/35" in p for p in rebuild.compare(built, bad))

    bad = copy.deepcopy(manifest)
    bad["sha256"][hashed] = "0" * 64
    assert any(hashed in p and "sha256" in p for p in rebuild.compare(built, bad))

    bad = copy.deepcopy(manifest)
    table = next(iter(bad["tables"]))
    bad["tables"][table]["columns"]["eps"][3] = "0.123"
    assert any(table in p and "column eps" in p for p in rebuild.compare(built, bad))


def test_values_the_manuscript_prints(built):
    tex = (built / "results/kim/values/values.tex").read_text()
    macros = dict(re.findall(r"\\newcommand\{\\(\w+)\}\{(.*?)\}(?:\s|$)", tex))
    assert macros["PaperOmegaAtG"] == "0.5521"
    assert macros["SeriesAgreeFwd"] == macros["SeriesPrintedFwd"]
    values = json.loads((built / "results/kim/values/values.json").read_text())
    assert values["OmegaAtG"]["value"] == pytest.approx(0.000296 * 0.1 ** -0.75 * 0.0109 ** -1.25, rel=1e-12)


@pytest.mark.skipif(not rebuild.have_tex(), reason="needs pdflatex and latexmk")
def test_the_pdf_has_no_unresolved_references(built):
    assert (built / "results/paper/restitution.pdf").stat().st_size > 50_000
    log = (built / "build/paper/restitution.log").read_text(errors="replace")
    assert "undefined" not in log.lower(), [l for l in log.splitlines() if "undefined" in l.lower()]
    assert "Rerun to get" not in log


def test_a_figure_script_runs_as_a_notebook(built, tmp_path):
    """Outside Snakemake the script replays the pipeline's last run of its rule."""
    tree = copy_built(built, tmp_path / "t")
    before = (tree / "results/kim/figures/fig3.png").read_bytes()
    proc = subprocess.run([sys.executable, "../workflow/scripts/fig3_phase.py"], cwd=tree / "paper",
                          env=ENV, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert (tree / "results/kim/figures/fig3.png").read_bytes() == before


def test_jupytext_renders_the_scripts_as_notebooks(tmp_path):
    import jupytext

    for script in sorted((ROOT / "workflow/scripts").glob("fig*.py")):
        nb = jupytext.read(script)
        assert len(nb.cells) >= 3, script.name


# ------------------------------------------------------------------------------ clean rebuilds
@pytest.mark.slow
def test_two_clean_builds_give_identical_bytes(built, tmp_path):
    other = rebuild.copy_tree(tmp_path / "other")
    rebuild.run_pipeline(other, cores=2, target=ALL)
    a, b = rebuild.digest_results(built), rebuild.digest_results(other)
    assert len(a) >= 28
    assert [f for f in sorted(set(a) | set(b)) if a.get(f) != b.get(f)] == []


@pytest.mark.slow
def test_make_check_fails_on_an_altered_manifest(tmp_path):
    manifest = json.loads(rebuild.MANIFEST.read_text())
    values_file = next(iter(manifest["values"]))
    manifest["values"][values_file]["EpsAtG"]["value"] = 0.5
    altered = tmp_path / "manifest.json"
    altered.write_text(json.dumps(manifest))
    proc = subprocess.run([sys.executable, str(ROOT / "workflow/tools/rebuild.py"), "--manifest", str(altered),
                           "check"], env=ENV, capture_output=True, text=True)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "check FAILED: 1 difference(s)" in proc.stdout
    assert "EpsAtG" in proc.stdout and "expected 0.5" in proc.stdout


@pytest.mark.slow
def test_changing_d1_changes_omega_in_the_manuscript(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    cfg = tree / "config.yaml"
    cfg.write_text(cfg.read_text().replace("D1: 0.000296", "D1: 0.0004"))
    old = (built / "results/kim/values/values.tex").read_text()
    rebuild.run_pipeline(tree, cores=2, target=ALL)
    new = (tree / "results/kim/values/values.tex").read_text()
    get = lambda text: re.search(r"\\newcommand\{\\OmegaAtG\}\{([^}]*)\}", text).group(1)  # noqa: E731
    assert float(get(new)) == pytest.approx(float(get(old)) * 0.0004 / 0.000296, rel=1e-3)
    if ALL == "all":
        assert (tree / "results/paper/restitution.pdf").read_bytes() != \
            (built / "results/paper/restitution.pdf").read_bytes()
