"""Bathroom accessories on the wall: towel bars and rings, toilet-roll holders, robe hooks and
mirror cabinets. Each hangs from the wall at its back (-X): its back plate(s) are flat at the
bounding box's back, and its "back" surface lies on (the first) plate's back face.

Hardware is listed as primitives (see `bathroom._parts.Prim`), so the placeholder boxes
come from exact bounds without building any solid.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.bathroom._parts import FIXTURE_MATERIALS, Prim, prim_bounds, prim_solid
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass
from indoorgen.assets.shapes.moving_parts import Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

PLATE = 0.012  # thickness of a wall plate or rosette (m)
TOWEL = 0.01  # thickness of a folded towel's layer (m)
HOOK_PLATE_ASPECT = 1.5  # a robe hook's plate is taller than wide
SHELF_CLEARANCE = 0.12  # least height between a mirror cabinet's shelves (bottles) (m)

def _plate(shape: str, size: float, y: float, z: float, aspect: float = 1.0) -> Prim:
    """A round (oval) rosette or square (oblong) plate on the wall (x = 0), centred on (y, z):
    `size` wide and `aspect` times as tall."""
    if shape == "round":
        return ("oval", (0.0, y, z), PLATE, size, size * aspect)
    return ("box", (0.0, y - size / 2, z - size * aspect / 2), (PLATE, y + size / 2, z + size * aspect / 2))


def _plate_back(shape: str, size: float, y: float, z: float, aspect: float = 1.0) -> Surface:
    """The back surface: a rectangle inside a plate's back face (x = 0)."""
    k = 0.68 if shape == "round" else 0.98
    return Surface.rect("back", Subpart.Back, (0.0, y, z), (-1, 0, 0), (0, 1, 0), k * size / 2,
                        k * size * aspect / 2)


def _towel(x: float, y: float, z: float, r: float, width: float, drop: float,
           back_drop: float) -> list[Prim]:
    """A towel folded over a horizontal Y-axis bar of radius r at (x, *, z): it wraps the bar
    and hangs `drop` in front and `back_drop` behind it."""
    wrap = r + TOWEL
    return [("rod", (x, y - width / 2, z), (x, y + width / 2, z), wrap),
            ("box", (x + r - OVERLAP, y - width / 2, z - drop), (x + wrap, y + width / 2, z)),
            ("box", (x - wrap, y - width / 2, z - back_drop), (x - r + OVERLAP, y + width / 2, z))]


def _parts(groups: list[tuple[list[Prim], str]], detail: bool) -> list[Part]:
    """Primitive groups (prims, slot) as parts: each primitive's solid, or one box per group."""
    out = []
    for prims, slot in groups:
        if not prims:
            continue
        if detail:
            out += [Part(prim_solid(q), slot) for q in prims]
        else:
            out.append(Part(box_between(*prim_bounds(prims)), slot))
    return out


class _WallHardware(PartsFactory):
    """Shared protocol of the small wall fittings: `groups(p)` lists (primitives, slot)."""

    size_class = "medium"
    slots = ["metal", "fabric"]
    material_choices = {"metal": FIXTURE_MATERIALS["metal"]}

    def groups(self, p: dict[str, Any]) -> list[tuple[list[Prim], str]]:
        raise NotImplementedError

    def parts(self, p, detail):
        return _parts(self.groups(p), detail)


