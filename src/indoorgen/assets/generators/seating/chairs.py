"""Chairs: dining chairs (slat, ladder or panel backs), light side chairs (Windsor, bentwood,
cantilever, moulded shell) and padded upholstered chairs. Front (+X) is where one sits from."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg
from numpy.typing import ArrayLike

from indoorgen.assets.generators.seating._parts import (
    bevel_points,
    leg_point,
    points_box,
    seat_surface,
    shear_back,
    shear_points,
    soft_sheared,
    splay_legs,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    bevel_box,
    board,
    box,
    box_between,
    rounded_rect_polygon,
    rounded_slab,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.assets.shapes.sweeps import (
    dedupe_points,
    fillet_path,
    polyline_tangents,
    rod_between,
    tube,
    tube_boxes,
    unit_rows,
)
from indoorgen.model.tags import Semantics as S


def thick_polyline(center: ArrayLike, thickness: float) -> np.ndarray:
    """The outline (a closed 2D polygon) of a band `thickness` wide around a 2D polyline."""
    c = np.asarray(center, float)
    seg = unit_rows(np.diff(c, axis=0))
    tang = np.empty_like(c)
    tang[0], tang[-1] = seg[0], seg[-1]
    tang[1:-1] = unit_rows(seg[:-1] + seg[1:])
    nrm = np.c_[-tang[:, 1], tang[:, 0]]
    scale = np.ones(len(c))
    scale[1:-1] = 1.0 / np.maximum(np.einsum("ij,ij->i", seg[:-1], tang[1:-1]), 0.3)
    off = nrm * (thickness / 2 * scale)[:, None]
    return np.vstack([c + off, (c - off)[::-1]])


def profile_slab(outline_xz: np.ndarray, y0: float, y1: float) -> m3d.Manifold:
    """A 2D outline in the XZ plane (side view) extruded across Y from y0 to y1."""
    pts = np.asarray(outline_xz, float)
    x, z = pts[:, 0], pts[:, 1]
    area = 0.5 * float(np.dot(x, np.roll(z, -1)) - np.dot(z, np.roll(x, -1)))
    cs = m3d.CrossSection([pts], m3d.FillRule.Positive if area > 0 else m3d.FillRule.Negative)
    slab = m3d.Manifold.extrude(cs, float(y1 - y0))  # along +Z; turn it to run along -Y
    return slab.rotate((90.0, 0.0, 0.0)).translate((0.0, float(y1), 0.0))


@register
class DiningChair(PartsFactory):
    """A dining chair: seat, four legs, a back of slats, ladder rails or a solid panel."""

    name = "dining_chair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Chair, S.DiningChair})
    size_class = "large"
    slots = ["wood", "fabric"]
    params = {
        "seat_width": Param(0.40, 0.50, doc="seat Y extent (m)"),
        "seat_depth": Param(0.40, 0.48, doc="seat X extent (m)"),
        "seat_height": Param(0.43, 0.48, doc="height of the seat's upper face (m)"),
        "seat_thickness": Param(0.03, 0.06, doc="seat board thickness (m)"),
        "seat_style": Param(kind="choice", choices=("wood", "padded"), doc="bare or padded seat"),
        "back_height": Param(0.35, 0.50, doc="back height above the seat (m)"),
        "back_style": Param(kind="choice", choices=("slats", "ladder", "solid"), doc="back design"),
        "n_slats": Param(2, 5, kind="int", doc="vertical slats or horizontal ladder rails"),
        "back_tilt": Param(0.0, 10.0, doc="backwards lean of the back (degrees)"),
        "leg_thickness": Param(0.025, 0.045, doc="leg section size (m)"),
        "leg_taper": Param(0.6, 1.0, doc="foot size / leg top size"),
        "stretchers": Param(kind="bool", doc="add stretchers between the legs"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Seat, legs, back posts and slats (or rails, or a panel), optional stretchers."""
        sw, sd, sh, st = p["seat_width"], p["seat_depth"], p["seat_height"], p["seat_thickness"]
        lt, bh = p["leg_thickness"], p["back_height"]
        z_seat0 = sh - st
        out: list[Part] = []
        padded = p["seat_style"] == "padded"
        if detail:
            seat = bevel_box((sd, sw, st), (0, 0, sh - st / 2), 0.012 if padded else 0.003, 2)
        else:
            seat = box((sd, sw, st), (0, 0, sh - st / 2))
        out.append(Part(seat, "fabric" if padded else "wood"))
        taper = p["leg_taper"] if detail else 1.0
        cx, cy = sd / 2 - lt / 2, sw / 2 - lt / 2
        for leg in legs((sd, sw), 0.0, lt, 0.0, z_seat0 + OVERLAP, taper=taper):
            out.append(Part(leg, "wood"))
        # back: posts continuing the back legs, plus slats/rails/panel between them
        tilt = p["back_tilt"]
        ztop = sh + bh
        back = []
        for s in (-1, 1):  # post: an upright piece through the seat, then the leaning part
            out.append(Part(box_between((-sd / 2, s * cy - lt / 2, z_seat0),
                                        (-sd / 2 + lt, s * cy + lt / 2, sh + OVERLAP)), "wood"))
            back.append(box_between((-sd / 2, s * cy - lt / 2, sh), (-sd / 2 + lt, s * cy + lt / 2, ztop)))
        bt = min(0.02, lt * 0.7)  # back boards' thickness
        xb0, xb1 = -sd / 2 + (lt - bt) / 2, -sd / 2 + (lt + bt) / 2
        y_in = cy - lt / 2 + OVERLAP  # inner faces of the posts (plus overlap)
        rail_h = min(0.07, bh * 0.2)
        back.append(box_between((xb0, -y_in, ztop - rail_h), (xb1, y_in, ztop)))  # top rail
        style, n = p["back_style"], int(p["n_slats"])
        z_lo = sh + 0.06  # the lowest back piece leaves a gap above the seat
        if not detail or style == "solid":
            back.append(box_between((xb0, -y_in, z_lo), (xb1, y_in, ztop)))
        elif style == "slats":
            back.append(box_between((xb0, -y_in, z_lo), (xb1, y_in, z_lo + 0.03)))  # bottom rail
            span = 2 * y_in
            slat_w = min(0.05, span / (2 * n + 1))
            for i in range(n):
                yc = -y_in + span * (i + 1) / (n + 1)
                back.append(box_between((xb0, yc - slat_w / 2, z_lo + 0.03 - OVERLAP),
                                        (xb1, yc + slat_w / 2, ztop - rail_h + OVERLAP)))
        else:  # ladder: horizontal rails
            gap = (ztop - rail_h - z_lo) / n
            for i in range(n):
                z = z_lo + i * gap
                back.append(box_between((xb0, -y_in, z), (xb1, y_in, z + min(0.04, gap * 0.5))))
        for b in back:
            out.append(Part(shear_back(b, sh, tilt), "wood"))
        if p["stretchers"]:
            zs, w = 0.14, min(0.018, lt * 0.6)
            for s in (-1, 1):
                out.append(Part(box_between((-cx, s * cy - w / 2, zs - w / 2),
                                            (cx, s * cy + w / 2, zs + w / 2)), "wood"))
            out.append(Part(box_between((cx - w / 2, -cy, zs + 0.04 - w / 2),
                                        (cx + w / 2, cy, zs + 0.04 + w / 2)), "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The seat between the back posts and the front edge."""
        sd, sw, sh, lt = p["seat_depth"], p["seat_width"], p["seat_height"], p["leg_thickness"]
        x0, x1 = -sd / 2 + lt + 0.01, sd / 2 - 0.02
        return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, sw / 2 - 0.02)]


