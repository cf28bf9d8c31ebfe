"""The master curve as a build (:mod:`restitution.fast.master`), with the errors of the rungs it
measures on its calibration grid (:func:`restitution.fast.calibration.measure_master`): what the
master, Pade and expansion rungs read. A stored curve is used only if every panel agrees with a
fresh integration at one point (a few ms): the cache's digest catches a damaged file, this a
wrong curve."""

from __future__ import annotations

import numpy as np

from ..build import Build, Site, digest
from ..calibration import MASTER, Calibration, measure_master
from ..master import MASTER_VERSION, MasterCurve, build_master, reference_eps
from ..rung import integrator_bound

__all__ = ["MasterCurveBuild", "SPOT_CHECK_AT"]

#: Where in each Chebyshev panel a loaded master curve is checked against the integrator (a
#: fraction of the panel's width, away from the nodes the curve was fitted on).
SPOT_CHECK_AT = 0.37


def spot_checks_pass(site: Site, m: MasterCurve) -> bool:
    """Every panel of ``m`` agrees with a fresh integration at one point, to its own bound (plus
    the integrator's)."""
    om = np.exp(m.s0 + (np.arange(m.coef.shape[0]) + SPOT_CHECK_AT) * m.width)
    ref = reference_eps(site.ex, om, 1e-13)
    err = np.abs(m.eps(om) - ref) / ref
    return bool(np.all(err <= 10.0 * (m.bound_at(om) + integrator_bound(1e-13, site.ex))))


class MasterCurveBuild(Build):
    """The Chebyshev master curve with the expansions beyond its joins; 0.1 s for (3/2, 1) and
    (3/2, 1/2), 4.6-4.9 s where alpha < gamma (the creeping return below Omega = 1e-3), 0.01 s for
    alpha = gamma (exact)."""

    name = MASTER
    seconds = {"alpha>gamma": 0.2, "alpha<=gamma": 5.0}

    def key(self, site):
        return f"master-{site.pair}-v{MASTER_VERSION}-{digest(site.master_settings.key())}"

    def make(self, site):
        return build_master(site.ex, site.master_settings, progress=site.progress).as_dict()

    def valid(self, site, d):
        try:
            m = MasterCurve.from_dict(d)
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False
        return (m.alpha == site.ex.alpha and m.gamma == site.ex.gamma and m.settings == site.master_settings
                and bool(np.all(np.isfinite(m.coef))) and spot_checks_pass(site, m))

    def load(self, site, d) -> Calibration:
        return measure_master(MasterCurve.from_dict(d))

    def what(self, site):
        return f"the master curve for {site.for_pair}"
