# Helpers shared by every stage: configuration (validated, one-line errors), variants,
# the package sources each rule imports, and the final outputs (derived from the rules).

import ast
import functools
import itertools
import os
import re
import shlex
import sys
from fractions import Fraction
from pathlib import Path


ROOT = Path(workflow.basedir)

from restitution_workflow.provenance import build_commit, versions
from restitution_workflow.config import ConfigError, check_config  # src/restitution_workflow/config.py

# Every generated file carries this date instead of "now" (the Makefile exports the same value).
os.environ.setdefault("SOURCE_DATE_EPOCH", "1700000000")
os.environ.setdefault("PYTHONHASHSEED", "0")


# ---------------------------------------------------------------------------------------------
# Configuration
# ---------------------------------------------------------------------------------------------

try:
    check_config(config, str(ROOT / "workflow" / "schemas" / "config.schema.yaml"))
except ConfigError as err:
    # One line naming the field and what is allowed; no traceback.
    sys.stderr.write(f"config error: {err}\n")
    sys.exit(2)

# `extra_variants` (empty in config.yaml) adds variants for one run: snakemake --config / --configfile.
VARIANTS = {v["name"]: v for v in config["variants"] + config["extra_variants"]}
MAIN = config["main_variant"]
NUMERICS = config["numerics"]
SERIES = config["series"]
CONNECTION = config["connection"]
COMPARE = config["compare"]
VALIDATION = config["validation"]

wildcard_constraints:
    variant="|".join(re.escape(name) for name in VARIANTS),
    fig="fig[1-4]",
    ext="pdf|png",


def vparam(key):
    """A params: entry taking `key` from the variant of the job (keeps params per-rule minimal)."""
    return lambda wildcards: VARIANTS[wildcards.variant][key]


def exponents(wildcards):
    return {"alpha": str(VARIANTS[wildcards.variant]["alpha"]),
            "gamma": str(VARIANTS[wildcards.variant]["gamma"])}


# The printed numbers of Kim's paper (series, c0-c2) only apply to its exponents.
PAPER_EXPONENTS = (Fraction(3, 2), Fraction(1))


def _exponents_of(name):
    from restitution.core.exponents import Exponents

    v = VARIANTS[name]
    ex = Exponents.parse(v["alpha"], v["gamma"])
    return ex.alpha, ex.gamma


def is_paper_case(name):
    """The paper's exponents: its printed numbers (series, c0-c2, claims) apply."""
    return _exponents_of(name) == PAPER_EXPONENTS


# ---------------------------------------------------------------------------------------------
# Package sources a script imports: declared as inputs so a physics change reruns exactly the
# rules that use it (Snakemake does not follow a script's imports by itself).
# ---------------------------------------------------------------------------------------------

PKG = ROOT / "src" / "restitution"


def _module_file(dotted):
    """src/restitution file of `core.collision` (a module) or `core` (a package), or None."""
    base = PKG.joinpath(*dotted.split(".")) if dotted else PKG
    for f in (base.with_suffix(".py"), base / "__init__.py"):
        if f.exists():
            return f
    return None


def _statements(body):
    """Every statement of a module, nested ones (in functions, classes, if/try/with) included: an
    import is a statement, so expressions need not be walked (ast.walk over every node took most
    of the Snakefile's load time, which every run, dry run and cluster job step pays)."""
    for node in body:
        yield node
        for field in ("body", "orelse", "finalbody", "handlers"):
            yield from _statements(getattr(node, field, ()))
        for case in getattr(node, "cases", ()):
            yield from _statements(case.body)


@functools.cache   # every rule asks again; parsing each module once keeps a no-op run fast
def _imports_of(dotted):
    """Dotted names (below restitution) of the package modules that module `dotted` imports."""
    f = _module_file(dotted)
    here = [p for p in dotted.split(".") if p] + (["__init__"] if f.name == "__init__.py" else [])
    found = set()
    for node in _statements(ast.parse(f.read_text(), filename=str(f)).body):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[:len(here) - node.level]
            elif node.module and (node.module + ".").startswith("restitution."):
                base = []
            else:
                continue
            mod = [part for part in (node.module or "").split(".") if part]
            if not node.level:
                mod = mod[1:]   # drop "restitution"
            found.add(".".join(base + mod))
            found.update(".".join(base + mod + [a.name]) for a in node.names)
        elif isinstance(node, ast.Import):
            found.update(a.name.split(".", 1)[1] for a in node.names if a.name.startswith("restitution."))
    return {m for m in found if m and _module_file(m)}


def lib(*modules):
    """src/restitution files the given modules ("core.collision", ...) need: their import closure,
    and the __init__.py of each package on the way. Those run on import, but only to import
    names: their own imports are not followed, so a change to the series does not rerun the
    integrations because restitution/__init__.py imports both."""
    seen, todo = set(), list(modules)
    while todo:
        m = todo.pop()
        if m in seen:
            continue
        seen.add(m)
        f = _module_file(m)
        if f is not None and f.name != "__init__.py":
            todo.extend(_imports_of(m) - seen)
    packages = {".".join(m.split(".")[:i]) for m in seen for i in range(len(m.split(".")))}
    files = {_module_file(m) or PKG.joinpath(*m.split(".")).with_suffix(".py") for m in seen | packages}
    return sorted(str(f.relative_to(ROOT)) for f in files)


BUILD_COMMIT, BUILD_VERSIONS = build_commit(ROOT), versions()


