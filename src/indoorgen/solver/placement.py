"""Planes, degrees of freedom and pose resolution (Infinigen Indoors, appendix E.2).

An object's planar relations pin some of its surfaces to parent planes. From them follow its
degrees of freedom: a translation projection matrix onto the intersection of the planes'
tangent subspaces, and whether it may still turn about +Z. `solve_pose` snaps a guessed pose onto
all its planes at once (least squares, so the guess moves as little as possible).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import TypeAlias, cast

import numpy as np
import shapely
import shapely.affinity
import shapely.geometry as sg

from indoorgen.assets import Asset, Surface
from indoorgen.constraints.relations import CONTACT_GAP, CoPlanar, Relation, StableAgainst
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.tags import Subpart
from indoorgen.solver.state import Placement, State

#: the relations a placement holds: each pins a child surface to a parent plane
PlanarRelation: TypeAlias = StableAgainst | CoPlanar


def planar(relation: Relation) -> PlanarRelation:
    """A placement's relation as the planar relation it is (the bounds hand relations over
    untyped; only planar ones ever become placements)."""
    return cast(PlanarRelation, relation)


@dataclass(frozen=True)
class DoF:
    """Where an object may go: translations `projection @ x` and, if `rotates`, turns about Z."""

    projection: np.ndarray
    rotates: bool


def _angle_diff(a: float, b: float) -> float:
    return abs((a - b + math.pi) % (2 * math.pi) - math.pi)


def solve_pose(state: State, asset: Asset, placements: list[Placement],
               position: np.ndarray, yaw: float) -> tuple[np.ndarray, float, DoF] | None:
    """Snap (position, yaw) so every placement holds; None if the planes contradict."""
    fixed_yaw = None
    rows = []
    for p in placements:
        cs = asset.surface(p.child_surface)
        ps = state.surface_world(p.parent, p.parent_surface)
        want = ps.normal if isinstance(p.relation, CoPlanar) else -ps.normal
        nc = cs.normal
        if abs(nc[2]) > 0.99:
            if want[2] * nc[2] < 0.99:
                return None
            if ps.subpart == Subpart.Rail:  # hung from a rail: turned across it
                y = hung_yaw(ps)
                if fixed_yaw is not None and _angle_diff(fixed_yaw, y) > 1e-6:
                    return None
                fixed_yaw = y
        else:
            if abs(want[2]) > 0.01:
                return None
            y = math.atan2(want[1], want[0]) - math.atan2(nc[1], nc[0])
            if fixed_yaw is None:
                fixed_yaw = y
            elif _angle_diff(fixed_yaw, y) > 1e-6:
                return None
        gap = CONTACT_GAP if isinstance(p.relation, StableAgainst) else 0.0
        offset = planar(p.relation).margin + gap
        rows.append((ps.normal, float(np.dot(ps.origin, ps.normal)) + offset, cs.origin))
    if fixed_yaw is not None:
        yaw = math.atan2(math.sin(fixed_yaw), math.cos(fixed_yaw))
    r = yaw_matrix(yaw)
    if not rows:
        return np.asarray(position, float), yaw, DoF(np.eye(3), True)
    n = np.array([row[0] for row in rows])
    b = np.array([row[1] - float(np.dot(r @ row[2], row[0])) for row in rows])
    pinv = _pinv(n)
    t = np.asarray(position, float) + pinv @ (b - n @ position)
    if np.abs(n @ t - b).max() > 1e-6:
        return None
    proj = np.eye(3) - pinv @ n
    proj[np.abs(proj) < 1e-12] = 0.0
    return t, yaw, DoF(proj, fixed_yaw is None)


def hung_yaw(rail: Surface) -> float:
    """The yaw of a thing hung from `rail` (a `Rail` surface, world frame): its front along the
    rail, so a hanger's shoulders run across it, as clothes hang in a wardrobe."""
    return math.atan2(float(rail.u[1]), float(rail.u[0]))


def snap_object(state: State, name: str, position: np.ndarray,
                yaw: float) -> tuple[np.ndarray, float, DoF] | None:
    """`solve_pose` for object `name` of the state, with its own asset and placements."""
    ob = state.objects[name]
    return solve_pose(state, ob.asset, ob.placements, position, yaw)


