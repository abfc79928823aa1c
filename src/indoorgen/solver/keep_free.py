"""Space that must stay free, as convex solids the solver collides: each moving part's sweep to
its open limit, a toilet's side and front clearances, the fronts of storage and appliances, and
the zone before each window; and the clearances the quality report measures them against.

An object's *keep-free* pieces (sweeps, use zones) travel with it like its own solid pieces, but
they only meet walls and other objects' solid pieces: two cabinets may open into the same aisle,
and what rests on or in an object may sit where its drawers slide. A window's zone is a fixed
piece that only keeps out what the report's window rule names: tall furniture and anything hung
on the wall.
"""
from __future__ import annotations

import fcl
import numpy as np
import shapely.geometry as sg
import trimesh
from scipy.spatial import ConvexHull

from indoorgen.assets import Asset
from indoorgen.assets.protocol import Joint
from indoorgen.model.tags import Semantics
from indoorgen.solver.broadphase import PIECE_SWEEP, PIECE_ZONE, YIELD_NONE, YIELD_UNDER, YIELD_ZONES

#: NKBA Bathroom Planning Guideline 11 / IRC R307: a toilet's centreline >= 15 in (0.38 m) from a
#: side wall or obstacle, >= 21 in (0.53 m) clear in front
TOILET_SIDE = 0.38
TOILET_FRONT = 0.53
#: small wall accessories a toilet may have beside it (not obstacles to sitting)
ACCESSORIES = (Semantics.ToiletRollHolder, Semantics.TowelBar, Semantics.TowelRing,
               Semantics.RobeHook)
#: the clear space is this much wider and deeper than the guideline (m), so touching counts
CLEAR_MARGIN = 0.005
#: free depth before the fronts of storage and appliances (ergonomic clearance: 0.6 m to open a
#: door or drawer and stand before it; NKBA kitchen guideline: 0.9 m before the fridge, range
#: and dishwasher, whose doors fold down or swing wide)
FRONT_CLEAR = 0.6
FRONT_CLEAR_WIDE = 0.9
WIDE_FRONTS = (Semantics.Fridge, Semantics.Range, Semantics.Dishwasher)
#: obstacles to walking and opening are the parts of objects between these heights above the
#: floor (m): rugs lie lower, wall cabinets and shelves above a counter hang higher (the
#: solver keeps fronts clear over this band; the report measures obstacles in it)
OBSTACLE_BAND = (0.05, 1.2)
#: margin kept off both sides of a front (m), so touching neighbours don't count
BAND_MARGIN = 0.02
#: storage with no front to keep clear
UNFRONTED = (Semantics.Box, Semantics.WallMounted, Semantics.SmallObject)
#: windows keep out floor objects taller than this (m) and anything hung on their wall (window
#: dressings aside), over this depth either side of the opening (m)
WINDOW_TALL = 1.0
WINDOW_DEPTH = 0.3
#: window dressings: what is hung at a window on purpose. The zone keeps light and the window's
#: use free of furniture and of things hung on its wall (art, shelves, cabinets); a curtain is
#: sized to its window and hung over and beside it, drawn open to the sides, so it belongs in the
#: zone and is exempt from it (the solver's `window_bound`, the report's `windows_keep_out`)
WINDOW_DRESSINGS = frozenset({Semantics.Curtain})
#: screens keep out of a window's zone wherever they stand (on a TV stand too): a screen before a
#: window is watched against the daylight and mirrors it (glare; TV-placement guidance)
WINDOW_SCREENS = frozenset({Semantics.TV})
#: what holds a screen keeps out of the zone before a window down to the floor: the screen will
#: stand on it, before the window (a stand under a sill left its TV nowhere to go)
SCREEN_STANDS = frozenset({Semantics.TVStand})
#: that zone starts this far over the floor (m), so a stand standing on it does not touch it
SCREEN_LIFT = 0.01
#: a sweep volume is inset this much on each side (m): an opened part may touch a wall or an
#: object (the report allows 5 mm), and a part built flush on the floor must not hit the floor
SWEEP_INSET = 0.004
#: the thinnest a moving link's box is taken to be (m), so its sweep is a solid
MIN_THICKNESS = 0.01
#: a revolute joint about a vertical axis this far inside its link's plan box (a fraction of the
#: half-size) spins in place, like a chair's swivel: it sweeps nothing beyond the object itself
TURNTABLE = 0.5


