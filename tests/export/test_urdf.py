"""URDF export loaded by the real consumers: yourdfpy and PyBullet."""
from __future__ import annotations

from xml.etree import ElementTree as ET

import numpy as np
import pybullet as pb
import pytest
import yourdfpy

#: the deepest a moving part's convex pieces may sink into its body's (m; contact margins)
PENETRATION_TOL = 0.006
@pytest.fixture
def bullet():
    cid = pb.connect(pb.DIRECT)
    yield cid
    pb.disconnect(cid)


def _urdfs(d):
    return [d / "scene.urdf", *sorted((d / "urdf").glob("*.urdf"))]


@pytest.mark.parametrize("room", ["living_room", "dining_room"])
def test_yourdfpy_loads_every_file(exported, room):
    bundle, d, _ = exported[room]
    files = _urdfs(d)
    assert len(files) == len(bundle.objects) + 2
    for f in files:
        robot = yourdfpy.URDF.load(str(f), load_meshes=True, load_collision_meshes=True)
        assert robot.scene is not None and len(robot.scene.geometry) > 0, f.name
    scene = yourdfpy.URDF.load(str(d / "scene.urdf"))
    assert scene.base_link == "world"
    fixed = {j.child for j in scene.robot.joints if j.parent == "world" and j.type == "fixed"}
    assert fixed == {"architecture"} | {f"{o.name}__base" for o in bundle.objects}
    # relative paths only
    for f in files:
        for m in ET.parse(f).getroot().iter("mesh"):
            assert not m.get("filename").startswith("/")


@pytest.mark.parametrize("room", ["dining_room"])
def test_pybullet_loads_scene_and_objects(exported, room, bullet):
    bundle, d, _ = exported[room]
    body = pb.loadURDF(str(d / "scene.urdf"), useFixedBase=True, physicsClientId=bullet)
    n_links = sum(len(bundle.assets[o.name].links) for o in bundle.objects) + 1
    assert pb.getNumJoints(body, physicsClientId=bullet) == n_links
    for f in sorted((d / "urdf").glob("*.urdf")):
        b = pb.loadURDF(str(f), useFixedBase=True, physicsClientId=bullet)
        assert b >= 0
    # masses come from volume x density: a chair weighs kilograms, a mug a fraction of one
    masses = {o.generator: bundle.inertials(o.name)["base"].mass for o in bundle.objects}
    if "dining_chair" in masses:
        assert 1.0 < masses["dining_chair"] < 30.0
    if "mug" in masses:
        assert 0.05 < masses["mug"] < 1.5


def _sweep(urdf: str, cid: int) -> list[tuple[str, float]]:
    """(joint, deepest penetration of its part into the body) over 7 values of its range."""
    b = pb.loadURDF(urdf, useFixedBase=True, flags=pb.URDF_USE_SELF_COLLISION,
                    physicsClientId=cid)
    out = []
    for j in range(pb.getNumJoints(b, physicsClientId=cid)):
        info = pb.getJointInfo(b, j, physicsClientId=cid)
        if info[2] not in (pb.JOINT_REVOLUTE, pb.JOINT_PRISMATIC):
            continue
        lo, hi = info[8], info[9]
        assert hi > lo
        deepest = 0.0
        for q in np.linspace(lo, hi, 7):
            pb.resetJointState(b, j, q, physicsClientId=cid)
            state = pb.getLinkState(b, j, computeForwardKinematics=True, physicsClientId=cid)
            assert state is not None
            pts = pb.getClosestPoints(b, b, 0.0, linkIndexA=j, linkIndexB=-1,
                                      physicsClientId=cid)
            deepest = min([deepest, *[p[8] for p in pts]])
        pb.resetJointState(b, j, 0.0, physicsClientId=cid)
        out.append((info[1].decode(), deepest))
    return out


def test_pybullet_joints_move_through_their_range_clear_of_the_body(articulated, bullet):
    bundle, d = articulated
    problems, checked = [], 0
    for obj in bundle.objects:
        joints = _sweep(str(d / "urdf" / f"{obj.name}.urdf"), bullet)
        assert len(joints) == len(bundle.assets[obj.name].joints), obj.name
        bad = [(n, round(p, 4)) for n, p in joints if p < -PENETRATION_TOL]
        checked += len(joints)
        if bad:
            problems.append((obj.name, bad))
    assert checked >= len(bundle.objects)
    assert problems == []


