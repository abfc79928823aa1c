"""Room doors as articulated objects in real homes (issue 11): every door (the front door
included) has its leaf on a joint with limits in URDF (PyBullet loads it), MJCF (MuJoCo compiles
it and the leaves stay put for 2 s) and USD (a UsdPhysics joint with limits and a damping drive
on a rigid-body leaf); open doors leave their openings clear at 0.3, 1.0 and 1.8 m, shut ones
block them, and a re-export from scene.json stands every leaf where it stood."""
from __future__ import annotations

import json
import math
from pathlib import Path
from xml.etree import ElementTree as ET

import mujoco
import pybullet
import pytest
import trimesh
from pxr import Usd, UsdPhysics, UsdValidation

from indoorgen.architecture.rebuild import scene_architecture
from indoorgen.architecture.solidify import solidify
from indoorgen.export.bundle import bundle_from_scene
from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.model.scene import Scene
from support.cli import run
from support.doors import RAY_HEIGHTS, blocked_heights, door_openings
from support.plans import apartment


def _check_joints(gen, d: Path) -> None:
    """Every door of `gen` has its leaf jointed in scene.urdf, scene.xml and scene.usdc."""
    doors = gen.scene.doors
    names = {el.name for el in gen.architecture.elements if el.kind == "door"}
    assert doors and set(doors) == names and "entrance" in doors
    # URDF: a revolute joint from the architecture to each leaf, with limits and dynamics
    robot = ET.parse(d / "scene.urdf").getroot()
    joints = {j.get("name"): j for j in robot.iter("joint")}
    for name, value in doors.items():
        j = joints[f"{name}__leaf_joint"]
        assert j.get("type") == "revolute"
        assert j.find("parent").get("link") == "architecture"
        assert j.find("child").get("link") == f"{name}__leaf"
        lim = j.find("limit")
        lo, hi = float(lim.get("lower")), float(lim.get("upper"))
        # zero is the exported pose: the shut pose at -value, fully open beyond it
        assert lo == pytest.approx(-value, abs=1e-5) and hi > lo + math.radians(89)
        assert float(lim.get("effort")) > 0 and float(lim.get("velocity")) > 0
        assert float(j.find("dynamics").get("damping")) > 0
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(d / "scene.urdf"), useFixedBase=True)
        infos = [pybullet.getJointInfo(body, i, physicsClientId=client)
                 for i in range(pybullet.getNumJoints(body, physicsClientId=client))]
        loaded = {i[1].decode(): i for i in infos}
        for name in doors:
            info = loaded[f"{name}__leaf_joint"]
            assert info[2] == pybullet.JOINT_REVOLUTE and info[9] > info[8]
    finally:
        pybullet.disconnect(client)
    # MJCF: compiles; a hinge per leaf, range shut..open, the leaf starting where it stands
    m = mujoco.MjModel.from_xml_path(str(d / "scene.xml"))
    data = mujoco.MjData(m)
    mujoco.mj_forward(m, data)
    adr = {}
    for name, value in doors.items():
        jid = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_JOINT, f"{name}__leaf_joint")
        assert jid >= 0 and m.jnt_type[jid] == mujoco.mjtJoint.mjJNT_HINGE
        lo, hi = m.jnt_range[jid]
        assert lo == 0.0 and math.radians(89) < hi <= math.radians(100.5)
        assert m.dof_damping[m.jnt_dofadr[jid]] > 0 and m.dof_frictionloss[m.jnt_dofadr[jid]] > 0
        adr[name] = m.jnt_qposadr[jid]
        assert data.qpos[adr[name]] == pytest.approx(value, abs=1e-5)
    for _ in range(int(2.0 / m.opt.timestep)):
        mujoco.mj_step(m, data)
    for name, value in doors.items():
        assert abs(data.qpos[adr[name]] - value) < 0.01, name  # it stays put for 2 s
    # USD: a revolute joint per leaf with limits and a damping drive; the leaf a rigid body
    stage = Usd.Stage.Open(str(d / "scene.usdc"))
    found = {}
    for prim in stage.Traverse():
        if prim.IsA(UsdPhysics.RevoluteJoint) and "/doors/" in str(prim.GetPath()):
            found[prim.GetPath().GetParentPath().GetParentPath().name] = prim
    assert set(found) == set(doors)
    for prim in found.values():
        joint = UsdPhysics.RevoluteJoint(prim)
        assert joint.GetLowerLimitAttr().Get() == pytest.approx(0.0)
        assert 89.0 < joint.GetUpperLimitAttr().Get() <= 100.5
        drive = UsdPhysics.DriveAPI(prim, "angular")
        assert drive and drive.GetDampingAttr().Get() > 0
        assert drive.GetStiffnessAttr().Get() == 0.0
        (leaf,) = joint.GetBody1Rel().GetTargets()
        leaf_prim = stage.GetPrimAtPath(leaf)
        assert leaf_prim.HasAPI(UsdPhysics.RigidBodyAPI) and leaf_prim.HasAPI(UsdPhysics.MassAPI)
        assert UsdPhysics.MassAPI(leaf_prim).GetMassAttr().Get() > 5.0  # a real door leaf
        assert not joint.GetBody0Rel().GetTargets()  # jointed to the world
    assert stage.GetPrimAtPath("/World/PhysicsScene")
    issues = UsdValidation.ValidationContext(
        UsdValidation.ValidationRegistry().GetOrLoadAllValidators()).Validate(stage)
    errors = [e for e in issues if e.GetType() == UsdValidation.ValidationErrorType.Error]
    assert errors == [], [(e.GetName(), e.GetMessage()) for e in errors[:5]]


