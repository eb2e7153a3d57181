"""Conformance checks that plugin authors run on their own plugin.

``check_plugin(my_plugin_module)`` registers the plugin in a fresh registry,
checks that every spec it provides validates, that its names do not collide
with the installed plugins, and that the object each spec builds behaves as
its kind requires (a sensor degrades a signal onto its ADC grid, a feature set
returns one finite float32 row per window, a classifier fits and predicts
reproducibly, a dataset yields loadable recordings). sdt-framework runs the
same checks on every built-in plugin in its own test suite.

Example
-------
>>> from sdt_framework.conformance import check_plugin
>>> import my_sdt_plugin
>>> check_plugin(my_sdt_plugin)          # raises ConformanceError on failure
>>> check_plugin("my_package.plugin:MyPlugin")  # the entry point's value, loaded as sdt does

A plugin is a module, an instance or a class (instantiated without arguments,
as discovery does); a string is an entry point's value and is imported the way
``sdt`` imports it, so the form declared in ``pyproject.toml`` is what is checked.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .errors import SDTError, validation_summary
from .parts import PartSpec, all_modes, resolve
from .registry import Registry, build_registry, load_entry_point
from .specs import (
    BearingSpec,
    ClassifierSpec,
    DatasetSpec,
    FeatureContext,
    FeatureSetSpec,
    MachineSpec,
    ReaderSpec,
    SensorSpec,
    Spec,
)
from .stages import StageContext, StageSpec

__all__ = ["ConformanceError", "check_plugin", "check_spec"]


class ConformanceError(SDTError, AssertionError):
    """A plugin that does not behave as its kind requires."""


def _fail(spec: Spec, message: str) -> None:
    raise ConformanceError(f"{spec.kind} {spec.name!r} ({spec.plugin}): {message}")


def _check_sensor(spec: SensorSpec) -> None:
    from .chain import degrade

    fs = max(20000.0, float(spec.at_rate(20000.0).sampling_rate_hz))
    t = np.arange(int(fs)) / fs
    x = 0.5 * np.sin(2 * np.pi * 80.0 * t)[None, :].repeat(2, axis=0)
    y, rate = degrade(x, fs, spec, seed=1)
    if rate != spec.at_rate(fs).sampling_rate_hz:
        _fail(spec, f"output rate {rate} != sampling_rate_hz {spec.sampling_rate_hz}")
    if y.ndim != 2 or y.shape[0] != 2 or not np.all(np.isfinite(y)):
        _fail(spec, f"degrade returned shape {y.shape} or non-finite values")
    if spec.requantise and spec.full_scale_g is not None and spec.quantisation_step_g:
        if np.max(np.abs(y)) > spec.full_scale_g:
            _fail(spec, "output exceeds the full scale")
        steps = y / spec.quantisation_step_g
        if not np.allclose(steps, np.round(steps), atol=1e-6):
            _fail(spec, "output is not on the quantisation grid")
    y2, _ = degrade(x, fs, spec, seed=1)
    if not np.array_equal(y, y2):
        _fail(spec, "the same seed gave different outputs")


def _check_part(spec: PartSpec) -> None:
    """Every mode resolves to a valid sensor with a source for every value; the default runs."""
    for mode in all_modes(spec):
        try:
            resolved = resolve(spec, mode)
        except SDTError as exc:
            raise ConformanceError(f"{exc} (plugin {spec.plugin!r})") from None
        for source in resolved.sources:
            if not (source.source and source.where) and not source.absent:
                _fail(spec, f"{resolved.sensor.name}: {source.field} has no provenance")
    _check_sensor(resolve(spec).sensor)
    _check_error_terms(spec)


def _check_error_terms(spec: PartSpec) -> None:
    """With its error terms on, every mode that has some draws a unit that compiles.

    A mode without terms is an :class:`ErrorTermsError` by design and is
    passed over; a part with terms must have at least one mode that runs.
    """
    from . import registry
    from .chain import compile_chain
    from .parts.error_modes import ErrorTermsError
    from .stages import draw_unit

    if all(term.absent and term.stand_in == "none" for term in spec.errors.values()):
        return  # the documents give no term: nothing to turn on
    ran = 0
    for mode in all_modes(spec):
        for key in ("errors", "cross_axis"):
            try:
                sensor = resolve(spec, {**mode, key: "datasheet"}).sensor
            except ErrorTermsError:
                continue  # this mode (or this key) has no terms
            try:
                unit = draw_unit(registry.default_registry().bind(sensor), seed=0, k=0)
                compile_chain(unit, max(20000.0, float(unit.sampling_rate_hz)))
            except SDTError as exc:
                raise ConformanceError(f"{exc} (plugin {spec.plugin!r})") from None
            ran += 1
    if not ran:
        _fail(spec, "has error terms, but no mode turns any of them on")


def _probe_context() -> FeatureContext:
    """A recording's context for a set working in orders: 1500 rpm, a probe machine with
    one deep-groove bearing at the channel (a made-up geometry: the check exercises the
    extraction path, it reads no real machine)."""
    bearing = BearingSpec(
        name="probe", balls=8, ball_mm=10.0, pitch_mm=50.0, channel="ch1", faults=()
    )
    machine = MachineSpec(name="probe", shaft_rpm=1500.0, bearings=(bearing,))
    return FeatureContext(speed_hz=25.0, speed_from="conformance probe", machine=machine,
                          channel="ch1", recording="probe")  # fmt: skip


def _check_feature_set(spec: FeatureSetSpec) -> None:
    # Through the real extraction path: windowing, centring, output validation.
    from .features import extract

    signal = np.random.default_rng(0).normal(size=(2, 4800))  # 2 x 1.5 s at 3200 Hz
    try:
        table = extract(
            signal, 3200.0, spec, context=_probe_context() if spec.needs_speed else None
        )
    except SDTError as exc:
        raise ConformanceError(f"{exc} (plugin {spec.plugin!r})") from None
    if table.values.shape != (4, len(spec.feature_names)):  # 2 windows per acquisition
        _fail(spec, f"expected 4 windows x {len(spec.feature_names)}, got {table.values.shape}")


def _check_classifier(spec: ClassifierSpec) -> None:
    rng = np.random.default_rng(0)
    n = 200  # enough for minibatch learners with early stopping to take several steps
    X = np.vstack([rng.normal(-2, 1, size=(n, 3)), rng.normal(2, 1, size=(n, 3))])
    y = np.repeat([0, 1], n)
    predictions = []
    for _ in range(2):
        estimator = spec.build(seed=7)
        for method in ("fit", "predict"):
            if not callable(getattr(estimator, method, None)):
                _fail(spec, f"estimator {type(estimator).__name__} has no {method}()")
        estimator.fit(X, y)
        predictions.append(np.asarray(estimator.predict(X)))
    if predictions[0].shape != (2 * n,):
        _fail(spec, f"predict returned shape {predictions[0].shape}, expected ({2 * n},)")
    if not np.array_equal(predictions[0], predictions[1]):
        _fail(spec, "two estimators built with the same seed disagree")
    if np.mean(predictions[0] == y) < 0.9:
        _fail(spec, "cannot separate two well-separated Gaussian blobs")


def _check_stage(spec: StageSpec) -> None:
    """The stage builds from its example, keeps rows and input, is finite and reproducible."""
    from .chain import RunContext

    rates = {"digital": (1000.0, 1000.0)}.get(spec.domain, (20000.0, 1000.0))
    context = StageContext(rates[0], 20000.0, 1000.0, 2.0, f"{spec.name}.0", "conformance")
    stage = spec.factory(spec.params.model_validate(spec.example), context)
    t = np.arange(int(rates[0])) / rates[0]
    x = 0.5 * np.sin(2 * np.pi * 80.0 * t)[None, :].repeat(2, axis=0)
    before = x.copy()
    node = (0.3 * x, -0.2 * x) if spec.node else None  # a node stage reads two more axes
    ctx = RunContext(seed=1, acquisition_ids=(0, 1), threads=1, node=node)
    y, y2 = stage.apply(x, ctx), stage.apply(x, ctx)
    if not np.array_equal(x, before):
        _fail(spec, "apply modified its input")
    if y.ndim != 2 or y.shape[0] != 2 or not np.all(np.isfinite(y)):
        _fail(spec, f"apply returned shape {y.shape} or non-finite values")
    if stage.fs_out != (rates[1] if spec.domain != "analog" else rates[0]):
        _fail(spec, f"fs_out {stage.fs_out} does not match its domain {spec.domain}")
    if not np.array_equal(y, y2):
        _fail(spec, "the same seed gave different outputs")


def _check_dataset(spec: DatasetSpec) -> None:
    if spec.requires_path:
        return  # needs user data; its loader is exercised by the plugin's own tests
    dataset = spec.loader(None, duration=1.0)
    recordings = dataset.recordings()
    if not recordings:
        _fail(spec, "yields no recordings")
    data = recordings[0].load()
    if data.ndim != 2 or not np.all(np.isfinite(data)):
        _fail(spec, f"load() returned shape {data.shape} or non-finite values")


def _check_reader(spec: ReaderSpec) -> None:
    """A reader needs a real file of its format to be read; here only what holds for any:
    it names a suffix, and its sniff answers (never raises) on bytes of another format."""
    if not spec.suffixes:
        _fail(spec, "names no suffix")
    if spec.sniff is not None:
        for head in (b"", b"\x00" * 1024, b"time,acc\n0,1\n"):
            try:
                answer = spec.sniff(head)
            except Exception as exc:
                _fail(spec, f"sniff raised {type(exc).__name__} on {len(head)} bytes")
            if not isinstance(answer, bool):
                _fail(spec, f"sniff returned {type(answer).__name__}, not bool")


_CHECKS: dict[type[Spec], Callable[[Any], None]] = {
    SensorSpec: _check_sensor,
    FeatureSetSpec: _check_feature_set,
    ClassifierSpec: _check_classifier,
    DatasetSpec: _check_dataset,
    PartSpec: _check_part,
    StageSpec: _check_stage,
    ReaderSpec: _check_reader,
}


def check_spec(spec: Spec) -> None:
    """Check one spec's behaviour for its kind; raise ConformanceError on failure."""
    _CHECKS[type(spec)](spec)


