"""Error types a user can act on.

Every error a user can cause derives from :class:`SDTError`. The CLI prints
such errors as one line (no traceback) and exits with status 2; anything else
is a bug and keeps its traceback.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

__all__ = [
    "DuplicateNameError",
    "PluginLoadError",
    "SDTError",
    "SpecFileError",
    "UnknownNameError",
]


class SDTError(Exception):
    """A problem in the user's input, configuration or environment."""


class UnknownNameError(SDTError, KeyError):
    """A name that no registered plugin provides."""

    def __init__(self, kind: str, name: str, available: Iterable[str]) -> None:
        self.kind = kind
        self.name = name
        self.available = sorted(available)
        close = difflib.get_close_matches(name, self.available, n=1, cutoff=0.5)
        hint = f" Did you mean {close[0]!r}?" if close else ""
        listed = ", ".join(self.available) if self.available else "(none registered)"
        super().__init__(f"unknown {kind} {name!r}.{hint} Available: {listed}.")

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
