"""Shared pieces of the appliance and kitchen generators (appliances.py, appliances_cooking.py,
kitchen.py): open-fronted shells, hinged and sliding fronts with their motions, pull bars,
windowed door leaves, wire racks, cabinet units under a countertop, and the surfaces that go
with them. Design frame as everywhere: front +X, width along Y, Z up; fronts face +X.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import manifold3d as m3d
import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.assets.base import Joint, Surface
from indoorgen.assets.parts_factory import make_joint
from indoorgen.assets.shapes.frames import carcass, frame
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import (
    MOVING_GAP,
    DoorJoint,
    Front,
    hinge_motion,
    knob,
    slide_motion,
)
from indoorgen.assets.shapes.primitives import Part, box_between, rod
from indoorgen.model.tags import Subpart

OVERLAP = 0.002
#: how far a bar handle's outer face stands in front of the leaf it is mounted on (m)
HANDLE_PROUD = 0.03
#: hinged doors open to this angle
DOOR_OPEN = math.radians(100)
#: how far the raised frame of a shaker front stands proud of the leaf (m)
SHAKER_DEPTH = 0.006
#: drop-down doors (oven, dishwasher) open flat
FLAP_OPEN = math.radians(90)


# --------------------------------------------------------------------------------- solids
def open_shell(lo: Sequence[float], hi: Sequence[float], wall: float, back: float | None = None,
               open_top: bool = False) -> m3d.Manifold:
    """A hollow box spanning `lo`..`hi` with walls `wall` thick (the back, at low X, `back`
    thick), open at its +X face, or at its top face when `open_top` (a basin, a tray)."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    b = wall if back is None else back
    if open_top:
        inner = box_between((lo[0] + wall, lo[1] + wall, lo[2] + b),
                            (hi[0] - wall, hi[1] - wall, hi[2] + 0.01))
    else:
        inner = box_between((lo[0] + b, lo[1] + wall, lo[2] + wall),
                            (hi[0] + 0.01, hi[1] - wall, hi[2] - wall))
    return box_between(lo, hi) - inner


def rounded_rect_prism(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float,
                       radius: float, segments: int = 6) -> m3d.Manifold:
    """A vertical prism over the rectangle x0..x1, y0..y1 with rounded vertical edges."""
    r = min(radius, 0.49 * min(x1 - x0, y1 - y0))
    if r < 1e-4:
        return box_between((x0, y0, z0), (x1, y1, z1))
    cs = m3d.CrossSection.square((x1 - x0 - 2 * r, y1 - y0 - 2 * r), True).offset(
        r, m3d.JoinType.Round, 2.0, 4 * segments)
    return m3d.Manifold.extrude(cs, z1 - z0).translate(((x0 + x1) / 2, (y0 + y1) / 2, z0))


def pull_bar(x_face: float, a: Sequence[float], b: Sequence[float], standoff: float = HANDLE_PROUD,
             radius: float = 0.009, sections: int = 12) -> m3d.Manifold:
    """A round pull bar on a +X-facing face at `x_face` running from a=(y, z) to b=(y, z), its
    outer side `standoff` in front of the face, held by two posts 8% in from its ends that
    sink 1 mm into the face."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    xb = x_face + standoff - radius
    bar = rod((xb, a[0], a[1]), (xb, b[0], b[1]), radius, sections)
    posts = [rod((x_face - 0.001, *(a + t * (b - a))), (xb, *(a + t * (b - a))), radius * 0.8, 8)
             for t in (0.08, 0.92)]
    return solid_union([bar] + posts)


def window_leaf(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float,
                border: tuple[float, float, float, float], link: str, slot: str,
                glass_slot: str = "glass") -> list[Part]:
    """A door leaf (x0..x1 thick) with a rectangular window: the leaf with a hole leaving a
    frame of `border` = (low y, high y, bottom, top) widths, and a glass pane in the middle of
    its thickness overlapping the hole's edges by 1 mm (so the two are one shell)."""
    bl, br, bb, bt = border
    leaf = box_between((x0, y0, z0), (x1, y1, z1))
    hole = box_between((x0 - 0.01, y0 + bl, z0 + bb), (x1 + 0.01, y1 - br, z1 - bt))
    th = min(0.006, (x1 - x0) * 0.4)
    xm = (x0 + x1) / 2
    glass = box_between((xm - th / 2, y0 + bl - 0.001, z0 + bb - 0.001),
                        (xm + th / 2, y1 - br + 0.001, z1 - bt + 0.001))
    return [Part(leaf - hole, slot, link), Part(glass, glass_slot, link)]


