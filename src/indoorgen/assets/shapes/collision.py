"""Convex collision pieces: each part's hull, carved around moving parts and the free space over
covered shelves, large hollow parts split."""
from __future__ import annotations

from collections.abc import Sequence

import manifold3d as m3d
import numpy as np

from indoorgen.assets.shapes.mesh import link_names, solid_union
from indoorgen.assets.shapes.primitives import Part, box_between


def convex_pieces(parts: Sequence[Part], max_pieces: int = 48, decompose: bool = False,
                  keep_free: Sequence[Sequence[float]] = ()) -> list[tuple[str, m3d.Manifold]]:
    """Convex collision pieces (link, hull) for simulators: the convex hull of each part, since
    generators build objects from simple parts. With `decompose`, a part that is far from
    convex (a hollow carcass, a bowl, an L-shaped board) is first cut into nearly convex
    pieces, so that what goes inside it (a drawer, a lid, an apple) is not inside its collision
    shape. With `decompose`, the body's hulls also keep out of the `keep_free` boxes (the space
    over each inner shelf or cell, where the solver puts things). Beyond `max_pieces` per link
    (foliage, many slats), neighbouring pieces are grouped by their centres and each group
    hulled."""
    out: list[tuple[str, m3d.Manifold]] = []
    for link in link_names(parts):
        mine = [p.solid for p in parts if p.link == link and not p.solid.is_empty()]
        limit = max_pieces
        if decompose:
            carved = _carve_link(link, mine, parts, keep_free)
            if len(carved) != len(mine):
                limit = 2 * max_pieces  # grouping would hull the cuts back together
            mine = [piece for solid in carved for piece in convex_split(solid)]
        if len(mine) > limit:
            centres = np.array([(np.asarray(s.bounding_box()[:3]) + s.bounding_box()[3:]) / 2
                                for s in mine])
            groups = _group_by_position(centres, limit)
            mine = [solid_union([mine[i] for i in g]) for g in groups]
        out.extend((link, s.hull()) for s in mine)
    return out


def carve_around(solids: list[m3d.Manifold], boxes: Sequence[Sequence[float]],
                 shapes: Sequence[m3d.Manifold] | None = None) -> list[m3d.Manifold]:
    """Cut each solid whose convex hull would swallow part of one of `boxes` (the bounding boxes
    of the object's moving parts at rest: a drawer in its carcass, a bin inside a fridge) along
    that box's six face planes. The pieces outside the box then have hulls that keep out of it,
    so a simulator lets the drawer slide; what lies inside the box is usually nothing (the
    cavity) or thin. With `shapes` (one solid per box), a hull must swallow part of the shape
    itself, not merely of its box, to be cut."""
    for i, box in enumerate(boxes):
        lo, hi = np.asarray(box[:3], float), np.asarray(box[3:], float)
        if np.any(hi - lo <= 2 * SWALLOW_MARGIN):
            continue
        inner = box_between(lo + SWALLOW_MARGIN, hi - SWALLOW_MARGIN)
        if shapes is not None:
            inner = inner ^ shapes[i]
        out = []
        for solid in solids:
            if (solid.hull() ^ inner).volume() <= SWALLOW_VOLUME:
                out.append(solid)
                continue
            rest = solid  # what is left on the box's side of every plane cut so far
            for axis in range(3):
                for cut, keep_low in ((lo[axis], True), (hi[axis], False)):
                    beyond, rest = _split(rest, axis, cut, keep_low)
                    if beyond is not None and beyond.volume() > 1e-9:
                        out.append(beyond)  # wholly beyond one face of the box: safe whole
            # inside the box's slab: separate bits go out one by one, and a bit that still
            # wraps round the moving part (a pot's rim round its lid's skirt) in short pieces
            for bit in rest.decompose():
                out.extend(p for p in _unwrap(bit, inner) if p.volume() > 1e-9)
        solids = out
    return solids


def _unwrap(solid: m3d.Manifold, keep_out: m3d.Manifold, depth: int = 4
            ) -> list[m3d.Manifold]:
    """`solid` halved across its longest side until no piece's hull takes more than
    SWALLOW_VOLUME of `keep_out` or the piece is nearly convex (at most 2**depth pieces): a
    ring cut into short arcs."""
    hull = solid.hull()
    if depth == 0 or solid.volume() >= CONVEX_FILL * hull.volume() or \
            (hull ^ keep_out).volume() <= SWALLOW_VOLUME:
        return [solid]  # (a convex bit inside the box, a post, stays whole: cutting won't help)
    bb = np.asarray(solid.bounding_box(), float)
    axis = int(np.argmax(bb[3:] - bb[:3]))
    low, high = _split(solid, axis, (bb[axis] + bb[axis + 3]) / 2, True)
    if low is None:
        return [solid]
    return [p for half in (low, high) for p in _unwrap(half, keep_out, depth - 1)]


