"""The docs never drift: the shell blocks of README.md and docs/ run, and print what they show.

A page's ```sh block is what a learner is told to type; the ``` block right after it (no
language) is what the page says they will see. Each sh block is either listed in CHECKS below
(how to run it: which of its lines, after which processes the page's earlier steps started)
or carries, on the line before it, `<!-- not checked: REASON -->` (a window, a keyboard, a
command that runs until Ctrl-C ...). A new block with neither fails here, naming its page and
line; so does a check whose block is gone.

The checked blocks of a page run in the page's order, grouped by what runs beside them (a
scene: turtlesim, a lesson's server, union.launch), each group in a ROS_DOMAIN_ID of its own
(own_domain) with the scene's processes started as the page starts them. A block's lines run
in one bash, as typed (from a fresh folder, HOME there too, with .venv activated: `source
.venv/bin/activate` means this clone's); each must exit 0 (or, for a block that shows an
error, the last must fail), and their output must be what the page shows, once what
legitimately varies is made alike (normalise): log time stamps, pids, goal ids, the clone's
and the home folder's path, and `...` on a line of its own in the page stands for lines left
out. Blocks whose numbers vary (a pose, a time stamp, a count) compare with every number
alike. Where a scene's processes must first discover each other, a block that does not yet
print what the page shows runs again, until TIMEOUT.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

import pytest
from helpers import BIN, TIMEOUT, NodeProcess, script

ROOT = Path(__file__).resolve().parent.parent
PAGES = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md")])
HEADLESS = {"DISPLAY": "", "WAYLAND_DISPLAY": ""}
NOT_CHECKED = re.compile(r"^\s*<!-- not checked: (\S.*?) -->\s*$")
FENCE_OPEN = re.compile(r"^( *)```(\S*)\s*$")
FENCE_CLOSE = re.compile(r"^ *```\s*$")
# A page whose every block is marked: why it has no checked step.
NO_CHECKED_STEP = {
    "docs/dev/testing.md": "its commands run the test suite itself",
    "docs/ros1-to-ros2.md": "its one block sets variables for two machines",
    "docs/rqt-in-the-browser.md": "its steps are clicks in a browser (tests/test_web_rqt.py)",
}
# Where a line's output ends in the one bash that runs a block: a line of its own.
END = "\x1eend of line, exit status "


@dataclass(frozen=True)
class Block:
    page: str  # relative to the clone
    line: int  # the opening fence's line, from 1
    commands: tuple[str, ...]
    shown: tuple[str, ...] | None  # the output block right after it, if any
    not_checked: str | None  # the marker's reason

    @property
    def key(self) -> tuple[str, str]:
        return self.page, self.commands[0].strip()

    def __str__(self) -> str:
        return f"{self.page}:{self.line}"


@dataclass(frozen=True)
class Check:
    """How one block runs. scene: what runs beside it (SCENES), started as the page's earlier
    steps start it; lines: the indexes of the block's lines to run (None: all; the others
    start something the scene already runs, or run until Ctrl-C); said: lines whose comment
    (up to two spaces or `...`) is what that line prints; started: the block starts the
    scene, and the page shows what its last process prints first; numbers: every number
    varies; fails: the last line must fail."""

    scene: str | None = None
    lines: tuple[int, ...] | None = None
    said: tuple[int, ...] = ()
    started: bool = False
    numbers: bool = False
    fails: bool = False


# What runs beside a block: commands as the pages type them, and a line each prints once ready
# (None: nothing to wait for).
SCENES: dict[str, tuple[tuple[str, str | None], ...]] = {
    "turtlesim": (("ros2 run turtlesim turtlesim_node", "Spawning turtle [turtle1]"),),
    "action_server": (("action_server", None),),  # it logs nothing until a goal comes
    "service_server": (("service_server", "ready srv server!"),),
    "add_two_ints": (("add_two_ints_server", "Ready to add two ints."),),
    "parameter_server": (("service_server_with_parameter", "ready srv server!"),),
    "params_file": (
        (
            "service_server_with_parameter --ros-args --params-file "
            "ros_tutorials_parameter/config/parameters.yaml",
            "ready srv server!",
        ),
    ),
    "parameter_3": (
        ("service_server_with_parameter --ros-args -p calculation_method:=3", "ready srv server!"),
    ),
    "dynamics_talker": (("dynamics_talker", "hello world"),),
    "dynamics_goodbye": (("dynamics_talker --ros-args -p talker_str:=Goodbye", "Goodbye"),),
    "topic_publisher": (("topic_publisher", "send msg"),),
    "topic_pair": (("topic_publisher", "send msg"), ("topic_subscriber", "recieve msg")),
    "talker_listener": (("talker", "hello world"), ("listener", "I heard: [hello world")),
    "union": (("roslaunch ros_tutorials_topic union.launch --screen", "recieve msg"),),
    "seeds": (
        ("aandb_talker", "[talker]: msg a: 1.000000, msg b:2.000000"),
        ("aandb_listener", "[listener]: I heard: msg:a 1.000000, msg:b 2.000000"),
        ("num_publisher", None),
        ("num_subscriber", "[sub]: I heard: ["),
        ("user_record_publisher", None),
        ("user_record_subscriber", "Receive : Ada Lovelace, age 36, score "),
    ),
    "workspace": (),  # no process: the blocks share their folder (~/ros2_ws)
    "tf2_demo": (
        ("ros2 launch turtle_tf2_py turtle_tf2_demo.launch.py", "Successfully spawned turtle2"),
    ),
}

CHECKS: dict[tuple[str, str], Check] = {
    # README.md
    ("README.md", "source .venv/bin/activate"): Check(
        scene="turtlesim", lines=(0, 2, 4, 7), said=(2,)
    ),
    # actions.md
    ("docs/actions.md", "action_server            # terminal 1"): Check(
        scene="action_server", lines=(1,)
    ),
    ("docs/actions.md", "ros2 action list -t"): Check(scene="action_server"),
    ("docs/actions.md", "ros2 action info /ros_tutorial_action"): Check(scene="action_server"),
    ("docs/actions.md", "ros2 interface show ros_tutorials_interfaces/action/Fibonacci"): Check(),
    (
        "docs/actions.md",
        "ros2 action send_goal /ros_tutorial_action ros_tutorials_interfaces/action/Fibonacci"
        " '{order: 3}' --feedback",
    ): Check(scene="action_server"),
    ("docs/actions.md", "action_client 50"): Check(scene="action_server", fails=True),
    # command-line-tools.md
    ("docs/command-line-tools.md", "ros2 -h"): Check(),
    # rviz-in-the-browser.md
    ("docs/rviz-in-the-browser.md", "rviz2 -d robot.rviz"): Check(fails=True),
    (
        "docs/command-line-tools.md",
        "ros2 node info /turtlesim          # or: rosnode info /turtlesim",
    ): Check(scene="turtlesim"),
    ("docs/command-line-tools.md", "ros2 topic list -t"): Check(scene="turtlesim"),
    (
        "docs/command-line-tools.md",
        "ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist '{linear: {x: 2.0}}'",
    ): Check(scene="turtlesim"),
    ("docs/command-line-tools.md", "ros2 service call /clear std_srvs/srv/Empty"): Check(
        scene="turtlesim"
    ),
    ("docs/command-line-tools.md", "ros2 param list"): Check(scene="turtlesim"),
    (
        "docs/command-line-tools.md",
        "ros2 param get /turtlesim background_b      # Integer value is: 255",
    ): Check(scene="turtlesim", said=(0, 1)),
    (
        "docs/command-line-tools.md",
        "rosservice call /ros_tutorial_srv 10 5        # result: 15  (1: plus, the default)",
    ): Check(scene="parameter_server", said=(0, 2, 4, 6)),
    # launch.md
    ("docs/launch.md", "rosnode list"): Check(scene="union"),
    ("docs/launch.md", "ros2 topic list"): Check(scene="union"),
    ("docs/launch.md", "roslaunch union.launch --print"): Check(),
    ("docs/launch.md", "roslaunch ros_tutorials_parameter combine.launch --show-args"): Check(),
    ("docs/launch.md", "source .venv/bin/activate"): Check(lines=(0, 5, 6)),
    # official-tutorials.md
    ("docs/official-tutorials.md", "rosdep init"): Check(),
    # tf2.md
    ("docs/tf2.md", "ros2 node list"): Check(scene="tf2_demo"),
    ("docs/tf2.md", "ros2 pkg executables turtle_tf2_py"): Check(),
    # urdf.md
    ("docs/urdf.md", "ros2 pkg executables robot_state_publisher"): Check(),
    (
        "docs/urdf.md",
        "ros2 run robot_state_publisher robot_state_publisher --ros-args -p "
        "\"robot_description:=<robot name='r'/>\"",
    ): Check(fails=True),
    # own-package.md
    (
        "docs/own-package.md",
        "source .venv/bin/activate                 # in every new terminal"
        " (or: source install/setup.bash below)",
    ): Check(scene="workspace"),
    ("docs/own-package.md", "colcon build"): Check(scene="workspace", numbers=True),
    ("docs/own-package.md", "source install/setup.bash"): Check(scene="workspace", said=(2, 3)),
    # parameters.md
    (
        "docs/parameters.md",
        "service_server_with_parameter                # terminal 1",
    ): Check(scene="parameter_server", lines=(1,)),
    ("docs/parameters.md", "rosparam list"): Check(scene="parameter_server"),
    ("docs/parameters.md", "ros2 param describe /service_server calculation_method"): Check(
        scene="parameter_server"
    ),
    (
        "docs/parameters.md",
        "rosservice call /ros_tutorial_srv 10 5        # result: 15  (1: plus, the default)",
    ): Check(scene="parameter_server", said=(0, 2, 4, 6)),
    ("docs/parameters.md", "ros2 param set /service_server calculation_method 3"): Check(
        scene="parameter_server"
    ),
    ("docs/parameters.md", "ros2 param get /service_server calculation_method"): Check(
        scene="parameter_server"
    ),
    ("docs/parameters.md", "ros2 param set /service_server calculation_method 7"): Check(
        scene="parameter_server", fails=True
    ),
    ("docs/parameters.md", "ros2 param dump /service_server"): Check(scene="parameter_server"),
    (
        "docs/parameters.md",
        "service_server_with_parameter --ros-args --params-file "
        "ros_tutorials_parameter/config/parameters.yaml",
    ): Check(scene="params_file", lines=(1,), said=(1,)),
    (
        "docs/parameters.md",
        "dynamics_talker                              # [dynamics_talker]: hello world,"
        " 10 times a second",
    ): Check(scene="dynamics_talker", lines=(1,)),
    ("docs/parameters.md", "rosparam set /calculation_method 2"): Check(
        scene="parameter_server", said=(2,)
    ),
    ("docs/parameters.md", "dynamics_talker --ros-args -p talker_str:=Goodbye"): Check(
        scene="dynamics_goodbye", lines=(1, 2)
    ),
    (
        "docs/parameters.md",
        "service_server_with_parameter --ros-args -p calculation_method:=3",
    ): Check(scene="parameter_3", lines=(), started=True),
    # rosbag.md
    (
        "docs/rosbag.md",
        "rosbag record -O mybag --duration 3 /ros_tutorial_msg      # or: ros2 bag record"
        " -o mybag ...; without --duration, Ctrl-C ends it",
    ): Check(scene="topic_publisher", numbers=True),
    ("docs/rosbag.md", "ros2 bag info mybag          # or: rosbag info mybag"): Check(
        scene="topic_publisher", numbers=True
    ),
    ("docs/rosbag.md", "rosbag play mybag            # or: ros2 bag play mybag"): Check(
        scene="topic_publisher", numbers=True
    ),
    # rqt-and-logging.md
    ("docs/rqt-and-logging.md", "rqt_graph -o graph.svg"): Check(scene="union"),
    ("docs/rqt-and-logging.md", "rqt_logger_level /ns1/topic_publisher"): Check(scene="union"),
    (
        "docs/rqt-and-logging.md",
        "rqt_logger_level /ns1/topic_publisher warn   # its INFO lines stop; `info` brings them"
        " back",
    ): Check(scene="union"),
    (
        "docs/rqt-and-logging.md",
        "rqt_graph                         # a window that follows nodes as they come and go"
        " (needs a display)",
    ): Check(scene="union", lines=(1, 2)),
    (
        "docs/rqt-and-logging.md",
        "rqt_logger_level                                   # every node that serves them,"
        " and its level",
    ): Check(scene="union"),
    # seeds/README.md
    (
        "docs/seeds/README.md",
        "aandb_talker         # seed 002: [talker]: msg a: 1.000000,"
        " msg b:2.000000   (AandB on chatter, 10 Hz)",
    ): Check(scene="seeds", lines=(), started=True),
    # services.md
    ("docs/services.md", "service_server"): Check(scene="service_server", lines=(), started=True),
    ("docs/services.md", "service_client 2 3"): Check(scene="service_server"),
    ("docs/services.md", "rosservice call /ros_tutorial_srv 10 2          # the book's way"): Check(
        scene="service_server"
    ),
    (
        "docs/services.md",
        "ros2 service call /ros_tutorial_srv ros_tutorials_interfaces/srv/SrvTutorial"
        " '{a: 10, b: 2}'",
    ): Check(scene="service_server"),
    ("docs/services.md", "ros2 service type /ros_tutorial_srv"): Check(scene="service_server"),
    (
        "docs/services.md",
        "ros2 interface show ros_tutorials_interfaces/srv/SrvTutorial   # or: rossrv show"
        " ros_tutorials_interfaces/SrvTutorial",
    ): Check(),
    ("docs/services.md", "service_client 2 3 --timeout 1"): Check(fails=True),
    ("docs/services.md", "service_client 1.5 2"): Check(fails=True),
    ("docs/services.md", "add_two_ints_client 1 2             # terminal 2"): Check(
        scene="add_two_ints", lines=(1,)
    ),
    ("docs/services.md", "rosservice args /add_two_ints       # a b"): Check(
        scene="add_two_ints", said=(0, 1)
    ),
    # topics.md
    ("docs/topics.md", "topic_publisher"): Check(scene="topic_publisher", lines=(), started=True),
    ("docs/topics.md", "topic_subscriber"): Check(
        scene="topic_pair", lines=(), started=True, numbers=True
    ),
    ("docs/topics.md", "ros2 topic list"): Check(scene="topic_pair"),
    ("docs/topics.md", "ros2 topic info /ros_tutorial_msg"): Check(scene="topic_pair"),
    (
        "docs/topics.md",
        "ros2 topic echo /ros_tutorial_msg --once     # or: rostopic echo -n 1 /ros_tutorial_msg",
    ): Check(scene="topic_pair", numbers=True),
    (
        "docs/topics.md",
        "ros2 interface show ros_tutorials_interfaces/msg/MsgTutorial   # or: rosmsg show"
        " ros_tutorials_interfaces/MsgTutorial",
    ): Check(),
    ("docs/topics.md", "talker          # terminal 1: [talker]: hello world 0 ..."): Check(
        scene="talker_listener", lines=(), started=True
    ),
    # turtlesim.md
    (
        "docs/turtlesim.md",
        "ros2 run turtlesim turtlesim_node          # or, as seeds 001 and 004:"
        " rosrun turtlesim turtlesim_node",
    ): Check(scene="turtlesim", lines=(), started=True),
    ("docs/turtlesim.md", "ros2 node list"): Check(scene="turtlesim"),
    ("docs/turtlesim.md", "rostopic list"): Check(scene="turtlesim"),
    ("docs/turtlesim.md", "rostopic echo -n 1 /turtle1/pose"): Check(
        scene="turtlesim", numbers=True
    ),
    (
        "docs/turtlesim.md",
        'ros2 service call /turtle1/set_pen turtlesim/srv/SetPen "{r: 255, g: 255, b: 255,'
        ' width: 10, off: 0}"',
    ): Check(scene="turtlesim"),
    ("docs/turtlesim.md", "rosservice type /spawn | rossrv show"): Check(scene="turtlesim"),
    ("docs/turtlesim.md", 'rosservice call /spawn 3 3 0.2 "new_turtle"'): Check(scene="turtlesim"),
    (
        "docs/turtlesim.md",
        "ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute"
        " '{theta: 1.57}'",
    ): Check(scene="turtlesim", numbers=True),
    (
        "docs/turtlesim.md",
        "rostopic pub /turtle1/cmd_vel geometry_msgs/Twist 'linear: x: 0.2'"
        "     # the seed's short form, accepted",
    ): Check(scene="turtlesim", lines=(3, 4)),
    (
        "docs/turtlesim.md",
        "rosrun turtlesim turtlesim_node                  # or: turtlesim_node",
    ): Check(scene="turtlesim", lines=(1, 4, 6), said=(1,)),
    ("docs/turtlesim.md", "ros2 param set /turtlesim background_b 0"): Check(
        scene="turtlesim", lines=(0, 1, 2, 3)
    ),
}


def blocks(page: Path) -> list[Block]:
    """The page's sh blocks, each with the output block right after it and its marker."""
    lines = page.read_text().splitlines()
    found = []
    index = 0
    while index < len(lines):
        opening = FENCE_OPEN.match(lines[index])
        if not opening:
            index += 1
            continue
        indent, language = len(opening.group(1)), opening.group(2)
        start = index
        index += 1
        body = []
        while index < len(lines) and not FENCE_CLOSE.match(lines[index]):
            body.append(lines[index][indent:])
            index += 1
        index += 1
        if language != "sh":
            continue
        shown = None
        after = index
        while after < len(lines) and not lines[after].strip():
            after += 1
        if after < len(lines) and FENCE_CLOSE.match(lines[after]) and after - index <= 1:
            out = []
            after += 1
            while after < len(lines) and not FENCE_CLOSE.match(lines[after]):
                out.append(lines[after][indent:])
                after += 1
            shown = tuple(out)
        before = start - 1
        while before >= 0 and not lines[before].strip():
            before -= 1
        marker = NOT_CHECKED.match(lines[before]) if before >= 0 else None
        found.append(
            Block(
                str(page.relative_to(ROOT)),
                start + 1,
                tuple(line for line in body if line.strip()),
                shown,
                marker.group(1) if marker else None,
            )
        )
    return found


