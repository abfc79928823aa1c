"""Clothes on hangers: shirts, dresses, coats and trousers hanging from a hanger whose hook rests
on a rail (a wardrobe's `Rail` surface).

A garment is its flat silhouette (drawn in the hanger's plane, YZ) given a thickness along X,
over a hanger (a sloped wooden, plastic or wire shoulder bar) with a metal hook on top. The hook
is visual only: its hull would swallow the rail, so the collision pieces are the garment and the
hanger below the rail, and the `hook` surface (downward, at the rail's top) is what the solver
rests on the rail. The front faces +X, along the rail, so garments hang turned across it.
"""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg
import shapely.ops

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.hanging import RAIL_RADIUS, hook
from indoorgen.assets.shapes.outlines import ccw
from indoorgen.assets.shapes.primitives import Part, box_between
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: the kinds of garment
GARMENTS = ("shirt", "dress", "coat", "trousers")
#: the hanger's shoulder bar top, below the rail's top (m): under the rail with 1.2 cm to spare
BAR_TOP = -2 * RAIL_RADIUS - 0.012
#: the shoulder bar's drop from its middle to its ends (m)
BAR_DROP = 0.05
#: the shoulder bar's height and thickness by hanger kind (m)
BAR_SIZE = {"wood": (0.03, 0.012), "plastic": (0.022, 0.008), "wire": (0.006, 0.006)}
#: the hook's wire radius (m)
HOOK_WIRE = 0.0025
#: the half-width of the neck opening where the hanger shows (m)
NECK = 0.06


def _yz_extrude(ring: np.ndarray, x0: float, x1: float) -> m3d.Manifold:
    """Extrude a ring drawn in (y, z) from x0 to x1 along X."""
    m = m3d.Manifold.extrude(m3d.CrossSection([ccw(ring)]), x1 - x0)
    # (a, b, h) -> (x = x0 + h, y = a, z = b): a proper rotation (det +1)
    return m.transform(np.array([[0.0, 0.0, 1.0, x0], [1.0, 0.0, 0.0, 0.0],
                                 [0.0, 1.0, 0.0, 0.0]]))


def _ring(poly: sg.Polygon) -> np.ndarray:
    """The exterior of `poly` without its closing point."""
    return np.asarray(poly.exterior.coords)[:-1]


