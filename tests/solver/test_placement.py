"""Planes, degrees of freedom and pose snapping: a snapped child surface lies on its parent
plane, facing it; the DoF are what the planes leave free; relations hold only over the parent."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
import shapely.affinity
import shapely.geometry as sg

from indoorgen.assets import Surface
from indoorgen.constraints.relations import CONTACT_GAP
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import against_wall, hung_from, on_floor
from indoorgen.solver.placement import (
    SURFACE_GAP,
    free_region,
    headroom,
    placements_hold,
    planar,
    sample_point,
    snap_object,
    solve_pose,
)
from indoorgen.solver.state import Placement
from support.solverscene import ROOM, floor, make_state, put, top_of, wall


def _gap(state, name: str) -> list[float]:
    """Per placement: signed distance of the child surface from its parent plane, minus the
    relation's margin (0 when snapped, up to the contact gap), and the normals' dot product."""
    ob = state.objects[name]
    out = []
    for p in ob.placements:
        parent = state.surface_world(p.parent, p.parent_surface)
        child = state.surface_world(name, p.child_surface)
        d = float(np.dot(child.origin - parent.origin, parent.normal)) - planar(p.relation).margin
        out.append((d, float(np.dot(child.normal, parent.normal))))
    return out


def test_snapping_puts_each_child_surface_on_its_parent_plane_facing_it():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5), yaw=0.3)
    plate = put(st, "plate", top_of(table), (2.1, 1.4), yaw=1.0, stage="small")
    art = put(st, "wall_art", wall(1), (3.5, 1.0, 1.4), stage="medium")
    for name in (table, plate, art):
        for d, dot in _gap(st, name):
            assert d == pytest.approx(CONTACT_GAP, abs=1e-9)
            assert dot == pytest.approx(-1.0)


def test_floor_leaves_x_y_and_yaw_free():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5), yaw=0.7)
    ob = st.objects[table]
    res = solve_pose(st, ob.asset, ob.placements, ob.position + [0.3, -0.2, 0.5], 1.1)
    assert res is not None
    pos, yaw, dof = res
    np.testing.assert_allclose(pos, ob.position + [0.3, -0.2, 0.0], atol=1e-12)  # z snaps back
    assert yaw == 1.1 and dof.rotates
    np.testing.assert_allclose(dof.projection, np.diag([1.0, 1.0, 0.0]), atol=1e-12)


def test_floor_and_wall_leave_only_the_direction_along_the_wall():
    st = make_state()
    pl = [Placement(on_floor, ROOM, "bottom", "floor"), Placement(against_wall, ROOM, "back", "wall_0")]
    name = put(st, "bookcase", pl, (2.0, 1.0), yaw=2.0)
    ob = st.objects[name]
    pos, yaw, dof = solve_pose(st, ob.asset, ob.placements, ob.position, ob.yaw)
    assert not dof.rotates
    np.testing.assert_allclose(dof.projection, np.diag([1.0, 0.0, 0.0]), atol=1e-12)  # wall_0: y = 0
    np.testing.assert_allclose(st.front(name), [0.0, 1.0, 0.0], atol=1e-12)  # back to the wall
    assert [d for d, _ in _gap(st, name)] == pytest.approx([CONTACT_GAP, CONTACT_GAP], abs=1e-9)


def test_planes_that_cannot_hold_together_give_none():
    st = make_state()
    name = put(st, "bookcase", floor(), (2.0, 1.5))
    ob = st.objects[name]
    opposite = [Placement(against_wall, ROOM, "back", "wall_0"),
                Placement(against_wall, ROOM, "back", "wall_2")]
    assert solve_pose(st, ob.asset, opposite, ob.position, 0.0) is None
    upside_down = [Placement(on_floor, ROOM, "top", "floor")]  # the top facing down
    assert solve_pose(st, ob.asset, upside_down, ob.position, 0.0) is None


def test_no_placement_leaves_the_pose_free():
    st = make_state()
    name = put(st, "plate", floor(), (1.0, 1.0))
    ob = st.objects[name]
    pos, yaw, dof = solve_pose(st, ob.asset, [], np.array([0.5, 0.5, 0.5]), 0.2)
    np.testing.assert_array_equal(pos, [0.5, 0.5, 0.5])
    assert yaw == 0.2 and dof.rotates and (dof.projection == np.eye(3)).all()


def test_snap_object_is_solve_pose_with_the_objects_own_asset_and_planes():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5))
    ob = st.objects[table]
    guess = ob.position + [0.1, 0.1, 0.3]
    a = snap_object(st, table, guess, 0.4)
    b = solve_pose(st, ob.asset, ob.placements, guess, 0.4)
    np.testing.assert_array_equal(a[0], b[0])
    assert a[1] == b[1] and (a[2].projection == b[2].projection).all()


def test_placements_hold_only_over_the_parent_surface():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5))
    plate = put(st, "plate", top_of(table), (2.0, 1.5), stage="small")
    assert placements_hold(st, table) and placements_hold(st, plate)
    z = st.objects[plate].position[2]
    st.set_pose(plate, np.array([3.5, 1.5, z]), 0.0)  # in the plane of the top, off the table
    assert not placements_hold(st, plate)


def test_sample_point_lies_on_the_surface_inside_the_margin():
    st = make_state(4.0, 3.0)
    surface = st.surface_world(ROOM, "floor")
    rng = np.random.default_rng(3)
    pts = np.array([sample_point(surface, rng, margin=0.5) for _ in range(200)])
    np.testing.assert_allclose(pts[:, 2], 0.0, atol=1e-12)
    assert pts[:, 0].min() >= 0.5 - 1e-9 and pts[:, 0].max() <= 3.5 + 1e-9
    assert pts[:, 1].min() >= 0.5 - 1e-9 and pts[:, 1].max() <= 2.5 + 1e-9
    again = np.random.default_rng(3)
    np.testing.assert_array_equal(sample_point(surface, again, margin=0.5), pts[0])


def test_free_region_keeps_a_thing_wholly_on_the_surface_and_clear_of_its_neighbours():
    shelf = Surface.rect("shelf", Subpart.SupportSurface, (0, 0, 1), (0, 0, 1), (1, 0, 0), 0.3, 0.15)
    square = np.array([[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]])
    region = free_region(shelf, square, [])
    gap = SURFACE_GAP
    np.testing.assert_allclose(region.bounds, [-0.2 + gap, -0.05 + gap, 0.2 - gap, 0.05 - gap])
    # a book already standing on the right half: the thing's centre stays 0.1 m + gap left of it
    taken = np.array([[0.0, -0.15], [0.3, -0.15], [0.3, 0.15], [0.0, 0.15]])
    assert free_region(shelf, square, [taken]).bounds[2] == pytest.approx(-0.1 - gap)
    # deeper than the shelf, or no room left beside the neighbours: nowhere
    assert free_region(shelf, square * [1, 2], []).is_empty
    assert free_region(shelf, square, [taken, taken - [0.3, 0]]).is_empty


def test_headroom_is_the_height_under_the_shelf_above_and_unbounded_on_top():
    st = make_state()
    case = put(st, "bookcase", floor(), (2.0, 1.5))
    ob = st.objects[case]
    shelves = sorted((s for s in ob.asset.surfaces if s.subpart == Subpart.SupportSurface
                      and s.name != "top"), key=lambda s: s.origin[2])
    assert len(shelves) >= 2
    room = headroom(st, case, shelves[0].name)
    assert 0.1 < room <= shelves[1].origin[2] - shelves[0].origin[2]
    assert headroom(st, case, "top") == math.inf


def test_a_garment_hung_from_a_rail_turns_across_it_and_slides_along_it_only():
    st = make_state()
    wardrobe = put(st, "wardrobe", floor(), (2.0, 1.5), yaw=0.4, seed=1)
    rail = next(s.name for s in st.objects[wardrobe].asset.surfaces if s.subpart == Subpart.Rail)
    rail_w = st.surface_world(wardrobe, rail)
    garment = put(st, "hung_garment", [Placement(hung_from, wardrobe, "hook", rail)],
                  tuple(rail_w.origin[:2]), yaw=2.0, stage="small")
    ob = st.objects[garment]
    assert placements_hold(st, garment)
    assert [d for d, _ in _gap(st, garment)] == pytest.approx([CONTACT_GAP], abs=1e-9)
    # its front (and so its thin side) runs along the rail, its shoulders across it
    np.testing.assert_allclose(st.front(garment), rail_w.u, atol=1e-12)
    pos, yaw, dof = solve_pose(st, ob.asset, ob.placements, ob.position, ob.yaw + 1.0)
    assert not dof.rotates and yaw == pytest.approx(ob.yaw)
    # free to move in the rail's plane; the rail's narrow strip keeps it on the rail
    np.testing.assert_allclose(dof.projection @ rail_w.normal, 0.0, atol=1e-12)


def test_a_rectangle_s_free_region_is_the_general_erosion_and_grown_outlines_are_cut_out():
    """The free region of a rectangular surface, worked out directly, is the intersection of the
    surface moved back by each corner of the thing's box; outlines already standing there, grown
    by the box, are cut out of it (100 random cases, and a notched surface the general way)."""
    rng = np.random.default_rng(3)
    for _ in range(100):
        w, d = rng.uniform(0.2, 2.0, 2)
        rect = sg.box(-w / 2, -d / 2, w / 2, d / 2)
        foot = rng.uniform(-0.3, 0.3, (6, 2))
        taken = [rng.uniform(-w / 2, w / 2, 2) + rng.uniform(-0.1, 0.1, (5, 2))
                 for _ in range(int(rng.integers(0, 4)))]
        x0, y0 = foot.min(axis=0) - SURFACE_GAP
        x1, y1 = foot.max(axis=0) + SURFACE_GAP
        expected = rect
        for cx, cy in ((x0, y0), (x1, y0), (x1, y1), (x0, y1)):
            expected = expected.intersection(shapely.affinity.translate(rect, -cx, -cy))
        for o in taken:
            corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
            expected = expected.difference(sg.MultiPoint(
                (o[:, None, :] - corners[None]).reshape(-1, 2)).convex_hull)
        surface = Surface("top", Subpart.SupportSurface, np.zeros(3), np.array([0, 0, 1.0]),
                          np.array([1.0, 0, 0]), rect)
        got = free_region(surface, foot, taken)
        assert got.symmetric_difference(expected).area < 1e-12
    notched = sg.Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    surface = Surface("top", Subpart.SupportSurface, np.zeros(3), np.array([0, 0, 1.0]),
                      np.array([1.0, 0, 0]), notched)
    region = free_region(surface, np.array([[-0.2, -0.2], [0.2, 0.2]]), [])
    assert region.contains(sg.Point(1.6, 0.5)) and not region.contains(sg.Point(1.6, 1.5))
