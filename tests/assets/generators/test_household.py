"""Household objects: towels, folded clothes, baskets and storage boxes, every style, beyond
the generic contract in test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import (
    TOL,
    assert_clean_variant,
    assert_objects_tagged,
    build,
    choice_cases,
    surface_gap,
    variant,
)

HOUSEHOLD = ["towel", "folded_clothes", "basket", "storage_box"]
SEEDS = range(5)


@pytest.mark.parametrize("name,key,value", choice_cases(HOUSEHOLD))
def test_every_style_builds_one_clean_shell_per_link(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(HOUSEHOLD)
    assert {Semantics.Textile, Semantics.Towel} <= get_factory("towel").tags
    assert {Semantics.Container, Semantics.Basket} <= get_factory("basket").tags


@pytest.mark.parametrize("style", ["folded", "rolled"])
def test_towel_layers(style):
    for n in (1, 2, 3):
        _, p, a, _ = variant("towel", style=style, n_towels=n)
        assert a.mesh.body_count == 1
        if style == "folded":
            assert abs(a.extents[2] - n * p["n_layers"] * p["layer_thickness"] + (n - 1) * 0.001) < TOL
        else:
            # the roll's end lies flat: a flat patch of the mesh on the surface
            down = (a.mesh.face_normals[:, 2] < -0.99) & (a.mesh.triangles_center[:, 2] < 1e-6)
            assert a.mesh.area_faces[down].sum() > 0.5 * p["width"] * min(p["tail_length"], 0.02)
            # ... and the rolls are pressed flat under their centre of mass, which lies over
            # the flat patch at least 1 cm in from its edges (a roll held only by its end,
            # beside its centre, rolled off a vanity in MuJoCo and PyBullet)
            x = a.mesh.triangles[down][:, :, 0]
            com = a.mesh.center_mass[0]
            assert x.min() + 0.01 < com < x.max() - 0.01, (n, x.min(), com, x.max())


def test_folded_clothes_stack_height():
    for n in (1, 3, 5):
        _, p, a, _ = variant("folded_clothes", n_items=n, size_jitter=0.0, garment="tshirt",
                              mixed=False)
        h = n * p["item_thickness"] - (n - 1) * 0.001
        assert h - TOL < a.extents[2] < h + 0.006


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("basket", "storage_box") for s in SEEDS])
def test_container_interior_is_its_floor(name, seed):
    _, _, _, a = build(name, seed)
    inner = a.surfaces_of(Subpart.Interior)
    assert [s.name for s in inner] == ["interior_0"]
    s = inner[0]
    assert np.allclose(s.normal, (0, 0, 1)) and s.origin[2] < 0.05
    assert surface_gap(a, s) < TOL
    # open space above the floor: a point 3 cm up is not inside the solid
    c = s.to_world(np.array([s.polygon.representative_point().coords[0]]))[0]
    assert not a.mesh.contains([c + [0, 0, 0.03]])[0]


@pytest.mark.parametrize("lid", ["lift_off", "hinged"])
def test_storage_box_lid(lid):
    _, p, a, _ = variant("storage_box", lid_style=lid)
    (j,) = a.joints
    assert j.child == "lid"
    assert j.kind == ("prismatic" if lid == "lift_off" else "revolute")
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface and surface_gap(a, top) < TOL
    assert abs(a.link_mesh("lid").bounds[1, 2] - top.origin[2]) < 0.01
    opened = a.posed({j.name: j.upper})
    assert opened.bounds[1, 2] > a.mesh.bounds[1, 2] + 0.1
