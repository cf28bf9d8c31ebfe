"""Sweep 32: every deck folder of field rounds 27-31 re-audited with the current code, beside the round's engine
values (liveNN.py's live*.log, the deck run as written) and the round's stored audit.

usage: python sweep.py ROUNDS_STORED NEW_COPY [ROUND ...]
  ROUNDS_STORED: the folder holding fieldNN/ as committed (the round's record, its audit.* at its code);
  NEW_COPY: a copy of those fieldNN/ folders re-audited with tests/fieldkit/audit.sh (ROUND=NN QUICK=1).
Prints one line per folder: round, name, old and new rc, old and new flag (fieldkit.cmp.live's flag: the live pair's
last-stage row against the engine's eps; impact-normalised for wall decks), the kinds of change (changes.py), the
round's hand judgement (judgedNN.txt) and a first verdict; the verdicts that need a look are marked '?'.
"""
import contextlib
import io
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
sys.path.insert(0, here)
from fieldkit import classify, cmp  # noqa: E402
import changes  # noqa: E402


def cmp_lines(H, r):
    kw = dict(tag=f"LIVE{r}", impact=True)
    if r != 27:
        kw["pair"] = lambda n: "types 1 2"
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        cmp.live(H, **kw)
    out = {}
    for l in buf.getvalue().splitlines():
        p = l.split(" | ")
        h = p[0].split(" ", 2)
        out[h[0]] = dict(rc=h[1][3:] if len(h) > 1 else "?", flag=h[2] if len(h) > 2 else "", live=p[1] if len(p) > 1 else "",
                         rows=p[2] if len(p) > 2 else "", err=p[3] if len(p) > 3 else "")
    return out


def note_range(H, name, pair):
    """The time step note's eps range ('eps there A to B') for `pair` in the last stage, over its smallest/largest rows."""
    err = os.path.join(H, "decks", name, "audit.err")
    out = open(os.path.join(H, "decks", name, "audit.out")).read()
    m = re.findall(r"# stage (\d+) of (\d+)", out)
    last = f"(stage {m[-1][0]} of {m[-1][1]}" if m else None
    lo, hi = [], []
    for l in open(err):
        if not l.startswith("restitution deck: " + pair + " ") and not l.startswith("restitution deck: " + pair + ":"):
            continue
        if last and last not in l or not last and "(stage " in l:
            continue
        r = re.search(r"eps there (\S+) to (\S+) by", l)
        if r:
            lo.append(float(r.group(1))); hi.append(float(r.group(2)))
    return (min(lo), max(hi)) if lo else None


def pair_notes(H, name, pair):
    """The stderr notes of deck folder `name` that name `pair` (timings and tags normalised), but the time step
    notes ('a contact lasts N steps'), which the code now gives for every row."""
    err = os.path.join(H, "decks", name, "audit.err")
    if not os.path.exists(err):
        return []
    return [changes._norm(l) for l in open(err).read().splitlines()
            if (pair + ":" in l or pair + " (" in l or pair + " [" in l) and "a contact lasts" not in l]


def verdict(H, c, o, kinds, judged, name, Ho=None):
    """A first verdict from the new cmp line `c` (None: not refereed), the old one `o`, the kinds of change and the
    round's judgement; '?' marks what needs a look by hand."""
    err = os.path.join(H, "decks", name, "audit.err")
    if os.path.exists(err) and "Traceback" in open(err).read():
        return "TRACEBACK"
    rc = open(os.path.join(H, "decks", name, "audit.rc")).read().strip()
    same = set(kinds) <= {"same", "notes", "json-only"}
    if not same and c and o and Ho and c["rows"] == o["rows"] and c["rc"] == o["rc"]:
        pair = c["rows"].split(":")[0].replace("audit ", "").strip()
        same = pair_notes(H, name, pair) == pair_notes(Ho, name, pair)
    was = (judged or ("right (cmp ok)" if o and o.get("flag", "").startswith("ok") else "unjudged"))
    if c is None:
        return ("unrefereed, unchanged: " + was) if same else "unrefereed, changed ?"
    f, live = c["flag"], c["live"]
    engine_ran = "LIVE" in live and "ERROR" not in live
    of = (o or {}).get("flag", "")
    if rc not in ("0", "2"):
        return f"rc {rc} ?"
    if rc == "2":
        if not engine_ran:
            return "right refusal (engine stops too)"
        if same:
            return "refusal where the engine runs, unchanged: " + was
        return ("REGRESSION? refusal where the engine runs, was " + (of or "rc " + (o or {}).get("rc", "?")) + " ?")
    if f.startswith("ok"):
        return "right" + (" (no contact)" if "no contact" in f else "")
    if not engine_ran:
        return ("answered where the engine stops, unchanged: " + was) if same else "answered where the engine stops, changed ?"
    if f == "CHECK":
        pair = c["rows"].split(":")[0].replace("audit ", "").strip()
        e = re.search(r"LIVE\d+ eps (\S+)", live)
        nr = note_range(H, name, pair)
        if e and nr:
            v = float(e.group(1))
            if "wall" in pair:
                z = re.search(r"create_atoms 1 single 0.02 0.02 (\S+)", open(os.path.join(H, "decks", name, "in.deck")).read())
                v = v / (1 + 2 * 9.81 * (float(z.group(1)) - 0.002)) ** 0.5 if z else v
            if nr[0] - 1e-4 <= v <= nr[1] + 1e-4:
                return f"right with its time step note ({nr[0]}..{nr[1]} holds {v:.6f})" + ("" if same else ", changed")
    if same:
        return f"{f}, unchanged: " + was
    if f.startswith("CHECK(no row"):
        if of.startswith("ok"):
            return "conservative left-out? (was right) ?"
        if of == "CHECK" or of.startswith("CHECK(row"):
            return "right left-out (was printed wrong: fixed)"
        return f"left out, changed (was {of or 'rc ' + (o or {}).get('rc', '?')}): " + was + " ?"
    return f"{f}, changed (was {of}) ?"


def main(argv):
    S, N = argv[0], argv[1]
    rounds = [int(x) for x in argv[2:]] or [31, 30, 29, 28, 27]
    for r in rounds:
        Ho, Hn = os.path.join(S, f"field{r}"), os.path.join(N, f"field{r}")
        old, new = cmp_lines(Ho, r), cmp_lines(Hn, r)
        jf = os.path.join(Ho, f"judged{r}.txt")
        if not os.path.exists(jf):
            jf = os.path.join(here, f"judged{r}.txt")
        J = classify.judged(jf) if os.path.exists(jf) else {}
        for n in sorted(os.listdir(os.path.join(Hn, "decks"))):
            if not os.path.exists(os.path.join(Hn, "decks", n, "audit.rc")):
                print(r, n, "NOT AUDITED"); continue
            kinds, det = changes.compare(os.path.join(Ho, "decks", n), os.path.join(Hn, "decks", n))
            o, w = old.get(n, {}), new.get(n, {})
            j = J.get(classify.key(n))
            v = verdict(Hn, new.get(n), old.get(n), kinds, j, n, Ho)
            print(f"{r}\t{n}\trc {o.get('rc', '-')}->{w.get('rc', open(os.path.join(Hn, 'decks', n, 'audit.rc')).read().strip())}"
                  f"\tflag {o.get('flag', '-')} -> {w.get('flag', '-')}\t{','.join(kinds)}\t{v}\t| {w.get('live', '')[:50]}"
                  f" | {w.get('rows', '')} | was {o.get('rows', '')} | {det[:200]}")


if __name__ == "__main__":
    main(sys.argv[1:])
