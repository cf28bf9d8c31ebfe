"""The physics: the contact law x'' + Omega x^alpha + x^gamma x' = 0 and its exact solutions.

exponents (the rational pair alpha, gamma), model (materials, Omega, the inverse scaling), series
(the perturbation series), damped (the damped-only closed forms), dashpot (alpha = 1, gamma = 0),
law, collision and results (the scipy reference integration and what it returns), energy (1 - eps
from the energy balance), highprec (mpmath Taylor), asymptotics (small- and large-Omega
expansions, alpha = gamma), connection (the exact Omega~(Omega), its fit and the retrace check),
errors (the input checks every layer uses), root (a bracketed root without scipy).

Imports nothing from the rest of the package.
"""
