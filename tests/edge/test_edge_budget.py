"""The daily budget: payload arithmetic, fit per data rate, duty cycle, energy."""

from __future__ import annotations

import math

import pytest

from sdt_framework import SDTError
from sdt_framework.edge import RADIOS, Radio, edge_budget, format_interval, parse_interval
from sdt_framework.edge import report_bytes as payload


def test_paper8_is_32_bytes_per_axis_and_96_triaxial(paper8):
    assert len(paper8.feature_names) * 4 == 32 == payload(paper8)  # 8 features x float32
    assert payload(paper8, axes=3) == 96
    assert payload(paper8, axes=3, dtype="float16") == 48  # float16 halves it


def test_96_bytes_do_not_fit_sf10_to_sf12_in_eu868(paper8):
    budget = edge_budget(paper8, axes=3, interval_s=600, region="EU868")
    by_dr = {row.data_rate: row for row in budget.rows}
    assert [by_dr[f"DR{i}"].fits for i in range(7)] == [False] * 3 + [True] * 4
    # DR0-DR2 carry N = 51 bytes: the 96-byte report needs two uplinks (51 + 45)
    assert [by_dr[f"DR{i}"].messages_per_report for i in range(3)] == [2, 2, 2]
    assert [row.data_rate for row in budget.fitting()] == ["DR3", "DR4", "DR5", "DR6"]


def test_float16_report_fits_every_eu868_data_rate(paper8):
    budget = edge_budget(paper8, axes=3, region="EU868", dtype="float16")
    assert budget.app_payload_bytes == 48 and budget.dtypes == ("float16",)
    assert all(row.fits for row in budget.rows)


def test_airtime_messages_and_energy_by_hand_at_sf7(paper8):
    # PHY 109 B at SF7/125: ceil((872 - 28 + 28 + 16) / 28) = 32 -> 8 + 160 symbols;
    # (8 + 4.25 + 168) x 1.024 ms = 184.576 ms. 10 min -> 144 reports a day.
    budget = edge_budget(paper8, axes=3, interval_s=600, region="EU868")
    dr5 = budget.rows[5]
    assert dr5.modulation == "SF7/125 kHz"
    assert dr5.time_on_air_s == pytest.approx(0.184576)
    assert budget.reports_per_day == 144 and dr5.messages_per_day == 144
    assert dr5.airtime_per_day_s == pytest.approx(144 * 0.184576)
    assert dr5.transmit_fraction == pytest.approx(144 * 0.184576 / 86400)
    # default radio: SX1276 +13 dBm on RFO, 29 mA at 3.3 V
    assert dr5.energy_per_report_j == pytest.approx(0.029 * 3.3 * 0.184576)
    assert dr5.energy_per_day_j == pytest.approx(144 * 0.029 * 3.3 * 0.184576)


def test_split_report_costs_the_sum_of_its_uplinks(paper8):
    # DR0 (SF12/125, LDRO on): 51 + 45 application bytes -> PHY 64 and 58 bytes:
    # ceil((512 - 48 + 44) / 40) = 13 -> 73 symbols; ceil((464 - 48 + 44) / 40) = 12 -> 68;
    # (12.25 + 73) + (12.25 + 68) symbols of 32.768 ms.
    dr0 = edge_budget(paper8, axes=3, region="EU868").rows[0]
    assert dr0.time_on_air_s == pytest.approx((85.25 + 80.25) * 32.768e-3)
    assert dr0.longest_message_s == pytest.approx(85.25 * 32.768e-3)
    assert dr0.messages_per_day == 288


def test_a_report_of_many_uplinks_costs_each_uplink_once(paper8):
    # 1000 axes x 32 bytes = 32000 application bytes at DR0 (51 per uplink): 627 uplinks
    # of 51 bytes (PHY 64: 85.25 symbols, as above) and one of 32000 - 627 x 51 = 23 bytes:
    # PHY 36, ceil((288 - 48 + 44) / 40) = 8 -> 8 + 8 x 5 = 48 symbols after the preamble.
    dr0 = edge_budget(paper8, axes=1000, region="EU868").rows[0]
    assert dr0.messages_per_report == math.ceil(32000 / 51) == 628
    assert dr0.time_on_air_s == pytest.approx((627 * 85.25 + 12.25 + 48) * 32.768e-3, rel=1e-12)
    assert dr0.longest_message_s == pytest.approx(85.25 * 32.768e-3)


def test_duty_cycle_sets_the_shortest_interval(paper8):
    # 1 % in EU868: T_off = T/0.01 - T, so one report per T/0.01 at best
    slow = edge_budget(paper8, axes=3, interval_s=300, region="EU868").rows[0]
    assert slow.min_interval_s == pytest.approx(slow.time_on_air_s / 0.01)
    assert slow.min_interval_s > 300 and slow.duty_cycle_ok is False
    assert edge_budget(paper8, axes=3, interval_s=600, region="EU868").rows[0].duty_cycle_ok


def test_us915_has_no_duty_cycle_but_a_dwell_time(paper8):
    budget = edge_budget(paper8, axes=3, region="US915")
    assert budget.duty_cycle is None
    assert all(row.min_interval_s is None and row.duty_cycle_ok is None for row in budget.rows)
    dr0 = budget.rows[0]
    assert dr0.messages_per_report == math.ceil(96 / 11) == 9
    assert dr0.dwell_ok is True and budget.rows[4].dwell_ok is None


def test_radio_model_can_be_replaced(paper8):
    mine = Radio("my-radio", tx_current_a=0.045, supply_v=3.0)
    row = edge_budget(paper8, axes=1, region="EU868", radio=mine).rows[5]
    assert row.energy_per_report_j == pytest.approx(0.045 * 3.0 * row.time_on_air_s)
    boost = edge_budget(paper8, axes=1, region="EU868", radio="sx1276-boost-20dbm").rows[5]
    assert boost.energy_per_report_j / row.energy_per_report_j == pytest.approx(
        0.120 * 3.3 / (0.045 * 3.0)
    )
    assert RADIOS["sx1276-rfo-13dbm"].tx_current_a == 0.029
    with pytest.raises(SDTError, match="supply_v"):
        Radio("bad", tx_current_a=0.01, supply_v=0)


@pytest.mark.parametrize(
    ("text", "seconds"),
    [("10min", 600), ("30s", 30), ("1h", 3600), ("1.5h", 5400), ("2d", 172800), (600, 600)],
)
def test_interval_parsing(text, seconds):
    assert parse_interval(text) == seconds
    assert parse_interval(format_interval(seconds)) == seconds


@pytest.mark.parametrize("text", ["abc", "10m", "0min", "-5s", ""])
def test_bad_interval_is_one_clear_error(text):
    with pytest.raises(SDTError, match="interval"):
        parse_interval(text)


def test_bad_axes_and_interval_are_errors(paper8):
    with pytest.raises(SDTError, match="axes"):
        edge_budget(paper8, axes=0)
    with pytest.raises(SDTError, match="interval"):
        edge_budget(paper8, interval_s=0)
