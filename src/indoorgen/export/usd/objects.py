"""USD objects of a stage: /World/Objects/<object>, each a posed Xform with its render mesh
(or an instance of a shared prototype), convex collision pieces, rigid-body physics, one body
per link and physics joints for articulated objects, sphere lights at emissive faces, and
/World/Attachments: fixed joints welding objects to the link they hang from."""
from __future__ import annotations

import logging
import math
from collections import Counter

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdLux, UsdPhysics

from indoorgen.assets.protocol import Asset, Joint
from indoorgen.export.bundle import ExportBundle, MatRef
from indoorgen.export.lights import COLOR, emissive_faces, emitters
from indoorgen.export.meshes import corner_normals, corner_uv, face_slot_names
from indoorgen.export.physics import Inertial, matrix_to_quat, quat_between
from indoorgen.export.usd.materials import Looks, bind_slots
from indoorgen.export.usd.prims import (
    GRAVITY,
    add_drive,
    define_collision_piece,
    define_mesh,
    rigid_body,
    sanitize_name,
    solid_faces,
    tag_prim,
    unique_names,
)
from indoorgen.model.scene import SceneObject

log = logging.getLogger(__name__)

#: damping of every furniture hinge (N m s/rad) and slide (N s/m)
HINGE_DAMPING, SLIDE_DAMPING = 0.5, 10.0
#: the sag a gravity-loaded joint's spring allows under the child's full weight: a hinge's
#: (degrees) and a slide's (m)
HOLD_ANGLE, HOLD_SLIDE = 1.0, 0.005
#: the least share of its weight a joint's spring holds, as a catch does: a door on an upright
#: hinge or a level drawer feels gravity once its furniture leans (a cabinet settling 3 mm on
#: a 2-storey home's floor tipped 0.1 degrees, and both glass doors swung open 2 cm in a second)
CATCH_TILT = 0.05


