"""More tables: oval dining tables, desks and console tables (front, the user side, is +X).

Like the tables in tables.py they expose `top`, a support surface on the tabletop's upper face
(2 cm in from its edge). The oval dining table adds `side_0..side_N`, vertical planes tangent to
its edge all round, where chairs are pulled up (`programs.common.at_table`); a desk adds
`side_0`, the plane of its front edge, where its chair goes. Desk and console drawers are
articulated (prismatic joints), built with `parts.cabinet_fronts` inside open carcasses.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.tables import rect_table_parts
from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    bevel_box,
    board,
    box,
    cylinder,
    lathe,
    rounded_rect_polygon,
    rounded_slab,
)
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def _translate(parts: list[Part], offset) -> list[Part]:
    off = tuple(float(v) for v in offset)
    return [Part(p.solid.translate(off), p.slot, p.link) for p in parts]


def _drawer_joints(fronts, depth: float) -> list:
    """Prismatic joints for drawers `depth` deep, opening to 80% of it."""
    return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for _, m in fronts]


# ========================================================================= oval dining table
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
    for i, (lo, hi) in enumerate(zip(edges[:-1], edges[1:])):
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
    for i in range(n):
        j = int(np.searchsorted(s, i * perim / n)) % len(pts)
        (px, py), (nx, ny) = pts[j], nrm[j]
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

    def parts(self, p, detail):
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

    def extra_surfaces(self, p):
        a, b, h, er = p["width"] / 2, p["length"] / 2, p["height"], p["edge_radius"]
        if p["top_shape"] == "stadium":
            plan = rounded_rect_polygon(2 * a, 2 * b, a, 0.02)
        else:
            t = np.linspace(0.0, 2 * np.pi, 64, endpoint=False)
            ia, ib = a - 0.02 - er, b - 0.02 - er * b / a
            plan = sg.Polygon(np.c_[ia * np.cos(t), ib * np.sin(t)])
        return [support_polygon("top", (0, 0, h), plan),
                *oval_side_surfaces(p["top_shape"], a, b, h, self.CHAIR_SPACING)]


# ======================================================================================= desk
@register
class Desk(PartsFactory):
    """A writing / office desk: a top on four legs with an apron, on one drawer pedestal and a
    panel end, or on two pedestals; optional pencil drawer under the middle, modesty panel at
    the back and a hutch (a shelf on two sides) standing on the top's rear. Every drawer slides
    out on its own prismatic joint."""

    name = "desk"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.Desk})
    size_class = "large"
    drop_box = ("side_left", "side_right")  # its chair goes at side_0, the front edge
    slots = ["wood", "front", "metal", "back"]
    params = {
        "width": Param(1.0, 1.8, doc="Y extent (m)"),
        "depth": Param(0.55, 0.8, doc="X extent (m)"),
        "height": Param(0.72, 0.77, doc="height of the top's upper face (m)"),
        "top_thickness": Param(0.02, 0.04, doc="top thickness (m)"),
        "base_style": Param(kind="choice", choices=("legs", "single_pedestal", "double_pedestal"),
                            doc="four legs, one drawer pedestal and a panel end, or two pedestals"),
        "pedestal_side": Param(kind="choice", choices=("left", "right"),
                               doc="side (+Y left, -Y right) of a single pedestal"),
        "n_drawers": Param(2, 4, kind="int", doc="drawers per pedestal"),
        "pedestal_width": Param(0.35, 0.45, doc="pedestal Y extent (m)"),
        "leg_thickness": Param(0.035, 0.06, doc="leg section (m)"),
        "center_drawer": Param(kind="bool", doc="a shallow drawer under the middle of the top"),
        "modesty_panel": Param(kind="bool", doc="a panel closing the back of the knee space"),
        "hutch": Param(kind="bool", doc="a shelf unit standing on the back of the top"),
        "hutch_height": Param(0.25, 0.45, doc="hutch height above the top (m)"),
    }
    BOARD = 0.018
    PLINTH = 0.04
    CENTER_H = 0.1   # centre drawer compartment height (m)

    KNEE = 0.6  # the least knee space between pedestals (m)

    def _style(self, p) -> str:
        """The base style, a double pedestal becoming a single one where the desk is too
        narrow to leave knee space between two."""
        if p["base_style"] == "double_pedestal" and p["width"] < 2 * p["pedestal_width"] + self.KNEE:
            return "single_pedestal"
        return p["base_style"]

    def _pedestals(self, p) -> list[tuple[float, float]]:
        """(y0, y1) of each pedestal."""
        W, pw = p["width"], p["pedestal_width"]
        style = self._style(p)
        if style == "double_pedestal":
            return [(-W / 2, -W / 2 + pw), (W / 2 - pw, W / 2)]
        if style == "single_pedestal":
            return [(W / 2 - pw, W / 2)] if p["pedestal_side"] == "left" else [(-W / 2, -W / 2 + pw)]
        return []

    def _knee(self, p) -> tuple[float, float]:
        """The knee space's y range (between the supports' inner faces)."""
        W, lt = p["width"], p["leg_thickness"]
        peds = self._pedestals(p)
        y0, y1 = -W / 2 + 0.03 + lt, W / 2 - 0.03 - lt
        if self._style(p) == "single_pedestal":
            y0, y1 = (-W / 2 + 0.03, W / 2 - 0.03)
        for a, b in peds:
            if a > 0:
                y1 = a
            else:
                y0 = b
        return y0, y1

    def _front_x(self, p) -> float:
        return p["depth"] / 2 - FRONT_PROUD - 0.005

    def _fronts(self, p):
        """(parts, motion) of every drawer and each drawer's depth."""
        D, h, tt, t = p["depth"], p["height"], p["top_thickness"], self.BOARD
        xf = self._front_x(p)
        x0 = -D / 2 + 0.02
        z_under = h - tt
        out = []
        n = int(p["n_drawers"])
        for k, (y0, y1) in enumerate(self._pedestals(p)):
            zb, zt = self.PLINTH + t, z_under
            step = (zt - zb) / n
            cells = [Front(y0 + t, y1 - t, zb + i * step, zb + (i + 1) * step,
                           "drawer") for i in range(n)]
            depth = xf - x0 - 0.006 - 0.02
            out += [(f, depth) for f in cabinet_fronts(xf, cells, depth, prefix=f"p{k}_")]
        if p["center_drawer"]:
            ky0, ky1 = self._knee(p)
            w, yc = min(0.6, ky1 - ky0 - 0.1), (ky0 + ky1) / 2
            cells = [Front(yc - w / 2 + t, yc + w / 2 - t, z_under - self.CENTER_H + t, z_under,
                           "drawer")]
            depth = min(0.4, xf - x0 - 0.03)
            out += [(f, depth) for f in cabinet_fronts(xf, cells, depth, prefix="c_")]
        return out

    def parts(self, p, detail):
        W, D, h, tt = p["width"], p["depth"], p["height"], p["top_thickness"]
        t, lt = self.BOARD, p["leg_thickness"]
        z_under = h - tt
        xf, x0 = self._front_x(p), -D / 2 + 0.02
        out = [Part(bevel_box((D, W, tt), (0, 0, h - tt / 2), 0.004, 2) if detail else
                    box((D, W, tt), (0, 0, h - tt / 2)), "wood")]
        for y0, y1 in self._pedestals(p):
            pd, pw = xf - x0, y1 - y0
            ctr = ((xf + x0) / 2, (y0 + y1) / 2, 0.0)
            if detail:
                out += _translate(carcass(pd, pw, self.PLINTH, z_under + OVERLAP, t, back=0.006,
                                          top=False), ctr)
            else:
                out.append(board((x0, y0, self.PLINTH), (D / 2 - 0.005, y1, z_under + OVERLAP), "front"))
            out.append(board((x0 + 0.01, y0 + 0.01, 0.0), (xf - 0.03, y1 - 0.01, self.PLINTH + OVERLAP),
                              "wood"))
        style = self._style(p)
        if style == "legs":
            for leg in legs((D, W), 0.03, lt, 0.0, z_under + OVERLAP, taper=0.8 if detail else 1.0):
                out.append(Part(leg, "wood"))
            cx, cy = D / 2 - 0.03 - lt / 2, W / 2 - 0.03 - lt / 2
            ah = 0.07
            for s in (-1, 1):  # side aprons and the back apron
                out.append(board((-cx, s * cy - 0.01, z_under - ah),
                                  (cx, s * cy + 0.01, z_under + OVERLAP), "wood"))
            out.append(board((-cx - 0.01, -cy, z_under - ah), (-cx + 0.01, cy, z_under + OVERLAP),
                              "wood"))
        elif style == "single_pedestal":
            s = -1 if p["pedestal_side"] == "left" else 1
            ya, yb = sorted((s * W / 2, s * (W / 2 - 0.03)))
            out.append(board((-D / 2 + 0.02, ya, 0.0), (D / 2 - 0.02, yb, z_under + OVERLAP), "wood"))
        ky0, ky1 = self._knee(p)
        if p["modesty_panel"]:
            # against the carcasses' back panels (no sealed gap between them)
            out.append(board((-D / 2 + 0.02, ky0 - OVERLAP, z_under - 0.35),
                              (-D / 2 + 0.04, ky1 + OVERLAP, z_under + OVERLAP), "wood"))
        if p["center_drawer"]:
            w, yc = min(0.6, ky1 - ky0 - 0.1), (ky0 + ky1) / 2
            zc = z_under - self.CENTER_H
            if detail:
                cd = carcass(xf - x0, w, zc, z_under + OVERLAP, t, back=0.006, top=False)
                out += _translate(cd, ((xf + x0) / 2, yc, 0.0))
            else:
                out.append(board((x0, yc - w / 2, zc), (D / 2 - 0.005, yc + w / 2, z_under + OVERLAP),
                                  "front"))
        if detail:
            for parts, _ in (f for f, _ in self._fronts(p)):
                out += parts
        if p["hutch"]:
            out += self._hutch(p, detail)
        return out

    def _hutch_depth(self, p) -> float:
        return min(0.3, 0.4 * p["depth"])

    def _hutch(self, p, detail) -> list[Part]:
        W, D, h, hh = p["width"], p["depth"], p["height"], p["hutch_height"]
        t, hd = self.BOARD, self._hutch_depth(p)
        x0, x1 = -D / 2, -D / 2 + hd
        z0, z1 = h - OVERLAP, h + hh
        out = [board((x0, -W / 2, z1 - t), (x1, W / 2, z1), "wood"),
               board((x0, -W / 2 + t - OVERLAP, z0),
                      (x0 + 0.008, W / 2 - t + OVERLAP, z1 - t + OVERLAP), "back")]
        for s in (-1, 1):
            ya, yb = sorted((s * W / 2, s * (W / 2 - t)))
            out.append(board((x0, ya, z0), (x1, yb, z1 - t + OVERLAP), "wood"))
        return out

    def joints(self, p):
        return [make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth) for (_, m), depth in self._fronts(p)]

    def extra_surfaces(self, p):
        W, D, h = p["width"], p["depth"], p["height"]
        x0 = -D / 2 + (self._hutch_depth(p) + 0.01 if p["hutch"] else 0.02)
        x1 = D / 2 - 0.02
        out = [support_rect("top", ((x0 + x1) / 2, 0, h), (x1 - x0) / 2, W / 2 - 0.02),
               Surface.rect("side_0", Subpart.Side, (D / 2, 0, h / 2), (1, 0, 0), (0, 1, 0), W / 2,
                            h / 2)]
        if p["hutch"]:
            hd = self._hutch_depth(p)
            out.append(support_rect("hutch_top", (-D / 2 + hd / 2, 0, h + p["hutch_height"]),
                                    hd / 2 - 0.02,
                                    W / 2 - 0.02))
        return out


