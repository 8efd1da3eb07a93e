"""launch_yaml.Parser: launch.frontend's Parser for launch YAML files."""

from __future__ import annotations

from pathlib import Path

from launch.frontend.parser import Parser as BaseParser
from launch_foundation.parse import parse_yaml
from launch_yaml.entity import Entity


class Parser(BaseParser):
    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {"yaml", "yml"}

    @classmethod
    def load_bytes(cls, data: bytes, path: Path) -> tuple[Entity, Parser]:
        return Entity(parse_yaml(data, path)), cls()
