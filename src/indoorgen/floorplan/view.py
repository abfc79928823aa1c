"""The floorplan solver's state, which is also the room view its constraint program reads.

`GridPlan` holds, per storey, the cell grid and the label array (room index per cell), the
room graph and the staircase placeholder (a rectangle of cells shared by all storeys). It
implements `constraints.room_terms.RoomView`, computing the measures it can from the grid
(area, exterior length and corners, straight exterior walls, narrowness, shared walls) and
caching each room's measures until a move changes that room (`invalidate`).
"""
from __future__ import annotations

import math

import networkx as nx
import numpy as np
import shapely.geometry as sg
from shapely.geometry.polygon import orient

from indoorgen.constraints.room_terms import MIN_DOOR_WALL, SERVICE_ROOMS, STOREY, RoomView, ideal_areas
from indoorgen.floorplan.graph import HomeGraph
from indoorgen.floorplan.grid import OUTSIDE, Grid, opening, room_polygon, square_pieces, trace
from indoorgen.floorplan.rooms import room_type_of
from indoorgen.floorplan.stairs import flight_mask, flights
from indoorgen.model.polygons import polygon_pieces
from indoorgen.model.room_types import ROOM_TYPES, least_area

_TURN = math.radians(20.0)


def value_runs(*codes: np.ndarray) -> list[tuple[int, int, int, int, int]]:
    """Maximal runs of equal non-negative values along axis 1 of 2D int arrays, all found in
    one pass: (length, row, start, value, index of the array)."""
    blocks, offsets, widths = [], [], []
    pos = 0
    for c in codes:
        n_rows, n = c.shape
        b = np.full((n_rows, n + 1), OUTSIDE, np.int64)
        b[:, :n] = c
        blocks.append(b.ravel())
        offsets.append(pos)
        widths.append(n + 1)
        pos += b.size
    f = np.concatenate(blocks) if len(blocks) > 1 else blocks[0]
    change = np.flatnonzero(f[1:] != f[:-1]) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [len(f)]])
    vals = f[starts]
    keep = vals >= 0
    starts, ends, vals = starts[keep], ends[keep], vals[keep]
    which = np.searchsorted(np.asarray(offsets), starts, side="right") - 1
    local = starts - np.asarray(offsets)[which]
    rows, cols = np.divmod(local, np.asarray(widths)[which])
    return list(zip((ends - starts).tolist(), rows.tolist(), cols.tolist(), vals.tolist(),
                    which.tolist(), strict=False))


def _hull_area(pts: list[tuple[float, float]]) -> float:
    """Area of the convex hull of a few points (monotone chain)."""
    p = sorted(set(pts))
    if len(p) < 3:
        return 0.0

    def half(seq):
        h: list = []
        for q in seq:
            while len(h) >= 2 and ((h[-1][0] - h[-2][0]) * (q[1] - h[-2][1])
                                   - (h[-1][1] - h[-2][1]) * (q[0] - h[-2][0])) <= 0:
                h.pop()
            h.append(q)
        return h
    hull = half(p)[:-1] + half(reversed(p))[:-1]
    return 0.5 * abs(sum(hull[i][0] * hull[(i + 1) % len(hull)][1]
                         - hull[(i + 1) % len(hull)][0] * hull[i][1] for i in range(len(hull))))


def longest_run(x: np.ndarray) -> tuple[int, int, int]:
    """Longest run of True along axis 1 of a 2D boolean array: (length, row, start)."""
    if not x.any():
        return 0, -1, -1
    n_rows, n = x.shape
    flat = np.zeros((n_rows, n + 1), bool)
    flat[:, :n] = x
    f = flat.ravel().view(np.int8)
    d = np.diff(np.concatenate([[0], f]))
    starts = np.flatnonzero(d == 1)
    ends = np.flatnonzero(d == -1)
    lengths = ends - starts
    i = int(np.argmax(lengths))
    row, col = divmod(int(starts[i]), n + 1)
    return int(lengths[i]), row, col


def polygon_exterior_runs(points, contour: sg.Polygon
                          ) -> list[tuple[float, np.ndarray, np.ndarray]]:
    """The edges of a room outline (CCW points) that lie on the storey outline: (length,
    start, end), longest first."""
    ring = contour.exterior
    pts = np.asarray(points, float)
    out = []
    for a, b in zip(pts, np.roll(pts, -1, axis=0), strict=False):
        if all(ring.distance(sg.Point(p)) < 1e-6 for p in (a, b, (a + b) / 2)):
            out.append((float(np.hypot(*(b - a))), a, b))
    out.sort(key=lambda r: (-r[0], r[1][0], r[1][1]))
    return out


