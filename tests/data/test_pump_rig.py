"""The pump rig's machine file: every figure sourced, and agreeing with docs/data.md's own.

docs/data.md states the rig's defect frequencies from the same geometry
(``Bearings [M]``: the 6309's BPFO 3.037x, 74.9 Hz at 1480 rpm, BPFI 4.963x,
122.4 Hz; the 6308's BPFO 3.072x, 75.8 Hz); the file's numbers must give them.
"""

from __future__ import annotations

import pytest
from sdt_plugins.datasets.pump_rig import RIG_FILE, rig_machines

from sdt_framework.severity import builtin_tables


def test_every_machine_and_bearing_names_its_source() -> None:
    rig = rig_machines()
    assert sorted(rig) == ["Motor-2", "Motor-4"]
    for machine in rig.values():
        assert "[M]" in machine.source and machine.zone_why, machine.name
        for bearing in machine.bearings:
            assert "[M]" in bearing.source and "[G]" in bearing.source, bearing.name
    text = RIG_FILE.read_text(encoding="utf-8")
    for tag in ("[M] the archive's metadata", "[G] the 6309 / 6308 internal geometry"):
        assert tag in text  # each tag is defined in the file's header


def test_the_speeds_motors_and_tables_are_the_documented_ones() -> None:
    m2, m4 = rig_machines()["Motor-2"], rig_machines()["Motor-4"]
    assert (m2.shaft_rpm, m2.speed_percent, m2.poles, m2.power_kw) == (1480, 100, 4, 11)
    assert (m4.shaft_rpm, m4.speed_percent, m4.poles, m4.power_kw) == (2075, 70, 2, 22)
    assert m4.rated_rpm is None  # no source gives Motor-4's speed at 100 %
    assert m4.bearings == ()  # its 6310 and 6306 have no sourced geometry
    tables = builtin_tables()
    assert m2.zone_table in tables and m4.zone_table in tables


def test_the_defect_frequencies_are_those_docs_data_md_states() -> None:
    motor, pump = rig_machines()["Motor-2"].bearings
    shaft = 1480 / 60
    assert (motor.name, motor.channel, motor.faults) == (
        "6309",
        "ch2",
        ("bearing bpfo", "bearing bpfi"),
    )
    assert (pump.name, pump.channel, pump.faults) == ("6308", "ch4", ("bearing pump",))
    assert motor.bpfo == pytest.approx(3.037, abs=5e-4)
    assert motor.bpfo * shaft == pytest.approx(74.9, abs=0.05)
    assert motor.bpfi == pytest.approx(4.963, abs=5e-4)
    assert motor.bpfi * shaft == pytest.approx(122.4, abs=0.05)
    assert pump.bpfo == pytest.approx(3.072, abs=5e-4)
    assert pump.bpfo * shaft == pytest.approx(75.8, abs=0.05)


def test_speed_at_a_point_no_source_gives_is_the_rated_speed_scaled_and_says_so():
    from sdt_framework.specs import MachineSpec, OperatingPoint

    spec = MachineSpec(
        name="m",
        shaft_rpm=1480.0,
        speed_percent=100.0,
        rated_rpm=1480.0,
        operating_points=(OperatingPoint(percent=75.0, shaft_rpm=1101.0, source="log"),),
    )
    assert spec.speed_at(100).shaft_rpm == 1480.0  # its own point
    assert (spec.speed_at(75).shaft_rpm, spec.speed_at(75).source) == (1101.0, "log")
    scaled = spec.speed_at(50)
    assert scaled.shaft_rpm == 740.0 and "no source gives the speed" in scaled.source
    assert MachineSpec(name="n", shaft_rpm=2075.0, speed_percent=70.0).speed_at(50) is None


def test_motor2_speed_folders_carry_the_archive_s_measured_speeds() -> None:
    """740 / 1110 / 1480 rpm at 50 / 75 / 100 % (Motor-4: 2075 at 70 %): pumpwatch's SPEED_RPM,
    read from the archive's 'measurement overview.xlsx' ('Speed (RPM) +- 5'), tagged [M], never
    the scaled rule."""
    m2 = rig_machines()["Motor-2"]
    for percent, rpm in ((50, 740.0), (75, 1110.0), (100, 1480.0)):
        point = m2.speed_at(percent)
        assert point.shaft_rpm == rpm and point.source.startswith("[M]"), percent
        assert "no source gives" not in point.source
    m4 = rig_machines()["Motor-4"]
    assert m4.speed_at(70).shaft_rpm == 2075.0 and m4.speed_at(70).source.startswith("[M] 2075")
    assert m4.speed_at(50) is None  # no rated speed, no point given
