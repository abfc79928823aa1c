"""USD export of a scene, following (and extending) the export contract in DESIGN.md.

Stage (upAxis Z, metersPerUnit 1, defaultPrim /World)::

    /World/PhysicsScene                          UsdPhysics.Scene, gravity -Z 9.81 m/s^2
    /World/Looks/<material>_<seed>               UsdPreviewSurface + baked textures (relative)
    /World/Prototypes/<proto>                    class prims: meshes shared by identical objects
    /World/Architecture/<room>/<element>         Xform per element (floor, ceiling, wall_<i>,
                                                 doors, windows, stairs), "mesh" Mesh(es) below
        .../doors/<door>/leaf                    a door's leaf: rigid body, convex collision
                                                 pieces, joint (usd/doors.py)
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
import shutil
import tempfile
from os import PathLike
from pathlib import Path

from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade, UsdUtils

from indoorgen.assets.protocol import Asset
from indoorgen.errors import OutputError
from indoorgen.export.bundle import (
    EMISSIVE_SLOTS,
    ArchElement,
    ExportBundle,
    elements_from_rooms,
    make_bundle,
)
from indoorgen.export.meshes import corner_normals, mesh_uv
from indoorgen.export.textures import TextureStore
from indoorgen.export.usd.doors import write_leaf_physics
from indoorgen.export.usd.materials import Looks
from indoorgen.export.usd.objects import write_objects
from indoorgen.export.usd.prims import (
    GRAVITY,
    collider,
    define_mesh,
    export_stage,
    new_stage,
    part_name,
    sanitize_name,
    tag_prim,
)
from indoorgen.model.scene import Scene

log = logging.getLogger(__name__)

USD_EXTENSIONS = (".usda", ".usdc", ".usd", ".usdz")
#: the element kinds that are a room's own surfaces
ROOM_SURFACES = ("floor", "ceiling", "wall")


def write_usd(scene: Scene, path: str | PathLike, *, object_assets: dict[str, Asset],
              rooms: dict, texture_resolution: int = 256) -> None:
    """Write `scene` as a USD stage at `path` (.usda text, .usdc / .usd binary, .usdz package)
    from its assets and room geometry (a convenience over `bundle.make_bundle` +
    `write_usd_bundle`). Objects missing from `object_assets` are written as Xforms with their
    attributes but no mesh. Raises OutputError for an unknown extension or an unwritable place."""
    path = _check_path(path)
    bundle = make_bundle(scene, {n: a for n, a in object_assets.items() if n in scene.objects},
                         elements_from_rooms(scene, rooms))
    write_usd_bundle(bundle, path, TextureStore(path.parent, texture_resolution))


def _check_path(path: str | PathLike) -> Path:
    """`path` as a Path, or OutputError if its extension is not a USD one or its directory
    does not exist."""
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
    export_stage(stage, path)
    log.debug("USD stage written to %s", path)
    return path


def _write_usdz(bundle: ExportBundle, path: Path, textures: TextureStore, **kw) -> Path:
    """Stage + textures packaged as one .usdz (written through a temporary directory)."""
    tmp = Path(tempfile.mkdtemp(prefix=".usdz-", dir=path.parent))
    try:
        local = TextureStore(tmp, textures.resolution, cache_dir=textures._cache or None)
        local._cache = textures._cache
        stage = build_stage(bundle, local, layer_dir=tmp, **kw)
        inner = tmp / (path.stem + ".usdc")
        export_stage(stage, inner)
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
    stage = new_stage(kilograms_per_unit=1.0)
    textures.ensure(bundle.all_matrefs())
    looks = Looks(stage, textures, Path(layer_dir))
    if physics:
        scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
        scene.CreateGravityDirectionAttr(Gf.Vec3f(0.0, 0.0, -1.0))
        scene.CreateGravityMagnitudeAttr(GRAVITY)
    _write_architecture(stage, bundle, looks, physics)
    write_objects(stage, bundle, looks, instancing, physics)
    return stage


# --------------------------------------------------------------------------------------------
# architecture


def _write_architecture(stage: Usd.Stage, bundle: ExportBundle, looks: Looks,
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
        generator = el.kind if el.kind in ROOM_SURFACES else f"{el.kind}_simple"
        tag_prim(prim, name=el.name, generator=generator, room=el.room, parent=el.parent,
                 semantics=el.semantics)
        for piece in el.parts:
            mp = path.AppendChild(_part_name(el, piece.name))
            m = define_mesh(stage, mp, piece.mesh, mesh_uv(piece.mesh), corner_normals(piece.mesh))
            UsdShade.MaterialBindingAPI.Apply(m.GetPrim()).Bind(
                looks.get(piece.material, piece.slot in EMISSIVE_SLOTS))
            if physics and el.joint is None:
                collider(m.GetPrim())
                UsdPhysics.MeshCollisionAPI.Apply(m.GetPrim()).CreateApproximationAttr(
                    UsdPhysics.Tokens.none)
        if physics and el.joint is not None:
            write_leaf_physics(stage, path, path.GetParentPath(), el, bundle)


def _part_name(el: ArchElement, part: str) -> str:
    """The prim name of an element's part mesh, the name importers show for it: the room's
    and element's names for a room's floor, ceiling and walls (`living_room_0_floor`), the
    element's and part's otherwise (`door_2_casing`; a door's leaf is `door_2_leaf`)."""
    if part == "mesh":
        return sanitize_name(f"{el.room}_{el.name}" if el.kind in ROOM_SURFACES else el.name)
    return part_name(el.name, part)


def _tag_room(prim: Usd.Prim, room: str, bundle: ExportBundle) -> None:
    """Tag a room's prim with the contract attributes, its semantics "room" and its type."""
    rtype = bundle.room_types.get(room) or getattr(bundle.scene.rooms.get(room), "room_type", "")
    tag_prim(prim, name=room, generator="room", room=room, parent="",
             semantics=["room", rtype] if rtype else ["room"])
