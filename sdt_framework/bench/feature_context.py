"""Before any work: the speed and machine of every recording, for a feature set in orders.

A feature set that works in orders of the running speed (``needs_speed``, the
``orders`` set) is handed each recording's :class:`~sdt_framework.specs.FeatureContext`:
its speed, its machine (bearings) and its channel. The speed is the one the
recording carries (an NLN-EMP speed folder, a manifest's ``speed_rpm``); where
it carries none it is read off the spectrum of its first acquisition near the
nominal speed (:func:`sdt_framework.data.speed.recording_speed`), put on the
recording named as an estimate with its confidence, and counted in a note. A
recording with no speed and no nominal speed to look near, or whose spectrum
shows no 1x line, is refused in one line naming it and what to give.

Then every order band is checked at every recording's speed against every
sensor's output rate (:func:`~sdt_framework.features.check_order_bands`), so a
band above a sensor's Nyquist frequency is one line before the first feature is
computed, naming the band, its order, the speed, the sensor and the recording.
A set that does not need the speed reads nothing and changes nothing.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from ..data.recording import Recording
from ..data.speed import nominal_rpm, recording_speed, with_estimate
from ..errors import SDTError
from ..features import check_order_bands, samples_for
from ..specs import FeatureContext, FeatureSetSpec, MachineSpec, SensorSpec

__all__ = ["check_order_rates", "feature_contexts"]


def _speed_of(recording: Recording, machine: MachineSpec | None) -> tuple[Recording, str]:
    """``recording`` with a speed (its own, else the estimate off its spectrum) and the
    estimate's confidence ("" for its own); or refuse."""
    if recording.speed_rpm is not None:
        return recording, ""
    nominal = nominal_rpm(recording, machine)
    where = f"recording {recording.recording_id!r} ({recording.source})"
    if nominal is None:
        raise SDTError(
            f"{where} carries no speed and there is no nominal speed to read it near; give its "
            f"speed (a speed_rpm column in the manifest) or its machine's shaft_rpm "
            f"(machines.toml, docs/severity.md 'Your machine'): order features need the speed"
        )
    estimate = recording_speed(recording, recording.load(), machine=machine)
    if estimate.source != "spectrum":
        raise SDTError(
            f"{where} carries no speed and its spectrum shows none near {nominal:g} rpm "
            f"({estimate.reason}); give its speed (a speed_rpm column in the manifest)"
        )
    return with_estimate(recording, estimate, machine), estimate.confidence


def feature_contexts(
    feature_set: FeatureSetSpec,
    recordings: Sequence[Recording],
    machines: dict[str, MachineSpec],
) -> tuple[list[Recording], dict[str, FeatureContext], list[str]]:
    """The recordings with a speed on each, their contexts by recording id, and notes.

    Unchanged recordings, no contexts and no notes for a set that does not need
    the speed. Recordings that carry no speed are read (their first acquisition's
    spectrum); see the module notes for what is refused.
    """
    if not feature_set.needs_speed:
        return list(recordings), {}, []
    out, contexts, sure = [], {}, Counter()
    for recording in recordings:
        machine = machines.get(recording.machine)
        recording, confidence = _speed_of(recording, machine)
        if confidence:
            sure[confidence] += 1
        source = recording.speed_source or "no source named"
        contexts[recording.recording_id] = FeatureContext(
            speed_hz=recording.speed_rpm / 60.0,
            speed_from=source if confidence else f"given: {source}",
            machine=machine,
            channel=recording.channel,
            recording=recording.recording_id,
        )
        out.append(recording)
    notes = []
    if sure:
        counts = ", ".join(f"{n} {level}" for level, n in sorted(sure.items()))
        notes.append(
            f"feature set {feature_set.name!r} works in orders of the running speed: the speed of "
            f"{sum(sure.values())} recording(s) that carry none was read off the spectrum "
            f"(features.parquet's speed column says which); confidence: {counts}"
        )
    return out, contexts, notes


def check_order_rates(
    feature_set: FeatureSetSpec,
    recordings: Sequence[Recording],
    contexts: dict[str, FeatureContext],
    sensors: Sequence[SensorSpec],
    window_s: float,
) -> None:
    """Refuse, in one line, an order band above a sensor's Nyquist at a recording's speed."""
    if not contexts:
        return
    seen = set()
    for recording in recordings:
        context = contexts[recording.recording_id]
        for sensor in sensors:
            rate = float(sensor.at_rate(recording.sampling_rate_hz).sampling_rate_hz)
            key = (rate, context.speed_hz, recording.machine, recording.channel)
            if key in seen:
                continue
            seen.add(key)
            n = samples_for(window_s, rate)
            try:
                check_order_bands(feature_set, rate, n, context, f"{sensor.name}'s output rate")
            except SDTError as exc:
                if repr(recording.recording_id) in str(exc):  # named already
                    raise
                raise SDTError(f"recording {recording.recording_id!r}: {exc}") from None
