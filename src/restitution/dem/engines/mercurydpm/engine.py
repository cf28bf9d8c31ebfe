"""MercuryDPM as one Engine (restitution.dem.engine): its LinearViscoelastic species, from its
documentation; no runner (it was not run here), no scenes."""

from __future__ import annotations

from ...design import calibrated, refuse_passing_through
from ...engine import Engine
from ...typed_e import time_and_e_of_linear
from .contact import mercury_linear_contact

__all__ = ["MERCURYDPM"]


class MercuryEngine(Engine):
    """MercuryDPM LinearViscoelastic: a setting is (t_c, e) of setCollisionTimeAndRestitutionCoefficient."""

    name = "mercurydpm"
    label = "MercuryDPM"
    sample_setting = ({"t_c": 1e-4, "e": 0.6}, {})

    def contact(self, pair, **setting):
        return mercury_linear_contact(pair, **setting)

    def setting(self, pair, contact, **given) -> dict:
        t_c, e = time_and_e_of_linear(contact)
        return {"t_c": t_c, "e": e}

    def design(self, pair, *, eps: float, t_c: float, g: float = 1.0) -> dict:
        """The e that gives ``eps`` with collision time ``t_c`` (eps = e under its overlap rule)."""
        contact = calibrated(mercury_linear_contact(pair, t_c=t_c, e=0.5), eps, g)
        refuse_passing_through(contact, pair, eps, g, self.label)
        setting = {"t_c": t_c, "e": time_and_e_of_linear(contact)[1]}
        return {**setting, "eps": mercury_linear_contact(pair, **setting).eps(g)}


MERCURYDPM = MercuryEngine()
