"""Table 4 is built once as data; its Markdown, the report's table and the cells agree."""

from __future__ import annotations

import numpy as np
import pandas as pd

from sdt_framework.bench.table4 import NOTE, build_table4, table4_markdown
from sdt_framework.report.tables import table4_table

SENSORS = ["ref", "mems", "ref -> mems", "mems @ node1"]


def _results() -> pd.DataFrame:
    """Three repetitions per cell, one where only one run succeeded, and a failed column."""
    rows = []
    for scenario in ("forward", "backward"):
        for s, sensor in enumerate(SENSORS):
            for c, classifier in enumerate(("rf", "svm")):
                for repeat in range(3):
                    failed = sensor == "mems" and classifier == "svm" and scenario == "forward"
                    lonely = sensor == "ref -> mems" and classifier == "rf" and repeat > 0
                    rows.append(
                        {
                            "machine": "pump",
                            "scenario": scenario,
                            "sensor": sensor,
                            "classifier": classifier,
                            "macro_f1": 0.5 + 0.1 * s + 0.01 * c + 0.02 * repeat,
                            "status": "failed" if failed or lonely else "ok",
                        }
                    )
    return pd.DataFrame(rows)


def _pipe_rows(text: str) -> list[list[str]]:
    """The cells of a pipe table, separator line left out."""
    rows = []
    for line in text.splitlines():
        if line.startswith("|") and not set(line) <= set("|-"):
            rows.append([cell.strip() for cell in line.strip().strip("|").split("|")])
    return rows


def test_cells_hold_mean_and_sample_sd_of_the_successful_runs():
    results = _results()
    table = build_table4(results, SENSORS)
    assert table.columns == (("pump", "rf"), ("pump", "svm"))
    assert [b.scenario for b in table.blocks] == ["forward", "backward"]
    forward = table.blocks[0]
    assert forward.sensors == tuple(SENSORS)
    ok = results[(results["status"] == "ok") & (results["scenario"] == "forward")]
    for sensor, row in zip(forward.sensors, forward.cells, strict=True):
        for (_, classifier), cell in zip(table.columns, row, strict=True):
            values = ok[(ok["sensor"] == sensor) & (ok["classifier"] == classifier)]["macro_f1"]
            if values.empty:
                assert np.isnan(cell.mean) and cell.text() == "–"
                continue
            assert cell.mean == values.mean() and cell.n == len(values)
            if len(values) > 1:
                assert np.isclose(cell.sd, np.std(values.to_numpy(), ddof=1))
    # best mean per column within the block: the node row (s = 3) in both columns
    assert [row[0].best for row in forward.cells] == [False, False, False, True]


def test_markdown_and_report_table_show_the_same_rows():
    table = build_table4(_results(), SENSORS)
    text = table4_markdown(table)
    report = table4_table(_results(), SENSORS)
    rows = _pipe_rows(text)
    assert tuple(rows[0]) == report.header == ("Sensor", "pump RF", "pump SVM")
    assert [tuple(r) for r in rows[1:]] == list(report.rows)
    assert report.note == NOTE and text.endswith("\n" + NOTE + "\n")
    assert rows[1] == ["**Experiment A. Forward extrapolation**", "", ""]
    assert rows[3][0] == "mems" and rows[3][2] == "–"
    assert rows[4] == ["ref -> mems", "0.7000", "0.7300 ± 0.0200"]
    assert rows[5][0] == "mems @ node1" and rows[5][1] == "**0.8200 ± 0.0200**"


def test_no_successful_run_is_one_line():
    failed = _results().assign(status="failed")
    assert table4_markdown(build_table4(failed)) == "_No successful runs: nothing to tabulate._\n"
    assert table4_table(failed, SENSORS).rows == (("_No successful runs: nothing to tabulate._",),)
