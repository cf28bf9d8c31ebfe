"""Field round 40: for each audited deck, the rc and which of the notes under attack its stderr holds: SPAN ("the
contact's eps changes at the start of stage"), SHORT ("run fewer steps than one contact lasts"), KICK ("changes the
atoms' velocities, places or sizes between runs"), NU ("not understood"), and the last stderr line of a refusal.
usage: python notes40.py > notes40.out"""
import glob
import os

HERE = os.path.dirname(os.path.abspath(__file__))
KEYS = {"SPAN": "eps changes at the start of stage", "SHORT": "fewer steps than one contact lasts",
        "KICK": "velocities, places or sizes between runs", "NU": "not understood", "NOTAUD": "not audited",
        "LATE": "found late", "TB": "Traceback"}
for d in sorted(glob.glob(os.path.join(HERE, "decks", "*"))):
    if not os.path.exists(d + "/audit.rc"):
        continue
    rc = open(d + "/audit.rc").read().strip()
    err = open(d + "/audit.err").read()
    flags = [k for k, v in KEYS.items() if v in err]
    last = err.strip().splitlines()[-1][:200] if rc != "0" and err.strip() else ""
    print(os.path.basename(d), "rc=" + rc, ",".join(flags) or "-", last)
