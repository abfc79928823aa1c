"""Helpers for asset tests: cached builds, exact point-to-mesh distances, surfaces on the mesh,
faces by material slot, and the checks several generator families share."""
from __future__ import annotations

from functools import cache

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart

#: how close (m) a surface's points must lie to the mesh, and a built asset to its local frame
TOL = 1e-3


@cache
def build(name: str, seed: int):
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    return f, p, f.placeholder(p), f.create(p)


def make(name: str, seed: int = 0, **overrides):
    """A generator's params for `seed` with some overridden, and the detailed asset."""
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    p.update(overrides)
    return f, p, f.create(p)


def variant(name: str, **overrides):
    """`make` on seed 0, plus the placeholder of the same params."""
    f, p, a = make(name, 0, **overrides)
    return f, p, a, f.placeholder(p)


def distances(mesh: trimesh.Trimesh, pts: np.ndarray) -> np.ndarray:
    """Exact distance from each point to the mesh surface (brute force over nearby triangles)."""
    tris = mesh.triangles
    lo, hi = tris.min(axis=1), tris.max(axis=1)
    out = np.empty(len(pts))
    for i, q in enumerate(pts):
        near = np.all((lo <= q + 2e-3) & (hi >= q - 2e-3), axis=1)
        if not near.any():
            out[i] = np.inf
            continue
        t = tris[near]
        cp = trimesh.triangles.closest_point(t, np.repeat(q[None], len(t), axis=0))
        out[i] = np.linalg.norm(cp - q, axis=1).min()
    return out


