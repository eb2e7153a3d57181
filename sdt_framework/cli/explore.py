"""``sdt explore``: which sensor specification is enough — a sweep over chain parameters."""

from __future__ import annotations

import datetime as dt
import shlex
import sys
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import typer

from .common import console, err_console, registry
from .explore_tables import print_tables

if TYPE_CHECKING:
    from ..bench import Estimate, Plan
    from ..specs import SensorSpec


def _example() -> str:
    return resources.files("sdt_framework.explore").joinpath("example_sweep.toml").read_text()


STRATEGIES = ("auto", "adaptive", "exhaustive")


def explore(
    ctx: typer.Context,
    sweep_file: Path | None = typer.Argument(
        None, help="Sweep TOML file (a sweep table, optional benchmark table)."
    ),
    data: str | None = typer.Option(None, "--data", help="NLN-EMP root folder or manifest."),
    quick: bool = typer.Option(False, "--quick", help="The benchmark's quick preset."),
    jobs: int | None = typer.Option(
        None, "--jobs", help="Processes (default: all cores; this one alone under 5 s of work)."
    ),
    backend: str | None = typer.Option(None, "--backend", help="local (default) or dask."),
    scheduler: str | None = typer.Option(None, "--scheduler", help="Dask scheduler address."),
    out: Path | None = typer.Option(
        None, "--out", help="Output folder (default results/explore-<timestamp>); reuse to resume."
    ),
    yes: bool = typer.Option(False, "--yes", help="Run even if the estimate exceeds an hour."),
    example: bool = typer.Option(False, "--example", help="Print a commented starter sweep."),
    no_report: bool = typer.Option(False, "--no-report", help="Skip report.md/report.html."),
    strategy: str = typer.Option(
        "auto",
        "--strategy",
        help="adaptive: a cheap screen of every point, then the full protocol only where the "
        "minimum specification is decided (bisection along each axis); exhaustive: the full "
        "protocol on every point; auto (default): adaptive where it applies (a grid of "
        "ordered axes through the base), else exhaustive.",
    ),
) -> None:
    """Sweep sensor parameters around a base sensor and find the minimum specification.

    Before it starts it prints the estimated time of both strategies.
    Exhaustive: every design point runs the full `sdt benchmark` protocol; the
    folder gets explore.parquet, points.csv, skipped_points.csv,
    main_effects.csv, sensitivity.csv, min_spec.csv, pareto.csv and an
    Exploration report section. Adaptive: screen/ (every point, lr and knn, one
    repetition: the sensitivity ranking), rounds/<k> (the full protocol on the
    levels around each threshold), full/ (the last round), and min_spec.csv,
    sensitivity.csv and refinement.csv at the top; every table names the
    fidelity it rests on.

    Example:

      sdt explore --example > my_sweep.toml

      sdt explore examples/sweeps/rate_noise.toml --quick --out results/rate-noise

      sdt explore examples/sweeps/rate_noise.toml --strategy exhaustive --quick
    """
    if example:
        sys.stdout.write(_example())  # verbatim: no wrapping, no markup
        return
    if sweep_file is None:
        raise typer.BadParameter("give a sweep file, or --example to print one", param_hint="SWEEP")
    from ..bench import watch_interrupts
    from ..explore import load_sweep
    from ..inputs import require_regular_file
    from ..signals import building

    if strategy not in STRATEGIES:
        from ..errors import SDTError

        raise SDTError(f"--strategy {strategy}: choose one of {', '.join(STRATEGIES)}")
    require_regular_file(sweep_file, "sweep file")
    with building(f"reading the sweep file {sweep_file}", "shorten its ties and levels"):
        sweep, protocol = load_sweep(sweep_file)
    for note in sweep.target.life_notes():
        err_console.print(f"note: {sweep_file}: {note}", highlight=False, soft_wrap=True)
    given = {"data": data, "jobs": jobs, "backend": backend, "scheduler": scheduler}
    overrides: dict[str, Any] = {k: v for k, v in given.items() if v is not None}
    if quick:
        overrides["quick"] = True
    out_dir = out or Path("results") / dt.datetime.now().strftime("explore-%Y%m%d-%H%M%S")
    resume = shlex.join(["sdt", "explore", str(sweep_file), "--out", str(out_dir)])
    if strategy != "auto":
        resume += f" --strategy {strategy}"
    with watch_interrupts(terminate=True) as watch:
        try:
            choices = (yes, no_report, strategy)
            tables = _run(ctx, sweep, protocol, overrides, str(sweep_file), out_dir, choices)
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
    print_tables(tables, list(sweep.axes), sweep.target)


