"""USD export of a scene, following (and extending) the export contract in DESIGN.md.

Stage (upAxis Z, metersPerUnit 1, defaultPrim /World)::

    /World/PhysicsScene                          UsdPhysics.Scene, gravity -Z 9.81 m/s^2
    /World/Looks/<material>_<seed>               UsdPreviewSurface + baked textures (relative)
    /World/Prototypes/<proto>                    class prims: meshes shared by identical objects
    /World/Architecture/<room>/<element>         Xform per element (floor, ceiling, wall_<i>,
                                                 doors, windows, stairs), "mesh" Mesh(es) below
    /World/Objects/<object>                      Xform: translate + rotateZ (degrees)
        mesh                                     render mesh (object frame), GeomSubsets per
                                                 material slot (or an instance of a prototype)
        collision/piece_<i>                      convex pieces, purpose guide, CollisionAPI +
                                                 MeshCollisionAPI convexHull
        <link>/{mesh, collision}                 articulated objects: one rigid body per link
        joints/<joint>                           PhysicsRevoluteJoint / PhysicsPrismaticJoint
        light_<i>                                UsdLux.SphereLight at emissive faces

Every element and object prim carries `indoorgen:generator`, `indoorgen:room`,
`indoorgen:parent`, `indoorgen:name` (strings), `indoorgen:semantics` (string[]) and
UsdSemantics labels (`semantics:labels:class`). Movable objects are rigid bodies with mass from
volume x density; objects hanging from walls or ceilings are static colliders. Objects with
joints are articulations (ArticulationRootAPI on the object, one rigid body per link).
"""
from __future__ import annotations

import logging
import math
import re
import shutil
import tempfile
from collections import Counter
from os import PathLike
from pathlib import Path
from typing import Iterable

import numpy as np
import trimesh
from pxr import Gf, Sdf, Sdr, Tf, Usd, UsdGeom, UsdLux, UsdPhysics, UsdSemantics, UsdShade, Vt

from indoorgen.assets.protocol import Asset
from indoorgen.errors import OutputError
from indoorgen.export.bundle import EMISSIVE_SLOTS, ExportBundle, MatRef
from indoorgen.export.meshes import corner_normals, corner_uv, face_slot_names, mesh_uv
from indoorgen.export.physics import Inertial, matrix_to_quat, quat_between
from indoorgen.export.textures import TextureStore
from indoorgen.model.scene import Scene, SceneObject

log = logging.getLogger(__name__)

USD_EXTENSIONS = (".usda", ".usdc", ".usd", ".usdz")
ATTR_GENERATOR = "indoorgen:generator"
ATTR_ROOM = "indoorgen:room"
ATTR_PARENT = "indoorgen:parent"
ATTR_SEMANTICS = "indoorgen:semantics"
ATTR_NAME = "indoorgen:name"
#: the UsdSemantics taxonomy the labels are written under
SEMANTICS_TAXONOMY = "class"
GRAVITY = 9.81
#: SphereLight intensity (nits) of a bulb
LIGHT_INTENSITY = 8000.0


def write_usd(scene: Scene, path: str | PathLike, *, object_assets: dict[str, Asset],
              rooms: dict, texture_resolution: int = 256) -> None:
    """Write `scene` as a USD stage at `path` (.usda text, .usdc / .usd binary, .usdz package)
    from its assets and room geometry (a convenience over `bundle.make_bundle` +
    `write_usd_bundle`). Objects missing from `object_assets` are written as Xforms with their
    attributes but no mesh. Raises OutputError for an unknown extension or an unwritable place."""
    from indoorgen.export.bundle import elements_from_rooms, make_bundle
    path = _check_path(path)
    bundle = make_bundle(scene, {n: a for n, a in object_assets.items() if n in scene.objects},
                         elements_from_rooms(scene, rooms))
    write_usd_bundle(bundle, path, TextureStore(path.parent, texture_resolution))


def _check_path(path) -> Path:
    path = Path(path)
    if path.suffix.lower() not in USD_EXTENSIONS:
        raise OutputError(f"cannot write USD to {str(path)!r}: the file name must end in "
                          f"{', '.join(USD_EXTENSIONS)}")
    if not path.parent.is_dir():
        raise OutputError(f"cannot write USD to {str(path)!r}: directory {str(path.parent)!r} "
                          "does not exist")
    return path


