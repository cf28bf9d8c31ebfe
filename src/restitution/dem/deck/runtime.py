"""What a pass with its runs skipped cannot tell: a command after a run that reads a value the run
would have changed.

The engine runs the deck with every run skipped (LAMMPS) or one step long (LIGGGHTS), so time,
step, energies, positions and computes keep their values from before the runs. A command after a
run that substitutes such a value (an ``if`` whose condition reads ``${t}`` of ``variable t equal
time``, a ``pair_coeff`` from ``$(step*...)``) then takes another value, or another branch, than in
the real simulation, and the stages the audit reads may not be the ones the deck runs. The audit
cannot know the value, but it can tell which commands depend on one, from the deck's own variable
definitions as the engine executed them, and say so.

A reference counts as fixed by the run only where it provably is: a variable of a style the engine
sets once (index, loop, string, world, ...), or an equal-style formula of numbers, math functions
and such variables. Anything else (a thermo keyword, a compute, a fix, an atom value, a style this
module does not know) counts as run-dependent: a needless warning costs a line of stderr, a missing
one a wrong answer given as right.
"""

from __future__ import annotations

import re

__all__ = ["run_dependent", "read_in_run", "IN_RUN_ONLY", "boundary_faces", "resized_by_runs", "lost_in_runs", "stops_in_runs", "fixed_face", "constant_in_time", "CLOCK"]

#: Variable styles whose value is set when defined or by ``next``, never by a run (``format``
#: is not one: it formats an equal-style variable when used).
_FIXED_STYLES = frozenset({"index", "loop", "world", "universe", "uloop", "string", "getenv"})
#: Names an equal-style formula may hold without reading the simulation's state (LAMMPS' step
#: functions, logfreq, stride, vdisplace, swiggle and cwiggle, read the step: not among them).
_MATH = frozenset({"sqrt", "exp", "ln", "log", "abs", "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
                   "ceil", "floor", "round", "ternary", "PI", "version", "random", "normal"})
