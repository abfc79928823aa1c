"""The planning grid of one storey: 0.5 m cells over its outline, labelled with room indices.

A storey's plan during solving is an integer array `labels[iy, ix]` (-1 outside the outline).
A cell the outline cuts (a round or 45-degree bevel) is labelled like any other; the room's
polygon is then clipped by the outline, so the rooms of a storey always partition its outline
exactly. Everything a move or a term needs is derived from the labels with numpy: outlines
(traced boundaries), shared and exterior straight wall runs, openings for the narrowness test,
exterior length and corners per room.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.geometry as sg
from scipy import ndimage

from indoorgen.floorplan.contour import GRID

OUTSIDE = -1


@dataclass
class Grid:
    """Cells of size `size` with lower-left corner `origin`, shape (ny, nx), and what the outline
    leaves of each: `frac` (inside area fraction), `ext_len` (outline length inside the cell, m),
    `ext_corners` (outline corners assigned to the cell)."""

    contour: sg.Polygon
    origin: np.ndarray
    size: float
    frac: np.ndarray
    ext_len: np.ndarray
    ext_corners: np.ndarray

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, columns) of cells."""
        return self.frac.shape

    @property
    def inside(self) -> np.ndarray:
        """Cells at least partly inside the outline."""
        return self.frac > 1e-9

    @property
    def full(self) -> np.ndarray:
        """Cells wholly inside the outline."""
        return self.frac > 1.0 - 1e-9

    @property
    def partial(self) -> np.ndarray:
        """Cells only partly inside the outline (cut by a bevel)."""
        return self.inside & ~self.full

    def to_world(self, cx, cy) -> np.ndarray:
        """Grid-corner coordinates (in cells) to world (x, y), shape (..., 2)."""
        if isinstance(cx, (int, float)) and isinstance(cy, (int, float)):
            return np.array([self.origin[0] + cx * self.size, self.origin[1] + cy * self.size])
        return np.stack([self.origin[0] + np.asarray(cx, float) * self.size,
                         self.origin[1] + np.asarray(cy, float) * self.size], axis=-1)

    def xy(self, cx: float, cy: float) -> tuple[float, float]:
        """One grid-corner coordinate to world, as plain floats."""
        return (float(self.origin[0]) + cx * self.size, float(self.origin[1]) + cy * self.size)


def make_grid(contour: sg.Polygon, frame: tuple[np.ndarray, tuple[int, int]] | None = None,
              size: float = GRID) -> Grid:
    """The grid over `contour`. `frame` = (origin, (ny, nx)) reuses another storey's frame so
    cells line up between storeys; by default the frame is the contour's bounds on the grid."""
    if frame is None:
        x0, y0, x1, y1 = contour.bounds
        origin = np.floor(np.array([x0, y0]) / size + 1e-9) * size
        nx = int(math.ceil((x1 - origin[0]) / size - 1e-9))
        ny = int(math.ceil((y1 - origin[1]) / size - 1e-9))
    else:
        origin, (ny, nx) = np.asarray(frame[0], float), frame[1]
    ix, iy = np.meshgrid(np.arange(nx), np.arange(ny))
    x = origin[0] + ix * size
    y = origin[1] + iy * size
    boxes = shapely.box(x, y, x + size, y + size)
    shapely.prepare(contour)
    frac = shapely.area(shapely.intersection(boxes, contour)) / size**2
    frac = np.where(frac < 1e-6, 0.0, np.where(frac > 1 - 1e-6, 1.0, frac))
    ring = contour.exterior
    # each boundary piece on a shared cell edge is counted by both cells; only inside cells use
    # it, and the outside cell across has frac 0, so nothing is counted twice among rooms
    ext_len = np.where(frac > 0, shapely.length(shapely.intersection(boxes, ring)), 0.0)
    corners = np.zeros((ny, nx), np.int64)
    pts = np.asarray(ring.coords, float)[:-1]
    prev, nxt = np.roll(pts, 1, axis=0), np.roll(pts, -1, axis=0)
    d0, d1 = pts - prev, nxt - pts
    turn = np.abs(np.arctan2(d0[:, 0] * d1[:, 1] - d0[:, 1] * d1[:, 0], (d0 * d1).sum(axis=1)))
    for p, a, b, t in zip(pts, d0, d1, turn, strict=False):
        if t < math.radians(20):
            continue
        bis = -a / np.linalg.norm(a) + b / np.linalg.norm(b)
        probe = p + 1e-3 * bis / max(np.linalg.norm(bis), 1e-12)
        if not contour.contains(sg.Point(probe)):
            probe = p - 1e-3 * bis / max(np.linalg.norm(bis), 1e-12)
        cx, cy = np.floor((probe - origin) / size).astype(int)
        if 0 <= cy < ny and 0 <= cx < nx and frac[cy, cx] > 0:
            corners[cy, cx] += 1
    return Grid(contour, origin, size, frac, ext_len, corners)


