"""The ``synthetic-pump`` dataset: generated recordings behind the Recording interface.

Metadata is known without generating anything; ``Recording.load()`` generates
its run (all selected channels at once, since channels share their sources)
and keeps it for the process (:mod:`.kept`: up to 64 MB of runs, or the one run
being read where it is larger), so loading the channels of a run generates it once,
in a worker as in the main process, and a second benchmark over the same runs
generates none. Every recording's
``source`` names the generator's fingerprint (a hash of its two modules), so
features cached from an older generator are never served for a newer one.
"""

from __future__ import annotations

import hashlib
import math
import os
from collections.abc import Iterable
from functools import partial
from pathlib import Path

import numpy as np

from sdt_framework.data import Dataset, Recording
from sdt_framework.data.recording import measurement_groups
from sdt_framework.errors import SDTError
from sdt_framework.machine_files import spec_at_speeds

from . import model as m
from . import speeds as sp
from .generate import FS_HZ, generate_run
from .kept import KEEP_BYTES, kept_run

__all__ = ["DEFAULTS", "GENERATOR", "SyntheticPump", "open_synthetic"]

DEFAULTS = {"seed": 0, "acquisitions": 1, "duration": 12.0}
#: ``layout = "real"``: the real archive's columns per run (12 s each, five per 60 s
#: acquisition): healthy 60, a fault 15 (the data article: 10-20, 2-4 acquisitions)
REAL_LAYOUT = {"healthy": m.REAL_COLUMNS["healthy"], "fault": 15}
#: fingerprint of the generator: every module and data file of this package (the model,
#: the fault signatures, the code that draws, the marks and speeds) and the rig's speeds and
#: bearings it reads
_HERE = Path(__file__).parent
_FILES = sorted(p.name for p in _HERE.iterdir() if p.suffix in (".py", ".toml"))
MODULES = (*_FILES, "../pump_rig.toml")
GENERATOR = hashlib.sha256(b"".join(_HERE.joinpath(n).read_bytes() for n in MODULES)).hexdigest()[
    :12
]


def _select(value: str | Iterable[str] | None, known: Iterable[str], what: str) -> list[str]:
    known = list(known)
    if value is None:
        return known
    chosen = [value] if isinstance(value, str) else [str(v) for v in value]
    unknown = [v for v in chosen if v not in known]
    if unknown:
        raise SDTError(
            f"synthetic-pump: unknown {what} {', '.join(map(repr, unknown))}; "
            f"available: {', '.join(known)}"
        )
    return [k for k in known if k in chosen]


class SyntheticPump(Dataset):
    """Generated NLN-EMP-like recordings (see :func:`open_synthetic`)."""

    kept_bytes = KEEP_BYTES

    def __init__(
        self,
        *,
        seed: int,
        acquisitions: int,
        duration: float,
        machines: list[m.Machine],
        channels: list[str],
        conditions: list[str] | None,
        layout: str = "compact",
        glitches: bool = True,
    ) -> None:
        self.seed, self.acquisitions, self.duration = seed, acquisitions, duration
        self.glitches = glitches
        self._columns = {"healthy": acquisitions, "fault": acquisitions}
        if layout == "real":
            self._columns = dict(REAL_LAYOUT)
        self.channels = tuple(channels)
        recordings = []
        names = [machine.name for machine in machines]
        for machine in machines:
            # a machine at several speeds has a run per speed, "<speed>/<run>" as the NLN-EMP
            # reader names a run per speed folder: the unit a split keeps on one side
            prefix = f"{machine.speed}/" if names.count(machine.name) > 1 else ""
            for condition, levels in machine.conditions:
                if conditions is not None and condition not in conditions:
                    continue
                for level in m.levels_of(machine, condition, levels):
                    recordings += self._recordings(machine, condition, level, prefix)
        specs, notes = _specs(machines)
        super().__init__("synthetic-pump", recordings, [], notes, specs)

    def _recordings(
        self, machine: m.Machine, condition: str, level: int, prefix: str
    ) -> list[Recording]:
        """One recording per channel of the run (metadata only: nothing is generated)."""
        run, name = f"{condition} {level}", machine.name
        columns = self._columns["healthy" if condition == "healthy" else "fault"]
        point = m.RIG[name].speed_at(float(machine.speed))
        return [
            Recording(
                dataset="synthetic-pump",
                machine=name,
                speed=machine.speed,
                condition=condition,
                severity=None if condition == "healthy" else level,
                run=prefix + run,
                channel=ch,
                recording_id=f"{name}/{machine.speed}/{run}/{ch}",
                sampling_rate_hz=FS_HZ,
                units="g",
                n_acquisitions=columns,
                samples_per_acquisition=round(self.duration * FS_HZ),
                measurement=measurement_groups(columns),
                source=f"synthetic (generator {GENERATOR})",
                reader=partial(self._generate, machine.speed, name, condition, level, ch),
                speed_rpm=machine.rpm,
                speed_percent=float(machine.speed),
                speed_source=f"the generator's shaft speed, the rig's file at "
                f"{machine.speed} %: {point.source if point else ''}",
            )
            for ch in self.channels
        ]

    def _generate(
        self, speed: str, machine: str, condition: str, level: int, channel: str
    ) -> np.ndarray:
        columns = self._columns["healthy" if condition == "healthy" else "fault"]
        options = dict(
            channels=self.channels,
            acquisitions=columns,
            duration_s=self.duration,
            seed=self.seed,
            glitches=self.glitches,
            speed=float(speed),
        )
        key = (machine, condition, level, *sorted(options.items()))
        nbytes = len(self.channels) * columns * round(self.duration * FS_HZ) * 8
        run = kept_run(key, nbytes, lambda: generate_run(machine, condition, level, **options))
        return run[channel]


