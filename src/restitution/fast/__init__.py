"""Fast evaluation of eps(Omega) to a stated accuracy; builds on :mod:`restitution.core` only.

integrator (compiled DOP853), master (Chebyshev master curve with the expansions), calibration (what the
ladder builds, each piece on its own, and the rung errors measured on the curve), rung (what a rung is, and the tolerance formulas), rungs (the
registry: one module per kind of rung), ladder (the chooser: the cheapest quote that meets a
tolerance), cache (sealed files on disk).
"""
