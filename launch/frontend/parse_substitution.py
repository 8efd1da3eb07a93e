"""The one ``$(...)`` scanner of the markup front-ends (ros2/launch's
``launch.frontend.parse_substitution``): text -> a list of ``Substitution`` objects, each
``$(name arg...)`` made by the parse method its substitution exposed
(``@expose_substitution("name")``), its arguments lists of substitutions themselves.

The rules, as launch's grammar reads them:

- Text outside ``$(...)`` is a TextSubstitution; quotes in it are plain characters.
- A backslash makes the next character plain (``\\$(`` is no substitution, ``\\)`` no end).
- Inside ``$(name ...)`` arguments are split on whitespace; ``'...'`` or ``"..."`` quote one
  argument (the quotes dropped; a ``$(...)`` inside is still performed; inside one kind of
  quotes the other kind is a plain character, in nested substitutions too).
- Parentheses inside an unquoted argument must balance (``$(eval 1+(2))``).

``scan`` is the scanner itself, shared with the launcher's ROS 1 dialect (its own table of
names, no escapes): it yields plain text and ``(name, [argument parts])`` pieces.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from launch_foundation.errors import LaunchError

MAX_NESTING = 50  # $(...) inside $(...): deeper is refused before it exhausts Python's stack
_ESCAPE = re.compile(r"\\(.)", re.DOTALL)
_NAME_END = frozenset(" \t\r\n)")


class SubstitutionSyntaxError(LaunchError):
    """Text whose ``$(...)`` cannot be read (unterminated, nested too deep); the front-end
    that parses it adds the file:line."""


def replace_escaped_characters(text: str) -> str:
    """A backslash gives the character after it."""
    return _ESCAPE.sub(r"\1", text) if "\\" in text else text


# A piece of scanned text: plain text, or a substitution (name, arguments), each argument a
# list of pieces.
Piece = Any


def scan(text: str, escapes: bool = True) -> list[Piece]:
    """``text`` as pieces: ``str`` for plain text (escapes already replaced) and
    ``(name, [argument, ...])`` for each ``$(...)``, every argument a list of pieces."""
    pieces, _ = _template(text, 0, escapes, quote="", depth=0, inside=False)
    return pieces


def _template(
    text: str, position: int, escapes: bool, quote: str, depth: int, inside: bool
) -> tuple[list[Piece], int]:
    """Pieces from ``position`` to the end (top level) or to the closing quote ``quote``."""
    pieces: list[Piece] = []
    plain: list[str] = []
    length = len(text)
    parens = 0  # in a quoted argument, a quote inside parentheses is a plain character
    while position < length:
        char = text[position]
        if escapes and char == "\\" and position + 1 < length:
            plain.append(text[position + 1])
            position += 2
            continue
        if quote and char == quote and parens == 0:
            break
        if inside and char in "()":
            parens = max(0, parens + (1 if char == "(" else -1))
        if char == "$" and text.startswith("$(", position):
            if plain:
                pieces.append("".join(plain))
                plain = []
            substitution, position = _substitution(text, position, escapes, quote, depth + 1)
            pieces.append(substitution)
            continue
        plain.append(char)
        position += 1
    else:
        if quote:
            raise SubstitutionSyntaxError(f"unterminated quote {quote} in {text!r}")
    if plain or not pieces:
        pieces.append("".join(plain))
    return pieces, position


def _substitution(
    text: str, start: int, escapes: bool, quote: str, depth: int
) -> tuple[tuple[str, list[list[Piece]]], int]:
    """The ``$(...)`` at ``start``: (name, arguments) and the position after its ``)``."""
    if depth > MAX_NESTING:
        raise SubstitutionSyntaxError(f"substitutions nested more than {MAX_NESTING} deep")
    position, length = start + 2, len(text)
    while position < length and text[position] in " \t\r\n":
        position += 1
    name_start = position
    while position < length and text[position] not in _NAME_END:
        position += 1
    name = text[name_start:position]
    arguments: list[list[Piece]] = []
    while True:
        while position < length and text[position] in " \t\r\n":
            position += 1
        if position >= length:
            raise SubstitutionSyntaxError(f"unterminated substitution in {text!r}")
        if text[position] == ")":
            break
        argument, position = _argument(text, position, escapes, quote, depth)
        arguments.append(argument)
    if not name:
        raise SubstitutionSyntaxError(f"a substitution without a name in {text!r}")
    return (name, arguments), position + 1


def _argument(
    text: str, position: int, escapes: bool, quote: str, depth: int
) -> tuple[list[Piece], int]:
    """One argument of a substitution: up to whitespace or the substitution's ``)``."""
    pieces: list[Piece] = []
    plain: list[str] = []
    parens, length = 0, len(text)

    def flush() -> None:
        if plain:
            pieces.append("".join(plain))
            plain.clear()

    while position < length:
        char = text[position]
        if escapes and char == "\\" and position + 1 < length:
            plain.append(text[position + 1])
            position += 2
            continue
        if char in " \t\r\n" and parens == 0:
            break
        if char == ")":
            if parens == 0:
                break
            parens -= 1
        elif char == "(":
            parens += 1
            if parens > MAX_NESTING:
                raise SubstitutionSyntaxError(f"parentheses nested more than {MAX_NESTING} deep")
        elif char in "'\"" and not quote:  # a quoted part: its quotes dropped
            flush()
            inner, position = _template(text, position + 1, escapes, char, depth, True)
            if position >= length:
                raise SubstitutionSyntaxError(f"unterminated quote {char} in {text!r}")
            pieces += [piece for piece in inner if piece != ""] or [""]
            position += 1
            continue
        elif char == quote:  # the enclosing quoted argument ends inside this substitution
            raise SubstitutionSyntaxError(f"unterminated substitution in {text!r}")
        if char == "$" and text.startswith("$(", position):
            flush()
            substitution, position = _substitution(text, position, escapes, quote, depth + 1)
            pieces.append(substitution)
            continue
        plain.append(char)
        position += 1
    flush()
    return pieces or [""], position


