"""IDE recordings in a manifest, in ``validate-noise`` and ``twin check --plot``."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
from sdt_plugins.readers.ide.parse import read_ide

DATA = Path(__file__).parents[1] / "data" / "endaq"


def _manifest(folder: Path, rate: str) -> Path:
    shutil.copy(DATA / "SSX_Data.IDE", folder)
    manifest = folder / "m.csv"
    manifest.write_text(
        "path,variable,sampling_rate_hz,machine,condition,severity,recording_id,channel\n"
        f"SSX_Data.IDE,32:z,{rate},shaker,rest,,r1,z\n",
        encoding="utf-8",
    )
    return manifest


def test_a_manifest_row_reads_one_ide_axis_at_its_measured_rate(tmp_path, registry):
    from sdt_framework.data import open_dataset

    dataset = open_dataset(registry, str(_manifest(tmp_path, "3134.31")))
    (recording,) = dataset.recordings()
    expected = read_ide(DATA / "SSX_Data.IDE", 32, ["z"])
    assert np.array_equal(recording.load(), expected.values)
    assert recording.sampling_rate_hz == 3134.31


def test_a_manifest_rate_that_is_not_the_measured_one_is_refused(sdt_main, tmp_path):
    code, _, err = sdt_main("dataset", "inspect", str(_manifest(tmp_path, "3200")))
    assert code == 2
    assert "runs at 3134.31 Hz by its timestamps, the manifest says 3200 Hz" in err


def test_validate_noise_reads_the_parts_channel_of_an_ide_file(sdt_main):
    code, out, err = sdt_main(
        "validate-noise", "--sensor", "adxl345", "--axis", "z",
        "--recording", str(DATA / "SSX_Data.IDE"), "--windows", "4", "--json",
    )  # fmt: skip
    assert code == 0, err
    assert "signal '32:z': 8,580 samples at 3134.31 Hz (its timestamps)" in err
    data = json.loads(out)
    assert data["recording"]["fs_hz"] == read_ide(DATA / "SSX_Data.IDE", 32, ["z"]).rate_hz


def test_check_draws_its_figure(sdt_main, tmp_path):
    figure = tmp_path / "ssx.png"
    code, _out, err = sdt_main(
        "twin", "check", str(DATA / "SSX66115.IDE"), "--sensor", "adxl345", "--plot", str(figure)
    )
    assert code == 0, err
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
