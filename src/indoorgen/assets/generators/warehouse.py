"""Warehouse: selective pallet racking and wooden pallets (front +X is the aisle side)."""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between, rod
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
from indoorgen.model.tags import Semantics as S

MAX_RACK_HEIGHT = 6.0  # levels are dropped beyond this (m)


# ------------------------------------------------------------------------------- pallet rack
@register
class PalletRack(PartsFactory):
    """Selective pallet racking: 1-3 bays between upright frames (two C-section posts braced by
    horizontal and diagonal struts in a Z or X pattern), front and back beams at 2-5 levels,
    each level decked with a ribbed steel or plywood panel. Every decked bay at every level is a
    support surface `level_<i>_bay_<j>` for pallets."""

    name = "pallet_rack"
    tags = frozenset({S.Object, S.Warehouse, S.Storage, S.Shelf, S.PalletRack})
    size_class = "large"
    slots = ["frame", "metal", "wood"]
    params = {
        "n_bays": Param(1, 3, kind="int", doc="bays side by side"),
        "bay_width": Param(1.8, 2.8, doc="clear width between uprights (beam length) (m)"),
        "depth": Param(0.8, 1.1, doc="upright frame depth, X extent (m)"),
        "n_levels": Param(2, 5, kind="int",
                          doc=f"beam levels (dropped if the rack would exceed {MAX_RACK_HEIGHT} m)"),
        "level_spacing": Param(1.0, 1.6, doc="vertical pitch between beam levels (m)"),
        "first_level": Param(0.2, 0.35, doc="height of the lowest deck's top (m)"),
        "upright_width": Param(0.07, 0.11, doc="post section (m)"),
        "beam_height": Param(0.08, 0.14, doc="beam section height (m)"),
        "deck": Param(kind="choice", choices=("steel", "plywood"), doc="deck panels"),
        "bracing": Param(kind="choice", choices=("z", "x"), doc="frame bracing pattern"),
    }

    BEAM_D = 0.05   # beam section depth (m)
    BRACE_R = 0.012  # strut radius (m)
    WALL = 0.0025    # C-section wall thickness (m)

    def _levels(self, p) -> list[float]:
        n = int(p["n_levels"])
        while n > 2 and p["first_level"] + (n - 1) * p["level_spacing"] + 0.15 > MAX_RACK_HEIGHT:
            n -= 1
        return [p["first_level"] + i * p["level_spacing"] for i in range(n)]

    def _deck_t(self, p) -> float:
        return 0.004 if p["deck"] == "steel" else 0.018

    def _height(self, p) -> float:
        return self._levels(p)[-1] + 0.15

    def _frames_y(self, p) -> list[float]:
        """Centre y of each upright frame."""
        nb, bw, uw = int(p["n_bays"]), p["bay_width"], p["upright_width"]
        W = nb * bw + (nb + 1) * uw
        return [-W / 2 + uw / 2 + k * (bw + uw) for k in range(nb + 1)]

    def _post(self, p, x_c: float, y_c: float, inward: float) -> m3d.Manifold:
        """A C-section post centred on (x_c, y_c), open towards the frame's inside (`inward` =
        +1 or -1 along X)."""
        uw, H = p["upright_width"], self._height(p)
        z0 = 0.004  # stands in its foot plate
        post = box((uw, uw, H - z0), (x_c, y_c, (H + z0) / 2))
        w = self.WALL
        cut = box((uw, uw - 2 * w, H + 0.02), (x_c + inward * w, y_c, H / 2))
        return post - cut

    def _frame(self, p, y: float, detail: bool) -> list[Part]:
        D, uw, H = p["depth"], p["upright_width"], self._height(p)
        if not detail:  # posts and bracing lie within the frame's slab
            return [Part(box_between((-D / 2, y - uw / 2, 0.0), (D / 2, y + uw / 2, H)), "frame")]
        xp = D / 2 - uw / 2
        out = [Part(self._post(p, xp, y, -1.0), "frame"), Part(self._post(p, -xp, y, 1.0), "frame")]
        xa = D / 2 - self.WALL + OVERLAP  # struts reach the posts' webs
        for s in (-1, 1):  # foot plates, just inside the posts' outer faces
            a, b = s * (D / 2 - 0.001), s * (D / 2 - uw - 0.04)
            out.append(Part(box_between((min(a, b), y - uw / 2 + 0.001, 0.0),
                                        (max(a, b), y + uw / 2 - 0.001, 0.008)), "frame"))
        z0, z1 = 0.15, H - 0.1
        n = max(2, math.ceil((z1 - z0) / 0.9))
        zs = np.linspace(z0, z1, n + 1)
        r = self.BRACE_R
        clip = box_between((-xa, y - 2 * r, 0.0), (xa, y + 2 * r, H))  # flat strut ends in the webs
        struts = [((-xa - r, z), (xa + r, z)) for z in (z0, z1)]
        for i in range(n):
            a, b = zs[i], zs[i + 1]
            if p["bracing"] == "x" or i % 2 == 0:
                struts.append(((-xa - r, a), (xa + r, b)))
            if p["bracing"] == "x" or i % 2 == 1:
                struts.append(((xa + r, a), (-xa - r, b)))
        for (xa0, za), (xb0, zb) in struts:
            out.append(Part(rod((xa0, y, za), (xb0, y, zb), r, 8) ^ clip, "frame"))
        return out

    def _bay_y(self, p, j: int) -> tuple[float, float]:
        """Clear y range of bay j (between the uprights' faces)."""
        ys, uw = self._frames_y(p), p["upright_width"]
        return ys[j] + uw / 2, ys[j + 1] - uw / 2

    def _level(self, p, j: int, z: float, detail: bool) -> list[Part]:
        """Front and back beams and the deck of bay j at a level whose deck top is z."""
        D, bh, o = p["depth"], p["beam_height"], OVERLAP
        y0, y1 = self._bay_y(p, j)
        dt = self._deck_t(p)
        zb = z - dt  # beam top
        if not detail:
            return [Part(box_between((-D / 2, y0 - o, zb - bh), (D / 2, y1 + o, z)), "metal")]
        bd, e = self.BEAM_D, 0.001  # beams 1 mm inside the posts' faces (no coplanar seams)
        out = [Part(box_between((D / 2 - bd, y0 - o, zb - bh), (D / 2 - e, y1 + o, zb)), "metal"),
               Part(box_between((-D / 2 + e, y0 - o, zb - bh), (-D / 2 + bd, y1 + o, zb)), "metal")]
        deck_slot = "metal" if p["deck"] == "steel" else "wood"
        out.append(Part(box_between((-D / 2 + 0.003, y0 + 0.003, zb - o), (D / 2 - 0.003, y1 - 0.003, z)),
                        deck_slot))
        if p["deck"] == "steel":  # channels under the plate, beam to beam
            for yc in np.linspace(y0, y1, 5)[1:-1]:
                out.append(Part(box_between((-D / 2 + bd - o, yc - 0.015, zb - 0.03),
                                            (D / 2 - bd + o, yc + 0.015, zb)), "metal"))
        return out

    def parts(self, p, detail):
        """The pallet rack's solids: detailed, or the blocks of its placeholder."""
        out = []
        for y in self._frames_y(p):
            out += self._frame(p, y, detail)
        for z in self._levels(p):
            for j in range(int(p["n_bays"])):
                out += self._level(p, j, z, detail)
        return out

    def extra_surfaces(self, p):
        """The pallet rack's surfaces besides its bounding box's: level_<i>_bay_<j>."""
        D = p["depth"]
        out = []
        for i, z in enumerate(self._levels(p)):
            for j in range(int(p["n_bays"])):
                y0, y1 = self._bay_y(p, j)
                out.append(support_rect(f"level_{i}_bay_{j}", (0, (y0 + y1) / 2, z), D / 2 - 0.02,
                                        (y1 - y0) / 2 - 0.02))
        return out


