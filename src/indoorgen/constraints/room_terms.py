"""Room-level terms of the constraint DSL, for floorplan programs (Infinigen Indoors, D.3).

A floorplan program is an ordinary `Problem` whose objects are rooms (tagged `Semantics.Room`
plus their type, e.g. ``"bedroom"``) and storeys (tagged ``"storey"``)::

    rooms = scene()[Semantics.Room]
    bedrooms = rooms_of(rooms, "bedroom")
    Problem(constraints={"bedrooms see outside": bedrooms.all(
                lambda r: longest_exterior_wall(r) >= 1.5)},
            score_terms={"square rooms": rooms.sum(
                lambda r: (aspect_ratio(r) - 1) ** 2).minimize()})

Every term here is a `GeometricTerm`: it watches the rooms it reads, so the incremental
`Evaluator` recomputes, after a floorplan move, only the terms of the 1-3 rooms the move changed
(plus the few terms that read a changed room indirectly, such as a path through it).

The terms read a *room view*: an `ObjectView` over rooms that also offers the methods of
`RoomView` below. `RoomView` computes everything from room polygons, so a view over any plan
(generated or predefined) only has to supply the abstract methods; the floorplan solver's grid
view overrides the measures it can get faster from its cell grid.
"""
from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Hashable, Iterable
from functools import reduce
from typing import Any, TypeVar, cast

import networkx as nx
import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.constraints.node import Env, EvalContext, Tag
from indoorgen.constraints.scalars import Scalar, ScalarLike, as_scalar
from indoorgen.constraints.sets import ObjSet
from indoorgen.constraints.terms import GeometricTerm
from indoorgen.model.tags import Semantics

#: Tag of storey objects; the id of the staircase placeholder (watched by the staircase terms).
STOREY = "storey"
STAIR_PLACEHOLDER = "stair_placeholder"
#: Shortest straight shared wall (m) that takes a door (0.8-0.9 m leaf, margins, wall ends).
MIN_DOOR_WALL = 1.5
#: Shortest straight exterior wall (m) that takes a garage's 2.4 m vehicle door with margins.
MIN_VEHICLE_DOOR_WALL = 3.0
#: A balcony's least share of its outline on the storey's outline, and its shortest straight
#: outside edge (m): it sits on the edge of the home, not inside it (issue 11).
MIN_BALCONY_EXTERIOR_SHARE = 0.3
MIN_BALCONY_FRONT = 2.0
#: Narrowest a garage may be (m): a car and room to open its door (issue 11 saw a 14 x 2 m one).
MIN_GARAGE_WIDTH = 3.0
#: rooms one passes through or keeps things in: a storey with area to spare gives it to the
#: rooms one lives in, not to these (`ideal_areas`; a 24 m^2 bathroom beside a 14 m^2 bedroom,
#: an 11 m^2 closet and a 47.5 m^2 staircase room were what plain typical-area shares made)
SERVICE_ROOMS = frozenset({"bathroom", "closet", "utility", "staircase_room"})
#: Narrowest a generated plan makes a room of these types (m, by type name, on wall centre
#: lines): a bedroom fits a bed with a walkway beside it, a living room a sofa facing a TV across
#: a coffee table, a dining room a table with chairs pulled out, a kitchen a counter with room
#: to work at it, a bathroom a bath across its end (issue 11 saw a 1.5 x 14 m bedroom). Whole
#: 0.5 m planning cells. Living rooms 3.5 m wide made 2- and 3-storey plans squeeze kitchens
#: and bedrooms instead (2 of the first 3 2-storey homes failed on them).
PLANNED_WIDTHS = {"bedroom": 2.5, "living_room": 3.0, "dining_room": 3.0, "kitchen": 2.0,
                  "bathroom": 1.5}
#: Turns sharper than this (degrees) count as corners (a round bevel's chords do not).
CORNER_TURN_DEG = 20.0

R = TypeVar("R")


# --------------------------------------------------------------------------------------------
# the view


def ideal_areas(typical: list[float], service: list[bool], area: float) -> list[float]:
    """Each room's share of a storey's `area` (m^2), given the rooms' typical areas and which
    are service rooms (`SERVICE_ROOMS`): in proportion to the typical areas; a storey with area
    to spare gives it to the rooms one lives in, while service rooms keep their typical area."""
    typ = np.asarray(typical, float)
    svc = np.asarray(service, bool)
    living = math.fsum(typ[~svc])
    if area <= typ.sum() or living <= 0:
        return [float(a) for a in typ * (area / max(float(typ.sum()), 1e-9))]
    out = typ.copy()
    out[~svc] *= (area - math.fsum(typ[svc])) / living
    return [float(a) for a in out]


