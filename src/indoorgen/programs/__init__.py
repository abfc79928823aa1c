"""Built-in constraint programs, one function per room type: `program(room) -> Problem`."""
from __future__ import annotations

from typing import Callable

from indoorgen.constraints import Problem
from indoorgen.errors import UnknownRoomTypeError
from indoorgen.programs.bathroom import bathroom
from indoorgen.programs.bedroom import bedroom
from indoorgen.programs.dining_room import dining_room
from indoorgen.programs.kitchen import kitchen
from indoorgen.programs.living_room import living_room
from indoorgen.programs.office import office
from indoorgen.programs.small_rooms import balcony, closet, garage, hallway, staircase_room, utility
from indoorgen.programs.warehouse import warehouse

ROOM_PROGRAMS: dict[str, Callable[..., Problem]] = {
    "living_room": living_room,
    "dining_room": dining_room,
    "bedroom": bedroom,
    "kitchen": kitchen,
    "bathroom": bathroom,
    "closet": closet,
    "hallway": hallway,
    "utility": utility,
    "staircase_room": staircase_room,
    "garage": garage,
    "balcony": balcony,
    "office": office,
    "warehouse": warehouse,
}


def get_program(room_type: str) -> Callable[..., Problem]:
    """The program for `room_type`, or UnknownRoomTypeError listing the valid ones."""
    try:
        return ROOM_PROGRAMS[room_type]
    except KeyError:
        raise UnknownRoomTypeError(f"unknown room type {room_type!r}; valid: "
                                   + ", ".join(sorted(ROOM_PROGRAMS))) from None
