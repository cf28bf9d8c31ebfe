# The uniform approximation of eps (restitution.core.uniform): per variant the fitted form with its
# measured error estimate, and the supplement's section on its numbers and fit. Named for what it is, a
# fitted approximation, not a closed form (the exact family's closed form is elsewhere).


rule uniform_form:
    """The uniform forms of one variant (both end rules, where they exist), their errors over Omega and
    eps(g) from the force rule's."""
    input:
        curve=rules.eps_compare.output.curves,
        code=code("uniform_form.py"),
    output:
        json="results/{variant}/uniform/form.json",
        errors="results/{variant}/uniform/errors.csv",
        overlap_json="results/{variant}/uniform/form_overlap.json",
        overlap_errors="results/{variant}/uniform/errors_overlap.csv",
        curve="results/{variant}/uniform/eps_g.csv",
    params:
        exponents=exponents,
    log:
        "logs/{variant}/uniform_form.log",
    script:
        script_file("uniform_form.py")


rule uniform_section:
    """The supplement's section on the limits' constants and the uniform approximation's fit, the article's
    macros and tables of the form, and two figures."""
    input:
        forms=expand("results/{variant}/uniform/form.json", variant=list(VARIANTS)),
        errors=expand("results/{variant}/uniform/errors.csv", variant=list(VARIANTS)),
        overlap_forms=expand("results/{variant}/uniform/form_overlap.json", variant=list(VARIANTS)),
        overlap_errors=expand("results/{variant}/uniform/errors_overlap.csv", variant=list(VARIANTS)),
        curve=f"results/{MAIN}/uniform/eps_g.csv",
        code=code("uniform_section.py"),
    output:
        tex="results/paper/uniform_section.tex",
        values="results/paper/uniform_values.tex",
        table="results/paper/uniform_table.tex",            # the forms' tables alone, for the article
        overlap_table="results/paper/uniform_overlap_table.tex",
        eps_pdf="results/paper/uniform_eps.pdf",
        eps_png=report("results/paper/uniform_eps.png", caption="../report/uniform_eps.rst",
                       category="Figures", subcategory="uniform approximation"),
        err_pdf="results/paper/uniform_error.pdf",
        err_png=report("results/paper/uniform_error.png", caption="../report/uniform_error.rst",
                       category="Figures", subcategory="uniform approximation"),
    params:
        main=MAIN,
        variants=list(VARIANTS),
        exponents={name: {"alpha": str(v["alpha"]), "gamma": str(v["gamma"])} for name, v in VARIANTS.items()},
        materials={name: {"D1": float(v["D1"]), "D2": float(v["D2"])} for name, v in VARIANTS.items()},
    log:
        "logs/uniform_section.log",
    script:
        script_file("uniform_section.py")
