"""The source files a workflow script runs: the closure of its imports within the project's two
packages (the library under ``src/``, these helpers under ``workflow/lib/``), declared as the
rule's inputs, so that a change to any module a script runs reruns the rule, and a change to any
other module does not. Snakemake does not follow a script's imports.

The walk reads the files (``ast``), it imports nothing, and it errs on the side of rerunning: an
import inside a function counts, and so does a module named in a string assigned to a name (an
engine's ``deck_module = "restitution.dem.engines.lammps.deck"``, imported by name on first use).
Two rules keep it complete and still narrow:

- A package's ``__init__`` is followed where a name is imported *from* it (``from .rungs import
  ladder_rungs``, ``from .engines import ENGINES``). The entries of a registry are then inputs of
  every rule that reads the registry; listing them by hand went stale when an entry was added.
- The packages on the way to a module (``restitution`` and ``restitution.core`` for
  ``restitution.core.series``) are listed, because they run on import, but their own imports are
  not followed. ``restitution/__init__.py`` imports the series and the integrators for the public
  API, and a change to the series must not rerun the integrations.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

__all__ = ["PACKAGES", "module_file", "imports_of", "closure", "script_sources"]

#: The top-level packages whose modules count as sources, each with the folder (relative to the
#: project's root) that holds it: the library ships alone in its wheel, the helpers stay with the
#: workflow.
PACKAGES = {"restitution": Path("src"), "restitution_workflow": Path("workflow/lib")}


def module_file(root: Path, dotted: str) -> Path | None:
    """The file of a module or package of the project, or None.

    Parameters
    ----------
    root : Path
        The project's root (the folder of the Snakefile); each package is in its folder of
        `PACKAGES` below it.
    dotted : str
        A dotted name, such as ``"restitution.core.series"`` or ``"restitution.core"``.

    Returns
    -------
    Path or None
        ``.../core/series.py``, or a package's ``__init__.py``; None where neither exists.

    Examples
    --------
    >>> from pathlib import Path
    >>> root = Path(__file__).resolve().parents[3]
    >>> module_file(root, "restitution.core").name, module_file(root, "restitution.core.nothing")
    ('__init__.py', None)
    >>> module_file(root, "restitution_workflow.sources").relative_to(root).as_posix()
    'workflow/lib/restitution_workflow/sources.py'
    """
    parts = dotted.split(".")
    if parts[0] not in PACKAGES:
        return None
    base = (root / PACKAGES[parts[0]]).joinpath(*parts)
    for f in (base.with_suffix(".py"), base / "__init__.py"):
        if f.is_file():
            return f
    return None


def _statements(body):
    """Every statement, nested ones (in functions, classes, if/try/with/match) included. Imports are
    statements, so expressions need not be walked: ast.walk over every node took most of the
    Snakefile's load time, which every run, dry run and cluster job step pays."""
    for node in body:
        yield node
        for field in ("body", "orelse", "finalbody", "handlers"):
            yield from _statements(getattr(node, field, ()))
        for case in getattr(node, "cases", ()):
            yield from _statements(case.body)


def _imports_in(root: Path, path: Path, dotted: str | None) -> frozenset[str]:
    """Project modules and packages the file imports; ``dotted`` is its own name (None for a
    script, which belongs to no package and so has no relative imports)."""
    # the module's own name, with a package's __init__ one level down, so that "from . import x"
    # (level 1) drops exactly the last part
    here = []
    if dotted:
        here = dotted.split(".") + (["__init__"] if path.name == "__init__.py" else [])
    found = set()
    for node in _statements(ast.parse(path.read_text(), filename=str(path)).body):
        if isinstance(node, ast.ImportFrom):
            base = here[:len(here) - node.level] if node.level else []
            target = base + [p for p in (node.module or "").split(".") if p]
            if not target or target[0] not in PACKAGES:
                continue
            found.add(".".join(target))
            found.update(".".join(target + [a.name]) for a in node.names)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] in PACKAGES)
        elif isinstance(node, (ast.Assign, ast.AnnAssign)) and isinstance(node.value, ast.Constant) \
                and isinstance(node.value.value, str) and "." in node.value.value \
                and node.value.value.split(".")[0] in PACKAGES:
            # a module named to be imported on first use (an engine's deck_module = "restitution....");
            # a bare package name ("restitution", as a distribution's name) is no such module
            found.add(node.value.value)
    return frozenset(m for m in found if module_file(root, m) is not None)