BLOCKS = [block for page in PAGES for block in blocks(page)]


def named(page: str, line: str) -> list[Block]:
    """The blocks a CHECKS key names: the one that starts with the line, else those that have
    it."""
    first = [b for b in BLOCKS if b.page == page and b.commands[0].strip() == line]
    return first or [
        b for b in BLOCKS if b.page == page and line in (c.strip() for c in b.commands)
    ]


def check_of(block: Block) -> Check | None:
    for (page, line), check in CHECKS.items():
        if block in named(page, line):
            return check
    return None


def test_every_sh_block_is_checked_or_says_why_not():
    problems = []
    for block in BLOCKS:
        check = check_of(block)
        if check is None and block.not_checked is None:
            problems.append(
                f"{block}: a ```sh block that is neither checked (CHECKS in {Path(__file__).name})"
                " nor marked `<!-- not checked: REASON -->` on the line before it"
            )
        elif check is not None and block.not_checked is not None:
            problems.append(f"{block}: checked and marked not checked ({block.not_checked})")
    for (page, line), _ in CHECKS.items():
        matching = named(page, line)
        if len(matching) != 1:
            problems.append(f"{page}: {len(matching)} sh blocks have the line {line!r} (one must)")
    assert not problems, "\n".join(problems)


def test_every_page_has_a_checked_step():
    pages = {block.page for block in BLOCKS}
    unchecked = sorted(
        page
        for page in pages
        if page not in NO_CHECKED_STEP
        and not any(check_of(block) for block in BLOCKS if block.page == page)
    )
    assert not unchecked, f"pages without a checked sh block: {unchecked}"
    assert pages > set(NO_CHECKED_STEP)


