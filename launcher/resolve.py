"""Resolve a launch file: arguments, conditions, substitutions and scopes -> node declarations.

Both formats are read here, each detected per file. What differs is the set of tags and
attributes (each handler's ``@tag`` lines: the one place a tag is defined) and parameters:
- ROS 1 ``<param>`` writes to a parameter server, as roslaunch does: names are relative to the
  namespace of their group, the last value written wins, wherever it is written. At the end
  each node receives the parameters of its namespace and of the enclosing ones (the nearest
  wins) plus its private ones (``~name``, or written inside ``<node>``).
- ROS 2 ``<set_parameter>`` applies to the nodes after it in its scope, like ros2 launch.

Every ``<group>`` and every ``<include>`` is a scope: arguments, remaps, parameters,
environment and namespace set inside do not leak out (also in the ROS 2 format, where ros2
launch leaks included arguments). An included file sees only the arguments passed to it.
"""

from __future__ import annotations

import math
import os
import re
import shlex
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import yaml

from launcher import LaunchError
from launcher.parse import YAML_SUFFIXES, Element, parse_file
from launcher.substitutions import substitute, to_bool
from ros_tutorials_common.bounded import (
    InputError,
    load_yaml,
    parameter_problem,
    parameters_problem,
    read_params_file,
    read_text,
)
from ros_tutorials_common.names import TOKEN, valid_remap_name

_TOKEN = re.compile(TOKEN)

# How many times in a row a respawning process may fail quickly before we give up.
DEFAULT_RESPAWN_MAX_RETRIES = 10
# The longest respawn_delay, sigterm_timeout or sigkill_timeout accepted: one day. Longer is
# a typo (1e308) that would make the launcher wait forever.
MAX_SECONDS = 86400.0
# Groups and includes nested deeper than this are refused (a recursion, not a real file).
MAX_DEPTH = 50

CONDITIONS = {"if", "unless"}
PROCESS_ATTRS = {"args", "output", "respawn", "respawn_delay", "respawn_max_retries",
                 "sigterm_timeout", "sigkill_timeout", "launch_prefix", "on_exit"}  # fmt: skip
SYNTAX = {"ros1": "ROS 1 (roslaunch)", "ros2": "ROS 2"}
# Attributes kept with _ inside (parse.py) that both formats document with - (both accepted).
SPELLING = {"launch_prefix": "launch-prefix"}


@dataclass(frozen=True)
class Tag:
    """One tag of one format: its handler, its attributes and the parents it may appear in."""

    handler: Callable[[Resolver, Element, Scope], None]
    attrs: frozenset[str]
    under: frozenset[str]  # "launch" (the file's top level and <group>), "node", "executable"
    marks: frozenset[str]  # attributes that show a file is in this format (type= on <node>)


# Every tag of each format, filled by @tag on the Resolver's handlers. The allowed tags and
# attributes and the format detection are all read from here: adding a tag is one handler.
TAGS: dict[str, dict[str, Tag]] = {"ros1": {}, "ros2": {}}


def tag(
    fmt: str,
    name: str,
    attrs: Iterable[str],
    under: Iterable[str] = ("launch",),
    marks: Iterable[str] = (),
) -> Callable:
    """Register a Resolver method as the handler of <name> in ``fmt`` (ros2/launch's
    @expose_action). A tag only one format has also tells the format of the file it is in."""

    def register(handler: Callable) -> Callable:
        TAGS[fmt][name] = Tag(handler, frozenset(attrs), frozenset(under), frozenset(marks))
        return handler

    return register


def allowed_tags(fmt: str, parent: str) -> dict[str, frozenset[str]]:
    """The tags ``fmt`` allows under ``parent`` ("launch", "node", "executable"), and their
    attributes."""
    return {name: known.attrs for name, known in TAGS[fmt].items() if parent in known.under}


