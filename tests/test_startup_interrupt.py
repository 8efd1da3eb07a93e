"""Ctrl-C at any instant of a command's start: it ends, and prints no traceback once it runs.

Before a program's first function runs (Python's start, the .pth files, the imports), a Ctrl-C
gets Python's own answer, as for any Python program (docs/dev/limits.md, "Ctrl-C at any
moment"): a KeyboardInterrupt traceback (status 130), "Fatal Python error: init_import_site"
and one (status 1, while site reads the .pth files), or an error it caused ("ImportError:
initialization failed" from rclpy's C extension, status 1); rarely Python loses it (its
"Exception ignored" lines, or a Ctrl-C that reached the interpreter the ROS wheels' bootstrapper
replaces), and a second Ctrl-C stops the program. A lesson node's start lasts until it spins
(rclpy.init and its node's creation come before its try, as in ros2/examples): a traceback
through its main, or rclpy's refusal to create its node in the context its Ctrl-C handler
shut down. These are accepted, and nothing else (helpers.tracebacks_after_start).

A sweep starts a command as a user's shell would (without the ROS wheels' bootstrap done, so
the interpreter re-executes itself as it does for a user), sends SIGINT after a delay (to the
whole process group for the launcher, as a terminal does), and collects stderr. The delays
run from 0 to well past the import of rclpy, so they fall into every phase of the start:
Python's own, the .pth files and the re-exec, the imports, rclpy.init, the node's creation.
Nothing here asserts a time: a slower machine moves the phases, and the sweep still crosses
them (the runs go in parallel, which loads the machine further). See
ros_tutorials_common/shutdown.py.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import sysconfig
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from helpers import ROS_SHUT_DOWN, TIMEOUT, error_reports, tracebacks_after_start
from rclpy.context import Context

from ros_tutorials_common import shutdown

BIN = Path(sys.executable).parent
ROOT = Path(__file__).resolve().parents[1]
DELAYS = (0.0, 0.005, 0.01, 0.02, 0.04, 0.07, 0.1, 0.15, 0.25, 0.4, 0.6, 0.9, 1.4)
# Killed by SIGINT (a shell shows 130), 130 from the program itself, or 0 from a program
# for which Ctrl-C is the normal end (a node, once running).
STOPPED = {-signal.SIGINT, 128 + signal.SIGINT, 0}
LOST_GRACE = 2.0  # seconds a program whose Ctrl-C Python lost has to end anyway
LOST_WAIT = 10.0  # seconds before a Ctrl-C sent before the ROS wheels' re-exec is pressed again
# Python's words for a KeyboardInterrupt while it initialises (its streams, site): status 1.
INIT_INTERRUPTED = re.compile(r"^Fatal Python error: init_\w+: .*\nPython runtime state: ", re.M)


def stopped_well(status: int, err: str, node: bool = False) -> bool:
    """How a command may end after Ctrl-C (see the module's docstring): killed by SIGINT or
    its own 0 or 130, or status 1 where Python's report of a Ctrl-C while starting ended it
    (for NODE, a lesson node or its launch, also rclpy's refusal to create the node in the
    context its signal handler has shut down: helpers.ROS_SHUT_DOWN)."""
    init = INIT_INTERRUPTED.search(err)  # Python ends there: what follows is its own report
    if err.count("Fatal Python error") != (1 if init else 0):
        return False
    before = err[: init.start()] if init else err
    if tracebacks_after_start(before, node):
        return False
    return status in STOPPED or (status == 1 and bool(init or error_reports(before)))


def user_env() -> dict[str, str]:
    """The test's environment as a user's shell has it: the ROS wheels' bootstrap not done."""
    env = dict(os.environ)
    env.pop("_ROS_WHEELS_BOOTSTRAP_COMPLETE", None)
    return env


def lost_while_starting(err: str) -> bool:
    """Whether Python lost the Ctrl-C while the program started, and said so: raised in a
    callback Python runs for itself during an import (a module lock's weakref callback), it
    reports "Exception ignored in: ..."; raised while site runs a .pth file's line, site
    reports "Error processing line 1 of ....pth" and goes on; raised while Python checks the
    script's folder for sys.path, it reports "Failed checking if argv[0] is an import path
    entry" and goes on (docs/dev/limits.md)."""
    lost = re.search(
        r"^(Exception ignored in: |Error processing line \d+ of "
        r"|Failed checking if argv\[0\] is an import path entry).*\n(?:.*\n)*? *KeyboardInterrupt",
        err,
        re.M,
    )
    return bool(lost) and not tracebacks_after_start(err)


def _text(written: bytearray) -> str:
    return written.decode(errors="replace")


def _before_reexec(pid: int) -> bool:
    """Whether the process is still the interpreter that the ROS wheels' bootstrapper (a .pth
    file) replaces by a new one with the libraries' path: a Ctrl-C whose handler Python has
    not run yet when it calls execve is lost (docs/dev/limits.md)."""
    try:
        return b"_ROS_WHEELS_BOOTSTRAP_COMPLETE=" not in Path(f"/proc/{pid}/environ").read_bytes()
    except OSError:  # ended already
        return False


def _has_a_ros_node(group: int) -> bool:
    """Whether a process of the group has a DDS participant yet (Fast DDS's threads, named
    dds.*): a tool or node has made its ROS node, so its start is over. Before that, Python
    has now and then lost a Ctrl-C without a word (a rostopic echo pressed 0.4 s into its
    start, under the full suite, waited on as if nothing came; docs/dev/limits.md)."""
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            if int(stat.read_text().rsplit(")", 1)[1].split()[2]) != group:
                continue
            threads = stat.parent / "task"
            if any((t / "comm").read_text().startswith("dds.") for t in threads.iterdir()):
                return True
        except (OSError, ValueError, IndexError):
            continue  # gone meanwhile
    return False


def _ends(process: subprocess.Popen, written: bytearray, timeout: float) -> bool:
    """Whether the process ends within timeout seconds; False sooner (LOST_GRACE) once its
    output says Python lost the Ctrl-C while starting."""
    deadline = time.monotonic() + timeout
    while process.poll() is None:
        if lost_while_starting(_text(written)):
            try:
                process.wait(LOST_GRACE)
            except subprocess.TimeoutExpired:
                return False
        elif time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


def interrupt_after(command: list[str], delay: float, group: bool) -> tuple[int, str]:
    """Start command, SIGINT it after delay seconds, wait for its end: (status, stderr). A
    Ctrl-C that Python lost while starting (its "Exception ignored" lines, before the ROS
    wheels' re-exec, or without a word before the program had a ROS node) is pressed again,
    as a user would."""
    process = subprocess.Popen(
        command,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        env=user_env(),
        start_new_session=True,  # its own process group, as a terminal's foreground job
    )
    written = bytearray()

    def read() -> None:
        for chunk in iter(lambda: process.stderr.read1(), b""):
            written.extend(chunk)

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    time.sleep(delay)  # where in the start the Ctrl-C falls; nothing depends on the exact time
    press = os.killpg if group else os.kill
    before_reexec = _before_reexec(process.pid)
    starting = not _has_a_ros_node(process.pid)
    press(process.pid, signal.SIGINT)
    ended = _ends(process, written, LOST_WAIT if before_reexec or starting else TIMEOUT)
    text = _text(written)
    silent = starting and not tracebacks_after_start(text)  # lost, saying nothing
    if not ended and (before_reexec or silent or lost_while_starting(text)):
        press(process.pid, signal.SIGINT)
        ended = _ends(process, written, TIMEOUT)
    if ended:
        reader.join(TIMEOUT)
        return process.returncode, _text(written)
    # Whether the Ctrl-C is still pending (SigPnd/ShdPnd bit 2) and blocked (SigBlk), and
    # (SIGABRT: Python's fault handler, PYTHONFAULTHANDLER in conftest) where each thread was.
    try:
        status = Path(f"/proc/{process.pid}/status").read_text().splitlines()
    except OSError:
        status = []
    masks = [line for line in status if line.startswith(("SigPnd", "ShdPnd", "SigBlk"))]
    os.killpg(process.pid, signal.SIGABRT)
    try:
        process.wait(5)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
    reader.join(5)
    text = _text(written)
    pytest.fail(
        f"{command}: still running {TIMEOUT:.0f} s after Ctrl-C at {delay} s; "
        + " ".join(masks)
        + "; where it was:\n"
        + (text if len(text) < 6000 else f"{text[:3000]}\n...\n{text[-3000:]}")
    )


# name: (command line, SIGINT to its process group (a terminal's Ctrl-C), runs lesson nodes)
COMMANDS = {
    "rostopic echo (a tool, ROS 1 spelling)": (
        [str(BIN / "rostopic"), "echo", "/chatter"],
        False,
        False,
    ),
    "talker (a lesson node)": ([str(BIN / "talker")], False, True),
    "rosrun add_two_ints_server (exec)": (
        [str(BIN / "rosrun"), "ros_tutorials_service", "add_two_ints_server"],
        False,
        True,
    ),
    "rviz2 (a web server)": ([str(BIN / "rviz2"), "--port", "0"], False, False),
    "roslaunch union.launch (the launcher and its children)": (
        [str(BIN / "roslaunch"), "ros_tutorials_topic", "union.launch"],
        True,
        True,
    ),
}


@pytest.mark.parametrize("name", COMMANDS)
def test_ctrl_c_at_any_instant_of_the_start_ends_it_with_no_traceback_once_running(
    name: str, ros_domain: int
):
    command, group, node = COMMANDS[name]
    with ThreadPoolExecutor(max_workers=4) as pool:
        runs = list(pool.map(lambda delay: interrupt_after(command, delay, group), DELAYS))
    bad = [
        f"Ctrl-C after {delay} s: status {status}\n{err}"
        for delay, (status, err) in zip(DELAYS, runs, strict=True)
        if not stopped_well(status, err, node)
    ]
    assert not bad, f"{len(bad)} of {len(DELAYS)} runs of {name}:\n" + "\n".join(bad[:2])


def test_no_code_runs_at_every_start_of_python_and_console_scripts_are_pips():
    """Ctrl-C needs nothing of the environment: no .pth file of this project, and the console
    scripts start Python directly."""
    site_packages = Path(sysconfig.get_paths()["purelib"])
    assert not list(site_packages.glob("*ros_tutorials_ctrl_c*"))
    for name in ("ros2", "rostopic", "roslaunch", "talker"):
        first = (BIN / name).read_text().splitlines()[0]
        assert first == f"#!{sys.executable}", first


def test_make_setup_removes_what_an_older_set_up_installed_for_ctrl_c(tmp_path: Path):
    """An older clone's venv: its .pth file goes and its console scripts get pip's line back
    (tools/remove_ctrl_c_hold.py, run by `make setup`); other files stay as they were."""
    site_packages = tmp_path / "lib" / "python3.11" / "site-packages"
    site_packages.mkdir(parents=True)
    (site_packages / "00_ros_tutorials_ctrl_c.pth").write_text("import _signal\n")
    (site_packages / "other.pth").write_text("import other\n")
    (tmp_path / "bin").mkdir()
    held = tmp_path / "bin" / "rostopic"
    body = "# -*- coding: utf-8 -*-\nfrom ros2cmd.ros1 import rostopic\n"
    held.write_text(f"#!/usr/bin/env -S --block-signal=INT {sys.executable}\n{body}")
    plain = tmp_path / "bin" / "pip"
    plain.write_text(f"#!{sys.executable}\nimport sys\n")
    (tmp_path / "bin" / "python").symlink_to(sys.executable)
    tool = [sys.executable, "-S", str(ROOT / "tools" / "remove_ctrl_c_hold.py"), str(tmp_path)]
    said = subprocess.run(tool, capture_output=True, text=True, check=True).stdout
    assert "removed" in said and "1 console scripts" in said, said
    assert sorted(p.name for p in site_packages.iterdir()) == ["other.pth"]
    assert held.read_text() == f"#!{sys.executable}\n{body}"
    assert plain.read_text() == f"#!{sys.executable}\nimport sys\n"
    again = subprocess.run(tool, capture_output=True, text=True, check=True).stdout
    assert again == "", "a second run finds nothing to undo"


def test_a_ctrl_c_that_pybind11_turned_into_an_error_ends_quietly(monkeypatch):
    """A KeyboardInterrupt raised while rclpy's C++ converts a value (a message's __init__ in
    take_message) comes out as pybind11's RuntimeError: a stop once Ctrl-C was pressed, and
    an error (with its traceback) otherwise."""
    converted = RuntimeError(
        "Unable to convert call argument '0' to Python object (#define "
        "PYBIND11_DETAILED_ERROR_MESSAGES or compile in debug mode for details)"
    )
    monkeypatch.setattr(shutdown, "presses", 0)
    assert not shutdown.interrupted(converted)
    monkeypatch.setattr(shutdown, "presses", 1)
    assert shutdown.interrupted(converted)
    assert not shutdown.interrupted(RuntimeError("another error"))


def test_a_command_that_runs_until_ctrl_c_ends_normally_on_an_error_the_ctrl_c_caused():
    """`rostopic echo` (until_stopped) Ctrl-C'd while rclpy's C++ ran its Python code: the
    error that comes out (here one raised in handling the KeyboardInterrupt) is its normal end,
    as the KeyboardInterrupt itself is; an error of its own still goes up."""
    from ros2cmd.graph import until_stopped

    def fails_after_ctrl_c():
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as ctrl_c_pressed:
            message = "<built-in method take_message> returned a result with an error set"
            raise SystemError(message) from ctrl_c_pressed

    with until_stopped():
        raise KeyboardInterrupt
    with until_stopped():
        fails_after_ctrl_c()
    with pytest.raises(ValueError), until_stopped():
        raise ValueError("not a Ctrl-C")


def test_rclpy_objects_cut_short_by_ctrl_c_are_not_reported_and_other_errors_are(monkeypatch):
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

    monkeypatch.setattr(sys, "__unraisablehook__", seen.append)  # Python's, which prints
    shutdown._unraisable(unraisable(failed.value, Future.__del__))
    shutdown._unraisable(unraisable(executor_failed.value, SingleThreadedExecutor.__del__))
    assert seen == []
    other = unraisable(AttributeError("x"), stopped_well)
    shutdown._unraisable(other)
    assert seen == [other]


def test_keyboard_interrupt_waits_until_rclpy_has_shut_ros_down(context):
    """The SIGINT handler ros_args installs (ros_tutorials_common/ros/node_main.py) raises
    KeyboardInterrupt only once the context is down: here it waits for a thread that shuts
    the context down later, as rclpy's signal handler thread does, and gives up after its
    timeout while the context stays up."""
    from ros_tutorials_common.ros.node_main import _RosDown

    handler = _RosDown(context)
    assert handler.ros_is_up()
    assert not handler.wait_until_down(0.2), "the context is up: the wait must give up"
    shutting_down = threading.Timer(0.3, context.shutdown)
    shutting_down.start()
    try:
        assert handler.wait_until_down(TIMEOUT)
        assert not context.ok(), "the wait ended before the context was down"
    finally:
        shutting_down.join()
    assert not _RosDown(Context()).ros_is_up(), "a context never initialised"


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
    one; the executor drops one per callback): it reports it as unraisable and runs on. The
    tools' hook (shutdown.count_presses) delivers that Ctrl-C again, so the tool stops (`rostopic
    echo` ran on for 30 s after a Ctrl-C under load). Here the Ctrl-C lands in a __del__."""
    code = (
        "import os, signal, sys, time\n"
        "from ros_tutorials_common import shutdown\n"
        "shutdown.count_presses()\n"
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


def test_sigterm_at_any_instant_of_a_nodes_start_ends_it_by_sigterm_or_normally(ros_domain: int):
    """A talker sent SIGTERM as it started ends by SIGTERM, normally, or by rclpy's error for
    what it did in the context rclpy's SIGTERM handler had just shut down in its own thread
    (create the node, or publish from its timer: a plain rclpy node's race, status 1): never
    by SIGINT as after a Ctrl-C, never by another error."""

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
    ended = {0, -signal.SIGTERM, 128 + signal.SIGTERM}

    def ended_well(status: int, err: str) -> bool:
        if status == 1:  # rclpy refused to go on in the context SIGTERM shut down
            reports = error_reports(err)
            return bool(reports) and all(ROS_SHUT_DOWN.search(r[-1][-1]) for r in reports)
        return status in ended and "Traceback" not in err

    bad = [
        f"SIGTERM after {delay} s: status {status}\n{err}"
        for delay, (status, err) in zip(DELAYS, runs, strict=True)
        if not ended_well(status, err)
    ]
    assert not bad, f"{len(bad)} of {len(DELAYS)} runs:\n" + "\n".join(bad[:2])
