"""A scene file (YAML): checked against ``scene.schema.yaml`` beside this module (with the engines'
options from the registry: :func:`scene_schema`) and the rules between
fields a schema cannot state, every mistake one line naming the field (ParameterError).

What it gives back is a :class:`Scene`: the code and its options with defaults filled in, one atom
type per species radius (numbered in file order, as the input lines number them), the walls, and
the target of every material pair, as a function of speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...core.errors import ParameterError, number_in
from ...core.schema_lines import allowed, field, show
from ..engines import ENGINES, scene_engines

__all__ = ["Scene", "AtomType", "Target", "read_scene", "scene_from_dict", "scene_schema", "SCHEMA_PATH", "TOL_RANGE", "CODE_OPTIONS"]

SCHEMA_PATH = Path(__file__).with_name("scene.schema.yaml")
#: The scene tolerance (absolute, on eps): below 1e-8 the time-step study cannot promise a step
#: (restitution.dem.timestep refuses it); above 0.5 any eps in (0, 1) would do.
TOL_RANGE = (1e-8, 0.5)
#: Each code's options and their defaults (None: required), as the shipped engines give them (the
#: registry, restitution.dem.engines.ENGINES, is what a scene is checked against)
CODE_OPTIONS = {name: dict(ENGINES[name].scene_options) for name in scene_engines()}
MAX_FILE_BYTES = 1_000_000
#: Speeds over the range at which a constant target is fitted (the check is on the scene's grid).
FIT_POINTS = 64


@dataclass(frozen=True)
class AtomType:
    """One atom type of the code: a species at one radius."""

    number: int
    name: str          # the species' name, or name#k for the k-th radius of a list
    species: str
    material: str
    radius: float


@dataclass(frozen=True)
class Target:
    """The eps wanted for one material pair: a constant, or a measured table read as a curve
    piecewise linear in log speed and constant beyond its first and last points."""

    pair: tuple
    e: float | None = None
    table: tuple | None = None

    def at(self, speeds) -> np.ndarray:
        v = np.asarray(speeds, float)
        if self.table is None:
            return np.full(v.shape, self.e)
        tv, te = (np.array(c, float) for c in zip(*self.table))
        return np.interp(np.log(v), np.log(tv), te)

    def fit_points(self, grid) -> tuple:
        """The (speed, e) points a model is fitted to by least squares: the measured points of a
        table, or FIT_POINTS log-spaced speeds over the grid's range for a constant."""
        if self.table is None:
            speeds = np.geomspace(grid[0], grid[-1], FIT_POINTS)
            return speeds, self.at(speeds)
        tv, te = (np.array(c, float) for c in zip(*self.table))
        return tv, te

    def as_dict(self) -> dict:
        return {"pair": list(self.pair), **({"e": self.e} if self.table is None else {"table": [list(p) for p in self.table]})}


@dataclass(frozen=True)
class Scene:
    name: str
    code: str
    options: dict
    tolerance: float
    speeds: tuple
    check_points: int
    report_points: int
    materials: dict
    types: tuple
    walls: tuple
    targets: dict      # frozenset of the material pair's names -> Target

    def target(self, m1: str, m2: str) -> Target:
        return self.targets[frozenset((m1, m2))]

    def check_grid(self) -> np.ndarray:
        return np.geomspace(*self.speeds, self.check_points)

    def report_grid(self) -> np.ndarray:
        return np.geomspace(*self.speeds, self.report_points)


def read_scene(path) -> Scene:
    """The scene in the YAML file ``path``, checked; ParameterError (one line) for any mistake."""
    import yaml

    from ...core.strict_yaml import Refused, StrictLoader

    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_FILE_BYTES + 1)
    except OSError as err:
        raise ParameterError("file", str(path), f"cannot be read ({err.strerror})") from None
    if len(raw) > MAX_FILE_BYTES:
        raise ParameterError("file", str(path), f"larger than {MAX_FILE_BYTES} bytes: not a scene")
    try:
        data = yaml.load(raw.decode("utf-8"), Loader=StrictLoader)  # noqa: S506 - a SafeLoader subclass
    except UnicodeDecodeError:
        raise ParameterError("file", str(path), "is not UTF-8 text") from None
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None)
        where = f", line {mark.line + 1}" if mark else ""
        what = " ".join(str(getattr(err, "problem", None) or err).split())
        raise ParameterError("file", f"{path}{where}",
                             what if isinstance(err, Refused) else f"not valid YAML: {what}") from None
    return scene_from_dict(data)


def scene_schema() -> dict:
    """The JSON schema a scene file is checked against: ``scene.schema.yaml`` with the engines a
    scene may name and their options taken from the registry (restitution.dem.engines), so that an
    engine brings its scene options in its own module.

    Returns
    -------
    dict
        The schema, ``code`` and ``options`` filled in.

    Raises
    ------
    ValueError
        Where two engines give one option name different schemas (one field cannot say both).

    Examples
    --------
    >>> s = scene_schema()
    >>> s["properties"]["code"]["enum"], s["properties"]["options"]["properties"]["limitForce"]["type"]
    (['lammps', 'liggghts', 'kratos'], 'boolean')
    """
    import yaml

    with open(SCHEMA_PATH, encoding="utf-8") as fh:
        schema = yaml.safe_load(fh)
    codes = scene_engines()
    options: dict = {}
    for code in codes:
        for name, rule in ENGINES[code].scene_option_schema.items():
            if options.setdefault(name, rule) != rule:
                raise ValueError(f"scene option {name}: engine {code} gives it another schema than an earlier engine")
    schema["properties"]["code"]["enum"] = codes
    node = schema["properties"]["options"]
    node["properties"] = options
    node["description"] += " (" + "; ".join(f"{code} - {', '.join(ENGINES[code].scene_options)}" for code in codes) + ")"
    return schema


