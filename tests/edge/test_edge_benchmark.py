"""The benchmark rounds features to the on-node dtype; the report shows the edge budget."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework import SDTError
from sdt_framework.bench import BenchmarkConfig, load_config, plan_benchmark, run_benchmark_folder
from sdt_framework.report import build as report_build
from sdt_framework.report.load import load_results
from sdt_framework.report.render import render_markdown

#: the smallest useful benchmark: Motor-2, one channel, one MEMS sensor, one classifier
TINY = {
    "dataset_options": {"duration": 1.5},
    "machines": ["Motor-2"],
    "channels": ["ch1"],
    "sensors": ["adxl345"],
    "classifiers": ["lr"],
    "repeats": 1,
    "jobs": 1,
    "report": False,
}
NAMES = ["sigma", "S", "K", "CF", "A_RMS", "A_Peak", "V_RMS", "D_RMS"]


@pytest.fixture(scope="module")
def runs(tmp_path_factory, registry):
    """Results folders of the same tiny benchmark with float32 and float16 features."""
    root = tmp_path_factory.mktemp("dtype")
    out = {}
    for dtype in ("float32", "float16"):
        config = BenchmarkConfig(**TINY, cache_dir=str(root / "cache"), feature_dtype=dtype)
        folder = root / dtype
        out[dtype] = (run_benchmark_folder(config, registry, folder).result, folder)
    return out


def test_float16_features_are_the_float32_ones_rounded(runs):
    f32 = runs["float32"][0].features[NAMES].to_numpy()
    f16 = runs["float16"][0].features[NAMES].to_numpy()
    np.testing.assert_array_equal(f16, f32.astype(np.float16).astype(np.float32))
    assert not np.array_equal(f16, f32)


def test_float16_runs_have_their_own_keys_and_scores(runs):
    keys32 = {r.key for r in runs["float32"][0].runs}
    keys16 = {r.key for r in runs["float16"][0].runs}
    assert keys32.isdisjoint(keys16)  # never resumed from one another
    assert all(r.status == "ok" for r in runs["float16"][0].runs)


def test_feature_dtype_is_written_to_config_and_validated(runs, tmp_path):
    folder = runs["float16"][1]
    assert 'feature_dtype = "float16"' in (folder / "config.toml").read_text()
    assert load_config(folder / "config.toml", {}).feature_dtype == "float16"
    with pytest.raises(SDTError, match="feature_dtype"):
        load_config(None, {"feature_dtype": "float8"})


def test_default_config_does_not_mention_feature_dtype(tmp_path, registry):
    config = BenchmarkConfig(**TINY)
    assert config.feature_dtype is None
    assert plan_benchmark(config, registry).feature_set.dtype == "float32"


def test_report_has_an_edge_budget_section(runs, registry, tmp_path, monkeypatch):
    monkeypatch.setattr(report_build, "draw_figures", lambda *args: [])
    folder = load_results(runs["float16"][1])
    text = render_markdown(report_build.build_blocks(folder, registry, tmp_path), tmp_path)
    section = text[text.index("## Edge budget") : text.index("## Figures")]
    assert "### EU868" in section and "### US915" in section
    assert "16 B/axis x 3 axes = 48 B per report" in section
    assert "| DR0 | SF12/125 | 51 | yes | 1 |" in section  # 48 B fit SF12 in one uplink
    assert "Sent as float32, a report would be 96 B instead of 48 B" in section
    assert "fit one EU868 uplink at DR3, DR4, DR5, DR6" in section


def test_report_section_for_float32_says_sf10_to_sf12_need_two_uplinks(runs, registry):
    from sdt_framework.report.edge import edge_blocks

    folder = load_results(runs["float32"][1])
    text = render_markdown(edge_blocks(folder, registry), runs["float32"][1])
    for dr, sf in (("DR0", 12), ("DR1", 11), ("DR2", 10)):
        assert f"| {dr} | SF{sf}/125 | 51 | no | 2 |" in text
    assert "| DR3 | SF9/125 | 115 | yes | 1 |" in text
