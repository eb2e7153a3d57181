"""The synthetic pump at other speeds (issue 43): the physics that moves with the shaft.

Every expected frequency is computed here from the rig's file as a user reads it
(``MachineSpec.speed_at`` for the shaft speed, the 6309's geometry for its BPFO,
six vanes), never from the generator's own numbers; the speeds are the option a
user gives (``speeds`` in ``dataset_options``, ``sdt dataset synth --speeds``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import signal
from sdt_plugins.datasets.nln_emp import open_nln_emp
from sdt_plugins.datasets.pump_rig import rig_machines
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.datasets.synthetic_pump.generate import generate_run

from sdt_framework.bench.config import load_config
from sdt_framework.bench.plan import plan_benchmark
from sdt_framework.errors import SDTError
from sdt_framework.registry import build_registry

from .synth_common import amplitude_near

FS = 20000.0
MOTOR2 = rig_machines()["Motor-2"]


def shaft_hz(percent: float) -> float:
    """Motor-2's running speed at ``percent``, as the rig's file gives it to any reader."""
    point = MOTOR2.speed_at(percent)
    assert point is not None
    return point.shaft_rpm / 60.0


def run(condition: str, level: int, channels, percent: float, seconds: float = 4.0, seed=0):
    return generate_run(
        "Motor-2", condition, level, channels=tuple(channels), acquisitions=1,
        duration_s=seconds, seed=seed, speed=percent,
    )  # fmt: skip


@pytest.mark.parametrize("percent", [50, 75, 100])
def test_the_1x_and_vane_pass_lines_sit_at_the_orders_of_the_recordings_speed(percent) -> None:
    f1 = shaft_hz(percent)
    x = run("healthy", 1, ["ch1", "ch4"], percent)
    f = np.fft.rfftfreq(x["ch1"].shape[1], 1 / FS)
    spec = {ch: np.abs(np.fft.rfft(v[0] * np.hanning(v.shape[1]))) for ch, v in x.items()}
    low = (f > 5) & (f < 1.5 * f1)  # the largest low-frequency line: 1x
    assert f[low][np.argmax(spec["ch1"][low])] == pytest.approx(f1, rel=0.01)
    pump = (f > 3 * f1) & (f < 9 * f1)  # on the pump: six vanes pass per revolution
    assert f[pump][np.argmax(spec["ch4"][pump])] == pytest.approx(6 * f1, rel=0.01)


@pytest.mark.parametrize("percent", [50, 75])
def test_the_motor_bearings_defect_line_moves_with_the_speed(percent) -> None:
    # 6309: 8 balls of 17.46 mm on a 72.5 mm pitch circle; at half speed half as many
    # impacts per second, so twice the record for the same envelope resolution
    bpfo = 8 / 2 * (1 - 17.46 / 72.5) * shaft_hz(percent)
    x = run("bearing bpfo", 3, ["ch2"], percent, seconds=8.0)["ch2"][0]
    band = signal.sosfiltfilt(signal.butter(4, [2000, 8000], "bandpass", fs=FS, output="sos"), x)
    env = np.abs(signal.hilbert(band))
    f = np.fft.rfftfreq(env.size, 1 / FS)
    spec = np.abs(np.fft.rfft(env - env.mean()))
    sel = (f >= 10) & (f <= 400)
    line = spec[(f > bpfo * 0.98) & (f < bpfo * 1.02)].max()
    assert line > 10 * np.median(spec[sel])


@pytest.mark.usefixtures("no_scatter")
@pytest.mark.parametrize("percent", [50, 75])
def test_the_lines_grow_as_the_square_of_the_speed(percent) -> None:
    """An unbalance force m e w^2 and a pressure pulsation ~ head ~ n^2 (the affinity laws):
    at the same installation the 1x and vane-pass lines scale by (n / n_100)^2."""
    want = (shaft_hz(percent) / shaft_hz(100)) ** 2
    slow, full = run("healthy", 1, ["ch1", "ch2"], percent), run("healthy", 1, ["ch1", "ch2"], 100)
    for ch in ("ch1", "ch2"):
        for order in (1, 6):
            got = amplitude_near(slow[ch][0], order * shaft_hz(percent)) / amplitude_near(
                full[ch][0], order * shaft_hz(100)
            )
            assert got == pytest.approx(want, rel=0.03), (ch, order)


def test_a_run_at_another_speed_is_another_recording() -> None:
    """Its noise is drawn anew: the 50 % column is not a rescaled copy of the 100 % one."""
    slow, full = run("healthy", 1, ["ch5"], 50, 1.0), run("healthy", 1, ["ch5"], 100, 1.0)
    assert abs(np.corrcoef(slow["ch5"][0], full["ch5"][0])[0, 1]) < 0.1


def test_each_recording_carries_the_speed_the_rigs_file_gives() -> None:
    ds = open_synthetic(speeds=[50, 75, 100])
    recs = ds.recordings()
    assert {r.machine for r in recs} == {"Motor-2"}  # Motor-4 runs at 70 % only
    assert {r.speed for r in recs} == {"50", "75", "100"}
    for r in recs:
        assert r.speed_percent == float(r.speed)
        assert r.speed_rpm == MOTOR2.speed_at(r.speed_percent).shaft_rpm
        assert r.speed_source and r.recording_id.startswith(f"Motor-2/{r.speed}/")
    # the 50 % archive lacks "bearing bpfi 3" (statistics' README): not at 50 or 75 %. A run
    # per speed, named as the NLN-EMP reader names a run per speed folder
    runs = {r.run for r in recs}
    assert "100/bearing bpfi 3" in runs and "50/healthy 1" in runs
    assert "50/bearing bpfi 3" not in runs and "75/bearing bpfi 3" not in runs
    assert len(runs) == len(ds.runs()) == 15 + 14 + 14
    assert all(r.run.split("/")[0] == r.speed for r in recs)
    # one spec holds one operating point: none for a machine at several, and a note says so
    assert ds.machines == {} and any("Motor-2" in note for note in ds.notes)


def test_all_speeds_is_each_machine_at_every_speed_it_runs_at() -> None:
    recs = open_synthetic(speeds="all", channels="ch1").recordings()
    assert {(r.machine, r.speed) for r in recs} == {
        ("Motor-4", "70"), ("Motor-2", "50"), ("Motor-2", "75"), ("Motor-2", "100"),
    }  # fmt: skip
    # Motor-4 at its one speed keeps the directory name as its run
    assert {r.run for r in recs if r.machine == "Motor-4"} >= {"healthy 1", "coupling 3"}


def test_the_default_is_the_papers_protocol_and_says_its_speed() -> None:
    default = open_synthetic()
    same = open_synthetic(speeds=[70, 100])
    assert [r.metadata() for r in same.recordings()] == [r.metadata() for r in default.recordings()]
    rig = rig_machines()
    for r in default.recordings():
        assert r.speed_rpm == rig[r.machine].shaft_rpm and r.speed_percent == float(r.speed)
    assert set(default.machines) == {"Motor-4", "Motor-2"} and default.notes == []


@pytest.mark.parametrize(
    ("options", "words"),
    [
        ({"speeds": [60]}, "no machine is generated at 60 % speed"),
        ({"speeds": "fast"}, "speeds must be percents of rated speed"),
        ({"speeds": [50, math.nan]}, "speeds must be percents of rated speed"),
        ({"speeds": [True]}, "speeds must be percents of rated speed"),
        ({"speeds": []}, "speeds must be percents of rated speed"),
        ({"speeds": [50], "machines": ["Motor-4", "Motor-2"]}, "Motor-4 runs at none of"),
    ],
)
def test_a_speed_the_generator_does_not_run_is_one_line(options, words) -> None:
    with pytest.raises(SDTError, match=words) as caught:
        open_synthetic(**options)
    assert "\n" not in str(caught.value)


def test_the_same_option_selects_the_speeds_in_a_benchmark_config(tmp_path) -> None:
    config_file = tmp_path / "speeds.toml"
    config_file.write_text(
        "[benchmark]\ndataset_options = { speeds = [50, 75, 100], duration = 1.5 }\n"
        'classifiers = ["lr"]\nchannels = ["ch1"]\nrepeats = 1\n'
    )
    plan = plan_benchmark(load_config(config_file, {}), build_registry())
    assert {r.speed for r in plan.recordings} == {"50", "75", "100"}
    assert {r.speed_rpm for r in plan.recordings} == {
        MOTOR2.speed_at(p).shaft_rpm for p in (50, 75, 100)
    }


@pytest.fixture
def sdt(sdt_in_process):
    """``sdt(*args, cache=...)``: the command in this process (``dataset`` starts no worker)."""
    return lambda *args, cache: sdt_in_process(*args, env={"SDT_CACHE_DIR": str(cache)})


def test_synth_speeds_writes_each_speed_in_its_folder_of_the_archive_layout(sdt, tmp_path) -> None:
    out = tmp_path / "speeds"
    args = ("dataset", "synth", "--out", str(out), "--duration", "0.5", "--seed", "1")
    done = sdt(*args, "--speeds", "50,75,100", cache=tmp_path / "cache")
    assert done.returncode == 0, done.stderr
    motor = out / "Vibration" / "Motor-2"
    assert sorted(p.name for p in motor.iterdir()) == ["100", "50", "75"]
    assert not (out / "Vibration" / "Motor-4").exists()
    folder = motor / "50" / "healthy 1"
    assert sorted(p.name for p in folder.iterdir()) == [
        f"Vibration_Motor-2_50_time-healthy 1-ch{k}.csv" for k in range(1, 6)
    ]
    assert not (motor / "50" / "bearing bpfi 3").exists()
    # the files hold the generated signal, each speed its own, to 6 significant digits
    back = open_nln_emp(out, speeds=["50", "75", "100"], channels="ch4", cache=False)
    ref = {
        r.recording_id: r
        for r in open_synthetic(seed=1, duration=0.5, speeds=[50, 75, 100]).recordings()
    }
    found = {r.recording_id: r for r in back.recordings()}
    assert len(found) == 15 + 14 + 14
    for rid in ("Motor-2/50/bearing pump 2/ch4", "Motor-2/75/bearing pump 2/ch4"):
        np.testing.assert_allclose(found[rid].load(), ref[rid].load(), rtol=1e-5, atol=1e-9)


def test_synth_speeds_a_speed_not_generated_is_one_line_and_nothing_written(sdt, tmp_path) -> None:
    out = tmp_path / "none"
    done = sdt("dataset", "synth", "--out", str(out), "--speeds", "60", cache=tmp_path / "c")
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [
        "error: synthetic-pump: no machine is generated at 60 % speed; the speeds are: "
        "Motor-4 70 %; Motor-2 50, 75, 100 %"
    ]
    assert not (out / "Vibration").exists()
