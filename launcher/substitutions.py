"""Substitutions: the ``$(...)`` expressions in attribute values.

ROS 1: $(arg x) $(find pkg) $(env V) $(optenv V [default]) $(anon name) $(dirname) $(eval ...)
ROS 2: $(var x) $(env V [default]) $(find-pkg-share pkg) $(find-pkg-prefix pkg) $(dirname)
       $(anon name) $(not x) $(and x y) $(or x y) $(equals x y) $(eval ...) $(command ...)
Substitutions nest (``$(var $(var which))``). $(command) runs a program, so it is refused
unless the user passes --allow-code; so is an $(eval) that needs code to compute
(launcher/expressions.py reads the rest without running any).
"""

from __future__ import annotations

import math
import os
import shlex
import subprocess
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Protocol

from launcher import CodeRefused
from launcher.expressions import BUILTINS, MATH, NeedsCode, evaluate
from launcher.parse import Element
from ros_tutorials_common import packages
from ros_tutorials_common.bounded import MAX_INPUT_BYTES

TRUE_WORDS = ("true", "1")
MAX_NESTING = 50  # $(...) inside $(...): deeper is refused before it exhausts Python's stack
MAX_SUBSTITUTED = 1024 * 1024  # characters one attribute's substitutions may expand to
FALSE_WORDS = ("false", "0")


class Context(Protocol):
    """What a substitution can see: the scope it is written in (resolve.Scope)."""

    fmt: str
    file: Path
    args: dict[str, str]

    @property
    def allow_code(self) -> bool: ...

    def anon(self, name: str) -> str: ...

    def read_arg(self, name: str, element: Element) -> str: ...


def to_bool(value: str, element: Element, what: str) -> bool:
    word = value.strip().lower()
    if word in TRUE_WORDS:
        return True
    if word in FALSE_WORDS:
        return False
    raise element.error(f"{what} must be true, false, 1 or 0, not {value!r}")


def substitute(text: str, context: Context, element: Element) -> str:
    """Replace every $(...) in text; refuse a result longer than MAX_SUBSTITUTED characters
    (arguments whose defaults repeat the one before grow tenfold a level: ten levels of a
    1.2 KB file took the launcher to 10.8 GB)."""
    out, position, size = [], 0, 0
    while (start := text.find("$(", position)) >= 0:
        out.append(text[position:start])
        end = _closing_paren(text, start, element)
        value = _evaluate(text[start + 2 : end].strip(), context, element)
        size += start - position + len(value)
        if size > MAX_SUBSTITUTED:
            raise element.error(
                f"substitutions expand to more than {MAX_SUBSTITUTED:,} characters; refusing"
            )
        out.append(value)
        position = end + 1
    out.append(text[position:])
    return "".join(out)


def _closing_paren(text: str, start: int, element: Element) -> int:
    depth = 0
    for index in range(start + 1, len(text)):
        if text[index] == "(":
            depth += 1
            if depth > MAX_NESTING:
                raise element.error(f"substitutions nested more than {MAX_NESTING} deep")
        elif text[index] == ")":
            depth -= 1
            if depth == 0:
                return index
    raise element.error(f"unterminated substitution in {text!r}")


def _split_words(text: str) -> list[str]:
    """Split on spaces that are outside quotes and outside nested $(...); drop the quotes."""
    words: list[str] = []
    current: list[str] = []  # characters, joined once (adding to a string was quadratic)
    depth, quote, started = 0, "", False
    for char in text:
        if quote:
            if char == quote and depth == 0:
                quote = ""
                continue
        elif char in "'\"" and depth == 0:
            quote, started = char, True  # '' is an empty word, not no word
            continue
        elif char.isspace() and depth == 0:
            if started:
                words.append("".join(current))
            current, started = [], False
            continue
        depth += {"(": 1, ")": -1}.get(char, 0)
        current.append(char)
        started = True
    if started:
        words.append("".join(current))
    return words


def _evaluate(inner: str, context: Context, element: Element) -> str:
    name, _, rest = inner.partition(" ")
    table = ROS1 if context.fmt == "ros1" else ROS2
    if name not in table:
        known = ", ".join(f"$({known})" for known in table)
        raise element.error(f"unknown substitution $({name}); known here: {known}")
    if name == "command" and not context.allow_code:
        raise CodeRefused(f"{element.where}: $(command) runs a program named in the launch file")
    if context.fmt == "ros1" and name == "eval":
        return _ros1_eval(rest, context, element)  # ROS 1 eval sees raw Python, not $(...)
    words = [substitute(word, context, element) for word in _split_words(rest)]
    function, counts = table[name]
    if len(words) not in counts:
        raise element.error(f"$({name}) takes {_plural(counts)}, got {len(words)}: $({inner})")
    return function(words, context, element)


def _plural(counts: range) -> str:
    low, high = counts.start, counts.stop - 1
    return f"{low} argument(s)" if low == high else f"{low} to {high} arguments"


def _arg(words: list[str], context: Context, element: Element) -> str:
    return context.read_arg(words[0], element)


def _env(words: list[str], _context: Context, element: Element) -> str:
    value = os.environ.get(words[0], words[1] if len(words) > 1 else None)
    if value is None:
        raise element.error(f"environment variable {words[0]} is not set")
    return value


def _optenv(words: list[str], _context: Context, _element: Element) -> str:
    return os.environ.get(words[0], " ".join(words[1:]))


def _package_path(locate: Callable[[str], Path], words: list[str], element: Element) -> str:
    try:
        return str(locate(words[0]))
    except LookupError as error:
        raise element.error(str(error)) from None


