"""Reference pages written at build time from the sources they describe, so that none is typed by
hand and none goes stale: the config.yaml and scene-file schemas (field tables), the method
ladder's rung registry, and the recorded speed/accuracy snapshot.

Each page is written to docs/reference/_generated/ only when its text changes, so that Sphinx
does not rebuild pages whose source did not change.
"""

from __future__ import annotations

import csv
import inspect
import json
import re
import sys
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[3]
OUT = ROOT / "docs" / "reference" / "_generated"


def _cell(text) -> str:
    """One Markdown table cell: no newlines, pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def _plain(rst: str) -> str:
    """Docstring reST (``x``, :func:`x`) as Markdown code spans, for a Markdown table."""
    rst = re.sub(r":[a-z]+:`~?([^`]+)`", r"`\1`", rst)
    return rst.replace("``", "`")


def _resolve(schema: dict, node: dict) -> dict:
    """Follow a local ``$ref`` (``#/$defs/NAME``), keeping the node's own description over the target's."""
    ref = node.get("$ref")
    if not ref:
        return node
    target = schema
    for part in ref.lstrip("#/").split("/"):
        target = target[part]
    merged = dict(_resolve(schema, target))
    merged.update({k: v for k, v in node.items() if k != "$ref"})
    return merged


def _type(node: dict) -> str:
    """What a value may be, in a few words: the enum, the JSON type with its bounds, or the alternatives."""
    if "enum" in node:
        return "one of " + ", ".join(f"`{v}`" for v in node["enum"])
    if "oneOf" in node or "anyOf" in node:
        return " or ".join(_type(n) for n in node.get("oneOf", node.get("anyOf")))
    words = []
    t = node.get("type")
    if t:
        words.append(t if isinstance(t, str) else " or ".join(t))
    for key, sign in (("minimum", ">="), ("exclusiveMinimum", ">"), ("maximum", "<="), ("exclusiveMaximum", "<")):
        if key in node:
            words.append(f"{sign} {node[key]}")
    if "pattern" in node:
        words.append("matching `" + node["pattern"].replace("(?![\\s\\S])", "$") + "`")
    if t == "array" and "items" in node:
        words.append("of " + _type(node["items"]))
    return ", ".join(words) or "any"


def _rows(schema: dict, node: dict, prefix: str, required: set, out: list) -> None:
    node = _resolve(schema, node)
    for name, child in node.get("properties", {}).items():
        child = _resolve(schema, child)
        path = f"{prefix}{name}"
        default = f"`{json.dumps(child['default'])}`" if "default" in child else ""
        out.append((path, "yes" if name in required else "", _type(child), default, child.get("description", "")))
        if child.get("type") == "object" and "properties" in child:
            _rows(schema, child, path + ".", set(child.get("required", ())), out)
        items = child.get("items")
        if child.get("type") == "array" and isinstance(items, dict):
            items = _resolve(schema, items)
            if "properties" in items:
                _rows(schema, items, path + "[].", set(items.get("required", ())), out)


def schema_page(title: str, source: Path | dict, intro: str) -> str:
    """A page for one JSON schema (a YAML file, or the schema itself): its description, then every
    field (nested ones as a.b, list items as a[].b) with whether it is required, what it may be, its
    default and description."""
    schema = source if isinstance(source, dict) else yaml.safe_load(source.read_text())
    rows: list = []
    _rows(schema, schema, "", set(schema.get("required", ())), rows)
    # one entry per field rather than a table: the descriptions are sentences, too wide for columns
    lines = [f"# {title}", "", intro, "", _cell(schema.get("description", "")), ""]
    for path, required, value, default, what in rows:
        facts = "; ".join(filter(None, ["required" if required else "", _cell(value),
                                        f"default {_cell(default)}" if default else ""]))
        lines.append(f"- **`{path}`** ({facts}){': ' + _cell(what) if what else ''}")
    return "\n".join(lines) + "\n"


def rungs_page() -> str:
    """The method ladder's rungs in the order the chooser lists them, from the registry itself: the
    relation rungs of the full ladder (restitution.api.RELATIONS), then restitution.fast.rungs.RUNGS."""
    from restitution.api import RELATIONS
    from restitution.fast.rungs import ladder_rungs
    rungs = ladder_rungs(RELATIONS)
    lines = ["# The rungs of the method ladder", "",
             "Generated from the registry (`restitution.fast.rungs.ladder_rungs` with the full ladder's",
             "relations, `restitution.api.RELATIONS`) when the documentation is built, in the order the",
             "chooser (`restitution.fast.ladder`) lists them. A name may be served by two rungs, one per end",
             "rule. The cost is the rung's declared price per point, which the chooser compares (\"per",
             "request\": priced from the request); exact rungs are taken first wherever they serve.",
             "How the chooser uses them: {doc}`../../explanation/ladder`.", "",
             "| rung | end rules | exact | declared cost per point |", "| --- | --- | --- | --- |"]
    for i, rung in enumerate(rungs):
        lines.append(f"| [`{rung.name}`](#rung-{i}) | {', '.join(rung.ends)} | {'yes' if rung.exact else ''} | "
                     + (f"{rung.cost:.1e} s" if rung.cost else "per request") + " |")
    for i, rung in enumerate(rungs):
        cls = type(rung)
        # the class's own docstring, else its module's: a subclass without one would show the base's
        doc = inspect.cleandoc(cls.__dict__.get("__doc__") or sys.modules[cls.__module__].__doc__ or "")
        lines += ["", f"(rung-{i})=", f"## `{rung.name}` ({', '.join(rung.ends)})", "",
                  f"`{cls.__module__}.{cls.__name__}`", "", _plain(doc.split("\n\n")[0])]
    return "\n".join(lines) + "\n"


def speed_page() -> str:
    """The recorded speed/accuracy snapshot as a table (benchmarks/recorded/speed_accuracy.csv)."""
    with open(ROOT / "benchmarks" / "recorded" / "speed_accuracy.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    # the columns a reader compares; the CSV has the rest (median error, the Omega range of each row)
    head = ["alpha, gamma", "method", "setting", "evaluations per second", "max relative error", "note"]
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    lines += ["| " + " | ".join(_cell(c) for c in (f"{r['alpha']}, {r['gamma']}", r["method"], r["setting"],
                                                 r["evals_per_s"], r["max_rel_err"], r.get("note", ""))) + " |"
              for r in rows]
    return "\n".join(lines) + "\n"


def api_page() -> str:
    """The API page: an autosummary of ``restitution.__all__``, ``restitution.dem.__all__`` and the
    CLI's entry points, so that a name added to ``__all__`` gets its page without editing this site."""
    import restitution
    import restitution.dem

    def block(module: str, names) -> list:
        return [f".. currentmodule:: {module}", "", ".. autosummary::", "   :toctree: ../_autosummary", "",
                *(f"   {n}" for n in names), ""]

    lines = ["Python API", "==========", "",
             "The package's public names (``restitution.__all__``), each from its numpydoc docstring.", "",
             *block("restitution", restitution.__all__),
             "DEM layer", "---------", "",
             "``restitution.dem.__all__``; the codes' options are mapped in :doc:`../../howto/dem`.", "",
             *block("restitution.dem", restitution.dem.__all__),
             "Command line", "------------", "",
             "The entry point of the ``restitution`` command and its parser (:doc:`../cli`).", "",
             *block("restitution.cli", ["main", "build_parser"])]
    return "\n".join(lines)


def _write(name: str, text: str) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / name
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def generate(app=None) -> None:
    from restitution.dem.scene_file import scene_schema

    _write("config.md", schema_page(
        "config.yaml", ROOT / "workflow" / "schemas" / "config.schema.yaml",
        "The pipeline's configuration, generated from `workflow/schemas/config.schema.yaml`, against which "
        "the pipeline validates `config.yaml` (and any `--configfile`) before it runs anything."))
    _write("scene.md", schema_page(
        "The scene file", scene_schema(),
        "A scene for `restitution scene FILE` and `make scene SCENE=FILE`, generated from "
        "`src/restitution/dem/scene.schema.yaml` and each engine's options (`scene_option_schema` "
        "in `restitution.dem.engines`), against which every scene file is checked. "
        "See {doc}`../../howto/scenes` for how the answer is found."))
    _write("rungs.md", rungs_page())
    _write("api.rst", api_page())
    _write("speed_accuracy.md", speed_page())


def setup(app):
    # at config-inited, before Sphinx lists the source files: written any later, api.rst is not
    # among them on a fresh clone's first build, autosummary writes no stub pages for it and the
    # build fails on its warnings (later builds passed, the previous build's api.rst being there)
    app.connect("config-inited", lambda app, config: generate(app))
    return {"parallel_read_safe": True, "parallel_write_safe": True}


def figure(path: Path) -> None:
    """The README's and the index page's figure: eps against impact speed for the three materials
    of config.yaml, under both end rules, from the library (deterministic bytes: no metadata)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from restitution import Material, epsilon

    config = yaml.safe_load((ROOT / "config.yaml").read_text())
    g = np.geomspace(1e-3, 1e2, 120)
    fig, ax = plt.subplots(figsize=(8.0, 3.4), dpi=100)
    for i, v in enumerate(config["variants"]):
        m = Material(v["alpha"], v["gamma"], v["D1"], v["D2"])
        for end, style in (("force", "-"), ("overlap", "--")):
            try:
                eps = epsilon(alpha=v["alpha"], gamma=v["gamma"], omega=m.omega(g), tol=1e-8, end=end).eps
            except ValueError:          # the overlap rule: these bodies stick at some speeds
                continue
            ax.semilogx(g, eps, style, color=f"C{i}",
                        label=f"{v['name']} (alpha {v['alpha']}, gamma {v['gamma']}), {end} rule")
    ax.set_xlabel("impact speed g")
    ax.set_ylabel("coefficient of restitution eps")
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5), frameon=False)
    fig.tight_layout()
    fig.savefig(path, metadata={"Software": None})
    plt.close(fig)


if __name__ == "__main__":
    # `python -m restitution_workflow.docs_pages figure` refreshes docs/_static/eps.png (committed: the README
    # shows it on the forge, where nothing is built).
    if sys.argv[1:] == ["figure"]:
        figure(ROOT / "docs" / "_static" / "eps.png")
    else:
        generate()
