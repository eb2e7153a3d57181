"""DAQ files written as the DAQ software writes them, for tests that need a layout no library
writes: LabVIEW's LVM (``X_Columns`` ``Multi`` or ``One``) and HBM catman's UFF58.

The layouts are copied from real files in ``tests/data/readers/corpus`` (see its README):

- LVM ``Multi``, as lvm_read's ``multi_time_column.lvm`` (LabVIEW 2016): header lines end with
  a separator, one cell pair per channel (``Samples\\t51200\\t\\t51200\\t``), the column-name row
  ``X_Value\\tVoltage\\tX_Value\\tAcceleration\\tComment``, a data row a pair of cells per channel
  (a channel shorter than the others leaves its cells empty, as in ARTS-Lab's
  ``Test_001.lvm``, LabVIEW 2023). ``One``: one cell per channel, one X column.
- Values as LabVIEW prints them (``Test_001.lvm``): six decimals (``0.000117``), and below 1e-4
  ``%.6E`` with a bare exponent (``1.953125E-5``).
- catman UFF58 as pyuff's ``time-history-not-all-columns-filled.uff`` ("UFF58 file created by
  HBM catman"): every line padded with spaces to 80 characters (data lines to 78, six values
  of ``%13.5E``), record 7's abscissa numbers with three exponent digits (``5.00000E-005``),
  the closing ``-1`` padded to 80.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

CORPUS = Path(__file__).parents[1] / "data" / "readers" / "corpus"
CATMAN = CORPUS / "pyuff-time-history-not-all-columns-filled.uff"
#: pyuff's real PSD (VibControl): a file holding only it is refused, so it is not in the corpus
PSD = CORPUS.parent / "sample_dataset58_psd.uff"

FILE_HEADER = (
    "LabVIEW Measurement\t\nWriter_Version\t2\nReader_Version\t2\nSeparator\tTab\n"
    "Decimal_Separator\t.\nMulti_Headings\tYes\nX_Columns\t{layout}\nTime_Pref\tAbsolute\n"
    "Operator\tsdt\nDate\t2016/08/23\nTime\t10:45:47.0352557312499836422\n"
    "***End_of_Header***\t\n\t\n"
)


@dataclass
class Channel:
    """One channel of one LVM segment: its samples and header cells. ``x`` is its X column
    (default ``i * delta_x``), ``samples`` its header's ``Samples`` (default its length)."""

    name: str
    values: np.ndarray
    delta_x: float
    units: str = "g"
    x: np.ndarray | None = None
    samples: int | None = None
    dimension: str = "Time"
    delta_text: str | None = None


def number(value: float) -> str:
    """``value`` as LabVIEW writes it in an LVM file."""
    if value != 0 and abs(value) < 1e-4:
        mantissa, exponent = f"{value:.6E}".split("E")
        return f"{mantissa}E{int(exponent)}"
    return f"{value:.6f}"


def _segment(channels: list[Channel], layout: str) -> str:
    k, multi = len(channels), layout == "Multi"

    def row(key: str, cells: list[str]) -> str:
        r"""``Samples\t51200\t\t51200\t`` (Multi), ``Samples\t51200\t51200\t`` (One)."""
        return (
            key + "".join(f"\t{c}\t" if multi else f"\t{c}" for c in cells) + ("\t" * (not multi))
        )

    head = (
        f"Channels\t{k}" + "\t" * (2 * k - 1 if multi else k) + "\n"
        + row("Samples", [str(c.samples if c.samples is not None else len(c.values))
                          for c in channels]) + "\n"
        + row("Date", ["2016/08/23"] * k) + "\n"
        + row("Time", ["10:45:47.0352557312499836422"] * k) + "\n"
        + row("Y_Unit_Label", [c.units for c in channels]) + "\n"
        + row("X_Dimension", [c.dimension for c in channels]) + "\n"
        + row("X0", ["0.0000000000000000E+0"] * k) + "\n"
        + row("Delta_X", [c.delta_text or number(c.delta_x) for c in channels]) + "\n"
        + "***End_of_Header***" + "\t" * (2 * k if multi else k + 1) + "\n"
    )  # fmt: skip
    names = [f"X_Value\t{c.name}" for c in channels] if multi else [
        "X_Value\t" + "\t".join(c.name for c in channels)]  # fmt: skip
    head += "\t".join(names) + "\tComment\n"
    n = max(len(c.values) for c in channels)
    columns = []
    for i, c in enumerate(channels):
        x = c.x if c.x is not None else np.arange(len(c.values)) * c.delta_x
        pair = [[number(v) for v in x], [number(v) for v in c.values]]
        for cells in pair if multi else pair[i > 0 :]:
            columns.append(cells + [""] * (n - len(cells)))
    return head + "".join("\t".join(r) + "\n" for r in zip(*columns, strict=True))


def lvm_text(segments: list[list[Channel]], layout: str = "Multi") -> str:
    """A whole LVM file: the file header, then each segment after a line holding one tab."""
    return FILE_HEADER.format(layout=layout) + "\t\n".join(_segment(s, layout) for s in segments)


def _pad(text: str, width: int = 80) -> str:
    return text.ljust(width) + "\n"


def _e3(value: float) -> str:
    """catman's record-7 number: ``5.00000E-005``."""
    mantissa, exponent = f"{value:.5E}".split("E")
    return f"{mantissa}E{exponent[0]}{int(exponent[1:]):03d}"


def catman_uff(channels: dict[str, np.ndarray], rate_hz: float, units: str = "m/s²") -> str:
    """One catman time history (dataset 58, ASCII) per channel, in the real file's layout: its
    header lines with the name, point count, increment and units put in."""
    lines = CATMAN.read_text(encoding="utf-8").split("\n")[:13]
    out = []
    for name, values in channels.items():
        header = [line.rstrip(" ") for line in lines]
        header[2] = f"{name} : {units}"
        header[8] = f"{2:10d}{len(values):10d}{1:10d} {_e3(0.0)} {_e3(1 / rate_hz)} {_e3(0.0)}"
        header[10] = f"{1:10d}{0:5d}{0:5d}{0:5d} {name:<20} {units}"
        out += [_pad(h) for h in header]
        cells = [f"{v:13.5E}" for v in values]
        out += [_pad("".join(cells[i : i + 6]), 78) for i in range(0, len(cells), 6)]
        out.append(_pad("    -1"))
    return "".join(out)
