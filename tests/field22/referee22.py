"""Field round 22: the engine's end state (state22.py), then probe22.py for the engine's types beside the audit's rows (the tool: tests/fieldkit/referee.py, which says how it works).
usage: python referee22.py DECKDIR ..."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import referee  # noqa: E402

H = os.path.dirname(os.path.abspath(__file__))
referee.main(sys.argv[1:], state=os.path.join(H, "state22.py"), probe=os.path.join(H, "probe22.py"), pairs=(("1", "1"), ("2", "2")))
