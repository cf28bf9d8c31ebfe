"""A JSON-schema error as one line, ``<field> = <value>: <what is allowed>``, e.g.
``variants[kim].D1 = -1: must be > 0`` or ``species[g1].radius = -0.001: must be > 0``.

jsonschema's own messages are several lines long and name the failing keyword, not the field. The
pipeline's config.yaml and the scene files (:mod:`restitution.dem.scene.file`) are checked this way.
Needs jsonschema only for the errors it is given (no import here).
"""

from __future__ import annotations

import re

__all__ = ["field", "allowed", "show", "MAX_NAME"]

#: Longest name that labels a list entry (the schemas' maxLength: results/<name>/... must stay a path).
MAX_NAME = 64


def field(document: dict, path, root: str = "config") -> str:
    """variants[0].D1 -> variants[kim].D1 when the list entry has a name."""
    out = ""
    node = document
    for part in path:
        if isinstance(part, int):
            name = node[part].get("name") if isinstance(node, list) and isinstance(node[part], dict) else None
            # only a valid name labels the field: a long one would swamp the line, a newline break it
            valid = isinstance(name, str) and len(name) <= MAX_NAME and re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]*", name)
            out += f"[{name}]" if valid else f"[{part}]"
        else:
            out += f".{part}" if out else str(part)
        try:
            node = node[part]
        except (KeyError, IndexError, TypeError):
            node = None
    return out or root


def allowed(error) -> str:
    """What the failing keyword of a jsonschema ValidationError allows, in words."""
    v, s = error.validator, error.validator_value
    description = error.schema.get("description") if isinstance(error.schema, dict) else None
    # a folded YAML description ends in a newline: the message must stay one line
    description = " ".join(description.split()) if description else None
    text = {
        "minimum": lambda: f"must be >= {s}",
        "maximum": lambda: f"must be <= {s}",
        "exclusiveMinimum": lambda: f"must be > {s}",
        "exclusiveMaximum": lambda: f"must be < {s}",
        "minItems": lambda: f"needs at least {s} entries",
        "maxItems": lambda: f"allows at most {s} entries",
        "enum": lambda: "must be one of " + ", ".join(map(str, s)),
        "type": lambda: f"must be of type {s if isinstance(s, str) else ' or '.join(s)}",
        "pattern": lambda: f"must match {s}",
        "maxLength": lambda: f"must be at most {s} characters long",
        "minLength": lambda: f"must be at least {s} characters long",
    }.get(v, lambda: None)()
    if v == "required":
        missing = [k for k in s if k not in error.instance]
        return f"missing required field(s) {', '.join(missing)}"
    if v == "additionalProperties":
        names = ", ".join(sorted(error.schema.get("properties", {})))
        return f"unknown field(s); allowed: {names}"
    if v == "oneOf" and description:
        return f"must be {description}"
    if text is None:
        text = error.message
    return f"{text} ({description})" if description and v != "type" else text


def show(value) -> str:
    """repr of a value for the one-line message, shortened when it is very long."""
    text = repr(value)
    if len(text) > 80:
        text = f"{text[:60]}... ({len(value) if isinstance(value, str) else len(text)} characters)"
    return text
