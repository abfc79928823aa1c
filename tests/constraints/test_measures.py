"""The DSL's geometric measures evaluated through the expression graph against hand-computed
values."""
import math

import pytest
import shapely.geometry as sg

from indoorgen.constraints import (
    accessibility_cost,
    angle_alignment_cost,
    area,
    center_of_support_distance,
    distance,
    facing_angle,
    focus_score,
    freespace_2d,
    front_clearance,
    height,
    min_distance,
    reflectional_asymmetry,
    rotational_asymmetry,
    scene,
    volume,
)
from indoorgen.errors import ConstraintError
from indoorgen.model.tags import Semantics as S
from support.dsl import dining_view, value
from support.fakeview import FakeView


def test_rotational_asymmetry_zero_for_even_chairs_and_grows_when_one_moves():
    chairs = scene()[S.Chair]
    assert value(dining_view(), rotational_asymmetry(chairs)) == pytest.approx(0.0, abs=1e-9)
    a = value(dining_view(0.3), rotational_asymmetry(chairs))
    b = value(dining_view(0.6), rotational_asymmetry(chairs))
    assert 0 < a < b


def test_chairs_face_table_alignment_and_focus():
    v = dining_view()
    chairs, table = scene()[S.Chair], scene()[S.DiningTable]
    assert value(v, angle_alignment_cost(chairs, table)) == pytest.approx(0.0, abs=1e-9)
    assert value(v, focus_score(chairs, table)) == pytest.approx(0.0, abs=1e-9)
    v.move("chair0", yaw=0.0)  # chair0 at +x side now faces away: cost (1 - cos 180)/2 = 1
    assert value(v, angle_alignment_cost(chairs, table)) == pytest.approx(1.0)
    assert value(v, focus_score(chairs, table)) == pytest.approx(1.0)


def test_accessibility_blocker_in_front_costs_more_than_to_the_side():
    def cost(pos):
        v = FakeView()
        v.add("tv", {S.TV}, (0, 0, 1.0), yaw=0.0, extents=(0.1, 1.2, 0.7))
        v.add("box", {S.Furniture}, pos, extents=(0.6, 0.6, 0.6))
        return value(v, accessibility_cost(scene()[S.TV], scene()[S.Furniture]))
    front = cost((2.05, 0.0, 1.0))
    side = cost((0.05 + 2 * math.cos(0.8), 2 * math.sin(0.8), 1.0))
    behind = cost((-2.0, 0.0, 1.0))
    diag = math.sqrt(3 * 0.36)
    # the TV's front plane is x = 0.05; blocker 2 m ahead: cost = 2 / 2^2 * diag
    assert front == pytest.approx(diag / 2)
    assert 0 < side < front
    assert behind == 0.0
    slow = FakeView()
    slow.add("tv", {S.TV}, (0, 0, 1.0), extents=(0.1, 1.2, 0.7))
    slow.add("box", {S.Furniture}, (2.05, 0.0, 1.0), extents=(0.6, 0.6, 0.6))
    assert value(slow, accessibility_cost(scene()[S.TV], scene()[S.Furniture], fast=False)) > front


def test_sizes_distances_and_support():
    v = FakeView()
    v.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    v.add("a", {S.Furniture}, (1, 1, 0.5), extents=(1, 2, 0.5))
    v.add("b", {S.Furniture}, (3, 1, 0.5), extents=(1, 1, 1))
    v.add("p", {S.Plate}, (1.2, 1.0, 0.76), extents=(0.2, 0.2, 0.02),
          support=sg.box(0.5, 0.0, 1.5, 2.0))
    f = scene()[S.Furniture]
    assert value(v, volume(f)) == pytest.approx(1.0 + 1.0)
    assert value(v, volume(f, dims=(0, 1))) == pytest.approx(2.0 + 1.0)
    assert value(v, area(f)) == pytest.approx(2 * 1 + 1 * 1)
    assert value(v, distance(f[S.Furniture].named("a"), scene().named("b"))) == pytest.approx(1.0)
    assert value(v, distance(scene().named("b"), scene()[S.Room])) == pytest.approx(0.5)
    assert value(v, min_distance(scene().named("a"), scene().named("b"))) == pytest.approx(1.0)
    assert value(v, freespace_2d(scene().named("a"), scene()[S.Plate])) == pytest.approx(2 - 0.04)
    assert value(v, center_of_support_distance(scene()[S.Plate])) == pytest.approx(0.2)
    assert value(v, height(scene().named("b"))) == pytest.approx(0.5)


def test_reflectional_asymmetry_of_nightstands():
    v = FakeView()
    v.add("bed", {S.Furniture}, (0, 0, 0.3), yaw=0.0, extents=(2, 1.6, 0.6))
    v.add("n1", {S.SideTable}, (-0.7, 1.1, 0.3), yaw=0.0, extents=(0.4, 0.4, 0.5))
    v.add("n2", {S.SideTable}, (-0.7, -1.1, 0.3), yaw=0.0, extents=(0.4, 0.4, 0.5))
    term = reflectional_asymmetry(scene()[S.SideTable], scene().named("bed"))
    assert value(v, term) == pytest.approx(0.0, abs=1e-9)
    v.move("n2", center=(0.2, -1.1, 0.3))
    assert value(v, term) > 0.0