def normalise(text: str, home: Path, numbers: bool) -> list[str]:
    """Lines as alike as what legitimately varies allows."""
    text = text.replace(str(ROOT), "<clone>").replace(str(home), "~")
    text = re.sub(r"/(?:root|home/[\w.-]+)(?=/|\b)", "~", text)
    # An absolute path to a file of a clone, as the page's writer's clone had it.
    text = re.sub(
        r"/[^\s:()'\"]+?(?=/(?:ros2cmd|ros_tutorials_\w+|\.venv|launcher)/)", "<clone>", text
    )
    text = re.sub(r"(\[ ?[A-Z]+\]) \[(?:\d+\.\d+|\.\.\.)\]", r"\1 [...]", text)
    text = re.sub(r"\(pid \d+\)", "(pid N)", text)
    text = re.sub(r"ID: [0-9a-f]{32}", "ID: <id>", text)
    text = re.sub(r"\.py: \d+:", ".py: N:", text)  # a warning's line in the code
    if numbers:
        text = re.sub(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", "#", text)
    # `ros2 topic pub --once` says it waits only when the subscriber is not matched yet when it
    # looks (ros2cli's too): whether it is depends on discovery's timing, not on the command.
    text = re.sub(
        r"^Waiting for at least \d+ matching subscription\(s\)\.\.\.\n", "", text, flags=re.M
    )
    lines = [line.rstrip() for line in text.splitlines()]
    while lines and not lines[-1]:
        lines.pop()
    while lines and not lines[0]:
        lines.pop(0)
    return lines


def matches(shown: list[str], printed: list[str], prefix: bool = False) -> bool:
    """The printed lines are what the page shows (`...` on a line: any lines; prefix: the
    page shows how the output starts)."""
    parts = [r"(?:.*\n)*?" if line.strip() == "..." else re.escape(line) + r"\n" for line in shown]
    pattern = "".join(parts) + (r"(?:.*\n)*" if prefix else "")
    return re.fullmatch(pattern, "".join(line + "\n" for line in printed)) is not None


def said(command: str) -> str:
    """The output a line's comment says it prints: up to two spaces, or `...`."""
    comment = command.partition("#")[2].strip()
    return re.split(r"  |\.\.\.", comment)[0].strip()


def command_words(command: str) -> list[str]:
    words = shlex.split(command, comments=True)
    # A file of the clone, named as from its root.
    return [str(ROOT / word) if "/" in word and (ROOT / word).is_file() else word for word in words]


def start(command: str, ready: str | None, cwd: Path) -> NodeProcess:
    words = command_words(command)
    process = NodeProcess(script(words[0]), *words[1:], env={**HEADLESS, "HOME": str(cwd)})
    if ready is not None:
        process.wait_for_text(ready)
    return process


def run_block(block: Block, check: Check, cwd: Path) -> list[tuple[str, str, int]]:
    """The block's lines run in one bash as typed: (line, its output, its exit status) each."""
    chosen = [
        line
        for index, line in enumerate(block.commands)
        if check.lines is None or index in check.lines
    ]
    script_lines = ["exec 2>&1"]
    for line in chosen:
        line = re.sub(r"(?<![\w/])\.venv/", f"{ROOT}/.venv/", line)
        script_lines += [line, f'echo "{END}$?"']
    environment = {
        **{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"},
        **HEADLESS,
        "HOME": str(cwd),
        "PATH": f"{BIN}:{os.environ['PATH']}",
        "PYTHONUNBUFFERED": "1",
    }
    try:
        result = subprocess.run(
            ["bash", "-c", "\n".join(script_lines)],
            cwd=cwd,
            env=environment,
            capture_output=True,
            text=True,
            timeout=TIMEOUT * 2,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"{block}: did not finish within {TIMEOUT * 2:.0f} s")
    pieces = result.stdout.split(END)
    done = []
    for index, line in enumerate(chosen):
        if index + 1 >= len(pieces):
            pytest.fail(f"{block}: bash ended before {line!r}:\n{result.stdout}")
        output = pieces[index] if index == 0 else pieces[index].partition("\n")[2]
        done.append((line, output, int(pieces[index + 1].partition("\n")[0])))
    return done


def problem(block: Block, check: Check, done: list[tuple[str, str, int]], home: Path) -> str:
    """What differs from the page, or "" if nothing does."""
    for index, (line, output, status) in enumerate(done):
        last = index == len(done) - 1
        if "Traceback" in output:
            return f"{line!r} printed a traceback:\n{output}"
        if (status != 0) != (check.fails and last):
            return f"{line!r} exited with {status}:\n{output}"
        original = block.commands.index(line)
        if original in check.said and said(line) not in output:
            return f"{line!r}: its comment says {said(line)!r}; it printed:\n{output}"
    if block.shown is not None:
        shown = normalise("\n".join(block.shown), home, check.numbers)
        printed = normalise("".join(output for _, output, _ in done), home, check.numbers)
        if not matches(shown, printed):
            return "the page shows:\n" + "\n".join(shown) + "\nprinted:\n" + "\n".join(printed)
    return ""


def groups() -> list[tuple[str, str | None, list[tuple[Block, Check]]]]:
    """Each page's checked blocks, in its order, by scene."""
    found: dict[tuple[str, str | None], list[tuple[Block, Check]]] = {}
    for block in BLOCKS:
        check = check_of(block)
        if check is not None:
            found.setdefault((block.page, check.scene), []).append((block, check))
    return [(page, scene, steps) for (page, scene), steps in found.items()]


@pytest.mark.parametrize(
    ("page", "scene", "steps"),
    groups(),
    ids=[f"{page}:{scene or 'one-shot'}" for page, scene, _ in groups()],
)
def test_the_page_prints_what_it_shows(page, scene, steps, own_domain, node_process, tmp_path):
    started: list[NodeProcess] = []
    for command, ready in SCENES.get(scene, ()) if scene else ():
        words = command_words(command)
        process = node_process(
            script(words[0]), *words[1:], env={**HEADLESS, "HOME": str(tmp_path)}
        )
        if ready is not None:
            process.wait_for_text(ready)
        started.append(process)
    for block, check in steps:
        if check.started:
            shown = normalise("\n".join(block.shown or ()), tmp_path, check.numbers)
            started[-1].wait_for_output(
                lambda lines, shown=shown, check=check: matches(
                    shown, normalise("\n".join(lines), tmp_path, check.numbers), prefix=True
                ),
                what=f"what {block} shows: " + " / ".join(shown),
            )
            continue
        deadline = time.monotonic() + TIMEOUT
        while True:
            found = problem(block, check, run_block(block, check, tmp_path), tmp_path)
            if not found:
                break
            # Discovery may not have joined the scene's processes and the command yet.
            if not started or time.monotonic() > deadline:
                pytest.fail(f"{block}: {found}")
