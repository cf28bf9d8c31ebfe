"""The fuzz's deck checks (issue 28): every type pair and flat wall of a random deck, as
`restitution deck` reads it, run head-on in the real engine (LAMMPS or LIGGGHTS) with the deck's own
lines; extrapolated to dt = 0 the engine must give the eps listed, and keep together the bodies said to
stick. A damaged deck is answered or refused in one line."""

from __future__ import annotations

import math
import re
import tempfile
import traceback
from fractions import Fraction
from pathlib import Path

from fuzz_outcome import engine_error, one_line


# ------------------------------------------------------------------------------------ decks
#: What `restitution deck` says a LAMMPS deck gives, against the deck's own pair_coeff lines run in
#: LAMMPS: extrapolated to dt = 0 from t_c/2000, /4000, /8000, to this in eps (the separation speed
#: over the impact speed). The steps' error is one in the separation speed, of the impact speed's
#: scale whatever eps is, so the tolerance is absolute in eps, not relative to it: a hooke pair
#: damped to eps 0.0432236 (session 23's fuzz, exact in closed form) came out 0.0432171 from those
#: three step sizes, and LAMMPS at 128 000, 512 000, 2 048 000 steps a contact gave 0.0432200,
#: 0.0432230, 0.0432234, closing on the audit's value: 6.5e-6 off, 15 times a tolerance relative to eps.
DECK_EXTRAPOLATED = 1e-5
DECK_STEPS = 2000
#: A pair the audit says sticks must stay together in LAMMPS for this many elastic contact times, or
#: leave with eps below DECK_STICK_EPS.
DECK_STICK_TIMES = 30
DECK_STICK_EPS = 1e-3
#: Smallest eps run in LAMMPS, per end rule: below it the spheres take too many steps to part (under the
#: overlap rule a creeping return; under the force rule they leave overlapping, at eps g).
DECK_MIN_EPS = {"overlap": 1e-3, "force": 0.02}
#: Nor a run of more steps than this (a strongly overdamped pair: the step follows the damping's
#: fast time, the creep its slow one; or a force-rule pair leaving slowly while still overlapping).
DECK_MAX_STEPS = 400_000


def check_script_deck_case(text: str, speeds: list, types: dict, nhead: int) -> list[dict]:
    """Every stage of a deck of script_deck_cases, every type pair, run head-on in LAMMPS with the
    deck's own lines up to that stage's first run (the control flow, quotes, variables and labels
    as LAMMPS itself runs them, from a file it includes: jump SELF needs one): extrapolated to
    dt = 0 within DECK_EXTRAPOLATED of the stage's eps."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck
    from restitution.dem.pair import Pair

    case = {"deck": text, "speeds": speeds}
    try:
        res = audit_deck(text, speeds)
    except Exception as exc:  # noqa: BLE001
        ok = isinstance(exc, ParameterError) and one_line(exc)
        return [{"method": "script deck (lammps)", "rule": "-", "status": "refused" if ok else "FAIL",
                 "ratio": 0.0, "case": case, "detail": "" if ok else "".join(traceback.format_exception_only(exc))}]
    lines = text.splitlines()
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, stage in enumerate(res["stages"]):
            first = stage["runs"][0]["line"]             # the deck's line number of the stage's first run
            # the engine needs no run: the earlier runs become no-ops, the stage ends before its own
            own = ["print run" if ln == "run 1" else ln for ln in lines[nhead:first - 1]]
            path = Path(tmp) / f"in.stage{k}"
            path.write_text("\n".join(own) + "\n")
            engine = _lammps_runner(f"include {path}", len(types))
            for p in stage["pairs"]:
                i, j = p["types"]
                pair = Pair.spheres(types[i]["radius"], types[j]["radius"], types[i]["density"], types[j]["density"])
                worst, detail, checked = _check_deck_row(p, pair, (i, j), engine, "lammps",
                                                         f"stage {k + 1} pair {i}-{j}")
                records.append({"method": "script deck (lammps)", "rule": p["end"], "case": case, "pair": f"{i}-{j}",
                                "status": "FAIL" if worst > 1.0 else "answered" if checked else "refused",
                                "ratio": worst, "detail": detail if worst > 1.0 else ""})
    return records

def check_deck_mutation(text: str) -> dict:
    """A damaged deck is answered or refused in one line (ParameterError), never another exception."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck

    rec = {"method": "deck mutation", "rule": "-", "ratio": 0.0, "case": {"deck": text}}
    try:
        audit_deck(text, [0.5, 5.0])
        rec.update(status="answered", detail="")
    except ParameterError as exc:
        one = one_line(exc)
        rec.update(status="refused" if one else "FAIL", detail="" if one else f"refusal of several lines: {exc}")
    except Exception as exc:  # noqa: BLE001
        rec.update(status="FAIL", detail="".join(traceback.format_exception_only(exc)).strip())
    return rec

