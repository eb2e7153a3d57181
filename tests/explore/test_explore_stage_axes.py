"""Sweeping chain-stage parameters: keys, points, skipped points, min-spec, cost, end to end."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework import build_registry
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.errors import SDTError
from sdt_framework.explore import build_points, design_points, load_sweep, min_spec, parse_sweep
from sdt_framework.explore.pareto import demands, point_costs
from sdt_framework.explore.run import plan_explore
from sdt_framework.explore.stage_axes import check_stage_axes
from sdt_framework.explore.sweep import Target
from sdt_framework.specs import SensorSpec
from sdt_framework.stages import StageContext

from ..helpers import small_protocol

TINY = small_protocol()
NONLINEARITY = {"base": "adxl345", "axes": {"nonlinearity.second_pct_fs": {"levels": [0, 2.5]}}}


def points_of(sweep: dict, base: SensorSpec, registry):
    parsed = parse_sweep(sweep)
    axes = check_stage_axes(parsed, base, registry)
    return build_points(parsed, base, design_points(parsed), axes)


def test_points_carry_the_stage_with_the_swept_values(registry):
    points, skipped = points_of(NONLINEARITY, registry.sensor("adxl345"), registry)
    assert skipped.empty
    assert [p.spec.name for p in points] == [
        "adxl345~nonlinearity.second_pct_fs=0",
        "adxl345~nonlinearity.second_pct_fs=2.5",
    ]
    for point, level in zip(points, [0.0, 2.5], strict=True):
        (use,) = point.spec.stages  # the base lists no stage: the point adds it
        assert use.name == "nonlinearity" and use.params == {"second_pct_fs": level}
        bound = registry.bind(point.spec).stages[0]  # the stage's own model accepts it
        assert bound.params["second_pct_fs"] == level and bound.params["third_pct_fs"] == 0.0


def test_a_listed_stage_is_set_in_place_on_every_axis(registry):
    base = SensorSpec.model_validate(
        {
            **registry.sensor("adxl345").model_dump(exclude={"plugin", "distribution"}),
            "name": "xa-base",
            "stages": [
                {"name": "offset", "params": {"offset_mg": 5}},
                {
                    "name": "cross-axis",
                    "params": {"pct": 1},
                    "per_axis": {"z": {"pct": 3}},
                },
            ],
        }
    )
    sweep = {"base": "xa-base", "axes": {"cross-axis.pct": {"levels": [0.5, 2]}}}
    points, _ = points_of(sweep, base, registry)
    for point, level in zip(points, [0.5, 2.0], strict=True):
        assert [u.name for u in point.spec.stages] == ["offset", "cross-axis"]  # none added
        assert point.spec.stages[0].params == {"offset_mg": 5}
        assert point.spec.stages[1].params == {"pct": level}
        assert point.spec.for_axis("z").stages[1].params["pct"] == level  # z override dropped
    assert base.stages[1].per_axis == {"z": {"pct": 3}}  # the base is left as it was


def test_a_stage_at_zero_is_exactly_the_identity(registry):
    """x + x*x*(0 + 0*x) == x bit for bit, so the point at 0 is the base's chain."""
    spec = registry.stage("nonlinearity")
    context = StageContext(20000.0, 20000.0, 3200.0, 16.0, "nonlinearity.0", "t")
    stage = spec.factory(spec.params.model_validate({"second_pct_fs": 0}), context)
    x = np.random.default_rng(0).normal(0, 5, (3, 4096))
    x[0, :4] = [0.0, -0.0, 15.9, -15.9]
    assert np.array_equal(stage.apply(x, None), x)
    assert (stage.k2, stage.k3) == (0.0, 0.0)


def test_the_point_at_zero_reproduces_the_base_features_bit_for_bit(tmp_path, registry):
    explore = plan_explore(
        parse_sweep(NONLINEARITY), {**TINY, "cache_dir": str(tmp_path / "c1")}, {}, registry
    )
    result = run_benchmark(explore.plan, tmp_path / "explore")
    config = BenchmarkConfig(**{**TINY, "cache_dir": str(tmp_path / "c2"), "sensors": ["adxl345"]})
    bench = run_benchmark(plan_benchmark(config, build_registry()), tmp_path / "bench")
    names = list(explore.plan.feature_set.feature_names)
    features = result.features.set_index("sensor")
    zero = features.loc["adxl345~nonlinearity.second_pct_fs=0", names].to_numpy()
    theirs = bench.features[bench.features["sensor"] == "adxl345"][names].to_numpy()
    assert np.array_equal(zero, theirs)  # bit-identical
    bent = features.loc["adxl345~nonlinearity.second_pct_fs=2.5", names].to_numpy()
    assert not np.array_equal(bent, theirs)  # and the stage does act at 2.5 % FS


