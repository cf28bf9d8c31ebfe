"""The uniform approximation as a build (:mod:`restitution.fast.uniform_build`), one per end rule:
the force rule's (alpha > gamma, 0.6-0.7 s) and the overlap rule's own (gamma < alpha < 2 gamma + 1,
2-3.5 s). A stored form is used only if it is for these exponents and rule and meets its error estimate at
a few points (the overlap rule's from Omega = 1e-3 up: below, each integration of the creeping
return is slow)."""

from __future__ import annotations

import numpy as np

from ...core.problem import Problem
from ...core.uniform import UNIFORM_VERSION, UniformForm
from ..build import Build
from ..calibration import UNIFORM, UNIFORM_OVERLAP
from ..master import reference_eps
from ..uniform_build import build_uniform

__all__ = ["UniformFormBuild"]


class UniformFormBuild(Build):
    """The uniform approximation of the end rule ``end`` ("force" or "overlap")."""

    def __init__(self, end: str):
        self.end = end
        self.name = UNIFORM_OVERLAP if end == "overlap" else UNIFORM
        self.seconds = {"alpha>gamma": 3.0 if end == "overlap" else 0.7}

    def key(self, site):
        return f"uniform-{'overlap-' if self.end == 'overlap' else ''}{site.pair}-v{UNIFORM_VERSION}"

    def make(self, site):
        return build_uniform(Problem(site.ex, self.end), site.progress).as_dict()

    def valid(self, site, d):
        try:
            u = UniformForm.from_dict(d)
            if (u.alpha, u.gamma, u.end) != (site.ex.alpha, site.ex.gamma, self.end) or not 0 < u.bound_eps < 1:
                return False
            om = np.geomspace(1e-3 if self.end == "overlap" else 1e-7, 1e7, 8) * 1.37
            ref = reference_eps(Problem(site.ex, self.end), om, 1e-13)
            return bool(np.all(np.abs(u.eps(om) / ref - 1) <= u.bound_eps))
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False

    def load(self, site, d) -> UniformForm:
        return UniformForm.from_dict(d)

    def what(self, site):
        return f"the {self.end} rule's uniform approximation for {site.for_pair}"
