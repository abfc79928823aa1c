"""More lighting: ceiling lights, pendants, desk lamps, wall sconces and table lamps.

Light-emitting pieces (bulbs, opal diffusers, LED faces) use the "emissive" slot, which the
exporters turn into lights. Ceiling-mounted fixtures have a flat canopy at the top of their
bounding box (their `top` surface, which attaches to the ceiling); wall sconces have a flat
wall plate at the back (their `back`). Placeholders are the axis-aligned boxes of groups of
detailed pieces, so they enclose them and share their bounding box exactly.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DoorJoint
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    rod,
)
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

LIGHT_SLOTS = ["metal", "shade", "glass", "emissive", "wax", "ceramic", "plastic"]


# -------------------------------------------------------------------------------- helpers
def _aabb(parts: Sequence[Part]) -> Part:
    """One box enclosing a group of parts (slot and link of the first)."""
    bbs = np.array([q.solid.bounding_box() for q in parts], float)
    return Part(box_between(bbs[:, :3].min(axis=0), bbs[:, 3:].max(axis=0)), parts[0].slot,
                parts[0].link)


def _build(groups: Sequence[Sequence[Part]], detail: bool) -> list[Part]:
    """The detailed parts, or (placeholder) one enclosing box per group."""
    if detail:
        return [q for g in groups for q in g]
    return [_aabb(g) for g in groups if g]


def _shell(outer: Sequence[tuple[float, float]], thickness: float, sections: int = 48) -> m3d.Manifold:
    """A lathed shell open at both ends: the outer profile (radius, z) bottom to top, its wall
    `thickness` thick inwards."""
    inner = [(max(r - thickness, 0.001), z) for r, z in reversed(outer)]
    return lathe(list(outer) + inner, sections)


def _bulb(z0: float, r: float, x: float = 0.0, y: float = 0.0, sections: int = 24) -> m3d.Manifold:
    """A pear-shaped bulb standing on z0 (its neck down), `r` its widest radius."""
    prof = [(0.0, 0.0), (0.45 * r, 0.0), (0.5 * r, 0.35 * r), (0.85 * r, 0.8 * r), (r, 1.35 * r),
            (0.92 * r, 1.8 * r), (0.6 * r, 2.15 * r), (0.0, 2.3 * r)]
    return lathe(prof, sections).translate((x, y, z0))


def _flame(z0: float, r: float, x: float = 0.0, y: float = 0.0, sections: int = 16) -> m3d.Manifold:
    """A candle-flame bulb standing on z0, `r` its widest radius."""
    prof = [(0.0, 0.0), (0.55 * r, 0.0), (r, 0.9 * r), (0.8 * r, 2.0 * r), (0.3 * r, 3.0 * r),
            (0.0, 3.4 * r)]
    return lathe(prof, sections).translate((x, y, z0))


def _top_disc(r: float, z: float) -> Surface:
    """The ceiling-facing `top` of a round canopy of radius r whose top face is at z."""
    return support_polygon("top", (0, 0, z), circle_polygon(0.995 * r, 48), subpart=Subpart.Top)


def _top_rect(hx: float, hy: float, z: float) -> Surface:
    return support_polygon("top", (0, 0, z), sg.box(-hx, -hy, hx, hy), subpart=Subpart.Top)


@dataclass(frozen=True)
class _Kit:
    """Part builders at a level of detail: the real round pieces or, for placeholders (which
    only need each group's bounding box), their exact axis-aligned boxes (`boxes`) or coarse
    8-section versions with the same bounding box (lathes keep vertices on the axes; for parts
    that are then rotated about Y)."""

    detail: bool
    boxes: bool = True

    def n(self, sections: int) -> int:
        return sections if self.detail else 8

    def _cheap_box(self, r: float, z0: float, z1: float, x: float = 0.0, y: float = 0.0):
        return box_between((x - r, y - r, z0), (x + r, y + r, z1))

    def lathe(self, profile, sections: int = 48) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return lathe(profile, self.n(sections))
        pts = np.asarray(profile, float)
        return self._cheap_box(pts[:, 0].max(), pts[:, 1].min(), pts[:, 1].max())

    def cylinder(self, radius: float, height: float, center, sections: int = 32, **kw) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return cylinder(radius, height, center, self.n(sections), **kw)
        r = max(radius, kw.get("radius_top") or 0.0)
        x, y, z = (float(c) for c in center)
        return self._cheap_box(r, z, z + height, x, y)

    def disc(self, r: float, z0: float, h: float, x: float = 0.0, y: float = 0.0, n: int = 48):
        return self.cylinder(r, h, (x, y, z0), n)

    def shell(self, outer, thickness: float, sections: int = 48) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return _shell(outer, thickness, self.n(sections))
        return self.lathe(outer)

    def bulb(self, z0: float, r: float, x: float = 0.0, y: float = 0.0) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return _bulb(z0, r, x, y, self.n(24))
        return self._cheap_box(r, z0, z0 + 2.3 * r, x, y)

    def flame(self, z0: float, r: float, x: float = 0.0, y: float = 0.0) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return _flame(z0, r, x, y, self.n(16))
        return self._cheap_box(r, z0, z0 + 3.4 * r, x, y)

    def sphere(self, r: float, sections: int = 12) -> m3d.Manifold:
        if self.detail or not self.boxes:
            return m3d.Manifold.sphere(r, self.n(sections))
        return self._cheap_box(r, -r, r)

    def rod(self, p0, p1, radius: float, sections: int = 12) -> m3d.Manifold:
        if self.detail:
            return rod(p0, p1, radius, sections)
        p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
        d = (p1 - p0) / np.linalg.norm(p1 - p0)
        pad = radius * np.sqrt(np.clip(1.0 - d ** 2, 0.0, 1.0))
        return box_between(np.minimum(p0, p1) - pad, np.maximum(p0, p1) + pad)


FINE, CHEAP, CHEAP_ROUND = _Kit(True), _Kit(False), _Kit(False, boxes=False)


# ---------------------------------------------------------------------------- ceiling light
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

    def _groups(self, p, k: _Kit | None) -> tuple[list[list[Part]], float, Surface]:
        return getattr(self, f"_{p['style']}")(p, k)

    def parts(self, p, detail):
        return _build(self._groups(p, FINE if detail else CHEAP)[0], detail)

    def extra_surfaces(self, p):
        return [self._groups(p, None)[2]]

    # ---- styles: each returns (groups of parts, overall height, top surface); with k=None
    # ---- only the height and the top (no parts)
    def _dome(self, p, k: _Kit | None):
        R = p["diameter"] / 2
        h = min(max(p["body_height"], 0.06), 0.4 * p["diameter"])  # a shallow flush dome
        Rd = R - 0.01
        rf = 0.3 * Rd
        us = np.linspace(0.0, 1.0, 10)
        prof = [(0.0, 0.0)] + [(rf + (Rd - rf) * math.sin(u * math.pi / 2), h * (1 - math.cos(u * math.pi / 2)))
                               for u in us] + [(Rd, h + OVERLAP), (0.0, h + OVERLAP)]
        H = h + self.CANOPY_H
        if k is None:
            return [], H, _top_disc(R, H)
        base = [Part(k.disc(R, h, self.CANOPY_H), "metal")]
        if p["trim"]:
            base.append(Part(k.lathe([(Rd - 0.003, h - 0.02), (R - 0.002, h - 0.02), (R - 0.002, h + OVERLAP),
                                    (Rd - 0.003, h + OVERLAP)], 48), "metal"))
        return [base, [Part(k.lathe(prof, 48), "emissive")]], H, _top_disc(R, H)

    def _drum(self, p, k: _Kit | None):
        R = p["diameter"] / 2
        bh = max(p["body_height"], 0.1)
        th, cr = 0.003, p["canopy_radius"]
        stem = max(p["drop"], 0.05)
        H = bh + stem + self.CANOPY_H
        if k is None:
            return [], H, _top_disc(cr, H)
        shade = [Part(k.shell([(R, 0.0), (R, bh)], th), "shade"),
                 Part(k.disc(R - th + OVERLAP, 0.004, 0.004), "emissive")]
        zh = bh - 0.015
        hub = [Part(k.disc(0.03, zh, 0.015, n=24), "metal")]
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 2
            hub.append(Part(k.rod((0.0, 0.0, bh - 0.008), ((R - th / 2) * math.cos(a), (R - th / 2) * math.sin(a),
                                                         bh - 0.008), 0.003, 8), "metal"))
        rb = max(0.012, min(0.035, (bh - 0.015 - 0.025 - 0.02) / 2.3))
        zs = zh - 0.025
        hub.append(Part(k.disc(0.015, zs, 0.025 + OVERLAP, n=16), "metal"))
        hub.append(Part(k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, zs + OVERLAP)), "emissive"))
        top = [Part(k.disc(cr, H - self.CANOPY_H, self.CANOPY_H), "metal"),
               Part(k.rod((0.0, 0.0, bh - OVERLAP), (0.0, 0.0, H - self.CANOPY_H + OVERLAP), 0.008, 12), "metal")]
        return [shade, hub, top], H, _top_disc(cr, H)

    def _panel(self, p, k: _Kit | None):
        R = p["diameter"] / 2
        pt = min(max(0.4 * p["body_height"], 0.025), 0.06)
        lens, inset = 0.003, 0.012
        body_slot = "metal" if p["trim"] else "plastic"
        if k is None:
            top = _top_disc(R, lens + pt) if p["shape"] == "round" else _top_rect(R - 0.001, R - 0.001, lens + pt)
            return [], lens + pt, top
        if p["shape"] == "round":
            body = k.disc(R, lens, pt)
            face = k.disc(R - inset, 0.0, lens + OVERLAP)
            top = _top_disc(R, lens + pt)
        else:
            body = box_between((-R, -R, lens), (R, R, lens + pt))
            face = box_between((-R + inset, -R + inset, 0.0), (R - inset, R - inset, lens + OVERLAP))
            top = _top_rect(R - 0.001, R - 0.001, lens + pt)
        return [[Part(body, body_slot), Part(face, "emissive")]], lens + pt, top

    def _spots(self, p, k: _Kit | None):
        R = p["diameter"] / 2
        n = int(p["n_lights"])
        can_l = min(max(0.6 * p["body_height"], 0.06), 0.12)
        stem = min(max(0.4 * p["drop"], 0.02), 0.15)
        lens, rc = 0.003, 0.032
        z_plate = lens + can_l + stem
        H = z_plate + 0.025
        slot = "metal" if p["trim"] else "plastic"
        if k is None:
            top = (_top_disc(min(0.12, 0.4 * R), H) if p["shape"] == "round"
                   else _top_rect(0.034, R - 0.001, H))
            return [], H, top
        if p["shape"] == "round":  # a small plate, the spots splayed out on slanted stems
            rp = min(0.12, 0.4 * R)
            plate = k.disc(rp, z_plate, 0.025)
            ang = 2 * math.pi * np.arange(n) / n
            centres = np.c_[(R - rc) * np.cos(ang), (R - rc) * np.sin(ang)]
            roots = 0.6 * rp * np.c_[np.cos(ang), np.sin(ang)]
            top = _top_disc(rp, H)
        else:  # a straight track bar
            plate = box_between((-0.035, -R, z_plate), (0.035, R, H))
            centres = np.c_[np.zeros(n), np.linspace(-R + 0.05, R - 0.05, n)]
            roots = centres
            top = _top_rect(0.034, R - 0.001, H)
        groups = [[Part(plate, slot)]]
        for (x, y), (xr, yr) in zip(centres, roots):
            groups.append([Part(k.disc(rc, lens, can_l, x, y, 24), slot),
                           Part(k.disc(rc - 0.006, 0.0, lens + OVERLAP, x, y, 24), "emissive"),
                           Part(k.rod((x, y, lens + can_l - 0.01), (xr, yr, z_plate + OVERLAP), 0.006, 8), slot)])
        return groups, H, top

    def _chandelier(self, p, k: _Kit | None):
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
            return [], H, _top_disc(cr, H)
        groups = [[Part(k.lathe(col, 24), "metal"),
                   Part(k.rod((0.0, 0.0, z_col1), (0.0, 0.0, H - self.CANOPY_H + OVERLAP), 0.007, 12), "metal"),
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
                arm = [Part(k.rod(q0, q1, 0.006, 8), "metal") for q0, q1 in zip(pts, pts[1:])]
            else:  # the curved arm's box (the rods' boxes stay within 6 mm of its points)
                arm = [Part(box_between(pts.min(axis=0) - 0.006, pts.max(axis=0) + 0.006), "metal")]
            x, y, z = pts[-1]
            arm += [Part(k.sphere(0.006, 8).translate((x, y, z)), "metal"),
                    Part(k.disc(0.028, z - 0.004, 0.01, x, y, 24), "metal"),
                    Part(k.disc(0.011, z + 0.006 - OVERLAP, 0.07, x, y, 16), "wax"),
                    Part(k.flame(z + 0.076 - OVERLAP, 0.012, x, y), "emissive")]
            groups.append(arm)
        return groups, H, _top_disc(cr, H)


# ---------------------------------------------------------------------------- pendant light
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

    def _shade_parts(self, p, k: _Kit = CHEAP) -> list[Part]:
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
            out.append(Part(k.rod((0.0, 0.0, sh - rw), (rr * math.cos(a), rr * math.sin(a), sh - rw), rw, 6), "metal"))
        return out

    def _heights(self, p) -> tuple[float, float]:
        """(z of the shade's top, overall height)."""
        sh = p["shade_height"]
        if p["shade"] == "globe":
            sh = self._shade_parts(p)[0].solid.bounding_box()[5]
        return sh, sh + self.CAP_H + p["drop"] + self.CANOPY_H

    def parts(self, p, detail):
        k = FINE if detail else CHEAP
        zs, H = self._heights(p)
        cr = p["canopy_radius"]
        z_cap = zs - OVERLAP
        fitting = [Part(k.disc(self.CAP_R, z_cap, self.CAP_H, n=24), "metal")]
        if p["shade"] != "globe":
            rb = self._bulb_r(p)
            z_sock = z_cap - 0.03
            fitting.append(Part(k.disc(0.014, z_sock, 0.03 + OVERLAP, n=16), "metal"))
            fitting.append(Part(k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, z_sock + OVERLAP)),
                                "emissive"))
        r_stem = 0.003 if p["stem"] == "cord" else 0.007
        top = [Part(k.rod((0.0, 0.0, z_cap + self.CAP_H - OVERLAP), (0.0, 0.0, H - self.CANOPY_H + OVERLAP),
                        r_stem, 8), "metal" if p["stem"] == "rod" else "plastic"),
               Part(k.disc(cr, H - self.CANOPY_H, self.CANOPY_H), "metal")]
        return _build([self._shade_parts(p, k) + fitting, top[:1], top[1:]], detail)

    def extra_surfaces(self, p):
        return [_top_disc(p["canopy_radius"], self._heights(p)[1])]


