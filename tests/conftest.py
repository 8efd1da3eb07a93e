"""Shared fixtures: a private ROS domain per test session, rclpy contexts, processes.

Every pytest session claims a ROS_DOMAIN_ID nobody else on this machine holds (an flock on a
file per id), so concurrent test runs, benchmarks and demos never see each other's nodes.
The DDS defaults (localhost only) are applied before anything initialises rclpy.
"""

from __future__ import annotations

import fcntl
import os
import random
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
import rclpy
from helpers import NodeProcess
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor

from ros_tutorials_common import apply_dds_defaults

# Fast DDS maps domain ids 0..232 to ports; stay in the range every RMW accepts.
DOMAIN_IDS = range(1, 102)


def _claim_domain_id() -> tuple[int, object]:
    lock_dir = Path(tempfile.gettempdir()) / "ros_tutorials_domains"
    lock_dir.mkdir(exist_ok=True)
    candidates = list(DOMAIN_IDS)
    random.shuffle(candidates)
    for domain_id in candidates:
        handle = open(lock_dir / f"{domain_id}.lock", "w")  # noqa: SIM115 - held for the session
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            handle.close()
            continue
        return domain_id, handle
    raise RuntimeError("no free ROS_DOMAIN_ID: every id in 1..101 is held by another run")


@pytest.fixture(scope="session", autouse=True)
def ros_domain(tmp_path_factory: pytest.TempPathFactory) -> Iterator[int]:
    """This session's own ROS_DOMAIN_ID, set in os.environ for rclpy and for child processes."""
    domain_id, lock = _claim_domain_id()
    os.environ["ROS_DOMAIN_ID"] = str(domain_id)
    os.environ["ROS_LOG_DIR"] = str(tmp_path_factory.mktemp("ros_log"))
    apply_dds_defaults()
    yield domain_id
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
        node.destroy_node()
    ex.shutdown()


@pytest.fixture
def node_process(ros_domain: int) -> Iterator[Callable[..., NodeProcess]]:
    """Start tutorial executables as real processes; all are killed at the end of the test."""
    started: list[NodeProcess] = []

    def start(*args: str, env: dict[str, str] | None = None) -> NodeProcess:
        proc = NodeProcess(*args, env=env)
        started.append(proc)
        return proc

    yield start
    for proc in started:
        proc.kill()
