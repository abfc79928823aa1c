"""What the kitchen cabinets and the appliances share: open-fronted shells, pull bars, door
leaves with a window, the joint a front opens on, and interior shelf surfaces.

Design frame as everywhere: front +X, width along Y, Z up; fronts face +X.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

import manifold3d as m3d
import numpy as np

from indoorgen.assets.protocol import Joint, Surface
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import DOOR_OPEN, DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import Part, box_between, rod
from indoorgen.model.tags import Subpart

#: how far a bar handle's outer face stands in front of the leaf it is mounted on (m)
HANDLE_PROUD = 0.03
#: drop-down doors (oven, dishwasher) open flat
FLAP_OPEN = math.radians(90)


def open_shell(lo: Sequence[float], hi: Sequence[float], wall: float, back: float | None = None,
               open_top: bool = False) -> m3d.Manifold:
    """A hollow box spanning `lo`..`hi` with walls `wall` thick (the back, at low X, `back`
    thick), open at its +X face, or at its top face when `open_top` (a basin, a tray)."""
    c0, c1 = np.asarray(lo, float), np.asarray(hi, float)
    b = wall if back is None else back
    if open_top:
        inner = box_between((c0[0] + wall, c0[1] + wall, c0[2] + b),
                            (c1[0] - wall, c1[1] - wall, c1[2] + 0.01))
    else:
        inner = box_between((c0[0] + b, c0[1] + wall, c0[2] + wall),
                            (c1[0] + 0.01, c1[1] - wall, c1[2] - wall))
    return box_between(lo, hi) - inner


def pull_bar(x_face: float, a: Sequence[float], b: Sequence[float], standoff: float = HANDLE_PROUD,
             radius: float = 0.009, sections: int = 12) -> m3d.Manifold:
    """A round pull bar on a +X-facing face at `x_face` running from a=(y, z) to b=(y, z), its
    outer side `standoff` in front of the face, held by two posts 8% in from its ends that
    sink 1 mm into the face."""
    pa, pb = np.asarray(a, float), np.asarray(b, float)
    xb = x_face + standoff - radius
    bar = rod((xb, pa[0], pa[1]), (xb, pb[0], pb[1]), radius, sections)
    posts = [rod((x_face - 0.001, *(pa + t * (pb - pa))), (xb, *(pa + t * (pb - pa))), radius * 0.8, 8)
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

def joint_for(m: DoorJoint, slide: float = 0.3, open_angle: float = DOOR_OPEN) -> Joint:
    """A named joint for a motion: `<link>_joint`, revolute to `open_angle` (drop-down flaps
    to 90 degrees) or prismatic to `slide` metres."""
    if m.kind == "prismatic":
        return make_joint(f"{m.link}_joint", m, 0.0, slide)
    upper = FLAP_OPEN if abs(m.axis[1]) > 0.5 else open_angle
    return make_joint(f"{m.link}_joint", m, 0.0, upper)


def interior_rect(name: str, x0: float, x1: float, y0: float, y1: float, z: float,
                  margin: float = 0.01) -> Surface:
    """An upward `Subpart.Interior` rectangle (a shelf inside a closed compartment)."""
    return Surface.rect(name, Subpart.Interior, ((x0 + x1) / 2, (y0 + y1) / 2, z), (0, 0, 1),
                        (1, 0, 0), max((x1 - x0) / 2 - margin, 0.005), max((y1 - y0) / 2 - margin, 0.005))
