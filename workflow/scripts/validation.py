# %% [markdown]
# # Validation of a variant against known results
#
# eps depends on (alpha, gamma, Omega) only, so variants are compared, and validated, on one
# log-spaced grid of Omega (`compare` in config.yaml) rather than on their impact-speed ranges (for
# the dashpot every g gives the same Omega). The reference eps on that grid
# (`restitution.core.collision.collide_many`) is compared with every known result that applies to the
# variant's exponents:
#
# * alpha = 1, gamma = 0: the exact linear spring-dashpot (`restitution.core.dashpot`), force-zero end;
# * alpha = gamma: the exact parametric solution (`restitution.core.asymptotics.equal_exponents_eps`);
# * alpha = 3/2, gamma = 1/2 (viscoelastic spheres): the two-term elastic expansion (whose existence
#   Ramirez et al. 1999 state), eps = 1 - C1 delta + C2 delta^2 + ..., delta = Omega^(-3/5)
#   (`restitution.core.asymptotics.elastic_limit`): its error must fall like the first omitted power,
#   delta^3, so the slope of log(error) against log(Omega) over the top decade of the grid is
#   compared with -3A, A = (gamma+1)/(alpha+1); and the Pade form as implemented in Granulars.jl
#   (attributed there to Mueller and Poeschel 2011)
#   (`restitution.fast.calibration.pade_mp2011`) where delta <= `pade_delta_max`;
# * alpha - 1 - 2 gamma = 0: eps does not depend on g (spread of the figure-4 curve).
#
# A result whose library module is missing is listed as "not available" instead of failing.

# %%
from fractions import Fraction

import numpy as np
import pandas as pd
from restitution_workflow.pipeline import start, write_csv, write_json

from restitution.core import asymptotics
from restitution.core.collision import collide_many
from restitution.core.dashpot import dashpot_collision
from restitution.core.exponents import Exponents
from restitution.fast.calibration import pade_mp2011

start(snakemake)

HERTZ = (Fraction(3, 2), Fraction(1, 2))

# %%
p = snakemake.params
tol = p.tolerances
ex = Exponents.parse(p.exponents["alpha"], p.exponents["gamma"])
curve = pd.read_csv(snakemake.input.curve)
omega = np.geomspace(p.grid["omega_min"], p.grid["omega_max"], p.grid["points"])
res = collide_many(ex, omega, rtol=p.rtol)
ref = res["eps"]
known = pd.DataFrame({"omega": omega, "eps_reference": ref, "tau_c": res["tau_c"], "ended_by": res["ended_by"]})
checks = []


def check(name, reference, measured, limit, passed, *, what, note="", omega_range=None, n=None, digits=3):
    """One row; ``digits``: the significant digits of ``measured`` that the measurement supports."""
    checks.append({"variant": p.variant, "check": name, "reference": reference, "what": what,
                   "measured": None if measured is None else float(measured), "digits": digits, "tolerance": limit,
                   "passed": None if passed is None else bool(passed), "note": note,
                   "omega_min": None if omega_range is None else float(omega_range[0]),
                   "omega_max": None if omega_range is None else float(omega_range[1]),
                   "n": n})


def rel_err(a, b):
    return np.abs(np.asarray(a, float) / b - 1.0)


# %% Closed forms
if (ex.alpha, ex.gamma) == (1, 0):
    exact = np.array([dashpot_collision(w).eps for w in omega])
    known["eps_dashpot"] = exact
    err = rel_err(ref, exact).max()
    check("linear spring-dashpot, closed form", "schwager2008", err, tol["closed_form_tolerance"],
          err <= tol["closed_form_tolerance"], what="max relative error",
          note="contact ends where the force vanishes", omega_range=(omega.min(), omega.max()), n=len(omega))

