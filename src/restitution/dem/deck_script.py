"""LAMMPS' input-script language, apart from what its commands mean: how an ``if`` decides, and
which commands run (:class:`Script`: variables, ``include``, ``if``, ``jump``/``label``, ``next``,
``quit``). The deck reader (:mod:`restitution.dem.deck`) gives every other command its meaning for a
contact.

How a file becomes commands and words, the substitution of ``$x``, ``${name}`` and ``$(...)``, and
the formula languages of conditions and equal-style expressions are
:mod:`restitution.dem.deck_text`'s.
:func:`if_branches` splits an ``if`` command into its conditions and commands.
"""

from __future__ import annotations

import re

from .deck_text import (PLACEHOLDER, TRIPLE, ScriptError, Unevaluated, evaluate_boolean, logical_lines,
                        newer_syntax, placeholder, strip_comment, substituted, unquoted, words)

__all__ = ["LocatedError", "Script", "MAX_JUMPS", "MAX_DEPTH", "if_branches"]


def if_branches(args: list[str]) -> list[tuple[str | None, list[str]]]:
    """``if`` command's words after ``if`` (boolean then t1 t2 ... elif boolean f1 ... else e1 ...)
    as [(condition, commands)], the else branch with condition None; ScriptError where LAMMPS
    stops on its form (no then, a branch without commands)."""
    if len(args) < 3 or args[1] != "then":
        raise ScriptError("if needs: if boolean then command ... (LAMMPS stops: illegal if command)")
    branches, condition, k = [], args[0], 2
    while True:
        end = k
        while end < len(args) and args[end] not in ("elif", "else"):
            end += 1
        if end == k:
            raise ScriptError("a branch of if without a command (LAMMPS stops: illegal if command)")
        branches.append((condition, args[k:end]))
        if end == len(args):
            return branches
        if args[end] == "elif":
            if end + 1 >= len(args):
                raise ScriptError("elif without a condition (LAMMPS stops: illegal if command)")
            condition, k = args[end + 1], end + 2
        else:
            if branches[-1][0] is None:
                raise ScriptError("a second else (LAMMPS stops: illegal if command)")
            condition, k = None, end + 1


# ---------------------------------------------------------------------------- control flow
#: Jumps followed before a deck counts as a loop the reader does not finish
MAX_JUMPS = 10_000
#: include files (and jumps to other files) nested deeper than this are a loop
MAX_DEPTH = 16


class LocatedError(ScriptError):
    """A ScriptError with the line it belongs to: ``loc`` (file or None, line number), ``text``."""

    def __init__(self, why: str, loc, text: str):
        super().__init__(why)
        self.loc, self.text = loc, text


class _Quit(Exception):
    """LAMMPS' quit: nothing after it runs."""


