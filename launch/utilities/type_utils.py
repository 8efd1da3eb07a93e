"""launch.utilities.type_utils: the value types launch actions and the front-ends accept
(``int``, ``float``, ``bool``, ``str`` and uniform lists of them), text coerced to them by
YAML's rules, and values mixing substitutions with them performed into them, as ros2/launch
reads them."""

from __future__ import annotations

import typing
from collections.abc import Iterable
from typing import Any

import yaml

from launch._base import Substitution, normalize_to_list_of_substitutions, perform
from launch.utilities.ensure_argument_type_impl import ensure_argument_type

ScalarTypesTuple = (int, float, bool, str)
ListTypesTuple = (list[int], list[float], list[bool], list[str])
AllowedTypesTuple = ScalarTypesTuple + ListTypesTuple
ScalarTypesType = type
AllowedTypesType = Any
ScalarValueType = int | float | bool | str
AllowedValueType = Any
SomeValueType = Any
StrSomeValueType = Any
NormalizedValueType = Any

_LISTS = "int, float, str, bool, List[int], List[float], List[str], List[bool]"


def is_typing_list(data_type: Any) -> bool:
    """``list``'s typing form: ``List``, ``List[int]``, ``list[int]``."""
    return data_type is typing.List or typing.get_origin(data_type) is list  # noqa: UP006


def is_valid_scalar_type(data_type: Any) -> bool:
    return data_type in ScalarTypesTuple


def extract_type(data_type: Any) -> tuple[type, bool]:
    """(the scalar type, whether a list of it); ValueError for any other type."""
    is_list = False
    scalar = data_type
    if is_typing_list(data_type) and typing.get_args(data_type):
        is_list, scalar = True, typing.get_args(data_type)[0]
    if not is_valid_scalar_type(scalar):
        raise ValueError(f"Unrecognized data type: {data_type}")
    return scalar, is_list


def is_instance_of_valid_type(value: Any, *, can_be_str: bool = False) -> bool:
    """A scalar of the allowed types, or a uniform list of one (with text mixed in if
    ``can_be_str``); an empty list is one."""
    if isinstance(value, list):
        if not value:
            return True
        member = next((type(x) for x in value if type(x) is not str), str)
        if member not in ScalarTypesTuple:
            return False
        kinds = (member, str) if can_be_str else member
        return all(isinstance(x, kinds) for x in value)
    return isinstance(value, ScalarTypesTuple)


def is_instance_of(value: Any, data_type: Any = None, *, can_be_str: bool = False) -> bool:
    if data_type is None:
        return is_instance_of_valid_type(value, can_be_str=can_be_str)
    scalar, is_list = extract_type(data_type)
    kinds: Any = (str, scalar) if can_be_str else scalar
    if not is_list:
        return isinstance(value, kinds)
    return isinstance(value, list) and all(isinstance(x, kinds) for x in value)


def _as_yaml(value: str, message: str, can_be_str: bool) -> Any:
    if not value:
        return value
    try:
        output = yaml.safe_load(value)
    except yaml.YAMLError as error:
        if can_be_str:
            return value
        raise ValueError(f"{message}: yaml.safe_load() failed\n{error}") from None
    if not is_instance_of_valid_type(output, can_be_str=can_be_str):
        raise ValueError(f"{message}: output type is not allowed, got {type(output)}")
    return output


def coerce_to_type(value: str, data_type: Any = None, *, can_be_str: bool = False) -> Any:
    """Text as ``data_type`` (YAML's rules when None; for bool, 1 and 0 too); with
    ``can_be_str`` text that is no such value stays text. ValueError if it cannot."""
    ensure_argument_type(value, str, "value", "coerce_to_type")
    if data_type is None:
        return _as_yaml(value, f"Failed to convert '{value}' using yaml rules", can_be_str)
    scalar, is_list = extract_type(data_type)
    kinds: Any = (str, scalar) if can_be_str else scalar
    if is_list:
        message = f"Cannot convert value '{value}' to a list of '{kinds}'"
        output = _as_yaml(value, message, can_be_str)
        if not isinstance(output, list) or not all(isinstance(x, kinds) for x in output):
            raise ValueError(message + (f", got {output}" if isinstance(output, list) else ""))
        return output
    if scalar is str:
        return value
    if scalar in (int, float):
        try:
            return scalar(value)
        except ValueError:
            if can_be_str:
                return value
            raise
    text = {"1": "true", "0": "false"}.get(value, value)
    output = _as_yaml(text, f"Failed to convert '{value}' to '{scalar}'", can_be_str)
    if isinstance(output, kinds):
        return output
    raise ValueError(f"Cannot convert value '{value}' to '{scalar}'")


