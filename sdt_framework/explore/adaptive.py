"""The adaptive strategy: a cheap screen of every point, then the full protocol where it decides.

1. **Screen** (``<out>/screen``): every design point through the protocol with
   the cheap, deterministic classifiers :data:`SCREEN_CLASSIFIERS` on one
   repetition. It gives the sensitivity ranking (fidelity "screen") and, per
   parameter, where the minimum specification probably lies.
2. **Refinement** (``<out>/rounds/<k>``): the full protocol on the lines
   through the base, round by round (:mod:`~sdt_framework.explore.refine`):
   first the levels the screen puts around each threshold, then bisection
   until every cell's last failing and first passing levels are both run at
   full fidelity. Each round is an ordinary results folder holding the
   reference, the base and every point refined so far; the runs of earlier
   rounds are copied in, so nothing is computed twice.
3. ``<out>/full`` links to the last round; ``<out>/min_spec.csv`` (fidelity
   "full"), ``<out>/sensitivity.csv`` (fidelity "screen") and
   ``<out>/refinement.csv`` (which point was run at full fidelity in which
   round, and why) sit at the top.

Running the same command again resumes: the screen and each round resume
their folders, and the rounds repeat the same choices from the same results.
"""

from __future__ import annotations

import math
import os
import re
import shutil
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from ..bench.estimate import Estimate, format_duration
from ..bench.job import Wording, run_plan_folder
from ..bench.plan import Plan, plan_benchmark
from ..bench.results import write_frame
from ..errors import SDTError
from ..registry import Registry
from .effects import with_best
from .objectives import verdicts
from .output import write_explore, write_sweep_file
from .pareto import demands
from .refine import Line, lines, next_groups, screen_groups
from .run import ExplorePlan, explore_table
from .size import adaptive_estimate

__all__ = [
    "ADAPTIVE_ENTRIES",
    "SCREEN_CLASSIFIERS",
    "Adaptive",
    "budget",
    "estimates",
    "not_adaptive",
    "point_table",
    "screen_of",
    "screen_plan",
]

#: the screen: deterministic and the cheapest of the built-in classifiers (bench/estimate.py)
SCREEN_CLASSIFIERS = ("lr", "knn")
#: what an adaptive sweep's folder holds (anything else there is not ours)
ADAPTIVE_ENTRIES = frozenset(
    {"screen", "rounds", "full", "min_spec.csv", "sensitivity.csv", "refinement.csv", "sweep.toml"}
)
#: left by a write cut short (io.atomic_path, the link's temporary name)
_TEMPORARY = re.compile(r"^\..+\.tmp$")
_SMALLER = "use fewer points, repeats or classifiers, shorter or fewer recordings"


def not_adaptive(explore: ExplorePlan) -> str | None:
    """Why adaptive refinement cannot answer this sweep (what to do instead), or None."""
    sweep = explore.sweep
    if sweep.design != "grid":
        return (
            f"design {sweep.design!r} estimates sensitivity indices from every point; adaptive "
            f"refinement needs design = 'grid' (or use --strategy exhaustive)"
        )
    demand = demands(sweep, explore.stage_axes)
    unordered = [f for f in sweep.axes if demand[f] == "neither"]
    if unordered:
        return (
            f"axis {unordered[0]} has no demanding direction, so there is no order to bisect; "
            f"give its demand ('higher' or 'lower') in [sweep.cost.{unordered[0]}], or use "
            f"--strategy exhaustive"
        )
    base = explore.base_values()
    if len(sweep.axes) > 1:
        for field in sweep.axes:
            if not np.isclose(explore.design[field].to_numpy(float), base[field]).any():
                return (
                    f"the base's {field} ({base[field]:g}) is not one of its levels, so no line "
                    f"runs through the base; add it to the levels, or use --strategy exhaustive"
                )
    return None


def point_table(explore: ExplorePlan) -> pd.DataFrame:
    """The evaluated points: ``point`` and each swept value."""
    fields = list(explore.sweep.axes)
    rows = [{"point": p.spec.name, **{f: p.values[f] for f in fields}} for p in explore.points]
    return pd.DataFrame(rows, columns=["point", *fields])