def write_usd_bundle(bundle: ExportBundle, path: str | PathLike, textures: TextureStore, *,
                     instancing: bool = True, physics: bool = True) -> Path:
    """Write the stage of `bundle` to `path`; textures go to `textures.root/textures/` and are
    referenced relative to the stage. A `.usdz` path packages stage and textures into one
    archive. Returns the path written."""
    path = _check_path(path)
    if path.suffix.lower() == ".usdz":
        return _write_usdz(bundle, path, textures, instancing=instancing, physics=physics)
    stage = build_stage(bundle, textures, layer_dir=path.parent, instancing=instancing,
                        physics=physics)
    _export(stage, path)
    log.debug("USD stage written to %s", path)
    return path


def _export(stage: Usd.Stage, path: Path) -> None:
    try:
        ok = stage.GetRootLayer().Export(str(path))
    except Tf.ErrorException as e:
        raise OutputError(f"cannot write USD to {str(path)!r}: {e}") from None
    if not ok:
        raise OutputError(f"cannot write USD to {str(path)!r}")


def _write_usdz(bundle: ExportBundle, path: Path, textures: TextureStore, **kw) -> Path:
    """Stage + textures packaged as one .usdz (written through a temporary directory)."""
    from pxr import UsdUtils
    tmp = Path(tempfile.mkdtemp(prefix=".usdz-", dir=path.parent))
    try:
        local = TextureStore(tmp, textures.resolution, cache_dir=textures._cache or None)
        local._cache = textures._cache
        stage = build_stage(bundle, local, layer_dir=tmp, **kw)
        inner = tmp / (path.stem + ".usdc")
        _export(stage, inner)
        if not UsdUtils.CreateNewUsdzPackage(Sdf.AssetPath(str(inner)), str(path)):
            raise OutputError(f"cannot write USDZ package {str(path)!r}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return path


# --------------------------------------------------------------------------------------------
# stage


def build_stage(bundle: ExportBundle, textures: TextureStore, *, layer_dir: Path,
                instancing: bool = True, physics: bool = True) -> Usd.Stage:
    """The in-memory stage of `bundle` (see the module docstring for its layout); texture paths
    are made relative to `layer_dir`, where the stage will be saved."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    textures.ensure(bundle.all_matrefs())
    looks = _Looks(stage, textures, Path(layer_dir))
    if physics:
        scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
        scene.CreateGravityDirectionAttr(Gf.Vec3f(0.0, 0.0, -1.0))
        scene.CreateGravityMagnitudeAttr(GRAVITY)
    _write_architecture(stage, bundle, looks, physics)
    _write_objects(stage, bundle, looks, instancing, physics)
    return stage


# --------------------------------------------------------------------------------------------
# names and attributes


def sanitize_name(name: str) -> str:
    """`name` made into a valid USD prim identifier (letters, digits, underscores; not starting
    with a digit)."""
    ident = re.sub(r"[^A-Za-z0-9_]", "_", str(name))
    return "_" + ident if not ident or ident[0].isdigit() else ident


def _unique_names(names: Iterable[str]) -> dict[str, str]:
    """Map each name to a sanitised identifier, suffixing duplicates created by sanitising."""
    out: dict[str, str] = {}
    used: set[str] = set()
    for n in names:
        base = sanitize_name(n)
        ident, k = base, 1
        while ident in used:
            ident, k = f"{base}_{k}", k + 1
        used.add(ident)
        out[n] = ident
    return out


def _tag_prim(prim: Usd.Prim, *, name: str, generator: str, room: str, parent: str,
              semantics: Iterable[str]) -> None:
    """Set the contract's indoorgen:* attributes and the UsdSemantics class labels on `prim`."""
    string = Sdf.ValueTypeNames.String
    prim.CreateAttribute(ATTR_NAME, string).Set(str(name))
    prim.CreateAttribute(ATTR_GENERATOR, string).Set(str(generator))
    prim.CreateAttribute(ATTR_ROOM, string).Set(str(room))
    prim.CreateAttribute(ATTR_PARENT, string).Set(str(parent))
    tags = sorted({t.value if hasattr(t, "value") else str(t) for t in semantics})
    prim.CreateAttribute(ATTR_SEMANTICS, Sdf.ValueTypeNames.StringArray).Set(Vt.StringArray(tags))
    labels = UsdSemantics.LabelsAPI.Apply(prim, SEMANTICS_TAXONOMY)
    labels.CreateLabelsAttr().Set(Vt.TokenArray(tags))


def _define_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh,
                 uv: np.ndarray | None = None, normals: np.ndarray | None = None
                 ) -> UsdGeom.Mesh:
    """A UsdGeom.Mesh at `path` holding the triangles of `mesh` (points, counts, indices,
    extent; polygonal, no subdivision), with faceVarying normals and `primvars:st` when given
    (per-corner arrays (F, 3, 3) and (F, 3, 2))."""
    usd_mesh = UsdGeom.Mesh.Define(stage, path)
    verts = np.ascontiguousarray(mesh.vertices, dtype=np.float32)
    faces = np.ascontiguousarray(mesh.faces, dtype=np.int32)
    usd_mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(verts))
    usd_mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(faces), 3, np.int32)))
    usd_mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(faces.reshape(-1)))
    usd_mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    if len(verts):
        usd_mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(
            np.stack([verts.min(axis=0), verts.max(axis=0)])))
    if normals is not None:
        usd_mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(
            np.ascontiguousarray(normals.reshape(-1, 3), np.float32)))
        usd_mesh.SetNormalsInterpolation(UsdGeom.Tokens.faceVarying)
    if uv is not None:
        pv = UsdGeom.PrimvarsAPI(usd_mesh).CreatePrimvar(
            "st", Sdf.ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.faceVarying)
        pv.Set(Vt.Vec2fArray.FromNumpy(np.ascontiguousarray(uv.reshape(-1, 2), np.float32)))
    return usd_mesh