def coerce_list(value: list[str], data_type: Any = None, *, can_be_str: bool = False) -> list:
    ensure_argument_type(value, list, "value", "coerce_list")
    output = [coerce_to_type(item, data_type, can_be_str=can_be_str) for item in value]
    if not is_instance_of_valid_type(output, can_be_str=can_be_str):
        raise ValueError(f"cannot convert value to {data_type}. Got value=`{value}`")
    return output


def get_typed_value(value: Any, data_type: Any, *, can_be_str: bool = False) -> Any:
    """Text or a list of text as ``data_type``; a list needs a list type (TypeError)."""
    if isinstance(value, list):
        scalar = None
        if data_type is not None:
            scalar, is_list = extract_type(data_type)
            if not is_list:
                raise TypeError(f"Cannot convert input '{value}' of type list to '{scalar}'")
        return coerce_list(value, scalar, can_be_str=can_be_str)
    return coerce_to_type(value, data_type, can_be_str=can_be_str)


def is_substitution(x: Any) -> bool:
    """A Substitution, or a non-empty list of substitutions and text with one substitution."""
    if isinstance(x, Substitution):
        return True
    if isinstance(x, (str, bytes)) or not isinstance(x, Iterable):
        return False
    items = list(x)
    return (
        bool(items)
        and all(isinstance(item, (Substitution, str)) for item in items)
        and any(isinstance(item, Substitution) for item in items)
    )


def normalize_typed_substitution(value: Any, data_type: Any) -> Any:
    """A value, substitutions, or a list mixing values and substitutions, normalized so that
    perform_typed_substitution can give a ``data_type`` of it later; TypeError if it cannot."""
    if isinstance(value, ScalarTypesTuple):
        if not is_instance_of(value, data_type):
            raise TypeError(f"value='{value}' is not an instance of {data_type}")
        return value
    if is_substitution(value):
        return normalize_to_list_of_substitutions(value)
    if not isinstance(value, Iterable):
        raise TypeError(
            "value should be either a scalar, a substitutions, or a mixed list of scalars "
            f"and substitutions. Got `value={value}` of type `{type(value)}`. "
        )
    kinds: set[type] = set()
    for item in value:
        if isinstance(item, ScalarTypesTuple):
            kinds.add(type(item))
        elif is_substitution(item):
            kinds.add(Substitution)
        else:
            raise TypeError(
                "value is a list, and one of the items is not a scalar, a Substitution or a "
                f"list of substitutions. Got value='{value}'"
            )
    is_list = True
    if data_type is not None:
        data_type, is_list = extract_type(data_type)
    if not is_list:
        raise TypeError(
            "The provided value resolves to a list, though the required type is a scalar. "
            f"Got value='{value}', data_type='{data_type}'."
        )

    def normal(item: Any, keep: type | None = None, convert: Any = None) -> Any:
        if is_substitution(item) and not (keep is not None and isinstance(item, keep)):
            return normalize_to_list_of_substitutions(item)
        return convert(item) if convert is not None else item

    for allowed, scalar, convert in (
        ({Substitution}, None, None), ({str, Substitution}, str, None),
        ({bool, Substitution}, bool, None), ({int, Substitution}, int, None),
        ({int, float, Substitution}, float, float),
    ):  # fmt: skip
        if kinds <= allowed:
            if scalar is not None and data_type not in (None, scalar):
                raise TypeError(
                    f"Got a list of '{scalar}', expected a list of '{data_type}'. value='{value}'"
                )
            if scalar is str:
                return [x if isinstance(x, str) else normal(x) for x in value]
            return [normal(x, convert=convert) for x in value]
    raise TypeError(f"Input value is not an acceptable 'SomeValueType'.Got value='{value}'")


def is_normalized_substitution(x: Any) -> bool:
    return isinstance(x, list) and bool(x) and all(isinstance(i, Substitution) for i in x)


def perform_typed_substitution(context: Any, value: Any, data_type: Any) -> Any:
    """Perform a normalized value (normalize_typed_substitution) and coerce it to
    ``data_type``; ValueError if the result is not one."""
    if isinstance(value, ScalarTypesTuple):
        if data_type is not None and not is_instance_of(value, data_type):
            raise TypeError(f"value=`{value}` is a scalar and not an instance of `{data_type}`")
        return value
    if is_normalized_substitution(value):
        return coerce_to_type(perform(value, context), data_type)
    if isinstance(value, list):
        scalar = None
        if data_type is not None:
            scalar, is_list = extract_type(data_type)
            if not is_list:
                raise ValueError(
                    "The input value is a list, cannot convert it to a scalar. "
                    f"Got value='{value}', expected type {scalar}."
                )
        output = [
            coerce_to_type(perform(item, context), scalar)
            if is_normalized_substitution(item)
            else item
            for item in value
        ]
        if not is_instance_of(output, data_type):
            raise ValueError(f"The result '{output}' is not an instance of {data_type}")
        return output
    raise TypeError(f"value='{value}' is not an instance of a valid type")
