"""`floorplan.json`: read and write a home's floorplan (a contract: tools outside the project
read it). The schema::

    {"storeys": [{"level": 0, "elevation": 0.0, "height": 2.8,
                  "rooms": [{"name": "bedroom_0", "type": "bedroom", "polygon": [[x, y], ...]}],
                  "doors": [{"name": ..., "rooms": [a, b], "center": [x, y], "width": w,
                             "height": h}],
                  "windows": [{"name": ..., "room": r, "center": [x, y], "width": w,
                               "height": h, "sill": s}],
                  "openings": [{"name": ..., "rooms": [a, b], "center": [x, y], "width": w,
                                "height": h}]}],
     "stairs": [{"from_level": 0, "to_level": 1, "polygon": [[x, y], ...]}],
     "entrance": {"room": ..., "center": [x, y]},
     "vehicle_doors": [{"room": garage, "center": [x, y], "width": w, "height": h}]}

`vehicle_doors` (garages' doors to the outside, on exterior walls) is left out when there are none.

Room polygons are counter-clockwise partition polygons (walls are centred on their edges); a
door's or opening's centre lies on the wall the two rooms share, a window's on an exterior wall
of its room, the entrance's on an exterior wall of its ground-floor room. A stair polygon is the
flight's footprint listed [bottom-left, bottom-right, top-right, top-left] as seen walking up.
Numbers are rounded to 1e-6 and keys sorted, so the same plan always gives the same bytes.
"""
from __future__ import annotations

import json
import math
from collections.abc import Iterable
from os import PathLike
from pathlib import Path
from typing import Any

import numpy as np
import shapely
import shapely.geometry as sg
from shapely.geometry.polygon import orient

from indoorgen.errors import ConfigError, InvalidGeometryError
from indoorgen.model.floorplan import (
    DoorSpec,
    Entrance,
    Floorplan,
    RoomSpec,
    StairSpec,
    Storey,
    VehicleDoor,
    WindowSpec,
)
from indoorgen.model.room_types import room_type


def _r(x: float) -> float:
    v = round(float(x), 6)
    return 0.0 if v == 0 else v


def _pts(points: Iterable[tuple[float, float]]) -> list[list[float]]:
    return [[_r(x), _r(y)] for x, y in points]


def to_json(fp: Floorplan) -> dict[str, Any]:
    """The floorplan.json object of `fp`."""
    return {
        "storeys": [{
            "level": s.level, "elevation": _r(s.elevation), "height": _r(s.height),
            "rooms": [{"name": r.name, "type": r.type, "polygon": _pts(r.polygon)}
                      for r in s.rooms],
            "doors": [_door(d) for d in s.doors],
            "windows": [{"name": w.name, "room": w.room, "center": [_r(c) for c in w.center],
                         "width": _r(w.width), "height": _r(w.height), "sill": _r(w.sill)}
                        for w in s.windows],
            "openings": [_door(o) for o in s.openings],
        } for s in fp.storeys],
        "stairs": [{"from_level": st.from_level, "to_level": st.to_level,
                    "polygon": _pts(st.polygon)} for st in fp.stairs],
        "entrance": ({"room": fp.entrance.room,
                      "center": [_r(c) for c in fp.entrance.center]}
                     if fp.entrance is not None else None),
    } | ({"vehicle_doors": [{"room": v.room, "center": [_r(c) for c in v.center],
                             "width": _r(v.width), "height": _r(v.height)}
                            for v in fp.vehicle_doors]} if fp.vehicle_doors else {})


def _door(d: DoorSpec) -> dict[str, Any]:
    return {"name": d.name, "rooms": list(d.rooms), "center": [_r(c) for c in d.center],
            "width": _r(d.width), "height": _r(d.height)}


def dumps(fp: Floorplan) -> str:
    """The canonical floorplan.json text."""
    return json.dumps(to_json(fp), indent=1, sort_keys=True) + "\n"


def write_floorplan(fp: Floorplan, path: str | PathLike[str]) -> None:
    """Write `fp` as floorplan.json at `path`."""
    Path(path).write_text(dumps(fp))


# --------------------------------------------------------------------------------------------
# reading


