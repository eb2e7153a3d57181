"""`sdt compare --json` and the report carry the zone agreement, checked from features.parquet."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sdt_framework.cli.main import app
from sdt_framework.labels import slug

from .conftest import assert_real_png

runner = CliRunner()
LOW = (0.71, 1.8, 4.5)  # ISO 20816-1 Table C.1, low end: the default for Motor-2


def test_compare_json_zone_agreement_matches_features_parquet(results_dir) -> None:
    result = runner.invoke(app, ["compare", str(results_dir), "--json"])
    assert result.exit_code == 0, result.output
    severity = json.loads(result.stdout)["severity"]
    assert severity["tables"]["Motor-2"]["name"] == "iso20816-1-typical-low"
    assert "Table C.1" in severity["tables"]["Motor-2"]["source"]
    # independent: pair the windows, grade both V_RMS with explicit comparisons
    f = pd.read_parquet(results_dir / "features.parquet")
    keys = ["machine", "channel", "recording_id", "acquisition", "window"]
    ref = f[f["sensor"] == "wilcoxon-786b10"][[*keys, "V_RMS"]]
    mems = f[f["sensor"] == "adxl345"][[*keys, "V_RMS"]]
    pairs = mems.merge(ref, on=keys, suffixes=("_s", "_r"))

    def zone(v):
        return np.select([v <= LOW[0], v <= LOW[1], v <= LOW[2]], [0, 1, 2], 3)

    same = zone(pairs["V_RMS_s"].to_numpy(float)) == zone(pairs["V_RMS_r"].to_numpy(float))
    better = zone(pairs["V_RMS_s"].to_numpy(float)) < zone(pairs["V_RMS_r"].to_numpy(float))
    rows = {(z["channel"], z["sensor"]): z for z in severity["zones"]}
    pooled = rows[("all", "adxl345")]
    assert pooled["share_same"] == pytest.approx(same.mean())
    assert pooled["share_better"] == pytest.approx(better.mean())
    assert pooled["n_windows"] == len(pairs)
    assert pooled["ci_low"] <= pooled["share_same"] <= pooled["ci_high"]
    for channel in ("ch1", "ch4"):
        mine = (pairs["channel"] == channel).to_numpy()
        assert rows[(channel, "adxl345")]["share_same"] == pytest.approx(same[mine].mean())


def test_compare_text_names_the_zone_table(results_dir) -> None:
    result = runner.invoke(app, ["compare", str(results_dir)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    assert "ISO zones of V_RMS (10-1000 Hz) against wilcoxon-786b10" in result.stdout
    assert "Motor-2 zone table: iso20816-1-typical-low (ISO 20816-1:2016" in result.stdout
    assert "the pump end (ch4, ch5) is graded by the same table as a proxy" in result.stdout
    assert "alarms: criterion II (ISO 10816-3:2009 5.3, 5.4.1, 5.4.2)" in result.stdout
    assert "ISO zone per condition" in result.stdout


def test_report_has_the_severity_section_and_captioned_spectra(full_report) -> None:
    folder, written = full_report
    text = written["md"].read_text(encoding="utf-8")
    section = text[text.index("## Severity and alarms") :]
    assert "### Zone agreement" in section and "iso20816-1-typical-low" in section
    # criterion II's clauses are ISO 10816-3:2009's (5.3, 5.4.1, 5.4.2), not ISO 20816-1's
    assert "### Alarms (criterion II, ISO 10816-3:2009 5.3, 5.4.1, 5.4.2)" in section
    assert "### Zone per condition" in section
    # ch4 is in the small folder: the pump bearing's envelope (6308 lines) is drawn
    assert_real_png(folder / "figures" / f"{slug('envelope', 'Motor-2', 'bearing pump')}.png")
    caption = next(line for line in section.splitlines() if "6308 lines" in line and line[0] == "*")
    for words in ("one-sided peak amplitude", "flat-top window", "RBW", "unit gE", "2×BSF"):
        assert words in caption
    assert "What each envelope band holds" in caption and "adxl345: " in caption
    assert_real_png(folder / "figures" / f"{slug('velocity', 'Motor-2')}.png")
    assert_real_png(folder / "figures" / f"{slug('levels', 'Motor-2')}.png")
    assert "ASD by fault level" in section and "severity waterfall" not in section


def test_compare_json_zone_per_condition_matches_features_parquet(results_dir) -> None:
    # issue 40, item 8: "condition X: reference zone A, ADXL345 zone B", from the windows
    result = runner.invoke(app, ["compare", str(results_dir), "--json"])
    assert result.exit_code == 0, result.output
    rows = json.loads(result.stdout)["severity"]["conditions"]
    f = pd.read_parquet(results_dir / "features.parquet")
    for sensor in ("wilcoxon-786b10", "adxl345"):
        mine = f[
            (f["sensor"] == sensor) & (f["condition"] == "bearing bpfo") & (f["severity"] == 3)
        ]
        medians = mine.groupby("channel")["V_RMS"].median()
        worst = medians.idxmax()
        v = float(medians[worst])
        zone = "ABCD"[int(np.select([v <= LOW[0], v <= LOW[1], v <= LOW[2]], [0, 1, 2], 3))]
        (row,) = [
            r
            for r in rows
            if r["sensor"] == sensor
            and r["channel"] == "all"
            and r["condition"] == "bearing bpfo"
            and r["severity"] == 3
        ]
        assert (row["from_channel"], row["zone"]) == (worst, zone)
        assert row["v_rms"] == pytest.approx(v)
