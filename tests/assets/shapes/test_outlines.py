"""Planar outlines: rings turned counter-clockwise, a cross-section's largest polygon."""
from __future__ import annotations

import manifold3d as m3d
import numpy as np
import pytest

from indoorgen.assets.shapes.outlines import ccw, largest_polygon

SQUARE = [(0, 0), (1, 0), (1, 1), (0, 1)]


def signed_area(pts) -> float:
    x, y = np.asarray(pts, float).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_ccw_turns_clockwise_rings_and_keeps_the_others():
    kept = ccw(SQUARE)
    assert kept.dtype == float and np.array_equal(kept, np.array(SQUARE, float))
    turned = ccw(SQUARE[::-1])
    assert signed_area(turned) > 0 and np.array_equal(turned, np.array(SQUARE, float))
    cs = m3d.CrossSection([ccw(SQUARE[::-1])], m3d.FillRule.Positive)
    assert cs.area() == pytest.approx(1.0)


def test_largest_polygon_of_a_cross_section():
    two = m3d.CrossSection([np.array(SQUARE, float), np.array(SQUARE, float) * 0.5 + 3.0])
    poly = largest_polygon(two)
    assert poly.area == pytest.approx(1.0) and poly.bounds == pytest.approx((0, 0, 1, 1))