def _split(solid: m3d.Manifold, axis: int, cut: float, beyond_low: bool
           ) -> tuple[m3d.Manifold | None, m3d.Manifold]:
    """(the part of `solid` beyond the plane x_axis = cut, the rest): beyond is the low side
    when `beyond_low`, else the high side; None when the plane misses the solid."""
    bb = np.asarray(solid.bounding_box(), float)
    if not bb[axis] < cut < bb[axis + 3]:
        return None, solid
    on_axis = np.arange(3) == axis
    lo, hi = bb[:3] - 1, bb[3:] + 1
    low = solid ^ box_between(lo, np.where(on_axis, cut, hi))
    high = solid ^ box_between(np.where(on_axis, cut, lo), hi)
    return (low, high) if beyond_low else (high, low)


def free_space_above(solids: Sequence[m3d.Manifold], rect: Sequence[float], z: float,
                     top: float) -> list[float] | None:
    """The box (x0, y0, z0, x1, y1, z1) of open space over the horizontal rectangle
    rect = (x0, y0, x1, y1) at height z, up to the first solid above the rectangle's middle
    (below `top`): a shelf or cell under a board. None where nothing covers it (a basin, a
    plate: open above, where a hull over the rim is what simulators expect) or less than 1 cm
    is free."""
    x0, y0, x1, y1 = (float(v) for v in rect)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    column = box_between((cx - 1e-3, cy - 1e-3, z + 1e-3), (cx + 1e-3, cy + 1e-3, top + 1.0))
    ceiling = top
    for solid in solids:
        bb = solid.bounding_box()
        if not (bb[0] <= cx <= bb[3] and bb[1] <= cy <= bb[4]) or bb[5] <= z:
            continue  # (a cheap test first: the boolean below is what costs)
        hit = solid ^ column
        if not hit.is_empty():
            ceiling = min(ceiling, float(hit.bounding_box()[2]))
    if ceiling >= top - 1e-3 or ceiling - z < 0.01 or x1 - x0 < 0.01 or y1 - y0 < 0.01:
        return None
    return [x0 + 2e-3, y0 + 2e-3, z + 1e-3, x1 - 2e-3, y1 - 2e-3, ceiling - 1e-3]


def _carve_worthy(solid: m3d.Manifold) -> bool:
    """Whether a moving part is big enough to carve collision pieces around (MIN_CARVE across):
    a jar's cap or a knob is left to the simulator's contact margins."""
    if solid.is_empty():
        return False
    bb = np.asarray(solid.bounding_box(), float)
    return float(np.max(bb[3:] - bb[:3])) >= MIN_CARVE


#: moving parts smaller than this (m) get no carving (see `_carve_worthy`)
MIN_CARVE = 0.1


#: a moving part counts as swallowed by a hull that takes more than this of it (m^3, 1 cm^3),
#: once its box is shrunk by SWALLOW_MARGIN (so that parts merely touching do not count)
SWALLOW_VOLUME = 1e-6


SWALLOW_MARGIN = 1e-3


def _carve_link(link: str, solids: list[m3d.Manifold], parts: Sequence[Part],
                keep_free: Sequence[Sequence[float]]) -> list[m3d.Manifold]:
    """One link's solids cut so that their hulls keep clear of the other side: the body's out
    of the moving parts' boxes and the `keep_free` boxes, a moving part's (when big enough)
    out of the body (a lid's rim inside its pot)."""
    if link == "base":
        moving = [p.solid for p in parts if p.link != "base" and _carve_worthy(p.solid)]
        return carve_around(solids, [m.bounding_box() for m in moving] + list(keep_free))
    body = [p.solid for p in parts if p.link == "base" and not p.solid.is_empty()]
    big = [s for s in solids if _carve_worthy(s)]
    return carve_around(big, [b.bounding_box() for b in body], body) + \
        [s for s in solids if not _carve_worthy(s)]


#: a piece whose volume fills at least this share of its convex hull counts as convex
CONVEX_FILL = 0.85


#: parts whose hull is smaller than this (m^3, 10 litres) keep their hull: a leaf, a pot, a vase
MIN_SPLIT_VOLUME = 0.01


def convex_split(solid: m3d.Manifold, depth: int = 3) -> list[m3d.Manifold]:
    """Cut a solid into pieces that each nearly fill their convex hull: recursively split it by
    the axis-aligned plane through the middle of its bounding box (along x, y or z) that leaves
    the least empty hull volume, up to `depth` times (at most 2**depth pieces). Small solids
    (hull under MIN_SPLIT_VOLUME) stay whole."""
    vol = solid.volume()
    if vol <= 0:
        return []
    hull_vol = solid.hull().volume()
    if depth == 0 or vol >= CONVEX_FILL * hull_vol or hull_vol < MIN_SPLIT_VOLUME:
        return [solid]
    lo = np.asarray(solid.bounding_box()[:3], float)
    hi = np.asarray(solid.bounding_box()[3:], float)
    best, best_waste = None, hull_vol - vol
    for axis in range(3):
        if hi[axis] - lo[axis] < 1e-3:
            continue
        cut = (lo[axis] + hi[axis]) / 2
        on_axis = np.arange(3) == axis
        halves = [solid ^ box_between(lo - 1, np.where(on_axis, cut, hi + 1)),
                  solid ^ box_between(np.where(on_axis, cut, lo - 1), hi + 1)]
        if min(h.volume() for h in halves) <= 1e-12:
            continue
        waste = sum(h.hull().volume() - h.volume() for h in halves)
        if waste < best_waste:
            best, best_waste = halves, waste
    if best is None:
        return [solid]
    return [piece for h in best for piece in convex_split(h, depth - 1)]


