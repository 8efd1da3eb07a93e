"""launch_xml.Entity: launch.frontend's Entity over the launcher's parsed element
(launch_foundation/parse.py), which remembers its file and line."""

from __future__ import annotations

import typing
from typing import Any

import yaml

from launch.frontend.entity import Entity as BaseEntity
from launch_foundation.errors import LaunchError
from launch_foundation.parse import Element

_TRUE, _FALSE = ("true", "1"), ("false", "0")


class MissingAttribute(LaunchError, AttributeError):
    """An attribute (or children) an entity needs is not there: one line at its file:line."""


class Entity(BaseEntity):
    """One element of a launch file; what its parse method reads is remembered, so that an
    attribute or child nobody read is refused (assert_entity_completely_parsed)."""

    def __init__(self, element: Element, parent: Entity | None = None) -> None:
        self.element = element
        self._parent = parent
        self._read_attrs: set[str] = set()
        self._read_children: set[str] = set()
        self._children_read = False

    @property
    def type_name(self) -> str:
        return self.element.tag

    @property
    def parent(self) -> Entity | None:
        return self._parent

    @property
    def where(self) -> str:
        return self.element.where

    @property
    def children(self) -> list[Entity]:
        self._children_read = True
        return [type(self)(child, self) for child in self.element.children]

    def get_attr(
        self, name: str, *, data_type: Any = str, optional: bool = False, can_be_str: bool = True
    ) -> Any:
        key = name.replace("-", "_")
        if (
            typing.get_origin(data_type) is list
            and typing.get_args(data_type)
            and (
                isinstance(typing.get_args(data_type)[0], type)
                and issubclass(typing.get_args(data_type)[0], BaseEntity)
            )
        ):
            self._read_children.add(key)
            found = [type(self)(c, self) for c in self.element.children if c.tag == key]
            if not found and not optional:
                raise MissingAttribute(f"{self.where}: <{self.type_name}> needs <{name}> children")
            return found or None
        if key not in self.element.attrs:
            if optional:
                return None
            raise MissingAttribute(f"{self.where}: <{self.type_name}> needs a {name!r} attribute")
        self._read_attrs.add(key)
        return _coerce(self.element.attrs[key], data_type, can_be_str, self.element, name)

    def assert_entity_completely_parsed(self) -> None:
        unread = sorted(set(self.element.attrs) - self._read_attrs)
        if unread:
            written = self.element.spelled.get(unread[0], unread[0])
            raise self.element.error(f"unknown attribute {written!r} on <{self.type_name}>")
        if not self._children_read:
            extra = [c for c in self.element.children if c.tag not in self._read_children]
            if extra:
                raise extra[0].error(f"<{extra[0].tag}> is not allowed in <{self.type_name}>")


def _coerce(text: str, data_type: Any, can_be_str: bool, element: Element, name: str) -> Any:
    """An attribute's text as ``data_type``; text with a $(...) stays text where it may."""
    if data_type is str:
        return text
    if can_be_str and "$(" in text:
        return text
    if data_type is None:
        try:
            return yaml.safe_load(text)
        except yaml.YAMLError:
            return text
    if typing.get_origin(data_type) is list:
        (item_type,) = typing.get_args(data_type) or (str,)
        try:
            items = yaml.safe_load(text)
        except yaml.YAMLError:
            items = None
        if not isinstance(items, list):
            raise element.error(f"{name}={text!r} is not a list")
        return [_coerce(str(item), item_type, False, element, name) for item in items]
    if data_type is bool:  # as to_bool reads a flag
        word = text.strip().lower()
        if word not in _TRUE + _FALSE:
            raise element.error(f"{name!r} must be true, false, 1 or 0, not {text!r}")
        return word in _TRUE
    try:
        return data_type(text)
    except (TypeError, ValueError):
        what = {int: "an integer", float: "a number"}.get(data_type, str(data_type))
        raise element.error(f"{name!r} must be {what}, not {text!r}") from None
