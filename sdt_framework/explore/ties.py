"""Tied parameters: a field computed from the point's other values, e.g. ``"0.25 * rate"``.

Datasheets give filter corners as fractions of the output data rate, so a rate
sweep keeps them valid only if they move with the rate. An expression may use
numbers, the short names of SensorSpec fields (``rate``, ``nsd``, ``bits``, ...),
parentheses and ``+ - * /``; nothing else is evaluated (no names from Python,
no calls), so a sweep file cannot run code. A tie may set a stage parameter
(``"gauss-markov.tau_s" = "2"``) but not read one: ``stage.param`` is not a name.

An expression is at most :data:`MAX_TIE_CHARS` characters, checked before it
is parsed, so a huge one cannot exhaust the parser's recursion or the memory.
A division by a constant zero is refused with the file; a value that divides
by zero or is not finite only at some design points skips those points, with
the reason.
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Mapping

from ..errors import SDTError

__all__ = ["MAX_TIE_CHARS", "check_tie", "evaluate_tie"]

#: Longest tie accepted; datasheet ties such as "0.4999 * rate" are a dozen characters.
MAX_TIE_CHARS = 200

_OPS = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
}


def _parse(field: str, expression: str) -> ast.expr:
    if len(expression) > MAX_TIE_CHARS:
        raise SDTError(
            f"tie {field} is {len(expression)} characters long (at most {MAX_TIE_CHARS}); "
            f"write a short expression such as '0.25 * rate'"
        )
    try:
        return ast.parse(expression, mode="eval").body
    except (SyntaxError, RecursionError, MemoryError):
        raise SDTError(
            f"tie {field} = {expression!r} is not an expression; write e.g. '0.25 * rate'"
        ) from None


def _names(node: ast.expr, field: str, expression: str) -> set[str]:
    names: set[str] = set()
    for sub in ast.walk(node):
        if isinstance(sub, ast.Attribute):
            raise SDTError(
                f"tie {field} = {expression!r}: a tie may use only SensorSpec fields (rate, "
                f"nsd, ...), not stage parameters such as 'stage.param' (they are not names)"
            )
        if isinstance(sub, ast.Name):
            names.add(sub.id)
        elif isinstance(sub, ast.Constant) and isinstance(sub.value, int | float):
            continue
        elif not isinstance(sub, ast.BinOp | ast.UnaryOp | ast.Load | ast.USub | ast.UAdd) and (
            type(sub) not in _OPS
        ):
            raise SDTError(
                f"tie {field} = {expression!r}: only numbers, parameter names and + - * / "
                f"are allowed"
            )
    return names


def check_tie(field: str, expression: str, short_names: Mapping[str, str]) -> None:
    """Raise ValueError if ``expression`` uses anything but numbers, known names and arithmetic.

    A ValueError, so the sweep model's validation reports it with the file and key.
    """
    try:
        node = _parse(field, expression)
        names = _names(node, field, expression)
    except SDTError as exc:
        raise ValueError(str(exc)) from None
    known = set(short_names.values()) | set(short_names)
    unknown = sorted(names - known)
    if unknown:
        raise ValueError(
            f"tie {field} = {expression!r} names unknown parameter(s) {unknown}; "
            f"use {', '.join(sorted(short_names.values()))}"
        )
    for sub in ast.walk(node):
        constant = isinstance(sub, ast.BinOp) and isinstance(sub.op, ast.Div)
        if constant and not any(isinstance(n, ast.Name) for n in ast.walk(sub.right)):
            try:
                divisor = _walk(sub.right, {}, expression)
            except ZeroDivisionError:
                divisor = 0.0
            if divisor == 0:
                raise ValueError(f"tie {field} = {expression!r} divides by zero; fix the divisor")


def _walk(node: ast.expr, values: Mapping[str, float], expression: str) -> float:
    """The value of an expression tree that :func:`check_tie` accepted."""
    if isinstance(node, ast.Constant):
        return float(node.value)
    if isinstance(node, ast.Name):
        return float(values[node.id])
    if isinstance(node, ast.UnaryOp):
        inner = _walk(node.operand, values, expression)
        return -inner if isinstance(node.op, ast.USub) else inner
    if isinstance(node, ast.BinOp):
        left = _walk(node.left, values, expression)
        return _OPS[type(node.op)](left, _walk(node.right, values, expression))
    raise SDTError(f"cannot evaluate {expression!r}")


def evaluate_tie(expression: str, values: Mapping[str, float]) -> float:
    """The value of ``expression`` with ``values`` (short or long names) substituted.

    Raises ValueError (the point is skipped with this reason) when the expression
    divides by zero or gives a value that is not finite at these values.
    """
    node = _parse("", expression)
    try:
        value = _walk(node, values, expression)
    except ZeroDivisionError:
        value = math.nan
    if not math.isfinite(value):
        at = ", ".join(f"{k}={v:g}" for k, v in values.items() if k in _names_in(node))
        raise ValueError(
            f"tie {expression!r} is not a finite number at {at or 'this point'} "
            f"(a division by zero or an overflow)"
        )
    return value


def _names_in(node: ast.expr) -> set[str]:
    return {sub.id for sub in ast.walk(node) if isinstance(sub, ast.Name)}
