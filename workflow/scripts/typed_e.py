# %% [markdown]
# # The e you type against the eps you get
#
# Every DEM code whose damping is set from a typed restitution coefficient e gives an eps that
# depends on e alone, but is e only where the code's damping formula and its end of contact agree.
# The library's eps for each code and e (restitution.dem.engines.typed_e_table, relative accuracy
# 1e-10), and for each row the engine that confirms it: the engine tests run every row at the e
# values of TYPED_E_ENGINE_ES and demand TYPED_E_ENGINE_RTOL. This script only calls the library
# and writes what it returns.

# %%
import calendar
import math
import re

import pandas as pd
from restitution_workflow.latex import esc, fixed, fixed_down, fixed_up, sci, sci_up
from restitution_workflow.pipeline import start, write_csv, write_text

from restitution.dem.calibrate import calibrate
from restitution.dem.contact import Contact
from restitution.dem.engines.kratos.contact import LINEAR_ZETA_STEP
from restitution.dem.engines.lammps.contact import LAMMPS_CHECKED, TSUJI_POLY, TSUJI_SQRT2_SINCE, tsuji_a
from restitution.dem.engines.typed_e_table import (TYPED_E_CODES, TYPED_E_ENGINE_REFINEMENTS, TYPED_E_ENGINES,
                                           TYPED_E_ENGINE_ES, TYPED_E_ENGINE_RTOL, typed_e_table)
from restitution.dem.typed_e import THORNTON_H

start(snakemake)
out = snakemake.output
es = [float(e) for e in snakemake.params.es]

# %% the table
table = typed_e_table(es)
rows = [{"code": code, "engine": TYPED_E_ENGINES[code], **{f"eps_at_e_{e:g}": r[code] for e, r in zip(es, table)}}
        for code in TYPED_E_CODES]
write_csv(out.csv, pd.DataFrame(rows))

# Each row's code is the engine that confirms it (a test checks that they are the same code), so
# one column names both: the code and the version run
def release_name(engine: str) -> str:
    """LAMMPS' version as its own output names it ("LAMMPS (22 Jul 2025)"), not as the Python
    module's version label (2025.7.22); other engines unchanged."""
    m = re.fullmatch(r"LAMMPS (\d{4})\.(\d{1,2})\.(\d{1,2})", engine)
    if not m:
        return engine
    year, month, day = (int(x) for x in m.groups())
    return f"LAMMPS ({day} {calendar.month_abbr[month]} {year})"


# each row names its engine (a test reads it on the row's line) in one word, so that no name wraps and a row
# is one line; the releases, one per engine, are named once, in the data statement (macro TypedEReleases, written
# by rule typed_e_runs from the runs' own output). An option
# is kept whole: a keyword with underscores (limit_damping, DEM_D_Hertz_viscous_Coulomb) is one box, and the
# option breaks only between words


def unbroken(option: str) -> str:
    """The option in TeX, each word that holds an underscore in an mbox."""
    return " ".join(rf"\mbox{{{esc(w)}}}" if "_" in w else esc(w) for w in option.split(" "))


# The end rule each option's formula was derived for, beside the one the option runs (the table's rule column,
# and the count of options that miss e under their own rule). The dashpot's formula (LAMMPS' coeff_restitution,
# LIGGGHTS, Yade's ViscElMat) and Tsuji's fit are the overlap rule's; Kratos' linear law bisects the force
# rule's eps (the engines' contact modules say where each comes from). Thornton's fit (Yade's Hertz-Mindlin,
# Kratos' Hertz law) is taken as made for the force rule because Yade's source says so, and LAMMPS' tsuji
# polynomial (Marshall's fit, by LAMMPS' source) as the overlap rule's because the damping that returns e under
# that rule is its near-constant multiple; neither paper is checked on this, so the column marks those rows
# (INFERRED_ROWS) and the caption says what the mark means (referee r29)
DERIVED_FOR = {"Yade Hertz-Mindlin en": "force", "Kratos DEM_D_Hertz_viscous_Coulomb": "force",
               "Kratos DEM_D_Linear_viscous_Coulomb": "force"}