@register
class TowelBar(_WallHardware):
    """A towel bar: one or two parallel bars (round, square or flat) held off the wall by posts
    on round or square rosettes, optionally with a towel folded over the front bar."""

    name = "towel_bar"
    tags = frozenset({S.Object, S.BathroomFixture, S.TowelBar, S.WallMounted})
    params = {
        "length": Param(0.3, 0.9, doc="distance between the rosettes' centres (m)"),
        "projection": Param(0.05, 0.09, doc="wall to the front bar's axis (double: >= 7.5 cm) (m)"),
        "bar_shape": Param(kind="choice", choices=("round", "square", "flat"), doc="bar section"),
        "bar_size": Param(0.012, 0.025, doc="bar diameter or height (m)"),
        "rosette": Param(kind="choice", choices=("round", "square"), doc="wall plate shape"),
        "rosette_size": Param(0.045, 0.07, doc="wall plate diameter or side (m)"),
        "double": Param(kind="bool", doc="a second bar behind the first"),
        "towel": Param(kind="bool", doc="a towel folded over the front bar"),
        "towel_width": Param(0.3, 0.6, doc="towel width (at most the bar's free length) (m)"),
        "towel_drop": Param(0.2, 0.42, doc="how far the towel hangs below the bar (m)"),
    }

    def _bars(self, p) -> list[float]:
        """x of each bar's axis, front first."""
        if p["double"]:
            front = max(p["projection"], 0.075)
            return [front, front - 0.04]
        return [p["projection"]]

    def _bar(self, p, x: float, y0: float, y1: float) -> Prim:
        r = p["bar_size"] / 2
        if p["bar_shape"] == "round":
            return ("rod", (x, y0, 0.0), (x, y1, 0.0), r)
        hx = r if p["bar_shape"] == "square" else 0.004
        return ("box", (x - hx, y0, -r), (x + hx, y1, r))

    def groups(self, p):
        """The towel bar's fittings as (primitives, material slot) groups."""
        L, rs = p["length"], p["rosette_size"]
        bars = self._bars(p)
        hw: list[Prim] = []
        for y in (-L / 2, L / 2):
            hw += [_plate(p["rosette"], rs, y, 0.0),
                   ("rod", (PLATE - OVERLAP, y, 0.0), (bars[0], y, 0.0), 0.009),
                   ("sphere", (bars[0], y, 0.0), max(p["bar_size"] / 2 + 0.004, 0.011))]
        hw += [self._bar(p, x, -L / 2, L / 2) for x in bars]
        towel: list[Prim] = []
        if p["towel"]:
            w = min(p["towel_width"], L - 0.06)
            towel = _towel(bars[0], 0.0, 0.0, p["bar_size"] / 2 + 0.001, w, p["towel_drop"],
                           0.85 * p["towel_drop"])
        return [(hw, "metal"), (towel, "fabric")]

    def extra_surfaces(self, p):
        """The towel bar's surfaces besides its bounding box's: back (a rosette's back face)."""
        return [_plate_back(p["rosette"], p["rosette_size"], -p["length"] / 2, 0.0)]


@register
class TowelRing(_WallHardware):
    """A towel ring: a round, square or open (hoop) ring hanging parallel to the wall from an arm
    on a round or square plate, optionally with a towel drawn through it."""

    name = "towel_ring"
    tags = frozenset({S.Object, S.BathroomFixture, S.TowelRing, S.WallMounted})
    params = {
        "plate": Param(kind="choice", choices=("round", "square"), doc="wall plate shape"),
        "plate_size": Param(0.04, 0.07, doc="wall plate diameter or side (m)"),
        "projection": Param(0.045, 0.08, doc="wall to the ring's plane (m)"),
        "ring": Param(kind="choice", choices=("round", "square", "hoop"),
                      doc="closed ring, square frame, or a hoop under a bar"),
        "ring_diameter": Param(0.15, 0.22, doc="outer size of the ring (m)"),
        "tube": Param(0.008, 0.014, doc="diameter of the ring's tube (m)"),
        "towel": Param(kind="bool", doc="a towel drawn through the ring"),
        "towel_drop": Param(0.15, 0.35, doc="how far the towel hangs below the ring (m)"),
    }

    def groups(self, p):
        """The towel ring's fittings as (primitives, material slot) groups."""
        x = p["projection"]
        r = p["tube"] / 2
        R = p["ring_diameter"] / 2 - r
        zc = -0.02 - R  # the ring hangs from the arm's end
        hw: list[Prim] = [_plate(p["plate"], p["plate_size"], 0.0, 0.0),
                          ("rod", (PLATE - OVERLAP, 0.0, 0.0), (x, 0.0, 0.0), 0.007),
                          ("sphere", (x, 0.0, 0.0), 0.011)]
        rv = min(0.005, 0.85 * r)  # hangers and uprights: thinner, ending inside the tube
        if p["ring"] == "round":
            hw += [("rod", (x, 0.0, 0.0), (x, 0.0, zc + R), rv), ("ring", (x, 0.0, zc), R, r)]
        elif p["ring"] == "square":
            top, bot = zc + R, zc - R
            hw += [("rod", (x, 0.0, 0.0), (x, 0.0, top), rv),
                   ("rod", (x, -R - r, top), (x, R + r, top), r),
                   ("rod", (x, -R - r, bot), (x, R + r, bot), r),
                   ("rod", (x, -R, top), (x, -R, bot), 0.85 * r), ("rod", (x, R, top), (x, R, bot), 0.85 * r)]
        else:  # a hoop hanging from a bar across the arm's end
            hw += [("rod", (x, -R - r, -0.012), (x, R + r, -0.012), r),
                   ("rod", (x, -R, -0.012), (x, -R, zc - r), 0.85 * r),
                   ("rod", (x, R, -0.012), (x, R, zc - r), 0.85 * r),
                   ("hoop", (x, 0.0, zc), R, r)]
        towel: list[Prim] = []
        if p["towel"]:
            zb = zc - R  # the towel rests on the bottom of the ring
            towel = _towel(x, 0.0, zb, r + 0.001, 0.9 * R, p["towel_drop"], p["towel_drop"] * 0.9)
        return [(hw, "metal"), (towel, "fabric")]

    def extra_surfaces(self, p):
        """The towel ring's surfaces besides its bounding box's: back (its plate's back face)."""
        return [_plate_back(p["plate"], p["plate_size"], 0.0, 0.0)]


