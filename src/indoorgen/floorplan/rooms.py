"""What the floorplan stage knows about each room type: typical area (Table 8 of Infinigen
Indoors), minimum area, which types need the exterior, take windows, count as functional, should
be square, may be narrow; and the parsing of user room lists (``bedroom=2,bathroom=1``).

Room types are the string values of `tags.RoomType`; rooms are named ``<type>_<k>``.
"""
from __future__ import annotations

from indoorgen.errors import UnknownRoomTypeError
from indoorgen.model.tags import RoomType

LIVING = RoomType.LivingRoom.value
DINING = RoomType.DiningRoom.value
KITCHEN = RoomType.Kitchen.value
BEDROOM = RoomType.Bedroom.value
BATHROOM = RoomType.Bathroom.value
CLOSET = RoomType.Closet.value
HALLWAY = RoomType.Hallway.value
GARAGE = RoomType.Garage.value
BALCONY = RoomType.Balcony.value
UTILITY = RoomType.Utility.value
STAIRCASE = RoomType.StaircaseRoom.value

#: Every room type a floorplan may hold.
ROOM_TYPES: tuple[str, ...] = (LIVING, DINING, KITCHEN, BEDROOM, BATHROOM, CLOSET, HALLWAY,
                               GARAGE, BALCONY, UTILITY, STAIRCASE)

#: Typical floor area in m^2 (Infinigen Indoors, Table 8; a typical US household).
TYPICAL_AREA: dict[str, float] = {
    KITCHEN: 20.0, BEDROOM: 20.0, LIVING: 25.0, DINING: 20.0, CLOSET: 3.0, BATHROOM: 7.0,
    UTILITY: 3.0, GARAGE: 35.0, BALCONY: 6.0, HALLWAY: 6.0, STAIRCASE: 20.0,
}

#: Smallest usable floor area in m^2 per type (a hard limit for the solver and for the check
#: that a room list fits a given area).
MIN_AREA: dict[str, float] = {
    KITCHEN: 6.0, BEDROOM: 7.0, LIVING: 10.0, DINING: 6.0, CLOSET: 2.0, BATHROOM: 3.0,
    UTILITY: 2.0, GARAGE: 15.0, BALCONY: 3.0, HALLWAY: 2.25, STAIRCASE: 10.0,
}

#: Narrowest a room may be (m); closets may be down to MIN_CLOSET_WIDTH.
MIN_WIDTH = 1.2
MIN_CLOSET_WIDTH = 1.0

#: Types that must touch the exterior (D.2): bedrooms, garages and balconies.
EXTERIOR_TYPES = frozenset({BEDROOM, GARAGE, BALCONY})
#: Types whose share of the exterior walls and corners the objective rewards (D.3).
VIEW_TYPES = frozenset({BEDROOM, BALCONY})
#: Functional types (D.3 "functional room area").
FUNCTIONAL_TYPES = frozenset({KITCHEN, BEDROOM, LIVING, BATHROOM, DINING})
#: Types the aspect-ratio term asks to be square.
SQUARE_TYPES = frozenset({KITCHEN, BEDROOM, LIVING, DINING, BATHROOM, GARAGE, UTILITY})
#: Types allowed to be narrower than the minimum room width.
NARROW_OK_TYPES = frozenset({CLOSET})
#: Types that can be the house's entrance room on the ground floor.
ENTRANCE_TYPES = frozenset({LIVING, HALLWAY})
#: Pairs of types joined by an open connection (no wall) rather than a door, when chosen.
OPEN_PAIRS = frozenset({frozenset({LIVING, DINING}), frozenset({DINING, KITCHEN})})

#: Window (min width, max width, height, sill) in metres by room type; types not listed get no
#: windows.
WINDOWS: dict[str, tuple[float, float, float, float]] = {
    LIVING: (1.2, 2.4, 1.5, 0.8), DINING: (1.0, 2.0, 1.4, 0.9), KITCHEN: (0.9, 1.6, 1.2, 1.05),
    BEDROOM: (1.0, 1.8, 1.4, 0.9), BATHROOM: (0.5, 0.8, 0.6, 1.5), HALLWAY: (0.6, 1.0, 1.2, 0.9),
    STAIRCASE: (0.6, 1.0, 1.2, 1.0), UTILITY: (0.5, 0.8, 0.6, 1.4), GARAGE: (0.6, 1.2, 0.5, 1.7),
}

#: Interior door width by the type of room it leads into (m); the entrance door is wider.
DOOR_WIDTH: dict[str, float] = {BATHROOM: 0.8, CLOSET: 0.8, UTILITY: 0.8, GARAGE: 0.9}
DEFAULT_DOOR_WIDTH = 0.9
ENTRANCE_DOOR_WIDTH = 1.0
DOOR_HEIGHT = 2.05

#: Colours for plan drawings.
COLORS: dict[str, str] = {
    LIVING: "#f4d6a0", DINING: "#f2bf8c", KITCHEN: "#e8a87c", BEDROOM: "#a8c8e8",
    BATHROOM: "#9fe0d8", CLOSET: "#c9b8e0", HALLWAY: "#e6e6e6", GARAGE: "#b8b8b8",
    BALCONY: "#bfe3a8", UTILITY: "#d8d0a8", STAIRCASE: "#e0c0d0",
}

_ALIASES = {"living": LIVING, "livingroom": LIVING, "dining": DINING, "diningroom": DINING,
            "staircase": STAIRCASE, "stairs": STAIRCASE, "stair": STAIRCASE,
            "bath": BATHROOM, "hall": HALLWAY, "corridor": HALLWAY}


def room_type_of(name: str) -> str:
    """The type of a room called ``<type>_<k>``."""
    return name.rsplit("_", 1)[0]


def check_room_type(t: str) -> str:
    """`t` normalised (lower case, aliases such as ``living`` resolved), or
    UnknownRoomTypeError listing the valid types."""
    key = str(t).strip().lower().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key.replace("_", ""), _ALIASES.get(key, key))
    if key not in ROOM_TYPES:
        raise UnknownRoomTypeError(f"unknown room type {t!r}; valid: {', '.join(ROOM_TYPES)}")
    return key


def parse_room_counts(spec: str | dict | None) -> dict[str, int]:
    """Parse ``"bedroom=2,bathroom=1"`` (or a dict) into {type: count}.

    Raises UnknownRoomTypeError for an unknown type and ConfigError for a malformed entry or a
    negative count."""
    from indoorgen.errors import ConfigError
    if spec is None or spec == "":
        return {}
    if isinstance(spec, dict):
        items = list(spec.items())
    else:
        items = [tuple(p.split("=", 1)) if "=" in p else (p, None)
                 for p in str(spec).split(",") if p.strip()]
    out: dict[str, int] = {}
    for k, v in items:
        if v is None:
            raise ConfigError(f"--rooms entry {k!r} must be TYPE=COUNT, e.g. bedroom=2")
        t = check_room_type(k)
        try:
            n = int(v)
        except (TypeError, ValueError):
            raise ConfigError(f"--rooms count for {k!r} must be a whole number, "
                              f"got {v!r}") from None
        if n < 0 or n > 12:
            raise ConfigError(f"--rooms count for {k!r} is {n}; it must be between 0 and 12")
        out[t] = n
    if out.get(LIVING, 1) < 1:
        raise ConfigError("--rooms living_room=0: a home needs at least one living room")
    return out
