"""Staircases (straight, L, U, spiral) and a free-standing balustrade segment.

A straight flight climbs toward +X from its bottom riser at the -X end; L and U stairs turn at a
quarter / half landing; a spiral winds around a central column. Every flight has n risers of one
height r (0.15-0.20 m, the count computed from the total rise) and n-1 treads of one going; its
last riser arrives at the upper floor (or a landing), so the treads' tops are at r, 2r, ...,
(n-1)r above the bottom. Each tread's walkable top is a support surface ``tread_i`` (numbered
bottom to top) and each landing's ``landing_i``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.architectural import (
    MEMBER_OVERLAP,
    baluster,
    baluster_positions,
    handrail,
    hull,
    post,
    prism,
)
from indoorgen.assets.shapes.primitives import Part, box_between, cylinder, rod
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

RISER_MIN, RISER_MAX = 0.15, 0.20
#: newel post size (m)
POST = 0.09
#: riser board thickness (m)
RISER_T = 0.02
#: depth of the beams under a landing's edges (m)
BEAM = 0.15
#: gap between the two flights of a U stair (m)
WELL = 0.12
#: baluster spacing (m)
SPACING = 0.11
#: central column radius of a spiral stair (m)
COLUMN = 0.075

STAIR_MATERIALS = {"frame": {"painted_wood": 3.0, "oak": 1.0, "painted_metal": 1.5, "brushed_steel": 0.5},
                   "metal": {"painted_metal": 2.0, "brushed_steel": 2.0, "chrome": 0.5},
                   "wood": {"oak": 3.0, "walnut": 1.5, "pine_planks": 1.0, "painted_wood": 0.7}}


def riser_count(rise: float, target: float) -> int:
    """Risers for a storey of height `rise` (m): rise/target rounded, kept so that each riser is
    RISER_MIN..RISER_MAX high."""
    lo = math.ceil(rise / RISER_MAX - 1e-9)
    hi = math.floor(rise / RISER_MIN + 1e-9)
    return int(min(max(round(rise / target), lo), hi))


def rail_style(baluster_style: str) -> str:
    """Turned and square balusters carry a moulded flat handrail, rods and glass a round one."""
    return "flat" if baluster_style in ("spindle", "square") else "round"


@dataclass(frozen=True)
class Flight:
    """One straight flight of `n` risers starting at level z0, climbing along quarter-turn
    `quarter` (0 +X, 1 +Y, 2 -X, 3 -Y) from its first riser's face centred at (ox, oy)."""

    n: int
    z0: float
    quarter: int
    ox: float
    oy: float
    start_floor: bool
    end_floor: bool

    def rotation(self) -> np.ndarray:
        """The flight's turn about Z (its quarter), as a 3x3 matrix."""
        c, s = [(1, 0), (0, 1), (-1, 0), (0, -1)][self.quarter % 4]
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]], float)

    def place(self, solid: m3d.Manifold) -> m3d.Manifold:
        """A solid built in the flight's own frame, turned and moved to where the flight is."""
        return solid.rotate((0.0, 0.0, 90.0 * self.quarter)).translate((self.ox, self.oy, 0.0))

    def point(self, x: float, y: float, z: float = 0.0) -> np.ndarray:
        """A point of the flight's own frame in the staircase's frame."""
        return self.rotation() @ np.array([x, y, z]) + np.array([self.ox, self.oy, 0.0])


