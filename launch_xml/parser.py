"""launch_xml.Parser: launch.frontend's Parser for launch XML files."""

from __future__ import annotations

from pathlib import Path

from launch.frontend.parser import Parser as BaseParser
from launch_foundation.parse import parse_bytes
from launch_xml.entity import Entity


class Parser(BaseParser):
    @classmethod
    def get_file_extensions(cls) -> set[str]:
        return {"xml", "launch"}

    @classmethod
    def load_bytes(cls, data: bytes, path: Path) -> tuple[Entity, Parser]:
        return Entity(parse_bytes(data, path)), cls()