INFERRED_ROWS = ("Yade Hertz-Mindlin en", "Kratos DEM_D_Hertz_viscous_Coulomb",
                 "LAMMPS hertz + damping tsuji, limit_damping", "LAMMPS hertz + damping tsuji (default)")
RULE_LETTER = {"overlap": "o", "force": "f"}


def rule_cell(code: str) -> str:
    """'derived for / runs' as two letters (o: zero overlap, f: zero force); * where the derived-for rule
    is inferred, not read in the paper the fit comes from."""
    mark = r"$^\ast$" if code in INFERRED_ROWS else ""
    return rf"{RULE_LETTER[DERIVED_FOR.get(code, 'overlap')]}{mark}\,/\,{RULE_LETTER[TYPED_E_CODES[code](0.5).end]}"


lines = [r"\begin{tabular}{l>{\raggedright\arraybackslash}p{5.5cm}c" + "r" * len(es) + "}",
         r"\toprule",
         # "e =" once: the rule column's width is taken from the repeated heads, so that no option wraps
         r"code & option & rule & " + " & ".join((r"$e = {}$" if i == 0 else "${}$").format(fixed(e, 2))
                                                 for i, e in enumerate(es)) + r" \\", r"\midrule"]
# Kratos' options are class names of its source: the article names the model they select (the class names are
# in the supplement's DEM section), as it does for the other codes' options
SHOWN = {"Kratos DEM_D_Hertz_viscous_Coulomb": "Hertz, viscous damping",
         "Kratos DEM_D_Linear_viscous_Coulomb": "linear, viscous damping"}
for r in rows:
    option = SHOWN.get(r["code"], r["code"].split(" ", 1)[1])
    cells = [esc(release_name(r["engine"]).split(" ", 1)[0]), unbroken(option), rule_cell(r["code"])] + [
        fixed(r[f"eps_at_e_{e:g}"], 4) for e in es]
    lines.append(" & ".join(cells) + r" \\")
lines += [r"\bottomrule", r"\end{tabular}"]
write_text(out.table, "\n".join(lines))

# %% the numbers the section prints
clamp = "Yade ViscElMat (tc, en)"
MID = 0.5                                   # the e most often typed, and the one codes' manuals show
half = dict(zip(es, table))[MID]
top = dict(zip(es, table))[max(es)]
loss_ratio = {code: fixed((1 - top[code]) / (1 - max(es)), 1)
              for code in ("Yade Hertz-Mindlin en", "Kratos DEM_D_Hertz_viscous_Coulomb")}
if len(set(loss_ratio.values())) != 1:
    raise SystemExit(f"the fitted relations miss e = {max(es)} differently: {loss_ratio}")
