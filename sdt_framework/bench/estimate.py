"""How big a planned benchmark is and roughly how long it will take, before any work.

The estimate is deliberately simple (and printed as an estimate):

- features: ``FEATURE_SECONDS_PER_MSAMPLE`` per million input samples run
  through one chain draw. A recording costs its samples (acquisitions x
  samples per acquisition) once per sensor and repetition, or once per sensor
  for a chain without noise (computed once, shared by all repetitions);
- classifiers: ``a + b * n_train`` seconds per run, with ``(a, b)`` per
  classifier in :data:`RUN_SECONDS` and ``n_train`` the run's training
  windows; a classifier not in the table (a plugin) is costed as the slowest
  built-in;
- the sum is divided by the processes that compute at once: the processes
  started (:func:`~.pool.pool_size`: ``--jobs``, at most two per core and one
  per task), but no more than the cores; runs already stored in the results
  folder are not counted. With the default ``--jobs`` (all cores) a local
  benchmark whose sum is under :data:`ALONE_BELOW_SECONDS` runs in the calling
  process alone (``Estimate.alone``): starting worker processes would take
  longer than they save;
- transfer pairs and node samples (``sample = "node"``) add runs: a pair's
  training set is its chains' windows, a node's its x channel's;
- ``--units`` multiplies the runs, and the draws of a sensor with tolerances
  (one without shares unit 0's);
- memory: the process itself, plus per feature block (one recording x sensor
  x unit x repetition), per feature row (window) and per run, all held until
  the results are written, plus each process's chain run on the largest
  recording, plus each worker process started on this machine (``PROCESS_BYTES``
  each: 268 and 271 MB peak for the two loky workers of the run below with
  ``--jobs 2``), plus the samples the dataset keeps between reads in each process
  that reads (``Dataset.kept_bytes``, the dataset's samples at most: the synthetic
  pump keeps up to 64 MB of runs, which raised the peak of the ``--units 2`` run
  below from 270 to 314 MB); disk: one run file per run and ``features.parquet``.

The memory constants are peak resident sizes measured with ``/usr/bin/time -v``
on ``sdt benchmark --quick --machines Motor-2 --classifiers lr --jobs 1`` with
``--units`` 2, 8 and 16 (289, 379 and 495 MB: 33 kB per block) and with 40 s
acquisitions (444 and 586 MB for units 2 and 8: 630 B per row once the blocks
are counted), and with one 200 s and one 40 s recording (1235 and 421 MB: 254 B
per input sample while it runs through a chain); the disk constants from the
folders those runs wrote. On those runs the estimate is 5 to 14 % above the
measured peak (446 MB for 391 at 20 repeats, 552 for 495 at 16 units, 1298 for
1235 with the 200 s recording).

The time constants are single-thread CPU times measured on the reference machine
(2 vCPU AMD EPYC, Python 3.11, scikit-learn 1.9, xgboost 3.2) by
``python benchmarks/bench_estimate.py``, which also prints how far the
estimate of the ``--quick`` benchmark is from its measured time. Feature-cache
hits are not subtracted, so the estimate errs on the long side.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..data.recording import Recording
from ..features import samples_for
from ..specs import SensorSpec
from ..stages import has_tolerances
from .plan import Plan
from .pool import cores, pool_size

__all__ = [
    "ALONE_BELOW_SECONDS",
    "ASSUMES",
    "CONFIRM_ABOVE_SECONDS",
    "FEATURE_SECONDS_PER_MSAMPLE",
    "RUN_SECONDS",
    "Estimate",
    "estimate",
    "estimate_like",
]

#: What every printed estimate rests on, said beside it (a loaded machine took 10x longer).
ASSUMES = (
    "single-thread times measured on an idle 2-core reference machine; a loaded or slower "
    "machine takes longer, a warm feature cache less"
)
#: A benchmark estimated to take longer than this needs ``--yes`` to start.
CONFIRM_ABOVE_SECONDS = 3600.0
#: Single-thread seconds under which the default ``--jobs`` starts no worker process. Two loky
#: workers cost about 5 CPU-s and 2-4 s of wall time to start (each imports scipy, pandas and
#: scikit-learn). Wall seconds of ``sdt benchmark --quick ... --no-report`` with ``--jobs 1``
#: vs ``--jobs 2`` on the reference machine, by single-thread estimate: ``--machines Motor-2
#: --classifiers lr`` 2 s: 3.9 vs 5.8; ``--classifiers lr`` 6 s: 7.9 vs 9.0; ``--classifiers
#: lr,rf,knn`` 14 s: 13.5 vs 11.8; all five classifiers 30 s: 24.8 vs 17.3. Under 5 s one
#: process wins on 2 cores (the break-even is near 9 s) and loses about 2 s at most on many.
ALONE_BELOW_SECONDS = 5.0
#: Chain + features, seconds per million input samples per draw (one thread).
FEATURE_SECONDS_PER_MSAMPLE = 0.047
#: classifier -> (seconds per run, seconds per training window), one thread.
RUN_SECONDS: dict[str, tuple[float, float]] = {
    "lr": (0.02, 0.00003),
    "knn": (0.02, 0.0),
    "rf": (0.17, 0.00015),
    "xgb": (0.03, 0.0006),
    "mlp": (0.07, 0.0005),
}
#: resident size of the process before any data (interpreter, numpy, pandas, sklearn)
PROCESS_BYTES = 250_000_000
#: peak bytes per feature block (recording x sensor x unit x repetition), per
#: feature row (one window) and per finished run kept until the results are written
BLOCK_BYTES = 34_000
ROW_BYTES = 700
RUN_BYTES = 20_000
#: peak bytes per input sample of the recording a process is running through a chain
CHAIN_BYTES_PER_SAMPLE = 260
#: bytes on disk per run file and per row of features.parquet (measured 4.7 kB, 36 B)
RUN_FILE_BYTES = 6_000
ROW_FILE_BYTES = 40


@dataclass(frozen=True)
class Estimate:
    """Size and estimated duration of a benchmark."""

    runs: int
    runs_to_do: int
    feature_draws: int
    seconds: float
    workers: int
    memory_bytes: int = PROCESS_BYTES
    disk_bytes: int = 0
    #: the part of ``memory_bytes`` that does not grow with the work (processes, chains)
    fixed_bytes: int = PROCESS_BYTES
    #: too short for worker processes to help: the default ``--jobs`` runs it in this process
    alone: bool = False

    def scaled(self, count: int) -> Estimate:
        """The estimate of ``count`` times this work (the processes counted once)."""
        return Estimate(
            self.runs * count,
            self.runs_to_do * count,
            self.feature_draws * count,
            self.seconds * count,
            self.workers,
            self.fixed_bytes + (self.memory_bytes - self.fixed_bytes) * count,
            self.disk_bytes * count,
            self.fixed_bytes,
            self.alone,
        )

    def after(self, stored_runs: int) -> Estimate:
        """This estimate once ``stored_runs`` of its runs are done (a resume skips them)."""
        to_do = max(0, self.runs - stored_runs)
        share = to_do / self.runs if self.runs else 1.0
        return replace(self, runs_to_do=to_do, seconds=self.seconds * share)

    def line(self) -> str:
        """One line for the terminal: size and estimated time."""
        todo = "" if self.runs_to_do == self.runs else f" ({self.runs_to_do} still to do)"
        why = "; starting worker processes would take longer, --jobs N starts N"
        return (
            f"{self.runs} runs{todo} and {self.feature_draws} featurised signals, "
            f"estimated {format_duration(self.seconds)} on {self.workers} process"
            f"{'es' if self.workers > 1 else ''}{why if self.alone else ''}"
        )


def format_duration(seconds: float) -> str:
    """``42 s``, ``12 min``, ``3.4 h`` or ``2.1 days``."""
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    if seconds < 2 * 86400:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.1f} days"


def _windows(recording: Recording, sensor: SensorSpec, window_s: float, settle_s: float) -> int:
    rate = float(sensor.at_rate(recording.sampling_rate_hz).sampling_rate_hz)
    ratio = rate / recording.sampling_rate_hz
    samples = int((recording.samples_per_acquisition - 1) * ratio) + 1
    usable = samples - samples_for(settle_s, rate)
    return recording.n_acquisitions * max(0, usable // samples_for(window_s, rate))


def _draws(sensor: SensorSpec, repeats: int, units: int | None) -> int:
    noisy = sensor.inject_noise and sensor.noise_density_ug_rthz != 0
    drawn = units if units is not None and has_tolerances(sensor) else 1
    return (repeats if noisy else 1) * drawn


def estimate(plan: Plan, stored_runs: int = 0, *, alone_if_short: bool = True) -> Estimate:
    """Size, estimated wall time, peak memory and disk of ``plan``; ``stored_runs`` are done.

    Pure arithmetic on the plan's sizes: nothing is allocated per unit, run or
    window, so a plan of 10^12 runs is estimated as fast as a small one. With
    ``alone_if_short`` (what a run does), a local plan under
    :data:`ALONE_BELOW_SECONDS` with the default ``--jobs`` is costed in one process.
    """
    config = plan.config
    units = config.units or 1
    feature_seconds = 0.0
    draws = 0
    rows = 0
    for recording in plan.recordings:
        samples = recording.total_samples
        for sensor in plan.sensors:
            n = _draws(sensor, config.repeats, config.units)
            draws += n
            feature_seconds += n * samples / 1e6 * FEATURE_SECONDS_PER_MSAMPLE
            rows += _windows(recording, sensor, config.window_s, config.settle_s)
    blocks = len(plan.recordings) * len(plan.sensors) * config.repeats * units
    rows *= config.repeats * units
    slowest = max(RUN_SECONDS.values(), key=lambda ab: ab[0] + 1000 * ab[1])
    by_run = {(r.machine, r.run): [] for r in plan.recordings}
    for recording in plan.recordings:
        by_run[(recording.machine, recording.run)].append(recording)
    run_seconds = 0.0
    runs = 0
    specs = {sensor.name: sensor for sensor in plan.sensors}
    for (machine, scenario), part in plan.allocation.groupby(["machine", "scenario"], sort=True):
        if (machine, scenario) in plan.skipped:
            continue
        train = part[part["side"] == "train"]["run"]
        members = [rec for run in train for rec in by_run.get((machine, run), [])]
        for pair, _ in plan.run_groups():  # ordinary, transfer; each on channels and nodes
            for channels in [None, *(n.channels[:1] for n in plan.sample_nodes)]:
                n_train = sum(
                    _windows(r, specs[name], config.window_s, config.settle_s)
                    for name in pair.train
                    for r in members
                    if channels is None or r.channel in channels
                )
                for clf in plan.classifiers:
                    a, b = RUN_SECONDS.get(clf.name, slowest)
                    run_seconds += config.repeats * units * (a + b * n_train)
                    runs += config.repeats * units
    to_do = max(0, runs - stored_runs)
    if runs:
        run_seconds *= to_do / runs
    workers = pool_size(config.n_jobs(), max(len(plan.recordings), to_do))
    alone = (
        alone_if_short
        and workers > 1
        and config.jobs == -1
        and config.backend == "local"
        and feature_seconds + run_seconds < ALONE_BELOW_SECONDS
    )
    workers = 1 if alone else workers
    largest = max((r.total_samples for r in plan.recordings), default=0)
    remote = config.backend == "dask" and config.scheduler  # the workers are elsewhere
    here = 0 if remote or workers == 1 else workers  # worker processes on this machine
    # samples the dataset keeps between reads, in each process that reads (a small
    # dataset's whole samples at most)
    samples = sum(r.total_samples for r in plan.recordings)
    kept = plan.dataset.kept_at_most(samples) * (1 if workers == 1 else here)
    fixed = PROCESS_BYTES * (1 + here) + workers * CHAIN_BYTES_PER_SAMPLE * largest + kept
    memory = fixed + BLOCK_BYTES * blocks + ROW_BYTES * rows + RUN_BYTES * runs
    disk = RUN_FILE_BYTES * to_do + ROW_FILE_BYTES * rows
    seconds = (feature_seconds + run_seconds) / min(workers, cores())
    return Estimate(runs, to_do, draws, seconds, workers, memory, disk, fixed, alone)


def estimate_like(plan: Plan, sensor: SensorSpec, count: int) -> Estimate:
    """``plan`` run on ``count`` sensors each costing what ``sensor`` costs.

    For a sweep whose sensors do not exist yet: its size is known from the
    number of design points before any point is built.
    """
    return estimate(replace(plan, sensors=[sensor]), alone_if_short=False).scaled(count)
