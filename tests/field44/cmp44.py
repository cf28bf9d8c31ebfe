"""Field round 44: the live pair's eps measured by the engine (live*.log: the deck as written, on 1 process and on
several) beside the audit's rows for that pair in every stage (audit.out, tests/fieldkit/rows.py).
Round 36 added `match=`: the stages whose row is within 0.004 of the 1-process value (a run every is made as its
parts, so the pair meets in a stage before the last: the stage is judged by hand in judged44.txt). Flags: the last stage's row against the 1-process value (within 0.004, the step error at dt 1e-6 s being 0.0015), as
rounds 27-33 (`ok`, `ok(no contact)`, `CHECK`, `noeps-row`), and NPDIFF where the values on 1 and on several processes
differ by more than 0.002 (or one runs and the other stops) while the audit answered rc 0.
usage: python cmp44.py > cmp44.out (the referee is round 37's live37.py: its lines say LIVE37)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import cmp_np  # noqa: E402

if __name__ == "__main__":
    cmp_np.main(os.path.dirname(os.path.abspath(__file__)), tag="LIVE37")
