"""The synthetic pump at each of its speeds: the machine there, and each run's marks there.

``speeds.toml`` says which speeds each machine is generated at and where their
marks come from (the real per-channel statistics of that speed, or the law that
derives a speed between two measured ones); the rig's file gives each speed's
shaft rpm (``MachineSpec.speed_at``). At another speed everything tied to the
shaft moves with it, since the sources are orders of the running speed (1x, 2x,
vane pass, bearing defect rates, the slot-pass tone), the lines' forces scale as
a power of the speed, and the casing resonances stay where they are (Hz). Each
run's RMS, kurtosis and crest factor per channel come from that speed's marks,
which the mix reproduces (``mix.py``), as at the paper's points.
"""

from __future__ import annotations

import dataclasses
import math
import tomllib
from functools import cache
from pathlib import Path

import numpy as np

from sdt_framework.errors import SDTError

from . import model as m

__all__ = ["LINE_EXPONENT", "machine_at", "marks", "measured", "percents", "select", "target"]

_HERE = Path(__file__).parent
_PLAN = tomllib.loads((_HERE / "speeds.toml").read_text(encoding="utf-8"))
#: the lines' acceleration ~ shaft speed ** LINE_EXPONENT (speeds.toml, [lines], with its why)
LINE_EXPONENT = float(_PLAN["lines"]["exponent"])


def percents(name: str) -> tuple[float, ...]:
    """The speeds (% of rated) the generator runs ``name`` at, ascending."""
    plan = _PLAN["machine"][name]
    return tuple(sorted(float(p) for p in [*plan["marks"], *plan["derived"]]))


def _measured(name: str) -> list[float]:
    return sorted(float(p) for p in _PLAN["machine"][name]["marks"])


@cache
def machine_at(name: str, percent: float | None = None) -> m.Machine:
    """``name`` at ``percent`` % of rated speed (None: its paper point, ``model.MACHINES``).

    The shaft rpm is the rig's at that point (``MachineSpec.speed_at``); the runs are
    those its marks hold; the random draws are keyed by the speed too, so a run at
    another speed is another recording of the same rig.
    """
    base = m.MACHINES[name]
    if percent is None or math.isclose(percent, float(base.speed)):
        return base
    if not any(math.isclose(percent, p) for p in percents(name)):
        raise SDTError(
            f"synthetic-pump: {name} is not generated at {percent:g} %; it runs at "
            f"{', '.join(f'{p:g}' for p in percents(name))} %"
        )
    point = m.RIG[name].speed_at(percent)
    if point is None:  # speeds.toml lists a speed the rig's file cannot give: a packaging error
        raise SDTError(
            f"synthetic-pump: the rig's file gives no shaft speed for {name} at {percent:g} %"
        )
    held = {run for run in marks(name, percent)}
    absent = {
        (condition, level)
        for condition, levels in base.conditions
        for level in range(1, levels + 1)
        if f"{condition} {level}" not in held
    }
    return dataclasses.replace(
        base,
        speed=f"{percent:g}",
        rpm=point.shaft_rpm,
        absent=frozenset(absent),
        key=f"{name} at {percent:g} %",
        line_scale=(point.shaft_rpm / base.rpm) ** LINE_EXPONENT,
    )


def _rpm(name: str, percent: float) -> float:
    base = m.MACHINES[name]
    if math.isclose(percent, float(base.speed)):
        return base.rpm
    point = m.RIG[name].speed_at(percent)
    assert point is not None  # machine_at refused such a speed first
    return point.shaft_rpm


@cache
def _file(name: str) -> dict:
    return tomllib.loads((_HERE / name).read_text(encoding="utf-8"))


