"""What changed in the paper between a git revision and this tree: results/paper/diff.pdf.

    python workflow/tools/build_diff.py BASE          (make diff BASE=<git revision>)

The manuscript is built at BASE in a worktree of its own (build/diff/<commit>/, kept, so a second
diff against the same BASE reuses its cached results) and here. Each side is flattened: every
\\input inlined and every macro of a generated file (the numbers the pipeline computes) replaced by
its value, so a changed number is a changed word for latexdiff, which marks it. The marked-up
source is compiled here (figures as they are now) to results/paper/diff.pdf.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MAIN = Path("paper") / "restitution.tex"
DEFINITION = re.compile(r"\\newcommand\{\\([A-Za-z]+)\}\{")
INPUT = re.compile(r"\\input\{([^}]*)\}")


def _braced(text: str, start: int) -> int:
    """Index just after the brace group that opens at text[start - 1] == '{'."""
    depth = 1
    for i in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0) if text[i - 1] != "\\" else 0
        if depth == 0:
            return i + 1
    raise ValueError("unbalanced braces")


def _expand(text: str, macros: dict[str, str]) -> str:
    """Generated macros replaced by their values (a `\\Name{}` spacing guard goes with the macro:
    latexdiff would otherwise split `\\texttt{...}{}` across its markup)."""
    use = re.compile(r"\\([A-Za-z]+)(\{\})?(?![A-Za-z])")
    for _ in range(5):   # values may use other generated macros
        new = use.sub(lambda m: macros.get(m.group(1), m.group(0)), text)
        if new == text:
            break
        text = new
    return text


def flatten(tree: Path) -> str:
    """paper/restitution.tex of `tree` with inputs inlined and generated macros expanded."""
    macros: dict[str, str] = {}

    def inline(path: Path) -> str:
        text = (tree / path).read_text()
        generated = path.parts[0] == "results"
        out, pos = [], 0
        for m in DEFINITION.finditer(text):
            if not generated:
                continue
            end = _braced(text, m.end())
            macros[m.group(1)] = text[m.end():end - 1]
            out.append(text[pos:m.start()])
            pos = end
        text = "".join(out) + text[pos:]
        return INPUT.sub(lambda m: inline(_source(_expand(m.group(1), macros))), text)

    def _source(name: str) -> Path:
        return Path(name if name.endswith(".tex") else name + ".tex")

    return _expand(inline(MAIN), macros)


def run(cmd: list[str], cwd: Path, what: str) -> None:
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout[-3000:] + proc.stderr[-3000:])
        raise SystemExit(f"diff: {what} failed (exit {proc.returncode})")


def build_base(base: str) -> Path:
    commit = subprocess.run(["git", "rev-parse", "--verify", f"{base}^{{commit}}"], cwd=ROOT, capture_output=True,
                            text=True)
    if commit.returncode != 0:
        raise SystemExit(f"diff: BASE = {base!r}: not a git revision of this repository")
    sha = commit.stdout.strip()
    tree = ROOT / "build" / "diff" / sha[:12]
    if not (tree / ".git").exists():
        shutil.rmtree(tree, ignore_errors=True)
        run(["git", "worktree", "add", "--detach", "--force", str(tree), sha], ROOT, "git worktree add")
    if not (tree / ".venv").exists():
        (tree / ".venv").symlink_to(ROOT / ".venv", target_is_directory=True)
    print(f"diff: building the manuscript at {base} ({sha[:12]}) in {tree.relative_to(ROOT)} ...", flush=True)
    run(["make", "--no-print-directory", "-o", ".venv/.installed-stamp", "-o", "tex", "paper"], tree,
        f"the build at {base}")
    return tree


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", help="git revision to compare with (a commit, tag or branch)")
    args = parser.parse_args(argv)
    if not args.base:
        raise SystemExit("diff: BASE is empty: give a git revision, e.g. make diff BASE=HEAD~1")
    base_tree = build_base(args.base)
    work = ROOT / "build" / "diff"
    (work / "old.tex").write_text(flatten(base_tree))
    (work / "new.tex").write_text(flatten(ROOT))
    with open(ROOT / "diff.tex", "w") as fh:   # compiled from the root: the figures' paths resolve
        proc = subprocess.run(["latexdiff", "--type=CFONT", str(work / "old.tex"), str(work / "new.tex")],
                              stdout=fh, stderr=subprocess.PIPE, text=True)
    try:
        if proc.returncode != 0:
            raise SystemExit(f"diff: latexdiff failed: {proc.stderr[-500:]}")
        env_date = {**os.environ, "FORCE_SOURCE_DATE": "1"}
        for old in work.glob("diff.*"):   # latexmk would not retry a failed run by itself
            old.unlink()
        proc = subprocess.run(["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error",
                               f"-outdir={work}", "diff.tex"], cwd=ROOT, capture_output=True, text=True, env=env_date)
        if proc.returncode != 0:
            sys.stderr.write(proc.stdout[-3000:])
            raise SystemExit("diff: the marked-up manuscript did not compile (log in build/diff/diff.log)")
    finally:
        shutil.move(ROOT / "diff.tex", work / "diff.tex")
    dest = ROOT / "results" / "paper" / "diff.pdf"
    dest.parent.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(work / "diff.pdf", dest)
    print(f"diff: {dest}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
