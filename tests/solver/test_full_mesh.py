"""The full-mesh re-check: a scene whose placeholders are clear keeps everything; of two
colliding objects the later-placed one goes, with what rests on it."""
from __future__ import annotations

from indoorgen.solver.full_mesh import full_mesh_check
from support.solverscene import assert_consistent, floor, make_state, put, top_of, wall


def test_a_clear_scene_keeps_everything():
    st = make_state()
    table = put(st, "dining_table_rect", floor(), (2.0, 1.5))
    put(st, "plate", top_of(table), (2.0, 1.5), stage="small")
    put(st, "wall_art", wall(0), (2.0, 0.0, 1.5), stage="medium")
    names = set(st.objects)
    assert full_mesh_check(st) == []
    assert set(st.objects) == names


def test_the_later_of_two_colliding_objects_goes_with_what_rests_on_it():
    st = make_state()
    put(st, "dining_table_rect", floor(), (2.0, 1.5), name="a_table")
    put(st, "dining_table_rect", floor(), (2.1, 1.5), name="b_table")
    put(st, "plate", top_of("b_table"), (2.1, 1.5), stage="small", name="a_plate")
    art = put(st, "wall_art", wall(0), (2.0, 0.0, 1.5), stage="medium")
    assert full_mesh_check(st) == ["b_table", "a_plate"]
    assert set(st.objects) == {"a_table", art}
    assert_consistent(st)
