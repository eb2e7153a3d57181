"""100 000-character labels from a manifest: shortened on the terminal, whole in the files.

On main a benchmark whose manifest named conditions, recordings and files
with 100 000 characters printed every one of them whole in its ``skipped``
and saturation lines (megabytes of terminal output). Now each over-long label
is cut in the middle on the terminal, saying how long it was; the result
files keep every label whole.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

HEADER = "path,sampling_rate_hz,machine,condition,severity,recording_id,channel\n"
LONG = 100_000

#: what the terminal shows is printed by this process (the benchmark with --jobs 1, the same
#: results at any --jobs): ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def test_long_labels_are_shortened_on_the_terminal_and_whole_in_the_files(sdt, tmp_path):
    rng = np.random.default_rng(0)
    healthy, fault = "healthy" + "h" * LONG, "fault" + "f" * LONG
    lines = [HEADER]
    for condition, gain in ((healthy, 1.0), (fault, 30.0)):  # 30 g clips the +-16 g adxl345
        for index in range(3):
            name = f"{condition[:5]}{index}"
            np.save(tmp_path / f"{name}.npy", gain * rng.normal(size=40_000))
            severity = index + 1 if gain > 1 else ""
            lines.append(f"{name}.npy,20000,m,{condition},{severity},{name}{'r' * LONG},ch1\n")
    missing = "/".join(["missing" + "m" * 243] * 15) + ".npy"  # 3,764 characters: a long path
    lines.append(f"{missing},20000,m,{healthy},,gone,ch1\n")
    manifest = tmp_path / "m.csv"
    manifest.write_text("".join(lines))
    out = tmp_path / "out"

    done = sdt("benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
               "--classifiers", "lr", "--no-report", "--jobs", "1", "--out", str(out))  # fmt: skip
    assert done.returncode == 0, done.stderr[:2000]
    assert len(done.stdout) + len(done.stderr) < 20_000  # before: over 600 kB
    skipped = [line for line in done.stderr.splitlines() if "file not found" in line]
    assert len(skipped) == 1 and skipped[0].startswith(f"skipped {str(tmp_path)[:50]}")
    assert f"({len(str(tmp_path / missing)) + 1:,} characters)" in skipped[0]  # path and ':'
    assert len(skipped[0]) < 400
    clipped = [line for line in done.stderr.splitlines() if "full scale (clipped)" in line]
    assert len(clipped) == 1 and "characters)" in clipped[0] and len(clipped[0]) < 2000

    features = pd.read_parquet(out / "features.parquet", columns=["condition", "recording_id"])
    assert set(features["condition"]) == {healthy, fault}  # whole in the result files
    assert features["recording_id"].str.contains("r" * LONG, regex=False).all()


def test_a_manifest_where_no_scenario_can_be_scored_is_one_error_line(sdt, tmp_path):
    """Every (machine, scenario) skipped (one class has a single run): a user error, exit 2.

    Found with the long labels: on main this ended in pandas' "No objects to
    concatenate" traceback after the plan had emptied every recording.
    """
    rng = np.random.default_rng(0)
    lines = [HEADER]
    for condition, runs in (("healthy", 3), ("odd" + "o" * LONG, 1)):
        for index in range(runs):
            name = f"{condition[:3]}{index}"
            np.save(tmp_path / f"{name}.npy", rng.normal(size=40_000))
            lines.append(f"{name}.npy,20000,m,{condition},,{name},ch1\n")
    manifest = tmp_path / "m.csv"
    manifest.write_text("".join(lines))
    done = sdt("benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
               "--classifiers", "lr", "--out", str(tmp_path / "out"))  # fmt: skip
    assert done.returncode == 2
    line = done.stderr.strip()
    assert line.startswith("error: nothing to benchmark: none of the 3 (machine, scenario) pairs")
    assert "no test run for odd" in line and "characters)" in line and len(line) < 600
