"""Tests for the geometric scalar terms; expected values are worked out by hand in comments."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, Point, Polygon, box

from indoorgen.constraints.geometry import (
    accessibility_cost_fast,
    accessibility_cost_slow,
    angle_alignment_cost,
    bbox_area,
    bbox_volume,
    center_of_support_distance,
    facing_angle,
    focus_score,
    freespace_2d,
    front_free_depth,
    mesh_to_fcl,
    min_distance,
    polygon_distance,
    reflectional_asymmetry,
    rotational_asymmetry,
)

S2 = math.sqrt(0.5)  # cos 45 deg


def unit_cube(center) -> trimesh.Trimesh:
    m = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    m.apply_translation(center)
    return m


def dirs(yaws) -> np.ndarray:
    y = np.asarray(yaws, float)
    return np.stack([np.cos(y), np.sin(y)], axis=1)


# ------------------------------------------------------------------------- rotational symmetry
FOUR = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])


def test_rotational_four_chairs_facing_centre_is_zero():
    assert rotational_asymmetry(FOUR, -FOUR) == pytest.approx(0.0, abs=1e-9)
    # same chairs listed in a scrambled order, and around an off-origin table
    perm = [2, 0, 3, 1]
    assert rotational_asymmetry(FOUR[perm] + [3.0, -2.0], -FOUR[perm]) == pytest.approx(0.0, abs=1e-9)


def test_rotational_shifted_chair_hand_value():
    # Chair (1,0) moved to (2,0), all still facing the origin.
    # centroid (0.25,0); p = (1.75,0), (-0.25,1), (-1.25,0), (-0.25,-1).
    # CCW order from atan2: (-0.25,-1)[-104deg], (1.75,0)[0], (-0.25,1)[104deg], (-1.25,0)[180].
    # f_i = R(-i*90deg) p_i: (-0.25,-1), (0,-1.75), (0.25,-1), (0,-1.25); q = (0,-1.25).
    # sum ||f_i - q||^2 = 0.125 + 0.25 + 0.125 + 0 = 0.5 -> /n = 0.125; / max|p|^2 = 1.75^2
    # -> location = 0.125 / 3.0625 = 2/49.
    # Fronts in that order (0,1), (-1,0), (0,-1), (1,0) all map to f_i = (0,1) -> orientation 0.
    # score = (2/49 + 0)/2 = 1/49.
    c = FOUR.copy()
    c[0, 0] = 2.0
    assert rotational_asymmetry(c, -FOUR) == pytest.approx(1.0 / 49.0, rel=1e-12)


def test_rotational_grows_with_shift():
    vals = []
    for s in (0.0, 0.1, 0.3, 0.6, 1.0):
        c = FOUR.copy()
        c[0, 0] += s
        vals.append(rotational_asymmetry(c, -FOUR))
    assert vals[0] == pytest.approx(0.0, abs=1e-9)
    assert all(b > a for a, b in itertools.pairwise(vals))


def test_rotational_pair_orientation():
    # Two objects at (0,0),(2,0): p = (-1,0),(1,0); order (1,0),(-1,0); f = (1,0),(1,0) -> loc 0.
    # Both facing +x: f = (1,0), R(-180)(1,0) = (-1,0); q = 0; orientation = (1+1)/2 = 1.
    # score = (0 + 1)/2 = 0.5. Facing each other: f = (-1,0),(-1,0) -> 0.
    c = np.array([[0.0, 0.0], [2.0, 0.0]])
    assert rotational_asymmetry(c, dirs([0.0, 0.0])) == pytest.approx(0.5)
    assert rotational_asymmetry(c, dirs([0.0, math.pi])) == pytest.approx(0.0, abs=1e-12)


def test_rotational_trivial_sizes():
    assert rotational_asymmetry(np.zeros((0, 2)), np.zeros((0, 2))) == 0.0
    assert rotational_asymmetry(np.array([[3.0, 4.0]]), dirs([1.0])) == 0.0


@st.composite
def _arrangements(draw):
    n = draw(st.integers(2, 7))
    angles = np.sort(draw(st.lists(st.floats(-math.pi, math.pi), min_size=n, max_size=n)))
    radii = np.array(draw(st.lists(st.floats(0.3, 3.0), min_size=n, max_size=n)))
    yaws = np.array(draw(st.lists(st.floats(-math.pi, math.pi), min_size=n, max_size=n)))
    centers = radii[:, None] * dirs(angles)
    perm = np.array(draw(st.permutations(list(range(n)))))
    theta = draw(st.floats(-math.pi, math.pi))
    shift = np.array(draw(st.tuples(st.floats(-5, 5), st.floats(-5, 5))))
    return centers, dirs(yaws), perm, theta, shift


def _well_posed(centers: np.ndarray) -> bool:
    """Angular order around the centroid is unambiguous (no ties, nobody at the centroid)."""
    p = centers - centers.mean(axis=0)
    if np.linalg.norm(p, axis=1).min() < 1e-2:
        return False
    a = np.sort(np.arctan2(p[:, 1], p[:, 0]))
    gaps = np.diff(np.concatenate([a, [a[0] + 2 * math.pi]]))
    return bool(gaps.min() > 1e-3)


@settings(max_examples=60, deadline=None)
@given(_arrangements())
def test_rotational_invariant_to_order_rotation_translation(arr):
    centers, fronts, perm, theta, shift = arr
    if not _well_posed(centers):
        return
    base = rotational_asymmetry(centers, fronts)
    assert base >= 0.0
    assert rotational_asymmetry(centers[perm], fronts[perm]) == pytest.approx(base, abs=1e-9)
    r = np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])
    moved = rotational_asymmetry(centers @ r.T + shift, fronts @ r.T)
    assert moved == pytest.approx(base, abs=1e-9)


# ------------------------------------------------------------------------ reflectional symmetry
X_PLANE = (np.zeros(2), np.array([1.0, 0.0]))  # the line x = 0 (normal +x, direction +y)


def test_reflection_symmetric_nightstands_zero():
    # Nightstands at (+-1,0) both facing +y (yaw pi/2): phi = pi/2, yaw' = pi - pi/2 = pi/2,
    # reflections are (1,0) and (-1,0) with the same yaw -> matched at zero cost -> score 0.
    c = np.array([[-1.0, 0.0], [1.0, 0.0]])
    s = reflectional_asymmetry(c, np.array([math.pi / 2] * 2), np.ones(2), *X_PLANE)
    assert s == pytest.approx(0.0, abs=1e-12)
    # Mirror-image yaws also symmetric: yaw 0.3 at (-1,0) and pi - 0.3 at (1,0)
    s = reflectional_asymmetry(c, np.array([0.3, math.pi - 0.3]), np.ones(2), *X_PLANE)
    assert s == pytest.approx(0.0, abs=1e-12)


def test_reflection_position_asymmetry_hand_value():
    # originals (-1,0),(1.5,0); reflections (1,0),(-1.5,0) (yaws all pi/2, no angular cost).
    # cost matrix [[2, 0.5], [0.5, 3]] -> matching cost 0.5 + 0.5 = 1; volumes 1 -> sum D_dev = 1.
    # alpha = mean pairwise distance = 2.5; score = 1 - 1/(1 + 1/2.5) = 1 - 1/1.4 = 2/7.
    c = np.array([[-1.0, 0.0], [1.5, 0.0]])
    s = reflectional_asymmetry(c, np.array([math.pi / 2] * 2), np.ones(2), *X_PLANE)
    assert s == pytest.approx(2.0 / 7.0, rel=1e-12)


def test_reflection_angular_asymmetry_hand_value():
    # A = (-1,0, yaw pi/2), B = (1,0, yaw 0). A' = (1,0, pi/2), B' = (-1,0, pi).
    # A-B': pos 0, ang pi/2; B-A': pos 0, ang pi/2 (vs 2 and 2+pi for the other pairing).
    # sum D_dev = pi; alpha = 2; score = 1 - 1/(1 + pi/2) = pi/(2 + pi).
    c = np.array([[-1.0, 0.0], [1.0, 0.0]])
    s = reflectional_asymmetry(c, np.array([math.pi / 2, 0.0]), np.ones(2), *X_PLANE)
    assert s == pytest.approx(math.pi / (2.0 + math.pi), rel=1e-12)
    # doubling the volumes doubles sum D_dev: 1 - 1/(1 + pi) = pi/(1 + pi)
    s2 = reflectional_asymmetry(c, np.array([math.pi / 2, 0.0]), 2 * np.ones(2), *X_PLANE)
    assert s2 == pytest.approx(math.pi / (1.0 + math.pi), rel=1e-12)


def test_reflection_oblique_plane_and_trivial():
    # line y = x through (1,1): normal (1,-1)/sqrt2, direction angle pi/4 -> yaw' = pi/2 - yaw.
    # (2,1) yaw 0 mirrors to (1,2) yaw pi/2: the pair is symmetric.
    c = np.array([[2.0, 1.0], [1.0, 2.0]])
    s = reflectional_asymmetry(c, np.array([0.0, math.pi / 2]), np.ones(2),
                               np.array([1.0, 1.0, 0.0]), np.array([1.0, -1.0, 0.0]))
    assert s == pytest.approx(0.0, abs=1e-12)
    assert reflectional_asymmetry(np.zeros((0, 2)), np.zeros(0), np.zeros(0), *X_PLANE) == 0.0
    # single object at (1,0) yaw pi/2: D_pos = 2, alpha = 1 -> 1 - 1/3 = 2/3
    one = reflectional_asymmetry(np.array([[1.0, 0.0]]), np.array([math.pi / 2]), np.ones(1),
                                 *X_PLANE)
    assert one == pytest.approx(2.0 / 3.0)


# ---------------------------------------------------------------------------- angle alignment
ROOM = box(0.0, 0.0, 4.0, 4.0)


def test_angle_alignment_to_room_wall():
    # object at (0.5, 2): nearest wall x = 0, inward normal (1,0).
    c = np.array([[0.5, 2.0]])
    assert angle_alignment_cost(dirs([0.0]), c, ROOM) == pytest.approx(0.0, abs=1e-12)  # (1-1)/2
    assert angle_alignment_cost(dirs([math.pi / 2]), c, ROOM) == pytest.approx(0.5)      # (1-0)/2
    assert angle_alignment_cost(dirs([math.pi]), c, ROOM) == pytest.approx(1.0)          # (1+1)/2
    # near the top wall y = 4 the inward normal is (0,-1); facing -y costs 0, facing +x 0.5
    c2 = np.array([[2.0, 3.7]])
    assert angle_alignment_cost(dirs([-math.pi / 2]), c2, ROOM) == pytest.approx(0.0, abs=1e-12)
    assert angle_alignment_cost(dirs([0.0]), c2, ROOM) == pytest.approx(0.5)


def test_angle_alignment_sums_and_clockwise_polygon():
    # A clockwise-listed room must give the same inward normals.
    cw = Polygon([(0, 0), (0, 4), (4, 4), (4, 0)])
    c = np.array([[0.5, 2.0], [2.0, 0.5]])     # nearest walls x=0 (normal +x), y=0 (normal +y)
    f = dirs([math.pi, math.pi / 2])           # 1.0 + 0.0
    assert angle_alignment_cost(f, c, cw) == pytest.approx(1.0)
    # 45 deg off the normal: (1 - cos45)/2
    assert angle_alignment_cost(dirs([math.pi / 4]), c[:1], ROOM) == pytest.approx((1 - S2) / 2)


def test_angle_alignment_chairs_face_table():
    # table [-1,1]^2; chair at (0,-1.5) outside: closest edge y=-1, inward normal (0,+1).
    table = box(-1.0, -1.0, 1.0, 1.0)
    c = np.array([[0.0, -1.5], [2.0, 0.0]])
    facing = dirs([math.pi / 2, math.pi])      # towards the table -> 0 + 0
    assert angle_alignment_cost(facing, c, table) == pytest.approx(0.0, abs=1e-12)
    away = dirs([-math.pi / 2, 0.0])           # away -> 1 + 1
    assert angle_alignment_cost(away, c, table) == pytest.approx(2.0)


# ------------------------------------------------------------------------------------ focus
def test_focus_cases():
    target = np.array([0.0, 0.0])
    c = np.array([[2.0, 0.0]])
    assert focus_score(c, dirs([math.pi]), target) == pytest.approx(0.0, abs=1e-12)   # (1-1)/2
    assert focus_score(c, dirs([0.0]), target) == pytest.approx(1.0)                  # (1+1)/2
    assert focus_score(c, dirs([math.pi / 2]), target) == pytest.approx(0.5)          # (1-0)/2
    # the distance does not matter (normalised form): same at 10 m
    assert focus_score(c * 5, dirs([math.pi / 2]), target) == pytest.approx(0.5)
    # sum of two sofas: facing (0) + 45 deg off ((1 - cos45)/2)
    cc = np.array([[2.0, 0.0], [0.0, 3.0]])
    ff = dirs([math.pi, -math.pi / 2 + math.pi / 4])
    assert focus_score(cc, ff, target) == pytest.approx((1 - S2) / 2)


def test_focus_3d_and_degenerate():
    c = np.array([[0.0, 0.0, 1.0]])
    assert focus_score(c, np.array([[0.0, 0.0, -1.0]]), np.zeros(3)) == pytest.approx(0.0)
    assert focus_score(c, np.array([[1.0, 0.0, 0.0]]), np.zeros(3)) == pytest.approx(0.5)
    # object exactly at the target: no direction, neutral 0.5
    assert focus_score(np.zeros((1, 2)), dirs([0.0]), np.zeros(2)) == pytest.approx(0.5)


# ----------------------------------------------------------------------------- accessibility
TV_C = np.array([[0.0, 0.0, 1.0]])
TV_N = np.array([[1.0, 0.0, 0.0]])
TV_FP = np.array([[0.1, 0.3, 0.5]])  # (a_c - f_p).n = -0.1 -> a_proj = (0.1, 0, 1)


def test_accessibility_fast_straight_ahead():
    # blocker at a_proj + (1,0,0): dot 1, dist^2 1, diag 1.5 -> 1/1 * 1.5 = 1.5
    cost = accessibility_cost_fast(TV_C, TV_N, TV_FP, np.array([[1.1, 0.0, 1.0]]), np.array([1.5]))
    assert cost == pytest.approx(1.5, rel=1e-12)


def test_accessibility_fast_off_axis_and_behind():
    # 45 deg off at distance 1: dot cos45, dist^2 1 -> cos45 * 1.5 (< 1.5)
    b = np.array([[0.1 + S2, S2, 1.0]])
    cost = accessibility_cost_fast(TV_C, TV_N, TV_FP, b, np.array([1.5]))
    assert cost == pytest.approx(S2 * 1.5, rel=1e-12)
    assert cost < 1.5
    # behind the plane: dot = -1 -> clamped to 0
    assert accessibility_cost_fast(TV_C, TV_N, TV_FP, np.array([[-0.9, 0.0, 1.0]]),
                                   np.array([1.5])) == 0.0
    # no blockers
    assert accessibility_cost_fast(TV_C, TV_N, TV_FP, np.zeros((0, 3)), np.zeros(0)) == 0.0


def test_accessibility_fast_picks_nearest_and_sums():
    # blockers: (2.1,0,1) straight ahead at 2 m (diag 1), (0.1,0.5,1) beside at 0.5 m (diag 2).
    # nearest is the side one: dot 0 -> 0 contribution, the far one is ignored.
    b = np.array([[2.1, 0.0, 1.0], [0.1, 0.5, 1.0]])
    assert accessibility_cost_fast(TV_C, TV_N, TV_FP, b, np.array([1.0, 2.0])) == pytest.approx(0.0)
    # two TVs, one blocker each: TV1 blocker at 2 m ahead, diag 1 -> 2/4 * 1 = 0.5;
    # TV2 at (0,5,1) facing -y, plane point (0,4.9,1) -> a_proj (0,4.9,1); blocker (0,4.4,1):
    # rel (0,-0.5,0), dot 0.5, dist^2 0.25 -> 2 * diag 0.5 = 1.0. total 1.5
    ac = np.array([[0.0, 0.0, 1.0], [0.0, 5.0, 1.0]])
    an = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
    fp = np.array([[0.1, 0.0, 1.0], [0.0, 4.9, 1.0]])
    b = np.array([[2.1, 0.0, 1.0], [0.0, 4.4, 1.0]])
    assert accessibility_cost_fast(ac, an, fp, b, np.array([1.0, 0.5])) == pytest.approx(1.5)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5),
                          st.floats(0.0, 3.0)), min_size=1, max_size=6),
       st.floats(-math.pi, math.pi))
def test_accessibility_fast_never_negative(blockers, yaw):
    b = np.array([t[:3] for t in blockers])
    d = np.array([t[3] for t in blockers])
    n = np.array([[math.cos(yaw), math.sin(yaw), 0.0]])
    cost = accessibility_cost_fast(TV_C, n, TV_C + 0.2 * n, b, d)
    assert cost >= 0.0 and math.isfinite(cost)


def test_accessibility_slow_unit_cubes():
    # TV = unit cube at (0,0,0.5) ([-.5,.5]x[-.5,.5]x[0,1]), front +x, plane point (0.5,0,0.5)
    # -> a_c = (0,0,0.5), a_proj = (0.5,0,0.5).
    # Blocker = unit cube at (2.5,1.5,1.5) ([2,3]x[1,2]x[1,2]): the closest points are the corners
    # (0.5,0.5,1) on the TV and (2,1,1) on the blocker (distance sqrt(1.5^2+0.5^2)).
    # rel = (2,1,1) - (0.5,0,0.5) = (1.5,1,0.5): dot 1.5, |rel|^2 = 3.5, diag sqrt(3)
    # -> cost = 1.5/3.5 * sqrt(3) = 3*sqrt(3)/7.
    tv = unit_cube((0.0, 0.0, 0.5))
    near = unit_cube((2.5, 1.5, 1.5))
    far = unit_cube((6.0, 0.0, 0.5))   # straight ahead but farther: not the closest blocker
    n, fp = np.array([[1.0, 0.0, 0.0]]), np.array([[0.5, 0.0, 0.5]])
    expected = 3.0 * math.sqrt(3.0) / 7.0
    assert accessibility_cost_slow([tv], n, fp, [near]) == pytest.approx(expected, rel=1e-9)
    assert accessibility_cost_slow([tv], n, fp, [far, near]) == pytest.approx(expected, rel=1e-9)
    # far alone: closest point on its face x = 5.5 has rel.n = 5, |rel|^2 >= 25 -> <= 5/25*sqrt3
    assert 0.0 < accessibility_cost_slow([tv], n, fp, [far]) <= 0.2 * math.sqrt(3) + 1e-9
    # behind: unit cube at (-2.5, 1.5, 1.5) -> clamped to 0
    assert accessibility_cost_slow([tv], n, fp, [unit_cube((-2.5, 1.5, 1.5))]) == 0.0
    assert accessibility_cost_slow([tv], n, fp, []) == 0.0


# ------------------------------------------------------------------------------- free space
def test_freespace_plate_on_table():
    # 1x1 table (area 1) minus a 0.2x0.2 plate (0.04) -> 0.96
    table = box(0, 0, 1, 1)
    plate = box(0.4, 0.4, 0.6, 0.6)
    assert freespace_2d([table], [plate]) == pytest.approx(0.96)
    # two overlapping plates (union 0.04 + 0.04 - 0.01 = 0.07) -> 0.93, not 0.92
    p2 = box(0.5, 0.5, 0.7, 0.7)
    assert freespace_2d([table], [plate, p2]) == pytest.approx(0.93)
    # a plate half over the edge only covers 0.02 of the table -> 0.98
    assert freespace_2d([table], [box(0.9, 0.4, 1.1, 0.6)]) == pytest.approx(0.98)
    assert freespace_2d([table], []) == pytest.approx(1.0)
    assert freespace_2d([], [plate]) == 0.0


# ---------------------------------------------------------------------------- area / volume
def test_bbox_volume_and_area():
    e = np.array([[1.0, 2.0, 3.0], [0.5, 0.5, 2.0]])
    # volumes 6 + 0.5 = 6.5; XY dims: 2 + 0.25 = 2.25
    assert bbox_volume(e) == pytest.approx(6.5)
    assert bbox_volume(e, dims=(0, 1)) == pytest.approx(2.25)
    # two largest extents: 2*3 = 6 and 0.5*2 = 1 -> 7; a painting 0.02 x 1.2 x 0.8 -> 0.96
    assert bbox_area(e) == pytest.approx(7.0)
    assert bbox_area(np.array([[0.02, 1.2, 0.8]])) == pytest.approx(0.96)
    assert bbox_volume(np.zeros((0, 3))) == 0.0 and bbox_area(np.zeros((0, 3))) == 0.0


# ------------------------------------------------------------------------------- distances
def test_min_distance_cubes():
    a = unit_cube((0.0, 0.0, 0.0))
    # centres 2 m apart: faces at x = 0.5 and 1.5 -> 1.0
    assert min_distance([a], [unit_cube((2.0, 0.0, 0.0))]) == pytest.approx(1.0, abs=1e-9)
    # the minimum over pairs: 1.0 vs corner-to-corner sqrt(2^2+2^2+2^2)
    pair = [unit_cube((3.0, 3.0, 3.0)), unit_cube((0.0, 2.0, 0.0))]
    assert min_distance([a], pair) == pytest.approx(1.0, abs=1e-9)
    assert min_distance([a], [unit_cube((3.0, 3.0, 3.0))]) == pytest.approx(2 * math.sqrt(3))
    assert min_distance([a], [unit_cube((1.0, 0.0, 0.0))]) == 0.0       # touching
    assert min_distance([a], [unit_cube((0.3, 0.2, 0.0))]) == 0.0       # intersecting
    assert min_distance([], [a]) == math.inf and min_distance([a], []) == math.inf


def test_mesh_to_fcl_builds_model():
    import fcl

    model = mesh_to_fcl(unit_cube((0.0, 0.0, 0.0)))
    assert isinstance(model, fcl.BVHModel)
    assert model.num_tries_() == 12  # a box has 12 triangles


def test_polygon_distance_and_center_of_support():
    assert polygon_distance(box(0, 0, 1, 1), box(3, 0, 4, 1)) == pytest.approx(2.0)
    assert polygon_distance(box(0, 0, 1, 1), LineString([(0, 2.5), (5, 2.5)])) == pytest.approx(1.5)
    assert polygon_distance(box(0, 0, 1, 1), box(0.5, 0.5, 2, 2)) == 0.0
    table = box(0, 0, 2, 1)                  # centroid (1, 0.5)
    assert center_of_support_distance(np.array([1.0, 0.5]), table) == pytest.approx(0.0)
    # (1.3, 0.9) -> offset (0.3, 0.4) -> 0.5
    assert center_of_support_distance(np.array([1.3, 0.9, 0.8]), table) == pytest.approx(0.5)
    assert center_of_support_distance(np.zeros(2), Point(0, 0).buffer(1.0)) == pytest.approx(0.0)


def test_facing_angle_in_degrees_and_zero_on_the_target():
    assert facing_angle(np.zeros(2), np.array([1.0, 0.0]), np.array([3.0, 3.0])) \
        == pytest.approx(45.0)
    assert facing_angle(np.zeros(3), np.array([1.0, 0.0, 0.0]),
                                 np.array([-2.0, 0.0, 5.0])) == pytest.approx(180.0)
    assert facing_angle(np.ones(2), np.array([0.0, 1.0]), np.ones(2)) == 0.0


def test_front_free_depth_stops_at_the_first_blocker_in_the_band():
    edge = (np.array([0.0, -0.5]), np.array([0.0, 0.5]))
    front = np.array([1.0, 0.0])
    near = Polygon([(1.0, 0.2), (1.5, 0.2), (1.5, 0.8), (1.0, 0.8)])
    aside = Polygon([(0.5, 0.6), (0.9, 0.6), (0.9, 0.9), (0.5, 0.9)])
    wall = LineString([(2.5, -3.0), (2.5, 3.0)])
    assert front_free_depth(edge, front, [aside, wall], 3.0) == pytest.approx(2.5)
    assert front_free_depth(edge, front, [aside, wall, near], 3.0) == pytest.approx(1.0)
    assert front_free_depth(edge, front, [wall], 2.0) == 2.0
