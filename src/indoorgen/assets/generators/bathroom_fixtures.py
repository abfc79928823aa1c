"""Bathroom fixtures: pedestal sinks, vanities, vessel basins, bathtubs (alcove, freestanding,
corner), toilets and shower enclosures. Fronts face +X; objects that stand against a wall have
their back at -X. Basins and tubs are real hollows (manifold3d subtraction), open at the top.

Round and tapered shells are built as convex hulls of stacked outlines (`_hull_stack`), so a
basin's outer skin can be made to contain its cavity plus a wall thickness by construction.
"""
from __future__ import annotations

import math
from typing import Any, Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from ...tags import Semantics as S
from ...tags import Subpart
from ..base import Param, Surface, register
from ..parts import (FRONT_PROUD, MOVING_GAP, DoorJoint, Front, Part, box, box_between,
                     cabinet_fronts, carcass, circle_polygon, cylinder, lathe, legs, rod, solid_union)
from ._common import PartsFactory, make_joint, support_polygon, support_rect

OV = 0.002  # overlap between touching pieces so that each link unions into one shell
GAP = MOVING_GAP

#: sanitary-ware finishes shared by the fixtures
FIXTURE_MATERIALS: dict[str, dict[str, float]] = {
    "porcelain": {"porcelain": 4.0, "glazed_ceramic": 1.0},
    "ceramic": {"glazed_ceramic": 2.0, "porcelain": 1.0, "matte_ceramic": 1.0},
    "metal": {"chrome": 4.0, "brushed_steel": 2.0, "brass": 1.0},
    "glass": {"clear_glass": 3.0, "frosted_glass": 1.0},
    "countertop": {"marble": 2.0, "granite": 1.0, "terrazzo": 1.0, "concrete": 0.5},
    "front": {"painted_wood": 2.0, "oak": 1.0, "walnut": 1.0},
    "wood": {"plywood": 1.0, "painted_wood": 1.0},
    "tile": {"glazed_ceramic": 2.0, "marble": 1.0},
}


# ------------------------------------------------------------------------ outline helpers
def _ellipse(a: float, b: float, center: tuple[float, float] = (0.0, 0.0),
             n: int = 48) -> m3d.CrossSection:
    """An ellipse with semi-axes a (X) and b (Y); vertices on +-X and +-Y (exact bbox)."""
    return m3d.CrossSection.circle(1.0, n).scale((float(a), float(b))).translate(
        (float(center[0]), float(center[1])))


def _rrect(lx: float, ly: float, r: float, center: tuple[float, float] = (0.0, 0.0),
           n: int = 24) -> m3d.CrossSection:
    """A rectangle lx (X) by ly (Y) with corners rounded by r, centred on `center`."""
    r = min(float(r), 0.49 * min(lx, ly))
    c = (float(center[0]), float(center[1]))
    if r < 1e-4:
        return m3d.CrossSection.square((float(lx), float(ly)), True).translate(c)
    return m3d.CrossSection.square((lx - 2 * r, ly - 2 * r), True).offset(
        r, m3d.JoinType.Round, 2.0, n).translate(c)


def _points(cs: m3d.CrossSection) -> np.ndarray:
    """All outline vertices of a cross-section, (N, 2)."""
    return np.vstack([np.asarray(p, float) for p in cs.to_polygons()])


def _polygon(cs: m3d.CrossSection, inset: float = 0.0) -> sg.Polygon:
    """The largest polygon of a cross-section as shapely, optionally shrunk by `inset`."""
    polys = [sg.Polygon(np.asarray(p, float)) for p in cs.to_polygons()]
    poly = max(polys, key=lambda q: q.area)
    return poly.buffer(-inset, join_style="mitre") if inset else poly


def _hull_stack(levels: Sequence[tuple[float, m3d.CrossSection]]) -> m3d.Manifold:
    """The convex hull of horizontal outlines placed at heights z: a tapered, rounded solid."""
    pts = [np.c_[_points(cs), np.full(len(_points(cs)), z)] for z, cs in levels]
    return m3d.Manifold.hull_points(np.vstack(pts))


def _offset_levels(levels: Sequence[tuple[float, m3d.CrossSection]], d: float, dz: float
                   ) -> list[tuple[float, m3d.CrossSection]]:
    """The same stack with every outline grown by d and moved down by dz (a shell's skin)."""
    return [(z - dz, cs.offset(d, m3d.JoinType.Round, 2.0, 24)) for z, cs in levels]


def _ring(outer: m3d.CrossSection, inner: m3d.CrossSection) -> sg.Polygon:
    """The polygon between two nested outlines (a rim)."""
    return _polygon(outer).difference(_polygon(inner))


# ------------------------------------------------------------------------------- faucets
FAUCET_STYLES = ("lever", "gooseneck", "two_handle")

#: a primitive of a small fixture, kept as data so its bounds are known without building it:
#: ("cyl", radius, height, (x, y, z0)), ("rod", p0, p1, radius), ("box", lo, hi),
#: ("sphere", centre, radius), ("arc", centre, R, tube): a half ring of radius R in the XZ
#: plane arching up, ("ring", centre, R, tube): a ring in the YZ plane (parallel to a wall),
#: ("hoop", centre, R, tube): the lower half of such a ring (its ends level with the centre),
#: ("oval", (x0, y, z), thickness, width, height): an elliptic wall plate from x0 along +X
Prim = tuple


def _cyl_sections(r: float) -> int:
    return 24 if r > 0.015 else 16


def _rod_sections(r: float) -> int:
    return 12 if r > 0.008 else 8


def _circle(n: int, offset: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """cos and sin of n equally spaced angles starting at `offset` (radians)."""
    a = offset + 2 * np.pi * np.arange(n) / n
    return np.cos(a), np.sin(a)


_AXES = np.eye(3)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product of two 3-vectors (np.cross is slow on single vectors)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _rod_points(p0, p1, r: float) -> np.ndarray:
    """The vertices of a rod: two polygons turned half a step, so that an axis-aligned rod has
    flat faces (not edges) facing the other two axes and rests on a facet."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = (p1 - p0) / math.sqrt(float(np.dot(p1 - p0, p1 - p0)))
    k = int(np.argmin(np.abs(d)))
    u = _cross(d, _AXES[k])
    u /= math.sqrt(float(np.dot(u, u)))
    v = _cross(d, u)
    n = _rod_sections(r)
    c, s = _circle(n, np.pi / n)
    ring = r * (c[:, None] * u + s[:, None] * v)
    return np.vstack([p0 + ring, p1 + ring])


def _ring_points(q: Prim) -> np.ndarray:
    """The vertices of a "ring", "hoop" or "arc" primitive (as `prim_solid` builds them)."""
    kind, (cx, cy, cz), R, t = q
    if kind == "arc":
        ct, st = _circle(12)
        th = np.radians(np.linspace(0.0, 180.0, 25))
    else:  # the tube's section and the ring turned half a step (flat faces outermost); the
        # hoop's 31 segments put an edge, not a vertex, at its bottom
        ct, st = _circle(12, np.radians(15.0))
        th = (np.radians(np.linspace(0.0, 180.0, 32)) if kind == "hoop"
              else 2 * np.pi * np.arange(32) / 32 + np.pi / 32)
    rho = (R + t * ct)[None, :]
    h = (t * st)[None, :]
    x, y = rho * np.cos(th)[:, None], rho * np.sin(th)[:, None]
    h = np.broadcast_to(h, x.shape)
    if kind == "ring":  # revolved about Z, then turned +90 deg about Y: (x, y, z) -> (z, y, -x)
        pts = np.stack([h, y, -x], axis=-1)
    elif kind == "hoop":  # (x, y, z) -> (z, -x, -y)
        pts = np.stack([h, -x, -y], axis=-1)
    else:  # arc: turned +90 deg about X: (x, y, z) -> (x, -z, y)
        pts = np.stack([x, -h, y], axis=-1)
    return pts.reshape(-1, 3) + (cx, cy, cz)


def prim_points(q: Prim) -> np.ndarray:
    """Points whose bounding box is exactly the primitive's (its vertices, or a sphere's poles)."""
    kind = q[0]
    if kind == "cyl":
        r, h, (x, y, z) = q[1], q[2], q[3]
        c, s = _circle(_cyl_sections(r))
        ring = np.c_[x + r * c, y + r * s]
        return np.vstack([np.c_[ring, np.full(len(c), z)], np.c_[ring, np.full(len(c), z + h)]])
    if kind == "rod":
        return _rod_points(q[1], q[2], q[3])
    if kind == "box":
        return np.array([q[1], q[2]], float)
    if kind == "sphere":
        return np.asarray(q[1], float) + q[2] * np.vstack([np.eye(3), -np.eye(3)])
    if kind == "oval":
        (x0, y, z), th, w, h = q[1], q[2], q[3], q[4]
        c, s = _circle(24, np.radians(7.5))
        e = np.c_[y + w / 2 * c, z + h / 2 * s]
        return np.vstack([np.c_[np.full(len(c), x0), e], np.c_[np.full(len(c), x0 + th), e]])
    return _ring_points(q)


def prim_solid(q: Prim) -> m3d.Manifold:
    """The solid of a primitive."""
    kind = q[0]
    if kind == "cyl":
        return cylinder(q[1], q[2], q[3], _cyl_sections(q[1]))
    if kind in ("rod", "oval"):
        return m3d.Manifold.hull_points(prim_points(q))
    if kind == "box":
        return box_between(q[1], q[2])
    if kind == "sphere":
        return m3d.Manifold.sphere(q[2], 16).translate(tuple(float(v) for v in q[1]))
    (cx, cy, cz), R, tube = q[1], q[2], q[3]
    if kind == "arc":
        arc = m3d.Manifold.revolve(m3d.CrossSection.circle(tube, 12).translate((R, 0.0)), 24, 180.0)
        return arc.rotate((90.0, 0.0, 0.0)).translate((cx, cy, cz))
    tube_cs = m3d.CrossSection.circle(tube, 12).rotate(15.0).translate((R, 0.0))
    if kind == "ring":
        return m3d.Manifold.revolve(tube_cs, 32).rotate((0.0, 0.0, 180.0 / 32)).rotate(
            (0.0, 90.0, 0.0)).translate((cx, cy, cz))
    half = m3d.Manifold.revolve(tube_cs, 31, 180.0)  # hoop: in XY over y >= 0, then (z, -x, -y)
    return half.transform(np.array([[0.0, 0.0, 1.0, cx], [-1.0, 0.0, 0.0, cy], [0.0, -1.0, 0.0, cz]]))


def prim_bounds(prims: Sequence[Prim]) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) corners of the box around primitives (exact: from their vertices)."""
    pts = np.vstack([prim_points(q) for q in prims])
    return pts.min(axis=0), pts.max(axis=0)


