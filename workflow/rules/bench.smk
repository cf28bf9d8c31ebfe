# Stage: speed against accuracy in the manuscript. Rendered from the committed snapshot of
# `make bench` (benchmarks/recorded/), not from a fresh run: costs vary from run to run and the
# PDF must be byte-identical between builds. The benchmark itself is not part of the paper build.

BENCH_OUTPUTS = ["results/paper/bench_table.tex", "results/paper/bench_pareto.pdf",
                 "results/paper/bench_pareto.png", "results/paper/bench_values.tex"]


rule bench_section:
    """Table and Pareto plot (max relative error against cost) of the main variant's methods."""
    input:
        table="benchmarks/recorded/speed_accuracy.csv",
        code=code("bench_section.py"),
    output:
        table=BENCH_OUTPUTS[0],
        pdf=BENCH_OUTPUTS[1],
        png=BENCH_OUTPUTS[2],
        values=BENCH_OUTPUTS[3],
    params:
        exponents=lambda wildcards: {"alpha": str(VARIANTS[MAIN]["alpha"]), "gamma": str(VARIANTS[MAIN]["gamma"])},
    log:
        "logs/bench_section.log",
    script:
        script_file("bench_section.py")
