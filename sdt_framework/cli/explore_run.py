"""Running ``sdt explore``'s two strategies once planned and estimated (see ``cli/explore.py``)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from .common import console, warn

if TYPE_CHECKING:
    from ..bench import Estimate

__all__ = ["adaptive", "exhaustive"]


def adaptive(explore_plan: Any, reg: Any, out_dir: Path, report: bool) -> dict[str, Any]:
    """Screen every point, refine along the lines through the base, report the last round."""
    from ..explore import Adaptive
    from ..signals import building
    from .progress import progress_bar

    smaller = "use fewer points, repeats or classifiers, shorter or fewer recordings"
    with building("running the adaptive sweep", smaller), progress_bar() as progress:
        tables = Adaptive(explore_plan, reg, out_dir, progress, warn).run()
    if report:
        from ..report import write_report

        write_report(out_dir / "full", registry=reg)
    rounds = tables["refinement"]
    n_rounds = int(rounds["round"].max())
    console.print(
        f"screen: {len(explore_plan.points)} points in {out_dir / 'screen'}; full protocol: "
        f"{rounds['point'].nunique()} points in {n_rounds} round{'s' if n_rounds > 1 else ''} in "
        f"{out_dir / 'full'}; answer in {out_dir}",
        highlight=False,
        soft_wrap=True,
    )
    return tables


#: how the exhaustive sweep's refusals and out-of-memory line name it
_SWEEP_WORDS = (
    "sweep",
    "use fewer points, repeats or classifiers",
    "use fewer points, repeats or classifiers, shorter or fewer recordings, or fewer --jobs",
)


def exhaustive(
    reg: Any, explore_plan: Any, out_dir: Path, size: Estimate, report: bool
) -> dict[str, Any]:
    """Every point through the full protocol in one benchmark folder."""
    from ..bench import Wording, run_plan_folder
    from ..explore import assumptions, explore_table, write_explore
    from ..signals import building
    from .progress import Bars

    tables: dict[str, Any] = {}
    bars = Bars()

    def started(plan: Any, benchmark: Estimate) -> None:
        console.print(f"  {size.line()}", highlight=False, soft_wrap=True)
        console.print(
            f"  ({assumptions(plan, benchmark, report)})", highlight=False, soft_wrap=True
        )

    def finish(run: Any) -> None:
        with building(f"running the sweep ({size.line()})", _SWEEP_WORDS[2]):
            table = explore_table(explore_plan, run.results, run.result.features)
            tables.update(write_explore(explore_plan, table, out_dir))
        bars.close()
        if report:
            from ..report import write_report

            write_report(out_dir, registry=reg)

    try:  # the sweep's size, the report's included, was checked and agreed to before
        run = run_plan_folder(
            explore_plan.plan, out_dir, yes=True, progress=bars, warn=warn, started=started,
            finish=finish, wording=Wording(*_SWEEP_WORDS),
        )  # fmt: skip
    finally:
        bars.close()
    console.print(f"{len(run.results)} runs; exploration in {out_dir}", highlight=False)
    return tables
