"""Architectural parts: what the door, window and staircase generators share, and `opening_size`.

The generators live in generators/openings/doors.py (interior_door, sliding_door,
exterior_door), generators/openings/windows.py (window, bay_window) and generators/stairs.py
(staircase, stair_railing); architecture/fixtures.py sizes wall openings with `opening_size`.

Door and window frame: the wall is the YZ plane, its thickness along X centred on x=0 (+X is the
side a door swings into and the room side of a window; -X the other room or the outside), the
opening's width along Y and its bottom at z=0 (a window's caller lifts it to its sill height).
Every door and window carries an ``opening`` surface (Subpart.Wall: the piece of wall the asset
replaces; not Interior, whose surfaces lie on the mesh; normal +X) lying in the wall's centre
plane and spanning the *rough opening*: the hole the wall needs, which the frame
(jambs, head, sill) fills; casings and sills lap over the wall around it. interior_door,
exterior_door and window have bounding boxes symmetric about the wall, so their origin lies on
the wall's centre plane; a sliding_door's track and leaf hang on the +X face and a bay_window
projects to -X, so for those the ``opening`` surface (not x=0, and for the sliding door not y=0)
marks the wall. Place any of them by putting the ``opening`` surface on the wall's opening.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.protocol import Surface
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.primitives import Part, bevel_box, box, box_between, lathe, rod
from indoorgen.model.tags import Subpart

#: how far touching members (jambs, rails, treads, balusters) overlap so that each link unions
#: into one shell (m; finer than primitives.OVERLAP)
MEMBER_OVERLAP = 0.001
#: clearance around door leaves and window sashes in their frames (m, > moving_parts.MOVING_GAP)
LEAF_GAP = 0.003
#: glass pane thickness (m)
GLASS = 0.006
#: a casing's inner edge stands back this far from the face of the jamb or lining it frames (m)
CASING_REVEAL = 0.004

#: side lites of an exterior door: choice -> count
SIDELITE_COUNT = {"none": 0, "left": 1, "right": 1, "both": 2}
#: default side-lite module width when params do not give one (m)
DEFAULT_SIDELITE_WIDTH = 0.35


def opening_size(params: dict[str, Any]) -> tuple[float, float]:
    """The rough opening (width along Y, height along Z, in metres) that the wall needs for the
    params of a door or window generator (interior_door, sliding_door, exterior_door, window,
    bay_window): the hole the frame fills, which is also the ``opening`` surface's rectangle.
    It is the `width` x `height` params, plus an exterior door's side lites
    (`sidelites` count x `sidelite_width`). Casings, sills and a bay's projection lap over the
    wall around it and need no hole."""
    w, h = float(params["width"]), float(params["height"])
    n = SIDELITE_COUNT.get(str(params.get("sidelites", "none")), 0)
    if n:
        w += n * float(params.get("sidelite_width", DEFAULT_SIDELITE_WIDTH))
    return w, h


def opening_surface(y0: float, y1: float, z0: float, z1: float, x: float = 0.0) -> Surface:
    """The ``opening`` surface: the rectangle y0..y1 x z0..z1 in the plane x (normal +X), the
    hole to cut in the wall. Subpart.Wall: it is the piece of wall the asset stands in for (it
    lies in the wall's centre plane, not on the mesh)."""
    return Surface.rect("opening", Subpart.Wall, (x, (y0 + y1) / 2, (z0 + z1) / 2),
                        (1, 0, 0), (0, 1, 0), (y1 - y0) / 2, (z1 - z0) / 2)


# ------------------------------------------------------------------------------- solids
def hull(points: Sequence[Sequence[float]]) -> m3d.Manifold:
    """The convex hull of 3D points."""
    return m3d.Manifold.hull_points(np.asarray(points, float))


def prism(points: Sequence[Sequence[float]] | np.ndarray, lo: float, hi: float, axis: str = "z"
          ) -> m3d.Manifold:
    """A 2D polygon extruded from `lo` to `hi` along `axis`: "z" takes (x, y) points, "y" takes
    (x, z) points and "x" takes (y, z) points. The polygon may be concave."""
    pts = np.asarray(points, float)
    x, y = pts[:, 0], pts[:, 1]
    if float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) < 0:
        pts = pts[::-1]
    solid = m3d.CrossSection([pts], m3d.FillRule.Positive).extrude(float(hi - lo))
    if axis == "z":
        return solid.translate((0.0, 0.0, float(lo)))
    if axis == "y":  # (a, b, c) -> (a, -c, b): a rotation, so orientation is kept
        return solid.rotate((90.0, 0.0, 0.0)).translate((0.0, float(hi), 0.0))
    mat = np.array([[0.0, 0.0, 1.0, float(lo)], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]])
    return solid.transform(mat)


