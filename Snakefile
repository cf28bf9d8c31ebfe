# restitution: rebuild and audit S. Kim, "Coefficient of Restitution for Viscoelastic Materials".
#
#   snakemake --cores 2                     everything, manuscript PDF included (results/paper/)
#   snakemake --cores 2 outputs             everything except the PDF (no TeX needed)
#   snakemake results/figures/fig1.pdf      one figure of the main variant, and only what it needs
#
# Per-variant outputs live under results/<variant>/; see config.yaml for the variants.

configfile: "config.yaml"


include: "workflow/rules/common.smk"     # config validation, variants, package-source inputs
include: "workflow/rules/series.smk"     # exact perturbation series and their LaTeX tables
include: "workflow/rules/reference.smk"  # reference integrations (trajectories, eps(g), accuracy)
include: "workflow/rules/figures.smk"    # figures 1-4 (PDF + PNG)
include: "workflow/rules/values.smk"     # every number the manuscript prints, as LaTeX macros
include: "workflow/rules/manuscript.smk" # the reproduction article, built with latexmk


rule all:
    default_target: True
    input:
        all_outputs_but_pdf(),
        PAPER_PDF,


rule outputs:
    input:
        all_outputs_but_pdf(),
