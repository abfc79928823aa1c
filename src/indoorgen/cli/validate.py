"""`indoorgen validate`: an independent check of a written scene directory."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

from indoorgen.validate import validate_scene_dir


def add_parser(subparsers: argparse._SubParsersAction) -> None:
    """Register `validate` on the top-level subparsers."""
    v = subparsers.add_parser("validate", help="check a generated scene directory independently")
    v.add_argument("scene")
    v.set_defaults(func=run_validate)


def run_validate(args: argparse.Namespace) -> int:
    """`indoorgen validate`: print the report; exit 1 when the scene breaks a check."""
    rep = validate_scene_dir(Path(args.scene))
    print(json.dumps(rep, indent=1, sort_keys=True))
    return 0 if rep["ok"] else 1
