"""``sdt benchmark``: the main job — every sensor x classifier x scenario, repeated.

Exit status: 0 when every classifier produced results; 1 when some classifier
failed in every one of its runs (results are still written, a summary line
names it and its first error); 2 for a user error (one line, nothing run);
130 after Ctrl-C and 143 after SIGTERM, each with one line giving the exact
command that resumes.
"""

from __future__ import annotations

import datetime as dt
import shlex
from pathlib import Path
from typing import Any

import typer
from rich.text import Text

from .benchmark_table import print_table4
from .common import console, err_console, registry, shorten_labels, warn
from .dataset_inspect import parse_speeds

EXIT_CLASSIFIER_FAILED = 1
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as a shell reports a process ended by Ctrl-C
EXIT_TERMINATED = 143  # 128 + SIGTERM


def _say(label: str, style: str, message: str) -> None:
    """One line on stderr; ``message`` is printed as given (over-long labels shortened),
    never read as markup."""
    err_console.print(
        Text.assemble((label, style), " ", shorten_labels(message)), highlight=False, soft_wrap=True
    )


def _resume_command(ctx: typer.Context, out_dir: Path, yes: bool) -> str:
    """The exact command that resumes the benchmark in ``out_dir`` (from its config.toml)."""
    root = ctx.find_root()
    files = (root.obj or {}).get("sensor_files", [])
    command = ["sdt", *[a for f in files for a in ("--sensor-file", str(f))], "benchmark"]
    command += [str(out_dir / "config.toml"), "--out", str(out_dir)]
    return shlex.join(command + (["--yes"] if yes else []))


def _interrupted(
    ctx: typer.Context, out_dir: Path, yes: bool, claimed: bool, terminated: bool = False
) -> typer.Exit:
    """The one line after Ctrl-C or SIGTERM: how to resume once ``out_dir`` is claimed,
    else start again."""
    label = "terminated:" if terminated else "interrupted:"
    if claimed:
        stored = len(list((out_dir / "runs").glob("*.json")))
        _say(
            label,
            "yellow",
            f"{stored} finished run{'' if stored == 1 else 's'} kept in {out_dir}; resume with: "
            f"{_resume_command(ctx, out_dir, yes)}",
        )
    else:
        _say(label, "yellow", "before the run started; run the same command again")
    return typer.Exit(EXIT_TERMINATED if terminated else EXIT_INTERRUPTED)


def _failures(results: Any) -> bool:
    """Print one line per classifier with failed runs; True if one failed in all of them."""
    any_total = False
    for name, part in results.groupby("classifier", sort=True):
        failed = part[part["status"] == "error"]
        if failed.empty:
            continue
        first = " ".join(str(failed["error"].iloc[0]).split())[:200]
        whole = len(failed) == len(part)
        any_total |= whole
        _say(
            "error:" if whole else "warning:",
            "bold red" if whole else "yellow",
            f"classifier {name!r} failed in {'all ' if whole else ''}{len(failed)} of "
            f"{len(part)} runs (first error: {first})",
        )
    return any_total


def _names(value: str | None) -> list[str] | None:
    return [part.strip() for part in value.split(",") if part.strip()] if value else None


def _sensor_names(value: str | None) -> list[str] | None:
    """Comma-separated sensor names; commas inside a part's mode brackets stay."""
    from ..parts import split_names

    return split_names(value) or None if value else None


