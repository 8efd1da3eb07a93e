"""The ``$(eval ...)`` expressions launch files write, evaluated without running code.

Real launchers hand ``$(eval)`` to Python's ``eval``. Nearly every expression written in a
launch file is a comparison or a bit of logic or arithmetic on values already substituted in
(the Using-Substitutions tutorial: ``$(eval "200 == 200 and True")``), and such expressions
need no code: this module reads them with Python's own parser and computes them from a fixed
set of operations (values, names of the launch file's arguments, and/or/not, comparisons,
arithmetic, ``a if c else b``, calls of a few pure functions). Anything else (an attribute, a
subscript, a lambda, a call of any other function) raises ``NeedsCode``: it runs only with
--allow-code, through ``eval`` as the real launchers do.

Values are bounded by their size (about the length of their text, nested lists counted in
full), and an operation that would make a value too big is refused before it is computed:
``9**9**9``, ``'x' * 10**10``, ``[[1]*10**6]*10**6`` (a million references, but a text of
10**12 characters), ``'%0999999999d' % 1``. So no step runs for long or takes much memory,
and Ctrl-C is answered at once.
"""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Callable
from typing import Any

MAX_INT_BITS = 4096  # the largest integer an expression may make
MAX_LENGTH = 1024 * 1024  # the longest string or list an expression may make

# The math module's constants and its functions that are cheap for any argument (not
# factorial, comb, perm: math.factorial(10**9) runs for hours).
MATH = {name: getattr(math, name) for name in (
    "pi", "e", "tau", "inf", "nan", "sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
    "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "exp", "log", "log10", "log2", "floor",
    "ceil", "trunc", "fabs", "fmod", "hypot", "degrees", "radians", "copysign", "isclose",
    "isfinite", "isinf", "isnan", "gcd", "isqrt", "pow", "remainder",
)}  # fmt: skip


def _round(number: Any, ndigits: Any = None) -> Any:
    # round(10, -10**18) computes 10**(10**18) first.
    if isinstance(ndigits, int) and abs(ndigits) > MAX_INT_BITS:
        raise OverflowError(f"round() to more than {MAX_INT_BITS} digits")
    return round(number, ndigits)


# Python built-ins both launchers' expressions use, and that cannot run code.
BUILTINS: dict[str, Callable[..., Any]] = {"abs": abs, "min": min, "max": max, "round": _round,
    "int": int, "float": float, "str": str, "bool": bool, "len": len}  # fmt: skip

_BINARY = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
           ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
           ast.Pow: operator.pow}  # fmt: skip
_UNARY = {ast.Not: operator.not_, ast.USub: operator.neg, ast.UAdd: operator.pos}
_COMPARE = {ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt,
            ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge,
            ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
            ast.Is: operator.is_, ast.IsNot: operator.is_not}  # fmt: skip


class NeedsCode(Exception):
    """The expression is more than this evaluator reads: it needs Python's eval."""


def evaluate(expression: str, names: dict[str, Any]) -> Any:
    """The value of ``expression``, where ``names`` are the only names it may use.

    Raises NeedsCode for what only code can do, and ValueError, TypeError, ZeroDivisionError,
    NameError or OverflowError as Python would for a bad expression."""
    try:
        tree = ast.parse(expression.strip(), mode="eval")
    except SyntaxError as error:
        raise ValueError(f"invalid syntax: {error.msg}") from None
    return _value(tree.body, names)


def _size(value: Any, limit: int = MAX_LENGTH) -> int:
    """About the length of str(value), each reference to a list counted in full (what str()
    or == would go through); a walk that passes LIMIT stops there."""
    sizes: dict[int, int] = {}  # a list referenced many times is walked once

    def size(item: Any) -> int:
        if isinstance(item, str):
            return len(item) + 2
        if isinstance(item, bool) or item is None:
            return 5
        if isinstance(item, int):
            return item.bit_length() // 3 + 2  # its decimal digits and sign, at most
        if not isinstance(item, (list, tuple)):
            return 24  # a float, a function
        if id(item) not in sizes:
            total = 2
            for element in item:
                total += size(element) + 2
                if total > limit:
                    break
            sizes[id(item)] = total
        return sizes[id(item)]

    return size(value)


