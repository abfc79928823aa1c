"""Ceiling-mounted lights: flush domes, drum shades, LED panels, spot bars and chandeliers, and
pendants on a cord or rod; a flat canopy at the top is their `top` surface."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.lighting._parts import (
    CHEAP,
    FINE,
    LIGHT_SLOTS,
    Kit,
    build_groups,
    top_disc,
    top_rect,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.model.tags import Semantics as S


@register
class CeilingLight(PartsFactory):
    """A ceiling light: a flush opal dome on a round base, a semi-flush drum shade on a stem, a
    flat LED panel (round or square), a bar or plate of down-pointing spots, or a chandelier
    with curved arms carrying candle bulbs. A flat canopy / base forms the bounding box's top
    (the `top` surface, against the ceiling)."""

    name = "ceiling_light"
    tags = frozenset({S.Object, S.Lighting, S.CeilingLight, S.CeilingMounted})
    size_class = "medium"
    slots = LIGHT_SLOTS
    params = {
        "style": Param(kind="choice", choices=("dome", "drum", "panel", "spots", "chandelier"),
                       doc="fixture type"),
        "diameter": Param(0.25, 0.7, doc="overall diameter / length (m)"),
        "body_height": Param(0.06, 0.25, doc="dome / drum / column / spot can height (m)"),
        "drop": Param(0.05, 0.6, doc="stem or downrod length below the canopy (drum, spots, "
                                     "chandelier) (m)"),
        "n_lights": Param(3, 8, kind="int", doc="spots, or chandelier arms (rounded up to even)"),
        "canopy_radius": Param(0.04, 0.08, doc="ceiling canopy radius (drum, chandelier) (m)"),
        "shape": Param(kind="choice", choices=("round", "square"),
                       doc="panel outline; spots on a round plate or a straight bar"),
        "trim": Param(kind="bool", doc="metal trim band (dome) / metal body (panel, spots)"),
    }

    CANOPY_H = 0.02

    def _groups(self, p, k: Kit | None) -> tuple[list[list[Part]], float, Surface]:
        return getattr(self, f"_{p['style']}")(p, k)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The fixture of its style (placeholder: the boxes of its groups)."""
        return build_groups(self._groups(p, FINE if detail else CHEAP)[0], detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The canopy's or base's `top`, against the ceiling."""
        return [self._groups(p, None)[2]]

    # ---- styles: each returns (groups of parts, overall height, top surface); with k=None
    # ---- only the height and the top (no parts)
    def _dome(self, p, k: Kit | None):
        R = p["diameter"] / 2
        h = min(max(p["body_height"], 0.06), 0.4 * p["diameter"])  # a shallow flush dome
        Rd = R - 0.01
        rf = 0.3 * Rd
        us = np.linspace(0.0, 1.0, 10)
        prof = [(0.0, 0.0)] + [(rf + (Rd - rf) * math.sin(u * math.pi / 2),
                                h * (1 - math.cos(u * math.pi / 2))) for u in us] + \
            [(Rd, h + OVERLAP), (0.0, h + OVERLAP)]
        H = h + self.CANOPY_H
        if k is None:
            return [], H, top_disc(R, H)
        base = [Part(k.disc(R, h, self.CANOPY_H), "metal")]
        if p["trim"]:
            base.append(Part(k.lathe([(Rd - 0.003, h - 0.02), (R - 0.002, h - 0.02), (R - 0.002, h + OVERLAP),
                                    (Rd - 0.003, h + OVERLAP)], 48), "metal"))
        return [base, [Part(k.lathe(prof, 48), "emissive")]], H, top_disc(R, H)

    def _drum(self, p, k: Kit | None):
        R = p["diameter"] / 2
        bh = max(p["body_height"], 0.1)
        th, cr = 0.003, p["canopy_radius"]
        stem = max(p["drop"], 0.05)
        H = bh + stem + self.CANOPY_H
        if k is None:
            return [], H, top_disc(cr, H)
        shade = [Part(k.shell([(R, 0.0), (R, bh)], th), "shade"),
                 Part(k.disc(R - th + OVERLAP, 0.004, 0.004), "emissive")]
        zh = bh - 0.015
        hub = [Part(k.disc(0.03, zh, 0.015, n=24), "metal")]
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 2
            rim = ((R - th / 2) * math.cos(a), (R - th / 2) * math.sin(a), bh - 0.008)
            hub.append(Part(k.rod((0.0, 0.0, bh - 0.008), rim, 0.003, 8), "metal"))
        rb = max(0.012, min(0.035, (bh - 0.015 - 0.025 - 0.02) / 2.3))
        zs = zh - 0.025
        hub.append(Part(k.disc(0.015, zs, 0.025 + OVERLAP, n=16), "metal"))
        hub.append(Part(k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, zs + OVERLAP)),
                        "emissive"))
        top = [Part(k.disc(cr, H - self.CANOPY_H, self.CANOPY_H), "metal"),
               Part(k.rod((0.0, 0.0, bh - OVERLAP), (0.0, 0.0, H - self.CANOPY_H + OVERLAP), 0.008, 12),
                    "metal")]
        return [shade, hub, top], H, top_disc(cr, H)

    def _panel(self, p, k: Kit | None):
        R = p["diameter"] / 2
        pt = min(max(0.4 * p["body_height"], 0.025), 0.06)
        lens, inset = 0.003, 0.012
        body_slot = "metal" if p["trim"] else "plastic"
        if k is None:
            top = (top_disc(R, lens + pt) if p["shape"] == "round"
                   else top_rect(R - 0.001, R - 0.001, lens + pt))
            return [], lens + pt, top
        if p["shape"] == "round":
            body = k.disc(R, lens, pt)
            face = k.disc(R - inset, 0.0, lens + OVERLAP)
            top = top_disc(R, lens + pt)
        else:
            body = box_between((-R, -R, lens), (R, R, lens + pt))
            face = box_between((-R + inset, -R + inset, 0.0), (R - inset, R - inset, lens + OVERLAP))
            top = top_rect(R - 0.001, R - 0.001, lens + pt)
        return [[Part(body, body_slot), Part(face, "emissive")]], lens + pt, top

    def _spots(self, p, k: Kit | None):
        R = p["diameter"] / 2
        n = int(p["n_lights"])
        can_l = min(max(0.6 * p["body_height"], 0.06), 0.12)
        stem = min(max(0.4 * p["drop"], 0.02), 0.15)
        lens, rc = 0.003, 0.032
        z_plate = lens + can_l + stem
        H = z_plate + 0.025
        slot = "metal" if p["trim"] else "plastic"
        if k is None:
            top = (top_disc(min(0.12, 0.4 * R), H) if p["shape"] == "round"
                   else top_rect(0.034, R - 0.001, H))
            return [], H, top
        if p["shape"] == "round":  # a small plate, the spots splayed out on slanted stems
            rp = min(0.12, 0.4 * R)
            plate = k.disc(rp, z_plate, 0.025)
            ang = 2 * math.pi * np.arange(n) / n
            centres = np.c_[(R - rc) * np.cos(ang), (R - rc) * np.sin(ang)]
            roots = 0.6 * rp * np.c_[np.cos(ang), np.sin(ang)]
            top = top_disc(rp, H)
        else:  # a straight track bar
            plate = box_between((-0.035, -R, z_plate), (0.035, R, H))
            centres = np.c_[np.zeros(n), np.linspace(-R + 0.05, R - 0.05, n)]
            roots = centres
            top = top_rect(0.034, R - 0.001, H)
        groups = [[Part(plate, slot)]]
        for (x, y), (xr, yr) in zip(centres, roots, strict=True):
            groups.append([Part(k.disc(rc, lens, can_l, x, y, 24), slot),
                           Part(k.disc(rc - 0.006, 0.0, lens + OVERLAP, x, y, 24), "emissive"),
                           Part(k.rod((x, y, lens + can_l - 0.01), (xr, yr, z_plate + OVERLAP), 0.006, 8),
                                slot)])
        return groups, H, top

    def _chandelier(self, p, k: Kit | None):
        R = p["diameter"] / 2
        n = 2 * math.ceil(int(p["n_lights"]) / 2)
        ch = min(max(p["body_height"], 0.12), 0.3)
        cr, drop = p["canopy_radius"], max(p["drop"], 0.1)
        fin = 0.04
        rc = 0.035
        col = [(0.0, 0.0), (0.012, 0.0), (0.02, fin * 0.6), (0.015, fin)]
        ts = np.linspace(0.0, 1.0, 9)
        col += [(rc * (0.55 + 0.45 * math.sin(math.pi * (0.15 + 0.85 * t))), fin + t * ch) for t in ts[1:]]
        col += [(0.012, fin + ch + 0.01), (0.0, fin + ch + 0.01)]
        z_col1 = fin + ch
        H = z_col1 + drop + self.CANOPY_H
        if k is None:
            return [], H, top_disc(cr, H)
        groups = [[Part(k.lathe(col, 24), "metal"),
                   Part(k.rod((0.0, 0.0, z_col1), (0.0, 0.0, H - self.CANOPY_H + OVERLAP), 0.007, 12),
                        "metal"),
                   Part(k.disc(cr, H - self.CANOPY_H, self.CANOPY_H), "metal")]]
        za = fin + 0.3 * ch
        Ra = R - 0.028
        # a quadratic Bezier arm in its (radial, z) plane
        P0, P1, P2 = np.array([0.6 * rc, za]), np.array([0.7 * Ra, za - 0.07]), np.array([Ra, za + 0.06])
        us = np.linspace(0.0, 1.0, 6)
        curve = [(1 - u) ** 2 * P0 + 2 * u * (1 - u) * P1 + u ** 2 * P2 for u in us]
        for i in range(n):
            ang = 2 * math.pi * i / n
            c, s = math.cos(ang), math.sin(ang)
            pts = np.array([(q[0] * c, q[0] * s, q[1]) for q in curve])
            if k.detail:
                arm = [Part(k.rod(q0, q1, 0.006, 8), "metal") for q0, q1 in zip(pts, pts[1:], strict=False)]
            else:  # the curved arm's box (the rods' boxes stay within 6 mm of its points)
                arm = [Part(box_between(pts.min(axis=0) - 0.006, pts.max(axis=0) + 0.006), "metal")]
            x, y, z = pts[-1]
            arm += [Part(k.sphere(0.006, 8).translate((x, y, z)), "metal"),
                    Part(k.disc(0.028, z - 0.004, 0.01, x, y, 24), "metal"),
                    Part(k.disc(0.011, z + 0.006 - OVERLAP, 0.07, x, y, 16), "wax"),
                    Part(k.flame(z + 0.076 - OVERLAP, 0.012, x, y), "emissive")]
            groups.append(arm)
        return groups, H, top_disc(cr, H)


PENDANT_SHADES = ("dome", "cone", "drum", "globe", "cage")


@register
class PendantLight(PartsFactory):
    """A pendant: ceiling canopy (its `top`), a cord or rod, a cap and a dome, cone, drum, opal
    globe or wire cage shade with a bulb inside."""

    name = "pendant_light"
    tags = frozenset({S.Object, S.Lighting, S.PendantLight, S.CeilingMounted})
    size_class = "medium"
    slots = LIGHT_SLOTS
    params = {
        "shade": Param(kind="choice", choices=PENDANT_SHADES, doc="shade type"),
        "shade_diameter": Param(0.15, 0.5, doc="shade diameter at its widest (m)"),
        "shade_height": Param(0.12, 0.35, doc="shade height (m)"),
        "drop": Param(0.3, 1.2, doc="cord length from the canopy to the shade (m)"),
        "canopy_radius": Param(0.04, 0.07, doc="ceiling canopy radius (m)"),
        "bulb_radius": Param(0.025, 0.05, doc="bulb radius (m; shrunk to fit the shade)"),
        "stem": Param(kind="choice", choices=("cord", "rod"), doc="thin cord or rigid rod"),
    }

    CANOPY_H = 0.025
    CAP_R, CAP_H = 0.025, 0.04

    def _outer(self, p) -> list[tuple[float, float]]:
        """The shade's outer profile (radius, z), rim (z = 0) to top (z = shade height)."""
        R, sh, kind = p["shade_diameter"] / 2, p["shade_height"], p["shade"]
        rt = self.CAP_R - 0.005
        if kind == "cone":
            return [(R, 0.0), (rt, sh)]
        if kind == "drum":
            return [(R, 0.0), (R, sh)]
        us = np.linspace(0.0, 1.0, 12)  # dome: a quarter ellipse
        return [(rt + (R - rt) * math.cos(u * math.pi / 2), sh * math.sin(u * math.pi / 2)) for u in us]

    def _bulb_r(self, p) -> float:
        R, sh = p["shade_diameter"] / 2, p["shade_height"]
        return min(p["bulb_radius"], 0.4 * R, (sh - 0.03) / 2.8)

    def _shade_parts(self, p, k: Kit = CHEAP) -> list[Part]:
        R, sh, kind = p["shade_diameter"] / 2, p["shade_height"], p["shade"]
        th = 0.003
        if kind in ("dome", "cone"):
            return [Part(k.shell(self._outer(p), th), "shade")]
        if kind == "drum":
            return [Part(k.shell([(R, 0.0), (R, sh)], th), "shade"),
                    Part(k.lathe([(self.CAP_R - 0.005, sh - th), (R - OVERLAP, sh - th), (R - OVERLAP, sh),
                                (self.CAP_R - 0.005, sh)], 48), "shade")]
        if kind == "globe":
            # an opal sphere with a flat foot (its lowest point) and a flat neck for the cap
            rg = min(R, sh / 2)
            us = np.linspace(-math.pi / 2 + 0.25, math.pi / 2 - 0.2, 14)
            arc = [(rg * math.cos(u), rg * (1 + math.sin(u))) for u in us]
            prof = [(0.0, 0.0), (arc[0][0], 0.0)] + arc[1:] + [(0.0, arc[-1][1])]
            return [Part(k.lathe(prof, 32), "emissive")]
        # cage: two rings and vertical bars, joined to the cap by spokes
        rw = 0.003
        rr = R - rw
        out = [Part(m3d.Manifold.revolve(m3d.CrossSection.circle(rw, 8).translate((rr, 0.0)), 32)
                    .translate((0.0, 0.0, rw)), "metal"),
               Part(m3d.Manifold.revolve(m3d.CrossSection.circle(rw, 8).translate((rr, 0.0)), 32)
                    .translate((0.0, 0.0, sh - rw)), "metal")]
        nb = 8
        for i in range(nb):
            a = 2 * math.pi * (i + 0.5) / nb
            x, y = rr * math.cos(a), rr * math.sin(a)
            out.append(Part(k.rod((x, y, rw), (x, y, sh - rw), rw, 6), "metal"))
        for i in range(4):
            a = 2 * math.pi * i / 4 + math.pi / 4
            out.append(Part(k.rod((0.0, 0.0, sh - rw), (rr * math.cos(a), rr * math.sin(a), sh - rw), rw, 6),
                            "metal"))
        return out

    def _heights(self, p) -> tuple[float, float]:
        """(z of the shade's top, overall height)."""
        sh = p["shade_height"]
        if p["shade"] == "globe":
            sh = self._shade_parts(p)[0].solid.bounding_box()[5]
        return sh, sh + self.CAP_H + p["drop"] + self.CANOPY_H

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Shade, cap and bulb, the cord or rod, and the ceiling canopy."""
        k = FINE if detail else CHEAP
        zs, H = self._heights(p)
        cr = p["canopy_radius"]
        z_cap = zs - OVERLAP
        fitting = [Part(k.disc(self.CAP_R, z_cap, self.CAP_H, n=24), "metal")]
        if p["shade"] != "globe":
            rb = self._bulb_r(p)
            z_sock = z_cap - 0.03
            fitting.append(Part(k.disc(0.014, z_sock, 0.03 + OVERLAP, n=16), "metal"))
            bulb = k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, z_sock + OVERLAP))
            fitting.append(Part(bulb, "emissive"))
        r_stem = 0.003 if p["stem"] == "cord" else 0.007
        top = [Part(k.rod((0.0, 0.0, z_cap + self.CAP_H - OVERLAP), (0.0, 0.0, H - self.CANOPY_H + OVERLAP),
                        r_stem, 8), "metal" if p["stem"] == "rod" else "plastic"),
               Part(k.disc(cr, H - self.CANOPY_H, self.CANOPY_H), "metal")]
        return build_groups([self._shade_parts(p, k) + fitting, top[:1], top[1:]], detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The canopy's `top`, against the ceiling."""
        return [top_disc(p["canopy_radius"], self._heights(p)[1])]
