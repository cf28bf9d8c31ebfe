"""The tools the field rounds use to make and referee adversarial deck folders (tests/field13 ... tests/field27).

Each round's folder keeps its decks, logs and findings as its record, and for every tool a thin entry point
with the round's own file name and command line (e.g. ``python tests/field27/probe27.py ARGS``) that calls the
one copy here with the round's names: the scratch-folder prefix, the deck variables' prefix and the tag its
output lines carry. The engines (LAMMPS' ``lmp``, ``liggghts``) are the referees; nothing here imports the
project. None of these modules are tests: pytest collects only ``test_*.py``.
"""
