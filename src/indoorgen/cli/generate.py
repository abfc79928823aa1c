"""`indoorgen generate`: a furnished home, or one room, into a directory."""
from __future__ import annotations

import argparse
import functools
import importlib.util
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from indoorgen.architecture.doors import DOOR_MODES, check_door_mode
from indoorgen.assets.materials import check_style, style_names
from indoorgen.constraints.problem import Problem
from indoorgen.errors import ConfigError, IndoorGenError
from indoorgen.export import parse_formats
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.schemas import (
    MAX_HOME_AREA,
    MAX_ROOM_SIDE,
    MIN_ROOM_SIDE,
    FloorplanFile,
    RoomPolygon,
    parse,
    read_json_file,
    read_json_text,
)
from indoorgen.outputs import OVERWRITE_HELP, check_writable
from indoorgen.pipeline import (
    PRESETS,
    GenerateConfig,
    HomeConfig,
    generate,
    generate_home,
    get_preset,
    write_scene_dir,
)
from indoorgen.rng import MAX_SEED
from indoorgen.solver.workers import usable_cores


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Register `generate` on the top-level subparsers."""
    g = subparsers.add_parser("generate", help="generate a furnished home (or one room) into a directory")
    g.add_argument("--seed", type=int, default=0)
    home = g.add_argument_group("a whole home (the default)")
    home.add_argument("--floors", type=int, help="storeys, 1-3 (default 1)")
    home.add_argument("--rooms", help="room counts, e.g. bedroom=2,bathroom=1")
    home.add_argument("--area", type=float, help="ground-floor area in m^2")
    home.add_argument("--floorplan", help="a predefined floorplan.json to furnish")
    home.add_argument("--doors", help="room door leaves: " + "|".join(DOOR_MODES)
                      + " (default open; random: each door open or shut, from the seed)")
    home.add_argument("--workers", type=int, default=None,
                      help="processes solving the home's rooms in parallel (default: one per "
                      "core this process may use); any number gives the same scene")
    g.add_argument("--room",
                   help="one room of this type instead of a home: " + ", ".join(ROOM_TYPES))
    g.add_argument("--size", type=float, nargs=2, metavar=("W", "D"), help="room size in metres")
    g.add_argument("--polygon", help='room outline as JSON, e.g. "[[0,0],[5,0],[5,4],[0,4]]"')
    g.add_argument("--program", help="a custom constraint program, FILE.py:FUNCTION")
    g.add_argument("--out", help="output directory (default ./scene_SEED)")
    g.add_argument("--overwrite", action="store_true", help=OVERWRITE_HELP)
    g.add_argument("--usd-format", choices=["usda", "usdc"], default="usdc",
                   help="binary .usdc (default) or text .usda")
    g.add_argument("--formats", default="usd,urdf,mjcf",
                   help="export formats: usd,usda,usdc,usdz,urdf,mjcf,glb,obj")
    g.add_argument("--preset", default="default",
                   help="time for density: " + ", ".join(PRESETS) + " (default: default)")
    g.add_argument("--style", default=None,
                   help="the home style furniture materials come from: " + ", ".join(style_names())
                   + " (default: drawn from the seed)")
    g.add_argument("--check", action="store_true",
                   help="verify incremental constraint evaluation against full (slow)")
    g.add_argument("--nav-image", action="store_true",
                   help="also write nav_<storey>.png: the floor a robot reaches from the entrance")
    g.add_argument("-q", "--quiet", action="store_true")
    g.set_defaults(func=run_generate)


def _load_program(spec: str) -> Callable[..., Problem]:
    """`path/to/file.py:function` -> the function (a user's own constraint program)."""
    path, _, func = spec.partition(":")
    if not func or not Path(path).is_file():
        raise ConfigError(f"--program {spec!r}: expected FILE.py:FUNCTION with an existing file")
    mod_spec = importlib.util.spec_from_file_location(Path(path).stem, path)
    if mod_spec is None or mod_spec.loader is None:
        raise ConfigError(f"--program {spec!r}: {path} is not a loadable Python file")
    mod = importlib.util.module_from_spec(mod_spec)
    try:
        mod_spec.loader.exec_module(mod)
    except IndoorGenError:
        raise
    except Exception as e:  # a user's file that does not import
        raise ConfigError(f"--program {spec!r} failed to load: {type(e).__name__}: {e}") from None
    fn = getattr(mod, func, None)
    if not callable(fn):
        raise ConfigError(f"--program {spec!r}: {path} has no function {func!r}")
    return _guarded(fn, spec)


def _guarded(fn: Callable[..., Problem], spec: str) -> Callable[..., Problem]:
    """`fn` whose own exceptions become one ConfigError naming the program and the first line
    of its error (it keeps `fn`'s name, which scene.json records)."""

    @functools.wraps(fn)
    def program(*args: Any, **kwargs: Any) -> Problem:
        try:
            return fn(*args, **kwargs)
        except IndoorGenError as e:  # a fault the program's DSL calls found: named with it
            raise type(e)(f"--program {spec!r}: {e}") from e
        except Exception as e:  # the user's code: any error it makes is theirs to fix
            first = (str(e).strip().splitlines() or [""])[0]
            raise ConfigError(f"--program {spec!r} raised {type(e).__name__}: {first}") from e

    return program


def _check_sizes(args: argparse.Namespace) -> None:
    """Refuse --size and --area outside the ranges a room or a home may have, before any work."""
    if args.size is not None:
        w, d = args.size
        if not all(MIN_ROOM_SIDE <= v <= MAX_ROOM_SIDE for v in (w, d)):
            raise ConfigError(f"--size {w:g} {d:g} is out of range; each side must be between "
                              f"{MIN_ROOM_SIDE:g} and {MAX_ROOM_SIDE:g} m")
    if args.area is not None and not 0 < args.area <= MAX_HOME_AREA:
        raise ConfigError(f"--area {args.area:g} is out of range; a home's ground floor is "
                          f"over 0 and at most {MAX_HOME_AREA:g} m^2")


def run_generate(args: argparse.Namespace) -> int:
    """`indoorgen generate`: a furnished home (default) or one room, written atomically."""
    out = Path(args.out or f"scene_{args.seed}")
    check_writable(out, overwrite=args.overwrite)
    formats, config = check_options(args)
    progress = not args.quiet and sys.stderr.isatty()
    if isinstance(config, GenerateConfig):
        gen = generate(args.seed, config, progress=progress)
    else:
        gen = generate_home(args.seed, config, progress=progress)
    write_scene_dir(gen, out, usd_ext=args.usd_format, formats=formats, nav_images=args.nav_image,
                    overwrite=args.overwrite)
    if not args.quiet:
        rep = gen.report
        viol = sum(r["n_violated"] for r in rep["rooms"].values())
        print(f"{out}: {len(gen.scene.rooms)} room(s), {rep['objects']} objects, {viol} hard "
              f"constraints violated, {rep['timings_s']['total']:.2f} s")
        print(f"{out}: layout quality {_quality_line(rep['quality'])}")
        print(f"{out}: navigation {_navigation_line(rep['navigation'])}")
        print(f"{out}: status {_status_line(rep['status'], rep.get('replanned', []))}")
    return 0


def check_options(args: argparse.Namespace) -> tuple[list[str], GenerateConfig | HomeConfig]:
    """Check every option before any work (`batch` checks a dataset's options once with it):
    the export formats and the room's or the home's configuration; ConfigError if one is bad."""
    formats = parse_formats(args.formats)
    get_preset(args.preset)  # a bad name fails here, before any work
    if args.style is not None:
        check_style(args.style)
    if not 0 <= args.seed <= MAX_SEED:
        raise ConfigError(f"--seed must be an integer from 0 to {MAX_SEED}, got {args.seed}")
    if args.workers is not None and args.workers < 1:
        raise ConfigError(f"--workers must be a positive integer, got {args.workers}")
    _check_sizes(args)
    room_opts = [o for o in ("room", "size", "polygon", "program") if getattr(args, o) is not None]
    if args.doors is not None:
        check_door_mode(args.doors)
    home_opts = [o for o in ("floors", "rooms", "area", "floorplan", "doors")
                 if getattr(args, o) is not None]
    if room_opts and home_opts:
        raise ConfigError(f"--{room_opts[0]} makes a single room and --{home_opts[0]} a whole "
                          "home; give options of one kind only")
    return formats, (_room_config(args) if room_opts else _home_config(args))


def _quality_line(quality: dict[str, Any]) -> str:
    """One line for the layout-quality report: passed, or which hard rules failed, and the share
    of all rule instances that hold."""
    checked = sum(r["checked"] for r in quality["rules"].values())
    held = sum(r["passed"] for r in quality["rules"].values())
    share = f"{held}/{checked} rule checks hold"
    if quality["passed"]:
        return f"passed ({share})"
    failed = sorted({line.split(":", 1)[0] for line in quality["failures"]})
    return f"FAILED: {', '.join(failed)} ({share}; see report.json)"


def _navigation_line(nav: dict[str, Any]) -> str:
    """One line for the navigation report: the reachable share, and what cannot be reached."""
    line = (f"{nav['reachable_share']:.0%} of the walkable floor reachable by a "
            f"{nav['agent_radius']:g} m-radius robot")
    if nav["unreachable_rooms"]:
        line += f"; unreachable rooms: {', '.join(nav['unreachable_rooms'])}"
    if nav["unreachable_doors"]:
        line += f"; doors not passable: {', '.join(nav['unreachable_doors'])}"
    return line


def _status_line(status: dict[str, Any], replanned: list[dict[str, Any]]) -> str:
    """One line for the scene's status: ok, or failed with its first reason and a count; and
    how many of the seed's floorplans were given up first."""
    reasons = status["reasons"]
    given_up = (f" (on the seed's floorplan {len(replanned) + 1}: {len(replanned)} before it "
                f"failed; see report.json's replanned)" if replanned else "")
    if not status["failed"]:
        return f"ok: every hard requirement met{given_up}"
    more = f" (+{len(reasons) - 1} more; see report.json)" if len(reasons) > 1 else ""
    return f"FAILED: {reasons[0]}{more}{given_up}"


def _room_config(args: argparse.Namespace) -> GenerateConfig:
    cfg = GenerateConfig(room_type=args.room or "living_room",
                         size=tuple(args.size) if args.size else None,
                         program=_load_program(args.program) if args.program else None,
                         check=args.check, preset=args.preset, style=args.style)
    if args.polygon:
        data = read_json_text(args.polygon, "--polygon", "polygon")
        room = parse(RoomPolygon, {"polygon": data}, "--polygon")
        cfg.polygon = list(room.polygon)
    return cfg


def _home_config(args: argparse.Namespace) -> HomeConfig:
    plan = None
    if args.floorplan:
        plan = read_json_file(args.floorplan, f"--floorplan file {args.floorplan!r}", "floorplan")
        parse(FloorplanFile, plan, f"--floorplan file {args.floorplan!r}")
    return HomeConfig(floors=1 if args.floors is None else args.floors, rooms=args.rooms,
                      area=args.area,
                      floorplan=plan, check=args.check, doors=args.doors or "open",
                      preset=args.preset, workers=args.workers or usable_cores(), style=args.style)
