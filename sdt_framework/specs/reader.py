"""ReaderSpec: a signal file format, registered by a plugin through ``register_signal_readers``.

A reader says which files it reads (``suffixes``, and a ``sniff`` of their
first bytes where a suffix is shared or absent) and provides three functions:

- ``scan(path, **options)`` -> list of :class:`~sdt_framework.signals.SignalInfo`,
  one per signal the file holds, reading headers only where the format allows
  (``sdt dataset inspect FILE``, ``sdt dataset manifest``);
- ``probe(path, variable, **options)`` -> the one ``SignalInfo`` a manifest row reads
  (``variable`` None: the file's only signal);
- ``read(path, variable, **options)`` -> float64 (n_acquisitions, n_samples), all
  finite, in the units ``probe`` reports.

``options`` are the reader's own manifest columns (``full_scale_g`` for integer
WAV files), listed in ``options`` so that the manifest knows them.

A reader may also say what a file costs before it is read: ``count(path,
variable)`` -> the values the file stores (every signal's, or ``variable``'s),
from its header, None where it cannot tell; ``parse_bytes_per_value``, the
peak memory its read takes per value beyond the float64 result (a text format
parsed whole). A command sizes a file through them
(:func:`sdt_framework.signals.file_sizes.file_samples`) and refuses one that
cannot fit before reading it.

A format whose files hold several channels, each a sensor on its own clock
(enDAQ IDE), also provides ``channels(path)`` -> (list of
:class:`~sdt_framework.signals.Channel`, notes) and ``read_channel(path,
channel, axes)`` -> :class:`~sdt_framework.signals.ChannelSignal`: ``sdt twin``
pairs two channels of such a file, ``sdt validate-noise --recording`` reads the
channel of the sensor's part and ``sdt dataset inspect`` lists them
(:mod:`sdt_framework.signals.channels`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar

from pydantic import Field, field_validator, model_validator

from .base import Spec

__all__ = ["ReaderSpec"]


class ReaderSpec(Spec):
    """A signal file format: suffixes, a sniffing check, and scan/probe/read functions."""

    kind: ClassVar[str] = "signal reader"
    _provenance: ClassVar[frozenset[str]] = frozenset(
        {
            "plugin",
            "distribution",
            "sniff",
            "scan",
            "probe",
            "read",
            "count",
            "channels",
            "read_channel",
        }
    )

    label: str = Field(description="Format name shown to users (``TDMS``, ``UFF58``).")
    suffixes: tuple[str, ...] = Field(description="File suffixes, lower case with the dot.")
    options: tuple[str, ...] = Field(
        default=(), description="Manifest columns the reader takes as keyword options."
    )
    sniff: Callable[[bytes], bool] | None = Field(
        default=None,
        exclude=True,
        description="sniff(first 1024 bytes) -> whether this reader reads the file.",
    )
    scan: Callable[..., Any] = Field(exclude=True, description="scan(path, **options).")
    probe: Callable[..., Any] = Field(exclude=True, description="probe(path, variable, **options).")
    read: Callable[..., Any] = Field(exclude=True, description="read(path, variable, **options).")
    count: Callable[..., int | None] | None = Field(
        default=None,
        exclude=True,
        description="count(path, variable) -> values stored, from the header (None: unknown).",
    )
    parse_bytes_per_value: float = Field(
        default=0.0,
        ge=0.0,
        description="Peak bytes per value a read takes beyond its float64 result (measured).",
    )
    channels: Callable[..., Any] | None = Field(
        default=None,
        exclude=True,
        description="channels(path) -> (channels, notes), for a file of several channels.",
    )
    read_channel: Callable[..., Any] | None = Field(
        default=None,
        exclude=True,
        description="read_channel(path, channel, axes) -> the channel's axes on one grid.",
    )

    @field_validator("suffixes")
    @classmethod
    def _check_suffixes(cls, value: tuple[str, ...]) -> tuple[str, ...]:
        for suffix in value:
            if not (suffix.startswith(".") and suffix == suffix.lower() and len(suffix) > 1):
                raise ValueError(f"suffix {suffix!r}: give it lower case with its dot ('.tdms')")
        return value

    @model_validator(mode="after")
    def _channels_together(self) -> ReaderSpec:
        if (self.channels is None) != (self.read_channel is None):
            raise ValueError("give both channels and read_channel, or neither")
        return self

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields plus the functions' qualified names."""
        data = super().content_dict()
        for key in ("scan", "probe", "read", "channels", "read_channel"):
            func = getattr(self, key)
            if func is not None:
                data[key] = f"{func.__module__}:{func.__qualname__}"
        return data
