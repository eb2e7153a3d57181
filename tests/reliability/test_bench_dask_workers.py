"""A Dask worker that cannot do the work as this machine would is one line before any work.

Two honest ways a worker differs from the machine that sends the work, each a
real ``dask worker`` process joined to a local scheduler beside an ordinary one:

- a worker in its own mount namespace with an empty filesystem mounted over the
  data folder (``unshare``): the path exists here and not there, as on a node
  without the shared filesystem;
- a worker started with another environment (``PYTHONPATH`` holding a plugin
  distribution this machine does not have).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.errors import SDTError


def _manifest(folder: Path) -> Path:
    """Six 1.5 s runs at 20 kHz on one channel: healthy 1-3 and a fault at severities 1-3."""
    folder.mkdir()
    rng = np.random.default_rng(0)
    rows = []
    for condition, severity in [("healthy", "")] * 3 + [("bearing", s) for s in (1, 2, 3)]:
        run = f"{condition}-{len(rows)}"
        np.save(folder / f"{run}.npy", rng.normal(size=30000))
        rows.append(f"{run}.npy,20000,{condition},{severity},{run},ch1")
    manifest = folder / "manifest.csv"
    header = "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
    manifest.write_text(header + "\n".join(rows) + "\n")
    return manifest


def _worker(address: str, prefix: list[str], env: dict[str, str]) -> subprocess.Popen:
    command = [sys.executable, "-m", "distributed.cli.dask_worker", address]
    command += ["--nthreads", "1", "--no-dashboard", "--name", "odd"]
    return subprocess.Popen(
        prefix + command,
        env={**os.environ, **env},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )


def _can_unshare() -> str | None:
    if shutil.which("unshare") is None:
        return "the unshare program is absent"
    probe = subprocess.run(
        ["unshare", "-rm", "sh", "-c", "mount -t tmpfs none /mnt"], capture_output=True
    )
    return None if probe.returncode == 0 else f"unshare -rm failed: {probe.stderr[:100]!r}"


def _cluster_with_odd_worker(prefix: list[str], env: dict[str, str]):
    """(cluster, client, the odd worker's process, its address)."""
    from distributed import Client, LocalCluster

    cluster = LocalCluster(
        n_workers=1,
        threads_per_worker=1,
        processes=False,
        protocol="tcp",  # not inproc: the odd worker is another process
        host="127.0.0.1",
        dashboard_address=":0",
    )
    client = Client(cluster)
    odd = _worker(cluster.scheduler_address, prefix, env)
    client.wait_for_workers(2, timeout=120)
    address = next(a for a, w in client.scheduler_info()["workers"].items() if w["name"] == "odd")
    return cluster, client, odd, address


def test_worker_that_cannot_see_the_data_is_one_line_before_any_work(tmp_path, sdt_main):
    reason = _can_unshare()
    if reason:
        pytest.skip(f"cannot hide a path from one worker here: {reason}")
    manifest = _manifest(tmp_path / "data")
    mount = f'mount -t tmpfs none "{tmp_path / "data"}" && exec "$0" "$@"'
    hide = ["unshare", "-rm", "sh", "-c", mount]
    cluster, client, odd, address = _cluster_with_odd_worker(hide, {})
    try:
        code, _, err = sdt_main(
            "benchmark", "--data", str(manifest), "--quick", "--classifiers", "lr",
            "--backend", "dask", "--scheduler",
            cluster.scheduler_address, "--no-report", "--out", str(tmp_path / "out"),
            "--cache-dir", str(tmp_path / "cache"),
        )  # fmt: skip
    finally:
        client.close()
        odd.terminate()
        odd.wait(30)
        cluster.close()
    errors = [line for line in err.splitlines() if line.startswith("error:")]
    assert code == 2 and "Traceback" not in err, err
    first = sorted((tmp_path / "data").glob("*.npy"))[0]
    assert errors == [
        f"error: Dask worker {address} (host {os.uname().nodename}) cannot open data file "
        f"{first} (and 5 more of 6); every worker needs the same software and data paths "
        f"(docs/scale.md)"
    ]
    assert not list((tmp_path / "out" / "runs").glob("*.json"))
    assert not (tmp_path / "cache" / "features").exists()  # no recording was featurised


def test_worker_with_another_plugin_is_named(tmp_path):
    from sdt_framework.bench.workers import check_workers

    site = tmp_path / "site"
    info = site / "sdt_extra_sensors-1.2.dist-info"
    info.mkdir(parents=True)
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: sdt-extra-sensors\nVersion: 1.2\n")
    (info / "entry_points.txt").write_text("[sdt_framework]\nextra = sdt_extra_sensors\n")
    path = os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    cluster, client, odd, address = _cluster_with_odd_worker([], {"PYTHONPATH": path})
    try:
        with pytest.raises(SDTError) as caught:
            check_workers(client, [], str(tmp_path / "cache"))
        # the other worker (this process's environment) passes alone
        ordinary = next(a for a in client.scheduler_info()["workers"] if a != address)
        client.retire_workers([address])
        assert check_workers(client, [], str(tmp_path / "cache")) == 1
    finally:
        client.close()
        odd.terminate()
        odd.wait(30)
        cluster.close()
    assert str(caught.value) == (
        f"Dask worker {address} (host {os.uname().nodename}) has sdt-extra-sensors 1.2, not "
        f"installed here; every worker needs the same software and data paths (docs/scale.md)"
    )
    assert ordinary != address


def test_cache_no_worker_can_write_and_a_cluster_without_workers(read_only_dir):
    from distributed import Client, LocalCluster

    from sdt_framework.bench.workers import check_workers

    cache = read_only_dir / "cache"
    with (
        LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0")
        as cluster,
        Client(cluster) as client,
    ):  # fmt: skip
        with pytest.raises(SDTError, match=f"cannot create the feature cache {cache} "):
            check_workers(client, [], str(cache))
        client.retire_workers(list(client.scheduler_info()["workers"]))
        with pytest.raises(SDTError) as caught:
            check_workers(client, [], "")
    assert str(caught.value) == (
        "the Dask cluster has no workers; start some or leave --scheduler out"
    )