def benchmark(
    ctx: typer.Context,
    config_file: Path | None = typer.Argument(None, help="TOML config (\\[benchmark] table)."),
    data: str | None = typer.Option(None, "--data", help="NLN-EMP root folder or manifest."),
    dataset: str | None = typer.Option(None, "--dataset", help="Registered dataset name."),
    sensors: str | None = typer.Option(
        None,
        "--sensors",
        help="Comma-separated sensor names; a part with a mode as adxl355\\[range=8g,odr=4000] "
        "(default: the reference, adxl345, adxl357).",
    ),
    transfer: list[str] | None = typer.Option(
        None,
        "--transfer",
        help="Cross-chain runs 'TRAIN -> TEST' (repeatable): train on one chain, test on "
        "another, e.g. 'wilcoxon-786b10 -> adxl345,adxl357', 'reference -> *', or a mix "
        "'wilcoxon-786b10+adxl345 -> adxl345'.",
    ),
    sample: str | None = typer.Option(
        None,
        "--sample",
        help="channel (default, the paper's) or node: one sample per window per triaxial node "
        "(config keys axes and nodes in \\[benchmark]).",
    ),
    classifiers: str | None = typer.Option(None, "--classifiers", help="Comma-separated."),
    features: str | None = typer.Option(None, "--features", help="Feature set: paper8, orders."),
    feature_dtype: str | None = typer.Option(
        None, "--feature-dtype", help="Round features to float16 or float32 before classifying."
    ),
    scenarios: str | None = typer.Option(
        None, "--scenarios", help="Comma-separated: forward,backward,interpolation,speed-transfer."
    ),
    speeds: str | None = typer.Option(
        None, "--speeds", help="Operating speeds to use, e.g. 50,75,100 (docs/report.md)."
    ),
    machines: str | None = typer.Option(None, "--machines", help="Comma-separated machines."),
    channels: str | None = typer.Option(None, "--channels", help="Comma-separated channels."),
    allocation: str | None = typer.Option(
        None, "--allocation", help="CSV/TOML train/test table replacing the scenario rule."
    ),
    repeats: int | None = typer.Option(None, "--repeats", help="Repetitions N (default 10)."),
    units: int | None = typer.Option(
        None, "--units", help="Physical units per sensor, drawn from its tolerances."
    ),
    seed: int | None = typer.Option(None, "--seed", help="Base seed (default 0)."),
    out: Path | None = typer.Option(
        None, "--out", help="Output folder (default results/<timestamp>); reuse it to resume."
    ),
    jobs: int | None = typer.Option(
        None, "--jobs", help="Processes (default: all cores; this one alone under 5 s of work)."
    ),
    backend: str | None = typer.Option(None, "--backend", help="local (default) or dask."),
    scheduler: str | None = typer.Option(None, "--scheduler", help="Dask scheduler address."),
    cache_dir: str | None = typer.Option(None, "--cache-dir", help="Feature cache folder."),
    quick: bool = typer.Option(
        False,
        "--quick",
        help="Small preset: 2 repeats; 4 s synthetic acquisitions or 5 per NLN-EMP run.",
    ),
    no_report: bool = typer.Option(False, "--no-report", help="Skip report.md/report.html."),
    yes: bool = typer.Option(
        False, "--yes", help="Start even if the estimated time is over an hour."
    ),
) -> None:
    """Benchmark sensors x classifiers x scenarios and write tidy results and Table 4.

    With no data it runs on the embedded synthetic-pump dataset. Every name
    resolves through the plugin registry, so installed sensor plugins and
    --sensor-file profiles join by name. Re-using --out resumes a run of the
    same configuration; Ctrl-C (or SIGTERM) stops it and prints the command that resumes.
    A benchmark estimated at over an hour needs --yes.

    Example:

      sdt benchmark --quick --out results/first-look

      sdt benchmark --sensors wilcoxon-786b10,adxl345,adxl357 --classifiers lr,rf --repeats 5

      sdt benchmark --quick --sensors "wilcoxon-786b10,adxl355\\[range=8g],iis3dwb,mpu6050"

      sdt benchmark --data ~/data/NLN-EMP --out results/nln   # needs NLN-EMP downloaded (README)

      sdt benchmark --quick --units 5

      sdt benchmark --quick --transfer "wilcoxon-786b10 -> adxl345,adxl357"

      sdt benchmark --quick --speeds 50,75,100 --scenarios speed-transfer --classifiers lr
    """
    # Imported here so that `sdt --help` and the listing commands start fast.
    from ..bench import load_config, watch_interrupts

    given: dict[str, Any] = {
        "data": data,
        "dataset": dataset,
        "sensors": _sensor_names(sensors),
        "classifiers": _names(classifiers),
        "features": features,
        "feature_dtype": feature_dtype,
        "scenarios": _names(scenarios),
        "speeds": parse_speeds(speeds),
        "machines": _names(machines),
        "channels": _names(channels),
        "allocation": allocation,
        "repeats": repeats,
        "units": units,
        "transfer": transfer or None,
        "sample": sample,
        "seed": seed,
        "jobs": jobs,
        "backend": backend,
        "scheduler": scheduler,
        "cache_dir": cache_dir,
    }
    overrides = {k: v for k, v in given.items() if v is not None}
    if quick:
        overrides["quick"] = True
    if no_report:
        overrides["report"] = False
    out_dir = out or Path("results") / dt.datetime.now().strftime("%Y%m%d-%H%M%S")
    claimed: list[bool] = []  # set once the results folder is claimed (resumable from then on)
    with watch_interrupts(terminate=True) as watch:
        try:
            config = load_config(config_file, overrides)
            failed = _run(ctx, config, out_dir, yes, claimed)
        except KeyboardInterrupt:
            raise _interrupted(ctx, out_dir, yes, bool(claimed), watch.terminated) from None
        except Exception:
            if not watch.seen:  # e.g. a worker pool broken by the same Ctrl-C or SIGTERM
                raise
            raise _interrupted(ctx, out_dir, yes, bool(claimed), watch.terminated) from None
    if failed:
        raise typer.Exit(EXIT_CLASSIFIER_FAILED)


