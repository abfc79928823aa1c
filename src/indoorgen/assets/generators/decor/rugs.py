"""Rugs: a thin rectangular, round or oval slab with a raised binding, a bath mat, and round or
oval rugs with braid grooves and a bound or fringed edge. Their whole footprint is the
`bottom`."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.decor._parts import cross_section
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, circle_polygon, cylinder, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Rug(PartsFactory):
    """A thin rug slab (rectangle with rounded corners, round or oval) with a slightly raised
    binding around its edge."""

    name = "rug"
    tags = frozenset({S.Object, S.Decor, S.FloorCovering, S.Rug})
    size_class = "large"
    slots = ["rug", "binding"]
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=("rect", "round", "oval"), doc="outline"),
        "length": Param(1.2, 3.0, doc="Y extent (m); a round rug uses it as its diameter"),
        "width": Param(0.8, 2.0, doc="X extent (m); capped at the length"),
        "thickness": Param(0.005, 0.01, doc="pile thickness (m)"),
        "corner_radius": Param(0.0, 0.08, doc="corner rounding of a rectangular rug (m)"),
        "binding_width": Param(0.0, 0.04, doc="width of the raised edge binding (0 = none) (m)"),
    }

    def outline(self, p: dict[str, Any]) -> m3d.CrossSection:
        """The rug's plan as a cross-section (rounded rectangle, disc or ellipse)."""
        L = p["length"]
        Wd = min(p["width"], L)
        if p["shape"] == "round":
            return m3d.CrossSection.circle(L / 2, 64)
        if p["shape"] == "oval":
            return m3d.CrossSection.circle(0.5, 64).scale((Wd, L))
        r = min(p["corner_radius"], 0.45 * Wd)
        if r < 1e-3:
            return m3d.CrossSection.square((Wd, L), True)
        return m3d.CrossSection.square((Wd - 2 * r, L - 2 * r), True).offset(
            r, m3d.JoinType.Round, 2.0, 32)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The pile slab and, if wide enough, the raised binding round its edge."""
        cs = self.outline(p)
        th = p["thickness"]
        out = [Part(m3d.Manifold.extrude(cs, th), "rug")]
        bw = p["binding_width"]
        if detail and bw > 0.005:
            ring = cs - cs.offset(-bw, m3d.JoinType.Round, 2.0, 32)
            out.append(Part(m3d.Manifold.extrude(ring, 0.002).translate((0, 0, th - OVERLAP / 2)),
                            "binding"))
        elif bw > 0.005:  # placeholder: keep the full height with a thin top sheet
            out.append(Part(m3d.Manifold.extrude(cs, 0.002).translate((0, 0, th - OVERLAP / 2)),
                            "binding"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The whole footprint as the `bottom`."""
        polys = self.outline(p).to_polygons()
        poly = sg.Polygon(np.asarray(polys[0], float)).buffer(-0.0005, join_style="mitre")
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


@register
class BathMat(Rug):
    """A bath mat: a small, thick, soft rectangle with rounded corners or an oval before a bath,
    shower or basin (60-90 x 40-60 cm, the common sizes). Not a `Rug`: it lies alone, under no group."""

    name = "bath_mat"
    tags = frozenset({S.Object, S.Decor, S.FloorCovering, S.Textile, S.BathMat})
    size_class = "medium"
    params = {
        "shape": Param(kind="choice", choices=("rect", "oval"), doc="outline"),
        "length": Param(0.6, 0.9, doc="Y extent (m)"),
        "width": Param(0.4, 0.6, doc="X extent (m)"),
        "thickness": Param(0.008, 0.015, doc="pile thickness (m)"),
        "corner_radius": Param(0.02, 0.08, doc="corner rounding (m)"),
        "binding_width": Param(0.0, 0.02, doc="width of the raised edge binding (0 = none) (m)"),
    }
    material_choices = {"rug": {"knit": 2.0, "plain_weave": 1.5, "berber_carpet": 1.0,
                                "carpet": 1.0},
                        "binding": {"plain_weave": 1.0, "linen": 1.0}}


