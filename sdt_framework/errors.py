"""Error types a user can act on, and the one for a bug in sdt.

Every error a user can cause derives from :class:`SDTError`. The CLI prints
such errors as one line (no traceback) and exits with status 2. Every one
pickles whatever its ``__init__`` takes (:meth:`SDTError.__reduce__`): an
error raised in a worker process (loky, Dask) reaches the main process as
itself, never as a pool broken by an error that cannot be rebuilt. Anything else
is a bug: :class:`InternalError` is raised where sdt finds one of its own
invariants broken, and the CLI reports it, like any other unexpected
exception, as an ``internal error:`` line asking for a report, exit status
:data:`INTERNAL_EXIT` (``SDT_DEBUG=1`` adds the traceback).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable

from pydantic import ValidationError

__all__ = [
    "INTERNAL_EXIT",
    "ArgumentTypeError",
    "ArgumentValueError",
    "DuplicateNameError",
    "InternalError",
    "PluginLoadError",
    "SDTError",
    "SDTWarning",
    "SpecFileError",
    "UnknownNameError",
    "UserInterruptError",
    "field_errors",
    "one_line",
    "shown",
    "validation_summary",
]


def _rebuild(cls: type[BaseException], args: tuple[object, ...], state: dict) -> BaseException:
    """``cls`` with ``args`` and attributes ``state``, without calling its ``__init__``."""
    exc = cls.__new__(cls, *args)
    exc.args = args
    exc.__dict__.update(state)
    return exc


class SDTError(Exception):
    """A problem in the user's input, configuration or environment.

    ``exit_code`` is the status the CLI exits with after printing the message.
    """

    exit_code: int = 2

    def __reduce__(self) -> tuple[object, ...]:
        """Pickle as message and attributes, so a subclass whose ``__init__`` takes other
        arguments than its message (:class:`UnknownNameError`) is rebuilt as it was.

        Python's default rebuilds an exception by calling ``cls(*self.args)``: for
        ``ChainInputError(sensor, label, reason)`` that call lacks two arguments, and a
        worker's error broke the whole process pool (``BrokenProcessPool``).
        """
        return _rebuild, (type(self), self.args, dict(self.__dict__))


#: exit status of a bug in sdt (EX_SOFTWARE of sysexits.h): never a user's mistake (2)
INTERNAL_EXIT = 70


class InternalError(RuntimeError):
    """A state sdt should never reach whatever the input: a bug in sdt, not a user error.

    Deliberately not an :class:`SDTError`, so no handler of user errors takes
    it for one; the CLI exits with :data:`INTERNAL_EXIT`.
    """


class SDTWarning(UserWarning):
    """A problem sdt worked around (a cache entry recomputed): one ``warning:`` line in the CLI."""


class UserInterruptError(SDTError):
    """The user stopped the command (Ctrl-C); the CLI exits with status 130."""

    exit_code = 130


class ArgumentTypeError(SDTError, TypeError):
    """A Python API argument of the wrong type (also a :class:`TypeError`)."""


class ArgumentValueError(SDTError, ValueError):
    """A Python API argument of the right type but an unusable value (also a ValueError)."""


class UnknownNameError(SDTError, KeyError):
    """A name that no registered plugin provides."""

    def __init__(self, kind: str, name: str, available: Iterable[str], *, note: str = "") -> None:
        self.kind = kind
        self.name = name
        self.available = sorted(available)
        close = difflib.get_close_matches(name, self.available, n=1, cutoff=0.5)
        hint = f" Did you mean {close[0]!r}?" if close else ""
        listed = ", ".join(self.available) if self.available else "(none registered)"
        tail = f" {note}" if note else ""
        super().__init__(f"unknown {kind} {name!r}.{hint} Available: {listed}.{tail}")

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return str(self.args[0])


class DuplicateNameError(SDTError):
    """Two plugins registered the same name for the same kind."""

    def __init__(self, kind: str, name: str, first: str, second: str) -> None:
        self.kind = kind
        self.name = name
        super().__init__(
            f"{kind} {name!r} is registered twice: by {first} and by {second}. "
            f"Uninstall one, or block one with SDT_BLOCK_PLUGINS."
        )


class PluginLoadError(SDTError):
    """A plugin that could not be imported or whose registration failed."""

    def __init__(self, plugin: str, distribution: str, reason: str) -> None:
        self.plugin = plugin
        self.distribution = distribution
        self.reason = reason
        super().__init__(f"plugin {plugin!r} (distribution {distribution}) failed: {reason}")


class SpecFileError(SDTError):
    """A TOML spec file that does not validate."""

    def __init__(self, path: object, field: str, reason: str) -> None:
        self.path = str(path)
        self.field = field
        self.reason = reason
        where = f" field {field!r}:" if field else ""
        super().__init__(f"{self.path}:{where} {reason}")


def one_line(text: object, limit: int = 300) -> str:
    """``text`` on one line (whitespace runs made one space), at most ``limit`` characters."""
    flat = " ".join(str(text).split())
    return flat if len(flat) <= limit else flat[: limit - 3] + "..."


def shown(value: object) -> str:
    """``repr`` of a value for a message, a NumPy scalar as the Python number it holds.

    NumPy 2 writes a scalar's repr as its constructor (``np.float64(nan)``,
    ``np.int64(5)``), which a message read by a person should not show: a value
    read from a file or passed through the Python API is often one. Every message
    that quotes a value goes through here (re-exported for the readers by
    :mod:`sdt_framework.signals.tokens`).

    >>> import numpy as np
    >>> shown(np.float64("nan")), shown(np.int64(5)), shown(0.1), shown("abc")
    ('nan', '5', '0.1', "'abc'")
    """
    if type(value).__module__ == "numpy" and getattr(value, "ndim", None) == 0:
        value = value.item()  # type: ignore[attr-defined]
    return repr(value)


#: how pydantic tags the branch of a union in an error's location ('constrained-float',
#: "literal['native']", 'function-after[...]', 'float'); a field or key is never one
_BRANCH_TAG = re.compile(r"^([a-z]+(-[a-z]+)+|[a-z-]+\[.*\]|float|int|str|bool|none)$", re.DOTALL)


def field_errors(
    exc: ValidationError, *, unknown: str = "unknown field", show_input: bool = False
) -> list[tuple[str, str]]:
    """(field, reason) of each error of a pydantic ``ValidationError``: the one way they read.

    ``field`` is the dotted path (a union's branch tags, such as
    'constrained-float', left out: the field is named once, with its first
    reason); ``reason`` is pydantic's message without its "Value error, "
    prefix, ``unknown`` for a key the model does not have (callers add where
    to look the keys up), and the value given if ``show_input``.
    """
    out: dict[str, str] = {}
    for error in exc.errors():
        loc = [str(p) for p in error.get("loc", ()) if not _BRANCH_TAG.match(str(p))]
        field = ".".join(loc)
        reason = str(error.get("msg", "invalid")).removeprefix("Value error, ")
        if error.get("type") == "extra_forbidden":
            reason = unknown
        if show_input and "input" in error:
            reason = f"{reason} (got {error['input']!r})"
        out.setdefault(field, reason)
    return list(out.items())


def validation_summary(exc: Exception) -> str:
    """One line naming each invalid field of a pydantic ``ValidationError`` and why.

    Other exceptions give ``"TypeName: message"`` on one line. The offending
    values are not quoted (they may be long); the field names are. A user
    file's error names its first field instead:
    :func:`sdt_framework.toml_files.validate_file`.
    """
    if not isinstance(exc, ValidationError):
        return one_line(f"{type(exc).__name__}: {exc}")
    parts = [f"field {f!r}: {reason}" if f else reason for f, reason in field_errors(exc)]
    return one_line("; ".join(parts))
