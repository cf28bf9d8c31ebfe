"""The stability atlas: the library (grid, plan, shards, invariant checks) and the pipeline's table.

The invariants are asserted over the whole grid of the atlas the pipeline generates: in a clean
build in a temporary copy (slow, shared with the fault tests) and, when it exists, in the working
tree's results/stability/atlas.csv. A coarse atlas built through the library covers every exponent
pair of the default grid over the whole Omega range in a few seconds.
"""

from __future__ import annotations

import csv
import math
from fractions import Fraction

import numpy as np
import pytest

from restitution.audit import stability as st
from restitution.audit import stability_checks as sc
from restitution.core.errors import ParameterError




def _read(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


# ------------------------------------------------------------------------------------ the grid
def test_omega_grid_has_exact_decades_and_the_requested_density():
    grid = st.omega_grid(1e-8, 1e8, 2)
    assert grid.size == 33 and grid[0] == 1e-8 and grid[-1] == 1e8
    assert 1.0 in grid and 1e-4 in grid
    assert np.allclose(np.diff(np.log10(grid)), 0.5, rtol=0, atol=1e-12)
    assert np.array_equal(st.omega_grid(1e-8, 1e8, 2), grid)      # same floats every time


def test_default_spec_is_the_issue_grid():
    spec = st.AtlasSpec.from_config({})
    assert spec.alphas == ("1", "5/4", "3/2", "2", "5/2")
    assert spec.gammas == ("0", "1/2", "1", "3/2")
    assert (spec.omega_min, spec.omega_max) == (1e-8, 1e8)
    assert len(spec.pairs) == 20
    assert spec.stated_accuracy == pytest.approx(10 * spec.rtol + 1e-13)


def test_exponents_are_normalised():
    spec = st.AtlasSpec.from_config({"alphas": ["6/4", 2], "gammas": ["2/4", 0]})
    assert spec.alphas == ("3/2", "2") and spec.gammas == ("1/2", "0")
    with pytest.raises(ParameterError, match="gammas"):
        st.AtlasSpec.from_config({"gammas": ["2/4", 0.5]})     # the same exponent twice


@pytest.mark.parametrize("cfg, field", [
    ({"per_decade": 0}, "per_decade"),
    ({"per_decade": 2.5}, "per_decade"),
    ({"per_decade": True}, "per_decade"),
    ({"omega_min": 0}, "omega_min"),
    ({"omega_min": -1e-8}, "omega_min"),
    ({"omega_min": float("nan")}, "omega_min"),
    ({"omega_max": float("inf")}, "omega_max"),
    ({"omega_min": 3e-8}, "omega_min"),                  # not a power of ten
    ({"omega_max": 1e20}, "omega_max"),                  # beyond what the atlas accepts
    ({"omega_min": 1e4, "omega_max": 1e2}, "omega_max"),
    ({"rtol": 0}, "rtol"),
    ({"rtol": 1e-16}, "rtol"),
    ({"rtol": "loose"}, "rtol"),
    ({"accuracy": 1e-12}, "accuracy"),                   # tighter than rtol cannot be claimed
    ({"tight_rtol": 1e-6}, "tight_rtol"),                # looser than rtol compares nothing
    ({"tight_decades": 0}, "tight_decades"),
    ({"reference_omegas": [3e-3]}, "reference_omegas"),  # not on the grid
    ({"reference_omegas": 1e-8}, "reference_omegas"),    # not a list
    ({"reference_omegas": [1e9]}, "reference_omegas"),   # outside the range
    ({"reference_digits": 4}, "reference_digits"),
    ({"alphas": []}, "alphas"),
    ({"alphas": "3/2"}, "alphas"),
    ({"alphas": ["0"]}, "alphas"),
    ({"alphas": ["-1"]}, "alphas"),
    ({"alphas": ["7/19"]}, "alphas"),
    ({"alphas": ["3/2", "1.5"]}, "alphas"),              # the same exponent twice
    ({"gammas": ["-1/2"]}, "gammas"),
    ({"gammas": [float("nan")]}, "gammas"),
    ({"per_decad": 2}, "per_decad"),                     # mistyped key
])
def test_bad_settings_name_the_field(cfg, field):
    with pytest.raises(ParameterError) as err:
        st.AtlasSpec.from_config(cfg)
    assert err.value.field.startswith(field)
    assert "\n" not in str(err.value)


# ------------------------------------------------------------------------------------ the plan
def test_plan_marks_tight_and_reference_points():
    spec = st.AtlasSpec.from_config({})
    points = st.plan(spec)
    assert len(points) == 20 * 33
    one = [p for p in points if (p.alpha, p.gamma) == ("3/2", "1")]
    assert [p.omega for p in one if p.tight] == [1e-8, 1e-4, 1.0, 1e4, 1e8]
    assert [p.omega for p in one if p.reference] == [1e-8, 1e8]
    # alpha <= gamma: the mpmath reference cost grows like 1/Omega; it moves up to 1e-2
    creep = [p for p in points if (p.alpha, p.gamma) == ("1", "3/2")]
    assert [p.omega for p in creep if p.reference] == [1e-2, 1e8]


@pytest.mark.parametrize("n", [1, 2, 3, 7])
def test_shards_partition_the_plan_and_balance_the_cost(n):
    spec = st.AtlasSpec.from_config({})
    points = st.plan(spec)
    shards = [st.shard(points, k, n, spec) for k in range(n)]
    flat = [p for s in shards for p in s]
    assert sorted(flat, key=points.index) == points and len(flat) == len(points)
    costs = [sum(st.estimated_cost(p, spec) for p in s) for s in shards]
    assert max(costs) - min(costs) <= max(st.estimated_cost(p, spec) for p in points)


def test_bad_shard_numbers():
    points = st.plan(st.AtlasSpec.from_config({"alphas": ["3/2"], "gammas": ["1"]}))
    for k, n in ((2, 2), (-1, 2), (0, 0), (0, 1.5)):
        with pytest.raises(ParameterError):
            st.shard(points, k, n)


# ------------------------------------------------------------------------------------ the checks
def _record(omega, eps, **kw):
    rec = {"alpha": "3/2", "gamma": "1", "omega": omega, "eps": eps, "tau_b": 1.0, "x_b": 1.0, "tau_c": 2.0,
           "x_c": 0.5, "ended_by": "force", "status": "ok", "err_tight": math.nan, "worst_tight": "",
           "err_ref": math.nan, "worst_ref": "", "err_exact": math.nan, "worst_exact": ""}
    rec.update(kw)
    return rec


@pytest.mark.parametrize("bad, check", [
    ({"eps": 1.0 + 1e-12}, "eps_range"),
    ({"eps": 0.0}, "eps_range"),
    ({"tau_c": 0.5}, "order"),
    ({"x_c": 2.0}, "order"),
    ({"x_c": 0.0}, "x_c"),
    ({"ended_by": "separation", "x_c": 0.0}, "ended_by"),
    ({"tau_b": math.nan}, "finite"),
    ({"x_c": math.inf}, "finite"),
    ({"status": "IntegrationError: solve_ivp failed"}, "finite"),
    ({"err_tight": 1e-6, "worst_tight": "tau_c"}, "tight"),
    ({"err_ref": math.inf, "worst_ref": "ended_by"}, "reference"),
    ({"err_exact": 2e-9, "worst_exact": "eps"}, "exact"),
])
def test_each_invariant_is_checked(bad, check):
    good, _ = sc.check_invariants([_record(2.0, 0.4)], accuracy=1e-9)
    assert good == []
    violations, _ = sc.check_invariants([_record(2.0, **{"eps": 0.4, **bad})], accuracy=1e-9)
    assert [v.check for v in violations] == [check], violations
    assert violations[0].omega == 2.0 and "alpha=3/2" in str(violations[0])


def test_monotonicity_allows_only_unresolvable_steps():
    ok, unresolved = sc.check_invariants([_record(1.0, 0.5), _record(2.0, 0.5 - 1e-10), _record(3.0, 0.6)], 1e-9)
    assert ok == [] and unresolved == {("3/2", "1"): 1}
    bad, _ = sc.check_invariants([_record(1.0, 0.5), _record(2.0, 0.5 - 1e-6), _record(3.0, 0.6)], 1e-9)
    assert [v.check for v in bad] == ["monotone"]


def test_a_pair_with_large_exponents_is_held_to_the_accuracy_collide_states_for_it():
    """collide states more for alpha + gamma > 4 (core.conditioning.exponent_factor); the atlas holds
    each pair to what collide states for it, not to the common pairs' accuracy."""
    from restitution.core.collision import collide

    spec = st.AtlasSpec.from_config({"alphas": ["8", "3/2"], "gammas": ["7", "1"]})
    common = spec.stated_accuracy
    assert spec.accuracy_for("3/2", "1") == common
    assert spec.accuracy_for("8", "7") == pytest.approx(common * (15 / 4) ** 3)
    assert collide(("8", "7"), 1.0, rtol=spec.rtol).error_bound == pytest.approx(spec.accuracy_for("8", "7"))
    err = 10 * common   # within the large pair's statement, not the common one's
    records = [_record(2.0, 0.4, alpha="8", gamma="7", err_tight=err), _record(2.0, 0.4, err_tight=err)]
    violations, _ = sc.check_invariants(records, spec.accuracy_for)
    assert [(v.alpha, v.check) for v in violations] == [("3/2", "tight")]
    summary = {r["alpha"]: r["accuracy"] for r in sc.summarize(records, spec.accuracy_for)}
    assert summary == {"8": spec.accuracy_for("8", "7"), "3/2": common}
    fixed = st.AtlasSpec.from_config({"alphas": ["8"], "gammas": ["7"], "accuracy": 1e-9})
    assert fixed.accuracy_for("8", "7") == 1e-9


def test_records_from_a_csv_are_checked_the_same(tmp_path):
    records = [_record(1.0, 0.3), _record(2.0, 1.5)]
    path = tmp_path / "a.csv"
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(records[0]))
        w.writeheader()
        w.writerows(records)
    violations, _ = sc.check_invariants(_read(path), 1e-9)
    assert [v.check for v in violations] == ["eps_range"]


