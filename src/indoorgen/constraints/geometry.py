"""Geometric scalar terms of the constraint DSL (Infinigen Indoors, Appendix A.1).

Every function here is pure: objects are described by plain numpy arrays, shapely footprints or
world-space trimesh meshes, so the terms are independent of the solver and of the scene graph.
All objects are upright (they only rotate about +Z); a "front" is the world direction of the
object's local +X, and a "yaw" is the angle of that front measured counter-clockwise from +X.

Deviations from the formulas as printed in the paper are deliberate and documented in the
docstring of the function concerned:

* :func:`rotational_asymmetry` orders objects by angle around their centroid (the paper leaves
  the order implicit), which makes the score independent of input order.
* :func:`reflectional_asymmetry` is the 2D (yaw-only) form, and normalises by the mean pairwise
  distance between the *objects* (the paper's printed alpha has a typo, p_i - p'_i).
* :func:`focus_score` normalises the direction to the target so that each contribution really is
  in [0, 1], as the paper states but its printed formula does not achieve.
* :func:`accessibility_cost_fast` / :func:`accessibility_cost_slow` clamp the signed numerator
  at 0, so blockers behind the accessed plane cost nothing instead of a reward.
* :func:`freespace_2d` uses unions so overlapping footprints are not double counted, and only
  subtracts the part of B that lies on A.
"""
from __future__ import annotations

import logging
import math
from collections.abc import Sequence

import fcl
import numpy as np
import shapely
import trimesh
from scipy.optimize import linear_sum_assignment
from shapely.geometry import LineString, MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.geometry.polygon import orient

logger = logging.getLogger(__name__)

__all__ = [
    "mesh_to_fcl",
    "rotational_asymmetry",
    "reflectional_asymmetry",
    "angle_alignment_cost",
    "focus_score",
    "accessibility_cost_fast",
    "accessibility_cost_slow",
    "freespace_2d",
    "bbox_volume",
    "bbox_area",
    "min_distance",
    "polygon_distance",
    "center_of_support_distance",
]

#: Lengths below this are treated as zero (degenerate directions, coincident points).
_EPS = 1e-12


# ------------------------------------------------------------------------------------- helpers
def _unit_rows(v: np.ndarray) -> np.ndarray:
    """Rows of `v` scaled to unit length; zero rows stay zero."""
    v = np.asarray(v, dtype=float)
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    unit: np.ndarray = np.divide(v, n, out=np.zeros_like(v), where=n > _EPS)
    return unit


def _rotate2d(v: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Rotate each 2D row v[i] counter-clockwise by angles[i] (radians)."""
    c, s = np.cos(angles), np.sin(angles)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=1)


def _wrapped_angle_diff(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """|a - b| wrapped into [0, pi]. For rotations about one axis this equals the quaternion
    distance 2*arccos(|q_a . q_b|) used by the paper."""
    d = np.mod(np.asarray(a, float) - np.asarray(b, float) + math.pi, 2.0 * math.pi) - math.pi
    wrapped: np.ndarray = np.abs(d)
    return wrapped


def mesh_to_fcl(mesh: trimesh.Trimesh) -> fcl.BVHModel:
    """An fcl bounding-volume-hierarchy model of `mesh`, in the mesh's own (world) coordinates."""
    verts = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int32)
    model = fcl.BVHModel()
    model.beginModel(len(verts), len(faces))
    model.addSubModel(verts, faces)
    model.endModel()
    return model


def _fcl_objects(meshes: Sequence[trimesh.Trimesh]) -> list[fcl.CollisionObject]:
    return [fcl.CollisionObject(mesh_to_fcl(m), fcl.Transform()) for m in meshes]


def _fcl_distance(a: fcl.CollisionObject, b: fcl.CollisionObject) -> tuple[float, np.ndarray]:
    """Exact distance between two fcl objects (0 when they touch or intersect) and the point on
    `b` closest to `a` (a point of the overlap when they intersect)."""
    req = fcl.DistanceRequest(enable_nearest_points=True)
    res = fcl.DistanceResult()
    d = fcl.distance(a, b, req, res)
    return max(0.0, float(d)), np.asarray(res.nearest_points[1], dtype=float)


