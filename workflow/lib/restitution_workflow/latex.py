"""LaTeX text for the generated tables and sections: numbers, fractions, escaping, and the
plain-text notation of the library's notes (``Omega~ = c0 + c1 Omega``) set as mathematics.

Nothing here computes physics; it only formats what the pipeline computed.
"""

from __future__ import annotations

import math
import re
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal
from fractions import Fraction


# ------------------------------------------------------------------------------------- numbers
def sci(x, sig: int = 4) -> str:
    """x with `sig` significant digits; a\\times10^{b} outside [1e-3, 1e5); --- for None/NaN."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "---"
    if x == 0:
        return "0"
    mant, exp = f"{x:.{sig - 1}e}".split("e")
    e = int(exp)
    if -3 <= e < 5:
        text = f"{x:.{max(sig - 1 - e, 0)}f}"
        # in running text a bare "-" is a hyphen: math mode makes it a minus sign
        return rf"\ensuremath{{{text}}}" if x < 0 else text
    return rf"\ensuremath{{{mant}\times 10^{{{e}}}}}"


def outward(x, sig: int, *, upper: bool) -> float:
    """x rounded to `sig` significant digits away from the side it bounds.

    An upper bound ("at most", "up to", "below") is rounded towards +infinity, a lower bound
    ("at least") towards -infinity, so that the printed bound still holds: 1.106e-10 printed as an
    upper bound with two digits is 1.2e-10, not 1.1e-10; 2.796e-9 as a lower bound is 2.7e-9.

    Examples
    --------
    >>> outward(1.106e-10, 2, upper=True), outward(2.796e-9, 2, upper=False)
    (1.2e-10, 2.7e-09)
    >>> outward(0.0544, 2, upper=True), outward(9.96, 2, upper=True)
    (0.055, 10.0)
    """
    if x == 0 or not math.isfinite(x):
        return float(x)
    d = Decimal(repr(float(x)))
    quantum = Decimal(1).scaleb(d.adjusted() - sig + 1)
    return float(d.quantize(quantum, rounding=ROUND_CEILING if upper else ROUND_FLOOR))


def sci_up(x, sig: int = 2) -> str:
    """An upper bound x as `sci` prints it, rounded up (`outward`), so that it still bounds."""
    return sci(x if x is None else outward(x, sig, upper=True), sig)


def sci_down(x, sig: int = 2) -> str:
    """A lower bound x as `sci` prints it, rounded down (`outward`), so that it still bounds."""
    return sci(x if x is None else outward(x, sig, upper=False), sig)


def fixed_up(x, decimals: int = 4) -> str:
    """An upper bound x as `fixed` prints it, rounded up at its last decimal, so that it still bounds.

    Examples
    --------
    >>> fixed_up(1.46182, 3), fixed_up(1.0700, 2)
    ('1.462', '1.07')
    """
    return fixed(_quantize(x, decimals, upper=True), decimals)


def fixed_down(x, decimals: int = 4) -> str:
    """A lower bound x as `fixed` prints it, rounded down at its last decimal, so that it still bounds.

    Examples
    --------
    >>> fixed_down(1.40495, 3)
    '1.404'
    """
    return fixed(_quantize(x, decimals, upper=False), decimals)


def _quantize(x, decimals: int, *, upper: bool):
    if x is None or not math.isfinite(x):
        return x
    d = Decimal(repr(float(x))).quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_CEILING if upper else ROUND_FLOOR)
    return float(d)


def fixed(x, decimals: int = 4) -> str:
    """x with a fixed number of decimals (--- for None/NaN), a real minus sign in math mode."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "---"
    text = f"{x:.{decimals}f}"
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return rf"\ensuremath{{{text}}}" if text.startswith("-") else text


def frac_tex(q: Fraction) -> str:
    if q.denominator == 1:
        return rf"\ensuremath{{{q.numerator}}}"
    sign = "-" if q < 0 else ""
    return rf"\ensuremath{{{sign}{abs(q.numerator)}/{q.denominator}}}"


# ------------------------------------------------------------------------------------- text
_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
            "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}


def esc(text: str) -> str:
    """Plain text with LaTeX's special characters escaped."""
    return "".join(_SPECIAL.get(ch, ch) for ch in str(text))


_GREEK = {"Omega": r"\Omega", "tau": r"\tau", "Delta": r"\Delta", "eps": r"\varepsilon",
          "alpha": r"\alpha", "gamma": r"\gamma", "delta": r"\delta", "pi": r"\pi", "xi": r"\xi",
          "mu": r"\mu"}
#: Tokens that stand for one sign, as the named group that matched them.
_SIGNS = {"pm": r"\pm", "arrow": r"\to", "le": r"\le", "ge": r"\ge", "lt": "<", "gt": ">", "bar": "|",
          "approx": r"\approx", "sim": r"\sim"}
