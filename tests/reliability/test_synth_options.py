"""The synthetic pump's new dataset options (layout, glitches) refuse a bad value with
one ``error:`` line naming the option and what it takes, exit 2, no traceback, nothing
written, through ``sdt benchmark`` as a user types it (default --jobs)."""

from __future__ import annotations

import pytest

#: refused before any worker starts (default --jobs kept): ``sdt`` runs in this process
pytestmark = pytest.mark.in_process


@pytest.mark.parametrize(
    ("option", "message"),
    [
        ('layout = "archive"', "synthetic-pump: layout must be 'compact' or 'real', got 'archive'"),
        ('glitches = "yes"', "synthetic-pump: glitches must be true or false, got 'yes'"),
    ],
)
def test_bad_synthetic_option_is_one_error_line(sdt, tmp_path, option: str, message: str):
    config = tmp_path / "bad.toml"
    config.write_text(
        f"[benchmark]\ndataset_options = {{ duration = 1.5, {option} }}\n"
        "machines = ['Motor-2']\nsensors = ['adxl345']\nrepeats = 1\nreport = false\n"
    )
    out = tmp_path / "out"
    result = sdt("benchmark", str(config), "--out", str(out))
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    assert result.stderr.strip().startswith("error:") and message in result.stderr
    assert not out.exists()
