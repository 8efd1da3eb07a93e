"""Ctrl-C at any instant of a command's start: no traceback, no "Fatal Python error".

A sweep starts a command as a user's shell would (without the ROS wheels' bootstrap done, so
the interpreter re-executes itself as it does for a user), sends SIGINT after a delay (to the
whole process group for the launcher, as a terminal does), and collects stderr. The delays
run from 0 to well past the import of rclpy, so they fall into every phase of the start:
Python's own, the .pth files and the re-exec, the imports, rclpy.init, the node's creation.
Nothing here asserts a time: a slower machine moves the phases, and the sweep still crosses
them (the runs go in parallel, which loads the machine further). See ros_tutorials_common/ctrl_c.py.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import sysconfig
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from fnmatch import fnmatch
from pathlib import Path

import pytest
import tomllib
from helpers import TIMEOUT
from rclpy.context import Context

from ros_tutorials_common import ctrl_c

BIN = Path(sys.executable).parent
ROOT = Path(__file__).resolve().parents[1]
DELAYS = (0.0, 0.005, 0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.25, 0.4, 0.6, 0.9, 1.4)
# Killed by SIGINT (a shell shows 130), 130 from the program itself, or 0 from a program
# for which Ctrl-C is the normal end (a node, once running).
STOPPED = {-signal.SIGINT, 128 + signal.SIGINT, 0}


def user_env() -> dict[str, str]:
    """The test's environment as a user's shell has it: the ROS wheels' bootstrap not done."""
    env = dict(os.environ)
    env.pop("_ROS_WHEELS_BOOTSTRAP_COMPLETE", None)
    return env


def interrupt_after(command: list[str], delay: float, group: bool) -> tuple[int, str]:
    """Start command, SIGINT it after delay seconds, wait for its end: (status, stderr)."""
    process = subprocess.Popen(
        command,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        env=user_env(),
        start_new_session=True,  # its own process group, as a terminal's foreground job
    )
    time.sleep(delay)  # where in the start the Ctrl-C falls; nothing depends on the exact time
    (os.killpg if group else os.kill)(process.pid, signal.SIGINT)
    try:
        _, err = process.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        # Whether the Ctrl-C is still pending (SigPnd/ShdPnd bit 2) and blocked (SigBlk), and
        # (SIGABRT: Python's fault handler, PYTHONFAULTHANDLER in conftest) where each thread was.
        try:
            status = Path(f"/proc/{process.pid}/status").read_text().splitlines()
        except OSError:
            status = []
        masks = [line for line in status if line.startswith(("SigPnd", "ShdPnd", "SigBlk"))]
        os.killpg(process.pid, signal.SIGABRT)
        try:
            _, err = process.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            _, err = process.communicate()
        pytest.fail(
            f"{command}: still running {TIMEOUT:.0f} s after Ctrl-C at {delay} s; "
            + " ".join(masks)
            + "; where it was:\n"
            + err.decode(errors="replace")[-4000:]
        )
    return process.returncode, err.decode(errors="replace")


COMMANDS = {
    "rostopic echo (a tool, ROS 1 spelling)": ([str(BIN / "rostopic"), "echo", "/chatter"], False),
    "talker (a lesson node)": ([str(BIN / "talker")], False),
    "rosrun add_two_ints_server (exec)": (
        [str(BIN / "rosrun"), "ros_tutorials_service", "add_two_ints_server"],
        False,
    ),
    "roslaunch union.launch (the launcher and its children)": (
        [str(BIN / "roslaunch"), "ros_tutorials_topic", "union.launch"],
        True,
    ),
}


@pytest.mark.parametrize("name", COMMANDS)
def test_ctrl_c_at_any_instant_of_the_start_prints_no_traceback(name: str, ros_domain: int):
    command, group = COMMANDS[name]
    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = list(pool.map(lambda delay: interrupt_after(command, delay, group), DELAYS))
    bad = [
        f"Ctrl-C after {delay} s: status {status}\n{err}"
        for delay, (status, err) in zip(DELAYS, runs, strict=True)
        if status not in STOPPED or "Traceback" in err or "Fatal Python error" in err
    ]
    assert not bad, f"{len(bad)} of {len(DELAYS)} runs of {name}:\n" + "\n".join(bad[:2])


