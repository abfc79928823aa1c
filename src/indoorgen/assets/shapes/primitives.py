"""Solid building blocks as manifold3d Manifolds (boxes, bevelled and tapered boxes, rounded
slabs, cylinders, rods, lathed profiles, tori, panels), the `Part` that tags one with its material
slot and link, circle and rounded-rectangle polygons, and the overlap touching pieces share.

Round things come in two flavours: `circumscribed=False` (the default, for detailed meshes) puts
polygon vertices on the true circle, with one on each of +-X and +-Y when `sections` is a multiple
of 4, so the bounding box is exact; `circumscribed=True` (for placeholders) scales the polygon
out by 1/cos(pi/n) and turns it half a step so that its edge midpoints touch the circle on the
axes: the low-poly solid contains the true circle and still has the exact bounding box.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

#: a point or size in 3D: a tuple, a list or a numpy array of three floats
Vec3 = Sequence[float] | np.ndarray

#: how far touching pieces of one link interpenetrate, so that their union is one closed shell (m)
OVERLAP = 0.002
#: the same for millimetre-scale details of small objects (books, clocks, towels, laptops) (m)
SMALL_OVERLAP = 0.001


@dataclass(frozen=True)
class Part:
    """One solid piece of an asset, the name of its material slot ("wood", "metal"...) and the
    link it belongs to: "base" for the fixed body, another name for a part that moves on a joint
    (a door leaf, a drawer). Parts of one link are unioned into one closed shell."""

    solid: m3d.Manifold
    slot: str
    link: str = "base"


def _round_sections(sections: int) -> int:
    """`sections` rounded up to a multiple of 4 (at least 4): a vertex on each of +-X and +-Y."""
    return max(4, int(math.ceil(sections / 4.0)) * 4)


# ----------------------------------------------------------------------------------- primitives
def box(extents: Vec3, center: Vec3 = (0.0, 0.0, 0.0)) -> m3d.Manifold:
    """An axis-aligned box of size `extents` (x, y, z) centred on `center`."""
    return m3d.Manifold.cube(tuple(float(e) for e in extents), True).translate(
        tuple(float(c) for c in center))


def box_between(lo: Vec3, hi: Vec3) -> m3d.Manifold:
    """An axis-aligned box spanning corner `lo` to corner `hi`."""
    a, b = np.asarray(lo, float), np.asarray(hi, float)
    return box(b - a, (a + b) / 2)


def board(lo: Vec3, hi: Vec3, slot: str = "wood", link: str = "base") -> Part:
    """A box part spanning corner `lo` to corner `hi` (a board, rail, post or placeholder)."""
    return Part(box_between(lo, hi), slot, link)


def _octant_dirs(segments: int) -> np.ndarray:
    """Unit directions covering the +++ octant of a sphere (including its three axis poles)."""
    out = []
    for i in range(segments + 1):
        phi = (math.pi / 2) * i / segments  # from +Z down to the equator
        for j in range(segments + 1):
            th = (math.pi / 2) * j / segments
            out.append((math.sin(phi) * math.cos(th), math.sin(phi) * math.sin(th), math.cos(phi)))
    return np.unique(np.round(np.array(out), 12), axis=0)


def bevel_box(extents: Vec3, center: Vec3 = (0.0, 0.0, 0.0), radius: float = 0.01,
              segments: int = 2) -> m3d.Manifold:
    """A box with every edge rounded by `radius` (segments=1 gives a chamfer), as the convex hull
    of eight corner sphere patches. Its bounding box is exactly `extents` (the rounding only
    removes material), so a plain `box` of the same size contains it (used by placeholders)."""
    ext = np.asarray(extents, float)
    r = float(min(radius, 0.49 * ext.min()))
    if r <= 1e-5:
        return box(ext, center)
    dirs = _octant_dirs(max(1, segments))
    pts = []
    inner = ext / 2 - r
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                s = np.array([sx, sy, sz], float)
                pts.append(inner * s + r * dirs * s)
    return m3d.Manifold.hull_points(np.vstack(pts)).translate(tuple(float(c) for c in center))


def tapered_box(bottom_xy: tuple[float, float], top_xy: tuple[float, float], z0: float, z1: float,
                center_xy: tuple[float, float] = (0.0, 0.0)) -> m3d.Manifold:
    """A square-section frustum (a tapered leg): bottom size `bottom_xy` at z0, top size `top_xy`
    at z1, centred on `center_xy`."""
    cx, cy = center_xy
    pts = []
    for (sx, sy), z in ((bottom_xy, z0), (top_xy, z1)):
        for a in (-0.5, 0.5):
            for b in (-0.5, 0.5):
                pts.append((cx + a * sx, cy + b * sy, z))
    return m3d.Manifold.hull_points(np.array(pts, float))


def rounded_slab(dx: float, dy: float, z0: float, z1: float, corner: float,
                 center: Sequence[float] = (0.0, 0.0), sections: int = 32) -> m3d.Manifold:
    """A slab dx (X) by dy (Y) from z0 to z1 whose plan has corners rounded by `corner` (half
    the smaller side: a stadium or a disc). Its bounding box is exact."""
    r = min(max(corner, 1e-4), 0.5 * min(dx, dy) - 1e-6)
    n = max(4, int(math.ceil(sections / 4.0)) * 4)
    a = 2 * np.pi * np.arange(n) / n
    circ = r * np.c_[np.cos(a), np.sin(a)]
    pts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            c = np.array([center[0] + sx * (dx / 2 - r), center[1] + sy * (dy / 2 - r)])
            for z in (z0, z1):
                pts.append(np.c_[c[0] + circ[:, 0], c[1] + circ[:, 1], np.full(n, z)])
    return m3d.Manifold.hull_points(np.vstack(pts))


def rounded_rect_section(d: float, w: float, r: float) -> m3d.CrossSection:
    """A d (X) by w (Y) rectangle centred on the origin, its corners rounded by `r` (at most
    0.45 of the smaller side), as a manifold cross-section to extrude (box walls, lids)."""
    if r < 1e-4:
        return m3d.CrossSection.square((d, w), True)
    r = min(r, 0.45 * min(d, w))
    return m3d.CrossSection.square((d - 2 * r, w - 2 * r), True).offset(r, m3d.JoinType.Round,
                                                                      2.0, 24)


def rounded_rect_polygon(dx: float, dy: float, corner: float, inset: float,
                         center: Sequence[float] = (0.0, 0.0)) -> sg.Polygon:
    """The plan of `rounded_slab(dx, dy, ..., corner)` shrunk by `inset`, as a shapely polygon
    (for support surfaces on rounded seats and tops)."""
    r = min(max(corner, 1e-4), 0.5 * min(dx, dy) - 1e-6)
    core = sg.box(center[0] - dx / 2 + r, center[1] - dy / 2 + r,
                  center[0] + dx / 2 - r, center[1] + dy / 2 - r)
    if r - inset > 1e-4:
        return core.buffer(r - inset, 16)
    return core.buffer(r - inset, 16, join_style=2)


def cylinder(radius: float, height: float, center: Vec3 = (0.0, 0.0, 0.0), sections: int = 32,
             radius_top: float | None = None, circumscribed: bool = False) -> m3d.Manifold:
    """A Z-axis cylinder (or cone frustum if `radius_top` is given) whose BOTTOM centre is
    `center`. See the module docstring for `circumscribed`."""
    n = _round_sections(sections)
    rt = radius if radius_top is None else radius_top
    k = 1.0 / math.cos(math.pi / n) if circumscribed else 1.0
    c = m3d.Manifold.cylinder(float(height), float(radius * k), float(rt * k), n)
    if circumscribed:
        c = c.rotate((0.0, 0.0, 180.0 / n))
    return c.translate(tuple(float(v) for v in center))


def rod(p0: Vec3, p1: Vec3, radius: float, sections: int = 12) -> m3d.Manifold:
    """A cylinder of `radius` from point p0 to point p1 (any direction)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = p1 - p0
    length = float(np.linalg.norm(d))
    c = m3d.Manifold.cylinder(length, float(radius), -1.0, _round_sections(sections))
    z = np.array([0.0, 0.0, 1.0])
    dn = d / length
    axis = np.cross(z, dn)
    s, cth = np.linalg.norm(axis), float(np.dot(z, dn))
    if s < 1e-12:
        rot = np.eye(3) if cth > 0 else np.diag([1.0, -1.0, -1.0])
    else:
        k = axis / s
        kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        rot = np.eye(3) + s * kx + (1 - cth) * kx @ kx
    mat = np.hstack([rot, p0[:, None]])
    return c.transform(mat)


