"""ROS 2's XML and YAML (launch_xml, launch_yaml) as the launcher reads them: each tag checked
where it stands (its ``@tag`` line: its attributes, the places it may stand, the signs of its
format), then built by the parse method its action exposed (launch.frontend, as ros2/launch's
``@expose_action``) and executed in the file's scope: what a tag does is its action's one
definition, in launch/ and launch_ros/. The entities an action holds (a ``<group>``'s, a
``<timer>``'s children) are read when the action reaches them.
"""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING, Any

from launch_foundation.parse import Element
from launcher import attributes as read
from launcher.scope import Scope
from launcher.sink import note_unreached
from launcher.tags import PROCESS_ATTRS, allowed_tags, check_tag, tag

if TYPE_CHECKING:
    from launcher.loading import Loader

PARAM_ATTRS = frozenset({"name", "value", "from", "type", "value_sep", "allow_substs"})


@cache
def _launch_parser() -> type:
    """launch.frontend's Parser for the launcher: the entities an action holds (a <group>'s,
    a <timer>'s children) are read when the action reaches them, in its scope and by the
    tag's handler of the file's format (Loader.deferred). Made at its first use: launch_xml
    brings in the whole launch model, which a file without ROS 2 actions never needs, and its
    import was a third of the launcher's start before its first process."""
    from launch_xml import Parser

    class LaunchParser(Parser):
        def __init__(self, loader: Loader, parent: str) -> None:
            self.loader, self.parent = loader, parent

        def parse_action(self, entity: Any) -> Any:
            return self.loader.deferred(entity.element, self.parent)

    return LaunchParser


class Ros2Markup:
    """The handlers of ROS 2's markup tags. One per launch."""

    def __init__(self, loader: Loader) -> None:
        self.loader = loader
        # Each <set_parameter>'s entry, to tell whether a node after it received it.
        self.set_parameters: list[tuple[tuple[str, Any], str]] = []

    def finish(self, unreached: dict[tuple[str, str], list[str]]) -> None:
        """The <set_parameter>s no node after them received, into ``unreached``."""
        nodes = self.loader.plan.nodes
        for entry, where in self.set_parameters:
            if not any(param is entry for node in nodes for param in node.params):
                note_unreached(unreached, where, "no <node> follows it in its scope", entry[0])

    @tag("ros2", "arg", {"name", "default", "description"}, marks={"description"})
    def on_arg(self, element: Element, scope: Scope) -> None:
        """DeclareLaunchArgument, its default performed only if no value was given or set
        before (ros2 launch keeps a value set before, even one let in from the including file,
        which is said once, here)."""
        name = read.text(element, "name", scope)
        scope.declared[name] = element.line
        for child in element.children:
            check_tag(child, {"choice": {"value"}}, scope, "arg")
        if name in scope.given:
            scope.args[name] = scope.given[name]
        elif name in scope.inherited and name in scope.args:
            scope.inherited.discard(name)  # not again where it is read
            self.loader.warn(
                f"{element.where}: argument {name!r} is {scope.args[name]!r}, the value of the "
                "file including this one (not passed to it), not its default; ros2 launch lets "
                "it in (its includes are not scoped)"
            )
        self.loader.run(self.parse(element), element, scope)

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
        self.loader.run(self.parse(element), element, scope)

    def parse(self, element: Element) -> Any:
        """``element``'s action, as launch.frontend's Parser builds it (if/unless were read
        already: enabled()); the entities it holds are read when the action reaches them."""
        from launch_xml import Entity

        action = _launch_parser()(self.loader, element.tag).build(Entity(element))
        action.condition = None
        return action

    @tag("ros2", "group", {"scoped", "forwarding"}, marks={"scoped", "forwarding"})
    @tag("ros2", "timer", {"period"})
    def on_nested(self, element: Element, scope: Scope) -> None:
        """GroupAction and TimerAction, built by their parse methods, one level deeper (a
        group's <keep>s are its parse method's; the other children are read when reached)."""
        for child in element.children:
            if element.tag == "group" and child.tag == "keep":
                check_tag(child, {"keep": {"name", "value"}}, scope, "group")
        self.loader.run_nested(self.parse(element), element, scope)

    @tag("ros2", "include", {"file"})
    def on_ros2_include(self, element: Element, scope: Scope) -> None:
        """IncludeLaunchDescription: its file and each <arg name value> performed when it
        executes (ros2 launch does not scope an include: see resolve_file)."""
        arguments_at = {}
        for child in element.children:
            check_tag(child, {"arg": {"name", "value"}}, scope, "include")
            arguments_at.setdefault(child.attrs.get("name", ""), child.where)
        action = self.parse(element)
        action.arguments_at = arguments_at
        self.loader.run(action, element, scope)

    @tag("ros2", "env", {"name", "value"}, under={"node", "executable"})
    def on_env(self, element: Element, scope: Scope) -> None:
        """Read by Node.parse and ExecuteProcess.parse into the process's environment."""

    @tag("ros2", "reset", set())
    def on_reset(self, element: Element, scope: Scope) -> None:
        """ResetLaunchConfigurations, built by its parse (its <keep>s checked here first)."""
        for child in element.children:
            check_tag(child, {"keep": {"name", "value"}}, scope, "reset")
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

    @tag("ros2", "node_container", {"pkg", "exec", "name", "namespace", "args", "output"},
         marks={"exec", "namespace"})  # fmt: skip
    @tag("ros2", "load_composable_node", {"target"})
    def on_container(self, element: Element, scope: Scope) -> None:
        """ComposableNodeContainer with its components, or LoadComposableNodes for a container
        (``target``), built by their parse methods."""
        for child in element.children:
            check_tag(child, allowed_tags("ros2", "node_container"), scope, element.tag)
            self.check_children(child, scope)
        self.loader.run(self.parse(element), element, scope)

    @tag(
        "ros2", "composable_node", {"pkg", "plugin", "name", "namespace"}, under={"node_container"}
    )
    @tag("ros2", "extra_arg", {"name", "value"}, under={"composable_node"})
    def on_component_part(self, element: Element, scope: Scope) -> None:
        """Read by ComposableNode.parse (its container's parse method)."""

    @tag("ros2", "node", {"pkg", "exec", "name", "namespace", "ros_args", "exec_name"}
         | PROCESS_ATTRS,
         marks={"exec", "namespace", "ros_args"})  # fmt: skip
    @tag("ros2", "executable", {"cmd", "name", "cwd"} | PROCESS_ATTRS)
    def on_ros2_process(self, element: Element, scope: Scope) -> None:
        """launch_ros's Node or launch's ExecuteProcess, built by their parse methods (their
        <param>, <remap> and <env> children read into the action), in a scope of its own."""
        self.check_children(element, scope)
        self.loader.run(self.parse(element), element, scope.child(in_node=True))

    def check_children(self, element: Element, scope: Scope) -> None:
        """The children a <node>, <executable> or <composable_node> may hold, and the
        <param>s a group of parameters holds (their parse methods read them)."""
        for child in element.children:
            check_tag(child, allowed_tags("ros2", element.tag), scope, element.tag)
            if child.tag == "param":
                self.check_param_group(child, scope)

    def check_param_group(self, element: Element, scope: Scope) -> None:
        for child in element.children:
            check_tag(child, {"param": PARAM_ATTRS - {"from"}}, scope, "param")
            self.check_param_group(child, scope)
