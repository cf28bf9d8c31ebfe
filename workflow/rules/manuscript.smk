# Stage 5: the article and its supplement. paper/restitution.tex \input's generated files only
# (values, tables) and includes the main variant's figures; latexmk runs in build/paper/
# (scratch, not reproducible byte for byte) and only the PDF is copied to results/paper/.


# latexmk can stop one pass short: after a clean build of the supplement it reported "References
# changed" after its third pdflatex pass and ended, with a section's page still moving (LaTeX's
# "Rerun to get cross-references right" in the log). Further pdflatex passes settle it; three more
# at most, and the test of the built tree fails if the warning is still there.
def settle(name):
    return (f"for pass in 1 2 3; do grep -q 'Rerun to get' {{params.build:q}}/{name}.log || break; "
            f"pdflatex -interaction=nonstopmode -halt-on-error -file-line-error "
            f"-output-directory={{params.build:q}} {{input.tex:q}} >> {{log:q}} 2>&1 "
            f"|| (tail -n 40 {{log:q}} >&2; exit 1); done; ")


rule manuscript_inputs:
    """Where the manuscript finds the main variant's generated files."""
    input:
        code=code("manuscript_inputs.py"),
    output:
        "results/paper/inputs.tex",
    params:
        main=MAIN,
    log:
        "logs/manuscript_inputs.log",
    script:
        script_file("manuscript_inputs.py")


rule software:
    """The versions of Python and of the packages that compute and typeset (a parameter: an upgrade
    rewrites the file, and every script's rule reads it)."""
    output:
        SOFTWARE,
    params:
        versions=json.dumps(BUILD_VERSIONS, indent=2),
    log:
        "logs/software.log",
    shell:
        "printf '%s\\n' {params.versions:q} | {ATOMIC} write {output:q} 2> {log:q}"


rule provenance:
    """The commit (a parameter: a new one reruns this rule alone) and the software versions the
    manuscript names."""
    input:
        code=code("provenance.py"),
        software=SOFTWARE,
    output:
        "results/paper/provenance.tex",
    params:
        commit=BUILD_COMMIT,
    log:
        "logs/provenance.log",
    script:
        script_file("provenance.py")


rule article_labels:
    """The numbers of the article's labels, which the supplement cites (xr, prefix A-), while the article
    cites the supplement's: one pdflatex pass of the article gives them before the supplement is built, so
    the two documents need no cycle in the build. Only the numbers are kept
    (workflow/lib/restitution_workflow/aux_labels.py): they follow from the article's source alone, not from
    its pages, its citations or the supplement's .aux of an earlier build that this pass may find."""
    input:
        tex="paper/restitution.tex",
        code="workflow/lib/restitution_workflow/aux_labels.py",
        generated=manuscript_inputs,   # asked when the DAG is built: every stage is included by then
    output:
        ARTICLE_LABELS,
    log:
        "logs/article_labels.log",
    params:
        build="build/article-labels",
    shell:
        "rm -rf {params.build:q} && mkdir -p {params.build:q} && "
        "export FORCE_SOURCE_DATE=1 SOURCE_DATE_EPOCH=${{SOURCE_DATE_EPOCH:-1700000000}}; "
        "pdflatex -draftmode -interaction=nonstopmode -halt-on-error -file-line-error "
        "-output-directory={params.build:q} {input.tex:q} > {log:q} 2>&1 "
        "|| (tail -n 40 {log:q} >&2; exit 1); "
        "{AUX_LABELS} {params.build:q}/restitution.aux | {ATOMIC} write {output:q}"


rule supplement:
    """The supplement (paper/supplement.tex): the audit, the other force laws, the cost study, the DEM
    details and the stability atlas. Its .aux is an output too: the article reads its labels (xr), as it
    reads the article's (rule article_labels)."""
    input:
        tex="paper/supplement.tex",
        bib="paper/restitution.bib",
        article=ARTICLE_LABELS,
        generated=manuscript_inputs,   # asked when the DAG is built: every stage is included by then
    output:
        pdf=SUPPLEMENT_PDF,
        bbl=SUPPLEMENT_BBL,
        aux=SUPPLEMENT_AUX,
    log:
        "logs/supplement.log",
    params:
        build="build/supplement",
    shell:
        "rm -rf {params.build:q} && mkdir -p {params.build:q} && "
        "export FORCE_SOURCE_DATE=1 SOURCE_DATE_EPOCH=${{SOURCE_DATE_EPOCH:-1700000000}}; "
        "latexmk -pdf -interaction=nonstopmode -halt-on-error -file-line-error "
        "-outdir={params.build:q} {input.tex:q} > {log:q} 2>&1 "
        "|| (tail -n 40 {log:q} >&2; exit 1); " + settle("supplement") +
        "{ATOMIC} install {params.build:q}/supplement.bbl {output.bbl:q} && "
        "{ATOMIC} install {params.build:q}/supplement.aux {output.aux:q} && "
        "{ATOMIC} install {params.build:q}/supplement.pdf {output.pdf:q}"


