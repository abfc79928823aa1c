"""Kitchen cabinetry: base cabinets under a countertop, runs of them, islands and wall cabinets.
Fronts face +X.

Base units stand on a recessed plinth (the toe kick); their fronts are overlay doors and drawers
(each its own link with a joint), the countertop overhangs the fronts and is the `top` support
surface; shelves behind doors are `Subpart.Interior` surfaces.
"""
from __future__ import annotations

import math
from typing import Any

from indoorgen.assets.generators.kitchen._parts import (
    HANDLES,
    Unit,
    counter_params,
    countertop,
    run_parts,
    unit_parts,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DOOR_OPEN
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_rect
from indoorgen.model.tags import Semantics as S

#: front layouts of the units of a run, per pattern (cycled along the run)
PATTERNS = {
    "mixed": ("drawers", "doors", "drawer_doors"),
    "doors": ("doors",),
    "drawer_doors": ("drawer_doors",),
    "drawers_ends": ("drawers", "doors"),
}
#: relative width of the units of a run, scaled by `width_variation`
WIDTH_WAVE = (0.0, 1.0, -0.6, 0.5, -1.0)


@register
class KitchenBaseCabinet(PartsFactory):
    """One base cabinet of a kitchen: a carcass on a recessed toe-kick plinth, overlay fronts
    (doors with a shelf behind, a drawer stack, or a drawer over doors; flat or shaker) and a
    countertop slab overhanging the front. `top` is the countertop (support surface); the
    carcass bottom and shelf are `interior_i` surfaces."""

    name = "kitchen_base_cabinet"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet, S.KitchenCabinet, S.Countertop})
    size_class = "large"
    slots = ["wood", "front", "metal", "countertop"]
    solid_bottom = True
    params = {
        "width": Param(0.3, 1.0, doc="Y extent (m)"),
        **counter_params(),
        "toe_kick_depth": Param(0.04, 0.08, doc="how far the plinth is set back (m)"),
        "layout": Param(kind="choice", choices=("doors", "drawers", "drawer_doors"),
                        doc="fronts: doors, a drawer stack, or a drawer over doors"),
        "n_drawers": Param(2, 4, kind="int", doc="drawers in a drawer stack"),
        "hinge_side": Param(kind="choice", choices=("left", "right"),
                            doc="hinge side of a single door (units under 0.5 m)"),
        "edge_radius": Param(0.0, 0.008, doc="rounding of the countertop's edges (m)"),
    }

    def _units(self, p) -> list[Unit]:
        W = p["width"]
        return [Unit(-W / 2, W / 2, p["layout"], int(p["n_drawers"]), p["hinge_side"])]

    def parts(self, p, detail):
        """The kitchen base cabinet's solids: detailed, or the blocks of its placeholder."""
        D, W = p["depth"], p["width"]
        out, _, _ = run_parts(p, self._units(p), detail, False)
        out.append(countertop(p, -D / 2, D / 2 + p["overhang"], -W / 2, W / 2, detail))
        return out

    def joints(self, p):
        """The base cabinet's joints, one per door and drawer."""
        return run_parts(p, self._units(p), False, False)[1]

    def extra_surfaces(self, p):
        """The base cabinet's surfaces besides its bounding box's: top (countertop), bottom, interior_<i>."""
        D, W, H, kd = p["depth"], p["width"], p["height"], p["toe_kick_depth"]
        x1 = D / 2 + p["overhang"]
        return [support_rect("top", ((x1 - D / 2) / 2, 0, H), (x1 + D / 2) / 2 - 0.02, W / 2 - 0.02),
                bottom_rect((-kd / 2, 0, 0), (D - kd) / 2, W / 2 - 0.01),
                *run_parts(p, self._units(p), False, False)[2]]


def run_units(p: dict[str, Any]) -> list[Unit]:
    """The units of a run: `n_units` of `unit_width` varied by `width_variation`, centred on
    y = 0, their layouts cycling through the `front_pattern`."""
    n = int(p["n_units"])
    wave = [WIDTH_WAVE[i % len(WIDTH_WAVE)] for i in range(n)]
    ws = [p["unit_width"] * (1.0 + p["width_variation"] * k) for k in wave]
    pattern = PATTERNS[p["front_pattern"]]
    if p["front_pattern"] == "drawers_ends":
        layouts = ["drawers" if i in (0, n - 1) else "doors" for i in range(n)]
    else:
        layouts = [pattern[i % len(pattern)] for i in range(n)]
    y = -sum(ws) / 2
    out = []
    for i, (w, lay) in enumerate(zip(ws, layouts, strict=True)):
        out.append(Unit(y, y + w, lay, 3 if i % 2 == 0 else 4, "left" if i % 2 == 0 else "right"))
        y += w
    return out


