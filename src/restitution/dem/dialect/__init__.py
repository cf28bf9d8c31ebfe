"""What an engine's deck dialect builds on, below the engines: the settings a deck's commands build
and the one-line refusal (:mod:`restitution.dem.dialect.state`), and an engine's run of a deck's
scratch copy as a child process (:mod:`restitution.dem.dialect.child`). The deck reader above the
engines (:mod:`restitution.dem.deck`) uses both; nothing here imports an engine or the reader.
"""
