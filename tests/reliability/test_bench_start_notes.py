"""What a benchmark says before it starts about settings that will not do what they seem.

From a new user's walk-through: the ``sdt benchmark --help`` example ``--sensors
adxl345,adxl357`` drops the reference, and only at the end did ``sdt compare``
fail and the report say "Not available". A scheduler address given without
``--backend dask`` was silently ignored.
"""

from __future__ import annotations

import re
import shlex

import pytest
import typer

from sdt_framework.cli.main import app

#: the benchmark runs with --jobs 1 (no worker): ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process

ARGS = ["--quick", "--machines", "Motor-2", "--channels", "ch1", "--classifiers", "lr"]


def test_a_reference_left_out_and_an_unused_scheduler_are_said_at_the_start(sdt, tmp_path):
    out = tmp_path / "out"
    done = sdt(
        "benchmark", *ARGS, "--sensors", "adxl345,adxl357", "--scheduler", "tcp://127.0.0.1:8786",
        "--no-report", "--out", str(out), "--jobs", "1",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = done.stderr.splitlines()
    assert lines[0].startswith("note: this benchmark is ")
    assert lines[1:3] == [
        "note: --scheduler tcp://127.0.0.1:8786 is not used: the backend is local; add "
        "--backend dask to send the work there",
        "warning: the reference wilcoxon-786b10 is not among the sensors (adxl345, adxl357): "
        "sdt compare and the report's Verdict compare every sensor with it and will have "
        "nothing to compare with; add it (--sensors wilcoxon-786b10,adxl345,adxl357), or "
        "compare with one of these later (sdt compare OUT --baseline adxl345)",
    ]
    assert (out / "results.csv").exists()  # a warning, not a refusal


def test_every_help_example_naming_sensors_names_the_reference():
    command = typer.main.get_command(app).get_command(None, "benchmark")
    text = command.help.replace("\\[", "[")
    examples = [line.strip() for line in text.splitlines() if "--sensors" in line]
    assert examples, text
    for line in examples:
        tokens = shlex.split(line, comments=True)
        names = re.split(r",(?![^\[]*\])", tokens[tokens.index("--sensors") + 1])
        assert "wilcoxon-786b10" in names, line
