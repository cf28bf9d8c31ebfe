"""Field round 26: the engine's end state (state26.py), then probe26.py for the engine's types beside the audit's rows (the tool: tests/fieldkit/referee.py, which says how it works).
usage: python referee26.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import referee  # noqa: E402

H = os.path.dirname(os.path.abspath(__file__))
referee.main(sys.argv[1:], state=os.path.join(H, "state26.py"), probe=os.path.join(H, "probe26.py"))
