"""One room's solid architecture: door placement, and the meshes, surfaces and keep-out zones of
its floor, ceiling and walls (the polygon is checked by `model.polygons.validate_polygon`).

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

import manifold3d
import numpy as np
import shapely
import shapely.geometry as sg
import trimesh

from indoorgen.architecture.solids import extrude_outline, subtract, to_trimesh
from indoorgen.assets.protocol import Surface
from indoorgen.errors import InvalidGeometryError
from indoorgen.model.polygons import largest_polygon, signed_area, validate_polygon
from indoorgen.model.scene import Door, Room
from indoorgen.model.tags import Subpart

log = logging.getLogger(__name__)

#: Thickness of floor and ceiling slabs (m).
SLAB_THICKNESS = 0.1
#: Distance a door opening keeps from either end of its wall (m).
DOOR_CORNER_MARGIN = 0.2
#: Extra width of a door's clearance zone beyond the door leaf (m, total over both sides).
DOOR_ZONE_EXTRA_WIDTH = 0.2


# --------------------------------------------------------------------------------------------
# polygons


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
    if sg.Polygon(quad).is_valid and abs(signed_area(quad)) > 1e-9:
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
    return largest_polygon(rect.intersection(poly))


# --------------------------------------------------------------------------------------------
# surfaces


def floor_surface(poly: sg.Polygon) -> Surface:
    """Floor: plane z=0, normal +Z, u=+X so (u, v) coordinates are world (x, y)."""
    return Surface("floor", Subpart.Floor, np.zeros(3), np.array([0.0, 0.0, 1.0]),
                   np.array([1.0, 0.0, 0.0]), poly)


def ceiling_surface(poly: sg.Polygon, height: float) -> Surface:
    """Ceiling: plane z=height facing down (-Z), u=+X, hence v = -Y and (u, v) = (x, -y)."""
    pts = np.asarray(poly.exterior.coords, float)[:-1] * [1.0, -1.0]
    uv = shapely.geometry.polygon.orient(sg.Polygon(pts), sign=1.0)
    return Surface("ceiling", Subpart.Ceiling, np.array([0.0, 0.0, height]),
                   np.array([0.0, 0.0, -1.0]), np.array([1.0, 0.0, 0.0]), uv)


def wall_surfaces(room: Room) -> list[Surface]:
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
        return [to_trimesh(extrude_outline(np.asarray(z.exterior.coords)[:-1], 0.0, height))
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
    if signed_area(np.asarray(room.polygon, float)) < 0:
        raise InvalidGeometryError(
            f"room {room.name!r} polygon is clockwise; wall indices assume counter-clockwise "
            "order (reverse its points)")
    _, _, _, length = _edges(room)
    for door in room.doors:
        _check_door(room, door, length)
    outer = _outer_corners(room)
    grown = extrude_outline(outer, -SLAB_THICKNESS, 0.0)
    floor = to_trimesh(grown)
    ceiling = to_trimesh(extrude_outline(outer, room.height, room.height + SLAB_THICKNESS))
    walls = [_build_wall(room, i, outer) for i in range(len(length))]
    surfaces = [floor_surface(poly), ceiling_surface(poly, room.height), *wall_surfaces(room)]
    zones = [_door_zone(room, poly, d) for d in room.doors]
    return RoomGeometry(room, floor, ceiling, walls, surfaces, zones)


def _build_wall(room: Room, i: int, outer: np.ndarray) -> trimesh.Trimesh:
    """Wall i as a watertight mesh with the openings of its doors subtracted."""
    solid = extrude_outline(_wall_footprint(room, i, outer), 0.0, room.height)
    solid = subtract(solid, [_door_cutter(room, d) for d in room.doors if d.wall == i])
    if solid.status() != manifold3d.Error.NoError:
        raise InvalidGeometryError(f"room {room.name!r} wall {i}: boolean failed ({solid.status()})")
    return to_trimesh(solid)