if ex.alpha == ex.gamma:
    exact = asymptotics.equal_exponents_eps(omega)
    known["eps_equal_exponents"] = exact
    err = rel_err(ref, exact).max()
    check("alpha = gamma, parametric closed form", "", err, tol["closed_form_tolerance"],
          err <= tol["closed_form_tolerance"], what="max relative error",
          omega_range=(omega.min(), omega.max()), n=len(omega))

# %% Viscoelastic spheres: elastic-limit series and the Pade form
if (ex.alpha, ex.gamma) == HERTZ:
    A = float((ex.gamma + 1) / (ex.alpha + 1))
    series = asymptotics.elastic_limit(ex)
    top = omega >= omega.max() / 10.0

    def error_slope(eps):
        err = rel_err(eps, ref)
        return float(np.polyfit(np.log(omega[top]), np.log(err[top]), 1)[0]), err

    # the two terms C1 mu - C2 mu^2 alone (Ramirez et al. state that such an expansion exists; their
    # printed constants were not read): the first term omitted is the end-of-contact term
    # beta mu^end_power (mu = Omega^-A), so the error falls like that term, not like delta^3.
    known["eps_ramirez"] = series.eps(omega, order=2, end_term=False)
    slope, err = error_slope(known["eps_ramirez"])
    expected = -A * min(3.0, series.end_power)
    check("two-term elastic expansion without the end term, error exponent", "", slope,
          tol["series_slope_tolerance"], abs(slope - expected) <= tol["series_slope_tolerance"],
          what=f"slope (expected {expected:g})",
          note=f"C1 = {series.C1:.7f}, C2 = {series.C2:.7f}; the first omitted term is this work's "
               f"end-of-contact term, Omega^{-A * series.end_power:g}",
          omega_range=(omega[top].min(), omega[top].max()), n=int(top.sum()),
          # the fitted errors carry the reference's own error: the slope's third digit moves with
          # the CPU's rounding (-1.8249 and -1.8251 on two machines)
          digits=2)
    known["eps_elastic_series"] = series.eps(omega, order=2)
    slope, err = error_slope(known["eps_elastic_series"])
    expected = -3.0 * A
    check("the same with this work's end-of-contact term, error exponent", "", slope,
          tol["series_slope_tolerance"], abs(slope - expected) <= tol["series_slope_tolerance"],
          what=f"slope (expected {expected:g})",
          note=f"end-of-contact coefficient {series.E:.7g}, times Omega^({-A * series.end_power:g}); error "
               f"{err[-1]:.2e} at the largest Omega",
          omega_range=(omega[top].min(), omega[top].max()), n=int(top.sum()), digits=2)
    known["eps_pade"] = pade_mp2011(omega)
    delta = omega ** (-A)
    near = delta <= tol["pade_delta_max"]
    err = rel_err(known["eps_pade"], ref)[near]
    check("Padé form as implemented in", "granularsjl", err.max() if near.any() else None, tol["pade_tolerance"],
          bool(near.any()) and err.max() <= tol["pade_tolerance"], what="max relative error",
          note=f"where delta = Omega^(-{A:g}) <= {tol['pade_delta_max']:g}",
          omega_range=(omega[near].min(), omega[near].max()) if near.any() else None, n=int(near.sum()))

# %% alpha - 1 - 2 gamma = 0: eps independent of g
if ex.omega_exponent == 0:
    e = curve["eps"].to_numpy()
    spread = float((e.max() - e.min()) / e.mean())
    check("restitution independent of the impact speed", "", spread, tol["g_independence_tolerance"],
          spread <= tol["g_independence_tolerance"], what="relative spread of eps over g",
          note=f"{len(e)} impact speeds from {curve['g'].min():g} to {curve['g'].max():g}",
          omega_range=(float(curve["omega"].min()), float(curve["omega"].max())), n=len(e))

# %%
write_csv(snakemake.output.known, known)
write_json(snakemake.output.json, {"variant": p.variant, "alpha": str(ex.alpha), "gamma": str(ex.gamma),
                                   "checks": checks})
for c in checks:
    print(c)
