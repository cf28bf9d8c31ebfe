# For DEM modellers (issue 14): eps(v) of two spheres in the real LAMMPS engine over the library's
# curves for both end-of-contact rules, and the main variant's damping calibrated to target eps.
# LAMMPS comes with the optional group restitution[dem], which `make paper` installs (test extra).
#
# Needs from the including Snakefile: common.smk (lib, code, script_file, MAIN, VARIANTS).
# Settings: config["dem"] (all optional; the schema lists them and their defaults).

DEM_FILES = [
    "results/dem/lammps_eps.csv",
    "results/dem/curves.csv",
    "results/dem/calibration.csv",
    "results/dem/calibration.tex",
    "results/dem/values.tex",
    "results/dem/eps_lammps.pdf",
    "results/dem/eps_lammps.png",
]


def lammps_run_files():
    """Each LAMMPS run's deck (.in) and screen (.out), named for its end rule, impact speed and the
    steps per contact time (dt = t_c / n: three steps per speed, extrapolated to dt = 0, and a fourth,
    finer one that tests the model of the time-step error)."""
    steps = config["dem"]["lammps_steps"]
    return [f"results/dem/lammps_runs/{rule}_g{g:g}_n{steps * k}.{ext}" for rule in ("force", "overlap")
            for g in config["dem"]["speeds"] for k in (1, 2, 4, 8) for ext in ("in", "out")]


LAMMPS_RUNS_README = "results/dem/lammps_runs/README.txt"


rule dem_study:
    """LAMMPS runs (three time steps each, extrapolated, and a fourth that tests the extrapolation) with
    each run's deck and screen, the library's eps(v) for both rules, the calibration table, the section's
    numbers and its figure."""
    input:
        code=code("dem_study.py"),
    output:
        DEM_FILES,
        # what LAMMPS was given and printed in every run behind lammps_eps.csv (the arXiv bundle's)
        runs=lammps_run_files(),
        readme=LAMMPS_RUNS_README,
    params:
        # the overlap_* settings belong to rule overlap_limit: a change there must not rerun LAMMPS
        dem={k: v for k, v in config["dem"].items() if not k.startswith("overlap_")},
        material={k: VARIANTS[MAIN][k] for k in ("name", "alpha", "gamma", "D1", "D2")},
    log:
        "logs/dem_study.log",
    script:
        script_file("dem_study.py")


# The e a user types into each code against the eps the code really gives (issue 25): the library's
# table (restitution.dem.engines.typed_e_table), each row with the engine that confirms it. The table reads the
# engine registry, so every registered engine's modules are inputs (code() follows the registry).
TYPED_E_FILES = ["results/dem/typed_e.csv", "results/dem/typed_e.tex", "results/dem/typed_e_values.tex"]


rule typed_e:
    """The typed-e table: the library's eps for each code and typed e, and each row's engine, the e
    values at which the engine tests run it and the agreement they demand."""
    input:
        code=code("typed_e.py"),
        # the engines' runs of the table's rows: the text quotes how close they come
        runs="results/dem/typed_e_runs/typed_e_runs.csv",
    output:
        csv=TYPED_E_FILES[0],
        table=TYPED_E_FILES[1],
        values=TYPED_E_FILES[2],
    params:
        es=[0.1, 0.3, 0.5, 0.7, 0.9, 0.99],
    log:
        "logs/typed_e.log",
    script:
        script_file("typed_e.py")


# The engine runs behind the typed-e table (issue 53): every row run in the engine named for it, as the
# engine tests run it, with what each engine was given and printed kept for the arXiv bundle.
TYPED_E_RUNS = "results/dem/typed_e_runs"
#: The input file each engine run as a child process is given (its runner writes it; the script checks
#: that the recorded files are these).
TYPED_E_PROCESS_INPUTS = {"liggghts": ["in.collide"], "yade": ["collide.py"], "kratos": ["collide.py"]}


def typed_e_run_engines():
    """The registered engines with typed-e rows, in registry order."""
    from restitution.dem.engines import ENGINES
    return [name for name, engine in ENGINES.items() if engine.typed_e]


def typed_e_run_files():
    """Every engine's recorded runs: LAMMPS one deck and screen per run, named for the row's option,
    e and steps per contact; the others their input, command and output of one process."""
    import re
    from restitution.dem.engines import ENGINES
    from restitution.dem.engines.typed_e_table import TYPED_E_ENGINE_ES, TYPED_E_ENGINE_REFINEMENTS
    files = []
    for name in typed_e_run_engines():
        engine = ENGINES[name]
        if name == "lammps":
            files += [f"{TYPED_E_RUNS}/lammps/{re.sub(r'[^a-z0-9]+', '_', row.split(' ', 1)[1].lower()).strip('_')}"
                      f"_e{e:g}_n{engine.typed_e_steps * k}.{ext}"
                      for row in engine.typed_e for e in TYPED_E_ENGINE_ES for k in TYPED_E_ENGINE_REFINEMENTS
                      for ext in ("in", "out")]
        else:
            files += [f"{TYPED_E_RUNS}/{name}/{f}" for f in [*TYPED_E_PROCESS_INPUTS[name], "command.txt", "output.txt"]]
    return files


