"""Messages to and from the YAML a user types, e.g. ``'{a: 10, b: 5}'``.

Filling a message walks its fields with the type information every generated class
carries (``get_fields_and_field_types()`` and ``SLOT_TYPES``), so a wrong field name or a
value out of range for the field gets a clear one-line error before anything is sent.
The ROS 1 tools also give values by position (``rosservice call /srv 10 5``): a list of
values fills the fields in order. As ros2cli reads them, ``header: "auto"`` and a Time given
as ``"now"`` take the current time, and a key YAML 1.1 reads as a boolean (``off``, ``on``,
``yes``, ``no``) names the field so spelled (turtlesim/srv/SetPen's ``off``). Printing is
rosidl_runtime_py's: ``message_to_yaml`` and ``message_to_csv`` write what ``ros2 topic echo``
shows (truncation, ``--no-arr``, ``--no-str``, ``--flow-style``).
"""

from __future__ import annotations

import array
import contextlib
import importlib
import math
import re
import sys
from collections.abc import Callable
from functools import cache
from typing import TYPE_CHECKING, Any

from ros2cmd.errors import ToolError
from ros2cmd.typenames import full_type_name
from ros_tutorials_common.bounded import InputError, load_yaml

if TYPE_CHECKING:
    from rosidl_parser.definition import NamespacedType

# rclpy, rosidl_parser (loaded with any message class already) and yaml (its reader compiles a
# large pattern as it loads) are imported in the functions that use them, so that the verbs'
# modules load without them.

# Value ranges of the integer types, by their IDL names as SLOT_TYPES spells them.
INTEGER_RANGES: dict[str, tuple[int, int]] = {}
for _bits in (8, 16, 32, 64):
    INTEGER_RANGES[f"int{_bits}"] = (-(2 ** (_bits - 1)), 2 ** (_bits - 1) - 1)
    INTEGER_RANGES[f"uint{_bits}"] = (0, 2**_bits - 1)
for _alias, _name in {
    "short": "int16",
    "long": "int32",
    "long long": "int64",
    "unsigned short": "uint16",
    "unsigned long": "uint32",
    "unsigned long long": "uint64",
    "octet": "uint8",  # .msg `byte`
    "char": "uint8",  # .msg `char`
    "wchar": "uint16",
}.items():
    INTEGER_RANGES[_alias] = INTEGER_RANGES[_name]
FLOAT32_MAX = 3.4028234663852886e38


# `linear: x: 0.2`: block YAML (`linear:` newline `  x: 0.2`) whose line breaks were lost, as
# seed 004 prints its rostopic pub examples. Not YAML; read as {linear: {x: 0.2}}.
_FLATTENED_BLOCK = re.compile(r"\s*(?:[A-Za-z_]\w*\s*:\s+){2,}[^:{}\[\],]+")


def parse_yaml(text: str) -> Any:
    """Parse the YAML a user typed; a syntax error becomes one line saying where."""
    import yaml

    try:
        return load_yaml(text, "the YAML")  # bounded: no alias bomb, at most 1 MiB
    except InputError as error:
        raise ToolError(str(error)) from None
    except yaml.YAMLError as error:
        if _FLATTENED_BLOCK.fullmatch(text):
            *keys, value = (part.strip() for part in text.split(":"))
            return parse_yaml("".join(f"{{{key}: " for key in keys) + value + "}" * len(keys))
        mark = getattr(error, "problem_mark", None)
        where = f" at column {mark.column + 1}" if mark else ""
        problem = getattr(error, "problem", None) or str(error).splitlines()[0]
        raise ToolError(f"invalid YAML {text!r}{where}: {problem}") from None


# PyYAML (YAML 1.1) reads these keys as booleans: `{off: 0}` arrives as {False: 0}. A message
# field so named (turtlesim/srv/SetPen's `off`) is what the user meant.
_BOOLEAN_KEYS = {
    True: ("on", "yes", "y", "true", "On", "Yes", "Y", "True", "ON", "YES", "TRUE"),
    False: ("off", "no", "n", "false", "Off", "No", "N", "False", "OFF", "NO", "FALSE"),
}

TimeSetter = Callable[[Any], None]


