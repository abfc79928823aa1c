"""Where a walking agent may go: the floor rasterised at a few centimetres, obstacles seen in
the agent's height band, erosion by its radius, door edges and the points in front of objects it
must reach.

Shared by the solver's circulation term (one room at a time, while it furnishes) and the
navigation measure (a whole storey, on a finished scene), so both see the floor alike.

A `Grid`'s cell (i, j) has its centre at (x0 + (j + 0.5) cell, y0 + (i + 0.5) cell). `erode`
keeps the cells an agent's centre can occupy; `cover` is the floor its body sweeps from a set of
centres. Both use scipy's Euclidean distance transform on cell centres.
"""
from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.geometry as sg
import trimesh
from scipy import ndimage

from indoorgen.model.polygons import signed_area
from indoorgen.model.tags import Semantics

#: Heights above a storey's floor (m) between which anything is an obstacle to a walking agent.
BAND = (0.02, 1.8)
#: Radius of the walking agent (m): issue 11's robot.
AGENT_RADIUS = 0.25
#: Side of a grid cell (m).
CELL = 0.05
#: Margin round the rasterised region in the grid (m).
GRID_MARGIN = 0.5
#: Depth beyond the agent's radius of the strips in front of doors and at stair ends (m).
APPROACH = 0.3
#: Gap between an object's front face and the agent's edge at its front point (m).
FRONT_GAP = 0.1
#: A front point counts as reached when a reachable centre lies this close (m).
FRONT_TOLERANCE = 0.1
#: Large objects used from the front: seating, storage, appliances, fixtures, desks.
FRONT_TAGS = frozenset(t.value for t in (
    Semantics.Sofa, Semantics.SectionalSofa, Semantics.Armchair, Semantics.Wardrobe,
    Semantics.Dresser, Semantics.Bookcase, Semantics.Appliance, Semantics.KitchenCabinet,
    Semantics.KitchenSink, Semantics.KitchenIsland, Semantics.Vanity, Semantics.BathroomSink,
    Semantics.Toilet, Semantics.Bathtub, Semantics.Shower, Semantics.Desk))
#: Seats a person may step up to anywhere along the front: a coffee table 0.35-0.45 m before a
#: sofa leaves no passage for the agent, who sits down at the end of the seat beside the table.
SEAT_TAGS = frozenset(t.value for t in (Semantics.Sofa, Semantics.SectionalSofa,
                                        Semantics.Armchair))
#: Large objects used from their sides.
BED_TAGS = frozenset(t.value for t in (Semantics.Bed, Semantics.BunkBed))

#: A rasterised piece of a grid: (row start, column start, boolean mask of the window).
Patch = tuple[int, int, np.ndarray]


