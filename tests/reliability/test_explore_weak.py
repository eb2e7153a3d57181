"""Weak spots of ``sdt explore`` found by the round-3 bad-input probe.

On main before this round:

- Morris with one trajectory ran and printed 24 raw numpy warnings and an
  empty sigma (sigma, the spread of the elementary effects, needs two);
- SALib's delta analysis printed "[field][balanced] Only one bin remains ..."
  notices on the terminal (it sets its own ``"once"`` warning filter, which
  beat the ``"ignore"`` around it);
- ``levels = [true, false]`` was read as 1 and 0;
- the printed estimate counted the chains, features and classifiers only
  ("estimated 0 s" for a sweep that ran a minute) and said nothing of what it
  assumed;
- a one-axis Sobol design said "field 'sensors': lists a name twice" although
  the user wrote no sensors: with one axis Saltelli's AB matrix is B, so every
  point is drawn twice (any ``samples``); points that coincide for another
  reason (Morris trajectories revisiting a coarse grid) said the same.
"""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import numpy as np
import pytest

from ..helpers import EXPLORE_BENCHMARK

#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _sweep(folder: Path, sweep: str) -> Path:
    path = folder / "sweep.toml"
    path.write_text(textwrap.dedent(sweep) + EXPLORE_BENCHMARK)
    return path


def _refused(result) -> str:
    err = result.stderr
    assert result.returncode == 2 and err.count("\n") == 1 and err.startswith("error:"), err
    assert "Warning" not in err and "Traceback" not in err
    return err


def test_boolean_levels_are_refused_naming_the_axis(sdt, tmp_path: Path) -> None:
    sweep = _sweep(tmp_path, '[sweep]\nbase = "adxl345"\n[sweep.axes]\n'
                   "adc_bits = { levels = [true, false] }\n")  # fmt: skip
    err = _refused(sdt("explore", str(sweep), "--out", str(tmp_path / "out")))
    assert "sweep.axes.adc_bits" in err and "true/false is not a number" in err
    assert not (tmp_path / "out").exists()


def test_one_morris_trajectory_is_refused_naming_samples(sdt, tmp_path: Path) -> None:
    sweep = _sweep(tmp_path, '[sweep]\nbase = "adxl345"\ndesign = "morris"\nsamples = 1\n'
                   '[sweep.axes]\nfull_scale_g = { range = [2, 16] }\n'
                   'noise_density_ug_rthz = { range = [25, 1000] }\n')  # fmt: skip
    err = _refused(sdt("explore", str(sweep), "--out", str(tmp_path / "out")))
    assert "morris needs samples >= 2 (got 1)" in err and "sigma" in err


def test_one_axis_sobol_names_the_real_cause(sdt, tmp_path: Path) -> None:
    from SALib.sample import sobol

    # the cause, checked on SALib itself: one axis, one sample -> 3 points, 2 distinct
    unit = sobol.sample({"num_vars": 1, "names": ["a"], "bounds": [[0, 1]]}, 1,
                        calc_second_order=False, seed=0)  # fmt: skip
    assert len(unit) == 3 and len(np.unique(unit, axis=0)) == 2
    sweep = _sweep(tmp_path, '[sweep]\nbase = "adxl345"\ndesign = "sobol"\nsamples = 1\n'
                   '[sweep.axes]\nnoise_density_ug_rthz = { range = [25, 1000] }\n')  # fmt: skip
    err = _refused(sdt("explore", str(sweep), "--out", str(tmp_path / "out")))
    assert "sobol needs at least 2 axes (got 1)" in err and "sensors" not in err


def test_repeated_design_points_are_named(sdt, tmp_path: Path) -> None:
    from SALib.sample import morris

    problem = {"num_vars": 2, "names": ["a", "b"], "bounds": [[0, 1]] * 2}
    unit = morris.sample(problem, 4, num_levels=4, seed=0)
    sweep = _sweep(tmp_path, '[sweep]\nbase = "adxl345"\ndesign = "morris"\nsamples = 4\n'
                   '[sweep.axes]\nfull_scale_g = { range = [2, 16] }\n'
                   'noise_density_ug_rthz = { range = [25, 1000] }\n')  # fmt: skip
    err = _refused(sdt("explore", str(sweep), "--out", str(tmp_path / "out")))
    i, j = (int(k) for k in re.search(r"design points (\d+) and (\d+) are the same", err).groups())
    assert i != j and np.array_equal(unit[i], unit[j])  # the same point of SALib's design
    assert "samples = 4" in err and "sensors" not in err


def test_lhs_sweep_keeps_salib_quiet_and_says_what_its_estimate_assumes(
    sdt, tmp_path: Path
) -> None:
    sweep = _sweep(tmp_path, '[sweep]\nbase = "adxl345"\ndesign = "lhs"\nsamples = 8\n'
                   '[sweep.axes]\nnoise_density_ug_rthz = { range = [25, 1000] }\n'
                   'full_scale_g = { range = [2, 16] }\n')  # fmt: skip
    result = sdt("explore", str(sweep), "--out", str(tmp_path / "out"), "--no-report")
    assert result.returncode == 0, result.stderr
    assert "bin" not in result.stderr and "Warning" not in result.stderr, result.stderr
    out = " ".join(result.stdout.split())
    total = float(re.search(r"estimated (\d+) s on", out)[1])
    parts = re.search(r"estimate = (.*?); it assumes a cold feature cache", out)[1]
    seconds = [float(s) for s in re.findall(r"(\d+) s", parts)]
    assert "process start" in parts and "recordings read or generated" in parts
    assert total >= 3 and abs(total - sum(seconds)) <= len(seconds)  # each part rounded
