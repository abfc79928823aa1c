"""The solid-building steps every piece of architecture shares: prisms over 2D outlines and
shapely regions, boolean cuts, and the conversion of manifold3d solids to trimesh meshes.

manifold3d guarantees watertight results for extrusions and booleans; meshes keep float64
vertices so faces built on a room polygon stay exactly on it.
"""
from __future__ import annotations

from typing import Any

import manifold3d
import numpy as np
import numpy.typing as npt
import shapely.geometry as sg
import trimesh
from shapely.geometry.polygon import orient

from indoorgen.errors import InvalidGeometryError
from indoorgen.model.polygons import signed_area


def to_trimesh(m: manifold3d.Manifold) -> trimesh.Trimesh:
    """Convert a manifold3d solid to a trimesh (float64 vertices, so faces built on the room
    polygon stay exactly on it)."""
    mesh = m.to_mesh64() if hasattr(m, "to_mesh64") else m.to_mesh()
    return trimesh.Trimesh(np.asarray(mesh.vert_properties[:, :3], float),
                           np.asarray(mesh.tri_verts, np.int64), process=True)


def extrude_outline(outline: npt.ArrayLike, z0: float, z1: float) -> manifold3d.Manifold:
    """A prism over the 2D `outline` (N, 2, any orientation) from z0 to z1."""
    pts = np.asarray(outline, float)
    if signed_area(pts) < 0:
        pts = pts[::-1]
    cs = manifold3d.CrossSection([np.ascontiguousarray(pts)])
    return manifold3d.Manifold.extrude(cs, z1 - z0).translate([0.0, 0.0, z0])


def _rings(poly: Any) -> list[np.ndarray]:
    """The counter-clockwise outer ring and the holes of every polygon in `poly` (N, 2)."""
    out = []
    for p in getattr(poly, "geoms", [poly]):
        if not isinstance(p, sg.Polygon) or p.is_empty:
            continue
        p = orient(p, 1.0)
        out.append(np.ascontiguousarray(np.asarray(p.exterior.coords)[:-1, :2]))
        out += [np.ascontiguousarray(np.asarray(h.coords)[:-1, :2]) for h in p.interiors]
    return out


def extrude_region(poly: Any, z0: float, z1: float) -> manifold3d.Manifold:
    """A prism over a shapely (multi)polygon, holes included, from z0 to z1."""
    rings = _rings(poly)
    if not rings:
        return manifold3d.Manifold()
    cs = manifold3d.CrossSection(rings, manifold3d.FillRule.Positive)
    return manifold3d.Manifold.extrude(cs, z1 - z0).translate([0.0, 0.0, z0])


def subtract(solid: manifold3d.Manifold, cutters: list[manifold3d.Manifold]
             ) -> manifold3d.Manifold:
    """`solid` minus every one of `cutters` (one batched boolean)."""
    if not cutters:
        return solid
    return manifold3d.Manifold.batch_boolean([solid, *cutters], manifold3d.OpType.Subtract)


def checked_mesh(m: manifold3d.Manifold, what: str) -> trimesh.Trimesh:
    """`m` as a trimesh, or InvalidGeometryError naming `what` if its boolean failed."""
    if m.status() != manifold3d.Error.NoError:
        raise InvalidGeometryError(f"{what}: solid boolean failed ({m.status()})")
    return to_trimesh(m)