@register
class ToiletRollHolder(_WallHardware):
    """A toilet-roll holder: an open L-arm on one plate, a bar between two plates, or an arm
    under a curved cover; optionally holding a roll of paper (a tube on the spindle)."""

    name = "toilet_roll_holder"
    tags = frozenset({S.Object, S.BathroomFixture, S.ToiletRollHolder, S.WallMounted})
    slots = ["metal", "paper"]
    material_choices = {"metal": FIXTURE_MATERIALS["metal"]}
    params = {
        "style": Param(kind="choice", choices=("arm", "bar", "cover"),
                       doc="open arm, bar between two plates, or arm with a cover"),
        "plate": Param(kind="choice", choices=("round", "square"), doc="wall plate shape"),
        "plate_size": Param(0.04, 0.07, doc="wall plate diameter or side (m)"),
        "roll": Param(kind="bool", doc="a roll on the spindle"),
        "roll_radius": Param(0.045, 0.06, doc="outer radius of the roll (m)"),
        "roll_width": Param(0.095, 0.11, doc="width of the roll (m)"),
        "spindle_radius": Param(0.006, 0.01, doc="radius of the arm or bar (m)"),
    }

    def _spindle(self, p) -> tuple[float, float, float]:
        """(spindle x, y of the (first) plate, y of the spindle's free end or second plate)."""
        x = max(p["roll_radius"], 0.055) + 0.015
        half = p["roll_width"] / 2 + 0.02
        return x, -half, half

    def groups(self, p):
        """The toilet-roll holder's fittings as (primitives, material slot) groups."""
        x, y0, y1 = self._spindle(p)
        ps, ra = p["plate_size"], p["spindle_radius"]
        hw: list[Prim] = [_plate(p["plate"], ps, y0, 0.0),
                          ("rod", (PLATE - OVERLAP, y0, 0.0), (x, y0, 0.0), ra),
                          ("sphere", (x, y0, 0.0), ra * 1.3)]
        if p["style"] == "bar":
            hw += [_plate(p["plate"], ps, y1, 0.0), ("rod", (PLATE - OVERLAP, y1, 0.0), (x, y1, 0.0), ra),
                   ("sphere", (x, y1, 0.0), ra * 1.3), ("rod", (x, y0, 0.0), (x, y1, 0.0), ra)]
        else:
            hw += [("rod", (x, y0, 0.0), (x, y1 - 0.01, 0.0), ra), ("sphere", (x, y1 - 0.01, 0.0), ra * 1.4)]
        roll: list[Prim] = []
        if p["roll"]:
            core = 0.021
            zr = ra - core - 0.0025  # the roll hangs on the spindle (2.5 mm overlap)
            roll = [("tube", (x, -p["roll_width"] / 2, zr), p["roll_width"], p["roll_radius"], core)]
        return [(hw, "metal"), (roll, "paper")]

    def _cover(self, p) -> tuple[m3d.Manifold, tuple[np.ndarray, np.ndarray]]:
        """A curved sheet over the roll from the plate's top, and its bounds."""
        x, y0, y1 = self._spindle(p)
        R = max(p["roll_radius"], 0.055) + 0.012
        # a ring sector about the spindle in the (x, -z) plane, from the wall over the top to
        # 40 degrees in front, extruded along Y: extruding along +Z and turning -90 degrees
        # about X maps (u, v, w) to (u, w, -v)
        a_max = math.degrees(math.acos(max(-1.0, (0.003 - x) / (R + 0.003))))
        a = np.radians(np.linspace(a_max, 40.0, 24))
        outer = np.c_[x + (R + 0.003) * np.cos(a), -(R + 0.003) * np.sin(a)]
        inner = np.c_[x + R * np.cos(a), -R * np.sin(a)][::-1]
        pts = np.vstack([outer, inner])
        width = y1 - y0 + 0.01
        cs = m3d.CrossSection([pts], m3d.FillRule.NonZero)
        sheet = m3d.Manifold.extrude(cs, width).rotate((-90.0, 0.0, 0.0)).translate((0.0, y0 - 0.005, 0.0))
        # a back plate from the wall plate's top up to the sheet's back edge
        z_back = (R + 0.003) * math.sin(math.radians(a_max))
        zb0 = min(p["plate_size"] / 2 - 0.005, z_back - 0.004)
        back = box_between((0.0, y0 - 0.005, zb0), (0.006, y0 - 0.005 + width, z_back + 0.006))
        lo = np.array([0.0, y0 - 0.005, min(zb0, -pts[:, 1].max())])
        hi = np.array([pts[:, 0].max(), y0 - 0.005 + width, max(-pts[:, 1].min(), z_back + 0.006)])
        return sheet + back, (lo, hi)

    def parts(self, p, detail):
        """The toilet-roll holder's solids: detailed, or the blocks of its placeholder."""
        out = []
        for prims, slot in self.groups(p):
            tubes = [q for q in prims if q[0] == "tube"]
            rest = [q for q in prims if q[0] != "tube"]
            if rest:
                out += _parts([(rest, slot)], detail)
            for _, (cx, cy, cz), w, ro, ri in tubes:
                if detail:
                    # turned half a step: the roll rests on a facet, not an edge
                    ring = (m3d.CrossSection.circle(ro, 48) - m3d.CrossSection.circle(ri, 24)).rotate(3.75)
                    out.append(Part(m3d.Manifold.extrude(ring, w).rotate((-90.0, 0.0, 0.0))
                                    .translate((cx, cy, cz)), slot))
                else:  # the 48-gon turned half a step reaches ro * cos(3.75 deg) on the axes
                    re = ro * math.cos(math.radians(3.75))
                    out.append(Part(box_between((cx - re, cy, cz - re), (cx + re, cy + w, cz + re)), slot))
        if p["style"] == "cover":
            solid, (lo, hi) = self._cover(p)
            out.append(Part(solid if detail else box_between(tuple(lo), tuple(hi)), "metal"))
        return out

    def extra_surfaces(self, p):
        """The holder's surfaces besides its bounding box's: back (its plate's back face)."""
        _, y0, _ = self._spindle(p)
        return [_plate_back(p["plate"], p["plate_size"], y0, 0.0)]


