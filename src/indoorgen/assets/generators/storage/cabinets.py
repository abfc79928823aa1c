"""Closed storage built as cases: TV stands, cabinets (doors over shelves, optional drawer row),
dressers (rows of drawers) and nightstands. Every door and drawer is articulated; `top` is a
support surface."""
from __future__ import annotations

import math
from typing import Any

from indoorgen.assets.generators.storage._cases import (
    Case,
    CaseFactory,
    Row,
    back_surface,
    base_bottom,
    case_layout,
    interior_surface,
    shelf_board,
    shelf_heights,
    top_surface,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.moving_parts import (
    DOOR_OPEN,
    FRONT_PROUD,
    Front,
    cabinet_fronts,
    make_joint,
)
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


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

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """Whether it stands on a plinth (its footprint rests on mesh)."""
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Carcass, top, fronts (placeholder: one block) and a plinth or legs."""
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

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The doors' hinges and the drawers' slides."""
        return [make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN) if m.kind == "revolute"
                else make_joint(f"{m.link}_joint", m, 0.0, 0.8 * (p["depth"] - p["board_thickness"] - 0.02))
                for _, m in self._fronts(p)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` (for the TV), the carcass footprint and its back."""
        W, D, H, zb = p["width"], p["depth"], p["height"], p["base_height"]
        z0 = 0.0 if p["base_style"] == "plinth" else zb
        return [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02),
                bottom_rect((0, 0, 0), D / 2, W / 2),  # the carcass footprint, handles excluded
                Surface.rect("back", Subpart.Back, (-D / 2, 0, (z0 + H) / 2), (-1, 0, 0), (0, 1, 0),
                             W / 2, (H - z0) / 2)]


@register
class Cabinet(CaseFactory):
    """A freestanding cabinet: 1-2 hinged doors (flat, shaker or glazed) over fixed interior
    shelves, an optional row of drawers on top, on legs or a plinth. Its `top` is a support
    surface; the compartment floor and shelves are Interior surfaces."""

    name = "cabinet"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet})
    size_class = "large"
    params = {
        "width": Param(0.4, 1.0, doc="carcass Y extent (m)"),
        "depth": Param(0.32, 0.6, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.7, 1.9, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_doors": Param(1, 2, kind="int", doc="doors side by side"),
        "drawer_row": Param(kind="bool", doc="a row of drawers above the doors"),
        "n_shelves": Param(0, 4, kind="int",
                           doc="interior shelves behind the doors (fewer if < 18 cm apart)"),
        "door_style": Param(kind="choice", choices=("flat", "shaker", "glass"), doc="door design"),
        "base_style": Param(kind="choice", choices=("plinth", "legs", "round_legs"),
                            doc="what the carcass stands on"),
        "base_height": Param(0.04, 0.18, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "top_overhang": Param(0.0, 0.03, doc="how far the top overhangs the front and sides (m)"),
    }

    def _n_doors(self, p) -> int:
        return 1 if p["width"] < 0.5 else int(p["n_doors"])

    def layout(self, p: dict[str, Any]) -> Case:
        """A door row (and a drawer row on top with `drawer_row`) over the base."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        nd = self._n_doors(p)
        free = z_top - p["base_height"] - 2 * t  # interior height less one separator board
        rows = [Row("door", 1.0, nd)]
        if p["drawer_row"]:
            dh = 0.16 if free < 0.8 else 0.2
            rows = [Row("door", free - dh, nd), Row("drawer", dh, nd)]
        return case_layout(W, D, t, 0.006, p["base_height"], z_top, rows, overlay=True)

    def _shelves(self, p, case):
        _, z0, z1 = case.rows[0]
        return shelf_heights(z0, z1, int(p["n_shelves"]), case.t, 0.18)

    def _interior_parts(self, p, case):
        yi0, yi1 = case.inner()
        return [shelf_board(case, yi0, yi1, z) for z in self._shelves(p, case)]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The case, its shelves and fronts, top board and base."""
        return self._topped_case(p, detail, p["base_height"])

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top`, the footprint, the back and the compartment floor and shelves."""
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        yi0, yi1 = case.inner()
        _, z0, _ = case.rows[0]
        out = [top_surface(D, W, H, p["top_overhang"]),
               base_bottom(D, W, p["base_style"]),
               back_surface(W, p["base_height"], H, D)]
        for i, z in enumerate([z0] + self._shelves(p, case)):
            out.append(interior_surface(f"interior_{i}", case, yi0, yi1, z))
        return out


def _graduated_rows(n: int, graduated: bool) -> list[float]:
    """Row weights bottom first: graduated dressers have deeper drawers lower down."""
    return [1.0 + (0.18 * (n - 1 - i) if graduated else 0.0) for i in range(n)]


@register
class Dresser(CaseFactory):
    """A chest of drawers: 3-6 rows of 1-3 drawers (optionally graduated, the top row split into
    smaller drawers), overlay or framed fronts, flat or shaker, on a plinth or legs. Every drawer
    is articulated; `top` is a support surface."""

    name = "dresser"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Dresser})
    size_class = "large"
    params = {
        "width": Param(0.6, 1.6, doc="carcass Y extent (m)"),
        "depth": Param(0.4, 0.55, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.7, 1.3, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_rows": Param(3, 6, kind="int", doc="drawer rows (fewer if a row would be < 11 cm)"),
        "drawers_per_row": Param(1, 3, kind="int", doc="drawers side by side (capped by width)"),
        "top_split": Param(kind="bool", doc="split the top row into one more, smaller drawers"),
        "graduated": Param(kind="bool", doc="deeper drawers towards the bottom"),
        "fit": Param(kind="choice", choices=("overlay", "framed"),
                     doc="fronts cover the board edges or sit within the frame"),
        "door_style": Param(kind="choice", choices=("flat", "shaker"), doc="drawer front design"),
        "base_style": Param(kind="choice", choices=("plinth", "legs", "round_legs"),
                            doc="what the carcass stands on"),
        "base_height": Param(0.04, 0.16, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "top_overhang": Param(0.0, 0.03, doc="how far the top overhangs the front and sides (m)"),
    }

    def layout(self, p: dict[str, Any]) -> Case:
        """Rows of drawers, as many as stay at least 11 cm high, graduated or not."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        inner = z_top - p["base_height"] - t
        n = int(p["n_rows"])
        while n > 1 and (inner - (n - 1) * t) / n < 0.11:
            n -= 1
        cols = int(min(p["drawers_per_row"], max(1, math.floor(W / 0.3))))
        weights = _graduated_rows(n, p["graduated"])
        rows = [Row("drawer", w, cols) for w in weights]
        if p["top_split"] and (W - 2 * t) / (cols + 1) >= 0.2:
            rows[-1] = Row("drawer", weights[-1] * 0.8, cols + 1)
        return case_layout(W, D, t, 0.006, p["base_height"], z_top, rows,
                            overlay=p["fit"] == "overlay")

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The case and its drawers, top board and base."""
        return self._topped_case(p, detail, p["base_height"])

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top`, the footprint, the back and each drawer's floor (`drawer_<i>_floor`,
        moving with its drawer)."""
        W, D, H = p["width"], p["depth"], p["height"]
        floors = self.drawer_floors(self.layout(p))
        return [top_surface(D, W, H, p["top_overhang"]),
                base_bottom(D, W, p["base_style"]),
                back_surface(W, p["base_height"], H, D)] + floors


NIGHTSTAND_LAYOUTS = {
    # rows bottom first
    "drawer_shelf": (Row("open", 1.3), Row("drawer", 1.0)),
    "two_drawers": (Row("drawer", 1.0), Row("drawer", 1.0)),
    "drawer_door": (Row("door", 2.0), Row("drawer", 1.0)),
    "open": (Row("open", 1.0), Row("open", 1.0)),
    "three_drawers": (Row("drawer", 1.0), Row("drawer", 1.0), Row("drawer", 1.0)),
}


@register
class Nightstand(CaseFactory):
    """A bedside table: a small case with a drawer over an open shelf, two or three drawers, a
    drawer over a door, or two open shelves; on tall legs or a plinth. `top` is a support
    surface, as is the floor of every open shelf (`shelf_i`); a door compartment's floor is an
    Interior surface."""

    name = "nightstand"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Nightstand})
    size_class = "medium"
    params = {
        "width": Param(0.35, 0.6, doc="carcass Y extent (m)"),
        "depth": Param(0.3, 0.45, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.45, 0.7, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.015, 0.022, doc="board thickness (m)"),
        "layout": Param(kind="choice", choices=tuple(NIGHTSTAND_LAYOUTS),
                        doc="what fills the case, top to bottom"),
        "base_style": Param(kind="choice", choices=("legs", "round_legs", "plinth"),
                            doc="what the case stands on"),
        "base_height": Param(0.03, 0.22, doc="leg / plinth height (m; plinths capped at 8 cm)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "door_style": Param(kind="choice", choices=("flat", "shaker"), doc="front design"),
        "top_overhang": Param(0.0, 0.025, doc="how far the top overhangs the front and sides (m)"),
    }

    def _zb(self, p) -> float:
        return min(p["base_height"], 0.08) if p["base_style"] == "plinth" else p["base_height"]

    def _rows(self, p) -> tuple[Row, ...]:
        rows = NIGHTSTAND_LAYOUTS[p["layout"]]
        inner = p["height"] - p["board_thickness"] - self._zb(p) - p["board_thickness"]
        if len(rows) == 3 and inner < 0.36:
            rows = rows[1:]
        return rows

    def layout(self, p: dict[str, Any]) -> Case:
        """The rows of the chosen layout (three drawers become two in a low case)."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        return case_layout(W, D, t, 0.005, self._zb(p), H - t, self._rows(p), overlay=True)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The case and its fronts, top board and legs or plinth."""
        return self._topped_case(p, detail, self._zb(p), leg=0.032)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top`, footprint, back, open shelf floors and a door compartment's floor."""
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        out = [top_surface(D, W, H, p["top_overhang"]),
               base_bottom(D, W, p["base_style"]),
               back_surface(W, self._zb(p), H, D)]
        yi0, yi1 = case.inner()
        k = 0
        for row, z0, _ in case.rows:
            if row.kind == "open":
                x0, x1 = -D / 2 + case.back, D / 2
                out.append(support_rect(f"shelf_{k}", ((x0 + x1) / 2, 0, z0), (x1 - x0) / 2 - 0.02,
                                        (yi1 - yi0) / 2 - 0.02))
                k += 1
            elif row.kind == "door":
                out.append(interior_surface("interior_0", case, yi0, yi1, z0))
        return out