# ------------------------------------------------------------------------------------ symmetry
def _cyclic_asymmetry(v: np.ndarray) -> float:
    """Mean squared deviation of vectors v (already in cyclic order) from the best perfectly
    n-fold rotationally symmetric set: f_i = R(-2*pi*i/n) v_i, q = mean f_i,
    w_i = R(2*pi*i/n) q, result (1/n) * sum ||w_i - v_i||^2. Rotations preserve norms, so this
    equals (1/n) * sum ||q - f_i||^2."""
    n = len(v)
    f = _rotate2d(v, -2.0 * math.pi * np.arange(n) / n)
    q = f.mean(axis=0)
    return float(np.mean(np.sum((f - q) ** 2, axis=1)))


def rotational_asymmetry(centers: np.ndarray, fronts: np.ndarray) -> float:
    """Continuous rotational asymmetry of a set of upright objects (paper: rotation_asymmetry).

    score = (location asymmetry + orientation asymmetry) / 2, where each part measures how far the
    point set (resp. the set of front vectors) is from one that is invariant under rotation by
    2*pi/n about the centroid; 0 means a perfect regular arrangement (e.g. chairs evenly around a
    round table, all facing it).

    Location: p_i = x_i - centroid, normalised by max_i ||p_i||; orientation: the unit fronts
    (not centred, so a set of objects all facing the same way is *not* symmetric). For each, with
    f_i = R(-2*pi*i/n) v_i, q = mean(f_i), w_i = R(2*pi*i/n) q, asymmetry = mean ||w_i - v_i||^2.

    Choices beyond the paper:

    * the i-th object is the i-th in counter-clockwise angular order of p_i around the centroid
      (ties broken by radius, then front angle), so the score does not depend on input order;
    * the paper's "rotate so that p_1 lies on the axis" step is skipped: the score is invariant
      under any global rotation anyway;
    * if all objects coincide the location part is 0.

    Args:
        centers: (n, 2) XY positions.
        fronts: (n, 2) front vectors (normalised here).

    Returns:
        The score, >= 0; 0.0 for n <= 1.
    """
    centers = np.asarray(centers, dtype=float).reshape(-1, 2)
    fronts = np.asarray(fronts, dtype=float).reshape(-1, 2)
    if len(centers) != len(fronts):
        raise ValueError(f"{len(centers)} centers but {len(fronts)} fronts")
    n = len(centers)
    if n <= 1:
        return 0.0
    p = centers - centers.mean(axis=0)
    radius = np.linalg.norm(p, axis=1)
    angle = np.arctan2(p[:, 1], p[:, 0])
    front_angle = np.arctan2(fronts[:, 1], fronts[:, 0])
    order = np.lexsort((front_angle, radius, angle))  # last key is the primary one
    p, u = p[order], _unit_rows(fronts[order])
    scale = radius.max()
    location = _cyclic_asymmetry(p / scale) if scale > _EPS else 0.0
    orientation = _cyclic_asymmetry(u)
    return 0.5 * (location + orientation)


