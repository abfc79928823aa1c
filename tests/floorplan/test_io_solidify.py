"""floorplan.json round trips; predefined plans; solidified rooms behave like RoomGeometry."""
from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.errors import ConfigError, IndoorGenError, InvalidGeometryError
from indoorgen.floorplan.check import floorplan_problems
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.io import dumps, from_json, read_floorplan, to_json, write_floorplan
from indoorgen.floorplan.room import RoomGeometry
from indoorgen.floorplan.solidify import HomeRoomGeometry, solidify
from indoorgen.floorplan.solve import AnnealConfig
from indoorgen.floorplan.usd import build_architecture_stage
from indoorgen.model.scene import Room
from indoorgen.model.tags import Subpart

#: A hand-drawn five-room apartment with doors, an open kitchen, windows and a front door.
APARTMENT = json.loads((Path(__file__).parent / "data" / "apartment.json").read_text())


def test_predefined_plan_round_trips_and_solidifies(tmp_path):
    fp = from_json(copy.deepcopy(APARTMENT))
    assert floorplan_problems(fp) == []
    write_floorplan(fp, tmp_path / "floorplan.json")
    again = read_floorplan(tmp_path / "floorplan.json")
    assert dumps(again) == dumps(fp)
    assert to_json(again)["storeys"][0]["rooms"][2]["polygon"] == [[0, 5], [5, 5], [5, 8], [0, 8]]
    arch = solidify(again)
    assert set(arch.rooms) == {r["name"] for r in APARTMENT["storeys"][0]["rooms"]}
    kinds = sorted(e.kind for e in arch.elements)
    assert kinds == ["door"] * 4 + ["window"] * 3   # three doors and the entrance
    living = arch.rooms["living_room_0"]
    assert {d.name for d in living.room.doors} == {"d0", "d1", "o0", "entrance"}


def test_schema_keys_are_exactly_the_contract():
    fp = generate_floorplan(2, FloorplanConfig(floors=2,
                                               anneal=AnnealConfig(steps_per_storey=30)))
    d = json.loads(dumps(fp))
    assert set(d) == {"storeys", "stairs", "entrance"}
    assert set(d["entrance"]) == {"room", "center"}
    for s in d["storeys"]:
        assert set(s) == {"level", "elevation", "height", "rooms", "doors", "windows", "openings"}
        assert all(set(r) == {"name", "type", "polygon"} for r in s["rooms"])
        assert all(set(x) == {"name", "rooms", "center", "width", "height"}
                   for x in s["doors"] + s["openings"])
        assert all(set(w) == {"name", "room", "center", "width", "height", "sill"}
                   for w in s["windows"])
    assert [set(st) for st in d["stairs"]] == [{"from_level", "to_level", "polygon"}]
    # a generated plan round-trips too
    assert dumps(from_json(d)) == dumps(fp)


@pytest.mark.parametrize("mutate, err, match", [
    (lambda d: d["storeys"][0]["rooms"][1].update(polygon=[[5, 0], [10, 0], [10, 5], [5, 5]]),
     InvalidGeometryError, "overlap"),
    (lambda d: d["storeys"][0]["rooms"][0].update(type="ballroom"), IndoorGenError, "ballroom"),
    (lambda d: d["storeys"][0]["doors"][0].update(rooms=["living_room_0", "attic_0"]),
     ConfigError, "attic_0"),
    (lambda d: d["storeys"][0].pop("rooms"), ConfigError, "no 'rooms'"),
    (lambda d: d["storeys"][0]["windows"][0].update(width="wide"), ConfigError, "number"),
    (lambda d: d["storeys"][0]["rooms"][0].update(polygon=[[0, 0], [6, 5], [6, 0], [0, 5]]),
     InvalidGeometryError, "simple polygon"),
])
def test_bad_predefined_plans_say_what_is_wrong(mutate, err, match):
    d = copy.deepcopy(APARTMENT)
    mutate(d)
    with pytest.raises(err, match=match):
        from_json(d)


def test_door_off_its_wall_is_rejected_when_solidifying():
    d = copy.deepcopy(APARTMENT)
    d["storeys"][0]["doors"][0]["center"] = [2.5, 3.0]
    with pytest.raises(InvalidGeometryError, match="d0"):
        solidify(from_json(d))


@pytest.fixture(scope="module")
def two_storeys():
    fp = generate_floorplan(1, FloorplanConfig(floors=2,
                                               anneal=AnnealConfig(steps_per_storey=60)))
    return fp, solidify(fp)


def test_rooms_are_room_geometries(two_storeys):
    fp, arch = two_storeys
    for storey in fp.storeys:
        for spec in storey.rooms:
            g = arch.rooms[spec.name]
            assert isinstance(g, RoomGeometry) and isinstance(g, HomeRoomGeometry)
            assert isinstance(g.room, Room) and g.room.room_type == spec.type
            assert g.room.storey == storey.level and g.elevation == storey.elevation
            free = sg.Polygon(g.room.polygon)
            assert free.is_valid and free.exterior.is_ccw
            assert spec.shape().contains(free) and free.area < spec.shape().area
            names = [s.name for s in g.surfaces]
            assert names[:2] == ["floor", "ceiling"]
            assert names[2:] == [f"wall_{i}" for i in range(len(g.room.polygon))]
            assert g.surface("floor").subpart == Subpart.Floor
            assert g.surface("floor").origin[2] == pytest.approx(storey.elevation)
            assert g.surface("ceiling").origin[2] == pytest.approx(storey.elevation + storey.height)
            for i in range(len(g.room.polygon)):
                s = g.wall_surface(i)
                assert s.subpart == Subpart.Wall
                mid = s.to_world(np.array([[s.polygon.bounds[2] / 2, 1.0]]))[0]
                inside = mid[:2] + 0.05 * s.normal[:2]
                assert free.buffer(1e-6).contains(sg.Point(inside))
                assert mid[2] == pytest.approx(storey.elevation + 1.0)
            for m in g.collision_meshes():
                assert m.is_watertight and m.volume > 0
            for z in g.door_zones:
                assert free.buffer(1e-6).contains(z)
            for zm in g.door_zone_meshes():
                assert zm.bounds[0][2] == pytest.approx(storey.elevation)
            for d in g.room.doors:   # doors fit their wall of the free polygon
                p = np.asarray(g.room.polygon)
                length = np.linalg.norm(p[(d.wall + 1) % len(p)] - p[d.wall])
                assert d.width / 2 - 1e-6 <= d.offset <= length - d.width / 2 + 1e-6


