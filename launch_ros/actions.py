"""launch_ros.actions: Node, and what applies to the nodes after it in its scope."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import yaml

from launch._base import Action, LaunchContext, Substitution, normalize, perform
from launch._missing import module_getattr
from launch.actions import ExecuteProcess
from launch_ros.parameter_descriptions import ParameterFile, ParameterValue
from launcher.declarations import NodeDecl
from launcher.resolve import join_namespace, remap_problem, valid_name
from ros_tutorials_common.bounded import InputError, load_yaml, parameter_problem, read_params_file

__all__ = [
    "Node", "PushROSNamespace", "PushRosNamespace", "SetParameter", "SetParametersFromFile",
    "SetRemap",
]  # fmt: skip


def _is_substitutions(value: Any) -> bool:
    if isinstance(value, (str, Substitution)):
        return True
    return isinstance(value, (list, tuple)) and any(isinstance(v, Substitution) for v in value)


def parameter_value(value: Any, context: LaunchContext, where: str) -> Any:
    """A parameter's value as launch_ros gives it: substitutions and text read as YAML."""
    if isinstance(value, ParameterValue):
        text = perform(value.value, context)
        return text if value.value_type is str else _yaml(text, where)
    if isinstance(value, bool | int | float) or value is None:
        return value
    if _is_substitutions(value):
        return _yaml(perform(value, context), where)
    if isinstance(value, (list, tuple)):
        return [parameter_value(item, context, where) for item in value]
    return value


def _yaml(text: str, where: str) -> Any:
    try:
        value = load_yaml(text, "the parameter value")
    except (yaml.YAMLError, InputError):
        return text
    return text if value is None or isinstance(value, dict) else value


def _flatten(prefix: str, value: Any) -> list[tuple[str, Any]]:
    if not isinstance(value, dict):
        return [(prefix, value)]
    pairs = []
    for key, item in value.items():
        pairs += _flatten(f"{prefix}.{key}" if prefix else str(key), item)
    return pairs


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

    def process_decl(self, context: LaunchContext) -> NodeDecl:
        if self.package is None:
            raise self.error("Node needs a package= here (a program by path: ExecuteProcess)")
        scope = context.scope
        name = perform(self.node_name, context) if self.node_name is not None else None
        if name is not None and not valid_name(name):
            raise self.error(f"invalid node name {name!r}")
        namespace = scope.namespace
        if self.node_namespace is not None:
            namespace = join_namespace(scope.namespace, perform(self.node_namespace, context))
            if namespace != "/" and not all(valid_name(p) for p in namespace[1:].split("/")):
                raise self.error(f"invalid namespace {namespace!r}")
        remaps = list(scope.remaps)
        for pair in self.remappings:
            source, target = (perform(part, context) for part in pair)
            for name_, side in ((source, "from"), (target, "to")):
                if remap_problem(name_, side):
                    raise self.error(remap_problem(name_, side) or "")
            remaps.append((source, target))
        params, files = list(scope.params), list(scope.params_files)
        for item in self.parameters:
            if isinstance(item, dict):
                values = {perform(k, context): v for k, v in item.items()}
                for key, value in _flatten("", values):
                    typed = parameter_value(value, context, self.where)
                    problem = parameter_problem(key, typed)
                    if problem:
                        raise self.error(problem)
                    params.append((key, typed))
            else:
                source = item.param_file if isinstance(item, ParameterFile) else item
                path = Path(perform(source, context))
                try:
                    read_params_file(path)
                except InputError as error:
                    raise self.error(str(error)) from None
                files.append(str(path))
        decl = NodeDecl(
            self.where,
            package=perform(self.package, context),
            executable=perform(self.executable, context),
            name=name,
            namespace=namespace,
            args=[perform(arg, context) for arg in self.arguments],
            ros_args=[perform(arg, context) for arg in self.ros_arguments],
            remaps=remaps,
            params=params,
            params_files=files,
        )
        self.fill(decl, context)
        if self.name is not None:  # exec_name: the output prefix
            decl.label = perform(self.name, context)
        return decl


class PushRosNamespace(Action):
    def __init__(self, namespace: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.namespace = namespace

    def execute(self, context: LaunchContext) -> None:
        value = perform(self.namespace, context)
        context.scope.namespace = join_namespace(context.scope.namespace, value)


PushROSNamespace = PushRosNamespace


class SetParameter(Action):
    def __init__(self, name: Any, value: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.name, self.value = name, value

    def execute(self, context: LaunchContext) -> None:
        value = parameter_value(self.value, context, self.where)
        context.scope.params.append((perform(self.name, context), value))


class SetParametersFromFile(Action):
    def __init__(self, filename: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.filename = filename

    def execute(self, context: LaunchContext) -> None:
        path = Path(perform(self.filename, context))
        try:
            read_params_file(path)
        except InputError as error:
            raise self.error(str(error)) from None
        context.scope.params_files.append(str(path))


class SetRemap(Action):
    def __init__(self, src: Any, dst: Any, **kw: Any) -> None:
        super().__init__(**kw)
        self.src, self.dst = src, dst

    def execute(self, context: LaunchContext) -> None:
        pair = (perform(self.src, context), perform(self.dst, context))
        for name, side in zip(pair, ("from", "to"), strict=True):
            if remap_problem(name, side):
                raise self.error(remap_problem(name, side) or "")
        context.scope.remaps.append(pair)


__getattr__ = module_getattr("launch_ros.actions", lambda: __all__)