def _check_rays(scene_json: str, blocked: bool) -> None:
    """Re-export from a scene.json's text and cast rays through every door opening at its
    leaf."""
    scene = Scene.from_json(json.loads(scene_json))
    _, arch = scene_architecture(scene)
    leaves = {e.parent: e for e in bundle_from_scene(scene).elements if e.joint is not None}
    openings = door_openings(arch)
    assert set(leaves) == set(openings) == set(scene.doors)
    for name, (centre, normal, elevation) in openings.items():
        hits = blocked_heights(leaves[name].parts[0].mesh, centre, normal, elevation)
        assert hits == (list(RAY_HEIGHTS) if blocked else []), (name, hits)


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_home_doors_are_jointed_in_every_format(generated_homes, exported_homes, home):
    gen, (_, d) = generated_homes[home], exported_homes[home]
    _check_joints(gen, d)
    assert gen.scene.config["doors"] == "open"
    assert all(v == pytest.approx(math.pi / 2) for v in gen.scene.doors.values())
    # the 2-storey home has doors on both storeys
    storeys = {e.storey for e in gen.architecture.elements if e.kind == "door"}
    assert storeys == set(range(gen.scene.config["floors"]))


@pytest.mark.slow
@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_open_doors_leave_every_opening_clear(generated_homes, exported_homes, home):
    gen, (_, d) = generated_homes[home], exported_homes[home]
    _check_rays(gen.scene.dumps(), blocked=False)
    glb = trimesh.load(d / "scene.glb")
    for name in gen.scene.doors:
        assert glb.graph.transforms.parents[f"{name}_leaf"] == name  # a node of its own


@pytest.mark.slow
def test_closed_doors_from_the_cli_block_openings_and_the_robot(tmp_path):
    # the hand-drawn apartment's living room, bedroom and bathroom: two doors off the room
    # the front door opens into (a whole generated home, kitchen and all, took 40-140 s)
    plan = apartment()
    storey = plan["storeys"][0]
    keep = {"living_room_0", "bedroom_0", "bathroom_0"}
    storey["rooms"] = [r for r in storey["rooms"] if r["name"] in keep]
    for kind in ("doors", "openings"):
        storey[kind] = [d for d in storey[kind] if set(d["rooms"]) <= keep]
    storey["windows"] = [w for w in storey["windows"] if w["room"] in keep]
    (tmp_path / "plan.json").write_text(json.dumps(plan))
    out = tmp_path / "shut"
    r = run("generate", "--seed", "11", "--floorplan", str(tmp_path / "plan.json"),
            "--doors", "closed", "--preset", "fast", "--formats", "mjcf", "-q", "--out", str(out))
    assert r.returncode == 0, r.stderr[-3000:]
    scene = json.loads((out / "scene.json").read_text())
    assert scene["config"]["doors"] == "closed"
    assert scene["doors"] and set(scene["doors"].values()) == {0.0}
    _check_rays((out / "scene.json").read_text(), blocked=True)
    nav = json.loads((out / "report.json").read_text())["navigation"]
    # shut doors wall every room off from the hall inside the front door
    interior = [n for n in scene["doors"] if n != "entrance"]
    assert set(interior) <= set(nav["unreachable_doors"])
    assert nav["unreachable_rooms"]


def test_random_doors_are_reproducible():
    # the door states are drawn with the architecture, before any furniture (a home's
    # scene.doors is `solidify`'s `door_states`)
    plan = generate_floorplan(5, FloorplanConfig(rooms="bedroom=2,bathroom=1,kitchen=1", area=70.0))
    states = solidify(plan, seed=5, doors="random").door_states
    assert states == solidify(plan, seed=5, doors="random").door_states
    assert len(states) > 2 and len(set(states.values())) == 2  # some shut, some open


