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
