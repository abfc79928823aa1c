"""Tables: rectangular and round dining tables, coffee tables and side tables.

All tables expose `top` (a SupportSurface: the tabletop's upper face minus a 2 cm border) and
side surfaces `side_0..` spanning the full height, which is where chairs are pushed in; box
`side_left`/`side_right` are replaced by these.
"""
from __future__ import annotations

import math
from typing import Any

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    bevel_box,
    box,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
)
from indoorgen.assets.shapes.surfaces import (
    polygon_side_surfaces,
    rect_side_surfaces,
    support_polygon,
    support_rect,
)
from indoorgen.model.tags import Semantics as S

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


def rect_table_surfaces(p: dict[str, Any], depth: float, width: float):
    h = p["height"]
    return [support_rect("top", (0, 0, h), depth / 2 - 0.02, width / 2 - 0.02),
            *rect_side_surfaces(depth, width, h)]


def _common_params(h: tuple[float, float], lt: tuple[float, float]) -> dict[str, Param]:
    return {
        "height": Param(*h, doc="overall height = tabletop's upper face (m)"),
        "top_thickness": Param(0.025, 0.05, doc="tabletop thickness (m)"),
        "edge_radius": Param(0.0, 0.01, doc="rounding of the tabletop edges (m)"),
        "leg_thickness": Param(*lt, doc="leg section size at the top (m)"),
        "leg_inset": Param(0.0, 0.06, doc="distance of the legs' outer faces from the top's edge (m)"),
        "leg_style": Param(kind="choice", choices=LEG_STYLES, doc="leg shape"),
    }


@register
class DiningTableRect(PartsFactory):
    """A rectangular dining table: top, apron and four legs; optional stretchers."""

    name = "dining_table_rect"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.DiningTable})
    size_class = "large"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.8, 1.0, doc="X extent, the short side (m)"),
        "length": Param(1.2, 2.2, doc="Y extent, the long side (m)"),
        **_common_params((0.72, 0.78), (0.05, 0.09)),
        "apron_height": Param(0.06, 0.12, doc="height of the apron boards under the top (m)"),
        "stretchers": Param(kind="bool", doc="add an H of stretchers between the legs"),
    }

    def parts(self, p, detail):
        return rect_table_parts(p, detail, p["depth"], p["length"], apron=True)

    def extra_surfaces(self, p):
        return rect_table_surfaces(p, p["depth"], p["length"])


@register
class CoffeeTable(PartsFactory):
    """A low rectangular coffee table, optionally with a lower shelf."""

    name = "coffee_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.CoffeeTable})
    size_class = "large"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.5, 0.8, doc="X extent (m)"),
        "length": Param(0.9, 1.4, doc="Y extent (m)"),
        **_common_params((0.38, 0.48), (0.035, 0.07)),
        "apron": Param(kind="bool", doc="add apron boards under the top"),
        "apron_height": Param(0.04, 0.08, doc="apron board height (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf between the legs"),
        "shelf_height": Param(0.08, 0.15, doc="height of the lower shelf's upper face (m)"),
    }

    def parts(self, p, detail):
        return rect_table_parts(p, detail, p["depth"], p["length"], apron=p["apron"])

    def extra_surfaces(self, p):
        return rect_table_surfaces(p, p["depth"], p["length"])


@register
class SideTable(PartsFactory):
    """A small square-ish side table, optionally with a lower shelf."""

    name = "side_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.SideTable})
    size_class = "medium"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.4, 0.6, doc="X extent (m)"),
        "width": Param(0.4, 0.6, doc="Y extent (m)"),
        **_common_params((0.5, 0.65), (0.03, 0.05)),
        "apron": Param(kind="bool", doc="add apron boards under the top"),
        "apron_height": Param(0.04, 0.08, doc="apron board height (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf between the legs"),
        "shelf_height": Param(0.12, 0.25, doc="height of the lower shelf's upper face (m)"),
    }

    def parts(self, p, detail):
        return rect_table_parts(p, detail, p["depth"], p["width"], apron=p["apron"])

    def extra_surfaces(self, p):
        return rect_table_surfaces(p, p["depth"], p["width"])


