"""shapes/architectural: the rough opening a door or window needs, and the solids doors, windows
and stairs are built from (prisms, boxes, casings, frames, glazing grids, baluster spacing)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.assets.shapes.architectural import (
    MEMBER_OVERLAP,
    baluster_positions,
    casing,
    glazed_sash,
    grid_cells,
    muntins,
    opening_size,
    opening_surface,
    oriented_box,
    prism,
    ring,
)
from indoorgen.model.tags import Subpart

sizes = st.floats(0.05, 3.0)


def test_opening_size_adds_side_lites():
    base = {"width": 0.9, "height": 2.1}
    assert opening_size(base) == (0.9, 2.1)
    assert opening_size({**base, "sidelites": "both", "sidelite_width": 0.3}) == pytest.approx((1.5, 2.1))
    assert opening_size({**base, "sidelites": "left", "sidelite_width": 0.3}) == pytest.approx((1.2, 2.1))


@given(sizes, sizes, st.sampled_from(["none", "left", "right", "both"]), st.floats(0.2, 0.5))
def test_opening_size_is_the_leaf_plus_its_side_lites(w, h, side, lite):
    """Only the width grows, by one side lite per side that has one; without a width given the
    default side lite counts."""
    n = {"none": 0, "left": 1, "right": 1, "both": 2}[side]
    got = opening_size({"width": w, "height": h, "sidelites": side, "sidelite_width": lite})
    assert got == pytest.approx((w + n * lite, h))
    assert opening_size({"width": w, "height": h, "sidelites": side})[0] >= w


@given(st.floats(-1, 1), st.floats(0.1, 2), st.floats(0, 1), st.floats(0.1, 2), st.floats(-0.2, 0.2))
def test_opening_surface_is_the_rectangle_in_the_wall_plane(y0, w, z0, h, x):
    s = opening_surface(y0, y0 + w, z0, z0 + h, x)
    assert s.name == "opening" and s.subpart == Subpart.Wall
    assert np.allclose(s.normal, (1, 0, 0)) and np.allclose(s.u, (0, 1, 0))
    c = s.corners()
    assert np.allclose(c[:, 0], x)
    assert np.allclose(c[:, 1:].min(axis=0), (y0, z0)) and np.allclose(c[:, 1:].max(axis=0), (y0 + w, z0 + h))


@settings(max_examples=30)
@given(st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1)), min_size=3, max_size=8),
       st.floats(-1, 1), st.floats(0.01, 1), st.sampled_from(["x", "y", "z"]))
def test_prism_extrudes_the_polygon_along_its_axis(pts, lo, depth, axis):
    """Any simple polygon, either way round: the solid's volume is its area times the depth and
    its extent along the axis is lo..lo+depth."""
    poly = sg.MultiPoint(pts).convex_hull
    if not isinstance(poly, sg.Polygon) or poly.area < 1e-3:
        return
    ring_pts = np.asarray(poly.exterior.coords)[:-1]
    for order in (ring_pts, ring_pts[::-1]):
        solid = prism(order, lo, lo + depth, axis)
        assert solid.volume() == pytest.approx(poly.area * depth, rel=1e-6)
        k = "xyz".index(axis)
        bb = solid.bounding_box()
        assert bb[k] == pytest.approx(lo, abs=1e-9) and bb[k + 3] == pytest.approx(lo + depth, abs=1e-9)


@given(st.tuples(sizes, sizes, sizes), st.floats(-180, 180))
def test_oriented_box_keeps_its_size_when_turned(size, yaw):
    solid = oriented_box((0.1, 0.2, 0.3), size, yaw)
    assert solid.volume() == pytest.approx(size[0] * size[1] * size[2], rel=1e-6)
    bb = solid.bounding_box()
    assert (bb[2] + bb[5]) / 2 == pytest.approx(0.3) and bb[5] - bb[2] == pytest.approx(size[2])
    a = math.radians(yaw)
    half_x = (abs(math.cos(a)) * size[0] + abs(math.sin(a)) * size[1]) / 2
    assert (bb[3] - bb[0]) / 2 == pytest.approx(half_x, abs=1e-9)


@given(st.integers(1, 5), st.integers(1, 5), st.floats(0.5, 2), st.floats(0.5, 2), st.floats(0, 0.05))
def test_grid_cells_tile_the_rectangle_between_bars(cols, rows, w, h, bar):
    cells = grid_cells(0.0, w, 0.0, h, cols, rows, bar)
    assert len(cells) == cols * rows
    c = np.array(cells)
    assert c[:, 0].min() == pytest.approx(0.0) and c[:, 1].max() == pytest.approx(w)
    assert c[:, 2].min() == pytest.approx(0.0) and c[:, 3].max() == pytest.approx(h)
    widths, heights = c[:, 1] - c[:, 0], c[:, 3] - c[:, 2]
    assert np.allclose(widths, widths[0]) and np.allclose(heights, heights[0])  # equal lites
    assert widths.sum() / rows == pytest.approx(w - (cols - 1) * bar)  # bars between them
    assert np.allclose(c[:cols, 2], 0.0)  # listed bottom row first


@given(st.floats(0.05, 5), st.floats(0.05, 0.3), st.floats(0, 0.3))
def test_baluster_positions_are_spread_no_further_apart_than_the_spacing(length, spacing, margin):
    xs = baluster_positions(length, spacing, margin)
    assert len(xs) >= 1
    if length > 2 * margin:
        assert xs[0] == pytest.approx(margin) and xs[-1] == pytest.approx(length - margin)
        assert (np.diff(xs) <= spacing + 1e-9).all()
        if len(xs) > 2:
            assert np.allclose(np.diff(xs), np.diff(xs)[0])  # evenly
    else:
        assert xs == pytest.approx([length / 2])


@pytest.mark.parametrize("side", [1, -1])
def test_casing_frames_the_opening_on_one_face(side):
    """Two legs whose inner edges are the opening's sides and a head above it, standing off the
    wall face on the given side and sunk MEMBER_OVERLAP into it."""
    legs_and_head = casing(side * 0.1, side, -0.4, 0.4, 0.0, 2.0, 0.07, 0.02, detail=True)
    assert len(legs_and_head) == 3
    bbs = np.array([s.bounding_box() for s in legs_and_head])
    left, right, head = bbs
    assert left[4] == pytest.approx(-0.4) and right[1] == pytest.approx(0.4)
    assert head[2] == pytest.approx(2.0) and head[5] == pytest.approx(2.07)
    outer = bbs[:, 3].max() if side > 0 else -bbs[:, 0].min()
    inner = bbs[:, 0].min() if side > 0 else -bbs[:, 3].max()
    assert outer == pytest.approx(0.12) and inner == pytest.approx(0.1 - MEMBER_OVERLAP)


def test_ring_is_a_frame_of_members_around_a_hole():
    frame = ring(0.0, 1.0, 0.0, 2.0, 0.0, 0.05, 0.1, border_bottom=0.2)
    assert frame.volume() == pytest.approx((1.0 * 2.0 - 0.8 * 1.7) * 0.05, rel=1e-6)


@pytest.mark.parametrize("cols,rows", [(1, 1), (2, 1), (3, 2)])
def test_glazed_sash_divides_its_pane_into_lites(cols, rows):
    """A frame, a glass pane and (cols - 1) + (rows - 1) glazing bars; without detail one box."""
    parts = glazed_sash(0.0, 0.05, 0.0, 1.0, 0.0, 1.2, 0.06, cols, rows, "sash")
    assert [q.slot for q in parts].count("glass") == 1
    assert len(parts) == 2 + (cols - 1) + (rows - 1)
    assert len(muntins(0.0, 1.0, 0.0, 1.2, 0.0, 0.02, cols, rows)) == (cols - 1) + (rows - 1)
    (block,) = glazed_sash(0.0, 0.05, 0.0, 1.0, 0.0, 1.2, 0.06, cols, rows, "sash", detail=False)
    assert block.solid.volume() == pytest.approx(0.05 * 1.0 * 1.2)
