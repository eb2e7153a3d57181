"""Cross-axis sensitivity: the model, its inputs, and triaxial nodes in a benchmark."""

from __future__ import annotations

import numpy as np
import pytest
from sdt_plugins.sensors.adxl345 import ADXL345

from sdt_framework import SDTError, build_registry
from sdt_framework.api import degrade, extract
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.featurise import noise_seed
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.chain import ChainInputError, compile_chain
from sdt_framework.chain.shared import SharedPrefix
from sdt_framework.stages import StageSpec
from sdt_framework.validation import noise_check

FS = 20000.0
PLAIN = ADXL345.model_copy(update={"name": "plain", "stages": ()})


def crossed(pct: float, name: str = "crossed"):
    """The ADXL345 profile with a cross-axis stage of ``pct`` %."""
    stages = [{"name": "cross-axis", "params": {"pct": pct}}]
    return ADXL345.model_validate({**ADXL345.model_dump(), "name": name, "stages": stages})


def bound(sensor):
    """``sensor`` with its stages bound, as a caller holding a registry hands it to the chain
    (``compile_chain``, ``SharedPrefix`` and ``noise_check`` take bound profiles only)."""
    return build_registry().bind(sensor)


def tones(freqs, seconds=1.0, amp=0.5):
    t = np.arange(int(FS * seconds)) / FS
    return [amp * np.sin(2 * np.pi * f * t)[None, :].repeat(2, axis=0) for f in freqs]


def test_runs_first_on_the_raw_inputs():
    chain = compile_chain(bound(crossed(1.0)), FS)
    assert chain.stages[0].name == "cross-axis.0"


def test_equals_the_plain_chain_on_the_coupled_input():
    """Linear model: chain(a_x + c (a_y + a_z)) computed by hand, with noise and bits."""
    ax, ay, az = tones((120.0, 310.0, 455.0))
    c = 0.04
    want, _ = degrade(ax + c * (ay + az), FS, PLAIN, seed=3)
    got, _ = degrade(ax, FS, crossed(100 * c), seed=3, other_axes={"y": ay, "z": az})
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)


def test_crosstalk_tone_has_the_configured_share():
    """A 310 Hz tone on y alone appears on x at pct / 100 of its amplitude (FFT amplitude)."""
    ax, ay, az = tones((120.0, 310.0, 455.0))
    spec = crossed(2.5)
    sensor = spec.model_copy(update={"inject_noise": False, "requantise": False})
    y, fs_out = degrade(0 * ax, FS, sensor, other_axes={"y": ay, "z": 0 * az}, noise=False)
    tail = y[0, int(fs_out * 0.5) :]  # after the filters settle
    spectrum = np.abs(np.fft.rfft(tail * np.hanning(len(tail)))) / (np.hanning(len(tail)).sum() / 2)
    freqs = np.fft.rfftfreq(len(tail), 1 / fs_out)
    peak = spectrum[np.argmin(np.abs(freqs - 310.0))]
    # the chain passes 310 Hz with gain ~1 (the 1600 Hz Butterworth low-passes), so the
    # crosstalk amplitude is 0.025 x 0.5 = 12.5 mg
    assert peak == pytest.approx(0.025 * 0.5, rel=0.03)


def test_without_the_other_axes_it_is_one_clear_error():
    (ax,) = tones((120.0,))
    with pytest.raises(SDTError, match="needs the same acquisitions on the node's other two axes"):
        degrade(ax, FS, crossed(1.0))
    with pytest.raises(ChainInputError, match="must map the node's other two axes"):
        degrade(ax, FS, crossed(1.0), other_axes={"y": ax})
    with pytest.raises(ChainInputError, match="axis 'z' holds shape"):
        degrade(ax, FS, crossed(1.0), other_axes={"y": ax, "z": ax[:1]})


def test_shared_prefix_with_a_node_matches_degrade():
    ax, ay, az = tones((120.0, 310.0, 455.0))
    shared = SharedPrefix(ax, FS, other_axes={"y": ay, "z": az})
    for sensor in (PLAIN, bound(crossed(3.0))):
        want, _ = degrade(ax, FS, sensor, seed=5, other_axes={"y": ay, "z": az})
        got, _ = shared.degrade(sensor, seed=5)
        np.testing.assert_array_equal(got, want)


def test_a_node_stage_must_run_first():
    spec = build_registry().stage("cross-axis")
    assert spec.node
    with pytest.raises(ValueError, match="must be an analog stage placed before mechanical"):
        StageSpec.model_validate({**dict(spec), "name": "x3", "anchor": "analog"})


