"""Seating's shared shape helpers: splayed legs (slanted posts), backs leaning by a shear and the
exact boxes that stand in for them in placeholders, and seat surfaces."""
from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.protocol import Surface
from indoorgen.assets.shapes.primitives import Part, Vec3, bevel_box, box_between
from indoorgen.assets.shapes.surfaces import support_polygon


def post(bottom: Vec3, top: Vec3, r_bottom: float,
         r_top: float | None = None, sections: int = 16, circumscribed: bool = False,
         square: bool = False) -> m3d.Manifold:
    """A straight or slanted leg from point `bottom` to point `top` whose horizontal sections
    are circles (or squares, `square=True`) of radius r_bottom at the bottom and r_top at the
    top: its foot stands flat on the floor however far it is splayed. `circumscribed` makes the
    polygon contain the true circle, with the same bounding box (for placeholders)."""
    rt = r_bottom if r_top is None else r_top
    if square:
        ring = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)], float)
    else:
        n = max(4, int(math.ceil(sections / 4.0)) * 4)
        k = 1.0 / math.cos(math.pi / n) if circumscribed else 1.0
        a = 2 * np.pi * np.arange(n) / n + (math.pi / n if circumscribed else 0.0)
        ring = k * np.c_[np.cos(a), np.sin(a)]
    b, t = np.asarray(bottom, float), np.asarray(top, float)
    pts = np.vstack([np.c_[b[0] + r_bottom * ring[:, 0], b[1] + r_bottom * ring[:, 1],
                           np.full(len(ring), b[2])],
                     np.c_[t[0] + rt * ring[:, 0], t[1] + rt * ring[:, 1], np.full(len(ring), t[2])]])
    return m3d.Manifold.hull_points(pts)


def splay_legs(corners: Sequence[tuple[float, float]], z_top: float, r_top: float,
               r_foot: float, splay: float, detail: bool, slot: str, square: bool = False,
               sections: int = 16) -> tuple[list[Part], list[tuple[np.ndarray, np.ndarray]]]:
    """Legs from the (x, y) `corners` under a seat at height z_top down to feet pushed `splay`
    metres further out (radially from the origin). Returns the parts and each leg's
    (foot, top) centre points, for rungs and rings."""
    out, axes = [], []
    for cx, cy in corners:
        d = math.hypot(cx, cy)
        ux, uy = (cx / d, cy / d) if d > 1e-9 else (0.0, 0.0)
        foot = np.array([cx + ux * splay, cy + uy * splay, 0.0])
        top = np.array([cx, cy, z_top])
        out.append(Part(post(foot, top, r_foot, r_top, sections if detail else 8,
                             circumscribed=not detail, square=square), slot))
        axes.append((foot, top))
    return out, axes


def leg_point(axis: tuple[np.ndarray, np.ndarray], z: float) -> np.ndarray:
    """The centre of a leg (foot, top) at height z."""
    foot, top = axis
    t = (z - foot[2]) / (top[2] - foot[2])
    return foot + t * (top - foot)


def seat_surface(name: str, z: float, plan: sg.Polygon) -> Surface:
    """An upward support surface at height z with the (x, y) polygon `plan`."""
    return support_polygon(name, (0.0, 0.0, z), plan)


def shear_points(points: np.ndarray, z0: float, tilt_deg: float) -> np.ndarray:
    """`shear_back` applied to points (N, 3)."""
    pts = np.array(points, float).reshape(-1, 3)
    pts[:, 0] -= math.tan(math.radians(tilt_deg)) * (pts[:, 2] - z0)
    return pts


def bevel_points(extents: Sequence[float], center: Sequence[float], radius: float,
                 segments: int = 2) -> np.ndarray:
    """The points whose convex hull `shapes.primitives.bevel_box` is (the same formula), so that the
    bounding box of a transformed bevelled box is found without building it."""
    ext = np.asarray(extents, float)
    r = float(min(radius, 0.49 * ext.min()))
    signs = np.array([(sx, sy, sz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
    if r <= 1e-5:
        return np.asarray(center, float) + signs * ext / 2
    seg = max(1, segments)
    phi, th = np.meshgrid(np.arange(seg + 1) * (math.pi / 2) / seg, np.arange(seg + 1) * (math.pi / 2) / seg,
                          indexing="ij")
    dirs = np.unique(np.round(np.c_[(np.sin(phi) * np.cos(th)).ravel(), (np.sin(phi) * np.sin(th)).ravel(),
                                    np.cos(phi).ravel()], 12), axis=0)
    pts = signs[:, None, :] * ((ext / 2 - r)[None, None, :] + r * dirs[None, :, :])
    return pts.reshape(-1, 3) + np.asarray(center, float)


def soft_sheared(extents: Sequence[float], center: Sequence[float], radius: float, z0: float,
                 tilt_deg: float, detail: bool, segments: int = 2) -> m3d.Manifold:
    """A bevelled box leaning back by `tilt_deg` about z0 (an upholstered back), or for a
    placeholder the box around it (a sheared plain box would reach further than its rounded
    corners do, so its bounding box would not match)."""
    if detail:
        return shear_back(bevel_box(extents, center, radius, segments), z0, tilt_deg)
    return points_box(shear_points(bevel_points(extents, center, radius, segments), z0, tilt_deg), 0.0)


def shear_back(solid: m3d.Manifold, z0: float, tilt_deg: float) -> m3d.Manifold:
    """Lean `solid` backwards (-X) by `tilt_deg` about height z0 (a shear: horizontal sections
    keep their shape, so a placeholder box sheared alike still contains what it contained)."""
    if abs(tilt_deg) <= 1e-6:
        return solid
    k = math.tan(math.radians(tilt_deg))
    return solid.transform(np.array([[1.0, 0.0, -k, k * z0], [0.0, 1.0, 0.0, 0.0],
                                     [0.0, 0.0, 1.0, 0.0]]))


def aabb_box(solids: Iterable[m3d.Manifold]) -> m3d.Manifold:
    """One box covering the bounding boxes of `solids` (a placeholder piece)."""
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for s in solids:
        bb = np.asarray(s.bounding_box(), float)
        lo, hi = np.minimum(lo, bb[:3]), np.maximum(hi, bb[3:])
    return box_between(lo, hi)


def points_box(points: np.ndarray, pad: float) -> m3d.Manifold:
    """The box around `points` (N, 3) grown by `pad` on every side (a placeholder piece)."""
    pts = np.asarray(points, float)
    return box_between(pts.min(axis=0) - pad, pts.max(axis=0) + pad)
