"""Keep-free volumes: sweeps reach where moving parts open to, use zones are where the guidelines
put them, and the broadphase collides them only with what they must keep out."""
from __future__ import annotations

import fcl
import numpy as np
import trimesh

from indoorgen.assets.cache import convex_shape, mesh_bvh
from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics as S
from indoorgen.solver.broadphase import (
    DOOR_ZONE,
    PIECE_SOLID,
    PIECE_SWEEP,
    PIECE_ZONE,
    SOLID,
    WINDOW_ZONE,
    YIELD_ALL,
    YIELD_NONE,
    YIELD_UNDER,
    YIELD_ZONES,
    Broadphase,
    world_boxes,
)
from indoorgen.solver.keep_free import (
    FRONT_CLEAR,
    FRONT_CLEAR_WIDE,
    TOILET_FRONT,
    TOILET_SIDE,
    WINDOW_DEPTH,
    hull_solid,
    keep_free_volumes,
    open_limit,
    sweep_volumes,
    use_zones,
    window_volume,
    window_zone,
)


def _asset(name: str, seed: int = 0):
    fac = get_factory(name)
    params = fac.sample_params(np.random.default_rng(seed))
    return fac, params, fac.placeholder(params)


def test_a_dressers_drawers_sweep_out_before_its_front_as_far_as_they_open():
    fac, params, asset = _asset("dresser", 3)
    lo, hi = asset.mesh.bounds
    sweeps = sweep_volumes(asset.joints, fac.link_boxes(params))
    assert len(sweeps) == len(asset.joints) > 0
    for j, pts in zip(asset.joints, sweeps, strict=True):
        assert j.kind == "prismatic"
        # an open drawer reaches its travel beyond the front, and stays within the width
        assert pts[:, 0].max() >= hi[0] + 0.8 * open_limit(j)
        assert pts[:, 1].min() >= lo[1] - 1e-6 and pts[:, 1].max() <= hi[1] + 1e-6


def test_a_fridge_door_swings_out_in_front_and_past_its_hinge_side():
    fac, params, asset = _asset("fridge", 1)
    lo, hi = asset.mesh.bounds
    sweeps = sweep_volumes(asset.joints, fac.link_boxes(params))
    doors = [pts for j, pts in zip(asset.joints, sweeps, strict=True) if j.kind == "revolute"]
    assert doors
    for pts in doors:
        assert pts[:, 0].max() > hi[0] + 0.3  # the door stands out before the fridge


def test_a_swivel_spins_in_place_and_sweeps_nothing():
    fac, params, asset = _asset("office_chair", 0)
    assert asset.joints
    assert sweep_volumes(asset.joints, fac.link_boxes(params)) == []


def test_a_toilets_clear_space_follows_the_guideline():
    bounds = np.array([[-0.35, -0.2, 0.0], [0.35, 0.2, 0.75]])
    (zone,) = use_zones(frozenset({S.Toilet}), bounds, "large")
    lo, hi = zone.min(axis=0), zone.max(axis=0)
    assert lo[1] <= -TOILET_SIDE and hi[1] >= TOILET_SIDE  # either side of the centreline
    assert hi[0] >= 0.35 + TOILET_FRONT                      # before it
    assert lo[0] > -0.35                                     # not into the wall behind
    assert use_zones(frozenset({S.Sofa}), bounds, "large") == []


def test_a_ranges_front_is_kept_clear_for_its_door():
    bounds = np.array([[-0.3, -0.38, 0.0], [0.3, 0.38, 0.95]])
    (zone,) = use_zones(frozenset({S.Range, S.Appliance}), bounds, "large")
    assert zone[:, 0].min() >= 0.3 - 1e-9 and zone[:, 0].max() >= 0.3 + FRONT_CLEAR_WIDE
    (zone,) = use_zones(frozenset({S.Storage, S.Bookcase}), bounds, "large")
    assert zone[:, 0].max() >= 0.3 + FRONT_CLEAR and zone[:, 0].max() < 0.3 + FRONT_CLEAR_WIDE
    assert use_zones(frozenset({S.Storage, S.Box}), bounds, "large") == []
    assert use_zones(frozenset({S.Appliance, S.Microwave}), bounds, "medium") == []


