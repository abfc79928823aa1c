"""Built-in constraint programs: one per room type (`rooms/`), what furniture holds in any room
(`contents`), the relations they name (`relations`) and the floorplan objective (`floorplan`).
`get_program(room_type)` gives a room type's program with the contents (and what every room
asks of its rugs and its ceiling lights) added."""
from __future__ import annotations

from collections.abc import Callable

from indoorgen.constraints import ObjSet, Problem
from indoorgen.errors import UnknownRoomTypeError
from indoorgen.programs.contents import DEFAULT_FULLNESS, contents
from indoorgen.programs.relations import LIGHT_HEADROOM, OVER_TABLE_BOTTOM, lights_clear, rugs_centred
from indoorgen.programs.rooms.balcony import balcony
from indoorgen.programs.rooms.bathroom import bathroom
from indoorgen.programs.rooms.bedroom import bedroom
from indoorgen.programs.rooms.closet import closet
from indoorgen.programs.rooms.dining_room import dining_room
from indoorgen.programs.rooms.garage import garage
from indoorgen.programs.rooms.hallway import hallway
from indoorgen.programs.rooms.kitchen import kitchen
from indoorgen.programs.rooms.living_room import living_room
from indoorgen.programs.rooms.office import office
from indoorgen.programs.rooms.staircase_room import staircase_room
from indoorgen.programs.rooms.utility import utility
from indoorgen.programs.rooms.warehouse import warehouse

#: where a room's ceiling light may hang lower than LIGHT_HEADROOM: over the dining table (the
#: dining program hangs it there)
LIGHT_BOTTOM = {"dining_room": OVER_TABLE_BOTTOM}

#: A room program: the room (a set holding it) -> its constraint program.
RoomProgram = Callable[[ObjSet], Problem]

ROOM_PROGRAMS: dict[str, RoomProgram] = {
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


def get_program(room_type: str, fullness: float = DEFAULT_FULLNESS) -> RoomProgram:
    """The program for `room_type` (its furniture, plus what the furniture holds at
    `fullness`), or UnknownRoomTypeError listing the valid ones."""
    try:
        furnish = ROOM_PROGRAMS[room_type]
    except KeyError:
        raise UnknownRoomTypeError(f"unknown room type {room_type!r}; valid: "
                                   + ", ".join(sorted(ROOM_PROGRAMS))) from None

    def program(room: ObjSet) -> Problem:
        return (furnish(room) + contents(room, fullness, room_type) + rugs_centred(room)
                + lights_clear(room, LIGHT_BOTTOM.get(room_type, LIGHT_HEADROOM)))
    program.__name__ = furnish.__name__
    program.__doc__ = furnish.__doc__
    return program
