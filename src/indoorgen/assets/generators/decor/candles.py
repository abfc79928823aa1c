"""Candles: pillars, tapers in a candlestick, tealights and jar candles, optionally lit (a wick and
an emissive flame)."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.decor._parts import bbox_part
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, circle_polygon, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: flame size (its height is 2.8 times this) (m)
FLAME = 0.011


def _flame(z0: float, size: float) -> m3d.Manifold:
    """A teardrop flame standing on z0 (its base overlaps the wick by 3 mm)."""
    prof = [(0.0, 0.0), (0.45 * size, 0.35 * size), (0.5 * size, 0.8 * size),
            (0.35 * size, 1.6 * size), (0.12 * size, 2.4 * size), (0.0, 2.8 * size)]
    return lathe(prof, 16).translate((0.0, 0.0, z0))


@register
class Candle(PartsFactory):
    """A candle: a `pillar` (with a melted pool and drips), a `taper` in a turned candlestick,
    a `tealight` in its metal cup, or a `jar` candle (wax in an open glass jar). Optionally lit:
    a wick and an emissive flame."""

    name = "candle"
    frequency = 0.5  # fewer than frames, vases and plants
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Candle})
    size_class = "small"
    slots = ["wax", "metal", "glass", "fabric", "emissive"]
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=("pillar", "taper", "tealight", "jar"),
                       doc="kind of candle"),
        "radius": Param(0.025, 0.045, doc="pillar / jar radius (m)"),
        "height": Param(0.06, 0.2, doc="pillar / jar / taper wax height (m)"),
        "lit": Param(kind="bool", doc="burning: wick and flame"),
        "melt_depth": Param(0.0, 0.012, doc="depth of the melted pool at the top (m)"),
        "drips": Param(0, 5, kind="int", doc="wax drips down the side (pillar, taper)"),
        "holder_radius": Param(0.035, 0.06, doc="candlestick base radius (m)"),
        "holder_height": Param(0.07, 0.18, doc="candlestick height (m)"),
    }

    def _base_radius(self, p) -> float:
        st = p["style"]
        if st == "taper":
            return p["holder_radius"]
        if st == "tealight":
            return 0.019
        return p["radius"]

    def _wax_top(self, p) -> tuple[float, float, float]:
        """(z of the wax top, wax radius, height the wick/flame start from)."""
        st, H, R = p["style"], p["height"], p["radius"]
        if st == "pillar":
            return H, R, H - p["melt_depth"]
        if st == "taper":
            zt = p["holder_height"] + H - 0.012
            return zt, 0.011, zt
        if st == "tealight":
            return 0.014, 0.017, 0.014
        zt = 0.65 * H
        return zt, R - 0.003, zt - 0.4 * p["melt_depth"]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The candle of its style and, lit, a wick and flame; placeholder: cylinders."""
        st, H = p["style"], p["height"]
        z_wax, r_wax, z_wick = self._wax_top(p)
        top = max(z_wax, H if st == "jar" else 0.0)
        if p["lit"]:
            top = max(top, z_wick + 0.006 + 2.8 * FLAME)
        if not detail:
            return self._cheap(p, top)
        out = {"pillar": self._pillar, "taper": self._taper, "tealight": self._tealight,
               "jar": self._jar}[st](p)
        if p["lit"]:
            out.append(Part(rod((0, 0, z_wick - 0.004), (0, 0, z_wick + 0.009), 0.0012, 8), "fabric"))
            out.append(Part(_flame(z_wick + 0.006, FLAME), "emissive"))
        return out

    def _cheap(self, p, top):
        st = p["style"]
        if st == "taper":
            hr, hh = p["holder_radius"], p["holder_height"]
            return [Part(cylinder(hr, hh * 0.3 + 0.001, (0, 0, 0), 16, circumscribed=True), "metal"),
                    Part(cylinder(max(0.022, 0.45 * hr), top - hh * 0.3, (0, 0, hh * 0.3), 8,
                                  circumscribed=True), "wax")]
        out = [Part(cylinder(self._base_radius(p), top, (0, 0, 0), 16, circumscribed=True), "wax")]
        if st == "pillar":  # drips bulge out of the side: a box round each
            out += [bbox_part([d], "wax") for d in self._drips(p, p["radius"] - 0.0015,
                                                               p["height"], 5)]
        return out

    def _drips(self, p, r: float, z_top: float, n_max: int) -> list[Part]:
        out = []
        for k in range(min(int(p["drips"]), n_max)):
            a = 2 * math.pi * (k * 0.382 + 0.1)
            ln = 0.015 + 0.012 * ((k * 7) % 3)
            c0 = np.array([r * math.cos(a), r * math.sin(a), z_top - 0.003])
            c1 = np.array([r * math.cos(a), r * math.sin(a), z_top - ln])
            drip = m3d.Manifold.hull_points(np.vstack([
                m3d.Manifold.sphere(0.0035, 8).translate(tuple(c0)).to_mesh().vert_properties,
                m3d.Manifold.sphere(0.0028, 8).translate(tuple(c1)).to_mesh().vert_properties]))
            out.append(Part(drip, "wax"))
        return out

    def _pillar(self, p):
        H, R, m = p["height"], p["radius"], p["melt_depth"]
        prof = [(0.0, 0.0), (R, 0.0), (R, H - 0.003), (R - 0.003, H), (R - 0.005, H)]
        if m > 0.001:
            prof += [(0.75 * R, H - 0.6 * m), (0.4 * R, H - m), (0.0, H - m)]
        else:
            prof += [(0.0, H)]
        return [Part(lathe(prof, 48), "wax")] + self._drips(p, R - 0.0015, H, 5)

    def _taper(self, p):
        hr, hh, H = p["holder_radius"], p["holder_height"], p["height"]
        stem_r, cup_r = 0.009, 0.02
        # a turned candlestick: foot, baluster stem, cup with a 14 mm socket for the candle
        prof = [(0.0, 0.0), (hr, 0.0), (hr, 0.08 * hh), (0.55 * hr, 0.16 * hh),
                (stem_r + 0.003, 0.24 * hh), (stem_r, 0.4 * hh), (1.5 * stem_r, 0.55 * hh),
                (stem_r, 0.7 * hh), (cup_r, hh - 0.018), (cup_r, hh), (0.0115, hh),
                (0.0115, hh - 0.014), (0.0, hh - 0.014)]
        holder = lathe(prof, 32)
        z0 = hh - 0.014 - SMALL_OVERLAP
        z1 = hh + H - 0.012
        candle = lathe([(0.0, z0), (0.011, z0), (0.0095, z1 - 0.002), (0.008, z1), (0.0, z1)], 24)
        return [Part(holder, "metal"), Part(candle, "wax")] + self._drips(p, 0.009, z1, 3)

    def _tealight(self, p):
        cup = lathe([(0.0, 0.0), (0.019, 0.0), (0.019, 0.016), (0.0185, 0.016), (0.0185, 0.0005),
                     (0.0, 0.0005)], 32)
        wax = cylinder(0.0187, 0.0145 - 0.0003, (0, 0, 0.0003), 32)
        return [Part(cup, "metal"), Part(wax, "wax")]

    def _jar(self, p):
        H, R = p["height"], p["radius"]
        w = 0.003
        jar = lathe([(0.0, 0.0), (R, 0.0), (R, H), (R - w, H), (R - w, 0.006), (0.0, 0.006)], 48)
        z_wax, _, _ = self._wax_top(p)
        m = p["melt_depth"]
        wax = lathe([(0.0, 0.006 - SMALL_OVERLAP), (R - w + 0.0005, 0.006 - SMALL_OVERLAP),
                     (R - w + 0.0005, z_wax), (0.6 * R, z_wax - 0.4 * m), (0.0, z_wax - 0.4 * m)], 48)
        return [Part(jar, "glass"), Part(wax, "wax")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The round underside (pillar, jar, cup or candlestick foot) as the `bottom`."""
        r = self._base_radius(p) - 0.0005
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r, 32),
                                subpart=Subpart.Bottom, up=False)]