class Script:
    """One pass through a deck as LAMMPS runs it: its variables (index, loop, string, world,
    universe, equal), ``include``, ``if``/``elif``/``else``, ``jump``/``label`` (a jump to another
    file leaves the current one, as LAMMPS replaces its input file), ``next`` (index and loop
    variables; an exhausted one skips the next jump) and ``quit``; every other command goes to
    ``execute``.

    Parameters
    ----------
    execute : callable
        ``execute(words, line, loc)`` for every other command that runs: its words (quotes
        removed), its substituted text and ``loc`` = (file name or None, line number).
    evaluate : callable
        ``evaluate(expression, variables)``: an equal-style expression's value; raises
        :class:`~restitution.dem.deck_text.Unevaluated` naming why it has none.
    note : callable
        ``note(loc, line, why)``: a line whose effect the reader does not know, never guessed.
    fetch : callable
        ``fetch(name, loc, line)``: the text of a file the deck names.
    inert : set
        Commands that cannot change what the caller reads: a branch of an ``if`` whose condition
        the reader cannot evaluate may hold only these (and variables, then unknown).
    """

    def __init__(self, execute, evaluate, note, fetch, inert=frozenset()):
        self.execute, self.evaluate, self.note, self.fetch, self.inert = execute, evaluate, note, fetch, inert
        self.variables: dict = {}       # name -> value (str or float), None where not evaluated
        # the placeholder a substitution leaves (<unevaluated-variable-NAME>, <unevaluated-expression-K>)
        # -> why it has no value: a command that needs the number names it
        self.reasons: dict = {}
        self._sequence: dict = {}       # index and loop variables: name -> [values, position]
        self._equal: dict = {}          # equal-style name -> expression, evaluated again after next
        self._skip_jump = False
        self.jumps = 0
        # (loc, line, what) of the first syntax LIGGGHTS 3.8.0 stops on (triple quotes, string
        # or |^ conditions): the caller knows only at the end which engine the deck is for
        self.newer = None

    def run(self, text: str) -> None:
        """Run the deck ``text`` (the file LAMMPS is started with) to its end or its quit."""
        try:
            self._file(text, None, 0, None)
        except _Quit:
            pass

    def substitute(self, text: str) -> str:
        """LAMMPS' substitution of $x, ${name} and the immediate $(expression): a variable without
        a known value is left as <unevaluated-variable-NAME> or <unevaluated-expression-K>, its reason
        in ``reasons`` (a command that needs it then says so)."""
        def immediate(expr):
            value, why = self._value(expr.split(":")[0])    # $(expr:format)
            if why is None:
                return repr(value)
            mark = placeholder("expression", len(self.reasons))
            self.reasons[mark] = f"$({expr}): {why}"
            return mark

        def variable(name):
            if self.variables.get(name) is None:
                self.reasons.setdefault(_mark(name), "never defined" if name not in self.variables else
                                        "it has no value here")
                return _mark(name)
            value = self.variables[name]
            return repr(value) if isinstance(value, float) else str(value)
        return substituted(text, variable, immediate)

    def _file(self, text: str, source, depth: int, label, loc=None, line: str = "") -> None:
        """Run a file from its top, or from ``label`` (the jump at ``loc``, ``line`` named where absent)."""
        lines = logical_lines(text)
        labels = _labels(lines)
        k = 0 if label is None else _after_label(labels, label, loc, line)
        while k < len(lines):
            n, raw = lines[k]
            k += 1
            jump = self._command(raw, (source, n), depth)
            if jump is None:
                continue
            name, target, loc, line = jump
            self.jumps += 1
            if self.jumps > MAX_JUMPS:
                raise LocatedError(f"more than {MAX_JUMPS} jumps: a loop the reader does not finish", loc, line)
            if name != "SELF":
                self._enter(name, loc, line, depth, target)
                return                   # LAMMPS reads the other file in place of this one
            k = 0 if target is None else _after_label(labels, target, loc, line)

    def _enter(self, name: str, loc, line: str, depth: int, label) -> None:
        if depth >= MAX_DEPTH:
            raise LocatedError(f"includes or jumps to other files nested deeper than {MAX_DEPTH}: a loop", loc, line)
        self._file(self.fetch(name, loc, line), name, depth + 1, label, loc, line)

    def _command(self, raw: str, loc, depth: int):
        """Run one command; a jump to follow as (file, label or None, loc, line), else None."""
        # runs of blanks outside quotes are one (the line as shown), as LAMMPS splits its words
        line = unquoted(strip_comment(raw), lambda text: re.sub(r"\s+", " ", self.substitute(text))).strip()
        if not line:
            return None
        if TRIPLE in line and self.newer is None:
            self.newer = (loc, line, "a triple-quoted text")
        try:
            w = words(line)
        except ScriptError as why:
            raise LocatedError(str(why), loc, line) from None
        cmd = w[0]
        if cmd == "if":
            return self._if(w, line, loc, depth)
        if cmd == "jump":
            return self._jump(w, line, loc)
        if cmd == "next":
            self._next(w, line, loc)
        elif cmd == "quit":
            raise _Quit
        elif cmd == "include" and len(w) == 2:
            self._enter(w[1], loc, line, depth, None)
        elif cmd == "variable" and len(w) >= 3:
            self._variable(w, line, loc)
        elif cmd != "label":
            self.execute(w, line, loc)
        return None

    def _jump(self, w: list, line: str, loc):
        if len(w) not in (2, 3):
            raise LocatedError("jump needs a file (or SELF) and at most a label", loc, line)
        if self._skip_jump:              # the jump after an exhausted next: the loop ends
            self._skip_jump = False
            return None
        if any("<unevaluated" in x for x in w[1:]):
            raise LocatedError("where this jump goes depends on a variable the reader does not evaluate", loc, line)
        return w[1], (w[2] if len(w) == 3 else None), loc, line

    def _if(self, w: list, line: str, loc, depth: int):
        try:
            branches = if_branches(w[1:])
        except ScriptError as why:
            raise LocatedError(str(why), loc, line) from None
        for k, (condition, commands) in enumerate(branches):
            if condition is not None:
                newer = newer_syntax(self.substitute(condition))
                if newer and self.newer is None:
                    self.newer = (loc, line, newer)
                truth = evaluate_boolean(self.substitute(condition))
                if truth is None:
                    self._undecided(branches[k:], condition, line, loc)
                    return None
                if not truth:
                    continue
            jump = None
            for command in commands:     # LAMMPS runs them all; a jump takes effect after
                jump = self._command(command, loc, depth) or jump
            return jump
        return None

    def _undecided(self, branches: list, condition: str, line: str, loc) -> None:
        """An if whose condition the reader cannot evaluate: harmless where every command it might
        run is inert (variables it sets become unknown), else the deck is refused."""
        assigned = []
        for _, commands in branches:
            for command in commands:
                try:
                    w = words(strip_comment(command))
                except ScriptError:
                    w = [command]
                if w and w[0] == "variable" and len(w) >= 2:
                    assigned.append(w[1])
                elif w and w[0] not in self.inert:
                    shown = " ".join(condition.split())
                    raise LocatedError(f"which commands run depends on the condition \"{shown}\", which the reader "
                                       f"cannot evaluate, and a branch runs {w[0]}: not guessed", loc, line)
        for name in assigned:
            self.variables[name] = None
            self.reasons[_mark(name)] = f"set in a branch of the if at line {loc[1]}, whose condition the reader " \
                                        "cannot evaluate"
            self._sequence.pop(name, None)
            self._equal.pop(name, None)
        self.note(loc, line, "condition not evaluated; its branches change no contact"
                  + (f" (variables {', '.join(assigned)} unknown after it)" if assigned else ""))

    def _variable(self, w: list, line: str, loc) -> None:
        name, style, args = w[1], w[2], w[3:]
        if style == "delete":
            for table in (self.variables, self._sequence, self._equal):
                table.pop(name, None)
            return
        if style in ("index", "loop", "world", "universe", "uloop") and name in self.variables:
            return            # LAMMPS ignores a second definition of these (the command line's -var wins)
        self._sequence.pop(name, None)
        self._equal.pop(name, None)
        value, why = None, f"variable style {style} is not evaluated"
        if style == "index" and args:
            self._sequence[name] = [args, 0]
        elif style == "loop" and args:
            values = _loop_values(args)
            if values is not None:
                self._sequence[name] = [values, 0]
        elif style in ("string", "world", "universe") and args:
            value = args[0]
        elif style == "uloop" and args:
            value = "1"
        elif style == "equal" and args:
            self._equal[name] = " ".join(args)
            value, why = self._value(self._equal[name])
        if name in self._sequence:
            value = self._sequence[name][0][0]
        self.variables[name] = value
        if value is None:
            self.reasons[_mark(name)] = why
            self.note(loc, line, f"variable not evaluated ({why})")
        self._refresh()

    def _value(self, expr: str):
        """(an equal-style expression's value, None), or (None, why it has none)."""
        m = PLACEHOLDER.search(expr)
        if m:                            # it substituted a variable without a value: that one's reason
            shown = f"${{{m.group(2)}}}" if m.group(1) == "variable" else "$(...)"
            return None, f"it uses {shown}, which has none: {self.reasons.get(m.group(0), 'no value here')}"
        try:
            return self.evaluate(expr, self.variables), None
        except Unevaluated as why:
            return None, str(why)

    def _next(self, w: list, line: str, loc) -> None:
        if len(w) < 2:
            raise LocatedError("next needs a variable (LAMMPS stops: illegal next command)", loc, line)
        for name in w[1:]:
            if name not in self._sequence:
                raise LocatedError(f"next {name}: the reader follows next on index and loop variables only (a loop "
                                   "may run again with values it does not know)", loc, line)
        for name in w[1:]:
            entry = self._sequence[name]
            entry[1] += 1
            if entry[1] < len(entry[0]):
                self.variables[name] = entry[0][entry[1]]
            else:                        # exhausted: LAMMPS deletes it and skips the next jump
                del self._sequence[name]
                self.variables.pop(name, None)
                self._skip_jump = True
        self._refresh()

    def _refresh(self) -> None:
        """Equal-style variables are evaluated where used: after next, with the new values."""
        for name, expr in self._equal.items():
            self.variables[name], why = self._value(expr)
            if why is not None:
                self.reasons[_mark(name)] = why


