"""The tools the field rounds use to make and referee adversarial deck folders (tests/field13 ... tests/field28).

Each round's folder keeps its decks, logs and findings as its record, and for every tool a thin entry point with
the round's own file name and command line (e.g. ``python tests/field28/probe28.py ARGS``) that calls the one copy
here with the round's names: the scratch-folder prefix, the prefix of the variables a probe adds to a deck, and the
tag its output lines carry. The engines (LAMMPS' ``lmp`` and its Python module, ``liggghts``) are the referees;
nothing here imports the project. None of these modules are tests: pytest collects only ``test_*.py``.

Making decks: decks (the helpers and folder writer of every generator, make_decksNN.py), specs (the spec tables of
rounds 13-21), xdecks.sh (the engines' example decks copied in). Running and auditing: audit.sh, engine.sh, env.sh,
difftest.sh. Engine probes: scratch (the copy a probe runs in), probe and wprobe (LAMMPS pair and walls), lprobe
(LIGGGHTS), state, engine_stages, liggghts_state, neighbor_check, liggghts and liggghts_neighbor (rounds 15-19's
LIGGGHTS experiments), dtcheck, live (a deck's own pair run as written). Refereeing and summing up: referee,
spec_referee, rows, cmp, jsoncheck, summary, classify.
"""
