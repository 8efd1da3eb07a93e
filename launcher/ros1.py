"""The ROS 1 dialect: roslaunch's XML read by roslaunch's rules, as a front-end of its own
over the same model (its ``<node>`` is launch_ros's ``Node``, its ``<env>``
``SetEnvironmentVariable``). One method per tag, as roslaunch's xmlloader; the scope is one
object (launcher/scope.py, roslaunch's LoaderContext).

- ``<group>`` and ``<include>`` are scopes: an included file sees only the arguments passed to
  it (all of them with ``pass_all_args``), and nothing set inside leaks out.
- a later ``<remap>`` of a name replaces the earlier.
- ``<param>`` and ``<rosparam>`` write a parameter server, as roslaunch does: names are relative
  to the namespace of their group, the last value written wins, wherever it is written. At the
  end (``finish``) each node receives the parameters of its namespace and of the enclosing
  ones (the nearest wins) plus its private ones (``~name``, or written inside ``<node>``).
- roslaunch's substitutions (``$(arg)``, ``$(find)``, ``$(optenv)``, its ``$(eval)``) are
  launch_foundation.substitutions' ROS 1 table.
"""

from __future__ import annotations

import math
import shlex
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launch_foundation.declarations import NodeDecl
from launch_foundation.errors import CodeRefused, LaunchError
from launch_foundation.naming import flatten, join_namespace, remap_problem, valid_name
from launch_foundation.parse import Element
from launch_foundation.substitutions import run_command, to_bool
from launcher import attributes as read
from launcher.ros1_substitutions import substitute
from launcher.scope import Scope
from launcher.sink import Recording, note_unreached
from launcher.tags import check_tag, tag
from ros_tutorials_common.bounded import (
    InputError,
    load_yaml,
    parameter_problem,
    parameters_problem,
    read_text,
)

if TYPE_CHECKING:
    from launcher.loading import Loader


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


def _load_yaml(text: str, element: Element) -> Any:
    """YAML written in (or read by) a launch file, within the limits of bounded.load_yaml."""
    import yaml  # here: a launch without parameters reads no YAML

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


def _short(text: str, limit: int = 60) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def clear_params(element: Element, scope: Scope) -> None:
    """roslaunch's clear_params: checked as roslaunch checks it, and otherwise nothing to do:
    a ROS 2 node's parameters start empty (there is no parameter server to clear)."""
    if read.flag(element, "clear_params", scope):
        where = "name" if element.tag == "node" else "ns"
        if where not in element.attrs:
            raise element.error(f"clear_params on <{element.tag}> needs a '{where}'")


