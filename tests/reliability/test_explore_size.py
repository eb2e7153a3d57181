"""A sweep file's size is checked from the file alone, before its design is built.

On main before round 2 the design was built in full first: a 10^8-point grid
(itertools.product of every level) or a sobol design with ``samples =
1048576`` (4 194 304 points, each then validated as a sensor profile) was
killed by the kernel or ended in MemoryError tracebacks. Here building the
design fails the test, so none of these tests can allocate it, on old code or
new.
"""

from __future__ import annotations

import textwrap
import tomllib
from pathlib import Path

import pytest

from sdt_framework.explore.design import design_points
from sdt_framework.explore.size import design_size
from sdt_framework.explore.sweep_file import parse_sweep

GRID = """
[sweep]
base = "adxl345"
[sweep.axes]
noise_density_ug_rthz = { range = [25, 1000], scale = "log", steps = 100 }
full_scale_g = { range = [2, 16], steps = 100 }
adc_bits = { range = [8, 24], steps = 100 }
mech_cutoff_hz = { range = [1000, 5000], steps = 100 }
"""
SOBOL = """
[sweep]
base = "adxl345"
design = "sobol"
samples = 1048576
[sweep.axes]
noise_density_ug_rthz = { range = [25, 1000], scale = "log" }
full_scale_g = { range = [2, 16] }
"""
SMALL = """
[sweep]
base = "adxl345"
[sweep.axes]
noise_density_ug_rthz = { levels = [90, 290] }
[benchmark]
machines = ["Motor-2"]
"""


@pytest.fixture
def no_design(monkeypatch):
    """Building the design fails the test: the size must be known without it."""

    def refuse(sweep):
        pytest.fail(f"the {sweep.design} design was built before its size was checked")

    monkeypatch.setattr("sdt_framework.explore.run.design_points", refuse)


def _file(tmp_path: Path, text: str) -> str:
    path = tmp_path / "sweep.toml"
    path.write_text(textwrap.dedent(text))
    return str(path)


@pytest.mark.parametrize(
    ("text", "points"),
    [(GRID, "100,000,000"), (SOBOL, "4,194,304")],  # 100^4; 2^20 x (2 axes + 2)
)
@pytest.mark.parametrize("yes", [[], ["--yes"]])
def test_a_design_that_cannot_fit_is_refused_unbuilt(
    sdt_main, tmp_path, no_design, text, points, yes
):
    out = tmp_path / "out"
    code, _, err = sdt_main("explore", _file(tmp_path, text), "--quick", "--out", str(out), *yes)
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"error: this sweep of {points} design points is ")
    assert " of memory, more than the " in err
    assert err.rstrip().endswith(
        "shrink it (fewer levels or samples, --quick, fewer repeats or classifiers)"
    )
    assert not out.exists()


def test_a_long_design_needs_yes_before_it_is_built(sdt_main, tmp_path, no_design, monkeypatch):
    monkeypatch.setattr("sdt_framework.bench.estimate.CONFIRM_ABOVE_SECONDS", 0.0)
    out = tmp_path / "out"
    code, _, err = sdt_main(
        "explore", _file(tmp_path, SMALL), "--quick", "--out", str(out), "--strategy", "exhaustive"
    )
    assert code == 2 and err.count("\n") == 1
    # 2 points + reference and base, costed as the base: 3 scenarios x 5 classifiers x 2 repeats
    assert err.startswith("error: this sweep of 2 design points is 120 runs and ")
    assert "add --yes to run it, or shrink it" in err and not out.exists()


@pytest.mark.parametrize(
    ("table", "expected"),
    [
        ({"axes": {"adc_bits": {"levels": [8, 10, 12]}, "full_scale_g": {"range": [2, 16]}}}, 12),
        ({"design": "lhs", "samples": 5, "axes": {"full_scale_g": {"range": [2, 16]}}}, 5),
        (
            {
                "design": "sobol",
                "samples": 8,
                "axes": {"full_scale_g": {"range": [2, 16]}, "adc_bits": {"range": [8, 16]}},
            },
            32,
        ),
        (
            {
                "design": "morris",
                "samples": 3,
                "axes": {"full_scale_g": {"range": [2, 16]}, "adc_bits": {"range": [8, 16]}},
            },
            9,
        ),
    ],
)
def test_the_size_is_the_built_designs_length(table, expected):
    sweep = parse_sweep({"base": "adxl345", **table})
    assert design_size(sweep) == expected == len(design_points(sweep))


def test_the_python_api_refuses_it_too(no_design):
    from sdt_framework import build_registry
    from sdt_framework.errors import SDTError
    from sdt_framework.explore.run import plan_explore

    sweep = parse_sweep(tomllib.loads(GRID)["sweep"])
    with pytest.raises(SDTError, match=r"^a sweep of 100,000,000 design points needs about "):
        plan_explore(sweep, {}, {"quick": True}, build_registry())
