"""The USD building blocks every indoorgen stage uses: prim names, the contract's
`indoorgen:*` attributes and semantic labels, triangle meshes, rigid bodies with their mass, a
new Z-up stage in metres, and writing a stage to a file."""
from __future__ import annotations

import re
from collections.abc import Iterable
from os import PathLike

import numpy as np
import trimesh
from pxr import Gf, Sdf, Tf, Usd, UsdGeom, UsdPhysics, UsdSemantics, Vt

from indoorgen.errors import OutputError
from indoorgen.export.physics import Inertial, matrix_to_quat

ATTR_GENERATOR = "indoorgen:generator"
ATTR_ROOM = "indoorgen:room"
ATTR_PARENT = "indoorgen:parent"
ATTR_SEMANTICS = "indoorgen:semantics"
ATTR_NAME = "indoorgen:name"
#: the UsdSemantics taxonomy the labels are written under
SEMANTICS_TAXONOMY = "class"


def new_stage(kilograms_per_unit: float | None = None) -> Usd.Stage:
    """An empty in-memory stage: upAxis Z, metersPerUnit 1, kilogramsPerUnit when given,
    default prim /World (an Xform)."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    if kilograms_per_unit is not None:
        UsdPhysics.SetStageKilogramsPerUnit(stage, kilograms_per_unit)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    return stage


def export_stage(stage: Usd.Stage, path: str | PathLike) -> None:
    """Write `stage` to `path` (its extension picks the format); OutputError if it cannot be
    written."""
    try:
        ok = stage.GetRootLayer().Export(str(path))
    except Tf.ErrorException as e:
        raise OutputError(f"cannot write USD to {str(path)!r}: {e}") from None
    if not ok:
        raise OutputError(f"cannot write USD to {str(path)!r}")


def sanitize_name(name: str) -> str:
    """`name` made into a valid USD prim identifier (letters, digits, underscores; not starting
    with a digit)."""
    ident = re.sub(r"[^A-Za-z0-9_]", "_", str(name))
    return "_" + ident if not ident or ident[0].isdigit() else ident


def unique_names(names: Iterable[str]) -> dict[str, str]:
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


def tag_prim(prim: Usd.Prim, *, name: str, generator: str, room: str, parent: str,
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


def define_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh,
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


def rigid_body(prim: Usd.Prim, inertial: Inertial) -> None:
    """RigidBodyAPI + MassAPI (mass, centre of mass, principal inertia and axes)."""
    UsdPhysics.RigidBodyAPI.Apply(prim)
    mass = UsdPhysics.MassAPI.Apply(prim)
    mass.CreateMassAttr(float(inertial.mass))
    mass.CreateCenterOfMassAttr(Gf.Vec3f(*map(float, inertial.com)))
    moments, axes = inertial.diagonalised()
    mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*map(float, moments)))
    q = matrix_to_quat(axes)
    mass.CreatePrincipalAxesAttr(Gf.Quatf(float(q[0]), Gf.Vec3f(*map(float, q[1:]))))
