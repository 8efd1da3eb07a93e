"""launch_ros.descriptions: ComposableNode (a component for a container), and the parameter
descriptions launch_ros also exports from here."""

from __future__ import annotations

from typing import Any

from launch._base import LaunchContext, caller_where, perform
from launch._missing import module_getattr
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from launch_ros.utilities import node_parameters, node_remaps, relative_namespace
from launcher.declarations import ComponentDecl

__all__ = ["ComposableNode", "ParameterFile", "ParameterValue"]


class ComposableNode:
    """A component: a plugin of a package, loaded into a component container (the container
    is planned and shown, not started: rclcpp_components is not on PyPI)."""

    def __init__(
        self,
        *,
        package: Any,
        plugin: Any,
        name: Any = None,
        namespace: Any = None,
        parameters: Any = None,
        remappings: Any = None,
        extra_arguments: Any = None,
        condition: Any = None,
    ) -> None:
        self.where = caller_where()
        self.package, self.plugin, self.node_name, self.node_namespace = (
            package, plugin, name, namespace)  # fmt: skip
        self.parameters = list(parameters or [])
        self.remappings = list(remappings or [])
        self.extra_arguments = list(extra_arguments or [])
        self.condition = condition

    def component_decl(self, context: LaunchContext, namespace: str) -> ComponentDecl:
        """This component as the plan holds it; ``namespace``: its container's."""
        if self.node_namespace is not None:
            namespace = relative_namespace(self, namespace, context)
        extra = []
        for item in self.extra_arguments:
            for key, value in dict(item).items():
                extra.append((perform(key, context), perform(value, context)))
        params, _files = node_parameters(self, self.parameters, context)
        return ComponentDecl(
            self.where,
            perform(self.package, context),
            perform(self.plugin, context),
            perform(self.node_name, context) if self.node_name is not None else None,
            namespace,
            node_remaps(self, self.remappings, context),
            params,
            extra,
        )


__getattr__ = module_getattr("launch_ros.descriptions", lambda: __all__)
