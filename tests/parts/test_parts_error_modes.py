"""Error terms are off by default and enabled by mode keys: names, hashes, stages, chain, runs."""

from __future__ import annotations

import hashlib

import numpy as np
import pytest

from sdt_framework import SDTError
from sdt_framework.api import degrade
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.errors import SpecFileError
from sdt_framework.parts import ErrorTermsError, all_modes, load_part_text, resolve
from sdt_framework.stages import draw_unit

from .conftest import TOY

pytestmark = pytest.mark.catalog
catalogue = pytest.importorskip("sdt_sensors_catalog", reason="install plugins/sensors-catalog")
PARTS = {part.name: part for part in catalogue.load_parts()}

#: per part: (number of modes, SHA-256 of the sorted "name content_hash" lines of every
#: mode), recorded at commit d2116f8, before parts had error terms; results folders and
#: caches are keyed on these names and hashes
BEFORE = {
    "adxl1002": (28, "3d3ec5e2ecdc6dcd1f11fb008be02ae1"),
    "adxl313": (80, "4ba0d68837e098b05b5e3f1946a290f0"),
    "adxl345-ds": (128, "630a271f2bf40bb4e4e41f48bbfdca6e"),
    "adxl355": (33, "78a071f71174f2cd31d9cc20c72dbce1"),
    "adxl357-ds": (33, "f53efba3b7c4cc26b3f0e2d4600b495f"),
    "adxl372": (15, "7c35ff5e0f139c823336e9605a5a64a6"),
    "bmi270": (32, "45d04acc353249d8b07ce24d99b43364"),
    "iim42352": (20, "cb04fcec8bd88572dcb0385dcf231e86"),
    "iis3dwb": (72, "837d8a215431d10f10b1639772fbc64e"),
    "ism330dhcx": (360, "6dfa3959a1d5799cb519013670026015"),
    "kx134": (128, "4ef9193eb65f3de5845bba644b1021dc"),
    "lis2dw12": (248, "c0c22511a207c878b0ed19ee6b58e430"),
    "lis3dh": (100, "9e99ae9601855ea4b08bbc429d28ee44"),
    "mpu6050": (28, "6c8082da0b6c8c536951b7686f0f7e66"),
}
DEFAULTS = {"errors": "off", "cross_axis": "off", "temp": "25c"}


@pytest.mark.parametrize("name", sorted(BEFORE))
def test_every_mode_keeps_its_name_and_hash(name):
    part = PARTS[name]
    sensors = [resolve(part, mode).sensor for mode in all_modes(part)]
    # issue 40 moved the sigma-delta parts to sampling = "decimate": that field alone
    # changed, so with the paper's model put back each mode hashes as it did
    sensors = [s.model_copy(update={"sampling": "sample-then-filter"}) for s in sensors]
    pairs = sorted((s.name, s.content_hash()) for s in sensors)
    digest = hashlib.sha256("\n".join(f"{n} {h}" for n, h in pairs).encode()).hexdigest()
    assert (len(pairs), digest[:32]) == BEFORE[name]
    for mode in all_modes(part)[:3]:  # the new keys at their defaults change nothing
        plain, spelled = resolve(part, mode).sensor, resolve(part, {**mode, **DEFAULTS}).sensor
        assert (spelled.name, spelled.content_hash()) == (plain.name, plain.content_hash())
        assert not plain.stages and not plain.tolerances


def test_enabled_keys_name_the_sensor_and_list_nominal_zero_stages():
    sensor = resolve(PARTS["adxl355"], {"errors": "datasheet", "temp": "85c"}).sensor
    assert sensor.name == "adxl355[errors=datasheet,odr=4000,range=2g,temp=85c]"
    assert [use.name for use in sensor.stages] == ["offset", "scale", "nonlinearity"]
    offset, scale, nonlinearity = (use.params for use in sensor.stages)
    assert offset["tempco_mg_per_c"] == scale["tempco_pct_per_c"] == 0
    assert nonlinearity == {"second_pct_fs": 0.0}
    assert offset["temperature"]["celsius"] == 85 and offset["temperature"]["reference_c"] == 25
    crossed = resolve(PARTS["adxl355"], {"cross_axis": "datasheet"}).sensor
    assert crossed.name == "adxl355[cross_axis=datasheet,odr=4000,range=2g]"
    assert [use.name for use in crossed.stages] == ["cross-axis"]
    assert resolve(PARTS["adxl355"], {"temp": "25c", "errors": "datasheet"}).sensor.name == (
        "adxl355[errors=datasheet,odr=4000,range=2g]"
    )


