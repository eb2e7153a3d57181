"""``sdt twin check --reference-scale`` and ``--json`` never give a confident wrong check
(issue 29, B3).

Before the fix ``--reference-scale 1e-300`` on SSX66115 gave "63 judgeable bands" and
a JSON with ``NaN`` (not JSON), ``1626`` (a typo for 1.626) clipped the twin and still
said the gains agree, and ``1e308`` leaked an overflow warning and blamed the
recording.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.twin import Pair, Signal, check_twin

SSX = Path(__file__).parents[1] / "data" / "endaq" / "SSX66115.IDE"


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _strict(text: str) -> object:
    """``json.loads`` that refuses NaN and infinities (``allow_nan=False`` semantics)."""

    def refuse(constant: str) -> None:
        raise AssertionError(f"not JSON: {constant}")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize("factor", ["1e-300", "1e300", "1626", "1e308", "nan"])
def test_an_implausible_reference_scale_is_refused_in_one_line(sdt, factor):
    run = sdt("twin", "check", str(SSX), "--sensor", "adxl345", "--reference-scale", factor)
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr.count("\n") == 1 and run.stderr.startswith("error: ")
    assert f"--reference-scale {float(factor):g}: outside the plausible 0.1-10" in run.stderr
    assert "calibration" in run.stderr  # why: it corrects a calibration
    assert "Warning" not in run.stderr and "overflow" not in run.stderr
    assert SSX.name not in run.stderr  # the factor is at fault, not the recording


def _tone_pair(reference_x: np.ndarray | None = None, scale: float = 1.0) -> Pair:
    """A 100 Hz tone on y (and 80 Hz on the device's x), 4 s, reference 5 kHz, device 3.2 kHz."""
    rng = np.random.default_rng(2)
    t = np.arange(4 * 5000) / 5000
    x = np.sin(2 * np.pi * 80 * t) if reference_x is None else reference_x
    reference = np.stack([x, np.sin(2 * np.pi * 100 * t)]) + 1e-4 * rng.normal(size=(2, t.size))
    if reference_x is not None:
        reference[0] = reference_x
    td = np.arange(4 * 3200) / 3200
    device = np.stack([2 * np.sin(2 * np.pi * 80 * td), np.sin(2 * np.pi * 100 * td)])
    device += 3e-3 * rng.normal(size=device.shape)
    return Pair(
        "tone.toml",
        Signal("[reference]", None, ("x", "y"), scale * reference, 5000.0, 0.0),
        Signal("[device]", None, ("x", "y"), device, 3200.0, 0.0),
        "000000000000",
    )


def test_a_reference_below_the_smallest_float_is_never_judgeable(registry):
    assert np.float64(1e-300) ** 2 == 0.0  # its power, and so its spectrum, is zero
    with pytest.raises(SDTError, match="no band can be judged"):
        check_twin(_tone_pair(scale=1e-300), registry.sensor("adxl345"))


def test_json_is_valid_when_a_figure_is_undefined(sdt, tmp_path):
    pair = _tone_pair(reference_x=np.zeros(4 * 5000))  # the reference's x carries nothing
    np.save(tmp_path / "ref.npy", pair.reference.values)
    np.save(tmp_path / "dev.npy", pair.device.values)
    (tmp_path / "pair.toml").write_text(
        '[reference]\nfile = "ref.npy"\naxes = ["x", "y"]\nrate_hz = 5000\n\n'
        '[device]\nfile = "dev.npy"\naxes = ["x", "y"]\nrate_hz = 3200\n'
    )
    run = sdt("twin", "check", str(tmp_path / "pair.toml"), "--sensor", "adxl345", "--json")
    assert run.returncode == 0, run.stderr
    assert "Warning" not in run.stderr
    out = _strict(run.stdout)
    # the device's strongest axis is x (2 g at 80 Hz), where the reference is all zeros: the
    # reference's THD there has no fundamental, and is null, not NaN
    assert out["distortion"]["axis"] == "x"
    assert out["distortion"]["reference"] is None
    floor_x = next(f for f in out["floors"] if f["axis"] == "x")
    assert floor_x["reference_ug"] == 0.0 and floor_x["judgeable"] is False
    assert out["summary"]["judgeable_bands"] > 0  # y is judged
