"""Regression guard: the synthetic pump against the real archive's per-channel statistics.

The targets are computed here from ``tests/data/nln_emp_stats/column0_stats.csv``
(a copy of the shared statistics, with their sources in its README), not read
from the generator: RMS, peak, Pearson kurtosis and crest factor of the first
12 s column of every real record, glitch records (kurtosis > 20) left out, and
the same quantities measured on the first 12 s column of every synthetic run of
the default dataset (seed 0), synthetic glitches left out by the same rule. The
shares within bound must meet the issue's thresholds and not fall below the
shares recorded in ``synth_stats_guard.json`` (seed 0 is bit-identical from run
to run, so a drop means the generator changed).
"""

from __future__ import annotations

import csv
import json
import tomllib
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.datasets.synthetic_pump import model as model
from sdt_plugins.datasets.synthetic_pump.generate import generate_run

from .synth_common import measure

HERE = Path(__file__).parent
STATS = HERE / "nln_emp_stats"
GUARD = json.loads((HERE / "synth_stats_guard.json").read_text())
SPEED = {"Motor-4": "70", "Motor-2": "100"}
NAMES = ("rms_g", "peak_g", "kurtosis_pearson", "crest_factor")
CHANNELS = ("ch1", "ch2", "ch3", "ch4", "ch5")


def real_rows() -> dict[tuple[str, str, str], dict[str, float]]:
    with (STATS / "column0_stats.csv").open(newline="") as handle:
        return {
            (r["machine"], r["folder"], r["channel"]): {k: float(r[k]) for k in NAMES}
            for r in csv.DictReader(handle)
            if SPEED.get(r["machine"]) == r["speed_pct"]
        }


@pytest.fixture(scope="module")
def cells() -> tuple[dict, dict]:
    """(real, synthetic): (machine, run, channel) -> statistics, glitches left out."""
    real = {k: v for k, v in real_rows().items() if v["kurtosis_pearson"] <= 20}
    synth = {}
    for machine, folder in sorted({(m, f) for m, f, _ in real}):
        condition, level = folder.rsplit(" ", 1)
        levels = dict(model.MACHINES[machine].conditions).get(condition)
        if levels is None or not level.isdigit() or int(level) > levels:
            continue  # a real folder the default does not generate (e.g. "healthy noise")
        run = generate_run(
            machine, condition, int(level), channels=CHANNELS, acquisitions=1,
            duration_s=12.0, seed=0,
        )  # fmt: skip
        for ch, x in run.items():
            values = measure(x[0])
            if values["kurtosis_pearson"] <= 20:
                synth[(machine, folder, ch)] = values
    return real, synth


def test_the_default_generates_every_real_run_and_no_other() -> None:
    real = {(m, f) for m, f, _ in real_rows()}
    generated = {
        (name, f"{c} {k}")
        for name, machine in model.MACHINES.items()
        for c, levels in machine.conditions
        for k in model.levels_of(machine, c, levels)
    }
    assert generated <= real  # no invented run: Motor-4 "cavitation suction 2" is absent
    assert ("Motor-4", "cavitation suction 2") not in generated


def test_every_mark_is_its_real_row_or_the_mean_of_its_class_where_the_row_is_a_glitch() -> None:
    rows = real_rows()
    marks = tomllib.loads(
        (Path(model.__file__).with_name("marks.toml")).read_text(encoding="utf-8")
    )
    for machine, runs in marks.items():
        for run, channels in runs.items():
            condition = run.rsplit(" ", 1)[0]
            for ch, (rms, kurt, crest) in channels.items():
                row = rows[(machine, run, ch)]
                if row["kurtosis_pearson"] > 20:
                    others = [
                        v for (m, f, c), v in rows.items()
                        if m == machine and c == ch and f.rsplit(" ", 1)[0] == condition
                        and f != run and v["kurtosis_pearson"] <= 20
                    ]  # fmt: skip
                    row = {k: float(np.mean([o[k] for o in others])) for k in NAMES}
                want = (row["rms_g"], row["kurtosis_pearson"], row["crest_factor"])
                assert (rms, kurt, crest) == pytest.approx(want, rel=1e-3), (machine, run, ch)


