"""A recording's speed: carried (a manifest's speed_rpm), or an estimate off its spectrum.

The signals are built here: a 4-pole motor's shaft line at a known speed with
its 2x, a 50 Hz mains line and its 100 Hz, and white noise, 4 s at 20 kHz
(0.25 Hz lines). The expected speed is the one put in; the speeds are written
as numbers, not computed by the code under test.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data import open_manifest
from sdt_framework.data.speed import (
    estimate_speeds,
    nominal_rpm,
    recording_speed,
    select_speeds,
    speed_matches,
)
from sdt_framework.errors import SDTError
from sdt_framework.specs import MachineSpec

FS, SECONDS = 20000.0, 4.0
HEADER = "path,sampling_rate_hz,machine,condition,severity,recording_id,channel,speed,speed_rpm\n"


def _motor(rpm: float, seed: int) -> np.ndarray:
    t = np.arange(int(FS * SECONDS)) / FS
    shaft = rpm / 60.0
    x = 2.0 * np.sin(2 * np.pi * 50.0 * t) + 0.5 * np.sin(2 * np.pi * 100.0 * t)
    x += 1.0 * np.sin(2 * np.pi * shaft * t) + 0.3 * np.sin(2 * np.pi * 2 * shaft * t + 1)
    return x + 0.3 * np.random.default_rng(seed).standard_normal(t.size)


def _manifest(folder: Path, rows: list[tuple[str, float, str, str]]) -> Path:
    """rows: (name, true rpm, speed label, speed_rpm cell)."""
    lines = [HEADER]
    for seed, (name, rpm, label, cell) in enumerate(rows):
        np.save(folder / f"{name}.npy", _motor(rpm, seed))
        lines.append(f"{name}.npy,20000,pump,healthy,,{name},ch1,{label},{cell}\n")
    (folder / "m.csv").write_text("".join(lines), encoding="utf-8")
    return folder / "m.csv"


def test_a_speed_given_in_the_manifest_is_carried_with_its_line_and_percentage(tmp_path, readers):
    manifest = _manifest(tmp_path, [("a", 1450.0, "full", "1450"), ("b", 1100.0, "part", "")])
    (tmp_path / "machines.toml").write_text(
        "[machine.pump]\nshaft_rpm = 1450\nrated_rpm = 1450\n", encoding="utf-8"
    )
    a, b = open_manifest(manifest, readers=readers).recordings()
    assert (a.speed, a.speed_rpm, a.speed_percent) == ("full", 1450.0, 100.0)
    assert a.speed_source.startswith("manifest speed_rpm (line 2), % of the rated 1450 rpm in")
    assert (b.speed, b.speed_rpm, b.speed_percent, b.speed_source) == ("part", None, None, "")


def test_where_none_is_given_the_speed_is_estimated_and_named_an_estimate(tmp_path, readers):
    manifest = _manifest(tmp_path, [("a", 1450.0, "", "1450"), ("b", 1470.0, "", "")])
    dataset = open_manifest(manifest, readers=readers)
    notes = estimate_speeds(dataset, nominal=1480.0)
    a, b = dataset.recordings()
    assert a.speed_rpm == 1450.0 and a.speed_source.startswith("manifest")  # given: kept
    # 1470 rpm put in; the Hann-windowed, 8x padded, interpolated line lands within 0.02 Hz
    assert b.speed_rpm == pytest.approx(1470.0, abs=1.2)
    assert b.speed_source.startswith("estimate: 1470 rpm (24.5")
    assert "read off the spectrum, confidence high" in b.speed_source
    assert notes == dataset.notes[-1:]
    assert notes[0].endswith("for 1 recording(s) that carry none; confidence: 1 high")


def test_without_a_nominal_speed_nothing_is_guessed(tmp_path, readers):
    manifest = _manifest(tmp_path, [("b", 1470.0, "", "")])
    dataset = open_manifest(manifest, readers=readers)  # no machines.toml, no --nominal-rpm
    (note,) = estimate_speeds(dataset)
    assert note.startswith("1 recording(s) carry no speed and have no nominal speed to look near")
    assert dataset.recordings()[0].speed_rpm is None
    rec = dataset.recordings()[0]
    with pytest.raises(SDTError, match="carries no speed and there is no nominal speed"):
        recording_speed(rec, rec.load())


def test_a_line_under_the_mains_guard_gives_no_speed_and_says_why(tmp_path, readers):
    # a 2-pole motor at 2997 rpm: 49.95 Hz, inside the 50 Hz guard; no line is read
    manifest = _manifest(tmp_path, [("c", 2997.0, "", "")])
    dataset = open_manifest(manifest, readers=readers)
    estimate_speeds(dataset, nominal=2950.0)
    (rec,) = dataset.recordings()
    assert rec.speed_rpm is None
    assert rec.speed_source.startswith("no speed: the estimate from the spectrum read none")
    assert "the shaft line may lie under a mains line" in rec.speed_source


def test_the_nominal_speed_is_the_machines_at_the_recordings_operating_point(tmp_path, readers):
    machine = MachineSpec(name="pump", shaft_rpm=1480.0, speed_percent=100.0, rated_rpm=1480.0)
    rec = open_manifest(_manifest(tmp_path, [("a", 740.0, "50", "")]), readers=readers)
    (rec,) = rec.recordings()
    assert nominal_rpm(rec, machine) == 1480.0  # no operating point: the machine's speed
    half = rec.__class__(**{**rec.__dict__, "speed_percent": 50.0})
    assert nominal_rpm(half, machine) == 740.0  # the rated speed scaled (speed_at)
    assert recording_speed(half, half.load(), machine=machine).hz == pytest.approx(
        740.0 / 60, abs=0.02
    )


def test_speeds_select_by_percentage_or_label_and_refuse_one_the_data_lacks(tmp_path, readers):
    manifest = _manifest(tmp_path, [("a", 1450.0, "100", "1450"), ("b", 725.0, "low", "725")])
    (tmp_path / "machines.toml").write_text(
        "[machine.pump]\nshaft_rpm = 1450\nrated_rpm = 1450\n", encoding="utf-8"
    )
    a, b = open_manifest(manifest, readers=readers).recordings()
    assert speed_matches(b, 50) and speed_matches(b, "low") and not speed_matches(b, "50x")
    assert speed_matches(a, "100") and speed_matches(a, 100.0) and not speed_matches(a, 50)
    assert select_speeds([a, b], [50.0]) == [b]
    with pytest.raises(SDTError) as error:
        select_speeds([a, b], [75.0, "high"])
    assert str(error.value) == (
        "speeds: no recording at 75, 'high'; the data has pump low (50 %), pump 100 "
        "(machine and speed label, % of rated where it differs)"
    )


def test_inspect_estimates_on_request_and_shows_it(tmp_path, sdt_main):
    manifest = _manifest(tmp_path, [("b", 1470.0, "", "")])
    code, out, err = sdt_main("dataset", "inspect", str(manifest), "--nominal-rpm", "1480")
    assert code == 0, err
    assert "note: speed estimated from the spectrum" in err
    (line,) = [x for x in out.splitlines() if x.startswith("speed pump -:")]
    assert line.startswith("speed pump -: 1470 rpm (1 recording): estimate: 1470 rpm (24.5")
    assert "read off the spectrum, confidence high" in line
    code, out, err = sdt_main("dataset", "inspect", str(manifest), "--json", "--estimate-speed")
    assert code == 0, err
    assert json.loads(out)["recordings"][0]["speed_rpm"] is None  # no nominal: no guess
    assert "no nominal speed to look near" in err
