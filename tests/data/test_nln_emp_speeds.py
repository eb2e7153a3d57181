"""NLN-EMP reads every speed folder of the archive, speed on every recording (issue 43).

A tree in the archive's layout is written by hand here: Motor-2 at 50, 75 and
100 %, Motor-4 at 70 % and at a folder the rig gives no speed for (50 %). The
expected shaft speeds are the archive's own as its public readers give them
(pumpwatch's SPEED_RPM, read from "measurement overview.xlsx": Motor-2 740 /
1110 / 1480 rpm, Motor-4 at 70 % 2075 rpm), written here as numbers, not read
from the rig file the reader uses.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from sdt_plugins.datasets.nln_emp import open_nln_emp

from sdt_framework.errors import SDTError

from .test_data_nln_emp import signal, write_csv

ARCHIVE_RPM = {("Motor-2", "50"): 740.0, ("Motor-2", "75"): 1110.0,
               ("Motor-2", "100"): 1480.0, ("Motor-4", "70"): 2075.0}  # fmt: skip


@pytest.fixture
def archive(tmp_path: Path) -> Path:
    runs = [
        ("Motor-2", "50", "healthy 1"),
        ("Motor-2", "50", "bearing bpfo 2"),
        ("Motor-2", "75", "healthy 1"),
        ("Motor-2", "75", "impeller 1"),
        ("Motor-2", "100", "healthy 1"),
        ("Motor-2", "100", "bearing pump 1"),
        ("Motor-4", "70", "healthy 1"),
        ("Motor-4", "50", "healthy 1"),
    ]
    for i, (machine, speed, run) in enumerate(runs):
        for ch in ("ch1", "ch2"):
            write_csv(tmp_path, machine, speed, run, ch, signal(i, n_acq=2, n=50))
    return tmp_path


def test_every_speed_folder_is_read_with_its_speed_on_every_recording(archive, tmp_path):
    ds = open_nln_emp(archive, speeds="all", cache=False)
    recordings = ds.recordings()
    assert {(r.machine, r.speed) for r in recordings} == {*ARCHIVE_RPM, ("Motor-4", "50")}
    assert len(recordings) == 16
    for rec in recordings:
        assert rec.speed_percent == float(rec.speed), rec.recording_id
        assert rec.speed_source.startswith(f"the archive's speed folder '{rec.speed}'")
        if (rec.machine, rec.speed) in ARCHIVE_RPM:
            assert rec.speed_rpm == ARCHIVE_RPM[rec.machine, rec.speed], rec.recording_id
            assert "[M]" in rec.speed_source and "no source gives" not in rec.speed_source
        else:  # Motor-4 has no rated speed and no source for 50 %: no rpm, and it says why
            assert rec.speed_rpm is None
            assert "gives none for Motor-4 at 50 %" in rec.speed_source
    # a machine read at several speeds has a run per speed folder: 'healthy 1' at 50 % and at
    # 75 % are two runs (a split may put them on two sides), not one merged run
    assert len(ds.runs()) == 8
    assert sorted(r for r in ds.runs() if r.startswith("Motor-2/")) == [
        "Motor-2/100/bearing pump 1",
        "Motor-2/100/healthy 1",
        "Motor-2/50/bearing bpfo 2",
        "Motor-2/50/healthy 1",
        "Motor-2/75/healthy 1",
        "Motor-2/75/impeller 1",
    ]
    # speeds are carried in the metadata every recording gives (the feature cache's key too)
    assert {r.metadata()["speed_rpm"] for r in recordings} == {*ARCHIVE_RPM.values(), None}


def test_the_default_is_still_the_papers_subsets_and_speeds_select_folders(archive):
    default = open_nln_emp(archive, cache=False)
    assert {(r.machine, r.speed) for r in default.recordings()} == {
        ("Motor-2", "100"),
        ("Motor-4", "70"),
    }
    assert {r.speed_rpm for r in default.recordings()} == {1480.0, 2075.0}
    assert sorted(default.runs()) == ["Motor-2/bearing pump 1", "Motor-2/healthy 1",
                                      "Motor-4/healthy 1"]  # fmt: skip
    chosen = open_nln_emp(archive, speeds=[50, 75.0], cache=False)  # numbers name folders
    assert {(r.machine, r.speed) for r in chosen.recordings()} == {
        ("Motor-2", "50"),
        ("Motor-2", "75"),
        ("Motor-4", "50"),
    }
    mapping = open_nln_emp(archive, speeds={"Motor-2": "all"}, cache=False)
    assert {(r.machine, r.speed) for r in mapping.recordings()} == {
        ("Motor-2", "50"),
        ("Motor-2", "75"),
        ("Motor-2", "100"),
        ("Motor-4", "70"),  # a machine the mapping does not name: the paper's speed
    }


def test_a_machine_with_none_of_the_speeds_is_a_note_and_a_bad_speed_one_line(archive):
    ds = open_nln_emp(archive, speeds=["75"], cache=False)
    assert {r.machine for r in ds.recordings()} == {"Motor-2"}
    assert ds.notes[-1] == (
        "no speed folder selected by speeds=['75'] for Motor-4 (50, 70) (folders it has in "
        "brackets)"
    )
    for bad in ([True], [], {"Motor-2": [None]}):
        with pytest.raises(SDTError, match=r"^speeds"):
            open_nln_emp(archive, speeds=bad, cache=False)


def test_dataset_inspect_shows_the_speed_as_text_and_json(archive, sdt_main):
    root = str(archive)
    code, out, err = sdt_main("dataset", "inspect", root, "--speeds", "all", "--json")
    assert code == 0, err
    info = json.loads(out)
    assert {(r["machine"], r["speed"], r["speed_rpm"]) for r in info["recordings"]} == {
        *((m, s, rpm) for (m, s), rpm in ARCHIVE_RPM.items()),
        ("Motor-4", "50", None),
    }
    assert all(r["speed_percent"] == float(r["speed"]) for r in info["recordings"])
    assert all(r["speed_source"] for r in info["recordings"])
    speeds = {(s["machine"], s["speed"]): s for s in info["summary"]["speeds"]}
    assert sorted(speeds) == sorted({*ARCHIVE_RPM, ("Motor-4", "50")})
    assert speeds["Motor-2", "50"]["recordings"] == 4
    assert speeds["Motor-2", "50"]["speed_rpm"] == 740.0

    code, out, err = sdt_main("dataset", "inspect", root, "--speeds", "50,75")
    assert code == 0, err
    lines = out.splitlines()
    assert lines[0].split()[:4] == ["machine", "speed", "rpm", "condition"]
    row = next(line for line in lines if "Motor-2/75/healthy 1/ch1" in line)
    assert row.split()[:3] == ["Motor-2", "75", "1110"]
    row = next(line for line in lines if "Motor-4/50/healthy 1/ch1" in line)
    assert row.split()[:3] == ["Motor-4", "50", "-"]
    shown = [line for line in lines if line.startswith("speed ")]
    assert [line.split(":")[0] for line in shown] == [
        "speed Motor-2 50",
        "speed Motor-2 75",
        "speed Motor-4 50",
    ]
    assert shown[0].startswith("speed Motor-2 50: 740 rpm, 50 % of rated (4 recordings): the ")
    assert "[M] 740 rpm at 50 % ('Speed (RPM) +- 5')" in shown[0]  # rich markup left alone
    assert shown[2].startswith("speed Motor-4 50: no rpm, 50 % of rated (2 recordings): the ")
    assert lines[-1].startswith("nln-emp: 10 recordings in 5 runs (Motor-2, Motor-4)")


def test_an_archive_read_at_several_speeds_is_written_back_in_its_layout(archive, tmp_path):
    from sdt_framework.data import write_nln_emp

    read = open_nln_emp(archive, speeds="all", cache=False)
    written = write_nln_emp(read, tmp_path / "copy")
    relative = sorted(str(p.relative_to(tmp_path / "copy")) for p in written)
    assert relative == sorted(
        str(p.relative_to(archive)) for p in (archive / "Vibration").rglob("*.csv")
    )
    again = open_nln_emp(tmp_path / "copy", speeds="all", cache=False)
    assert sorted(again.runs()) == sorted(read.runs())
