# Stage 1: the exact perturbation series x(tau; Omega) = sum_n Omega^n x_n(tau), forward and
# inverse, with rational coefficients (restitution.core.series), and their LaTeX tables marked
# against the coefficients the paper prints.


rule series:
    input:
        code=code("series.py"),
    output:
        forward="results/{variant}/series/forward.json",
        inverse="results/{variant}/series/inverse.json",
    params:
        exponents=exponents,
        omega_order=SERIES["omega_order"],
        max_power=str(SERIES["max_power"]),
    log:
        "logs/{variant}/series.log",
    script:
        script_file("series.py")


rule series_table:
    input:
        forward=rules.series.output.forward,
        inverse=rules.series.output.inverse,
        code=code("series_table.py"),
    output:
        table="results/{variant}/series/table.tex",
        agreement="results/{variant}/series/agreement.json",
    params:
        compare_with_paper=lambda wc: is_paper_case(wc.variant),
    log:
        "logs/{variant}/series_table.log",
    script:
        script_file("series_table.py")
