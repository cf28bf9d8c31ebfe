"""Every public entry point has a numpydoc docstring, and every Examples section in the package runs
(issue 45): the API reference is generated from these docstrings, so an example that no longer runs
would be a wrong page. Doctests run here, under tests/conftest.py's hermetic HOME and caches, rather
than through pytest's --doctest-modules, which would collect src/ outside that conftest."""

from __future__ import annotations

import doctest
import importlib
import inspect
import pkgutil

import pytest

import restitution
import restitution.cli
import restitution.dem

#: The public entry points: the package's and the DEM layer's __all__, and the CLI's.
PUBLIC = ([getattr(restitution, n) for n in restitution.__all__]
          + [getattr(restitution.dem, n) for n in restitution.dem.__all__]
          + [restitution.cli.main, restitution.cli.build_parser])
#: Sections each must have; Returns only for functions, Raises where an error can reach the caller
#: (a class documents its constructor's parameters).
SECTIONS = ("Parameters", "Examples")


def _name(obj) -> str:
    return f"{obj.__module__}.{obj.__qualname__}"


@pytest.mark.parametrize("obj", PUBLIC, ids=_name)
def test_every_public_entry_point_has_a_numpydoc_docstring(obj):
    pytest.importorskip("numpydoc", reason="the docs group: make docs or make test installs it")
    from numpydoc.docscrape import ClassDoc, FunctionDoc
    doc = ClassDoc(obj) if inspect.isclass(obj) else FunctionDoc(obj)
    for section in SECTIONS:
        if section == "Parameters" and obj is restitution.cli.build_parser:
            continue        # takes none
        assert doc[section], f"{_name(obj)} has no {section} section"
    if not inspect.isclass(obj):
        assert doc["Returns"], f"{_name(obj)} has no Returns section"


def _modules():
    yield restitution
    for info in pkgutil.walk_packages(restitution.__path__, "restitution."):
        yield importlib.import_module(info.name)


MODULES = sorted({m.__name__ for m in _modules()})


def _doctests(module_name: str):
    module = importlib.import_module(module_name)
    finder = doctest.DocTestFinder(exclude_empty=True)
    # only the tests defined in this module (a name it imports has its examples run where defined)
    return [t for t in finder.find(module, module_name) if t.examples
            and (t.filename or "").endswith(module.__file__.rsplit("/", 1)[-1])]


WITH_EXAMPLES = [m for m in MODULES if _doctests(m)]


def test_the_public_entry_points_have_examples_to_run():
    assert {"restitution.api", "restitution.cli", "restitution.dem.calibrate"} <= set(WITH_EXAMPLES)


@pytest.mark.parametrize("module_name", WITH_EXAMPLES)
def test_docstring_examples_run(module_name):
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in _doctests(module_name):
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples failed in {module_name}"


def test_the_pipeline_helpers_examples_run():
    """restitution_workflow (workflow/lib) is not in the package, but its names are in the API
    reference where the tutorials import them (check_config): its Examples run too."""
    import restitution_workflow
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    finder = doctest.DocTestFinder(exclude_empty=True)
    for info in pkgutil.iter_modules(restitution_workflow.__path__, "restitution_workflow."):
        module = importlib.import_module(info.name)
        for test in finder.find(module, info.name):
            if (test.filename or "") == module.__file__:
                runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.attempted >= 8 and result.failed == 0, result


#: Public names (a module's __all__, defined there) of core/ and dem/ still without the numpydoc
#: sections they need: 143 when counted first (issue 55), fewer since. The count may only fall.
#: The deck modules are left out while they are being rewritten.
UNDOCUMENTED_AT_MOST = 54


def _missing_sections(obj) -> list[str]:
    from numpydoc.docscrape import ClassDoc, FunctionDoc
    doc = ClassDoc(obj) if inspect.isclass(obj) else FunctionDoc(obj)
    missing = []
    if inspect.signature(obj).parameters and not doc["Parameters"]:
        missing.append("Parameters")
    if inspect.isfunction(obj) and not doc["Returns"]:
        missing.append("Returns")
    if not doc["Examples"]:
        missing.append("Examples")
    return missing


def test_core_and_dem_public_names_lose_no_numpydoc_sections():
    pytest.importorskip("numpydoc", reason="the docs group: make docs or make test installs it")
    undocumented = []
    for name in MODULES:
        if not name.startswith(("restitution.core.", "restitution.dem.")) or ".deck" in name:
            continue
        module = importlib.import_module(name)
        for public in getattr(module, "__all__", ()):
            obj = getattr(module, public, None)
            if ((inspect.isclass(obj) or inspect.isfunction(obj)) and obj.__module__ == name
                    and _missing_sections(obj)):
                undocumented.append(f"{name}.{public}")
    assert len(undocumented) <= UNDOCUMENTED_AT_MOST, "\n".join(undocumented)
