"""Independent checks of a `Floorplan` (generated or predefined), from its polygons alone.

`floorplan_problems` lists every rule a plan breaks (an empty list means it is sound): rooms of
a storey overlap or leave gaps in the outline; a room is unreachable from the front door
through doors, open connections and stairs; a door is narrower than 0.8 m or not in a wall its
two rooms share; a room is narrower than 1.2 m (a closet than 1 m), or has parts joined by a
narrower neck; bathroom privacy is broken;
required rooms are missing; a flight is not held by staircase rooms on both its storeys; and
what `home_problems` lists (stairs, garages, balconies, entrance, bathroom access).
"""
from __future__ import annotations

import networkx as nx
import numpy as np
import shapely
import shapely.geometry as sg

from indoorgen.constraints.room_terms import MIN_BALCONY_EXTERIOR_SHARE
from indoorgen.floorplan.graph import balcony_problems, privacy_problems, zone_problems
from indoorgen.floorplan.rooms import min_width
from indoorgen.floorplan.stairs import stair_door_ok, stair_obstacles
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.polygons import cross_2d, narrow_area, polygon_pieces
from indoorgen.model.room_types import (
    BALCONY,
    BATHROOM,
    GARAGE,
    HALLWAY,
    KITCHEN,
    LIVING_ROOM,
    STAIRCASE_ROOM,
    least_area,
)

MIN_DOOR_WIDTH = 0.8
#: Free landing depth at both ends of a flight (m, issue 11).
MIN_LANDING = 0.9
#: What a wall takes off a room's free floor at most (m): half the default exterior wall
#: (`floorplan.generate.FloorplanConfig.exterior_wall`).
WALL_HALF = 0.12
#: What the front door may open into.
ENTRANCE_TYPES = frozenset({HALLWAY, LIVING_ROOM})


def _door_problems(fp: Floorplan) -> list[str]:
    out = []
    for s in fp.storeys:
        for d in s.doors + s.openings:
            if d.width < MIN_DOOR_WIDTH - 1e-9:
                out.append(f"{d.name} is {d.width:.2f} m wide (< {MIN_DOOR_WIDTH} m)")
            try:
                a, b = s.room(d.rooms[0]).shape(), s.room(d.rooms[1]).shape()
            except KeyError:
                out.append(f"{d.name} names a room not on storey {s.level}")
                continue
            shared = a.exterior.intersection(b.exterior.buffer(1e-6))
            c = sg.Point(d.center)
            if shared.is_empty or shared.distance(c) > 1e-3:
                out.append(f"{d.name} is not on a wall shared by {d.rooms[0]} and {d.rooms[1]}")
                continue
            # the door's whole width must lie on the shared wall
            seg = _segment_through(shared, np.asarray(d.center, float))
            if seg is None or seg < d.width - 1e-6:
                out.append(f"{d.name} ({d.width:.2f} m) does not fit on the wall shared by "
                           f"{d.rooms[0]} and {d.rooms[1]}")
    return out


def _segment_through(lines, c: np.ndarray) -> float | None:
    """Length of the portion of `lines` straddling point c symmetrically (twice the distance
    from c to the nearer end of the straight piece containing it)."""
    for ln in getattr(lines, "geoms", [lines]):
        pts = np.asarray(getattr(ln, "coords", []))
        for a, b in zip(pts[:-1], pts[1:], strict=False):
            d = b - a
            L = float(np.hypot(*d))
            if L < 1e-9:
                continue
            s = float(np.dot(c - a, d) / L)
            if -1e-6 <= s <= L + 1e-6 and abs(cross_2d(d / L, c - a)) < 1e-3:
                return 2 * min(s, L - s)
    return None


