"""The room-graph grammar: valid graphs, fixed counts, privacy, planarity, user graphs."""
from __future__ import annotations

import networkx as nx
import pytest

from indoorgen.errors import ConfigError
from indoorgen.floorplan.graph import (
    MAX_LIVING_NEIGHBOURS,
    OFF_HALLWAY,
    HomeGraph,
    balcony_problems,
    graph_from_spec,
    graph_problems,
    privacy_problems,
    sample_home_graph,
    zone_problems,
)
from indoorgen.floorplan.rooms import room_type_of
from indoorgen.rng import stream


def _sample(seed, floors=1, counts=None):
    return sample_home_graph(lambda a: stream(seed, "test", a), floors, counts)


@pytest.mark.parametrize("floors", [1, 2, 3])
def test_sampled_graphs_are_valid(floors):
    for seed in range(25):
        hg = _sample(seed, floors)
        assert hg.n_storeys == floors
        assert graph_problems(hg) == []
        home = hg.home()
        assert nx.is_connected(home)
        assert all(nx.check_planarity(g)[0] for g in hg.storeys)
        assert hg.entrance in hg.storeys[0]
        assert room_type_of(hg.entrance) in ("living_room", "hallway")
        if floors > 1:
            assert [room_type_of(s) for s in hg.stairs] == ["staircase_room"] * floors
            assert all(s in g for s, g in zip(hg.stairs, hg.storeys, strict=False))
        names = hg.rooms()
        assert len(names) == len(set(names))


@pytest.mark.parametrize("floors", [1, 2, 3])
def test_living_rooms_are_not_hubs_and_bathrooms_lead_nowhere(floors):
    """A living room keeps at most MAX_LIVING_NEIGHBOURS doors, the front door included, once
    bedrooms, bathrooms and service rooms are moved onto hallways, and no room is reached only through a
    bathroom (a 2 m^2 closet behind a bathroom leaves the bathroom no wall for its fixtures)."""
    for seed in range(60):
        hg = _sample(seed, floors)
        home = hg.home()
        for n in home.nodes:
            near = [room_type_of(m) for m in home.neighbors(n)]
            doors = len(near) + (n == hg.entrance)  # the front door is a door too
            if room_type_of(n) == "living_room" and doors > MAX_LIVING_NEIGHBOURS:
                assert not set(near) & set(OFF_HALLWAY), (seed, n, near)
            if room_type_of(n) == "bathroom":
                assert all(home.degree(m) > 1 for m in home.neighbors(n)), (seed, n, near)


def test_same_stream_same_graph():
    assert _sample(7, 2).to_json() == _sample(7, 2).to_json()


@pytest.mark.parametrize("counts, floors", [({"bedroom": 2, "bathroom": 1}, 1),
                                            ({"bedroom": 4, "bathroom": 2}, 2),
                                            ({"bedroom": 1, "kitchen": 1, "garage": 1}, 1),
                                            ({"bedroom": 5, "bathroom": 3, "closet": 2}, 3)])
def test_fixed_counts_are_met(counts, floors):
    for seed in range(6):
        hg = _sample(seed, floors, counts)
        have = hg.type_counts()
        for t, n in counts.items():
            assert have.get(t, 0) == n
        assert graph_problems(hg, counts) == []


def test_privacy_rules():
    g = nx.Graph([("living_room_0", "bedroom_0"), ("bedroom_0", "bathroom_0"),
                  ("living_room_0", "bedroom_1")])
    problems = privacy_problems(g)
    assert any("bedroom_1 reaches no bathroom" in p for p in problems)
    g.add_edge("bathroom_0", "living_room_0")  # en-suite opening onto the living room too
    assert any("bathroom_0 is shared" in p for p in privacy_problems(g))
    ok = nx.Graph([("living_room_0", "hallway_0"), ("hallway_0", "bedroom_0"),
                   ("hallway_0", "bedroom_1"), ("hallway_0", "bathroom_0"),
                   ("bedroom_0", "bathroom_1"), ("bathroom_1", "closet_0")])
    assert privacy_problems(ok) == []
    # one bedroom with the home's only bathroom en-suite: a guest has to cross the bedroom
    ensuite = nx.Graph([("living_room_0", "bedroom_0"), ("bedroom_0", "bathroom_0")])
    assert "every bathroom is behind a bedroom" in privacy_problems(ensuite)
    assert "every bathroom is behind a bedroom" in privacy_problems(ensuite, "living_room_0")


