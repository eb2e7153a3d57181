"""``tools.testcpu``: each test's CPU is counted where it was spent, and summed per file.

A test module that burns 0.4 CPU-s in the test itself, one that has a child process
burn it, and one that only sleeps run under the plugin in a fresh pytest; each row
must put the CPU where it was spent (process_time and a child's own clock are the
independent measure), and the summary must rank the file by the sum.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BURN = "import time\nend = time.process_time() + 0.4\nwhile time.process_time() < end:\n    pass\n"
MODULE = f"""
import subprocess, sys, time

def test_burns():
{"".join("    " + line + chr(10) for line in BURN.splitlines())}
def test_child_burns():
    subprocess.run([sys.executable, "-c", {BURN!r}], check=True)

def test_sleeps():
    time.sleep(0.3)
"""


def test_each_tests_cpu_is_counted_where_it_was_spent_and_summed_per_file(tmp_path):
    (tmp_path / "test_costs.py").write_text(MODULE, encoding="utf-8")
    out = tmp_path / "cpu"
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p",
         "tools.testcpu.plugin", f"--test-cpu={out}", str(tmp_path / "test_costs.py")],
        cwd=ROOT, capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert run.returncode == 0, run.stdout + run.stderr
    rows = {r["id"].split("::")[1]: r for r in map(json.loads, (out / "main.jsonl").open())}
    assert set(rows) == {"test_burns", "test_child_burns", "test_sleeps"}
    assert rows["test_burns"]["self"] >= 0.38 and rows["test_burns"]["children"] < 0.1
    assert rows["test_child_burns"]["children"] >= 0.38 and rows["test_child_burns"]["self"] < 0.3
    assert rows["test_sleeps"]["wall"] >= 0.3 and rows["test_sleeps"]["self"] < 0.1

    again = subprocess.run(run.args, cwd=ROOT, capture_output=True, text=True, check=False)
    assert again.returncode == 4 and "holds an earlier run's rows" in again.stderr, again.stderr
    assert len((out / "main.jsonl").read_text().splitlines()) == 3  # nothing added

    summary = subprocess.run(
        [sys.executable, "-m", "tools.testcpu", str(out), "--top", "5"],
        cwd=ROOT, capture_output=True, text=True, check=True,
    )  # fmt: skip
    head, _, first = summary.stdout.splitlines()[:3]
    assert head.startswith("3 tests: CPU ")
    cpu, own, child, _, tests, name = first.split()
    assert name.endswith("test_costs.py") and tests == "3"
    assert abs(float(cpu) - float(own) - float(child)) <= 0.1  # each printed to 0.1 s
    assert float(own) >= 0.38 and float(child) >= 0.38


@pytest.mark.parametrize(
    ("content", "extra", "said"),
    [
        (None, [], "no test rows"),
        ("not json\n", [], "gw0.jsonl:1: not a JSON line"),
        ('{"id": "t.py::a", "self": 1, "children": 0, "wall": 1}\n', ["--top", "0"], "--top 0"),
    ],
)
def test_an_empty_folder_a_damaged_line_or_no_lines_asked_is_one_line_and_exit_2(
    tmp_path, content, extra, said
):
    if content is not None:
        (tmp_path / "gw0.jsonl").write_text(content, encoding="utf-8")
    done = subprocess.run(
        [sys.executable, "-m", "tools.testcpu", str(tmp_path), *extra],
        cwd=ROOT, capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and said in done.stderr
