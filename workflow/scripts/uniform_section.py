# %% [markdown]
# # The uniform approximation: the article's macros and tables, the supplement's section
#
# Reads the uniform forms of every variant (uniform_form.py) and writes the supplement's section (the limits'
# constants of the main variant from restitution.core.asymptotics, how the form is fitted, the overlap rule's
# form), the macros and tables the article prints, and two figures: eps(g) of the main variant from the
# uniform approximation over the reference and
# the paper's printed relation, and the form's relative error in eps and 1 - eps for every variant.

# %%
import math
from fractions import Fraction

import mpmath
import numpy as np
import pandas as pd
import sympy as sp
from restitution_workflow.latex import esc, frac_tex, sci, sci_up
from restitution_workflow.law_names import law_name
from restitution_workflow.pipeline import (TEXT_WIDTH_PT, read_json, save_figure, setup_matplotlib,
                                          start, write_text)

from restitution.core import asymptotics as asy
from restitution.core.collision import OMEGA_RANGE, collide
from restitution.core.problem import Problem
from restitution.core.dashpot import dashpot_collision
from restitution.core.uniform import DEGREE_STEP, OVERLAP_P, SELECTION_TARGET, UniformForm
from restitution.fast.uniform_build import FIT_RTOL, LAW_BELOW

start(snakemake)
plt = setup_matplotlib()
p = snakemake.params
forms = {name: read_json(path) for name, path in zip(p.variants, snakemake.input.forms)}
errors = {name: pd.read_csv(path) for name, path in zip(p.variants, snakemake.input.errors)}
overlap_forms = {name: read_json(path) for name, path in zip(p.variants, snakemake.input.overlap_forms)}
overlap_errors = {name: pd.read_csv(path) for name, path in zip(p.variants, snakemake.input.overlap_errors)}
main = forms[p.main]
main_overlap = overlap_forms[p.main]
ex = p.exponents[p.main]
V = asy.viscous_limit((ex["alpha"], ex["gamma"]))
E = asy.elastic_limit((ex["alpha"], ex["gamma"]))

# %% figure: errors over g of the main variant (figure 4 shows eps itself)
curve = pd.read_csv(snakemake.input.curve)
a_, g_ = Fraction(ex["alpha"]), Fraction(ex["gamma"])
w = (a_ - 1 - 2 * g_) / (g_ + 1)
A_ = (g_ + 1) / (a_ + 1)
mat = p.materials[p.main]
scale = mat["D1"] * mat["D2"] ** (-float(a_ + 1) / float(g_ + 1))   # Omega = scale g^w
om = scale * curve["g"].to_numpy() ** float(w)
ref = curve["eps_reference"].to_numpy()
law_viscous = V.k * om
law_elastic = 1.0 - E.C1 * om ** (-float(A_))
rel = lambda x: np.abs(x / ref - 1.0)  # noqa: E731
# drawn at the size it prints (width: a fraction of TEXT_WIDTH_PT): 10.5 pt puts tick exponents and legend
# indices (0.7 of it) above 7 pt
plt.rcParams.update(dict.fromkeys(("axes.labelsize", "xtick.labelsize", "ytick.labelsize", "legend.fontsize",
                                   "axes.titlesize"), 10.5))
# the text width; the legend below the axes, off the data (inside, in the band between the curves, a reader
# took it for part of the plot)
# drawn at 0.9 of the text width, the width the article prints it at (at the full width its tick exponents printed
# at 6.7 pt, referee r19), and as high as it printed before
EPS_PRINT_WIDTH = 0.9
fig, ax = plt.subplots(figsize=(EPS_PRINT_WIDTH * TEXT_WIDTH_PT / 72.27, EPS_PRINT_WIDTH * 3.0))
ax.loglog(curve["g"], np.maximum(rel(curve["eps_uniform"].to_numpy()), 1e-17), color="tab:orange", lw=2.0,
          label="uniform approximation")
rel_loss = lambda x: np.abs((1.0 - x) / (1.0 - ref) - 1.0)  # noqa: E731  (the elastic law is one for 1 - eps)
ax.loglog(curve["g"], rel_loss(law_elastic), color="tab:green", ls="--", lw=1.5,
          label=r"elastic law $1 - C_1\mu$")
ax.loglog(curve["g"], rel(law_viscous), color="tab:blue", ls="-.", lw=1.5, label=r"viscous law $k\Omega$")
if "eps_printed" in curve and curve["eps_printed"].notna().any():
    ax.loglog(curve["g"], rel(curve["eps_printed"].to_numpy()), color="tab:red", ls=":", lw=2.0,
              label="Kim's printed relation")
ax.set_xlabel(r"impact speed $g$ (in the units of $D_1$, $D_2$)")
# one axis, two quantities: the elastic law is a law for 1 - eps, and its curve is the error in that
ax.set_ylabel("relative error in $\\varepsilon$\n(elastic law: in $1 - \\varepsilon$)")
ax.set_ylim(1e-9, 1e4)
# no title: the caption names the material, and with it the exponents
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.3), ncol=2, frameon=False, borderaxespad=0, handlelength=2.5)
fig.set_layout_engine("tight")
save_figure(fig, snakemake.output.eps_pdf, snakemake.output.eps_png, width=EPS_PRINT_WIDTH)
plt = setup_matplotlib()   # the style of the other figures again
err_elastic_gmin, err_viscous_gmax = float(rel_loss(law_elastic)[0]), float(rel(law_viscous)[-1])
LAW_TOL = 0.01
ok_el = np.nonzero(rel_loss(law_elastic) <= LAW_TOL)[0]
ok_vi = np.nonzero(rel(law_viscous) <= LAW_TOL)[0]
g_el = float(curve["g"].iloc[ok_el.max()]) if ok_el.size and ok_el.min() == 0 else None
g_vi = float(curve["g"].iloc[ok_vi.min()]) if ok_vi.size and ok_vi.max() == len(ref) - 1 else None
_tol = sci(100 * LAW_TOL, 1)
LAW_RANGE = {   # (elastic law within LAW_TOL somewhere, viscous law within LAW_TOL somewhere) -> one sentence
    (True, True): rf"Within {_tol}\,\% they hold only for $g \le {sci(g_el, 2)}$ (elastic) and "
                  rf"$g \ge {sci(g_vi, 2)}$ (viscous).",
    (True, False): rf"Only the elastic law comes within {_tol}\,\%, for $g \le {sci(g_el, 2)}$.",
    (False, True): rf"Only the viscous law comes within {_tol}\,\%, for $g \ge {sci(g_vi, 2)}$.",
    (False, False): rf"Neither comes within {_tol}\,\% anywhere over these speeds.",
}

