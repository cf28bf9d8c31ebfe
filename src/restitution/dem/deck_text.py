"""LAMMPS' input-script text, as the deck reader reads it: how a file becomes commands and words
(the tokenizer), how ``$x``, ``${name}`` and ``$(expression)`` are substituted, and the two formula
languages those expressions and ``if`` conditions are written in (the evaluator). What the commands
do, and which of them run, is :mod:`restitution.dem.deck_script`'s and :mod:`restitution.dem.deck`'s.

LAMMPS (22 Jul 2025, and LIGGGHTS, which shares its parser) reads a script as follows, and so
does :func:`logical_lines` with :func:`words`:

1. A line whose last printable character is ``&`` continues on the next, the ``&`` removed (even
   in a comment); a line with an odd number of triple quotes ``\"\"\"`` continues with its newline
   kept, so a triple-quoted text may span lines.
2. ``#`` starts a comment, except inside single, double or triple quotes.
3. ``$x``, ``${name}`` and ``$(expression)`` are replaced outside quotes (:func:`unquoted` applies
   a substitution there only, :func:`substituted` finds the references); a command such as ``if``
   or ``print`` may substitute its own quoted arguments later, when it runs.
4. The line is split into words at whitespace; a word in quotes is one word, quotes removed.

The formula languages: the equal-style expression (``variable NAME equal ...`` and ``$(...)``,
:func:`evaluate`) and the ``if`` command's condition (:func:`evaluate_boolean`, a smaller language:
no arithmetic).

Equal-style expressions follow LAMMPS' documented grammar (the ``variable`` command: numbers,
constants, math operators and functions), each rule checked against LAMMPS 22 Jul 2025 itself:

- operators, highest precedence first: unary ``-`` and ``!``; ``^``; ``* / %``; ``+ -``;
  ``< <= > >=``; ``== !=``; ``&&``; ``|| |^``. Every binary operator binds left to right, ``^``
  included (LAMMPS gives 2^3^2 = 64), and a unary operator binds tighter than ``^`` (-2^2 = 4,
  !2^0 = 1, 2^-1 = 0.5). Comparisons and logic give 1 or 0.
- constants PI, on/off, true/false, yes/no; ``v_name`` references to variables with a numeric value.
- functions sqrt exp ln log (base 10: log(100) = 2) abs sign sin cos tan asin acos atan atan2
  ceil floor round (LAMMPS' round is floor(x + 0.5): round(-2.5) = -2) ternary.
- where LAMMPS stops (divide by 0, modulo 0, sqrt or log of a negative, asin of 2, 0^-1) the
  expression has no value here either.

Anything else (thermo keywords such as ``step``, computes, fixes, group and region functions, the
seeded draws random() and normal(), the time-dependent ramp() and its kin, ``version``) is not
evaluated: :class:`Unevaluated` names the sub-expression and why, never a guess.
"""

from __future__ import annotations

import math
import re

__all__ = ["ScriptError", "TRIPLE", "segments", "logical_lines", "strip_comment", "unquoted", "words", "PLACEHOLDER",
           "placeholder", "substituted", "Unevaluated", "evaluate", "evaluate_boolean", "newer_syntax"]

#: LAMMPS' triple quote, which may span lines
TRIPLE = '"""'


# ---------------------------------------------------------------------------- words
class ScriptError(ValueError):
    """Why a line is not a command LAMMPS would run (the caller names the line)."""


def _segments(line: str):
    """(text, quote) pieces of ``line``: quote is "" outside quotes, else the quote that opened the
    piece (the quotes themselves belong to the quoted piece). LAMMPS' own scan: a quote anywhere,
    even inside a word, opens or closes."""
    out, start, quote, k = [], 0, "", 0
    while k < len(line):
        if not quote:
            opening = TRIPLE if line.startswith(TRIPLE, k) else line[k] if line[k] in "\"'" else ""
            if opening:
                if k > start:
                    out.append((line[start:k], ""))
                start, quote = k, opening
                k += len(opening)
                continue
        elif line.startswith(quote, k):
            k += len(quote)
            out.append((line[start:k], quote))
            start, quote = k, ""
            continue
        k += 1
    if start < len(line):
        out.append((line[start:], quote))
    return out