def test_other_programs_of_the_environment_keep_pythons_ctrl_c(ros_domain: int):
    """Only this project's commands hold SIGINT: Python's own KeyboardInterrupt elsewhere."""
    code = "import time; print('ready', flush=True); time.sleep(60)"
    process = subprocess.Popen(
        [sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=user_env()
    )
    assert process.stdout.readline() == b"ready\n"
    blocked = Path(f"/proc/{process.pid}/status").read_text().split("SigBlk:")[1].split()[0]
    assert not int(blocked, 16) & (1 << (signal.SIGINT - 1)), "SIGINT left blocked"
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=TIMEOUT)
    assert b"KeyboardInterrupt" in err and process.returncode == -signal.SIGINT


def test_which_command_lines_are_this_projects():
    python = sys.executable
    assert ctrl_c.is_project_command([python, "-m", "launcher", "union.launch"])
    assert ctrl_c.is_project_command([python, "-X", "dev", "-mros2cmd", "topic", "list"])
    assert ctrl_c.is_project_command([python, str(ROOT / "ros_tutorials_topic" / "talker.py")])
    assert ctrl_c.is_project_command([python, str(BIN / "rostopic"), "list"])
    assert not ctrl_c.is_project_command([python, "-m", "pytest"])
    assert not ctrl_c.is_project_command([python, "-c", "import launcher"])
    assert not ctrl_c.is_project_command([python, str(BIN / "pip"), "list"])
    assert not ctrl_c.is_project_command([python])
    assert ctrl_c.starts_project_command([python, "-m", "ros_tutorials_topic.publisher"])
    assert ctrl_c.starts_project_command([str(BIN / "talker")])
    assert not ctrl_c.starts_project_command(["/bin/sleep", "1"])


def test_every_package_releases_ctrl_c_and_make_setup_installed_the_hold():
    """A package whose __init__ did not release SIGINT would leave its commands deaf to it."""
    patterns = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"][
        "packages"
    ]["find"]["include"]
    found = {path.parent.name for path in ROOT.glob("*/__init__.py")}
    assert {name for name in found if any(fnmatch(name, p) for p in patterns)} == ctrl_c.PACKAGES
    for name in ctrl_c.PACKAGES:
        assert "_release_ctrl_c()" in (ROOT / name / "__init__.py").read_text(), name
    pth = Path(sysconfig.get_paths()["purelib"]) / ctrl_c.PTH_NAME
    assert pth.read_text() == ctrl_c.pth_line()


def test_errors_a_ctrl_c_causes_in_ros_end_quietly_and_others_do_not():
    """What ROS raises once rclpy's signal handler has shut the context down counts as the
    Ctrl-C (no traceback, death by SIGINT); other ROS errors keep their traceback."""
    rcl_error = type("RCLError", (RuntimeError,), {})
    stopped = [
        "failed to shutdown: rcl_shutdown already called on the given context, at init.c:333",
        "Failed to create publisher: the given context is not valid",
    ]
    for text in stopped:
        assert ctrl_c.interrupted(rcl_error(text)), text
    assert not ctrl_c.interrupted(rcl_error("failed to create subscription: invalid topic name"))
    assert not ctrl_c.interrupted(RuntimeError("rcl_shutdown already called"))  # not ROS's


