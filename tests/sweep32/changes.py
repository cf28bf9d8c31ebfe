"""What changed in a deck folder's audit between two copies of a field round: the round's stored audit.* (its record)
and a re-audit with the current code (a copy of the round's folder, audited with tests/fieldkit/audit.sh QUICK=1).

Kinds, worst first: rc (exit code changed), rows-out (a pair or wall row of some stage gone), rows-in (a row added),
eps (a printed eps/word changed beyond 1e-6 relative), flags (a row's [bracket] annotation changed), notes (only the
stderr notes/reasons changed), json-only (audit.json differs beyond float noise, the text alike), same.
usage: python changes.py OLD_ROUND_DIR NEW_ROUND_DIR  -> one line per folder: NAME KIND[,KIND...] | detail
"""
import json
import os
import re
import sys


def parse_out(path):
    """{(stage, name): (flag, [row words per g])} from audit.out; stage 0 for a one-stage deck."""
    res, st, name = {}, 0, None
    if not os.path.exists(path):
        return res
    for l in open(path):
        if l.startswith("# stage"):
            st += 1
        elif l.startswith("#"):
            continue
        elif not l.startswith(" "):
            m = re.match(r"(types \d+ \d+|type \d+ on wall [^:\s\[(]+)( \(([^()]*)\))?( \[.*\])?: ", l)
            if m:
                q = (m.group(3) or "").split(" ")[0]
                name = (st, m.group(1) + (" " + q if q in ("smallest", "largest") else ""))
                res[name] = ((m.group(4) or "").strip() + ("(" + m.group(3) + ")" if m.group(3) and q not in ("smallest", "largest") else ""), [])
            elif l.startswith("type"):
                name = (st, re.split(r" \(| \[|:", l)[0])
                res[name] = (l.strip(), [])
            else:
                name = None
        elif name and l.split()[:1] == ["g"]:
            res[name][1].append(" ".join(l.split()[2:]))
    return res


def _num(s):
    m = re.match(r"eps (\S+)", s)
    return m.group(1) if m else None


def rows_differ(a, b):
    """True where two rows' words differ beyond float noise (eps to 1e-6 relative; '(N steps...)' ignored)."""
    if len(a) != len(b):
        return True
    for x, y in zip(a, b):
        if _num(x) and _num(y):
            try:
                vx = [float(v) for v in _num(x).split("..")]
                vy = [float(v) for v in _num(y).split("..")]
            except ValueError:
                if _num(x) != _num(y):
                    return True
                continue
            if len(vx) != len(vy) or any(abs(p - q) > 1e-6 * max(1, abs(p)) for p, q in zip(vx, vy)):
                return True
        elif re.sub(r"\(.*", "", x).strip() != re.sub(r"\(.*", "", y).strip():
            return True
    return False


def rnd(o):
    if isinstance(o, str):
        return _norm(o)
    if isinstance(o, float):
        return float(f"{o:.6g}")
    if isinstance(o, dict):
        return {k: rnd(v) for k, v in o.items()}
    if isinstance(o, list):
        return [rnd(v) for v in o]
    return o


def jdiff(a, b, p="", out=None):
    """The paths (list indices dropped) where two JSON values differ."""
    out = set() if out is None else out
    if isinstance(a, dict) and isinstance(b, dict):
        for k in set(a) | set(b):
            if k not in a or k not in b:
                out.add(p + "." + k + ("+" if k not in a else "-"))
            else:
                jdiff(a[k], b[k], p + "." + k, out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out.add(p + "[len]")
        for x, y in zip(a, b):
            jdiff(x, y, p + "[]", out)
    elif a != b:
        out.add(p)
    return out


def _load(p):
    try:
        return rnd(json.load(open(p)))
    except Exception:
        return None


def _notes(p):
    if not os.path.exists(p):
        return []
    return [_norm(l) for l in open(p).read().splitlines()]


def _norm(s):
    """A note without its timings and the pass's per-run tag."""
    return re.sub(r"#restitution-[0-9a-f]+", "#restitution-", re.sub(r"\d+(\.\d+)? s\b", "", s))


def compare(old, new):
    """(kinds, detail) for deck folders `old` and `new`."""
    kinds, det = [], []
    rco = open(old + "/audit.rc").read().strip() if os.path.exists(old + "/audit.rc") else "?"
    rcn = open(new + "/audit.rc").read().strip() if os.path.exists(new + "/audit.rc") else "?"
    if rco != rcn:
        kinds.append("rc"); det.append(f"rc {rco}->{rcn}")
    o, n = parse_out(old + "/audit.out"), parse_out(new + "/audit.out")
    gone = [k for k in o if k not in n]
    come = [k for k in n if k not in o]
    if gone:
        kinds.append("rows-out"); det.append("out: " + ", ".join(f"s{s}:{x}" for s, x in gone))
    if come:
        kinds.append("rows-in"); det.append("in: " + ", ".join(f"s{s}:{x}" for s, x in come))
    ch = [k for k in o if k in n and rows_differ(o[k][1], n[k][1])]
    if ch:
        kinds.append("eps")
        det.append("eps: " + "; ".join(f"s{s}:{x} {_num(o[(s, x)][1][0]) if o[(s, x)][1] else '-'}->"
                                       f"{_num(n[(s, x)][1][0]) if n[(s, x)][1] else '-'}" for s, x in ch))
    fl = [k for k in o if k in n and o[k][0] != n[k][0]]
    if fl:
        kinds.append("flags"); det.append("flags: " + ", ".join(f"s{s}:{x}" for s, x in fl))
    if not kinds and _notes(old + "/audit.err") != _notes(new + "/audit.err"):
        kinds.append("notes")
    jo, jn = _load(old + "/audit.json"), _load(new + "/audit.json")
    if not kinds and jo != jn:
        kinds.append("json-only"); det.append(" ".join(sorted(jdiff(jo, jn)))[:300] if jo and jn else "json unreadable")
    return kinds or ["same"], "; ".join(det)


def main(argv):
    O, N = argv[0], argv[1]
    for n in sorted(os.listdir(os.path.join(N, "decks"))):
        k, d = compare(os.path.join(O, "decks", n), os.path.join(N, "decks", n))
        print(n, ",".join(k), "|", d)


if __name__ == "__main__":
    main(sys.argv[1:])