# --------------------------------------------------------------------------------- desk lamp
HEAD_TILT = 0.6  # head joint range: +-0.6 rad (~34 degrees)


@register
class DeskLamp(PartsFactory):
    """A desk lamp: a round or square weighted base, an architect arm (pairs of rods between
    knuckles) or a gooseneck, and a cone, dome or cylinder head on a fork. The head tilts on a
    revolute joint (`head_joint`); the bulb inside it is emissive."""

    name = "desk_lamp"
    tags = frozenset({S.Object, S.Lighting, S.DeskLamp})
    size_class = "medium"
    slots = LIGHT_SLOTS
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=("architect", "gooseneck"), doc="arm type"),
        "base_shape": Param(kind="choice", choices=("round", "square"), doc="base outline"),
        "base_size": Param(0.12, 0.2, doc="base diameter / side (m)"),
        "arm_length": Param(0.22, 0.4, doc="lower arm / gooseneck rise (m)"),
        "upper_length": Param(0.18, 0.35, doc="upper arm / gooseneck reach (m)"),
        "arm_angle": Param(55.0, 80.0, doc="lower arm elevation (degrees; architect)"),
        "head_shape": Param(kind="choice", choices=("cone", "dome", "cylinder"), doc="head shade"),
        "head_radius": Param(0.045, 0.075, doc="head rim radius (m)"),
        "head_angle": Param(45.0, 75.0, doc="head axis below horizontal (degrees)"),
    }

    BASE_H = 0.025
    KNUCKLE_R = 0.012
    KNUCKLE_W = 0.008  # half width of the head knuckle along Y
    CHEEK = (0.010, 0.018)  # the fork's cheeks span these |y|

    def _pivot(self, p, k: _Kit = CHEAP) -> tuple[np.ndarray, np.ndarray, list[Part]]:
        """The head pivot P, the arm's direction there, and the arm's parts (up to the fork)."""
        b = p["base_size"]
        xb = -0.25 * b
        z0 = self.BASE_H + 0.03
        out = [Part(k.disc(0.016, self.BASE_H - OVERLAP, 0.03 + OVERLAP, xb, 0.0, 16), "metal")]
        P0 = np.array([xb, 0.0, z0])
        if p["style"] == "architect":
            a1 = math.radians(p["arm_angle"])
            P1 = P0 + p["arm_length"] * np.array([math.cos(a1), 0.0, math.sin(a1)])
            u = np.array([math.cos(math.radians(10)), 0.0, math.sin(math.radians(10))])
            Q = P1 + (p["upper_length"] - 0.025) * u
            for P in (P0, P1):  # knuckles across the rod pairs
                out.append(Part(k.rod(P + (0, -0.022, 0), P + (0, 0.022, 0), 0.011, 16), "metal"))
            for y in (-0.016, 0.016):
                off = np.array([0.0, y, 0.0])
                out.append(Part(k.rod(P0 + off, P1 + off, 0.004, 8), "metal"))
                out.append(Part(k.rod(P1 + off, Q + off, 0.004, 8), "metal"))
        else:  # gooseneck: straight rise, then a quarter bend towards +X
            rise, reach = p["arm_length"], p["upper_length"] - 0.025
            rc = min(0.5 * reach, 0.5 * rise)
            pts = [P0, P0 + (0, 0, rise - rc)]
            for t in np.linspace(0.0, math.pi / 2, 7)[1:]:
                pts.append(pts[1] + np.array([rc * (1 - math.cos(t)), 0.0, rc * math.sin(t)]))
            pts.append(pts[-1] + np.array([reach - rc, 0.0, 0.0]))
            for a, c in zip(pts, pts[1:]):
                out.append(Part(k.rod(a, c, 0.006, 8), "metal"))
                out.append(Part(k.sphere(0.006, 8).translate(tuple(c)), "metal"))
            Q = pts[-1]
            u = np.array([1.0, 0.0, 0.0])
        P = Q + 0.025 * u
        # the fork: a bridge across at Q and two cheeks reaching the pivot
        out.append(Part(k.rod(Q + (0, -self.CHEEK[1], 0), Q + (0, self.CHEEK[1], 0), 0.007, 12), "metal"))
        for s in (-1, 1):
            ya, yb = s * self.CHEEK[0], s * self.CHEEK[1]
            cheek = [k.rod(c + (0, min(ya, yb), 0), c + (0, max(ya, yb), 0), self.KNUCKLE_R * 0.9, 16)
                     for c in (P, Q)]
            out.append(Part(m3d.Manifold.batch_hull(cheek), "metal"))
        return P, u, out

    def _head(self, p, P: np.ndarray, k: _Kit = CHEAP) -> list[Part]:
        """The head (knuckle, neck, shade, socket, bulb) on link "head", its axis pointing
        `head_angle` below horizontal."""
        R, kind = p["head_radius"], p["head_shape"]
        sh = 1.6 * R if kind != "dome" else 1.2 * R
        th, r0 = 0.002, 0.02
        if kind == "cone":
            outer = [(r0, 0.0), (R, -sh)]
        elif kind == "cylinder":
            outer = [(R, 0.0), (R, -sh)]
        else:
            us = np.linspace(0.0, 1.0, 8)
            outer = [(r0 + (R - r0) * math.sin(u * math.pi / 2), -sh * (1 - math.cos(u * math.pi / 2)) ** 0.7)
                     for u in us]
        prof = [(0.0, 0.0)] + outer + [(outer[-1][0] - th, outer[-1][1])] + \
            [(max(r - th, 0.001), z - th) for r, z in reversed(outer[:-1])] + [(0.0, -th)]
        cup = k.lathe(prof, 32)
        neck = 0.045
        rb = min(0.3 * R, 0.022)
        z_sock = -th - 0.03  # the socket reaches into the cup's back, the neck starts inside it
        local = [(cup, "shade"),
                 (k.cylinder(0.011, 0.03 + th / 2, (0.0, 0.0, z_sock), 16), "metal"),
                 (k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, z_sock + OVERLAP)), "emissive"),
                 (k.cylinder(0.0065, neck + OVERLAP + th / 2, (0.0, 0.0, -th / 2), 12), "metal")]
        beta = p["head_angle"] - 90.0
        d = np.array([math.cos(math.radians(p["head_angle"])), 0.0, -math.sin(math.radians(p["head_angle"]))])
        back = P + d * neck
        out = [Part(s.rotate((0.0, beta, 0.0)).translate(tuple(back)), slot, "head") for s, slot in local]
        out.append(Part(k.rod(P + (0, -self.KNUCKLE_W, 0), P + (0, self.KNUCKLE_W, 0), self.KNUCKLE_R, 16),
                        "metal", "head"))
        return out

    def _base(self, p, k: _Kit = FINE) -> Part:
        b = p["base_size"]
        if p["base_shape"] == "round":
            return Part(k.cylinder(b / 2, self.BASE_H, (0, 0, 0), 48, radius_top=b / 2 - 0.006), "metal")
        return Part(box_between((-b / 2, -b / 2, 0.0), (b / 2, b / 2, self.BASE_H)), "metal")

    def parts(self, p, detail):
        k = FINE if detail else CHEAP
        P, _, arm = self._pivot(p, k)
        head = self._head(p, P, k if detail else CHEAP_ROUND)  # rotated: boxes would grow
        if detail:
            return [self._base(p)] + arm + head
        return [self._base(p) if p["base_shape"] == "square" else
                Part(cylinder(p["base_size"] / 2, self.BASE_H, (0, 0, 0), 16, circumscribed=True), "metal"),
                _aabb(arm), _aabb(head)]

    def joints(self, p):
        P, _, _ = self._pivot(p)
        return [make_joint("head_joint", DoorJoint("revolute", np.array([0.0, 1.0, 0.0]), P, "head"),
                           -HEAD_TILT, HEAD_TILT)]

    def extra_surfaces(self, p):
        b = p["base_size"]
        poly = (circle_polygon(0.998 * b / 2, 48) if p["base_shape"] == "round"
                else sg.box(-b / 2 + 0.0005, -b / 2 + 0.0005, b / 2 - 0.0005, b / 2 - 0.0005))
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------ wall sconce
@register
class WallSconce(PartsFactory):
    """A wall sconce: a flat wall plate (its `back`, against the wall), an arm reaching out and
    rising to a fabric shade around an upright bulb, an up-light bowl, an opal globe or a candle
    with a flame bulb."""

    name = "wall_sconce"
    tags = frozenset({S.Object, S.Lighting, S.WallSconce, S.WallMounted})
    size_class = "medium"
    slots = LIGHT_SLOTS
    params = {
        "style": Param(kind="choice", choices=("shade", "uplight", "globe", "candle"),
                       doc="what the arm carries"),
        "plate_shape": Param(kind="choice", choices=("round", "rect"), doc="wall plate outline"),
        "plate_size": Param(0.08, 0.15, doc="wall plate diameter / height (m)"),
        "reach": Param(0.1, 0.25, doc="arm projection from the wall to the fixture axis (m)"),
        "arm_rise": Param(0.02, 0.15, doc="rise of the arm's upright part (m)"),
        "shade_diameter": Param(0.1, 0.25, doc="shade / bowl / globe diameter (m; kept clear of "
                                               "the wall)"),
        "shade_height": Param(0.08, 0.2, doc="shade / bowl height (m)"),
    }

    PLATE_T = 0.015

    def _R(self, p) -> float:
        """Fixture radius, at least 2.5 cm clear of the wall plate."""
        return min(p["shade_diameter"] / 2, p["reach"] - self.PLATE_T - 0.025)

    def _plate(self, p, zc: float, k: _Kit) -> m3d.Manifold:
        s, t = p["plate_size"], self.PLATE_T
        if p["plate_shape"] == "round":
            return k.cylinder(s / 2, t, (0.0, 0.0, 0.0), 32, circumscribed=True).rotate((0.0, 90.0, 0.0)) \
                .translate((0.0, 0.0, zc))
        return box_between((0.0, -0.4 * s, zc - s / 2), (t, 0.4 * s, zc + s / 2))

    def _fixture(self, p, x: float, z: float, k: _Kit) -> list[Part]:
        """What sits on the arm's end at (x, 0, z)."""
        R, sh, st = self._R(p), p["shade_height"], p["style"]
        o = OVERLAP
        cup = Part(k.disc(0.025, z - 0.012, 0.02, x, 0.0, 24), "metal")
        if st == "candle":
            return [Part(k.disc(min(R, 0.04), z - 0.006, 0.012, x, 0.0, 24), "metal"),
                    Part(k.disc(0.012, z + 0.006 - o, 0.08, x, 0.0, 16), "wax"),
                    Part(k.flame(z + 0.086 - o, 0.013, x), "emissive")]
        if st == "globe":
            rg = R
            us = np.linspace(-math.pi / 2 + 0.5, math.pi / 2 - 0.35, 12)
            prof = [(0.0, 0.0), (rg * math.cos(us[0]), 0.0)] + \
                   [(rg * math.cos(u), rg * (math.sin(u) - math.sin(us[0]))) for u in us[1:]]
            prof.append((0.0, prof[-1][1]))
            return [cup, Part(k.lathe(prof, 32).translate((x, 0.0, z + 0.008 - o)), "emissive")]
        if st == "uplight":
            th = 0.004
            zb = z + 0.008 - o
            us = np.linspace(0.0, 1.0, 8)
            outer = [(0.3 * R + 0.7 * R * math.sin(u * math.pi / 2), zb + sh * (1 - math.cos(u * math.pi / 2)))
                     for u in us]
            prof = [(0.0, zb)] + outer + [(R - th, outer[-1][1])] + \
                [(max(r - th, 0.001), zz + th) for r, zz in reversed(outer[:-1])] + [(0.0, zb + th)]
            rb = min(0.03, 0.4 * R)
            return [cup, Part(k.lathe(prof, 48).translate((x, 0.0, 0.0)), "shade"),
                    Part(k.disc(0.012, zb + th - o, 0.02, x, 0.0, 16), "metal"),
                    Part(k.bulb(zb + th + 0.02 - 2 * o, rb, x), "emissive")]
        # fabric shade on a spider around an upright bulb
        th = 0.003
        z_s0 = z + 0.02
        rt = 0.7 * R
        rb = min(0.03, 0.35 * rt)
        out = [cup, Part(k.disc(0.014, z + 0.008 - o, 0.035, x, 0.0, 16), "metal"),
               Part(k.bulb(z + 0.043 - o, rb, x), "emissive"),
               Part(k.shell([(R, z_s0), (rt, z_s0 + sh)], th).translate((x, 0.0, 0.0)), "shade")]
        z_sp = z_s0 + sh - 0.01
        r_sp = rt + (R - rt) * 0.01 / sh - th / 2
        hub = max(z + 0.043 + 2.3 * rb, z_sp)
        out.append(Part(k.rod((x, 0.0, z + 0.04), (x, 0.0, hub + 0.004), 0.003, 8), "metal"))
        for i in range(3):
            a = 2 * math.pi * i / 3
            out.append(Part(k.rod((x, 0.0, hub), (x + r_sp * math.cos(a), r_sp * math.sin(a), z_sp), 0.0025, 8),
                            "metal"))
        return out

    def _zp(self, p) -> float:
        return 0.1  # plate centre height in the design frame (recentred later)

    def parts(self, p, detail):
        k = FINE if detail else CHEAP
        zc = self._zp(p)
        reach, rise = p["reach"], p["arm_rise"]
        x1 = reach
        z1 = zc + rise
        arm = [Part(k.rod((self.PLATE_T - OVERLAP, 0.0, zc), (x1, 0.0, zc), 0.007, 12), "metal"),
               Part(k.sphere(0.007, 12).translate((x1, 0.0, zc)), "metal"),
               Part(k.rod((x1, 0.0, zc), (x1, 0.0, z1), 0.007, 12), "metal")]
        plate = [Part(self._plate(p, zc, k), "metal")]
        fixture = self._fixture(p, x1, z1, k)
        return _build([plate, arm, fixture], detail)

    def extra_surfaces(self, p):
        s, zc = p["plate_size"], self._zp(p)
        if p["plate_shape"] == "round":
            poly = circle_polygon(0.99 * s / 2, 32)
        else:
            poly = sg.box(-0.4 * s + 0.001, -s / 2 + 0.001, 0.4 * s - 0.001, s / 2 - 0.001)
        return [Surface("back", Subpart.Back, np.array([0.0, 0.0, zc]), np.array([-1.0, 0.0, 0.0]),
                        np.array([0.0, 1.0, 0.0]), poly)]