rule manuscript:
    """The article (paper/restitution.tex), which cites the supplement's sections, tables and figures by
    their numbers, read from the supplement's .aux."""
    input:
        tex="paper/restitution.tex",
        bib="paper/restitution.bib",
        supplement=SUPPLEMENT_AUX,
        generated=manuscript_inputs,   # asked when the DAG is built: every stage is included by then
    output:
        pdf=PAPER_PDF,
        bbl=PAPER_BBL,   # the bibliography as typeset: what an arXiv bundle carries instead of the .bib
    log:
        "logs/manuscript.log",
    params:
        build="build/paper",
    shell:
        # FORCE_SOURCE_DATE makes pdfTeX take dates from SOURCE_DATE_EPOCH; the .tex file removes
        # the trailer ID and the PTEX info, so the PDF bytes depend on the sources only.
        "rm -rf {params.build:q} && mkdir -p {params.build:q} && "
        "export FORCE_SOURCE_DATE=1 SOURCE_DATE_EPOCH=${{SOURCE_DATE_EPOCH:-1700000000}}; "
        "latexmk -pdf -interaction=nonstopmode -halt-on-error -file-line-error "
        "-outdir={params.build:q} {input.tex:q} > {log:q} 2>&1 "
        "|| (tail -n 40 {log:q} >&2; exit 1); " + settle("restitution") +
        # through the one atomic writer: never a truncated PDF under the final name
        "{ATOMIC} install {params.build:q}/restitution.bbl {output.bbl:q} && "
        "{ATOMIC} install {params.build:q}/restitution.pdf {output.pdf:q}"


rule arxiv:
    """results/paper/arxiv.tar.gz: what arXiv compiles with plain pdflatex, no bibtex (`make arxiv`)."""
    input:
        tex="paper/restitution.tex",
        bbl=PAPER_BBL,
        pdf=PAPER_PDF,
        supplement_tex="paper/supplement.tex",
        supplement_bbl=SUPPLEMENT_BBL,
        supplement_aux=SUPPLEMENT_AUX,
        article_labels=ARTICLE_LABELS,
        supplement_pdf=SUPPLEMENT_PDF,
        generated=manuscript_inputs,   # asked when the DAG is built: every stage is included by then
        # the tables behind the engine and calibration numbers, so a reader can check them without
        # the software: LAMMPS' eps per speed and rule (extrapolated and coarsest step), the typed-e
        # table, the calibrated dampings and Feng's formula against the exact family; and the ledger of
        # Kim's claims with each row's tolerance and notes, which the supplement's table names
        data=["results/dem/lammps_eps.csv", "results/dem/typed_e.csv", "results/dem/calibration.csv",
              "results/paper/feng_calibration.csv", f"results/{MAIN}/claims.csv",
              # the tolerance study behind the supplement's accuracy figures (referee r28: named, not carried)
              f"results/{MAIN}/reference/accuracy.csv",
              # every atlas pair's uniform form, shape and coefficients, which the supplement's table
              # summarises and the abstract quotes (referee r27: printed nowhere before)
              *expand("results/stability/uniform/{shard}-of-{shards}.json", shard=range(STABILITY_SHARDS),
                      shards=STABILITY_SHARDS)],
        # and every engine run behind an engine number: LAMMPS' behind lammps_eps.csv and each engine's
        # behind the typed-e table, its deck and its output, with how to rerun them (the READMEs last)
        engine_runs=lammps_run_files() + [LAMMPS_RUNS_README],
        typed_e_runs=typed_e_run_files() + [f"{TYPED_E_RUNS}/typed_e_runs.csv", f"{TYPED_E_RUNS}/README.txt"],
        # the checksums of all of those files (the supplement's data section names it)
        manifest=ENGINE_RUNS_MANIFEST,
        code=code("arxiv_bundle.py"),
    output:
        "results/paper/arxiv.tar.gz",
    params:
        # the sources go in as an ancillary archive of the tracked files: a new commit makes a new bundle
        commit=BUILD_COMMIT,
    log:
        "logs/arxiv.log",
    script:
        script_file("arxiv_bundle.py")


rule exact_family:
    """The exact family alpha = 2 gamma + 1: the reference integrator against the linear dashpot at
    (gamma + 1) Omega under both end rules, and the overlap rule's sticking threshold (the article's
    section on it prints the measured agreement)."""
    input:
        code=code("exact_family.py"),
    output:
        values="results/paper/exact_family_values.tex",
        table="results/paper/exact_family.csv",
    params:
        pairs=[[str(a), str(g)] for a, g in config["exact_family"]["pairs"]],
        omegas=[float(w) for w in config["exact_family"]["omegas"]],
        rtol=float(config["exact_family"]["rtol"]),
        below=float(config["exact_family"]["below"]),
        above=float(config["exact_family"]["above"]),
    log:
        "logs/exact_family.log",
    script:
        script_file("exact_family.py")


rule feng_calibration:
    """Feng's calibration formula for the family alpha = 2 gamma + 1 (arXiv:2603.27764) against the
    library's exact family under both end rules, with the reference integrator as a second method (the
    supplement's table)."""
    input:
        code=code("feng_calibration.py"),
    output:
        values="results/paper/feng_values.tex",
        tex="results/paper/feng_table.tex",
        table="results/paper/feng_calibration.csv",
    params:
        targets=[float(e) for e in config["exact_family"]["calibration_targets"]],
        powers=[str(q) for q in config["exact_family"]["calibration_powers"]],
        rtol=float(config["exact_family"]["rtol"]),
    log:
        "logs/feng_calibration.log",
    script:
        script_file("feng_calibration.py")
