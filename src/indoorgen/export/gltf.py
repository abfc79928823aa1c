"""glTF binary export (`scene.glb`): Y-up, every mesh once in the scene's hierarchy, textured
PBR materials, the lamps' lights.

Node hierarchy (names in brackets; every name is unique in the file):

    world
      storey_<k>                              (homes; a single room hangs from `world`)
        <room>                                one node per room
          <room>/floor, <room>/ceiling, <room>/walls...      its architecture
          <object>                            each object of the room, at its pose
            <object>/<link>                   one node per link (a moving link at its joint)
              <object>/light_<i>              a KHR_lights_punctual point light (lamps)
        storey_<k>/doors -> <door> -> <door>_leaf   a door leaf, a node of its own at the angle it
                                              stands, its joint in `extras`
        storey_<k>/windows -> <window>
      stairs -> <stair>

A link node holds one mesh with a primitive per material slot; identical objects share their
meshes. indoorgen works Z-up; glTF is Y-up by specification, so every position, normal, node
translation and rotation goes through `Y_UP` (x, y, z) -> (x, z, -y): floors lie in the XZ plane,
heights run along +Y, and an object's yaw about +Z becomes a turn about +Y. Element and object
nodes carry their semantic labels and indoorgen's attributes in `extras`. Lights come from
`export/lights.py` (the emitters USD's SphereLights stand for), as point lights in candela.
"""
from __future__ import annotations

import io
import logging
import math
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image

from indoorgen.export.bundle import EMISSIVE_SLOTS, ArchElement, ExportBundle, MatRef
from indoorgen.export.gltf_document import GltfDocument
from indoorgen.export.lights import COLOR, emitters
from indoorgen.export.meshes import Piece, asset_slot_pieces, joint_frames, mesh_piece, tangents
from indoorgen.export.textures import TextureStore

log = logging.getLogger(__name__)

#: JPEG quality of the embedded textures
JPEG_QUALITY = 90
#: indoorgen's Z-up frame to glTF's Y-up frame (a proper rotation: -90 degrees about +X)
Y_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])
#: emissive colour of bulbs and diffusers (linear RGB)
EMISSIVE_FACTOR = (1.0, 0.9, 0.75)
#: the last part of every mesh's name: importers that number the primitives of a mesh
#: (trimesh: `<name>_1`, `<name>_2`...) then never meet the name of another mesh (`door_1`)
MESH = "mesh"
#: element kinds that belong to one room (their nodes are named `<room>/<element>`)
ROOM_KINDS = {"floor", "ceiling", "wall"}


def y_up(points: np.ndarray) -> np.ndarray:
    """Points or directions (N, 3) of indoorgen's Z-up frame in glTF's Y-up frame."""
    out: np.ndarray = np.asarray(points, float) @ Y_UP.T
    return out


def _yaw_quaternion(yaw: float) -> np.ndarray:
    """The glTF rotation (x, y, z, w) of a turn by `yaw` about indoorgen's +Z (glTF's +Y)."""
    return np.array([0.0, math.sin(yaw / 2), 0.0, math.cos(yaw / 2)])


def _jpeg(img: Image.Image) -> bytes:
    """`img` encoded as JPEG (small, fast to encode)."""
    buf = io.BytesIO()
    img.convert("RGB").save(buf, format="JPEG", quality=JPEG_QUALITY)
    return buf.getvalue()


class _Materials:
    """One glTF material per (MatRef, emissive), its maps embedded once (state: the indices
    handed out)."""

    def __init__(self, doc: GltfDocument, textures: TextureStore) -> None:
        self.doc = doc
        self.textures = textures
        self._materials: dict[tuple[MatRef, bool], int] = {}
        self._maps: dict[tuple[MatRef, str], int] = {}
        self.normal_mapped: set[int] = set()

    def _map(self, ref: MatRef, kind: str) -> int:
        """Texture index of one map of `ref` ("base_color", "normal", "metallic_roughness")."""
        key = (ref, kind)
        if key not in self._maps:
            paths = self.textures.paths(ref)
            if kind == "metallic_roughness":  # glTF packs roughness in G and metalness in B
                rough = np.asarray(Image.open(paths["roughness"]).convert("L"))
                metal = (np.asarray(Image.open(paths["metallic"]).convert("L"))
                         if "metallic" in paths else np.zeros_like(rough))
                img = Image.fromarray(np.stack([np.full_like(rough, 255), rough, metal], axis=-1))
            else:
                img = Image.open(paths[kind])
            self._maps[key] = self.doc.texture(_jpeg(img))
        return self._maps[key]

    def get(self, ref: MatRef, emissive: bool = False) -> int:
        """The material index of `ref` (glowing when `emissive`)."""
        key = (ref, emissive)
        if key in self._materials:
            return self._materials[key]
        info = self.textures.info(ref)
        paths = self.textures.paths(ref)
        pbr: dict[str, Any] = {"metallicFactor": 1.0 if "metallic" in paths
                               else float(info.metallic_value), "roughnessFactor": 1.0}
        if "base_color" in paths:
            pbr["baseColorTexture"] = {"index": self._map(ref, "base_color")}
            pbr["baseColorFactor"] = [1.0, 1.0, 1.0, float(info.opacity)]
        else:
            pbr["baseColorFactor"] = [*map(float, info.mean_color), float(info.opacity)]
        if "roughness" in paths:
            pbr["metallicRoughnessTexture"] = {"index": self._map(ref, "metallic_roughness")}
        else:
            pbr["roughnessFactor"] = float(info.mean_roughness)
        mat: dict[str, Any] = {"name": ref.key + ("_emissive" if emissive else ""),
                               "pbrMetallicRoughness": pbr}
        if "normal" in paths:
            mat["normalTexture"] = {"index": self._map(ref, "normal")}
        if info.opacity < 1.0:
            mat["alphaMode"] = "BLEND"
        if emissive:
            mat["emissiveFactor"] = list(EMISSIVE_FACTOR)
        index = self.doc.material(mat)
        if "normal" in paths:
            self.normal_mapped.add(index)
        self._materials[key] = index
        return index