@dataclass(frozen=True)
class Grid:
    """A regular grid of square cells of side `cell`; cell (i, j) has its centre at
    (x0 + (j + 0.5) cell, y0 + (i + 0.5) cell): rows run along y, columns along x."""

    x0: float
    y0: float
    cell: float
    shape: tuple[int, int]

    @classmethod
    def covering(cls, bounds: tuple[float, float, float, float], cell: float,
                 margin: float = GRID_MARGIN) -> Grid:
        """The grid covering `bounds` (minx, miny, maxx, maxy) plus `margin` on every side."""
        x0, y0 = bounds[0] - margin, bounds[1] - margin
        nx = int(np.ceil((bounds[2] + margin - x0) / cell))
        ny = int(np.ceil((bounds[3] + margin - y0) / cell))
        return cls(float(x0), float(y0), float(cell), (ny, nx))

    @property
    def extent(self) -> tuple[float, float, float, float]:
        """(left, right, bottom, top) of the grid, as matplotlib's imshow takes it."""
        ny, nx = self.shape
        return (self.x0, self.x0 + nx * self.cell, self.y0, self.y0 + ny * self.cell)

    def window(self, bounds: tuple[float, float, float, float]
               ) -> tuple[int, int, np.ndarray, np.ndarray] | None:
        """The cells whose centres may lie in `bounds` (minx, miny, maxx, maxy): first row and
        column and the centres' x and y coordinates; None when no cell does."""
        ny, nx = self.shape
        minx, miny, maxx, maxy = bounds
        j0 = max(int(np.floor((minx - self.x0) / self.cell - 0.5)), 0)
        j1 = min(int(np.ceil((maxx - self.x0) / self.cell - 0.5)) + 1, nx)
        i0 = max(int(np.floor((miny - self.y0) / self.cell - 0.5)), 0)
        i1 = min(int(np.ceil((maxy - self.y0) / self.cell - 0.5)) + 1, ny)
        if j0 >= j1 or i0 >= i1:
            return None
        xs = self.x0 + (np.arange(j0, j1) + 0.5) * self.cell
        ys = self.y0 + (np.arange(i0, i1) + 0.5) * self.cell
        return i0, j0, xs, ys

    def patches(self, geoms: Iterable[sg.base.BaseGeometry]) -> list[Patch]:
        """Each geometry's cells (those whose centre it contains) over its bounding-box window."""
        out = []
        for g in geoms:
            if g.is_empty:
                continue
            w = self.window(g.bounds)
            if w is None:
                continue
            i0, j0, xs, ys = w
            xx, yy = np.meshgrid(xs, ys)
            out.append((i0, j0, shapely.contains_xy(g, xx, yy)))
        return out

    def disc(self, centre: np.ndarray, radius: float) -> Patch | None:
        """The cells whose centre lies within `radius` of `centre` (x, y); None if none does."""
        x, y = float(centre[0]), float(centre[1])
        w = self.window((x - radius, y - radius, x + radius, y + radius))
        if w is None:
            return None
        i0, j0, xs, ys = w
        inside = (xs[None, :] - x) ** 2 + (ys[:, None] - y) ** 2 <= radius * radius
        return i0, j0, inside

    def near_boxes(self, boxes: np.ndarray, rotation: np.ndarray, translation: np.ndarray,
                   margin: float) -> list[Patch]:
        """Per box, the cells whose centre lies within `margin` of it: `boxes` (k, 2, 2) are
        local XY boxes (low and high corners) placed by 2x2 `rotation` and `translation`. With
        `margin` an agent's radius, these are the centres the boxes keep the agent from."""
        out = []
        lo, hi = np.asarray(boxes, float)[:, 0], np.asarray(boxes, float)[:, 1]
        half = (hi - lo) / 2
        centre = (lo + hi) / 2 @ rotation.T + translation
        reach = half @ np.abs(rotation).T + margin
        for c, h, r in zip(centre, half, reach, strict=True):
            w = self.window((c[0] - r[0], c[1] - r[1], c[0] + r[0], c[1] + r[1]))
            if w is None:
                continue
            i0, j0, xs, ys = w
            # the cells' centres in the box's frame, then their distance to the box
            dx, dy = xs[None, :] - c[0], ys[:, None] - c[1]
            u = np.abs(dx * rotation[0, 0] + dy * rotation[1, 0]) - h[0]
            v = np.abs(dx * rotation[0, 1] + dy * rotation[1, 1]) - h[1]
            out.append((i0, j0, np.maximum(u, 0) ** 2 + np.maximum(v, 0) ** 2
                        < margin * margin))
        return out

    def rasterise(self, geoms: Iterable[sg.base.BaseGeometry]) -> np.ndarray:
        """Cells whose centre lies in any of `geoms` (each tested on its bounding-box window)."""
        return paint(np.zeros(self.shape, bool), self.patches(geoms))

    def area(self, mask: np.ndarray) -> float:
        """Area (m^2) of the cells set in `mask`."""
        return float(np.count_nonzero(mask)) * self.cell ** 2


def paint(mask: np.ndarray, patches: Iterable[Patch]) -> np.ndarray:
    """Set the cells of `patches` in `mask` (in place) and return it."""
    for i0, j0, m in patches:
        mask[i0:i0 + m.shape[0], j0:j0 + m.shape[1]] |= m
    return mask


def patch_values(values: np.ndarray, patch: Patch) -> np.ndarray:
    """The entries of `values` (a grid-shaped array) at the cells set in `patch`."""
    i0, j0, m = patch
    return values[i0:i0 + m.shape[0], j0:j0 + m.shape[1]][m]


def door_segment(polygon: np.ndarray, wall: int, offset: float, width: float
                 ) -> tuple[np.ndarray, np.ndarray]:
    """A door's edge on a room's floor `polygon` (2, 2) and the unit normal into the room: the
    door is centred `offset` along edge `wall` (vertex `wall` -> `wall + 1`)."""
    p = np.asarray(polygon, float)
    a, b = p[wall], p[(wall + 1) % len(p)]
    d = (b - a) / np.linalg.norm(b - a)
    inward = np.array([-d[1], d[0]])
    if signed_area(p) < 0:  # clockwise polygon: the left-hand normal points out
        inward = -inward
    mid = a + d * offset
    return np.stack([mid - d * width / 2, mid + d * width / 2]), inward


