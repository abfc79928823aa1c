"""Dining tables: rectangular (apron, four legs), round (pedestal or 3-4 legs) and oval (elliptical
or stadium top on one or two pedestals or four legs); chairs go against their `side_i` facets."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.tables._parts import rect_table_parts, rect_table_surfaces, table_params
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    board,
    box,
    circle_polygon,
    cylinder,
    lathe,
    rounded_rect_polygon,
    rounded_slab,
)
from indoorgen.assets.shapes.surfaces import polygon_side_surfaces, support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class DiningTableRect(PartsFactory):
    """A rectangular dining table: top, apron and four legs; optional stretchers."""

    name = "dining_table_rect"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.DiningTable})
    size_class = "large"
    slots = ["wood"]
    drop_box = ("side_left", "side_right")
    params = {
        "depth": Param(0.8, 1.0, doc="X extent, the short side (m)"),
        "length": Param(1.2, 2.2, doc="Y extent, the long side (m)"),
        **table_params((0.72, 0.78), (0.05, 0.09)),
        "apron_height": Param(0.06, 0.12, doc="height of the apron boards under the top (m)"),
        "stretchers": Param(kind="bool", doc="add an H of stretchers between the legs"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, legs, apron and optional stretchers."""
        return rect_table_parts(p, detail, p["depth"], p["length"], apron=True)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and the four side facets."""
        return rect_table_surfaces(p, p["depth"], p["length"])


@register
class DiningTableRound(PartsFactory):
    """A round dining table on a pedestal or on 3-4 legs. Its `n_sides` side facets (a regular
    N-gon circumscribing the top) are where chairs go."""

    name = "dining_table_round"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.DiningTable})
    size_class = "large"
    slots = ["wood", "metal"]
    drop_box = ("side_left", "side_right")
    params = {
        "radius": Param(0.45, 0.7, doc="tabletop radius (m)"),
        "height": Param(0.72, 0.78, doc="overall height = tabletop's upper face (m)"),
        "top_thickness": Param(0.025, 0.05, doc="tabletop thickness (m)"),
        "edge_radius": Param(0.0, 0.01, doc="rounding of the tabletop's edge (m)"),
        "base_style": Param(kind="choice", choices=("pedestal", "legs3", "legs4"),
                            doc="central pedestal or 3/4 legs"),
        "n_sides": Param(4, 8, kind="int", doc="number of chair-facing side facets"),
        "column_radius": Param(0.04, 0.09, doc="pedestal column radius (m)"),
        "foot_radius_frac": Param(0.45, 0.7, doc="pedestal foot radius / top radius"),
        "leg_thickness": Param(0.04, 0.07, doc="leg diameter for legged bases (m)"),
        "leg_radius_frac": Param(0.55, 0.75, doc="leg circle radius / top radius"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The round top and a pedestal or 3-4 legs with a ring apron."""
        r, h, tt = p["radius"], p["height"], p["top_thickness"]
        er = p["edge_radius"]
        n = 64 if detail else 16
        if detail and er > 1e-4:
            prof = [(0.0, h - tt)]
            for k in range(5):  # bottom corner arc
                a = -math.pi / 2 + (math.pi / 2) * k / 4
                prof.append((r - er + er * math.cos(a), h - tt + er + er * math.sin(a)))
            for k in range(5):  # top corner arc
                a = (math.pi / 2) * k / 4
                prof.append((r - er + er * math.cos(a), h - er + er * math.sin(a)))
            prof.append((0.0, h))
            top = lathe(prof, n)
        else:
            top = cylinder(r, tt, (0, 0, h - tt), n, circumscribed=not detail)
        out = [Part(top, "wood")]
        z_under = h - tt + OVERLAP
        circ = not detail
        if p["base_style"] == "pedestal":
            fr = r * p["foot_radius_frac"]
            cr = p["column_radius"]
            foot = cylinder(fr, 0.04, (0, 0, 0), n, radius_top=(fr * 0.8 if detail else None),
                            circumscribed=circ)
            out.append(Part(foot, "metal"))
            out.append(Part(cylinder(cr, z_under - 0.03, (0, 0, 0.03), 32 if detail else 8,
                                     circumscribed=circ), "wood"))
            out.append(Part(cylinder(min(cr * 2.2, r * 0.6), 0.03, (0, 0, z_under - 0.03),
                                     32 if detail else 8, circumscribed=circ), "wood"))
        else:
            k = 3 if p["base_style"] == "legs3" else 4
            lr, lt = r * p["leg_radius_frac"], p["leg_thickness"]
            for i in range(k):
                a = 2 * math.pi * (i + 0.5) / k
                c = (lr * math.cos(a), lr * math.sin(a), 0.0)
                out.append(Part(cylinder(lt / 2 * (0.7 if detail else 1.0), z_under, c,
                                         16 if detail else 8, radius_top=lt / 2,
                                         circumscribed=circ), "wood"))
            # a ring apron tying the legs together under the top
            ring_r = lr + lt / 2 + 0.005
            ring = [(ring_r - 0.02, z_under - 0.06), (ring_r, z_under - 0.06), (ring_r, z_under),
                    (ring_r - 0.02, z_under)]
            out.append(Part(lathe(ring, n, circumscribed=circ), "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The round `top` and `n_sides` chair facets."""
        r, h = p["radius"], p["height"]
        return [support_polygon("top", (0, 0, h), circle_polygon(r - 0.02, 64)),
                *polygon_side_surfaces(r, int(p["n_sides"]), h)]


def oval_outline(shape: str, a: float, b: float, n: int = 720) -> tuple[np.ndarray, np.ndarray]:
    """Dense points (n, 2) on the edge of an oval top (semi-axes a along X, b along Y; an
    "ellipse" or a "stadium" with round ends of radius a) and their outward unit normals,
    counter-clockwise from the +X extreme."""
    if shape == "ellipse":
        t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
        pts = np.c_[a * np.cos(t), b * np.sin(t)]
        nrm = np.c_[b * np.cos(t), a * np.sin(t)]
        return pts, nrm / np.linalg.norm(nrm, axis=1, keepdims=True)
    # stadium: straight sides x = +-a for |y| <= b - a, half circles of radius a at the ends
    c = b - a
    perim = 4 * c + 2 * np.pi * a
    s = np.linspace(0.0, perim, n, endpoint=False)
    pts, nrm = np.empty((n, 2)), np.empty((n, 2))
    segs = [c, np.pi * a, 2 * c, np.pi * a, c]
    edges = np.cumsum([0.0] + segs)
    for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:], strict=False)):
        m = (s >= lo) & (s < hi)
        u = s[m] - lo
        if i == 0:
            pts[m], nrm[m] = np.c_[np.full(m.sum(), a), u], (1.0, 0.0)
        elif i == 1:
            ang = u / a
            nrm[m] = np.c_[np.cos(ang), np.sin(ang)]
            pts[m] = np.c_[a * np.cos(ang), c + a * np.sin(ang)]
        elif i == 2:
            pts[m], nrm[m] = np.c_[np.full(m.sum(), -a), c - u], (-1.0, 0.0)
        elif i == 3:
            ang = np.pi + u / a
            nrm[m] = np.c_[np.cos(ang), np.sin(ang)]
            pts[m] = np.c_[a * np.cos(ang), -c + a * np.sin(ang)]
        else:
            pts[m], nrm[m] = np.c_[np.full(m.sum(), a), -c + u], (1.0, 0.0)
    return pts, nrm


