"""`indoorgen` command line: argument handling only; the work is in `pipeline` and friends.

Any `IndoorGenError` becomes one line on stderr and exit status 2.
"""
from __future__ import annotations

import argparse
import importlib.util
import json
import logging
import sys
from pathlib import Path

from indoorgen.errors import ConfigError, IndoorGenError


def _load_program(spec: str):
    """`path/to/file.py:function` -> the function (a user's own constraint program)."""
    path, _, func = spec.partition(":")
    if not func or not Path(path).is_file():
        raise ConfigError(f"--program {spec!r}: expected FILE.py:FUNCTION with an existing file")
    mod_spec = importlib.util.spec_from_file_location(Path(path).stem, path)
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
    return fn


def _cmd_generate(args) -> int:
    from indoorgen.export import parse_formats
    from indoorgen.outputs import check_writable
    from indoorgen.pipeline import generate, generate_home, write_scene_dir
    out = Path(args.out or f"scene_{args.seed}")
    check_writable(out)
    formats = parse_formats(args.formats)
    if args.seed < 0:
        raise ConfigError(f"--seed must be a non-negative integer, got {args.seed}")
    progress = not args.quiet and sys.stderr.isatty()
    room_opts = [o for o in ("room", "size", "polygon", "program") if getattr(args, o) is not None]
    home_opts = [o for o in ("floors", "rooms", "area", "floorplan")
                 if getattr(args, o) is not None]
    if room_opts and home_opts:
        raise ConfigError(f"--{room_opts[0]} makes a single room and --{home_opts[0]} a whole "
                          "home; give options of one kind only")
    if room_opts:
        gen = generate(args.seed, _room_config(args), progress=progress)
    else:
        gen = generate_home(args.seed, _home_config(args), progress=progress)
    write_scene_dir(gen, out, usd_ext=args.usd_format, formats=formats)
    if not args.quiet:
        rep = gen.report
        viol = sum(r["n_violated"] for r in rep["rooms"].values())
        print(f"{out}: {len(gen.scene.rooms)} room(s), {rep['objects']} objects, {viol} hard "
              f"constraints violated, {rep['timings_s']['total']:.2f} s")
    return 0


def _room_config(args):
    from indoorgen.pipeline import GenerateConfig
    cfg = GenerateConfig(room_type=args.room or "living_room",
                         size=tuple(args.size) if args.size else None,
                         program=_load_program(args.program) if args.program else None,
                         check=args.check)
    if args.polygon:
        try:
            cfg.polygon = [tuple(map(float, p)) for p in json.loads(args.polygon)]
        except (ValueError, TypeError):
            raise ConfigError(f"--polygon must be a JSON list of [x, y] points, got "
                              f"{args.polygon!r}") from None
    return cfg


def _home_config(args):
    from indoorgen.pipeline import HomeConfig
    plan = None
    if args.floorplan:
        try:
            plan = json.loads(Path(args.floorplan).read_text())
        except FileNotFoundError:
            raise ConfigError(f"--floorplan {args.floorplan}: no such file") from None
        except (ValueError, OSError) as e:
            raise ConfigError(f"--floorplan {args.floorplan} is not a floorplan.json "
                              f"({type(e).__name__}: {e})") from None
    return HomeConfig(floors=1 if args.floors is None else args.floors, rooms=args.rooms,
                      area=args.area,
                      floorplan=plan, check=args.check)


def _cmd_validate(args) -> int:
    from indoorgen.validate import validate_scene_dir
    rep = validate_scene_dir(Path(args.scene))
    print(json.dumps(rep, indent=1, sort_keys=True))
    return 0 if rep["ok"] else 1


def _cmd_assets_list(args) -> int:
    from indoorgen.assets import factory_names, get_factory
    rows = []
    for n in factory_names():
        f = get_factory(n)
        joints = _joint_names(f)
        rows.append({"name": n, "tags": sorted(t.value for t in f.tags),
                     "n_params": len(f.params), "joints": joints,
                     "size_class": f.size_class})
    if args.json:
        print(json.dumps(rows, indent=1))
    else:
        for r in rows:
            j = f"  joints: {', '.join(r['joints'])}" if r["joints"] else ""
            print(f"{r['name']:24s} {r['n_params']:3d} params  {', '.join(r['tags'])}{j}")
        print(f"{len(rows)} generators, {sum(r['n_params'] for r in rows)} parameters")
    return 0


