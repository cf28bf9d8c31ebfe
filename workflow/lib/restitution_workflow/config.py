"""Validation of config.yaml with one-line messages (used by workflow/rules/common.smk).

jsonschema's own messages are several lines long and name the failing keyword, not the
field. Here every error becomes ``<field> = <value>: <what is allowed>``, e.g.
``variants[kim].D1 = -1: must be > 0``. The schema's defaults are filled in as well.
"""

from __future__ import annotations

import copy
import math
from fractions import Fraction

import jsonschema
import yaml

# one-line messages from jsonschema's errors: shared with the scene files of restitution.dem.scene.file
from restitution.core.strict_yaml import Refused, StrictLoader
from restitution.core.schema_lines import MAX_NAME, allowed as _allowed, field as _field, show as _show  # noqa: F401


class ConfigError(ValueError):
    """A configuration value outside what the workflow accepts; its message is one line naming the
    field, the value and what is allowed (see :func:`check_config`)."""


def _resolve(schema, root):
    if "$ref" in schema:
        ref = schema["$ref"].split("/")[-1]
        schema = {**root["$defs"][ref], **{k: v for k, v in schema.items() if k != "$ref"}}
    return schema


def _as_number(value, kind: str = "number"):
    """YAML 1.1 reads 1e-10 (no dot) as text, and `snakemake --config` passes every value of a
    nested structure as text; accept such text as the number it means."""
    if isinstance(value, str):
        try:
            return int(value) if kind == "integer" else float(value)
        except ValueError:
            return value
    return value


def _number_branch(schema, root):
    """The numeric alternative of a schema (itself, or its number branch of a oneOf), else None."""
    schema = _resolve(schema, root)
    if schema.get("type") in ("number", "integer"):
        return schema
    for alt in schema.get("oneOf", []):
        alt = _resolve(alt, root)
        if alt.get("type") in ("number", "integer"):
            return {**alt, "description": alt.get("description", schema.get("description"))}
    return None


def _finite_range(schema) -> str:
    """'must be a finite number in [a, b]' (or > a, ...) from a number schema's bounds."""
    if schema is None:
        return "must be a finite number"
    lo = ("(", schema["exclusiveMinimum"]) if "exclusiveMinimum" in schema else \
        ("[", schema["minimum"]) if "minimum" in schema else None
    hi = (")", schema["exclusiveMaximum"]) if "exclusiveMaximum" in schema else \
        ("]", schema["maximum"]) if "maximum" in schema else None
    if lo and hi:
        text = f"must be a finite number in {lo[0]}{lo[1]}, {hi[1]}{hi[0]}"
    elif lo:
        text = f"must be a finite number {'>' if lo[0] == '(' else '>='} {lo[1]}"
    elif hi:
        text = f"must be a finite number {'<' if hi[0] == ')' else '<='} {hi[1]}"
    else:
        text = "must be a finite number"
    description = " ".join(schema.get("description", "").split())   # folded YAML: one line
    return f"{text} ({description})" if description else text


_DOUBLE_MAX = 1.7976931348623157e308

#: $defs whose values a later, more specific check reads (exponents: restitution.core.exponents,
#: whose message gives the allowed rationals); the walk below leaves them to it.
_CHECKED_ELSEWHERE = ("#/$defs/exponent",)