# %% figure: relative error of the forms, one panel per force law (columns) and end rule (rows): in one
# panel per rule the three laws' curves and their error-estimate lines ran together
# as wide as the text it prints at, so that its sizes print as set (at 7.2 in wide the fit to 7 pt shrank the
# titles and the ticks' exponents to that limit)
fig, axes = plt.subplots(2, len(p.variants), figsize=(TEXT_WIDTH_PT / 72.27, 4.6), sharey=True, sharex=True,
                         squeeze=False)
for row, (fs, errs, rule) in enumerate(((forms, errors, "force"), (overlap_forms, overlap_errors, "overlap"))):
    for i, name in enumerate(p.variants):
        ax = axes[row, i]
        if row == 0:
            # the law's name over its exponents: on one line the three titles ran into each other
            ax.set_title(rf"{law_name(name, tex=False)}" "\n"
                         rf"$\alpha = {p.exponents[name]['alpha']}$, $\gamma = {p.exponents[name]['gamma']}$",
                         fontsize=10)
        if not fs[name]["available"]:
            ax.text(0.5, 0.5, "no form:\nthe bodies can stick" if rule == "overlap" else "no form",
                    transform=ax.transAxes, ha="center", va="center", fontsize=9.5)
            continue
        e = errs[name]
        el = e["omega"] >= 1
        ax.loglog(e["omega"], np.maximum(e["err_eps"], 1e-17), color="tab:blue", lw=1.3,
                  label=r"in $\varepsilon$")
        ax.loglog(e["omega"][el], np.maximum(e["err_one_minus_eps"][el], 1e-17), color="tab:orange", lw=1.3,
                  ls="--", label=r"in $1-\varepsilon$ ($\Omega \geq 1$)")
        # one line, the larger estimate: two lines a few per cent apart could not be told apart in print
        ax.axhline(max(fs[name]["bound_eps"], fs[name]["bound_one_minus_eps"]), color="0.25", lw=1.0,
                   ls=(0, (1, 1.5)), label="error estimate")
    # on two lines: on one, at this size, the two rows' labels ran into each other
    axes[row, 0].set_ylabel(f"{rule} rule:\nrelative error", fontsize=10)
for ax in axes.ravel():
    ax.set_ylim(1e-12, 1e-2)
    ax.set_xticks([1e-8, 1e-4, 1, 1e4, 1e8], labels=["$10^{-8}$", "", "$1$", "", "$10^{8}$"])
for ax in axes[1]:
    ax.set_xlabel(r"$\Omega$")
handles, labels = axes[0, 0].get_legend_handles_labels()
fig.legend(handles, labels, loc="lower center", ncol=4, frameon=False, fontsize=9.5)
fig.set_layout_engine("tight", rect=(0, 0.06, 1, 1))   # redone when save_figure resizes
save_figure(fig, snakemake.output.err_pdf, snakemake.output.err_png, width=1.0)

# %% the laws in physical units: Omega = D1 D2^(-(alpha+1)/(gamma+1)) g^w, w = (alpha-1-2gamma)/(gamma+1)
def frac(s):
    return frac_tex(Fraction(s))


HERTZ = (Fraction(3, 2), Fraction(1, 2))   # Hertz elasticity with Kuwabara-Kono damping (the model's definition)


def end_term_power(a, g):
    """q of the end term beta mu^q (Appendix A): (alpha + 1)/(alpha - gamma)."""
    return (a + 1) / (a - g)


def common_step(a: Fraction, b: Fraction) -> Fraction:
    """The largest rational of which a and b are both whole multiples."""
    return Fraction(math.gcd(a.numerator * b.denominator, b.numerator * a.denominator), a.denominator * b.denominator)


def elastic_power(a, g):
    """Exponent of g in 1 - eps ~ C1 Omega^(-A) when Omega = const g^w."""
    return -(a - 1 - 2 * g) / (g + 1) * (g + 1) / (a + 1)


if w == 0:
    units = (r"Here $\alpha - 1 - 2\gamma = 0$: $\Omega$, and with it $\varepsilon$, does not depend on the "
             r"impact speed.")
else:
    slow, fast = ("elastic", "viscous") if w < 0 else ("viscous", "elastic")
    # the prefactors of the two laws are the article's (CFViscousPrefactor, CFElasticPrefactor): here only what
    # it leaves out, the exponents' comparison with Brilliantov et al. and the laws' errors over Kim's speeds
    units = (rf"\paragraph{{The leading laws in physical units.}} With $\Omega \propto g^{{\varpi}}$, $\varpi = {frac(w)}$, "
             rf"slow impacts of Kim's material are {slow} and fast ones {fast}. "
             rf"The same rule for Hertz contact with Kuwabara--Kono damping ($\alpha = {frac(HERTZ[0])}$, "
             rf"$\gamma = {frac(HERTZ[1])}$) gives the $1 - \varepsilon \propto g^{{{frac(elastic_power(*HERTZ))}}}$ of "
             rf"Brilliantov et al.~\cite{{brilliantov1996}}; for Kim's exponents the elastic law is $g^{{{frac(-w * A_)}}}$ instead, and "
             rf"fast impacts give $\varepsilon \propto g^{{{frac(w)}}}$, a regime that law, an expansion about "
             rf"elastic impacts, does not describe. Both laws are leading order only. At the slowest impact of "
             rf"\ArtFig{{fig:eps}} ($g = {sci(float(curve['g'].iloc[0]), 2)}$) the elastic law is off by "
             rf"{sci(100 * err_elastic_gmin, 2)}\,\% in $1 - \varepsilon$; at the fastest "
             rf"($g = {sci(float(curve['g'].iloc[-1]), 2)}$) the viscous law is off by {sci(100 * err_viscous_gmax, 2)}\,\% "
             rf"in $\varepsilon$. " + LAW_RANGE[(g_el is not None, g_vi is not None)]
             + r" Everywhere in between the uniform approximation of \ArtEq{eq:uniform} holds (\ArtFig{fig:uniform-eps}).")