def oval_side_surfaces(shape: str, a: float, b: float, height: float, spacing: float
                       ) -> list[Surface]:
    """Vertical facets tangent to an oval top's edge (Subpart.Side, `side_0..`), spread evenly
    along the perimeter about every `spacing` metres (an even number, at least 4, starting at
    the +X extreme), each 90% of that spacing wide and full height."""
    pts, nrm = oval_outline(shape, a, b)
    seg = np.linalg.norm(np.diff(np.vstack([pts, pts[:1]]), axis=0), axis=1)
    s = np.r_[0.0, np.cumsum(seg)]
    perim = s[-1]
    n = max(4, 2 * int(round(perim / (2 * spacing))))
    out = []
    # each facet's point and normal interpolated along the outline at its arc length, so they
    # vary smoothly with the params (picking the nearest sample jumped a facet by a sample's
    # angle when a param moved in its 6th decimal, as scene.json's rounding does)
    closed_pts, closed_nrm = np.vstack([pts, pts[:1]]), np.vstack([nrm, nrm[:1]])
    for i in range(n):
        t = i * perim / n
        j = min(int(np.searchsorted(s, t, side="right")), len(s) - 1)
        f = 0.0 if s[j] <= s[j - 1] else (t - s[j - 1]) / (s[j] - s[j - 1])
        px, py = closed_pts[j - 1] + f * (closed_pts[j] - closed_pts[j - 1])
        nx, ny = closed_nrm[j - 1] + f * (closed_nrm[j] - closed_nrm[j - 1])
        nx, ny = np.array([nx, ny]) / np.hypot(nx, ny)
        out.append(Surface.rect(f"side_{i}", Subpart.Side, (px, py, height / 2), (nx, ny, 0.0),
                                (-ny, nx, 0.0), 0.45 * perim / n, height / 2))
    return out


