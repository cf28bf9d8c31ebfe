"""Field round 18: the outcome of each deck (by prefix of its folder name), checked to cover every folder once.
usage: python classify18.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked": "p01 p02 p03 p06 p07 p08 p09 p10 p14 p15 p16 p18 p21 p22 p28 s01 s03 s06 s11 u01 u02 u03 u04 u08 u10 u11 u12 "
                            "w02 w03 w04 w09 w13 k05 k18 b07 b17 b22 b27 b28 b30 b39 b42 b54 x01 x02 G01 G03 G04 G11 G14 G22 G29 G32 G36 G37 G40",
 "correct otherwise": "p11 p17 p19 p20 p23 p25 s02 s05 s07 s08 s09 s10 s12 s14 s15 u05 u07 u09 w01 w08 w12 b03 b05 b06 b10 b12 b13 b14 b15 "
                      "b16 b19 b31 b33 b38 b44 k06 k07 k09 k16 k20 x03 G02 G05 G06 G07 G08 G10 G13 G15 G16 G17 G20 G21 G23 G25 G26 G27 "
                      "G30 G33 G34 G35 G38 G39 G41 G42 G44 G45 G46 G47 G50 G51 b47 b48 b52 R01b",
 "effect named fairly": "k03 k11 k17 G28 p13 u06 w05 w06 w07 w10 w11 w14 w15 b01 b02 b11 b34 k01 k02 k04 k08 k10 k12 k13 k14 k15 k19 "
                        "b20 b23 b26 b35 b36 b37 b50 G09 G18 G19 G24 G43 G49",
 "named with a false word": "R01",
 "SILENTLY WRONG (D1)": "b53",
 "WRONG: pairs the engine makes declared impossible (D1)": "b04",
 "WRONG: pairs that cannot happen reported (D2)": "b24 b45 b55 G48",
 "WRONG NUMBER, cause and remedy named falsely (D5)": "b40",
 "fair refusal": "p04 p05 p12 p24 p27 b08 b18 b21 b32 b43 b51 G12 G31",
 "AVOIDABLE REFUSAL": "s04 s13 b09 b25 b46 b49 b41",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py
