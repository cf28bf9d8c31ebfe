# Stage 3: figures 1-4 of the paper, per variant, as PDF (for LaTeX) and PNG (for people).
# Each figure is its own rule and script, so restyling one reruns that figure (and the
# manuscript) only. The main variant's figures are also copied to results/figures/.


rule fig1_forward:
    """Forward collision at g_figure: reference vs the series truncated at Omega^0..Omega^N."""
    input:
        trajectory=rules.reference_trajectories.output.forward,
        summary=rules.reference_trajectories.output.summary,
        code=code("fig1_forward.py"),
    output:
        pdf="results/{variant}/figures/fig1.pdf",
        png=report("results/{variant}/figures/fig1.png", caption="../report/fig1.rst",
                   category="Figures", subcategory="{variant}"),
    params:
        exponents=exponents,
        omega_order=SERIES["omega_order"],
        max_power=str(SERIES["max_power"]),
        plot=vparam("plot"),
    log:
        "logs/{variant}/fig1.log",
    script:
        script_file("fig1_forward.py")


rule fig2_inverse:
    """Inverse collision: time-reversed, rescaled reference vs the inverse series (x~(0) = 0)."""
    input:
        trajectory=rules.reference_trajectories.output.inverse,
        summary=rules.reference_trajectories.output.summary,
        code=code("fig2_inverse.py"),
    output:
        pdf="results/{variant}/figures/fig2.pdf",
        png=report("results/{variant}/figures/fig2.png", caption="../report/fig2.rst",
                   category="Figures", subcategory="{variant}"),
    params:
        exponents=exponents,
        omega_order=SERIES["omega_order"],
        max_power=str(SERIES["max_power"]),
        plot=vparam("plot"),
    log:
        "logs/{variant}/fig2.log",
    script:
        script_file("fig2_inverse.py")


rule fig3_phase:
    """Phase diagram (x, x') of the damped-only forward and inverse motions (Omega = 0)."""
    input:
        code=code("fig3_phase.py"),
    output:
        pdf="results/{variant}/figures/fig3.pdf",
        png=report("results/{variant}/figures/fig3.png", caption="../report/fig3.rst",
                   category="Figures", subcategory="{variant}"),
    params:
        gamma=lambda wc: str(VARIANTS[wc.variant]["gamma"]),
        points=NUMERICS["phase_points"],
    log:
        "logs/{variant}/fig3.log",
    script:
        script_file("fig3_phase.py")


rule printed_relation:
    """The paper's Omega~ = c0 + c1 Omega + c2 Omega^2 with its printed c's, for figure 4."""
    input:
        code=code("printed_relation.py"),
    output:
        "results/{variant}/relations/printed.json",
    log:
        "logs/{variant}/printed_relation.log",
    script:
        script_file("printed_relation.py")


BUILT_FOR["printed_relation"] = is_paper_case   # the printed c's exist for the paper's exponents only


rule fig4_eps:
    """eps(g): reference integration and every available Omega~(Omega) relation (eps_compare)."""
    input:
        curves=rules.eps_compare.output.curves,
        errors=rules.eps_compare.output.errors,
        known="results/{variant}/validation/known.csv",   # eps(Omega) where g does not matter
        code=code("fig4_eps.py"),
    output:
        pdf="results/{variant}/figures/fig4.pdf",
        png=report("results/{variant}/figures/fig4.png", caption="../report/fig4.rst",
                   category="Figures", subcategory="{variant}"),
        values="results/{variant}/figures/fig4_values.tex",   # where the axes clip a curve (the caption says)
    params:
        exponents=exponents,
        g_figure=vparam("g_figure"),
        fit_g_range=vparam("fit_g_range"),
    log:
        "logs/{variant}/fig4.log",
    script:
        script_file("fig4_eps.py")


rule main_figure:
    """results/figures/figN.{pdf,png}: the main variant's figures, under a stable name."""
    input:
        f"results/{MAIN}/figures/{{fig}}.{{ext}}",
    output:
        "results/figures/{fig}.{ext}",
    log:
        "logs/main_figure_{fig}_{ext}.log",
    shell:
        # through the one atomic writer: never a half-copied figure, and its digest recorded
        "{ATOMIC} install {input:q} {output:q} 2> {log:q}"
