# Stage 5: every number the manuscript prints, collected from the stage outputs and written as
# LaTeX macros (values.tex, \newcommand{\OmegaAtG}{...}) and as JSON for `make check`.


def claims_inputs(wildcards):
    """The claims ledger feeds the macros where the paper's exponents apply, and the accuracy
    study those of the main variant (the only one whose text prints it)."""
    out = {}
    if is_paper_case(wildcards.variant):
        out.update(claims_values=f"results/{wildcards.variant}/claims/values.json",
                   claims_csv=f"results/{wildcards.variant}/claims.csv")
    if wildcards.variant == MAIN:
        out["accuracy"] = f"results/{wildcards.variant}/reference/accuracy.csv"
    return out


rule values:
    input:
        unpack(claims_inputs),
        summary=rules.reference_trajectories.output.summary,
        curve=rules.reference_eps_curve.output[0],
        agreement=rules.series_table.output.agreement,
        readings=rules.connection_readings.output.json,
        fit=rules.connection_fit.output.json,
        errors=rules.eps_compare.output.errors,
        code=code("values.py"),
    output:
        tex="results/{variant}/values/values.tex",
        json="results/{variant}/values/values.json",
    params:
        exponents=exponents,
        D1=vparam("D1"),
        D2=vparam("D2"),
        rtol=NUMERICS["rtol"],
        omega_order=SERIES["omega_order"],
        max_power=str(SERIES["max_power"]),
        claims=lambda wc: is_paper_case(wc.variant),
        accuracy=lambda wc: wc.variant == MAIN,
    log:
        "logs/{variant}/values.log",
    script:
        script_file("values.py")
