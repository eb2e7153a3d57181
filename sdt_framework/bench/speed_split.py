"""The speed-transfer scenario: train at some operating speeds, test at another (issue 43).

A pump on a variable-frequency drive is diagnosed at speeds its classifier
never saw. The scenario asks what that costs each sensor, holding all else
equal: every run is split *within its own speed* by one of the paper's rules
(``split``, default forward: train on the lowest severity level, test on the
highest; healthy runs: all but the last train), and each fold, tested at speed
T, has two arms on the same test runs:

- ``speed T -> T`` (within speed): trained on the split's training runs at T;
- ``speed S -> T`` (speed shift): trained on the split's training runs at the
  speeds S instead (several joined by ``+``: ``speed 50+100 -> 75``).

Their difference is the loss under the speed shift, paired run by run (same
test recordings, noise draws and seeds); ``sdt compare`` and the report show
it per sensor and per class. Leave-one-speed-out (``--scenarios
speed-transfer``) makes one fold per speed of each machine, trained at all its
other speeds; ``speed_transfer = {train = [100], test = [75]}`` names one pair.
``split = "all"`` trains on every run at S and tests on every run at T (the
literature's leave-one-speed-out), which leaves no run to train a within-speed
arm on: it has the shift arm only.

A run's speed is its dataset's label of the operating point (an NLN-EMP speed
folder, a manifest's ``speed``), else its % of rated speed, else its shaft
speed (``1480 rpm``): :func:`speed_key`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Literal

import pandas as pd
from pydantic import BaseModel, ConfigDict, field_validator, model_validator

from ..data.recording import Recording
from ..data.speed import speed_matches
from ..errors import SDTError
from .scenarios import (
    COLUMNS,
    Run,
    natural,
    parse_speed_scenario,
    rule_allocation,
    speed_scenario,
)

__all__ = [
    "SPEED_TRANSFER",
    "SpeedTransfer",
    "check_speeds",
    "matches",
    "speed_allocation",
    "speed_key",
    "speed_title",
]

#: the scenario's name in ``scenarios`` (``--scenarios speed-transfer``)
SPEED_TRANSFER = "speed-transfer"


class SpeedTransfer(BaseModel):
    """The config's ``speed_transfer`` table: one pair of speeds, and the split within a speed."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)

    train: list[float | str] | None = None
    test: list[float | str] | None = None
    split: Literal["forward", "backward", "interpolation", "all"] = "forward"

    @field_validator("train", "test", mode="before")
    @classmethod
    def _speeds(cls, value: object) -> object:
        if isinstance(value, list) and not value:
            raise ValueError("must name at least one speed, e.g. [100]")
        return check_speeds(value, "75")

    @model_validator(mode="after")
    def _pair(self) -> SpeedTransfer:
        if (self.train is None) != (self.test is None):
            given, lacking = ("train", "test") if self.train is not None else ("test", "train")
            raise ValueError(
                f"gives {given} but no {lacking}; name both (train = [100], test = [75]), or "
                f"neither for leave-one-speed-out"
            )
        both = [t for t in self.test or () if any(_same(t, s) for s in self.train or ())]
        if both:
            raise ValueError(
                f"{_shown(both[0])} is both a training and a test speed; a speed transfer "
                f"tests at a speed it did not train at"
            )
        return self


def check_speeds(value: object, example: str) -> object:
    """``value`` if each item of a list of speeds is a speed (a positive number, or a label);
    else ValueError naming the item (pydantic's "before" check of ``speeds`` lists)."""
    for item in value if isinstance(value, list) else ():
        if isinstance(item, bool) or (isinstance(item, str) and not item.strip()):
            shown = str(item).lower() if isinstance(item, bool) else repr(item)
            raise ValueError(
                f"{shown} is not a speed; give a number ({example}) or a label ('{example}')"
            )
        if isinstance(item, int | float) and not item > 0:
            raise ValueError(f"{item!r} is not a speed; give a positive number (% of rated)")
    return value


