"""`indoorgen` command line: argument handling only, one module per command; the work is in
`pipeline` and the packages below it.

Any `IndoorGenError` becomes one line on stderr and exit status 2.
"""
from __future__ import annotations

import argparse
import logging
import sys

from indoorgen.cli import assets, export, floorplan, generate, validate
from indoorgen.errors import IndoorGenError


def build_parser() -> argparse.ArgumentParser:
    """The whole command line: generate, validate, export, assets, asset, floorplan."""
    p = argparse.ArgumentParser(prog="indoorgen",
                                description="Procedural furnished homes and rooms.")
    p.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = p.add_subparsers(dest="command", required=True)
    generate.add_parser(sub)
    validate.add_parser(sub)
    assets.add_parsers(sub)
    export.add_parser(sub)
    floorplan.add_parser(sub)
    return p


def main(argv: list[str] | None = None) -> int:
    """Run one command; bad input prints one line and returns 2."""
    parser = build_parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")
    try:
        return int(args.func(args))
    except IndoorGenError as e:
        print(f"indoorgen: error: {e}", file=sys.stderr)
        return 2