def faucet(x: float, y: float, z: float, style: str, height: float, reach: float) -> list[Prim]:
    """A deck-mounted tap standing on the deck at (x, y, z) and pouring towards +X: a
    single-lever mixer ("lever"), a tall arched spout with a side lever ("gooseneck") or a
    spout between two cross handles ("two_handle"). `height` is its top above the deck,
    `reach` how far the outlet is in front of its base. Its pieces overlap (one shell)."""
    z0 = z - OV
    if style == "gooseneck":
        R = reach / 2
        zt = z + max(height - R, 0.06)
        return [("cyl", 0.024, 0.035, (x, y, z0)), ("cyl", 0.012, zt - z0 + 0.001, (x, y, z0)),
                ("arc", (x + R, y, zt), R, 0.009), ("cyl", 0.011, 0.035, (x + reach, y, zt - 0.03)),
                ("rod", (x, y + 0.01, z + 0.07), (x, y + 0.065, z + 0.085), 0.006)]
    if style == "two_handle":
        hy, zc = 0.075, z + min(0.06, height * 0.5)
        prims = [("box", (x - 0.03, y - hy - 0.03, z0), (x + 0.03, y + hy + 0.03, z + 0.012)),
                 ("cyl", 0.015, height * 0.7 + 0.012, (x, y, z0)),
                 ("rod", (x - 0.005, y, z + height * 0.62), (x + reach, y, z + height * 0.45), 0.011),
                 ("cyl", 0.012, 0.025, (x + reach - 0.004, y, z + height * 0.45 - 0.022))]
        for s in (-1, 1):
            yh = y + s * hy
            prims += [("cyl", 0.014, zc - z0, (x, yh, z0)),
                      ("rod", (x - 0.025, yh, zc - 0.006), (x + 0.025, yh, zc - 0.006), 0.005),
                      ("rod", (x, yh - 0.025, zc - 0.006), (x, yh + 0.025, zc - 0.006), 0.005)]
        return prims
    # single-lever mixer: a round body, a straight spout and a lever on top
    zs = z + height * 0.72
    return [("cyl", 0.028, 0.01, (x, y, z0)), ("cyl", 0.021, height * 0.82 - OV, (x, y, z0)),
            ("rod", (x, y, zs), (x + reach, y, zs - 0.012), 0.011),
            ("cyl", 0.012, 0.02, (x + reach - 0.006, y, zs - 0.03)),
            ("rod", (x + 0.005, y, z + height * 0.8), (x - 0.07, y, z + height), 0.006)]


def prim_parts(prims: Sequence[Prim], detail: bool, slot: str = "metal") -> list[Part]:
    """Primitives as parts; the placeholder is the box around them."""
    if detail:
        return [Part(prim_solid(q), slot) for q in prims]
    return [Part(box_between(*prim_bounds(prims)), slot)]


def faucet_parts(x: float, y: float, z: float, style: str, height: float, reach: float,
                 detail: bool, slot: str = "metal") -> list[Part]:
    """`faucet` as parts; the placeholder is the box around it."""
    return prim_parts(faucet(x, y, z, style, height, reach), detail, slot)


def faucet_footprint(x: float, y: float, style: str) -> sg.Polygon:
    """The deck area a faucet's base covers (kept off support surfaces), with a margin."""
    if style == "two_handle":
        return sg.box(x - 0.04, y - 0.115, x + 0.04, y + 0.115)
    return sg.Point(x, y).buffer(0.04, 16)


# -------------------------------------------------------------------------------- basins
def bowl_cavity_levels(shape: str, lx: float, ly: float, depth: float, cx: float, cy: float,
                       z_top: float, radius: float = 0.04) -> list[tuple[float, m3d.CrossSection]]:
    """The stacked outlines of a basin's hollow: opening lx (X) by ly (Y) centred on (cx, cy)
    at z_top, `depth` deep, narrowing towards a rounded bottom ("rect": rounded-rectangle
    sections, otherwise elliptical). The first level lies 5 cm above z_top (it cuts the top)."""
    if shape == "rect":
        sec = lambda s: _rrect(lx * s, ly * s, radius * s, (cx, cy))
    else:
        sec = lambda s: _ellipse(lx * s / 2, ly * s / 2, (cx, cy), 48)
    prof = ((-0.05, 1.0), (0.0, 1.0), (0.3, 0.97), (0.6, 0.88), (0.85, 0.7), (1.0, 0.45))
    return [(z_top - t * depth, sec(s)) for t, s in prof]


def hollow(outer: m3d.Manifold, cavity_levels: Sequence[tuple[float, m3d.CrossSection]]
           ) -> m3d.Manifold:
    """`outer` with the cavity cut out."""
    return outer - _hull_stack(cavity_levels)


def bowl_skin(cavity_levels: Sequence[tuple[float, m3d.CrossSection]], wall: float,
              z_max: float) -> list[tuple[float, m3d.CrossSection]]:
    """The cavity grown by `wall` (sides and bottom), keeping only levels at or below z_max:
    hulled with a rim slab it gives a bowl whose walls are at least `wall` thick."""
    lv = _offset_levels(cavity_levels, wall, 0.0)
    lv[-1] = (lv[-1][0] - wall, lv[-1][1])
    return [(min(z, z_max), cs) for z, cs in lv]


@register
class BathroomSinkPedestal(PartsFactory):
    """A pedestal washbasin: a ceramic basin (rectangular, oval or round bowl, hollowed) with a
    flat tap deck along its back, standing on a column, tapered or flared pedestal; a deck
    tap (lever mixer, gooseneck or two handles). The basin's back sits against the wall."""

    name = "bathroom_sink_pedestal"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.BathroomSink})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
    params = {
        "basin_shape": Param(kind="choice", choices=("rect", "oval", "round"), doc="bowl and basin outline"),
        "width": Param(0.45, 0.65, doc="basin Y extent (m)"),
        "depth": Param(0.38, 0.52, doc="basin X extent, wall to front (m)"),
        "height": Param(0.8, 0.88, doc="height of the basin rim (m)"),
        "basin_thickness": Param(0.16, 0.22, doc="Z extent of the basin body (m)"),
        "bowl_depth": Param(0.1, 0.15, doc="depth of the bowl below the rim (m)"),
        "deck_depth": Param(0.07, 0.11, doc="depth of the flat tap deck at the back (m)"),
        "pedestal_style": Param(kind="choice", choices=("column", "tapered", "flared"),
                                doc="pedestal profile"),
        "pedestal_radius": Param(0.07, 0.12, doc="pedestal radius at its waist (m)"),
        "faucet_style": Param(kind="choice", choices=FAUCET_STYLES, doc="tap type"),
        "corner_radius": Param(0.02, 0.08, doc="corner rounding of the basin outline (m)"),
    }

    def _geometry(self, p) -> dict[str, Any]:
        W, D, H = p["width"], p["depth"], p["height"]
        deck, rim = p["deck_depth"], 0.03
        lx = D - deck - rim
        ly = W - 2 * rim
        if p["basin_shape"] == "round":
            lx = ly = min(lx, ly)
        cx = -D / 2 + deck + lx / 2
        depth = min(p["bowl_depth"], p["basin_thickness"] - 0.03)
        return dict(W=W, D=D, H=H, deck=deck, lx=lx, ly=ly, cx=cx, depth=depth,
                    T=p["basin_thickness"], wall=0.012, fx=-D / 2 + deck / 2)

    def _outline(self, p, g) -> m3d.CrossSection:
        W, D, r = g["W"], g["D"], p["corner_radius"]
        if p["basin_shape"] == "rect":
            return _rrect(D, W, r)
        back = _rrect(g["deck"] + 0.02, W, min(r, 0.03), (-D / 2 + (g["deck"] + 0.02) / 2, 0.0))
        a = (D - g["deck"]) / 2
        front = _ellipse(a, W / 2, (D / 2 - a, 0.0), 64)
        return m3d.CrossSection.batch_hull([back, front])

    def _cavity(self, p, g):
        return bowl_cavity_levels(p["basin_shape"], g["lx"], g["ly"], g["depth"], g["cx"], 0.0,
                                  g["H"], radius=max(p["corner_radius"], 0.03))

    def parts(self, p, detail):
        g = self._geometry(p)
        H, W, D = g["H"], g["W"], g["D"]
        # the basin's underside reaches the bowl's skin (a wall below the bowl's floor)
        basin_bottom = max(H - g["T"], H - g["depth"] - g["wall"])
        rp = p["pedestal_radius"]
        z_top = basin_bottom + 0.006
        prof = {"column": (1.25, 1.0, 1.15), "tapered": (1.35, 1.1, 0.85),
                "flared": (1.6, 1.0, 1.2)}[p["pedestal_style"]]
        r_foot, r_mid, r_top = (rp * k for k in prof)
        cx = g["cx"]
        out: list[Part] = []
        if detail:
            outline = self._outline(p, g)
            cav = self._cavity(p, g)
            skin = bowl_skin(cav, g["wall"], H - 0.03)
            under = outline.offset(-0.04, m3d.JoinType.Round, 2.0, 24)
            outer = _hull_stack([(H, outline), (H - 0.025, outline), (basin_bottom + 0.02, under)]
                                + [(max(z, basin_bottom), cs) for z, cs in skin])
            out.append(Part(hollow(outer, cav), "porcelain"))
            pts = [(0.0, 0.0), (r_foot, 0.0), (r_foot, 0.015), (r_mid, z_top * 0.5),
                   (r_top, z_top), (0.0, z_top)]
            out.append(Part(lathe(pts, 48).translate((cx, 0.0, 0.0)), "porcelain"))
            out.append(Part(cylinder(0.02, 0.004, (cx, 0.0, H - g["depth"] - 0.003), 24), "metal"))
        else:
            out.append(Part(box_between((-D / 2, -W / 2, basin_bottom), (D / 2, W / 2, H)), "porcelain"))
            rmax = max(r_foot, r_mid, r_top)
            out.append(Part(cylinder(rmax, z_top + OV, (cx, 0.0, 0.0), 12, circumscribed=True),
                            "porcelain"))
        out += faucet_parts(g["fx"], 0.0, H, p["faucet_style"], 0.16, g["deck"] / 2 + 0.1, detail)
        return out

    def extra_surfaces(self, p):
        g = self._geometry(p)
        rp = p["pedestal_radius"] * {"column": 1.25, "tapered": 1.35, "flared": 1.6}[p["pedestal_style"]]
        out = [support_polygon("bottom", (g["cx"], 0, 0), circle_polygon(rp * 0.995, 48),
                               subpart=Subpart.Bottom, up=False)]
        # the tap deck either side of the tap
        x0, x1 = -g["D"] / 2 + 0.01, g["cx"] - g["lx"] / 2 - 0.01
        deck = sg.box(x0, -g["W"] / 2 + 0.05, x1, g["W"] / 2 - 0.05)
        deck = deck.difference(faucet_footprint(g["fx"], 0.0, p["faucet_style"]).buffer(0.01))
        if x1 - x0 > 0.02:
            out += [support_polygon(f"deck_{i}", (0, 0, g["H"]), q)
                    for i, q in enumerate(_pieces(deck, 4e-4))]
        return out


def _pieces(geom, min_area: float = 1e-4) -> list[sg.Polygon]:
    """The polygons of a shapely geometry (a difference may split a deck in two), ordered by
    their centroid's y, dropping slivers smaller than `min_area`."""
    polys = [geom] if isinstance(geom, sg.Polygon) else list(getattr(geom, "geoms", []))
    polys = [q for q in polys if isinstance(q, sg.Polygon) and q.area >= min_area]
    return sorted(polys, key=lambda q: q.centroid.y)


# ------------------------------------------------------------------------- vessel basins
VESSEL_SHAPES = ("round", "oval", "rect", "square")


def _vessel_section(shape: str, lx: float, ly: float, r: float, center=(0.0, 0.0)):
    """A section of a vessel of full size lx (X) by ly (Y) at scale 1."""
    if shape in ("rect", "square"):
        return lambda s: _rrect(lx * s, ly * s, r * s, center)
    return lambda s: _ellipse(lx * s / 2, ly * s / 2, center, 64)


