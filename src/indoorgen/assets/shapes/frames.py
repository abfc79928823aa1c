"""Frames, legs and cabinet carcasses: the structural skeletons many furniture families share."""
from __future__ import annotations

from collections.abc import Sequence

import manifold3d as m3d

from indoorgen.assets.shapes.primitives import Part, Vec3, box, box_between, cylinder, tapered_box


def frame(outer_w: float, outer_h: float, border: float, depth: float,
          center: Vec3 = (0.0, 0.0, 0.0)) -> m3d.Manifold:
    """A rectangular picture-frame ring lying in the YZ plane (depth along X): outer size
    outer_w (Y) x outer_h (Z), members `border` wide."""
    outer = box((depth, outer_w, outer_h), center)
    inner = box((depth * 2 + 0.01, outer_w - 2 * border, outer_h - 2 * border), center)
    return outer - inner


def legs(footprint: tuple[float, float], inset: float, thickness: float, z0: float, z1: float,
         taper: float = 1.0, round_legs: bool = False, circumscribed: bool = False,
         sections: int = 16) -> list[m3d.Manifold]:
    """Four legs under a rectangle `footprint` = (depth X, width Y): each leg's outer faces are
    `inset` from the footprint's edges; legs run from z0 (floor) to z1. `taper` < 1 shrinks the
    foot (tapered leg, outer faces kept vertical... approximately: the taper is about the leg
    axis). `round_legs` makes cylinders of diameter `thickness`."""
    d, w = footprint
    cx = d / 2 - inset - thickness / 2
    cy = w / 2 - inset - thickness / 2
    out = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            c = (sx * cx, sy * cy)
            if round_legs:
                r = thickness / 2
                out.append(cylinder(r, z1 - z0, (c[0], c[1], z0), sections,
                                    radius_top=None, circumscribed=circumscribed)
                           if taper >= 0.999 else
                           cylinder(r * taper, z1 - z0, (c[0], c[1], z0), sections, radius_top=r,
                                    circumscribed=circumscribed))
            elif taper >= 0.999:
                out.append(box((thickness, thickness, z1 - z0), (c[0], c[1], (z0 + z1) / 2)))
            else:
                tb = thickness * taper
                out.append(tapered_box((tb, tb), (thickness, thickness), z0, z1, c))
    return out


# ----------------------------------------------------------------------------------- cabinets
def carcass(depth: float, width: float, z0: float, z1: float, board: float,
            back: float = 0.006, shelves: Sequence[float] = (), dividers: Sequence[float] = (),
            slot: str = "wood", back_slot: str | None = None, top: bool = True) -> list[Part]:
    """An open-fronted cabinet box spanning x in [-depth/2, depth/2] (front at +depth/2), y in
    [-width/2, width/2], z in [z0, z1]: two sides, a bottom, a top (unless `top` is False,
    e.g. under a countertop), a back panel `back` thick, fixed shelves whose upper faces are at
    the heights in `shelves`, and full-height vertical dividers centred on the y values in
    `dividers`. Boards overlap by 1 mm so the union is one shell."""
    d2, w2, t, o = depth / 2, width / 2, board, 0.001
    bs = back_slot or slot
    solids = [
        Part(box_between((-d2, -w2, z0), (d2, -w2 + t, z1)), slot),            # sides
        Part(box_between((-d2, w2 - t, z0), (d2, w2, z1)), slot),
        Part(box_between((-d2, -w2 + t - o, z0), (d2, w2 - t + o, z0 + t)), slot),  # bottom
        Part(box_between((-d2, -w2 + t - o, z0 + t - o),
                         (-d2 + back, w2 - t + o, z1 - (t if top else 0) + o)), bs),
    ]
    if top:
        solids.append(Part(box_between((-d2, -w2 + t - o, z1 - t), (d2, w2 - t + o, z1)), slot))
    for zs in shelves:
        solids.append(Part(box_between((-d2 + back - o, -w2 + t - o, zs - t),
                                       (d2 - 0.01, w2 - t + o, zs)), slot))
    for yd in dividers:
        solids.append(Part(box_between((-d2 + back - o, yd - t / 2, z0 + t - o),
                                       (d2, yd + t / 2, z1 - (t if top else 0) + o)), slot))
    return solids
