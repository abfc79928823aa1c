"""Contours and the planning grid: outlines, traced room polygons, wall runs, openings."""
from __future__ import annotations

import numpy as np
import pytest
import shapely
import shapely.geometry as sg
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.errors import InvalidGeometryError
from indoorgen.floorplan.contour import GRID, bevelled_rectangle, make_contour, upper_contour, user_contour
from indoorgen.floorplan.grid import make_grid, opening, room_polygon, runs, trace
from indoorgen.floorplan.subdivide import merge, mondrian


@pytest.mark.parametrize("area", [40.0, 90.0, 160.0])
def test_contour_area_grid_and_validity(area):
    for seed in range(8):
        c = make_contour(np.random.default_rng(seed), area)
        assert c.is_valid and not c.interiors and c.exterior.is_ccw
        assert abs(c.area - area) / area < 0.15
        x0, y0, x1, y1 = c.bounds
        assert (x0, y0) == (0.0, 0.0)
        assert x1 % GRID == 0 and y1 % GRID == 0


def test_bevels_cut_corners():
    kinds = set()
    for seed in range(40):
        p = bevelled_rectangle(np.random.default_rng(seed), 12.0, 9.0)
        assert p.is_valid and p.area <= 108.0 + 1e-9
        n = len(p.exterior.coords) - 1
        kinds.add("plain" if n == 4 else "bevelled")
    assert kinds == {"plain", "bevelled"}


def test_upper_contour_is_a_subset_keeping_the_stairs():
    below = make_contour(np.random.default_rng(1), 120.0)
    keep = sg.box(3.0, 3.0, 5.0, 8.0)
    for seed in range(20):
        up = upper_contour(np.random.default_rng(seed), below, keep, 50.0, p_same=0.0)
        assert up.difference(below).area < 1e-9
        assert up.contains(keep) and up.area >= 50.0


def test_user_contour_errors():
    with pytest.raises(InvalidGeometryError, match="self-intersecting"):
        user_contour([[0, 0], [10, 10], [10, 0], [0, 10]])
    with pytest.raises(InvalidGeometryError, match="too small"):
        user_contour([[0, 0], [3, 0], [3, 3], [0, 3]])
    assert user_contour([[0, 0], [10, 0], [10, 8], [0, 8]]).area == pytest.approx(80.0)


def _union(mask):
    ys, xs = np.nonzero(mask)
    return shapely.union_all([sg.box(x, y, x + 1, y + 1) for x, y in zip(xs, ys)])


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 6), st.integers(0, 6), st.integers(1, 4),
                          st.integers(1, 4)), min_size=1, max_size=4))
def test_trace_matches_shapely(rects):
    m = np.zeros((10, 10), bool)
    for y, x, h, w in rects:
        m[y:y + h, x:x + w] = True
    xy = trace(m)
    u = _union(m)
    simple = isinstance(u, sg.Polygon) and not u.interiors and u.is_valid
    if xy is None:
        # only rejected when not one simple polygon (or touching itself at a corner)
        assert not simple or len(shapely.simplify(u, 0).exterior.coords) - 1 != 0
        return
    p = sg.Polygon(xy)
    assert simple and p.is_valid and p.exterior.is_ccw
    assert p.area == pytest.approx(u.area)
    assert len(xy) == len(shapely.simplify(u, 0).exterior.coords) - 1


def test_rooms_partition_a_bevelled_outline_exactly():
    c = bevelled_rectangle(np.random.default_rng(3), 11.0, 8.5).difference(
        sg.Point(11, 8.5).buffer(2.0))
    c = shapely.geometry.polygon.orient(c, 1.0)
    g = make_grid(c)
    assert g.frac.sum() * GRID ** 2 == pytest.approx(c.area)
    assert g.ext_len.sum() == pytest.approx(c.length)
    labels = merge(np.random.default_rng(0), mondrian(np.random.default_rng(0), g, 9), 6)
    polys = [room_polygon(g, labels == i) for i in range(labels.max() + 1)]
    assert all(p is not None for p in polys)
    assert sum(p.area for p in polys) == pytest.approx(c.area)
    assert shapely.union_all(polys).symmetric_difference(c).area < 1e-6


def test_runs_and_opening():
    lab = np.full((6, 8), -1)
    lab[1:5, 1:4] = 0
    lab[1:5, 4:7] = 1
    full = lab >= 0
    rs = runs(lab, full)
    shared = [r for r in rs if {r.left, r.right} == {0, 1}]
    assert len(shared) == 1 and shared[0].length == 4 and shared[0].axis == 1
    m = np.zeros((7, 7), bool)
    m[1:6, 1:4] = True     # 3 wide
    m[3:5, 4:7] = True     # a 2-wide arm
    o = opening(m, 3)
    assert o[1:6, 1:4].all() and not o[3:5, 4:7].any()
