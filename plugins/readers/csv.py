"""CSV signal files (the rule of :mod:`sdt_framework.signals.csv_rule`): no rate or units held."""

from __future__ import annotations

from pathlib import Path

from sdt_framework import hookimpl
from sdt_framework.signals.csv_rule import read_csv_signal
from sdt_framework.signals.rules import SignalInfo
from sdt_framework.specs import ReaderSpec


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The file's series (or the named column); the whole file is parsed."""
    parsed = read_csv_signal(path, variable)
    return SignalInfo(variable, *parsed.data.shape, note=parsed.note)


def scan(path: Path) -> list[SignalInfo]:
    """The file's series, as one signal of acquisitions."""
    return [probe(path, None)]


def read(path: Path, variable: str | None):
    """float64 (n_series, n_samples); every value checked finite."""
    return read_csv_signal(path, variable).data


@hookimpl
def register_signal_readers(register):
    """Register the CSV reader."""
    register(
        ReaderSpec(
            name="csv",
            label="CSV",
            suffixes=(".csv",),
            description="Comma-separated numbers; a header and a time column are detected",
            source="sdt-framework (docs/data.md)",
            scan=scan,
            probe=probe,
            read=read,
        )
    )
