"""How ``sdt`` ends when something goes wrong: one line and an exit status, never a traceback
for a problem the user can act on.

- :class:`~sdt_framework.errors.SDTError`: ``error: <message>``, exit 2 (its ``exit_code``).
- Ctrl-C anywhere in a command: one ``interrupted:`` line, exit 130 (typer alone would exit
  130 silently). A command that wants a specific hint (how to resume) catches
  KeyboardInterrupt itself and raises :class:`~sdt_framework.errors.UserInterruptError`
  with it, or adds it as a note to the KeyboardInterrupt it re-raises.
- The environment's errors, :class:`OSError` (permission denied, read-only or full disk,
  a folder where a file is expected, a missing folder, HOME unusable) and
  :class:`MemoryError`: one line naming the path (for memory: the step that was
  building, see :func:`sdt_framework.signals.sizes.building`), the cause and what to
  do, exit 2.
- Anything else (an :class:`~sdt_framework.errors.InternalError`, or any other exception
  no code path expected) is a bug in sdt, never the user's mistake: one
  ``internal error:`` line naming the exception and where it was raised, asking for a
  report with the ``SDT_DEBUG=1`` output, exit status 70
  (:data:`~sdt_framework.errors.INTERNAL_EXIT`, EX_SOFTWARE).

``SDT_DEBUG=1`` prints the traceback of every error above (Ctrl-C excepted) before
its line; the line and the exit status stay the same.
"""

from __future__ import annotations

import contextlib
import errno
import os
import shlex
import sys
import traceback
import warnings
from collections.abc import Callable, Iterator
from typing import Any, NoReturn

import click
from typer.core import TyperGroup

try:  # a typer that carries its own copy of click raises that copy's usage errors
    from typer._click.exceptions import NoArgsIsHelpError, UsageError
except ImportError:  # an older typer parses with click itself
    from click.exceptions import NoArgsIsHelpError, UsageError

from ..errors import INTERNAL_EXIT, SDTError, SDTWarning, UserInterruptError, one_line
from .common import print_error, warn

__all__ = [
    "ENV_DEBUG",
    "InterruptibleGroup",
    "internal_error_line",
    "memory_error_line",
    "os_error_line",
    "run",
]

ENV_DEBUG = "SDT_DEBUG"

_PERMISSION = "check its permissions (and its folder's), or choose another location"
_ADVICE = {
    errno.ENOENT: "check the path; a folder on the way may be missing (HOME, --out, --cache-dir)",
    errno.EACCES: _PERMISSION,
    errno.EPERM: _PERMISSION,
    errno.EROFS: "the file system is read-only; choose a writable location",
    errno.ENOSPC: "the disk is full; free some space or choose another location",
    errno.EDQUOT: "the disk quota is used up; free some space or choose another location",
    errno.EISDIR: "a folder is where a file is expected; give a file path",
    errno.ENOTDIR: "a part of the path is a file, not a folder; check the path",
    errno.EEXIST: "it already exists; choose another path",
    errno.ENOTEMPTY: "the folder is not empty; choose another path",
    errno.ENAMETOOLONG: "the name is too long; use a shorter path",
    errno.EMFILE: "too many open files; raise the limit (ulimit -n) or use fewer --jobs",
}
_GENERIC = "an operating-system error; check the paths, permissions, free space and addresses given"


def os_error_line(exc: OSError) -> str:
    """One line for an OSError: the path(s), the system's reason, and what to do."""
    code = exc.errno if isinstance(exc.errno, int) else None
    reason = one_line(exc.strerror or exc or type(exc).__name__, 200)
    if code is not None:
        reason += f" ({errno.errorcode.get(code, code)})"
    advice = _ADVICE.get(code, _GENERIC) if code is not None else _GENERIC
    paths = [os.fsdecode(p) for p in (exc.filename, exc.filename2) if p is not None]
    if code == errno.EEXIST and paths and os.path.isfile(paths[0]):
        advice = "it is a file, where a folder is needed; choose another path"
    where = " -> ".join(repr(one_line(p, 200)) for p in paths) if paths else type(exc).__name__
    return f"{where}: {reason}; {advice}"


def memory_error_line(exc: MemoryError) -> str:
    """One line for a MemoryError: what was being built when it ran out, and what to do.

    The step is named by :func:`~sdt_framework.signals.sizes.building` where it
    was entered (the sweep design, its points, the benchmark's features); a
    MemoryError from elsewhere blames no particular input.
    """
    from ..signals import memory_cause

    detail = one_line(exc, 200) or "MemoryError"
    cause = memory_cause(exc)
    if cause is not None:
        what, reduce = cause
        return f"out of memory while {what} ({detail}); {reduce}, or use a machine with more memory"
    return (
        f"out of memory ({detail}); ask for less data at once (check the sizes asked for and "
        f"the files given) or use a machine with more memory"
    )