def approach_strip(segment: np.ndarray, inward: np.ndarray, depth: float) -> sg.Polygon:
    """The strip `depth` deep in front of a door's edge `segment`, on the side `inward` points."""
    return sg.Polygon([segment[0], segment[1], segment[1] + depth * inward,
                       segment[0] + depth * inward])


def band_boxes(boxes: np.ndarray, lift: float, band: tuple[float, float] = BAND) -> np.ndarray:
    """The XY boxes (k, 2, 2) of local boxes `boxes` (k, 2, 3) that reach into heights `band`
    above the floor when their frame stands `lift` above it."""
    b = np.asarray(boxes, float).reshape(-1, 2, 3)
    keep = (b[:, 1, 2] + lift >= band[0]) & (b[:, 0, 2] + lift <= band[1])
    return b[keep][:, :, :2]


def band_outlines(pieces: Iterable[trimesh.Trimesh], transform: np.ndarray, floor_z: float,
                  band: tuple[float, float] = BAND) -> list[sg.Polygon]:
    """World-XY outlines of convex `pieces` (local meshes placed by 4x4 `transform`) clipped to
    heights `band` above `floor_z`: the convex hull of each clipped piece, seen from above."""
    lo, hi = floor_z + band[0], floor_z + band[1]
    out = []
    for piece in pieces:
        v = np.asarray(piece.vertices, float) @ transform[:3, :3].T + transform[:3, 3]
        z = v[:, 2]
        if z.max() < lo or z.min() > hi:
            continue
        pts = [v[(z >= lo) & (z <= hi), :2]]
        e = np.asarray(piece.edges_unique)
        za, zb = z[e[:, 0]], z[e[:, 1]]
        for h in (lo, hi):
            cross = (za - h) * (zb - h) < 0
            if cross.any():
                t = ((h - za[cross]) / (zb[cross] - za[cross]))[:, None]
                pts.append(v[e[cross, 0], :2] + t * (v[e[cross, 1], :2] - v[e[cross, 0], :2]))
        hull = sg.MultiPoint(np.vstack(pts)).convex_hull
        if isinstance(hull, sg.Polygon):
            out.append(hull)
        elif not hull.is_empty:  # a flat piece seen edge-on: a thin sliver still blocks
            out.append(hull.buffer(0.005))
    return out


def access_points(tags: Iterable[str], bounds: np.ndarray, radius: float) -> list[np.ndarray]:
    """Local XY points (object frame, front +X) an agent of `radius` must reach to use an object
    with `tags` and local bounding box `bounds` (2, 3); any one of them suffices: the front
    point (for a seat also the two ends of its front), or for a bed its two side points; [] when
    its front does not matter."""
    tags = set(tags)
    if not tags & (FRONT_TAGS | BED_TAGS):
        return []
    (x0, y0, _), (x1, y1, _) = np.asarray(bounds, float)
    gap = radius + FRONT_GAP
    xc, yc = (x0 + x1) / 2, (y0 + y1) / 2
    if tags & BED_TAGS:
        return [np.array([xc, y1 + gap]), np.array([xc, y0 - gap])]
    if tags & SEAT_TAGS:
        return [np.array([x1 + gap, y]) for y in (yc, y0, y1)]
    return [np.array([x1 + gap, yc])]


def erode(free: np.ndarray, radius: float, cell: float) -> np.ndarray:
    """Cells where a disc of `radius` centred on the cell stays on `free` cells: a cell centre
    at least `radius` from the edge of the free region (which lies half a cell beyond the last
    free centre)."""
    dist = ndimage.distance_transform_edt(free) * cell
    return np.asarray(dist >= radius + cell / 2)


def cover(centres: np.ndarray, free: np.ndarray, radius: float, cell: float) -> np.ndarray:
    """Free cells within `radius` of a cell of `centres`: the floor swept by a disc of `radius`
    whose centre may be anywhere in `centres`."""
    if not centres.any():
        return np.zeros_like(free)
    dist = ndimage.distance_transform_edt(~centres) * cell
    return np.asarray((dist <= radius + 1e-9) & free)
