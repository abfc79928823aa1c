"""Decor's shared shape helpers. Flat outlines in the wall plane are `CrossSection`s in (y, z)
extruded along X (`wall_outline`, `yz_extrude`) with a `back_surface` where they meet the wall;
`framed_picture` is a picture in its frame (wall art, standing photo frames); `bbox_part` is the
one-box placeholder of a small, intricate object."""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.protocol import Surface
from indoorgen.assets.shapes.frames import frame
from indoorgen.assets.shapes.outlines import ccw
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.model.tags import Subpart


def cross_section(pts: np.ndarray) -> m3d.CrossSection:
    """A cross-section from one simple polygon (any orientation)."""
    return m3d.CrossSection([ccw(pts)], m3d.FillRule.Positive)


def circle_points(r: float, n: int, center: tuple[float, float] = (0.0, 0.0),
                  circumscribed: bool = False) -> np.ndarray:
    """An n-gon on a circle (a vertex on +x), or circumscribed about it (flats on the axes)."""
    a = np.arange(n) * 2 * math.pi / n
    if circumscribed:
        a = a + math.pi / n
        r = r / math.cos(math.pi / n)
    return np.c_[center[0] + r * np.cos(a), center[1] + r * np.sin(a)]


def yz_extrude(cs: m3d.CrossSection, x0: float, x1: float) -> m3d.Manifold:
    """Extrude a cross-section drawn in the wall plane (its x = our y, its y = our z) from
    x0 to x1 along X."""
    m = m3d.Manifold.extrude(cs, x1 - x0)
    return m.transform(np.array([[0.0, 0.0, 1.0, x0], [1.0, 0.0, 0.0, 0.0],
                                 [0.0, 1.0, 0.0, 0.0]]))


def back_surface(poly_yz: sg.Polygon, x: float) -> Surface:
    """A `back` surface (normal -X) at x whose outline is `poly_yz` in (y, z) coordinates
    (the surface's v axis is -Z, so z is mirrored)."""
    pts = np.asarray(poly_yz.exterior.coords)[:-1]
    return Surface("back", Subpart.Back, np.array([x, 0.0, 0.0]), np.array([-1.0, 0.0, 0.0]),
                   np.array([0.0, 1.0, 0.0]), sg.Polygon(np.c_[pts[:, 0], -pts[:, 1]]))


def wall_outline(shape: str, width: float, height: float, n: int = 64,
             circumscribed: bool = False) -> m3d.CrossSection:
    """A wall-plane outline standing on z=0: "rect", "round" (diameter = width) or "arched"
    (a rectangle topped by a half disc as wide as it)."""
    if shape == "round":
        return cross_section(circle_points(width / 2, n, (0.0, width / 2), circumscribed))
    if shape == "arched":
        r = width / 2
        body = m3d.CrossSection.square((width, max(height - r, 0.01)), False).translate((-r, 0.0))
        top = cross_section(circle_points(r, n, (0.0, max(height - r, 0.01)), circumscribed))
        return body + top
    return m3d.CrossSection.square((width, height), False).translate((-width / 2, 0.0))


def bbox_part(parts: list[Part], slot: str) -> Part:
    """One box spanning the bounding box of `parts` (a placeholder for small, intricate
    objects: exact bounds, contains everything)."""
    bbs = np.array([q.solid.bounding_box() for q in parts])
    return Part(box_between(bbs[:, :3].min(axis=0), bbs[:, 3:].max(axis=0)), slot)


def framed_picture(W: float, H: float, D: float, frame_width: float, mat_width: float,
                   recess: float, detail: bool) -> list[Part]:
    """A picture W (Y) by H (Z) standing on z=0, D deep along X and facing +X: a backing board
    at the back, the frame ring, an optional mat and the print recessed by `recess` behind the
    frame's front (placeholder: the backing and one block). Slots: backing, frame, mat, canvas."""
    fw = min(frame_width, 0.2 * min(W, H))
    bk = 0.004
    out = [Part(box_between((-D / 2, -W / 2, 0.0), (-D / 2 + bk, W / 2, H)), "backing")]
    if not detail:
        out.append(Part(box_between((-D / 2 + bk - OVERLAP, -W / 2, 0.0), (D / 2, W / 2, H)), "frame"))
        return out
    out.append(Part(frame(W, H, fw, D - bk + OVERLAP, (bk / 2 - OVERLAP / 2, 0, H / 2)), "frame"))
    xf = D / 2 - recess  # picture front
    mw = min(mat_width, 0.25 * min(W, H) - fw)
    iw, ih = W - 2 * fw + 2 * OVERLAP, H - 2 * fw + 2 * OVERLAP
    if mw > 0.005:
        out.append(Part(frame(iw, ih, mw + OVERLAP, xf + 0.001 - (-D / 2 + bk - OVERLAP),
                              ((xf + 0.001 + (-D / 2 + bk - OVERLAP)) / 2, 0, H / 2)), "mat"))
        iw, ih = iw - 2 * mw, ih - 2 * mw
    out.append(Part(box_between((-D / 2 + bk - OVERLAP, -iw / 2, H / 2 - ih / 2),
                                (xf, iw / 2, H / 2 + ih / 2)), "canvas"))
    return out