class RoomView:
    """Polygon-based room measures and the `ObjectView` methods, for a plan of rooms.

    Subclasses supply `room_ids`, `storey_ids`, `polygon`, `room_type`, `level`, `neighbours`,
    `contour`, `entry_point`, `entry_room`, `stair_polygon` and `typical_area`; everything else
    has a polygon-based default here. Measures are cached per room until `invalidate(rooms)`.
    """

    def __init__(self) -> None:
        self._cache: dict[str, dict[Hashable, Any]] = {}

    # -- to supply ---------------------------------------------------------------------------
    def room_ids(self) -> list[str]:
        """Every room of the plan."""
        raise NotImplementedError

    def storey_ids(self) -> list[str]:
        """Every storey object of the plan (``storey_<level>``)."""
        raise NotImplementedError

    def polygon(self, o: str) -> sg.Polygon:
        """Room o's outline."""
        raise NotImplementedError

    def room_type(self, o: str) -> str:
        """Room o's type, e.g. "bedroom"."""
        raise NotImplementedError

    def level(self, o: str) -> int:
        """The storey room o is on."""
        raise NotImplementedError

    def neighbours(self, o: str) -> list[str]:
        """The rooms o must connect to (its room-graph neighbours)."""
        raise NotImplementedError

    def contour(self, level: int) -> sg.Polygon:
        """The outline of storey `level`."""
        raise NotImplementedError

    def entry_point(self, level: int) -> np.ndarray:
        """Where one enters storey `level` (the front door, or the stairs' top)."""
        raise NotImplementedError

    def entry_room(self, level: int) -> str:
        """The room one enters storey `level` through."""
        raise NotImplementedError

    def stair_polygon(self) -> sg.Polygon | None:
        """The staircase placeholder's outline, if the plan has stairs."""
        raise NotImplementedError

    def typical_area(self, o: str) -> float:
        """Typical area of room o's type (m^2)."""
        raise NotImplementedError

    def min_area(self, o: str) -> float:
        """Smallest acceptable area of o (m^2); none by default."""
        return 0.0

    # -- caching -----------------------------------------------------------------------------
    def invalidate(self, rooms: Iterable[str]) -> None:
        """Forget cached measures of `rooms` (call after they changed)."""
        for r in rooms:
            self._cache.pop(r, None)

    def cached(self, o: str, key: Hashable, fn: Callable[[], R]) -> R:
        """o's cached value under `key`, computed by `fn` the first time."""
        d = self._cache.setdefault(o, {})
        if key not in d:
            d[key] = fn()
        value: R = d[key]
        return value

    # -- ObjectView ----------------------------------------------------------------------------
    def all_ids(self) -> frozenset[str]:
        """Every room and storey."""
        return frozenset(self.room_ids()) | frozenset(self.storey_ids())

    def tags(self, o: str) -> frozenset[Tag]:
        """``{"storey"}`` for a storey, else ``{Room, <room type>}``."""
        if o.startswith(STOREY):
            return frozenset({STOREY})
        return frozenset({Semantics.Room, self.room_type(o)})

    def generator(self, o: str) -> str:
        """Rooms have no generator: ""."""
        return ""

    def params(self, o: str) -> dict[str, Any]:
        """Rooms have no params: {}."""
        return {}

    def relations(self, o: str) -> list[Any]:
        """Rooms relate to nothing: []."""
        return []

    def children(self, o: str) -> set[str]:
        """Rooms relate to nothing: no room is another's parent."""
        return set()

    def floor_z(self, o: str) -> float:
        """Room plans are measured in plan coordinates: every floor is at 0."""
        return 0.0

    def center(self, o: str) -> np.ndarray:
        """The centroid of the room's outline (z = 0)."""
        c = self.polygon(o).centroid
        return np.array([c.x, c.y, 0.0])

    def front(self, o: str) -> np.ndarray:
        """Rooms face +X."""
        return np.array([1.0, 0.0, 0.0])

    def side_axis(self, o: str) -> np.ndarray:
        """Rooms' side axis is +Y."""
        return np.array([0.0, 1.0, 0.0])

    def front_point(self, o: str) -> np.ndarray:
        """The room's centre."""
        return self.center(o)

    def yaw(self, o: str) -> float:
        """Rooms are unrotated: 0."""
        return 0.0

    def extents(self, o: str) -> np.ndarray:
        """The size of the room's bounding box (height 0)."""
        x0, y0, x1, y1 = self.polygon(o).bounds
        return np.array([x1 - x0, y1 - y0, 0.0])

    def footprint(self, o: str) -> sg.Polygon:
        """The room's outline."""
        return self.polygon(o)

    def outline(self, o: str) -> Any:
        """The room's walls: its outline's exterior ring."""
        return self.polygon(o).exterior

    def world_mesh(self, o: str) -> Any:
        """Rooms have no mesh: None."""
        return None

    def support_polygon(self, o: str) -> Any:
        """Rooms rest on nothing: None."""
        return None

    # -- measures (polygon-based defaults) -------------------------------------------------
    def storey_level(self, s: str) -> int:
        """The level of storey object `s` (``storey_<level>``)."""
        return int(s.rsplit("_", 1)[1])

    def area(self, o: str) -> float:
        """Floor area of o (m^2)."""
        return float(self.polygon(o).area)

    def ideal_area(self, o: str) -> float:
        """o's share of its storey's area (D.3 "typical room area"; `ideal_areas`)."""
        lv = self.level(o)
        rooms = [r for r in self.room_ids() if self.level(r) == lv]
        return ideal_areas([self.typical_area(r) for r in rooms],
                           [self.room_type(r) in SERVICE_ROOMS for r in rooms],
                           float(self.contour(lv).area))[rooms.index(o)]

    def aspect_ratio(self, o: str) -> float:
        """max(w/h, h/w) of o's bounding box (1 = square)."""
        x0, y0, x1, y1 = self.polygon(o).bounds
        w, h = x1 - x0, y1 - y0
        return float(max(w / h, h / w)) if min(w, h) > 0 else math.inf

    def convexity(self, o: str) -> float:
        """Convex hull area over area (1 = convex)."""
        p = self.polygon(o)
        return float(p.convex_hull.area / p.area) if p.area > 0 else math.inf

    def wall_count(self, o: str) -> float:
        """Number of o's corners, hence walls."""
        return float(len(_corners(self.polygon(o))))

    def wall_lines(self, o: str) -> tuple[frozenset[float], frozenset[float]]:
        """Distinct x of vertical and y of horizontal walls of o (1 mm resolution)."""
        def f() -> tuple[frozenset[float], frozenset[float]]:
            pts = np.asarray(self.polygon(o).exterior.coords)
            d = np.diff(pts, axis=0)
            xs = np.round(pts[:-1, 0][np.abs(d[:, 0]) < 1e-9], 3)
            ys = np.round(pts[:-1, 1][np.abs(d[:, 1]) < 1e-9], 3)
            return frozenset(xs.tolist()), frozenset(ys.tolist())
        return self.cached(o, "lines", f)

    def exterior_length(self, o: str) -> float:
        """Length of o's outline on the storey's exterior (m)."""
        return float(self.polygon(o).exterior.intersection(self.contour(self.level(o)).exterior).length)

    def perimeter(self, o: str) -> float:
        """Length of o's outline (m)."""
        return self.cached(o, "perimeter", lambda: float(self.polygon(o).exterior.length))

    def longest_exterior_wall(self, o: str) -> float:
        """Longest straight exterior wall of o (m)."""
        ring = self.contour(self.level(o)).exterior.buffer(1e-6)
        return float(max((sg.LineString(s).length for s in _segments(self.polygon(o))
                          if ring.contains(sg.LineString(s))), default=0.0))

    def exterior_corners(self, o: str) -> float:
        """Corners of the storey outline that belong to o: each corner belongs to the room
        holding the point just inside it (so every corner counts for exactly one room)."""
        probes = _corner_probes(self.contour(self.level(o)))
        poly = self.polygon(o)
        return float(sum(1 for p in probes if poly.contains(sg.Point(p))))

    def narrow_area(self, o: str, width: float) -> float:
        """Area lost by opening the room with a `width` square (erode, then buffer back): the
        parts of the room narrower than `width` (D.3 "narrow passages")."""
        p = self.polygon(o)
        r = width / 2 - 1e-4
        opened = p.buffer(-r, join_style="mitre").buffer(r, join_style="mitre")
        return float(max(0.0, p.area - opened.intersection(p).area))

    def shared_wall(self, a: str, b: str) -> tuple[float, np.ndarray | None]:
        """The longest straight wall a and b share: (length, midpoint)."""
        common = self.polygon(a).exterior.intersection(self.polygon(b).exterior)
        lines = [g for g in getattr(common, "geoms", [common]) if g.length > 0]
        if lines:
            lines = list(getattr(shapely.line_merge(shapely.union_all(lines)), "geoms",
                                 [shapely.line_merge(shapely.union_all(lines))]))
        best, mid = 0.0, None
        for ln in lines:
            for s in _segments_of_line(ln):
                length = float(np.linalg.norm(s[1] - s[0]))
                if length > best:
                    best, mid = length, (s[0] + s[1]) / 2
        return best, mid

    def missing_doors(self, o: str) -> float:
        """Graph neighbours of o on its storey that o shares no door-wide wall with."""
        return float(sum(1 for n in self.neighbours(o)
                         if self.shared_wall(o, n)[0] < MIN_DOOR_WALL - 1e-6))

    def passage_point(self, a: str, b: str) -> np.ndarray:
        """Where one walks from a into b: the middle of their longest shared wall."""
        _, mid = self.shared_wall(a, b)
        if mid is None:
            ca, cb = self.center(a)[:2], self.center(b)[:2]
            halfway: np.ndarray = (ca + cb) / 2
            return halfway
        return mid

    def entry_path(self, o: str) -> list[str]:
        """Rooms from the storey's entry room to o along the room graph (fewest rooms)."""
        lv = self.level(o)
        g = self.storey_graph(lv)
        path: list[str] = nx.shortest_path(g, self.entry_room(lv), o)
        return path

    def storey_graph(self, level: int) -> nx.Graph:
        """The room graph of one storey (from `neighbours`)."""
        g = nx.Graph()
        for r in self.room_ids():
            if self.level(r) == level:
                g.add_node(r)
                g.add_edges_from((r, n) for n in self.neighbours(r))
        return g

    def path_directness(self, o: str) -> float:
        """L1 distance from the storey's entry to o's centre divided by the L1 length of the walk
        through the rooms of `entry_path` (1 = no detour; D.3 "shortest path to entrance")."""
        path = self.entry_path(o)
        stops = [np.asarray(self.entry_point(self.level(o)), float)[:2]]
        stops += [self.passage_point(a, b) for a, b in itertools.pairwise(path)]
        stops.append(self.center(o)[:2])
        pts = np.asarray(stops)
        walk = float(np.abs(np.diff(pts, axis=0)).sum())
        direct = float(np.abs(pts[-1] - pts[0]).sum())
        return direct / walk if walk > 1e-9 else 1.0

    def storey_area(self, s: str) -> float:
        """Floor area of storey `s` (its outline's area)."""
        return float(self.contour(self.storey_level(s)).area)

    def outline_length(self, s: str) -> float:
        """Length of storey `s`'s outline (m)."""
        return float(self.contour(self.storey_level(s)).exterior.length)

    def outline_corners(self, s: str) -> float:
        """Corners of storey `s`'s outline."""
        return float(len(_corners(self.contour(self.storey_level(s)))))

    def stair_coverage(self, o: str) -> float:
        """Share of the staircase placeholder inside o (1 if there are no stairs)."""
        sp = self.stair_polygon()
        if sp is None or sp.area <= 0:
            return 1.0
        return float(self.polygon(o).intersection(sp).area / sp.area)

    def stair_iou(self, o: str) -> float:
        """Intersection over union of o and the staircase placeholder (1 without stairs)."""
        sp = self.stair_polygon()
        if sp is None:
            return 1.0
        p = self.polygon(o)
        inter = p.intersection(sp).area
        return float(inter / (p.area + sp.area - inter))