def open_limit(j: Joint) -> float:
    """The joint's open limit: the end of its range with the larger travel."""
    return j.upper if abs(j.upper) >= abs(j.lower) else j.lower


def spins_in_place(j: Joint, pts: np.ndarray) -> bool:
    """Does a revolute joint spin its link (points `pts`) in place, about a vertical axis well
    inside it (a chair's swivel)? Such a part has no open pose to keep free."""
    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    if j.kind != "revolute" or abs(axis[2]) < 0.99:
        return False
    lo, hi = pts[:, :2].min(axis=0), pts[:, :2].max(axis=0)
    centre, half = (lo + hi) / 2, np.maximum((hi - lo) / 2, 1e-9)
    return bool((np.abs(np.asarray(j.origin, float)[:2] - centre) <= TURNTABLE * half).all())


def _inset(pts: np.ndarray, inset: float) -> np.ndarray:
    """Points pulled towards their box's centre so the box shrinks by `inset` on every side."""
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    scale = np.where(half > 2 * inset, (half - inset) / np.maximum(half, 1e-12), 1.0)
    return centre + (pts - centre) * scale


def sweep_volumes(joints: list[Joint], link_boxes: dict[str, np.ndarray]) -> list[np.ndarray]:
    """One convex volume (asset frame, as the points it is the hull of) per joint: its moving
    link's box
    (`link_boxes`: link -> (2, 3) box at the closed pose) at the open limit, and half-way for a
    door, a lid or a flap, so the arc is covered."""
    out = []
    for j in joints:
        box = link_boxes.get(j.child)
        if box is None:
            continue
        lo, hi = np.asarray(box, float)
        pad = np.maximum(MIN_THICKNESS - (hi - lo), 0.0) / 2  # a flat link still has a volume
        pts = trimesh.bounds.corners(np.array([lo - pad, hi + pad]))
        if spins_in_place(j, pts):
            continue
        limit = open_limit(j)
        values = (limit,) if j.kind == "prismatic" else (limit / 2, limit)
        moved = np.vstack([trimesh.transform_points(pts, j.transform(v)) for v in values])
        out.append(_inset(moved, SWEEP_INSET))
    return out


def _box(lo: tuple[float, float, float], hi: tuple[float, float, float]) -> np.ndarray:
    return trimesh.bounds.corners(np.array([lo, hi]))


def use_zones(tags: frozenset, bounds: np.ndarray, size_class: str) -> list[np.ndarray]:
    """The clear space an object needs to be used (asset frame, as the corners of a box; from
    its bounding box `bounds` (2, 3)): a toilet's, `TOILET_SIDE` either side of its centreline
    over its depth and `TOILET_FRONT` before it; before floor-standing storage and appliances
    (`size_class` "large", and furniture of "medium" size: a nightstand, not a microwave on a
    counter) `FRONT_CLEAR`, or `FRONT_CLEAR_WIDE` for a fridge, range or dishwasher (boxes,
    wall-mounted and small things aside)."""
    lo, hi = np.asarray(bounds, float)
    if Semantics.Toilet in tags:
        cy, side = (lo[1] + hi[1]) / 2, TOILET_SIDE + CLEAR_MARGIN
        return [_box((lo[0] + BAND_MARGIN, cy - side, lo[2] + OBSTACLE_BAND[0]),  # the wall
                     (hi[0] + TOILET_FRONT + CLEAR_MARGIN, cy + side,  # behind is not beside it
                      lo[2] + OBSTACLE_BAND[1]))]
    fronted = Semantics.Storage in tags or Semantics.Appliance in tags
    standing = size_class == "large" or (size_class == "medium" and Semantics.Furniture in tags)
    if not fronted or not standing or any(t in tags for t in UNFRONTED):
        return []
    wide = any(t in tags for t in WIDE_FRONTS)
    depth = (FRONT_CLEAR_WIDE if wide else FRONT_CLEAR) + CLEAR_MARGIN
    return [_box((hi[0], lo[1] + BAND_MARGIN, lo[2] + OBSTACLE_BAND[0]),
                 (hi[0] + depth, hi[1] - BAND_MARGIN, lo[2] + OBSTACLE_BAND[1]))]


