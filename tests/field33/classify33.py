"""Field round 33: the outcome table. judged33.txt (by hand, from the engine's own values) first; the rest from cmp33.out
(the live pair measured in the deck as written agrees with the audit's last stage). usage: python classify33.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

ORDER = ("SIL", "ANSW", "FALSE", "AVOID", "conservative", "correct", "fair", "not")   # worst first, then the rest by name
classify.outcome(os.path.dirname(os.path.abspath(__file__)), round=33, order=ORDER)
