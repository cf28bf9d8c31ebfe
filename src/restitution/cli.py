"""Command line: `restitution series`, `collide`, `eps`, `calibrate`, `lammps`, `deck` and `scene`.

User mistakes end in one line on stderr and exit status 2, never a traceback.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys

from .core.errors import ParameterError
from .core.exponents import number_argument

EXIT_USAGE = 2


class _OneLineParser(argparse.ArgumentParser):
    """argparse prints the whole usage block on error; we print one line."""

    def error(self, message):  # noqa: D401 - argparse hook
        raise _UsageError(f"{self.prog}: {message}")


class _UsageError(Exception):
    pass


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {value}")
    return value


def add_end(p: argparse.ArgumentParser) -> None:
    p.add_argument("--end", default="force",
                   help="end-of-contact rule: force (contact ends where the total force vanishes; LAMMPS "
                        "limit_damping, default) or overlap (when the overlap returns to 0; LAMMPS' default)")


def _add_exponents(p: argparse.ArgumentParser) -> None:
    p.add_argument("--alpha", required=True, help="elastic exponent, a rational > 0 such as 3/2")
    p.add_argument("--gamma", required=True, help="dissipative exponent, a rational >= 0 such as 1")


def build_parser() -> argparse.ArgumentParser:
    """The ``restitution`` command's parser, every subcommand included (the CLI reference page is
    generated from it).

    Returns
    -------
    argparse.ArgumentParser
        A parser whose errors are one line (exit status 2).

    Examples
    --------
    >>> from restitution.cli import build_parser
    >>> args = build_parser().parse_args(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.47"])
    >>> args.command, args.omega
    ('collide', 0.47)
    """
    parser = _OneLineParser(prog="restitution",
                            description="Coefficient of restitution of viscoelastic collisions.")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_OneLineParser)

    s = sub.add_parser("series", help="exact perturbation series x_n(tau) of the scaled equation")
    _add_exponents(s)
    s.add_argument("--omega-order", type=_positive_int, default=4, help="highest power of Omega (default 4)")
    s.add_argument("--max-power", default="11", help="highest power of tau kept, a rational >= 1 (default 11)")
    s.add_argument("--inverse", action="store_true", help="the inverse collision x'' + Omega x^a - x^g x' = 0")
    s.add_argument("--json", action="store_true", help="machine-readable output")

    c = sub.add_parser("collide", help="integrate one collision: eps, tau_b, x_b, tau_c, x_c")
    _add_exponents(c)
    c.add_argument("--omega", type=number_argument, help="scaled parameter Omega > 0")
    c.add_argument("--D1", type=number_argument, help="elastic constant D1 > 0 (with --D2 and --g)")
    c.add_argument("--D2", type=number_argument, help="dissipative constant D2 > 0")
    c.add_argument("--g", type=number_argument, help="impact speed g > 0")
    c.add_argument("--rtol", type=number_argument, default=None,
                   help="relative tolerance of methods reference and integrator (default 1e-12)")
    c.add_argument("--method", default="reference",
                   help="reference (scipy, default), integrator (compiled; formerly fast), highprec (mpmath) "
                        "or exact-family, alias closed-form (alpha = 2 gamma + 1: the linear dashpot at "
                        "(gamma+1) Omega, exact)")
    c.add_argument("--digits", type=int, default=None, help="digits of --method highprec (default 30)")
    add_end(c)
    c.add_argument("--json", action="store_true", help="machine-readable output")

    add_eps_subcommand(sub)

    k = sub.add_parser("calibrate", help="the damping D2 that gives a target eps at an impact speed",
                       description="D2 of delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 with eps(g) = "
                                   "--eps; several --g/--eps pairs: least squares, residual reported.")
    _add_exponents(k)
    k.add_argument("--D1", type=number_argument, required=True, help="elastic constant D1 > 0")
    k.add_argument("--eps", type=number_argument, nargs="+", required=True, metavar="E", help="target eps in (0, 1)")
    k.add_argument("--g", type=number_argument, nargs="+", required=True, metavar="V", help="impact speed(s) > 0")
    add_end(k)
    k.add_argument("--json", action="store_true", help="machine-readable output")

    add_lammps_subcommand(sub)
    add_deck_subcommand(sub)
    add_scene_subcommand(sub)
    return parser


def add_scene_subcommand(subparsers) -> None:
    s = subparsers.add_parser(
        "scene", help="the cheapest contact model per contact of a DEM scene, and its input lines",
        description="Reads a scene file (YAML: materials, species, walls, code options, speeds, targets, "
                    "tolerance; see docs/howto/scenes.md) and answers for every contact. Exit status 1 when "
                    "some contact has no model within the tolerance, or an overlap at which the code's "
                    "geometry breaks.")
    s.add_argument("file", help="the scene file")
    s.add_argument("--json", action="store_true", help="machine-readable output")
    s.add_argument("--out", metavar="DIR", help="also write DIR/scene.json, DIR/input.lammps and DIR/table.txt")


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
                          for r in c["rungs"])
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

    from .fast.cache import nearest_existing
    here = nearest_existing(Path(path).absolute())
    if not here.is_dir():
        raise ParameterError(name, path, f"cannot be a directory: {here} is a file")
    try:
        with tempfile.TemporaryFile(dir=here):
            pass
    except OSError as exc:
        raise ParameterError(name, path, f"cannot be written ({exc.strerror})") from None


def _run_scene(args, out) -> int:
    from pathlib import Path

    from .dem.scene import answer_scene, contact_count
    from .dem.scene_file import read_scene
    scene = read_scene(args.file)
    if args.out:
        _check_writable_dir("out", args.out)
    n = contact_count(scene)
    if n > LARGE_SCENE:
        # measured: about 2.2 kB of JSON per contact, and the answer is held in memory until written
        print(f"restitution scene: {n} contacts ({len(scene.types)} atom types, {len(scene.walls)} wall"
              f"{'' if len(scene.walls) == 1 else 's'}), each "
              f"answered and listed: about {n * 2.2e-3:.0f} MB of JSON; progress follows", file=sys.stderr, flush=True)
    res = answer_scene(scene, progress=_Progress("scene", "contacts", 1.0))
    if any((c.get("setting") or {}).get("damping") == "tsuji" for c in res["contacts"]):
        from .dem.codes import TSUJI_VERSION_NOTE
        print(f"restitution scene: note: {TSUJI_VERSION_NOTE}", file=sys.stderr)
    text = json.dumps(res, separators=(", ", ": ")) + "\n"
    table = scene_table(res)
    if args.out:   # everything computed first: a refused scene writes nothing
        d = Path(args.out)
        try:
            d.mkdir(parents=True, exist_ok=True)
            (d / "scene.json").write_text(text)
            (d / "input.lammps").write_text("\n".join(res["input_lines"]) + "\n")
            (d / "table.txt").write_text(table)
        except OSError as exc:
            raise ParameterError("out", args.out, f"cannot be written ({exc.strerror})") from None
    out.write(text if args.json else table)
    return 0 if res["met"] else 1


def add_deck_subcommand(subparsers) -> None:
    d = subparsers.add_parser(
        "deck", help="the eps a LAMMPS or LIGGGHTS input deck really gives, for every type pair and flat wall",
        description="Reads pair_style granular (LAMMPS) or pair_style gran model hertz|hooke (LIGGGHTS) decks. "
                    "One --g: five speeds over two decades around it; several: those speeds.")
    d.add_argument("file", help="the input script")
    d.add_argument("--g", type=number_argument, nargs="+", required=True, metavar="V", help="impact speed(s)")
    d.add_argument("--radius", nargs="+", default=[], metavar="T=R", help="radius of atom type T")
    d.add_argument("--density", nargs="+", default=[], metavar="T=RHO", help="density of atom type T")
    d.add_argument("--json", action="store_true", help="machine-readable output")


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


def _run_deck(args, out) -> None:
    from .dem.codes import TSUJI_VERSION_NOTE
    from .dem.deck import audit_deck
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
    res = audit_deck(text, speeds, _per_type("radius", args.radius), _per_type("density", args.density), read_file)
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
        rows += [(p, f"types {p['types'][0]} {p['types'][1]}", "R1 + R2", "the spheres through each other",
                  "the spheres together", head) for p in stage["pairs"]]
        rows += [(w, f"type {w['types'][0]} on wall {w['wall']}", "the radius", "the sphere through the wall",
                  "the sphere on the wall", head) for w in stage["walls"]]
    for p, name, reach, pushed, _, head in rows:   # no eps there: said on stderr too, where a --json reader looks
        through = [g for g, t in zip(p["speeds"], p["passes_through"]) if t]
        if through:
            where = f" ({head.removeprefix('# ')})" if head else ""
            print(f"restitution deck: {name}{where}: the engine pushes {pushed} from g = {min(through):.4g} on (the "
                  f"largest overlap reaches {reach}): no eps there", file=sys.stderr)
    if args.json:
        _write_json(res, out)
        return
    if res["ignored"]:
        out.write(f"# {res['code']} deck; no part in a head-on contact: {', '.join(res['ignored'])}\n")
    shown = None
    for p, name, reach, pushed, kept, head in rows:
        if head and head != shown:
            out.write(head + "\n")
            shown = head
        typed = "none typed" if p["typed_e"] is None else f"typed e {p['typed_e']:.6g}"
        out.write(f"{name}: {p['model']} ({typed}), end rule {p['end']}\n")
        for g, e, stick, through in zip(p["speeds"], p["eps"], p["sticks"], p["passes_through"]):
            out.write(f"  g {g:<12.6g} " + (
                f"passes through: the largest overlap reaches {reach} = {p['overlap_limit']:.4g}, the engine "
                f"pushes {pushed} (no eps)\n" if through else
                f"sticks: the attractive phase keeps {kept} (eps 0)\n" if stick else f"eps {e:.10f}\n"))
        if p["exact_line"]:
            t, w = p["types"][0], p.get("wall_type")
            shared = f" (entry {t} {w}: types {min(t, w)} {max(t, w)} get eps = e from it too)" if w else ""
            out.write(f"  for eps = e exactly{shared}: {p['exact_line']}\n")


def _stage_head(stage: dict, k: int, n: int) -> str:
    """The text output's heading of stage k of n (none where the deck has one stage)."""
    if n == 1:
        return ""
    runs = stage["runs"]
    where = ", ".join(f"{r['file']} line {r['line']}" if r["file"] else f"line {r['line']}" for r in runs[:5])
    more = f" and {len(runs) - 5} more" if len(runs) > 5 else ""
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


def _run_lammps(args, out) -> None:
    from .dem.codes import TSUJI_VERSION_NOTE, Pair
    from .dem.settings import lammps_audit, lammps_design
    if (args.eta_n0 is None) == (args.eps is None):
        raise ParameterError("eps", args.eps, "give exactly one of --eta-n0 (audit) and --eps (design)")
    for flag, values in (("--radius", args.radius), ("--density", args.density)):
        if len(values) > 2:
            raise _UsageError(f"restitution lammps: {flag} takes one value (both spheres) or two (one each), "
                              f"got {len(values)}")
    # the stiffness options the chosen normal model does not read would be dropped without a word
    reads = {"hooke": ("k_n",), "hertz": ("k_n",), "hertz/material": ("E", "nu")}.get(args.normal, ())
    for name in ("k_n", "E", "nu"):
        if getattr(args, name) is not None and args.normal in {"hooke", "hertz", "hertz/material"} and name not in reads:
            flag = "--" + name.replace("_", "-")
            raise _UsageError(f"restitution lammps: {flag} is not read by --normal {args.normal} (it reads "
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
    if args.damping == "tsuji":     # after the answer: a refusal stays one line
        print(f"restitution lammps: note: {TSUJI_VERSION_NOTE}", file=sys.stderr)
    if args.json:
        _write_json(res, out)
        return
    out.write(res.pop("pair_coeff") + "\n")
    rows = res.pop("rows", None)
    for key, value in res.items():
        out.write(f"# {key} = {value:.12g}\n" if isinstance(value, float) else f"# {key} = {value}\n")
    for row in rows or ():
        out.write(f"g {row['g']:<12.6g} " + ("passes through: the largest overlap reaches R1 + R2 (no eps)\n"
                                             if row["passes_through"] else
                                             f"eps {row['eps']:.12g}  t_c {row['contact_time']:.6g}\n"))


def _run_calibrate(args, out) -> None:
    from .dem.calibrate import calibrate
    one = len(args.eps) == 1 and len(args.g) == 1
    res = calibrate(args.alpha, args.gamma, D1=args.D1, eps=args.eps[0] if one else args.eps,
                    g=args.g[0] if one else args.g, end=args.end).as_dict()
    _report_approximation(args)
    if args.json:
        _write_json(res, out)
        return
    for key, value in res.items():
        out.write(f"{key:>8}  {value:.12g}\n" if isinstance(value, float) else f"{key:>8}  {value}\n")


def add_eps_subcommand(subparsers) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "eps", help="coefficient of restitution to a tolerance (picks the cheapest adequate method)",
        description="eps for Omega values or impact speeds, to a relative tolerance; says which method "
                    "was used and its error bound.")
    p.add_argument("--alpha", required=True, help="elastic exponent, a rational > 0 such as 3/2")
    p.add_argument("--gamma", required=True, help="dissipative exponent, a rational >= 0 such as 1")
    p.add_argument("--omega", type=number_argument, nargs="+", metavar="W", help="scaled parameter(s) Omega > 0")
    p.add_argument("--D1", type=number_argument, help="elastic constant D1 > 0 (with --D2 and --g)")
    p.add_argument("--D2", type=number_argument, help="dissipative constant D2 > 0")
    p.add_argument("--g", type=number_argument, nargs="+", metavar="V", help="impact speed(s) g > 0")
    p.add_argument("--tol", type=number_argument, default=None,
                   help="relative tolerance in (0, 1) (default 1e-9; with --method and no --tol, that method's own bound)")
    p.add_argument("--method", default=None,
                   help="force one rung of the ladder (it must meet --tol if given), e.g. closed-form, master, integrator")
    p.add_argument("--no-build", action="store_true",
                   help="never build the master curve; use only methods that need nothing cached")
    add_end(p)
    p.add_argument("--json", action="store_true", help="machine-readable output")
    return p


def run_eps(args, out) -> None:
    from .api import epsilon

    physical = (args.D1, args.D2, args.g)
    if args.omega is not None and any(v is not None for v in physical):
        raise ParameterError("omega", args.omega, "give either --omega or all of --D1 --D2 --g, not both")
    if args.omega is None and any(v is None for v in physical):
        missing = next(n for n, v in zip(("--D1", "--D2", "--g"), physical) if v is None)
        raise ParameterError(missing.lstrip("-"), None, "give --omega, or all of --D1 --D2 --g")
    tol = 1e-9 if args.tol is None and args.method is None else args.tol
    kwargs = dict(alpha=args.alpha, gamma=args.gamma, tol=tol, method=args.method,
                  build=False if args.no_build else None, end=args.end)
    if args.omega is not None:
        res = epsilon(omega=args.omega, **kwargs)
    else:
        res = epsilon(g=args.g, D1=args.D1, D2=args.D2, **kwargs)
    _report_approximation(args)
    eps = [float(e) for e in res.eps.ravel()]
    if args.json:
        extra = {} if res.coefficients is None else {"coefficients": res.coefficients}
        json.dump({"eps": eps, "method": res.method, "error_bound": float(res.error_bound), **extra}, out,
                  separators=(", ", ": "))
        out.write("\n")
        return
    out.write(f"method {res.method} ({res.setting or 'no setting'}), relative error bound "
              f"{res.error_bound:.3g}" + ("" if res.tol is None else f" (tol {res.tol:.3g})") + "\n")
    out.write(f"{'Omega':>22}  {'eps':>22}\n")
    for w, e in zip(res.omega.ravel(), eps):
        out.write(f"{w:22.15g}  {e:22.15g}\n")


def _omega_from_args(args) -> float:
    physical = [args.D1, args.D2, args.g]
    if args.omega is not None:
        if any(v is not None for v in physical):
            raise _UsageError("restitution collide: give either --omega or all of --D1 --D2 --g, not both")
        return args.omega
    if any(v is None for v in physical):
        raise _UsageError("restitution collide: give --omega, or all of --D1 --D2 --g")
    from .core.model import Material
    return Material(args.alpha, args.gamma, args.D1, args.D2).omega(args.g)


def _report_approximation(args) -> None:
    """Say on stderr when a float exponent was replaced by a nearby rational, and by how much."""
    from .core.exponents import Exponents
    ex = Exponents.parse(args.alpha, args.gamma)
    for name, given, exact, err in (("alpha", args.alpha, ex.alpha, ex.alpha_error),
                                    ("gamma", args.gamma, ex.gamma, ex.gamma_error)):
        if err:
            print(f"restitution: note: {name} = {given} taken as {exact} (|difference| = {err:.3g})",
                  file=sys.stderr)


def _write_json(data, out) -> None:
    json.dump(data, out, separators=(", ", ": "))
    out.write("\n")


class _Progress:
    """A long computation's price on stderr while it runs: past a few seconds it says how far it is
    and about how long it takes in all, then again every half minute. ``power``: how the cost of the
    first k of n steps grows (k^power), so the estimate is elapsed * (n/k)^power."""

    FIRST, EVERY = 3.0, 30.0

    def __init__(self, label: str, steps: str, power: float = 1.0, note: str = "", stream=None):
        import time
        self.clock = time.monotonic
        self.start = self.clock()
        self.next = self.start + self.FIRST
        self.label, self.steps, self.power, self.note, self.stream = label, steps, power, note, stream

    def __call__(self, done: int, total: int) -> None:
        now = self.clock()
        if now < self.next or done >= total:
            return
        self.next = now + self.EVERY
        elapsed = now - self.start
        whole = elapsed * (total / done) ** self.power
        print(f"restitution {self.label}: {done} of {total} {self.steps} after {elapsed:.0f} s; about "
              f"{_duration(whole)} in all{self.note}", file=self.stream or sys.stderr, flush=True)


def _duration(seconds: float) -> str:
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


def _run_series(args, out) -> None:
    from .core.series import series_for
    ps = series_for((args.alpha, args.gamma), args.omega_order, args.max_power,
                             "inverse" if args.inverse else "forward",
                             # the first k powers cost about k^3.5 (k^2.7 to k^4.2 measured between pairs)
                             progress=_Progress("series", "powers of tau", 3.5,
                                                " (an estimate, good to a factor of about two)"))
    _report_approximation(args)
    data = ps.as_dict()
    if args.json:
        _write_json(data, out)
        return
    out.write(f"{data['direction']} collision, alpha = {data['alpha']}, gamma = {data['gamma']}, "
              f"p = {data['p']}: x = sum_n Omega^n x_n(tau)\n")
    out.write(f"{'n':>3}  {'power':>8}  coefficient\n")
    for n, terms in data["orders"].items():
        for power, coeff in terms:
            out.write(f"{n:>3}  {power:>8}  {coeff}\n")


def _run_collide(args, out) -> None:
    # an option the chosen method does not read would be dropped without a word
    if args.digits is not None and args.method != "highprec":
        raise _UsageError(f"restitution collide: --digits is read by --method highprec only (method here: "
                          f"{args.method}); drop it or add --method highprec")
    if args.rtol is not None and args.method in ("highprec", "closed-form", "exact-family"):
        raise _UsageError(f"restitution collide: --rtol is read by --method reference and integrator only; "
                          f"{args.method} sets its own accuracy" + (" (use --digits)" if args.method == "highprec" else ""))
    omega = _omega_from_args(args)
    from .api import collide
    result = collide(args.alpha, args.gamma, omega, method=args.method,
                     rtol=1e-12 if args.rtol is None else args.rtol,
                     digits=30 if args.digits is None else args.digits, end=args.end).as_dict()
    _report_approximation(args)
    if args.json:
        _write_json(result, out)
        return
    for key, value in result.items():
        shown = f"{value:.12g}" if isinstance(value, float) and math.isfinite(value) else value
        out.write(f"{key:>6}  {shown}\n")


_NEGATIVE_VALUE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def _attach_negative_values(argv: list[str]) -> list[str]:
    """`--gamma -1/2` -> `--gamma=-1/2`: argparse would read -1/2 or -inf as an option and say only
    "expected one argument"; attached, the value reaches the physics, which names the allowed range."""
    out: list[str] = []
    i = 0
    while i < len(argv):
        tok = argv[i]
        if (tok.startswith("--") and "=" not in tok and i + 1 < len(argv)
                and _NEGATIVE_VALUE.match(argv[i + 1])):
            out.append(f"{tok}={argv[i + 1]}")
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


def _refuse_repeated_options(argv) -> None:
    """argparse keeps the last of `--omega 1 --omega 2` silently; a value given twice is a mistake."""
    seen = set()
    for token in argv:
        if token.startswith("--"):
            name = token.split("=", 1)[0]
            if name in seen:
                raise _UsageError(f"restitution: {name} given twice: give it once (several values "
                                  "go after one option: --omega 0.1 0.5)")
            seen.add(name)


def main(argv=None, out=None) -> int:
    """Run the ``restitution`` command.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default: ``sys.argv[1:]``).
    out : file-like, optional
        Where the answer is written (default: standard output); notes go to standard error.

    Returns
    -------
    int
        The exit status: 0 on success, 1 where a subcommand reports a failed check (``scene``),
        2 for a mistake in the arguments (one line on standard error, no traceback).

    Raises
    ------
    SystemExit
        Only from ``--help``, as argparse does.

    Examples
    --------
    >>> from restitution.cli import main
    >>> main(["collide", "--alpha", "1", "--gamma", "0", "--omega", "1"])   # doctest: +ELLIPSIS
     alpha  1
     gamma  0
     omega  1
       eps  0.298436059...
    ...
    0
    >>> main(["collide", "--alpha", "1", "--gamma", "0", "--omega", "-1"])   # the message goes to stderr
    2
    """
    out = sys.stdout if out is None else out
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        _refuse_repeated_options(argv)
        args = build_parser().parse_args(_attach_negative_values(argv))
        status = {"series": _run_series, "collide": _run_collide, "eps": run_eps, "calibrate": _run_calibrate,
                  "lammps": _run_lammps, "deck": _run_deck, "scene": _run_scene}[args.command](args, out)
    except _UsageError as exc:
        print(str(exc), file=sys.stderr)
        return EXIT_USAGE
    except ParameterError as exc:
        print(f"restitution: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except BrokenPipeError:
        # the reader (`| head`) has what it wanted; Python would print a traceback at exit
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    return status or 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