def sample_polygon(poly: sg.Polygon) -> np.ndarray:
    """Deterministic points inside a polygon: a representative point, the centroid, points
    90% of the way to each vertex and a small grid."""
    c = np.asarray(poly.representative_point().coords[0])
    pts = [c, np.asarray(poly.centroid.coords[0])]
    verts = np.asarray(poly.exterior.coords)[:-1]
    step = max(1, len(verts) // 8)
    pts += [c + 0.9 * (v - c) for v in verts[::step]]
    x0, y0, x1, y1 = poly.bounds
    for a in (0.2, 0.5, 0.8):
        for b in (0.2, 0.5, 0.8):
            pts.append(np.array([x0 + a * (x1 - x0), y0 + b * (y1 - y0)]))
    return np.array([q for q in pts if poly.contains(sg.Point(q))])


def to_local(surface, pts3: np.ndarray) -> np.ndarray:
    d = pts3 - surface.origin
    return np.c_[d @ surface.u, d @ surface.v]




def part_signature(factory, params) -> tuple:
    """A cheap fingerprint of the detailed design of `params`: every piece's bounding box,
    volume, size, link and material slot, and every named surface (no booleans, so comparing
    many variants stays fast)."""
    p = factory.resolve(params)
    parts = factory.parts(p, True)
    pieces = tuple(sorted((tuple(np.round(q.solid.bounding_box(), 6)), round(q.solid.volume(), 10),
                           q.solid.num_tri(), q.link, q.slot) for q in parts))
    surfaces = tuple(sorted((s.name, tuple(np.round(s.origin, 6)), tuple(np.round(s.polygon.bounds, 6)))
                            for s in factory.extra_surfaces(p)))
    return pieces, surfaces


def param_values(prm) -> list:
    """The values a parameter is moved through: its range's ends, both booleans, every choice."""
    if prm.kind == "float":
        return [prm.low, (prm.low + prm.high) / 2, prm.high]
    if prm.kind == "int":
        return [int(prm.low), int(prm.high)]
    if prm.kind == "bool":
        return [False, True]
    return list(prm.choices)


def inert_params(factory, n_bases: int = 16) -> list[str]:
    """Parameters that never change the design (geometry, materials or surfaces), whatever the
    design around them:
    each is moved through its values on a few base designs (sampled ones, and the first of
    them with every number at its low and at its high end)."""
    bases = [factory.sample_params(np.random.default_rng(s)) for s in range(n_bases - 2)]
    for end in ("low", "high"):
        bases.append(dict(bases[0], **{k: (getattr(q, end) if q.kind == "float"
                                           else int(getattr(q, end)))
                                       for k, q in factory.params.items()
                                       if q.kind in ("float", "int")}))
    inert = []
    for k, prm in factory.params.items():
        if not any(len({part_signature(factory, dict(b, **{k: v}))
                        for v in param_values(prm)}) > 1 for b in bases):
            inert.append(k)
    return inert


def surface_gap(asset, surface) -> float:
    """Largest distance from the surface's sample points to the mesh."""
    pts = surface.to_world(sample_polygon(surface.polygon))
    assert len(pts) >= 3
    return float(distances(asset.mesh, pts).max())


def assert_on_mesh(asset, surface) -> None:
    """The surface lies on the mesh (within TOL)."""
    assert surface_gap(asset, surface) < TOL, surface.name


def support_surfaces(asset) -> dict:
    """The asset's support surfaces by name."""
    return {s.name: s for s in asset.surfaces if s.subpart == Subpart.SupportSurface}


def point_inside(asset, pts) -> np.ndarray:
    """Whether each point is inside the asset's mesh."""
    return asset.mesh.contains(np.atleast_2d(np.asarray(pts, float)))


def slot_faces(a, slot: str) -> np.ndarray:
    """Indices of the faces in material slot `slot` (none if the asset has no such slot)."""
    return np.nonzero(a.face_slots == a.slots.index(slot))[0] if slot in a.slots else np.zeros(0, int)


def slot_mesh(a, slot: str) -> trimesh.Trimesh:
    """The faces of one material slot as a mesh."""
    return a.mesh.submesh([slot_faces(a, slot)], append=True, repair=False)


def as_manifold(mesh: trimesh.Trimesh) -> m3d.Manifold:
    """A closed trimesh as a manifold3d solid (for exact boolean checks)."""
    return m3d.Manifold(m3d.Mesh(vert_properties=np.asarray(mesh.vertices, np.float32),
                                 tri_verts=np.asarray(mesh.faces, np.uint32)))


def assert_furniture_tags(name: str, must: set, must_not: set) -> None:
    """A large piece of furniture tagged with all of `must` and none of `must_not`."""
    f = get_factory(name)
    assert {Semantics.Object, Semantics.Furniture} | must <= f.tags
    assert not (must_not & f.tags)
    assert f.size_class == "large"


def assert_objects_tagged(names) -> None:
    """Each generator is an Object, and a small one a SmallObject."""
    for name in names:
        f = get_factory(name)
        assert Semantics.Object in f.tags
        if f.size_class == "small":
            assert Semantics.SmallObject in f.tags, name


def choice_cases(names) -> list[tuple]:
    """(generator, param, value) for every choice and both values of every flag of `names`:
    random seeds need not reach every style."""
    out = []
    for name in names:
        f = get_factory(name)
        for k, prm in sorted(f.params.items()):
            if prm.kind == "choice":
                out += [(name, k, c) for c in prm.choices]
            elif prm.kind == "bool":
                out += [(name, k, True), (name, k, False)]
    return out


def assert_clean_variant(name: str, key: str, value) -> None:
    """The seed-0 design with `key` set to `value`: one watertight shell per link, within the
    triangle budget, the placeholder on its bounds, in the local frame."""
    f, p, a, ph = variant(name, **{key: value})
    m = a.mesh
    assert m.is_watertight and m.is_winding_consistent and m.volume > 0
    assert m.body_count == len(a.links)
    limit = 30000 if f.size_class == "large" else 5000 if f.size_class == "small" else 20000
    assert len(m.faces) <= limit
    assert np.abs(ph.mesh.bounds - m.bounds).max() <= 0.02
    assert abs(m.bounds[0, 2]) < TOL and np.all(np.abs(m.bounds[:, :2].sum(axis=0)) < 2 * TOL)