# --------------------------------------------------------------------------------------------
# materials


def _sdr_type(shader_id: str, name: str) -> Sdf.ValueTypeName:
    node = Sdr.Registry().GetShaderNodeByIdentifier(shader_id)
    return node.GetShaderInput(name).GetTypeAsSdfType().GetSdfType()


class _Looks:
    """Material prims under /World/Looks, created on first use (one per material, seed and
    emissive flag)."""

    def __init__(self, stage: Usd.Stage, textures: TextureStore, layer_dir: Path) -> None:
        self.stage, self.textures, self.layer_dir = stage, textures, layer_dir
        self.root = UsdGeom.Scope.Define(stage, "/World/Looks").GetPath()
        self._mats: dict[tuple[MatRef, bool], UsdShade.Material] = {}

    def get(self, ref: MatRef, emissive: bool = False) -> UsdShade.Material:
        key = (ref, emissive)
        if key not in self._mats:
            self._mats[key] = self._make(ref, emissive)
        return self._mats[key]

    def _make(self, ref: MatRef, emissive: bool) -> UsdShade.Material:
        info = self.textures.info(ref)
        name = sanitize_name(ref.key + ("_emissive" if emissive else ""))
        path = self.root.AppendChild(name)
        mat = UsdShade.Material.Define(self.stage, path)
        pbr = UsdShade.Shader.Define(self.stage, path.AppendChild("PBR"))
        pbr.CreateIdAttr("UsdPreviewSurface")

        def inp(shader, sid, n, value=None):
            i = shader.CreateInput(n, _sdr_type(sid, n))
            if value is not None:
                i.Set(value)
            return i

        ps = "UsdPreviewSurface"
        files = {k: self.textures.relpath(ref, k, self.layer_dir)
                 for k in ("base_color", "roughness", "normal", "metallic")}
        st_out = None
        if any(files.values()):
            reader = UsdShade.Shader.Define(self.stage, path.AppendChild("uv"))
            reader.CreateIdAttr("UsdPrimvarReader_float2")
            inp(reader, "UsdPrimvarReader_float2", "varname", "st")
            reader_out = reader.CreateOutput("result", Sdf.ValueTypeNames.Float2)
            xf = UsdShade.Shader.Define(self.stage, path.AppendChild("uv_scale"))
            xf.CreateIdAttr("UsdTransform2d")
            inp(xf, "UsdTransform2d", "in").ConnectToSource(reader_out)
            s = float(self.textures.uv_scale(ref))
            inp(xf, "UsdTransform2d", "scale", Gf.Vec2f(s, s))
            st_out = xf.CreateOutput("result", Sdf.ValueTypeNames.Float2)

        def texture(kind: str, raw: bool, normal: bool = False):
            tex = UsdShade.Shader.Define(self.stage, path.AppendChild(f"tex_{kind}"))
            tid = "UsdUVTexture"
            tex.CreateIdAttr(tid)
            inp(tex, tid, "file", Sdf.AssetPath("./" + files[kind]))
            inp(tex, tid, "st").ConnectToSource(st_out)
            inp(tex, tid, "wrapS", "repeat")
            inp(tex, tid, "wrapT", "repeat")
            inp(tex, tid, "sourceColorSpace", "raw" if raw else "sRGB")
            if normal:
                inp(tex, tid, "scale", Gf.Vec4f(2.0, 2.0, 2.0, 1.0))
                inp(tex, tid, "bias", Gf.Vec4f(-1.0, -1.0, -1.0, 0.0))
            return tex

        if files["base_color"]:
            t = texture("base_color", raw=False)
            inp(pbr, ps, "diffuseColor").ConnectToSource(
                t.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
        else:
            inp(pbr, ps, "diffuseColor", Gf.Vec3f(*_linear(info.mean_color)))
        if files["roughness"]:
            t = texture("roughness", raw=True)
            inp(pbr, ps, "roughness").ConnectToSource(
                t.CreateOutput("r", Sdf.ValueTypeNames.Float))
        else:
            inp(pbr, ps, "roughness", float(info.mean_roughness))
        if files["metallic"]:
            t = texture("metallic", raw=True)
            inp(pbr, ps, "metallic").ConnectToSource(t.CreateOutput("r", Sdf.ValueTypeNames.Float))
        else:
            inp(pbr, ps, "metallic", float(info.metallic_value))
        if files["normal"]:
            t = texture("normal", raw=True, normal=True)
            inp(pbr, ps, "normal").ConnectToSource(t.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
        if info.opacity < 1.0:
            inp(pbr, ps, "opacity", float(info.opacity))
            inp(pbr, ps, "ior", float(info.ior))
        if emissive:
            inp(pbr, ps, "emissiveColor", Gf.Vec3f(1.0, 0.9, 0.75))
        mat.CreateSurfaceOutput().ConnectToSource(pbr.ConnectableAPI(), "surface")
        mat.GetPrim().CreateAttribute("indoorgen:material", Sdf.ValueTypeNames.String).Set(ref.name)
        mat.GetPrim().CreateAttribute("indoorgen:family", Sdf.ValueTypeNames.String).Set(info.family)
        return mat


def _linear(c) -> tuple[float, float, float]:
    c = np.asarray(c, float)
    lin = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return tuple(float(x) for x in lin)


def _bind_slots(mesh: UsdGeom.Mesh, face_slots: np.ndarray, slots: list[str],
                materials: dict[str, MatRef], looks: _Looks) -> None:
    """Bind one material per slot: directly when the mesh has one slot, else one
    `materialBind` GeomSubset per slot."""
    used = np.unique(face_slots)
    api = UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim())

    def material(si: int) -> UsdShade.Material | None:
        slot = slots[si] if si < len(slots) else "body"
        ref = materials.get(slot)
        return None if ref is None else looks.get(ref, slot in EMISSIVE_SLOTS)

    if len(used) == 1:
        m = material(int(used[0]))
        if m is not None:
            api.Bind(m)
        return
    for si in used:
        idx = np.nonzero(face_slots == si)[0].astype(np.int32)
        slot = slots[si] if si < len(slots) else "body"
        subset = api.CreateMaterialBindSubset(sanitize_name(slot), Vt.IntArray.FromNumpy(idx),
                                              UsdGeom.Tokens.face)
        m = material(int(si))
        if m is not None:
            UsdShade.MaterialBindingAPI.Apply(subset.GetPrim()).Bind(m)
    api.SetMaterialBindSubsetsFamilyType(UsdGeom.Tokens.partition)


# --------------------------------------------------------------------------------------------
# architecture


def _write_architecture(stage: Usd.Stage, bundle: ExportBundle, looks: _Looks,
                        physics: bool) -> None:
    """/World/Architecture/...: one Xform per element, its part meshes (world coordinates)
    below; room prims tagged as rooms; every element a static triangle-mesh collider."""
    arch = UsdGeom.Xform.Define(stage, "/World/Architecture").GetPrim().GetPath()
    rooms = list(dict.fromkeys([*bundle.scene.rooms, *bundle.room_types]))
    for room_name in rooms:
        if not any(room_name in e.path[:-1] for e in bundle.elements):
            # a room without geometry still gets its (empty) prim
            prim = UsdGeom.Xform.Define(stage, arch.AppendChild(sanitize_name(room_name)))
            _tag_room(prim.GetPrim(), room_name, bundle)
    for el in bundle.elements:
        path = arch
        for i, part in enumerate(el.path):
            path = path.AppendChild(sanitize_name(part))
            if not stage.GetPrimAtPath(path):
                prim = UsdGeom.Xform.Define(stage, path).GetPrim()
                if i < len(el.path) - 1 and part in bundle.room_types:
                    _tag_room(prim, part, bundle)
        prim = stage.GetPrimAtPath(path)
        generator = el.kind if el.kind in ("floor", "ceiling", "wall") else f"{el.kind}_simple"
        _tag_prim(prim, name=el.name, generator=generator, room=el.room, parent=el.parent,
                  semantics=el.semantics)
        for part in el.parts:
            mp = path.AppendChild(sanitize_name(part.name))
            m = _define_mesh(stage, mp, part.mesh, mesh_uv(part.mesh), corner_normals(part.mesh))
            UsdShade.MaterialBindingAPI.Apply(m.GetPrim()).Bind(
                looks.get(part.material, part.slot in EMISSIVE_SLOTS))
            if physics:
                UsdPhysics.CollisionAPI.Apply(m.GetPrim())
                UsdPhysics.MeshCollisionAPI.Apply(m.GetPrim()).CreateApproximationAttr(
                    UsdPhysics.Tokens.none)


def _tag_room(prim: Usd.Prim, room: str, bundle: ExportBundle) -> None:
    rtype = bundle.room_types.get(room) or getattr(bundle.scene.rooms.get(room), "room_type", "")
    _tag_prim(prim, name=room, generator="room", room=room, parent="",
              semantics=["room", rtype] if rtype else ["room"])


# --------------------------------------------------------------------------------------------
# objects


class _ObjectMeshes:
    """Per-asset arrays computed once per distinct asset (normals, UVs, link faces)."""

    def __init__(self) -> None:
        self._cache: dict[int, tuple] = {}

    def get(self, asset: Asset) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        key = id(asset)
        if key not in self._cache:
            self._cache[key] = (corner_uv(asset), corner_normals(asset.mesh),
                                face_slot_names(asset), asset)
        return self._cache[key][:3]


def _write_objects(stage: Usd.Stage, bundle: ExportBundle, looks: _Looks, instancing: bool,
                   physics: bool) -> None:
    """/World/Objects/<name>: posed Xform per object with its meshes, collision, physics."""
    root = UsdGeom.Xform.Define(stage, "/World/Objects").GetPrim().GetPath()
    idents = _unique_names(bundle.scene.objects)
    cache = _ObjectMeshes()
    counts = Counter(bundle.proto_key(o.name) for o in bundle.objects
                     if not bundle.assets[o.name].joints)
    protos: dict[tuple, Sdf.Path] = {}
    for name, obj in bundle.scene.objects.items():
        xf = UsdGeom.Xform.Define(stage, root.AppendChild(idents[name]))
        _set_pose(xf, obj)
        prim = xf.GetPrim()
        _tag_prim(prim, name=name, generator=obj.generator, room=obj.room,
                  parent=obj.parent, semantics=obj.tags)
        asset = bundle.assets.get(name)
        if asset is None:
            log.warning("USD export: object %r has no asset; writing an Xform without mesh", name)
            continue
        mats = bundle.materials[name]
        pkey = bundle.proto_key(name)
        inertial = bundle.inertials(name) if physics else None
        fixed = bundle.is_fixed(obj)
        if asset.joints:
            _write_articulated(stage, prim.GetPath(), obj, asset, mats, looks, cache,
                               inertial, physics, fixed)
        else:
            if instancing and counts[pkey] > 1:
                if pkey not in protos:
                    protos[pkey] = _define_prototype(stage, len(protos), asset, mats, looks,
                                                     cache, physics)
                    _write_lights(stage, protos[pkey], asset)
                prim.GetReferences().AddInternalReference(protos[pkey])
                prim.SetInstanceable(True)
            else:
                _write_link(stage, prim.GetPath(), asset, "base", mats, looks, cache, physics,
                            whole=True)
                _write_lights(stage, prim.GetPath(), asset)
            if physics and not fixed:
                _rigid_body(prim, inertial["base"])
        if asset.joints:
            _write_lights(stage, prim.GetPath(), asset)


def _define_prototype(stage: Usd.Stage, k: int, asset: Asset, mats: dict[str, MatRef],
                      looks: _Looks, cache: _ObjectMeshes, physics: bool) -> Sdf.Path:
    """A class prim /World/Prototypes/proto_<k> holding the meshes of one distinct object."""
    root = Sdf.Path("/World/Prototypes")
    if not stage.GetPrimAtPath(root):
        stage.CreateClassPrim(root)
    path = root.AppendChild(f"proto_{k}")
    stage.CreateClassPrim(path)
    _write_link(stage, path, asset, "base", mats, looks, cache, physics, whole=True)
    return path


def _write_link(stage: Usd.Stage, path: Sdf.Path, asset: Asset, link: str,
                mats: dict[str, MatRef], looks: _Looks, cache: _ObjectMeshes, physics: bool,
                whole: bool = False) -> None:
    """`mesh` (render) and `collision/piece_<i>` below `path` for one link (or, with `whole`,
    the whole asset as one mesh, for objects without joints)."""
    uv, nrm, fslots = cache.get(asset)
    if whole:
        faces = np.arange(len(asset.mesh.faces))
        sub = asset.mesh
    else:
        faces = asset.link_faces(link)
        sub = asset.link_mesh(link)
    if len(faces):
        m = _define_mesh(stage, path.AppendChild("mesh"), sub, uv[faces], nrm[faces])
        _bind_slots(m, fslots[faces], list(asset.slots), mats, looks)
    if physics:
        pieces = [p for ln, p in asset.collision if whole or ln == link]
        if pieces:
            scope = UsdGeom.Scope.Define(stage, path.AppendChild("collision"))
            scope.CreatePurposeAttr(UsdGeom.Tokens.guide)
            for i, piece in enumerate(pieces):
                cm = _define_mesh(stage, scope.GetPath().AppendChild(f"piece_{i}"), piece)
                cm.CreatePurposeAttr(UsdGeom.Tokens.guide)
                UsdPhysics.CollisionAPI.Apply(cm.GetPrim())
                UsdPhysics.MeshCollisionAPI.Apply(cm.GetPrim()).CreateApproximationAttr(
                    UsdPhysics.Tokens.convexHull)


def _rigid_body(prim: Usd.Prim, inertial: Inertial) -> None:
    """RigidBodyAPI + MassAPI (mass, centre of mass, principal inertia and axes)."""
    UsdPhysics.RigidBodyAPI.Apply(prim)
    mass = UsdPhysics.MassAPI.Apply(prim)
    mass.CreateMassAttr(float(inertial.mass))
    mass.CreateCenterOfMassAttr(Gf.Vec3f(*map(float, inertial.com)))
    moments, axes = inertial.diagonalised()
    mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*map(float, moments)))
    q = matrix_to_quat(axes)
    mass.CreatePrincipalAxesAttr(Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:]))))


