"""Storage: TV stands and bookcases (open side / doors facing +X)."""
from __future__ import annotations

import math
from typing import Any

from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

MIN_SHELF_CLEARANCE = 0.25  # books up to ~24 cm tall fit on every shelf


@register
class TVStand(PartsFactory):
    """A low media cabinet: carcass with 2-4 compartments (open, doors or drawers), on legs or a
    plinth. Its `top` is a support surface (for the TV)."""

    name = "tv_stand"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.TVStand})
    size_class = "large"
    slots = ["wood", "front", "metal"]
    params = {
        "width": Param(1.2, 2.0, doc="Y extent (m)"),
        "depth": Param(0.35, 0.5, doc="X extent of the carcass (m)"),
        "height": Param(0.4, 0.6, doc="height of the top's upper face (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_compartments": Param(2, 4, kind="int", doc="compartments side by side"),
        "front_style": Param(kind="choice", choices=("open", "doors", "drawers"),
                             doc="what closes the compartments"),
        "base_style": Param(kind="choice", choices=("legs", "plinth"), doc="legs or a plinth"),
        "base_height": Param(0.04, 0.15, doc="leg or plinth height (m)"),
        "edge_radius": Param(0.0, 0.006, doc="rounding of the top's edges (m)"),
    }

    def bottom_is_solid(self, params):
        return self.resolve(params)["base_style"] == "plinth"

    def _cells(self, p) -> tuple[list[Front], list[float]]:
        """The compartments' fronts (each a door, alternately hinged left and right, or two
        drawers) and the dividers' y positions."""
        W, H, t = p["width"], p["height"], p["board_thickness"]
        zb, n = p["base_height"], int(p["n_compartments"])
        inner = W - 2 * t
        cw = (inner - (n - 1) * t) / n
        z0, z1 = zb + t, H - t
        cells, dividers = [], []
        for i in range(n):
            y0 = -inner / 2 + i * (cw + t)
            y1 = y0 + cw
            if i:
                dividers.append(y0 - t / 2)
            if p["front_style"] == "doors":
                cells.append(Front(y0, y1, z0, z1, "left" if i % 2 == 0 else "right"))
            elif p["front_style"] == "drawers":
                zm = (z0 + z1) / 2
                cells += [Front(y0, y1, z0, zm, "drawer"), Front(y0, y1, zm, z1, "drawer")]
            else:
                cells.append(Front(y0, y1, z0, z1, "open"))
        return cells, dividers

    def _fronts(self, p):
        cells, _ = self._cells(p)
        depth = p["depth"] - p["board_thickness"] - 0.02
        return cabinet_fronts(p["depth"] / 2, cells, depth)

    def parts(self, p, detail):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        zb = p["base_height"]
        _, dividers = self._cells(p)
        out = carcass(D, W, zb, H - t + OVERLAP, t, back=t, dividers=dividers, top=False)
        er = p["edge_radius"]
        top = (bevel_box((D, W, t), (0, 0, H - t / 2), er, 2) if detail and er > 1e-4
               else box((D, W, t), (0, 0, H - t / 2)))
        out.append(Part(top, "wood"))
        if p["front_style"] != "open":
            if detail:
                out += [part for parts, _ in self._fronts(p) for part in parts]
            else:  # closed compartments: their contents, the fronts and handles as one block
                out.append(Part(box_between((-D / 2 + t, -W / 2 + t, zb + t),
                                            (D / 2 + FRONT_PROUD, W / 2 - t, H - t)), "front"))
        if p["base_style"] == "plinth":
            out.append(Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, zb + OVERLAP)), "wood"))
        else:
            for leg in legs((D, W), 0.02, 0.04, 0.0, zb + OVERLAP, taper=0.7 if detail else 1.0,
                            round_legs=True, circumscribed=not detail, sections=16 if detail else 8):
                out.append(Part(leg, "metal"))
        return out

    def joints(self, p):
        return [make_joint(f"{m.link}_joint", m, 0.0, math.radians(100)) if m.kind == "revolute"
                else make_joint(f"{m.link}_joint", m, 0.0, 0.8 * (p["depth"] - p["board_thickness"] - 0.02))
                for _, m in self._fronts(p)]

    def extra_surfaces(self, p):
        W, D, H, zb = p["width"], p["depth"], p["height"], p["base_height"]
        z0 = 0.0 if p["base_style"] == "plinth" else zb
        return [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02),
                bottom_rect((0, 0, 0), D / 2, W / 2),  # the carcass footprint, handles excluded
                Surface.rect("back", Subpart.Back, (-D / 2, 0, (z0 + H) / 2), (-1, 0, 0), (0, 1, 0),
                             W / 2, (H - z0) / 2)]


