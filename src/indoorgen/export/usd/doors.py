"""USD door leaves: each a rigid body (mass from volume x density, convex collision pieces)
below its door's static frame, on a UsdPhysics revolute or prismatic joint to the world with
limits (0 = shut, upper = fully open) and a damping drive (no stiffness: the leaf stays where
it is pushed), its collisions with the frame filtered.

The leaf's meshes stand where the scene stands it (open or shut); the joint's body-1 frame is
authored so the joint reads that value there, so a simulator starts with the door as exported
and can shut and open it within its limits.
"""
from __future__ import annotations

import math

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics
from trimesh.transformations import quaternion_matrix

from indoorgen.export.bundle import ArchElement, ExportBundle
from indoorgen.export.physics import matrix_to_quat, quat_between
from indoorgen.export.usd.prims import add_drive, define_collision_piece, rigid_body

#: damping of a door's drive: N m s/rad for a hinge, N s/m for a slide
DOOR_DAMPING = 5.0
#: the largest force or torque the damping drive exerts (N or N m)
DRIVE_MAX_FORCE = 100.0


def _quat(m: np.ndarray) -> Gf.Quatf:
    q = matrix_to_quat(m)
    return Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:])))


def write_leaf_physics(stage: Usd.Stage, path: Sdf.Path, frame: Sdf.Path, el: ArchElement,
                       bundle: ExportBundle) -> None:
    """Make the leaf prim at `path` a rigid body with convex collision pieces and a damped
    joint `path/joint` to the world; filter its collisions with the colliders of its door's
    `frame` prim."""
    j = el.joint
    assert j is not None  # moving elements have joints
    prim = stage.GetPrimAtPath(path)
    scope = UsdGeom.Scope.Define(stage, path.AppendChild("collision"))
    scope.CreatePurposeAttr(UsdGeom.Tokens.guide)
    for i, piece in enumerate(bundle.element_pieces(el)):
        define_collision_piece(stage, scope.GetPath().AppendChild(f"piece_{i}"), piece)
    rigid_body(prim, bundle.element_inertial(el))
    casing = frame_colliders(stage, frame, path)
    if casing:
        UsdPhysics.FilteredPairsAPI.Apply(prim).CreateFilteredPairsRel().SetTargets(casing)

    axis = np.asarray(j.axis, float) / np.linalg.norm(j.axis)
    origin = np.asarray(j.origin, float)
    rot0 = quaternion_matrix(quat_between(np.array([1.0, 0.0, 0.0]), axis))[:3, :3]
    jp = path.AppendChild("joint")
    value = float(el.joint_value)
    if j.kind == "prismatic":
        joint = UsdPhysics.PrismaticJoint.Define(stage, jp)
        lo, hi = float(j.lower), float(j.upper)
        pos1, rot1 = origin + value * axis, rot0
    else:
        joint = UsdPhysics.RevoluteJoint.Define(stage, jp)
        lo, hi = math.degrees(j.lower), math.degrees(j.upper)
        c, s = math.cos(value), math.sin(value)
        rot1 = rot0 @ np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
        pos1 = origin
    joint.CreateAxisAttr(UsdPhysics.Tokens.x)
    joint.CreateLowerLimitAttr(lo)
    joint.CreateUpperLimitAttr(hi)
    joint.CreateBody1Rel().SetTargets([path])
    joint.CreateLocalPos0Attr(Gf.Vec3f(*map(float, origin)))
    joint.CreateLocalRot0Attr(_quat(rot0))
    joint.CreateLocalPos1Attr(Gf.Vec3f(*map(float, pos1)))
    joint.CreateLocalRot1Attr(_quat(rot1))
    joint.GetPrim().CreateAttribute("indoorgen:joint", Sdf.ValueTypeNames.String).Set(j.name)
    joint.GetPrim().CreateAttribute("indoorgen:state", Sdf.ValueTypeNames.Double).Set(value)
    add_drive(joint, j.kind != "prismatic", damping=DOOR_DAMPING, max_force=DRIVE_MAX_FORCE)


def frame_colliders(stage: Usd.Stage, frame: Sdf.Path, leaf: Sdf.Path) -> list[Sdf.Path]:
    """The colliders below a door's `frame` prim outside its `leaf`: what a filtered pair
    names (the frame's Xform is neither a body nor a collider, so engines ignore it there)."""
    return [p.GetPath() for p in Usd.PrimRange(stage.GetPrimAtPath(frame))
            if p.HasAPI(UsdPhysics.CollisionAPI) and not p.GetPath().HasPrefix(leaf)]
