"""Seating: dining chairs, sofas and armchairs. Front (+X) is where one sits from."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S


def _shear_back(solid, z0: float, tilt_deg: float):
    """Lean everything above z0 backwards (-X) by `tilt_deg` (a shear: horizontal sections keep
    their shape, so boxes stay boxes and the low-detail back still contains the detailed one)."""
    if tilt_deg <= 1e-6:
        return solid
    k = math.tan(math.radians(tilt_deg))
    mat = np.array([[1.0, 0.0, -k, k * z0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])
    return solid.transform(mat)


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

    def parts(self, p, detail):
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
            out.append(Part(_shear_back(b, sh, tilt), "wood"))
        if p["stretchers"]:
            zs, w = 0.14, min(0.018, lt * 0.6)
            for s in (-1, 1):
                out.append(Part(box_between((-cx, s * cy - w / 2, zs - w / 2),
                                            (cx, s * cy + w / 2, zs + w / 2)), "wood"))
            out.append(Part(box_between((cx - w / 2, -cy, zs + 0.04 - w / 2),
                                        (cx + w / 2, cy, zs + 0.04 + w / 2)), "wood"))
        return out

    def extra_surfaces(self, p):
        sd, sw, sh, lt = p["seat_depth"], p["seat_width"], p["seat_height"], p["leg_thickness"]
        x0, x1 = -sd / 2 + lt + 0.01, sd / 2 - 0.02
        return [support_rect("seat", ((x0 + x1) / 2, 0, sh), (x1 - x0) / 2, sw / 2 - 0.02)]


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


def _upholstered_params(width, depth, height, arm_width, back) -> dict[str, Param]:
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

    def parts(self, p, detail):
        return upholstered_parts(p, detail, int(p["n_cushions"]))


@register
class Armchair(PartsFactory):
    """An upholstered armchair: one seat cushion, back, two arms."""

    name = "armchair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Armchair})
    size_class = "large"
    slots = ["fabric", "cushion", "wood"]
    params = _upholstered_params((0.7, 1.0), (0.75, 0.9), (0.75, 1.0), (0.08, 0.2), (0.12, 0.2))

    def parts(self, p, detail):
        return upholstered_parts(p, detail, 1)