Rect = tuple[float, float, float, float]  # (x0, x1, y0, y1)


def _slot_rects(size_u: float, size_v: float, pitch: float, bar: float, border: float) -> list[Rect]:
    """The slots (u0, u1, v0, v1) of a grille spanning [0, size_u] x [0, size_v]: running
    along u, leaving bars `bar` wide every `pitch` and a `border` all round."""
    n = max(1, int(round((size_v - 2 * border + bar) / pitch)))
    edges = np.linspace(border - bar / 2, size_v - border + bar / 2, n + 1)
    return [(border, size_u - border, e0 + bar / 2, e1 - bar / 2)
            for e0, e1 in zip(edges[:-1], edges[1:]) if e1 - e0 - bar > 0.002]


def rects_polygon(add: Sequence[Rect], sub: Sequence[Rect] = (), inset: float = 0.0) -> sg.Polygon:
    """The union of the `add` rectangles minus the `sub` ones, shrunk by `inset`, as one
    polygon with holes (its largest piece). 2D booleans in manifold3d: much faster than
    shapely's, which matters as placeholders carry these surfaces."""
    def cs(rects: Sequence[Rect]) -> list[m3d.CrossSection]:
        return [m3d.CrossSection.square((b - a, d - c)).translate((a, c)) for a, b, c, d in rects]

    shape = m3d.CrossSection.batch_boolean(cs(add), m3d.OpType.Add)
    if sub:
        shape = m3d.CrossSection.batch_boolean([shape] + cs(sub), m3d.OpType.Subtract)
    if inset > 0:
        shape = shape.offset(-inset, m3d.JoinType.Miter)
    rings = [np.asarray(r, float) for r in shape.to_polygons()]
    areas = [abs(_ring_area(r)) for r in rings]
    k = int(np.argmax(areas))
    outer = sg.Polygon(rings[k])
    holes = [r for i, r in enumerate(rings) if i != k and outer.contains(sg.Point(r[0]))]
    return sg.Polygon(rings[k], holes)


def _ring_area(r: np.ndarray) -> float:
    """Signed area of a closed 2D ring (N, 2) (shoelace)."""
    x, y = r[:, 0], r[:, 1]
    return 0.5 * float(x[:-1] @ y[1:] - y[:-1] @ x[1:] + x[-1] * y[0] - y[-1] * x[0])


def slotted_plate(size_u: float, size_v: float, thickness: float, pitch: float = 0.03,
                  bar: float = 0.005, border: float | None = None) -> m3d.Manifold:
    """A grille: a plate spanning [0, size_u] x [0, size_v] x [0, thickness] cut through by
    slots running along u, leaving bars `bar` wide every `pitch` and a border (default
    1.5 bars) all round. Built as one extruded 2D section, so it costs no 3D booleans."""
    b = 1.5 * bar if border is None else border
    outer = m3d.CrossSection.square((size_u, size_v))
    slots = [m3d.CrossSection.square((u1 - u0, v1 - v0)).translate((u0, v0))
             for u0, u1, v0, v1 in _slot_rects(size_u, size_v, pitch, bar, b)]
    cs = m3d.CrossSection.batch_boolean([outer] + slots, m3d.OpType.Subtract) if slots else outer
    return m3d.Manifold.extrude(cs, thickness)


def wire_rack(x0: float, x1: float, y0: float, y1: float, z_top: float, radius: float = 0.003,
              pitch: float = 0.03) -> m3d.Manifold:
    """A rack shelf whose top is at `z_top`: a 2*radius thick grille of bars running front to
    back every `pitch` inside a frame spanning x0..x1, y0..y1 (so its ends can sink into side
    walls)."""
    t = 2 * radius
    return slotted_plate(x1 - x0, y1 - y0, t, pitch, t).translate((x0, y0, z_top - t))