def _run_params() -> dict[str, Param]:
    return {
        "n_units": Param(2, 5, kind="int", doc="cabinet units side by side"),
        "unit_width": Param(0.4, 0.8, doc="nominal unit width (m)"),
        "width_variation": Param(0.0, 0.3, doc="how much unit widths vary along the run (fraction)"),
        "front_pattern": Param(kind="choice", choices=tuple(PATTERNS),
                               doc="how unit fronts alternate along the run"),
    }


@register
class CountertopRun(PartsFactory):
    """A kitchen run: 2-5 base-cabinet units of varying widths and fronts (drawer stacks, doors,
    drawer over doors) under one continuous countertop, optionally with a backsplash upstand.
    `top` is the countertop (support surface); shelves behind doors are `u<i>_interior_<j>`."""

    name = "countertop_run"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet, S.KitchenCabinet, S.Countertop})
    size_class = "large"
    slots = ["wood", "front", "metal", "countertop"]
    solid_bottom = True
    params = {
        **_run_params(),
        **counter_params(),
        "toe_kick_depth": Param(0.04, 0.08, doc="how far the plinth is set back (m)"),
        "backsplash_height": Param(0.0, 0.12,
                                   doc="upstand along the back of the countertop (m; < 2 cm: none)"),
    }

    def parts(self, p, detail):
        """The countertop run's solids: detailed, or the blocks of its placeholder."""
        units = run_units(p)
        D, H = p["depth"], p["height"]
        y0, y1 = units[0].y0, units[-1].y1
        out, _, _ = run_parts(p, units, detail, True)
        out.append(countertop(p, -D / 2, D / 2 + p["overhang"], y0, y1, detail))
        bh = p["backsplash_height"]
        if bh >= 0.02:
            out.append(Part(box_between((-D / 2, y0, H - OVERLAP), (-D / 2 + 0.015, y1, H + bh)),
                            "countertop"))
        return out

    def joints(self, p):
        """The run's joints, one per door and drawer of each unit."""
        return run_parts(p, run_units(p), False, True)[1]

    def extra_surfaces(self, p):
        """The run's surfaces besides its bounding box's: top (countertop), bottom, u<i>_interior_<j>."""
        units = run_units(p)
        D, H, kd = p["depth"], p["height"], p["toe_kick_depth"]
        y0, y1 = units[0].y0, units[-1].y1
        xb = -D / 2 + (0.015 if p["backsplash_height"] >= 0.02 else 0.0)
        x1 = D / 2 + p["overhang"]
        return [support_rect("top", ((xb + x1) / 2, 0, H), (x1 - xb) / 2 - 0.02, (y1 - y0) / 2 - 0.02),
                bottom_rect((-kd / 2, 0, 0), (D - kd) / 2, (y1 - y0) / 2 - 0.01),
                *run_parts(p, units, False, True)[2]]


