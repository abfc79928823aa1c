"""What the appliance generators share: grilles and wire racks (one extruded 2D section each,
no 3D booleans) and the surfaces on top of their bars.
"""
from __future__ import annotations

from collections.abc import Sequence

import manifold3d as m3d
import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.assets.protocol import Surface
from indoorgen.model.tags import Subpart

Rect = tuple[float, float, float, float]  # (x0, x1, y0, y1)


def _slot_rects(size_u: float, size_v: float, pitch: float, bar: float, border: float) -> list[Rect]:
    """The slots (u0, u1, v0, v1) of a grille spanning [0, size_u] x [0, size_v]: running
    along u, leaving bars `bar` wide every `pitch` and a `border` all round."""
    n = max(1, int(round((size_v - 2 * border + bar) / pitch)))
    edges = np.linspace(border - bar / 2, size_v - border + bar / 2, n + 1)
    return [(border, size_u - border, e0 + bar / 2, e1 - bar / 2)
            for e0, e1 in zip(edges[:-1], edges[1:], strict=True) if e1 - e0 - bar > 0.002]


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