def _primitive(doc: GltfDocument, piece: Piece, material: int, uv_scale: float,
               normal_mapped: bool) -> dict[str, Any] | None:
    """A triangle primitive of `piece` (already Y-up) with `material`; UVs in texture repeats,
    flipped to glTF's top-left origin; tangents where the material has a normal map. Triangles
    whose corners welded into fewer than three vertices (no area) are left out, and the vertices
    only they used; None when no triangle is left."""
    f = piece.faces
    f = f[(f[:, 0] != f[:, 1]) & (f[:, 1] != f[:, 2]) & (f[:, 2] != f[:, 0])]
    if len(f) == 0:
        return None
    # only the vertices a triangle uses (one left only by a dropped triangle has no normal)
    used, f = np.unique(f, return_inverse=True)
    piece = Piece(piece.vertices[used], piece.uv[used], piece.normals[used], f.reshape(-1, 3))
    uv = piece.uv * uv_scale
    attributes = {"POSITION": doc.accessor(piece.vertices, bounds=True),
                  "NORMAL": doc.accessor(piece.normals),
                  "TEXCOORD_0": doc.accessor(np.stack([uv[:, 0], 1.0 - uv[:, 1]], axis=1))}
    if normal_mapped:
        attributes["TANGENT"] = doc.accessor(tangents(piece))
    return {"attributes": attributes, "indices": doc.accessor(piece.faces, indices=True),
            "material": material}


class _Names:
    """Unique node names: the wanted one, else the node's path, else a numbered one."""

    def __init__(self) -> None:
        self._used: set[str] = set()

    def __call__(self, wanted: str, path: tuple[str, ...] = ()) -> str:
        """A name not handed out yet, `wanted` if it is free."""
        name = wanted
        if name in self._used and path:
            name = "/".join(path)
        k = 1
        while name in self._used:
            k += 1
            name = f"{wanted}#{k}"
        self._used.add(name)
        return name


