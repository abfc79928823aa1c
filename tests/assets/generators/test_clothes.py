"""Clothes on hangers, beyond the generic contract in test_generators.py: every kind builds
clean, hangs from a wardrobe's rail without touching it, and collides only below the rail."""
from __future__ import annotations

import fcl
import numpy as np
import pytest

from indoorgen.assets.cache import mesh_bvh
from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.shapes.hanging import RAIL_HALF_WIDTH, RAIL_RADIUS
from indoorgen.constraints.relations import CONTACT_GAP
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import assert_clean_variant, assert_objects_tagged, choice_cases, variant

CLOTHES = ["hung_garment"]


@pytest.mark.parametrize("name,key,value", choice_cases(CLOTHES))
def test_every_kind_builds_one_clean_shell(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(CLOTHES)
    assert {Semantics.Textile, Semantics.Garment} <= get_factory("hung_garment").tags


@pytest.fixture(scope="module")
def wardrobe():
    """A hinged wardrobe's full asset and its first rail's surface."""
    f = get_factory("wardrobe")
    p = f.resolve(dict(f.sample_params(np.random.default_rng(0)), door_type="hinged"))
    a = f.create(p)
    return a, next(s for s in a.surfaces if s.subpart == Subpart.Rail)


@pytest.mark.parametrize("garment", ["shirt", "dress", "coat", "trousers"])
def test_hung_on_the_rail_it_touches_nothing_and_collides_only_below_it(wardrobe, garment):
    asset, rail = wardrobe
    _, _, g, cheap = variant("hung_garment", garment=garment, length=0.6)
    hook = g.surface("hook")
    np.testing.assert_allclose(hook.normal, [0, 0, -1])
    assert hook.origin[2] > g.mesh.bounds[1][2] - 0.02  # at the top
    yaw = float(np.arctan2(rail.u[1], rail.u[0]))  # turned across the rail
    box = fcl.CollisionObject(mesh_bvh(asset.mesh), fcl.Transform())
    for across in (-RAIL_HALF_WIDTH, RAIL_HALF_WIDTH):
        spot = rail.origin + across * rail.v + [0.0, 0.0, CONTACT_GAP]
        pos = spot - yaw_matrix(yaw) @ hook.origin
        hung = fcl.CollisionObject(mesh_bvh(g.mesh), fcl.Transform(yaw_matrix(yaw), pos))
        assert not fcl.collide(hung, box, fcl.CollisionRequest(), fcl.CollisionResult())
    # the hook is visual only: every collision piece is below the rail
    rail_bottom = hook.origin[2] - 2 * RAIL_RADIUS
    for a in (g, cheap):
        assert max(piece.bounds[1][2] for _, piece in a.collision) < rail_bottom