def budget(explore: ExplorePlan) -> tuple[int, int]:
    """At most how many points the refinement runs at full fidelity, in at most how many rounds.

    Only points on the lines through the base are ever refined; a round
    halves every cell's bracket, after the first round the screen chose.
    """
    demand = demands(explore.sweep, explore.stage_axes)
    by_field = lines(point_table(explore), list(explore.sweep.axes), explore.base_values(), demand)
    names = {p for line in by_field.values() for group in line.groups for p in group}
    widest = max((len(line.groups) for line in by_field.values()), default=0)
    return len(names), 1 + math.ceil(math.log2(widest + 1))


def estimates(
    explore: ExplorePlan, registry: Registry, exhaustive: Estimate, report: bool
) -> tuple[list[str], Estimate | None]:
    """Both strategies' estimates as printed lines, and the adaptive one (None: not applicable).

    ``exhaustive`` is the full protocol on every point (with what the run
    adds: :func:`~sdt_framework.explore.size.run_estimate`). The adaptive one
    is its screen plus its refinement at most (:func:`budget` points and rounds).
    """
    n = len(explore.points)
    lines = [f"exhaustive: full protocol on {n} points: {exhaustive.line()}"]
    reason = not_adaptive(explore)
    if reason is not None:
        return [*lines, f"adaptive: does not apply ({reason})"], None
    points, rounds = budget(explore)
    screen = screen_plan(explore, registry).plan
    first, refine = adaptive_estimate(screen, explore.plan, explore.base, points, rounds, report)
    total = first.seconds + refine.seconds
    most = max(first.workers, refine.workers)  # a screen too short for workers runs alone
    workers = f"{most} process{'es' if most > 1 else ''}"
    lines.append(
        f"adaptive: screen of {n} points ({' and '.join(SCREEN_CLASSIFIERS)}, 1 repetition) "
        f"{format_duration(first.seconds)} + full protocol on at most {points} points in at "
        f"most {rounds} rounds {format_duration(refine.seconds)}: at most "
        f"{format_duration(total)} on {workers}"
    )
    memory = max(first.memory_bytes, refine.memory_bytes)
    return lines, replace(refine, seconds=total, memory_bytes=memory)


def screen_plan(explore: ExplorePlan, registry: Registry) -> ExplorePlan:
    """The same points under the screen protocol: cheap classifiers, one repetition, no report."""
    return replace(explore, plan=screen_of(explore.plan, registry))


def screen_of(plan: Plan, registry: Registry) -> Plan:
    """``plan``'s data, sensors and options with the screen's classifiers and one repetition."""
    config = plan.config.model_copy(
        update={"classifiers": list(SCREEN_CLASSIFIERS), "repeats": 1, "report": False}
    )
    return plan_benchmark(config, registry)


