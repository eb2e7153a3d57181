"""How much each sensor loses under a speed shift (issue 43): the speed-transfer arms, paired.

The speed-transfer scenario (:mod:`~sdt_framework.bench.speed_split`) scores each
fold tested at speed T twice on the same test runs: ``speed T -> T`` trained at T
(within speed) and ``speed S -> T`` trained at the speeds S. The loss under the
speed shift is their difference, ``within - shift``, taken run by run: the same
sensor, classifier, feature set, unit, node and repetition (so the same noise
draws and seeds). Positive: the sensor's classifier does worse at a speed it was
not trained at. ``excess`` is a sensor's loss minus the baseline sensor's, paired
by repetition: whether a candidate loses more than the reference does.

Intervals are 95 % Student-t intervals over repetitions (each repetition's loss
averaged over units and nodes first); one repetition gives no interval.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from scipy import stats

from ..bench.results import scenario_rank
from ..bench.scenarios import parse_speed_scenario, speed_scenario

__all__ = ["UNPAIRED", "speed_arms", "speed_loss", "speed_loss_by_class", "unpaired_arms"]

#: what is said of shift arms without a within-speed arm (``split = "all"``, or the arm skipped)
UNPAIRED = (
    "no within-speed arm to take the loss against (split = 'all' has none; or it was skipped: "
    "skipped.csv); Table 4 shows their Macro F1"
)

#: the columns that pair a shift run with its within-speed run (those the results carry)
PAIR_KEYS = [
    "machine",
    "sensor",
    "train_sensor",
    "test_sensor",
    "node",
    "feature_set",
    "classifier",
    "unit",
    "repeat",
]
#: one row of the loss table: a shift arm's sensor x classifier x feature set
ROW_KEYS = ["machine", "shift", "within", "sensor", "feature_set", "classifier"]


def speed_arms(scenarios: pd.Series | list[str]) -> list[tuple[str, str]]:
    """(shift arm, its within-speed arm) of each shift arm present whose within arm is present,
    in display order (:func:`~sdt_framework.bench.results.scenario_rank`)."""
    present = set(pd.Series(scenarios).dropna())
    arms = []
    for name in sorted(present, key=scenario_rank):
        parsed = parse_speed_scenario(name)
        if parsed is None or parsed[0] == (parsed[1],):
            continue
        within = speed_scenario([parsed[1]], parsed[1])
        if within in present:
            arms.append((name, within))
    return arms


def unpaired_arms(scenarios: pd.Series | list[str]) -> list[str]:
    """Shift arms present whose within-speed arm is not: their loss cannot be computed."""
    present = set(pd.Series(scenarios).dropna())
    paired = {shift for shift, _within in speed_arms(scenarios)}
    shifts = [s for s in present if (p := parse_speed_scenario(s)) and p[0] != (p[1],)]
    return sorted(set(shifts) - paired, key=scenario_rank)


def _paired(frame: pd.DataFrame, value: str, extra: list[str]) -> pd.DataFrame:
    """Rows of each shift arm joined to their within-speed twin: ``within``, ``shifted``,
    ``loss`` (within - shifted) of ``value``, one row per paired run (and ``extra`` key)."""
    if "status" in frame:
        frame = frame[frame["status"] == "ok"]
    keys = [k for k in PAIR_KEYS if k in frame.columns] + extra
    parts = []
    for shift, within in speed_arms(frame["scenario"]):
        a = frame[frame["scenario"] == within][[*keys, value]].rename(columns={value: "within_f1"})
        b = frame[frame["scenario"] == shift][[*keys, value]].rename(columns={value: "shift_f1"})
        joined = a.merge(b, on=keys, how="inner").assign(shift=shift, within=within)
        parts.append(joined)
    if not parts:
        return pd.DataFrame(columns=[*keys, "within_f1", "shift_f1", "shift", "within", "loss"])
    joined = pd.concat(parts, ignore_index=True)
    joined["loss"] = joined["within_f1"] - joined["shift_f1"]
    return joined


def _interval(values: pd.Series) -> tuple[float, float]:
    """95 % Student-t interval of the mean of ``values``; NaNs below two values."""
    v = values.to_numpy(dtype=float)
    if len(v) < 2:
        return (np.nan, np.nan)
    half = stats.t.ppf(0.975, len(v) - 1) * v.std(ddof=1) / np.sqrt(len(v))
    return (v.mean() - half, v.mean() + half)


def speed_loss(results: pd.DataFrame, baseline: str | None = None) -> pd.DataFrame:
    """Per (machine, shift arm, sensor, feature set, classifier): the within-speed and shifted
    Macro F1, the loss (mean, 95 % CI over repetitions, n repetitions) and, given ``baseline``,
    the excess loss over the baseline sensor's (mean and CI, paired by repetition)."""
    paired = _paired(results, "macro_f1", [])
    columns = [*ROW_KEYS, "within_f1", "shift_f1", "loss", "loss_low", "loss_high", "n"]
    if paired.empty:
        return pd.DataFrame(columns=[*columns, "excess", "excess_low", "excess_high"])
    per_rep = paired.groupby([*ROW_KEYS, "repeat"], dropna=False, sort=False)[
        ["within_f1", "shift_f1", "loss"]
    ].mean()
    per_rep = per_rep.reset_index()
    rows = []
    for key, part in per_rep.groupby(ROW_KEYS, dropna=False, sort=False):
        low, high = _interval(part["loss"])
        means = part[["within_f1", "shift_f1", "loss"]].mean()
        rows.append((*key, *means, low, high, len(part)))
    table = pd.DataFrame(rows, columns=columns)
    excess = pd.DataFrame(columns=[*ROW_KEYS, "excess", "excess_low", "excess_high"])
    if baseline is not None:
        other = [k for k in ROW_KEYS if k != "sensor"]
        base = per_rep[per_rep["sensor"] == baseline][[*other, "repeat", "loss"]]
        both = per_rep[per_rep["sensor"] != baseline].merge(
            base, on=[*other, "repeat"], suffixes=("", "_base")
        )
        both["excess"] = both["loss"] - both["loss_base"]
        excess = pd.DataFrame(
            [
                (*key, part["excess"].mean(), *_interval(part["excess"]))
                for key, part in both.groupby(ROW_KEYS, dropna=False, sort=False)
            ],
            columns=excess.columns,
        )
    table = table.merge(excess, on=ROW_KEYS, how="left")
    order = {s: i for i, (s, _w) in enumerate(speed_arms(table["shift"]))}
    return table.sort_values(
        ["machine", "shift"], key=lambda c: c.map(order) if c.name == "shift" else c, kind="stable"
    ).reset_index(drop=True)


def speed_loss_by_class(per_class: pd.DataFrame) -> pd.DataFrame:
    """Per (machine, shift arm, sensor, class): the within-speed and shifted F1 of the class
    and the loss, each a mean over the paired runs (classifiers, feature sets, units,
    repetitions), and n, the number of paired runs."""
    paired = _paired(per_class.rename(columns={"f1": "class_f1"}), "class_f1", ["class"])
    keys = ["machine", "shift", "within", "sensor", "class"]
    if paired.empty:
        return pd.DataFrame(columns=[*keys, "within_f1", "shift_f1", "loss", "n"])
    grouped = paired.groupby(keys, dropna=False, sort=False)
    table = grouped[["within_f1", "shift_f1", "loss"]].mean()
    table["n"] = grouped.size()
    return table.reset_index()
