"""Stools and benches: bar and counter stools, low stools, ottomans and poufs, and benches with
an optional back. Front (+X) is where one sits from."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.seating._parts import (
    aabb_box,
    leg_point,
    seat_surface,
    shear_back,
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
    circle_polygon,
    cylinder,
    lathe,
    rounded_rect_polygon,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.assets.shapes.sweeps import fillet_path, rod_between, tube, tube_boxes
from indoorgen.model.tags import Semantics as S


def soft_disc(radius: float, z0: float, z1: float, top_edge: float, bottom_edge: float = 0.0,
              sections: int = 48) -> m3d.Manifold:
    """A disc (cushion, stool top) from z0 to z1 whose top and bottom rims are rounded by
    `top_edge` / `bottom_edge` (m): a lathe, with the exact bounding box of the plain disc."""
    e1 = min(top_edge, 0.49 * (z1 - z0), 0.49 * radius)
    e0 = min(bottom_edge, 0.49 * (z1 - z0), 0.49 * radius)
    prof = [(0.0, z0)]
    if e0 > 1e-4:
        a = np.linspace(-math.pi / 2, 0.0, 5)
        prof += list(zip(radius - e0 + e0 * np.cos(a), z0 + e0 + e0 * np.sin(a), strict=True))
    else:
        prof.append((radius, z0))
    if e1 > 1e-4:
        a = np.linspace(0.0, math.pi / 2, 5)
        prof += list(zip(radius - e1 + e1 * np.cos(a), z1 - e1 + e1 * np.sin(a), strict=True))
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


class _SeatBaseBack(PartsFactory):
    """A seat on a base with an optional back (the `back` param); subclasses build each piece."""

    def _seat(self, p: dict[str, Any], detail: bool) -> list[Part]:
        raise NotImplementedError

    def _base(self, p: dict[str, Any], detail: bool) -> list[Part]:
        raise NotImplementedError

    def _back(self, p: dict[str, Any], detail: bool) -> list[Part]:
        raise NotImplementedError

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Seat, base and (with `back`) the back."""
        out = self._seat(p, detail) + self._base(p, detail)
        if p["back"]:
            out += self._back(p, detail)
        return out


@register
class BarStool(_SeatBaseBack):
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
            bent = fillet_path(path, 0.04, 4)
            zm = sh + 0.5 * bh
            mid = [(rb * math.cos(a) - k * 0.5 * bh, rb * math.sin(a), zm)
                   for a in np.linspace(math.pi - a0, math.pi + a0, 9)]
            if detail:
                return [Part(tube(bent, 0.011, 12), "metal"), Part(tube(mid, 0.008, 10), "metal")]
            return [Part(b, "metal") for b in tube_boxes(bent, 0.011, 3)]
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The seat's plan, in front of the back if there is one."""
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """A legged stool, an ottoman on feet or a pouf, with any tufting buttons."""
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
                                               h * (1 - np.cos(t)) / 2, strict=True)) + [(0.0, h)]
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The top inset from its rounded edge, minus the tufting buttons."""
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


@register
class Bench(_SeatBaseBack):
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The seat (`seat`), or each slat's top (`seat_i`), in front of any back."""
        d, L, sh = p["depth"], p["length"], p["seat_height"]
        x_back = -d / 2 + 0.08 if p["back"] else -d / 2
        if p["style"] != "slatted":
            m = 0.03 if p["style"] == "upholstered" else 0.01
            x0, x1 = max(x_back, -d / 2 + m), d / 2 - m
            return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, L / 2 - m)]
        out: list[Surface] = []
        for x0, x1 in self._slats(p):
            x0, x1 = max(x0 + 0.005, x_back), x1 - 0.005
            if x1 - x0 > 0.02:
                out.append(support_rect(f"seat_{len(out)}", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2,
                                        L / 2 - 0.01))
        return out
