"""The report opens with the decision table and its Edge budget holds each sensor's node table."""

from __future__ import annotations

from sdt_framework.edge.cells import cell
from sdt_framework.edge.node import NodeSettings, node_budget
from sdt_framework.report.build import build_blocks
from sdt_framework.report.document import Heading, Paragraph, Table
from sdt_framework.report.load import load_results


def test_decision_table_opens_the_report_with_one_row_per_candidate(results_dir, registry):
    folder = load_results(results_dir)
    blocks = build_blocks(folder, registry, results_dir / "figures")
    titles = [b.text for b in blocks if isinstance(b, Heading) and b.level == 2]
    assert titles[0] == "Decision table" and titles[1] == "Verdict"
    at = blocks.index(
        next(b for b in blocks if isinstance(b, Heading) and b.text == "Decision table")
    )
    table = next(b for b in blocks[at:] if isinstance(b, Table))
    assert [row[0] for row in table.rows] == ["adxl345"]  # every sensor but the reference
    _, loss, price, current, payload, life = table.rows[0]
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


def test_edge_budget_holds_a_node_table_per_sensor_or_says_why_not(results_dir, registry):
    folder = load_results(results_dir)
    blocks = build_blocks(folder, registry, results_dir / "figures")
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
