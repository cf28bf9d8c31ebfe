"""Field round 20: the outcome of each deck folder (by the prefix of its name), checked to cover every folder once.
usage: python classify20.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked (head-on referee agrees)":
    "p02 p03 p05 p07 p21 s01 s08 x01 x03 x36 m06 m07 m21 h05 w07 w15 w18 w19 t09 R01 L13 L24 L27 L36 L42 L43 L51 L54 L56 L57 L61",
 "correct otherwise (D1/D2 and sizes checked against the engine's state, PROBE prints or the deck's numbers)":
    "p01 p04 p06 p08 p09 p10 p11 p12 p13 p14 p16 p17 p18 p19 p20 p22 s02 s04 s05 s06 s07 s09 s10 s16 s19 s20 s21 s22 "
    "x02 x05 x06 x07 x08 x09 x10 x11 x12 x13 x14 x15 x16 x17 x18 x19 x20 x21 x22 x23 x24 x25 x26 x27 x28 x29 x30 x31 x32 x33 x34 x35 x37 x38 "
    "t02 t03 t04 t05 t06 t10 t13 w03 w05 w08 w12 w13 w14 m08 m11 m14 m15 m22 h04 h07 h12 h15 e05 e06 "
    "i01 i03 i06 i07 i08 i09 i10 i13 i15 z01 z02 z03 z04 z05 z06 z07 z08 z10 z11 z19 z21 z22 z23 z24 z25 z27 z29 z33 z42 "
    "L05 L06 L07 L09 L14 L15 L18 L21 L22 L25 L29 L37 L41 L45 L50 L52 L53 L55 L58 L60 L62 L63 L65 L66 L67 L68 "
    "L73 L74 L75 L76 L87 L88 L89 L90 L91 L94 L96 L99 L100",
 "effect named fairly": "m01 m02 m03 m04 m05 m09 m10 m13 m16 m17 m18 m19 m20 m23 h01 h09 h10 h11 h13 h14 t01 t07 "
    "w01 w02 w04 w06 w09 w11 w16 w17 z37 s11 s12 s14 s24 i02 i12 L02 L03 L10 L19 L26 L28 L30 L31 L32 L35 L38 L39 L49 L82 R02 R03 R04",
 "SILENTLY WRONG: `quit` not seen (LIGGGHTS quit; quit in run N every M in both engines), stages after it reported as the deck's (new, D1)": "L81 L85 L86 L93 e27",
 "WRONG EPS with a false word (effectively silent): commands the audit never executes though they change a contact - `partition yes 1 CMD` (both engines run CMD), `ndx2group` (z36: type 2 'has no particle'), `timer timeout 0` (z28: no run made), `fix ttm` (z40: a drag) - each said to have 'no part in a contact' (new, D5)": "z30 z31 z32 L98 z36 z28 z40",
 "WRONG, nothing said: what `unfix` in `run N every M` removes is reported for the runs after it (new, D2)": "e03 e24 L71",
 "WRONG with a false word: same (D2), a removed wall or fix said to act": "e16 e20 e21 L78",
 "WRONG NUMBER, nothing said: `timestep` in `run N every M` not seen, steps per contact and eps at the deck's dt stated at the old dt (new, D3)": "e15 L72",
 "same (D3), the later dt finer (the stated steps per contact too few: harmless direction)": "e12 t08",
 "left class: steps per contact at the coarsest timestep of a merged stage": "t11",
 "left class: run-time failures (the engine stops only when the runs are made; the audit answers)": "h02 i04 i14 i16 L92 z26 z41",
 "fair refusal": "L01 L04 L08 L11 L12 L16 L17 L20 L23 L33 L34 L40 L44 L46 L47 L48 L64 L69 h03 i05 i11 m12 m24 p15 s03 s13 s15 s17 t12 w10 x04 z09 z13 z34 z35 z39 "
    "e01 e02 e04 e07 e08 e09 e10 e11 e13 e14 e18 e19 e22 e23 e25 e26 e28 L59 L70 L77 L79",
 "AVOIDABLE REFUSAL (mild, new): a file the deck writes with print/fix print/write_coeff, read back by include/variable file": "z12 z14 z15 z16 z17 z18 z38 L80 L83",
 "AVOIDABLE REFUSAL with a false engine error: `if ... then quit` or `if ... then \"run N\"` in LIGGGHTS (the audit's own rewrite into an include)": "L84 L95 L97",
 "AVOIDABLE REFUSAL, left classes (pair_style none stage; fix adapt reset yes)": "h06 h08 s18 s23",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py