# --------------------------------------------------------------------------------------------
# outlines


def pad(a: np.ndarray, width: int = 1, value=0) -> np.ndarray:
    """`a` with a border of `width` cells of `value` on every side (np.pad is slow on small
    arrays)."""
    out = np.full((a.shape[0] + 2 * width, a.shape[1] + 2 * width), value, a.dtype)
    out[width:-width, width:-width] = a
    return out


def trace(mask: np.ndarray) -> np.ndarray | None:
    """The counter-clockwise outline of a 4-connected, hole-free cell mask as (N, 2) grid-corner
    coordinates (x, y), one point per corner; None if the mask is empty, disconnected, has a
    hole or touches itself at a corner.

    Corners are the lattice points whose 2x2 cell neighbourhood holds 1 or 3 inside cells. On a
    simple rectilinear outline, the corners on each grid line, sorted along it, pair up into
    edges; walking the alternating horizontal and vertical edges visits every corner once."""
    m = pad(mask).view(np.int8)
    a, b, c, d = m[:-1, :-1], m[:-1, 1:], m[1:, :-1], m[1:, 1:]
    s = a + b + c + d
    if ((s == 2) & (a == d)).any():
        return None  # two cells touching only at a corner
    cy, cx = np.nonzero(s & 1)
    n = len(cx)
    if n < 4:
        return None
    # horizontal partners: sort by (y, x) and pair consecutive corners; vertical likewise
    h = np.empty(n, np.int64)
    h[0::2], h[1::2] = np.arange(1, n, 2), np.arange(0, n, 2)  # nonzero is already (y, x) order
    ov = np.lexsort((cy, cx))
    v = np.empty(n, np.int64)
    v[ov[0::2]], v[ov[1::2]] = ov[1::2], ov[0::2]
    hl, vl = h.tolist(), v.tolist()
    # corner 0 is the lowest-leftmost, a convex corner; going up first walks clockwise
    order = [0]
    i, horiz = vl[0], True
    while i != 0:
        order.append(i)
        i = hl[i] if horiz else vl[i]
        horiz = not horiz
        if len(order) > n:
            return None
    if len(order) != n:
        return None
    order.reverse()
    return np.stack([cx[order], cy[order]], axis=1).astype(float)


def room_polygon(grid: Grid, mask: np.ndarray) -> sg.Polygon | None:
    """The world polygon of the cells in `mask`, clipped by the outline where it cuts them; None
    if the cells do not form a simple polygon."""
    ys, xs = np.nonzero(mask)
    if len(ys) == 0:
        return None
    y0, x0 = ys.min(), xs.min()
    crop = mask[y0:ys.max() + 1, x0:xs.max() + 1]
    xy = trace(crop)
    if xy is None:
        return None
    pts = grid.to_world(xy[:, 0] + x0, xy[:, 1] + y0)
    poly = sg.Polygon(pts)
    if (grid.partial & mask).any():
        poly = poly.intersection(grid.contour)
        if not isinstance(poly, sg.Polygon):
            parts = [g for g in getattr(poly, "geoms", []) if isinstance(g, sg.Polygon)]
            if len(parts) != 1:
                return None
            poly = parts[0]
        poly = shapely.simplify(poly, 1e-9)
        if poly.is_empty or poly.interiors:
            return None
    return poly


