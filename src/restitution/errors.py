"""One exception type for every user mistake, so front ends can print one line and exit 2."""

from __future__ import annotations

import math


class ParameterError(ValueError):
    """A user-supplied value is outside what the model or a method supports.

    The message always names the field and the allowed range, so the CLI and the
    workflow can show it as a single line without a traceback.
    """

    def __init__(self, field: str, value: object, allowed: str):
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {value!r}: {allowed}")


def require_positive_finite(field: str, value) -> float:
    """Return ``value`` as a float, or raise ParameterError unless it is finite and > 0."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise ParameterError(field, value, "must be a finite number > 0")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ParameterError(field, value, "must be a finite number > 0") from None
    if not math.isfinite(x) or x <= 0.0:
        raise ParameterError(field, value, "must be a finite number > 0")
    return x
