"""Universal File Format dataset 58 (ASCII and binary 58b) through pyuff.

Simcenter Testlab, ME'scope and many modal tools export time histories as
dataset 58: one function per dataset, its abscissa increment (the sample
period), its ordinate units label. Each time response (function type 1) is a
signal named by its position among the file's datasets 58 (``1``, ``2``...);
its rate is ``1 / abscissa_inc``, which UFF stores with 6 significant digits,
so a manifest rate may differ from it by :data:`UFF_RATE_TOLERANCE`. A
spectrum, an FRF, unevenly spaced data or a dataset pyuff cannot parse is
listed and refused by name, and the file's time histories beside it read. A
file that does not end with a dataset's closing ``-1`` line is refused (a copy
cut short: pyuff would silently read only the complete datasets before the
cut); HBM catman pads that line with spaces to 80 columns. A dataset without
an ordinate units label carries a note: it is read in g.

pyuff reads the whole file into memory (about 4 bytes per byte of file,
measured below), so a file over :data:`UFF_MAX_BYTES`, or one whose parse
cannot fit in the memory available, is refused before it is read. A parsed
file is kept for the next call on the same version of it (its size and time),
the most recently used files up to :data:`PARSED_KEEP_BYTES` of arrays: a
manifest, then a benchmark's probes and reads, parse each file once in a process.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.file_sizes import check_parse_size
from sdt_framework.signals.parsed import keep_parsed
from sdt_framework.signals.rules import (
    SignalInfo,
    as_acquisitions,
    increment_rate,
    note_unstated_units,
    pick,
)
from sdt_framework.signals.tokens import brief
from sdt_framework.specs import ReaderSpec

#: where dataset 58 states units (record 9, the ordinate axis units label)
UNITS_FIELD = "ordinate_axis_units_lab"
#: 6 significant digits of an increment (UFF's E13.5 field): 1/2 unit in the 6th digit
UFF_RATE_TOLERANCE = 1e-5
#: function types of UFF dataset 58 record 6 (Universal File Format, dataset 58)
FUNCTION_TYPES = {0: "general", 1: "time response", 2: "auto spectrum", 3: "cross spectrum",
                  4: "frequency response function", 5: "transmissibility", 6: "coherence",
                  9: "power spectral density"}  # fmt: skip
#: largest UFF file read, bytes: about 35 s (ASCII) and 5 GB of memory for pyuff
UFF_MAX_BYTES = 1_000_000_000
#: peak memory of pyuff per byte of file: measured 4.0 (ASCII, 40 MB) and 3.4 (binary 58b,
#: 44 MB) with ``/usr/bin/time -v`` (2 vCPU, Python 3.11, pyuff 2.4), rounded up
UFF_PARSE_BYTES_PER_BYTE = 5
#: parsed arrays kept for the next call, bytes (the last file always, however large)
PARSED_KEEP_BYTES = 256_000_000
#: bytes at the end of a file searched for its closing ``-1``: a line of 80 columns (HBM catman
#: pads the ``-1`` with spaces to 80) many times over, and the trailing blanks some tools add
TAIL_BYTES = 4096


def _ends_complete(path: Path) -> bool:
    """The file's last line is a dataset's closing ``-1`` (catman pads it to 80 columns)."""
    size = path.stat().st_size
    with open(path, "rb") as handle:
        handle.seek(max(0, size - TAIL_BYTES))
        tail = handle.read().rstrip()
    return tail.endswith(b"-1") and tail[:-2][-1:] in (b" ", b"\n", b"\r", b"")


def _nbytes(parsed: tuple[tuple[int, ...], tuple[dict | str, ...]]) -> int:
    """Bytes of a parse's arrays (each dataset's ``data`` and ``x``)."""
    return sum(v.nbytes for d in parsed[1] if isinstance(d, dict) for v in d.values()
               if isinstance(v, np.ndarray))  # fmt: skip


@keep_parsed(PARSED_KEEP_BYTES, _nbytes)
def _sets(path: str, mtime_ns: int, size: int) -> tuple[tuple[int, ...], tuple[dict | str, ...]]:
    """(every dataset type, the datasets 58) of a file, read once per version of it; a dataset
    pyuff cannot parse is the reason, a string."""
    import pyuff

    file = Path(path)
    advice = "export fewer or shorter functions per file (one file per channel or run)"
    check_parse_size(file, "UFF", UFF_MAX_BYTES, UFF_PARSE_BYTES_PER_BYTE, advice)
    if size == 0 or not _ends_complete(file):
        raise DataFileError(
            f"{file}: truncated: the file does not end with a dataset's closing '-1' line "
            f"({size:,} bytes); copy it from the measurement system again"
        )
    try:
        uff = pyuff.UFF(path)
        types = tuple(int(t) for t in uff.get_set_types())
    except Exception as exc:  # pyuff raises bare Exception on damaged datasets
        raise DataFileError(f"{file}: not a readable UFF file (pyuff: {brief(exc)})") from None
    found = tuple(_one_set(uff, i) for i, t in enumerate(types) if t == 58)
    if not found:
        held = ", ".join(str(t) for t in sorted(set(types))) or "none"
        raise DataFileError(
            f"{file}: holds no dataset 58 (time history); its datasets are {held}; "
            f"export the measured functions as dataset 58"
        )
    return types, found


def _one_set(uff: Any, index: int) -> dict | str:
    """Dataset ``index``, or why pyuff cannot read it (one dataset it cannot parse, an FRF or
    spectrum in a layout it does not know, does not keep the others from being read)."""
    try:
        return uff.read_sets(index)
    except Exception as exc:  # pyuff wraps its parse error in a bare Exception
        return f"pyuff cannot read it ({brief(exc.__context__ or exc)})"


def _datasets(path: Path) -> tuple[dict | str, ...]:
    try:
        stat = path.stat()
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    return _sets(str(path), stat.st_mtime_ns, stat.st_size)[1]


def _units(item: dict[str, Any]) -> str | None:
    label = str(item.get("ordinate_axis_units_lab", "")).strip()
    return None if label.upper() in ("", "NONE") else label


def _info(path: Path, number: int, item: dict[str, Any] | str) -> SignalInfo:
    where = f"{path}: dataset 58 #{number}"
    if isinstance(item, str):
        return SignalInfo(str(number), 1, 0, fault=f"{where}: {item}; export it again",
                          units_field=UNITS_FIELD)  # fmt: skip
    points = int(item.get("num_pts", 0))
    rate, fault = increment_rate(path, item.get("abscissa_inc"), f"dataset 58 #{number} "
                                 "abscissa_inc")  # fmt: skip
    kind = int(item.get("func_type", 0))
    if kind != 1:
        fault = (
            f"{where} is a {FUNCTION_TYPES.get(kind, f'type {kind}')} (function type {kind}), "
            f"not a time response (type 1); export the time history"
        )
    elif int(item.get("abscissa_spacing", 1)) != 1:
        fault = f"{where} is unevenly spaced; export it evenly"
    elif len(item["data"]) != points:
        fault = (
            f"{where} declares {points:,} points and holds {len(item['data']):,}; the dataset "
            f"is damaged; export it again"
        )
    label = f"{item.get('id1', '')} node {item.get('rsp_node')} dir {item.get('rsp_dir')}"
    return SignalInfo(str(number), 1, points, rate, _units(item), "abscissa_inc",
                      UFF_RATE_TOLERANCE, label.strip(), fault=fault,
                      units_field=UNITS_FIELD)  # fmt: skip


def scan(path: Path) -> list[SignalInfo]:
    """Every dataset 58, numbered from 1."""
    infos = [_info(path, n, item) for n, item in enumerate(_datasets(path), start=1)]
    return note_unstated_units(path, infos)


def probe(path: Path, variable: str | None) -> SignalInfo:
    """Dataset 58 number ``variable``, or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (1, n_samples), all finite."""
    info = probe(path, variable)
    data = np.asarray(_datasets(path)[int(str(info.variable)) - 1]["data"])  # type: ignore[index]
    return as_acquisitions(path, data)


@hookimpl
def register_signal_readers(register):
    """Register the UFF58 reader."""
    register(
        ReaderSpec(
            name="uff58",
            label="UFF58",
            suffixes=(".uff", ".unv", ".uf"),
            description="Universal File Format dataset 58 time histories, ASCII or binary (pyuff)",
            source="pyuff (MIT); UFF dataset 58 specification",
            scan=scan,
            probe=probe,
            read=read,
        )
    )
