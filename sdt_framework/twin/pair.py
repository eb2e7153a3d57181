"""A paired recording: the reference and the device signals, each on its own even grid.

A pair is a TOML file naming two signal files (:mod:`.pair_toml`), or one
recorder file of several channels (an enDAQ IDE file): any file whose reader,
among those the caller hands down, lists channels
(:mod:`sdt_framework.signals.channels`). There the device is the acceleration
channel whose sensor table names the part the twin models (``ADXL345 ...``
for ``adxl345`` or a profile fitted from it), the reference the fastest other
acceleration channel (the piezo); either can be named by channel id. Only the
x/y/z subchannels are used (a microphone subchannel is not an axis).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

from ..errors import SDTError
from ..inputs import require_regular_file
from ..signals.channels import Channel, accelerometers, matches_part
from ..signals.files import channel_reader
from ..signals.rules import RATE_RANGE_HZ
from .pair_toml import is_pair_toml, load_toml_pair
from .signals import Pair, Signal, chosen_axes, digest, unit_mistake

__all__ = ["Pair", "Signal", "load_pair"]


def _pick(path: str, channels: list[Channel], sensor: str, device: int | None,
          reference: int | None) -> tuple[Channel, Channel]:  # fmt: skip
    listed = ", ".join(f"{c.id} ({', '.join(c.parts) or c.name})" for c in channels)
    by_id = {c.id: c for c in channels}
    for given, what in ((device, "device"), (reference, "reference")):
        if given is not None and given not in by_id:
            raise SDTError(
                f"{path}: no acceleration channel {given} for the {what}; it has {listed}"
            )
    if device is None:
        found = [c for c in channels if matches_part(c, sensor) and c.id != reference]
        if len(found) != 1:
            why = "none" if not found else "more than one"
            raise SDTError(
                f"{path}: {why} of the acceleration channels {listed} is the part of "
                f"{sensor!r}; name it with --device-channel"
            )
        device = found[0].id
    if reference is None:
        others = [c for c in channels if c.id != device]
        if not others:
            raise SDTError(f"{path}: only one acceleration channel ({listed}); no reference")
        reference = max(others, key=lambda c: c.rate_hz).id
    if reference == device:
        raise SDTError(f"{path}: the reference and the device are both channel {device}")
    return by_id[reference], by_id[device]


def _signal(reader: Any, path: str, channel: Channel, axes: list[str]) -> Signal:
    read = reader.read_channel(path, channel.id, axes)
    part = ", ".join(channel.parts) or None
    return Signal(f"channel {channel.id}", part, tuple(axes), read.values, read.rate_hz,
                  read.start_s, read.note, read.rate_sd_hz)  # fmt: skip


def load_pair(
    path: str | os.PathLike[str],
    sensor: str,
    *,
    readers: Sequence[Any],
    axes: list[str] | None = None,
    device_channel: int | None = None,
    reference_channel: int | None = None,
) -> Pair:
    """The pair at ``path`` for the twin of ``sensor`` (a profile name): a recorder file of
    channels (IDE), or a TOML pair file naming two signals (:mod:`.pair_toml`), read by
    ``readers`` (``registry.signal_readers()``, handed down)."""
    path = str(path)
    require_regular_file(path, "paired recording")  # a device or a pipe, named as such
    if is_pair_toml(path):
        if device_channel is not None or reference_channel is not None:
            raise SDTError(f"{path}: a TOML pair names its signals; channel options are for IDE")
        return _checked(load_toml_pair(path, readers, axes))
    reader = _channel_reader(path, readers)
    channels = accelerometers(reader.channels(path)[0])
    ref, dev = _pick(path, channels, sensor, device_channel, reference_channel)
    chosen = chosen_axes(
        path,
        [s.axis for s in ref.subchannels],
        [s.axis for s in dev.subchannels],
        axes,
        f"both channels {ref.id} and {dev.id}",
    )
    return _checked(
        Pair(
            path,
            _signal(reader, path, ref, chosen),
            _signal(reader, path, dev, chosen),
            digest(path),
        )
    )


def _channel_reader(path: str, readers: Sequence[Any]) -> Any:
    """The reader of ``path`` if its files hold channels, else refused."""
    reader = channel_reader(path, readers)
    if reader is None:
        formats = [f"{r.label}: {', '.join(r.suffixes)}" for r in readers if r.channels]
        raise SDTError(
            f"{path}: not a recorder file of channels ({'; '.join(formats) or 'none registered'})"
            f" nor a pair file (.toml); give a paired recording"
        )
    return reader


#: the two sides of one recording last about as long: a larger ratio is a unit mistake
DURATION_RATIO = 10.0


def _span(signal: Signal) -> str:
    n, rate = signal.values.shape[1], signal.rate_hz
    return f"{signal.label} holds {n:,} samples at {rate:.6g} Hz, {n / rate:.4g} s"


def _checked(pair: Pair) -> Pair:
    """``pair`` if the reference is faster than the device, the two sides last about as long,
    their rates are plausible and they overlap at least 1 s (one check for ``twin check``
    and ``twin fit``, IDE files and TOML pairs alike)."""
    path, ref, dev = pair.path, pair.reference, pair.device
    if ref.rate_hz <= dev.rate_hz:
        raise SDTError(
            f"{path}: the reference ({ref.label}, {ref.rate_hz:.6g} Hz) is not faster than "
            f"the device ({dev.label}, {dev.rate_hz:.6g} Hz); a twin needs a reference "
            f"sampled above the device's rate"
        )
    lasts = [s.values.shape[1] / s.rate_hz for s in (ref, dev)]
    ratio = max(lasts) / min(lasts) if min(lasts) > 0 else float("inf")
    if not ratio <= DURATION_RATIO:
        raise SDTError(
            f"{path}: {_span(ref)}; {_span(dev)}: one recording's two sides differ "
            f"{ratio:.4g}-fold in length; {unit_mistake()}"
        )
    lo, hi = RATE_RANGE_HZ
    for side in (ref, dev):
        if not lo <= side.rate_hz <= hi:
            raise SDTError(
                f"{path}: {side.label} runs at {side.rate_hz:.6g} Hz, outside {lo:g} Hz to "
                f"{hi:.0e} Hz (the twin's bands start at 10 Hz); {unit_mistake()}"
            )
    start = max(ref.start_s, dev.start_s)
    end = min(ref.end_s, dev.end_s)
    if end - start < 1.0:
        raise SDTError(
            f"{path}: the reference and the device overlap for {max(end - start, 0):.2f} s "
            f"(at least 1 s is needed); they are not one recording"
        )
    return pair
