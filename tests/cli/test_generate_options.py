"""The generate command's options as parsed and checked before any work."""
from __future__ import annotations

import pytest

from indoorgen.cli import build_parser
from indoorgen.cli.generate import check_options
from indoorgen.errors import ConfigError
from indoorgen.solver.workers import usable_cores


def options(*argv: str):
    """`indoorgen generate ARGV` checked: (formats, configuration)."""
    return check_options(build_parser().parse_args(["generate", *argv]))


def test_a_home_is_solved_on_every_usable_core_unless_told():
    assert options("--seed", "3")[1].workers == usable_cores() >= 1
    assert options("--seed", "3", "--workers", "1")[1].workers == 1


def test_workers_must_be_positive():
    with pytest.raises(ConfigError, match="--workers must be a positive integer, got 0"):
        options("--workers", "0")
