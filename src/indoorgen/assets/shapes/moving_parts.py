"""Parts that move and what moves them: handles, knobs, hinged doors, drawers, cabinet fronts, and
their hinge or slide motions."""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import manifold3d as m3d
import numpy as np
import shapely

from indoorgen.assets.protocol import Joint, Surface
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.primitives import Part, Vec3, box_between, rod
from indoorgen.model.tags import Subpart

# --------------------------------------------------------------------------- moving parts
#: clearance between a moving part and the body it moves against (m)
MOVING_GAP = 0.002
#: door / drawer front thickness (m)
FRONT_T = 0.018
#: gap left around every front, so neighbouring fronts never touch (m)
REVEAL = 0.002
#: how far `bar_handle` and `knob` stand proud of the front they are on (their defaults) (m)
HANDLE_STANDOFF = {"bar": 0.03, "knob": 0.025}
#: how far hinged doors open (rad)
DOOR_OPEN = math.radians(100)


def bar_handle(center: Vec3, length: float, vertical: bool, standoff: float = HANDLE_STANDOFF["bar"],
               thickness: float = 0.012) -> m3d.Manifold:
    """A bar handle on a +X-facing front: a bar `length` long (vertical or horizontal) held
    `standoff` proud of the front by two posts; `center` is on the front face. The posts sink
    1 mm into the front so that the handle unions with it into one shell."""
    cx, cy, cz = (float(c) for c in center)
    t, half = thickness, length / 2
    xb0, xb1 = cx + standoff - t, cx + standoff
    if vertical:
        bar = box_between((xb0, cy - t / 2, cz - half), (xb1, cy + t / 2, cz + half))
        ends = [(cy, cz - 0.8 * half), (cy, cz + 0.8 * half)]
    else:
        bar = box_between((xb0, cy - half, cz - t / 2), (xb1, cy + half, cz + t / 2))
        ends = [(cy - 0.8 * half, cz), (cy + 0.8 * half, cz)]
    posts = [box_between((cx - 0.001, y - t / 2, z - t / 2), (xb0 + 0.001, y + t / 2, z + t / 2))
             for y, z in ends]
    return solid_union([bar] + posts)


def knob(center: Vec3, radius: float = 0.015, standoff: float = HANDLE_STANDOFF["knob"]) -> m3d.Manifold:
    """A round knob on a +X-facing front at `center`."""
    cx, cy, cz = (float(c) for c in center)
    stem = rod((cx - 0.001, cy, cz), (cx + standoff * 0.6, cy, cz), radius * 0.45, 12)
    head = rod((cx + standoff * 0.5, cy, cz), (cx + standoff, cy, cz), radius, 16)
    return solid_union([stem, head])


def hinged_door(front_x: float, y0: float, y1: float, z0: float, z1: float, thickness: float,
                hinge: str, link: str, handle: str = "bar", slot: str = "front",
                handle_slot: str = "metal", gap: float = MOVING_GAP
                ) -> tuple[list[Part], DoorJoint]:
    """A door leaf covering the opening y0..y1, z0..z1 of a +X-facing front whose face is at
    `front_x`, hinged on its `hinge` side ("left" = low y, "right" = high y, "bottom" = a
    drop-down flap like an oven door, "top" = a lift-up flap). The leaf stands `gap` in front of
    the face, so it swings outward without touching the body. Returns its parts (on `link`) and
    the joint description (axis through the leaf's outer hinge edge, 0 = shut)."""
    x0, x1 = front_x + gap, front_x + gap + thickness
    leaf = box_between((x0, y0, z0), (x1, y1, z1))
    parts = [Part(leaf, slot, link)]
    w, h = y1 - y0, z1 - z0
    if hinge in ("left", "right"):
        yh = y1 - min(0.05, w * 0.2) if hinge == "left" else y0 + min(0.05, w * 0.2)
        zc = z0 + h * (0.5 if h < 0.5 else 0.75 if z0 < 0.5 else 0.2)
        zc = min(max(zc, z0 + 0.06), z1 - 0.06)
        hl = min(0.14, h * 0.4)
        grip = (x1, yh, zc)
        vertical = True
    else:
        zh = z1 - min(0.05, h * 0.2) if hinge == "bottom" else z0 + min(0.05, h * 0.2)
        grip = (x1, (y0 + y1) / 2, zh)
        hl = min(0.3, w * 0.6)
        vertical = False
    if handle == "bar":
        parts.append(Part(bar_handle(grip, hl, vertical), handle_slot, link))
    elif handle == "knob":
        parts.append(Part(knob(grip), handle_slot, link))
    return parts, hinge_motion(hinge, x1, y0, y1, z0, z1, link)


def drawer(front_x: float, y0: float, y1: float, z0: float, z1: float, depth: float,
           thickness: float, link: str, board: float = 0.012, handle: str = "bar",
           slot: str = "front", box_slot: str = "wood", handle_slot: str = "metal",
           gap: float = MOVING_GAP) -> tuple[list[Part], DoorJoint]:
    """A drawer for the opening y0..y1, z0..z1 of a +X-facing front at `front_x`: a front panel
    `gap` proud of the face plus an open-topped box `depth` deep that slides inside the opening
    with `gap` clearance all round. Returns its parts (on `link`) and a prismatic joint along +X
    (0 = shut; open it at most `depth` minus a little so it stays in its runners)."""
    fx0, fx1 = front_x + gap, front_x + gap + thickness
    parts = [Part(box_between((fx0, y0, z0), (fx1, y1, z1)), slot, link)]
    # the box inside the opening, clear of it by 2*gap on each side, below and above
    by0, by1, bz0 = y0 + 2 * gap, y1 - 2 * gap, z0 + 2 * gap
    bz1 = max(bz0 + 0.03, z1 - 0.02)
    bx0, bx1 = front_x - depth, fx0 + 0.001
    b = board
    shell = [box_between((bx0, by0, bz0), (bx1, by1, bz0 + b)),                # bottom
             box_between((bx0, by0, bz0), (bx0 + b, by1, bz1)),                # back
             box_between((bx0, by0, bz0), (bx1, by0 + b, bz1)),                # sides
             box_between((bx0, by1 - b, bz0), (bx1, by1, bz1))]
    parts.append(Part(solid_union(shell), box_slot, link))
    grip = (fx1, (y0 + y1) / 2, (z0 + z1) / 2)
    if handle == "bar":
        parts.append(Part(bar_handle(grip, min(0.16, (y1 - y0) * 0.5), False), handle_slot, link))
    elif handle == "knob":
        parts.append(Part(knob(grip), handle_slot, link))
    return parts, DoorJoint("prismatic", np.array([1.0, 0.0, 0.0]), np.array(grip), link)


