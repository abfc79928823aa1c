"""More seating: side chairs, upholstered chairs, office chairs, bar stools, stools/ottomans,
L-shaped sectional sofas and benches. Front (+X) is where one sits from.

The module also holds seating's own shape helpers: slanted posts (splayed legs), extruded side
profiles (moulded shells) and the bounding-box pieces placeholders are made of.
"""
from __future__ import annotations

import math
from typing import Any, Iterable, Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import frame, legs
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    bevel_box,
    board,
    box,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    rounded_rect_polygon,
    rounded_slab,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
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

# ===================================================================================== helpers


def post(bottom: Sequence[float], top: Sequence[float], r_bottom: float,
         r_top: float | None = None, sections: int = 16, circumscribed: bool = False,
         square: bool = False) -> m3d.Manifold:
    """A straight or slanted leg from point `bottom` to point `top` whose horizontal sections
    are circles (or squares, `square=True`) of radius r_bottom at the bottom and r_top at the
    top: its foot stands flat on the floor however far it is splayed. `circumscribed` makes the
    polygon contain the true circle, with the same bounding box (for placeholders)."""
    rt = r_bottom if r_top is None else r_top
    if square:
        ring = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)], float)
    else:
        n = max(4, int(math.ceil(sections / 4.0)) * 4)
        k = 1.0 / math.cos(math.pi / n) if circumscribed else 1.0
        a = 2 * np.pi * np.arange(n) / n + (math.pi / n if circumscribed else 0.0)
        ring = k * np.c_[np.cos(a), np.sin(a)]
    b, t = np.asarray(bottom, float), np.asarray(top, float)
    pts = np.vstack([np.c_[b[0] + r_bottom * ring[:, 0], b[1] + r_bottom * ring[:, 1],
                           np.full(len(ring), b[2])],
                     np.c_[t[0] + rt * ring[:, 0], t[1] + rt * ring[:, 1], np.full(len(ring), t[2])]])
    return m3d.Manifold.hull_points(pts)


def thick_polyline(center: Sequence[Sequence[float]], thickness: float) -> np.ndarray:
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


def shear_points(points: np.ndarray, z0: float, tilt_deg: float) -> np.ndarray:
    """`shear_back` applied to points (N, 3)."""
    pts = np.array(points, float).reshape(-1, 3)
    pts[:, 0] -= math.tan(math.radians(tilt_deg)) * (pts[:, 2] - z0)
    return pts


def bevel_points(extents: Sequence[float], center: Sequence[float], radius: float,
                 segments: int = 2) -> np.ndarray:
    """The points whose convex hull `parts.bevel_box` is (the same formula), so that the
    bounding box of a transformed bevelled box is found without building it."""
    ext = np.asarray(extents, float)
    r = float(min(radius, 0.49 * ext.min()))
    signs = np.array([(sx, sy, sz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], float)
    if r <= 1e-5:
        return np.asarray(center, float) + signs * ext / 2
    seg = max(1, segments)
    phi, th = np.meshgrid(np.arange(seg + 1) * (math.pi / 2) / seg, np.arange(seg + 1) * (math.pi / 2) / seg,
                          indexing="ij")
    dirs = np.unique(np.round(np.c_[(np.sin(phi) * np.cos(th)).ravel(), (np.sin(phi) * np.sin(th)).ravel(),
                                    np.cos(phi).ravel()], 12), axis=0)
    pts = signs[:, None, :] * ((ext / 2 - r)[None, None, :] + r * dirs[None, :, :])
    return pts.reshape(-1, 3) + np.asarray(center, float)


def soft_sheared(extents: Sequence[float], center: Sequence[float], radius: float, z0: float,
                 tilt_deg: float, detail: bool, segments: int = 2) -> m3d.Manifold:
    """A bevelled box leaning back by `tilt_deg` about z0 (an upholstered back), or for a
    placeholder the box around it (a sheared plain box would reach further than its rounded
    corners do, so its bounding box would not match)."""
    if detail:
        return shear_back(bevel_box(extents, center, radius, segments), z0, tilt_deg)
    return points_box(shear_points(bevel_points(extents, center, radius, segments), z0, tilt_deg), 0.0)


def shear_back(solid: m3d.Manifold, z0: float, tilt_deg: float) -> m3d.Manifold:
    """Lean `solid` backwards (-X) by `tilt_deg` about height z0 (a shear: horizontal sections
    keep their shape, so a placeholder box sheared alike still contains what it contained)."""
    if abs(tilt_deg) <= 1e-6:
        return solid
    k = math.tan(math.radians(tilt_deg))
    return solid.transform(np.array([[1.0, 0.0, -k, k * z0], [0.0, 1.0, 0.0, 0.0],
                                     [0.0, 0.0, 1.0, 0.0]]))


def aabb_box(solids: Iterable[m3d.Manifold]) -> m3d.Manifold:
    """One box covering the bounding boxes of `solids` (a placeholder piece)."""
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    for s in solids:
        bb = np.asarray(s.bounding_box(), float)
        lo, hi = np.minimum(lo, bb[:3]), np.maximum(hi, bb[3:])
    return box_between(lo, hi)


def points_box(points: np.ndarray, pad: float) -> m3d.Manifold:
    """The box around `points` (N, 3) grown by `pad` on every side (a placeholder piece)."""
    pts = np.asarray(points, float)
    return box_between(pts.min(axis=0) - pad, pts.max(axis=0) + pad)


def splay_legs(corners: Sequence[tuple[float, float]], z_top: float, r_top: float,
               r_foot: float, splay: float, detail: bool, slot: str, square: bool = False,
               sections: int = 16) -> tuple[list[Part], list[tuple[np.ndarray, np.ndarray]]]:
    """Legs from the (x, y) `corners` under a seat at height z_top down to feet pushed `splay`
    metres further out (radially from the origin). Returns the parts and each leg's
    (foot, top) centre points, for rungs and rings."""
    out, axes = [], []
    for cx, cy in corners:
        d = math.hypot(cx, cy)
        ux, uy = (cx / d, cy / d) if d > 1e-9 else (0.0, 0.0)
        foot = np.array([cx + ux * splay, cy + uy * splay, 0.0])
        top = np.array([cx, cy, z_top])
        out.append(Part(post(foot, top, r_foot, r_top, sections if detail else 8,
                             circumscribed=not detail, square=square), slot))
        axes.append((foot, top))
    return out, axes


def leg_point(axis: tuple[np.ndarray, np.ndarray], z: float) -> np.ndarray:
    """The centre of a leg (foot, top) at height z."""
    foot, top = axis
    t = (z - foot[2]) / (top[2] - foot[2])
    return foot + t * (top - foot)


def seat_surface(name: str, z: float, plan: sg.Polygon) -> Surface:
    """An upward support surface at height z with the (x, y) polygon `plan`."""
    return support_polygon(name, (0.0, 0.0, z), plan)


# ================================================================================ side chair
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

    def parts(self, p, detail):
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
            out += [Part(tube([a, b], r, 10), "wood") for a, b, r in zip(feet, tops, radii)]
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
        path = fillet_path(dedupe_points(path), 0.05, 4)
        out += [Part(s, "wood") for s in ([tube(path, r, 12)] if detail else tube_boxes(path, r, 8))]
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
                    for y, z in zip(ys, zy)]
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

    def extra_surfaces(self, p):
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


