"""launch_ros.parameter_descriptions: a parameter value with its type, a parameters file."""

from __future__ import annotations

from typing import Any

from launch._base import caller_where
from launch._missing import module_getattr

__all__ = ["ParameterFile", "ParameterValue"]


class ParameterValue:
    """A value read as YAML when the launch runs, unless ``value_type`` is str."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value, self.value_type = value, value_type


class ParameterFile:
    """A parameters file; with ``allow_substs`` its $(...) are substituted first (the
    front-ends' syntax), into a file of its own."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self.param_file = param_file
        self.allow_substs = allow_substs
        self.where = caller_where()  # its errors name this line


__getattr__ = module_getattr("launch_ros.parameter_descriptions", lambda: __all__)
