"""The ``$(eval ...)`` expressions launch files write, evaluated without running code.

Real launchers hand ``$(eval)`` to Python's ``eval``. Nearly every expression written in a
launch file is a comparison or a bit of logic or arithmetic on values already substituted in
(the Using-Substitutions tutorial: ``$(eval "200 == 200 and True")``), and such expressions
need no code: this module reads them with Python's own parser and computes them from a fixed
set of operations (values, names of the launch file's arguments, and/or/not, comparisons,
arithmetic, ``a if c else b``, calls of a few pure functions). Anything else (an attribute, a
subscript, a lambda, a call of any other function) raises ``NeedsCode``: it runs only with
--allow-code, through ``eval`` as the real launchers do. Results are bounded, so
``9**9**9`` or ``'x' * 10**10`` is refused rather than exhausting the machine.
"""

from __future__ import annotations

import ast
import math
import operator
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
# Python built-ins both launchers' expressions use, and that cannot run code.
BUILTINS: dict[str, Callable[..., Any]] = {"abs": abs, "min": min, "max": max, "round": round,
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


def _bounded(value: Any) -> Any:
    if isinstance(value, int) and value.bit_length() > MAX_INT_BITS:
        raise OverflowError(f"an integer of more than {MAX_INT_BITS} bits")
    if isinstance(value, (str, list, tuple)) and len(value) > MAX_LENGTH:
        raise OverflowError(f"a value longer than {MAX_LENGTH} items")
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
        if repeated and count * len(sequence) > MAX_LENGTH:
            raise OverflowError(f"a value longer than {MAX_LENGTH} items")
    return left * right


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
        if isinstance(node.op, ast.Pow):
            return _bounded(_power(left, right))
        if isinstance(node.op, ast.Mult):
            return _bounded(_repeat(left, right))
        return _bounded(_BINARY[type(node.op)](left, right))
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
        return tuple(items) if isinstance(node, ast.Tuple) else items
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and not node.keywords:
        function = names.get(node.func.id)
        if callable(function) and not any(isinstance(a, ast.Starred) for a in node.args):
            return _bounded(function(*(_value(arg, names) for arg in node.args)))
    raise NeedsCode(ast.unparse(node))
