"""Room names, room-count lists and minimum widths of the floorplan stage."""
from __future__ import annotations

import pytest

from indoorgen.errors import ConfigError, UnknownRoomTypeError
from indoorgen.floorplan.rooms import (
    MIN_CLOSET_WIDTH,
    MIN_WIDTH,
    min_width,
    parse_room_counts,
    planned_width,
    room_type_of,
)


def test_room_counts_parsing_and_errors():
    assert parse_room_counts("bedroom=2, bathroom=1") == {"bedroom": 2, "bathroom": 1}
    assert parse_room_counts("living=1,staircase=0") == {"living_room": 1, "staircase_room": 0}
    with pytest.raises(UnknownRoomTypeError, match="kitchn"):
        parse_room_counts("kitchn=1")
    with pytest.raises(ConfigError, match="TYPE=COUNT"):
        parse_room_counts("bedroom")
    with pytest.raises(ConfigError, match="whole number"):
        parse_room_counts("bedroom=two")
    with pytest.raises(ConfigError, match="between 0 and 12"):
        parse_room_counts("bedroom=13")
    with pytest.raises(ConfigError, match="at least one living room"):
        parse_room_counts({"living_room": 0})
    with pytest.raises(UnknownRoomTypeError, match="office"):  # single rooms only
        parse_room_counts("office=1")


def test_room_names_and_widths():
    assert room_type_of("staircase_room_2") == "staircase_room"
    assert min_width("closet") == MIN_CLOSET_WIDTH and min_width("bedroom") == MIN_WIDTH
    assert min_width("not_a_type") == MIN_WIDTH
    # generated plans make the main rooms wider (a bed and a walkway, not a 1.5 m strip)
    assert planned_width("bedroom") >= 2.5 and planned_width("living_room") >= 2.5
    assert planned_width("closet") == MIN_CLOSET_WIDTH and planned_width("garage") == min_width("garage")
