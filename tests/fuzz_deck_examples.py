"""The fuzz's example decks (issue 52): LAMMPS' own granular examples (``examples/granular``, ``pour``,
``granregion``) and mutations of them that exercise what the engine now interprets itself: a
coefficient through a variable or a formatted ``$(...)``, ``pair_coeff`` type ranges, a ``set``
before the atoms exist, the contact lines inside ``if``, a ``jump``/``next`` loop, and an extra type
that no particle has (walls only). LAMMPS is the referee of every audited pair: the pair_style and
pair_coeff lines LAMMPS executed (its own substitution) run head-on in LAMMPS with the particles'
sizes as LAMMPS holds them (a poured type: its executed ``fix pour`` line's), extrapolated to dt = 0;
the audit's eps must match to fuzz_deck_checks.DECK_EXTRAPOLATED, or the audit must refuse in one
line. Walls are refereed by the "decks" kind (fuzz_deck_checks), not here.
"""

from __future__ import annotations

import math
import re
import shutil
import tempfile
import traceback
from pathlib import Path

from hypothesis import strategies as st

from fuzz_outcome import one_line

#: Where the Debian package lammps-examples puts them
EXAMPLES = Path("/usr/share/lammps/examples")
FOLDERS = ("granular", "pour", "granregion")
#: The lines that set the contact a mutation may touch
_CONTACT = re.compile(r"^\s*pair_(coeff|style)\s", re.M)


def example_decks() -> list[Path]:
    """The official example decks present on this machine."""
    return sorted(p for folder in FOLDERS for p in (EXAMPLES / folder).glob("in.*"))


