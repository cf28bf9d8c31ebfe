"""Fast evaluation of eps(Omega) to a stated accuracy; builds on :mod:`restitution.core` only.

kernel and integrator (compiled DOP853), master (Chebyshev master curve with the expansions),
calibration (the cached bundle of rung errors), ladder (the cheapest rung that meets a
tolerance), cache (sealed files on disk).
"""