@register
class SideChair(PartsFactory):
    """A light armless side chair, four families: a Windsor (thick saddle seat, splayed turned
    legs with an H-stretcher, spindle back under a bowed crest rail), a bentwood bistro chair
    (round-ish seat, leg ring, back legs bent into one hoop with spindles), a cantilever chair
    (one tubular-steel S frame per side, no back legs, padded seat and back) and a moulded
    plastic shell on splayed legs. Seat size, height, back height and lean, leg thickness and
    splay, seat roundness and spindle count vary."""

    name = "side_chair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Chair, S.SideChair})
    size_class = "large"
    slots = ["wood", "metal", "plastic", "fabric"]
    params = {
        "style": Param(kind="choice", choices=("windsor", "bentwood", "cantilever", "shell"),
                       doc="chair family"),
        "seat_width": Param(0.40, 0.48, doc="seat Y extent (m)"),
        "seat_depth": Param(0.40, 0.47, doc="seat X extent (m)"),
        "seat_height": Param(0.43, 0.48, doc="height of the seat's upper face (m)"),
        "seat_thickness": Param(0.02, 0.045, doc="seat board / shell / pad thickness (m)"),
        "seat_roundness": Param(0.03, 0.24, doc="corner radius of the seat's plan (m); "
                                                 "half the width makes it round"),
        "back_height": Param(0.32, 0.48, doc="height of the back above the seat (m)"),
        "back_tilt": Param(3.0, 14.0, doc="backwards lean of the back (degrees)"),
        "leg_thickness": Param(0.022, 0.036, doc="leg (or frame tube) diameter (m)"),
        "leg_splay": Param(0.0, 0.05, doc="how far the feet stand out beyond the leg tops "
                                          "(cantilever: how far the runners reach forward) (m)"),
        "n_spindles": Param(3, 9, kind="int", doc="back spindles (Windsor, bentwood)"),
    }

    # ---- pieces shared by the styles
    def _seat_plan(self, p) -> tuple[float, float, float]:
        sd, sw = p["seat_depth"], p["seat_width"]
        return sd, sw, min(p["seat_roundness"], 0.5 * min(sd, sw) - 0.001)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The chair of its family (Windsor, bentwood, cantilever or shell)."""
        return getattr(self, "_" + p["style"])(p, detail)

    def _windsor(self, p, detail):
        sd, sw, rc = self._seat_plan(p)
        sh, st = p["seat_height"], max(p["seat_thickness"], 0.035)
        lt, tilt, splay = p["leg_thickness"], p["back_tilt"], p["leg_splay"]
        z0 = sh - st
        seat = rounded_slab(sd, sw, z0, sh, rc) if detail else box((sd, sw, st), (0, 0, sh - st / 2))
        out = [Part(seat, "wood")]
        ix, iy = sd / 2 - 0.06, sw / 2 - 0.06
        corners = [(sx * ix, sy * iy) for sx in (-1, 1) for sy in (-1, 1)]
        lp, axes = splay_legs(corners, z0 + OVERLAP, lt / 2, lt * 0.35, splay, detail, "wood")
        out += lp
        # H-stretcher: a rung between front and back leg on each side, one across the middle
        zs, rr = 0.17, lt * 0.3
        mids = []
        for j in (0, 1):  # corners 0/2 are y=-, 1/3 are y=+
            a, b = leg_point(axes[j], zs), leg_point(axes[j + 2], zs)
            out.append(Part(rod_between(a, b, rr, detail), "wood"))
            mids.append((a + b) / 2)
        out.append(Part(rod_between(mids[0], mids[1], rr, detail), "wood"))
        # spindle back under a bowed crest rail, leaning back from the seat's top
        n, zc = int(p["n_spindles"]), sh + p["back_height"] - 0.02
        k = math.tan(math.radians(tilt))
        yc, xb, bow = sw / 2 - 0.05, -sd / 2 + 0.045, 0.04
        lean = k * (zc - sh)  # how far the crest stands behind the spindles' feet
        ys = np.linspace(-yc, yc, 25)
        crest = np.c_[xb - bow * (1 - (ys / yc) ** 2) - lean, ys, np.full(len(ys), zc)]
        y = np.linspace(-yc + 0.01, yc - 0.01, n + 2)
        x = xb - bow * (1 - (y / yc) ** 2)
        feet = np.c_[xb + 0.3 * (x - xb) + 0.01 * k, y, np.full(n + 2, sh - 0.01)]
        tops = np.c_[x - lean, y, np.full(n + 2, zc)]
        radii = np.full(n + 2, 0.0065)
        radii[[0, -1]] = 0.011  # thicker end spindles
        if detail:
            out += [Part(tube([a, b], r, 10), "wood") for a, b, r in zip(feet, tops, radii, strict=True)]
            out.append(Part(tube(crest, 0.02, 12), "wood"))
        else:
            out.append(Part(_spindle_back_box(crest, 0.02, feet, tops, radii), "wood"))
        return out

    def _bentwood(self, p, detail):
        sd, sw, rc = self._seat_plan(p)
        sh, st = p["seat_height"], p["seat_thickness"]
        lt, tilt, splay = p["leg_thickness"], p["back_tilt"], p["leg_splay"]
        z0, r = sh - st, lt / 2
        seat = rounded_slab(sd, sw, z0, sh, rc) if detail else box((sd, sw, st), (0, 0, sh - st / 2))
        out = [Part(seat, "wood")]
        # legs on a circle inside the seat, so that one ring ties all four
        R = 0.5 * min(sd, sw) - 0.045
        c45 = R * math.sqrt(0.5)
        fl, ax_f = splay_legs([(c45, -c45), (c45, c45)], z0 + OVERLAP, r, r * 0.8, splay,
                              detail, "wood")
        out += fl
        # the back legs and the back hoop: one bent piece from foot to foot
        k = math.tan(math.radians(tilt))
        xb, yb = -c45, c45
        zt = sh + p["back_height"] - r
        hoop_r = yb
        zh = zt - hoop_r
        sfx, sfy = (-splay * math.sqrt(0.5), splay * math.sqrt(0.5))
        arc = np.linspace(math.pi, 0.0, 13)
        top = [(xb - k * (zh + hoop_r * math.sin(a) - sh), hoop_r * math.cos(a),
                zh + hoop_r * math.sin(a)) for a in arc]
        path = ([(xb + sfx, -yb - sfy, 0.0), (xb + sfx, -yb - sfy, 0.03), (xb, -yb, sh)] + top
                + [(xb, yb, sh), (xb + sfx, yb + sfy, 0.03), (xb + sfx, yb + sfy, 0.0)])
        bent = fillet_path(dedupe_points(path), 0.05, 4)
        out += [Part(s, "wood") for s in ([tube(bent, r, 12)] if detail else tube_boxes(bent, r, 8))]
        # a ring between the legs
        zr = 0.2
        ring_r = math.hypot(*leg_point(ax_f[0], zr)[:2])
        if detail:
            out.append(Part(torus(ring_r, lt * 0.3, (0, 0, zr), 48, 8), "wood"))
        else:
            rr = ring_r + lt * 0.3
            out.append(Part(box((2 * rr, 2 * rr, lt * 0.6), (0, 0, zr)), "wood"))
        # spindles from a low back rail up to the hoop
        zr0, xs0 = sh + 0.1, xb - k * 0.1
        rail = ((xs0, -yb, zr0), (xs0, yb, zr0))
        n = int(p["n_spindles"])
        ys = np.linspace(-yb, yb, n + 2)[1:-1]
        zy = zh + np.sqrt(np.maximum(hoop_r ** 2 - ys ** 2, 0.0))
        if detail:
            out.append(Part(tube(rail, r * 0.6, 10), "wood"))
            out += [Part(tube([(xs0, y, zr0), (xb - k * (z - sh), y, z)], r * 0.45, 8), "wood")
                    for y, z in zip(ys, zy, strict=True)]
        else:
            pts = np.vstack([rail, np.c_[xb - k * (zy - sh), ys, zy]])
            out.append(Part(points_box(pts, r * 0.6), "wood"))
        return out

    def _cantilever(self, p, detail):
        sd, sw, rc = self._seat_plan(p)
        sh = p["seat_height"]
        st = max(p["seat_thickness"], 0.03)
        rt = min(max(p["leg_thickness"] / 2, 0.011), 0.015)
        k = math.tan(math.radians(p["back_tilt"]))
        ys = sw / 2 - rt - 0.01
        zr = sh - st - rt + OVERLAP  # seat rail centre line, just under the pad
        xf_floor = sd / 2 + 0.03 + p["leg_splay"]
        xr = -sd / 2 + 0.04
        ztop = sh + p["back_height"] - 0.02
        out: list[Part] = []
        for s in (-1, 1):
            pts = [(xr - 0.02, s * ys, rt), (xf_floor, s * ys, rt), (sd / 2 - 0.01, s * ys, zr),
                   (xr, s * ys, zr), (xr - k * (ztop - zr), s * ys, ztop)]
            path = fillet_path(pts, 0.07, 6)
            out += [Part(q,
                         "metal") for q in ([tube(path, rt, 16)] if detail else tube_boxes(path, rt, 6))]
            if detail:  # floor glides under the runner's ends
                for gx in (xr - 0.005, xf_floor - 0.09):
                    out.append(board((gx - 0.015, s * ys - 0.007, 0.0),
                                      (gx + 0.015, s * ys + 0.007, 0.005), "plastic"))
        out.append(Part(rod_between((xr - 0.01, -ys, rt), (xr - 0.01, ys, rt), rt, detail, 16), "metal"))
        seat = (bevel_box((sd - 0.02, sw, st), (0.0, 0, sh - st / 2), min(0.015, st / 3), 2)
                if detail else box((sd - 0.02, sw, st), (0.0, 0, sh - st / 2)))
        out.append(Part(seat, "fabric"))
        zb0 = sh + 0.12
        bt = 0.03
        back = soft_sheared((bt + rt * 0.3, sw, ztop + 0.02 - zb0),
                            (xr + (bt - rt * 0.3) / 2, 0, (zb0 + ztop + 0.02) / 2), 0.012, zr,
                            p["back_tilt"], detail)
        out.append(Part(back, "fabric"))
        return out

    def _shell(self, p, detail):
        sd, sw, rc = self._seat_plan(p)
        sh = p["seat_height"]
        t = 0.45 * p["seat_thickness"] + 0.006
        k = math.tan(math.radians(p["back_tilt"] + 6))
        zs = sh - t / 2  # centre line of the seat pan
        ztop = sh + p["back_height"]
        xr = -sd / 2 + 0.02
        centre = fillet_path([(sd / 2, zs - 0.025, 0), (sd / 2 - 0.05, zs, 0), (xr, zs, 0),
                              (xr - k * (ztop - zs), ztop - t / 2, 0)], 0.09, 8)[:, :2]
        outline = thick_polyline(centre, t)
        nseg = len(centre) - 1
        out: list[Part] = []
        if detail:
            shell = profile_slab(outline, -sw / 2, sw / 2) ^ _front_round(sd, sw, rc)
            out.append(Part(shell, "plastic"))
        else:
            # the band's quads, grouped: seat pan, bend, back
            quads = [np.vstack([outline[i], outline[i + 1], outline[-i - 1], outline[-i - 2]])
                     for i in range(nseg)]
            groups = np.array_split(np.arange(nseg), 3)
            for g in groups:
                q = np.vstack([quads[i] for i in g])
                out.append(board((q[:, 0].min(), -sw / 2, q[:, 1].min()),
                                  (min(q[:, 0].max(), sd / 2), sw / 2, q[:, 1].max()), "plastic"))
        lt, splay = p["leg_thickness"], p["leg_splay"]
        zt = sh - t + OVERLAP
        ix, iy = sd / 2 - 0.08, sw / 2 - 0.07
        corners = [(sx * ix, sy * iy) for sx in (-1, 1) for sy in (-1, 1)]
        lp, axes = splay_legs(corners, zt - 0.012, lt / 2, lt * 0.4, splay + 0.02, detail, "wood")
        out += lp
        plate = box_between((-ix - lt / 2, -iy - lt / 2, zt - 0.012 - OVERLAP),
                            (ix + lt / 2, iy + lt / 2, zt))
        out.append(Part(plate, "metal"))
        zs0 = 0.18
        for j in (0, 1):
            a, b = leg_point(axes[j], zs0), leg_point(axes[j + 2], zs0)
            out.append(Part(rod_between(a, b, 0.005, detail, 8), "metal"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The seat's plan in front of the back, inset from its edge."""
        sd, sw, rc = self._seat_plan(p)
        style, sh = p["style"], p["seat_height"]
        plan = rounded_rect_polygon(sd, sw, rc, 0.02)
        c45 = (0.5 * min(sd, sw) - 0.045) * math.sqrt(0.5)  # bentwood back posts
        x_back = {"windsor": -sd / 2 + 0.08, "bentwood": -c45 + p["leg_thickness"] / 2 + 0.02,
                  "cantilever": -sd / 2 + 0.09, "shell": -sd / 2 + 0.12}[style]
        x_front = sd / 2 - (0.08 if style == "shell" else 0.025)
        if style == "cantilever":
            plan = sg.box(-sd / 2 + 0.03, -sw / 2 + 0.03, sd / 2 - 0.04, sw / 2 - 0.03)
        plan = plan.intersection(sg.box(x_back, -sw, x_front, sw))
        return [seat_surface("seat", sh, plan)]