@register
class KitchenIsland(PartsFactory):
    """A freestanding kitchen island: base-cabinet units facing +X, a finished back panel, and
    a countertop overhanging the back (-X) by `seating_overhang` for bar stools. Ends are plain,
    "waterfall" (the countertop material turning down to the floor) or "legs" (posts under the
    overhang's corners). `top` is the whole countertop (support surface)."""

    name = "kitchen_island"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet, S.KitchenCabinet, S.Countertop,
                      S.KitchenIsland})
    size_class = "large"
    slots = ["wood", "front", "metal", "countertop"]
    params = {
        **_run_params(),
        **counter_params((0.88, 0.94)),
        "seating_overhang": Param(0.2, 0.4, doc="countertop overhang on the seating side (m)"),
        "side_overhang": Param(0.0, 0.15, doc="countertop overhang past the end units (m; "
                                              "not with waterfall ends)"),
        "end_style": Param(kind="choice", choices=("plain", "waterfall", "legs"),
                           doc="plain ends, waterfall slabs, or posts under the overhang"),
    }

    def _geometry(self, p) -> tuple[list[Unit], float, float, float, float]:
        """(units, countertop x0, x1, y0, y1)."""
        units = run_units(p)
        D = p["depth"]
        x0 = -D / 2 - 0.018 - p["seating_overhang"]
        x1 = D / 2 + p["overhang"]
        side = p["countertop_thickness"] if p["end_style"] == "waterfall" else p["side_overhang"]
        return units, x0, x1, units[0].y0 - side, units[-1].y1 + side

    def parts(self, p, detail):
        """The kitchen island's solids: detailed, or the blocks of its placeholder."""
        p = dict(p, toe_kick_depth=0.06)
        units, x0, x1, y0, y1 = self._geometry(p)
        D, H, ct = p["depth"], p["height"], p["countertop_thickness"]
        zc = H - ct
        out, _, _ = run_parts(p, units, detail, True)
        out.append(countertop(p, x0, x1, y0, y1, detail))
        # the finished back panel on the seating side, floor to countertop
        out.append(Part(box_between((-D / 2 - 0.018, units[0].y0, 0.0),
                                    (-D / 2 + 0.001, units[-1].y1, zc + 0.001)),
                        "front"))
        if p["end_style"] == "waterfall":
            for ya, yb in ((y0, units[0].y0 + 0.001), (units[-1].y1 - 0.001, y1)):
                out.append(Part(box_between((x0, ya, 0.0), (x1, yb, zc + 0.001)), "countertop"))
        elif p["end_style"] == "legs":
            lt = 0.06
            for yl in (y0 + 0.03, y1 - 0.03 - lt):
                lx = x0 + 0.03
                out.append(Part(box_between((lx, yl, 0.0), (lx + lt, yl + lt, zc + 0.001)), "wood"))
                if lx + lt < -D / 2 - 0.018 + 0.001:  # a rail tying the post to the back panel
                    out.append(Part(box_between((lx + lt - 0.001, yl, zc - 0.06),
                                                (-D / 2 - 0.018 + 0.001, yl + lt, zc + 0.001)), "wood"))
        return out

    def joints(self, p):
        # doors of the end units must stop at 90 degrees against a waterfall slab
        """The island's joints, one per door and drawer (90 degrees at most beside waterfall ends)."""
        angle = math.radians(90) if p["end_style"] == "waterfall" else DOOR_OPEN
        return run_parts(dict(p, toe_kick_depth=0.06), run_units(p), False, True, angle)[1]

    def extra_surfaces(self, p):
        """The island's surfaces besides its bounding box's: top (countertop), u<i>_interior_<j>."""
        units, x0, x1, y0, y1 = self._geometry(p)
        H = p["height"]
        return [support_rect("top", ((x0 + x1) / 2, (y0 + y1) / 2, H), (x1 - x0) / 2 - 0.02,
                             (y1 - y0) / 2 - 0.02),
                *run_parts(dict(p, toe_kick_depth=0.06), units, False, True)[2]]


@register
class KitchenWallCabinet(PartsFactory):
    """A wall-mounted kitchen cabinet: carcass with a top, overlay doors (one or a pair, flat,
    shaker or glazed) or one lift-up flap, and 1-3 fixed shelves. Its back lies flat on the
    wall; `bottom` is its lower face; shelves are `interior_i` surfaces."""

    name = "kitchen_wall_cabinet"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet, S.KitchenCabinet, S.WallCabinet,
                      S.WallMounted})
    size_class = "medium"
    slots = ["wood", "front", "metal", "glass"]
    solid_bottom = True
    params = {
        "width": Param(0.3, 1.0, doc="Y extent (m)"),
        "depth": Param(0.28, 0.37, doc="carcass X extent (m)"),
        "height": Param(0.35, 0.95, doc="Z extent (m)"),
        "board_thickness": Param(0.016, 0.02, doc="carcass board thickness (m)"),
        "door_type": Param(kind="choice", choices=("hinged", "flap_up"),
                           doc="side-hinged doors or one lift-up flap"),
        "door_style": Param(kind="choice", choices=("flat", "shaker", "glass"),
                            doc="slab, shaker or glazed fronts"),
        "n_shelves": Param(1, 3, kind="int", doc="fixed shelves (fewer if the cabinet is short)"),
        "handle": Param(kind="choice", choices=HANDLES, doc="front hardware (none = push-to-open)"),
        "hinge_side": Param(kind="choice", choices=("left", "right"),
                            doc="hinge side of a single door (cabinets under 0.5 m)"),
    }

    def _unit(self, p) -> Unit:
        W = p["width"]
        return Unit(-W / 2, W / 2, "flap_up" if p["door_type"] == "flap_up" else "doors",
                    hinge=p["hinge_side"])

    def _build(self, p, detail):
        H, t = p["height"], p["board_thickness"]
        k = min(int(p["n_shelves"]), max(0, int((H - 2 * t) / 0.22) - 1))
        return unit_parts(self._unit(p), p["depth"], 0.0, H, t, detail, "", p["handle"],
                          p["door_style"], top=True, high=True, n_shelves=k)

    def parts(self, p, detail):
        """The kitchen wall cabinet's solids: detailed, or the blocks of its placeholder."""
        return self._build(p, detail)[0]

    def joints(self, p):
        """The wall cabinet's joints, one per door or flap."""
        return self._build(p, False)[1]

    def extra_surfaces(self, p):
        """The wall cabinet's surfaces besides its bounding box's: bottom, interior_<i> (shelves)."""
        D, W = p["depth"], p["width"]
        return [bottom_rect((0, 0, 0), D / 2, W / 2), *self._build(p, False)[2]]
