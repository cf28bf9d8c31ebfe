# Stage 2: reference integrations of the scaled equation (restitution.core.collision, scipy
# solve_ivp with events). Each expensive step is its own rule, so restyling a figure never
# reruns an integration. Everything here depends on Omega, hence on D1 and D2.


rule reference_trajectories:
    """Forward collision at g_figure, and its time-reversed, rescaled image (the inverse collision)."""
    input:
        code=code("reference_trajectories.py"),
    output:
        forward="results/{variant}/reference/forward.csv",
        inverse="results/{variant}/reference/inverse.csv",
        summary="results/{variant}/reference/summary.json",
    params:
        exponents=exponents,
        D1=vparam("D1"),
        D2=vparam("D2"),
        g=vparam("g_figure"),
        rtol=NUMERICS["rtol"],
        points=NUMERICS["trajectory_points"],
    priority: 50  # first: the slow symbolic connection (next stage) waits for its x~_c
    log:
        "logs/{variant}/reference_trajectories.log",
    script:
        script_file("reference_trajectories.py")


rule reference_eps_curve:
    """eps, tau_b, tau_c, ... over the impact speeds of figure 4."""
    input:
        code=code("reference_eps_curve.py"),
    output:
        "results/{variant}/reference/eps_curve.csv",
    params:
        exponents=exponents,
        D1=vparam("D1"),
        D2=vparam("D2"),
        g_range=vparam("g_range"),
        rtol=NUMERICS["rtol"],
    log:
        "logs/{variant}/reference_eps_curve.log",
    script:
        script_file("reference_eps_curve.py")


rule reference_accuracy:
    """How eps, tau_b, tau_c at g_figure move with the solver tolerance (the speed/accuracy trade)."""
    input:
        code=code("reference_accuracy.py"),
    output:
        "results/{variant}/reference/accuracy.csv",
    params:
        exponents=exponents,
        D1=vparam("D1"),
        D2=vparam("D2"),
        g=vparam("g_figure"),
        rtols=NUMERICS["accuracy_rtols"],
    log:
        "logs/{variant}/reference_accuracy.log",
    script:
        script_file("reference_accuracy.py")


BUILT_FOR["reference_accuracy"] = lambda name: name == MAIN   # the manuscript prints the main variant's only

