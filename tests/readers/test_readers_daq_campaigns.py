"""A campaign saved as multi-time-column LVM, and one exported by HBM catman as UFF58, each run
through ``sdt dataset manifest`` then ``sdt benchmark --quick --data`` to the end (issue 41).

The synthetic pump's Motor-2 (channel ch1, two acquisitions a run) is written as LabVIEW
writes ``X_Columns`` ``Multi`` (one segment an acquisition; the 20 kHz accelerometer, the same
at 10 kHz as a second module would log it, and a 1 kHz tachometer in V, each with its own time
column and length) and as catman writes UFF58 (one time history an acquisition, in m/s²;
every other file with a PSD without units appended by pyuff); layouts in ``daq_files.py``. On
main the 10 kHz channel was listed at the 20 kHz one's length and the benchmark stopped on its
empty cells ("non-finite value"); the catman files ending in catman's padded -1 were refused
as cut short and those with a PSD (no rate) left out, so the manifest had no file. Every
signal the manifest names reads as the format's own library (lvm_read, pyuff) reads it.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.signals.files import read_signal

from .daq_files import PSD, Channel, catman_uff, lvm_text

ARGS = ("--quick", "--sensors", "adxl345", "--classifiers", "lr", "--jobs", "1", "--no-report")
#: LVM: each signal of a file is a channel of its own (two accelerometers at two rates);
#: UFF: each dataset an acquisition of the file's channel
PATTERNS = {"lvm": "{machine}/{condition}/{severity}/{run}/ch1.lvm",
            "uff": "{machine}/{condition}/{severity}/{run}/{channel}.uff"}  # fmt: skip
G = 9.80665  # m/s² per g (CGPM 1901, standard gravity)


def _campaign(root: Path, fmt: str) -> int:
    import pyuff

    psd = {**pyuff.UFF(str(PSD)).read_sets(0),
           "ordinate_axis_units_lab": "NONE"}  # fmt: skip
    count = 0
    for rec, data in open_synthetic(machines="Motor-2", duration=1.0, channels="ch1",
                                    acquisitions=2).iter_loaded():  # fmt: skip
        severity = "-" if rec.severity is None else str(rec.severity)
        folder = root / rec.machine / rec.condition / severity / rec.run
        folder.mkdir(parents=True)
        file = folder / f"{rec.channel}.{fmt}"
        if fmt == "lvm":
            tacho = np.where(np.arange(len(data[0]) // 20) % 10 < 5, 5.0, 0.0)
            step = 1 / rec.sampling_rate_hz
            segments = [[Channel("acc", np.round(row, 6), step),
                         Channel("acc half rate", np.round(row[::2], 6), 2 * step),
                         Channel("tacho", tacho, 1e-3, units="V")] for row in data]  # fmt: skip
            file.write_text(lvm_text(segments), encoding="utf-8")
        else:
            file.write_text(catman_uff({f"a{i}": row * G for i, row in enumerate(data)},
                                       rec.sampling_rate_hz), encoding="utf-8")  # fmt: skip
            if count % 2 == 0:  # every other file ends with its PSD, the rest with catman's -1
                pyuff.UFF(str(file)).write_sets(psd, mode="add")
        count += 1
    return count


def _reference(file: Path, fmt: str) -> np.ndarray:
    """The accelerometers' acquisitions as the format's own library reads them: LVM
    (segments, rows, 2 channels), its columns after each X column; UFF (datasets, samples)."""
    if fmt == "lvm":
        import lvm_read

        lvm = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)
        return np.stack([lvm[s]["data"][:, [1, 3]] for s in range(lvm["Segments"])])
    import pyuff

    return np.stack([d["data"] for d in pyuff.UFF(str(file)).read_sets([0, 1])])


@pytest.mark.parametrize(("fmt", "units"), [("lvm", "g"), ("uff", "m/s^2")])
def test_a_daq_campaign_runs_manifest_then_benchmark(
    tmp_path, monkeypatch, sdt_main, fmt, units, readers
):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    root = tmp_path / fmt
    files = _campaign(root, fmt)
    manifest = tmp_path / "campaign.csv"
    code, out, err = sdt_main("dataset", "manifest", str(root), "--pattern",
                              PATTERNS[fmt], "--out", str(manifest))  # fmt: skip
    assert code == 0, err
    recordings = 2 * files if fmt == "lvm" else files
    assert f"from {files} files ({recordings} recordings); 0 not used" in out
    with open(manifest, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    rates = {"20000.0", "10000.0"} if fmt == "lvm" else {"20000.0"}
    assert {(r["sampling_rate_hz"], r["units"]) for r in rows} == {(r, units) for r in rates}
    if fmt == "lvm":  # the tachometer in V is left out and counted, once a file
        assert f"{files} signals skipped: not an acceleration unit ('V': {files})" in err
    else:  # each PSD, without units or rate, is left out and named
        assert f"{(files + 1) // 2} signals skipped: not readable as they stand" in err
    references: dict[Path, np.ndarray] = {}  # each file parsed once by its library (slow)
    for row in rows:  # LVM: a row a channel, its segments; UFF: a row a dataset
        file = manifest.parent / row["path"]
        if file not in references:
            references[file] = _reference(file, fmt)
        reference = references[file]
        if fmt == "lvm":
            half = row["variable"] == "acc half rate"
            expected = reference[:, : len(reference[0]) // (1 + half), int(half)]
        else:
            expected = reference[[int(row["variable"]) - 1]]
        np.testing.assert_array_equal(read_signal(file, readers, row["variable"]), expected)
    code, out, err = sdt_main("benchmark", "--data", str(manifest), *ARGS,
                              "--out", str(tmp_path / "out"))  # fmt: skip
    assert code == 0, err
    results = pd.read_csv(tmp_path / "out" / "results.csv")
    assert len(results) > 0 and (results["status"] == "ok").all()
