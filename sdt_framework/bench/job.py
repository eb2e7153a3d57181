"""The main job as one call: plan, size check, claim, run and write one results folder.

:func:`run_benchmark_folder` is what ``sdt benchmark`` does, for every caller
(the command, a notebook, ``sdt explore``, the calibration scripts, the tests):

1. plan the configuration (:func:`~.plan.plan_benchmark`) and hand the plan to
   ``check`` (``sdt benchmark`` checks its severity zone tables there: the
   severity package sits above this one);
2. check the plan's size (:mod:`.size_check`): nothing is written for a plan
   that cannot fit, nor for one estimated above an hour unless ``yes``;
3. claim and lock the folder (:func:`~.runner.preflight`: a new or empty
   folder, or a resume of the same configuration), then tell ``started``;
4. run (:func:`~.runner.run_benchmark`: what the folder holds is resumed;
   Ctrl-C raises ``KeyboardInterrupt`` with every finished run stored) and write
   every output file atomically (:func:`~.output.write_outputs`);
5. hand the written folder to ``finish`` while it is still locked (the
   command writes its report there: the report sits above this package), then
   release the lock, unless the caller held it before.

:func:`run_plan_folder` is the same from step 2 on, for a caller that has its
plan already (``sdt explore`` plans its design points with the registry).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from ..registry import Registry
from ..signals.sizes import building
from . import runner
from .config import BenchmarkConfig
from .estimate import Estimate
from .folder_lock import holds_results_folder, unlock_results_folder
from .output import write_outputs
from .plan import Plan, plan_benchmark
from .runner import BenchmarkResult, Progress, Warn
from .size_check import check_size
from .table4 import Table4, build_table4

__all__ = ["BENCHMARK", "FolderRun", "Wording", "run_benchmark_folder", "run_plan_folder"]


@dataclass(frozen=True)
class Wording:
    """How the refusals and the out-of-memory line name the work and what makes it smaller."""

    what: str = "benchmark"
    #: what makes the plan smaller (a refusal before the run)
    smaller: str = "lower --repeats or select fewer sensors, classifiers or machines"
    #: what takes less memory at once (memory running out during the run)
    less_at_once: str = "process less data at once (shorter or fewer recordings, fewer --jobs)"


BENCHMARK = Wording()


@dataclass(frozen=True)
class FolderRun:
    """A written results folder: where, what was planned, the estimate and what it found."""

    out_dir: Path
    plan: Plan
    #: the estimate checked before the run (runs already stored not counted)
    size: Estimate
    #: runs, features, counters (computed, resumed, cached) and timings
    result: BenchmarkResult
    #: the tidy results table, as written to results.parquet: one row per run
    results: pd.DataFrame

    @property
    def failed(self) -> int:
        """Runs that failed (status "error"); they are not stored, so a resume retries them."""
        return int((self.results["status"] == "error").sum())

    def table4(self) -> Table4:
        """Table 4 of the results (table4.md's content), sensors in the plan's order."""
        return build_table4(self.results, [s.name for s in self.plan.sensors])


def run_plan_folder(
    plan: Plan,
    out_dir: str | os.PathLike[str],
    *,
    yes: bool = False,
    progress: Progress | None = None,
    warn: Warn | None = None,
    started: Callable[[Plan, Estimate], None] | None = None,
    finish: Callable[[FolderRun], None] | None = None,
    wording: Wording = BENCHMARK,
) -> FolderRun:
    """Check ``plan``'s size, claim ``out_dir``, run, write every output; the written folder.

    Parameters
    ----------
    yes
        Start a plan estimated above an hour (one that cannot fit is refused anyway).
    progress, warn
        ``progress(stage, done, total)`` and ``warn(line)`` as
        :func:`~.runner.run_benchmark` takes them (by default no progress, and
        each warning a ``RuntimeWarning``).
    started
        Called with the plan and its estimate once the folder is claimed, before any work.
    finish
        Called with the written folder while it is still locked (a report, say).
    wording
        How the refusals name the work (``sdt explore`` says "sweep").

    Raises
    ------
    SDTError
        Before anything is written: a plan that cannot fit or is too long
        without ``yes``, a folder that must not be written or that another
        process holds.
    KeyboardInterrupt
        On Ctrl-C; every finished run stays stored, and the same call resumes.
    """
    out = Path(out_dir)
    held = holds_results_folder(out)
    try:
        size = check_size(plan, out, yes, wording.what, wording.smaller)
        runner.preflight(plan, out)
        if started is not None:
            started(plan, size)
        with building(f"running the {wording.what} ({size.line()})", wording.less_at_once):
            workers = 1 if size.alone else None  # too short for worker processes to help
            result = runner.run_benchmark(plan, out, progress, warn, workers=workers)
            results = write_outputs(result, out)
        run = FolderRun(out, plan, size, result, results)
        if finish is not None:
            finish(run)
        return run
    finally:
        if not held:
            unlock_results_folder(out)


def run_benchmark_folder(
    config: BenchmarkConfig,
    registry: Registry,
    out_dir: str | os.PathLike[str],
    *,
    yes: bool = False,
    progress: Progress | None = None,
    warn: Warn | None = None,
    check: Callable[[Plan], None] | None = None,
    started: Callable[[Plan, Estimate], None] | None = None,
    finish: Callable[[FolderRun], None] | None = None,
) -> FolderRun:
    """Plan ``config`` with ``registry``, hand the plan to ``check``, then :func:`run_plan_folder`.

    Example::

        from sdt_framework import build_registry
        from sdt_framework.bench import load_config, run_benchmark_folder

        run = run_benchmark_folder(load_config(None, {"quick": True}), build_registry(), "out")
        print(run.results.groupby("sensor")["macro_f1"].mean())
    """
    plan = plan_benchmark(config, registry)
    if check is not None:
        check(plan)
    return run_plan_folder(
        plan, out_dir, yes=yes, progress=progress, warn=warn, started=started, finish=finish
    )
