"""One room's solid architecture: polygon validation, door placement, and the meshes, surfaces
and keep-out zones of its floor, ceiling and walls.

Conventions (DESIGN.md): metres, Z up, the room polygon counter-clockwise in the XY plane with the
floor's walking surface at z=0. Walls stand OUTSIDE the polygon, so the polygon is exactly the
free floor area and every wall's inner face lies on a polygon edge; this keeps the solver's
"against the wall" planes identical to the room outline. Solids are built with manifold3d, which
guarantees watertight results for extrusions and the boolean cuts of door openings.
"""
from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from typing import Iterable

import manifold3d
import numpy as np
import shapely
import shapely.geometry as sg
import trimesh

from indoorgen.assets.protocol import Surface
from indoorgen.errors import InvalidGeometryError
from indoorgen.model.scene import Door, Room
from indoorgen.model.tags import Subpart

log = logging.getLogger(__name__)

#: Smallest floor area (m^2) and wall length (m) accepted for a room polygon.
MIN_AREA = 0.5
MIN_SIDE = 0.5
#: Thickness of floor and ceiling slabs (m).
SLAB_THICKNESS = 0.1
#: Distance a door opening keeps from either end of its wall (m).
DOOR_CORNER_MARGIN = 0.2
#: Extra width of a door's clearance zone beyond the door leaf (m, total over both sides).
DOOR_ZONE_EXTRA_WIDTH = 0.2


# --------------------------------------------------------------------------------------------
# polygons


def validate_polygon(polygon) -> sg.Polygon:
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
    area = abs(_signed_area(pts))
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


def _polygon_points(polygon) -> np.ndarray:
    """The distinct outline points of `polygon` as an (N, 2) float array (closing point and
    consecutive duplicates removed)."""
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


def _collinear(pts: np.ndarray, tol: float = 1e-9) -> bool:
    """Whether all points lie on one line (the smallest singular value of the centred points
    vanishes)."""
    centred = pts - pts.mean(axis=0)
    return bool(np.linalg.svd(centred, compute_uv=False)[-1] <= tol * max(1.0, np.abs(pts).max()))


def _signed_area(pts: np.ndarray) -> float:
    """Shoelace area; positive for counter-clockwise outlines."""
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def rectangle(width: float, depth: float) -> list[tuple[float, float]]:
    """Counter-clockwise corners of the rectangle [0, width] x [0, depth]."""
    w, d = float(width), float(depth)
    return [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]


def l_shape(width: float, depth: float, cut_w: float, cut_d: float) -> list[tuple[float, float]]:
    """Counter-clockwise corners of [0, width] x [0, depth] with the cut_w x cut_d rectangle at
    its +x +y corner removed."""
    w, d, cw, cd = float(width), float(depth), float(cut_w), float(cut_d)
    if not (0 < cw < w and 0 < cd < d):
        raise InvalidGeometryError(
            f"l_shape cut {cw} x {cd} must be smaller than the room {w} x {d} and positive")
    return [(0.0, 0.0), (w, 0.0), (w, d - cd), (w - cw, d - cd), (w - cw, d), (0.0, d)]


