"""`indoorgen batch`: many seeds into a dataset directory; `indoorgen dataset-stats`: what is in it.

Every `generate` option passes through: the batch command takes the generate command's own
argument definitions (all but --seed, --out, --overwrite and --quiet, which a batch sets per
scene), and each scene is made by `generate`'s own function, `run_generate`.
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path
from typing import Any

from indoorgen.batch.dataset import make_dataset, summary_lines
from indoorgen.batch.stats import dataset_stats, plot_stats, stats_lines
from indoorgen.cli import generate
from indoorgen.errors import BatchConfigError

#: generate's options that a batch sets for each scene itself
PER_SCENE = frozenset({"seed", "out", "overwrite", "quiet", "help", "workers"})
#: the generate options holding a path, made absolute so a worker elsewhere finds the file
PATH_OPTIONS = ("program", "floorplan")
#: what --max-memory-per-worker's units mean
_UNITS = {"": 2**20, "k": 2**10, "m": 2**20, "g": 2**30, "t": 2**40}
#: the most seeds one batch takes (a typo such as --count 1e9 fails at once)
MAX_SCENES = 10_000_000


def _generate_parser() -> argparse.ArgumentParser:
    """The generate command's own parser (built on a scratch subparsers object)."""
    scratch = argparse.ArgumentParser(add_help=False).add_subparsers()
    generate.add_parser(scratch)
    parser: argparse.ArgumentParser = scratch.choices["generate"]
    return parser


def generate_options(**overrides: Any) -> dict[str, Any]:
    """The generate options a batch's scenes are made with: generate's defaults, then
    `overrides` (by destination name: room="bedroom", preset="fast"...)."""
    parser = _generate_parser()
    opts = {a.dest: a.default for a in parser._actions if a.dest not in PER_SCENE}
    unknown = sorted(set(overrides) - set(opts))
    if unknown:
        raise BatchConfigError(f"unknown generate option(s) {', '.join(unknown)}; valid: "
                               + ", ".join(sorted(opts)))
    opts.update(overrides)
    for name in PATH_OPTIONS:
        if opts.get(name):
            path, sep, rest = str(opts[name]).partition(":")
            opts[name] = str(Path(path).resolve()) + sep + rest
    return opts


def add_parsers(subparsers: argparse._SubParsersAction) -> None:
    """Register `batch` and `dataset-stats` on the top-level subparsers."""
    b = subparsers.add_parser("batch", help="generate a dataset: many seeds, resumable, on local "
                              "processes or a Dask cluster")
    b.add_argument("--count", type=int, metavar="N", help="how many scenes (with --seeds: the first COUNT)")
    seeds = b.add_mutually_exclusive_group()
    seeds.add_argument("--start-seed", type=int, default=0, metavar="S", help="the first seed (default 0)")
    seeds.add_argument("--seeds", metavar="FILE", help="a file of seeds: integers separated by "
                       "spaces, commas or lines (# starts a comment)")
    b.add_argument("--out", required=True, metavar="DIR", help="the dataset directory")
    b.add_argument("--workers", type=int, metavar="K", help="local processes (default: the number of cores)")
    b.add_argument("--scheduler", metavar="local|tcp://HOST:PORT",
                   help="run on Dask: 'local' (a LocalCluster of --workers processes) or a "
                   "scheduler address")
    b.add_argument("--scheduler-timeout", type=float, default=10.0, metavar="SEC",
                   help="seconds to wait for the scheduler to answer (default 10)")
    b.add_argument("--timeout-per-scene", type=float, metavar="SEC", help="kill a scene after SEC seconds")
    b.add_argument("--max-memory-per-worker", metavar="SIZE", help="kill a scene whose process holds more "
                   "memory than this (e.g. 4G, 1500M)")
    b.add_argument("--retry-failed", action="store_true",
                   help="also retry seeds that failed or timed out")
    b.add_argument("--force", action="store_true", help="add to a directory made with other "
                   "options or another indoorgen version")
    b.add_argument("-q", "--quiet", action="store_true", help="no progress bar or summary")
    passed = b.add_argument_group("generate options (passed to every scene; see `indoorgen "
                                  "generate --help`)")
    for action in _generate_parser()._actions:  # the same definitions, not copies of them
        if action.dest not in PER_SCENE:
            passed._add_action(action)
    b.set_defaults(func=run_batch)

    s = subparsers.add_parser("dataset-stats", help="what a dataset holds: room types, objects, "
                              "diversity, quality, navigation, disk use; plotted in stats.png")
    s.add_argument("dir", help="a dataset directory written by `indoorgen batch`")
    s.add_argument("--plot", help="where to write the plot (default DIR/stats.png)")
    s.set_defaults(func=run_dataset_stats)


