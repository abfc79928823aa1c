"""Decorative bowls and trays: a wide, low bowl (the shared vessel profiles) or a rounded tray
with a raised rim, for a coffee table or a shelf. Decor, not tableware: kitchens do not use it."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, rounded_rect_polygon, rounded_slab
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
class DecorBowl(PartsFactory):
    """A decorative `bowl` (wide and low: round, conical, flared or deep wall, flat base or foot
    ring) or a `tray` (a rounded rectangle with a raised rim); its inner floor an `interior`."""

    name = "decor_bowl"
    tags = frozenset({S.Object, S.SmallObject, S.Decor})
    size_class = "small"
    slots = ["body"]
    material_choices = {
        "body": {"glazed_ceramic": 2.0, "matte_ceramic": 1.5, "walnut": 1.5, "oak": 1.0,
                 "brass": 1.0, "marble": 1.0, "clear_glass": 0.5, "painted_metal": 0.5},
    }
    params = {
        "style": Param(kind="choice", choices=("bowl", "tray"), doc="bowl or tray"),
        **bowl_params(0.08, 0.17, 0.04, 0.09),
        "tray_length": Param(0.25, 0.45, doc="tray: X extent (m)"),
        "tray_width": Param(0.6, 1.0, doc="tray: Y extent / X extent"),
        "tray_height": Param(0.025, 0.05, doc="tray: Z extent (m)"),
        "tray_corner": Param(0.01, 0.5, doc="tray: corner radius / half the shorter side"),
    }

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """A tray and a flat-based bowl rest on their whole bottom; a foot ring does not."""
        p = self.resolve(params)
        return p["style"] == "tray" or not p["foot_ring"]

    def _tray(self, p: dict[str, Any]) -> tuple[float, float, float, float]:
        """(length, width, height, corner radius) of the tray."""
        L = p["tray_length"]
        W = L * p["tray_width"]
        return L, W, p["tray_height"], max(p["tray_corner"] * 0.5 * min(L, W), 0.004)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The hollow bowl or the tray (slab less its well); placeholder: a cylinder or the slab."""
        if p["style"] == "bowl":
            if not detail:
                return [cheap_cylinder(p["radius"] + p["rim_flare"], 0.0, p["height"], "body")]
            return [Part(bowl_vessel(p).shell, "body")]
        L, W, H, c = self._tray(p)
        slab = rounded_slab(L, W, 0.0, H, c)
        if not detail:
            return [Part(slab, "body")]
        w = p["wall_thickness"] + 0.003
        well = rounded_slab(L - 2 * w, W - 2 * w, p["base_thickness"], H + 0.01, max(c - w, 0.002))
        return [Part(slab - well, "body")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The bowl's round bottom and inner floor, or the tray's rounded bottom and well floor."""
        if p["style"] == "bowl":
            v = bowl_vessel(p)
            return [round_bottom("bottom", bowl_base_radius(p)),
                    interior_floor("interior", v.floor_z, v.floor_r)]
        L, W, _, c = self._tray(p)
        w = p["wall_thickness"] + 0.003
        return [support_polygon("bottom", (0, 0, 0), rounded_rect_polygon(L, W, c, 0.0005),
                                subpart=Subpart.Bottom, up=False),
                support_polygon("interior", (0, 0, p["base_thickness"]),
                                rounded_rect_polygon(L, W, c, w + 0.003), subpart=Subpart.Interior)]