def _non_finite(node, schema, root, path=()):
    """(path, value, allowed) of the first NaN or infinity in the config, else None.

    YAML reads .nan/.inf as floats and the schema's bounds cannot catch them (every comparison
    with NaN is false, inf passes a lower bound); text such as "nan" given on the command line
    has become a float in _fill_defaults. An object schema without properties (free-form) would be
    left to its own checks; the schema has none today."""
    if schema is not None and schema.get("$ref") in _CHECKED_ELSEWHERE:
        return None
    resolved = _resolve(schema, root) if schema is not None else None
    if resolved is not None and resolved.get("type") == "object" and "properties" not in resolved:
        return None
    # an integer beyond double range (YAML reads 1000...0 exactly) overflows where it is used
    beyond = isinstance(node, int) and not isinstance(node, bool) and abs(node) > _DOUBLE_MAX
    if beyond or (isinstance(node, float) and not math.isfinite(node)):
        shown = f"{'-' if node < 0 else ''}{str(abs(node))[0]}e{len(str(abs(node))) - 1}" if beyond else node
        return path, shown, _finite_range(_number_branch(schema, root) if schema is not None else None)
    if isinstance(node, dict):
        obj = _object_branch(resolved, root) if resolved is not None else None
        props = obj.get("properties", {}) if obj is not None else {}
        for key, value in node.items():
            found = _non_finite(value, props.get(key), root, path + (key,))
            if found:
                return found
    elif isinstance(node, list):
        items = None
        if resolved is not None:
            for alt in [resolved] + [_resolve(a, root) for a in resolved.get("oneOf", [])]:
                if isinstance(alt.get("items"), dict):
                    items = alt["items"]
                    break
        for i, value in enumerate(node):
            found = _non_finite(value, items, root, path + (i,))
            if found:
                return found
    return None


def _object_branch(schema, root):
    """The object alternative of a oneOf (e.g. "null or {min, max}"), else the schema itself."""
    for alt in schema.get("oneOf", []):
        alt = _resolve(alt, root)
        if alt.get("type") == "object":
            return alt
    return schema


def _fill_defaults(node, schema, root):
    """Apply `default` values of the schema (objects and arrays of objects), and read numbers
    written as 1e-10 as numbers where the schema wants a number."""
    schema = _resolve(schema, root)
    if isinstance(node, dict):
        schema = _object_branch(schema, root)
        for key, sub in schema.get("properties", {}).items():
            if key not in node and "default" in sub:
                node[key] = copy.deepcopy(sub["default"])
            if key in node:
                sub_r = _resolve(sub, root)
                if sub_r.get("type") in ("number", "integer"):
                    node[key] = _as_number(node[key], sub_r["type"])
                _fill_defaults(node[key], sub, root)
    elif isinstance(node, list) and isinstance(schema.get("items"), dict):
        items = _resolve(schema["items"], root)
        for i, item in enumerate(node):
            if items.get("type") in ("number", "integer"):
                node[i] = _as_number(item, items["type"])
            _fill_defaults(node[i], schema["items"], root)


def check_config(config: dict, schema_path: str) -> dict:
    """Validate ``config`` in place (defaults filled in); raise ConfigError with one line.

    The schema is checked by Snakemake's own validate(); its error is rewritten as one line naming
    the field. Then what a schema cannot say: NaN and infinities (they pass every bound), and the
    rules between fields (beyond_schema).

    Parameters
    ----------
    config : dict
        The configuration as read from YAML (``config.yaml`` and any ``--config``); changed in place.
    schema_path : str
        The JSON schema, ``workflow/schemas/config.schema.yaml``.

    Returns
    -------
    dict
        ``config`` itself, with the schema's defaults filled in.

    Raises
    ------
    ConfigError
        For the first value the workflow does not accept, in one line.

    Examples
    --------
    >>> import yaml
    >>> from pathlib import Path
    >>> root = Path(__file__).resolve().parents[3]
    >>> schema = str(root / "workflow" / "schemas" / "config.schema.yaml")
    >>> config = yaml.safe_load((root / "config.yaml").read_text())
    >>> check_config(config, schema)["variants"][0]["name"]      # the paper's material, first
    'kim'
    >>> config["variants"][0]["D1"] = -1
    >>> check_config(config, schema)
    Traceback (most recent call last):
    ...
    restitution_workflow.config.ConfigError: variants[kim].D1 = -1: must be > 0
    """
    from snakemake.exceptions import WorkflowError
    from snakemake.utils import validate

    with open(schema_path) as fh:
        schema = yaml.safe_load(fh)
    _fill_defaults(config, schema, schema)
    try:
        validate(config, schema_path, set_default=False)   # defaults: _fill_defaults (oneOf branches too)
    except WorkflowError as err:
        # validate() raises while handling jsonschema's error: that error is the exception's context
        if not isinstance(err.__context__, jsonschema.ValidationError):
            raise
        error = jsonschema.exceptions.best_match([err.__context__])   # into oneOf's branches
        field = _field(config, error.absolute_path)
        value = error.instance if error.validator not in ("required", "additionalProperties") else "{...}"
        if error.validator == "additionalProperties":
            extra = sorted(set(error.instance) - set(error.schema.get("properties", {})))
            field = f"{field}.{extra[0]}" if field != "config" else extra[0]
            value = error.instance[extra[0]]
        raise ConfigError(f"{field} = {_show(value)}: {_allowed(error)}") from None

    found = _non_finite(config, schema, schema)
    if found:
        path, value, allowed = found
        raise ConfigError(f"{_field(config, path)} = {value!r}: {allowed}")
    beyond_schema(config)
    return config


