"""Per-unit tolerances: draws follow their distributions, unit k is stable, runs carry units."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import norm
from sdt_plugins.sensors.adxl345 import ADXL345

from sdt_framework import SensorSpec, build_registry
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.stages import base_name, draw_unit

SENSOR = SensorSpec.model_validate(
    {
        **ADXL345.model_dump(),
        "name": "unit-test[range=2g]",
        "tolerances": {
            "noise_density_ug_rthz": {"spread": 10.0},
            "scale.error_pct": {"distribution": "uniform", "spread": 5.0},
        },
    }
)


def test_unit_draws_match_their_distributions():
    units = [draw_unit(SENSOR, 4, k) for k in range(3000)]
    nsd = np.array([u.noise_density_ug_rthz for u in units])
    scale = np.array([u.stages[0].params["error_pct"] for u in units])
    # normal truncated at +-3 SD: SD factor sqrt(1 - 2*3*phi(3) / (2*Phi(3) - 1))
    factor = np.sqrt(1 - 6 * norm.pdf(3) / (2 * norm.cdf(3) - 1))
    assert nsd.mean() == pytest.approx(290, abs=3 * 10 / np.sqrt(3000))
    assert nsd.std() == pytest.approx(10 * factor, rel=0.05)
    assert np.abs(nsd - 290).max() <= 30
    assert scale.mean() == pytest.approx(0, abs=3 * 5 / np.sqrt(3 * 3000))
    assert scale.std() == pytest.approx(5 / np.sqrt(3), rel=0.05)
    assert np.abs(scale).max() <= 5
    assert all(not u.tolerances and u.stages[0].name == "scale" for u in units[:5])


def test_unit_k_is_the_same_unit_in_every_run_and_every_mode():
    other_mode = SENSOR.model_copy(update={"name": "unit-test[range=8g]"})
    assert base_name(other_mode.name) == "unit-test"
    a, b = draw_unit(SENSOR, 4, 7), draw_unit(other_mode, 4, 7)
    assert a.noise_density_ug_rthz == b.noise_density_ug_rthz
    assert a.stages[0].params == b.stages[0].params
    assert draw_unit(SENSOR, 4, 8).noise_density_ug_rthz != a.noise_density_ug_rthz
    assert draw_unit(SENSOR, 5, 7).noise_density_ug_rthz != a.noise_density_ug_rthz


def test_tolerances_leave_the_nominal_profile_and_its_hash_alone():
    plain = SensorSpec.model_validate({**SENSOR.model_dump(), "tolerances": {}})
    assert plain.content_hash() == SENSOR.content_hash()
    assert draw_unit(plain, 4, 0) is plain


def test_per_axis_spreads_draw_each_axis_on_its_own():
    """A tolerance with per_axis: Z gets its own spread and stream; Y, not listed, shares X."""
    sensor = SensorSpec.model_validate(
        {
            **ADXL345.model_dump(),
            "name": "axes-test",
            "tolerances": {"offset.tempco_mg_per_c": {"spread": 1.0, "per_axis": {"z": 3.0}}},
        }
    )
    units = [draw_unit(sensor, 4, k) for k in range(3000)]
    x, y, z = (
        np.array([u.for_axis(a).stages[0].params["tempco_mg_per_c"] for u in units]) for a in "xyz"
    )
    factor = np.sqrt(1 - 6 * norm.pdf(3) / (2 * norm.cdf(3) - 1))  # truncated at +-3 SD
    assert x.std() == pytest.approx(factor, rel=0.05)
    assert z.std() == pytest.approx(3 * factor, rel=0.05)
    assert np.array_equal(x, y)
    assert abs(np.corrcoef(x, z)[0, 1]) < 4 / np.sqrt(3000)  # independent draws


def test_benchmark_with_units_labels_runs_and_spreads_only_toleranced_sensors(tmp_path):
    config = BenchmarkConfig(
        dataset_options={"duration": 1.5},
        machines=["Motor-2"],
        channels=["ch1"],
        sensors=["wilcoxon-786b10", "adxl345"],
        classifiers=["lr"],
        repeats=2,
        units=3,
        jobs=1,
        report=False,
        cache_dir=str(tmp_path / "cache"),
    )
    result = run_benchmark(plan_benchmark(config, build_registry()), tmp_path / "out")
    results = tidy(result.runs)[0]
    assert sorted(results["unit"].unique()) == [0, 1, 2]
    assert len(results) == 2 * 3 * 2 * len(config.scenarios)  # sensors x units x repeats x ...
    feats = result.features
    names = list(result.plan.feature_set.feature_names)

    def unit(sensor, k):
        rows = feats[(feats["sensor"] == sensor) & (feats["unit"] == k) & (feats["repeat"] == 0)]
        return rows[names].to_numpy()

    assert np.array_equal(unit("wilcoxon-786b10", 0), unit("wilcoxon-786b10", 2))
    assert not np.allclose(unit("adxl345", 0), unit("adxl345", 2))


def test_report_unit_spread_separates_units_from_noise():
    from sdt_framework.report.units import unit_spread

    # unit means 0.5, 0.6, 0.7 (SD 0.1); within each unit repeats differ by +-0.02 (SD 0.02*sqrt2)
    rows = [
        {
            "scenario": "forward",
            "sensor": "s",
            "classifier": "lr",
            "machine": m,
            "unit": u,
            "repeat": r,
            "macro_f1": 0.5 + 0.1 * u + (0.02 if r else -0.02),
            "status": "ok",
        }
        for m in ("M1", "M2")
        for u in range(3)
        for r in range(2)
    ]
    import pandas as pd

    spread = unit_spread(pd.DataFrame(rows)).iloc[0]
    assert (spread.units, spread.repeats) == (3, 2)
    assert spread["mean"] == pytest.approx(0.6)
    assert spread.sd_units == pytest.approx(0.1)
    assert spread.sd_noise == pytest.approx(0.04 / np.sqrt(2))
