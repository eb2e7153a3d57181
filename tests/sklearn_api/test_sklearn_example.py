"""The notebook-style example runs, and its pipeline's features are the CLI's features."""

from __future__ import annotations

import runpy
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from sdt_framework.cli.main import app
from sdt_framework.features import read_feature_table

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "sklearn_pipeline.py"
runner = CliRunner()


@pytest.fixture(scope="module")
def example():
    """The example's namespace, run on 1.5 s acquisitions (2 windows each)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("SDT_EXAMPLE_DURATION_S", "1.5")
        return runpy.run_path(str(EXAMPLE), run_name="example")


def sdt(*args: str) -> None:
    result = runner.invoke(app, [str(a) for a in args])
    assert result.exit_code == 0, result.output


def test_example_cross_validates_two_sensors_by_run(example):
    X, y, groups = example["X"], example["y"], example["run_of_row"]
    assert X.shape == (15 * 2, 2000 + 12800)  # 15 runs x 2 windows, lead-in + window
    assert len(set(groups)) == 15 and len(set(y)) == 5
    assert set(example["scores"]) == {"adxl345", "adxl357"}
    for values in example["scores"].values():
        assert values.shape == (3,) and np.all((values >= 0) & (values <= 1))
    assert list(example["features"].columns)[:2] == ["sigma", "S"]


def test_pipeline_equals_sdt_degrade_then_sdt_features_extract(example, tmp_path):
    # noise off, so `sdt degrade` (row-index noise ids) and the twin agree sample for sample
    X = example["X"]
    np.save(tmp_path / "rows.npy", X)
    sdt("degrade", tmp_path / "rows.npy", "--sensor", "adxl345", "--fs", "20000",
        "--no-noise", "--out", tmp_path / "deg.npy")  # fmt: skip
    sdt("features", "extract", tmp_path / "deg.npy", "--fs", "3200", "--settle-s", "0.1",
        "--out", tmp_path / "cli.parquet")  # fmt: skip
    cli = read_feature_table(tmp_path / "cli.parquet")
    pipe = example["make_pipeline_for"]("adxl345")[:2].set_params(twin__noise=False)
    np.testing.assert_array_equal(pipe.fit_transform(X), cli.values)
    assert list(cli.acquisition) == list(range(len(X)))  # one window per row, in row order


def test_pipeline_features_equal_cli_features_of_the_twin_output(example, tmp_path):
    # with noise: the same degraded rows through the pipeline's extractor and the CLI
    pipe = example["make_pipeline_for"]("adxl357")[:2]
    twin_out = pipe[0].fit_transform(example["X"])
    np.save(tmp_path / "twin.npy", twin_out)
    sdt("features", "extract", tmp_path / "twin.npy", "--fs", "4000", "--settle-s", "0",
        "--out", tmp_path / "cli.parquet")  # fmt: skip
    cli = read_feature_table(tmp_path / "cli.parquet")
    np.testing.assert_array_equal(pipe.fit_transform(example["X"]), cli.values)
