"""Sofas and armchairs: upholstered bases, arms, backs and cushions, and the L-shaped sectional
with a chaise longue. Front (+X) is where one sits from."""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box, cylinder
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S


def upholstered_parts(p: dict[str, Any], detail: bool, n_cushions: int) -> list[Part]:
    """Base, back, two arms, seat and back cushions of a sofa/armchair (front +X), on legs or
    a plinth base. Cushions overlap their neighbours slightly so the union is one shell."""
    W, D, H = p["width"], p["depth"], p["height"]
    sh, ct, aw, ah = p["seat_height"], p["cushion_thickness"], p["arm_width"], p["arm_height"]
    bt, cr = p["back_thickness"], p["corner_radius"]
    on_legs = p["base_style"] == "legs"
    lh = p["leg_height"] if on_legs else 0.0
    out: list[Part] = []

    def soft(ext, ctr, r):
        return bevel_box(ext, ctr, r, 2) if detail else box(ext, ctr)

    zb = sh - ct  # top of the base frame
    out.append(Part(soft((D, W - 2 * aw + 2 * OVERLAP, zb - lh), (0, 0, (lh + zb) / 2), 0.005), "fabric"))
    # arms
    arm_r = min(aw / 2 - 0.002, 0.06) if p["arm_style"] == "rounded" else cr
    for s in (-1, 1):
        out.append(Part(soft((D, aw, ah - lh), (0, s * (W - aw) / 2, (lh + ah) / 2), arm_r), "fabric"))
    # back
    out.append(Part(soft((bt, W - 2 * aw + 2 * OVERLAP, H - lh), (-D / 2 + bt / 2, 0, (lh + H) / 2), cr),
                    "fabric"))
    # seat cushions (overlap base, back, arms and each other by OVERLAP)
    inner = W - 2 * aw
    cw = inner / n_cushions
    cd = D - bt - 0.01
    for i in range(n_cushions):
        y0 = -inner / 2 + i * cw - OVERLAP
        y1 = y0 + cw + 2 * OVERLAP
        out.append(Part(soft((cd + OVERLAP, y1 - y0, ct + OVERLAP),
                             (-D / 2 + bt + (cd - OVERLAP) / 2, (y0 + y1) / 2, sh - (ct - OVERLAP) / 2),
                             min(cr, ct / 3)), "cushion"))
    # back cushions leaning on the back
    bct = min(0.14, (D - bt) * 0.25)
    zb0, zb1 = sh - OVERLAP, min(H - 0.03, sh + 0.45)
    if zb1 - zb0 > 0.1:
        for i in range(n_cushions):
            y0 = -inner / 2 + i * cw - OVERLAP
            y1 = y0 + cw + 2 * OVERLAP
            out.append(Part(soft((bct, y1 - y0, zb1 - zb0),
                                 (-D / 2 + bt - OVERLAP + bct / 2, (y0 + y1) / 2, (zb0 + zb1) / 2),
                                 min(cr, bct / 3)), "cushion"))
    if on_legs:
        lt = 0.05
        for leg in legs((D, W), 0.03, lt, 0.0, lh + OVERLAP, taper=0.7 if detail else 1.0,
                        round_legs=True, circumscribed=not detail, sections=16 if detail else 8):
            out.append(Part(leg, "wood"))
    return out


def _upholstered_params(width: tuple[float, float], depth: tuple[float, float], height: tuple[float, float],
                        arm_width: tuple[float, float], back: tuple[float, float]) -> dict[str, Param]:
    return {
        "width": Param(*width, doc="Y extent including arms (m)"),
        "depth": Param(*depth, doc="X extent (m)"),
        "height": Param(*height, doc="height of the back's top (m)"),
        "seat_height": Param(0.40, 0.46, doc="height of the seat cushions' upper face (m)"),
        "cushion_thickness": Param(0.10, 0.16, doc="seat cushion thickness (m)"),
        "arm_width": Param(*arm_width, doc="arm Y extent (m)"),
        "arm_height": Param(0.55, 0.68, doc="height of the arms' top (m)"),
        "arm_style": Param(kind="choice", choices=("square", "rounded"), doc="arm shape"),
        "back_thickness": Param(*back, doc="back X extent (m)"),
        "corner_radius": Param(0.01, 0.04, doc="rounding of the upholstery (m)"),
        "base_style": Param(kind="choice", choices=("legs", "plinth"),
                            doc="on short legs or sitting on a plinth base"),
        "leg_height": Param(0.05, 0.15, doc="leg height when on legs (m)"),
    }


@register
class Sofa(PartsFactory):
    """A sofa: base, back, two arms, 2-4 seat cushions with matching back cushions."""

    name = "sofa"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Sofa})
    size_class = "large"
    slots = ["fabric", "cushion", "wood"]
    params = {
        **_upholstered_params((1.6, 2.4), (0.8, 0.95), (0.75, 0.9), (0.1, 0.25), (0.15, 0.25)),
        "n_cushions": Param(2, 4, kind="int", doc="number of seat cushions"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Base, arms, back and `n_cushions` seat and back cushions."""
        return upholstered_parts(p, detail, int(p["n_cushions"]))


@register
class Armchair(PartsFactory):
    """An upholstered armchair: one seat cushion, back, two arms."""

    name = "armchair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Armchair})
    size_class = "large"
    slots = ["fabric", "cushion", "wood"]
    params = _upholstered_params((0.7, 1.0), (0.75, 0.9), (0.75, 1.0), (0.08, 0.2), (0.12, 0.2))

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Base, arms, back and one seat and back cushion."""
        return upholstered_parts(p, detail, 1)


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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Base, arm, back, seat and back cushions and legs or a plinth."""
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Each seat cushion's top (`seat_i`) and the chaise's (`chaise`)."""
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
