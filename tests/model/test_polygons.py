"""Room outlines: validation, orientation, signed areas, the largest piece of a region."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.errors import InvalidGeometryError
from indoorgen.model.polygons import cross_2d, largest_polygon, signed_area, validate_polygon


def _rect(w: float, d: float) -> list[tuple[float, float]]:
    return [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]


def test_validate_reorients_clockwise_polygon():
    poly = validate_polygon(list(reversed(_rect(3, 2))))
    assert poly.exterior.is_ccw and poly.area == pytest.approx(6.0)


def test_validate_accepts_closed_ring_and_shapely_polygon():
    pts = _rect(3, 2)
    assert validate_polygon(pts + [pts[0]]).area == pytest.approx(6.0)
    assert validate_polygon(sg.Polygon(pts)).area == pytest.approx(6.0)


@pytest.mark.parametrize("pts, match", [
    ([(0, 0), (1, 0)], "at least 3"),
    ([], "at least 3"),
    ([(0, 0), (2, 0), (4, 0)], "zero area"),
    ([(0, 0), (2, 2), (2, 0), (0, 2)], "self-intersecting"),
    ([(0, 0), (0.6, 0), (0.6, 0.6), (0, 0.6)], "too small"),
    ([(0, 0), (4, 0), (4, 3), (3.8, 3), (0, 3)], "side 2"),
])
def test_invalid_polygons_raise(pts, match):
    with pytest.raises(InvalidGeometryError, match=match):
        validate_polygon(pts)


def test_validate_rejects_holes_and_non_points():
    with pytest.raises(InvalidGeometryError, match="holes"):
        validate_polygon(sg.box(0, 0, 5, 5).difference(sg.box(1, 1, 2, 2)))
    with pytest.raises(InvalidGeometryError, match="non-finite"):
        validate_polygon([(0, 0), (1, 0), (1, np.inf)])
    with pytest.raises(InvalidGeometryError, match="list of"):
        validate_polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0)])


def test_signed_area_and_cross():
    pts = np.asarray(_rect(3, 2), float)
    assert signed_area(pts) == pytest.approx(6.0)
    assert signed_area(pts[::-1]) == pytest.approx(-6.0)
    assert cross_2d((1.0, 0.0), (0.0, 1.0)) == 1.0
    assert cross_2d(np.array([0.0, 1.0]), np.array([1.0, 0.0])) == -1.0


def test_largest_polygon_keeps_the_biggest_piece():
    two = sg.box(0, 0, 1, 1).union(sg.box(2, 0, 5, 1))
    assert largest_polygon(two).area == pytest.approx(3.0)
    assert largest_polygon(sg.box(0, 0, 1, 1)).area == pytest.approx(1.0)
    assert largest_polygon(sg.LineString([(0, 0), (1, 1)])).is_empty
