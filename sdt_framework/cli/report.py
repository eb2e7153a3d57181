"""``sdt report``: the paper's tables and figures from a results folder, as Markdown and HTML."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated

import typer

from ..errors import SDTError
from .common import console, registry
from .outdir import output_folder

__all__ = ["report"]


def report(
    ctx: typer.Context,
    results_dir: Annotated[
        Path, typer.Argument(metavar="RESULTS_DIR", help="Folder written by `sdt benchmark`.")
    ],
    format_: Annotated[
        str,
        typer.Option("--format", help="Comma-separated: md (report.md), html (report.html)."),
    ] = "md,html",
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            help="Folder for the report and figures (default: RESULTS_DIR; needed when it is "
            "read-only).",
        ),
    ] = None,
) -> None:
    """Write report.md and a self-contained report.html into RESULTS_DIR (or --out).

    Table 4 (mean ± SD Macro F1), deltas to the reference sensor, failed runs,
    paper Fig. 2, 3, 4, 6 and 7 (also as PNG files in RESULTS_DIR/figures),
    the allocation, the configuration, timings and software versions. Missing
    optional files are listed in the report instead of stopping it.

    Example:

      sdt benchmark --quick --out results/first-look --no-report

      sdt report results/first-look

      sdt report results/first-look --format html

      sdt report results/first-look --out results/first-look-report   # e.g. from a read-only folder
    """
    from ..report import write_report  # matplotlib only when a report is drawn

    formats = tuple(part.strip() for part in format_.split(",") if part.strip())
    if not formats:
        raise SDTError("--format needs md, html or md,html")
    if not Path(results_dir).is_dir():  # named as a missing results folder, not an output one
        raise SDTError(f"{results_dir}: not a results folder (no such directory)")
    target = output_folder(Path(results_dir), out, "the report")
    start = time.perf_counter()
    written = write_report(results_dir, formats, registry=registry(ctx), out_dir=target)
    figures = sorted((target / "figures").glob("*.png"))
    console.print(
        f"report of {results_dir} in {time.perf_counter() - start:.1f} s: "
        + ", ".join(str(p) for p in written.values())
        + f" ({len(figures)} figures in {target / 'figures'})",
        highlight=False,
        soft_wrap=True,
    )
