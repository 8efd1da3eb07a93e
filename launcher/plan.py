"""Plan: node declarations -> process specs with their full command lines.

A plan is plain data: it can be printed (``--print``) and tested without starting anything.
This is the one place where (package, executable) becomes a command line, and where a node's
name, namespace, remaps and parameters become standard ROS arguments:
``--ros-args -r __node:=NAME -r __ns:=/NS -r from:=to -p name:=value --params-file FILE``.
"""

from __future__ import annotations

import os
import shlex
import shutil
import sys
from dataclasses import dataclass, field
from typing import Any

from launch_foundation.declarations import AT_START, ContainerDecl, Launch, NodeDecl, Step, When
from launch_foundation.errors import LaunchError
from ros_tutorials_common import packages
from ros_tutorials_common.bounded import InputError, load_yaml

DEFAULT_SIGTERM_TIMEOUT = 5.0  # seconds after SIGINT before SIGTERM, as ros2 launch
DEFAULT_SIGKILL_TIMEOUT = 5.0  # seconds after SIGTERM before SIGKILL


@dataclass
class ProcessSpec:
    """Everything needed to start, watch and stop one process."""

    label: str  # output prefix and log file name: the node's full name without the first /
    command: list[str]
    where: str  # file:line of the declaration
    process_name: str = ""  # ros2 launch's name for it, before its number: the executable's
    node: str | None = None  # full node name, if it is a named ROS node
    env: dict[str, str | None] = field(default_factory=dict)  # changes; None unsets
    output: str = "log"
    respawn: bool = False
    respawn_delay: float = 0.0
    respawn_max_retries: int = 0
    required: bool = False
    sigterm_timeout: float = DEFAULT_SIGTERM_TIMEOUT
    sigkill_timeout: float = DEFAULT_SIGKILL_TIMEOUT
    cwd: str | None = None
    remaps: list[tuple[str, str]] = field(default_factory=list)  # shown by --print
    params: list[tuple[str, Any]] = field(default_factory=list)
    when: When = AT_START  # a timer or an event handler starts it later
    output_format: str | None = None  # NodeDecl.output_format


def command_for(package: str, executable: str, where: str) -> list[str]:
    """The command line that runs one executable of a tutorial package."""
    try:
        return packages.command(package, executable)
    except packages.UnknownExecutable as error:
        raise LaunchError(f"{where}: {error}") from None


def ros_value(value: Any) -> str:
    """A parameter value as ``-p name:=value`` needs it: rcl reads it as YAML."""
    if isinstance(value, str):
        import yaml  # here: a launch without parameters reads no YAML

        try:
            plain = load_yaml(value) == value and value == value.strip()
        except (yaml.YAMLError, InputError):
            plain = False
        if plain:
            return value
    import json

    return json.dumps(value)  # JSON is YAML: quoted strings, true/false, numbers, lists


def ros_arguments(node: NodeDecl) -> list[str]:
    """The standard ROS arguments that give a node its name, namespace, remaps, params."""
    rules = []
    if node.name:
        rules += ["-r", f"__node:={node.name}"]
    if node.namespace != "/":
        rules += ["-r", f"__ns:={node.namespace}"]
    for source, target in node.remaps:
        rules += ["-r", f"{source}:={target}"]
    for name, value in node.params:
        rules += ["-p", f"{name}:={ros_value(value)}"]
    for path in node.params_files:
        rules += ["--params-file", path]
    rules += node.ros_args
    return ["--ros-args", *rules] if rules else []


def program_path() -> str:
    """The PATH a launched process gets: this environment's commands (ros2, the lessons')
    first, as in an activated venv, even if the launcher was started by its full path."""
    path = os.environ.get("PATH", os.defpath)
    here = os.path.dirname(sys.executable)
    return path if here in path.split(os.pathsep) else here + os.pathsep + path


def _check_program(program: str, where: str) -> None:
    """The program exists and may be run; otherwise say which of the two it is."""
    if shutil.which(program, path=program_path()) is not None:
        return
    if "/" in program:
        candidates = [program]
    else:
        candidates = [os.path.join(d, program) for d in os.get_exec_path() if d]
    for path in candidates:
        if os.path.isdir(path):
            raise LaunchError(f"{where}: program {program!r} is a directory ({path})")
        if os.path.isfile(path):
            raise LaunchError(f"{where}: program {program!r} is not executable ({path})")
    raise LaunchError(f"{where}: program {program!r} not found")


def _process_name(node: NodeDecl, command: list[str]) -> str:
    """What ros2 launch calls the process (then -N): the name given to it, else its program's
    file name (turtlesim_node, ros2; with a launch-prefix, the prefix's program)."""
    if node.label:
        return node.label
    if node.cmd is not None and node.name:  # <executable name=...>
        return node.name
    if node.launch_prefix or node.cmd is not None:
        return os.path.basename(command[0])
    return node.executable or os.path.basename(command[0])


def _label(node: NodeDecl) -> str:
    if node.label:
        return node.label
    if node.name:
        return f"{node.namespace.rstrip('/')}/{node.name}".lstrip("/")
    base = node.executable if node.cmd is None else node.cmd[0].rsplit("/", 1)[-1]
    return f"{node.namespace.rstrip('/')}/{base}".lstrip("/")


# The --ros-args options that take a NAME:=VALUE rule (rcl's arguments.c), and what one is.
_REMAP, _PARAM = "a remap is FROM:=TO", "a parameter is NAME:=VALUE"
_RULE_OPTIONS = {"-r": _REMAP, "--remap": _REMAP, "-p": _PARAM, "--param": _PARAM}


