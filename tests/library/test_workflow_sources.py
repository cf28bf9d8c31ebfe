"""restitution_workflow.sources: the project files a workflow script runs, which the rules declare
as inputs (a module missing there leaves a stale number after a change, with exit status 0)."""

from __future__ import annotations

import doctest
from pathlib import Path

import pytest

from restitution_workflow import sources
from restitution_workflow.sources import closure, imports_of, script_sources

ROOT = Path(__file__).resolve().parents[2]


def test_doctests_run():
    result = doctest.testmod(sources)
    assert result.attempted >= 4 and result.failed == 0


def _tree(tmp_path: Path, files: dict[str, str]) -> Path:
    """A project root holding each package's files in its folder (sources.PACKAGES)."""
    root = tmp_path / "project"
    for rel, text in files.items():
        path = root / sources.PACKAGES[rel.split("/")[0]] / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def _names(root: Path, files) -> set[str]:
    """Each file relative to its package's folder: restitution/core/a.py, restitution_workflow/x.py."""
    return {str(f.relative_to(next(root / d for d in sources.PACKAGES.values() if f.is_relative_to(root / d))))
            for f in files}


@pytest.fixture
def toy(tmp_path) -> Path:
    """A package with a facade __init__ (imports two modules for its public names), a registry
    (its __init__ imports each entry), a reader of the registry and a module under the facade."""
    return _tree(tmp_path, {
        "restitution/__init__.py": "from .core.a import A\nfrom .core.b import B\n",
        "restitution/core/__init__.py": "",
        "restitution/core/a.py": "A = 1\n",
        "restitution/core/b.py": "from .a import A\nB = A\n",
        "restitution/core/c.py": "def late():\n    from . import b   # inside a function: still counted\n",
        "restitution/reg/__init__.py": "from .one import ONE\nfrom .two import TWO\nENTRIES = [ONE, TWO]\n",
        "restitution/reg/one.py": "ONE = 1\n",
        "restitution/reg/two.py": "from ..core.a import A\nTWO = A\n",
        "restitution/reader.py": "from .reg import ENTRIES\n",
        "restitution_workflow/__init__.py": "",
        "restitution_workflow/helpers.py": "import json\nfrom . import atomic\n",
        "restitution_workflow/atomic.py": "",
    })


def test_a_registry_read_brings_every_entry(toy):
    assert _names(toy, closure(toy, ["restitution.reader"])) == {
        "restitution/__init__.py", "restitution/reader.py", "restitution/reg/__init__.py",
        "restitution/reg/one.py", "restitution/reg/two.py", "restitution/core/__init__.py",
        "restitution/core/a.py"}


def test_the_packages_on_the_way_are_listed_but_not_followed(toy):
    # restitution/__init__.py runs (listed) but its import of core.b is not this module's
    assert _names(toy, closure(toy, ["restitution.core.a"])) == {
        "restitution/__init__.py", "restitution/core/__init__.py", "restitution/core/a.py"}


def test_an_import_inside_a_function_counts(toy):
    assert "restitution.core.b" in imports_of(toy, "restitution.core.c")
    assert "restitution/core/a.py" in _names(toy, closure(toy, ["restitution.core.c"]))


def test_a_module_named_for_a_later_import_counts(toy):
    (toy / "src/restitution/late.py").write_text('class E:\n    runner_module = "restitution.core.b"\n'
                                                 'NOT_A_MODULE = "restitution.core.nothing"\n'
                                                 'DISTRIBUTION = "restitution"\n')
    assert imports_of(toy, "restitution.late") == {"restitution.core.b"}


def test_a_script_brings_its_helpers_and_their_imports(toy, tmp_path):
    script = tmp_path / "script.py"
    script.write_text("import numpy\nfrom restitution_workflow.helpers import x\n"
                      "import restitution.core.b\n")
    assert _names(toy, script_sources(toy, script)) == {
        "restitution_workflow/__init__.py", "restitution_workflow/helpers.py", "restitution_workflow/atomic.py",
        "restitution/__init__.py", "restitution/core/__init__.py", "restitution/core/a.py", "restitution/core/b.py"}


def test_a_name_that_is_no_module_is_refused(toy):
    with pytest.raises(FileNotFoundError, match="restitution.nothing"):
        closure(toy, ["restitution.nothing"])


def test_every_module_a_shipped_engine_or_rung_brings_is_an_input_of_the_typed_e_table():
    """The typed-e table reads the engine registry, and each engine's design asks the ladder, which
    reads the rung and build registries: every entry of the three is an input of its rule."""
    src = ROOT / "src"
    got = _names(ROOT, script_sources(ROOT, ROOT / "workflow" / "scripts" / "typed_e.py"))
    entries = {f"restitution/{d}/{f.name}" for d in ("dem/engines", "fast/rungs", "fast/builds")
               for f in (src / "restitution" / d).iterdir() if f.suffix == ".py" and f.name != "__init__.py"}
    entries |= {f"restitution/dem/engines/{e.name}/engine.py" for e in (src / "restitution/dem/engines").iterdir()
                if (e / "engine.py").is_file()}
    assert entries and entries <= got, sorted(entries - got)