def test_stairs_and_floor_opening(two_storeys):
    fp, arch = two_storeys
    (st,) = fp.stairs
    flight = next(e for e in arch.elements if e.kind == "stair").meshes["flight"]
    assert flight.is_watertight
    assert flight.bounds[0][2] == pytest.approx(0.0, abs=1e-6)
    assert flight.bounds[1][2] == pytest.approx(fp.storeys[1].elevation, abs=1e-6)
    hole = st.shape()
    upper = next(g for g in arch.rooms.values()
                 if g.storey == 1 and g.plan_polygon.intersection(hole).area > 0)
    assert upper.room.room_type == "staircase_room"
    # the floor slab of the room above has the flight's opening cut out
    c = hole.centroid
    hits = upper.floor.ray.intersects_any(
        np.array([[c.x, c.y, 10.0]]), np.array([[0.0, 0.0, -1.0]]))
    assert not hits[0]
    assert any(z.intersects(hole) for z in upper.door_zones)


def test_usd_stage_layout(two_storeys):
    from pxr import UsdGeom
    fp, arch = two_storeys
    stage = build_architecture_stage(arch)
    assert UsdGeom.GetStageUpAxis(stage) == "Z"
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetPath() == "/World"
    for storey in fp.storeys:
        for r in storey.rooms:
            for part in ("floor", "ceiling", "walls"):
                prim = stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/"
                                           f"{r.name}/{part}")
                assert prim.IsValid(), (r.name, part)
                assert prim.GetAttribute("indoorgen:room").Get() == r.name
        for d in storey.doors:
            assert stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/doors/"
                                       f"{d.name}").IsValid()
        for w in storey.windows:
            assert stage.GetPrimAtPath(f"/World/Architecture/storey_{storey.level}/windows/"
                                       f"{w.name}").IsValid()
    assert stage.GetPrimAtPath("/World/Architecture/stairs/stair_0_1").IsValid()


def test_scene_room_json_is_unchanged_for_single_rooms():
    """`Room.elevation` is written only when set, so single-room scene.json stays as before."""
    r = Room("living_room_0", "living_room", [(0, 0), (4, 0), (4, 3), (0, 3)])
    assert set(r.to_json()) == {"name", "type", "polygon", "height", "wall_thickness",
                                "storey", "doors"}
    up = Room("bedroom_2", "bedroom", [(0, 0), (4, 0), (4, 3), (0, 3)], storey=1, elevation=3.0)
    assert up.to_json()["elevation"] == 3.0
    assert Room.from_json(up.to_json()) == up and Room.from_json(r.to_json()) == r


@pytest.fixture(scope="module")
def catalogue_arch(two_storeys):
    """The two-storey plan solidified with catalogue doors, windows and stairs."""
    return solidify(two_storeys[0], seed=5)


@pytest.mark.xdist_group("catalogue_arch")  # one worker builds the fixture for both tests
def test_catalogue_doors_windows_and_stairs(two_storeys, catalogue_arch):
    fp, _ = two_storeys
    arch = catalogue_arch
    gens = {(e.kind, e.generator) for e in arch.elements}
    assert {("door", "interior_door"), ("door", "exterior_door"), ("window", "window"),
            ("stair", "staircase"), ("railing", "stair_railing")} <= gens
    stair = next(e for e in arch.elements if e.kind == "stair").meshes["stair"]
    (st,) = fp.stairs
    assert st.shape().buffer(0.3).contains(sg.box(*stair.bounds[0][:2], *stair.bounds[1][:2]))
    for e in arch.elements:
        assert all(m.is_watertight for m in e.meshes.values()), e.name
    stage = build_architecture_stage(arch)
    d = fp.storeys[0].doors[0]
    prim = stage.GetPrimAtPath(f"/World/Architecture/storey_0/doors/{d.name}")
    assert prim.GetAttribute("indoorgen:generator").Get() == "interior_door"


@pytest.mark.xdist_group("catalogue_arch")
def test_catalogue_elements_carry_their_own_collision_pieces(catalogue_arch):
    """Doors, windows and stairs from the catalogue bring the asset's convex pieces (placed in
    the world like the mesh), so exporters never decompose them; each piece is convex and lies
    within the element's mesh bounds."""
    for e in catalogue_arch.elements:
        if not e.generator:
            continue
        assert e.collision, e.name
        (mesh,) = e.meshes.values()
        lo, hi = mesh.bounds
        for piece in e.collision:
            assert piece.is_watertight and piece.is_convex, e.name
            assert np.all(piece.bounds[0] >= lo - 0.02), e.name
            assert np.all(piece.bounds[1] <= hi + 0.02), e.name
