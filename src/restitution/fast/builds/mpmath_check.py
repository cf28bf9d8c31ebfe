"""The master curve's check against the mpmath reference as a build
(:func:`restitution.fast.master.mpmath_check`, ``settings.n_highprec`` points, 2.8 s for 12): made
for the pipeline and the benchmark (``Ladder.calibration``), never for an eps request; loading it
can only widen the curve's bound (:func:`restitution.fast.master.widen_by_check`)."""

from __future__ import annotations

import numpy as np

from ..build import Build, digest
from ..calibration import CALIBRATION_VERSION, MASTER, MPMATH
from ..master import MASTER_VERSION, mpmath_check, reference_eps, widen_by_check
from ..rung import integrator_bound

__all__ = ["MpmathCheck"]


class MpmathCheck(Build):
    """mpmath's eps at a few points of the master curve's range, which widen its bound where they
    disagree with it."""

    name = MPMATH
    after = (MASTER,)
    seconds = {"alpha>gamma": 3.0, "alpha<=gamma": 3.0}

    def key(self, site):
        s = site.settings
        return f"mpmath-check-{site.pair}-v{CALIBRATION_VERSION}.{MASTER_VERSION}-{digest(s.key())}"

    def make(self, site):
        s = site.settings
        return mpmath_check(site.built[MASTER].master, s.n_highprec, s.highprec_digits, s.seed, site.progress)

    def valid(self, site, d):
        """Its mpmath values agree with the integrator where they were taken: an edited value must
        not widen the curve's bound for nothing, nor hide a wrong curve."""
        try:
            pts, hp = np.asarray(d["omega"], float), np.asarray(d["eps"], float)
            if (d["alpha"], d["gamma"]) != (str(site.ex.alpha), str(site.ex.gamma)) or pts.shape != hp.shape:
                return False
            ref = reference_eps(site.ex, pts, 1e-13)
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False
        return bool(np.all(np.abs(hp / ref - 1) <= 10.0 * integrator_bound(1e-13, site.ex)))

    def load(self, site, d):
        widen_by_check(site.built[MASTER].master, d)
        return d

    def what(self, site):
        return f"the master curve's check against mpmath for {site.for_pair}"