def _find(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.package_folder, words, element)  # ROS 1: rospack find


def _find_share(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.share_directory, words, element)


def _find_prefix(words: list[str], _context: Context, element: Element) -> str:
    return _package_path(packages.prefix, words, element)


def _dirname(_words: list[str], context: Context, _element: Element) -> str:
    return str(context.file.parent)


def _anon(words: list[str], context: Context, _element: Element) -> str:
    return context.anon(words[0])


def _not(words: list[str], _context: Context, element: Element) -> str:
    return str(not to_bool(words[0], element, "$(not) argument")).lower()


def _and(words: list[str], _context: Context, element: Element) -> str:
    return str(all(to_bool(word, element, "$(and) argument") for word in words)).lower()


def _or(words: list[str], _context: Context, element: Element) -> str:
    return str(any(to_bool(word, element, "$(or) argument") for word in words)).lower()


def _equals(words: list[str], _context: Context, _element: Element) -> str:
    return str(words[0] == words[1]).lower()


def _python_eval(expression: str, names: dict, context: Context, element: Element) -> str:
    """An expression read by launcher/expressions.py, or, if it needs code and the user
    allowed it, by Python's eval with the same names (and the whole math module)."""
    shown = f"$(eval {expression})"
    try:
        try:
            return str(evaluate(expression, names))
        except NeedsCode as part:
            if not context.allow_code:
                raise CodeRefused(
                    f"{element.where}: {shown} runs code written in the launch file ({part})"
                ) from None
        scope = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}
        return str(eval(expression, {**scope, **names}))  # opted in with --allow-code
    except CodeRefused:
        raise
    except Exception as error:
        raise element.error(f"{shown} failed: {error}") from None


def _auto(value: str) -> object:
    """An argument's text typed as roslaunch types it for $(eval): a number, a bool, or text."""
    try:
        if "." in value:
            return float(value)
        if "_" not in value:  # Python reads 1_000 as a number; roslaunch keeps it text
            return int(value)
    except ValueError:
        pass
    return value.lower() == "true" if value.lower() in ("true", "false") else value


def _ros1_eval(expression: str, context: Context, element: Element) -> str:
    if "__" in expression:  # roslaunch refuses these too (they reach Python's internals)
        raise element.error(f"$(eval {expression}): '__' is not allowed in $(eval)")
    names: dict = {name: _auto(value) for name, value in context.args.items()}
    # roslaunch's functions and constants win over arguments of the same name.
    names.update(MATH, **BUILTINS, true=True, false=False)
    names["arg"] = lambda name: _auto(context.read_arg(name, element))
    names["env"] = lambda name: _env([name], context, element)
    names["optenv"] = lambda name, default="": os.environ.get(name, default)
    names["find"] = lambda package: _find([package], context, element)
    names["anon"] = context.anon
    names["dirname"] = lambda: str(context.file.parent)
    return _python_eval(expression, names, context, element)


def _ros2_eval(words: list[str], context: Context, element: Element) -> str:
    return _python_eval(" ".join(words), {**MATH, **BUILTINS}, context, element)


def _command(words: list[str], _context: Context, element: Element) -> str:
    try:
        command = shlex.split(" ".join(words))
    except ValueError as error:
        raise element.error(f"$(command {' '.join(words)}): {error}") from None
    shown = f"$(command {' '.join(words)})"
    # Its output is read with the same limit as a file (1 MiB); stderr goes to a file, so
    # neither pipe can fill up and block it, nor fill the launcher's memory.
    with tempfile.TemporaryFile() as errors:
        try:
            process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=errors)
        except OSError as error:
            raise element.error(f"{shown} failed: {error}") from None
        with process:
            assert process.stdout is not None
            out = process.stdout.read(MAX_INPUT_BYTES + 1)
            if len(out) > MAX_INPUT_BYTES:
                process.kill()
                raise element.error(f"{shown} printed more than 1 MiB")
            try:
                code = process.wait(timeout=60)
            except subprocess.TimeoutExpired:
                process.kill()
                raise element.error(f"{shown} failed: still running after 60 s") from None
        errors.seek(0)
        stderr = errors.read(64 * 1024).decode(errors="replace")
    if code != 0:
        reason = stderr.strip().splitlines()[-1:] or [f"exit code {code}"]
        raise element.error(f"{shown} failed: {reason[0]}")
    try:
        return out.decode()
    except UnicodeDecodeError:
        raise element.error(f"{shown} printed something that is not UTF-8 text") from None


ANY = range(1, 100)
ROS1 = {
    "arg": (_arg, range(1, 2)),
    "find": (_find, range(1, 2)),
    "env": (_env, range(1, 2)),
    "optenv": (_optenv, ANY),
    "anon": (_anon, range(1, 2)),
    "dirname": (_dirname, range(0, 1)),
    "eval": (None, ANY),
}
ROS2 = {
    "var": (_arg, range(1, 2)),
    "env": (_env, range(1, 3)),
    "find-pkg-share": (_find_share, range(1, 2)),
    "find-pkg-prefix": (_find_prefix, range(1, 2)),
    "dirname": (_dirname, range(0, 1)),
    "anon": (_anon, range(1, 2)),
    "not": (_not, range(1, 2)),
    "and": (_and, range(2, 100)),
    "or": (_or, range(2, 100)),
    "equals": (_equals, range(2, 3)),
    "eval": (_ros2_eval, ANY),
    "command": (_command, ANY),
}
