"""The full-mesh re-check: a scene whose placeholders are clear keeps everything; of two
colliding objects the later-placed one goes, with what rests on it."""
from __future__ import annotations

import fcl
import numpy as np

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets.cache import AssetCache, mesh_bvh
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.scene import Room
from indoorgen.programs.relations import on_ceiling
from indoorgen.solver.broadphase import WINDOW_ZONE
from indoorgen.solver.full_mesh import full_mesh_check
from indoorgen.solver.state import Placement, State
from support.solverscene import ROOM, assert_consistent, floor, make_state, put, top_of, wall


def ceiling() -> list[Placement]:
    """Hanging from the room's ceiling."""
    return [Placement(on_ceiling, ROOM, "top", "ceiling")]


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


def test_a_window_zone_removes_only_what_must_keep_out_of_it():
    # a window low in wall 0 (y = 0): a candle on a table before it and a pendant light beside
    # it stay, as the solver lets them; a picture hung over it goes
    geo = build_room(Room(ROOM, "living_room", rectangle(4.0, 3.0), 2.7, 0.12))
    geo.windows = [np.array([(1.0, -0.06, 0.7), (3.0, 0.06, 2.2)])]
    st = State({ROOM: geo}, AssetCache())
    table = put(st, "dining_table_rect", floor(), (2.0, 0.7), np.pi / 2)
    candle = put(st, "candle", top_of(table), (2.0, 0.35), stage="small")
    light = put(st, "pendant_light", ceiling(), (1.0, 0.3), stage="medium")
    art = put(st, "wall_art", wall(0), (2.0, 0.0, 1.5), stage="medium")
    assert not any(st.collides(n) for n in (table, candle, light)) and st.collides(art)
    zone = next(piece for piece, kind in zip(st.static, st.static_kinds, strict=True)
                if kind == WINDOW_ZONE)  # the candle and the light reach into it
    assert all(fcl.collide(zone, fcl.CollisionObject(
        mesh_bvh(st.cache.full(st.objects[n].generator, st.objects[n].params).mesh),
        fcl.Transform(yaw_matrix(st.objects[n].yaw), st.objects[n].position)),
        fcl.CollisionRequest(), fcl.CollisionResult()) for n in (candle, light))
    assert full_mesh_check(st) == [art]
    assert set(st.objects) == {table, candle, light}


def test_a_screen_keeps_out_of_a_window_zone_even_on_its_stand():
    # a TV before a window glares, watched against the daylight: it keeps out of the window's
    # zone wherever it stands, so its stand keeps out of the zone down to the floor (a stand
    # under the sill left its TV nowhere to go); other low furniture stands there freely
    geo = build_room(Room(ROOM, "living_room", rectangle(4.0, 3.0), 2.7, 0.12))
    geo.windows = [np.array([(1.0, -0.06, 0.7), (3.0, 0.06, 2.2)])]
    st = State({ROOM: geo}, AssetCache())
    stand = put(st, "tv_stand", floor(), (2.0, 0.3), np.pi / 2)
    tv = put(st, "tv", top_of(stand), (2.0, 0.3), np.pi / 2, stage="small")
    assert st.window_bound(tv) and not st.window_bound(stand)
    assert st.collides(stand) and st.collides(tv)
    assert full_mesh_check(st) == [tv]  # the zone below the sill is a rule, not a solid
    st.remove(stand)
    stand = put(st, "tv_stand", floor(), (3.6, 1.5), np.pi)  # beside the window, both stand
    tv = put(st, "tv", top_of(stand), (3.6, 1.5), np.pi, stage="small")
    assert not st.collides(stand) and not st.collides(tv)
    table = put(st, "coffee_table", floor(), (2.0, 0.6))  # a low table before it is fine
    assert not st.collides(table)
