"""No module uses another module's private names (a leading underscore): a name one module shares
with another is public in the module that owns it, so the seams between modules are where the
meaning changes, not where a file grew long. Every module of the package, read with ast: names in
`from ... import _x`, and attributes `mod._x` of a package module imported as `mod`.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[2] / "src" / "restitution"
MODULES = sorted(PKG.rglob("*.py"))


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _target(path: Path, node: ast.ImportFrom) -> str | None:
    """Dotted name (below restitution) of the module a `from ... import` reads, or None if it is
    not the package's."""
    if node.level:
        here = list(path.relative_to(PKG).with_suffix("").parts)
        if here[-1] == "__init__":
            here = here[:-1] + ["__init__"]
        base = here[:len(here) - node.level]
        return ".".join(base + [p for p in (node.module or "").split(".") if p])
    if node.module == "restitution" or (node.module or "").startswith("restitution."):
        return node.module.removeprefix("restitution").lstrip(".")
    return None


def private_uses(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(), filename=str(path))
    found, modules = [], set()   # local names bound to package modules
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            target = _target(path, node)
            if target is None:
                continue
            for alias in node.names:
                if _private(alias.name):
                    found.append(f"line {node.lineno}: from {target or 'restitution'} import {alias.name}")
                modules.add(alias.asname or alias.name)   # may be a module (`from . import ladder`)
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("restitution."):
                    modules.add(alias.asname or alias.name)
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr) and isinstance(node.value, ast.Name) \
                and node.value.id in modules:
            found.append(f"line {node.lineno}: {node.value.id}.{node.attr}")
    return found


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PKG)))
def test_no_module_uses_another_modules_private_names(path):
    assert not private_uses(path), f"{path.relative_to(PKG)} uses private names of other modules: {private_uses(path)}"


def test_the_check_sees_both_forms(tmp_path):
    bad = tmp_path / "restitution" / "core" / "bad.py"
    bad.parent.mkdir(parents=True)
    bad.write_text("from .series import _poly, public\nfrom . import model as m\nx = m._cache\n"
                   "from .series import __all__\n")
    global PKG
    saved, PKG = PKG, tmp_path / "restitution"
    try:
        uses = private_uses(bad)
    finally:
        PKG = saved
    assert uses == ["line 1: from core.series import _poly", "line 3: m._cache"]