def _too_big(what: str = "a value") -> OverflowError:
    return OverflowError(f"{what} longer than {MAX_LENGTH} characters")


def _bounded(value: Any) -> Any:
    if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
        raise OverflowError(f"an integer of more than {MAX_INT_BITS} bits")
    if _size(value) > MAX_LENGTH:
        raise _too_big()
    return value


def _power(base: Any, exponent: Any) -> Any:
    # Checked before computing: 9 ** 9 ** 9 would take minutes only to be refused after.
    big = isinstance(base, int) and isinstance(exponent, int) and abs(base) > 1
    if big and exponent * max(base.bit_length() - 1, 1) > MAX_INT_BITS:
        raise OverflowError(f"an integer of more than {MAX_INT_BITS} bits")
    return base**exponent


def _repeat(left: Any, right: Any) -> Any:
    for sequence, count in ((left, right), (right, left)):  # 'ab' * 3 or 3 * 'ab'
        repeated = isinstance(sequence, (str, list, tuple)) and isinstance(count, int)
        if repeated and count > 0 and count * _size(sequence) > MAX_LENGTH:
            raise _too_big()
    return left * right


# A printf-style conversion: flags, width, precision (either may be '*', read from the values).
_CONVERSION = re.compile(r"%[-#0 +]*(\*|\d*)(?:\.(\*|\d*))?[hlL]?(.)", re.DOTALL)


def _format(text: str, values: Any) -> str:
    """text % values, refused before it is computed if its widths would make it too big."""
    given = values if isinstance(values, tuple) else (values,)
    numbers = [n for n in given if isinstance(n, int) and not isinstance(n, bool)]
    widths = 0
    for match in _CONVERSION.finditer(text):
        for part in match.group(1, 2):
            if part == "*":
                widths += max((abs(n) for n in numbers), default=0)
            elif part:
                widths += int(part)
    if len(text) + widths + _size(values) > MAX_LENGTH:
        raise _too_big("a formatted text")
    return text % values


def _binary(op: ast.operator, left: Any, right: Any) -> Any:
    if isinstance(op, ast.Pow):
        return _power(left, right)
    if isinstance(op, ast.Mult):
        return _repeat(left, right)
    if isinstance(op, ast.Mod) and isinstance(left, str):
        return _format(left, right)
    return _BINARY[type(op)](left, right)


def _value(node: ast.AST, names: dict[str, Any]) -> Any:
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float, str, bool)):
        return node.value
    if isinstance(node, ast.Constant) and node.value is None:
        return None
    if isinstance(node, ast.Name):
        if node.id not in names:
            raise NameError(f"name {node.id!r} is not defined")
        return names[node.id]
    if isinstance(node, ast.BoolOp):
        result = None
        for item in node.values:  # Python's short-circuit: the deciding operand is the value
            result = _value(item, names)
            if isinstance(node.op, ast.And) != bool(result):
                return result
        return result
    if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
        return _UNARY[type(node.op)](_value(node.operand, names))
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        left, right = _value(node.left, names), _value(node.right, names)
        return _bounded(_binary(node.op, left, right))
    if isinstance(node, ast.Compare):
        left = _value(node.left, names)
        for op, comparator in zip(node.ops, node.comparators, strict=True):
            right = _value(comparator, names)
            if not _COMPARE[type(op)](left, right):
                return False
            left = right
        return True
    if isinstance(node, ast.IfExp):
        test = _value(node.test, names)
        return _value(node.body if test else node.orelse, names)
    if isinstance(node, (ast.Tuple, ast.List)):
        items = [_value(item, names) for item in node.elts]
        return _bounded(tuple(items) if isinstance(node, ast.Tuple) else items)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        function = names.get(node.func.id)
        if callable(function) and not any(isinstance(a, ast.Starred) for a in node.args):
            return _bounded(function(*(_value(arg, names) for arg in node.args)))
    raise NeedsCode(ast.unparse(node))