@pytest.mark.parametrize(
    ("axes", "ties", "field", "message"),
    [
        (
            {"nonlinarity.second_pct_fs": {"levels": [1]}},
            {},
            "sweep.axes",
            "no stage 'nonlinarity' is registered (did you mean 'nonlinearity'?); registered "
            "stages: clock, cross-axis,",
        ),
        (
            {"offset.temperature": {"levels": [85]}},
            {},
            "sweep.axes",
            "'offset.temperature' is not a numeric parameter of stage 'offset'; its numeric "
            "parameters: offset_mg, tempco_mg_per_c",
        ),
        (
            {"nonlinearity.second_pct": {"levels": [1]}},
            {},
            "sweep.axes",
            "(did you mean 'second_pct_fs'?); its numeric parameters: full_scale_g, "
            "second_pct_fs, third_pct_fs",
        ),
        (
            {"gauss-markov.sigma_ug": {"levels": [300]}},
            {},
            "sweep.axes",
            "does not list stage 'gauss-markov', whose tau_s has no default; list the stage in "
            "the base profile with those params",
        ),
        (
            {"sampling_rate_hz": {"levels": [3200]}},
            {"flicker.colour": "2"},
            "sweep.ties",
            "'flicker.colour' is not a numeric parameter of stage 'flicker'",
        ),
    ],
)
def test_bad_stage_keys_are_one_line_naming_file_and_key(
    tmp_path, registry, axes, ties, field, message
):
    sweep = parse_sweep({"base": "adxl345", "axes": axes, "ties": ties})
    with pytest.raises(SDTError) as info:
        plan_explore(sweep, TINY, {}, registry, where="my.toml")
    text = str(info.value)
    assert text.startswith(f"my.toml: field '{field}': ") and "\n" not in text
    assert message in text


def test_ties_may_set_but_not_read_a_stage_parameter(tmp_path, registry):
    base = registry.sensor("adxl345")
    sweep = {
        "base": "adxl345",
        "axes": {"gauss-markov.sigma_ug": {"levels": [-5, 300]}},
        "ties": {"gauss-markov.tau_s": "0.5"},
    }
    points, skipped = points_of(sweep, base, registry)
    assert [u.params for u in points[0].spec.stages] == [{"sigma_ug": 300.0, "tau_s": 0.5}]
    # the stage's model rejects a negative sigma: that point is skipped with the reason
    assert skipped["point"].tolist() == ["adxl345~gauss-markov.sigma_ug=-5"]
    assert "sigma_ug" in skipped["reason"].iloc[0]
    assert "greater than 0" in skipped["reason"].iloc[0]
    path = tmp_path / "tie.toml"
    path.write_text(
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\nnonlinearity.second_pct_fs = { levels = [1] }\n'
        '[sweep.ties]\ndigital_cutoff_hz = "nonlinearity.second_pct_fs * 2"\n'
    )
    with pytest.raises(SDTError, match=r"not stage parameters such as 'stage\.param'") as info:
        load_sweep(path)
    assert str(path) in str(info.value) and "\n" not in str(info.value)


def test_zero_error_magnitude_a_stage_requires_positive_means_the_stage_left_out(registry):
    base = registry.sensor("adxl345")
    sweep = {
        "base": "adxl345",
        "axes": {"gauss-markov.sigma_ug": {"levels": [0, 300]}},
        "ties": {"gauss-markov.tau_s": "0.5"},
    }
    parsed = parse_sweep(sweep)
    axes = check_stage_axes(parsed, base, registry)
    points, skipped = build_points(parsed, base, design_points(parsed), axes)
    assert skipped.empty
    assert points[0].spec.stages == ()  # sigma 0: no bias process, the base's own chain
    blank = {"name": "", "description": "", "source": ""}
    assert points[0].spec.content_dict() | blank == base.content_dict() | blank
    assert [u.name for u in points[1].spec.stages] == ["gauss-markov"]
    # and 0 is the base's value of an error the base does not have
    from sdt_framework.explore.stage_axes import base_value

    assert base_value(base, "gauss-markov.sigma_ug", axes) == 0.0
    assert np.isnan(base_value(base, "gauss-markov.tau_s", axes))  # not a magnitude: no value


def test_unquoted_dotted_toml_keys_are_stage_keys(tmp_path):
    path = tmp_path / "dotted.toml"
    path.write_text(
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\n'
        "gauss-markov.sigma_ug = { levels = [100, 300] }\n"
        '"nonlinearity.second_pct_fs" = { levels = [0, 1] }\n'
        '[sweep.ties]\ngauss-markov.tau_s = "1"\n'
        "[sweep.cost]\ngauss-markov.sigma_ug = { weight = 2 }\n"
    )
    sweep, _ = load_sweep(path)
    assert list(sweep.axes) == ["gauss-markov.sigma_ug", "nonlinearity.second_pct_fs"]
    assert sweep.ties == {"gauss-markov.tau_s": "1"} and sweep.cost["gauss-markov.sigma_ug"]
    assert set(demands(sweep).values()) == {"lower"}  # error magnitudes


