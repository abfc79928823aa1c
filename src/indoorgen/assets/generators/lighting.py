"""Lighting: a floor lamp (base disc, pole, lathed shade held by spokes)."""
from __future__ import annotations

import math

import numpy as np
from manifold3d import Manifold

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, circle_polygon, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def shade_radius(p, t: float) -> float:
    """Outer shade radius at fraction t of its height (0 = bottom rim, 1 = top rim)."""
    rb, rt = p["shade_bottom_radius"], min(p["shade_top_radius"], p["shade_bottom_radius"])
    style = p["shade_style"]
    if style == "drum":
        return rb
    if style == "cone":
        return rb + (rt - rb) * t
    # bell: concave flare towards the bottom; stays inside the straight cone
    return rt + (rb - rt) * (1 - t) ** 2


@register
class FloorLamp(PartsFactory):
    """A floor lamp: weighted base disc, pole, bulb and a drum/cone/bell shade."""

    name = "floor_lamp"
    tags = frozenset({S.Object, S.Lighting, S.FloorLamp})
    size_class = "medium"
    slots = ["metal", "shade", "emissive"]
    solid_bottom = True
    params = {
        "height": Param(1.4, 1.8, doc="overall height = top of the shade (m)"),
        "base_radius": Param(0.12, 0.2, doc="base disc radius (m)"),
        "base_height": Param(0.015, 0.04, doc="base disc thickness (m)"),
        "pole_radius": Param(0.008, 0.016, doc="pole radius (m)"),
        "shade_bottom_radius": Param(0.16, 0.25, doc="shade radius at its lower rim (m)"),
        "shade_top_radius": Param(0.1, 0.2, doc="shade radius at its upper rim (m; capped at "
                                                "the lower rim's for cone/bell)"),
        "shade_height": Param(0.22, 0.35, doc="shade height (m)"),
        "shade_style": Param(kind="choice", choices=("drum", "cone", "bell"), doc="shade shape"),
        "shade_thickness": Param(0.002, 0.004, doc="shade wall thickness (m)"),
    }

    def parts(self, p, detail):
        H, br, bh = p["height"], p["base_radius"], p["base_height"]
        pr, sh, st = p["pole_radius"], p["shade_height"], p["shade_thickness"]
        z_s0 = H - sh
        z_spoke = H - 0.012
        out = [Part(cylinder(br, bh, (0, 0, 0), 48 if detail else 16, circumscribed=not detail,
                             radius_top=(br - min(0.01, bh) if detail else None)), "metal"),
               Part(cylinder(pr, z_spoke - bh + OVERLAP + 0.004, (0, 0, bh - OVERLAP), 16 if detail else 8,
                             circumscribed=not detail), "metal")]
        if not detail:
            rb, rt = shade_radius(p, 0.0), shade_radius(p, 1.0)
            # (the bell's profile lies inside this straight frustum)
            out.append(Part(cylinder(rb, sh, (0, 0, z_s0), 16, radius_top=rt, circumscribed=True),
                            "shade"))
            return out
        ns = 2 if p["shade_style"] != "bell" else 10
        ts = np.linspace(0.0, 1.0, ns)
        outer = [(shade_radius(p, t), z_s0 + t * sh) for t in ts]
        inner = [(r - st, z) for r, z in reversed(outer)]
        out.append(Part(lathe(outer + inner, 64), "shade"))
        # three horizontal spokes from the pole to the middle of the shade wall
        r_mid = shade_radius(p, (z_spoke - z_s0) / sh) - st / 2
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 6
            out.append(Part(rod((0, 0, z_spoke), (r_mid * math.cos(a), r_mid * math.sin(a), z_spoke),
                                0.003, 8), "metal"))
        out.append(Part(cylinder(0.015, 0.05, (0, 0, z_spoke - 0.05), 16), "metal"))  # socket
        bulb = Manifold.sphere(0.035, 24).translate((0.0, 0.0, z_spoke - 0.075))
        out.append(Part(bulb, "emissive"))
        return out

    def extra_surfaces(self, p):
        br = p["base_radius"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(br * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]
