"""`indoorgen export`: re-export a saved scene.json to other formats, without solving."""
from __future__ import annotations

import argparse
from pathlib import Path

from indoorgen.export.formats import DEFAULT_FORMATS, FORMATS
from indoorgen.export.scene_files import export_scene
from indoorgen.outputs import OVERWRITE_HELP


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Register `export` on the top-level subparsers."""
    e = subparsers.add_parser("export", help="re-export a saved scene.json to other formats")
    e.add_argument("scene", help="a scene.json (or the directory holding it)")
    e.add_argument("--formats", default=",".join(DEFAULT_FORMATS),
                   help=f"comma-separated, from {', '.join(FORMATS)} "
                        f"(default {','.join(DEFAULT_FORMATS)})")
    e.add_argument("--out", help="output directory (default: the scene's own directory)")
    e.add_argument("--usd-format", choices=["usdc", "usda"], default="usdc")
    e.add_argument("--texture-resolution", type=int, default=512,
                   help="texture size in pixels (0: no textures)")
    e.add_argument("--doors", help="re-stand a home's door leaves: open|closed|random "
                                   "(default: as scene.json records them)")
    e.add_argument("--overwrite", action="store_true", help=OVERWRITE_HELP)
    e.set_defaults(func=run_export)


def run_export(args: argparse.Namespace) -> int:
    """`indoorgen export`."""
    out, timings = export_scene(Path(args.scene), Path(args.out) if args.out else None,
                                args.formats, usd_ext=args.usd_format,
                                texture_resolution=args.texture_resolution, doors=args.doors,
                                overwrite=args.overwrite)
    print(f"{out}: " + ", ".join(f"{k} {v:.2f} s" for k, v in timings.items()))
    return 0
