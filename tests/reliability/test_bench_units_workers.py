"""``sdt benchmark --units N`` as the README writes it, on loky and on Dask worker processes.

A drawn unit adds the stages its tolerances name (the ADXL345's ``temperature.
tempco_mg_per_c``). Those stages used to be bound by a binder that importing
the registry installs: the parent process had one, a loky or Dask worker
(which imports only what it unpickles) did not, so every ``--units`` run with
the default ``--jobs`` stopped with "lists stages no registry bound". Each run
here goes through the real command; the results must equal a ``--jobs 1`` run
(the seeds do not depend on the process a recording is featurised in).
The README's run is long enough for its default ``--jobs`` to start workers; cut
short as here, it would run in its own process, so ``--jobs 2`` starts them.
The data is cut to one machine and one channel to keep the runs short, and one
test covers both sensors (the ADXL345, whose tempco stage was the one left
unbound, and the README's ADXL355 at 85 °C): a separate ADXL345-only pair of runs
checked nothing this one does not.
"""

from __future__ import annotations

import pandas as pd
from distributed import LocalCluster

from ..helpers import sdt_here

CUT = ("--machines", "Motor-2", "--channels", "ch1")


def _results(folder) -> pd.DataFrame:
    table = pd.read_csv(folder / "results.csv").drop(columns="fit_seconds")
    return table.sort_values(["scenario", "sensor", "classifier", "unit", "repeat"]).reset_index(
        drop=True
    )


def _run(sdt, tmp_path, name: str, *args: str) -> pd.DataFrame:
    out = tmp_path / name
    done = sdt("benchmark", "--quick", *args, *CUT, "--no-report", "--out", str(out))
    return _checked(done, out)


def _checked(done, out) -> pd.DataFrame:
    assert done.returncode == 0, done.stderr
    assert "no registry bound" not in done.stderr
    return _results(out)


def test_readme_units_at_85c_on_loky_and_on_dask_workers_equal_jobs_1(sdt, tmp_path):
    """The README's ``--units 5 ... adxl355[errors=datasheet,temp=85c]`` block (one classifier).

    The loky run is a real process: workers an earlier test started in this one would have
    imported the registry already, which is what hid the unbound stages."""

    def here(*args: str):
        return sdt_here(*args, env={"SDT_CACHE_DIR": str(tmp_path / "cache")})

    args = (
        "--units",
        "5",
        "--sensors",
        "adxl345,adxl355[errors=datasheet,temp=85c]",
        "--classifiers",
        "lr",
    )
    default = _run(sdt, tmp_path, "default", *args, "--jobs", "2")  # the README's workers
    # the command itself may run in this process where its workers start fresh anyway: the
    # --jobs 1 reference, and the Dask run (this test's own new cluster does the work)
    single = _run(here, tmp_path, "jobs1", *args, "--jobs", "1")
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        on_dask = ("--backend", "dask", "--scheduler", cluster.scheduler_address)
        dask = _run(here, tmp_path, "dask", *args, *on_dask)
    # 3 scenarios x 2 sensors x 5 units x 2 repeats, every run scored, units really differ
    assert len(default) == 3 * 2 * 5 * 2 and (default["status"] == "ok").all()
    assert default["sensor"].nunique() == 2
    assert sorted(default["unit"].unique()) == [0, 1, 2, 3, 4]
    adxl345 = default[default["sensor"] == "adxl345"]
    assert adxl345.groupby("unit")["macro_f1"].mean().nunique() > 1
    pd.testing.assert_frame_equal(default, single)
    pd.testing.assert_frame_equal(default, dask)
