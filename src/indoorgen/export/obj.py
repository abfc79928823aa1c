"""Wavefront OBJ + MTL: the mesh files URDF and MJCF reference, and the `obj` export format.

`MeshFiles` writes (and deduplicates) the per-object mesh files of one export under `meshes/`:
visual meshes as one OBJ per (link, material slot) with a one-material MTL (UVs already scaled
to texture repeats; MuJoCo takes one material per geom) and collision pieces as binary STL.
`write_obj_format` writes `scene.obj` (world coordinates) and `obj/<object>.obj` (object frame).
"""
from __future__ import annotations

import logging
import os
from collections.abc import Set as AbstractSet
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from indoorgen.export.bundle import EMISSIVE_SLOTS, ArchElement, ExportBundle, MatRef
from indoorgen.export.convex import box_bounds, sound_piece
from indoorgen.export.meshes import Piece, asset_slot_pieces, mesh_piece, unique_rows
from indoorgen.export.textures import TextureStore

log = logging.getLogger(__name__)

MESH_DIR = "meshes"


def _rows(fmt: str, arr: np.ndarray) -> str:
    """`fmt` applied to every row of `arr`, a line each (what `np.savetxt` writes, formatted in
    one %-operation instead of a Python loop over rows: 3-4x faster)."""
    if len(arr) == 0:
        return ""
    return ((fmt + "\n") * len(arr)) % tuple(np.asarray(arr).ravel().tolist())


def obj_text(groups: list[tuple[str, Piece, float]], mtllib: str | None = None) -> str:
    """OBJ text of `groups` = (material name, piece, uv scale); one `usemtl` group each."""
    out = ["# indoorgen\n"]
    if mtllib:
        out.append(f"mtllib {mtllib}\n")
    base = 0
    for mat, piece, scale in groups:
        out.append(f"o {mat}\n")
        out.append(_rows("v %.6f %.6f %.6f", piece.vertices))
        out.append(_rows("vt %.5f %.5f", piece.uv * scale))
        out.append(_rows("vn %.4f %.4f %.4f", piece.normals))
        out.append(f"usemtl {mat}\n")
        f = piece.faces + 1 + base
        tri = np.repeat(f, 3, axis=1)
        out.append(_rows("f %d/%d/%d %d/%d/%d %d/%d/%d", tri))
        base += len(piece.vertices)
    return "".join(out)


def mtl_text(materials: dict[str, MatRef], textures: TextureStore, mtl_dir: Path,
             emissive: AbstractSet[str] = frozenset()) -> str:
    """MTL text: one `newmtl` per entry (scalar fallbacks plus texture maps relative to
    `mtl_dir`; `map_Pr`/`map_Pm`/`norm` are the PBR extension of the format)."""
    out = []
    for name, ref in materials.items():
        info = textures.info(ref)
        r, g, b = info.mean_color
        out.append(f"newmtl {name}\nKa 0 0 0\nKd {r:.4f} {g:.4f} {b:.4f}\nKs 0.1 0.1 0.1\n"
                   f"Ns {max(1.0, (1 - info.mean_roughness) * 200):.1f}\n"
                   f"d {info.opacity:.3f}\nillum 2\nPr {info.mean_roughness:.3f}\n"
                   f"Pm {info.metallic_value:.3f}\n")
        if name in emissive:
            out.append("Ke 1.0 0.9 0.75\n")
        for kind, key in (("base_color", "map_Kd"), ("roughness", "map_Pr"),
                          ("metallic", "map_Pm"), ("normal", "norm")):
            rel = textures.relpath(ref, kind, mtl_dir)
            if rel:
                out.append(f"{key} {rel}\n")
        out.append("\n")
    return "".join(out)


_STL_RECORD = np.dtype([("normal", "<f4", 3), ("vertices", "<f4", (3, 3)), ("attr", "<u2")])


