# Two commands do all the set-up on a fresh Debian 12 / Python 3.11 machine:
#   make demo   -> creates .venv, installs everything from PyPI, runs the main job on bundled data
#   make test   -> creates .venv, installs everything from PyPI, runs the test suite
# and one for the third-party planner under test:
#   make sut-commonroad -> creates .venv-commonroad (CommonRoad's reactive planner + the same ROS wheels)
# The interpreter for both venvs: Debian's /usr/bin/python3.11 when it can make one (it is built with PGO and LTO and
# runs the closed loop ~8 % faster than a plain source build of 3.11, e.g. pyenv's; docs/performance.md), else
# python3. `make PY=...` overrides.
PY ?= $(shell /usr/bin/python3.11 -c 'import ensurepip, venv' >/dev/null 2>&1 && echo /usr/bin/python3.11 || echo python3)
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

CR_VENV := .venv-commonroad
CR_STAMP := $(CR_VENV)/.installed

.PHONY: setup accel demo test test-fast maps clean sut-commonroad

$(STAMP): requirements.txt requirements-dev.txt setup.py
	$(PY) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip setuptools wheel
	$(BIN)/pip install -q -r requirements-dev.txt
	$(BIN)/pip install -q -e .
	touch $(STAMP)

# The compiled build of the player's, planner's and oracle's hot modules (Cython; the same results, ~20 % less CPU;
# txt2sce_ros/accel.py). Incremental: only modules whose source changed are compiled again (~1.5 min for all on 2
# cores). Optional: where it cannot be built, everything runs from the plain source.
accel: $(STAMP)
	@$(BIN)/txt2sce accel build || echo "warning: no compiled build; the plain Python source runs (slower, same results)" >&2

setup: $(STAMP) accel

# The planner's own environment (its protobuf pin clashes with ours); the adapter imports the checkout through
# PYTHONPATH (sut_adapters/commonroad/venv.py), so only the planner stack and the ROS wheels are installed here.
$(CR_STAMP): requirements-commonroad.txt
	$(PY) -m venv $(CR_VENV)
	$(CR_VENV)/bin/pip install -q --upgrade pip setuptools wheel
	$(CR_VENV)/bin/pip install -q -r requirements-commonroad.txt
	touch $(CR_STAMP)

sut-commonroad: $(CR_STAMP)

demo: $(STAMP) accel
	$(BIN)/txt2sce demo --out demo_out

test: $(STAMP) $(CR_STAMP) accel
	$(BIN)/python -m pytest -q tests

clean:
	rm -rf $(VENV) $(CR_VENV) demo_out build install log .pytest_cache
