"""The part model rejects structures that would leave a value without a source or a mode."""

from __future__ import annotations

import pytest

from sdt_framework.errors import SpecFileError
from sdt_framework.parts import load_part_file, load_part_text

from .conftest import TOY


def edited(old: str, new: str) -> str:
    assert old in TOY
    return TOY.replace(old, new, 1)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            edited('doc = "ds"\nwhere = "Table 1"\nbasis = "nominal"\n', 'doc = "ds"\n'),
            "a value needs its provenance: doc, where and basis",
        ),
        (edited('doc = "ds"', 'doc = "nope"'), "document 'nope' is not in \\[documents\\]"),
        (edited('why = "not invented"', 'why = ""'), "an absent value needs stand_in and why"),
        (
            edited("[values.adc_bits]\nvalue = 16", "[values.adc_bits]\nodr_fraction = 0.1"),
            "only a filter cutoff can be a fraction of the ODR",
        ),
        (edited("[values.adc_bits]", "[values.adc_bitz]"), "unknown value 'adc_bitz'"),
        (edited('default = "2g"', 'default = "3g"'), "default '3g' is not one of"),
        (edited('interface = "digital"', 'interface = "digital"\nfoo = 1'), "unknown field"),
    ],
)
def test_bad_part_files_name_the_file_field_and_reason(text, message):
    with pytest.raises(SpecFileError, match=message) as info:
        load_part_text(text, "toy.toml")
    assert str(info.value).startswith("toy.toml:")


def test_a_value_missing_for_some_mode_is_rejected():
    text = edited(
        '[values.digital_order]\nvalue = 4\ndoc = "ds"\nwhere = "Table 2"\nbasis = "nominal"\n',
        "",
    ) + (
        '\n[modes.filt]\ndefault = "a"\ndefault_why = "x"\n[modes.filt.options.b]\n'
        '[modes.filt.options.a.digital_order]\nvalue = 4\ndoc = "ds"\nwhere = "T"\n'
        'basis = "nominal"\n'
    )
    # digital_order now exists only for filt=a: filt=b would have none
    with pytest.raises(SpecFileError, match="digital_order is not given for every mode"):
        load_part_text(text, "toy.toml")


def test_two_mode_keys_may_not_set_the_same_value():
    text = (
        TOY
        + '\n[modes.extra]\ndefault = "a"\ndefault_why = "x"\n'
        + (
            '[modes.extra.options.a.full_scale_g]\nvalue = 4\ndoc = "ds"\nwhere = "T"\n'
            'basis = "nominal"\n'
        )
    )
    with pytest.raises(SpecFileError, match="full_scale_g is set by two mode keys"):
        load_part_text(text, "toy.toml")


def test_missing_and_invalid_toml_files(tmp_path):
    with pytest.raises(SpecFileError, match="file not found"):
        load_part_file(tmp_path / "none.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("name = ")
    with pytest.raises(SpecFileError, match="not valid TOML"):
        load_part_file(bad)
