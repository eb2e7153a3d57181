"""Every design point is in points.csv or, with its reason, in skipped_points.csv.

On main before round 2 a rate level above the data's rate was left out of the
benchmark (one "skipped sensor" line) but stayed in points.csv and never
reached skipped_points.csv; a level of ``inf`` for the range or the noise was
run and ended mid-benchmark with a non-finite signal after the folder was
claimed. Non-finite levels are now refused when the sweep file is read, in one
line naming the level (tests/reliability/test_cli_errors_round2.py), before any
design is built; a level the data cannot feed is a skipped point.
"""

from __future__ import annotations

import re
import textwrap

import pandas as pd
import pytest
from sdt_plugins.datasets.synthetic_pump.dataset import GENERATOR

from ..helpers import EXPLORE_BENCHMARK

SWEEP = (
    """
[sweep]
base = "adxl345"
[sweep.axes]
sampling_rate_hz = { levels = [800, 40000] }
full_scale_g = { levels = [16, 8] }
[sweep.ties]
digital_cutoff_hz = "0.4 * rate"
"""
    + EXPLORE_BENCHMARK
    + "jobs = 1\n"
)


def test_every_skipped_point_is_written_with_its_reason(sdt_main, tmp_path):
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(textwrap.dedent(SWEEP))
    out = tmp_path / "out"
    code, _, err = sdt_main("explore", str(sweep), "--out", str(out), "--no-report")
    assert code == 0, err
    points = pd.read_csv(out / "points.csv")
    skipped = pd.read_csv(out / "skipped_points.csv")
    # 2 x 2 grid: only rate 800 is a sensor the 20 kHz data can feed
    assert list(points["point"]) == ["adxl345~rate=800,range=16", "adxl345~rate=800,range=8"]
    assert sorted(skipped["design_index"]) == [2, 3]
    reasons = dict(zip(skipped["point"], skipped["reason"], strict=True))
    for full_scale in (16, 8):
        name = f"adxl345~rate=4e+04,range={full_scale}"
        assert reasons[name] == (
            f"sensor '{name}' samples at 40000 Hz, above the data's 20000 Hz "
            f"(e.g. synthetic (generator {GENERATOR}))"
        )
    # each skipped point is said once, as a point (not again as a skipped sensor)
    assert err.count("skipped point ") == 2 and "skipped sensor adxl345~" not in err
    results = pd.read_csv(out / "results.csv")
    assert set(results["sensor"]) == {
        "wilcoxon-786b10",
        "adxl345",
        "adxl345~rate=800,range=16",
        "adxl345~rate=800,range=8",
    }


def test_non_finite_levels_are_refused_before_any_design(registry):
    from sdt_framework.errors import SpecFileError
    from sdt_framework.explore.sweep_file import parse_sweep

    for level in (float("nan"), float("inf")):
        with pytest.raises(
            SpecFileError, match=re.escape("levels.0': Input should be a finite number")
        ):
            parse_sweep({"base": "adxl345", "axes": {"sampling_rate_hz": {"levels": [level]}}})