# the engine tests' collision (tests/engine_case.py): unlike spheres, glass on steel; one speed, each row's
# eps being a function of e alone. The manifest rule prints it for the article's table caption.
TYPED_E_COLLISION = {"radii": [1e-3, 1.5e-3], "densities": [2500.0, 7800.0]}


rule typed_e_runs:
    """Each typed-e row in its engine at the confirming e values (three time steps, extrapolated), its
    eps beside the table's, and every run's deck and output (LAMMPS, LIGGGHTS, Yade, Kratos)."""
    input:
        code=code("typed_e_runs.py"),
    output:
        csv=f"{TYPED_E_RUNS}/typed_e_runs.csv",
        values=f"{TYPED_E_RUNS}/values.tex",
        runs=typed_e_run_files(),
        readme=f"{TYPED_E_RUNS}/README.txt",
    params:
        engines=typed_e_run_engines(),
        radii=TYPED_E_COLLISION["radii"],
        densities=TYPED_E_COLLISION["densities"],
        material={"E": 5e7, "nu": 0.3},
        g=0.1,
    log:
        "logs/typed_e_runs.log",
    script:
        script_file("typed_e_runs.py")


ENGINE_RUNS_MANIFEST = "results/dem/engine_runs_manifest.txt"


rule engine_runs_manifest:
    """Every engine run file the arXiv bundle carries with its SHA-256 (the manifest, in the bundle), the
    supplement's count of them per engine, and one LAMMPS deck typeset as it was run."""
    input:
        lammps=lammps_run_files() + [LAMMPS_RUNS_README],
        typed=typed_e_run_files() + [f"{TYPED_E_RUNS}/typed_e_runs.csv", f"{TYPED_E_RUNS}/README.txt"],
        code=code("engine_runs_manifest.py"),
    output:
        manifest=ENGINE_RUNS_MANIFEST,
        values="results/paper/engine_runs_values.tex",
        deck="results/paper/engine_runs_deck.tex",
    params:
        # the first of the figure's runs: force rule, slowest speed, coarsest step
        sample=lammps_run_files()[0],
        collision=TYPED_E_COLLISION,
    log:
        "logs/engine_runs_manifest.log",
    script:
        script_file("engine_runs_manifest.py")


# The overlap rule's viscous limit (issue 24): eps ~ C Omega^k for gamma <= alpha < 2 gamma + 1, the law
# against both integrators for the variants' exponents and a few more, and the section's numbers.
OVERLAP_FILES = [
    "results/dem/overlap_limit.csv",
    "results/dem/overlap_curves.csv",
    "results/dem/overlap_table.tex",
    "results/dem/overlap_values.tex",
    "results/dem/overlap_limit.pdf",
    "results/dem/overlap_limit.png",
]


def _overlap_pairs():
    """(alpha, gamma, label) of every variant where the law exists ("main" for the main one), then the
    configured check pairs."""
    pairs = []
    for name, v in VARIANTS.items():
        a, g = Fraction(str(v["alpha"])), Fraction(str(v["gamma"]))
        if g <= a < 2 * g + 1:
            pairs.append((str(a), str(g), "main" if name == MAIN else name))
    pairs += [(str(Fraction(a)), str(Fraction(g)), "check") for a, g in config["dem"]["overlap_check_pairs"]]
    return pairs


rule overlap_limit:
    """eps ~ C Omega^k under the overlap rule: the law, its checks against the reference and mpmath
    integrators, its table, figure and the numbers the manuscript prints."""
    input:
        code=code("overlap_limit.py"),
    output:
        csv=OVERLAP_FILES[0],
        curves=OVERLAP_FILES[1],
        table=OVERLAP_FILES[2],
        values=OVERLAP_FILES[3],
        pdf=OVERLAP_FILES[4],
        png=OVERLAP_FILES[5],
    params:
        pairs=_overlap_pairs(),
        check_omegas=config["dem"]["overlap_check_omegas"],
        moderate_omegas=[0.3, 0.1, 0.05],
        highprec_omega=1.0e-2,
        highprec_digits=20,
        curve_omega=[1.0e-4, 10.0],
        curve_points=21,
        decay_inverse_omegas=list(range(1, 32, 2)),
        material={"D1": float(VARIANTS[MAIN]["D1"]), "D2": float(VARIANTS[MAIN]["D2"]),
                  "g_max": float(VARIANTS[MAIN]["g_range"]["max"])},
    log:
        "logs/overlap_limit.log",
    script:
        script_file("overlap_limit.py")
