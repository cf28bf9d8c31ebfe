"""A relation rung's c0-c2 as a build, one per :class:`restitution.fast.calibration.Relation`
(the paper's perturbation route takes seconds an order; the relation's own ``build_seconds``
prices it). Its error is measured on the master curve's grid when loaded, from the c0-c2 it
holds, so an edited c is quoted with the error it really has."""

from __future__ import annotations

import math

from ..build import Build, safe_name
from ..calibration import (CALIBRATION_VERSION, MASTER, Calibration, Relation, measure_relation, relation_build,
                           relation_dict)

__all__ = ["RelationBuild"]


class RelationBuild(Build):
    """The c0-c2 of ``relation`` (or why it has none for these exponents)."""

    after = (MASTER,)

    def __init__(self, relation: Relation):
        self.relation = relation
        self.name = relation_build(relation.name)
        self.seconds = {"alpha>gamma": relation.build_seconds, "alpha<=gamma": relation.build_seconds}

    def key(self, site):
        return f"relation-{safe_name(self.relation.name)}-{site.pair}-v{CALIBRATION_VERSION}"

    def make(self, site):
        return relation_dict(site.ex, self.relation, site.progress)

    def valid(self, site, d):
        try:
            same = ((d["version"], d["name"], d["alpha"], d["gamma"])
                    == (CALIBRATION_VERSION, self.relation.name, str(site.ex.alpha), str(site.ex.gamma)))
            return same and (isinstance(d.get("unavailable"), str) if "c" not in d
                             else len(d["c"]) == 3 and all(math.isfinite(float(x)) for x in d["c"]))
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False

    def load(self, site, d) -> Calibration:
        return measure_relation(site.built[MASTER].master, d)

    def what(self, site):
        return f"the {self.relation.name} relation for {site.for_pair}"
