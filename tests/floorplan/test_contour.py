"""Storey outlines: generated, bevelled, upper storeys, a user's own."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.errors import InvalidGeometryError
from indoorgen.floorplan.contour import (
    GRID,
    UPPER_MIN_WIDTH,
    UPPER_SLACK,
    bevelled_rectangle,
    make_contour,
    upper_contour,
    user_contour,
)
from indoorgen.model.polygons import narrow_area


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


def test_upper_contour_is_cut_towards_its_rooms_area():
    """A large ground floor under a few upstairs rooms: the upper outline is cut down towards
    its target (never under the least area, never off the stairs, nowhere under 3 m wide), even
    with the staircase against the outline's edge."""
    below = sg.box(0.0, 0.0, 14.0, 14.0)
    for keep in (sg.box(3.0, 3.0, 5.0, 9.0), sg.box(0.0, 8.0, 6.0, 10.0)):
        areas = []
        for seed in range(20):
            up = upper_contour(np.random.default_rng(seed), below, keep, 80.0, target=100.0)
            assert up.difference(below).area < 1e-9
            assert up.buffer(1e-6).contains(keep) and up.area >= 80.0
            assert narrow_area(up, UPPER_MIN_WIDTH) < 0.01
            areas.append(up.area)
        assert np.median(areas) <= UPPER_SLACK * 100.0, areas


def test_user_contour_errors():
    with pytest.raises(InvalidGeometryError, match="self-intersecting"):
        user_contour([[0, 0], [10, 10], [10, 0], [0, 10]])
    with pytest.raises(InvalidGeometryError, match="too small"):
        user_contour([[0, 0], [3, 0], [3, 3], [0, 3]])
    assert user_contour([[0, 0], [10, 0], [10, 8], [0, 8]]).area == pytest.approx(80.0)