def beam(p0: Sequence[float], p1: Sequence[float], width: float, height: float) -> m3d.Manifold:
    """A straight member from p0 to p1 (their centres) whose section in the vertical plane is
    `width` (horizontal, across the run) by `height` (vertical): a sheared box for sloping
    handrails and stringers, whose ends are vertical."""
    a, b = np.asarray(p0, float), np.asarray(p1, float)
    d = b[:2] - a[:2]
    n = np.array([-d[1], d[0], 0.0]) / max(float(np.linalg.norm(d)), 1e-12)
    pts = [p + sn * n * width / 2 + sz * np.array([0.0, 0.0, height / 2])
           for p in (a, b) for sn in (-1, 1) for sz in (-1, 1)]
    return hull(pts)


def oriented_box(center: Sequence[float], size: Sequence[float], yaw_deg: float) -> m3d.Manifold:
    """A box of `size` (x, y, z before turning) turned by `yaw_deg` about Z, centred on `center`."""
    return box(size).rotate((0.0, 0.0, float(yaw_deg))).translate(tuple(float(c) for c in center))


def slab(y0: float, y1: float, z0: float, z1: float, x0: float, x1: float, detail: bool,
         radius: float = 0.002) -> m3d.Manifold:
    """A board x0..x1 x y0..y1 x z0..z1 with slightly eased edges when detailed."""
    lo, hi = np.array([x0, y0, z0]), np.array([x1, y1, z1])
    if detail and radius > 1e-4:
        return bevel_box(tuple(hi - lo), tuple((lo + hi) / 2), radius, 1)
    return box_between(tuple(lo), tuple(hi))


def casing(face_x: float, side: int, y0: float, y1: float, z0: float, z_head: float,
           width: float, thickness: float, detail: bool) -> list[m3d.Manifold]:
    """An architrave on one wall face around an opening: two legs whose inner edges are at y0
    and y1, standing from z0, and a head whose lower edge is at z_head; `width` wide and
    `thickness` proud of the face at x=face_x (side=+1 the +X face, -1 the -X face). Its back
    sinks MEMBER_OVERLAP into what it covers."""
    xa, xb = ((face_x - MEMBER_OVERLAP, face_x + thickness) if side > 0
              else (face_x - thickness, face_x + MEMBER_OVERLAP))
    r = min(0.004, thickness * 0.3)
    return [slab(y0 - width, y0, z0, z_head + MEMBER_OVERLAP, xa, xb, detail, r),
            slab(y1, y1 + width, z0, z_head + MEMBER_OVERLAP, xa, xb, detail, r),
            slab(y0 - width, y1 + width, z_head, z_head + width, xa, xb, detail, r)]


def ring(y0: float, y1: float, z0: float, z1: float, x0: float, x1: float, border: float,
         border_bottom: float | None = None) -> m3d.Manifold:
    """A rectangular frame in the YZ plane: outer y0..y1 x z0..z1, members `border` wide (the
    bottom one `border_bottom`), x0..x1 deep."""
    bb = border if border_bottom is None else border_bottom
    outer = box_between((x0, y0, z0), (x1, y1, z1))
    inner = box_between((x0 - 0.01, y0 + border, z0 + bb), (x1 + 0.01, y1 - border, z1 - border))
    return outer - inner


def grid_cells(y0: float, y1: float, z0: float, z1: float, cols: int, rows: int, bar: float
               ) -> list[tuple[float, float, float, float]]:
    """The cells (y0, y1, z0, z1) of a cols x rows grid filling a rectangle, separated by bars
    `bar` wide; rows listed bottom to top."""
    cw = (y1 - y0 - (cols - 1) * bar) / cols
    rh = (z1 - z0 - (rows - 1) * bar) / rows
    return [(y0 + i * (cw + bar), y0 + i * (cw + bar) + cw, z0 + j * (rh + bar), z0 + j * (rh + bar) + rh)
            for j in range(rows) for i in range(cols)]


def muntins(y0: float, y1: float, z0: float, z1: float, x0: float, x1: float, cols: int,
            rows: int, bar: float = 0.02) -> list[m3d.Manifold]:
    """Glazing bars dividing the pane y0..y1 x z0..z1 into cols x rows lites, x0..x1 deep, their
    ends sunk MEMBER_OVERLAP into the surrounding frame."""
    out = []
    for i in range(1, cols):
        y = y0 + (y1 - y0) * i / cols
        out.append(box_between((x0, y - bar / 2, z0 - MEMBER_OVERLAP),
                               (x1, y + bar / 2, z1 + MEMBER_OVERLAP)))
    e = min(0.002, 0.1 * (x1 - x0))  # horizontal bars a little shallower: no flush faces
    for j in range(1, rows):
        z = z0 + (z1 - z0) * j / rows
        out.append(box_between((x0 + e, y0 - MEMBER_OVERLAP, z - bar / 2),
                               (x1 - e, y1 + MEMBER_OVERLAP, z + bar / 2)))
    return out