def vessel_bounds(lx: float, ly: float, height: float, lip: bool,
                  center: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> tuple[np.ndarray, np.ndarray]:
    """(lo, hi) corners of the box around a `vessel` (its rim, or lip, is its widest part)."""
    e = 0.012 if lip else 0.0
    c = np.asarray(center, float)
    return c - (lx / 2 + e, ly / 2 + e, 0.0), c + (lx / 2 + e, ly / 2 + e, height)


def vessel(shape: str, lx: float, ly: float, height: float, wall: float, flare: float,
           curve: float, foot: float, lip: bool, radius: float = 0.04,
           center: tuple[float, float, float] = (0.0, 0.0, 0.0)
           ) -> tuple[m3d.Manifold, m3d.CrossSection, m3d.CrossSection, float]:
    """A vessel basin standing at `center` (x, y, floor z): a hollow bowl lx (X) by ly (Y) at
    its rim, `height` tall, whose sections shrink to `flare` at the bottom along u^curve
    (curve < 1: a rounded belly), on an optional foot `foot` tall (>= 5 mm) and with an
    optional flat lip. Returns (solid, footprint on the floor, section of the hollow's flat
    floor, z of that floor); the solid is a function, so that it is only built when needed."""
    cx, cy, cz = center
    sec = _vessel_section(shape, lx, ly, radius, (cx, cy))
    has_foot = foot >= 0.005
    zb = cz + (foot if has_foot else 0.0)
    zt = cz + height
    size = lambda u: flare + (1.0 - flare) * u ** curve
    zu = lambda u: zb + 0.012 + u * (zt - zb - 0.012)
    us = (0.0, 0.08, 0.2, 0.4, 0.6, 0.8, 1.0)
    z_floor = zb + max(wall, 0.012) + 0.006
    floor = sec(size(0.08)).offset(-wall - 0.02, m3d.JoinType.Round, 2.0, 24)
    footprint = sec(flare * 0.85) if has_foot else sec(flare - 0.03)

    def solid() -> m3d.Manifold:
        body = _hull_stack([(zb, sec(flare - 0.03))] + [(zu(u), sec(size(u))) for u in us])
        inset = lambda u: sec(size(u)).offset(-wall, m3d.JoinType.Round, 2.0, 24)
        cav = [(zt + 0.05, inset(1.0))] + [(zu(u), inset(u)) for u in reversed(us)
                                           if zu(u) > z_floor + 0.02] + [(z_floor, floor)]
        if lip:
            body = body + m3d.Manifold.extrude(sec(1.0).offset(0.012, m3d.JoinType.Round, 2.0, 24),
                                               0.01).translate((0.0, 0.0, zt - 0.01))
        if has_foot:
            body = body + m3d.Manifold.extrude(footprint, zb - cz + OV).translate((0.0, 0.0, cz))
        return body - _hull_stack(cav)

    return solid, footprint, floor, z_floor


def _vessel_args(p: dict[str, Any]) -> tuple[str, float, float]:
    """(shape, lx, ly) of a vessel basin's params (round and square ignore the aspect)."""
    L = p["length"]
    aspect = 1.0 if p["shape"] in ("round", "square") else p["aspect"]
    return p["shape"], L * aspect, L


@register
class CountertopBasin(PartsFactory):
    """A vessel washbasin that sits on a countertop: a hollow round, oval, rectangular or square
    bowl with straight or bellied walls, optionally on a foot and with a flat lip, and a
    drain in its floor. Its bottom (the foot) rests on the counter."""

    name = "countertop_basin"
    tags = frozenset({S.Object, S.BathroomFixture, S.BathroomSink})
    size_class = "small"
    slots = ["porcelain", "metal"]
    material_choices = {"porcelain": {"porcelain": 3.0, "glazed_ceramic": 1.0, "marble": 1.0,
                                      "concrete": 0.5},
                        "metal": FIXTURE_MATERIALS["metal"]}
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=VESSEL_SHAPES, doc="outline of the bowl"),
        "length": Param(0.35, 0.6, doc="Y extent at the rim (m)"),
        "aspect": Param(0.6, 0.85, doc="X extent / Y extent (oval and rect; round and square: 1)"),
        "height": Param(0.1, 0.2, doc="Z extent (m)"),
        "wall_thickness": Param(0.006, 0.014, doc="wall thickness (m)"),
        "flare": Param(0.45, 0.85, doc="bottom section / rim section (taper of the walls)"),
        "curve": Param(0.35, 1.0, doc="wall profile exponent (1 straight, < 1 bellied)"),
        "foot_height": Param(0.0, 0.03, doc="height of a foot under the bowl (< 5 mm: none) (m)"),
        "lip": Param(kind="bool", doc="flat lip around the rim"),
        "corner_radius": Param(0.02, 0.06, doc="corner rounding of rect and square bowls (m)"),
    }

    def _build(self, p):
        shape, lx, ly = _vessel_args(p)
        return vessel(shape, lx, ly, p["height"], p["wall_thickness"], p["flare"], p["curve"],
                      p["foot_height"], p["lip"], p["corner_radius"])

    def parts(self, p, detail):
        shape, lx, ly = _vessel_args(p)
        if not detail:
            return [Part(box_between(*vessel_bounds(lx, ly, p["height"], p["lip"])), "porcelain")]
        shell, _, _, z_floor = self._build(p)
        return [Part(shell(), "porcelain"),
                Part(cylinder(0.022, 0.0035, (0.0, 0.0, z_floor - 0.003), 24), "metal")]

    def extra_surfaces(self, p):
        _, footprint, floor, z_floor = self._build(p)
        basin = _polygon(floor, 0.003).difference(sg.Point(0, 0).buffer(0.026, 16))
        return [support_polygon("bottom", (0, 0, 0), _polygon(footprint, 0.0005),
                                subpart=Subpart.Bottom, up=False),
                support_polygon("basin", (0, 0, z_floor), basin, subpart=Subpart.Interior)]


# -------------------------------------------------------------------------------- vanity
BOARD = 0.018
BOWL_DEPTH = 0.16  # depth of an undermount bowl below the countertop's top face


