"""Presence and height rules on hand-built rooms: lights and their headroom, the kitchen sink, counter runs,
accessory heights, wall cabinets and reach."""
from __future__ import annotations

import numpy as np

from indoorgen.assets import get_factory
from indoorgen.quality.rules import (
    accessory_heights,
    counter_runs,
    hood_over_range,
    kitchen_has_sink,
    light_headroom,
    light_off_the_walls,
    reach,
    room_has_light,
    wall_cabinet_height,
)
from support.qualityscene import FACE_UP, context, new_scene, put, report, size


def test_room_without_light_fails_and_with_one_passes():
    sc = new_scene("dining_room")
    assert [c.ok for c in room_has_light(context(sc))] == [False]
    put(sc, "ceiling_light", 3.0, 2.5, z=2.5)
    assert [c.ok for c in room_has_light(context(sc))] == [True]


def test_balcony_needs_no_light():
    assert room_has_light(context(new_scene("balcony"))) == []


def test_a_pendant_leaves_headroom_over_the_floor_and_may_hang_lower_over_a_table():
    """A pendant whose bottom is 1.3 m up over open floor fails (a person walks into it); the
    same pendant over a dining table's middle, 0.7 m or more over its top, passes."""
    params = {**get_factory("pendant_light").sample_params(np.random.default_rng(0)),
              "drop": 1.0, "shade_height": 0.2}
    for over_table, bottom, ok in ((False, 1.3, False), (False, 2.05, True), (True, 1.6, True),
                                   (True, 1.3, False)):
        sc = new_scene("dining_room")
        if over_table:
            put(sc, "dining_table_rect", 3.0, 2.5)
        put(sc, "pendant_light", 3.0, 2.5, z=bottom, params=params)
        (c,) = light_headroom(context(sc))
        assert c.ok == ok and abs(c.value - bottom) < 1e-6, (over_table, bottom)
        assert c.limit == (min(2.0, size("dining_table_rect")[2] + 0.7) if over_table else 2.0)


def test_a_ceiling_light_hangs_over_the_room_not_by_a_wall():
    """A light 0.3 m off a wall fails, one in the middle of the room passes; in a 1.2 m wide
    hallway the middle itself (0.6 m off each wall) passes, 0.4 m off a wall does not."""
    for x, away, ok in ((0.3, 0.3, False), (3.0, 2.5, True)):  # in a 6 x 5 m room
        sc = new_scene("bedroom")
        put(sc, "ceiling_light", x, 2.5, z=2.5)
        (c,) = light_off_the_walls(context(sc))
        assert c.ok == ok and abs(c.value - away) < 1e-6 and c.limit == 0.6
    for y, ok in ((0.6, True), (0.4, False)):
        sc = new_scene("hallway", width=4.0, depth=1.2)
        put(sc, "ceiling_light", 2.0, y, z=2.5)
        (c,) = light_off_the_walls(context(sc))
        assert c.ok == ok and abs(c.limit - 0.48) < 1e-6, (y, c)


def test_kitchen_without_sink_fails_the_scene_with_a_named_reason():
    sc = new_scene("kitchen")
    put(sc, "ceiling_light", 3.0, 2.5, z=2.5)
    put(sc, "fridge", 1.0, 0.5, FACE_UP)
    rep = report(sc)
    assert rep["passed"] is False
    assert rep["rules"]["kitchen_has_sink"]["passed"] == 0
    assert any(f.startswith("kitchen_has_sink: room_0") for f in rep["failures"])


def test_kitchen_sink_passes():
    sc = new_scene("kitchen")
    put(sc, "kitchen_sink", 2.0, 0.3, FACE_UP)
    (c,) = kitchen_has_sink(context(sc))
    assert c.ok and c.objects == ("kitchen_sink_0",)


def test_a_counter_run_has_no_gaps_and_the_fridge_closes_it():
    sink_w, cab_w, fridge_w = (size(g)[1] for g in ("kitchen_sink", "kitchen_base_cabinet", "fridge"))
    for gap, ok in ((0.01, True), (0.3, False)):
        sc = new_scene("kitchen")
        x = 1.0
        for g, w in (("kitchen_base_cabinet", cab_w), ("kitchen_sink", sink_w), ("fridge", fridge_w)):
            put(sc, g, x + w / 2, 0.4, FACE_UP)
            x += w + gap
        checks = counter_runs(context(sc))
        assert [c.objects[0] for c in checks] == ["kitchen_base_cabinet_0", "kitchen_sink_1", "fridge_2"]
        assert all(c.ok == ok and abs(c.value - gap) < 0.02 for c in checks)


def test_toilet_roll_height_is_measured_at_its_centre():
    h = size("toilet_roll_holder")[2]
    sc = new_scene("bathroom")
    put(sc, "toilet_roll_holder", 1.0, 0.05, FACE_UP, z=2.3 - h / 2, parent="wall_0")
    put(sc, "toilet_roll_holder", 2.0, 0.05, FACE_UP, z=0.675 - h / 2, parent="wall_0")
    checks = {c.objects[0]: c for c in accessory_heights(context(sc))}
    high, ok = checks["toilet_roll_holder_0"], checks["toilet_roll_holder_1"]
    assert not high.ok and abs(high.value - 2.3) < 1e-6 and high.limit == [0.6, 0.75]
    assert ok.ok and abs(ok.value - 0.675) < 1e-6


def test_wall_cabinet_bottom_height():
    sc = new_scene("kitchen")
    put(sc, "kitchen_wall_cabinet", 1.0, 0.2, FACE_UP, z=1.4, parent="wall_0")
    put(sc, "kitchen_wall_cabinet", 3.0, 0.2, FACE_UP, z=0.9, parent="wall_0")
    assert [c.ok for c in wall_cabinet_height(context(sc))] == [True, False]


def test_laptop_on_a_wardrobe_is_out_of_reach():
    sc = new_scene("bedroom")
    w = put(sc, "wardrobe", 1.0, 0.4, FACE_UP)
    top = size("wardrobe")[2]
    put(sc, "laptop", 1.0, 0.4, z=top, parent=w)
    t = put(sc, "desk", 4.0, 0.5, FACE_UP)
    put(sc, "laptop", 4.0, 0.5, z=size("desk")[2], parent=t)
    checks = reach(context(sc))
    assert [(c.objects[1], c.ok) for c in checks] == [(w, False), (t, True)]
    assert abs(checks[0].value - top) < 1e-6


def test_hood_offset_is_measured_along_the_range_not_front_to_back():
    """A wall hood is shallower than the range below it: its centre sits behind the range's, which
    is still centred. Sliding it sideways along the wall is what breaks the rule."""
    sc = new_scene("kitchen")
    depth = size("range")[0]
    put(sc, "range", 2.0, 0.05 + depth / 2, FACE_UP, name="range")
    hood_y = size("range_hood")[0] / 2
    hood = put(sc, "range_hood", 2.0, hood_y, FACE_UP, z=1.6, parent="wall_0", name="hood")
    (c,) = hood_over_range(context(sc))
    assert c.objects == (hood, "range") and c.value < 1e-6
    sc.objects[hood].pose = type(sc.objects[hood].pose)((2.4, hood_y, 1.6), FACE_UP)
    (c,) = hood_over_range(context(sc))
    assert abs(c.value - 0.4) < 1e-6 and not c.ok
