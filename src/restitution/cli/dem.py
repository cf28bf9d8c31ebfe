"""The ``restitution`` subcommands for DEM modellers: ``lammps`` (a LAMMPS setting <-> eps),
``deck`` (what an input deck really gives) and ``scene`` (the cheapest model per contact of a scene,
and its input lines); what each engine asks to be said beside an answer comes from its entry in
restitution.dem.engines.ENGINES."""

from __future__ import annotations

import argparse
import json
import math
import os
import sys

from ..core.errors import ParameterError
from ..core.exponents import number_argument
from .common import Progress, UsageError, write_json

__all__ = ["add_dem_subcommands", "add_scene_subcommand", "add_deck_subcommand", "add_lammps_subcommand",
           "scene_table", "run_scene", "run_deck", "run_lammps", "LARGE_SCENE"]


def add_scene_subcommand(subparsers) -> None:
    s = subparsers.add_parser(
        "scene", help="the cheapest contact model per contact of a DEM scene, and its input lines",
        description="Reads a scene file (YAML: materials, species, walls, code options, speeds, targets, "
                    "tolerance; see docs/howto/scenes.md) and answers for every contact. Exit status 1 when "
                    "some contact has no model within the tolerance, or an overlap at which the code's "
                    "geometry breaks.")
    s.add_argument("file", help="the scene file")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.add_argument("--out", metavar="DIR", help="also write DIR/scene.json, the input lines (DIR/input.lammps; "
                                                "DIR/MaterialsDEM.json for Kratos) and DIR/table.txt")


def scene_table(res: dict) -> str:
    """The text answer of `restitution scene`: one block per contact, then the input lines."""
    o = res["options"]
    w = max([22] + [len(c["chosen"] or "none meets the tolerance") for c in res["contacts"]])   # "chosen" column
    head = [f"scene {res['scene']}: {res['code']} (" + ", ".join(f"{k} {str(v).lower() if isinstance(v, bool) else v}" for k, v in o.items()) + f"), "
            f"tolerance {res['tolerance']:g} on eps, speeds {res['speeds'][0]:g} to {res['speeds'][1]:g}",
            f"# checked: {res['check']}",
            f"{'contact':<24} {'types':<9} {'chosen':<{w}} {'max dev':>9} {'at v':>9} {'eps at lo .. hi':>17} "
            f"{'dt (s)':>10}"]
    rows = []
    for c in res["contacts"]:
        name = f"{c['a']}-{c['b']}"
        types = " ".join(map(str, c["types"]))
        if c["chosen"] is None:
            rows.append(f"{name:<24} {types:<9} {'none meets the tolerance':<{w}}")
        else:
            rows.append(f"{name:<24} {types:<9} {c['chosen']:<{w}} {c['max_deviation']:9.2g} {c['at_speed']:9.3g} "
                        f"{c['eps'][0]:7.4f} .. {c['eps'][-1]:6.4f} {c['dt']:10.3g}")
        tried = "; ".join(f"{r['name']} {r['max_deviation']:.3g}" + (f" at {r['at_speed']:.3g}" if r["at_speed"] else "")
                          + (" accepted" if r["accepted"] else " rejected") + (f" ({r['reason']})" if r.get("reason") else "")
                          for r in c["models"])
        rows.append(f"  tried: {tried}")
        if c["chosen"] is not None:
            ratio = max(c["max_overlap"]) / c["overlap_limit"]
            rows.append(f"  largest overlap {max(c['max_overlap']):.3g} m: {ratio:.2g} of "
                        + ("the radius" if c["b"].startswith("wall:") else "the sum of the radii"))
        if c.get("problem"):
            rows.append(f"  NOT MET: {c['problem']}")
    return "\n".join(head + rows + ["", "# input lines"] + res["input_lines"]) + "\n"


#: A scene with more contacts than this says its size before it starts (a 200-type scene has
#: 20,100 type pairs and writes tens of MB).
LARGE_SCENE = 1000


