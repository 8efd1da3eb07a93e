"""Resolve a launch file: arguments, conditions, substitutions and scopes -> node declarations.

(About 1 150 lines: the markup front-ends' one table of tags, the scope every handler reads,
and the ROS 1 dialect's rules, about 300 lines of it, which need both; what a ROS 2 tag does is
its action's, in launch/ and launch_ros/.)

Both XML formats and YAML are read here, each detected per file. Each tag has its ``@tag``
line (its attributes, where it may stand, the signs of its format) on the handler that reads
it. A ROS 2 tag's handler has its action (launch/, launch_ros/) built by the parse method
the action exposed (launch.frontend) and executes it in the
file's scope (``run``): what the tag does is the action's. ROS 1's rules are its handlers':
- ``<param>`` writes to a parameter server, as roslaunch does: names are relative to the
  namespace of their group, the last value written wins, wherever it is written. At the end
  each node receives the parameters of its namespace and of the enclosing ones (the nearest
  wins) plus its private ones (``~name``, or written inside ``<node>``).
- a later ``<remap>`` of a name replaces the earlier; ``<group>`` and ``<include>`` are scopes:
  an included file sees only the arguments passed to it, and nothing set inside leaks out.
A ROS 2 ``<include>`` is not scoped, as in ros2 launch (``resolve_file`` says where a value
crossed one); ``<set_parameter>`` applies to the nodes after it in its scope.
"""

from __future__ import annotations

import math
import os
import re
import shlex
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path
from typing import Any

from launch_foundation.declarations import (
    AT_START,
    ArgInfo,
    ContainerDecl,
    Launch,
    NodeDecl,
    Step,
    When,
)
from launch_foundation.errors import CodeRefused, LaunchError
from launch_foundation.naming import (
    flatten,
    join_namespace,
    namespace_under,
    remap_problem,
    valid_name,
)
from launch_foundation.parse import YAML_SUFFIXES, Element, parse_file
from launch_foundation.substitutions import (
    MAX_LAUNCH_SUBSTITUTED,
    run_command,
    substitute,
    to_bool,
)
from ros_tutorials_common.bounded import (
    InputError,
    load_yaml,
    parameter_problem,
    parameters_problem,
    read_text,
)

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
            self.resolver.note_read(self, name, element)
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
        return self.resolver.options.allow_code

    def anon(self, name: str) -> str:
        return self.resolver.anon(name)

    def charge(self, size: int, element: Element) -> None:
        self.resolver.charge(size, element.where)


# Substitutions only one format has: a sign of the file's format as good as a tag.
_SUBSTITUTION_SIGNS = {
    "ros1": re.compile(r"\$\(\s*(arg|find|optenv)\s"),
    "ros2": re.compile(r"\$\(\s*(var|find-pkg-share|find-pkg-prefix|find-exec|not|and|or|equals"
                       r"|command)\s"),
}  # fmt: skip
# roslaunch tags this launcher does not run: a sign of a ROS 1 file, and why each is refused.
ROS1_UNSUPPORTED = {
    "machine": "remote machines are roslaunch's (ROS 2 nodes find each other by discovery: "
    "start the node on that machine)",
}
# Where an element stands, as TAGS' ``under`` names it.
_PLACE = {"launch": "launch", "group": "launch", "timer": "launch", "node": "node",
          "executable": "executable", "node_container": "node_container",
          "load_composable_node": "node_container",
          "composable_node": "composable_node"}  # fmt: skip


def _sign(fmt: str, element: Element, parent: str) -> str | None:
    """What in ``element`` (a child of a ``parent`` place) only ``fmt`` has: its tag, a tag in
    that place, an attribute (``<arg value>``, ``<node type>``) or a substitution; else None."""
    if fmt == "ros1" and element.tag in ROS1_UNSUPPORTED:
        return f"<{element.tag}>"
    other = TAGS["ros2" if fmt == "ros1" else "ros1"]
    known, theirs = TAGS[fmt].get(element.tag), other.get(element.tag)
    if known is not None and parent in known.under:
        if theirs is None:
            return f"<{element.tag}>"
        if parent not in theirs.under:
            return f"<{element.tag}> in <{parent}>"
        marks = sorted(known.marks & element.attrs.keys())
        if marks:
            return f"<{element.tag} {element.spelled.get(marks[0], marks[0])}=...>"
    for value in element.attrs.values():
        if found := _SUBSTITUTION_SIGNS[fmt].search(value):
            return f"$({found[1]} ...)"
    return None


