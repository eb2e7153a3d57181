"""A benchmark with a feature set in orders: each recording's speed handed down, bad input refused.

The synthetic pump's recordings carry their speed (the generator's 1480 rpm at
100 %), handed down to the features as given; a recording that carries none (here
the same recordings with their speed taken away, as a manifest without speed_rpm
gives them) has it read off its spectrum near the machine's shaft speed and named
an estimate; a machine spec whose speed is wrong leaves nothing to read, and a
sensor whose Nyquist frequency is below an order band at that speed is refused
before any feature is computed.
"""

from __future__ import annotations

import dataclasses

import pandas as pd
import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.features.orders import ORDERS
from typer.testing import CliRunner

from sdt_framework import SDTError
from sdt_framework.bench.feature_context import feature_contexts
from sdt_framework.bench.runner import plan_benchmark
from sdt_framework.cli.main import app
from sdt_framework.data.speed import recording_speed


def test_sdt_benchmark_runs_the_orders_set_at_each_recordings_speed(tmp_path) -> None:
    out = tmp_path / "out"
    result = CliRunner().invoke(
        app,
        ["benchmark", "--quick", "--features", "orders", "--machines", "Motor-2",
         "--channels", "ch1", "--sensors", "wilcoxon-786b10,adxl345", "--classifiers", "lr",
         "--scenarios", "forward", "--repeats", "1", "--jobs", "1", "--no-report",
         "--out", str(out), "--cache-dir", str(tmp_path / "cache")],
        env={"COLUMNS": "200"},
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "read off the spectrum" not in result.output  # every recording carries its speed
    assert (pd.read_csv(out / "results.csv")["status"] == "ok").all()
    frame = pd.read_parquet(out / "features.parquet")
    assert list(frame.columns[-6:]) == ["A_1X", "A_2X", "A_3X", "V_ORD", "D_ORD", "ENV_1X"]
    pump = open_synthetic(None, duration=1.0, machines=["Motor-2"], channels=["ch1"])
    given = {r.recording_id: r.speed_rpm for r in pump.recordings()}
    for recording_id, speed in frame.groupby("recording_id")["speed"].first().items():
        assert speed.startswith(f"{given[recording_id]:.0f} rpm") and "given" in speed


def _speedless(recordings):
    """The recordings as a manifest without speed_rpm hands them: no speed."""
    return [dataclasses.replace(r, speed_rpm=None, speed_percent=None, speed_source="")
            for r in recordings]  # fmt: skip


def test_a_recording_without_speed_has_it_estimated_and_named_so(registry) -> None:
    pump = open_synthetic(None, duration=4.0, machines=["Motor-2"], channels=["ch1"])
    recordings = _speedless(pump.recordings()[:3])
    machine = pump.machines["Motor-2"]
    _, contexts, notes = feature_contexts(ORDERS, recordings, {"Motor-2": machine})
    assert len(notes) == 1 and "read off the spectrum" in notes[0]
    for recording in recordings:  # each one's own estimate, read independently here
        estimate = recording_speed(recording, recording.load(), nominal=1480.0)
        context = contexts[recording.recording_id]
        assert context.speed_from.startswith("estimate: ")
        assert abs(context.speed_hz - estimate.hz) < 1e-9
        assert abs(estimate.hz * 60 - 1480) < 0.03 * 1480


def test_an_order_band_above_a_sensors_nyquist_is_refused_before_any_run(
    small_config, registry
) -> None:
    config = small_config(features="orders", sensors=["wilcoxon-786b10", "lis3dh"])
    with pytest.raises(SDTError) as error:
        plan_benchmark(config, registry)
    message = str(error.value)
    # 40.2 orders x ~24.6 Hz ~ 985 Hz, above the LIS3DH's 1344 Hz / 2
    assert "order band '0.4-40 orders'" in message and "1480 rpm" in message
    assert "above the Nyquist frequency 672 Hz of fs=1344 Hz" in message
    assert "lis3dh[mode=normal,odr=1344,range=2g]'s output rate" in message


def test_a_recording_whose_spectrum_shows_no_speed_is_refused() -> None:
    pump = open_synthetic(None, duration=1.5, machines=["Motor-2"], channels=["ch1"])
    recordings = _speedless(pump.recordings()[:1])
    wrong = pump.machines["Motor-2"].model_copy(update={"shaft_rpm": 900.0})
    with pytest.raises(SDTError) as error:
        feature_contexts(ORDERS, recordings, {"Motor-2": wrong})
    assert "carries no speed and its spectrum shows none near 900 rpm" in str(error.value)


def test_a_recording_with_no_speed_and_no_machine_is_refused() -> None:
    pump = open_synthetic(None, duration=1.5, machines=["Motor-2"], channels=["ch1"])
    recordings = _speedless(pump.recordings()[:1])
    with pytest.raises(SDTError) as error:
        feature_contexts(ORDERS, recordings, {})  # no machine: no nominal speed to read near
    assert "carries no speed and there is no nominal speed to read it near" in str(error.value)


def test_a_set_that_does_not_need_the_speed_reads_nothing(small_config, registry) -> None:
    plan = plan_benchmark(small_config(), registry)  # paper8
    assert plan.contexts == {} and plan.notes == []
