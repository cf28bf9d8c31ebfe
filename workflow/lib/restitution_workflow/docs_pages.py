"""Reference pages written at build time from the sources they describe, so that none is typed by
hand and none goes stale: the config.yaml and scene-file schemas (field tables), the method
ladder's rung registry, and the recorded speed/accuracy snapshot.

Each page is written to docs/reference/_generated/ only when its text changes, so that Sphinx
does not rebuild pages whose source did not change.
"""

from __future__ import annotations

import csv
import importlib
import inspect
import json
import re
import sys
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[3]
DOCS = ROOT / "docs"
OUT = DOCS / "reference" / "_generated"


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


#: The problems each rung is probed on, first served first: the paper's exponents under either end
#: rule, then Hertz with delta^(1/4) damping (the exact family, alpha = 2 gamma + 1).
PROBES = (("3/2", "1", "force"), ("3/2", "1", "overlap"), ("3/2", "1/4", "force"))
#: The Omegas probed for a rung's domain: every decade the library's numbers span.
DECADES = range(-300, 301)


def _probe(rung) -> tuple[str, str, str]:
    """(problem probed, Omega domain, reachable bound) of one rung, asked through its own
    interface (``outside``, ``quote``) without building anything."""
    import math

    import numpy as np

    from restitution.core.exponents import Exponents
    from restitution.core.problem import Problem
    from restitution.fast.rung import TOL_FLOOR, Request

    for alpha, gamma, end in PROBES:
        problem = Problem(Exponents.parse(alpha, gamma), end)
        if not rung.serves(Request(problem, np.array([1.0]), TOL_FLOOR)):
            continue
        inside = [k for k in DECADES if rung.outside(Request(problem, np.array([10.0 ** k]), TOL_FLOOR)) is None]
        if not inside:
            continue
        lo, hi = inside[0], inside[-1]
        middle = 10.0 ** inside[len(inside) // 2]
        quote = rung.quote(Request(problem, np.array([middle]), TOL_FLOOR))
        everywhere = (lo, hi) == (DECADES[0], DECADES[-1])
        # a rung reading a build may learn its range from the build (a relation's grid): not known here
        domain = (f"set by its {quote.needs_build}" if everywhere and quote.needs_build else
                  "every Omega probed" if everywhere else f"1e{lo} to 1e{hi}") \
            + (" (with gaps)" if len(inside) != hi - lo + 1 else "")
        if math.isfinite(quote.bound):
            reach = f"{quote.bound:.1e}"
        elif quote.needs_build:
            reach = f"at least {quote.floor:.0e} (its {quote.needs_build})" if quote.floor else \
                f"stated by its {quote.needs_build}"
        else:
            reach = _cell(quote.reason)
        return f"{alpha}, {gamma}, {end}", domain, reach
    return "none probed", "", ""


def rungs_page() -> str:
    """The method ladder's rungs in the order the chooser lists them, from the registry itself: the
    relation rungs of the full ladder (restitution.api.RELATIONS), then restitution.fast.rungs.RUNGS;
    for each, what a user chooses by (the smallest bound it states, its Omega domain, its cost),
    asked of the rung itself."""
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
             "Each rung is asked, without building anything, on the first of these problems it serves:",
             "the paper's exponents (alpha = 3/2, gamma = 1) under the force rule, then under the overlap",
             "rule, then Hertz with delta^(1/4) damping (alpha = 3/2, gamma = 1/4). *Omega domain*: the",
             f"decades 1e{DECADES[0]} to 1e{DECADES[-1]} it does not refuse (`outside`); *smallest bound*:",
             "the relative error bound it quotes for the tightest tolerance, at a decade in the middle",
             "of that domain (a rung that reads a build states its bound once the build is made).", "",
             "| rung | end rules | exact | probed on | Omega domain | smallest bound | declared cost per point |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for i, rung in enumerate(rungs):
        probed, domain, reach = _probe(rung)
        lines.append(f"| [`{rung.name}`](#rung-{i}) | {', '.join(rung.ends)} | {'yes' if rung.exact else ''} | "
                     f"{probed} | {domain} | {reach} | "
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
    from restitution.fast.ladder import RENAMED
    with open(ROOT / "benchmarks" / "recorded" / "speed_accuracy.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:   # a run recorded before a method's rename shows the name a reader can type today
        if r["method"] in RENAMED:
            r["method"] = f"{RENAMED[r['method']]} (recorded as {r['method']})"
    # the columns a reader compares; the CSV has the rest (median error, the Omega range of each row)
    head = ["alpha, gamma", "method", "setting", "evaluations per second", "max relative error", "note"]
    lines = ["| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    lines += ["| " + " | ".join(_cell(c) for c in (f"{r['alpha']}, {r['gamma']}", r["method"], r["setting"],
                                                 r["evals_per_s"], r["max_rel_err"], r.get("note", ""))) + " |"
              for r in rows]
    return "\n".join(lines) + "\n"


def _docs_code() -> list[str]:
    """The Python the documentation runs or shows: each tutorial, and each Python block or code
    cell of its Markdown pages (a cell's option lines left out)."""
    code = [p.read_text() for p in sorted((DOCS / "tutorials").glob("*.py"))]
    for page in sorted(DOCS.rglob("*.md")):
        if "_build" in page.parts or "_generated" in page.parts:
            continue
        for m in re.finditer(r"^```(?:python|\{code-cell\}[^\n]*)\n(.*?)^```", page.read_text(), flags=re.S | re.M):
            code.append("".join(ln for ln in m.group(1).splitlines(True) if not ln.startswith(":")))
    return code


def tutorial_imports() -> dict[str, list[str]]:
    """The project's names the documentation's code imports (``from restitution... import name``:
    the tutorials, and the code of the Markdown pages), by module: each gets an API entry, so a
    reader can look up whatever a tutorial or a how-to uses."""
    import ast

    found: dict[str, list[str]] = {}
    for code in _docs_code():
        for node in ast.walk(ast.parse(code)):
            if isinstance(node, ast.ImportFrom) and not node.level and node.module \
                    and node.module.split(".")[0] in ("restitution", "restitution_workflow"):
                names = found.setdefault(node.module, [])
                names += [a.name for a in node.names if a.name not in names]
    return found


def returned_types(objects) -> dict[str, list[str]]:
    """The classes the given functions return, by their home module, read from their return
    annotations (other objects are passed over)."""
    found: dict[str, list[str]] = {}
    for obj in objects:
        if not inspect.isfunction(obj):
            continue
        ann = inspect.signature(obj).return_annotation
        cls = sys.modules[obj.__module__].__dict__.get(ann) if isinstance(ann, str) else ann
        if inspect.isclass(cls):
            names = found.setdefault(cls.__module__, [])
            names += [cls.__name__] if cls.__name__ not in names else []
    return found


def api_page() -> str:
    """The API page: autosummaries of ``restitution.__all__``, ``restitution.dem.__all__``, the
    classes their functions return, the CLI's entry points and every project name a tutorial
    imports, so that a name added to ``__all__`` (or to a tutorial) gets its page without editing
    this site."""
    import restitution
    import restitution.dem

    listed = {("restitution", n) for n in restitution.__all__} | {("restitution.dem", n) for n in restitution.dem.__all__}

    def block(module: str, names) -> list:
        return [f".. currentmodule:: {module}", "", ".. autosummary::", "   :toctree: ../_autosummary", "",
                *(f"   {n}" for n in names), ""]

    def blocks(by_module: dict) -> list:
        out = []
        for module, names in sorted(by_module.items()):
            names = [n for n in names if (module, n) not in listed]
            listed.update((module, n) for n in names)
            out += block(module, names) if names else []
        return out

    imported = tutorial_imports()
    public = [getattr(m, n) for m in (restitution, restitution.dem) for n in m.__all__]
    # the public names' own classes are listed above under their public spelling
    listed_objects = {id(o) for o in public}
    returned = returned_types(public + [getattr(importlib.import_module(m), n) for m, ns in imported.items() for n in ns])
    results = {m: [n for n in ns if id(getattr(importlib.import_module(m), n)) not in listed_objects]
               for m, ns in returned.items()}
    lines = ["Python API", "==========", "",
             "The package's public names (``restitution.__all__``), each from its numpydoc docstring; a",
             "class's page lists its methods and properties.", "",
             *block("restitution", restitution.__all__),
             "DEM layer", "---------", "",
             "``restitution.dem.__all__``; the codes' options are mapped in :doc:`../../howto/dem`.", "",
             *block("restitution.dem", restitution.dem.__all__),
             "What they return", "----------------", "",
             "The objects the functions of this page return (``collide`` a ``Collision``,",
             "``perturbation_series`` a ``PerturbationSeries``, ...), at their home modules.", "",
             *blocks(results),
             "Names the documentation's code uses", "-----------------------------------", "",
             "Every other name the documentation's code imports (the :doc:`../../tutorials/index`, the",
             "how-to pages), at the module it imports it from: the engines' contact laws and designers,",
             "the LAMMPS runner, the pipeline's config check.", "",
             *blocks(imported),
             "Command line", "------------", "",
             "The entry point of the ``restitution`` command and its parser (:doc:`../cli`).", "",
             *block("restitution.cli", ["main", "build_parser"])]
    return "\n".join(lines)


def _write(name: str, text: str) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    path = OUT / name
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def notebooks(out: Path = DOCS / "tutorials" / "_notebooks") -> list[Path]:
    """Each tutorial as a Jupyter notebook (jupytext: percent format to .ipynb, outputs left to the
    reader's kernel), for the tutorials page's download links; written only when changed."""
    import jupytext

    out.mkdir(parents=True, exist_ok=True)
    written = []
    for script in sorted((DOCS / "tutorials").glob("*.py")):
        path = out / f"{script.stem}.ipynb"
        text = jupytext.writes(jupytext.read(script, fmt="py:percent"), fmt="ipynb")
        if not path.exists() or path.read_text() != text:
            path.write_text(text)
        written.append(path)
    return written


def generate(app=None) -> None:
    from restitution.dem.scene.file import scene_schema

    _write("config.md", schema_page(
        "config.yaml", ROOT / "workflow" / "schemas" / "config.schema.yaml",
        "The pipeline's configuration, generated from `workflow/schemas/config.schema.yaml`, against which "
        "the pipeline validates `config.yaml` (and any `--configfile`) before it runs anything."))
    _write("scene.md", schema_page(
        "The scene file", scene_schema(),
        "A scene for `restitution scene FILE` and `make scene SCENE=FILE`, generated from "
        "`src/restitution/dem/scene/scene.schema.yaml` and each engine's options (`scene_option_schema` "
        "in `restitution.dem.engines`), against which every scene file is checked. "
        "See {doc}`../../howto/scenes` for how the answer is found."))
    _write("rungs.md", rungs_page())
    _write("api.rst", api_page())
    _write("speed_accuracy.md", speed_page())
    notebooks()


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
