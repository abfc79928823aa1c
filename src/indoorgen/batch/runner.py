"""Running a batch's scene tasks: one child process per scene, supervised by its parent.

A child generates one scene and sends back its record (`jobs.run_scene`). The parent kills a
child that outlives `timeout` (a `timeout` record) or whose resident memory passes
`max_memory` (a `failed` record), and a child that dies (killed, out of memory) loses only its
own scene: the next scene gets a fresh process. Children fork from a `forkserver` that has
imported the generate command once, so a scene pays no start-up imports, and no state passes
from one scene to the next.

`run_local` keeps `workers` children busy on this machine; `run_dask` submits one task per scene
to a Dask cluster (`--scheduler`), where each task supervises its scene's child the same way.
"""
from __future__ import annotations

import contextlib
import logging
import multiprocessing
import multiprocessing.connection
import os
import signal
import time
from collections import deque
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from pathlib import Path
from typing import Any

from threadpoolctl import threadpool_limits

from indoorgen.batch.jobs import Entry, record, run_scene, scene_dir
from indoorgen.errors import SchedulerError
from indoorgen.outputs import clean_stale

log = logging.getLogger(__name__)

#: how often the parent looks at its children's memory and clocks (seconds)
POLL_S = 0.25
#: native threads (OpenBLAS's pool) per scene's process. A batch's parallelism is its workers, as
#: with Dask, whose workers set OMP/MKL/OPENBLAS_NUM_THREADS=1: a scene's small matrix products gain
#: nothing from a second thread, whose spinning took ~20% more CPU per scene and ate the other
#: worker's core (a 2-worker batch ran 1.68x a 1-worker one; see benchmarks/batch.py)
SCENE_THREADS = 1
#: the page size /proc/<pid>/statm counts in
_PAGE = os.sysconf("SC_PAGE_SIZE") if hasattr(os, "sysconf") else 4096


#: the process contexts a batch starts its children with
_Context = multiprocessing.context.ForkServerContext | multiprocessing.context.SpawnContext


@dataclass(frozen=True)
class SceneJob:
    """What every scene of a batch shares: the generate entry and options, where scenes go, and
    the limits each child is held to (seconds, bytes of resident memory; None: no limit)."""

    entry: Entry
    options: Mapping[str, Any]
    scenes: Path
    timeout: float | None = None
    max_memory: int | None = None


@dataclass
class _Child:
    """One scene's process, its result pipe and when it started."""

    seed: int
    proc: BaseProcess
    conn: Connection
    started: float = field(default_factory=time.monotonic)


def _child_main(job: SceneJob, seed: int, conn: Connection) -> None:
    """In the child: generate one scene, with native thread pools (BLAS) of one thread, and
    send its record to the parent."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    with threadpool_limits(limits=SCENE_THREADS):
        conn.send(run_scene(job.entry, job.options, seed, job.scenes))
    conn.close()


def _context(job: SceneJob) -> _Context:
    """The forkserver context (children fork from a server that imported the entry's module
    once); spawn where there is no forkserver."""
    if "forkserver" in multiprocessing.get_all_start_methods():
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload([job.entry.__module__, "indoorgen.batch.jobs"])
        return ctx
    return multiprocessing.get_context("spawn")


def _start(ctx: _Context, job: SceneJob, seed: int) -> _Child:
    """Start seed `seed`'s child."""
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_child_main, args=(job, seed, send), name=f"indoorgen-scene-{seed}",
                       daemon=True)
    proc.start()
    send.close()
    return _Child(seed, proc, recv)


def _rss(pid: int | None) -> int:
    """Resident memory of process `pid` in bytes (0 where /proc cannot say)."""
    try:
        with open(f"/proc/{pid}/statm") as f:
            return int(f.read().split()[1]) * _PAGE
    except (OSError, ValueError, IndexError):
        return 0


def _check(child: _Child, job: SceneJob) -> dict[str, Any] | None:
    """The child's record if it has finished (sent a record, died, or was killed over a
    limit), else None."""
    if child.conn.poll():
        try:
            rec: dict[str, Any] = child.conn.recv()
            child.proc.join()
            return rec
        except (EOFError, OSError):
            pass
    elapsed = time.monotonic() - child.started
    if not child.proc.is_alive():
        child.proc.join()
        code = child.proc.exitcode
        how = f"killed by signal {-code}" if code is not None and code < 0 else f"exit {code}"
        return record(child.seed, "failed", f"the scene's process died ({how}; out of memory?)",
                      wall=elapsed)
    if job.timeout is not None and elapsed > job.timeout:
        _kill(child)
        return record(child.seed, "timeout", f"over --timeout-per-scene {job.timeout:g} s",
                      wall=elapsed)
    if job.max_memory is not None and (rss := _rss(child.proc.pid)) > job.max_memory:
        _kill(child)
        return record(child.seed, "failed", f"resident memory {rss / 2**20:.0f} MiB over "
                      f"--max-memory-per-worker {job.max_memory / 2**20:.0f} MiB", wall=elapsed)
    return None


