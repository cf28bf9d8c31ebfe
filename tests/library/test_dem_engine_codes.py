"""The LIGGGHTS and Yade contact laws (restitution.dem.engines) without the engines: round trips, the
numbers Yade itself reported, and one-line refusals."""

import math

import pytest

from restitution.core.errors import ParameterError
from restitution.dem import Contact
from restitution.dem.engines import ENGINES
from restitution.dem.engines.kratos.contact import linear_force_eps
from restitution.dem.engines.liggghts.contact import liggghts_contact, liggghts_e
from restitution.dem.engines.liggghts.design import liggghts_design
from restitution.dem.engines.yade.contact import (thornton_betan, yade_mindlin_contact, yade_mindlin_en,
                                                  yade_viscel_contact, yade_viscel_setting)
from restitution.dem.engines.yade.design import yade_design
from engine_case import PAIR  # noqa: E402


def test_thornton_fit_is_what_yade_computes():
    """MindlinPhys.betan that Yade 2023.02a set for en = 0.5 (read from the engine's interaction)."""
    assert thornton_betan(0.5) == pytest.approx(0.2330248576834424, rel=1e-14)
    es = [0.05 * k for k in range(1, 20)]
    assert all(thornton_betan(a) > thornton_betan(b) for a, b in zip(es, es[1:]))   # one en per betan


@pytest.mark.parametrize("model", [{"model": "hertz"}, {"model": "hooke", "characteristic_velocity": 2.0}])
@pytest.mark.parametrize("e", [0.05, 0.5, 0.97])
def test_liggghts_e_inverts_the_damping(model, e):
    contact = liggghts_contact(PAIR, E=5e7, nu=0.3, e=e, **model)
    assert liggghts_e(contact) == pytest.approx(e, rel=1e-12)


def test_yade_settings_invert_the_contacts():
    c = yade_viscel_contact(PAIR, tc=2e-4, en=0.3)
    assert yade_viscel_setting(PAIR, c, given="tc") == pytest.approx({"tc": 2e-4, "en": 0.3}, rel=1e-12)
    c = yade_viscel_contact(PAIR, kn=3e4, cn=0.4)
    assert yade_viscel_setting(PAIR, c, given="kn") == pytest.approx({"kn": 3e4, "cn": 0.4}, rel=1e-12)
    assert c.D1 == pytest.approx(3e4 / (2 * PAIR.m))          # per particle, in series
    c = yade_mindlin_contact(PAIR, E=5e7, nu=0.3, en=0.42)
    assert yade_mindlin_en(c)["en"] == pytest.approx(0.42, rel=1e-10)
    assert c.D2 / math.sqrt(c.D1) == pytest.approx(2 * thornton_betan(0.42) * math.sqrt(1.5))


@pytest.mark.parametrize("call, field", [
    (lambda: yade_viscel_contact(PAIR, tc=1e-4, en=0.5, kn=1e4), "kn"),
    (lambda: yade_viscel_contact(PAIR, tc=1e-4, en=1.0), "en"),
    (lambda: yade_mindlin_contact(PAIR, E=5e7, nu=0.3, en=0.5, betan=0.2), "en"),
    (lambda: yade_mindlin_contact(PAIR, E=5e7, nu=0.7, en=0.5), "nu"),
    (lambda: liggghts_contact(PAIR, E=5e7, nu=0.3, e=0.5, model="hooke"), "characteristic_velocity"),
    (lambda: liggghts_contact(PAIR, E=5e7, nu=0.3, e=0.5, model="hysteresis"), "model"),
    (lambda: yade_design(PAIR, eps=0.5, law="hertz"), "law"),
    (lambda: yade_design(PAIR, eps=1.2, law="viscel-kn", kn=1e4), "eps"),
])
def test_one_line_refusals(call, field):
    with pytest.raises(ParameterError) as info:
        call()
    assert info.value.field == field and "\n" not in str(info.value)


@pytest.mark.parametrize("design", [
    lambda g: liggghts_design(PAIR, eps=0.5, model="hertz", E=1e5, nu=0.3, limit_force=True, g=g),
    lambda g: yade_design(PAIR, eps=0.5, law="viscel-kn", kn=10.0, g=g),
    lambda g: yade_design(PAIR, eps=0.5, law="mindlin", E=1e5, nu=0.3, g=g),
])
def test_a_design_whose_spheres_pass_through_each_other_is_refused(design):
    """As lammps_design already did: a soft contact at a high speed overlaps past R1 + R2, where the
    engine gives another eps than the one the design states."""
    assert design(1e-3)["eps"] == pytest.approx(0.5, rel=1e-9)
    with pytest.raises(ParameterError) as info:
        design(1e3)
    assert info.value.field == "g" and "through each other" in str(info.value)


def test_every_registered_engine_inverts_its_own_contact_law():
    """Engine.setting is Engine.contact's inverse, for each engine of the registry (each through its
    own sample_setting): the setting found from a contact gives that contact back."""
    from restitution.dem.engines import ENGINES
    for name, engine in ENGINES.items():
        setting, given = engine.sample_setting
        contact = engine.contact(PAIR, **setting)
        found = {**given, **engine.setting(PAIR, contact, **given)}
        again = engine.contact(PAIR, **found)
        assert (again.D1, again.D2) == pytest.approx((contact.D1, contact.D2), rel=1e-12), name


def test_mercurydpm_design_reaches_its_eps_with_the_collision_time_asked():
    from restitution.dem.engines import ENGINES
    res = ENGINES["mercurydpm"].design(PAIR, eps=0.7, t_c=1e-4)
    assert res["t_c"] == 1e-4 and res["eps"] == pytest.approx(0.7, abs=1e-9)
    assert res["e"] == pytest.approx(0.7, abs=1e-9)     # overlap rule, linear dashpot: eps = e


@pytest.mark.parametrize("setting", [
    lambda c: yade_viscel_setting(PAIR, c, given="tc"),
    lambda c: yade_viscel_setting(PAIR, c, given="kn"),
    lambda c: ENGINES["mercurydpm"].setting(PAIR, c),
])
def test_a_linear_codes_setting_is_refused_for_a_contact_that_is_not_linear(setting):
    # A (t_c, e) or (kn, cn) read off a Hertz contact gives another collision in the code:
    # it was returned without a word.
    hertz = Contact("3/2", "1/2", D1=1.5e8, D2=2.0e4)
    with pytest.raises(ParameterError, match="needs the linear contact"):
        setting(hertz)


@pytest.mark.parametrize("zeta", [-0.1, float("nan"), float("inf")])
def test_the_linear_force_rule_eps_refuses_a_damping_ratio_that_is_negative_or_not_finite(zeta):
    # A negative ratio gave eps > 1 without a word.
    with pytest.raises(ParameterError, match="zeta"):
        linear_force_eps(zeta)


@pytest.mark.parametrize("second, field", [({"E2": -1.0, "nu2": 0.3}, "E2"), ({"E2": 1e7, "nu2": 0.7}, "nu2"),
                                           ({"E2": 1e7}, "nu2")])
def test_a_second_materials_bad_modulus_is_refused_under_its_own_name(second, field):
    # A bad E2 was refused as "E = -1", naming the field the user had right.
    with pytest.raises(ParameterError, match=f"^{field} = "):
        liggghts_contact(PAIR, E=1e7, nu=0.3, e=0.5, **second)