# LAMMPS' tsuji damping against Tsuji's formula: Tsuji's A(e) was fitted with the mass of one particle where
# LAMMPS puts the effective mass, half of it for like particles. The damping that returns e under the rule the
# fit was made for (zero overlap, LAMMPS' default; eps depends on e alone, D1 = g = 1 lose nothing), over
# LAMMPS' A(e) sqrt(D1): sqrt(2) up to the fit's own error if that is the whole difference; and the eps that
# A(e) times sqrt(2), what LAMMPS' development source applies, gives for the middle e under either rule
TSUJI = ("3/2", "1/4")                      # Hertz elasticity, tsuji's delta^(1/4) damping
ratio = {e: calibrate(*TSUJI, D1=1.0, eps=e, g=1.0, end="overlap").D2 / tsuji_a(e) for e in es}
# the text states the factor's range over the interval of e the table spans, not over its six e: the table's e
# miss its extremes (the fit's error oscillates in e), so the range is taken on a grid of step TSUJI_STEP
TSUJI_STEP = 1e-3
n_grid = round((max(es) - min(es)) / TSUJI_STEP) + 1
grid = [min(es) + i * (max(es) - min(es)) / (n_grid - 1) for i in range(n_grid)]
ratio_grid = {e: calibrate(*TSUJI, D1=1.0, eps=e, g=1.0, end="overlap").D2 / tsuji_a(e) for e in grid}
e_low, e_high = min(ratio_grid, key=ratio_grid.get), max(ratio_grid, key=ratio_grid.get)
sqrt2_eps = {end: Contact(*TSUJI, 1.0, math.sqrt(2.0) * tsuji_a(MID), end).eps(1.0) for end in ("force", "overlap")}
# A row runs "its" rule when its end rule is the one its formula was derived for (DERIVED_FOR, above, the
# table's rule column); it misses e when it is off by more than the table's accuracy (1e-10) can explain: MISS
# is far above that and far below the smallest miss (Kratos' bisection, about 1e-5)
MISS = 1e-8
own_rule = [code for code in TYPED_E_CODES if TYPED_E_CODES[code](MID).end == DERIVED_FOR.get(code, "overlap")]
missing = [code for code in own_rule if any(abs(r[code] / r["e"] - 1.0) > MISS for r in table)]
# The engine runs (typed_e_runs.csv, written by the rule that runs them): per engine, how far its finest raw
# run lies from the table and how far its extrapolation does. Three step sizes determine the two Richardson
# levels and leave nothing over to test the error model, so the text quotes both and claims no more
runs = pd.read_csv(snakemake.input.runs)
runs["engine_name"] = runs["engine"].str.split(" ").str[0]
finest = (runs[f"eps_dt{TYPED_E_ENGINE_REFINEMENTS[-1]}"] / runs["eps_table"] - 1.0).abs().groupby(runs["engine_name"]).max()
extrapolated = runs["relative_deviation"].abs().groupby(runs["engine_name"]).max()
# Where the change between successive step sizes does not shrink, two error terms do not describe the runs: with
# three step sizes the extrapolation fits them exactly and cannot show it, so the caption counts these rows
steps = [runs[f"eps_dt{k}"] for k in TYPED_E_ENGINE_REFINEMENTS]
grows = sum(((b - c).abs() >= (a - b).abs()) for a, b, c in zip(steps, steps[1:], steps[2:])).astype(bool)
not_shrinking = int(grows.sum())
# the caption names those cases (engine, option as the table shows it, e) and quotes their extrapolation's deviation
# from the table: with a step-to-step change that grows, that agreement is fortuitous (referee r23 recomputed one)
diverging = runs[grows]


def case_name(code: str) -> str:
    """A run's case as the table names it: its engine in one word, then its option."""
    return f"{code.split(' ', 1)[0]} " + unbroken(SHOWN.get(code, code.split(' ', 1)[1]))