@register
class RobeHook(_WallHardware):
    """A robe hook: one prong (or a long upper and a short lower prong) rising from a round or
    square plate, ending in a ball or a flat disc."""

    name = "robe_hook"
    tags = frozenset({S.Object, S.BathroomFixture, S.RobeHook, S.WallMounted})
    slots = ["metal"]
    params = {
        "style": Param(kind="choice", choices=("single", "double"), doc="one or two prongs"),
        "plate": Param(kind="choice", choices=("round", "square"), doc="wall plate shape"),
        "plate_size": Param(0.035, 0.06, doc="wall plate width (1.5 times as tall) (m)"),
        "projection": Param(0.04, 0.08, doc="how far the prong reaches from the wall (m)"),
        "prong_radius": Param(0.004, 0.008, doc="prong radius (m)"),
        "tip": Param(kind="choice", choices=("ball", "disc"), doc="end of the prong"),
        "rise": Param(0.015, 0.05, doc="how far the tip rises above the prong's root (m)"),
    }

    def _prong(self, p, z: float, reach: float, rise: float) -> list[Prim]:
        r = p["prong_radius"]
        xm = PLATE + 0.55 * (reach - PLATE)
        end = (reach, 0.0, z + rise)
        out: list[Prim] = [("rod", (PLATE - OVERLAP, 0.0, z), (xm, 0.0, z - 0.006), r),
                           ("sphere", (xm, 0.0, z - 0.006), r),
                           ("rod", (xm, 0.0, z - 0.006), end, r)]
        if p["tip"] == "ball":
            out.append(("sphere", end, 1.7 * r))
        else:
            out.append(("rod", (reach - r, 0.0, z + rise), (reach + 0.004, 0.0, z + rise), 2.2 * r))
        return out

    def groups(self, p):
        """The robe hook's fittings as (primitives, material slot) groups."""
        ps = p["plate_size"]
        hw = [_plate(p["plate"], ps, 0.0, 0.0, HOOK_PLATE_ASPECT)]
        double = p["style"] == "double"
        hw += self._prong(p, ps * 0.22 if double else 0.0, p["projection"], p["rise"])
        if double:  # a shorter, lower prong under the first
            hw += self._prong(p, -ps * 0.28, PLATE + 0.6 * (p["projection"] - PLATE), 0.5 * p["rise"])
        return [(hw, "metal")]

    def extra_surfaces(self, p):
        """The robe hook's surfaces besides its bounding box's: back (its plate's back face)."""
        return [_plate_back(p["plate"], p["plate_size"], 0.0, 0.0, HOOK_PLATE_ASPECT)]


