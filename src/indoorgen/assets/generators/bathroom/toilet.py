"""Toilets: two-piece, one-piece and wall-hung, with a seat and lid on their own links.

Front faces +X, the back (-X) against the wall. The bowl is a real hollow (manifold3d
subtraction), open at the top.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.bathroom._parts import (
    FIXTURE_MATERIALS,
    Prim,
    ellipse,
    hollow,
    hull_stack,
    outline_points,
    outline_polygon,
    prim_parts,
    rounded_rect,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


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
        """Whether the toilet stands on its foot (floor-standing), not hung on the wall."""
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
        x_h = x_hl + tl + MOVING_GAP  # back edge of the seat (the lid rests behind it when both open)
        x_e = x_h - 0.02 + a  # centre of the rim ellipse
        z_s = H + MOVING_GAP  # underside of the seat
        z_l = z_s + ts + MOVING_GAP  # underside of the lid
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
            return [("cyl", 0.022, 0.009, (g["cd"] / 2, 0.0, top - OVERLAP))]
        x, y, z = g["cd"] - 0.05, g["cw"] / 2, g["H"] + g["ch"] - 0.05
        if g["style"] == "one_piece":  # its sides lean in: 0.5 cw wide at H - 0.12, 0.46 cw at the top
            y = g["cw"] * (0.5 - 0.04 * (z - g["H"] + 0.12) / (g["ch"] + 0.12)) - 0.004
        return [("rod", (x, y - OVERLAP, z), (x, y + 0.01, z), 0.018),
                ("rod", (x, y + 0.012, z), (x - 0.075, y + 0.012, z + 0.01), 0.007)]

    def _cistern(self, p, g) -> list[Part]:
        H, cd, cw, ch = g["H"], g["cd"], g["cw"], g["ch"]
        if g["style"] == "two_piece":
            body = box_between((0.0, -cw / 2, H - 0.01), (cd, cw / 2, H + ch))
            lid = box_between((0.0, -cw / 2 - 0.008, H + ch - OVERLAP),
                              (cd + 0.008, cw / 2 + 0.008, H + ch + 0.025))
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
                                    - opening.offset(0.005, m3d.JoinType.Round, 2.0, 24), ts * 0.4 + OVERLAP)
        return low + high.translate((0.0, 0.0, z + ts * 0.6 - OVERLAP))

    def _lid(self, g) -> m3d.Manifold:
        outline = self._outline(g, g["x_hl"])
        tl, z = g["tl"], g["z_l"]
        return hull_stack([(z, outline), (z + 0.5 * tl, outline),
                            (z + tl, outline.offset(-0.012, m3d.JoinType.Round, 2.0, 24))])

    # ---- generator protocol
    def parts(self, p, detail):
        """The toilet's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        H, a, b, x_e = g["H"], g["a"], g["b"], g["x_e"]
        out: list[Part] = []
        if detail:
            out.append(Part(hollow(self._body(p, g), self._cavity(g)), "porcelain"))
            if not g["wall"]:
                out += self._cistern(p, g)
            for s in (-1, 1):  # hinge posts under the lid's back edge
                out.append(Part(box_between((g["x_hl"] + 0.004, s * 0.7 * b - 0.015, H - OVERLAP),
                                            (g["x_h"] - MOVING_GAP, s * 0.7 * b + 0.015,
                                             g["z_s"] + g["ts"] - 0.001)),
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
        """The toilet's joints: seat_joint, lid_joint."""
        g = self._g(p)
        up = self._open_limit(g, g["x_hl"], g["front"] - g["x_hl"])
        axis = np.array([0.0, -1.0, 0.0])
        seat = DoorJoint("revolute", axis, np.array([g["x_h"], 0.0, g["z_s"] + g["ts"]]), "seat")
        lid = DoorJoint("revolute", axis, np.array([g["x_hl"], 0.0, g["z_l"] + g["tl"]]), "lid")
        return [make_joint("seat_joint", seat, 0.0, up), make_joint("lid_joint", lid, 0.0, up)]

    def extra_surfaces(self, p):
        """The toilet's surfaces besides its bounding box's: back, bottom."""
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
