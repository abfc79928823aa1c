"""Asset benchmark: build time and size of every generator.

    python benchmarks/assets.py [--seeds 5] [--only NAME ...]

Prints, per generator, the median milliseconds to build the placeholder and the full mesh over
`--seeds` parameter samples, the median and largest triangle counts, and whether each meets the
catalogue's targets (placeholder <= 5 ms; full <= 150 ms for small and medium objects, <= 1 s for
large ones; <= 30k triangles large, <= 5k small). Then the catalogue's totals.
"""
from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from indoorgen.assets import factory_names, get_factory

FULL_MS = {"small": 150.0, "medium": 150.0, "large": 1000.0}
TRIANGLES = {"small": 5000, "medium": 20000, "large": 30000}


def measure(name: str, seeds: int) -> dict:
    f = get_factory(name)
    ph_ms, full_ms, tris = [], [], []
    for seed in range(seeds):
        p = f.sample_params(np.random.default_rng(seed))
        t0 = time.perf_counter()
        f.placeholder(p)
        t1 = time.perf_counter()
        a = f.create(p)
        t2 = time.perf_counter()
        ph_ms.append((t1 - t0) * 1e3)
        full_ms.append((t2 - t1) * 1e3)
        tris.append(len(a.mesh.faces))
    return {"name": name, "size": f.size_class, "params": len(f.params),
            "ph_ms": statistics.median(ph_ms), "full_ms": statistics.median(full_ms),
            "tris": int(statistics.median(tris)), "tris_max": max(tris),
            "joints": len(a.joints)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--only", nargs="*")
    args = ap.parse_args()
    names = args.only or factory_names()
    print(f"{'generator':26s} {'size':6s} {'params':>6s} {'ph ms':>7s} {'full ms':>8s} "
          f"{'tris':>6s} {'max':>6s}  targets")
    rows, misses = [], 0
    for n in names:
        r = measure(n, args.seeds)
        rows.append(r)
        miss = []
        if r["ph_ms"] > 5.0:
            miss.append("placeholder")
        if r["full_ms"] > FULL_MS[r["size"]]:
            miss.append("full")
        if r["tris_max"] > TRIANGLES[r["size"]]:
            miss.append("triangles")
        misses += bool(miss)
        print(f"{n:26s} {r['size']:6s} {r['params']:6d} {r['ph_ms']:7.1f} {r['full_ms']:8.1f} "
              f"{r['tris']:6d} {r['tris_max']:6d}  {'MISS ' + ','.join(miss) if miss else 'ok'}")
    print(f"\n{len(rows)} generators, {sum(r['params'] for r in rows)} parameters, "
          f"{sum(1 for r in rows if r['joints'])} articulated (seed {args.seeds - 1})")
    print(f"median placeholder {statistics.median(r['ph_ms'] for r in rows):.1f} ms, "
          f"median full {statistics.median(r['full_ms'] for r in rows):.1f} ms, "
          f"slowest full {max(rows, key=lambda r: r['full_ms'])['name']} "
          f"{max(r['full_ms'] for r in rows):.0f} ms; {misses} generators miss a target")


if __name__ == "__main__":
    main()
