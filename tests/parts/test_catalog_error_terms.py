"""Every catalogue part's error terms against the datasheet figures, written here independently.

The table was typed from the research notes (/work/helpers/datasheets/<part>.md,
read from the documents each part cites), converted to the stage parameters'
units by hand: mg/°C, %/°C, % of full scale, %. Totals printed over a
temperature range are divided here by the largest distance from 25 °C in that
range (MPU-6050: ±35 mg over 0..70 °C -> 35/45 mg/°C). The per-unit draw
follows the documented rule, applied here, not read from the code: a normal
with SD = the typical figure, unless only a maximum is given or 3 typical SDs
would pass the maximum, then uniform over ± the maximum. The nonlinearity's
stage parameter is 3/2 of the figure (a second-order term deviates from its
least-squares line by 2/3 of its value at full scale).
"""

from __future__ import annotations

import pytest

from sdt_framework.parts import ErrorTermsError, resolve

pytestmark = pytest.mark.catalog
catalogue = pytest.importorskip("sdt_sensors_catalog", reason="install plugins/sensors-catalog")
PARTS = {part.name: part for part in catalogue.load_parts()}

#: term -> (stage.parameter, factor from the figure to the parameter's spread)
STAGE = {
    "offset_tempco": ("offset.tempco_mg_per_c", 1.0),
    "sensitivity_tempco": ("scale.tempco_pct_per_c", 1.0),
    "nonlinearity": ("nonlinearity.second_pct_fs", 1.5),
    "cross_axis": ("cross-axis.pct", 1.0),
}

#: part -> term -> (typical, maximum): a number, (x, y, z), or {range option: number};
#: a missing term is absent (the documents give no figure)
NOTES: dict[str, dict[str, tuple[object, object]]] = {
    "adxl1002": {},  # data sheet not read; no secondary source gives a term
    # ADXL313 Rev. D Table 1
    "adxl313": {"offset_tempco": ((0.5, 0.5, 0.75), None), "sensitivity_tempco": (0.01, None),
                "nonlinearity": (0.5, None), "cross_axis": (1, None)},
    # ADXL345 Rev. G Table 1
    "adxl345-ds": {"offset_tempco": ((0.4, 0.4, 1.2), None), "sensitivity_tempco": (0.01, None),
                   "nonlinearity": (0.5, None), "cross_axis": (1, None)},
    # ADXL355 Rev. D Table 2: offset tempco +/-0.01 typ, +/-0.15 max; NL at 2 g and 8 g only
    "adxl355": {"offset_tempco": (0.01, 0.15), "sensitivity_tempco": (0.01, None),
                "nonlinearity": ({"2g": 0.1, "8g": 1.6}, None), "cross_axis": (1, None)},
    # ADXL357 page 1: 0.75 mg/°C max; the rest from the ADXL356-EP drawing (stand-ins)
    "adxl357-ds": {"offset_tempco": (None, 0.75), "sensitivity_tempco": (0.01, None),
                   "nonlinearity": ({"10g": 0.1}, None), "cross_axis": (1, None)},
    # ADXL372 Rev. C Table 1 (normal operation)
    "adxl372": {"offset_tempco": (50, None), "sensitivity_tempco": (0.1, None),
                "nonlinearity": (0.5, None), "cross_axis": (2.5, None)},
    # BMI270 rev 1.5 Table 2: TCOA, TCSA, NLA at 2 g, SXA
    "bmi270": {"offset_tempco": (0.25, None), "sensitivity_tempco": (0.004, None),
               "nonlinearity": ({"2g": 0.5}, None), "cross_axis": (1, None)},
    # IIM-42352 DS-000442 Table 1: NL at +/-2 g
    "iim42352": {"offset_tempco": (0.15, None), "sensitivity_tempco": (0.005, None),
                 "nonlinearity": ({"2g": 0.1}, None), "cross_axis": (1, None)},
    # IIS3DWB DS12569 Rev 7 Table 3: SoDr +/-1 % typ, +/-2 % max over -40..105 (80 °C from 25)
    "iis3dwb": {"offset_tempco": (1, None), "sensitivity_tempco": (1 / 80, 2 / 80)},
    # ISM330DHCX DS13012 Rev 7 Table 2
    "ism330dhcx": {"offset_tempco": (0.1, 0.5), "sensitivity_tempco": (0.005, 0.01),
                   "cross_axis": (0.5, None)},
    # KX134 Specifications Rev 1.0 Table 1
    "kx134": {"offset_tempco": (0.5, None), "sensitivity_tempco": (0.01, None),
              "nonlinearity": (0.6, None), "cross_axis": (2, None)},
    # LIS2DW12 DS11811 Rev 9 Table 3
    "lis2dw12": {"offset_tempco": (0.2, None), "sensitivity_tempco": (0.01, None)},
    # LIS3DH DocID17530 Rev 2 Table 4
    "lis3dh": {"offset_tempco": (0.5, None), "sensitivity_tempco": (0.01, None)},
    # MPU-6050 PS Rev 3.4 section 6.2: zero-g change +/-35 mg X/Y, +/-60 mg Z over 0..70 °C
    "mpu6050": {"offset_tempco": ((35 / 45, 35 / 45, 60 / 45), None),
                "sensitivity_tempco": (0.02, None), "nonlinearity": (0.5, None),
                "cross_axis": (2, None)},
}  # fmt: skip


