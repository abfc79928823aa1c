"""A storey's free floor as a boolean grid: what a walking agent may stand on.

Per storey, at `cell` metres (5 cm by default), the free floor is the union of the storey's room
floor polygons (`scene.Room.polygon` is the floor inside the wall faces, so walls are already
out) plus each door's opening through its wall (an open door's leaf stands in its swing zone,
which the solver keeps free; a shut door's passage is left out), minus the stair flight on the
storey it starts from and the stairwell on the storey above, minus every obstacle between
`model.walkable.BAND` heights above that storey's floor: objects (each convex placeholder piece
clipped to the band, its outline the convex hull of the clipped piece) and railings. Windows are
part of the walls.

The grid, the band outlines, erosion by the agent's radius and door edges are in
`model.walkable`, which the solver's circulation term shares.
"""
from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.assets.cache import AssetCache
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.scene import Room, Scene
from indoorgen.model.walkable import CELL, Grid, approach_strip, band_outlines, door_segment

#: How far a door with a room on one side only (the entrance, a single room's door) is opened
#: outward through its wall (m): more than the thickest wall.
LONE_DOOR_DEPTH = 0.3
#: Two rooms' door edges farther apart than this (m) are not one door seen from both sides.
DOOR_PAIR_GAP = 0.6


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
        return approach_strip(seg, inward, depth)

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


def door_sites(rooms: Iterable[Room]) -> dict[str, DoorSite]:
    """Every door of `rooms` (one storey) by name, with its passage through the wall: between
    the two rooms' door edges when both rooms list it, else `LONE_DOOR_DEPTH` outward."""
    sides: dict[str, list[tuple[str, np.ndarray, np.ndarray]]] = {}
    for room in rooms:
        for d in room.doors:
            seg, inward = door_segment(np.asarray(room.polygon, float), d.wall, d.offset, d.width)
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
                     cell: float = CELL) -> StoreyOccupancy:
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
