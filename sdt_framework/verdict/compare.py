"""Paired comparison of every sensor with a baseline: per cell, per machine and scenario, overall.

Runs of two sensors that share the cell (dataset, feature set, machine,
scenario, classifier) and the repetition are paired: with common random
numbers they saw the same noise draws, classifier seeds, recordings and
split, so their difference is not blurred by any of these. For each
comparison the table holds the mean difference Δ (candidate - baseline), a
95 % t interval over repetitions, a 95 % percentile interval from resampling
the test recordings (:mod:`.recordings`), the paired t p-value (Holm-adjusted
over the cells), the TOST p-value and the label (:mod:`.equivalence`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from ..bench.results import scenario_rank
from ..errors import SDTError
from .aggregate import aggregate_rows, cell_rows
from .equivalence import combine
from .inputs import unpaired_runs
from .paired import holm, paired_t_pvalue, t_interval, tost_pvalue
from .ranking import DegenerateBlocksError, Ranking, friedman_nemenyi
from .recordings import RecordingSets

__all__ = ["CELL_KEYS", "Comparison", "compare", "stack_folders"]

#: what two paired runs share besides the repetition (those present in the table)
CELL_KEYS = ("dataset", "feature_set", "machine", "scenario", "classifier")
#: what fixes the test recordings of a run
TEST_SET_KEYS = ("dataset", "machine", "scenario")
#: the numbers of a comparison row, in comparison.csv order (label, reason and notes follow)
_COLUMNS = [
    "n_repeats",
    "baseline_mean",
    "candidate_mean",
    "delta",
    "sd",
    "ci_low",
    "ci_high",
    "n_recordings",
    "rec_ci_low",
    "rec_ci_high",
    "p_value",
    "p_holm",
    "p_tost",
    "label",
    "reason",
    "n_cells",
]


@dataclass
class Comparison:
    """Everything ``sdt compare`` prints and the report's verdict cites."""

    baseline: str
    margin: float
    alpha: float
    treatment: str  # the column whose values are compared ("sensor", or "source" for 2 folders)
    cells: list[str]  # the columns of a cell
    groups: list[str]  # the columns of a verdict group (cells without classifier and sensor)
    table: pd.DataFrame  # one row per comparison, levels "cell", "group", "overall"
    means: pd.DataFrame  # mean Macro F1 per group (rows) and treatment (columns)
    ranking: Ranking | None
    ranking_note: str
    #: pairs left out because one side has no successful run (see :func:`.inputs.unpaired_runs`)
    unpaired: pd.DataFrame = field(default_factory=pd.DataFrame)
    #: (machine, scenario) -> (the classes with a single physical test run there, classes)
    single_run_classes: dict[tuple[str, str], tuple[list[str], int]] = field(default_factory=dict)

    @property
    def candidates(self) -> list[str]:
        """Compared treatments other than the baseline, in table order."""
        return list(dict.fromkeys(self.table["candidate"]))


def _checked(results: pd.DataFrame, baseline: str, margin: float, treatment: str) -> pd.DataFrame:
    if not (np.isfinite(margin) and margin > 0):
        raise SDTError(f"the margin must be a Macro F1 difference > 0, got {margin:g}")
    ok = results[results["status"] == "ok"] if "status" in results else results
    names = sorted(ok[treatment].dropna().unique())
    if baseline not in names:
        raise SDTError(
            f"baseline {baseline!r} has no successful run in the results; "
            f"choose --baseline from {names}"
        )
    if len(names) < 2:
        raise SDTError(f"nothing to compare: the results hold only {treatment} {names}")
    return ok


def _pivot(ok: pd.DataFrame, cells: list[str], treatment: str) -> pd.DataFrame:
    keys = [*cells, "repeat", treatment]
    doubled = ok.duplicated(keys)
    if doubled.any():
        first = ok.loc[doubled, keys].iloc[0].to_dict()
        raise SDTError(
            f"{int(doubled.sum())} run(s) share {keys} with another run (e.g. {first}); "
            f"the results mix runs that cannot be paired"
        )
    return ok.set_index(keys)["macro_f1"].unstack(treatment)