def synthetic(levels, f1, other_levels=(3200.0,)) -> tuple[pd.DataFrame, list[str]]:
    """Tidy results of a grid over a stage key x rate, Macro-F1 = f1(level) exactly."""
    key = "offset.offset_mg"
    rows = []
    for level in levels:
        for rate in other_levels:
            for r in range(3):
                rows.append(
                    {
                        "point": f"p{level}-{rate}",
                        "role": "point",
                        "machine": "m",
                        "scenario": "forward",
                        "classifier": "lr",
                        "repeat": r,
                        "macro_f1": f1(level),
                        key: level,
                        "sampling_rate_hz": rate,
                    }
                )
    return pd.DataFrame(rows), [key, "sampling_rate_hz"]


def test_min_spec_of_an_error_term_is_its_largest_tolerable_level():
    # F1 = 1 - level / 10 >= 0.75  <=>  level <= 2.5: the largest tested level meeting it is 2
    levels = [0.0, 0.5, 1.0, 2.0, 4.0, 8.0]
    results, fields = synthetic(levels, lambda v: 1.0 - v / 10)
    base = {"offset.offset_mg": 0.0, "sampling_rate_hz": 3200.0}
    demand = {"offset.offset_mg": "lower", "sampling_rate_hz": "higher"}
    table = min_spec(results, fields, base, Target(macro_f1=0.75), demand).set_index("parameter")
    assert table.loc["offset.offset_mg", "min_level"] == 2.0
    assert table.loc["offset.offset_mg", "levels_tested"] == len(levels)


def test_min_spec_ranks_a_signed_error_by_magnitude_and_needs_both_signs():
    # the positive side hurts twice as much: +4 fails (0.6) while -4 meets (0.8)
    levels = [-8.0, -4.0, -2.0, 0.0, 2.0, 4.0, 8.0]
    results, fields = synthetic(levels, lambda v: 1.0 - max(v, 0) / 10 - max(-v, 0) / 20)
    base = {"offset.offset_mg": 0.0, "sampling_rate_hz": 3200.0}
    demand = {"offset.offset_mg": "lower", "sampling_rate_hz": "higher"}
    table = min_spec(results, fields, base, Target(macro_f1=0.7), demand).set_index("parameter")
    assert table.loc["offset.offset_mg", "min_level"] == 2.0  # |offset| <= 2 mg, either sign


def test_a_parameter_with_no_demanding_direction_gets_a_note_not_a_level():
    results, fields = synthetic([0.5, 1.0, 2.0], lambda v: 0.9)
    base = {"offset.offset_mg": 1.0, "sampling_rate_hz": 3200.0}
    demand = {"offset.offset_mg": "neither", "sampling_rate_hz": "higher"}
    row = min_spec(results, fields, base, Target(macro_f1=0.5), demand).iloc[0]
    assert np.isnan(row["min_level"]) and "no demanding direction" in row["note"]
    axes = {"gauss-markov.tau_s": {"levels": [0.1, 1]}, "adc_bits": {"levels": [12]}}
    sweep = parse_sweep({"base": "x", "axes": axes})
    assert demands(sweep)["gauss-markov.tau_s"] == "neither"


def test_stage_costs_count_halvings_or_the_span_of_the_magnitude():
    # base value 0 (the error absent): linear, 1 unit from 0 to the largest |level| (4 mg),
    # by magnitude: more error is cheaper, whatever its sign
    zero = parse_sweep({"base": "x", "axes": {"offset.offset_mg": {"levels": [-4, 0, 2]}}})
    values = pd.DataFrame({"offset.offset_mg": [-4.0, 0.0, 2.0]})
    costs = point_costs(values, {"offset.offset_mg": 0.0}, zero, 10.0)
    assert costs.tolist() == [9.0, 10.0, 9.5]
    # non-zero base and levels: log, one step per halving of the magnitude
    log = parse_sweep({"base": "x", "axes": {"gauss-markov.sigma_ug": {"levels": [100, 400]}}})
    values = pd.DataFrame({"gauss-markov.sigma_ug": [100.0, 400.0]})
    assert point_costs(values, {"gauss-markov.sigma_ug": 200.0}, log, 0.0).tolist() == [1.0, -1.0]


def run_cli(sdt_in_process, tmp_path, body: str):
    """``sdt explore`` of ``body``, in this process (refused, or ``jobs = 1``: no worker)."""
    path = tmp_path / "sweep.toml"
    path.write_text(body)
    out = tmp_path / "out"
    return sdt_in_process("explore", str(path), "--out", str(out)), out