def _pinv(n: np.ndarray) -> np.ndarray:
    """Pseudo-inverse of the (k, 3) plane-normal matrix: n^T (n n^T)^-1 when the normals are
    independent (the usual case: a floor, or a floor and one or two walls), which is a small
    solve instead of an SVD; the SVD only for dependent planes (two walls facing each other)."""
    gram = n @ n.T
    if len(n) <= 3 and abs(np.linalg.det(gram)) > 1e-9:
        return n.T @ np.linalg.inv(gram)
    return np.linalg.pinv(n)


def _in_parent_2d(parent: Surface, pts: np.ndarray) -> np.ndarray:
    d = pts - parent.origin
    return np.stack([d @ parent.u, d @ parent.v], axis=1)


def placements_hold(state: State, name: str, tol: float = 1e-4) -> bool:
    """Does each of the object's relations hold geometrically: no overhang where the relation
    forbids it, and the child's centroid over the parent surface otherwise?"""
    ob = state.objects[name]
    r = yaw_matrix(ob.yaw)
    for p in ob.placements:
        parent = state.surface_world(p.parent, p.parent_surface)
        child = ob.asset.surface(p.child_surface).transformed(r, ob.position)
        if isinstance(p.relation, CoPlanar):
            continue  # in the plane is all CoPlanar asks (solve_pose guarantees it)
        if isinstance(p.relation, StableAgainst) and p.relation.overhang:
            pts = child.corners()
        else:
            c = child.polygon.centroid
            pts = child.to_world(np.array([[c.x, c.y]]))
        if not _inside(parent.polygon, _in_parent_2d(parent, pts), tol):
            return False
    return True


def _inside(poly: sg.Polygon, xy: np.ndarray, tol: float) -> bool:
    """Are all points inside `poly` or within `tol` of it? (Corners suffice: a child surface is
    convex, and walls and collisions catch the rare notch of a non-convex room.)"""
    inside = shapely.contains_xy(poly, xy[:, 0], xy[:, 1])
    if inside.all():
        return True
    out = xy[~inside]
    return bool((shapely.distance(poly, shapely.points(out)) <= tol).all())


@functools.lru_cache(maxsize=4096)
def _shrunk(poly: sg.Polygon, margin: float) -> sg.Polygon:
    """`poly` shrunk by `margin`, or `poly` itself if nothing would be left. Cached: the same
    shelf or floor polygon is shrunk by the same object's margin over and over."""
    shrunk = poly.buffer(-margin)
    return shrunk if not shrunk.is_empty and shrunk.area > 1e-6 else poly


def sample_point(surface: Surface, rng: np.random.Generator, margin: float = 0.0) -> np.ndarray:
    """A uniform random point of a surface polygon (optionally shrunk by `margin`), in world."""
    poly = surface.polygon
    if margin > 0:
        poly = _shrunk(poly, round(float(margin), 4))
    x0, y0, x1, y1 = poly.bounds
    for _ in range(4):  # rejection sampling, 16 candidates at a time
        cand = rng.uniform([x0, y0], [x1, y1], size=(16, 2))
        inside = shapely.contains_xy(poly, cand[:, 0], cand[:, 1])
        if inside.any():
            q = cand[int(np.argmax(inside))]
            break
    else:
        c = poly.representative_point()
        q = np.array([c.x, c.y])
    return surface.to_world(q[None])[0]


#: free space kept around what is put on a surface (m): between things side by side, and
#: between a thing and the sides of the shelf or cupboard it stands in (touching placeholders
#: count as a collision)
SURFACE_GAP = 0.005


def surface_offsets(surface: Surface, offsets: np.ndarray) -> np.ndarray:
    """World XY offsets (N, 2) in the 2D coordinates of a horizontal `surface`."""
    return np.stack([offsets @ surface.u[:2], offsets @ surface.v[:2]], axis=1)