def _lammps_runner(engine_lines: str, ntypes: int):
    """runs -> (relative velocity after / -g, or the exception) for runs (pair, types, g, dt, t_run),
    each in its own LAMMPS instance with the deck's own variable and pair_coeff lines."""
    from restitution.dem.engines.lammps.run import lammps_eps

    def run(runs):
        out = []
        for pair, types, g, dt, t_run in runs:
            try:
                out.append(lammps_eps(pair, engine_lines, g, dt, t_run, types, ntypes))
            except Exception as exc:  # noqa: BLE001
                out.append(exc)
        return out
    return run


def _liggghts_runner(engine_lines: str):
    """As _lammps_runner, all runs of one pair in one LIGGGHTS process (its start costs a second)."""
    from restitution.dem.engines.liggghts.run import liggghts_states

    def run(runs):
        if not runs:
            return []
        pair = runs[0][0]
        try:
            states = liggghts_states(pair, [(engine_lines, g, dt, t_run, types) for _, types, g, dt, t_run in runs])
        except Exception as exc:  # noqa: BLE001
            return [exc] * len(runs)
        return [-rel / g if gap > pair.R1 + pair.R2 else ArithmeticError("the spheres had not separated")
                for (_, _, g, _, _), (rel, gap) in zip(runs, states)]
    return run


def _check_deck_row(p: dict, pair, key: tuple, engine, code: str, name: str) -> tuple:
    """One audited contact (a type pair, or a type on a wall) in the engine at each listed speed:
    (the worst error over DECK_EXTRAPOLATED, what it was, whether anything ran). ``engine`` runs
    (pair, key, g, dt, t_run) tuples as _lammps_runner's function does."""
    from restitution.dem.contact import TIMES_OMEGA_MAX, Contact
    from restitution.dem.extrapolate import richardson

    a, c = float(Fraction(p["alpha"])), float(Fraction(p["gamma"]))
    runs, checks = [], []
    for g, listed, sticks, through in zip(p["speeds"], p["eps"], p["sticks"], p["passes_through"]):
        # not run: no eps listed (the centres would meet), or the bodies would take too many
        # steps to part (the force rule leaves them overlapping, moving apart at eps g)
        if through or (not sticks and listed < DECK_MIN_EPS[p["end"]]):
            continue
        # the undamped contact: its largest overlap bounds the damped one's, and its duration;
        # the step also resolves the damping's own time 1 / (D2 delta^gamma) (overdamped contacts)
        reach = (g * g * (a + 1.0) / (2.0 * p["D1"])) ** (1.0 / (a + 1.0))
        t_el = 2.0 * reach / g * math.sqrt(math.pi) * math.gamma(1.0 + 1.0 / (a + 1.0)) / \
            math.gamma(0.5 + 1.0 / (a + 1.0))
        fastest = min(t_el, 1.0 / (p["D2"] * reach ** c))
        if sticks:
            if DECK_STICK_TIMES * t_el / (fastest / DECK_STEPS) > DECK_MAX_STEPS:
                continue
            checks.append((g, listed, True, len(runs)))
            runs.append((pair, key, g, fastest / DECK_STEPS, DECK_STICK_TIMES * t_el))
            continue
        contact = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"])
        try:
            t_c = contact.contact_time(g)
        except Exception as exc:  # noqa: BLE001
            if not contact.omega(g) > TIMES_OMEGA_MAX:
                checks.append((g, listed, False, exc))
                continue
            # beyond the contact times' Omega the contact is all but undamped: its duration is
            # the elastic one to O(Omega^-1/2), enough to choose the steps
            t_c = t_el
        t_run = 1.2 * t_c + (2.0 * reach / (listed * g) if p["end"] == "force" else 0.0)
        # a whole number of steps per contact: where the damping force does not vanish at zero
        # overlap (gamma = 0) the last step's share of it, O(dt) and set by where the contact's
        # end falls in that step, would otherwise make eps(dt) jagged
        dt = t_c / (DECK_STEPS * math.ceil(t_c / fastest))
        if 4.0 * t_run / dt > DECK_MAX_STEPS:
            continue
        checks.append((g, listed, False, len(runs)))
        runs += [(pair, key, g, dt / m, t_run) for m in (1, 2, 4)]
    got = engine(runs)
    worst, detail = 0.0, ""
    for g, listed, sticks, at in checks:
        if isinstance(at, Exception):
            ratio, what = math.inf, f"t_c: {at}"
        elif sticks:
            eps = got[at]
            if isinstance(eps, ArithmeticError):     # still together: what the audit said
                continue
            if isinstance(eps, Exception):
                ratio, what = math.inf, f"{code}: {engine_error(eps)}"
            else:
                ratio = eps / DECK_STICK_EPS
                what = f"the audit says they stick, {code} lets them go with eps {eps:.4g}"
        else:
            three = got[at: at + 3]
            bad = next((e for e in three if isinstance(e, Exception)), None)
            if bad is not None:
                ratio, what = math.inf, f"{code}: {engine_error(bad)}"
            else:
                eps = richardson(*three, c)
                ratio = abs(eps - listed) / DECK_EXTRAPOLATED
                what = f"the audit says eps {listed:.8g}, {code} {eps:.8g} at dt = 0"
        if ratio > worst:
            worst, detail = ratio, f"{name} ({p['model']}, {p['end']} rule) at {g:.4g}: {what}"
    return worst, detail, bool(checks)