class _Reader:
    """Field access with error messages naming the offending entry."""

    def __init__(self, where: str) -> None:
        self.where = where

    def get(self, d: Any, key: str, kind: type | None = None, default: Any = ...) -> Any:
        if not isinstance(d, dict):
            raise ConfigError(f"floorplan.json: {self.where} must be an object, got "
                              f"{type(d).__name__}")
        if key not in d:
            if default is not ...:
                return default
            raise ConfigError(f"floorplan.json: {self.where} has no {key!r}")
        v = d[key]
        if kind is float:
            try:
                v = float(v)
            except (TypeError, ValueError):
                raise ConfigError(f"floorplan.json: {self.where}.{key} must be a number, got "
                                  f"{d[key]!r}") from None
            if not math.isfinite(v):
                raise ConfigError(f"floorplan.json: {self.where}.{key} is not finite")
        elif kind is int:
            if isinstance(v, bool) or not isinstance(v, int):
                raise ConfigError(f"floorplan.json: {self.where}.{key} must be an integer, got "
                                  f"{v!r}")
        elif kind is list and not isinstance(v, list):
            raise ConfigError(f"floorplan.json: {self.where}.{key} must be a list")
        elif kind is str and not isinstance(v, str):
            raise ConfigError(f"floorplan.json: {self.where}.{key} must be a string")
        return v

    def point(self, v: Any, key: str) -> tuple[float, float]:
        try:
            x, y = (float(c) for c in v)
        except (TypeError, ValueError):
            raise ConfigError(f"floorplan.json: {self.where}.{key} must be [x, y], got "
                              f"{v!r}") from None
        return (x, y)

    def polygon(self, v: Any, key: str) -> list[tuple[float, float]]:
        if not isinstance(v, list) or len(v) < 3:
            raise ConfigError(f"floorplan.json: {self.where}.{key} must be a list of at least "
                              "3 [x, y] points")
        pts = [self.point(p, key) for p in v]
        poly = sg.Polygon(pts)
        if not poly.is_valid or poly.area <= 0:
            raise InvalidGeometryError(
                f"floorplan.json: {self.where}.{key} is not a simple polygon "
                f"({shapely.is_valid_reason(poly)})")
        return [(p[0], p[1]) for p in np.asarray(orient(poly, 1.0).exterior.coords)[:-1].tolist()]


def from_json(d: dict[str, Any]) -> Floorplan:
    """Parse a floorplan.json object; raises ConfigError / InvalidGeometryError naming the
    entry at fault (missing keys, bad numbers, overlapping rooms, unknown room types or room
    names, doors off their walls are found by `check_predefined`)."""
    rd = _Reader("the file")
    storeys = []
    names: set[str] = set()
    for k, s in enumerate(rd.get(d, "storeys", list)):
        r = _Reader(f"storeys[{k}]")
        st = Storey(r.get(s, "level", int), r.get(s, "elevation", float),
                    r.get(s, "height", float))
        for i, room in enumerate(r.get(s, "rooms", list)):
            rr = _Reader(f"storeys[{k}].rooms[{i}]")
            name = rr.get(room, "name", str)
            if name in names:
                raise ConfigError(f"floorplan.json: room name {name!r} is used twice")
            names.add(name)
            st.rooms.append(RoomSpec(name, room_type(rr.get(room, "type", str), floorplan=True).name,
                                     rr.polygon(rr.get(room, "polygon", list), "polygon")))
        for key, target in (("doors", st.doors), ("openings", st.openings)):
            for i, door in enumerate(r.get(s, key, list, [])):
                rr = _Reader(f"storeys[{k}].{key}[{i}]")
                pair = rr.get(door, "rooms", list)
                if len(pair) != 2:
                    raise ConfigError(f"floorplan.json: {rr.where}.rooms must name two rooms")
                target.append(DoorSpec(rr.get(door, "name", str), (str(pair[0]), str(pair[1])),
                                       rr.point(rr.get(door, "center"), "center"),
                                       rr.get(door, "width", float),
                                       rr.get(door, "height", float)))
        for i, w in enumerate(r.get(s, "windows", list, [])):
            rr = _Reader(f"storeys[{k}].windows[{i}]")
            st.windows.append(WindowSpec(rr.get(w, "name", str), rr.get(w, "room", str),
                                         rr.point(rr.get(w, "center"), "center"),
                                         rr.get(w, "width", float), rr.get(w, "height", float),
                                         rr.get(w, "sill", float)))
        storeys.append(st)
    stairs = []
    for i, s in enumerate(rd.get(d, "stairs", list, [])):
        r = _Reader(f"stairs[{i}]")
        pts = [r.point(p, "polygon") for p in r.get(s, "polygon", list)]
        if len(pts) != 4:
            raise ConfigError(f"floorplan.json: stairs[{i}].polygon must be the 4 corners of "
                              "the flight: bottom-left, bottom-right, top-right, top-left")
        stairs.append(StairSpec(r.get(s, "from_level", int), r.get(s, "to_level", int), pts))
    entrance = None
    e = d.get("entrance") if isinstance(d, dict) else None
    if e is not None:
        r = _Reader("entrance")
        entrance = Entrance(r.get(e, "room", str), r.point(r.get(e, "center"), "center"))
    vehicle_doors = []
    for i, v in enumerate(rd.get(d, "vehicle_doors", list, [])):
        r = _Reader(f"vehicle_doors[{i}]")
        vehicle_doors.append(VehicleDoor(r.get(v, "room", str), r.point(r.get(v, "center"), "center"),
                                         r.get(v, "width", float), r.get(v, "height", float)))
    fp = Floorplan(storeys, stairs, entrance, vehicle_doors=vehicle_doors)
    check_predefined(fp)
    return fp