def test_a_failing_integration_is_recorded_not_raised(monkeypatch):
    import restitution.core.collision as collision

    def broken(*args, **kwargs):
        raise collision.IntegrationError("solve_ivp failed on (0, 1): step size too small")

    monkeypatch.setattr(collision, "collide", broken)
    spec = st.AtlasSpec.from_config({"alphas": ["3/2"], "gammas": ["1"], "per_decade": 1,
                                     "omega_min": 1e-1, "omega_max": 1e1, "reference_omegas": []})
    records = st.run_atlas(spec)
    assert all(r["status"].startswith("IntegrationError") for r in records)
    violations, _ = sc.check_invariants(records, spec.stated_accuracy)
    assert {v.check for v in violations} == {"finite"} and len(violations) == len(records)


# ------------------------------------------------------------------------------------ a coarse atlas
@pytest.fixture(scope="module")
def coarse():
    """Every default exponent pair, one Omega per decade from 1e-8 to 1e8, tight runs every 8
    decades, the mpmath reference at Omega = 1e8 (cheap there): ~10 s."""
    spec = st.AtlasSpec.from_config({"per_decade": 1, "tight_decades": 8, "reference_omegas": [1e8]})
    return spec, st.run_atlas(spec)


@pytest.mark.slow
def test_coarse_atlas_holds_every_invariant(coarse):
    spec, records = coarse
    violations, unresolved = sc.check_invariants(records, spec.stated_accuracy)
    assert violations == [], "\n".join(map(str, violations))
    assert sum(unresolved.values()) == 0
    assert len(records) == 20 * 17
    # what the integrator's authors found: alpha > gamma ends by the force, alpha <= gamma by separation
    for r in records:
        assert r["ended_by"] == ("force" if Fraction(r["alpha"]) > Fraction(r["gamma"]) else "separation")


