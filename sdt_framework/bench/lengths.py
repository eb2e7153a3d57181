"""Before any work: every recording holds one analysis window for every sensor.

A recording shorter than the settling time plus one window gives a sensor no
feature row. Met in a worker, it stopped a benchmark half-way (a TDMS channel
with no sample or one). A recording's length is in its metadata (the file's
header, read when the dataset is opened), so every recording is checked here,
before the first file is read, and the first one too short is named in one line
with its length and what one window needs.
"""

from __future__ import annotations

from collections.abc import Sequence

from ..data.recording import Recording
from ..errors import SDTError
from ..features import samples_for
from ..specs import SensorSpec

__all__ = ["check_lengths"]


def _needs(rate: float, sensors: Sequence[SensorSpec], window_s: float, settle_s: float):
    """(seconds, samples, target rate, sensor) of the sensor needing the longest input."""
    needs = []
    for sensor in sensors:
        target = float(sensor.at_rate(rate).sampling_rate_hz)
        samples = samples_for(window_s, target) + samples_for(settle_s, target)
        needs.append((samples / target, samples, target, sensor.name))
    return max(needs)


def check_lengths(
    recordings: Sequence[Recording], sensors: Sequence[SensorSpec], window_s: float, settle_s: float
) -> None:
    """Refuse the plan if a recording is shorter than ``settle_s`` + ``window_s`` for a sensor.

    A recording of ``n`` samples at ``fs`` becomes ``n / fs * target`` samples at a
    sensor's rate ``target``; it needs ``round(settle_s * target) + round(window_s *
    target)`` of them (:func:`~sdt_framework.features.samples_for`, as the windowing counts).
    """
    if not sensors:
        return
    needs = {}
    short = []
    for rec in recordings:
        rate = rec.sampling_rate_hz
        if rate not in needs:
            needs[rate] = _needs(rate, sensors, window_s, settle_s)
        _, samples, target, _ = needs[rate]
        if rec.samples_per_acquisition / rate * target < samples:
            short.append(rec)
    if not short:
        return
    first = short[0]
    seconds, samples, target, sensor = needs[first.sampling_rate_hz]
    n = first.samples_per_acquisition
    plural = "" if n == 1 else "s"
    more = f" (and {len(short) - 1} more recordings too short)" if len(short) > 1 else ""
    todo = "leave it out of the data or give a longer recording"
    if len(short) == len(recordings):
        todo = f"every recording is: give recordings of at least {seconds:.4g} s"
    raise SDTError(
        f"recording {first.recording_id} ({first.source}) holds {n:,} sample{plural} "
        f"per acquisition ({n / first.sampling_rate_hz:.4g} s at {first.sampling_rate_hz:g} Hz), "
        f"shorter than one {window_s:g} s window after {settle_s:g} s settling ({seconds:.4g} s: "
        f"{sensor} needs {samples:,} samples at {target:g} Hz){more}; {todo}"
    )
