"""The room-type table: sane sizes, flags as the floorplan stage always had them, aliases, and
errors that name the valid types."""
from __future__ import annotations

import dataclasses

import pytest

from indoorgen.errors import UnknownRoomTypeError
from indoorgen.model.room_types import (
    DEFAULT_DEPTH,
    DEFAULT_HEIGHT,
    DEFAULT_WIDTH,
    FLOORPLAN_TYPES,
    ROOM_TYPES,
    RoomTypeSpec,
    Windows,
    room_type,
)
from indoorgen.programs import ROOM_PROGRAMS

#: The floorplan types in the order error messages have always listed them.
OLD_FLOORPLAN_TYPES = ("living_room", "dining_room", "kitchen", "bedroom", "bathroom", "closet",
                       "hallway", "garage", "balcony", "utility", "staircase_room")


def _with(flag: str) -> set[str]:
    return {n for n, s in ROOM_TYPES.items() if getattr(s, flag)}


def test_every_type_has_sane_sizes():
    for name, s in ROOM_TYPES.items():
        assert s.name == name
        for lo, hi in (s.width, s.depth):
            assert 1.0 <= lo < hi <= 30.0, name
        assert 2.2 <= s.height <= 12.0, name
        assert 0.7 <= s.door_width <= 1.0, name
        assert s.colour.startswith("#") and len(s.colour) == 7, name
        if s.in_floorplans:
            assert 0 < s.min_area <= s.typical_area, name
        else:
            assert s.min_area == s.typical_area == 0.0, name
        if s.windows is not None:
            w = s.windows
            assert 0 < w.min_width <= w.max_width and w.height > 0 and w.sill > 0, name
            assert w.max_count >= 1, name


def test_every_program_has_a_type_and_single_room_only_types_are_there():
    assert set(ROOM_PROGRAMS) == set(ROOM_TYPES)
    assert FLOORPLAN_TYPES == OLD_FLOORPLAN_TYPES
    assert set(ROOM_TYPES) - set(FLOORPLAN_TYPES) == {"office", "warehouse"}


def test_flags_are_the_floorplan_stage_constants():
    assert _with("exterior") == {"bedroom", "garage", "balcony"}
    assert _with("view") == {"bedroom", "balcony"}
    assert _with("functional") == {"kitchen", "bedroom", "living_room", "bathroom", "dining_room"}
    assert _with("square") == {"kitchen", "bedroom", "living_room", "dining_room", "bathroom",
                               "garage", "utility"}
    assert _with("narrow_ok") == {"closet"}
    assert _with("entrance") == {"living_room", "hallway"}
    assert {n for n, s in ROOM_TYPES.items() if s.windows is not None} == \
        set(FLOORPLAN_TYPES) - {"closet", "balcony"}
    assert {n: s.door_width for n, s in ROOM_TYPES.items() if s.door_width != 0.9} == \
        {"bathroom": 0.8, "closet": 0.8, "utility": 0.8}
    assert {n: s.windows.max_count for n, s in ROOM_TYPES.items()
            if s.windows is not None and s.windows.max_count > 1} == \
        {"living_room": 3, "dining_room": 2, "bedroom": 2, "kitchen": 2}
    assert ROOM_TYPES["kitchen"].windows == Windows(0.9, 1.6, 1.2, 1.05, max_count=2)
    assert ROOM_TYPES["hallway"].min_area == 2.25 and ROOM_TYPES["garage"].typical_area == 35.0


def test_single_room_defaults():
    assert ROOM_TYPES["warehouse"].height == 6.5
    assert {n for n, s in ROOM_TYPES.items() if s.height != DEFAULT_HEIGHT} == {"warehouse"}
    assert ROOM_TYPES["office"].width == (3.0, 4.2) and ROOM_TYPES["office"].depth == (2.8, 3.8)
    custom = RoomTypeSpec("my_room")  # a user's own type gets the defaults
    assert (custom.width, custom.depth, custom.height) == (DEFAULT_WIDTH, DEFAULT_DEPTH,
                                                           DEFAULT_HEIGHT)
    assert not custom.in_floorplans


def test_specs_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        ROOM_TYPES["bedroom"].min_area = 1.0  # type: ignore[misc]


@pytest.mark.parametrize("given, name", [
    ("bedroom", "bedroom"), ("Living Room", "living_room"), ("living", "living_room"),
    ("living-room", "living_room"), ("LIVINGROOM", "living_room"), ("dining", "dining_room"),
    ("stairs", "staircase_room"), ("stair", "staircase_room"), ("staircase", "staircase_room"),
    ("bath", "bathroom"), ("hall", "hallway"), ("corridor", "hallway"), (" office ", "office"),
    ("warehouse", "warehouse"),
])
def test_aliases_resolve(given, name):
    assert room_type(given).name == name


def test_unknown_types_raise_naming_the_valid_ones():
    with pytest.raises(UnknownRoomTypeError, match="ballroom") as e:
        room_type("ballroom")
    assert all(t in str(e.value) for t in ROOM_TYPES)
    with pytest.raises(UnknownRoomTypeError) as e:
        room_type("office", floorplan=True)
    assert str(e.value) == ("unknown room type 'office'; valid: " + ", ".join(OLD_FLOORPLAN_TYPES))
    assert room_type("Bath", floorplan=True).name == "bathroom"


def test_a_furnished_room_needs_more_floor_for_each_door_past_its_second():
    from indoorgen.model.room_types import BASE_DOORS, DOOR_AREA, ROOM_TYPES, least_area
    bedroom = ROOM_TYPES["bedroom"].min_area
    assert least_area("bedroom", 1) == least_area("bedroom", BASE_DOORS) == bedroom
    assert least_area("bedroom", BASE_DOORS + 2) == bedroom + 2 * DOOR_AREA
    # a closet or hallway is passed through, not furnished: its minimum stands
    assert least_area("hallway", 5) == ROOM_TYPES["hallway"].min_area