@pytest.mark.slow
def test_coarse_atlas_compares_where_it_should(coarse):
    spec, records = coarse
    summary = {(r["alpha"], r["gamma"]): r for r in sc.summarize(records, spec.stated_accuracy)}
    assert all(r["n_tight"] == 3 and r["n_ref"] == 1 for r in summary.values())
    assert summary[("1", "0")]["n_exact"] == 17 and summary[("1", "1")]["n_exact"] == 17
    assert summary[("3/2", "1")]["n_exact"] == 0
    assert max(r["max_err_tight"] for r in summary.values()) <= spec.stated_accuracy
    # x_c of order 1e-32 at Omega = 1e8 for alpha - gamma = 1/4, still positive and accurate
    assert summary[("5/4", "1")]["x_c_min"] == pytest.approx(1e-32, rel=1e-6)


@pytest.mark.slow
def test_shards_give_the_same_records_as_one_run(coarse):
    spec, records = coarse
    small = st.AtlasSpec.from_config({"alphas": ["1", "2"], "gammas": ["1/2"], "per_decade": 1,
                                      "tight_decades": 8, "reference_omegas": [1e8]})
    points = st.plan(small)
    merged = [r for k in range(3) for r in st.run_atlas(small, st.shard(points, k, 3, small))]
    key = lambda r: (r["alpha"], r["index"])  # noqa: E731
    one = {key(r): r for r in records if r["gamma"] == "1/2" and r["alpha"] in ("1", "2")}
    assert len(merged) == len(one)
    for r in merged:
        ref = one[key(r)]
        assert all(r[q] == ref[q] for q in st.QUANTITIES)


