"""The report's "Deployment" section: cross-chain training and node-level samples.

Shown when the results hold them (``[benchmark] transfer``, ``sample =
"node"``):

- the **transfer matrix** per scenario: training chain (rows) x test chain
  (columns), Macro F1 averaged over machines and classifiers, with a 95 %
  t-interval over repetitions; the diagonal is the ordinary benchmark;
- **node versus channel**: per sensor and scenario, the same average for the
  channel samples (the paper's) and for each node, and the bytes a node sends
  per window (its three axes' vectors).
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pandas as pd
from scipy import stats

from ..bench.results import SCENARIO_TITLES
from ..errors import SDTError
from ..features import resolve_feature_set
from .document import Block, Heading, Paragraph, Table, literal
from .load import ResultsFolder

__all__ = ["deployment_blocks", "mean_ci"]


def mean_ci(frame: pd.DataFrame) -> tuple[float, float, float]:
    """Mean Macro F1 and its 95 % t-interval over repetitions (each repetition's mean over
    machines and classifiers first); NaN bounds with a single repetition."""
    per_repeat = frame.groupby("repeat")["macro_f1"].mean().to_numpy()
    mean = float(per_repeat.mean())
    if len(per_repeat) < 2:
        return mean, float("nan"), float("nan")
    half = stats.t.ppf(0.975, len(per_repeat) - 1) * per_repeat.std(ddof=1)
    half /= np.sqrt(len(per_repeat))
    return mean, mean - half, mean + half


def _cell(frame: pd.DataFrame) -> str:
    if frame.empty:
        return "–"
    mean, lo, hi = mean_ci(frame)
    return f"{mean:.3f}" if np.isnan(lo) else f"{mean:.3f} [{lo:.3f}, {hi:.3f}]"


def _by_scenario(frame: pd.DataFrame):
    """(scenario, rows) in the paper's order (A forward, B backward, C interpolation)."""
    order = {s: i for i, s in enumerate(SCENARIO_TITLES)}
    for scenario in sorted(frame["scenario"].unique(), key=lambda s: order.get(s, 99)):
        yield scenario, frame[frame["scenario"] == scenario]


def _node_headers(nodes: list[str]) -> list[str]:
    return ["per node"] if nodes == ["node"] else [f"node {n}" for n in nodes]


def _columns(results: pd.DataFrame) -> pd.DataFrame:
    """Results with train_sensor, test_sensor and node (older folders: the sensor itself)."""
    out = results.copy()
    for column in ("train_sensor", "test_sensor"):
        if column not in out:
            out[column] = out["sensor"]
    if "node" not in out:
        out["node"] = None
    return out


def _transfer(ok: pd.DataFrame, order: list[str]) -> list[Block]:
    channels = ok[ok["node"].isna()]
    crossed = channels[channels["train_sensor"] != channels["test_sensor"]]
    if crossed.empty:
        return []
    trains = [s for s in order if s in set(channels["train_sensor"])]
    trains += sorted(set(channels["train_sensor"]) - set(trains))
    tests = [s for s in order if s in set(crossed["test_sensor"])]
    blocks: list[Block] = [
        Heading("Training on one chain, running on another", 3),
        Paragraph(
            "Macro F1 (mean over machines and classifiers, 95 % interval over repetitions) of "
            "a classifier trained on the row's chain and tested on the column's, same split "
            "and seeds; the diagonal is the ordinary benchmark. `sdt compare DIR --baseline "
            "SENSOR` tests each difference."
        ),
    ]
    for scenario, part in _by_scenario(channels):
        rows = tuple(
            (literal(train),
             *(_cell(part[(part["train_sensor"] == train) & (part["test_sensor"] == t)])
               for t in tests))
            for train in trains
        )  # fmt: skip
        header = ("train \\ test", *map(literal, tests))
        blocks += [Paragraph(f"**{literal(scenario)}**"), Table(header, rows)]
    return blocks


def _nodes(ok: pd.DataFrame, order: list[str], node_bytes: str) -> list[Block]:
    own = ok[ok["train_sensor"] == ok["test_sensor"]]
    nodes = sorted(n for n in own["node"].dropna().unique())
    if not nodes:
        return []
    blocks: list[Block] = [
        Heading("One decision per node", 3),
        Paragraph(
            f"Macro F1 (as above) with every channel's windows as samples (the paper's) and "
            f"with one sample per window per triaxial node, its axes' features concatenated "
            f"({node_bytes} per window)."
        ),
    ]
    sensors = [s for s in order if s in set(own["test_sensor"])]
    for scenario, part in _by_scenario(own):
        rows = []
        for sensor in sensors:
            mine = part[part["test_sensor"] == sensor]
            cells = [_cell(mine[mine["node"].isna()])]
            cells += [_cell(mine[mine["node"] == node]) for node in nodes]
            rows.append((literal(sensor), *cells))
        header = ("sensor", "per channel", *map(literal, _node_headers(nodes)))
        blocks += [Paragraph(f"**{literal(scenario)}**"), Table(header, tuple(rows))]
    return blocks


def _node_bytes(folder: ResultsFolder, registry: Any) -> str:
    config = folder.config
    try:
        spec = resolve_feature_set(registry, config.features if config else "paper8")
    except SDTError:
        return "three axes' feature vectors"
    if config is not None and config.feature_dtype:
        spec = spec.with_dtype(config.feature_dtype)
    return f"3 x {len(spec.feature_names)} values at {spec.dtype}: {3 * spec.bytes_per_window} B"


def deployment_blocks(folder: ResultsFolder, registry: Any) -> list[Block]:
    """The section, or nothing when the results hold neither transfer nor node runs."""
    ok = _columns(folder.ok)
    order = [s for s in folder.sensors if "->" not in s and " @ " not in s]
    blocks = _transfer(ok, order) + _nodes(ok, order, _node_bytes(folder, registry))
    return [Heading("Deployment", 2), *blocks] if blocks else []
