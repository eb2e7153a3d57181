"""A campaign recorded as 24-bit WAV with a sensitivity runs ``sdt dataset manifest`` then
``sdt benchmark --quick --data`` to the end, and benchmarks exactly as the same samples
written as CSV (issue 41, item 6: on main every 24-bit WAV was refused, so the manifest held
no recording)."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import soundfile
from sdt_plugins.datasets.synthetic_pump import open_synthetic

ARGS = ("--quick", "--sensors", "adxl345", "--classifiers", "lr", "--jobs", "1", "--no-report")
TEMPLATE = "{machine}/{speed}/{condition}/{severity}/{run}/{channel}"
#: the recorder's full scale: a sample of 2**23 - 1 counts is (almost) 16 g
FULL_SCALE_G = 16.0


def _write(root: Path, fmt: str) -> int:
    """Every recording of a short synthetic pump (channel ch1), quantised as a 24-bit recorder
    at 16 g full scale would store it: 24-bit WAV (libsndfile), or CSV of the same values."""
    count = 0
    for rec, data in open_synthetic(duration=1.5, channels="ch1", acquisitions=2).iter_loaded():
        counts = np.round(data / FULL_SCALE_G * 2**23).astype(np.int64)
        assert np.abs(counts).max() < 2**23  # no sample clipped
        severity = "-" if rec.severity is None else str(rec.severity)
        folder = root / rec.machine / str(rec.speed) / rec.condition / severity / rec.run
        folder.mkdir(parents=True)
        file = folder / f"{rec.channel}.{fmt}"
        if fmt == "wav":  # one channel per acquisition, left-justified in int32
            soundfile.write(file, (counts.T << 8).astype(np.int32), int(rec.sampling_rate_hz),
                            subtype="PCM_24")  # fmt: skip
        else:
            np.savetxt(file, (counts / 2**23 * FULL_SCALE_G).T, delimiter=",", fmt="%.17g",
                       header=",".join(f"a{i}" for i in range(len(data))), comments="")  # fmt: skip
        count += 1
    return count


def _run(sdt_main, tmp_path: Path, fmt: str) -> tuple[pd.DataFrame, list[dict[str, str]]]:
    root, manifest, out = tmp_path / fmt, tmp_path / f"{fmt}.csv", tmp_path / f"out-{fmt}"
    files = _write(root, fmt)
    extra = ("--rate-hz", "20000") if fmt == "csv" else ("--full-scale-g", str(FULL_SCALE_G))
    code, text, err = sdt_main("dataset", "manifest", str(root), "--pattern",
                               f"{TEMPLATE}.{fmt}", "--out", str(manifest), *extra)  # fmt: skip
    assert code == 0, err
    assert f"from {files} files ({files} recordings); 0 not used" in text
    code, _, err = sdt_main("benchmark", "--data", str(manifest), *ARGS, "--out", str(out))
    assert code == 0, err
    with open(manifest, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return pd.read_csv(out / "results.csv").drop(columns="fit_seconds"), rows


def test_a_24_bit_wav_campaign_with_a_full_scale_benchmarks_as_its_csv(
    sdt_main, tmp_path, monkeypatch
):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    expected, _ = _run(sdt_main, tmp_path, "csv")
    results, rows = _run(sdt_main, tmp_path, "wav")
    # the rate came from each WAV's header, the units from its full scale
    assert {(r["sampling_rate_hz"], r["units"], r["full_scale_g"]) for r in rows} == {
        ("20000.0", "g", "16.0")
    }
    assert len(results) > 0
    pd.testing.assert_frame_equal(results, expected)
