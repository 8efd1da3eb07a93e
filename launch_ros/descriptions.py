"""launch_ros.descriptions: ComposableNode (a component for a container), and the parameter
descriptions launch_ros also exports from here."""

from __future__ import annotations

from typing import Any

from launch._base import caller_where, perform
from launch._missing import module_getattr
from launch.actions import enabled
from launch.launch_context import LaunchContext
from launch_foundation.declarations import ComponentDecl
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from launch_ros.utilities import (
    frontend_node_parts,
    node_parameters,
    node_remaps,
    relative_namespace,
)

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

    @classmethod
    def parse(cls, parser: Any, entity: Any) -> tuple[type, dict[str, Any]]:
        """A front-end's <composable_node> (its container's parse method builds it): its
        <param>s, <remap>s and <extra_arg>s read when the container is planned."""
        from launch.actions import frontend_attr
        from launch.frontend.entity import Entity
        from launch.frontend.frontend_text import FrontendText

        kwargs: dict[str, Any] = {
            "package": frontend_attr(entity, "pkg", optional=False),
            "plugin": frontend_attr(entity, "plugin", optional=False),
            "name": frontend_attr(entity, "name"), "namespace": frontend_attr(entity, "namespace"),
            "condition": parser.parse_condition(entity),
        }  # fmt: skip
        kwargs["parameters"], kwargs["remappings"] = frontend_node_parts(entity)
        extra = entity.get_attr("extra_arg", data_type=list[Entity], optional=True) or []
        kwargs["extra_arguments"] = [
            {FrontendText(item.get_attr("name"), item.element): FrontendText(
                item.get_attr("value"), item.element)}
            for item in extra
        ]  # fmt: skip
        return cls, kwargs

    def component_decl(self, context: LaunchContext, namespace: str) -> ComponentDecl:
        """This component as the plan holds it; ``namespace``: its container's."""
        if self.node_namespace is not None:
            namespace = relative_namespace(self, namespace, context)
        extra = []
        for item in self.extra_arguments:
            for key, value in dict(item).items():
                if enabled(key, context):  # a front-end's <extra_arg if=...>
                    extra.append((perform(key, context), perform(value, context)))
        params, _files = node_parameters(self, self.parameters, context)
        return ComponentDecl(
            self.where,
            perform(self.package, context),
            perform(self.plugin, context),
            (perform(self.node_name, context) or None) if self.node_name is not None else None,
            namespace,
            node_remaps(self, self.remappings, context),
            params,
            extra,
        )


__getattr__ = module_getattr("launch_ros.descriptions", lambda: __all__)
