# Stability atlas (issue 6): the reference integrator over Omega = 1e-8 .. 1e8 and a grid of
# exponents, every point checked against its invariants, a tighter tolerance, the mpmath
# reference and the closed forms (restitution.audit.stability). Split into `shards` parallel jobs of
# equal estimated cost; the merged table does not depend on the number of shards.
#
# Needs from the including Snakefile: common.smk (lib, code, script_file, WILDCARD_VALUES).
# Settings: config["stability"] (all optional; the schema lists them).

from restitution.audit.stability import AtlasSpec as _AtlasSpec
from restitution_workflow.config import atlas_settings as _atlas_settings

# config["stability"] was checked with the rest of the config (common.smk): schema and AtlasSpec.
STABILITY_SPEC = _AtlasSpec.from_config(_atlas_settings(config)).as_dict()
STABILITY_SHARDS = config["stability"]["shards"]

# the shards a build makes (their outputs join `all` like every rule's)
WILDCARD_VALUES.update(shard=lambda: range(STABILITY_SHARDS), shards=lambda: [STABILITY_SHARDS])


rule stability_shard:
    """One shard of the atlas: collide (and the comparisons) at its share of the points."""
    input:
        code=code("stability_atlas.py"),
    output:
        "results/stability/shards/{shard}-of-{shards}.csv",
    # The shards are the longest jobs of a cold build and only the merge waits for them: start
    # them before everything else (the critical path), the short jobs fill the other cores.
    priority: 50
    wildcard_constraints:
        shard=r"\d+",
        shards=r"\d+",
    params:
        spec=STABILITY_SPEC,
    log:
        "logs/stability/shard-{shard}-of-{shards}.log",
    script:
        script_file("stability_atlas.py")


rule stability_atlas:
    """The merged atlas, its invariants, the per-pair summary, the limits, and the appendix's numbers."""
    input:
        shards=expand("results/stability/shards/{shard}-of-{shards}.csv",
                      shard=range(STABILITY_SHARDS), shards=STABILITY_SHARDS),
        code=code("stability_atlas.py"),
    output:
        atlas="results/stability/atlas.csv",
        summary="results/stability/summary.csv",
        limits="results/stability/limits.csv",
        violations="results/stability/violations.csv",
        table="results/stability/summary.tex",
        values="results/stability/values.tex",
    params:
        spec=STABILITY_SPEC,
    log:
        "logs/stability/atlas.log",
    script:
        script_file("stability_atlas.py")


rule fig_stability:
    """The atlas figure: eps, 1 - eps, tau_c against Omega with the limits, and the measured errors."""
    input:
        atlas=rules.stability_atlas.output.atlas,
        code=code("fig_stability.py"),
    output:
        pdf="results/stability/atlas.pdf",
        png=report("results/stability/atlas.png", caption="../report/atlas.rst", category="Figures",
                   subcategory="all variants"),
    params:
        spec=STABILITY_SPEC,
    log:
        "logs/stability/fig_stability.log",
    script:
        script_file("fig_stability.py")


# The atlas's pairs, dealt round-robin to the shards. The variants' pairs among them are built again
# by rule uniform_form (the same library call): taking them from there would make the shards
# depend on the variants, and adding a variant would rerun the atlas.
_ATLAS_PAIRS = [list(p) for p in _AtlasSpec.from_config(_atlas_settings(config)).pairs]


rule uniform_shard:
    """The uniform forms (both end rules, where they exist) of one share of the atlas's pairs."""
    input:
        code=code("uniform_atlas.py"),
    output:
        "results/stability/uniform/{shard}-of-{shards}.json",
    # long and needed only by the appendix's table, like the atlas's shards: start them first
    priority: 50
    wildcard_constraints:
        shard=r"\d+",
        shards=r"\d+",
    params:
        pairs=lambda wildcards: _ATLAS_PAIRS[int(wildcards.shard)::int(wildcards.shards)],
    log:
        "logs/stability/uniform-{shard}-of-{shards}.log",
    script:
        script_file("uniform_atlas.py")


rule uniform_atlas:
    """The uniform approximation of every exponent pair of the atlas: its row in the appendix's table."""
    input:
        shards=expand("results/stability/uniform/{shard}-of-{shards}.json",
                      shard=range(STABILITY_SHARDS), shards=STABILITY_SHARDS),
        code=code("uniform_atlas.py"),
    output:
        csv="results/stability/uniform_forms.csv",
        tex="results/stability/uniform_forms.tex",
        values="results/stability/uniform_forms_values.tex",   # the article's summary of the table
    params:
        pairs=_ATLAS_PAIRS,
        # the pairs whose form the article's table prints: their rows point there instead of repeating it
        article_pairs=[[str(v["alpha"]), str(v["gamma"])] for v in VARIANTS.values()],
    log:
        "logs/stability/uniform_atlas.log",
    script:
        script_file("uniform_atlas.py")