def _engine_lines(text: str, code: str, wall: bool = False) -> str:
    """The deck's lines an engine run takes. LAMMPS: its variables and pair_coeff lines (the runner
    writes the pair style), for a wall also the pair style, the groups and the wall's line.
    LIGGGHTS: the box, the materials and the pair style, never the wall or its mesh (_wall_runner
    passes the deck's own wall lines apart), nor the deck's atoms, integrator and run; the particle
    templates and the atoms' set lines only gave radii."""
    body = text.splitlines()
    if code == "lammps":
        return "\n".join(ln for ln in body if ln.startswith(("variable", "pair_", "group", "fix floor") if wall
                                                         else ("variable", "pair_coeff")))
    start = next(k for k, ln in enumerate(body) if ln.startswith("create_box"))
    return "\n".join([body[start]] + [ln for ln in body[start + 1:]
                                      if not ln.startswith(("fix pts", "fix floor", "fix mesh1", "group",
                                                            "create_atoms", "set type", "run", "fix integr"))]
                     + [ln for ln in body[:start] if ln.startswith("variable")])


def _wall_runner(text: str, code: str, ntypes: int, types: dict, wall: dict):
    """As _lammps_runner for a sphere of the key's type falling onto the deck's own wall (placed at
    z = 0 as the deck writes it; _engine_lines); for LIGGGHTS on all atoms, its mesh a triangle
    scaled to the sphere (centre 2.1 radii from its nearest edge). All runs in one process unless
    one stays on the wall (then one each)."""
    from restitution.dem.engines.lammps.run import lammps_wall_eps
    from restitution.dem.engines.liggghts.run import liggghts_wall_eps_runs

    lines = _engine_lines(text, code, wall=True)
    own = [re.sub(r"^fix floor \S+", "fix floor all", ln) for ln in text.splitlines()
           if ln.startswith(("fix mesh1", "fix floor"))]

    def batch(runs):
        (t,) = runs[0][1]
        r, rho = types[t]["radius"], types[t]["density"]
        try:
            if code == "lammps":
                return [lammps_wall_eps(r, rho, lines, g, dt, t_run, atom_type=t, ntypes=ntypes)
                        for _, _, g, dt, t_run in runs]
            plate = _plate([(x * r, y * r) for x, y in ((-3, -3), (6, -3), (-3, 6))])
            return liggghts_wall_eps_runs(r, rho, [(lines, g, dt, t_run, t, wall["wall_type"])
                                                   for _, _, g, dt, t_run in runs],
                                          wall="\n".join(own), files={"plate.stl": plate})
        except Exception as exc:  # noqa: BLE001
            return [exc]

    def run(runs):
        if code == "liggghts":       # one process for all, unless one of them stays on the wall
            got = batch(runs) if runs else []
            if len(got) == len(runs):
                return got
        return [batch([one])[0] for one in runs]
    return run


#: The referee's LAMMPS: the deck run as it is, in its own process (an error of LAMMPS' may leave
#: its instance unusable); MPICH's library loaded by path first, as the LAMMPS wheel needs
_LAMMPS_DECK = """
import ctypes, os, sys
lib = os.path.join(sys.prefix, "lib", "libmpi.so.12")
if os.path.exists(lib):
    ctypes.CDLL(lib, mode=ctypes.RTLD_GLOBAL)
import lammps
lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
try:
    lmp.file(sys.argv[1])
except Exception as exc:
    print(str(exc).strip())
    sys.exit(3)
"""


