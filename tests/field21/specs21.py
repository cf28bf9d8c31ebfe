"""Field round 21: round 20's spec table, copied unchanged at the start of the round (specs20.py: its names are round 20's
decks, not this round's, so run here it stops at the first name that has no folder in tests/field21/decks, as the copy
did); kept so the round's command still means what it meant. usage: python specs21.py [NAME ...]"""
import importlib.util, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit.specs import write  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("specs20", os.path.join(HERE, "..", "field20", "specs20.py"))
specs20 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(specs20)
write(specs20.S, os.path.join(HERE, "decks"), sys.argv[1:])
