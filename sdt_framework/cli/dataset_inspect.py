"""What ``sdt dataset inspect`` does with a dataset: open it as asked, print it.

:func:`open_inspected` opens it at the speeds asked (``--speeds``, handed to a
dataset that has speed folders) and reads the speed of each recording that
carries none off its spectrum when asked (``--estimate-speed``).
:func:`print_dataset` prints a line per recording (its speed label and shaft
speed, rpm, ``-`` where none is known), then one ``speed`` line per operating
point saying where its speed comes from (the archive's speed folder and the
rig's figure, a manifest's ``speed_rpm`` column, or an estimate from the
spectrum with its confidence), what was skipped, and the summary line.
"""

from __future__ import annotations

import math
from typing import Any

from ..errors import SDTError
from .common import console, registry, shorten_labels
from .dataset_files import cell

__all__ = ["open_inspected", "parse_speeds", "print_dataset"]

HEADER = ["machine", "speed", "rpm", "condition", "severity", "channel", "run", "recording_id",
          "acquisitions", "samples", "fs_hz"]  # fmt: skip


def _rpm(value: float | None) -> str:
    return "-" if value is None else f"{value:.0f}"


def _row(r: dict[str, Any]) -> list[Any]:
    return [
        cell(r["machine"]),
        cell(r["speed"] or "-"),
        _rpm(r["speed_rpm"]),
        cell(r["condition"]),
        "-" if r["severity"] is None else r["severity"],
        cell(r["channel"]),
        cell(r["run"]),
        cell(r["recording_id"]),
        r["n_acquisitions"],
        r["samples_per_acquisition"],
        f"{r['sampling_rate_hz']:g}",
    ]


def speed_line(s: dict[str, Any]) -> str | None:
    """One operating point of ``describe()["summary"]["speeds"]``; None when nothing is known."""
    if s["speed_rpm"] is None and s["speed_percent"] is None and not s["speed_source"]:
        return None
    rpm = "no rpm" if s["speed_rpm"] is None else f"{s['speed_rpm']:.0f} rpm"
    percent = "" if s["speed_percent"] is None else f", {s['speed_percent']:.3g} % of rated"
    n = s["recordings"]
    return (
        f"speed {s['machine']} {s['speed'] or '-'}: {rpm}{percent} ({n} recording"
        f"{'s' if n != 1 else ''}): {s['speed_source'] or 'no source'}"
    )


def print_dataset(info: dict[str, Any], summary_line: str) -> None:
    """The text ``sdt dataset inspect`` prints for ``info`` (``Dataset.describe()``)."""
    rows = [_row(r) for r in info["recordings"]]
    widths = [max(len(str(x)) for x in col) for col in zip(HEADER, *rows, strict=False)]
    for line in [HEADER, *rows]:
        console.print(
            "  ".join(str(x).ljust(w) for x, w in zip(line, widths, strict=True)),
            highlight=False,
            soft_wrap=True,
        )
    for speed in info["summary"]["speeds"]:
        text = speed_line(speed)
        if text is not None:
            console.print(shorten_labels(text), markup=False, highlight=False, soft_wrap=True)
    for item in info["skipped"]:
        console.print(
            shorten_labels(f"skipped {item['path']}: {item['reason']}"),
            highlight=False,
            soft_wrap=True,
        )
    console.print(shorten_labels(summary_line), highlight=False, soft_wrap=True)


def parse_speeds(text: str | None) -> str | list[float | str] | None:
    """``--speeds``: ``all``, or a comma list whose numbers are numbers (``50,75``) and
    whose other names are speed labels as written."""
    if text is None or text.strip().lower() == "all":
        return None if text is None else "all"
    items = [item.strip() for item in text.split(",")]
    if not all(items):
        raise SDTError(f"--speeds {text!r}: an empty name; give 'all' or e.g. 50,75,100")
    out: list[float | str] = []
    for item in items:
        try:
            out.append(float(item) if item.isascii() else item)
        except ValueError:
            out.append(item)
    return out


def open_inspected(
    ctx: Any,
    path_or_name: str,
    *,
    speeds: str | None,
    validate: bool,
    estimate: bool,
    nominal_rpm: float | None,
) -> Any:
    """The dataset ``inspect`` shows: opened at ``speeds`` (the dataset's ``speeds``
    option), validated, its speeds estimated where none is carried, as asked."""
    from ..data import (
        estimate_speeds,
        open_dataset,  # heavy (scipy, pyarrow): on use only
    )
    from .guards import os_errors

    if nominal_rpm is not None and not (math.isfinite(nominal_rpm) and nominal_rpm > 0):
        raise SDTError(f"--nominal-rpm {nominal_rpm:g}: give the shaft speed in rpm, above 0")
    chosen = parse_speeds(speeds)
    options = {} if chosen is None else {"speeds": chosen}
    with os_errors(path_or_name):
        try:
            dataset = open_dataset(registry(ctx), path_or_name, **options)
        except TypeError as exc:
            if "'speeds'" not in str(exc):
                raise
            raise SDTError(
                f"--speeds: {path_or_name} has no speed folders to choose from (its dataset "
                f"takes no speeds option); drop --speeds: its recordings show their speed"
            ) from None
        if validate:
            dataset.validate()
        if estimate or nominal_rpm is not None:
            estimate_speeds(dataset, nominal=nominal_rpm)
    return dataset
