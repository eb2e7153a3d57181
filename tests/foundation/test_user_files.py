"""Every kind of user file goes through one loader: each encoding fault is one line, exit 2.

Per kind (benchmark config, sweep, sensor file, twin pair file through the
``sdt`` command; part file and allocation table through their loaders): a
Latin-1 byte, UTF-16 text, a NUL byte each give one line naming the file and
saying to save it as UTF-8; a UTF-8 byte-order mark is read, so what is named
is the file's invalid field.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from sdt_framework.bench.scenarios import Run, load_allocation
from sdt_framework.errors import SDTError
from sdt_framework.parts import load_part_file

#: kind -> (file name, command after the path (None: loader), valid text, text with a bad field,
#: what the bad field's line names)
KINDS = {
    "config": (
        "bench.toml",
        lambda p, out: ["benchmark", p, "--out", out],
        "[benchmark]\nrepeats = 2\n",
        "[benchmark]\nrepeats = 0\n",
        "field 'repeats'",
    ),
    "sweep": (
        "sweep.toml",
        lambda p, out: ["explore", p, "--out", out],
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [12] }\n',
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [12], colour = 1 }\n',
        "field 'sweep.axes.adc_bits.colour': unknown key",
    ),
    "sensor file": (
        "mine.toml",
        lambda p, out: ["--sensor-file", p, "sensors", "list"],
        '[sensor]\nname = "mine"\n',
        '[sensor]\nname = "mine"\n',
        "field 'sensor[0].sampling_rate_hz': Field required",
    ),
    "pair file": (
        "pair.toml",
        lambda p, out: ["twin", "check", p, "--sensor", "adxl345"],
        '[reference]\nfile = "ref.npy"\n',
        '[reference]\nfile = "ref.npy"\n',
        "field 'reference.axes': Field required",
    ),
    "part file": ("part.toml", None, 'name = "p"\n', 'name = "p"\ncolour = 1\n', "field '"),
    "allocation TOML": (
        "allocation.toml",
        None,
        '[[allocation]]\nmachine = "Motor-2"\n',
        "allocation = [1]\n",
        "allocation entry 1 is of type int",
    ),
    "allocation CSV": (
        "allocation.csv",
        None,
        "machine,scenario,run,side\n",
        "machine,scenario\nMotor-2,forward\n",
        "lacks column(s) ['run', 'side']",
    ),
}
FAULTS = {
    "latin-1": (lambda text: text.encode() + b"# caf\xe9\n", "not UTF-8 text (byte"),
    "utf-16": (lambda text: text.encode("utf-16"), "is UTF-16 text"),
    "nul": (lambda text: text.encode() + b"\x00\n", "NUL byte (line"),
}


def _one_line(kind: str, path: Path, tmp_path: Path, sdt_main) -> str:
    """The one error line of reading ``path`` as a file of ``kind``."""
    command = KINDS[kind][1]
    if command is None:
        with pytest.raises(SDTError) as info:
            if kind == "part file":
                load_part_file(path)
            else:
                load_allocation(path, [Run("Motor-2", "healthy 1", "healthy", None)])
        text = str(info.value)
        assert "\n" not in text
        return f"error: {text}"
    status, _, err = sdt_main(*command(str(path), str(tmp_path / "out")))
    lines = [line for line in err.splitlines() if line.strip()]
    assert status == 2, err
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


@pytest.mark.parametrize("fault", sorted(FAULTS))
@pytest.mark.parametrize("kind", sorted(KINDS))
def test_an_encoding_fault_is_one_line_naming_the_file(sdt_main, tmp_path, kind, fault):
    name, _, good, _, _ = KINDS[kind]
    encode, needle = FAULTS[fault]
    path = tmp_path / name
    path.write_bytes(encode(good))
    line = _one_line(kind, path, tmp_path, sdt_main)
    assert line.startswith(f"error: {path}: ") and needle in line, line
    assert "save it as a UTF-8" in line


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_a_utf8_byte_order_mark_is_read(sdt_main, tmp_path, kind):
    name, _, _, bad, named = KINDS[kind]
    path = tmp_path / name
    path.write_bytes(b"\xef\xbb\xbf" + bad.encode())
    line = _one_line(kind, path, tmp_path, sdt_main)
    assert line.startswith(f"error: {path}: ") and named in line, line
