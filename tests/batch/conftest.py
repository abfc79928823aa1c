"""A small dataset made once for the batch tests: 6 hallways (fast preset, MJCF only) on 2 local
workers, with a program that raises inside generation for one seed."""
from __future__ import annotations

import pytest

from support.cli import run

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


@pytest.fixture(scope="session")
def program(tmp_path_factory):
    """`FILE.py:hallway`, the program of PROGRAM."""
    path = tmp_path_factory.mktemp("program") / "flaky.py"
    path.write_text(PROGRAM)
    return f"{path}:hallway"


@pytest.fixture(scope="session")
def local_batch(tmp_path_factory, program):
    """`indoorgen batch` of seeds 0-5 on 2 local workers: (its directory, the process)."""
    out = tmp_path_factory.mktemp("batch") / "data"
    r = run("batch", "--count", "6", "--workers", "2", "--out", str(out), *GENERATE,
            "--program", program)
    assert r.returncode == 0, r.stderr
    return out, r