def _numbers(line: str) -> list[tuple[int, int]]:
    """Spans of the plain numbers of a contact line after its type fields."""
    words = list(re.finditer(r"\S+", line))
    skip = 3 if words and words[0].group() == "pair_coeff" else 2
    return [(m.start(), m.end()) for m in words[skip:] if re.fullmatch(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", m.group())]


@st.composite
def example_deck_cases(draw):
    """(deck text, folder, speeds, mutations applied): one official deck, 0-3 mutations."""
    decks = example_decks()
    path = draw(st.sampled_from(decks))
    lines = path.read_text().splitlines()
    done: list = []
    header = []
    # two mutations that make a refused example answerable, so that LAMMPS referees its pairs: one
    # diameter where it pours a range (LAMMPS' fix pour diam one), a mapped normal model where it
    # has a cohesive one (JKR, DMT: E, eta_n0, nu kept, the work of adhesion dropped)
    if draw(st.booleans()):
        lines = [re.sub(r"\bdiam\s+range\s+(\S+)\s+\S+", r"diam one \1", ln) for ln in lines]
        lines = [re.sub(r"\bdiam\s+poly\s+\d+\s+(\S+)\s+\S+(\s+\S+\s+\S+)*?(?=\s+[a-z]|\s*$)", r"diam one \1", ln)
                 for ln in lines]
        done.append("one size")
    if draw(st.booleans()):
        lines = [re.sub(r"\b(jkr|dmt)\s+(\S+)\s+(\S+)\s+(\S+)\s+\S+", r"hertz/material \2 \3 \4", ln) for ln in lines]
        done.append("mapped normal model")
    contact = [k for k, ln in enumerate(lines) if _CONTACT.match(ln)]
    for kind in draw(st.lists(st.sampled_from(["variable", "format", "range", "set", "if", "loop", "walls only"]),
                              max_size=3, unique=True)):
        if not contact:
            break
        k = draw(st.sampled_from(contact))
        line = lines[k]
        spans = _numbers(line)
        if kind in ("variable", "format") and spans:
            a, b = draw(st.sampled_from(spans))
            x = float(line[a:b])
            if kind == "variable":
                name = f"fz{len(header)}"
                header.append(f"variable {name} equal {x!r}/2*2")
                lines[k] = line[:a] + "${" + name + "}" + line[b:]
            else:
                digits = draw(st.integers(3, 12))
                lines[k] = line[:a] + f"$({x!r}*1.0:%.{digits}g)" + line[b:]
        elif kind == "range" and line.split()[:3] == ["pair_coeff", "*", "*"]:
            n = _ntypes(lines)
            if n:
                first, second = draw(st.sampled_from([(f"1*{n}", "*"), ("*", f"1*{n}"), (f"*{n}", f"1*")]))
                lines[k] = line.replace("pair_coeff * *", f"pair_coeff {first} {second}", 1)
        elif kind == "set":
            made = next((i for i, ln in enumerate(lines) if ln.split()[:1] == ["create_atoms"]), None)
            if made is None:
                continue
            # after atoms exist (LAMMPS stops on a set without any): atoms made later keep defaults
            lines.insert(made + 1, "set type 1 diameter 0.37 density 3.0")
            contact = [i + (i > made) for i in contact]
        elif kind == "if" and '"' not in line:
            header.append("variable fzon equal 1")
            lines[k] = f'if "${{fzon}} > 0" then "{line.strip()}" else "print skipped"'
        elif kind == "loop":
            lines[k] = f"variable fzn loop 2\nlabel fzagain\n{line}\nnext fzn\njump SELF fzagain"
        elif kind == "walls only":
            box = next((i for i, ln in enumerate(lines) if ln.split()[:1] == ["create_box"]), None)
            if box is not None and lines[box].split()[1].isdigit():
                words = lines[box].split()
                lines[box] = " ".join([words[0], str(int(words[1]) + 1), *words[2:]])
        else:
            continue
        done.append(kind)
    g = 10.0 ** draw(st.floats(-1.5, 0.5))
    return "\n".join(header + lines) + "\n", str(path.parent), [g, 3.0 * g], done


def _ntypes(lines: list[str]) -> int | None:
    box = next((ln for ln in lines if ln.split()[:1] == ["create_box"]), None)
    return int(box.split()[1]) if box and box.split()[1].isdigit() else None


def _engine_view(path: Path, root: Path):
    """What LAMMPS executed (commands, the atoms it held at each run) in the audit's safe copy."""
    from restitution.dem.deck import BUDGET
    from restitution.dem.deck.scratch import scratch_copy
    from restitution.dem.deck.stream import executed, snapshots
    from restitution.dem.engines.lammps import deck_run

    scratch = scratch_copy(path, root, deck_run.marker(root))
    # every run's marker writes the atoms (the audit's own pass writes them where they may change)
    done = deck_run.run_copy(scratch.deck, root, BUDGET, check_every=True)
    return executed(done.echo, scratch), snapshots(done.atoms) + snapshots(done.at_end)


def _poured(text: str) -> tuple[int, set, set] | None:
    """(type, diameters, densities) of an executed fix pour line (LAMMPS' defaults 1 and 1)."""
    w = text.split()
    if len(w) < 7 or w[3] != "pour":
        return None
    diam, dens = {1.0}, {1.0}
    for k, tok in enumerate(w):
        if tok == "diam" and k + 2 < len(w) and w[k + 1] == "one":
            diam = {float(w[k + 2])}
        elif tok == "diam" and k + 3 < len(w) and w[k + 1] == "range":
            diam = {float(w[k + 2]), float(w[k + 3])}
        elif tok == "diam" and k + 2 < len(w) and w[k + 1] == "poly":
            diam = {float(w[k + 3 + 2 * m]) for m in range(int(w[k + 2]))}
        elif tok == "dens" and k + 2 < len(w):
            dens = {float(w[k + 1]), float(w[k + 2])}
    return int(w[5]), diam, dens


def _within(held: set, sphere) -> bool:
    """Whether (R, rho) lies within the radii and densities a type holds (a pour range's ends among them)."""
    return bool(held) and all(min(v[k] for v in held) * (1 - 1e-12) <= sphere[k] <= max(v[k] for v in held) * (1 + 1e-12)
                              for k in (0, 1))


def check_example_deck_case(text: str, folder: str, speeds: list, mutations: list) -> list[dict]:
    """The audit of one (mutated) example deck against LAMMPS, pair by pair (see the module)."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck
    from restitution.dem.engines.lammps.run import lammps_eps
    from restitution.dem.pair import Pair

    from fuzz_deck_checks import _check_deck_row

    case = {"deck": text, "folder": folder, "speeds": speeds, "mutations": mutations}
    with tempfile.TemporaryDirectory(prefix="fuzz-example-") as tmp:
        work = Path(tmp) / "deck"
        shutil.copytree(folder, work)
        path = work / "in.fuzz"
        path.write_text(text)
        try:
            res = audit_deck(text, speeds, path=path)
        except Exception as exc:  # noqa: BLE001
            ok = isinstance(exc, ParameterError) and one_line(exc)
            return [{"method": "example deck (lammps)", "rule": "-", "status": "refused" if ok else "FAIL",
                     "ratio": 0.0, "case": case, "refusal": str(exc) if ok else "",
                     "detail": "" if ok else "".join(traceback.format_exception_only(exc)).strip()}]
        root = Path(tmp) / "view"
        root.mkdir()
        commands, atoms = _engine_view(path, root)
    last = res["stages"][-1]["runs"]
    first_run = (last[0]["file"], last[0]["line"]) if last else None
    style, coeffs, sizes, markers = None, [], {}, 0
    for cmd in commands:
        if cmd.stage is not None and cmd.loc == first_run:
            break
        markers += cmd.stage is not None
        w = cmd.text.split()
        if w[:1] == ["pair_style"]:
            style, coeffs = " ".join(w[1:]), ([] if style is None or w[1] != style.split()[0] else coeffs)
        elif w[:1] == ["pair_coeff"]:
            coeffs.append(cmd.text)
        elif (poured := _poured(cmd.text)) is not None:
            t, diam, dens = poured
            sizes.setdefault(t, set()).update((0.5 * d, rho) for d in diam for rho in dens)
    # the atoms LAMMPS held at that run (the deck's end where it has none)
    held = atoms[min(markers, len(atoms) - 1) if last else -1] if atoms else {}
    for t, got in held.items():
        sizes.setdefault(t, set()).update(got)
    ntypes = max([t for p in res["pairs"] for t in p["types"]] + [1])
    records = []
    for p in res["pairs"]:
        i, j = p["types"]
        if len(sizes.get(i, ())) == 1 and len(sizes.get(j, ())) == 1:
            (ri, rhoi), (rj, rhoj) = next(iter(sizes[i])), next(iter(sizes[j]))
        elif len(p.get("at") or ()) == 2 and all(_within(sizes.get(t, ()), s) for t, s in zip((i, j), p["at"])):
            (ri, rhoi), (rj, rhoj) = p["at"]     # one end of the pair's range: checked at the spheres it names
        else:
            records.append({"method": "example deck (lammps)", "rule": p["end"], "case": case, "pair": f"{i}-{j}",
                            "status": "FAIL", "ratio": math.inf,
                            "detail": f"pair {i}-{j} answered at {p.get('at')}, but LAMMPS holds sizes "
                                      f"{sizes.get(i)} and {sizes.get(j)}"})
            continue
        pair = Pair.spheres(ri, rj, rhoi, rhoj)

        def engine(runs, style=style, lines="\n".join(coeffs)):
            out = []
            for pr, types, g, dt, t_run in runs:
                try:
                    out.append(lammps_eps(pr, lines, g, dt, t_run, types, ntypes, style=style))
                except Exception as exc:  # noqa: BLE001
                    out.append(exc)
            return out
        worst, detail, checked = _check_deck_row(p, pair, (i, j), engine, "lammps", f"pair {i}-{j}")
        records.append({"method": "example deck (lammps)", "rule": p["end"], "case": case, "pair": f"{i}-{j}",
                        "status": "FAIL" if worst > 1.0 else "answered" if checked else "refused", "ratio": worst,
                        "detail": detail if worst > 1.0 else ""})
    return records or [{"method": "example deck (lammps)", "rule": "-", "status": "answered", "ratio": 0.0,
                        "case": case, "detail": ""}]