def _segments(poly: sg.Polygon) -> list[np.ndarray]:
    pts = np.asarray(poly.exterior.coords)
    return [pts[i:i + 2] for i in range(len(pts) - 1)]


def _segments_of_line(line: Any) -> list[np.ndarray]:
    """Straight pieces of a (multi)line, merging collinear consecutive segments."""
    pts = np.asarray(line.coords)
    out: list[np.ndarray] = []
    start = pts[0]
    for i in range(1, len(pts) - 1):
        d0, d1 = pts[i] - pts[i - 1], pts[i + 1] - pts[i]
        if abs(d0[0] * d1[1] - d0[1] * d1[0]) > 1e-9:
            out.append(np.array([start, pts[i]]))
            start = pts[i]
    out.append(np.array([start, pts[-1]]))
    return out


def _corner_probes(poly: sg.Polygon) -> list[np.ndarray]:
    """For each corner of the outline, a point 1 mm inside it along the corner's bisector."""
    pts = np.asarray(poly.exterior.coords)[:-1]
    out: list[np.ndarray] = []
    for i, p in enumerate(pts):
        a, b = pts[i] - pts[i - 1], pts[(i + 1) % len(pts)] - pts[i]
        turn = abs(math.atan2(a[0] * b[1] - a[1] * b[0], float(np.dot(a, b))))
        if turn <= math.radians(CORNER_TURN_DEG):
            continue
        bis = -a / np.linalg.norm(a) + b / np.linalg.norm(b)
        bis = bis / max(np.linalg.norm(bis), 1e-12)
        probe = p + 1e-3 * bis
        if not poly.contains(sg.Point(probe)):
            probe = p - 1e-3 * bis
        out.append(probe)
    return out


