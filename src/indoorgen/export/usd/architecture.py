"""`architecture.usda`: a solidified home as a USD stage (upAxis Z, metersPerUnit 1, default
prim /World), following the export contract of DESIGN.md::

    /World/Architecture/storey_<k>/<room>/{floor, ceiling, walls}/<room>_<part>
    /World/Architecture/storey_<k>/doors/<door>/{door | leaf, casing}
    /World/Architecture/storey_<k>/windows/<window>/{window | frame, glass}
    /World/Architecture/stairs/<stair>/{stair | flight}, .../<rail>/{railing | rail}

(the part meshes named `<element>_<part>`, e.g. `door_2_casing`, so importers show them by
name; the first part name when the element comes from the asset catalogue, whose generator is
then its `indoorgen:generator`; the others for the simple parametric solids.)

One Xform per element with its meshes (world coordinates) below; every element carries
`indoorgen:generator`, `indoorgen:room`, `indoorgen:parent`, `indoorgen:semantics` (and
`indoorgen:name`).
"""
from __future__ import annotations

from os import PathLike

from pxr import Usd, UsdGeom

from indoorgen.architecture.solidify import Architecture
from indoorgen.export.usd.prims import (
    define_mesh,
    export_stage,
    new_stage,
    part_name,
    sanitize_name,
    tag_prim,
)


def build_architecture_stage(arch: Architecture) -> Usd.Stage:
    """The in-memory stage of `arch`."""
    stage = new_stage()
    root = UsdGeom.Xform.Define(stage, "/World/Architecture").GetPrim().GetPath()
    for storey in arch.floorplan.storeys:
        sp = root.AppendChild(f"storey_{storey.level}")
        prim = UsdGeom.Xform.Define(stage, sp).GetPrim()
        tag_prim(prim, name=f"storey_{storey.level}", generator="floorplan", room="",
                 parent="", semantics=["storey"])
        for r in storey.rooms:
            g = arch.rooms[r.name]
            rp = sp.AppendChild(sanitize_name(r.name))
            tag_prim(UsdGeom.Xform.Define(stage, rp).GetPrim(), name=r.name,
                     generator="floorplan", room=r.name, parent="",
                     semantics=["room", r.type])
            parts = [("floor", g.floor, "floor"), ("ceiling", g.ceiling, "ceiling")]
            parts += [(f"walls_{i}" if i else "walls", w, "wall") for i, w in enumerate(g.walls)]
            for name, mesh, kind in parts:
                ep = rp.AppendChild(name)
                tag_prim(UsdGeom.Xform.Define(stage, ep).GetPrim(), name=name,
                         generator=kind, room=r.name, parent="", semantics=[kind, "architecture"])
                define_mesh(stage, ep.AppendChild(part_name(r.name, name)), mesh)
    groups = {"door": "doors", "window": "windows", "stair": "stairs", "railing": "stairs"}
    for el in arch.elements:
        group = groups.get(el.kind, "elements")
        base = root if group == "stairs" else root.AppendChild(f"storey_{el.storey}")
        gp = base.AppendChild(group)
        if not stage.GetPrimAtPath(gp):
            UsdGeom.Xform.Define(stage, gp)
        ep = gp.AppendChild(sanitize_name(el.name))
        tag_prim(UsdGeom.Xform.Define(stage, ep).GetPrim(), name=el.name,
                 generator=el.generator or f"{el.kind}_simple", room=el.room,
                 parent=el.room, semantics=el.semantics)
        for part, mesh in el.meshes.items():
            define_mesh(stage, ep.AppendChild(part_name(el.name, part)), mesh)
    return stage


def write_architecture_usd(arch: Architecture, path: str | PathLike) -> None:
    """Write `arch` to `path` (.usda or .usdc); OutputError if it cannot be written."""
    export_stage(build_architecture_stage(arch), path)
