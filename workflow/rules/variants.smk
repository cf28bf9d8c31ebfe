# Stage 6: the variants side by side. Every variant is integrated on a common grid of Omega and
# validated there against the known results that apply to its exponents, gets a generated
# section of the article (all but the main variant) and an index of its outputs
# (results/<variant>/study.txt, the target of a one-off study). The manuscript-level outputs
# (results/paper/) gather all variants: adding a variant reruns its own jobs and these.


rule validation:
    """Reference eps on the common grid of Omega, against closed forms, published expansions, and
    g-independence where it must hold."""
    input:
        curve=rules.reference_eps_curve.output[0],
        code=code("validation.py"),
    output:
        json="results/{variant}/validation/validation.json",
        known="results/{variant}/validation/known.csv",
    params:
        variant=lambda wc: wc.variant,
        exponents=exponents,
        grid=COMPARE,
        rtol=NUMERICS["rtol"],
        tolerances=VALIDATION,
    log:
        "logs/{variant}/validation.log",
    script:
        script_file("validation.py")


rule variant_section:
    """The generated section of an extra variant (numbers from its values.json)."""
    input:
        values="results/{variant}/values/values.json",
        validation=rules.validation.output.json,
        form="results/{variant}/uniform/form.json",
        code=code("variant_section.py"),
    output:
        "results/{variant}/section.tex",
    log:
        "logs/{variant}/variant_section.log",
    script:
        script_file("variant_section.py")


BUILT_FOR["variant_section"] = lambda name: name != MAIN   # the main variant is the article itself


rule study:
    """results/<variant>/study.txt: the list of everything the variant's study produced."""
    input:
        lambda wc: variant_outputs(wc.variant),
    output:
        "results/{variant}/study.txt",
    params:
        header=lambda wc: (f"# study of variant {wc.variant} (alpha = {VARIANTS[wc.variant]['alpha']}, "
                           f"gamma = {VARIANTS[wc.variant]['gamma']}): files produced"),
    log:
        "logs/{variant}/study.log",
    shell:
        # through the one atomic writer (a temporary name, then renamed; the digest recorded)
        "(echo {params.header:q}; printf '%s\\n' {input:q} | LC_ALL=C sort) "
        "| {ATOMIC} write {output:q} 2> {log:q}"


rule compare_variants:
    """eps(Omega) of every variant on the common grid, with the known results."""
    input:
        known=expand("results/{variant}/validation/known.csv", variant=list(VARIANTS)),
        curves=expand("results/{variant}/reference/eps_curve.csv", variant=list(VARIANTS)),
        code=code("compare_variants.py"),
    output:
        pdf="results/paper/eps_omega.pdf",
        png=report("results/paper/eps_omega.png", caption="../report/eps_omega.rst", category="Figures",
                   subcategory="all variants"),
    params:
        variants=list(VARIANTS),
        exponents={name: (str(v["alpha"]), str(v["gamma"])) for name, v in VARIANTS.items()},
        grid=COMPARE,
    log:
        "logs/compare_variants.log",
    script:
        script_file("compare_variants.py")


rule variants_tex:
    """results/paper/variants.tex (\\input of each extra variant's section) and the validation table."""
    input:
        sections=expand("results/{variant}/section.tex", variant=EXTRA),
        validation=expand("results/{variant}/validation/validation.json", variant=list(VARIANTS)),
        code=code("variants_tex.py"),
    output:
        sections="results/paper/variants.tex",
        validation="results/paper/validation.tex",
        macros="results/paper/variants_values.tex",
    log:
        "logs/variants_tex.log",
    script:
        script_file("variants_tex.py")
