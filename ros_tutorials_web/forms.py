"""Forms for rqt's plugins in the browser (rqt.py): a message's fields as a form, the texts
typed in it read as their fields' types (ros2cmd.messages fills and checks the message), and
a parameter's value typed as text read as the parameter's type. What does not fit is
Refused with one line for the page."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from typing import Any

from ros2cmd.errors import ToolError
from ros2cmd.messages import fill_message, message_to_ordered, parse_yaml
from ros2cmd.param.api import described_type
from ros2cmd.param.api import parameter_value as typed_parameter
from ros2cmd.typenames import full_type_name, load_type

MAX_DEPTH = 8  # nested messages shown in a form


class Refused(Exception):
    """A request the page made that cannot be done: one line for the page."""


def form(cls: type, depth: int = 0) -> list[dict[str, Any]]:
    """A message class's fields for a form: name, type, kind (bool, number, string, message,
    array) and the default value as text (a nested message: its fields)."""
    from rosidl_parser.definition import AbstractNestedType, BasicType, NamespacedType

    msg = cls()
    fields = []
    for (name, type_text), slot in zip(
        cls.get_fields_and_field_types().items(), cls.SLOT_TYPES, strict=True
    ):
        entry: dict[str, Any] = {"name": name, "type": type_text}
        value = getattr(msg, name)
        if isinstance(slot, NamespacedType) and depth < MAX_DEPTH:
            entry["kind"] = "message"
            entry["fields"] = form(type(value), depth + 1)
        elif isinstance(slot, (AbstractNestedType, NamespacedType)):
            entry["kind"] = "array"
            entry["default"] = json.dumps(message_to_ordered(msg)[name])
        elif isinstance(slot, BasicType) and slot.typename == "boolean":
            entry["kind"] = "bool"
            entry["default"] = "true" if value else "false"
        elif isinstance(slot, BasicType) and slot.typename not in ("char", "wchar"):
            entry["kind"] = "number"
            entry["default"] = repr(value) if isinstance(value, float) else str(value)
        else:  # strings (and char, as text)
            entry["kind"] = "string"
            entry["default"] = str(value)
        fields.append(entry)
    return fields


def typed_values(cls: type, typed: Any, path: str = "") -> dict[str, Any]:
    """The values typed in a form (a dict of texts, nested for nested messages) as the data
    fill_message takes: a string field's text as typed, any other read as YAML."""
    from rosidl_parser.definition import AbstractString, NamespacedType

    if not isinstance(typed, dict):
        raise Refused(f"{path or 'the message'}: expected the form's fields")
    fields = dict(zip(cls.get_fields_and_field_types(), cls.SLOT_TYPES, strict=True))
    values: dict[str, Any] = {}
    for name, text in typed.items():
        where = f"{path}.{name}" if path else name
        slot = fields.get(name)
        if slot is None:
            raise Refused(f"'{where}' is not a field of {full_type_name(cls)}")
        if isinstance(slot, NamespacedType) and isinstance(text, dict):
            values[name] = typed_values(type(getattr(cls(), name)), text, where)
        elif not isinstance(text, str):
            raise Refused(f"{where}: expected the text typed in its field")
        elif isinstance(slot, AbstractString):
            values[name] = text
        else:
            try:
                values[name] = parse_yaml(text) if text.strip() else None
            except ToolError as error:
                raise Refused(f"{where}: {error}") from None
            if values[name] is None:
                raise Refused(f"{where}: no value typed")
    return values


def filled(cls: type, typed: Any) -> Any:
    """A message of ``cls`` filled from a form's values, or Refused with the one line."""
    try:
        return fill_message(cls(), typed_values(cls, typed))
    except ToolError as error:
        raise Refused(str(error)) from None


def type_class(name: Any, kinds: tuple[str, ...]) -> type:
    if not isinstance(name, str) or not name:
        raise Refused("no type chosen")
    try:
        return load_type(name, kinds)
    except ToolError as error:
        raise Refused(str(error)) from None
    except Exception as error:  # a broken package's module: its words, one line
        raise Refused(f"cannot load {name}: {error}") from None


# --- parameters ------------------------------------------------------------------------------


def parameter_entry(name: str, value: Any, descriptor: Any) -> dict[str, Any]:
    """One parameter for the page: as rqt_reconfigure shows it."""
    from rclpy.parameter import parameter_value_to_python

    entry: dict[str, Any] = {
        "name": name,
        "type": described_type(value.type),
        "value": plain(parameter_value_to_python(value)),
        "description": descriptor.description,
        "read_only": descriptor.read_only,
    }
    kinds = (("integer", descriptor.integer_range), ("double", descriptor.floating_point_range))
    for kind, ranges in kinds:
        if ranges:
            r = ranges[0]
            entry["range"] = {"from": r.from_value, "to": r.to_value, "step": r.step, "kind": kind}
    return entry


def plain(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, (bytes, bytearray)):
        return list(value)
    return value


def parameter_value(text: Any, kind: str) -> Any:
    """The ParameterValue for the text typed, read as the parameter's type (a parameter
    keeps its type: 5 for a double is 5.0, as rqt_reconfigure's spin box gives it)."""
    if not isinstance(text, str):
        raise Refused("expected the value as text")
    try:
        data = parse_yaml(text) if kind != "string" else text
    except ToolError as error:
        raise Refused(str(error)) from None
    checks: dict[str, tuple[Callable[[Any], bool], Callable[[Any], Any]]] = {
        "boolean": (_is_bool, bool),
        "integer": (_is_int, int),
        "double": (is_number, float),
        "string": (_is_str, str),
        "boolean array": (_all(_is_bool), list),
        "integer array": (_all(_is_int), list),
        "double array": (_all(is_number), lambda v: [float(x) for x in v]),
        "string array": (_all(_is_str), list),
    }
    if kind not in checks:
        raise Refused(f"a parameter of type {kind} cannot be set here")
    fits, convert = checks[kind]
    if not fits(data):
        raise Refused(f"{text!r} is not a {kind}")
    try:
        return typed_parameter(kind, convert(data))
    except (AssertionError, ValueError, TypeError, OverflowError) as error:
        raise Refused(f"{text!r} does not fit a {kind}: {error}") from None


def _is_bool(v: Any) -> bool:
    return isinstance(v, bool)


def _is_int(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool) and -(2**63) <= v < 2**63


def is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _is_str(v: Any) -> bool:
    return isinstance(v, str)


def _all(fits: Callable[[Any], bool]) -> Callable[[Any], bool]:
    return lambda v: isinstance(v, list) and all(fits(x) for x in v)


def plain_data(value: Any) -> Any:
    """Ordered message data as JSON can carry it (bytes as numbers, NaN as text)."""
    if isinstance(value, dict):
        return {k: plain_data(v) for k, v in value.items()}
    return plain(value)
