"""write_report / `sdt report` on a real (small) results folder, intact and damaged."""

from __future__ import annotations

import re
from pathlib import Path

import pandas as pd
import pytest

from sdt_framework import SDTError
from sdt_framework.report import write_report
from sdt_framework.report.figures import FIGURES

from .conftest import assert_real_png

PNGS = [name for name, _ in FIGURES.values()]


def _written_pngs(folder: Path) -> list[str]:
    """The PNG files the report wrote into ``figures/``."""
    return [p.name for p in (folder / "figures").glob("*.png")]


def test_every_figure_is_a_real_png(full_report):
    folder, _ = full_report
    for name in PNGS:
        assert_real_png(folder / "figures" / name)


def test_markdown_links_every_figure_and_holds_the_tables(full_report):
    folder, written = full_report
    assert written["md"] == folder / "report.md"
    text = written["md"].read_text(encoding="utf-8")
    links = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", text)
    # the paper's figures, and every figure written (the severity section adds its spectra)
    assert set(PNGS) <= {Path(link).name for link in links}
    assert sorted(Path(link).name for link in links) == sorted(_written_pngs(folder))
    for link in links:
        assert not Path(link).is_absolute() and (folder / link).is_file()
    assert "Not drawn" not in text
    # Table 4 and the delta table carry the real numbers of results.parquet
    results = pd.read_parquet(folder / "results.parquet")
    cell = results.query("scenario == 'forward' and sensor == 'adxl345' and classifier == 'lr'")
    assert f"{cell['macro_f1'].mean():.4f} ± {cell['macro_f1'].std():.4f}" in text
    ref = results.query(
        "scenario == 'forward' and sensor == 'wilcoxon-786b10' and classifier == 'lr'"
    )["macro_f1"].mean()
    assert f"{cell['macro_f1'].mean() - ref:+.4f}" in text
    for section in (
        "Experiment A. Forward extrapolation",
        "Train/test allocation",
        "Configuration (config.toml)",
        "Software",
        "Timing",
        "repeats = 2",
    ):
        assert section in text, section


def test_html_is_self_contained(full_report):
    _, written = full_report
    page = written["html"].read_text(encoding="utf-8")
    assert page.count('src="data:image/png;base64,') == len(_written_pngs(written["md"].parent))
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", page)
    assert "<link" not in page and "<script" not in page
    assert "<table>" in page and "<strong>" in page  # best cells in bold


def test_missing_files_are_reported_not_fatal(results_dir, registry):
    for name in ("features.parquet", "confusion.parquet", "config.toml", "summary.json"):
        (results_dir / name).unlink()
    written = write_report(results_dir, ["md"], registry=registry)
    assert set(written) == {"md"} and not (results_dir / "report.html").exists()
    text = written["md"].read_text(encoding="utf-8")
    for name in ("features.parquet", "confusion.parquet", "config.toml", "summary.json"):
        assert f"{name} is missing" in text
    assert text.count("Not drawn:") == 3  # Fig. 2 (no config), Fig. 3, Fig. 7
    assert_real_png(results_dir / "figures" / "fig6_radar.png")  # per_class is still there
    assert_real_png(results_dir / "figures" / "fig4_noise.png")  # sensors come from results


def test_failed_runs_are_listed_with_their_errors(results_dir, registry):
    results = pd.read_parquet(results_dir / "results.parquet")
    bad = (results["sensor"] == "adxl345") & (results["classifier"] == "knn")
    results.loc[bad, "status"] = "error"
    results.loc[bad, "error"] = "ValueError: the knn broke\ntraceback line"
    results.loc[bad, "macro_f1"] = float("nan")
    results.to_parquet(results_dir / "results.parquet")
    text = write_report(results_dir, registry=registry)["md"].read_text(encoding="utf-8")
    assert "## Failed runs" in text
    assert text.count("ValueError: the knn broke") == int(bad.sum())
    assert "traceback line" not in text
    assert f"{int(bad.sum())} failed run(s)" in text


def test_all_runs_failed_still_gives_a_report(results_dir, registry):
    results = pd.read_parquet(results_dir / "results.parquet")
    results["status"], results["error"] = "error", "boom"
    results.to_parquet(results_dir / "results.parquet")
    text = write_report(results_dir, registry=registry)["md"].read_text(encoding="utf-8")
    assert "No successful runs" in text and "has no successful run" in text


@pytest.mark.parametrize("case", ["no-folder", "a-file", "no-results"])
def test_unusable_folder_is_one_clear_error(tmp_path, case):
    target = tmp_path / "x"
    if case == "a-file":
        target.write_text("not a folder")
    elif case == "no-results":
        target.mkdir()
        (target / "config.toml").write_text("[benchmark]\n")
    with pytest.raises(SDTError, match=re.escape(str(target))):
        write_report(target)


def test_unknown_format_is_refused_before_any_work(results_dir):
    with pytest.raises(SDTError, match="pdf"):
        write_report(results_dir, ["md", "pdf"])
    assert not (results_dir / "figures").exists()


def test_cli_report_and_errors(results_dir, tmp_path, sdt_in_process, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sdt = sdt_in_process  # the entry point, in this process: a report starts no benchmark
    done = sdt("report", str(results_dir), "--format", "html")
    assert done.returncode == 0, done.stderr
    assert (results_dir / "report.html").is_file() and not (results_dir / "report.md").exists()
    assert "report.html" in done.stdout
    missing = sdt("report", str(tmp_path / "nowhere"))
    assert missing.returncode == 2
    assert missing.stderr.strip().count("\n") == 0 and "nowhere" in missing.stderr