def _edges(room: Room) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Per edge i (vertex i -> i+1) of the room's CCW polygon: start points, end points,
    unit directions and lengths."""
    p = np.asarray(room.polygon, float)
    q = np.roll(p, -1, axis=0)
    d = q - p
    length = np.linalg.norm(d, axis=1)
    return p, q, d / length[:, None], length


def _inward(direction: np.ndarray) -> np.ndarray:
    """Inward (left-hand) unit normals of CCW edges with unit `direction` (N, 2)."""
    return np.stack([-direction[..., 1], direction[..., 0]], axis=-1)


# --------------------------------------------------------------------------------------------
# doors


def place_door(room: Room, rng: np.random.Generator, width: float = 0.9) -> Door:
    """Choose a wall and an offset for a new door of `width` in `room` and return the Door.

    Only walls at least `width + 0.4` m long qualify, and the opening keeps 0.2 m from both
    corners. Positions overlapping existing doors of the room are avoided. The room is not
    modified: the caller appends the door to `room.doors` if it keeps it.
    """
    _, _, _, length = _edges(room)
    eligible = np.flatnonzero(length >= width + 2 * DOOR_CORNER_MARGIN - 1e-9)
    if eligible.size == 0:
        raise InvalidGeometryError(
            f"room {room.name!r} has no wall long enough for a {width} m door "
            f"(needs {width + 2 * DOOR_CORNER_MARGIN:.2f} m; longest is {length.max():.2f} m)")
    name = f"door_{len(room.doors)}"
    for _ in range(32):
        wall = int(rng.choice(eligible))
        lo = DOOR_CORNER_MARGIN + width / 2
        offset = float(rng.uniform(lo, length[wall] - lo))
        if not any(_doors_overlap(wall, offset, width, d) for d in room.doors):
            return Door(name, wall, offset, width)
    raise InvalidGeometryError(
        f"room {room.name!r} has no free wall space for another {width} m door")


def _doors_overlap(wall: int, offset: float, width: float, other: Door) -> bool:
    """Whether an opening centred `offset` along `wall` overlaps `other` (with corner margin)."""
    return (other.wall == wall and
            abs(other.offset - offset) < (width + other.width) / 2 + DOOR_CORNER_MARGIN)


def _check_door(room: Room, door: Door, length: np.ndarray) -> None:
    """Raise InvalidGeometryError if `door` does not fit within its wall."""
    if not 0 <= door.wall < len(length):
        raise InvalidGeometryError(
            f"door {door.name!r} of room {room.name!r} is on wall {door.wall}; "
            f"the room has walls 0..{len(length) - 1}")
    half = door.width / 2
    if door.offset - half < -1e-9 or door.offset + half > length[door.wall] + 1e-9:
        raise InvalidGeometryError(
            f"door {door.name!r} (width {door.width}, offset {door.offset:.3f}) does not fit on "
            f"wall {door.wall} of room {room.name!r}, which is {length[door.wall]:.3f} m long")
    if door.height > room.height + 1e-9:
        raise InvalidGeometryError(
            f"door {door.name!r} is {door.height} m tall but room {room.name!r} is only "
            f"{room.height} m high")


# --------------------------------------------------------------------------------------------
# solids


def _to_trimesh(m: manifold3d.Manifold) -> trimesh.Trimesh:
    """Convert a manifold3d solid to a trimesh (float64 vertices, so faces built on the room
    polygon stay exactly on it)."""
    mesh = m.to_mesh64() if hasattr(m, "to_mesh64") else m.to_mesh()
    return trimesh.Trimesh(np.asarray(mesh.vert_properties[:, :3], float),
                           np.asarray(mesh.tri_verts, np.int64), process=True)


def _extrude(outline: np.ndarray, z0: float, z1: float) -> manifold3d.Manifold:
    """A prism over the 2D `outline` (N, 2, any orientation) from z0 to z1."""
    pts = np.asarray(outline, float)
    if _signed_area(pts) < 0:
        pts = pts[::-1]
    cs = manifold3d.CrossSection([np.ascontiguousarray(pts)])
    return manifold3d.Manifold.extrude(cs, z1 - z0).translate([0.0, 0.0, z0])


def _outer_corners(room: Room) -> np.ndarray:
    """Mitred outer corners: vertex i of the polygon offset outward by the wall thickness, i.e.
    the intersection of the offset lines of edges i-1 and i (N, 2)."""
    p, _, d, _ = _edges(room)
    n_out = -_inward(d)
    t = room.wall_thickness
    d_prev, n_prev = np.roll(d, 1, axis=0), np.roll(n_out, 1, axis=0)
    # Point on offset line of edge i: p_i + t n_i + s d_i; on edge i-1: p_i + t n_{i-1} + r d_{i-1}.
    # Solve s d_i - r d_{i-1} = t (n_{i-1} - n_i) for s (2x2 per vertex).
    rhs = t * (n_prev - n_out)
    cross = d[:, 0] * (-d_prev[:, 1]) - d[:, 1] * (-d_prev[:, 0])
    s = (rhs[:, 0] * (-d_prev[:, 1]) - rhs[:, 1] * (-d_prev[:, 0])) / np.where(
        np.abs(cross) < 1e-12, 1.0, cross)
    s = np.where(np.abs(cross) < 1e-12, 0.0, s)  # collinear edges: no mitre needed
    return p + t * n_out + s[:, None] * d


def _wall_footprint(room: Room, i: int, outer: np.ndarray) -> np.ndarray:
    """Footprint quad of wall i: its inner edge on the polygon plus the mitred outer corners.
    Falls back to a plain rectangle overlapping its neighbours if the mitre would fold over
    (very sharp corners)."""
    p, q, d, _ = _edges(room)
    j = (i + 1) % len(p)
    quad = np.array([p[i], q[i], outer[j], outer[i]])
    if sg.Polygon(quad).is_valid and abs(_signed_area(quad)) > 1e-9:
        return quad
    n_out = -_inward(d[i])
    t = room.wall_thickness
    log.debug("room %s wall %d: mitre folds over, using an overlapping rectangle", room.name, i)
    return np.array([p[i] - t * d[i], q[i] + t * d[i],
                     q[i] + t * d[i] + t * n_out, p[i] - t * d[i] + t * n_out])


def _door_cutter(room: Room, door: Door) -> manifold3d.Manifold:
    """The box removed from a wall for `door`: door.width along the wall, three wall thicknesses
    across it, from just below the floor to door.height."""
    p, _, d, _ = _edges(room)
    centre = p[door.wall] + door.offset * d[door.wall]
    t = room.wall_thickness
    angle = math.degrees(math.atan2(d[door.wall, 1], d[door.wall, 0]))
    eps = 0.01
    box = manifold3d.Manifold.cube([door.width, 3 * t, door.height + eps], center=True)
    return (box.rotate([0.0, 0.0, angle])
            .translate([centre[0], centre[1], (door.height + eps) / 2 - eps]))


def _door_zone(room: Room, poly: sg.Polygon, door: Door) -> sg.Polygon:
    """Clearance rectangle in front of `door`, inside the room and clipped to its polygon."""
    p, _, d, _ = _edges(room)
    dw, nw = d[door.wall], _inward(d[door.wall])
    centre = p[door.wall] + door.offset * dw
    half = (door.width + DOOR_ZONE_EXTRA_WIDTH) / 2
    depth = door.clearance_depth
    rect = sg.Polygon([centre - half * dw, centre + half * dw,
                       centre + half * dw + depth * nw, centre - half * dw + depth * nw])
    zone = rect.intersection(poly)
    if isinstance(zone, sg.Polygon):
        return zone
    parts = [g for g in getattr(zone, "geoms", []) if isinstance(g, sg.Polygon)]
    return max(parts, key=lambda g: g.area) if parts else sg.Polygon()


# --------------------------------------------------------------------------------------------
# surfaces


def _floor_surface(poly: sg.Polygon) -> Surface:
    """Floor: plane z=0, normal +Z, u=+X so (u, v) coordinates are world (x, y)."""
    return Surface("floor", Subpart.Floor, np.zeros(3), np.array([0.0, 0.0, 1.0]),
                   np.array([1.0, 0.0, 0.0]), poly)


def _ceiling_surface(poly: sg.Polygon, height: float) -> Surface:
    """Ceiling: plane z=height facing down (-Z), u=+X, hence v = -Y and (u, v) = (x, -y)."""
    pts = np.asarray(poly.exterior.coords, float)[:-1] * [1.0, -1.0]
    uv = shapely.geometry.polygon.orient(sg.Polygon(pts), sign=1.0)
    return Surface("ceiling", Subpart.Ceiling, np.array([0.0, 0.0, height]),
                   np.array([0.0, 0.0, -1.0]), np.array([1.0, 0.0, 0.0]), uv)


def _wall_surfaces(room: Room) -> list[Surface]:
    """Inner face of each wall i: inward normal, u = -edge direction (so v = normal x u = +Z),
    origin at the edge's end vertex, polygon [0, L] x [0, height]."""
    _, q, d, length = _edges(room)
    n = _inward(d)
    out = []
    for i in range(len(q)):
        out.append(Surface(
            f"wall_{i}", Subpart.Wall, np.array([q[i, 0], q[i, 1], 0.0]),
            np.array([n[i, 0], n[i, 1], 0.0]), np.array([-d[i, 0], -d[i, 1], 0.0]),
            sg.box(0.0, 0.0, float(length[i]), room.height)))
    return out


