"""Sweep files, designs and points: validation, sizes, ties and skipped points."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.explore import build_points, design_points, load_sweep, parse_sweep
from sdt_framework.explore.ties import evaluate_tie
from sdt_framework.specs import SensorSpec

BASE = SensorSpec(
    name="adxl345",
    sampling_rate_hz=3200,
    full_scale_g=16,
    adc_bits=13,
    noise_density_ug_rthz=290,
    mech_cutoff_hz=7000,
    analog_cutoff_hz=1600,
    digital_cutoff_hz=1599,
    digital_order=1,
)


def write(tmp_path, text: str):
    path = tmp_path / "sweep.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ("[sweep.axes]\nbogus_hz = { levels = [1] }", "'bogus_hz' is not a sweepable field"),
        ("[sweep.axes]\nadc_bits = { levels = [] }", "levels is empty"),
        ("[sweep.axes]\nfull_scale_g = { range = [16, 2] }", "range low 16 must be below high 2"),
        (
            "[sweep.axes]\nadc_bits = { levels = [12] }\n[sweep.ties]\n"
            'digital_cutoff_hz = "0.25 * speed"',
            "names unknown parameter(s) ['speed']",
        ),
        (
            "[sweep.axes]\nadc_bits = { levels = [12] }\n[sweep.ties]\n"
            'digital_cutoff_hz = "__import__(1)"',
            "only numbers, parameter names and + - * /",
        ),
        ("[sweep.axes]\nadc_bits = { levels = [12], colour = 1 }", "unknown key"),
    ],
)
def test_bad_sweeps_name_the_file_and_key(tmp_path, body, message):
    path = write(tmp_path, f'[sweep]\nbase = "adxl345"\n{body}\n')
    with pytest.raises(SDTError) as info:
        load_sweep(path)
    text = str(info.value)
    assert str(path) in text
    assert message in text


def test_missing_design_library_is_one_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "SALib", None)
    monkeypatch.setitem(sys.modules, "SALib.sample", None)
    sweep = parse_sweep(
        {"base": "adxl345", "design": "morris", "axes": {"adc_bits": {"range": [10, 16]}}}
    )
    with pytest.raises(SDTError, match="needs SALib; install it"):
        design_points(sweep)


def test_design_sizes_follow_the_estimators():
    axes = {
        "sampling_rate_hz": {"range": [800, 6400], "scale": "log"},
        "noise_density_ug_rthz": {"range": [25, 1000], "scale": "log"},
    }
    sizes = {
        "lhs": 10,  # samples
        "sobol": 8 * (2 + 2),  # N (d + 2)
        "morris": 5 * (2 + 1),  # trajectories (d + 1)
    }
    for design, expected in sizes.items():
        samples = {"lhs": 10, "sobol": 8, "morris": 5}[design]
        table = design_points(
            parse_sweep({"base": "x", "design": design, "samples": samples, "axes": axes})
        )
        assert len(table) == expected
        rate = table["sampling_rate_hz"]
        assert rate.between(800 * (1 - 1e-12), 6400 * (1 + 1e-12)).all()
        # log scale: the unit coordinate maps to log-uniform values
        u = table["u_sampling_rate_hz"]
        assert np.allclose(rate, 800 * 8**u)


def test_range_grid_levels_are_log_spaced():
    table = design_points(
        parse_sweep(
            {
                "base": "x",
                "axes": {
                    "noise_density_ug_rthz": {"range": [10, 1000], "scale": "log", "steps": 3}
                },
            }
        )
    )
    assert table["noise_density_ug_rthz"].tolist() == pytest.approx([10, 100, 1000])


def test_ties_follow_the_rate_and_reject_code():
    assert evaluate_tie("0.25 * rate", {"rate": 4000}) == 1000
    assert evaluate_tie("rate / 2 - 1", {"rate": 3200}) == 1599
    assert evaluate_tie("-(nsd) + 2 * nsd", {"nsd": 5}) == 5


def test_points_are_validated_specs_and_invalid_ones_are_skipped_with_reason():
    sweep = parse_sweep({"base": "adxl345", "axes": {"sampling_rate_hz": {"levels": [800, 3200]}}})
    points, skipped = build_points(sweep, BASE, design_points(sweep))
    assert [p.spec.name for p in points] == ["adxl345~rate=3200"]
    assert points[0].spec.content_dict() | {"name": "", "description": "", "source": ""} == (
        BASE.content_dict() | {"name": "", "description": "", "source": ""}
    )
    assert skipped["point"].tolist() == ["adxl345~rate=800"]
    assert "at or above the Nyquist frequency 400 Hz" in skipped["reason"].iloc[0]


def test_tied_cutoff_keeps_every_rate_valid():
    sweep = parse_sweep(
        {
            "base": "adxl345",
            "axes": {"sampling_rate_hz": {"levels": [800, 1600, 3200, 6400]}},
            "ties": {"digital_cutoff_hz": "rate / 2 - 1"},
        }
    )
    points, skipped = build_points(sweep, BASE, design_points(sweep))
    assert skipped.empty
    assert [p.spec.digital_cutoff_hz for p in points] == [399, 799, 1599, 3199]
    # the point at the base rate is the base sensor, field for field
    same = points[2].spec
    assert same.model_dump(exclude={"name", "description", "source"}) == BASE.model_dump(
        exclude={"name", "description", "source"}
    )
