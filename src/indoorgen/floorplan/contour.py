"""The outline of each storey.

The ground floor's area is the sum of its rooms' typical areas (Table 8) times a slack factor, or
the user's `--area`; its outline is a rectangle on the 0.5 m grid whose corners are randomly
bevelled with a rectangular notch, a round profile or a 45-degree chamfer. An upper storey is the
storey below, or that outline with rectangular strips or corners removed (never touching the
staircase): cut down towards its own rooms' typical areas where the storey below is much larger
than they need. A user may give the ground outline as a polygon instead.
"""
from __future__ import annotations

import math

import numpy as np
import shapely
import shapely.geometry as sg
from shapely.geometry.polygon import orient

from indoorgen.errors import InvalidGeometryError
from indoorgen.model.polygons import narrow_area, validate_polygon

#: The planning grid (m): every split, extrusion and rectangular bevel lies on it.
GRID = 0.5
#: Probability that a corner is bevelled, and the mix of bevel kinds.
BEVEL_PROB = 0.35
BEVEL_KINDS = ("notch", "round", "chamfer")
BEVEL_KIND_P = (0.5, 0.25, 0.25)
#: Shortest chord of a round bevel (m), so no wall along it is tiny.
MIN_CHORD = 0.7
#: The smallest outline a home can have (m^2).
MIN_CONTOUR_AREA = 12.0


def snap(x: float | np.ndarray, grid: float = GRID):
    """Round to the nearest multiple of `grid`."""
    return np.round(np.asarray(x, float) / grid) * grid


def _corner_cut(kind: str, corner: np.ndarray, dx: float, dy: float, a: float, b: float
                ) -> sg.Polygon:
    """The region removed at `corner` (a rectangle corner; the rectangle lies towards +dx, +dy
    from it): an a x b notch, a chamfer with legs a, or a round bevel of radius a."""
    ex, ey = np.array([dx, 0.0]), np.array([0.0, dy])
    if kind == "notch":
        pts = [corner, corner + a * ex, corner + a * ex + b * ey, corner + b * ey]
    elif kind == "chamfer":
        pts = [corner, corner + a * ex, corner + a * ey]
    else:
        n = max(2, int(math.floor(0.5 * math.pi * a / MIN_CHORD)))
        centre = corner + a * ex + a * ey
        t = np.linspace(0.0, 0.5 * math.pi, n + 1)
        # the arc runs from corner + a*ey (t=0) to corner + a*ex (t=pi/2), bulging to `corner`
        arc = centre[None] - a * (np.cos(t)[:, None] * ex + np.sin(t)[:, None] * ey)
        pts = [corner, *arc[::-1]]
    return sg.Polygon(pts).buffer(0)


def bevelled_rectangle(rng: np.random.Generator, width: float, depth: float) -> sg.Polygon:
    """The rectangle [0, width] x [0, depth] with each corner bevelled with probability
    BEVEL_PROB (notch, round or chamfer, sized on the grid up to a third of the shorter side)."""
    poly = sg.box(0.0, 0.0, width, depth)
    corners = [((0.0, 0.0), 1, 1), ((width, 0.0), -1, 1), ((width, depth), -1, -1),
               ((0.0, depth), 1, -1)]
    limit = min(width, depth) / 3.0
    for c, dx, dy in corners:
        if rng.random() >= BEVEL_PROB or limit < 1.0:
            continue
        kind = BEVEL_KINDS[int(rng.choice(3, p=BEVEL_KIND_P))]
        hi = min(limit, 3.0 if kind == "notch" else 2.5)
        a = float(snap(rng.uniform(1.0, hi)))
        b = float(snap(rng.uniform(1.0, hi)))
        a, b = max(a, 1.0), max(b, 1.0)
        poly = poly.difference(_corner_cut(kind, np.array(c), dx, dy, a, b))
    return _clean(poly)


def _clean(poly) -> sg.Polygon:
    """A CCW polygon without repeated or collinear vertices."""
    poly = shapely.simplify(poly, 1e-9)
    return orient(poly, sign=1.0)


def make_contour(rng: np.random.Generator, area: float, max_aspect: float = 1.6) -> sg.Polygon:
    """A bevelled rectangle of about `area` m^2 with sides on the grid and aspect ratio at most
    `max_aspect`, its lower-left corner at the origin."""
    if area < MIN_CONTOUR_AREA:
        raise InvalidGeometryError(f"--area {area:g} m^2 is too small; a home needs at least "
                                   f"{MIN_CONTOUR_AREA:g} m^2")
    aspect = float(rng.uniform(1.0, max_aspect))
    if rng.random() < 0.5:
        aspect = 1.0 / aspect
    best, target = None, area
    sub = np.random.default_rng(rng.integers(2**63))
    for _ in range(12):
        w = float(max(snap(math.sqrt(target * aspect)), 3.0))
        d = float(max(snap(target / w), 3.0))
        poly = bevelled_rectangle(np.random.default_rng(sub.integers(2**63)), w, d)
        err = abs(poly.area - area) / area
        if best is None or err < best[0]:
            best = (err, poly)
        if err < 0.06:
            break
        target *= area / poly.area
    assert best is not None  # the loop ran at least once
    return best[1]