def listed(items: list[str]) -> str:
    """'a', 'a and b', 'a, b and c'."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


diverging_es = sorted(set(diverging["e"]))
cases = listed([case_name(code) for code in diverging["row"]])
# one e for all: said once ("both at e = 0.50"), else each case with its own e
if len(diverging_es) == 1 and len(diverging) > 1:
    cases += rf", {'both' if len(diverging) == 2 else 'all'} at $e = {fixed(diverging_es[0], 2)}$"
elif len(diverging) > 0:
    cases = listed([rf"{case_name(code)} at $e = {fixed(e, 2)}$" for code, e in zip(diverging["row"], diverging["e"])])
macros = {
    "TypedEMid": fixed(MID, 1),
    "TypedEOwnRuleRows": str(len(own_rule)), "TypedEOwnRuleMissing": str(len(missing)),
    # Thornton, Cummins and Cleary's coefficients as the library holds them (the ones Yade and Kratos use),
    # printed as they stand, so that a reader can recompute the Hertz-Mindlin rows without the engines
    "TypedEThorntonTerms": str(len(THORNTON_H)),
    # set as the rows of a display, five to a row: in running text the list overran the line (supplement)
    "TypedEThorntonH": r" \\ ".join(
        rf"\Xi_{{{i + 1}}}, \dots, \Xi_{{{min(i + 5, len(THORNTON_H))}}} &= "
        + r",\ ".join(f"{h!r}" for h in THORNTON_H[i:i + 5]) for i in range(0, len(THORNTON_H), 5)),
    # LAMMPS' documented polynomial for tsuji damping, as the library holds it, so that a reader can
    # recompute the tsuji rows without LAMMPS
    "TypedETsujiTerms": str(len(TSUJI_POLY) - 1),
    "TypedETsujiPoly": rf"\Psi_0, \dots, \Psi_{{{len(TSUJI_POLY) - 1}}} &= " + r",\ ".join(f"{a!r}" for a in TSUJI_POLY),
    # the width of the last interval of Kratos' bisection for its linear law's damping ratio
    "TypedEKratosZetaStep": sci(LINEAR_ZETA_STEP, 2),
    "TypedERunSteps": str(len(TYPED_E_ENGINE_REFINEMENTS)),
    # "within": bounds, rounded up like every bound the article prints (1.0145e-4 is not within 1.0e-4)
    **{f"TypedEFinest{name}": sci_up(finest[name], 2) for name in ("LAMMPS", "LIGGGHTS", "Yade", "Kratos")},
    "TypedEExtrapolatedMax": sci_up(extrapolated.max(), 2),    # "within": a bound, rounded up
    "TypedERunsNotShrinking": str(not_shrinking), "TypedERunsCount": str(len(runs)),
    "TypedERunsNotShrinkingCases": cases or "none",
    # measured deviations of single cases, in the cases' order: two digits, not bounds
    "TypedERunsNotShrinkingExtrapolated": listed([sci(abs(x), 2) for x in diverging["relative_deviation"]])
    if len(diverging) else "---",
    # ranges ("... to ... times LAMMPS'"): their ends rounded outward
    "TypedETsujiRatioMin": fixed_down(ratio_grid[e_low], 3), "TypedETsujiRatioMax": fixed_up(ratio_grid[e_high], 3),
    "TypedETsujiRatioMinAt": fixed(e_low, 3), "TypedETsujiRatioMaxAt": fixed(e_high, 3),
    "TypedETsujiGridStep": fixed(TSUJI_STEP, 3),
    "TypedETsujiRatioTableMin": fixed_down(min(ratio.values()), 3),
    "TypedETsujiRatioTableMax": fixed_up(max(ratio.values()), 3),
    "TypedETsujiRatioAtMid": fixed(ratio[MID], 4), "TypedEMinE": fixed(min(es), 2),
    "TypedETsujiSqrtTwoAtMid": fixed(sqrt2_eps["overlap"], 4),
    "TypedETsujiSqrtTwoLimitAtMid": fixed(sqrt2_eps["force"], 4),
    "TypedEEngineEs": ", ".join(fixed(e, 2) for e in TYPED_E_ENGINE_ES),
    "TypedEEngineRtol": sci(TYPED_E_ENGINE_RTOL, 1),
    "TypedEClampAtMid": fixed(half[clamp], 4),
    "TypedETsujiAtMid": fixed(half["LAMMPS hertz + damping tsuji, limit_damping"], 4),
    "TypedETsujiDefaultAtMid": fixed(half["LAMMPS hertz + damping tsuji (default)"], 4),
    "TypedECoeffRestAtMid": fixed(half["LAMMPS hertz + damping coeff_restitution, limit_damping"], 4),
    "TypedELammpsChecked": LAMMPS_CHECKED,
    "TypedETsujiSqrtSince": TSUJI_SQRT2_SINCE,
    "TypedEMindlinAtTop": fixed(dict(zip(es, table))[max(es)]["Yade Hertz-Mindlin en"], 4),
    "TypedETopE": fixed(max(es), 2),
    # how far the fitted relation misses at the top e, in the loss: (1 - eps)/(1 - e), the same for Yade's
    # Hertz-Mindlin and Kratos' Hertz law (one relation; checked to the printed digit)
    "TypedEMindlinLossRatio": loss_ratio["Yade Hertz-Mindlin en"],
    # Kratos' linear law misses e only by its bisection's tolerance: the largest miss at the table's e, to the
    # digits it has (a maximum over six e, not a bound over all e: the text says so), small enough to set it
    # apart from the misses of the fitted relations and of LAMMPS' tsuji damping
    "TypedEKratosLinearMaxDev": sci_up(max(abs(r["Kratos DEM_D_Linear_viscous_Coulomb"] / r["e"] - 1.0)
                                              for r in table), 2),   # "at most": rounded up
}
write_text(out.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))
