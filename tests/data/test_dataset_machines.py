"""Every dataset says which machines it describes: the rig for the pump datasets, a user's own.

NLN-EMP hands the rig's machines with the real archive's layout, but only at
the speed each spec is for: a machine read at another speed folder would get
the wrong shaft speed and defect lines, so it gets none, and a note says what
to give. A manifest's machines are its ``machines.toml``; a machine that file
describes and no row names is a note (a misspelt name), not silence.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from sdt_plugins.datasets.nln_emp import open_nln_emp
from sdt_plugins.datasets.pump_rig import rig_machines
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.data import open_manifest, write_nln_emp

from ..helpers import six_recordings


def _archive(tmp_path: Path) -> Path:
    pump = open_synthetic(machines="Motor-2", conditions="healthy", channels="ch1", duration=0.3)
    write_nln_emp(pump, tmp_path)
    return tmp_path


def test_nln_emp_hands_the_rigs_machine_at_its_speed(tmp_path) -> None:
    dataset = open_nln_emp(_archive(tmp_path), cache=False)
    assert dataset.machines == {"Motor-2": rig_machines()["Motor-2"]}
    assert dataset.notes == []


def test_nln_emp_at_another_speed_gets_no_spec_and_a_note(tmp_path) -> None:
    root = _archive(tmp_path)
    shutil.move(root / "Vibration" / "Motor-2" / "100", root / "Vibration" / "Motor-2" / "50")
    dataset = open_nln_emp(root, speeds="50", cache=False)
    assert {r.speed for r in dataset.recordings()} == {"50"}
    assert dataset.machines == {}
    (note,) = dataset.notes
    assert note.startswith(
        "Motor-2: the rig's machine spec is for 100 % speed (1480 rpm), the recordings are "
        "at 50 % (each carries its speed_rpm): no machine spec"
    )
    assert "[benchmark.machine_specs.Motor-2]" in note


def test_a_manifests_machines_toml_is_read_and_listed(sdt_main, tmp_path, readers) -> None:
    manifest = six_recordings(tmp_path)
    (tmp_path / "machines.toml").write_text(
        "[machine.m]\nshaft_rpm = 1500\n[machine.M]\nshaft_rpm = 900\n", encoding="utf-8"
    )
    dataset = open_manifest(manifest, readers=readers)
    assert dataset.machines["m"].shaft_rpm == 1500.0
    assert dataset.machines["m"].origin == str(tmp_path / "machines.toml")
    (note,) = dataset.notes
    assert note == f"{tmp_path / 'machines.toml'} describes 'M', which no manifest row names " \
        "(machines: 'm')"  # fmt: skip
    code, out, err = sdt_main("dataset", "inspect", str(manifest), "--json")
    assert code == 0, err
    listed = json.loads(out)["machines"]
    assert sorted(listed) == ["M", "m"] and listed["m"]["shaft_rpm"] == 1500.0


def test_a_manifest_without_machines_toml_describes_none(tmp_path, readers) -> None:
    assert open_manifest(six_recordings(tmp_path), readers=readers).machines == {}