def test_measure_functions_equal_the_set_methods():
    v = FakeView()
    v.add("a", {S.Furniture}, (1, 1, 0.5), extents=(1, 2, 0.5))
    v.add("b", {S.Furniture}, (3, 1, 0.5), extents=(1, 1, 1))
    f, a, b = scene()[S.Furniture], scene().named("a"), scene().named("b")
    assert value(v, f.volume()) == value(v, volume(f))
    assert value(v, f.area()) == value(v, area(f))
    assert value(v, a.distance(b)) == value(v, distance(a, b))
    assert value(v, a.min_distance(b)) == value(v, min_distance(a, b))


def test_center_distance_is_zero_only_when_centred():
    """Outline distance is 0 for any overlap; centre distance says how far off-centre it is."""
    v = FakeView()
    v.add("table", {S.Furniture}, (2.0, 1.5, 0.375), extents=(1.8, 0.9, 0.75))
    v.add("light", {S.Lighting}, (2.7, 1.5, 2.3), extents=(0.3, 0.3, 0.4))
    light, table = scene()[S.Lighting], scene()[S.Furniture]
    assert value(v, light.distance(table)) == pytest.approx(0.0)
    assert value(v, light.center_distance(table)) == pytest.approx(0.7)
    v.add("light2", {S.Lighting}, (2.0, 1.5, 2.3), extents=(0.3, 0.3, 0.4))
    assert value(v, light.center_distance(table)) == pytest.approx(0.0)


def test_front_distance_is_walked_between_the_fronts():
    """Two appliances on the walls of a corner: their fronts stand closer than their centres."""
    v = FakeView()
    v.add("range", {S.Range}, (1.0, 0.3, 0.45), yaw=math.pi / 2, extents=(0.6, 0.76, 0.9))
    v.add("fridge", {S.Fridge}, (0.35, 1.2, 0.9), extents=(0.7, 0.8, 1.8))
    cooker, fridge = scene()[S.Range], scene()[S.Fridge]
    assert value(v, fridge.center_distance(cooker)) == pytest.approx(math.hypot(0.65, 0.9))
    assert value(v, fridge.front_distance(cooker)) == pytest.approx(math.hypot(0.3, 0.6))


def _sofa_and_stand(stand_yaw: float, stand_pos=(4.0, 0.0, 0.3)) -> FakeView:
    v = FakeView()
    v.add("sofa", {S.Sofa}, (0, 0, 0.4), yaw=0.0, extents=(0.9, 2.0, 0.8))
    v.add("stand", {S.TVStand}, stand_pos, yaw=stand_yaw, extents=(0.4, 1.5, 0.5))
    return v


def test_facing_angle_is_the_angle_to_the_nearest_target_in_degrees():
    sofa, stand = scene()[S.Sofa], scene()[S.TVStand]
    v = _sofa_and_stand(math.pi)
    assert value(v, facing_angle(sofa, stand)) == pytest.approx(0.0, abs=1e-9)
    assert value(v, facing_angle(stand, sofa)) == pytest.approx(0.0, abs=1e-9)
    turned = _sofa_and_stand(math.pi / 2)   # the stand faces sideways: 90 deg off
    assert value(turned, facing_angle(stand, sofa)) == pytest.approx(90.0)
    aside = _sofa_and_stand(math.pi, stand_pos=(4.0, 4.0, 0.3))   # 45 deg off the sofa's axis
    assert value(aside, facing_angle(sofa, stand)) == pytest.approx(45.0)
    assert value(aside, facing_angle(sofa, scene()[S.Bed])) == 0.0   # no target: no angle


def test_front_clearance_measures_free_depth_before_each_face_to_walls_and_blockers():
    v = FakeView()
    v.add_room("room", [(0, 0), (5, 0), (5, 4), (0, 4)])
    # a wardrobe 0.6 m deep, back to the wall x = 0, facing +x; a chair 1.0 m before its front
    v.add("wardrobe", {S.Wardrobe}, (0.3, 2.0, 1.0), yaw=0.0, extents=(0.6, 1.2, 2.0))
    v.add("chair", {S.Chair}, (1.85, 2.0, 0.4), yaw=0.0, extents=(0.5, 0.5, 0.8))
    wardrobe, room = scene()[S.Wardrobe], scene()[S.Room]
    blockers = scene()[S.Chair] | room
    assert value(v, front_clearance(wardrobe, blockers)) == pytest.approx(1.0)
    # the left side (+y) sees the wall at y = 4; the right side (-y) the wall at y = 0
    assert value(v, front_clearance(wardrobe, blockers, face="left")) == pytest.approx(1.4)
    assert value(v, front_clearance(wardrobe, blockers, face="right", probe=1.0)) == 1.0
    v.move("chair", center=(2.0, 3.2, 0.4))   # beside the band: the far wall at x = 5 counts
    assert value(v, front_clearance(wardrobe, blockers, probe=9.0)) == pytest.approx(4.4)
    # a negative margin widens the band past the sides (doors swinging out): the chair is in
    v.move("chair", center=(1.2, 2.9, 0.4))
    assert value(v, front_clearance(wardrobe, blockers, probe=9.0)) == pytest.approx(4.4)
    assert value(v, front_clearance(wardrobe, blockers, margin=-0.3)) == pytest.approx(0.35)
    with pytest.raises(ConstraintError):
        front_clearance(wardrobe, blockers, face="top")