def _spindle_back_box(crest: np.ndarray, crest_r: float, feet: np.ndarray, tops: np.ndarray,
                      radii: np.ndarray) -> m3d.Manifold:
    """The box around a crest rail tube and straight spindle tubes (exact ring extents)."""
    half_c = crest_r * np.sqrt(np.clip(1.0 - polyline_tangents(crest) ** 2, 0.0, 1.0))
    t = unit_rows(tops - feet)
    half_s = radii[:, None] * np.sqrt(np.clip(1.0 - t ** 2, 0.0, 1.0))
    lo = np.vstack([crest - half_c, feet - half_s, tops - half_s]).min(axis=0)
    hi = np.vstack([crest + half_c, feet + half_s, tops + half_s]).max(axis=0)
    return box_between(lo, hi)


def _front_round(sd: float, sw: float, rc: float) -> m3d.Manifold:
    """A tall rounded prism that trims a shell's plan to a seat with rounded front corners."""
    return rounded_slab(sd, sw, -1.0, 3.0, rc) + box_between((-2.0, -sw / 2, -1.0), (0.0, sw / 2, 3.0))


@register
class UpholsteredChair(PartsFactory):
    """A padded accent / dining chair: a thick upholstered seat block and back (plain, vertical
    channel tufting, or a wingback), no arms, padded arms or wooden arm rests on posts, and
    tapered wooden, turned round or thin metal legs."""

    name = "upholstered_chair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Chair, S.UpholsteredChair})
    size_class = "large"
    slots = ["upholstery", "wood", "metal"]
    params = {
        "seat_width": Param(0.46, 0.60, doc="seat Y extent (m)"),
        "seat_depth": Param(0.46, 0.58, doc="seat X extent (m)"),
        "seat_height": Param(0.42, 0.48, doc="height of the seat's upper face (m)"),
        "seat_thickness": Param(0.08, 0.14, doc="padded seat block thickness (m)"),
        "back_height": Param(0.35, 0.60, doc="height of the back above the seat (m)"),
        "back_thickness": Param(0.06, 0.12, doc="back X thickness (m)"),
        "back_tilt": Param(4.0, 15.0, doc="backwards lean of the back (degrees)"),
        "back_style": Param(kind="choice", choices=("plain", "channel", "wing"),
                            doc="plain padded back, vertical channels, or a wingback"),
        "n_channels": Param(3, 7, kind="int", doc="vertical channels of a channel back"),
        "arms": Param(kind="choice", choices=("none", "padded", "wood"), doc="arm style"),
        "leg_style": Param(kind="choice", choices=("tapered", "round", "metal"),
                           doc="tapered square wood, turned round wood or thin metal legs"),
        "corner_radius": Param(0.01, 0.04, doc="rounding of the upholstery edges (m)"),
    }
    ARM_W = 0.08  # padded arm width (m)
    ARM_H = 0.20  # arm top above the seat (m)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Padded seat, back (plain, channels or wings), arms and legs."""
        sd, sw, sh, st = p["seat_depth"], p["seat_width"], p["seat_height"], p["seat_thickness"]
        bh, bt, tilt, cr = p["back_height"], p["back_thickness"], p["back_tilt"], p["corner_radius"]
        z0 = sh - st
        k = math.tan(math.radians(tilt))

        def soft(ext, ctr, r, seg=2):
            return bevel_box(ext, ctr, r, seg) if detail else box(ext, ctr)

        out = [Part(soft((sd, sw, st), (0, 0, sh - st / 2), min(cr, st / 3)), "upholstery")]
        ztop = sh + bh
        back_ctr = (-sd / 2 + bt / 2, 0, (z0 + ztop) / 2)
        back = []  # (extents, centre, radius, segments) of the back's pieces
        if p["back_style"] == "channel":
            n = int(p["n_channels"])
            cw = sw / n
            for i in range(n):
                yc = -sw / 2 + (i + 0.5) * cw
                w = cw + (0.008 if 0 < i < n - 1 else 0.004)
                yc += 0.002 if i == 0 else -0.002 if i == n - 1 else 0.0
                back.append(((bt, w, ztop - z0), (back_ctr[0], yc, back_ctr[2]), 0.45 * min(bt, cw), 3))
        else:
            back.append(((bt, sw, ztop - z0), back_ctr, min(cr * 1.5, bt / 2.5), 2))
        wings = []
        if p["back_style"] == "wing":
            zw0 = sh + 0.3 * bh
            wings = [((0.24, 0.07, ztop - zw0), (-sd / 2 + 0.12, s * (sw / 2 - 0.035), (zw0 + ztop) / 2),
                      min(cr, 0.03), 2) for s in (-1, 1)]
        if detail:
            out += [Part(soft_sheared(b[0], b[1], b[2], z0, tilt, True, b[3]), "upholstery")
                    for b in back + wings]
        else:  # boxes around the leaning back and each wing: see `soft_sheared`
            pts = np.vstack([bevel_points(*b) for b in back])
            out.append(Part(points_box(shear_points(pts, z0, tilt), 0.0), "upholstery"))
            out += [Part(soft_sheared(*b[:3], z0, tilt, False, b[3]), "upholstery") for b in wings]
        arms = p["arms"]
        za = sh + self.ARM_H
        if arms == "padded":
            for s in (-1, 1):
                y0, y1 = sw / 2 - 0.006, sw / 2 + self.ARM_W
                out.append(Part(soft((sd, y1 - y0, za - z0), (0, s * (y0 + y1) / 2, (z0 + za) / 2),
                                     min(cr, 0.03)), "upholstery"))
        elif arms == "wood":
            xr0 = -sd / 2 + bt / 2 - k * (za - z0)
            for s in (-1, 1):
                yc = s * (sw / 2 + 0.015)
                out.append(Part(soft((sd / 2 + 0.02 - xr0, 0.05, 0.025),
                                     ((xr0 + sd / 2 + 0.02) / 2, yc, za - 0.0125), 0.008), "wood"))
                yp = s * (sw / 2 + 0.012)
                out.append(board((sd / 2 - 0.075, yp - 0.0175, z0 + 0.01),
                                  (sd / 2 - 0.04, yp + 0.0175, za - 0.025 + OVERLAP), "wood"))
        style = p["leg_style"]
        lt = {"tapered": 0.045, "round": 0.045, "metal": 0.024}[style]
        taper = {"tapered": 0.6, "round": 0.7, "metal": 1.0}[style] if detail else 1.0
        for leg in legs((sd, sw), 0.03, lt, 0.0, z0 + 0.02, taper=taper,
                        round_legs=style != "tapered", circumscribed=not detail,
                        sections=16 if detail else 8):
            out.append(Part(leg, "metal" if style == "metal" else "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The padded seat in front of the back, inset from its rounded edge."""
        sd, sw, sh = p["seat_depth"], p["seat_width"], p["seat_height"]
        m = min(p["corner_radius"], p["seat_thickness"] / 3) + 0.01
        x0, x1 = -sd / 2 + p["back_thickness"] + 0.01, sd / 2 - m
        return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, sw / 2 - m)]
