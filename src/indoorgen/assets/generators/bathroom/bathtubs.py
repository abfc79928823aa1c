"""Bathtubs: built-in alcove tubs, freestanding tubs and corner tubs.

Fronts face +X; a tub against a wall has its back at -X (a corner tub: walls at -X and +Y).
Tubs are real hollows (manifold3d subtraction), open at the top.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.bathroom._parts import (
    FIXTURE_MATERIALS,
    corner_outline,
    drain_disc,
    ellipse,
    faucet,
    hollow,
    hull_stack,
    outline_polygon,
    polygon_pieces,
    prim_bounds,
    prim_solid,
    rounded_rect,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


class _BuiltInTub(PartsFactory):
    """What the built-in tubs (alcove, corner) declare alike: a large porcelain fixture with
    metal fittings, standing on its whole bottom."""

    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True


@register
class BathtubAlcove(_BuiltInTub):
    """A built-in rectangular bathtub for a three-wall alcove: a block with a flat rim and a
    tiled-in back, its front an apron (flat, with a recessed toe kick, or panelled); the
    hollow tapers to a flat floor with a sloped backrest at one end and the drain and overflow
    at the other. Rim: support surface; floor of the hollow: interior surface."""

    name = "bathtub_alcove"
    params = {
        "length": Param(1.4, 1.8, doc="Y extent, along the back wall (m)"),
        "width": Param(0.7, 0.85, doc="X extent, wall to apron (m)"),
        "height": Param(0.45, 0.6, doc="rim height (m)"),
        "rim_width": Param(0.05, 0.12, doc="width of the rim along the sides (m)"),
        "basin_depth": Param(0.3, 0.45, doc="depth of the hollow below the rim (m)"),
        "drain_end": Param(kind="choice", choices=("left", "right"), doc="end with drain (+Y / -Y)"),
        "backrest_slope": Param(0.05, 0.3, doc="how far the backrest end leans back (m)"),
        "corner_radius": Param(0.04, 0.2, doc="corner rounding of the hollow's opening (m)"),
        "apron_style": Param(kind="choice", choices=("flat", "kick", "panelled"),
                             doc="plain apron, recessed toe kick, or raised panel moulding"),
    }

    def _g(self, p) -> dict[str, Any]:
        L, D, H = p["length"], p["width"], p["height"]
        rim = p["rim_width"]
        depth = min(p["basin_depth"], H - 0.1)
        s = 1.0 if p["drain_end"] == "left" else -1.0
        l_in, w_in = L - 2 * rim - 0.04, D - 2 * rim
        slope = p["backrest_slope"]
        # the floor: narrower than the opening, pushed towards the drain end
        yb0, yb1 = -l_in / 2 + slope + 0.06, l_in / 2 - 0.06
        return dict(L=L, D=D, H=H, rim=rim, depth=depth, s=s, l_in=l_in, w_in=w_in,
                    z_f=H - depth, fy=s * (yb0 + yb1) / 2, fl=yb1 - yb0, fw=w_in - 0.14)

    def _cavity(self, p, g) -> list[tuple[float, m3d.CrossSection]]:
        r = p["corner_radius"]
        top = rounded_rect(g["w_in"], g["l_in"], r)
        rb = 0.05
        return [(g["H"] + 0.05, top), (g["H"], top),
                (g["z_f"] + rb, rounded_rect(g["fw"] + 0.06, g["fl"] + 0.06, 0.08, (0.0, g["fy"]))),
                (g["z_f"], rounded_rect(g["fw"], g["fl"], 0.06, (0.0, g["fy"])))]

    def _drain_y(self, g) -> float:
        return g["s"] * (g["l_in"] / 2 - 0.06 - 0.1)

    def parts(self, p, detail):
        """The alcove tub's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        L, D, H = g["L"], g["D"], g["H"]
        front = D / 2 + (0.01 if p["apron_style"] == "panelled" else 0.0)
        if not detail:
            return [Part(box_between((-D / 2, -L / 2, 0.0), (front, L / 2, H)), "porcelain")]
        if p["apron_style"] == "kick":
            outer = (box_between((-D / 2, -L / 2, 0.07), (D / 2, L / 2, H))
                     + box_between((-D / 2, -L / 2, 0.0), (D / 2 - 0.05, L / 2, 0.07 + OVERLAP)))
        else:
            outer = box_between((-D / 2, -L / 2, 0.0), (D / 2, L / 2, H))
        if p["apron_style"] == "panelled":
            border = 0.05
            outer = outer + (box_between((D / 2 - OVERLAP, -L / 2 + 0.04, 0.05),
                                         (front, L / 2 - 0.04, H - 0.05))
                             - box_between((D / 2, -L / 2 + 0.04 + border, 0.05 + border),
                                           (front + 0.01, L / 2 - 0.04 - border, H - 0.05 - border)))
        out = [Part(hollow(outer, self._cavity(p, g)), "porcelain")]
        dy = self._drain_y(g)
        out.append(Part(drain_disc(0.0, dy, g["z_f"]), "metal"))
        # overflow cover on the drain end wall, 10 cm under the rim
        zo = H - 0.1
        t = (H - zo) / (H - g["z_f"] - 0.05)
        y_wall = g["s"] * ((1 - t) * g["l_in"] / 2 + t * (abs(g["fy"]) + g["fl"] / 2 + 0.03))
        out.append(Part(rod((0.0, y_wall + g["s"] * 0.03, zo), (0.0, y_wall - g["s"] * 0.008, zo),
                            0.03, 24), "metal"))
        return out

    def extra_surfaces(self, p):
        """The alcove tub's surfaces besides its bounding box's: rim, basin, bottom."""
        g = self._g(p)
        L, D = g["L"], g["D"]
        cav = self._cavity(p, g)
        rim = sg.box(-D / 2 + 0.005, -L / 2 + 0.005, D / 2 - 0.005, L / 2 - 0.005).difference(
            outline_polygon(cav[1][1]).buffer(0.005))
        drain = sg.Point(0.0, self._drain_y(g)).buffer(0.04, 16)
        floor = outline_polygon(cav[-1][1], 0.005).difference(drain)
        out = [support_polygon("rim", (0, 0, g["H"]), rim),
               support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        if p["apron_style"] == "kick":
            out.append(Surface.rect("bottom", Subpart.Bottom, (-0.025, 0, 0), (0, 0, -1), (1, 0, 0),
                                    D / 2 - 0.025, L / 2))
        return out


TUB_SHAPES = ("oval", "slipper", "double_slipper", "rounded_rect")


@register
class BathtubFreestanding(PartsFactory):
    """A freestanding bathtub: an oval or rounded-rectangular shell whose sides flare out from
    a smaller bottom, with a plain or rolled rim, or a slipper (one end raised) or double
    slipper (both ends raised) rim; standing flush on the floor, on a plinth or on four claw
    feet. The floor of the hollow is an interior surface."""

    name = "bathtub_freestanding"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {"porcelain": {"porcelain": 3.0, "glazed_ceramic": 1.0, "marble": 0.5,
                                      "concrete": 0.3},
                        "metal": {"chrome": 2.0, "brass": 2.0, "brushed_steel": 1.0,
                                  "painted_metal": 1.0}}
    params = {
        "shape": Param(kind="choice", choices=TUB_SHAPES, doc="plan shape and rim profile"),
        "length": Param(1.5, 1.8, doc="Y extent at the rim (m)"),
        "width": Param(0.7, 0.85, doc="X extent at the rim (m)"),
        "height": Param(0.55, 0.68, doc="height of the (lowest) rim (m)"),
        "end_rise": Param(0.08, 0.2, doc="how far slipper ends rise above the rim (m)"),
        "wall_thickness": Param(0.02, 0.05, doc="shell thickness (m)"),
        "flare": Param(0.72, 0.9, doc="bottom size / rim size"),
        "base": Param(kind="choice", choices=("flush", "plinth", "feet"), doc="what it stands on"),
        "base_height": Param(0.05, 0.15, doc="plinth or feet height (m)"),
        "rolled_rim": Param(kind="bool", doc="a rolled bead around a level rim"),
    }

    def bottom_is_solid(self, params):
        """Whether the tub stands on its whole bottom (flush or on a plinth), not on feet."""
        return self.resolve(params)["base"] != "feet"

    def _g(self, p) -> dict[str, Any]:
        A, B = p["width"] / 2, p["length"] / 2
        slipper = p["shape"] in ("slipper", "double_slipper")
        zb = 0.0 if p["base"] == "flush" else p["base_height"]
        H = p["height"]
        top = H + (p["end_rise"] if slipper else 0.0)
        t = p["wall_thickness"]

        def sec(s: float) -> m3d.CrossSection:
            if p["shape"] == "rounded_rect":
                return rounded_rect(2 * A * s, 2 * B * s, 0.5 * A * s)
            return ellipse(A * s, B * s, (0.0, 0.0), 64)

        return dict(A=A, B=B, H=H, top=top, zb=zb, t=t, sec=sec, slipper=slipper,
                    rolled=p["rolled_rim"] and not slipper, z_f=zb + t + 0.005)

    def _size(self, p, g, z: float) -> float:
        """Section scale at height z: flaring from `flare` at the bottom to 1 at the rim height
        (a slipper's raised ends rise straight above it, so the plan size is the rim's)."""
        u = min(max((z - g["zb"]) / (g["H"] - g["zb"]), 0.0), 1.0)
        return p["flare"] + (1.0 - p["flare"]) * (1.0 - (1.0 - u) ** 2)

    def _floor(self, p, g) -> m3d.CrossSection:
        return g["sec"](self._size(p, g, g["z_f"] + 0.05)).offset(-g["t"] - 0.07, m3d.JoinType.Round, 2.0, 24)

    def _drain_y(self, p, g) -> float:
        return -(g["B"] * p["flare"] - g["t"] - 0.2)

    def parts(self, p, detail):
        """The freestanding tub's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        A, B, zb, top, t, sec = g["A"], g["B"], g["zb"], g["top"], g["t"], g["sec"]
        e = 0.02 if g["rolled"] else 0.0
        out: list[Part] = []
        if not detail:
            out.append(Part(box_between((-A - e, -B - e, zb), (A + e, B + e, top)), "porcelain"))
        else:
            f = p["flare"]
            zs = np.unique(np.r_[np.linspace(zb + 0.04, g["H"], 7), top])

            def off(cs: m3d.CrossSection, d: float) -> m3d.CrossSection:
                return cs.offset(d, m3d.JoinType.Round, 2.0, 24)

            body = hull_stack([(zb, off(sec(f), -0.035)), (zb + 0.012, off(sec(f), -0.012))]
                               + [(float(z), sec(self._size(p, g, z))) for z in zs])
            if g["rolled"]:
                r = 0.02
                body = body + hull_stack([(top, sec(1.0)), (top - r, off(sec(1.0), r)),
                                           (top - 2 * r, sec(self._size(p, g, top - 2 * r)))])
            cav = ([(top + 0.1, off(sec(1.0), -t))]
                   + [(float(z), off(sec(self._size(p, g, z)), -t)) for z in zs[::-1] if z > g["z_f"] + 0.06]
                   + [(g["z_f"] + 0.05, off(sec(self._size(p, g, g["z_f"] + 0.05)), -t - 0.01)),
                      (g["z_f"], self._floor(p, g))])
            shell = hollow(body, cav)
            if g["slipper"]:
                shell = shell - self._rim_cutter(p, g)
            out.append(Part(shell, "porcelain"))
            out.append(Part(drain_disc(0.0, self._drain_y(p, g), g["z_f"]), "metal"))
        if p["base"] == "plinth":
            plinth = off(sec(p["flare"]), -0.06) if detail else None
            if detail:
                out.append(Part(m3d.Manifold.extrude(plinth, zb + OVERLAP), "porcelain"))
            else:
                out.append(Part(box_between((-A * p["flare"], -B * p["flare"], 0.0),
                                            (A * p["flare"], B * p["flare"], zb + OVERLAP)), "porcelain"))
        elif p["base"] == "feet":
            for fx, fy in self._feet(p, g):
                if detail:
                    prof = [(0.0, 0.0), (0.04, 0.0), (0.034, 0.02), (0.02, zb * 0.55),
                            (0.036, zb), (0.045, zb + min(t / 2, 0.01)), (0.0, zb + min(t / 2, 0.01))]
                    out.append(Part(lathe(prof, 24).translate((fx, fy, 0.0)), "metal"))
                else:
                    out.append(Part(cylinder(0.045, zb + 0.01, (fx, fy, 0.0), 8, circumscribed=True),
                                    "metal"))
        return out

    def _feet(self, p, g) -> list[tuple[float, float]]:
        f = p["flare"]
        ax, by = g["A"] * f - 0.035, g["B"] * f - 0.035
        return [(sx * 0.7 * ax, sy * 0.8 * by) for sx in (-1, 1) for sy in (-1, 1)]

    def _rim_cutter(self, p, g) -> m3d.Manifold:
        """The solid above a slipper rim: level in the middle, rising towards one (+Y) or both
        ends along a parabola (convex, so a hull of points under it)."""
        A, B, H, rise = g["A"] + 0.1, g["B"] + 0.05, g["H"], p["end_rise"]
        if p["shape"] == "double_slipper":
            ys = np.linspace(-B, B, 17)
            zs = H + rise * (np.abs(ys) / g["B"]) ** 2
        else:
            y0 = -0.2 * g["B"]
            ys = np.concatenate([[-B], np.linspace(y0, B, 12)])
            zs = H + rise * (np.clip(ys - y0, 0.0, None) / (g["B"] - y0)) ** 2
        pts = [(sx * A, y, z) for y, z in zip(ys, zs, strict=True) for sx in (-1, 1)]
        pts += [(sx * A, y, g["top"] + 1.0) for y in (-B, B) for sx in (-1, 1)]
        return m3d.Manifold.hull_points(np.array(pts, float))

    def extra_surfaces(self, p):
        """The freestanding tub's surfaces besides its bounding box's: basin, bottom."""
        g = self._g(p)
        floor = outline_polygon(self._floor(p, g), 0.005).difference(
            sg.Point(0.0, self._drain_y(p, g)).buffer(0.04, 16))
        out = [support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        f = p["flare"]
        if p["base"] == "plinth":
            out.append(support_polygon("bottom", (0, 0, 0), outline_polygon(
                g["sec"](f).offset(-0.06, m3d.JoinType.Round, 2.0, 24), 0.0005), Subpart.Bottom, up=False))
        elif p["base"] == "flush":
            out.append(support_polygon("bottom", (0, 0, 0), outline_polygon(
                g["sec"](f).offset(-0.035, m3d.JoinType.Round, 2.0, 24), 0.0005), Subpart.Bottom, up=False))
        return out


def _rot2(deg: float) -> np.ndarray:
    """2D rotation matrix (counter-clockwise by `deg` degrees)."""
    a = math.radians(deg)
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


def _halfplane_cut(cs: m3d.CrossSection, k: float) -> m3d.CrossSection:
    """`cs` without the part where x - y < k (cuts a corner at (-X, +Y) square to the diagonal)."""
    big = 10.0
    keep = m3d.CrossSection.hull_points(np.array(
        [(k / 2 + big, -k / 2 + big), (k / 2 - big, -k / 2 - big), (big * 2, -big * 2)], float))
    return cs ^ keep


@register
class BathtubCorner(_BuiltInTub):
    """A corner bathtub for the corner between the back (-X) and left (+Y) walls: a block whose
    open front is a quarter circle or a diagonal (pentagonal plan), optionally on a recessed
    plinth; the hollow follows the front, leaving a triangular deck in the wall corner,
    optionally with a deck-mounted tap. Rim: support surface; floor: interior surface."""

    name = "bathtub_corner"
    params = {
        "shape": Param(kind="choice", choices=("quarter_round", "pentagon"), doc="plan of the front"),
        "length": Param(1.2, 1.6, doc="Y extent along the back wall (m)"),
        "width": Param(1.2, 1.5, doc="X extent along the left wall (m)"),
        "height": Param(0.5, 0.62, doc="rim height (m)"),
        "front_cut": Param(0.55, 0.85, doc="front rounding radius or chamfer / the smaller side"),
        "rim_width": Param(0.06, 0.12, doc="rim width along the front (m)"),
        "corner_deck": Param(0.12, 0.3, doc="extra depth of the deck in the wall corner (m)"),
        "basin_depth": Param(0.35, 0.45, doc="depth of the hollow (m)"),
        "kick": Param(kind="bool", doc="recessed plinth under the front"),
        "deck_tap": Param(kind="bool", doc="deck-mounted tap on the corner deck"),
    }

    def _g(self, p) -> dict[str, Any]:
        lx, ly, H = p["width"], p["length"], p["height"]
        cut = p["front_cut"] * min(lx, ly)
        outline = corner_outline(lx, ly, p["shape"], cut)
        k = -(lx + ly) / 2 + (p["rim_width"] + p["corner_deck"]) * math.sqrt(2) + 0.25

        def rnd(cs: m3d.CrossSection, r: float) -> m3d.CrossSection:  # rounds inner corners by r
            return cs.offset(-r, m3d.JoinType.Round, 2.0, 24).offset(r, m3d.JoinType.Round, 2.0, 24)

        opening = rnd(_halfplane_cut(outline.offset(-p["rim_width"], m3d.JoinType.Round, 2.0, 24), k), 0.12)
        z_f = H - min(p["basin_depth"], H - 0.1)
        return dict(lx=lx, ly=ly, H=H, outline=outline, opening=opening, z_f=z_f, k=k,
                    floor=opening.offset(-0.16, m3d.JoinType.Round, 2.0, 24),
                    mid=opening.offset(-0.1, m3d.JoinType.Round, 2.0, 24))

    def _tap_xy(self, g) -> tuple[float, float]:
        """The middle of the corner deck, on the diagonal."""
        c = np.array([-g["lx"] / 2, g["ly"] / 2])
        d = (g["k"] + (g["lx"] + g["ly"]) / 2) / math.sqrt(2)  # deck depth along the diagonal
        q = c + np.array([1.0, -1.0]) / math.sqrt(2) * (d * 0.45)
        return float(q[0]), float(q[1])

    def _drain_xy(self, g) -> tuple[float, float]:
        c = outline_polygon(g["floor"]).centroid
        return c.x, c.y

    def _tap(self, g) -> list[m3d.Manifold]:
        tx, ty = self._tap_xy(g)
        return [prim_solid(q).rotate((0.0, 0.0, -45.0)).translate((tx, ty, 0.0))
                for q in faucet(0.0, 0.0, g["H"], "lever", 0.18, 0.16)]

    def parts(self, p, detail):
        """The corner tub's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        lx, ly, H = g["lx"], g["ly"], g["H"]
        if not detail:
            out = [Part(box_between((-lx / 2, -ly / 2, 0.0), (lx / 2, ly / 2, H)), "porcelain")]
            if p["deck_tap"]:
                lo, hi = prim_bounds(faucet(0.0, 0.0, H, "lever", 0.18, 0.16))
                tx, ty = self._tap_xy(g)
                c = np.array([(x, y) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]) @ _rot2(-45.0).T
                out.append(Part(box_between((tx + c[:, 0].min(), ty + c[:, 1].min(), lo[2]),
                                            (tx + c[:, 0].max(), ty + c[:, 1].max(), hi[2])), "metal"))
            return out
        kh = 0.08
        if p["kick"]:
            plinth = self._plinth(g)
            outer = (m3d.Manifold.extrude(g["outline"], H - kh).translate((0.0, 0.0, kh))
                     + m3d.Manifold.extrude(plinth, kh + OVERLAP))
        else:
            outer = m3d.Manifold.extrude(g["outline"], H)
        cav = [(H + 0.05, g["opening"]), (H, g["opening"]), (g["z_f"] + 0.06, g["mid"]),
               (g["z_f"], g["floor"])]
        out = [Part(hollow(outer, cav), "porcelain"), Part(drain_disc(*self._drain_xy(g), g["z_f"]), "metal")]
        if p["deck_tap"]:
            out += [Part(s, "metal") for s in self._tap(g)]
        return out

    def _plinth(self, g) -> m3d.CrossSection:
        """The plinth under a recessed front: the outline pulled 5 cm back from the open front
        but still flush with both walls."""
        return g["outline"].offset(-0.025, m3d.JoinType.Miter, 2.0).translate((-0.025, 0.025)) ^ g["outline"]

    def extra_surfaces(self, p):
        """The corner tub's surfaces besides its bounding box's: rim, basin, bottom."""
        g = self._g(p)
        rim = outline_polygon(g["outline"], 0.005).difference(outline_polygon(g["opening"]).buffer(0.005))
        if p["deck_tap"]:
            tx, ty = self._tap_xy(g)
            rim = rim.difference(sg.Point(tx, ty).buffer(0.1, 16))
        dx, dy = self._drain_xy(g)
        floor = outline_polygon(g["floor"], 0.005).difference(sg.Point(dx, dy).buffer(0.04, 16))
        rim = max(polygon_pieces(rim), key=lambda q: q.area)
        out = [support_polygon("rim", (0, 0, g["H"]), rim),
               support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        if p["kick"]:
            out.append(support_polygon("bottom", (0, 0, 0), outline_polygon(self._plinth(g), 0.0005),
                                       Subpart.Bottom, up=False))
        else:
            out.append(support_polygon("bottom", (0, 0, 0), outline_polygon(g["outline"], 0.0005),
                                       Subpart.Bottom, up=False))
        return out