# the viscous expansion against the reference integrator (printed beside it)
CHECK_OMEGA = 1e-4
ref_check = collide((ex["alpha"], ex["gamma"]), CHECK_OMEGA, rtol=1e-12).eps
check_lead = abs(float(V.eps(CHECK_OMEGA, order=0)) / ref_check - 1.0)
check_first = abs(float(V.eps(CHECK_OMEGA, order=1)) / ref_check - 1.0)
# the order of the omitted term, tested by a sequence rather than one point: (eps / eps_first - 1) scaled by
# Omega^2 ln^2 Omega tends to a constant if that is the remainder's order (to 0 like 1/ln Omega if it were
# Omega^2 ln Omega). Three digits: at 1e-5 the remainder is 5e-9 of eps, so the integrator's 1e-12 moves the
# ratio by 2e-4 there (at 1e-6 by 1e-2 of it, which is why the sequence stops at 1e-5)
REMAINDER_OMEGAS = (1e-2, 1e-3, 1e-4, 1e-5)
REMAINDER_RTOL = 1e-12
remainder_ratio = []
for _om in REMAINDER_OMEGAS:
    _ref = collide((ex["alpha"], ex["gamma"]), _om, rtol=REMAINDER_RTOL).eps
    remainder_ratio.append((_ref / float(V.eps(_om, order=1)) - 1.0) / (_om * np.log(_om)) ** 2)
end_power = 1 + (g_ + 1) / (a_ - g_) if a_ > g_ else None
# beta = (alpha - gamma)/((gamma + 1)(alpha + 1)) is rational for rational exponents: printed as the fraction,
# checked against the library's floating-point value (a second route to the same number)
end_coef = (a_ - g_) / ((g_ + 1) * (a_ + 1))
if abs(float(end_coef) - float(E.E)) > 1e-12 * abs(float(E.E)):
    raise SystemExit(f"end coefficient: exact {end_coef} but the library gives {E.E}")
# Eq. (end-term) at these exponents: the difference of the two rules over its leading term beta mu^q, at three
# Omega of the elastic side. It tends to 1 like 1 + O(mu); the text says how far from 1 it still is there (for
# Kim's exponents, q = 5, the O(mu) correction is not small at these Omega)
END_RATIO_OMEGAS = (10.0, 30.0, 100.0)
end_ratio, end_scaled_dev, end_scaled_size = [], [], []
for _om in END_RATIO_OMEGAS:
    _eps_f = collide(Problem.of(ex["alpha"], ex["gamma"], "force"), _om, rtol=1e-12).eps
    _eps_o = collide(Problem.of(ex["alpha"], ex["gamma"], "overlap"), _om, rtol=1e-12).eps
    _mu_q = float(E.delta(_om)) ** float(E.end_power)
    end_ratio.append((_eps_f - _eps_o) / (float(E.E) * _mu_q))
    # Eq. (end-term)'s factor eps_o^(q-1) (Appendix): the ratio over it differs from 1 by
    # O(mu^q eps_o^(q-2)), the size printed beside it
    end_scaled_dev.append(end_ratio[-1] / _eps_o ** (float(E.end_power) - 1) - 1)
    end_scaled_size.append(_mu_q * _eps_o ** (float(E.end_power) - 2))
print("(eps_force - eps_overlap) / (beta mu^q):", dict(zip(END_RATIO_OMEGAS, end_ratio)))
print("... / eps_o^(q-1) - 1:", dict(zip(END_RATIO_OMEGAS, end_scaled_dev)), "mu^q eps_o^(q-2):", end_scaled_size)
# the text compares the first two (the third difference, 1e-9 for Kim's exponents, is too small for a
# relative comparison in double precision) and says each lies below its size: hold it to that
if not all(abs(d) < z for d, z in zip(end_scaled_dev[:2], end_scaled_size[:2])):
    raise SystemExit(f"end term: ratio / eps_o^(q-1) - 1 = {end_scaled_dev} not below mu^q eps_o^(q-2) = {end_scaled_size}")
end_clause = (r"so for these exponents the difference is smaller than the omitted $O(\mu^3)$: it is the leading effect of "
              r"ending at zero force, not a term of an expansion of $\varepsilon_{\mathrm{force}}$ alone" if end_power > 3 else
              r"so for these exponents it is the first correction after $C_2$")

