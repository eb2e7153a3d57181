"""LVM text as LabVIEW's Write To Measurement File writes it (Writer_Version 2, tab separated,
'.' decimal, X_Columns One, a segment header per write), byte for byte in the layout of the
real files lvm_read ships (``tests/data/readers/short.lvm``): header lines end with a tab,
every line with a line break, values with six decimals, ``Delta_X`` as ``%.6E``."""

from __future__ import annotations

import io

import numpy as np

FILE_HEADER = (
    "LabVIEW Measurement\t\nWriter_Version\t2\nReader_Version\t2\nSeparator\tTab\n"
    "Decimal_Separator\t.\nMulti_Headings\tYes\nX_Columns\tOne\nTime_Pref\tRelative\n"
    "Operator\tsdt\nDate\t2024/05/14\nTime\t10:00:00.000000\n***End_of_Header***\t\n\t\n"
)


def segment(names: list[str], rows: np.ndarray, delta_x: float, units: str = "g") -> str:
    """One segment: its header (one cell per channel) and ``rows`` (samples x channels)."""

    def cells(value: str) -> str:
        return "\t".join([value] * len(names)) + "\t\n"

    header = (
        f"Channels\t{len(names)}\t\n"
        f"Samples\t{cells(str(len(rows)))}"
        f"Date\t{cells('2024/05/14')}"
        f"Time\t{cells('10:00:00.000000')}"
        f"Y_Unit_Label\t{cells(units)}"
        f"X_Dimension\t{cells('Time')}"
        f"X0\t{cells('0.0000000000000000E+0')}"
        f"Delta_X\t{cells(f'{delta_x:.6E}')}"
        f"***End_of_Header***\t{chr(9) * len(names)}\n"
        f"X_Value\t{chr(9).join(names)}\tComment\n"
    )
    body = io.StringIO()
    np.savetxt(body, np.c_[np.arange(len(rows)) * delta_x, rows], fmt="%.6f", delimiter="\t")
    return header + body.getvalue()


def lvm(segments: list[str]) -> str:
    """A whole file: the file header, then each segment after a line holding one separator
    (as after the file header)."""
    return FILE_HEADER + "\t\n".join(segments)
