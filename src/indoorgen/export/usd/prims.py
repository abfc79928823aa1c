"""The USD building blocks every indoorgen stage uses: prim names, the contract's
`indoorgen:*` attributes and semantic labels, triangle meshes, rigid bodies with their mass, a
new Z-up stage in metres, and writing a stage to a file."""
from __future__ import annotations

import math
import re
from collections.abc import Iterable
from os import PathLike

import numpy as np
import trimesh
from pxr import Gf, Sdf, Tf, Usd, UsdGeom, UsdPhysics, UsdSemantics, Vt

from indoorgen.errors import OutputError
from indoorgen.export.convex import box_bounds, vertex_limited
from indoorgen.export.meshes import unique_rows
from indoorgen.export.physics import Inertial, matrix_to_quat

ATTR_GENERATOR = "indoorgen:generator"
ATTR_ROOM = "indoorgen:room"
ATTR_PARENT = "indoorgen:parent"
ATTR_SEMANTICS = "indoorgen:semantics"
ATTR_NAME = "indoorgen:name"
#: standard gravity (m/s^2) of the physics scene and of the joints' holding springs
GRAVITY = 9.81
#: the UsdSemantics taxonomy the labels are written under
SEMANTICS_TAXONOMY = "class"


#: how close (m) two collision shapes come before Newton makes them a contact candidate, per
#: shape (a pair's is the sum): Newton's default, 10 cm, made every piece within 20 cm of
#: another a candidate (9,240 contacts in a living room at rest, 90% of a step's time); 5 mm is
#: three 600 Hz steps of a 2 m/s fall
CONTACT_GAP = 0.005
#: the most vertices a collision hull is written with: PhysX's and Newton's default
#: `hullVertexLimit`, past which they reduce a hull themselves, and not always well
HULL_VERTEX_LIMIT = 64


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


def part_name(owner: str, part: str) -> str:
    """The prim name of `owner`'s part mesh, which importers show as the object's name:
    `<owner>_<part>` (`door_2_casing`), or just `owner` when it already ends in `part`
    (`door_2_leaf`'s leaf)."""
    return sanitize_name(owner if owner.endswith(part) else f"{owner}_{part}")


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


#: faces smaller than this (m^2, in the written float32 points) are dropped at write time
MIN_FACE_AREA = 1e-12


def solid_faces(mesh: trimesh.Trimesh) -> np.ndarray:
    """Indices of the faces of `mesh` `define_mesh` writes: those whose area, measured on the
    float32 points a stage stores, is above MIN_FACE_AREA (zero-area faces are dropped)."""
    cross = _face_cross(mesh)
    return np.nonzero(0.5 * np.linalg.norm(cross, axis=1) > MIN_FACE_AREA)[0]


def _face_cross(mesh: trimesh.Trimesh) -> np.ndarray:
    """(F, 3) cross products of the faces' edges, on the float32 points a stage stores."""
    tri = np.asarray(mesh.vertices, np.float32).astype(float)[np.asarray(mesh.faces, int)]
    if len(tri) == 0:
        return np.zeros((0, 3))
    return np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])


def _indexed_points(mesh: trimesh.Trimesh, faces: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(points, face vertex indices) of the faces `faces` of `mesh`: float32 points, co-located
    points welded, points no face uses left out."""
    verts = np.asarray(mesh.vertices, np.float32)
    tri = np.asarray(mesh.faces, np.int64)[faces]
    used, inverse = unique_rows(verts[tri.reshape(-1)])
    return np.ascontiguousarray(used), inverse.reshape(-1, 3).astype(np.int32)


def define_mesh(stage: Usd.Stage, path: Sdf.Path, mesh: trimesh.Trimesh,
                uv: np.ndarray | None = None, normals: np.ndarray | None = None
                ) -> UsdGeom.Mesh:
    """A UsdGeom.Mesh at `path` holding the triangles of `mesh` (points, counts, indices,
    extent; polygonal, no subdivision), with indexed faceVarying `primvars:normals` (the face
    normals when none are given) and `primvars:st` when given (per-corner arrays (F, 3, 3) and
    (F, 3, 2)). Zero-area faces are dropped (`solid_faces`) and co-located points welded,
    so the stage passes the asset validators' geometry rules."""
    usd_mesh = UsdGeom.Mesh.Define(stage, path)
    keep = solid_faces(mesh)
    verts, faces = _indexed_points(mesh, keep)
    usd_mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(verts))
    usd_mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(faces), 3, np.int32)))
    usd_mesh.CreateFaceVertexIndicesAttr(Vt.IntArray.FromNumpy(faces.reshape(-1)))
    usd_mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    if len(verts):
        usd_mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(
            np.stack([verts.min(axis=0), verts.max(axis=0)])))
    if normals is None:
        cross = _face_cross(mesh)[keep]
        corner = np.repeat((cross / np.linalg.norm(cross, axis=1)[:, None])[:, None], 3, axis=1)
    else:
        corner = np.asarray(normals, float)[keep]
    _indexed_primvar(usd_mesh, "normals", Sdf.ValueTypeNames.Normal3fArray, Vt.Vec3fArray,
                     corner.reshape(-1, 3))
    if uv is not None:
        _indexed_primvar(usd_mesh, "st", Sdf.ValueTypeNames.TexCoord2fArray, Vt.Vec2fArray,
                         np.asarray(uv)[keep].reshape(-1, 2))
    return usd_mesh