def test_exported_urdf_collisions_are_the_asset_pieces(exported):
    """Every object URDF holds one <collision> per convex piece, boxes as <box>; a rug has
    none (as in MJCF and USD: furniture stands on the floor through it)."""
    bundle, d, _ = exported["living_room"]
    kinds = {"box": 0, "mesh": 0}
    rugs = 0
    for obj in bundle.objects:
        root = ET.parse(d / "urdf" / f"{obj.name}.urdf").getroot()
        cols = root.findall(".//collision/geometry/*")
        rugs += bundle.lies_under(obj)
        want = 0 if bundle.lies_under(obj) else len(bundle.assets[obj.name].collision)
        assert len(cols) == want, obj.name
        for c in cols:
            kinds[c.tag] += 1
    assert kinds["box"] > 0 and kinds["mesh"] > 0 and rugs >= 1


def test_every_joint_has_limits_effort_velocity_and_damping(articulated):
    _, d = articulated
    joints = [j for f in _urdfs(d) for j in ET.parse(f).getroot().iter("joint")
              if j.get("type") in ("revolute", "prismatic")]
    assert joints
    for j in joints:
        lim, dyn = j.find("limit"), j.find("dynamics")
        assert lim is not None and dyn is not None, j.get("name")
        assert float(lim.get("upper")) > float(lim.get("lower"))
        assert float(lim.get("effort")) > 0 and float(lim.get("velocity")) > 0
        assert float(dyn.get("damping")) > 0


def test_moving_parts_collision_follows_their_links(articulated, bullet):
    """Opening a joint carries its link's collision shapes with it: a drawer's pieces slide
    out by the joint's travel, a door's swing away from where they stood shut."""
    bundle, d = articulated
    moved = 0
    for obj in bundle.objects:
        b = pb.loadURDF(str(d / "urdf" / f"{obj.name}.urdf"), useFixedBase=True,
                        physicsClientId=bullet)
        for j in range(pb.getNumJoints(b, physicsClientId=bullet)):
            info = pb.getJointInfo(b, j, physicsClientId=bullet)
            if info[2] not in (pb.JOINT_REVOLUTE, pb.JOINT_PRISMATIC):
                continue
            lo, hi = info[8], info[9]
            shut = np.array(pb.getAABB(b, j, physicsClientId=bullet))
            pb.resetJointState(b, j, hi if abs(hi) >= abs(lo) else lo, physicsClientId=bullet)
            opened = np.array(pb.getAABB(b, j, physicsClientId=bullet))
            pb.resetJointState(b, j, 0.0, physicsClientId=bullet)
            travel = np.abs(opened - shut).max()
            if info[2] == pb.JOINT_PRISMATIC:
                assert np.isclose(travel, max(abs(lo), abs(hi)), atol=0.02), info[1]
            else:
                assert travel > 0.01, info[1]
            moved += 1
    assert moved >= len(bundle.objects)


@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_pybullet_loads_the_homes(exported_homes, home, bullet):
    bundle, d = exported_homes[home]
    body = pb.loadURDF(str(d / "scene.urdf"), useFixedBase=True, physicsClientId=bullet)
    n_links = sum(len(bundle.assets[o.name].links) for o in bundle.objects) + 1 + len(
        bundle.moving_elements)
    assert pb.getNumJoints(body, physicsClientId=bullet) == n_links


def test_hung_garments_and_drawer_contents_are_fixed_to_their_links(articulated):
    bundle, d = articulated
    robot = ET.parse(d / "scene.urdf").getroot()
    parents = {j.find("child").get("link"): j for j in robot.iter("joint")}
    garments = [o.name for o in bundle.objects if o.generator == "hung_garment"]
    assert garments
    for g in garments:
        j = parents[f"{g}__base"]
        assert j.get("type") == "fixed" and j.find("parent").get("link") == "wardrobe_0__base"
    j = parents["folded_clothes_0__base"]  # in a drawer: fixed to the drawer
    assert j.get("type") == "fixed" and j.find("parent").get("link") == "dresser_0__drawer_0"