def _group_by_position(points: np.ndarray, k: int) -> list[list[int]]:
    """Split points into at most k spatially compact groups by recursive median cuts along the
    longest axis (deterministic, no RNG)."""
    groups = [list(range(len(points)))]
    while len(groups) < k:
        i = max(range(len(groups)), key=lambda g: len(groups[g]))
        g = groups[i]
        if len(g) < 2:
            break
        pts = points[g]
        ax = int(np.argmax(pts.max(axis=0) - pts.min(axis=0)))
        order = [g[j] for j in np.argsort(pts[:, ax], kind="stable")]
        half = len(order) // 2
        groups[i:i + 1] = [order[:half], order[half:]]
    return groups


def box_minus(box: Sequence[float] | np.ndarray, holes: Sequence[Sequence[float]]
              ) -> list[list[float]]:
    """The axis-aligned box (x0, y0, z0, x1, y1, z1) with the `holes` (boxes alike) taken out, as
    a few boxes: each hole splits what it meets into the slabs below and above it, then beside
    it along y, then before and behind it along x (a cupboard's cheap block becomes its boards
    around the compartments, with no boolean or hull)."""
    pieces = [np.asarray(box, float)]
    for hole in holes:
        h = np.asarray(hole, float)
        out = []
        for b in pieces:
            lo, hi = np.maximum(b[:3], h[:3]), np.minimum(b[3:], h[3:])
            if np.any(hi - lo <= 1e-9):
                out.append(b)
                continue
            rest = b.copy()
            for axis in (2, 1, 0):
                if rest[axis] < lo[axis]:
                    below = rest.copy()
                    below[axis + 3] = lo[axis]
                    out.append(below)
                if hi[axis] < rest[axis + 3]:
                    above = rest.copy()
                    above[axis] = hi[axis]
                    out.append(above)
                rest[axis], rest[axis + 3] = lo[axis], hi[axis]
        pieces = out
    return [b.tolist() for b in pieces if np.all(b[3:] - b[:3] > 1e-9)]


def hollowed(parts: Sequence[Part], holes: Sequence[Sequence[float]]) -> list[Part]:
    """`parts` with the `holes` (boxes) taken out of the base link's box-shaped parts (a
    placeholder's blocks; other shapes are left whole): what the solver fills stays free."""
    out: list[Part] = []
    for part in parts:
        bb = np.asarray(part.solid.bounding_box(), float)
        is_box = part.solid.volume() >= 0.999 * float(np.prod(bb[3:] - bb[:3]))
        if part.link != "base" or not is_box:
            out.append(part)
            continue
        out.extend(Part(box_between(b[:3], b[3:]), part.slot, part.link) for b in box_minus(bb, holes))
    return out


#: a stowage box lower or narrower than this (m) holds nothing worth placing
MIN_STOWAGE = 0.03
#: things put away stand this far above their surface (the solver's contact gap,
#: constraints.relations.CONTACT_GAP, which assets sit below and cannot import)
STAND_GAP = 0.001


def clear_of(box: Sequence[float], solids: Sequence[m3d.Manifold]) -> list[float] | None:
    """`box` (x0, y0, z0, x1, y1, z1) cut back until none of `solids` enters it: each solid
    that does (a freezer drawer's bin, a door's bottle rack) is kept out by lowering the box's
    top or moving one of its sides, whichever keeps the most of it. None when less than
    MIN_STOWAGE is left in some direction."""
    b = np.asarray(box, float)
    for solid in solids:
        bb = np.asarray(solid.bounding_box(), float)
        if np.any(np.minimum(b[3:], bb[3:]) - np.maximum(b[:3], bb[:3]) <= 1e-6):
            continue
        hit = solid ^ box_between(b[:3], b[3:])
        if hit.is_empty() or hit.volume() <= 1e-9:
            continue
        h = np.asarray(hit.bounding_box(), float)
        if h[5] <= b[2] + STAND_GAP:
            continue  # flush with the floor (a drain cover): what stands there clears it
        options = []
        for axis in range(3):
            lower = b.copy()
            lower[axis + 3] = h[axis]
            options.append(lower)
            if axis < 2:  # (the bottom stays on its shelf)
                upper = b.copy()
                upper[axis] = h[axis + 3]
                options.append(upper)
        b = max(options, key=lambda o: float(np.prod(np.clip(o[3:] - o[:3], 0.0, None))))
        if np.any(b[3:] - b[:3] < MIN_STOWAGE):
            return None
    return b.tolist()
