"""The tables' shared pieces: a rectangular table's top, legs, apron, shelf and stretchers, its
surfaces and common params, and moving a list of parts."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import OVERLAP, Part, Vec3, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import rect_side_surfaces, support_rect

LEG_STYLES = ("straight", "tapered", "round")


def rect_table_parts(p: dict[str, Any], detail: bool, depth: float, width: float,
                     apron: bool) -> list[Part]:
    """Top + 4 legs (+ apron, lower shelf, stretchers) of a rectangular table in the local
    frame. Low-detail legs are plain boxes/circumscribed cylinders that contain the detailed."""
    h, tt = p["height"], p["top_thickness"]
    lt, inset = p["leg_thickness"], p["leg_inset"]
    style = p["leg_style"]
    z_under = h - tt
    out: list[Part] = []
    if detail and p.get("edge_radius", 0) > 1e-4:
        top = bevel_box((depth, width, tt), (0, 0, h - tt / 2), p["edge_radius"], 2)
    else:
        top = box((depth, width, tt), (0, 0, h - tt / 2))
    out.append(Part(top, "wood"))
    taper = 0.6 if (style == "tapered" and detail) else 1.0
    for leg in legs((depth, width), inset, lt, 0.0, z_under + OVERLAP, taper=taper,
                    round_legs=style == "round", circumscribed=not detail,
                    sections=16 if detail else 8):
        out.append(Part(leg, "wood"))
    cx = depth / 2 - inset - lt / 2  # leg centre lines
    cy = width / 2 - inset - lt / 2
    if apron:
        ah, at = p["apron_height"], 0.02
        z0, z1 = z_under - ah, z_under + OVERLAP
        xa = depth / 2 - inset - 0.01 - at / 2  # set back 1 cm from the legs' outer faces
        ya = width / 2 - inset - 0.01 - at / 2
        for s in (-1, 1):
            out.append(Part(box_between((s * xa - at / 2, -cy, z0), (s * xa + at / 2, cy, z1)),
                            "wood"))
            out.append(Part(box_between((-cx, s * ya - at / 2, z0), (cx, s * ya + at / 2, z1)),
                            "wood"))
    if p.get("lower_shelf"):
        zs, st = p["shelf_height"], 0.018
        out.append(Part(box_between((-cx, -cy, zs - st), (cx, cy, zs)), "wood"))
    if p.get("stretchers"):
        zs, sw = 0.15, min(0.025, lt * 0.6)
        for s in (-1, 1):
            out.append(Part(box_between((-cx, s * cy - sw / 2, zs - sw / 2),
                                        (cx, s * cy + sw / 2, zs + sw / 2)), "wood"))
        out.append(Part(box_between((-sw / 2, -cy, zs - sw / 2), (sw / 2, cy, zs + sw / 2)),
                        "wood"))
    return out


def rect_table_surfaces(p: dict[str, Any], depth: float, width: float) -> list[Surface]:
    """A rectangular table's `top` (2 cm in from its edge) and its four side facets."""
    h = p["height"]
    return [support_rect("top", (0, 0, h), depth / 2 - 0.02, width / 2 - 0.02),
            *rect_side_surfaces(depth, width, h)]


def table_params(h: tuple[float, float], lt: tuple[float, float]) -> dict[str, Param]:
    """The params rectangular tables share, with their height and leg thickness ranges."""
    return {
        "height": Param(*h, doc="overall height = tabletop's upper face (m)"),
        "top_thickness": Param(0.025, 0.05, doc="tabletop thickness (m)"),
        "edge_radius": Param(0.0, 0.01, doc="rounding of the tabletop edges (m)"),
        "leg_thickness": Param(*lt, doc="leg section size at the top (m)"),
        "leg_inset": Param(0.0, 0.06, doc="distance of the legs' outer faces from the top's edge (m)"),
        "leg_style": Param(kind="choice", choices=LEG_STYLES, doc="leg shape"),
    }


def translate_parts(parts: list[Part], offset: Vec3) -> list[Part]:
    """The parts moved by `offset` (slot and link kept)."""
    off = tuple(float(v) for v in offset)
    return [Part(p.solid.translate(off), p.slot, p.link) for p in parts]
