"""Kitchen utensils: knives, forks, spoons, chopsticks, spatulas and cutting boards.

Utensils lie flat on the table, front (+X) towards their working end: heads and blades are flat
extrusions resting on z = 0, handles are swept tubes (`kitchenware._parts.sweep`: an extruded
section bent along a path by one vectorised warp, no booleans) whose ends rest on the table too.
"""
from __future__ import annotations

import math
from collections.abc import Callable

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.kitchenware._parts import sweep
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.primitives import Part, bevel_box, box_between, cylinder
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: how far touching pieces sink into each other so that their union is one shell (m)
SINK = 0.001
CUTLERY_METAL = {"brushed_steel": 3.0, "chrome": 2.0, "brass": 0.3}
BOARD_WOOD = {"oak": 2.0, "walnut": 1.5, "pine_planks": 0.7, "plywood": 0.3}


def lying_path(x0: float, x1: float, thick: Callable[[np.ndarray], np.ndarray],
               rise: Callable[[np.ndarray], np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """The centre line of a handle lying along +X from x0 to x1 whose underside is `rise(t)`
    above the table (0 where it rests)."""
    def path(t: np.ndarray) -> np.ndarray:
        return np.c_[x0 + (x1 - x0) * t, np.zeros_like(t), rise(t) + 0.5 * thick(t)]
    return path


def extrude_outline(poly: sg.Polygon, z0: float, z1: float) -> m3d.Manifold:
    """A shapely polygon (holes allowed) extruded from z0 to z1."""
    rings = [np.asarray(poly.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1]
                                                        for r in poly.interiors]
    cs = m3d.CrossSection(rings, m3d.FillRule.EvenOdd)
    return m3d.Manifold.extrude(cs, z1 - z0).translate((0.0, 0.0, z0))


def _flat_box(x0: float, x1: float, half_y: float, z1: float, slot: str) -> Part:
    """A placeholder box from x0 to x1, +-half_y, z 0..z1."""
    return Part(box_between((x0, -half_y, 0.0), (x1, half_y, z1)), slot)



# ---------------------------------------------------------------------------------- cutlery
def _smooth(a: float, b: float, power: float = 1.0) -> Callable[[np.ndarray], np.ndarray]:
    """t -> a + (b - a) * t**power."""
    return lambda t: a + (b - a) * np.asarray(t) ** power


def _round_end(f: Callable[[np.ndarray], np.ndarray], frac: float = 0.06
               ) -> Callable[[np.ndarray], np.ndarray]:
    """`f` shrunk to a rounded end over the first `frac` of t."""
    def g(t):
        t = np.asarray(t)
        k = np.sqrt(np.clip(1 - ((frac - t) / frac).clip(0, None) ** 2, 0.12, 1.0))
        return f(t) * k
    return g


KNIFE_STYLES = ("table", "chef", "paring", "bread", "cleaver")


def _blade_outline(style: str, L: float, w: float) -> sg.Polygon:
    """Outline of a blade from its heel (x = 0) to its tip (x = L), spine along +Y."""
    x = np.linspace(0.0, L, 17)
    u = x / L
    h = w / 2
    if style in ("table", "bread"):
        k = np.sqrt(np.clip(1 - ((u - 0.8) / 0.2).clip(0, None) ** 2, 0.0, 1.0))
        spine, edge = h * k, -h * k
        spine[-1] = edge[-1] = 0.0
        if style == "bread":
            edge = edge + 0.0012 * (np.arange(len(x)) % 2) * (u < 0.9)
    elif style == "cleaver":
        k = np.sqrt(np.clip(1 - ((u - 0.93) / 0.07).clip(0, None) ** 2, 0.0, 1.0))
        r = h * (1 - k)  # both front corners round off
        spine, edge = h - r, -h + r
        spine[-1], edge[-1] = 0.25 * h, -0.25 * h
    else:  # chef / paring: straight spine dropping to a point, edge curving up to it
        tip = 0.4 * h
        spine = h - (h - tip) * ((u - 0.65) / 0.35).clip(0, None) ** 2
        edge = -h + (h + tip) * ((u - 0.45) / 0.55).clip(0, None) ** 1.8
        spine[-1] = edge[-1] = tip
    pts = np.vstack([np.c_[x, edge], np.c_[x[::-1], spine[::-1]]])
    poly = sg.Polygon(pts).buffer(0)
    if style == "cleaver":
        poly = poly.difference(sg.Point(0.85 * L, 0.6 * h).buffer(0.006, quad_segs=8))
    return poly


@register
class Knife(PartsFactory):
    """A knife lying flat, tip towards +X: table knife, chef's knife, paring knife, bread knife
    (serrated) or cleaver (with its hanging hole); the blade rests on its tip and rises to the
    middle of the handle (metal, wood with rivets, or plastic), optionally with a bolster."""

    name = "knife"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Kitchenware, S.Cutlery,
                      S.Knife})
    size_class = "small"
    slots = ["metal", "wood", "plastic"]
    material_choices = {"metal": CUTLERY_METAL}
    params = {
        "style": Param(kind="choice", choices=KNIFE_STYLES, doc="kind of knife"),
        "blade_length": Param(0.09, 0.22, doc="blade length (paring: x0.5) (m)"),
        "blade_width": Param(0.018, 0.05, doc="blade width (table: x0.5, cleaver: x1.8) (m)"),
        "blade_thickness": Param(0.0015, 0.003, doc="blade thickness (m)"),
        "handle_length": Param(0.09, 0.13, doc="handle length (m)"),
        "handle_thickness": Param(0.012, 0.022, doc="handle thickness (m)"),
        "handle_material": Param(kind="choice", choices=("metal", "wood", "plastic"),
                                 doc="handle material (wood gets rivets)"),
        "bolster": Param(kind="bool", doc="a metal collar between handle and blade"),
    }

    def _dims(self, p) -> tuple[float, float, float, float, float]:
        """(blade length, blade width, handle length, handle width, handle thickness)."""
        s = p["style"]
        L = p["blade_length"] * (0.5 if s == "paring" else 1.0)
        w = p["blade_width"] * {"table": 0.5, "cleaver": 1.8, "paring": 0.6}.get(s, 1.0)
        ht = p["handle_thickness"]
        return L, w, p["handle_length"], 0.024 if s == "cleaver" else 0.02, ht

    def _top(self, p) -> float:
        ht = self._dims(p)[4]
        return ht + (0.0003 if p["handle_material"] == "wood" else 0.0)

    def parts(self, p, detail):
        """The knife's solids: detailed, or the blocks of its placeholder."""
        L, w, Lh, hw, ht = self._dims(p)
        hmat = p["handle_material"]
        if not detail:
            half = max(w / 2, 0.5 * hw * (1.1 if p["bolster"] else 1.05))
            return [_flat_box(-Lh, L, half, self._top(p), "metal")]
        tb = p["blade_thickness"]
        blade = extrude_outline(_blade_outline(p["style"], L, w), 0.0, tb)
        lift = (ht - tb) / 2  # the heel at the handle's mid-height, the tip on the table
        blade = blade.transform(np.array([[1, 0, 0, 0], [0, 1, 0, 0], [-lift / L, 0, 1, lift]],
                                         float))
        tang = box_between((-0.03, -0.2 * hw, lift), (0.001, 0.2 * hw, lift + tb))
        width = _round_end(_smooth(1.05 * hw, 0.95 * hw))
        thick = _round_end(_smooth(ht, 0.92 * ht))
        handle = sweep(lying_path(-Lh, -0.002, thick, lambda t: 0.0 * t), width, thick, 12,
                       floor=True)
        out = [Part(blade, "metal"), Part(tang, "metal"), Part(handle, hmat)]
        if p["bolster"]:  # a collar as thick as the handle, a little wider, tapering forward
            bthick = _smooth(ht, 0.5 * ht)
            out.append(Part(sweep(lying_path(-0.006, 0.012, bthick,
                                             lambda t: (ht - bthick(t)) / 2),
                                  _smooth(1.1 * hw, 0.6 * hw), bthick, 3), "metal"))
        if hmat == "wood":
            for xr in (-0.8 * Lh, -0.5 * Lh, -0.2 * Lh):
                out.append(Part(cylinder(0.0022, 0.0025, (xr, 0.0, ht - 0.0022), 12), "metal"))
        return out


