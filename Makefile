# make demo  : set up .venv and verify the bundled lead-screw lift example, writing its report
# make test  : set up .venv and run the whole test suite (lint included)
# make docs  : the API reference from the docstrings (Sphinx) into build/api
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
BASE_STAMP := $(VENV)/.installed-base-stamp
export MPLBACKEND := Agg

.PHONY: demo test lint sysdeps direct bench clean docs

# scripts/install.sh creates the venv when missing and installs with uv (on PATH, or bootstrapped into the venv
# from PyPI), or with pip when uv cannot be had (MECHVERIFY_INSTALLER=pip forces pip).
INSTALL := PYTHON=$(PYTHON) VENV=$(VENV) bash scripts/install.sh

# demo: the base install and gmsh (wheels only, no compiler; the demo's plates with holes are meshed by gmsh);
# test/bench add the dev and cluster extras (sectionproperties - which builds Triangle - and vtk are test
# references only).
$(BASE_STAMP): pyproject.toml
	$(INSTALL) -e '.[mesh]'
	touch $@

$(STAMP): $(BASE_STAMP)
	$(INSTALL) -e '.[dev,mesh,cluster,explore,docs]'
	touch $@

sysdeps:
	@bash scripts/system-deps.sh

# direct: the optional CHOLMOD (mechverify[direct], GPL) for the FEA's direct solves in the tests and benchmarks;
# it compiles against the system's SuiteSparse, so `make demo` (wheels only) does not install it.
direct: $(STAMP) sysdeps
	@$(BIN)/python -c "import sksparse.cholmod" 2>/dev/null || \
	  $(INSTALL) 'scikit-sparse>=0.4.12,<0.5' || echo "scikit-sparse not installed: FEA uses SuperLU"

demo: $(BASE_STAMP) sysdeps
	$(BIN)/python -m mechverify.demo

lint: $(STAMP)
	$(BIN)/ruff check $(wildcard mechverify tests benchmarks examples)

test: $(STAMP) direct lint
	$(BIN)/python -m pytest

bench: $(STAMP) direct
	$(BIN)/python benchmarks/run.py

# docs: the API reference from the docstrings into build/api (warnings are errors)
docs: $(STAMP)
	$(BIN)/python -m sphinx -b html -q -W --keep-going docs/api build/api

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache .ruff_cache