def floorplan_problems(fp: Floorplan, contours: list[sg.Polygon] | None = None,
                       counts: dict[str, int] | None = None) -> list[str]:
    """Everything wrong with `fp` (see module docstring). `contours` are the storeys' intended
    outlines (checked to equal the union of their rooms); `counts` the required room counts."""
    out = []
    for s in fp.storeys:
        shapes = [r.shape() for r in s.rooms]
        for r, p in zip(s.rooms, shapes, strict=False):
            if not p.is_valid or p.area <= 0:
                out.append(f"{r.name} is not a valid polygon")
        total = sum(p.area for p in shapes)
        union = shapely.union_all(shapes)
        if total - union.area > 1e-4:
            out.append(f"rooms on storey {s.level} overlap by {total - union.area:.4f} m^2")
        if contours is not None:
            c = contours[s.level]
            gap = c.symmetric_difference(union).area
            if gap > 1e-4:
                out.append(f"rooms on storey {s.level} differ from its outline by {gap:.4f} m^2")
        for r, p in zip(s.rooms, shapes, strict=False):
            doors = sum(r.name in d.rooms for d in s.doors + s.openings) + int(
                fp.entrance is not None and fp.entrance.room == r.name)
            # a plan of a home's last tries, on minimum widths, keeps only its types' minimum
            least = least_area(r.type, doors if fp.info.get("planned_widths", True) else 0)
            if p.area < least - 1e-9:
                out.append(f"{r.name} ({p.area:.1f} m^2) is smaller than {least} m^2 for "
                           f"{doors} doors")
            width = min_width(r.type)
            if narrow_area(p, width) > 0.01:
                out.append(f"{r.name} is narrower than {width} m somewhere "
                           f"({narrow_area(p, width):.2f} m^2)")
            elif polygon_pieces(p, width) > 1:
                out.append(f"{r.name} has a neck narrower than {width} m between its parts")
    out += _door_problems(fp)
    if fp.entrance is None:
        out.append("the plan has no entrance")
    types = [r.type for _, r in fp.rooms()]
    if counts:
        for t, n in counts.items():
            if types.count(t) != n:
                out.append(f"{types.count(t)} {t} rooms, required {n}")
    for s in fp.storeys:
        if not any(r.type == LIVING_ROOM for r in s.rooms):
            out.append(f"storey {s.level} has no living room")
    for t in (BATHROOM, KITCHEN):
        if t not in types and (counts or {}).get(t, 1):
            out.append(f"the home has no {t}")
    out += _stair_counts(fp) + home_problems(fp)
    return out


def home_problems(fp: Floorplan, wall_half: float = WALL_HALF) -> list[str]:
    """What a person would question in a plan (issue 11), which the generator re-draws a plan
    for: stairs without free landings or with a staircase door over them or out of the
    landings' reach; a garage without a vehicle door on an outside wall or a door into the
    home; a balcony off the edge of the storey or not entered from a living room or bedroom;
    an entrance not into a hallway or living room; bathroom privacy broken, every bathroom
    behind a bedroom, a shared room reached only through a bedroom, a room out of reach."""
    g = fp.connection_graph()
    out = _stair_problems(fp, wall_half) + _garage_problems(fp, g) + _balcony_problems(fp)
    types = {r.name: r.type for _, r in fp.rooms()}
    out += balcony_problems(g, types)
    entrance = fp.entrance.room if fp.entrance is not None else None
    out += zone_problems(g, entrance, types)
    if entrance is not None:
        reach = nx.node_connected_component(g, entrance)
        out += [f"{n} cannot be reached from the entrance" for n in g.nodes if n not in reach]
    if fp.entrance is not None:
        t = fp.storey_of(fp.entrance.room).room(fp.entrance.room).type
        if t not in ENTRANCE_TYPES:
            out.append(f"the front door opens into a {t}, not a hallway or living room")
    out += privacy_problems(g, entrance, types)
    return out


def _garage_problems(fp: Floorplan, g: nx.Graph) -> list[str]:
    out = []
    for s, r in fp.rooms():
        if r.type != GARAGE:
            continue
        doors = [v for v in fp.vehicle_doors if v.room == r.name]
        if not doors:
            out.append(f"{r.name} has no vehicle door")
        ring = s.contour().exterior
        for v in doors:
            u = _wall_direction(r.shape(), np.asarray(v.center, float))
            ends = [np.asarray(v.center) + h * u for h in (-v.width / 2, v.width / 2)] \
                if u is not None else []
            if not ends or any(ring.distance(sg.Point(p)) > 1e-3 for p in ends):
                out.append(f"{r.name}'s vehicle door is not on an outside wall")
        if r.name not in g or not g.degree(r.name):
            out.append(f"{r.name} has no door into the home")
    return out