def _write_articulated(stage: Usd.Stage, path: Sdf.Path, obj: SceneObject, asset: Asset,
                       mats: dict[str, MatRef], looks: _Looks, cache: _ObjectMeshes,
                       inertials: dict[str, Inertial] | None, physics: bool, fixed: bool
                       ) -> None:
    """One Xform (rigid body) per link, in the object frame, and one physics joint per
    articulation; the object prim is the articulation root. A fixed object's base is welded
    to the world by a fixed joint."""
    link_paths = {}
    for link in asset.links:
        lp = path.AppendChild(sanitize_name(link))
        UsdGeom.Xform.Define(stage, lp)
        _write_link(stage, lp, asset, link, mats, looks, cache, physics)
        link_paths[link] = lp
        if physics and inertials is not None:
            _rigid_body(stage.GetPrimAtPath(lp), inertials[link])
    if not physics:
        return
    UsdPhysics.ArticulationRootAPI.Apply(stage.GetPrimAtPath(path))
    jscope = UsdGeom.Scope.Define(stage, path.AppendChild("joints")).GetPath()
    if fixed:
        fj = UsdPhysics.FixedJoint.Define(stage, jscope.AppendChild("world_anchor"))
        fj.CreateBody1Rel().SetTargets([link_paths["base"]])
        m = obj.pose.matrix()
        fj.CreateLocalPos0Attr(Gf.Vec3f(*map(float, m[:3, 3])))
        q = matrix_to_quat(m[:3, :3])
        fj.CreateLocalRot0Attr(Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:]))))
        fj.CreateLocalPos1Attr(Gf.Vec3f(0.0, 0.0, 0.0))
        fj.CreateLocalRot1Attr(Gf.Quatf(1.0, Gf.Vec3f(0.0, 0.0, 0.0)))
    for j in asset.joints:
        if j.child not in link_paths or j.parent not in link_paths:
            continue
        jp = jscope.AppendChild(sanitize_name(j.name))
        if j.kind == "prismatic":
            joint = UsdPhysics.PrismaticJoint.Define(stage, jp)
            lo, hi = float(j.lower), float(j.upper)
        else:
            joint = UsdPhysics.RevoluteJoint.Define(stage, jp)
            lo, hi = math.degrees(j.lower), math.degrees(j.upper)
        joint.CreateAxisAttr(UsdPhysics.Tokens.x)
        joint.CreateLowerLimitAttr(lo)
        joint.CreateUpperLimitAttr(hi)
        joint.CreateBody0Rel().SetTargets([link_paths[j.parent]])
        joint.CreateBody1Rel().SetTargets([link_paths[j.child]])
        origin = Gf.Vec3f(*map(float, j.origin))
        q = quat_between([1.0, 0.0, 0.0], j.axis)
        rot = Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:])))
        joint.CreateLocalPos0Attr(origin)
        joint.CreateLocalRot0Attr(rot)
        joint.CreateLocalPos1Attr(origin)
        joint.CreateLocalRot1Attr(rot)
        joint.GetPrim().CreateAttribute("indoorgen:joint", Sdf.ValueTypeNames.String).Set(j.name)


