"""glTF binary export (`scene.glb`) through trimesh.

Node hierarchy: `world` -> `architecture` -> one node per element (its parts below; a door's
leaf is an element node of its own, `.../doors/<door>/leaf`, at the angle it stands, its joint
in `extras`) and
`world` -> `objects` -> one node per object at its pose -> one node per link -> one mesh per
material slot. Materials are glTF PBR (base colour, metallic-roughness and normal textures);
identical objects share their glTF meshes. Every element and object node carries its semantic
labels and the indoorgen attributes in `extras`.
"""
from __future__ import annotations

import io
import logging
from pathlib import Path
from typing import Any

import numpy as np
import trimesh
from PIL import Image
from trimesh.visual.material import PBRMaterial
from trimesh.visual.texture import TextureVisuals

from indoorgen.export.bundle import ExportBundle, MatRef
from indoorgen.export.meshes import Piece, asset_slot_pieces, joint_frames, mesh_piece
from indoorgen.export.textures import TextureStore

log = logging.getLogger(__name__)

#: JPEG quality of the embedded textures
JPEG_QUALITY = 90


class _Materials:
    """One PBRMaterial per MatRef (images loaded once)."""

    def __init__(self, textures: TextureStore) -> None:
        self.textures = textures
        self._m: dict[tuple, PBRMaterial] = {}

    def get(self, ref: MatRef, emissive: bool = False) -> PBRMaterial:
        key = (ref, emissive)
        if key in self._m:
            return self._m[key]
        info = self.textures.info(ref)
        paths = self.textures.paths(ref)
        kw = {"name": ref.key + ("_emissive" if emissive else ""),
              "roughnessFactor": 1.0, "metallicFactor": 1.0 if "metallic" in paths else
              float(info.metallic_value)}
        if "base_color" in paths:
            kw["baseColorTexture"] = _jpeg(Image.open(paths["base_color"]))
            kw["baseColorFactor"] = [1.0, 1.0, 1.0, float(info.opacity)]
        else:
            kw["baseColorFactor"] = [*map(float, info.mean_color), float(info.opacity)]
        if "roughness" in paths:
            rough = np.asarray(Image.open(paths["roughness"]).convert("L"))
            metal = (np.asarray(Image.open(paths["metallic"]).convert("L")) if "metallic" in paths
                     else np.zeros_like(rough))
            kw["metallicRoughnessTexture"] = _jpeg(Image.fromarray(
                np.stack([np.zeros_like(rough), rough, metal], axis=-1)))
        else:
            kw["roughnessFactor"] = float(info.mean_roughness)
        if "normal" in paths:
            kw["normalTexture"] = _jpeg(Image.open(paths["normal"]))
        if info.opacity < 1.0:
            kw["alphaMode"] = "BLEND"
        if emissive:
            kw["emissiveFactor"] = [1.0, 0.9, 0.75]
        m = PBRMaterial(**kw)
        self._m[key] = m
        return m


def _jpeg(img: Image.Image) -> Image.Image:
    """`img` re-opened from an in-memory JPEG: trimesh then embeds it as JPEG (fast to encode
    and small) instead of re-encoding a PNG."""
    buf = io.BytesIO()
    img.convert("RGB").save(buf, format="JPEG", quality=JPEG_QUALITY)
    buf.seek(0)
    out = Image.open(buf)
    out.load()
    return out


def _geometry(piece: Piece, material: PBRMaterial, scale: float) -> trimesh.Trimesh:
    mesh = trimesh.Trimesh(piece.vertices, piece.faces, vertex_normals=piece.normals,
                           process=False)
    mesh.visual = TextureVisuals(uv=piece.uv * scale, material=material)
    return mesh


def build_scene(bundle: ExportBundle, textures: TextureStore) -> trimesh.Scene:
    """The trimesh Scene of `bundle` (see module docstring)."""
    scene = trimesh.Scene(base_frame="world")
    mats = _Materials(textures)
    g = scene.graph
    g.update(frame_from="world", frame_to="architecture", matrix=np.eye(4))
    g.update(frame_from="world", frame_to="objects", matrix=np.eye(4))
    for el in bundle.elements:
        node = "architecture/" + "/".join(el.path)
        meta: dict[str, Any] = {"name": el.name, "kind": el.kind, "room": el.room,
                "semantics": sorted(el.semantics), "generator": el.kind, "parent": el.parent}
        if el.joint is not None:  # a door leaf, standing at its joint value
            meta.update(joint=el.joint.kind, joint_value=round(float(el.joint_value), 6),
                        joint_lower=float(el.joint.lower), joint_upper=float(el.joint.upper))
        g.update(frame_from="architecture", frame_to=node, matrix=np.eye(4), metadata=meta)
        for part in el.parts:
            gname = f"{node}/{part.name}"
            scene.add_geometry(_geometry(mesh_piece(part.mesh), mats.get(part.material),
                                         textures.uv_scale(part.material)),
                               geom_name=gname, node_name=gname, parent_node_name=node)
    shared: dict[tuple, dict[tuple[str, str], str]] = {}
    for obj in bundle.objects:
        asset = bundle.assets[obj.name]
        node = f"objects/{obj.name}"
        g.update(frame_from="objects", frame_to=node, matrix=obj.pose.matrix(),
                 metadata={"name": obj.name, "generator": obj.generator, "room": obj.room,
                           "parent": obj.parent, "semantics": sorted(obj.tags),
                           "seed": int(obj.seed), "movable": not bundle.is_fixed(obj)})
        key = bundle.proto_key(obj.name)
        geoms = shared.get(key)
        if geoms is None:
            geoms = {}
            mref = bundle.materials[obj.name]
            for link in asset.links:
                for slot, piece in asset_slot_pieces(asset, link):
                    ref = mref.get(slot) or next(iter(mref.values()))
                    gname = f"{obj.name}/{link}/{slot}"
                    scene.add_geometry(_geometry(piece, mats.get(ref, slot in ("emissive",
                                                                               "bulb")),
                                                 textures.uv_scale(ref)), geom_name=gname)
                    geoms[(link, slot)] = gname
            shared[key] = geoms
        frames = joint_frames(asset)
        for link in asset.links:
            lnode = f"{node}/{link}"
            m = np.eye(4)
            m[:3, 3] = frames[link]
            g.update(frame_from=node, frame_to=lnode, matrix=m, metadata={"link": link})
            inv = np.eye(4)
            inv[:3, 3] = -frames[link]
            for (glink, slot), gname in geoms.items():
                if glink == link:
                    g.update(frame_from=lnode, frame_to=f"{lnode}/{slot}", matrix=inv,
                             geometry=gname)
    scene.metadata["indoorgen"] = {"seed": int(bundle.scene.seed),
                                   "objects": len(bundle.objects),
                                   "elements": len(bundle.elements)}
    return scene


def write_glb(bundle: ExportBundle, path: Path, textures: TextureStore) -> Path:
    """Write `scene.glb` (binary glTF, textures embedded) to `path`."""
    scene = build_scene(bundle, textures)
    data = scene.export(file_type="glb")
    Path(path).write_bytes(data)
    return Path(path)
