# The README's commands. Each target does the set-up it needs, once:
#   make run    set up if needed, then run the main demo
#   make test   set up if needed, then ruff and pytest
#   make setup  only the set-up (venv, install, interface generation, ament index)
#   make bench  set up if needed, then the benchmarks (a few minutes; prints a table)
#   make interfaces  rebuild the interface packages (colcon) after a .msg/.srv/.action changed
#   make test-load  the test suite with every core kept busy (RUNS=3: three runs in a row)
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
INSTALLED := $(VENV)/.installed
INTERFACES := $(VENV)/.interfaces
PACKAGES := $(VENV)/.packages
# A new package.xml, or a launch/ or config/ folder gained or changed, registers the packages again
# (the lessons' and the stand-ins': every top-level folder with a package.xml).
PACKAGE_SOURCES := $(wildcard */package.xml */launch */config)
HOLD_REMOVED := $(VENV)/.ctrl_c_hold_removed
ENVIRONMENT := $(VENV)/.ros_environment
INTERFACE_SOURCES := $(wildcard interfaces/cmake/*.cmake interfaces/*/CMakeLists.txt \
	interfaces/*/package.xml interfaces/*/msg/*.msg interfaces/*/srv/*.srv interfaces/*/action/*.action)

.PHONY: setup run test test-load lint bench clean interfaces

setup: $(HOLD_REMOVED) $(INTERFACES) $(PACKAGES) $(ENVIRONMENT)

# A venv of an older clone: its .pth file that held SIGINT at every start of Python goes, and
# its console scripts start Python directly again (before anything else runs in it).
$(HOLD_REMOVED): tools/remove_ctrl_c_hold.py
	test ! -x $(PY) || $(PY) -S tools/remove_ctrl_c_hold.py $(VENV)
	mkdir -p $(VENV) && rm -f $(VENV)/.ctrl_c && touch $@

$(INSTALLED): pyproject.toml tools/rosdep_here/pyproject.toml | $(HOLD_REMOVED)
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test,interfaces]'
	$(PY) -m pip install --quiet ./tools/rosdep_here
	touch $@

# colcon builds them, as a learner's workspace (tools/build_interfaces.py); after the
# environment's setup files, which colcon looks for in the underlay (order only).
$(INTERFACES): $(INSTALLED) $(INTERFACE_SOURCES) tools/build_interfaces.py | $(ENVIRONMENT)
	$(PY) tools/build_interfaces.py
	touch $@

# The packages in this environment's ament index (README: "Packages and the ament index").
$(PACKAGES): $(INTERFACES) $(PACKAGE_SOURCES) tools/register_packages.py
	$(PY) tools/register_packages.py
	touch $@

# `source .venv/bin/activate` sets ROS_VERSION, ROS_PYTHON_VERSION and ROS_DISTRO, as a ROS
# install's setup.bash does (the official "Configuring environment" tutorial looks for them),
# and in an interactive bash or zsh TAB completion of the commands completion.py names.
$(ENVIRONMENT): $(INSTALLED) tools/ros_environment.py ros_tutorials_common/dds.py \
	ros_tutorials_common/completion.py
	$(PY) tools/ros_environment.py
	touch $@

# "Your own message" (README): a new or changed file in interfaces/*/ rebuilds what changed.
interfaces: $(INTERFACES)

# Ctrl-C is how the demo ends (roslaunch's status 130): not an error for make to report. The
# shell traps SIGINT only so that it waits for that status; roslaunch gets the default handler.
run: setup
	trap : INT; $(VENV)/bin/roslaunch union.launch || test $$? -eq 130

lint: setup
	$(VENV)/bin/ruff check .

# JOBS pytest processes (pytest-xdist); each claims its own ROS_DOMAIN_ID (tests/conftest.py).
# More than the 2 cores: most tests spend their time waiting (process start, DDS discovery).
JOBS ?= 6
# The tests and the processes they start keep compiled bytecode (__pycache__, ignored by git)
# even where the environment says PYTHONDONTWRITEBYTECODE (as some CI images and containers
# do): otherwise every pytest process compiles the test files again (1.4 s of CPU each) and
# every process a test starts compiles this project's modules again.
PYTEST := env -u PYTHONDONTWRITEBYTECODE $(PY) -m pytest
test: lint
	$(PYTEST) -n $(JOBS)

# One busy process per core beside the tests (tests/cpu_load.py), stopped when pytest ends;
# RUNS runs in a row, stopping at the first that fails.
RUNS ?= 1
test-load: lint
	@for run in $$(seq $(RUNS)); do \
		echo "== test run $$run of $(RUNS), CPU kept busy"; \
		$(PYTEST) --cpu-load=auto -n $(JOBS) $(PYTEST_ARGS) || exit 1; \
	done

bench: setup
	$(PY) -m benchmarks

clean:
	rm -rf $(VENV) build