@register
class Staircase(PartsFactory):
    """A one-storey staircase: straight, L-shaped (quarter landing), U-shaped (half landing) or
    spiral. Treads (with a nosing) on closed stringers (boards along the sides, treads housed
    between) or cut stringers (sawtooth, under the treads), open or closed risers, and on the
    open side(s) a balustrade of round, square or turned balusters or glass panels under a
    handrail between newel posts; landings stand on posts and carry their own railing on the
    open side. Riser height is derived from the total rise (0.15-0.20 m, uniform). Surfaces:
    ``tread_i`` per tread and ``landing_i`` per landing (support surfaces)."""

    name = "staircase"
    tags = frozenset({S.Object, S.Architecture, S.Staircase})
    size_class = "large"
    slots = ["wood", "frame", "metal", "glass"]
    material_choices = STAIR_MATERIALS
    params = {
        "style": Param(kind="choice", choices=("straight", "l_shaped", "u_shaped", "spiral"),
                       doc="plan shape"),
        "total_rise": Param(2.4, 3.6, doc="floor-to-floor height climbed (m)"),
        "riser_target": Param(0.16, 0.19, doc="preferred riser height (m); the count is the rise "
                                              "over it, rounded, then kept in 0.15-0.20 m"),
        "going": Param(0.22, 0.32, doc="tread depth nosing to nosing (m; a spiral's at its "
                                       "walking line, mid-tread)"),
        "width": Param(0.8, 1.3, doc="flight width (m; a spiral's tread length)"),
        "closed_risers": Param(kind="bool", doc="riser boards between treads"),
        "railing_side": Param(kind="choice", choices=("both", "left", "right"),
                              doc="open side(s) with a balustrade, seen climbing"),
        "turn": Param(kind="choice", choices=("left", "right"), doc="turning direction (L, U, spiral)"),
        "tread_thickness": Param(0.03, 0.05, doc="tread thickness (m)"),
        "nosing": Param(0.0, 0.03, doc="tread overhang past the riser below (m)"),
        "stringer": Param(kind="choice", choices=("closed", "cut"), doc="stringer type"),
        "baluster_style": Param(kind="choice", choices=("round", "square", "spindle", "glass"),
                                doc="balustrade infill"),
        "handrail_height": Param(0.85, 1.0, doc="handrail height above the nosings (m)"),
        "landing_split": Param(0.35, 0.65, doc="share of the risers below the landing (L, U)"),
    }

    # ------------------------------------------------------------------ layout
    def _g(self, p: dict[str, Any]) -> dict[str, Any]:
        n = riser_count(p["total_rise"], p["riser_target"])
        r, go, w, nos = p["total_rise"] / n, p["going"], p["width"], p["nosing"]
        style, s = p["style"], (1 if p["turn"] == "left" else -1)
        flights, landings = [], []
        left = p["railing_side"] in ("both", "left")
        right = p["railing_side"] in ("both", "right")
        if style == "straight":
            flights = [Flight(n, 0.0, 0, 0.0, 0.0, True, True)]
        elif style in ("l_shaped", "u_shaped"):
            n1 = int(min(max(round(n * p["landing_split"]), 3), n - 3))
            xa, zl = (n1 - 1) * go, n1 * r
            flights.append(Flight(n1, 0.0, 0, 0.0, 0.0, True, False))
            if style == "l_shaped":
                flights.append(Flight(n - n1, zl, 1 if s > 0 else 3, xa + w / 2, s * w / 2, False, True))
                ys = sorted((-s * w / 2, s * w / 2))
            else:
                yc = s * (w + WELL)
                flights.append(Flight(n - n1, zl, 2, xa - nos, yc, False, True))
                ys = sorted((-s * w / 2, yc + s * w / 2))
            landings.append({"x0": xa - nos, "x1": xa + w, "y0": ys[0], "y1": ys[1], "z": zl})
        return {"n": n, "r": r, "go": go, "w": w, "nos": nos, "tt": p["tread_thickness"], "s": s,
                "hh": p["handrail_height"], "flights": flights, "landings": landings,
                "left": left, "right": right, "closed": p["stringer"] == "closed",
                "outer_railed": right if s > 0 else left, "inner_railed": left if s > 0 else right}

    # ---------------------------------------------------------- flight pieces
    @staticmethod
    def _pitch(g, fl: Flight):
        """The nosing line P(x) of a flight, in its frame."""
        r, go, nos = g["r"], g["go"], g["nos"]
        return lambda x: fl.z0 + r + (x + nos) * r / go

    def _ends(self, g, fl: Flight) -> tuple[float, float, float, float]:
        """(x start, x end, z bottom cut, z top clip) of a flight's stringers, in its frame."""
        go, n = g["go"], fl.n
        x_s = -g["nos"] - POST if fl.start_floor else -0.06
        x_e = (n - 1) * go + (RISER_T if fl.end_floor else 0.06)
        z_cut = fl.z0 if fl.start_floor else fl.z0 - BEAM
        return x_s, x_e, z_cut, fl.z0 + n * g["r"]

    def _stringer_profile(self, g, fl: Flight, closed: bool) -> np.ndarray:
        """A stringer's (x, z) outline in its flight's frame."""
        r, go, tt, nos, n, z0 = g["r"], g["go"], g["tt"], g["nos"], fl.n, fl.z0
        P = self._pitch(g, fl)
        x_s, x_e, z_cut, z_top = self._ends(g, fl)
        if closed:
            b = r + tt + nos * r / go + 0.1
            band = [(x_s, P(x_s) - b), (x_e, P(x_e) - b), (x_e, P(x_e) + 0.06), (x_s, P(x_s) + 0.06)]
            return _clip_z(band, z_cut, z_top)
        b2 = r + tt + nos * r / go + 0.12
        top = [(0.0, z0 + r - tt + MEMBER_OVERLAP)] if fl.start_floor else \
            [(-0.06, z0 - 0.01), (0.0, z0 - 0.01), (0.0, z0 + r - tt + MEMBER_OVERLAP)]
        for i in range(n - 1):
            top.append(((i + 1) * go, z0 + (i + 1) * r - tt + MEMBER_OVERLAP))
            if i < n - 2:
                top.append(((i + 1) * go, z0 + (i + 2) * r - tt + MEMBER_OVERLAP))
        z_end = z0 + n * r - tt + (0.0 if fl.end_floor else MEMBER_OVERLAP)
        top += [((n - 1) * go, z_end), (x_e, z_end)]
        outline = sg.Polygon(top + [(x_e, z_cut - 10), (top[0][0], z_cut - 10)])
        below = sg.Polygon([(x_s - 1, P(x_s - 1) - b2), (x_e + 1, P(x_e + 1) - b2), (x_e + 1, 1e3),
                            (x_s - 1, 1e3)])
        cut = outline.intersection(below).intersection(sg.box(-10, z_cut, 100, 1e3))
        return np.asarray(cut.exterior.coords)[:-1]

    def _rail_y(self, g, side: int) -> float:
        """The balustrade's centre line (flight frame y) on `side` (+1 left, -1 right)."""
        return side * (g["w"] / 2 - (0.02 if g["closed"] else 0.035))

    def _flight(self, p, g, fl: Flight) -> list[Part]:
        """Treads, risers, stringers and balustrades of one flight, in its frame."""
        r, go, w, tt, nos, n, z0 = g["r"], g["go"], g["w"], g["tt"], g["nos"], fl.n, fl.z0
        closed = g["closed"]
        sw = 0.04
        ty = w / 2 - sw + 0.01 if closed else w / 2
        out = []
        for i in range(n - 1):
            z = z0 + (i + 1) * r
            x1 = (i + 1) * go + (RISER_T if p["closed_risers"] or i == n - 2 else 0.0)
            out.append(Part(box_between((i * go - nos, -ty, z - tt), (x1, ty, z)), "wood"))
        if p["closed_risers"]:
            for j in range(n):
                zb = z0 if j == 0 else z0 + j * r - MEMBER_OVERLAP
                zt = z0 + (j + 1) * r - tt + MEMBER_OVERLAP
                if j == n - 1:
                    zt = z0 + n * r if fl.end_floor else z0 + n * r - tt + MEMBER_OVERLAP
                out.append(Part(box_between((j * go, -ty, zb), (j * go + RISER_T, ty, zt)), "frame"))
        prof = self._stringer_profile(g, fl, closed)
        ys = [(w / 2 - sw, w / 2), (-w / 2, -w / 2 + sw)] if closed else \
            [(w / 2 - 0.095, w / 2 - 0.045), (-w / 2 + 0.045, -w / 2 + 0.095)] + \
            ([(-0.025, 0.025)] if w > 1.0 else [])
        out += [Part(prism(prof, y0, y1, "y"), "frame") for y0, y1 in ys]
        for side, on in ((1, g["left"]), (-1, g["right"])):
            if on:
                out += self._flight_rail(p, g, fl, side)
        return out

    def _flight_rail(self, p, g, fl: Flight, side: int) -> list[Part]:
        """Newels at both ends, a handrail along the pitch and the infill, on one side."""
        r, go, tt, nos, n, z0, hh = g["r"], g["go"], g["tt"], g["nos"], fl.n, fl.z0, g["hh"]
        P = self._pitch(g, fl)
        x_s, x_e, z_cut, z_top = self._ends(g, fl)
        y = self._rail_y(g, side)
        style = p["baluster_style"]
        xb, xt = -nos - POST / 2, (n - 1) * go + POST / 2
        zb_post = z_cut if fl.start_floor else z0 - tt
        zt_post = z0 + n * r - tt - (0.25 if fl.end_floor else 0.0)
        out = [Part(post(xb, y, zb_post, P(xb) + hh + 0.08, POST), "frame"),
               Part(post(xt, y, zt_post, P(xt) + hh + 0.08, POST), "frame"),
               Part(handrail((xb, y, P(xb) + hh), (xt, y, P(xt) + hh), rail_style(style)), "wood")]
        a0, a1 = xb + POST / 2, xt - POST / 2
        if style == "glass":
            a0, a1 = a0 - MEMBER_OVERLAP, a1 + MEMBER_OVERLAP  # into the newels, not flush with them
            if g["closed"]:
                xk = min(max((z_top - 0.06 - z0 - r) * go / r - nos, a0), a1)
                bottom = [(a0, P(a0) + 0.045), (xk, P(xk) + 0.045), (a1, min(P(a1) + 0.045, z_top - 0.015))]
            else:
                bottom = [(a0, P(a0) - 0.01), (a1, P(a1) - 0.01)]
            pts = [q for k, q in enumerate(bottom) if k == 0 or abs(q[0] - bottom[k - 1][0]) > 1e-4]
            pts += [(a1, P(a1) + hh - 0.03), (a0, P(a0) + hh - 0.03)]
            out.append(Part(prism(pts, y - 0.006, y + 0.006, "y"), "glass"))
            return out
        slot = "wood" if style == "spindle" else "metal"
        if g["closed"]:
            xs = a0 + baluster_positions(a1 - a0, SPACING, 0.05)
            bases = [min(P(x) + 0.06, z_top) - 0.02 for x in xs]
        else:
            xs, bases = [], []
            for i in range(n - 1):
                for k in (0.25, 0.75):
                    xs.append(i * go - nos + k * (go + nos))
                    bases.append(z0 + (i + 1) * r - 0.005)
        out += [Part(baluster(x, y, zb, P(x) + hh - 0.02, style), slot)
                for x, zb in zip(xs, bases, strict=True)]
        return out

    # ---------------------------------------------------------------- landings
    def _landing(self, p, g, lg: dict) -> list[Part]:
        """A platform on edge beams and corner posts, with a railing on its open edges."""
        x0, x1, y0, y1, z = lg["x0"], lg["x1"], lg["y0"], lg["y1"], lg["z"]
        tt, hh = g["tt"], g["hh"]
        out = [Part(box_between((x0, y0, z - tt), (x1, y1, z)), "wood")]
        beams = [box_between((x0, y0, z - BEAM), (x1, y0 + 0.05, z - tt + MEMBER_OVERLAP)),
                 box_between((x0, y1 - 0.05, z - BEAM), (x1, y1, z - tt + MEMBER_OVERLAP)),
                 box_between((x0, y0, z - BEAM), (x0 + 0.05, y1, z - tt + MEMBER_OVERLAP)),
                 box_between((x1 - 0.05, y0, z - BEAM), (x1, y1, z - tt + MEMBER_OVERLAP))]
        out += [Part(b, "frame") for b in beams]
        runs = self._landing_runs(g, lg)
        tall = {tuple(np.round(c, 6)) for run in runs for c in run}
        for c in self._landing_corners(lg):
            top = z + hh + 0.08 if tuple(np.round(c, 6)) in tall else z - tt + MEMBER_OVERLAP
            out.append(Part(post(c[0], c[1], 0.0, top, POST, 0.0, top > z), "frame"))
        style = p["baluster_style"]
        for a, b in runs:
            out += self._level_rail(style, a, b, z, hh)
        return out

    @staticmethod
    def _landing_corners(lg) -> list[np.ndarray]:
        h = POST / 2
        return [np.array(c) for c in ((lg["x0"] + h, lg["y0"] + h), (lg["x1"] - h, lg["y0"] + h),
                                      (lg["x1"] - h, lg["y1"] - h), (lg["x0"] + h, lg["y1"] - h))]

    def _landing_runs(self, g, lg) -> list[tuple[np.ndarray, np.ndarray]]:
        """Railing runs (post centre to post centre) along the landing's open outer edges (the
        ones the outer side of the flights continues along) and, on a U stair, across the well
        between the flights' inner newels."""
        runs = []
        f1, f2 = g["flights"]
        if g["inner_railed"] and f2.quarter == 2:
            side = g["s"]
            y = self._rail_y(g, side)
            runs.append((f1.point((f1.n - 1) * g["go"] + POST / 2, y)[:2],
                         f2.point(-g["nos"] - POST / 2, y)[:2]))
        if not g["outer_railed"]:
            return runs
        c = self._landing_corners(lg)
        near, far = (0, 3) if g["s"] > 0 else (3, 0)  # the outer long edge is at low y for a left turn
        a, b = c[near], c[1 if g["s"] > 0 else 2]
        d = c[2 if g["s"] > 0 else 1]
        runs += [(a, b), (b, d)]
        if f2.quarter == 2:  # U: the far short edge too
            runs.append((d, c[far]))
        return runs

    def _level_rail(self, style: str, a: np.ndarray, b: np.ndarray, z: float, hh: float) -> list[Part]:
        """A level balustrade from post centre a to b on a floor at height z."""
        d = b - a
        L = float(np.linalg.norm(d))
        u = d / L
        yaw = math.degrees(math.atan2(u[1], u[0]))
        p0, p1 = np.r_[a, z + hh], np.r_[b, z + hh]
        out = [Part(handrail(p0, p1, rail_style(style)), "wood")]
        if style == "glass":
            q0, q1 = a + u * (POST / 2 - MEMBER_OVERLAP), b - u * (POST / 2 - MEMBER_OVERLAP)
            pts = [(x, y, zz) for x, y in (q0, q1) for zz in (z - 0.01, z + hh - 0.03)]
            n = np.array([-u[1], u[0]]) * 0.006
            out.append(Part(hull([(x + sx * n[0], y + sx * n[1], zz) for x, y, zz in pts for sx in (-1, 1)]),
                            "glass"))
            return out
        ts = baluster_positions(L, SPACING, POST / 2 + 0.05)
        slot = "wood" if style == "spindle" else "metal"
        out += [Part(baluster(a[0] + u[0] * t, a[1] + u[1] * t, z - 0.005, z + hh - 0.02, style, yaw), slot)
                for t in ts]
        return out

    # ------------------------------------------------------------------ spiral
    def _spiral_g(self, g) -> dict[str, float]:
        w = g["w"]
        R = COLUMN + w
        r_walk = COLUMN + w / 2
        alpha = g["go"] / r_walk
        return {"R": R, "rw": r_walk, "alpha": alpha, "nos_a": g["nos"] / r_walk, "ry": R - 0.05}

    def _spiral_angle(self, g, sg_, i: float) -> float:
        """Angle (rad, signed by the turn) of the front of tread i (without nosing)."""
        return g["s"] * i * sg_["alpha"]

    @staticmethod
    def _sector(a0: float, a1: float, r0: float, r1: float, circumscribed: bool = False,
                step: float = math.radians(8.0)) -> np.ndarray:
        """Plan outline of an annular sector between angles a0 < a1 (radii r0 < r1; r0 = 0 gives
        a pie slice), its arcs in <= `step` steps; circumscribed: the outer arc's polygon
        pushed out so that it contains the true arc."""
        k = max(2, int(math.ceil(abs(a1 - a0) / step)))
        t = np.linspace(a0, a1, k + 1)
        f = 1.0 / math.cos(abs(a1 - a0) / k / 2) if circumscribed else 1.0
        outer = np.stack([np.cos(t), np.sin(t)], axis=1) * (r1 * f)
        inner = outer[::-1] * (r0 / (r1 * f)) if r0 > 0 else np.zeros((1, 2))
        return np.vstack([outer, inner])

    def _spiral(self, p, g) -> list[Part]:
        """Column, pie-slice treads (nosing overlapping the step below), radial risers and the
        outer balustrade."""
        n, r, tt, s = g["n"], g["r"], g["tt"], g["s"]
        q = self._spiral_g(g)
        out = [Part(cylinder(COLUMN, n * r, (0.0, 0.0, 0.0), 24), "frame")]
        for i in range(n - 1):
            out.append(Part(prism(self._tread_outline(g, q, i), (i + 1) * r - tt, (i + 1) * r), "wood"))
        if p["closed_risers"]:
            for j in range(n - 1):
                a = self._spiral_angle(g, q, j)
                out.append(Part(prism(self._riser_footprint(a, s, q["R"] - 0.02),
                                      j * r - (MEMBER_OVERLAP if j else 0.0),
                                      (j + 1) * r - tt + MEMBER_OVERLAP), "frame"))
        out += self._spiral_rail(p, g, q)
        return out

    @staticmethod
    def _riser_footprint(a: float, s: int, r1: float) -> np.ndarray:
        """Plan outline of a spiral riser board along the radius at angle a, on the lower step's
        side of it, from inside the column to radius r1."""
        c, sn = math.cos(a), math.sin(a)
        radial, tang = np.array([c, sn]), np.array([-sn, c]) * (-s) * RISER_T
        r0 = COLUMN * 0.5
        return np.array([radial * r0, radial * r1, radial * r1 + tang, radial * r0 + tang])

    def _spiral_rail_height(self, g, q, a: float) -> float:
        """Handrail top height at signed angle a: hh above the nosing line."""
        return g["r"] * (1 + (a * g["s"] + q["nos_a"]) / q["alpha"]) + g["hh"]

    def _spiral_posts(self, g, q) -> list[tuple[float, float, float]]:
        """(angle, bottom, top) of the newels at the balustrade's ends: on the floor before the
        first tread and on the last tread."""
        n, r, tt, s, ry = g["n"], g["r"], g["tt"], g["s"], q["ry"]
        a_start = -s * (q["nos_a"] + POST / 2 / ry)
        a_end = s * ((n - 1) * q["alpha"] - POST / 2 / ry)
        return [(a, z0, self._spiral_rail_height(g, q, a) + 0.08)
                for a, z0 in ((a_start, 0.0), (a_end, (n - 1) * r - tt))]

    def _tread_outline(self, g, q, i: int) -> np.ndarray:
        """Plan outline of spiral tread i: a pie slice from its nosing to the next tread."""
        a, s = self._spiral_angle(g, q, i), g["s"]
        lo, hi = sorted((a - s * q["nos_a"], a + s * q["alpha"]))
        return self._sector(lo, hi, 0.0, q["R"], step=math.radians(12.0))

    def _spiral_rail(self, p, g, q) -> list[Part]:
        """The outer balustrade: a round handrail in short straight pieces along the helix,
        newels at its ends, and two balusters (or a glass panel) per tread."""
        n, r, s = g["n"], g["r"], g["s"]
        ry, style = q["ry"], p["baluster_style"]
        (a_start, _, _), (a_end, _, _) = self._spiral_posts(g, q)
        k = max(2, int(math.ceil(abs(a_end - a_start) / math.radians(12.0))))
        angles = np.linspace(a_start, a_end, k + 1)
        pts = [np.array([ry * math.cos(a), ry * math.sin(a),
                         self._spiral_rail_height(g, q, a)]) for a in angles]
        segs = []
        for p0, p1 in zip(pts[:-1], pts[1:], strict=True):
            d = (p1 - p0) / np.linalg.norm(p1 - p0) * 0.012
            segs.append(rod(p0 - d - (0, 0, 0.0225), p1 + d - (0, 0, 0.0225), 0.0225, 12))
        out = [Part(seg, "wood") for seg in segs]
        for a, z0, z1 in self._spiral_posts(g, q):
            out.append(Part(post(ry * math.cos(a), ry * math.sin(a), z0, z1, POST, math.degrees(a)), "frame"))
        infill = []
        for i in range(n - 1):
            a = self._spiral_angle(g, q, i)
            zt = (i + 1) * r
            if style == "glass":
                b0, b1 = a + s * 0.03, a + s * (q["alpha"] - 0.03)
                corners = []
                for b in (b0, b1):
                    c = np.array([math.cos(b), math.sin(b)])
                    for dr in (-0.006, 0.006):
                        for z in (zt - 0.005, self._spiral_rail_height(g, q, b) - 0.03):
                            corners.append(((ry + dr) * c[0], (ry + dr) * c[1], z))
                infill.append(hull(corners))
                continue
            for f in (0.3, 0.75):
                b = a + s * f * q["alpha"]
                infill.append(baluster(ry * math.cos(b), ry * math.sin(b), zt - 0.005,
                                       self._spiral_rail_height(g, q, b) - 0.02, style, math.degrees(b)))
        slot = "glass" if style == "glass" else "wood" if style == "spindle" else "metal"
        out += [Part(q, slot) for q in infill]
        return out

    # ------------------------------------------------------------------- parts
    def parts(self, p, detail):
        """The staircase's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        if p["style"] == "spiral":
            return self._spiral(p, g) if detail else self._spiral_cheap(p, g)
        out: list[Part] = []
        for fl in g["flights"]:
            pieces = self._flight(p, g, fl) if detail else self._flight_cheap(p, g, fl)
            out += [Part(fl.place(q.solid), q.slot) for q in pieces]
        for lg in g["landings"]:
            out += self._landing(p, g, lg) if detail else self._landing_cheap(p, g, lg)
        return out

    def _flight_cheap(self, p, g, fl: Flight) -> list[Part]:
        """Blocks under the steps (two steps each), and per side a hull round the stringer,
        balustrade and newels."""
        r, go, w, nos, n, z0, hh = g["r"], g["go"], g["w"], g["nos"], fl.n, fl.z0, g["hh"]
        P = self._pitch(g, fl)
        x_s, x_e, z_cut, z_top = self._ends(g, fl)
        closed = g["closed"]
        b2 = r + g["tt"] + nos * r / go + (0.1 if closed else 0.12)
        out = []
        step = 4 if n > 9 else 2  # steps per block: fewer pieces, a little more volume
        for i in range(0, n - 1, step):
            j = min(i + step - 1, n - 2)
            xa, xb = i * go - nos, (j + 1) * go + RISER_T
            zb = max(z_cut, P(xa) - b2 - 0.001)
            out.append(Part(box_between((xa, -w / 2, zb), (xb, w / 2, z0 + (j + 1) * r)), "wood"))
        out.append(Part(box_between(((n - 1) * go - 0.001, -w / 2, max(z_cut, P((n - 1) * go) - b2 - 0.001)),
                                    (x_e, w / 2, z_top)), "wood"))
        if not fl.start_floor:
            out.append(Part(box_between((x_s, -w / 2, z_cut), (0.0, w / 2, z0 + 0.001)), "wood"))
        prof = self._stringer_profile(g, fl, True)
        for side, on in ((1, g["left"]), (-1, g["right"])):
            if not (closed or on):
                continue
            y0, y1 = sorted((side * w / 2, side * (w / 2 - (0.04 if closed else 0.1))))
            pts = [(x, y, z) for x, z in prof for y in (y0, y1)] if closed else []
            if on:
                y = self._rail_y(g, side)
                ya, yb = y - POST / 2 - 0.011, y + POST / 2 + 0.011
                xb, xt = -nos - POST / 2, (n - 1) * go + POST / 2
                zb_post = z_cut if fl.start_floor else z0 - g["tt"]
                zt_post = z0 + n * r - g["tt"] - (0.25 if fl.end_floor else 0.0)
                for x, zlo in ((xb, zb_post), (xt, min(zt_post, P(xt) - r - 0.05))):
                    pts += [(x + sx * (POST / 2 + 0.011), yy, zz) for sx in (-1, 1) for yy in (ya, yb)
                            for zz in (zlo, P(x) + hh + 0.08)]
            out.append(Part(hull(pts), "frame"))
        return out

    def _landing_cheap(self, p, g, lg) -> list[Part]:
        out = [Part(box_between((lg["x0"], lg["y0"], 0.0), (lg["x1"], lg["y1"], lg["z"])), "wood")]
        e = POST / 2 + 0.011
        for a, b in self._landing_runs(g, lg):
            lo, hi = np.minimum(a, b) - e, np.maximum(a, b) + e
            out.append(Part(box_between((lo[0], lo[1], lg["z"] - g["tt"]),
                                        (hi[0], hi[1], lg["z"] + g["hh"] + 0.08)), "frame"))
        return out

    def _spiral_cheap(self, p, g) -> list[Part]:
        """The column, and per two treads a block from the floor to the handrail over them
        (the hull of their outlines, plus the newels and the first riser at the ends): it holds
        the treads' own outline points, so the bounding box is the detailed one."""
        n, s, ry = g["n"], g["s"], self._spiral_g(g)["ry"]
        q = self._spiral_g(g)
        out = [Part(cylinder(COLUMN, n * g["r"], (0.0, 0.0, 0.0), 8, circumscribed=True), "frame")]
        (a0, b0, t0), (a1, b1, t1) = self._spiral_posts(g, q)
        h = POST / 2 + 0.01  # the cap's half width
        sq = np.array([(-h, -h), (h, -h), (h, h), (-h, h)])
        for i in range(0, n - 1, 2):
            j = min(i + 1, n - 2)
            plan = np.vstack([self._tread_outline(g, q, k) for k in range(i, j + 1)])
            far = min((j + 1) * q["alpha"], a1 * s)  # the highest point of the rail over them
            top = self._spiral_rail_height(g, q, s * far) + 0.001
            pts = [(x, y, z) for x, y in plan for z in (0.0, top)]
            for a, zb, zt, here in ((a0, b0, t0, i == 0), (a1, b1, t1, j == n - 2)):
                if here:
                    c, sn = math.cos(a), math.sin(a)
                    corners = sq @ np.array([[c, sn], [-sn, c]]) + (ry * c, ry * sn)
                    pts += [(x, y, z) for x, y in corners for z in (zb, zt)]
            if i == 0:
                pts += [(x, y, 0.0) for x, y in self._riser_footprint(0.0, s, q["R"] - 0.02)]
            out.append(Part(hull(pts), "wood"))
        return out

    # ---------------------------------------------------------------- surfaces
    def extra_surfaces(self, p):
        """The staircase's surfaces besides its bounding box's: landing_<j>, tread_<k>."""
        g = self._g(p)
        if p["style"] == "spiral":
            return self._spiral_surfaces(p, g)
        out: list[Surface] = []
        go, nos, w, r = g["go"], g["nos"], g["w"], g["r"]
        hw = (w / 2 - 0.05) if g["closed"] else (w / 2 - 0.075)
        k = 0
        up = np.array([0.0, 0.0, 1.0])
        hx = (go + nos - 0.02) / 2
        rect = sg.box(-hx, -hw, hx, hw)  # every tread's walkable top, shared
        for fl in g["flights"]:
            rot = fl.rotation()
            t = np.array([fl.ox, fl.oy, 0.0])
            u = rot @ np.array([1.0, 0.0, 0.0])
            for i in range(fl.n - 1):
                c = np.array([(i + 0.5) * go - nos / 2, 0.0, fl.z0 + (i + 1) * r])
                out.append(Surface(f"tread_{k}", Subpart.SupportSurface, rot @ c + t, up, u, rect))
                k += 1
        for j, lg in enumerate(g["landings"]):
            turn = len(g["flights"]) == 2 and g["flights"][1].quarter != 2
            x0 = lg["x0"] + (0.13 if turn else g["nos"] + POST + 0.03)
            x1, y0, y1 = lg["x1"] - 0.13, lg["y0"] + 0.13, lg["y1"] - 0.13
            out.append(support_rect(f"landing_{j}", ((x0 + x1) / 2, (y0 + y1) / 2, lg["z"]), (x1 - x0) / 2,
                                    (y1 - y0) / 2))
        return out

    def _spiral_surfaces(self, p, g) -> list[Surface]:
        """Each tread's top between the column and the balustrade, from just behind its nosing
        edge to a line parallel to the next riser (clear of it when risers are closed). The
        treads are congruent: one outline, drawn relative to the tread's front, turned by u."""
        q = self._spiral_g(g)
        s, r = g["s"], g["r"]
        r0, r1 = COLUMN + 0.03, q["R"] - 0.105
        d = RISER_T + 0.01 if p["closed_risers"] else 0.005
        front = -s * q["nos_a"] + s * 0.005 / r0
        back = s * q["alpha"]
        outer = self._arc(front, back - s * math.asin(d / r1), r1)
        inner = self._arc(back - s * math.asin(d / r0), front, r0)
        poly = sg.Polygon(np.vstack([outer, inner]))
        up = np.array([0.0, 0.0, 1.0])
        out = []
        for i in range(g["n"] - 1):
            a = self._spiral_angle(g, q, i)
            out.append(Surface(f"tread_{i}", Subpart.SupportSurface, np.array([0.0, 0.0, (i + 1) * r]), up,
                               np.array([math.cos(a), math.sin(a), 0.0]), poly))
        return out

    @staticmethod
    def _arc(a0: float, a1: float, radius: float) -> np.ndarray:
        """Points on a circle from angle a0 to a1 (inscribed, <= 8 degree steps)."""
        k = max(1, int(math.ceil(abs(a1 - a0) / math.radians(8.0))))
        t = np.linspace(a0, a1, k + 1)
        return np.stack([np.cos(t), np.sin(t)], axis=1) * radius