def _run(
    ctx: typer.Context,
    sweep: Any,
    protocol: dict[str, Any],
    overrides: dict[str, Any],
    where: str,
    out_dir: Path,
    choices: tuple[bool, bool, str],
) -> dict[str, Any]:
    """Plan the sweep, estimate both strategies, check the folder, run the chosen one, report."""
    from ..bench import check_estimate, stored_runs
    from ..explore import exhaustive_estimate, plan_explore, screen_of, sweep_estimate
    from .explore_run import adaptive
    from .explore_run import exhaustive as run_exhaustive
    from .planned import print_skipped

    yes, no_report, strategy = choices
    reg = registry(ctx)
    stored = stored_runs(out_dir)

    def check_design(points: int, probe: Plan, base: SensorSpec) -> None:
        """Before the design is built: its points costed from the sweep file alone.

        An adaptive sweep screens every point, so the screen alone is checked
        here; its refinement is added once the design shows its lines.
        """
        what = f"sweep of {points:,} design points"
        if strategy == "adaptive" or (strategy == "auto" and sweep.design == "grid"):
            size = sweep_estimate(screen_of(probe, reg), base, points)
            check_estimate(size, out_dir, True, what, REDUCE)  # memory and disk
            what = f"{what} (its screen alone)"
        else:
            size = sweep_estimate(probe, base, points).after(stored)
        check_estimate(size, out_dir, yes, what, REDUCE, verb="run")

    explore_plan = plan_explore(sweep, protocol, overrides, reg, where=where, check=check_design)
    plan = explore_plan.plan
    report = plan.config.report and not no_report
    exhaustive = exhaustive_estimate(plan, report, stored_runs=stored)
    chosen, size = _choose(explore_plan, reg, strategy, exhaustive, report)
    check_estimate(size, out_dir, yes, f"{chosen} sweep", REDUCE, verb="run")
    if chosen == "adaptive":
        from ..explore import Adaptive

        Adaptive(explore_plan, reg, out_dir).check_folder()  # before anything is written
    for row in explore_plan.skipped.itertuples():
        err_console.print(f"skipped point {row.point}: {row.reason}", highlight=False)
    print_skipped(plan, shown=set(explore_plan.skipped["point"]))
    console.print(
        f"{len(explore_plan.points)} points ({len(explore_plan.skipped)} skipped) + reference "
        f"and base on {len(plan.recordings)} recordings -> {out_dir}",
        highlight=False,
        soft_wrap=True,
    )
    if chosen == "adaptive":
        return adaptive(explore_plan, reg, out_dir, report)
    return run_exhaustive(reg, explore_plan, out_dir, exhaustive, report)


#: what makes a sweep smaller, in the refusals
REDUCE = "shrink it (fewer levels or samples, --quick, fewer repeats or classifiers)"


def _choose(
    explore_plan: Any, reg: Any, strategy: str, exhaustive: Estimate, report: bool
) -> tuple[str, Estimate]:
    """Print both strategies' estimates and which one runs (and why); return it and its size."""
    from ..errors import SDTError
    from ..explore import estimates, not_adaptive

    reason = not_adaptive(explore_plan)
    if reason is not None and strategy == "adaptive":
        raise SDTError(f"--strategy adaptive: {reason}")
    lines, adaptive = estimates(explore_plan, reg, exhaustive, report)
    for line in lines:
        console.print(line, highlight=False, soft_wrap=True)
    if adaptive is None:
        console.print("strategy: exhaustive", highlight=False)
        return "exhaustive", exhaustive
    chosen = "exhaustive" if strategy == "exhaustive" else "adaptive"
    console.print(f"strategy: {chosen}", highlight=False)
    if chosen == "exhaustive":
        return chosen, exhaustive
    return chosen, adaptive
