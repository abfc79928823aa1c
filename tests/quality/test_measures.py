"""The community measures on hand-built rooms: collision and out-of-bounds rates."""
from __future__ import annotations

from indoorgen.quality.measures import colliding_objects, community_measures, out_of_bounds_objects
from support.qualityscene import FACE_UP, context, new_scene, put, size


def test_overlapping_objects_collide_and_apart_they_do_not():
    sc = new_scene()
    put(sc, "sofa", 2.0, 1.0, FACE_UP)
    put(sc, "sofa", 2.3, 1.0, FACE_UP)
    put(sc, "armchair", 5.0, 4.0, FACE_UP)
    ctx = context(sc)
    hits = colliding_objects(ctx)
    assert set(hits) == {"sofa_0", "sofa_1"} and hits["sofa_0"][0] == "sofa_1"
    m = community_measures(ctx)
    assert m["objects"] == 3 and abs(m["collision_rate"] - 2 / 3) < 1e-3


def test_an_object_on_another_touches_but_does_not_collide():
    sc = new_scene()
    t = put(sc, "coffee_table", 3.0, 2.0)
    put(sc, "vase", 3.0, 2.0, z=size("coffee_table")[2], parent=t)
    assert colliding_objects(context(sc)) == {}


def test_objects_through_a_wall_are_out_of_bounds():
    sc = new_scene()
    put(sc, "bookcase", 3.0, 0.05, FACE_UP)  # half its depth into wall_0
    put(sc, "bookcase", 3.0, 2.5, FACE_UP)
    oob = out_of_bounds_objects(context(sc))
    assert list(oob) == ["bookcase_0"] and oob["bookcase_0"] > 0.05
    assert community_measures(context(sc))["out_of_bounds_rate"] == 0.5
