"""Shared fixtures: a private ROS domain per test session, rclpy contexts, processes.

Every pytest session claims a ROS_DOMAIN_ID nobody else on this machine holds, so
concurrent test runs, benchmarks and demos never see each other's nodes.
The DDS defaults (localhost only) are applied before anything initialises rclpy.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import helpers
import pytest
import rclpy
from helpers import NodeProcess, ready
from rclpy.action import ActionClient
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from warm import Starter

from ros2cmd import daemon, graph
from ros2cmd.local_participants import domain_processes
from ros_tutorials_common.ament import apply_ament_defaults
from ros_tutorials_common.dds import (
    PRIVATE_DOMAIN_IDS,
    apply_dds_defaults,
    claim_private_domain_id,
)

# `pytest --cpu-load=auto` (`make test-load`): the suite with every core kept busy.
pytest_plugins = ["cpu_load"]


def pytest_configure(config: pytest.Config) -> None:
    config.addinivalue_line(
        "markers", "long: a test that takes far longer than the others; it runs first"
    )


def pytest_sessionfinish(session: pytest.Session) -> None:
    """Free the shared memory that the processes killed by the tests left behind.

    Fast DDS keeps each participant's shared-memory segment in /dev/shm (memory, not disk)
    and removes it when the participant closes; a process killed with SIGKILL leaves it, and
    a run of the suite left about 150 files and 35 MB. Its own tool removes those no running
    process holds (`fastdds shm clean`: it looks at each segment's file lock, so a running
    process's segment, also another session's, stays); run once, by the pytest process that
    started the others, in the background: the run does not wait for it.
    """
    fastdds = Path(sys.prefix) / "tools" / "fastdds" / "fastdds.py"  # what bin/fastdds runs
    if hasattr(session.config, "workerinput") or not fastdds.exists():
        return
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    subprocess.Popen([sys.executable, fastdds, "shm", "clean"], start_new_session=True, **quiet)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """The tests marked long start first, each in a pytest process of its own (the rest in
    their order): the suite then does not wait at its end for a long test that started
    last, or for several queued in one process.

    pytest-xdist (load scheduling, xdist/scheduler/load.py) first hands each process a
    chunk of len(items) // workers // 4 tests (at least 2) in this order, then tops them up
    as they finish; so the long tests go to the starts of those chunks.
    """
    long = [item for item in items if item.get_closest_marker("long")]
    rest = [item for item in items if not item.get_closest_marker("long")]
    workers = getattr(config, "workerinput", {}).get("workercount", 1)
    chunk = max(2, len(items) // workers // 4)
    items[:] = rest
    for position, item in enumerate(long):
        items.insert(min(position * chunk, len(items)), item)


# The start of the reason of a skip for a missing browser or display (tests/browser.py).
NEEDS_BROWSER_OR_DISPLAY = "needs a browser or display:"


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo) -> Iterator[None]:
    """With CI=true, a test skipped for a missing browser or display fails instead: CI
    (`.ci/run`) installs them, and a browser test that does not run tests nothing."""
    outcome = yield
    report = outcome.get_result()
    if os.environ.get("CI", "").lower() != "true" or not report.skipped:
        return
    reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else str(report.longrepr)
    if NEEDS_BROWSER_OR_DISPLAY in reason:
        report.outcome = "failed"
        reason = reason.removeprefix("Skipped: ")
        report.longrepr = f"CI=true, and this test would be skipped: {reason}"


@pytest.fixture(scope="session", autouse=True)
def ros_domain(tmp_path_factory: pytest.TempPathFactory) -> Iterator[int]:
    """This session's own ROS_DOMAIN_ID, set in os.environ for rclpy and for child processes."""
    # Run in the background (nohup, `make test &`, some CI runners), pytest would inherit
    # SIGINT *ignored* and pass that on to every process a test starts, so the Ctrl-C the
    # tests send would do nothing. Take the default back for them.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    domain_id, lock = claim_private_domain_id()
    os.environ["ROS_DOMAIN_ID"] = str(domain_id)
    os.environ["ROS_LOG_DIR"] = str(tmp_path_factory.mktemp("ros_log"))
    # A process that crashes (two rare segfaults at exit after Ctrl-C/SIGTERM were seen on
    # 2026-11-22) prints where each thread was, into the output the failing test shows.
    os.environ.setdefault("PYTHONFAULTHANDLER", "1")
    apply_dds_defaults()
    # What the first package lookup would add to os.environ (this environment's prefix in
    # AMENT_PREFIX_PATH, ros_tutorials_common/ament.py), added before the warm-start server
    # takes the environment it serves: a lookup in a test then changes nothing (test_warm failed).
    apply_ament_defaults()
    # Lists discover for themselves unless a test asks for the daemon (tests/test_daemon.py).
    os.environ[daemon.NO_DAEMON_VARIABLE] = "1"
    # A tool waits up to 30 s, not 5, for a node, topic or server that is running: once, under
    # CI's load, `ros2 param load /turtlesim` did not see a running turtlesim within 5 s.
    # Tests of the "unknown ..." errors give --timeout themselves.
    os.environ[graph.TIMEOUT_VARIABLE] = str(helpers.TIMEOUT)
    # The processes of this project that the tests start, forked from one that has imported
    # it (tests/warm.py): a third of the CPU a cold start costs.
    helpers.warm = Starter(str(tmp_path_factory.mktemp("warm")))
    yield domain_id
    helpers.warm.stop()
    helpers.warm = None
    daemon.stop_quietly()  # a daemon a test started must not outlive the session
    lock.close()


