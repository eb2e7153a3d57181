"""A third party adds a signal format with a plugin, through the entry point the built-ins use."""

from __future__ import annotations

import json

import numpy as np

PLUGIN = """
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.signals.rules import SignalInfo, as_acquisitions
from sdt_framework.specs import ReaderSpec


def _parse(path):
    rate, *values = Path(path).read_text().split()
    return float(rate), np.array(values, dtype=float)


def scan(path):
    rate, values = _parse(path)
    return [SignalInfo(None, 1, len(values), rate, "mg", "first line")]


def probe(path, variable):
    return scan(path)[0]


def read(path, variable):
    return as_acquisitions(path, _parse(path)[1])


@hookimpl
def register_signal_readers(register):
    register(ReaderSpec(name="acme", label="ACME", suffixes=(".acme",), scan=scan,
                        probe=probe, read=read, description="rate on line 1, then samples"))
"""


def test_a_reader_plugin_reads_in_inspect_and_in_a_manifest(fake_dist, sdt_main, tmp_path):
    fake_dist("sdt-acme", {"acme": "sdt_acme_reader"}, {"sdt_acme_reader": PLUGIN})
    code, out, err = sdt_main("plugins", "list")
    assert code == 0, err
    assert "signal reader: acme" in out and "signal reader: tdms" in out
    root = tmp_path / "recordings"
    (root / "healthy").mkdir(parents=True)
    file = root / "healthy" / "run1.acme"
    file.write_text("1000\n" + "\n".join(str(v) for v in range(64)) + "\n")
    code, out, err = sdt_main("dataset", "inspect", str(file), "--json")
    assert code == 0, err
    info = json.loads(out)
    assert (info["format"], info["reader"]) == ("ACME", "acme")
    assert info["signals"][0]["rate_hz"] == 1000.0 and info["signals"][0]["duration_s"] == 0.064
    code, _, err = sdt_main("dataset", "manifest", str(root), "--pattern", "{run}.acme",
                            "--out", str(tmp_path / "n.csv"))  # fmt: skip
    assert code == 2 and "names no {condition}" in err
    manifest = tmp_path / "m.csv"
    code, out, err = sdt_main("dataset", "manifest", str(root), "--pattern",
                              "{condition}/{run}.acme", "--out", str(manifest))  # fmt: skip
    assert code == 0, err
    assert "1 rows from 1 files (1 recordings); 0 not used" in out
    assert "recordings/healthy/run1.acme,1000.0,healthy,,run1,run1" in manifest.read_text()
    from sdt_framework.data import open_dataset
    from sdt_framework.registry import build_registry

    (recording,) = open_dataset(build_registry(), str(manifest)).recordings()
    assert (recording.sampling_rate_hz, recording.units) == (1000.0, "mg")
    np.testing.assert_allclose(recording.load()[0], np.arange(64) * 1e-3)  # mg -> g
