"""Beds: a bed family (frames, headboards, footboard, mattress, pillows, blanket, under-bed
drawers) and bunk beds.

A bed's head is at -X (its `back`, against the wall) and its foot at +X. Bedding is made of
watertight pieces unioned with the frame: pillows are soft boxes sunk 1 cm into the mattress, a
spread blanket is a thin bevelled slab with drapes down the sides, a folded one a thick slab at
the foot. The top of the bedding is a support surface, `mattress`.
"""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, DoorJoint, drawer, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box_between
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.assets.shapes.sweeps import rod_between
from indoorgen.model.tags import Semantics as S

MATTRESS_WIDTHS = {"single": 0.9, "double": 1.4, "queen": 1.6, "king": 1.8}
CLEAR = 0.01  # gap between the mattress and the frame around it (m)
BLANKET = 0.015  # spread blanket thickness (m)


def _soft(lo, hi, r: float, detail: bool, segments: int = 2) -> m3d.Manifold:
    """A bevelled box between corners lo and hi (a plain box for placeholders)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    if detail and r > 1e-4:
        return bevel_box(hi - lo, (lo + hi) / 2, r, segments)
    return box_between(lo, hi)


def _mattress_r(mt: float) -> float:
    return min(0.04, mt / 4)


def pillow(x0: float, x1: float, yc: float, width: float, z0: float, height: float,
           detail: bool) -> m3d.Manifold:
    """A soft pillow lying flat: x0..x1 deep, `width` wide about yc, from z0 up by `height`."""
    return _soft((x0, yc - width / 2, z0), (x1, yc + width / 2, z0 + height), 0.45 * height,
                 detail, 3)


def side_drawer(side: int, face: float, x0: float, x1: float, z0: float, z1: float,
                depth: float, link: str) -> tuple[list[Part], DoorJoint]:
    """A drawer opening sideways (+Y for side=1, -Y for side=-1) from a face at |y| = `face`,
    for the opening x0..x1, z0..z1: `shapes.moving_parts.drawer` built facing +X, turned about Z."""
    deg = 90.0 * side
    ly0, ly1 = (-x1, -x0) if side > 0 else (x0, x1)
    parts, motion = drawer(face, ly0, ly1, z0, z1, depth, 0.018, link)
    turned = [Part(p.solid.rotate((0.0, 0.0, deg)), p.slot, p.link) for p in parts]
    rot = np.array([[0.0, -side, 0.0], [side, 0.0, 0.0], [0.0, 0.0, 1.0]])
    return turned, DoorJoint(motion.kind, rot @ motion.axis, rot @ motion.origin, link)


# ========================================================================================= bed
@register
class Bed(PartsFactory):
    """A bed, single to king: a panel, slatted, platform or upholstered frame; a panel,
    slatted, upholstered or channel-tufted headboard; optional footboard; mattress; 1-4
    pillows; a spread (with side drapes and a turned-down band) or folded blanket; optional
    under-bed drawers on both long sides (each on a prismatic joint). The bedding's top is the
    `mattress` support surface (plus `blanket` on a folded blanket)."""

    name = "bed"
    tags = frozenset({S.Object, S.Furniture, S.Bed})
    size_class = "large"
    slots = ["wood", "upholstery", "fabric", "front", "metal"]
    params = {
        "size": Param(kind="choice", choices=tuple(MATTRESS_WIDTHS),
                      doc="mattress width: single 0.9, double 1.4, queen 1.6, king 1.8 m"),
        "mattress_length": Param(1.9, 2.1, doc="mattress X extent (m)"),
        "mattress_thickness": Param(0.15, 0.30, doc="mattress thickness (m)"),
        "frame_style": Param(kind="choice", choices=("panel", "slatted", "platform", "upholstered"),
                             doc="panel rails, slim rails on slats, a wide platform, or padded rails"),
        "frame_height": Param(0.25, 0.45, doc="height of the side rails' top (m)"),
        "leg_height": Param(0.05, 0.2, doc="clearance under the rails / platform plinth height (m)"),
        "headboard_style": Param(kind="choice", choices=("panel", "slatted", "upholstered", "channel"),
                                 doc="headboard design"),
        "headboard_height": Param(0.3, 0.7, doc="headboard height above the mattress top (m)"),
        "footboard": Param(kind="bool", doc="a footboard instead of a plain foot rail"),
        "n_pillows": Param(1, 4, kind="int", doc="pillows (a second row rests on the first)"),
        "blanket": Param(kind="choice", choices=("spread", "folded", "none"), doc="blanket"),
        "drawers": Param(kind="bool", doc="two drawers under each long side"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        mw, ml, mt = MATTRESS_WIDTHS[p["size"]], p["mattress_length"], p["mattress_thickness"]
        style, hstyle = p["frame_style"], p["headboard_style"]
        rt = {"panel": 0.03, "slatted": 0.03, "platform": 0.0, "upholstered": 0.07}[style]
        hbt = 0.08 if hstyle in ("upholstered", "channel") else 0.045
        fh = p["frame_height"]
        z_deck = fh - 0.06
        W = mw + 0.16 if style == "platform" else mw + 2 * (CLEAR + rt)
        ft = 0.045 if p["footboard"] else max(rt, 0.03)
        x_h0 = 0.0
        x_h1 = x_h0 + hbt
        xm0 = x_h1 + CLEAR
        xm1 = xm0 + ml
        x_f0 = xm1 + (0.08 if style == "platform" else CLEAR)
        x_f1 = x_f0 + ft
        lh = min(p["leg_height"], fh - 0.15)
        zr0 = z_deck - 0.03 if p["drawers"] else lh  # bottom of the rails (or platform slab)
        if style == "platform":
            lh = min(p["leg_height"], z_deck - 0.08)
            zr0 = z_deck - 0.04 if p["drawers"] else lh
        return dict(mw=mw, ml=ml, mt=mt, rt=rt, hbt=hbt, fh=fh, z_deck=z_deck, W=W, ft=ft,
                    x_h0=x_h0, x_h1=x_h1, xm0=xm0, xm1=xm1, x_f0=x_f0, x_f1=x_f1, lh=lh, zr0=zr0,
                    z_top=z_deck + mt, r=_mattress_r(mt), style=style)

    def _pillow_rows(self, p, g) -> list[tuple[float, float, float, float, float]]:
        """(x0, x1, yc, width, z0) of each pillow."""
        mw = g["mw"]
        per_row = 1 if mw < 1.2 else 2
        n = min(int(p["n_pillows"]), 2 * per_row)
        pw = min(0.7, (mw - 0.08) / per_row - 0.02)
        out = []
        for i in range(n):
            row, col = divmod(i, per_row)
            k = min(per_row, n - row * per_row)
            yc = (col - (k - 1) / 2) * (pw + 0.03)
            x0 = g["xm0"] + 0.04 + row * 0.12
            out.append((x0, x0 + 0.45, yc, pw, g["z_top"] - 0.01 + row * 0.08))
        return out

    def _pillows_end(self, p, g) -> float:
        return max(x1 for _, x1, *_ in self._pillow_rows(p, g))

    def _drawer_cells(self, p, g) -> list[tuple[int, float, float, float, float]]:
        """(side, x0, x1, z0, z1) of each drawer opening."""
        x0, x1 = g["x_h1"] + 0.04, g["xm1"] - 0.04
        z0, z1 = 0.03, g["zr0"] - 0.015
        xm = (x0 + x1) / 2
        return [(s, a, b, z0, z1) for s in (1, -1) for a, b in ((x0, xm - 0.01), (xm + 0.01, x1))]

    def _drawer_face(self, g) -> float:
        return g["W"] / 2 - FRONT_PROUD

    def _drawers(self, p, g):
        face = self._drawer_face(g)
        depth = min(0.55, face - 0.05)
        return [side_drawer(s, face, a, b, z0, z1, depth, f"drawer_{i}")
                for i, (s, a, b, z0, z1) in enumerate(self._drawer_cells(p, g))], depth

    # ---- pieces
    def _headboard(self, p, g, detail) -> list[Part]:
        W, x0, x1 = g["W"], g["x_h0"], g["x_h1"]
        zt = g["z_top"] + p["headboard_height"]
        hs = p["headboard_style"]
        if hs in ("upholstered", "channel"):
            z0 = g["zr0"] if p["drawers"] else g["lh"]
            if hs == "upholstered" or not detail:
                return [Part(_soft((x0, -W / 2, z0), (x1, W / 2, zt), 0.03, detail), "upholstery")]
            n = max(5, int(round(W / 0.16)))
            cw = W / n
            out = []
            for i in range(n):
                ya = -W / 2 + i * cw - (OVERLAP if i else 0.0)
                yb = -W / 2 + (i + 1) * cw + (OVERLAP if i < n - 1 else 0.0)
                out.append(Part(bevel_box((x1 - x0, yb - ya, zt - z0),
                                          (x1 - (x1 - x0) / 2, (ya + yb) / 2, (z0 + zt) / 2),
                                          0.45 * min(x1 - x0, cw), 3), "upholstery"))
            return out
        pt = 0.06
        out = [board((x0, s * W / 2 - (pt if s > 0 else 0), 0.0),
                      (x1, s * W / 2 + (pt if s < 0 else 0), zt + 0.02), "wood") for s in (-1, 1)]
        yi = W / 2 - pt + OVERLAP
        zb = g["fh"] - 0.1
        xa, xb = x0 + 0.008, x1 - 0.008
        if hs == "panel" or not detail:
            out.append(board((xa, -yi, zb), (xb, yi, zt), "wood"))
            if hs == "panel":
                out.append(Part(_soft((x0 - 0.0, -W / 2, zt - 0.01), (x1, W / 2, zt + 0.02), 0.006,
                                      detail), "wood"))
            return out
        out.append(board((xa, -yi, zt - 0.06), (xb, yi, zt), "wood"))
        out.append(board((xa, -yi, zb), (xb, yi, zb + 0.06), "wood"))
        n = max(3, int((2 * yi) / 0.12))
        for i in range(n):
            yc = -yi + (i + 0.5) * 2 * yi / n
            out.append(board((xa + 0.005, yc - 0.025, zb + 0.06 - OVERLAP),
                              (xb - 0.005, yc + 0.025, zt - 0.06 + OVERLAP), "wood"))
        return out

    def _frame(self, p, g, detail) -> list[Part]:
        W, style, fh, zr0 = g["W"], g["style"], g["fh"], g["zr0"]
        xa, xb = g["x_h1"] - OVERLAP, g["x_f0"] + OVERLAP
        out: list[Part] = []
        if style == "platform":
            inset = 0.08
            out.append(board((xa, -W / 2, zr0), (g["x_f1"], W / 2, g["z_deck"]), "wood"))
            if not p["drawers"]:
                out.append(board((xa, -W / 2 + inset, 0.0),
                                  (g["x_f1"] - inset, W / 2 - inset, zr0 + OVERLAP), "wood"))
        else:
            rt = g["rt"]
            slot = "upholstery" if style == "upholstered" else "wood"
            z0 = fh - 0.1 if style == "slatted" and not p["drawers"] else zr0
            for s in (-1, 1):
                lo = (xa, s * W / 2 - (rt if s > 0 else 0), z0)
                hi = (xb, s * W / 2 + (rt if s < 0 else 0), fh)
                out.append(Part(_soft(lo, hi, 0.025 if style == "upholstered" else 0.0, detail), slot))
            # the deck (slats) the mattress lies on
            yi = W / 2 - rt + OVERLAP
            if style == "slatted":  # slats on a centre beam
                out.append(board((xa, -0.03, g["z_deck"] - 0.06),
                                  (xb, 0.03, g["z_deck"] - 0.02 + OVERLAP), "wood"))
            if style == "slatted" and detail:
                n = max(6, int((xb - xa) / 0.12))
                for i in range(n):
                    xc = xa + 0.03 + i * (xb - xa - 0.06) / (n - 1)
                    out.append(board((xc - 0.035, -yi, g["z_deck"] - 0.02),
                                      (xc + 0.035, yi, g["z_deck"]), "wood"))
            else:
                out.append(board((xa, -yi, g["z_deck"] - 0.02), (xb, yi, g["z_deck"]), "wood"))
            if not p["drawers"]:
                lt = 0.06
                lz = (z0 if style == "slatted" else zr0) + OVERLAP
                for x in (g["x_h1"], g["x_f1"] - lt):
                    for s in (-1, 1):
                        y = s * W / 2 - (lt if s > 0 else 0)
                        out.append(board((x, y, 0.0), (x + lt, y + lt, lz), "wood"))
        # the foot: a rail, or a footboard reaching above the mattress
        if style == "platform" and not p["footboard"]:
            return out
        top = g["z_top"] + 0.08 if p["footboard"] else fh
        bottom = 0.0 if p["footboard"] else (fh - 0.1 if style == "slatted" and not p["drawers"] else zr0)
        soft = p["headboard_style"] in ("upholstered", "channel") and p["footboard"]
        out.append(Part(_soft((g["x_f0"], -W / 2, bottom), (g["x_f1"], W / 2, top),
                              0.02 if soft else 0.004,
                              detail), "upholstery" if soft else "wood"))
        return out

    def _storage(self, p, g, detail) -> list[Part]:
        """The box under the bed holding the drawers: a block with a cavity per drawer."""
        W, face = g["W"], self._drawer_face(g)
        x0, x1 = g["x_h1"] - OVERLAP, g["xm1"]
        # up to the deck (or the platform slab) it carries
        z1 = (g["zr0"] if g["style"] == "platform" else g["z_deck"] - 0.02) + OVERLAP
        if not detail:  # the block with its drawers shut, fronts and handles included
            return [board((x0, -W / 2, 0.0), (x1, W / 2, z1), "wood")]
        block = box_between((x0, -face, 0.0), (x1, face, z1))
        _, depth = self._drawers(p, g)
        cuts = []
        for s, a, b, z0, z1 in self._drawer_cells(p, g):
            ya, yb = sorted((s * (face + 0.01), s * (face - depth - 0.012)))
            cuts.append(box_between((a, ya, z0), (b, yb, z1)))
        body = block - solid_union(cuts)
        out = [Part(body, "wood")]
        for parts, _ in self._drawers(p, g)[0]:
            out += [Part(q.solid, "front" if q.slot == "front" else q.slot, q.link) for q in parts]
        return out

    def _bedding(self, p, g, detail) -> list[Part]:
        mw, r = g["mw"], g["r"]
        xm0, xm1, zd, zt = g["xm0"], g["xm1"], g["z_deck"], g["z_top"]
        out = [Part(_soft((xm0, -mw / 2, zd - OVERLAP), (xm1, mw / 2, zt), r, detail), "fabric")]
        for x0, x1, yc, pw, z0 in self._pillow_rows(p, g):
            out.append(Part(pillow(x0, x1, yc, pw, z0, 0.13, detail), "fabric"))
        kind = p["blanket"]
        if kind == "spread":
            xb0 = self._pillows_end(p, g) + 0.05
            t = BLANKET
            zb = max(g["fh"] + 0.01, zt - 0.25)
            pieces = [_soft((xb0, -mw / 2 - t, zt - 0.003), (xm1 + t, mw / 2 + t, zt + t), 0.006, detail),
                      _soft((xb0, -mw / 2 - t, zt + t - OVERLAP), (xb0 + 0.3, mw / 2 + t, zt + 2 * t),
                            0.006, detail)]
            for s in (-1, 1):
                y0, y1 = sorted((s * (mw / 2 - 0.001), s * (mw / 2 + t)))
                pieces.append(box_between((xb0, y0, zb), (xm1 + t, y1, zt + OVERLAP)))
            pieces.append(box_between((xm1 - 0.001, -mw / 2 - t, zb),
                                      (xm1 + t, mw / 2 + t, zt + OVERLAP)))
            out += [Part(q, "fabric") for q in pieces]
        elif kind == "folded":
            x0, x1 = self._folded_x(g)
            out.append(Part(_soft((x0, -mw / 2 + 0.05, zt - 0.003), (x1, mw / 2 - 0.05, zt + 0.06), 0.02,
                                  detail), "fabric"))
        return out

    def _folded_x(self, g) -> tuple[float, float]:
        return g["xm1"] - 0.5, g["xm1"] - 0.06

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Headboard, frame, bedding and (with `drawers`) the under-bed drawers."""
        g = self._g(p)
        out = self._headboard(p, g, detail) + self._frame(p, g, detail) + self._bedding(p, g, detail)
        if p["drawers"]:
            out += self._storage(p, g, detail)
        return out

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """A prismatic joint per under-bed drawer, opening to 80% of its depth."""
        if not p["drawers"]:
            return []
        g = self._g(p)
        drawers, depth = self._drawers(p, g)
        return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for _, m in drawers]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The bedding's top (`mattress`, clear of the pillows) and a folded blanket's top."""
        g = self._g(p)
        mw, r = g["mw"], g["r"]
        x0 = self._pillows_end(p, g) + 0.03
        kind = p["blanket"]
        if kind == "spread":
            x0 = self._pillows_end(p, g) + 0.05 + 0.3 + 0.03
            x1, z, hw = g["xm1"] - 0.02, g["z_top"] + BLANKET, mw / 2 - 0.02
        elif kind == "folded":
            x1, z, hw = self._folded_x(g)[0] - 0.03, g["z_top"], mw / 2 - r - 0.01
        else:
            x1, z, hw = g["xm1"] - r - 0.01, g["z_top"], mw / 2 - r - 0.01
        out = [support_rect("mattress", ((x0 + x1) / 2, 0, z), (x1 - x0) / 2, hw)]
        if kind == "folded":
            fx0, fx1 = self._folded_x(g)
            out.append(support_rect("blanket", ((fx0 + fx1) / 2, 0, g["z_top"] + 0.06),
                                    (fx1 - fx0) / 2 - 0.03, mw / 2 - 0.05 - 0.03))
        return out


# ==================================================================================== bunk bed
@register
class BunkBed(PartsFactory):
    """A bunk bed: four posts carrying two mattress decks, guard rails around the upper bunk
    (open at the ladder), panel, slatted or railed ends, and a vertical or angled ladder on the
    front (+X) side at one end. Optional bedding (a pillow and a folded blanket per bunk). Both
    mattress tops are support surfaces (`mattress_lower`, `mattress_upper`)."""

    name = "bunk_bed"
    tags = frozenset({S.Object, S.Furniture, S.Bed, S.BunkBed})
    size_class = "large"
    slots = ["wood", "fabric", "metal"]
    params = {
        "mattress_width": Param(0.8, 1.2, doc="mattress X extent (m)"),
        "mattress_length": Param(1.9, 2.0, doc="mattress Y extent (m)"),
        "mattress_thickness": Param(0.12, 0.2, doc="mattress thickness (m)"),
        "post_thickness": Param(0.05, 0.09, doc="corner post section (m)"),
        "lower_height": Param(0.2, 0.35, doc="height of the lower deck (m)"),
        "upper_height": Param(1.3, 1.6, doc="height of the upper deck (m)"),
        "guard_height": Param(0.2, 0.35, doc="guard rail top above the upper mattress (m)"),
        "end_style": Param(kind="choice", choices=("panel", "slats", "rails"),
                           doc="how the head and foot ends are closed"),
        "ladder_side": Param(kind="choice", choices=("left", "right"),
                             doc="ladder at the +Y (left) or -Y (right) end of the front"),
        "ladder_style": Param(kind="choice", choices=("vertical", "angled"), doc="ladder kind"),
        "rung_spacing": Param(0.22, 0.3, doc="vertical distance between ladder rungs (m)"),
        "bedding": Param(kind="bool", doc="a pillow and a folded blanket on each bunk"),
    }
    RAIL_T = 0.03    # rail thickness (m)
    RAIL_H = 0.15    # side rail height (m)
    OPENING = 0.5    # guard opening at the ladder (m)

    def _g(self, p) -> dict[str, Any]:
        mw, ml, mt, pt = (p["mattress_width"], p["mattress_length"], p["mattress_thickness"],
                          p["post_thickness"])
        X = mw / 2 + CLEAR + pt  # outer faces of the posts
        Y = ml / 2 + CLEAR + pt
        decks = (p["lower_height"], p["upper_height"])
        H = decks[1] + mt + p["guard_height"]
        ls = 1.0 if p["ladder_side"] == "left" else -1.0
        return dict(mw=mw, ml=ml, mt=mt, pt=pt, X=X, Y=Y, decks=decks, H=H, ls=ls,
                    xi=mw / 2 + CLEAR, yi=ml / 2 + CLEAR)

    def _level(self, p, g, zd: float, upper: bool, detail) -> list[Part]:
        xi, yi, rt = g["xi"], g["yi"], self.RAIL_T
        z0, z1 = zd - 0.05, zd - 0.05 + self.RAIL_H
        if not detail:  # rails, deck, mattress and bedding as one block
            ztop = max(z1, zd + g["mt"] + (0.11 if p["bedding"] else 0.0))
            return [board((-xi - rt, -yi - rt, z0), (xi + rt, yi + rt, ztop), "wood")]
        out = []
        for s in (-1, 1):  # long rails front/back, end rails
            out.append(board((s * xi - (0 if s > 0 else rt), -yi - OVERLAP, z0),
                              (s * xi + (rt if s > 0 else 0), yi + OVERLAP, z1), "wood"))
            out.append(board((-xi - OVERLAP, s * yi - (0 if s > 0 else rt), z0),
                              (xi + OVERLAP, s * yi + (rt if s > 0 else 0), z1), "wood"))
        out.append(board((-xi - OVERLAP, -yi - OVERLAP, zd - 0.02), (xi + OVERLAP, yi + OVERLAP, zd),
                          "wood"))  # deck
        mt = g["mt"]
        out.append(Part(_soft((-g["mw"] / 2, -g["ml"] / 2, zd - OVERLAP),
                              (g["mw"] / 2, g["ml"] / 2, zd + mt),
                              _mattress_r(mt), detail), "fabric"))
        if p["bedding"]:
            zt = zd + mt
            yh = -g["ls"] * (g["ml"] / 2 - 0.04)  # head end: away from the ladder
            y0, y1 = sorted((yh, yh + g["ls"] * 0.42))
            out.append(Part(_soft((-g["mw"] / 2 + 0.08, y0, zt - 0.01),
                                  (g["mw"] / 2 - 0.08, y1, zt + 0.12), 0.054,
                                  detail, 3), "fabric"))
            f0, f1 = self._folded_y(g)
            out.append(Part(_soft((-g["mw"] / 2 + 0.05, f0, zt - 0.003),
                                  (g["mw"] / 2 - 0.05, f1, zt + 0.06), 0.02,
                                  detail), "fabric"))
        return out

    def _folded_y(self, g) -> tuple[float, float]:
        yf = g["ls"] * (g["ml"] / 2 - 0.06)
        return tuple(sorted((yf, yf - g["ls"] * 0.4)))

    def _ends(self, p, g, detail) -> list[Part]:
        xi, yi, rt, H = g["xi"], g["yi"], self.RAIL_T, g["H"]
        style = p["end_style"]
        out = []
        zl, zu = g["decks"]
        spans = [(zl - 0.05 + self.RAIL_H - OVERLAP, zl + g["mt"] + 0.3),
                 (zu - 0.05 + self.RAIL_H - OVERLAP, H - 0.02)]
        for s in (-1, 1):
            y0, y1 = (s * yi - (0 if s > 0 else rt), s * yi + (rt if s > 0 else 0))
            if not detail:  # both spans (and the rails between them) as one board
                out.append(board((-xi - OVERLAP, y0, spans[0][0]), (xi + OVERLAP, y1, spans[1][1]),
                                  "wood"))
                continue
            for z0, z1 in spans:
                if style == "panel":
                    out.append(board((-xi - OVERLAP, y0 + 0.005, z0), (xi + OVERLAP, y1 - 0.005, z1),
                                      "wood"))
                elif style == "slats":
                    out.append(board((-xi - OVERLAP, y0, z1 - 0.05), (xi + OVERLAP, y1, z1), "wood"))
                    n = max(3, int(2 * xi / 0.12))
                    for i in range(n):
                        xc = -xi + (i + 0.5) * 2 * xi / n
                        out.append(board((xc - 0.02, y0 + 0.005, z0),
                                          (xc + 0.02, y1 - 0.005, z1 - 0.05 + OVERLAP), "wood"))
                else:
                    for z in np.linspace(z0 + 0.06, z1 - 0.025, 3):
                        out.append(board((-xi - OVERLAP, y0, z - 0.025), (xi + OVERLAP, y1, z + 0.025),
                                          "wood"))
        return out

    def _guard(self, p, g, detail) -> list[Part]:
        xi, yi, rt = g["xi"], g["yi"], self.RAIL_T
        zu = g["decks"][1]
        z0, z1 = zu - 0.05 + self.RAIL_H - OVERLAP, g["H"] - 0.02
        out = []
        for s in (-1, 1):
            x0, x1 = (s * xi - (0 if s > 0 else rt), s * xi + (rt if s > 0 else 0))
            if s < 0:
                ya, yb = -yi - OVERLAP, yi + OVERLAP
            else:  # front: open at the ladder end
                ya, yb = sorted((-g["ls"] * (yi + OVERLAP), g["ls"] * (yi - self.OPENING)))
            if not detail:  # rails and posts as one board (the closing post included)
                if s > 0:
                    ya, yb = ya - 0.02, yb + 0.02
                out.append(board((x0 - 0.004, ya, z0), (x1 + (0.01 if s > 0 else 0.004), yb, z1),
                                  "wood"))
                continue
            out.append(board((x0, ya, z1 - 0.05), (x1, yb, z1), "wood"))
            out.append(board((x0, ya, (z0 + z1) / 2 - 0.025), (x1, yb, (z0 + z1) / 2 + 0.025), "wood"))
            # posts 4 mm thicker than the rails, so that no faces are coplanar (slivers)
            if s > 0:  # a short post closing the guard at the opening
                yp = g["ls"] * (yi - self.OPENING)
                out.append(board((x0 - 0.004, yp - 0.02, z0), (x1 + 0.01, yp + 0.02, z1), "wood"))
            else:
                for y in np.linspace(-yi * 0.5, yi * 0.5, 2):
                    out.append(board((x0 - 0.004, y - 0.02, z0), (x1 + 0.004, y + 0.02, z1), "wood"))
        return out

    def _ladder(self, p, g, detail) -> list[Part]:
        xi, yi, X = g["xi"], g["yi"], g["X"]
        ls = g["ls"]
        zl, zu = g["decks"]
        top = zu - 0.05 + self.RAIL_H
        ya, yb = sorted((ls * (yi - 0.05), ls * (yi - self.OPENING + 0.05)))
        x_in = xi + self.RAIL_T - OVERLAP
        sw = 0.035  # stile width along Y
        out = []
        rung_zs = np.arange(p["rung_spacing"], top - 0.1, p["rung_spacing"])
        if p["ladder_style"] == "vertical":
            if not detail:
                xr = (x_in + X) / 2
                return [board((min(x_in, xr - 0.014), ya, 0.0), (max(X, xr + 0.014), yb, top), "wood")]
            for y in (ya, yb - sw):
                out.append(board((x_in, y, 0.0), (X, y + sw, top), "wood"))
            if detail:
                for z in rung_zs:
                    out.append(Part(rod_between(((x_in + X) / 2, ya + sw / 2, z),
                                                ((x_in + X) / 2, yb - sw / 2, z),
                                                0.014, True, 12), "wood"))
            else:
                out.append(board(((x_in + X) / 2 - 0.014, ya, rung_zs[0] - 0.014),
                                  ((x_in + X) / 2 + 0.014, yb, rung_zs[-1] + 0.014), "wood"))
            return out
        run = 0.35  # how far the foot of an angled ladder stands out
        d = X - x_in
        for y in (ya, yb - sw):
            out.append(Part(_stile(x_in, X, y, sw, run, top), "wood"))
        xs = x_in + d / 2 + run * (1 - rung_zs / top)  # the rungs' axes, along Y
        if detail:
            out += [Part(rod_between((x, ya + sw / 2, z), (x, yb - sw / 2, z), 0.014, True, 12), "wood")
                    for x, z in zip(xs, rung_zs, strict=True)]
        else:
            out.append(board((xs.min() - 0.014, ya + sw / 2, rung_zs.min() - 0.014),
                              (xs.max() + 0.014, yb - sw / 2, rung_zs.max() + 0.014), "wood"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Four posts, both decks with their mattresses, the ends, the guard rails and the ladder."""
        g = self._g(p)
        X, Y, pt, H = g["X"], g["Y"], g["pt"], g["H"]
        out = []
        for sx in (-1, 1):
            for sy in (-1, 1):
                x0, x1 = sorted((sx * X, sx * (X - pt)))
                y0, y1 = sorted((sy * Y, sy * (Y - pt)))
                out.append(Part(_soft((x0, y0, 0.0), (x1, y1, H), 0.004, detail), "wood"))
        for i, zd in enumerate(g["decks"]):
            out += self._level(p, g, zd, i == 1, detail)
        return out + self._ends(p, g, detail) + self._guard(p, g, detail) + self._ladder(p, g, detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Both mattress tops (`mattress_lower`, `mattress_upper`), clear of any bedding."""
        g = self._g(p)
        mw, ml, mt = g["mw"], g["ml"], g["mt"]
        r = _mattress_r(mt)
        out = []
        for name, zd in zip(("mattress_lower", "mattress_upper"), g["decks"], strict=True):
            if p["bedding"]:
                yh = -g["ls"] * (ml / 2 - 0.04) + g["ls"] * 0.42
                f0, f1 = self._folded_y(g)
                ya, yb = sorted((yh + g["ls"] * 0.03, (f0 if g["ls"] > 0 else f1) - g["ls"] * 0.03))
            else:
                ya, yb = -ml / 2 + r + 0.01, ml / 2 - r - 0.01
            out.append(support_rect(name, (0, (ya + yb) / 2, zd + mt), mw / 2 - r - 0.01, (yb - ya) / 2))
        return out


def _stile(x_in: float, x_out: float, y: float, width: float, run: float, top: float) -> m3d.Manifold:
    """A slanted ladder stile: its foot `run` metres out from the frame, its top against it
    (horizontal sections are rectangles x_out - x_in deep and `width` wide)."""
    d = x_out - x_in
    pts = [(x + dx, y + dy, z) for x, z in ((x_in + run, 0.0), (x_in, top))
           for dx in (0.0, d) for dy in (0.0, width)]
    return m3d.Manifold.hull_points(np.array(pts, float))
