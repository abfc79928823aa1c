"""Planar outlines: point rings turned counter-clockwise (what a manifold3d `CrossSection` with the
Positive fill rule needs) and a cross-section read back as its largest shapely polygon (for a
surface that follows an extruded outline)."""
from __future__ import annotations

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg
from numpy.typing import ArrayLike


def ccw(pts: ArrayLike) -> np.ndarray:
    """The 2D ring `pts` (N, 2) as floats, reversed if it runs clockwise (signed area < 0)."""
    pts = np.asarray(pts, float)
    x, y = pts[:, 0], pts[:, 1]
    area = 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    return pts if area > 0 else pts[::-1]


def largest_polygon(cs: m3d.CrossSection) -> sg.Polygon:
    """The largest polygon of a cross-section, as shapely."""
    polys = [sg.Polygon(np.asarray(p, float)) for p in cs.to_polygons()]
    return max(polys, key=lambda q: q.area)
