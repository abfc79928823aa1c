"""Material library benchmark: median milliseconds to generate each material's maps.

    python benchmarks/materials.py [--resolution 512] [--seeds 5] [--only oak,brick]

Calls `MaterialGenerator.generate` directly (bypassing bake's cache), one seed after another,
and prints per material the median wall-clock and CPU (process) time and the worst wall time,
then the totals. On a shared machine the CPU time is the steadier figure.
"""
from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from indoorgen.assets.materials import get_material, material_names


def time_material(name: str, resolution: int, seeds: int) -> tuple[list[float], list[float]]:
    """Wall-clock and CPU milliseconds of `generate` for seeds 0..seeds-1."""
    gen = get_material(name)
    wall, cpu = [], []
    for seed in range(seeds):
        params = gen.sample_params(np.random.default_rng(seed))
        t0, c0 = time.perf_counter(), time.process_time()
        gen.generate(params, resolution, seed)
        wall.append((time.perf_counter() - t0) * 1000.0)
        cpu.append((time.process_time() - c0) * 1000.0)
    return wall, cpu


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--resolution", type=int, default=512)
    ap.add_argument("--seeds", type=int, default=5)
    ap.add_argument("--only", default="", help="comma-separated material names")
    args = ap.parse_args()
    names = [n for n in args.only.split(",") if n] or material_names()
    get_material(names[0]).generate({}, 64, 0)  # warm up imports and FFT plans
    print(f"== materials at {args.resolution} px, {args.seeds} seeds ==")
    print(f"{'material':<22} {'family':<10} {'median ms':>9} {'cpu ms':>8} {'max ms':>8}")
    medians, cpus = [], []
    for name in names:
        wall, cpu = time_material(name, args.resolution, args.seeds)
        medians.append(statistics.median(wall))
        cpus.append(statistics.median(cpu))
        print(f"{name:<22} {get_material(name).family:<10} {medians[-1]:9.1f} {cpus[-1]:8.1f} "
              f"{max(wall):8.1f}")
    print(f"{'total (sum of medians)':<33} {sum(medians):9.1f} {sum(cpus):8.1f}")
    print(f"{'mean per material':<33} {sum(medians) / len(medians):9.1f} "
          f"{sum(cpus) / len(cpus):8.1f}")
    slow = int(np.argmax(medians))
    print(f"{'slowest':<22} {names[slow]:<10} {medians[slow]:9.1f} {cpus[slow]:8.1f}")


if __name__ == "__main__":
    main()
