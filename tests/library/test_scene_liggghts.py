"""A LIGGGHTS scene's generated lines in the real engine (Debian package liggghts): the
fix property/global matrices of every atom type, two spheres colliding head-on, or one sphere
falling onto a flat wall of the wall's atom type, at the scene's time step within its tolerance of
the predicted eps, and extrapolated to dt = 0 within 1e-6.

Every pair contact: LIGGGHTS refuses a system whose atom types in use do not start at 1 ("Atom types
must start from 1 for granular simulations"), so a run of two later types holds a resting type-1
sphere out of reach (restitution.dem.engines.liggghts.run); before it, only the contacts of type 1 were run.
"""

import pytest

from restitution.dem.engines.liggghts.run import available, liggghts_eps_runs, liggghts_wall_eps_runs
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair
from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import scene_from_dict

from test_scene import _liggghts_scene

pytestmark = [pytest.mark.dem, pytest.mark.slow,
              pytest.mark.skipif(not available(), reason="LIGGGHTS not installed (Debian package liggghts)")]


@pytest.mark.parametrize("limit_force", [False, True], ids=["limitForce off", "limitForce on"])
def test_liggghts_gives_the_predicted_eps(limit_force):
    res = answer_scene(scene_from_dict(_liggghts_scene(limit_force)))
    n = len(res["types"]) + len({c["types"][1] for c in res["contacts"] if c["b"].startswith("wall:")})
    lines = "\n".join([f"create_box {n} box"] + [ln for ln in res["input_lines"] if not ln.startswith("#")])
    types = {t["number"]: t for t in res["types"]}
    checked = 0
    for c in res["contacts"]:
        if c["b"].startswith("wall:"):
            continue
        a, b = types[c["types"][0]], types[c["types"][1]]
        pair = Pair.spheres(a["radius"], b["radius"], a["density"], b["density"])
        for i in (0, len(c["speeds"]) - 1):
            g, t_c, predicted = c["speeds"][i], c["contact_time"][i], c["eps"][i]
            at = tuple(c["types"])
            eps = liggghts_eps_runs(pair, [(lines, g, c["dt"], 1.5 * t_c, at)]
                                    + [(lines, g, t_c / 1000 / m, 1.5 * t_c, at) for m in (1, 2, 4)])
            assert abs(eps[0] - predicted) <= res["tolerance"], (c["a"], c["b"], g, eps[0], predicted)
            assert abs(richardson(*eps[1:], c["gamma"]) / predicted - 1) <= 1e-6, (c["a"], c["b"], g)
            checked += 1
    assert checked == 2 * sum(not c["b"].startswith("wall:") for c in res["contacts"]) > 6


@pytest.mark.parametrize("limit_force", [False, True], ids=["limitForce off", "limitForce on"])
def test_liggghts_gives_the_predicted_eps_at_the_wall(limit_force):
    """The wall contacts: a primitive wall (fix wall/gran ... primitive type W zplane 0.0) with the
    scene's model, W the wall's atom type in the scene's lines; before, only LAMMPS ran them."""
    res = answer_scene(scene_from_dict(_liggghts_scene(limit_force)))
    walls = [c for c in res["contacts"] if c["b"].startswith("wall:")]
    n = len(res["types"]) + len({c["types"][1] for c in walls})
    lines = "\n".join([f"create_box {n} box"] + [ln for ln in res["input_lines"] if not ln.startswith("#")])
    types = {t["number"]: t for t in res["types"]}
    for c in walls:
        t = types[c["types"][0]]
        for i in (0, len(c["speeds"]) - 1):
            g, t_c, predicted = c["speeds"][i], c["contact_time"][i], c["eps"][i]
            at = (lines, g, c["dt"], 1.5 * t_c, *c["types"])
            eps = liggghts_wall_eps_runs(t["radius"], t["density"], [at] + [
                (lines, g, t_c / 1000 / m, 1.5 * t_c, *c["types"]) for m in (1, 2, 4)])
            assert abs(eps[0] - predicted) <= res["tolerance"], (c["a"], c["b"], g, eps[0], predicted)
            assert abs(richardson(*eps[1:], c["gamma"]) / predicted - 1) <= 1e-6, (c["a"], c["b"], g, eps, predicted)
    assert len(walls) == 3
