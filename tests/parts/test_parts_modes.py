"""Parts in a mode: names, defaults, ODR fractions, per-axis values, one-line mode errors."""

from __future__ import annotations

import pytest

from sdt_framework.errors import SDTError
from sdt_framework.parts import (
    ModeError,
    all_modes,
    canonical_name,
    resolve,
    split_name,
    split_names,
)


def test_name_with_a_mode_splits_and_canonical_form_sorts_keys():
    assert split_name("adxl355[range=8g, odr=4000]") == ("adxl355", {"range": "8g", "odr": "4000"})
    assert split_name("mpu6050") == ("mpu6050", {})
    assert canonical_name("adxl355", {"range": "8g", "odr": "4000"}) == "adxl355[odr=4000,range=8g]"
    assert split_names("adxl355[range=8g,odr=4000],iis3dwb[range=4g], mpu6050") == [
        "adxl355[range=8g,odr=4000]",
        "iis3dwb[range=4g]",
        "mpu6050",
    ]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("a[range]", "'range' is not key=option"),
        ("a[range=2g,range=4g]", "mode key 'range' is given twice"),
        ("a[]", "empty brackets"),
        ("a[x=1", "not a sensor name"),
    ],
)
def test_malformed_names_are_one_clear_error(text, message):
    with pytest.raises(SDTError, match=message):
        split_name(text)


def test_default_mode_fills_every_key_and_names_it(toy):
    resolved = resolve(toy)
    assert resolved.mode == {"odr": "4000", "range": "2g"}
    assert resolved.sensor.name == "toy[odr=4000,range=2g]"
    assert resolve(toy, {"range": "2g"}).sensor == resolved.sensor


def test_an_odr_fraction_moves_with_the_odr(toy):
    fast = resolve(toy, {"odr": "4000"}).sensor
    slow = resolve(toy, {"odr": "1000"}).sensor
    assert (fast.digital_cutoff_hz, slow.digital_cutoff_hz) == (1000.0, 250.0)  # ODR/4
    assert (fast.analog_cutoff_hz, slow.analog_cutoff_hz) == (2000.0, 500.0)  # stand-in ODR/2


def test_per_axis_noise_follows_the_axis(toy):
    sensor = resolve(toy).sensor
    assert sensor.noise_density_ug_rthz == 100  # X is the default axis
    assert sensor.for_axis("z").noise_density_ug_rthz == 150
    assert sensor.for_axis("y") == sensor  # same figures: the very same profile
    assert sensor.for_axis("z").content_hash() != sensor.content_hash()


def test_absent_values_say_what_stands_in_and_why(toy):
    sources = {s.field: s for s in resolve(toy).sources}
    assert sources["mech_cutoff_hz"].value is None
    assert sources["mech_cutoff_hz"].absent == "no resonance given"
    assert sources["analog_cutoff_hz"].why == "the output Nyquist"
    assert sources["analog_cutoff_hz"].odr_fraction == 0.5
    assert sources["full_scale_g"].set_by == "range=2g"
    assert sources["adc_bits"].source == "Toy data sheet, Rev. 1"
    assert resolve(toy).sensor.mech_cutoff_hz is None


@pytest.mark.parametrize(
    ("mode", "message"),
    [
        ({"range": "4g"}, r"^part 'toy': range=4g is not an option; range is one of 2g, 8g$"),
        ({"rang": "2g"}, r"^part 'toy' has no mode key 'rang'; its keys: odr, range$"),
        (
            {"odr": "100", "range": "8g"},
            r"^part 'toy': odr=100 needs range in 2g; got range=8g$",
        ),
    ],
)
def test_an_invalid_mode_is_one_line_naming_part_key_and_allowed_values(toy, mode, message):
    with pytest.raises(ModeError, match=message):
        resolve(toy, mode)


def test_every_valid_mode_is_listed_and_excluded_ones_are_not(toy):
    modes = all_modes(toy)
    assert len(modes) == 5  # 2 ranges x 3 rates, minus 100 Hz at 8 g
    assert {"odr": "100", "range": "8g"} not in modes
