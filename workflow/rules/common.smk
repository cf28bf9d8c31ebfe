# Helpers shared by every stage: configuration (validated, one-line errors), variants,
# the package sources each rule imports, and the final outputs (derived from the rules).

import functools
import itertools
import json
import os
import re
import shlex
import sys
from fractions import Fraction
from pathlib import Path


ROOT = Path(workflow.basedir)

from restitution_workflow.provenance import build_commit, versions
from restitution_workflow.config import ConfigError, check_config  # workflow/lib/restitution_workflow/config.py
from restitution_workflow.sources import script_sources

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


BUILD_COMMIT, BUILD_VERSIONS = build_commit(ROOT), versions()


# The one atomic writer, for shell rules: `{ATOMIC} install SRC DEST`, `... | {ATOMIC} write DEST`.
ATOMIC = f"{shlex.quote(sys.executable)} {shlex.quote(str(ROOT / 'workflow' / 'lib' / 'restitution_workflow' / 'atomic.py'))}"
# The numbers of a document's labels from its .aux: `{AUX_LABELS} FILE.aux | {ATOMIC} write DEST`.
AUX_LABELS = f"{shlex.quote(sys.executable)} {shlex.quote(str(ROOT / 'workflow' / 'lib' / 'restitution_workflow' / 'aux_labels.py'))}"


def script_file(name):
    """Path of a workflow script for `script:` (relative to the .smk files) ..."""
    return f"../scripts/{name}"


#: The Python and package versions that compute the numbers (rule software), read by every script's
#: rule through code(): an upgrade reruns every job, so no output computed with the old versions is
#: kept beside a provenance section that names the new ones.
SOFTWARE = "results/paper/software.json"


def code(name):
    """... and the same file as an input, with every project module it runs (the closure of its
    imports, restitution_workflow.sources; Snakemake does not follow a script's imports): a change
    to any of them reruns the rule and its dependants, a change to any other module does not.
    And the software versions (SOFTWARE)."""
    script = ROOT / "workflow" / "scripts" / name
    return [f"workflow/scripts/{name}", SOFTWARE] + [str(f.relative_to(ROOT)) for f in script_sources(ROOT, script)]


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
ARTICLE_LABELS = "results/paper/article_labels.aux"   # the supplement's cross-references to the article (xr)
EXTRA = [name for name in VARIANTS if name != MAIN]   # variants with a generated section

#: Rules built for only some variants (rule name -> predicate on the variant's name), each set
#: beside its rule. Such a rule can still be asked for any variant by its path.
BUILT_FOR = {}
#: Rules built only when their output is asked for (not part of `all`/`outputs`), and the rules
#: that make the PDF (`all` adds them; `outputs` is everything that needs no TeX).
ON_REQUEST = {"arxiv"}
NEEDS_TEX = {"article_labels", "manuscript", "supplement"}
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