@register
class Vanity(PartsFactory):
    """A bathroom vanity: a cabinet on a plinth or legs under a stone countertop with one or
    two basins (undermount bowls cut into the top, or vessel bowls standing on it) and a deck
    tap behind each; under each basin doors, or a fixed false front over drawers, optionally
    beside a column of drawers. Doors and drawers are articulated; the countertop around the
    basins is a support surface and the cabinet floor behind doors an interior surface."""

    name = "vanity"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.BathroomSink, S.Vanity,
                      S.Storage, S.Cabinet})
    size_class = "large"
    slots = ["wood", "front", "countertop", "porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("wood", "front", "countertop",
                                                         "porcelain", "metal")}
    params = {
        "width": Param(0.6, 1.6, doc="Y extent (m)"),
        "depth": Param(0.45, 0.56, doc="cabinet X extent (m); the top overhangs 15 mm"),
        "height": Param(0.8, 0.9, doc="height of the countertop's top face (m)"),
        "n_basins": Param(1, 2, kind="int", doc="basins (2 only when width >= 1.2 m)"),
        "basin_type": Param(kind="choice", choices=("undermount", "vessel"),
                            doc="bowl under the top or standing on it"),
        "basin_shape": Param(kind="choice", choices=("oval", "rect", "round"), doc="bowl outline"),
        "front_style": Param(kind="choice", choices=("doors", "drawers", "doors_drawers"),
                             doc="doors under the basin, drawers (under a false front), or doors "
                                 "beside a drawer column (one basin, width >= 0.8 m)"),
        "base_style": Param(kind="choice", choices=("plinth", "legs"), doc="recessed plinth or legs"),
        "base_height": Param(0.08, 0.2, doc="plinth or leg height (m)"),
        "top_thickness": Param(0.02, 0.04, doc="countertop thickness (m)"),
        "backsplash": Param(kind="bool", doc="upstand along the back of the top"),
        "faucet_style": Param(kind="choice", choices=FAUCET_STYLES, doc="tap type"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="door and drawer pulls"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        W, D, H, tt = p["width"], p["depth"], p["height"], p["top_thickness"]
        n = int(p["n_basins"]) if W >= 1.2 else 1
        inner0, inner1 = -W / 2 + BOARD, W / 2 - BOARD
        # side sections: a drawer column (doors_drawers, drawers) or a cupboard (doors), on one
        # side when there is room (doors_drawers) and on both sides of a basin bay that would
        # otherwise be wider than 0.9 m
        side = "cupboard" if p["front_style"] == "doors" else "column"
        span = inner1 - inner0
        n_side = 0
        if n == 1 and span > 0.9 + 0.3 + BOARD:
            n_side = 2 if span > 0.9 + 2 * (0.3 + BOARD) else 1
        elif n == 1 and p["front_style"] == "doors_drawers" and W >= 0.8:
            n_side = 1
        wc = 0.0
        if n_side:
            wc = min(max(0.3 * W, 0.3), 0.45)
            wc = max(wc, (span - 0.9 - n_side * BOARD) / n_side)
        bays: list[tuple[float, float, str]] = []  # (y0, y1, kind) of the inner openings
        y = inner0
        if n_side:
            bays.append((y, y + wc, side))
            y += wc + BOARD
        bw = (inner1 - y - (n - 1) * BOARD - (wc + BOARD if n_side == 2 else 0.0)) / n
        for _ in range(n):
            bays.append((y, y + bw, "basin"))
            y += bw + BOARD
        if n_side == 2:
            bays.append((y, y + wc, side))
        zb = p["base_height"]
        return dict(W=W, D=D, H=H, tt=tt, n=n, bays=bays, zb=zb, z0=zb + BOARD, z1=H - tt,
                    oh=0.015, bs=0.015 if p["backsplash"] else 0.0)

    def _basins(self, p, g) -> list[dict[str, float]]:
        """Each basin's opening centre (cx, cy) and size (lx, ly), and its tap's base x."""
        D, oh = g["D"], g["oh"]
        out = []
        for y0, y1, kind in g["bays"]:
            if kind != "basin":
                continue
            bw = y1 - y0
            lx, ly = min(0.42, D - 0.19), min(0.55, bw - 0.16)
            if p["basin_type"] == "vessel":
                lx, ly = min(0.4, D - 0.17), min(0.5, bw - 0.1)
            if p["basin_shape"] == "round":
                lx = ly = min(lx, ly)
            cx = D / 2 + oh - 0.06 - lx / 2
            fx = max(cx - lx / 2 - 0.05, -D / 2 + g["bs"] + 0.045)
            out.append(dict(cx=cx, cy=(y0 + y1) / 2, lx=lx, ly=ly, fx=fx))
        return out

    def _cells(self, p, g) -> tuple[list[Front], list[tuple[float, float, float, float]]]:
        """The moving fronts, and the fixed false fronts (y0, y1, z0, z1) over undermount bowls."""
        z0, z1 = g["z0"], g["z1"]
        cells, fixed = [], []
        under = p["basin_type"] == "undermount"
        for y0, y1, kind in g["bays"]:
            if kind == "cupboard":
                cells.append(Front(y0, y1, z0, z1, "right" if y0 > 0 else "left"))
            elif kind == "column":
                k = 3 if z1 - z0 > 0.5 else 2
                hs = np.linspace(z0, z1, k + 1)
                cells += [Front(y0, y1, float(a), float(b), "drawer") for a, b in zip(hs[:-1], hs[1:])]
            elif p["front_style"] == "drawers":
                top = z1
                if under:
                    top = z1 - BOWL_DEPTH + g["tt"] - 0.03
                    fixed.append((y0, y1, top, z1))
                k = 2 if top - z0 > 0.3 else 1
                hs = np.linspace(z0, top, k + 1)
                cells += [Front(y0, y1, float(a), float(b), "drawer") for a, b in zip(hs[:-1], hs[1:])]
            elif y1 - y0 > 0.55:
                ym = (y0 + y1) / 2
                cells += [Front(y0, ym, z0, z1, "left"), Front(ym, y1, z0, z1, "right")]
            else:
                cells.append(Front(y0, y1, z0, z1, "left"))
        return cells, fixed

    def _fronts(self, p, g):
        cells, _ = self._cells(p, g)
        return cabinet_fronts(g["D"] / 2, cells, g["D"] - 0.006 - 0.03, handle=p["handle"])

    # ---- geometry
    def _basin_solids(self, p, g, b) -> tuple[list[tuple[m3d.Manifold, str]], m3d.Manifold | None]:
        """(solid, slot) pieces of one basin, and the cut it makes in the countertop."""
        H, tt = g["H"], g["tt"]
        shape = p["basin_shape"]
        if p["basin_type"] == "vessel":
            shell, _, _, zf = vessel(shape, b["lx"], b["ly"], 0.14, 0.01, 0.6, 0.6, 0.0, False,
                                     0.04, (b["cx"], b["cy"], H - OV))
            return [(shell(), "porcelain"),
                    (cylinder(0.022, 0.0035, (b["cx"], b["cy"], zf - 0.003), 24), "metal")], None
        cav = bowl_cavity_levels(shape, b["lx"], b["ly"], BOWL_DEPTH, b["cx"], b["cy"], H, 0.05)
        skin = bowl_skin(cav, 0.012, H - tt + OV)
        cut = _hull_stack(cav)
        drain = cylinder(0.022, 0.0035, (b["cx"], b["cy"], H - BOWL_DEPTH - 0.003), 24)
        return [(_hull_stack(skin) - cut, "porcelain"), (drain, "metal")], cut

    def parts(self, p, detail):
        g = self._g(p)
        W, D, H, tt, zb = g["W"], g["D"], g["H"], g["tt"], g["zb"]
        dividers = [y1 + BOARD / 2 for (_, y1, _), _n in zip(g["bays"][:-1], g["bays"][1:])]
        # (the placeholder's block of carcass and fronts stands for the boards)
        out = [Part(s.solid, "wood") for s in carcass(D, W, zb, H - tt + OV, BOARD, back=0.006,
                                                      dividers=dividers, top=False)] if detail else []
        top = box_between((-D / 2, -W / 2, H - tt), (D / 2 + g["oh"], W / 2, H))
        cuts = []
        for b in self._basins(p, g):
            if detail:
                pieces, cut = self._basin_solids(p, g, b)
                cuts += [cut] if cut is not None else []
                out += [Part(s, slot) for s, slot in pieces]
            elif p["basin_type"] == "vessel":
                out.append(Part(box_between(*vessel_bounds(b["lx"], b["ly"], 0.14, False,
                                                           (b["cx"], b["cy"], H - OV))), "porcelain"))
            else:
                hx, hy = b["lx"] / 2 + 0.012, b["ly"] / 2 + 0.012
                out.append(Part(box_between((b["cx"] - hx, b["cy"] - hy, H - BOWL_DEPTH - 0.012),
                                            (b["cx"] + hx, b["cy"] + hy, H - tt + OV)), "porcelain"))
            fh = 0.3 if p["basin_type"] == "vessel" else 0.16
            reach = b["cx"] - b["fx"] if p["basin_type"] == "vessel" else b["cx"] - b["lx"] / 2 - b["fx"] + 0.08
            out += faucet_parts(b["fx"], b["cy"], H, p["faucet_style"], fh, reach, detail)
        out.append(Part(top - solid_union(cuts) if detail and cuts else top, "countertop"))
        if g["bs"]:
            out.append(Part(box_between((-D / 2, -W / 2, H - OV), (-D / 2 + g["bs"], W / 2, H + 0.1)),
                            "countertop"))
        _, fixed = self._cells(p, g)
        for y0, y1, z0, z1 in (fixed if detail else ()):
            out.append(Part(box_between((D / 2 - OV, y0 - OV, z0 + 0.002),
                                        (D / 2 + GAP + 0.018, y1 + OV, z1 - 0.002)), "front"))
        if detail:
            out += [part for parts, _ in self._fronts(p, g) for part in parts]
        else:
            proud = FRONT_PROUD if p["handle"] == "bar" else GAP + 0.018 + 0.025
            out.append(Part(box_between((-D / 2, -W / 2, zb), (D / 2 + proud, W / 2, H - tt + OV)),
                            "front"))
        if p["base_style"] == "plinth":
            out.append(Part(box_between((-D / 2, -W / 2, 0.0), (D / 2 - 0.05, W / 2, zb + OV)), "wood"))
        else:
            for leg in legs((D, W), 0.01, 0.04, 0.0, zb + OV, taper=0.6 if detail else 1.0,
                            round_legs=True, circumscribed=not detail, sections=16 if detail else 8):
                out.append(Part(leg, "metal"))
        return out

    def joints(self, p):
        g = self._g(p)
        depth = g["D"] - 0.006 - 0.03
        return [make_joint(f"{m.link}_joint", m, 0.0, math.radians(100)) if m.kind == "revolute"
                else make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth)
                for _, m in self._fronts(p, g)]

    def extra_surfaces(self, p):
        g = self._g(p)
        W, D, H = g["W"], g["D"], g["H"]
        top = sg.box(-D / 2 + g["bs"] + 0.01, -W / 2 + 0.01, D / 2 + g["oh"] - 0.01, W / 2 - 0.01)
        for b in self._basins(p, g):
            if p["basin_type"] == "vessel":
                hole = _polygon(_ellipse(b["lx"] / 2, b["ly"] / 2, (b["cx"], b["cy"]))
                                if p["basin_shape"] != "rect" else
                                _rrect(b["lx"], b["ly"], 0.04, (b["cx"], b["cy"])))
            else:
                hole = _polygon(bowl_cavity_levels(p["basin_shape"], b["lx"], b["ly"], BOWL_DEPTH,
                                                   b["cx"], b["cy"], H, 0.05)[0][1])
            top = top.difference(hole.buffer(0.02)).difference(
                faucet_footprint(b["fx"], b["cy"], p["faucet_style"]).buffer(0.01))
        out = [support_polygon(f"countertop_{i}" if i else "countertop", (0, 0, H), q)
               for i, q in enumerate(_pieces(top, 4e-3))]
        cells, _ = self._cells(p, g)
        k = 0
        for y0, y1, kind in g["bays"]:
            if kind == "cupboard" or (kind == "basin" and p["front_style"] != "drawers"):
                out.append(Surface.rect(f"interior_{k}", Subpart.Interior,
                                        (0.0, (y0 + y1) / 2, g["z0"]), (0, 0, 1), (1, 0, 0),
                                        D / 2 - 0.02, (y1 - y0) / 2 - 0.01))
                k += 1
        out.append(Surface.rect("back", Subpart.Back, (-D / 2, 0, (g["zb"] + H) / 2), (-1, 0, 0),
                                (0, 1, 0), W / 2, (H - g["zb"]) / 2))
        if p["base_style"] == "plinth":
            out.append(Surface.rect("bottom", Subpart.Bottom, (-0.025, 0, 0), (0, 0, -1), (1, 0, 0),
                                    D / 2 - 0.025, W / 2))
        return out

    def bottom_is_solid(self, params):
        return self.resolve(params)["base_style"] == "plinth"


# ------------------------------------------------------------------------------ bathtubs
def _drain(x: float, y: float, z_floor: float, r: float = 0.035) -> m3d.Manifold:
    """A drain disc set into a floor at z_floor, its top 0.5 mm proud."""
    return cylinder(r, 0.0045, (x, y, z_floor - 0.004), 24)


@register
class BathtubAlcove(PartsFactory):
    """A built-in rectangular bathtub for a three-wall alcove: a block with a flat rim and a
    tiled-in back, its front an apron (flat, with a recessed toe kick, or panelled); the
    hollow tapers to a flat floor with a sloped backrest at one end and the drain and overflow
    at the other. Rim: support surface; floor of the hollow: interior surface."""

    name = "bathtub_alcove"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
    params = {
        "length": Param(1.4, 1.8, doc="Y extent, along the back wall (m)"),
        "width": Param(0.7, 0.85, doc="X extent, wall to apron (m)"),
        "height": Param(0.45, 0.6, doc="rim height (m)"),
        "rim_width": Param(0.05, 0.12, doc="width of the rim along the sides (m)"),
        "basin_depth": Param(0.3, 0.45, doc="depth of the hollow below the rim (m)"),
        "drain_end": Param(kind="choice", choices=("left", "right"), doc="end with drain (+Y / -Y)"),
        "backrest_slope": Param(0.05, 0.3, doc="how far the backrest end leans back (m)"),
        "corner_radius": Param(0.04, 0.2, doc="corner rounding of the hollow's opening (m)"),
        "apron_style": Param(kind="choice", choices=("flat", "kick", "panelled"),
                             doc="plain apron, recessed toe kick, or raised panel moulding"),
    }

    def _g(self, p) -> dict[str, Any]:
        L, D, H = p["length"], p["width"], p["height"]
        rim = p["rim_width"]
        depth = min(p["basin_depth"], H - 0.1)
        s = 1.0 if p["drain_end"] == "left" else -1.0
        l_in, w_in = L - 2 * rim - 0.04, D - 2 * rim
        slope = p["backrest_slope"]
        # the floor: narrower than the opening, pushed towards the drain end
        yb0, yb1 = -l_in / 2 + slope + 0.06, l_in / 2 - 0.06
        return dict(L=L, D=D, H=H, rim=rim, depth=depth, s=s, l_in=l_in, w_in=w_in,
                    z_f=H - depth, fy=s * (yb0 + yb1) / 2, fl=yb1 - yb0, fw=w_in - 0.14)

    def _cavity(self, p, g) -> list[tuple[float, m3d.CrossSection]]:
        r = p["corner_radius"]
        top = _rrect(g["w_in"], g["l_in"], r)
        rb = 0.05
        return [(g["H"] + 0.05, top), (g["H"], top),
                (g["z_f"] + rb, _rrect(g["fw"] + 0.06, g["fl"] + 0.06, 0.08, (0.0, g["fy"]))),
                (g["z_f"], _rrect(g["fw"], g["fl"], 0.06, (0.0, g["fy"])))]

    def _drain_y(self, g) -> float:
        return g["s"] * (g["l_in"] / 2 - 0.06 - 0.1)

    def parts(self, p, detail):
        g = self._g(p)
        L, D, H = g["L"], g["D"], g["H"]
        front = D / 2 + (0.01 if p["apron_style"] == "panelled" else 0.0)
        if not detail:
            return [Part(box_between((-D / 2, -L / 2, 0.0), (front, L / 2, H)), "porcelain")]
        if p["apron_style"] == "kick":
            outer = (box_between((-D / 2, -L / 2, 0.07), (D / 2, L / 2, H))
                     + box_between((-D / 2, -L / 2, 0.0), (D / 2 - 0.05, L / 2, 0.07 + OV)))
        else:
            outer = box_between((-D / 2, -L / 2, 0.0), (D / 2, L / 2, H))
        if p["apron_style"] == "panelled":
            border = 0.05
            outer = outer + (box_between((D / 2 - OV, -L / 2 + 0.04, 0.05), (front, L / 2 - 0.04, H - 0.05))
                             - box_between((D / 2, -L / 2 + 0.04 + border, 0.05 + border),
                                           (front + 0.01, L / 2 - 0.04 - border, H - 0.05 - border)))
        out = [Part(hollow(outer, self._cavity(p, g)), "porcelain")]
        dy = self._drain_y(g)
        out.append(Part(_drain(0.0, dy, g["z_f"]), "metal"))
        # overflow cover on the drain end wall, 10 cm under the rim
        zo = H - 0.1
        t = (H - zo) / (H - g["z_f"] - 0.05)
        y_wall = g["s"] * (g["l_in"] / 2 - t * (g["l_in"] / 2 - (g["fl"] / 2 + 0.03 + g["s"] * g["fy"] * 0 + abs(g["fy"]) * 0)))
        y_wall = g["s"] * ((1 - t) * g["l_in"] / 2 + t * (abs(g["fy"]) + g["fl"] / 2 + 0.03))
        out.append(Part(rod((0.0, y_wall + g["s"] * 0.03, zo), (0.0, y_wall - g["s"] * 0.008, zo),
                            0.03, 24), "metal"))
        return out

    def extra_surfaces(self, p):
        g = self._g(p)
        L, D = g["L"], g["D"]
        cav = self._cavity(p, g)
        rim = sg.box(-D / 2 + 0.005, -L / 2 + 0.005, D / 2 - 0.005, L / 2 - 0.005).difference(
            _polygon(cav[1][1]).buffer(0.005))
        floor = _polygon(cav[-1][1], 0.005).difference(sg.Point(0.0, self._drain_y(g)).buffer(0.04, 16))
        out = [support_polygon("rim", (0, 0, g["H"]), rim),
               support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        if p["apron_style"] == "kick":
            out.append(Surface.rect("bottom", Subpart.Bottom, (-0.025, 0, 0), (0, 0, -1), (1, 0, 0),
                                    D / 2 - 0.025, L / 2))
        return out


TUB_SHAPES = ("oval", "slipper", "double_slipper", "rounded_rect")


@register
class BathtubFreestanding(PartsFactory):
    """A freestanding bathtub: an oval or rounded-rectangular shell whose sides flare out from
    a smaller bottom, with a plain or rolled rim, or a slipper (one end raised) or double
    slipper (both ends raised) rim; standing flush on the floor, on a plinth or on four claw
    feet. The floor of the hollow is an interior surface."""

    name = "bathtub_freestanding"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {"porcelain": {"porcelain": 3.0, "glazed_ceramic": 1.0, "marble": 0.5,
                                      "concrete": 0.3},
                        "metal": {"chrome": 2.0, "brass": 2.0, "brushed_steel": 1.0,
                                  "painted_metal": 1.0}}
    params = {
        "shape": Param(kind="choice", choices=TUB_SHAPES, doc="plan shape and rim profile"),
        "length": Param(1.5, 1.8, doc="Y extent at the rim (m)"),
        "width": Param(0.7, 0.85, doc="X extent at the rim (m)"),
        "height": Param(0.55, 0.68, doc="height of the (lowest) rim (m)"),
        "end_rise": Param(0.08, 0.2, doc="how far slipper ends rise above the rim (m)"),
        "wall_thickness": Param(0.02, 0.05, doc="shell thickness (m)"),
        "flare": Param(0.72, 0.9, doc="bottom size / rim size"),
        "base": Param(kind="choice", choices=("flush", "plinth", "feet"), doc="what it stands on"),
        "base_height": Param(0.05, 0.15, doc="plinth or feet height (m)"),
        "rolled_rim": Param(kind="bool", doc="a rolled bead around a level rim"),
    }

    def bottom_is_solid(self, params):
        return self.resolve(params)["base"] != "feet"

    def _g(self, p) -> dict[str, Any]:
        A, B = p["width"] / 2, p["length"] / 2
        slipper = p["shape"] in ("slipper", "double_slipper")
        zb = 0.0 if p["base"] == "flush" else p["base_height"]
        H = p["height"]
        top = H + (p["end_rise"] if slipper else 0.0)
        t = p["wall_thickness"]
        if p["shape"] == "rounded_rect":
            sec = lambda s: _rrect(2 * A * s, 2 * B * s, 0.5 * A * s)
        else:
            sec = lambda s: _ellipse(A * s, B * s, (0.0, 0.0), 64)
        return dict(A=A, B=B, H=H, top=top, zb=zb, t=t, sec=sec, slipper=slipper,
                    rolled=p["rolled_rim"] and not slipper, z_f=zb + t + 0.005)

    def _size(self, p, g, z: float) -> float:
        """Section scale at height z: flaring from `flare` at the bottom to 1 at the rim height
        (a slipper's raised ends rise straight above it, so the plan size is the rim's)."""
        u = min(max((z - g["zb"]) / (g["H"] - g["zb"]), 0.0), 1.0)
        return p["flare"] + (1.0 - p["flare"]) * (1.0 - (1.0 - u) ** 2)

    def _floor(self, p, g) -> m3d.CrossSection:
        return g["sec"](self._size(p, g, g["z_f"] + 0.05)).offset(-g["t"] - 0.07, m3d.JoinType.Round, 2.0, 24)

    def _drain_y(self, p, g) -> float:
        return -(g["B"] * p["flare"] - g["t"] - 0.2)

    def parts(self, p, detail):
        g = self._g(p)
        A, B, zb, top, t, sec = g["A"], g["B"], g["zb"], g["top"], g["t"], g["sec"]
        e = 0.02 if g["rolled"] else 0.0
        out: list[Part] = []
        if not detail:
            out.append(Part(box_between((-A - e, -B - e, zb), (A + e, B + e, top)), "porcelain"))
        else:
            f = p["flare"]
            zs = np.unique(np.r_[np.linspace(zb + 0.04, g["H"], 7), top])
            off = lambda cs, d: cs.offset(d, m3d.JoinType.Round, 2.0, 24)
            body = _hull_stack([(zb, off(sec(f), -0.035)), (zb + 0.012, off(sec(f), -0.012))]
                               + [(float(z), sec(self._size(p, g, z))) for z in zs])
            if g["rolled"]:
                r = 0.02
                body = body + _hull_stack([(top, sec(1.0)), (top - r, off(sec(1.0), r)),
                                           (top - 2 * r, sec(self._size(p, g, top - 2 * r)))])
            cav = ([(top + 0.1, off(sec(1.0), -t))]
                   + [(float(z), off(sec(self._size(p, g, z)), -t)) for z in zs[::-1] if z > g["z_f"] + 0.06]
                   + [(g["z_f"] + 0.05, off(sec(self._size(p, g, g["z_f"] + 0.05)), -t - 0.01)),
                      (g["z_f"], self._floor(p, g))])
            shell = hollow(body, cav)
            if g["slipper"]:
                shell = shell - self._rim_cutter(p, g)
            out.append(Part(shell, "porcelain"))
            out.append(Part(_drain(0.0, self._drain_y(p, g), g["z_f"]), "metal"))
        if p["base"] == "plinth":
            plinth = off(sec(p["flare"]), -0.06) if detail else None
            if detail:
                out.append(Part(m3d.Manifold.extrude(plinth, zb + OV), "porcelain"))
            else:
                out.append(Part(box_between((-A * p["flare"], -B * p["flare"], 0.0),
                                            (A * p["flare"], B * p["flare"], zb + OV)), "porcelain"))
        elif p["base"] == "feet":
            for fx, fy in self._feet(p, g):
                if detail:
                    prof = [(0.0, 0.0), (0.04, 0.0), (0.034, 0.02), (0.02, zb * 0.55),
                            (0.036, zb), (0.045, zb + min(t / 2, 0.01)), (0.0, zb + min(t / 2, 0.01))]
                    out.append(Part(lathe(prof, 24).translate((fx, fy, 0.0)), "metal"))
                else:
                    out.append(Part(cylinder(0.045, zb + 0.01, (fx, fy, 0.0), 8, circumscribed=True), "metal"))
        return out

    def _feet(self, p, g) -> list[tuple[float, float]]:
        f = p["flare"]
        ax, by = g["A"] * f - 0.035, g["B"] * f - 0.035
        return [(sx * 0.7 * ax, sy * 0.8 * by) for sx in (-1, 1) for sy in (-1, 1)]

    def _rim_cutter(self, p, g) -> m3d.Manifold:
        """The solid above a slipper rim: level in the middle, rising towards one (+Y) or both
        ends along a parabola (convex, so a hull of points under it)."""
        A, B, H, rise = g["A"] + 0.1, g["B"] + 0.05, g["H"], p["end_rise"]
        if p["shape"] == "double_slipper":
            ys = np.linspace(-B, B, 17)
            zs = H + rise * (np.abs(ys) / g["B"]) ** 2
        else:
            y0 = -0.2 * g["B"]
            ys = np.concatenate([[-B], np.linspace(y0, B, 12)])
            zs = H + rise * (np.clip(ys - y0, 0.0, None) / (g["B"] - y0)) ** 2
        pts = [(sx * A, y, z) for y, z in zip(ys, zs) for sx in (-1, 1)]
        pts += [(sx * A, y, g["top"] + 1.0) for y in (-B, B) for sx in (-1, 1)]
        return m3d.Manifold.hull_points(np.array(pts, float))

    def extra_surfaces(self, p):
        g = self._g(p)
        floor = _polygon(self._floor(p, g), 0.005).difference(
            sg.Point(0.0, self._drain_y(p, g)).buffer(0.04, 16))
        out = [support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        f = p["flare"]
        if p["base"] == "plinth":
            out.append(support_polygon("bottom", (0, 0, 0), _polygon(
                g["sec"](f).offset(-0.06, m3d.JoinType.Round, 2.0, 24), 0.0005), Subpart.Bottom, up=False))
        elif p["base"] == "flush":
            out.append(support_polygon("bottom", (0, 0, 0), _polygon(
                g["sec"](f).offset(-0.035, m3d.JoinType.Round, 2.0, 24), 0.0005), Subpart.Bottom, up=False))
        return out


def corner_outline(lx: float, ly: float, shape: str, cut: float, n: int = 24) -> m3d.CrossSection:
    """The plan of a corner fixture lx (X) by ly (Y) centred on the origin, walls along its
    back (-X) and left (+Y) sides, its open front corner (+X, -Y) rounded by a quarter circle
    of radius `cut` ("quarter_round") or cut off by a diagonal `cut` along each side
    ("pentagon")."""
    corners = [(-lx / 2, -ly / 2), (-lx / 2, ly / 2), (lx / 2, ly / 2)]
    if shape == "pentagon":
        pts = corners + [(lx / 2, -ly / 2 + cut), (lx / 2 - cut, -ly / 2)]
    else:
        c = (lx / 2 - cut, -ly / 2 + cut)
        a = np.linspace(-math.pi / 2, 0.0, n + 1)
        pts = corners + list(zip(c[0] + cut * np.cos(a), c[1] + cut * np.sin(a)))
    return m3d.CrossSection.hull_points(np.array(pts, float))


def _rot2(deg: float) -> np.ndarray:
    """2D rotation matrix (counter-clockwise by `deg` degrees)."""
    a = math.radians(deg)
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


def _halfplane_cut(cs: m3d.CrossSection, k: float) -> m3d.CrossSection:
    """`cs` without the part where x - y < k (cuts a corner at (-X, +Y) square to the diagonal)."""
    big = 10.0
    keep = m3d.CrossSection.hull_points(np.array(
        [(k / 2 + big, -k / 2 + big), (k / 2 - big, -k / 2 - big), (big * 2, -big * 2)], float))
    return cs ^ keep


@register
class BathtubCorner(PartsFactory):
    """A corner bathtub for the corner between the back (-X) and left (+Y) walls: a block whose
    open front is a quarter circle or a diagonal (pentagonal plan), optionally on a recessed
    plinth; the hollow follows the front, leaving a triangular deck in the wall corner,
    optionally with a deck-mounted tap. Rim: support surface; floor: interior surface."""

    name = "bathtub_corner"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Bathtub})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=("quarter_round", "pentagon"), doc="plan of the front"),
        "length": Param(1.2, 1.6, doc="Y extent along the back wall (m)"),
        "width": Param(1.2, 1.5, doc="X extent along the left wall (m)"),
        "height": Param(0.5, 0.62, doc="rim height (m)"),
        "front_cut": Param(0.55, 0.85, doc="front rounding radius or chamfer / the smaller side"),
        "rim_width": Param(0.06, 0.12, doc="rim width along the front (m)"),
        "corner_deck": Param(0.12, 0.3, doc="extra depth of the deck in the wall corner (m)"),
        "basin_depth": Param(0.35, 0.45, doc="depth of the hollow (m)"),
        "kick": Param(kind="bool", doc="recessed plinth under the front"),
        "deck_tap": Param(kind="bool", doc="deck-mounted tap on the corner deck"),
    }

    def _g(self, p) -> dict[str, Any]:
        lx, ly, H = p["width"], p["length"], p["height"]
        cut = p["front_cut"] * min(lx, ly)
        outline = corner_outline(lx, ly, p["shape"], cut)
        k = -(lx + ly) / 2 + (p["rim_width"] + p["corner_deck"]) * math.sqrt(2) + 0.25
        rnd = lambda cs, r: cs.offset(-r, m3d.JoinType.Round, 2.0, 24).offset(r, m3d.JoinType.Round, 2.0, 24)
        opening = rnd(_halfplane_cut(outline.offset(-p["rim_width"], m3d.JoinType.Round, 2.0, 24), k), 0.12)
        z_f = H - min(p["basin_depth"], H - 0.1)
        return dict(lx=lx, ly=ly, H=H, outline=outline, opening=opening, z_f=z_f, k=k,
                    floor=opening.offset(-0.16, m3d.JoinType.Round, 2.0, 24),
                    mid=opening.offset(-0.1, m3d.JoinType.Round, 2.0, 24))

    def _tap_xy(self, g) -> tuple[float, float]:
        """The middle of the corner deck, on the diagonal."""
        c = np.array([-g["lx"] / 2, g["ly"] / 2])
        d = (g["k"] + (g["lx"] + g["ly"]) / 2) / math.sqrt(2)  # deck depth along the diagonal
        q = c + np.array([1.0, -1.0]) / math.sqrt(2) * (d * 0.45)
        return float(q[0]), float(q[1])

    def _drain_xy(self, g) -> tuple[float, float]:
        c = _polygon(g["floor"]).centroid
        return c.x, c.y

    def _tap(self, g) -> list[m3d.Manifold]:
        tx, ty = self._tap_xy(g)
        return [prim_solid(q).rotate((0.0, 0.0, -45.0)).translate((tx, ty, 0.0))
                for q in faucet(0.0, 0.0, g["H"], "lever", 0.18, 0.16)]

    def parts(self, p, detail):
        g = self._g(p)
        lx, ly, H = g["lx"], g["ly"], g["H"]
        if not detail:
            out = [Part(box_between((-lx / 2, -ly / 2, 0.0), (lx / 2, ly / 2, H)), "porcelain")]
            if p["deck_tap"]:
                lo, hi = prim_bounds(faucet(0.0, 0.0, H, "lever", 0.18, 0.16))
                tx, ty = self._tap_xy(g)
                c = np.array([(x, y) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]) @ _rot2(-45.0).T
                out.append(Part(box_between((tx + c[:, 0].min(), ty + c[:, 1].min(), lo[2]),
                                            (tx + c[:, 0].max(), ty + c[:, 1].max(), hi[2])), "metal"))
            return out
        kh = 0.08
        if p["kick"]:
            plinth = self._plinth(g)
            outer = (m3d.Manifold.extrude(g["outline"], H - kh).translate((0.0, 0.0, kh))
                     + m3d.Manifold.extrude(plinth, kh + OV))
        else:
            outer = m3d.Manifold.extrude(g["outline"], H)
        cav = [(H + 0.05, g["opening"]), (H, g["opening"]), (g["z_f"] + 0.06, g["mid"]),
               (g["z_f"], g["floor"])]
        out = [Part(hollow(outer, cav), "porcelain"), Part(_drain(*self._drain_xy(g), g["z_f"]), "metal")]
        if p["deck_tap"]:
            out += [Part(s, "metal") for s in self._tap(g)]
        return out

    def _plinth(self, g) -> m3d.CrossSection:
        """The plinth under a recessed front: the outline pulled 5 cm back from the open front
        but still flush with both walls."""
        return g["outline"].offset(-0.025, m3d.JoinType.Miter, 2.0).translate((-0.025, 0.025)) ^ g["outline"]

    def extra_surfaces(self, p):
        g = self._g(p)
        rim = _polygon(g["outline"], 0.005).difference(_polygon(g["opening"]).buffer(0.005))
        if p["deck_tap"]:
            tx, ty = self._tap_xy(g)
            rim = rim.difference(sg.Point(tx, ty).buffer(0.1, 16))
        dx, dy = self._drain_xy(g)
        floor = _polygon(g["floor"], 0.005).difference(sg.Point(dx, dy).buffer(0.04, 16))
        out = [support_polygon("rim", (0, 0, g["H"]), _pieces(rim)[0] if not isinstance(rim, sg.Polygon) else rim),
               support_polygon("basin", (0, 0, g["z_f"]), floor, subpart=Subpart.Interior)]
        if p["kick"]:
            out.append(support_polygon("bottom", (0, 0, 0), _polygon(self._plinth(g), 0.0005),
                                       Subpart.Bottom, up=False))
        else:
            out.append(support_polygon("bottom", (0, 0, 0), _polygon(g["outline"], 0.0005),
                                       Subpart.Bottom, up=False))
        return out