def _handle(x0: float, x1: float, w_end: float, w_neck: float, t_end: float, t_neck: float,
            hump: float, n: int = 14, rise_to: float = 0.0) -> m3d.Manifold:
    """A cutlery handle from its rounded end (x0, resting on the table) to its neck (x1, whose
    underside is `rise_to` up), arching `hump` above the table in between."""
    width = _round_end(_smooth(w_end, w_neck, 1.3))
    thick = _round_end(_smooth(t_end, t_neck))

    def rise(t):
        t = np.asarray(t)
        return hump * np.sin(math.pi * t) ** 1.2 * (1 - t) + rise_to * t ** 2

    return sweep(lying_path(x0, x1, thick, rise), width, thick, n, floor=True)


@register
class Fork(PartsFactory):
    """A table fork lying on its back, tines towards +X: a flat head with 2-4 tines (slots cut
    out, corners rounded) and a handle that arches off the table and tapers to a narrow neck."""

    name = "fork"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cutlery, S.Fork})
    size_class = "small"
    slots = ["metal", "wood", "plastic"]
    material_choices = {"metal": CUTLERY_METAL}
    params = {
        "tines": Param(2, 4, kind="int", doc="number of tines"),
        "head_length": Param(0.035, 0.055, doc="head length, neck to tips (m)"),
        "head_width": Param(0.02, 0.03, doc="head width (m)"),
        "handle_length": Param(0.11, 0.15, doc="handle length (m)"),
        "handle_width": Param(0.012, 0.024, doc="handle width at its end (m)"),
        "thickness": Param(0.0018, 0.0035, doc="metal thickness (m)"),
        "hump": Param(0.003, 0.012, doc="how high the handle arches off the table (m)"),
        "handle_material": Param(kind="choice", choices=("metal", "wood", "plastic"),
                                 doc="handle material"),
    }

    def _head(self, p) -> sg.Polygon:
        L, W, n = p["head_length"], p["head_width"], int(p["tines"])
        wn = 0.006
        x = np.linspace(0.0, L, 9)
        half = (wn + (W - wn) * np.sin(0.5 * math.pi * np.minimum(x / (0.4 * L), 1.0))) / 2
        poly = sg.Polygon(np.vstack([np.c_[x, -half], np.c_[x[::-1], half[::-1]]]))
        sw = W * (0.12 if n > 2 else 0.3)
        tw = (W - (n - 1) * sw) / n
        for i in range(n - 1):
            y0 = -W / 2 + (i + 1) * tw + i * sw
            poly = poly.difference(sg.box(0.45 * L, y0, L + 0.01, y0 + sw))
        r = 0.3 * min(tw, sw)
        return poly.buffer(-r, join_style="round", quad_segs=3).buffer(
            r, join_style="round", quad_segs=3)

    def parts(self, p, detail):
        """The fork's solids: detailed, or the blocks of its placeholder."""
        L, W, Lh = p["head_length"], p["head_width"], p["handle_length"]
        t, hw = p["thickness"], p["handle_width"]
        th_end = 1.5 * t
        top = max(p["hump"] + th_end, 1.5 * t) + 0.0005
        if not detail:
            return [_flat_box(-Lh, L, max(W, hw) / 2, top, "metal")]
        head = extrude_outline(self._head(p), 0.0, t)
        handle = _handle(-Lh, 0.004, hw, 0.006, th_end, t, p["hump"])
        return [Part(head, "metal"), Part(handle, p["handle_material"])]


