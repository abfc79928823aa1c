"""Make a dataset from Python: on local processes, on a Dask LocalCluster, or on a SLURM cluster
through dask-jobqueue.

    python examples/make_dataset.py --out data --count 100                 # local processes
    python examples/make_dataset.py --out data --count 100 --dask-local 2  # a Dask LocalCluster
    python examples/make_dataset.py --out data --count 5000 --slurm 50     # 50 SLURM jobs

The same as `indoorgen batch --count 100 --out data --room bedroom --preset fast` (add
`--scheduler local` or `--scheduler tcp://HOST:8786` for Dask). Run it again to resume: seeds
already done are skipped. `indoorgen dataset-stats data` then says what the dataset holds.

On SLURM (`pip install dask-jobqueue`), `slurm_client` below asks for one single-core job per
worker. Each worker runs one scene at a time, in a child process it supervises (time limit,
memory); for that its worker process must be allowed children, hence
`DASK_DISTRIBUTED__WORKER__DAEMON=False` in the job's prologue. Adjust the queue, account,
memory and walltime to your site.
"""
from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from indoorgen.batch.dataset import make_dataset, summary_lines
from indoorgen.cli.batch import generate_options
from indoorgen.cli.generate import run_generate


def slurm_client(jobs: int) -> Any:
    """A Dask client on `jobs` SLURM jobs of one single-threaded worker each (dask-jobqueue)."""
    from dask_jobqueue import SLURMCluster  # noqa: PLC0415 (only on a cluster's login node)
    from distributed import Client  # noqa: PLC0415

    cluster = SLURMCluster(
        queue="normal",                 # your partition
        account=None,                   # your account, if your site needs one
        cores=1, processes=1,           # one worker, one scene at a time, per job
        memory="8GB",                   # a 2-storey home's scene process stays well under this
        walltime="12:00:00",
        job_script_prologue=["export DASK_DISTRIBUTED__WORKER__DAEMON=False"],
        worker_extra_args=["--nthreads", "1"],
    )
    cluster.adapt(minimum_jobs=1, maximum_jobs=jobs)  # jobs come and go with the work left
    return Client(cluster)


def local_dask_client(workers: int) -> Any:
    """A Dask client on a LocalCluster of `workers` processes (what `--scheduler local` starts)."""
    import dask  # noqa: PLC0415
    from distributed import Client, LocalCluster  # noqa: PLC0415

    with dask.config.set({"distributed.worker.daemon": False}):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, dashboard_address=":0")
    return Client(cluster)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--count", type=int, default=10)
    ap.add_argument("--room", default="bedroom", help="a room type, or 'home' for whole homes")
    ap.add_argument("--preset", default="fast")
    ap.add_argument("--formats", default="usd,urdf,mjcf")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--dask-local", type=int, metavar="WORKERS")
    where.add_argument("--slurm", type=int, metavar="JOBS")
    args = ap.parse_args()

    # every `indoorgen generate` option by its name: room, floors, rooms, doors, program...
    opts = generate_options(preset=args.preset, formats=args.formats,
                            **({} if args.room == "home" else {"room": args.room}))
    client = None
    if args.dask_local:
        client = local_dask_client(args.dask_local)
    elif args.slurm:
        client = slurm_client(args.slurm)
    try:
        summary = make_dataset(args.out, range(args.count), run_generate, opts, client=client,
                               timeout=1800)
    finally:
        if client is not None:
            client.close()
            client.cluster.close()
    for line in summary_lines(summary):
        print(line)


if __name__ == "__main__":
    main()