def beyond_schema(config: dict) -> None:
    """The rules between fields that the schema cannot express, with the library's own checks (so the
    messages match the CLI's). Imports only light modules: no sympy, no scipy."""
    from restitution.audit.readings import reading_labels
    from restitution.audit.stability import AtlasSpec
    from restitution.core.errors import ParameterError
    from restitution.core.exponents import Exponents
    from restitution.core.series import MAX_INDEX

    every = config["variants"] + config["extra_variants"]
    names = [v["name"] for v in every]
    dupes = sorted({n for n in names if names.count(n) > 1})
    if dupes:
        raise ConfigError(f"variants[].name = {dupes[0]!r}: must be unique (over variants and extra_variants)")
    if config["main_variant"] not in names:
        raise ConfigError(f"main_variant = {config['main_variant']!r}: must be one of {', '.join(names)}")
    main = next(v for v in every if v["name"] == config["main_variant"])
    if _paper_exponents_differ(main):
        raise ConfigError(f"main_variant = {config['main_variant']!r}: must have the paper's exponents alpha = 3/2, "
                          "gamma = 1 (the manuscript audits the paper's claims); study other materials as further "
                          "variants")
    _ordered("compare.omega_max", config["compare"]["omega_max"], "compare.omega_min", config["compare"]["omega_min"])
    try:
        max_power = Fraction(str(config["series"]["max_power"]))
        if max_power < 1:
            raise ValueError
    except (ValueError, ZeroDivisionError):
        raise ConfigError(f"series.max_power = {config['series']['max_power']!r}: "
                          "must be a rational number >= 1") from None
    labels = reading_labels()
    for v in every:
        where = f"{'variants' if v in config['variants'] else 'extra_variants'}[{v['name']}]"
        try:
            ex = Exponents.parse(v["alpha"], v["gamma"])
        except ParameterError as err:
            raise ConfigError(f"{where}.{err}") from None
        # the series engine's limit, checked here so that a value it cannot serve stops the run
        # before any job, not inside every series job
        if max_power * ex.p > MAX_INDEX:
            raise ConfigError(f"series.max_power = {max_power}: must be at most {Fraction(MAX_INDEX, ex.p)} "
                              f"for variant {v['name']} (exponent denominator p = {ex.p})")
        _ordered(f"{where}.g_range.max", v["g_range"]["max"], "g_range.min", v["g_range"]["min"])
        if v["fit_g_range"] is not None:
            _ordered(f"{where}.fit_g_range.max", v["fit_g_range"]["max"], "fit_g_range.min", v["fit_g_range"]["min"])
        _check_omega_served(where, v, ex)
        for label in [] if v["readings"] == "all" else v["readings"]:
            if label not in labels:
                raise ConfigError(f"{where}.readings = {label!r}: must be one of {', '.join(labels)} (or the word all)")
    if config["connection"]["figure_reading"] not in labels:
        raise ConfigError(f"connection.figure_reading = {config['connection']['figure_reading']!r}: "
                          f"must be one of {', '.join(labels)}")
    for i, pair in enumerate(config["exact_family"]["pairs"]):
        # the schema leaves exponents to Exponents.parse (NaN and infinity included): without this
        # check a pair ["3/2", .nan] was accepted and stopped the exact-family job with a traceback
        try:
            ex = Exponents.parse(*pair)
        except ParameterError as err:
            raise ConfigError(f"exact_family.pairs[{i}].{err}") from None
        if ex.alpha != 2 * ex.gamma + 1:
            raise ConfigError(f"exact_family.pairs[{i}] = [{ex.alpha}, {ex.gamma}]: must satisfy alpha = 2 gamma + 1 "
                              "(the exact family that maps onto the linear dashpot)")
    _check_calibration_powers(config["exact_family"]["calibration_powers"])
    try:
        AtlasSpec.from_config(atlas_settings(config))
    except ParameterError as err:
        raise ConfigError(f"stability.{err}") from None