@register
class Spoon(PartsFactory):
    """A spoon lying on its back, bowl towards +X: teaspoon to serving spoon sizes, an oval or
    round hollow bowl (a half-ellipsoid shell flattened where it rests) and a handle rising from
    the table to the bowl's rim."""

    name = "spoon"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cutlery, S.Spoon})
    size_class = "small"
    slots = ["metal", "wood", "plastic"]
    material_choices = {"metal": CUTLERY_METAL}
    params = {
        "bowl_length": Param(0.04, 0.075, doc="bowl length (m)"),
        "bowl_width_frac": Param(0.55, 0.9, doc="bowl width / length (round: soup spoon)"),
        "bowl_depth": Param(0.006, 0.014, doc="bowl depth (m)"),
        "handle_length": Param(0.09, 0.16, doc="handle length (m)"),
        "handle_width": Param(0.012, 0.026, doc="handle width at its end (m)"),
        "thickness": Param(0.0015, 0.003, doc="metal thickness (m)"),
        "material": Param(kind="choice", choices=("metal", "wood", "plastic"),
                          doc="material (wood: thicker)"),
    }

    def _dims(self, p) -> tuple[float, float, float, float]:
        """(half length, half width, depth, thickness) of the bowl."""
        t = p["thickness"] * (2.0 if p["material"] == "wood" else 1.0)
        a = p["bowl_length"] / 2
        return a, a * p["bowl_width_frac"], max(p["bowl_depth"], 2.5 * t), t

    def _bowl(self, p) -> m3d.Manifold:
        a, b, c, t = self._dims(p)
        unit = m3d.Manifold.sphere(1.0, 28)
        outer = unit.scale((a, b, c)).translate((a, 0.0, c)).trim_by_plane((0, 0, -1), -c)
        inner = unit.scale((a - t, b - t, c - t)).translate((a, 0.0, c))
        return (outer - inner).translate((0.0, 0.0, -0.0004)).trim_by_plane((0, 0, 1), 0.0)

    def parts(self, p, detail):
        """The spoon's solids: detailed, or the blocks of its placeholder."""
        a, b, c, t = self._dims(p)
        Lh, hw = p["handle_length"], p["handle_width"]
        top = c + 0.35 * t  # the neck rises a little above the rim
        if not detail:
            return [_flat_box(-Lh, 2 * a, max(b, hw / 2), top, p["material"])]
        handle = _handle(-Lh, 0.005, hw, 0.0075, 1.3 * t, 1.3 * t, 0.0,
                         rise_to=c - 0.0004 - 0.95 * 1.3 * t)
        return [Part(self._bowl(p), p["material"]), Part(handle, p["material"])]