@cache
def marks(name: str, percent: float) -> dict[str, dict[str, tuple[float, float, float]]]:
    """run -> channel -> (RMS g, kurtosis, crest) of ``name`` at ``percent`` %.

    A speed with real statistics: its marks file. A derived speed: each value a power
    of the shaft speed through the two measured speeds around it (``speeds.toml``,
    [derived]), for the runs both of them hold.
    """
    plan = _PLAN["machine"][name]
    for key, file in plan["marks"].items():
        if math.isclose(float(key), percent):
            runs = _file(file)[name]
            return {run: {ch: tuple(v) for ch, v in chs.items()} for run, chs in runs.items()}
    measured = _measured(name)
    lo = max(p for p in measured if p < percent)
    hi = min(p for p in measured if p > percent)
    low, high = marks(name, lo), marks(name, hi)
    n, n_lo, n_hi = _rpm(name, percent), _rpm(name, lo), _rpm(name, hi)
    weight = math.log(n / n_lo) / math.log(n_hi / n_lo)
    return {
        run: {
            ch: tuple(
                float(a * (b / a) ** weight)
                for a, b in zip(low[run][ch], high[run][ch], strict=True)
            )
            for ch in low[run]
        }
        for run in low
        if run in high
    }


def target(machine: m.Machine, run: str, channel: str) -> tuple[float, float, float]:
    """(RMS g, kurtosis, crest factor) of ``run`` on ``channel`` at the machine's speed.

    The triaxial node's ch6 (horizontal, no real counterpart) takes ch1's, the other
    horizontal motor channel. A run the marks lack (a level or healthy run beyond the
    real ones, asked for through ``generate_run``) takes the mean of its class's runs on
    that channel.
    """
    name = "ch1" if channel == "ch6" else channel
    runs = marks(machine.name, float(machine.speed))
    if run in runs:
        return runs[run][name]
    condition = run.rsplit(" ", 1)[0]
    rows = [v[name] for k, v in runs.items() if k.rsplit(" ", 1)[0] == condition]
    return tuple(float(np.mean(col)) for col in zip(*rows, strict=True))  # type: ignore[return-value]


def measured(machine: m.Machine, run: str) -> bool:
    """Whether the marks hold ``run`` at the machine's speed (else its class mean stands in)."""
    return run in marks(machine.name, float(machine.speed))


def _percents(value: object) -> list[float]:
    """Speeds given as a number, a list of numbers or a text ("50,75,100"), % of rated."""
    items = list(value) if isinstance(value, (list, tuple, set, frozenset)) else [value]
    if isinstance(value, str):
        items = value.split(",")
    out = []
    for item in items:
        try:
            out.append(math.nan if isinstance(item, bool) else float(item))  # type: ignore[arg-type]
        except (TypeError, ValueError):
            out.append(math.nan)
    if not out or not all(0 < p < math.inf for p in out):  # NaN fails too
        raise SDTError(
            f"synthetic-pump: speeds must be percents of rated speed, e.g. [50, 75, 100], "
            f"'50,75,100' or 'all'; got {value!r}"
        )
    return out


def select(value: object, names: list[str], explicit: bool) -> list[m.Machine]:
    """The chosen machines at the chosen speeds (None: each at its paper point; "all": every
    speed each runs at); a speed no chosen machine runs at, or a machine the user named that
    runs at none of them, is one line."""
    if value is None:
        return [m.MACHINES[name] for name in names]
    if isinstance(value, str) and value.strip().lower() == "all":
        return [machine_at(name, q) for name in names for q in percents(name)]
    wanted = _percents(value)
    runs_at = {name: percents(name) for name in names}
    offered = "; ".join(f"{n} {', '.join(f'{p:g}' for p in ps)} %" for n, ps in runs_at.items())
    unknown = [
        p for p in wanted if not any(math.isclose(p, q) for ps in runs_at.values() for q in ps)
    ]
    if unknown:
        raise SDTError(
            f"synthetic-pump: no machine is generated at {', '.join(f'{p:g}' for p in unknown)} "
            f"% speed; the speeds are: {offered}"
        )
    chosen = {
        name: [q for q in ps if any(math.isclose(p, q) for p in wanted)]
        for name, ps in runs_at.items()
    }
    idle = [name for name, qs in chosen.items() if not qs]
    if explicit and idle:
        raise SDTError(
            f"synthetic-pump: {', '.join(idle)} runs at none of the speeds "
            f"{', '.join(f'{p:g}' for p in wanted)} %; the speeds are: {offered}"
        )
    return [machine_at(name, q) for name, qs in chosen.items() for q in qs]