_SUB = r"(?:_(?:[0-9]+|[A-Za-z]+)|[0-9](?![0-9.]))"
_TOKEN = re.compile(
    r"(?P<graphics>\\includegraphics)"
    r"|(?P<sci>(?<![\w.])(?P<mant>[0-9]+(?:\.[0-9]+)?)e(?P<exp>[-+]?[0-9]+)(?![\w.]))"
    r"|(?P<sqrtp>sqrt\((?P<sqrtarg>[^()]*)\))"
    r"|(?P<sqrt>sqrt(?P<sqrtnum>[0-9]))"
    r"|(?P<func>\b(?:atanh|atan|tanh|tan|log|exp)\b)"
    r"|(?P<greek>(?<![A-Za-z])(?:Omega|tau|Delta|eps|alpha|gamma|delta|pi|xi|mu)(?![A-Za-z]))(?P<gtilde>~)?"
    r"(?P<gsub>" + _SUB + r")?(?P<gprime>'{1,2}(?!s\b))?"
    r"|(?P<sym>\b(?:x|D|c|G|H|v|g)(?![A-Za-z(]))(?P<stilde>~)?(?P<ssub>" + _SUB + r"|\*)?"
    r"(?P<sprime>'{1,2}(?!s\b))?"
    r"|(?P<times>(?<=[\w)])\*(?=[\w(]))"
    r"|(?P<pow>\^(?:\((?P<powarg>[^()]*(?:\([^()]*\)[^()]*)*)\)|(?P<pownum>-?[0-9.]+)))"
    r"|(?P<pm>\+-)"
    r"|(?P<arrow>->)"
    r"|(?P<le><=)"
    r"|(?P<ge>>=)"
    r"|(?P<minus>(?<![\w.)])-(?=[0-9]))"
    r"|(?P<bminus>(?<=\s)-(?=\s))"
    r"|(?P<lt><)"
    r"|(?P<gt>>)"
    r"|(?P<bar>\|)"
    r"|(?P<approx>(?:(?<=\s)|^)~(?=\s?[0-9]))"
    r"|(?P<sim>(?<=\s)~(?=\s))"
)


def _sub_tex(sub: str | None) -> str:
    if not sub:
        return ""
    if sub == "*":
        return "_*"
    s = sub.lstrip("_")
    if s == "t":  # sympy's Omega_t is Omega~
        return ""
    if len(s) > 1 and s.isalpha():  # eps_paper: a word as subscript
        return rf"_{{\mathrm{{{s}}}}}"
    return f"_{{{s}}}"


def _math(body: str) -> str:
    return rf"\({body}\)"


def _inner(text: str) -> str:
    """The math-mode version of a fragment (inside an exponent or a square root)."""
    out = []
    for chunk in re.split(r"(\\\(|\\\))", math_text(text)):
        if chunk not in (r"\(", r"\)"):
            out.append(chunk.replace(r"\textasciitilde{}", r"\sim ").replace(r"\_", "_"))
    return "".join(out)


def math_text(text: str) -> str:
    """The library's plain-text notation set for LaTeX: Omega~ -> tilde Omega, x1' -> x_1',
    ^(...) -> superscripts, +- -> pm, sqrt2 -> root; everything else escaped."""
    out, pos = [], 0
    for m in _TOKEN.finditer(text):
        out.append(esc(text[pos:m.start()]))
        pos = m.end()
        k = m.lastgroup
        if m.group("graphics"):
            out.append(r"\texttt{\textbackslash includegraphics}")
        elif m.group("sci"):   # 1.6e-08 as a number, not as text
            out.append(_math(rf"{m.group('mant')}\times 10^{{{int(m.group('exp'))}}}"))
        elif m.group("sqrtp") is not None:
            out.append(_math(rf"\sqrt{{{_inner(m.group('sqrtarg'))}}}"))
        elif m.group("sqrt"):
            out.append(_math(rf"\sqrt{{{m.group('sqrtnum')}}}"))
        elif m.group("func"):
            out.append(_math(rf"\operatorname{{{m.group('func')}}}"))
        elif m.group("greek"):
            base = _GREEK[m.group("greek")]
            tilde = m.group("gtilde") or (m.group("gsub") == "_t")
            base = rf"\tilde{base}" if tilde else base
            out.append(_math(base + _sub_tex(m.group("gsub")) + (m.group("gprime") or "")))
        elif m.group("sym"):
            base = m.group("sym")
            base = rf"\tilde {base}" if m.group("stilde") else base
            out.append(_math(base + _sub_tex(m.group("ssub")) + (m.group("sprime") or "")))
        elif m.group("pow"):
            arg = m.group("powarg") if m.group("powarg") is not None else m.group("pownum")
            out.append(_math(f"^{{{_inner(arg)}}}"))
        elif m.group("times"):
            out.append(r"\,")
        elif m.lastgroup in _SIGNS or m.group("minus") or m.group("bminus"):
            out.append(_math(_SIGNS.get(m.lastgroup, "-")))
        else:  # pragma: no cover
            raise AssertionError(k)
    out.append(esc(text[pos:]))
    return "".join(out)


def sentence(text: str) -> str:
    """A note as a sentence: capitalised first letter, final full stop."""
    text = text.strip()
    if not text:
        return text
    text = text[0].upper() + text[1:]
    return text if text.endswith((".", "!", "?")) else text + "."