@register
class RoundRug(PartsFactory):
    """A round or oval rug: a thin lathed pile, optionally braided (concentric grooves), with a
    plain edge, a raised bound edge or a fringe of tassels all round."""

    name = "rug_round"
    tags = frozenset({S.Object, S.Decor, S.FloorCovering, S.Rug})
    size_class = "large"
    slots = ["carpet", "fabric"]
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=("round", "oval"), doc="outline"),
        "diameter": Param(0.8, 2.4, doc="Y extent of the pile (m)"),
        "aspect": Param(0.55, 0.85, doc="oval: X extent / Y extent"),
        "thickness": Param(0.006, 0.015, doc="pile thickness (m)"),
        "edge": Param(kind="choice", choices=("plain", "bound", "fringe"), doc="edge finish"),
        "binding_width": Param(0.015, 0.045, doc="width of a bound edge's band (m)"),
        "fringe_length": Param(0.03, 0.08, doc="length of the fringe's tassels (m)"),
        "n_grooves": Param(0, 6, kind="int", doc="concentric braid grooves on top (0 = plain pile)"),
    }

    def _sx(self, p) -> float:
        return p["aspect"] if p["shape"] == "oval" else 1.0

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Lathed pile with braid grooves, and a bound edge or a tassel fringe."""
        R, t, sx = p["diameter"] / 2, p["thickness"], self._sx(p)
        bound, fringe = p["edge"] == "bound", p["edge"] == "fringe"
        top = t + (0.002 if bound else 0.0)
        r_out = R + (p["fringe_length"] if fringe else 0.0)
        if not detail:
            return [Part(cylinder(r_out, top, (0, 0, 0), 16, circumscribed=True).scale((sx, 1, 1)),
                         "carpet")]
        prof = [(0.0, 0.0), (R, 0.0), (R, t - 0.002), (R - 0.002, t)]
        n = int(p["n_grooves"])
        gw, gd = 0.012, 0.35 * t
        r_end = R - (p["binding_width"] if bound else 0.0) - 0.02
        for k in range(n, 0, -1):  # grooves from the outside in
            rk = r_end * k / (n + 1)
            prof += [(rk + gw / 2, t), (rk, t - gd), (rk - gw / 2, t)]
        prof.append((0.0, t))
        out = [Part(lathe(prof, 96).scale((sx, 1, 1)), "carpet")]
        if bound:
            bw = p["binding_width"]
            ring = [(R - 0.0015, 0.0), (R, 0.0), (R, top), (R - bw, top), (R - bw, t - 0.0005),
                    (R - 0.0015, t - 0.0005)]
            out.append(Part(lathe(ring, 96).scale((sx, 1, 1)), "fabric"))
        if fringe:
            out.append(Part(self._fringe(R, p["fringe_length"]).scale((sx, 1, 1)), "fabric"))
        return out

    @staticmethod
    def _fringe(R: float, length: float) -> m3d.Manifold:
        """A gear-shaped slab: tassels 4 mm wide every 12 mm, from 5 mm inside the pile's edge
        out to R + length, lifted 1 mm off the floor."""
        n = max(24, int(2 * math.pi * R / 0.012) // 4 * 4)
        half = 0.5 * 0.004 / R
        a = np.arange(n) * 2 * math.pi / n
        r_in, r_out = R - 0.005, R + length
        ang = np.stack([a - half, a - half, a + half, a + half], axis=1).ravel()
        rad = np.tile([r_in, r_out, r_out, r_in], n)
        gear = cross_section(np.c_[rad * np.cos(ang), rad * np.sin(ang)])
        return m3d.Manifold.extrude(gear, 0.003).translate((0.0, 0.0, 0.001))

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The pile's round or oval footprint as the `bottom`."""
        R, sx = p["diameter"] / 2 - 0.0005, self._sx(p)
        poly = circle_polygon(R, 96)
        poly = sg.Polygon(np.asarray(poly.exterior.coords)[:-1] * np.array([sx, 1.0]))
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]
