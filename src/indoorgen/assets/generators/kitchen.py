"""Kitchen cabinetry and the sink: base cabinets under a countertop, runs of them, islands, wall
cabinets, and a sink basin set in a countertop section with its faucet. Fronts face +X.

Base units stand on a recessed plinth (the toe kick); their fronts are overlay doors and drawers
(each its own link with a joint), the countertop overhangs the fronts and is the `top` support
surface; shelves behind doors are `Subpart.Interior` surfaces.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import shapely.geometry as sg

from indoorgen.assets.base import Param, Surface, register
from indoorgen.assets.generators._kitchen_common import (
    DOOR_OPEN,
    OVERLAP,
    Unit,
    rounded_rect_prism,
    unit_parts,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.shapes.primitives import Part, bevel_box, box, box_between, cylinder, lathe, rod, torus
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon, support_rect
from indoorgen.model.tags import Semantics as S

HANDLES = ("bar", "knob", "none")
FRONT_STYLES = ("flat", "shaker")
#: front layouts of the units of a run, per pattern (cycled along the run)
PATTERNS = {
    "mixed": ("drawers", "doors", "drawer_doors"),
    "doors": ("doors",),
    "drawer_doors": ("drawer_doors",),
    "drawers_ends": ("drawers", "doors"),
}
#: relative width of the units of a run, scaled by `width_variation`
WIDTH_WAVE = (0.0, 1.0, -0.6, 0.5, -1.0)


def _counter_params(height=(0.86, 0.93)) -> dict[str, Param]:
    return {
        "depth": Param(0.55, 0.62, doc="carcass X extent, front to wall (m)"),
        "height": Param(*height, doc="height of the countertop's upper face (m)"),
        "countertop_thickness": Param(0.02, 0.045, doc="countertop slab thickness (m)"),
        "overhang": Param(0.03, 0.06, doc="how far the countertop reaches past the carcass front (m)"),
        "toe_kick_height": Param(0.08, 0.15, doc="plinth height under the carcass (m)"),
        "handle": Param(kind="choice", choices=HANDLES, doc="front hardware (none = push-to-open)"),
        "front_style": Param(kind="choice", choices=FRONT_STYLES, doc="flat slab or shaker fronts"),
    }


def _countertop(p: dict[str, Any], x0: float, x1: float, y0: float, y1: float,
                detail: bool) -> Part:
    """The countertop slab over x0..x1, y0..y1, its upper face at `height`; rounded edges."""
    H, ct = p["height"], p["countertop_thickness"]
    ext, c = (x1 - x0, y1 - y0, ct), ((x0 + x1) / 2, (y0 + y1) / 2, H - ct / 2)
    r = p.get("edge_radius", 0.0)
    solid = bevel_box(ext, c, r, 2) if detail and r > 1e-4 else box(ext, c)
    return Part(solid, "countertop")


def _run_parts(p: dict[str, Any], units: list[Unit], detail: bool, prefix_units: bool,
               open_angle: float = DOOR_OPEN) -> tuple[list[Part], list, list[Surface]]:
    """Carcasses and fronts of `units` (one run, fronts at x = depth/2) on a plinth: parts,
    joints and interior surfaces. The placeholder's units are one block."""
    D, H, ct = p["depth"], p["height"], p["countertop_thickness"]
    zk, zc = p["toe_kick_height"], H - ct
    out, joints, surfs = [], [], []
    for i, u in enumerate(units):
        prefix = f"u{i}_" if prefix_units else ""
        parts, js, ss = unit_parts(u, D, zk, zc + 0.001, 0.018, detail, prefix, p["handle"],
                                   p["front_style"], top=False, open_angle=open_angle)
        out += parts
        joints += js
        surfs += ss
    y0, y1 = units[0].y0, units[-1].y1
    if not detail:  # every unit's block has the same depth and height: merge them
        blocks = [q.solid.bounding_box() for q in out]
        lo = [min(b[k] for b in blocks) for k in range(3)]
        hi = [max(b[k + 3] for b in blocks) for k in range(3)]
        out = [Part(box_between(lo, hi), "wood")]
    out.append(Part(box_between((-D / 2, y0 + 0.01, 0.0),
                                (D / 2 - p["toe_kick_depth"], y1 - 0.01, zk + OVERLAP)),
                    "wood"))
    return out, joints, surfs


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
        **_counter_params(),
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
        D, W = p["depth"], p["width"]
        out, _, _ = _run_parts(p, self._units(p), detail, False)
        out.append(_countertop(p, -D / 2, D / 2 + p["overhang"], -W / 2, W / 2, detail))
        return out

    def joints(self, p):
        return _run_parts(p, self._units(p), False, False)[1]

    def extra_surfaces(self, p):
        D, W, H, kd = p["depth"], p["width"], p["height"], p["toe_kick_depth"]
        x1 = D / 2 + p["overhang"]
        return [support_rect("top", ((x1 - D / 2) / 2, 0, H), (x1 + D / 2) / 2 - 0.02, W / 2 - 0.02),
                bottom_rect((-kd / 2, 0, 0), (D - kd) / 2, W / 2 - 0.01),
                *_run_parts(p, self._units(p), False, False)[2]]


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
    for i, (w, lay) in enumerate(zip(ws, layouts)):
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
        **_counter_params(),
        "toe_kick_depth": Param(0.04, 0.08, doc="how far the plinth is set back (m)"),
        "backsplash_height": Param(0.0, 0.12,
                                   doc="upstand along the back of the countertop (m; < 2 cm: none)"),
    }

    def parts(self, p, detail):
        units = run_units(p)
        D, H = p["depth"], p["height"]
        y0, y1 = units[0].y0, units[-1].y1
        out, _, _ = _run_parts(p, units, detail, True)
        out.append(_countertop(p, -D / 2, D / 2 + p["overhang"], y0, y1, detail))
        bh = p["backsplash_height"]
        if bh >= 0.02:
            out.append(Part(box_between((-D / 2, y0, H - OVERLAP), (-D / 2 + 0.015, y1, H + bh)),
                            "countertop"))
        return out

    def joints(self, p):
        return _run_parts(p, run_units(p), False, True)[1]

    def extra_surfaces(self, p):
        units = run_units(p)
        D, H, kd = p["depth"], p["height"], p["toe_kick_depth"]
        y0, y1 = units[0].y0, units[-1].y1
        xb = -D / 2 + (0.015 if p["backsplash_height"] >= 0.02 else 0.0)
        x1 = D / 2 + p["overhang"]
        return [support_rect("top", ((xb + x1) / 2, 0, H), (x1 - xb) / 2 - 0.02, (y1 - y0) / 2 - 0.02),
                bottom_rect((-kd / 2, 0, 0), (D - kd) / 2, (y1 - y0) / 2 - 0.01),
                *_run_parts(p, units, False, True)[2]]


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
        **_counter_params((0.88, 0.94)),
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
        p = dict(p, toe_kick_depth=0.06)
        units, x0, x1, y0, y1 = self._geometry(p)
        D, H, ct = p["depth"], p["height"], p["countertop_thickness"]
        zc = H - ct
        out, _, _ = _run_parts(p, units, detail, True)
        out.append(_countertop(p, x0, x1, y0, y1, detail))
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
        angle = math.radians(90) if p["end_style"] == "waterfall" else DOOR_OPEN
        return _run_parts(dict(p, toe_kick_depth=0.06), run_units(p), False, True, angle)[1]

    def extra_surfaces(self, p):
        units, x0, x1, y0, y1 = self._geometry(p)
        H = p["height"]
        return [support_rect("top", ((x0 + x1) / 2, (y0 + y1) / 2, H), (x1 - x0) / 2 - 0.02,
                             (y1 - y0) / 2 - 0.02),
                *_run_parts(dict(p, toe_kick_depth=0.06), units, False, True)[2]]


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
        return self._build(p, detail)[0]

    def joints(self, p):
        return self._build(p, False)[1]

    def extra_surfaces(self, p):
        D, W = p["depth"], p["width"]
        return [bottom_rect((0, 0, 0), D / 2, W / 2), *self._build(p, False)[2]]


