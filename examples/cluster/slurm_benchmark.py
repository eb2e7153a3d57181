"""Run ``sdt benchmark`` on a SLURM cluster: dask-jobqueue starts the workers, sdt feeds them.

Run it on the login node, in the Python environment every compute node also
sees (a shared home or software folder), with the data and the feature cache on
a filesystem every node mounts at the same path (docs/scale.md):

    pip install "sdt-framework[cluster]"
    python examples/cluster/slurm_benchmark.py --nodes 4 --cores 16 --queue cpu \\
        -- --data /shared/NLN-EMP --cache-dir /shared/sdt-cache --out results/nln

Each SLURM job is one node running ``--cores`` single-threaded Dask workers (a
fit is single-threaded by design; parallelism comes from workers). Everything
after ``--`` goes to ``sdt benchmark``, which checks every worker before
sending work (same sdt and plugin versions, data files readable, cache
writable) and stores each finished run in ``--out`` on this machine, so a
cluster that goes away mid-run is resumed by running the same command again.
"""

from __future__ import annotations

import argparse
import subprocess
import sys

from dask_jobqueue import SLURMCluster


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nodes", type=int, default=2, help="SLURM jobs (one per node)")
    parser.add_argument("--cores", type=int, default=16, help="workers per node")
    parser.add_argument("--memory", default="64GB", help="memory per node")
    parser.add_argument("--walltime", default="02:00:00", help="time limit per job")
    parser.add_argument("--queue", default=None, help="SLURM partition")
    parser.add_argument("--account", default=None, help="SLURM account")
    parser.add_argument("benchmark", nargs=argparse.REMAINDER, help="-- sdt benchmark options")
    args = parser.parse_args()
    options = [a for a in args.benchmark if a != "--"]
    cluster = SLURMCluster(
        cores=args.cores,
        processes=args.cores,  # one thread per worker process
        memory=args.memory,
        walltime=args.walltime,
        queue=args.queue,
        account=args.account,
    )
    print(cluster.job_script(), flush=True)
    cluster.scale(jobs=args.nodes)
    try:
        with cluster.get_client() as client:
            client.wait_for_workers(args.nodes * args.cores)  # all: only those present are checked
            command = ["sdt", "benchmark", *options, "--backend", "dask"]
            command += ["--scheduler", cluster.scheduler_address]
            return subprocess.run(command, check=False).returncode
    finally:
        cluster.close()


if __name__ == "__main__":
    sys.exit(main())