class Ros1Loader:
    """The handlers of roslaunch's tags, and the parameter server they fill. One per launch."""

    def __init__(self, loader: Loader) -> None:
        self.loader = loader
        # The parameter server roslaunch would fill, full name -> value, and the nodes whose
        # parameters come from it once every file is read.
        self.param_server: dict[str, Any] = {}
        self.param_origin: dict[str, tuple[str, str]] = {}  # key -> (name as written, where)
        self.nodes: list[NodeDecl] = []
        # Each ~param written outside a <node> (name, where) -> whether a node got it.
        self.private_given: dict[tuple[str, str], bool] = {}
        self.tests: list[str] = []  # <test>s, ignored as roslaunch ignores them

    def finish(self, unreached: dict[tuple[str, str], list[str]]) -> None:
        """Each node's parameters from the parameter server; the parameters no node receives
        (ROS 1 kept every one on its server) into ``unreached`` ((where, why) -> names)."""
        reached: set[str] = set()
        for node in self.nodes:
            node.params = self._ros1_params(node, reached) + node.params
        for key, (name, where) in self.param_origin.items():
            if key not in reached:
                why = "ROS 2 has no parameter server; put it inside a <node>"
                note_unreached(unreached, where, why, name)
        for (name, where), given in self.private_given.items():
            if not given:
                note_unreached(unreached, where, "no <node> follows it in its scope", "~" + name)
        if self.tests:
            self.loader.warn(
                f"ignored {len(self.tests)} <test> (roslaunch leaves them to rostest; ROS 2 has "
                f"launch_testing): {', '.join(self.tests)}"
            )

    @tag("ros1", "arg", {"name", "default", "value", "doc"}, marks={"value", "doc"})
    def on_arg(self, element: Element, scope: Scope) -> None:
        name = read.text(element, "name", scope)
        fixed = "value" in element.attrs  # a constant, not an argument
        if name in scope.declared:
            raise element.error(
                f"argument {name!r} is declared twice (first at line {scope.declared[name]}); "
                "roslaunch refuses that too"
            )
        scope.declared[name] = element.line
        for child in element.children:
            check_tag(child, {"choice": {"value"}}, scope, "arg")
        # A fixed value cannot be set from outside, except by pass_all_args, which it overrides
        # (roslaunch's own tests load such files).
        if fixed and name in scope.given and not scope.pass_all:
            raise element.error(f"argument {name!r} has a fixed value and cannot be set")
        if fixed:
            value = read.text(element, "value", scope)
        elif name in scope.given:
            value = scope.given[name]
        elif "default" in element.attrs:
            value = read.text(element, "default", scope)
        else:  # roslaunch fails only where such an argument is used
            scope.unset[name] = element.line
            return
        choices = [read.text(child, "value", scope) for child in element.children]
        if choices and value not in choices:
            raise element.error(f"argument {name!r} is {value!r}; choose one of {choices}")
        scope.args[name] = value

    @tag("ros1", "group", {"ns", "clear_params"}, marks={"ns", "clear_params"})
    def on_ros1_group(self, element: Element, scope: Scope) -> None:
        clear_params(element, scope)
        ns = read.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
        self.loader.resolve_scope(element, scope.child(namespace=ns))

    @tag("ros1", "include", {"file", "ns", "pass_all_args", "clear_params"},
         marks={"ns", "pass_all_args", "clear_params"})  # fmt: skip
    def on_ros1_include(self, element: Element, scope: Scope) -> None:
        """roslaunch's <include>: a scope of its own (namespace, <env>), the included file
        seeing only the arguments passed to it (all of them with pass_all_args)."""
        path = Path(read.text(element, "file", scope))
        if not path.is_absolute():  # relative to the including file, not the current directory
            path = scope.file.parent / path
        pass_all = read.flag(element, "pass_all_args", scope)
        clear_params(element, scope)
        given = dict(scope.args) if pass_all else {}
        given_at: dict[str, str] = {}
        inner = scope.child(pass_all=pass_all)  # what the included file starts with
        allowed = {"arg": {"name", "value"}, "env": {"name", "value"}}
        for child in element.children:
            check_tag(child, allowed, scope, "include")
            if not read.enabled(child, scope):
                continue
            if child.tag == "env":  # roslaunch: an <env> in <include> is for the included nodes
                self.on_env(child, inner)
                continue
            name = read.text(child, "name", scope)
            given[name] = read.text(child, "value", scope)
            given_at.setdefault(name, child.where)
        if "ns" in element.attrs:
            inner.namespace = read.namespace(element, "ns", scope)
        if not path.is_file():
            raise element.error(f"included file {path} does not exist")
        self.loader.resolve_file(path, given, inner, not pass_all, element.where, given_at)

    @tag("ros1", "remap", {"from", "to"}, under={"launch", "node"})
    def on_remap(self, element: Element, scope: Scope) -> None:
        names = []
        for side in ("from", "to"):
            written = name = read.text(element, side, scope)
            if name.startswith("~") and not name.startswith("~/"):
                name = "~/" + name[1:]  # ROS 1's private ~name is ~/name in ROS 2
            if remap_problem(name, side):
                raise element.error(remap_problem(written, side) or "")
            names.append(name)
        # roslaunch: a later remap of the same name replaces the earlier
        scope.remaps[:] = [remap for remap in scope.remaps if remap[0] != names[0]]
        scope.remaps.append((names[0], names[1]))

    @tag("ros1", "env", {"name", "value"}, under={"launch", "node"})
    def on_env(self, element: Element, scope: Scope) -> None:
        from launch.actions import SetEnvironmentVariable

        name, value = read.text(element, "name", scope), read.text(element, "value", scope)
        self.loader.run(SetEnvironmentVariable(name, value), element, scope)

    # Parameters go to the parameter server, under the namespace of their scope (inside
    # <node>: the node's private namespace).

    @tag("ros1", "param", {"name", "value", "type", "textfile", "binfile", "command"},
         under={"launch", "node"}, marks={"textfile", "binfile"})  # fmt: skip
    def on_ros1_param(self, element: Element, scope: Scope) -> None:
        name = read.text(element, "name", scope)
        sources = sorted({"value", "textfile", "binfile", "command"} & element.attrs.keys())
        if len(sources) > 1:
            raise element.error(f"<param> takes one of value, textfile, binfile, command, "
                                f"not {' and '.join(sources)}")  # fmt: skip
        if "binfile" in element.attrs:
            raise element.error(
                "binfile is not supported: a ROS 2 parameter given to a node at its start "
                "cannot hold a file's bytes"
            )
        if "textfile" in element.attrs:  # the file's text, as a string parameter
            path = Path(read.text(element, "textfile", scope))
            try:
                value: Any = read_text(path if path.is_absolute() else scope.file.parent / path)
            except InputError as error:
                raise element.error(str(error)) from None
        elif "command" in element.attrs:  # roslaunch: what the program prints, typed
            command = read.text(element, "command", scope)
            if not scope.allow_code:
                raise CodeRefused(f"{element.where}: <param command={command!r}> runs a program")
            shown = f"<param command={command!r}>"
            text = run_command(command, element.error, shown)
            value = _typed_value(text, element.attrs.get("type"), element)
        else:
            text = read.text(element, "value", scope)
            value = _typed_value(text, element.attrs.get("type"), element)
        value = self.flat_lists(element, name, value)
        if name.startswith("~"):
            name = name[1:]  # private: inside <node> the namespace is already the node's
            _check_params(element, {name: value} if isinstance(value, dict) else None, name, value)
            if not scope.in_node:  # roslaunch: for each node after it in this scope
                scope.private[:] = [entry for entry in scope.private if entry[0] != name]
                scope.private.append((name, value, element.where))
                self.private_given.setdefault((name, element.where), False)
                return
        _check_params(element, {name: value} if isinstance(value, dict) else None, name, value)
        for key, item in flatten(value, "/", join_namespace(scope.namespace, name)):
            self.param_server[key] = item
            self.param_origin[key] = (name, element.where)

    @tag("ros1", "rosparam", {"command", "file", "param", "ns", "subst_value"}, {"launch", "node"})
    def on_rosparam(self, element: Element, scope: Scope) -> None:
        command = read.text(element, "command", scope, "load")
        if command not in ("load", "delete", "dump"):
            raise element.error(f"<rosparam command={command!r}>: use load, delete or dump")
        namespace = scope.namespace
        if "ns" in element.attrs:
            namespace = join_namespace(namespace, read.text(element, "ns", scope))
        if "param" in element.attrs:
            namespace = join_namespace(namespace, read.text(element, "param", scope))
        if command == "dump":  # roslaunch wrote the parameter server to a file at the start
            self.loader.warn(
                f'{element.where}: <rosparam command="dump"> does nothing: ROS 2 has no '
                "parameter server (`ros2 param dump NODE` saves a node's parameters)"
            )
            return
        if command == "delete":  # written before, so no node receives it
            for key in [k for k in self.param_server if k == namespace or
                        k.startswith(namespace.rstrip("/") + "/")]:  # fmt: skip
                del self.param_server[key]
                del self.param_origin[key]
            return
        if "file" in element.attrs:
            path = Path(read.text(element, "file", scope))
            try:  # at most 1 MiB of UTF-8
                text = read_text(path if path.is_absolute() else scope.file.parent / path)
            except InputError as error:
                raise element.error(str(error)) from None
        else:
            text = element.text
        if read.flag(element, "subst_value", scope):
            text = substitute(text, scope, element)
        value = _load_yaml(text, element)
        if value is None:  # an empty file or tag: nothing to load, as roslaunch
            return
        value = self.flat_lists(element, element.attrs.get("param", ""), value)
        _check_params(element, value if isinstance(value, dict) else None, "", value)
        if "param" not in element.attrs and not isinstance(value, dict):
            raise element.error("<rosparam> without 'param' must hold a YAML mapping")
        for key, item in flatten(value, "/", namespace):
            self.param_server[key] = item
            self.param_origin[key] = (key, element.where)

    def flat_lists(self, element: Element, name: str, value: Any) -> Any:
        """ROS 1 takes a list of lists (a footprint); a ROS 2 parameter cannot: such a list
        goes on as its YAML text, as ROS 2 navigation reads a footprint, with one warning."""
        if isinstance(value, dict):
            return {
                key: self.flat_lists(element, f"{name}/{key}" if name else str(key), item)
                for key, item in value.items()
            }
        if isinstance(value, list) and any(isinstance(item, list | dict) for item in value):
            import yaml

            text = yaml.safe_dump(value, default_flow_style=True, width=math.inf).strip()
            self.loader.warn(
                f"{element.where}: param {name.lstrip('/')!r} is a list of lists, which a ROS 2 "
                f"parameter cannot hold: given as the string {_short(text)!r} (as ROS 2 "
                "navigation reads a footprint)"
            )
            return text
        return value

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

    @tag("ros1", "test", {"pkg", "type", "name", "test_name", "args", "ns", "clear_params",
                          "cwd", "launch_prefix", "retry", "time_limit"})  # fmt: skip
    def on_test(self, element: Element, scope: Scope) -> None:
        """roslaunch skips <test> (rostest runs it): said in one line at the end."""
        name = element.attrs.get("test_name") or element.attrs.get("name") or "<test>"
        self.tests.append(f"{name} ({element.where})")

    @tag("ros1", "node", {"pkg", "type", "name", "ns", "args", "output", "respawn", "respawn_delay",
                          "required", "launch_prefix", "clear_params"},
         marks={"type", "ns", "clear_params"})  # fmt: skip
    def on_ros1_node(self, element: Element, scope: Scope) -> None:
        """roslaunch's <node>: launch_ros's Node in the node's private scope (where its
        <param>s go, to the parameter server; its parameters are given in finish())."""
        clear_params(element, scope)
        package = read.text(element, "pkg", scope)
        executable = read.text(element, "type", scope)
        for attr, value in (("pkg", package), ("type", executable)):
            if not value.strip():
                raise element.error(f"<node {attr}> is empty")
        name = read.text(element, "name", scope)  # a ROS 1 node must be named
        if not valid_name(name):
            raise element.error(f"invalid node name {name!r}")
        namespace = scope.namespace
        if "ns" in element.attrs:
            namespace = read.namespace(element, "ns", scope)
        args = read.words(element, "args", scope)
        output = read.text(element, "output", scope, "log")
        if output not in ("screen", "log"):
            raise element.error(f"output={output!r}; use one of screen, log")
        respawn = read.flag(element, "respawn", scope)
        respawn_delay = read.number(element, "respawn_delay", scope) or 0.0
        launch_prefix = read.words(element, "launch_prefix", scope)
        required = read.flag(element, "required", scope)
        if required and respawn:
            raise element.error("a node cannot be both respawn and required")
        # The children (<param>, <remap>, <env>) apply to a scope of the node's own, its
        # private namespace, where its <param>s go; the ~params written before it in its scope
        # go there first.
        private = f"{namespace.rstrip('/')}/{name}"
        for key, value, where in scope.private:
            for full, item in flatten(value, "/", f"{private}/{key}"):
                self.param_server[full] = item
                self.param_origin[full] = ("~" + key, where)
            self.private_given[(key, where)] = True
        node_scope = scope.child(namespace=private, params=[], in_node=True)
        self.loader.resolve_children(element, node_scope, element.tag)
        from launch.actions import Shutdown
        from launch_ros.actions import Node

        # Its namespace is absolute already (its scope's is its private one); its parameters
        # come from the parameter server at the end (finish()), its remaps are its scope's (the
        # last of a name won).
        action = Node(
            package=package, executable=executable, name=name, namespace=namespace,
            arguments=args, output=output, respawn=respawn, respawn_delay=respawn_delay,
            prefix=shlex.join(launch_prefix) or None, on_exit=Shutdown() if required else None,
        )  # fmt: skip
        recording = Recording(self.loader.plan)
        self.loader.run(action, element, node_scope, recording)
        self.nodes.extend(recording.nodes)
