"""Field round 30: the outcome table. judged30.txt (by hand, from the engine's own values) first; the rest from cmp30.out
(the live pair measured in the deck as written agrees with the audit's last stage). usage: python classify30.py"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

ORDER = ("SIL", "WRONG", "FALSE", "AVOID", "left out", "correct", "fair", "not")   # worst first, then the rest by name
classify.outcome(os.path.dirname(os.path.abspath(__file__)), round=30, order=ORDER)
