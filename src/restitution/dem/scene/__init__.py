"""A scene's answer: for every contact it can have (atom type x atom type, atom type x wall), the
cheapest contact model that meets the tolerance over the speed range (the choice of
:mod:`restitution.dem.model_choice`, every model tried reported), its calibrated setting in the
code's own conventions, eps(v) of that setting, the contact time and a time step, and the input
lines for the whole scene.

The fit is shared by every contact with one material pair (it is a fit of log C, see
model_choice); each contact then gets its own damping from its effective mass and radius, and the
eps listed for it is evaluated again from the setting as printed in its input line (the round
trip, reported as ``round_trip``). The engine the scene names (restitution.dem.engines.ENGINES)
gives the candidate models, each contact's setting and the input lines.
"""

from __future__ import annotations


import numpy as np

from ...core.errors import ParameterError
from ...core.problem import Problem
from ...fast.integrator import COLUMNS, collide_fast
from ..contact import Contact
from ..engine import Engine
from ..engines import ENGINES
from ..model_choice import EVAL_TOL, SMALL_EPS, Fit, fit_model, scaled_eps
from .contacts import SceneContact, scene_contacts
from .file import Scene
from ..timestep import REFINE, VERIFY_STEPS, recommended_dt, verlet_eps

__all__ = ["answer_scene"]

#: A scene that checks more points than this (material pairs x check speeds) has the evaluator's
#: master curves built for the exponents it uses (1-2 s under the overlap rule, 15-30 s under the
#: force rule, then cached on disk); below it, the compiled integrator answers (~5e-5 s a point).
BUILD_POINTS = 50_000
#: Speeds per material pair at which the models' eps(v) are listed for plots.
PLOT_POINTS = 200


def _choose_model(scene: Scene, engine: Engine, models, end: str, target, grid, probe: SceneContact,
           build) -> tuple[list[Fit], Fit | None]:
    """Fit each model in turn; stop at the first that meets the tolerance and that the engine can
    express (tsuji's e, for one, reaches only part of the range of damping)."""
    fits = []
    for model in models:
        fit = fit_model(model, end, target, grid, scene.tolerance, build)
        if fit.accepted:
            try:
                engine.scene_setting(scene, probe, fit)
            except ParameterError as err:
                fit = Fit(model, fit.log_c, fit.max_deviation, fit.at_speed, False, fit.error_bound, fit.grid,
                          fit.eps, reason=f"{engine.label} cannot express it: {err}")
        fits.append(fit)
        if fit.accepted:
            return fits, fit
    return fits, None


def _overlap_check(c: SceneContact, overlap, speeds) -> dict:
    """The largest overlap at each listed speed (the contact law's maximum compression, in metres)
    against where the code's geometry breaks: the centre reaching the wall (a wall contact), the two
    centres meeting (a pair). Beyond it the code pushes the bodies through each other, and the eps
    listed is not what it gives (found running LAMMPS: a sphere at 67 m/s onto a soft hooke wall)."""
    limit = c.a.radius + (c.b.radius if c.b is not None else 0.0)
    worst = int(np.argmax(overlap))
    out = {"max_overlap": [float(d) for d in overlap], "overlap_limit": float(limit),
           "overlap_ok": bool(overlap[worst] < limit)}
    if not out["overlap_ok"]:
        where = "the particle's radius (its centre reaches the wall)" if c.b is None else \
            "the sum of the radii (the centres meet)"
        out["problem"] = (f"at {speeds[worst]:.3g} m/s the largest overlap, {overlap[worst]:.3g} m, reaches {where}: "
                          "the code's geometry breaks there and the eps listed is not what it gives; "
                          "a stiffer contact or lower speeds")
    return out