def glazed_sash(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, border: float,
                cols: int, rows: int, link: str, slot: str = "frame", detail: bool = True
                ) -> list[Part]:
    """A window sash (or a fixed glazed panel): a frame `border` wide, x0..x1 deep, around a
    glass pane (GLASS thick, centred, its edges sunk into the frame) divided by muntins into
    cols x rows lites. Without detail, one box."""
    if not detail:
        return [Part(box_between((x0, y0, z0), (x1, y1, z1)), slot, link)]
    xm = (x0 + x1) / 2
    iy0, iy1, iz0, iz1 = y0 + border, y1 - border, z0 + border, z1 - border
    out = [Part(ring(y0, y1, z0, z1, x0, x1, border), slot, link),
           Part(box_between((xm - GLASS / 2, iy0 - 0.006, iz0 - 0.006),
                            (xm + GLASS / 2, iy1 + 0.006, iz1 + 0.006)), "glass", link)]
    depth = (x1 - x0) * 0.35
    out += [Part(m, slot, link) for m in muntins(iy0, iy1, iz0, iz1, xm - depth, xm + depth, cols, rows)]
    return out


# ------------------------------------------------------------------------------ hardware
def lever(face_x: float, y: float, z: float, toward: float, standoff: float = 0.065,
          length: float = 0.12, rose: float = 0.025) -> m3d.Manifold:
    """A lever handle on a +X-facing face at (face_x, y, z): a round rose, a neck and a
    horizontal lever `length` long pointing along `toward` (+1 or -1 in Y), its front at
    face_x + standoff."""
    x1 = face_x + standoff
    return solid_union([
        rod((face_x - MEMBER_OVERLAP, y, z), (face_x + 0.008, y, z), rose, 16),
        rod((face_x + 0.007, y, z), (x1 - 0.01, y, z), 0.009, 12),
        bevel_box((0.018, length + 0.02, 0.016), (x1 - 0.009, y + toward * (length / 2), z), 0.005, 1),
    ])


def round_knob(face_x: float, y: float, z: float, standoff: float = 0.065,
               radius: float = 0.028) -> m3d.Manifold:
    """A round door knob on a +X-facing face: rose, neck and a turned knob ending at
    face_x + standoff."""
    x1 = face_x + standoff
    k = radius
    head = lathe([(0.0, 0.0), (0.55 * k, 0.0), (k, 0.35 * k), (0.95 * k, 0.85 * k), (0.6 * k, 1.2 * k),
                  (0.0, 1.25 * k)], 16).rotate((0.0, 90.0, 0.0)).translate((x1 - 1.25 * k, y, z))
    return solid_union([rod((face_x - MEMBER_OVERLAP, y, z), (face_x + 0.008, y, z), 0.026, 16),
                        rod((face_x + 0.007, y, z), (x1 - 1.2 * k, y, z), 0.01, 12), head])


# ------------------------------------------------------------------------------- railings
def baluster(x: float, y: float, z0: float, z1: float, style: str, yaw_deg: float = 0.0
             ) -> m3d.Manifold:
    """One vertical baluster from z0 to z1 at (x, y): "round" a 12 mm rod, "square" a 25 mm bar
    turned to the run (yaw), "spindle" a turned wooden spindle (square ends, a rounded shaft)."""
    h = z1 - z0
    if style == "square":
        return oriented_box((x, y, (z0 + z1) / 2), (0.025, 0.025, h), yaw_deg)
    if style == "spindle":
        end = min(0.12, h * 0.2)
        return solid_union([
            oriented_box((x, y, z0 + end / 2), (0.035, 0.035, end), yaw_deg),
            oriented_box((x, y, z1 - end / 2), (0.035, 0.035, end), yaw_deg),
            rod((x, y, z0 + end - MEMBER_OVERLAP), (x, y, z1 - end + MEMBER_OVERLAP), 0.014, 12)])
    return rod((x, y, z0), (x, y, z1), 0.008, 8)


def handrail(p0: Sequence[float], p1: Sequence[float], style: str) -> m3d.Manifold:
    """A handrail whose top centre runs from p0 to p1: "round" a 45 mm rail, "flat" a
    70 x 40 mm moulded rail."""
    a, b = np.asarray(p0, float), np.asarray(p1, float)
    if style == "round":
        return rod(tuple(a - (0, 0, 0.0225)), tuple(b - (0, 0, 0.0225)), 0.0225, 12)
    return beam(tuple(a - (0, 0, 0.02)), tuple(b - (0, 0, 0.02)), 0.07, 0.04)


def post(x: float, y: float, z0: float, z1: float, size: float, yaw_deg: float = 0.0,
         detail: bool = True) -> m3d.Manifold:
    """A square newel post from z0 to z1 with a cap (and a ball finial when detailed)."""
    body = oriented_box((x, y, (z0 + z1) / 2), (size, size, z1 - z0), yaw_deg)
    if not detail:
        return body
    cap = oriented_box((x, y, z1 - 0.01), (size + 0.02, size + 0.02, 0.02), yaw_deg)
    return solid_union([body, cap])


def baluster_positions(length: float, spacing: float, margin: float) -> np.ndarray:
    """Evenly spread positions along a run of `length`, `margin` clear of each end, at most
    `spacing` apart (at least one)."""
    span = length - 2 * margin
    if span <= 0:
        return np.array([length / 2])
    n = max(1, int(math.ceil(span / spacing)) + 1)
    return margin + np.linspace(0.0, span, n)
