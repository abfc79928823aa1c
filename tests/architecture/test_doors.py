"""Door states (open, closed, random, recorded values) and door leaves on their joints in a
solidified home: leaves clear of the opening when open, across it when shut, their sweep inside
the swing zone the solver keeps free."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
import shapely.geometry as sg
import trimesh

from indoorgen.architecture.doors import (
    DOOR_MODES,
    OPEN_ANGLE,
    check_door_mode,
    door_value,
    open_value,
    placed_joint,
    posed,
)
from indoorgen.architecture.solidify import solidify
from indoorgen.assets.protocol import Joint
from indoorgen.errors import ConfigError
from indoorgen.model.floorplan_io import from_json
from support.doors import blocked_heights, door_openings
from support.plans import apartment

HINGE = Joint("leaf_joint", "revolute", np.array([0.0, 0.0, 1.0]), np.zeros(3), 0.0,
              math.radians(95), "leaf")


def test_bad_door_mode_names_the_value_and_the_valid_ones():
    with pytest.raises(ConfigError, match=r"'ajar'.*open, closed, random"):
        check_door_mode("ajar")
    assert [check_door_mode(m) for m in DOOR_MODES] == list(DOOR_MODES)


def test_door_values_by_mode_and_recorded():
    assert door_value("open", 0, "d", HINGE) == pytest.approx(OPEN_ANGLE)
    narrow = Joint("j", "revolute", np.array([0.0, 0.0, 1.0]), np.zeros(3), 0.0, 1.2, "leaf")
    assert open_value(narrow) == pytest.approx(1.2)  # its own limit when smaller than 90 deg
    slide = Joint("j", "prismatic", np.array([0.0, 1.0, 0.0]), np.zeros(3), 0.0, 0.8, "leaf")
    assert open_value(slide) == pytest.approx(0.8)
    assert door_value("closed", 0, "d", HINGE) == 0.0
    assert door_value({"d": 0.7, "e": 9.0}, 0, "d", HINGE) == pytest.approx(0.7)
    assert door_value({"d": 0.7, "e": 9.0}, 0, "e", HINGE) == pytest.approx(HINGE.upper)
    assert door_value({"d": 0.7}, 0, "x", HINGE) == 0.0  # not recorded: shut
    with pytest.raises(ConfigError):
        door_value("ajar", 0, "d", HINGE)


def test_random_doors_draw_per_door_from_the_seed():
    names = [f"door_{i}" for i in range(40)]
    a = [door_value("random", 3, n, HINGE) for n in names]
    assert a == [door_value("random", 3, n, HINGE) for n in names]
    assert sorted(set(a)) == [0.0, OPEN_ANGLE]
    assert 10 <= sum(v > 0 for v in a) <= 30
    assert a != [door_value("random", 4, n, HINGE) for n in names]


def test_posed_turns_a_leaf_about_its_hinge():
    leaf = trimesh.creation.box(bounds=[[-0.02, 0.0, 0.0], [0.0, 0.8, 2.0]])
    m = np.eye(4)
    m[:3, 3] = [5.0, 1.0, 0.0]
    joint = placed_joint(HINGE, m)
    np.testing.assert_allclose(joint.origin, [5.0, 1.0, 0.0])
    open_leaf = posed(leaf.copy().apply_transform(m), joint, math.pi / 2)
    # +90 deg about +Z: the leaf's +Y extent now runs along -X from the hinge
    np.testing.assert_allclose(open_leaf.bounds, [[4.2, 0.98, 0.0], [5.0, 1.0, 2.0]], atol=1e-9)


@pytest.fixture(scope="module")
def homes():
    """The apartment with catalogue doors, open and shut."""
    return {mode: solidify(from_json(apartment()), seed=5, doors=mode)
            for mode in ("open", "closed")}


def _leaves(arch):
    return {e.name: e for e in arch.elements if e.kind == "door"}


def test_every_door_has_a_jointed_leaf(homes):
    for mode, arch in homes.items():
        leaves = _leaves(arch)
        assert set(leaves) == {"d0", "d1", "d2", "entrance"}
        for e in leaves.values():
            assert e.joint is not None and e.joint.kind == "revolute"
            assert e.joint.lower == 0.0 and math.radians(90) <= e.joint.upper <= math.radians(100)
            assert np.allclose(np.abs(e.joint.axis), [0, 0, 1])
            assert "leaf" in e.meshes and e.leaf_collision and e.collision
            assert e.state == pytest.approx(OPEN_ANGLE if mode == "open" else 0.0)
        assert arch.door_states == {n: round(e.state, 6) for n, e in leaves.items()}


def test_open_leaves_clear_the_opening_and_shut_ones_block_it(homes):
    for mode, arch in homes.items():
        leaves = _leaves(arch)
        for name, (centre, normal, elevation) in door_openings(arch).items():
            hits = blocked_heights(leaves[name].meshes["leaf"], centre, normal, elevation)
            assert hits == ([] if mode == "open" else [0.3, 1.0, 1.8]), (mode, name, hits)
            # the frame alone never blocks the opening
            assert blocked_heights(leaves[name].meshes["door"], centre, normal, elevation) == []


def test_open_leaf_stands_in_the_swing_zone(homes):
    """The leaf at its open angle, where it stands on the floor of the room it swings into,
    lies in that room's keep-out zones (which the solver keeps free of furniture)."""
    arch = homes["open"]
    for name, e in _leaves(arch).items():
        geo = arch.rooms[e.room]
        leaf = e.meshes["leaf"]
        foot = shapely.MultiPoint(np.asarray(leaf.vertices)[:, :2]).convex_hull
        on_floor = foot.intersection(sg.Polygon(geo.room.polygon))
        assert on_floor.area > 0.01, name  # it stands in the room, not in the wall
        zones = shapely.union_all(geo.door_zones).buffer(1e-6)
        assert on_floor.difference(zones).area < 1e-6, name
        # and it swings wholly within the room: its sweep from shut to open too
        sweep = shapely.union_all([
            shapely.MultiPoint(np.asarray(posed(leaf, e.joint, -a).vertices)[:, :2]).convex_hull
            for a in np.linspace(0.0, e.state, 7)]).intersection(sg.Polygon(geo.room.polygon))
        assert sweep.difference(zones).area < 1e-6, name