def reflectional_asymmetry(centers: np.ndarray, yaws: np.ndarray, volumes: np.ndarray,
                           plane_point: np.ndarray, plane_normal: np.ndarray) -> float:
    """Continuous mirror asymmetry of a set of upright objects across a vertical plane (paper:
    reflection_asymmetry), in the XY plane.

    Each object (p_i, yaw_i) is reflected across the line through `plane_point` with normal N:
    p' = p - 2((p - plane_point) . N) N and yaw' = 2*phi - yaw, phi being the line's direction
    angle (yaw is the angle of the front from +X). Originals and reflections are paired by a
    minimum-cost bipartite matching (scipy's modified Jonker-Volgenant) on
    cost = ||p_i - p'_j|| + D_ang(yaw_i, yaw'_j), D_ang = |yaw_i - yaw'_j| wrapped to [0, pi]
    (= the paper's 2*arccos|q.q'| for rotations about Z). With D_dev_i = V_i * (D_pos + D_ang)
    and alpha the mean pairwise distance between the objects,

        score = 1 - 1 / (1 + sum_i D_dev_i / alpha),

    in [0, 1): 0 for a perfectly mirror-symmetric set (e.g. two nightstands either side of a
    bed), growing towards 1 with the volume-weighted deviation.

    Deviations: the paper's printed alpha, sum_{i != j} ||p_i - p'_i|| / (N(N-1)), has an index
    typo; we use the mean pairwise distance sum_{i != j} ||p_i - p_j|| / (N(N-1)). alpha = 1.0
    when N < 2 or all objects coincide, to avoid dividing by zero.

    Args:
        centers: (n, 2) XY positions.
        yaws: (n,) yaw angles in radians.
        volumes: (n,) bounding-box volumes used as weights.
        plane_point: a point on the mirror line (XY, extra coordinates ignored).
        plane_normal: the mirror line's normal (XY, extra coordinates ignored; normalised here).
    """
    p = np.asarray(centers, dtype=float).reshape(-1, 2)
    yaw = np.asarray(yaws, dtype=float).reshape(-1)
    vol = np.asarray(volumes, dtype=float).reshape(-1)
    if not len(p) == len(yaw) == len(vol):
        raise ValueError("centers, yaws and volumes must have the same length")
    n = len(p)
    if n == 0:
        return 0.0
    normal = np.asarray(plane_normal, dtype=float).reshape(-1)[:2]
    norm = float(np.linalg.norm(normal))
    if norm <= _EPS:
        raise ValueError("plane_normal must have a non-zero XY component")
    normal = normal / norm
    origin = np.asarray(plane_point, dtype=float).reshape(-1)[:2]

    p_ref = p - 2.0 * ((p - origin) @ normal)[:, None] * normal[None, :]
    phi = math.atan2(normal[1], normal[0]) + 0.5 * math.pi
    yaw_ref = 2.0 * phi - yaw

    d_pos = np.linalg.norm(p[:, None, :] - p_ref[None, :, :], axis=2)
    d_ang = _wrapped_angle_diff(yaw[:, None], yaw_ref[None, :])
    cost = d_pos + d_ang
    rows, cols = linear_sum_assignment(cost)
    total = float(np.sum(vol[rows] * cost[rows, cols]))

    alpha = 1.0
    if n >= 2:
        pair = np.linalg.norm(p[:, None, :] - p[None, :, :], axis=2)
        mean_pair = float(pair.sum() / (n * (n - 1)))
        if mean_pair > _EPS:
            alpha = mean_pair
    return 1.0 - 1.0 / (1.0 + total / alpha)