def test_balconies_are_leaves_off_living_rooms_and_bedrooms():
    for floors in (1, 2):
        for seed in range(25):
            home = _sample(seed, floors).home()
            for b in (n for n in home.nodes if room_type_of(n) == "balcony"):
                assert {room_type_of(n) for n in home.neighbors(b)} <= {"living_room", "bedroom"}
    g = nx.Graph([("living_room_0", "balcony_0"), ("balcony_0", "utility_0")])
    assert balcony_problems(g) == ["balcony_0 is entered from ['utility_0'], not a living room "
                                   "or bedroom"]


def test_floors_out_of_range():
    for n in (0, 4):
        with pytest.raises(ConfigError, match="--floors"):
            _sample(0, n)


def test_user_graph_round_trips_and_is_checked():
    hg = _sample(3, 2)
    again = graph_from_spec(hg.to_json())
    assert again.to_json() == hg.to_json()
    with pytest.raises(ConfigError, match="not on storey"):
        graph_from_spec({"storeys": [{"rooms": ["living_room_0"],
                                      "edges": [["living_room_0", "bedroom_0"]]}]})
    k5 = {"storeys": [{"rooms": [f"hallway_{i}" for i in range(5)] + ["living_room_0"],
                       "edges": [[f"hallway_{i}", f"hallway_{j}"] for i in range(5)
                                 for j in range(i + 1, 5)] + [["living_room_0", "hallway_0"]]}],
          "entrance": "living_room_0"}
    with pytest.raises(ConfigError, match="not planar"):
        graph_from_spec(k5)
    assert isinstance(graph_from_spec({"storeys": [{"rooms": ["living_room_0", "bathroom_0"],
                                                    "edges": [["living_room_0", "bathroom_0"]]}]}),
                      HomeGraph)


def test_shared_rooms_are_not_behind_bedrooms():
    g = nx.Graph([("hallway_0", "bedroom_0"), ("bedroom_0", "kitchen_0"),
                  ("bedroom_0", "bathroom_0"), ("hallway_0", "bathroom_1")])
    assert zone_problems(g, "hallway_0") == ["kitchen_0 is reached only through a bedroom"]
    g.add_edge("hallway_0", "kitchen_0")
    assert zone_problems(g, "hallway_0") == []   # an en-suite bathroom may be behind it


def test_sampled_homes_have_one_garage_at_most_and_no_ground_floor_balcony():
    for floors in (1, 2):
        for seed in range(25):
            hg = _sample(seed, floors)
            assert sum(room_type_of(n) == "garage" for n in hg.rooms()) <= 1
            assert not any(room_type_of(n) == "balcony" for n in hg.rooms(0))
    two = HomeGraph([nx.Graph([("living_room_0", "garage_0"), ("living_room_0", "garage_1"),
                               ("living_room_0", "balcony_0"), ("living_room_0", "bathroom_0"),
                               ("living_room_0", "kitchen_0")])], "living_room_0")
    assert {"a balcony on the ground floor", "more than one garage (2)"} <= set(
        graph_problems(two))
    # asked for, or drawn by the user, they stay (a terrace on the exterior, a second garage)
    assert graph_problems(two, {"garage": 2, "balcony": 1}) == []
    assert isinstance(graph_from_spec(two.to_json()), HomeGraph)


@pytest.mark.parametrize("seed", range(6))
def test_a_small_flat_grows_no_rooms_it_was_not_asked_for(seed):
    """A 55 m^2 home asked for with one bedroom, a bathroom and a kitchen is a flat: a living
    room (dining in it), the three rooms asked for and perhaps a hall; no dining room, utility
    room or closet too small to furnish."""
    counts = {"bedroom": 1, "bathroom": 1, "kitchen": 1}
    hg = sample_home_graph(lambda a: stream(seed, "test", a), 1, counts, max_area=55.0)
    types = {room_type_of(n) for n in hg.rooms()}
    assert types <= {"living_room", "hallway", "bedroom", "bathroom", "kitchen"}
    assert hg.type_counts()["bedroom"] == 1


def test_a_large_home_still_grows_rooms_it_was_not_asked_for():
    """With room to spare, the grammar's own rooms (a dining room, a closet...) still grow
    beside the counted ones."""
    counts = {"bedroom": 1, "bathroom": 1, "kitchen": 1}
    grown = set()
    for seed in range(6):
        hg = sample_home_graph(lambda a, s=seed: stream(s, "test", a), 1, counts, max_area=160.0)
        grown |= {room_type_of(n) for n in hg.rooms()}
    assert grown - {"living_room", "hallway", "bedroom", "bathroom", "kitchen"}
