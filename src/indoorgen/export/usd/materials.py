"""USD materials of a stage: one UsdPreviewSurface per material reference (baked textures
referenced relative to the stage, or mean values where a map is missing), bound to meshes per
material slot."""
from __future__ import annotations

from pathlib import Path

import numpy as np
from pxr import Gf, Sdf, Sdr, Usd, UsdGeom, UsdShade, Vt

from indoorgen.export.bundle import EMISSIVE_SLOTS, MatRef
from indoorgen.export.textures import TextureStore
from indoorgen.export.usd.prims import sanitize_name


def _sdr_type(shader_id: str, name: str) -> Sdf.ValueTypeName:
    node = Sdr.Registry().GetShaderNodeByIdentifier(shader_id)
    return node.GetShaderInput(name).GetTypeAsSdfType().GetSdfType()


class Looks:
    """Material prims under /World/Looks, created on first use (one per material, seed and
    emissive flag)."""

    def __init__(self, stage: Usd.Stage, textures: TextureStore, layer_dir: Path) -> None:
        self.stage, self.textures, self.layer_dir = stage, textures, layer_dir
        self.root = UsdGeom.Scope.Define(stage, "/World/Looks").GetPath()
        self._mats: dict[tuple[MatRef, bool], UsdShade.Material] = {}

    def get(self, ref: MatRef, emissive: bool = False) -> UsdShade.Material:
        """The material of `ref` (emissive: glowing, for bulbs and flames), made on first use."""
        key = (ref, emissive)
        if key not in self._mats:
            self._mats[key] = self._make(ref, emissive)
        return self._mats[key]

    def _make(self, ref: MatRef, emissive: bool) -> UsdShade.Material:
        info = self.textures.info(ref)
        name = sanitize_name(ref.key + ("_emissive" if emissive else ""))
        path = self.root.AppendChild(name)
        mat = UsdShade.Material.Define(self.stage, path)
        pbr = UsdShade.Shader.Define(self.stage, path.AppendChild("PBR"))
        pbr.CreateIdAttr("UsdPreviewSurface")

        def inp(shader, sid, n, value=None):
            i = shader.CreateInput(n, _sdr_type(sid, n))
            if value is not None:
                i.Set(value)
            return i

        ps = "UsdPreviewSurface"
        files = {k: self.textures.relpath(ref, k, self.layer_dir)
                 for k in ("base_color", "roughness", "normal", "metallic")}
        st_out = None
        if any(files.values()):
            reader = UsdShade.Shader.Define(self.stage, path.AppendChild("uv"))
            reader.CreateIdAttr("UsdPrimvarReader_float2")
            inp(reader, "UsdPrimvarReader_float2", "varname", "st")
            reader_out = reader.CreateOutput("result", Sdf.ValueTypeNames.Float2)
            xf = UsdShade.Shader.Define(self.stage, path.AppendChild("uv_scale"))
            xf.CreateIdAttr("UsdTransform2d")
            inp(xf, "UsdTransform2d", "in").ConnectToSource(reader_out)
            s = float(self.textures.uv_scale(ref))
            inp(xf, "UsdTransform2d", "scale", Gf.Vec2f(s, s))
            st_out = xf.CreateOutput("result", Sdf.ValueTypeNames.Float2)

        def texture(kind: str, raw: bool, normal: bool = False):
            tex = UsdShade.Shader.Define(self.stage, path.AppendChild(f"tex_{kind}"))
            tid = "UsdUVTexture"
            tex.CreateIdAttr(tid)
            file = files[kind]
            assert file is not None  # only maps the material has are read
            inp(tex, tid, "file", Sdf.AssetPath("./" + file))
            inp(tex, tid, "st").ConnectToSource(st_out)
            inp(tex, tid, "wrapS", "repeat")
            inp(tex, tid, "wrapT", "repeat")
            inp(tex, tid, "sourceColorSpace", "raw" if raw else "sRGB")
            if normal:
                inp(tex, tid, "scale", Gf.Vec4f(2.0, 2.0, 2.0, 1.0))
                inp(tex, tid, "bias", Gf.Vec4f(-1.0, -1.0, -1.0, 0.0))
            return tex

        if files["base_color"]:
            t = texture("base_color", raw=False)
            inp(pbr, ps, "diffuseColor").ConnectToSource(
                t.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
        else:
            inp(pbr, ps, "diffuseColor", Gf.Vec3f(*_linear(info.mean_color)))
        if files["roughness"]:
            t = texture("roughness", raw=True)
            inp(pbr, ps, "roughness").ConnectToSource(
                t.CreateOutput("r", Sdf.ValueTypeNames.Float))
        else:
            inp(pbr, ps, "roughness", float(info.mean_roughness))
        if files["metallic"]:
            t = texture("metallic", raw=True)
            inp(pbr, ps, "metallic").ConnectToSource(t.CreateOutput("r", Sdf.ValueTypeNames.Float))
        else:
            inp(pbr, ps, "metallic", float(info.metallic_value))
        if files["normal"]:
            t = texture("normal", raw=True, normal=True)
            inp(pbr, ps, "normal").ConnectToSource(t.CreateOutput("rgb", Sdf.ValueTypeNames.Float3))
        if info.opacity < 1.0:
            inp(pbr, ps, "opacity", float(info.opacity))
            inp(pbr, ps, "ior", float(info.ior))
        if emissive:
            inp(pbr, ps, "emissiveColor", Gf.Vec3f(1.0, 0.9, 0.75))
        mat.CreateSurfaceOutput().ConnectToSource(pbr.ConnectableAPI(), "surface")
        mat.GetPrim().CreateAttribute("indoorgen:material", Sdf.ValueTypeNames.String).Set(ref.name)
        mat.GetPrim().CreateAttribute("indoorgen:family", Sdf.ValueTypeNames.String).Set(info.family)
        return mat


def _linear(c) -> tuple[float, float, float]:
    c = np.asarray(c, float)
    lin = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
    return float(lin[0]), float(lin[1]), float(lin[2])


def bind_slots(mesh: UsdGeom.Mesh, face_slots: np.ndarray, slots: list[str],
                materials: dict[str, MatRef], looks: Looks) -> None:
    """Bind one material per slot: directly when the mesh has one slot, else one
    `materialBind` GeomSubset per slot."""
    used = np.unique(face_slots)
    api = UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim())

    def material(si: int) -> UsdShade.Material | None:
        slot = slots[si] if si < len(slots) else "body"
        ref = materials.get(slot)
        return None if ref is None else looks.get(ref, slot in EMISSIVE_SLOTS)

    if len(used) == 1:
        m = material(int(used[0]))
        if m is not None:
            api.Bind(m)
        return
    for si in used:
        idx = np.nonzero(face_slots == si)[0].astype(np.int32)
        slot = slots[si] if si < len(slots) else "body"
        subset = api.CreateMaterialBindSubset(sanitize_name(slot), Vt.IntArray.FromNumpy(idx),
                                              UsdGeom.Tokens.face)
        m = material(int(si))
        if m is not None:
            UsdShade.MaterialBindingAPI.Apply(subset.GetPrim()).Bind(m)
    api.SetMaterialBindSubsetsFamilyType(UsdGeom.Tokens.partition)
