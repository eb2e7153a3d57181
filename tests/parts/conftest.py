"""A small part written in the test, independent of the catalogue."""

from __future__ import annotations

import pytest

from sdt_framework.parts import PartSpec, load_part_text

#: a made-up part exercising every form of value (numbers invented for the test)
TOY = """
name = "toy"
manufacturer = "Test"
description = "made-up part"
interface = "digital"

[documents.ds]
title = "Toy data sheet"
revision = "Rev. 1"

[values.adc_bits]
value = 16
doc = "ds"
where = "Table 1"
basis = "nominal"

[values.noise_density_ug_rthz]
axes = { x = 100, y = 100, z = 150 }
doc = "ds"
where = "Table 1"
basis = "typical"

[values.mech_cutoff_hz]
absent = "no resonance given"
stand_in = "none"
why = "not invented"

[values.analog_cutoff_hz]
absent = "no anti-alias corner"
stand_in = { odr_fraction = 0.5, doc = "ds", where = "convention", basis = "nominal" }
why = "the output Nyquist"

[values.digital_cutoff_hz]
odr_fraction = 0.25
doc = "ds"
where = "Table 2"
basis = "setting"

[values.digital_order]
value = 4
doc = "ds"
where = "Table 2"
basis = "nominal"

[modes.range]
default = "2g"
default_why = "power-on"
field = "full_scale_g"
unit = "g"
doc = "ds"
where = "Table 1"
basis = "nominal"
options = ["2g", "8g"]

[modes.odr]
default = "4000"
default_why = "power-on"
field = "sampling_rate_hz"
doc = "ds"
where = "Table 3"
basis = "setting"
options = ["4000", "1000", "100"]
only_with = { "100" = { range = ["2g"] } }
"""


@pytest.fixture
def toy() -> PartSpec:
    """The toy part, validated."""
    return load_part_text(TOY, "toy.toml")
