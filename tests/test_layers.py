"""The package's layers import only downward: core <- fast, core <- audit, and api / cli on top.

Read from the source with ast (relative and absolute imports, at module level or inside
functions), so a lazy import inside a function cannot hide a wrong direction.
"""

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[1] / "src" / "restitution"

#: What each layer may import from the package (itself included).
ALLOWED = {
    "core": {"core"},
    "fast": {"core", "fast"},
    "audit": {"core", "fast", "audit"},   # audit.relations hands the paper's c's to the fast ladder
    "dem": {"core", "fast", "dem"},
    "api": {"core", "fast", "audit", "api"},
    "cli": {"core", "fast", "audit", "dem", "api", "cli"},
    "__init__": {"core", "api", "__init__"},
}


def _layer(path: Path) -> str:
    rel = path.relative_to(PKG)
    return rel.parts[0] if len(rel.parts) > 1 else rel.stem


def _imported_layers(path: Path, root: Path = PKG) -> set[str]:
    here = list(path.relative_to(root).with_suffix("").parts)
    found = set()
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                target = here[:len(here) - node.level] + [p for p in (node.module or "").split(".") if p]
                # `from . import api` at the top: the names are the modules
                found.update(target[:1] or [a.name for a in node.names])
            elif node.module and node.module.startswith("restitution."):
                found.add(node.module.split(".")[1])
            elif node.module == "restitution":
                found.update(a.name for a in node.names)
        elif isinstance(node, ast.Import):
            found.update(a.name.split(".")[1] for a in node.names if a.name.startswith("restitution."))
    return found


MODULES = sorted(PKG.rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_imports_point_down(path):
    layer = _layer(path)
    assert layer in ALLOWED, f"{path.relative_to(PKG)} is in no layer: add it to ALLOWED or move it"
    wrong = _imported_layers(path) - ALLOWED[layer]
    assert not wrong, f"{path.relative_to(PKG)} ({layer}) imports {sorted(wrong)}"


def test_fast_and_core_never_import_audit():
    for path in MODULES:
        if _layer(path) in ("core", "fast"):
            assert "audit" not in _imported_layers(path), path


def test_the_check_sees_a_wrong_import(tmp_path):
    """The checker itself: upward imports planted in a module of core, one lazy, are found."""
    bad = tmp_path / "core" / "bad.py"
    bad.parent.mkdir()
    bad.write_text("from .errors import ParameterError\n\n\ndef f():\n    from ..audit import claims\n"
                   "    from restitution.fast import ladder\n")
    assert _imported_layers(bad, tmp_path) == {"core", "audit", "fast"}