# Eq. (viscous) against an exact result that shares nothing with its derivation: the linear dashpot (alpha = 1,
# gamma = 0), whose force-rule eps is elementary (Appendix, core.dashpot). The relative difference at two Omega,
# scaled by Omega^2 ln^2 Omega, and the expansion of the exact formula itself, by sympy, whose terms below
# Omega^2 must vanish if k, c_log and c_v are right (the library's constants enter as exact rationals)
DASHPOT_OMEGAS = (1e-3, 1e-4)
V_dash = asy.viscous_limit(("1", "0"))
dashpot_rel = [dashpot_collision(_om).eps / float(V_dash.eps(_om, order=1)) - 1.0 for _om in DASHPOT_OMEGAS]
dashpot_ratio = [r / (_om * math.log(_om)) ** 2 for r, _om in zip(dashpot_rel, DASHPOT_OMEGAS)]
_t = sp.symbols("t", positive=True)
_w = sp.sqrt(sp.Rational(1, 4) - _t)
_ln_exact = (sp.log(_t) - sp.log(sp.Rational(1, 2) - _t + _w)) / (2 * _w)      # ln eps, tau_c of the force rule
_k, _cl, _cv = (sp.nsimplify(x) for x in (V_dash.k, V_dash.c_log, V_dash.c_const))
_ln_first = sp.log(_k * _t) + sp.log(1 - _t * (_cl * sp.log(1 / _t) + _cv))
_diff = sp.expand(sp.series(_ln_exact - _ln_first, _t, 0, 3).removeO())
_lt = sp.Symbol("L")
_poly = sp.Poly(sp.expand(_diff.subs(sp.log(_t), _lt)), _t, _lt)
if any(m[0] < 2 for m, c in _poly.terms() if c != 0):
    raise SystemExit(f"the dashpot's exact eps disagrees with Eq. (viscous) below Omega^2: {_diff}")
dashpot_terms = {m[1]: _poly.coeff_monomial(_t ** 2 * _lt ** m[1]) for m, c in _poly.terms() if m[0] == 2}
if set(dashpot_terms) - {0, 1, 2} or not all(v.is_Integer for v in dashpot_terms.values()):
    raise SystemExit(f"unexpected form of the dashpot's remainder: {_diff}")
# the three terms against the exact difference at the smaller Omega: what they leave is O(Omega^3 ln^3 Omega)
_om = DASHPOT_OMEGAS[-1]
_pred = sum(float(c) * _om ** 2 * math.log(_om) ** j for j, c in dashpot_terms.items())
dashpot_pred_dev = abs(math.expm1(_pred) / dashpot_rel[-1] - 1.0)


def whole(x: float) -> str:
    """A constant that is a whole number for these exponents, printed as one; ten digits if it is not."""
    return sci(round(x), 1) if abs(x - round(x)) <= 1e-12 * max(1.0, abs(x)) else sci(x, 10)


# Ramirez et al.'s closed form of the Hertz constant (alpha = 3/2, gamma = 1/2), evaluated as they write it, against
# the library's C1 of Eq. (elastic) at those exponents: sqrt(pi) Gamma(3/5) / (2^(1/5) 5^(2/5) Gamma(21/10))
E_hertz = asy.elastic_limit(tuple(str(x) for x in HERTZ))
# their expression's four rationals, as written: sqrt(pi) Gamma(a) / (2^b 5^c Gamma(d)); the article prints the
# expression from these and the number from evaluating it
RAMIREZ = dict(a=Fraction(3, 5), b=Fraction(1, 5), c=Fraction(2, 5), d=Fraction(21, 10))
_f = lambda q: mpmath.mpf(q.numerator) / q.denominator  # noqa: E731
with mpmath.workdps(30):
    ramirez_c1 = float(mpmath.sqrt(mpmath.pi) * mpmath.gamma(_f(RAMIREZ["a"]))
                       / (2 ** _f(RAMIREZ["b"]) * 5 ** _f(RAMIREZ["c"]) * mpmath.gamma(_f(RAMIREZ["d"]))))
ramirez_form = (rf"\sqrt{{\pi}}\,\Gamma(\tfrac{{{RAMIREZ['a'].numerator}}}{{{RAMIREZ['a'].denominator}}})"
                rf"/\big(2^{{{RAMIREZ['b']}}}\,5^{{{RAMIREZ['c']}}}\,"
                rf"\Gamma(\tfrac{{{RAMIREZ['d'].numerator}}}{{{RAMIREZ['d'].denominator}}})\big)")
ramirez_dev = abs(ramirez_c1 / E_hertz.C1 - 1.0)
RAMIREZ_C2 = Fraction(3, 5)      # their C2 = (3/5) C1^2
ramirez_c2_dev = abs(float(RAMIREZ_C2) * ramirez_c1 ** 2 / E_hertz.C2 - 1.0)
nu_hertz = (HERTZ[1] + 1) / (HERTZ[0] + 1)

# the physical range of the viscous side for Hertz with Kuwabara-Kono damping: Omega = const g^w_hertz, so going
# from Omega = 1 down to the viscous limit's Omega = VISCOUS_EDGE multiplies the impact speed by this factor
VISCOUS_EDGE = 0.1
w_hertz = (HERTZ[0] - 1 - 2 * HERTZ[1]) / (HERTZ[1] + 1)
hertz_speed_factor = VISCOUS_EDGE ** (1.0 / float(w_hertz))
# Eq. (uniform)'s fitted correction vanishes like Omega^(sigma s0) at the viscous end, where zeta ~ 1/(k Omega):
# relative to zeta it is O(Omega^(1 + sigma s0)); for Hertz-Kuwabara-Kono and for the main law
hertz_name = next(n for n in p.variants if (Fraction(p.exponents[n]["alpha"]), Fraction(p.exponents[n]["gamma"])) == HERTZ)
sigma_s0 = {n: float(forms[n]["sigma"]) * forms[n]["m0"] for n in (hertz_name, p.main)}

# the elastic end of the form (the bracket has no delta^2 term; the fitted sum must supply it): measured at the
# largest Omega the reference integrator accepts, against the size of the C2 term there

ELASTIC_CHECK = OMEGA_RANGE[1]
_u = UniformForm.from_dict({k: v for k, v in main.items() if k not in ("available", "formula")
                            and not k.startswith("printed")})
_loss_ref = collide((ex["alpha"], ex["gamma"]), ELASTIC_CHECK, rtol=1e-12).one_minus_eps
form_loss_err = abs(float(_u.one_minus_eps(ELASTIC_CHECK)) / _loss_ref - 1.0)
c2_rel = float(E.C2 * E.delta(ELASTIC_CHECK) ** 2) / _loss_ref
sigma_m1 = main["sigma"] * main["m1"]
viscous_first = r"the leading and first-order terms at the viscous end"

