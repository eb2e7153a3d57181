"""The verdict end to end on a real (small) results folder: storage, report, `sdt compare`."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from sklearn.metrics import f1_score
from typer.testing import CliRunner

from sdt_framework.cli.main import app, main
from sdt_framework.verdict import LABELS, compare

runner = CliRunner()
RUN = ["machine", "scenario", "sensor", "classifier", "repeat"]


def sdt(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sdt_framework", *map(str, args)],
        capture_output=True,
        text=True,
        check=False,
    )


def test_per_recording_counts_reproduce_every_run(results_master):
    results = pd.read_parquet(results_master / "results.parquet")
    counts = pd.read_parquet(results_master / "per_recording.parquet")
    confusion = pd.read_parquet(results_master / "confusion.parquet")
    assert counts["recording_id"].nunique() > 1 and (counts["count"] > 0).all()
    summed = counts.groupby([*RUN, "true", "predicted"])["count"].sum()
    stored = confusion[confusion["count"] > 0].set_index([*RUN, "true", "predicted"])["count"]
    pd.testing.assert_series_equal(summed.sort_index(), stored.sort_index(), check_names=False)
    for key, part in counts.groupby(RUN):
        y_true = np.repeat(part["true"].to_numpy(), part["count"].to_numpy())
        y_pred = np.repeat(part["predicted"].to_numpy(), part["count"].to_numpy())
        run = results.set_index(RUN).loc[key]
        assert f1_score(y_true, y_pred, average="macro", zero_division=0) == run["macro_f1"]


def test_the_report_opens_with_the_decision_table_then_the_verdict(full_report):
    _, written = full_report
    text = written["md"].read_text(encoding="utf-8")
    headings = [line for line in text.splitlines() if line.startswith("## ")]
    assert headings[:2] == ["## Decision table", "## Verdict"]  # issue 34: decision first
    verdict = text.split("## Verdict")[1].split("\n## ")[0]
    assert "adxl345 vs wilcoxon-786b10" in verdict and "Best sensor" in verdict
    assert "Friedman/Nemenyi not computed" in verdict  # two sensors: no ranking
    html = written["html"].read_text(encoding="utf-8")
    assert html.index("<h2>Verdict</h2>") < html.index("<h2>Table 4")


def test_sdt_compare_prints_the_verdict_and_writes_the_table(results_dir):
    result = runner.invoke(app, ["compare", str(results_dir)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    table = pd.read_csv(results_dir / "comparison.csv")
    assert set(table["label"]) <= set(LABELS)
    assert set(table["level"]) == {"cell", "group", "overall"}
    cells = table[table["level"] == "cell"]
    assert len(cells) == 3 * 2  # Motor-2: 3 scenarios x 2 classifiers, adxl345 vs the reference
    assert cells["n_recordings"].notna().all()  # per_recording.parquet was used
    overall = table[table["level"] == "overall"].iloc[0]
    out = result.stdout
    assert "Verdict" in out and f"Δ {overall['delta']:+.3f}" in out
    first = cells.iloc[0]
    assert f"{first['label']} {first['delta']:+.3f}" in out


def test_sdt_compare_json(results_dir):
    result = runner.invoke(app, ["compare", str(results_dir), "--margin", "0.05", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["baseline"] == "wilcoxon-786b10" and data["margin"] == 0.05
    assert data["ranking"] is None and data["verdict"]
    assert {row["candidate"] for row in data["table"]} == {"adxl345"}


def test_two_copies_of_one_folder_are_equivalent(results_dir, tmp_path):
    other = tmp_path / "copy"
    shutil.copytree(results_dir, other)
    result = runner.invoke(app, ["compare", str(results_dir), str(other), "--json"])
    assert result.exit_code == 0, result.output
    table = pd.DataFrame(json.loads(result.stdout)["table"])
    assert set(table["label"]) == {"equivalent"} and (table["delta"] == 0).all()
    cells = table[table["level"] == "cell"]
    assert (cells["rec_ci_low"] == 0).all() and (cells["rec_ci_high"] == 0).all()
    assert (other / f"comparison_vs_{results_dir.name}.csv").is_file()


def test_a_folder_without_per_recording_counts_still_compares(results_dir):
    (results_dir / "per_recording.parquet").unlink()
    result = runner.invoke(app, ["compare", str(results_dir), "--json"])
    assert result.exit_code == 0, result.output
    table = pd.DataFrame(json.loads(result.stdout)["table"])
    assert table["rec_ci_low"].isna().all()
    decided = table[table["label"] != "inconclusive"]
    assert all("repetition CI only" in r for r in decided["reason"])


def test_bad_input_is_one_line_and_exit_2(results_dir, tmp_path, monkeypatch, capsys):
    moved = tmp_path / "moved"
    shutil.copytree(results_dir, moved)
    frame = pd.read_parquet(moved / "results.parquet")
    frame.assign(machine="Motor-9").to_parquet(moved / "results.parquet")  # nothing in common
    counts = pd.read_parquet(moved / "per_recording.parquet")  # kept matching its results
    counts.assign(machine="Motor-9").to_parquet(moved / "per_recording.parquet")
    cases = [
        (["compare", tmp_path / "missing"], "not a results folder"),
        (["compare", results_dir, "--baseline", "adxl999"], "baseline 'adxl999'"),
        (["compare", results_dir, "--margin", "0"], "margin must be"),
        (["compare", results_dir, moved], "nothing to pair"),
    ]
    for args, message in cases:  # in-process through the real entry point
        monkeypatch.setattr(sys, "argv", ["sdt", *map(str, args)])
        with pytest.raises(SystemExit) as stop:
            main()
        err = capsys.readouterr().err
        lines = [line for line in err.splitlines() if line.strip()]
        assert stop.value.code == 2, (args, err)
        assert len(lines) == 1 and lines[0].startswith("error: ") and message in lines[0], lines
    result = sdt("compare", tmp_path / "missing")  # and once as a user runs it
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert result.stderr.strip().startswith("error: ") and "not a results folder" in result.stderr


def test_verdict_section_with_three_sensors_draws_the_cd_diagram(results_dir, tmp_path):
    from sdt_framework.report.document import Figure, Items
    from sdt_framework.report.load import load_results
    from sdt_framework.report.verdict import verdict_blocks

    results = pd.read_parquet(results_dir / "results.parquet")
    third = results[results["sensor"] == "adxl345"].assign(
        sensor="adxl345-worse", macro_f1=lambda f: f["macro_f1"] - 0.2
    )
    pd.concat([results, third]).to_parquet(results_dir / "results.parquet")
    blocks = verdict_blocks(load_results(results_dir), {}, tmp_path / "figures")
    figure = next(b for b in blocks if isinstance(b, Figure))
    assert figure.path.is_file() and figure.path.stat().st_size > 5000
    items = next(b for b in blocks if isinstance(b, Items)).items
    ranking = next(i for i in items if i.startswith("**ranking**"))
    # the made-up sensor's average rank, recomputed here with pandas: last in every block
    # where the reference is not 0.2 below the ADXL345 (the data decides, not the test)
    both = pd.concat([results, third])
    means = both.groupby(["machine", "scenario", "classifier", "sensor"])["macro_f1"].mean()
    expected = means.unstack("sensor").rank(axis=1, ascending=False)["adxl345-worse"].mean()
    assert expected > 2.5  # it is last in most blocks, so the ranking must show it low
    assert "3 sensors" in ranking and f"adxl345-worse {expected:.2f}" in ranking
    # paired differences shift by exactly -0.2; the made-up sensor has no per-recording counts
    table = compare(load_results(results_dir).results, "wilcoxon-786b10").table
    overall = table[table["level"] == "overall"].set_index("candidate")
    assert overall.loc["adxl345-worse", "delta"] == pytest.approx(
        overall.loc["adxl345", "delta"] - 0.2
    )
    text = next(i for i in items if i.startswith("**overall, adxl345-worse**"))
    assert f"Δ {overall.loc['adxl345-worse', 'delta']:+.3f}" in text


def test_verdict_section_says_why_when_the_reference_is_missing(results_dir, tmp_path):
    from sdt_framework.report.document import Paragraph
    from sdt_framework.report.load import load_results
    from sdt_framework.report.verdict import verdict_blocks

    results = pd.read_parquet(results_dir / "results.parquet")
    results[results["sensor"] != "wilcoxon-786b10"].to_parquet(results_dir / "results.parquet")
    blocks = verdict_blocks(load_results(results_dir), {}, tmp_path)
    assert isinstance(blocks[1], Paragraph)
    assert blocks[1].text.startswith(
        "Not available: the reference wilcoxon-786b10 was not among the benchmark's sensors"
    )
    assert "choose --baseline" not in blocks[1].text  # an option only `sdt compare` has