def _balcony_problems(fp: Floorplan) -> list[str]:
    out = []
    for s in fp.storeys:
        ring = s.contour().exterior.buffer(1e-6)
        for r in s.rooms:
            if r.type != BALCONY:
                continue
            edge = r.shape().exterior
            if edge.intersection(ring).length < MIN_BALCONY_EXTERIOR_SHARE * edge.length - 1e-6:
                out.append(f"{r.name} is inside the outline, not on its edge")
    return out


def _stair_problems(fp: Floorplan, wall_half: float) -> list[str]:
    return _landing_problems(fp, wall_half) + _stair_door_problems(fp, wall_half)


def _stair_counts(fp: Floorplan) -> list[str]:
    out = []
    n = len(fp.storeys)
    if n > 1 and len(fp.stairs) != n - 1:
        out.append(f"{n} storeys but {len(fp.stairs)} flights")
    for st in fp.stairs:
        poly = st.shape()
        for lv in (st.from_level, st.to_level):
            s = fp.storeys[lv]
            holders = [r for r in s.rooms if r.shape().intersection(poly).area > 1e-6]
            if len(holders) != 1 or holders[0].type != STAIRCASE_ROOM or \
                    poly.difference(holders[0].shape()).area > 1e-4:
                out.append(f"flight {st.from_level}->{st.to_level} is not inside one staircase "
                           f"room on storey {lv}")
    return out



def _landing_problems(fp: Floorplan, wall_half: float) -> list[str]:
    """Flights without a free landing MIN_LANDING deep (past the walls' inner halves) and
    as wide as the flight, inside the staircase room, at their foot and their head."""
    out = []
    for st in fp.stairs:
        p = np.asarray(st.polygon, float)
        up = (p[3] - p[0]) / np.linalg.norm(p[3] - p[0])
        deep = (MIN_LANDING + wall_half) * up
        for lv, strip, end in ((st.from_level, sg.Polygon([p[0] - deep, p[1] - deep, p[1], p[0]]),
                                "foot"),
                               (st.to_level, sg.Polygon([p[3], p[2], p[2] + deep, p[3] + deep]),
                                "head")):
            holder = next((r for r in fp.storeys[lv].rooms
                           if r.shape().buffer(1e-6).contains(strip)), None)
            others = [o for o in stair_obstacles(fp.stairs, lv) if o.intersection(strip).area > 1e-6]
            if holder is None or holder.type != STAIRCASE_ROOM or others:
                out.append(f"flight {st.from_level}->{st.to_level} has no free {MIN_LANDING} m "
                           f"landing at its {end} in its staircase room")
    return out


def _stair_door_problems(fp: Floorplan, wall_half: float) -> list[str]:
    """Doors of staircase rooms opening over a flight or stairwell, or out of an agent's reach
    from the storey's landings (`floorplan.stairs.stair_door_ok`)."""
    out = []
    for s in fp.storeys:
        if not stair_obstacles(fp.stairs, s.level):
            continue
        for r in s.rooms:
            if r.type != STAIRCASE_ROOM:
                continue
            poly = r.shape()
            for d in s.doors + s.openings:
                if r.name not in d.rooms:
                    continue
                u = _wall_direction(poly, np.asarray(d.center, float))
                if u is None or not stair_door_ok(poly, fp.stairs, s.level, np.asarray(d.center), u,
                                                  d.width, wall_half):
                    out.append(f"{d.name} opens over the stairs or out of reach of their "
                               "landings")
    return out


def _wall_direction(poly: sg.Polygon, c: np.ndarray) -> np.ndarray | None:
    """Unit direction of the edge of `poly` through point c (None if c is on no edge)."""
    pts = np.asarray(poly.exterior.coords)
    for a, b in zip(pts[:-1], pts[1:], strict=False):
        d = b - a
        L = float(np.hypot(*d))
        if L > 1e-9 and abs(cross_2d(d / L, c - a)) < 1e-3 and -1e-6 <= np.dot(c - a, d) / L <= L + 1e-6:
            return d / L
    return None
