"""Floorplan benchmark: seconds per home, rule checks over many seeds, objective terms.

    python benchmarks/floorplan.py [--seeds 100] [--floors 1 2 3] [--steps N] [--jobs 1]

For each number of storeys, generates homes for seeds 0..N-1 and prints the median and 90th
percentile seconds (wall and CPU) of the floorplan stage (graph -> annealing -> openings) and of
solidification, the median for one-storey homes of 6-9 rooms, how many homes break a rule of
`floorplan.check` (should be 0), how many fell back to minimum room widths, per room type the
rooms' areas and doors, and the objective and each of its twelve terms (weighted) before and
after annealing, averaged over the seeds.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from indoorgen.architecture.solidify import solidify
from indoorgen.floorplan.check import floorplan_problems
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.floorplan import Floorplan
from indoorgen.programs.floorplan import floorplan as default_program


def one(job: tuple[int, int, int | None]) -> dict:
    seed, floors, steps = job
    cfg = FloorplanConfig(floors=floors)
    if steps is not None:
        cfg.anneal = FloorplanAnnealConfig(steps_per_storey=steps)
    w0, c0 = time.perf_counter(), time.process_time()
    try:
        fp = generate_floorplan(seed, cfg)
    except Exception as e:  # reported, not fatal: the benchmark counts failures
        return {"seed": seed, "error": f"{type(e).__name__}: {e}"}
    w1, c1 = time.perf_counter(), time.process_time()
    solidify(fp)
    w2, c2 = time.perf_counter(), time.process_time()
    stats = fp.info["stats"]
    return {"seed": seed, "rooms": [len(s.rooms) for s in fp.storeys],
            "fallback": not fp.info.get("planned_widths", True), "room_doors": room_doors(fp),
            "wall": w1 - w0, "cpu": c1 - c0, "solid_wall": w2 - w1, "solid_cpu": c2 - c1,
            "problems": floorplan_problems(fp, fp.info["contours"]),
            "start": stats.start.scores, "end": stats.end.scores,
            "loss": (stats.start.loss, stats.end.loss), "timings": fp.info["timings_s"]}


def room_doors(fp: Floorplan) -> list[tuple[str, float, int]]:
    """(type, area m^2, doors and open connections, the front door counted) of every room."""
    out = []
    for s in fp.storeys:
        for r in s.rooms:
            doors = sum(r.name in d.rooms for d in s.doors + s.openings)
            doors += int(fp.entrance is not None and fp.entrance.room == r.name)
            out.append((r.type, r.shape().area, doors))
    return out


def print_rooms(ok: list[dict]) -> None:
    """Per room type: how many, their median and smallest area, and how many have 3+ doors."""
    by_type: dict[str, list[tuple[float, int]]] = {}
    for r in ok:
        for t, area, doors in r["room_doors"]:
            by_type.setdefault(t, []).append((area, doors))
    print(f"  {'room type':16s} {'rooms':>5s} {'median m^2':>10s} {'min m^2':>8s} "
          f"{'3+ doors':>8s} {'median doors':>12s}")
    for t, rows in sorted(by_type.items()):
        areas, doors = [a for a, _ in rows], [d for _, d in rows]
        print(f"  {t:16s} {len(rows):5d} {statistics.median(areas):10.1f} {min(areas):8.1f} "
              f"{sum(d >= 3 for d in doors):8d} {statistics.median(doors):12.1f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=100)
    ap.add_argument("--floors", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--steps", type=int, default=None, help="annealing steps per storey")
    ap.add_argument("--jobs", type=int, default=1, help="worker processes (timings are per "
                    "process; use 1 for clean figures)")
    args = ap.parse_args()
    weights = {k: t.weight for k, t in default_program().score_terms.items()}
    generate_floorplan(0, FloorplanConfig(anneal=FloorplanAnnealConfig(steps_per_storey=5)))  # warm up
    for floors in args.floors:
        jobs = [(s, floors, args.steps) for s in range(args.seeds)]
        if args.jobs > 1:
            with ProcessPoolExecutor(args.jobs) as ex:
                rows = list(ex.map(one, jobs))
        else:
            rows = [one(j) for j in jobs]
        ok = [r for r in rows if "error" not in r]
        errors = [r for r in rows if "error" in r]
        bad = [r for r in ok if r["problems"]]

        def q(xs, p):
            return float(np.percentile(xs, p)) if xs else float("nan")

        wall = [r["wall"] for r in ok]
        cpu = [r["cpu"] for r in ok]
        print(f"== {floors} storey(s), {len(rows)} seeds ==")
        print(f"  floorplan stage  median {statistics.median(wall):.3f} s wall, "
              f"{statistics.median(cpu):.3f} s CPU; p90 {q(wall, 90):.3f} s wall")
        print(f"    of which init {statistics.median([r['timings']['init'] for r in ok]):.3f} s, "
              f"anneal {statistics.median([r['timings']['anneal'] for r in ok]):.3f} s (median)")
        print(f"  solidify         median {statistics.median([r['solid_wall'] for r in ok]):.3f}"
              f" s wall, {statistics.median([r['solid_cpu'] for r in ok]):.3f} s CPU")
        if floors == 1:
            mid = [r for r in ok if 6 <= r["rooms"][0] <= 9]
            if mid:
                print(f"  one storey, 6-9 rooms ({len(mid)} homes): median "
                      f"{statistics.median([r['wall'] for r in mid]):.3f} s wall, "
                      f"{statistics.median([r['cpu'] for r in mid]):.3f} s CPU")
        print(f"  rooms per storey: mean {np.mean([np.mean(r['rooms']) for r in ok]):.1f}")
        print(f"  homes breaking a rule: {len(bad)}   generation errors: {len(errors)}   "
              f"on minimum widths: {sum(r['fallback'] for r in ok)}")
        print_rooms(ok)
        for r in bad[:5]:
            print(f"    seed {r['seed']}: {r['problems'][:3]}")
        for r in errors[:5]:
            print(f"    seed {r['seed']}: {r['error']}")
        s0 = np.mean([r["loss"][0] for r in ok])
        s1 = np.mean([r["loss"][1] for r in ok])
        lower = sum(1 for r in ok if r["loss"][1] < r["loss"][0])
        print(f"  objective: mean {s0:.3f} -> {s1:.3f}  (lower in {lower}/{len(ok)} homes)")
        print(f"  {'term (weighted, mean over homes)':50s} {'start':>8s} {'end':>8s}")
        for k, w in weights.items():
            a = np.mean([w * r["start"][k] for r in ok])
            b = np.mean([w * r["end"][k] for r in ok])
            print(f"  {k:50s} {a:8.3f} {b:8.3f}")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
