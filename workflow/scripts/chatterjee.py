# %% [markdown]
# # Chatterjee, James and Brogliato's zero-load coefficients against the elastic limit's C1 and C2
#
# Chatterjee et al. (Granular Matter 2022, article 14) scale the collision to elastic units,
#     u'' + u^a + g d(u^b)/dt = 0,   u(0) = 0,  u'(0) = 1,
# with an external load that vanishes at their theta = 1, and expand the restitution coefficient to second
# order in the damping g:
#     eps = 1 - b I g + b^2 I (Q - I/2) g^2,   I = K J,  Q = L M,
#     K = 2 ((a+1)/2)^nu,  L = ((a+1)/2)^nu,  nu = b/(a+1),
#     J = int_0^1 x^(b-1) (1 - x^(a+1))^(1/2) dx,   M = int_0^1 x^(b-1) (1 - x^(a+1))^(-1/2) dx
# (their integrals J and M at theta = 1; s = x^(a+1) turns them into B(nu, 3/2)/(a+1) and B(nu, 1/2)/(a+1)).
# In this project's variables a = alpha, b = gamma + 1, and their damping g b u^(b-1) u' is mu u^gamma u'
# with mu = b g, so their coefficients of -mu and mu^2 are I and I (Q - I/2), to be set against the
# article's C1 and C2 = nu C1^2 (1 - eps_overlap = C1 mu - C2 mu^2).
#
# Their coefficients are evaluated here from these forms in mpmath, the Beta functions and, as a second
# route, the two integrals by quadrature, without the library's code for C1 and C2; the library's values
# (restitution.core.asymptotics) are read only to be compared. Pairs: the article's force laws, the exact
# family's and the stability atlas's (the supplement's table).

# %%
from fractions import Fraction

import mpmath

from restitution_workflow.latex import sci_up
from restitution_workflow.pipeline import start, write_text

from restitution.core.asymptotics import elastic_limit

start(snakemake)
p = snakemake.params
mpmath.mp.dps = p.digits
pairs = sorted({(Fraction(a), Fraction(g)) for a, g in p.pairs})


# %% their coefficients at zero load, from the Beta forms or by quadrature
def their_coefficients(alpha: Fraction, gamma: Fraction, quadrature: bool = False):
    """(I, I (Q - I/2)) of Chatterjee et al. at zero load, from the Beta forms or by quadrature."""
    a = mpmath.mpf(alpha.numerator) / alpha.denominator
    b = mpmath.mpf(gamma.numerator) / gamma.denominator + 1
    nu = b / (a + 1)
    if quadrature:
        # tanh-sinh meets the square-root end points to about half the working digits (1e-17 at 30): the
        # integrals are taken at twice the digits, so that the check holds to the precision compared
        with mpmath.workdps(2 * mpmath.mp.dps):
            J = mpmath.quad(lambda x: x ** (b - 1) * mpmath.sqrt(1 - x ** (a + 1)), [0, 1])
            M = mpmath.quad(lambda x: x ** (b - 1) / mpmath.sqrt(1 - x ** (a + 1)), [0, 1])
    else:
        J = mpmath.beta(nu, mpmath.mpf(3) / 2) / (a + 1)
        M = mpmath.beta(nu, mpmath.mpf(1) / 2) / (a + 1)
    K = 2 * ((a + 1) / 2) ** nu
    L = ((a + 1) / 2) ** nu
    I, Q = K * J, L * M
    return I, I * (Q - I / 2), nu


def rel(x, y) -> float:
    return float(abs(x / y - 1))


# %% against the library's C1 and C2 at every pair
first_dev = second_dev = quad_dev = identity_dev = 0.0
for alpha, gamma in pairs:
    first, second, nu = their_coefficients(alpha, gamma)
    q_first, q_second, _ = their_coefficients(alpha, gamma, quadrature=True)
    limit = elastic_limit((str(alpha), str(gamma)))
    first_dev = max(first_dev, rel(first, limit.C1))
    second_dev = max(second_dev, rel(second, limit.C2))
    quad_dev = max(quad_dev, rel(q_first, first), rel(q_second, second))
    # their second coefficient is nu times the square of their first (B(nu, 1/2) = (2 nu + 1) B(nu, 3/2)),
    # to the working precision: the relation C2 = nu C1^2 is contained in their expression
    identity_dev = max(identity_dev, rel(second, nu * first ** 2))
    print(f"alpha={alpha} gamma={gamma}: I={mpmath.nstr(first, 17)} (library C1 {limit.C1!r}), "
          f"I(Q-I/2)={mpmath.nstr(second, 17)} (library C2 {limit.C2!r})")

# the library works in double precision: agreement to a few units of 1e-16 is all it can show
assert first_dev < 1e-13 and second_dev < 1e-13, (first_dev, second_dev)
assert identity_dev < 10.0 ** (5 - p.digits) and quad_dev < 10.0 ** (5 - p.digits), (identity_dev, quad_dev)

# %% macros
macros = {
    "CJPairs": str(len(pairs)),
    "CJDigits": str(p.digits),
    "CJCOneDev": sci_up(max(first_dev, 1e-16), 1),
    "CJCTwoDev": sci_up(max(second_dev, 1e-16), 1),
    "CJQuadDev": sci_up(max(quad_dev, 10.0 ** -p.digits), 1),
    "CJIdentityDev": sci_up(max(identity_dev, 10.0 ** -p.digits), 1),
}
write_text(snakemake.output.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))