# the abstract gives the figure for Kim's exponents and the largest over all the laws fitted, so that a reader
# does not take one law's figure for the family's; it says "12 coefficients per law", true only if every law has
# as many
fitted = [n for n in p.variants if forms[n]["available"]]
if any(len(forms[n]["a"]) != len(main["a"]) for n in fitted):
    raise SystemExit("the uniform forms have different numbers of coefficients: "
                     + ", ".join(f"{n}: {len(forms[n]['a'])}" for n in fitted))
worst = max(fitted, key=lambda n: forms[n]["bound_eps"])


def held_out(m: dict, what: str = "eps") -> float:
    """The largest relative error on the held-out points: the random test points and the dense scan
    (the model-selection points chose the shape, so they are not held out)."""
    return max(m[f"test_{what}"], m[f"dense_{what}"])


# the out-of-sample figure, over the held-out points of every law
worst_test = max(fitted, key=lambda n: held_out(forms[n]["measured"]))
# how far the dense scan's maximum lies above the model-selection points' (a grid four times coarser): the
# measured case for the factor in the error estimate
dense_ratio = max(forms[n]["measured"]["dense_eps"] / forms[n]["measured"]["selection_eps"] for n in fitted)
macros = {
    # error estimates (twice the largest error on any set, plus the reference accuracy) are rounded up like
    # bounds: rounded to nearest, 2 x 3.92e-4 printed as 7.8e-4, below the definition's own figures
    "CFBoundEpsWorst": sci_up(forms[worst]["bound_eps"], 2),
    "CFLawsFitted": str(len(fitted)),
    "CFBoundEps": sci_up(main["bound_eps"], 2), "CFBoundLoss": sci_up(main["bound_one_minus_eps"], 2),
    # the sets of points not used to fit the coefficients: the validation points (the grid points between
    # the fitted ones, which choose the shape), the random test points and the dense scan, used for nothing else
    "CFValidationPoints": str(main["measured"]["n_selection"]), "CFTestPoints": str(main["measured"]["n_test"]),
    "CFDensePoints": str(main["measured"]["n_dense"]),
    # largest errors on the held-out points: maxima, rounded up
    "CFTestEps": sci_up(held_out(main["measured"]), 2),
    "CFTestLoss": sci_up(held_out(main["measured"], "one_minus_eps"), 2),
    # three digits, as Table S16 of the supplement prints it (uniform_atlas.py's held_out_tex): the error estimate (twice the largest error on any set, plus the reference accuracy) is
    # printed beside it, and at two digits, rounded up, the two could read as inconsistent
    "CFTestEpsWorst": sci_up(held_out(forms[worst_test]["measured"]), 3),
    "CFTestEpsWorstLaw": esc(law_name(worst_test)),
    "CFDenseOverSelection": f"{dense_ratio:.3f}",
    "CFFitRtol": sci(FIT_RTOL, 1),
    "CFOverlapBoundEps": sci_up(main_overlap["bound_eps"], 2) if main_overlap["available"] else "none",
    "CFOverlapBoundLoss": sci_up(main_overlap["bound_one_minus_eps"], 2) if main_overlap["available"] else "none",
    # the overlap form's size and where its references are the creep law rather than integrations
    "CFOverlapTerms": str(len(main_overlap["a"])) if main_overlap["available"] else "none",
    "CFOverlapLawBelow": sci(LAW_BELOW, 1),
    "CFViscousK": sci(V.k, 6), "CFElasticCOne": sci(E.C1, 6),
    "CFViscousPrefactor": sci(V.k * scale, 4), "CFViscousPower": frac(w),
    "CFElasticPrefactor": sci(E.C1 * scale ** (-float(A_)), 4), "CFElasticPower": frac(-w * A_),
    "CFLawErrElastic": sci(100 * err_elastic_gmin, 2), "CFLawErrViscous": sci(100 * err_viscous_gmax, 2),
    # the Hertz law with Kuwabara-Kono damping (Ramirez et al. state that its elastic constants exist)
    "CFHertzAlpha": frac(HERTZ[0]), "CFHertzGamma": frac(HERTZ[1]),
    "CFHertzLossPower": frac(elastic_power(*HERTZ)),
    # under the force rule the end term beta mu^q joins the series: its powers are those of the largest
    # g^p of which both mu and mu^q are whole powers (q = 5/2 for Hertz: mu^(1/2), g^(1/10))
    "CFHertzHalfLossPower": frac(elastic_power(*HERTZ) * common_step(Fraction(1), end_term_power(*HERTZ))),
    # Eq. (uniform) at the elastic end (defect 2 of issue 43): exact to leading order only there
    "CFElasticCheckOmega": sci(ELASTIC_CHECK, 1),
    "CFFormLossErrAtCheck": sci(form_loss_err, 2),
    "CFCTwoRelAtCheck": sci(c2_rel, 2),
    "CFSigmaMOne": sci(sigma_m1, 3),
    "CFTwoNu": sci(2 * float(A_), 3),
    "CFViscousCheckOmega": sci(CHECK_OMEGA, 1),
    "CFViscousLeadErr": sci(check_lead, 2),
    "CFViscousFirstErr": sci(check_first, 2),
    "CFViscousRemRtol": sci(REMAINDER_RTOL, 1),
    "CFViscousRemOmegaA": sci(REMAINDER_OMEGAS[0], 1), "CFViscousRemRatioA": sci(remainder_ratio[0], 3),
    "CFViscousRemOmegaB": sci(REMAINDER_OMEGAS[1], 1), "CFViscousRemRatioB": sci(remainder_ratio[1], 3),
    "CFViscousRemOmegaC": sci(REMAINDER_OMEGAS[2], 1), "CFViscousRemRatioC": sci(remainder_ratio[2], 3),
    "CFViscousRemOmegaD": sci(REMAINDER_OMEGAS[3], 1), "CFViscousRemRatioD": sci(remainder_ratio[3], 3),
    # the dashpot check of Eq. (viscous): relative difference of the exact eps, its ratio to Omega^2 ln^2 Omega, and
    # the exact expansion's Omega^2 ln^j Omega coefficients (sympy)
    "CFDashOmegaA": sci(DASHPOT_OMEGAS[0], 1), "CFDashRelA": sci(dashpot_rel[0], 3), "CFDashRatioA": sci(dashpot_ratio[0], 3),
    "CFDashOmegaB": sci(DASHPOT_OMEGAS[1], 1), "CFDashRelB": sci(dashpot_rel[1], 3), "CFDashRatioB": sci(dashpot_ratio[1], 3),
    "CFDashK": whole(V_dash.k), "CFDashCLog": whole(V_dash.c_log), "CFDashCV": whole(V_dash.c_const),
    "CFDashTermTwo": str(dashpot_terms.get(2, 0)), "CFDashTermOne": str(dashpot_terms.get(1, 0)),
    "CFDashTermZero": str(dashpot_terms.get(0, 0)), "CFDashPredDev": sci_up(dashpot_pred_dev, 1),
    # Ramirez et al.'s closed form of C1 (Hertz) against the library's, and (3/5) C1^2 against C2
    "CFRamirezForm": rf"\ensuremath{{{ramirez_form}}}",
    "CFRamirezCOne": sci(ramirez_c1, 11), "CFRamirezDev": sci_up(max(ramirez_dev, 1e-16), 1),
    "CFRamirezCTwoDev": sci_up(max(ramirez_c2_dev, 1e-16), 1), "CFRamirezCTwoFactor": frac(RAMIREZ_C2), "CFHertzNu": frac(nu_hertz),
    # Omega of Hertz-Kuwabara-Kono against g, and the speed factor from Omega = 1 to the viscous limit's edge
    "CFHertzOmegaPower": frac(w_hertz), "CFViscousEdge": sci(VISCOUS_EDGE, 1),
    "CFHertzSpeedFactor": sci(hertz_speed_factor, 2),
    # Eq. (uniform)'s correction at the viscous end: sigma s0, and the relative remainder's power 1 + sigma s0
    "CFHertzSigmaSZero": sci(sigma_s0[hertz_name], 2), "CFHertzRemPower": sci(1 + sigma_s0[hertz_name], 2),
    "CFSigmaSZero": sci(sigma_s0[p.main], 2), "CFRemPower": sci(1 + sigma_s0[p.main], 2),
    "CFElasticCTwo": sci(E.C2, 6),
    "CFEndCoef": sci(E.E, 6),
    "CFEndCoefExact": frac(end_coef),
    "CFEndRatioOmegaA": sci(END_RATIO_OMEGAS[0], 2), "CFEndRatioA": f"{end_ratio[0]:.2f}",
    "CFEndRatioOmegaB": sci(END_RATIO_OMEGAS[1], 2), "CFEndRatioB": f"{end_ratio[1]:.2f}",
    "CFEndRatioOmegaC": sci(END_RATIO_OMEGAS[2], 2), "CFEndRatioC": f"{end_ratio[2]:.2f}",
    "CFEndScaledDevA": sci(abs(end_scaled_dev[0]), 1), "CFEndScaledSizeA": sci(end_scaled_size[0], 1),
    "CFEndScaledDevB": sci(abs(end_scaled_dev[1]), 1), "CFEndScaledSizeB": sci(end_scaled_size[1], 1),
    # the range of Omega over which the form's coefficients were fitted and tested
    "CFFitOmegaMin": sci(main["omega_range"][0], 1), "CFFitOmegaMax": sci(main["omega_range"][1], 1),
    "CFEndPower": frac(end_power) if end_power is not None else "none",
    "CFFormTerms": str(len(main["a"])),
    "CFFormDegree": str(len(main["a"]) - 1),
}
write_text(snakemake.output.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))


