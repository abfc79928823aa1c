"""The 2D layout of a storey's walls and openings, shared by solidification and drawing.

Walls are centred on room boundaries: interior walls `interior` thick on the edges two rooms
share, exterior walls `exterior` thick on the storey outline. A room's *free* polygon is its
partition polygon minus the walls, i.e. the floor inside its wall faces. Each door, opening and
window is located on its wall by a frame: centre, unit direction along the wall, unit normal
and the wall's thickness there.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely
import shapely.geometry as sg
from shapely.geometry.polygon import orient

from indoorgen.errors import InvalidGeometryError
from indoorgen.model.floorplan import DoorSpec, Entrance, Storey, WindowSpec


@dataclass(frozen=True)
class WallThickness:
    """Thickness of interior walls (centred on edges two rooms share) and exterior walls
    (centred on the storey outline), m."""

    interior: float = 0.12
    exterior: float = 0.24


@dataclass
class WallFrame:
    """Where an opening sits: `center` on the wall's centre line, `u` along the wall, `n` across
    it (towards `toward`, the room it opens into or, for windows, out of the house), wall
    `thickness`."""

    center: np.ndarray
    u: np.ndarray
    n: np.ndarray
    thickness: float

    def rect(self, width: float, depth0: float, depth1: float) -> sg.Polygon:
        """The rectangle `width` along the wall, from depth0 to depth1 along n."""
        c, u, n = self.center, self.u, self.n
        h = width / 2
        return sg.Polygon([c - h * u + depth0 * n, c + h * u + depth0 * n,
                           c + h * u + depth1 * n, c - h * u + depth1 * n])


def wall_footprint(storey: Storey, t: WallThickness) -> sg.Polygon:
    """Every wall of the storey as one 2D region."""
    polys = [r.shape() for r in storey.rooms]
    outline = shapely.union_all(polys).buffer(0)
    ring = outline.exterior
    lines = shapely.union_all([p.exterior for p in polys])
    interior = lines.difference(ring.buffer(1e-6, join_style="mitre"))
    walls = [ring.buffer(t.exterior / 2, join_style="mitre", cap_style="flat")]
    if not interior.is_empty:
        walls.append(interior.buffer(t.interior / 2, cap_style="square", join_style="mitre"))
    return shapely.union_all(walls).buffer(0)


def outer_outline(storey: Storey, t: WallThickness) -> sg.Polygon:
    """The storey outline grown to the outer faces of its exterior walls."""
    outline = shapely.union_all([r.shape() for r in storey.rooms]).buffer(0)
    return outline.buffer(t.exterior / 2, join_style="mitre")


def free_polygon(room_poly: sg.Polygon, walls: sg.Polygon) -> sg.Polygon:
    """The floor of a room inside its wall faces (the largest piece if walls split it)."""
    free = room_poly.difference(walls)
    if isinstance(free, sg.MultiPolygon) or hasattr(free, "geoms"):
        parts = [g for g in getattr(free, "geoms", []) if isinstance(g, sg.Polygon)]
        if not parts:
            raise InvalidGeometryError("a room is entirely covered by walls")
        free = max(parts, key=lambda g: g.area)
    free = shapely.simplify(sg.Polygon(free.exterior), 1e-7)
    return orient(free, 1.0)


def room_region(room_poly: sg.Polygon, outline: sg.Polygon, t: WallThickness) -> sg.Polygon:
    """The room's polygon grown across the exterior wall to its outer face: its share of the
    storey's slab and walls."""
    grown = room_poly.buffer(t.exterior / 2, join_style="mitre")
    others = outline.difference(room_poly)
    region = grown.difference(others.buffer(-1e-7, join_style="mitre"))
    return region if not region.is_empty else room_poly


def _nearest_segment(lines, p: np.ndarray) -> tuple[np.ndarray, float] | None:
    """Unit direction of the segment of `lines` nearest to p, and the distance to it."""
    best = None
    for ln in getattr(lines, "geoms", [lines]):
        if not hasattr(ln, "coords") or ln.is_empty:
            continue
        pts = np.asarray(ln.coords)
        for a, b in zip(pts[:-1], pts[1:], strict=False):
            d = b - a
            L = float(np.hypot(*d))
            if L < 1e-9:
                continue
            s = float(np.clip(np.dot(p - a, d) / L**2, 0.0, 1.0))
            dist = float(np.hypot(*(a + s * d - p)))
            if best is None or dist < best[1]:
                best = (d / L, dist)
    return best


def door_frame(storey: Storey, door: DoorSpec, t: WallThickness) -> WallFrame:
    """The frame of a door or opening between its two rooms; `n` points into rooms[1]."""
    a, b = storey.room(door.rooms[0]).shape(), storey.room(door.rooms[1]).shape()
    c = np.asarray(door.center, float)
    shared = a.exterior.intersection(b.exterior.buffer(1e-6)).intersection(
        a.exterior.buffer(1e-6))
    seg = _nearest_segment(shared, c)
    if seg is None or seg[1] > 0.05:
        raise InvalidGeometryError(
            f"door {door.name!r} at {tuple(door.center)} is not on a wall shared by "
            f"{door.rooms[0]!r} and {door.rooms[1]!r}")
    u = seg[0]
    n = np.array([-u[1], u[0]])
    if not b.contains(sg.Point(c + 0.05 * n)):
        n = -n
    return WallFrame(c, u, n, t.interior)


def exterior_frame(storey: Storey, room: str, center, t: WallThickness, what: str) -> WallFrame:
    """The frame of a window or the front door in an exterior wall of `room`; `n` points out."""
    poly = storey.room(room).shape()
    outline = storey.contour()
    c = np.asarray(center, float)
    ext = poly.exterior.intersection(outline.exterior.buffer(1e-6))
    seg = _nearest_segment(ext, c)
    if seg is None or seg[1] > 0.05:
        raise InvalidGeometryError(f"{what} at {tuple(center)} is not on an exterior wall of "
                                   f"room {room!r}")
    u = seg[0]
    n = np.array([-u[1], u[0]])
    if poly.contains(sg.Point(c + 0.05 * n)):
        n = -n
    return WallFrame(c, u, n, t.exterior)


def window_frame(storey: Storey, w: WindowSpec, t: WallThickness) -> WallFrame:
    """The frame of window `w` in its room's exterior wall; `n` points out."""
    return exterior_frame(storey, w.room, w.center, t, f"window {w.name!r}")


def entrance_frame(storey: Storey, e: Entrance, t: WallThickness) -> WallFrame:
    """The frame of the front door in its room's exterior wall; `n` points out."""
    return exterior_frame(storey, e.room, e.center, t, "the entrance")