# -------------------------------------------------------------------------------- table lamp
def _base_radius(shape: str, R: float, t: float) -> float:
    """Lamp base radius at fraction t of its height (0 = foot, 1 = top)."""
    bump = lambda c, w: math.exp(-((t - c) / w) ** 2)
    if shape == "cylinder":
        return R
    if shape == "column":
        return R if t < 0.08 else 0.35 * R + 0.1 * R * bump(0.9, 0.05)
    if shape == "gourd":
        return 0.3 * R + 0.7 * R * max(bump(0.3, 0.2), 0.7 * bump(0.72, 0.13))
    return 0.25 * R + 0.75 * R * math.sin(math.pi * min(t * 1.05, 1.0)) ** 1.3  # vase


@register
class TableLamp(PartsFactory):
    """A table lamp: a lathed ceramic base (vase, gourd, column or cylinder), a neck, socket and
    bulb, a harp carrying a drum, empire or bell shade on a spider."""

    name = "table_lamp"
    tags = frozenset({S.Object, S.Lighting, S.TableLamp})
    size_class = "medium"
    slots = LIGHT_SLOTS
    solid_bottom = True
    params = {
        "base_shape": Param(kind="choice", choices=("vase", "gourd", "column", "cylinder"),
                            doc="base profile"),
        "base_height": Param(0.15, 0.4, doc="base height (m)"),
        "base_radius": Param(0.05, 0.12, doc="base radius at its widest (m)"),
        "shade_shape": Param(kind="choice", choices=("drum", "empire", "bell"), doc="shade profile"),
        "shade_radius": Param(0.12, 0.22, doc="shade radius at its lower rim (m)"),
        "shade_height": Param(0.14, 0.28, doc="shade height (m)"),
        "neck_height": Param(0.03, 0.12, doc="gap from the base's top to the shade's rim (m)"),
    }

    def _foot_r(self, p) -> float:
        return max(_base_radius(p["base_shape"], p["base_radius"], 0.0), 0.03)

    def _shade_outer(self, p, z0: float) -> list[tuple[float, float]]:
        Rb, sh, kind = p["shade_radius"], p["shade_height"], p["shade_shape"]
        if kind == "drum":
            return [(Rb, z0), (Rb, z0 + sh)]
        Rt = 0.6 * Rb
        if kind == "empire":
            return [(Rb, z0), (Rt, z0 + sh)]
        ts = np.linspace(0.0, 1.0, 10)
        return [(Rt + (Rb - Rt) * (1 - t) ** 2, z0 + t * sh) for t in ts]

    def parts(self, p, detail):
        k = FINE if detail else CHEAP
        hb, R, shape = p["base_height"], p["base_radius"], p["base_shape"]
        o = OVERLAP
        ts = np.linspace(0.0, 1.0, 24)
        prof = [(0.0, 0.0), (self._foot_r(p), 0.0)]
        prof += [(max(_base_radius(shape, R, t), 0.016), t * hb) for t in ts[1:]]
        prof += [(0.0, hb)]
        base = [Part(k.lathe(prof, 48), "ceramic")]
        z_sb = hb + p["neck_height"]
        sh = p["shade_height"]
        z_st = z_sb + sh
        rb = 0.03
        z_bulb = z_sb + 0.35 * sh - rb
        z_sock = z_bulb - 0.035
        fit = [Part(k.rod((0.0, 0.0, hb - 0.01), (0.0, 0.0, z_sock + o), 0.009, 12), "metal"),
               Part(k.disc(0.018, z_sock, 0.035 + o, n=16), "metal"),
               Part(k.bulb(z_bulb, rb), "emissive")]
        # the harp: two uprights from a saddle under the socket to a top bar, a finial on it
        yh = 0.05
        z_h = z_st - 0.012
        fit.append(Part(k.rod((0.0, -yh, z_sock + 0.006), (0.0, yh, z_sock + 0.006), 0.004, 8), "metal"))
        for y in (-yh, yh):
            fit.append(Part(k.rod((0.0, y, z_sock + 0.002), (0.0, y, z_h + 0.004), 0.0035, 8), "metal"))
        fit.append(Part(k.rod((0.0, -yh - 0.0035, z_h), (0.0, yh + 0.0035, z_h), 0.004, 8), "metal"))
        fit.append(Part(k.disc(0.01, z_h - o, 0.02, n=12), "metal"))
        outer = self._shade_outer(p, z_sb)
        th = 0.003
        shade = [Part(k.shell(outer, th), "shade")]
        r_sp = outer[-1][0] + (outer[-2][0] - outer[-1][0]) * 0.012 / (outer[-1][1] - outer[-2][1]) - th / 2
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 2
            shade.append(Part(k.rod((0.0, 0.0, z_h), (r_sp * math.cos(a), r_sp * math.sin(a), z_h), 0.0025, 8),
                              "metal"))
        return _build([base, fit, shade], detail)

    def extra_surfaces(self, p):
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(0.995 * self._foot_r(p), 48),
                                subpart=Subpart.Bottom, up=False)]
