"""The ROS 2 Jazzy tutorial "Understanding parameters" (Beginner: CLI tools), typed as printed.

This project's turtlesim runs as a process (headless), turtle_teleop_key in a pseudo-terminal;
each `ros2 param ...` line of the page is typed as the page prints it, and its output is
compared with the page's. What differs, and why: the page's nodes are C++ (rclcpp), which
declare the `qos_overrides./parameter_events.publisher.*` parameters; rclpy nodes do not, and
declare `start_type_description_service` (read-only) instead; this turtlesim has a few
parameters of its own (headless, holonomic, snapshot_*).
"""

from __future__ import annotations

import os
import shlex
import subprocess
from pathlib import Path

import pytest
import yaml
from helpers import BIN, TIMEOUT, fails, ok, run
from test_turtlesim_processes import HEADLESS, Terminal

TURTLESIM = (str(BIN / "ros2"), "run", "turtlesim", "turtlesim_node")


def typed(line: str, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """A command line of the page, in a shell (for its `>`), this environment's bin first on
    PATH as after sourcing ROS 2."""
    return subprocess.run(
        ["bash", "-c", line],
        cwd=cwd,
        env={**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ['PATH']}"},
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
    )


def page(line: str, cwd: Path | None = None) -> str:
    """A `ros2 ...` line of the page that must succeed; its standard output."""
    result = run(*shlex.split(line), cwd=str(cwd) if cwd else None)
    assert result.returncode == 0, f"{line} failed:\n{result.stderr}"
    assert "Traceback" not in result.stderr
    return result.stdout


def color_under_the_turtle() -> dict[str, int]:
    """The background colour turtlesim shows under turtle1 (its color_sensor topic)."""
    shown = ok("ros2", "topic", "echo", "--once", "/turtle1/color_sensor")
    return yaml.safe_load(shown.split("\n---")[0])


@pytest.fixture
def turtlesim(own_domain, node_process):  # the page: only what the test starts
    """`ros2 run turtlesim turtlesim_node`, headless."""
    sim = node_process(*TURTLESIM, env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    return sim


@pytest.fixture
def teleop(ros_domain):
    """`ros2 run turtlesim turtle_teleop_key` in a terminal of its own."""
    terminal = Terminal()
    terminal.wait_for("'Q' to quit.")
    yield terminal
    terminal.close()


@pytest.mark.long  # the page, step by step, and turtlesim started again: 10 to 20 s
def test_the_parameters_page(node_process, turtlesim, teleop, tmp_path):
    # 2 ros2 param list: each node's name, then its parameters indented by two spaces
    listed = page("ros2 param list").splitlines()
    assert listed.index("/teleop_turtle:") < listed.index("/turtlesim:")
    teleop_params = listed[listed.index("/teleop_turtle:") + 1 : listed.index("/turtlesim:")]
    turtlesim_params = listed[listed.index("/turtlesim:") + 1 :]
    for name in ("scale_angular", "scale_linear", "use_sim_time"):
        assert f"  {name}" in teleop_params
    for name in ("background_b", "background_g", "background_r", "use_sim_time"):
        assert f"  {name}" in turtlesim_params
    assert turtlesim_params == sorted(turtlesim_params)
    assert all(line.startswith("  ") for line in teleop_params + turtlesim_params)

    # 3 ros2 param get
    assert page("ros2 param get /turtlesim background_g") == "Integer value is: 86\n"
    assert page("ros2 param get /turtlesim background_r") == "Integer value is: 69\n"
    assert page("ros2 param get /turtlesim background_b") == "Integer value is: 255\n"

    # 4 ros2 param set: the background changes at once
    assert page("ros2 param set /turtlesim background_r 150") == "Set parameter successful\n"
    assert color_under_the_turtle() == {"r": 150, "g": 86, "b": 255}

    # 5 ros2 param dump, into a file
    dumped = typed("ros2 param dump /turtlesim > turtlesim.yaml", cwd=tmp_path)
    assert dumped.returncode == 0 and dumped.stderr == "", dumped.stderr
    text = (tmp_path / "turtlesim.yaml").read_text()
    assert text.startswith(
        "/turtlesim:\n"
        "  ros__parameters:\n"
        "    background_b: 255\n"
        "    background_g: 86\n"
        "    background_r: 150\n"
    )
    assert "    use_sim_time: false\n" in text
    assert text.endswith("\n\n")  # ros2 prints the YAML, then a newline
    params = yaml.safe_load(text)["/turtlesim"]["ros__parameters"]
    assert list(params) == sorted(params)

    # 6 ros2 param load: every parameter in the file's order; read-only ones refused
    page("ros2 param set /turtlesim background_r 10")
    loaded = run("ros2", "param", "load", "/turtlesim", "turtlesim.yaml", cwd=str(tmp_path))
    assert loaded.returncode == 0, loaded.stderr
    succeeded = loaded.stdout.splitlines()
    refused = loaded.stderr.splitlines()
    for name in ("background_b", "background_g", "background_r", "use_sim_time"):
        assert f"Set parameter {name} successful" in succeeded
    assert (
        "Set parameter start_type_description_service failed: "
        "Trying to set a read-only parameter: start_type_description_service."
    ) in refused
    assert len(succeeded) + len(refused) == len(params)
    assert page("ros2 param get /turtlesim background_r") == "Integer value is: 150\n"

    # 7 the same node started with the saved file: the purple background from the start
    turtlesim.interrupt()
    again = node_process(
        *TURTLESIM, "--ros-args", "--params-file", str(tmp_path / "turtlesim.yaml"), env=HEADLESS
    )
    again.wait_for_text("Spawning turtle [turtle1]")
    assert page("ros2 param get /turtlesim background_r") == "Integer value is: 150\n"
    assert color_under_the_turtle() == {"r": 150, "g": 86, "b": 255}


def test_list_options_describe_and_delete(turtlesim):
    typed_list = page("ros2 param list /turtlesim --param-type --filter background")
    assert typed_list.splitlines() == [
        "  background_b (type: integer)",
        "  background_g (type: integer)",
        "  background_r (type: integer)",
    ]
    # prefixes are namespaces ('qos_overrides' for 'qos_overrides.x'), as rclpy lists them
    assert page("ros2 param list /turtlesim --param-prefixes background") == ""
    assert page("ros2 param get /turtlesim holonomic") == "Boolean value is: False\n"
    # started without a display: headless, and the parameter says so
    assert page("ros2 param get /turtlesim headless") == "Boolean value is: True\n"
    assert page("ros2 param get /turtlesim snapshot_path --hide-type") == "turtlesim.png\n"
    described = page("ros2 param describe /turtlesim background_r headless")
    assert described.splitlines() == [
        "Parameter name: background_r",
        "  Type: integer",
        "  Description: Red channel of the background color",
        "  Constraints:",
        "    Min value: 0",
        "    Max value: 255",
        "    Step: 1",
        "Parameter name: headless",
        "  Type: boolean",
        "  Description: Never open a window (true also when none could open)",
        "  Constraints:",
        "    Read only: true",
    ]
    # a statically typed parameter cannot be undeclared: the node's reason, in ros2's words
    line = fails("ros2", "param", "delete", "/turtlesim", "holonomic")
    assert line == "Deleting parameter failed: Static parameter cannot be undeclared"


def test_a_node_with_dynamically_typed_and_array_parameters(node_process):
    """get prints arrays as ros2param does; set types the value as YAML reads it; delete."""
    code = (
        "import rclpy\n"
        "from rclpy.node import Node\n"
        "rclpy.init()\n"
        "node = Node('arrays', allow_undeclared_parameters=True,\n"
        "            automatically_declare_parameters_from_overrides=True)\n"
        "print('ready', flush=True)\n"
        "rclpy.spin(node)\n"
    )
    arrays = node_process(
        "-c", code, "--ros-args",
        "-p", "ints:=[1, 2]", "-p", "doubles:=[1.5, 2.0]", "-p", "names:=[a, b]",
        "-p", "flags:=[true, false]", "-p", "ratio:=0.5",
    )  # fmt: skip
    arrays.wait_for_text("ready")
    ints, doubles, names, flags, ratio = (
        page(f"ros2 param get /arrays {name}")
        for name in ("ints", "doubles", "names", "flags", "ratio")
    )
    assert ints == "Integer values are: [1, 2]\n"
    assert doubles == "Double values are: [1.5, 2.0]\n"
    assert names == "String values are: ['a', 'b']\n"
    assert flags == "Boolean values are: [True, False]\n"
    assert ratio == "Double value is: 0.5\n"
    for value, shown in (
        ("'[3, 4]'", "Integer values are: [3, 4]"),
        ("hello", "String value is: hello"),
        ("true", "Boolean value is: True"),
        ("'[1, 2.5]'", "String value is: [1, 2.5]"),  # mixed: the text, as rclpy does
        ("'{a: 1}'", "String value is: {a: 1}"),
        ("\"'5'\"", "String value is: 5"),
    ):
        assert page(f"ros2 param set /arrays free {value}") == "Set parameter successful\n"
        assert page("ros2 param get /arrays free") == shown + "\n"
    assert page("ros2 param delete /arrays free") == "Deleted parameter successfully\n"
    assert "  free" not in page("ros2 param list /arrays")
    dumped = yaml.safe_load(page("ros2 param dump /arrays"))
    assert dumped["/arrays"]["ros__parameters"]["ints"] == [1, 2]


@pytest.fixture(scope="class")
def shared_turtlesim(class_own_domain, class_node_process):
    """One turtlesim for the tests of a class that leave it as it is."""
    sim = class_node_process(*TURTLESIM, env=HEADLESS)
    sim.wait_for_text("Spawning turtle [turtle1]")
    return sim


class TestBadInput:
    """Unknown nodes and parameters, wrong types, values out of range: one line, exit 1.
    One turtlesim for the class: none of these changes it (checked after each)."""

    @pytest.mark.parametrize(
        "line,expected",
        [
            (
                "ros2 param set /turtlesim background_r 300",
                "Setting parameter failed: Parameter background_r out of range. "
                "Min: 0, Max: 255, value: 300",
            ),
            (
                "ros2 param set /turtlesim background_r purple",
                "Setting parameter failed: Wrong parameter type, expected 'Type.INTEGER' "
                "got 'Type.STRING'",
            ),
            (
                "ros2 param set /turtlesim background_r 99999999999999999999",
                "error: cannot set parameter 'background_r' = 99999999999999999999 does not "
                "fit a ROS integer (int64)",
            ),
            (
                "ros2 param set /turtlesim nope 1",
                "Setting parameter failed: Invalid access to undeclared parameter(s): []",
            ),
            ("ros2 param get /turtlesim nope", "error: node '/turtlesim' has no parameter 'nope'"),
            (
                "ros2 param describe /turtlesim nope",
                "error: node '/turtlesim' has no parameter 'nope'",
            ),
            (
                "ros2 param get /nope background_r --timeout 1",
                "error: unknown node '/nope': not seen in the graph (waited 1 s)",
            ),
            (
                "ros2 param list /nope --timeout 1",
                "error: unknown node '/nope': not seen in the graph (waited 1 s)",
            ),
            (
                "ros2 param list --filter '('",
                "error: invalid --filter regular expression '(': missing ), unterminated "
                "subpattern at position 0",
            ),
        ],
    )
    def test_one_line(self, shared_turtlesim, line, expected):
        assert fails(*shlex.split(line)) == expected
        assert page("ros2 param get /turtlesim background_r") == "Integer value is: 69\n"

    def test_usage_is_exit_2(self):
        result = run("ros2", "param", "get", "/turtlesim")
        assert result.returncode == 2
        assert "the following arguments are required: parameter_name" in result.stderr

    def test_load_of_a_file_without_the_node(self, shared_turtlesim, tmp_path):
        path = tmp_path / "other.yaml"
        path.write_text("/other:\n  ros__parameters:\n    background_r: 1\n")
        line = fails("ros2", "param", "load", "/turtlesim", str(path))
        assert line == f"error: {path} has no entry that matches /turtlesim"


def test_dump_output_dir_is_humbles_deprecated_spelling(turtlesim, tmp_path):
    result = run("ros2", "param", "dump", "/turtlesim", "--output-dir", str(tmp_path))
    assert result.returncode == 0, result.stderr
    saved = tmp_path / "turtlesim.yaml"
    assert result.stdout == f"Saving to:  {saved}\n"
    assert "'--output-dir' is deprecated; use redirection to save to a file" in result.stderr
    assert yaml.safe_load(saved.read_text())["/turtlesim"]["ros__parameters"]["background_g"] == 86