@pytest.mark.parametrize(
    ("part", "mode", "message"),
    [
        ("adxl355", {"errors": "on"}, "errors=on is not an option; errors is one of off, data"),
        ("adxl355", {"errors": "datasheet", "temp": "hot"}, "temp=hot is not a temperature"),
        ("adxl355", {"temp": "85c"}, "acts through the temperature coefficients"),
        ("lis3dh", {"errors": "datasheet", "temp": "125c"}, "outside -40 to 85 °C"),
        ("mpu6050", {"errors": "datasheet", "temp": "85c"}, "outside 0 to 70 °C"),
        ("adxl1002", {"errors": "datasheet"}, "give no 0 g offset temperature coefficient"),
        ("lis3dh", {"cross_axis": "datasheet"}, "give no cross-axis sensitivity"),
        ("adxl355", {"eror": "datasheet"}, "its keys: cross_axis, errors, odr, range, temp"),
    ],
)
def test_keys_a_part_cannot_honour_are_one_clear_line(part, mode, message):
    with pytest.raises(SDTError, match=message):
        resolve(PARTS[part], mode)


def test_a_part_without_error_terms_says_so_and_hashes_as_before(toy):
    assert "errors" not in toy.content_dict()
    with pytest.raises(ErrorTermsError, match=r"lists no \[errors\]"):
        resolve(toy, {"errors": "datasheet"})


@pytest.mark.parametrize(
    ("section", "message"),
    [
        ('[errors.drift]\nvalue = 1\ndoc = "ds"\nwhere = "T1"\nbasis = "typical"\nprinted = "1"',
         "unknown error term"),
        ('[errors.cross_axis]\nvalue = 1\ndoc = "ds"\nwhere = "T1"\nbasis = "typical"',
         "doc, where, basis and printed"),
        ('[errors.cross_axis]\nvalue = 1\ndoc = "dx"\nwhere = "T1"\nbasis = "typical"\n'
         'printed = "1"', "document 'dx' is not in"),
        ('[errors.nonlinearity]\nby = "range"\ntable = { 2g = 0.5 }\ndoc = "ds"\nwhere = "T1"\n'
         'basis = "typical"\nprinted = "0.5 %"', "leaves out options of range"),
        ('[errors.offset_tempco]\nvalue = 1\ndoc = "ds"\nwhere = "T1"\nbasis = "typical"\n'
         'printed = "1"\nrange_c = [30, 80]', "over 25 °C"),
        ('[errors.cross_axis]\nabsent = "not given"', "needs stand_in"),
    ],
)  # fmt: skip
def test_bad_error_sections_name_the_field(section, message):
    with pytest.raises(SpecFileError, match=message):
        load_part_text(TOY + "\n" + section + "\n", "toy.toml")


def test_the_temperature_moves_a_unit_by_its_tempco_and_not_at_25c(registry):
    """Zero input, noise off: the output is the unit's offset tempco x (T - 25 °C)."""
    fs, x = 20000.0, np.zeros(20000)
    hot = registry.sensor("adxl355[errors=datasheet,temp=85c]")
    step = hot.quantisation_step_g
    offsets = []
    for k in range(3):
        unit = draw_unit(hot, 11, k)
        tempco = next(u for u in unit.stages if u.name == "offset").params["tempco_mg_per_c"]
        y, fs_out = degrade(x, fs, unit, noise=False)
        settled = y[-int(fs_out / 4) :]
        assert np.all(np.abs(settled - 1e-3 * tempco * 60) <= step), k
        offsets.append(settled.mean())
        cool = draw_unit(registry.sensor("adxl355[errors=datasheet]"), 11, k)
        assert np.array_equal(degrade(x, fs, cool, noise=False)[0], np.zeros_like(y))
    assert len(set(offsets)) == 3  # three units, three offsets