@register
class Chopsticks(PartsFactory):
    """A pair of chopsticks lying side by side, touching at their thick ends and splaying
    slightly towards their tips (+X); round or square, optionally with their tips raised on a
    small ceramic rest."""

    name = "chopsticks"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cutlery, S.Chopsticks})
    size_class = "small"
    slots = ["wood", "plastic", "metal", "ceramic"]
    material_choices = {"metal": CUTLERY_METAL}
    params = {
        "length": Param(0.2, 0.27, doc="length (m)"),
        "radius": Param(0.0035, 0.005, doc="half-thickness at the thick end (m)"),
        "tip_frac": Param(0.35, 0.6, doc="tip thickness / thick-end thickness"),
        "section": Param(kind="choice", choices=("round", "square"), doc="cross-section"),
        "spread": Param(0.0, 4.0, doc="angle between the two (degrees)"),
        "rest": Param(kind="bool", doc="tips raised on a chopstick rest"),
        "material": Param(kind="choice", choices=("wood", "plastic", "metal"), doc="material"),
    }

    REST_H = 0.012

    def _geometry(self, p) -> tuple[float, float, float, float]:
        """(rest x, rise of the underside per metre, half-spread angle, y offset)."""
        L, r = p["length"], p["radius"]
        xr = 0.75 * L
        slope = (self.REST_H - SINK) / xr if p["rest"] else 0.0
        return xr, slope, math.radians(p["spread"]) / 2, r - 0.0005

    def _stick(self, p) -> m3d.Manifold:
        L, r = p["length"], p["radius"]
        xr, slope, _, _ = self._geometry(p)
        thick = _smooth(2 * r, 2 * r * p["tip_frac"])
        path = lying_path(0.0, L, thick, lambda t: slope * L * np.asarray(t))
        return sweep(path, thick, thick, 6, p["section"], floor=True)

    def _rest_box(self, p) -> tuple[np.ndarray, np.ndarray]:
        r = p["radius"]
        xr, _, ang, off = self._geometry(p)
        half = off + (xr + 0.01) * math.tan(ang) + r + 0.006
        return np.array([xr - 0.008, -half, 0.0]), np.array([xr + 0.008, half, self.REST_H])

    def parts(self, p, detail):
        """The chopsticks' solids: detailed, or the blocks of its placeholder."""
        L, r = p["length"], p["radius"]
        xr, slope, ang, off = self._geometry(p)
        mat = p["material"]
        if not detail:
            half = off + L * math.sin(ang) + r * (1 + math.sin(ang)) + 1e-4
            if p["rest"]:
                half = max(half, self._rest_box(p)[1][1])
            # the thick end, the raised tips or the rest, whichever is highest
            top = max(2 * r, slope * L + 2 * r * p["tip_frac"],
                      self.REST_H if p["rest"] else 0.0) + 1e-4
            return [Part(box_between((0.0, -half, 0.0), (L * math.cos(ang) + r * math.sin(ang)
                                                          + 1e-4, half, top)), mat)]
        out = []
        for s in (-1, 1):
            stick = self._stick(p).rotate((0.0, 0.0, s * math.degrees(ang))).translate(
                (0.0, s * off, 0.0))
            out.append(Part(stick, mat))
        if p["rest"]:
            lo, hi = self._rest_box(p)
            out.append(Part(bevel_box(hi - lo, (lo + hi) / 2, 0.004, 2), "ceramic"))
        return out