@register
class BathroomMirrorCabinet(PartsFactory):
    """A wall-hung mirror cabinet: a shallow carcass with glass shelves (interior surfaces)
    behind one to three hinged doors, all-mirror or framed, optionally an open shelf below
    (a support surface) and a light bar on top or underneath. Its back panel hangs on the wall."""

    name = "bathroom_mirror_cabinet"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.MirrorCabinet, S.Mirror,
                      S.Storage, S.Cabinet, S.WallMounted})
    size_class = "medium"
    slots = ["wood", "front", "mirror", "glass", "emissive"]
    material_choices = {"wood": FIXTURE_MATERIALS["front"], "front": FIXTURE_MATERIALS["front"],
                        "glass": {"clear_glass": 1.0}, "mirror": {"mirror": 1.0}}
    params = {
        "width": Param(0.4, 1.0, doc="Y extent (m)"),
        "height": Param(0.5, 0.8, doc="Z extent of the carcass (m)"),
        "depth": Param(0.1, 0.18, doc="X extent of the carcass (m)"),
        "n_doors": Param(1, 3, kind="int", doc="doors (adjusted so each is 0.25 to 0.6 m wide)"),
        "n_shelves": Param(1, 3, kind="int", doc="glass shelves behind the doors (fewer if "
                                                   "they would be under 12 cm apart)"),
        "open_shelf": Param(kind="bool", doc="an open compartment under the doors"),
        "light": Param(kind="choice", choices=("none", "top", "bottom"), doc="light bar"),
        "door_style": Param(kind="choice", choices=("mirror", "framed"),
                            doc="all-mirror doors or mirror panes in a frame"),
    }

    def _g(self, p) -> dict[str, Any]:
        W, H, D = p["width"], p["height"], p["depth"]
        t = 0.016
        n = min(max(int(p["n_doors"]), math.ceil(W / 0.6)), max(1, int(W // 0.25)))
        z_d0 = 0.13 if p["open_shelf"] else 0.0  # bottom of the door zone
        z_in = z_d0 + t  # floor of the closed part
        k = min(int(p["n_shelves"]), int((H - t - z_in) / SHELF_CLEARANCE) - 1)
        zs = [z_in + (i + 1) * (H - t - z_in) / (k + 1) for i in range(k)]
        return dict(W=W, H=H, D=D, t=t, n=n, z_d0=z_d0, z_in=z_in, shelves=zs)

    def _fronts(self, p, g):
        W, n = g["W"], g["n"]
        ys = np.linspace(-W / 2, W / 2, n + 1)
        cells = [Front(float(ys[i]), float(ys[i + 1]), g["z_d0"], g["H"],
                       "left" if i < n / 2 else "right")
                 for i in range(n)]
        slot = "mirror" if p["door_style"] == "mirror" else "front"
        return cabinet_fronts(g["D"] / 2, cells, 0.1, handle="none", slot=slot)

    def parts(self, p, detail):
        """The mirror cabinet's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        W, H, D, t = g["W"], g["H"], g["D"], g["t"]
        out = carcass(D, W, 0.0, H, t, back=0.006, shelves=[g["z_in"]] if p["open_shelf"] else ())
        for z in g["shelves"]:  # glass shelves on the sides
            out.append(Part(box_between((-D / 2 + 0.006 - OVERLAP, -W / 2 + t - OVERLAP, z - 0.006),
                                        (D / 2 - 0.015, W / 2 - t + OVERLAP, z)), "glass"))
        if detail:
            for parts, _ in self._fronts(p, g):
                out += parts
                if p["door_style"] == "framed":
                    leaf = parts[0].solid.bounding_box()
                    out.append(Part(box_between((leaf[3] - OVERLAP, leaf[1] + 0.03, leaf[2] + 0.03),
                                                (leaf[3] + 0.003, leaf[4] - 0.03, leaf[5] - 0.03)),
                                    "mirror", parts[0].link))
        else:
            x1 = D / 2 + 0.002 + 0.018 + (0.003 if p["door_style"] == "framed" else 0.0)
            out.append(Part(box_between((-D / 2, -W / 2, g["z_d0"]), (x1, W / 2, H)), "mirror"))
        if p["light"] == "top":
            out.append(Part(box_between((D / 2 - 0.05, -W / 2 + 0.04, H - OVERLAP),
                                        (D / 2, W / 2 - 0.04, H + 0.025)), "emissive"))
        elif p["light"] == "bottom":
            out.append(Part(box_between((D / 2 - 0.05, -W / 2 + 0.04, -0.015),
                                        (D / 2 - 0.01, W / 2 - 0.04, OVERLAP)), "emissive"))
        return out

    def joints(self, p):
        """The mirror cabinet's joints, one per door."""
        g = self._g(p)
        return [make_joint(f"{m.link}_joint", m, 0.0, math.radians(100)) for _, m in self._fronts(p, g)]

    def extra_surfaces(self, p):
        """The mirror cabinet's surfaces besides its bounding box's: interior_<i>, back, shelf."""
        g = self._g(p)
        W, H, D, t = g["W"], g["H"], g["D"], g["t"]
        x0, x1 = -D / 2 + 0.006, D / 2 - 0.015
        inner = W / 2 - t - 0.005
        out = [Surface.rect(f"interior_{i}", Subpart.Interior, ((x0 + x1) / 2, 0.0, z), (0, 0, 1), (1, 0, 0),
                            (x1 - x0) / 2 - 0.005, inner)
               for i, z in enumerate([g["z_in"]] + g["shelves"])]
        if p["open_shelf"]:
            out.append(support_rect("shelf", ((x0 + D / 2) / 2, 0.0, t), (D / 2 - x0) / 2 - 0.005, inner))
        out.append(Surface.rect("back", Subpart.Back, (-D / 2, 0.0, H / 2), (-1, 0, 0), (0, 1, 0),
                                W / 2 - 0.001, H / 2 - 0.001))
        return out
