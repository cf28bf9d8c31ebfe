"""The real Yade engine (Debian package ``yade``, run headless; `make test` installs it as root)
against the library and restitution.dem.engines.yade.contact.

Two spheres (unlike radii and masses) collide head-on with ViscElMat given (tc, en), ViscElMat
given (kn, cn) and Hertz-Mindlin given en, at three speeds over two decades. Yade never lets the
normal force turn attractive, so only the force rule exists there. Yade's eps, extrapolated to
dt = 0 from three time steps, must agree with the library's to 1e-6 (forward), and the library's
values for a target eps must reach it in Yade to 1e-5 (design).
"""

import pytest

from restitution.dem.engines.yade.contact import yade_mindlin_contact, yade_viscel_contact
from restitution.dem.engines.yade.design import yade_design
from restitution.dem.engines.yade.run import (available, mindlin_material, viscel_material, yade_eps_extrapolated,
                                              yade_states)
from restitution.dem.engines.typed_e_table import TYPED_E_CODES
from engine_case import MATERIAL, PAIR, SPEEDS  # noqa: E402

pytestmark = [pytest.mark.dem, pytest.mark.slow,
              pytest.mark.skipif(not available(), reason="Yade not installed: as root, apt-get install yade "
                                                         "(make test does it)")]


def _engine(contact, setting):
    return yade_eps_extrapolated(PAIR, setting, SPEEDS, {g: contact.contact_time(g) for g in SPEEDS}, contact.gamma)


def _forward(kind):
    """(library contact, Yade setting, typed-e table row or None) for typed values."""
    if kind == "viscel-tc":
        return (yade_viscel_contact(PAIR, tc=1e-4, en=0.5), viscel_material(PAIR, tc=1e-4, en=0.5),
                "Yade ViscElMat (tc, en)")
    if kind == "viscel-kn":
        # kn and cn per particle, as typed into ViscElMat (Yade joins the two in series)
        return yade_viscel_contact(PAIR, kn=2e4, cn=0.25), viscel_material(PAIR, kn=2e4, cn=0.25), None
    en = 0.99 if kind == "mindlin-0.99" else 0.5
    return (yade_mindlin_contact(PAIR, en=en, **MATERIAL), mindlin_material(PAIR, en=en, **MATERIAL),
            "Yade Hertz-Mindlin en" if en == 0.5 else None)


@pytest.mark.parametrize("kind", ["viscel-tc", "viscel-kn", "mindlin", "mindlin-0.99"])
def test_yade_agrees_with_the_library(kind):
    contact, setting, row = _forward(kind)
    if row:
        assert contact.eps(1.0) == pytest.approx(TYPED_E_CODES[row](0.5).eps(1.0), rel=1e-10)
    runs = _engine(contact, setting)
    for g in SPEEDS:
        exact = contact.eps(g)
        assert abs(runs[g][0] / exact - 1) <= 1e-6, (g, exact, runs[g])
    if kind == "viscel-tc":
        assert runs[SPEEDS[0]][0] > 0.55      # the clamp: en = 0.5 gives 0.5503, not 0.5
    if kind == "mindlin-0.99":
        assert runs[SPEEDS[0]][0] < 0.98      # Thornton's fit near the elastic end: en = 0.99 gives 0.9789


@pytest.mark.parametrize("kind", ["viscel-tc", "viscel-kn", "mindlin"])
def test_the_designed_values_reach_their_target_in_yade(kind):
    target = 0.55
    if kind == "viscel-tc":
        design = yade_design(PAIR, eps=target, law=kind, tc=1e-4)
        assert design["tc"] == 1e-4           # the contact time asked for is kept; en does the work
        contact, setting = yade_viscel_contact(PAIR, tc=design["tc"], en=design["en"]), \
            viscel_material(PAIR, tc=design["tc"], en=design["en"])
    elif kind == "viscel-kn":
        design = yade_design(PAIR, eps=target, law=kind, kn=2e4)
        contact, setting = yade_viscel_contact(PAIR, kn=design["kn"], cn=design["cn"]), \
            viscel_material(PAIR, kn=design["kn"], cn=design["cn"])
    else:
        design = yade_design(PAIR, eps=target, law=kind, **MATERIAL)
        # the en Yade's own fit turns into the calibrated betan: typed as a user would
        contact, setting = yade_mindlin_contact(PAIR, en=design["en"], **MATERIAL), \
            mindlin_material(PAIR, en=design["en"], **MATERIAL)
    runs = _engine(contact, setting)
    for g in SPEEDS:
        assert abs(runs[g][0] - target) <= 1e-5, (g, design, runs[g])


@pytest.mark.parametrize("kind", ["viscel-tc", "viscel-kn", "mindlin"])
def test_the_stiffness_is_yades(kind):
    """eps does not see D1 where it depends on the typed e alone (tc and en; Hertz-Mindlin's E*, R
    and m): the overlap at maximum compression does. Yade's, read at the library's time of maximum
    compression, must be the library's there (and the spheres at rest relative to each other)."""
    contact, setting, _ = _forward(kind)
    g = 0.1
    col = contact.collision(g)
    t_b = col.tau_b * float(contact.material.time_scale(g))
    delta_b = col.x_b * float(contact.material.length_scale(g))
    rel, gap = yade_states(PAIR, [(*setting, g, t_b / 8000, t_b)])[0]
    assert abs((PAIR.R1 + PAIR.R2 - gap) / delta_b - 1) <= 1e-4, (gap, delta_b)
    assert abs(rel) <= 1e-3 * g
