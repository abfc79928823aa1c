"""A workbench: a thick top at standing work height on four stout legs braced by rails, a lower
shelf, and maybe a pegboard back with hooks and a drawer under the top (front, the user side,
is +X; its back stands against a wall)."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.generators.tables._parts import translate_parts
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box, rod
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S

#: the drawer box's height under the top (m) and its width's share of the bench
DRAWER_H = 0.12
DRAWER_W = (0.4, 0.55)
#: how far the legs' outer faces stand in from the top's edges (m)
LEG_INSET = 0.03
#: how far a tool hook stands out of the pegboard (m): the top's surface starts in front of them
HOOK_REACH = 0.07


@register
class Workbench(PartsFactory):
    """A garage or workshop bench: a thick top (butcher block or plywood) 0.86-0.95 m high, on
    four stout timber or steel legs with rails near the floor carrying a lower shelf; maybe a
    pegboard back standing on the top's rear edge with tool hooks, and a drawer hung under the
    top at one end, sliding out on a prismatic joint."""

    name = "workbench"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.Workbench})
    size_class = "large"
    slots = ["wood", "leg", "back", "front", "metal"]
    material_choices = {
        "wood": {"oak": 2.0, "plywood": 2.0, "pine_planks": 2.0, "walnut": 0.3},
        "leg": {"pine_planks": 2.0, "painted_metal": 2.0, "galvanized_steel": 1.0, "oak": 0.5},
        "back": {"plywood": 3.0, "painted_wood": 1.0, "painted_metal": 0.5},
    }
    params = {
        "width": Param(1.2, 2.0, doc="Y extent of the top (m)"),
        "depth": Param(0.55, 0.75, doc="X extent of the top (m)"),
        "height": Param(0.86, 0.95, doc="height of the top's upper face: standing work height (m)"),
        "top_thickness": Param(0.03, 0.06, doc="top thickness (m)"),
        "leg_thickness": Param(0.05, 0.09, doc="leg section (m)"),
        "shelf_height": Param(0.12, 0.25, doc="height of the lower shelf's upper face (m)"),
        "pegboard": Param(kind="bool", doc="a pegboard back with tool hooks on the top's rear"),
        "pegboard_height": Param(0.45, 0.75, doc="how far the pegboard rises above the top (m)"),
        "drawer": Param(kind="bool", doc="a drawer hung under the top at one end"),
        "drawer_side": Param(kind="choice", choices=("left", "right"),
                             doc="the end (+Y left, -Y right) the drawer hangs at"),
        "n_hooks": Param(3, 8, kind="int", doc="tool hooks on the pegboard"),
    }
    BOARD = 0.018
    PEG_T = 0.012  # pegboard thickness (m)

    def _rail_box(self, p) -> tuple[float, float]:
        """(x, y) half extents of the rectangle through the legs' centre lines."""
        inset, lt = LEG_INSET, p["leg_thickness"]
        return p["depth"] / 2 - inset - lt / 2, p["width"] / 2 - inset - lt / 2

    def _drawer_span(self, p) -> tuple[float, float]:
        """(y0, y1) of the drawer's box, between the legs at its end."""
        W, lt, inset = p["width"], p["leg_thickness"], LEG_INSET
        w = min(DRAWER_W[1], max(DRAWER_W[0], 0.3 * W))
        inner = W / 2 - inset - lt - 0.005
        return (inner - w, inner) if p["drawer_side"] == "left" else (-inner, -inner + w)

    def _fronts(self, p):
        """(parts, motion) of the drawer, if any, and its depth."""
        if not p["drawer"]:
            return []
        D, h, tt = p["depth"], p["height"], p["top_thickness"]
        xf = D / 2 - FRONT_PROUD - 0.005
        x0 = -D / 2 + LEG_INSET + p["leg_thickness"]
        y0, y1 = self._drawer_span(p)
        z1 = h - tt
        t = self.BOARD
        cells = [Front(y0 + t, y1 - t, z1 - DRAWER_H + t, z1, "drawer")]
        depth = xf - x0 - 0.03
        return [(f, depth) for f in cabinet_fronts(xf, cells, depth, handle="bar")]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, legs, rails and lower shelf, the drawer box and front, the pegboard and hooks."""
        W, D, h, tt = p["width"], p["depth"], p["height"], p["top_thickness"]
        lt, inset = p["leg_thickness"], LEG_INSET
        z_under = h - tt
        top = bevel_box((D, W, tt), (0, 0, h - tt / 2), 0.003, 2) if detail else \
            box((D, W, tt), (0, 0, h - tt / 2))
        out = [Part(top, "wood")]
        out += [Part(leg, "leg") for leg in legs((D, W), inset, lt, 0.0, z_under + OVERLAP)]
        cx, cy = self._rail_box(p)
        zs = p["shelf_height"]
        # rails along the front and back carry the shelf; rails along the ends, under the top,
        # brace the legs (none along the front under the top: a drawer slides out there)
        rh = min(0.06, lt)
        for s in (-1, 1):
            out.append(board((s * cx - lt / 2 + 0.01, -cy, zs - self.BOARD - rh),
                             (s * cx + lt / 2 - 0.01, cy, zs - self.BOARD + OVERLAP), "leg"))
            out.append(board((-cx, s * cy - lt / 2 + 0.01, z_under - rh),
                             (cx, s * cy + lt / 2 - 0.01, z_under + OVERLAP), "leg"))
        out.append(board((-cx - lt / 2, -cy + lt / 2 - OVERLAP, zs - self.BOARD),
                         (cx + lt / 2, cy - lt / 2 + OVERLAP, zs), "wood"))
        if p["drawer"]:
            y0, y1 = self._drawer_span(p)
            x0, xf = -D / 2 + inset + lt, D / 2 - 0.005
            if detail:
                box_parts = carcass(xf - FRONT_PROUD - x0, y1 - y0, z_under - DRAWER_H,
                                    z_under + OVERLAP, self.BOARD, top=False)
                out += translate_parts(box_parts, ((xf - FRONT_PROUD + x0) / 2, (y0 + y1) / 2, 0.0))
                out += [q for parts, _ in (f for f, _ in self._fronts(p)) for q in parts]
            else:
                out.append(board((x0, y0, z_under - DRAWER_H), (xf, y1, z_under + OVERLAP), "front"))
        if p["pegboard"]:
            out += self._pegboard(p, detail)
        return out

    def _pegboard(self, p, detail) -> list[Part]:
        """The board standing on the top's rear edge and, in detail, its hooks."""
        W, D, h, ph = p["width"], p["depth"], p["height"], p["pegboard_height"]
        x0 = -D / 2
        out = [board((x0, -W / 2, h - OVERLAP), (x0 + self.PEG_T, W / 2, h + ph), "back")]
        if detail:
            n = int(p["n_hooks"])
            step = (W - 0.2) / n
            for i in range(n):
                y = -W / 2 + 0.1 + (i + 0.5) * step
                z = h + ph * (0.45 if i % 2 else 0.7)
                tip = (x0 + self.PEG_T + HOOK_REACH, y, z + 0.02)
                out.append(Part(rod((x0 + self.PEG_T - OVERLAP, y, z), tip, 0.003, 8), "metal"))
        return out

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """A prismatic joint for the drawer, opening to 80% of its depth."""
        return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for (_, m), depth in self._fronts(p)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` (in front of any pegboard's hooks) and the lower `shelf`, both support surfaces."""
        W, D, h = p["width"], p["depth"], p["height"]
        x0 = -D / 2 + (self.PEG_T + HOOK_REACH + 0.01 if p["pegboard"] else 0.02)
        x1 = D / 2 - 0.02
        cx, cy = self._rail_box(p)
        lt = p["leg_thickness"]
        return [support_rect("top", ((x0 + x1) / 2, 0, h), (x1 - x0) / 2, W / 2 - 0.02),
                support_rect("shelf", (0, 0, p["shelf_height"]), cx + lt / 2 - 0.01,
                             cy - lt / 2 - 0.01)]
