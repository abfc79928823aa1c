"""A storey's free floor as a boolean grid: what a walking agent may stand on.

Per storey, at `cell` metres (5 cm by default), the free floor is the union of the storey's room
floor polygons (`scene.Room.polygon` is the floor inside the wall faces, so walls are already
out) plus each door's opening through its wall (an open door's leaf stands in its swing zone,
which the solver keeps free; a shut door's passage is left out), minus the stair flight on the
storey it starts from and the stairwell on the storey above, minus every obstacle between `BAND`
heights above that storey's floor: objects (each convex placeholder piece clipped to the band,
its outline the convex hull of the clipped piece) and railings. Windows are part of the walls.

`erode` keeps the cells an agent's centre can occupy; `cover` is the floor its body sweeps from
a set of centres. Both use scipy's Euclidean distance transform on cell centres.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import numpy as np
import shapely
import shapely.geometry as sg
import trimesh
from scipy import ndimage

from indoorgen.assets.cache import AssetCache
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.polygons import signed_area
from indoorgen.model.scene import Room, Scene

#: Heights above a storey's floor (m) between which anything is an obstacle to a walking agent.
BAND = (0.02, 1.8)
#: How far a door with a room on one side only (the entrance, a single room's door) is opened
#: outward through its wall (m): more than the thickest wall.
LONE_DOOR_DEPTH = 0.3
#: Two rooms' door edges farther apart than this (m) are not one door seen from both sides.
DOOR_PAIR_GAP = 0.6
#: Margin round the storey in the grid (m).
GRID_MARGIN = 0.5


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

    def rasterise(self, geoms: Iterable[sg.base.BaseGeometry]) -> np.ndarray:
        """Cells whose centre lies in any of `geoms` (each tested on its bounding-box window)."""
        mask = np.zeros(self.shape, bool)
        ny, nx = self.shape
        for g in geoms:
            if g.is_empty:
                continue
            minx, miny, maxx, maxy = g.bounds
            j0 = max(int(np.floor((minx - self.x0) / self.cell - 0.5)), 0)
            j1 = min(int(np.ceil((maxx - self.x0) / self.cell - 0.5)) + 1, nx)
            i0 = max(int(np.floor((miny - self.y0) / self.cell - 0.5)), 0)
            i1 = min(int(np.ceil((maxy - self.y0) / self.cell - 0.5)) + 1, ny)
            if j0 >= j1 or i0 >= i1:
                continue
            xs = self.x0 + (np.arange(j0, j1) + 0.5) * self.cell
            ys = self.y0 + (np.arange(i0, i1) + 0.5) * self.cell
            xx, yy = np.meshgrid(xs, ys)
            mask[i0:i1, j0:j1] |= shapely.contains_xy(g, xx, yy)
        return mask

    def area(self, mask: np.ndarray) -> float:
        """Area (m^2) of the cells set in `mask`."""
        return float(np.count_nonzero(mask)) * self.cell ** 2


@dataclass
class DoorSite:
    """A door or open connection on one storey: its `passage` through the wall and, per room it
    opens into, the door's edge on that room's floor (two points) and the unit normal into the
    room."""

    name: str
    passage: sg.Polygon
    sides: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)

    def approach(self, room: str, depth: float) -> sg.Polygon:
        """The strip `depth` deep in front of the door on `room`'s side, the door's width."""
        seg, inward = self.sides[room]
        return sg.Polygon([seg[0], seg[1], seg[1] + depth * inward, seg[0] + depth * inward])

    @property
    def centre(self) -> np.ndarray:
        """The middle of the passage."""
        c = self.passage.centroid
        return np.array([c.x, c.y])


@dataclass
class StoreyOccupancy:
    """One storey on its grid: `floor` (rooms and door passages, stairs cut out), `obstacles`
    (objects and railings in the band) and `free` = floor and not obstacle; rooms' polygons
    and door sites for the analyses built on it."""

    level: int
    elevation: float
    grid: Grid
    floor: np.ndarray
    obstacles: np.ndarray
    rooms: dict[str, sg.Polygon]
    doors: dict[str, DoorSite]

    @property
    def free(self) -> np.ndarray:
        """Cells an agent of zero radius may stand on."""
        return np.asarray(self.floor & ~self.obstacles)


def door_segment(room: Room, wall: int, offset: float, width: float
                 ) -> tuple[np.ndarray, np.ndarray]:
    """A door's edge on `room`'s floor polygon (2, 2) and the unit normal into the room."""
    p = np.asarray(room.polygon, float)
    a, b = p[wall], p[(wall + 1) % len(p)]
    d = (b - a) / np.linalg.norm(b - a)
    inward = np.array([-d[1], d[0]])
    if signed_area(p) < 0:  # clockwise polygon: the left-hand normal points out
        inward = -inward
    mid = a + d * offset
    return np.stack([mid - d * width / 2, mid + d * width / 2]), inward


def door_sites(rooms: Iterable[Room]) -> dict[str, DoorSite]:
    """Every door of `rooms` (one storey) by name, with its passage through the wall: between
    the two rooms' door edges when both rooms list it, else `LONE_DOOR_DEPTH` outward."""
    sides: dict[str, list[tuple[str, np.ndarray, np.ndarray]]] = {}
    for room in rooms:
        for d in room.doors:
            seg, inward = door_segment(room, d.wall, d.offset, d.width)
            sides.setdefault(d.name, []).append((room.name, seg, inward))
    out = {}
    for name in sorted(sides):
        found = sides[name]
        pair = (len(found) == 2 and
                float(np.abs(np.mean(found[0][1], axis=0) - np.mean(found[1][1], axis=0)).max())
                < DOOR_PAIR_GAP)
        if pair:
            passage = sg.MultiPoint(np.vstack([found[0][1], found[1][1]])).convex_hull
        else:
            seg, inward = found[0][1], found[0][2]
            passage = sg.Polygon([seg[0], seg[1], seg[1] - LONE_DOOR_DEPTH * inward,
                                  seg[0] - LONE_DOOR_DEPTH * inward])
        out[name] = DoorSite(name, passage, {r: (seg, inward) for r, seg, inward in found})
    return out


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


