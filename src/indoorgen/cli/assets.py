"""The asset catalogue on the command line: `indoorgen assets list`, `indoorgen assets sheet`, and
`indoorgen asset NAME` (one textured asset to a file)."""
from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np
from tqdm import tqdm

from indoorgen.assets import AssetFactory, factory_names, get_factory
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.errors import ParameterError
from indoorgen.export.asset_file import ASSET_EXTENSIONS, write_asset
from indoorgen.export.scene_files import check_texture_resolution
from indoorgen.outputs import atomic_file
from indoorgen.render.preview import contact_sheet


def add_parsers(subparsers: argparse._SubParsersAction) -> None:
    """Register `assets` (list, sheet) and `asset` on the top-level subparsers."""
    a = subparsers.add_parser("assets", help="the asset catalogue")
    asub = a.add_subparsers(dest="assets_command", required=True)
    al = asub.add_parser("list", help="list generators")
    al.add_argument("--json", action="store_true")
    al.set_defaults(func=run_list)
    sh = asub.add_parser("sheet", help="draw every generator into one PNG contact sheet")
    sh.add_argument("--out", default="sheet.png")
    sh.add_argument("--seed", type=int, default=0)
    sh.add_argument("--cols", type=int, default=10)
    sh.add_argument("--only", nargs="+", metavar="NAME", help="draw only these generators")
    sh.set_defaults(func=run_sheet)

    a = subparsers.add_parser("asset", help="write one textured asset to a file")
    a.add_argument("name", help="generator name (see `indoorgen assets list`)")
    a.add_argument("--seed", type=int, default=0)
    a.add_argument("--out", required=True, help="FILE" + "|".join(ASSET_EXTENSIONS))
    a.add_argument("--param", action="append", default=[], metavar="K=V",
                   help="override one parameter (repeatable)")
    a.add_argument("--texture-resolution", type=int, default=512)
    a.set_defaults(func=run_asset)


def run_list(args: argparse.Namespace) -> int:
    """`indoorgen assets list`: every generator, its tags, parameters and joints."""
    rows: list[dict[str, Any]] = []
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


def _joint_names(factory: AssetFactory) -> list[str]:
    """The joint kinds a generator can have: the union over 12 sampled parameter sets of
    its joints' names with the numbers stripped (door_0_joint, door_1_joint -> door_joint)."""
    if not isinstance(factory, PartsFactory):
        return []
    names: set[str] = set()
    for seed in range(12):
        p = factory.resolve(factory.sample_params(np.random.default_rng(seed)))
        names |= {re.sub(r"_\d+", "", j.name) for j in factory.joints(p)}
    return sorted(names)


def run_sheet(args: argparse.Namespace) -> int:
    """`indoorgen assets sheet`: every generator drawn into one PNG contact sheet."""
    names = factory_names()
    if args.only:
        names = [get_factory(n).name for n in args.only]  # unknown names: one-line error
    with atomic_file(Path(args.out)) as tmp:
        contact_sheet(names, tmp, seed=args.seed, cols=args.cols,
                      progress=tqdm(names, desc="drawing", disable=not sys.stderr.isatty()))
    print(f"{args.out}: {len(names)} generators")
    return 0


def parse_param(text: str) -> tuple[str, Any]:
    """`k=v` -> (k, v) with v read as JSON when it parses (numbers, true/false), else a string."""
    key, sep, value = text.partition("=")
    if not sep or not key.strip():
        raise ParameterError(f"--param {text!r} is invalid; expected NAME=VALUE")
    try:
        v = json.loads(value)
    except ValueError:
        v = value
    return key.strip(), v


def run_asset(args: argparse.Namespace) -> int:
    """`indoorgen asset NAME`: one textured asset written to a file."""
    check_texture_resolution(args.texture_resolution)
    overrides = dict(parse_param(p) for p in args.param)
    out = write_asset(args.name, args.seed, Path(args.out), overrides,
                      texture_resolution=args.texture_resolution)
    print(f"{out}: {args.name} seed {args.seed}")
    return 0
