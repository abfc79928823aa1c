"""Reach from the entrance: analytic shares in empty rooms, furniture and narrow gaps cutting
rooms off, doors and stairs linking them, and a generated home's report."""
from __future__ import annotations

import json
import math

import pytest

from indoorgen.architecture.solidify import Architecture
from indoorgen.architecture.walls import WallThickness
from indoorgen.model.floorplan import Floorplan, StairSpec, Storey
from indoorgen.quality.navigation import (
    access_points,
    navigability,
    navigation_report,
    reach,
    write_nav_images,
)
from indoorgen.quality.occupancy import LONE_DOOR_DEPTH
from support.navscenes import BoxCache, box, rect_room, scene_of

R = 0.25
CORNER = (1 - math.pi / 4) * R * R  # floor a disc of radius R misses in a right-angled corner


def _report(rooms, objects=(), architecture=None, **kw):
    sc, geo = scene_of(rooms, list(objects))
    return navigation_report(sc, geo, BoxCache(), architecture, **kw)


def test_empty_room_is_reached_but_for_its_corners():
    room = rect_room("r", 0, 0, 4, 3, (("door_0", 0, 2.0, 0.9),))
    rep = _report([room])
    free = 12.0 + 0.9 * LONE_DOOR_DEPTH
    # four room corners and the two far corners of the dead-end door passage
    assert rep["storeys"]["0"]["free_m2"] == pytest.approx(free, abs=1e-6)
    # the 5 cm grid misses about twice the corner area (10 cells a corner); 2 cm comes closer
    assert rep["reachable_share_of_free"] == pytest.approx(1 - 6 * CORNER / free, abs=0.008)
    fine = _report([room], cell=0.02)["reachable_share_of_free"]
    assert fine == pytest.approx(1 - 6 * CORNER / free, abs=0.003)
    # no agent fits in a corner wherever it stands: the walkable floor leaves them out
    s = rep["storeys"]["0"]
    assert s["walkable_m2"] == pytest.approx(s["reachable_m2"])
    assert rep["reachable_share"] == 1.0
    assert rep["passed"] and not rep["failures"]
    assert rep["unreachable_rooms"] == rep["unreachable_doors"] == []
    sc, geo = scene_of([room])
    sr = reach(sc, geo, BoxCache()).storeys[0]
    # the agent's centre keeps R from the walls (and steps a little into the door passage)
    assert sr.occ.grid.area(sr.reached) == pytest.approx((4 - 2 * R) * (3 - 2 * R), abs=0.2)


def _split_room(gap: float):
    """A 6 x 3 room with the entrance on the left and a door on the right, cut by a row of
    furniture at x = 3 that leaves a `gap` at the top wall."""
    room = rect_room("r", 0, 0, 6, 3, (("entrance", 3, 1.5, 0.9), ("far", 1, 1.5, 0.9)))
    return room, [box("row", "r", 3.0, (3.0 - gap) / 2, (0.6, 3.0 - gap, 0.9))]


def test_furniture_across_the_room_cuts_off_the_far_part():
    room, row = _split_room(0.0)
    open_share = _report([room])["reachable_share"]
    rep = _report([room], row)
    assert rep["reachable_share"] < 0.6 * open_share
    assert rep["unreachable_doors"] == ["far"]
    assert rep["unreachable_rooms"] == []  # the room itself is entered, but not its far door
    assert not rep["passed"] and rep["failures"] == ["door far cannot be passed from the entrance"]


def test_a_narrow_gap_passes_a_thin_agent_only():
    room, row = _split_room(0.4)
    wide = _report([room], row, agent_radius=0.25)
    thin = _report([room], row, agent_radius=0.15)
    assert wide["unreachable_doors"] == ["far"]
    assert thin["unreachable_doors"] == []
    assert thin["reachable_share"] > 0.9 > wide["reachable_share"]


def _two_rooms(width: float):
    a = rect_room("a", 0, 0, 4, 3, (("entrance", 3, 1.5, 0.9), ("d", 1, 1.5, width)))
    b = rect_room("b", 4.12, 0, 8.12, 3, (("d", 3, 1.5, width),))
    return [a, b]


def test_an_open_door_links_two_rooms():
    rep = _report(_two_rooms(0.9))
    assert rep["passed"] and rep["unreachable_doors"] == []
    assert rep["reachable_share"] > 0.98
    narrow = _report(_two_rooms(0.4))
    assert narrow["unreachable_rooms"] == ["b"] and narrow["unreachable_doors"] == ["d"]
    assert not narrow["passed"]
    assert narrow["failures"] == ["room b is not reachable from the entrance",
                                  "door d cannot be passed from the entrance"]


def test_a_shut_door_cuts_off_the_room_behind_an_open_one_does_not():
    """scene.json's door states: a leaf recorded shut (0) blocks its passage, an open one
    (its joint value) does not; the front door shut still lets the agent start inside."""
    for doors, cut_off in (({"d": 1.5708, "entrance": 0.0}, False),
                           ({"d": 0.0, "entrance": 1.5708}, True)):
        sc, geo = scene_of(_two_rooms(0.9))
        sc.doors = doors
        rep = navigation_report(sc, geo, BoxCache())
        assert rep["unreachable_rooms"] == (["b"] if cut_off else []), doors
        assert rep["unreachable_doors"] == (["d"] if cut_off else []), doors
        # a shut door is the user's choice: the room behind it fails, the door does not
        assert rep["failures"] == (["room b is not reachable from the entrance"]
                                   if cut_off else []), doors


