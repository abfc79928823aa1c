"""Every room type and what the project knows about it, in one table.

`ROOM_TYPES` maps a type's name (the string rooms carry in `Room.room_type`, and in a home the
prefix of a room's name ``<type>_<k>``) to its `RoomTypeSpec`: the size a single room of the
type gets when the user gives none, and for the types a floorplan places, their typical and
minimum areas (typical: Table 8 of Infinigen Indoors, a typical US household), where they must
or like to be (exterior, views, entrance), their windows, door width and colour in plan
drawings. `room_type` looks a name up, resolving aliases such as ``living`` or ``stairs``.

The constraint programs furnishing each type are one layer up, in `indoorgen.programs`.
"""
from __future__ import annotations

from dataclasses import dataclass

from indoorgen.errors import UnknownRoomTypeError

LIVING_ROOM = "living_room"
DINING_ROOM = "dining_room"
KITCHEN = "kitchen"
BEDROOM = "bedroom"
BATHROOM = "bathroom"
CLOSET = "closet"
HALLWAY = "hallway"
GARAGE = "garage"
BALCONY = "balcony"
UTILITY = "utility"
STAIRCASE_ROOM = "staircase_room"
OFFICE = "office"
WAREHOUSE = "warehouse"

#: A single room's width and depth ranges (m) and wall height (m) for a type without its own.
DEFAULT_WIDTH = (4.0, 6.0)
DEFAULT_DEPTH = (3.5, 5.0)
DEFAULT_HEIGHT = 2.7
#: Width (m) of an interior door into a room of a type without its own.
DEFAULT_DOOR_WIDTH = 0.9
#: Plan-drawing colour of a type without its own.
DEFAULT_COLOUR = "#dddddd"
#: Floors of the rooms that get wet (bathrooms, utility rooms): tile or stone, not wood or carpet.
WET_FLOORS = ("square_tile", "hex_tile", "herringbone_tile", "slate", "terrazzo")


@dataclass(frozen=True)
class Windows:
    """The windows a floorplan gives a room of one type: width range, height and sill height
    above the floor (m), and at most `max_count` of them."""

    min_width: float
    max_width: float
    height: float
    sill: float
    max_count: int = 1


@dataclass(frozen=True)
class RoomTypeSpec:
    """What the project knows about one room type (see the module docstring).

    `width`, `depth` and `height` are a single room's when the user gives no size (width and
    depth drawn uniformly from the ranges). The other fields concern floorplans, which place
    the type only if `in_floorplans`: `typical_area` and `min_area` (m^2, 0 for types
    floorplans never place), whether the type must touch the exterior (`exterior`), has its
    share of exterior walls and corners rewarded (`view`), counts as functional area
    (`functional`), should be square (`square`), may be narrower than other rooms
    (`narrow_ok`), can be the ground floor's entrance room (`entrance`); its `windows` (None:
    no windows), the `door_width` of a door leading into it, its `colour` in plan drawings, the
    `aliases` users may type for it and the `floors` it is laid with."""

    name: str
    width: tuple[float, float] = DEFAULT_WIDTH
    depth: tuple[float, float] = DEFAULT_DEPTH
    height: float = DEFAULT_HEIGHT
    in_floorplans: bool = False
    typical_area: float = 0.0
    min_area: float = 0.0
    exterior: bool = False
    view: bool = False
    functional: bool = False
    square: bool = False
    narrow_ok: bool = False
    entrance: bool = False
    windows: Windows | None = None
    door_width: float = DEFAULT_DOOR_WIDTH
    colour: str = DEFAULT_COLOUR
    aliases: tuple[str, ...] = ()
    #: the floor materials a room of the type is laid with (empty: any of the homes' floors)
    floors: tuple[str, ...] = ()


