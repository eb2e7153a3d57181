"""A benchmark whose --sensors leaves the reference out: the report says why its verdict and
delta sections are absent and suggests commands that exist (before: "choose --baseline from
[...]", an option only `sdt compare` has, and a delta section that just said "Not shown")."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

CONFIG = """\
[benchmark]
sensors = ["adxl345", "adxl357"]
classifiers = ["lr"]
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
scenarios = ["interpolation"]
repeats = 2
dataset_options = { duration = 1.5 }
"""


def _sdt(*args: str, cwd) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sdt_framework", *map(str, args)],
        capture_output=True,
        text=True,
        check=False,
        cwd=cwd,
    )


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory):
    """`sdt benchmark small.toml --out res` (default --jobs, with the report), no reference."""
    root = tmp_path_factory.mktemp("noref")
    (root / "small.toml").write_text(CONFIG)
    run = _sdt("benchmark", "small.toml", "--out", "res", "--cache-dir", "cache", cwd=root)
    assert run.returncode == 0, run.stderr
    return root


def _sections(text: str) -> dict[str, str]:
    parts = re.split(r"^## ", text, flags=re.M)[1:]
    return {p.split("\n", 1)[0]: p.split("\n", 1)[1] for p in parts}


def _notes(report_md) -> list[str]:
    sections = _sections(report_md.read_text(encoding="utf-8"))
    notes = [sections[n] for n in ("Verdict", "Delta to the reference (wilcoxon-786b10)")]
    for body in notes:
        assert "the reference wilcoxon-786b10 was not among the benchmark's sensors" in body
        assert "adxl345, adxl357" in body  # what the folder holds
        assert "`sdt benchmark --sensors wilcoxon-786b10,adxl345,adxl357 --out NEW_FOLDER`" in body
        assert "choose --baseline" not in body
    return notes


def test_benchmark_report_says_why_and_what_to_run(folder):
    notes = _notes(folder / "res" / "report.md")
    # the compare command it suggests runs as printed
    command = re.search(r"`sdt (compare [^`]+)`", notes[0]).group(1).split()
    assert command[-2:] == ["--baseline", "adxl345"]
    ran = _sdt(*command, "--out", "cmp", cwd=folder)
    assert ran.returncode == 0, ran.stderr
    assert "adxl357 vs adxl345" in ran.stdout


def test_sdt_report_says_the_same(folder):
    run = _sdt("report", "res", "--format", "md", "--out", "again", cwd=folder)
    assert run.returncode == 0, run.stderr
    assert _notes(folder / "again" / "report.md") == _notes(folder / "res" / "report.md")
