"""The claims ledger: values computed by the library, verdicts decided from them (and only them)."""

import copy
import math

import pytest

from restitution.audit import claim_values, claims
from restitution.audit import printed
from restitution.audit.readings import Reading

PAPER = {"alpha": printed.ALPHA, "gamma": printed.GAMMA, "D1": printed.D1, "D2": printed.D2}
FAST = {"points": 6, "tracking_samples": 301, "radius_max_power": 61,
        "readings": [Reading(omega_orders=2), Reading()]}


@pytest.fixture(scope="module")
def values():
    inputs = claim_values.reference_inputs(PAPER, FAST)
    return claim_values.compute_claim_values(PAPER, FAST, **inputs)


@pytest.fixture(scope="module")
def rows(values):
    return claims.build_claims(values)


def _find(rows, text):
    hits = [r for r in rows if text in r["claim"]]
    assert hits, f"no row with {text!r}"
    return hits[0]


@pytest.mark.slow
def test_every_row_has_every_column_and_a_valid_verdict(rows):
    assert len(rows) > 10
    for r in rows:
        assert tuple(r) == claims.COLUMNS
        assert r["verdict"] in claims.VERDICTS
        assert r["claim"] and r["where"] and r["our_value"] != ""


def test_every_claim_of_the_issue_has_a_row(rows):
    for text in ["forward and inverse series x_0..x_4", "D* =", "Omega at g", "tau_b at g",
                 "forward series stop tracking", "inverse series stop tracking",
                 "c0, c1, c2 of the connection", "Omega proportional to g^(-3/4)",
                 "terms in g^(1/4)", "shape of figure 4", "Taylor series valid", "G tanh",
                 "Delta = tau_b - tau_0", "Delta~ ="]:
        _find(rows, text)


def test_computed_values_and_their_verdicts(values, rows):
    # computed, not typed: the formula gives ~0.473 where the paper prints 0.5521
    assert values["omega_at_g"] == pytest.approx(0.4726, abs=1e-4)
    assert _find(rows, "Omega at g")["verdict"] == claims.NOT_REPRODUCED
    assert values["d_star"] == pytest.approx(2.835e-3, rel=1e-3)
    assert _find(rows, "D* =")["verdict"] == claims.REPRODUCED
    assert all(r["verdict"] == claims.REPRODUCED for r in rows if "series x" in r["claim"])
    assert _find(rows, "Omega proportional")["verdict"] == claims.REPRODUCED
    assert values["radius_forward"] == pytest.approx(math.pi / math.sqrt(2), rel=1e-4)
    assert values["radius_inverse"] == pytest.approx(math.pi / math.sqrt(2), rel=1e-4)
    assert _find(rows, "forward damped-only Taylor")["verdict"] == claims.REPRODUCED
    assert _find(rows, "inverse damped-only Taylor")["verdict"] == claims.NOT_REPRODUCED
    assert _find(rows, "G tanh")["verdict"] == claims.NOT_REPRODUCED
    assert _find(rows, "Delta = tau_b")["verdict"] == claims.REPRODUCED


@pytest.mark.parametrize("path,new,claim,before,after", [
    (("omega_at_g",), printed.OMEGA_AT_G, "Omega at g", claims.NOT_REPRODUCED, claims.REPRODUCED),
    (("d_star",), 1e-2, "D* =", claims.REPRODUCED, claims.NOT_REPRODUCED),
    (("tau_b_at_g",), 2.21, "tau_b at g", claims.NOT_REPRODUCED, claims.REPRODUCED),
    (("radius_inverse",), math.sqrt(2), "inverse damped-only Taylor", claims.NOT_REPRODUCED, claims.REPRODUCED),
    (("omega_g_exponent",), "-2/3", "Omega proportional", claims.REPRODUCED, claims.NOT_REPRODUCED),
    (("delta_equal",), [False, True], "Delta = tau_b", claims.REPRODUCED, claims.NOT_REPRODUCED),
])
def test_perturbing_a_value_flips_its_verdict(values, path, new, claim, before, after):
    assert _find(claims.build_claims(values), claim)["verdict"] == before
    changed = copy.deepcopy(values)
    changed[path[0]] = new
    assert _find(claims.build_claims(changed), claim)["verdict"] == after