def drawer_floor(name: str, front_x: float, y0: float, y1: float, z0: float, depth: float,
                 link: str, board: float = 0.012, gap: float = MOVING_GAP) -> Surface:
    """The upward `Interior` surface on the floor of the box `drawer` builds for the same
    arguments, inside its back, sides and front, moving with its `link`: what is put away in
    the drawer rests there and comes out with it."""
    x0, x1 = front_x - depth + board, front_x + gap
    ya, yb = y0 + 2 * gap + board, y1 - 2 * gap - board
    z = z0 + 2 * gap + board
    return Surface(name, Subpart.Interior, np.array([(x0 + x1) / 2, (ya + yb) / 2, z]),
                   np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                   shapely.box(-(x1 - x0) / 2 + 0.005, -(yb - ya) / 2 + 0.005,
                               (x1 - x0) / 2 - 0.005, (yb - ya) / 2 - 0.005), link)


@dataclass(frozen=True)
class DoorJoint:
    """How a moving part built here moves (kind, axis, origin, link); the generator adds the
    joint's name and range when it turns this into an `assets.protocol.Joint`."""

    kind: str
    axis: np.ndarray
    origin: np.ndarray
    link: str


def hinge_motion(hinge: str, x1: float, y0: float, y1: float, z0: float, z1: float,
                 link: str) -> DoorJoint:
    """The revolute motion of a leaf whose outer face is at `x1`, covering y0..y1, z0..z1,
    hinged on its `hinge` side ("left" = low y, "right" = high y, "bottom" drop-down, "top"
    lift-up): the axis runs along the leaf's outer hinge edge, so it swings away from the body."""
    if hinge == "left":
        axis, origin = (0.0, 0.0, -1.0), (x1, y0, z0)
    elif hinge == "right":
        axis, origin = (0.0, 0.0, 1.0), (x1, y1, z0)
    elif hinge == "bottom":
        axis, origin = (0.0, 1.0, 0.0), (x1, y0, z0)
    elif hinge == "top":
        axis, origin = (0.0, -1.0, 0.0), (x1, y0, z1)
    else:
        raise ValueError(f"hinge must be left, right, bottom or top, got {hinge!r}")
    return DoorJoint("revolute", np.array(axis), np.array(origin), link)


def slide_motion(link: str, origin: Sequence[float]) -> DoorJoint:
    """A prismatic motion along +X (a drawer pulled out)."""
    return DoorJoint("prismatic", np.array([1.0, 0.0, 0.0]), np.asarray(origin, float), link)


@dataclass(frozen=True)
class Front:
    """One cell of a cabinet front: the opening y0..y1, z0..z1 and what closes it: "left" or
    "right" (a door hinged on that side), "flap_down" / "flap_up" (hinged at the bottom / top),
    "drawer", or "open" (nothing)."""

    y0: float
    y1: float
    z0: float
    z1: float
    kind: str


def cabinet_fronts(front_x: float, cells: Sequence[Front], depth: float, *, thickness: float = FRONT_T,
                   handle: str = "bar", prefix: str = "", slot: str = "front",
                   handle_slot: str = "metal", reveal: float = REVEAL
                   ) -> list[tuple[list[Part], DoorJoint]]:
    """Doors, flaps and drawers for the `cells` of a +X front at `front_x`, each on its own link
    (`door_0`, `drawer_1`...); each cell is shrunk by `reveal` on every edge so neighbours never
    touch. Drawer boxes reach `depth` behind the front. Returns (parts, motion) per moving cell."""
    out = []
    for i, c in enumerate(cells):
        y0, y1, z0, z1 = c.y0 + reveal, c.y1 - reveal, c.z0 + reveal, c.z1 - reveal
        if c.kind == "open":
            continue
        if c.kind == "drawer":
            out.append(drawer(front_x, y0, y1, z0, z1, depth, thickness, f"{prefix}drawer_{i}",
                              handle=handle, slot=slot, handle_slot=handle_slot))
        else:
            hinge = {"left": "left", "right": "right", "flap_down": "bottom", "flap_up": "top"}.get(c.kind)
            if hinge is None:
                raise ValueError(f"unknown front kind {c.kind!r}")
            out.append(hinged_door(front_x, y0, y1, z0, z1, thickness, hinge, f"{prefix}door_{i}",
                                   handle=handle, slot=slot, handle_slot=handle_slot))
    return out


#: how far cabinet fronts and their handles stand proud of the carcass (gap + leaf + bar handle)
FRONT_PROUD = MOVING_GAP + FRONT_T + HANDLE_STANDOFF["bar"]


def make_joint(name: str, moving: DoorJoint, lower: float, upper: float) -> Joint:
    """A named `Joint` with range [lower, upper] from a moving part's description."""
    return Joint(name, moving.kind, moving.axis, moving.origin, lower, upper, moving.link)
