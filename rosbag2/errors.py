"""BagError, the one error of reading and writing bags, and how its line shows a path or a
library's error (a 5,000-character name, a multi-line exception) in one readable line."""

from __future__ import annotations

from pathlib import Path

from ros_tutorials_common.errors import ToolError


class BagError(ToolError):
    """A bag that cannot be read or written; the message names the file and the reason."""


def shown(path: Path | str, most: int = 120) -> str:
    """A path for an error line: a 5,000-character name shows its start and its length."""
    text = str(path)
    return text if len(text) <= most else f"{text[:most]}... ({len(text)} characters)"


def short(error: BaseException) -> str:
    """The first line of an error's message (its type's name if it has none)."""
    return str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