# ========================================================================= upholstered chair
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

    def parts(self, p, detail):
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
            out += [Part(soft_sheared(*b[:3], z0, tilt, True, b[3]), "upholstery") for b in back + wings]
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

    def extra_surfaces(self, p):
        sd, sw, sh = p["seat_depth"], p["seat_width"], p["seat_height"]
        m = min(p["corner_radius"], p["seat_thickness"] / 3) + 0.01
        x0, x1 = -sd / 2 + p["back_thickness"] + 0.01, sd / 2 - m
        return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, sw / 2 - m)]


# ============================================================================== office chair
@register
class OfficeChair(PartsFactory):
    """A swivel office chair: five-star base on twin-wheel casters, gas-lift column with a
    shroud, seat mechanism, padded seat, a padded or mesh back on a spine, optional armrests
    and headrest. Everything above the gas spring turns on a revolute `swivel` joint."""

    name = "office_chair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Chair, S.OfficeChair})
    size_class = "large"
    slots = ["plastic", "fabric", "metal"]
    params = {
        "base_radius": Param(0.28, 0.34, doc="distance of the casters from the column (m)"),
        "caster_radius": Param(0.022, 0.032, doc="caster wheel radius (m)"),
        "seat_height": Param(0.42, 0.54, doc="height of the seat's upper face (m)"),
        "seat_width": Param(0.46, 0.54, doc="seat Y extent (m)"),
        "seat_depth": Param(0.44, 0.52, doc="seat X extent (m)"),
        "seat_thickness": Param(0.06, 0.10, doc="seat cushion thickness (m)"),
        "back_height": Param(0.45, 0.68, doc="back panel height (m)"),
        "back_tilt": Param(4.0, 16.0, doc="backwards lean of the back (degrees)"),
        "back_style": Param(kind="choice", choices=("padded", "mesh"),
                            doc="upholstered back or a mesh stretched on a frame"),
        "armrests": Param(kind="bool", doc="add armrests"),
        "headrest": Param(kind="bool", doc="add a headrest above the back"),
    }
    SEAT_X = 0.02  # the seat sits slightly forward of the column (m)

    def _levels(self, p) -> dict[str, float]:
        cr = p["caster_radius"]
        z_tip = 2 * cr + 0.025  # underside of the star's arm tips
        z_hub0 = z_tip + 0.02
        z_hub1 = z_hub0 + 0.045
        z_seat0 = p["seat_height"] - p["seat_thickness"]
        z_mech0 = z_seat0 - 0.045
        z_gas = z_mech0 - 0.045
        return dict(tip=z_tip, hub0=z_hub0, hub1=z_hub1, seat0=z_seat0, mech0=z_mech0, gas=z_gas)

    def _base(self, p, detail) -> list[Part]:
        """Hub, five arms with their casters, gas spring and its shroud (placeholder: a box per
        arm with its caster, one cylinder for spring and shroud)."""
        L = self._levels(p)
        cr, R = p["caster_radius"], p["base_radius"]
        n = 16 if detail else 8
        out = [Part(cylinder(0.05, L["hub1"] + 0.01 - (L["hub0"] - 0.005), (0, 0, L["hub0"] - 0.005),
                             n * 2, circumscribed=not detail), "plastic")]
        for i in range(5):
            th = math.pi + 2 * math.pi * i / 5
            d = np.array([math.cos(th), math.sin(th), 0.0])
            t = np.array([-math.sin(th), math.cos(th), 0.0])
            arm = np.array([d * dist + t * sy * hw + (0, 0, z)
                            for dist, hw, zs in ((0.03, 0.026, (L["hub0"], L["hub1"])),
                                                 (R + 0.02, 0.018, (L["tip"], L["tip"] + 0.03)))
                            for sy in (-1, 1) for z in zs])
            c, sc = d * (R + 0.02), d * R  # wheel centre, swivel stem
            if not detail:  # the box around arm, wheel, hood and stem, from their corners
                pts = [arm]
                for ht, hd, zs in ((cr, 0.0225, (0.0, 2 * cr)), (0.88 * cr, 0.025, (cr, 2 * cr + 0.012))):
                    pts.append([c + a * t + b * d + (0, 0, z) for a in (-ht, ht) for b in (-hd, hd)
                                for z in zs])
                pts.append([sc + (a, b, z) for a in (-0.008, 0.008) for b in (-0.008, 0.008)
                            for z in (2 * cr, L["tip"] + OVERLAP)])
                out.append(Part(points_box(np.vstack(pts), 0.0), "plastic"))
                continue
            # a twin wheel on a radial axle, its hood and a swivel stem
            deg = math.degrees(th)
            wheel = cylinder(cr, 0.045, (0, 0, -0.0225), 16).rotate((90.0, 0.0, 0.0)).rotate(
                (0.0, 0.0, deg + 90.0)).translate((float(c[0]), float(c[1]), cr))
            hood = box((0.05, 1.76 * cr, cr + 0.012), (0, 0, 0)).rotate((0.0, 0.0, deg)).translate(
                (float(c[0]), float(c[1]), 1.5 * cr + 0.006))
            stem = cylinder(0.008, L["tip"] + OVERLAP - 2 * cr, (float(sc[0]), float(sc[1]), 2 * cr), 16)
            out += [Part(m3d.Manifold.hull_points(arm), "plastic"), Part(wheel, "plastic"),
                    Part(hood, "metal"), Part(stem, "metal")]
        zc0 = L["hub1"]
        hs = 0.6 * (L["gas"] - zc0)
        if detail:
            out.append(Part(cylinder(0.028, L["gas"] - zc0 + OVERLAP, (0, 0, zc0 - OVERLAP), 32), "metal"))
            out.append(Part(cylinder(0.042, hs, (0, 0, zc0 - OVERLAP), 32, radius_top=0.034), "plastic"))
        else:
            out.append(Part(cylinder(0.042, L["gas"] - zc0 + OVERLAP, (0, 0, zc0 - OVERLAP), 16,
                                     circumscribed=True), "plastic"))
        return out

    def _seat(self, p, detail) -> list[Part]:
        """Everything on the swivel: piston, mechanism, seat, spine, back, headrest, armrests
        (placeholder: one box for piston and mechanism, one per armrest, one for the headrest)."""
        L = self._levels(p)
        sd, sw, sh, st = p["seat_depth"], p["seat_width"], p["seat_height"], p["seat_thickness"]
        bh, tilt = p["back_height"], p["back_tilt"]
        x0 = self.SEAT_X
        link = "seat"
        seat = ((sd, sw, st), (x0, 0, sh - st / 2), min(0.03, st / 3))
        mech = ((-0.11, -0.1, L["mech0"]), (0.12, 0.1, L["seat0"] + OVERLAP))
        if detail:
            piston = cylinder(0.016, L["mech0"] - L["gas"] - 0.002 + OVERLAP, (0, 0, L["gas"] + 0.002), 16)
            out = [Part(piston, "metal", link),
                   board(*mech, "metal", link), Part(bevel_box(*seat, 2), "fabric", link)]
        else:
            out = [board((-0.11, -0.1, L["gas"] + 0.002), mech[1], "metal", link),
                   Part(box(*seat[:2]), "fabric", link)]
        # spine: under the seat to the back, then up behind the back panel
        xb = x0 - sd / 2  # seat rear
        zs0 = L["seat0"] - 0.04
        out.append(board((xb - 0.065, -0.03, zs0), (-0.08, 0.03, L["seat0"] - 0.01), "metal", link))
        zb0, zb1 = sh + 0.05, sh + 0.05 + bh
        spine = box_between((xb - 0.065, -0.03, zs0), (xb - 0.022, 0.03, zb0 + 0.5 * bh))
        out.append(Part(shear_back(spine, sh, tilt), "metal", link))
        bw, zm = 0.95 * sw, (zb0 + zb1) / 2
        if p["back_style"] == "padded":
            back = soft_sheared((0.06, bw, bh), (xb, 0, zm), 0.025, sh, tilt, detail)
            out.append(Part(back, "fabric", link))
        elif detail:
            ring = frame(bw, bh, 0.03, 0.035, (xb - 0.0125, 0, zm))
            mesh = box((0.008, bw - 0.06 + 2 * OVERLAP, bh - 0.06 + 2 * OVERLAP), (xb - 0.0125, 0, zm))
            out += [Part(shear_back(ring, sh, tilt), "plastic", link),
                    Part(shear_back(mesh, sh, tilt), "fabric", link)]
        else:
            back = shear_back(box((0.035, bw, bh), (xb - 0.0125, 0, zm)), sh, tilt)
            out.append(Part(back, "plastic", link))
        if p["headrest"]:
            post = ((xb - 0.03, -0.02, zb1 - 0.05), (xb - 0.002, 0.02, zb1 + 0.1))
            pad = ((0.06, 0.28, 0.13), (xb - 0.01, 0, zb1 + 0.08 + 0.065 - OVERLAP), 0.025)
            if detail:
                out += [Part(shear_back(box_between(*post), sh, tilt), "metal", link),
                        Part(soft_sheared(*pad, sh, tilt, True), "fabric", link)]
            else:
                corners = np.array([(x, y, z) for x in (post[0][0], post[1][0]) for y in (-0.02, 0.02)
                                    for z in (post[0][2], post[1][2])])
                pts = np.vstack([corners, bevel_points(*pad)])
                out.append(Part(points_box(shear_points(pts, sh, tilt), 0.0), "fabric", link))
        if p["armrests"]:
            za = sh + 0.2
            for s in (-1, 1):
                ya = s * (sw / 2 + 0.02)
                y0, y1 = sorted((s * 0.06, s * (sw / 2 + 0.035)))
                arm = [((-0.07, y0, zs0 + 0.005), (0.01, y1, L["seat0"] - 0.01)),   # bracket
                       ((-0.05, ya - 0.0125, zs0 + 0.005), (-0.01, ya + 0.0125, za + OVERLAP)),  # post
                       ((-0.145, ya - 0.0375, za), (0.105, ya + 0.0375, za + 0.03))]  # pad
                if detail:
                    out += [board(*arm[0], "metal", link), board(*arm[1], "plastic", link),
                            Part(bevel_box((0.25, 0.075, 0.03), (-0.02, ya, za + 0.015), 0.012, 2), "plastic",
                                 link)]
                else:
                    lo, hi = np.min([c[0] for c in arm], axis=0), np.max([c[1] for c in arm], axis=0)
                    out.append(board(lo, hi, "plastic", link))
        return out

    def parts(self, p, detail):
        return self._base(p, detail) + self._seat(p, detail)

    def joints(self, p):
        return [Joint("swivel", "revolute", np.array([0.0, 0.0, 1.0]), np.zeros(3), -math.pi,
                      math.pi, "seat")]

    def extra_surfaces(self, p):
        sd, sw, sh = p["seat_depth"], p["seat_width"], p["seat_height"]
        m = min(0.03, p["seat_thickness"] / 3) + 0.01
        return [support_rect("seat", (self.SEAT_X, 0, sh), sd / 2 - m, sw / 2 - m)]