def segments(line: str) -> list[tuple[str, str]]:
    """(text, quote) pieces of ``line`` as LAMMPS scans it: quote is "" outside quotes, else the
    quote that opened the piece (the quotes belong to the piece).

    Parameters
    ----------
    line : str

    Returns
    -------
    list of (str, str)

    Examples
    --------
    >>> segments('if "${a} > 1" then "run 1"')
    [('if ', ''), ('"${a} > 1"', '"'), (' then ', ''), ('"run 1"', '"')]
    """
    return list(_segments(line))


def strip_comment(line: str) -> str:
    """``line`` up to its first ``#`` outside quotes."""
    kept = []
    for text, quote in _segments(line):
        if not quote and "#" in text:
            kept.append(text.split("#", 1)[0])
            break
        kept.append(text)
    return "".join(kept)


def logical_lines(text: str) -> list[tuple[int, str]]:
    """(number of the first physical line, command text) of every non-blank command in ``text``:
    continuations joined, comments removed, quotes kept."""
    out, pending, start = [], "", 0
    for n, raw in enumerate(text.splitlines(), 1):
        if not pending:
            start = n
        pending += raw
        if pending.count(TRIPLE) % 2:
            pending += "\n"          # an open triple quote: the text goes on, newline and all
            continue
        body = pending.rstrip()
        if body.endswith("&"):
            pending = body[:-1]
            continue
        line = strip_comment(pending).strip()
        pending = ""
        if line:
            out.append((start, line))
    if pending.strip() and strip_comment(pending).strip():
        out.append((start, strip_comment(pending).strip()))   # LAMMPS runs an unfinished last line too
    return out


def unquoted(line: str, substitute) -> str:
    """``line`` with ``substitute(text)`` applied to each piece outside quotes."""
    return "".join(text if quote else substitute(text) for text, quote in _segments(line))


def words(line: str) -> list[str]:
    """The words of a command: split at whitespace, a quoted text one word without its quotes.
    ScriptError where a quote is not closed, or a closing quote runs into more text (LAMMPS stops
    on both)."""
    out, k, n = [], 0, len(line)
    while k < n:
        if line[k].isspace():
            k += 1
            continue
        quote = TRIPLE if line.startswith(TRIPLE, k) else line[k] if line[k] in "\"'" else ""
        if quote:
            end = line.find(quote, k + len(quote))
            if end < 0:
                raise ScriptError(f"a {quote} quote is not closed (LAMMPS stops: unbalanced quotes)")
            after = end + len(quote)
            if after < n and not line[after].isspace():
                raise ScriptError(f"text runs on after a closing {quote} quote (LAMMPS stops: unbalanced quotes)")
            out.append(line[k + len(quote):end])
            k = after
        else:
            end = k
            while end < n and not line[end].isspace():
                end += 1
            out.append(line[k:end])
            k = end
    return out


# ---------------------------------------------------------------------------- substitution
#: ${name}, the start of $(expression) (its end is the balancing parenthesis: any depth), $x
_REFERENCE = re.compile(r"\$\{(\w+)\}|\$(\()|\$(\w)")
#: What a substitution leaves where a reference has no value: <unevaluated-variable-NAME> or
#: <unevaluated-expression-K>; a command that needs the number names the reason kept for it
PLACEHOLDER = re.compile(r"<unevaluated-(variable|expression)-(\w+)>")


def placeholder(kind: str, key) -> str:
    """The text a reference without a value leaves (``kind`` "variable" or "expression").

    Examples
    --------
    >>> placeholder("variable", "kn")
    '<unevaluated-variable-kn>'
    """
    return f"<unevaluated-{kind}-{key}>"


def _closing(text: str, k: int) -> int | None:
    """The index of the parenthesis that closes the one at text[k], or None."""
    depth = 0
    for j in range(k, len(text)):
        depth += {"(": 1, ")": -1}.get(text[j], 0)
        if depth == 0:
            return j
    return None