@register
class DiningTableOval(PartsFactory):
    """An oval dining table: an elliptical or stadium (racetrack) top on a central pedestal, a
    double pedestal joined by a beam, or four legs tied by an oval apron. Chairs go against its
    `side_i` facets, tangent to the edge all round."""

    name = "dining_table_oval"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.DiningTable})
    size_class = "large"
    drop_box = ("side_left", "side_right")  # chairs go on the tangent side_i facets only
    slots = ["wood", "metal"]
    CHAIR_SPACING = 0.6  # perimeter length per chair facet (m)
    params = {
        "length": Param(1.4, 2.4, doc="Y extent, the long axis (m)"),
        "width": Param(0.9, 1.2, doc="X extent, the short axis (m)"),
        "height": Param(0.72, 0.78, doc="overall height = tabletop's upper face (m)"),
        "top_thickness": Param(0.025, 0.05, doc="tabletop thickness (m)"),
        "edge_radius": Param(0.0, 0.01, doc="rounding of the tabletop's edge (m)"),
        "top_shape": Param(kind="choice", choices=("ellipse", "stadium"),
                           doc="elliptical or racetrack (straight sides, round ends) top"),
        "base_style": Param(kind="choice", choices=("pedestal", "double_pedestal", "legs4"),
                            doc="one or two pedestals, or four legs with an apron"),
        "column_radius": Param(0.04, 0.09, doc="pedestal column radius (m)"),
        "leg_thickness": Param(0.04, 0.07, doc="leg diameter for the legged base (m)"),
        "taper": Param(0.5, 1.0, doc="legs' foot / top diameter; a pedestal column flares to "
                                     "(2 - taper) times its radius at the foot"),
    }

    def _top(self, p, detail) -> m3d.Manifold:
        a, b = p["width"] / 2, p["length"] / 2
        h, tt, er = p["height"], p["top_thickness"], p["edge_radius"]
        if p["top_shape"] == "stadium":
            return rounded_slab(2 * a, 2 * b, h - tt, h, a, sections=64) if detail else \
                box((2 * a, 2 * b, tt), (0, 0, h - tt / 2))
        if not detail:
            return cylinder(a, tt, (0, 0, h - tt), 16, circumscribed=True).scale((1.0, b / a, 1.0))
        if er > 1e-4:
            prof = [(0.0, h - tt)]
            for k in range(5):
                ang = -math.pi / 2 + (math.pi / 2) * k / 4
                prof.append((a - er + er * math.cos(ang), h - tt + er + er * math.sin(ang)))
            for k in range(5):
                ang = (math.pi / 2) * k / 4
                prof.append((a - er + er * math.cos(ang), h - er + er * math.sin(ang)))
            prof.append((0.0, h))
            top = lathe(prof, 96)
        else:
            top = cylinder(a, tt, (0, 0, h - tt), 96)
        return top.scale((1.0, b / a, 1.0))

    def _pedestal(self, p, y: float, foot_r: float, detail, stretch: float = 1.0) -> list[Part]:
        """Foot, column and head plate of a pedestal at (0, y); the foot stretched along Y."""
        h, tt, cr = p["height"], p["top_thickness"], p["column_radius"]
        zu = h - tt + OVERLAP
        n = 48 if detail else 12
        c = not detail
        prof = [(0, 0), (foot_r, 0), (foot_r, 0.015), (foot_r * 0.75, 0.035), (cr * 1.3, 0.06), (0, 0.06)]
        foot = (lathe(prof, n) if detail else cylinder(foot_r, 0.06, (0, 0, 0), n, circumscribed=True))
        return [Part(foot.scale((1.0, stretch, 1.0)).translate((0.0, y, 0.0)), "metal"),
                Part(cylinder(cr * (2.0 - p["taper"]), zu - 0.05, (0, y, 0.05), 32 if detail else 8,
                              radius_top=cr, circumscribed=c), "wood"),
                Part(cylinder(min(2.2 * cr, 0.2), 0.03, (0, y, zu - 0.03), 32 if detail else 8,
                              circumscribed=c), "wood")]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The oval top and one or two pedestals, or four legs with an oval apron."""
        a, b = p["width"] / 2, p["length"] / 2
        h, tt = p["height"], p["top_thickness"]
        out = [Part(self._top(p, detail), "wood")]
        style = p["base_style"]
        zu = h - tt + OVERLAP
        if style == "pedestal":
            # a long top gets a foot stretched along its length
            out += self._pedestal(p, 0.0, min(0.8 * a, 0.45), detail, min(b / a, 1.6))
        elif style == "double_pedestal":
            yp = 0.5 * b
            for y in (-yp, yp):
                out += self._pedestal(p, y, min(0.55 * a, 0.3, 0.9 * yp), detail)
            out.append(board((-0.04, -yp, zu - 0.09), (0.04, yp, zu), "wood"))
        else:
            lt = p["leg_thickness"]
            ka, kb = 0.75 * a, b - 0.25 * a
            c = math.sqrt(0.5)
            spots = [(sx * ka * c, sy * kb * c) for sx in (-1, 1) for sy in (-1, 1)]
            for x, y in spots:
                out.append(Part(cylinder(lt / 2 * (p["taper"] if detail else 1.0), zu, (x, y, 0.0),
                                         16 if detail else 8, radius_top=lt / 2, circumscribed=not detail),
                                "wood"))
            # an oval apron through the legs' centres
            rr = ka  # the ellipse (ka, kb) passes through the legs' centres
            ring = lathe([(rr - 0.02, zu - 0.07), (rr + 0.005, zu - 0.07), (rr + 0.005, zu),
                          (rr - 0.02, zu)],
                         64 if detail else 12, circumscribed=not detail).scale((1.0, kb / ka, 1.0))
            out.append(Part(ring, "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and the facets tangent to its edge."""
        a, b, h, er = p["width"] / 2, p["length"] / 2, p["height"], p["edge_radius"]
        if p["top_shape"] == "stadium":
            plan = rounded_rect_polygon(2 * a, 2 * b, a, 0.02)
        else:
            t = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
            ia, ib = a - 0.02 - er, b - 0.02 - er * b / a
            plan = sg.Polygon(np.c_[ia * np.cos(t), ib * np.sin(t)])
        return [support_polygon("top", (0, 0, h), plan),
                *oval_side_surfaces(p["top_shape"], a, b, h, self.CHAIR_SPACING)]