# ========================================================================== stools and benches
def soft_disc(radius: float, z0: float, z1: float, top_edge: float, bottom_edge: float = 0.0,
              sections: int = 48) -> m3d.Manifold:
    """A disc (cushion, stool top) from z0 to z1 whose top and bottom rims are rounded by
    `top_edge` / `bottom_edge` (m): a lathe, with the exact bounding box of the plain disc."""
    e1 = min(top_edge, 0.49 * (z1 - z0), 0.49 * radius)
    e0 = min(bottom_edge, 0.49 * (z1 - z0), 0.49 * radius)
    prof = [(0.0, z0)]
    if e0 > 1e-4:
        a = np.linspace(-math.pi / 2, 0.0, 5)
        prof += list(zip(radius - e0 + e0 * np.cos(a), z0 + e0 + e0 * np.sin(a)))
    else:
        prof.append((radius, z0))
    if e1 > 1e-4:
        a = np.linspace(0.0, math.pi / 2, 5)
        prof += list(zip(radius - e1 + e1 * np.cos(a), z1 - e1 + e1 * np.sin(a)))
    else:
        prof.append((radius, z1))
    prof.append((0.0, z1))
    return lathe(prof, sections)


def _ring_or_box(major: float, minor: float, z: float, detail: bool) -> m3d.Manifold:
    """A horizontal ring (a footrest) about the Z axis, or its bounding box."""
    if detail:
        return torus(major, minor, (0, 0, z), 48, 8)
    r = major + minor
    return box((2 * r, 2 * r, 2 * minor), (0, 0, z))


