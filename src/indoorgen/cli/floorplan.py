"""`indoorgen floorplan`: generate (or read) a home's floorplan and write `plan.png`,
`floorplan.json` and `architecture.usda` into a directory, atomically (a temporary sibling
directory renamed into place when complete)."""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

from indoorgen.architecture.solidify import solidify
from indoorgen.architecture.walls import WallThickness
from indoorgen.errors import ConfigError
from indoorgen.export.usd.architecture import write_architecture_usd
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan, storey_pitch
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.floorplan_io import read_floorplan, write_floorplan
from indoorgen.model.schemas import MAX_HOME_AREA, HomeContour, RoomGraph, parse, read_json_file
from indoorgen.outputs import OVERWRITE_HELP, atomic_dir, check_writable
from indoorgen.render.floorplan import draw_floorplan
from indoorgen.rng import MAX_SEED


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Register the `floorplan` subcommand on an argparse subparsers object."""
    p = subparsers.add_parser(
        "floorplan", help="generate a multi-room, multi-storey home's floorplan and architecture",
        description="Writes plan.png, floorplan.json and architecture.usda into --out.")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--floors", type=int, default=1, help="storeys, 1 to 3 (default 1)")
    p.add_argument("--rooms", default=None,
                   help="fixed room counts for the whole home, e.g. bedroom=2,bathroom=1")
    p.add_argument("--area", type=float, default=None,
                   help="ground-floor area in m^2 (default: from the rooms' typical areas)")
    p.add_argument("--contour", default=None,
                   help="JSON file with the ground-floor outline: [[x, y], ...]")
    p.add_argument("--graph", default=None,
                   help='JSON file fixing the room graph: {"storeys": [{"rooms": [...], '
                        '"edges": [[a, b], ...]}], "entrance": ROOM}')
    p.add_argument("--plan", default=None,
                   help="a floorplan.json to solidify and draw instead of generating one")
    p.add_argument("--steps", type=int, default=None, help="annealing steps per storey")
    p.add_argument("--out", default=None, help="output directory (default ./floorplan_SEED)")
    p.add_argument("--overwrite", action="store_true", help=OVERWRITE_HELP)
    p.add_argument("-q", "--quiet", action="store_true")
    p.set_defaults(func=run_floorplan)


def _read_contour(path: str) -> list[list[float]]:
    """The --contour file's outline (a list of [x, y], or {"contour": [...]}), schema-checked."""
    what = f"--contour file {path!r}"
    data = read_json_file(path, what, "contour")
    if isinstance(data, dict) and "contour" not in data and "polygon" in data:
        data = {**data, "contour": data["polygon"]}
        del data["polygon"]
    doc = parse(HomeContour, data if isinstance(data, dict) else {"contour": data}, what)
    return [list(p) for p in doc.contour]


def _read_graph(path: str) -> dict[str, Any]:
    """The --graph file's room graph, schema-checked (as `graph_from_spec` reads it)."""
    what = f"--graph file {path!r}"
    data = read_json_file(path, what, "graph")
    parse(RoomGraph, data, what)
    return {k: v for k, v in data.items() if k != "format_version"}


def run_floorplan(args: argparse.Namespace) -> int:
    """The command: validate arguments, generate or read, solidify, write, report one line."""

    t0 = time.perf_counter()
    if not 0 <= args.seed <= MAX_SEED:
        raise ConfigError(f"--seed must be an integer from 0 to {MAX_SEED}, got {args.seed}")
    if not 1 <= args.floors <= 3:
        raise ConfigError(f"--floors {args.floors} is out of range; a home has 1 to 3 storeys")
    if args.steps is not None and args.steps < 0:
        raise ConfigError(f"--steps must be >= 0, got {args.steps}")
    if args.area is not None and not 0 < args.area <= MAX_HOME_AREA:
        raise ConfigError(f"--area {args.area:g} is out of range; a home's ground floor is "
                          f"over 0 and at most {MAX_HOME_AREA:g} m^2")
    out = Path(args.out or f"floorplan_{args.seed}")
    check_writable(out, overwrite=args.overwrite)
    cfg = FloorplanConfig(floors=args.floors, rooms=args.rooms, area=args.area,
                          contour=_read_contour(args.contour) if args.contour else None,
                          graph=_read_graph(args.graph) if args.graph else None)
    if args.steps is not None:
        cfg.anneal = FloorplanAnnealConfig(steps_per_storey=args.steps)
    if args.plan:
        fp = read_floorplan(args.plan)
        pitch = None
    else:
        fp = generate_floorplan(args.seed, cfg)
        pitch = storey_pitch(cfg)
    walls = WallThickness(cfg.interior_wall, cfg.exterior_wall)
    arch = solidify(fp, walls, pitch, seed=args.seed)
    with atomic_dir(out, overwrite=args.overwrite) as tmp:
        write_floorplan(fp, tmp / "floorplan.json")
        draw_floorplan(fp, tmp / "plan.png", walls,
                       title=f"floorplan  seed {args.seed}" if not args.plan else args.plan)
        write_architecture_usd(arch, tmp / "architecture.usda")
    if not args.quiet:
        n_rooms = sum(len(s.rooms) for s in fp.storeys)
        msg = f"{out}: {len(fp.storeys)} storey(s), {n_rooms} rooms"
        a = fp.info.get("anneal")
        if a:
            msg += f", objective {a['objective_start']:.3f} -> {a['objective_end']:.3f}"
        print(f"{msg}, {time.perf_counter() - t0:.2f} s", file=sys.stdout)
    return 0
