"""What launch_ros's Node and ComposableNode share: a node's namespace, remaps and parameters
as launch_ros evaluates them in a launch context."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from launch._base import LaunchContext, Substitution, element_at, perform
from launch.actions import flag
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from launcher import LaunchError
from launcher.naming import flatten, namespace_under, remap_problem, yaml_parameter
from launcher.substitutions import substituted_params_file
from ros_tutorials_common.bounded import InputError, parameter_problem, read_params_file


def _is_substitutions(value: Any) -> bool:
    if isinstance(value, (str, Substitution)):
        return True
    return isinstance(value, (list, tuple)) and any(isinstance(v, Substitution) for v in value)


def parameter_value(value: Any, context: LaunchContext, where: str) -> Any:
    """A parameter's value as launch_ros gives it: substitutions and text read as YAML."""
    if isinstance(value, ParameterValue):
        text = perform(value.value, context)
        return text if value.value_type is str else yaml_parameter(text)
    if isinstance(value, bool | int | float) or value is None:
        return value
    if _is_substitutions(value):
        return yaml_parameter(perform(value, context))
    if isinstance(value, (list, tuple)):
        return [parameter_value(item, context, where) for item in value]
    return value


def relative_namespace(entity: Any, base: str, context: LaunchContext) -> str:
    """``entity``'s node_namespace, relative to ``base`` (absolute if it starts with /)."""
    value = perform(entity.node_namespace, context)
    namespace = namespace_under(base, value)
    if namespace is None:
        raise LaunchError(f"{entity.where}: invalid namespace {value!r}")
    return namespace


def node_remaps(
    entity: Any, remappings: list[Any], context: LaunchContext
) -> list[tuple[str, str]]:
    """The SetRemap remaps of the scope, then the node's own, checked as rcl checks them."""
    remaps = list(context.ros_remaps)
    for pair in remappings:
        source, target = (perform(part, context) for part in pair)
        for name_, side in ((source, "from"), (target, "to")):
            if remap_problem(name_, side):
                raise LaunchError(f"{entity.where}: {remap_problem(name_, side)}")
        remaps.append((source, target))
    return remaps


def node_parameters(
    entity: Any, parameters: list[Any], context: LaunchContext
) -> tuple[list[tuple[str, Any]], list[str]]:
    """The SetParameter parameters and files of the scope, then the node's own: dictionaries
    (nested ones flattened into dotted names) and parameters files, checked now."""
    params, files = list(context.ros_params), list(context.ros_params_files)
    for item in parameters:
        if isinstance(item, dict):
            values = {perform(k, context): v for k, v in item.items()}
            for key, value in flatten(values, "."):
                typed = parameter_value(value, context, entity.where)
                problem = parameter_problem(key, typed)
                if problem:
                    raise LaunchError(f"{entity.where}: {problem}")
                params.append((key, typed))
        else:
            source = item.param_file if isinstance(item, ParameterFile) else item
            where = item.where if isinstance(item, ParameterFile) else entity.where
            path = Path(perform(source, context))
            if isinstance(item, ParameterFile) and flag(item.allow_substs, context):
                element = element_at(where)
                path = substituted_params_file(path, context.frontend_scope, element)
            try:  # checked now: the node would fail on it later
                read_params_file(path)
            except InputError as error:
                raise LaunchError(f"{where}: {error}") from None
            files.append(str(path))
    return params, files