def _clip_z(poly: list[tuple[float, float]], z0: float, z1: float) -> np.ndarray:
    """A convex (x, z) polygon clipped to z0 <= z <= z1 (Sutherland-Hodgman on two lines)."""
    pts = list(poly)
    for bound, keep_above in ((z0, True), (z1, False)):
        out = []
        for k, (x, z) in enumerate(pts):
            xn, zn = pts[(k + 1) % len(pts)]
            inside, inside_n = (z >= bound) == keep_above, (zn >= bound) == keep_above
            if inside:
                out.append((x, z))
            if inside != inside_n:
                t = (bound - z) / (zn - z)
                out.append((x + t * (xn - x), bound))
        pts = out
    return np.array(pts)


# --------------------------------------------------------------------------- stair railing
@register
class StairRailing(PartsFactory):
    """A free-standing balustrade segment for a landing edge or round a stair opening: square
    newel posts at the ends (and between, at most `post_spacing` apart), a handrail, and an
    infill of round, square or turned balusters, horizontal bars or glass panels, on a shoe
    rail or straight on the floor. It runs along Y."""

    name = "stair_railing"
    tags = frozenset({S.Object, S.Architecture, S.Railing})
    size_class = "large"
    slots = ["wood", "frame", "metal", "glass"]
    material_choices = STAIR_MATERIALS
    params = {
        "length": Param(0.8, 4.0, doc="length along Y (m)"),
        "height": Param(0.85, 1.1, doc="handrail top height (m)"),
        "infill": Param(kind="choice", choices=("round", "square", "spindle", "bars", "glass"),
                        doc="balusters, horizontal bars or glass panels"),
        "baluster_spacing": Param(0.09, 0.13, doc="baluster spacing (m)"),
        "post_size": Param(0.06, 0.1, doc="post section (m)"),
        "post_spacing": Param(1.0, 2.0, doc="largest distance between posts (m)"),
        "shoe_rail": Param(kind="bool", doc="infill stands on a bottom rail"),
        "handrail": Param(kind="choice", choices=("round", "flat"), doc="handrail section"),
    }

    def _posts(self, p) -> np.ndarray:
        L, ps = p["length"], p["post_size"]
        half = L / 2 - ps / 2 - 0.01
        k = max(1, int(math.ceil(2 * half / p["post_spacing"])))
        return np.linspace(-half, half, k + 1)

    def parts(self, p, detail):
        """The stair railing's solids: detailed, or the blocks of its placeholder."""
        L, H, ps = p["length"], p["height"], p["post_size"]
        top = H + 0.06
        e = ps / 2 + 0.01
        if not detail:
            return [Part(box_between((-e, -L / 2, 0.0), (e, L / 2, top)), "frame")]
        ys = self._posts(p)
        out = [Part(post(0.0, y, 0.0, top, ps), "frame") for y in ys]
        out.append(Part(handrail((0.0, ys[0], H), (0.0, ys[-1], H), p["handrail"]), "wood"))
        infill, slot = [], {"spindle": "wood", "glass": "glass"}.get(p["infill"], "metal")
        z0 = 0.04 if p["shoe_rail"] else 0.0
        if p["shoe_rail"]:
            out.append(Part(box_between((-0.03, ys[0], 0.0), (0.03, ys[-1], 0.04 + MEMBER_OVERLAP)), "frame"))
        for ya, yb in zip(ys[:-1], ys[1:], strict=True):
            a, b = ya + ps / 2 - MEMBER_OVERLAP, yb - ps / 2 + MEMBER_OVERLAP
            if p["infill"] == "glass":
                infill.append(box_between((-0.006, a, z0 - MEMBER_OVERLAP if z0 else 0.06),
                                          (0.006, b, H - 0.03)))
            elif p["infill"] == "bars":
                zs = np.arange(max(z0, 0.08) + 0.02, H - 0.06, p["baluster_spacing"])
                infill += [rod((0.0, a, z), (0.0, b, z), 0.01, 8) for z in zs]
            else:
                infill += [baluster(0.0, ya + t, z0 - MEMBER_OVERLAP if z0 else 0.0, H - 0.02, p["infill"],
                                    90.0)
                           for t in baluster_positions(yb - ya, p["baluster_spacing"], ps / 2 + 0.04)]
        out += [Part(q, slot) for q in infill]
        return out
