# Two commands do all set-up on a fresh machine: `make run` and `make test`.
# Each step leaves a stamp in .venv, so a second run skips what is already done.

PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
DEMO := assets/recipes/pasta-bake.txt
# The native llama.cpp build segfaults on this class of machine (AMX kernels); this one does not.
export CMAKE_ARGS := -DGGML_NATIVE=OFF -DLLAVA_BUILD=OFF
export HF_HUB_OFFLINE := 1
export TRANSFORMERS_OFFLINE := 1

.PHONY: run test models install doctor clean-venv

run: models
	$(BIN)/cook2ltl app $(DEMO)

test: models
	@echo "==> [4/4] tests"
	$(BIN)/python -m pytest

models: install
	@echo "==> [3/4] models (fetched or trained into the per-user cache; skipped when present)"
	$(BIN)/cook2ltl models provision

install: $(VENV)/.installed

doctor: models
	$(BIN)/cook2ltl doctor

$(VENV)/.created:
	@echo "==> [1/4] Python environment in $(VENV)"
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	@touch $@

# torch first, pinned: its CPU build lies on this machine's disk, while a bare `torch` pulls a CUDA build.
# llama-cpp-python compiles (3-10 minutes) the first time; pip caches the built wheel for later clones.
$(VENV)/.installed: $(VENV)/.created pyproject.toml
	@echo "==> [2/4] packages (torch CPU, llama-cpp-python build, the project)"
	$(BIN)/python -m pip install --progress-bar off torch==2.13.0
	$(BIN)/python -m pip install --progress-bar off -e ".[models,llm,sim,planning,dev]"
	$(BIN)/python -m pip install --progress-bar off --no-deps flloat==0.3.0
	@command -v mona >/dev/null || (apt-get install -y -q mona || (apt-get update -q && apt-get install -y -q mona)) \
		|| echo "MONA could not be installed: the ltlf2dfa oracle test will be skipped"
	@touch $@

clean-venv:
	rm -rf $(VENV)