def _fail(field_name: str, value, what: str):
    raise ParameterError(field_name, value, what)


def _non_finite(node, path=()):
    if isinstance(node, float) and not math.isfinite(node):
        return path, node
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
    for key, value in items:
        found = _non_finite(value, path + (key,))
        if found:
            return found
    return None


def scene_from_dict(data) -> Scene:
    """The scene of an already parsed document (see :func:`read_scene`)."""
    import jsonschema

    if not isinstance(data, dict):
        _fail("scene", show(data), "must be a mapping (name: ..., code: ..., materials: ...)")
    found = _non_finite(data)
    if found:
        _fail(field(data, found[0], "scene"), found[1], "must be a finite number")
    schema = scene_schema()
    errors = list(jsonschema.Draft202012Validator(schema).iter_errors(data))
    # the code decides which options exist: a code outside the registry is the mistake to name
    on_code = [e for e in errors if list(e.absolute_path) == ["code"]]
    error = jsonschema.exceptions.best_match(on_code or errors)
    if error is not None:
        where = field(data, error.absolute_path, "scene")
        value = error.instance
        if error.validator == "additionalProperties":
            extra = sorted(set(error.instance) - set(error.schema.get("properties", {})))
            where, value = (f"{where}.{extra[0]}" if where != "scene" else extra[0]), error.instance[extra[0]]
        elif error.validator == "required":
            value = "{...}"
        _fail(where, show(value) if isinstance(value, str) and len(value) > 80 else value, allowed(error))
    return _beyond_schema(data)


def _beyond_schema(d: dict) -> Scene:
    tolerance = number_in("tolerance", d["tolerance"], *TOL_RANGE,
                          why="the accuracy a time step can promise (restitution.dem.timestep) up to any eps at all")
    lo, hi = d["speeds"]
    if not lo < hi:
        _fail("speeds", d["speeds"], "must be [lowest, highest] with lowest < highest")
    code = d["code"]
    engine = ENGINES[code]
    options = dict(engine.scene_options)
    for key, value in d["options"].items():
        if key not in options:
            _fail(f"options.{key}", value, f"is not an option of code {code}; its options: {', '.join(options)}")
        options[key] = value
    missing = [k for k, v in options.items() if v is None]
    if missing:
        _fail(f"options.{missing[0]}", None,
              f"code {code} needs it: one of {', '.join(engine.scene_option_schema[missing[0]]['enum'])}")
    needs, reader = engine.material_keys(options)
    for name, mat in d["materials"].items():
        for key in needs:
            if key not in mat:
                _fail(f"materials.{name}.{key}", None, f"{reader} reads {' and '.join(needs)}: give it")
        for key in set(mat) - set(needs) - {"density"}:
            _fail(f"materials.{name}.{key}", mat[key], f"is not read by {reader} (it reads {' and '.join(needs)})")
        engine.check_material(name, mat)
    types, seen = [], set()
    for i, sp in enumerate(d["species"]):
        where = f"species[{sp['name']}]"
        if sp["name"] in seen:
            _fail(f"{where}.name", sp["name"], "must be unique among the species")
        seen.add(sp["name"])
        if sp["material"] not in d["materials"]:
            _fail(f"{where}.material", sp["material"], f"must be one of the materials: {', '.join(d['materials'])}")
        radii = sp["radius"] if isinstance(sp["radius"], list) else [sp["radius"]]
        for k, r in enumerate(radii):
            label = sp["name"] if len(radii) == 1 else f"{sp['name']}#{k + 1}"
            types.append(AtomType(len(types) + 1, label, sp["name"], sp["material"], float(r)))
    walls = tuple(d.get("walls", []))
    for k, w in enumerate(walls):
        if w not in d["materials"]:
            _fail(f"walls[{k}]", w, f"must be one of the materials: {', '.join(d['materials'])}")
    if len(set(walls)) != len(walls):
        _fail("walls", list(walls), "each wall material at most once")
    targets = {}
    for k, t in enumerate(d["targets"]):
        where = f"targets[{k}]"
        for m in t["pair"]:
            if m not in d["materials"]:
                _fail(f"{where}.pair", t["pair"], f"names materials: {', '.join(d['materials'])}")
        if ("e" in t) == ("table" in t):
            _fail(where, t.get("e", "{...}"), "give exactly one of e (a constant) and table ((speed, e) points)")
        key = frozenset(t["pair"])
        if key in targets:
            _fail(f"{where}.pair", t["pair"], "this material pair already has a target")
        table = None
        if "table" in t:
            table = tuple((float(v), float(e)) for v, e in t["table"])
            if any(b[0] <= a[0] for a, b in zip(table, table[1:])):
                _fail(f"{where}.table", t["table"], "speeds must increase strictly from point to point")
        targets[key] = Target(tuple(t["pair"]), None if table else float(t["e"]), table)
    for a, b in _material_pairs(types, walls):
        if frozenset((a, b)) not in targets:
            _fail("targets", f"[{a}, {b}]", f"the scene has {a}-{b} contacts: give their e or table")
    return Scene(d["name"], code, options, tolerance, (float(lo), float(hi)), d.get("check_points", 1000),
                 d.get("report_points", 9), dict(d["materials"]), tuple(types), walls, targets)


def _material_pairs(types, walls):
    mats = sorted({t.material for t in types})
    pairs = {(a, b) for i, a in enumerate(mats) for b in mats[i:]}
    return sorted(pairs | {tuple(sorted((m, w))) for m in mats for w in walls})
