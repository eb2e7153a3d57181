"""Running a sweep: its points become sensors of one ordinary benchmark.

The points, the base sensor and the reference are handed to
:func:`~sdt_framework.bench.plan_benchmark` as the sensor list, so a sweep runs
exactly the protocol of ``sdt benchmark`` (datasets, scenarios, classifiers,
repetitions, seeds, feature cache, resume, local or Dask execution) and leaves
the same files. The noise of an acquisition depends on (seed, repetition,
recording, acquisition) only, never on the sensor's name, so every point sees
the same draws (common random numbers) and a point equal to a registered
sensor reproduces that sensor's benchmark numbers exactly.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import pandas as pd

from ..bench.config import BenchmarkConfig, quick_preset, validate_config
from ..bench.plan import Plan, plan_benchmark
from ..bench.size_check import unfit
from ..errors import SDTError
from ..registry import Registry
from ..sensor_files import load_sensor_file
from ..specs import SensorSpec
from .design import design_points, repeated_point, unit_column
from .life import check_report_interval, point_lives, with_battery_life
from .points import Point, build_points, left_out
from .size import design_size, sweep_estimate
from .stage_axes import StageAxis, base_value, check_stage_axes
from .sweep import Sweep
from .zones import with_zone_agreement, zone_assignments

__all__ = ["ExplorePlan", "explore_table", "plan_explore"]


@dataclass
class ExplorePlan:
    """A sweep resolved into a checked benchmark plan."""

    sweep: Sweep
    base: SensorSpec
    design: pd.DataFrame
    points: list[Point]
    skipped: pd.DataFrame
    plan: Plan
    #: the sweep's stage-parameter keys, checked against the registry
    stage_axes: dict[str, StageAxis] = field(default_factory=dict)

    def base_values(self) -> dict[str, float]:
        """The base's value of every swept parameter (NaN: a stage it lacks, no default)."""
        return {key: base_value(self.base, key, self.stage_axes) for key in self.sweep.axes}

    def lives(self) -> pd.DataFrame:
        """Each point's and the base's battery life on the target's cell and interval (.life)."""
        specs = {p.spec.name: p.spec for p in self.points}
        specs.setdefault(self.base.name, self.base)
        window = self.plan.config.window_s
        return point_lives(list(specs.values()), self.plan.feature_set, window, self.sweep.target)


def resolve_base(name: str, registry: Registry) -> SensorSpec:
    """The base sensor: a registered name (with a mode, if parts have one) or a TOML file."""
    if name.endswith(".toml"):
        specs = load_sensor_file(name)
        if len(specs) != 1:
            raise SDTError(f"{name}: the base file holds {len(specs)} sensors; keep one")
        spec = specs[0]
        if spec.name not in {s.name for s in registry.sensors()}:
            registry.add(spec)
        return spec
    return registry.sensor(name)


def plan_explore(
    sweep: Sweep,
    protocol: dict[str, Any],
    overrides: dict[str, Any],
    registry: Registry,
    where: str = "sweep",
    check: Callable[[int, Plan, SensorSpec], None] | None = None,
) -> ExplorePlan:
    """Design, build and register the points, and plan the benchmark that evaluates them.

    ``protocol`` is the sweep file's ``[benchmark]`` table and ``overrides``
    the command-line options (``quick`` applies the quick preset under them).
    Before the design is built, ``check`` is given its number of points, the
    protocol planned on no points (its data, classifiers and options) and the
    base sensor, to estimate the sweep (:mod:`~sdt_framework.explore.size`)
    and refuse it; by default a sweep that cannot fit in memory is refused.
    """
    if "sensors" in protocol:
        raise SDTError(
            f"{where}: benchmark.sensors is set by the sweep (reference, base and points); "
            f"remove it"
        )
    base = resolve_base(sweep.base, registry)
    stage_axes = check_stage_axes(sweep, base, registry, where)
    data = {**protocol, **{k: v for k, v in overrides.items() if k != "quick"}}
    if overrides.get("quick"):
        data = quick_preset(data)
    probe = plan_benchmark(_config(data, None, where), registry)  # the data and protocol
    n_points = design_size(sweep)
    (check or _refuse_unfit)(n_points, probe, base)
    design = design_points(sweep)
    repeated = repeated_point(sweep, design)
    if repeated is not None:
        raise SDTError(f"{where}: {repeated}")
    points, skipped = build_points(sweep, base, design, stage_axes)
    if not points:
        raise SDTError(
            f"{where}: none of the {len(design)} design points is a valid sensor; "
            f"first reason: {skipped['reason'].iloc[0]}"
        )
    for point in points:
        registry.add(point.spec)
    names = [base.name, *(p.spec.name for p in points)]
    if probe.reference not in names:  # the reference follows the data, as the probe found
        names = [probe.reference, *names]
    plan = plan_benchmark(_config(data, names, where), registry)
    specs = [base, *(p.spec for p in points)]
    check_report_interval(sweep.target, specs, plan.feature_set, plan.config.window_s, where)
    if sweep.target.zone_agreement is not None or plan.config.zones:
        zone_assignments(plan, where, every=sweep.target.zone_agreement is not None)
    points, skipped = left_out(points, skipped, plan.skipped_sensors, list(sweep.axes))
    if not points:
        raise SDTError(
            f"{where}: none of the {len(design)} design points can be evaluated on this data; "
            f"first reason: {skipped['reason'].iloc[0]}"
        )
    return ExplorePlan(sweep, base, design, points, skipped, plan, stage_axes)


def _refuse_unfit(points: int, probe: Plan, base: SensorSpec) -> None:
    problem = unfit(sweep_estimate(probe, base, points))
    if problem is not None:
        raise SDTError(f"a sweep of {points:,} design points {problem}; use fewer points")


def _config(data: dict[str, Any], sensors: list[str] | None, where: str) -> BenchmarkConfig:
    return validate_config({**data, "sensors": sensors}, where)


def explore_table(
    explore: ExplorePlan, results: pd.DataFrame, features: pd.DataFrame | None = None
) -> pd.DataFrame:
    """The tidy exploration table: benchmark results plus each point's parameters.

    One row per point x machine x scenario x classifier x repetition; the
    reference and the base carry ``role`` "reference" and "base", the base
    its own values of the swept parameters, the reference none. With the
    benchmark's ``features`` and a target asking for zone agreement, each row
    also carries its point's ``zone_agreement`` on that machine (:mod:`.zones`);
    with a target asking for battery life, its ``battery_life_years`` (:mod:`.life`).
    """
    fields = list(explore.sweep.axes)
    ref = explore.plan.reference
    rows = []
    for point in explore.points:
        rows.append(
            {
                "sensor": point.spec.name,
                "role": "point",
                "design_index": point.index,
                **{f: point.values[f] for f in fields},
            }
        )
    base_values = explore.base_values()
    rows.append({"sensor": explore.base.name, "role": "base", "design_index": -1, **base_values})
    params = pd.DataFrame(rows).drop_duplicates("sensor")
    units = explore.design.set_index("design_index")[[unit_column(f) for f in fields]]
    params = params.join(units, on="design_index")
    table = results.merge(params, on="sensor", how="left")
    table.loc[table["sensor"] == ref, "role"] = "reference"
    table = table[table["status"] == "ok"].rename(columns={"sensor": "point"})
    table["design_index"] = table["design_index"].fillna(-1).astype(int)
    table = table.reset_index(drop=True)
    target = explore.sweep.target
    if target.min_battery_life_years is not None:
        table = with_battery_life(table, explore.lives(), target)
    if features is None:
        return table
    return with_zone_agreement(table, features, explore.plan, target)