def _check_writable_dir(name: str, path: str) -> None:
    """Refuse before a long computation, not after it, a directory that cannot be written.

    A probe file is made in ``path`` or in its nearest existing ancestor (and removed at once):
    permission bits alone do not tell, e.g. for root or on a read-only file system.
    """
    import tempfile
    from pathlib import Path

    from ..fast.cache import nearest_existing
    here = nearest_existing(Path(path).absolute())
    if not here.is_dir():
        raise ParameterError(name, path, f"cannot be a directory: {here} is a file")
    try:
        with tempfile.TemporaryFile(dir=here):
            pass
    except OSError as exc:
        raise ParameterError(name, path, f"cannot be written ({exc.strerror})") from None


def run_scene(args, out) -> int:
    from pathlib import Path

    from ..dem.scene import answer_scene, contact_count
    from ..dem.scene.file import read_scene
    scene = read_scene(args.file)
    if args.out:
        _check_writable_dir("out", args.out)
    n = contact_count(scene)
    if n > LARGE_SCENE:
        # measured: about 2.2 kB of JSON per contact, and the answer is held in memory until written
        print(f"restitution scene: {n} contacts ({len(scene.types)} atom types, {len(scene.walls)} wall"
              f"{'' if len(scene.walls) == 1 else 's'}), each "
              f"answered and listed: about {n * 2.2e-3:.0f} MB of JSON; progress follows", file=sys.stderr, flush=True)
    res = answer_scene(scene, progress=Progress("scene", "contacts", 1.0))
    from ..dem.engines import ENGINES
    for note in ENGINES[res["code"]].notes([c.get("setting") or {} for c in res["contacts"]]):
        print(f"restitution scene: note: {note}", file=sys.stderr)
    text = json.dumps(res, separators=(", ", ": ")) + "\n"
    table = scene_table(res)
    if args.out:   # everything computed first: a refused scene writes nothing
        d = Path(args.out)
        try:
            d.mkdir(parents=True, exist_ok=True)
            (d / "scene.json").write_text(text)
            (d / ENGINES[res["code"]].scene_input_file).write_text("\n".join(res["input_lines"]) + "\n")
            (d / "table.txt").write_text(table)
        except OSError as exc:
            raise ParameterError("out", args.out, f"cannot be written ({exc.strerror})") from None
    out.write(text if args.json else table)
    return 0 if res["met"] else 1


def add_deck_subcommand(subparsers) -> None:
    d = subparsers.add_parser(
        "deck", help="the eps a LAMMPS or LIGGGHTS input deck (or a Kratos MaterialsDEM.json) really gives, for "
                     "every type pair and flat wall",
        description="Reads pair_style granular (LAMMPS) or pair_style gran model hertz|hooke|hertz/stiffness|"
                    "hooke/stiffness (LIGGGHTS) decks, and "
                    "Kratos MaterialsDEM.json files (--radius per material id where the model part gives none). "
                    "One --g: five speeds over two decades around it; several: those speeds.")
    d.add_argument("file", help="the input script")
    d.add_argument("--g", type=number_argument, nargs="+", required=True, metavar="V",
                   help="impact speed(s), in the deck's units (m/s for units si, cm/s for cgs)")
    d.add_argument("--radius", nargs="+", default=[], metavar="T=R", help="radius of atom type T (the deck's units)")
    d.add_argument("--density", nargs="+", default=[], metavar="T=RHO",
                   help="density of atom type T (the deck's units)")
    d.add_argument("--json", action="store_true", help="machine-readable output")
    budget = d.add_argument("--budget", type=number_argument,
                            default=_LibraryDefault("restitution.dem.deck", "BUDGET"), metavar="SECONDS",
                            help="wall time the engine's pass through the deck may spend in a loop (from the first "
                                 "line it runs a second time) before it is ended; a pass that runs no line twice may "
                                 "take %(ceiling)s times it in all (default: %(default)s)")
    # the ceiling as the library has it, read when the help is printed (argparse fills %(name)s
    # from the action's attributes)
    budget.ceiling = _LibraryDefault("restitution.dem.dialect.child", "CEILING")
    run_budget = d.add_argument(
        "--run-budget", type=float, default=_LibraryDefault("restitution.dem.deck", "RUN_BUDGET"), metavar="SECONDS",
        help="where the deck reads, after a run, what its runs change (a set or group by region or by an atom-style "
             "variable of positions, a count after a pour, the step, an energy), its engine makes its runs for real (at "
             "most %(steps)s steps, outputs not written) within this wall time, and the audit reads the state they "
             "reach; where a run is followed by another, they are made to see that the engine ends each (a deck it "
             "stops in is refused); 0, or a budget that runs out, keeps the runs skipped: such a set is refused, such "
             "a stage's rows are marked, and an end not seen is said (default: %(default)s)")
    run_budget.steps = _LibraryDefault("restitution.dem.deck", "MAX_RUN_STEPS")


