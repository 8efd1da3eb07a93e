"""What a launch file declares, as every front-end hands it on: the processes to run
(``NodeDecl``), the steps that happen later (``Step``, at a ``When``), the arguments a file takes
(``ArgInfo``), and a whole resolved file (``Launch``).

The launcher's front-ends build these: XML and YAML (launcher/loading.py) and Python
(launcher/python_files.py), through the ``launch`` and ``launch_ros`` packages;
launcher/plan.py turns them into process specs and launcher/supervise.py does the steps.
Data only (and ``shown_line``, the one reading of output_format), importing nothing of the
launcher, so every stage can take it from here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import SimpleNamespace
from typing import Any, Protocol

# How many times in a row a respawning process may fail quickly before we give up.
DEFAULT_RESPAWN_MAX_RETRIES = 10
# The longest respawn_delay, sigterm_timeout or sigkill_timeout accepted: one day. Longer is
# a typo (1e308) that would make the launcher wait forever.
MAX_SECONDS = 86400.0


@dataclass(frozen=True)
class When:
    """When a process starts or a step happens: at the launch's start, or on an event of a
    process (its index in ``Launch.nodes``; None: of any process), then after ``delay`` s
    (a timer). Events: "start", "exit" (also OnExecutionComplete), "stdout", "stderr",
    "shutdown"."""

    event: str | None = None
    target: int | None = None
    delay: float = 0.0

    def later(self, seconds: float) -> When:
        return replace(self, delay=self.delay + seconds)

    def describe(self, labels: list[str]) -> str:
        what = {"start": "started", "exit": "exited", "stdout": "printed to stdout",
                "stderr": "printed to stderr"}  # fmt: skip
        if self.event is None:
            text = "at start"
        elif self.event == "shutdown":
            text = "when the launch shuts down"
        else:
            target = "any process" if self.target is None else labels[self.target]
            text = f"when {target} {what.get(self.event, self.event)}"
        return f"{text}, after {self.delay:g} s" if self.delay else text


AT_START = When()


@dataclass
class Step:
    """Something the launch does besides starting a process, at a time ``when`` says: print a
    message ("log"), shut the launch down ("shutdown", with its reason; "error", when an action
    of an event handler failed: ros2 launch's ERROR line, the reason, exit status 1), or call a
    function of a Python launch file with the event ("call"; it returns more steps, done at
    once)."""

    when: When
    kind: str
    text: str = ""
    call: Callable[[dict[str, Any]], list[Step]] | None = None
    where: str = ""


@dataclass
class NodeDecl:
    """One process to run, as the launch file declares it (before packages are looked up)."""

    where: str
    package: str | None = None  # a ROS node: package and executable
    executable: str | None = None
    cmd: list[str] | None = None  # an <executable cmd="...">
    name: str | None = None  # None: the node's own default name
    namespace: str = "/"
    args: list[str] = field(default_factory=list)
    ros_args: list[str] = field(default_factory=list)
    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, Any]] = field(default_factory=list)
    params_files: list[str] = field(default_factory=list)
    env: dict[str, str | None] = field(default_factory=dict)  # None: unset
    output: str = "log"
    respawn: bool = False
    respawn_delay: float = 0.0
    respawn_max_retries: int = DEFAULT_RESPAWN_MAX_RETRIES
    required: bool = False
    sigterm_timeout: float | None = None
    sigkill_timeout: float | None = None
    launch_prefix: list[str] = field(default_factory=list)
    cwd: str | None = None
    when: When = AT_START
    label: str | None = None  # the output prefix, if not the node's name (ExecuteProcess name=)
    # ExecuteProcess(output_format=...): how each line is shown, str.format with ``line`` and
    # ``this`` (this.process_description.final_name); None: "[name] line"
    output_format: str | None = None


@dataclass
class ComponentDecl:
    """A composable node (launch_ros ComposableNode, <composable_node>): a plugin of a package,
    loaded into a component container."""

    where: str
    package: str
    plugin: str
    name: str | None = None  # None: the component's default name
    namespace: str = "/"
    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, Any]] = field(default_factory=list)
    extra_args: list[tuple[str, str]] = field(default_factory=list)


@dataclass
class ContainerDecl:
    """A component container and the components it loads (<node_container>,
    ComposableNodeContainer), or components loaded into one named by ``target``
    (<load_composable_node>, LoadComposableNodes)."""

    where: str
    name: str  # the container's full node name (or the target's, as written)
    package: str | None = None  # None: components for a container started elsewhere
    executable: str | None = None
    components: list[ComponentDecl] = field(default_factory=list)


@dataclass
class Launch:
    """A resolved launch file: the processes to run, the <log> messages to print at the start,
    and the steps that happen later (timers, event handlers)."""

    nodes: list[NodeDecl]
    messages: list[str]
    warnings: list[str] = field(default_factory=list)  # file:line: what reaches no node
    steps: list[Step] = field(default_factory=list)
    containers: list[ContainerDecl] = field(default_factory=list)  # planned, not started


@dataclass
class ArgInfo:
    name: str
    default: str | None
    description: str
    choices: list[str]
    fixed: bool  # ROS 1 <arg value=...>: cannot be set from outside
    where: str
    fmt: str = "ros2"


class PlanSink(Protocol):
    """The one thing the launch model (``launch``, ``launch_ros``) knows of the launcher: where
    executing an entity hands its result. The launcher's LaunchPlan (launcher/sink.py) is one.

    - ``add_node``: a process to run (ExecuteProcess, Node); returns its index, by which an
      event handler's ``When`` names it.
    - ``add_step``: a message, a shutdown, or a call of the launch file's code at an event
      (lazy: its substitutions are performed when the supervisor reports the event).
    - ``warn``: one line printed before the launch starts.
    - ``include``: read another launch file (any format) with the ``given`` arguments, in
      ``scope`` (the including context's, opaque to the model), included at file:line
      ``where``; ``given_at``: where a front-end wrote each argument (checked, and named in
      warnings), None from a Python file.
    - ``add_container``: a component container or components to load (planned and shown;
      not started: rclcpp_components is not on PyPI).
    """

    def add_node(self, node: NodeDecl) -> int: ...

    def add_step(self, step: Step) -> None: ...

    def warn(self, text: str) -> None: ...

    def include(
        self,
        path: Path,
        given: dict[str, str],
        scope: Any,
        where: str | None = None,
        given_at: dict[str, str] | None = None,
    ) -> None: ...

    def add_container(self, container: ContainerDecl) -> None: ...


def shown_line(output_format: str | None, name: str, line: str) -> str:
    """A line of a process's output as the screen shows it: ``[name] line``, or as its
    ExecuteProcess's output_format says (str.format, as ros2 launch formats it; checked when
    the launch was planned)."""
    if output_format is None:
        return f"[{name}] {line}"
    this = SimpleNamespace(process_description=SimpleNamespace(final_name=name, name=name))
    return output_format.format(line=line, this=this)
