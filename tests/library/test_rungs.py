"""The rung interface: a rung is one object in the registry, and the chooser only compares quotes."""

from __future__ import annotations

import io

import numpy as np

from restitution.fast.ladder import Ladder
from restitution.fast.rung import Rung


class Toy(Rung):
    """eps = 1 for every Omega, claimed exact: cheaper than anything (a wrong rung, on purpose)."""

    name, cost = "toy", 1e-12
    ends = ("force", "overlap")

    def bound(self, req, built):
        return 0.0, "toy"

    def evaluate(self, req, built, setting, omega):
        return np.ones(np.shape(omega))


def test_a_rung_added_to_the_registry_is_quoted_and_chosen(tmp_path):
    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    assert lad.evaluate([0.3], tol=1e-9, build=False).method == "integrator"
    lad.rungs = (*lad.rungs, Toy())          # what one registry line does
    lad.rung_names = (*lad.rung_names, "toy")
    r = lad.evaluate([0.3, 3.0], tol=1e-9, build=False)
    assert r.method == "toy" and np.all(r.eps == 1.0)
    assert lad.with_end("overlap").evaluate([0.3], tol=1e-9, build=False).method == "toy"


def test_a_rung_that_does_not_serve_the_rule_is_listed_with_the_reason(tmp_path):
    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    q = {c["method"]: c for c in lad.with_end("overlap").evaluate([0.3], tol=1e-6, build=False).candidates}
    assert not q["fitted-c"]["available"] and "force rule only" in q["fitted-c"]["reason"]


def test_the_reference_rung_quotes_what_collide_states_under_either_rule():
    """Under "overlap" where the rules coincide (alpha <= gamma) the force rule's numbers apply: the
    reference rung quotes collide's own stated bound, not the overlap rule's wider one."""
    from restitution.core.collision import collide
    from restitution.core.exponents import as_exponents
    from restitution.core.problem import Problem
    from restitution.fast.rung import Request, reference_rtol
    from restitution.fast.rungs.reference import Reference

    for alpha, gamma, rule in (("1", "3/2", "force"), ("3/2", "1", "overlap")):
        req = Request(Problem(as_exponents(alpha, gamma), "overlap"), np.array([1.0]), 1e-9)
        assert req.effective_end == rule
        quoted = Reference().bound(req, {})[0]
        stated = collide(Problem.of(alpha, gamma, "overlap"), 1.0, rtol=reference_rtol(1e-9, Problem(req.ex, rule))).error_bound
        assert quoted == stated


def test_an_integrating_rung_runs_at_the_setting_it_quoted(monkeypatch):
    """The quote's Setting carries the rtol (digits) as a number, and evaluate reads it back: the
    tolerance formulas are asked once, in bound, never again when the quote runs."""
    from restitution.core.problem import Problem
    from restitution.fast import rung as rung_module
    from restitution.fast.rung import Request, Setting
    from restitution.fast.rungs import highprec, integrator, overlap_integrator, reference

    om = np.array([0.5])
    cases = [(integrator.Integrator(), Problem.of("3/2", "1")),
             (overlap_integrator.OverlapIntegrator(), Problem.of("3/2", "1", "overlap")),
             (reference.Reference(), Problem.of("3/2", "1")),
             (highprec.Highprec(), Problem.of("3/2", "1"))]
    quotes = []
    for rung, problem in cases:
        q = rung.quote(Request(problem, om, 1e-8))
        assert isinstance(q.setting, Setting) and (q.setting.rtol or q.setting.digits), rung.name
        quotes.append(q)

    def derived_again(*args, **kwargs):
        raise AssertionError("a tolerance formula was asked again when the quote ran")

    for module in (rung_module, integrator, overlap_integrator, reference, highprec):
        for name in ("integrator_rtol", "reference_rtol", "highprec_digits"):
            if hasattr(module, name):
                monkeypatch.setattr(module, name, derived_again)
    for q in quotes:
        eps = q.run(om)
        assert 0.0 < float(eps[0]) < 1.0, q.name


def test_the_answer_and_its_table_carry_the_setting_as_a_value(tmp_path):
    """EpsResult.setting and each candidate's setting are Settings (PartSettings for an answer made
    part by part), not display strings; str() and --json show the same words as before."""
    from restitution.fast.ladder import PartSettings
    from restitution.fast.rung import Setting

    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    r = lad.evaluate([0.3], tol=1e-6, method="integrator", build=False)
    assert isinstance(r.setting, Setting) and r.setting.rtol == r.parts[0].setting.rtol > 0
    assert r.as_dict()["setting"] == str(r.setting) == f"rtol={r.setting.rtol:.3g}"
    assert all(isinstance(c["setting"], Setting) for c in r.candidates)
    # under the overlap rule the far-below points go to the overlap law, the others to the integrator
    joined = lad.with_end("overlap").evaluate([1e-10, 0.3], tol=1e-9, build=False)
    assert len(joined.parts) > 1 and isinstance(joined.setting, PartSettings)
    assert joined.setting.parts == tuple((p.method, p.setting) for p in joined.parts)
    assert joined.as_dict()["setting"] == "; ".join(f"{p.method}: {p.setting}" for p in joined.parts)


def test_the_table_lists_each_rung_name_once_under_either_rule(tmp_path):
    """master and integrator are one rung per end rule: the table shows the one serving the rule
    asked (it listed both, the other as "serves the ... rule only")."""
    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    for end in ("force", "overlap"):
        table = lad.with_end(end).evaluate([0.3], tol=1e-6, build=False).candidates
        names = [c["method"] for c in table]
        assert len(names) == len(set(names)) and {"master", "integrator"} <= set(names), end
        integ = next(c for c in table if c["method"] == "integrator")
        assert integ["available"] and integ["setting"].end == end, end