def _number(value: float | str) -> float | None:
    try:
        number = float(value)
    except ValueError:
        return None
    return number if math.isfinite(number) else None


def _same(a: float | str, b: float | str) -> bool:
    x, y = _number(a), _number(b)
    if x is not None and y is not None:
        return math.isclose(x, y)
    return str(a).strip() == str(b).strip()


def _shown(value: float | str) -> str:
    return f"{value:g}" if isinstance(value, float | int) else repr(value)


def speed_key(recording: Recording) -> str | None:
    """The operating point a recording ran at, as scenario labels name it; None if unknown.

    The dataset's label (``"75"``, ``"full"``), else the % of rated speed
    (``"75"``), else the shaft speed (``"1110 rpm"``).
    """
    if recording.speed is not None and recording.speed.strip():
        return recording.speed.strip()
    if recording.speed_percent is not None:
        return f"{recording.speed_percent:g}"
    if recording.speed_rpm is not None:
        return f"{recording.speed_rpm:g} rpm"
    return None


def speed_title(name: object) -> str | None:
    """A speed scenario's heading (Table 4, the report); None for any other name."""
    parsed = parse_speed_scenario(name)
    if parsed is None:
        return None
    train, test = parsed
    if train == (test,):
        return f"Within speed: trained and tested at {test}"
    return f"Speed transfer: trained at {'+'.join(train)}, tested at {test}"


def matches(recording: Recording, value: float | str) -> bool:
    """Whether ``recording`` runs at ``value``: as ``speeds`` selects (its label, its % of
    rated), or its speed key as shown (``"1110 rpm"``), or its shaft speed in rpm."""
    if speed_matches(recording, value) or speed_key(recording) == str(value).strip():
        return True
    number = None if isinstance(value, str) else float(value)
    return (
        number is not None
        and recording.speed_rpm is not None
        and math.isclose(recording.speed_rpm, number)
    )


def _fold_speeds(
    speeds: dict[str, list[str]], setting: SpeedTransfer | None, found: dict[str, set[str]]
) -> tuple[dict[str, list[tuple[tuple[str, ...], str]]], dict[tuple[str, str], str]]:
    """Per machine, its folds (training speeds, test speed); machines with none, and why."""
    folds: dict[str, list[tuple[tuple[str, ...], str]]] = {}
    skipped: dict[tuple[str, str], str] = {}
    for machine, keys in sorted(speeds.items()):
        if setting is None or setting.train is None:
            if len(keys) < 2:
                skipped[(machine, SPEED_TRANSFER)] = (
                    f"runs at one speed only ({keys[0]}): speed transfer needs two"
                )
                continue
            folds[machine] = [(tuple(k for k in keys if k != t), t) for t in keys]
            continue
        train = tuple(k for k in keys if k in found["train"])
        tests = [k for k in keys if k in found["test"]]
        if not train or not tests:
            side = "training" if not train else "test"
            skipped[(machine, SPEED_TRANSFER)] = (
                f"no run at the {side} speed(s) of speed_transfer (its runs are at "
                f"{', '.join(keys)})"
            )
            continue
        folds[machine] = [(train, t) for t in tests]
    return folds, skipped