@register
class Spatula(PartsFactory):
    """A kitchen spatula lying flat, head towards +X: a metal turner (thin square head, slotted),
    a silicone scraper (thicker head, rounded corners) or a wooden spatula; the handle arches off
    the table from its rounded end to the neck."""

    name = "spatula"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Spatula})
    size_class = "small"
    slots = ["metal", "rubber", "wood", "plastic"]
    material_choices = {"metal": CUTLERY_METAL}
    params = {
        "style": Param(kind="choice", choices=("turner", "scraper", "wooden"), doc="kind"),
        "head_length": Param(0.06, 0.11, doc="head length (m)"),
        "head_width": Param(0.045, 0.09, doc="head width (m)"),
        "handle_length": Param(0.14, 0.22, doc="handle length (m)"),
        "handle_width": Param(0.018, 0.03, doc="handle width at its end (m)"),
        "slots": Param(0, 4, kind="int", doc="slots through a turner's head"),
        "hump": Param(0.005, 0.02, doc="how high the handle arches off the table (m)"),
    }

    #: style -> (head thickness, corner radius / width, head slot, handle slot)
    STYLES = {"turner": (0.0015, 0.08, "metal", "plastic"),
              "scraper": (0.004, 0.3, "rubber", "plastic"),
              "wooden": (0.005, 0.25, "wood", "wood")}

    def _head(self, p) -> sg.Polygon:
        L, W, style = p["head_length"], p["head_width"], p["style"]
        _, cr, _, _ = self.STYLES[style]
        r = cr * W
        # a blade widening from the neck to the full width, square or rounded at the front
        neck = 0.012
        x0 = -0.005
        poly = sg.Polygon([(x0, -neck / 2), (0.3 * L, -W / 2), (L, -W / 2), (L, W / 2),
                           (0.3 * L, W / 2), (x0, neck / 2)])
        poly = poly.buffer(-r, join_style="round", quad_segs=4).buffer(
            r, join_style="round", quad_segs=4)
        n = int(p["slots"]) if style == "turner" else 0
        if n:
            sw = min(0.005, 0.5 * W / (2 * n))
            for y in (np.arange(n) - (n - 1) / 2) * (0.7 * W / max(n, 1)):
                poly = poly.difference(sg.box(0.35 * L, y - sw / 2, 0.85 * L, y + sw / 2)
                                       .buffer(sw / 2 * 0.99, quad_segs=3))
        return poly

    def parts(self, p, detail):
        """The spatula's solids: detailed, or the blocks of its placeholder."""
        L, W, Lh = p["head_length"], p["head_width"], p["handle_length"]
        t, _, head_slot, handle_slot = self.STYLES[p["style"]]
        hw = p["handle_width"]
        th = 0.008 if p["style"] != "turner" else 0.01
        top = p["hump"] + th + 0.0005
        if not detail:
            return [_flat_box(-Lh, L, max(W, hw) / 2, top, head_slot)]
        head = extrude_outline(self._head(p), 0.0, t)
        handle = _handle(-Lh, 0.004, hw, 0.011, th, max(t * 1.2, 0.004), p["hump"])
        return [Part(head, head_slot), Part(handle, handle_slot)]


BOARD_STYLES = ("rect", "rounded", "paddle")