def test_the_nominal_unit_equals_the_default_mode(registry):
    x = np.random.default_rng(1).normal(0, 0.3, 8000)
    plain, _ = degrade(x, 20000.0, registry.sensor("adxl355"), seed=4)
    nominal, _ = degrade(x, 20000.0, registry.sensor("adxl355[errors=datasheet,temp=85c]"), seed=4)
    np.testing.assert_array_equal(nominal, plain)


def _config(tmp_path, sensor, **kw):
    return BenchmarkConfig(
        dataset_options={"duration": 1.5},
        machines=["Motor-2"],
        channels=["ch1"],
        sensors=[sensor],
        classifiers=["lr"],
        repeats=1,
        units=3,
        jobs=1,
        report=False,
        cache_dir=str(tmp_path / "cache"),
        **kw,
    )


def test_a_benchmark_with_error_terms_draws_different_units(tmp_path, registry):
    sensor = "adxl345-ds[errors=datasheet,temp=85c]"
    result = run_benchmark(plan_benchmark(_config(tmp_path, sensor), registry), tmp_path / "o")
    assert all(run.status == "ok" for run in result.runs)
    names = list(result.plan.feature_set.feature_names)
    feats = result.features.sort_values(["recording_id", "acquisition", "window"])
    units = [feats.loc[feats["unit"] == k, names].to_numpy() for k in range(3)]
    assert units[0].shape == units[1].shape == units[2].shape and len(units[0])
    assert not np.array_equal(units[0], units[1]) and not np.array_equal(units[1], units[2])


def test_cross_axis_needs_a_triaxial_node_and_runs_with_one(tmp_path, registry):
    sensor = "adxl355[cross_axis=datasheet]"
    with pytest.raises(SDTError, match=r"read triaxial nodes \(cross-axis\).*has no axis"):
        plan_benchmark(_config(tmp_path, sensor), registry)
    axes = {"ch1": "x", "ch2": "y", "ch3": "z"}
    result = run_benchmark(
        plan_benchmark(_config(tmp_path, sensor, axes=axes), registry), tmp_path / "o"
    )
    assert all(run.status == "ok" for run in result.runs)
    assert sorted(result.features["unit"].unique()) == [0, 1, 2]


def test_sensors_show_lists_the_terms_and_list_is_unaffected():
    import json

    from typer.testing import CliRunner

    from sdt_framework.cli.main import app

    runner = CliRunner()
    shown = runner.invoke(app, ["sensors", "show", "adxl355[errors=datasheet,temp=85c]", "--json"])
    assert shown.exit_code == 0, shown.output
    data = json.loads(shown.stdout)
    assert data["sensor"]["name"] == "adxl355[errors=datasheet,odr=4000,range=2g,temp=85c]"
    assert data["error_mode"] == {"errors": "datasheet", "cross_axis": "off", "temp": "85c"}
    terms = {t["term"]: t for t in data["error_terms"]}
    assert terms["offset_tempco"]["enabled"] and not terms["cross_axis"]["enabled"]
    assert terms["offset_tempco"]["printed"].startswith("-0.15 min / +/-0.01 typ")
    text = runner.invoke(app, ["sensors", "show", "adxl355"], env={"COLUMNS": "200"}).output
    assert "Error terms: off. Enable with adxl355[errors=datasheet]" in text
    assert "* nonlinearity" not in text  # given at the default +/-2 g
    listed = runner.invoke(app, ["sensors", "list", "--json"])
    modes = {e["name"]: e.get("modes") for e in json.loads(listed.stdout)}
    assert set(modes["adxl355"]) == {"odr", "range"}
