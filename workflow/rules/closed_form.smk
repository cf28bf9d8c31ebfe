# The coefficient of restitution in closed form (restitution.core.uniform): per variant the fitted
# uniform form with its measured bound, and the manuscript section that shows it.


rule uniform_form:
    """The uniform forms of one variant (both end rules, where they exist), their errors over Omega and
    eps(g) from the force rule's."""
    input:
        curve=rules.eps_compare.output.curves,
        code=code("uniform_form.py"),
    output:
        json="results/{variant}/closed_form/form.json",
        errors="results/{variant}/closed_form/errors.csv",
        overlap_json="results/{variant}/closed_form/form_overlap.json",
        overlap_errors="results/{variant}/closed_form/errors_overlap.csv",
        curve="results/{variant}/closed_form/eps_g.csv",
    params:
        exponents=exponents,
    log:
        "logs/{variant}/uniform_form.log",
    script:
        script_file("uniform_form.py")


rule closed_form_section:
    """The manuscript's closed-form section: limits, the form, its numbers and two figures."""
    input:
        forms=expand("results/{variant}/closed_form/form.json", variant=list(VARIANTS)),
        errors=expand("results/{variant}/closed_form/errors.csv", variant=list(VARIANTS)),
        overlap_forms=expand("results/{variant}/closed_form/form_overlap.json", variant=list(VARIANTS)),
        overlap_errors=expand("results/{variant}/closed_form/errors_overlap.csv", variant=list(VARIANTS)),
        curve=f"results/{MAIN}/closed_form/eps_g.csv",
        code=code("closed_form_section.py"),
    output:
        tex="results/paper/closed_form.tex",
        values="results/paper/closed_form_values.tex",
        table="results/paper/uniform_table.tex",            # the forms' tables alone, for the article
        overlap_table="results/paper/uniform_overlap_table.tex",
        eps_pdf="results/paper/closed_form_eps.pdf",
        eps_png=report("results/paper/closed_form_eps.png", caption="../report/closed_form_eps.rst",
                       category="Figures", subcategory="closed form"),
        err_pdf="results/paper/closed_form_error.pdf",
        err_png=report("results/paper/closed_form_error.png", caption="../report/closed_form_error.rst",
                       category="Figures", subcategory="closed form"),
    params:
        main=MAIN,
        variants=list(VARIANTS),
        exponents={name: {"alpha": str(v["alpha"]), "gamma": str(v["gamma"])} for name, v in VARIANTS.items()},
        materials={name: {"D1": float(v["D1"]), "D2": float(v["D2"])} for name, v in VARIANTS.items()},
    log:
        "logs/closed_form_section.log",
    script:
        script_file("closed_form_section.py")
