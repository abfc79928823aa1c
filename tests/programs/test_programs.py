"""The program registry agrees with the room-type table, and unknown types fail helpfully."""
from __future__ import annotations

import pytest

from indoorgen.constraints import Problem, scene
from indoorgen.errors import UnknownRoomTypeError
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.tags import Semantics
from indoorgen.programs import ROOM_PROGRAMS, get_program


def test_every_room_type_has_a_program_and_every_program_a_room_type():
    assert set(ROOM_PROGRAMS) == set(ROOM_TYPES)


@pytest.mark.parametrize("room_type", sorted(ROOM_TYPES))
def test_get_program_returns_a_program_building_a_problem(room_type):
    problem = get_program(room_type)(scene()[Semantics.Room].named(f"{room_type}_0"))
    assert isinstance(problem, Problem)
    assert problem.constraints, f"{room_type} asks for nothing"


def test_unknown_room_type_names_the_valid_ones():
    with pytest.raises(UnknownRoomTypeError, match="ballroom.*valid: .*bedroom"):
        get_program("ballroom")
