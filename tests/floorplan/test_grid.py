"""The planning grid: traced room polygons, wall runs, openings."""
from __future__ import annotations

import numpy as np
import pytest
import shapely
import shapely.geometry as sg
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.floorplan.grid import opening, runs, trace


def _union(mask):
    ys, xs = np.nonzero(mask)
    return shapely.union_all([sg.box(x, y, x + 1, y + 1) for x, y in zip(xs, ys, strict=False)])


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