def check_plugin(plugin: Any, *, installed: Registry | None = None) -> list[Spec]:
    """Register ``plugin`` alone, check it, and return the specs it provides.

    Parameters
    ----------
    plugin
        A plugin module, instance or class implementing sdt-framework hooks, or
        the value of its entry point (``"my_package.plugin:MyPlugin"``), loaded
        exactly as ``sdt`` loads entry points.
    installed
        Registry of the other plugins to check name clashes against (default:
        everything installed; an installed copy of ``plugin`` itself, with an
        identical definition, is not a clash).
    """
    name = None
    if isinstance(plugin, str):
        name = plugin
        try:
            plugin = load_entry_point(plugin)
        except Exception as exc:
            raise ConformanceError(
                f"entry point {plugin!r} failed to load: {validation_summary(exc)}"
            ) from None
    fresh = build_registry(entry_points=False)
    info = fresh.register_plugin(plugin, name)
    if info.status != "loaded":
        raise ConformanceError(f"plugin {info.name!r} failed to register: {info.error}")
    installed = installed if installed is not None else build_registry()
    specs: list[Spec] = [
        # its profiles' stages may come from other plugins: bound to the installed ones
        *(installed.bind(sensor) for sensor in fresh.sensors(bound=False)),
        *fresh.feature_sets(),
        *fresh.classifiers(),
        *fresh.datasets(),
        *fresh.parts(),
        *fresh.stages(),
        *fresh.signal_readers(),
    ]
    if not specs:
        raise ConformanceError(f"plugin {info.name!r} registers nothing")
    taken = {
        SensorSpec: installed.sensors(),
        FeatureSetSpec: installed.feature_sets(),
        ClassifierSpec: installed.classifiers(),
        DatasetSpec: installed.datasets(),
        PartSpec: installed.parts(),
        StageSpec: installed.stages(),
        ReaderSpec: installed.signal_readers(),
    }
    taken[SensorSpec] += installed.parts()  # one namespace: a part is used where a sensor is
    taken[PartSpec] += installed.sensors()
    for spec in specs:
        for other in taken[type(spec)]:
            # The plugin itself, when installed, provides the identical definition.
            if other.name == spec.name and other.content_hash() != spec.content_hash():
                raise ConformanceError(
                    f"{spec.kind} {spec.name!r} is already provided by plugin "
                    f"{other.plugin!r} ({other.distribution}); choose another name"
                )
        check_spec(spec)
    return specs
