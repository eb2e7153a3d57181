"""Are a comparison's inputs complete? Gaps a verdict must not pass over in silence.

Two kinds of gap change a verdict without changing any number the user sees
beside it:

- ``per_recording.parquet`` missing the counts of some runs (a resume by an
  older version, a truncated copy). The recording-level interval of the
  affected cells is then not computed and their label rests on the
  repetition interval alone: "inconclusive" can become "better". A folder
  whose counts do not match its results is therefore refused by ``sdt
  compare`` (:func:`recording_gaps` says what is wrong), never used in part.
- Runs without a partner (a failed run, a run only one of two folders has):
  they cannot be paired and are left out. :func:`unpaired_runs` lists them so
  the caller can name them.
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

__all__ = ["recording_gaps", "unpaired_runs"]

#: the columns of a per-recording row besides the run's own columns
_COUNT_COLUMNS = ("recording_id", "true", "predicted", "count")
#: run columns that identify a run in both tables (those present in both)
_RUN_KEYS = ("dataset", "machine", "scenario", "sensor", "feature_set", "classifier", "repeat")
_RUN_KEYS += ("unit", "seed")


def _describe(row: pd.Series) -> str:
    return " ".join(f"{k}={v}" for k, v in row.items())


def recording_gaps(results: pd.DataFrame, per_recording: pd.DataFrame) -> str | None:
    """What ``per_recording`` lacks to cover every successful run of ``results``, or None.

    Every successful run must have counts that add up to its test windows
    (``n_test``), and no counts may belong to a run the results do not hold.
    The answer names how many runs are affected and the first of them.
    """
    missing = sorted(set(_COUNT_COLUMNS) - set(per_recording))
    if missing:
        return f"lacks the column(s) {missing}"
    ok = results[results["status"] == "ok"] if "status" in results else results
    keys = [k for k in _RUN_KEYS if k in ok and k in per_recording]
    if "repeat" not in keys:
        return "has no run columns to match its rows with results.parquet"
    sums = per_recording.groupby(keys, dropna=False)["count"].sum().rename("_counted")
    wanted = ok.set_index(keys)["n_test"] if "n_test" in ok else None
    runs = ok[keys].drop_duplicates().set_index(keys).index
    joined = pd.DataFrame(index=runs).join(sums, how="outer")
    if wanted is not None:
        joined = joined.join(wanted.rename("_wanted"), how="left")
    absent = joined["_counted"].isna()
    extra = ~joined.index.isin(runs)
    wrong = pd.Series(False, index=joined.index)
    if wanted is not None:
        wrong = ~absent & ~extra & joined["_counted"].ne(joined["_wanted"])
    for mask, what in (
        (absent, "lacks the counts of"),
        (wrong, "holds counts that do not add up to the test windows of"),
    ):
        if mask.any():
            first = _describe(joined.index[mask.to_numpy()].to_frame(index=False).iloc[0])
            count = f"{int(mask.sum())} of the {len(runs)} runs"
            return f"{what} {count} in the results (first: {first})"
    if extra.any():
        first = _describe(joined.index[extra].to_frame(index=False).iloc[0])
        return f"holds counts of {int(extra.sum())} runs the results do not have (first: {first})"
    return None


def unpaired_runs(wide: pd.DataFrame, baseline: str, candidates: Sequence[str]) -> pd.DataFrame:
    """Runs left out because the other side of their pair has no successful run.

    ``wide`` is Macro F1 indexed by (cell columns, repeat) with one column per
    treatment. One row per left-out pair: the index columns, ``present`` (the
    treatment with a run) and ``missing`` (the one without).
    """
    parts = []
    has_base = wide[baseline].notna()
    for candidate in candidates:
        has_candidate = wide[candidate].notna()
        for present, missing, mask in (
            (candidate, baseline, has_candidate & ~has_base),
            (baseline, candidate, has_base & ~has_candidate),
        ):
            part = wide.index[mask.to_numpy()].to_frame(index=False)
            parts.append(part.assign(present=present, missing=missing))
    columns = [*wide.index.names, "present", "missing"]
    return pd.concat(parts, ignore_index=True) if parts else pd.DataFrame(columns=columns)
