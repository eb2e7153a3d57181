"""Dask workers get absolute data paths, whatever folder they were started in.

docs/scale.md says the plan names every recording by its absolute path; on
main a relative ``--data manifest.csv`` gave the workers relative paths, and a
worker started in another folder was refused: "cannot open data file
healthy0.npy". Also: ``--data`` naming nothing is said to not exist.
"""

from __future__ import annotations

import os
import subprocess
import sys

from ..helpers import six_recordings


def test_a_worker_started_in_another_folder_opens_the_data(tmp_path, sdt_main, monkeypatch):
    from distributed import Client, LocalCluster

    data = tmp_path / "data"
    elsewhere = tmp_path / "elsewhere"
    data.mkdir()
    elsewhere.mkdir()
    six_recordings(data, "manifest.csv")
    with (
        LocalCluster(n_workers=0, processes=False, protocol="tcp", host="127.0.0.1",
                     dashboard_address=":0") as cluster,
        Client(cluster) as client,
    ):  # fmt: skip
        worker = subprocess.Popen(
            [sys.executable, "-m", "distributed.cli.dask_worker", cluster.scheduler_address,
             "--nthreads", "1", "--no-dashboard"],
            cwd=elsewhere, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )  # fmt: skip
        try:
            client.wait_for_workers(1, timeout=120)
            monkeypatch.chdir(data)
            code, out, err = sdt_main(
                "benchmark", "--data", "manifest.csv", "--quick", "--sensors", "wilcoxon-786b10",
                "--classifiers", "lr", "--backend", "dask", "--scheduler",
                cluster.scheduler_address, "--no-report", "--out", str(tmp_path / "out"),
                "--cache-dir", str(tmp_path / "cache"),
            )  # fmt: skip
        finally:
            worker.terminate()
            worker.wait(30)
    assert code == 0 and "error" not in err, err
    assert "6 runs (6 computed, 0 resumed, 0 failed)" in out
    assert os.getcwd() == str(data)


def test_a_data_path_that_does_not_exist_is_said_so(tmp_path, sdt_main, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for given in ("manifst.csv", "NLN-EMPP"):
        code, _, err = sdt_main("benchmark", "--data", given, "--quick", "--out", "out")
        assert code == 2 and err.splitlines() == [
            f"error: --data {given} does not exist (looked for in {tmp_path}); give an NLN-EMP "
            f"folder, a .csv/.parquet manifest or a registered dataset (manifest, nln-emp, "
            f"synthetic-pump)"
        ], err
    assert not (tmp_path / "out").exists()
