# Stage: prior series set beside this project's numbers. Schwager and Poeschel's (2008) half-power
# series for Hertz contact with viscoelastic damping, re-derived (restitution.core.delayed_recovery) and
# compared term by term: with the published numbers that can be read (Schwager and Poeschel's second
# coefficient as quoted by Chatterjee et al.), this project's elastic expansion, a fit to the integrator, and the
# integrator itself. And Chatterjee, James and Brogliato's (2022) zero-load expansion at general exponents.


rule schwager_poeschel:
    """Coefficient and truncation-error tables and their macros (alpha = 3/2, gamma = 1/2, force rule)."""
    input:
        code=code("schwager_poeschel.py"),
    output:
        table="results/paper/schwager_poeschel_table.tex",
        errors="results/paper/schwager_poeschel_errors.tex",
        values="results/paper/schwager_poeschel_values.tex",
    params:
        kmax=12,                        # h_k through s^12: the re-derived h_13, h_14 are uncertain in the 2nd digit
        rtol=1e-13,                     # the reference integrator's tolerance (checked against mpmath)
        check_omega=1000.0,
        fit_omega=[30.0, 1e5, 24],      # Omega of the least-squares fit: s = Omega^(-3/10) in [0.03, 0.36]
        fit_degree=11,
        residual_omega_max=3000.0,      # the fit of h_6..h_8 once h_0..h_5 are subtracted
        residual_degree=6,
        end_omegas=[10.0, 15.0, 20.0, 30.0, 50.0, 100.0],  # where the end relation's remainder is above the noise
        omegas=[10.0, 30.0, 100.0, 1000.0, 10000.0],
        orders=[2, 4, 5, 6, 8, 10, 12],
        # Schwager and Poeschel's printed mu^2 coefficient as Chatterjee et al.'s toolbox quotes it (config.yaml)
        quoted_c2=config["prior_art"]["schwager_poeschel_c2"],
    log:
        "logs/schwager_poeschel.log",
    script:
        script_file("schwager_poeschel.py")


rule chatterjee_coefficients:
    """Chatterjee, James and Brogliato's (2022) zero-load coefficients, from their Beta-function forms and
    their integrals in mpmath, against the library's C1 and C2 at the article's force laws, the exact
    family's pairs and the stability atlas's pairs."""
    input:
        code=code("chatterjee.py"),
    output:
        values="results/paper/chatterjee_values.tex",
    params:
        # evaluated when the job runs: the atlas's pairs are set in stability.smk, included later
        pairs=lambda wildcards: ([[v["alpha"], v["gamma"]] for v in config["variants"]]
                                 + config["exact_family"]["pairs"] + _ATLAS_PAIRS),
        digits=30,
    log:
        "logs/chatterjee_coefficients.log",
    script:
        script_file("chatterjee.py")
