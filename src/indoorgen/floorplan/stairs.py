"""The stairs of a home in its staircase placeholder, and what keeps them usable.

The placeholder is a rectangle two 1 m lanes wide shared by all storeys. The flight from storey
k climbs along lane k mod 2, alternating direction, so flights of a three-storey home stack as a
switchback and every flight arrives beside the start of the next (`flights`). A landing LANDING
deep is left free at both ends of every flight, inside the placeholder, so inside the staircase
room that holds it.

A staircase room's door must open where a person (or an agent of AGENT_RADIUS) can use it: no
flight or stairwell, with its railing, within DOOR_APPROACH in front of it on the staircase side,
and a walk on the room's free floor from every landing of the storey to it (`stair_door_ok`).
`flight_mask` marks the grid cells of the flights and stairwells of a storey, which the
floorplan solver keeps clear in front of the staircase room's door walls.
"""
from __future__ import annotations

import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.floorplan.grid import Grid
from indoorgen.model.floorplan import StairSpec

#: Landing left at each end of a flight inside the placeholder (m): less the thickest wall's
#: inner half (0.12 m) it leaves 0.98 m of free floor, deeper than the 0.9 m issue 11 asks for.
LANDING = 1.1
#: The radius of the agent the staircase room's doors are placed for (m; the navigation
#: measure's default, `quality.navigation.reach`).
AGENT_RADIUS = 0.25
#: Half a stair railing's thickness, kept clear round a stairwell or flight (m).
RAIL_CLEARANCE = 0.05
#: Depth of floor kept clear of flights and stairwells in front of a staircase room's door on
#: its staircase side (m): a 0.9 m leaf swings in it, and it fits a 1 m lane beside a flight.
DOOR_APPROACH = 0.9


def flights(placeholder: sg.Polygon, n_storeys: int) -> list[StairSpec]:
    """Straight flights in the `placeholder` rectangle, one per pair of consecutive storeys."""
    x0, y0, x1, y1 = placeholder.bounds
    along_x = (x1 - x0) >= (y1 - y0)
    length = (x1 - x0) if along_x else (y1 - y0)
    width = ((y1 - y0) if along_x else (x1 - x0)) / 2
    e_long = np.array([1.0, 0.0]) if along_x else np.array([0.0, 1.0])
    e_side = np.array([0.0, 1.0]) if along_x else np.array([1.0, 0.0])
    base = np.array([x0, y0])
    out = []
    for k in range(n_storeys - 1):
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


def stair_obstacles(stairs: list[StairSpec], level: int) -> list[sg.Polygon]:
    """Footprints of the flights leaving storey `level` and of the stairwells arriving on it."""
    return [st.shape() for st in stairs if level in (st.from_level, st.to_level)]


def landing_points(stairs: list[StairSpec], level: int, beyond: float = 0.5
                   ) -> list[np.ndarray]:
    """Points `beyond` metres past the foot of each flight leaving storey `level` and past the
    head of each flight arriving on it: where one stands on its landings."""
    out = []
    for st in stairs:
        p = np.asarray(st.polygon, float)
        up = (p[3] - p[0]) / np.linalg.norm(p[3] - p[0])
        if st.from_level == level:
            out.append((p[0] + p[1]) / 2 - beyond * up)
        if st.to_level == level:
            out.append((p[2] + p[3]) / 2 + beyond * up)
    return out


def stair_door_ok(room: sg.Polygon, stairs: list[StairSpec], level: int, centre: np.ndarray,
                  u: np.ndarray, width: float, wall_half: float) -> bool:
    """Whether a door of width `width` centred at `centre` on a wall of staircase room `room`
    (`u` along the wall) suits storey `level`'s stairs: no flight or stairwell (with its
    railing) within DOOR_APPROACH in front of it on the room's side, and an agent of
    AGENT_RADIUS walks on the room's free floor (its outline less `wall_half`) from every
    landing of the storey to it."""
    obstacles = stair_obstacles(stairs, level)
    if not obstacles:
        return True
    c = np.asarray(centre, float)
    n = np.array([-u[1], u[0]])
    if not room.contains(sg.Point(c + 0.1 * n)):
        n = -n
    half = u * (width / 2 + 0.1)
    zone = sg.Polygon([c - half, c + half, c + half + DOOR_APPROACH * n,
                       c - half + DOOR_APPROACH * n])
    blocked = shapely.union_all(obstacles).buffer(RAIL_CLEARANCE, join_style="mitre")
    if zone.intersects(blocked):
        return False
    free = room.buffer(-wall_half, join_style="mitre").difference(blocked)
    centres = free.buffer(-AGENT_RADIUS)
    door_pt = sg.Point(c + (wall_half + AGENT_RADIUS + 0.05) * n)
    part = next((g for g in getattr(centres, "geoms", [centres]) if g.distance(door_pt) < 0.05),
                None)
    return part is not None and all(part.distance(sg.Point(q)) < 0.05
                                    for q in landing_points(stairs, level))


def flight_mask(grid: Grid, stairs: list[StairSpec], level: int) -> np.ndarray:
    """Cells of `grid` that a flight leaving or a stairwell arriving on storey `level` covers."""
    out = np.zeros(grid.shape, bool)
    for poly in stair_obstacles(stairs, level):
        x0, y0, x1, y1 = poly.bounds
        ix0, iy0 = np.floor((np.array([x0, y0]) - grid.origin) / grid.size + 1e-6).astype(int)
        ix1, iy1 = np.ceil((np.array([x1, y1]) - grid.origin) / grid.size - 1e-6).astype(int)
        out[max(0, iy0):iy1, max(0, ix0):ix1] = True
    return out


def _pt(p) -> tuple[float, float]:
    return (round(float(p[0]), 6), round(float(p[1]), 6))
