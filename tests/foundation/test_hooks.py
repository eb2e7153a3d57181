"""Each hook, exercised by a minimal in-process plugin, plus meta-tests on the hookspecs."""

from __future__ import annotations

import inspect
import types
from pathlib import Path

import numpy as np

from sdt_framework import (
    ClassifierSpec,
    DatasetSpec,
    FeatureSetSpec,
    SensorSpec,
    build_registry,
    hookimpl,
    hookspecs,
)


def plugin_with(hook_name: str, spec: object) -> types.ModuleType:
    module = types.ModuleType(f"p_{hook_name}")

    def impl(register):
        register(spec)

    setattr(module, hook_name, hookimpl(impl))
    return module


def test_hook_register_sensors():
    spec = SensorSpec(
        name="tiny",
        sampling_rate_hz=100,
        full_scale_g=2,
        adc_bits=8,
        noise_density_ug_rthz=1,
        mech_cutoff_hz=40,
        analog_cutoff_hz=30,
    )
    registry = build_registry(entry_points=False, plugins=[plugin_with("register_sensors", spec)])
    assert registry.sensor("tiny").plugin == "p_register_sensors"


def test_hook_register_features():
    spec = FeatureSetSpec(
        name="peak",
        feature_names=("peak",),
        units=("g",),
        compute=lambda w, fs: np.abs(w).max(axis=1, keepdims=True),
    )
    registry = build_registry(entry_points=False, plugins=[plugin_with("register_features", spec)])
    assert registry.feature_set("peak").bytes_per_window == 4


def test_hook_register_classifiers():
    spec = ClassifierSpec(name="dummy", estimator="sklearn.dummy:DummyClassifier", seed_param=None)
    registry = build_registry(
        entry_points=False, plugins=[plugin_with("register_classifiers", spec)]
    )
    assert type(registry.classifier("dummy").build(seed=3)).__name__ == "DummyClassifier"


def test_hook_register_datasets():
    spec = DatasetSpec(name="nothing", loader=lambda path, **options: None, requires_path=False)
    registry = build_registry(entry_points=False, plugins=[plugin_with("register_datasets", spec)])
    assert registry.dataset("nothing").requires_path is False


def hook_names() -> list[str]:
    return [
        name
        for name, obj in vars(hookspecs).items()
        if inspect.isfunction(obj) and name.startswith("register_")
    ]


def test_every_hook_is_documented_and_tested():
    names = hook_names()
    assert {
        "register_sensors",
        "register_features",
        "register_classifiers",
        "register_datasets",
    } <= set(names)
    source = Path(__file__).read_text()
    for name in names:
        assert inspect.getdoc(getattr(hookspecs, name)), f"hook {name} has no docstring"
        assert f"def test_hook_{name}(" in source, f"hook {name} has no test_hook_{name}"


def test_hook_register_parts():
    from sdt_framework.parts import load_part_text

    part = load_part_text(
        """
        name = "tiny-part"
        manufacturer = "Test"
        interface = "digital"
        [documents.ds]
        title = "Tiny data sheet"
        revision = "Rev. 1"
        [values]
        sampling_rate_hz = { value = 100, doc = "ds", where = "T1", basis = "setting" }
        adc_bits = { value = 8, doc = "ds", where = "T1", basis = "nominal" }
        noise_density_ug_rthz = { value = 1, doc = "ds", where = "T1", basis = "typical" }
        mech_cutoff_hz = { value = 40, doc = "ds", where = "T1", basis = "typical" }
        analog_cutoff_hz = { value = 30, doc = "ds", where = "T1", basis = "typical" }
        digital_cutoff_hz = { value = "none", doc = "ds", where = "T1", basis = "derived" }
        digital_order = { value = "none", doc = "ds", where = "T1", basis = "derived" }
        [modes.range]
        default = "2g"
        default_why = "power-on"
        field = "full_scale_g"
        unit = "g"
        doc = "ds"
        where = "T2"
        basis = "nominal"
        options = ["2g", "4g"]
        """,
        "tiny.toml",
    )
    registry = build_registry(entry_points=False, plugins=[plugin_with("register_parts", part)])
    assert registry.part("tiny-part").plugin == "p_register_parts"
    sensor = registry.sensor("tiny-part[range=4g]")
    assert (sensor.name, sensor.full_scale_g) == ("tiny-part[range=4g]", 4)
    assert sensor.distribution == "(in-process)"


def test_hook_register_stages():
    from pydantic import BaseModel, ConfigDict

    from sdt_framework.stages import StageSpec

    class Gain(BaseModel):
        model_config = ConfigDict(extra="forbid")
        gain: float = 2.0

    class Multiply:
        def __init__(self, params, context):
            self.name, self.fs_in, self.fs_out, self.gain = (
                context.label,
                context.fs,
                context.fs,
                params.gain,
            )

        def apply(self, x, ctx):
            return x * self.gain

    spec = StageSpec(name="times", domain="digital", params=Gain, factory=Multiply)
    registry = build_registry(entry_points=False, plugins=[plugin_with("register_stages", spec)])
    assert registry.stage("times").plugin == "p_register_stages"
    sensor = registry.bind(
        SensorSpec(
            name="tiny",
            sampling_rate_hz=100,
            full_scale_g=2,
            adc_bits=8,
            noise_density_ug_rthz=0,
            mech_cutoff_hz=None,
            analog_cutoff_hz=None,
            requantise=False,
            stages=[{"name": "times", "params": {"gain": 3}}],
        )
    )
    from sdt_framework.api import degrade

    y, _ = degrade(np.ones(100), 100.0, sensor)
    assert np.array_equal(y, np.full(100, 3.0))


def test_hook_register_signal_readers(tmp_path):
    from sdt_framework.signals.files import reader_for
    from sdt_framework.signals.rules import SignalInfo
    from sdt_framework.specs import ReaderSpec

    def scan(path):
        return [SignalInfo(None, 1, 3, 100.0, "g", "header")]

    spec = ReaderSpec(
        name="three",
        label="THREE",
        suffixes=(".three",),
        sniff=lambda head: head.startswith(b"3"),
        scan=scan,
        probe=lambda path, variable: scan(path)[0],
        read=lambda path, variable: np.ones((1, 3)),
    )
    registry = build_registry(
        entry_points=False, plugins=[plugin_with("register_signal_readers", spec)]
    )
    assert registry.signal_reader("three").plugin == "p_register_signal_readers"
    unnamed = tmp_path / "recording"
    unnamed.write_bytes(b"3 three samples")
    reader = reader_for(unnamed, registry.signal_readers())  # by its first bytes
    assert reader.read(unnamed, None).tolist() == [[1.0, 1.0, 1.0]]
