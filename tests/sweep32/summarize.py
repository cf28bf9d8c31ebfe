"""Sweep 32's outcome per deck folder and counts per round, from sweep.py's lines (sweepNN.tsv) and the hand
judgements of manual.txt (lines ``ROUND NAME => OUTCOME | why``).
usage: python summarize.py sweep31.tsv sweep30.tsv ...   -> outcome lines (ROUND NAME OUTCOME | verdict), then counts
"""
import collections
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))

ORDER = ["TRACEBACK", "SILENTLY WRONG", "avoidable refusal", "conservative left-out", "other (rows beside the live pair, claims)",
         "right", "right with its note's range/hedge", "right refusal or left-out with reason", "not refereed", "CHECK BY HAND"]


def outcome(v):
    """The outcome class of sweep.py verdict `v` (hand judgement still needed: 'CHECK BY HAND')."""
    j = v.split(": ", 1)[1] if ", unchanged: " in v or v.startswith("unrefereed, unchanged: ") else ""
    if v.startswith("left out, changed (was rc 2): "):
        J = v.split(": ", 1)[1].upper()
        if "AVOIDABLE" in J or "FALSE REFUSAL" in J:
            return "conservative left-out"  # a refusal where the engine gives the law, now a left-out pair
        if J.startswith("FAIR REFUSAL"):
            return "right refusal or left-out with reason"
    if v.startswith("TRACEBACK"):
        return "TRACEBACK"
    if v.startswith("right with its time step note"):
        return "right with its note's range/hedge"
    if v.startswith("right refusal") or v.startswith("right left-out"):
        return "right refusal or left-out with reason"
    if v.startswith("right"):
        return "right"
    if v.startswith("conservative left-out"):
        return "conservative left-out"
    if j:
        J = j.upper()
        if J.startswith("SILENTLY WRONG"):
            return "SILENTLY WRONG"
        if "AVOIDABLE REFUSAL" in J or "FALSE REFUSAL" in J:
            return "avoidable refusal"
        if J.startswith("AVOIDABLE") or J.startswith("CONSERVATIVE") or "LEFT OUT BESIDE A NOTE WHOSE REASON" in J \
                or J.startswith("LEFT OUT WITH THE PERIODIC") or J.startswith("WRONG BESIDE A FALSE NOTE"):
            return "conservative left-out"
        if J.startswith("WRONG CLAIM") or J.startswith("ROWS FOR") or J.startswith("ANSWERED WHERE"):
            return "other (rows beside the live pair, claims)"
        if "NOT REFEREED" in J or J.startswith("UNJUDGED") or J.startswith("LIGGGHTS TUTORIAL"):
            return "not refereed"
        if J.startswith("FAIR REFUSAL") or J.startswith("RIGHT REFUSAL") or J.startswith("RIGHT RC 2") \
                or J.startswith("CORRECT: LEFT OUT") or "LEFT OUT" in J and J.startswith("CORRECT"):
            return "right refusal or left-out with reason"
        if "HEDGED" in J or "NOTE" in J and J.startswith("CORRECT") or J.startswith("RIGHT: TIME-STEP"):
            return "right with its note's range/hedge"
        if J.startswith("CORRECT") or J.startswith("RIGHT") or J.startswith("EFFECT NAMED") or J.startswith("ANSWERED"):
            return "right"
    return "CHECK BY HAND"


def main(argv):
    manual = {}
    mf = os.path.join(here, "manual.txt")
    if os.path.exists(mf):
        for l in open(mf):
            if l.strip() and not l.startswith("#"):
                k, v = l.split(" => ", 1)
                manual[tuple(k.split())] = v.strip()
    counts = collections.defaultdict(collections.Counter)
    for f in argv:
        for l in open(f):
            p = l.rstrip("\n").split("\t")
            r, n, v = p[0], p[1], p[5]
            m = manual.get((r, n.split("_")[0])) or manual.get((r, n))
            o = m.split(" | ")[0] if m else outcome(v)
            counts[r][o] += 1
            print(r, n, "=>", o, "|", (m.split(" | ", 1)[1] if m and " | " in m else v)[:300])
    print()
    rounds = sorted(counts, reverse=True)
    print("| outcome | " + " | ".join(rounds) + " | all |")
    print("|---|" + "---|" * (len(rounds) + 1))
    for o in ORDER:
        if any(counts[r][o] for r in rounds):
            print(f"| {o} | " + " | ".join(str(counts[r][o]) for r in rounds) + f" | {sum(counts[r][o] for r in rounds)} |")
    print("| total | " + " | ".join(str(sum(counts[r].values())) for r in rounds) + f" | {sum(sum(c.values()) for c in counts.values())} |")


if __name__ == "__main__":
    main(sys.argv[1:])