def run_batch(args: argparse.Namespace) -> int:
    """`indoorgen batch`: check every input, then make the dataset and print its summary."""
    seeds = _seeds(args)
    workers = args.workers
    if workers is not None and workers < 1:
        raise BatchConfigError(f"--workers must be at least 1, got {workers}")
    if args.timeout_per_scene is not None and args.timeout_per_scene <= 0:
        raise BatchConfigError(f"--timeout-per-scene must be over 0 s, got {args.timeout_per_scene:g}")
    max_memory = parse_size(args.max_memory_per_worker) if args.max_memory_per_worker else None
    options = generate_options(**{k: v for k, v in vars(args).items()
                                  if k in generate_options()})
    _check_generate_options(options)
    result = make_dataset(Path(args.out), seeds, generate.run_generate, options, workers=workers,
                          scheduler=args.scheduler, timeout=args.timeout_per_scene,
                          max_memory=max_memory, retry_failed=args.retry_failed,
                          force=args.force, progress=not args.quiet and sys.stderr.isatty(),
                          connect_timeout=args.scheduler_timeout)
    if not args.quiet:
        for line in summary_lines(result):
            print(f"{args.out}: {line}")
    return 0


def _check_generate_options(options: dict[str, Any]) -> None:
    """Refuse bad generate options before any work: run generate's own checks on a scratch
    output (everything up to the first scene's work), so a typo fails once, not per scene."""
    ns = argparse.Namespace(**{**options, "seed": 0, "quiet": True, "overwrite": False,
                               "workers": 1})
    generate.check_options(ns)


def _seeds(args: argparse.Namespace) -> list[int]:
    """The batch's seeds, from --start-seed and --count or from --seeds FILE."""
    if args.count is not None and not 1 <= args.count <= MAX_SCENES:
        raise BatchConfigError(f"--count must be between 1 and {MAX_SCENES}, got {args.count}")
    if args.seeds is None:
        if args.count is None:
            raise BatchConfigError("give --count N (with --start-seed S), or --seeds FILE")
        if args.start_seed < 0:
            raise BatchConfigError(f"--start-seed must be a non-negative integer, got "
                                   f"{args.start_seed}")
        return list(range(args.start_seed, args.start_seed + args.count))
    seeds = read_seeds(Path(args.seeds))
    return seeds[:args.count] if args.count is not None else seeds


def read_seeds(path: Path) -> list[int]:
    """The seeds of a seeds file (integers separated by spaces, commas or lines; # comments),
    each once, in order; BatchConfigError naming the first bad token."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise BatchConfigError(f"--seeds {str(path)!r} cannot be read: "
                               f"{getattr(e, 'strerror', None) or e}") from None
    seeds: dict[int, None] = {}
    for n, line in enumerate(text.splitlines(), 1):
        for token in re.split(r"[\s,]+", line.split("#", 1)[0].strip()):
            if not token:
                continue
            if not token.isdigit() or len(token) > 19:
                raise BatchConfigError(f"--seeds {str(path)!r} line {n}: {token[:40]!r} is not a "
                                       "non-negative integer seed")
            seeds[int(token)] = None
            if len(seeds) > MAX_SCENES:
                raise BatchConfigError(f"--seeds {str(path)!r} holds over {MAX_SCENES} seeds")
    if not seeds:
        raise BatchConfigError(f"--seeds {str(path)!r} holds no seeds")
    return list(seeds)


def parse_size(text: str) -> int:
    """`4G`, `1500M`, `512m`, `2048` (MiB) -> bytes; BatchConfigError if it does not parse."""
    m = re.fullmatch(r"\s*([0-9]+(?:\.[0-9]+)?)\s*([kmgtKMGT]?)(i?[bB])?\s*", text)
    if m is None or float(m[1]) <= 0:
        raise BatchConfigError(f"--max-memory-per-worker {text!r}: expected a size such as 4G "
                               "or 1500M")
    return int(float(m[1]) * _UNITS[m[2].lower()])


def run_dataset_stats(args: argparse.Namespace) -> int:
    """`indoorgen dataset-stats DIR`: print the dataset's statistics and plot them."""
    stats = dataset_stats(Path(args.dir))
    plot = Path(args.plot) if args.plot else Path(args.dir) / "stats.png"
    plot_stats(stats, plot)
    for line in stats_lines(stats):
        print(line)
    print(f"plot: {plot}")
    return 0
