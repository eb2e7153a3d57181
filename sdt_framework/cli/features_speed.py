"""``sdt features extract``'s context for a feature set in orders of the running speed.

A set that needs the speed (``orders``, ``bearing-orders``) reads each band at
the recording's speed: ``--speed-rpm`` gives it; ``--nominal-rpm`` reads it off
the spectrum of the file's first acquisition near that speed
(:func:`sdt_framework.speed.estimate_running_speed`), and the features' metadata
names it an estimate with its confidence. ``--machines FILE --machine NAME``
gives the machine (its bearings, for ``bearing-orders``; its shaft speed as the
nominal one), ``--channel`` which bearing. No speed and none to estimate, or a
spectrum that shows no shaft line: one line, exit 2.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import SDTError
from ..specs import FeatureContext, FeatureSetSpec, MachineSpec

__all__ = ["SPEED_HELP", "extract_context"]

SPEED_HELP = {
    "speed": "Running speed, rpm, for a set in orders (orders, bearing-orders).",
    "nominal": "Estimate the speed off the spectrum near this rpm (named an estimate).",
    "machines": "Machine file (\\[machine.NAME] tables, docs/severity.md) for --machine.",
    "machine": "The machine in --machines: bearings for bearing-orders, shaft_rpm as nominal.",
    "channel": "The channel's name, which picks the machine's bearing listed at it.",
}


def _rpm(option: str, value: float | None) -> float | None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise SDTError(f"{option} {value:g}: give the shaft speed in rpm, above 0")
    return value


def _machine(machines: Path | None, name: str | None) -> MachineSpec | None:
    from ..machine_files import load_machine_file

    if name is None:
        if machines is not None:
            raise SDTError(f"--machines {machines}: name the machine in it with --machine NAME")
        return None
    if machines is None:
        raise SDTError(f"--machine {name}: give the machine file it is in with --machines FILE")
    found = load_machine_file(machines)
    if name not in found:
        raise SDTError(
            f"--machine {name}: {machines} has no machine {name!r}; it has "
            f"{', '.join(map(repr, sorted(found)))}"
        )
    return found[name]


def extract_context(
    spec: FeatureSetSpec,
    samples: np.ndarray,
    fs: float,
    label: str,
    *,
    speed_rpm: float | None,
    nominal_rpm: float | None,
    machines: Path | None,
    machine_name: str | None,
    channel: str | None,
) -> FeatureContext | None:
    """The context ``spec`` is computed with (None for a set that does not need the speed)."""
    from ..speed import estimate_running_speed

    speed_rpm = _rpm("--speed-rpm", speed_rpm)
    nominal_rpm = _rpm("--nominal-rpm", nominal_rpm)
    machine = _machine(machines, machine_name)
    if not spec.needs_speed:
        return None
    common = {"machine": machine, "channel": channel or "", "recording": label}
    if speed_rpm is not None:
        return FeatureContext(speed_rpm / 60.0, "given: --speed-rpm", **common)
    near = nominal_rpm if nominal_rpm is not None else (machine.shaft_rpm if machine else None)
    if near is None:
        raise SDTError(
            f"{label}: feature set {spec.name!r} works in orders of the running speed and the "
            f"file carries none; give --speed-rpm RPM, or --nominal-rpm RPM to read it off the "
            f"spectrum near that speed"
        )
    first = np.asarray(samples, dtype=float).reshape(-1, np.shape(samples)[-1])[0]
    estimate = estimate_running_speed(first, fs, near / 60.0)
    if estimate.source != "spectrum":
        raise SDTError(
            f"{label}: no running speed to read off the spectrum near {near:g} rpm "
            f"({estimate.reason}); give --speed-rpm RPM"
        )
    return FeatureContext(estimate.hz, f"estimate: {estimate.describe()}", **common)
