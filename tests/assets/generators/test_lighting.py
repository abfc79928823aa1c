"""Lighting: lights that really emit, ceiling mounts, a tilting desk-lamp head, sconces on the
wall, beyond the generic contract in test_generators.py."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import TOL, build, make, slot_faces, surface_gap

LIGHTS = ["ceiling_light", "pendant_light", "desk_lamp", "wall_sconce", "table_lamp"]


def test_tags():
    for name in LIGHTS:
        assert Semantics.Lighting in get_factory(name).tags
    assert Semantics.WallMounted in get_factory("wall_sconce").tags
    for name in ("ceiling_light", "pendant_light"):
        assert Semantics.CeilingMounted in get_factory(name).tags


@pytest.mark.parametrize("name", LIGHTS)
@pytest.mark.parametrize("seed", range(8))
def test_lights_emit(name, seed):
    _, _, _, a = build(name, seed)
    faces = slot_faces(a, "emissive")
    assert len(faces) >= 8 and a.mesh.area_faces[faces].sum() > 1e-4


@pytest.mark.parametrize("name", ["ceiling_light", "pendant_light"])
@pytest.mark.parametrize("seed", range(10))
def test_ceiling_mounts(name, seed):
    _, _, _, a = build(name, seed)
    top = a.surface("top")
    assert top.subpart == Subpart.Top and np.allclose(top.normal, (0, 0, 1))
    assert abs(top.origin[2] - a.extents[2]) < TOL
    assert surface_gap(a, top) < TOL  # a flat canopy against the ceiling
    assert top.polygon.area >= math.pi * 0.035 ** 2


@pytest.mark.parametrize("style", ["dome", "drum", "panel", "spots", "chandelier"])
def test_ceiling_light_styles(style):
    f, p, a = make("ceiling_light", 2, style=style)
    top = a.surface("top")
    assert surface_gap(a, top) < TOL
    assert a.mesh.is_watertight and a.mesh.body_count == 1
    # the light comes out below the mounting: emissive faces are in the lower 90 %
    em = a.mesh.triangles_center[slot_faces(a, "emissive")]
    assert em[:, 2].min() < 0.9 * a.extents[2]


@pytest.mark.parametrize("shade", ["dome", "cone", "drum", "globe", "cage"])
def test_pendant_hangs_by_its_cord(shade):
    f, p, a = make("pendant_light", 0, shade=shade, drop=0.9)
    assert a.extents[2] > 0.9 + p["shade_height"] * 0.5
    # the cord is thin: a horizontal slice half way up the drop is smaller than 2 cm across
    z = a.extents[2] - 0.025 - 0.45
    section = a.mesh.section(plane_origin=(0, 0, z), plane_normal=(0, 0, 1))
    assert section is not None
    ext = section.bounds[1] - section.bounds[0]
    assert ext[:2].max() < 0.02


@pytest.mark.parametrize("seed", range(8))
def test_desk_lamp_head_tilts(seed):
    f, p, _, a = build("desk_lamp", seed)
    (j,) = a.joints
    assert j.kind == "revolute" and j.child == "head" and np.allclose(np.abs(j.axis), (0, 1, 0))
    head = a.link_mesh("head")
    em = np.isin(a.link_faces("head"), slot_faces(a, "emissive"))
    assert em.any()  # the bulb is in the head
    for q in (j.lower, j.upper):
        moved = trimesh.transform_points(head.vertices, j.transform(q))
        assert np.linalg.norm(moved - head.vertices, axis=1).max() > 0.05
    bottom = a.surface("bottom")
    assert surface_gap(a, bottom) < TOL


@pytest.mark.parametrize("seed", range(10))
def test_wall_sconce_back_on_wall(seed):
    _, p, _, a = build("wall_sconce", seed)
    back = a.surface("back")
    d = a.extents[0]
    assert np.allclose(back.normal, (-1, 0, 0)) and np.allclose(back.corners()[:, 0], -d / 2)
    assert surface_gap(a, back) < TOL
    # nothing but the plate touches the wall: the mesh within 1 cm of it is plate-sized
    near = a.mesh.vertices[a.mesh.vertices[:, 0] < -d / 2 + 0.01]
    assert np.ptp(near[:, 1]) <= p["plate_size"] + 1e-6 and np.ptp(near[:, 2]) <= p["plate_size"] + 1e-6


@pytest.mark.parametrize("seed", range(8))
def test_table_lamp_bulb_under_shade(seed):
    _, p, _, a = build("table_lamp", seed)
    em = a.mesh.triangles_center[slot_faces(a, "emissive")]
    r = np.linalg.norm(em[:, :2], axis=1)
    assert r.max() < p["shade_radius"] * 0.6  # the bulb is on the axis, inside the shade
    z_shade0 = p["base_height"] + p["neck_height"]
    assert em[:, 2].min() > z_shade0 - 0.06 and em[:, 2].max() < z_shade0 + p["shade_height"]
    assert surface_gap(a, a.surface("bottom")) < TOL
