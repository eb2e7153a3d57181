"""The report opens with the decision table and its Edge budget holds each sensor's node table."""

from __future__ import annotations

import shutil

import pandas as pd
import pytest
from sdt_plugins.datasets.pump_rig import rig_machines

from sdt_framework.edge.cells import cell
from sdt_framework.edge.node import NodeSettings, node_budget
from sdt_framework.report.build import build_blocks
from sdt_framework.report.document import Heading, Paragraph, Table
from sdt_framework.report.load import load_results
from sdt_framework.severity import assign_tables


@pytest.fixture(scope="module")
def report(results_master, registry, tmp_path_factory):
    """(folder, loaded results, report blocks) of an intact copy of the small results folder,
    built once: every test here reads the same blocks and none changes them."""
    target = tmp_path_factory.mktemp("decision") / "results"
    shutil.copytree(results_master, target, ignore=shutil.ignore_patterns("runs", "cache"))
    folder = load_results(target)
    return target, folder, build_blocks(folder, registry, target / "figures")


def test_decision_table_opens_the_report_with_one_row_per_candidate(report, registry):
    _, folder, blocks = report
    titles = [b.text for b in blocks if isinstance(b, Heading) and b.level == 2]
    assert titles[0] == "Decision table" and titles[1] == "Verdict"
    at = blocks.index(
        next(b for b in blocks if isinstance(b, Heading) and b.text == "Decision table")
    )
    table = next(b for b in blocks[at:] if isinstance(b, Table))
    assert [row[0] for row in table.rows] == ["adxl345"]  # every sensor but the reference
    _, loss, price, current, payload, life, _zones = table.rows[0]
    assert "**" in loss  # the verdict label
    assert price.startswith("3.92 EUR (part adxl345-ds)")  # the catalogue part's price
    assert current == "140 uA"  # Table 7, 3200 Hz
    assert payload == "96 B"  # paper8: 8 features x float32 x 3 axes
    expected = node_budget(
        registry.sensor("adxl345"),
        registry.feature_set("paper8"),
        cell("2xAA"),
        NodeSettings(window_s=folder.config.window_s),
    )
    assert life == f"{expected.life_years:.2f} y"


def test_edge_budget_holds_a_node_table_per_sensor_or_says_why_not(report):
    _, _, blocks = report
    at = next(
        i for i, b in enumerate(blocks) if isinstance(b, Heading) and b.text.startswith("Node")
    )
    names = [b.text for b in blocks[at:] if isinstance(b, Heading) and b.level == 4]
    assert names == ["wilcoxon-786b10", "adxl345"]
    after = blocks[
        blocks.index(next(b for b in blocks[at:] if getattr(b, "text", "") == "wilcoxon-786b10"))
        + 1
    ]
    assert isinstance(after, Paragraph) and "no measuring supply current" in after.text
    tables = [b for b in blocks[at:] if isinstance(b, Table) and b.header[0] == "consumer"]
    assert len(tables) == 1 and tables[0].rows[-1][0] == "total per report"


def _table_after(blocks, heading: str) -> Table:
    at = blocks.index(next(b for b in blocks if isinstance(b, Heading) and b.text == heading))
    return next(b for b in blocks[at:] if isinstance(b, Table))


def test_decision_zone_agreement_is_the_severity_sections_figure(report):
    """The column equals the "Zone agreement" table's all-channel share, and a count by hand.

    The hand count pairs every adxl345 window of features.parquet with the
    reference's same window and compares zones from the zone table's cuts.
    """
    results_dir, folder, blocks = report
    header = _table_after(blocks, "Decision table").header
    decision = {
        r[0]: r[header.index("zone agreement")] for r in _table_after(blocks, "Decision table").rows
    }
    severity = _table_after(blocks, "Zone agreement")
    pooled = [r for r in severity.rows if r[1] == "all"]  # machine, channel, sensor, table, same
    assert [r[2] for r in pooled] == ["adxl345"]
    assert decision == {"adxl345": f"Motor-2 {pooled[0][4]}"}
    cuts = assign_tables(["Motor-2"], specs=rig_machines())["Motor-2"].table.cuts
    features = pd.read_parquet(results_dir / "features.parquet")
    if "repeat" in features:
        features = features[features["repeat"] == 0]
    key = ["channel", "recording_id", "acquisition", "window"]
    ref = features[features["sensor"] == folder.reference].set_index(key)["V_RMS"]
    mine = features[features["sensor"] == "adxl345"].set_index(key)["V_RMS"]
    both = pd.concat([ref.rename("ref"), mine.rename("mine")], axis=1, join="inner")
    zone_ref = sum((both["ref"] > c).astype(int) for c in cuts)
    zone_mine = sum((both["mine"] > c).astype(int) for c in cuts)
    assert decision["adxl345"] == f"Motor-2 {100 * (zone_ref == zone_mine).mean():.1f} %"
