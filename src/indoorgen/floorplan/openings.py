"""Doors, open connections, windows, the front door and the stairs of a solved plan.

- A door joins each pair of graph neighbours, on their longest shared straight wall: centred or
  near one end (leaving wall for furniture), always near an end into a kitchen or bathroom; its
  width depends on the room it leads into.
- Living/dining and dining/kitchen pairs are instead joined by an open connection (the whole
  shared wall removed) with probability `open_prob`.
- A garage's vehicle door goes in the middle of its longest straight exterior wall.
- The front door goes in the middle of the entrance room's longest straight exterior wall.
- Rooms that take windows get one to three, on their longest straight exterior walls, with
  the width limits and sill heights of their type, kept clear of the front door and the stairs.
- Stairs: straight flights in the staircase placeholder (`stairs.flights`).
- A staircase room's doors are placed where nothing of a flight or stairwell lies in front of
  them on the staircase side and an agent of AGENT_RADIUS walks from every landing of that
  storey to them (`stair_door_ok`): never over a stairwell, never behind its railing.
"""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg

from indoorgen.floorplan.rooms import room_type_of
from indoorgen.floorplan.stairs import flights, stair_door_ok
from indoorgen.floorplan.view import GridPlan, longest_run
from indoorgen.model.floorplan import DoorSpec, Entrance, StairSpec, VehicleDoor, WindowSpec
from indoorgen.model.polygons import cross_2d
from indoorgen.model.room_types import (
    BATHROOM,
    DINING_ROOM,
    GARAGE,
    KITCHEN,
    LIVING_ROOM,
    ROOM_TYPES,
    STAIRCASE_ROOM,
)

#: Clear wall kept between a door or window and the end of its wall run (m).
END_MARGIN = 0.15
#: Rooms whose doors go near an end of their wall, never in its middle: a kitchen's counter
#: run and a bathroom's fixtures need the wall unbroken.
END_DOOR_TYPES = frozenset({KITCHEN, BATHROOM})
#: Pairs of types joined by an open connection (no wall) rather than a door, when chosen.
OPEN_PAIRS = frozenset({frozenset({LIVING_ROOM, DINING_ROOM}), frozenset({DINING_ROOM, KITCHEN})})
#: The widest open connection (m), centred in its shared wall: the wall either side of it stays
#: for furniture (a 3.4 x 5.9 m living room opened along its whole west wall had no wall left
#: for a bookcase)
MAX_OPENING = 3.0
#: A garage's vehicle door (m): a single-car up-and-over or sectional door.
VEHICLE_DOOR_WIDTH = 2.4
VEHICLE_DOOR_HEIGHT = 2.1
#: The front door's width, and every interior door's height (m).
ENTRANCE_DOOR_WIDTH = 1.0
DOOR_HEIGHT = 2.05


def shared_runs(plan: GridPlan, a: str, b: str) -> list[tuple[float, np.ndarray, np.ndarray]]:
    """Straight walls rooms a and b share along full cells: (length m, start, end), longest
    first."""
    k, i = plan.index[a]
    _, j = plan.index[b]
    g = plan.grids[k]
    lab = plan.labels[k]
    pa, pb = (lab == i) & g.full, (lab == j) & g.full
    out = []
    for axis in (0, 1):
        x = (pa[:-1] & pb[1:]) | (pb[:-1] & pa[1:]) if axis == 0 else \
            ((pa[:, :-1] & pb[:, 1:]) | (pb[:, :-1] & pa[:, 1:])).T
        x = x.copy()
        while True:
            length, row, start = longest_run(x)
            if length == 0:
                break
            x[row, start:start + length] = False
            if axis == 0:
                p, q = g.to_world(start, row + 1), g.to_world(start + length, row + 1)
            else:
                p, q = g.to_world(row + 1, start), g.to_world(row + 1, start + length)
            out.append((length * g.size, p, q))
    out.sort(key=lambda r: (-r[0], r[1][0], r[1][1]))
    return out


def door_width(into: str) -> float:
    """The width of a door leading into room `into` (by its type)."""
    return ROOM_TYPES[room_type_of(into)].door_width