class _LibraryDefault:
    """An option's default that is a library constant, shown by --help and left to the library
    otherwise: read when the help is printed, because importing the deck audit to build the parser
    would cost every subcommand's start most of a second."""

    def __init__(self, module: str, name: str):
        self.module, self.name = module, name

    def __str__(self) -> str:
        import importlib
        return f"{getattr(importlib.import_module(self.module), self.name):g}"


def _per_type(name: str, items) -> dict:
    out = {}
    for item in items:
        t, _, value = item.partition("=")
        if not t.isdigit() or int(t) < 1:
            raise ParameterError(name, item, "give TYPE=VALUE with an atom type >= 1, e.g. 1=0.001")
        try:
            out[int(t)] = number_argument(value)
        except argparse.ArgumentTypeError:
            raise ParameterError(name, item, "the value must be a finite number > 0, e.g. 1=0.001") from None
        if not math.isfinite(out[int(t)]) or out[int(t)] <= 0:
            raise ParameterError(name, item, "the value must be a finite number > 0")
    return out


def run_deck(args, out) -> None:
    from ..dem.deck import audit_deck
    from ..dem.engines.lammps.contact import TSUJI_VERSION_NOTE
    try:
        with open(args.file, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
    except OSError as exc:
        raise ParameterError("file", args.file, f"cannot be read ({exc.strerror})") from None
    for g in args.g:
        if not math.isfinite(g) or g <= 0:
            raise ParameterError("g", g, "must be a finite number > 0")
    speeds = [args.g[0] * 10.0 ** k for k in (-1, -0.5, 0, 0.5, 1)] if len(args.g) == 1 else list(args.g)
    base = os.path.dirname(os.path.abspath(args.file))

    def read_file(name: str) -> str:
        # LAMMPS opens these relative to where it runs: the deck's directory, as it is normally started
        with open(os.path.join(base, name), encoding="utf-8", errors="replace") as fh:
            return fh.read()
    from ..dem.engines import ENGINES
    for engine in ENGINES.values():      # an engine whose contacts a material file sets claims its file
        if engine.materials is not None and engine.materials.is_materials_file(text):
            return _run_materials(engine, args, text, speeds, read_file, out)
    res = audit_deck(text, speeds, _per_type("radius", args.radius), _per_type("density", args.density), read_file,
                     path=args.file, **({} if isinstance(args.budget, _LibraryDefault) else {"budget": args.budget}),
                     **({} if isinstance(args.run_budget, _LibraryDefault) else {"run_budget": args.run_budget}))
    for note in res["notes"]:
        print(f"restitution deck: {note}", file=sys.stderr)
    if any("damping tsuji" in row["model"] for row in res["pairs"] + res["walls"]):
        print(f"restitution deck: note: {TSUJI_VERSION_NOTE}", file=sys.stderr)
    for row in res["unknown_lines"]:     # never guessed: each named, one per line
        where = f"{row['file']} line {row['line']}" if row["file"] else f"line {row['line']}"
        print(f"restitution deck: {where} {row['why']}: {row['text']}", file=sys.stderr)
    stages = res["stages"]
    if len(stages) > 1:                # a --json reader that takes "pairs" alone learns it here
        print(f"restitution deck: the contact settings change between runs: {len(stages)} stages, each reported "
              "(\"stages\" in --json; \"pairs\" and \"walls\" are the last one's)", file=sys.stderr)
    rows = []
    for k, stage in enumerate(stages, 1):
        head = _stage_head(stage, k, len(stages))
        rows += [(p, f"types {p['types'][0]} {p['types'][1]}{_sized(p)}", "R1 + R2", "the spheres through each other",
                  "the spheres together", head) for p in stage["pairs"]]
        rows += [(w, f"type {w['types'][0]} on wall {w['wall']}{_sized(w)}", "the radius",
                  "the sphere through the wall", "the sphere on the wall", head) for w in stage["walls"]]
    for p, name, reach, pushed, _, head in rows:   # no eps there: said on stderr too, where a --json reader looks
        through = [g for g, t in zip(p["speeds"], p["passes_through"]) if t]
        if through:
            where = f" ({head.removeprefix('# ')})" if head else ""
            print(f"restitution deck: {name}{where}: the engine pushes {pushed} from g = {min(through):.4g} on (the "
                  f"largest overlap reaches {reach}): no eps there", file=sys.stderr)
    for p, name, _, _, _, head in rows:
        where = f" ({head.removeprefix('# ')})" if head else ""
        for sized in _by_fix(p.get("beside") or []):
            fix = sized[0]
            line = f"{fix['file']} line {fix['line']}" if fix["file"] else f"line {fix['line']}"
            size = "".join(_effect_size(p, each, len(sized) > 1) for each in sized)
            if len(sized) > 1:
                size = (", by the sizes present (the law's own eps does not depend on size), at the sizes that end "
                        "its range" + size)
            # a fix whose computed size is the contact's own eps at every speed changes nothing
            kept = fix["eps_engine"] is not None and list(fix["eps_engine"]) == list(p["eps"]) and len(sized) == 1
            effect = "which leaves the eps the engine measures the contact's" if kept else \
                f"which changes the eps the engine measures{size}"
            print(f"restitution deck: {name}{where}: {line} fix {fix['style']} ({fix['fix']}): {fix['what']}, {effect}"
                  + (f"; {fix['why']}" if fix["why"] else ""), file=sys.stderr)
    for p, name, _, _, _, head in rows:
        few = [(g, n, e, d, w) for g, n, e, d, w in zip(p["speeds"], p.get("steps_per_contact") or [], p["eps"],
                                                         p.get("eps_at_dt_spread") or [], p.get("dt_within_tol") or [])
               if w is not None]
        if few:
            where = f" ({head.removeprefix('# ')})" if head else ""
            said = [(f"{n:.3g} steps", " (" + (f"eps there {d[0]:.6f} to {d[1]:.6f} by where in a step it starts, "
                                               if d is not None else "too few to resolve it, ")
                     + f"dt -> 0: {e:.6f}; dt <= {w:.3g} keeps eps within {p['dt_tol']:g})") for _, n, e, d, w in few]
            # a law whose eps and contact time do not depend on g says the same at every speed: once
            clauses = ([f"{said[0][0]} at every speed given{said[0][1]}"] if len(few) > 1 and len(set(said)) == 1
                       else [f"{steps} at g = {g:.4g}{rest}" for (g, *_), (steps, rest) in zip(few, said)])
            reset = f" ({p['dt_reset']} changes the time step during the runs)" if p.get("dt_reset") else ""
            print(f"restitution deck: {name}{where}: at the deck's time step {p['dt']:.4g}{reset} a contact lasts "
                  + ", ".join(clauses), file=sys.stderr)
    if args.json:
        write_json(res, out)
        return
    if res.get("units", "si") != "si":
        out.write(f"# speeds g in {res['speed_unit']}: the deck's units {res['units']}, as its sizes and masses\n")
    if res["ignored"]:
        out.write(f"# {res['code']} deck; no part in a head-on contact: {', '.join(res['ignored'])}\n")
    shown = None
    # a stage without rows has its heading all the same, and why it has none
    empty = {_stage_head(s, k, len(stages)): s["why"] for k, s in enumerate(stages, 1) if "why" in s}
    rows += [(None, "", "", "", "", head) for head in empty]
    rows.sort(key=lambda row: int(row[-1].split()[2]) if row[-1] else 0)     # by stage, in order within one
    for p, name, reach, pushed, kept, head in rows:
        if head and head != shown:
            out.write(head + "\n")
            shown = head
        if p is None:
            out.write(f"(no rows: {empty[head]})\n")
            continue
        typed = "none typed" if p["typed_e"] is None else f"typed e {p['typed_e']:.6g}"
        out.write(f"{name}{_lone(p)}: {p['model']} ({typed}), end rule {p['end']}\n")
        steps = p.get("steps_per_contact") or [None] * len(p["speeds"])
        late = p.get("late") or [False] * len(p["speeds"])
        for g, e, stick, through, n, found_late in zip(p["speeds"], p["eps"], p["sticks"], p["passes_through"], steps,
                                                       late):
            out.write(f"  g {g:<12.6g} " + (
                f"passes through: the largest overlap reaches {reach} = {p['overlap_limit']:.4g}, the engine "
                f"pushes {pushed} (no eps)\n" if through else
                ("found late: the neighbour lists may find the contact only in overlap, at any speed (no eps)\n"
                 if p["late_above"] == 0 else f"found late: above {p['late_above']:.4g} the neighbour lists may find "
                 "the contact only in overlap (no eps)\n") if found_late else
                f"sticks: the attractive phase keeps {kept} (eps 0)\n" if stick else f"eps {e:.10f}" + (
                    f"  ({n:.3g} steps per contact at dt {p['dt']:.4g})" if n is not None else "") + "\n"))
        if p["exact_line"]:
            t, w = p["types"][0], p.get("wall_type")
            shared = f" (entry {t} {w}: types {min(t, w)} {max(t, w)} get eps = e from it too)" if w else ""
            out.write(f"  for eps = e exactly{shared}: {p['exact_line']}\n")


def _sized(row: dict) -> str:
    """Where a type has several sizes: which end of the pair's eps range the row is, at which spheres;
    and where the stage's settings were read from values the runs change, that they may not be the deck's."""
    doubt = (" [its settings follow a value the skipped runs change: may not be the deck's, a note says which]"
             if row.get("may_differ") else "")
    return _ends_said(row) + doubt


def _lone(row: dict) -> str:
    """Where a type has one sphere, which no fix adds to: that its pair with itself does not happen."""
    return (f" [type {row['types'][0]} has one sphere at this run and no fix makes more: this pair does not happen "
            "here; its eps is the settings' for two such spheres]" if row.get("lone") else "")


def _ends_said(row: dict) -> str:
    """Which end of the pair's eps range the row is, at which spheres ("" for one size)."""
    if "sizes" not in row:
        return ""
    if row["sizes"] == "any":
        return " (spheres of several sizes: this law's eps does not depend on size, so this row holds for every size)"
    at = " and ".join(f"radius {r:.6g} density {rho:.6g}" for r, rho in row["at"])
    if row["sizes"] == "only":
        return f" (spheres of several sizes, of which only these meet: {at})"
    over = "the sizes sampled (a note says which)" if row.get("sampled") else "the sizes present"
    if row.get("if_poured"):
        over += f" and, if fix {', '.join(row['if_poured'])} has not finished inserting, its own"
    return f" ({row['sizes']} over {over}, at {at})"


def _run_materials(engine, args, text: str, speeds: list, read_file, out) -> None:
    """``restitution deck`` on an engine's material file (Kratos' MaterialsDEM.json)."""
    if args.density:
        raise ParameterError("density", args.density, f"{engine.label}'s material file gives the densities")
    res = engine.materials.audit_materials(text, speeds, _per_type("radius", args.radius), read_file)
    for row in res["not_audited"]:
        print(f"restitution deck: relation {row['relation']} ({' - '.join(row['materials'])}) not audited: "
              f"{row['why']}", file=sys.stderr)
    if args.json:
        write_json(res, out)
        return
    dt = res["time_step"]
    step = "not given (no ProjectParametersDEM.json beside it)" if dt is None else f"{dt:g} ({res['scheme']})"
    out.write(f"# {res['code']} materials file; time step {step}\n")
    for row in res["relations"] + res["walls"]:
        a, b = row["materials"]
        name = f"relation {row['relation']} wall: {a} on a wall of {b}" if row in res["walls"] else \
            f"relation {row['relation']}: {a} - {b}"
        out.write(f"{name}: {row['model']} (typed e {row['typed_e']:.6g}), end rule {row['end']}; radius from "
                  f"{', '.join(dict.fromkeys(row['radius_from']))}\n")
        steps = row["steps_per_contact"] or [None] * len(row["speeds"])
        for g, e, n in zip(row["speeds"], row["eps"], steps):
            out.write(f"  g {g:<12.6g} " + (f"passes through: the largest overlap reaches {row['overlap_limit']:.4g} "
                                            "(no eps)\n" if e is None else
                                            f"eps {e:.10f}" + (f"  ({n:.0f} steps per contact)" if n else "") + "\n"))
        if row["exact_line"]:
            out.write(f"  for eps = e: {row['exact_line']}\n")


def _stage_head(stage: dict, k: int, n: int) -> str:
    """The text output's heading of stage k of n (none where the deck has one stage).

    Examples
    --------
    >>> runs = [{"file": None, "line": 22, "pass": p} for p in (1, 2, 3)] + [{"file": None, "line": 29}]
    >>> _stage_head({"runs": runs}, 1, 2)
    '# stage 1 of 2: the contact settings of the runs at line 22 (passes 1 to 3), line 29'
    """
    if n == 1:
        return ""
    runs = stage["runs"]
    # a loop's passes of one line, one after another, said once: "line 22 (passes 1 to 13)"
    spans: list = []
    for r in runs:
        here = f"{r['file']} line {r['line']}" if r["file"] else f"line {r['line']}"
        if spans and spans[-1][0] == here and r.get("pass") is not None and spans[-1][2] == r["pass"] - 1:
            spans[-1][2] = r["pass"]
        else:
            spans.append([here, r.get("pass"), r.get("pass")])
    where = ", ".join(here + ("" if first is None else f" (pass {first})" if first == last else
                              f" (passes {first} to {last})") for here, first, last in spans[:5])
    more = f" and {len(spans) - 5} more" if len(spans) > 5 else ""
    return f"# stage {k} of {n}: the contact settings of the run{'s' if len(runs) > 1 else ''} at {where}{more}"


def add_lammps_subcommand(subparsers) -> None:
    m = subparsers.add_parser(
        "lammps", help="LAMMPS pair_style granular settings <-> eps for two spheres",
        description="With --eta-n0: the eps(v) these settings give at each --g (audit). With --eps: the "
                    "damping that gives it at --g, as a pair_coeff line (design). SI or any consistent units.")
    for flag, what in (("--normal", "hooke, hertz or hertz/material"),
                       ("--damping", "velocity, mass_velocity, viscoelastic, tsuji or coeff_restitution")):
        m.add_argument(flag, required=True, help=what)
    for flag, what in (("--k-n", "stiffness of hooke / hertz"), ("--E", "Young's modulus of hertz/material"),
                       ("--nu", "Poisson ratio of hertz/material"), ("--eta-n0", "LAMMPS' damping coefficient "
                       "(tsuji, coeff_restitution: its e)"), ("--eps", "target eps at the (single) --g")):
        m.add_argument(flag, type=number_argument, help=what)
    m.add_argument("--limit-damping", action="store_true", help="LAMMPS' limit_damping keyword (force end rule)")
    m.add_argument("--radius", type=number_argument, nargs="+", required=True, metavar="R",
                   help="radius of both spheres, or of each (two values)")
    m.add_argument("--density", type=number_argument, nargs="+", required=True, metavar="RHO",
                   help="density of both spheres, or of each (two values)")
    m.add_argument("--g", type=number_argument, nargs="+", required=True, metavar="V", help="impact speed(s)")
    m.add_argument("--json", action="store_true", help="machine-readable output")


def run_lammps(args, out) -> None:
    from ..dem.engines import ENGINES
    from ..dem.engines.lammps.design import lammps_audit, lammps_design
    from ..dem.pair import Pair
    if (args.eta_n0 is None) == (args.eps is None):
        raise ParameterError("eps", args.eps, "give exactly one of --eta-n0 (audit) and --eps (design)")
    for flag, values in (("--radius", args.radius), ("--density", args.density)):
        if len(values) > 2:
            raise UsageError(f"restitution lammps: {flag} takes one value (both spheres) or two (one each), "
                              f"got {len(values)}")
    # the stiffness options the chosen normal model does not read would be dropped without a word
    reads = {"hooke": ("k_n",), "hertz": ("k_n",), "hertz/material": ("E", "nu")}.get(args.normal, ())
    for name in ("k_n", "E", "nu"):
        if getattr(args, name) is not None and args.normal in {"hooke", "hertz", "hertz/material"} and name not in reads:
            flag = "--" + name.replace("_", "-")
            raise UsageError(f"restitution lammps: {flag} is not read by --normal {args.normal} (it reads "
                              + " and ".join("--" + r.replace("_", "-") for r in reads) + ")")
    radii, dens = (args.radius * 2)[:2], (args.density * 2)[:2]
    pair = Pair.spheres(radii[0], radii[1], dens[0], dens[1])
    stiff = {"normal": args.normal, "k_n": args.k_n, "E": args.E, "nu": args.nu, "damping": args.damping,
             "limit_damping": args.limit_damping}
    if args.eps is not None:
        if len(args.g) != 1:
            raise ParameterError("g", args.g, "give one impact speed with --eps")
        res = lammps_design(pair, eps=args.eps, g=args.g[0], **stiff)
    else:
        res = lammps_audit(pair, args.g, eta_n0=args.eta_n0, **stiff)
    for note in ENGINES["lammps"].notes([stiff]):     # after the answer: a refusal stays one line
        print(f"restitution lammps: note: {note}", file=sys.stderr)
    if args.json:
        write_json(res, out)
        return
    out.write(res.pop("pair_coeff") + "\n")
    rows = res.pop("rows", None)
    for key, value in res.items():
        out.write(f"# {key} = {value:.12g}\n" if isinstance(value, float) else f"# {key} = {value}\n")
    for row in rows or ():
        out.write(f"g {row['g']:<12.6g} " + ("passes through: the largest overlap reaches R1 + R2 (no eps)\n"
                                             if row["passes_through"] else
                                             f"eps {row['eps']:.12g}  t_c {row['contact_time']:.6g}\n"))


def add_dem_subcommands(sub) -> None:
    """Add ``lammps``, ``deck`` and ``scene`` to the subparsers ``sub``, in that order."""
    add_lammps_subcommand(sub)
    add_deck_subcommand(sub)
    add_scene_subcommand(sub)


def _by_fix(beside: list) -> list:
    """A row's beside effects, those of one fix given at several sizes (``at``) together."""
    out: list = []
    for fix in beside:
        if out and "at" in fix and "at" in out[-1][0] and (fix["fix"], fix["file"], fix["line"]) == (
                out[-1][0]["fix"], out[-1][0]["file"], out[-1][0]["line"]):
            out[-1].append(fix)
        else:
            out.append([fix])
    return out


def _effect_size(row: dict, fix: dict, at: bool) -> str:
    """": eps at g = ..." of one beside effect (face by face where several; ``at``: led by its sizes)."""
    size = _engine_eps(row, fix["eps_engine"])
    if len(fix.get("faces") or []) > 1:       # a gravity on a wall of several faces or directions
        size = ": " + "; ".join(f"{face['face']} (gravity {face['push']:+.4g} into it){_engine_eps(row, face['eps_engine'])}"
                                for face in fix["faces"])
    if not at:
        return size
    return "; at " + " and ".join(f"radius {r:.6g} density {rho:.6g}" for r, rho in fix["at"]) + size


def _engine_eps(row: dict, eps_engine) -> str:
    """": eps at g = ... (the contact's own ...), ..." of a beside effect's eps_engine ("" where none)."""
    sized = [(g, e, own) for g, e, own in zip(row["speeds"], eps_engine or [], row["eps"])
             if e is not None and own is not None]
    return (": " + ", ".join(f"{e:.6g} at g = {g:.4g} (the contact's own {own:.6g})" for g, e, own in sized)
            if sized else "")