# ---------------------------------------------------------------------------------- alignment
def _inward_edges(reference: BaseGeometry) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Start points, end points and inward unit normals of every non-degenerate boundary edge of
    a polygon (or multipolygon), holes included."""
    if isinstance(reference, Polygon):
        polys = [reference]
    elif isinstance(reference, MultiPolygon):
        polys = list(reference.geoms)
    else:
        raise TypeError(f"reference must be a Polygon or MultiPolygon, got {type(reference)!r}")
    starts, ends = [], []
    for poly in polys:
        # exterior counter-clockwise, holes clockwise: the interior is always on the left
        poly = orient(poly, sign=1.0)
        for ring in (poly.exterior, *poly.interiors):
            xy = np.asarray(ring.coords, dtype=float)[:, :2]
            starts.append(xy[:-1])
            ends.append(xy[1:])
    a = np.concatenate(starts) if starts else np.zeros((0, 2))
    b = np.concatenate(ends) if ends else np.zeros((0, 2))
    d = b - a
    keep = np.linalg.norm(d, axis=1) > _EPS
    a, b, d = a[keep], b[keep], d[keep]
    normals = _unit_rows(np.stack([-d[:, 1], d[:, 0]], axis=1))  # left normal
    return a, b, normals


def angle_alignment_cost(fronts: np.ndarray, centers: np.ndarray, reference: Polygon) -> float:
    """How far objects are from facing along the inward normal of the nearest edge of a
    reference footprint (paper: angle_alignment_cost):

        cost = sum_i (1 - cos theta_i) / 2,

    theta_i being the angle between object i's front (XY) and the inward normal of the edge of
    `reference` closest to the object's centre. Each term is in [0, 1]: 0 when the front points
    along the inward normal, 0.5 when perpendicular, 1 when opposite.

    "Inward" always means towards the polygon's interior, which serves both uses: for a room the
    object sits inside and is aligned when it faces away from its nearest wall into the room; for
    "chairs face the table" the chair sits outside the table footprint and is aligned when it faces
    into the table.

    Args:
        fronts: (n, 2) front vectors (normalised here; extra coordinates ignored).
        centers: (n, 2) XY centres (extra coordinates ignored).
        reference: the reference footprint (a MultiPolygon is also accepted).
    """
    fronts = np.asarray(fronts, dtype=float)
    centers = np.asarray(centers, dtype=float)
    fronts = fronts.reshape(-1, fronts.shape[-1])[:, :2]
    centers = centers.reshape(-1, centers.shape[-1])[:, :2]
    if len(fronts) != len(centers):
        raise ValueError(f"{len(fronts)} fronts but {len(centers)} centers")
    if len(fronts) == 0:
        return 0.0
    a, b, normals = _inward_edges(reference)
    if len(a) == 0:
        raise ValueError("reference polygon has no edges")
    # point-to-segment distances, (n objects, E edges)
    d = b - a
    rel = centers[:, None, :] - a[None, :, :]
    t = np.clip(np.einsum("nek,ek->ne", rel, d) / np.einsum("ek,ek->e", d, d), 0.0, 1.0)
    closest = a[None] + t[..., None] * d[None]
    dist = np.linalg.norm(centers[:, None, :] - closest, axis=2)
    edge = np.argmin(dist, axis=1)
    cos = np.einsum("nk,nk->n", _unit_rows(fronts), normals[edge])
    return float(np.sum((1.0 - cos) / 2.0))


def focus_score(centers: np.ndarray, fronts: np.ndarray, target: np.ndarray) -> float:
    """How far objects turn away from a target (paper: focus_score):

        score = sum_a (1 - n_a . (b_c - a_c) / ||b_c - a_c||) / 2,

    n_a the unit front of object a, a_c its centre, b_c the target's centre. Each term is in
    [0, 1]: 0 facing the target, 0.5 perpendicular, 1 facing directly away.

    Deviation: the paper prints (1 - n_a . (b_c - a_c)) / (2 ||b_c - a_c||), which does not
    normalise the dot product and so is neither in [0, 1] nor scale invariant; we normalise the
    direction (and the front) so each contribution is in [0, 1] as the paper states. An object
    whose centre coincides with the target has no direction to face and contributes 0.5.

    Works with 2D or 3D arrays: centers, fronts (n, d); target (d,) or broadcastable to (n, d).
    """
    centers = np.asarray(centers, dtype=float)
    fronts = np.asarray(fronts, dtype=float)
    dim = centers.shape[-1]
    centers = centers.reshape(-1, dim)
    fronts = fronts.reshape(-1, dim)
    if len(centers) != len(fronts):
        raise ValueError(f"{len(centers)} centers but {len(fronts)} fronts")
    if len(centers) == 0:
        return 0.0
    to_target = np.asarray(target, dtype=float) - centers
    dist = np.linalg.norm(to_target, axis=1)
    cos = np.einsum("nk,nk->n", _unit_rows(fronts), _unit_rows(to_target))
    terms = np.where(dist > _EPS, (1.0 - cos) / 2.0, 0.5)
    return float(np.sum(terms))


# ------------------------------------------------------------------------------ accessibility
def _project_to_planes(a_centers: np.ndarray, a_normals: np.ndarray,
                       a_plane_points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """a_proj = a_c - ((a_c - f_p) . n) n, with n normalised; returns (a_proj, n)."""
    c = np.asarray(a_centers, dtype=float).reshape(-1, 3)
    n = _unit_rows(np.asarray(a_normals, dtype=float).reshape(-1, 3))
    fp = np.asarray(a_plane_points, dtype=float).reshape(-1, 3)
    if not len(c) == len(n) == len(fp):
        raise ValueError("a_centers, a_normals and a_plane_points must have the same length")
    return c - np.einsum("nk,nk->n", c - fp, n)[:, None] * n, n


def _blocking_terms(closest: np.ndarray, a_proj: np.ndarray, normals: np.ndarray,
                    diagonals: np.ndarray) -> np.ndarray:
    """max(0, (b - a_proj) . n) / ||b - a_proj||^2 * diag per row; 0 if b == a_proj."""
    rel = closest - a_proj
    ahead = np.maximum(0.0, np.einsum("nk,nk->n", rel, normals))
    d2 = np.einsum("nk,nk->n", rel, rel)
    ratio = np.divide(ahead, d2, out=np.zeros_like(ahead), where=d2 > _EPS)
    terms: np.ndarray = ratio * diagonals
    return terms


def accessibility_cost_fast(a_centers: np.ndarray, a_normals: np.ndarray,
                            a_plane_points: np.ndarray, b_centers: np.ndarray,
                            b_diagonals: np.ndarray) -> float:
    """How much objects B block access to the accessed plane (e.g. front) of objects A (paper:
    accessibility_cost, fast version).

    For each a: a_proj = a_c - ((a_c - f_p) . n_a) n_a projects a's centroid onto its plane;
    b(a) is the blocker whose centroid is closest to a_proj, and

        cost = sum_a max(0, (b_c - a_proj) . n_a) / ||b_c - a_proj||^2 * diag(b),

    which grows as the blocker gets larger, closer, and more squarely in front of the plane.

    Deviation: the paper uses the signed numerator; we clamp it at 0, deliberately, so a blocker
    behind the plane contributes 0 rather than a negative cost (which would reward clutter behind
    e.g. a TV). A blocker whose centroid lies exactly on a_proj contributes 0.

    Args:
        a_centers, a_normals, a_plane_points: (n, 3) centroid, accessed-plane unit normal and a
            point on that plane for each accessed object.
        b_centers: (m, 3) blocker centroids.
        b_diagonals: (m,) blocker bounding-box diagonal lengths.

    Returns:
        The cost (>= 0); 0.0 when there are no blockers or no accessed objects.
    """
    b_c = np.asarray(b_centers, dtype=float).reshape(-1, 3)
    b_d = np.asarray(b_diagonals, dtype=float).reshape(-1)
    if len(b_c) != len(b_d):
        raise ValueError(f"{len(b_c)} blocker centers but {len(b_d)} diagonals")
    a_proj, n = _project_to_planes(a_centers, a_normals, a_plane_points)
    if len(b_c) == 0 or len(a_proj) == 0:
        return 0.0
    dist = np.linalg.norm(b_c[None, :, :] - a_proj[:, None, :], axis=2)
    nearest = np.argmin(dist, axis=1)
    return float(np.sum(_blocking_terms(b_c[nearest], a_proj, n, b_d[nearest])))


def accessibility_cost_slow(a_meshes: Sequence[trimesh.Trimesh], a_normals: np.ndarray,
                            a_plane_points: np.ndarray,
                            b_meshes: Sequence[trimesh.Trimesh]) -> float:
    """Exact-mesh version of :func:`accessibility_cost_fast` (paper: accessibility_cost, slow).

    b(a) is the blocker whose mesh is closest to a's mesh (exact mesh-mesh distance via fcl), the
    point on b(a)'s mesh closest to a's mesh replaces b's centroid, and diag(b) is the diagonal
    of b(a)'s mesh bounds; a's centroid is the centre of its mesh bounds. The same clamp at 0 for
    blockers behind the plane applies. When meshes intersect, fcl's reported point (inside the
    overlap) is used.

    Args:
        a_meshes: n world-space meshes of the accessed objects.
        a_normals, a_plane_points: (n, 3) accessed-plane unit normal and a point on it.
        b_meshes: m world-space blocker meshes.
    """
    a_meshes, b_meshes = list(a_meshes), list(b_meshes)
    if not a_meshes or not b_meshes:
        return 0.0
    a_centers = np.array([m.bounds.mean(axis=0) for m in a_meshes], dtype=float)
    a_proj, n = _project_to_planes(a_centers, a_normals, a_plane_points)
    if len(a_proj) != len(a_meshes):
        raise ValueError(f"{len(a_meshes)} meshes but {len(a_proj)} normals/plane points")
    b_diag = np.array([float(np.linalg.norm(np.ptp(m.bounds, axis=0))) for m in b_meshes])
    a_objs, b_objs = _fcl_objects(a_meshes), _fcl_objects(b_meshes)
    closest = np.empty((len(a_objs), 3))
    diag = np.empty(len(a_objs))
    for i, ao in enumerate(a_objs):
        best, best_pt, best_j = math.inf, None, -1
        for j, bo in enumerate(b_objs):
            d, pt = _fcl_distance(ao, bo)
            if d < best:
                best, best_pt, best_j = d, pt, j
        closest[i], diag[i] = best_pt, b_diag[best_j]
        logger.debug("accessibility_cost_slow: a[%d] blocked by b[%d] at distance %.4g",
                     i, best_j, best)
    return float(np.sum(_blocking_terms(closest, a_proj, n, diag)))


# ------------------------------------------------------------------------------ area / volume
def freespace_2d(a_footprints: Sequence[Polygon], b_footprints: Sequence[Polygon]) -> float:
    """Free 2D area left on objects A once objects B are placed (paper: freespace_2d).

    The paper's sum_a mu(proj a) - sum_b mu(proj b) is computed as

        area(union(A)) - area(union(B) ∩ union(A)),

    a deliberate choice: overlapping footprints are not double counted, and the part of a B
    footprint that lies outside every A (e.g. a plate overhanging the table edge, or an object in
    another room) does not reduce A's free space. The result is in [0, area(union(A))].
    """
    a_geoms = [g for g in a_footprints if g is not None and not g.is_empty]
    if not a_geoms:
        return 0.0
    a_union = shapely.union_all(a_geoms)
    b_geoms = [g for g in b_footprints if g is not None and not g.is_empty]
    if not b_geoms:
        return float(a_union.area)
    covered = shapely.union_all(b_geoms).intersection(a_union)
    return float(a_union.area - covered.area)


def bbox_volume(extents: np.ndarray, dims: Sequence[int] = (0, 1, 2)) -> float:
    """Total bounding-box "volume" of a set of objects: sum over objects of the product of
    their extents along `dims` (all three axes by default; e.g. dims=(0, 1) gives footprint
    area). `extents` is (n, 3)."""
    e = np.asarray(extents, dtype=float)
    if e.size == 0:
        return 0.0
    e = e.reshape(-1, e.shape[-1])
    return float(np.sum(np.prod(e[:, list(dims)], axis=1)))


def bbox_area(extents: np.ndarray) -> float:
    """Total bounding-box area of a set of objects: per object the product of its two largest
    extents (the paper's choice, suiting flat objects like paintings and rugs), summed.
    `extents` is (n, 3)."""
    e = np.asarray(extents, dtype=float)
    if e.size == 0:
        return 0.0
    e = np.sort(e.reshape(-1, e.shape[-1]), axis=1)
    return float(np.sum(e[:, -1] * e[:, -2]))


# ---------------------------------------------------------------------------------- distances
def min_distance(meshes_a: Sequence[trimesh.Trimesh],
                 meshes_b: Sequence[trimesh.Trimesh]) -> float:
    """Minimum exact mesh-to-mesh distance over all pairs (a, b) (paper: min_distance), via fcl;
    0 if any pair touches or intersects, inf if either list is empty."""
    meshes_a, meshes_b = list(meshes_a), list(meshes_b)
    if not meshes_a or not meshes_b:
        return math.inf
    a_objs, b_objs = _fcl_objects(meshes_a), _fcl_objects(meshes_b)
    best = math.inf
    for ao in a_objs:
        for bo in b_objs:
            req = fcl.DistanceRequest()
            res = fcl.DistanceResult()
            best = min(best, max(0.0, float(fcl.distance(ao, bo, req, res))))
            if best == 0.0:
                return 0.0
    return best


def polygon_distance(a: Polygon, b: Polygon | LineString | BaseGeometry) -> float:
    """Shortest 2D distance between two footprints (or a footprint and a line such as a wall);
    0 when they touch or overlap."""
    return float(a.distance(b))


def center_of_support_distance(child_center_xy: np.ndarray, support: Polygon) -> float:
    """Distance from a child's XY centre to the centroid of the polygon supporting it (e.g. "put
    the vase in the middle of the table"); 0 when it sits exactly at the centre."""
    c = np.asarray(child_center_xy, dtype=float).reshape(-1)[:2]
    centroid = support.centroid
    return float(math.hypot(c[0] - centroid.x, c[1] - centroid.y))


def facing_angle(center: np.ndarray, front: np.ndarray, target: np.ndarray) -> float:
    """Angle in degrees (0..180) between an object's front and the plan direction from its centre
    to a target point: 0 when it faces the target, 90 side-on (a sofa and its TV each within
    ~30 deg: THX / SMPTE viewing-angle guidance). 0 when the centre is on the target."""
    d = np.asarray(target, float)[:2] - np.asarray(center, float)[:2]
    f = np.asarray(front, float)[:2]
    nd, nf = float(np.linalg.norm(d)), float(np.linalg.norm(f))
    if nd < 1e-9 or nf < 1e-12:
        return 0.0
    return math.degrees(math.acos(float(np.clip(np.dot(d, f) / (nd * nf), -1.0, 1.0))))


def front_free_depth(front_edge: tuple[np.ndarray, np.ndarray], front: np.ndarray,
                     blockers: Sequence[BaseGeometry], probe: float) -> float:
    """Free plan depth before an object's front edge (two world XY points), along its unit
    `front`, over the edge's width, to the first blocker (footprints, or walls as lines);
    `probe` when nothing is that close."""
    a, b = (np.asarray(p, float)[:2] for p in front_edge)
    f = np.asarray(front, float)[:2]
    band = Polygon([a, b, b + f * probe, a + f * probe])
    edge = LineString([a, b])
    depth = probe
    for g in blockers:
        hit = g.intersection(band)
        if not hit.is_empty:
            depth = min(depth, float(hit.distance(edge)))
    return depth
