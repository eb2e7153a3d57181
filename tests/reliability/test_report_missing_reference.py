"""A benchmark whose --sensors leaves the reference out: the report says why its verdict and
delta sections are absent and suggests commands that exist (before: "choose --baseline from
[...]", an option only `sdt compare` has, and a delta section that just said "Not shown").

Every command runs through sdt's entry point in this process (the report's subject is its
text, not workers or signals): the benchmark with ``--jobs 1`` (its results are the same at
any --jobs, test_bench_jobs.py) and the figures drawn here whatever the cores."""

from __future__ import annotations

import contextlib
import io
import re

import pytest

from ..helpers import entry_status

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


#: the report draws its figures in this process (as on a machine of fewer than 4 cores)
ONE_PROCESS_FIGURES = ("sdt_framework.report.figures.PARALLEL_FROM_CORES", 10**6)


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory):
    """`sdt benchmark small.toml --out res --jobs 1` (with the report), no reference; run once
    for the module through the entry point in this process (``sdt_in_process`` is per test)."""
    root = tmp_path_factory.mktemp("noref")
    (root / "small.toml").write_text(CONFIG)
    args = ["benchmark", "small.toml", "--out", "res", "--cache-dir", "cache", "--jobs", "1"]
    err = io.StringIO()
    with pytest.MonkeyPatch.context() as patch, contextlib.redirect_stdout(io.StringIO()):
        patch.chdir(root)
        patch.setattr(*ONE_PROCESS_FIGURES)
        with contextlib.redirect_stderr(err):
            code = entry_status(args, patch)
    assert code == 0, err.getvalue()
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


def test_benchmark_report_says_why_and_what_to_run(folder, sdt_in_process, monkeypatch):
    notes = _notes(folder / "res" / "report.md")
    # the compare command it suggests runs as printed
    command = re.search(r"`sdt (compare [^`]+)`", notes[0]).group(1).split()
    assert command[-2:] == ["--baseline", "adxl345"]
    monkeypatch.chdir(folder)
    ran = sdt_in_process(*command, "--out", "cmp")
    assert ran.returncode == 0, ran.stderr
    assert "adxl357 vs adxl345" in ran.stdout


def test_sdt_report_says_the_same(folder, sdt_in_process, monkeypatch):
    monkeypatch.chdir(folder)
    monkeypatch.setattr(*ONE_PROCESS_FIGURES)
    run = sdt_in_process("report", "res", "--format", "md", "--out", "again")
    assert run.returncode == 0, run.stderr
    assert _notes(folder / "again" / "report.md") == _notes(folder / "res" / "report.md")