def build(pieces: list[Piece], make: Callable[[str, list[list[Any]]], Any]) -> list[Any]:
    """Pieces as substitutions: text a TextSubstitution, each ``(name, arguments)`` what
    ``make(name, arguments)`` returns for its arguments built the same way."""
    from launch._base import TextSubstitution

    out: list[Any] = []
    for piece in pieces:
        if isinstance(piece, str):
            out.append(TextSubstitution(text=piece))
        else:
            name, arguments = piece
            out.append(make(name, [build(argument, make) for argument in arguments]))
    return out


def parse_substitution(string_value: str) -> list[Any]:
    """Text -> substitutions, each ``$(name ...)`` by its exposed parse method."""
    from launch.frontend.expose import instantiate_substitution

    if not string_value:
        return build([""], instantiate_substitution)
    return build(scan(string_value), instantiate_substitution)


def parse_if_substitutions(value: Any) -> Any:
    """``value`` with the substitutions of its text parsed: text without any stays text,
    other scalars stay as they are, a list is read item by item and must be of one type."""
    from launch._base import TextSubstitution

    types: set[type] = set()

    def parse_one(item: Any) -> Any:
        if isinstance(item, str):
            parsed = parse_substitution(item)
            if len(parsed) == 1 and isinstance(parsed[0], TextSubstitution):
                types.add(str)
                return parsed[0].text
            return parsed
        types.add(type(item))
        return item

    output = [parse_one(item) for item in value] if isinstance(value, list) else parse_one(value)
    if len(types) > 1:
        raise ValueError("The result is a non-uniform list")
    return output


def parse_at(text: str, where: str) -> list[Any]:
    """``parse_substitution`` for a front-end: every substitution made knows ``where`` (the
    attribute's file:line) and an error names it."""
    from launch.frontend.expose import instantiate_substitution

    def make(name: str, arguments: list[list[Any]]) -> Any:
        try:
            substitution = instantiate_substitution(name, arguments)
        except LaunchError as error:
            raise LaunchError(f"{where}: {error}") from None
        except (TypeError, ValueError, AttributeError, RuntimeError) as error:
            raise LaunchError(f"{where}: $({name}): {error}") from None
        substitution.where = where
        return substitution

    try:
        pieces = scan(text) if text else [""]
    except SubstitutionSyntaxError as error:
        raise LaunchError(f"{where}: {error}") from None
    return build(pieces, make)


def perform_capped(parts: list[Any], context: Any, where: str) -> str:
    """The text of a front-end's attribute: its substitutions performed, refused past
    MAX_SUBSTITUTED characters, and counted toward the launch's MAX_LAUNCH_SUBSTITUTED."""
    from launch._base import element_at
    from launch_foundation.substitutions import MAX_SUBSTITUTED

    out: list[str] = []
    size = 0
    for part in parts:
        value = part.perform(context)
        size += len(value)
        if size > MAX_SUBSTITUTED:
            raise LaunchError(
                f"{where}: substitutions expand to more than {MAX_SUBSTITUTED:,} characters; "
                "refusing"
            )
        out.append(value)
    result = "".join(out)
    if len(parts) > 1 or not hasattr(parts[0], "text"):
        context.frontend_scope.charge(len(result), element_at(where))
    return result
