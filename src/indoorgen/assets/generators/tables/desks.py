"""Desks: a top on legs or drawer pedestals, optional centre drawer, modesty panel and hutch.
Drawers slide out on prismatic joints (front, the user side, is +X)."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.generators.tables._parts import translate_parts
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Desk(PartsFactory):
    """A writing / office desk: a top on four legs with an apron, on one drawer pedestal and a
    panel end, or on two pedestals; optional pencil drawer under the middle, modesty panel at
    the back and a hutch (a shelf on two sides) standing on the top's rear. Every drawer slides
    out on its own prismatic joint."""

    name = "desk"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.Desk})
    size_class = "large"
    drop_box = ("side_left", "side_right")  # its chair goes at side_0, the front edge
    slots = ["wood", "front", "metal", "back"]
    params = {
        "width": Param(1.0, 1.8, doc="Y extent (m)"),
        "depth": Param(0.55, 0.8, doc="X extent (m)"),
        "height": Param(0.72, 0.77, doc="height of the top's upper face (m)"),
        "top_thickness": Param(0.02, 0.04, doc="top thickness (m)"),
        "base_style": Param(kind="choice", choices=("legs", "single_pedestal", "double_pedestal"),
                            doc="four legs, one drawer pedestal and a panel end, or two pedestals"),
        "pedestal_side": Param(kind="choice", choices=("left", "right"),
                               doc="side (+Y left, -Y right) of a single pedestal"),
        "n_drawers": Param(2, 4, kind="int", doc="drawers per pedestal"),
        "pedestal_width": Param(0.35, 0.45, doc="pedestal Y extent (m)"),
        "leg_thickness": Param(0.035, 0.06, doc="leg section (m)"),
        "center_drawer": Param(kind="bool", doc="a shallow drawer under the middle of the top"),
        "modesty_panel": Param(kind="bool", doc="a panel closing the back of the knee space"),
        "hutch": Param(kind="bool", doc="a shelf unit standing on the back of the top"),
        "hutch_height": Param(0.25, 0.45, doc="hutch height above the top (m)"),
    }
    BOARD = 0.018
    PLINTH = 0.04
    CENTER_H = 0.1   # centre drawer compartment height (m)

    KNEE = 0.6  # the least knee space between pedestals (m)

    def _style(self, p) -> str:
        """The base style, a double pedestal becoming a single one where the desk is too
        narrow to leave knee space between two."""
        if p["base_style"] == "double_pedestal" and p["width"] < 2 * p["pedestal_width"] + self.KNEE:
            return "single_pedestal"
        return p["base_style"]

    def _pedestals(self, p) -> list[tuple[float, float]]:
        """(y0, y1) of each pedestal."""
        W, pw = p["width"], p["pedestal_width"]
        style = self._style(p)
        if style == "double_pedestal":
            return [(-W / 2, -W / 2 + pw), (W / 2 - pw, W / 2)]
        if style == "single_pedestal":
            return [(W / 2 - pw, W / 2)] if p["pedestal_side"] == "left" else [(-W / 2, -W / 2 + pw)]
        return []

    def _knee(self, p) -> tuple[float, float]:
        """The knee space's y range (between the supports' inner faces)."""
        W, lt = p["width"], p["leg_thickness"]
        peds = self._pedestals(p)
        y0, y1 = -W / 2 + 0.03 + lt, W / 2 - 0.03 - lt
        if self._style(p) == "single_pedestal":
            y0, y1 = (-W / 2 + 0.03, W / 2 - 0.03)
        for a, b in peds:
            if a > 0:
                y1 = a
            else:
                y0 = b
        return y0, y1

    def _front_x(self, p) -> float:
        return p["depth"] / 2 - FRONT_PROUD - 0.005

    def _fronts(self, p):
        """(parts, motion) of every drawer and each drawer's depth."""
        D, h, tt, t = p["depth"], p["height"], p["top_thickness"], self.BOARD
        xf = self._front_x(p)
        x0 = -D / 2 + 0.02
        z_under = h - tt
        out = []
        n = int(p["n_drawers"])
        for k, (y0, y1) in enumerate(self._pedestals(p)):
            zb, zt = self.PLINTH + t, z_under
            step = (zt - zb) / n
            cells = [Front(y0 + t, y1 - t, zb + i * step, zb + (i + 1) * step,
                           "drawer") for i in range(n)]
            depth = xf - x0 - 0.006 - 0.02
            out += [(f, depth) for f in cabinet_fronts(xf, cells, depth, prefix=f"p{k}_")]
        if p["center_drawer"]:
            ky0, ky1 = self._knee(p)
            w, yc = min(0.6, ky1 - ky0 - 0.1), (ky0 + ky1) / 2
            cells = [Front(yc - w / 2 + t, yc + w / 2 - t, z_under - self.CENTER_H + t, z_under,
                           "drawer")]
            depth = min(0.4, xf - x0 - 0.03)
            out += [(f, depth) for f in cabinet_fronts(xf, cells, depth, prefix="c_")]
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, pedestals or legs with aprons, panels, drawers and the hutch."""
        W, D, h, tt = p["width"], p["depth"], p["height"], p["top_thickness"]
        t, lt = self.BOARD, p["leg_thickness"]
        z_under = h - tt
        xf, x0 = self._front_x(p), -D / 2 + 0.02
        out = [Part(bevel_box((D, W, tt), (0, 0, h - tt / 2), 0.004, 2) if detail else
                    box((D, W, tt), (0, 0, h - tt / 2)), "wood")]
        for y0, y1 in self._pedestals(p):
            pd, pw = xf - x0, y1 - y0
            ctr = ((xf + x0) / 2, (y0 + y1) / 2, 0.0)
            if detail:
                out += translate_parts(carcass(pd, pw, self.PLINTH, z_under + OVERLAP, t, back=0.006,
                                          top=False), ctr)
            else:
                out.append(board((x0, y0, self.PLINTH), (D / 2 - 0.005, y1, z_under + OVERLAP), "front"))
            out.append(board((x0 + 0.01, y0 + 0.01, 0.0), (xf - 0.03, y1 - 0.01, self.PLINTH + OVERLAP),
                              "wood"))
        style = self._style(p)
        if style == "legs":
            for leg in legs((D, W), 0.03, lt, 0.0, z_under + OVERLAP, taper=0.8 if detail else 1.0):
                out.append(Part(leg, "wood"))
            cx, cy = D / 2 - 0.03 - lt / 2, W / 2 - 0.03 - lt / 2
            ah = 0.07
            for s in (-1, 1):  # side aprons and the back apron
                out.append(board((-cx, s * cy - 0.01, z_under - ah),
                                  (cx, s * cy + 0.01, z_under + OVERLAP), "wood"))
            out.append(board((-cx - 0.01, -cy, z_under - ah), (-cx + 0.01, cy, z_under + OVERLAP),
                              "wood"))
        elif style == "single_pedestal":
            s = -1 if p["pedestal_side"] == "left" else 1
            ya, yb = sorted((s * W / 2, s * (W / 2 - 0.03)))
            out.append(board((-D / 2 + 0.02, ya, 0.0), (D / 2 - 0.02, yb, z_under + OVERLAP), "wood"))
        ky0, ky1 = self._knee(p)
        if p["modesty_panel"]:
            # against the carcasses' back panels (no sealed gap between them)
            out.append(board((-D / 2 + 0.02, ky0 - OVERLAP, z_under - 0.35),
                              (-D / 2 + 0.04, ky1 + OVERLAP, z_under + OVERLAP), "wood"))
        if p["center_drawer"]:
            w, yc = min(0.6, ky1 - ky0 - 0.1), (ky0 + ky1) / 2
            zc = z_under - self.CENTER_H
            if detail:
                cd = carcass(xf - x0, w, zc, z_under + OVERLAP, t, back=0.006, top=False)
                out += translate_parts(cd, ((xf + x0) / 2, yc, 0.0))
            else:
                out.append(board((x0, yc - w / 2, zc), (D / 2 - 0.005, yc + w / 2, z_under + OVERLAP),
                                  "front"))
        if detail:
            for parts, _ in (f for f, _ in self._fronts(p)):
                out += parts
        if p["hutch"]:
            out += self._hutch(p, detail)
        return out

    def _hutch_depth(self, p) -> float:
        return min(0.3, 0.4 * p["depth"])

    def _hutch(self, p, detail) -> list[Part]:
        W, D, h, hh = p["width"], p["depth"], p["height"], p["hutch_height"]
        t, hd = self.BOARD, self._hutch_depth(p)
        x0, x1 = -D / 2, -D / 2 + hd
        z0, z1 = h - OVERLAP, h + hh
        out = [board((x0, -W / 2, z1 - t), (x1, W / 2, z1), "wood"),
               board((x0, -W / 2 + t - OVERLAP, z0),
                      (x0 + 0.008, W / 2 - t + OVERLAP, z1 - t + OVERLAP), "back")]
        for s in (-1, 1):
            ya, yb = sorted((s * W / 2, s * (W / 2 - t)))
            out.append(board((x0, ya, z0), (x1, yb, z1 - t + OVERLAP), "wood"))
        return out

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """A prismatic joint per drawer, opening to 80% of its depth."""
        return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for (_, m), depth in self._fronts(p)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` (in front of any hutch), the front edge `side_0`, the hutch top."""
        W, D, h = p["width"], p["depth"], p["height"]
        x0 = -D / 2 + (self._hutch_depth(p) + 0.01 if p["hutch"] else 0.02)
        x1 = D / 2 - 0.02
        out = [support_rect("top", ((x0 + x1) / 2, 0, h), (x1 - x0) / 2, W / 2 - 0.02),
               Surface.rect("side_0", Subpart.Side, (D / 2, 0, h / 2), (1, 0, 0), (0, 1, 0), W / 2,
                            h / 2)]
        if p["hutch"]:
            hd = self._hutch_depth(p)
            out.append(support_rect("hutch_top", (-D / 2 + hd / 2, 0, h + p["hutch_height"]),
                                    hd / 2 - 0.02,
                                    W / 2 - 0.02))
        return out