def _corners(poly: sg.Polygon) -> np.ndarray:
    """Vertices of the outline where it turns by more than CORNER_TURN_DEG."""
    pts = np.asarray(poly.exterior.coords)[:-1]
    d0 = pts - np.roll(pts, 1, axis=0)
    d1 = np.roll(pts, -1, axis=0) - pts
    turn = np.abs(np.arctan2(d0[:, 0] * d1[:, 1] - d0[:, 1] * d1[:, 0], (d0 * d1).sum(axis=1)))
    corners: np.ndarray = pts[turn > math.radians(CORNER_TURN_DEG)]
    return corners


def _room_view(ev: EvalContext) -> RoomView:
    """The evaluator's view, which room terms require to be a `RoomView`."""
    return cast(RoomView, ev.view)


# --------------------------------------------------------------------------------------------
# set helpers


def rooms_of(rooms: ObjSet, *types: str) -> ObjSet:
    """The members of `rooms` of any of `types` (room type names, e.g. "bedroom")."""
    return reduce(lambda a, b: a | b, (rooms[str(getattr(t, "value", t))] for t in types))


class OnStorey(ObjSet):
    """The members of a set that lie on the storey (or storeys) of another set."""

    def compute(self, ev: EvalContext, env: Env) -> frozenset[str]:
        """The rooms whose level is one of the storeys'."""
        objs: frozenset[str] = ev.get(self.children[0], env)
        storeys: frozenset[str] = ev.get(self.children[1], env)
        view = _room_view(ev)
        levels = {view.storey_level(s) for s in storeys}
        return frozenset(o for o in objs if view.level(o) in levels)

    def label(self) -> str:
        """`on_storey`."""
        return "on_storey"