def test_cross_axis_without_triaxial_nodes_is_refused_before_any_work(sdt_in_process, tmp_path):
    body = (
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\n"cross-axis.pct" = { levels = [0, 2] }\n'
        '[benchmark]\nmachines = ["Motor-2"]\nchannels = ["ch1"]\nclassifiers = ["lr"]\n'
        "repeats = 1\n"
    )
    result, out = run_cli(sdt_in_process, tmp_path, body)
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:"), lines
    assert "read triaxial nodes (cross-axis)" in lines[0] and "[benchmark] axes" in lines[0]
    assert not out.exists()


def test_explore_end_to_end_names_the_stage_parameter_in_min_spec(sdt_in_process, tmp_path):
    body = (
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\n'
        '"nonlinearity.second_pct_fs" = { levels = [0, 5] }\n'
        "[sweep.target]\nmax_loss = 0.2\n"
        '[benchmark]\nmachines = ["Motor-2"]\nchannels = ["ch1"]\nclassifiers = ["lr"]\n'
        f'scenarios = ["forward"]\nrepeats = 1\njobs = 1\ncache_dir = "{tmp_path / "cache"}"\n'
        "dataset_options = { duration = 1.5 }\n"
    )
    result, out = run_cli(sdt_in_process, tmp_path, body)
    assert result.returncode == 0, result.stderr
    spec = pd.read_csv(out / "min_spec.csv")
    assert set(spec["parameter"]) == {"nonlinearity.second_pct_fs"}
    assert (spec["base_level"] == 0).all()
    # the default (adaptive) strategy screens every point: their table is the screen's
    points = pd.read_csv(out / "screen" / "points.csv")
    assert points["nonlinearity.second_pct_fs"].tolist() == [0, 5]
    assert "nonlinearity.second_pct_fs (base 0)" in result.stdout
    again, _ = load_sweep(out / "sweep.toml")  # the sweep as run reads back the same
    assert list(again.axes) == ["nonlinearity.second_pct_fs"]


def test_max_loss_to_base_measures_from_the_base_sensor():
    # F1 = 0.9 - level / 20; the base scores 0.9: loss <= 0.06 <=> level <= 1.2
    results, fields = synthetic([0.0, 0.5, 1.0, 2.0, 4.0], lambda v: 0.9 - v / 20)
    base_rows = results[results["point"] == "p0.0-3200.0"].assign(point="base", role="base")
    reference = base_rows.assign(point="ref", role="reference", macro_f1=1.0)
    both = pd.concat([results, base_rows, reference], ignore_index=True)
    base = {"offset.offset_mg": 0.0, "sampling_rate_hz": 3200.0}
    demand = {"offset.offset_mg": "lower", "sampling_rate_hz": "higher"}
    target = Target(max_loss_to_base=0.06)
    table = min_spec(both, fields, base, target, demand).set_index("parameter")
    assert table.loc["offset.offset_mg", "threshold"] == pytest.approx(0.84)
    assert table.loc["offset.offset_mg", "min_level"] == 1.0
    assert table.loc["offset.offset_mg", "target"] == "loss to base <= 0.06"


@pytest.mark.catalog
def test_a_part_in_a_mode_at_85c_is_a_base_and_keeps_its_temperature(registry):
    base = registry.sensor("adxl345-ds[errors=datasheet,cross_axis=off,temp=85c]")
    sweep = {"base": base.name, "axes": {"scale.tempco_pct_per_c": {"levels": [0.01, 0.1]}}}
    points, skipped = points_of(sweep, base, registry)
    assert skipped.empty
    own = build_registry()  # the shared registry stays as installed
    for point, level in zip(points, [0.01, 0.1], strict=True):
        assert point.spec.name == f"{base.name}~scale.tempco_pct_per_c={level:g}"
        own.add(point.spec)  # a point keeps its base's mode in its name
        scale = next(u for u in own.sensor(point.spec.name).stages if u.name == "scale")
        assert scale.params["tempco_pct_per_c"] == level
        assert scale.params["temperature"]["celsius"] == 85.0


@pytest.mark.parametrize("path", sorted(Path(__file__).parents[2].glob("examples/sweeps/*.toml")))
def test_every_example_sweep_plans_its_points(path, registry):
    sweep, _ = load_sweep(path)
    if "[" in sweep.base:
        pytest.importorskip("sdt_sensors_catalog", reason="install plugins/sensors-catalog")
    base = registry.sensor(sweep.base)
    points, skipped = build_points(
        sweep, base, design_points(sweep), check_stage_axes(sweep, base, registry, path)
    )
    assert points and skipped.empty