def _mark(name: str) -> str:
    """The placeholder a variable without a value leaves where it is substituted."""
    return placeholder("variable", name)


def _labels(lines: list) -> dict:
    """label -> index of the line after its first ``label`` command: LAMMPS searches from the top."""
    out = {}
    for k, (_, raw) in enumerate(lines):
        if not raw.startswith("label"):
            continue
        try:
            w = words(raw)
        except ScriptError:
            continue
        if len(w) >= 2 and w[0] == "label":
            out.setdefault(w[1], k + 1)
    return out


def _after_label(labels: dict, label: str, loc, line: str) -> int:
    if label not in labels:
        raise LocatedError(f"label {label} is not in the file (LAMMPS stops: label wasn't found)", loc, line)
    return labels[label]


def _loop_values(args: list):
    """loop N [pad] (1..N) or loop N1 N2 [pad] (N1..N2), pad giving each the width of the last;
    None where the bounds are not integers."""
    pad = args[-1] == "pad"
    bounds = args[:-1] if pad else args
    if not 1 <= len(bounds) <= 2 or not all(re.fullmatch(r"\d+", b) for b in bounds):
        return None
    lo, hi = (1, int(bounds[0])) if len(bounds) == 1 else (int(bounds[0]), int(bounds[1]))
    if hi < lo:
        return None                      # LAMMPS stops on it
    width = len(str(hi)) if pad else 0
    return _Loop(lo, hi, width)


class _Loop:
    """A loop variable's values as strings, without listing them (a loop may count to 10^9)."""

    def __init__(self, lo: int, hi: int, width: int):
        self.lo, self.hi, self.width = lo, hi, width

    def __len__(self) -> int:
        return max(0, self.hi - self.lo + 1)

    def __getitem__(self, k: int) -> str:
        return str(self.lo + k).zfill(self.width)