@pytest.mark.parametrize(
    ("name", "factor", "need"),
    [("rms_g", 1.5, 0.90), ("kurtosis_pearson", 1.5, 0.90), ("crest_factor", 1.5, 0.85),
     ("peak_g", 2.0, 0.80)],
)  # fmt: skip
def test_cells_within_bound_of_the_real_records(cells, name: str, factor: float, need: float):
    real, synth = cells
    common = set(real) & set(synth)
    assert len(common) >= 0.95 * 244  # 244 real cells after the glitch rule; a few synthetic
    ratios = np.array([synth[c][name] / real[c][name] for c in common])
    share = float(np.mean((ratios >= 1 / factor) & (ratios <= factor)))
    assert share >= need
    assert share >= GUARD["seed0"][name] - 0.02


def test_each_fault_family_moves_each_channel_as_the_real_rig(cells) -> None:
    """Mean RMS of a family's runs over the mean of the healthy runs, per machine and
    channel: within 25 % of the real ratio for at least 85 % of the pairs."""
    real, synth = cells

    def ratios(table: dict) -> dict[tuple[str, str, str], float]:
        groups: dict[tuple[str, str, str], list[float]] = {}
        for (m, f, c), v in table.items():
            groups.setdefault((m, f.rsplit(" ", 1)[0], c), []).append(v["rms_g"])
        return {
            k: np.mean(v) / np.mean(groups[(k[0], "healthy", k[2])])
            for k, v in groups.items()
            if k[1] != "healthy"
        }

    common = set(real) & set(synth)
    got = ratios({c: synth[c] for c in common})
    want = ratios({c: real[c] for c in common})
    close = [abs(got[k] / want[k] - 1) <= 0.25 for k in want]
    assert len(close) == 12 * 5
    assert np.mean(close) >= 0.85
    assert np.mean(close) >= GUARD["seed0"]["ratio_to_healthy"] - 0.02


@pytest.fixture(scope="module")
def healthy_columns() -> dict[tuple[str, str], np.ndarray]:
    """(statistic, channel) -> the value of every 12 s column of Motor-4 healthy 1 and 2.

    Twelve acquisitions of five columns per run, glitches on: the real figures are a
    StandardScaler's over the 120 real columns, glitched ones kept (the statistics' README).
    """
    columns: dict[tuple[str, str], list[float]] = {}
    for level in (1, 2):
        run = generate_run(
            "Motor-4", "healthy", level, channels=CHANNELS, acquisitions=60, duration_s=12.0,
            seed=0,
        )  # fmt: skip
        for ch, x in run.items():
            for column in x:
                for name, value in measure(column).items():
                    columns.setdefault((name, ch), []).append(value)
    return {key: np.array(values) for key, values in columns.items()}


@pytest.mark.parametrize(
    ("name", "ch", "moment"),
    [(n, c, k) for n in ("rms_g", "crest_factor") for c in CHANNELS for k in ("mean", "sd")],
)
def test_healthy_motor4_columns_spread_as_the_real_ones(
    healthy_columns, name: str, ch: str, moment: str
) -> None:
    """Mean and SD over the 120 columns of healthy 1 and 2 within 25 % of
    healthy_spread_motor4.csv, for RMS and crest factor on every channel."""
    with (STATS / "healthy_spread_motor4.csv").open(newline="") as handle:
        spread = {(r["statistic"], r["channel"]): (float(r["mean"]), float(r["sd"]))
                  for r in csv.DictReader(handle)}  # fmt: skip
    values = healthy_columns[(name, ch)]
    assert values.size == 120
    real_mean, real_sd = spread[(name, ch)]
    got, want = (values.mean(), real_mean) if moment == "mean" else (values.std(), real_sd)
    assert got == pytest.approx(want, rel=0.25)


def test_healthy_runs_glitch_on_ch2_and_ch3_only() -> None:
    """The real healthy Motor-4 columns carry spikes on ch2 and ch3 and none on ch1, ch4
    and ch5 (their kurtosis SD 0.44, 0.29, 0.39 in healthy_spread_motor4.csv); a fault
    run's glitches reach those channels too (column0_stats.csv: unbalance motor 4 ch4/ch5)."""
    hit: dict[str, set[str]] = {}
    for condition, level in (("healthy", 1), ("unbalance motor", 4)):
        options = dict(channels=CHANNELS, acquisitions=60, duration_s=0.5, seed=0)
        with_glitches = generate_run("Motor-4", condition, level, **options)
        without = generate_run("Motor-4", condition, level, glitches=False, **options)
        hit[condition] = {ch for ch in CHANNELS if np.any(with_glitches[ch] != without[ch])}
    assert hit["healthy"] and hit["healthy"] <= {"ch2", "ch3"}
    assert hit["unbalance motor"] - {"ch2", "ch3"}
