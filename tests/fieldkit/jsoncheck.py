"""Every deck folder with audit rc 0: its --json parses, and the last stage's eps at each speed of each pair and wall in
--json equals the text rows (to the text's 10 decimals); rc 2 folders: audit.json empty or a refusal (rounds 24-28).
usage: python jsoncheckNN.py
"""
import json, os, re


def main(D):
    """Check the deck folders under `D`; print the disagreements and the counts."""
    bad = n_ok = 0
    for n in sorted(os.listdir(D)):
        d = os.path.join(D, n)
        rc = open(os.path.join(d, "audit.rc")).read().strip() if os.path.exists(os.path.join(d, "audit.rc")) else "?"
        if rc != "0":
            continue
        try:
            j = json.load(open(os.path.join(d, "audit.json")))
        except Exception as e:
            print("JSON BAD", n, e); bad += 1; continue
        text = open(os.path.join(d, "audit.out")).read().split("# stage")[-1]
        tvals = [float(x) for x in re.findall(r"^  g \S+\s+eps (\S+)", text, re.M)]
        jvals = [e for row in j["pairs"] + j["walls"] for e, s, p in zip(row["eps"], row["sticks"], row["passes_through"]) if e is not None and not s and not p]
        same = len(tvals) == len([v for v in jvals]) and all(abs(a - b) < 1e-9 for a, b in zip(tvals, jvals))
        if not same:
            print("DIFF", n, len(tvals), len(jvals), tvals[:3], jvals[:3]); bad += 1
        else:
            n_ok += 1
    print(n_ok, "agree,", bad, "differ")
