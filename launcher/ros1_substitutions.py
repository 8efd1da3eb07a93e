r"""roslaunch's substitutions, the ROS 1 dialect's own: ``$(arg x)`` ``$(find pkg)`` ``$(env V)``
``$(optenv V [default])`` ``$(anon name)`` ``$(dirname)`` ``$(eval ...)``, as roslaunch reads
them (no escapes; ``$(eval)`` sees raw Python, not ``$(...)``). They nest (``$(arg $(arg
which))``). The ROS 2 formats' ``$(...)`` are launch.frontend's scanner's, the model's one
engine for their text (launcher/attributes.py). An ``$(eval)`` that needs code to compute is
refused unless the user passes --allow-code (launch_foundation/expressions.py reads the rest
without running any).
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from pathlib import Path

from launch_foundation.errors import CodeRefused
from launch_foundation.expressions import BUILTINS, MATH, NeedsCode, evaluate
from launch_foundation.parse import Element
from launch_foundation.substitutions import MAX_NESTING, MAX_SUBSTITUTED, Context
from ros_tutorials_common import packages


def substitute(text: str, context: Context, element: Element) -> str:
    """Replace every $(...) in text; refuse a result longer than MAX_SUBSTITUTED characters
    (arguments whose defaults repeat the one before grow tenfold a level: ten levels of a
    1.2 KB file took the launcher to 10.8 GB)."""
    if "$(" not in text:
        return text
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
    result = "".join(out)
    context.charge(len(result), element)
    return result


def _closing_paren(text: str, start: int, element: Element) -> int:
    depth, index = 0, start + 1
    while index < len(text):
        char = text[index]
        if char == "(":
            depth += 1
            if depth > MAX_NESTING:
                raise element.error(f"substitutions nested more than {MAX_NESTING} deep")
        elif char == ")":
            depth -= 1
            if depth == 0:
                return index
        index += 1
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
    if name not in ROS1:
        known = ", ".join(f"$({known})" for known in ROS1)
        raise element.error(f"unknown substitution $({name}); known here: {known}")
    if name == "eval":
        return _ros1_eval(rest, context, element)  # ROS 1 eval sees raw Python, not $(...)
    words = [substitute(word, context, element) for word in _split_words(rest)]
    function, counts = ROS1[name]
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


def _dirname(_words: list[str], context: Context, _element: Element) -> str:
    return str(context.file.parent)


def _anon(words: list[str], context: Context, _element: Element) -> str:
    return context.anon(words[0])


def _python_eval(expression: str, names: dict, context: Context, element: Element) -> str:
    """An expression read by launch_foundation/expressions.py, or, if it needs code and the user
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
