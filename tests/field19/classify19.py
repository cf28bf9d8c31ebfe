"""Field round 19: the outcome of each deck (by prefix of its folder name), checked to cover every folder once.
usage: python classify19.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked": "a02 a04 a08 a09 a11 a12 a14 b02 b05 d01 d03 d04 d07 d10 e08 e13 f01 f06 m01 m02 m05 m07 m09 m10 m11 m13 "
                            "v02 v05 v08 v14 L08 L10 L17 L20 L25 L26 L28 R04 R05 c02 c05 c07 c11 c19",
 "correct otherwise": "a01 a03 a05 a06 a07 b03 b07 b08 b12 d02 d06 d09 e04 e10 h04 h08 m06 m12 n04 n05 n06 n07 n08 v01 v03 v04 v07 v12 v13 v15 v16 "
                      "r01 r02 L02 L03 L04 L07 L09 L11 L12 L14 L16 L18 L19 L21 L22 L24 R01 R02 R03 "
                      "c01 c03 c06 c09 c14 c17 c18 c22 c24 c25 c27 c28 c34 c35 c38 c39 c40 v18 L31 L35 R06 R07",
 "effect named fairly": "e01 e02 e03 e05 e06 e07 e09 e11 e12 e15 f03 h01 h02 h05 h06 h07 h09 n01 n02 n03 b01 b04 b09 b11 b13 L05 L06 L13 L27 L29 c20 L32",
 "SILENTLY WRONG: a size range widened by a size the engine never makes, called present (C5)": "c31 L37 c36 c37 L39 L40 L41",
 "WRONG: eps for settings no step uses, nothing said (C1)": "b10 c10 c29",
 "WRONG: pairs of spheres a LIGGGHTS insertion has not made yet reported, nothing said (C4)": "L33 L34 L36",
 "named with a false word": "c30",
 "WRONG NUMBER: the time step stated is one the engine does not use, nothing said (C3)": "c08 c13 L30",
 "engine stops in a run the pass skips; the audit answers": "c23",
 "an insertion that fails in the run (deposit near too large): its pairs reported, the engine warns": "c32",
 "fair refusal": "L01 L15 L23 a13 b06 d05 d08 e14 f04 f05 h03 m03 m04 m08 v06 v09 v10 v11 c04 c12 L38 v17",
 "AVOIDABLE REFUSAL (C2)": "a10 f02 c26",
 "AVOIDABLE REFUSAL (round 18 D4's family: set after an insertion run)": "c21",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py