def substituted(text: str, variable, immediate) -> str:
    """``text`` with LAMMPS' references replaced: ``$x`` and ``${name}`` by ``variable(name)``,
    the immediate ``$(expression)`` (parentheses nested to any depth) by ``immediate(expression)``.
    An unbalanced ``$(`` is left as it is, with the rest of the text.

    Parameters
    ----------
    text : str
        A piece of a command outside quotes.
    variable, immediate : callable
        name -> its text; expression (as written between the parentheses) -> its text.

    Returns
    -------
    str

    Examples
    --------
    >>> substituted("pair_coeff * * hertz ${kn} $(2*(1+1)) $x", lambda n: n.upper(), lambda e: "4")
    'pair_coeff * * hertz KN 4 X'
    """
    out, k = [], 0
    while (m := _REFERENCE.search(text, k)) is not None:
        out.append(text[k:m.start()])
        if m.group(2) is None:
            out.append(variable(m.group(1) or m.group(3)))
            k = m.end()
            continue
        end = _closing(text, m.start(2))
        if end is None:               # unbalanced: left as it is (a number needed from it says so)
            out.append(text[m.start():])
            k = len(text)
            break
        out.append(immediate(text[m.end():end]))
        k = end + 1
    return "".join(out) + text[k:]


# ---------------------------------------------------------------------------- equal-style
class Unevaluated(ValueError):
    """An expression the reader gives no value: the message names the sub-expression and why."""


_NUMBER = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_LEX = re.compile(rf"\s*(?:(?P<num>{_NUMBER})(?![\w.])|(?P<name>[A-Za-z_]\w*(?:\[[^\]]*\])?)"
                  r"|(?P<op>\|\||\|\^|&&|==|!=|<=|>=|[-+*/%^<>!(),]))")
#: binary operators -> precedence (higher binds tighter); all bind left to right in LAMMPS
_BINARY = {"||": 1, "|^": 1, "&&": 2, "==": 3, "!=": 3, "<": 4, "<=": 4, ">": 4, ">=": 4, "+": 5, "-": 5,
           "*": 6, "/": 6, "%": 6, "^": 7}
_CONSTANTS = {"PI": math.pi, "on": 1.0, "off": 0.0, "true": 1.0, "false": 0.0, "yes": 1.0, "no": 0.0}


def _checked(name: str, domain, f):
    """f, refused (as LAMMPS stops on it) for an argument outside ``domain``."""
    def g(x):
        if not domain(x):
            raise Unevaluated(f"{name}({x:g}): LAMMPS stops (invalid argument)")
        return f(x)
    return g


_FUNCTIONS = {
    "sqrt": (1, _checked("sqrt", lambda x: x >= 0, math.sqrt)),
    "exp": (1, math.exp),
    "ln": (1, _checked("ln", lambda x: x > 0, math.log)),
    "log": (1, _checked("log", lambda x: x > 0, math.log10)),      # LAMMPS' log is base 10
    "abs": (1, abs),
    "sign": (1, lambda x: 1.0 if x >= 0 else -1.0),
    "sin": (1, math.sin), "cos": (1, math.cos), "tan": (1, math.tan),
    "asin": (1, _checked("asin", lambda x: -1 <= x <= 1, math.asin)),
    "acos": (1, _checked("acos", lambda x: -1 <= x <= 1, math.acos)),
    "atan": (1, math.atan), "atan2": (2, math.atan2),
    "ceil": (1, math.ceil), "floor": (1, math.floor),
    "round": (1, lambda x: math.floor(x + 0.5)),
    "ternary": (3, lambda x, y, z: y if x != 0.0 else z),
}
#: functions whose value depends on what the reader does not follow (a random generator's state,
#: the time step, the atoms): their reason
_NOT_EVALUATED = {"random": "a seeded random draw", "normal": "a seeded random draw",
                  **dict.fromkeys(("ramp", "stagger", "logfreq", "logfreq2", "logfreq3", "stride", "stride2",
                                   "vdisplace", "swiggle", "cwiggle"), "a function of the time step")}


def _lex(expr: str) -> list:
    tokens, k = [], 0
    while k < len(expr):
        if expr[k:].strip() == "":
            break
        m = _LEX.match(expr, k)
        if not m or m.end() == k:
            raise Unevaluated(f"{expr[k:].strip()[:20]!r}: not LAMMPS formula syntax")
        kind = m.lastgroup
        tokens.append((kind, m.group(kind)))
        k = m.end()
    return tokens