#: An upper storey larger than this times its rooms' target area is cut down towards it (with
#: at most UPPER_CUTS cuts, each the best of UPPER_DRAWS random strips and corners); below it, an
#: upper storey is the storey below or that minus one strip or corner, as drawn. An upper storey
#: of a few bedrooms on a ground floor sized for a kitchen, dining room and garage otherwise
#: came out up to twice its rooms' typical area, in living rooms of 45-50 m^2.
UPPER_SLACK = 1.15
UPPER_CUTS = 2
UPPER_DRAWS = 16
#: The narrowest part an upper outline may keep (m): a room's width with its walls.
UPPER_MIN_WIDTH = 3.0


def upper_contour(rng: np.random.Generator, below: sg.Polygon, keep: sg.Polygon | None,
                  min_area: float, target: float | None = None,
                  p_same: float = 0.5) -> sg.Polygon:
    """The outline of the storey above `below`: `below` itself or less a grid-aligned strip or
    corner rectangle (cut towards `target` m^2 when `below` is over UPPER_SLACK times it), always
    containing `keep` (the staircase, plus a grid cell of margin) and at least `min_area` m^2."""

    # the staircase and a grid cell round it, where the storey below has that cell
    margin = keep.buffer(GRID, join_style="mitre").intersection(below) if keep is not None \
        else None

    def fits(poly) -> bool:
        return (isinstance(poly, sg.Polygon) and not poly.interiors and poly.area >= min_area
                and (keep is None or poly.buffer(1e-6).contains(margin))
                and narrow_area(poly, UPPER_MIN_WIDTH) < 0.01)

    if target is not None and below.area > UPPER_SLACK * target:
        poly = below
        for _ in range(UPPER_CUTS):
            cuts = [poly.difference(_random_cut(rng, poly, 0.6)) for _ in range(UPPER_DRAWS)]
            ok = [c for c in cuts if fits(c)]
            if not ok:
                break
            best = min(ok, key=lambda c: abs(c.area - target))
            if abs(best.area - target) >= abs(poly.area - target):
                break
            poly = best
            if poly.area <= UPPER_SLACK * target:
                break
        return _clean(poly)
    if rng.random() < p_same:
        return below
    for _ in range(8):
        poly = below.difference(_random_cut(rng, below, 0.4))
        if fits(poly):
            return _clean(poly)
    return below


def _random_cut(rng: np.random.Generator, poly: sg.Polygon, depth_share: float) -> sg.Polygon:
    """A grid-aligned rectangle to remove from `poly`: a strip along one side (or a corner of
    it) reaching in up to `depth_share` of the outline's extent (at least 1.5 m)."""
    x0, y0, x1, y1 = poly.bounds
    side = int(rng.integers(4))
    corner = rng.random() < 0.5
    ext = (x1 - x0) if side % 2 == 0 else (y1 - y0)
    depth = float(snap(rng.uniform(1.5, max(1.5, depth_share * ext))))
    along = (y1 - y0) if side % 2 == 0 else (x1 - x0)
    length = float(snap(rng.uniform(0.35, 0.65) * along)) if corner else along + 1.0
    if side == 0:    # from +x
        return sg.box(x1 - depth, y0 - 0.5, x1 + 0.5, y0 + length)
    if side == 1:    # from +y
        return sg.box(x1 - length, y1 - depth, x1 + 0.5, y1 + 0.5)
    if side == 2:    # from -x
        return sg.box(x0 - 0.5, y1 - length, x0 + depth, y1 + 0.5)
    return sg.box(x0 - 0.5, y0 - 0.5, x0 + length, y0 + depth)


def user_contour(points) -> sg.Polygon:
    """Validate a user's outline (list of [x, y]); raises InvalidGeometryError if it is
    self-intersecting, degenerate or smaller than MIN_CONTOUR_AREA."""
    try:
        poly = validate_polygon(points)
    except InvalidGeometryError as e:
        raise InvalidGeometryError(str(e).replace("room polygon", "contour")) from None
    if poly.area < MIN_CONTOUR_AREA:
        raise InvalidGeometryError(f"contour area {poly.area:.1f} m^2 is too small; a home needs "
                                   f"at least {MIN_CONTOUR_AREA:g} m^2")
    return _clean(poly)
