"""A recording's running speed: the one it carries, or an estimate read off its spectrum.

A recording carries its operating speed where its dataset knows it
(:class:`~sdt_framework.data.Recording`: ``speed_rpm``, ``speed_percent``,
``speed_source``): an NLN-EMP speed folder with the rig's shaft speed there, a
manifest's ``speed_rpm`` column. Where it carries none, the speed is read off
the spectrum of its first acquisition (the 1x line within 3 % of a nominal
speed, lines near the mains frequencies and their harmonics skipped:
:func:`sdt_framework.speed.estimate_running_speed`), and named as an estimate
with its confidence. The nominal speed to look near is the caller's, else the
machine's at the recording's operating point
(:meth:`~sdt_framework.specs.MachineSpec.speed_at`), else the machine's
``shaft_rpm``.

What a later step calls:

- :func:`recording_speed` -> :class:`~sdt_framework.speed.SpeedEstimate`: the
  speed of one loaded recording, given or estimated, with its confidence
  (``.hz``, ``.confidence``, ``.describe()``);
- :func:`estimate_speeds`: every recording of a dataset that carries no speed
  gets the estimate (in place), and notes say how many and how sure;
- :func:`select_speeds`: the recordings at some speeds (the benchmark's
  ``speeds``), by ``speed_percent`` or by the dataset's speed label.
"""

from __future__ import annotations

import dataclasses
import math
from collections import Counter
from collections.abc import Sequence

import numpy as np

from ..errors import SDTError
from ..specs import MachineSpec
from ..speed import SpeedEstimate, estimate_running_speed
from .recording import Dataset, Recording

__all__ = [
    "estimate_speeds",
    "nominal_rpm",
    "recording_speed",
    "select_speeds",
    "speed_matches",
    "with_estimate",
]


def nominal_rpm(recording: Recording, machine: MachineSpec | None = None) -> float | None:
    """The speed to look near: the recording's own, else its machine's at the recording's
    operating point (``speed_percent``), else the machine's ``shaft_rpm``; None without one."""
    if recording.speed_rpm is not None:
        return recording.speed_rpm
    if machine is None:
        return None
    if recording.speed_percent is not None:
        point = machine.speed_at(recording.speed_percent)
        if point is not None:
            return point.shaft_rpm
    return machine.shaft_rpm


def recording_speed(
    recording: Recording,
    data: np.ndarray,
    *,
    machine: MachineSpec | None = None,
    nominal: float | None = None,
) -> SpeedEstimate:
    """The running speed of ``recording`` (samples ``data``, as ``load()`` returns them).

    The speed it carries (``source`` "given", its ``speed_source`` as the reason), else
    read off the spectrum of its first acquisition near ``nominal`` rpm (default
    :func:`nominal_rpm`). Raises :class:`SDTError` when it carries none and there is
    no nominal speed to look near.
    """
    if recording.speed_rpm is not None:
        return SpeedEstimate(recording.speed_rpm / 60.0, "given", reason=recording.speed_source)
    near = nominal if nominal is not None else nominal_rpm(recording, machine)
    if near is None or not (math.isfinite(near) and near > 0):
        raise SDTError(
            f"recording {recording.recording_id!r} carries no speed and there is no nominal "
            f"speed to look near; give one (--nominal-rpm RPM), a speed_rpm column in the "
            f"manifest, or the machine's shaft_rpm in machines.toml (docs/data.md)"
        )
    first = np.asarray(data, dtype=float).reshape(-1, data.shape[-1])[0]
    return estimate_running_speed(first, recording.sampling_rate_hz, near / 60.0)


def with_estimate(
    recording: Recording, estimate: SpeedEstimate, machine: MachineSpec | None = None
) -> Recording:
    """``recording`` carrying ``estimate``: speed_rpm read off the spectrum and a source that
    names it an estimate with its confidence ("estimate: 1470 rpm (24.500 Hz) read off the
    spectrum, confidence high: ..."); unchanged for a given speed. An estimate
    that found no line leaves speed_rpm empty and says why in ``speed_source``."""
    if estimate.source == "given":
        return recording
    before = f"; {recording.speed_source}" if recording.speed_source else ""
    if estimate.source != "spectrum":
        source = f"no speed: the estimate from the spectrum read none ({estimate.reason}){before}"
        return dataclasses.replace(recording, speed_source=source)
    rpm = estimate.hz * 60.0
    percent = recording.speed_percent
    if percent is None and machine is not None and machine.rated_rpm is not None:
        percent = 100.0 * rpm / machine.rated_rpm
    return dataclasses.replace(
        recording,
        speed_rpm=rpm,
        speed_percent=percent,
        speed_source=f"estimate: {estimate.describe()}{before}",
    )


