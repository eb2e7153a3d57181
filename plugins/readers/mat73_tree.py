"""The arrays of a MATLAB v7.3 file by their MATLAB names, inside structs and cells too.

MATLAB saves a v7.3 file as HDF5 (the layout h5py shows, written by MATLAB's
``save -v7.3``): a variable is a top-level dataset or group whose
``MATLAB_class`` attribute names its class; a struct is a group holding one
member per field; a cell is a dataset of references into ``#refs#``, one per
element; a struct array (``s(2).f``) is a struct group whose fields are such
datasets of references, one per element; an empty array is a dataset holding
its dimensions, marked ``MATLAB_empty``; a sparse matrix is a group marked
``MATLAB_sparse``. Recordings are often kept in structs and cells (``rec.acc``,
``trial{3}``), so each numeric array found there is a signal named as MATLAB
writes the expression that reaches it: ``s.f``, ``c{2}``, ``s(3).f``,
``s.c{1}.x`` (element numbers count in MATLAB's column-major order from 1).

Inside structs and cells only numeric and logical arrays that hold values are
listed (text fields, empty fields and objects are metadata, not signals); a
top-level variable is always listed, with the reason when it is not a signal,
so that a file holding nothing readable says what it holds.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from sdt_framework.signals.rules import names

from .mat import NUMERIC

#: structs and cells nested deeper than this are not followed (a file's references could loop)
MAX_DEPTH = 8
#: at most this many arrays are listed from one file
MAX_ARRAYS = 10_000


@dataclass(frozen=True)
class Array:
    """One array of the file: its MATLAB name, class and shape (MATLAB's order), and the dataset
    that holds it (None where the name is not an array: a struct, a cell, a sparse matrix)."""

    name: str
    cls: str
    shape: tuple[int, ...]
    dataset: Any = None
    why: str | None = None


def matlab_class(node: Any) -> str:
    """The ``MATLAB_class`` attribute ('' when absent)."""
    value = node.attrs.get("MATLAB_class", b"")
    return value.decode() if isinstance(value, bytes) else str(value)


def _is_references(node: Any) -> bool:
    import h5py

    return isinstance(node, h5py.Dataset) and h5py.check_dtype(ref=node.dtype) is not None


def dims(shape: tuple[int, ...]) -> str:
    """``10 x 1``: a shape as MATLAB prints it."""
    return " x ".join(f"{n:,}" for n in shape) if shape else "1 x 1"


def _dataset(name: str, node: Any, top: bool) -> Iterator[Array]:
    cls = matlab_class(node)
    if node.attrs.get("MATLAB_empty", 0):
        if top:  # the dataset holds the dimensions, in MATLAB's order
            yield Array(name, cls, tuple(int(n) for n in node[()]), why="empty")
        return
    shape = tuple(node.shape[::-1])
    if cls in NUMERIC and node.dtype.names:  # MATLAB stores complex as (real, imag)
        yield Array(name, cls, shape, why="complex")
    elif cls in NUMERIC | {"logical"} or top:
        yield Array(name, cls, shape, node)


def _elements(handle: Any, node: Any, name: str, field: str | None, depth: int) -> Iterator[Array]:
    """The arrays each reference of ``node`` leads to: cell elements ``name{k}``, or the field
    ``field`` of struct-array elements ``name(k).field``."""
    for k, ref in enumerate(node[()].ravel(), start=1):  # C order of h5py = MATLAB's linear
        if not ref:
            continue
        label = f"{name}{{{k}}}" if field is None else f"{name}({k}).{field}"
        yield from _walk(handle, handle[ref], label, depth + 1, top=False)


def _walk(handle: Any, node: Any, name: str, depth: int, top: bool) -> Iterator[Array]:
    import h5py

    cls = matlab_class(node)
    if depth > MAX_DEPTH:
        return
    if isinstance(node, h5py.Group):
        if "MATLAB_sparse" in node.attrs:
            if cls in NUMERIC | {"logical"}:
                yield Array(name, cls, (), why="sparse")
        elif cls == "struct":
            yield from _struct(handle, node, name, depth)
        elif top:
            yield Array(name, cls or "group", (), why="class")
    elif _is_references(node):
        if cls == "cell" or not cls:
            yield from _elements(handle, node, name, None, depth)
        elif top:
            yield Array(name, cls, tuple(node.shape[::-1]), why="class")
    else:
        yield from _dataset(name, node, top)


def _struct(handle: Any, group: Any, name: str, depth: int) -> Iterator[Array]:
    for field, member in group.items():
        if _is_references(member) and not matlab_class(member):  # a struct array's field
            yield from _elements(handle, member, name, field, depth)
        else:
            yield from _walk(handle, member, f"{name}.{field}", depth + 1, top=False)


def arrays(handle: Any) -> list[Array]:
    """Every array of an open v7.3 file (``h5py.File``), top-level variables first in name
    order, then what each struct or cell holds; a top-level struct or cell holding no numeric
    array is listed itself, as a ``struct`` or ``cell`` with its fields or size."""
    found: list[Array] = []
    for name, node in sorted(handle.items()):
        if name.startswith("#"):  # '#refs#', '#subsystem#': MATLAB's own storage
            continue
        inside = []
        for array in _walk(handle, node, name, 0, top=True):
            inside.append(array)
            if len(found) + len(inside) >= MAX_ARRAYS:
                break
        if not inside:  # a struct or cell holding no numeric array: say what it holds
            inside = [Array(name, matlab_class(node), tuple(getattr(node, "shape", ())[::-1]),
                            why=_contents(node))]  # fmt: skip
        found.extend(inside)
        if len(found) >= MAX_ARRAYS:
            break
    return found


def _contents(node: Any) -> str:
    """``holds no numeric array (fields 'a', 'b')``: why a struct or cell gives no signal."""
    import h5py

    if isinstance(node, h5py.Group):
        fields = sorted(node.keys())
        return f"holds no numeric array (fields {names(fields)})" if fields else "has no field"
    return "holds no numeric array"