def test_keep_free_volumes_are_solids_with_their_boxes():
    fac, params, asset = _asset("countertop_run", 2)
    shapes, boxes, kinds = keep_free_volumes(asset, fac.tags, fac.size_class,
                                             fac.link_boxes(params))
    assert len(shapes) == len(boxes) == 2  # the fronts' sweeps (one hull) and the clear front
    assert list(kinds) == [PIECE_SWEEP, PIECE_ZONE]
    for s, b in zip(shapes, boxes, strict=True):
        inside = fcl.CollisionObject(fcl.Sphere(0.001), fcl.Transform((b[0] + b[1]) / 2))
        assert fcl.collide(fcl.CollisionObject(s, fcl.Transform()), inside,
                           fcl.CollisionRequest(), fcl.CollisionResult()) > 0


def test_hull_solid_is_the_hull():
    rng = np.random.default_rng(0)
    pts = rng.uniform(-1, 1, (40, 3))
    solid = fcl.CollisionObject(hull_solid(pts), fcl.Transform())
    hull = trimesh.convex.convex_hull(pts)
    for q in rng.uniform(-1.2, 1.2, (60, 3)):
        probe = fcl.CollisionObject(fcl.Sphere(1e-4), fcl.Transform(q))
        hit = fcl.collide(solid, probe, fcl.CollisionRequest(), fcl.CollisionResult()) > 0
        d = float(trimesh.proximity.signed_distance(hull, q[None])[0])
        if abs(d) > 1e-3:
            assert hit == (d > 0)


def test_a_window_zone_reaches_into_the_room_at_the_windows_height():
    bounds = np.array([[1.0, -0.1, 0.9], [2.2, 0.1, 2.1]])
    zone, axis = window_zone(bounds)
    assert axis == 0 and zone.bounds == (1.0, -0.1 - WINDOW_DEPTH, 2.2, 0.1 + WINDOW_DEPTH)
    vol = window_volume(bounds)
    assert np.allclose(vol.bounds[:, 2], [0.9, 2.1])


def _box(size, at) -> tuple[list[fcl.CollisionObject], np.ndarray]:
    m = trimesh.creation.box(size)
    shape = convex_shape(m)
    obj = fcl.CollisionObject(shape, fcl.Transform(np.eye(3), np.asarray(at, float)))
    return [obj], world_boxes(np.array([m.bounds]), np.eye(3), np.asarray(at, float))


def _with_free(solid_at, free_at, kind=PIECE_SWEEP):
    a, ab = _box([0.5, 0.5, 0.5], solid_at)
    f, fb = _box([0.5, 0.5, 0.5], free_at)
    return a + f, np.vstack([ab, fb]), np.array([PIECE_SOLID, kind])


