"""Sphinx configuration of the restitution documentation (`make docs`).

Tutorials are jupytext percent-format scripts (docs/tutorials/*.py) that myst-nb executes at build
time; their outputs are cached (docs/_build/.jupyter_cache), so an unchanged tutorial is not run
again. The reference pages come from the code: autosummary + numpydoc for the API, sphinx-argparse
for the CLI, and restitution_workflow.docs_pages for the schemas and the rung registry.
"""

import os
from pathlib import Path

HERE = Path(__file__).resolve().parent
# The tutorials run in a temporary directory (nb_execution_in_temp) and find the repository's
# files (scenes/, config.yaml, the Snakefile) through this; the kernels inherit the environment.
os.environ["RESTITUTION_DOCS_ROOT"] = str(HERE.parent)

project = "restitution"
author = "the restitution developers"
copyright = "the restitution developers"
from restitution import __version__ as release  # noqa: E402

version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    # MathJax from the docs group's own package, copied into _static/: the equations render with no
    # network (sphinx.ext.mathjax alone loads it from a CDN); tests/library/test_docs_site.py checks
    # that no page loads a script from the web.
    "sphinx-mathjax-offline",
    "numpydoc",
    "myst_nb",
    "sphinxarg.ext",
    "sphinx_copybutton",
    "restitution_workflow.docs_pages",   # the schema pages and the rung table, from the code
]

# tutorials/_notebooks: the tutorials as .ipynb for download (docs_pages.notebooks), not pages
exclude_patterns = ["_build", "_ext", "conf.py", "reference/_generated/speed_accuracy.md", "**.ipynb_checkpoints",
                    "tutorials/_notebooks"]
templates_path = ["_templates"]

# Tutorials: percent-format scripts read through jupytext, executed once per change.
nb_custom_formats = {".py": ["jupytext.reads", {"fmt": "py:percent"}]}
nb_execution_mode = "cache"
# RESTITUTION_DOCS_CACHE: the test suite executes the tutorials afresh in its own directory
nb_execution_cache_path = os.environ.get("RESTITUTION_DOCS_CACHE", str(HERE / "_build" / ".jupyter_cache"))
# a tutorial that fails is a failed build, not a page with a traceback on it
nb_execution_raise_on_error = True
nb_execution_timeout = 600
nb_execution_show_tb = True
# the library's notes on stderr (builds it makes, their cache paths) are the machine's, not the lesson's
nb_output_stderr = "remove"
# the tutorials run in docs/tutorials/, where the small decks and configs they write stay out of the tree
nb_execution_in_temp = True
myst_enable_extensions = ["colon_fence", "dollarmath"]
myst_heading_anchors = 3

autosummary_generate = True
autodoc_typehints = "none"          # numpydoc's Parameters section says the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

html_theme = "pydata_sphinx_theme"
html_title = "restitution"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
}
html_static_path = ["_static"]
html_css_files = ["custom.css"]
html_last_updated_fmt = None
