"""The overlap rule's own master curve as a build (:mod:`restitution.fast.overlap_master`,
1-2 s: its panels' nodes and the viscous law's C): what the overlap rule's master rung reads. A stored curve is used only if it is for
these exponents and passes its own spot checks against the integrator."""

from __future__ import annotations

from ..build import Build
from ..overlap_master import OVERLAP_CURVE_VERSION, OverlapCurve, build_overlap_curve

__all__ = ["OverlapCurveBuild", "OVERLAP_CURVE"]

#: Its name (what the overlap rule's master rung ``needs``).
OVERLAP_CURVE = "overlap-rule master curve"


class OverlapCurveBuild(Build):
    """Chebyshev panels of eps(Omega) under the overlap rule, above the sticking boundary."""

    name = OVERLAP_CURVE
    seconds = {"alpha>gamma": 2.0}

    def key(self, site):
        return f"overlap-curve-{site.pair}-v{OVERLAP_CURVE_VERSION}"

    def make(self, site):
        return build_overlap_curve(site.ex, site.progress).as_dict()

    def valid(self, site, d):
        try:
            c = OverlapCurve.from_dict(d)
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False
        return (c.alpha, c.gamma) == (site.ex.alpha, site.ex.gamma) and c.spot_checks_pass()

    def load(self, site, d) -> OverlapCurve:
        return OverlapCurve.from_dict(d)

    def what(self, site):
        return f"the overlap rule's master curve for {site.for_pair}"