def test_a_lost_ctrl_c_is_not_delivered_again_where_ros_is_down_already(monkeypatch):
    """In a node whose Ctrl-C rclpy's handler answered by shutting ROS down, the program ends
    through ExternalShutdownException; a KeyboardInterrupt delivered again would only come
    after its except clause and end it by SIGINT instead of exit status 0."""
    delivered = []
    monkeypatch.setattr(ctrl_c, "_deliver_again", lambda: delivered.append(True))
    lost = type("Unraisable", (), {"exc_value": KeyboardInterrupt(), "object": None})()
    monkeypatch.setattr(ctrl_c, "ros_stopped", True)
    ctrl_c._quiet_unraisablehook(lost)
    assert delivered == []
    monkeypatch.setattr(ctrl_c, "ros_stopped", False)  # a tool: only the KeyboardInterrupt
    ctrl_c._quiet_unraisablehook(lost)
    assert delivered == [True]


def test_a_ctrl_c_that_pybind11_turned_into_an_error_ends_quietly(monkeypatch):
    """A KeyboardInterrupt raised while rclpy's C++ converts a value (a message's __init__ in
    take_message) comes out as pybind11's RuntimeError: a stop once Ctrl-C was pressed, and
    an error (with its traceback) otherwise."""
    converted = RuntimeError(
        "Unable to convert call argument '0' to Python object (#define "
        "PYBIND11_DETAILED_ERROR_MESSAGES or compile in debug mode for details)"
    )
    monkeypatch.setattr(ctrl_c, "pressed", False)
    assert not ctrl_c.interrupted(converted)
    monkeypatch.setattr(ctrl_c, "pressed", True)
    assert ctrl_c.interrupted(converted)
    assert not ctrl_c.interrupted(RuntimeError("another error"))


def test_rclpy_objects_cut_short_by_ctrl_c_are_not_reported_and_other_errors_are():
    """rclpy's Future.__del__ (and the executor's) fails on an object whose __init__ a Ctrl-C
    cut short ("Exception ignored in: <function Future.__del__ ...>"): said nothing of; other
    unraisable errors are."""
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.task import Future

    cut = Future.__new__(Future)  # as a KeyboardInterrupt inside __init__ leaves it
    with pytest.raises(AttributeError) as failed:
        cut.__del__()
    cut._exception = None  # this one may now be collected quietly
    executor = SingleThreadedExecutor.__new__(SingleThreadedExecutor)
    with pytest.raises(AttributeError) as executor_failed:
        executor.__del__()
    executor._sigint_gc = None
    seen = []

    def unraisable(exc_value, where):
        return type("Unraisable", (), {"exc_value": exc_value, "object": where})()

    previous = ctrl_c._previous_unraisablehook
    ctrl_c._previous_unraisablehook = seen.append
    try:
        ctrl_c._quiet_unraisablehook(unraisable(failed.value, Future.__del__))
        ctrl_c._quiet_unraisablehook(
            unraisable(executor_failed.value, SingleThreadedExecutor.__del__)
        )
        assert seen == []
        other = unraisable(AttributeError("x"), test_which_command_lines_are_this_projects)
        ctrl_c._quiet_unraisablehook(other)
        assert seen == [other]
    finally:
        ctrl_c._previous_unraisablehook = previous


def test_keyboard_interrupt_waits_until_rclpy_has_shut_ros_down(context):
    """The SIGINT handler ros_args installs (ros_tutorials_common/ros/node_main.py) raises
    KeyboardInterrupt only once the context is down: here it waits for a thread that shuts
    the context down later, as rclpy's signal handler thread does, and gives up after its
    timeout while the context stays up."""
    from ros_tutorials_common.ros.node_main import _CtrlCOnceRosIsDown

    handler = _CtrlCOnceRosIsDown(context)
    assert handler.ros_is_up()
    assert not handler.wait_until_down(0.2), "the context is up: the wait must give up"
    shutting_down = threading.Timer(0.3, context.shutdown)
    shutting_down.start()
    try:
        assert handler.wait_until_down(TIMEOUT)
        assert not context.ok(), "the wait ended before the context was down"
    finally:
        shutting_down.join()
    assert not _CtrlCOnceRosIsDown(Context()).ros_is_up(), "a context never initialised"


