"""The machines of a benchmark: the dataset's own, the config's over them, paths kept right."""

from __future__ import annotations

from pathlib import Path

from sdt_plugins.datasets.pump_rig import rig_machines
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.bench.config import load_config, write_config
from sdt_framework.bench.config_paths import relative_to, resolve_written
from sdt_framework.bench.machines import benchmark_machines
from sdt_framework.data import Dataset
from sdt_framework.machine_files import load_machine_file

TABLE = {"shaft_rpm": 1500.0, "bearings": []}


def test_both_pump_datasets_expose_the_rigs_machines() -> None:
    pump = open_synthetic(machines="Motor-2", duration=0.5)
    assert pump.machines == {"Motor-2": rig_machines()["Motor-2"]}
    assert pump.machines["Motor-2"].shaft_rpm == 1480.0
    assert [b.name for b in pump.machines["Motor-2"].bearings] == ["6309", "6308"]


def test_a_machine_the_config_gives_replaces_the_datasets(tmp_path) -> None:
    dataset = Dataset("d", [], [], machines=dict(rig_machines()))
    config = load_config(None, {"machine_specs": {"Motor-2": TABLE, "pump-B": TABLE}})
    machines = benchmark_machines(config, dataset)
    assert sorted(machines) == ["Motor-2", "Motor-4", "pump-B"]
    assert machines["Motor-2"].shaft_rpm == 1500.0 and machines["Motor-2"].bearings == ()
    assert machines["Motor-2"].origin == "benchmark config"
    assert machines["Motor-4"] == rig_machines()["Motor-4"]


def test_a_machine_files_relative_zone_table_is_read_beside_it(tmp_path) -> None:
    (tmp_path / "plant").mkdir()
    path = tmp_path / "plant" / "machines.toml"
    path.write_text('[machine.p]\nshaft_rpm = 900\nzone_table = "limits.toml#ours"\n')
    (spec,) = load_machine_file(path).values()
    assert spec.zone_table == f"{tmp_path / 'plant' / 'limits.toml'}#ours"
    assert spec.origin == str(path)


def test_the_written_config_keeps_machine_paths_relative_to_its_folder(tmp_path) -> None:
    data = {"machine_specs": str(tmp_path / "rig" / "machines.toml")}
    written = relative_to(data, tmp_path / "results")
    assert written["machine_specs"] == "../rig/machines.toml"
    assert resolve_written(written, tmp_path / "results") == data
    tables = {"machine_specs": {"p": {**TABLE, "zone_table": str(tmp_path / "z.toml#a")}}}
    written = relative_to(tables, tmp_path / "results")
    assert written["machine_specs"]["p"]["zone_table"] == "../z.toml#a"
    assert resolve_written(written, tmp_path / "results") == tables


def test_inline_machines_survive_the_written_config(tmp_path) -> None:
    bearing = {"name": "6205", "balls": 9, "ball_mm": 7.94, "pitch_mm": 39.04,
               "channel": "DE", "faults": ["outer"]}  # fmt: skip
    config = load_config(None, {"machine_specs": {"p": {**TABLE, "bearings": [bearing]}}})
    write_config(config, tmp_path / "config.toml")
    again = load_config(tmp_path / "config.toml", {})
    assert again.machine_specs == config.machine_specs
    dataset = Dataset("d", [], [])
    (spec,) = benchmark_machines(again, dataset).values()
    assert spec.bearings[0].bpfo == 9 / 2 * (1 - 7.94 / 39.04)
    assert (
        Path(tmp_path / "config.toml").read_text().count("[[benchmark.machine_specs.p.bearings]]")
    )
