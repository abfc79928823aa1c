"""A home's floorplan as plain data: storeys of room polygons with doors, open connections and
windows, the stairs between storeys and the front entrance.

This is what `floorplan.json` holds (see `io.py` for the exact schema) and what `solidify`
turns into walls, floors, ceilings, doors, windows and stairs. Room polygons are the rooms'
*partition* polygons: walls are centred on their shared edges, and the rooms of a storey
partition its outline. Storey k's floor is at `elevation`, its ceiling `height` above it.

Stair convention: a stair's `polygon` is the flight's footprint listed from the bottom step's
left corner: [bottom-left, bottom-right, top-right, top-left], "left" as seen walking up. So the
first edge is the front of the lowest step and the flight climbs from edge 0-1 to edge 3-2.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely
import shapely.geometry as sg

Point = tuple[float, float]


@dataclass
class RoomSpec:
    """A room: unique `name`, `type` (a RoomType value) and CCW partition polygon."""

    name: str
    type: str
    polygon: list[Point]

    def shape(self) -> sg.Polygon:
        return sg.Polygon(self.polygon)


@dataclass
class DoorSpec:
    """A door (or, as an opening, a doorless gap) in the wall between `rooms`, centred on the
    wall's centre line at `center`."""

    name: str
    rooms: tuple[str, str]
    center: Point
    width: float
    height: float


@dataclass
class WindowSpec:
    """A window in an exterior wall of `room`: `sill` metres above the floor, `height` tall."""

    name: str
    room: str
    center: Point
    width: float
    height: float
    sill: float


@dataclass
class StairSpec:
    """A straight flight from storey `from_level` to `to_level` (see module docstring for the
    polygon's order)."""

    from_level: int
    to_level: int
    polygon: list[Point]

    def frame(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float]:
        """(bottom-left corner, unit direction up the flight, unit direction to the right,
        run length, width)."""
        p = np.asarray(self.polygon, float)
        up = p[3] - p[0]
        right = p[1] - p[0]
        run, width = float(np.linalg.norm(up)), float(np.linalg.norm(right))
        return p[0], up / run, right / width, run, width

    def shape(self) -> sg.Polygon:
        return shapely.geometry.polygon.orient(sg.Polygon(self.polygon), 1.0)


@dataclass
class Entrance:
    """The front door: in an exterior wall of `room` (ground floor), centred at `center`."""

    room: str
    center: Point
    width: float = 1.0
    height: float = 2.1


@dataclass
class Storey:
    level: int
    elevation: float
    height: float
    rooms: list[RoomSpec] = field(default_factory=list)
    doors: list[DoorSpec] = field(default_factory=list)
    windows: list[WindowSpec] = field(default_factory=list)
    openings: list[DoorSpec] = field(default_factory=list)

    def room(self, name: str) -> RoomSpec:
        for r in self.rooms:
            if r.name == name:
                return r
        raise KeyError(name)

    def contour(self) -> sg.Polygon:
        """The storey's outline: the union of its rooms."""
        return shapely.union_all([r.shape() for r in self.rooms]).buffer(0)


@dataclass
class Floorplan:
    """A whole home. `info` carries what produced it (seed, solver statistics); it is not part
    of floorplan.json."""

    storeys: list[Storey]
    stairs: list[StairSpec] = field(default_factory=list)
    entrance: Entrance | None = None
    info: dict[str, Any] = field(default_factory=dict)

    def rooms(self) -> list[tuple[Storey, RoomSpec]]:
        return [(s, r) for s in self.storeys for r in s.rooms]

    def storey_of(self, room: str) -> Storey:
        for s in self.storeys:
            if any(r.name == room for r in s.rooms):
                return s
        raise KeyError(room)
