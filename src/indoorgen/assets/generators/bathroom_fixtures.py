"""Bathroom fixtures: bathtubs (alcove, freestanding, corner), toilets and shower enclosures.
Fronts face +X; a fixture against a wall has its back at -X (a corner fixture: walls at -X and
+Y). Tubs and toilet bowls are real hollows (manifold3d subtraction), open at the top; the
shared outline, hull and primitive helpers are in `bathroom`.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.base import Param, Surface, register
from indoorgen.assets.generators.bathroom import (
    FIXTURE_MATERIALS,
    GAP,
    OV,
    Prim,
    ellipse,
    faucet,
    hollow,
    hull_stack,
    outline_points,
    outline_polygon,
    polygon_pieces,
    prim_bounds,
    prim_parts,
    prim_solid,
    rounded_rect,
)
from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.shapes.moving_parts import DoorJoint
from indoorgen.assets.shapes.primitives import Part, box_between, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


# ------------------------------------------------------------------------------ bathtubs
def _drain(x: float, y: float, z_floor: float, r: float = 0.035) -> m3d.Manifold:
    """A drain disc set into a floor at z_floor, its top 0.5 mm proud."""
    return cylinder(r, 0.0045, (x, y, z_floor - 0.004), 24)


@register
class BathtubAlcove(PartsFactory):
    """A built-in rectangular bathtub for a three-wall alcove: a block with a flat rim and a
    tiled-in back, its front an apron (flat, with a recessed toe kick, or panelled); the
    hollow tapers to a flat floor with a sloped backrest at one end and the drain and overflow
    at the other. Rim: support surface; floor of the hollow: interior surface."""

    name = "bathtub_alcove"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
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
        g = self._g(p)
        L, D, H = g["L"], g["D"], g["H"]
        front = D / 2 + (0.01 if p["apron_style"] == "panelled" else 0.0)
        if not detail:
            return [Part(box_between((-D / 2, -L / 2, 0.0), (front, L / 2, H)), "porcelain")]
        if p["apron_style"] == "kick":
            outer = (box_between((-D / 2, -L / 2, 0.07), (D / 2, L / 2, H))
                     + box_between((-D / 2, -L / 2, 0.0), (D / 2 - 0.05, L / 2, 0.07 + OV)))
        else:
            outer = box_between((-D / 2, -L / 2, 0.0), (D / 2, L / 2, H))
        if p["apron_style"] == "panelled":
            border = 0.05
            outer = outer + (box_between((D / 2 - OV, -L / 2 + 0.04, 0.05), (front, L / 2 - 0.04, H - 0.05))
                             - box_between((D / 2, -L / 2 + 0.04 + border, 0.05 + border),
                                           (front + 0.01, L / 2 - 0.04 - border, H - 0.05 - border)))
        out = [Part(hollow(outer, self._cavity(p, g)), "porcelain")]
        dy = self._drain_y(g)
        out.append(Part(_drain(0.0, dy, g["z_f"]), "metal"))
        # overflow cover on the drain end wall, 10 cm under the rim
        zo = H - 0.1
        t = (H - zo) / (H - g["z_f"] - 0.05)
        y_wall = g["s"] * ((1 - t) * g["l_in"] / 2 + t * (abs(g["fy"]) + g["fl"] / 2 + 0.03))
        out.append(Part(rod((0.0, y_wall + g["s"] * 0.03, zo), (0.0, y_wall - g["s"] * 0.008, zo),
                            0.03, 24), "metal"))
        return out

    def extra_surfaces(self, p):
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
        return self.resolve(params)["base"] != "feet"

    def _g(self, p) -> dict[str, Any]:
        A, B = p["width"] / 2, p["length"] / 2
        slipper = p["shape"] in ("slipper", "double_slipper")
        zb = 0.0 if p["base"] == "flush" else p["base_height"]
        H = p["height"]
        top = H + (p["end_rise"] if slipper else 0.0)
        t = p["wall_thickness"]
        if p["shape"] == "rounded_rect":
            sec = lambda s: rounded_rect(2 * A * s, 2 * B * s, 0.5 * A * s)
        else:
            sec = lambda s: ellipse(A * s, B * s, (0.0, 0.0), 64)
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
        g = self._g(p)
        A, B, zb, top, t, sec = g["A"], g["B"], g["zb"], g["top"], g["t"], g["sec"]
        e = 0.02 if g["rolled"] else 0.0
        out: list[Part] = []
        if not detail:
            out.append(Part(box_between((-A - e, -B - e, zb), (A + e, B + e, top)), "porcelain"))
        else:
            f = p["flare"]
            zs = np.unique(np.r_[np.linspace(zb + 0.04, g["H"], 7), top])
            off = lambda cs, d: cs.offset(d, m3d.JoinType.Round, 2.0, 24)
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
            out.append(Part(_drain(0.0, self._drain_y(p, g), g["z_f"]), "metal"))
        if p["base"] == "plinth":
            plinth = off(sec(p["flare"]), -0.06) if detail else None
            if detail:
                out.append(Part(m3d.Manifold.extrude(plinth, zb + OV), "porcelain"))
            else:
                out.append(Part(box_between((-A * p["flare"], -B * p["flare"], 0.0),
                                            (A * p["flare"], B * p["flare"], zb + OV)), "porcelain"))
        elif p["base"] == "feet":
            for fx, fy in self._feet(p, g):
                if detail:
                    prof = [(0.0, 0.0), (0.04, 0.0), (0.034, 0.02), (0.02, zb * 0.55),
                            (0.036, zb), (0.045, zb + min(t / 2, 0.01)), (0.0, zb + min(t / 2, 0.01))]
                    out.append(Part(lathe(prof, 24).translate((fx, fy, 0.0)), "metal"))
                else:
                    out.append(Part(cylinder(0.045, zb + 0.01, (fx, fy, 0.0), 8, circumscribed=True), "metal"))
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
        pts = [(sx * A, y, z) for y, z in zip(ys, zs) for sx in (-1, 1)]
        pts += [(sx * A, y, g["top"] + 1.0) for y in (-B, B) for sx in (-1, 1)]
        return m3d.Manifold.hull_points(np.array(pts, float))

    def extra_surfaces(self, p):
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


def corner_outline(lx: float, ly: float, shape: str, cut: float, n: int = 24) -> m3d.CrossSection:
    """The plan of a corner fixture lx (X) by ly (Y) centred on the origin, walls along its
    back (-X) and left (+Y) sides, its open front corner (+X, -Y) rounded by a quarter circle
    of radius `cut` ("quarter_round") or cut off by a diagonal `cut` along each side
    ("pentagon")."""
    corners = [(-lx / 2, -ly / 2), (-lx / 2, ly / 2), (lx / 2, ly / 2)]
    if shape == "pentagon":
        pts = corners + [(lx / 2, -ly / 2 + cut), (lx / 2 - cut, -ly / 2)]
    else:
        c = (lx / 2 - cut, -ly / 2 + cut)
        a = np.linspace(-math.pi / 2, 0.0, n + 1)
        pts = corners + list(zip(c[0] + cut * np.cos(a), c[1] + cut * np.sin(a)))
    return m3d.CrossSection.hull_points(np.array(pts, float))


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
class BathtubCorner(PartsFactory):
    """A corner bathtub for the corner between the back (-X) and left (+Y) walls: a block whose
    open front is a quarter circle or a diagonal (pentagonal plan), optionally on a recessed
    plinth; the hollow follows the front, leaving a triangular deck in the wall corner,
    optionally with a deck-mounted tap. Rim: support surface; floor: interior surface."""

    name = "bathtub_corner"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
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
        rnd = lambda cs, r: cs.offset(-r, m3d.JoinType.Round, 2.0, 24).offset(r, m3d.JoinType.Round, 2.0, 24)
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
                     + m3d.Manifold.extrude(plinth, kh + OV))
        else:
            outer = m3d.Manifold.extrude(g["outline"], H)
        cav = [(H + 0.05, g["opening"]), (H, g["opening"]), (g["z_f"] + 0.06, g["mid"]),
               (g["z_f"], g["floor"])]
        out = [Part(hollow(outer, cav), "porcelain"), Part(_drain(*self._drain_xy(g), g["z_f"]), "metal")]
        if p["deck_tap"]:
            out += [Part(s, "metal") for s in self._tap(g)]
        return out

    def _plinth(self, g) -> m3d.CrossSection:
        """The plinth under a recessed front: the outline pulled 5 cm back from the open front
        but still flush with both walls."""
        return g["outline"].offset(-0.025, m3d.JoinType.Miter, 2.0).translate((-0.025, 0.025)) ^ g["outline"]

    def extra_surfaces(self, p):
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


# -------------------------------------------------------------------------------- toilet
def _clip_back(cs: m3d.CrossSection, x0: float) -> m3d.CrossSection:
    """`cs` without what lies behind x = x0."""
    lo = cs.bounds()
    return cs ^ m3d.CrossSection.square((lo[2] - x0 + 1.0, lo[3] - lo[1] + 1.0)).translate(
        (x0, lo[1] - 0.5))


@register
class Toilet(PartsFactory):
    """A toilet: a hollow glazed bowl (oval rim, funnel-shaped hollow) on an exposed waisted
    foot or a smooth skirted body, with a cistern on it (two-piece), merged into it
    (one-piece) or none (wall-hung: it hangs from the wall, its flat back is its mounting
    face). The seat ring and the lid are separate links hinged about a Y axis at the back
    (they open until they lean on the cistern or wall); a push button or a side lever flushes."""

    name = "toilet"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Toilet})
    size_class = "large"
    slots = ["porcelain", "plastic", "metal"]
    material_choices = {"porcelain": FIXTURE_MATERIALS["porcelain"],
                        "plastic": {"glossy_plastic": 3.0, "painted_wood": 1.0, "oak": 0.5},
                        "metal": FIXTURE_MATERIALS["metal"]}
    params = {
        "style": Param(kind="choice", choices=("two_piece", "one_piece", "wall_hung"),
                       doc="cistern on the bowl, merged with it, or none (hung on the wall)"),
        "rim_height": Param(0.38, 0.44, doc="rim height above the floor (wall-hung: the bowl "
                                            "is 6 cm shorter and hangs at any height) (m)"),
        "bowl_length": Param(0.42, 0.5, doc="X length of the rim (round to elongated) (m)"),
        "bowl_width": Param(0.34, 0.39, doc="Y width of the rim (m)"),
        "rim_width": Param(0.03, 0.045, doc="width of the rim around the opening (m)"),
        "cistern_width": Param(0.36, 0.48, doc="cistern Y extent (m)"),
        "cistern_depth": Param(0.15, 0.22, doc="cistern X extent (m)"),
        "cistern_height": Param(0.28, 0.4, doc="cistern height above the rim (one-piece: 60%) (m)"),
        "seat_thickness": Param(0.018, 0.03, doc="seat ring thickness (m)"),
        "lid_thickness": Param(0.015, 0.028, doc="lid thickness (m)"),
        "flush": Param(kind="choice", choices=("button", "lever"),
                       doc="push button on top or lever on the side of the cistern"),
        "foot": Param(kind="choice", choices=("exposed", "skirted"),
                      doc="waisted foot or smooth skirted body (floor-standing styles)"),
    }

    def bottom_is_solid(self, params):
        return self.resolve(params)["style"] != "wall_hung"

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        style = p["style"]
        wall = style == "wall_hung"
        H = p["rim_height"] - (0.06 if wall else 0.0)
        a, b = p["bowl_length"] / 2, p["bowl_width"] / 2
        cd, cw = p["cistern_depth"], p["cistern_width"]
        ch = p["cistern_height"] * (0.6 if style == "one_piece" else 1.0)
        ts, tl = p["seat_thickness"], p["lid_thickness"]
        cf = {"two_piece": cd + 0.008, "one_piece": cd + 0.05, "wall_hung": 0.0}[style]
        x_hl = cf + 0.02  # back edge of the lid
        x_h = x_hl + tl + GAP  # back edge of the seat (the lid rests behind it when both open)
        x_e = x_h - 0.02 + a  # centre of the rim ellipse
        z_s = H + GAP  # underside of the seat
        z_l = z_s + ts + GAP  # underside of the lid
        return dict(style=style, wall=wall, H=H, a=a, b=b, cd=cd, cw=cw, ch=ch, ts=ts, tl=tl,
                    cf=cf, x_hl=x_hl, x_h=x_h, x_e=x_e, z_s=z_s, z_l=z_l,
                    front=x_e + a + 0.005, rw=p["rim_width"], x_foot=0.3 * cd if not wall else 0.0)

    def _foot(self, p, g) -> m3d.CrossSection:
        """The footprint on the floor (floor-standing styles)."""
        x0, x1 = g["x_foot"], g["x_e"] + (0.85 if p["foot"] == "skirted" else 0.45) * g["a"]
        w = 1.7 * g["b"] if p["foot"] == "skirted" else 0.22
        return rounded_rect(x1 - x0, w, 0.05, ((x0 + x1) / 2, 0.0))

    def _flush(self, p, g) -> list[Prim]:
        if g["wall"]:
            return []
        top = g["H"] + g["ch"] + (0.025 if g["style"] == "two_piece" else 0.0)
        if p["flush"] == "button":
            return [("cyl", 0.022, 0.009, (g["cd"] / 2, 0.0, top - OV))]
        x, y, z = g["cd"] - 0.05, g["cw"] / 2, g["H"] + g["ch"] - 0.05
        if g["style"] == "one_piece":  # its sides lean in: 0.5 cw wide at H - 0.12, 0.46 cw at the top
            y = g["cw"] * (0.5 - 0.04 * (z - g["H"] + 0.12) / (g["ch"] + 0.12)) - 0.004
        return [("rod", (x, y - OV, z), (x, y + 0.01, z), 0.018),
                ("rod", (x, y + 0.012, z), (x - 0.075, y + 0.012, z + 0.01), 0.007)]

    def _cistern(self, p, g) -> list[Part]:
        H, cd, cw, ch = g["H"], g["cd"], g["cw"], g["ch"]
        if g["style"] == "two_piece":
            body = box_between((0.0, -cw / 2, H - 0.01), (cd, cw / 2, H + ch))
            lid = box_between((0.0, -cw / 2 - 0.008, H + ch - OV), (cd + 0.008, cw / 2 + 0.008, H + ch + 0.025))
            return [Part(body, "porcelain"), Part(lid, "porcelain")]
        lv = [(H - 0.12, rounded_rect(cd + 0.05 + 0.08, cw, 0.04, ((cd + 0.05 - 0.08) / 2, 0.0))),
              (H + ch, rounded_rect(cd + 0.08, 0.92 * cw, 0.04, ((cd - 0.08) / 2, 0.0)))]
        pts = np.vstack([np.c_[np.maximum(outline_points(cs)[:, 0], 0.0), outline_points(cs)[:, 1],
                               np.full(len(outline_points(cs)), z)] for z, cs in lv])
        return [Part(m3d.Manifold.hull_points(pts), "porcelain")]

    def _body(self, p, g) -> m3d.Manifold:
        """The bowl, its rear deck and its foot (or, wall-hung, its mounting block)."""
        H, a, b, x_e = g["H"], g["a"], g["b"], g["x_e"]
        x_deck = 0.0 if g["style"] != "one_piece" else g["cd"] - 0.01
        deck = rounded_rect(x_e - x_deck, 1.5 * b, 0.0, ((x_e + x_deck) / 2, 0.0))
        bowl = [(H, ellipse(a, b, (x_e, 0.0))), (H - 0.03, ellipse(a, b, (x_e, 0.0))),
                (H, deck), (H - 0.09, deck)]
        if g["wall"]:
            block = rounded_rect(0.04, 0.32, 0.0, (0.02, 0.0))
            return hull_stack(bowl + [(H - 0.22, ellipse(0.75 * a, 0.8 * b, (x_e - 0.1 * a, 0.0))),
                                       (0.0, ellipse(0.55 * a, 0.6 * b, (x_e - 0.2 * a, 0.0))),
                                       (0.06, block)])
        if p["foot"] == "skirted":
            return hull_stack(bowl + [(0.0, self._foot(p, g))])
        # exposed: the bowl narrows to a waist, which flares out again to the foot
        z_b, z_w = H - 0.2, 0.1
        foot = self._foot(p, g)
        fx0, fy0, fx1, fy1 = outline_polygon(foot).bounds
        waist = rounded_rect(0.8 * (fx1 - fx0), 0.16, 0.05, ((fx0 + fx1) / 2 + 0.05 * (fx1 - fx0), 0.0))
        return (hull_stack(bowl + [(z_b, ellipse(0.7 * a, 0.75 * b, (x_e - 0.1 * a, 0.0))), (z_w, waist)])
                + hull_stack([(0.0, foot), (0.015, foot), (z_w + 0.01, waist)]))

    def _cavity(self, g) -> list[tuple[float, m3d.CrossSection]]:
        H, a, b, rw, x_e = g["H"], g["a"], g["b"], g["rw"], g["x_e"]
        opening = ellipse(a - rw, b - rw, (x_e + 0.005, 0.0))
        return [(H + 0.05, opening), (H, opening),
                (H - 0.05, ellipse(0.9 * (a - rw), 0.9 * (b - rw), (x_e, 0.0))),
                (H - 0.2, ellipse(0.06, 0.06, (x_e - 0.25 * a, 0.0), 24))]

    def _outline(self, g, x0: float) -> m3d.CrossSection:
        return _clip_back(ellipse(g["a"] + 0.005, g["b"] + 0.005, (g["x_e"], 0.0), 64), x0)

    def _seat(self, g) -> m3d.Manifold:
        outline = self._outline(g, g["x_h"])
        opening = ellipse(g["a"] - g["rw"] - 0.005, g["b"] - g["rw"] - 0.005, (g["x_e"] + 0.01, 0.0))
        ts, z = g["ts"], g["z_s"]
        low = m3d.Manifold.extrude(outline - opening, ts * 0.6).translate((0.0, 0.0, z))
        high = m3d.Manifold.extrude(outline.offset(-0.005, m3d.JoinType.Round, 2.0, 24)
                                    - opening.offset(0.005, m3d.JoinType.Round, 2.0, 24), ts * 0.4 + OV)
        return low + high.translate((0.0, 0.0, z + ts * 0.6 - OV))

    def _lid(self, g) -> m3d.Manifold:
        outline = self._outline(g, g["x_hl"])
        tl, z = g["tl"], g["z_l"]
        return hull_stack([(z, outline), (z + 0.5 * tl, outline),
                            (z + tl, outline.offset(-0.012, m3d.JoinType.Round, 2.0, 24))])

    # ---- generator protocol
    def parts(self, p, detail):
        g = self._g(p)
        H, a, b, x_e = g["H"], g["a"], g["b"], g["x_e"]
        out: list[Part] = []
        if detail:
            out.append(Part(hollow(self._body(p, g), self._cavity(g)), "porcelain"))
            if not g["wall"]:
                out += self._cistern(p, g)
            for s in (-1, 1):  # hinge posts under the lid's back edge
                out.append(Part(box_between((g["x_hl"] + 0.004, s * 0.7 * b - 0.015, H - OV),
                                            (g["x_h"] - GAP, s * 0.7 * b + 0.015, g["z_s"] + g["ts"] - 0.001)),
                                "metal"))
            out.append(Part(self._seat(g), "plastic", "seat"))
            out.append(Part(self._lid(g), "plastic", "lid"))
            out += prim_parts(self._flush(p, g), True)
            return out
        x0 = 0.0 if g["style"] != "one_piece" else g["cd"] - 0.01
        x0 = min(x0, g["x_foot"]) if not g["wall"] else 0.0
        out.append(Part(box_between((x0, -b, 0.0), (x_e + a, b, H)), "porcelain"))
        if g["style"] == "two_piece":  # the cistern and its overhanging lid
            e = 0.008
            out.append(Part(box_between((0.0, -g["cw"] / 2 - e, H - 0.01),
                                        (g["cd"] + e, g["cw"] / 2 + e, H + g["ch"] + 0.025)), "porcelain"))
        elif g["style"] == "one_piece":  # the cistern tapers up from its widest foot
            out.append(Part(box_between((0.0, -g["cw"] / 2, H - 0.12),
                                        (g["cd"] + 0.05, g["cw"] / 2, H + g["ch"])), "porcelain"))
        out.append(Part(box_between((g["x_hl"], -b - 0.005, H), (g["front"], b + 0.005, g["z_l"] + g["tl"])),
                        "plastic"))
        if self._flush(p, g):
            out += prim_parts(self._flush(p, g), False)
        return out

    def _open_limit(self, g, x_back: float, length: float) -> float:
        """How far (rad) a seat or lid hinged `x_back - cf` in front of the cistern (or wall)
        can tilt past vertical before its top leans on it."""
        room = max(x_back - g["cf"] - 0.006, 0.0)
        return math.pi / 2 + math.asin(min(room / length, 0.3))

    def joints(self, p):
        g = self._g(p)
        up = self._open_limit(g, g["x_hl"], g["front"] - g["x_hl"])
        axis = np.array([0.0, -1.0, 0.0])
        seat = DoorJoint("revolute", axis, np.array([g["x_h"], 0.0, g["z_s"] + g["ts"]]), "seat")
        lid = DoorJoint("revolute", axis, np.array([g["x_hl"], 0.0, g["z_l"] + g["tl"]]), "lid")
        return [make_joint("seat_joint", seat, 0.0, up), make_joint("lid_joint", lid, 0.0, up)]

    def extra_surfaces(self, p):
        g = self._g(p)
        H, cw = g["H"], g["cw"]
        if g["wall"]:
            back = Surface.rect("back", Subpart.Back, (0.0, 0.0, (0.07 + H - 0.01) / 2), (-1, 0, 0),
                                (0, 1, 0), 0.15, (H - 0.01 - 0.07) / 2)
            return [back]
        if g["style"] == "two_piece":
            z0, z1, hw = H - 0.005, H + g["ch"] - 0.005, cw / 2 - 0.005
        else:
            z0, z1, hw = H - 0.11, H + g["ch"] - 0.01, 0.46 * cw - 0.01
        return [Surface.rect("back", Subpart.Back, (0.0, 0.0, (z0 + z1) / 2), (-1, 0, 0), (0, 1, 0),
                             hw, (z1 - z0) / 2),
                support_polygon("bottom", (0, 0, 0), outline_polygon(self._foot(p, g), 0.0005),
                                Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------ showers
def _arc_panel(c: tuple[float, float], r0: float, r1: float, z0: float, z1: float,
               phi0: float, phi1: float) -> m3d.Manifold:
    """A curved panel: the ring sector between radii r0 and r1 about the vertical axis through
    `c`, from angle phi0 to phi1 (degrees, counter-clockwise from +X), spanning z0..z1."""
    cs = m3d.CrossSection.square((r1 - r0, z1 - z0)).translate((r0, z0))
    n = max(4, int(math.ceil((phi1 - phi0) / 3.75)))
    return m3d.Manifold.revolve(cs, int(n * 360 / (phi1 - phi0)), phi1 - phi0).rotate(
        (0.0, 0.0, phi0)).translate((c[0], c[1], 0.0))


SURROUND = 0.008  # thickness of the wall panels lining the enclosure's two walls


@register
class ShowerEnclosure(PartsFactory):
    """A shower: a low ceramic tray lined by wall panels on its back (-X) and left (+Y) walls,
    a glass enclosure - a square corner (fixed side panel, front with a hinged or sliding
    door), a quadrant (curved front of two sliding curved doors between straight returns) or a
    walk-in (one fixed panel braced to the wall, open end) - frameless or framed, and a rain
    head on a riser over a bar mixer. Doors are articulated; the tray's floor is an interior
    surface and the back wall panel its back."""

    name = "shower_enclosure"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Shower})
    size_class = "large"
    slots = ["ceramic", "tile", "glass", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("ceramic", "tile", "glass", "metal")}
    solid_bottom = True
    params = {
        "layout": Param(kind="choice", choices=("corner_square", "quadrant", "walk_in"),
                        doc="enclosure type"),
        "tray_length": Param(0.8, 1.6, doc="Y extent (quadrant: at most depth + 0.2; walk-in: "
                                           "at least 1.2) (m)"),
        "tray_depth": Param(0.8, 1.0, doc="X extent (m)"),
        "tray_height": Param(0.03, 0.12, doc="tray height (m)"),
        "glass_height": Param(1.85, 2.0, doc="height of the glass above the tray (m)"),
        "glass_thickness": Param(0.006, 0.01, doc="glass thickness (m)"),
        "door": Param(kind="choice", choices=("hinged", "sliding"), doc="door of a square corner"),
        "frame": Param(kind="choice", choices=("frameless", "framed"), doc="metal profiles"),
        "quadrant_radius": Param(0.45, 0.6, doc="radius of a quadrant's curved front (m)"),
        "panel_fraction": Param(0.5, 0.8, doc="walk-in panel length / tray length"),
        "head_radius": Param(0.08, 0.15, doc="rain head radius (m)"),
        "head_height": Param(1.95, 2.15, doc="height of the rain head above the floor (m)"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        D = p["tray_depth"]
        W = p["tray_length"]
        if p["layout"] == "quadrant":
            W = min(W, D + 0.2)
        elif p["layout"] == "walk_in":
            W = max(W, 1.2)
        th, t = p["tray_height"], p["glass_thickness"]
        e = 0.03
        R = min(p["quadrant_radius"], min(D, W) - 0.25)
        return dict(D=D, W=W, th=th, t=t, e=e, x_f=D / 2 - e, y_s=-W / 2 + e, R=R,
                    c=(D / 2 - R, -W / 2 + R), R_arc=R - e, R_d=R - e - t - GAP,
                    z0=th - OV, z1=th + p["glass_height"], x_w=-D / 2 + SURROUND,
                    y_w=W / 2 - SURROUND, framed=p["frame"] == "framed")

    def _tray_outline(self, p, g) -> m3d.CrossSection:
        if p["layout"] == "quadrant":
            return corner_outline(g["D"], g["W"], "quarter_round", g["R"])
        return rounded_rect(g["D"], g["W"], 0.0)

    def _recess(self, p, g) -> m3d.CrossSection:
        return self._tray_outline(p, g).offset(-0.07, m3d.JoinType.Round, 2.0, 24)

    def _hinged(self, g) -> dict[str, float]:
        """Square corner, hinged door: the door's y range, hinged on the wall (+Y) side."""
        y1 = g["y_w"] - 0.02
        span = y1 - (g["y_s"] - g["t"] / 2)
        y0 = y1 - min(0.65, 0.6 * span)
        return dict(y0=y0, y1=y1)

    def _sliding(self, g) -> dict[str, float]:
        """Square corner, sliding door: outside the fixed front panel, overlapping it 5 cm."""
        y1 = g["y_w"] - 0.015
        ym = (g["y_s"] + y1) / 2
        return dict(y0=ym - 0.05, y1=y1, ym=ym, x0=g["x_f"] + g["t"] / 2 + GAP,
                    z1=g["z1"] - 0.04)

    def _door_handle(self, x_face: float, y: float, zc: float, sides: tuple[int, ...]) -> list[Prim]:
        """Vertical bar handles on the faces of a +X-facing glass leaf (side +1: outside, -1:
        inside; x_face is the outer face for +1, the inner face for -1)."""
        out = []
        for s, xf in zip(sides, (x_face,) * len(sides)):
            xb = xf + s * 0.03
            out += [("rod", (xb, y, zc - 0.15), (xb, y, zc + 0.15), 0.01),
                    ("rod", (xf - s * OV, y, zc - 0.12), (xb, y, zc - 0.12), 0.007),
                    ("rod", (xf - s * OV, y, zc + 0.12), (xb, y, zc + 0.12), 0.007)]
        return out

    def _moving(self, p, g) -> list[tuple[list[Part], DoorJoint, float]]:
        """(parts, motion, upper limit) of each door leaf."""
        t, z0, x_f = g["t"], g["th"] + 0.01, g["x_f"]
        zc = g["th"] + 1.05
        if p["layout"] == "walk_in":
            return []
        if p["layout"] == "quadrant":
            (cx, cy), rd, out = g["c"], g["R_d"], []
            z1 = g["z1"] - 0.04
            for i, (a0, a1, sgn) in enumerate(((-90.0, -46.0, -1.0), (-44.0, 0.0, 1.0))):
                leaf = _arc_panel((cx, cy), rd - t / 2, rd + t / 2, z0, z1, a0, a1)
                ah = math.radians(-46.0 - 4.0 if sgn < 0 else -44.0 + 4.0)
                ro = rd + t / 2
                knob = [("rod", (cx + (ro - OV) * math.cos(ah), cy + (ro - OV) * math.sin(ah), zc),
                         (cx + (ro + 0.025) * math.cos(ah), cy + (ro + 0.025) * math.sin(ah), zc), 0.012)]
                parts = [Part(leaf, "glass", f"door_{i}")] + [Part(s.solid, "metal", f"door_{i}")
                                                            for s in prim_parts(knob, True)]
                motion = DoorJoint("revolute", np.array([0.0, 0.0, sgn]), np.array([cx, cy, 0.0]),
                                   f"door_{i}")
                # a leaf slides round until its far end is 9 cm (mixer) from the back wall or
                # 2 cm from the left wall, at most 36 degrees
                room = (cx - g["x_w"] - 0.09) if sgn < 0 else (g["y_w"] - 0.02 - cy)
                out.append((parts, motion, min(math.asin(min(max(room / (rd + t / 2), 0.1), 1.0)),
                                               math.radians(36.0))))
            return out
        if p["door"] == "hinged":
            h = self._hinged(g)
            leaf = box_between((x_f - t / 2, h["y0"], z0), (x_f + t / 2, h["y1"], g["z1"] - 0.01))
            handle = self._door_handle(x_f + t / 2, h["y0"] + 0.06, zc, (1,)) + \
                self._door_handle(x_f - t / 2, h["y0"] + 0.06, zc, (-1,))
            parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
            motion = DoorJoint("revolute", np.array([0.0, 0.0, 1.0]),
                               np.array([x_f + t / 2, h["y1"], 0.0]), "door_0")
            return [(parts, motion, math.radians(95.0))]
        s = self._sliding(g)
        leaf = box_between((s["x0"], s["y0"], z0), (s["x0"] + t, s["y1"], s["z1"]))
        handle = self._door_handle(s["x0"] + t, s["y0"] + 0.08, zc, (1,))
        parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
        motion = DoorJoint("prismatic", np.array([0.0, -1.0, 0.0]), np.array([s["x0"], s["y0"], z0]),
                           "door_0")
        # it stops short of the corner clamp, which stands proud of the fixed glass
        travel = min(0.8 * (s["y1"] - s["y0"]), s["y0"] - (g["y_s"] + t / 2 + 0.006 + GAP))
        return [(parts, motion, travel)]

    def _fixed(self, p, g) -> list[Part]:
        """Tray, wall panels, fixed glass, profiles and rails."""
        D, W, th, t = g["D"], g["W"], g["th"], g["t"]
        x_f, y_s, x_w, y_w, z0, z1 = g["x_f"], g["y_s"], g["x_w"], g["y_w"], g["z0"], g["z1"]
        tray = m3d.Manifold.extrude(self._tray_outline(p, g), th)
        tray = tray - m3d.Manifold.extrude(self._recess(p, g), 0.05).translate((0.0, 0.0, th - 0.008))
        out = [Part(tray, "ceramic"),
               Part(box_between((-D / 2, -W / 2, z0), (x_w, W / 2, z1)), "tile"),
               Part(box_between((-D / 2, y_w, z0), (x_f + t / 2 + 0.006, W / 2, z1)), "tile")]
        out += self._drain_parts(p, g)
        glass, metal = [], []
        pw = 0.015 + (0.01 if g["framed"] else 0.0)  # wall profile width
        if p["layout"] == "walk_in":
            y0 = y_w - p["panel_fraction"] * W
            glass.append(box_between((x_f - t / 2, y0, z0), (x_f + t / 2, y_w + OV, z1)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_w - pw, z0), (x_f + t / 2 + 0.006, y_w + OV, z1)))
            metal.append(rod((x_f, y0 + 0.05, z1 - 0.06), (x_w - OV, y0 + 0.05, z1 - 0.06), 0.01, 12))
        elif p["layout"] == "quadrant":
            (cx, cy), ra = g["c"], g["R_arc"]
            glass.append(box_between((x_w - OV, y_s - t / 2, z0), (cx + 0.01, y_s + t / 2, z1)))
            glass.append(box_between((x_f - t / 2, cy - 0.01, z0), (x_f + t / 2, y_w + OV, z1)))
            rail_z0 = g["z1"] - 0.04 + GAP
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, rail_z0, z1 + 0.01, -90.0, 0.0))
            metal.append(box_between((cx - 0.01, y_s - 0.014, rail_z0), (cx + 0.011, y_s + 0.014, z1 + 0.01)))
            metal.append(box_between((x_f - 0.014, cy - 0.011, rail_z0), (x_f + 0.014, cy + 0.01, z1 + 0.01)))
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, z0, th + 0.008, -90.0, 0.0))
        else:
            glass.append(box_between((x_w - OV, y_s - t / 2, z0), (x_f + t / 2, y_s + t / 2, z1)))
            if p["door"] == "hinged":
                h = self._hinged(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0), (x_f + t / 2, h["y0"] - GAP, z1)))
                for zh in (th + 0.3, g["z1"] - 0.3):  # hinges on the wall
                    metal.append(box_between((x_f - 0.02, h["y1"] + GAP, zh - 0.04),
                                             (x_f + 0.02, y_w + OV, zh + 0.04)))
            else:
                s = self._sliding(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0), (x_f + t / 2, s["ym"] + 0.05, z1)))
                metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, s["z1"] + GAP),
                                         (s["x0"] + t + 0.008, y_w + OV, z1 + 0.01)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, z0),
                                     (x_f + t / 2 + 0.006, y_s + t / 2 + 0.006, z1)))  # corner clamp/post
        if p["layout"] != "walk_in":  # wall profile of the side panel
            metal.append(box_between((x_w - OV, y_s - t / 2 - 0.006, z0), (x_w + pw, y_s + t / 2 + 0.006, z1)))
        if g["framed"] and p["layout"] != "walk_in":  # top rail along the side panel
            x_end = g["c"][0] + 0.011 if p["layout"] == "quadrant" else x_f + t / 2 + 0.006
            metal.append(box_between((x_w - OV, y_s - t / 2 - 0.006, z1 - 0.03),
                                     (x_end, y_s + t / 2 + 0.006, z1 + 0.01)))
        return (out + [Part(s, "glass") for s in glass] + [Part(s, "metal") for s in metal]
                + [Part(prim_solid(q), "metal") for q in self._head(p, g)])

    def _head(self, p, g) -> list[Prim]:
        """Bar mixer on the back wall panel, riser, arm and round rain head."""
        x_w = g["x_w"]
        xr = x_w + 0.05
        zm = g["th"] + 0.95
        zh = max(p["head_height"], zm + 0.5)
        arm = min(0.35, g["D"] / 2)
        return [("box", (x_w - OV, -0.1, zm - 0.04), (x_w + 0.012, 0.1, zm + 0.04)),
                ("rod", (xr, -0.16, zm), (xr, 0.16, zm), 0.025),
                ("rod", (x_w + 0.01, -0.07, zm), (xr, -0.07, zm), 0.012),
                ("rod", (x_w + 0.01, 0.07, zm), (xr, 0.07, zm), 0.012),
                ("cyl", 0.011, zh - zm, (xr, 0.0, zm)),
                ("rod", (x_w - OV, 0.0, zh - 0.15), (xr, 0.0, zh - 0.15), 0.01),
                ("rod", (xr - 0.01, 0.0, zh - 0.008), (xr + arm, 0.0, zh - 0.008), 0.01),
                ("cyl", p["head_radius"], 0.014, (xr + arm, 0.0, zh - 0.03))]

    def parts(self, p, detail):
        g = self._g(p)
        if detail:
            return self._fixed(p, g) + [q for parts, _, _ in self._moving(p, g) for q in parts]
        D, W = g["D"], g["W"]
        hl, hh = prim_bounds(self._head(p, g))
        x1, z1 = g["x_f"] + g["t"] / 2 + 0.006, g["z1"] + 0.01
        if p["layout"] == "corner_square":
            x1 = g["x_f"] + g["t"] / 2 + 0.03 + 0.01  # hinged door handle
            if p["door"] == "sliding":
                x1 = self._sliding(g)["x0"] + g["t"] + 0.03 + 0.01
        elif p["layout"] == "quadrant":
            x1 = g["x_f"] + g["t"] / 2
        elif p["layout"] == "walk_in":
            z1 = g["z1"]
        return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, g["th"])), "ceramic"),
                Part(box_between((-D / 2, -W / 2, g["z0"]), (max(x1, D / 2), W / 2, max(z1, hh[2]))), "glass")]

    def joints(self, p):
        g = self._g(p)
        return [make_joint(f"{m.link}_joint", m, 0.0, up) for _, m, up in self._moving(p, g)]

    def extra_surfaces(self, p):
        g = self._g(p)
        rec = self._recess(p, g)
        c = outline_polygon(rec).centroid
        floor = outline_polygon(rec, 0.005).difference(sg.Point(c.x, c.y).buffer(0.05, 16))
        return [support_polygon("tray", (0, 0, g["th"] - 0.008), floor, subpart=Subpart.Interior),
                support_polygon("bottom", (0, 0, 0), outline_polygon(self._tray_outline(p, g), 0.0005),
                                Subpart.Bottom, up=False),
                Surface.rect("back", Subpart.Back, (-g["D"] / 2, 0.0, g["z1"] / 2), (-1, 0, 0), (0, 1, 0),
                             g["W"] / 2 - 0.001, g["z1"] / 2 - 0.001)]

    def _drain_parts(self, p, g) -> list[Part]:
        c = outline_polygon(self._recess(p, g)).centroid
        return [Part(_drain(c.x, c.y, g["th"] - 0.008, 0.045), "metal")]