def on_storey(rooms: ObjSet, storey: ObjSet) -> ObjSet:
    """The members of `rooms` on the storey `storey` (usually a loop variable over
    ``scene()["storey"]``)."""
    return OnStorey(rooms, storey)


# --------------------------------------------------------------------------------------------
# scalar terms


class RoomTerm(GeometricTerm):
    """Sum over the members of a set (typically one bound room) of a room-view measure, named
    `measure` and called as ``view.<measure>(room, *args)``."""

    #: measures that read other rooms or the staircase, and what else they watch
    _DEPENDS: dict[str, Callable[[RoomView, str], list[str]]] = {
        "missing_doors": lambda v, o: v.neighbours(o),
        "path_directness": lambda v, o: [*v.entry_path(o), STAIR_PLACEHOLDER],
        "stair_coverage": lambda v, o: [STAIR_PLACEHOLDER],
        "stair_iou": lambda v, o: [STAIR_PLACEHOLDER],
    }

    #: measures that never change while a plan is solved (nothing to watch)
    _CONSTANT = frozenset({"ideal_area", "min_area", "storey_area", "outline_length",
                           "outline_corners"})

    def __init__(self, objs: ObjSet, measure: str, *args: float):
        super().__init__(objs)
        self.measure, self.args = measure, args

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The measure summed over the members (constant measures watch nothing)."""
        s: frozenset[str]
        if self.measure in self._CONSTANT:
            s = ev.get(self.children[0], env)
        else:
            (s,) = self.members(ev, env)
        view = _room_view(ev)
        fn = getattr(view, self.measure)
        dep = self._DEPENDS.get(self.measure)
        total: list[float] = []
        for o in sorted(s):
            if dep is not None:
                ev.watch(dep(view, o))
            total.append(float(fn(o, *self.args)))
        return math.fsum(total)

    def label(self) -> str:
        """The measure's name."""
        return self.measure


