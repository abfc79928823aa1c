"""Arrangement rules on hand-built rooms: a TV facing the sofa at a viewing distance, the coffee
table before it, the bed's head at a wall, dining chairs facing their table, matching sets and
rugs under their group."""
from __future__ import annotations

import math

import numpy as np

from indoorgen.assets import get_factory
from indoorgen.model.scene import Pose
from indoorgen.quality.arrangement import (
    bed_head_to_wall,
    coffee_table_in_front_of_sofa,
    dining_chairs_face_table,
    matching_sets,
    rug_under_group,
    tv_faces_seating,
    viewing_distance,
)
from support.qualityscene import FACE_DOWN, FACE_LEFT, FACE_RIGHT, FACE_UP, context, new_scene, put, size


def _tv_room(tv_yaw: float):
    sc = new_scene()
    put(sc, "sofa", 3.0, 0.6, FACE_UP)
    put(sc, "tv", 3.0, 4.6, tv_yaw)
    return sc


def test_tv_turned_away_fails_and_turned_to_the_sofa_passes():
    (away,) = tv_faces_seating(context(_tv_room(FACE_UP)))
    (facing,) = tv_faces_seating(context(_tv_room(FACE_DOWN)))
    assert not away.ok and away.value > 170
    assert facing.ok and facing.value < 1 and facing.objects == ("tv_1", "sofa_0")


def test_sofa_turned_away_from_the_tv_fails():
    sc = new_scene()
    put(sc, "sofa", 3.0, 0.6, FACE_RIGHT)
    put(sc, "tv", 3.0, 4.6, FACE_DOWN)
    (c,) = tv_faces_seating(context(sc))
    assert not c.ok and abs(c.detail["seat_angle"] - 90) < 1


def test_coffee_table_before_the_sofa():
    sofa_depth = size("sofa")[0]
    table_depth = size("coffee_table")[0]
    good = new_scene()
    put(good, "sofa", 3.0, 1.0, FACE_UP)
    put(good, "coffee_table", 3.0, 1.0 + sofa_depth / 2 + 0.45 + table_depth / 2, FACE_UP)
    (c,) = coffee_table_in_front_of_sofa(context(good))
    assert c.ok and abs(c.value - 0.45) < 1e-3
    beside = new_scene()
    put(beside, "sofa", 3.0, 1.0, FACE_UP)
    put(beside, "coffee_table", 5.0, 1.0, FACE_UP + 0.4)
    (c,) = coffee_table_in_front_of_sofa(context(beside))
    assert not c.ok


def test_bed_head_against_the_wall():
    depth = size("bed")[0]
    sc = new_scene("bedroom")
    put(sc, "bed", 2.0, depth / 2 + 0.02, FACE_UP)
    put(sc, "bed", 4.5, depth / 2 + 1.0, FACE_UP)
    assert [(c.ok, round(c.value, 3)) for c in bed_head_to_wall(context(sc))] == \
        [(True, 0.02), (False, 1.0)]


def _dining(chair_seeds: tuple[int, int]):
    sc = new_scene("dining_room")
    t = put(sc, "dining_table_rect", 3.0, 2.5)
    fac = get_factory("dining_chair")
    reach = size("dining_table_rect")[0] / 2 + 0.3
    for i, (s, yaw) in enumerate(zip(chair_seeds, (FACE_RIGHT, FACE_LEFT), strict=True)):
        x = 3.0 - reach if i == 0 else 3.0 + reach
        put(sc, "dining_chair", x, 2.5, yaw, parent=t, seed=s,
            params=fac.sample_params(np.random.default_rng(s)))
    return sc


def test_chairs_face_their_table():
    checks = dining_chairs_face_table(context(_dining((1, 1))))
    assert [c.ok for c in checks] == [True, True]
    sc = _dining((1, 1))
    turned = sc.objects["dining_chair_2"]
    turned.pose = Pose(turned.pose.position, math.pi / 2)
    assert [c.ok for c in dining_chairs_face_table(context(sc))] == [True, False]


def test_matching_sets_count_designs():
    (same,) = matching_sets(context(_dining((1, 1))))
    (mixed,) = matching_sets(context(_dining((1, 2))))
    assert same.ok and same.value == 1
    assert not mixed.ok and mixed.value == 2


def test_viewing_distance_from_the_sofa_to_the_screen():
    for tv_y, ok in ((3.4, True), (4.6, False)):
        sc = new_scene(depth=6.0)
        put(sc, "sofa", 3.0, 0.6, FACE_UP)
        put(sc, "tv", 3.0, tv_y, FACE_DOWN)
        (c,) = viewing_distance(context(sc))
        assert c.ok == ok and abs(c.value - (tv_y - 0.6)) < 0.05


def _group_on_rug(rug_y: float):
    """A sofa, its coffee table and a 2.6 x 1.9 m rug centred at `rug_y`; and the rug centre
    that puts its back edge 0.25 m under the sofa's front."""
    sofa_depth = size("sofa")[0]
    table_depth = size("coffee_table")[0]
    sc = new_scene()
    put(sc, "sofa", 3.0, 1.0, FACE_UP)
    put(sc, "coffee_table", 3.0, 1.0 + sofa_depth / 2 + 0.45 + table_depth / 2, FACE_UP)
    put(sc, "rug", 3.0, rug_y, FACE_UP, params={"shape": "rect", "length": 2.6, "width": 1.9,
                                               "thickness": 0.01, "corner_radius": 0.0,
                                               "binding_width": 0.0})
    return sc, 1.0 + sofa_depth / 2 - 0.25 + 0.95


def test_a_rug_under_the_seating_group_passes_and_one_lying_off_it_fails():
    _, under = _group_on_rug(0.0)
    good, _ = _group_on_rug(under)
    (c,) = rug_under_group(context(good))
    assert c.ok and c.value == 1.0 and c.objects[1] == "sofa_0"
    off, _ = _group_on_rug(under + 1.2)  # only the coffee table's far edge on it
    (c,) = rug_under_group(context(off))
    assert not c.ok and c.value < 0.75
    alone = new_scene()
    put(alone, "sofa", 3.0, 1.0, FACE_UP)
    put(alone, "rug", 3.0, 4.0, FACE_UP)
    (c,) = rug_under_group(context(alone))
    assert not c.ok and c.value == 0.0 and c.objects == ("rug_1",)