@dataclass
class Options:
    """What the command line decides about resolving."""

    allow_code: bool = False


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
    message ("log"), shut the launch down ("shutdown", with its reason), or call a function of
    a Python launch file with the event ("call"; it returns more steps, done at once)."""

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


@dataclass
class Launch:
    """A resolved launch file: the processes to run, the <log> messages to print at the start,
    and the steps that happen later (timers, event handlers)."""

    nodes: list[NodeDecl]
    messages: list[str]
    warnings: list[str] = field(default_factory=list)  # file:line: what reaches no node
    steps: list[Step] = field(default_factory=list)


@dataclass
class ArgInfo:
    name: str
    default: str | None
    description: str
    choices: list[str]
    fixed: bool  # ROS 1 <arg value=...>: cannot be set from outside
    where: str
    fmt: str = "ros2"


@dataclass
class Scope:
    """What applies at one point of a launch file; groups and includes get a copy."""

    resolver: Resolver
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

    def child(self, **changes: Any) -> Scope:
        copies = {"args": dict(self.args), "remaps": list(self.remaps), "params": list(self.params),
                  "params_files": list(self.params_files), "env": dict(self.env),
                  "declared": dict(self.declared)}  # fmt: skip
        return replace(self, **{**copies, **changes})

    @property
    def allow_code(self) -> bool:
        return self.resolver.options.allow_code

    def anon(self, name: str) -> str:
        return self.resolver.anon(name)


def join_namespace(base: str, name: str) -> str:
    """Namespace ``name`` relative to ``base`` (absolute if it starts with /)."""
    full = name if name.startswith("/") else f"{base.rstrip('/')}/{name}"
    return "/" + "/".join(part for part in full.split("/") if part)


def remap_problem(name: str, side: str) -> str | None:
    """Why rcl would refuse ``name`` as the ``side`` ("from" or "to") of a remap; else None."""
    if valid_remap_name(name, side):
        return None
    return (
        f"remap {side}={name!r} is not a valid ROS name (parts of letters, digits and _, "
        "not starting with a digit, separated by one /; ~/ only at the start)"
    )


def valid_name(name: str) -> bool:
    """One part of a ROS name: ASCII letters, digits and _, not starting with a digit (rcl
    refuses 'pé' and 'nsü', which str.isalnum takes)."""
    return _TOKEN.fullmatch(name) is not None


def _written_in(fmt: str, element: Element) -> bool:
    """Whether ``element`` uses syntax only ``fmt`` has: a tag or a marking attribute."""
    known = TAGS[fmt].get(element.tag)
    if known is None:
        return False
    return element.tag not in TAGS["ros2" if fmt == "ros1" else "ros1"] or bool(
        known.marks & element.attrs.keys()
    )


def detect_format(root: Element) -> str:
    """ "ros1" or "ros2", from the syntax used in the file (else from its name)."""
    first: dict[str, Element | None] = {"ros1": None, "ros2": None}  # the first in its syntax
    stack = [root]
    while stack:
        element = stack.pop()
        stack.extend(element.children)
        for fmt, found in first.items():
            if found is None and _written_in(fmt, element):
                first[fmt] = element
    if root.file.suffix in YAML_SUFFIXES:  # launch_yaml is a ROS 2 front-end only
        return "ros2"
    ros1, ros2 = first["ros1"], first["ros2"]
    if ros1 and ros2:
        raise LaunchError(
            f"{root.file}: mixes ROS 1 syntax (line {ros1.line}: <{ros1.tag}>) "
            f"and ROS 2 syntax (line {ros2.line}: <{ros2.tag}>)"
        )
    if ros1 or ros2:
        return "ros1" if ros1 else "ros2"
    return "ros1" if root.file.name.endswith(".launch") else "ros2"


def _check(element: Element, allowed: set[str] | frozenset[str]) -> None:
    for name in element.attrs:
        if name not in allowed | CONDITIONS:
            known = ", ".join(sorted(SPELLING.get(a, a) for a in allowed | CONDITIONS))
            written = element.spelled.get(name, name)  # as the file wrote it
            raise element.error(
                f"unknown attribute {written!r} on <{element.tag}>; allowed: {known}"
            )
    if "if" in element.attrs and "unless" in element.attrs:
        raise element.error("use either 'if' or 'unless', not both")


def _check_tag(element: Element, allowed: dict, fmt: str, parent: str) -> None:
    """``element`` is one of the ``allowed`` tags (tag -> attributes) under ``parent``."""
    if fmt == "ros2" and element.tag in ("node_container", "load_composable_node"):
        raise element.error(
            f"<{element.tag}>: rclpy has no component container in ROS 2 Jazzy, so composable "
            "nodes cannot be loaded here; start each component as a <node> of its own"
        )
    if element.tag not in allowed:
        known = ", ".join(f"<{name}>" for name in sorted(allowed))
        raise element.error(
            f"unknown tag <{element.tag}> in <{parent}> ({SYNTAX[fmt]} format); allowed: {known}"
        )
    _check(element, allowed[element.tag])


def _file_args(root: Element) -> list[Element]:
    """The <arg> declarations of a file, wherever they are (but not inside <include>)."""
    found, stack = [], list(reversed(root.children))
    while stack:
        element = stack.pop()
        if element.tag == "arg":
            found.append(element)
        elif element.tag != "include":
            stack.extend(reversed(element.children))
    return found


def describe_args(path: Path) -> list[ArgInfo]:
    """The arguments a launch file declares, for --show-args (nothing is resolved)."""
    if path.name.endswith(".py"):
        from launcher.python_files import describe_python_args

        return describe_python_args(path)
    root = parse_file(path)
    fmt = detect_format(root)
    infos = []
    for element in _file_args(root):
        attrs = element.attrs
        if "name" not in attrs:
            raise element.error("<arg> needs a 'name'")
        choices = [child.attrs.get("value", "") for child in element.children]
        fixed = fmt == "ros1" and "value" in attrs
        description = attrs.get("doc" if fmt == "ros1" else "description", "")
        default = attrs.get("value") if fixed else attrs.get("default")
        infos.append(
            ArgInfo(attrs["name"], default, description, choices, fixed, element.where, fmt)
        )
    return infos


def _add_once(names: list[str], name: str) -> None:
    if name not in names:
        names.append(name)


def _typed_value(text: str, kind: str | None, element: Element) -> Any:
    """A parameter value from its text, typed as roslaunch and ros2 launch do."""
    name = element.attrs.get("name", "")
    try:
        if kind in ("str", "string"):
            return text
        if kind == "int":
            return int(text)
        if kind == "double":
            return float(text)
        if kind in ("bool", "boolean"):
            return to_bool(text, element, "")
    except (ValueError, LaunchError):  # int('abc'), float('fast'), to_bool('yes please')
        what = {"int": "an int", "double": "a double"}.get(kind, "a bool (true, false, 1 or 0)")
        raise element.error(f"param {name!r}: {text!r} is not {what}") from None
    if kind == "yaml":
        return _load_yaml(text, element)  # its own error: what is wrong with the YAML
    if kind is not None:
        raise element.error(f"unknown parameter type {kind!r}; use str, int, double, bool, yaml")
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    if text.strip().lower() in ("true", "false"):
        return text.strip().lower() == "true"
    return text


def _ros2_value(text: str) -> Any:
    """A ROS 2 <param value>, typed as launch_ros types it: read as YAML (``[2, 5, 8]`` is a
    list, ``2.5`` a double, ``true`` a bool), text where YAML gives no single value."""
    try:
        value = load_yaml(text, "the parameter value")
    except (yaml.YAMLError, InputError):
        return text
    return text if value is None or isinstance(value, dict) else value


def _load_yaml(text: str, element: Element) -> Any:
    """YAML written in (or read by) a launch file, within the limits of bounded.load_yaml."""
    try:
        return load_yaml(text, "the YAML")
    except InputError as error:
        raise element.error(str(error)) from None
    except yaml.YAMLError as error:
        raise element.error(f"invalid YAML: {' '.join(str(error).split())}") from None


def _check_params(element: Element, mapping: dict | None, name: str, value: Any) -> None:
    """Refuse, at file:line, what no ROS parameter can hold (a date, an int above int64...)."""
    problem = parameters_problem(mapping) if mapping is not None else None
    problem = problem or (None if mapping is not None else parameter_problem(name, value))
    if problem:
        raise element.error(problem)


def _check_params_file(element: Element, path: Path) -> None:
    """A ROS 2 params file, checked before anything starts: the child would fail on it later."""
    try:
        read_params_file(path)
    except InputError as error:
        raise element.error(str(error)) from None


def _flatten(prefix: str, value: Any) -> list[tuple[str, Any]]:
    """A YAML mapping as (name, value) pairs with /-separated names."""
    if not isinstance(value, dict):
        return [(prefix, value)]
    pairs = []
    for key, item in value.items():
        pairs += _flatten(f"{prefix.rstrip('/')}/{key}", item)
    return pairs


class Resolver:
    """Walks launch files and collects node declarations. One per launch."""

    def __init__(self, options: Options) -> None:
        self.options = options
        self.nodes: list[NodeDecl] = []
        self.messages: list[str] = []
        self.steps: list[Step] = []
        self.warnings: list[str] = []
        # The Python front-end: actions executed, the index of each process action (what an
        # event handler's target_action names), handlers waiting for their target, and the
        # launch configurations read (an argument read but not declared is not a typo).
        self.executed: dict[int, Any] = {}
        self.process_index: dict[int, int] = {}
        self.deferred_handlers: list[tuple[Any, Any]] = []
        self.configurations_read: set[str] = set()
        self.anon_names: dict[str, str] = {}
        self.include_chain: list[Path] = []
        self.depth = 0  # nested groups and includes
        # ROS 1: the parameter server roslaunch would fill, full name -> value, and the
        # nodes whose parameters come from it once every file is read.
        self.param_server: dict[str, Any] = {}
        self.param_origin: dict[str, tuple[str, str]] = {}  # key -> (name as written, where)
        self.ros1_nodes: list[NodeDecl] = []
        # ROS 2: each <set_parameter>'s entry, to tell whether a node after it received it.
        self.set_parameters: list[tuple[tuple[str, Any], str]] = []

    def anon(self, name: str) -> str:
        if name not in self.anon_names:
            self.anon_names[name] = f"{name}_{os.getpid()}_{os.urandom(3).hex()}"
        return self.anon_names[name]

    # -- files and scopes ---------------------------------------------------------------------

    def resolve_file(
        self,
        path: Path,
        given: dict[str, str],
        parent: Scope | None,
        strict: bool = True,
        include: Element | None = None,
        given_at: dict[str, Element] | None = None,
    ) -> None:
        path = path.resolve()
        if path in self.include_chain:
            chain = " -> ".join(str(p) for p in [*self.include_chain, path])
            message = f"launch files include each other in a loop: {chain}"
            raise include.error(message) if include else LaunchError(message)
        if path.name.endswith(".py"):  # the Python front-end (launch and launch_ros)
            from launcher.python_files import resolve_python_file

            if parent is None:
                scope = Scope(self, path, "ros2", {}, given)
            else:
                scope = parent.child(file=path, fmt="ros2", args={}, given=given, declared={})
            self.include_chain.append(path)
            self.depth += 1
            try:
                if self.depth > MAX_DEPTH:
                    raise LaunchError(f"{path}: includes nested more than {MAX_DEPTH} deep")
                resolve_python_file(path, scope, strict=strict and parent is None)
            finally:
                self.depth -= 1
                self.include_chain.pop()
            return
        root = parse_file(path)
        _check(root, {"deprecated"})
        if "deprecated" in root.attrs:  # ros2 launch prints the file's own deprecation message
            self.warnings.append(
                f"{root.where}: {path.name} is deprecated: {root.attrs['deprecated']}"
            )
        fmt = detect_format(root)
        declared = {element.attrs.get("name") for element in _file_args(root)}
        unknown = sorted(set(given) - declared) if strict else []
        if unknown:
            names = ", ".join(sorted(n for n in declared if n)) or "none"
            if given_at and unknown[0] in given_at:  # an <include>'s <arg>: name its line
                raise given_at[unknown[0]].error(
                    f"no argument named {', '.join(unknown)} is declared in {path.name} "
                    f"(declared: {names})"
                )
            raise LaunchError(
                f"{path}: no argument named {', '.join(unknown)} is declared (declared: {names})"
            )
        if parent is None:
            scope = Scope(self, path, fmt, {}, given)
        else:
            scope = parent.child(file=path, fmt=fmt, args={}, given=given, declared={})
        self.include_chain.append(path)
        self.resolve_scope(root, scope)
        self.include_chain.pop()

    def resolve_scope(self, element: Element, scope: Scope) -> None:
        """The children of <launch> or <group>, one level deeper (a recursion is refused)."""
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise element.error(f"groups and includes nested more than {MAX_DEPTH} deep")
            self.resolve_children(element, scope, "launch")
        finally:
            self.depth -= 1

    def resolve_children(self, element: Element, scope: Scope, parent: str) -> None:
        """Each enabled child of ``element``, by the handler its format registered for its tag."""
        allowed = allowed_tags(scope.fmt, parent)
        for child in element.children:
            _check_tag(child, allowed, scope.fmt, element.tag)
            if self.enabled(child, scope):
                TAGS[scope.fmt][child.tag].handler(self, child, scope)

    def finish(self) -> Launch:
        reached: set[str] = set()
        for node in self.ros1_nodes:
            node.params = self._ros1_params(node, reached) + node.params
        # A parameter no node receives would be dropped without a word (ROS 1 kept every one
        # on its parameter server): one warning for each place that wrote such parameters.
        unreached: dict[tuple[str, str], list[str]] = {}  # (where, why) -> names
        for key, (name, where) in self.param_origin.items():
            if key not in reached:
                why = "ROS 2 has no parameter server; put it inside a <node>"
                _add_once(unreached.setdefault((where, why), []), name)
        for entry, where in self.set_parameters:
            if not any(param is entry for node in self.nodes for param in node.params):
                why = "no <node> follows it in its scope"
                _add_once(unreached.setdefault((where, why), []), entry[0])
        warnings = [
            f"{where}: param {', '.join(map(repr, names))} "
            f"{'is' if len(names) == 1 else 'are'} given to no node: {why}"
            for (where, why), names in unreached.items()
        ]
        return Launch(self.nodes, self.messages, self.warnings + warnings, self.steps)

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

    # -- attribute helpers --------------------------------------------------------------------

    def text(self, element: Element, name: str, scope: Scope, default: str | None = None) -> str:
        if name in element.attrs:
            return substitute(element.attrs[name], scope, element)
        if default is None:
            raise element.error(f"<{element.tag}> needs a {name!r} attribute")
        return default

    def words(self, element: Element, name: str, scope: Scope) -> list[str]:
        """An attribute split into words as a shell would (args, cmd, launch-prefix)."""
        text = self.text(element, name, scope, "")
        try:
            return shlex.split(text)
        except ValueError as error:  # No closing quotation
            raise element.error(f"{name.replace('_', '-')}={text!r}: {error}") from None

    def env_name(self, element: Element, scope: Scope) -> str:
        name = self.text(element, "name", scope)
        if not name or "=" in name or "\0" in name:
            raise element.error(f"invalid environment variable name {name!r}")
        return name

    def flag(self, element: Element, name: str, scope: Scope) -> bool:
        return to_bool(self.text(element, name, scope, "false"), element, f"{name!r}")

    def number(self, element: Element, name: str, scope: Scope, kind: type = float) -> Any:
        text = self.text(element, name, scope, "")
        if not text:
            return None
        try:
            value = kind(text)
        except ValueError:
            value = None
        # nan and inf would make the supervisor's deadlines unreachable: refuse them too.
        bad = value is None or not math.isfinite(value) or value < 0
        if bad and not (kind is int and value == -1):
            raise element.error(f"{name!r} must be a non-negative number, not {text!r}")
        if kind is float and value > MAX_SECONDS:
            raise element.error(f"{name!r} is {text} s; at most {MAX_SECONDS:.0f} s (a day)")
        return value

    def enabled(self, element: Element, scope: Scope) -> bool:
        if "if" in element.attrs:
            return to_bool(self.text(element, "if", scope), element, "'if'")
        if "unless" in element.attrs:
            return not to_bool(self.text(element, "unless", scope), element, "'unless'")
        return True

    def namespace(self, element: Element, name: str, scope: Scope) -> str:
        value = self.text(element, name, scope)
        full = join_namespace(scope.namespace, value)
        parts = value.strip("/").split("/")  # "a//b" has an empty part: a typo, refused
        bad_part = value.strip("/") and not all(valid_name(part) for part in parts)
        if bad_part or (full != "/" and not all(valid_name(p) for p in full[1:].split("/"))):
            raise element.error(f"invalid namespace {value!r}")
        return full

    # -- tags: arguments, scopes, includes ----------------------------------------------------

    @tag("ros1", "arg", {"name", "default", "value", "doc"})
    @tag("ros2", "arg", {"name", "default", "description"})
    def on_arg(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope)
        fixed = "value" in element.attrs  # ROS 1: a constant, not an argument
        if scope.fmt == "ros1" and name in scope.declared:
            raise element.error(
                f"argument {name!r} is declared twice (first at line {scope.declared[name]}); "
                "roslaunch refuses that too"
            )
        scope.declared[name] = element.line
        for child in element.children:
            _check_tag(child, {"choice": {"value"}}, scope.fmt, "arg")
        if fixed and name in scope.given:
            raise element.error(f"argument {name!r} has a fixed value and cannot be set")
        if name in scope.given:
            value = scope.given[name]
        elif fixed:
            value = self.text(element, "value", scope)
        elif "default" in element.attrs:
            value = self.text(element, "default", scope)
        else:
            raise element.error(f"argument {name!r} is required: pass {name}:=<value>")
        choices = [self.text(child, "value", scope) for child in element.children]
        if choices and value not in choices:
            raise element.error(f"argument {name!r} is {value!r}; choose one of {choices}")
        scope.args[name] = value

    @tag("ros2", "let", {"name", "value"})
    def on_let(self, element: Element, scope: Scope) -> None:
        scope.args[self.text(element, "name", scope)] = self.text(element, "value", scope)

    @tag("ros1", "group", {"ns"}, marks={"ns"})
    def on_ros1_group(self, element: Element, scope: Scope) -> None:
        ns = self.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
        self.resolve_scope(element, scope.child(namespace=ns))

    @tag("ros2", "group", {"scoped"})
    def on_ros2_group(self, element: Element, scope: Scope) -> None:
        scoped = self.flag(element, "scoped", scope) or "scoped" not in element.attrs
        self.resolve_scope(element, scope.child() if scoped else scope)

    @tag("ros2", "push_ros_namespace", {"namespace"})
    def on_push_ros_namespace(self, element: Element, scope: Scope) -> None:
        scope.namespace = self.namespace(element, "namespace", scope)

    @tag("ros1", "include", {"file", "ns", "pass_all_args"})
    @tag("ros2", "include", {"file"})
    def on_include(self, element: Element, scope: Scope) -> None:
        path = Path(self.text(element, "file", scope))
        if not path.is_absolute():  # relative to the including file, not the current directory
            path = scope.file.parent / path
        pass_all = scope.fmt == "ros1" and self.flag(element, "pass_all_args", scope)
        given = dict(scope.args) if pass_all else {}
        given_at = {}
        for child in element.children:
            _check_tag(child, {"arg": {"name", "value"}}, scope.fmt, "include")
            if self.enabled(child, scope):
                name = self.text(child, "name", scope)
                given[name] = self.text(child, "value", scope)
                given_at.setdefault(name, child)
        ns = self.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
        if not path.is_file():
            raise element.error(f"included file {path} does not exist")
        self.resolve_file(path, given, scope.child(namespace=ns), not pass_all, element, given_at)

    @tag("ros2", "log", {"message", "level"})
    def on_log(self, element: Element, scope: Scope) -> None:
        text = self.text(element, "message", scope)
        self.add_step(Step(scope.when, "log", text, where=element.where))

    @tag("ros2", "timer", {"period"})
    def on_timer(self, element: Element, scope: Scope) -> None:
        """<timer period="S">: its children happen S seconds after the timer itself."""
        period = self.number(element, "period", scope)
        if period is None:
            raise element.error("<timer> needs a 'period' in seconds")
        self.resolve_scope(element, scope.child(when=scope.when.later(period)))

    # -- tags: what applies to nodes, in a scope or inside one <node> --------------------------

    @tag("ros1", "remap", {"from", "to"}, under={"launch", "node"})
    @tag("ros2", "set_remap", {"from", "to"})
    @tag("ros2", "remap", {"from", "to"}, under={"node"})
    def on_remap(self, element: Element, scope: Scope) -> None:
        names = []
        for side in ("from", "to"):
            written = name = self.text(element, side, scope)
            if scope.fmt == "ros1" and name.startswith("~") and not name.startswith("~/"):
                name = "~/" + name[1:]  # ROS 1's private ~name is ~/name in ROS 2
            if remap_problem(name, side):
                raise element.error(remap_problem(written, side) or "")
            names.append(name)
        scope.remaps.append((names[0], names[1]))

    @tag("ros1", "env", {"name", "value"}, under={"launch", "node"})
    @tag("ros2", "set_env", {"name", "value"})
    @tag("ros2", "env", {"name", "value"}, under={"node", "executable"})
    def on_env(self, element: Element, scope: Scope) -> None:
        scope.env[self.env_name(element, scope)] = self.text(element, "value", scope)

    @tag("ros2", "append_env", {"name", "value", "prepend", "separator"})
    def on_append_env(self, element: Element, scope: Scope) -> None:
        """Add to a variable of the environment the launch started with (or set before)."""
        name = self.env_name(element, scope)
        value = self.text(element, "value", scope)
        prepend = self.text(element, "prepend", scope, "false").strip().lower()
        if prepend not in ("true", "false", "1", "0", "yes", "no"):
            raise element.error(f"'prepend' must be true or false, not {prepend!r}")
        separator = self.text(element, "separator", scope, os.pathsep)
        old = scope.env[name] if name in scope.env else os.environ.get(name)
        if old:
            first, last = (value, old) if prepend in ("true", "1", "yes") else (old, value)
            value = first + separator + last
        scope.env[name] = value

    @tag("ros2", "reset", set())
    def on_reset(self, element: Element, scope: Scope) -> None:
        """Forget every launch configuration but the <keep>s (values read before forgetting)."""
        kept = {}
        for child in element.children:
            _check_tag(child, {"keep": {"name", "value"}}, scope.fmt, "reset")
            kept[self.text(child, "name", scope)] = self.text(child, "value", scope)
        scope.args.clear()
        scope.args.update(kept)

    @tag("ros2", "unset_env", {"name"})
    def on_unset_env(self, element: Element, scope: Scope) -> None:
        scope.env[self.env_name(element, scope)] = None

    @tag("ros2", "set_parameter", {"name", "value"})
    @tag("ros2", "param", {"name", "value", "from"}, under={"node"})
    def on_ros2_param(self, element: Element, scope: Scope) -> None:
        if "from" in element.attrs:  # a params file, checked now: the child would fail on it later
            path = Path(self.text(element, "from", scope))
            path = path if path.is_absolute() else scope.file.parent / path
            _check_params_file(element, path)
            scope.params_files.append(str(path))
            return
        value = _ros2_value(self.text(element, "value", scope))
        name = self.text(element, "name", scope)
        _check_params(element, None, name, value)
        entry = (name, value)
        scope.params.append(entry)
        if element.tag == "set_parameter":
            self.set_parameters.append((entry, element.where))

    # ROS 1 parameters go to the parameter server, under the namespace of their scope (inside
    # <node>: the node's private namespace).

    @tag("ros1", "param", {"name", "value", "type"}, under={"launch", "node"})
    def on_ros1_param(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope)
        if name.startswith("~"):
            name = name[1:]  # private: inside <node> the namespace is already the node's
        value = _typed_value(self.text(element, "value", scope), element.attrs.get("type"), element)
        _check_params(element, {name: value} if isinstance(value, dict) else None, name, value)
        for key, item in _flatten(join_namespace(scope.namespace, name), value):
            self.param_server[key] = item
            self.param_origin[key] = (name, element.where)

    @tag("ros1", "rosparam", {"command", "file", "param", "ns", "subst_value"}, {"launch", "node"})
    def on_rosparam(self, element: Element, scope: Scope) -> None:
        command = self.text(element, "command", scope, "load")
        if command != "load":
            raise element.error(f"<rosparam command={command!r}> is not supported; only 'load'")
        if "file" in element.attrs:
            path = Path(self.text(element, "file", scope))
            try:  # at most 1 MiB of UTF-8
                text = read_text(path if path.is_absolute() else scope.file.parent / path)
            except InputError as error:
                raise element.error(str(error)) from None
        else:
            text = element.text
        if self.flag(element, "subst_value", scope):
            text = substitute(text, scope, element)
        value = _load_yaml(text, element)
        _check_params(element, value if isinstance(value, dict) else None, "", value)
        namespace = scope.namespace
        if "ns" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "ns", scope))
        if "param" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "param", scope))
        elif not isinstance(value, dict):
            raise element.error("<rosparam> without 'param' must hold a YAML mapping")
        for key, item in _flatten(namespace, value):
            self.param_server[key] = item
            self.param_origin[key] = (key, element.where)

    def _ros1_params(self, node: NodeDecl, reached: set[str]) -> list[tuple[str, Any]]:
        """A ROS 1 node's parameters from the parameter server (see the module docstring);
        adds the keys it receives to ``reached``."""
        parts = node.namespace.strip("/").split("/") if node.namespace != "/" else []
        namespaces = ["/" + "/".join(parts[:depth]) for depth in range(len(parts) + 1)]
        private = f"{node.namespace.rstrip('/')}/{node.name}/"
        params: dict[str, Any] = {}
        for namespace in namespaces:  # the nearest namespace is last, so it wins
            prefix = namespace.rstrip("/") + "/"
            for key, value in self.param_server.items():
                rest = key[len(prefix) :]
                if key.startswith(prefix) and "/" not in rest:
                    params[rest] = value
                    reached.add(key)
        for key, value in self.param_server.items():
            if key.startswith(private):
                params[key[len(private) :].replace("/", ".")] = value
                reached.add(key)
        return list(params.items())

    # -- tags: processes ----------------------------------------------------------------------

    @tag("ros1", "node", {"pkg", "type", "name", "ns", "args", "output", "respawn", "respawn_delay",
                          "required", "launch_prefix"}, marks={"type"})  # fmt: skip
    @tag("ros2", "node", {"pkg", "exec", "name", "namespace", "ros_args"} | PROCESS_ATTRS,
         marks={"exec"})  # fmt: skip
    @tag("ros2", "executable", {"cmd", "name", "cwd"} | PROCESS_ATTRS)
    def on_process(self, element: Element, scope: Scope) -> None:
        """<node> (both formats) and <executable>: the one place a NodeDecl is filled.

        Each attribute is read the same way for every tag: one the tag does not allow was
        refused already (its @tag attributes), so here it reads as its default.
        """
        ros1 = scope.fmt == "ros1"
        package = executable = cmd = name = None
        if element.tag == "executable":
            cmd = self.words(element, "cmd", scope)
            if not cmd:
                raise element.error("<executable> needs a non-empty 'cmd'")
            name = self.text(element, "name", scope, "") or None
        else:
            package = self.text(element, "pkg", scope)
            executable = self.text(element, "type" if ros1 else "exec", scope)
            if ros1 or "name" in element.attrs:  # a ROS 1 node must be named
                name = self.text(element, "name", scope)
                if not valid_name(name):
                    raise element.error(f"invalid node name {name!r}")
        ns_attr = "ns" if ros1 else "namespace"
        namespace = scope.namespace
        if ns_attr in element.attrs:
            namespace = self.namespace(element, ns_attr, scope)
        cwd = self.text(element, "cwd", scope, "") or None
        args = self.words(element, "args", scope)
        output = self.text(element, "output", scope, "log")
        outputs = ("screen", "log") if ros1 else ("screen", "log", "both")
        if output not in outputs:
            raise element.error(f"output={output!r}; use one of {', '.join(outputs)}")
        respawn = self.flag(element, "respawn", scope)
        respawn_delay = self.number(element, "respawn_delay", scope) or 0.0
        retries = self.number(element, "respawn_max_retries", scope, int)
        launch_prefix = self.words(element, "launch_prefix", scope)
        ros_args = self.words(element, "ros_args", scope)
        on_exit = self.text(element, "on_exit", scope, "")
        if on_exit not in ("", "shutdown"):
            raise element.error(f"on_exit={on_exit!r} is not supported; use 'shutdown'")
        required = self.flag(element, "required", scope) or on_exit == "shutdown"
        if required and respawn:
            raise element.error(
                "a node cannot be both respawn and required"
                if ros1
                else "a process cannot both respawn and shut the launch down on exit"
            )
        sigterm_timeout = self.number(element, "sigterm_timeout", scope)
        sigkill_timeout = self.number(element, "sigkill_timeout", scope)
        # The children (<param>, <remap>, <env>) apply to a scope of the node's own, as anywhere
        # else. In ROS 1 its namespace is the node's private one, where its <param>s go, and its
        # parameters come from the parameter server only (finish()), not from a ROS 2 includer.
        private = f"{namespace.rstrip('/')}/{name}"
        node_scope = scope.child(namespace=private, params=[]) if ros1 else scope.child()
        self.resolve_children(element, node_scope, element.tag)
        node = NodeDecl(
            element.where,
            package=package,
            executable=executable,
            cmd=cmd,
            name=name,
            namespace=namespace,
            args=args,
            ros_args=ros_args,
            remaps=node_scope.remaps,
            params=node_scope.params,
            params_files=node_scope.params_files,
            env=node_scope.env,
            output=output,
            respawn=respawn,
            respawn_delay=respawn_delay,
            respawn_max_retries=DEFAULT_RESPAWN_MAX_RETRIES if retries is None else retries,
            required=required,
            sigterm_timeout=sigterm_timeout,
            sigkill_timeout=sigkill_timeout,
            launch_prefix=launch_prefix,
            cwd=cwd,
            when=scope.when,
        )
        self.add_node(node)
        if ros1:
            self.ros1_nodes.append(node)


def resolve(path: Path, args: dict[str, str], options: Options | None = None) -> Launch:
    """Read a launch file (and what it includes) with the given argument values."""
    resolver = Resolver(options or Options())
    resolver.resolve_file(path, args, None)
    return resolver.finish()
