"""Dishes: lathed plates and hollow bowls (bowls of `shapes.vessels`, shared with the fruit bowl)."""
from __future__ import annotations

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, circle_polygon, cylinder, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.assets.shapes.vessels import (
    bowl_base_radius,
    bowl_params,
    bowl_vessel,
    cheap_cylinder,
    interior_floor,
    round_bottom,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Plate(PartsFactory):
    """A plate: flat foot/well of radius `foot_frac * radius`, a rim rising to `rim_height`;
    its top surface is the underside lifted by `thickness` (so walls keep their thickness)."""

    name = "plate"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Plate})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.09, 0.15, doc="outer radius (m)"),
        "rim_height": Param(0.015, 0.035, doc="Z extent (m)"),
        "thickness": Param(0.004, 0.008, doc="wall thickness (m)"),
        "foot_frac": Param(0.5, 0.7, doc="flat foot (and well) radius / radius"),
        "rim_curve": Param(1.0, 2.5, doc="rim profile exponent (1 = straight cone, >1 = curved)"),
        "rim_lip": Param(kind="bool", doc="add a flat lip at the rim"),
    }

    def underside(self, p, n: int) -> list[tuple[float, float]]:
        """The plate's underside as n + 1 (r, z) points from the foot's edge to the rim."""
        R, h, th = p["radius"], p["rim_height"], p["thickness"]
        rf = R * p["foot_frac"]
        lip = 0.12 * (R - rf) if p["rim_lip"] else 0.0
        pts = []
        for i in range(n + 1):
            u = i / n
            r = rf + (R - lip - rf) * u
            pts.append((r, (h - th) * u ** p["rim_curve"]))
        if lip:
            pts.append((R, h - th))
        return pts

    def parts(self, p, detail):
        """The plate's solids: detailed, or the blocks of its placeholder."""
        R, h, th = p["radius"], p["rim_height"], p["thickness"]
        if not detail:
            return [Part(cylinder(R, h, (0, 0, 0), 16, circumscribed=True), "ceramic")]
        under = self.underside(p, 10)
        top = [(r, z + th) for r, z in reversed(under)]
        prof = [(0.0, 0.0)] + under + top + [(0.0, th)]
        return [Part(lathe(prof, 64), "ceramic")]

    def extra_surfaces(self, p):
        """The plate's surfaces besides its bounding box's: bottom, top."""
        rf = p["radius"] * p["foot_frac"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(rf * 0.995, 64),
                                subpart=Subpart.Bottom, up=False),
                support_polygon("top", (0, 0, p["thickness"]), circle_polygon(rf * 0.95, 64))]



@register
class Bowl(PartsFactory):
    """A bowl: round, conical, flared or deep wall profile from a flat base or a foot ring, with
    an optional flared rim; hollow, its inner floor an `interior` surface."""

    name = "bowl"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bowl})
    size_class = "small"
    slots = ["ceramic"]
    params = bowl_params(0.06, 0.13, 0.04, 0.09)

    def bottom_is_solid(self, params):
        """Whether the bowl rests on a flat base, not on a foot ring."""
        return not self.resolve(params)["foot_ring"]

    def parts(self, p, detail):
        """The bowl's solids: detailed, or the blocks of its placeholder."""
        if not detail:
            return [cheap_cylinder(p["radius"] + p["rim_flare"], 0.0, p["height"], "ceramic")]
        return [Part(bowl_vessel(p).shell, "ceramic")]

    def extra_surfaces(self, p):
        """The bowl's surfaces besides its bounding box's: bottom, interior."""
        v = bowl_vessel(p)
        return [round_bottom("bottom", bowl_base_radius(p)),
                interior_floor("interior", v.floor_z, v.floor_r)]