@functools.cache
def imports_of(root: Path, dotted: str) -> frozenset[str]:
    """The project's modules and packages that module ``dotted`` imports, anywhere in its file.

    Parameters
    ----------
    root : Path
        The project's root, where ``src/`` and ``workflow/lib/`` lie (the import roots searched).
    dotted : str
        The importing module.

    Returns
    -------
    frozenset of str
        Dotted names. ``from .engines import ENGINES`` gives the package ``...engines``;
        ``from .core import conditioning`` gives both ``...core`` and ``...core.conditioning``.

    Raises
    ------
    FileNotFoundError
        If ``dotted`` is not a module of the project.

    Examples
    --------
    >>> from pathlib import Path
    >>> root = Path(__file__).resolve().parents[3]
    >>> "restitution.dem.engines" in imports_of(root, "restitution.dem.engines.typed_e_table")
    True
    """
    f = module_file(root, dotted)
    if f is None:
        raise FileNotFoundError(f"{dotted}: no such module under {root}")
    return _imports_in(root, f, dotted)


def closure(root: Path, modules) -> list[Path]:
    """The files the given modules run: their imports' closure, and each package on the way.

    Parameters
    ----------
    root : Path
        The project's root.
    modules : iterable of str
        Dotted names of modules or packages.

    Returns
    -------
    list of Path
        Sorted. A package's ``__init__.py`` is followed only where it is imported from (see the
        module docstring).

    Raises
    ------
    FileNotFoundError
        If a name is not a module of the project.

    See Also
    --------
    script_sources : The same closure for a workflow script, from the file itself.

    Examples
    --------
    >>> from pathlib import Path
    >>> root = Path(__file__).resolve().parents[3]
    >>> files = {f.relative_to(root).as_posix() for f in closure(root, ["restitution.dem.engines.typed_e_table"])}
    >>> "src/restitution/dem/engines/yade/engine.py" in files     # a registry's entry
    True
    >>> "src/restitution/core/series.py" in {f.relative_to(root).as_posix() for f in
    ...                                      closure(root, ["restitution.core.collision"])}
    False
    """
    seen, todo = set(), list(modules)
    while todo:
        m = todo.pop()
        if m not in seen:
            seen.add(m)
            todo.extend(imports_of(root, m) - seen)
    parts = [m.split(".") for m in seen]
    on_the_way = {".".join(p[:i]) for p in parts for i in range(1, len(p))}
    return sorted({module_file(root, m) for m in seen | on_the_way})


def script_sources(root: Path, script: Path) -> list[Path]:
    """The project files a workflow script runs (the closure of its own imports).

    Parameters
    ----------
    root : Path
        The project's root.
    script : Path
        A script outside the packages (``workflow/scripts/*.py``).

    Returns
    -------
    list of Path
        Sorted; the script itself is not among them.

    Raises
    ------
    FileNotFoundError
        If the script does not exist.

    Examples
    --------
    >>> from pathlib import Path
    >>> root = Path(__file__).resolve().parents[3]
    >>> files = script_sources(root, root / "workflow" / "scripts" / "typed_e.py")
    >>> sorted(f.name for f in files if f.parent.name == "restitution_workflow")
    ['__init__.py', 'atomic.py', 'latex.py', 'pdf_text.py', 'pipeline.py']
    """
    return closure(root, _imports_in(root, script, None))