@pytest.fixture
def context(ros_domain: int) -> Iterator[Context]:
    """An initialised rclpy context of its own for one test."""
    ctx = Context()
    rclpy.init(context=ctx)
    yield ctx
    ctx.try_shutdown()


@pytest.fixture
def executor(context: Context) -> Iterator[SingleThreadedExecutor]:
    """An executor on the test's context; nodes added to it are destroyed at the end."""
    ex = SingleThreadedExecutor(context=context)
    yield ex
    for node in ex.get_nodes():
        ex.remove_node(node)
        # destroy_node() leaves a node's action clients, which keep it in the graph of the
        # session's domain (where later tests list the nodes): they go first. (Action servers
        # are the lessons' own, destroyed by their node's destroy_node().)
        for waitable in list(node.waitables):
            if isinstance(waitable, ActionClient):
                waitable.destroy()
        node.destroy_node()
    ex.shutdown()


def _processes() -> Iterator[Callable[..., NodeProcess]]:
    started: list[NodeProcess] = []

    def start(*args: str, env: dict[str, str] | None = None) -> NodeProcess:
        proc = NodeProcess(*args, env=env)
        started.append(proc)
        return proc

    yield start
    for proc in started:
        proc.kill()


def _own_domain() -> Iterator[int]:
    """A ROS_DOMAIN_ID of its own, where no process of this machine runs at the start, set in
    os.environ until the end (processes started in it start cold: tests/warm.py serves the
    session's environment)."""
    for _ in range(len(PRIVATE_DOMAIN_IDS)):
        domain_id, lock = claim_private_domain_id()
        if not (domain_processes(domain_id) or (False,))[0]:
            break
        lock.close()
    else:
        pytest.fail("no private ROS_DOMAIN_ID without running processes")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("ROS_DOMAIN_ID", str(domain_id))
        yield domain_id
    lock.close()


@pytest.fixture
def own_domain(ros_domain: int) -> Iterator[int]:
    """For tests that check a whole listing against a tutorial page, which must see only what
    the test starts (the session's domain may still hold what earlier tests left running)."""
    yield from _own_domain()


@pytest.fixture(scope="class")
def class_own_domain(ros_domain: int) -> Iterator[int]:
    """own_domain, for the tests of a class that share the processes they check."""
    yield from _own_domain()


@pytest.fixture
def node_process(ros_domain: int) -> Iterator[Callable[..., NodeProcess]]:
    """Start tutorial executables as real processes; all are killed at the end of the test."""
    yield from _processes()


@pytest.fixture(scope="class")
def class_node_process(ros_domain: int) -> Iterator[Callable[..., NodeProcess]]:
    """Like node_process, for processes that the tests of one class share (servers that
    those tests only ask, never change); killed when the class's tests are done, so they
    never meet the servers of tests outside the class (which use the same node names)."""
    yield from _processes()


@pytest.fixture
def parameter_lesson(node_process) -> NodeProcess:
    """The parameter lesson's server: /ros_tutorial_srv and its calculation_method (1..4)."""
    return ready(node_process("-m", "ros_tutorials_parameter.server"))


@pytest.fixture(scope="class")
def shared_parameter_lesson(class_node_process) -> NodeProcess:
    """The parameter lesson's server, one for the tests of a class that leave it as it is
    (bad requests)."""
    return ready(class_node_process("-m", "ros_tutorials_parameter.server"))


@pytest.fixture
def unchanged_parameter_lesson(shared_parameter_lesson) -> Iterator[NodeProcess]:
    """The shared parameter server; after the test, it must still run (nothing already
    running is lost because of one bad request)."""
    yield shared_parameter_lesson
    assert shared_parameter_lesson.process.poll() is None, shared_parameter_lesson.output