def _config(tmp_path, **kw):
    base = dict(
        dataset_options={"duration": 1.5},
        machines=["Motor-2"],
        channels=["ch1"],
        sensors=["adxl345", "crossed"],
        classifiers=["lr"],
        repeats=1,
        jobs=1,
        report=False,
        cache_dir=str(tmp_path / "cache"),
        axes={"ch1": "x", "ch2": "y", "ch3": "z"},
    )
    return BenchmarkConfig(**{**base, **kw})


def _registry(pct: float):
    registry = build_registry()
    registry.add(crossed(pct))
    return registry


def test_benchmark_reads_the_node_partners_of_each_scored_channel(tmp_path):
    """ch1 is scored; ch2 and ch3 (not scored) are its node's y and z axes."""
    registry = _registry(5.0)
    plan = plan_benchmark(_config(tmp_path), registry)
    assert {r.channel for r in plan.recordings} == {"ch1"}
    assert plan.nodes and all(
        (y.channel, z.channel) == ("ch2", "ch3") for y, z in plan.nodes.values()
    )
    result = run_benchmark(plan, tmp_path / "out")
    assert all(r.status == "ok" for r in result.runs)
    feats = result.features.set_index(["sensor", "recording_id", "acquisition", "window"])
    names = list(plan.feature_set.feature_names)
    # independent check: the plain ADXL345 on ch1 + 5 % (ch2 + ch3), by hand
    rec = plan.recordings[0]
    y_rec, z_rec = plan.nodes[rec.recording_id]
    coupled = rec.load() + 0.05 * (y_rec.load() + z_rec.load())
    chain_seed = noise_seed(ADXL345, 0, 0, rec.recording_id)
    out, fs_out = degrade(coupled, FS, PLAIN, seed=chain_seed)
    table = extract(out, fs_out, plan.feature_set, window_s=0.64, settle_s=0.1)
    got = feats.loc["crossed"].loc[rec.recording_id, names].to_numpy()
    np.testing.assert_allclose(got, table.values, rtol=1e-6)
    assert not np.allclose(got, feats.loc["adxl345"].loc[rec.recording_id, names].to_numpy())


def test_zero_cross_axis_gives_the_plain_sensors_features(tmp_path):
    registry = _registry(0.0)
    result = run_benchmark(plan_benchmark(_config(tmp_path), registry), tmp_path / "out")
    feats = result.features.set_index(["sensor", "recording_id", "acquisition", "window"])
    names = list(result.plan.feature_set.feature_names)
    np.testing.assert_array_equal(
        feats.loc["crossed", names].to_numpy(), feats.loc["adxl345", names].to_numpy()
    )


@pytest.mark.parametrize(
    ("axes", "message"),
    [
        ({}, "channel 'ch1' .* has no axis"),
        ({"ch1": "x", "ch2": "y", "ch3": "y"}, "has channels \\['ch2', 'ch3'\\] on axis 'y'"),
        ({"ch1": "x", "ch2": "y"}, "has no channel on axis 'z'"),
    ],
)
def test_incomplete_nodes_are_refused_before_any_work(tmp_path, axes, message):
    with pytest.raises(SDTError, match=message):
        plan_benchmark(_config(tmp_path, axes=axes), _registry(1.0))


def test_a_tolerance_alone_adds_the_stage_and_needs_nodes(tmp_path):
    """A unit drawn from a 'cross-axis.pct' tolerance gets the stage, so nodes are needed."""
    sensor = PLAIN.model_validate(
        {
            **PLAIN.model_dump(),
            "name": "crossed",
            "tolerances": {"cross-axis.pct": {"distribution": "uniform", "spread": 1.0}},
        }
    )
    registry = build_registry()
    registry.add(sensor)
    with pytest.raises(SDTError, match="has no axis"):
        plan_benchmark(_config(tmp_path, axes={}, units=2), registry)
    plan = plan_benchmark(_config(tmp_path, units=2), registry)
    assert plan.nodes


def test_zero_motion_check_reads_zeros_on_the_other_axes():
    """validate-noise: on a node at rest the coupling adds nothing, bit for bit."""
    plain = noise_check(PLAIN, seed=4).to_dict()
    with_stage = noise_check(bound(crossed(5.0)), seed=4).to_dict()
    assert with_stage["sdt"] == plain["sdt"]
