"""Numbers printed in S. Kim, "Coefficient of Restitution for Viscoelastic Materials".

These are the paper's claims, transcribed once so that tests, the claims ledger and
the manuscript compare against one source. Nothing in the library computes from
them except where a method is explicitly "the paper's relation".
"""

from __future__ import annotations

#: Material constants used for the paper's figures (its Sec. V and conclusions).
D1 = 0.000296
D2 = 0.0109
ALPHA = "3/2"
GAMMA = "1"
#: Impact speed of figures 1 and 2.
G_FIGURES = 0.1
#: "D_* ~ 3 x 10^-3".
D_STAR = 3e-3
#: "Omega ~ 0.5521 when g = 0.1".
OMEGA_AT_G = 0.5521
#: "tau_b = 2.2 for g = 0.1" (quoted from the author's simulations).
TAU_B_AT_G = 2.2
#: Omega~ = c0 + c1 Omega + c2 Omega^2.
PRINTED_C = (6.0203, -1.5257, 0.0256)
#: "Omega is proportional to g^(-3/4)".
OMEGA_G_EXPONENT = "-3/4"
#: "eps has terms that are a function of g^(1/4)".
EPS_G_EXPONENT = "1/4"
#: Where the paper says the higher-order series stop tracking the numerical solution.
FORWARD_DIVERGENCE_TAU = 2.0  # "begin to diverge around tau ~ 2.0"
INVERSE_DIVERGENCE_TAU = 1.5  # "second or higher order solutions begin to diverge for tau < 1.5"
#: Stated radius of validity of the damped-only Taylor series.
FORWARD_TAYLOR_RADIUS = "pi/sqrt(2)"
INVERSE_TAYLOR_RADIUS = "sqrt(2)"

#: Printed series x_n(tau) = sum coeff * tau^power, as (power, coefficient) strings.
PRINTED_SERIES = {
    "forward": {
        0: [("1", "1"), ("3", "-1/6"), ("5", "1/30"), ("7", "-17/2520"), ("9", "31/22680"),
            ("11", "-691/2494800")],
        1: [("7/2", "-4/35"), ("11/2", "107/3465"), ("15/2", "-42683/5405400"),
            ("19/2", "2719883/1396755360")],
        2: [("6", "1/175"), ("8", "-169/64680"), ("10", "206383/227026800")],
        3: [("17/2", "-22/104125"), ("21/2", "165853/1096811100")],
        4: [("11", "52/8017625")],
    },
    "inverse": {
        0: [("1", "1"), ("3", "1/6"), ("5", "1/30"), ("7", "17/2520"), ("9", "31/22680"),
            ("11", "691/2494800")],
        1: [("7/2", "-4/35"), ("11/2", "-107/3465"), ("15/2", "-42683/5405400"),
            ("19/2", "-2719883/1396755360")],
        2: [("6", "1/175"), ("8", "169/64680"), ("10", "206383/227026800")],
        3: [("17/2", "-22/104125"), ("21/2", "-165853/1096811100")],
        4: [("11", "52/8017625")],
    },
}
