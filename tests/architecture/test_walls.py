"""The 2D wall layout of a storey (indoorgen.architecture.walls)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.architecture.walls import (
    WallThickness,
    door_frame,
    entrance_frame,
    free_polygon,
    outer_outline,
    room_region,
    wall_footprint,
    window_frame,
)
from indoorgen.errors import InvalidGeometryError
from indoorgen.model.floorplan import DoorSpec
from indoorgen.model.floorplan_io import from_json
from support.plans import apartment

T = WallThickness()


@pytest.fixture(scope="module")
def storey():
    return from_json(apartment()).storeys[0]


def test_walls_are_centred_on_room_edges(storey):
    walls = wall_footprint(storey, T)
    outline = storey.contour()
    # exterior walls straddle the outline, interior ones the shared edges
    assert walls.contains(sg.Point(0.0, 2.0)) and walls.contains(sg.Point(6.0, 4.0))
    assert not walls.contains(sg.Point(3.0, 2.5))
    assert outer_outline(storey, T).area == pytest.approx(
        outline.buffer(T.exterior / 2, join_style="mitre").area)


def test_free_polygon_is_the_floor_inside_the_wall_faces(storey):
    walls = wall_footprint(storey, T)
    room = storey.room("kitchen_0").shape()
    free = free_polygon(room, walls)
    assert free.exterior.is_ccw and room.contains(free)
    # kitchen_0 is 4 x 5 m: exterior walls on three sides, an interior one on the fourth
    assert free.area == pytest.approx((4 - T.exterior / 2 - T.interior / 2) *
                                      (5 - T.exterior / 2 - T.interior / 2))
    region = room_region(room, storey.contour(), T)
    assert region.contains(room) and region.area > room.area


def test_frames_point_into_the_second_room_or_out_of_the_house(storey):
    d = storey.doors[0]                      # living_room_0 -> bedroom_0, on y = 5
    f = door_frame(storey, d, T)
    assert np.allclose(f.n, [0, 1]) and f.thickness == T.interior
    w = window_frame(storey, storey.windows[0], T)  # living room, on y = 0
    assert np.allclose(w.n, [0, -1]) and w.thickness == T.exterior
    from_json_plan = from_json(apartment())
    e = entrance_frame(storey, from_json_plan.entrance, T)  # on x = 0
    assert np.allclose(e.n, [-1, 0])
    rect = f.rect(d.width, 0.0, 1.0)
    assert rect.area == pytest.approx(d.width)


def test_a_door_off_its_wall_is_named(storey):
    bad = DoorSpec("stray", ("living_room_0", "bedroom_0"), (2.5, 3.0), 0.9, 2.05)
    with pytest.raises(InvalidGeometryError, match="stray"):
        door_frame(storey, bad, T)
