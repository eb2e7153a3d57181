"""The readers a caller holds are the ones that read: handed down, never looked up below.

A registry of its own (a notebook's, a test's) with a reader plugin the
installed distributions lack reads that format everywhere it hands its table:
a manifest named in a benchmark config (``dataset = "manifest"``), and a pair
of channels for the twin. Before, a config naming the ``manifest`` dataset
opened it with the default registry's readers (installed into the data layer
when the registry module was imported), so the caller's reader was never
asked and its files were skipped as "format not recognised"; and a twin pair
had to be an IDE file, read by a module of the core.
"""

from __future__ import annotations

import types
from pathlib import Path

import numpy as np
import pytest

from sdt_framework import hookimpl
from sdt_framework.bench import plan
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.registry import build_registry
from sdt_framework.report.signals import open_config_dataset
from sdt_framework.signals import Channel, ChannelSignal, SignalInfo, Subchannel
from sdt_framework.signals.rules import as_acquisitions
from sdt_framework.specs import ReaderSpec
from sdt_framework.twin import load_pair

RATE = 2000.0
PIEZO_RATE = 20000.0


def _acme() -> types.ModuleType:
    """A reader plugin for ``.acme`` files: the rate on line 1, then samples in mg."""

    def parse(path):
        rate, *values = Path(path).read_text().split()
        return float(rate), np.array(values, dtype=float)

    def scan(path):
        rate, values = parse(path)
        return [SignalInfo(None, 1, len(values), rate, "mg", "first line")]

    def read(path, variable):
        return as_acquisitions(path, parse(path)[1])

    module = types.ModuleType("acme_reader")
    module.register_signal_readers = hookimpl(
        lambda register: register(
            ReaderSpec(name="acme", label="ACME", suffixes=(".acme",), scan=scan,
                       probe=lambda path, variable: scan(path)[0], read=read)
        )
    )  # fmt: skip
    return module


def _manifest(folder: Path) -> tuple[Path, dict[str, np.ndarray]]:
    """A manifest of two .acme runs (healthy, bpfo) of 4096 samples, and their samples in g."""
    rng = np.random.default_rng(5)
    rows, truth = ["path,sampling_rate_hz,condition,severity,recording_id,channel"], {}
    for run, condition, severity in (("r1", "healthy", ""), ("r2", "bearing bpfo", "1")):
        mg = np.round(rng.normal(0, 300, 4096), 3)
        (folder / f"{run}.acme").write_text(f"{RATE}\n" + "\n".join(map(str, mg)) + "\n")
        rows.append(f"{run}.acme,,{condition},{severity},{run},ch1")
        truth[condition] = mg * 1e-3
    (folder / "m.csv").write_text("\n".join(rows) + "\n")
    return folder / "m.csv", truth


def test_a_manifest_named_in_the_config_is_read_by_the_callers_readers(tmp_path):
    registry = build_registry(plugins=[_acme()])
    manifest, truth = _manifest(tmp_path)
    config = BenchmarkConfig(dataset="manifest", data=str(manifest))
    recordings = open_config_dataset(config, registry)  # the report's view of the run
    assert {r.condition for r in recordings} == set(truth)
    for recording in recordings:
        assert recording.sampling_rate_hz == RATE  # from the file, the row left it empty
        np.testing.assert_allclose(recording.load()[0], truth[recording.condition], rtol=1e-12)
    opened = plan._open(config, registry).recordings()  # the benchmark's own opening of it
    assert sorted(r.condition for r in opened) == sorted(truth)


def _recorder(ref: np.ndarray, dev: np.ndarray, dev_rate: float) -> types.ModuleType:
    """A reader plugin for ``.rec`` files of two channels (a piezo, an ADXL345): its own
    format, read through ``channels``/``read_channel`` alone."""

    def channel(cid: int) -> tuple[Channel, np.ndarray, float]:
        values, rate, part = (
            (ref, PIEZO_RATE, "832M1 piezo") if cid == 8 else (dev, dev_rate, "ADXL345 MEMS")
        )
        subs = tuple(Subchannel(i, a, a, "Acceleration", "g", part) for i, a in enumerate("xyz"))
        n = values.shape[1]
        info = Channel(cid, f"channel {cid}", subs, n, 0.0, (n - 1) / rate, rate, rate)
        return info, values, rate

    def channels(path):
        return [channel(8)[0], channel(32)[0]], ()

    def read_channel(path, cid, axes=None):
        info, values, rate = channel(cid)
        chosen = [s for s in info.subchannels if axes is None or s.axis in axes]
        rows = values[[s.index for s in chosen]]
        return ChannelSignal(str(path), info, tuple(chosen), 0.0, rate, rows, None, 0.0)

    def unused(*args, **kwargs):
        raise AssertionError("the twin reads a recorder file by its channels")

    module = types.ModuleType("recorder_reader")
    module.register_signal_readers = hookimpl(
        lambda register: register(
            ReaderSpec(name="rec", label="REC", suffixes=(".rec",), scan=unused, probe=unused,
                       read=unused, channels=channels, read_channel=read_channel)
        )
    )  # fmt: skip
    return module


def test_a_pair_of_channels_is_read_through_any_format_that_lists_them(tmp_path):
    rng = np.random.default_rng(9)
    ref, dev = rng.normal(0, 0.1, (3, 40_000)), rng.normal(0, 0.1, (3, 6_400))
    file = tmp_path / "bench.rec"
    file.write_bytes(b"two channels")
    registry = build_registry(plugins=[_recorder(ref, dev, 3200.0)])
    pair = load_pair(file, "adxl345", readers=registry.signal_readers(), axes=["x", "z"])
    # the device is the channel whose part the twin models, the reference the other one
    assert (pair.device.label, pair.device.part) == ("channel 32", "ADXL345 MEMS")
    assert (pair.reference.label, pair.reference.rate_hz) == ("channel 8", PIEZO_RATE)
    np.testing.assert_array_equal(pair.device.values, dev[[0, 2]])
    np.testing.assert_array_equal(pair.reference.values, ref[[0, 2]])
    installed = build_registry().signal_readers()  # no reader of .rec files: refused by name
    with pytest.raises(Exception, match=r"bench\.rec: not a recorder file of channels \(enDAQ"):
        load_pair(file, "adxl345", readers=installed)


def test_a_reader_gives_both_channel_functions_or_neither():
    with pytest.raises(ValueError, match="give both channels and read_channel, or neither"):
        ReaderSpec(name="half", label="HALF", suffixes=(".half",), scan=print, probe=print,
                   read=print, channels=print)  # fmt: skip