def write_stl(path: Path, mesh) -> None:
    """`mesh` as a binary STL file: thousands of small collision pieces go out per scene, and
    one buffer written at once is about twice as fast as `trimesh.Trimesh.export`."""
    tri = np.asarray(mesh.vertices, float)[np.asarray(mesh.faces)]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-18)
    rec = np.zeros(len(tri), _STL_RECORD)
    rec["normal"], rec["vertices"] = n, tri
    with open(path, "wb") as f:
        f.write(b"indoorgen convex piece".ljust(80, b" ") + np.uint32(len(tri)).tobytes()
                + rec.tobytes())


@dataclass(frozen=True)
class CollisionGeom:
    """One convex collision piece as exporters write it: an axis-aligned box primitive
    (`center`, `size`, in the frame the piece was given in) where the piece is one, which
    simulators collide fastest and need no file for, else a binary STL `path` (relative to the
    export root)."""

    path: str = ""
    center: tuple[float, float, float] = (0.0, 0.0, 0.0)
    size: tuple[float, float, float] = (0.0, 0.0, 0.0)

    @property
    def is_box(self) -> bool:
        """Whether the geom is a box primitive (no mesh file)."""
        return not self.path


def _box_of(piece) -> CollisionGeom | None:
    """The box primitive of `piece` if it is an axis-aligned box (`convex.box_bounds`)."""
    box = box_bounds(piece)
    if box is None:
        return None
    return CollisionGeom("", tuple(box[0].tolist()), tuple(box[1].tolist()))


def collision_geoms(pieces, directory: Path, stem: str, rel: str) -> list[CollisionGeom]:
    """Box primitives for the box-shaped pieces, STL files `directory/<stem>_<i>.stl` (paths
    `rel/<stem>_<i>.stl`) for the rest."""
    out = []
    for i, piece in enumerate(pieces):
        box = _box_of(piece)
        if box is None:
            p = directory / f"{stem}_{i}.stl"
            write_stl(p, piece)
            box = CollisionGeom(f"{rel}/{p.name}")
        out.append(box)
    return out


@dataclass
class VisualFile:
    """One visual mesh file: its path (relative to the export root), material and slot."""

    path: str
    material: MatRef
    slot: str
    link: str
    #: distinct vertices in the file (MuJoCo refuses a mesh of fewer than 4)
    vertices: int = 4