@register
class HungGarment(PartsFactory):
    """A garment on a hanger (shirt, dress, coat or trousers folded over the bar), hooked on a
    rail: shoulders along Y, front +X along the rail, the hook's `hook` surface at the top."""

    name = "hung_garment"
    tags = frozenset({S.Object, S.SmallObject, S.Textile, S.Garment})
    size_class = "small"
    slots = ["fabric", "hanger", "hook"]
    visual_slots = ("hook",)
    material_choices = {
        "hanger": {"oak": 2.0, "walnut": 1.0, "matte_plastic": 2.0, "glossy_plastic": 1.0},
        "hook": {"chrome": 2.0, "brushed_steel": 2.0, "brass": 0.5},
    }
    params = {
        "garment": Param(kind="choice", choices=GARMENTS, doc="kind of garment"),
        "shoulder_width": Param(0.36, 0.48, doc="the hanger's and the shoulders' width (m)"),
        "length": Param(0.55, 1.1, doc="from the shoulders to the hem (m; trousers: half "
                                        "their leg, folded over the bar)"),
        "thickness": Param(0.02, 0.06, doc="X extent of the hanging garment (m; a coat's "
                                           "doubles)"),
        "hem_flare": Param(0.85, 1.35, doc="hem width over the shoulders' (a dress flares)"),
        "sleeves": Param(kind="choice", choices=("long", "short", "none"),
                         doc="sleeve length (shirts, dresses, coats)"),
        "sleeve_spread": Param(0.0, 0.05, doc="how far the sleeves hang out from the body (m)"),
        "hanger": Param(kind="choice", choices=("wood", "plastic", "wire"), doc="hanger kind"),
    }

    def _thickness(self, p: dict[str, Any]) -> float:
        return p["thickness"] * (2.0 if p["garment"] == "coat" else 1.0)

    def _length(self, p: dict[str, Any]) -> float:
        """From the shoulders' top to the hem (m): a shirt is at most 0.8 m, a coat at least 0.8."""
        return {"shirt": min(p["length"], 0.8), "coat": max(p["length"], 0.8),
                "trousers": min(p["length"], 0.6)}.get(p["garment"], p["length"])

    def _silhouette(self, p: dict[str, Any]) -> sg.Polygon:
        """The garment's outline in (y, z): body, sleeves, or trousers' legs over the bar."""
        w2, top = p["shoulder_width"] / 2, BAR_TOP + 0.004
        bottom = top - self._length(p)
        if p["garment"] == "trousers":
            half = 0.2 * (1.0 + 0.2 * (p["hem_flare"] - 1.0))
            return sg.box(-half, bottom, half, top - 0.004 - BAR_DROP * half / w2)
        flare = p["hem_flare"] if p["garment"] == "dress" else min(p["hem_flare"], 1.05)
        hem = max(w2 * flare, 0.12)
        sh = top - BAR_DROP
        body = sg.Polygon([(-NECK, top - 0.012), (-w2, sh), (-0.85 * w2, sh - 0.2), (-hem, bottom),
                           (hem, bottom), (0.85 * w2, sh - 0.2), (w2, sh), (NECK, top - 0.012)])
        sleeve = {"long": 0.58, "short": 0.2, "none": 0.0}[p["sleeves"]]
        sleeve = min(sleeve, self._length(p) - 0.05)
        if sleeve <= 0.0:
            return body
        spread = p["sleeve_spread"]
        parts = [body]
        for s in (-1.0, 1.0):
            parts.append(sg.Polygon([(s * (w2 - 0.1), sh + 0.01), (s * w2, sh),
                                     (s * (w2 + spread), sh - sleeve),
                                     (s * (w2 + spread - 0.1), sh - sleeve)]))
        out = shapely.ops.unary_union(parts)
        return out if isinstance(out, sg.Polygon) else max(out.geoms, key=lambda g: g.area)

    def _bar(self, p: dict[str, Any]) -> np.ndarray:
        """The shoulder bar's outline in (y, z): a shallow inverted V."""
        w2 = p["shoulder_width"] / 2 - 0.01
        h = BAR_SIZE[p["hanger"]][0]
        return np.array([(-w2, BAR_TOP - BAR_DROP), (0.0, BAR_TOP), (w2, BAR_TOP - BAR_DROP),
                         (w2, BAR_TOP - BAR_DROP - h), (0.0, BAR_TOP - h),
                         (-w2, BAR_TOP - BAR_DROP - h)])

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The garment and the hanger's bar, and the hook over them (slot `hook`, visual only)."""
        t2 = self._thickness(p) / 2
        shape = self._silhouette(p)
        bar_t2 = BAR_SIZE[p["hanger"]][1] / 2
        hanger_hook = hook(HOOK_WIRE, BAR_TOP - 0.009)
        if not detail:
            hb = hanger_hook.bounding_box()
            y0, z0, y1, _ = shape.bounds
            w2 = p["shoulder_width"] / 2 - 0.01  # the bar's ends
            return [Part(box_between((-t2, min(y0, -w2), z0), (t2, max(y1, w2), BAR_TOP + 0.004)),
                         "fabric"),
                    Part(box_between((hb[0], hb[1], BAR_TOP + 0.004), hb[3:]), "hook")]
        garment = _yz_extrude(_ring(shape), -t2, t2)
        bar = _yz_extrude(self._bar(p), -bar_t2, bar_t2)
        return [Part(garment, "fabric"), Part(bar, "hanger"),
                Part(hanger_hook, "hook")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `hook` surface: downward, where the hook's arc rests on a rail's top."""
        return [Surface.rect("hook", Subpart.Hook, (0.0, 0.0, 0.0), (0, 0, -1), (1, 0, 0),
                             HOOK_WIRE, HOOK_WIRE)]
