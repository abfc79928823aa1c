"""Tests for one room's solid architecture (indoorgen.architecture.room)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.architecture.room import RoomGeometry, build_room, l_shape, place_door, rectangle
from indoorgen.errors import InvalidGeometryError
from indoorgen.model.polygons import validate_polygon
from indoorgen.model.scene import Door, Room
from indoorgen.model.tags import Subpart


def _rect_room(**kw) -> Room:
    return Room("living", "living_room", rectangle(5.0, 4.0), **kw)


def _l_room(**kw) -> Room:
    return Room("l", "living_room", l_shape(6.0, 5.0, 2.5, 2.0), **kw)


# ---------------------------------------------------------------- polygons


def test_rectangle_and_l_shape_are_ccw_and_valid():
    for pts, area in [(rectangle(5, 4), 20.0), (l_shape(6, 5, 2.5, 2), 30.0 - 5.0)]:
        poly = validate_polygon(pts)
        assert poly.exterior.is_ccw
        assert poly.area == pytest.approx(area)


def test_build_room_rejects_bad_polygon_and_bad_door():
    with pytest.raises(InvalidGeometryError):
        build_room(Room("r", "living_room", [(0, 0), (2, 2), (2, 0), (0, 2)]))
    with pytest.raises(InvalidGeometryError, match="does not fit"):
        build_room(_rect_room(doors=[Door("d", 0, 4.8)]))
    with pytest.raises(InvalidGeometryError, match="wall 7"):
        build_room(_rect_room(doors=[Door("d", 7, 1.0)]))


# ---------------------------------------------------------------- doors


def test_place_door_respects_wall_length_and_margins():
    room = _l_room()
    lengths = np.linalg.norm(np.roll(room.polygon, -1, axis=0) - np.asarray(room.polygon), axis=1)
    rng = np.random.default_rng(3)
    for _ in range(50):
        d = place_door(room, rng, width=0.9)
        assert lengths[d.wall] >= 0.9 + 0.4
        assert 0.2 + 0.45 - 1e-9 <= d.offset <= lengths[d.wall] - 0.2 - 0.45 + 1e-9


def test_place_door_is_deterministic_and_avoids_existing_doors():
    room = Room("small", "closet", rectangle(1.4, 1.4))
    a = place_door(room, np.random.default_rng(7))
    b = place_door(room, np.random.default_rng(7))
    assert a == b
    room.doors.append(a)
    c = place_door(room, np.random.default_rng(1))
    assert c.wall != a.wall  # a 1.4 m wall holds only one 0.9 m door
    assert c.name != a.name


def test_place_door_fails_when_no_wall_is_long_enough():
    room = Room("tiny", "closet", rectangle(1.0, 1.0))
    with pytest.raises(InvalidGeometryError, match="long enough"):
        place_door(room, np.random.default_rng(0))


# ---------------------------------------------------------------- geometry


@pytest.fixture(scope="module")
def rect_geo() -> RoomGeometry:
    return build_room(_rect_room(doors=[Door("d0", 0, 2.0), Door("d1", 1, 3.0, width=0.8)]))


@pytest.fixture(scope="module")
def l_geo() -> RoomGeometry:
    return build_room(_l_room(doors=[Door("d0", 3, 1.0)]))


@pytest.fixture(params=["rect", "l"])
def geo(request, rect_geo, l_geo) -> RoomGeometry:
    return rect_geo if request.param == "rect" else l_geo


def test_meshes_are_watertight(geo):
    assert len(geo.walls) == len(geo.room.polygon)
    for m in geo.collision_meshes():
        assert m.is_watertight and m.volume > 0


def test_slabs(geo):
    room = geo.room
    t = room.wall_thickness
    poly = sg.Polygon(room.polygon)
    assert geo.floor.bounds[1, 2] == pytest.approx(0.0)
    assert geo.floor.bounds[0, 2] == pytest.approx(-0.1)
    assert geo.ceiling.bounds[0, 2] == pytest.approx(room.height)
    # slabs cover the polygon grown by the wall thickness (mitred)
    grown = poly.buffer(t, join_style="mitre")
    assert geo.floor.volume == pytest.approx(grown.area * 0.1, rel=1e-6)
    assert geo.ceiling.volume == pytest.approx(grown.area * 0.1, rel=1e-6)


def test_walls_lie_outside_with_inner_face_on_edge(geo):
    room = geo.room
    p = np.asarray(room.polygon, float)
    q = np.roll(p, -1, axis=0)
    door_walls = {d.wall for d in room.doors}
    for i, wall in enumerate(geo.walls):
        d = (q[i] - p[i]) / np.linalg.norm(q[i] - p[i])
        n_in = np.array([-d[1], d[0]])
        # sample along the middle of the edge, away from corners and door openings
        ts = np.linspace(0.3, 0.7, 5) if i not in door_walls else np.array([0.02, 0.98])
        base = p[i] + ts[:, None] * (q[i] - p[i])
        z = np.full((len(ts), 1), 2.4)
        outside = np.hstack([base - 0.01 * n_in, z])
        inside = np.hstack([base + 0.01 * n_in, z])
        assert wall.contains(outside).all(), f"wall {i} missing just outside its edge"
        assert not wall.contains(inside).any(), f"wall {i} protrudes into the room"
        # no vertex inside the room
        xy = wall.vertices[:, :2]
        assert (((xy - p[i]) @ n_in) <= 1e-9).all()
        # thickness is the room's wall thickness
        assert ((xy - p[i]) @ n_in).min() == pytest.approx(-room.wall_thickness)


def test_walls_tile_the_ring_without_gaps_or_overlaps(geo):
    """Mitred walls exactly fill the band between the polygon and its outward offset: their
    volumes add up to band area x height less the door openings."""
    room = geo.room
    poly = sg.Polygon(room.polygon)
    band = poly.buffer(room.wall_thickness, join_style="mitre").area - poly.area
    openings = sum(d.width * room.wall_thickness * d.height for d in room.doors)
    total = sum(w.volume for w in geo.walls)
    assert total == pytest.approx(band * room.height - openings, rel=1e-6)
    # each pair of neighbouring walls shares its mitre face: the corner column is filled
    ring = poly.buffer(room.wall_thickness / 2, join_style="mitre").exterior
    pts = np.asarray(ring.coords)[:-1]
    mid = (pts + np.roll(pts, -1, axis=0)) / 2  # edge midpoints of the half-offset ring
    pts3 = np.hstack([mid, np.full((len(mid), 1), 2.5)])
    inside_any = np.zeros(len(mid), bool)
    for w in geo.walls:
        inside_any |= w.contains(pts3)
    assert inside_any.all()


def test_door_zone_clipped_to_room_near_corner():
    geo = build_room(_l_room(doors=[Door("d0", 3, 1.5)]))
    zone = geo.door_zones[0]
    assert sg.Polygon(geo.room.polygon).buffer(1e-9).contains(zone)
    assert zone.area < 1.1


def test_door_openings_are_cut(rect_geo):
    room = rect_geo.room
    p = np.asarray(room.polygon, float)
    q = np.roll(p, -1, axis=0)
    for door in room.doors:
        d = (q[door.wall] - p[door.wall]) / np.linalg.norm(q[door.wall] - p[door.wall])
        n_out = np.array([d[1], -d[0]])
        centre = p[door.wall] + door.offset * d + n_out * room.wall_thickness / 2
        wall = rect_geo.walls[door.wall]
        assert not wall.contains([[*centre, 1.0]]).any()
        # the wall is still there above the door and beside it
        assert wall.contains([[*centre, door.height + 0.3]]).all()
        beside = centre + d * (door.width / 2 + 0.1)
        assert wall.contains([[*beside, 1.0]]).all()


def test_door_zones_inside_room(geo):
    poly = sg.Polygon(geo.room.polygon)
    assert len(geo.door_zones) == len(geo.room.doors)
    for door, zone in zip(geo.room.doors, geo.door_zones, strict=False):
        assert zone.area > 0
        assert poly.buffer(1e-9).contains(zone)
        assert zone.area == pytest.approx((door.width + 0.2) * door.clearance_depth)
    meshes = geo.door_zone_meshes(height=2.0)
    assert len(meshes) == len(geo.door_zones)
    for m, z in zip(meshes, geo.door_zones, strict=False):
        assert m.is_watertight
        assert m.bounds[0, 2] == pytest.approx(0.0) and m.bounds[1, 2] == pytest.approx(2.0)
        assert m.volume == pytest.approx(z.area * 2.0)


def test_floor_and_ceiling_surfaces(geo):
    room = geo.room
    poly = sg.Polygon(room.polygon)
    floor = geo.surface("floor")
    assert floor.subpart == Subpart.Floor
    np.testing.assert_allclose(floor.normal, [0, 0, 1])
    np.testing.assert_allclose(floor.v, [0, 1, 0])
    fw = floor.corners()
    assert np.allclose(fw[:, 2], 0)
    assert sg.Polygon(fw[:, :2]).equals(poly)

    ceil = geo.surface("ceiling")
    assert ceil.subpart == Subpart.Ceiling
    np.testing.assert_allclose(ceil.normal, [0, 0, -1])
    cw = ceil.corners()
    assert np.allclose(cw[:, 2], room.height)
    assert sg.Polygon(cw[:, :2]).equals(poly)
    assert ceil.polygon.exterior.is_ccw


def test_wall_surfaces_map_to_world(geo):
    room = geo.room
    p = np.asarray(room.polygon, float)
    q = np.roll(p, -1, axis=0)
    h = room.height
    walls = [s for s in geo.surfaces if s.subpart == Subpart.Wall]
    assert len(walls) == len(p)
    for i in range(len(p)):
        s = geo.wall_surface(i)
        assert s.name == f"wall_{i}"
        length = np.linalg.norm(q[i] - p[i])
        d = (q[i] - p[i]) / length
        np.testing.assert_allclose(s.normal, [-d[1], d[0], 0], atol=1e-12)
        np.testing.assert_allclose(np.linalg.norm(s.normal), 1.0)
        np.testing.assert_allclose(s.u[2], 0.0)
        np.testing.assert_allclose(s.v, [0, 0, 1], atol=1e-12)
        assert s.polygon.equals(sg.box(0, 0, length, h))
        uv = np.array([[0, 0], [length, 0], [length, h], [0, h]])
        world = s.to_world(uv)
        expect = np.array([[*q[i], 0], [*p[i], 0], [*p[i], h], [*q[i], h]])
        np.testing.assert_allclose(world, expect, atol=1e-9)
        # the surface's plane is the wall's inner face: points on it sit on the mesh boundary
        mid = s.to_world([[length / 2, h - 0.1]])[0]
        dist = geo.walls[i].nearest.signed_distance([mid])
        assert abs(dist[0]) < 1e-6


def test_clockwise_room_is_rejected():
    with pytest.raises(InvalidGeometryError, match="clockwise"):
        build_room(Room("cw", "living_room", list(reversed(rectangle(4, 3)))))