def _time_step(scene: Scene, fit: Fit, end: str, speeds, eps, tau_c) -> list:
    """Steps per contact N(v) at the first, middle and last listed speed for one time step shared by
    every listed speed: the velocity-Verlet study of restitution.dem.timestep run on the scaled
    contact (the scheme is scale-free: N depends on Omega only) at those three speeds, for an error
    in eps below the tolerance; then that step is run at every listed speed, and refined until each
    is within the tolerance too, while that costs little.

    Where a contact takes few steps, the error is far from first order in dt (a Hertz-tsuji contact
    of the small scene: 0.0040 at 12.5 steps per contact, 0.0123 at 14.0, with 0.01 asked): the
    shortest contact's steps say nothing of a slower speed's, whose contact is longer."""
    model = fit.model
    scaled = [Contact(model.alpha, model.gamma, float(w), 1.0, end) for w in fit.omega(speeds)]
    tol = [min(0.5, scene.tolerance / e) for e in eps]
    study = []
    for i in sorted({0, len(speeds) // 2, len(speeds) - 1}):
        ts = recommended_dt(scaled[i], 1.0, tol[i], eps=float(eps[i]), contact_time=float(tau_c[i]))
        study.append((i, ts.steps_per_contact))
    # a contact's t_c(v) is its own constant times T(v) = tau_c v^(-gamma/(gamma+1)), so one dt in
    # units of that constant serves every contact of the material pair
    T = np.asarray(tau_c) * np.asarray(speeds, float) ** (-float(model.gamma / (model.gamma + 1)))
    dt = min(T[i] / n for i, n in study)

    def within(dt):
        return all(abs(verlet_eps(c, 1.0, tc * dt / Tj) / e - 1.0) <= t
                   for c, tc, Tj, e, t in zip(scaled, tau_c, T, eps, tol))

    while float(np.sum(T)) / dt <= VERIFY_STEPS * 10 and not within(dt):
        dt /= REFINE
    return [(i, float(T[i] / dt)) for i, _ in study]


def contact_count(scene: Scene) -> int:
    """How many contacts :func:`answer_scene` answers: every pair of atom types, and every type on
    every wall (what a scene's price grows with: its time and the size of its answer)."""
    n = len(scene.types)
    return n * (n + 1) // 2 + n * len(scene.walls)


def answer_scene(scene: Scene, progress=None) -> dict:
    """The scene's answer as a JSON-ready dict (see docs/howto/scenes.md); ``progress(done, total)``,
    if given, is called after each contact."""
    engine = ENGINES[scene.code]
    end = engine.end_rule(scene.options)
    models = engine.models(scene.options)
    grid, speeds = scene.check_grid(), scene.report_grid()
    contacts = scene_contacts(scene)
    by_materials: dict = {}
    for c in contacts:
        by_materials.setdefault(frozenset(c.materials), []).append(c)
    build = True if len(by_materials) * len(grid) > BUILD_POINTS else None
    answers = {}
    for key, group in by_materials.items():
        fits, chosen = _choose_model(scene, engine, models, end, scene.target(*group[0].materials), grid, group[0], build)
        shared = {"fits": fits, "chosen": chosen, "materials": group[0].materials,
                  "models": [f.as_dict() for f in fits]}
        if chosen is not None:
            problem = Problem.of(chosen.model.alpha, chosen.model.gamma, end)
            ex = problem.ex
            eps_fit, bound = scaled_eps(chosen.model, end, chosen.omega(speeds), build)
            rows = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, chosen.omega(speeds), EVAL_TOL,
                                problem.effective_end)
            tau_c = rows[:, COLUMNS.index("tau_c")]
            shared.update(eps_fit=eps_fit, bound=bound, tau_c=tau_c, x_b=rows[:, COLUMNS.index("x_b")],
                          steps=_time_step(scene, chosen, end, speeds, eps_fit, tau_c))
        answers[key] = shared
    # the round trip: eps of every contact from its setting as printed, one evaluation per model
    walls = engine.wall_types(scene)
    out = []
    pending: dict = {}
    for done, c in enumerate(contacts, 1):
        if progress is not None:
            progress(done, len(contacts))
        a = answers[frozenset(c.materials)]
        row = {"a": c.a.name, "b": c.b.name if c.b is not None else f"wall:{c.wall}",
               "types": [c.a.number, c.b.number if c.b is not None else walls.get(c.wall, "wall")],
               "materials": list(c.materials),
               "effective_mass": c.pair.m, "effective_radius": c.pair.R,
               "models": a["models"], "chosen": None, "input_lines": [], "end": end}
        fit = a["chosen"]
        if fit is not None:
            setting = engine.scene_setting(scene, c, fit)
            contact = engine.contact(c.pair, **setting)
            row.update(chosen=fit.model.name, setting=setting, input_lines=engine.contact_lines(scene, c, setting),
                       max_deviation=fit.max_deviation, at_speed=fit.at_speed, alpha=str(contact.alpha),
                       gamma=str(contact.gamma), D1=contact.D1, D2=contact.D2, speeds=[float(v) for v in speeds])
            scale = contact.material.time_scale(speeds)
            t_c = a["tau_c"] * scale
            row["contact_time"] = [float(t) for t in t_c]
            row["dt"] = float(min(t_c[i] / n for i, n in a["steps"]))
            row["dt_study"] = [{"speed": float(speeds[i]), "steps_per_contact": float(n)} for i, n in a["steps"]]
            row.update(_overlap_check(c, a["x_b"] * contact.material.length_scale(speeds), speeds))
            pending.setdefault(fit.model, []).append((row, contact.material.omega(speeds), a))
        out.append(row)
    for model, items in pending.items():
        eps, bound = scaled_eps(model, end, np.concatenate([om for _, om, _ in items]), build)
        for k, (row, _, a) in enumerate(items):
            mine = eps[k * len(speeds):(k + 1) * len(speeds)]
            row["eps"] = [float(e) for e in mine]
            row["error_bound"] = float(bound * np.max(mine))
            row["round_trip"] = float(np.max(np.abs(mine - a["eps_fit"])))
    # every model tried, per material pair, on at most PLOT_POINTS of the check grid (the report's plots)
    step = max(1, len(grid) // PLOT_POINTS)
    curves = [{"pair": list(a["materials"]), "speeds": [float(v) for v in grid[::step]],
               "target": [float(e) for e in scene.target(*a["materials"]).at(grid[::step])],
               "models": [{"name": f.model.name, "accepted": f.accepted,
                          "eps": [float(e) for e in f.eps[::step]]} for f in a["fits"] if f.eps]}
              for a in answers.values()]
    lines = engine.input_lines(scene, out)
    return {"scene": scene.name, "code": scene.code, "options": scene.options, "tolerance": scene.tolerance,
            "speeds": list(scene.speeds), "check_points": scene.check_points,
            "check": f"every model's |eps - target| at {scene.check_points} log-spaced speeds over the range, "
                     f"plus the evaluation's bound (relative {EVAL_TOL:g}; where the bodies can stick, absolute "
                     f"{EVAL_TOL * SMALL_EPS:g} for eps below {SMALL_EPS:g})",
            "types": [{"number": t.number, "name": t.name, "species": t.species, "material": t.material,
                       "radius": t.radius, "density": float(scene.materials[t.material]["density"])}
                      for t in scene.types],
            "targets": [t.as_dict() for t in scene.targets.values()],
            "met": all(r["chosen"] is not None and r["overlap_ok"] for r in out),
            "input_lines": lines, "contacts": out, "curves": curves}
