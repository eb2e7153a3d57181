"""User strings reach the terminal as given: never read as rich markup or emoji codes.

A file called ``run[bold].npy`` must not lose ``[bold]``, ``a:x:b.npy`` must not become
``a❌b.npy``, and a message holding ``[/]`` must not crash the error printer. The whole
``main()`` entry point runs in this process (as ``sdt`` would) with the terminal widened so
that no line is wrapped.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.cli import common

# "a[/]b.npy" is the file "]b.npy" in the folder "a[": a path a user can type
NAMES = ["run[bold].npy", "a:x:b.npy", "x[red]:smile:.npy", "a[/]b.npy"]


@pytest.fixture
def sdt(monkeypatch: pytest.MonkeyPatch, sdt_main):
    """``sdt_main`` with both consoles 400 columns wide, so no line wraps."""
    # the private attribute behind Console.width: undoing it restores "follow the
    # terminal" (None); undoing the property would pin the width for later tests
    monkeypatch.setattr(common.console, "_width", 400)
    monkeypatch.setattr(common.err_console, "_width", 400)
    return sdt_main


@pytest.mark.parametrize("name", NAMES)
def test_file_names_print_as_given(sdt, tmp_path: Path, monkeypatch, name: str):
    monkeypatch.chdir(tmp_path)
    Path(name).parent.mkdir(exist_ok=True)
    np.save(name, np.random.default_rng(0).normal(size=4000))
    out = name.replace(".npy", ".csv")
    status, stdout, stderr = sdt("features", "extract", name, "--fs", "3200", "--out", out)
    assert status == 0, stderr
    assert stdout.rstrip().endswith(f"to {out}")
    assert Path(out).is_file()
    # a recording at 1 kHz cannot become a 3.2 kHz sensor's: the error quotes the file name
    status, _, stderr = sdt(
        "degrade", name, "--sensor", "adxl345", "--fs", "1000", "--out", "d.npy"
    )
    assert status == 2
    assert stderr.startswith(f"error: sensor 'adxl345', recording {name!r}: target rate")
    assert stderr.count("\n") == 1


@pytest.mark.parametrize("name", ["x[/]", "a:x:b", "[bold]y[/bold]", "[/"])
def test_error_printer_takes_any_message(sdt, name: str):
    status, _, stderr = sdt("sensors", "show", name)
    assert status == 2
    # one line, printed as given: the name is quoted verbatim, nothing is interpreted
    # (names with brackets are refused by the part-mode parser, the rest as unknown)
    assert stderr.startswith("error: ") and stderr.count("\n") == 1
    assert f"{name!r}" in stderr


def test_table_cells_print_as_given(sdt, tmp_path: Path):
    profile = tmp_path / "s.toml"
    profile.write_text(
        'name = "odd"\ndescription = "made by [bold]us[/bold] :x: [/]"\n'
        "sampling_rate_hz = 1000\nfull_scale_g = 2\nadc_bits = 10\n"
        "noise_density_ug_rthz = 100\nmech_cutoff_hz = 3000\nanalog_cutoff_hz = 400\n"
    )
    status, stdout, stderr = sdt("--sensor-file", str(profile), "sensors", "show", "odd")
    assert status == 0, stderr
    assert "made by [bold]us[/bold] :x: [/]" in stdout


def test_unit_brackets_in_the_feature_list_print_once(sdt):
    status, stdout, stderr = sdt("features", "list")
    assert status == 0, stderr
    assert "sigma [g]" in stdout and "V_RMS [mm/s]" in stdout and "\\[" not in stdout
