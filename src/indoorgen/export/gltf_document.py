"""A glTF 2.0 document built in memory and packed as binary glTF (`.glb`).

`GltfDocument` holds the JSON tree and one binary buffer: accessors (each in a buffer view of its
own, aligned and with its target, POSITION with its bounds), embedded images, textures with one
repeating sampler, PBR materials, meshes of primitives, nodes and KHR_lights_punctual point
lights. `glb()` packs them as the specification lays out: a 12-byte header, the JSON chunk
(space-padded) and the BIN chunk (zero-padded), each 4-byte aligned.
"""
from __future__ import annotations

import json
import struct
from typing import Any

import numpy as np

#: glTF enums (specification section 5): accessor component types, buffer view targets,
#: sampler filters and wrapping, primitive mode
FLOAT, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
LINEAR, LINEAR_MIPMAP_LINEAR, REPEAT = 9729, 9987, 10497
TRIANGLES = 4
#: accessor type by the number of components per element
_TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}
#: GLB magic ("glTF"), version and chunk types ("JSON", "BIN\0")
_MAGIC, _VERSION, _JSON, _BIN = 0x46546C67, 2, 0x4E4F534A, 0x004E4942
LIGHTS_EXT = "KHR_lights_punctual"


class GltfDocument:
    """A glTF document under construction (state: the JSON tree and the binary buffer)."""

    def __init__(self, generator: str) -> None:
        self.tree: dict[str, Any] = {"asset": {"version": "2.0", "generator": generator},
                                     "scene": 0, "scenes": [{"nodes": []}], "nodes": [],
                                     "meshes": [], "materials": [], "textures": [],
                                     "images": [], "samplers": [], "accessors": [],
                                     "bufferViews": [], "buffers": []}
        self._chunks: list[bytes] = []
        self._length = 0
        self._lights: list[dict[str, Any]] = []

    # -- binary data -----------------------------------------------------------------------
    def _view(self, data: bytes, target: int | None = None) -> int:
        """A buffer view over `data` appended to the buffer (4-byte aligned); its index."""
        pad = -self._length % 4
        if pad:
            self._chunks.append(b"\0" * pad)
            self._length += pad
        view: dict[str, Any] = {"buffer": 0, "byteOffset": self._length, "byteLength": len(data)}
        if target is not None:
            view["target"] = target
        self._chunks.append(data)
        self._length += len(data)
        self.tree["bufferViews"].append(view)
        return len(self.tree["bufferViews"]) - 1

    def accessor(self, array: np.ndarray, *, indices: bool = False, bounds: bool = False) -> int:
        """An accessor of `array` (float32 vertex data, or unsigned triangle indices, 16-bit
        when they fit); `bounds` adds its min and max (required on POSITION). Its index."""
        if indices:
            flat = np.asarray(array).reshape(-1)
            small = flat.size == 0 or int(flat.max()) < 65535
            data = flat.astype(np.uint16 if small else np.uint32)
            acc: dict[str, Any] = {"componentType": UNSIGNED_SHORT if small else UNSIGNED_INT,
                                   "type": "SCALAR", "count": int(data.size)}
            acc["bufferView"] = self._view(data.tobytes(), ELEMENT_ARRAY_BUFFER)
        else:
            rows: np.ndarray = np.ascontiguousarray(array, dtype=np.float32)
            acc = {"componentType": FLOAT, "type": _TYPES[rows.shape[1]],
                   "count": int(rows.shape[0])}
            acc["bufferView"] = self._view(rows.tobytes(), ARRAY_BUFFER)
            if bounds:
                acc["min"] = [float(x) for x in rows.min(axis=0)]
                acc["max"] = [float(x) for x in rows.max(axis=0)]
        self.tree["accessors"].append(acc)
        return len(self.tree["accessors"]) - 1

    def texture(self, image: bytes, mime: str = "image/jpeg") -> int:
        """A texture of the encoded `image` (embedded in the buffer), repeating; its index."""
        if not self.tree["samplers"]:
            self.tree["samplers"].append({"magFilter": LINEAR, "minFilter": LINEAR_MIPMAP_LINEAR,
                                          "wrapS": REPEAT, "wrapT": REPEAT})
        self.tree["images"].append({"bufferView": self._view(image), "mimeType": mime})
        self.tree["textures"].append({"sampler": 0, "source": len(self.tree["images"]) - 1})
        return len(self.tree["textures"]) - 1

    # -- scene objects -----------------------------------------------------------------------
    def material(self, material: dict[str, Any]) -> int:
        """Append a material (a glTF material object); its index."""
        self.tree["materials"].append(material)
        return len(self.tree["materials"]) - 1

    def mesh(self, name: str, primitives: list[dict[str, Any]]) -> int:
        """Append a mesh of triangle `primitives` (attributes, indices, material); its index."""
        self.tree["meshes"].append({"name": name, "primitives": [
            {**p, "mode": TRIANGLES} for p in primitives]})
        return len(self.tree["meshes"]) - 1

    def light(self, name: str, candela: float, color: tuple[float, ...]) -> int:
        """A KHR_lights_punctual point light of `candela` and linear RGB `color`; its index."""
        self._lights.append({"name": name, "type": "point", "intensity": float(candela),
                             "color": [float(c) for c in color]})
        return len(self._lights) - 1

    def node(self, name: str, parent: int | None, *, translation: np.ndarray | None = None,
             rotation: np.ndarray | None = None, mesh: int | None = None,
             light: int | None = None, extras: dict[str, Any] | None = None) -> int:
        """A node named `name` under node `parent` (None: a root of the scene), placed by
        `translation` and the unit quaternion `rotation` (x, y, z, w); its index."""
        node: dict[str, Any] = {"name": name}
        if translation is not None and np.any(translation):
            node["translation"] = [float(x) for x in translation]
        if rotation is not None and not np.allclose(rotation, (0, 0, 0, 1)):
            node["rotation"] = [float(x) for x in rotation]
        if mesh is not None:
            node["mesh"] = mesh
        if light is not None:
            node["extensions"] = {LIGHTS_EXT: {"light": light}}
        if extras:
            node["extras"] = extras
        self.tree["nodes"].append(node)
        index = len(self.tree["nodes"]) - 1
        if parent is None:
            self.tree["scenes"][0]["nodes"].append(index)
        else:
            self.tree["nodes"][parent].setdefault("children", []).append(index)
        return index

    # -- packing -----------------------------------------------------------------------------
    def glb(self, scene_extras: dict[str, Any] | None = None) -> bytes:
        """The document as binary glTF bytes (empty arrays left out, as the schema asks)."""
        tree = {k: v for k, v in self.tree.items() if v != []}
        binary = b"".join(self._chunks)
        binary += b"\0" * (-len(binary) % 4)
        if binary:
            tree["buffers"] = [{"byteLength": len(binary)}]
        else:
            tree.pop("bufferViews", None)
        if self._lights:
            tree["extensionsUsed"] = [LIGHTS_EXT]
            tree["extensions"] = {LIGHTS_EXT: {"lights": self._lights}}
        if scene_extras:
            tree["scenes"] = [{**tree["scenes"][0], "extras": scene_extras}]
        text = json.dumps(tree, separators=(",", ":"), sort_keys=False).encode()
        text += b" " * (-len(text) % 4)
        chunks = struct.pack("<II", len(text), _JSON) + text
        if binary:
            chunks += struct.pack("<II", len(binary), _BIN) + binary
        return struct.pack("<III", _MAGIC, _VERSION, 12 + len(chunks)) + chunks