def detect(root: Element) -> tuple[str, str]:
    """The file's format, "ros1" or "ros2", from every sign of one in it (else from its name),
    and why, for the errors a wrong guess would cause."""
    first: dict[str, tuple[Element, str] | None] = {"ros1": None, "ros2": None}
    stack = [(child, "launch") for child in reversed(root.children)]
    while stack:  # in the file's order, so the first sign is the earliest line
        element, parent = stack.pop()
        place = _PLACE.get(element.tag, element.tag)
        stack.extend((child, place) for child in reversed(element.children))
        for fmt, found in first.items():
            if found is None and (sign := _sign(fmt, element, parent)):
                first[fmt] = (element, sign)
    if root.file.suffix in YAML_SUFFIXES:  # launch_yaml is a ROS 2 front-end only
        return "ros2", "a YAML launch file"
    ros1, ros2 = first["ros1"], first["ros2"]
    if ros1 and ros2:
        raise LaunchError(
            f"{root.file}: mixes ROS 1 syntax (line {ros1[0].line}: {ros1[1]}) "
            f"and ROS 2 syntax (line {ros2[0].line}: {ros2[1]})"
        )
    for fmt, found in first.items():
        if found:
            return fmt, f"line {found[0].line}: {found[1]}"
    if root.file.name.endswith(".launch"):
        return "ros1", "nothing in it is only ROS 1 or only ROS 2, and its name ends in .launch"
    return "ros2", "nothing in it is only ROS 1 or only ROS 2, and its name is not *.launch"


def detect_format(root: Element) -> str:
    """ "ros1" or "ros2", from the syntax used in the file (else from its name)."""
    return detect(root)[0]


def _check(element: Element, allowed: set[str] | frozenset[str], note: str = "") -> None:
    """Only ``allowed`` attributes (and if/unless); ``note`` ends the error (the format)."""
    for name in element.attrs:
        if name not in allowed | CONDITIONS:
            known = ", ".join(sorted(SPELLING.get(a, a) for a in allowed | CONDITIONS))
            written = element.spelled.get(name, name)  # as the file wrote it
            raise element.error(
                f"unknown attribute {written!r} on <{element.tag}>; allowed: {known}{note}"
            )
    if "if" in element.attrs and "unless" in element.attrs:
        raise element.error("use either 'if' or 'unless', not both")


def _check_tag(element: Element, allowed: dict, scope: Scope, parent: str) -> None:
    """``element`` is one of the ``allowed`` tags (tag -> attributes) under ``parent``."""
    fmt = scope.fmt
    if fmt == "ros1" and element.tag in ROS1_UNSUPPORTED:
        raise element.error(f"<{element.tag}> is not supported: {ROS1_UNSUPPORTED[element.tag]}")
    if element.tag not in allowed:
        known = ", ".join(f"<{name}>" for name in sorted(allowed))
        raise element.error(
            f"unknown tag <{element.tag}> in <{parent}> ({SYNTAX[fmt]} format); allowed: {known}"
            f"{scope.note}"
        )
    _check(element, allowed[element.tag], scope.note)


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


PARAM_ATTRS = frozenset({"name", "value", "from", "type", "value_sep", "allow_substs"})


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


def _short(text: str, limit: int = 60) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


@cache
def _launch_parser() -> type:
    """launch.frontend's Parser for the launcher: the entities an action holds (a <group>'s,
    a <timer>'s children) are read when the action reaches them, in its scope and by the
    tag's handler of the file's format (Resolver.deferred). Made at its first use: launch_xml
    brings in the whole launch model, which a file without ROS 2 actions never needs, and its
    import was a third of the launcher's start before its first process."""
    from launch_xml import Parser

    class LaunchParser(Parser):
        def __init__(self, resolver: Resolver, parent: str) -> None:
            self.resolver, self.parent = resolver, parent

        def parse_action(self, entity: Any) -> Any:
            return self.resolver.deferred(entity.element, self.parent)

    return LaunchParser