def _check_calibration_powers(powers: list) -> None:
    """Feng's elastic exponents p: each a rational >= 1 (the schema leaves exponents to the
    library's reader: without this a power .nan or .inf was accepted, and the calibration job then
    failed on it), 3/2 among them (the table prints Hertz's row)."""
    from restitution.core.errors import ParameterError
    from restitution.core.exponents import parse_exponent

    read = []
    for i, q in enumerate(powers):
        try:
            read.append(parse_exponent(f"calibration_powers[{i}]", q, minimum=Fraction(1), inclusive=True))
        except ParameterError as err:
            raise ConfigError(f"exact_family.{err}") from None
    if Fraction(3, 2) not in read:
        raise ConfigError(f"exact_family.calibration_powers = {powers!r}: must include 3/2 (Hertz's p, a row of the "
                          "table)")


def _paper_exponents_differ(variant: dict) -> bool:
    from restitution.core.errors import ParameterError
    from restitution.core.exponents import Exponents

    try:
        ex = Exponents.parse(variant["alpha"], variant["gamma"])
    except ParameterError:
        return False   # reported with the variant's field below
    return (ex.alpha, ex.gamma) != (Fraction(3, 2), Fraction(1))


def _ordered(high_field: str, high, low_label: str, low) -> None:
    if not low < high:
        raise ConfigError(f"{high_field} = {high!r}: must be > {low_label} = {low!r}")


def atlas_settings(config: dict) -> dict:
    """The stability block without `shards` (the workflow's, not the atlas's)."""
    return {k: v for k, v in config["stability"].items() if k != "shards"}


def _check_omega_served(where: str, v: dict, ex) -> None:
    """Every impact speed of a variant must give an Omega the reference integrator serves: D1, D2
    and g are each fine alone, but together they set Omega (Omega is a power of g, so the ends of
    each range suffice)."""
    from restitution.core.collision import OMEGA_RANGE
    from restitution.core.errors import ParameterError
    from restitution.core.model import Material

    material = Material.of(ex, v["D1"], v["D2"])
    speeds = [("g_figure", v["g_figure"]), ("g_range.min", v["g_range"]["min"]), ("g_range.max", v["g_range"]["max"])]
    if v["fit_g_range"] is not None:
        speeds += [("fit_g_range.min", v["fit_g_range"]["min"]), ("fit_g_range.max", v["fit_g_range"]["max"])]
    lo, hi = OMEGA_RANGE
    for field, g in speeds:
        try:
            omega = float(material.omega(g))
        except ParameterError as err:   # Omega beyond double precision
            raise ConfigError(f"{where}.{field} = {g!r}: {err.allowed}") from None
        if not lo <= omega <= hi:
            raise ConfigError(f"{where}.{field} = {g!r}: gives Omega = {omega:.3g} with D1 = {v['D1']!r}, "
                              f"D2 = {v['D2']!r}; the reference integrator serves Omega in [{lo:g}, {hi:g}]")


