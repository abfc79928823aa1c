"""A storey's free floor: rasterised rooms and door passages, stairs cut out, objects in the
band."""
from __future__ import annotations

import pytest
import shapely.geometry as sg

from indoorgen.model.floorplan import Floorplan, StairSpec, Storey
from indoorgen.quality.occupancy import LONE_DOOR_DEPTH, door_sites, storey_occupancy
from support.navscenes import BoxCache, box, rect_room, scene_of

CELL = 0.05


def test_door_between_two_rooms_opens_a_passage_through_the_wall():
    a = rect_room("a", 0, 0, 4, 3, (("d", 1, 1.5, 0.9),))
    b = rect_room("b", 4.12, 0, 8, 3, (("d", 3, 1.5, 0.9),))
    site = door_sites([a, b])["d"]
    assert set(site.sides) == {"a", "b"}
    assert site.passage.bounds == pytest.approx((4.0, 1.05, 4.12, 1.95))
    # the approach strips lie inside each room
    assert sg.Polygon(a.polygon).contains(site.approach("a", 0.5).buffer(-1e-6))
    assert sg.Polygon(b.polygon).contains(site.approach("b", 0.5).buffer(-1e-6))


def test_lone_door_opens_outward():
    room = rect_room("r", 0, 0, 4, 3, (("entrance", 0, 2.0, 1.0),))
    site = door_sites([room])["entrance"]
    assert site.passage.bounds == pytest.approx((1.5, -LONE_DOOR_DEPTH, 2.5, 0.0))


def test_storey_occupancy_cuts_objects_of_its_storey_and_stairs():
    down = rect_room("down", 0, 0, 6, 5, (("entrance", 0, 3.0, 1.0),))
    up = rect_room("up", 0, 0, 6, 5, storey=1, elevation=3.0)
    objs = [box("sofa", "down", 4.0, 4.0, (1.0, 1.0, 0.8)),
            box("bed", "up", 1.0, 1.0, (1.0, 1.0, 0.5), z=3.0),
            box("lamp", "up", 1.0, 4.0, (0.4, 0.4, 0.3), z=5.0)]  # above the band upstairs
    sc, _ = scene_of([down, up], objs)
    fp = Floorplan([Storey(0, 0.0, 2.8), Storey(1, 3.0, 2.8)],
                   stairs=[StairSpec(0, 1, [(4.0, 0.5), (5.0, 0.5), (5.0, 3.5), (4.0, 3.5)])])
    cache = BoxCache()
    o0 = storey_occupancy(sc, cache, 0, floorplan=fp)
    o1 = storey_occupancy(sc, cache, 1, floorplan=fp)
    g = o0.grid
    passage = 1.0 * LONE_DOOR_DEPTH
    assert g.area(o0.floor) == pytest.approx(30.0 + passage - 3.0, abs=1e-6)
    assert g.area(o0.obstacles) == pytest.approx(1.0, abs=1e-6)
    assert g.area(o1.floor) == pytest.approx(30.0 - 3.0, abs=1e-6)
    assert g.area(o1.obstacles) == pytest.approx(1.0, abs=1e-6)
    assert g.area(o0.free) == pytest.approx(30.0 + passage - 4.0, abs=1e-6)
    assert set(o0.doors) == {"entrance"} and not o1.doors