def read_floorplan(path: str | PathLike[str]) -> Floorplan:
    """Read floorplan.json at `path` (ConfigError if missing or not JSON)."""
    p = Path(path)
    try:
        data = json.loads(p.read_text())
    except FileNotFoundError:
        raise ConfigError(f"floorplan file {str(p)!r} does not exist") from None
    except (OSError, ValueError) as e:
        raise ConfigError(f"floorplan file {str(p)!r} is not readable JSON: {e}") from None
    return from_json(data)


def check_predefined(fp: Floorplan) -> None:
    """Raise if a plan cannot be solidified: no storeys, levels out of order, overlapping rooms,
    doors/windows naming unknown rooms, stairs between missing storeys."""
    if not fp.storeys:
        raise ConfigError("floorplan.json: the plan has no storeys")
    for k, s in enumerate(fp.storeys):
        if s.level != k:
            raise ConfigError(f"floorplan.json: storeys[{k}].level is {s.level}; storeys must be "
                              "listed by level from 0")
        if not s.rooms:
            raise ConfigError(f"floorplan.json: storey {k} has no rooms")
        if not 2.0 <= s.height <= 6.0:
            raise ConfigError(f"floorplan.json: storey {k} height {s.height} is outside [2, 6] m")
        shapes = [r.shape() for r in s.rooms]
        for i in range(len(shapes)):
            for j in range(i + 1, len(shapes)):
                if shapes[i].intersection(shapes[j]).area > 1e-4:
                    raise InvalidGeometryError(
                        f"floorplan.json: rooms {s.rooms[i].name!r} and {s.rooms[j].name!r} on "
                        f"storey {k} overlap")
        here = {r.name for r in s.rooms}
        for d in s.doors + s.openings:
            for r in d.rooms:
                if r not in here:
                    raise ConfigError(f"floorplan.json: {d.name!r} names room {r!r}, which is "
                                      f"not on storey {k}")
        for w in s.windows:
            if w.room not in here:
                raise ConfigError(f"floorplan.json: window {w.name!r} names room {w.room!r}, "
                                  f"which is not on storey {k}")
    levels = {s.level for s in fp.storeys}
    for st in fp.stairs:
        if st.from_level not in levels or st.to_level != st.from_level + 1 or \
                st.to_level not in levels:
            raise ConfigError(f"floorplan.json: a stair from {st.from_level} to {st.to_level} "
                              "must join a storey to the next one")
    for v in fp.vehicle_doors:
        if v.room not in {r.name for r in fp.storeys[0].rooms}:
            raise ConfigError(f"floorplan.json: vehicle door room {v.room!r} is not on the "
                              "ground floor")
    if fp.entrance is not None and fp.entrance.room not in {r.name for r in fp.storeys[0].rooms}:
        raise ConfigError(f"floorplan.json: entrance room {fp.entrance.room!r} is not on the "
                          "ground floor")