def _check_ros_args(args: list[str], where: str) -> None:
    """A node's args with a rule rcl cannot parse would end the node in rclpy.init's
    traceback: say it here, in one line, before anything starts."""
    in_ros_args = False
    for position, word in enumerate(args):
        if word == "--ros-args":
            in_ros_args = True
        elif word == "--":
            in_ros_args = False
        elif in_ros_args and word in _RULE_OPTIONS:
            rule = args[position + 1] if position + 1 < len(args) else ""
            name, separator, _ = rule.partition(":=")
            if not separator or not name:
                shown = f"{word} {rule}".strip()
                raise LaunchError(
                    f"{where}: args: invalid ROS argument '{shown}': {_RULE_OPTIONS[word]}"
                )


def make_plan(
    launch: Launch,
    screen: bool = False,
    sigterm_timeout: float = DEFAULT_SIGTERM_TIMEOUT,
    sigkill_timeout: float = DEFAULT_SIGKILL_TIMEOUT,
) -> list[ProcessSpec]:
    """Turn a resolved launch into process specs; every lookup error is raised here."""
    specs: list[ProcessSpec] = []
    named: dict[str, str] = {}
    labels: dict[str, int] = {}
    for node in launch.nodes:
        if node.cmd is not None:
            command = node.cmd + node.args
        else:
            command = command_for(node.package or "", node.executable or "", node.where)
            command += node.args + ros_arguments(node)
        command = node.launch_prefix + command
        _check_ros_args(node.args, node.where)
        _check_program(command[0], node.where)
        label = _label(node)
        full_name = None  # the node's own name, whatever its process is called (exec_name)
        if node.name and node.cmd is None:
            full_name = f"{node.namespace.rstrip('/')}/{node.name}"
        if full_name in named:
            raise LaunchError(
                f"{node.where}: a second node named {full_name} "
                f"(the first is at {named[full_name]})"
            )
        if full_name:
            named[full_name] = node.where
        labels[label] = labels.get(label, 0) + 1
        if labels[label] > 1:  # unnamed processes of the same executable
            label = f"{label}-{labels[label]}"
        specs.append(
            ProcessSpec(
                label=label,
                command=command,
                where=node.where,
                process_name=_process_name(node, command),
                node=full_name,
                env=node.env,
                output="screen" if screen else node.output,
                respawn=node.respawn,
                respawn_delay=node.respawn_delay,
                respawn_max_retries=node.respawn_max_retries,
                required=node.required,
                sigterm_timeout=node.sigterm_timeout
                if node.sigterm_timeout is not None
                else sigterm_timeout,
                sigkill_timeout=node.sigkill_timeout
                if node.sigkill_timeout is not None
                else sigkill_timeout,
                cwd=node.cwd,
                remaps=node.remaps,
                params=node.params,
                when=node.when,
                output_format=node.output_format,
            )
        )
    return specs


def format_plan(
    specs: list[ProcessSpec],
    messages: list[str],
    steps: list[Step] | None = None,
    containers: list[ContainerDecl] | None = None,
) -> str:
    """The plan as text, for --print (component containers last: they are not started)."""
    lines = [f"log: {message}" for message in messages]
    labels = [spec.label for spec in specs]
    for step in steps or []:
        what = {"log": f"log: {step.text}", "shutdown": f"shutdown: {step.text}"}
        if step.kind == "call" and step.text in what:  # a log or shutdown made at the event
            what["call"] = f"{step.text}: (its text when the event happens)"
        lines.append(f"{what.get(step.kind, 'call: a function of the launch file')}  "
                     f"({step.when.describe(labels)})")  # fmt: skip
    for spec in specs:
        lines.append(f"[{spec.label}]  ({spec.where})")
        if spec.when != AT_START:
            lines.append(f"    starts:  {spec.when.describe(labels)}")
        if spec.node:
            lines.append(f"    node:    {spec.node}")
        lines.append(f"    command: {shlex.join(spec.command)}")
        for source, target in spec.remaps:
            lines.append(f"    remap:   {source} -> {target}")
        for name, value in spec.params:
            lines.append(f"    param:   {name} = {value!r}")
        for name, value in spec.env.items():
            lines.append(
                f"    env:     {name}={value}" if value is not None else f"    unset:   {name}"
            )
        options = [f"output={spec.output}"]
        if spec.respawn:
            options.append(
                f"respawn (delay {spec.respawn_delay:g} s, max {spec.respawn_max_retries} retries)"
            )
        if spec.required:
            options.append("required (its exit ends the launch)")
        if spec.cwd:
            options.append(f"cwd={spec.cwd}")
        lines.append(f"    options: {', '.join(options)}")
    for container in containers or []:
        if container.package is not None:
            lines.append(f"[container {container.name}]  ({container.where})")
            lines.append(f"    command: {container.package} {container.executable} (not started)")
        else:
            lines.append(f"[load into {container.name}]  ({container.where})")
        for component in container.components:
            name = f"{component.namespace.rstrip('/')}/{component.name or '<default name>'}"
            lines.append(f"    component: {name} = {component.package} {component.plugin}"
                         f"  ({component.where})")  # fmt: skip
            for source, target in component.remaps:
                lines.append(f"        remap:   {source} -> {target}")
            for key, value in component.params:
                lines.append(f"        param:   {key} = {value!r}")
            for key, value in component.extra_args:
                lines.append(f"        extra:   {key} = {value}")
    return "\n".join(lines)