def stacked(name: str) -> str:
    """A column head on two lines where the name has a dash (Hertz--Kuwabara--Kono), else one."""
    first, dash, rest = esc(name).partition("--")
    return rf"\shortstack{{{first}--\\{rest}}}" if dash else esc(name)


rows = []
for name in p.variants:
    f = forms[name]
    ab = rf"{frac(p.exponents[name]['alpha'])} & {frac(p.exponents[name]['gamma'])}"
    if f["available"]:
        # the name on one line: stacked, it stood above its row's numbers
        rows.append(rf"{esc(law_name(name))} & {ab} & {sci(f['b'], 12)} & {sci(f['c3'], 12)} & {float(f['sigma']):g} & "
                    rf"{f['m0']} & {f['m1']} & {sci_up(f['bound_eps'], 2)}, {sci_up(f['bound_one_minus_eps'], 2)} \\")
    else:
        rows.append(rf"{esc(law_name(name))} & {ab} & \multicolumn{{6}}{{l}}{{none: {esc(f['reason'])}}} \\")
overlap_rows = []
for name in p.variants:
    f = overlap_forms[name]
    ab = rf"{frac(p.exponents[name]['alpha'])} & {frac(p.exponents[name]['gamma'])}"
    if f["available"]:
        kv = Fraction(p.exponents[name]["gamma"]) + 1
        kv /= 2 * Fraction(p.exponents[name]["gamma"]) + 1 - Fraction(p.exponents[name]["alpha"])
        overlap_rows.append(rf"{esc(law_name(name))} & {ab} & {frac(kv)} & {len(f['a'])} & {sci_up(f['bound_eps'], 2)} & "
                            rf"{sci_up(f['bound_one_minus_eps'], 2)} \\")
    else:
        why = (r"none: $\alpha \geq 2\gamma + 1$, the bodies can stick" if "stick" in f["reason"]
               else r"none: $\alpha \leq \gamma$, as for the force rule")
        overlap_rows.append(rf"{esc(law_name(name))} & {ab} & \multicolumn{{4}}{{l}}{{{why}}} \\")