@register
class BarStool(PartsFactory):
    """A tall bar / counter stool: a round or square seat (bare or with a leather cushion) on
    three or four splayed legs tied by a footrest ring (or four footrest rungs), or on a
    pedestal with a domed foot and a spoked footrest ring; optional low back."""

    name = "bar_stool"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Stool, S.BarStool})
    size_class = "large"
    slots = ["wood", "metal", "leather"]
    params = {
        "seat_height": Param(0.62, 0.80, doc="height of the seat's upper face (m); counter "
                                             "stools are lower than bar stools"),
        "seat_shape": Param(kind="choice", choices=("round", "square"), doc="seat plan"),
        "seat_size": Param(0.32, 0.42, doc="seat diameter or side (m)"),
        "seat_thickness": Param(0.03, 0.07, doc="seat thickness, cushion included (m)"),
        "padded": Param(kind="bool", doc="a leather cushion on the seat board"),
        "base_style": Param(kind="choice", choices=("legs4", "legs3", "pedestal"),
                            doc="four or three legs, or a central pedestal"),
        "leg_thickness": Param(0.022, 0.04, doc="leg diameter (m); thin legs are steel tube"),
        "leg_splay": Param(0.0, 0.08, doc="how far the feet stand out beyond the leg tops (m)"),
        "footrest_height": Param(0.22, 0.34, doc="height of the footrest (m)"),
        "back": Param(kind="bool", doc="add a low back"),
        "back_height": Param(0.12, 0.28, doc="height of the low back above the seat (m)"),
    }
    TILT = 8.0  # backwards lean of the low back (degrees)

    def _leg_corners(self, p) -> list[tuple[float, float]]:
        R = p["seat_size"] / 2
        if p["base_style"] == "legs4":
            if p["seat_shape"] == "square":
                c = R - 0.04
                return [(sx * c, sy * c) for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
            angles = [45, 135, 225, 315]
        else:
            angles = [60, 180, 300]
        rl = R - 0.045
        return [(rl * math.cos(math.radians(a)), rl * math.sin(math.radians(a))) for a in angles]

    def _seat(self, p, detail) -> list[Part]:
        S, sh, st = p["seat_size"], p["seat_height"], p["seat_thickness"]
        R, z0 = S / 2, sh - st
        round_ = p["seat_shape"] == "round"
        if p["padded"]:
            zb = z0 + 0.45 * st
            pieces = [(z0, zb + OVERLAP, 0.004, "wood"), (zb, sh, min(0.02, 0.45 * (sh - zb)), "leather")]
        else:
            pieces = [(z0, sh, 0.008, "wood")]
        out = []
        for za, zb, e, slot in pieces:
            if not detail:
                solid = (cylinder(R, zb - za, (0, 0, za), 16, circumscribed=True) if round_
                         else box((S, S, zb - za), (0, 0, (za + zb) / 2)))
            elif round_:
                solid = soft_disc(R, za, zb, e, 0.003)
            else:
                solid = bevel_box((S, S, zb - za), (0, 0, (za + zb) / 2), max(e, 0.004), 2)
            out.append(Part(solid, slot))
        return out

    def _base(self, p, detail) -> list[Part]:
        S, sh, st = p["seat_size"], p["seat_height"], p["seat_thickness"]
        z0, fh, lt = sh - st, p["footrest_height"], p["leg_thickness"]
        out: list[Part] = []
        if p["base_style"] == "pedestal":
            rb = max(0.19, 0.5 * S)
            prof = [(0, 0), (rb, 0), (rb, 0.012), (rb * 0.8, 0.022), (0.06, 0.035), (0, 0.035)]
            out.append(Part(lathe(prof, 48) if detail else
                            cylinder(rb, 0.035, (0, 0, 0), 16, circumscribed=True), "metal"))
            out.append(Part(cylinder(0.028, z0 + OVERLAP - 0.03, (0, 0, 0.03), 24 if detail else 8,
                                     circumscribed=not detail), "metal"))
            pr = min(0.11, S / 2 - 0.03)
            out.append(Part(cylinder(pr, 0.015 + OVERLAP, (0, 0, z0 - 0.015), 32 if detail else 8,
                                     circumscribed=not detail), "metal"))
            ring = min(0.17, rb - 0.02)
            out.append(Part(_ring_or_box(ring, 0.01, fh, detail), "metal"))
            for i in range(3):
                a = 2 * math.pi * i / 3
                out.append(Part(rod_between((0, 0, fh), (ring * math.cos(a), ring * math.sin(a), fh),
                                            0.007, detail, 8), "metal"))
            return out
        slot = "metal" if lt < 0.028 else "wood"
        lp, axes = splay_legs(self._leg_corners(p), z0 + OVERLAP, lt / 2, lt * 0.4, p["leg_splay"],
                              detail, slot)
        out += lp
        pts = [leg_point(ax, fh) for ax in axes]
        if p["seat_shape"] == "square" and p["base_style"] == "legs4":
            for i in range(4):
                out.append(Part(rod_between(pts[i], pts[(i + 1) % 4], 0.01, detail, 10), "metal"))
        else:
            out.append(Part(_ring_or_box(float(np.hypot(*pts[0][:2])), 0.01, fh, detail), "metal"))
        return out

    def _back(self, p, detail) -> list[Part]:
        S, sh, st = p["seat_size"], p["seat_height"], p["seat_thickness"]
        R, z0, bh = S / 2, sh - st, p["back_height"]
        k = math.tan(math.radians(self.TILT))
        ztop = sh + bh
        if p["seat_shape"] == "round":
            rb, a0 = R - 0.02, 0.6
            arc = [(rb * math.cos(a) - k * bh, rb * math.sin(a), ztop)
                   for a in np.linspace(math.pi - a0, math.pi + a0, 9)]
            path = ([(rb * math.cos(math.pi - a0), rb * math.sin(math.pi - a0), z0 + 0.005)] + arc
                    + [(rb * math.cos(math.pi + a0), rb * math.sin(math.pi + a0), z0 + 0.005)])
            path = fillet_path(path, 0.04, 4)
            zm = sh + 0.5 * bh
            mid = [(rb * math.cos(a) - k * 0.5 * bh, rb * math.sin(a), zm)
                   for a in np.linspace(math.pi - a0, math.pi + a0, 9)]
            if detail:
                return [Part(tube(path, 0.011, 12), "metal"), Part(tube(mid, 0.008, 10), "metal")]
            return [Part(b, "metal") for b in tube_boxes(path, 0.011, 3)]
        out = []
        yp = R - 0.06
        for s in (-1, 1):
            out.append(Part(rod_between((-R + 0.03, s * yp, z0 + 0.005),
                                        (-R + 0.03 - k * bh, s * yp, ztop),
                                        0.011, detail, 12), "metal"))
        bh2 = min(0.1, 0.5 * bh)
        out.append(Part(soft_sheared((0.025, S - 0.06, bh2), (-R + 0.03, 0, ztop - bh2 / 2), 0.008, sh,
                                     self.TILT, detail), "wood"))
        return out

    def parts(self, p, detail):
        out = self._seat(p, detail) + self._base(p, detail)
        if p["back"]:
            out += self._back(p, detail)
        return out

    def extra_surfaces(self, p):
        S, sh = p["seat_size"], p["seat_height"]
        R = S / 2
        if p["seat_shape"] == "round":
            plan = circle_polygon(R - 0.03, 48)
            x_back = -0.83 * (R - 0.02) + 0.025
        else:
            plan = rounded_rect_polygon(S, S, 0.01, 0.025)
            x_back = -R + 0.06
        if p["back"]:
            plan = plan.intersection(sg.box(x_back, -R, R, R))
        return [seat_surface("seat", sh, plan)]


@register
class Stool(PartsFactory):
    """A low stool family: a legged wooden stool (round or square top, 3-4 splayed legs,
    optional rungs and padded top), an upholstered ottoman on small feet (optionally button
    tufted), or a soft pouf (a bulging drum or a soft cube)."""

    name = "stool"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Stool})
    size_class = "large"
    slots = ["wood", "upholstery", "metal"]
    params = {
        "style": Param(kind="choice", choices=("legged", "ottoman", "pouf"), doc="stool family"),
        "shape": Param(kind="choice", choices=("round", "square"), doc="plan shape"),
        "height": Param(0.36, 0.48, doc="height of the top (m)"),
        "size": Param(0.32, 0.60, doc="diameter or side (m)"),
        "seat_thickness": Param(0.025, 0.06, doc="top board thickness of a legged stool (m)"),
        "n_legs": Param(3, 4, kind="int", doc="legs of a legged stool or feet of an ottoman"),
        "leg_thickness": Param(0.025, 0.045, doc="leg / foot diameter (m)"),
        "leg_splay": Param(0.0, 0.06, doc="how far a legged stool's feet stand out (m)"),
        "corner_radius": Param(0.005, 0.05, doc="rounding of the top's / upholstery's edges (m)"),
        "tufted": Param(kind="bool", doc="button tufting (ottoman, pouf) or a padded top "
                                         "(legged stool)"),
        "stretchers": Param(kind="bool", doc="rungs between a legged stool's legs"),
    }
    FEET = 0.06  # ottoman feet height (m)
    PAD = 0.04   # padded top thickness of a legged stool (m)

    def _buttons(self, p) -> list[tuple[float, float]]:
        if not p["tufted"] or p["style"] == "legged":
            return []
        S = p["size"]
        if p["style"] == "pouf":
            return [(0.0, 0.0)]
        if p["shape"] == "round":
            ring = [(0.25 * S * math.cos(a),
                     0.25 * S * math.sin(a)) for a in np.arange(5) * 2 * math.pi / 5]
            return [(0.0, 0.0)] + ring
        q = S / 4
        grid = [(sx * q, sy * q) for sx in (-1, 1) for sy in (-1, 1)]
        return grid + ([(0.0, 0.0)] if S > 0.45 else [])

    def _soft(self, p, z0, z1, edge, bottom_edge, slot, detail) -> Part:
        S = p["size"]
        if not detail:
            return Part(cylinder(S / 2, z1 - z0, (0, 0, z0), 16, circumscribed=True)
                        if p["shape"] == "round" else box((S, S, z1 - z0), (0, 0, (z0 + z1) / 2)), slot)
        if p["shape"] == "round":
            return Part(soft_disc(S / 2, z0, z1, edge, bottom_edge), slot)
        return Part(bevel_box((S, S, z1 - z0), (0, 0, (z0 + z1) / 2), max(edge, 0.003), 2), slot)

    def parts(self, p, detail):
        style, S, h = p["style"], p["size"], p["height"]
        cr, lt = p["corner_radius"], p["leg_thickness"]
        R = S / 2
        out: list[Part] = []
        if style == "legged":
            st = p["seat_thickness"]
            ztop = h - (self.PAD if p["tufted"] else 0.0)
            out.append(self._soft(p, ztop - st, ztop + (OVERLAP if p["tufted"] else 0.0),
                                  min(cr, st / 2), 0.002, "wood", detail))
            if p["tufted"]:
                out.append(self._soft(p, ztop, h, min(0.02, cr + 0.01), 0.005, "upholstery", detail))
            n = int(p["n_legs"])
            if p["shape"] == "square" and n == 4:
                c = R - 0.035 - lt / 2
                corners = [(sx * c, sy * c) for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1))]
            else:
                rl = R - 0.035 - lt / 2
                corners = [(rl * math.cos(a), rl * math.sin(a))
                           for a in (np.arange(n) * 2 * math.pi / n + math.pi / n)]
            lp, axes = splay_legs(corners, ztop - st + OVERLAP, lt / 2, lt * 0.35, p["leg_splay"],
                                  detail, "wood")
            out += lp
            if p["stretchers"]:
                pts = [leg_point(ax, 0.35 * h) for ax in axes]
                for i in range(n):
                    out.append(Part(rod_between(pts[i], pts[(i + 1) % n], lt * 0.3, detail, 10), "wood"))
        elif style == "ottoman":
            out.append(self._soft(p, self.FEET, h, cr, cr, "upholstery", detail))
            n = 4 if p["shape"] == "square" else int(p["n_legs"])
            rl = (R - 0.03 - lt / 2) if p["shape"] == "round" else (R - 0.03 - lt / 2) * math.sqrt(2)
            for i in range(n):
                a = 2 * math.pi * i / n + math.pi / 4
                out.append(Part(cylinder(lt / 2, self.FEET + 0.01,
                                         (rl * math.cos(a), rl * math.sin(a), 0.0),
                                         16 if detail else 8, radius_top=lt / 2 * (1.0 if detail else 1.0),
                                         circumscribed=not detail), "wood"))
        else:  # pouf
            if p["shape"] == "round":
                t = np.linspace(0.0, math.pi, 17)
                prof = [(0.0, 0.0)] + list(zip(R * (0.8 + 0.2 * np.sin(t)),
                                               h * (1 - np.cos(t)) / 2)) + [(0.0, h)]
                out.append(Part(lathe(prof, 48) if detail else
                                cylinder(R, h, (0, 0, 0), 16, circumscribed=True), "upholstery"))
            else:
                out.append(Part(bevel_box((S, S, h), (0, 0, h / 2), self._pouf_round(p), 3) if detail
                                else box((S, S, h), (0, 0, h / 2)), "upholstery"))
        for bx, by in self._buttons(p):
            out.append(Part(cylinder(0.012, 0.008, (bx, by, h - 0.004), 12 if detail else 8,
                                     circumscribed=not detail), "upholstery"))
        return out

    def _pouf_round(self, p) -> float:
        return min(0.3 * min(p["size"], p["height"]), 2 * p["corner_radius"] + 0.03)

    def extra_surfaces(self, p):
        style, S, h, cr = p["style"], p["size"], p["height"], p["corner_radius"]
        R = S / 2
        if style == "pouf":
            m = 0.2 * R + 0.03 if p["shape"] == "round" else self._pouf_round(p) + 0.01
        elif style == "ottoman":
            m = cr + 0.01
        else:
            m = (min(0.02, cr + 0.01) if p["tufted"] else min(cr, p["seat_thickness"] / 2)) + 0.01
        plan = (circle_polygon(R - m, 48) if p["shape"] == "round"
                else rounded_rect_polygon(S, S, 0.001, m))
        for bx, by in self._buttons(p):
            plan = plan.difference(sg.Point(bx, by).buffer(0.02, 8))
        return [seat_surface("seat", h, plan)]