def _joint_names(factory) -> list[str]:
    """The joint kinds a generator can have: the union over 12 sampled parameter sets of
    its joints' names with the numbers stripped (door_0_joint, door_1_joint -> door_joint)."""
    import re

    import numpy as np
    names: set[str] = set()
    for seed in range(12):
        p = factory.resolve(factory.sample_params(np.random.default_rng(seed)))
        names |= {re.sub(r"_\d+", "", j.name) for j in factory.joints(p)}
    return sorted(names)


def _cmd_assets_sheet(args) -> int:
    from tqdm import tqdm

    from indoorgen.assets import factory_names, get_factory
    from indoorgen.outputs import atomic_file
    from indoorgen.render.preview import contact_sheet
    names = factory_names()
    if args.only:
        names = [get_factory(n).name for n in args.only]  # unknown names: one-line error
    with atomic_file(Path(args.out)) as tmp:
        contact_sheet(names, tmp, seed=args.seed, cols=args.cols,
                      progress=tqdm(names, desc="drawing", disable=not sys.stderr.isatty()))
    print(f"{args.out}: {len(names)} generators")
    return 0


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="indoorgen",
                                description="Procedural furnished homes and rooms.")
    p.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = p.add_subparsers(dest="command", required=True)

    g = sub.add_parser("generate", help="generate a furnished home (or one room) into a directory")
    g.add_argument("--seed", type=int, default=0)
    home = g.add_argument_group("a whole home (the default)")
    home.add_argument("--floors", type=int, help="storeys, 1-3 (default 1)")
    home.add_argument("--rooms", help="room counts, e.g. bedroom=2,bathroom=1")
    home.add_argument("--area", type=float, help="ground-floor area in m^2")
    home.add_argument("--floorplan", help="a predefined floorplan.json to furnish")
    g.add_argument("--room",
                   help="one room of this type instead of a home: living_room, dining_room, "
                        "bedroom, kitchen, bathroom, office, closet, hallway, utility, "
                        "staircase_room, garage, balcony, warehouse")
    g.add_argument("--size", type=float, nargs=2, metavar=("W", "D"), help="room size in metres")
    g.add_argument("--polygon", help='room outline as JSON, e.g. "[[0,0],[5,0],[5,4],[0,4]]"')
    g.add_argument("--program", help="a custom constraint program, FILE.py:FUNCTION")
    g.add_argument("--out", help="output directory (default ./scene_SEED)")
    g.add_argument("--usd-format", choices=["usda", "usdc"], default="usdc",
                   help="binary .usdc (default) or text .usda")
    g.add_argument("--formats", default="usd,urdf,mjcf",
                   help="export formats: usd,usda,usdc,usdz,urdf,mjcf,glb,obj")
    g.add_argument("--check", action="store_true",
                   help="verify incremental constraint evaluation against full (slow)")
    g.add_argument("-q", "--quiet", action="store_true")
    g.set_defaults(func=_cmd_generate)

    v = sub.add_parser("validate", help="check a generated scene directory independently")
    v.add_argument("scene")
    v.set_defaults(func=_cmd_validate)

    a = sub.add_parser("assets", help="the asset catalogue")
    asub = a.add_subparsers(dest="assets_command", required=True)
    al = asub.add_parser("list", help="list generators")
    al.add_argument("--json", action="store_true")
    al.set_defaults(func=_cmd_assets_list)
    sh = asub.add_parser("sheet", help="draw every generator into one PNG contact sheet")
    sh.add_argument("--out", default="sheet.png")
    sh.add_argument("--seed", type=int, default=0)
    sh.add_argument("--cols", type=int, default=10)
    sh.add_argument("--only", nargs="+", metavar="NAME", help="draw only these generators")
    sh.set_defaults(func=_cmd_assets_sheet)
    importlib.import_module("indoorgen.export.command").add_export_parsers(sub)
    importlib.import_module("indoorgen.floorplan.command").add_floorplan_parser(sub)
    return p




def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    try:
        return args.func(args)
    except IndoorGenError as e:
        print(f"indoorgen: error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