# ============================================================================== console table
@register
class ConsoleTable(PartsFactory):
    """A narrow hall / sofa table: a top on four straight, tapered or round legs or on two slab
    ends, with an apron holding 0-3 drawers (articulated) and an optional lower shelf (a
    support surface, `shelf`)."""

    name = "console_table"
    tags = frozenset({S.Object, S.Furniture, S.Table, S.ConsoleTable})
    size_class = "large"
    slots = ["wood", "front", "metal"]
    params = {
        "width": Param(0.8, 1.6, doc="Y extent (m)"),
        "depth": Param(0.25, 0.45, doc="X extent (m)"),
        "height": Param(0.72, 0.85, doc="height of the top's upper face (m)"),
        "top_thickness": Param(0.02, 0.045, doc="top thickness (m)"),
        "edge_radius": Param(0.0, 0.008, doc="rounding of the top's edges (m)"),
        "leg_style": Param(kind="choice", choices=("straight", "tapered", "round", "panel"),
                           doc="leg shape, or two slab ends"),
        "leg_thickness": Param(0.03, 0.05, doc="leg section / slab-end thickness (m)"),
        "lower_shelf": Param(kind="bool", doc="add a shelf near the floor"),
        "shelf_height": Param(0.12, 0.3, doc="height of the lower shelf's upper face (m)"),
        "n_drawers": Param(0, 3, kind="int", doc="drawers in the apron"),
        "apron_height": Param(0.08, 0.14, doc="apron height under the top (m)"),
    }
    INSET = 0.02
    BOARD = 0.016

    def _carcass_span(self, p) -> tuple[float, float, float, float]:
        """x0, x_front, y0, y1 of the apron's drawer carcass."""
        D, W, lt = p["depth"], p["width"], p["leg_thickness"]
        xf = D / 2 - FRONT_PROUD - 0.005
        x0 = -D / 2 + self.INSET
        yi = W / 2 - self.INSET - lt + OVERLAP  # between the legs' (or ends') inner faces
        return x0, xf, -yi, yi

    def _fronts(self, p):
        n = int(p["n_drawers"])
        if n == 0:
            return [], 0.0
        h, tt, ah, t = p["height"], p["top_thickness"], p["apron_height"], self.BOARD
        x0, xf, y0, y1 = self._carcass_span(p)
        z0, z1 = h - tt - ah + t, h - tt
        inner0, inner1 = y0 + t, y1 - t
        cw = (inner1 - inner0 - (n - 1) * t) / n
        cells = [Front(inner0 + i * (cw + t), inner0 + i * (cw + t) + cw, z0, z1,
                       "drawer") for i in range(n)]
        depth = xf - x0 - 0.006 - 0.02
        return cabinet_fronts(xf, cells, depth), depth

    def _table_params(self, p) -> dict[str, Any]:
        return {"height": p["height"], "top_thickness": p["top_thickness"],
                "edge_radius": p["edge_radius"],
                "leg_thickness": p["leg_thickness"], "leg_inset": self.INSET, "leg_style": p["leg_style"],
                "apron_height": p["apron_height"], "lower_shelf": p["lower_shelf"],
                "shelf_height": p["shelf_height"], "stretchers": False}

    def parts(self, p, detail):
        D, W, h, tt = p["depth"], p["width"], p["height"], p["top_thickness"]
        lt, t = p["leg_thickness"], self.BOARD
        n = int(p["n_drawers"])
        if p["leg_style"] != "panel":
            out = rect_table_parts(self._table_params(p), detail, D, W, apron=n == 0)
        else:
            er = p["edge_radius"]
            out = [Part(bevel_box((D, W, tt), (0, 0, h - tt / 2), er, 2) if detail and er > 1e-4
                        else box((D, W, tt), (0, 0, h - tt / 2)), "wood")]
            for s in (-1, 1):
                ya, yb = sorted((s * (W / 2 - self.INSET), s * (W / 2 - self.INSET - lt)))
                out.append(board((-D / 2 + self.INSET, ya, 0.0),
                                  (D / 2 - self.INSET, yb, h - tt + OVERLAP), "wood"))
            if p["lower_shelf"]:
                yi = W / 2 - self.INSET - lt + OVERLAP
                zs = p["shelf_height"]
                out.append(board((-D / 2 + self.INSET, -yi, zs - 0.018), (D / 2 - self.INSET, yi, zs),
                                  "wood"))
            if n == 0:  # a back apron stiffening the ends
                yi = W / 2 - self.INSET - lt + OVERLAP
                out.append(board((-D / 2 + self.INSET, -yi, h - tt - p["apron_height"]),
                                  (-D / 2 + self.INSET + 0.02, yi, h - tt + OVERLAP), "wood"))
        if n:
            x0, xf, y0, y1 = self._carcass_span(p)
            z0 = h - tt - p["apron_height"]
            if detail:
                inner0, inner1 = y0 + t, y1 - t
                cw = (inner1 - inner0 - (n - 1) * t) / n
                dividers = [inner0 + i * (cw + t) - t / 2 for i in range(1, n)]
                cc = carcass(xf - x0, y1 - y0, z0, h - tt + OVERLAP, t, back=0.006, dividers=dividers,
                             top=False)
                out += _translate(cc, ((xf + x0) / 2, (y0 + y1) / 2, 0.0))
                fronts, _ = self._fronts(p)
                for parts, _ in fronts:
                    out += parts
            else:
                out.append(board((x0, y0, z0), (D / 2 - 0.005, y1, h - tt + OVERLAP), "front"))
        return out

    def joints(self, p):
        fronts, depth = self._fronts(p)
        return _drawer_joints(fronts, depth)

    def extra_surfaces(self, p):
        D, W, h, lt = p["depth"], p["width"], p["height"], p["leg_thickness"]
        out = [support_rect("top", (0, 0, h), D / 2 - 0.02, W / 2 - 0.02)]
        if p["lower_shelf"]:
            if p["leg_style"] == "panel":
                hx, hy = D / 2 - self.INSET - 0.01, W / 2 - self.INSET - lt - 0.01
            else:  # the shelf spans between the legs' centre lines; keep clear of the legs
                hx = D / 2 - self.INSET - lt - 0.01
                hy = W / 2 - self.INSET - lt - 0.01
            out.append(support_rect("shelf", (0, 0, p["shelf_height"]), hx, hy))
        return out
