"""Layout-quality benchmark: the `quality` report over generated rooms and homes.

    python benchmarks/quality.py [--seeds 20] [--homes 5] [--types living_room,bedroom]

Generates `--seeds` single rooms of each main room type (living, dining, kitchen, bedroom,
bathroom) and `--homes` one-storey homes, evaluates `quality.layout.quality_report` on each, and
prints: per rule, its instances and pass rate (and, for hard rules, how many scenes it failed);
per room type (homes' rooms included), the median objects per room and the median share of a
room's most common generator, and how many rooms end with a violated hard constraint of their
program (circulation included); the community measures (median and p90 over scenes); and the
report's time per scene. `--misses` also prints every failed instance as its scene finishes.
"""
from __future__ import annotations

import argparse
import statistics
import time
from collections import Counter, defaultdict

import numpy as np

from indoorgen.pipeline import GenerateConfig, Generated, HomeConfig, generate, generate_home
from indoorgen.quality.layout import quality_report

ROOM_TYPES = ("living_room", "dining_room", "kitchen", "bedroom", "bathroom")
MEASURES = ("collision_rate", "out_of_bounds_rate")


def scenes(seeds: int, homes: int, types: tuple[str, ...] = ROOM_TYPES):
    """(label, Generated) for every room and home benchmarked."""
    for rt in types:
        for seed in range(seeds):
            yield f"{rt} seed {seed}", generate(seed, GenerateConfig(room_type=rt))
    for seed in range(homes):
        yield f"home seed {seed}", generate_home(seed, HomeConfig())


def room_stats(g: Generated, per_type: dict[str, list[tuple[int, float, bool]]]) -> None:
    """Add each room's (objects, most common generator's share, any hard constraint of its
    program violated) to `per_type`."""
    for rn, room in g.scene.rooms.items():
        objs = g.scene.objects_in(rn)
        if objs:
            top = Counter(o.generator for o in objs).most_common(1)[0][1]
            result = g.results.get(rn)
            violated = result is not None and any(v > 0 for v in result.violations.values())
            per_type[room.room_type].append((len(objs), top / len(objs), violated))


def misses(label: str, rep: dict) -> list[str]:
    """One line per failed instance of a scene's quality report (`rules`' instances list
    failed ones first): the scene, the rule, its room and objects and what it measured."""
    return [f"  {label}: {name} in {c['room']}: {', '.join(c['objects'])}: value {c['value']}, "
            f"limit {c['limit']}{', ' + str(c['detail']) if 'detail' in c else ''}"
            for name, r in sorted(rep["rules"].items()) for c in r["instances"] if not c["ok"]]


def main() -> None:
    """Run the benchmark and print its tables."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=20, help="single rooms per main room type")
    ap.add_argument("--homes", type=int, default=5, help="one-storey homes")
    ap.add_argument("--types", default=",".join(ROOM_TYPES),
                    help="comma-separated room types to generate single rooms of")
    ap.add_argument("--misses", action="store_true",
                    help="print every failed instance as its scene finishes")
    a = ap.parse_args()
    types = tuple(t for t in a.types.split(",") if t)
    checked: Counter[str] = Counter()
    passed: Counter[str] = Counter()
    scenes_failed: Counter[str] = Counter()
    hard: dict[str, bool] = {}
    measures: dict[str, list[float]] = defaultdict(list)
    per_type: dict[str, list[tuple[int, float, bool]]] = defaultdict(list)
    times, n, n_passed = [], 0, 0
    for label, g in scenes(a.seeds, a.homes, types):
        t0 = time.perf_counter()
        rep = quality_report(g.scene, g.rooms, g.cache, g.architecture)
        times.append(time.perf_counter() - t0)
        if a.misses:
            for line in misses(label, rep):
                print(line, flush=True)
        n += 1
        n_passed += rep["passed"]
        for name, r in rep["rules"].items():
            checked[name] += r["checked"]
            passed[name] += r["passed"]
            hard[name] = r["hard"]
            scenes_failed[name] += r["passed"] < r["checked"]
        for m in MEASURES:
            measures[m].append(rep["measures"][m])
        room_stats(g, per_type)

    print(f"{n} scenes ({a.seeds} seeds x {len(types)} room types, {a.homes} homes); "
          f"{n_passed} pass every hard rule")
    print(f"\n{'rule':32s} {'hard':>4s} {'instances':>9s} {'passed':>7s} {'rate':>6s} {'scenes failed':>13s}")
    for name in sorted(checked):
        rate = passed[name] / checked[name] if checked[name] else 1.0
        print(f"{name:32s} {'yes' if hard[name] else '':>4s} {checked[name]:9d} {passed[name]:7d} "
              f"{rate:6.1%} {scenes_failed[name]:13d}")
    total_c, total_p = sum(checked.values()), sum(passed.values())
    print(f"{'all rules':32s} {'':4s} {total_c:9d} {total_p:7d} {total_p / max(total_c, 1):6.1%}")
    print(f"\n{'room type':16s} {'rooms':>5s} {'median objects':>14s} {'median top-generator share':>26s} "
          f"{'hard violated':>13s}")
    for rt in sorted(per_type):
        rows = per_type[rt]
        print(f"{rt:16s} {len(rows):5d} {statistics.median(r[0] for r in rows):14.1f} "
              f"{statistics.median(r[1] for r in rows):26.1%} {sum(r[2] for r in rows):13d}")
    print(f"\n{'measure':20s} {'median':>8s} {'p90':>8s}")
    for m in MEASURES:
        v = np.array(measures[m])
        print(f"{m:20s} {np.median(v):8.4f} {np.percentile(v, 90):8.4f}")
    t = np.array(times)
    print(f"\nreport time per scene: median {np.median(t):.3f} s, p90 {np.percentile(t, 90):.3f} s, "
          f"max {t.max():.3f} s")


if __name__ == "__main__":
    main()
