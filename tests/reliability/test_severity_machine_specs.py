"""A machine spec a user writes wrong is one line naming the file and the field, exit 2.

The machine file beside a manifest (``machines.toml``), the config's
``machine_specs`` tables and the machine file a config names are read before
any run: a missing field, a bearing whose ball is as large as its pitch circle
(or whose balls do not fit around it), a number written as text and a zone
table name that does not exist each stop the command with one line, nothing
on stdout, no traceback. Before the rig became data none of these files was
read at all.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ..helpers import six_recordings

GOOD = """
[machine.m]
shaft_rpm = 1480
zone_table = "iso10816-3-group2-rigid"

[[machine.m.bearings]]
name = "6205"
balls = 9
ball_mm = 7.94
pitch_mm = 39.04
channel = "ch1"
faults = ["fault"]
"""

QUICK = ("--quick", "--sensors", "wilcoxon-786b10", "--classifiers", "lr", "--scenarios")


def _one_line(code: int, out: str, err: str) -> str:
    assert code == 2, err
    assert out == "" and "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[0]


@pytest.mark.parametrize(
    "bad, field, words",
    [
        (GOOD.replace("shaft_rpm = 1480\n", ""), "machine.m.shaft_rpm", "Field required"),
        (GOOD.replace("pitch_mm = 39.04", "pitch_mm = 7.94"), "machine.m.bearings.0",
         "ball_mm 7.94 >= pitch_mm 7.94: a ball cannot be as large as its pitch circle"),
        (GOOD.replace("balls = 9", "balls = 30"), "machine.m.bearings.0",
         "30 balls of 7.94 mm do not fit around a 39.04 mm pitch circle"),
        (GOOD.replace("shaft_rpm = 1480", 'shaft_rpm = "1480"'), "machine.m.shaft_rpm",
         "must be a number, got the string '1480': drop the quotes"),
        (GOOD.replace('channel = "ch1"\n', ""), "machine.m.bearings.0.channel", "Field required"),
    ],
)  # fmt: skip
def test_a_bad_machines_toml_beside_the_manifest_is_one_line(
    sdt_main, tmp_path: Path, bad: str, field: str, words: str
) -> None:
    manifest = six_recordings(tmp_path)
    (tmp_path / "machines.toml").write_text(bad, encoding="utf-8")
    line = _one_line(*sdt_main("dataset", "inspect", str(manifest)))
    assert line.startswith(f"error: {tmp_path / 'machines.toml'}: field {field!r}:"), line
    assert words in line


def test_a_zone_table_name_that_does_not_exist_stops_the_benchmark(sdt_main, tmp_path) -> None:
    manifest = six_recordings(tmp_path)
    (tmp_path / "machines.toml").write_text(GOOD.replace("group2-rigid", "group9"))
    out_dir = tmp_path / "out"
    line = _one_line(
        *sdt_main("benchmark", "--data", str(manifest), *QUICK, "forward", "--out", str(out_dir))
    )
    assert line.startswith(
        f"error: {tmp_path / 'machines.toml'}: machine 'm' field 'zone_table': unknown zone "
        f"table 'iso10816-3-group9'; give a built-in name"
    ), line
    assert not out_dir.exists()  # refused before the folder was claimed


def test_a_bad_machine_table_in_the_config_names_the_config(sdt_main, tmp_path) -> None:
    manifest = six_recordings(tmp_path)
    config = tmp_path / "bench.toml"
    config.write_text(
        f'[benchmark]\ndata = "{manifest}"\n[benchmark.machine_specs.m]\nshaft_rpm = -5\n'
    )
    line = _one_line(*sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line.startswith(f"error: {config}: field 'machine_specs.m.shaft_rpm':"), line
    assert "greater than 0" in line


def test_a_machine_file_the_config_names_must_exist(sdt_main, tmp_path) -> None:
    manifest = six_recordings(tmp_path)
    config = tmp_path / "bench.toml"
    config.write_text(f'[benchmark]\ndata = "{manifest}"\nmachine_specs = "nowhere.toml"\n')
    line = _one_line(*sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line.startswith("error: nowhere.toml: file not found"), line
