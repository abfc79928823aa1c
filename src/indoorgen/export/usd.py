"""USD export of a scene, following the export contract in DESIGN.md.

Stage layout (upAxis Z, metersPerUnit 1, defaultPrim /World):

    /World/Architecture/<room>/{floor, ceiling, wall_<i>}   Xform per element, Mesh "mesh" below
    /World/Objects/<object>                                  Xform: translate + rotateZ (degrees)
    /World/Objects/<object>/mesh                             the asset mesh in the local frame

Every element and object prim carries `indoorgen:generator`, `indoorgen:room`,
`indoorgen:parent` (strings) and `indoorgen:semantics` (string[]). Prim names are the scene's
names made into valid USD identifiers; the original name is kept in `indoorgen:name`.

This is the basic exporter: one mesh per prim, no materials, no prototype sharing, no physics.
"""
from __future__ import annotations

import logging
import math
import re
from os import PathLike
from pathlib import Path
from typing import Iterable

import numpy as np
import trimesh
from pxr import Sdf, Tf, Usd, UsdGeom, Vt

from ..assets.base import Asset
from ..errors import OutputError
from ..floorplan.room import RoomGeometry
from ..scene import Scene, SceneObject

log = logging.getLogger(__name__)

USD_EXTENSIONS = (".usda", ".usdc", ".usd")
ATTR_GENERATOR = "indoorgen:generator"
ATTR_ROOM = "indoorgen:room"
ATTR_PARENT = "indoorgen:parent"
ATTR_SEMANTICS = "indoorgen:semantics"
ATTR_NAME = "indoorgen:name"


def write_usd(scene: Scene, path: str | PathLike, *, object_assets: dict[str, Asset],
              rooms: dict[str, RoomGeometry]) -> None:
    """Write `scene` as a USD stage at `path` (.usda text, .usdc / .usd binary by extension).

    `object_assets` maps object names to their built Asset (mesh in the object's local frame);
    `rooms` maps room names to their RoomGeometry (meshes in world coordinates). Objects or rooms
    missing from these maps are still written as Xforms with their attributes, but without mesh.
    Raises OutputError for an unknown extension or an unwritable location.
    """
    path = Path(path)
    if path.suffix.lower() not in USD_EXTENSIONS:
        raise OutputError(f"cannot write USD to {str(path)!r}: the file name must end in "
                          f"{', '.join(USD_EXTENSIONS)}")
    stage = build_stage(scene, object_assets=object_assets, rooms=rooms)
    if not path.parent.is_dir():
        raise OutputError(f"cannot write USD to {str(path)!r}: directory {str(path.parent)!r} "
                          "does not exist")
    try:
        ok = stage.GetRootLayer().Export(str(path))
    except Tf.ErrorException as e:
        raise OutputError(f"cannot write USD to {str(path)!r}: {e}") from None
    if not ok:
        raise OutputError(f"cannot write USD to {str(path)!r}")
    log.debug("USD stage written to %s", path)


def build_stage(scene: Scene, *, object_assets: dict[str, Asset],
                rooms: dict[str, RoomGeometry]) -> Usd.Stage:
    """The in-memory USD stage of `scene` (see module docstring for its layout)."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    _write_architecture(stage, scene, rooms)
    _write_objects(stage, scene, object_assets)
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
    """Set the contract's indoorgen:* attributes on `prim`."""
    string = Sdf.ValueTypeNames.String
    prim.CreateAttribute(ATTR_NAME, string).Set(str(name))
    prim.CreateAttribute(ATTR_GENERATOR, string).Set(str(generator))
    prim.CreateAttribute(ATTR_ROOM, string).Set(str(room))
    prim.CreateAttribute(ATTR_PARENT, string).Set(str(parent))
    tags = [t.value if hasattr(t, "value") else str(t) for t in semantics]
    prim.CreateAttribute(ATTR_SEMANTICS, Sdf.ValueTypeNames.StringArray).Set(
        Vt.StringArray(sorted(set(tags))))


def _define_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh) -> UsdGeom.Mesh:
    """A UsdGeom.Mesh at `path` holding the triangles of `mesh` (points, counts, indices,
    extent; polygonal, no subdivision)."""
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
    return usd_mesh


# --------------------------------------------------------------------------------------------
# architecture


def _write_architecture(stage: Usd.Stage, scene: Scene, rooms: dict[str, RoomGeometry]) -> None:
    """/World/Architecture/<room>/{floor, ceiling, wall_i}, meshes in world coordinates."""
    arch = UsdGeom.Xform.Define(stage, "/World/Architecture").GetPrim().GetPath()
    room_names = list(dict.fromkeys([*scene.rooms, *rooms]))
    idents = _unique_names(room_names)
    for room_name in room_names:
        room = scene.rooms.get(room_name) or rooms[room_name].room
        room_path = arch.AppendChild(idents[room_name])
        room_prim = UsdGeom.Xform.Define(stage, room_path).GetPrim()
        _tag_prim(room_prim, name=room_name, generator="room", room=room_name, parent="",
                  semantics=["room", room.room_type])
        geo = rooms.get(room_name)
        if geo is None:
            log.warning("USD export: room %r has no geometry; writing an empty Xform", room_name)
            continue
        elements = [("floor", geo.floor, ["floor"]), ("ceiling", geo.ceiling, ["ceiling"])]
        elements += [(f"wall_{i}", w, ["wall"]) for i, w in enumerate(geo.walls)]
        for elem, mesh, tags in elements:
            _write_element(stage, room_path.AppendChild(elem), mesh, room_name, tags)


def _write_element(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh, room: str,
                   tags: list[str]) -> None:
    """One architectural element: an Xform tagged with its kind, its mesh below it."""
    prim = UsdGeom.Xform.Define(stage, path).GetPrim()
    _tag_prim(prim, name=path.name, generator=tags[0], room=room, parent="", semantics=tags)
    _define_mesh(stage, path.AppendChild("mesh"), mesh)


# --------------------------------------------------------------------------------------------
# objects


def _write_objects(stage: Usd.Stage, scene: Scene, object_assets: dict[str, Asset]) -> None:
    """/World/Objects/<name>: posed Xform per object with its local-frame mesh below."""
    root = UsdGeom.Xform.Define(stage, "/World/Objects").GetPrim().GetPath()
    idents = _unique_names(scene.objects)
    for name, obj in scene.objects.items():
        xf = UsdGeom.Xform.Define(stage, root.AppendChild(idents[name]))
        _set_pose(xf, obj)
        _tag_prim(xf.GetPrim(), name=name, generator=obj.generator, room=obj.room,
                  parent=obj.parent, semantics=obj.tags)
        asset = object_assets.get(name)
        if asset is None:
            log.warning("USD export: object %r has no asset; writing an Xform without mesh", name)
            continue
        _define_mesh(stage, xf.GetPath().AppendChild("mesh"), asset.mesh)


def _set_pose(xf: UsdGeom.Xform, obj: SceneObject) -> None:
    """translate then rotateZ (degrees), so local-to-world = T(position) * Rz(yaw)."""
    xf.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(
        tuple(float(v) for v in obj.pose.position))
    xf.AddRotateZOp(UsdGeom.XformOp.PrecisionDouble).Set(math.degrees(obj.pose.yaw))