def _test_runs(allocation: pd.DataFrame | None) -> pd.Series | None:
    """Test runs of each class, per (machine, scenario, condition), from allocation.csv."""
    if allocation is None or not {"machine", "scenario", "condition", "side"} <= set(allocation):
        return None
    test = allocation[allocation["side"] == "test"]
    return test.groupby(["machine", "scenario", "condition"])["run"].nunique()


def _single_run_classes(
    per_class: pd.Series | None,
) -> dict[tuple[str, str], tuple[list[str], int]]:
    """(machine, scenario) -> (the classes tested on one physical run there, all its classes)."""
    if per_class is None:
        return {}
    single: dict[tuple[str, str], list[str]] = {}
    classes: dict[tuple[str, str], int] = {}
    for (machine, scenario, condition), runs in per_class.items():
        cell = (str(machine), str(scenario))
        classes[cell] = classes.get(cell, 0) + 1
        if runs == 1:
            single.setdefault(cell, []).append(str(condition))
    return {cell: (sorted(names), classes[cell]) for cell, names in single.items()}


def compare(
    results: pd.DataFrame,
    baseline: str,
    *,
    margin: float = 0.02,
    treatment: str = "sensor",
    cells: Sequence[str] | None = None,
    per_recording: pd.DataFrame | None = None,
    allocation: pd.DataFrame | None = None,
    alpha: float = 0.05,
    n_boot: int = 2000,
    seed: int = 0,
    order: Sequence[str] = (),
) -> Comparison:
    """Compare every value of ``treatment`` with ``baseline``, paired by cell and repetition.

    Parameters
    ----------
    results
        The tidy results table (``results.parquet``); failed runs are ignored.
    baseline
        The value of ``treatment`` the others are compared with (the reference sensor).
    margin
        Equivalence margin δ in Macro F1 (> 0).
    treatment
        Column whose values are compared: "sensor", or "source" for two folders.
    cells
        Columns two paired runs share besides "repeat"; default :data:`CELL_KEYS`.
    per_recording
        ``per_recording.parquet`` for the recording-level intervals (optional).
    allocation
        ``allocation.csv``, to report the number of test runs per class (optional).
    alpha
        1 - coverage of the intervals; the TOST's one-sided tests are at alpha / 2.
    n_boot, seed
        Recording resamples and their base seed (the result is deterministic).
    order
        Display order of the candidates (others follow, sorted).

    Raises
    ------
    SDTError
        A margin <= 0, a baseline without runs, or nothing that can be paired.
    """
    ok = _checked(results, baseline, margin, treatment)
    cells = [c for c in (cells or CELL_KEYS) if c in ok.columns]
    ok = ok.assign(**{c: ok[c].fillna("") for c in cells})  # a blank key still pairs, not drops
    groups = [c for c in cells if c not in ("classifier", "sensor")]
    wide = _pivot(ok, cells, treatment)
    candidates = [c for c in order if c in wide.columns and c != baseline]
    candidates += sorted(c for c in wide.columns if c != baseline and c not in candidates)
    unpaired = unpaired_runs(wide, baseline, candidates)
    diffs = {c: (wide[c] - wide[baseline]).dropna() for c in candidates}
    diffs = {c: d for c, d in diffs.items() if not d.empty}
    if not diffs:
        raise SDTError(
            f"nothing to pair: no cell ({', '.join(cells)}) and repetition has runs of both "
            f"{baseline!r} and another {treatment}"
        )
    recording_sets = None
    if per_recording is not None and not per_recording.empty:
        test_keys = [c for c in TEST_SET_KEYS if c in cells]
        recording_sets = RecordingSets(per_recording, test_keys, n_boot=n_boot, seed=seed)
    rows, draws = cell_rows(diffs, wide, baseline, cells, recording_sets, treatment, alpha)
    rows += aggregate_rows(rows, diffs, draws, cells, groups, alpha)
    table = _sorted(pd.DataFrame(rows), candidates)
    table["ci_low"], table["ci_high"] = t_interval(
        table["delta"], table["sd"], table["n_repeats"], 1 - alpha
    )
    table["p_value"] = paired_t_pvalue(table["delta"], table["sd"], table["n_repeats"])
    is_cell = (table["level"] == "cell").to_numpy()
    table["p_holm"] = np.nan
    table.loc[is_cell, "p_holm"] = holm(table.loc[is_cell, "p_value"].to_numpy())
    table["p_tost"] = tost_pvalue(table["delta"], table["sd"], table["n_repeats"], margin)
    per_class = _test_runs(allocation)
    if per_class is not None and {"machine", "scenario"} <= set(table):
        fewest = per_class.groupby(level=["machine", "scenario"]).min()
        index = pd.MultiIndex.from_frame(table[["machine", "scenario"]].astype(object))
        table["test_runs_per_class"] = fewest.reindex(index).to_numpy()
    labels = [
        combine(
            (r.ci_low, r.ci_high),
            int(r.n_repeats),
            (r.rec_ci_low, r.rec_ci_high),
            r.rec_detail,
            margin,
        )
        for r in table.itertuples()
    ]
    table["label"] = [label for label, _ in labels]
    table["reason"] = [reason for _, reason in labels]
    table.insert(0, "margin", margin)
    first = ["margin", "level", *cells, "baseline", "candidate", *_COLUMNS]
    table = table[first + [c for c in table.columns if c not in first]]
    blocks = ok.groupby([*cells, treatment])["macro_f1"].mean().unstack(treatment).dropna()
    means = blocks.groupby(level=groups).mean() if groups else blocks.mean().to_frame().T
    ranking, note = None, ""
    try:
        ranking = friedman_nemenyi(blocks, alpha)
    except DegenerateBlocksError as exc:
        note = f"not computed: {str(exc).replace('treatments', treatment + 's')}"
    except ValueError:
        note = (
            f"not computed: Friedman needs at least 3 {treatment}s and 2 complete blocks "
            f"({', '.join(cells)}); here {blocks.shape[1]} and {blocks.shape[0]}"
        )
    return Comparison(
        baseline,
        margin,
        alpha,
        treatment,
        cells,
        groups,
        table,
        means,
        ranking,
        note,
        unpaired,
        _single_run_classes(per_class),
    )


