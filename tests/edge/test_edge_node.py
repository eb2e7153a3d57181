"""The node energy model against hand calculations, its cells, and its bad input."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework import SDTError
from sdt_framework.edge import Radio
from sdt_framework.edge import node_defaults as nd
from sdt_framework.edge.cells import Cell, cell, life_years
from sdt_framework.edge.node import NodeSettings, battery_life_years, node_budget
from sdt_framework.specs import SensorSpec
from sdt_framework.specs.supply import Supply, SupplyFigure


def _figure(value: float) -> SupplyFigure:
    return SupplyFigure(value=value, doc="test", where="test", printed=f"{value:g}")


@pytest.fixture
def sensor():
    """A made-up sensor: 100 uA measuring, 1 uA standby, 10 ms turn-on, 3200 Hz."""
    return SensorSpec(
        name="hand",
        sampling_rate_hz=3200,
        full_scale_g=16,
        adc_bits=13,
        noise_density_ug_rthz=100,
        mech_cutoff_hz=None,
        analog_cutoff_hz=None,
        supply=Supply(measure_ua=_figure(100), standby_ua=_figure(1), turn_on_ms=_figure(10)),
    )


def test_charge_per_report_and_life_match_the_hand_calculation(sensor, paper8):
    settings = NodeSettings(
        interval_s=600,
        window_s=0.5,
        axes=3,
        data_rate="DR5",
        radio=Radio("hand-radio", 20e-3, 3.3),
        rx_current_a=10e-3,
        rx_symbols=8,
        sleep_current_a=2e-6,
        mcu_current_a=5e-3,
        mcu_time_s=0.01,
        mcu_acquire_current_a=4e-3,
        regulator_current_a=3e-6,
    )
    battery = Cell("hand-cell", 1000.0, 3.6, 0.02, 50.0, "test")
    result = node_budget(sensor, paper8, battery, settings)
    # Time on air at DR5 (SF7, 125 kHz), paper8 x 3 axes x float32 = 96 B + 13 B = 109 B:
    # T_sym = 2**7 / 125e3 = 1.024 ms; preamble (8 + 4.25) x 1.024 = 12.544 ms;
    # n_payload = 8 + ceil((8 x 109 - 4 x 7 + 28 + 16) / (4 x 7)) x 5 = 8 + 32 x 5 = 168;
    # ToA = 12.544 + 168 x 1.024 = 184.576 ms.
    toa = 0.184576
    rx1 = 8 * 1.024e-3  # 8 symbols at SF7/125 kHz
    rx2 = 8 * 32.768e-3  # 8 symbols at SF12/125 kHz (EU868 RX2)
    expected = {
        "accelerometer measuring": 100e-6 * (0.010 + 0.5),  # 51 uC
        "accelerometer standby": 1e-6 * (600 - 0.51),  # 599.49 uC
        "microcontroller acquiring": 4e-3 * (0.010 + 0.5),  # 2040 uC: awake through the window
        "microcontroller features": 5e-3 * 0.01,  # 50 uC
        "radio transmit (DR5)": 20e-3 * toa,  # 3691.52 uC
        "radio RX1": 10e-3 * rx1,  # 81.92 uC
        "radio RX2": 10e-3 * rx2,  # 2621.44 uC
        "regulator quiescent": 3e-6 * 600,  # 1800 uC: the whole interval
        "node sleep": 2e-6 * (600 - 0.51 - 0.01 - toa - rx1 - rx2),  # 1198.050176 uC
    }
    got = {stage.consumer: stage.charge_c for stage in result.stages}
    assert got == pytest.approx(expected, rel=1e-12)
    total = 12133.420176e-6  # the sum of the nine charges above, C
    assert result.charge_per_report_c == pytest.approx(total, rel=1e-12)
    assert result.average_current_a == pytest.approx(total / 600, rel=1e-12)
    assert result.energy_per_report_j == pytest.approx(total * 3.6, rel=1e-12)
    # life = 1 / (I [mA] x 8766 h / C [mAh] + s) = 1 / (0.0202224 x 8.766 + 0.02) years
    assert result.life_years == pytest.approx(1 / (total / 600 * 1e3 * 8.766 + 0.02), rel=1e-12)
    assert result.life_years == pytest.approx(5.0692, abs=1e-4)
    assert not result.life_capped
    assert result.notes == (nd.NOT_COUNTED,)  # every figure given: only what is never counted


def test_unknown_figures_are_listed_not_filled_in(sensor, paper8):
    settings = NodeSettings(data_rate="DR5", mcu_current_a=None)  # run current not known
    result = node_budget(sensor, paper8, cell("D"), settings)
    for consumer in ("microcontroller features", "microcontroller acquiring"):
        mcu = next(s for s in result.stages if s.consumer == consumer)
        assert mcu.charge_c is None and mcu.current_a is None
        assert any(f"{consumer} not counted" in n for n in result.notes)
    assert result.charge_per_report_c == pytest.approx(
        sum(s.charge_c for s in result.stages if s.charge_c is not None)
    )


def test_a_split_report_pays_one_rx_pair_per_uplink(registry, paper8):
    """96 B at EU868 DR0 (51 B per uplink) goes in 2 uplinks, each followed by RX1 and RX2."""
    budget = node_budget(
        registry.sensor("adxl345"), paper8, cell("2xAA"), NodeSettings(data_rate="DR0")
    )
    assert budget.uplinks == 2
    stages = {s.consumer: s for s in budget.stages}
    symbol = 2**12 / 125e3  # SF12/125 kHz: 32.768 ms; RX1 (offset 0) and RX2 are both SF12
    i_rx = 13.6e-3  # the RAK4260 module's receive current (radios.toml)
    for window in ("radio RX1", "radio RX2"):
        assert stages[window].time_s == pytest.approx(2 * 8 * symbol)
        assert stages[window].charge_c == pytest.approx(2 * i_rx * 8 * symbol)  # 7.13 mC each
    one = node_budget(registry.sensor("adxl345"), paper8.with_dtype("float16"), cell("2xAA"),
                      NodeSettings(data_rate="DR0"))  # fmt: skip
    assert one.uplinks == 1  # 48 B fits one DR0 uplink: one pair
    assert {s.consumer: s.time_s for s in one.stages}["radio RX1"] == pytest.approx(8 * symbol)


def test_microcontroller_regulator_and_module_terms_by_hand(registry, paper8):
    budget = node_budget(registry.sensor("adxl345"), paper8, cell("2xAA"))
    stages = {s.consumer: s for s in budget.stages}
    # awake at 91 uA/MHz x 80 MHz while the window is acquired (no turn-on time on record)
    assert stages["microcontroller acquiring"].current_a == pytest.approx(91e-6 * 80)
    assert stages["microcontroller acquiring"].charge_c == pytest.approx(7.28e-3 * 0.64)
    assert stages["regulator quiescent"].charge_c == pytest.approx(1.6e-6 * 600)  # MCP1700
    assert stages["radio transmit (DR3)"].current_a == pytest.approx(33.1e-3)  # RAK4260, 14 dBm
    assert stages["radio RX1"].current_a == pytest.approx(13.6e-3)
    assert budget.radio == "rak4260-14dbm"
    lower = node_budget(registry.sensor("adxl345"), paper8, cell("2xAA"),
                        NodeSettings(mcu_acquire_current_a=2.57e-6))  # fmt: skip
    assert budget.charge_per_report_c - lower.charge_per_report_c == pytest.approx(
        (7.28e-3 - 2.57e-6) * 0.64
    )


def test_life_years_hand_values():
    plain = Cell("plain", 2600.0, 3.6, 0.0, 1000.0, "test")
    assert life_years(0.1e-3, plain) == pytest.approx(2600 / 0.1 / 8766)  # 26000 h
    assert life_years(0.0, plain) == 1000.0  # no drain, no self-discharge: the shelf life
    leaky = Cell("leaky", 2600.0, 3.6, 0.05, 1000.0, "test")
    assert life_years(0.0, leaky) == pytest.approx(20.0)  # 5 % a year alone: 20 years
    capped = Cell("capped", 2600.0, 3.6, 0.05, 10.0, "test")
    assert life_years(0.0, capped) == 10.0


def test_battery_life_function_for_explore(registry, paper8):
    adxl345 = registry.sensor("adxl345")
    years = battery_life_years(adxl345, paper8, cell("2xAA"))
    assert years == pytest.approx(node_budget(adxl345, paper8, cell("2xAA")).life_years)
    assert battery_life_years(registry.sensor("wilcoxon-786b10"), paper8, cell("2xAA")) is None


def test_interval_shorter_than_acquisition_plus_transmission_is_refused(sensor, paper8):
    with pytest.raises(SDTError, match="shorter than one acquisition"):
        node_budget(sensor, paper8, cell("C"), NodeSettings(interval_s=0.6, region="US915"))


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--battery", "AAA"], "error: unknown battery 'AAA'"),
        (["--sensor-current-ua", "-3"], "error: --sensor-current-ua must be a number >= 0"),
        (["--mcu-current-ma", "-1"], "error: --mcu-current-ma must be a number >= 0"),
        (["--interval", "0.5s", "--region", "US915"], "error: interval 0.5 s is shorter than"),
        (
            [
                "--capacity-mah",
                "0",
                "--cell-voltage",
                "3.6",
                "--self-discharge-pct",
                "1",
                "--shelf-life-years",
                "10",
            ],
            "error: --capacity-mah must be > 0 mAh",
        ),
    ],
)
def test_node_bad_input_is_one_line_and_exit_2(sdt_main, args, message):
    code, _, err = sdt_main("budget", "--sensor", "adxl345", *args)  # refused before any work
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith(message), err


def test_non_dominated_by_hand():
    from sdt_framework.edge.life_objective import non_dominated

    # (cost, -macro_f1, -life): c is dominated by a (cheaper, as good, longer life);
    # b trades cost for life; d has no life (NaN): never on the front.
    objectives = np.array(
        [
            [1.0, -0.80, -8.0],  # a
            [2.0, -0.80, -9.0],  # b
            [1.5, -0.80, -7.0],  # c
            [0.5, -0.90, np.nan],  # d
        ]
    )
    assert non_dominated(objectives).tolist() == [True, True, False, False]


def test_point_lives_nan_where_no_supply(registry, paper8):
    from sdt_framework.edge.life_objective import point_lives

    lives = point_lives([registry.sensor("adxl345"), registry.sensor("wilcoxon-786b10")], paper8)
    assert lives[0] == pytest.approx(
        node_budget(registry.sensor("adxl345"), paper8, cell("2xAA")).life_years
    )
    assert np.isnan(lives[1])


def test_default_microcontroller_stage_by_hand(registry, paper8):
    # 3200 Hz x 0.64 s = 2048 samples per axis: the reference FFT itself, 2439 us at
    # 120 MHz = 292 680 cycles per axis; at 91 uA/MHz the charge is 91 pC per cycle.
    budget = node_budget(registry.sensor("adxl345"), paper8, cell("2xAA"))
    mcu = next(s for s in budget.stages if s.consumer == "microcontroller features")
    assert mcu.time_s == pytest.approx(3 * 292680 / 80e6)  # 10.98 ms at 80 MHz
    assert mcu.current_a == pytest.approx(91e-6 * 80)  # 7.28 mA
    assert mcu.charge_c == pytest.approx(3 * 292680 * 91e-12)  # 79.9 uC


def test_a_set_in_orders_costs_its_ffts_and_the_speed_estimate(sensor, paper8, registry):
    """orders: 3 FFTs of the window per axis and one 8x zero-padded FFT for the speed."""
    orders = registry.feature_set("orders")
    settings = NodeSettings(interval_s=600, window_s=0.64, axes=3)
    battery = cell("2xAA")
    t_mcu = {
        spec.name: next(
            s.time_s for s in node_budget(sensor, spec, battery, settings).stages
            if s.consumer == "microcontroller features"
        )
        for spec in (paper8, orders)
    }  # fmt: skip

    # node.toml: arm_cfft_f32, 2048 points, 2439 us at 120 MHz; the node runs at 80 MHz and
    # an FFT of N points takes N log2 N / (2048 x 11) of that
    def fft(n: int) -> float:
        return 2439e-6 * 120 / 80 * n * np.log2(n) / (2048 * 11)

    n = 2048  # 0.64 s at 3200 Hz
    assert t_mcu["paper8"] == pytest.approx(3 * fft(n), rel=1e-9)  # 11.0 ms, as before
    assert t_mcu["orders"] == pytest.approx(3 * 3 * fft(n) + fft(8 * n), rel=1e-9)  # 70.2 ms
