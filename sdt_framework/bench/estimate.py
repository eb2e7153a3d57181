"""How long a planned benchmark will take, before it starts: a rough, documented estimate.

seconds = (chain_seconds + classify_seconds) / processes, with

- chain_seconds = input samples x sensor-repetitions x CHAIN_SECONDS_PER_SAMPLE, where
  a sensor that injects no noise counts once (it is shared by all repetitions);
- classify_seconds = sum over runs of FIT_SECONDS_PER_1K_WINDOWS[classifier] x
  training windows / 1000 (unknown classifiers: the slowest known rate).

The constants were measured on the reference machine (2 vCPUs, shared with
other work at the time, so they err on the long side) from one
``sdt benchmark --quick`` run: the median ``fit_seconds`` per classifier over
its 300 training windows, and the featurisation time in summary.json (16.5 s
on 2 processes for 20.8 M input samples x 5 sensor-repetitions; the synthetic
generator's own time included). On a quiet machine the estimate errs long by up to
about four times (the full default protocol: 860 s estimated, 218 s measured):
enough to tell minutes from hours, which is what it is for. Runs already stored in the output folder
are not subtracted: the estimate is for a run from scratch.
"""

from __future__ import annotations

from .plan import Plan

__all__ = ["CHAIN_SECONDS_PER_SAMPLE", "FIT_SECONDS_PER_1K_WINDOWS", "estimate_seconds"]

#: SDT chain + feature extraction, per input sample and sensor-repetition
CHAIN_SECONDS_PER_SAMPLE = 3.2e-7
#: classifier fit + predict per 1000 training windows (paper hyperparameters)
FIT_SECONDS_PER_1K_WINDOWS = {"lr": 0.22, "knn": 0.05, "rf": 2.8, "xgb": 2.2, "mlp": 2.8}


def estimate_seconds(plan: Plan) -> tuple[float, int]:
    """(estimated wall seconds, number of classifier runs) of ``plan`` from scratch."""
    config = plan.config
    repeats = config.repeats
    draws = sum(
        repeats if s.inject_noise and s.noise_density_ug_rthz > 0 else 1 for s in plan.sensors
    )
    samples = sum(r.n_acquisitions * r.samples_per_acquisition for r in plan.recordings)
    chain = samples * draws * CHAIN_SECONDS_PER_SAMPLE

    windows: dict[tuple[str, str], int] = {}  # (machine, run) -> windows of one sensor
    for rec in plan.recordings:
        seconds = rec.samples_per_acquisition / rec.sampling_rate_hz
        per = rec.n_acquisitions * max(0, int((seconds - config.settle_s) / config.window_s))
        windows[(rec.machine, rec.run)] = windows.get((rec.machine, rec.run), 0) + per
    slowest = max(FIT_SECONDS_PER_1K_WINDOWS.values())
    fit_rate = sum(FIT_SECONDS_PER_1K_WINDOWS.get(c.name, slowest) for c in plan.classifiers)
    classify, runs = 0.0, 0
    groups = plan.allocation.groupby(["machine", "scenario"], sort=True)
    for (machine, scenario), part in groups:
        if (machine, scenario) in plan.skipped:
            continue
        train = part[part["side"] == "train"]
        n_train = sum(windows.get((machine, run), 0) for run in train["run"])
        classify += fit_rate * n_train / 1000 * len(plan.sensors) * repeats
        runs += len(plan.classifiers) * len(plan.sensors) * repeats
    return (chain + classify) / max(1, config.n_jobs()), runs