def test_furniture_against_a_door_cuts_off_the_room_behind():
    rep = _report(_two_rooms(0.9), [box("wardrobe", "b", 4.5, 1.5, (0.6, 1.6, 2.0))])
    assert rep["unreachable_rooms"] == ["b"] and rep["unreachable_doors"] == ["d"]


def _storeys(stairs):
    down = rect_room("down", 0, 0, 6, 5, (("entrance", 0, 1.0, 1.0),))
    up = rect_room("up", 0, 0, 6, 6, storey=1, elevation=3.0)
    fp = Floorplan([Storey(0, 0.0, 2.8), Storey(1, 3.0, 2.8)], stairs=stairs)
    return [down, up], Architecture(fp, {}, [], WallThickness())


STAIR = StairSpec(0, 1, [(3.0, 1.2), (4.0, 1.2), (4.0, 4.2), (3.0, 4.2)])


def test_a_stair_links_its_storeys():
    rooms, arch = _storeys([STAIR])
    rep = _report(rooms, architecture=arch)
    assert rep["passed"] and rep["storeys"]["1"]["reachable_share"] > 0.95
    rooms, arch = _storeys([])
    rep = _report(rooms, architecture=arch)
    assert rep["unreachable_rooms"] == ["up"] and rep["storeys"]["1"]["reachable_share"] == 0
    assert 0 < rep["reachable_share"] < 0.6


def test_a_blocked_stair_head_cuts_off_the_upper_storey():
    rooms, arch = _storeys([STAIR])
    chest = box("chest", "up", 3.5, 4.6, (1.6, 0.6, 0.8), z=3.0)
    rep = _report(rooms, [chest], architecture=arch)
    assert rep["unreachable_rooms"] == ["up"]


def test_large_object_fronts_and_bed_sides():
    room = rect_room("r", 0, 0, 5, 4, (("entrance", 3, 2.0, 0.9),))
    # a wardrobe facing +x into the room, and one facing the wall (its front unreachable)
    good = box("wardrobe_0", "r", 0.3, 0.6, (0.6, 1.0, 2.0), tags=("wardrobe",))
    bad = box("wardrobe_1", "r", 4.7, 3.0, (0.6, 1.0, 2.0), tags=("wardrobe",))
    # a bed along the bottom wall: one side against it, the other free
    bed = box("bed_0", "r", 2.5, 0.5, (2.0, 1.0, 0.5), tags=("bed",))
    small = box("plant_0", "r", 2.5, 2.5, (0.3, 0.3, 0.5), tags=("plant",))
    rep = _report([room], [good, bad, bed, small])
    assert rep["large_objects_unreachable"] == [{"object": "wardrobe_1", "room": "r"}]
    assert access_points(small, BoxCache(), R) == []
    assert len(access_points(bed, BoxCache(), R)) == 2


def test_report_is_json_ready_and_deterministic():
    rep = _report(_two_rooms(0.9), [box("sofa", "a", 2.0, 2.0, (1.0, 2.0, 0.8), tags=("sofa",))])
    again = _report(_two_rooms(0.9), [box("sofa", "a", 2.0, 2.0, (1.0, 2.0, 0.8), tags=("sofa",))])
    assert json.dumps(rep, sort_keys=True) == json.dumps(again, sort_keys=True)
    assert set(rep) == {"agent_radius", "cell", "storeys", "reachable_share",
                        "reachable_share_of_free", "rooms", "doors", "unreachable_rooms",
                        "unreachable_doors", "large_objects_unreachable", "passed", "failures"}
    assert (rep["rooms"], rep["doors"]) == (2, 2)


def test_navigability_is_the_largest_region_share():
    room, row = _split_room(0.0)
    sc, geo = scene_of([room])
    assert navigability(sc, geo, BoxCache()) == pytest.approx(1.0)
    sc, geo = scene_of([room], row)
    assert navigability(sc, geo, BoxCache()) == pytest.approx(0.5, abs=0.05)


def test_nav_images_one_per_storey(tmp_path):
    rooms, arch = _storeys([STAIR])
    sc, geo = scene_of(rooms)
    paths = write_nav_images(sc, geo, BoxCache(), arch, tmp_path)
    assert [p.name for p in paths] == ["nav_0.png", "nav_1.png"]
    assert all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in paths)


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_generated_home_report_is_consistent(generated_homes, home):
    gen = generated_homes[home]
    rep = navigation_report(gen.scene, gen.rooms, gen.cache, gen.architecture)
    assert set(rep["storeys"]) == {str(k) for k in range(gen.scene.config["floors"])}
    for s in rep["storeys"].values():
        assert 0 < s["reachable_m2"] <= s["walkable_m2"] <= s["free_m2"]
        assert 0 <= s["reachable_share_of_free"] <= s["reachable_share"] <= 1
    assert 0 <= rep["reachable_share"] <= 1
    assert set(rep["unreachable_rooms"]) <= set(gen.scene.rooms)
    assert {o["object"] for o in rep["large_objects_unreachable"]} <= set(gen.scene.objects)
    assert rep["passed"] == (not rep["unreachable_rooms"] and not rep["unreachable_doors"])
    assert 0 < navigability(gen.scene, gen.rooms, gen.cache, gen.architecture) <= 1