def bookcase_levels(p: dict[str, Any]) -> tuple[int, float, float]:
    """(number of shelf levels, clearance between them, top of the bottom board). Levels are
    `n_shelves` reduced until each gets >= 25 cm of clearance (the height range ensures >= 3)."""
    H, t, ph = p["height"], p["board_thickness"], p["plinth_height"]
    z_b = ph + t
    k = int(p["n_shelves"])
    while k > 1:
        clear = (H - t - z_b - (k - 1) * t) / k
        if clear >= MIN_SHELF_CLEARANCE:
            break
        k -= 1
    clear = (H - t - z_b - (k - 1) * t) / k
    return k, clear, z_b


@register
class Bookcase(PartsFactory):
    """An open bookcase: sides, back panel, top, a solid plinth and 3-6 shelf levels, each a
    support surface `shelf_i` (shelf_0 = the bottom board)."""

    name = "bookcase"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Bookcase})
    size_class = "large"
    slots = ["wood", "back"]
    solid_bottom = True
    params = {
        "width": Param(0.6, 1.2, doc="Y extent (m)"),
        "depth": Param(0.25, 0.4, doc="X extent (m)"),
        "height": Param(0.95, 2.1, doc="Z extent (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_shelves": Param(3, 6, kind="int",
                           doc="shelf levels incl. the bottom board; reduced if the height cannot "
                               "give each >= 0.25 m of clearance"),
        "plinth_height": Param(0.04, 0.1, doc="plinth height under the bottom board (m)"),
        "back_thickness": Param(0.004, 0.012, doc="back panel thickness (m)"),
        "shelf_setback": Param(0.0, 0.02, doc="how far shelves stop short of the front (m)"),
    }

    def parts(self, p, detail):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        bt, sb = p["back_thickness"], p["shelf_setback"]
        k, clear, z_b = bookcase_levels(p)
        out: list[Part] = [
            Part(box_between((-D / 2, -W / 2, H - t), (D / 2, W / 2, H)), "wood"),  # top
            Part(box_between((-D / 2, -W / 2, 0.0), (-D / 2 + bt, W / 2, H - t + OVERLAP)), "back"),
            Part(box_between((-D / 2 + bt - OVERLAP, -W / 2 + t - OVERLAP, 0.0),
                             (D / 2, W / 2 - t + OVERLAP, p["plinth_height"] + OVERLAP)), "wood"),
        ]
        for s in (-1, 1):
            out.append(Part(box_between((-D / 2 + bt - OVERLAP, min(s * W / 2, s * (W / 2 - t)), 0.0),
                                        (D / 2, max(s * W / 2, s * (W / 2 - t)), H - t + OVERLAP)), "wood"))
        for i in range(k):
            zt = z_b + i * (clear + t)
            x1 = D / 2 if i == 0 else D / 2 - sb
            out.append(Part(box_between((-D / 2 + bt - OVERLAP, -W / 2 + t - OVERLAP, zt - t),
                                        (x1, W / 2 - t + OVERLAP, zt)), "wood"))
        return out

    def extra_surfaces(self, p):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        bt, sb = p["back_thickness"], p["shelf_setback"]
        k, clear, z_b = bookcase_levels(p)
        out = [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02)]
        iw = W - 2 * t
        for i in range(k):
            zt = z_b + i * (clear + t)
            x0, x1 = -D / 2 + bt, (D / 2 if i == 0 else D / 2 - sb)
            out.append(support_rect(f"shelf_{i}", ((x0 + x1) / 2, 0, zt), (x1 - x0 - 0.02) / 2,
                                    (iw - 0.02) / 2))
        return out