def _triple(rows):
    return next(r for r in rows if r["id"] == "c-triple")


def test_a_reading_that_hit_the_printed_coefficients_would_be_reproduced(values):
    changed = copy.deepcopy(values)
    changed["readings"][0]["c"] = list(printed.PRINTED_C)
    changed["readings"][0]["defined"] = True
    row = _triple(claims.build_claims(changed))
    assert row["verdict"] == claims.REPRODUCED and row["our_value"].startswith("1 of 2 readings")
    changed["readings"][0]["c"][2] += 1e-3
    assert _triple(claims.build_claims(changed))["verdict"] == claims.NOT_REPRODUCED


def test_one_row_per_statement_of_the_paper(rows, values):
    """The printed (c0, c1, c2) is one statement: the readings, the least-squares fit and the
    consequences of using the printed c's are evidence in its one row, judged to the printed
    digits (not to the fit's standard errors, which are not statistical)."""
    ids = [r["id"] for r in rows]
    assert len(set(ids)) == len(ids)
    triple = f"({printed.PRINTED_C[0]}, {printed.PRINTED_C[1]}, {printed.PRINTED_C[2]})"
    assert [r["id"] for r in rows if r["paper_value"] == triple] == ["c-triple"]
    row = _triple(rows)
    assert row["verdict"] == claims.NOT_REPRODUCED and "5e-05 each" in row["tolerance"]
    assert f"{values['fit']['c'][0]:.4f}" in row["our_value"] and "readings" in row["our_value"]
    fitted_on_the_printed = copy.deepcopy(values)
    fitted_on_the_printed["fit"]["c"] = list(printed.PRINTED_C)
    assert _triple(claims.build_claims(fitted_on_the_printed))["verdict"] == claims.REPRODUCED


def test_series_mismatch_is_reported(values):
    changed = copy.deepcopy(values)
    changed["series"][1]["n_match"] -= 1
    changed["series"][1]["mismatches"] = [["7/2", "-4/35", "-3/35"]]
    row = next(r for r in claims.build_claims(changed) if r["id"] == "series")
    assert row["verdict"] == claims.NOT_REPRODUCED and "7/2" in row["note"]


def test_one_row_per_printed_table_and_per_equation(rows, values):
    """Issue 24: the ten printed series are one statement, and so are Delta and Delta~."""
    assert [r["id"] for r in rows if "series x" in r["claim"]] == ["series"]
    total = sum(s["n_terms"] for s in values["series"])
    assert _find(rows, "every printed coefficient")["our_value"].startswith(f"{total} of {total} equal")
    assert [r["id"] for r in rows if "Delta" in r["claim"]] == ["delta"]


def test_tracking_verdict_depends_on_the_values(values):
    changed = copy.deepcopy(values)
    for thr in changed["tracking"]["forward"].values():
        for order in thr:
            thr[order] = printed.FORWARD_DIVERGENCE_TAU
    assert _find(claims.build_claims(changed), "forward series stop tracking")["verdict"] == claims.REPRODUCED
    first = next(iter(changed["tracking"]["forward"]))
    for order in changed["tracking"]["forward"][first]:
        changed["tracking"]["forward"][first][order] = 1.0
    assert _find(claims.build_claims(changed), "forward series stop tracking")["verdict"] == claims.AMBIGUOUS


def test_eps_exponent_row_is_settled_by_the_exact_exponents(values, rows):
    row = _find(rows, "terms in g^(1/4)")
    assert row["verdict"] == claims.NOT_REPRODUCED
    assert "g^(3/5)" in row["our_value"] and "g^(-3/4)" in row["our_value"]
    # without exponents to derive from, the measured slope decides
    changed = copy.deepcopy(values)
    del changed["alpha"]
    changed["eps_scaling"]["loss_g_exponent_small_g"] = 0.25
    assert next(r for r in claims._scaling_rows(changed) if r["id"] == "eps-scaling")["verdict"] == claims.REPRODUCED