class _ObjectMeshes:
    """Per-asset arrays computed once per distinct asset (normals, UVs, link faces)."""

    def __init__(self) -> None:
        self._cache: dict[int, tuple] = {}

    def get(self, asset: Asset) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(corner UVs, corner normals, face slot indices) of `asset`."""
        key = id(asset)
        if key not in self._cache:
            self._cache[key] = (corner_uv(asset), corner_normals(asset.mesh),
                                face_slot_names(asset), asset)
        return self._cache[key][:3]


def write_objects(stage: Usd.Stage, bundle: ExportBundle, looks: Looks, instancing: bool,
                   physics: bool) -> None:
    """/World/Objects/<name>: posed Xform per object with its meshes, collision, physics."""
    root = UsdGeom.Xform.Define(stage, "/World/Objects").GetPrim().GetPath()
    idents = unique_names(bundle.scene.objects)
    cache = _ObjectMeshes()
    counts = Counter(bundle.proto_key(o.name) for o in bundle.objects
                     if not bundle.assets[o.name].joints)
    protos: dict[tuple, Sdf.Path] = {}
    for name, obj in bundle.scene.objects.items():
        xf = UsdGeom.Xform.Define(stage, root.AppendChild(idents[name]))
        _set_pose(xf, obj)
        prim = xf.GetPrim()
        tag_prim(prim, name=name, generator=obj.generator, room=obj.room,
                 parent=obj.parent, semantics=obj.tags)
        asset = bundle.assets.get(name)
        if asset is None:
            log.warning("USD export: object %r has no asset; writing an Xform without mesh", name)
            continue
        mats = bundle.materials[name]
        pkey = bundle.proto_key(name)
        inertial = bundle.inertials(name) if physics else None
        fixed = bundle.is_fixed(obj)
        # a rug: no collision pieces (furniture stands on the floor through it)
        physics_here = physics and not bundle.lies_under(obj)
        if asset.joints:
            _write_articulated(stage, prim.GetPath(), obj, asset, mats, looks, cache,
                               inertial, physics, fixed)
        else:
            if instancing and counts[pkey] > 1:
                if pkey not in protos:
                    protos[pkey] = _define_prototype(stage, len(protos), obj.generator, asset,
                                                     mats, looks, cache, physics_here)
                    _write_lights(stage, protos[pkey], sanitize_name(obj.generator), asset,
                                  obj.generator)
                prim.GetReferences().AddInternalReference(protos[pkey])
                prim.SetInstanceable(True)
            else:
                _write_link(stage, prim.GetPath(), _body_name(idents[name], asset), asset,
                            "base", mats, looks, cache, physics_here, whole=True)
                _write_lights(stage, prim.GetPath(), idents[name], asset, obj.generator)
            if physics and not fixed:
                assert inertial is not None  # computed whenever physics is on
                rigid_body(prim, inertial["base"])
        if asset.joints:
            _write_lights(stage, prim.GetPath(), idents[name], asset, obj.generator)
    if physics:
        _write_attachments(stage, root, bundle, idents)


def _write_attachments(stage: Usd.Stage, root: Sdf.Path, bundle: ExportBundle,
                       idents: dict[str, str]) -> None:
    """/World/Attachments/<name>: a fixed joint welding each object fixed to another's link
    (`ExportBundle.attachment`: a garment to the wardrobe it hangs in) to that link's body, at
    its pose in the link's frame (a link's Xform carries no transform of its own)."""
    scope = None
    for name, obj in bundle.scene.objects.items():
        att = bundle.attachment(obj)
        if att is None or name not in bundle.assets:
            continue
        if scope is None:
            scope = UsdGeom.Scope.Define(stage, root.GetParentPath().AppendChild("Attachments"))
        parent = root.AppendChild(idents[att.parent])
        if bundle.assets[att.parent].joints:
            parent = parent.AppendChild(sanitize_name(att.link))
        fj = UsdPhysics.FixedJoint.Define(stage, scope.GetPath().AppendChild(idents[name]))
        fj.CreateBody0Rel().SetTargets([parent])
        fj.CreateBody1Rel().SetTargets([root.AppendChild(idents[name])])
        fj.CreateLocalPos0Attr(Gf.Vec3f(*map(float, att.position)))
        half = att.yaw / 2
        fj.CreateLocalRot0Attr(Gf.Quatf(math.cos(half), Gf.Vec3f(0.0, 0.0, math.sin(half))))
        fj.CreateLocalPos1Attr(Gf.Vec3f(0.0, 0.0, 0.0))
        fj.CreateLocalRot1Attr(Gf.Quatf(1.0, Gf.Vec3f(0.0, 0.0, 0.0)))


def _define_prototype(stage: Usd.Stage, k: int, asset_name: str, asset: Asset,
                      mats: dict[str, MatRef], looks: Looks, cache: _ObjectMeshes,
                      physics: bool) -> Sdf.Path:
    """A class prim /World/Prototypes/proto_<k> holding the meshes of one distinct object (its
    mesh named `asset_name`, the generator's, which importers show for every instance)."""
    root = Sdf.Path("/World/Prototypes")
    if not stage.GetPrimAtPath(root):
        stage.CreateClassPrim(root)
    path = root.AppendChild(f"proto_{k}")
    stage.CreateClassPrim(path)
    _write_link(stage, path, _body_name(sanitize_name(asset_name), asset), asset, "base", mats,
                looks, cache, physics, whole=True)
    return path


def _write_link(stage: Usd.Stage, path: Sdf.Path, mesh_name: str, asset: Asset, link: str,
                mats: dict[str, MatRef], looks: Looks, cache: _ObjectMeshes, physics: bool,
                whole: bool = False) -> None:
    """The render mesh `mesh_name` (the name importers show for the object) and
    `collision/piece_<i>` below `path` for one link (or, with `whole`, the whole asset as one
    mesh, for objects without joints)."""
    uv, nrm, fslots = cache.get(asset)
    if whole:
        faces = np.arange(len(asset.mesh.faces))
        sub = asset.mesh
    else:
        faces = asset.link_faces(link)
        sub = asset.link_mesh(link)
    if len(faces):
        m = define_mesh(stage, path.AppendChild(mesh_name), sub, uv[faces], nrm[faces])
        bind_slots(m, fslots[faces][solid_faces(sub)], list(asset.slots), mats, looks)
    if physics:
        pieces = [p for ln, p in asset.collision if whole or ln == link]
        if pieces:
            scope = UsdGeom.Scope.Define(stage, path.AppendChild("collision"))
            scope.CreatePurposeAttr(UsdGeom.Tokens.guide)
            for i, piece in enumerate(pieces):
                define_collision_piece(stage, scope.GetPath().AppendChild(f"piece_{i}"), piece)


def _write_articulated(stage: Usd.Stage, path: Sdf.Path, obj: SceneObject, asset: Asset,
                       mats: dict[str, MatRef], looks: Looks, cache: _ObjectMeshes,
                       inertials: dict[str, Inertial] | None, physics: bool, fixed: bool
                       ) -> None:
    """One Xform (rigid body) per link, in the object frame, and one physics joint per
    articulation; the object prim is the articulation root. A fixed object's base is welded
    to the world by a fixed joint."""
    link_paths = {}
    for link in asset.links:
        lp = path.AppendChild(sanitize_name(link))
        UsdGeom.Xform.Define(stage, lp)
        _write_link(stage, lp, f"{path.name}_{lp.name}", asset, link, mats, looks, cache,
                    physics)
        link_paths[link] = lp
        if physics and inertials is not None:
            rigid_body(stage.GetPrimAtPath(lp), inertials[link])
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
        q = quat_between(np.array([1.0, 0.0, 0.0]), j.axis)
        rot = Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:])))
        joint.CreateLocalPos0Attr(origin)
        joint.CreateLocalRot0Attr(rot)
        joint.CreateLocalPos1Attr(origin)
        joint.CreateLocalRot1Attr(rot)
        joint.GetPrim().CreateAttribute("indoorgen:joint", Sdf.ValueTypeNames.String).Set(j.name)
        if inertials is not None:
            add_drive(joint, j.kind != "prismatic", **_joint_drive(j, inertials[j.child]))


