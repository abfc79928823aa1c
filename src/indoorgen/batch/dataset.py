"""Making a dataset: a batch of seeds into one directory, resumable and crash-safe.

`make_dataset` checks the directory (`manifest.check_batch_dir`), holds it for the run (one
batch writes a directory at a time), cleans what killed attempts left, skips the seeds already
done, runs the rest on the local pool or a Dask cluster (`runner`), appends each record to the
manifest as it lands, shows a tqdm bar, and returns the run's `summary`.
"""
from __future__ import annotations

import contextlib
import functools
import os
import statistics
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

from tqdm import tqdm

from indoorgen.batch.jobs import Entry
from indoorgen.batch.manifest import (
    Manifest,
    check_batch_dir,
    clean_leftovers,
    latest,
    read_manifest,
    scenes_dir,
    seeds_to_run,
    write_batch_json,
)
from indoorgen.batch.runner import SceneJob, dask_client, run_dask, run_local
from indoorgen.outputs import output_lock


def make_dataset(out: Path, seeds: Sequence[int], entry: Entry, options: Mapping[str, Any], *,
                 workers: int | None = None, scheduler: str | None = None, client: Any = None,
                 timeout: float | None = None, max_memory: int | None = None,
                 retry_failed: bool = False, force: bool = False, progress: bool = True,
                 connect_timeout: float = 10.0) -> dict[str, Any]:
    """Generate every seed of `seeds` not yet done in `out` with the generate `options`
    (through `entry`), on `workers` local processes (default: the cores), a Dask `scheduler`
    (`local` or an address) or an existing Dask `client`; return the `summary` of the run."""
    out = Path(out)
    workers = workers or (os.cpu_count() or 1)
    settings = {"generate": dict(options)}
    check_batch_dir(out, settings, force=force)
    job = SceneJob(entry, dict(options), scenes_dir(out.resolve()), timeout, max_memory)
    with _runner(job, workers, scheduler, client, connect_timeout) as run:
        out.mkdir(parents=True, exist_ok=True)
        with output_lock(out):
            write_batch_json(out, settings)
            clean_leftovers(out)
            todo = seeds_to_run(seeds, out, retry_failed=retry_failed)
            t0 = time.monotonic()
            done: list[dict[str, Any]] = []
            with Manifest(out) as manifest, \
                    tqdm(total=len(todo), unit="scene", file=sys.stderr, disable=not progress,
                         dynamic_ncols=True) as bar:
                for rec in run(todo):
                    manifest.append(rec)
                    done.append(rec)
                    bar.update(1)
                    bar.set_postfix(failed=sum(r["status"] != "ok" for r in done), refresh=False)
    return summary(done, time.monotonic() - t0, read_manifest(out), skipped=len(seeds) - len(todo))


@contextlib.contextmanager
def _runner(job: SceneJob, workers: int, scheduler: str | None, client: Any,
            connect_timeout: float) -> Iterator[Callable[[Sequence[int]], Iterator[dict[str, Any]]]]:
    """A function running seeds to their records as they finish, on the local pool or on Dask
    (connected first, so a scheduler that does not answer fails before anything is written)."""
    if client is not None:
        yield functools.partial(run_dask, job, client=client)
    elif scheduler is not None:
        with dask_client(scheduler, workers=workers, connect_timeout=connect_timeout,
                         max_memory=job.max_memory) as c:
            yield functools.partial(run_dask, job, client=c)
    else:
        yield functools.partial(run_local, job, workers=workers)


def summary(run: Sequence[Mapping[str, Any]], elapsed: float,
            manifest: Iterable[Mapping[str, Any]], *, skipped: int = 0) -> dict[str, Any]:
    """This run's scenes per hour and failures, and medians over the whole dataset (each seed's
    last record in the manifest): seconds per scene, objects, rule checks held, reachable share."""
    ok = [r for r in run if r["status"] == "ok"]
    last = [r for r in latest(manifest).values() if r["status"] == "ok"]

    def med(values: Iterable[Any]) -> float | None:
        vals = [float(v) for v in values if v is not None]
        return round(statistics.median(vals), 4) if vals else None

    return {"attempted": len(run), "ok": len(ok), "skipped": skipped,
            "failed": sum(r["status"] == "failed" for r in run),
            "timeout": sum(r["status"] == "timeout" for r in run),
            "failure_rate": round(1 - len(ok) / len(run), 4) if run else 0.0,
            "seconds": round(elapsed, 2),
            "scenes_per_hour": round(len(ok) * 3600 / elapsed, 1) if elapsed > 0 else None,
            "dataset_ok": len(last),
            "median_scene_seconds": med(r["seconds"].get("wall") for r in last),
            "median_objects": med(r.get("objects") for r in last),
            "median_rule_share": med(r["quality"].get("share") for r in last),
            "median_reachable_share": med(r["navigation"].get("reachable_share") for r in last)}


def summary_lines(s: Mapping[str, Any]) -> list[str]:
    """The summary as the lines `indoorgen batch` prints at the end."""
    return [f"{s['ok']} of {s['attempted']} scenes made in {s['seconds']:.0f} s "
            f"({s['scenes_per_hour']} scenes/hour); {s['failed']} failed, {s['timeout']} timed "
            f"out (failure rate {s['failure_rate']:.1%}); {s['skipped']} already done",
            f"dataset: {s['dataset_ok']} scenes; medians: {s['median_scene_seconds']} s per scene, "
            f"{s['median_objects']} objects, {s['median_rule_share']} of rule checks held, "
            f"{s['median_reachable_share']} of the floor reachable"]