# --------------------------------------------------------------------------------- the sink
@register
class KitchenSink(PartsFactory):
    """A kitchen sink: a countertop section with one or two basins (undermounted below the
    cut-out, or dropped in with a rim on the countertop) hollowed out of a rounded steel
    block, drains, and a faucet behind the basin (gooseneck or angular spout; single lever or
    two cross handles). The countertop around the basin is the `top` support surface."""

    name = "kitchen_sink"
    tags = frozenset({S.Object, S.KitchenSink, S.Countertop})
    size_class = "medium"
    slots = ["countertop", "metal"]
    params = {
        "width": Param(0.6, 1.2, doc="countertop section Y extent (m)"),
        "depth": Param(0.55, 0.65, doc="countertop section X extent (m)"),
        "countertop_thickness": Param(0.02, 0.04, doc="countertop slab thickness (m)"),
        "bowls": Param(kind="choice", choices=("single", "double"), doc="one or two basins"),
        "bowl_depth": Param(0.16, 0.24, doc="basin depth below the countertop (m)"),
        "bowl_width_frac": Param(0.6, 0.85, doc="basin Y extent / section width"),
        "corner_radius": Param(0.01, 0.05, doc="rounding of the basin's corners (m)"),
        "mount": Param(kind="choice", choices=("undermount", "drop_in"),
                       doc="basin under the cut-out or dropped in with a rim"),
        "faucet": Param(kind="choice", choices=("gooseneck", "angular"), doc="spout shape"),
        "faucet_handles": Param(kind="choice", choices=("lever", "cross"),
                                doc="one side lever or two cross handles"),
        "faucet_height": Param(0.22, 0.4, doc="faucet height above the countertop (m)"),
    }

    WALL = 0.008
    RIM = 0.03

    def _sink_layout(self, p) -> dict[str, Any]:
        W, D, ct = p["width"], p["depth"], p["countertop_thickness"]
        zb = p["bowl_depth"]
        zt = zb + ct
        bw = W * p["bowl_width_frac"]
        bx0, bx1 = -D / 2 + 0.14, D / 2 - 0.06
        if p["bowls"] == "double":
            gap = 0.04
            wa = (bw - gap) * 0.55
            cav = [(-bw / 2, -bw / 2 + wa), (-bw / 2 + wa + gap, bw / 2)]
        else:
            cav = [(-bw / 2, bw / 2)]
        xf = (-D / 2 + bx0) / 2
        return dict(zb=zb, zt=zt, bw=bw, bx0=bx0, bx1=bx1, cav=cav, xf=xf, yf=0.0)

    def _faucet(self, p, L, solids: bool = True) -> tuple[list[m3d.Manifold], tuple[tuple, tuple]]:
        """The faucet solids (none unless `solids`: placeholders only need the box) and their
        bounding box ((x0, y0, z0), (x1, y1, z1))."""
        xf, yf, zt = L["xf"], L["yf"], L["zt"] - 0.001
        fh = p["faucet_height"]
        r = 0.014
        reach = min(max((L["bx0"] + L["bx1"]) / 2 - xf, 0.12), 0.3) * 0.75
        out: list[m3d.Manifold] = []

        def add(make) -> None:
            if solids:
                out.append(make())

        add(lambda: cylinder(0.03, 0.014, (xf, yf, zt), 24))
        lo, hi = [xf - 0.03, yf - 0.03, zt], [xf + 0.03, yf + 0.03, zt + fh]
        if p["faucet"] == "gooseneck":
            R = reach / 2
            zc = zt + fh - R - r
            add(lambda: rod((xf, yf, zt), (xf, yf, zc + 0.001), r, 16))
            add(lambda: torus(R, r, sections=24, tube_sections=12).rotate((90.0, 0.0, 0.0))
                .trim_by_plane((0.0, 0.0, 1.0), 0.0).translate((xf + R, yf, zc)))
            xs = xf + 2 * R
            add(lambda: rod((xs, yf, zc - 0.05), (xs, yf, zc + 0.001), r, 16))
            add(lambda: cylinder(r * 1.15, 0.02, (xs, yf, zc - 0.06), 16))
            lo[2], hi[0] = zt, xs + r * 1.15
        else:
            zc = zt + fh - r
            add(lambda: rod((xf, yf, zt), (xf, yf, zc + r), r, 16))
            xs = xf + reach
            add(lambda: rod((xf, yf, zc), (xs + r, yf, zc), r, 16))
            add(lambda: rod((xs, yf, zc - 0.06), (xs, yf, zc), r, 16))
            add(lambda: cylinder(r * 1.15, 0.015, (xs, yf, zc - 0.07), 16))
            hi[0] = xs + r * 1.15
        if p["faucet_handles"] == "lever":
            zl = zt + min(0.08, 0.3 * fh)
            add(lambda: rod((xf, yf, zl), (xf, yf + 0.045, zl), 0.013, 16))
            add(lambda: rod((xf, yf + 0.04, zl), (xf - 0.035, yf + 0.04, zl + 0.06), 0.005, 8))
            lo[0] = min(lo[0], xf - 0.04)
            hi[1] = max(hi[1], yf + 0.053)
        else:
            for s in (-1, 1):
                yh = yf + s * 0.09
                add(lambda: cylinder(0.02, 0.045, (xf, yh, zt), 16))
                add(lambda: rod((xf - 0.025, yh, zt + 0.04), (xf + 0.025, yh, zt + 0.04), 0.005, 8))
                add(lambda: rod((xf, yh - 0.025, zt + 0.04), (xf, yh + 0.025, zt + 0.04), 0.005, 8))
            lo[1], hi[1] = yf - 0.115, yf + 0.115
        return out, (tuple(lo), tuple(hi))

    def parts(self, p, detail):
        W, D, ct = p["width"], p["depth"], p["countertop_thickness"]
        L = self._sink_layout(p)
        zb, zt, bx0, bx1 = L["zb"], L["zt"], L["bx0"], L["bx1"]
        w, rc = self.WALL, p["corner_radius"]
        drop = p["mount"] == "drop_in"
        # outer block of the basin, its rim (drop-in) and the countertop's cut-out
        oy0, oy1 = L["cav"][0][0] - w, L["cav"][-1][1] + w
        ox0, ox1 = bx0 - w, bx1 + w
        faucet, (flo, fhi) = self._faucet(p, L, detail)
        if not detail:
            out = [Part(box_between((-D / 2, -W / 2, zb), (D / 2, W / 2, zt)), "countertop"),
                   Part(box_between((ox0 - (0 if drop else self.RIM), oy0 - (0 if drop else self.RIM), 0.0),
                                    (ox1 + (0 if drop else self.RIM), oy1 + (0 if drop else self.RIM),
                                     zb + 0.001)),
                        "metal"),
                   Part(box_between(flo, fhi), "metal")]
            if drop:
                out.append(Part(box_between((ox0 - self.RIM, oy0 - self.RIM, zt - 0.001),
                                            (ox1 + self.RIM, oy1 + self.RIM, zt + 0.006)), "metal"))
            return out
        cavities = [rounded_rect_prism(bx0, bx1, ya, yb, w, zt + 0.02, rc) for ya, yb in L["cav"]]
        if drop:
            block = rounded_rect_prism(ox0, ox1, oy0, oy1, 0.0, zt - 0.001, rc + w)
            rim = rounded_rect_prism(ox0 - self.RIM, ox1 + self.RIM, oy0 - self.RIM, oy1 + self.RIM,
                                     zt - 0.001, zt + 0.006, rc + w + self.RIM)
            hole = rounded_rect_prism(ox0 + 0.001, ox1 - 0.001, oy0 + 0.001, oy1 - 0.001, zb - 0.01,
                                      zt + 0.01, rc + w)
            basin = m3d.Manifold.batch_boolean([block, rim], m3d.OpType.Add)
        else:
            R = self.RIM
            basin = rounded_rect_prism(ox0 - R, ox1 + R, oy0 - R, oy1 + R, 0.0, zb + 0.001, rc + w + R)
            hole = m3d.Manifold.batch_boolean(
                [rounded_rect_prism(bx0, bx1, ya, yb, zb - 0.01, zt + 0.01, rc) for ya, yb in L["cav"]],
                m3d.OpType.Add)
        basin = m3d.Manifold.batch_boolean([basin] + cavities, m3d.OpType.Subtract)
        slab = box_between((-D / 2, -W / 2, zb), (D / 2, W / 2, zt)) - hole
        out = [Part(slab, "countertop"), Part(basin, "metal")]
        for ya, yb in L["cav"]:  # drain: a flange ring with a recessed strainer
            c = ((bx0 + bx1) / 2, (ya + yb) / 2)
            drain = lathe([(0.0, w - 0.001), (0.045, w - 0.001), (0.045, w + 0.002), (0.035, w + 0.002),
                           (0.03, w - 0.0005), (0.0, w - 0.0005)], 32).translate((c[0], c[1], 0.0))
            out.append(Part(drain, "metal"))
        out += [Part(f, "metal") for f in faucet]
        return out

    def extra_surfaces(self, p):
        W, D = p["width"], p["depth"]
        L = self._sink_layout(p)
        w = self.WALL
        ox0, ox1 = L["bx0"] - w, L["bx1"] + w
        oy0, oy1 = L["cav"][0][0] - w, L["cav"][-1][1] + w
        R = self.RIM + 0.005 if p["mount"] == "drop_in" else 0.005
        top = sg.box(-D / 2 + 0.01, -W / 2 + 0.01, D / 2 - 0.01, W / 2 - 0.01)
        top = top.difference(sg.box(ox0 - R, oy0 - R, ox1 + R, oy1 + R))
        _, (flo, fhi) = self._faucet(p, L, False)
        top = top.difference(sg.box(flo[0] - 0.005, flo[1] - 0.005, fhi[0] + 0.005, fhi[1] + 0.005))
        return [support_polygon("top", (0, 0, L["zt"]), top)]