# The one atomic writer, for shell rules: `{ATOMIC} install SRC DEST`, `... | {ATOMIC} write DEST`.
ATOMIC = f"{shlex.quote(sys.executable)} {shlex.quote(str(ROOT / 'src' / 'restitution_workflow' / 'atomic.py'))}"


def script_file(name):
    """Path of a workflow script for `script:` (relative to the .smk files) ..."""
    return f"../scripts/{name}"


def code(name):
    """... and the same file as an input, so touching it reruns the rule (and its dependants),
    with the helpers every script writes through (restitution_workflow/pipeline.py imports its atomic.py)."""
    return [f"workflow/scripts/{name}", "src/restitution_workflow/pipeline.py", "src/restitution_workflow/atomic.py"]


# ---------------------------------------------------------------------------------------------
# Figure 4 relations Omega~ = c0 + c1 Omega + c2 Omega^2 to draw next to the reference eps(g).
# Each is a JSON file {"kind", "label", "source", "c"} ("c": null and a "reason" where the
# relation does not exist for the variant): the paper's printed c's (its exponents only), ours
# from the paper's procedure (connection_readings) and ours from least squares (connection_fit).
# ---------------------------------------------------------------------------------------------

RELATIONS = {
    # kind -> (applies to variant?, path template)
    "printed": (is_paper_case, "results/{variant}/relations/printed.json"),
    "derived": (lambda name: True, "results/{variant}/relations/derived.json"),
    "fitted": (lambda name: True, "results/{variant}/relations/fitted.json"),
}


def relation_files(wildcards):
    return [tpl.format(variant=wildcards.variant)
            for applies, tpl in RELATIONS.values() if applies(wildcards.variant)]


# ---------------------------------------------------------------------------------------------
# Final outputs, derived from the rules: every output of every rule, for every configured variant
# the rule is built for. `all` and `outputs` request them all, so a deleted file is rebuilt
# (Snakemake does not remake a missing intermediate whose consumers are up to date). Computed when
# the DAG is built, after every include, so include order does not matter and a new rule's outputs
# join the build without being listed anywhere.
# ---------------------------------------------------------------------------------------------

FIGURES = ["fig1", "fig2", "fig3", "fig4"]
PAPER_PDF = "results/paper/restitution.pdf"
PAPER_BBL = "results/paper/restitution.bbl"
SUPPLEMENT_PDF = "results/paper/supplement.pdf"
SUPPLEMENT_BBL = "results/paper/supplement.bbl"
SUPPLEMENT_AUX = "results/paper/supplement.aux"   # the article's cross-references to the supplement (xr)
EXTRA = [name for name in VARIANTS if name != MAIN]   # variants with a generated section

#: Rules built for only some variants (rule name -> predicate on the variant's name), each set
#: beside its rule. Such a rule can still be asked for any variant by its path.
BUILT_FOR = {}
#: Rules built only when their output is asked for (not part of `all`/`outputs`), and the rules
#: that make the PDF (`all` adds them; `outputs` is everything that needs no TeX).
ON_REQUEST = {"arxiv"}
NEEDS_TEX = {"manuscript", "supplement"}
#: The values each wildcard of a final output takes; a stage with wildcards of its own adds them.
WILDCARD_VALUES = {"variant": lambda: list(VARIANTS), "fig": lambda: FIGURES, "ext": lambda: ["pdf", "png"]}


def _outputs_of(rule, variant=None):
    """The concrete outputs of `rule` for every value of its wildcards that the rule accepts (with
    `variant`: only the outputs of that variant)."""
    built_for = BUILT_FOR.get(rule.name, lambda name: True)
    out = []
    for pattern in rule.output:
        names = sorted(pattern.get_wildcard_names())
        if variant is not None and "variant" not in names:
            continue
        values = {n: [variant] if n == "variant" and variant is not None else WILDCARD_VALUES[n]() for n in names}
        for combination in itertools.product(*(values[n] for n in names)):
            wildcards = dict(zip(names, combination))
            if "variant" in wildcards and not built_for(wildcards["variant"]):
                continue
            path = pattern.apply_wildcards(wildcards)
            if pattern.match(path):   # the rule's wildcard constraints
                out.append(str(path))   # a plain path: the report() flag stays with the producing rule
    return out


def _promised(skip):
    return [rule for rule in workflow.rules if rule.name not in skip | ON_REQUEST | {"all", "outputs"}]


@functools.cache   # asked by `all`, `outputs` and every study once the rules are all defined
def final_outputs(tex=False):
    """Every output the pipeline promises (the PDF's too with tex=True), sorted."""
    return sorted({f for rule in _promised(set() if tex else NEEDS_TEX) for f in _outputs_of(rule)})


def variant_outputs(name):
    """Everything the study of one variant produces (the target of results/<name>/study.txt)."""
    return sorted({f for rule in _promised(NEEDS_TEX | {"study"}) for f in _outputs_of(rule, name)})


def manuscript_inputs(wildcards=None):
    """What the article and the supplement read besides their own .tex and .bib: the sections under
    paper/sections/, and every promised .tex and .pdf (LaTeX reads nothing else, and the manuscript
    reads no file that is not generated). Derived from the rules' outputs when the DAG is built, so
    a stage's table or figure joins the manuscript's inputs without its path being typed again."""
    sections = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "paper" / "sections").glob("*.tex"))
    return sections + [f for f in final_outputs() if f.endswith((".tex", ".pdf"))]
