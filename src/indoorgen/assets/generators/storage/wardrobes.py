"""Wardrobes: hinged or sliding doors over a hanging rail, hat shelf and shelf column, optional drawer
rows, on a plinth or legs. Interior shelves and floors are Interior surfaces."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from indoorgen.assets.generators.storage._cases import (
    Case,
    CaseFactory,
    Row,
    back_surface,
    base_bottom,
    case_base,
    case_body,
    case_fronts,
    case_layout,
    front_decor,
    front_proud,
    interior_surface,
    shelf_board,
    shelf_heights,
)
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.hanging import RAIL_RADIUS, rail_surface
from indoorgen.assets.shapes.moving_parts import DOOR_OPEN, FRONT_T, MOVING_GAP, REVEAL, DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, rod
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S

SLIDE_SPACING = 0.006   # between the two sliding-door tracks (room for the inner door's pull)


SLIDE_OVERLAP = 0.04    # how far the closed sliding doors overlap at the middle


@register
class Wardrobe(CaseFactory):
    """A tall wardrobe: 2-4 hinged doors (flat, shaker or mirrored) or two sliding doors on
    separate tracks, a hanging rail under a hat shelf, a shelf column behind the third/fourth
    door, optional drawer rows at the bottom; on a plinth or legs. Interior shelves and floors
    are Interior surfaces; `top` is a support surface (boxes on the wardrobe)."""

    name = "wardrobe"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Wardrobe})
    size_class = "large"
    params = {
        "width": Param(0.8, 2.4, doc="carcass Y extent (m)"),
        "depth": Param(0.52, 0.65, doc="carcass X extent, doors excluded (m)"),
        "height": Param(1.8, 2.4, doc="overall height (m)"),
        "board_thickness": Param(0.018, 0.025, doc="board thickness (m)"),
        "door_type": Param(kind="choice", choices=("hinged", "sliding"), doc="door mechanism"),
        "n_doors": Param(2, 4, kind="int",
                         doc="hinged doors (kept to 30-65 cm each); sliding wardrobes have two"),
        "door_style": Param(kind="choice", choices=("flat", "shaker", "mirror"), doc="door design"),
        "drawer_rows": Param(0, 2, kind="int", doc="rows of drawers at the bottom"),
        "shelf_drop": Param(0.25, 0.45, doc="hat shelf distance below the carcass top (m)"),
        "base_style": Param(kind="choice", choices=("plinth", "legs"), doc="plinth or legs"),
        "base_height": Param(0.05, 0.12, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type (hinged doors "
                                                                    "and drawers)"),
    }

    def _n_doors(self, p) -> int:
        if p["door_type"] == "sliding":
            return 2
        W = p["width"]
        return int(min(max(int(p["n_doors"]), math.ceil(W / 0.65)), math.floor(W / 0.3)))

    def _sliding(self, p) -> bool:
        return p["door_type"] == "sliding"

    def _divider(self, p) -> float | None:
        """The y of the full-height divider: between doors 2 and 3 of a 3-4 door wardrobe, at
        the middle of a wide sliding one; None without one."""
        W, n = p["width"], self._n_doors(p)
        if self._sliding(p):
            return 0.0 if W > 1.3 else None
        if n >= 3:
            return -W / 2 + 2 * W / n
        return None

    def layout(self, p: dict[str, Any]) -> Case:
        """Drawer rows at the bottom and the door zone above, split by any divider."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        nr = int(p["drawer_rows"])
        nd = 3 if W > 1.3 else 2
        free = z_top - p["base_height"] - t - nr * t
        rows = [Row("drawer", 0.22, nd) for _ in range(nr)]
        rows.append(Row("door", free - 0.22 * nr, self._n_doors(p)))
        yd = self._divider(p)
        return case_layout(W, D, t, 0.008, p["base_height"], z_top, rows,
                            overlay=not self._sliding(p), door_dividers=() if yd is None else (yd,))

    # ---- sliding doors
    def _track_depth(self) -> float:
        return 2 * MOVING_GAP + 2 * FRONT_T + SLIDE_SPACING + 0.004

    def _slide_proud(self) -> float:
        """How far the outer sliding door's pull stands in front of the carcass."""
        return MOVING_GAP + 2 * FRONT_T + SLIDE_SPACING + 0.01

    def _door_zone(self, p, case) -> tuple[float, float]:
        """z range of the sliding doors: above the bottom track, below the top board."""
        _, z0, z1 = case.rows[-1]
        return z0 + 0.02 + MOVING_GAP, case.z_top - MOVING_GAP

    def _sliding_doors(self, p, case) -> list[tuple[list[Part], DoorJoint]]:
        W, fx = p["width"], case.front_x
        za, zb = self._door_zone(p, case)
        out = []
        for k, (ya, yb) in enumerate(((-W / 2 + REVEAL, SLIDE_OVERLAP / 2),
                                      (-SLIDE_OVERLAP / 2, W / 2 - REVEAL))):
            x0 = fx + MOVING_GAP + k * (FRONT_T + SLIDE_SPACING)
            x1 = x0 + FRONT_T
            link = f"door_{k}"
            parts = [Part(box_between((x0, ya, za), (x1, yb, zb)), "front", link)]
            # a flush pull strip at the outer edge (the inner door's fits between the tracks)
            yp = ya + 0.03 if k == 0 else yb - 0.03
            proud = 0.004 if k == 0 else 0.01
            parts.append(Part(box_between((x1 - 0.001, yp - 0.01, za + 0.3 * (zb - za)),
                                          (x1 + proud, yp + 0.01, za + 0.7 * (zb - za))),
                              "metal", link))
            parts += front_decor(x1, ya, yb, za, zb, p["door_style"], link)
            axis = np.array([0.0, 1.0 if k == 0 else -1.0, 0.0])
            out.append((parts, DoorJoint("prismatic", axis, np.array([x1, (ya + yb) / 2, za]), link)))
        return out

    def _tracks(self, p, case) -> list[Part]:
        """Top and bottom tracks in front of the carcass, full width."""
        W, fx = p["width"], case.front_x
        td = self._track_depth()
        _, z0, _ = case.rows[-1]
        return [Part(box_between((fx - OVERLAP, -W / 2, z0 - case.t), (fx + td, W / 2, z0 + 0.02)),
                     "metal")]

    def fronts(self, p: dict[str, Any]) -> list[tuple[list[Part], DoorJoint]]:
        """Hinged doors and drawers, or the drawers and two sliding doors."""
        case = self.layout(p)
        if not self._sliding(p):
            return super().fronts(p)
        drawers = case_fronts(case, p["handle"], "flat", self.drawer_depth(case), drawers_only=True)
        return drawers + self._sliding_doors(p, case)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """Sliding doors slide, drawers pull out, hinged doors swing."""
        case = self.layout(p)
        out = []
        for _, m in self.fronts(p):
            if m.kind == "prismatic" and m.link.startswith("door"):
                out.append(make_joint(f"{m.link}_joint", m, 0.0, 0.9 * (p["width"] / 2 - SLIDE_OVERLAP)))
            elif m.kind == "prismatic":
                out.append(make_joint(f"{m.link}_joint", m, 0.0, 0.8 * self.drawer_depth(case)))
            else:
                out.append(make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN))
        return out

    # ---- interior
    def _sections(self, p, case) -> list[tuple[float, float, str]]:
        """(y0, y1, "hanging" | "shelves") of the door zone's sections."""
        yi0, yi1 = case.inner()
        yd = self._divider(p)
        if yd is None:
            return [(yi0, yi1, "hanging")]
        t = case.t
        right = "hanging" if self._sliding(p) else "shelves"
        return [(yi0, yd - t / 2, "hanging"), (yd + t / 2, yi1, right)]

    def _hat_shelf(self, p, case) -> float:
        return case.z_top - p["shelf_drop"]

    def _rail_z(self, p, case) -> float:
        """The height of the hanging rails' axis: 6 cm under the hat shelf."""
        return self._hat_shelf(p, case) - case.t - 0.06

    def _column_shelves(self, p, case) -> list[float]:
        _, z0, z1 = case.rows[-1]
        n = max(1, int(round((z1 - z0) / 0.38)) - 1)
        return shelf_heights(z0, z1, n, case.t, 0.25)

    def _interior_parts(self, p, case) -> list[Part]:
        out = []
        zs = self._hat_shelf(p, case)
        for y0, y1, kind in self._sections(p, case):
            if kind == "hanging":
                out.append(shelf_board(case, y0, y1, zs))
                zr = self._rail_z(p, case)
                out.append(Part(rod((0.0, y0 - 0.001, zr), (0.0, y1 + 0.001, zr), RAIL_RADIUS, 16),
                                "metal"))
            else:
                out += [shelf_board(case, y0, y1, z) for z in self._column_shelves(p, case)]
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Case, top, base, and in detail rails, shelves, tracks and fronts."""
        case = self.layout(p)
        W, D = p["width"], p["depth"]
        sliding = self._sliding(p)
        proud = front_proud(p["handle"]) if case.rows[0][0].kind == "drawer" or not sliding else 0.0
        if sliding:
            proud = max(proud, self._slide_proud())
        out = case_body(case, detail, D / 2 + proud)
        over = self._track_depth() if sliding else 0.0
        out.append(Part(box_between((-D / 2, -W / 2, case.z_top - OVERLAP),
                                    (D / 2 + over, W / 2, p["height"])), "wood"))
        out += case_base(D, W, p["base_height"], p["base_style"], detail)
        if detail:
            out += self._interior_parts(p, case)
            if sliding:
                out += self._tracks(p, case)
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top`, footprint, back, every interior floor and shelf, and each hanging rail's
        top (`rail_0`...)."""
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        over = self._track_depth() if self._sliding(p) else 0.0
        out = [support_rect("top", (over / 2, 0, H), (D + over) / 2 - 0.02, W / 2 - 0.02),
               base_bottom(D, W, p["base_style"]),
               back_surface(W, p["base_height"], H, D)]
        _, z0, _ = case.rows[-1]
        zs = self._hat_shelf(p, case)
        k = 0
        for y0, y1, kind in self._sections(p, case):
            for z in [z0] + ([zs] if kind == "hanging" else self._column_shelves(p, case)):
                out.append(interior_surface(f"interior_{k}", case, y0, y1, z))
                k += 1
        hanging = [(y0, y1) for y0, y1, kind in self._sections(p, case) if kind == "hanging"]
        out += [rail_surface(f"rail_{i}", 0.0, y0, y1, self._rail_z(p, case))
                for i, (y0, y1) in enumerate(hanging)]
        return out