def test_keep_free_pieces_meet_walls_and_unrelated_solids_only():
    wall = trimesh.creation.box([0.2, 4.0, 2.5])
    wall.apply_translation([3.0, 0.0, 1.25])
    window = trimesh.creation.box([0.6, 1.0, 1.0])
    window.apply_translation([-3.0, 0.0, 1.5])
    bp = Broadphase([fcl.CollisionObject(mesh_bvh(wall), fcl.Transform()),
                     fcl.CollisionObject(convex_shape(window), fcl.Transform())],
                    np.array([np.ravel(wall.bounds), np.ravel(window.bounds)]),
                    np.array([SOLID, WINDOW_ZONE]))
    # a cabinet whose drawers' sweep reaches into the wall collides; moved back, it does not
    pieces, boxes, free = _with_free([2.0, 0, 0.5], [2.8, 0, 0.5])
    bp.add("cabinet", pieces, boxes, free)
    assert bp.collides("cabinet")
    # two sweeps may overlap (two cabinets opening into one aisle)
    pieces2, boxes2, free2 = _with_free([0.0, 0, 0.5], [1.0, 0, 0.5])
    bp.add("other", pieces2, boxes2, free2)
    bp.remove("cabinet")
    pieces, boxes, free = _with_free([2.0, 1.5, 0.5], [1.0, 0.3, 0.5])
    bp.add("cabinet", pieces, boxes, free)
    assert not bp.collides("cabinet") and not bp.collides("other")
    # a solid in a sweep collides, from either side, unless the sweep's owner carries it
    vase, vb = _box([0.2, 0.2, 0.2], [1.0, 0.0, 0.5])
    bp.add("vase", vase, vb)
    assert bp.collides("vase") and bp.collides("other")
    assert not bp.collides("vase", carries=lambda a, b: b == "vase")
    assert not bp.collides("other", carries=lambda a, b: (a, b) == ("other", "vase"))
    assert bp.collides("other", carries=lambda a, b: (a, b) == ("vase", "other"))
    bp.remove("vase")
    # a cup may stand in a front's clear zone, not in a door's sweep; a rug lies in either
    zoned, zb, zk = _with_free([0.0, -1.5, 0.5], [1.0, -1.5, 0.5], PIECE_ZONE)
    bp.add("cabinet2", zoned, zb, zk)
    for at, yields, hit in (([1.0, -1.5, 0.5], YIELD_ZONES, False), ([1.0, 0.0, 0.5], YIELD_ZONES, True),
                            ([1.0, 0.0, 0.5], YIELD_ALL, False), ([1.0, -1.5, 0.5], YIELD_NONE, True)):
        cup, cb = _box([0.1, 0.1, 0.1], at)
        bp.add("cup", cup, cb, yields=yields)
        assert bp.collides("cup") == hit and bp.collides("cabinet2") == (hit and at[1] < -1)
        bp.remove("cup")
    # a window zone keeps out only what the window rule names
    tall, tb = _box([0.4, 0.4, 2.0], [-3.0, 0.0, 1.0])
    bp.add("wardrobe", tall, tb)
    assert not bp.collides("wardrobe") and bp.collides("wardrobe", windows=True)


def test_furniture_stands_on_a_rug_and_a_door_swings_over_it():
    """A rug lies under a sofa's legs and in a door's zone, but not in a wall or on another rug."""
    wall = trimesh.creation.box([0.2, 4.0, 2.5])
    wall.apply_translation([3.0, 0.0, 1.25])
    door = trimesh.creation.box([1.0, 1.0, 2.0])
    door.apply_translation([-2.0, 0.0, 1.0])
    bp = Broadphase([fcl.CollisionObject(mesh_bvh(wall), fcl.Transform()),
                     fcl.CollisionObject(convex_shape(door), fcl.Transform())],
                    np.array([np.ravel(wall.bounds), np.ravel(door.bounds)]),
                    np.array([SOLID, DOOR_ZONE]))
    rug, rb = _box([2.0, 1.5, 0.01], [0.0, 0.0, 0.005])
    bp.add("rug", rug, rb, yields=YIELD_UNDER)
    sofa, sb = _box([0.9, 2.0, 0.8], [0.3, 0.0, 0.4])
    bp.add("sofa", sofa, sb)
    assert not bp.collides("rug") and not bp.collides("sofa")
    other, ob = _box([1.0, 1.0, 0.01], [0.9, 0.0, 0.005])
    bp.add("other rug", other, ob, yields=YIELD_UNDER)
    assert bp.collides("rug") and bp.collides("other rug") and not bp.collides("sofa")
    bp.remove("other rug")
    for at, hit in (([-2.0, 0.0, 0.005], False), ([2.9, 0.0, 0.005], True)):
        bp.remove("rug")
        rug, rb = _box([1.0, 1.0, 0.01], at)
        bp.add("rug", rug, rb, yields=YIELD_UNDER)
        assert bp.collides("rug") == hit
