"""One look for every report figure: the sensor palette, the backend, saving.

Every figure colours a sensor the same way (the reference grey, as in the
paper), draws with the Agg backend (no display needed) and is saved at the
same resolution, atomically, so a half-written PNG never sits in a report.

Saving is the one place every figure passes, so it is where labels from the
data are made safe: each figure is a named file inside the figures folder
(:func:`sdt_framework.io.inside`; a name built from labels is a
:func:`~sdt_framework.labels.slug`), and every text drawn shows control
characters as their escapes (an ESC drawn raw printed matplotlib's "Glyph 27
missing" warning, ESC and all, on the terminal) and ``$`` as a dollar sign,
not the start of mathtext.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from matplotlib.figure import Figure

from ..io import atomic_path
from ..labels import middle_cut, visible

__all__ = [
    "DPI",
    "LABEL_LIMIT",
    "REFERENCE_COLOR",
    "figure_label",
    "figure_text",
    "new_figure",
    "save_figure",
    "sensor_colors",
]

DPI = 110
REFERENCE_COLOR = "0.45"
#: colours for the non-reference sensors, in order (red first, as the paper's ADXL345)
_CYCLE = ("#d62728", "#2ca02c", "#1f77b4", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf")
LINESTYLES = ("-", "--", "-.", ":")
#: longest label (class, sensor) drawn in a figure; the tables and files keep the whole name
LABEL_LIMIT = 40


#: a dollar sign not yet escaped: two of them would open matplotlib's mathtext
_DOLLAR = re.compile(r"(?<!\\)\$")


def figure_text(text: object) -> str:
    """``text`` as a figure draws it literally: controls escaped, ``$`` not mathtext.

    Idempotent, so a text passed twice is escaped once.
    """
    return _DOLLAR.sub(r"\\$", visible(str(text)))


def figure_label(text: object, limit: int = LABEL_LIMIT) -> str:
    """``text`` cut in the middle to at most ``limit`` characters for a tick or legend.

    A label is data (a manifest's condition, a sweep point's name): a
    100 000-character one drawn whole costs matplotlib minutes and fills the
    figure; the report's tables and the result files keep it whole. Drawn
    literally (:func:`figure_text`): a tick label is formatted only when drawn,
    after :func:`save_figure` has made the figure's other texts literal.
    """
    text = str(text)
    if len(text) > limit:
        text = middle_cut(text, (limit - 1) // 2)
    return figure_text(text)


def sensor_colors(sensors: Sequence[str], reference: str | None) -> dict[str, str]:
    """Map each sensor name to one colour: the reference grey, the others from a fixed cycle.

    Parameters
    ----------
    sensors
        Sensor names in report order; the order fixes the colours, so pass the
        configuration's sensor list to every figure of one report.
    reference
        Name of the reference sensor (drawn grey), or None.

    Returns
    -------
    dict
        ``{sensor: matplotlib colour}``.
    """
    colors: dict[str, str] = {}
    others = [s for s in dict.fromkeys(sensors) if s != reference]
    for i, name in enumerate(others):
        colors[name] = _CYCLE[i % len(_CYCLE)]
    if reference is not None and reference in sensors:
        colors[reference] = REFERENCE_COLOR
    return colors


def new_figure(width: float, height: float) -> Figure:
    """A matplotlib Figure on the Agg canvas with constrained (tight) layout.

    Uses :class:`matplotlib.figure.Figure` directly rather than pyplot, so no
    global figure state accumulates while a report draws many figures.
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = Figure(figsize=(width, height), layout="constrained", dpi=DPI)
    FigureCanvasAgg(fig)
    return fig


def _literal_texts(fig: Figure) -> None:
    """Every text of ``fig`` through :func:`figure_text`, before anything is drawn.

    Titles, axis labels, legends and annotations are text artists. Tick labels
    are formatted again when drawn, so names given as tick labels pass
    :func:`figure_label` where they are set.
    """
    from matplotlib.text import Text

    for artist in fig.findobj(Text):
        text = artist.get_text()
        if text and figure_text(text) != text:
            artist.set_text(figure_text(text))


def save_figure(fig: Figure, folder: str | os.PathLike[str], name: str) -> Path:
    """Save ``fig`` as ``folder/name`` (PNG at :data:`DPI`), atomically; return the path.

    ``name`` must keep the file inside ``folder`` (an :class:`~sdt_framework.io.OutputError`
    otherwise); its texts are drawn literally (:func:`_literal_texts`).
    """
    path = Path(folder) / name
    _literal_texts(fig)
    with atomic_path(path, root=folder) as tmp:
        fig.savefig(tmp, format="png", dpi=DPI, facecolor="white")
    return path
