"""The free-floor grid: rasterised rooms and door passages, obstacles clipped to the band,
stairs cut out, erosion and the floor an agent's body sweeps."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg
import trimesh

from indoorgen.model.floorplan import Floorplan, StairSpec, Storey
from indoorgen.quality.occupancy import (
    BAND,
    LONE_DOOR_DEPTH,
    Grid,
    band_outlines,
    cover,
    door_sites,
    erode,
    storey_occupancy,
)
from support.navscenes import BoxCache, box, rect_room, scene_of

CELL = 0.05


def _rect_mask(w: float, d: float) -> tuple[Grid, np.ndarray]:
    grid = Grid.covering((0.0, 0.0, w, d), CELL)
    return grid, grid.rasterise([sg.box(0, 0, w, d)])


def test_rasterised_rectangle_has_its_area():
    grid, mask = _rect_mask(4.0, 3.0)
    assert grid.area(mask) == pytest.approx(12.0, abs=1e-9)
    assert not mask[0].any() and not mask[:, 0].any()  # the margin stays empty


def test_erosion_leaves_the_centres_a_disc_fits():
    r = 0.25
    grid, free = _rect_mask(4.0, 3.0)
    centres = erode(free, r, CELL)
    assert grid.area(centres) == pytest.approx((4 - 2 * r) * (3 - 2 * r), abs=0.25)


def test_body_covers_all_but_the_corners():
    r = 0.25
    grid, free = _rect_mask(4.0, 3.0)
    swept = cover(erode(free, r, CELL), free, r, CELL)
    assert grid.area(swept) == pytest.approx(12.0 - (4 - math.pi) * r * r, abs=0.08)
    assert not (swept & ~free).any()
    assert not cover(np.zeros_like(free), free, r, CELL).any()


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


def _box_piece(lo: float, hi: float) -> trimesh.Trimesh:
    m = trimesh.creation.box((1.0, 0.5, hi - lo))
    m.apply_translation((0.0, 0.0, (lo + hi) / 2))
    return m


@pytest.mark.parametrize(("lo", "hi", "area"), [
    (0.0, 2.0, 0.5),     # spans the band
    (1.7, 2.5, 0.5),     # reaches into it from above (a high shelf)
    (0.0, 0.01, 0.0),    # a rug lies below it
    (1.9, 2.3, 0.0),     # a pendant lamp above it
])
def test_band_outlines_keep_what_a_walker_hits(lo, hi, area):
    polys = band_outlines([_box_piece(lo, hi)], np.eye(4), 0.0)
    assert sum(p.area for p in polys) == pytest.approx(area, abs=1e-6)


def test_band_clips_slanted_pieces():
    # a pyramid 3 m tall over a 2 x 2 base: its section at height z is 2 (3 - z) / 3 square
    apex = np.array([[0, 0, 3.0]])
    base = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], float)
    pyramid = trimesh.convex.convex_hull(np.vstack([base, apex]))
    for floor_z in (0.0, 2.0):  # the band's lower plane cuts its widest section
        side = 2 * (3.0 - floor_z - BAND[0]) / 3.0
        polys = band_outlines([pyramid], np.eye(4), floor_z)
        assert polys[0].area == pytest.approx(side * side, abs=1e-6)


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