def lathe(profile: Sequence[tuple[float, float]], sections: int = 48,
          circumscribed: bool = False) -> m3d.Manifold:
    """Revolve a closed 2D profile of (radius, z) points (counter-clockwise or not; radius >= 0)
    about the Z axis: cups, plates, vases and lamp shades. A profile that is a ring (not
    touching the axis) gives a tube; one with a notch gives a hollow vessel."""
    pts = np.asarray(profile, float)
    n = _round_sections(sections)
    if circumscribed:
        pts = pts * np.array([1.0 / math.cos(math.pi / n), 1.0])
    cs = m3d.CrossSection([pts], m3d.FillRule.Positive if _area(pts) > 0 else m3d.FillRule.Negative)
    out = m3d.Manifold.revolve(cs, n)
    if circumscribed:
        out = out.rotate((0.0, 0.0, 180.0 / n))
    return out


def _area(pts: np.ndarray) -> float:
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def torus(major: float, minor: float, center: Vec3 = (0.0, 0.0, 0.0), sections: int = 32,
          tube_sections: int = 12) -> m3d.Manifold:
    """A torus in the XY plane around `center` (rotate it for handles)."""
    cs = m3d.CrossSection.circle(float(minor), _round_sections(tube_sections)).translate(
        (float(major), 0.0))
    return m3d.Manifold.revolve(cs, _round_sections(sections)).translate(
        tuple(float(c) for c in center))


def panel(width: float, height: float, thickness: float, center: Vec3 = (0.0, 0.0, 0.0),
          normal_axis: str = "x") -> m3d.Manifold:
    """A thin board of `thickness` along `normal_axis` ("x", "y" or "z"); width runs along the
    next axis, height along the one after (x: width=Y, height=Z; y: width=X, height=Z;
    z: width=X, height=Y)."""
    ext = {"x": (thickness, width, height), "y": (width, thickness, height),
           "z": (width, height, thickness)}[normal_axis]
    return box(ext, center)


def circle_polygon(radius: float, sections: int = 32, center: tuple[float, float] = (0.0, 0.0)
                   ) -> sg.Polygon:
    """A shapely polygon inscribed in a circle (vertices on it, one on +X), so that it lies inside
    any mesh disc of the same radius built with a multiple of `sections` segments."""
    n = _round_sections(sections)
    a = np.arange(n) * 2 * math.pi / n
    return sg.Polygon(np.c_[center[0] + radius * np.cos(a), center[1] + radius * np.sin(a)])
