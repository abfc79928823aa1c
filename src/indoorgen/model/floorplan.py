"""A home's floorplan as plain data: storeys of room polygons with doors, open connections and
windows, the stairs between storeys and the front entrance.

This is what `floorplan.json` holds (see `floorplan_io` for the exact schema), what the
floorplan solver (`indoorgen.floorplan`) produces and what `architecture.solidify` turns into
walls, floors, ceilings, doors, windows and stairs. Room polygons are the rooms'
*partition* polygons: walls are centred on their shared edges, and the rooms of a storey
partition its outline. Storey k's floor is at `elevation`, its ceiling `height` above it.

Stair convention: a stair's `polygon` is the flight's footprint listed from the bottom step's
left corner: [bottom-left, bottom-right, top-right, top-left], "left" as seen walking up. So the
first edge is the front of the lowest step and the flight climbs from edge 0-1 to edge 3-2.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import networkx as nx
import numpy as np
import numpy.typing as npt
import shapely
import shapely.geometry as sg

Point = tuple[float, float]
Vector = npt.NDArray[np.float64]


@dataclass
class RoomSpec:
    """A room: unique `name`, `type` (a `room_types` name) and CCW partition polygon."""

    name: str
    type: str
    polygon: list[Point]

    def shape(self) -> sg.Polygon:
        """The polygon as a shapely Polygon."""
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

    def frame(self) -> tuple[Vector, Vector, Vector, float, float]:
        """(bottom-left corner, unit direction up the flight, unit direction to the right,
        run length, width)."""
        p = np.asarray(self.polygon, float)
        up = p[3] - p[0]
        right = p[1] - p[0]
        run, width = float(np.linalg.norm(up)), float(np.linalg.norm(right))
        return p[0], up / run, right / width, run, width

    def shape(self) -> sg.Polygon:
        """The footprint as a counter-clockwise shapely Polygon."""
        return shapely.geometry.polygon.orient(sg.Polygon(self.polygon), 1.0)


@dataclass
class Entrance:
    """The front door: in an exterior wall of `room` (ground floor), centred at `center`."""

    room: str
    center: Point
    width: float = 1.0
    height: float = 2.1


@dataclass
class VehicleDoor:
    """A garage's vehicle door: an opening `width` wide in an exterior wall of ground-floor room
    `room` (a garage), centred at `center`."""

    room: str
    center: Point
    width: float = 2.4
    height: float = 2.1


@dataclass
class Storey:
    """Storey `level` (0: the ground floor): its floor's `elevation` and ceiling `height` above
    it (m), its rooms and the doors, windows and open connections between them."""

    level: int
    elevation: float
    height: float
    rooms: list[RoomSpec] = field(default_factory=list)
    doors: list[DoorSpec] = field(default_factory=list)
    windows: list[WindowSpec] = field(default_factory=list)
    openings: list[DoorSpec] = field(default_factory=list)

    def room(self, name: str) -> RoomSpec:
        """The room called `name` (KeyError if not on this storey)."""
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
    #: garages' vehicle doors (ground floor)
    vehicle_doors: list[VehicleDoor] = field(default_factory=list)

    def rooms(self) -> list[tuple[Storey, RoomSpec]]:
        """Every room with its storey, storey by storey."""
        return [(s, r) for s in self.storeys for r in s.rooms]

    def storey_of(self, room: str) -> Storey:
        """The storey holding `room` (KeyError if none)."""
        for s in self.storeys:
            if any(r.name == room for r in s.rooms):
                return s
        raise KeyError(room)

    def stair_rooms(self, st: StairSpec) -> tuple[str | None, str | None]:
        """The rooms holding a flight's foot (lower storey) and its head (upper storey)."""
        poly = st.shape()
        out = []
        for lv in (st.from_level, st.to_level):
            storey = next((s for s in self.storeys if s.level == lv), None)
            best = None
            if storey is not None:
                areas = [(r.shape().intersection(poly).area, r.name) for r in storey.rooms]
                best = max(areas)[1] if areas and max(areas)[0] > 0 else None
            out.append(best)
        return out[0], out[1]

    def connection_graph(self) -> nx.Graph:
        """Rooms (nodes, storey by storey) joined by doors, open connections and stairs."""
        g = nx.Graph()
        for s in self.storeys:
            g.add_nodes_from(r.name for r in s.rooms)
            g.add_edges_from(tuple(d.rooms) for d in s.doors + s.openings)
        for st in self.stairs:
            a, b = self.stair_rooms(st)
            if a and b:
                g.add_edge(a, b)
        return g

    def room_depths(self) -> dict[str, int]:
        """Rooms' distance (in doors) from the front door, going up stairs (rooms out of reach
        one more than the farthest): doors swing into the deeper room."""
        g = self.connection_graph()
        start = self.entrance.room if self.entrance else self.storeys[0].rooms[0].name
        depth = dict(nx.single_source_shortest_path_length(g, start))
        far = max(depth.values(), default=0) + 1
        return {n: depth.get(n, far) for n in g.nodes}
