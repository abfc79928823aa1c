"""Tests for the basic USD exporter (indoorgen.export.usd)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh
from pxr import Usd, UsdGeom

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets.protocol import Asset, box_surfaces
from indoorgen.constraints import SupportedBy
from indoorgen.errors import OutputError
from indoorgen.export.usd.prims import CONTACT_GAP, sanitize_name
from indoorgen.export.usd.scene import write_usd
from indoorgen.model.scene import Door, Pose, RelationInstance, Room, Scene, SceneObject


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
        relations=[RelationInstance(repr(SupportedBy()), room.name, "bottom", "floor")])
    cup = SceneObject(
        "cup-0", "cup", {}, 12, Pose((2.1, 1.4, 0.5), -1.0), ["small_object", "cup"], room.name,
        relations=[RelationInstance(repr(SupportedBy()), "table_0", "bottom", "top")])
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
        # the mesh is named for the room and element: importers show that name
        mesh = UsdGeom.Mesh(stage.GetPrimAtPath(f"{room_path}/{elem}/living_room_{elem}"))
        assert len(mesh.GetPointsAttr().Get()) > 0
    floor_mesh = UsdGeom.Mesh(stage.GetPrimAtPath(f"{room_path}/floor/living_room_floor"))
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

        mesh_prim = stage.GetPrimAtPath(f"/World/Objects/{ident}/{ident}")
        mesh = UsdGeom.Mesh(mesh_prim)
        pts = np.array(mesh.GetPointsAttr().Get())
        asset_mesh = assets[name].mesh
        # the same triangles in the same order (points welded, so indexed differently)
        assert list(mesh.GetFaceVertexCountsAttr().Get()) == [3] * len(asset_mesh.faces)
        tri = pts[np.array(mesh.GetFaceVertexIndicesAttr().Get()).reshape(-1, 3)]
        np.testing.assert_allclose(tri, asset_mesh.vertices[asset_mesh.faces], atol=1e-6)
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
    assert not stage.GetPrimAtPath("/World/Objects/cup_0/cup_0").IsValid()
    assert stage.GetPrimAtPath("/World/Objects/table_0/table_0").IsA(UsdGeom.Mesh)
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


# --------------------------------------------------------------------------------------------
# the full exporter on generated rooms

from pathlib import Path  # noqa: E402

from pxr import Sdf, UsdPhysics, UsdSemantics, UsdShade, UsdValidation  # noqa: E402

from indoorgen.export.bundle import make_bundle  # noqa: E402
from indoorgen.export.textures import TextureStore  # noqa: E402
from indoorgen.export.usd.scene import write_usd_bundle  # noqa: E402


def _validate(stage):
    """Run every validator of the UsdValidation registry; (validator names, errors)."""
    reg = UsdValidation.ValidationRegistry()
    validators = reg.GetOrLoadAllValidators()
    issues = UsdValidation.ValidationContext(validators).Validate(stage)
    errors = [e for e in issues if e.GetType() == UsdValidation.ValidationErrorType.Error]
    return sorted(v.GetMetadata().name for v in validators), errors


@pytest.mark.parametrize("room", ["living_room", "dining_room"])
def test_validators_report_no_errors(exported, room, record_property):
    bundle, d, _ = exported[room]
    stage = Usd.Stage.Open(str(d / "scene.usdc"))
    names, errors = _validate(stage)
    record_property("validators", names)
    # the registry's core, geometry, shading, physics, lux and utils validators all ran
    for v in ("usdValidation:CompositionErrorTest", "usdGeomValidators:StageMetadataChecker",
              "usdShadeValidators:ShaderSdrCompliance", "usdShadeValidators:NormalMapTextureValidator",
              "usdPhysicsValidators:RigidBodyChecker", "usdPhysicsValidators:ColliderChecker",
              "usdLuxValidators:EncapsulationRulesValidator",
              "usdUtilsValidators:MissingReferenceValidator"):
        assert v in names
    assert len(names) >= 25
    assert errors == [], [(e.GetName(), e.GetMessage()) for e in errors[:5]]


@pytest.mark.xdist_group("export_homes")
@pytest.mark.parametrize("home", ["home1", "home2"])
def test_validators_report_no_errors_on_homes(exported_homes, home):
    _, d = exported_homes[home]
    _, errors = _validate(Usd.Stage.Open(str(d / "scene.usdc")))
    assert errors == [], [(e.GetName(), e.GetMessage()) for e in errors[:5]]


@pytest.mark.parametrize("room", ["living_room", "dining_room"])
def test_every_object_has_attributes_labels_and_physics(exported, room):
    bundle, d, _ = exported[room]
    stage = Usd.Stage.Open(str(d / "scene.usdc"))
    assert stage.GetPrimAtPath("/World/PhysicsScene").IsA(UsdPhysics.Scene)
    for obj in bundle.objects:
        prim = stage.GetPrimAtPath(f"/World/Objects/{obj.name}")
        assert prim.IsValid(), obj.name
        assert prim.GetAttribute("indoorgen:generator").Get() == obj.generator
        assert prim.GetAttribute("indoorgen:room").Get() == obj.room
        assert prim.GetAttribute("indoorgen:parent").Get() == obj.parent
        assert list(prim.GetAttribute("indoorgen:semantics").Get()) == sorted(obj.tags)
        labels = UsdSemantics.LabelsAPI(prim, "class").GetLabelsAttr().Get()
        assert sorted(labels) == sorted(obj.tags)
        if bundle.assets[obj.name].joints:
            assert prim.HasAPI(UsdPhysics.ArticulationRootAPI)
            base = stage.GetPrimAtPath(f"/World/Objects/{obj.name}/base")
            assert base.HasAPI(UsdPhysics.RigidBodyAPI) and base.HasAPI(UsdPhysics.MassAPI)
        elif bundle.is_fixed(obj):
            assert not prim.HasAPI(UsdPhysics.RigidBodyAPI)
        else:
            assert prim.HasAPI(UsdPhysics.RigidBodyAPI) and prim.HasAPI(UsdPhysics.MassAPI)
            assert UsdPhysics.MassAPI(prim).GetMassAttr().Get() > 0
        # collision on convex pieces (guide purpose), never on the render mesh; a rug has
        # none: what stands on it stands on the floor through its pile
        cols = [p for p in Usd.PrimRange(prim, Usd.TraverseInstanceProxies())
                if p.HasAPI(UsdPhysics.CollisionAPI)]
        assert bool(cols) != bundle.lies_under(obj), obj.name
        for c in cols:  # box-shaped pieces are cubes (box primitives), the rest hulls
            assert UsdGeom.Imageable(c).GetPurposeAttr().Get() == UsdGeom.Tokens.guide
            assert c.IsA(UsdGeom.Cube) or \
                UsdPhysics.MeshCollisionAPI(c).GetApproximationAttr().Get() == "convexHull"
            # Newton's contact candidates within millimetres, not its default 10 cm
            assert c.GetAttribute("newton:contactGap").Get() == pytest.approx(CONTACT_GAP)
    for prim in stage.GetPrimAtPath("/World/Architecture").GetChildren():
        assert prim.GetAttribute("indoorgen:semantics").Get()
        assert UsdSemantics.LabelsAPI(prim, "class").GetLabelsAttr().Get()


@pytest.mark.parametrize("room", ["living_room", "dining_room"])
def test_every_material_texture_resolves(exported, room):
    _, d, _ = exported[room]
    stage = Usd.Stage.Open(str(d / "scene.usdc"))
    materials = [p for p in stage.Traverse() if p.IsA(UsdShade.Material)]
    assert materials
    n_tex = 0
    for mat in materials:
        for shader in mat.GetChildren():
            f = shader.GetAttribute("inputs:file")
            if not f:
                continue
            asset = f.Get()
            assert not Path(asset.path).is_absolute()
            assert asset.resolvedPath and Path(asset.resolvedPath).is_file(), asset.path
            n_tex += 1
        surf = UsdShade.Material(mat).ComputeSurfaceSource()[0]
        assert surf and surf.GetIdAttr().Get() == "UsdPreviewSurface"
    assert n_tex >= 3 * len(materials) - 2
    # meshes carry faceVarying UVs (indexed: repeated values stored once) and normals
    mesh = next(UsdGeom.Mesh(p) for p in stage.Traverse() if p.IsA(UsdGeom.Mesh)
                and p.GetPath().pathString.startswith("/World/Objects"))
    st = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("st")
    assert st.GetInterpolation() == UsdGeom.Tokens.faceVarying
    assert st.IsIndexed() and len(st.Get()) < len(st.GetIndices())
    assert len(st.ComputeFlattened()) == 3 * len(mesh.GetFaceVertexCountsAttr().Get())
    normals = UsdGeom.PrimvarsAPI(mesh).GetPrimvar("normals")
    assert normals.GetInterpolation() == UsdGeom.Tokens.faceVarying and normals.IsIndexed()
    assert len(normals.ComputeFlattened()) == 3 * len(mesh.GetFaceVertexCountsAttr().Get())


def test_articulations_and_lights(articulated):
    bundle, d = articulated
    stage = Usd.Stage.Open(str(d / "scene.usdc"))
    _, errors = _validate(stage)
    assert errors == [], [(e.GetName(), e.GetMessage()) for e in errors[:5]]
    n_joints = 0
    jointed = [o for o in bundle.objects if bundle.assets[o.name].joints]  # not the garments
    for obj in jointed:
        asset = bundle.assets[obj.name]
        prim = stage.GetPrimAtPath(f"/World/Objects/{obj.name}")
        assert prim.HasAPI(UsdPhysics.ArticulationRootAPI), obj.name
        for j in asset.joints:
            jp = stage.GetPrimAtPath(f"/World/Objects/{obj.name}/joints/{j.name}")
            kind = UsdPhysics.PrismaticJoint if j.kind == "prismatic" else UsdPhysics.RevoluteJoint
            assert jp.IsA(kind), (obj.name, j.name)
            joint = kind(jp)
            lo, hi = joint.GetLowerLimitAttr().Get(), joint.GetUpperLimitAttr().Get()
            if j.kind == "revolute":
                lo, hi = math.radians(lo), math.radians(hi)
            assert lo == pytest.approx(j.lower, abs=1e-5) and hi == pytest.approx(j.upper, abs=1e-5)
            body1 = joint.GetBody1Rel().GetTargets()[0]
            assert stage.GetPrimAtPath(body1).HasAPI(UsdPhysics.RigidBodyAPI)
            n_joints += 1
    assert n_joints >= len(jointed)
    # a garment on the wardrobe's rail, clothes in a drawer: rigid bodies welded to its link
    links = {"hung_garment": "wardrobe_0/base", "folded_clothes": "dresser_0/drawer_0"}
    attached = [o for o in bundle.objects if bundle.attachment(o) is not None]
    assert {o.generator for o in attached} == set(links)
    for obj in attached:
        joint = UsdPhysics.FixedJoint(stage.GetPrimAtPath(f"/World/Attachments/{obj.name}"))
        assert joint.GetBody0Rel().GetTargets() == [f"/World/Objects/{links[obj.generator]}"]
        assert joint.GetBody1Rel().GetTargets() == [f"/World/Objects/{obj.name}"]
        assert stage.GetPrimAtPath(f"/World/Objects/{obj.name}").HasAPI(UsdPhysics.RigidBodyAPI)


def test_light_fixtures_get_lights(tmp_path):
    from indoorgen.assets import get_factory
    scene = Scene(seed=3)
    for g in ("floor_lamp", "desk_lamp"):
        f = get_factory(g)
        p = f.sample_params(np.random.default_rng(0))
        scene.add_object(SceneObject(f"{g}_0", g, p, 5, Pose((0, 0, 0)), ["lighting"], ""))
    assets = {n: get_factory(o.generator).create(o.params) for n, o in scene.objects.items()}
    write_usd_bundle(make_bundle(scene, assets, []), tmp_path / "l.usda",
                     TextureStore(tmp_path, 0))
    stage = Usd.Stage.Open(str(tmp_path / "l.usda"))
    from pxr import UsdLux
    lights = [p for p in stage.Traverse() if p.HasAPI(UsdLux.LightAPI)]
    assert len(lights) >= 2
    emissive = [p for p in stage.Traverse() if p.IsA(UsdShade.Shader) and
                p.GetAttribute("inputs:emissiveColor")]
    assert emissive


def _books_scene(n: int) -> tuple[Scene, dict]:
    from indoorgen.assets import get_factory
    f = get_factory("book")
    p = f.sample_params(np.random.default_rng(1))
    scene = Scene(seed=0)
    for i in range(n):
        scene.add_object(SceneObject(f"book_{i}", "book", p, 42, Pose((0.05 * i, 0, 0)),
                                     ["book"], ""))
    asset = f.create(p)
    return scene, {n: asset for n in scene.objects}


def test_instancing_makes_identical_books_smaller(tmp_path):
    scene, assets = _books_scene(60)
    bundle = make_bundle(scene, assets, [])
    tex = TextureStore(tmp_path, 0)
    size = {}
    for ext in ("usdc", "usda"):
        for mode in (True, False):
            p = tmp_path / f"{mode}.{ext}"
            write_usd_bundle(bundle, p, tex, instancing=mode)
            size[ext, mode] = p.stat().st_size
    # usdc already shares identical arrays; prototypes still save the per-object prims
    assert size["usdc", True] < 0.9 * size["usdc", False], size
    assert size["usda", True] < 0.2 * size["usda", False], size
    stage = Usd.Stage.Open(str(tmp_path / "True.usdc"))
    prims = [stage.GetPrimAtPath(f"/World/Objects/book_{i}") for i in range(60)]
    assert all(p.IsInstance() for p in prims)
    assert len(stage.GetPrototypes()) == 1
    _, errors = _validate(stage)
    assert errors == []


def test_usdz_package(tmp_path, tiny):
    scene, assets, rooms = tiny
    write_usd(scene, tmp_path / "scene.usdz", object_assets=assets, rooms=rooms,
              texture_resolution=32)
    assert (tmp_path / "scene.usdz").read_bytes()[:2] == b"PK"
    stage = Usd.Stage.Open(str(tmp_path / "scene.usdz"))
    assert stage.GetPrimAtPath("/World/Objects/table_0").IsValid()
    files = [a for a in stage.GetRootLayer().GetExternalAssetDependencies()]
    del files
    names, errors = _validate(stage)
    assert errors == []
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]
    assert Sdf  # noqa: B018
