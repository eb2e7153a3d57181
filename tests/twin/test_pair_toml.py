"""A pair described by TOML (CSV with a time column, NPY with a rate) checks like the IDE file.

The two signals of the real ``SSX66115.IDE`` pair are written out: the piezo as a
CSV in m/s^2 with its timestamps and its columns in another order, the ADXL345
as an NPY with its rate and start. The TOML route must give the IDE route's
band levels: the unit conversion, the column-to-axis mapping and the time base
are then right.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.twin import check_twin, load_pair

DATA = Path(__file__).parents[1] / "data" / "endaq"
G = 9.80665  # m/s^2 per g (standard gravity)


@pytest.fixture(scope="module")
def written(tmp_path_factory, readers):
    ide = load_pair(DATA / "SSX66115.IDE", "adxl345", readers=readers)
    folder = tmp_path_factory.mktemp("pair")
    ref = ide.reference
    t = ref.start_s + np.arange(ref.values.shape[1]) / ref.rate_hz
    x, y, z = ref.values * G
    table = np.column_stack([t, z, x, y])
    np.savetxt(folder / "piezo.csv", table, delimiter=",", header="t,az,ax,ay", comments="",
               fmt="%.10g")  # fmt: skip
    np.save(folder / "mems.npy", ide.device.values)
    (folder / "pair.toml").write_text(
        f"""[reference]
file = "piezo.csv"
columns = ["az", "ax", "ay"]
axes = ["z", "x", "y"]
time_column = "t"
units = "m/s^2"
part = "832M1"

[device]
file = "mems.npy"
axes = ["x", "y", "z"]
rate_hz = {ide.device.rate_hz!r}
start_s = {ide.device.start_s!r}
part = "ADXL345"
"""
    )
    return ide, folder


def test_toml_pair_checks_like_the_ide_file(written, registry):
    ide, folder = written
    pair = load_pair(folder / "pair.toml", "adxl345", readers=registry.signal_readers())
    assert pair.reference.axes == ("x", "y", "z")
    assert pair.reference.rate_hz == pytest.approx(ide.reference.rate_hz, rel=1e-9)
    assert np.allclose(pair.reference.values, ide.reference.values, rtol=1e-8, atol=1e-9)
    sensor = registry.sensor("adxl345")
    from_toml = check_twin(pair, sensor)
    from_ide = check_twin(ide, sensor)
    for a, b in zip(from_toml.bands, from_ide.bands, strict=True):
        assert a.real_rms_g == pytest.approx(b.real_rms_g, rel=1e-6)
        assert a.twin_rms_g == pytest.approx(b.twin_rms_g, rel=1e-3)
        assert a.judgeable == b.judgeable


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (('time_column = "t"', ""), "[reference] a CSV holds no rate; give rate_hz or time_column"),
        (('units = "m/s^2"', 'units = "furlong"'), "field 'reference.units'"),
        (('part = "832M1"', 'colour = "red"'), "field 'reference.colour': unknown field"),
        (('file = "mems.npy"', 'file = "missing.npy"'), "[device] file not found"),
        (('axes = ["x", "y", "z"]\nrate', 'axes = ["x", "y"]\nrate'), "holds 3 signal(s)"),
        (("rate_hz = ", "rate_hz = 9e9 #"), "is not faster than the device"),
        (("start_s = ", "start_s = 1e4 #"), "overlap for 0.00 s"),
    ],
)
def test_bad_pair_file_is_one_line(written, sdt_main, edit, words):
    _, folder = written
    text = (folder / "pair.toml").read_text().replace(*edit, 1)
    bad = folder / "bad.toml"
    bad.write_text(text)
    code, _, err = sdt_main("twin", "check", str(bad), "--sensor", "adxl345")
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and words in lines[0], err


def test_a_pair_without_motion_says_why_nothing_is_judged(tmp_path, sdt_main):
    rng = np.random.default_rng(4)
    np.save(tmp_path / "ref.npy", 1e-4 * rng.normal(size=(1, 20_000)))  # 4 s of white floor
    np.save(tmp_path / "dev.npy", 1e-4 * rng.normal(size=(1, 12_800)))
    (tmp_path / "rest.toml").write_text(
        '[reference]\nfile = "ref.npy"\naxes = ["x"]\nrate_hz = 5000\n\n'
        '[device]\nfile = "dev.npy"\naxes = ["x"]\nrate_hz = 3200\n'
    )
    code, _, err = sdt_main("twin", "check", str(tmp_path / "rest.toml"), "--sensor", "adxl345")
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "no band can be judged" in lines[0] and "floor" in lines[0], err


def test_the_reference_csv_is_read_once_for_its_columns_and_time(written, monkeypatch, registry):
    # three signal columns and a time column: one parse of the file, not four
    from sdt_framework.signals import csv_rule as csv_signal

    parsed: list[Path] = []
    real = csv_signal._parse

    def counting(path, *args):
        parsed.append(path)
        return real(path, *args)

    monkeypatch.setattr(csv_signal, "_parse", counting)
    _, folder = written
    pair = load_pair(folder / "pair.toml", "adxl345", readers=registry.signal_readers())
    assert [p.name for p in parsed] == ["piezo.csv"]
    # the columns come back in the order the pair names them, against numpy's own read
    table = np.loadtxt(folder / "piezo.csv", delimiter=",", skiprows=1)
    assert np.allclose(pair.reference.values * G, table[:, [2, 3, 1]].T, rtol=1e-9, atol=1e-12)