class GridPlan(RoomView):
    """Labels on grids for every storey of a home, with the room-view measures."""

    def __init__(self, graph: HomeGraph, grids: list[Grid], labels: list[np.ndarray],
                 stair_rect: tuple[int, int, int, int] | None):
        super().__init__()
        self.graph = graph
        self.grids = grids
        self.labels = labels
        self.names: list[list[str]] = [list(g.nodes) for g in graph.storeys]
        self.index: dict[str, tuple[int, int]] = {
            n: (k, i) for k, names in enumerate(self.names) for i, n in enumerate(names)}
        self.stair_rect = stair_rect  # (iy0, ix0, iy1, ix1) in cells, end exclusive
        #: rooms as wide as `rooms.planned_width` (else `rooms.min_width`: a home's last tries)
        self.planned_widths = True
        self._stair_mask: tuple[tuple[int, int, int, int], np.ndarray] | None = None
        self._paths = {}
        for k, g in enumerate(graph.storeys):
            entry = graph.storey_entry(k)
            self._paths.update(nx.single_source_shortest_path(g, entry))
        self._flight_cells: dict[tuple, np.ndarray] = {}
        self._ideal = {n: a for k, names in enumerate(self.names)
                       for n, a in zip(names, ideal_areas(
                           [ROOM_TYPES[room_type_of(n)].typical_area for n in names],
                           [room_type_of(n) in SERVICE_ROOMS for n in names],
                           grids[k].contour.area), strict=True)}

    # -- RoomView: the basics ----------------------------------------------------------------
    def room_ids(self) -> list[str]:
        """Every room of the home, storey by storey."""
        return [n for names in self.names for n in names]

    def storey_ids(self) -> list[str]:
        """The storeys' ids, ``storey_<k>``."""
        return [f"{STOREY}_{k}" for k in range(len(self.grids))]

    def room_type(self, o: str) -> str:
        """The type of room o (from its name)."""
        return room_type_of(o)

    def tags(self, o: str) -> frozenset:
        """Rooms: Room, their type, and "entrance" for the room with the front door."""
        t = super().tags(o)
        return t | {"entrance"} if o == self.graph.entrance else t

    def level(self, o: str) -> int:
        """The storey room o is on."""
        return self.index[o][0]

    def neighbours(self, o: str) -> list[str]:
        """o's room-graph neighbours on its storey, sorted."""
        return sorted(self.graph.storeys[self.index[o][0]].neighbors(o))

    def contour(self, level: int) -> sg.Polygon:
        """Storey `level`'s outline."""
        return self.grids[level].contour

    def entry_room(self, level: int) -> str:
        """The room storey `level` is entered by (entrance or staircase room)."""
        return self.graph.storey_entry(level)

    def entry_path(self, o: str) -> list[str]:
        """The rooms from the storey's entry room to o along the room graph."""
        return self._paths[o]

    def typical_area(self, o: str) -> float:
        """Typical area of o's type (m^2, from the room-type table)."""
        return ROOM_TYPES[room_type_of(o)].typical_area

    def min_area(self, o: str) -> float:
        """Smallest area o may have (m^2): `least_area` for its type and doors, or in a plan of
        a home's last tries (on minimum widths) its type's minimum."""
        if not self.planned_widths:
            return ROOM_TYPES[room_type_of(o)].min_area
        doors = len(self.neighbours(o)) + int(o == self.graph.entrance)
        return least_area(room_type_of(o), doors)

    def ideal_area(self, o: str) -> float:
        """o's share of its storey's area (m^2, `ideal_areas`)."""
        return self._ideal[o]

    def stair_polygon(self) -> sg.Polygon | None:
        """The staircase placeholder's rectangle (None in a one-storey home)."""
        if self.stair_rect is None:
            return None
        iy0, ix0, iy1, ix1 = self.stair_rect
        g = self.grids[0]
        (x0, y0), (x1, y1) = g.to_world(ix0, iy0), g.to_world(ix1, iy1)
        return sg.box(x0, y0, x1, y1)

    def stair_mask(self) -> np.ndarray | None:
        """Cells of the staircase placeholder (read only; shared while it does not move)."""
        if self.stair_rect is None:
            return None
        if self._stair_mask is None or self._stair_mask[0] != self.stair_rect:
            iy0, ix0, iy1, ix1 = self.stair_rect
            m = np.zeros(self.grids[0].shape, bool)
            m[iy0:iy1, ix0:ix1] = True
            self._stair_mask = (self.stair_rect, m)
        return self._stair_mask[1]

    def snapshot(self) -> dict:
        """The measure caches, to `restore` after undoing a move."""
        return {r: dict(d) for r, d in self._cache.items()}

    def restore(self, snapshot: dict) -> None:
        """Put back the measure caches of a `snapshot`."""
        self._cache = snapshot

    def entry_point(self, level: int) -> np.ndarray:
        """Where a storey is entered: the front door on the ground floor (the middle of the
        entrance room's longest outside wall), the staircase placeholder's centre above."""
        if level == 0:
            return self.front_door(self.graph.entrance)[1]
        if self.stair_rect is None:
            c = self.contour(level).centroid
            return np.array([c.x, c.y])
        iy0, ix0, iy1, ix1 = self.stair_rect
        return np.array(self.grids[0].xy((ix0 + ix1) / 2, (iy0 + iy1) / 2))

    # -- cells ---------------------------------------------------------------------------------
    def mask(self, o: str) -> np.ndarray:
        """The cells labelled o on its storey's grid."""
        k, i = self.index[o]
        return self.cached(o, "mask", lambda: self.labels[k] == i)

    def bbox(self, o: str, margin: int = 0) -> tuple[slice, slice]:
        """Row and column slices of o's cells, grown by `margin` cells (clipped to the grid)."""
        def f():
            m = self.mask(o)
            rows, cols = np.flatnonzero(m.any(axis=1)), np.flatnonzero(m.any(axis=0))
            if not len(rows):
                return 0, 0, 0, 0
            return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1
        y0, y1, x0, x1 = self.cached(o, "bbox", f)
        ny, nx = self.grids[self.index[o][0]].shape
        return (slice(max(0, y0 - margin), min(ny, y1 + margin)),
                slice(max(0, x0 - margin), min(nx, x1 + margin)))

    def has_partial(self, o: str) -> bool:
        """Whether o has cells only partly inside the outline (bevelled edges)."""
        k, _ = self.index[o]
        return self.cached(o, "partial", lambda: bool(
            self.grids[k].partial[self.bbox(o)][self.mask(o)[self.bbox(o)]].any()))

    def outline_points(self, o: str) -> list[tuple[float, float]] | None:
        """o's outline corners, counter-clockwise (None if o is not one simple polygon)."""
        def f():
            k, _ = self.index[o]
            g = self.grids[k]
            ys, xs = self.bbox(o)
            if ys.stop == ys.start:
                return None
            if self.has_partial(o):
                poly = room_polygon(g, self.mask(o))
                if poly is None:
                    return None
                return [tuple(p) for p in orient(poly, 1.0).exterior.coords[:-1]]
            xy = trace(self.mask(o)[ys, xs])
            if xy is None:
                return None
            pts = g.to_world(xy[:, 0] + xs.start, xy[:, 1] + ys.start)
            return [(float(x), float(y)) for x, y in pts]
        return self.cached(o, "outline", f)

    def polygon(self, o: str) -> sg.Polygon | None:
        """o's outline as a shapely Polygon (None if o is not one simple polygon)."""
        def f():
            pts = self.outline_points(o)
            return None if pts is None else sg.Polygon(pts)
        return self.cached(o, "polygon", f)

    # -- RoomView: measures from the grid and the outline ---------------------------------------
    def _cell_sum(self, o: str, what: str) -> float:
        k, _ = self.index[o]
        g = self.grids[k]

        def f():
            ys, xs = self.bbox(o)
            return float(getattr(g, what)[ys, xs][self.mask(o)[ys, xs]].sum())
        return self.cached(o, what, f)

    def area(self, o: str) -> float:
        """o's floor area (m^2), partial cells counted by their inside fraction."""
        g = self.grids[self.index[o][0]]
        return self._cell_sum(o, "frac") * g.size ** 2

    def exterior_length(self, o: str) -> float:
        """Length of o's walls on the storey outline (m)."""
        return self._cell_sum(o, "ext_len")

    def exterior_corners(self, o: str) -> float:
        """Number of the storey outline's corners on o's boundary."""
        return self._cell_sum(o, "ext_corners")

    def _shape(self, o: str) -> dict:
        """Centroid, hull area, corner count, wall lines and bounds of o's outline, computed in
        plain Python over its few corners."""
        def f():
            pts = self.outline_points(o)
            assert pts is not None  # measured only on valid plans
            n = len(pts)
            a = cx = cy = 0.0
            for i in range(n):
                x0, y0 = pts[i]
                x1, y1 = pts[(i + 1) % n]
                c = x0 * y1 - x1 * y0
                a += c
                cx += (x0 + x1) * c
                cy += (y0 + y1) * c
            a *= 0.5
            centroid = (cx / (6 * a), cy / (6 * a)) if a else pts[0]
            corners = 0
            xs_v, ys_h = set(), set()
            for i in range(n):
                (px, py), (x0, y0), (x1, y1) = pts[i - 1], pts[i], pts[(i + 1) % n]
                d0x, d0y, d1x, d1y = x0 - px, y0 - py, x1 - x0, y1 - y0
                if abs(math.atan2(d0x * d1y - d0y * d1x, d0x * d1x + d0y * d1y)) > _TURN:
                    corners += 1
                if abs(d1x) < 1e-9:
                    xs_v.add(round(x0, 3))
                if abs(d1y) < 1e-9:
                    ys_h.add(round(y0, 3))
            xs = [p[0] for p in pts]
            ys = [p[1] for p in pts]
            return {"area": a, "centroid": centroid, "hull": _hull_area(pts), "corners": corners,
                    "lines": (frozenset(xs_v), frozenset(ys_h)),
                    "bounds": (min(xs), min(ys), max(xs), max(ys))}
        return self.cached(o, "shape", f)

    def center(self, o: str) -> np.ndarray:
        """o's outline centroid (z = 0)."""
        c = self._shape(o)["centroid"]
        return np.array([c[0], c[1], 0.0])

    def aspect_ratio(self, o: str) -> float:
        """Long side over short side of o's bounding box (1: square)."""
        x0, y0, x1, y1 = self._shape(o)["bounds"]
        w, h = x1 - x0, y1 - y0
        return max(w / h, h / w)

    def convexity(self, o: str) -> float:
        """Convex hull area over area of o (1: convex)."""
        sh = self._shape(o)
        return sh["hull"] / sh["area"]

    def wall_count(self, o: str) -> float:
        """Number of corners (so of walls) of o's outline."""
        return float(self._shape(o)["corners"])

    def wall_lines(self, o: str) -> tuple[frozenset, frozenset]:
        """The x and y positions of o's vertical and horizontal walls."""
        return self._shape(o)["lines"]

    def narrow_pieces(self, o: str, width: float) -> int:
        """How many parts of o a `width` square can move about in, each cut off from the others
        by a neck narrower than `width` (1 for a room one walks through whole)."""
        def f():
            if self.has_partial(o):
                return polygon_pieces(self.polygon(o), width)
            g = self.grids[self.index[o][0]]
            ys, xs = self.bbox(o)
            return square_pieces(self.mask(o)[ys, xs], int(math.ceil(width / g.size - 1e-9)))
        return self.cached(o, ("pieces", width), f)

    def narrow_area(self, o: str, width: float) -> float:
        """Area of the parts of o narrower than `width` (m^2)."""
        def f():
            if self.has_partial(o):
                return RoomView.narrow_area(self, o, width)
            g = self.grids[self.index[o][0]]
            ys, xs = self.bbox(o)
            m = self.mask(o)[ys, xs]
            k = int(math.ceil(width / g.size - 1e-9))
            return float((m & ~opening(m, k)).sum()) * g.size ** 2
        return self.cached(o, ("narrow", width), f)

    def stair_coverage(self, o: str) -> float:
        """Share of the staircase placeholder inside o (1 in a one-storey home)."""
        if self.stair_rect is None:
            return 1.0
        iy0, ix0, iy1, ix1 = self.stair_rect
        inside = float(self.mask(o)[iy0:iy1, ix0:ix1].sum())
        return inside / ((iy1 - iy0) * (ix1 - ix0))

    def stair_iou(self, o: str) -> float:
        """Intersection over union of o and the staircase placeholder (1 in a one-storey home)."""
        if self.stair_rect is None:
            return 1.0
        iy0, ix0, iy1, ix1 = self.stair_rect
        cell = self.grids[0].size ** 2
        inter = float(self.mask(o)[iy0:iy1, ix0:ix1].sum()) * cell
        sp = (iy1 - iy0) * (ix1 - ix0) * cell
        return inter / (self.area(o) + sp - inter)

    def exterior_runs(self, o: str) -> list[tuple[float, np.ndarray, np.ndarray]]:
        """Straight exterior walls of o: (length m, start xy, end xy), longest first. Along
        full cells they are read off the grid; a room the outline cuts (a bevel, an off-grid or
        slanted outline) takes the straight edges of its polygon that lie on the outline."""
        def f():
            if self.has_partial(o):
                return self._polygon_exterior_runs(o)
            k, i = self.index[o]
            g = self.grids[k]
            ys, xs = self.bbox(o, 1)
            lab = self.labels[k][ys, xs]
            mine = (lab == i) & g.full[ys, xs]
            # a cell edge is exterior if the cell across is outside the outline or the grid
            out_ = np.ones((lab.shape[0] + 2, lab.shape[1] + 2), bool)
            out_[1:-1, 1:-1] = lab == OUTSIDE
            sides = ((0, 0, out_[:-2, 1:-1]), (0, 1, out_[2:, 1:-1]),
                     (1, 0, out_[1:-1, :-2]), (1, 1, out_[1:-1, 2:]))
            codes = [np.where(mine & across, 0, OUTSIDE) for _, _, across in sides]
            codes = [c if axis == 0 else c.T for (axis, _, _), c in zip(sides, codes, strict=False)]
            out = []
            for length, row, start, _, t in value_runs(*codes):
                axis, side, _ = sides[t]
                line = row + side
                if axis == 0:
                    a = g.xy(xs.start + start, ys.start + line)
                    b = g.xy(xs.start + start + length, ys.start + line)
                else:
                    a = g.xy(xs.start + line, ys.start + start)
                    b = g.xy(xs.start + line, ys.start + start + length)
                out.append((length * g.size, np.array(a), np.array(b)))
            out.sort(key=lambda r: (-r[0], r[1][0], r[1][1]))
            return out
        return self.cached(o, "ext_runs", f)

    def _polygon_exterior_runs(self, o: str) -> list[tuple[float, np.ndarray, np.ndarray]]:
        return polygon_exterior_runs(self.outline_points(o), self.contour(self.level(o)))

    def longest_exterior_wall(self, o: str) -> float:
        """Longest straight exterior wall (m): room for a window or the front door."""
        runs = self.exterior_runs(o)
        return runs[0][0] if runs else 0.0

    def front_door(self, o: str) -> tuple[float, np.ndarray]:
        """Length and middle of o's longest straight exterior wall (where a front door goes)."""
        runs = self.exterior_runs(o)
        if not runs:
            return 0.0, self.center(o)[:2]
        length, a, b = runs[0]
        return length, (a + b) / 2

    def walls_with(self, o: str) -> dict[int, tuple[float, tuple[float, float]]]:
        """For each room index across o's boundary: the longest straight wall they share along
        full cells, as (length m, midpoint)."""
        def f():
            k, i = self.index[o]
            g = self.grids[k]
            ys, xs = self.bbox(o, 1)
            lab = self.labels[k][ys, xs]
            full = g.full[ys, xs]
            mine = (lab == i) & full
            other = np.where(full & (lab != i), lab, OUTSIDE)
            best: dict[int, tuple[float, tuple[float, float]]] = {}
            # horizontal grid lines between rows r and r+1, vertical between cols c and c+1
            h = np.where(mine[:-1], other[1:], np.where(mine[1:], other[:-1], OUTSIDE))
            v = np.where(mine[:, :-1], other[:, 1:], np.where(mine[:, 1:], other[:, :-1], OUTSIDE))
            for length, row, start, lab_j, axis in value_runs(h, v.T):
                L = length * g.size
                if best.get(lab_j, (0.0,))[0] < L:
                    mid = start + length / 2
                    p = g.xy(xs.start + mid, ys.start + row + 1) if axis == 0 else \
                        g.xy(xs.start + row + 1, ys.start + mid)
                    best[lab_j] = (L, p)
            return best
        return self.cached(o, "walls", f)

    def shared_wall(self, a: str, b: str) -> tuple[float, np.ndarray | None]:
        """Longest straight wall a and b share along full cells: (length m, midpoint)."""
        k, _ = self.index[a]
        kb, j = self.index[b]
        if kb != k:
            return 0.0, None
        hit = self.walls_with(a).get(j)
        return (0.0, None) if hit is None else (hit[0], np.array(hit[1]))

    def missing_doors(self, o: str) -> float:
        """Number of o's graph neighbours it shares no door-wide wall with."""
        walls = self.walls_with(o)
        need = MIN_DOOR_WALL - 1e-6
        return float(sum(1 for n in self.neighbours(o)
                         if walls.get(self.index[n][1], (0.0,))[0] < need))

    def flight_cells(self, level: int) -> np.ndarray | None:
        """Cells of storey `level` under its flights and over its stairwells (None without
        stairs); cached while the staircase placeholder stays put."""
        sp = self.stair_polygon()
        if sp is None:
            return None
        key = (self.stair_rect, level)
        if key not in self._flight_cells:
            self._flight_cells[key] = flight_mask(self.grids[level], flights(
                sp, len(self.grids)), level)
        return self._flight_cells[key]

    def stair_missing_doors(self, o: str) -> float:
        """For staircase room o: its graph neighbours it shares no door-wide straight wall with
        whose two cells in front, on o's side, are clear of flights and stairwells (where the
        door may open, `stairs.stair_door_ok`)."""
        k, i = self.index[o]
        blocked = self.flight_cells(k)
        if blocked is None:
            return self.missing_doors(o)
        g = self.grids[k]
        lab = self.labels[k]
        mine = (lab == i) & g.full
        other = np.where(g.full & (lab != i), lab, OUTSIDE)
        best: dict[int, int] = {}
        for axis in (0, 1):
            m, oth, b = (mine, other, blocked) if axis == 0 else (mine.T, other.T, blocked.T)
            pad = np.zeros((1, b.shape[1]), bool)
            back = ~b & ~np.vstack([pad, b[:-1]])  # a cell and the one before it are clear
            ahead = ~b & ~np.vstack([b[1:], pad])  # a cell and the one after it are clear
            # the line between rows r and r+1: o below with the door opening back into it,
            # or o above with the door opening ahead into it
            line = np.where(m[:-1] & back[:-1], oth[1:],
                            np.where(m[1:] & ahead[1:], oth[:-1], OUTSIDE))
            for length, _, _, lab_j, _ in value_runs(line):
                best[lab_j] = max(best.get(lab_j, 0), length)
        need = MIN_DOOR_WALL - 1e-6
        return float(sum(1 for n in self.neighbours(o)
                         if best.get(self.index[n][1], 0) * g.size < need))

    def path_directness(self, o: str) -> float:
        """How direct the walk from the storey's entry point to o through the doors on its graph
        path is: Manhattan distance over walked distance (1: direct)."""
        path = self.entry_path(o)
        ex, ey = self.entry_point(self.level(o))[:2]
        px, py = float(ex), float(ey)
        walk = 0.0
        for a, b in zip(path, path[1:], strict=False):
            hit = self.walls_with(a).get(self.index[b][1])
            qx, qy = hit[1] if hit is not None else self._shape(b)["centroid"]
            walk += abs(qx - px) + abs(qy - py)
            px, py = qx, qy
        cx, cy = self._shape(o)["centroid"]
        walk += abs(cx - px) + abs(cy - py)
        direct = abs(cx - ex) + abs(cy - ey)
        return direct / walk if walk > 1e-9 else 1.0

    def invalidate(self, rooms) -> None:
        """Forget the measures of `rooms` and the shared-wall tables of rooms next to them."""
        rooms = set(rooms)
        if not rooms:
            return
        super().invalidate(rooms)
        idx: dict[int, set[int]] = {}
        for r in rooms:
            k, i = self.index[r]
            idx.setdefault(k, set()).add(i)
        for name, d in self._cache.items():
            w = d.get("walls")
            if w is not None and idx.get(self.index[name][0], set()) & w.keys():
                del d["walls"]