#: Far above any real configuration, far below what takes a parser long (an alias bomb expands
#: a few hundred bytes into gigabytes: its expanded size is counted before anything is built).
MAX_CONFIG_BYTES = 1_000_000
MAX_NODES = 100_000


def _expanded_nodes(node, sizes: dict) -> int:
    """Nodes the document would have with every alias expanded (an alias shares its anchor's node)."""
    if id(node) not in sizes:
        sizes[id(node)] = 0   # a recursive alias counts once
        children = node.value if isinstance(node, yaml.SequenceNode) else \
            [n for pair in node.value for n in pair] if isinstance(node, yaml.MappingNode) else []
        sizes[id(node)] = min(MAX_NODES + 1, 1 + sum(_expanded_nodes(c, sizes) for c in children))
    return sizes[id(node)]


def read_config_file(path) -> dict:
    """config.yaml as a mapping, or ConfigError with one line: a YAML syntax error with its line
    (Snakemake's own message is two lines and names none), a missing, empty, non-UTF-8 or oversized
    file, a key given twice, or more aliases than a configuration needs (an alias bomb)."""
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_CONFIG_BYTES + 1)
    except FileNotFoundError:
        raise ConfigError(f"{path}: not found (the study's settings; see README.md)") from None
    except OSError as err:
        raise ConfigError(f"{path}: cannot be read: {err.strerror}") from None
    if len(raw) > MAX_CONFIG_BYTES:
        raise ConfigError(f"{path}: larger than {MAX_CONFIG_BYTES} bytes: not a configuration")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as err:
        line = raw[:err.start].count(b"\n") + 1
        raise ConfigError(f"{path}, line {line}: byte 0x{raw[err.start]:02x} is not UTF-8 text") from None
    if not text.strip() or all(not l.strip() or l.lstrip().startswith("#") for l in text.splitlines()):
        raise ConfigError(f"{path}: empty: it must set main_variant and variants (see README.md)")
    try:
        root = yaml.compose(text, Loader=StrictLoader)
        if root is not None and _expanded_nodes(root, {}) > MAX_NODES:
            raise ConfigError(f"{path}: its YAML aliases (*name) expand to more than {MAX_NODES} values: "
                              "not a configuration")
        data = yaml.load(text, Loader=StrictLoader)  # noqa: S506 - a SafeLoader subclass
    except ConfigError as err:
        raise ConfigError(f"{path}, {err}" if str(err).startswith("line ") else str(err)) from None
    except yaml.YAMLError as err:
        mark = getattr(err, "problem_mark", None) or getattr(err, "context_mark", None)
        where = f"{path}, line {mark.line + 1}, column {mark.column + 1}" if mark else str(path)
        what = " ".join(str(getattr(err, "problem", None) or err).split())
        context = getattr(err, "context", None)
        if context and getattr(err, "problem", None):
            what = f"{what} ({' '.join(str(context).split())})"
        raise ConfigError(f"{where}: {what}" if isinstance(err, Refused) else f"{where}: not valid YAML: {what}") from None
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise ConfigError(f"{path} = {_show(data)}: must be a mapping of settings (main_variant: ..., "
                          "variants: ...)")
    return data


def precheck_file(path) -> None:
    """For the Snakefile, before its `configfile:` loads ``path``: a YAML syntax error becomes
    one line, "config error: <path>, line N, column M: ...", and exit status 2; so does a missing,
    empty or non-UTF-8 file, a duplicated key and an alias bomb (read_config_file)."""
    import sys

    try:
        read_config_file(path)
    except ConfigError as err:
        sys.stderr.write(f"config error: {err}\n")
        sys.exit(2)


if __name__ == "__main__":  # python workflow/lib/restitution_workflow/config.py config.yaml: the same check
    import sys

    for arg in sys.argv[1:] or ["config.yaml"]:
        precheck_file(arg)
