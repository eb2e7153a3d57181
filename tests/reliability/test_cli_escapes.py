"""User strings reach the terminal with their control characters shown, never obeyed.

On main a sensor file's description and a manifest path printed raw escape
sequences: ``ESC ] 0 ; … BEL`` sets the terminal's title, ``ESC [ 2 J`` clears
the screen. Names were safe only because their pattern refuses such characters.
"""

from __future__ import annotations

from pathlib import Path

from sdt_framework.cli.visible import visible

ESC = "\x1b"
HOSTILE = "\x1b]0;pwned\x07\x1b[2J"


def _sensor_file(folder: Path) -> Path:
    path = folder / "evil.toml"
    path.write_text(
        "[sensor]\n"
        'name = "evil"\n'
        'description = "a \\u001b]0;pwned\\u0007\\u001b[2J b"\n'
        "sampling_rate_hz = 3200\nfull_scale_g = 16\nadc_bits = 13\n"
        "noise_density_ug_rthz = 290\nmech_cutoff_hz = 7000\nanalog_cutoff_hz = 1600\n",
        encoding="utf-8",
    )
    return path


def test_visible_shows_controls_and_keeps_text():
    assert visible(f"a {HOSTILE} b") == "a \\x1b]0;pwned\\x07\\x1b[2J b"
    assert visible("µg/√Hz, 25 °C\tok") == "µg/√Hz, 25 °C\tok"  # printable text untouched
    assert visible("x\u202eevil") == "x\\u202eevil"  # a bidi override would reorder the line
    assert visible("\x9b2J") == "\\x9b2J"  # the one-byte C1 CSI


def test_a_sensor_description_cannot_drive_the_terminal(sdt_main, tmp_path):
    path = _sensor_file(tmp_path)
    for command in (["sensors", "show", "evil"], ["sensors", "list"]):
        code, out, err = sdt_main("--sensor-file", str(path), *command)
        assert code == 0, err
        assert ESC not in out and "\x07" not in out and ESC not in err
    code, out, _ = sdt_main("--sensor-file", str(path), "sensors", "show", "evil")
    assert "\\x1b]0;pwned" in out.replace("\n", "")  # shown, so the user sees what is there


def test_a_manifest_path_cannot_drive_the_terminal(sdt_main, tmp_path):
    folder = tmp_path / f"d{ESC}[2J"
    folder.mkdir()
    (folder / "a.npy").write_bytes(b"not an npy file")  # refused by its reader, named
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,machine,condition,severity,recording_id,channel\n"
        f'"{folder.name}/a.npy",20000,m,healthy,,r1,ch1\n',
        encoding="utf-8",
    )
    code, out, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--out", str(tmp_path / "out")
    )
    assert code == 2
    assert ESC not in out + err
    assert "d\\x1b[2J/a.npy" in err  # the path is named, made visible