class _Writer:
    """Builds the document of one bundle (state: the group nodes and shared meshes made)."""

    def __init__(self, bundle: ExportBundle, textures: TextureStore) -> None:
        self.bundle = bundle
        self.textures = textures
        self.doc = GltfDocument("indoorgen")
        self.materials = _Materials(self.doc, textures)
        self.names = _Names()
        self.root = self.doc.node(self.names("world"), None)
        self.groups: dict[tuple[str, ...], int] = {(): self.root}
        self.room_paths: dict[str, tuple[str, ...]] = {}
        self.meshes: dict[tuple, int] = {}
        self.lights: dict[tuple, int] = {}

    def group(self, path: tuple[str, ...]) -> int:
        """The group node of `path` (a storey, a room, `storey_0/doors`...), made on demand."""
        if path not in self.groups:
            parent = self.group(path[:-1])
            last = path[-1]
            wanted = last if last in self.bundle.room_types or len(path) == 1 else "/".join(path)
            self.groups[path] = self.doc.node(self.names(wanted, path), parent)
        return self.groups[path]

    def piece_primitive(self, piece: Piece, ref: MatRef,
                        emissive: bool = False) -> dict[str, Any] | None:
        """A primitive of `piece` (indoorgen frame) in material `ref` (None: no triangles)."""
        material = self.materials.get(ref, emissive)
        yup = Piece(y_up(piece.vertices), piece.uv, y_up(piece.normals), piece.faces)
        return _primitive(self.doc, yup, material, self.textures.uv_scale(ref),
                          material in self.materials.normal_mapped)

    # -- architecture ------------------------------------------------------------------------
    def element(self, el: ArchElement) -> None:
        """The node of one architectural element, its parts the primitives of its mesh."""
        meta: dict[str, Any] = {"name": el.name, "kind": el.kind, "room": el.room,
                                "semantics": sorted(el.semantics), "generator": el.kind,
                                "parent": el.parent}
        if el.joint is not None:  # a door leaf, standing at its joint value
            meta.update(joint=el.joint.kind, joint_value=round(float(el.joint_value), 6),
                        joint_lower=float(el.joint.lower), joint_upper=float(el.joint.upper),
                        joint_axis=[float(x) for x in y_up(np.asarray(el.joint.axis)[None])[0]],
                        joint_origin=[float(x) for x in y_up(np.asarray(el.joint.origin)[None])[0]])
        parent = el.path[:-1]
        if el.kind in ROOM_KINDS and el.room:
            self.room_paths.setdefault(el.room, parent)
        wanted = f"{el.room}/{el.name}" if el.kind in ROOM_KINDS and el.room else el.name
        made = [self.piece_primitive(mesh_piece(p.mesh), p.material) for p in el.parts]
        prims = [p for p in made if p is not None]
        mesh = self.doc.mesh(f"{wanted}/{MESH}", prims) if prims else None
        node = self.doc.node(self.names(wanted, el.path), self.group(parent), mesh=mesh,
                             extras=meta)
        self.groups[el.path] = node

    # -- objects -----------------------------------------------------------------------------
    def link_mesh(self, name: str, link: str, origin: np.ndarray) -> int | None:
        """The shared mesh of one link of object `name` (link frame), None when it has no
        faces."""
        key = (self.bundle.proto_key(name), link)
        if key not in self.meshes:
            asset = self.bundle.assets[name]
            mref = self.bundle.materials[name]
            prims = []
            for slot, piece in asset_slot_pieces(asset, link):
                ref = mref.get(slot) or next(iter(mref.values()))
                local = Piece(piece.vertices - origin, piece.uv, piece.normals, piece.faces)
                prim = self.piece_primitive(local, ref, slot in EMISSIVE_SLOTS)
                if prim is not None:
                    prims.append(prim)
            self.meshes[key] = (self.doc.mesh(f"{self.bundle.mesh_key(name)}/{link}/{MESH}", prims)
                                if prims else -1)
        index = self.meshes[key]
        return None if index < 0 else index

    def light(self, name: str, link: str, candela: float) -> int:
        """The light of one emitter (shared by identical objects)."""
        key = (self.bundle.proto_key(name), link)
        if key not in self.lights:
            self.lights[key] = self.doc.light(f"{self.bundle.mesh_key(name)}/{link}", candela,
                                              COLOR)
        return self.lights[key]

    def obj(self, name: str) -> None:
        """The node of one object at its pose, its links below it, lamps' lights below those."""
        o = self.bundle.scene.objects[name]
        asset = self.bundle.assets[name]
        meta = {"name": o.name, "generator": o.generator, "room": o.room, "parent": o.parent,
                "semantics": sorted(o.tags), "seed": int(o.seed),
                "movable": not self.bundle.is_fixed(o)}
        parent = self.group(self.room_paths[o.room]) if o.room in self.room_paths else self.root
        node = self.doc.node(self.names(o.name), parent,
                             translation=y_up(np.asarray(o.pose.position, float)[None])[0],
                             rotation=_yaw_quaternion(o.pose.yaw), extras=meta)
        frames = joint_frames(asset)
        joints = {j.child: j for j in asset.joints}
        links: dict[str, int] = {}
        pending = list(asset.links)
        while pending:  # parents first: a link hangs from its joint's parent link
            link = pending.pop(0)
            j = joints.get(link)
            up = j.parent if j is not None and j.parent in asset.links else None
            if up is not None and up not in links:
                pending.append(link)
                continue
            base = frames[up] if up is not None else np.zeros(3)
            extras: dict[str, Any] = {"link": link}
            if j is not None:
                extras.update(joint=j.name, joint_kind=j.kind, lower=float(j.lower),
                              upper=float(j.upper),
                              axis=[float(x) for x in y_up(np.asarray(j.axis)[None])[0]])
            links[link] = self.doc.node(
                self.names(f"{o.name}/{link}"), links[up] if up is not None else node,
                translation=y_up((frames[link] - base)[None])[0],
                mesh=self.link_mesh(name, link, frames[link]), extras=extras)
        for e in emitters(asset, o.generator):
            self.doc.node(self.names(f"{o.name}/light_{e.index}"), links[e.link],
                          translation=y_up((e.centre - frames[e.link])[None])[0],
                          light=self.light(name, e.link, e.candela))

    def build(self) -> bytes:
        """The whole document as .glb bytes."""
        self.textures.ensure(self.bundle.all_matrefs())
        for el in sorted(self.bundle.elements, key=lambda e: len(e.path)):
            self.element(el)
        for o in self.bundle.objects:
            self.obj(o.name)
        return self.doc.glb({"indoorgen": {"seed": int(self.bundle.scene.seed),
                                           "objects": len(self.bundle.objects),
                                           "elements": len(self.bundle.elements),
                                           "up": "+Y (indoorgen's +Z)"}})


def glb_bytes(bundle: ExportBundle, textures: TextureStore) -> bytes:
    """The binary glTF of `bundle` (see module docstring)."""
    return _Writer(bundle, textures).build()


def write_glb(bundle: ExportBundle, path: Path, textures: TextureStore) -> Path:
    """Write `scene.glb` (binary glTF, textures embedded) to `path`."""
    Path(path).write_bytes(glb_bytes(bundle, textures))
    return Path(path)
