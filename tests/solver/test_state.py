"""The solver state: adding, removing, posing and re-parenting objects keeps its indexes, its
cached geometry and the room's broadphase in step; door zones are solid; a saved scene rebuilds
the same state."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets import get_factory
from indoorgen.model.scene import Door, Pose, RelationInstance, Scene, SceneObject
from indoorgen.model.tags import Semantics as S
from indoorgen.solver.placement import solve_pose
from indoorgen.solver.state import ObjState, keep_out_prisms, state_from_scene
from support.solverscene import (
    ROOM,
    assert_consistent,
    floor,
    make_state,
    put,
    snapshot,
    top_of,
    wall,
)


def _furnished():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5))
    plate = put(st, "plate", top_of(table), (2.0, 1.5), stage="small")
    art = put(st, "wall_art", wall(0), (2.0, 0.0, 1.5), stage="medium")
    return st, table, plate, art


def test_add_registers_the_object_everywhere_and_remove_leaves_no_trace():
    st, table, plate, _ = _furnished()
    assert_consistent(st)
    before = (st.all_ids(), snapshot(st), {n: set(st.children(n)) for n in st.all_ids()},
              sorted(st.broadphase[ROOM]._pieces))
    cup = put(st, "cup", top_of(table), (1.8, 1.2), stage="small")
    assert cup in st.all_ids() and cup in st.members(ROOM, "small")
    assert st.children(table) == {plate, cup}
    assert_consistent(st)
    ob = st.remove(cup)
    assert ob.name == cup
    assert_consistent(st)
    after = (st.all_ids(), snapshot(st), {n: set(st.children(n)) for n in st.all_ids()},
             sorted(st.broadphase[ROOM]._pieces))
    assert after == before
    st.add(ob)  # the removed object goes back as it was
    assert_consistent(st)
    assert not st.collides(cup)


def test_members_are_per_room_and_stage_in_name_order():
    st = make_state()
    for name in ("b_table", "a_table"):
        put(st, "dining_table_rect", floor(), (1.0 if name == "a_table" else 3.0, 1.5), name=name)
    put(st, "wall_art", wall(1), (4.0, 1.5, 1.5), stage="medium", name="art")
    assert st.members(ROOM, "large") == ["a_table", "b_table"]
    assert st.members(ROOM, "medium") == ["art"]
    assert st.members(ROOM, "small") == []


def test_set_pose_moves_pieces_and_refreshes_cached_geometry():
    st, table, _, _ = _furnished()
    c0, fp0 = st.center(table), st.footprint(table)
    pos = st.objects[table].position + np.array([0.5, 0.2, 0.0])
    st.set_pose(table, pos, np.pi / 2)
    assert_consistent(st)
    np.testing.assert_allclose(st.center(table)[:2], c0[:2] + [0.5, 0.2], atol=0.1)
    assert not st.footprint(table).equals(fp0)
    np.testing.assert_allclose(st.front(table), [0.0, 1.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(st.side_axis(table), [-1.0, 0.0, 0.0], atol=1e-12)
    assert st.yaw(table) == pytest.approx(np.pi / 2)


def test_descendants_lists_what_rests_on_an_object_parents_first():
    st, table, plate, art = _furnished()
    cup = put(st, "cup", top_of(plate), (2.0, 1.5), stage="small")
    assert st.descendants(table) == [plate, cup]
    assert st.descendants(plate) == [cup]
    assert st.descendants(art) == []


def test_set_placements_keeps_the_children_index():
    st = make_state()
    t1 = put(st, "dining_table_rect", floor(), (1.0, 1.5))
    t2 = put(st, "dining_table_rect", floor(), (3.0, 1.5))
    plate = put(st, "plate", top_of(t1), (1.0, 1.5), stage="small")
    st.set_placements(plate, top_of(t2))
    assert st.children(t1) == set() and st.children(t2) == {plate}
    assert st.relations(plate) == [(top_of(t2)[0].relation, t2)]
    assert_consistent(st)


def test_set_asset_swaps_params_and_pieces_keeping_the_pose():
    st, table, _, _ = _furnished()
    ob = st.objects[table]
    pos, yaw = ob.position.copy(), ob.yaw
    size = st.extents(table)
    params = {**ob.params, "length": ob.params["length"] * 0.8}
    st.set_asset(table, params)
    assert st.objects[table].params == params
    assert st.extents(table).max() == pytest.approx(size.max() * 0.8, rel=0.05)
    np.testing.assert_array_equal(st.objects[table].position, pos)
    assert st.objects[table].yaw == yaw
    assert_consistent(st)


def test_collides_sees_other_objects_and_walls():
    st = make_state()
    a = put(st, "dining_table_rect", floor(), (2.0, 1.5))
    assert not st.collides(a)
    b = put(st, "dining_table_rect", floor(), (2.2, 1.6))  # overlapping the first
    assert st.collides(a) and st.collides(b)
    st.set_pose(b, np.array([0.1, 1.5, st.objects[b].position[2]]), 0.0)  # through wall_3 (x = 0)
    assert st.collides(b) and not st.collides(a)


def test_door_zones_are_solid():
    door = Door("door_0", 0, 2.0, 0.9)  # in wall_0 (y = 0), centred 2 m along it
    st = make_state(doors=(door,))
    inside = put(st, "dining_table_rect", floor(), (2.0, 1.0), yaw=np.pi / 2)  # long side along x
    assert st.collides(inside)
    st.set_pose(inside, np.array([2.0, 2.5, st.objects[inside].position[2]]), np.pi / 2)
    assert not st.collides(inside)


def test_keep_out_prisms_cover_the_zone_with_convex_pieces():
    square = sg.box(0, 0, 1, 1)
    (prism,) = keep_out_prisms(square, 0.5, 2.5)
    assert prism.is_convex and prism.volume == pytest.approx(2.0)
    ell = sg.Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    pieces = keep_out_prisms(ell, 0.0, 1.0)
    assert len(pieces) > 1 and all(p.is_convex for p in pieces)
    assert sum(p.volume for p in pieces) == pytest.approx(ell.area)
    assert keep_out_prisms(sg.Polygon(), 0.0, 1.0) == []


def test_object_view_of_a_room():
    st = make_state(4.0, 3.0)
    assert S.Room in st.tags(ROOM) and st.generator(ROOM) == "" and st.relations(ROOM) == []
    np.testing.assert_allclose(st.center(ROOM), [2.0, 1.5, 1.35])
    np.testing.assert_allclose(st.extents(ROOM), [4.0, 3.0, 2.7])
    assert st.footprint(ROOM).area == pytest.approx(12.0)
    assert st.floor_z(ROOM) == 0.0 and st.support_polygon(ROOM) is None


def test_support_polygon_is_the_parents_support_surface_only():
    st, table, plate, art = _furnished()
    top = st.support_polygon(plate)
    assert top is not None
    assert top.contains(sg.Point(st.objects[plate].position[:2]))
    assert st.support_polygon(table) is None  # on the room's floor
    assert st.support_polygon(art) is None


def test_state_from_scene_rebuilds_poses_and_relations():
    st, *_ = _furnished()
    sc = Scene(seed=0)
    for n, ob in st.objects.items():
        sc.add_object(SceneObject(
            n, ob.generator, ob.params, ob.seed, Pose(tuple(ob.position.tolist()), ob.yaw),
            sorted(map(str, ob.tags)), ob.room,
            [RelationInstance(repr(p.relation), p.parent, p.child_surface, p.parent_surface)
             for p in ob.placements], ob.stage))
    again = state_from_scene(sc, st.rooms, st.cache)
    assert snapshot(again) == snapshot(st)
    assert_consistent(again)
    assert not any(again.collides(n) for n in again.objects)


def _rough_object(st, generator: str, at: tuple[float, float], name: str, seed: int = 3) -> str:
    """Add a `generator` object as an add move does: with its trial placeholder, posed near
    `at` on the floor, not yet checked."""
    fac = get_factory(generator)
    params = fac.sample_params(np.random.default_rng(seed))
    asset, rough = st.cache.trial_placeholder(generator, params)
    st.add(ObjState(name, generator, params, seed, frozenset(fac.tags), ROOM, "large", asset,
                    floor(), np.zeros(3), 0.0, rough=rough))
    res = solve_pose(st, asset, floor(), np.array([*at, 0.0]), 0.0)
    assert res is not None
    st.set_pose(name, res[0], res[1])
    return name


def test_an_add_tries_poses_rough_and_a_clear_pose_gets_the_hollowed_placeholder():
    """A cupboard is tried with its body left solid (the same mesh, surfaces and joints, no
    detailed parts evaluated); once its pieces are clear it takes the placeholder, hollowed
    where things are put away, and is registered with the placeholder's pieces. One that
    collides stays rough (and an add then removes it)."""
    st = make_state(5.0, 4.0)
    name = _rough_object(st, "wardrobe", (2.5, 2.0), "wardrobe_0")
    ob = st.objects[name]
    full = st.cache.placeholder(ob.generator, ob.params)
    assert ob.rough and ob.asset is not full
    assert np.array_equal(ob.asset.mesh.vertices, full.mesh.vertices)
    assert [s.name for s in ob.asset.surfaces] == [s.name for s in full.surfaces]
    assert len(ob.asset.joints) == len(full.joints)
    # the rough body holds all of the hollowed one (it only lacks the hollows)
    rough_volume = sum(m.volume for _, m in ob.asset.collision)
    assert rough_volume > sum(m.volume for _, m in full.collision)
    assert not st.collides(name)
    assert not ob.rough and ob.asset is full
    assert len(ob.cobjs) >= len(st.cache.placeholder_convex(ob.generator, ob.params))
    assert_consistent(st)
    # a second wardrobe in the same spot collides and keeps its rough pieces
    other = _rough_object(st, "wardrobe", (2.5, 2.0), "wardrobe_1", seed=4)
    assert st.collides(other) and st.objects[other].rough


def test_a_generator_with_nothing_put_away_is_tried_with_its_placeholder():
    st = make_state()
    params = get_factory("dining_table_rect").sample_params(np.random.default_rng(0))
    asset, rough = st.cache.trial_placeholder("dining_table_rect", params)
    assert not rough and asset is st.cache.placeholder("dining_table_rect", params)
