"""What launch_ros's Node and ComposableNode share: a node's namespace, remaps and parameters
as launch_ros evaluates them in a launch context."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from launch._base import Substitution, element_at, perform
from launch.actions import enabled, flag
from launch.frontend.frontend_text import FrontendText
from launch.launch_context import LaunchContext
from launch_foundation.errors import LaunchError
from launch_foundation.naming import flatten, namespace_under, remap_problem, yaml_parameter
from launch_foundation.parse import Element
from launch_foundation.substitutions import substituted_params_file, to_bool
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from ros_tutorials_common.bounded import (
    InputError,
    parameter_problem,
    parameters_problem,
    read_params_file,
)


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
        if not enabled(pair[0], context):  # a front-end's <remap if=...>
            continue
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
    expanded = []
    for item in parameters:  # a front-end's <param>s: read now, in the node's scope
        expanded += item.expand(context) if isinstance(item, FrontendParameter) else [item]
    for item in expanded:
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
                path = substituted_params_file(path, _performer(element, context), element)
            files.append(str(params_file_checked(path, where, context)))
    return params, files


def _performer(element: Element, context: LaunchContext) -> Callable[[str], str]:
    """A text's $(...) performed at ``element`` in ``context`` (a parameters file's)."""
    return lambda text: FrontendText(text, element).perform(context)


def params_file_checked(path: Path, where: str, context: LaunchContext) -> Path:
    """A parameters file for a node, passed on as its path, as ros2 launch passes it. What
    would make it no parameters file at all (missing, too large, not YAML, no
    ``ros__parameters``) is refused now, at ``where``; a value rcl will refuse when the node
    reads it (a list of mixed types, a date) is said once, as a warning."""
    try:
        entries = read_params_file(path, values=False)
    except InputError as error:
        raise LaunchError(f"{where}: {error}") from None
    for entry in entries.values():
        problem = parameters_problem(entry["ros__parameters"])
        if problem:
            context.sink.warn(
                f"{where}: {path}: {problem}; passed to the node as it is (as ros2 launch "
                "passes it), where rcl will refuse it"
            )
            break
    return path


# A front-end's <param type=...>: (the Python type, whether a list); "yaml": read as YAML.
ROS2_TYPES: dict[str, tuple[type | None, bool]] = {
    "str": (str, False), "int": (int, False), "float": (float, False), "bool": (bool, False),
    "list_of_str": (str, True), "list_of_int": (int, True), "list_of_float": (float, True),
    "list_of_bool": (bool, True), "yaml": (None, False),
}  # fmt: skip


def frontend_node_parts(entity: Any) -> tuple[list[Any], list[Any]]:
    """The parameters and remappings a front-end's <node> or <composable_node> gives its
    action: its <param>s (each read when the node is planned) and <remap>s (from, to)."""
    from launch.frontend.entity import Entity

    params = entity.get_attr("param", data_type=list[Entity], optional=True) or []
    remaps = entity.get_attr("remap", data_type=list[Entity], optional=True) or []
    remappings = [
        tuple(
            FrontendText(item.get_attr(side), item.element, _remap_check(side))
            for side in ("from", "to")
        )
        for item in remaps
    ]
    return [FrontendParameter(item.element) for item in params], remappings


def _remap_check(side: str) -> Any:
    def check(name: str, element: Element) -> str:
        if remap_problem(name, side):  # at its own line (node_remaps checks it too)
            raise element.error(remap_problem(name, side) or "")
        return name

    return check


class FrontendParameter:
    """A front-end's <param>, read when its node is planned: ``{name: value}`` typed as
    launch_xml types it (by YAML, or by its ``type``; ``value-sep`` makes a list), a
    ParameterFile (``from``), or a group's <param>s (``<param name="group">``)."""

    def __init__(self, element: Element) -> None:
        self.element, self.where = element, element.where

    def expand(self, context: LaunchContext, prefix: str = "") -> list[Any]:
        element, scope = self.element, context.frontend_scope
        if not _holds(element, context):
            return []

        def text(name: str) -> str:
            if name not in element.attrs:
                raise element.error(f"<{element.tag}> needs a {name!r} attribute")
            return FrontendText(element.attrs[name], element).perform(context)

        if "from" in element.attrs:
            path = Path(text("from"))
            path = path if path.is_absolute() else scope.file.parent / path
            substs = "allow_substs" in element.attrs and to_bool(
                text("allow_substs"), element, "'allow_substs'"
            )
            parameter_file = ParameterFile(str(path), allow_substs=substs)
            parameter_file.where = element.where
            return [parameter_file]
        if "allow_substs" in element.attrs:
            raise element.error("allow_substs is for a parameters file (<param from=...>)")
        name = prefix + text("name")
        if element.children:  # a group of parameters: their names start with its own
            if {"value", "type"} & element.attrs.keys():
                raise element.error("<param> holds either a value or <param>s, not both")
            found = []
            for child in element.children:
                found += FrontendParameter(child).expand(context, name + ".")
            return found
        if "value_sep" in element.attrs:  # each item substituted and typed on its own
            separator = element.attrs["value_sep"]
            items = element.attrs.get("value", "").split(separator) if separator else []
            texts: str | list[str] = [
                FrontendText(item, element).perform(context) for item in items
            ]
        else:
            texts = text("value")
        value = _typed(texts, element.attrs.get("type"), element)
        problem = parameter_problem(name, value)
        if problem:  # at the <param>'s own line
            raise element.error(problem)
        return [{name: _as_typed(value)}]


def _holds(element: Element, context: LaunchContext) -> bool:
    from launch.frontend.frontend_text import frontend_enabled

    return frontend_enabled(element, context)


def _scalar(text: str, kind: type | None, element: Element) -> Any:
    """One value of a ROS 2 parameter as launch's coerce_to_type reads it."""
    if kind is None:
        return yaml_parameter(text)
    if kind is str:
        return text
    if kind is bool and text in ("1", "0"):  # launch takes 1 and 0 for true and false
        text = {"1": "true", "0": "false"}[text]
    try:
        value = kind(text) if kind in (int, float) else yaml_parameter(text)
    except ValueError:
        value = None
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        name = element.attrs.get("name", "")
        raise element.error(f"param {name!r}: {text!r} is not {kind.__name__}")
    return value


def _typed(texts: str | list[str], type_name: str | None, element: Element) -> Any:
    """A ROS 2 parameter's value from its text (or texts, split by value-sep) and type."""
    if type_name is not None and type_name not in ROS2_TYPES:
        known = ", ".join(ROS2_TYPES)
        raise element.error(f"unknown parameter type {type_name!r}; use one of {known}")
    kind, is_list = ROS2_TYPES[type_name] if type_name else (None, False)
    if isinstance(texts, list):
        if type_name is not None and not is_list and kind is not None:
            raise element.error(f"value-sep makes a list: use type='list_of_{type_name}'")
        return [_scalar(text, kind, element) for text in texts]
    if not is_list:
        return _scalar(texts, kind, element)
    items = yaml_parameter(texts)
    if not isinstance(items, list) or not all(
        isinstance(item, kind) and not (kind is int and isinstance(item, bool)) for item in items
    ):
        name = element.attrs.get("name", "")
        raise element.error(f"param {name!r}: {texts!r} is not a list of {kind.__name__}")
    return items


def _as_typed(value: Any) -> Any:
    """A value typed already, as Node takes it: text stays text (ParameterValue of str), not
    read as YAML again."""
    if isinstance(value, str):
        return ParameterValue(value, value_type=str)
    if isinstance(value, list):
        return [_as_typed(item) for item in value]
    return value
