# Two commands set everything up on a fresh Debian machine: `make paper` and `make test`.
# Everything runs inside .venv, created here on first use and pinned by constraints.txt.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
# Fixed build date: every generated file (figures, tables, PDF) carries this instead of "now".
export SOURCE_DATE_EPOCH ?= 1700000000
export PYTHONHASHSEED := 0

.PHONY: venv test

$(STAMP): pyproject.toml constraints.txt
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -c constraints.txt -e '.[test]'
	@touch $@

venv: $(STAMP)

test: $(STAMP)
	$(BIN)/python -m pytest -q

# ---------------------------------------------------------------------------------------------
# The paper pipeline (Snakefile, config.yaml, workflow/). Outputs under results/, the PDF at
# results/paper/restitution.pdf. CORES=all uses every core.
CORES        ?= 2
SNAKEMAKE    := $(BIN)/snakemake --cores $(CORES) --rerun-incomplete
# Runs in this tree go through workflow/tools/guard.py: results/ (and logs/, build/, .snakemake/)
# must be writable with room to spare, one run at a time (a second `make paper` waits for the
# first; LOCK_WAIT=S gives up after S seconds, LOCK_WAIT=0 at once), locks left by a killed run
# are cleared, and half-done jobs are redone.
LOCK_WAIT    ?=
GUARDED      := $(BIN)/python workflow/tools/guard.py $(if $(LOCK_WAIT),--wait $(LOCK_WAIT)) --
# Progress and finished jobs, without the per-job detail (targets go before this: --quiet
# takes a list).
QUIET        := --quiet host rules
PDF          := results/paper/restitution.pdf
# The only TeX the manuscript needs (article, amsmath/amssymb, graphicx, booktabs, microtype,
# geometry, hyperref, bibtex, latexmk), as Debian packages.
TEX_PACKAGES := texlive-latex-base texlive-latex-recommended texlive-fonts-recommended latexmk
HAVE_TEX      = command -v pdflatex >/dev/null 2>&1 && command -v latexmk >/dev/null 2>&1

.PHONY: paper tex outputs check expected reproducible bench notebooks

# Everything, PDF included; a second run does nothing. Without TeX (and no root to install it),
# everything except the PDF, and a message saying how to get it.
paper: $(STAMP) tex
	@if $(HAVE_TEX); then \
	  $(GUARDED) $(SNAKEMAKE) all $(QUIET) && echo "PDF: $(CURDIR)/$(PDF)"; \
	else \
	  $(GUARDED) $(SNAKEMAKE) outputs $(QUIET) && \
	  echo "Built everything under results/ except the PDF: pdflatex/latexmk are missing." && \
	  echo "To get $(PDF): as root, apt-get install $(TEX_PACKAGES); then run make paper again."; \
	fi

# TeX Live from the distribution's packages, only when it is missing and we may install it.
tex:
	@if ! { $(HAVE_TEX); }; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "Installing TeX Live (Debian packages: $(TEX_PACKAGES)) ..."; \
	    DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(TEX_PACKAGES) \
	      || echo "TeX Live could not be installed; the PDF will be skipped."; \
	  else \
	    echo "pdflatex not found and not root: the PDF will be skipped."; \
	  fi; \
	fi

# Everything except the PDF (no TeX needed).
outputs: $(STAMP)
	$(GUARDED) $(SNAKEMAKE) outputs $(QUIET)

# Rebuild from clean in a temporary directory and compare with tests/expected/manifest.json.
check: $(STAMP)
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) check

# Rewrite tests/expected/manifest.json from a clean rebuild (after an intended change).
expected: paper
	$(BIN)/python workflow/tools/rebuild.py manifest

# Two clean builds in temporary directories: every file under results/ must be byte-identical.
reproducible: $(STAMP)
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) twice

# Measurements, written under results/bench/: series derivation time, the speed/accuracy table of
# every eps method against the high-precision reference (speed_accuracy.csv, pareto.pdf/png), and
# the wall time of one cold pipeline run (environment and TeX already installed).
bench: $(STAMP)
	@mkdir -p results/bench
	$(BIN)/python benchmarks/series_speed.py | tee results/bench/series_speed.txt
	$(BIN)/python benchmarks/speed_accuracy.py --out results/bench
	$(BIN)/python workflow/tools/rebuild.py --cores $(CORES) bench

# The figure and table scripts as Jupyter notebooks (notebooks/, not tracked). They replay the
# pipeline's last run of their rule, so run `make paper` first.
NOTEBOOK_SCRIPTS := $(wildcard workflow/scripts/fig*.py) workflow/scripts/series_table.py \
                    workflow/scripts/values.py
notebooks: $(STAMP)
	@mkdir -p notebooks
	@for f in $(NOTEBOOK_SCRIPTS); do \
	  $(BIN)/jupytext --quiet --to ipynb --output notebooks/$$(basename $$f .py).ipynb $$f || exit 1; \
	done
	@echo "notebooks/: $$(ls notebooks | tr '\n' ' ')"