def _write_lights(stage: Usd.Stage, path: Sdf.Path, asset: Asset) -> None:
    """A SphereLight at the emissive faces of each link (bulbs, diffusers, flames)."""
    fs = face_slot_names(asset)
    emissive = [i for i, s in enumerate(asset.slots) if s in EMISSIVE_SLOTS]
    if not emissive:
        return
    mask = np.isin(fs, emissive)
    if not mask.any():
        return
    areas = np.asarray(asset.mesh.area_faces)
    centres = np.asarray(asset.mesh.triangles_center)
    for k, link in enumerate(asset.links):
        sel = np.intersect1d(np.nonzero(mask)[0], asset.link_faces(link))
        if len(sel) == 0:
            continue
        a = areas[sel]
        c = (centres[sel] * a[:, None]).sum(axis=0) / max(a.sum(), 1e-12)
        radius = float(np.clip(math.sqrt(a.sum() / (4 * math.pi)), 0.005, 0.25))
        parent = path if not asset.joints else path.AppendChild(sanitize_name(link))
        light = UsdLux.SphereLight.Define(stage, parent.AppendChild(f"light_{k}"))
        light.CreateRadiusAttr(radius)
        light.CreateIntensityAttr(LIGHT_INTENSITY)
        light.CreateColorAttr(Gf.Vec3f(1.0, 0.88, 0.72))
        light.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, c)))


def _set_pose(xf: UsdGeom.Xform, obj: SceneObject) -> None:
    """translate then rotateZ (degrees), so local-to-world = T(position) * Rz(yaw)."""
    xf.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(
        tuple(float(v) for v in obj.pose.position))
    xf.AddRotateZOp(UsdGeom.XformOp.PrecisionDouble).Set(math.degrees(obj.pose.yaw))