def place_doors(plan: GridPlan, rng: np.random.Generator, wall: float, open_prob: float,
                height: float, stairs: list[StairSpec] | None = None, wall_half: float = 0.12
                ) -> tuple[list[list[DoorSpec]], list[list[DoorSpec]]]:
    """Doors and open connections (full storey `height`) per storey, one per graph edge;
    `wall` is the interior wall thickness. A staircase room's doors go where `stair_door_ok`
    holds for `stairs` (`wall_half`: the most a wall takes off a room's free floor)."""
    doors, openings = [], []
    for level, g in enumerate(plan.graph.storeys):
        dk, ok = [], []
        depth = {n: len(plan.entry_path(n)) for n in g.nodes}
        for a, b in sorted(tuple(sorted(e)) for e in g.edges):
            runs = shared_runs(plan, a, b)
            if not runs:
                continue
            length, p, q = runs[0]
            u = (q - p) / length
            inner = b if depth[b] >= depth[a] else a
            pair = frozenset({room_type_of(a), room_type_of(b)})
            if pair in OPEN_PAIRS and rng.random() < open_prob:
                # the walls at its ends stay: an exterior wall's inner half is thicker
                ring = plan.contour(level).exterior
                ends = [wall_half if ring.distance(sg.Point(e)) < 1e-6 else wall / 2
                        for e in (p, q)]
                mid = p + (ends[0] + (length - ends[1])) / 2 * u
                ok.append(DoorSpec(f"opening_{a}_{b}", (a, b), _pt(mid),
                                   round(min(length - sum(ends), MAX_OPENING), 3), height))
                continue
            w = door_width(inner)
            lo = wall / 2 + END_MARGIN + w / 2
            if length < 2 * lo:
                continue
            # centred, or near one end (leaving wall for furniture); into a kitchen or bathroom
            # always at the end nearer one of its corners, so its walls stay unbroken
            end_room = next((r for r in (a, b) if room_type_of(r) in END_DOOR_TYPES), None)
            if end_room is not None:
                centre = _door_by_corner(plan, end_room, runs, lo)
            elif rng.random() < 0.5:
                centre = p + length / 2 * u
            else:
                centre = p + (lo if rng.random() < 0.5 else length - lo) * u
            stair_room = next((r for r in (a, b) if room_type_of(r) == STAIRCASE_ROOM), None)
            if stair_room is not None and stairs:
                centre = _stair_door_site(plan, stair_room, runs, centre, w, lo, level, stairs,
                                          wall_half)
            dk.append(DoorSpec(f"door_{a}_{b}", (a, b), _pt(centre), w, DOOR_HEIGHT))
        doors.append(dk)
        openings.append(ok)
    return doors, openings


def _door_by_corner(plan: GridPlan, room: str, runs, lo: float) -> np.ndarray:
    """The centre of a door into `room` at the end of a shared wall (of `runs`, each long enough
    for the door) nearest one of `room`'s corners (`lo`: from the wall's end to the door's
    centre); ties go to the longest wall, as `runs` are ordered."""
    poly = plan.polygon(room)
    assert poly is not None  # solved plans hold simple polygons
    corners = np.asarray(poly.exterior.coords)
    best: tuple[float, np.ndarray] | None = None
    for length, p, q in runs:
        if length < 2 * lo:
            continue
        u = (q - p) / length
        for end, c in ((p, p + lo * u), (q, q - lo * u)):
            gap = float(np.min(np.hypot(*(corners - end).T)))
            if best is None or gap < best[0] - 1e-9:
                best = (gap, c)
    assert best is not None  # the longest run is long enough (checked by the caller)
    return best[1]


def _stair_door_site(plan: GridPlan, room: str, runs, preferred: np.ndarray, width: float,
                     lo: float, level: int, stairs: list[StairSpec], wall_half: float
                     ) -> np.ndarray:
    """The centre of a staircase room's door: `preferred` if `stair_door_ok` holds there, else
    the first such place along the shared walls (longest first, every 0.25 m), else
    `preferred` (floorplan.check then reports the plan)."""
    poly = plan.polygon(room)
    assert poly is not None  # solved plans hold simple polygons
    for length, p, q in runs:
        u = (q - p) / length
        cands = [preferred] if length == runs[0][0] and p is runs[0][1] else []
        cands += [p + t * u for t in np.arange(lo, length - lo + 1e-9, 0.25)]
        for c in cands:
            if stair_door_ok(poly, stairs, level, c, u, width, wall_half):
                return c
    return preferred