# -------------------------------------------------------------------------------- toilet
def _clip_back(cs: m3d.CrossSection, x0: float) -> m3d.CrossSection:
    """`cs` without what lies behind x = x0."""
    lo = cs.bounds()
    return cs ^ m3d.CrossSection.square((lo[2] - x0 + 1.0, lo[3] - lo[1] + 1.0)).translate(
        (x0, lo[1] - 0.5))


@register
class Toilet(PartsFactory):
    """A toilet: a hollow glazed bowl (oval rim, funnel-shaped hollow) on an exposed waisted
    foot or a smooth skirted body, with a cistern on it (two-piece), merged into it
    (one-piece) or none (wall-hung: it hangs from the wall, its flat back is its mounting
    face). The seat ring and the lid are separate links hinged about a Y axis at the back
    (they open until they lean on the cistern or wall); a push button or a side lever flushes."""

    name = "toilet"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Toilet})
    size_class = "large"
    slots = ["porcelain", "plastic", "metal"]
    material_choices = {"porcelain": FIXTURE_MATERIALS["porcelain"],
                        "plastic": {"glossy_plastic": 3.0, "painted_wood": 1.0, "oak": 0.5},
                        "metal": FIXTURE_MATERIALS["metal"]}
    params = {
        "style": Param(kind="choice", choices=("two_piece", "one_piece", "wall_hung"),
                       doc="cistern on the bowl, merged with it, or none (hung on the wall)"),
        "rim_height": Param(0.38, 0.44, doc="rim height above the floor (wall-hung: the bowl "
                                            "is 6 cm shorter and hangs at any height) (m)"),
        "bowl_length": Param(0.42, 0.5, doc="X length of the rim (round to elongated) (m)"),
        "bowl_width": Param(0.34, 0.39, doc="Y width of the rim (m)"),
        "rim_width": Param(0.03, 0.045, doc="width of the rim around the opening (m)"),
        "cistern_width": Param(0.36, 0.48, doc="cistern Y extent (m)"),
        "cistern_depth": Param(0.15, 0.22, doc="cistern X extent (m)"),
        "cistern_height": Param(0.28, 0.4, doc="cistern height above the rim (one-piece: 60%) (m)"),
        "seat_thickness": Param(0.018, 0.03, doc="seat ring thickness (m)"),
        "lid_thickness": Param(0.015, 0.028, doc="lid thickness (m)"),
        "flush": Param(kind="choice", choices=("button", "lever"),
                       doc="push button on top or lever on the side of the cistern"),
        "foot": Param(kind="choice", choices=("exposed", "skirted"),
                      doc="waisted foot or smooth skirted body (floor-standing styles)"),
    }

    def bottom_is_solid(self, params):
        return self.resolve(params)["style"] != "wall_hung"

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        style = p["style"]
        wall = style == "wall_hung"
        H = p["rim_height"] - (0.06 if wall else 0.0)
        a, b = p["bowl_length"] / 2, p["bowl_width"] / 2
        cd, cw = p["cistern_depth"], p["cistern_width"]
        ch = p["cistern_height"] * (0.6 if style == "one_piece" else 1.0)
        ts, tl = p["seat_thickness"], p["lid_thickness"]
        cf = {"two_piece": cd + 0.008, "one_piece": cd + 0.05, "wall_hung": 0.0}[style]
        x_hl = cf + 0.02  # back edge of the lid
        x_h = x_hl + tl + GAP  # back edge of the seat (the lid rests behind it when both open)
        x_e = x_h - 0.02 + a  # centre of the rim ellipse
        z_s = H + GAP  # underside of the seat
        z_l = z_s + ts + GAP  # underside of the lid
        return dict(style=style, wall=wall, H=H, a=a, b=b, cd=cd, cw=cw, ch=ch, ts=ts, tl=tl,
                    cf=cf, x_hl=x_hl, x_h=x_h, x_e=x_e, z_s=z_s, z_l=z_l,
                    front=x_e + a + 0.005, rw=p["rim_width"], x_foot=0.3 * cd if not wall else 0.0)

    def _foot(self, p, g) -> m3d.CrossSection:
        """The footprint on the floor (floor-standing styles)."""
        x0, x1 = g["x_foot"], g["x_e"] + (0.85 if p["foot"] == "skirted" else 0.45) * g["a"]
        w = 1.7 * g["b"] if p["foot"] == "skirted" else 0.22
        return _rrect(x1 - x0, w, 0.05, ((x0 + x1) / 2, 0.0))

    def _flush(self, p, g) -> list[Prim]:
        if g["wall"]:
            return []
        top = g["H"] + g["ch"] + (0.025 if g["style"] == "two_piece" else 0.0)
        if p["flush"] == "button":
            return [("cyl", 0.022, 0.009, (g["cd"] / 2, 0.0, top - OV))]
        x, y, z = g["cd"] - 0.05, g["cw"] / 2, g["H"] + g["ch"] - 0.05
        if g["style"] == "one_piece":  # its sides lean in: 0.5 cw wide at H - 0.12, 0.46 cw at the top
            y = g["cw"] * (0.5 - 0.04 * (z - g["H"] + 0.12) / (g["ch"] + 0.12)) - 0.004
        return [("rod", (x, y - OV, z), (x, y + 0.01, z), 0.018),
                ("rod", (x, y + 0.012, z), (x - 0.075, y + 0.012, z + 0.01), 0.007)]

    def _cistern(self, p, g) -> list[Part]:
        H, cd, cw, ch = g["H"], g["cd"], g["cw"], g["ch"]
        if g["style"] == "two_piece":
            body = box_between((0.0, -cw / 2, H - 0.01), (cd, cw / 2, H + ch))
            lid = box_between((0.0, -cw / 2 - 0.008, H + ch - OV), (cd + 0.008, cw / 2 + 0.008, H + ch + 0.025))
            return [Part(body, "porcelain"), Part(lid, "porcelain")]
        lv = [(H - 0.12, _rrect(cd + 0.05 + 0.08, cw, 0.04, ((cd + 0.05 - 0.08) / 2, 0.0))),
              (H + ch, _rrect(cd + 0.08, 0.92 * cw, 0.04, ((cd - 0.08) / 2, 0.0)))]
        pts = np.vstack([np.c_[np.maximum(_points(cs)[:, 0], 0.0), _points(cs)[:, 1],
                               np.full(len(_points(cs)), z)] for z, cs in lv])
        return [Part(m3d.Manifold.hull_points(pts), "porcelain")]

    def _body(self, p, g) -> m3d.Manifold:
        """The bowl, its rear deck and its foot (or, wall-hung, its mounting block)."""
        H, a, b, x_e = g["H"], g["a"], g["b"], g["x_e"]
        x_deck = 0.0 if g["style"] != "one_piece" else g["cd"] - 0.01
        deck = _rrect(x_e - x_deck, 1.5 * b, 0.0, ((x_e + x_deck) / 2, 0.0))
        bowl = [(H, _ellipse(a, b, (x_e, 0.0))), (H - 0.03, _ellipse(a, b, (x_e, 0.0))),
                (H, deck), (H - 0.09, deck)]
        if g["wall"]:
            block = _rrect(0.04, 0.32, 0.0, (0.02, 0.0))
            return _hull_stack(bowl + [(H - 0.22, _ellipse(0.75 * a, 0.8 * b, (x_e - 0.1 * a, 0.0))),
                                       (0.0, _ellipse(0.55 * a, 0.6 * b, (x_e - 0.2 * a, 0.0))),
                                       (0.06, block)])
        if p["foot"] == "skirted":
            return _hull_stack(bowl + [(0.0, self._foot(p, g))])
        # exposed: the bowl narrows to a waist, which flares out again to the foot
        z_b, z_w = H - 0.2, 0.1
        foot = self._foot(p, g)
        fx0, fy0, fx1, fy1 = _polygon(foot).bounds
        waist = _rrect(0.8 * (fx1 - fx0), 0.16, 0.05, ((fx0 + fx1) / 2 + 0.05 * (fx1 - fx0), 0.0))
        return (_hull_stack(bowl + [(z_b, _ellipse(0.7 * a, 0.75 * b, (x_e - 0.1 * a, 0.0))), (z_w, waist)])
                + _hull_stack([(0.0, foot), (0.015, foot), (z_w + 0.01, waist)]))

    def _cavity(self, g) -> list[tuple[float, m3d.CrossSection]]:
        H, a, b, rw, x_e = g["H"], g["a"], g["b"], g["rw"], g["x_e"]
        opening = _ellipse(a - rw, b - rw, (x_e + 0.005, 0.0))
        return [(H + 0.05, opening), (H, opening),
                (H - 0.05, _ellipse(0.9 * (a - rw), 0.9 * (b - rw), (x_e, 0.0))),
                (H - 0.2, _ellipse(0.06, 0.06, (x_e - 0.25 * a, 0.0), 24))]

    def _outline(self, g, x0: float) -> m3d.CrossSection:
        return _clip_back(_ellipse(g["a"] + 0.005, g["b"] + 0.005, (g["x_e"], 0.0), 64), x0)

    def _seat(self, g) -> m3d.Manifold:
        outline = self._outline(g, g["x_h"])
        opening = _ellipse(g["a"] - g["rw"] - 0.005, g["b"] - g["rw"] - 0.005, (g["x_e"] + 0.01, 0.0))
        ts, z = g["ts"], g["z_s"]
        low = m3d.Manifold.extrude(outline - opening, ts * 0.6).translate((0.0, 0.0, z))
        high = m3d.Manifold.extrude(outline.offset(-0.005, m3d.JoinType.Round, 2.0, 24)
                                    - opening.offset(0.005, m3d.JoinType.Round, 2.0, 24), ts * 0.4 + OV)
        return low + high.translate((0.0, 0.0, z + ts * 0.6 - OV))

    def _lid(self, g) -> m3d.Manifold:
        outline = self._outline(g, g["x_hl"])
        tl, z = g["tl"], g["z_l"]
        return _hull_stack([(z, outline), (z + 0.5 * tl, outline),
                            (z + tl, outline.offset(-0.012, m3d.JoinType.Round, 2.0, 24))])

    # ---- generator protocol
    def parts(self, p, detail):
        g = self._g(p)
        H, a, b, x_e = g["H"], g["a"], g["b"], g["x_e"]
        out: list[Part] = []
        if detail:
            out.append(Part(hollow(self._body(p, g), self._cavity(g)), "porcelain"))
            if not g["wall"]:
                out += self._cistern(p, g)
            for s in (-1, 1):  # hinge posts under the lid's back edge
                out.append(Part(box_between((g["x_hl"] + 0.004, s * 0.7 * b - 0.015, H - OV),
                                            (g["x_h"] - GAP, s * 0.7 * b + 0.015, g["z_s"] + g["ts"] - 0.001)),
                                "metal"))
            out.append(Part(self._seat(g), "plastic", "seat"))
            out.append(Part(self._lid(g), "plastic", "lid"))
            out += prim_parts(self._flush(p, g), True)
            return out
        x0 = 0.0 if g["style"] != "one_piece" else g["cd"] - 0.01
        x0 = min(x0, g["x_foot"]) if not g["wall"] else 0.0
        out.append(Part(box_between((x0, -b, 0.0), (x_e + a, b, H)), "porcelain"))
        if g["style"] == "two_piece":  # the cistern and its overhanging lid
            e = 0.008
            out.append(Part(box_between((0.0, -g["cw"] / 2 - e, H - 0.01),
                                        (g["cd"] + e, g["cw"] / 2 + e, H + g["ch"] + 0.025)), "porcelain"))
        elif g["style"] == "one_piece":  # the cistern tapers up from its widest foot
            out.append(Part(box_between((0.0, -g["cw"] / 2, H - 0.12), (g["cd"] + 0.05, g["cw"] / 2, H + g["ch"])),
                            "porcelain"))
        out.append(Part(box_between((g["x_hl"], -b - 0.005, H), (g["front"], b + 0.005, g["z_l"] + g["tl"])),
                        "plastic"))
        if self._flush(p, g):
            out += prim_parts(self._flush(p, g), False)
        return out

    def _open_limit(self, g, x_back: float, length: float) -> float:
        """How far (rad) a seat or lid hinged `x_back - cf` in front of the cistern (or wall)
        can tilt past vertical before its top leans on it."""
        room = max(x_back - g["cf"] - 0.006, 0.0)
        return math.pi / 2 + math.asin(min(room / length, 0.3))

    def joints(self, p):
        g = self._g(p)
        up = self._open_limit(g, g["x_hl"], g["front"] - g["x_hl"])
        axis = np.array([0.0, -1.0, 0.0])
        seat = DoorJoint("revolute", axis, np.array([g["x_h"], 0.0, g["z_s"] + g["ts"]]), "seat")
        lid = DoorJoint("revolute", axis, np.array([g["x_hl"], 0.0, g["z_l"] + g["tl"]]), "lid")
        return [make_joint("seat_joint", seat, 0.0, up), make_joint("lid_joint", lid, 0.0, up)]

    def extra_surfaces(self, p):
        g = self._g(p)
        H, cw = g["H"], g["cw"]
        if g["wall"]:
            back = Surface.rect("back", Subpart.Back, (0.0, 0.0, (0.07 + H - 0.01) / 2), (-1, 0, 0),
                                (0, 1, 0), 0.15, (H - 0.01 - 0.07) / 2)
            return [back]
        if g["style"] == "two_piece":
            z0, z1, hw = H - 0.005, H + g["ch"] - 0.005, cw / 2 - 0.005
        else:
            z0, z1, hw = H - 0.11, H + g["ch"] - 0.01, 0.46 * cw - 0.01
        return [Surface.rect("back", Subpart.Back, (0.0, 0.0, (z0 + z1) / 2), (-1, 0, 0), (0, 1, 0),
                             hw, (z1 - z0) / 2),
                support_polygon("bottom", (0, 0, 0), _polygon(self._foot(p, g), 0.0005),
                                Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------ showers
def _arc_panel(c: tuple[float, float], r0: float, r1: float, z0: float, z1: float,
               phi0: float, phi1: float) -> m3d.Manifold:
    """A curved panel: the ring sector between radii r0 and r1 about the vertical axis through
    `c`, from angle phi0 to phi1 (degrees, counter-clockwise from +X), spanning z0..z1."""
    cs = m3d.CrossSection.square((r1 - r0, z1 - z0)).translate((r0, z0))
    n = max(4, int(math.ceil((phi1 - phi0) / 3.75)))
    return m3d.Manifold.revolve(cs, int(n * 360 / (phi1 - phi0)), phi1 - phi0).rotate(
        (0.0, 0.0, phi0)).translate((c[0], c[1], 0.0))


SURROUND = 0.008  # thickness of the wall panels lining the enclosure's two walls


@register
class ShowerEnclosure(PartsFactory):
    """A shower: a low ceramic tray lined by wall panels on its back (-X) and left (+Y) walls,
    a glass enclosure - a square corner (fixed side panel, front with a hinged or sliding
    door), a quadrant (curved front of two sliding curved doors between straight returns) or a
    walk-in (one fixed panel braced to the wall, open end) - frameless or framed, and a rain
    head on a riser over a bar mixer. Doors are articulated; the tray's floor is an interior
    surface and the back wall panel its back."""

    name = "shower_enclosure"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Shower})
    size_class = "large"
    slots = ["ceramic", "tile", "glass", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("ceramic", "tile", "glass", "metal")}
    solid_bottom = True
    params = {
        "layout": Param(kind="choice", choices=("corner_square", "quadrant", "walk_in"),
                        doc="enclosure type"),
        "tray_length": Param(0.8, 1.6, doc="Y extent (quadrant: at most depth + 0.2; walk-in: "
                                           "at least 1.2) (m)"),
        "tray_depth": Param(0.8, 1.0, doc="X extent (m)"),
        "tray_height": Param(0.03, 0.12, doc="tray height (m)"),
        "glass_height": Param(1.85, 2.0, doc="height of the glass above the tray (m)"),
        "glass_thickness": Param(0.006, 0.01, doc="glass thickness (m)"),
        "door": Param(kind="choice", choices=("hinged", "sliding"), doc="door of a square corner"),
        "frame": Param(kind="choice", choices=("frameless", "framed"), doc="metal profiles"),
        "quadrant_radius": Param(0.45, 0.6, doc="radius of a quadrant's curved front (m)"),
        "panel_fraction": Param(0.5, 0.8, doc="walk-in panel length / tray length"),
        "head_radius": Param(0.08, 0.15, doc="rain head radius (m)"),
        "head_height": Param(1.95, 2.15, doc="height of the rain head above the floor (m)"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        D = p["tray_depth"]
        W = p["tray_length"]
        if p["layout"] == "quadrant":
            W = min(W, D + 0.2)
        elif p["layout"] == "walk_in":
            W = max(W, 1.2)
        th, t = p["tray_height"], p["glass_thickness"]
        e = 0.03
        R = min(p["quadrant_radius"], min(D, W) - 0.25)
        return dict(D=D, W=W, th=th, t=t, e=e, x_f=D / 2 - e, y_s=-W / 2 + e, R=R,
                    c=(D / 2 - R, -W / 2 + R), R_arc=R - e, R_d=R - e - t - GAP,
                    z0=th - OV, z1=th + p["glass_height"], x_w=-D / 2 + SURROUND,
                    y_w=W / 2 - SURROUND, framed=p["frame"] == "framed")

    def _tray_outline(self, p, g) -> m3d.CrossSection:
        if p["layout"] == "quadrant":
            return corner_outline(g["D"], g["W"], "quarter_round", g["R"])
        return _rrect(g["D"], g["W"], 0.0)

    def _recess(self, p, g) -> m3d.CrossSection:
        return self._tray_outline(p, g).offset(-0.07, m3d.JoinType.Round, 2.0, 24)

    def _hinged(self, g) -> dict[str, float]:
        """Square corner, hinged door: the door's y range, hinged on the wall (+Y) side."""
        y1 = g["y_w"] - 0.02
        span = y1 - (g["y_s"] - g["t"] / 2)
        y0 = y1 - min(0.65, 0.6 * span)
        return dict(y0=y0, y1=y1)

    def _sliding(self, g) -> dict[str, float]:
        """Square corner, sliding door: outside the fixed front panel, overlapping it 5 cm."""
        y1 = g["y_w"] - 0.015
        ym = (g["y_s"] + y1) / 2
        return dict(y0=ym - 0.05, y1=y1, ym=ym, x0=g["x_f"] + g["t"] / 2 + GAP,
                    z1=g["z1"] - 0.04)

    def _door_handle(self, x_face: float, y: float, zc: float, sides: tuple[int, ...]) -> list[Prim]:
        """Vertical bar handles on the faces of a +X-facing glass leaf (side +1: outside, -1:
        inside; x_face is the outer face for +1, the inner face for -1)."""
        out = []
        for s, xf in zip(sides, (x_face,) * len(sides)):
            xb = xf + s * 0.03
            out += [("rod", (xb, y, zc - 0.15), (xb, y, zc + 0.15), 0.01),
                    ("rod", (xf - s * OV, y, zc - 0.12), (xb, y, zc - 0.12), 0.007),
                    ("rod", (xf - s * OV, y, zc + 0.12), (xb, y, zc + 0.12), 0.007)]
        return out

    def _moving(self, p, g) -> list[tuple[list[Part], DoorJoint, float]]:
        """(parts, motion, upper limit) of each door leaf."""
        t, z0, x_f = g["t"], g["th"] + 0.01, g["x_f"]
        zc = g["th"] + 1.05
        if p["layout"] == "walk_in":
            return []
        if p["layout"] == "quadrant":
            (cx, cy), rd, out = g["c"], g["R_d"], []
            z1 = g["z1"] - 0.04
            for i, (a0, a1, sgn) in enumerate(((-90.0, -46.0, -1.0), (-44.0, 0.0, 1.0))):
                leaf = _arc_panel((cx, cy), rd - t / 2, rd + t / 2, z0, z1, a0, a1)
                ah = math.radians(-46.0 - 4.0 if sgn < 0 else -44.0 + 4.0)
                ro = rd + t / 2
                knob = [("rod", (cx + (ro - OV) * math.cos(ah), cy + (ro - OV) * math.sin(ah), zc),
                         (cx + (ro + 0.025) * math.cos(ah), cy + (ro + 0.025) * math.sin(ah), zc), 0.012)]
                parts = [Part(leaf, "glass", f"door_{i}")] + [Part(s.solid, "metal", f"door_{i}")
                                                            for s in prim_parts(knob, True)]
                motion = DoorJoint("revolute", np.array([0.0, 0.0, sgn]), np.array([cx, cy, 0.0]),
                                   f"door_{i}")
                # a leaf slides round until its far end is 9 cm (mixer) from the back wall or
                # 2 cm from the left wall, at most 36 degrees
                room = (cx - g["x_w"] - 0.09) if sgn < 0 else (g["y_w"] - 0.02 - cy)
                out.append((parts, motion, min(math.asin(min(max(room / (rd + t / 2), 0.1), 1.0)),
                                               math.radians(36.0))))
            return out
        if p["door"] == "hinged":
            h = self._hinged(g)
            leaf = box_between((x_f - t / 2, h["y0"], z0), (x_f + t / 2, h["y1"], g["z1"] - 0.01))
            handle = self._door_handle(x_f + t / 2, h["y0"] + 0.06, zc, (1,)) + \
                self._door_handle(x_f - t / 2, h["y0"] + 0.06, zc, (-1,))
            parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
            motion = DoorJoint("revolute", np.array([0.0, 0.0, 1.0]),
                               np.array([x_f + t / 2, h["y1"], 0.0]), "door_0")
            return [(parts, motion, math.radians(95.0))]
        s = self._sliding(g)
        leaf = box_between((s["x0"], s["y0"], z0), (s["x0"] + t, s["y1"], s["z1"]))
        handle = self._door_handle(s["x0"] + t, s["y0"] + 0.08, zc, (1,))
        parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
        motion = DoorJoint("prismatic", np.array([0.0, -1.0, 0.0]), np.array([s["x0"], s["y0"], z0]), "door_0")
        # it stops short of the corner clamp, which stands proud of the fixed glass
        travel = min(0.8 * (s["y1"] - s["y0"]), s["y0"] - (g["y_s"] + t / 2 + 0.006 + GAP))
        return [(parts, motion, travel)]

    def _fixed(self, p, g) -> list[Part]:
        """Tray, wall panels, fixed glass, profiles and rails."""
        D, W, th, t, e = g["D"], g["W"], g["th"], g["t"], g["e"]
        x_f, y_s, x_w, y_w, z0, z1 = g["x_f"], g["y_s"], g["x_w"], g["y_w"], g["z0"], g["z1"]
        tray = m3d.Manifold.extrude(self._tray_outline(p, g), th)
        tray = tray - m3d.Manifold.extrude(self._recess(p, g), 0.05).translate((0.0, 0.0, th - 0.008))
        out = [Part(tray, "ceramic"),
               Part(box_between((-D / 2, -W / 2, z0), (x_w, W / 2, z1)), "tile"),
               Part(box_between((-D / 2, y_w, z0), (x_f + t / 2 + 0.006, W / 2, z1)), "tile")]
        out += self._drain_parts(p, g)
        glass, metal = [], []
        pw = 0.015 + (0.01 if g["framed"] else 0.0)  # wall profile width
        if p["layout"] == "walk_in":
            y0 = y_w - p["panel_fraction"] * W
            glass.append(box_between((x_f - t / 2, y0, z0), (x_f + t / 2, y_w + OV, z1)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_w - pw, z0), (x_f + t / 2 + 0.006, y_w + OV, z1)))
            metal.append(rod((x_f, y0 + 0.05, z1 - 0.06), (x_w - OV, y0 + 0.05, z1 - 0.06), 0.01, 12))
        elif p["layout"] == "quadrant":
            (cx, cy), ra = g["c"], g["R_arc"]
            glass.append(box_between((x_w - OV, y_s - t / 2, z0), (cx + 0.01, y_s + t / 2, z1)))
            glass.append(box_between((x_f - t / 2, cy - 0.01, z0), (x_f + t / 2, y_w + OV, z1)))
            rail_z0 = g["z1"] - 0.04 + GAP
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, rail_z0, z1 + 0.01, -90.0, 0.0))
            metal.append(box_between((cx - 0.01, y_s - 0.014, rail_z0), (cx + 0.011, y_s + 0.014, z1 + 0.01)))
            metal.append(box_between((x_f - 0.014, cy - 0.011, rail_z0), (x_f + 0.014, cy + 0.01, z1 + 0.01)))
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, z0, th + 0.008, -90.0, 0.0))
        else:
            glass.append(box_between((x_w - OV, y_s - t / 2, z0), (x_f + t / 2, y_s + t / 2, z1)))
            if p["door"] == "hinged":
                h = self._hinged(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0), (x_f + t / 2, h["y0"] - GAP, z1)))
                for zh in (th + 0.3, g["z1"] - 0.3):  # hinges on the wall
                    metal.append(box_between((x_f - 0.02, h["y1"] + GAP, zh - 0.04), (x_f + 0.02, y_w + OV, zh + 0.04)))
            else:
                s = self._sliding(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0), (x_f + t / 2, s["ym"] + 0.05, z1)))
                metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, s["z1"] + GAP),
                                         (s["x0"] + t + 0.008, y_w + OV, z1 + 0.01)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, z0),
                                     (x_f + t / 2 + 0.006, y_s + t / 2 + 0.006, z1)))  # corner clamp/post
        if p["layout"] != "walk_in":  # wall profile of the side panel
            metal.append(box_between((x_w - OV, y_s - t / 2 - 0.006, z0), (x_w + pw, y_s + t / 2 + 0.006, z1)))
        if g["framed"] and p["layout"] != "walk_in":  # top rail along the side panel
            metal.append(box_between((x_w - OV, y_s - t / 2 - 0.006, z1 - 0.03), (g["c"][0] + 0.011 if p["layout"] == "quadrant" else x_f + t / 2 + 0.006, y_s + t / 2 + 0.006, z1 + 0.01)))
        return (out + [Part(s, "glass") for s in glass] + [Part(s, "metal") for s in metal]
                + [Part(prim_solid(q), "metal") for q in self._head(p, g)])

    def _head(self, p, g) -> list[Prim]:
        """Bar mixer on the back wall panel, riser, arm and round rain head."""
        x_w = g["x_w"]
        xr = x_w + 0.05
        zm = g["th"] + 0.95
        zh = max(p["head_height"], zm + 0.5)
        arm = min(0.35, g["D"] / 2)
        return [("box", (x_w - OV, -0.1, zm - 0.04), (x_w + 0.012, 0.1, zm + 0.04)),
                ("rod", (xr, -0.16, zm), (xr, 0.16, zm), 0.025),
                ("rod", (x_w + 0.01, -0.07, zm), (xr, -0.07, zm), 0.012),
                ("rod", (x_w + 0.01, 0.07, zm), (xr, 0.07, zm), 0.012),
                ("cyl", 0.011, zh - zm, (xr, 0.0, zm)),
                ("rod", (x_w - OV, 0.0, zh - 0.15), (xr, 0.0, zh - 0.15), 0.01),
                ("rod", (xr - 0.01, 0.0, zh - 0.008), (xr + arm, 0.0, zh - 0.008), 0.01),
                ("cyl", p["head_radius"], 0.014, (xr + arm, 0.0, zh - 0.03))]

    def parts(self, p, detail):
        g = self._g(p)
        if detail:
            return self._fixed(p, g) + [q for parts, _, _ in self._moving(p, g) for q in parts]
        D, W = g["D"], g["W"]
        hl, hh = prim_bounds(self._head(p, g))
        x1, z1 = g["x_f"] + g["t"] / 2 + 0.006, g["z1"] + 0.01
        if p["layout"] == "corner_square":
            x1 = g["x_f"] + g["t"] / 2 + 0.03 + 0.01  # hinged door handle
            if p["door"] == "sliding":
                x1 = self._sliding(g)["x0"] + g["t"] + 0.03 + 0.01
        elif p["layout"] == "quadrant":
            x1 = g["x_f"] + g["t"] / 2
        elif p["layout"] == "walk_in":
            z1 = g["z1"]
        return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, g["th"])), "ceramic"),
                Part(box_between((-D / 2, -W / 2, g["z0"]), (max(x1, D / 2), W / 2, max(z1, hh[2]))), "glass")]

    def joints(self, p):
        g = self._g(p)
        return [make_joint(f"{m.link}_joint", m, 0.0, up) for _, m, up in self._moving(p, g)]

    def extra_surfaces(self, p):
        g = self._g(p)
        rec = self._recess(p, g)
        c = _polygon(rec).centroid
        floor = _polygon(rec, 0.005).difference(sg.Point(c.x, c.y).buffer(0.05, 16))
        return [support_polygon("tray", (0, 0, g["th"] - 0.008), floor, subpart=Subpart.Interior),
                support_polygon("bottom", (0, 0, 0), _polygon(self._tray_outline(p, g), 0.0005),
                                Subpart.Bottom, up=False),
                Surface.rect("back", Subpart.Back, (-g["D"] / 2, 0.0, g["z1"] / 2), (-1, 0, 0), (0, 1, 0),
                             g["W"] / 2 - 0.001, g["z1"] / 2 - 0.001)]

    def _drain_parts(self, p, g) -> list[Part]:
        c = _polygon(self._recess(p, g)).centroid
        return [Part(_drain(c.x, c.y, g["th"] - 0.008, 0.045), "metal")]
