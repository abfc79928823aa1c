"""Drinkware: cups, mugs, wine glasses and tumblers, all solids of revolution.

A cup is a closed lathed solid with an open cavity; mugs, glasses and tumblers are hollow
vessels (`shapes.vessels.revolve_vessel`) whose cavity opens at the rim.
"""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.primitives import Part, bevel_box, box_between, circle_polygon, lathe, torus
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    Vessel,
    cheap_cylinder,
    interior_floor,
    revolve_vessel,
    round_bottom,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Cup(PartsFactory):
    """A cup or mug: a lathed body with a hollow, optionally a torus handle on +Y (clipped so
    none of it enters the cavity)."""

    name = "cup"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.035, 0.05, doc="outer radius at the rim (m)"),
        "bottom_frac": Param(0.7, 1.0, doc="outer radius at the base / at the rim"),
        "height": Param(0.07, 0.12, doc="body height (m)"),
        "wall_thickness": Param(0.003, 0.006, doc="wall thickness (m)"),
        "base_thickness": Param(0.005, 0.012, doc="floor thickness (m)"),
        "handle": Param(kind="bool", doc="add a handle"),
        "handle_size": Param(0.018, 0.03, doc="handle loop radius (m)"),
        "handle_thickness": Param(0.004, 0.008, doc="handle cross-section radius (m)"),
    }

    def _r(self, p, z: float) -> float:
        rb, rt = p["radius"] * p["bottom_frac"], p["radius"]
        return rb + (rt - rb) * z / p["height"]

    def _handle_dims(self, p) -> tuple[float, float, float]:
        """(loop radius, tube radius, centre height), shrunk to stay within the body height."""
        H, hr = p["height"], p["handle_thickness"]
        R = min(p["handle_size"], 0.5 * H - hr - 0.012)
        return R, hr, H * 0.5

    def parts(self, p, detail):
        """The cup's solids: detailed, or the blocks of its placeholder."""
        H, w, b = p["height"], p["wall_thickness"], p["base_thickness"]
        rb, rt = p["radius"] * p["bottom_frac"], p["radius"]
        out = []
        if detail:
            prof = [(0.0, 0.0), (rb, 0.0), (rt, H), (rt - w, H), (self._r(p, b) - w, b), (0.0, b)]
            body = lathe(prof, 48)
            out.append(Part(body, "ceramic"))
        else:
            out.append(Part(lathe([(0.0, 0.0), (rb, 0.0), (rt, H), (0.0, H)], 16, circumscribed=True),
                            "ceramic"))
        if p["handle"]:
            R, hr, zc = self._handle_dims(p)
            yc = self._r(p, zc)
            if detail:
                ring = torus(R, hr, sections=24, tube_sections=8).rotate((90.0, 0.0, 90.0))
                ring = ring.translate((0.0, yc, zc))
                cavity = lathe([(0.0, b), (self._r(p, b) - w + 0.0005, b),
                                (rt - w + 0.0005, H), (rt - w + 0.0005, H + 0.05), (0.0, H + 0.05)], 48)
                out.append(Part(ring - cavity, "ceramic"))
            else:
                out.append(Part(box_between((-hr, yc - 0.004, zc - R - hr), (hr, yc + R + hr, zc + R + hr)),
                                "ceramic"))
        return out

    def extra_surfaces(self, p):
        """The cup's surfaces besides its bounding box's: bottom."""
        rb = p["radius"] * p["bottom_frac"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(rb * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------------- mugs
MUG_SHAPES = ("straight", "tapered", "barrel", "tulip")


@register
class Mug(PartsFactory):
    """A mug: straight, tapered, barrel or tulip body, hollow with a thick floor, and a handle on
    +Y (a round or ear-shaped torus segment, or a squared loop) whose ends sink into the wall."""

    name = "mug"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup, S.Mug})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.036, 0.05, doc="outer radius at the rim (m)"),
        "height": Param(0.08, 0.115, doc="height (m)"),
        "shape": Param(kind="choice", choices=MUG_SHAPES, doc="body profile"),
        "bottom_frac": Param(0.72, 0.95, doc="base radius / rim radius (straight: base bevel)"),
        "wall_thickness": Param(0.003, 0.006, doc="wall thickness (m)"),
        "base_thickness": Param(0.007, 0.012, doc="floor thickness (m)"),
        "handle_shape": Param(kind="choice", choices=("round", "ear", "square"), doc="handle loop"),
        "handle_size": Param(0.02, 0.032, doc="handle loop half-height (m)"),
        "handle_thickness": Param(0.004, 0.008, doc="handle cross-section radius (m)"),
    }

    def _radius(self, p, t: np.ndarray) -> np.ndarray:
        R, b, s = p["radius"], p["bottom_frac"], p["shape"]
        if s == "straight":
            return np.full_like(t, R)
        if s == "tapered":
            return R * (b + (1 - b) * t)
        if s == "barrel":
            return R * (b + (1 - b) * np.sin(math.pi * np.clip(t * 0.9 + 0.1, 0, 1)) ** 0.6 * 1.0)
        return R * (b + (1 - b) * np.sin(0.5 * math.pi * t) ** 2)  # tulip: widening to the rim

    def _outer(self, p) -> list[tuple[float, float]]:
        H = p["height"]
        t = np.linspace(0.0, 1.0, 13)
        r = self._radius(p, t)
        c = (1 - p["bottom_frac"]) * p["radius"] * 0.3 if p["shape"] == "straight" else 0.002
        c = max(c, 0.0015)
        pts = [(0.0, 0.0), (float(r[0]) - c, 0.0)]
        z = t * H
        z[0] = c
        return pts + list(zip(r.tolist(), z.tolist(), strict=True))

    def _rmax(self, p) -> float:
        return float(max(q[0] for q in self._outer(p)))

    def _handle_dims(self, p) -> tuple[float, float, float, float, float]:
        """(loop half-height, tube radius, centre height, Y scale, attachment y)."""
        H, t = p["height"], p["handle_thickness"]
        sy, sz = {"round": (1.0, 1.0), "ear": (0.9, 1.15), "square": (0.9, 1.0)}[p["handle_shape"]]
        R = min(p["handle_size"] * sz, 0.5 * H - t - 0.008)
        zc = 0.52 * H
        tt = np.array([(zc - R) / H, zc / H, (zc + R) / H])
        yc = float(self._radius(p, tt).min()) - 0.5 * p["wall_thickness"]
        # at least 12 mm between the loop and the widest part of the body, for the fingers
        ry = max(R * sy / sz, self._rmax(p) - yc + 0.012 + t)
        return R, t, zc, ry, yc

    def _handle(self, p, cavity: m3d.Manifold) -> m3d.Manifold:
        R, t, zc, ry, yc = self._handle_dims(p)
        if p["handle_shape"] == "square":
            bars = [bevel_box((2 * t, ry + t, 2 * t), (0, yc + (ry + t) / 2, zc + R), t * 0.6),
                    bevel_box((2 * t, ry + t, 2 * t), (0, yc + (ry + t) / 2, zc - R), t * 0.6),
                    bevel_box((2 * t, 2 * t, 2 * R + 2 * t), (0, yc + ry, zc), t * 0.6)]
            loop = solid_union(bars)
        else:
            loop = torus(1.0, t / R, sections=24, tube_sections=8).rotate((90.0, 0.0, 90.0))
            loop = loop.scale((R, ry, R)).translate((0.0, yc, zc))
        keep = m3d.Manifold.cube((1.0, 1.0, 1.0), True).scale((0.2, 0.2, 0.2)).translate(
            (0.0, yc + 0.1 - 0.3 * ry, zc))
        return (loop ^ keep) - cavity

    def parts(self, p, detail):
        """The mug's solids: detailed, or the blocks of its placeholder."""
        H = p["height"]
        R, t, zc, ry, yc = self._handle_dims(p)
        if not detail:
            rm = self._rmax(p)
            # a torus scaled by ry/R across reaches ry * (1 + t/R); the square loop ry + t
            reach = ry + t if p["handle_shape"] == "square" else ry * (1 + t / R)
            return [cheap_cylinder(rm, 0.0, H, "ceramic"),
                    Part(box_between((-t, rm - 0.003, zc - R - t), (t, yc + reach, zc + R + t)),
                         "ceramic")]
        v = revolve_vessel(self._outer(p), p["wall_thickness"], p["base_thickness"])
        return [Part(v.shell, "ceramic"), Part(self._handle(p, v.cavity), "ceramic")]

    def extra_surfaces(self, p):
        """The mug's surfaces besides its bounding box's: bottom, interior."""
        o = self._outer(p)
        v = revolve_vessel(o, p["wall_thickness"], p["base_thickness"])
        return [round_bottom("bottom", o[1][0]), interior_floor("interior", v.floor_z, v.floor_r)]


