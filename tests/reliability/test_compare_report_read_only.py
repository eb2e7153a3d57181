"""``sdt compare`` and ``sdt report`` read a folder they cannot write, and write elsewhere.

A colleague's results, a read-only mount or an archive: the folder is read as
usual, ``--out`` takes what the command writes; without ``--out`` one line
says to add it (exit 2), before any work. The folder is made read-only with
its mode for an ordinary user and with the immutable attribute for root, whom
modes do not stop.
"""

from __future__ import annotations

import os
import shutil
import subprocess

import pytest

from sdt_framework import build_registry
from sdt_framework.bench import BenchmarkConfig, run_benchmark_folder

from .conftest import SMALL


@pytest.fixture
def locked(tmp_path):
    """A small results folder nobody can create files in (removed from the lock afterwards)."""
    folder = tmp_path / "archive"
    config = BenchmarkConfig(
        **{**SMALL, "sensors": ["wilcoxon-786b10", "adxl345"], "classifiers": ["lr"]},
        cache_dir=str(tmp_path / "cache"),
    )
    run_benchmark_folder(config, build_registry(), folder)
    shutil.rmtree(folder / "runs")  # an archived copy: the outputs only
    if os.geteuid() == 0:
        subprocess.run(["chattr", "+i", str(folder)], check=True)
    else:
        folder.chmod(0o555)
    try:
        (folder / "probe").touch()
        pytest.fail("the folder should not be writable")
    except OSError:
        pass
    yield folder
    if os.geteuid() == 0:
        subprocess.run(["chattr", "-i", str(folder)], check=True)
    else:
        folder.chmod(0o755)


def one_error_line(code: int, err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def test_compare_on_a_read_only_folder_writes_to_out_or_says_how(locked, tmp_path, sdt_main):
    before = sorted(p.name for p in locked.iterdir())
    line = one_error_line(*sdt_main("compare", str(locked))[::2])
    assert line.startswith(f"error: cannot write the comparison table into {locked} (")
    assert line.endswith("add --out OTHER_FOLDER to write it elsewhere")

    code, out, err = sdt_main("compare", str(locked), "--out", str(tmp_path / "verdict"))
    assert code == 0, err
    assert (tmp_path / "verdict" / "comparison.csv").is_file()
    assert f"comparison table: {tmp_path / 'verdict' / 'comparison.csv'}" in out
    assert sorted(p.name for p in locked.iterdir()) == before


def test_report_on_a_read_only_folder_writes_to_out_or_says_how(locked, tmp_path, sdt_main):
    line = one_error_line(*sdt_main("report", str(locked), "--format", "md")[::2])
    assert line.startswith(f"error: cannot write the report into {locked} (")
    assert "add --out OTHER_FOLDER" in line

    target = tmp_path / "report"
    code, _, err = sdt_main("report", str(locked), "--format", "md", "--out", str(target))
    assert code == 0, err
    text = (target / "report.md").read_text()
    assert "Benchmark report: archive" in text and "figures/" in text
    assert list((target / "figures").glob("*.png"))
    assert not (locked / "report.md").exists()