def _run(ctx: typer.Context, config: Any, out_dir: Path, yes: bool, claimed: list[bool]) -> bool:
    """The main job (:func:`~sdt_framework.bench.run_benchmark_folder`) with the terminal's
    lines and the report; True if some classifier failed in all its runs.

    The results folder stays locked from its claim until the outputs and the report are
    written (:mod:`~sdt_framework.bench.folder_lock`).
    """
    from ..bench import ASSUMES, run_benchmark_folder, saturation_lines, saturation_summary
    from .benchmark_notes import start_lines
    from .planned import print_skipped
    from .progress import Bars

    reg = registry(ctx)
    bars = Bars()

    def check(plan: Any) -> None:
        if config.zones or plan.machines:  # zone tables checked before any run (severity)
            from ..severity import assign_tables

            machines = sorted({r.machine for r in plan.recordings})
            where, window_s = "[benchmark] zones", config.window_s
            assign_tables(
                machines, configured=config.zones, where=where, window_s=window_s,
                specs=plan.machines,
            )  # fmt: skip

    def started(plan: Any, size: Any) -> None:
        claimed.append(True)
        print_skipped(plan)
        console.print(
            f"{plan.dataset.name}: {len(plan.recordings)} recordings, {len(plan.sensors)} "
            f"sensors, {len(plan.classifiers)} classifiers, {len(config.scenarios)} scenarios, "
            f"{config.repeats} repeats -> {out_dir}",
            highlight=False,
            soft_wrap=True,
        )
        _say("note:", "yellow", f"this benchmark is {size.line()} ({ASSUMES})")
        for label, line in start_lines(plan, size):
            _say(label, "yellow", line)

    def finish(run: Any) -> None:
        bars.close()
        print_table4(run.results, [s.name for s in run.plan.sensors])
        for line in saturation_lines(saturation_summary(run.result.saturation)):
            warn(line)
        if config.report:
            from ..report import write_report  # the report layer sits above the benchmark

            write_report(out_dir, registry=reg)

    try:
        run = run_benchmark_folder(
            config, reg, out_dir, yes=yes, progress=bars, warn=warn, check=check,
            started=started, finish=finish,
        )  # fmt: skip
    finally:
        bars.close()
    result = run.result
    console.print(
        f"{len(run.results)} runs ({result.runs_computed} computed, {result.runs_resumed} "
        f"resumed, {run.failed} failed) in {sum(result.seconds.values()):.0f} s; results in "
        f"{out_dir}",
        highlight=False,
        soft_wrap=True,
    )
    return _failures(run.results)