def _kill(child: _Child) -> None:
    """Kill the child and reap it."""
    child.proc.kill()
    child.proc.join()


def _finish(child: _Child, job: SceneJob) -> None:
    """Close the child's pipe and remove what a killed child left of its scene."""
    child.conn.close()
    clean_stale(scene_dir(job.scenes, child.seed))


def run_local(job: SceneJob, seeds: Sequence[int], *, workers: int) -> Iterator[dict[str, Any]]:
    """Generate `seeds` with up to `workers` children at a time, yielding each scene's record
    as it finishes (in finishing order). Stopping early (an exception, Ctrl-C, closing the
    iterator) kills the children still running."""
    ctx = _context(job)
    pending = deque(seeds)
    running: list[_Child] = []
    try:
        while pending or running:
            while pending and len(running) < max(1, workers):
                running.append(_start(ctx, job, pending.popleft()))
            multiprocessing.connection.wait([c.conn for c in running]
                                            + [c.proc.sentinel for c in running], timeout=POLL_S)
            for child in list(running):
                rec = _check(child, job)
                if rec is not None:
                    running.remove(child)
                    _finish(child, job)
                    yield rec
    finally:
        for child in running:
            _kill(child)
            _finish(child, job)


def supervise_one(job: SceneJob, seed: int) -> dict[str, Any]:
    """One scene in a supervised child, waited for here (a Dask task's body). In a daemonic
    process, which may not have children, the scene runs in this process instead: the cluster's
    own worker restarts and memory limits then hold it, and the timeout is not applied."""
    if multiprocessing.current_process().daemon:
        log.warning("seed %d runs in the Dask worker's own process (a daemonic worker may not "
                    "start children; set distributed.worker.daemon to False): no time limit", seed)
        return run_scene(job.entry, job.options, seed, job.scenes)
    return next(run_local(job, [seed], workers=1))


def run_dask(job: SceneJob, seeds: Sequence[int], *, client: Any) -> Iterator[dict[str, Any]]:
    """Generate `seeds` on the Dask cluster of `client` (a `distributed.Client`), one task per
    scene, yielding each record as it finishes. A task whose workers died more often than the
    cluster allows (`distributed.scheduler.allowed-failures`) is recorded as failed."""
    from distributed import as_completed  # noqa: PLC0415 (optional dependency: the dask extra)

    futures = {client.submit(supervise_one, job, s, key=f"indoorgen-scene-{s}-{time.time_ns()}",
                             pure=False): s for s in seeds}
    try:
        for fut in as_completed(futures):
            seed = futures[fut]
            try:
                yield fut.result()
            except Exception as e:  # a worker lost with the task (KilledWorker) or the like
                yield record(seed, "failed", f"{type(e).__name__}: {str(e).strip()[:200]}")
            finally:
                clean_stale(scene_dir(job.scenes, seed))
    finally:
        client.cancel(list(futures))


@contextlib.contextmanager
def dask_client(scheduler: str, *, workers: int, connect_timeout: float,
                max_memory: int | None = None) -> Iterator[Any]:
    """A `distributed.Client` for `--scheduler`: `local` starts a `LocalCluster` of `workers`
    single-threaded processes (non-daemonic, so each task can supervise its scene's child);
    an address (`tcp://HOST:PORT`) connects to a running scheduler, failing with a one-line
    SchedulerError if it does not answer within `connect_timeout` seconds."""
    try:  # optional dependency (the `dask` extra): imported only when a batch asks for Dask
        import dask  # noqa: PLC0415
        from distributed import Client, LocalCluster  # noqa: PLC0415
    except ImportError:
        raise SchedulerError("--scheduler needs Dask: pip install 'indoorgen[dask]'") from None
    # Dask logs each worker's start and stop at INFO on its own handlers: keep them to warnings
    logging.getLogger("distributed").setLevel(max(logging.WARNING, logging.getLogger().level))
    if scheduler == "local":
        with dask.config.set({"distributed.worker.daemon": False}):
            cluster = LocalCluster(n_workers=max(1, workers), threads_per_worker=1,
                                   processes=True, dashboard_address=":0",
                                   memory_limit=max_memory or "auto")
        try:
            with Client(cluster) as client:
                yield client
        finally:
            cluster.close()
        return
    if not scheduler.startswith(("tcp://", "tls://", "ucx://", "inproc://")):
        raise SchedulerError(f"--scheduler {scheduler!r}: expected 'local' or an address such as "
                             "tcp://HOST:8786")
    try:
        client = Client(scheduler, timeout=connect_timeout)
    except (OSError, TimeoutError) as e:
        raise SchedulerError(f"the Dask scheduler at {scheduler} did not answer within "
                             f"{connect_timeout:g} s ({type(e).__name__}); start it, or check "
                             "the address") from None
    with client:
        yield client