# --------------------------------------------------------------------------------------------
# wall runs


@dataclass(frozen=True)
class Run:
    """A straight run of grid-cell edges: on the horizontal (axis 0: y = line) or vertical
    (axis 1: x = line) grid line `line`, from `start` to `end` along it (cell units); `left` is
    the label on the lower / left side, `right` the other."""

    axis: int
    line: int
    start: int
    end: int
    left: int
    right: int

    @property
    def length(self) -> int:
        """Number of cell edges in the run."""
        return self.end - self.start


def runs(labels: np.ndarray, full: np.ndarray) -> list[Run]:
    """Every maximal straight run of cell edges with the same (left, right) label pair, where
    the labels differ and both cells are full (or outside the outline). Outside is -1."""
    ny, nx = labels.shape
    lab = pad(labels, 1, OUTSIDE)
    ok = pad(full | (labels == OUTSIDE), 1, True)
    out: list[Run] = []
    for axis in (0, 1):
        if axis == 0:   # horizontal lines y = 0..ny between rows r-1 (below) and r (above)
            a, b = lab[:-1, 1:-1], lab[1:, 1:-1]
            valid = (a != b) & ok[:-1, 1:-1] & ok[1:, 1:-1]
        else:           # vertical lines x = 0..nx between cols c-1 (left) and c (right)
            a, b = lab[1:-1, :-1].T, lab[1:-1, 1:].T
            valid = (a != b) & ok[1:-1, :-1].T & ok[1:-1, 1:].T
        code = np.where(valid, (a + 1) * 100003 + (b + 1), -1)
        n_lines, n_pos = code.shape
        flat = np.concatenate([code, np.full((n_lines, 1), -1)], axis=1).ravel()
        edges = np.flatnonzero(np.diff(np.concatenate([[-2], flat])) != 0)
        starts, ends = edges, np.append(edges[1:], len(flat))
        keep = flat[starts] >= 0
        starts, ends = starts[keep], ends[keep]
        cd = flat[starts]
        ln, s = np.divmod(starts, n_pos + 1)
        for li, si, ei, ci in zip(ln.tolist(), s.tolist(), (s + ends - starts).tolist(),
                                  cd.tolist(), strict=False):
            out.append(Run(axis, li, si, ei, ci // 100003 - 1, ci % 100003 - 1))
    return out


# --------------------------------------------------------------------------------------------
# morphology


def _window_sum(m: np.ndarray, k: int) -> np.ndarray:
    """Sum over each k x k window (output shape (ny-k+1, nx-k+1))."""
    c = np.zeros((m.shape[0] + 1, m.shape[1] + 1), np.int32)
    c[1:, 1:] = np.cumsum(np.cumsum(m, axis=0, dtype=np.int32), axis=1)
    return c[k:, k:] - c[:-k, k:] - c[k:, :-k] + c[:-k, :-k]


def square_pieces(mask: np.ndarray, k: int) -> int:
    """How many separate places a k x k square can slide around in inside `mask` (connected
    by one-cell steps): more than one where a neck narrower than k joins parts of it."""
    ny, nx = mask.shape
    if k <= 1 or ny < k or nx < k:
        return int(ndimage.label(mask)[1])
    return int(ndimage.label(_window_sum(mask, k) == k * k)[1])


def opening(mask: np.ndarray, k: int) -> np.ndarray:
    """Morphological opening of `mask` by a k x k square: the union of all k x k squares of
    cells inside it. Cells of `mask` not in the result are where it is narrower than k."""
    if k <= 1:
        return mask.copy()
    ny, nx = mask.shape
    if ny < k or nx < k:
        return np.zeros_like(mask)
    fits = _window_sum(mask, k) == k * k           # squares with top-left (lower-left) corner
    return _window_sum(pad(fits, k - 1, False), k) > 0  # cells covered by a fitting square
