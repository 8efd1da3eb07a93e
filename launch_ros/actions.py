"""launch_ros.actions: Node, and what applies to the nodes after it in its scope."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launch._base import Action, caller_where, normalize, perform
from launch._missing import module_getattr
from launch.actions import ExecuteProcess, NameValueAction, command_words, frontend_attr
from launch.frontend.expose import expose_action
from launch.launch_context import LaunchContext
from launch_foundation.declarations import ComponentDecl, ContainerDecl, NodeDecl
from launch_foundation.errors import LaunchError
from launch_foundation.naming import join_namespace, namespace_under, remap_problem, valid_name
from launch_ros.utilities import (
    frontend_node_parts,
    node_parameters,
    node_remaps,
    parameter_value,
    params_file_checked,
    relative_namespace,
)
from ros_tutorials_common.bounded import parameter_problem

__all__ = [
    "ComposableNodeContainer", "LifecycleNode", "LoadComposableNodes", "Node",
    "PushROSNamespace", "PushRosNamespace", "SetParameter", "SetParametersFromFile", "SetRemap",
]  # fmt: skip


@expose_action("node")
class Node(ExecuteProcess):
    """A ROS node of a package: its name, namespace, parameters, remaps and arguments become
    the standard ROS arguments (launcher/plan.py)."""

    def __init__(
        self,
        *,
        executable: Any,
        package: Any = None,
        name: Any = None,
        namespace: Any = None,
        exec_name: Any = None,
        parameters: Any = None,
        remappings: Any = None,
        ros_arguments: Any = None,
        arguments: Any = None,
        **kwargs: Any,
    ) -> None:
        super().__init__(cmd=["<node>"], name=exec_name, **kwargs)
        self.package, self.executable = package, executable
        self.node_name, self.node_namespace = name, namespace
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.ros_arguments = list(normalize(ros_arguments)) if ros_arguments else []
        self.arguments = list(arguments or [])

    @classmethod
    def parse(cls, entity: Any, parser: Any, ignore: Any = ()) -> tuple[type, dict[str, Any]]:
        """<node>: what <executable> has (ExecuteProcess.parse) but its command, and the
        node's own attributes; its <param>s and <remap>s are its parameters and remappings."""
        from launch.frontend.frontend_text import FrontendWords, split_words

        _, kwargs = super().parse(entity, parser, ignore=("cmd",))
        kwargs["package"] = frontend_attr(entity, "pkg", _not_blank("pkg"), optional=False)
        kwargs["executable"] = frontend_attr(entity, "exec", _not_blank("exec"), optional=False)
        for attr in ("name", "namespace", "exec_name"):
            value = frontend_attr(entity, attr)
            if value is not None:
                kwargs[attr] = value
        for attr, key in (("args", "arguments"), ("ros_args", "ros_arguments")):
            value = frontend_attr(entity, attr, split_words(attr), FrontendWords)
            if value is not None:
                kwargs[key] = [value]
        kwargs["parameters"], kwargs["remappings"] = frontend_node_parts(entity)
        return cls, kwargs

    def process_decl(self, context: LaunchContext) -> NodeDecl:
        if self.package is None:
            raise self.error("Node needs a package= here (a program by path: ExecuteProcess)")
        name = perform(self.node_name, context) if self.node_name is not None else None
        if name is not None and not valid_name(name):
            raise self.error(f"invalid node name {name!r}")
        namespace = context.ros_namespace
        if self.node_namespace is not None:
            namespace = relative_namespace(self, namespace, context)
        remaps = node_remaps(self, self.remappings, context)
        params, files = node_parameters(self, self.parameters, context)
        decl = NodeDecl(
            self.where,
            package=perform(self.package, context),
            executable=perform(self.executable, context),
            name=name,
            namespace=namespace,
            args=command_words(self.arguments, context),
            ros_args=command_words(self.ros_arguments, context),
            remaps=remaps,
            params=params,
            params_files=files,
        )
        self.fill(decl, context)
        if self.name is not None:  # exec_name: the output prefix
            decl.label = perform(self.name, context) or decl.label
        return decl


class LifecycleNode(Node):
    """launch_ros's LifecycleNode: a managed node, planned and started as a Node (it starts
    unconfigured, as under ros2 launch until something asks it to change state, through its
    ``<node>/change_state`` service); its name and namespace are required keywords, as
    launch_ros jazzy requires them. The launcher hosts no ROS node, so it makes no such call
    itself: a launch file's EmitEvent(ChangeState) is refused with one line."""

    def __init__(self, *, name: Any, namespace: Any, **kwargs: Any) -> None:
        super().__init__(name=name, namespace=namespace, **kwargs)


def _not_blank(attr: str) -> Any:
    def check(text: str, element: Any) -> str:
        if not text.strip():
            raise element.error(f"<node {attr}> is empty")
        return text

    return check