overlap_names = [n for n in p.variants if overlap_forms[n]["available"]]
n_overlap = max((len(overlap_forms[n]["a"]) for n in overlap_names), default=0)
# every number to the twelve digits the printed-digit check assumes (sigma and r too: sigma may be nu itself)
overlap_coef_rows = [" & ".join([label] + [sci(overlap_forms[n][key], 12) for n in overlap_names]) + r" \\"
                     for label, key in ((r"$\bar b$", "b"), (r"$\Theta$", "K"), (r"$\bar\sigma$", "sigma"), (r"$\bar\Lambda$", "r"))]
overlap_coef_rows.append(" & ".join([r"$\bar s_1$"] + [str(overlap_forms[n]["m1"]) for n in overlap_names]) + r" \\")
overlap_coef_rows += [" & ".join([rf"$\bar a_{{{j}}}$"] + [sci(overlap_forms[n]["a"][j], 12) if j < len(overlap_forms[n]["a"])
                                                     else "" for n in overlap_names]) + r" \\"
                      for j in range(n_overlap)]
overlap_printed = max((overlap_forms[n]["printed_max_change"] for n in overlap_names), default=0.0)
coef_names = [n for n in p.variants if forms[n]["available"]]
coef_rows = [" & ".join([label] + [sci(forms[n][key], 12) for n in coef_names]) + r" \\"
             for label, key in (("$k$", "k"), (r"$c_{\log}$", "c_log"), (r"$\nu$", "A"))]
n_rows = max((len(forms[n]["a"]) for n in coef_names), default=0)
coef_rows += [" & ".join([rf"$a_{{{j}}}$"] + [sci(forms[n]["a"][j], 12) if j < len(forms[n]["a"]) else ""
                                             for n in coef_names]) + r" \\"
              for j in range(n_rows)]


def two_tables(cols: str, header: str, rows: list, names: list, coef_rows: list) -> str:
    """A form's table: one row per variant, then its numbers in one column per variant."""
    # 4pt between columns: with the law's name on one line the default 6pt made the first table 17pt too wide
    # 3pt: at \small (every script at 7 pt) the article's table of the forms was 14pt wider than the text at 4pt
    return "\n".join([r"\setlength{\tabcolsep}{3pt}", rf"\begin{{tabular}}{{{cols}}}", r"\toprule", header + r" \\", r"\midrule", *rows,
                      r"\bottomrule", r"\end{tabular}", "", r"\vspace{1ex}",
                      rf"\begin{{tabular}}{{l{'r' * len(names)}}}", r"\toprule",
                      " & " + " & ".join(stacked(law_name(n)) for n in names) + r" \\", r"\midrule", *coef_rows,
                      r"\bottomrule", r"\end{tabular}"])


force_tables = two_tables(r"lllllllll", r"force law & $\alpha$ & $\gamma$ & $b$ & $c_{\mathrm b}$ & $\sigma$ & $s_0$ & $s_1$ & "
                          r"error estimate: $\varepsilon$, $1-\varepsilon$", rows, coef_names, coef_rows)
# the force law's column as wide as its longest name (a fixed 2.1 cm broke Hertz--Kuwabara--Kono over three lines)
overlap_tables = two_tables(r"lllllll", r"force law & $\alpha$ & $\gamma$ & $\kappa$ & $\bar N + 1$ & "
                            r"$2\times$ max.\ error $\varepsilon$ & $2\times$ max.\ error $1-\varepsilon$", overlap_rows, overlap_names,
                            overlap_coef_rows)
