"""The package's layers import only downward: core <- fast, core <- audit, and api / cli on top.

Read from the source with ast (relative and absolute imports, at module level or inside
functions), so a lazy import inside a function cannot hide a wrong direction.
"""

import ast
from pathlib import Path

import pytest

PKG = Path(__file__).resolve().parents[2] / "src" / "restitution"

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


# ------------------------------------------------------------------ rungs: no cycle, no private names
def _module_name(path: Path, root: Path = PKG) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, root: Path = PKG):
    """(imported module, names) for every package import in ``path`` (lazy ones included)."""
    here = _module_name(path, root).split(".")
    package = here if path.name == "__init__.py" else here[:-1]
    for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = package[:len(package) - (node.level - 1)] + [p for p in (node.module or "").split(".") if p]
            yield ".".join(base), [a.name for a in node.names]


def _private_imports(root: Path = PKG, under: str = "fast") -> list[str]:
    found = []
    for path in sorted((root / under).rglob("*.py")):
        for module, names in _imports(path, root):
            modules = {_module_name(p, root) for p in root.rglob("*.py")}
            private = [n for n in names if n.startswith("_") and f"{module}.{n}" not in modules]
            if private:
                found.append(f"{path.relative_to(root)} imports {private} from {module}")
    return found


def _cycles(root: Path = PKG, under: str = "fast") -> list[tuple[str, str]]:
    modules = {_module_name(p, root): p for p in (root / under).rglob("*.py")}
    graph = {m: set() for m in modules}
    for m, path in modules.items():
        for target, names in _imports(path, root):
            for t in [target, *(f"{target}.{n}" for n in names)]:
                if t in modules and t != m and not m.startswith(t + "."):
                    graph[m].add(t)
    pairs = []
    for a in graph:   # a pair that reaches each other through the graph
        pairs += [(a, b) for b in _reach(graph, a) if b != a and a in _reach(graph, b)]
    return pairs


def _reach(graph, start):
    seen, todo = set(), list(graph[start])
    while todo:
        b = todo.pop()
        if b not in seen:
            seen.add(b)
            todo += graph[b]
    return seen


def test_fast_imports_no_private_name_of_another_module():
    assert _private_imports() == []


def test_fast_has_no_import_cycle():
    """fast.ladder and fast.overlap used to import each other (COST, TOL_FLOOR, _Quote, rung_names)."""
    assert _cycles() == []


def test_the_rung_checks_see_a_cycle_and_a_private_import(tmp_path):
    fast = tmp_path / "fast"
    fast.mkdir()
    (fast / "__init__.py").write_text("")
    (fast / "a.py").write_text("from .b import _Quote\n")
    (fast / "b.py").write_text("def f():\n    from .a import g\n")
    assert _private_imports(tmp_path) == ["fast/a.py imports ['_Quote'] from fast.b"]
    assert sorted(_cycles(tmp_path)) == [("fast.a", "fast.b"), ("fast.b", "fast.a")]


# ------------------------------------------------------------------ dem: folders import one way
def _dem_folder(package: str) -> str:
    """The folder node of a package of dem: ``dem`` for its top-level files, ``dem/deck`` for a
    subfolder's, ``dem/engines/lammps`` for an engine's (each engine its own node)."""
    parts = package.split(".")[1:]   # below dem
    if parts and parts[0] == "engines":
        return "/".join(["dem", *parts[:2]]) if len(parts) > 1 else "dem/engines"
    return "/".join(["dem", *parts[:1]])


def _dem_folder_edges(root: Path = PKG) -> set[tuple[str, str]]:
    """(importing folder, imported folder) for every import between two folders of dem, lazy ones
    and absolute ones (``restitution.dem.x``) included."""
    paths = sorted((root / "dem").rglob("*.py"))
    modules = {_module_name(p, root): p for p in paths}
    # the folder of a module is its package's: a subfolder's __init__ belongs to that subfolder
    node = {m: _dem_folder(m if p.name == "__init__.py" else m.rsplit(".", 1)[0]) for m, p in modules.items()}
    edges = set()
    for m, path in modules.items():
        here = m.split(".")
        package = here if path.name == "__init__.py" else here[:-1]
        for n in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            targets = []
            if isinstance(n, ast.ImportFrom) and n.level:
                base = ".".join(package[:len(package) - (n.level - 1)] + ([n.module] if n.module else []))
                targets = [base, *(f"{base}.{a.name}" for a in n.names)]
            elif isinstance(n, ast.ImportFrom) and (n.module or "").startswith("restitution."):
                base = n.module.removeprefix("restitution.")
                targets = [base, *(f"{base}.{a.name}" for a in n.names)]
            elif isinstance(n, ast.Import):
                targets = [a.name.removeprefix("restitution.") for a in n.names if a.name.startswith("restitution.")]
            for t in targets:
                if t in modules and node[t] != node[m]:
                    edges.add((node[m], node[t]))
    return edges


def _folder_cycles(edges: set[tuple[str, str]]) -> list[tuple[str, str]]:
    graph = {}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
        graph.setdefault(b, set())
    return sorted((a, b) for a in graph for b in _reach(graph, a) if b != a and a in _reach(graph, b))


def test_dem_folders_import_one_way():
    """No folder of dem imports one that imports it back: the model at dem's top, the dialects'
    base (dialect) below the engines, the deck reader and scenes above them."""
    edges = _dem_folder_edges()
    assert ("dem/deck", "dem/engines/lammps") in edges   # the check sees the real imports
    assert _folder_cycles(edges) == []


def test_the_folder_check_sees_the_flat_layout(tmp_path):
    """dem as it was: the deck reader at dem's top importing an engine's dialect, which imports the
    deck state back from dem's top."""
    dem = tmp_path / "dem"
    (dem / "engines" / "lammps").mkdir(parents=True)
    for f in ("__init__.py", "engines/__init__.py", "engines/lammps/__init__.py"):
        (dem / f).write_text("")
    (dem / "deck_state.py").write_text("from .pair import Pair\n")
    (dem / "pair.py").write_text("")
    (dem / "deck.py").write_text("def f():\n    from .engines.lammps import deck_run\n")
    (dem / "engines" / "lammps" / "deck_run.py").write_text("from ...deck_state import Deck\n")
    edges = _dem_folder_edges(tmp_path)
    assert edges == {("dem", "dem/engines/lammps"), ("dem/engines/lammps", "dem")}
    assert _folder_cycles(edges) == [("dem", "dem/engines/lammps"), ("dem/engines/lammps", "dem")]
