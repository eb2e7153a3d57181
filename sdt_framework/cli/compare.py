"""``sdt compare``: paired statistics and the verdict of one results folder, or of two."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer
from rich.table import Table
from rich.text import Text

from ..errors import SDTError
from .common import console, print_json, print_table, registry, warn
from .outdir import output_folder

__all__ = ["compare"]


def _ci(low: float, high: float) -> str:
    return "–" if np.isnan(low) else f"[{low:+.3f}, {high:+.3f}]"


def _p(value: float) -> str:
    return "–" if np.isnan(value) else f"{value:.3g}"


def _cell_text(row: Any) -> str:
    return (
        f"{row.label} {row.delta:+.3f}\nreps {_ci(row.ci_low, row.ci_high)}"
        f"\nrecs {_ci(row.rec_ci_low, row.rec_ci_high)}"
    )


def _print_tables(comparison: Any) -> None:
    """Per table (machine): rows scenario x classifier, one column per candidate."""
    table = comparison.table
    candidates = comparison.candidates
    cells = table[table["level"] == "cell"]
    outer = [c for c in comparison.groups if c != "scenario"]
    inner = [c for c in comparison.cells if c not in outer]
    title = (
        f"Δ Macro F1 to {comparison.baseline}, 95 % CIs over repetitions and recordings, "
        f"margin ±{comparison.margin:g}"
    )
    named = [i for i, c in enumerate(outer) if cells[c].nunique() > 1 or c == "machine"]
    for key, part in cells.groupby(outer, sort=False) if outer else [((), cells)]:
        key = key if isinstance(key, tuple) else (key,)
        where = " ".join(str(key[i]) for i in named)
        out = Table(title=f"{where}: {title}" if where else title, title_justify="left")
        for column in inner:
            out.add_column(column, no_wrap=True)
        for candidate in candidates:
            out.add_column(str(candidate), no_wrap=True)
        rows = part.groupby(inner, sort=False)
        previous: tuple = ()
        for values, row_part in rows:
            values = values if isinstance(values, tuple) else (values,)
            by_candidate = {r.candidate: r for r in row_part.itertuples()}
            if previous and values[0] != previous[0]:
                out.add_section()
            # a key is shown when it or a key to its left changed (a nested layout)
            shown = [
                str(v) if values[: i + 1] != previous[: i + 1] else "" for i, v in enumerate(values)
            ]
            previous = values
            out.add_row(
                *shown,
                *(_cell_text(by_candidate[c]) if c in by_candidate else "–" for c in candidates),
            )
        print_table(out)


def _resume_command(folder: Any) -> str:
    """The command that rewrites every output file of ``folder`` from its stored runs."""
    root = folder.path
    if (root / "sweep.toml").is_file():
        return f"sdt explore {root / 'sweep.toml'} --out {root}"
    return f"sdt benchmark {root / 'config.toml'} --out {root}"


def _check_recordings(folder: Any) -> None:
    """Refuse per-recording counts that do not cover the runs; warn when there are none.

    Counts missing for some runs would leave those cells without their
    recording-level interval and could move their labels (inconclusive to
    better), with nothing on screen to tell: such a folder is refused with the
    way to repair it. A folder without the file at all (written before it
    existed, or the file deleted on purpose) is compared on repetitions,
    with a warning.
    """
    if folder.per_recording_problem:
        raise SDTError(
            f"{folder.per_recording_problem}; compared without it whole, labels could change "
            f"unseen. Rewrite it by resuming ({_resume_command(folder)}: finished runs are "
            f"reused), or delete it to compare on the repetition intervals only"
        )
    if folder.per_recording is None:
        warn(
            f"{folder.path / 'per_recording.parquet'} is missing: the labels rest on the "
            f"repetition intervals only (no recording-level intervals)"
        )


def _unpaired(comparison: Any) -> None:
    """One warning naming the runs left out because their partner has no successful run."""
    left = comparison.unpaired
    if left.empty:
        return
    keys = [c for c in left.columns if c not in ("present", "missing")]
    named = [
        f"{row['present']}: "
        + " ".join(f"{k}={row[k]}" for k in keys if str(row[k]))
        + f" has no partner in {row['missing']}"
        for _, row in left.head(3).iterrows()
    ]
    more = f"; and {len(left) - 3} more" if len(left) > 3 else ""
    warn(
        f"{len(left)} run{'s' if len(left) > 1 else ''} left out of the comparison, "
        f"{'their partners have' if len(left) > 1 else 'its partner has'} no successful run: "
        + "; ".join(named)
        + more
    )


def compare(
    ctx: typer.Context,
    results_dirs: Annotated[
        list[Path],
        typer.Argument(
            metavar="RESULTS_DIR [OTHER_DIR]",
            help="A folder written by `sdt benchmark`; with a second folder, compare the two.",
        ),
    ],
    baseline: Annotated[
        str | None,
        typer.Option(
            "--baseline",
            help="Sensor to compare with (default: the folder's reference sensor); "
            "with two folders, the label of one of them (default: the first).",
        ),
    ] = None,
    margin: Annotated[
        float,
        typer.Option("--margin", help="Equivalence margin in Macro F1 (> 0)."),
    ] = 0.02,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of tables.")] = False,
    zones: Annotated[
        list[str] | None,
        typer.Option(
            "--zones",
            help="Zone table for every machine (built-in name or FILE.toml[#name]), or "
            "MACHINE=TABLE; repeatable. Default: Motor-2 iso20816-1-typical-low, Motor-4 "
            "iso10816-3-group2-rigid (docs/severity.md).",
        ),
    ] = None,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            help="Folder for the comparison table (default: the results folder; needed when "
            "that folder is read-only).",
        ),
    ] = None,
) -> None:
    """Paired comparison of every sensor with the reference, and the verdict.

    Runs of two sensors sharing machine, scenario, classifier and repetition
    are paired. Per cell and per machine/scenario: the mean Macro F1
    difference with a 95 % interval over repetitions and one over resampled
    test recordings, a paired t p-value (Holm-adjusted over cells) and the
    label equivalent / worse / better / inconclusive at the margin; then the
    Friedman test, Nemenyi critical difference and plain-sentence verdict.
    Writes comparison.csv into RESULTS_DIR (or --out). With two folders (e.g.
    two feature sets), runs are paired by machine, scenario, sensor,
    classifier and repetition, and the table goes to
    OTHER_DIR/comparison_vs_<first>.csv (or into --out). Runs without a
    partner are named in a warning; a per_recording.parquet that does not
    cover every run is refused (one line says how to rewrite it). With one
    folder, also the ISO zone agreement of every sensor with the reference
    (V_RMS graded A-D per window, the dangerous better-zone share), the zone
    per condition and criterion II alarms on each sensor's own baseline.

    Example:

      sdt benchmark --quick --out results/first-look

      sdt compare results/first-look

      sdt compare results/first-look --baseline adxl357 --margin 0.05 --json

      sdt benchmark --quick --feature-dtype float16 --out results/float16

      sdt compare results/first-look results/float16

      sdt compare results/first-look --out results/verdict   # e.g. from a read-only folder

      sdt compare results/first-look --zones Motor-4=iso10816-3-group2-flexible
    """
    from ..bench import write_frame
    from ..report import load_results
    from ..verdict import compare as run_compare
    from ..verdict import pair_folders, verdict
    from .compare_severity import check_zones, print_severity, severity_agreement, severity_json
    from .compare_speed import print_speed_loss, speed_loss_json, speed_tables

    check_zones(zones)
    if len(results_dirs) > 2:
        raise SDTError(f"give one or two results folders, got {len(results_dirs)}")
    folders = [load_results(path) for path in results_dirs]
    for folder in folders:
        _check_recordings(folder)
    pair = None
    if len(folders) == 2:  # the folders are compared, run by run (verdict.pair_folders)
        pair = pair_folders(
            [f.results for f in folders],
            [f.path for f in folders],
            per_recording=[f.per_recording for f in folders],
            allocation=folders[0].allocation,
            baseline=baseline,
        )
        csv_path = folders[1].path / pair.table_name
    else:
        csv_path = folders[0].path / "comparison.csv"
    csv_path = output_folder(csv_path.parent, out, "the comparison table") / csv_path.name
    if pair is not None:
        comparison = pair.compare(margin)
    else:
        folder = folders[0]
        comparison = run_compare(
            folder.results,
            baseline or folder.reference,
            margin=margin,
            per_recording=folder.per_recording,
            allocation=folder.allocation,
            order=folder.sensors,
        )
    _unpaired(comparison)
    write_frame(comparison.table, csv_path)
    findings = verdict(comparison)
    severity, note = None, "two folders: zone agreement is given for one folder"
    if len(folders) == 1:
        reg = registry(ctx)
        severity, note = severity_agreement(folders[0], zones, comparison.baseline, registry=reg)
    speed = speed_tables(folders[-1], comparison.baseline)  # the loss under a speed shift
    if as_json:
        ranking = comparison.ranking
        print_json(
            {
                "baseline": comparison.baseline,
                "margin": comparison.margin,
                "treatment": comparison.treatment,
                "csv": str(csv_path),
                "verdict": [{"scope": f.scope, "text": f.text} for f in findings],
                "unpaired": json.loads(comparison.unpaired.to_json(orient="records")),
                "ranking": None
                if ranking is None
                else {
                    "average_ranks": ranking.ranks.to_dict(),
                    "n_blocks": ranking.n_blocks,
                    "chi2": ranking.chi2,
                    "p_value": ranking.p_value,
                    "ff": ranking.ff,
                    "p_ff": ranking.p_ff,
                    "cd": ranking.cd,
                },
                "table": json.loads(comparison.table.to_json(orient="records")),
                "severity": severity_json(severity, note),
                "speed_loss": speed_loss_json(speed),
            }
        )
        return
    _print_tables(comparison)
    if speed is not None:
        print_speed_loss(speed, comparison.baseline)
    console.print(Text("Verdict", style="bold"))
    for finding in findings:  # user strings (sensor names) are printed as given
        console.print(Text.assemble((finding.scope, "bold"), ": ", finding.text), highlight=False)
    if severity is not None:
        print_severity(severity)
    else:
        console.print(f"zone agreement: {note}", highlight=False, soft_wrap=True)
    console.print(f"comparison table: {csv_path}", highlight=False, soft_wrap=True)