_SPECS = (
    RoomTypeSpec(LIVING_ROOM, (4.6, 6.4), (3.9, 5.4), in_floorplans=True, typical_area=25.0,
                 min_area=15.0, functional=True, square=True, entrance=True,
                 windows=Windows(1.2, 2.4, 1.5, 0.8, max_count=3), colour="#f4d6a0",
                 aliases=("living", "livingroom")),
    RoomTypeSpec(DINING_ROOM, (4.0, 5.4), (3.6, 4.8), in_floorplans=True, typical_area=20.0,
                 min_area=6.0, functional=True, square=True,
                 windows=Windows(1.0, 2.0, 1.4, 0.9, max_count=2), colour="#f2bf8c",
                 aliases=("dining", "diningroom")),
    RoomTypeSpec(KITCHEN, (3.2, 4.8), (2.8, 4.2), in_floorplans=True, typical_area=20.0,
                 min_area=8.0, functional=True, square=True,
                 windows=Windows(0.9, 1.6, 1.2, 1.05, max_count=2), colour="#e8a87c"),
    RoomTypeSpec(BEDROOM, (3.4, 4.6), (3.2, 4.2), in_floorplans=True, typical_area=20.0,
                 min_area=7.0, exterior=True, view=True, functional=True, square=True,
                 windows=Windows(1.0, 1.8, 1.4, 0.9, max_count=2), colour="#a8c8e8"),
    RoomTypeSpec(BATHROOM, (2.2, 3.2), (2.0, 2.8), in_floorplans=True, typical_area=7.0,
                 min_area=3.0, functional=True, square=True,
                 windows=Windows(0.5, 0.8, 0.6, 1.5), door_width=0.8, colour="#9fe0d8",
                 aliases=("bath",), floors=WET_FLOORS),
    RoomTypeSpec(CLOSET, (1.6, 2.4), (1.4, 2.2), in_floorplans=True, typical_area=3.0,
                 min_area=2.0, narrow_ok=True, door_width=0.8, colour="#c9b8e0"),
    RoomTypeSpec(HALLWAY, (1.4, 2.0), (3.0, 5.0), in_floorplans=True, typical_area=6.0,
                 min_area=2.25, entrance=True, windows=Windows(0.6, 1.0, 1.2, 0.9),
                 colour="#e6e6e6", aliases=("hall", "corridor")),
    RoomTypeSpec(GARAGE, (3.2, 6.0), (5.5, 6.5), in_floorplans=True, typical_area=35.0,
                 min_area=15.0, exterior=True, square=True,
                 windows=Windows(0.6, 1.2, 0.5, 1.7), door_width=0.9, colour="#b8b8b8",
                 floors=("concrete",)),
    RoomTypeSpec(BALCONY, (2.0, 4.0), (1.4, 2.2), in_floorplans=True, typical_area=6.0,
                 min_area=3.0, exterior=True, view=True, colour="#bfe3a8",
                 floors=("square_tile", "slate", "concrete", "pine_planks")),
    RoomTypeSpec(UTILITY, (2.0, 3.0), (1.8, 2.6), in_floorplans=True, typical_area=3.0,
                 min_area=2.0, square=True, windows=Windows(0.5, 0.8, 0.6, 1.4),
                 door_width=0.8, colour="#d8d0a8", floors=(*WET_FLOORS, "concrete")),
    RoomTypeSpec(STAIRCASE_ROOM, (2.4, 3.2), (3.0, 4.5), in_floorplans=True, typical_area=20.0,
                 min_area=10.0, windows=Windows(0.6, 1.0, 1.2, 1.0), colour="#e0c0d0",
                 aliases=("staircase", "stairs", "stair")),
    # single rooms only
    RoomTypeSpec(OFFICE, (3.0, 4.2), (2.8, 3.8)),
    RoomTypeSpec(WAREHOUSE, (14.0, 22.0), (10.0, 16.0), height=6.5, floors=("concrete",)),
)

#: Every room type by name: the floorplan types first, in the order error messages list them.
ROOM_TYPES: dict[str, RoomTypeSpec] = {s.name: s for s in _SPECS}
#: The types floorplans place, in table order.
FLOORPLAN_TYPES: tuple[str, ...] = tuple(s.name for s in _SPECS if s.in_floorplans)
_ALIASES: dict[str, str] = {a: s.name for s in _SPECS for a in s.aliases}
#: the floor (m^2) a furnished room needs for each door past BASE_DOORS: the door's swing and
#: the way to it, which furniture keeps clear (a 3 x 3 m bedroom with three doors and a window
#: held no bed); a type's `min_area` allows for BASE_DOORS doors
DOOR_AREA, BASE_DOORS = 3.0, 2


def least_area(type_name: str, doors: int) -> float:
    """The smallest area (m^2) a room of `type_name` with `doors` doors and open connections
    (the front door counts) may have: its type's `min_area`, and in a room one furnishes
    DOOR_AREA more for each door past BASE_DOORS."""
    spec = ROOM_TYPES[type_name]
    return spec.min_area + (DOOR_AREA * max(0, doors - BASE_DOORS) if spec.functional else 0.0)


def room_type(name: str, *, floorplan: bool = False) -> RoomTypeSpec:
    """The spec of room type `name`, normalised first (case, ``-`` and spaces as ``_``,
    aliases such as ``living`` or ``stairs`` resolved); with `floorplan`, only the types
    floorplans place are valid. UnknownRoomTypeError lists the valid types otherwise."""
    key = str(name).strip().lower().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key.replace("_", ""), key)
    valid = FLOORPLAN_TYPES if floorplan else tuple(ROOM_TYPES)
    if key not in valid:
        raise UnknownRoomTypeError(f"unknown room type {name!r}; valid: {', '.join(valid)}")
    return ROOM_TYPES[key]
