"""The floorplan data (indoorgen.model.floorplan): rooms, stairs, connections, door depths."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.model.floorplan import StairSpec
from indoorgen.model.floorplan_io import from_json
from support.plans import apartment, two_storey_home


def test_rooms_storeys_and_contour():
    fp = from_json(apartment())
    assert [r.name for _, r in fp.rooms()][:2] == ["living_room_0", "kitchen_0"]
    assert fp.storey_of("bathroom_0").level == 0
    with pytest.raises(KeyError):
        fp.storey_of("attic_0")
    assert fp.storeys[0].contour().area == pytest.approx(80.0)
    assert fp.storeys[0].room("kitchen_0").shape().area == pytest.approx(20.0)


def test_connections_and_depths_from_the_front_door():
    fp = from_json(apartment())
    g = fp.connection_graph()
    assert set(g.neighbors("living_room_0")) == {"bedroom_0", "bathroom_0", "kitchen_0"}
    depth = fp.room_depths()
    assert depth["living_room_0"] == 0 and depth["kitchen_0"] == 1 and depth["bedroom_1"] == 2


def test_stairs_join_their_storeys_rooms():
    fp, _ = two_storey_home()
    (st,) = fp.stairs
    foot, head = fp.stair_rooms(st)
    assert foot.startswith("staircase_room") and head.startswith("staircase_room")
    assert fp.connection_graph().has_edge(foot, head)


def test_stair_frame_follows_the_polygon_order():
    st = StairSpec(0, 1, [(0.0, 0.0), (1.0, 0.0), (1.0, 4.0), (0.0, 4.0)])
    p0, up, right, run, width = st.frame()
    assert np.allclose(p0, [0, 0]) and np.allclose(up, [0, 1]) and np.allclose(right, [1, 0])
    assert (run, width) == (4.0, 1.0)
    assert st.shape().exterior.is_ccw