def _specs(machines: list[m.Machine]) -> tuple[dict, list[str]]:
    """The rig's spec of each machine generated at its spec's speed only, a note for another
    (:func:`~sdt_framework.machine_files.spec_at_speeds`, as the NLN-EMP reader decides)."""
    found: dict[str, list[str]] = {}
    for machine in machines:
        found.setdefault(machine.name, []).append(machine.speed)
    specs, notes = {}, []
    for name, at in found.items():
        spec, note = spec_at_speeds(name, m.RIG[name], at)
        if spec is not None:
            specs[name] = spec
        if note:
            notes.append(note)
    return specs, notes


def open_synthetic(
    path: str | os.PathLike[str] | None = None,
    *,
    seed: int = DEFAULTS["seed"],
    acquisitions: int = DEFAULTS["acquisitions"],
    duration: float = DEFAULTS["duration"],
    machines: str | Iterable[str] | None = None,
    channels: str | Iterable[str] | None = None,
    conditions: str | Iterable[str] | None = None,
    triaxial: bool = False,
    layout: str = "compact",
    glitches: bool = True,
    speeds: float | str | Iterable[float | str] | None = None,
) -> SyntheticPump:
    """The synthetic pump dataset (``path`` is ignored: nothing is read from disk).

    Parameters
    ----------
    seed
        Base seed; the same seed gives bit-identical signals.
    acquisitions
        Continuous acquisitions per run and channel (default 1).
    duration
        Length of each acquisition, s (default 12, as in NLN-EMP).
    machines, channels, conditions
        Subsets (default both machines, ch1-ch5, every class).
    triaxial
        Add ch6, so that ch6, ch2 and ch3 form a triaxial node on the motor drive-end
        bearing housing (x, y, z: ``model.NODE_AXES``); off by default, the
        paper's five channels. The other channels' signals do not change with it.
    layout
        ``"compact"`` (default): ``acquisitions`` columns per run; ``"real"``: the real
        archive's proportions, healthy runs 60 columns (12 acquisitions of 60 s), fault runs
        15 (3), each column ``duration`` long (columns 5k..5k+4 form one acquisition).
    glitches
        Common-mode glitches at the real archive's rate (21 of 575 records; on by default,
        as the real records carry them): spikes on several channels of one column at once,
        up to the recorder's +-50 g.
    speeds
        Operating speeds, % of rated (``speeds.toml``): Motor-2 runs at 50, 75 and 100,
        Motor-4 at 70. Default: the paper's protocol, each machine at its paper point
        (Motor-4 70, Motor-2 100). Given, each chosen machine is generated at each of
        these speeds it runs at, and only the machines that run at one of them are
        chosen unless ``machines`` names them (``[50, 75, 100]``: Motor-2 alone);
        ``"all"``: every speed of each. A machine at several speeds has a run per speed,
        ``"50/healthy 1"`` (the NLN-EMP reader's name of a run per speed folder).
    """
    if not isinstance(triaxial, bool):
        raise SDTError(f"synthetic-pump: triaxial must be true or false, got {triaxial!r}")
    if not isinstance(glitches, bool):
        raise SDTError(f"synthetic-pump: glitches must be true or false, got {glitches!r}")
    if layout not in ("compact", "real"):
        raise SDTError(f"synthetic-pump: layout must be 'compact' or 'real', got {layout!r}")
    if int(acquisitions) < 1:
        raise SDTError(f"synthetic-pump: acquisitions must be >= 1, got {acquisitions}")
    if not 0.2 < float(duration) < math.inf:
        raise SDTError(f"synthetic-pump: duration must be a finite number > 0.2 s, got {duration}")
    chosen_machines = _select(machines, m.MACHINES, "machine")
    at_speeds = sp.select(speeds, chosen_machines, explicit=machines is not None)
    known_conditions = {c for name in chosen_machines for c, _ in m.MACHINES[name].conditions}
    chosen_conditions = (
        None if conditions is None else _select(conditions, sorted(known_conditions), "condition")
    )
    return SyntheticPump(
        seed=int(seed),
        acquisitions=int(acquisitions),
        duration=float(duration),
        machines=at_speeds,
        channels=_select(
            channels, [*m.CHANNELS, *m.NODE_CHANNELS] if triaxial else m.CHANNELS, "channel"
        ),
        conditions=chosen_conditions,
        layout=layout,
        glitches=glitches,
    )