def fill_message(
    msg: Any, values: Any, path: str = "", stamps: list[TimeSetter] | None = None
) -> Any:
    """Set msg's fields from a dict (by name) or a list (in order); return msg.

    As `ros2 topic pub` does, a std_msgs/Header given as "auto" and a builtin_interfaces/Time
    given as "now" get the current time; with ``stamps`` given, a setter for each such field
    is appended to it, so that a publisher can stamp every message it sends anew.
    """
    from rclpy.clock import Clock

    fields = list(msg.get_fields_and_field_types())
    slot_types = dict(zip(fields, msg.SLOT_TYPES, strict=True))
    where = f"{path} ({full_type_name(type(msg))})" if path else full_type_name(type(msg))
    if values is None:
        return msg
    if isinstance(values, list):
        if len(values) != len(fields):
            raise ToolError(
                f"{where} takes {len(fields)} value(s) ({' '.join(fields) or 'none'}), "
                f"got {len(values)}"
            )
        values = dict(zip(fields, values, strict=True))
    if not isinstance(values, dict):
        if len(fields) != 1:
            raise ToolError(f"{where} needs a mapping of its fields ({', '.join(fields)})")
        values = {fields[0]: values}  # `rostopic pub /t std_msgs/String hello`
    for key, value in values.items():
        name = _field_name(key, fields)
        if name not in slot_types:
            raise ToolError(
                f"'{name}' is not a field of {where} (fields: {', '.join(fields) or 'none'})"
            )
        field_path = f"{path}.{name}" if path else name
        slot_type = slot_types[name]
        current = getattr(msg, name)
        if _is_type(slot_type, "std_msgs", "Header") and value == "auto":
            current.stamp = Clock().now().to_msg()
            if stamps is not None:
                stamps.append(lambda stamp, header=current: setattr(header, "stamp", stamp))
            continue
        if _is_type(slot_type, "builtin_interfaces", "Time") and value == "now":
            setattr(msg, name, Clock().now().to_msg())
            if stamps is not None:
                stamps.append(lambda stamp, owner=msg, name=name: setattr(owner, name, stamp))
            continue
        setattr(msg, name, _convert(value, slot_type, current, field_path, stamps))
    return msg


def _field_name(key: Any, fields: list[str]) -> str:
    """The field a key names: a key YAML read as a boolean names the field so spelled."""
    if isinstance(key, bool):
        named = [name for name in _BOOLEAN_KEYS[key] if name in fields]
        if len(named) == 1:
            return named[0]
    return str(key)


def _convert(
    value: Any, slot_type: Any, current: Any, path: str, stamps: list[TimeSetter] | None = None
) -> Any:
    from rosidl_parser.definition import (
        AbstractGenericString,
        AbstractNestedType,
        Array,
        BasicType,
        BoundedSequence,
        NamespacedType,
    )

    if isinstance(slot_type, NamespacedType):
        if _is_type(slot_type, "builtin_interfaces", "Time") and value == "now":
            from rclpy.clock import Clock

            return Clock().now().to_msg()
        return fill_message(current, value, path, stamps)
    if isinstance(slot_type, AbstractNestedType):  # arrays and sequences
        if not isinstance(value, list):
            raise ToolError(f"{path} is a list; give it as [...], got {value!r}")
        if isinstance(slot_type, Array) and len(value) != slot_type.size:
            raise ToolError(f"{path} takes exactly {slot_type.size} items, got {len(value)}")
        if isinstance(slot_type, BoundedSequence) and len(value) > slot_type.maximum_size:
            raise ToolError(
                f"{path} takes at most {slot_type.maximum_size} items, got {len(value)}"
            )
        item_type = slot_type.value_type
        items = []
        for i, item in enumerate(value):
            template = None
            if isinstance(item_type, NamespacedType):
                template = _message_class(item_type)()
            items.append(_convert(item, item_type, template, f"{path}[{i}]"))
        return items
    if isinstance(slot_type, AbstractGenericString):
        if not isinstance(value, str):  # YAML read `5` as a number, `true` as a boolean
            raise ToolError(
                f"{path} is a string, got {value!r} ({type(value).__name__}); "
                f"quote it to send text: '{{{path.rsplit('.', 1)[-1]}: \"{value}\"}}'"
            )
        text = value
        try:
            text.encode("utf-8")
        except UnicodeEncodeError as error:  # a lone surrogate: "\ud800" in YAML
            raise ToolError(
                f"{path} is not valid Unicode text: {text[error.start]!r} at position "
                f"{error.start} is half of a UTF-16 surrogate pair"
            ) from None
        maximum = getattr(slot_type, "maximum_size", None)
        if maximum is not None and len(text) > maximum:
            raise ToolError(f"{path} takes at most {maximum} characters, got {len(text)}")
        return text
    if isinstance(slot_type, BasicType):
        return _convert_basic(value, slot_type.typename, path)
    raise ToolError(f"{path}: unsupported field type {slot_type!r}")


