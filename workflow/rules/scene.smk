# Scenes (issue 26): `make scene SCENE=scenes/x.yaml` answers every contact of a DEM scene (the
# cheapest contact model within its tolerance, the calibrated setting, eps(v), contact time, time
# step), writes the code's input lines and a report with plots, under results/scenes/<name>/.
# Keyed by the scene's `name`: the file is config["scene"] when it has that name, else
# scenes/<name>.yaml. Built on request only (not part of `all`); each scene cached like a variant:
# rerun when its file or the library sources it uses change.
#
# Needs from the including Snakefile: common.smk (lib, code, script_file, ON_REQUEST).

ON_REQUEST.update({"scene", "scene_answer", "scene_report"})
SCENE_FILES = {}
if config.get("scene"):
    from restitution.core.errors import ParameterError
    from restitution.dem.scene.file import read_scene

    try:
        SCENE_FILES[read_scene(config["scene"]).name] = config["scene"]
    except ParameterError as err:
        # one line naming the field, before any job: nothing is written
        sys.stderr.write(f"scene error: {err}\n")
        sys.exit(2)

wildcard_constraints:
    scene="[A-Za-z][A-Za-z0-9_-]*",

SCENE_OUT = "results/scenes/{scene}/"


def scene_source(wildcards):
    return SCENE_FILES.get(wildcards.scene, f"scenes/{wildcards.scene}.yaml")


rule scene:
    """The scene given as --config scene=FILE (what `make scene SCENE=FILE` runs)."""
    input:
        [SCENE_OUT.format(scene=name) + "report.html" for name in SCENE_FILES],


rule scene_answer:
    """`restitution scene`'s answer: the JSON, the input lines and the text table."""
    input:
        scene=scene_source,
        code=code("scene_answer.py"),
    output:
        json=SCENE_OUT + "scene.json",
        lines=SCENE_OUT + "input.lammps",
        table=SCENE_OUT + "table.txt",
    log:
        "logs/scene_answer-{scene}.log",
    script:
        script_file("scene_answer.py")


rule scene_report:
    """The report: eps(v) of every rung tried against the target per material pair, the deviation
    against the tolerance band, contact time and time step against speed; one HTML page."""
    input:
        json=SCENE_OUT + "scene.json",
        table=SCENE_OUT + "table.txt",
        code=code("scene_report.py"),
    output:
        html=SCENE_OUT + "report.html",
        eps_pdf=SCENE_OUT + "eps.pdf",
        eps_png=SCENE_OUT + "eps.png",
        dev_pdf=SCENE_OUT + "deviation.pdf",
        dev_png=SCENE_OUT + "deviation.png",
        dt_pdf=SCENE_OUT + "timestep.pdf",
        dt_png=SCENE_OUT + "timestep.png",
    log:
        "logs/scene_report-{scene}.log",
    script:
        script_file("scene_report.py")
