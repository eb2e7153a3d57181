"""A run whose feature set holds no V_RMS (``orders``) is told why no window is graded.

The ISO zones grade each window's velocity RMS, a paper8 feature. Before, the report's
severity section and ``sdt compare`` said "features.parquet with V_RMS is missing", as
if a file were lost; now they say the run's feature set does not compute it and what
to run instead (issue 43).
"""

from __future__ import annotations

from typer.testing import CliRunner

from sdt_framework.cli.main import app


def test_an_orders_run_says_its_set_holds_no_vrms(tmp_path) -> None:
    out = tmp_path / "out"
    runner = CliRunner()
    run = runner.invoke(
        app,
        ["benchmark", "--quick", "--features", "orders", "--machines", "Motor-2",
         "--channels", "ch1", "--sensors", "wilcoxon-786b10,adxl345", "--classifiers", "lr",
         "--scenarios", "forward", "--repeats", "1", "--jobs", "1",
         "--out", str(out), "--cache-dir", str(tmp_path / "cache")],
        env={"COLUMNS": "200"},
    )  # fmt: skip
    assert run.exit_code == 0, run.output
    report = (out / "report.md").read_text(encoding="utf-8")
    # report.md escapes Markdown in text: V\_RMS
    assert "Not shown: features.parquet holds no V\\_RMS (this run's feature set does not" in report
    assert "is missing" not in report
    compare = runner.invoke(app, ["compare", str(out)], env={"COLUMNS": "200"})
    assert compare.exit_code == 0, compare.output
    assert "--features paper8+orders) to grade the windows: no zone agreement" in compare.output
