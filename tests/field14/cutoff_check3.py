"""Field round 14: the cutoff keyword on every pair (pair_coeff * *), one whole run (no per-step loop): two spheres 3 mm apart
meet head-on and fly apart; eps = relative speed after / before. Non-periodic, and periodic with the contact
across the periodic boundary (ghost atoms). No import from the project. usage: python cutoff_check2.py"""
from cutoff_check2 import main  # the same runs, the cutoff on pair_coeff * * (this folder's script)

main((True,), star=True)
