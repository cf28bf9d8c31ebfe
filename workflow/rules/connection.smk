# Stage 4: the connection Omega~ = c0 + c1 Omega + c2 Omega^2 between the forward and inverse
# collisions, three ways (restitution.audit.matching, restitution.core.connection): the paper's procedure for each reading of its
# text, a least-squares fit to the exact connection, and the eps(g) each relation implies against
# the reference. Where the paper's exponents apply, the claims ledger (restitution.audit.claims).


rule connection_readings:
    """c0-c2 from the paper's procedure, one row per reading (symbolic; the slow step)."""
    input:
        summary=rules.reference_trajectories.output.summary,
        code=code("connection_readings.py"),
    output:
        json="results/{variant}/connection/readings.json",
        csv="results/{variant}/connection/readings.csv",
        tex="results/{variant}/connection/readings.tex",
        relation="results/{variant}/relations/derived.json",
    params:
        exponents=exponents,
        readings=vparam("readings"),
        figure_reading=CONNECTION["figure_reading"],
    priority: 50  # on the critical path (the slow symbolic connection, then the ledger)
    log:
        "logs/{variant}/connection_readings.log",
    script:
        script_file("connection_readings.py")


rule connection_fit:
    """Least-squares c0-c2 on the exact connection (figure-4 points in the fit range), and the
    retrace check of the exact connection at g_figure."""
    input:
        curve=rules.reference_eps_curve.output[0],
        summary=rules.reference_trajectories.output.summary,
        code=code("connection_fit.py"),
    output:
        json="results/{variant}/connection/fit.json",
        residuals="results/{variant}/connection/fit_residuals.csv",
        relation="results/{variant}/relations/fitted.json",
    params:
        exponents=exponents,
        fit_g_range=vparam("fit_g_range"),
        rtol=NUMERICS["rtol"],
    log:
        "logs/{variant}/connection_fit.log",
    script:
        script_file("connection_fit.py")


rule eps_compare:
    """eps(g) from every relation against the reference: curves and the error table."""
    input:
        curve=rules.reference_eps_curve.output[0],
        relations=relation_files,
        code=code("eps_compare.py"),
    output:
        curves="results/{variant}/connection/eps_compare.csv",
        errors=report("results/{variant}/connection/eps_errors.csv", caption="../report/eps_errors.rst",
                      category="Tables", subcategory="{variant}"),
        tex="results/{variant}/connection/eps_errors.tex",
    params:
        exponents=exponents,
        fit_g_range=vparam("fit_g_range"),
    log:
        "logs/{variant}/eps_compare.log",
    script:
        script_file("eps_compare.py")


rule claims:
    """The claims ledger (paper's exponents only): claims.csv, its LaTeX table and the discussion
    of every row that was not reproduced."""
    input:
        readings=rules.connection_readings.output.json,
        fit=rules.connection_fit.output.json,
        curve=rules.reference_eps_curve.output[0],
        summary=rules.reference_trajectories.output.summary,
        code=code("claims.py"),
    output:
        csv=report("results/{variant}/claims.csv", caption="../report/claims.rst", category="Tables",
                   subcategory="{variant}"),
        values="results/{variant}/claims/values.json",
        table="results/{variant}/claims/table.tex",
        discussion="results/{variant}/claims/discussion.tex",
    params:
        material=lambda wc: {k: VARIANTS[wc.variant][k] for k in ("alpha", "gamma", "D1", "D2")},
        g_figure=vparam("g_figure"),
        rtol=NUMERICS["rtol"],
    priority: 50  # on the critical path (the slow symbolic connection, then the ledger)
    log:
        "logs/{variant}/claims.log",
    script:
        script_file("claims.py")


BUILT_FOR["claims"] = is_paper_case   # the ledger audits the paper's printed numbers: its exponents only