def object_obstacles(scene: Scene, cache: AssetCache, level: int, elevation: float
                     ) -> dict[str, list[sg.Polygon]]:
    """Band outlines of every object in a room of storey `level`, by object name (objects
    entirely outside the band have none)."""
    out = {}
    for name in sorted(scene.objects):
        ob = scene.objects[name]
        room = scene.rooms.get(ob.room)
        if room is None or room.storey != level:
            continue
        pieces = [m for _, m in cache.placeholder(ob.generator, ob.params).collision]
        polys = band_outlines(pieces, ob.pose.matrix(), elevation)
        if polys:
            out[name] = polys
    return out


def storey_occupancy(scene: Scene, cache: AssetCache, level: int, *,
                     rooms: Mapping[str, Room] | None = None, floorplan: Floorplan | None = None,
                     extra_obstacles: Iterable[sg.Polygon] = (), shut: Iterable[str] = (),
                     cell: float = 0.05) -> StoreyOccupancy:
    """The occupancy grid of storey `level` of `scene`: rooms and the passages of doors not
    `shut` (names), less stair footprints and stairwells (from `floorplan`'s stairs), objects
    and `extra_obstacles` (e.g. railings' outlines in the band). `rooms` defaults to
    `scene.rooms`."""
    here = {n: r for n, r in sorted((rooms or scene.rooms).items()) if r.storey == level}
    if not here:
        raise ValueError(f"scene has no room on storey {level}")
    elevation = next(iter(here.values())).elevation
    polys = {n: sg.Polygon(r.polygon) for n, r in here.items()}
    doors = door_sites(here.values())
    holes = [sg.Polygon(st.polygon) for st in (floorplan.stairs if floorplan else [])
             if level in (st.from_level, st.to_level)]
    shut = set(shut)
    walkable = [*polys.values(), *(d.passage for n, d in doors.items() if n not in shut)]
    grid = Grid.covering(shapely.union_all(walkable).bounds, cell)
    floor = grid.rasterise(walkable) & ~grid.rasterise(holes)
    blocking = [p for ps in object_obstacles(scene, cache, level, elevation).values() for p in ps]
    obstacles = grid.rasterise([*blocking, *extra_obstacles])
    return StoreyOccupancy(level, elevation, grid, floor, obstacles, polys, doors)


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
