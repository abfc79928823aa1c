"""What the batch tests share: the cheapest generate options and a program failing for one seed."""
from __future__ import annotations

import argparse
import contextlib
import io
import json
from pathlib import Path

from threadpoolctl import threadpool_info

from indoorgen.cli import main

#: the options every batch test passes through to generate: the cheapest scenes there are
GENERATE = ["--room", "hallway", "--preset", "fast", "--formats", "mjcf"]
#: the seed whose program raises
BAD_SEED = 3

#: a program that furnishes a hallway as the built-in one does, but raises while seed BAD_SEED
#: is generated (it finds the seed in `pipeline.generate`'s frame: the program is not given it)
PROGRAM = f'''
import sys

from indoorgen.programs import get_program


def hallway(room):
    frame = sys._getframe()
    while frame is not None:
        if frame.f_code.co_name == "generate" and frame.f_locals.get("seed") == {BAD_SEED}:
            raise RuntimeError("seed {BAD_SEED} fails on purpose")
        frame = frame.f_back
    return get_program("hallway")(room)
'''


def batch(*args: str) -> tuple[int, str]:
    """`indoorgen batch ARGS` in this process (its scenes still run in processes of their own):
    the exit status and what it printed."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(["batch", *args])
    return code, out.getvalue()


def record_blas_threads(args: argparse.Namespace) -> int:
    """A batch entry that writes, instead of a scene, how many threads each native BLAS pool
    of its process has (`blas_threads.json`) and a report of no objects."""
    out = Path(args.out)
    out.mkdir(parents=True)
    pools = [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]
    (out / "blas_threads.json").write_text(json.dumps(pools))
    (out / "report.json").write_text(json.dumps({"objects": 0}))
    return 0
