"""ROS names and parameters as launch files write them, the one place for the front-ends and
the launch model: namespaces joined, node and namespace parts checked, remaps checked as rcl
checks them, nested parameter mappings flattened into names, a parameter's text typed."""

from __future__ import annotations

import re
from typing import Any

from ros_tutorials_common.bounded import InputError, load_yaml
from ros_tutorials_common.names import TOKEN, valid_remap_name

_TOKEN = re.compile(TOKEN)
# Text YAML can only read as itself: no indicator first, no ": ", " #", quotes, newlines or
# spaces at its ends.
_PLAIN_TEXT = re.compile(r"[A-Za-z_/](?:[A-Za-z0-9_./ -]*[A-Za-z0-9_./-])?")


def join_namespace(base: str, name: str) -> str:
    """Namespace ``name`` relative to ``base`` (absolute if it starts with /)."""
    full = name if name.startswith("/") else f"{base.rstrip('/')}/{name}"
    return "/" + "/".join(part for part in full.split("/") if part)


def remap_problem(name: str, side: str) -> str | None:
    """Why rcl would refuse ``name`` as the ``side`` ("from" or "to") of a remap; else None."""
    if valid_remap_name(name, side):
        return None
    return (
        f"remap {side}={name!r} is not a valid ROS name (parts of letters, digits and _, "
        "not starting with a digit, separated by one /; ~/ only at the start)"
    )


def valid_name(name: str) -> bool:
    """One part of a ROS name: ASCII letters, digits and _, not starting with a digit (rcl
    refuses 'pé' and 'nsü', which str.isalnum takes)."""
    return _TOKEN.fullmatch(name) is not None


def flatten(value: Any, separator: str, prefix: str = "") -> list[tuple[str, Any]]:
    """A mapping as (name, value) pairs, nested keys joined by ``separator``: "." for a ROS 2
    node's parameters (launch_ros), "/" for roslaunch's parameter server keys."""
    if not isinstance(value, dict):
        return [(prefix, value)]
    pairs = []
    for key, item in value.items():
        name = f"{prefix.rstrip(separator)}{separator}{key}" if prefix else str(key)
        pairs += flatten(item, separator, name)
    return pairs


def namespace_under(base: str, value: str) -> str | None:
    """Namespace ``value`` under ``base`` (absolute if it starts with /), or None if a part of
    it is not a valid name ("a//b" has an empty part: a typo)."""
    full = join_namespace(base, value)
    parts = value.strip("/").split("/")
    bad_part = value.strip("/") and not all(valid_name(part) for part in parts)
    if bad_part or (full != "/" and not all(valid_name(p) for p in full[1:].split("/"))):
        return None
    return full


def yaml_parameter(text: str) -> Any:
    """A ROS 2 parameter's text as launch_ros types it, in every format: read as YAML (``[2,
    5, 8]`` is a list, ``2.5`` a double, ``true`` a bool), the text itself where YAML gives
    no single value (a mapping, nothing, or no valid YAML)."""
    if len(text) > 1024 and _PLAIN_TEXT.fullmatch(text):  # YAML reads it as this text; its
        return text  # pure-Python scanner would take seconds for a megabyte
    import yaml  # here: a launch without parameters reads no YAML

    try:
        value = load_yaml(text, "the parameter value")
    except (yaml.YAMLError, InputError):
        return text
    return text if value is None or isinstance(value, dict) else value
