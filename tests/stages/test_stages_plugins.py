"""Stage plugins: the hook, binding and placement, one-line errors, the untouched paper chain."""

from __future__ import annotations

import hashlib
import types

import numpy as np
import pytest
from pydantic import BaseModel, ConfigDict, Field
from scipy.signal import butter, sosfilt
from sdt_plugins.sensors.adxl345 import ADXL345
from sdt_plugins.sensors.adxl357 import ADXL357
from sdt_plugins.sensors.wilcoxon_786b10 import WILCOXON_786B10

from sdt_framework import SDTError, SensorSpec, UnknownNameError, build_registry, hookimpl
from sdt_framework.api import degrade
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.chain import compile_chain
from sdt_framework.chain.shared import SharedPrefix
from sdt_framework.stages import StageSpec

FS = 20000.0


def signal() -> np.ndarray:
    t = np.arange(20000) / FS
    return np.stack(
        [
            0.3 * np.sin(2 * np.pi * 97 * t) + 0.05 * np.sin(2 * np.pi * 2300 * t),
            0.8 * np.cos(2 * np.pi * 31 * t),
        ]
    )


#: (content hash, SHA-256 of degrade(signal(), 20 kHz, sensor, seed=7)) computed with the
#: code of commit 1984d18, before stage plugins existed.
GOLDEN = {
    "adxl345": ("73a86275940a6da8", "d24e8007f30c8092"),
    "adxl357": ("2de84f020836a740", "90098437e9f56947"),
    "wilcoxon-786b10": ("1f9a50dc1f8d4321", "ac4dcb9e800981f8"),
}


@pytest.mark.parametrize("sensor", [ADXL345, ADXL357, WILCOXON_786B10], ids=lambda s: s.name)
def test_paper_chain_is_bit_identical_without_extra_stages(sensor):
    y, _ = degrade(signal(), FS, sensor, seed=7)
    digest = hashlib.sha256(y.tobytes()).hexdigest()[:16]
    assert (sensor.content_hash()[:16], digest) == GOLDEN[sensor.name]


