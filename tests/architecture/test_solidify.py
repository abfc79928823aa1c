"""Solidified homes: predefined and generated plans as solids, rooms that behave like a single
room's RoomGeometry, stairs and floor openings, catalogue doors, windows and stairs."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.architecture.room import RoomGeometry
from indoorgen.architecture.solidify import HomeRoomGeometry, solidify
from indoorgen.assets.cache import AssetCache
from indoorgen.constraints.sets import scene
from indoorgen.errors import InvalidGeometryError
from indoorgen.model.floorplan_io import from_json
from indoorgen.model.scene import Room
from indoorgen.model.tags import Semantics, Subpart
from indoorgen.programs import get_program
from indoorgen.solver.stages import solve
from indoorgen.solver.state import State
from support.plans import apartment, two_storey_home


def test_predefined_plan_solidifies():
    arch = solidify(from_json(apartment()))
    assert set(arch.rooms) == {r["name"] for r in apartment()["storeys"][0]["rooms"]}
    kinds = sorted(e.kind for e in arch.elements)
    assert kinds == ["door"] * 4 + ["window"] * 3   # three doors and the entrance
    living = arch.rooms["living_room_0"]
    assert {d.name for d in living.room.doors} == {"d0", "d1", "o0", "entrance"}


def test_door_off_its_wall_is_rejected_when_solidifying():
    d = apartment()
    d["storeys"][0]["doors"][0]["center"] = [2.5, 3.0]
    with pytest.raises(InvalidGeometryError, match="d0"):
        solidify(from_json(d))


@pytest.fixture(scope="module")
def two_storeys():
    return two_storey_home()


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


def test_railings_stand_free_of_walls_and_doorways(two_storeys):
    fp, arch = two_storeys
    (st,) = fp.stairs
    _, head_room = fp.stair_rooms(st)
    room = fp.storeys[1].room(head_room)
    outline = room.shape().exterior
    rails = [e for e in arch.elements if e.kind == "railing"]
    assert rails
    doorways = [sg.Point(d.center).buffer(d.width / 2)
                for d in fp.storeys[1].doors + fp.storeys[1].openings if head_room in d.rooms]
    for e in rails:
        for m in e.meshes.values():
            pts = [sg.Point(p) for p in m.vertices[:, :2]]
            # no rail inside a wall (the wall guards that side) nor across a doorway
            assert min(outline.distance(p) for p in pts) > 0.02
            assert not any(dw.contains(p) for dw in doorways for p in pts)


def test_garage_gets_a_vehicle_door_in_its_outside_wall():
    d = apartment()
    d["storeys"][0]["rooms"][4]["type"] = "garage"   # bedroom_1: its east wall is outside
    d["vehicle_doors"] = [{"room": "bedroom_1", "center": [10.0, 6.5], "width": 2.4,
                           "height": 2.1}]
    arch = solidify(from_json(d))
    (gd,) = [e for e in arch.elements if e.kind == "vehicle_door"]
    assert gd.room == "bedroom_1" and "garage_door" in gd.semantics
    assert all(m.is_watertight for m in gd.meshes.values())
    garage = arch.rooms["bedroom_1"]
    assert "vehicle_door_bedroom_1" in {dr.name for dr in garage.room.doors}
    # the wall is open through the door's middle, closed beside it
    walls = garage.walls[0]
    through = walls.ray.intersects_any(np.array([[9.0, 6.5, 1.0], [9.0, 5.1, 1.0]]),
                                       np.array([[1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]))
    panel = gd.meshes["panel"].ray.intersects_any(np.array([[9.0, 6.5, 1.0]]),
                                                  np.array([[1.0, 0.0, 0.0]]))
    assert list(through) == [False, True] and panel[0]


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


@pytest.mark.xdist_group("catalogue_arch")
def test_catalogue_elements_carry_their_own_collision_pieces(catalogue_arch):
    """Doors, windows and stairs from the catalogue bring the asset's convex pieces (placed in
    the world like the mesh), so exporters never decompose them; each piece is convex and lies
    within the element's mesh bounds (a door's leaf: its own pieces within the leaf)."""
    for e in catalogue_arch.elements:
        if not e.generator:
            continue
        assert e.collision, e.name
        assert set(e.meshes) == ({e.kind, "leaf"} if e.joint is not None else {e.kind})
        parts = [(e.meshes[e.kind], e.collision)]
        if e.joint is not None:
            assert e.leaf_collision, e.name
            parts.append((e.meshes["leaf"], e.leaf_collision))
        for mesh, pieces in parts:
            lo, hi = mesh.bounds
            for piece in pieces:
                assert piece.is_watertight and piece.is_convex, e.name
                assert np.all(piece.bounds[0] >= lo - 0.02), e.name
                assert np.all(piece.bounds[1] <= hi + 0.02), e.name


@pytest.mark.slow
def test_existing_object_solver_furnishes_an_upper_storey_room(two_storeys):
    _, arch = two_storeys
    name = next(n for n, g in arch.rooms.items()
                if g.storey == 1 and g.room.room_type == "living_room")
    geom = arch.rooms[name]
    state = State({name: geom}, AssetCache())
    problem = get_program("living_room")(scene()[Semantics.Room].named(name))
    solve(state, {name: problem}, 0, steps={"large": 60, "medium": 30, "small": 30})
    assert len(state.objects) > 3
    free = sg.Polygon(geom.room.polygon).buffer(0.01)
    for o, ob in state.objects.items():
        assert free.contains(state.footprint(o)), o
        assert ob.position[2] >= geom.elevation - 1e-6
