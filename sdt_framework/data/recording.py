"""Recordings and datasets: metadata that is cheap, signals that are loaded lazily.

A :class:`Recording` is one channel of one physical run (all its acquisitions).
Its metadata (machine, condition, severity, run, channel, rate, shape) is known
without reading the signal, so listing a dataset of tens of gigabytes is
instant; :meth:`Recording.load` reads the samples only when asked, one file at
a time. A :class:`Dataset` holds the recordings it found plus a list of
:class:`Skipped` entries: bad input is never dropped silently, it is reported
with the file (and row) and counted.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from ..signals.errors import DataFileError, SignalTypeError

if TYPE_CHECKING:
    from ..specs import MachineSpec

__all__ = [
    "DataFileError",
    "Dataset",
    "Recording",
    "SignalTypeError",
    "Skipped",
    "measurement_groups",
]

#: consecutive 12 s acquisitions forming one 60 s measurement (SPEC section 4)
ACQUISITIONS_PER_MEASUREMENT = 5


def measurement_groups(n_acquisitions: int) -> tuple[int, ...]:
    """Measurement index of each acquisition: column ``i`` belongs to group ``i // 5``."""
    return tuple(i // ACQUISITIONS_PER_MEASUREMENT for i in range(n_acquisitions))


@dataclass(frozen=True)
class Skipped:
    """Something found but not used: the file (or directory) and why."""

    path: str
    reason: str

    def as_dict(self) -> dict[str, str]:
        """JSON-ready form."""
        return {"path": self.path, "reason": self.reason}


@dataclass(frozen=True)
class Recording:
    """One channel of one run: metadata plus a lazy loader.

    Attributes
    ----------
    dataset, machine, speed, condition, severity, run, channel
        Where the signal comes from. ``condition`` is the class label,
        ``severity`` the fault level (None for healthy), ``run`` the physical
        run (a condition directory, or a manifest ``recording_id``): the unit
        of a train/test split.
    recording_id
        Unique per run x channel.
    sampling_rate_hz, units
        Rate of the stored samples; units of the source file (``load`` returns g).
    n_acquisitions, samples_per_acquisition
        Shape of ``load()``.
    measurement
        Measurement group of each acquisition (60 s = five 12 s acquisitions).
    source
        File path, or ``"synthetic"``.
    speed_rpm, speed_percent, speed_source
        The operating (shaft) speed the recording was taken at, in rpm, and in %
        of the machine's rated speed where that is known (variable speed, issue
        43); ``speed_source`` says where the figures come from (e.g. "the
        archive's speed folder", "manifest speed_rpm", "estimate: 1470 rpm ...
        read off the spectrum, confidence high: ...") or why there is none,
        empty when nothing is known. ``speed`` is the dataset's own label of
        the operating point (an NLN-EMP speed folder).
        :mod:`sdt_framework.data.speed` reads the speed of a recording that
        carries none off its spectrum.
    """

    dataset: str
    machine: str
    speed: str | None
    condition: str
    severity: int | None
    run: str
    channel: str
    recording_id: str
    sampling_rate_hz: float
    units: str
    n_acquisitions: int
    samples_per_acquisition: int
    measurement: tuple[int, ...]
    source: str
    reader: Callable[[], np.ndarray] = field(repr=False, compare=False, hash=False)
    speed_rpm: float | None = None
    speed_percent: float | None = None
    speed_source: str = ""

    @property
    def total_samples(self) -> int:
        """Samples in all: ``n_acquisitions * samples_per_acquisition``."""
        return self.n_acquisitions * self.samples_per_acquisition

    def load(self) -> np.ndarray:
        """Read the signal: float64 array (n_acquisitions, samples_per_acquisition) in g.

        Raises
        ------
        DataFileError
            If the file is malformed or does not match the metadata; the
            message names the file and row.
        """
        data = np.asarray(self.reader(), dtype=np.float64)
        expected = (self.n_acquisitions, self.samples_per_acquisition)
        if data.shape != expected:
            raise DataFileError(
                f"{self.source}: recording {self.recording_id!r} has shape {data.shape}, "
                f"its metadata says {expected}"
            )
        return data

    def metadata(self) -> dict[str, Any]:
        """JSON-ready metadata (no samples)."""
        return {
            "dataset": self.dataset,
            "machine": self.machine,
            "speed": self.speed,
            "condition": self.condition,
            "severity": self.severity,
            "run": self.run,
            "channel": self.channel,
            "recording_id": self.recording_id,
            "sampling_rate_hz": self.sampling_rate_hz,
            "units": self.units,
            "n_acquisitions": self.n_acquisitions,
            "samples_per_acquisition": self.samples_per_acquisition,
            "measurement": list(self.measurement),
            "source": self.source,
            "speed_rpm": self.speed_rpm,
            "speed_percent": self.speed_percent,
            "speed_source": self.speed_source,
        }


class Dataset:
    """A named collection of recordings plus what was skipped while finding them.

    Subclasses only discover recordings; loading, failure bookkeeping and the
    summary live here once. ``notes`` are things a reader did to the data that
    a user should know (a CSV time column dropped), one line each. ``machines``
    are the machines the dataset describes (shaft speed, bearings, zone table),
    by the name its recordings give: what severity and the report read.
    """

    #: samples a dataset may keep in a process between reads (a cache), bytes: memory
    #: estimates count it beside the recording being read (:meth:`kept_at_most`)
    kept_bytes: int = 0

    def kept_at_most(self, samples: int) -> int:
        """Bytes this dataset keeps in a process between reads of recordings that hold
        ``samples`` float64 samples in all: :attr:`kept_bytes`, or all of them where fewer."""
        return min(self.kept_bytes, 8 * samples)

    def __init__(
        self,
        name: str,
        recordings: list[Recording],
        skipped: list[Skipped],
        notes: list[str] | None = None,
        machines: dict[str, MachineSpec] | None = None,
    ) -> None:
        self.name = name
        self._recordings = list(recordings)
        self._skipped = list(skipped)
        self.notes = list(notes or [])
        self.machines: dict[str, MachineSpec] = dict(machines or {})

    def recordings(self) -> list[Recording]:
        """Every usable recording (metadata only; nothing is read)."""
        return list(self._recordings)

    @property
    def skipped(self) -> list[Skipped]:
        """Files, directories and rows that were found but not used, with the reason."""
        return list(self._skipped)

    def runs(self) -> dict[str, list[Recording]]:
        """Recordings grouped by (machine, run): the unit of a train/test split."""
        out: dict[str, list[Recording]] = {}
        for rec in self._recordings:
            out.setdefault(f"{rec.machine}/{rec.run}", []).append(rec)
        return out

    def replace(self, recordings: list[Recording]) -> None:
        """Put each of ``recordings`` in place of the recording with its ``recording_id``
        (an updated copy: an estimated speed); an id the dataset does not hold is refused."""
        new = {r.recording_id: r for r in recordings}
        unknown = set(new) - {r.recording_id for r in self._recordings}
        if unknown:
            raise ValueError(f"{self.name}: no recording {sorted(unknown)[0]!r} to replace")
        self._recordings = [new.get(r.recording_id, r) for r in self._recordings]

    def load(self, recording: Recording) -> np.ndarray | None:
        """Load one recording; a bad file is moved to :attr:`skipped` and None returned."""
        try:
            return recording.load()
        except DataFileError as exc:
            self._recordings = [r for r in self._recordings if r is not recording]
            self._skipped.append(Skipped(recording.source, str(exc)))
            return None

    def iter_loaded(self) -> Iterator[tuple[Recording, np.ndarray]]:
        """Yield (recording, samples) for every recording that loads; bad ones are skipped."""
        for rec in self.recordings():
            data = self.load(rec)
            if data is not None:
                yield rec, data

    def validate(self) -> list[Skipped]:
        """Read every recording once (warming any cache); return what newly failed."""
        before = len(self._skipped)
        for _ in self.iter_loaded():
            pass
        return self._skipped[before:]

    def describe(self) -> dict[str, Any]:
        """Summary for ``sdt dataset inspect``: recordings, skipped entries, notes, the
        machines the dataset describes and counts."""
        recs = self._recordings
        return {
            "dataset": self.name,
            "recordings": [r.metadata() for r in recs],
            "skipped": [s.as_dict() for s in self._skipped],
            "notes": list(self.notes),
            "machines": {n: m.model_dump(mode="json") for n, m in self.machines.items()},
            "summary": {
                "recordings": len(recs),
                "runs": len(self.runs()),
                "machines": sorted({r.machine for r in recs}),
                "conditions": dict(sorted(Counter(r.condition for r in recs).items())),
                "channels": sorted({r.channel for r in recs}),
                "acquisitions": sum(r.n_acquisitions for r in recs),
                "skipped": len(self._skipped),
                "speeds": _speeds(recs),
            },
        }

    def summary_line(self) -> str:
        """One line: how many recordings, runs and skipped entries."""
        s = self.describe()["summary"]
        return (
            f"{self.name}: {s['recordings']} recordings in {s['runs']} runs "
            f"({', '.join(s['machines']) or 'no machines'}), {s['acquisitions']} acquisitions; "
            f"{s['skipped']} skipped"
        )


def _speeds(recordings: list[Recording]) -> list[dict[str, Any]]:
    """Each (machine, speed label, rpm, %, source) the recordings carry, with how many do."""
    keys = ("machine", "speed", "speed_rpm", "speed_percent", "speed_source")
    counts = Counter(tuple(getattr(r, k) for k in keys) for r in recordings)

    def order(key: tuple) -> tuple:
        machine, label, rpm, percent, source = key
        return machine, math.inf if percent is None else percent, label or "", rpm or 0, source

    rows = sorted(counts.items(), key=lambda kv: order(kv[0]))
    return [{**dict(zip(keys, key, strict=True)), "recordings": n} for key, n in rows]