# --------------------------------------------------------------------------- glassware
#: wine glass bowl shapes: (height of the widest point / bowl height, radius scale)
GLASS_SHAPES = {"balloon": (0.45, 1.0), "tulip": (0.4, 0.9), "flute": (0.75, 0.62),
                "coupe": (1.0, 1.15)}


@register
class Wineglass(PartsFactory):
    """A stemmed glass: a thin foot disc, a stem and a hollow bowl (balloon, tulip, flute or
    coupe) whose rim may narrow inward; one lathed shell."""

    name = "wineglass"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Wineglass, S.Cup})
    size_class = "small"
    slots = ["glass"]
    solid_bottom = True
    params = {
        "height": Param(0.14, 0.24, doc="total height (m)"),
        "bowl_radius": Param(0.035, 0.05, doc="outer radius of the bowl at its widest (m)"),
        "bowl_frac": Param(0.4, 0.6, doc="bowl height / total height (coupe: halved)"),
        "shape": Param(kind="choice", choices=tuple(GLASS_SHAPES), doc="bowl shape"),
        "rim_narrowing": Param(0.0, 0.25, doc="how much the rim narrows from the widest point"),
        "foot_radius": Param(0.028, 0.042, doc="foot disc radius (m)"),
        "stem_radius": Param(0.003, 0.005, doc="stem radius (m)"),
        "wall_thickness": Param(0.0015, 0.0025, doc="bowl wall thickness (m)"),
    }

    def _dims(self, p) -> tuple[float, float, float]:
        """(stem top z, widest bowl radius, foot thickness)."""
        H, s = p["height"], p["shape"]
        bowl_h = H * p["bowl_frac"] * (0.5 if s == "coupe" else 1.0)
        return H - bowl_h, p["bowl_radius"] * GLASS_SHAPES[s][1], 0.003

    def _outer(self, p) -> list[tuple[float, float]]:
        H, rf, rs = p["height"], p["foot_radius"], p["stem_radius"]
        z0, Rb, tf = self._dims(p)
        shape = p["shape"]
        tm, _ = GLASS_SHAPES[shape]
        narrow = p["rim_narrowing"] * (0.5 if shape == "flute" else 1.0)
        rim = 1.0 - narrow - (0.08 if shape in ("balloon", "tulip") else 0.0)
        t = np.linspace(0.0, 1.0, 17)
        u = np.minimum(t / tm, 1.0)
        if shape == "coupe":
            g = np.sin(0.5 * math.pi * t) ** 0.6
        else:
            rise = (np.sqrt(1.0 - (1.0 - u) ** 2) if shape == "balloon"
                    else np.sin(0.5 * math.pi * u) ** 0.9)
            g = np.where(t <= tm, rise,
                         1.0 - (1.0 - rim) * ((t - tm) / (1.0 - tm)).clip(0, 1) ** 1.5)
        r0 = 1.6 * rs
        rb = r0 + (Rb - r0) * g
        zb = z0 + (H - z0) * t
        foot = [(0.0, 0.0), (rf, 0.0), (rf, tf * 0.6), (rf - 0.004, tf), (2.5 * rs, tf + 0.004),
                (rs, tf + 0.012), (rs, z0 - 0.004)]
        return foot + list(zip(rb.tolist(), zb.tolist(), strict=True))

    def _vessel(self, p) -> Vessel:
        z0 = self._dims(p)[0]
        return revolve_vessel(self._outer(p), p["wall_thickness"], z0 + 0.006)

    def parts(self, p, detail):
        """The wineglass's solids: detailed, or the blocks of its placeholder."""
        if detail:
            return [Part(self._vessel(p).shell, "glass")]
        z0 = self._dims(p)[0]
        rmax = max(r for r, z in self._outer(p) if z >= z0 - 0.004)
        return [cheap_cylinder(p["foot_radius"], 0.0, z0, "glass"),
                cheap_cylinder(rmax, z0 - 0.004, p["height"], "glass")]

    def extra_surfaces(self, p):
        """The wineglass's surfaces besides its bounding box's: bottom."""
        return [round_bottom("bottom", p["foot_radius"])]


