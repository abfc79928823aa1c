"""Checks shared by the generator family tests (tests/assets/generators/): surfaces on the mesh,
faces of a material slot, rays dropped onto an asset, and the checks several families run on
their interior shelves, wall backs and material choices."""
from __future__ import annotations

import math

import numpy as np
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.materials.base import material_names
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import distances, sample_polygon

TOL = 1e-3


def on_mesh(asset, surface) -> float:
    """Largest distance from points of a surface to the mesh."""
    pts = surface.to_world(sample_polygon(surface.polygon))
    assert len(pts) >= 3
    return float(distances(asset.mesh, pts).max())


def faces_of_slot(asset, slot: str) -> np.ndarray:
    """Indices of the faces of material `slot` (none if the asset has no such slot)."""
    if slot not in asset.slots:
        return np.zeros(0, int)
    return np.nonzero(asset.face_slots == asset.slots.index(slot))[0]


def first_hit_down(mesh: trimesh.Trimesh, x: float, y: float) -> float:
    """Height of the first surface a ray going straight down at (x, y) meets (-inf if none)."""
    top = mesh.bounds[1][2] + 0.1
    locs, _, _ = mesh.ray.intersects_location([[x, y, top]], [[0, 0, -1.0]])
    return float(locs[:, 2].max()) if len(locs) else -math.inf


def design_offset(factory, params) -> np.ndarray:
    """The translation from a generator's design frame to the asset frame."""
    return factory._layout(factory.resolve(params))[1]


def check_interior_shelves(asset, required: bool = True, min_area: float = 0.03) -> None:
    """Interior surfaces face up, lie inside the body and on a shelf, and are whole shelves (more
    than `min_area`); a wire rack's surface is the tops of its bars (a polygon with a hole per
    slot) across the whole rack, not one bar."""
    inner = asset.surfaces_of(Subpart.Interior)
    if required:
        assert inner, "no interior surfaces"
    lo, hi = asset.mesh.bounds
    for s in inner:
        assert np.allclose(s.normal, (0, 0, 1))
        c = s.corners()
        assert (c >= lo - TOL).all() and (c <= hi + TOL).all()
        assert on_mesh(asset, s) < TOL, s.name
        x0, y0, x1, y1 = s.polygon.bounds
        assert (x1 - x0) * (y1 - y0) > min_area
        if s.polygon.interiors:  # a rack: its bars cover a fair part of it
            assert s.polygon.area > 0.1 * (x1 - x0) * (y1 - y0)


def check_wall_back(asset, min_area: float = 0.0) -> None:
    """A wall-mounted asset's `back` faces the wall (-X), lies on the bounding box's back and on
    the mesh, and is larger than `min_area`."""
    back = asset.surface("back")
    assert back.subpart == Subpart.Back and np.allclose(back.normal, (-1, 0, 0))
    assert np.allclose(back.corners()[:, 0], asset.mesh.bounds[0][0], atol=TOL)
    assert on_mesh(asset, back) < TOL
    assert back.polygon.area > min_area


def check_open_inner_floor(asset) -> None:
    """A vessel's `interior` surface lies on its inner floor, above the underside, and a ray
    dropped into its mouth reaches it (the cavity is open, not sealed)."""
    body = asset.link_mesh("base")
    s = asset.surface("interior")
    assert s.subpart == Subpart.Interior and np.allclose(s.normal, (0, 0, 1))
    assert distances(body, s.to_world(sample_polygon(s.polygon))).max() < TOL
    assert 0.003 < s.origin[2] < 0.5 * asset.extents[2] + 0.02
    assert abs(first_hit_down(body, s.origin[0], s.origin[1]) - s.origin[2]) < TOL


def check_thin_walled(placeholder, asset) -> None:
    """Much less material than the solid of the same outline (the placeholder's hull): hollow."""
    base = asset.link_mesh("base")
    assert base.volume < 0.45 * placeholder.mesh.convex_hull.volume, base.volume


def check_small_objects(names) -> None:
    """The generators `names` make small objects: size class "small", tagged SmallObject."""
    for name in names:
        f = get_factory(name)
        assert f.size_class == "small" and Semantics.SmallObject in f.tags, name


def check_material_choices(names) -> None:
    """Every slot the generators `names` choose materials for is theirs, and every material
    they name exists."""
    known = set(material_names())
    for name in names:
        f = get_factory(name)
        for slot, choices in f.material_choices.items():
            assert slot in f.slots, (name, slot)
            assert set(choices) <= known, (name, set(choices) - known)
