"""Field round 39: the outcome table. judged39.txt (by hand, from the engine's own values on 1 and 2 processes) first;
the rest from cmp39.out (the live pair measured in the deck as written agrees with the audit's last stage, on 1 process
and, where the flag has no NPDIFF, on 2). usage: python classify39.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

ORDER = ("SIL", "TRACE", "ANSW", "REF", "NP", "AVOID", "CONSERVATIVE", "conservative", "left out", "correct", "fair", "not")   # worst first
classify.outcome(os.path.dirname(os.path.abspath(__file__)), round=39, order=ORDER)