class MeshFiles:
    """Mesh files of one export, written once per distinct object look (state: what has been
    written)."""

    def __init__(self, bundle: ExportBundle, root: Path, textures: TextureStore) -> None:
        self.bundle, self.root, self.textures = bundle, Path(root), textures
        self._visual: dict[tuple, list[VisualFile]] = {}
        self._collision: dict[str, list[tuple[str, CollisionGeom]]] = {}
        self._arch: dict[tuple, tuple[list[VisualFile], list[CollisionGeom]]] = {}
        self._ids: dict[tuple, str] = {}

    def proto_id(self, name: str) -> str:
        """Directory name of an object's look (generator + short hash)."""
        key = self.bundle.proto_key(name)
        if key not in self._ids:
            self._ids[key] = f"{self.bundle.mesh_key(name)}_{len(self._ids)}"
        return self._ids[key]

    def visuals(self, name: str) -> list[VisualFile]:
        """Visual OBJ files of object `name` (one per link and slot), in the asset frame."""
        key = self.bundle.proto_key(name)
        if key in self._visual:
            return self._visual[key]
        asset = self.bundle.assets[name]
        mats = self.bundle.materials[name]
        d = self.root / MESH_DIR / self.proto_id(name)
        d.mkdir(parents=True, exist_ok=True)
        files = []
        for link in asset.links:
            for slot, piece in asset_slot_pieces(asset, link):
                ref = mats.get(slot) or next(iter(mats.values()))
                stem = f"{link}_{slot}"
                self._write_visual(d, stem, piece, ref, slot in EMISSIVE_SLOTS)
                files.append(VisualFile(f"{MESH_DIR}/{d.name}/{stem}.obj", ref, slot, link,
                                        len(unique_rows(piece.vertices)[0])))
        self._visual[key] = files
        return files

    def _write_visual(self, d: Path, stem: str, piece: Piece, ref: MatRef,
                      emissive: bool) -> None:
        scale = self.textures.uv_scale(ref)
        (d / f"{stem}.obj").write_text(obj_text([(ref.key, piece, scale)], f"{stem}.mtl"))
        (d / f"{stem}.mtl").write_text(
            mtl_text({ref.key: ref}, self.textures, d, {ref.key} if emissive else set()))

    def collisions(self, name: str) -> list[tuple[str, CollisionGeom]]:
        """(link, geometry in the asset frame) of each convex piece of object `name`, made sound
        (`convex.sound_piece`: slabs at least 1 mm thick, slivers left out)."""
        key = self.bundle.mesh_key(name)
        if key in self._collision:
            return self._collision[key]
        asset = self.bundle.assets[name]
        d = self.root / MESH_DIR / f"{key}_collision"
        d.mkdir(parents=True, exist_ok=True)
        out = []
        for i, (link, piece) in enumerate(asset.collision):
            sound = sound_piece(piece)
            if sound is None:  # a sliver: no simulator can hull it
                log.debug("%s: collision piece %d of %s dropped (a sliver)", name, i, link)
                continue
            (geom,) = collision_geoms([sound], d, f"{link}_{i}", f"{MESH_DIR}/{d.name}")
            out.append((link, geom))
        self._collision[key] = out
        return out

    def architecture(self, el: ArchElement) -> tuple[list[VisualFile], list[CollisionGeom]]:
        """Visual OBJ files and collision pieces of an element (world coordinates)."""
        if el.path in self._arch:
            return self._arch[el.path]
        ident = "_".join(el.path)
        d = self.root / MESH_DIR / "architecture"
        d.mkdir(parents=True, exist_ok=True)
        vis = []
        for part in el.parts:
            stem = f"{ident}_{part.name}"
            self._write_visual(d, stem, mesh_piece(part.mesh), part.material, False)
            vis.append(VisualFile(f"{MESH_DIR}/architecture/{stem}.obj", part.material,
                                  part.slot, "base"))
        col = collision_geoms(self.bundle.element_pieces(el), d, f"{ident}_collision",
                              f"{MESH_DIR}/architecture")
        self._arch[el.path] = (vis, col)
        return vis, col


def write_obj_format(bundle: ExportBundle, root: Path, textures: TextureStore) -> list[Path]:
    """`scene.obj` + `scene.mtl` (everything, world coordinates) and `obj/<object>.obj` + .mtl
    per object (object frame, closed pose). Returns the files written."""
    root = Path(root)
    (root / "obj").mkdir(parents=True, exist_ok=True)
    scene_groups: list[tuple[str, Piece, float]] = []
    scene_mats: dict[str, MatRef] = {}
    written = []
    for el in bundle.elements:
        for part in el.parts:
            g = f"{'_'.join(el.path)}_{part.name}"
            scene_groups.append((part.material.key, mesh_piece(part.mesh),
                                 textures.uv_scale(part.material)))
            scene_mats[part.material.key] = part.material
            del g
    for obj in bundle.objects:
        asset = bundle.assets[obj.name]
        mats = bundle.materials[obj.name]
        groups, used = [], {}
        for link in asset.links:
            for slot, piece in asset_slot_pieces(asset, link):
                ref = mats.get(slot) or next(iter(mats.values()))
                groups.append((ref.key, piece, textures.uv_scale(ref)))
                used[ref.key] = ref
        stem = obj.name
        (root / "obj" / f"{stem}.obj").write_text(obj_text(groups, f"{stem}.mtl"))
        (root / "obj" / f"{stem}.mtl").write_text(mtl_text(used, textures, root / "obj"))
        written.append(root / "obj" / f"{stem}.obj")
        m = obj.pose.matrix()
        scene_groups += [(k, p.transformed(m), s) for k, p, s in groups]
        scene_mats.update(used)
    (root / "scene.obj").write_text(obj_text(scene_groups, "scene.mtl"))
    (root / "scene.mtl").write_text(mtl_text(scene_mats, textures, root))
    written.insert(0, root / "scene.obj")
    return written


def relpath(path: str, start: Path, root: Path) -> str:
    """`path` (relative to `root`) made relative to directory `start`."""
    return Path(os.path.relpath(root / path, start)).as_posix()
