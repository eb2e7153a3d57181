"""A synthetic-pump run written as TDMS and as UFF58 in a folder tree, turned into a manifest by
``sdt dataset manifest``, benchmarks exactly as the same samples written as CSV do."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import pyuff
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.data.open import round_significant

DATA = Path(__file__).parents[1] / "data" / "readers"
ARGS = ("--quick", "--sensors", "adxl345", "--classifiers", "lr", "--jobs", "1", "--no-report")
#: a real dataset 58 (pyuff's binary8byte.uff: a time response in g) as the fields of ours
UFF_TEMPLATE = {k: v for k, v in pyuff.UFF(str(DATA / "binary8byte.uff")).read_sets(0).items()}
TEMPLATE = "{machine}/{speed}/{condition}/{severity}/{run}/{channel}"


def _write(root: Path, fmt: str) -> int:
    """Every recording of a short synthetic pump (channel ch1) as one file; samples rounded to
    6 significant digits, which every format stores exactly. Returns the file count."""
    import pyuff
    from nptdms import ChannelObject, TdmsWriter

    dataset = open_synthetic(duration=1.5, channels="ch1", acquisitions=2)
    count = 0
    for rec, data in dataset.iter_loaded():
        data = round_significant(data)
        severity = "-" if rec.severity is None else str(rec.severity)
        folder = root / rec.machine / str(rec.speed) / rec.condition / severity / rec.run
        folder.mkdir(parents=True)
        file = folder / f"{rec.channel}.{fmt}"
        step = 1.0 / rec.sampling_rate_hz
        if fmt == "csv":
            np.savetxt(file, data.T, delimiter=",", fmt="%.17g",
                       header=",".join(f"a{i}" for i in range(len(data))), comments="")  # fmt: skip
        elif fmt == "tdms":
            props = {"wf_increment": step, "unit_string": "g"}
            with TdmsWriter(file) as writer:
                writer.write_segment(
                    [ChannelObject("acc", f"a{i}", row, properties=props) for i, row in
                     enumerate(data)]
                )  # fmt: skip
        else:
            uff = pyuff.UFF(str(file))
            for i, row in enumerate(data):
                dataset = {
                    **UFF_TEMPLATE,
                    "binary": i % 2,
                    "data": row,
                    "num_pts": len(row),
                    "x": np.arange(len(row)) * step,
                    "abscissa_inc": step,
                    "id1": f"a{i}",
                }
                uff.write_sets(dataset, mode="add" if file.exists() else "overwrite")  # fmt: skip
        count += 1
    return count


def _results(folder: Path) -> pd.DataFrame:
    return pd.read_csv(folder / "results.csv").drop(columns="fit_seconds")


@pytest.fixture
def runs(tmp_path, monkeypatch, sdt_main):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))

    def run(fmt: str) -> tuple[pd.DataFrame, list[dict[str, str]]]:
        root = tmp_path / fmt
        files = _write(root, fmt)
        manifest = tmp_path / f"{fmt}.csv"
        extra = ("--rate-hz", "20000") if fmt == "csv" else ()
        code, out, err = sdt_main("dataset", "manifest", str(root), "--pattern",
                                  f"{TEMPLATE}.{fmt}", "--out", str(manifest), *extra)  # fmt: skip
        assert code == 0, err
        assert f"from {files} files ({files} recordings); 0 not used" in out
        code, _, err = sdt_main("benchmark", "--data", str(manifest), *ARGS,
                                "--out", str(tmp_path / f"out-{fmt}"))  # fmt: skip
        assert code == 0, err
        with open(manifest, encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        return _results(tmp_path / f"out-{fmt}"), rows

    return run


def test_tdms_and_uff58_trees_benchmark_as_the_csv_tree(runs):
    expected, csv_rows = runs("csv")
    assert {r["sampling_rate_hz"] for r in csv_rows} == {"20000.0"}
    for fmt in ("tdms", "uff"):
        results, rows = runs(fmt)
        # the rate and units came from the files (wf_increment / abscissa_inc, unit_string /
        # ordinate label); two rows per file, one per acquisition
        assert {(r["sampling_rate_hz"], r["units"]) for r in rows} == {("20000.0", "g")}
        assert len(rows) == 2 * len(csv_rows)
        pd.testing.assert_frame_equal(results, expected)
