"""Occasional tables: low coffee tables and side tables (optionally with a lower shelf), and narrow
console tables with drawers in the apron (articulated, front +X)."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.generators.tables._parts import (
    rect_table_parts,
    rect_table_surfaces,
    table_params,
    translate_parts,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S


@register
class CoffeeTable(PartsFactory):
    """A low rectangular coffee table, optionally with a lower shelf."""

    name = "coffee_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.CoffeeTable})
    size_class = "large"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.5, 0.8, doc="X extent (m)"),
        "length": Param(0.9, 1.4, doc="Y extent (m)"),
        **table_params((0.38, 0.48), (0.035, 0.07)),
        "apron": Param(kind="bool", doc="add apron boards under the top"),
        "apron_height": Param(0.04, 0.08, doc="apron board height (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf between the legs"),
        "shelf_height": Param(0.08, 0.15, doc="height of the lower shelf's upper face (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, legs, optional apron and lower shelf."""
        return rect_table_parts(p, detail, p["depth"], p["length"], apron=p["apron"])

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and the four side facets."""
        return rect_table_surfaces(p, p["depth"], p["length"])


@register
class SideTable(PartsFactory):
    """A small square-ish side table, optionally with a lower shelf."""

    name = "side_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.SideTable})
    size_class = "medium"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.4, 0.6, doc="X extent (m)"),
        "width": Param(0.4, 0.6, doc="Y extent (m)"),
        **table_params((0.5, 0.65), (0.03, 0.05)),
        "apron": Param(kind="bool", doc="add apron boards under the top"),
        "apron_height": Param(0.04, 0.08, doc="apron board height (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf between the legs"),
        "shelf_height": Param(0.12, 0.25, doc="height of the lower shelf's upper face (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, legs, optional apron and lower shelf."""
        return rect_table_parts(p, detail, p["depth"], p["width"], apron=p["apron"])

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and the four side facets."""
        return rect_table_surfaces(p, p["depth"], p["width"])


def _drawer_joints(fronts, depth: float) -> list:
    """Prismatic joints for drawers `depth` deep, opening to 80% of it."""
    return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for _, m in fronts]


@register
class ConsoleTable(PartsFactory):
    """A narrow hall / sofa table: a top on four straight, tapered or round legs or on two slab
    ends, with an apron holding 0-3 drawers (articulated) and an optional lower shelf (a
    support surface, `shelf`)."""

    name = "console_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.ConsoleTable})
    size_class = "large"
    slots = ["wood", "front", "metal"]
    params = {
        "width": Param(0.8, 1.6, doc="Y extent (m)"),
        "depth": Param(0.25, 0.45, doc="X extent (m)"),
        "height": Param(0.72, 0.85, doc="height of the top's upper face (m)"),
        "top_thickness": Param(0.02, 0.045, doc="top thickness (m)"),
        "edge_radius": Param(0.0, 0.008, doc="rounding of the top's edges (m)"),
        "leg_style": Param(kind="choice", choices=("straight", "tapered", "round", "panel"),
                           doc="leg shape, or two slab ends"),
        "leg_thickness": Param(0.03, 0.05, doc="leg section / slab-end thickness (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf near the floor"),
        "shelf_height": Param(0.12, 0.3, doc="height of the lower shelf's upper face (m)"),
        "n_drawers": Param(0, 3, kind="int", doc="drawers in the apron"),
        "apron_height": Param(0.08, 0.14, doc="apron height under the top (m)"),
    }
    INSET = 0.02
    BOARD = 0.016

    def _carcass_span(self, p) -> tuple[float, float, float, float]:
        """x0, x_front, y0, y1 of the apron's drawer carcass."""
        D, W, lt = p["depth"], p["width"], p["leg_thickness"]
        xf = D / 2 - FRONT_PROUD - 0.005
        x0 = -D / 2 + self.INSET
        yi = W / 2 - self.INSET - lt + OVERLAP  # between the legs' (or ends') inner faces
        return x0, xf, -yi, yi

    def _fronts(self, p):
        n = int(p["n_drawers"])
        if n == 0:
            return [], 0.0
        h, tt, ah, t = p["height"], p["top_thickness"], p["apron_height"], self.BOARD
        x0, xf, y0, y1 = self._carcass_span(p)
        z0, z1 = h - tt - ah + t, h - tt
        inner0, inner1 = y0 + t, y1 - t
        cw = (inner1 - inner0 - (n - 1) * t) / n
        cells = [Front(inner0 + i * (cw + t), inner0 + i * (cw + t) + cw, z0, z1,
                       "drawer") for i in range(n)]
        depth = xf - x0 - 0.006 - 0.02
        return cabinet_fronts(xf, cells, depth), depth

    def _table_params(self, p) -> dict[str, Any]:
        return {"height": p["height"], "top_thickness": p["top_thickness"],
                "edge_radius": p["edge_radius"],
                "leg_thickness": p["leg_thickness"], "leg_inset": self.INSET, "leg_style": p["leg_style"],
                "apron_height": p["apron_height"], "lower_shelf": p["lower_shelf"],
                "shelf_height": p["shelf_height"], "stretchers": False}

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top on legs or slab ends, lower shelf, and the apron with its drawers."""
        D, W, h, tt = p["depth"], p["width"], p["height"], p["top_thickness"]
        lt, t = p["leg_thickness"], self.BOARD
        n = int(p["n_drawers"])
        if p["leg_style"] != "panel":
            out = rect_table_parts(self._table_params(p), detail, D, W, apron=n == 0)
        else:
            er = p["edge_radius"]
            out = [Part(bevel_box((D, W, tt), (0, 0, h - tt / 2), er, 2) if detail and er > 1e-4
                        else box((D, W, tt), (0, 0, h - tt / 2)), "wood")]
            for s in (-1, 1):
                ya, yb = sorted((s * (W / 2 - self.INSET), s * (W / 2 - self.INSET - lt)))
                out.append(board((-D / 2 + self.INSET, ya, 0.0),
                                  (D / 2 - self.INSET, yb, h - tt + OVERLAP), "wood"))
            if p["lower_shelf"]:
                yi = W / 2 - self.INSET - lt + OVERLAP
                zs = p["shelf_height"]
                out.append(board((-D / 2 + self.INSET, -yi, zs - 0.018), (D / 2 - self.INSET, yi, zs),
                                  "wood"))
            if n == 0:  # a back apron stiffening the ends
                yi = W / 2 - self.INSET - lt + OVERLAP
                out.append(board((-D / 2 + self.INSET, -yi, h - tt - p["apron_height"]),
                                  (-D / 2 + self.INSET + 0.02, yi, h - tt + OVERLAP), "wood"))
        if n:
            x0, xf, y0, y1 = self._carcass_span(p)
            z0 = h - tt - p["apron_height"]
            if detail:
                inner0, inner1 = y0 + t, y1 - t
                cw = (inner1 - inner0 - (n - 1) * t) / n
                dividers = [inner0 + i * (cw + t) - t / 2 for i in range(1, n)]
                cc = carcass(xf - x0, y1 - y0, z0, h - tt + OVERLAP, t, back=0.006, dividers=dividers,
                             top=False)
                out += translate_parts(cc, ((xf + x0) / 2, (y0 + y1) / 2, 0.0))
                fronts, _ = self._fronts(p)
                for parts, _ in fronts:
                    out += parts
            else:
                out.append(board((x0, y0, z0), (D / 2 - 0.005, y1, h - tt + OVERLAP), "front"))
        return out

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """A prismatic joint per apron drawer."""
        fronts, depth = self._fronts(p)
        return _drawer_joints(fronts, depth)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and the lower `shelf`."""
        D, W, h, lt = p["depth"], p["width"], p["height"], p["leg_thickness"]
        out = [support_rect("top", (0, 0, h), D / 2 - 0.02, W / 2 - 0.02)]
        if p["lower_shelf"]:
            if p["leg_style"] == "panel":
                hx, hy = D / 2 - self.INSET - 0.01, W / 2 - self.INSET - lt - 0.01
            else:  # the shelf spans between the legs' centre lines; keep clear of the legs
                hx = D / 2 - self.INSET - lt - 0.01
                hy = W / 2 - self.INSET - lt - 0.01
            out.append(support_rect("shelf", (0, 0, p["shelf_height"]), hx, hy))
        return out