#: Functions that draw a new value at each evaluation
_DRAWN = frozenset({"random", "normal"})
_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_NUMBER = re.compile(r"(?<![A-Za-z0-9_.])(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
#: Commands after a run whose substituted values cannot change what the audit reads: outputs (the
#: pass writes none) and the runs themselves (their own checks). Every other command is watched: a
#: file an include or jump names, a label, a group's atoms (field round 28, V81: ``include
#: k$(step).in`` read k0.in in the pass, k3000.in in LAMMPS; V84: ``group g id $(step/1500)``).
_UNWATCHED = frozenset({"print", "thermo", "thermo_style", "thermo_modify", "dump", "dump_modify", "undump",
                        "write_dump", "write_data", "write_restart", "write_coeff", "restart", "log", "echo",
                        "shell", "python", "run", "rerun", "minimize", "min_style", "min_modify", "clear",
                        "quit", "next"})


def _references(text: str, formula: bool = True) -> tuple[list, list, str]:
    """(variable names referenced, immediate formulas, the text without them): ``${name}``, ``$x``,
    ``$(formula)`` with its parentheses balanced and its ``:format`` dropped, and in a formula
    ``v_name`` (in a command the engine reads ``v_name`` while it runs, unaffected by the skip)."""
    names, formulas, rest, i = [], [], [], 0
    while i < len(text):
        if text.startswith("$(", i):
            depth, j = 0, i + 1
            while j < len(text):
                depth += {"(": 1, ")": -1}.get(text[j], 0)
                if depth == 0:
                    break
                j += 1
            inner = text[i + 2:j]
            formulas.append(inner.rsplit(":%", 1)[0] if ":%" in inner else inner)
            i = j + 1
        elif text.startswith("${", i):
            j = text.find("}", i)
            j = len(text) if j < 0 else j
            names.append(text[i + 2:j])
            i = j + 1
        elif text[i] == "$" and i + 1 < len(text):
            names.append(text[i + 1])
            i += 2
        elif formula and text.startswith("v_", i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = _NAME.match(text, i + 2)
            names.append(m.group(0) if m else "")
            i = m.end() if m else i + 2
        else:
            rest.append(text[i])
            i += 1
    return names, formulas, "".join(rest)


#: What a pass whose step and time are set after each skipped run to those the deck's run reaches
#: (a clocked pass) reads as the deck's own run does
CLOCK = frozenset({"step", "time", "dt"})
#: The commands that write a file the copy keeps for the deck's later reads, and name it by the
#: step where its name holds a ``*`` (LAMMPS measured: ``write_data d.*`` at step 10 wrote d.10)
STEP_NAMED = frozenset({"write_restart", "write_data"})


def _fixed(text: str, styles: dict, seen: frozenset = frozenset(), allowed: frozenset = _MATH) -> bool:
    """Whether every substitution in the command ``text`` is fixed by the run."""
    names, formulas, _ = _references(text, formula=False)
    return (all(_variable_fixed(n, styles, seen, allowed) for n in names)
            and all(_formula_fixed(f, styles, seen, allowed) for f in formulas))


def _variable_fixed(name: str, styles: dict, seen: frozenset, allowed: frozenset = _MATH) -> bool:
    if name in seen or name not in styles:
        return False                          # circular, or defined where this pass did not see it
    style, formula = styles[name]
    if style in _FIXED_STYLES:
        return True
    return style == "equal" and _formula_fixed(formula, styles, seen | {name}, allowed)


def _formula_fixed(formula: str, styles: dict, seen: frozenset, allowed: frozenset = _MATH) -> bool:
    names, formulas, bare = _references(formula)
    return (all(_variable_fixed(n, styles, seen, allowed) for n in names)
            and all(_formula_fixed(f, styles, seen, allowed) for f in formulas)
            and all(n in allowed for n in _NAME.findall(_NUMBER.sub(" ", bare))))


def constant_in_time(token: str, formulas: dict) -> bool:
    """Whether a value the engine reads as ``v_NAME`` (or a number) keeps one value at every step.

    Stricter than fixed by the run: ``random`` and ``normal`` draw anew at each evaluation.

    Parameters
    ----------
    token : str
        A number or ``v_NAME``.
    formulas : dict
        Variable name -> its equal-style formula (None for another style).

    Returns
    -------
    bool
        True for a number, or an equal-style variable of numbers, math functions and such variables.

    Examples
    --------
    >>> constant_in_time("v_a", {"a": "2*sqrt(v_b)", "b": "4"}), constant_in_time("v_t", {"t": "0.1*time"})
    (True, False)
    >>> constant_in_time("v_r", {"r": "random(0,1,5)"}), constant_in_time("0.5", {})
    (False, True)
    """
    if _NUMBER.fullmatch(token.lstrip("+-")):
        return True
    styles = {k: ("equal", f) for k, f in formulas.items() if f is not None}
    return token.startswith("v_") and _variable_fixed(token[2:], styles, frozenset(), _MATH - _DRAWN)


def run_dependent(commands: list, source: dict | None = None, clocked: bool = False) -> list:
    """The commands after a run whose substituted values may depend on the runs the pass skipped
    (``clocked``: where the pass set its step and time after each run to the deck's, those not).

    Parameters
    ----------
    commands : list of Executed
        The commands as the engine ran them (:func:`restitution.dem.deck.stream.executed`), with
        ``stage`` set on the runs.
    source : dict, optional
        (file, line) -> the deck's text of that line, before substitution; a command's own text
        where a line is missing.

    Returns
    -------
    list of (tuple, str)
        ((file, line), text before substitution) of each such command, each line once, in the
        order the engine first ran it.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 1), "variable t equal time"), Executed((None, 2), "variable i loop 3"),
    ...         Executed((None, 3), "run 10", stage=0), Executed((None, 4), 'if "${i} > 1" then quit'),
    ...         Executed((None, 5), 'if "${t} > 0.1" then "jump SELF done"')]
    >>> run_dependent(cmds)
    [((None, 5), 'if "${t} > 0.1" then "jump SELF done"')]
    >>> run_dependent(cmds, clocked=True)
    []

    A fix halt may end a run early, so a clocked pass's step after it is not the deck's:

    >>> halted = cmds[:2] + [Executed((None, 6), "fix h all halt 10 v_t > 1"), *cmds[2:]]
    >>> [loc for loc, _ in run_dependent(halted, clocked=True)]
    [(None, 5)]

    A file named by the step (its ``*``) after a run:

    >>> written = cmds[2:3] + [Executed((None, 7), "write_restart r.*"), Executed((None, 8), "write_data d.0")]
    >>> run_dependent(written), run_dependent(written, clocked=True)
    ([((None, 7), 'write_restart r.*')], [])
    >>> run_dependent(cmds[2:3] + [Executed((None, 9), "write_restart r.*")], {(None, 9): "write_restart ${f}"})
    [((None, 9), 'write_restart ${f}')]
    """
    allowed = _MATH | CLOCK if clocked else _MATH
    source = source or {}
    styles: dict = {}
    # a fix halt may end a run before its last step: the step and time after it are not those a
    # clocked pass sets (the deck's run to its end)
    halts: set = set()
    # a loop runs the same lines over and over: a line is checked again only where a variable
    # definition changed since its last check (``version`` counts the changes)
    version, checked = 0, {}
    after_run, found, seen = False, [], set()
    for cmd in commands:
        text = source.get(cmd.loc, cmd.text)
        split = text.split()
        if not split:
            continue
        if split[0] == "run" and cmd.stage is None:
            # a command a run's every runs between its parts, known by the run's line: its own text
            # there, before substitution (field round 28, V63: variable s equal $(step) redefining
            # an s defined before the run was read as the echoed number, fixed)
            text = _every_command(text, cmd.text, lambda c: _fixed(c, styles, allowed=allowed))
            split = text.split()
        if split[0] == "variable" and len(split) >= 3 and cmd.stage is None:
            # the text before substitution: an immediate $() in a definition is read as the
            # formula it substitutes, so run-dependent where that is
            definition = None if split[2] == "delete" else (split[2], " ".join(split[3:]))
            if styles.get(split[1]) != definition:
                version += 1
                if definition is None:
                    styles.pop(split[1], None)
                else:
                    styles[split[1]] = definition
        if split[0] == "unfix" and len(split) > 1 or split[0] == "fix" and len(split) > 1:
            halts.discard(split[1])
            if split[0] == "fix" and len(split) > 3 and split[3] == "halt":
                halts.add(split[1])
        if cmd.stage is not None:
            after_run = True
            if halts and allowed is not _MATH:
                allowed, version = _MATH, version + 1
        elif after_run and "step" not in allowed and any(
                said[:1] and said[0] in STEP_NAMED and "*" in " ".join(said[1:2]) for said in (split, cmd.text.split())):
            # (as written, or as the engine ran it: a branch of an if, a name from a variable: field
            # round 37, R26 R27)
            # the engine puts the step in place of the *, and a later read (``read_restart r.*``, the
            # largest step; a name written out) finds the file by it (field round 36, M15: two files
            # of the pass's step 0, one overwriting the other, where LAMMPS wrote r.1000 and r.0)
            if (cmd.loc, text) not in seen:
                seen.add((cmd.loc, text))
                found.append((cmd.loc, text))
        elif after_run and split[0] not in _UNWATCHED and (cmd.loc, text) not in seen \
                and checked.get((cmd.loc, text)) != version:
            checked[(cmd.loc, text)] = version
            if not _fixed(text, styles, allowed=allowed):
                seen.add((cmd.loc, text))
                found.append((cmd.loc, text))
    return found


#: What a formula reads that LAMMPS gives only inside a run: a function of the run's own start and
#: end (a ramp, a wiggle, the steps elapsed), or a compute's or fix's value, current there
IN_RUN_ONLY = re.compile(r"\b(?:ramp|vdisplace|swiggle|cwiggle)\s*\(|\belap(?:sed|long)\b|\b(?:[cf]|[id]2?)_\w")


def _reads_in_run(text: str, styles: dict, seen: frozenset = frozenset()) -> bool:
    """Whether ``text``, through its substitutions and the variables they (or its ``v_`` words)
    name, reads a value LAMMPS gives only inside a run (:data:`IN_RUN_ONLY`)."""
    names, formulas, _ = _references(text)
    if any(IN_RUN_ONLY.search(f) for f in formulas):
        return True
    for name in names:
        if name in seen or name not in styles:
            continue
        style, formula = styles[name]
        if IN_RUN_ONLY.search(formula) or _reads_in_run(formula, styles, seen | {name}):
            return True
    return False


def read_in_run(commands: list, source: dict, parted: set) -> tuple | None:
    """The first command a run's ``every`` runs between the parts of a run the copy made as its parts
    (its line among ``parted``) that reads a value LAMMPS gives only inside a run, directly or
    through a variable: a ramp, a wiggle, the steps elapsed, a compute's value. The copy runs such a
    command between runs of its own, where that value is another (field round 34: a ramp(1000,3000)
    read through ${k} gave 1000 in the copy, 3000 in LAMMPS' run). ((file, line), text as written)
    or None.

    Parameters
    ----------
    commands : list of Executed
        The commands as the engine ran them, ``stage`` set on the runs.
    source : dict
        (file, line) -> the deck's text of that line, before substitution.
    parted : set
        The (file, line) of each run the copy made as its parts.

    Returns
    -------
    tuple or None

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> run = 'run 20 every 10 "pair_coeff * * hooke ${k} 0"'
    >>> cmds = [Executed((None, 1), "variable k equal ramp(1,3)"), Executed((None, 2), "run 10", stage=0),
    ...         Executed((None, 2), "pair_coeff * * hooke 1 0")]
    >>> read_in_run(cmds, {(None, 1): "variable k equal ramp(1,3)", (None, 2): run}, {(None, 2)})
    ((None, 2), 'pair_coeff * * hooke ${k} 0')
    >>> read_in_run(cmds[1:], {(None, 2): run}, {(None, 2)}) is None
    True
    """
    styles: dict = {}
    for cmd in commands:
        text = source.get(cmd.loc, cmd.text)
        split = text.split()
        if not split:
            continue
        if split[0] == "run" and cmd.stage is None and cmd.loc in parted:
            written = _every_command(text, cmd.text, lambda c: not _reads_in_run(c, styles))
            if _reads_in_run(written, styles):
                return cmd.loc, written
            split = written.split()
        if split[0] == "variable" and len(split) >= 3 and cmd.stage is None:
            if split[2] == "delete":
                styles.pop(split[1], None)
            else:
                styles[split[1]] = (split[2], " ".join(split[3:]))
    return None


def _every_command(run: str, echoed: str, fixed=None) -> str:
    """The command of ``run ... every M c1 c2 ...`` as written whose first two words are the echoed
    command's (the engine echoes it substituted), else its first word; the echoed text where none
    is. Of several such
    (``pair_coeff 1 2`` twice), the first that ``fixed`` (a test of a command's text) finds not
    fixed by the run: which of them the echo is, the substituted words do not tell.

    Examples
    --------
    >>> run = 'run 20 every 10 "pair_coeff 1 2 hooke 2000 0" "pair_coeff 1 2 hooke $(step) 0"'
    >>> _every_command(run, "pair_coeff 1 2 hooke 10 0")
    'pair_coeff 1 2 hooke 2000 0'
    >>> _every_command(run, "pair_coeff 1 2 hooke 10 0", lambda c: "$" not in c)
    'pair_coeff 1 2 hooke $(step) 0'
    >>> quoted = "'if " + '"$(step) > 15"' + " then quit'"
    >>> _every_command("run 20 every 10 " + quoted, 'if "20 > 15" then quit')
    'if "$(step) > 15" then quit'
    """
    from ..deck_text import ScriptError, words
    try:
        split = words(run)
    except ScriptError:
        return echoed
    k = split.index("every") if "every" in split else len(split)
    head = echoed.split()[:2]
    # (an if's condition is substituted in its second word: its first word alone tells it)
    alike = [c for c in split[k + 2:] if c.split()[:2] == head] or \
        [c for c in split[k + 2:] if c.split()[:1] == head[:1]]
    if not alike:
        return echoed
    return next((c for c in alike if fixed is not None and not fixed(c)), alike[0])


def resized_by_runs(commands: list) -> list:
    """The runs after a run in which a fix adapt changed the atoms' sizes as it went (``reset no``,
    the default, leaves them changed: LAMMPS fix adapt), whose sizes and masses are then those the
    run left, which a pass with its runs skipped (or one step long) never reaches.

    A fix adapt that gives its group one constant diameter counts not: its size is known before the
    run (:func:`restitution.dem.deck.beside.adapted_diameter`). A ``reset yes`` puts the sizes back.

    Parameters
    ----------
    commands : list of Executed
        The commands as the engine ran them, with ``stage`` set on the runs.

    Returns
    -------
    list of (tuple, str)
        ((file, line), text) of the first such run, with why, as :func:`run_dependent` gives its
        commands; empty where there is none.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 1), "variable d equal 0.004+0.02*time"),
    ...         Executed((None, 2), "fix ad all adapt 1 atom diameter v_d reset no"),
    ...         Executed((None, 3), "run 1000", stage=0), Executed((None, 4), "unfix ad"),
    ...         Executed((None, 5), "run 100", stage=1)]
    >>> resized_by_runs(cmds)
    [((None, 5), 'run 100, whose sizes are those the run at line 3 left, as fix adapt ad resized its atoms')]
    >>> resized_by_runs([Executed((None, 1), "variable d equal 0.006"), *cmds[1:]])
    []
    """
    from ..dialect.state import place
    from .beside import ADAPT, SETTING, adapt_parts
    formulas: dict = {}
    adapts: dict = {}
    setting: dict = {}       # the SETTING fixes in force
    grown = None
    for cmd in commands:
        split = cmd.text.split()
        if not split:
            continue
        if cmd.stage is not None:
            if setting:
                # its sizes, masses or types hold from the run's first steps on, never in a pass
                # whose runs are skipped (field round 15, n03b: a diameter set every step, audited at
                # the size before it: 0.4972 where LAMMPS gives 0.4691)
                return [(cmd.loc, f"{cmd.text.strip()}, in which fix {next(iter(setting))} sets its atoms' "
                                  "attributes or types as the run goes")]
            if grown is not None:
                return [(cmd.loc, f"{cmd.text.strip()}, whose sizes are those the run at {place(grown[0])} left, "
                                  f"as fix adapt {grown[1]} resized its atoms")]
            grown = next(((cmd.loc, fix) for fix in adapts), None)
        elif split[0] == "variable" and len(split) >= 3:
            formulas[split[1]] = " ".join(split[3:]) if split[2] == "equal" else None
        elif split[0] == "unfix" and len(split) > 1:
            adapts.pop(split[1], None)
            setting.pop(split[1], None)
        elif split[0] == "fix" and len(split) > 3:
            adapts.pop(split[1], None)
            setting.pop(split[1], None)
            if split[3] in SETTING:
                setting[split[1]] = True
                continue
            if split[3] not in ADAPT:
                continue
            parts, keys = adapt_parts(split)
            sized = [args for kind, args in parts if kind == "atom" and args[:1] != ["charge"]]
            if sized and keys.get("reset", "no") != "yes" and not (
                    keys.get("scale", "no") == "no" and len(sized) == len(parts)
                    and all(len(a) == 2 and a[0] == "diameter" and constant_in_time(a[1], formulas) for a in sized)):
                adapts[split[1]] = True
    return []


def lost_in_runs(commands: list) -> list:
    """The first run after a run in which atoms may have gone: lost through an open boundary where
    ``thermo_modify lost ignore`` or ``warn`` lets the engine go on, or removed by a ``fix
    evaporate``. The pass, its runs skipped, still holds them (field round 22, v01: a sphere that
    fell out of the box was audited beside the two the engine kept, and set atom N then picked
    another atom than the engine's, w06).

    Parameters
    ----------
    commands : list of Executed
        The commands as the engine ran them, with ``stage`` set on the runs.

    Returns
    -------
    list of (tuple, str)
        ((file, line), text) of that run, with why, as :func:`resized_by_runs` gives its runs;
        empty where there is none.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 1), "thermo_modify lost ignore"), Executed((None, 2), "run 1000", stage=0),
    ...         Executed((None, 3), "run 100", stage=1)]
    >>> lost_in_runs(cmds)
    [((None, 3), 'run 100, whose atoms are those the run at line 2 left, some perhaps lost (thermo_modify lost ignore)')]
    >>> lost_in_runs(cmds[1:])
    []
    """
    from ..dialect.state import place
    why, evaporating, last = None, set(), None
    for cmd in commands:
        split = cmd.text.split()
        if not split:
            continue
        if cmd.stage is not None:
            if last is not None:
                return [(cmd.loc, f"{cmd.text.strip()}, whose atoms are those the run at {place(last)} left, some "
                                  f"perhaps {last_why}")]
            cause = why or (f"removed by fix {next(iter(evaporating))} (evaporate)" if evaporating else None)
            if cause is not None:
                last, last_why = cmd.loc, cause
        elif split[0] == "thermo_modify" and "lost" in split[1:-1]:
            value = split[split.index("lost") + 1]
            why = f"lost ({cmd.text.strip()})" if value in ("ignore", "warn") else None
        elif split[0] == "unfix" and len(split) > 1:
            evaporating.discard(split[1])
        elif split[0] == "fix" and len(split) > 3:
            evaporating.discard(split[1])
            if split[3] == "evaporate":
                evaporating.add(split[1])
    return []


def stops_in_runs(commands: list) -> list:
    """The first run after a run in which the engine may have stopped, or lost atoms, where the
    pass (its runs skipped, or one step long) cannot tell: any run may end on an error in what it
    evaluates (field round 24, S16: a thermo variable dividing by zero), and in particular a box
    with a fixed (``f``) face, through
    which a sphere that leaves it is lost (LAMMPS stops, "Lost atoms", under its default
    ``thermo_modify lost error``; LIGGGHTS 3.8.0 drops it and goes on), and a ``fix halt`` whose
    ``error`` is ``hard`` (its default: the engine exits when its condition holds) or ``soft`` (the
    run ends there, and LAMMPS makes no step in any run after it). Field round 23, r22, R11, R12: the
    later stages of decks that LAMMPS stops in their first run were audited, L37: a
    sphere LIGGGHTS lost stayed in the audit.

    Parameters
    ----------
    commands : list of Executed
        The commands as the engine ran them, with ``stage`` set on the runs.

    Returns
    -------
    list of (tuple, str)
        ((file, line), text) of that run, with why, as :func:`lost_in_runs` gives its runs; empty
        where there is none.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 1), "boundary p p f"), Executed((None, 2), "run 1000", stage=0),
    ...         Executed((None, 3), "run 100", stage=1)]
    >>> stops_in_runs(cmds)
    [((None, 3), 'run 100, reached only if the run at line 2 keeps every sphere in the box (boundary p p f)')]
    >>> stops_in_runs([Executed((None, 1), "boundary p p sm")] + cmds[1:])[0][1]
    'run 100, reached only if the run at line 2 ends without an error'
    >>> stops_in_runs(cmds[1:2])
    []
    >>> halt = Executed((None, 1), "fix h all halt 10 v_t > 0.0005")
    >>> stops_in_runs([halt] + cmds[1:])[0][1]
    'run 100, reached only if the run at line 2 does not meet the condition of fix h (halt, error hard)'
    """
    from ..dialect.state import place
    boundary, halts, last = None, {}, None
    for cmd in commands:
        split = cmd.text.split()
        if not split:
            continue
        if cmd.stage is not None:
            if last is not None:
                return [(cmd.loc, f"{cmd.text.strip()}, reached only if the run at {place(last)} {last_why}")]
            if halts:
                fix, style = next(iter(halts.items()))
                last, last_why = cmd.loc, f"does not meet the condition of fix {fix} (halt, error {style})"
            elif boundary is not None:
                last, last_why = cmd.loc, f"keeps every sphere in the box ({boundary})"
            else:
                # anything the run evaluates may stop it (round 24, S16: a thermo variable dividing
                # by zero at step 50): that the engine ends it is seen only where it is made
                last, last_why = cmd.loc, "ends without an error"
        elif (fixed := _fixed_after(split)) is not None:
            boundary = cmd.text.strip() if fixed else None
        elif split[0] == "unfix" and len(split) > 1:
            halts.pop(split[1], None)
        elif split[0] == "fix" and len(split) > 3:
            halts.pop(split[1], None)
            if split[3] == "halt":
                # hard (its default) exits; soft ends the run and LAMMPS skips every later run
                # (field round 23, R12); continue goes on as if nothing happened
                style = split[split.index("error") + 1] if "error" in split[:-1] else "hard"
                if style in ("hard", "soft"):
                    halts[split[1]] = style
    return []


def fixed_face(commands: list) -> bool:
    """Whether the box has a fixed (``f``) face at any run, through which a sphere is lost.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> fixed_face([Executed((None, 1), "boundary p p fm"), Executed((None, 2), "run 10", stage=0)])
    True
    >>> fixed_face([Executed((None, 1), "boundary p p m"), Executed((None, 2), "run 10", stage=0)])
    False
    """
    boundary = False
    for cmd in commands:
        split = cmd.text.split()
        if cmd.stage is not None and boundary:
            return True
        if (fixed := _fixed_after(split)) is not None:
            boundary = fixed
    return False


def _fixed_after(split: list) -> bool | None:
    """Whether the box has a fixed face after a ``boundary`` or ``change_box ... boundary`` command
    (only a plain ``f`` loses atoms: ``p`` wraps them, ``s`` and ``m`` follow them); None for any
    other command."""
    faces = boundary_faces(split)
    return None if faces is None else "f" in faces


def boundary_faces(split: list) -> list | None:
    """The six faces' letters a ``boundary`` or ``change_box ... boundary`` command sets, None for
    any other command.

    Parameters
    ----------
    split : list of str
        The command's words.

    Returns
    -------
    list of str or None

    Examples
    --------
    >>> boundary_faces("boundary p p fm".split()), boundary_faces("change_box all boundary f f p".split())
    (['p', 'p', 'p', 'p', 'f', 'm'], ['f', 'f', 'f', 'f', 'p', 'p'])
    >>> boundary_faces("run 10".split()) is None
    True
    """
    if split[:1] == ["boundary"]:
        return _faces(split[1:])
    if split[:1] == ["change_box"] and "boundary" in split:
        k = split.index("boundary")
        return _faces(split[k + 1:k + 4])
    return None


def _faces(words: list) -> list:
    """The six faces of a boundary's three words (``p``, ``fm``, ``f``: one letter for both faces)."""
    out = []
    for word in words[:3]:
        out += [word[0], word[-1]] if word else []
    return out
