"""Adding a build or a rung is one new module and one registry line (issue 44): a toy build and a
toy rung that reads it, written as a developer would write them (two module files, loaded as
modules), each entered in its registry by one line, and ``epsilon`` chooses, builds and caches
them as it does its own. The ladder knows neither by name: were it to bypass either registry, the
toy rung would never be chosen, nor the toy build found."""

from __future__ import annotations

import importlib.util
import io

import numpy as np
import pytest

from restitution import epsilon
from restitution.fast import builds, rungs
from restitution.fast.ladder import Ladder

TOY_BUILD = '''
from restitution.fast.build import Build

MAKES = []   # every make() (what the test counts)


class ToyTable(Build):
    """One number per pair of exponents, priced at 10 ms."""

    name = "toy table"
    seconds = {"alpha>gamma": 0.01}

    def key(self, site):
        return f"toy-table-{site.pair}-v1"

    def make(self, site):
        MAKES.append(site.pair)
        return {"pair": site.pair, "eps": 0.5}

    def valid(self, site, d):
        return d.get("pair") == site.pair

    def load(self, site, d):
        return float(d["eps"])
'''

TOY_RUNG = '''
import numpy as np

from restitution.fast.rung import Rung


class ToyRung(Rung):
    """eps read from the toy table, claimed good to 1e-12 at a picosecond a point."""

    name, cost = "toy", 1e-12

    def needs(self, req):
        return "toy table"

    def bound(self, req, table):
        return 1e-12, "toy"

    def evaluate(self, req, table, setting, omega):
        return np.full(np.shape(omega), table)
'''


def _module(tmp_path, name: str, source: str):
    path = tmp_path / f"{name}.py"
    path.write_text(source)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def toys(tmp_path, monkeypatch, empty_cache):
    """The two modules, each with its one registry line."""
    table = _module(tmp_path, "toy_table", TOY_BUILD)
    rung = _module(tmp_path, "toy_rung", TOY_RUNG)
    monkeypatch.setattr(builds, "BUILDS", (*builds.BUILDS, table.ToyTable()))
    monkeypatch.setattr(rungs, "RUNGS", (*rungs.RUNGS, rung.ToyRung()))
    return table


def test_a_toy_build_and_rung_are_built_once_and_chosen(toys, empty_cache):
    few, many = [0.3, 3.0], np.geomspace(0.3, 3.0, 2000)
    # two points: the integrator (about 0.1 ms) undercuts the toy table's 10 ms, which is not made
    r = epsilon(alpha="3/2", gamma="1", omega=few, tol=1e-9)
    assert r.method == "integrator" and toys.MAKES == []
    assert not [p for p in empty_cache.iterdir() if p.name.startswith("toy-table")]
    toy = next(c for c in r.candidates if c["method"] == "toy")
    assert not toy["available"] and "toy table" in toy["reason"]
    # 2,000 points (the integrator: about 0.1 s): the table pays, the dearer builds do not
    r = epsilon(alpha="3/2", gamma="1", omega=many, tol=1e-9)
    assert r.method == "toy" and np.all(r.eps == 0.5) and r.error_bound == 1e-12
    assert toys.MAKES == ["a3/2-g1"]
    made = sorted(p.name for p in empty_cache.iterdir() if not p.name.endswith(".lock"))
    assert [p for p in made if p.startswith("toy-table")] and not [p for p in made if p.startswith("master-")]
    # asked again, and by a new ladder reading the cache: read, not made again
    assert epsilon(alpha="3/2", gamma="1", omega=many, tol=1e-9).method == "toy"
    fresh = Ladder(("3/2", "1"), cache_dir=str(empty_cache), stream=io.StringIO())
    assert fresh.evaluate(few, tol=1e-9).method == "toy"
    assert toys.MAKES == ["a3/2-g1"]


def test_a_toy_build_is_not_made_where_an_exact_rung_meets_tol(toys, empty_cache):
    r = epsilon(alpha="2", gamma="1/2", omega=np.geomspace(0.3, 3.0, 2000), tol=1e-9)
    assert r.method == "exact-family" and toys.MAKES == []


def test_without_its_registry_line_the_toy_rung_is_unknown(tmp_path, empty_cache):
    _module(tmp_path, "toy_rung_alone", TOY_RUNG)   # the module alone, no registry line
    from restitution.core.errors import ParameterError
    with pytest.raises(ParameterError, match="method"):
        epsilon(alpha="3/2", gamma="1", omega=[0.3], tol=1e-9, method="toy")
