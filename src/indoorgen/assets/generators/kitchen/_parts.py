"""What the kitchen cabinets and the sink base share: cabinet units of a run - a carcass with
overlay doors, drawers and flaps (each its own link with a joint), their handles and shaker
frames - the interior surfaces behind the doors, and the units under a countertop (their shared
parameters, the plinth, the countertop slab). Fronts face +X.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.shapes.cabinet_parts import (
    HANDLE_PROUD,
    interior_rect,
    joint_for,
    open_shell,
    pull_bar,
    window_leaf,
)
from indoorgen.assets.shapes.frames import carcass, frame
from indoorgen.assets.shapes.moving_parts import (
    DOOR_OPEN,
    FRONT_T,
    MOVING_GAP,
    DoorJoint,
    Front,
    hinge_motion,
    knob,
    slide_motion,
)
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between

#: how far the raised frame of a shaker front stands proud of the leaf (m)
SHAKER_DEPTH = 0.006
#: gap between neighbouring fronts (m)
REVEAL = 0.003
#: front hardware choices of kitchen units
HANDLES = ("bar", "knob", "none")
#: front styles of kitchen base units
FRONT_STYLES = ("flat", "shaker")


def shaker_frame(x_face: float, y0: float, y1: float, z0: float, z1: float,
                 border: float = 0.06, depth: float = SHAKER_DEPTH) -> m3d.Manifold:
    """The raised rails and stiles of a shaker-style front on a +X face at `x_face` (sinks
    1 mm into it)."""
    w, h = y1 - y0, z1 - z0
    bd = min(border, 0.3 * min(w, h))
    return frame(w, h, bd, depth + 0.001, (x_face + depth / 2 - 0.0005, (y0 + y1) / 2, (z0 + z1) / 2))


def drawer_basket(front_x: float, opening: tuple[float, float, float, float], depth: float,
                  board: float = 0.006, wall_height: float | None = None) -> m3d.Manifold:
    """The open-topped box of a drawer sliding in an opening (y0, y1, z0, z1) of a +X face at
    `front_x`: `depth` deep, clear of the opening by 2*MOVING_GAP on the sides and bottom, and
    reaching 1 mm into the back of a front panel standing MOVING_GAP proud of the face."""
    y0, y1, z0, z1 = opening
    g = 2 * MOVING_GAP
    bz1 = z1 - 0.02 if wall_height is None else min(z1 - 0.01, z0 + g + wall_height)
    lo = (front_x - depth, y0 + g, z0 + g)
    hi = (front_x + MOVING_GAP + 0.001, y1 - g, bz1)
    return open_shell(lo, hi, board, open_top=True)

def grip_handle(x_face: float, y: float, z: float, length: float, vertical: bool,
                handle: str) -> m3d.Manifold | None:
    """A bar ("bar"), a knob ("knob") or nothing ("none") centred on (y, z) of a +X face."""
    if handle == "bar":
        half = length / 2
        a, b = ((y, z - half), (y, z + half)) if vertical else ((y - half, z), (y + half, z))
        return pull_bar(x_face, a, b, HANDLE_PROUD, 0.006, 8)
    if handle == "knob":
        return knob((x_face, y, z), 0.014, HANDLE_PROUD)
    return None


def cabinet_front(fx: float, cell: Front, opening: tuple[float, float, float, float],
                  depth: float, link: str, handle: str, style: str, high: bool = False,
                  slot: str = "front", build: bool = True) -> tuple[list[Part], DoorJoint]:
    """One overlay front of a carcass whose front face is at `fx`: a door leaf hinged on the
    cell's side ("left", "right", "flap_up", "flap_down") or a drawer (front panel plus an
    open box inside `opening` = the carcass's inner (y0, y1, z0, z1), `depth` deep). `style`
    "shaker" adds a raised frame, "glass" a window. `high` (wall cabinets) puts door handles
    near the bottom edge instead of the top. With build=False only the motion is computed."""
    y0, y1, z0, z1 = cell.y0 + REVEAL / 2, cell.y1 - REVEAL / 2, cell.z0 + REVEAL / 2, cell.z1 - REVEAL / 2
    x0, x1 = fx + MOVING_GAP, fx + MOVING_GAP + FRONT_T
    w, h = y1 - y0, z1 - z0
    drawer = cell.kind == "drawer"
    if drawer:
        zg = (z0 + z1) / 2 if h < 0.2 else z1 - 0.06
        grip, vertical, length = ((y0 + y1) / 2, zg), False, min(0.2, 0.5 * w)
        motion = slide_motion(link, (x1, grip[0], grip[1]))
    else:
        hinge = {"left": "left", "right": "right", "flap_down": "bottom", "flap_up": "top"}[cell.kind]
        if hinge in ("left", "right"):
            yh = y1 - min(0.04, 0.2 * w) if hinge == "left" else y0 + min(0.04, 0.2 * w)
            zh = z0 + min(0.08, 0.2 * h) if high else z1 - min(0.08, 0.2 * h)
            if h < 0.3:
                zh = (z0 + z1) / 2
            grip, vertical, length = (yh, zh), True, min(0.16, 0.4 * h)
        else:
            zh = z0 + min(0.04, 0.2 * h) if hinge == "top" else z1 - min(0.04, 0.2 * h)
            grip, vertical, length = ((y0 + y1) / 2, zh), False, min(0.3, 0.5 * w)
        # the axis runs along the outermost front edge (a shaker frame stands proud of the leaf)
        x_axis = x1 + (SHAKER_DEPTH if style == "shaker" else 0.0)
        motion = hinge_motion(hinge, x_axis, y0, y1, z0, z1, link)
    if not build:
        return [], motion
    if style == "glass" and not drawer:
        bd = min(0.06, 0.25 * min(w, h))
        parts = window_leaf(x0, x1, y0, y1, z0, z1, (bd, bd, bd, bd), link, slot)
    else:
        parts = [Part(box_between((x0, y0, z0), (x1, y1, z1)), slot, link)]
    if style == "shaker":
        parts.append(Part(shaker_frame(x1, y0, y1, z0, z1, 0.035 if drawer else 0.06), slot, link))
    if drawer:
        oy0, oy1, oz0, oz1 = opening
        op = (max(oy0, y0), min(oy1, y1), max(oz0, z0), min(oz1, z1))
        parts.append(Part(drawer_basket(fx, op, depth, 0.012), "wood", link))
    g = grip_handle(x1, grip[0], grip[1], length, vertical, handle)
    if g is not None:
        parts.append(Part(g, "metal", link))
    return parts, motion


# ------------------------------------------------------------------------- cabinet units
@dataclass(frozen=True)
class Unit:
    """One cabinet unit of a run: its span y0..y1 and front layout ("doors", "drawers",
    "drawer_doors", "flap_up"), `n_drawers` for a drawer stack."""

    y0: float
    y1: float
    layout: str
    n_drawers: int = 3
    hinge: str = "left"


def unit_cells(u: Unit, z0: float, z1: float) -> list[Front]:
    """The front cells of a unit whose carcass spans z0..z1 (overlay: they cover the carcass
    edges): doors (one below 0.5 m of width, hinged on `u.hinge`, else a pair), a drawer stack
    (graduated: lower drawers deeper), a drawer above doors, or one lift-up flap."""
    y0, y1 = u.y0, u.y1

    def doors(za: float, zb: float) -> list[Front]:
        if y1 - y0 < 0.5:
            return [Front(y0, y1, za, zb, u.hinge)]
        ym = (y0 + y1) / 2
        return [Front(y0, ym, za, zb, "left"), Front(ym, y1, za, zb, "right")]

    if u.layout == "doors":
        return doors(z0, z1)
    if u.layout == "flap_up":
        return [Front(y0, y1, z0, z1, "flap_up")]
    if u.layout == "drawers":
        n = max(2, u.n_drawers)
        wts = 1.0 + 0.3 * np.arange(n - 1, -1, -1)  # bottom drawer first, deepest
        edges = z0 + np.concatenate([[0.0], np.cumsum(wts)]) / wts.sum() * (z1 - z0)
        return [Front(y0, y1, float(edges[i]), float(edges[i + 1]), "drawer") for i in range(n)]
    if u.layout == "drawer_doors":
        zd = z1 - min(0.16, 0.25 * (z1 - z0))
        return doors(z0, zd) + [Front(y0, y1, zd, z1, "drawer")]
    raise ValueError(f"unknown unit layout {u.layout!r}")


def unit_parts(u: Unit, depth: float, z0: float, z1: float, t: float, detail: bool, prefix: str,
               handle: str, style: str, top: bool = False, high: bool = False,
               n_shelves: int = 1, open_angle: float = DOOR_OPEN
               ) -> tuple[list[Part], list[Joint], list[Surface]]:
    """One cabinet unit: carcass (x in [-depth/2, depth/2], y in u.y0..u.y1, z0..z1, boards
    `t`; a top board when `top`) with its overlay fronts, joints and `Subpart.Interior`
    surfaces (the bottom board and `n_shelves` evenly spaced fixed shelves behind doors).
    Side-hinged doors open to `open_angle`. With detail=False the carcass, fronts and handles
    are one block (the placeholder)."""
    w, yc = u.y1 - u.y0, (u.y0 + u.y1) / 2
    cells = unit_cells(u, z0, z1)
    door_cells = [c for c in cells if c.kind != "drawer"]
    z_in1 = z1 - (t if top else 0.0)
    shelves: list[float] = []
    if door_cells:
        zd = max(c.z1 for c in door_cells) - (t if top else 0.0)
        k = n_shelves if zd - z0 > 0.4 else 0
        shelves = [z0 + t + (zd - z0 - t) * (i + 1) / (k + 1) for i in range(k)]
    surfaces: list[Surface] = []
    if door_cells:
        ix0, ix1 = -depth / 2 + t, depth / 2 - 0.01
        for i, zs in enumerate([z0 + t] + shelves):
            surfaces.append(interior_rect(f"{prefix}interior_{i}", ix0, ix1, u.y0 + t, u.y1 - t, zs))
    fx = depth / 2
    opening = (u.y0 + t, u.y1 - t, z0 + t, z_in1)
    joints, out = [], []
    for i, c in enumerate(cells):
        link = f"{prefix}{'drawer' if c.kind == 'drawer' else 'door'}_{i}"
        parts, m = cabinet_front(fx, c, opening, depth - t - 0.02, link, handle, style, high, build=detail)
        out += parts
        joints.append(joint_for(m, slide=0.75 * (depth - t - 0.02), open_angle=open_angle))
    if not detail:  # the closed block: carcass, contents, fronts and handles
        block = box_between((-depth / 2, u.y0, z0), (fx + front_proud(handle, style), u.y1, z1))
        return [Part(block, "wood")], joints, surfaces
    out += [Part(s.solid.translate((0.0, yc, 0.0)), s.slot)
            for s in carcass(depth, w, z0, z1, t, back=t, shelves=shelves, top=top)]
    return out, joints, surfaces


def front_proud(handle: str, style: str = "flat") -> float:
    """How far a unit's fronts with their handles (or shaker frames) stand in front of the
    carcass (m)."""
    return MOVING_GAP + FRONT_T + max(HANDLE_PROUD if handle != "none" else 0.0,
                                      SHAKER_DEPTH if style == "shaker" else 0.0)


# ------------------------------------------------------------------- units under a countertop
def counter_params(height: tuple[float, float] = (0.86, 0.93)) -> dict[str, Param]:
    """The parameters every unit under a countertop shares (depth, countertop height and
    thickness, overhang, toe kick, front hardware and style), so units of a kitchen match."""
    return {
        "depth": Param(0.55, 0.62, doc="carcass X extent, front to wall (m)"),
        "height": Param(*height, doc="height of the countertop's upper face (m)"),
        "countertop_thickness": Param(0.02, 0.045, doc="countertop slab thickness (m)"),
        "overhang": Param(0.03, 0.06, doc="how far the countertop reaches past the carcass front (m)"),
        "toe_kick_height": Param(0.08, 0.15, doc="plinth height under the carcass (m)"),
        "handle": Param(kind="choice", choices=HANDLES, doc="front hardware (none = push-to-open)"),
        "front_style": Param(kind="choice", choices=FRONT_STYLES, doc="flat slab or shaker fronts"),
    }


def countertop(p: dict[str, Any], x0: float, x1: float, y0: float, y1: float,
               detail: bool) -> Part:
    """The countertop slab over x0..x1, y0..y1, its upper face at `height`; rounded edges."""
    H, ct = p["height"], p["countertop_thickness"]
    ext, c = (x1 - x0, y1 - y0, ct), ((x0 + x1) / 2, (y0 + y1) / 2, H - ct / 2)
    r = p.get("edge_radius", 0.0)
    solid = bevel_box(ext, c, r, 2) if detail and r > 1e-4 else box(ext, c)
    return Part(solid, "countertop")


def run_parts(p: dict[str, Any], units: list[Unit], detail: bool, prefix_units: bool,
              open_angle: float = DOOR_OPEN, n_shelves: int = 1
              ) -> tuple[list[Part], list[Joint], list[Surface]]:
    """Carcasses and fronts of `units` (one run, fronts at x = depth/2) on a plinth: parts,
    joints and interior surfaces (`n_shelves` fixed shelves behind doors). The placeholder's
    units are one block."""
    D, H, ct = p["depth"], p["height"], p["countertop_thickness"]
    zk, zc = p["toe_kick_height"], H - ct
    out, joints, surfs = [], [], []
    for i, u in enumerate(units):
        prefix = f"u{i}_" if prefix_units else ""
        parts, js, ss = unit_parts(u, D, zk, zc + 0.001, 0.018, detail, prefix, p["handle"],
                                   p["front_style"], top=False, n_shelves=n_shelves,
                                   open_angle=open_angle)
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