def speed_allocation(
    runs: Iterable[Run],
    recordings: Sequence[Recording],
    setting: SpeedTransfer | None,
) -> tuple[pd.DataFrame, dict[tuple[str, str], str]]:
    """The speed-transfer allocation of ``runs`` (their ``speed`` set), and machines left out.

    ``recordings`` are the runs' recordings (a configured speed is matched against
    them as ``speeds`` is). Raises :class:`SDTError` when no machine has two speeds, a
    configured speed is absent from the data, or one run would sit on both sides.
    """
    runs = list(runs)
    speeds: dict[str, list[str]] = {}
    for run in runs:
        if run.speed is not None:
            speeds.setdefault(run.machine, []).append(run.speed)
    speeds = {m: sorted(set(k), key=natural) for m, k in speeds.items()}
    if not speeds:
        raise SDTError(
            "speed transfer needs the speed of each run, and no run carries one: give a "
            "manifest's speed_rpm or speed column, or read an NLN-EMP archive's speed folders "
            "(docs/data.md, 'Speed of a recording')"
        )
    found = _configured(runs, recordings, setting)
    folds, skipped = _fold_speeds(speeds, setting, found)
    if not folds:
        raise SDTError(
            f"speed transfer needs runs at two speeds or more on one machine; the data has "
            f"{_held(runs)}: read more speeds (speeds = [50, 75, 100] in [benchmark], for "
            f"the synthetic pump or an NLN-EMP archive)"
        )
    split = "forward" if setting is None else setting.split
    rows: list[tuple] = []
    for machine, pairs in folds.items():
        mine = [r for r in runs if r.machine == machine and r.speed is not None]
        sides = {k: _sides([r for r in mine if r.speed == k], split) for k in speeds[machine]}
        for train, test in pairs:
            shift = speed_scenario(train, test)
            rows += [(r, shift, "train") for k in train for r, s in sides[k] if s == "train"]
            rows += [(r, shift, "test") for r, s in sides[test] if s == "test"]
            if split != "all":
                rows += [(r, speed_scenario([test], test), s) for r, s in sides[test]]
    frame = pd.DataFrame(
        [(r.machine, s, r.run, r.condition, r.severity, side) for r, s, side in rows],
        columns=COLUMNS,
    ).drop_duplicates(ignore_index=True)
    frame["severity"] = frame["severity"].astype("Int64")
    return frame, skipped


def _sides(runs: list[Run], split: str) -> list[tuple[Run, str]]:
    """(run, side) of the runs at one speed under ``split`` ("all": every run on both)."""
    if split == "all":
        return [(r, side) for r in runs for side in ("train", "test")]
    frame = rule_allocation(runs, [split])
    by_run = {(r.machine, r.run): r for r in runs}
    return [(by_run[(m, n)], s) for m, n, s in frame[["machine", "run", "side"]].itertuples(False)]


def _configured(
    runs: list[Run], recordings: Sequence[Recording], setting: SpeedTransfer | None
) -> dict[str, set[str]]:
    """The speed keys each side of ``setting`` names (empty for leave-one-speed-out)."""
    found: dict[str, set[str]] = {"train": set(), "test": set()}
    if setting is None or setting.train is None or setting.test is None:
        return found
    key_of = {(r.machine, r.run): r.speed for r in runs}
    for side, values in (("train", setting.train), ("test", setting.test)):
        for value in values:
            chosen = {key_of.get((r.machine, r.run)) for r in recordings if matches(r, value)}
            if not chosen - {None}:
                raise SDTError(
                    f"speed_transfer {side}: no run at {_shown(value)}; the data has {_held(runs)}"
                )
            found[side] |= chosen - {None}
    both = found["train"] & found["test"]
    if both:
        raise SDTError(
            f"speed_transfer: train {_list(setting.train)} and test {_list(setting.test)} both "
            f"select the runs at {sorted(both)[0]}; a speed transfer tests at a speed it did not "
            f"train at"
        )
    return found


def _held(runs: Sequence[Run]) -> str:
    """The speeds of each machine's runs, for a message: ``Motor-2 at 50, 100``."""
    speeds: dict[str, set[str]] = {}
    for run in runs:
        speeds.setdefault(run.machine, set()).add(run.speed or "no speed")
    held = sorted(speeds.items())
    return "; ".join(f"{m} at {', '.join(sorted(k, key=natural))}" for m, k in held)


def _list(values: Sequence[float | str]) -> str:
    return "[" + ", ".join(_shown(v) for v in values) + "]"
