"""Equivalence labels from confidence intervals and a margin, with the reason when undecided.

For a difference Δ = candidate - baseline (Macro F1) and a margin δ > 0, a
95 % interval [low, high] of Δ is read as:

- **equivalent**: -δ < low and high < +δ (the two one-sided tests, each at
  2.5 %, reject "Δ <= -δ" and "Δ >= +δ");
- **worse**: high < -δ (the candidate loses more than the margin);
- **better**: low > +δ (the candidate gains more than the margin);
- **inconclusive**: anything else (the interval crosses -δ or +δ).

A comparison has up to two intervals: one from the repetitions (noise draws
and classifier seeds) and one from resampling the test recordings. A label
other than inconclusive needs both to agree (an intersection-union rule: the
verdict holds under either source of uncertainty); when the recording
interval cannot be computed, the repetition interval decides alone and the
note says so.
"""

from __future__ import annotations

import numpy as np

__all__ = ["LABELS", "combine", "interval_label"]

LABELS = ("equivalent", "worse", "better", "inconclusive")


def interval_label(low: float, high: float, margin: float) -> str | None:
    """The label of one interval, or None when the interval is undefined (NaN)."""
    if np.isnan(low) or np.isnan(high):
        return None
    if high < -margin:
        return "worse"
    if low > margin:
        return "better"
    if -margin < low and high < margin:
        return "equivalent"
    return "inconclusive"


def _interval(low: float, high: float) -> str:
    return f"[{low:+.3f}, {high:+.3f}]"


def combine(
    rep: tuple[float, float],
    n_repeats: int,
    rec: tuple[float, float],
    rec_detail: str,
    margin: float,
) -> tuple[str, str]:
    """(label, reason) of one comparison from its two intervals.

    Parameters
    ----------
    rep
        The repetition interval (NaN when fewer than two repetitions).
    n_repeats
        Number of paired repetitions behind ``rep``.
    rec
        The recording interval (NaN when it could not be computed).
    rec_detail
        For a computed ``rec``: how many recordings it resampled; otherwise why it is missing.
    margin
        The equivalence margin δ.
    """
    by_rep = interval_label(*rep, margin)
    by_rec = interval_label(*rec, margin)
    if by_rep is None:
        return "inconclusive", f"too few repetitions ({n_repeats}): at least 2 are needed"
    if by_rec is None:
        note = f"repetition CI only ({rec_detail})" if rec_detail else "repetition CI only"
        if by_rep == "inconclusive":
            return "inconclusive", (
                f"too few repetitions: the CI {_interval(*rep)} over {n_repeats} "
                f"crosses ±{margin:g}; {note}"
            )
        return by_rep, note
    if by_rep == by_rec:
        if by_rep != "inconclusive":
            return by_rep, ""
        return "inconclusive", (
            f"too few repetitions and recordings: the repetition CI {_interval(*rep)} "
            f"({n_repeats} repetitions) and the recording CI {_interval(*rec)} ({rec_detail}) "
            f"both cross ±{margin:g}"
        )
    if by_rep == "inconclusive":
        return "inconclusive", (
            f"too few repetitions: the repetition CI {_interval(*rep)} over {n_repeats} "
            f"crosses ±{margin:g} (the recording CI alone says {by_rec})"
        )
    if by_rec == "inconclusive":
        return "inconclusive", (
            f"too few test recordings: the recording CI {_interval(*rec)} ({rec_detail}) "
            f"crosses ±{margin:g} (the repetition CI alone says {by_rep})"
        )
    return "inconclusive", f"the repetition CI says {by_rep}, the recording CI {by_rec}"
