"""Batch benchmark: scenes per hour with 1 and 2 local workers, their ratio, where the time goes,
and the peak memory of one scene's process for a 2-storey home.

    python benchmarks/batch.py [--scenes 6] [--room bedroom] [--preset fast] [--homes2 1]

Runs `make_dataset` (what `indoorgen batch` runs) over seeds 0..scenes-1 into a scratch
directory, once with 1 worker and once with 2, and prints scenes per hour for each and the ratio
(the target is >= 1.9x on two idle cores). To tell start-up cost from the work itself it prints,
per run, the median seconds a scene spends in the pipeline (report.json's total plus export)
and its CPU seconds (equal with 1 and 2 workers: the workers do not slow each other through
memory bandwidth or caches), and the wall time of the run not spent in scenes (process starts,
the manifest); a warm-up scene first starts the forkserver (imports paid once per run) and is
timed apart. The load average is printed beside the figures: on a shared machine the ratio
measures the neighbours too. Then it makes `--homes2` 2-storey homes (default preset, every
default format) with 1 worker and prints each scene process's peak resident memory (the
manifest's `peak_rss_mb`).
"""
from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

from indoorgen.batch.dataset import make_dataset
from indoorgen.batch.manifest import read_manifest
from indoorgen.cli.batch import generate_options
from indoorgen.cli.generate import run_generate


def run(out: Path, seeds: list[int], workers: int, options: dict) -> dict:
    load = os.getloadavg()[0]
    t0 = time.monotonic()
    s = make_dataset(out, seeds, run_generate, options, workers=workers, progress=False)
    wall = time.monotonic() - t0
    recs = [r for r in read_manifest(out) if r["status"] == "ok"]
    inside = [r["seconds"]["total"] + r["seconds"].get("export", 0.0) for r in recs]
    return {"workers": workers, "ok": s["ok"], "failed": s["failed"] + s["timeout"],
            "wall": wall, "per_hour": s["ok"] * 3600 / wall, "inside": statistics.median(inside),
            "overhead": wall - sum(inside) / workers, "load": load,
            "cpu": statistics.median(r["seconds"]["cpu"] for r in recs),
            "rss": max(r.get("peak_rss_mb", 0.0) for r in recs)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=6)
    ap.add_argument("--room", default="bedroom")
    ap.add_argument("--preset", default="fast")
    ap.add_argument("--formats", default="mjcf")
    ap.add_argument("--homes2", type=int, default=1)
    args = ap.parse_args()
    seeds = list(range(args.scenes))
    options = generate_options(room=args.room, preset=args.preset, formats=args.formats)
    with tempfile.TemporaryDirectory(prefix="indoorgen-batch-bench-") as tmp:
        t0 = time.monotonic()  # the first batch starts the forkserver, which imports indoorgen
        make_dataset(Path(tmp) / "warm", [10_000], run_generate, options, workers=1,
                     progress=False)
        print(f"start-up: the first scene of a run took {time.monotonic() - t0:.1f} s "
              "(the forkserver importing indoorgen once, then the scene)")
        results = [run(Path(tmp) / f"w{w}", seeds, w, options) for w in (1, 2)]
        print(f"{args.scenes} {args.room} scenes, preset {args.preset}, formats {args.formats}, "
              f"{os.cpu_count()} cores")
        for r in results:
            print(f"  {r['workers']} worker(s): {r['per_hour']:.0f} scenes/hour ({r['ok']} ok, "
                  f"{r['failed']} failed, {r['wall']:.1f} s); per scene median "
                  f"{r['inside']:.2f} s in the pipeline, {r['cpu']:.2f} CPU s; "
                  f"{r['overhead']:.1f} s of the run's wall "
                  "time outside scenes; "
                  f"peak RSS {r['rss']:.0f} MiB; load average at start {r['load']:.1f}")
        print(f"  ratio 2/1 workers: {results[1]['per_hour'] / results[0]['per_hour']:.2f}x "
              "(target >= 1.9x)")
        if args.homes2:
            home = generate_options(floors=2)
            r = run(Path(tmp) / "home2", list(range(args.homes2)), 1, home)
            rss = [rec.get("peak_rss_mb") for rec in read_manifest(Path(tmp) / "home2")]
            print(f"2-storey homes (default preset and formats): {r['ok']} ok, median "
                  f"{r['inside']:.1f} s in the pipeline; peak RSS per scene process (MiB): {rss}")


if __name__ == "__main__":
    main()