text = rf"""
\section{{Both limits and the uniform approximation: numbers and fit}}
\label{{sec:uniform}}

\ArtSec{{sec:limits}} states the viscous and elastic limits, the end-rule term and the uniform
approximation, and \ArtApp{{app:derivations}} derives them; Kim's relation does not hold (Sec.~\ref{{sec:ledger}}). This section
adds what the article leaves out: the constants to ten digits, the leading laws in physical units with their errors,
how the coefficients are fitted, the error over $\Omega$ (Fig.~\ref{{fig:uniform-error}}) and the overlap rule's form.

\paragraph{{Constants for Kim's exponents ($\alpha = {frac(ex['alpha'])}$, $\gamma = {frac(ex['gamma'])}$).}}
In the notation of \ArtEqs{{eq:viscous}}{{eq:end-term}}, viscous limit: $k = {sci(V.k, 10)}$, $c_{{\log}} = {sci(V.c_log, 10)}$,
$c_{{\mathrm{{v}}}} = {sci(V.c_const, 10)}$ (the subscript keeps it apart from Kim's unrelated $c_0$ of
Sec.~\ref{{sec:connection}}), and contact lasts $\tau_c = (2\ln(1/\Omega) + L)/\lambda$ with $L = {sci(V.L, 10)}$,
$\lambda = X^\gamma = {sci(V.lam, 10)}$. Elastic limit: $C_1 = {sci(E.C1, 10)}$, $C_2 = {sci(E.C2, 10)}$, end-rule term
$\beta\mu^q$ with $q = {frac(end_power)}$ and $\beta = {frac(end_coef)}$, {end_clause}; contact lasts
$\tau_c = \theta_c\,\Omega^{{-1/(\alpha+1)}}$ with $\theta_c = {sci(E.T0, 10)}$, its duration in the elastic time
$\theta = \Omega^{{1/(\alpha+1)}}\tau$ of \ArtApp{{app:derivations}}.

{units}

\paragraph{{How the uniform approximation is fitted.}}
Its {len(main['a'])} coefficients (more, in steps of {DEGREE_STEP}, only where the error on the model-selection
points stays above {sci(SELECTION_TARGET, 1)}) are fitted to integrations at relative tolerance $\CFFitRtol$ on every
other point of a grid over $10^{{-9}} \leq \Omega \leq 10^{{9}}$ (twenty per decade); the points in between choose the
shape $(\sigma, s_0, s_1)$. On the {main['measured']['n_test']} random test points, $\varepsilon$ and $1 - \varepsilon$
come from independent integrations in the variables of Sec.~\ref{{sec:reference}}; the dense scan uses the integrator at
$\CFFitRtol$. The article gives the resulting errors and the error estimate; Fig.~\ref{{fig:uniform-error}} shows the
error over the whole range. The numbers of \ArtTab{{tab:uniform}}, typed as printed, change $\varepsilon$ by at most
{sci(max(f['printed_max_change'] for f in forms.values() if f['available']), 2)} relative. A force law with
$\alpha \leq \gamma$ has no such form: for $\alpha = \gamma$ the exact implicit relation of \ArtSec{{sec:model}}
(Hunt and Crossley's case) applies, for $\alpha < \gamma$
the first viscous correction is not known. Table~\ref{{tab:uniform-atlas}} in the appendix gives the form for every
exponent pair of its survey of the reference integrator.

\begin{{figure}}[htbp]
\centering
\includegraphics[width=\linewidth]{{results/paper/uniform_error.pdf}}
\caption{{Relative error of the uniform approximations against integrations at relative tolerance $\CFFitRtol$, in $\varepsilon$ (solid) and in
$1 - \varepsilon$ (dashed), for every force law that has one: \ArtEq{{eq:uniform}} for the force rule (top),
Eq.~(\ref{{eq:uniform-overlap}}) for the overlap rule (bottom, from $\Omega = {sci(LAW_BELOW, 1)}$ up); one column per force law; dotted line: the larger of the empirical error estimates in $\varepsilon$ and in $1 - \varepsilon$ (twice the largest error measured on the model-selection, test and dense-scan points, plus the reference's accuracy; both are given with the forms).}}
\label{{fig:uniform-error}}
\end{{figure}}

\paragraph{{The overlap rule in one formula.}}
Where contact lasts until the overlap is back to zero (the default of the DEM codes, Sec.~\ref{{sec:dem}}), fast
impacts follow the creep law $\varepsilon = C_o\,\Omega^{{\kappa}}$ of \ArtEq{{eq:overlap-limit}}, $\kappa = (\gamma+1)/(2\gamma+1-\alpha)$,
up to a correction that vanishes like $\exp(-Q/\Omega)$, and slow ones the same elastic limit as above. For
$\gamma < \alpha < 2\gamma + 1$ (where the bodies cannot stick) one formula joins the two, with $\bar z = \bar b\,\Omega$,
$\bar u = \tanh(\tfrac{{\bar\sigma}}{{2}} \ln \bar z)$ and the power {OVERLAP_P} of $\bar z$ below fixed (bars mark the constants of this form, which differ from those of
that of \ArtEq{{eq:uniform}}):
\begin{{equation}}
\frac{{1}}{{\varepsilon}} = \frac{{\bar z^{OVERLAP_P}}}{{1 + \bar z^{OVERLAP_P}}} + \Theta \bar z^{{-\kappa}} (1 + \bar z^{OVERLAP_P})^{{(\kappa - \nu)/{OVERLAP_P}}}
\exp\!\Big[\exp(-\bar\Lambda/\bar z)\, (1-\bar u)^{{\bar s_1}} \sum_{{j=0}}^{{\bar N}} \bar a_j \cos(j \arccos \bar u)\Big],
\label{{eq:uniform-overlap}}
\end{{equation}}
with $\bar b = (C_o C_1)^{{1/(\kappa - \nu)}}$ and $\Theta = \bar b^{{\kappa}}/C_o$, so that
$\varepsilon \to C_o\,\Omega^{{\kappa}}$ and $1 - \varepsilon \to C_1 \Omega^{{-\nu}}$ exactly, and $\varepsilon > 0$
for any coefficients. The envelope $\exp(-\bar\Lambda/\bar z)$ has the form of the heuristic correction $\exp(-Q/\Omega)$, but its rate
$\bar\Lambda$ is a fitted shape constant, not the heuristic's $Q$; the shape $(\bar\sigma, \bar\Lambda, \bar s_1)$ and the
degree are chosen as for the force rule's form, the coefficients fitted with a small penalty on their size (without
it they grow to $10^8$ where the envelope leaves them free, and twelve printed digits would no longer reproduce the
formula). Below $\Omega = {sci(LAW_BELOW, 1)}$ each integration of the creeping return takes about a second, and there the
references are the creep law itself, checked against the integrator above it; the error estimate adds that difference and
the error of $C_o$. The error estimate for Kim's force law is {sci_up(main_overlap['bound_eps'], 2) if main_overlap['available'] else 'none'} in $\varepsilon$
and {sci_up(main_overlap['bound_one_minus_eps'], 2) if main_overlap['available'] else 'none'} in $1 - \varepsilon$ (Table~\ref{{tab:uniform-overlap}},
lower row of Fig.~\ref{{fig:uniform-error}}); the printed numbers change $\varepsilon$ by at most {sci(overlap_printed, 2)}.
For $\alpha \geq 2\gamma + 1$ the bodies can stick and there is no such formula: for $\alpha = 2\gamma + 1$ exactly when
$\Omega \leq 1/(4(\gamma+1))$, at every impact speed since $\Omega$ does not depend on $g$ there (\ArtSec{{sec:exact-family}}); the integrations cover those pairs.

\begin{{table}}[htbp]
\centering\small
\caption{{The overlap rule's form (\ref{{eq:uniform-overlap}}) of each force law: its number of coefficients and
twice the largest relative errors in $\varepsilon$ (over $10^{{-8}} \leq \Omega \leq 10^{{8}}$) and in $1 - \varepsilon$
(over $\Omega \geq 1$), measured on the model-selection, test and dense-scan points, plus the accuracy of the reference integration;
below, its constants, shape and coefficients.}}
\label{{tab:uniform-overlap}}
\vspace{{4pt}}
{overlap_tables}
\end{{table}}
"""
write_text(snakemake.output.tex, text)
write_text(snakemake.output.table, force_tables)
write_text(snakemake.output.overlap_table, overlap_tables)