def _term(measure: str, doc: str) -> Callable[..., Scalar]:
    def make(room: ObjSet, *args: float) -> Scalar:
        return RoomTerm(room, measure, *args)
    make.__name__ = measure
    make.__doc__ = doc
    return make


room_area = _term("area", "Floor area of the room (m^2).")
min_area = _term("min_area", "Smallest acceptable floor area of the room's type (m^2).")
ideal_area = _term("ideal_area", "The room's typical-area share of its storey's area (m^2).")
aspect_ratio = _term("aspect_ratio", "max(w/h, h/w) of the room's bounding box (1 = square).")
convexity = _term("convexity", "Convex hull area over area (1 = convex).")
wall_count = _term("wall_count", "Number of the room's corners, hence walls (4 = a rectangle).")
exterior_length = _term("exterior_length", "Length (m) of the room's outline on the exterior.")
longest_exterior_wall = _term("longest_exterior_wall",
                              "Longest straight exterior wall of the room (m): room for a "
                              "window or the front door.")
perimeter = _term("perimeter", "Length (m) of the room's outline.")
exterior_corners = _term("exterior_corners", "Corners of the storey outline the room holds.")
missing_doors = _term("missing_doors", "Graph neighbours the room shares no door-wide wall with.")
path_directness = _term("path_directness",
                        "Straight-line (L1) over walked distance from the storey's entry to the "
                        "room through the room graph (1 = no detour).")
stair_coverage = _term("stair_coverage", "Share of the staircase placeholder inside the room.")
stair_iou = _term("stair_iou", "Intersection over union of the room and the staircase "
                               "placeholder.")


storey_area = _term("storey_area", "Floor area of a storey (m^2): its outline's area.")
outline_length = _term("outline_length",
                       "Length of a storey's outline (m): all its exterior walls.")
outline_corners = _term("outline_corners", "Corners of a storey's outline.")


def narrow_area(room: ObjSet, width: float) -> Scalar:
    """Area (m^2) of the parts of the room narrower than `width` m: what an erosion by width/2
    followed by a buffer back removes (D.3 "narrow passages")."""
    return RoomTerm(room, "narrow_area", float(width))


class WallLines(GeometricTerm):
    """Number of distinct x coordinates of vertical walls plus distinct y coordinates of
    horizontal walls over all members (D.3 "collinearity": fewer means more aligned walls)."""

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The number of distinct wall lines."""
        (s,) = self.members(ev, env)
        xs: set[float] = set()
        ys: set[float] = set()
        view = _room_view(ev)
        for o in sorted(s):
            a, b = view.wall_lines(o)
            xs |= a
            ys |= b
        return float(len(xs) + len(ys))


def wall_lines(rooms: ObjSet) -> Scalar:
    """Distinct wall lines among `rooms` (see `WallLines`)."""
    return WallLines(rooms)


class RatioMismatch(Scalar):
    """max(a/b, b/a): 1 when a equals b, growing as they part (1e6 if either is <= 0)."""

    def __init__(self, a: Scalar, b: Scalar):
        super().__init__(a, b)

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The ratio of the larger value to the smaller."""
        a: float = ev.get(self.children[0], env)
        b: float = ev.get(self.children[1], env)
        if a <= 0 or b <= 0:
            return 1e6
        return max(a / b, b / a)

    def label(self) -> str:
        """`ratio_mismatch`."""
        return "ratio_mismatch"


def ratio_mismatch(a: ScalarLike, b: ScalarLike) -> Scalar:
    """max(a/b, b/a) of two scalars (D.3's typical-area mismatch)."""
    return RatioMismatch(as_scalar(a), as_scalar(b))


__all__ = ["RoomView", "STOREY", "STAIR_PLACEHOLDER", "MIN_DOOR_WALL", "rooms_of", "on_storey",
           "room_area", "min_area", "ideal_area", "aspect_ratio", "convexity", "wall_count",
           "exterior_length", "longest_exterior_wall", "exterior_corners", "missing_doors",
           "path_directness", "stair_coverage", "stair_iou", "narrow_area", "wall_lines",
           "storey_area", "outline_length", "outline_corners",
           "ratio_mismatch", "RoomTerm", "WallLines", "OnStorey", "RatioMismatch"]