def test_other_exponents_make_every_verdict_ambiguous(values):
    rows = claims.build_claims({"series": None, "alpha": "5/2", "gamma": "1/2"})
    assert len(rows) == 1 and rows[0]["verdict"] == claims.AMBIGUOUS
    changed = copy.deepcopy(values)
    changed["alpha"] = "5/2"
    assert {r["verdict"] for r in claims.build_claims(changed)} == {claims.AMBIGUOUS}


@pytest.mark.slow
def test_the_ledger_consumes_what_other_stages_computed(monkeypatch):
    """One source per number: given the pipeline's outputs, the ledger never runs the fit, the exact
    connection or the paper's procedure itself (those belong to connection_fit, reference_eps_curve
    and connection_readings)."""
    from restitution.audit import matching
    from restitution.core import connection

    inputs = claim_values.reference_inputs(PAPER, FAST)

    def forbidden(*args, **kwargs):
        raise AssertionError("the ledger computed what another stage computes")

    for module, name in ((connection, "fit_connection"), (connection, "exact_omega_tilde"),
                         (matching, "paper_procedure")):
        monkeypatch.setattr(module, name, forbidden)
    values = claim_values.compute_claim_values(PAPER, FAST, **inputs)
    assert values["fit"]["c"] == inputs["fit"]["c"]
    assert values["eps_at_g"] == inputs["at_figure"]["eps"]
    assert values["readings"] == inputs["readings"]


def test_first_order_is_judged_only_where_a_truncation_still_follows_the_solution(values):
    """'For tau > 2 the first order is better' is compared on the samples where some truncation is
    within the threshold of the reference; with none there, no verdict can be given."""
    tr = values["tracking"]
    assert all(n <= tr["samples_after_2"] for n in tr["comparable_samples_after_2"].values())
    row = next(r for r in claims.build_claims(values) if r["id"] == "first-order")
    assert "comparable samples" in row["our_value"]
    changed = copy.deepcopy(values)
    changed["tracking"]["first_order_best_after_2"] = {k: None for k in tr["first_order_best_after_2"]}
    row = next(r for r in claims.build_claims(changed) if r["id"] == "first-order")
    assert row["verdict"] == claims.AMBIGUOUS
    changed["tracking"]["first_order_best_after_2"] = {k: 0.2 for k in tr["first_order_best_after_2"]}
    row = next(r for r in claims.build_claims(changed) if r["id"] == "first-order")
    assert row["verdict"] == claims.NOT_REPRODUCED
    # better where comparable, but comparable on a small part of tau > 2 only: no verdict on the range
    changed["tracking"]["first_order_best_after_2"] = {k: 0.9 for k in tr["first_order_best_after_2"]}
    changed["tracking"]["comparable_samples_after_2"] = {k: 1 for k in tr["first_order_best_after_2"]}
    changed["tracking"]["samples_after_2"] = 100
    row = next(r for r in claims.build_claims(changed) if r["id"] == "first-order")
    assert row["verdict"] == claims.AMBIGUOUS and "1% of those with tau > 2" in row["our_value"]
    changed["tracking"]["comparable_samples_after_2"] = {k: 80 for k in tr["first_order_best_after_2"]}
    row = next(r for r in claims.build_claims(changed) if r["id"] == "first-order")
    assert row["verdict"] == claims.REPRODUCED


def test_tracking_times_are_located_not_read_off_the_grid(values):
    """The time a series stops tracking is where its error crosses the threshold, to the precision
    printed: recomputed here at that time, the error equals threshold x x_b."""
    from restitution.core.collision import collide
    from restitution.core.series import perturbation_series

    tr = values["tracking"]
    key = str(float(tr["thresholds"][1]))
    ps = perturbation_series("3/2", 1, 4, 11, "forward")
    for order in ("2", "4"):
        t = tr["forward"][key][order]
        x_ref = collide(("3/2", 1), tr["omega"], rtol=1e-10, t_eval=[t]).trajectory.x[0]
        err = abs(ps.evaluate([t], tr["omega"], order=int(order))[0] - x_ref)
        assert err == pytest.approx(float(key) * tr["x_b"], rel=1e-6)
        grid_step = tr["tau_c"] / (values["settings"]["tracking_samples"] - 1)
        assert not math.isclose(t / grid_step, round(t / grid_step), abs_tol=1e-6)   # not a grid point