@register
class DiningTableRound(PartsFactory):
    """A round dining table on a pedestal or on 3-4 legs. Its `n_sides` side facets (a regular
    N-gon circumscribing the top) are where chairs go."""

    name = "dining_table_round"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.DiningTable})
    size_class = "large"
    slots = ["wood", "metal"]
    drop_box = ("side_left", "side_right")
    params = {
        "radius": Param(0.45, 0.7, doc="tabletop radius (m)"),
        "height": Param(0.72, 0.78, doc="overall height = tabletop's upper face (m)"),
        "top_thickness": Param(0.025, 0.05, doc="tabletop thickness (m)"),
        "edge_radius": Param(0.0, 0.01, doc="rounding of the tabletop's edge (m)"),
        "base_style": Param(kind="choice", choices=("pedestal", "legs3", "legs4"),
                            doc="central pedestal or 3/4 legs"),
        "n_sides": Param(4, 8, kind="int", doc="number of chair-facing side facets"),
        "column_radius": Param(0.04, 0.09, doc="pedestal column radius (m)"),
        "foot_radius_frac": Param(0.45, 0.7, doc="pedestal foot radius / top radius"),
        "leg_thickness": Param(0.04, 0.07, doc="leg diameter for legged bases (m)"),
        "leg_radius_frac": Param(0.55, 0.75, doc="leg circle radius / top radius"),
    }

    def parts(self, p, detail):
        r, h, tt = p["radius"], p["height"], p["top_thickness"]
        er = p["edge_radius"]
        n = 64 if detail else 16
        if detail and er > 1e-4:
            prof = [(0.0, h - tt)]
            for k in range(5):  # bottom corner arc
                a = -math.pi / 2 + (math.pi / 2) * k / 4
                prof.append((r - er + er * math.cos(a), h - tt + er + er * math.sin(a)))
            for k in range(5):  # top corner arc
                a = (math.pi / 2) * k / 4
                prof.append((r - er + er * math.cos(a), h - er + er * math.sin(a)))
            prof.append((0.0, h))
            top = lathe(prof, n)
        else:
            top = cylinder(r, tt, (0, 0, h - tt), n, circumscribed=not detail)
        out = [Part(top, "wood")]
        z_under = h - tt + OVERLAP
        circ = not detail
        if p["base_style"] == "pedestal":
            fr = r * p["foot_radius_frac"]
            cr = p["column_radius"]
            foot = cylinder(fr, 0.04, (0, 0, 0), n, radius_top=(fr * 0.8 if detail else None),
                            circumscribed=circ)
            out.append(Part(foot, "metal"))
            out.append(Part(cylinder(cr, z_under - 0.03, (0, 0, 0.03), 32 if detail else 8,
                                     circumscribed=circ), "wood"))
            out.append(Part(cylinder(min(cr * 2.2, r * 0.6), 0.03, (0, 0, z_under - 0.03),
                                     32 if detail else 8, circumscribed=circ), "wood"))
        else:
            k = 3 if p["base_style"] == "legs3" else 4
            lr, lt = r * p["leg_radius_frac"], p["leg_thickness"]
            for i in range(k):
                a = 2 * math.pi * (i + 0.5) / k
                c = (lr * math.cos(a), lr * math.sin(a), 0.0)
                out.append(Part(cylinder(lt / 2 * (0.7 if detail else 1.0), z_under, c,
                                         16 if detail else 8, radius_top=lt / 2,
                                         circumscribed=circ), "wood"))
            # a ring apron tying the legs together under the top
            ring_r = lr + lt / 2 + 0.005
            ring = [(ring_r - 0.02, z_under - 0.06), (ring_r, z_under - 0.06), (ring_r, z_under),
                    (ring_r - 0.02, z_under)]
            out.append(Part(lathe(ring, n, circumscribed=circ), "wood"))
        return out

    def extra_surfaces(self, p):
        r, h = p["radius"], p["height"]
        return [support_polygon("top", (0, 0, h), circle_polygon(r - 0.02, 64)),
                *polygon_side_surfaces(r, int(p["n_sides"]), h)]
