"""``make run`` on a fresh clone: pip's editable-install banners stay out, its errors do not.

From a new user's walk-through: setuptools' "Please be careful with folders in
your working directory with the same name as your package" banner, printed
twice inside ``!!`` rules, came with every ``make run`` of a fresh clone. The
install step of the Makefile is run here with a stand-in for the venv's
Python (``VENV=`` a scratch folder) that prints what pip prints, so the
Makefile's own handling is what is tested.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BANNER = """\
  /tmp/pip-build-env-ybxm6yqi/overlay/lib/python3.11/site-packages/setuptools/command/editable_wheel.py:354: BuildBackendWarning: Editable installation.
  !!

          ********************************************************************************
          Please be careful with folders in your working directory with the same
          name as your package as they may take precedence during imports.
          ********************************************************************************

  !!
    with strategy, WheelFile(wheel_path, "w") as wheel_obj:
"""  # noqa: E501  (pip 26 and setuptools 80, as printed)


def _install(tmp_path: Path, stderr: str, status: int) -> subprocess.CompletedProcess[str]:
    """``make`` the install stamp with a venv whose python prints ``stderr``, exits ``status``."""
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    (tmp_path / "said.txt").write_text(stderr)
    python.write_text(f"#!/bin/sh\ncat '{tmp_path / 'said.txt'}' >&2\nexit {status}\n")
    python.chmod(0o755)
    return subprocess.run(
        ["make", "-C", str(ROOT), f"VENV={venv}", f"{venv}/.installed"],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


pytestmark = pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")


def test_the_editable_install_banners_are_not_printed(tmp_path):
    done = _install(tmp_path, BANNER + BANNER, 0)
    assert done.returncode == 0, done.stderr
    printed = done.stdout + done.stderr
    assert "Please be careful" not in printed and "!!" not in printed
    assert (tmp_path / "venv" / ".installed").exists()
    assert "Please be careful" in (tmp_path / "venv" / "install.log").read_text()


def test_a_failed_install_prints_pips_output_and_stops(tmp_path):
    error = "ERROR: Could not find a version that satisfies the requirement numpy>=99\n"
    done = _install(tmp_path, BANNER + error, 1)
    assert done.returncode != 0
    assert error.strip() in done.stderr and "pip install failed" in done.stderr
    assert not (tmp_path / "venv" / ".installed").exists()


def test_an_error_line_of_a_finished_install_is_printed(tmp_path):
    error = "ERROR: pip's dependency resolver does not currently take into account all the packages"
    done = _install(tmp_path, BANNER + error + "\n", 0)
    assert done.returncode == 0
    assert error in done.stderr and "Please be careful" not in done.stderr