@dataclass
class Adaptive:
    """One adaptive sweep into ``out``: ``run`` it; the tables come back by name."""

    explore: ExplorePlan
    registry: Registry
    out: Path
    progress: Callable | None = None
    warn: Callable[[str], None] | None = None

    def check_folder(self) -> None:
        """``out`` is new, empty or an adaptive sweep's folder (to resume); else one line."""
        if not self.out.is_dir():
            if self.out.exists():
                raise SDTError(f"--out {self.out} is a file; name a folder")
            return
        foreign = sorted(
            p.name
            for p in self.out.iterdir()
            if p.name not in ADAPTIVE_ENTRIES and not _TEMPORARY.match(p.name)
        )
        if foreign:
            raise SDTError(
                f"--out {self.out} holds {', '.join(foreign[:3])}, not an adaptive sweep's "
                f"folder; choose a new folder (--strategy exhaustive resumes an exhaustive one)"
            )

    def run(self) -> dict[str, pd.DataFrame]:
        """Screen, refine, write the answer's files; return the tables by name."""
        self.check_folder()
        screen = screen_plan(self.explore, self.registry)
        screen_table = explore_table(screen, *self._benchmark(screen.plan, self.out / "screen"))
        screened = write_explore(
            screen, screen_table, self.out / "screen", fidelity="screen", sweep_file=False
        )
        fields = list(self.explore.sweep.axes)
        demand = demands(self.explore.sweep, self.explore.stage_axes)
        by_field = lines(screened["points"], fields, self.explore.base_values(), demand)
        target = self.explore.sweep.target
        judged = verdicts(with_best(screen_table), fields, target)
        todo = {f: screen_groups(line, judged) for f, line in by_field.items()}
        why = "screen puts a threshold here"
        done: set[str] = set()
        log: list[dict[str, object]] = []
        folder: Path | None = None
        full, table, round_no = self.explore, None, 0
        while new := _names(by_field, todo) - done:
            round_no += 1
            log += _log(by_field, todo, round_no, why, done)
            done |= new
            previous, folder = folder, self.out / "rounds" / str(round_no)
            full = self._subset(done)
            table = explore_table(full, *self._benchmark(full.plan, folder, previous))
            judged = verdicts(with_best(table), fields, target)
            todo = {f: next_groups(line, judged) for f, line in by_field.items()}
            why = "bisection between the last failing and the first passing level"
        if folder is None or table is None:
            raise SDTError(
                "no line through the base has a valid point to refine; use --strategy exhaustive"
            )
        tables = write_explore(
            full, table, folder, "full", screened["sensitivity"], sweep_file=False
        )
        write_sweep_file(self.explore, self.out)
        _link(self.out / "full", folder)
        tables["refinement"] = pd.DataFrame(
            log, columns=["round", "parameter", "level", "point", "why"]
        )
        for name in ("min_spec", "sensitivity", "refinement"):
            write_frame(tables[name], self.out / f"{name}.csv")
        tables["screen_min_spec"] = screened["min_spec"]
        return tables

    def _subset(self, names: set[str]) -> ExplorePlan:
        """The full protocol on the reference, the base and the points ``names``."""
        points = [p for p in self.explore.points if p.spec.name in names]
        keep = [s for s in self.explore.plan.config.sensors if s in names or s in self._fixed()]
        config = self.explore.plan.config.model_copy(update={"sensors": keep})
        return replace(self.explore, points=points, plan=plan_benchmark(config, self.registry))

    def _fixed(self) -> set[str]:
        return {self.explore.plan.reference, self.explore.base.name}

    def _benchmark(
        self, plan: Plan, folder: Path, previous: Path | None = None
    ) -> tuple[pd.DataFrame, pd.DataFrame]:
        """Run ``plan`` in ``folder`` (resuming it), the runs of ``previous`` copied in first.

        Returns the tidy results and the windows' features (for zone agreement).
        The whole sweep's size was checked and agreed to before its first folder.
        """

        def copy_runs(plan: Plan, size: Estimate) -> None:  # once the folder is claimed
            for run in sorted((previous / "runs").glob("*.json")) if previous else ():
                target = folder / "runs" / run.name
                if not target.exists():
                    shutil.copy2(run, target)

        run = run_plan_folder(
            plan, folder, yes=True, progress=self.progress, warn=self.warn, started=copy_runs,
            wording=Wording("adaptive sweep", _SMALLER, _SMALLER),
        )  # fmt: skip
        return run.results, run.result.features


def _names(by_field: dict[str, Line], todo: dict[str, set[int]]) -> set[str]:
    return {p for f, groups in todo.items() for g in groups for p in by_field[f].groups[g]}


def _log(
    by_field: dict[str, Line], todo: dict[str, set[int]], round_no: int, why: str, done: set[str]
) -> list[dict[str, object]]:
    """One row per point a round adds: its round, parameter, level and why it was chosen."""
    rows = []
    for field, groups in todo.items():
        line = by_field[field]
        for g in sorted(groups):
            for point in line.groups[g]:
                if point not in done:
                    rows.append(
                        {
                            "round": round_no,
                            "parameter": field,
                            "level": line.levels[g],
                            "point": point,
                            "why": why,
                        }
                    )
    return rows


def _link(link: Path, folder: Path) -> None:
    """``link`` -> ``folder`` (relative), replacing an older link atomically."""
    tmp = link.with_name(f".{link.name}.tmp")
    if tmp.is_symlink() or tmp.exists():
        tmp.unlink()
    os.symlink(os.path.relpath(folder, link.parent), tmp)
    os.replace(tmp, link)