def rack_surface(name: str, x0: float, x1: float, y0: float, y1: float, z_top: float,
                 radius: float, pitch: float, clip: Rect) -> Surface:
    """The `Subpart.Interior` surface of the `wire_rack` with the same arguments: the tops of
    its bars (a polygon with a hole per slot) within `clip` (the part of the rack one can put
    things on, between the walls)."""
    t, e = 2 * radius, 0.0005
    slots = [(x0 + u0 - e, x0 + u1 + e, y0 + v0 - e, y0 + v1 + e)
             for u0, u1, v0, v1 in _slot_rects(x1 - x0, y1 - y0, pitch, t, 1.5 * t)]
    c0, c1, d0, d1 = clip[0] + e, clip[1] - e, clip[2] + e, clip[3] - e
    if all(c0 < a and b < c1 and d0 < c and d < d1 for a, b, c, d in slots):  # holes inside
        holes = np.array([[(a, c), (a, d), (b, d), (b, c), (a, c)] for a, b, c, d in slots])
        poly = shapely.polygons(shapely.linearrings([(c0, d0), (c1, d0), (c1, d1), (c0, d1)]),
                                holes=shapely.linearrings(holes))  # (vectorised: fast)
    else:
        poly = rects_polygon([clip], [(a + e, b - e, c + e, d - e) for a, b, c, d in slots], e)
    return Surface(name, Subpart.Interior, np.array([0.0, 0.0, z_top]), np.array([0.0, 0.0, 1.0]),
                   np.array([1.0, 0.0, 0.0]), poly)


def shaker_frame(x_face: float, y0: float, y1: float, z0: float, z1: float,
                 border: float = 0.06, depth: float = SHAKER_DEPTH) -> m3d.Manifold:
    """The raised rails and stiles of a shaker-style front on a +X face at `x_face` (sinks
    1 mm into it)."""
    w, h = y1 - y0, z1 - z0
    bd = min(border, 0.3 * min(w, h))
    return frame(w, h, bd, depth + 0.001, (x_face + depth / 2 - 0.0005, (y0 + y1) / 2, (z0 + z1) / 2))


# --------------------------------------------------------------------------------- motions
def joint_for(m: DoorJoint, slide: float = 0.3, open_angle: float = DOOR_OPEN) -> Joint:
    """A named joint for a motion: `<link>_joint`, revolute to `open_angle` (drop-down flaps
    to 90 degrees) or prismatic to `slide` metres."""
    if m.kind == "prismatic":
        return make_joint(f"{m.link}_joint", m, 0.0, slide)
    upper = FLAP_OPEN if abs(m.axis[1]) > 0.5 else open_angle
    return make_joint(f"{m.link}_joint", m, 0.0, upper)


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


# ------------------------------------------------------------------------------- surfaces
def interior_rect(name: str, x0: float, x1: float, y0: float, y1: float, z: float,
                  margin: float = 0.01) -> Surface:
    """An upward `Subpart.Interior` rectangle (a shelf inside a closed compartment)."""
    return Surface.rect(name, Subpart.Interior, ((x0 + x1) / 2, (y0 + y1) / 2, z), (0, 0, 1),
                        (1, 0, 0), max((x1 - x0) / 2 - margin, 0.005), max((y1 - y0) / 2 - margin, 0.005))


def back_surface(x_back: float, region_yz: sg.Polygon) -> Surface:
    """A `back` surface (normal -X) on the plane x = x_back covering `region_yz` (a polygon in
    (y, z)): for wall-mounted objects whose back is not the whole bounding rectangle."""
    c = region_yz.centroid
    oy, oz = float(c.x), float(c.y)
    # u = +Y, v = n x u = -Z: 2D coordinates are (y - oy, oz - z)
    poly = sg.Polygon([(y - oy, oz - z) for y, z in region_yz.exterior.coords])
    return Surface("back", Subpart.Back, np.array([x_back, oy, oz]), np.array([-1.0, 0.0, 0.0]),
                   np.array([0.0, 1.0, 0.0]), poly)


# ------------------------------------------------------------------------- cabinet fronts
#: front panel thickness of cabinet doors and drawers (m)
FRONT_T = 0.018
#: gap between neighbouring fronts (m)
REVEAL = 0.003


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