def _convert_basic(value: Any, typename: str, path: str) -> Any:
    if typename == "boolean":
        if not isinstance(value, bool):
            raise ToolError(f"{path} is a boolean (true or false), got {value!r}")
        return value
    if typename in ("float", "double", "long double"):
        if isinstance(value, str):
            # YAML 1.1 reads `1e40` and `1e-3` (no dot, or no sign in the exponent) as text;
            # ROS 1's rostopic took them as numbers, as Python's float() does.
            with contextlib.suppress(ValueError):
                value = float(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise ToolError(f"{path} is a number ({typename}), got {value!r}")
        value = float(value)
        if typename == "float" and math.isfinite(value) and abs(value) > FLOAT32_MAX:
            raise ToolError(f"{path} = {value!r} is out of range for float32")
        return value
    low, high = INTEGER_RANGES[typename]
    if typename in ("char", "octet") and isinstance(value, str) and len(value) == 1:
        value = ord(value)
    if isinstance(value, bool) or not isinstance(value, int):
        raise ToolError(f"{path} is an integer ({_ros_int_name(typename)}), got {value!r}")
    if not low <= value <= high:
        raise ToolError(
            f"{path} = {value} is out of range for {_ros_int_name(typename)} ({low} to {high})"
        )
    return bytes([value]) if typename == "octet" else value


def _ros_int_name(typename: str) -> str:
    return {"octet": "byte", "char": "char"}.get(typename, typename)


def _is_type(slot_type: Any, package: str, name: str) -> bool:
    """Whether a field's type is the message package/msg/name."""
    from rosidl_parser.definition import NamespacedType

    return (
        isinstance(slot_type, NamespacedType)
        and tuple(slot_type.namespaces) == (package, "msg")
        and slot_type.name == name
    )


def _message_class(slot_type: NamespacedType) -> type:
    module = importlib.import_module(".".join(slot_type.namespaces))
    return getattr(module, slot_type.name)


def message_to_data(msg: Any) -> Any:
    """A message as plain dicts, lists and scalars, fields in definition order."""
    if hasattr(msg, "get_fields_and_field_types"):
        return {
            name: message_to_data(getattr(msg, name)) for name in msg.get_fields_and_field_types()
        }
    if isinstance(msg, (list, tuple, array.array)) or type(msg).__name__ == "ndarray":
        return [message_to_data(item) for item in msg]
    if isinstance(msg, bytes):
        return list(msg) if len(msg) != 1 else msg[0]
    if hasattr(msg, "item"):  # numpy scalars from fixed-size arrays
        return msg.item()
    return msg


def message_to_yaml(
    msg: Any,
    *,
    truncate_length: int | None = None,
    no_arr: bool = False,
    no_str: bool = False,
    flow_style: bool = False,
) -> str:
    """A message as ``ros2 topic echo`` prints it (rosidl_runtime_py's message_to_yaml), without
    the final line break: block-style YAML in definition order, or one flow-style line.

    truncate_length shortens strings and arrays (``...`` after them), no_arr and no_str print
    a summary instead of the array or string fields.
    """
    import yaml

    data = message_to_ordered(msg, truncate_length=truncate_length, no_arr=no_arr, no_str=no_str)
    text = yaml.dump(
        data,
        Dumper=message_dumper(),
        allow_unicode=True,
        width=sys.maxsize,  # one value, one line, however long
        default_flow_style=flow_style,
        sort_keys=False,
    )
    return text.rstrip("\n")


@cache
def message_dumper() -> type:
    """The yaml Dumper that writes YAML as rosidl_runtime_py dumps a message (ros2 topic echo,
    ros2 service echo): its mappings (OrderedDicts there) never take the flow style by
    themselves, so --flow-style puts only the sequences in flow style (`client_gid: [1, 15,
    ...]`)."""
    import yaml

    class MessageDumper(yaml.SafeDumper):
        pass

    MessageDumper.add_representer(
        dict,
        lambda dumper, data: yaml.MappingNode(
            "tag:yaml.org,2002:map",
            [(dumper.represent_data(k), dumper.represent_data(v)) for k, v in data.items()],
        ),
    )
    return MessageDumper


def message_to_ordered(
    msg: Any, *, truncate_length: int | None = None, no_arr: bool = False, no_str: bool = False
) -> dict[str, Any]:
    """A message as plain data, fields in definition order, as rosidl_runtime_py converts it:
    bytes become text, numpy values Python numbers, nested messages dicts."""
    return {
        name: _plain(getattr(msg, name), slot_type, truncate_length, no_arr, no_str)
        for name, slot_type in zip(msg.get_fields_and_field_types(), msg.SLOT_TYPES, strict=True)
    }


def _plain(
    value: Any, slot_type: Any, truncate_length: int | None, no_arr: bool, no_str: bool
) -> Any:
    if isinstance(value, bytes):
        text = "".join(chr(c) for c in value[:truncate_length])
        cut = truncate_length is not None and len(value) > truncate_length
        return text + "..." if cut else text
    if isinstance(value, str):
        if no_str:
            return f"<string length: <{len(value)}>>"
        if truncate_length is not None and len(value) > truncate_length:
            return value[:truncate_length] + "..."
        return value
    if isinstance(value, (list, tuple, array.array)) or type(value).__name__ == "ndarray":
        if no_arr and slot_type is not None:
            return _array_summary(value, slot_type)
        # Only what is shown is converted: a 10 MB image's data is not walked to show 128 items.
        shown = value if truncate_length is None else value[:truncate_length]
        items = [_plain(item, None, truncate_length, no_arr, no_str) for item in shown]
        if truncate_length is not None and len(value) > truncate_length:
            return [*items, "..."]
        return items
    if hasattr(value, "get_fields_and_field_types"):
        return message_to_ordered(
            value, truncate_length=truncate_length, no_arr=no_arr, no_str=no_str
        )
    if hasattr(value, "item"):  # numpy scalars from fixed-size arrays
        return value.item()
    return value


def _type_name(slot_type: Any) -> str:
    """A field type's name as --no-arr shows it: 'double', 'string', 'geometry_msgs/Point'."""
    from rosidl_parser.definition import AbstractString, AbstractWString, BasicType, NamespacedType

    if isinstance(slot_type, BasicType):
        return slot_type.typename
    if isinstance(slot_type, AbstractString):
        return "string"
    if isinstance(slot_type, AbstractWString):
        return "wstring"
    if isinstance(slot_type, NamespacedType):
        return "/".join(slot_type.namespaced_name())
    return "unknown"


def _array_summary(value: Any, slot_type: Any) -> str:
    from rosidl_parser.definition import Array, BoundedSequence, UnboundedSequence

    item = _type_name(slot_type.value_type)
    if isinstance(slot_type, Array):
        return f"<array type: {item}[{slot_type.size}]>"
    if isinstance(slot_type, BoundedSequence):
        return f"<sequence type: {item}[{slot_type.maximum_size}], length: {len(value)}>"
    if isinstance(slot_type, UnboundedSequence):
        return f"<sequence type: {item}, length: {len(value)}>"
    return "unknown"


def message_to_csv(
    msg: Any, *, truncate_length: int | None = None, no_arr: bool = False, no_str: bool = False
) -> str:
    """A message as one line of comma-separated values (``ros2 topic echo --csv``)."""

    def text(value: Any, slot_type: Any = None) -> str:
        if isinstance(value, (list, tuple, array.array)) or type(value).__name__ == "ndarray":
            if no_arr and slot_type is not None:
                return _array_summary(value, slot_type)
            parts = []
            for i, item in enumerate(value):
                if truncate_length is not None and i >= truncate_length:
                    parts.append("...")
                    break
                parts.append(text(item))
            return ",".join(parts)
        if hasattr(value, "get_fields_and_field_types"):
            return message_to_csv(
                value, truncate_length=truncate_length, no_arr=no_arr, no_str=no_str
            )
        if no_str and isinstance(value, str):
            return f"<string length: <{len(value)}>>"
        cut = truncate_length is not None and isinstance(value, (str, bytes))
        if cut and len(value) > truncate_length:
            value = value[:truncate_length] + (b"..." if isinstance(value, bytes) else "...")
        return str(value)

    line = ""
    for name, slot_type in zip(msg.get_fields_and_field_types(), msg.SLOT_TYPES, strict=True):
        # As ros2topic: no comma while the line is still empty (after an empty array).
        line += ("," if line else "") + text(getattr(msg, name), slot_type)
    return line
