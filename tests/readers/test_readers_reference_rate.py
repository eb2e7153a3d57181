"""A reference recorded at an NI IEPE module's rate (25.6 or 51.2 kHz), read from TDMS, runs
through the paper's protocol with the ADXL345 and ADXL357 twins, without resampling by hand."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.signal import resample_poly
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.chain import compile_chain, degrade
from sdt_framework.data.open import round_significant


def _tdms(file: Path, rows: np.ndarray, rate: float) -> None:
    from nptdms import ChannelObject, TdmsWriter

    props = {"wf_increment": 1 / rate, "unit_string": "g"}
    with TdmsWriter(file) as writer:
        writer.write_segment(
            [ChannelObject("ai0", f"a{i}", row, properties=props) for i, row in enumerate(rows)]
        )


@pytest.mark.parametrize("rate", [25_600.0, 51_200.0])
def test_the_twins_see_an_in_band_tone_alike_at_the_daq_rate_and_at_20_khz(rate, adxl345, adxl357):
    """A 1 g, 80 Hz tone: each twin's output does not depend on the reference's rate (its
    chain designs its filters and resampling for the rate given); checked by the tone's
    amplitude, fitted here by least squares, against the same tone given at 20 kHz."""
    for sensor, out_rate in ((adxl345, 3200.0), (adxl357, 4000.0)):
        amplitudes = []
        for fs in (20_000.0, rate):
            t = np.arange(int(2.0 * fs)) / fs
            y, fs_out = degrade(np.sin(2 * np.pi * 80.0 * t), fs, sensor, noise=False)
            assert fs_out == out_rate == compile_chain(sensor, fs).fs_out
            tail = y[len(y) // 4 :]  # after the filters' start-up
            tt = (np.arange(len(y)) / fs_out)[len(y) // 4 :]
            basis = np.column_stack([np.sin(2 * np.pi * 80 * tt), np.cos(2 * np.pi * 80 * tt)])
            coef = np.linalg.lstsq(basis, tail, rcond=None)[0]
            amplitudes.append(float(np.hypot(*coef)))
        assert amplitudes[1] == pytest.approx(amplitudes[0], rel=2e-3), sensor.name
        assert amplitudes[0] == pytest.approx(1.0, rel=0.02)  # in band: passed almost unchanged


def test_a_25_6_khz_tdms_reference_runs_the_paper_protocol(sdt_main, tmp_path, monkeypatch):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    root = tmp_path / "daq"
    dataset = open_synthetic(duration=1.5, channels="ch1", machines="Motor-2")
    for rec, data in dataset.iter_loaded():
        severity = "-" if rec.severity is None else str(rec.severity)
        folder = root / rec.machine / f"{rec.condition} {severity}" / rec.run
        folder.mkdir(parents=True)
        # the pump as an NI 9234 would have sampled it: 20 kHz * 32 / 25 = 25.6 kHz
        _tdms(folder / f"{rec.channel}.tdms", round_significant(resample_poly(data, 32, 25,
              axis=-1)), 25_600.0)  # fmt: skip
    manifest = tmp_path / "manifest.csv"
    code, _, err = sdt_main("dataset", "manifest", str(root), "--pattern",
                              "{machine}/{condition} {severity}/{run}/{channel}.tdms",
                              "--out", str(manifest))  # fmt: skip
    assert code == 0, err
    with open(manifest, encoding="utf-8") as handle:
        assert {r["sampling_rate_hz"] for r in csv.DictReader(handle)} == {"25600.0"}
    code, _, err = sdt_main("benchmark", "--data", str(manifest), "--quick", "--classifiers",
                              "lr", "--jobs", "1", "--no-report", "--out",
                              str(tmp_path / "out"))  # fmt: skip
    assert code == 0, err
    results = pd.read_csv(tmp_path / "out" / "results.csv")
    assert set(results["sensor"]) == {"native-reference", "adxl345", "adxl357"}
    assert set(results["scenario"]) == {"forward", "backward", "interpolation"}
    assert results["macro_f1"].between(0, 1).all()