@register
class CuttingBoard(PartsFactory):
    """A cutting board: rectangular, rounded, or a paddle with a handle tab (towards +X); edges
    chamfered, optionally a grip hole (cut through) and a juice groove; its top (inside the
    groove, clear of the hole) is a support surface."""

    name = "cutting_board"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.CuttingBoard})
    size_class = "small"
    slots = ["wood", "plastic"]
    material_choices = {"wood": BOARD_WOOD}
    params = {
        "length": Param(0.25, 0.45, doc="X extent of the board (without a paddle's tab) (m)"),
        "width": Param(0.15, 0.32, doc="Y extent (m)"),
        "thickness": Param(0.012, 0.04, doc="thickness (m)"),
        "style": Param(kind="choice", choices=BOARD_STYLES, doc="outline"),
        "corner_radius": Param(0.005, 0.04, doc="corner rounding (rounded/paddle) (m)"),
        "handle_hole": Param(kind="bool", doc="a grip hole through the board (or tab)"),
        "juice_groove": Param(kind="bool", doc="a groove around the top"),
        "chamfer": Param(0.001, 0.004, doc="edge chamfer (m)"),
        "plastic": Param(kind="bool", doc="plastic board (else wood)"),
    }

    def _outlines(self, p) -> list[sg.Polygon]:
        """Convex pieces of the outline (board, and a paddle's tab)."""
        L, W, s = p["length"], p["width"], p["style"]
        r = 0.002 if s == "rect" else min(p["corner_radius"], 0.3 * W)
        board = sg.box(-L / 2 + r, -W / 2 + r, L / 2 - r, W / 2 - r).buffer(r, quad_segs=4)
        if s != "paddle":
            return [board]
        tw, tl = 0.35 * W, self._tab(p)
        tab = sg.box(L / 2 - 0.02, -tw / 2 + 0.01, L / 2 + tl - 0.01, tw / 2 - 0.01).buffer(
            0.01, quad_segs=4)
        return [board, tab]

    def _tab(self, p) -> float:
        return 0.1 if p["style"] == "paddle" else 0.0

    def _hole(self, p) -> sg.Polygon | None:
        if not p["handle_hole"]:
            return None
        L = p["length"]
        if p["style"] == "paddle":
            return sg.Point(L / 2 + self._tab(p) - 0.03, 0.0).buffer(0.012, quad_segs=4)
        return sg.LineString([(L / 2 - 0.045, -0.035), (L / 2 - 0.045, 0.035)]).buffer(
            0.011, quad_segs=4)

    def _groove(self, p) -> tuple[sg.Polygon, float] | None:
        """(the groove's ring, its depth)."""
        if not p["juice_groove"]:
            return None
        outer = self._outlines(p)[0].buffer(-0.015)
        return outer.difference(outer.buffer(-0.006)), min(0.003, 0.3 * p["thickness"])

    def _slab(self, poly: sg.Polygon, T: float, c: float) -> m3d.Manifold:
        """A convex outline extruded T thick with its top and bottom edges chamfered by c."""
        inner = poly.buffer(-c, join_style="mitre")
        return m3d.Manifold.batch_hull([extrude_outline(inner, 0.0, T),
                                        extrude_outline(poly, c, T - c)])

    def parts(self, p, detail):
        """The cutting board's solids: detailed, or the blocks of its placeholder."""
        T, slot = p["thickness"], "plastic" if p["plastic"] else "wood"
        L, W = p["length"], p["width"]
        if not detail:
            return [Part(box_between((-L / 2, -W / 2, 0.0), (L / 2 + self._tab(p), W / 2, T)),
                         slot)]
        c = min(p["chamfer"], 0.3 * T)
        body = solid_union([self._slab(q, T, c) for q in self._outlines(p)])
        hole, groove = self._hole(p), self._groove(p)
        if hole is not None:
            body = body - extrude_outline(hole, -0.01, T + 0.01)
        if groove is not None:
            ring, depth = groove
            body = body - extrude_outline(ring, T - depth, T + 0.01)
        return [Part(body, slot)]

    def _top_polygon(self, p) -> sg.Polygon:
        c = min(p["chamfer"], 0.3 * p["thickness"])
        top = self._outlines(p)[0].buffer(-c - 0.002)
        if p["juice_groove"]:
            top = self._outlines(p)[0].buffer(-0.015 - 0.006 - 0.002)
        hole = self._hole(p)
        if hole is not None and p["style"] != "paddle":
            x_cut = hole.bounds[0] - 0.004
            top = top.intersection(sg.box(-10, -10, x_cut, 10))
        return top.simplify(1e-5)

    def bottom_is_solid(self, params):
        """Whether the board's whole underside is solid (no hanging hole through it)."""
        return not self.resolve(params)["handle_hole"]

    def extra_surfaces(self, p):
        """The cutting board's surfaces besides its bounding box's: top, bottom."""
        c = min(p["chamfer"], 0.3 * p["thickness"])
        outline = self._outlines(p)
        bottom = (outline[0].union(outline[1]) if len(outline) > 1 else outline[0]).buffer(
            -c - 0.0005).simplify(1e-5)
        return [support_polygon("top", (0, 0, p["thickness"]), self._top_polygon(p)),
                support_polygon("bottom", (0, 0, 0), bottom, subpart=Subpart.Bottom, up=False)]
