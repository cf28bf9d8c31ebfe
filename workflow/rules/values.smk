# Stage 4: every number the manuscript prints, computed from the stage outputs and written as
# LaTeX macros (values.tex, \newcommand{\OmegaAtG}{...}) and as JSON for `make check`.


rule values:
    input:
        summary=rules.reference_trajectories.output.summary,
        forward=rules.reference_trajectories.output.forward,
        inverse=rules.reference_trajectories.output.inverse,
        curve=rules.reference_eps_curve.output[0],
        accuracy=rules.reference_accuracy.output[0],
        agreement=rules.series_table.output.agreement,
        relations=relation_files,
        src=lib("series", "model", "damped", "printed"),
        code=code("values.py"),
    output:
        tex="results/{variant}/values/values.tex",
        json="results/{variant}/values/values.json",
    params:
        exponents=exponents,
        D1=vparam("D1"),
        D2=vparam("D2"),
        g_range=vparam("g_range"),
        rtol=NUMERICS["rtol"],
        omega_order=SERIES["omega_order"],
        max_power=str(SERIES["max_power"]),
        compare_with_paper=lambda wc: is_paper_case(wc.variant),
        track_tolerance=NUMERICS["track_tolerance"],
    log:
        "logs/{variant}/values.log",
    script:
        script_file("values.py")