def _plate(corners) -> str:
    """An STL triangle in the plane z = 0, of the three (x, y) ``corners``."""
    return "".join(["solid plate\nfacet normal 0 0 1\n outer loop\n",
                    *(f"  vertex {x!r} {y!r} 0\n" for x, y in corners),
                    " endloop\nendfacet\nendsolid plate\n"])


def deck_folder(tmp: str, text: str) -> Path:
    """The deck written to ``tmp``/in.deck, beside the mesh it names (plate.stl: a triangle inside
    the generated decks' box, -1..1, in the plane of their walls, z = 0)."""
    deck = Path(tmp) / "in.deck"
    deck.write_text(text)
    if "plate.stl" in text:
        (Path(tmp) / "plate.stl").write_text(_plate([(-0.9, -0.9), (0.9, -0.9), (-0.9, 0.9)]))
    return deck


def engine_stop(deck: Path, code: str) -> str | None:
    """The deck run as it is by the engine itself (LAMMPS' Python module, or the liggghts binary),
    in its folder: None if it runs to its end, else the engine's own error message."""
    import shutil
    import subprocess
    import sys

    if code == "lammps":
        argv = [sys.executable, "-c", _LAMMPS_DECK, str(deck)]
    else:
        argv = (["stdbuf", "-oL"] if shutil.which("stdbuf") else []) + ["liggghts", "-in", str(deck), "-echo",
                                                                          "none", "-log", "none"]
    from restitution.dem.engines.liggghts.run import MPI_NOT_STARTED, MPI_START_RETRIES

    for _ in range(1 + MPI_START_RETRIES):
        proc = subprocess.run(argv, cwd=deck.parent, capture_output=True, text=True, errors="replace", timeout=600,
                              stdin=subprocess.DEVNULL)
        if not (proc.returncode and MPI_NOT_STARTED in proc.stdout + proc.stderr):
            break
    if proc.returncode == 0:
        return None
    said = (proc.stdout + proc.stderr).strip().splitlines()
    return next((ln for ln in said if "ERROR" in ln), said[-1] if said else f"status {proc.returncode}")


def _same_stop(audit: str, engine: str) -> bool:
    """Whether the audit's refusal quotes the engine's stop: the message after the audit's "stops
    here: " (up to any bracketed source place) is in the engine's own."""
    said = audit.split("stops here:", 1)[-1].strip()
    said = re.split(r" \(\S+\.cpp:\d+\)", said)[0].strip().rstrip(".")
    return bool(said) and said[:60] in engine


def check_liggghts_deck_case(text, speeds, types):
    """check_deck_case for a deck of liggghts_deck_cases, in LIGGGHTS."""
    return check_deck_case(text, speeds, types, "liggghts")


def _with_exact_line(text: str, line: str, code: str) -> str:
    """The deck with a pair's exact line in force: a later pair_coeff (LAMMPS), or the
    coefficientRestitution fix replaced (LIGGGHTS)."""
    if code == "lammps":
        return text + line + "\n"
    return "\n".join(line if "coefficientRestitution" in ln else ln for ln in text.splitlines()) + "\n"


