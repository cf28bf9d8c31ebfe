"""How a fuzz check reads an exception: a refusal must be one line, an engine's failure is named by
its ERROR line. Shared by the number, scene and deck checks (tests/fuzzing.py runs them all)."""

from __future__ import annotations


def one_line(exc) -> bool:
    """Whether ``exc`` reads as a refusal should: one non-empty line."""
    return "\n" not in str(exc) and str(exc).strip() != ""


def engine_error(exc) -> str:
    """The engine's ERROR line of a failed run, else the exception's first line."""
    lines = str(exc).splitlines()
    return next((ln.strip() for ln in lines if "ERROR" in ln), lines[0] if lines else repr(exc))
