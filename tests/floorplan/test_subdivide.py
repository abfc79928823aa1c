"""Mondrian subdivision and merging: the rooms of a storey partition its outline exactly."""
from __future__ import annotations

import numpy as np
import pytest
import shapely
import shapely.geometry as sg

from indoorgen.floorplan.contour import GRID, bevelled_rectangle
from indoorgen.floorplan.grid import make_grid, room_polygon
from indoorgen.floorplan.subdivide import merge, mondrian


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