def estimate_speeds(dataset: Dataset, *, nominal: float | None = None) -> list[str]:
    """Give every recording of ``dataset`` that carries no speed the estimate off its spectrum.

    Each is read (a file that fails to read goes to ``skipped``, as ever) and looked at
    near ``nominal`` rpm, else near its machine's speed (``dataset.machines``). The
    notes, one line each (how many were estimated and how sure, how many had no nominal
    speed to look near), are added to ``dataset.notes`` and returned.
    """
    estimated, unsure, orphans = [], Counter(), []
    for recording in dataset.recordings():
        if recording.speed_rpm is not None:
            continue
        machine = dataset.machines.get(recording.machine)
        if nominal is None and nominal_rpm(recording, machine) is None:
            orphans.append(recording.recording_id)
            continue
        data = dataset.load(recording)
        if data is None:
            continue
        estimate = recording_speed(recording, data, machine=machine, nominal=nominal)
        unsure[estimate.confidence] += 1
        estimated.append(with_estimate(recording, estimate, machine))
    dataset.replace(estimated)
    notes = []
    if estimated:
        counts = ", ".join(f"{n} {level}" for level, n in sorted(unsure.items()))
        notes.append(
            f"speed estimated from the spectrum (the 1x line near the nominal speed, mains lines "
            f"skipped) for {len(estimated)} recording(s) that carry none; confidence: {counts}"
        )
    if orphans:
        notes.append(
            f"{len(orphans)} recording(s) carry no speed and have no nominal speed to look near "
            f"(first {orphans[0]!r}); give --nominal-rpm RPM, or the machine's shaft_rpm in "
            f"machines.toml"
        )
    dataset.notes.extend(notes)
    return notes


def _number(value: object) -> float | None:
    """A finite number from a number or its text (ASCII digits only); else None."""
    if isinstance(value, bool):
        return None
    try:
        number = float(value) if not isinstance(value, str) or value.isascii() else math.nan
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def speed_matches(recording: Recording, value: float | str) -> bool:
    """Whether ``recording`` runs at ``value``: its speed label as written (``"50"``), or
    the same number as its ``speed_percent`` or its numeric label (50, ``"50.0"``)."""
    if isinstance(value, str) and recording.speed == value.strip():
        return True
    number = _number(value)
    known = (recording.speed_percent, _number(recording.speed))
    return number is not None and any(x is not None and math.isclose(x, number) for x in known)


def _speeds_of(recordings: Sequence[Recording]) -> str:
    """The speeds ``recordings`` run at, for a message."""
    seen = {(r.machine, r.speed or "-", r.speed_percent) for r in recordings}

    def order(s: tuple) -> tuple:  # by % of rated, else by the label's number, else its text
        value = s[2] if s[2] is not None else _number(s[1])
        return (s[0], math.inf if value is None else value, s[1])

    ordered = sorted(seen, key=order)
    return ", ".join(
        f"{m} {label}" + ("" if p is None or _number(label) == p else f" ({p:g} %)")
        for m, label, p in ordered
    )


def select_speeds(recordings: Sequence[Recording], speeds: Sequence[float | str]) -> list:
    """The recordings at any of ``speeds`` (:func:`speed_matches`); a speed that no
    recording runs at is refused, naming the speeds the data has."""
    absent = [s for s in speeds if not any(speed_matches(r, s) for r in recordings)]
    if absent:
        named = ", ".join(f"{s:g}" if isinstance(s, float) else repr(s) for s in absent)
        raise SDTError(
            f"speeds: no recording at {named}; the data has {_speeds_of(recordings) or 'none'} "
            f"(machine and speed label, % of rated where it differs)"
        )
    return [r for r in recordings if any(speed_matches(r, s) for s in speeds)]
