"""``sdt report SWEEP_FOLDER --out OTHER``: the exploration figures go to OTHER too.

On main the report of an ``sdt explore`` folder drew its four exploration
figures into ``SWEEP_FOLDER/figures`` whatever ``--out`` said: a folder the
user asked only to be read was written into (and a read-only one stopped the
report). They now go to the report's own figures folder, with every other file.
"""

from __future__ import annotations

from sdt_framework import build_registry
from sdt_framework.bench import run_plan_folder
from sdt_framework.explore.output import write_explore
from sdt_framework.explore.run import explore_table, plan_explore
from sdt_framework.explore.sweep_file import parse_sweep
from sdt_framework.report import write_report

from ..helpers import small_protocol

SWEEP = {
    "base": "adxl345",
    "axes": {"noise_density_ug_rthz": {"levels": [90, 290]}},
    "target": {"max_loss": 0.1},
}


def _files(root):
    return {p for p in root.rglob("*") if p.is_file()}


def test_the_report_of_a_sweep_writes_only_into_out(tmp_path):
    protocol = {**small_protocol(repeats=2), "cache_dir": str(tmp_path / "cache")}
    explore = plan_explore(parse_sweep(SWEEP), protocol, {}, build_registry())
    sweep = tmp_path / "sweep"
    table = explore_table(explore, run_plan_folder(explore.plan, sweep).results)
    write_explore(explore, table, sweep)
    before = _files(sweep)

    other = tmp_path / "report"
    written = write_report(sweep, ["md"], out_dir=other)
    assert _files(sweep) == before  # the sweep's folder is only read
    text = written["md"].read_text(encoding="utf-8")
    assert "## Exploration" in text and "(figures/explore_main_effects.png)" in text
    assert (other / "figures" / "explore_main_effects.png").is_file()
