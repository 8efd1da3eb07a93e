"""launch.frontend.Parser: a markup launch file -> entities -> a LaunchDescription of actions,
each built by the parse method its tag exposed (launch.frontend.expose)."""

from __future__ import annotations

import importlib
import os
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from launch.frontend.entity import Entity
from launch.frontend.expose import instantiate_action
from launch_foundation.errors import LaunchError

if TYPE_CHECKING:
    from launch.launch_description import LaunchDescription


# The front-ends (their module has a Parser) and the modules whose actions expose tags.
FRONT_ENDS = ("launch_xml", "launch_yaml")
EXTENSIONS = ("launch.actions", "launch_ros.actions")


class InvalidFrontendLaunchFileError(LaunchError):
    """No front-end could read the file."""


class Parser:
    """Reads a front-end's entities into actions. A front-end (launch_xml.Parser,
    launch_yaml.Parser) overrides ``load`` and ``get_file_extensions``."""

    @staticmethod
    def implementations() -> list[type[Parser]]:
        """The markup front-ends this launcher has, loaded by name as ros2/launch loads its
        'launch.frontend.parser' entry points."""
        return [importlib.import_module(name).Parser for name in FRONT_ENDS]

    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return set()

    @classmethod
    def may_parse(cls, filename: str) -> bool:
        return any(filename.endswith("." + ext) for ext in cls.get_file_extensions())

    @classmethod
    def is_filename_valid(cls, filename: str) -> bool:
        return any(parser.may_parse(filename) for parser in cls.implementations())

    @classmethod
    def get_parsers_from_filename(cls, filename: str) -> list[type[Parser]]:
        return [parser for parser in cls.implementations() if parser.may_parse(filename)]

    @classmethod
    def load(cls, file: str | os.PathLike[str] | IO[Any]) -> tuple[Entity, Parser]:
        """The root entity of a launch file (a path or an open file) and the parser that read
        it: the front-end its name's extension says, else each one in turn."""
        if cls is not Parser:  # a front-end's own load() is called with its text
            raise NotImplementedError
        if isinstance(file, (str, os.PathLike)):
            path = Path(file)
            try:
                data = path.read_bytes()
            except OSError as error:
                raise LaunchError(f"{path}: {error.strerror or error}") from None
        else:
            text = file.read()
            data = text.encode("utf-8") if isinstance(text, str) else text
            path = Path(getattr(file, "name", "") or "<launch>")
        chosen = cls.get_parsers_from_filename(path.name)
        candidates = chosen + [p for p in cls.implementations() if p not in chosen]
        errors = []
        for implementation in candidates:
            try:
                return implementation.load_bytes(data, path)
            except LaunchError as error:
                errors.append(str(error))
        raise InvalidFrontendLaunchFileError(f"{path}: no front-end reads it ({'; '.join(errors)})")

    @classmethod
    def load_bytes(cls, data: bytes, path: Path) -> tuple[Entity, Parser]:
        raise NotImplementedError

    def parse_action(self, entity: Entity) -> Any:
        """The action of one entity, by the parse method its tag exposed."""
        return self.build(entity)

    def build(self, entity: Entity) -> Any:
        """The action the parse method exposed for ``entity``'s tag builds (a parse method
        calls parse_action for the entities it holds: a front-end may defer those)."""
        _load_extensions()
        stack = self.__dict__.setdefault("_parsing", [])
        stack.append(entity)  # whose attributes parse_substitution is given
        try:
            return instantiate_action(entity, self)
        finally:
            stack.pop()

    def parse_substitution(self, value: str) -> list[Any]:
        """An attribute's text as substitutions, performed when an action needs it (errors
        name the line of the entity being parsed)."""
        from launch._base import element_at
        from launch.frontend.frontend_text import FrontendText

        stack = self.__dict__.get("_parsing") or [None]
        element = getattr(stack[-1], "element", None) or element_at("<launch>")
        return [FrontendText(value, element)]

    def parse_condition(self, entity: Entity) -> Any:
        """The IfCondition or UnlessCondition of an entity's ``if``/``unless``, or None."""
        from launch.conditions import IfCondition, UnlessCondition

        when = entity.get_attr("if", optional=True)
        unless = entity.get_attr("unless", optional=True)
        if when is not None and unless is not None:
            where = getattr(entity, "where", "<launch>")
            raise LaunchError(f"{where}: use either 'if' or 'unless', not both")
        if when is not None:
            return IfCondition(self.parse_substitution(when))
        if unless is not None:
            return UnlessCondition(self.parse_substitution(unless))
        return None

    def parse_if_substitutions(self, value: Any) -> Any:
        if isinstance(value, str):
            return self.parse_substitution(value)
        if isinstance(value, list):
            return [self.parse_if_substitutions(item) for item in value]
        return value

    def parse_description(self, entity: Entity) -> LaunchDescription:
        """The root <launch> as a LaunchDescription of the actions of its children."""
        from launch.launch_description import LaunchDescription

        if entity.type_name != "launch":
            raise LaunchError(f"the root tag is <{entity.type_name}>; expected <launch>")
        deprecated = entity.get_attr("deprecated", optional=True)
        actions = [self.parse_action(child) for child in entity.children]
        return LaunchDescription(actions, deprecated_reason=deprecated)


def _load_extensions() -> None:
    """The modules whose actions expose their tags, loaded by name as ros2/launch loads its
    'launch.frontend.launch_extension' entry points."""
    for name in EXTENSIONS:
        importlib.import_module(name)