class _Parser:
    """Precedence climbing over the tokens of one expression, evaluated as it goes."""

    def __init__(self, expr: str, variables: dict):
        self.expr, self.variables, self.tokens, self.k = expr, variables, _lex(expr), 0

    def peek(self):
        return self.tokens[self.k] if self.k < len(self.tokens) else (None, None)

    def take(self, op: str) -> None:
        if self.peek() != ("op", op):
            raise Unevaluated(f"{op!r} expected in {self.expr.strip()!r}: not LAMMPS formula syntax")
        self.k += 1

    def expression(self, floor: int = 0) -> float:
        left = self.unary()
        while True:
            kind, op = self.peek()
            if kind != "op" or _BINARY.get(op, 0) <= floor:
                return left
            self.k += 1
            left = _binary(op, left, self.expression(_BINARY[op]), self.expr)

    def unary(self) -> float:
        kind, tok = self.peek()
        if kind == "op" and tok in ("-", "!"):
            self.k += 1
            x = self.unary()
            return -x if tok == "-" else float(x == 0.0)
        return self.primary()

    def primary(self) -> float:
        kind, tok = self.peek()
        self.k += 1
        if kind == "num":
            return float(tok)
        if kind == "op" and tok == "(":
            x = self.expression()
            self.take(")")
            return x
        if kind == "name":
            if self.peek() == ("op", "("):
                return self.call(tok)
            return self.name(tok)
        raise Unevaluated(f"{self.expr.strip()!r} ends or breaks off early: not LAMMPS formula syntax")

    def call(self, name: str) -> float:
        if name in _NOT_EVALUATED:
            raise Unevaluated(f"{name}(): {_NOT_EVALUATED[name]}, which the reader does not evaluate")
        if name not in _FUNCTIONS:
            raise Unevaluated(f"{name}(): a function the reader does not evaluate (a group, region or special "
                              "function, or none LAMMPS has)")
        self.k += 1
        args = [] if self.peek() == ("op", ")") else [self.expression()]
        while self.peek() == ("op", ","):
            self.k += 1
            args.append(self.expression())
        self.take(")")
        shown = f"{name}({', '.join(f'{a:g}' for a in args)})"
        nargs, f = _FUNCTIONS[name]
        if len(args) != nargs:
            raise Unevaluated(f"{shown}: {name} takes {nargs} argument(s) (LAMMPS stops)")
        return float(f(*args))

    def name(self, word: str) -> float:
        if word in _CONSTANTS:
            return _CONSTANTS[word]
        if word.startswith("v_") and "[" not in word:
            value = self.variables.get(word[2:])
            try:
                return float(value)
            except (TypeError, ValueError):
                why = "never defined" if word[2:] not in self.variables else "has no numeric value here"
                raise Unevaluated(f"{word}: variable {word[2:]} {why}") from None
        if word == "version":
            raise Unevaluated("version: the LAMMPS build's date, which the reader does not know")
        raise Unevaluated(f"{word}: a thermo keyword, compute, fix or vector reference the reader does not evaluate")


def _binary(op: str, a: float, b: float, expr: str) -> float:
    if op in ("/", "%") and b == 0.0:
        raise Unevaluated(f"{a:g} {op} 0 in {expr.strip()!r}: LAMMPS stops ({'divide by 0' if op == '/' else 'modulo 0'})")
    if op == "^":
        if a == 0.0 and b < 0.0:
            raise Unevaluated(f"0^{b:g} in {expr.strip()!r}: LAMMPS stops (invalid power expression)")
        try:
            return math.pow(a, b) if not (a < 0 and b != int(b)) else math.nan
        except OverflowError:
            return math.inf
    return {"+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: a / b,
            "%": lambda: math.fmod(a, b), "<": lambda: float(a < b), "<=": lambda: float(a <= b),
            ">": lambda: float(a > b), ">=": lambda: float(a >= b), "==": lambda: float(a == b),
            "!=": lambda: float(a != b), "&&": lambda: float(a != 0.0 and b != 0.0),
            "||": lambda: float(a != 0.0 or b != 0.0), "|^": lambda: float((a != 0.0) != (b != 0.0))}[op]()


def evaluate(expr: str, variables: dict | None = None) -> float:
    """An equal-style expression's value as LAMMPS computes it.

    Parameters
    ----------
    expr : str
        The formula, its ``${...}`` references already substituted (quotes around it are removed).
    variables : dict, optional
        name -> value (a number, a string holding one, or None where unknown) for ``v_name``.

    Returns
    -------
    float
        The value (finite).

    Raises
    ------
    Unevaluated
        Where the reader gives it no value; the message names the sub-expression and why.
    """
    text = expr.strip().strip("\"'")
    parser = _Parser(text, variables or {})
    try:
        value = parser.expression()
    except RecursionError:
        raise Unevaluated(f"{text[:40]!r}...: nested too deeply for the reader") from None
    if parser.k != len(parser.tokens):
        raise Unevaluated(f"{' '.join(t for _, t in parser.tokens[parser.k:])[:40]!r} after a complete formula in "
                          f"{text!r}: not LAMMPS formula syntax")
    if not math.isfinite(value):
        raise Unevaluated(f"{text!r} gives {value} (LAMMPS carries it on; no contact number can be)")
    return value


