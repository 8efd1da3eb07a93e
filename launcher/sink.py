"""The launcher's ``PlanSink`` (launch_foundation.declarations): where executing the model's
entities hands its results. It collects the processes, the steps at events, the component
containers and the warnings of one launch, and makes them the ``Launch`` that plan.py plans.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launch_foundation.declarations import AT_START, ContainerDecl, Launch, NodeDecl, Step
from launch_foundation.errors import LaunchError
from launch_foundation.substitutions import MAX_LAUNCH_SUBSTITUTED


def describe_container(container: ContainerDecl) -> str:
    """A container and its components in one phrase (the warning, --print)."""
    what = f"{container.name}" if container.package else f"components for {container.name}"
    names = ", ".join(
        f"{c.namespace.rstrip('/')}/{c.name or '<default>'} ({c.package}::{c.plugin})"
        if "::" not in c.plugin
        else f"{c.namespace.rstrip('/')}/{c.name or '<default>'} ({c.plugin})"
        for c in container.components
    )
    return f"{what} with {names}" if names else f"{what} (no components)"


class LaunchPlan:
    """One launch's results, as the model hands them over (PlanSink). ``include`` reads the
    included file through ``load`` (launcher/loading.py's Loader.include)."""

    def __init__(self, load: Callable[..., None]) -> None:
        self._load = load
        self.nodes: list[NodeDecl] = []
        self.messages: list[str] = []
        self.steps: list[Step] = []
        self.warnings: list[str] = []
        self.containers: list[ContainerDecl] = []
        self.anon_names: dict[str, str] = {}
        self.expanded = 0  # characters substitutions expanded to, in the whole launch

    def warn(self, text: str) -> None:
        """A warning printed before the launch starts (once, however often it is found)."""
        if text not in self.warnings:
            self.warnings.append(text)

    def charge(self, size: int, where: str) -> None:
        """Count what substitutions expanded to; refuse the launch past MAX_LAUNCH_SUBSTITUTED
        (``where``: the file:line that crossed it)."""
        self.expanded += size
        if self.expanded > MAX_LAUNCH_SUBSTITUTED:
            raise LaunchError(
                f"{where}: this launch's substitutions expand to more than "
                f"{MAX_LAUNCH_SUBSTITUTED // (1024 * 1024)} MiB in all; refusing"
            )

    def anon(self, name: str) -> str:
        if name not in self.anon_names:
            self.anon_names[name] = f"{name}_{os.getpid()}_{os.urandom(3).hex()}"
        return self.anon_names[name]

    def include(
        self,
        path: Path,
        given: dict[str, str],
        scope: Any,
        where: str | None = None,
        given_at: dict[str, str] | None = None,
    ) -> None:
        """IncludeLaunchDescription's file (any format), included at ``where``; ``given_at``:
        where each argument was given (a front-end's <arg> lines, checked and named in warnings
        as roslaunch and launch_xml users expect them)."""
        self._load(path, given, scope, given_at is not None, where, given_at)

    def add_container(self, container: ContainerDecl) -> None:
        """Planned and shown, not started (see launch())."""
        self.containers.append(container)

    def add_node(self, node: NodeDecl) -> int:
        """Add a process to the launch; its index is how event handlers name it."""
        self.nodes.append(node)
        return len(self.nodes) - 1

    def add_step(self, step: Step) -> None:
        """A message at the start is printed before anything starts; anything else waits."""
        if step.kind == "log" and step.when == AT_START:
            self.messages.append(step.text)
        else:
            self.steps.append(step)

    def launch(self, warnings: list[str]) -> Launch:
        """The launch as collected, with the front-ends' closing ``warnings``."""
        if self.containers:
            self.warn(
                "component containers need rclcpp_components, which is not on PyPI; not "
                f"started: {'; '.join(describe_container(c) for c in self.containers)}"
            )
        for text in warnings:
            self.warn(text)
        return Launch(self.nodes, self.messages, self.warnings, self.steps, self.containers)


class Recording:
    """A sink that passes everything on to ``sink`` and keeps the processes declared through
    it: a front-end that needs the NodeDecl its action declared (a ROS 1 <node>, whose
    parameters come from the parameter server at the end) runs the action on one."""

    def __init__(self, sink: Any) -> None:
        self.sink = sink
        self.nodes: list[NodeDecl] = []

    def add_node(self, node: NodeDecl) -> int:
        self.nodes.append(node)
        return self.sink.add_node(node)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.sink, name)


def note_unreached(
    unreached: dict[tuple[str, str], list[str]], where: str, why: str, name: str
) -> None:
    """Parameter ``name``, written at ``where``, is given to no node (``why``): one warning for
    each place and reason, naming each parameter once."""
    names = unreached.setdefault((where, why), [])
    if name not in names:
        names.append(name)