# --------------------------------------------------------------------------------------------
# the assembled room


@dataclass
class RoomGeometry:
    """The solid architecture of one room, in world coordinates."""

    room: Room
    floor: trimesh.Trimesh
    ceiling: trimesh.Trimesh
    walls: list[trimesh.Trimesh]
    surfaces: list[Surface]
    door_zones: list[sg.Polygon] = field(default_factory=list)

    def collision_meshes(self) -> list[trimesh.Trimesh]:
        """Every solid the solver must not penetrate: walls, floor and ceiling slabs."""
        return [*self.walls, self.floor, self.ceiling]

    def door_zone_meshes(self, height: float = 2.0) -> list[trimesh.Trimesh]:
        """Door clearance zones extruded from z=0 to `height`: keep-out volumes for the solver."""
        return [_to_trimesh(_extrude(np.asarray(z.exterior.coords)[:-1], 0.0, height))
                for z in self.door_zones if not z.is_empty]

    def wall_surface(self, i: int) -> Surface:
        """Inner face surface of wall i (edge vertex i -> i+1)."""
        return self.surface(f"wall_{i}")

    def surface(self, name: str) -> Surface:
        """The surface called `name` ("floor", "ceiling" or "wall_<i>")."""
        for s in self.surfaces:
            if s.name == name:
                return s
        raise KeyError(f"room {self.room.name!r} has no surface {name!r}; "
                       f"have {[s.name for s in self.surfaces]}")