def check_deck_case(text: str, speeds: list, types: dict, code: str = "lammps", exact: tuple | None = None) -> list[dict]:
    """Every type pair of the deck in the real engine (LAMMPS or LIGGGHTS), head-on at both speeds,
    with the deck's own contact lines: where the audit gives eps, the engine extrapolated to dt = 0
    must agree to DECK_EXTRAPOLATED; where it says the spheres stick, the engine must keep them
    together (or let them go with eps below DECK_STICK_EPS). Where the audit writes a pair's exact
    line (the e that gives eps = the e typed, at the middle speed), the deck with that line is
    checked the same way for that pair alone (``exact``: the pair and the eps it must give): the
    audit must now say eps = e, and the engine agree. Every type on the deck's wall likewise, a
    sphere of that type falling onto the deck's own wall line, and its exact line (``exact`` =
    ("wall", type, e)) the same way. The referee of whether the deck runs is the engine itself
    (engine_stop): a refusal saying the engine stops is fair only where the engine, running the deck
    as written, stops with the message the audit quotes; an answered deck must run in it."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck
    from restitution.dem.pair import Pair

    case = {"deck": text, "speeds": speeds}
    lines = _engine_lines(text, code)
    engine = _lammps_runner(lines, len(types)) if code == "lammps" else _liggghts_runner(lines)
    engine_name = {"lammps": "LAMMPS", "liggghts": "LIGGGHTS"}[code]
    with tempfile.TemporaryDirectory() as tmp:
        deck = deck_folder(tmp, text)
        # the referee: the deck run as it is by the engine itself, apart from the audit's own run of
        # its scratch copy
        stop = engine_stop(deck, code)
        try:
            res = audit_deck(text, speeds, path=deck)
        except Exception as exc:  # noqa: BLE001
            ok = isinstance(exc, ParameterError) and one_line(exc)
            detail = "" if ok else "".join(traceback.format_exception_only(exc)).strip()
            if ok and f"{engine_name} stops" in str(exc):
                # a fair refusal only where the engine stops on the deck too, as the audit quotes it
                if stop is None:
                    ok, detail = False, f"the audit says {exc}, but {code} runs the deck"
                elif not _same_stop(str(exc), stop):
                    ok, detail = False, f"the audit says {exc}, but {code} stops otherwise: {stop}"
            return [{"method": f"deck ({code})", "rule": "-", "status": "refused" if ok else "FAIL", "ratio": 0.0,
                     "case": case, "detail": detail}]
    if stop is not None:
        return [{"method": f"deck ({code})", "rule": "-", "status": "FAIL", "ratio": 0.0, "case": case,
                 "detail": f"the audit answers, but {code} stops on the deck: {stop}"}]
    records = []
    for p in res["pairs"]:
        i, j = p["types"]
        if exact is not None and (i, j) != exact[:2]:
            continue
        rec = {"method": f"deck ({code})" + (": exact line" if exact else ""), "rule": p["end"], "case": case,
               "pair": f"{i}-{j}", "ratio": 0.0}
        pair = Pair.spheres(types[i]["radius"], types[j]["radius"], types[i]["density"], types[j]["density"])
        worst, detail, checked = _check_deck_row(p, pair, (i, j), engine, code, f"pair {i}-{j}")
        if exact is not None and p["eps"][0] is not None and abs(p["eps"][0] - exact[2]) > 1e-8:
            worst, detail = math.inf, (f"pair {i}-{j}: with its exact line the audit says eps {p['eps'][0]:.10g}, "
                                       f"not the e typed {exact[2]:.10g}")
        # "refused": nothing of this pair could be run (no eps, or too many steps)
        status = "FAIL" if worst > 1.0 else "answered" if checked or exact is not None else "refused"
        records.append({**rec, "status": status, "ratio": worst, "detail": detail if worst > 1.0 else ""})
        if exact is None and p["exact_line"]:
            middle = p["speeds"][len(p["speeds"]) // 2]
            records += check_deck_case(_with_exact_line(text, p["exact_line"], code), [middle], types, code,
                                       (i, j, p["typed_e"]))
    for w in res["walls"]:
        (t,) = w["types"]
        if exact is not None and exact[:2] != ("wall", t):
            continue
        worst, detail, checked = _check_deck_row(w, Pair.wall(types[t]["radius"], types[t]["density"]), (t,),
                                                 _wall_runner(text, code, len(types), types, w), code,
                                                 f"type {t} on wall {w['wall']}")
        if exact is not None and w["eps"][0] is not None and abs(w["eps"][0] - exact[2]) > 1e-8:
            worst, detail = math.inf, (f"type {t} on wall {w['wall']}: with its exact line the audit says eps "
                                       f"{w['eps'][0]:.10g}, not the e typed {exact[2]:.10g}")
        records.append({"method": f"deck ({code}): wall" + (": exact line" if exact else ""), "rule": w["end"],
                        "case": case, "pair": f"{t}-wall", "ratio": worst, "detail": detail if worst > 1.0 else "",
                        "status": "FAIL" if worst > 1.0 else "answered" if checked or exact else "refused"})
        if exact is None and w["exact_line"]:
            # LAMMPS: the wall's own line replaced (the deck's wall is the line starting "fix floor");
            # LIGGGHTS: the coefficientRestitution line, as for a pair
            fixed = ("\n".join(w["exact_line"] if ln.startswith("fix floor") else ln for ln in text.splitlines())
                     + "\n" if code == "lammps" else _with_exact_line(text, w["exact_line"], code))
            records += check_deck_case(fixed, [w["speeds"][len(w["speeds"]) // 2]], types, code,
                                       ("wall", t, w["typed_e"]))
    return records
