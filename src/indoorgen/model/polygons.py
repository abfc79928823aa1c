"""Plain 2D polygon facts shared by the floorplan solver and the architecture builders: the
check that an outline can make a room, signed areas and cross products, the largest piece of a
shapely result."""
from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any, TypeAlias

import numpy as np
import numpy.typing as npt
import shapely
import shapely.geometry as sg

from indoorgen.errors import InvalidGeometryError

#: Smallest floor area (m^2) and wall length (m) accepted for a room polygon.
MIN_AREA = 0.5
MIN_SIDE = 0.5

#: A room outline as given: (x, y) points (closing point optional) or a shapely Polygon.
PolygonLike: TypeAlias = "sg.Polygon | Iterable[Sequence[float]]"
Points: TypeAlias = npt.NDArray[np.float64]


def validate_polygon(polygon: PolygonLike) -> sg.Polygon:
    """Check that `polygon` (a sequence of (x, y) points or a shapely Polygon) can make a room and
    return it as a counter-clockwise shapely Polygon.

    Raises InvalidGeometryError naming the problem: fewer than 3 points, non-finite coordinates,
    collinear (zero-area) points, a self-intersecting outline, an area under 0.5 m^2, or a side
    shorter than 0.5 m.
    """
    pts = _polygon_points(polygon)
    if len(pts) < 3:
        raise InvalidGeometryError(
            f"room polygon has {len(pts)} distinct points; a room needs at least 3")
    if not np.all(np.isfinite(pts)):
        raise InvalidGeometryError("room polygon has non-finite (NaN or infinite) coordinates")
    if _collinear(pts):
        raise InvalidGeometryError("room polygon has zero area (its points are collinear)")
    area = abs(signed_area(pts))
    if not sg.LinearRing(pts).is_simple:
        raise InvalidGeometryError(
            "room polygon is self-intersecting; list its corners in order around the outline")
    if area < MIN_AREA:
        raise InvalidGeometryError(
            f"room polygon area {area:.3f} m^2 is too small; it must be at least {MIN_AREA} m^2")
    sides = np.linalg.norm(np.roll(pts, -1, axis=0) - pts, axis=1)
    if sides.min() < MIN_SIDE:
        i = int(np.argmin(sides))
        raise InvalidGeometryError(
            f"room polygon side {i} is {sides[i]:.3f} m long; every side must be at least "
            f"{MIN_SIDE} m")
    poly = sg.Polygon(pts)
    if not poly.is_valid:
        raise InvalidGeometryError(f"room polygon is invalid: {shapely.is_valid_reason(poly)}")
    return shapely.geometry.polygon.orient(poly, sign=1.0)


def _polygon_points(polygon: PolygonLike) -> Points:
    """The distinct outline points of `polygon` as an (N, 2) float array (closing point and
    consecutive duplicates removed)."""
    coords: Points
    if isinstance(polygon, sg.Polygon):
        if polygon.is_empty:
            return np.zeros((0, 2))
        if len(polygon.interiors):
            raise InvalidGeometryError("room polygon has holes; a room must be a simple polygon")
        coords = np.asarray(polygon.exterior.coords, float)[:, :2]
    else:
        try:
            coords = np.asarray(list(polygon), float)
        except (TypeError, ValueError) as e:
            raise InvalidGeometryError(f"room polygon is not a list of (x, y) points: {e}") from None
        if coords.size == 0:
            return np.zeros((0, 2))
        if coords.ndim != 2 or coords.shape[1] != 2:
            raise InvalidGeometryError(
                f"room polygon must be a list of (x, y) points, got shape {coords.shape}")
    if len(coords) == 0:
        return coords.reshape(0, 2)
    keep = np.ones(len(coords), bool)
    keep[1:] = np.any(np.abs(np.diff(coords, axis=0)) > 1e-12, axis=1)
    coords = coords[keep]
    if len(coords) > 1 and np.allclose(coords[0], coords[-1], atol=1e-12):
        coords = coords[:-1]
    return coords


def _collinear(pts: Points, tol: float = 1e-9) -> bool:
    """Whether all points lie on one line (the smallest singular value of the centred points
    vanishes)."""
    centred = pts - pts.mean(axis=0)
    return bool(np.linalg.svd(centred, compute_uv=False)[-1] <= tol * max(1.0, np.abs(pts).max()))


def signed_area(pts: Points) -> float:
    """Shoelace area of an (N, 2) outline; positive for counter-clockwise outlines."""
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def cross_2d(a: Sequence[float] | Points, b: Sequence[float] | Points) -> float:
    """z of the cross product of two 2D vectors."""
    return float(a[0] * b[1] - a[1] * b[0])


def largest_polygon(geom: Any) -> sg.Polygon:
    """`geom` itself if it is a Polygon, else its largest polygon piece (an empty Polygon if it
    has none): what is kept of a clipped region."""
    if isinstance(geom, sg.Polygon):
        return geom
    parts = [g for g in getattr(geom, "geoms", []) if isinstance(g, sg.Polygon)]
    return max(parts, key=lambda g: g.area) if parts else sg.Polygon()


def polygon_pieces(poly: sg.Polygon, width: float) -> int:
    """How many parts of `poly` a `width` square can move about in (its erosion by width / 2):
    more than one where a neck narrower than `width` joins them."""
    eroded = poly.buffer(-(width / 2 - 1e-4), join_style="mitre")
    return len(getattr(eroded, "geoms", [eroded])) if not eroded.is_empty else 0


def narrow_area(poly: sg.Polygon, width: float) -> float:
    """Area (m^2) of the parts of `poly` narrower than `width` (eroded by width / 2 and grown
    back: what the opening loses)."""
    r = width / 2 - 1e-4
    opened = poly.buffer(-r, join_style="mitre").buffer(r, join_style="mitre")
    return max(0.0, float(poly.area - opened.intersection(poly).area))
