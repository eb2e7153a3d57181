"""The critical-difference diagram (Demšar 2006, Fig. 1(a)) of a :class:`~.ranking.Ranking`.

Average ranks on an axis (best on the left), one labelled marker per
treatment, a bar joining treatments the Nemenyi test cannot tell apart, and
the CD drawn to scale above the axis. scikit-posthocs draws the diagram; this
module only sizes the figure and titles it with the test's numbers.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import pandas as pd

from .ranking import Ranking

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["plot_cd_diagram"]

#: width of the rank axis, and of one character of a 10 pt label (DejaVu Sans, generous), inches
AXIS_INCHES = 5.0
CHAR_INCHES = 0.08


def _short_names(ranking: Ranking, title: str) -> tuple[pd.Series, pd.DataFrame, str]:
    """Ranks and Nemenyi table with sweep points named by their settings alone.

    Design points (``base~a=1,b=2``) of one base share a long prefix; it is
    dropped from their labels (``~a=1,b=2``) and named once in the title, so
    the diagram stays readable.
    """
    names = [str(name) for name in ranking.ranks.index]
    bases = {name.split("~", 1)[0] for name in names if "~" in name}
    if len(bases) != 1:
        return ranking.ranks, ranking.nemenyi, title
    (base,) = bases
    rename = {name: name[len(base) :] for name in names if name.startswith(base + "~")}
    note = f"points ~... of {base}"
    title = f"{title}; {note}" if title else note
    return (
        ranking.ranks.rename(index=rename),
        ranking.nemenyi.rename(index=rename, columns=rename),
        title,
    )


def plot_cd_diagram(
    ranking: Ranking, colors: Mapping[str, str] | None = None, title: str = ""
) -> Figure:
    """A matplotlib Figure of the critical-difference diagram.

    Parameters
    ----------
    ranking
        Result of :func:`~.ranking.friedman_nemenyi`.
    colors
        Optional treatment -> colour mapping (the report's sensor colours).
    title
        First title line; the second gives N, k, the Friedman p-value and the CD.
    """
    import scikit_posthocs as sp
    from matplotlib.figure import Figure

    ranks, nemenyi, title = _short_names(ranking, title)
    # labels stand outside the axis, left and right: size the margins to the longest one
    longest = max(len(f"{name} ({rank:.2f})") for name, rank in ranks.items())
    margin = 0.3 + CHAR_INCHES * longest
    width, height = AXIS_INCHES + 2 * margin, 1.6 + 0.32 * ranking.k
    fig = Figure(figsize=(width, height), dpi=110)
    fig.subplots_adjust(
        left=margin / width, right=1 - margin / width, top=1 - 0.55 / height, bottom=0.05
    )
    ax = fig.add_subplot()
    palette = None
    if colors:
        palette = {
            short: colors.get(name, "#333333")
            for short, name in zip(ranks.index, ranking.ranks.index, strict=True)
        }
    sp.critical_difference_diagram(
        ranks,
        nemenyi,
        alpha=ranking.alpha,
        ax=ax,
        color_palette=palette,
        label_fmt_left="{label} ({rank:.2f})",
        label_fmt_right="({rank:.2f}) {label}",
    )
    # the CD to scale, above the rank axis and its tick labels (Demšar's Fig. 1)
    low = ax.get_ylim()[0]
    start = float(ranking.ranks.iloc[0])
    ax.plot([start, start + ranking.cd], [1.6, 1.6], color="k", linewidth=2)
    ax.vlines([start, start + ranking.cd], 1.45, 1.75, color="k", linewidth=1.5)
    ax.text(start + ranking.cd / 2, 1.85, f"CD = {ranking.cd:.2f}", ha="center", va="bottom")
    ax.set_ylim(low, 2.4)
    ax.set_xlabel("average rank (1 = best)")
    ax.xaxis.set_label_position("top")
    numbers = (
        f"N = {ranking.n_blocks} blocks, k = {ranking.k}; Friedman p = {ranking.p_value:.3g}; "
        f"Nemenyi CD = {ranking.cd:.2f} at α = {ranking.alpha:g}"
    )
    fig.suptitle(f"{title}\n{numbers}" if title else numbers, fontsize=9)
    return fig