def define_collision_piece(stage: Usd.Stage, path: Sdf.Path, piece: trimesh.Trimesh) -> Usd.Prim:
    """A convex collision piece at `path` (purpose guide, CollisionAPI): a box-shaped piece as
    a UsdGeom.Cube scaled to its size (engines collide it as a box primitive: fewer, cheaper
    contacts than a hull), any other as a mesh with the convexHull approximation, of at most
    `HULL_VERTEX_LIMIT` vertices."""
    box = box_bounds(piece)
    if box is None:
        geom: UsdGeom.Gprim = define_mesh(stage, path, vertex_limited(piece, HULL_VERTEX_LIMIT))
        prim = geom.GetPrim()
        UsdPhysics.MeshCollisionAPI.Apply(prim).CreateApproximationAttr(
            UsdPhysics.Tokens.convexHull)
    else:
        cube = UsdGeom.Cube.Define(stage, path)
        cube.CreateSizeAttr(1.0)
        cube.CreateExtentAttr(Vt.Vec3fArray([Gf.Vec3f(-0.5, -0.5, -0.5), Gf.Vec3f(0.5, 0.5, 0.5)]))
        cube.AddTranslateOp().Set(Gf.Vec3d(*map(float, box[0])))
        cube.AddScaleOp().Set(Gf.Vec3f(*map(float, box[1])))
        geom, prim = cube, cube.GetPrim()
    geom.CreatePurposeAttr(UsdGeom.Tokens.guide)
    collider(prim)
    return prim


def collider(prim: Usd.Prim) -> None:
    """Make `prim` collide (UsdPhysics.CollisionAPI) with Newton's contact gap `CONTACT_GAP`
    (NewtonCollisionAPI's `newton:contactGap`; other engines ignore it)."""
    UsdPhysics.CollisionAPI.Apply(prim)
    prim.AddAppliedSchema("NewtonCollisionAPI")
    prim.CreateAttribute("newton:contactGap", Sdf.ValueTypeNames.Float).Set(CONTACT_GAP)


def _indexed_primvar(mesh: UsdGeom.Mesh, name: str, type_name: Sdf.ValueTypeName, array,
                     corners: np.ndarray) -> None:
    """A faceVarying primvar `name` of per-corner values (N, k): each distinct float32 value
    stored once, with an index per corner."""
    values, index = unique_rows(np.asarray(corners, np.float32))
    pv = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(name, type_name, UsdGeom.Tokens.faceVarying)
    pv.Set(array.FromNumpy(np.ascontiguousarray(values)))
    pv.SetIndices(Vt.IntArray.FromNumpy(index.reshape(-1).astype(np.int32)))


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


def add_drive(joint: UsdPhysics.Joint, angular: bool, *, damping: float, stiffness: float = 0.0,
              target: float = 0.0, max_force: float | None = None) -> UsdPhysics.DriveAPI:
    """A force drive on `joint` from SI values (N m/rad, N m s/rad and rad for a hinge; N/m,
    N s/m and m for a slide), written in the per-degree units UsdPhysics wants for angular
    drives; no max force means unbounded."""
    per = math.pi / 180.0 if angular else 1.0
    drive = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "angular" if angular else "linear")
    drive.CreateTypeAttr(UsdPhysics.Tokens.force)
    drive.CreateStiffnessAttr(float(stiffness) * per)
    drive.CreateDampingAttr(float(damping) * per)
    drive.CreateTargetPositionAttr(float(target) / per)
    drive.CreateTargetVelocityAttr(0.0)
    if max_force is not None:
        drive.CreateMaxForceAttr(float(max_force))
    return drive
