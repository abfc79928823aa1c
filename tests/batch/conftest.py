"""A small dataset made once for the batch tests: 6 hallways (fast preset, MJCF only) on 2 local
workers, with a program that raises inside generation for one seed."""
from __future__ import annotations

import pytest

from support.batch import GENERATE, PROGRAM, batch


@pytest.fixture(scope="session")
def program(tmp_path_factory):
    """`FILE.py:hallway`, the program of PROGRAM."""
    path = tmp_path_factory.mktemp("program") / "flaky.py"
    path.write_text(PROGRAM)
    return f"{path}:hallway"


@pytest.fixture(scope="session")
def local_batch(tmp_path_factory, program):
    """`indoorgen batch` of seeds 0-5 on 2 local workers: (its directory, what it printed)."""
    out = tmp_path_factory.mktemp("batch") / "data"
    code, printed = batch("--count", "6", "--workers", "2", "--out", str(out), *GENERATE,
                          "--program", program)
    assert code == 0
    return out, printed
