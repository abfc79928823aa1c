"""Decor: rugs, framed wall art and vases."""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import frame
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box, box_between, circle_polygon, lathe
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

    def outline(self, p) -> m3d.CrossSection:
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

    def parts(self, p, detail):
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

    def extra_surfaces(self, p):
        polys = self.outline(p).to_polygons()
        poly = sg.Polygon(np.asarray(polys[0], float)).buffer(-0.0005, join_style="mitre")
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


@register
class WallArt(PartsFactory):
    """A framed picture (frame, optional mat, recessed picture on a backing board) or a
    gallery-wrapped canvas. Its back (-X) goes against the wall; the picture faces +X."""

    name = "wall_art"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.WallArt})
    size_class = "medium"
    slots = ["frame", "canvas", "mat", "backing"]
    solid_bottom = True
    params = {
        "width": Param(0.3, 1.5, doc="Y extent (m)"),
        "height": Param(0.3, 1.2, doc="Z extent (m)"),
        "style": Param(kind="choice", choices=("framed", "canvas"), doc="framed print or canvas"),
        "frame_width": Param(0.015, 0.08, doc="frame member width (m)"),
        "depth": Param(0.02, 0.05, doc="X extent: frame (or canvas stretcher) depth (m)"),
        "mat_width": Param(0.0, 0.08, doc="passe-partout width inside the frame (0 = none) (m)"),
        "recess": Param(0.004, 0.015, doc="how far the picture sits behind the frame's front (m)"),
    }

    def parts(self, p, detail):
        W, H, D = p["width"], p["height"], p["depth"]
        if p["style"] == "canvas":
            return [Part(box((D, W, H), (0, 0, H / 2)), "canvas")]
        fw = min(p["frame_width"], 0.2 * min(W, H))
        bk = 0.004
        out = [Part(box_between((-D / 2, -W / 2, 0.0), (-D / 2 + bk, W / 2, H)), "backing")]
        if not detail:
            out.append(Part(box_between((-D / 2 + bk - OVERLAP, -W / 2, 0.0), (D / 2, W / 2, H)), "frame"))
            return out
        out.append(Part(frame(W, H, fw, D - bk + OVERLAP, (bk / 2 - OVERLAP / 2, 0, H / 2)), "frame"))
        xf = D / 2 - p["recess"]  # picture front
        mw = min(p["mat_width"], 0.25 * min(W, H) - fw)
        iw, ih = W - 2 * fw + 2 * OVERLAP, H - 2 * fw + 2 * OVERLAP
        if mw > 0.005:
            out.append(Part(frame(iw, ih, mw + OVERLAP, xf + 0.001 - (-D / 2 + bk - OVERLAP),
                                  ((xf + 0.001 + (-D / 2 + bk - OVERLAP)) / 2, 0, H / 2)), "mat"))
            iw, ih = iw - 2 * mw, ih - 2 * mw
        out.append(Part(box_between((-D / 2 + bk - OVERLAP, -iw / 2, H / 2 - ih / 2),
                                    (xf, iw / 2, H / 2 + ih / 2)), "canvas"))
        return out


VASE_SHAPES = ("bulb", "cylinder", "bottle", "cone", "amphora")


def vase_radius(p, t: float) -> float:
    """Outer radius of the vase at fraction t of its height (0 = base, 1 = rim)."""
    R, foot, neck, belly = p["max_radius"], p["foot_frac"], p["neck_frac"], p["belly_frac"]
    shape = p["shape"]
    smooth = lambda a, b, u: a + (b - a) * (0.5 - 0.5 * math.cos(math.pi * min(max(u, 0.0), 1.0)))
    if shape == "cylinder":
        r = R * (foot + (1 - foot) * min(t / 0.05, 1.0)) if t < 0.05 else R
    elif shape == "cone":
        r = R * (foot + (1 - foot) * t)
    elif shape == "bottle":
        r = smooth(R * foot, R, t / 0.15) if t < 0.55 else smooth(R, R * neck * 0.6, (t - 0.55) / 0.2)
    elif shape == "amphora":
        r = (smooth(R * foot, R, t / belly) if t < belly
             else smooth(R, R * neck, (t - belly) / (0.85 - belly)) if t < 0.85
             else smooth(R * neck, R * (neck + 0.15), (t - 0.85) / 0.15))
    else:  # bulb
        r = smooth(R * foot, R, t / belly) if t < belly else smooth(R, R * neck, (t - belly) / (1 - belly))
    if p["lip"] and t > 0.94:
        r += 0.006 * (t - 0.94) / 0.06
    return max(r, p["wall_thickness"] + 0.006)


@register
class Vase(PartsFactory):
    """A lathed vase with a hollow interior: bulb, cylinder, bottle, cone or amphora profile."""

    name = "vase"
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Vase})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "height": Param(0.15, 0.5, doc="Z extent (m)"),
        "max_radius": Param(0.05, 0.15, doc="widest outer radius (m)"),
        "shape": Param(kind="choice", choices=VASE_SHAPES, doc="profile family"),
        "foot_frac": Param(0.5, 0.9, doc="base radius / max radius"),
        "neck_frac": Param(0.3, 0.9, doc="neck radius / max radius"),
        "belly_frac": Param(0.25, 0.6, doc="height of the widest point / height"),
        "wall_thickness": Param(0.003, 0.008, doc="wall thickness (m)"),
        "base_thickness": Param(0.005, 0.015, doc="floor thickness (m)"),
        "lip": Param(kind="bool", doc="flare the rim outwards"),
    }

    N_FINE = 24

    def parts(self, p, detail):
        H, w, b = p["height"], p["wall_thickness"], p["base_thickness"]
        ts = np.linspace(0.0, 1.0, self.N_FINE)
        rs = np.array([vase_radius(p, t) for t in ts])
        if detail:
            outer = [(0.0, 0.0)] + [(r, t * H) for r, t in zip(rs, ts)]
            zi = np.linspace(b, H, self.N_FINE)
            inner = [(vase_radius(p, z / H) - w, z) for z in zi[::-1]]
            return [Part(lathe(outer + inner + [(0.0, b)], 48), "ceramic")]
        # placeholder: a solid envelope over 8 levels, each radius the max nearby
        idx = np.linspace(0, self.N_FINE - 1, 8).round().astype(int)
        env = []
        for j, i in enumerate(idx):
            lo = idx[max(j - 1, 0)]
            hi = idx[min(j + 1, len(idx) - 1)]
            env.append((float(rs[lo:hi + 1].max()), float(ts[i] * H)))
        return [Part(lathe([(0.0, 0.0)] + env + [(0.0, H)], 16, circumscribed=True), "ceramic")]

    def extra_surfaces(self, p):
        r0 = vase_radius(p, 0.0)
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r0 * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]