TUMBLER_STYLES = ("smooth", "faceted", "ribbed")


@register
class GlassTumbler(PartsFactory):
    """A drinking glass: straight or tapered, optionally bulging, smooth, faceted (12 sides) or
    ribbed near the base, with a thin wall and a thick (heavy) base."""

    name = "glass_tumbler"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup})
    size_class = "small"
    slots = ["glass"]
    solid_bottom = True
    params = {
        "radius": Param(0.03, 0.045, doc="outer radius at the rim (m)"),
        "height": Param(0.07, 0.16, doc="height (m)"),
        "bottom_frac": Param(0.75, 1.0, doc="base radius / rim radius"),
        "bulge": Param(0.0, 0.08, doc="outward bulge of the wall at mid-height / radius"),
        "wall_thickness": Param(0.0015, 0.003, doc="wall thickness (m)"),
        "base_thickness": Param(0.004, 0.018, doc="thickness of the solid base (m)"),
        "style": Param(kind="choice", choices=TUMBLER_STYLES, doc="surface style"),
    }

    def _sections(self, p) -> int:
        return 12 if p["style"] == "faceted" else SECTIONS

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H, b = p["radius"], p["height"], p["bottom_frac"]
        n = 24 if p["style"] == "ribbed" else 10
        t = np.linspace(0.0, 1.0, n + 1)
        r = R * (b + (1 - b) * t + p["bulge"] * np.sin(math.pi * t))
        if p["style"] == "ribbed":
            r = r + 0.0012 * (np.abs(np.sin(math.pi * t * n / 2)) * (t < 0.5))
        c = 0.0015
        z = t * H
        z[0] = c
        return [(0.0, 0.0), (float(r[0]) - c, 0.0)] + list(zip(r.tolist(), z.tolist(), strict=True))

    def _vessel(self, p) -> Vessel:
        return revolve_vessel(self._outer(p), p["wall_thickness"], p["base_thickness"],
                              self._sections(p))

    def parts(self, p, detail):
        """The glass tumbler's solids: detailed, or the blocks of its placeholder."""
        if detail:
            return [Part(self._vessel(p).shell, "glass")]
        rmax = max(r for r, _ in self._outer(p))
        return [cheap_cylinder(rmax, 0.0, p["height"], "glass")]

    def extra_surfaces(self, p):
        """The glass tumbler's surfaces besides its bounding box's: bottom, interior."""
        o, n = self._outer(p), self._sections(p)
        v = self._vessel(p)
        # polygons with the mesh's own vertex angles, just inside its n-gons
        return [round_bottom("bottom", o[1][0], n), interior_floor("interior", v.floor_z,
                                                                   v.floor_r, n)]
