# Stage 5: the reproduction article. paper/restitution.tex \input's generated files only
# (values, tables) and includes the main variant's figures; latexmk runs in build/paper/
# (scratch, not reproducible byte for byte) and only the PDF is copied to results/paper/.


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


rule provenance:
    """The commit and software versions the manuscript names (parameters: a change reruns it)."""
    input:
        code=code("provenance.py"),
    output:
        "results/paper/provenance.tex",
    params:
        commit=BUILD_COMMIT,
        versions=BUILD_VERSIONS,
    log:
        "logs/provenance.log",
    script:
        script_file("provenance.py")


rule manuscript:
    input:
        tex="paper/restitution.tex",
        bib="paper/restitution.bib",
        generated=lambda wildcards: MANUSCRIPT_INPUTS,   # complete once every stage is included
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
        "FORCE_SOURCE_DATE=1 SOURCE_DATE_EPOCH=${{SOURCE_DATE_EPOCH:-1700000000}} "
        "latexmk -pdf -interaction=nonstopmode -halt-on-error -file-line-error "
        "-outdir={params.build:q} {input.tex:q} > {log:q} 2>&1 "
        "|| (tail -n 40 {log:q} >&2; exit 1); "
        # through the one atomic writer: never a truncated PDF under the final name
        "{ATOMIC} install {params.build:q}/restitution.bbl {output.bbl:q} && "
        "{ATOMIC} install {params.build:q}/restitution.pdf {output.pdf:q}"


rule arxiv:
    """results/paper/arxiv.tar.gz: what arXiv compiles with plain pdflatex, no bibtex (`make arxiv`)."""
    input:
        tex="paper/restitution.tex",
        bbl=PAPER_BBL,
        pdf=PAPER_PDF,
        generated=lambda wildcards: MANUSCRIPT_INPUTS,   # complete once every stage is included
        code=code("arxiv_bundle.py"),
    output:
        "results/paper/arxiv.tar.gz",
    log:
        "logs/arxiv.log",
    script:
        script_file("arxiv_bundle.py")