# ====================================================================== L-shaped sectional sofa
@register
class SofaLShaped(PartsFactory):
    """An L-shaped sectional sofa: a main section with a back along -X and an arm at one end,
    and a chaise longue reaching forward (+X) at the other end (on the sitter's left or right).
    Seat cushions (2-3 on the main section, one long chaise cushion) and back cushions on a
    base on short legs or a plinth. Each seat cushion's top is a support surface (`seat_i`,
    `chaise`)."""

    name = "sofa_l_shaped"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Sofa, S.SectionalSofa})
    size_class = "large"
    slots = ["upholstery", "fabric", "wood"]
    params = {
        "width": Param(2.2, 3.2, doc="overall Y extent (m)"),
        "depth": Param(0.85, 1.0, doc="X extent of the main section, back included (m)"),
        "chaise_length": Param(1.45, 1.8, doc="overall X extent along the chaise (m)"),
        "chaise_width": Param(0.7, 0.95, doc="Y extent of the chaise (m)"),
        "chaise_side": Param(kind="choice", choices=("left", "right"),
                             doc="the chaise on the sitter's left (+Y) or right (-Y)"),
        "height": Param(0.75, 0.9, doc="height of the back's top (m)"),
        "seat_height": Param(0.40, 0.46, doc="height of the seat cushions' upper face (m)"),
        "cushion_thickness": Param(0.10, 0.16, doc="seat cushion thickness (m)"),
        "arm_width": Param(0.1, 0.25, doc="Y extent of the arm (m)"),
        "arm_height": Param(0.55, 0.68, doc="height of the arm's top (m)"),
        "back_thickness": Param(0.15, 0.25, doc="X extent of the back (m)"),
        "corner_radius": Param(0.01, 0.04, doc="rounding of the upholstery (m)"),
        "n_cushions": Param(2, 3, kind="int", doc="seat cushions on the main section"),
        "base_style": Param(kind="choice", choices=("legs", "plinth"),
                            doc="on short legs or sitting on a plinth"),
        "leg_height": Param(0.05, 0.15, doc="leg height when on legs (m)"),
    }

    def _geom(self, p) -> dict[str, Any]:
        """Key coordinates, for the chaise on +Y (mirrored in y for a right chaise)."""
        W, D, L = p["width"], p["depth"], p["chaise_length"]
        cw, aw, bt = p["chaise_width"], p["arm_width"], p["back_thickness"]
        ct, sh = p["cushion_thickness"], p["seat_height"]
        lh = p["leg_height"] if p["base_style"] == "legs" else 0.0
        bct = min(0.14, (D - bt) * 0.25)
        r = min(p["corner_radius"], ct / 3)
        n = int(p["n_cushions"])
        y_in0, y_in1 = -W / 2 + aw, W / 2 - cw  # main cushions span
        return dict(W=W, D=D, L=L, cw=cw, aw=aw, bt=bt, ct=ct, sh=sh, lh=lh, bct=bct, r=r, n=n,
                    x0=-L / 2, xd=-L / 2 + D, zb=sh - ct, y_in0=y_in0, y_in1=y_in1,
                    s=1.0 if p["chaise_side"] == "left" else -1.0)

    def parts(self, p, detail):
        g = self._geom(p)
        s, cr = g["s"], p["corner_radius"]
        x0, xd, L, W = g["x0"], g["xd"], g["L"], g["W"]
        lh, zb, sh, H = g["lh"], g["zb"], g["sh"], p["height"]

        def soft(lo, hi, rad, slot):
            lo, hi = np.array(lo, float), np.array(hi, float)
            lo[1], hi[1] = sorted((s * lo[1], s * hi[1]))
            if detail:
                return Part(bevel_box(hi - lo, (lo + hi) / 2, rad, 2), slot)
            return board(lo, hi, slot)

        out = [
            soft((x0, g["y_in0"] - OVERLAP, lh), (xd, g["y_in1"] + OVERLAP, zb), 0.005, "upholstery"),
            soft((x0, g["y_in1"], lh), (L / 2, W / 2, zb), 0.005, "upholstery"),
            soft((x0, -W / 2, lh), (xd, -W / 2 + g["aw"], p["arm_height"]),
                 min(g["aw"] / 2 - 0.002, 0.06), "upholstery"),
            soft((x0, g["y_in0"] - OVERLAP, lh), (x0 + g["bt"], W / 2, H), cr, "upholstery"),
        ]
        for y0, y1 in self._cushion_spans(g):
            out.append(soft((x0 + g["bt"] - OVERLAP, y0, zb - OVERLAP), (xd, y1, sh), g["r"], "fabric"))
        out.append(soft((x0 + g["bt"] - OVERLAP, g["y_in1"] - OVERLAP, zb - OVERLAP), (L / 2, W / 2, sh),
                        g["r"], "fabric"))
        zb1 = min(H - 0.03, sh + 0.45)
        if zb1 - sh > 0.1:
            spans = self._cushion_spans(g) + [(g["y_in1"] - OVERLAP, W / 2)]
            for y0, y1 in spans:
                out.append(soft((x0 + g["bt"] - OVERLAP, y0, sh - OVERLAP),
                                (x0 + g["bt"] + g["bct"], y1, zb1), min(cr, g["bct"] / 3), "fabric"))
        if lh > 0:
            i, lt = 0.03, 0.05
            spots = [(x0 + i, -W / 2 + i), (xd - i, -W / 2 + i), (x0 + i, W / 2 - i),
                     (L / 2 - i, W / 2 - i), (L / 2 - i, g["y_in1"] + i), (xd - i, g["y_in1"] + i)]
            for x, y in spots:
                cx = x + (lt / 2 if x < 0 else -lt / 2)
                cy = s * (y + (lt / 2 if y < 0 else -lt / 2))
                # 2 cm into the base: its bevelled (faceted) underside rises near the corners
                out.append(Part(cylinder(lt / 2 * (0.7 if detail else 1.0), lh + 0.02, (cx, cy, 0.0),
                                         16 if detail else 8, radius_top=lt / 2,
                                         circumscribed=not detail), "wood"))
        else:
            out.append(soft((x0, -W / 2, 0.0), (xd, W / 2 - g["cw"], 0.04), 0.003, "upholstery"))
            out.append(soft((x0, W / 2 - g["cw"] - OVERLAP, 0.0), (L / 2, W / 2, 0.04), 0.003,
                            "upholstery"))
        return out

    def _cushion_spans(self, g) -> list[tuple[float, float]]:
        n, y0, y1 = g["n"], g["y_in0"], g["y_in1"]
        w = (y1 - y0) / n
        return [(y0 + i * w - OVERLAP, y0 + (i + 1) * w + OVERLAP) for i in range(n)]

    def extra_surfaces(self, p):
        g = self._geom(p)
        s, m = g["s"], g["r"] + 0.01
        xs0 = g["x0"] + g["bt"] + g["bct"] + 0.01
        out = []
        for i, (y0, y1) in enumerate(self._cushion_spans(g)):
            x1 = g["xd"] - m
            yc = s * (y0 + y1) / 2
            out.append(support_rect(f"seat_{i}", ((xs0 + x1) / 2, yc, g["sh"]), (x1 - xs0) / 2,
                                    (y1 - y0) / 2 - m))
        x1 = g["L"] / 2 - m
        y0, y1 = g["y_in1"], g["W"] / 2
        out.append(support_rect("chaise", ((xs0 + x1) / 2, s * (y0 + y1) / 2, g["sh"]), (x1 - xs0) / 2,
                                (y1 - y0) / 2 - m))
        return out


