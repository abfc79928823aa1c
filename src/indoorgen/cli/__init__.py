"""`indoorgen` command line: argument handling only, one module per command; the work is in
`pipeline` and the packages below it.

Any `IndoorGenError` becomes one line on stderr and exit status 2; so does anything else that
escapes a command (an internal error, named as such), and running out of memory or stack.
`--debug` shows the traceback instead.
"""
from __future__ import annotations

import argparse
import logging
import sys

from indoorgen.cli import assets, batch, export, floorplan, generate, validate
from indoorgen.errors import IndoorGenError


def build_parser() -> argparse.ArgumentParser:
    """The whole command line: generate, validate, export, assets, asset, floorplan, batch,
    dataset-stats."""
    p = argparse.ArgumentParser(prog="indoorgen",
                                description="Procedural furnished homes and rooms.")
    p.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    p.add_argument("--debug", action="store_true",
                   help="on an error, show the full traceback instead of one line")
    sub = p.add_subparsers(dest="command", required=True)
    generate.add_parser(sub)
    validate.add_parser(sub)
    assets.add_parsers(sub)
    export.add_parser(sub)
    floorplan.add_parser(sub)
    batch.add_parsers(sub)
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
        if args.debug:
            raise
        print(f"indoorgen: error: {_one_line(e)}", file=sys.stderr)
        return 2
    except (MemoryError, RecursionError) as e:
        if args.debug:
            raise
        print(f"indoorgen: error: the input is too large or too deeply nested to handle "
              f"({type(e).__name__}); give smaller input (--debug shows where)", file=sys.stderr)
        return 2
    except Exception as e:
        if args.debug:
            raise
        print(f"indoorgen: internal error: {type(e).__name__}: {_one_line(e)} (this is a bug; "
              "--debug shows the traceback)", file=sys.stderr)
        return 2


def _one_line(e: BaseException) -> str:
    """The first line of an exception's message (a message never spans lines on stderr)."""
    text = str(e).strip()
    return text.splitlines()[0] if text else type(e).__name__
