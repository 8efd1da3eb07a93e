"""Resolve a launch file: arguments, conditions, substitutions and scopes -> node declarations.

Both formats are read here, each detected per file. What differs is the set of tags and
attributes (tables below) and parameters:
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
import shlex
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import yaml

from launcher import LaunchError
from launcher.parse import Element, parse_file
from launcher.substitutions import substitute, to_bool
from ros_tutorials_common.bounded import (
    InputError,
    load_yaml,
    parameter_problem,
    parameters_problem,
    read_text,
)

# How many times in a row a respawning process may fail quickly before we give up.
DEFAULT_RESPAWN_MAX_RETRIES = 10
# The longest respawn_delay, sigterm_timeout or sigkill_timeout accepted: one day. Longer is
# a typo (1e308) that would make the launcher wait forever.
MAX_SECONDS = 86400.0
# Groups and includes nested deeper than this are refused (a recursion, not a real file).
MAX_DEPTH = 50

CONDITIONS = {"if", "unless"}
ROS1_TAGS = {
    "node": {"pkg", "type", "name", "ns", "args", "output", "respawn", "respawn_delay",
             "required", "launch_prefix"},
    "group": {"ns"},
    "remap": {"from", "to"},
    "param": {"name", "value", "type"},
    "rosparam": {"command", "file", "param", "ns", "subst_value"},
    "arg": {"name", "default", "value", "doc"},
    "include": {"file", "ns", "pass_all_args"},
    "env": {"name", "value"},
}  # fmt: skip
ROS1_SCOPE_TAGS = set(ROS1_TAGS)
ROS1_NODE_TAGS = {"param", "rosparam", "remap", "env"}
PROCESS_ATTRS = {"args", "output", "respawn", "respawn_delay", "respawn_max_retries",
                 "sigterm_timeout", "sigkill_timeout", "launch_prefix", "on_exit"}  # fmt: skip
ROS2_TAGS = {
    "node": {"pkg", "exec", "name", "namespace", "ros_args"} | PROCESS_ATTRS,
    "executable": {"cmd", "name", "cwd"} | PROCESS_ATTRS,
    "arg": {"name", "default", "description"},
    "choice": {"value"},
    "let": {"name", "value"},
    "group": {"scoped"},
    "push_ros_namespace": {"namespace"},
    "include": {"file"},
    "set_env": {"name", "value"},
    "unset_env": {"name"},
    "set_parameter": {"name", "value"},
    "set_remap": {"from", "to"},
    "log": {"message"},
    "param": {"name", "value", "from"},
    "remap": {"from", "to"},
    "env": {"name", "value"},
}
ROS2_SCOPE_TAGS = {"arg", "let", "node", "executable", "group", "push_ros_namespace", "include",
                   "set_env", "unset_env", "set_parameter", "set_remap", "log"}  # fmt: skip
ROS2_NODE_TAGS = {"param", "remap", "env"}
ROS2_ONLY = {"let", "executable", "push_ros_namespace", "set_env", "unset_env", "set_parameter",
             "set_remap", "log"}  # fmt: skip


@dataclass
class Options:
    """What the command line decides about resolving."""

    allow_code: bool = False


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


@dataclass
class Launch:
    """A resolved launch file: the processes to run and the <log> messages to print."""

    nodes: list[NodeDecl]
    messages: list[str]


@dataclass
class ArgInfo:
    name: str
    default: str | None
    description: str
    choices: list[str]
    fixed: bool  # ROS 1 <arg value=...>: cannot be set from outside
    where: str


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
    env: dict[str, str | None] = field(default_factory=dict)

    def child(self, **changes: Any) -> Scope:
        copies = {"args": dict(self.args), "remaps": list(self.remaps),
                  "params": list(self.params), "env": dict(self.env)}  # fmt: skip
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


def valid_name(name: str) -> bool:
    return bool(name) and (name[0].isalpha() or name[0] == "_") and name.replace("_", "a").isalnum()


def detect_format(root: Element) -> str:
    """ "ros1" or "ros2", from the syntax used in the file (else from its name)."""
    ros1 = ros2 = None
    stack = [root]
    while stack:
        element = stack.pop()
        stack.extend(element.children)
        attrs = element.attrs
        if element.tag in ROS2_ONLY or (element.tag == "node" and "exec" in attrs):
            ros2 = ros2 or element
        if element.tag == "rosparam" or (element.tag == "node" and "type" in attrs):
            ros1 = ros1 or element
        if element.tag == "group" and "ns" in attrs:
            ros1 = ros1 or element
    if ros1 and ros2:
        raise LaunchError(
            f"{root.file}: mixes ROS 1 syntax (line {ros1.line}: <{ros1.tag}>) "
            f"and ROS 2 syntax (line {ros2.line}: <{ros2.tag}>)"
        )
    if ros1 or ros2:
        return "ros1" if ros1 else "ros2"
    return "ros1" if root.file.name.endswith(".launch") else "ros2"


def _check(element: Element, allowed: set[str]) -> None:
    for name in element.attrs:
        if name not in allowed | CONDITIONS:
            known = ", ".join(sorted(allowed | CONDITIONS))
            raise element.error(f"unknown attribute {name!r} on <{element.tag}>; allowed: {known}")
    if "if" in element.attrs and "unless" in element.attrs:
        raise element.error("use either 'if' or 'unless', not both")


def _check_tag(
    element: Element, allowed: set[str], fmt: str, parent: str, attrs: set[str] | None = None
) -> None:
    if element.tag not in allowed:
        syntax = "ROS 1 (roslaunch)" if fmt == "ros1" else "ROS 2"
        known = ", ".join(f"<{tag}>" for tag in sorted(allowed))
        raise element.error(
            f"unknown tag <{element.tag}> in <{parent}> ({syntax} format); allowed: {known}"
        )
    _check(element, attrs or (ROS1_TAGS if fmt == "ros1" else ROS2_TAGS)[element.tag])


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
        infos.append(ArgInfo(attrs["name"], default, description, choices, fixed, element.where))
    return infos


def _typed_value(text: str, kind: str | None, element: Element) -> Any:
    """A parameter value from its text, typed as roslaunch and ros2 launch do."""
    try:
        if kind in ("str", "string"):
            return text
        if kind == "int":
            return int(text)
        if kind == "double":
            return float(text)
        if kind in ("bool", "boolean"):
            return to_bool(text, element, "a bool parameter")
        if kind == "yaml":
            return _load_yaml(text, element)
    except (ValueError, yaml.YAMLError) as error:
        raise element.error(f"value {text!r} is not a valid {kind}: {error}") from None
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
        data = load_yaml(read_text(path), str(path))
    except InputError as error:
        raise element.error(str(error)) from None
    except yaml.YAMLError as error:
        raise element.error(f"{path} is not valid YAML: {' '.join(str(error).split())}") from None
    if not isinstance(data, dict):
        raise element.error(f"{path} is not a params file (expected 'node: ros__parameters:')")
    for key, entry in data.items():
        if not isinstance(key, str):
            raise element.error(f"{path}: node name {key!r} is not a string")
        problem = parameters_problem(entry, "")
        if problem:
            raise element.error(f"{path}: {problem}")


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
        self.anon_names: dict[str, str] = {}
        self.include_chain: list[Path] = []
        self.depth = 0  # nested groups and includes
        # ROS 1: the parameter server roslaunch would fill, full name -> value, and the
        # nodes whose parameters come from it once every file is read.
        self.param_server: dict[str, Any] = {}
        self.ros1_nodes: list[NodeDecl] = []

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
    ) -> None:
        path = path.resolve()
        if path in self.include_chain:
            chain = " -> ".join(str(p) for p in [*self.include_chain, path])
            message = f"launch files include each other in a loop: {chain}"
            raise include.error(message) if include else LaunchError(message)
        root = parse_file(path)
        _check(root, {"deprecated"})
        fmt = detect_format(root)
        declared = {element.attrs.get("name") for element in _file_args(root)}
        unknown = sorted(set(given) - declared) if strict else []
        if unknown:
            names = ", ".join(sorted(n for n in declared if n)) or "none"
            raise LaunchError(
                f"{path}: no argument named {', '.join(unknown)} is declared (declared: {names})"
            )
        if parent is None:
            scope = Scope(self, path, fmt, {}, given)
        else:
            scope = parent.child(file=path, fmt=fmt, args={}, given=given)
        self.include_chain.append(path)
        self.resolve_children(root, scope)
        self.include_chain.pop()

    def resolve_children(self, element: Element, scope: Scope) -> None:
        allowed = ROS1_SCOPE_TAGS if scope.fmt == "ros1" else ROS2_SCOPE_TAGS
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise element.error(f"groups and includes nested more than {MAX_DEPTH} deep")
            for child in element.children:
                _check_tag(child, allowed, scope.fmt, element.tag)
                if self.enabled(child, scope):
                    handler = getattr(self, f"on_{scope.fmt}_{child.tag}", None) or getattr(
                        self, f"on_{child.tag}"
                    )
                    handler(child, scope)
        finally:
            self.depth -= 1

    def finish(self) -> Launch:
        for node in self.ros1_nodes:
            node.params = self._ros1_params(node) + node.params
        return Launch(self.nodes, self.messages)

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

    # -- tags common to both formats ----------------------------------------------------------

    def on_arg(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope)
        fixed = "value" in element.attrs  # ROS 1: a constant, not an argument
        for child in element.children:
            _check_tag(child, {"choice"}, scope.fmt, "arg")
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

    def on_group(self, element: Element, scope: Scope) -> None:
        if scope.fmt == "ros1":
            ns = self.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
            self.resolve_children(element, scope.child(namespace=ns))
        elif self.flag(element, "scoped", scope) or "scoped" not in element.attrs:
            self.resolve_children(element, scope.child())
        else:
            self.resolve_children(element, scope)

    def on_remap(self, element: Element, scope: Scope) -> None:
        scope.remaps.append((self.text(element, "from", scope), self.text(element, "to", scope)))

    on_set_remap = on_remap

    def on_env(self, element: Element, scope: Scope) -> None:
        scope.env[self.env_name(element, scope)] = self.text(element, "value", scope)

    on_set_env = on_env

    def on_include(self, element: Element, scope: Scope) -> None:
        path = Path(self.text(element, "file", scope))
        if not path.is_absolute():  # relative to the including file, not the current directory
            path = scope.file.parent / path
        pass_all = scope.fmt == "ros1" and self.flag(element, "pass_all_args", scope)
        given = dict(scope.args) if pass_all else {}
        for child in element.children:
            _check_tag(child, {"arg"}, scope.fmt, "include", {"name", "value"})
            if self.enabled(child, scope):
                given[self.text(child, "name", scope)] = self.text(child, "value", scope)
        ns = self.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
        if not path.is_file():
            raise element.error(f"included file {path} does not exist")
        self.resolve_file(path, given, scope.child(namespace=ns), not pass_all, element)

    # -- ROS 1 --------------------------------------------------------------------------------

    def on_ros1_node(self, element: Element, scope: Scope) -> None:
        node = self._node(element, scope, "type", "ns")
        node.required = self.flag(element, "required", scope)
        if node.required and node.respawn:
            raise element.error("a node cannot be both respawn and required")
        node_scope = scope.child(namespace=node.namespace)
        private = f"{node.namespace.rstrip('/')}/{node.name}"
        for child in element.children:
            _check_tag(child, ROS1_NODE_TAGS, "ros1", "node")
            if not self.enabled(child, node_scope):
                continue
            if child.tag in ("param", "rosparam"):
                self._ros1_param(child, node_scope, private)
            else:
                getattr(self, f"on_{child.tag}")(child, node_scope)
        node.remaps, node.env = node_scope.remaps, node_scope.env
        self.ros1_nodes.append(node)
        self.nodes.append(node)

    def on_ros1_param(self, element: Element, scope: Scope) -> None:
        self._ros1_param(element, scope, scope.namespace)

    on_rosparam = on_ros1_param

    def _ros1_param(self, element: Element, scope: Scope, namespace: str) -> None:
        if element.tag == "rosparam":
            return self._rosparam(element, scope, namespace)
        name = self.text(element, "name", scope)
        if name.startswith("~"):
            name = name[1:]  # private: inside <node> the namespace is already the node's
        value = _typed_value(self.text(element, "value", scope), element.attrs.get("type"), element)
        _check_params(element, {name: value} if isinstance(value, dict) else None, name, value)
        for key, item in _flatten(join_namespace(namespace, name), value):
            self.param_server[key] = item

    def _rosparam(self, element: Element, scope: Scope, namespace: str) -> None:
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
        if "ns" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "ns", scope))
        if "param" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "param", scope))
        elif not isinstance(value, dict):
            raise element.error("<rosparam> without 'param' must hold a YAML mapping")
        for key, item in _flatten(namespace, value):
            self.param_server[key] = item

    def _ros1_params(self, node: NodeDecl) -> list[tuple[str, Any]]:
        """A ROS 1 node's parameters from the parameter server (see the module docstring)."""
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
        for key, value in self.param_server.items():
            if key.startswith(private):
                params[key[len(private) :].replace("/", ".")] = value
        return list(params.items())

    # -- ROS 2 --------------------------------------------------------------------------------

    def on_ros2_node(self, element: Element, scope: Scope) -> None:
        node = self._node(element, scope, "exec", "namespace")
        node.ros_args = self.words(element, "ros_args", scope)
        self._ros2_process(node, element, scope, ROS2_NODE_TAGS)

    def on_executable(self, element: Element, scope: Scope) -> None:
        cmd = self.words(element, "cmd", scope)
        if not cmd:
            raise element.error("<executable> needs a non-empty 'cmd'")
        node = NodeDecl(element.where, cmd=cmd, namespace=scope.namespace)
        node.name = self.text(element, "name", scope, "") or None
        node.cwd = self.text(element, "cwd", scope, "") or None
        self._process_options(node, element, scope)
        self._ros2_process(node, element, scope, {"env"})

    def _ros2_process(self, node: NodeDecl, element: Element, scope: Scope, tags: set) -> None:
        on_exit = self.text(element, "on_exit", scope, "")
        if on_exit not in ("", "shutdown"):
            raise element.error(f"on_exit={on_exit!r} is not supported; use 'shutdown'")
        node.required = on_exit == "shutdown"
        if node.required and node.respawn:
            raise element.error("a process cannot both respawn and shut the launch down on exit")
        for name in ("sigterm_timeout", "sigkill_timeout"):
            setattr(node, name, self.number(element, name, scope))
        node.remaps, node.params, node.env = list(scope.remaps), list(scope.params), dict(scope.env)
        for child in element.children:
            _check_tag(child, tags, "ros2", element.tag)
            if not self.enabled(child, scope):
                continue
            if child.tag == "remap":
                node.remaps.append((self.text(child, "from", scope), self.text(child, "to", scope)))
            elif child.tag == "env":
                node.env[self.env_name(child, scope)] = self.text(child, "value", scope)
            elif "from" in child.attrs:
                path = Path(self.text(child, "from", scope))
                path = path if path.is_absolute() else scope.file.parent / path
                _check_params_file(child, path)
                node.params_files.append(str(path))
            else:
                node.params.append(self._ros2_param(child, scope))
        self.nodes.append(node)

    def _ros2_param(self, element: Element, scope: Scope) -> tuple[str, Any]:
        value = _typed_value(self.text(element, "value", scope), None, element)
        name = self.text(element, "name", scope)
        _check_params(element, None, name, value)
        return name, value

    def on_set_parameter(self, element: Element, scope: Scope) -> None:
        scope.params.append(self._ros2_param(element, scope))

    def on_let(self, element: Element, scope: Scope) -> None:
        scope.args[self.text(element, "name", scope)] = self.text(element, "value", scope)

    def on_push_ros_namespace(self, element: Element, scope: Scope) -> None:
        scope.namespace = self.namespace(element, "namespace", scope)

    def on_unset_env(self, element: Element, scope: Scope) -> None:
        scope.env[self.env_name(element, scope)] = None

    def on_log(self, element: Element, scope: Scope) -> None:
        self.messages.append(self.text(element, "message", scope))

    # -- nodes --------------------------------------------------------------------------------

    def _node(self, element: Element, scope: Scope, exec_attr: str, ns_attr: str) -> NodeDecl:
        node = NodeDecl(element.where)
        node.package = self.text(element, "pkg", scope)
        node.executable = self.text(element, exec_attr, scope)
        if scope.fmt == "ros1" or "name" in element.attrs:
            node.name = self.text(element, "name", scope)
            if not valid_name(node.name):
                raise element.error(f"invalid node name {node.name!r}")
        if ns_attr in element.attrs:
            node.namespace = self.namespace(element, ns_attr, scope)
        else:
            node.namespace = scope.namespace
        self._process_options(node, element, scope)
        return node

    def _process_options(self, node: NodeDecl, element: Element, scope: Scope) -> None:
        node.args = self.words(element, "args", scope)
        node.output = self.text(element, "output", scope, "log")
        outputs = ("screen", "log") if scope.fmt == "ros1" else ("screen", "log", "both")
        if node.output not in outputs:
            raise element.error(f"output={node.output!r}; use one of {', '.join(outputs)}")
        node.respawn = self.flag(element, "respawn", scope)
        node.respawn_delay = self.number(element, "respawn_delay", scope) or 0.0
        retries = self.number(element, "respawn_max_retries", scope, int)
        node.respawn_max_retries = DEFAULT_RESPAWN_MAX_RETRIES if retries is None else retries
        node.launch_prefix = self.words(element, "launch_prefix", scope)


def resolve(path: Path, args: dict[str, str], options: Options | None = None) -> Launch:
    """Read a launch file (and what it includes) with the given argument values."""
    resolver = Resolver(options or Options())
    resolver.resolve_file(path, args, None)
    return resolver.finish()
