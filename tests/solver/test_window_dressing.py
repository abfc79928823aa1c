"""Curtains hung at a room's windows: centred on the window, past its frame on both sides, from
above it to just over the floor (or below the sill over furniture under it), on the wall, clear
of the frame and of the furniture."""
from __future__ import annotations

import math

import fcl
import numpy as np

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.architecture.solidify import HomeRoomGeometry
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.model.scene import Door, Room
from indoorgen.solver.circulation import walkway
from indoorgen.solver.stages import make_namer
from indoorgen.solver.state import ObjState, State
from indoorgen.solver.window_dressing import HEM_FLOOR, HEM_SILL, ON_WALL, dress_windows
from support.solverscene import ROOM, floor, put

#: a window in wall_0 (y = 0, the room at y > 0): 1.2 m wide, 0.9-2.1 m high, its frame 3 cm
#: proud of the wall
WINDOW = np.array([[2.0, -0.15, 0.9], [3.2, 0.03, 2.1]])


def _state() -> State:
    geo = build_room(Room("living_room_0", "living_room", rectangle(5.0, 4.0)))
    assert abs(float(np.dot(geo.surface("wall_0").normal, [0, 1, 0])) - 1) < 1e-9
    home_geo = HomeRoomGeometry(**vars(geo), windows=[WINDOW])
    return State({"living_room_0": home_geo}, AssetCache())


def _dress(st: State, seed: int = 3) -> list[str]:
    return dress_windows(st, "living_room_0", "curtain", np.random.default_rng(seed), make_namer())


def _clear_of_window(st: State, name: str) -> bool:
    lo, hi = WINDOW
    box = fcl.CollisionObject(fcl.Box(*(hi - lo)), fcl.Transform(np.eye(3), (lo + hi) / 2))
    ob = st.objects[name]
    return not any(fcl.collide(box, c, fcl.CollisionRequest(), fcl.CollisionResult())
                   for c in ob.cobjs[:ob.n_solid])


def test_a_curtain_hangs_at_the_window_sized_to_it():
    st = _state()
    names = _dress(st)
    assert names == ["curtain_0"]
    ob = st.objects["curtain_0"]
    assert ob.placements[0].relation == ON_WALL and ob.placements[0].parent_surface == "wall_0"
    lo, hi = st.world_mesh("curtain_0").bounds
    assert abs((lo[0] + hi[0]) / 2 - WINDOW[:, 0].mean()) < 0.01  # centred on the window
    assert lo[0] < WINDOW[0, 0] - 0.04 and hi[0] > WINDOW[1, 0] + 0.04  # past the frame
    assert hi[2] > WINDOW[1, 2] + 0.05  # the rod above the frame
    assert abs(lo[2] - HEM_FLOOR) < 1e-6  # to just over the floor
    assert not st.collides("curtain_0") and _clear_of_window(st, "curtain_0")
    # the same seed hangs the same curtain
    again = _state()
    _dress(again)
    assert again.objects["curtain_0"].params == ob.params
    assert np.allclose(again.objects["curtain_0"].position, ob.position)


def test_over_a_sofa_under_the_window_the_curtain_ends_below_the_sill():
    st = _state()
    fac_params = next(p for p in (get_factory("sofa").sample_params(np.random.default_rng(s))
                                  for s in range(50))
                      if st.cache.placeholder("sofa", p).mesh.bounds[1][2] < 0.85)
    asset = st.cache.placeholder("sofa", fac_params)
    (x0, _, _), (x1, _, _) = asset.mesh.bounds
    st.add(ObjState("sofa_0", "sofa", fac_params, 0, frozenset(), "living_room_0", "large", asset,
                    [], np.array([2.6, -x0 + 0.05, 0.001]), math.pi / 2))
    assert not st.collides("sofa_0")
    names = _dress(st)
    assert names == ["curtain_0"]
    lo, _ = st.world_mesh("curtain_0").bounds
    assert WINDOW[0, 2] - HEM_SILL - 1e-6 <= lo[2] < WINDOW[0, 2]
    assert not st.collides("curtain_0") and _clear_of_window(st, "curtain_0")


def test_a_curtain_that_would_close_the_walkway_is_left_off():
    # a 5 x 2.9 m room, a door in the middle of each short wall, a bed across it from the far
    # wall leaving a 0.75 m way past the window: a curtain's folds would close it
    room = Room(ROOM, "bedroom", rectangle(5.0, 2.9), doors=[Door("a", 3, 1.45, 0.9),
                                                             Door("b", 1, 1.45, 0.9)])
    st = State({ROOM: HomeRoomGeometry(**vars(build_room(room)), windows=[WINDOW])},
               AssetCache())
    bed = put(st, "bed", floor(), (2.6, 2.9 - 1.075), math.pi / 2, seed=6)
    lo, hi = st.world_mesh(bed).bounds
    assert 0.7 < lo[1] < 0.8 and lo[0] < WINDOW[0, 0] + 0.2 and hi[0] > WINDOW[1, 0] - 0.2
    assert walkway(st, ROOM).violation == 0
    assert dress_windows(st, ROOM, "curtain", np.random.default_rng(3), make_namer()) == []
    assert walkway(st, ROOM).violation == 0
    # without the bed the same window takes its curtain
    st.remove(bed)
    assert dress_windows(st, ROOM, "curtain", np.random.default_rng(3), make_namer()) != []