def _sorted(table: pd.DataFrame, candidates: list[str]) -> pd.DataFrame:
    """Cells, then groups, then overall; candidates in order; scenarios in the paper's order,
    then speed transfers (:func:`~sdt_framework.bench.results.scenario_rank`)."""
    levels = {"cell": 0, "group": 1, "overall": 2}
    present = set(table["scenario"].dropna()) if "scenario" in table else set()
    scenarios = {s: i for i, s in enumerate(sorted(present, key=scenario_rank))}
    rank = {c: i for i, c in enumerate(candidates)}

    def key(column: pd.Series) -> pd.Series:
        if column.name == "level":
            return column.map(levels)
        if column.name == "candidate":
            return column.map(rank)
        if column.name == "scenario":
            return column.map(lambda v: (scenarios.get(v, len(scenarios)), str(v)))
        return column.astype(str)

    by = ["level", "candidate", *[c for c in table.columns if c in CELL_KEYS or c == "sensor"]]
    return table.sort_values(by, key=key, kind="stable", ignore_index=True)


def stack_folders(frames: Sequence[pd.DataFrame], labels: Sequence[str]) -> pd.DataFrame:
    """Several results (or per-recording) tables as one, with a "source" column of ``labels``."""
    return pd.concat(
        [frame.assign(source=label) for frame, label in zip(frames, labels, strict=True)],
        ignore_index=True,
    )
