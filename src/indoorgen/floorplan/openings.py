"""Doors, open connections, windows, the front door and the stairs of a solved plan.

- A door joins each pair of graph neighbours, on their longest shared straight wall: centred or
  near one end (leaving wall for furniture); its width depends on the room it leads into.
- Living/dining and dining/kitchen pairs are instead joined by an open connection (the whole
  shared wall removed) with probability `open_prob`.
- The front door goes in the middle of the entrance room's longest straight exterior wall.
- Rooms that take windows get one to three, on their longest straight exterior walls, with
  the width limits and sill heights of their type, kept clear of the front door and the stairs.
- Stairs: straight flights in the staircase placeholder, which is two lanes wide; the flight
  from storey k climbs along lane k mod 2, alternating direction, so flights of a three-storey
  home stack as a switchback and every flight arrives beside the start of the next.
"""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg

from indoorgen.floorplan.rooms import room_type_of
from indoorgen.floorplan.view import GridPlan, longest_run
from indoorgen.model.floorplan import DoorSpec, Entrance, StairSpec, WindowSpec
from indoorgen.model.polygons import cross_2d
from indoorgen.model.room_types import DINING_ROOM, KITCHEN, LIVING_ROOM, ROOM_TYPES, STAIRCASE_ROOM

#: Clear wall kept between a door or window and the end of its wall run (m).
END_MARGIN = 0.15
#: Landing left at each end of a flight inside the placeholder (m).
LANDING = 0.5
#: Pairs of types joined by an open connection (no wall) rather than a door, when chosen.
OPEN_PAIRS = frozenset({frozenset({LIVING_ROOM, DINING_ROOM}), frozenset({DINING_ROOM, KITCHEN})})
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
                height: float) -> tuple[list[list[DoorSpec]], list[list[DoorSpec]]]:
    """Doors and open connections (full storey `height`) per storey, one per graph edge;
    `wall` is the interior wall thickness."""
    doors, openings = [], []
    for g in plan.graph.storeys:
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
                mid = (p + q) / 2
                ok.append(DoorSpec(f"opening_{a}_{b}", (a, b), _pt(mid), round(length - wall, 3),
                                   height))
                continue
            w = door_width(inner)
            lo = wall / 2 + END_MARGIN + w / 2
            if length < 2 * lo:
                continue
            # centred, or near one end (leaving wall for furniture)
            t = length / 2 if rng.random() < 0.5 else (lo if rng.random() < 0.5 else length - lo)
            dk.append(DoorSpec(f"door_{a}_{b}", (a, b), _pt(p + t * u), w, DOOR_HEIGHT))
        doors.append(dk)
        openings.append(ok)
    return doors, openings


def place_entrance(plan: GridPlan) -> Entrance | None:
    """The front door, in the middle of the entrance room's longest straight exterior wall."""
    room = plan.graph.entrance
    length, mid = plan.front_door(room)
    if length < ENTRANCE_DOOR_WIDTH + 2 * END_MARGIN:
        return None
    return Entrance(room, _pt(mid), ENTRANCE_DOOR_WIDTH, 2.1)


def place_windows(plan: GridPlan, rng: np.random.Generator, wall: float,
                  entrance: Entrance | None, keep_clear: sg.Polygon | None
                  ) -> list[list[WindowSpec]]:
    """Windows per storey on the straight exterior walls of rooms whose type takes them."""
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
    if sp is None:
        return []
    x0, y0, x1, y1 = sp.bounds
    along_x = (x1 - x0) >= (y1 - y0)
    length = (x1 - x0) if along_x else (y1 - y0)
    width = ((y1 - y0) if along_x else (x1 - x0)) / 2
    e_long = np.array([1.0, 0.0]) if along_x else np.array([0.0, 1.0])
    e_side = np.array([0.0, 1.0]) if along_x else np.array([1.0, 0.0])
    base = np.array([x0, y0])
    out = []
    for k in range(len(plan.grids) - 1):
        lane = k % 2
        s0, s1 = LANDING, length - LANDING
        if k % 2 == 1:
            s0, s1 = s1, s0
        up = e_long if s1 > s0 else -e_long
        side0 = base + lane * width * e_side
        side1 = side0 + width * e_side
        a, b = side0 + s0 * e_long, side1 + s0 * e_long
        # order: bottom-left, bottom-right (seen walking up), top-right, top-left
        right = np.array([up[1], -up[0]])
        bl, br = (a, b) if np.dot(b - a, right) > 0 else (b, a)
        tl, tr = bl + (s1 - s0) * e_long, br + (s1 - s0) * e_long
        out.append(StairSpec(k, k + 1, [_pt(bl), _pt(br), _pt(tr), _pt(tl)]))
    return out


def _pt(p) -> tuple[float, float]:
    return (round(float(p[0]), 6), round(float(p[1]), 6))