def internal_error_line(exc: BaseException, argv: list[str] | None = None) -> str:
    """One line for a bug: the exception, where it was raised, and how to report it."""
    frames = traceback.extract_tb(exc.__traceback__)
    where = ""
    if frames:
        last = frames[-1]
        where = f" (raised at {os.path.basename(last.filename)}:{last.lineno} in {last.name})"
    command = one_line(shlex.join(["sdt", *(sys.argv[1:] if argv is None else argv)]), 160)
    detail = one_line(f"{type(exc).__name__}: {exc}", 300)
    return (
        f"{detail}{where}; this is a bug in sdt (or in a plugin it runs), not a mistake in your "
        f"input; please report it with the output of: SDT_DEBUG=1 {command}"
    )


def _interrupt(exc: BaseException) -> UserInterruptError:
    notes = " ".join(getattr(exc, "__notes__", ()))
    return UserInterruptError(one_line(f"stopped by Ctrl-C. {notes}".strip(), 400))


@contextlib.contextmanager
def _usage_as_one_line() -> Iterator[None]:
    """A mistyped command line as one ``error:`` line (exit 2), not a usage box of five;
    ``sdt`` or a group alone still prints its help."""
    try:
        yield
    except NoArgsIsHelpError:
        raise
    except UsageError as exc:
        names, ctx = [], exc.ctx
        while ctx is not None and ctx.parent is not None:  # the root's name is always sdt
            names.append(ctx.info_name)
            ctx = ctx.parent
        where = f"; see {' '.join(['sdt', *reversed(names)])} --help" if exc.ctx else ""
        raise SDTError(one_line(exc.format_message().rstrip("."), 400) + where) from exc


class InterruptibleGroup(TyperGroup):
    """The root group: Ctrl-C inside any command becomes :class:`UserInterruptError`, and a
    mistyped option, value or command one ``error:`` line (``sdt`` or a group alone still
    prints its help)."""

    def make_context(self, *args: Any, **kwargs: Any) -> click.Context:
        """Parse ``sdt``'s own options; a usage error there becomes one line."""
        with _usage_as_one_line():
            return super().make_context(*args, **kwargs)

    def invoke(self, ctx: click.Context) -> Any:
        """Run the command; turn KeyboardInterrupt into one ``interrupted:`` line, exit 130,
        and a usage error of the command's options or of a command name into one line."""
        try:
            with _usage_as_one_line():
                return super().invoke(ctx)
        except KeyboardInterrupt as exc:
            raise _interrupt(exc) from exc


def _show_warning_line(show: Callable[..., None]) -> Callable[..., None]:
    """``warnings.showwarning`` printing sdt's own warnings as one ``warning:`` line.

    An :class:`~sdt_framework.errors.SDTWarning` (a cache entry recomputed) is
    news for the user, not a Python diagnostic: no source file and line.
    Other warnings go to ``show``, Python's own display.
    """

    def display(
        message: Warning | str,
        category: type[Warning],
        filename: str,
        lineno: int,
        file: Any = None,
        line: str | None = None,
    ) -> None:
        if issubclass(category, SDTWarning):
            warn(one_line(message, 2000))
        else:
            show(message, category, filename, lineno, file, line)

    return display


def run(app: Callable[[], Any]) -> None:
    """Call ``app`` and turn the errors above into one line and an exit status."""
    previous = warnings.showwarning
    warnings.showwarning = _show_warning_line(previous)
    try:
        _run(app)
    finally:
        warnings.showwarning = previous


def _run(app: Callable[[], Any]) -> None:
    try:
        app()
    except UserInterruptError as exc:
        _exit(str(exc), exc.exit_code, "interrupted:")
    except SDTError as exc:
        _exit(str(exc), exc.exit_code, exc=exc)
    except KeyboardInterrupt as exc:
        _exit(str(_interrupt(exc)), UserInterruptError.exit_code, "interrupted:")
    except OSError as exc:
        _exit(os_error_line(exc), 2, exc=exc)
    except MemoryError as exc:
        _exit(memory_error_line(exc), 2, exc=exc)
    except Exception as exc:  # a bug: say so, never as a user's mistake
        _exit(internal_error_line(exc), INTERNAL_EXIT, "internal error:", exc=exc)


def _exit(
    message: str, code: int, label: str = "error:", exc: BaseException | None = None
) -> NoReturn:
    """Print ``label message`` (after ``exc``'s traceback under ``SDT_DEBUG=1``), exit ``code``."""
    if exc is not None and os.environ.get(ENV_DEBUG):
        sys.stderr.flush()
        traceback.print_exception(exc, file=sys.stderr)
        sys.stderr.flush()
    print_error(message, label=label, style="yellow" if code == 130 else "bold red")
    sys.exit(code)
