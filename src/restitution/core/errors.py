"""One exception type for every user mistake, so front ends can print one line and exit 2."""

from __future__ import annotations

import math


class ParameterError(ValueError):
    """A user-supplied value is outside what the model or a method supports.

    The message always names the field and the allowed range, so the CLI and the
    workflow can show it as a single line without a traceback. A subclass of ValueError.

    Parameters
    ----------
    field : str
        The argument or configuration field at fault (e.g. ``"D1"``).
    value : object
        The value given.
    allowed : str
        What would have been accepted, in words.

    Attributes
    ----------
    field, value, allowed
        The three parameters, kept for callers that report them their own way.

    Examples
    --------
    >>> from restitution import Material, ParameterError
    >>> try:
    ...     Material("3/2", 1, D1=-1.0, D2=0.01)
    ... except ParameterError as err:
    ...     print(err)
    ...     print(err.field)
    D1 = -1.0: must be a finite number > 0
    D1
    """

    def __init__(self, field: str, value: object, allowed: str):
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {value!r}: {allowed}")


class InputFileError(ParameterError):
    """A file the user gives (a DEM deck, a materials file) holds something that cannot be mapped,
    or lacks something: one line naming where, what stands there and why.

    The readers of each kind of file raise a subclass of their own, which may show the three its
    own way.

    Parameters
    ----------
    where : str
        Where in the file: a line ("line 12") or a field or setting ("radius").
    text
        What stands there (a line, a value), or None.
    why : str
        What cannot be mapped, what is missing, or what is allowed.

    Examples
    --------
    >>> err = InputFileError("radius", -0.5, "must be a finite number > 0")
    >>> print(err)
    radius = -0.5: must be a finite number > 0
    >>> isinstance(err, ParameterError), err.field
    (True, 'radius')
    """

    def __init__(self, where: str, text, why: str):
        super().__init__(where, text, why)


def _not_a_number(x) -> bool:
    """Values Python or numpy would quietly turn into a float: True (1), "0.5", a complex (its
    imaginary part dropped). The API takes the CLI's rules: numbers only."""
    return isinstance(x, (bool, str, bytes, complex)) or type(x).__name__ in ("bool_", "str_", "bytes_") \
        or (hasattr(x, "dtype") and getattr(x.dtype, "kind", "f") not in "iuf")


def real_array(field: str, value, allowed: str):
    """``value`` (a number or a sequence or array of numbers) as a float array, or ParameterError."""
    import numpy as np

    items = value if isinstance(value, (list, tuple)) else [value]
    if any(_not_a_number(x) for x in items):
        raise ParameterError(field, value, allowed)
    try:
        raw = np.asarray(value)
        if raw.dtype.kind not in "iuf":
            raise TypeError
        return raw.astype(float, copy=False)   # a float array is used as it is: no copy per call
    except (TypeError, ValueError):
        raise ParameterError(field, value, allowed) from None


def require_positive_finite(field: str, value) -> float:
    """Return ``value`` as a float, or raise ParameterError unless it is finite and > 0."""
    if _not_a_number(value):
        raise ParameterError(field, value, "must be a finite number > 0")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(field, value, "must be a finite number > 0") from None
    if not math.isfinite(x) or x <= 0.0:
        raise ParameterError(field, value, "must be a finite number > 0")
    return x


def integer_in(field: str, value, lo: int, hi: int) -> int:
    """``value`` as an int, or ParameterError unless it is an integer (not a bool) in [lo, hi]."""
    import numpy as np

    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or not lo <= value <= hi:
        raise ParameterError(field, value, f"must be an integer in [{lo}, {hi}]")
    return int(value)


def number_in(field: str, value, lo: float, hi: float, *, hi_open: bool = False, why: str = "") -> float:
    """``value`` as a float, or ParameterError unless it is a finite number in [lo, hi] (or [lo, hi)
    with ``hi_open``); ``why`` is added to the message after a colon."""
    allowed = f"must be a number in [{lo:g}, {hi:g}{')' if hi_open else ']'}" + (f": {why}" if why else "")
    if _not_a_number(value):
        raise ParameterError(field, value, allowed)
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(field, value, allowed) from None
    if not (math.isfinite(x) and lo <= x and (x < hi if hi_open else x <= hi)):
        raise ParameterError(field, value, allowed)
    return x


def one_of(field: str, value, choices) -> str:
    """``value`` if it is one of the strings ``choices``, else ParameterError listing them."""
    if not isinstance(value, str) or value not in choices:
        raise ParameterError(field, value, f"must be one of {', '.join(choices)}")
    return value


#: The positive doubles a derived quantity may take: normal numbers (a subnormal has lost digits).
DOUBLE_MIN, DOUBLE_MAX = 2.2250738585072014e-308, 1.7976931348623157e308


class DerivedRangeError(ParameterError):
    """A quantity computed from the user's inputs (a mass, D2, a stiffness, a time step) leaves the
    range of doubles. The message names the inputs as typed, not the derived value, which the user
    never gave."""

    def __init__(self, quantity: str, inputs: dict, log10_value: float | None = None,
                 lo: float = DOUBLE_MIN, hi: float = DOUBLE_MAX):
        given = ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}" for k, v in inputs.items())
        size = "" if log10_value is None or not math.isfinite(log10_value) else f" of about 1e{log10_value:+.0f}"
        where = "double precision " if (lo, hi) == (DOUBLE_MIN, DOUBLE_MAX) else ""
        allowed = (f"these give {quantity}{size}, outside {where}[{lo:.3g}, {hi:.3g}]; "
                   "choose values that keep it inside")
        self.field, self.value, self.allowed = next(iter(inputs), quantity), given, allowed
        ValueError.__init__(self, f"{given}: {allowed}")


def derived_in_range(quantity: str, value, inputs: dict, log10_value: float | None = None) -> float:
    """``value`` as a float if it is a normal positive double, else DerivedRangeError naming ``inputs``."""
    try:
        x = float(value)
    except (OverflowError, TypeError, ValueError):
        raise DerivedRangeError(quantity, inputs, log10_value) from None
    if not (math.isfinite(x) and DOUBLE_MIN <= x <= DOUBLE_MAX):
        if log10_value is None and math.isfinite(x) and x > 0:
            log10_value = math.log10(x)
        raise DerivedRangeError(quantity, inputs, log10_value)
    return x