def keep_free_volumes(asset: Asset, tags: frozenset, size_class: str,
                      link_boxes: dict[str, np.ndarray]
                      ) -> tuple[list[fcl.Convex], np.ndarray, np.ndarray]:
    """Every keep-free volume of an asset in its own frame, as fcl solids with their boxes
    (k, 2, 3) and kinds (`PIECE_SWEEP`, `PIECE_ZONE`): its joints' sweeps (from its moving
    links' boxes) and its use zones."""
    sweeps = sweep_volumes(asset.joints, link_boxes)
    # one hull round all the sweeps: the space before a run of fronts, which a person opening
    # them stands in anyway (and one solid where a run would have a dozen)
    swept = [np.vstack(sweeps)] if sweeps else []
    clouds = swept + use_zones(tags, asset.mesh.bounds, size_class)
    boxes = np.array([[c.min(axis=0), c.max(axis=0)] for c in clouds], float).reshape(-1, 2, 3)
    kinds = np.array([PIECE_SWEEP] * len(swept) + [PIECE_ZONE] * (len(clouds) - len(swept)), int)
    return [hull_solid(c) for c in clouds], boxes, kinds


def yields(tags: frozenset) -> int:
    """What an object's solid pieces yield to others' keep-free pieces, as the quality rules
    count obstacles: a rug to everything, solids too (furniture stands on it); a small object,
    or a wall accessory that belongs beside a toilet or basin, to use zones; anything else
    nothing."""
    if Semantics.FloorCovering in tags:
        return YIELD_UNDER
    if Semantics.SmallObject in tags or any(t in tags for t in ACCESSORIES):
        return YIELD_ZONES
    return YIELD_NONE


def hull_solid(points: np.ndarray) -> fcl.Convex:
    """The convex hull of `points` as an fcl solid (scipy's Qhull, faces turned outwards; many
    times quicker than a trimesh hull for the few points of a sweep)."""
    hull = ConvexHull(points)
    used = np.unique(hull.simplices)
    index = np.full(len(points), -1)
    index[used] = np.arange(len(used))
    faces = hull.simplices.copy()
    v = points[faces]
    normal = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    flip = np.einsum("ij,ij->i", normal, hull.equations[:, :3]) < 0
    faces[flip] = faces[flip][:, ::-1]
    faces = index[faces]
    flat = np.hstack([np.full((len(faces), 1), 3), faces]).ravel()
    return fcl.Convex(np.asarray(points[used], float), len(faces), flat)


def window_zone(bounds: np.ndarray) -> tuple[sg.Polygon, int]:
    """A window's keep-out zone in plan (its opening's box `bounds` (2, 3) widened
    `WINDOW_DEPTH` either side of the wall) and its long axis (0: x, 1: y). Walls of homes are
    axis-aligned."""
    (x0, y0, _), (x1, y1, _) = np.asarray(bounds, float)
    if x1 - x0 >= y1 - y0:
        return sg.box(x0, y0 - WINDOW_DEPTH, x1, y1 + WINDOW_DEPTH), 0
    return sg.box(x0 - WINDOW_DEPTH, y0, x1 + WINDOW_DEPTH, y1), 1


def window_volume(bounds: np.ndarray, floor: float | None = None) -> trimesh.Trimesh:
    """A window's keep-out zone as a solid: its plan zone over the opening's heights (from
    `floor` instead, if given: where screens' stands keep out)."""
    zone, _ = window_zone(bounds)
    z0, z1 = float(bounds[0][2]) if floor is None else floor, float(bounds[1][2])
    x0, y0, x1, y1 = zone.bounds
    return trimesh.creation.box(bounds=np.array([(x0, y0, z0), (x1, y1, z1)]))
