"""The train/test allocation of a plan: the scenario rules, or the user's table, then the check.

The runs of the recordings (each carrying its speed when the speed-transfer
scenario is asked for) are allocated by the paper's rules
(:func:`.scenarios.rule_allocation`) and the speed-transfer scenario
(:func:`.speed_split.speed_allocation`), or read from ``allocation`` when the
config names a table. Every (machine, scenario) that cannot be scored is
returned with its reason; a speed-transfer fold is scored as a whole: the
other arms of a fold one of whose arms cannot be scored are left out too.
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from ..data.recording import Recording
from ..errors import SDTError
from .config import BenchmarkConfig
from .scenarios import (
    Run,
    check_allocation,
    load_allocation,
    parse_speed_scenario,
    rule_allocation,
)
from .speed_split import SPEED_TRANSFER, speed_allocation, speed_key

__all__ = ["plan_allocation", "runs_of"]


def runs_of(recordings: Sequence[Recording], with_speed: bool = False) -> list[Run]:
    """The physical runs of ``recordings``, sorted by (machine, run).

    ``with_speed``: each run carries its speed (:func:`.speed_split.speed_key`),
    and a run whose channels name two speeds is refused.
    """
    speeds: dict[tuple[str, str], set[str | None]] = {}
    for rec in recordings:
        speeds.setdefault((rec.machine, rec.run), set()).add(speed_key(rec) if with_speed else None)
    for (machine, run), keys in speeds.items():
        if len(keys) > 1:
            named = ", ".join(sorted(str(k) for k in keys))
            raise SDTError(
                f"run {run!r} of {machine} has recordings at several speeds ({named}); a run "
                f"is one operating point: give each speed its own recording_id"
            )
        label = next(iter(keys))
        if label is not None and ("+" in label or "->" in label):
            raise SDTError(
                f"run {run!r} of {machine}: speed label {label!r} holds '+' or '->', which "
                f"speed-transfer labels ('speed 50+100 -> 75') use; rename the speed"
            )
    runs = {
        Run(r.machine, r.run, r.condition, r.severity, next(iter(speeds[(r.machine, r.run)])))
        for r in recordings
    }
    return sorted(runs, key=lambda r: (r.machine, r.run))


def _wanted(scenario: object, scenarios: Sequence[str]) -> bool:
    """Whether a row of a user's table belongs to the configured scenarios."""
    if parse_speed_scenario(scenario) is not None:
        return SPEED_TRANSFER in scenarios
    return scenario in scenarios


def _twins(allocation: pd.DataFrame, machine: str, scenario: str) -> list[str]:
    """The other arms of a speed-transfer fold (same machine, same test speed): a shift arm's
    within-speed arm, a within-speed arm's shift arms; none for another scenario."""
    parsed = parse_speed_scenario(scenario)
    if parsed is None:
        return []
    names = allocation.loc[allocation["machine"] == machine, "scenario"].unique()
    return [
        name
        for name in names
        if name != scenario and (p := parse_speed_scenario(name)) is not None and p[1] == parsed[1]
    ]


def plan_allocation(
    config: BenchmarkConfig, recordings: Sequence[Recording]
) -> tuple[pd.DataFrame, dict[tuple[str, str], str]]:
    """(allocation, (machine, scenario) -> why it cannot be scored) of ``recordings``."""
    speed = SPEED_TRANSFER in config.scenarios
    runs = runs_of(recordings, with_speed=speed)
    left: dict[tuple[str, str], str] = {}
    if config.allocation:
        allocation = load_allocation(config.allocation, runs)
        keep = [_wanted(s, config.scenarios) for s in allocation["scenario"]]
        allocation = allocation[keep]
    else:
        paper = [s for s in config.scenarios if s != SPEED_TRANSFER]
        allocation = rule_allocation(runs, paper)
        if speed:
            shifted, left = speed_allocation(runs, recordings, config.speed_transfer)
            allocation = pd.concat([allocation, shifted], ignore_index=True)
    allocation = allocation.sort_values(
        ["machine", "scenario", "condition", "run"], ignore_index=True
    )
    skipped = {**left, **check_allocation(allocation)}
    for (machine, scenario), reason in sorted(skipped.items()):
        for twin in _twins(allocation, machine, scenario):
            skipped.setdefault((machine, twin), f"its twin arm {scenario!r} is skipped: {reason}")
    return allocation, skipped