def _joint_drive(j: Joint, child: Inertial) -> dict[str, float]:
    """SI stiffness and damping of a furniture joint's drive: damping on every joint (a drawer
    or door stays where it is pushed), and, where gravity turns or slides the child (a lamp's
    arm, an oven door's bottom hinge), a spring to its rest pose that holds it there within
    HOLD_ANGLE (HOLD_SLIDE) against its full weight, critically damped; every joint's spring
    holds at least CATCH_TILT of that weight."""
    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    # share of gravity the joint feels
    tilt = max(math.sqrt(max(0.0, 1.0 - axis[2] ** 2)), CATCH_TILT)
    weight = child.mass * GRAVITY
    if j.kind == "prismatic":
        load, inertia, hold = weight * max(abs(axis[2]), CATCH_TILT), child.mass, HOLD_SLIDE
        damping = SLIDE_DAMPING
    else:
        lever = child.com - np.asarray(j.origin, float)
        lever = lever - (lever @ axis) * axis
        load, hold = weight * float(np.linalg.norm(lever)) * tilt, math.radians(HOLD_ANGLE)
        inertia = float(axis @ child.inertia @ axis) + child.mass * float(lever @ lever)
        damping = HINGE_DAMPING
    stiffness = load / hold
    return {"stiffness": stiffness,
            "damping": max(damping, 2.0 * math.sqrt(stiffness * inertia))}


def _body_name(name: str, asset: Asset) -> str:
    """The render mesh's name of a one-piece object: the object's, or `<name>_body` beside its
    lights (an importer then keeps the object's name for the Xform holding both)."""
    return f"{name}_body" if emissive_faces(asset).any() else name


def _write_lights(stage: Usd.Stage, path: Sdf.Path, owner: str, asset: Asset,
                  generator: str) -> None:
    """A SphereLight `<owner>_light_<k>` at each emitter of `asset` (`export.lights`: bulbs,
    diffusers, flames), together emitting the fixture's flux: normalized (UsdLux: luminance =
    intensity x 2^exposure / area), so its flux is pi x intensity lumens whatever its radius."""
    for e in emitters(asset, generator):
        parent = path if not asset.joints else path.AppendChild(sanitize_name(e.link))
        light = UsdLux.SphereLight.Define(stage, parent.AppendChild(f"{owner}_light_{e.index}"))
        light.CreateRadiusAttr(e.radius)
        light.CreateNormalizeAttr(True)
        light.CreateIntensityAttr(e.lumens / math.pi)
        light.CreateExposureAttr(0.0)
        light.CreateColorAttr(Gf.Vec3f(*COLOR))
        light.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*map(float, e.centre)))


def _set_pose(xf: UsdGeom.Xform, obj: SceneObject) -> None:
    """translate then rotateZ (degrees), so local-to-world = T(position) * Rz(yaw)."""
    xf.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(
        tuple(float(v) for v in obj.pose.position))
    xf.AddRotateZOp(UsdGeom.XformOp.PrecisionDouble).Set(math.degrees(obj.pose.yaw))