@pytest.mark.slow
def test_the_limits_meet_the_ends_of_the_atlas(coarse):
    pytest.importorskip("restitution.core.asymptotics")
    spec, records = coarse
    limits = {(d["alpha"], d["gamma"]): d for d in sc.limit_agreement(records)}
    assert len(limits) == 20
    for (a, g), d in limits.items():
        if Fraction(a) > Fraction(g):
            assert d["dev_eps_viscous"] < 1e-9 and d["dev_tau_c_viscous"] < 1e-5, d
    # Hertz with Kuwabara-Kono damping: 1 - eps at Omega = 1e8 against Ramirez et al.'s C1, C2
    from restitution.core.asymptotics import elastic_limit

    hertz = elastic_limit(("3/2", "1/2"))
    assert hertz.C1 == pytest.approx(1.1534489, abs=1e-6) and hertz.C2 == pytest.approx(0.7982666, abs=1e-6)
    assert limits[("3/2", "1/2")]["dev_one_minus_eps_elastic"] < 1e-4


# ------------------------------------------------------------------------------------ the pipeline's table
def _assert_pipeline_atlas(results):
    rows = _read(results / "stability" / "atlas.csv")
    spec = st.AtlasSpec()          # the pipeline's defaults (config.yaml may override: read them back)
    pairs = sorted({(r["alpha"], r["gamma"]) for r in rows})
    omegas = sorted({float(r["omega"]) for r in rows})
    assert len(rows) == len(pairs) * len(omegas), "every pair at every Omega, once"
    assert omegas[0] <= spec.omega_min and omegas[-1] >= spec.omega_max
    assert {"1", "5/4", "3/2", "2", "5/2"} <= {a for a, _ in pairs}
    assert {"0", "1/2", "1", "3/2"} <= {g for _, g in pairs}
    summary = _read(results / "stability" / "summary.csv")
    accuracy = float(summary[0]["accuracy"])
    assert len(summary) == len(pairs) and all(float(r["accuracy"]) == accuracy for r in summary)
    violations, unresolved = sc.check_invariants(rows, accuracy)
    assert violations == [], "\n".join(map(str, violations))
    assert _read(results / "stability" / "violations.csv") == []
    assert sum(1 for r in rows if r["err_ref"]) >= 2 * len(pairs)
    assert sum(1 for r in rows if r["err_tight"]) >= 2 * len(pairs)
    for name in ("atlas.pdf", "atlas.png", "summary.tex", "values.tex"):
        assert (results / "stability" / name).stat().st_size > 0, name


@pytest.mark.slow
def test_pipeline_atlas_holds_every_invariant(built):
    """The session's clean build (conftest.py), not the working tree: its results/ may be stale."""
    _assert_pipeline_atlas(built / "results")
