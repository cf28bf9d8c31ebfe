"""LAMMPS' formula languages under their former module name: they live in
:mod:`restitution.dem.deck_text`, beside the tokenizer they share (kept importable from here)."""

from .deck_text import Unevaluated, evaluate, evaluate_boolean, newer_syntax

__all__ = ["Unevaluated", "evaluate", "evaluate_boolean", "newer_syntax"]