# -- a third-party stage: a first-order DC-blocking high-pass ---------------------------------
class DcBlockParams(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")
    cutoff_hz: float = Field(default=1.0, gt=0, description="-3 dB corner, Hz.")


class DcBlock:
    """y = x - (first-order Butterworth low-pass of x): removes the DC offset."""

    def __init__(self, params: DcBlockParams, context) -> None:
        self.name, self.fs_in, self.fs_out = context.label, context.fs, context.fs
        self.sos = butter(1, params.cutoff_hz, "highpass", fs=context.fs, output="sos")

    def apply(self, x, ctx):
        return sosfilt(self.sos, x, axis=-1)


DC_BLOCK = StageSpec(
    name="dc-block",
    description="DC-blocking high-pass",
    domain="digital",
    where="after",
    anchor="noise",
    params=DcBlockParams,
    factory=DcBlock,
)
dc_plugin = types.ModuleType("dc_block_plugin")
dc_plugin.register_stages = hookimpl(lambda register: register(DC_BLOCK))


def with_stages(sensor: SensorSpec, name: str, stages: list[dict]) -> SensorSpec:
    return SensorSpec.model_validate({**sensor.model_dump(), "name": name, "stages": stages})


def test_third_party_stage_registers_and_runs_inside_a_benchmark(tmp_path):
    sensor = with_stages(
        ADXL345,
        "adxl345-ac",
        [{"name": "offset", "params": {"offset_mg": 300}}, {"name": "dc-block"}],
    )
    registry = build_registry(plugins=[dc_plugin])
    registry.add(sensor)
    assert registry.stage("dc-block").plugin == "dc_block_plugin"
    bound = registry.sensor("adxl345-ac")
    chain = compile_chain(bound, FS)
    assert [s.name for s in chain.stages][-5:] == [
        "offset.0",
        "noise",
        "dc-block.1",
        "digital",
        "quantise",
    ]
    y, _ = degrade(signal(), FS, bound, seed=1)
    # the 300 mg offset is blocked: the mean of the last half second is near zero
    assert abs(y[:, -1600:].mean()) < 0.01
    config = BenchmarkConfig(
        dataset_options={"duration": 1.5},
        machines=["Motor-2"],
        channels=["ch1"],
        sensors=["wilcoxon-786b10", "adxl345", "adxl345-ac"],
        classifiers=["lr"],
        repeats=1,
        jobs=1,
        report=False,
        cache_dir=str(tmp_path / "cache"),
    )
    result = run_benchmark(plan_benchmark(config, registry), tmp_path / "out")
    runs = [r for r in result.runs if r.labels["sensor"] == "adxl345-ac"]
    assert runs and all(r.status == "ok" for r in runs)
    feats = result.features.set_index(["sensor", "recording_id", "acquisition", "window"])
    names = list(result.plan.feature_set.feature_names)
    assert not np.allclose(
        feats.loc["adxl345-ac", names].values, feats.loc["adxl345", names].values
    )


def test_unknown_stage_name_is_one_line_with_the_closest_match():
    registry = build_registry()
    registry.add(with_stages(ADXL345, "bad-stage", [{"name": "ofset"}]))
    with pytest.raises(UnknownNameError) as err:
        registry.sensor("bad-stage")
    message = str(err.value)
    assert "\n" not in message and "unknown stage 'ofset'" in message and "'offset'" in message


def test_bad_stage_parameter_is_one_line_naming_sensor_stage_and_field():
    registry = build_registry()
    registry.add(
        with_stages(
            ADXL345, "bad-param", [{"name": "gauss-markov", "params": {"sigma_ug": -1, "tau_s": 1}}]
        )
    )
    with pytest.raises(SDTError) as err:
        registry.sensor("bad-param")
    message = str(err.value)
    assert "\n" not in message
    assert "'bad-param'" in message and "'gauss-markov'" in message and "sigma_ug" in message


def test_toml_profile_lists_stages(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text(
        """
name = "mine"
sampling_rate_hz = 1000
full_scale_g = 2
adc_bits = 16
noise_density_ug_rthz = 0
mech_cutoff_hz = 5000
analog_cutoff_hz = 400

[[stages]]
name = "scale"
params = { error_pct = 5 }

[[stages]]
name = "offset"
params = { offset_mg = 10 }
"""
    )
    registry = build_registry(sensor_files=[path])
    sensor = registry.sensor("mine")
    x = np.full((1, 2000), 0.5)
    y, _ = degrade(x, 2000.0, sensor.model_copy(update={"requantise": False}), noise=False)
    plain, _ = degrade(x, 2000.0, sensor.model_copy(update={"stages": (), "requantise": False}))
    # offset and scale both run before the noise stage, in the listed order
    np.testing.assert_allclose(y, plain * 1.05 + 0.010, rtol=0, atol=1e-12)


def test_random_stages_follow_the_noise_switch_and_common_random_numbers():
    stages = [{"name": "gauss-markov", "params": {"sigma_ug": 500, "tau_s": 0.05}}]
    a = with_stages(ADXL357, "a", stages).model_copy(update={"noise_density_ug_rthz": 0})
    b = a.model_copy(update={"name": "b"})
    x = signal()
    ya, _ = degrade(x, FS, a, seed=3)
    yb, _ = degrade(x, FS, b, seed=3)
    quiet, _ = degrade(x, FS, a, seed=3, noise=False)
    nominal, _ = degrade(x, FS, a.model_copy(update={"stages": ()}), seed=3)
    assert np.array_equal(ya, yb)  # the name of the sensor never enters the draws
    assert np.array_equal(quiet, nominal) and not np.array_equal(ya, quiet)


def test_shared_prefix_with_an_analog_stage_matches_degrade():
    nl = with_stages(ADXL345, "nl", [{"name": "nonlinearity", "params": {"third_pct_fs": 2}}])
    registry = build_registry()
    registry.add(nl)
    nl = registry.sensor("nl")
    shared = SharedPrefix(signal(), FS)
    for sensor in (ADXL345, nl, ADXL345):
        expected, _ = degrade(signal(), FS, sensor, seed=2)
        got, _ = shared.degrade(sensor, seed=2)
        assert np.array_equal(got, expected)
    assert shared.prefix_runs == 1  # the nonlinearity runs after the shared low-passes


def test_per_axis_stage_parameters():
    sensor = with_stages(
        ADXL345,
        "axes",
        [{"name": "offset", "params": {"offset_mg": 10}, "per_axis": {"z": {"offset_mg": 40}}}],
    ).model_copy(update={"noise_density_ug_rthz": 0, "requantise": False})
    x = np.zeros((1, 20000))
    yx, _ = degrade(x, FS, sensor.for_axis("x"))
    yz, _ = degrade(x, FS, sensor.for_axis("z"))
    np.testing.assert_allclose(
        [yx[0, -1], yz[0, -1]], [0.010, 0.040], rtol=1e-4
    )  # the digital filter's DC gain


def test_stage_spec_rejects_a_place_outside_its_domain():
    with pytest.raises(ValueError, match="analog stage cannot run after noise"):
        StageSpec(
            name="x",
            domain="analog",
            where="after",
            anchor="noise",
            params=DcBlockParams,
            factory=DcBlock,
        )


def test_a_stage_hash_follows_its_parameter_schema_and_each_content_dict_is_its_own():
    """The parameter schema in a stage's content is pydantic's own for that class. It is
    built once per class for speed, so a caller editing one ``content_dict`` must not change
    the next, and a class with another field must give another hash."""
    first = DC_BLOCK.content_dict()
    assert first["params"] == DcBlockParams.model_json_schema()
    first["params"]["properties"].clear()
    assert DC_BLOCK.content_dict()["params"] == DcBlockParams.model_json_schema()

    class WiderParams(DcBlockParams):
        order: int = Field(default=1, ge=1, description="Filter order.")

    wider = DC_BLOCK.model_copy(update={"params": WiderParams})
    assert wider.content_dict()["params"] == WiderParams.model_json_schema()
    assert wider.content_hash() != DC_BLOCK.content_hash()
