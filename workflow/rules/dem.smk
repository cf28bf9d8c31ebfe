# For DEM modellers (issue 14): eps(v) of two spheres in the real LAMMPS engine over the library's
# curves for both end-of-contact rules, and the main variant's damping calibrated to target eps.
# LAMMPS comes with the optional group restitution[dem], which `make paper` installs (test extra).
#
# Needs from the including Snakefile: common.smk (lib, code, script_file, MAIN, VARIANTS,
# MANUSCRIPT_INPUTS). Settings: config["dem"]
# (all optional; the schema lists them and their defaults).

DEM_FILES = [
    "results/dem/lammps_eps.csv",
    "results/dem/curves.csv",
    "results/dem/calibration.csv",
    "results/dem/calibration.tex",
    "results/dem/values.tex",
    "results/dem/eps_lammps.pdf",
    "results/dem/eps_lammps.png",
]
MANUSCRIPT_INPUTS.extend(["paper/sections/dem.tex", "results/dem/values.tex", "results/dem/calibration.tex",
                          "results/dem/eps_lammps.pdf"])


rule dem_study:
    """LAMMPS runs (three time steps each, extrapolated), the library's eps(v) for both rules, the
    calibration table, the section's numbers and its figure."""
    input:
        src=lib("dem.settings", "dem.lammps", "dem.timestep"),
        code=code("dem_study.py"),
    output:
        DEM_FILES,
    params:
        dem=config["dem"],
        material={k: VARIANTS[MAIN][k] for k in ("name", "alpha", "gamma", "D1", "D2")},
    log:
        "logs/dem_study.log",
    script:
        script_file("dem_study.py")