# ---------------------------------------------------------------------------- if conditions
#: LAMMPS' precedence of the Boolean operators (Variable's constructor): higher binds tighter
_BOOLEAN = {"||": 1, "|^": 1, "&&": 2, "==": 3, "!=": 3, "<": 4, "<=": 4, ">": 4, ">=": 4}
_TOKEN = re.compile(r"\s*(?:(?P<num>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(?![\w.])"
                    r"|(?P<str>[A-Za-z_]\w*)|(?P<op>\|\||\|\^|&&|==|!=|<=|>=|<|>|!|\(|\)))")


class _Undecided(Exception):
    """The condition holds something this reader does not evaluate, or LAMMPS would stop on it."""


def evaluate_boolean(text: str) -> bool | None:
    """The truth of an ``if`` condition, its variables already substituted, as LAMMPS decides it:
    numbers, and strings (a letter, then letters, digits and _) compared with == and !=; numbers
    compared with < <= > >= and combined with && || |^ (exclusive or) and !; parentheses. Any
    other text (arithmetic, a variable left unsubstituted, a string compared with a number, a
    lone string: LAMMPS stops on the last two) gives None: never a guess."""
    tokens, k = [], 0
    text = text.strip()
    while k < len(text):
        m = _TOKEN.match(text, k)
        if not m or m.end() == k:
            return None
        kind = m.lastgroup
        tokens.append((kind, float(m.group(kind)) if kind == "num" else m.group(kind)))
        k = m.end()
        while k < len(text) and text[k].isspace():
            k += 1
    try:
        value, rest = _condition(tokens, 0, 0)
        if rest != len(tokens) or isinstance(value, str):
            return None
    except (_Undecided, RecursionError):     # parentheses nested past Python's stack: not decided
        return None
    return value != 0.0


def newer_syntax(condition: str) -> str | None:
    """What in an ``if`` condition LIGGGHTS 3.8.0 (an older LAMMPS) stops on, "Invalid Boolean
    syntax" (checked in LIGGGHTS): a string operand, or |^; None where it has neither."""
    for m in _TOKEN.finditer(condition):
        if m.lastgroup == "str":
            return f"the string {m.group('str')} in an if condition"
        if m.group("op") == "|^":
            return "|^ in an if condition"
    return None


def _condition(tokens: list, k: int, floor: int):
    """Precedence climbing from tokens[k]: (value, next index); binary operators bind left to right."""
    left, k = _operand(tokens, k)
    while k < len(tokens) and tokens[k][0] == "op" and _BOOLEAN.get(tokens[k][1], 0) > floor:
        op = tokens[k][1]
        right, k = _condition(tokens, k + 1, _BOOLEAN[op])
        left = _compare(op, left, right)
    return left, k


def _operand(tokens: list, k: int):
    if k >= len(tokens):
        raise _Undecided
    kind, value = tokens[k]
    if kind == "op" and value == "!":
        inner, k = _operand(tokens, k + 1)
        if isinstance(inner, str):
            raise _Undecided
        return float(inner == 0.0), k
    if kind == "op" and value == "(":
        inner, k = _condition(tokens, k + 1, 0)
        if k >= len(tokens) or tokens[k] != ("op", ")") or isinstance(inner, str):
            raise _Undecided            # LAMMPS: a parenthesised lone string stops it too
        return inner, k + 1
    if kind == "op":
        raise _Undecided
    return value, k + 1


def _compare(op: str, a, b) -> float:
    if op in ("==", "!="):
        if isinstance(a, str) != isinstance(b, str):
            raise _Undecided            # LAMMPS stops: a string compared with a number
        return float((a == b) == (op == "=="))
    if isinstance(a, str) or isinstance(b, str):
        raise _Undecided                # LAMMPS stops: only == and != take strings
    return float({"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b, "&&": a != 0.0 and b != 0.0,
                  "||": a != 0.0 or b != 0.0, "|^": (a != 0.0) != (b != 0.0)}[op])