# ----------------------------------------------------------------------------------- pallet
@register
class WoodenPallet(PartsFactory):
    """A wooden pallet: a EUR-style block pallet (top boards on three cross boards, nine blocks,
    three bottom runners) or a GMA-style stringer pallet (deck boards across three stringers,
    optionally notched for four-way entry, optionally a bottom deck). Its `top` is a support
    surface whose holes are the gaps between the deck boards."""

    name = "wooden_pallet"
    tags = frozenset({S.Object, S.Warehouse, S.Pallet})
    size_class = "large"
    slots = ["wood"]
    params = {
        "style": Param(kind="choice", choices=("block", "stringer"), doc="construction"),
        "length": Param(1.0, 1.22, doc="Y extent (m)"),
        "width": Param(0.8, 1.02, doc="X extent (m)"),
        "n_top_boards": Param(5, 9, kind="int", doc="top deck boards"),
        "deck_thickness": Param(0.016, 0.022, doc="board thickness (m)"),
        "block_height": Param(0.075, 0.1, doc="block / stringer height (m)"),
        "coverage": Param(0.55, 0.85, doc="fraction of the top deck covered by boards"),
        "bottom_deck": Param(kind="bool", doc="stringer pallets: add bottom deck boards"),
        "notched": Param(kind="bool", doc="stringer pallets: notch the stringers for forklifts"),
    }

    CHAMFER = 0.003

    def _height(self, p) -> float:
        t, hb = p["deck_thickness"], p["block_height"]
        if p["style"] == "block":
            return 3 * t + hb  # bottom runners, blocks, cross boards, top boards
        return (2 * t if p["bottom_deck"] else t) + hb

    def _top_boards(self, p) -> list[tuple[float, float]]:
        """(x0, x1) of each top deck board; the boards run along Y, spaced along X (so the
        gaps between them are the top surface's holes, each spanning the length)."""
        n, span = int(p["n_top_boards"]), p["width"]
        bw = p["coverage"] * span / n
        starts = np.linspace(-span / 2, span / 2 - bw, n)
        return [(float(s), float(s) + bw) for s in starts]

    def _board(self, lo, hi, detail: bool) -> m3d.Manifold:
        lo, hi = np.asarray(lo, float), np.asarray(hi, float)
        if detail:
            return bevel_box(hi - lo, (lo + hi) / 2, self.CHAMFER, 1)
        return box_between(lo, hi)

    def _block_parts(self, p, detail: bool) -> list[Part]:
        L, Wd, t, hb, o = p["length"], p["width"], p["deck_thickness"], p["block_height"], OVERLAP
        out = []
        bx = min(0.145, Wd * 0.16)   # block / runner size along X
        by = min(0.145, L * 0.12)    # block / cross board size along Y
        xs = (-Wd / 2 + bx / 2, 0.0, Wd / 2 - bx / 2)
        ys = (-L / 2 + by / 2, 0.0, L / 2 - by / 2)
        for x in xs:  # bottom runners along Y
            out.append(Part(self._board((x - bx / 2, -L / 2, 0.0), (x + bx / 2, L / 2, t), detail), "wood"))
            for y in ys:
                out.append(Part(box_between((x - bx / 2 + 0.002, y - by / 2 + 0.002, t - o),
                                            (x + bx / 2 - 0.002, y + by / 2 - 0.002, t + hb + o)), "wood"))
        z = t + hb
        for y in ys:  # cross boards along X
            out.append(Part(self._board((-Wd / 2, y - by / 2, z), (Wd / 2, y + by / 2, z + t), detail),
                            "wood"))
        return out

    def _stringer_parts(self, p, detail: bool) -> list[Part]:
        L, Wd, t, hb, o = p["length"], p["width"], p["deck_thickness"], p["block_height"], OVERLAP
        out = []
        z0 = t if p["bottom_deck"] else 0.0
        sw = 0.038
        for y in (-L / 2 + sw / 2, 0.0, L / 2 - sw / 2):  # stringers along X
            s = box_between((-Wd / 2, y - sw / 2, max(z0 - o, 0.0)), (Wd / 2, y + sw / 2, z0 + hb + o))
            if p["notched"] and detail:
                for xc in (-0.3 * Wd, 0.3 * Wd):
                    s = s - box_between((xc - 0.115, y - sw, z0 - 0.01), (xc + 0.115, y + sw, z0 + 0.038))
            out.append(Part(s, "wood"))
        if p["bottom_deck"]:
            bw = 0.14
            for x in np.linspace(-Wd / 2, Wd / 2 - bw, 5 if Wd > 0.95 else 3):
                out.append(Part(self._board((x, -L / 2, 0.0), (x + bw, L / 2, t), detail), "wood"))
        return out

    def parts(self, p, detail):
        """The wooden pallet's solids: detailed, or the blocks of its placeholder."""
        L, Wd, t = p["length"], p["width"], p["deck_thickness"]
        H = self._height(p)
        if not detail:
            return [Part(box((Wd, L, H), (0.0, 0.0, H / 2)), "wood")]
        out = self._block_parts(p, detail) if p["style"] == "block" else self._stringer_parts(p, detail)
        for a, b in self._top_boards(p):
            out.append(Part(self._board((a, -L / 2, H - t - OVERLAP), (b, L / 2, H), detail), "wood"))
        return out

    def extra_surfaces(self, p):
        """The wooden pallet's surfaces besides its bounding box's: top."""
        L, Wd = p["length"], p["width"]
        H = self._height(p)
        m, eps, c = 0.01, 0.0005, self.CHAMFER
        outer = [(-Wd / 2 + m, -L / 2 + m), (Wd / 2 - m, -L / 2 + m), (Wd / 2 - m, L / 2 - m),
                 (-Wd / 2 + m, L / 2 - m)]
        boards = self._top_boards(p)
        holes = []
        for (_, b), (a, _) in zip(boards[:-1], boards[1:], strict=True):
            g0, g1 = b - c, a + c  # the gap, widened by the boards' chamfers
            holes.append([(g0, -L / 2 + m + eps), (g1, -L / 2 + m + eps), (g1, L / 2 - m - eps),
                          (g0, L / 2 - m - eps)])
        return [support_polygon("top", (0, 0, H), sg.Polygon(outer, holes))]