class Resolver:
    """Walks launch files and collects node declarations. One per launch."""

    def __init__(self, options: Options) -> None:
        self.options = options
        self.nodes: list[NodeDecl] = []
        self.messages: list[str] = []
        self.steps: list[Step] = []
        self.warnings: list[str] = []
        self.python_state: Any = None  # the launch model's own state (launch_state())
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
        # ROS 1: each ~param written outside a <node> (name, where) -> whether a node got it.
        self.private_given: dict[tuple[str, str], bool] = {}
        self.reads: dict[Path, set[str]] = {}  # the arguments each file reads
        self.expanded = 0  # characters substitutions expanded to, in the whole launch
        self.tests: list[str] = []  # ROS 1 <test>s, ignored as roslaunch ignores them
        self.containers: list[ContainerDecl] = []

    def warn(self, text: str) -> None:
        """A warning printed before the launch starts (once, however often it is found)."""
        if text not in self.warnings:
            self.warnings.append(text)

    def note_read(self, scope: Scope, name: str, element: Element) -> None:
        """``element`` reads argument ``name``: say so where the value crossed an include
        (ros2 launch does not scope includes; roslaunch and this launcher's ROS 1 files do)."""
        self.reads.setdefault(scope.file, set()).add(name)
        value = scope.args[name]
        if name in scope.inherited:
            self.warn(
                f"{element.where}: {name!r} ({value!r}) is not passed to this file but comes "
                "from the file including it; ros2 launch lets it in (its includes are not scoped)"
            )
        elif name in scope.leaked:
            self.warn(
                f"{element.where}: {name!r} ({value!r}) was set by {scope.leaked[name]}; "
                "ros2 launch lets it out (its includes are not scoped)"
            )

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

    # -- files and scopes ---------------------------------------------------------------------

    def resolve_file(
        self,
        path: Path,
        given: dict[str, str],
        parent: Scope | None,
        strict: bool = True,
        include: str | None = None,
        given_at: dict[str, str] | None = None,
    ) -> Scope:
        """Read one launch file with the ``given`` argument values, included from ``parent``
        (None: the file the user named) at file:line ``include``, each argument given at
        ``given_at[name]``. Returns the file's scope as it ends."""
        path = path.resolve()
        if path in self.include_chain:
            chain = " -> ".join(str(p) for p in [*self.include_chain, path])
            message = f"launch files include each other in a loop: {chain}"
            raise LaunchError(f"{include}: {message}" if include else message)
        is_python = path.name.endswith(".py")
        root = None if is_python else parse_file(path)
        fmt, why = ("ros2", "") if root is None else detect(root)
        # ros2 launch does not scope includes: an included ROS 2 file sees every launch
        # configuration of the file including it, and what it sets stays set after it.
        unscoped = parent is not None and parent.fmt == "ros2" and fmt == "ros2"
        if parent is None:
            scope = Scope(self, path, fmt, {}, given)
        elif unscoped:
            inherited = set(parent.args) - set(given)
            scope = parent.child(file=path, fmt=fmt, args={**parent.args, **given}, given=given,
                                 declared={}, inherited=inherited, leaked={})  # fmt: skip
        else:  # roslaunch: with pass_all_args every passed argument is usable, declared or not
            args = dict(given) if parent.pass_all else {}
            scope = parent.child(file=path, fmt=fmt, args=args, given=given, declared={},
                                 unset={}, inherited=set(), leaked={})  # fmt: skip
        if why.startswith("nothing"):  # a guess from the file name: say so where it matters
            scope.note = f" (read as {SYNTAX[fmt]} launch XML: {why})"
        self.include_chain.append(path)
        try:
            if root is None:  # the Python front-end (launch and launch_ros)
                self._resolve_python(path, scope, strict=strict and parent is None)
            else:  # (resolve_scope counts how deep groups and includes are nested)
                self._resolve_root(root, scope, strict and not unscoped, given_at)
        finally:
            self.include_chain.pop()
        if unscoped:
            assert parent is not None
            line = include.rpartition(":")[2] if include else ""
            where = f"{path.name} (included at line {line})" if include else path.name
            for name, value in scope.args.items():
                if name not in parent.args or parent.args[name] != value:
                    parent.args[name] = value
                    parent.inherited.discard(name)
                    if given.get(name) != value:  # not what the includer passed itself
                        parent.leaked[name] = where
        return scope

    def _resolve_python(self, path: Path, scope: Scope, strict: bool) -> None:
        from launcher.python_files import resolve_python_file

        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise LaunchError(f"{path}: includes nested more than {MAX_DEPTH} deep")
            resolve_python_file(path, scope, strict)
        finally:
            self.depth -= 1

    def _resolve_root(
        self, root: Element, scope: Scope, strict: bool, given_at: dict[str, str] | None
    ) -> None:
        """The <launch> of an XML or YAML file: its deprecation, its arguments, its entities."""
        path = scope.file
        _check(root, {"deprecated"})
        if "deprecated" in root.attrs:  # ros2 launch prints the file's own deprecation message
            self.warn(f"launch file [{path}] is deprecated: {root.attrs['deprecated']}")
        declared = {element.attrs.get("name") for element in _file_args(root)}
        unknown = sorted(set(scope.given) - declared)
        names = ", ".join(sorted(n for n in declared if n)) or "none"
        if unknown and strict and scope.fmt == "ros1":  # roslaunch: "unused args"
            if given_at and unknown[0] in given_at:  # an <include>'s <arg>: name its line
                raise LaunchError(
                    f"{given_at[unknown[0]]}: no argument named {', '.join(unknown)} is declared "
                    f"in {path.name} (declared: {names})"
                )
            raise LaunchError(
                f"{path}: no argument named {', '.join(unknown)} is declared (declared: {names})"
            )
        if scope.fmt == "ros2":  # ros2 launch sets every given argument as a configuration
            for name in unknown:
                scope.args.setdefault(name, scope.given[name])
        self.resolve_scope(root, scope)
        for name in unknown:  # a typo is worth a line where nothing reads the value
            named = given_at is not None and name in given_at  # by an <include>'s <arg>
            if name not in self.reads.get(path, set()) and (named or (strict and not given_at)):
                where = given_at[name] if given_at and named else str(path)
                self.warn(
                    f"{where}: {path.name} declares no argument {name!r} and does not read it "
                    f"(declared: {names})"
                )

    def resolve_scope(self, element: Element, scope: Scope) -> None:
        """The children of <launch> or <group>, one level deeper (a recursion is refused)."""
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise element.error(f"groups and includes nested more than {MAX_DEPTH} deep")
            self.resolve_children(element, scope, "launch")
        finally:
            self.depth -= 1

    def deferred(self, child: Element, parent: str) -> Any:
        """A child of a <group> or <timer> (``parent``) as a launch entity (launch._base
        .FrontendEntity) for the action holding it: when reached, it is checked and read by its
        tag's handler in the scope the action gives it."""
        from launch._base import FrontendEntity

        def handle(context: Any) -> None:
            scope = context.frontend_scope
            _check_tag(child, allowed_tags(scope.fmt, "launch"), scope, parent)
            if self.enabled(child, scope):
                TAGS[scope.fmt][child.tag].handler(self, child, scope)

        return FrontendEntity(handle, child.where)

    def run_nested(self, action: Any, element: Element, scope: Scope) -> None:
        """run() for an action that holds entities: one level deeper (a recursion is refused)."""
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise element.error(f"groups and includes nested more than {MAX_DEPTH} deep")
            self.run(action, element, scope)
        finally:
            self.depth -= 1

    def resolve_children(self, element: Element, scope: Scope, parent: str) -> None:
        """Each enabled child of ``element``, by the handler its format registered for its tag."""
        allowed = allowed_tags(scope.fmt, parent)
        for child in element.children:
            _check_tag(child, allowed, scope, element.tag)
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
        for (name, where), given in self.private_given.items():
            if not given:
                why = "no <node> follows it in its scope"
                _add_once(unreached.setdefault((where, why), []), "~" + name)
        if self.containers:
            self.warn(
                "component containers need rclcpp_components, which is not on PyPI; not "
                f"started: {'; '.join(describe_container(c) for c in self.containers)}"
            )
        if self.tests:
            self.warn(
                f"ignored {len(self.tests)} <test> (roslaunch leaves them to rostest; ROS 2 has "
                f"launch_testing): {', '.join(self.tests)}"
            )
        warnings = [
            f"{where}: param {', '.join(map(repr, names))} "
            f"{'is' if len(names) == 1 else 'are'} given to no node: {why}"
            for (where, why), names in unreached.items()
        ]
        return Launch(
            self.nodes, self.messages, self.warnings + warnings, self.steps, self.containers
        )

    def include(
        self,
        path: Path,
        given: dict[str, str],
        scope: Any,
        where: str | None = None,
        given_at: dict[str, str] | None = None,
    ) -> None:
        """PlanSink.include: IncludeLaunchDescription's file (any format), included at
        ``where``; ``given_at``: where each argument was given (a front-end's <arg> lines,
        checked and named in warnings as roslaunch and launch_xml users expect them)."""
        self.resolve_file(path, given, scope, given_at is not None, where, given_at)

    def add_container(self, container: ContainerDecl) -> None:
        """PlanSink.add_container: planned and shown, not started (see finish())."""
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

    def flag(self, element: Element, name: str, scope: Scope) -> bool:
        return to_bool(self.text(element, name, scope, "false"), element, f"{name!r}")

    def number(self, element: Element, name: str, scope: Scope, kind: type = float) -> Any:
        """A ROS 1 attribute's number, by the rule ExecuteProcess's front-end parse keeps."""
        from launch.actions import number_check

        text = number_check(name, kind)(self.text(element, name, scope, ""), element)
        return kind(text) if text else None

    def clear_params(self, element: Element, scope: Scope) -> None:
        """roslaunch's clear_params: checked as roslaunch checks it, and otherwise nothing to do:
        a ROS 2 node's parameters start empty (there is no parameter server to clear)."""
        if self.flag(element, "clear_params", scope):
            where = "name" if element.tag == "node" else "ns"
            if where not in element.attrs:
                raise element.error(f"clear_params on <{element.tag}> needs a '{where}'")

    def enabled(self, element: Element, scope: Scope) -> bool:
        if "if" in element.attrs:
            return to_bool(self.text(element, "if", scope), element, "'if'")
        if "unless" in element.attrs:
            return not to_bool(self.text(element, "unless", scope), element, "'unless'")
        return True

    def namespace(self, element: Element, name: str, scope: Scope) -> str:
        value = self.text(element, name, scope)
        full = namespace_under(scope.namespace, value)
        if full is None:
            raise element.error(f"invalid namespace {value!r}")
        return full

    def run(self, action: Any, element: Element, scope: Scope) -> None:
        """Execute a launch action (launch/, launch_ros/) in ``scope``: what the tag does is
        the action's one definition; its handler here only reads the attributes."""
        from launch._base import LaunchContext

        action.where = element.where
        LaunchContext(scope, self, self.launch_state()).visit(action)

    def launch_state(self) -> Any:
        """The launch model's executor state, one for the whole launch (every format)."""
        if self.python_state is None:
            from launch._base import LaunchState

            self.python_state = LaunchState()
        return self.python_state

    # -- tags: arguments, scopes, includes ----------------------------------------------------

    @tag("ros1", "arg", {"name", "default", "value", "doc"}, marks={"value", "doc"})
    @tag("ros2", "arg", {"name", "default", "description"}, marks={"description"})
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
            _check_tag(child, {"choice": {"value"}}, scope, "arg")
        # A fixed value cannot be set from outside, except by pass_all_args, which it overrides
        # (roslaunch's own tests load such files).
        if fixed and name in scope.given and not scope.pass_all:
            raise element.error(f"argument {name!r} has a fixed value and cannot be set")
        if scope.fmt == "ros2":
            self.declare(element, scope, name)
            return
        if fixed:
            value = self.text(element, "value", scope)
        elif name in scope.given:
            value = scope.given[name]
        elif "default" in element.attrs:
            value = self.text(element, "default", scope)
        else:  # roslaunch fails only where such an argument is used
            scope.unset[name] = element.line
            return
        choices = [self.text(child, "value", scope) for child in element.children]
        if choices and value not in choices:
            raise element.error(f"argument {name!r} is {value!r}; choose one of {choices}")
        scope.args[name] = value

    def declare(self, element: Element, scope: Scope, name: str) -> None:
        """A ROS 2 <arg>: DeclareLaunchArgument, its default performed only if no value was
        given or set before (ros2 launch keeps a value set before, even one let in from the
        including file, which is said once, here)."""
        if name in scope.given:
            scope.args[name] = scope.given[name]
        elif name in scope.inherited and name in scope.args:
            scope.inherited.discard(name)  # not again where it is read
            self.warn(
                f"{element.where}: argument {name!r} is {scope.args[name]!r}, the value of the "
                "file including this one (not passed to it), not its default; ros2 launch lets "
                "it in (its includes are not scoped)"
            )
        self.run(self.parse(element), element, scope)

    @tag("ros2", "let", {"name", "value"})
    @tag("ros2", "log", {"message", "level"})
    @tag("ros2", "set_env", {"name", "value"})
    @tag("ros2", "unset_env", {"name"})
    @tag("ros2", "append_env", {"name", "value", "prepend", "separator"})
    @tag("ros2", "push_ros_namespace", {"namespace"})
    @tag("ros2", "set_remap", {"from", "to"})
    def on_exposed(self, element: Element, scope: Scope) -> None:
        """A tag whose action is built by the parse method the action exposed for it
        (launch.frontend, as ros2/launch's @expose_action): its one definition."""
        self.run(self.parse(element), element, scope)

    def parse(self, element: Element) -> Any:
        """``element``'s action, as launch.frontend's Parser builds it (if/unless were read
        already: enabled()); the entities it holds are read when the action reaches them."""
        from launch_xml import Entity

        action = _launch_parser()(self, element.tag).build(Entity(element))
        action.condition = None
        return action

    @tag("ros1", "group", {"ns", "clear_params"}, marks={"ns", "clear_params"})
    def on_ros1_group(self, element: Element, scope: Scope) -> None:
        self.clear_params(element, scope)
        ns = self.namespace(element, "ns", scope) if "ns" in element.attrs else scope.namespace
        self.resolve_scope(element, scope.child(namespace=ns))

    @tag("ros2", "group", {"scoped", "forwarding"}, marks={"scoped", "forwarding"})
    @tag("ros2", "timer", {"period"})
    def on_nested(self, element: Element, scope: Scope) -> None:
        """GroupAction and TimerAction, built by their parse methods, one level deeper (a
        group's <keep>s are its parse method's; the other children are read when reached)."""
        for child in element.children:
            if element.tag == "group" and child.tag == "keep":
                _check_tag(child, {"keep": {"name", "value"}}, scope, "group")
        self.run_nested(self.parse(element), element, scope)

    @tag("ros1", "include", {"file", "ns", "pass_all_args", "clear_params"},
         marks={"ns", "pass_all_args", "clear_params"})  # fmt: skip
    def on_ros1_include(self, element: Element, scope: Scope) -> None:
        """roslaunch's <include>: a scope of its own (namespace, <env>), the included file
        seeing only the arguments passed to it (all of them with pass_all_args)."""
        path = Path(self.text(element, "file", scope))
        if not path.is_absolute():  # relative to the including file, not the current directory
            path = scope.file.parent / path
        pass_all = self.flag(element, "pass_all_args", scope)
        self.clear_params(element, scope)
        given = dict(scope.args) if pass_all else {}
        given_at: dict[str, str] = {}
        inner = scope.child(pass_all=pass_all)  # what the included file starts with
        allowed = {"arg": {"name", "value"}, "env": {"name", "value"}}
        for child in element.children:
            _check_tag(child, allowed, scope, "include")
            if not self.enabled(child, scope):
                continue
            if child.tag == "env":  # roslaunch: an <env> in <include> is for the included nodes
                self.on_env(child, inner)
                continue
            name = self.text(child, "name", scope)
            given[name] = self.text(child, "value", scope)
            given_at.setdefault(name, child.where)
        if "ns" in element.attrs:
            inner.namespace = self.namespace(element, "ns", scope)
        if not path.is_file():
            raise element.error(f"included file {path} does not exist")
        self.resolve_file(path, given, inner, not pass_all, element.where, given_at)

    @tag("ros2", "include", {"file"})
    def on_ros2_include(self, element: Element, scope: Scope) -> None:
        """IncludeLaunchDescription: its file and each <arg name value> performed when it
        executes (ros2 launch does not scope an include: see resolve_file)."""
        arguments_at = {}
        for child in element.children:
            _check_tag(child, {"arg": {"name", "value"}}, scope, "include")
            arguments_at.setdefault(child.attrs.get("name", ""), child.where)
        action = self.parse(element)
        action.arguments_at = arguments_at
        self.run(action, element, scope)

    # -- tags: what applies to nodes, in a scope or inside one <node> --------------------------

    @tag("ros1", "remap", {"from", "to"}, under={"launch", "node"})
    def on_remap(self, element: Element, scope: Scope) -> None:
        names = []
        for side in ("from", "to"):
            written = name = self.text(element, side, scope)
            if name.startswith("~") and not name.startswith("~/"):
                name = "~/" + name[1:]  # ROS 1's private ~name is ~/name in ROS 2
            if remap_problem(name, side):
                raise element.error(remap_problem(written, side) or "")
            names.append(name)
        # roslaunch: a later remap of the same name replaces the earlier
        scope.remaps[:] = [remap for remap in scope.remaps if remap[0] != names[0]]
        scope.remaps.append((names[0], names[1]))

    @tag("ros1", "env", {"name", "value"}, under={"launch", "node"})
    @tag("ros2", "env", {"name", "value"}, under={"node", "executable"})
    def on_env(self, element: Element, scope: Scope) -> None:
        from launch.actions import SetEnvironmentVariable

        name, value = self.text(element, "name", scope), self.text(element, "value", scope)
        self.run(SetEnvironmentVariable(name, value), element, scope)

    @tag("ros2", "reset", set())
    def on_reset(self, element: Element, scope: Scope) -> None:
        """ResetLaunchConfigurations, built by its parse (its <keep>s checked here first)."""
        for child in element.children:
            _check_tag(child, {"keep": {"name", "value"}}, scope, "reset")
        self.on_exposed(element, scope)

    @tag("ros2", "set_parameter", {"name", "value"})
    def on_set_parameter(self, element: Element, scope: Scope) -> None:
        """SetParameter, for the nodes after it in its scope (said if none receives it)."""
        self.on_exposed(element, scope)
        self.set_parameters.append((scope.params[-1], element.where))

    @tag("ros2", "param", PARAM_ATTRS, under={"node", "composable_node"}, marks={"value_sep"})
    @tag("ros2", "remap", {"from", "to"}, under={"node", "composable_node"})
    def on_node_part(self, element: Element, scope: Scope) -> None:
        """Read by Node.parse and ComposableNode.parse into their parameters and remappings."""

    # ROS 1 parameters go to the parameter server, under the namespace of their scope (inside
    # <node>: the node's private namespace).

    @tag("ros1", "param", {"name", "value", "type", "textfile", "binfile", "command"},
         under={"launch", "node"}, marks={"textfile", "binfile"})  # fmt: skip
    def on_ros1_param(self, element: Element, scope: Scope) -> None:
        name = self.text(element, "name", scope)
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
            path = Path(self.text(element, "textfile", scope))
            try:
                value: Any = read_text(path if path.is_absolute() else scope.file.parent / path)
            except InputError as error:
                raise element.error(str(error)) from None
        elif "command" in element.attrs:  # roslaunch: what the program prints, typed
            command = self.text(element, "command", scope)
            if not scope.allow_code:
                raise CodeRefused(f"{element.where}: <param command={command!r}> runs a program")
            shown = f"<param command={command!r}>"
            text = run_command(command, element.error, shown)
            value = _typed_value(text, element.attrs.get("type"), element)
        else:
            text = self.text(element, "value", scope)
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
        command = self.text(element, "command", scope, "load")
        if command not in ("load", "delete", "dump"):
            raise element.error(f"<rosparam command={command!r}>: use load, delete or dump")
        namespace = scope.namespace
        if "ns" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "ns", scope))
        if "param" in element.attrs:
            namespace = join_namespace(namespace, self.text(element, "param", scope))
        if command == "dump":  # roslaunch wrote the parameter server to a file at the start
            self.warn(
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
            self.warn(
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

    # -- tags: processes ----------------------------------------------------------------------

    @tag("ros2", "node_container", {"pkg", "exec", "name", "namespace", "args", "output"},
         marks={"exec", "namespace"})  # fmt: skip
    @tag("ros2", "load_composable_node", {"target"})
    def on_container(self, element: Element, scope: Scope) -> None:
        """ComposableNodeContainer with its components, or LoadComposableNodes for a container
        (``target``), built by their parse methods."""
        for child in element.children:
            _check_tag(child, allowed_tags("ros2", "node_container"), scope, element.tag)
            self.check_children(child, scope)
        self.run(self.parse(element), element, scope)

    @tag(
        "ros2", "composable_node", {"pkg", "plugin", "name", "namespace"}, under={"node_container"}
    )
    @tag("ros2", "extra_arg", {"name", "value"}, under={"composable_node"})
    def on_component_part(self, element: Element, scope: Scope) -> None:
        """Read by ComposableNode.parse (its container's parse method)."""

    @tag("ros1", "test", {"pkg", "type", "name", "test_name", "args", "ns", "clear_params",
                          "cwd", "launch_prefix", "retry", "time_limit"})  # fmt: skip
    def on_test(self, element: Element, scope: Scope) -> None:
        """roslaunch skips <test> (rostest runs it): said in one line at the end."""
        name = element.attrs.get("test_name") or element.attrs.get("name") or "<test>"
        self.tests.append(f"{name} ({element.where})")

    @tag("ros2", "node", {"pkg", "exec", "name", "namespace", "ros_args", "exec_name"}
         | PROCESS_ATTRS,
         marks={"exec", "namespace", "ros_args"})  # fmt: skip
    @tag("ros2", "executable", {"cmd", "name", "cwd"} | PROCESS_ATTRS)
    def on_ros2_process(self, element: Element, scope: Scope) -> None:
        """launch_ros's Node or launch's ExecuteProcess, built by their parse methods (their
        <param>, <remap> and <env> children read into the action), in a scope of its own."""
        self.check_children(element, scope)
        self.run(self.parse(element), element, scope.child(in_node=True))

    def check_children(self, element: Element, scope: Scope) -> None:
        """The children a <node>, <executable> or <composable_node> may hold, and the
        <param>s a group of parameters holds (their parse methods read them)."""
        for child in element.children:
            _check_tag(child, allowed_tags("ros2", element.tag), scope, element.tag)
            if child.tag == "param":
                self.check_param_group(child, scope)

    def check_param_group(self, element: Element, scope: Scope) -> None:
        for child in element.children:
            _check_tag(child, {"param": PARAM_ATTRS - {"from"}}, scope, "param")
            self.check_param_group(child, scope)

    @tag("ros1", "node", {"pkg", "type", "name", "ns", "args", "output", "respawn", "respawn_delay",
                          "required", "launch_prefix", "clear_params"},
         marks={"type", "ns", "clear_params"})  # fmt: skip
    def on_ros1_node(self, element: Element, scope: Scope) -> None:
        """roslaunch's <node>: launch_ros's Node in the node's private scope (where its
        <param>s go, to the parameter server; its parameters are given in finish())."""
        self.clear_params(element, scope)
        package = self.text(element, "pkg", scope)
        executable = self.text(element, "type", scope)
        for attr, value in (("pkg", package), ("type", executable)):
            if not value.strip():
                raise element.error(f"<node {attr}> is empty")
        name = self.text(element, "name", scope)  # a ROS 1 node must be named
        if not valid_name(name):
            raise element.error(f"invalid node name {name!r}")
        namespace = scope.namespace
        if "ns" in element.attrs:
            namespace = self.namespace(element, "ns", scope)
        args = self.words(element, "args", scope)
        output = self.text(element, "output", scope, "log")
        if output not in ("screen", "log"):
            raise element.error(f"output={output!r}; use one of screen, log")
        respawn = self.flag(element, "respawn", scope)
        respawn_delay = self.number(element, "respawn_delay", scope) or 0.0
        launch_prefix = self.words(element, "launch_prefix", scope)
        required = self.flag(element, "required", scope)
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
        self.resolve_children(element, node_scope, element.tag)
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
        self.run(action, element, node_scope)
        self.ros1_nodes.append(self.nodes[-1])


def resolve(path: Path, args: dict[str, str], options: Options | None = None) -> Launch:
    """Read a launch file (and what it includes) with the given argument values."""
    resolver = Resolver(options or Options())
    resolver.resolve_file(path, args, None)
    return resolver.finish()
