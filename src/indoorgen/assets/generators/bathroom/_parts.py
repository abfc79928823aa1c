"""What the bathroom generators share: sanitary-ware materials, plan outlines, stacked-outline
hulls, basin hollows, drains, corner plans, and primitive-based fittings (taps).

Fronts face +X; a fixture against a wall has its back at -X. Round and tapered shells are
convex hulls of stacked outlines (`hull_stack`), so a basin's outer skin can be made to contain
its hollow plus a wall thickness by construction. Small fittings are lists of primitives
(`Prim`) whose exact bounds are known without building them, so placeholders cost nothing.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, cylinder

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
def ellipse(a: float, b: float, center: tuple[float, float] = (0.0, 0.0),
             n: int = 48) -> m3d.CrossSection:
    """An ellipse with semi-axes a (X) and b (Y); vertices on +-X and +-Y (exact bbox)."""
    return m3d.CrossSection.circle(1.0, n).scale((float(a), float(b))).translate(
        (float(center[0]), float(center[1])))


def rounded_rect(lx: float, ly: float, r: float, center: tuple[float, float] = (0.0, 0.0),
           n: int = 24) -> m3d.CrossSection:
    """A rectangle lx (X) by ly (Y) with corners rounded by r, centred on `center`."""
    r = min(float(r), 0.49 * min(lx, ly))
    c = (float(center[0]), float(center[1]))
    if r < 1e-4:
        return m3d.CrossSection.square((float(lx), float(ly)), True).translate(c)
    return m3d.CrossSection.square((lx - 2 * r, ly - 2 * r), True).offset(
        r, m3d.JoinType.Round, 2.0, n).translate(c)


def outline_points(cs: m3d.CrossSection) -> np.ndarray:
    """All outline vertices of a cross-section, (N, 2)."""
    return np.vstack([np.asarray(p, float) for p in cs.to_polygons()])


def outline_polygon(cs: m3d.CrossSection, inset: float = 0.0) -> sg.Polygon:
    """The largest polygon of a cross-section as shapely, optionally shrunk by `inset`."""
    polys = [sg.Polygon(np.asarray(p, float)) for p in cs.to_polygons()]
    poly = max(polys, key=lambda q: q.area)
    return poly.buffer(-inset, join_style="mitre") if inset else poly


def hull_stack(levels: Sequence[tuple[float, m3d.CrossSection]]) -> m3d.Manifold:
    """The convex hull of horizontal outlines placed at heights z: a tapered, rounded solid."""
    pts = [np.c_[outline_points(cs), np.full(len(outline_points(cs)), z)] for z, cs in levels]
    return m3d.Manifold.hull_points(np.vstack(pts))


def _offset_levels(levels: Sequence[tuple[float, m3d.CrossSection]], d: float, dz: float
                   ) -> list[tuple[float, m3d.CrossSection]]:
    """The same stack with every outline grown by d and moved down by dz (a shell's skin)."""
    return [(z - dz, cs.offset(d, m3d.JoinType.Round, 2.0, 24)) for z, cs in levels]


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


def prim_bounds(prims: Sequence[Prim]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(lo, hi) corners of the box around primitives (exact: from their vertices)."""
    pts = np.vstack([prim_points(q) for q in prims])
    return tuple(pts.min(axis=0)), tuple(pts.max(axis=0))


def faucet(x: float, y: float, z: float, style: str, height: float, reach: float) -> list[Prim]:
    """A deck-mounted tap standing on the deck at (x, y, z) and pouring towards +X: a
    single-lever mixer ("lever"), a tall arched spout with a side lever ("gooseneck") or a
    spout between two cross handles ("two_handle"). `height` is its top above the deck,
    `reach` how far the outlet is in front of its base. Its pieces overlap (one shell)."""
    z0 = z - OVERLAP
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
    return [("cyl", 0.028, 0.01, (x, y, z0)), ("cyl", 0.021, height * 0.82 - OVERLAP, (x, y, z0)),
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
    def sec(s: float) -> m3d.CrossSection:
        if shape == "rect":
            return rounded_rect(lx * s, ly * s, radius * s, (cx, cy))
        return ellipse(lx * s / 2, ly * s / 2, (cx, cy), 48)

    prof = ((-0.05, 1.0), (0.0, 1.0), (0.3, 0.97), (0.6, 0.88), (0.85, 0.7), (1.0, 0.45))
    return [(z_top - t * depth, sec(s)) for t, s in prof]


def hollow(outer: m3d.Manifold, cavity_levels: Sequence[tuple[float, m3d.CrossSection]]
           ) -> m3d.Manifold:
    """`outer` with the cavity cut out."""
    return outer - hull_stack(cavity_levels)


def bowl_skin(cavity_levels: Sequence[tuple[float, m3d.CrossSection]], wall: float,
              z_max: float) -> list[tuple[float, m3d.CrossSection]]:
    """The cavity grown by `wall` (sides and bottom), keeping only levels at or below z_max:
    hulled with a rim slab it gives a bowl whose walls are at least `wall` thick."""
    lv = _offset_levels(cavity_levels, wall, 0.0)
    lv[-1] = (lv[-1][0] - wall, lv[-1][1])
    return [(min(z, z_max), cs) for z, cs in lv]


def polygon_pieces(geom, min_area: float = 1e-4) -> list[sg.Polygon]:
    """The polygons of a shapely geometry (a difference may split a deck in two), ordered by
    their centroid's y, dropping slivers smaller than `min_area`."""
    polys = [geom] if isinstance(geom, sg.Polygon) else list(getattr(geom, "geoms", []))
    polys = [q for q in polys if isinstance(q, sg.Polygon) and q.area >= min_area]
    return sorted(polys, key=lambda q: q.centroid.y)



def drain_disc(x: float, y: float, z_floor: float, r: float = 0.035) -> m3d.Manifold:
    """A drain disc set into a floor at z_floor, its top 0.5 mm proud."""
    return cylinder(r, 0.0045, (x, y, z_floor - 0.004), 24)


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
        pts = corners + list(zip(c[0] + cut * np.cos(a), c[1] + cut * np.sin(a), strict=True))
    return m3d.CrossSection.hull_points(np.array(pts, float))