@expose_action("node_container")
class ComposableNodeContainer(Node):
    """A component container with its components: planned and shown (--print); not started,
    as rclcpp_components is not on PyPI (the launch says so in one line)."""

    @classmethod
    def parse(cls, entity: Any, parser: Any, ignore: Any = ()) -> tuple[type, dict[str, Any]]:
        """<node_container>: a <node> with its <composable_node>s."""
        _, kwargs = super().parse(entity, parser)
        kwargs.setdefault("namespace", "")
        kwargs["composable_node_descriptions"] = _parse_components(entity, parser)
        return cls, kwargs

    def __init__(self, *, name: Any, namespace: Any, composable_node_descriptions: Any = None,
                 **kwargs: Any) -> None:  # fmt: skip
        kwargs.setdefault("package", "rclcpp_components")
        kwargs.setdefault("executable", "component_container")
        super().__init__(name=name, namespace=namespace, **kwargs)
        self.composable_node_descriptions = list(composable_node_descriptions or [])

    def execute(self, context: LaunchContext) -> None:
        name = perform(self.node_name, context)
        namespace = relative_namespace(self, context.ros_namespace, context)
        container = ContainerDecl(
            self.where,
            join_namespace(namespace, name),
            perform(self.package, context),
            perform(self.executable, context),
        )
        # a component's namespace is relative to the pushed one, not to its container's
        nodes = self.composable_node_descriptions
        container.components = _components(nodes, context, context.ros_namespace)
        context.sink.add_container(container)


@expose_action("load_composable_node")
class LoadComposableNodes(Action):
    """Components for a container (``target_container``: its action or its name)."""

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        """<load_composable_node target=...> with its <composable_node>s."""
        _, kwargs = super().parse(entity, parser)
        kwargs["target_container"] = frontend_attr(entity, "target", optional=False)
        kwargs["composable_node_descriptions"] = _parse_components(entity, parser)
        return cls, kwargs

    def __init__(self, *, composable_node_descriptions: Any, target_container: Any,
                 **kwargs: Any) -> None:  # fmt: skip
        super().__init__(**kwargs)
        self.composable_node_descriptions = list(composable_node_descriptions)
        self.target_container = target_container

    def execute(self, context: LaunchContext) -> None:
        target = self.target_container
        if isinstance(target, ComposableNodeContainer):
            base = relative_namespace(target, context.ros_namespace, context)
            name = join_namespace(base, perform(target.node_name, context))
        else:
            name = join_namespace(context.ros_namespace, perform(target, context))
        container = ContainerDecl(self.where, name)
        nodes = self.composable_node_descriptions
        container.components = _components(nodes, context, context.ros_namespace)
        context.sink.add_container(container)


def _parse_components(entity: Any, parser: Any) -> list[Any]:
    """The <composable_node>s of a front-end's container tag, each by ComposableNode.parse."""
    from launch.frontend.entity import Entity
    from launch_ros.descriptions import ComposableNode

    found = []
    for item in entity.get_attr("composable_node", data_type=list[Entity], optional=True) or []:
        node_type, kwargs = ComposableNode.parse(parser, item)
        node = node_type(**kwargs)
        node.where = item.where
        found.append(node)
    return found


def _components(nodes: list[Any], context: LaunchContext, namespace: str) -> list[ComponentDecl]:
    from launch_ros.descriptions import ComposableNode

    found = []
    for node in nodes:
        if not isinstance(node, ComposableNode):
            raise LaunchError(f"{caller_where()}: {type(node).__name__} is not a ComposableNode")
        if node.condition is None or node.condition.evaluate(context):
            found.append(node.component_decl(context, namespace))
    return found


@expose_action("push_ros_namespace")
class PushRosNamespace(Action):
    def __init__(self, namespace: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.namespace = namespace

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["namespace"] = parser.parse_substitution(entity.get_attr("namespace"))
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        value = perform(self.namespace, context)
        full = namespace_under(context.ros_namespace, value)
        if full is None:
            raise self.error(f"invalid namespace {value!r}")
        context.ros_namespace = full


PushROSNamespace = PushRosNamespace


@expose_action("set_parameter")
class SetParameter(NameValueAction):
    def execute(self, context: LaunchContext) -> None:
        name = perform(self.name, context)
        value = parameter_value(self.value, context, self.where)
        problem = parameter_problem(name, value)
        if problem:
            raise self.error(problem)
        context.ros_params.append((name, value))


class SetParametersFromFile(Action):
    def __init__(self, filename: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.filename = filename

    def execute(self, context: LaunchContext) -> None:
        path = Path(perform(self.filename, context))
        context.ros_params_files.append(str(params_file_checked(path, self.where, context)))


@expose_action("set_remap")
class SetRemap(Action):
    def __init__(self, src: Any, dst: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.src, self.dst = src, dst

    @classmethod
    def parse(cls, entity: Any, parser: Any) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs["src"] = parser.parse_substitution(entity.get_attr("from"))
        kwargs["dst"] = parser.parse_substitution(entity.get_attr("to"))
        return cls, kwargs

    def execute(self, context: LaunchContext) -> None:
        pair = (perform(self.src, context), perform(self.dst, context))
        for name, side in zip(pair, ("from", "to"), strict=True):
            if remap_problem(name, side):
                raise self.error(remap_problem(name, side) or "")
        context.ros_remaps.append(pair)


__getattr__ = module_getattr("launch_ros.actions", lambda: __all__)
