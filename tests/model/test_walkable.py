"""The walkable-floor raster: cells, erosion by the agent's radius, the floor its body sweeps,
obstacles clipped to the height band, door edges and access points."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg
import trimesh

from indoorgen.model.walkable import (
    BAND,
    Grid,
    access_points,
    approach_strip,
    band_outlines,
    cover,
    door_segment,
    erode,
    paint,
    patch_values,
)

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

def test_patches_paint_what_rasterise_gives():
    grid = Grid.covering((0.0, 0.0, 4.0, 3.0), CELL)
    geoms = [sg.box(0.5, 0.5, 1.5, 1.0), sg.Point(3.0, 2.0).buffer(0.4)]
    painted = paint(np.zeros(grid.shape, bool), grid.patches(geoms))
    assert (painted == grid.rasterise(geoms)).all()
    assert grid.area(painted) == pytest.approx(0.5 + math.pi * 0.16, abs=0.03)
    # a geometry off the grid gives no patch
    assert grid.patches([sg.box(50, 50, 51, 51)]) == []


def test_disc_holds_the_cells_within_its_radius():
    grid = Grid.covering((0.0, 0.0, 4.0, 3.0), CELL)
    patch = grid.disc(np.array([2.0, 1.5]), 0.1)
    assert patch is not None
    ids = np.arange(grid.shape[0] * grid.shape[1]).reshape(grid.shape)
    got = patch_values(ids, patch)
    i, j = np.divmod(got, grid.shape[1])
    x, y = grid.x0 + (j + 0.5) * CELL, grid.y0 + (i + 0.5) * CELL
    assert len(got) >= 9 and np.all(np.hypot(x - 2.0, y - 1.5) <= 0.1 + 1e-9)
    assert grid.disc(np.array([50.0, 50.0]), 0.1) is None


@pytest.mark.parametrize("clockwise", [False, True])
def test_door_segment_normal_points_into_the_room(clockwise):
    poly = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)
    wall = 0
    if clockwise:
        poly = poly[::-1].copy()  # edge 2 of the reversed outline is the bottom wall, x 4 -> 0
        wall = 2
    seg, inward = door_segment(poly, wall, 1.0, 0.8)
    assert inward == pytest.approx([0.0, 1.0])
    assert sorted(seg[:, 0]) == pytest.approx([0.6, 1.4] if not clockwise else [2.6, 3.4])
    strip = approach_strip(seg, inward, 0.5)
    assert strip.area == pytest.approx(0.4) and sg.box(0, 0, 4, 3).contains(strip)


def test_access_points_by_kind():
    bounds = np.array([[-0.5, -1.0, 0.0], [0.5, 1.0, 0.6]])
    assert access_points(["table"], bounds, 0.25) == []
    (front,) = access_points(["wardrobe"], bounds, 0.25)
    assert front == pytest.approx([0.5 + 0.35, 0.0])
    sides = access_points(["bed"], bounds, 0.25)
    assert np.array(sides) == pytest.approx(np.array([[0.0, 1.35], [0.0, -1.35]]))
    # a seat is reached anywhere along its front: beside a coffee table, at either end
    seat = access_points(["sofa"], bounds, 0.25)
    assert np.array(seat) == pytest.approx(np.array([[0.85, 0.0], [0.85, -1.0], [0.85, 1.0]]))
