"""Named surfaces a generator declares beyond its bounding box: support rectangles and polygons,
bottoms, side faces."""
from __future__ import annotations

import math

import numpy as np
import shapely.geometry as sg
from numpy.typing import ArrayLike

from indoorgen.assets.protocol import Surface
from indoorgen.model.tags import Subpart


# ------------------------------------------------------------------------- surface helpers
def support_rect(name: str, center: ArrayLike, half_x: float, half_y: float) -> Surface:
    """An upward (+Z) support surface: a rectangle +-half_x (X) by +-half_y (Y) about `center`."""
    return Surface.rect(name, Subpart.SupportSurface, center, (0, 0, 1), (1, 0, 0),
                        max(half_x, 0.005), max(half_y, 0.005))


def support_polygon(name: str, center: ArrayLike, polygon: sg.Polygon,
                    subpart: Subpart = Subpart.SupportSurface,
                    up: bool = True) -> Surface:
    """A horizontal surface with an arbitrary polygon in (x, y) about `center` (upward), or,
    with up=False, a downward one (a bottom: normal -Z, u = +X so v = -Y: y is mirrored)."""
    if up:
        return Surface(name, subpart, np.asarray(center, float), np.array([0.0, 0.0, 1.0]),
                       np.array([1.0, 0.0, 0.0]), polygon)
    mirrored = sg.Polygon([(x, -y) for x, y in polygon.exterior.coords])
    return Surface(name, subpart, np.asarray(center, float), np.array([0.0, 0.0, -1.0]),
                   np.array([1.0, 0.0, 0.0]), mirrored)


def bottom_rect(center: ArrayLike, half_x: float, half_y: float) -> Surface:
    """A `bottom` (normal -Z) rectangle about `center`: a footprint smaller than the bbox."""
    return Surface.rect("bottom", Subpart.Bottom, center, (0, 0, -1), (1, 0, 0), half_x, half_y)


def rect_side_surfaces(depth: float, width: float, height: float, z0: float = 0.0,
                       prefix: str = "side_") -> list[Surface]:
    """The four vertical bbox faces of a depth (X) x width (Y) box spanning z0..z0+height,
    all Subpart.Side, normals +X, -X, +Y, -Y (named side_0..side_3)."""
    d2, w2, hz = depth / 2, width / 2, z0 + height / 2
    return [
        Surface.rect(f"{prefix}0", Subpart.Side, (d2, 0, hz), (1, 0, 0), (0, 1, 0), w2, height / 2),
        Surface.rect(f"{prefix}1", Subpart.Side, (-d2, 0, hz), (-1, 0, 0), (0, 1, 0), w2, height / 2),
        Surface.rect(f"{prefix}2", Subpart.Side, (0, w2, hz), (0, 1, 0), (1, 0, 0), d2, height / 2),
        Surface.rect(f"{prefix}3", Subpart.Side, (0, -w2, hz), (0, -1, 0), (1, 0, 0), d2, height / 2),
    ]


def polygon_side_surfaces(radius: float, n: int, height: float) -> list[Surface]:
    """N vertical facets of the regular N-gon circumscribing a circle of `radius` about the Z
    axis (facet i's outward normal at angle 2*pi*i/N), each 2*r*tan(pi/N) wide and full height."""
    out = []
    half_w = radius * math.tan(math.pi / n)
    for i in range(n):
        a = 2 * math.pi * i / n
        nrm = (math.cos(a), math.sin(a), 0.0)
        u = (-math.sin(a), math.cos(a), 0.0)
        out.append(Surface.rect(f"side_{i}", Subpart.Side,
                                (radius * nrm[0], radius * nrm[1], height / 2), nrm, u,
                                half_w, height / 2))
    return out
