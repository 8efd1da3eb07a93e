"""Loading launch files: the file the user named and every file it includes, in any format.

Each file is read in its scope (launcher/scope.py): an XML or YAML file is parsed
(launch_foundation.parse), its format detected (launcher/tags.py), and each of its tags read by
the handler its format's front-end registered (launcher/ros1.py: roslaunch's rules;
launcher/ros2_markup.py: ROS 2's XML and YAML, whose tags the model's actions parse); a Python
file runs through launcher/python_files.py. Executing the model's actions hands every result to
one ``LaunchPlan`` (launcher/sink.py). Includes: a ROS 1 ``<include>`` is a scope of its own
(the included file sees only what is passed to it); a ROS 2 include is not scoped, as in ros2
launch (``resolve_file`` says where a value crossed one). A loop of includes, or groups and
includes nested deeper than MAX_DEPTH, is refused.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launch_foundation.declarations import ArgInfo, Launch
from launch_foundation.errors import LaunchError
from launch_foundation.parse import Element, parse_file
from launcher import ros1, ros2_markup
from launcher.attributes import enabled
from launcher.scope import Options, Scope
from launcher.sink import LaunchPlan
from launcher.tags import (
    SYNTAX,
    TAGS,
    allowed_tags,
    check_attributes,
    check_tag,
    detect,
    detect_format,
    file_args,
)

# Groups and includes nested deeper than this are refused (a recursion, not a real file).
MAX_DEPTH = 50


def describe_args(path: Path) -> list[ArgInfo]:
    """The arguments a launch file declares, for --show-args (nothing is resolved)."""
    if path.name.endswith(".py"):
        from launcher.python_files import describe_python_args

        return describe_python_args(path)
    root = parse_file(path)
    fmt = detect_format(root)
    infos = []
    for element in file_args(root):
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


class Loader:
    """Reads the files of one launch into its LaunchPlan. One per launch."""

    def __init__(self, options: Options) -> None:
        self.options = options
        self.plan = LaunchPlan(self.resolve_file)
        self.front_ends = {"ros1": ros1.Ros1Loader(self), "ros2": ros2_markup.Ros2Markup(self)}
        self.python_state: Any = None  # the launch model's own state (launch_state())
        self.include_chain: list[Path] = []
        self.depth = 0  # nested groups and includes
        self.reads: dict[Path, set[str]] = {}  # the arguments each file reads

    def warn(self, text: str) -> None:
        self.plan.warn(text)

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
        self.plan.charge(size, where)

    def anon(self, name: str) -> str:
        return self.plan.anon(name)

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
        check_attributes(root, {"deprecated"})
        if "deprecated" in root.attrs:  # ros2 launch prints the file's own deprecation message
            self.warn(f"launch file [{path}] is deprecated: {root.attrs['deprecated']}")
        declared = {element.attrs.get("name") for element in file_args(root)}
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
            check_tag(child, allowed_tags(scope.fmt, "launch"), scope, parent)
            if enabled(child, scope):
                self.dispatch(child, scope)

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
            check_tag(child, allowed, scope, element.tag)
            if enabled(child, scope):
                self.dispatch(child, scope)

    def dispatch(self, child: Element, scope: Scope) -> None:
        """``child``, enabled, read by the handler its format's front-end registered."""
        TAGS[scope.fmt][child.tag].handler(self.front_ends[scope.fmt], child, scope)

    def finish(self) -> Launch:
        """The launch: the front-ends' closing passes (the ROS 1 parameter server), then the
        parameters no node receives, one warning for each place that wrote them."""
        unreached: dict[tuple[str, str], list[str]] = {}  # (where, why) -> names
        for front_end in self.front_ends.values():
            front_end.finish(unreached)
        warnings = [
            f"{where}: param {', '.join(map(repr, names))} "
            f"{'is' if len(names) == 1 else 'are'} given to no node: {why}"
            for (where, why), names in unreached.items()
        ]
        return self.plan.launch(warnings)

    def run(self, action: Any, element: Element, scope: Scope, sink: Any = None) -> None:
        """Execute a launch action (launch/, launch_ros/) in ``scope``: what the tag does is
        the action's one definition; its handler only reads the attributes. ``sink``: another
        PlanSink than the launch's (a Recording of it)."""
        from launch.launch_context import LaunchContext

        action.where = element.where
        LaunchContext(scope, sink or self.plan, self.launch_state()).visit(action)

    def context(self, scope: Scope) -> Any:
        """A launch context of ``scope``, for a front-end's text performed outside an action."""
        from launch.launch_context import LaunchContext

        return LaunchContext(scope, self.plan, self.launch_state())

    def launch_state(self) -> Any:
        """The launch model's executor state, one for the whole launch (every format)."""
        if self.python_state is None:
            from launch.launch_context import LaunchState

            self.python_state = LaunchState()
        return self.python_state


def resolve(path: Path, args: dict[str, str], options: Options | None = None) -> Launch:
    """Read a launch file (and what it includes) with the given argument values."""
    loader = Loader(options or Options())
    loader.resolve_file(path, args, None)
    return loader.finish()
