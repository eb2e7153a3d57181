"""Which sensors a benchmark runs: the default set, and the ones the data cannot simulate.

The default set is the paper's: the reference chain, ADXL345 and ADXL357
(catalogue parts join only when named). The reference follows the data
(SPEC section 9): ``wilcoxon-786b10`` (the chain that recorded NLN-EMP at
20 kHz) when every recording is at 20 kHz, otherwise ``native-reference``, the
recording as is at its own rate. A named sensor the data is too slow for is
not an error: it is left out with its reason (``simulation_problem``), and the
rest run; only an empty remainder is an error.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from ..chain.simulable import simulation_problem
from ..data.recording import Recording
from ..errors import SDTError
from ..specs import SensorSpec

__all__ = [
    "NATIVE_REFERENCE",
    "PAPER_RATE_HZ",
    "PAPER_REFERENCE",
    "default_reference",
    "default_sensor_names",
    "screen_sensors",
]

PAPER_REFERENCE = "wilcoxon-786b10"
NATIVE_REFERENCE = "native-reference"
PAPER_RATE_HZ = 20000.0
PAPER_SENSORS = ("adxl345", "adxl357")


def default_reference(rates: Iterable[float]) -> str:
    """``wilcoxon-786b10`` if every rate is 20 kHz, else ``native-reference``."""
    return PAPER_REFERENCE if set(rates) == {PAPER_RATE_HZ} else NATIVE_REFERENCE


def default_sensor_names(rates: Iterable[float]) -> list[str]:
    """The paper's sensor set with the reference that fits the data's rates."""
    return [default_reference(rates), *PAPER_SENSORS]


def screen_sensors(
    sensors: list[SensorSpec], recordings: list[Recording], axes: Mapping[str, str]
) -> tuple[list[SensorSpec], dict[str, str]]:
    """Split ``sensors`` into those the recordings can simulate and the rest, with reasons.

    Each sensor is checked at every rate in the data and on every axis the
    recordings' channels map to (``axes``: channel -> axis, default x).
    """
    examples: dict[tuple[float, str], Recording] = {}
    for rec in recordings:
        examples.setdefault((rec.sampling_rate_hz, axes.get(rec.channel, "x")), rec)
    kept: list[SensorSpec] = []
    skipped: dict[str, str] = {}
    for sensor in sensors:
        for (rate, axis), rec in sorted(examples.items(), key=lambda item: item[0]):
            problem = simulation_problem(sensor.for_axis(axis), rate)
            if problem is not None:
                on_axis = f" (axis {axis})" if axis != "x" else ""
                skipped[sensor.name] = f"{problem}{on_axis} (e.g. {rec.source})"
                break
        else:
            kept.append(sensor)
    if not kept:
        reasons = "; ".join(skipped.values())
        raise SDTError(
            f"no sensor can be simulated from this data: {reasons}; drop these from --sensors "
            f"or use data recorded faster"
        )
    return kept, skipped
