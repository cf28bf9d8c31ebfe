"""A scene's answer: for every contact it can have (atom type x atom type, atom type x wall), the
cheapest contact model that meets the tolerance over the speed range (the ladder of
:mod:`restitution.dem.model_ladder`, every rung tried reported), its calibrated setting in the
code's own conventions, eps(v) of that setting, the contact time and a time step, and the input
lines for the whole scene.

The fit is shared by every contact with one material pair (it is a fit of log C, see
model_ladder); each contact then gets its own damping from its effective mass and radius, and the
eps listed for it is evaluated again from the setting as printed in its input line (the round
trip, reported as ``round_trip``). LAMMPS ``pair_style granular`` (pair_coeff per type pair, fix
wall/gran per type and wall) and LIGGGHTS ``model hertz`` (fix property/global per atom type, walls
with atom types of their own, coefficientRestitution per type pair).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import ParameterError
from ..core.exponents import as_exponents
from ..fast.integrator import COLUMNS, collide_fast
from .codes import (LIGGGHTS_E, LIGGGHTS_MODULUS, Pair, base_eta_n0, lammps_contact, lammps_eta_n0,
                    lammps_pair_coeff, liggghts_accepts_e, liggghts_contact, liggghts_e)
from .contact import Contact
from .model_ladder import EVAL_TOL, SMALL_EPS, Fit, fit_rung, lammps_rungs, liggghts_rungs, scaled_eps
from .scene_file import AtomType, Scene
from .timestep import REFINE, VERIFY_STEPS, recommended_dt, verlet_eps

__all__ = ["answer_scene"]

#: A scene that checks more points than this (material pairs x check speeds) has the evaluator's
#: master curves built for the exponents it uses (1-2 s under the overlap rule, 15-30 s under the
#: force rule, then cached on disk); below it, the compiled integrator answers (~5e-5 s a point).
BUILD_POINTS = 50_000
#: Speeds per material pair at which the rungs' eps(v) are listed for plots.
PLOT_POINTS = 200


@dataclass
class _Contact:
    a: AtomType
    b: AtomType | None       # None: a wall
    wall: str | None
    pair: Pair

    @property
    def materials(self) -> tuple:
        return (self.a.material, self.b.material if self.b is not None else self.wall)


def _contacts(scene: Scene) -> list[_Contact]:
    dens = {m: float(v["density"]) for m, v in scene.materials.items()}
    out = []
    for i, a in enumerate(scene.types):
        for b in scene.types[i:]:
            out.append(_Contact(a, b, None, Pair.spheres(a.radius, b.radius, dens[a.material], dens[b.material])))
    for a in scene.types:
        for w in scene.walls:
            out.append(_Contact(a, None, w, Pair.wall(a.radius, dens[a.material])))
    return out


def _stiffness(scene: Scene, m1: str, m2: str) -> dict:
    """The normal model's arguments for a contact of materials m1 and m2, as one pair_coeff I J
    line states them: k_n the geometric mean (LAMMPS' own mixing of k_n); for hertz/material the
    E that gives the pair's E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) with the mean nu, since the
    engine reads E and nu of one line as E* = E / (2 (1 - nu^2))."""
    normal = scene.options["normal"]
    p, q = scene.materials[m1], scene.materials[m2]
    if normal != "hertz/material":
        return {"normal": normal, "k_n": p["k_n"] if m1 == m2 else math.sqrt(p["k_n"] * q["k_n"])}
    if m1 == m2:
        return {"normal": normal, "E": float(p["E"]), "nu": float(p["nu"])}
    e_star = 1.0 / ((1.0 - p["nu"] ** 2) / p["E"] + (1.0 - q["nu"] ** 2) / q["E"])
    nu = 0.5 * (p["nu"] + q["nu"])
    return {"normal": normal, "E": 2.0 * (1.0 - nu ** 2) * e_star, "nu": nu}


def _d2(base: Contact, fit: Fit) -> Contact:
    """The contact with the damping D2 that puts Omega(v) on the fitted C v^k."""
    p = float((fit.rung.alpha + 1) / (fit.rung.gamma + 1))
    return Contact(base.alpha, base.gamma, base.D1, math.exp((math.log(base.D1) - fit.log_c) / p), base.end)


def _liggghts_materials(scene: Scene, c: _Contact) -> dict:
    m1, m2 = c.materials
    p, q = scene.materials[m1], scene.materials[m2]
    same = m1 == m2
    return {"E": float(p["E"]), "nu": float(p["nu"]), "E2": None if same else float(q["E"]),
            "nu2": None if same else float(q["nu"])}


def _setting(scene: Scene, c: _Contact, fit: Fit) -> dict:
    """The rung's setting for this contact: D2 from the fitted C, as the code's eta_n0 (or the e
    of tsuji or coeff_restitution; LIGGGHTS: coefficientRestitution) rounded as the input line prints it."""
    rung = fit.rung
    if scene.code == "liggghts":
        mats = _liggghts_materials(scene, c)
        limit = scene.options["limitForce"]
        base = liggghts_contact(c.pair, e=0.5, limit_force=limit, model=rung.normal, **mats)
        e = float(f"{liggghts_e(_d2(base, fit)):.12g}")
        if not liggghts_accepts_e(e):
            # LIGGGHTS stops on such a matrix before the first step (found running these lines)
            raise ParameterError("coefficientRestitution", e, f"LIGGGHTS requires {LIGGGHTS_E[0]} < e <= "
                                                              f"{LIGGGHTS_E[1]}")
        return {"model": rung.normal, **mats, "e": e, "limit_force": limit}
    stiff = _stiffness(scene, *c.materials)
    base = lammps_contact(c.pair, damping=rung.damping, eta_n0=base_eta_n0(rung.damping),
                          limit_damping=scene.options["limit_damping"], **stiff)
    eta = lammps_eta_n0(c.pair, rung.damping, _d2(base, fit))
    return {**stiff, "damping": rung.damping, "eta_n0": float(f"{eta:.12g}"),
            "limit_damping": scene.options["limit_damping"]}


def _code_contact(scene: Scene, c: _Contact, setting: dict) -> Contact:
    """The model the code builds from the setting as printed: the round trip's other end."""
    if scene.code == "liggghts":
        return liggghts_contact(c.pair, **setting)
    return lammps_contact(c.pair, **setting)


def _wall_types(scene: Scene) -> dict:
    """LIGGGHTS gives a wall a material through an atom type of its own: numbered after the particles'."""
    return {w: len(scene.types) + 1 + k for k, w in enumerate(scene.walls)}


def _lines(scene: Scene, c: _Contact, setting: dict) -> list[str]:
    if scene.code == "liggghts":
        j = c.b.number if c.b is not None else _wall_types(scene)[c.wall]
        return [f"coefficientRestitution {c.a.number} {j} {setting['e']:.12g}"]
    line = lammps_pair_coeff(**setting)
    if c.b is not None:
        return [line.replace("pair_coeff * *", f"pair_coeff {c.a.number} {c.b.number}", 1)]
    model = line.removeprefix("pair_coeff * * ")
    tag = f"{c.wall}_{c.a.number}"
    return [f"group type{c.a.number} type {c.a.number}",
            f"fix wall_{tag} type{c.a.number} wall/gran granular {model} zplane 0.0 NULL"]


def _liggghts_lines(scene: Scene, rows: list) -> list[str]:
    """fix property/global lines for every atom type (walls' after the particles'), the
    coefficientRestitution matrix from the contacts (entries between two walls never act: 0.5)."""
    walls = _wall_types(scene)
    mats = [t.material for t in scene.types] + list(walls)
    n = len(mats)
    e = [[0.5] * n for _ in range(n)]
    for row in rows:
        if row["chosen"] is None:
            continue
        i, j = row["types"]
        e[i - 1][j - 1] = e[j - 1][i - 1] = row["setting"]["e"]
    answered = {(min(r["types"]), max(r["types"])) for r in rows if r["chosen"] is not None}
    left = [f"{i}-{j}" for i in range(1, n + 1) for j in range(i, n + 1) if (i, j) not in answered]
    prop = lambda key: " ".join(f"{float(scene.materials[m][key]):.12g}" for m in mats)   # noqa: E731
    note = [f"# coefficientRestitution left at 0.5 (walls only, or no model within the tolerance): {', '.join(left)}"]
    # LIGGGHTS refuses youngsModulus outside [5e6, 1e9] in SI units unless told (found running these lines)
    moduli = [float(scene.materials[m]["E"]) for m in mats]
    told = (["soft_particles yes"] if min(moduli) < LIGGGHTS_MODULUS["si"][0] else []) + \
        (["hard_particles yes"] if max(moduli) > LIGGGHTS_MODULUS["si"][1] else [])
    return (note if left else []) + told + [f"fix m1 all property/global youngsModulus peratomtype {prop('E')}",
            f"fix m2 all property/global poissonsRatio peratomtype {prop('nu')}",
            f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
            + " ".join(f"{x:.12g}" for r in e for x in r),
            "# the tangential model reads a friction matrix: zero here (the scene is about head-on contacts); "
            "set your own",
            f"fix m4 all property/global coefficientFriction peratomtypepair {n} " + " ".join(["0"] * n * n),
            f"pair_style gran model {scene.options['model']} tangential no_history limitForce "
            + ("on" if scene.options["limitForce"] else "off"),
            "pair_coeff * *"]


def _climb(scene: Scene, rungs, end: str, target, grid, probe: _Contact, build) -> tuple[list[Fit], Fit | None]:
    """Fit each rung in turn; stop at the first that meets the tolerance and that the code can
    express (tsuji's e, for one, reaches only part of the range of damping)."""
    fits = []
    for rung in rungs:
        fit = fit_rung(rung, end, target, grid, scene.tolerance, build)
        if fit.accepted:
            try:
                _setting(scene, probe, fit)
            except ParameterError as err:
                fit = Fit(rung, fit.log_c, fit.max_deviation, fit.at_speed, False, fit.error_bound, fit.grid,
                          fit.eps, reason=f"{'LIGGGHTS' if scene.code == 'liggghts' else 'LAMMPS'} cannot express "
                                          f"it: {err}")
        fits.append(fit)
        if fit.accepted:
            return fits, fit
    return fits, None


def _overlap_check(c: _Contact, overlap, speeds) -> dict:
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
    rung = fit.rung
    scaled = [Contact(rung.alpha, rung.gamma, float(w), 1.0, end) for w in fit.omega(speeds)]
    tol = [min(0.5, scene.tolerance / e) for e in eps]
    study = []
    for i in sorted({0, len(speeds) // 2, len(speeds) - 1}):
        ts = recommended_dt(scaled[i], 1.0, tol[i], eps=float(eps[i]), contact_time=float(tau_c[i]))
        study.append((i, ts.steps_per_contact))
    # a contact's t_c(v) is its own constant times T(v) = tau_c v^(-gamma/(gamma+1)), so one dt in
    # units of that constant serves every contact of the material pair
    T = np.asarray(tau_c) * np.asarray(speeds, float) ** (-float(rung.gamma / (rung.gamma + 1)))
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
    if scene.code == "liggghts":
        end = "force" if scene.options["limitForce"] else "overlap"
        rungs = liggghts_rungs(scene.options["model"])
    else:
        end = "force" if scene.options["limit_damping"] else "overlap"
        rungs = lammps_rungs(scene.options["normal"], scene.options["damping"])
    grid, speeds = scene.check_grid(), scene.report_grid()
    contacts = _contacts(scene)
    by_materials: dict = {}
    for c in contacts:
        by_materials.setdefault(frozenset(c.materials), []).append(c)
    build = True if len(by_materials) * len(grid) > BUILD_POINTS else None
    answers = {}
    for key, group in by_materials.items():
        fits, chosen = _climb(scene, rungs, end, scene.target(*group[0].materials), grid, group[0], build)
        shared = {"fits": fits, "chosen": chosen, "materials": group[0].materials,
                  "rungs": [f.as_dict() for f in fits]}
        if chosen is not None:
            ex = as_exponents(chosen.rung.alpha, chosen.rung.gamma)
            eps_fit, bound = scaled_eps(chosen.rung, end, chosen.omega(speeds), build)
            rows = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, chosen.omega(speeds), EVAL_TOL,
                                end == "overlap" and ex.alpha > ex.gamma)
            tau_c = rows[:, COLUMNS.index("tau_c")]
            shared.update(eps_fit=eps_fit, bound=bound, tau_c=tau_c, x_b=rows[:, COLUMNS.index("x_b")],
                          steps=_time_step(scene, chosen, end, speeds, eps_fit, tau_c))
        answers[key] = shared
    # the round trip: eps of every contact from its setting as printed, one evaluation per rung
    walls = _wall_types(scene) if scene.code == "liggghts" else {}
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
               "rungs": a["rungs"], "chosen": None, "input_lines": [], "end": end}
        fit = a["chosen"]
        if fit is not None:
            setting = _setting(scene, c, fit)
            contact = _code_contact(scene, c, setting)
            row.update(chosen=fit.rung.name, setting=setting, input_lines=_lines(scene, c, setting),
                       max_deviation=fit.max_deviation, at_speed=fit.at_speed, alpha=str(contact.alpha),
                       gamma=str(contact.gamma), D1=contact.D1, D2=contact.D2, speeds=[float(v) for v in speeds])
            scale = contact.material.time_scale(speeds)
            t_c = a["tau_c"] * scale
            row["contact_time"] = [float(t) for t in t_c]
            row["dt"] = float(min(t_c[i] / n for i, n in a["steps"]))
            row["dt_study"] = [{"speed": float(speeds[i]), "steps_per_contact": float(n)} for i, n in a["steps"]]
            row.update(_overlap_check(c, a["x_b"] * contact.material.length_scale(speeds), speeds))
            pending.setdefault(fit.rung, []).append((row, contact.material.omega(speeds), a))
        out.append(row)
    for rung, items in pending.items():
        eps, bound = scaled_eps(rung, end, np.concatenate([om for _, om, _ in items]), build)
        for k, (row, _, a) in enumerate(items):
            mine = eps[k * len(speeds):(k + 1) * len(speeds)]
            row["eps"] = [float(e) for e in mine]
            row["error_bound"] = float(bound * np.max(mine))
            row["round_trip"] = float(np.max(np.abs(mine - a["eps_fit"])))
    # every rung tried, per material pair, on at most PLOT_POINTS of the check grid (the report's plots)
    step = max(1, len(grid) // PLOT_POINTS)
    curves = [{"pair": list(a["materials"]), "speeds": [float(v) for v in grid[::step]],
               "target": [float(e) for e in scene.target(*a["materials"]).at(grid[::step])],
               "rungs": [{"name": f.rung.name, "accepted": f.accepted,
                          "eps": [float(e) for e in f.eps[::step]]} for f in a["fits"] if f.eps]}
              for a in answers.values()]
    if scene.code == "liggghts":
        lines = _liggghts_lines(scene, out)
    else:
        lines = ["pair_style granular"] + [ln for row in out if not row["b"].startswith("wall:")
                                           for ln in row["input_lines"]]
        walls = [ln for row in out if row["b"].startswith("wall:") for ln in row["input_lines"]]
        if walls:
            # LAMMPS groups are static and fix wall/gran refuses dynamic ones: a group defined
            # before the atoms exist holds none, and its wall lets them through (measured)
            lines += ["# the groups hold the atoms present when they are defined: put these lines after "
                      "create_atoms/read_data,", "# or give a fix pour of type N the group typeN"]
        lines += walls
    return {"scene": scene.name, "code": scene.code, "options": scene.options, "tolerance": scene.tolerance,
            "speeds": list(scene.speeds), "check_points": scene.check_points,
            "check": f"every rung's |eps - target| at {scene.check_points} log-spaced speeds over the range, "
                     f"plus the evaluation's bound (relative {EVAL_TOL:g}; where the bodies can stick, absolute "
                     f"{EVAL_TOL * SMALL_EPS:g} for eps below {SMALL_EPS:g})",
            "types": [{"number": t.number, "name": t.name, "species": t.species, "material": t.material,
                       "radius": t.radius, "density": float(scene.materials[t.material]["density"])}
                      for t in scene.types],
            "targets": [t.as_dict() for t in scene.targets.values()],
            "met": all(r["chosen"] is not None and r["overlap_ok"] for r in out),
            "input_lines": lines, "contacts": out, "curves": curves}
