"""The scope a launch file is read in: one object holding what applies at one point of it
(roslaunch's LoaderContext): its arguments (launch configurations), namespace, remaps,
parameters, environment, and where its actions happen (``when``). A ``<group>`` or an
``<include>`` gets a copy (``child``); the ROS 2 formats' includes share theirs (launcher/
loading.py says why).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launch_foundation.declarations import AT_START, When
from launch_foundation.parse import Element

if TYPE_CHECKING:
    from launcher.loading import Loader


@dataclass
class Options:
    """What the command line decides about resolving."""

    allow_code: bool = False


@dataclass
class Scope:
    """What applies at one point of a launch file; groups and includes get a copy."""

    loader: Loader
    file: Path
    fmt: str  # "ros1" or "ros2"
    args: dict[str, str]
    given: dict[str, str]  # argument values passed in (command line or <include>)
    namespace: str = "/"
    remaps: list[tuple[str, str]] = field(default_factory=list)
    params: list[tuple[str, Any]] = field(default_factory=list)
    params_files: list[str] = field(default_factory=list)  # only inside a ROS 2 <node>
    env: dict[str, str | None] = field(default_factory=dict)
    # The <arg>s declared so far, name -> line: a group gets a copy, as in roslaunch (two
    # sibling groups may each declare one name), an included file none.
    declared: dict[str, int] = field(default_factory=dict)
    when: When = AT_START  # inside a <timer> or an event handler: later
    note: str = ""  # ends an unknown tag or attribute error: why the file was read in this format
    # ROS 1: included with pass_all_args (a fixed <arg value> then wins over the passed one);
    # the arguments declared without a value (an error only where one is used: name -> line);
    # the ~params written outside a <node>, for the nodes after them: (name, value, where).
    pass_all: bool = False
    unset: dict[str, int] = field(default_factory=dict)
    private: list[tuple[str, Any, str]] = field(default_factory=list)
    in_node: bool = False
    # ROS 2 includes are not scoped: the configurations that came in from the including file
    # without being passed, and those an included file let out (name -> where it was set).
    inherited: set[str] = field(default_factory=set)
    leaked: dict[str, str] = field(default_factory=dict)

    def child(self, **changes: Any) -> Scope:
        copies = {"args": dict(self.args), "remaps": list(self.remaps), "params": list(self.params),
                  "params_files": list(self.params_files), "env": dict(self.env),
                  "declared": dict(self.declared), "unset": dict(self.unset),
                  "private": list(self.private), "inherited": set(self.inherited),
                  "leaked": dict(self.leaked)}  # fmt: skip
        return replace(self, **{**copies, **changes})

    def read_arg(self, name: str, element: Element) -> str:
        """The value of argument (launch configuration) ``name`` where ``element`` uses it."""
        if name in self.args:
            self.loader.note_read(self, name, element)
            return self.args[name]
        if name in self.unset:  # roslaunch fails only where such an argument is used
            raise element.error(
                f"argument {name!r} is required (declared at line {self.unset[name]} without "
                f"a value): pass {name}:=<value>"
            )
        known = ", ".join(sorted(self.args)) or "none"
        raise element.error(f"argument {name!r} is not declared here (declared: {known})")

    @property
    def allow_code(self) -> bool:
        return self.loader.options.allow_code

    def anon(self, name: str) -> str:
        return self.loader.anon(name)

    def charge(self, size: int, element: Element) -> None:
        self.loader.charge(size, element.where)