def place_entrance(plan: GridPlan) -> Entrance | None:
    """The front door, in the middle of the entrance room's longest straight exterior wall."""
    room = plan.graph.entrance
    length, mid = plan.front_door(room)
    if length < ENTRANCE_DOOR_WIDTH + 2 * END_MARGIN:
        return None
    return Entrance(room, _pt(mid), ENTRANCE_DOOR_WIDTH, 2.1)


def place_vehicle_doors(plan: GridPlan) -> list[VehicleDoor]:
    """A vehicle door for each ground-floor garage, in the middle of its longest straight
    exterior wall (the plan's rules keep that wall MIN_VEHICLE_DOOR_WALL long)."""
    out = []
    for name in plan.names[0]:
        if room_type_of(name) != GARAGE:
            continue
        length, mid = plan.front_door(name)
        if length >= VEHICLE_DOOR_WIDTH + 2 * END_MARGIN:
            out.append(VehicleDoor(name, _pt(mid), VEHICLE_DOOR_WIDTH, VEHICLE_DOOR_HEIGHT))
    return out


def place_windows(plan: GridPlan, rng: np.random.Generator, wall: float,
                  entrance: Entrance | None, keep_clear: sg.Polygon | None,
                  vehicle_doors: list[VehicleDoor] | None = None) -> list[list[WindowSpec]]:
    """Windows per storey on the straight exterior walls of rooms whose type takes them, clear
    of the front door, the stairs and the garages' vehicle doors."""
    out = []
    for k, names in enumerate(plan.names):
        wk: list[WindowSpec] = []
        for name in names:
            spec = ROOM_TYPES[room_type_of(name)].windows
            if spec is None:
                continue
            w_min, w_max, height, sill = spec.min_width, spec.max_width, spec.height, spec.sill
            n_max = spec.max_count
            for length, p, q in plan.exterior_runs(name):
                if len(wk) and sum(1 for w in wk if w.room == name) >= n_max:
                    break
                u = (q - p) / length
                segs = [(0.0, length)]
                if entrance is not None and k == 0:
                    segs = _cut(segs, p, u, np.asarray(entrance.center), entrance.width / 2 + 0.3)
                for v in (vehicle_doors or []) if k == 0 else []:
                    if v.room == name:
                        segs = _cut(segs, p, u, np.asarray(v.center), v.width / 2 + 0.3)
                if keep_clear is not None and room_type_of(name) == STAIRCASE_ROOM:
                    segs = [s for s in segs if keep_clear.distance(
                        sg.LineString([p + s[0] * u, p + s[1] * u])) > 0.3]
                for s0, s1 in segs:
                    free = s1 - s0 - wall - 2 * END_MARGIN - 0.3
                    if free < w_min:
                        continue
                    width = round(min(w_max, free) * float(rng.uniform(0.75, 1.0)), 1)
                    width = max(width, w_min)
                    mid = p + (s0 + s1) / 2 * u
                    wk.append(WindowSpec(f"window_{name}_{sum(1 for w in wk if w.room == name)}",
                                         name, _pt(mid), width, height, sill))
                    break
        out.append(wk)
    return out


def _cut(segs, p, u, c, half):
    """Remove the interval around point c (projected on the line p + t u) from segments."""
    if abs(cross_2d(u, c - p)) > 1e-6:
        return segs
    t = float(np.dot(c - p, u))
    out = []
    for s0, s1 in segs:
        if t + half <= s0 or t - half >= s1:
            out.append((s0, s1))
            continue
        if t - half > s0:
            out.append((s0, t - half))
        if t + half < s1:
            out.append((t + half, s1))
    return out


def place_stairs(plan: GridPlan) -> list[StairSpec]:
    """Straight flights in the placeholder, one per pair of consecutive storeys."""
    sp = plan.stair_polygon()
    return [] if sp is None else flights(sp, len(plan.grids))


def _pt(p) -> tuple[float, float]:
    return (round(float(p[0]), 6), round(float(p[1]), 6))