def free_region(surface: Surface, footprint: np.ndarray, taken: list[np.ndarray],
                gap: float = SURFACE_GAP) -> sg.Polygon | sg.MultiPolygon:
    """Where on a horizontal `surface` (its 2D coordinates) a point may go so that the
    `footprint` around it (2D offsets from the point, the surface's coordinates) lies wholly on
    the surface and clear of every outline in `taken` (the surface's coordinates), `gap` apart:
    the surface eroded by the footprint's box, less each taken outline grown by it (a Minkowski
    sum of convex hulls). Empty where the thing fits nowhere. Exact for a convex surface; on a
    notched one the pose check still catches an overhang."""
    x0, y0 = footprint.min(axis=0) - gap
    x1, y1 = footprint.max(axis=0) + gap
    box = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    region = _eroded(surface.polygon, box)
    if region.is_empty:
        return region
    if taken:
        # each outline grown by the box: the hull of its points less each corner, all at once
        points = np.concatenate([(o[:, None, :] - box[None, :, :]).reshape(-1, 2) for o in taken])
        owner = np.repeat(np.arange(len(taken)), [4 * len(o) for o in taken])
        grown = shapely.convex_hull(shapely.multipoints(points, indices=owner))
        region = region.difference(shapely.union_all(grown))
    return region


def _eroded(polygon: sg.Polygon, box: np.ndarray) -> sg.Polygon:
    """Where a point may go so that it and `box` (4 corner offsets from it) lie on `polygon`:
    the intersection of the polygon and the polygon moved back by each corner; worked out
    directly for an axis-aligned rectangle (most surfaces), where it is one."""
    minx, miny, maxx, maxy = polygon.bounds
    (x0, y0), (x1, y1) = box[0], box[2]
    if len(polygon.interiors) == 0 and len(polygon.exterior.coords) == 5 and \
            abs(polygon.area - (maxx - minx) * (maxy - miny)) <= 1e-12:
        # (the point itself on the surface too, where the box does not hold it)
        lo_x, lo_y = minx - min(x0, 0.0), miny - min(y0, 0.0)
        hi_x, hi_y = maxx - max(x1, 0.0), maxy - max(y1, 0.0)
        if lo_x >= hi_x or lo_y >= hi_y:
            return sg.Polygon()
        return sg.box(lo_x, lo_y, hi_x, hi_y)
    region = polygon
    for cx, cy in box:
        region = region.intersection(shapely.affinity.translate(polygon, -cx, -cy))
        if region.is_empty:
            break
    return region


def sample_region(region: sg.Polygon | sg.MultiPolygon, rng: np.random.Generator) -> np.ndarray | None:
    """A uniform random point of a non-empty 2D `region` (a point of it where rejection
    sampling misses a sliver); None if the region is empty."""
    if region.is_empty or region.area <= 0.0:
        return None
    x0, y0, x1, y1 = region.bounds
    for _ in range(4):  # rejection sampling, 16 candidates at a time
        cand = rng.uniform([x0, y0], [x1, y1], size=(16, 2))
        inside = shapely.contains_xy(region, cand[:, 0], cand[:, 1])
        if inside.any():
            return cand[int(np.argmax(inside))]
    c = region.representative_point()
    return np.array([c.x, c.y])


def headroom(state: State, parent: str, surface: str) -> float:
    """The free height over a level surface of object `parent` (m) under the parent's own solid
    pieces (the shelf above, a cupboard's top); infinite on a top. What is taller does not go
    there, wherever it stands on the surface."""
    ob = state.objects[parent]
    if ob.boxes is None:
        return math.inf
    s = ob.asset.surface(surface)
    corners = s.corners()
    lo, hi = corners.min(axis=0) + SURFACE_GAP, corners.max(axis=0) - SURFACE_GAP
    boxes = ob.boxes[:ob.n_solid]
    over = (boxes[:, 0, 0] < hi[0]) & (boxes[:, 1, 0] > lo[0]) & (boxes[:, 0, 1] < hi[1]) \
        & (boxes[:, 1, 1] > lo[1]) & (boxes[:, 0, 2] > s.origin[2] + SURFACE_GAP)
    return float(boxes[over, 0, 2].min() - s.origin[2]) if over.any() else math.inf
