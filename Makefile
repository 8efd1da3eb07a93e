# The README's commands. Each target does the set-up it needs, once:
#   make run    set up if needed, then run the main demo
#   make test   set up if needed, then ruff and pytest
#   make setup  only the set-up (venv, install, interface generation)
#   make bench  set up if needed, then the benchmarks (a few minutes; prints a table)
#   make interfaces  regenerate the interface packages after a .msg/.srv/.action changed
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
INSTALLED := $(VENV)/.installed
INTERFACES := $(VENV)/.interfaces
INTERFACE_SOURCES := $(wildcard interfaces/cmake/*.cmake interfaces/*/CMakeLists.txt \
	interfaces/*/package.xml interfaces/*/msg/*.msg interfaces/*/srv/*.srv interfaces/*/action/*.action)

.PHONY: setup run test lint bench clean interfaces

setup: $(INTERFACES)

$(INSTALLED): pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test,interfaces]'
	touch $@

$(INTERFACES): $(INSTALLED) $(INTERFACE_SOURCES) tools/build_interfaces.py
	$(PY) tools/build_interfaces.py
	touch $@

# "Your own message" (README): a new or changed file in interfaces/*/ rebuilds what changed.
interfaces: $(INTERFACES)

run: setup
	$(PY) -m launcher union.launch

lint: setup
	$(VENV)/bin/ruff check .

test: lint
	$(PY) -m pytest

bench: setup
	$(PY) -m benchmarks

clean:
	rm -rf $(VENV) build
