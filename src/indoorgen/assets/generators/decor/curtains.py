"""Curtains: pleated fabric panels on a rod with finials, hung from rings or a rod pocket; the wall
board behind the rod brackets is the object's back."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.outlines import ccw
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, box_between, lathe, rod, torus
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def _wave_band(y0: float, y1: float, x_mid: float, amp: float, pitch: float,
               thick: float) -> m3d.CrossSection:
    """The plan (x, y) of a pleated curtain panel: a sine wave of amplitude `amp` and wavelength
    `pitch` across y0..y1 about x = x_mid, thickened by `thick` along its normals (where a fold
    is tighter than the thickness, the fill rule resolves the overlap)."""
    n = max(16, int(round((y1 - y0) / pitch * 16)))
    y = np.linspace(y0, y1, n + 1)
    k = 2 * math.pi / pitch
    x = x_mid + amp * np.sin(k * (y - y0))
    dx = amp * k * np.cos(k * (y - y0))
    nrm = np.c_[np.ones_like(dx), -dx] / np.sqrt(1 + dx ** 2)[:, None]
    c = np.c_[x, y]
    pts = np.vstack([c + 0.5 * thick * nrm, (c - 0.5 * thick * nrm)[::-1]])
    return m3d.CrossSection([ccw(pts)], m3d.FillRule.NonZero)


@register
class Curtain(PartsFactory):
    """A curtain on a rod: one or two pleated fabric panels (a sine-folded solid sheet), hung
    from rings or gathered on the rod (rod pocket), drawn closed or open to the sides. The rod
    with its finials sits on brackets fixed to a wall board, whose back is the object's back."""

    name = "curtain"
    tags = frozenset({S.Object, S.Decor, S.Textile, S.Curtain, S.WallMounted})
    size_class = "medium"
    slots = ["fabric", "metal", "wood"]
    params = {
        "width": Param(1.0, 3.0, doc="span between the end brackets (m)"),
        "drop": Param(1.0, 2.6, doc="height from the hem to the rod (m: 1.0 for a sill-length "
                      "curtain at a small window, 2.6 for a floor-length one)"),
        "n_panels": Param(1, 2, kind="int", doc="fabric panels (2 = a pair meeting in the middle)"),
        "coverage": Param(0.35, 1.0, doc="fraction of the width covered (< 1: drawn open)"),
        "fold_depth": Param(0.03, 0.09, doc="front-to-back depth of the folds (m)"),
        "fold_spacing": Param(0.1, 0.18, doc="fold wavelength when closed (m)"),
        "heading": Param(kind="choice", choices=("rings", "rod_pocket"), doc="how the fabric hangs"),
        "rod_radius": Param(0.01, 0.018, doc="rod radius (m)"),
        "finial": Param(kind="choice", choices=("ball", "disc", "cone"), doc="rod end finials"),
        "standoff": Param(0.07, 0.14, doc="rod axis distance from the wall (m)"),
    }
    THICK = 0.003

    def _geom(self, p) -> dict[str, float]:
        W, rr = p["width"], p["rod_radius"]
        pitch = p["fold_spacing"] * (0.5 + 0.5 * p["coverage"])
        amp = min(p["fold_depth"] / 2, 0.45 * pitch)
        xw = 0.0  # wall plane (the board's back)
        xr = max(p["standoff"], 0.018 + amp + self.THICK + 0.02, 0.018 + 0.025 + rr)
        zr = p["drop"] + (0.03 if p["heading"] == "rings" else 0.0)
        fr = 2.2 * rr if p["finial"] != "disc" else 2.0 * rr
        ext = 0.06
        tip = W / 2 + ext + {"ball": 2 * fr - 0.006, "disc": 0.012, "cone": 3.2 * fr - 0.004}[p["finial"]]
        ring_R, ring_m = rr + 0.004 + 0.003, 0.003
        # rings hang on the rod: their inner top edge 1 mm into the rod's top
        ring_zc = zr + rr - SMALL_OVERLAP - (ring_R - ring_m)
        return dict(W=W, rr=rr, pitch=pitch, amp=amp, xw=xw, xr=xr, zr=zr, fr=fr, ext=ext,
                    tip=tip, ring_R=ring_R, ring_m=ring_m, ring_zc=ring_zc)

    def _panels(self, p, g) -> list[tuple[float, float]]:
        W, cov = g["W"], p["coverage"]
        if int(p["n_panels"]) == 2:
            wp = cov * W / 2
            return [(-W / 2, -W / 2 + wp), (W / 2 - wp, W / 2)]
        return [(-W / 2, -W / 2 + cov * W)]

    def _fabric_top(self, p, g) -> float:
        if p["heading"] == "rings":
            return g["ring_zc"] - g["ring_R"] + 0.002
        return g["zr"] + g["rr"] + 0.03

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Wall board, rod with finials and brackets, pleated panels and rings."""
        g = self._geom(p)
        W, rr, xr, zr, xw, fr, ext = g["W"], g["rr"], g["xr"], g["zr"], g["xw"], g["fr"], g["ext"]
        amp, pitch = g["amp"], g["pitch"]
        zb0, zb1 = zr - 0.045, zr + 0.05
        yb = W / 2 + 0.04
        out = [Part(box_between((xw, -yb, zb0), (xw + 0.018, yb, zb1)), "wood")]
        zf = self._fabric_top(p, g)
        y_end = W / 2 + ext
        if not detail:
            out.append(Part(box_between((xw + 0.018 - SMALL_OVERLAP, -g["tip"], zr - fr),
                                        (xr + fr, g["tip"], zr + fr)), "metal"))
            for y0, y1 in self._panels(p, g):
                out.append(Part(box_between((xr - amp - self.THICK / 2, y0 - 0.003, 0.0),
                                            (xr + amp + self.THICK / 2, y1 + 0.003, zf + SMALL_OVERLAP)),
                                "fabric"))
            if p["heading"] == "rings":
                zc = g["ring_zc"]
                R = g["ring_R"] + g["ring_m"]
                out.append(Part(box_between((xr - R, -W / 2, zc - R), (xr + R, W / 2, zc + R)), "metal"))
            return out
        out.append(Part(rod((xr, -y_end, zr), (xr, y_end, zr), rr, 24), "metal"))
        for s in (-1, 1):
            out.append(Part(self._finial(p, g, s), "metal"))
            yb_ = s * (W / 2 + 0.02)
            out.append(Part(box_between((xw + 0.018 - SMALL_OVERLAP, yb_ - 0.008, zr - 0.012),
                                        (xr, yb_ + 0.008, zr + 0.012)), "metal"))
        for y0, y1 in self._panels(p, g):
            band = _wave_band(y0, y1, xr, amp, pitch, self.THICK)
            out.append(Part(m3d.Manifold.extrude(band, zf), "fabric"))
            if p["heading"] == "rings":
                zc = g["ring_zc"]
                n = int(math.floor((y1 - y0) / pitch + 1e-9))
                for k in range(n + 1):
                    yk = min(y0 + k * pitch, y1 - 0.004)
                    ring = torus(g["ring_R"], g["ring_m"], sections=12, tube_sections=6)
                    out.append(Part(ring.rotate((90.0, 0.0, 0.0)).translate((xr, yk, zc)), "metal"))
        return out

    @staticmethod
    def _finial(p, g, s: int) -> m3d.Manifold:
        xr, zr, fr, y_end = g["xr"], g["zr"], g["fr"], g["W"] / 2 + g["ext"]
        y0 = s * (y_end - 0.004)
        if p["finial"] == "ball":
            ball = m3d.Manifold.sphere(fr, 24).translate((xr, s * (y_end + fr - 0.006), zr))
            return ball
        if p["finial"] == "disc":
            return rod((xr, y0, zr), (xr, s * (y_end + 0.012), zr), fr, 24)
        prof = [(0.0, 0.0), (fr, 0.0), (0.3 * fr, 3.0 * fr), (0.0, 3.2 * fr)]
        return lathe(prof, 24).rotate((-90.0 * s, 0.0, 0.0)).translate((xr, y0, zr))

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The wall board's back against the wall."""
        g = self._geom(p)
        zr, yb = g["zr"], g["W"] / 2 + 0.04
        zb0, zb1 = zr - 0.045, zr + 0.05
        return [Surface.rect("back", Subpart.Back, (g["xw"], 0, (zb0 + zb1) / 2), (-1, 0, 0),
                             (0, 1, 0), yb - 0.002, (zb1 - zb0) / 2 - 0.002)]