def test_a_node_sees_ros_down_when_ctrl_c_reaches_it(node_process):
    """End to end: rclpy.init(args=ros_args()) then spin; at KeyboardInterrupt rclpy's handler
    has shut ROS down already, so the program's rclpy.try_shutdown() has nothing to race."""
    code = (
        "import rclpy\n"
        "from ros_tutorials_common.ros import ros_args\n"
        "rclpy.init(args=ros_args(['probe']))\n"
        "node = rclpy.create_node('probe')\n"
        "try:\n"
        "    print('spinning', flush=True)\n"  # in the try: the Ctrl-C may follow at once
        "    rclpy.spin(node)\n"
        "except KeyboardInterrupt:\n"
        "    print('ROS down at KeyboardInterrupt:', not rclpy.ok(), flush=True)\n"
        "rclpy.try_shutdown()\n"
    )
    probe = node_process("-c", code)
    probe.wait_for_text("spinning")
    assert probe.interrupt() == 0, probe.output
    assert "ROS down at KeyboardInterrupt: True" in probe.lines, probe.output


def test_a_ctrl_c_that_lands_in_a_del_is_not_lost(node_process):
    """Python cannot raise a KeyboardInterrupt out of a __del__ (rclpy's Future and Task have
    one; the executor drops one per callback): it reports it as unraisable and runs on. This
    project's hook delivers that Ctrl-C again, so the program stops (`rostopic echo` ran on
    for 30 s after a Ctrl-C under load). Here the Ctrl-C lands in a __del__ by construction."""
    code = (
        "import os, signal, sys, time\n"
        "from ros_tutorials_common import ctrl_c\n"
        "sys.unraisablehook = ctrl_c._quiet_unraisablehook  # as release() sets it\n"
        "class Collected:\n"
        "    pressed = False\n"
        "    def __del__(self):\n"
        "        if not Collected.pressed:\n"
        "            Collected.pressed = True\n"
        "            os.kill(os.getpid(), signal.SIGINT)\n"
        "            sum(range(1000))  # Python raises the KeyboardInterrupt here, in __del__\n"
        "try:\n"
        "    end = time.monotonic() + 10\n"
        "    while time.monotonic() < end:\n"
        "        Collected()\n"
        "        time.sleep(0.001)\n"
        "    print('ran on after Ctrl-C', flush=True)\n"
        "except KeyboardInterrupt:\n"
        "    print('stopped by Ctrl-C', flush=True)\n"
    )
    program = node_process("-c", code)
    assert program.wait() == 0, program.output
    assert program.lines == ["stopped by Ctrl-C"], program.output


def test_sigterm_at_any_instant_of_a_nodes_start_ends_it_quietly(ros_domain: int):
    """A talker sent SIGTERM as it starts ends without a traceback or a hang."""

    def terminate_after(delay: float) -> tuple[int, str]:
        process = subprocess.Popen(
            [str(BIN / "talker")],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            env=user_env(),
        )
        time.sleep(delay)  # where in the start it falls; nothing depends on the exact time
        process.terminate()
        try:
            _, err = process.communicate(timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            process.kill()
            pytest.fail(f"talker still running {TIMEOUT:.0f} s after SIGTERM at {delay} s")
        return process.returncode, err.decode(errors="replace")

    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = list(pool.map(terminate_after, DELAYS))
    # A lesson is plain rclpy: a SIGTERM while it creates its node (rclpy's handler shut ROS
    # down under it) ends it as ctrl_c.py ends a Ctrl-C at that instant, by SIGINT, quietly.
    ended = {0, -signal.SIGTERM, 128 + signal.SIGTERM, -signal.SIGINT}
    bad = [
        f"SIGTERM after {delay} s: status {status}\n{err}"
        for delay, (status, err) in zip(DELAYS, runs, strict=True)
        if status not in ended or "Traceback" in err or "Fatal Python error" in err
    ]
    assert not bad, f"{len(bad)} of {len(DELAYS)} runs:\n" + "\n".join(bad[:2])
