# restitution: rebuild and audit S. Kim, "Coefficient of Restitution for Viscoelastic Materials".
#
#   snakemake --cores 2                     everything, manuscript PDF included (results/paper/)
#   snakemake --cores 2 outputs             everything except the PDF (no TeX needed)
#   snakemake results/figures/fig1.pdf      one figure of the main variant, and only what it needs
#   snakemake results/hertz/study.txt       the whole study of one variant, and nothing else
#
# Per-variant outputs live under results/<variant>/; see config.yaml for the variants.

# No import path is set here: the package (src/restitution) and the workflow's helpers
# (workflow/lib/restitution_workflow, a project of their own: workflow/pyproject.toml) are installed
# into the environment (make venv: editable installs of this tree), so the Snakefile, its rule files
# and every `script:` import them by name.

# A YAML syntax error in config.yaml: one line with its line number, before Snakemake's
# `configfile:` would report it in two lines without one (workflow/lib/restitution_workflow/config.py).
from restitution_workflow.config import precheck_file

precheck_file("config.yaml")  # the path `configfile:` reads (relative to the working directory)

configfile: "config.yaml"


include: "workflow/rules/common.smk"     # config validation, variants, package-source inputs
include: "workflow/rules/series.smk"     # exact perturbation series and their LaTeX tables
include: "workflow/rules/reference.smk"  # reference integrations (trajectories, eps(g), accuracy)
include: "workflow/rules/connection.smk" # c0-c2 three ways, eps(g) every way, the claims ledger
include: "workflow/rules/figures.smk"    # figures 1-4 (PDF + PNG)
include: "workflow/rules/variants.smk"   # validation, cross-variant figure, generated sections
include: "workflow/rules/prior_series.smk" # Schwager-Poeschel series, term by term
include: "workflow/rules/uniform.smk" # the uniform approximation of every variant (fitted, not a closed form)
include: "workflow/rules/values.smk"     # every number the manuscript prints, as LaTeX macros
include: "workflow/rules/stability.smk"  # appendix: the stability atlas at the extremes (issue 6)
include: "workflow/rules/dem.smk"        # using the results in a DEM code: LAMMPS runs, calibration
include: "workflow/rules/bench.smk"      # speed against accuracy, from the recorded make bench table
include: "workflow/rules/scene.smk"      # DEM scenes on request: make scene SCENE=scenes/x.yaml
include: "workflow/rules/manuscript.smk" # the reproduction article, built with latexmk


# Bookkeeping, tables and the plots (a second each, read from results) that a cluster executor
# runs on the submitting host, not as a queued job.
localrules: all, outputs, study, software, main_figure, manuscript_inputs, provenance, variants_tex, variant_section,
    arxiv, scene, fig1_forward, fig2_inverse, fig3_phase, fig4_eps, uniform_atlas, engine_runs_manifest


rule all:
    default_target: True
    input:
        # every rule's outputs (workflow/rules/common.smk), asked when the DAG is built: after
        # every include, whatever their order
        lambda wildcards: final_outputs(tex=True),


rule outputs:
    input:
        lambda wildcards: final_outputs(),