def expected_draw(typ, maximum) -> tuple[str, float]:
    """The documented rule: (distribution, SD or half-width) from a typical and a maximum."""
    if typ is None or (maximum is not None and 3 * typ > maximum):
        return "uniform", maximum
    return "normal", typ


def on_axes(figure, option: str | None) -> tuple[float, float, float] | None:
    if isinstance(figure, dict):
        figure = figure.get(option)
    if figure is None or isinstance(figure, tuple):
        return figure
    return (figure,) * 3


def test_the_table_covers_the_catalogue():
    assert set(NOTES) == set(PARTS)
    for name, part in PARTS.items():
        assert set(part.errors) == set(STAGE), name  # every term given or marked absent


@pytest.mark.parametrize("name", sorted(NOTES))
def test_error_terms_match_the_datasheets_in_every_range(name):
    part, notes = PARTS[name], NOTES[name]
    ranges = list(part.modes["range"].options) if "range" in part.modes else [None]
    for option in ranges:
        mode = {"range": option} if option else {}
        enabled = {"errors": "datasheet", "cross_axis": "datasheet"}
        wanted = {}
        for term, (stage, factor) in STAGE.items():
            typ, maximum = notes.get(term, (None, None))
            typ_axes, max_axes = on_axes(typ, option), on_axes(maximum, option)
            if typ_axes is None and max_axes is None:
                continue
            pairs = [
                expected_draw(t, m)
                for t, m in zip(typ_axes or (None,) * 3, max_axes or (None,) * 3, strict=True)
            ]
            wanted[stage] = (pairs[0][0], [factor * spread for _, spread in pairs])
        if not any(s.startswith("cross-axis") for s in wanted):
            enabled.pop("cross_axis")
        if not wanted.keys() - {"cross-axis.pct"}:
            enabled.pop("errors")
        if not enabled:
            with pytest.raises(ErrorTermsError, match="give no"):
                resolve(part, {**mode, "errors": "datasheet"})
            continue
        sensor = resolve(part, {**mode, **enabled}).sensor
        got = {
            key: (tol.distribution, [tol.spread, tol.per_axis["y"], tol.per_axis["z"]])
            for key, tol in sensor.tolerances.items()
        }
        assert got.keys() == wanted.keys(), (name, option)
        for key, (distribution, spreads) in wanted.items():
            assert got[key][0] == distribution, (name, option, key)
            assert got[key][1] == pytest.approx(spreads, rel=1e-4), (name, option, key)


@pytest.mark.parametrize("name", sorted(NOTES))
def test_every_term_says_where_it_comes_from_or_why_it_is_absent(name):
    part = PARTS[name]
    for term in resolve(part).terms:
        if term.figure is not None:
            assert term.source and term.where and term.basis and term.printed, (name, term)
            assert term.source.startswith(part.documents[term.doc].title)
        else:
            assert term.absent, (name, term.term)
        if term.stand_in:  # a figure from another document says why that one
            assert term.why and term.absent


def test_stand_ins_and_conversions_are_shown_as_such():
    adxl357 = {t.term: t for t in resolve(PARTS["adxl357-ds"], {"range": "10g"}).terms}
    assert not adxl357["offset_tempco"].stand_in  # the ADXL357's own page 1
    assert adxl357["cross_axis"].stand_in and adxl357["cross_axis"].doc == "vid"
    mpu = {t.term: t for t in resolve(PARTS["mpu6050"]).terms}
    assert "35/45" in mpu["offset_tempco"].note and mpu["offset_tempco"].range_c == (0, 70)
    iis3dwb = {t.term: t for t in resolve(PARTS["iis3dwb"]).terms}
    assert "80 °C" in iis3dwb["sensitivity_tempco"].note
