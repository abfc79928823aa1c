"""Tests for the basic USD exporter (indoorgen.export.usd)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh
from pxr import Usd, UsdGeom

from indoorgen.assets.base import Asset, box_surfaces
from indoorgen.errors import OutputError
from indoorgen.export.usd import sanitize_name, write_usd
from indoorgen.floorplan.room import build_room, rectangle
from indoorgen.scene import Door, Pose, RelationInstance, Room, Scene, SceneObject


def _box_asset(depth: float, width: float, height: float) -> Asset:
    mesh = trimesh.creation.box((depth, width, height))
    mesh.apply_translation((0, 0, height / 2))
    return Asset(mesh, box_surfaces(depth, width, height))


@pytest.fixture(scope="module")
def tiny():
    room = Room("living room", "living_room", rectangle(4.0, 3.0), doors=[Door("door_0", 0, 1.0)])
    scene = Scene(seed=5, rooms={room.name: room})
    table = SceneObject(
        "table_0", "side_table", {"h": 0.5}, 11, Pose((2.0, 1.5, 0.0), math.radians(30)),
        ["furniture", "table", "side_table"], room.name,
        relations=[RelationInstance("StableAgainst", room.name, "bottom", "floor")])
    cup = SceneObject(
        "cup-0", "cup", {}, 12, Pose((2.1, 1.4, 0.5), -1.0), ["small_object", "cup"], room.name,
        relations=[RelationInstance("StableAgainst", "table_0", "bottom", "top")])
    scene.add_object(table)
    scene.add_object(cup)
    assets = {"table_0": _box_asset(0.6, 0.8, 0.5), "cup-0": _box_asset(0.08, 0.08, 0.1)}
    return scene, assets, {room.name: build_room(room)}


@pytest.mark.parametrize("ext", [".usda", ".usdc"])
def test_write_and_reopen(tmp_path, tiny, ext):
    scene, assets, rooms = tiny
    out = tmp_path / f"scene{ext}"
    write_usd(scene, out, object_assets=assets, rooms=rooms)
    assert out.exists()
    if ext == ".usda":
        assert out.read_text().startswith("#usda")
    else:
        assert out.read_bytes().startswith(b"PXR-USDC")

    stage = Usd.Stage.Open(str(out))
    assert UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z
    assert UsdGeom.GetStageMetersPerUnit(stage) == 1.0
    assert stage.GetDefaultPrim().GetPath() == "/World"

    # architecture
    room_path = "/World/Architecture/living_room"
    room_prim = stage.GetPrimAtPath(room_path)
    assert room_prim.IsValid()
    assert room_prim.GetAttribute("indoorgen:name").Get() == "living room"
    for elem, tag in [("floor", "floor"), ("ceiling", "ceiling")] + [
            (f"wall_{i}", "wall") for i in range(4)]:
        prim = stage.GetPrimAtPath(f"{room_path}/{elem}")
        assert prim.IsA(UsdGeom.Xform), elem
        assert list(prim.GetAttribute("indoorgen:semantics").Get()) == [tag]
        assert prim.GetAttribute("indoorgen:room").Get() == "living room"
        assert prim.GetAttribute("indoorgen:parent").Get() == ""
        assert prim.GetAttribute("indoorgen:generator").Get() == tag
        mesh = UsdGeom.Mesh(stage.GetPrimAtPath(f"{room_path}/{elem}/mesh"))
        assert len(mesh.GetPointsAttr().Get()) > 0
    floor_mesh = UsdGeom.Mesh(stage.GetPrimAtPath(f"{room_path}/floor/mesh"))
    np.testing.assert_allclose(np.array(floor_mesh.GetExtentAttr().Get()),
                               rooms["living room"].floor.bounds, atol=1e-5)

    # objects
    cache = UsdGeom.XformCache()
    for name, ident in [("table_0", "table_0"), ("cup-0", "cup_0")]:
        obj = scene.objects[name]
        prim = stage.GetPrimAtPath(f"/World/Objects/{ident}")
        assert prim.IsValid() and prim.IsA(UsdGeom.Xform)
        assert prim.GetAttribute("indoorgen:name").Get() == name
        assert prim.GetAttribute("indoorgen:generator").Get() == obj.generator
        assert prim.GetAttribute("indoorgen:room").Get() == obj.room
        assert prim.GetAttribute("indoorgen:parent").Get() == obj.parent
        assert list(prim.GetAttribute("indoorgen:semantics").Get()) == sorted(obj.tags)
        ops = [op.GetOpType() for op in UsdGeom.Xformable(prim).GetOrderedXformOps()]
        assert ops == [UsdGeom.XformOp.TypeTranslate, UsdGeom.XformOp.TypeRotateZ]
        m = np.array(UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(
            Usd.TimeCode.Default())).T  # USD uses row vectors
        np.testing.assert_allclose(m, obj.pose.matrix(), atol=1e-9)

        mesh_prim = stage.GetPrimAtPath(f"/World/Objects/{ident}/mesh")
        mesh = UsdGeom.Mesh(mesh_prim)
        pts = np.array(mesh.GetPointsAttr().Get())
        asset_mesh = assets[name].mesh
        np.testing.assert_allclose(pts, asset_mesh.vertices, atol=1e-6)
        assert list(mesh.GetFaceVertexCountsAttr().Get()) == [3] * len(asset_mesh.faces)
        np.testing.assert_array_equal(np.array(mesh.GetFaceVertexIndicesAttr().Get()),
                                      asset_mesh.faces.reshape(-1))
        np.testing.assert_allclose(np.array(mesh.GetExtentAttr().Get()), asset_mesh.bounds,
                                   atol=1e-6)
        # world points of the mesh agree with the pose applied to the local vertices
        world = np.array(cache.GetLocalToWorldTransform(mesh_prim)).T
        pts_w = pts @ world[:3, :3].T + world[:3, 3]
        np.testing.assert_allclose(pts_w, obj.pose.apply(asset_mesh.vertices), atol=1e-5)


def test_missing_asset_still_writes_object(tmp_path, tiny):
    scene, assets, rooms = tiny
    out = tmp_path / "partial.usda"
    write_usd(scene, out, object_assets={"table_0": assets["table_0"]}, rooms={})
    stage = Usd.Stage.Open(str(out))
    assert stage.GetPrimAtPath("/World/Objects/cup_0").IsValid()
    assert not stage.GetPrimAtPath("/World/Objects/cup_0/mesh").IsValid()
    assert stage.GetPrimAtPath("/World/Architecture/living_room").IsValid()


def test_bad_output_paths(tmp_path, tiny):
    scene, assets, rooms = tiny
    with pytest.raises(OutputError, match="must end in"):
        write_usd(scene, tmp_path / "scene.obj", object_assets=assets, rooms=rooms)
    with pytest.raises(OutputError, match="does not exist"):
        write_usd(scene, tmp_path / "nope" / "scene.usda", object_assets=assets, rooms=rooms)


def test_sanitize_name():
    assert sanitize_name("table_0") == "table_0"
    assert sanitize_name("cup-0") == "cup_0"
    assert sanitize_name("3 chairs") == "_3_chairs"