def build_room(room: Room) -> RoomGeometry:
    """Solidify `room`: floor and ceiling slabs, one watertight wall per edge with its door
    openings cut, the room's named surfaces and the clearance zone of every door.

    The polygon is validated (and reoriented counter-clockwise in a copy if necessary, so that
    wall indices refer to the CCW outline)."""
    poly = validate_polygon(room.polygon)
    if _signed_area(np.asarray(room.polygon, float)) < 0:
        raise InvalidGeometryError(
            f"room {room.name!r} polygon is clockwise; wall indices assume counter-clockwise "
            "order (reverse its points)")
    _, _, _, length = _edges(room)
    for door in room.doors:
        _check_door(room, door, length)
    outer = _outer_corners(room)
    grown = _extrude(outer, -SLAB_THICKNESS, 0.0)
    floor = _to_trimesh(grown)
    ceiling = _to_trimesh(_extrude(outer, room.height, room.height + SLAB_THICKNESS))
    walls = [_build_wall(room, i, outer) for i in range(len(length))]
    surfaces = [_floor_surface(poly), _ceiling_surface(poly, room.height), *_wall_surfaces(room)]
    zones = [_door_zone(room, poly, d) for d in room.doors]
    return RoomGeometry(room, floor, ceiling, walls, surfaces, zones)


def _build_wall(room: Room, i: int, outer: np.ndarray) -> trimesh.Trimesh:
    """Wall i as a watertight mesh with the openings of its doors subtracted."""
    solid = _extrude(_wall_footprint(room, i, outer), 0.0, room.height)
    cutters = [_door_cutter(room, d) for d in room.doors if d.wall == i]
    if cutters:
        solid = manifold3d.Manifold.batch_boolean([solid, *cutters], manifold3d.OpType.Subtract)
    if solid.status() != manifold3d.Error.NoError:
        raise InvalidGeometryError(f"room {room.name!r} wall {i}: boolean failed ({solid.status()})")
    return _to_trimesh(solid)


def build_rooms(rooms: Iterable[Room]) -> dict[str, RoomGeometry]:
    """`build_room` for each room, keyed by room name."""
    return {r.name: build_room(r) for r in rooms}
