"""Tied parameters: a field computed from the point's other values, e.g. ``"0.25 * rate"``.

Datasheets give filter corners as fractions of the output data rate, so a rate
sweep keeps them valid only if they move with the rate. An expression may use
numbers, the short names of SensorSpec fields (``rate``, ``nsd``, ``bits``, ...),
parentheses and ``+ - * /``; nothing else is evaluated (no names from Python,
no calls), so a sweep file cannot run code. A tie may set a stage parameter
(``"gauss-markov.tau_s" = "2"``) but not read one: ``stage.param`` is not a name.
"""

from __future__ import annotations

import ast
import operator
from collections.abc import Mapping

from ..errors import SDTError

__all__ = ["check_tie", "evaluate_tie"]

_OPS = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
}


def _parse(field: str, expression: str) -> ast.expr:
    try:
        return ast.parse(expression, mode="eval").body
    except SyntaxError:
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


def evaluate_tie(expression: str, values: Mapping[str, float]) -> float:
    """The value of ``expression`` with ``values`` (short or long names) substituted."""

    def walk(node: ast.expr) -> float:
        if isinstance(node, ast.Constant):
            return float(node.value)
        if isinstance(node, ast.Name):
            return float(values[node.id])
        if isinstance(node, ast.UnaryOp):
            inner = walk(node.operand)
            return -inner if isinstance(node.op, ast.USub) else inner
        if isinstance(node, ast.BinOp):
            return _OPS[type(node.op)](walk(node.left), walk(node.right))
        raise SDTError(f"cannot evaluate {expression!r}")

    return walk(ast.parse(expression, mode="eval").body)
