"""One overwrite rule for every output file a command is told to write.

On main before this round ``sdt degrade --out``, ``sdt features extract --out``,
``sdt validate-noise --plot`` and ``sdt twin check --plot`` silently replaced an
existing file, while ``sdt twin fit --out`` refused one with no way to allow
it. Now all five refuse an existing file in one line naming it, before any
work; ``--overwrite`` (the flag ``sdt dataset synth`` already had) allows it;
and an input file is never an output, ``--overwrite`` or not.

No command here starts a worker: ``sdt`` runs in this process (``in_process``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

DATA = Path(__file__).parents[1] / "data" / "endaq"
OLD = b"an earlier result the user wants to keep"

pytestmark = pytest.mark.in_process


def _signal(folder: Path) -> Path:
    path = folder / "sig.npy"
    np.save(path, np.sin(np.arange(8000) / 7.0))
    return path


def commands(folder: Path) -> dict[str, tuple[list[str], Path]]:
    """Each command, as a user types it, and the output file it names."""
    sig = _signal(folder)
    ide = str(DATA / "SSX_Data.IDE")
    return {
        "degrade": (
            ["degrade", str(sig), "--sensor", "adxl345", "--fs", "20000", "--out"],
            folder / "out.npy",
        ),
        "features": (
            ["features", "extract", str(sig), "--fs", "3200", "--out"],
            folder / "features.csv",
        ),
        "validate-noise": (
            ["validate-noise", "--sensor", "adxl345", "--windows", "2", "--plot"],
            folder / "noise.png",
        ),
        "twin check": (["twin", "check", ide, "--sensor", "adxl345", "--plot"], folder / "t.png"),
        "twin fit": (["twin", "fit", ide, "--sensor", "adxl345", "--out"], folder / "fit.toml"),
    }


@pytest.mark.parametrize(
    "name", ["degrade", "features", "validate-noise", "twin check", "twin fit"]
)
def test_an_existing_output_is_refused_and_overwrite_allows_it(
    sdt, sdt_main, monkeypatch, capsys, tmp_path: Path, name
):
    args, out = commands(tmp_path)[name]
    out.write_bytes(OLD)
    code, _, err = sdt_main(*args, str(out))  # refused before any work: in this process
    assert code == 2 and err.count("\n") == 1 and err.startswith("error:"), err
    assert f"{out} exists" in err and "--overwrite" in err, err
    assert out.read_bytes() == OLD  # untouched
    replaced = sdt(*args, str(out), "--overwrite")
    assert replaced.returncode == 0, replaced.stderr
    assert out.read_bytes() != OLD and out.stat().st_size > 0


@pytest.mark.parametrize("name", ["degrade", "features"])
def test_overwrite_never_makes_the_input_an_output(
    sdt_main, monkeypatch, capsys, tmp_path: Path, name
):
    args, _ = commands(tmp_path)[name]
    sig = tmp_path / "sig.npy"
    before = sig.read_bytes()
    target = tmp_path / "link.csv" if name == "features" else sig
    if name == "features":
        target.symlink_to(sig)
    code, _, err = sdt_main(*args, str(target), "--overwrite")
    assert code == 2 and "is the input file" in err, err
    assert sig.read_bytes() == before


def test_the_flag_is_documented_in_each_help(sdt_main, monkeypatch, capsys) -> None:
    for args in (["degrade"], ["features", "extract"], ["validate-noise"], ["twin", "check"],
                 ["twin", "fit"]):  # fmt: skip
        shown = sdt_main(*args, "--help")[1]
        assert "--overwrite" in shown and "never replaced" in " ".join(shown.split()), args
