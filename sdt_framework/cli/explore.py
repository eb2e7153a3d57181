"""``sdt explore``: which sensor specification is enough — a sweep over chain parameters."""

from __future__ import annotations

import datetime as dt
import shlex
import sys
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from .common import console, err_console, registry, table, warn

if TYPE_CHECKING:
    from ..bench.estimate import Estimate


def _example() -> str:
    return resources.files("sdt_framework.explore").joinpath("example_sweep.toml").read_text()


def _print_min_spec(min_spec: Any) -> None:
    """The minimum specification per machine and scenario (best classifier), as a table."""
    best = min_spec[min_spec["classifier"] == "best"]
    if best.empty:
        return
    wide = best.pivot_table(
        index=["machine", "scenario"], columns="parameter", values="min_level", dropna=False
    )
    rows = [
        [machine, scenario, *("none" if v != v else f"{v:g}" for v in values)]
        for (machine, scenario), values in zip(wide.index, wide.to_numpy(), strict=True)
    ]
    bases = best.drop_duplicates("parameter").set_index("parameter")["base_level"]
    columns = [f"{p} (base {'absent' if bases[p] != bases[p] else f'{bases[p]:g}'})" for p in wide]
    title = f"Minimum specification: {best['target'].iloc[0]} (best classifier)"
    table(title, ["machine", "scenario", *columns], rows)


def explore(
    ctx: typer.Context,
    sweep_file: Path | None = typer.Argument(
        None, help="Sweep TOML file (a sweep table, optional benchmark table)."
    ),
    data: str | None = typer.Option(None, "--data", help="NLN-EMP root folder or manifest."),
    quick: bool = typer.Option(False, "--quick", help="The benchmark's quick preset."),
    jobs: int | None = typer.Option(None, "--jobs", help="Processes (default: all cores)."),
    backend: str | None = typer.Option(None, "--backend", help="local (default) or dask."),
    scheduler: str | None = typer.Option(None, "--scheduler", help="Dask scheduler address."),
    out: Path | None = typer.Option(
        None, "--out", help="Output folder (default results/explore-<timestamp>); reuse to resume."
    ),
    yes: bool = typer.Option(False, "--yes", help="Run even if the estimate exceeds an hour."),
    example: bool = typer.Option(False, "--example", help="Print a commented starter sweep."),
    no_report: bool = typer.Option(False, "--no-report", help="Skip report.md/report.html."),
) -> None:
    """Sweep sensor parameters around a base sensor and find the minimum specification.

    Every design point runs the full `sdt benchmark` protocol; the folder gets
    explore.parquet, points.csv, skipped_points.csv, main_effects.csv,
    sensitivity.csv, min_spec.csv, pareto.csv and an Exploration report section.

    Example:

      sdt explore --example > my_sweep.toml

      sdt explore examples/sweeps/rate_noise.toml --quick --out results/rate-noise
    """
    if example:
        sys.stdout.write(_example())  # verbatim: no wrapping, no markup
        return
    if sweep_file is None:
        raise typer.BadParameter("give a sweep file, or --example to print one", param_hint="SWEEP")
    from ..bench.interrupt import watch_interrupts
    from ..data.sizes import building
    from ..explore.sweep_file import load_sweep
    from ..inputs import require_regular_file

    require_regular_file(sweep_file, "sweep file")
    with building(f"reading the sweep file {sweep_file}", "shorten its ties and levels"):
        sweep, protocol = load_sweep(sweep_file)
    given = {"data": data, "jobs": jobs, "backend": backend, "scheduler": scheduler}
    overrides: dict[str, Any] = {k: v for k, v in given.items() if v is not None}
    if quick:
        overrides["quick"] = True
    out_dir = out or Path("results") / dt.datetime.now().strftime("explore-%Y%m%d-%H%M%S")
    resume = shlex.join(["sdt", "explore", str(sweep_file), "--out", str(out_dir)])
    with watch_interrupts(terminate=True) as watch:
        try:
            tables = _run(ctx, sweep, protocol, overrides, str(sweep_file), out_dir, yes, no_report)
        except (KeyboardInterrupt, Exception) as exc:
            if not isinstance(exc, KeyboardInterrupt) and not watch.seen:
                raise  # not a pool broken by the same Ctrl-C or SIGTERM: a real error
            err_console.print(
                f"{'terminated' if watch.terminated else 'interrupted'}: finished runs are kept "
                f"in {out_dir}; resume with the same command and --out "
                f"({resume}{' --quick' if quick else ''})",
                highlight=False,
                soft_wrap=True,
            )
            raise typer.Exit(143 if watch.terminated else 130) from None
    _print_min_spec(tables["min_spec"])


def _run(
    ctx: typer.Context,
    sweep: Any,
    protocol: dict[str, Any],
    overrides: dict[str, Any],
    where: str,
    out_dir: Path,
    yes: bool,
    no_report: bool,
) -> dict[str, Any]:
    """Plan the sweep, check its size and the folder, run it, write and report."""
    from ..bench.estimate import estimate
    from ..bench.output import write_outputs
    from ..bench.runner import preflight, run_benchmark
    from ..data.sizes import building
    from ..explore.output import write_explore
    from ..explore.run import explore_table, plan_explore
    from ..explore.size import assumptions, run_estimate
    from .planned import check_estimate, print_skipped, stored_runs
    from .progress import progress_bar

    reg = registry(ctx)
    stored = stored_runs(out_dir)
    reduce = "shrink it (fewer levels or samples, --quick, fewer repeats or classifiers)"

    def check_design(points: int, size: Estimate) -> None:
        """Before the design is built: its points costed from the sweep file alone."""
        what = f"sweep of {points:,} design points"
        check_estimate(size.after(stored), out_dir, yes, what, reduce, verb="run")

    explore_plan = plan_explore(sweep, protocol, overrides, reg, where=where, check=check_design)
    plan = explore_plan.plan
    report = plan.config.report and not no_report
    benchmark = estimate(plan, stored_runs=stored)
    size = run_estimate(plan, benchmark, report)
    check_estimate(size, out_dir, yes, "sweep", reduce, verb="run")
    preflight(plan, out_dir)
    for row in explore_plan.skipped.itertuples():
        err_console.print(f"skipped point {row.point}: {row.reason}", highlight=False)
    print_skipped(plan, shown=set(explore_plan.skipped["point"]))
    console.print(
        f"{len(explore_plan.points)} points ({len(explore_plan.skipped)} skipped) + reference "
        f"and base on {len(plan.recordings)} recordings: {size.line()} -> {out_dir}",
        highlight=False,
        soft_wrap=True,
    )
    console.print(f"  ({assumptions(plan, benchmark, report)})", highlight=False, soft_wrap=True)
    smaller = (
        "use fewer points, repeats or classifiers, shorter or fewer recordings, or fewer --jobs"
    )
    with building(f"running the sweep ({size.line()})", smaller), progress_bar() as progress:
        result = run_benchmark(plan, out_dir, progress, warn)
        results = write_outputs(result, out_dir)
        tables = write_explore(explore_plan, explore_table(explore_plan, results), out_dir)
    if report:
        from ..report import write_report

        write_report(out_dir, registry=reg)
    console.print(f"{len(results)} runs; exploration in {out_dir}", highlight=False)
    return tables
