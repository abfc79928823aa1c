"""Home rooms benchmark: solve only the rooms of one type in a home, to study why they fail.

    python benchmarks/home_rooms.py SEED ROOM_TYPE [--floors 1] [--preset default] [--layout]
                                   [--rules]

Builds the home of `SEED` as `indoorgen generate --seed SEED --floors N` builds it (floorplan,
architecture, the room's program with the home's fullness), then solves just the rooms of
`ROOM_TYPE`, each exactly as in the whole home (every room draws its own random streams, so
the others do not change it). Prints the seconds taken and, per room, its size, the hard
constraints left unmet and its walkway record; with `--layout`, its polygon, doors and the
poses and sizes of its large objects; with `--rules`, the layout rules' failed instances (the
quality report's, over these rooms alone). A failed room of `benchmarks/home.py` reproduces here in
seconds instead of a whole home's minutes.
"""
from __future__ import annotations

import argparse
import time

import numpy as np

from indoorgen import pipeline
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.quality.layout import quality_report


def main() -> None:
    """Solve the home's rooms of one type and print what each left unmet."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("seed", type=int)
    ap.add_argument("room_type")
    ap.add_argument("--floors", type=int, default=1)
    ap.add_argument("--preset", default="default", help="fast, default or dense")
    ap.add_argument("--layout", action="store_true", help="print doors and large objects")
    ap.add_argument("--rules", action="store_true", help="print the layout rules' failed instances")
    args = ap.parse_args()
    plan = generate_floorplan(args.seed, FloorplanConfig(floors=args.floors))
    arch = pipeline.solidify(plan, seed=args.seed, doors="open")
    geometry = pipeline.room_geometries(arch)
    preset = pipeline.get_preset(args.preset)
    fullness = pipeline.scene_fullness(args.seed, preset)
    problems = {name: pipeline._home_problem(g.room.room_type, fullness, name)
                for name, g in geometry.items() if g.room.room_type == args.room_type}
    if not problems:
        types = sorted({g.room.room_type for g in geometry.values()})
        raise SystemExit(f"home {args.seed} has no {args.room_type}; it has {', '.join(types)}")
    t0 = time.perf_counter()
    gen = pipeline._furnish(args.seed, geometry, problems, {}, {},
                            steps=pipeline.stage_steps(preset, None), check=False,
                            progress=False)
    print(f"{len(problems)} room(s) solved in {time.perf_counter() - t0:.1f} s")
    for name in sorted(problems):
        room = geometry[name].room
        poly = np.asarray(room.polygon, float)
        size = np.ptp(poly, axis=0)
        record = gen.report["rooms"][name]
        unmet = {k: round(v, 3) for k, v in record["violations"].items() if v > 1e-9}
        print(f"{name}: {size[0]:.1f} x {size[1]:.1f} m, {len(poly)} corners, "
              f"{len(room.doors)} doors; unmet: {unmet or 'none'}; "
              f"walkway: {record['circulation']}")
        if args.rules:
            rooms = {n: geometry[n] for n in problems}
            rules = quality_report(gen.scene, rooms, gen.cache, gen.architecture)["rules"]
            for rule, rec in sorted(rules.items()):
                for inst in rec["instances"]:
                    if not inst["ok"] and inst["room"] == name:
                        print(f"  {rule} failed: {inst}")
        if not args.layout:
            continue
        print("  polygon", np.round(poly, 2).tolist())
        for d in room.doors:
            print(f"  door {d.name}: wall {d.wall}, offset {d.offset:.2f}, width {d.width:.2f}")
        for obj in sorted(gen.scene.objects.values(), key=lambda o: o.name):
            if obj.room == name and obj.stage == "large":
                extents = gen.state.objects[obj.name].asset.mesh.extents
                print(f"  {obj.name} at {np.round(obj.pose.position, 2).tolist()}, "
                      f"yaw {np.degrees(obj.pose.yaw):.0f}, size {np.round(extents, 2).tolist()}")


if __name__ == "__main__":
    main()