# ==================================================================================== benches
@register
class Bench(PartsFactory):
    """A bench: a slatted, solid-board or upholstered seat on four legs, two slab ends or two
    steel frames, optionally with a stretcher and a leaning back (slats, a board or a padded
    back on two posts). Its seat is a support surface (`seat`, or `seat_i` per slat)."""

    name = "bench"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Bench})
    size_class = "large"
    slots = ["wood", "upholstery", "metal"]
    params = {
        "length": Param(0.9, 1.8, doc="Y extent of the seat (m)"),
        "depth": Param(0.32, 0.45, doc="X extent of the seat (m)"),
        "seat_height": Param(0.42, 0.48, doc="height of the seat's upper face (m)"),
        "top_thickness": Param(0.03, 0.06, doc="seat board / slat assembly thickness (m)"),
        "style": Param(kind="choice", choices=("slatted", "solid", "upholstered"), doc="seat kind"),
        "base_style": Param(kind="choice", choices=("legs", "panel", "frame"),
                            doc="four legs, two slab ends or two rectangular steel frames"),
        "leg_thickness": Param(0.035, 0.06, doc="leg / slab-end / frame member thickness (m)"),
        "n_slats": Param(3, 7, kind="int", doc="seat slats of a slatted bench"),
        "stretcher": Param(kind="bool", doc="a rail along the bench between its ends"),
        "back": Param(kind="bool", doc="add a back on two posts"),
        "back_height": Param(0.30, 0.45, doc="height of the back's top above the seat (m)"),
    }
    TILT = 10.0   # backwards lean of the back (degrees)
    CUSHION = 0.06  # upholstered cushion thickness (m)
    GAP = 0.008   # gap between seat slats (m)
    END = 0.06    # distance of the ends (legs, slabs, frames, back posts) from the seat's ends (m)

    def _z_under(self, p) -> float:
        tt = p["top_thickness"]
        if p["style"] == "upholstered":
            return p["seat_height"] - self.CUSHION - 0.5 * tt
        return p["seat_height"] - tt

    def _slats(self, p) -> list[tuple[float, float]]:
        d, n = p["depth"], int(p["n_slats"])
        w = (d - (n - 1) * self.GAP) / n
        return [(-d / 2 + i * (w + self.GAP), -d / 2 + i * (w + self.GAP) + w) for i in range(n)]

    def _seat(self, p, detail) -> list[Part]:
        d, L, sh, tt = p["depth"], p["length"], p["seat_height"], p["top_thickness"]
        style = p["style"]

        def soft(lo, hi, r, slot):
            lo, hi = np.asarray(lo, float), np.asarray(hi, float)
            return Part(bevel_box(hi - lo, (lo + hi) / 2, r, 2) if detail else box_between(lo, hi), slot)

        if style == "solid":
            return [soft((-d / 2, -L / 2, sh - tt), (d / 2, L / 2, sh), 0.004, "wood")]
        if style == "upholstered":
            zc = sh - self.CUSHION
            return [soft((-d / 2, -L / 2, zc - 0.5 * tt), (d / 2, L / 2, zc + OVERLAP), 0.003, "wood"),
                    soft((-d / 2, -L / 2, zc), (d / 2, L / 2, sh), 0.02, "upholstery")]
        zs = sh - 0.65 * tt
        out = []
        if detail:
            out += [soft((x0, -L / 2, zs), (x1, L / 2, sh), 0.003, "wood") for x0, x1 in self._slats(p)]
        else:
            out.append(board((-d / 2, -L / 2, zs), (d / 2, L / 2, sh), "wood"))
        yb = L / 2 - self.END - p["leg_thickness"] / 2
        for y in (-yb, 0.0, yb):  # battens under the slats
            out.append(board((-d / 2 + 0.01, y - 0.02, sh - tt), (d / 2 - 0.01, y + 0.02, zs + OVERLAP),
                              "wood"))
        return out

    def _base(self, p, detail) -> list[Part]:
        d, L, lt = p["depth"], p["length"], p["leg_thickness"]
        zu = self._z_under(p) + OVERLAP
        base = p["base_style"]
        out: list[Part] = []
        yb = L / 2 - self.END - lt / 2  # centre lines of the ends
        if base == "legs":
            for leg in legs((d, 2 * (yb + lt / 2)), 0.02, lt, 0.0, zu, taper=0.7 if detail else 1.0):
                out.append(Part(leg, "wood"))
        elif base == "panel":
            for s in (-1, 1):
                out.append(board((-d / 2 + 0.02, s * yb - lt / 2, 0.0),
                                  (d / 2 - 0.02, s * yb + lt / 2, zu), "wood"))
        else:
            m = 0.03  # frame member section along X
            for s in (-1, 1):
                y0, y1 = s * yb - lt / 2, s * yb + lt / 2
                xs = (-d / 2 + 0.02, d / 2 - 0.02)
                bars = [box_between((xs[0], y0, 0.0), (xs[0] + m, y1, zu)),
                        box_between((xs[1] - m, y0, 0.0), (xs[1], y1, zu)),
                        box_between((xs[0], y0, 0.0), (xs[1], y1, m)),
                        box_between((xs[0], y0, zu - m), (xs[1], y1, zu))]
                if p["stretcher"]:  # a cross bar the stretcher is welded to
                    bars.append(box_between((xs[0], y0, 0.135), (xs[1], y1, 0.165)))
                out += [Part(b, "metal") for b in (bars if detail else [aabb_box(bars)])]
        if p["stretcher"]:
            zs = 0.15
            if base == "legs":
                cx = d / 2 - 0.02 - lt / 2
                for sx in (-1, 1):
                    out.append(board((sx * cx - 0.01, -yb, zs - 0.02), (sx * cx + 0.01, yb, zs + 0.02),
                                      "wood"))
            else:
                out.append(board((-0.015, -yb, zs - 0.03), (0.015, yb, zs + 0.03),
                                  "metal" if base == "frame" else "wood"))
        return out

    def _back(self, p, detail) -> list[Part]:
        d, L, sh, lt = p["depth"], p["length"], p["seat_height"], p["leg_thickness"]
        zt = sh + p["back_height"]
        zu = self._z_under(p)
        yb = L / 2 - self.END - lt / 2
        xp0, xp1 = -d / 2, -d / 2 + 0.04
        posts = [box_between((xp0, s * yb - 0.02, zu), (xp1, s * yb + 0.02, zt)) for s in (-1, 1)]
        out = [Part(shear_back(b, sh, self.TILT), "wood") for b in posts]
        x0, x1 = xp1 - OVERLAP, xp1 + 0.02
        z0 = sh + 0.08
        style = p["style"]
        if style == "upholstered":
            out.append(Part(soft_sheared((0.06, 2 * yb + 0.04, zt - z0), (xp1 + 0.02, 0, (z0 + zt) / 2),
                                         0.02,
                                         sh, self.TILT, detail), "upholstery"))
        elif style == "solid" or not detail:
            out.append(Part(shear_back(box_between((x0, -yb, z0), (x1, yb, zt)), sh, self.TILT), "wood"))
        else:
            n = 3
            h = (zt - z0 - (n - 1) * 0.02) / n
            for i in range(n):
                za = z0 + i * (h + 0.02)
                out.append(Part(shear_back(box_between((x0, -yb, za), (x1, yb, za + h)), sh, self.TILT),
                                "wood"))
        return out

    def parts(self, p, detail):
        out = self._seat(p, detail) + self._base(p, detail)
        if p["back"]:
            out += self._back(p, detail)
        return out

    def extra_surfaces(self, p):
        d, L, sh = p["depth"], p["length"], p["seat_height"]
        x_back = -d / 2 + 0.08 if p["back"] else -d / 2
        if p["style"] != "slatted":
            m = 0.03 if p["style"] == "upholstered" else 0.01
            x0, x1 = max(x_back, -d / 2 + m), d / 2 - m
            return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, L / 2 - m)]
        out = []
        for x0, x1 in self._slats(p):
            x0, x1 = max(x0 + 0.005, x_back), x1 - 0.005
            if x1 - x0 > 0.02:
                out.append(support_rect(f"seat_{len(out)}", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2,
                                        L / 2 - 0.01))
        return out
