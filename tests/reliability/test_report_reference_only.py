"""A benchmark with no sensor besides the reference: the report says so, exit 0 (issue 39, item 4).

On main ``sdt benchmark --quick --sensors wilcoxon-786b10 --classifiers lr``
ran all its runs, then ended in ``internal error: TypeError: Can only string
multiply by an integer`` in ``severity/agreement.py:alarm_thresholds``: with
no sensor to pair with the reference, the alarm thresholds were computed on an
empty machine column whose string dtype (pandas 3) met arithmetic. The same
when every MEMS profile is skipped because the data is sampled at 1500 Hz.
Now the severity section says why it is empty and the report is written.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sdt_framework.severity import alarm_thresholds, builtin_tables
from sdt_framework.severity.tables import Assignment

from ..helpers import MANIFEST_HEADER

NONE_TO_GRADE = "Not shown: no sensor besides the reference '{}' has windows to grade against it"

#: the report's text is the subject: ``sdt`` runs in this process (conftest.py), the
#: benchmarks with --jobs 1 (the same results at any --jobs, test_bench_jobs.py)
pytestmark = pytest.mark.in_process


@pytest.fixture(autouse=True)
def _figures_drawn_here(monkeypatch):
    """The report draws its figures in this process (as on a machine of fewer than 4 cores)."""
    monkeypatch.setattr("sdt_framework.report.figures.PARALLEL_FROM_CORES", 10**6)


def _severity(report: str) -> str:
    return report.split("## Severity and alarms")[1].split("\n## ")[0]


def test_reference_only_benchmark_writes_its_report(sdt, tmp_path):
    out = tmp_path / "out"
    done = sdt("benchmark", "--quick", "--sensors", "wilcoxon-786b10", "--classifiers", "lr",
               "--machines", "Motor-2", "--channels", "ch1", "--jobs", "1",
               "--out", str(out))  # fmt: skip
    assert done.returncode == 0, done.stderr[-2000:]
    assert "internal error" not in done.stderr
    section = _severity((out / "report.md").read_text(encoding="utf-8"))
    assert NONE_TO_GRADE.format("wilcoxon-786b10") in section


def test_every_mems_profile_skipped_at_1500_hz_writes_the_report(sdt, tmp_path):
    rng = np.random.default_rng(0)
    lines = [MANIFEST_HEADER]
    for condition, gain in (("healthy", 1.0), ("fault", 3.0)):
        for index in range(3):
            name = f"{condition}{index}"
            np.save(tmp_path / f"{name}.npy", gain * rng.normal(size=9000))  # 6 s at 1500 Hz
            severity = index + 1 if gain > 1 else ""
            lines.append(f"{name}.npy,1500,m,{condition},{severity},{name},ch1\n")
    (tmp_path / "m.csv").write_text("".join(lines))
    config = tmp_path / "bench.toml"
    config.write_text('[benchmark]\nzones = { m = "iso10816-3-group2-rigid" }\n')
    out = tmp_path / "out"
    done = sdt("benchmark", str(config), "--data", str(tmp_path / "m.csv"), "--quick",
               "--classifiers", "lr", "--jobs", "1", "--out", str(out))  # fmt: skip
    assert done.returncode == 0, done.stderr[-2000:]
    assert "internal error" not in done.stderr
    results = pd.read_parquet(out / "results.parquet")
    assert set(results["sensor"]) == {"native-reference"}  # adxl345/adxl357 skipped
    section = _severity((out / "report.md").read_text(encoding="utf-8"))
    assert NONE_TO_GRADE.format("native-reference") in section


def test_alarm_thresholds_of_no_pairs_are_an_empty_float_table():
    """The arithmetic itself: no healthy pair gives no threshold rows, of float dtype."""
    table = builtin_tables()["iso10816-3-group2-rigid"]
    pairs = pd.DataFrame(
        {
            "machine": pd.Series([], dtype="str"),
            "channel": pd.Series([], dtype="str"),
            "recording_id": pd.Series([], dtype="str"),
            "acquisition": pd.Series([], dtype="int64"),
            "window": pd.Series([], dtype="int64"),
            "sensor": pd.Series([], dtype="str"),
            "v_ref": pd.Series([], dtype="float64"),
            "v_sensor": pd.Series([], dtype="float64"),
            "healthy": pd.Series([], dtype="bool"),
        }
    )
    base = alarm_thresholds(pairs, {"m": Assignment("m", table, "test")})
    assert base.empty
    columns = ("baseline", "alarm", "baseline_ref", "alarm_ref", "trip")
    assert all(base[c].dtype == np.float64 for c in columns)
