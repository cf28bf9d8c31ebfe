"""Variants as pipeline inputs: per-variant results and sections, caching per variant, validation
against known results, one-off studies and the cluster profile.

Uses the session's clean build (conftest.py's `built`); tests that change
files work on copies of it or on fresh copies of the project.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import pytest
import yaml


from pipeline_tree import ALL, FLAT, FLAT_CONFIG, copy_built  # noqa: E402
from test_pipeline import (assert_one_config_error, PER_VARIANT, ROOT, VARIANT_NAMES, planned, read_csv,  # noqa: E402
                           rebuild, snakemake)

#: Manuscript-level jobs: they gather every variant, so a new variant reruns them (uniform_atlas: its table's rows
#: of the variants' exponent pairs refer to the article's table instead of repeating it; it only reads the shards).
#: jobs that read every variant (chatterjee_coefficients compares the prior-art coefficients at each
#: variant's force law), rerun when one is added
GATHERING = {"compare_variants", "variants_tex", "uniform_section", "uniform_atlas", "chatterjee_coefficients",
             "article_labels", "manuscript", "supplement", ALL}


def jobs_by_variant(tree: Path, *args: str) -> dict[str, set]:
    """Dry run: rule names planned per value of the variant wildcard ('' for jobs without one)."""
    out = snakemake(tree, *args, "--dry-run", "--cores", "1").stdout
    plan: dict[str, set] = {}
    rule = None
    for line in out.splitlines():
        m = re.match(r"(?:local)?rule (\w+):", line)
        if m:
            rule = m.group(1)
            plan.setdefault("", set()).add(rule)
            continue
        m = re.match(r"\s+wildcards: .*variant=([\w-]+)", line)
        if m and rule:
            plan[""].discard(rule)
            plan.setdefault(m.group(1), set()).add(rule)
    return plan


# ------------------------------------------------------------------------------ the default variants
def test_each_default_variant_has_its_results_and_section(built):
    for name in VARIANT_NAMES:
        d = built / "results" / name
        listed = (d / "study.txt").read_text().splitlines()[1:]
        assert listed and all((built / f).exists() for f in listed)
        for f in ("series/table.tex", "reference/eps_curve.csv", "connection/readings.csv", "connection/fit.json",
                  "connection/eps_errors.tex", "validation/validation.json", "figures/fig4.pdf"):
            assert (d / f).exists(), f"{name}: {f}"
    sections = (built / "results/paper/variants.tex").read_text()
    assert re.findall(r"\\input\{results/(\w+)/section.tex\}", sections) == ["hertz", "dashpot"]
    assert (built / "results/kim/claims.csv").exists()
    assert not (built / "results/hertz/claims.csv").exists()  # the paper's claims are for its exponents


def test_sections_say_where_the_papers_procedure_does_not_apply(built):
    dash = (built / "results/dashpot/section.tex").read_text()
    assert r"\tau_0" in dash and "does not exist" in dash            # gamma = 0: no reference point
    assert "does not depend on $g$" in dash                           # alpha - 1 - 2 gamma = 0
    assert "no least-squares connection" in dash
    fit = json.loads((built / "results/dashpot/connection/fit.json").read_text())
    assert not fit["applies"] and "Omega does not depend on g" in fit["reason"]
    errors = read_csv(built / "results/dashpot/connection/eps_errors.csv")
    assert (errors["n_defined"] == 0).all()
    hertz = (built / "results/hertz/section.tex").read_text()
    assert r"\input{results/hertz/connection/readings.tex}" in hertz
    assert "least-squares quadratic" in hertz


# ------------------------------------------------------------------------------ validation
def test_every_validation_check_passes_and_the_expected_ones_are_there(built):
    checks = {}
    for name in VARIANT_NAMES:
        for c in json.loads((built / f"results/{name}/validation/validation.json").read_text())["checks"]:
            checks[(name, c["check"])] = c
    assert set(checks) == {("dashpot", "linear spring-dashpot, closed form"),
                           ("dashpot", "restitution independent of the impact speed"),
                           ("hertz", "two-term elastic expansion without the end term, error exponent"),
                           ("hertz", "the same with this work's end-of-contact term, error exponent"),
                           ("hertz", "Padé form as implemented in")}
    failed = [k for k, c in checks.items() if not c["passed"]]
    assert failed == []
    table = (built / "results/paper/validation.tex").read_text()
    assert table.count("within") == len(checks)   # each check within its tolerance


def test_dashpot_matches_its_closed_form_directly(built):
    from restitution.core.dashpot import dashpot_collision

    grid = read_csv(built / "results/dashpot/validation/known.csv")
    worst = max(abs(e / dashpot_collision(w).eps - 1) for w, e in zip(grid["omega"], grid["eps_reference"]))
    assert worst < 1e-8


def test_hertz_against_the_elastic_series_and_the_pade_form(built):
    import numpy as np

    known = read_csv(built / "results/hertz/validation/known.csv")
    omega, ref = known["omega"].to_numpy(), known["eps_reference"].to_numpy()
    series_err = np.abs(known["eps_elastic_series"].to_numpy() / ref - 1)
    top = omega >= omega.max() / 100
    assert np.all(np.diff(series_err[top]) < 0)          # the series converges as Omega grows
    pade_err = np.abs(known["eps_pade"].to_numpy() / ref - 1)
    assert pade_err[omega ** (-0.6) <= 0.25].max() < 1e-3
    assert pade_err[omega < 1e-2].min() > 0.1             # and is not meant for the viscous end


def test_eps_does_not_depend_on_g_when_gamma_is_half_of_alpha_minus_one(built):
    curve = read_csv(built / "results/dashpot/reference/eps_curve.csv")
    assert curve["g"].nunique() == len(curve) > 1
    assert curve["omega"].nunique() == 1
    assert (curve["eps"].max() - curve["eps"].min()) <= 1e-12 * curve["eps"].mean()


# ------------------------------------------------------------------------------ caching per variant
def test_adding_a_fourth_variant_reruns_only_its_jobs_and_the_manuscript(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    cfg = tree / "config.yaml"
    data = yaml.safe_load(cfg.read_text())
    data["variants"].append(FLAT)
    cfg.write_text(yaml.safe_dump(data, sort_keys=False))
    plan = jobs_by_variant(tree, ALL)
    assert set(plan) <= {"", "flat"}, plan                     # nothing of kim, hertz, dashpot
    assert plan["flat"] >= set(PER_VARIANT) | {"variant_section"}
    assert plan[""] <= GATHERING
    assert "manuscript" in plan[""] or ALL != "all"


def test_changing_one_variant_leaves_the_others_alone(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    cfg = tree / "config.yaml"
    cfg.write_text(cfg.read_text().replace("D2: 0.25", "D2: 0.3", 1))
    plan = jobs_by_variant(tree, ALL)
    assert set(plan) <= {"", "hertz"}, plan
    assert {"reference_eps_curve", "connection_fit", "values", "variant_section"} <= plan["hertz"]
    assert "fig3_phase" not in plan["hertz"]  # the damped-only motion does not involve D2


# ------------------------------------------------------------------------------ one-off studies
def test_a_one_off_study_through_config_plans_only_its_own_jobs(built):
    plan = jobs_by_variant(built, "results/flat/study.txt", "--config", FLAT_CONFIG)
    assert set(plan) <= {"", "flat"}
    assert plan["flat"] >= set(PER_VARIANT) | {"variant_section"}
    assert plan.get("", set()) == set()


@pytest.mark.slow
def test_a_one_off_study_runs_into_its_own_folder(built, flat_study):
    """Gamma = (alpha - 1)/2 with gamma > 0: eps independent of g, validated; nothing else is touched.
    The study ran into a copy of the clean build (conftest.py's `flat_study`, shared with the cluster test)."""
    tree = flat_study
    before = rebuild.digest_results(built)
    after = rebuild.digest_results(tree)
    changed = {f for f in set(before) | set(after) if before.get(f) != after.get(f)}
    assert changed and all(f.startswith("results/flat/") for f in changed)
    checks = json.loads((tree / "results/flat/validation/validation.json").read_text())["checks"]
    assert [c["check"] for c in checks] == ["restitution independent of the impact speed"] and checks[0]["passed"]
    curve = read_csv(tree / "results/flat/reference/eps_curve.csv")
    assert curve["eps"].max() - curve["eps"].min() <= 1e-12 * curve["eps"].mean()
    section = (tree / "results/flat/section.tex").read_text()
    assert "does not depend on $g$" in section


# ------------------------------------------------------------------------------ configuration
@pytest.mark.parametrize("old, new, message", [
    ("readings: [P-N2-K2-Dprinted,", "readings: [P-N9-K2-Dprinted,",
     "config error: variants[hertz].readings = 'P-N9-K2-Dprinted': must be one of"),
    ("figure_reading: C-N2-K2-Dprinted", "figure_reading: nope", "config error: connection.figure_reading = 'nope'"),
    ("main_variant: kim", "main_variant: hertz", "config error: main_variant = 'hertz': must have the paper's"),
    ("  - name: dashpot", "  - name: hertz", "config error: variants[].name = 'hertz': must be unique"),
])
def test_bad_variant_config_is_one_line(fresh, old, new, message):
    assert_one_config_error(fresh, old, new, message)


# ------------------------------------------------------------------------------ cluster profile
def test_the_slurm_profile_parses_and_names_real_rules(fresh, tmp_path):
    """A dry run with the profile; without the SLURM plugin installed, on a copy that only swaps the
    executor for the local one (the resources and every other setting stay as shipped)."""
    profile = ROOT / "workflow/profiles/slurm/config.yaml"
    settings = yaml.safe_load(profile.read_text())
    assert settings["executor"] == "slurm"
    rules = set(snakemake(fresh, "--list-rules").stdout.split())
    assert set(settings["set-resources"]) <= rules
    for res in settings["set-resources"].values():
        assert res.get("runtime", 1) > 0 and res.get("mem_mb", 1) > 0
    try:
        import snakemake_executor_plugin_slurm  # noqa: F401
        local = profile.parent
    except ImportError:
        local = tmp_path / "slurm-local"
        local.mkdir()
        (local / "config.yaml").write_text(profile.read_text().replace("executor: slurm", "executor: local", 1))
    proc = snakemake(fresh, "--profile", str(local), "--dry-run", ALL)
    assert "manuscript" in proc.stdout or ALL != "all"


def test_the_docs_document_one_off_studies_and_the_cluster_profile():
    readme = (ROOT / "docs" / "howto" / "pipeline.md").read_text()     # the README's, until issue 45
    assert "extra_variants" in readme and "workflow/profiles/slurm" in readme
    assert FLAT_CONFIG in readme  # the documented one-off command is the tested one
