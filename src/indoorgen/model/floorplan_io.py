"""`floorplan.json`: read and write a home's floorplan (a contract: tools outside the project
read it). The schema (`model.schemas.FloorplanFile`, docs/schemas/floorplan.schema.json)::

    {"format_version": 1, "storeys": [{"level": 0, "elevation": 0.0, "height": 2.8,
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
from indoorgen.model.schemas import SCHEMA_VERSION, FloorplanFile, parse, read_json_file


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
    """The canonical floorplan.json text (with its schema's version; the plan a scene.json
    embeds is `to_json`'s, without it)."""
    return json.dumps({"format_version": SCHEMA_VERSION, **to_json(fp)}, indent=1,
                      sort_keys=True) + "\n"


def write_floorplan(fp: Floorplan, path: str | PathLike[str]) -> None:
    """Write `fp` as floorplan.json at `path`."""
    Path(path).write_text(dumps(fp))


# --------------------------------------------------------------------------------------------
# reading


def from_json(d: Any) -> Floorplan:
    """Parse a floorplan.json object against `schemas.FloorplanFile` (types, finite numbers in
    range, caps, references); raises SchemaError / InvalidGeometryError / UnknownRoomTypeError
    naming the entry at fault (overlapping rooms and doors naming other storeys' rooms are
    found by `check_predefined`)."""
    doc = parse(FloorplanFile, d, "floorplan.json")
    storeys = []
    for k, s in enumerate(doc.storeys):
        st = Storey(s.level, s.elevation, s.height)
        for i, room in enumerate(s.rooms):
            st.rooms.append(RoomSpec(room.name, room_type(room.type, floorplan=True).name,
                                     _simple(room.polygon, f"storeys[{k}].rooms[{i}].polygon")))
        for src, target in ((s.doors, st.doors), (s.openings, st.openings)):
            target.extend(DoorSpec(d.name, d.rooms, d.center, d.width, d.height) for d in src)
        st.windows.extend(WindowSpec(w.name, w.room, w.center, w.width, w.height, w.sill)
                          for w in s.windows)
        storeys.append(st)
    stairs = [StairSpec(s.from_level, s.to_level, list(s.polygon)) for s in doc.stairs]
    entrance = Entrance(doc.entrance.room, doc.entrance.center) if doc.entrance else None
    vehicle_doors = [VehicleDoor(v.room, v.center, v.width, v.height) for v in doc.vehicle_doors]
    fp = Floorplan(storeys, stairs, entrance, vehicle_doors=vehicle_doors)
    check_predefined(fp)
    return fp


def _simple(points: list[tuple[float, float]], where: str) -> list[tuple[float, float]]:
    """`points` as a counter-clockwise simple polygon (InvalidGeometryError naming `where`)."""
    poly = sg.Polygon(points)
    if not poly.is_valid or poly.area <= 0:
        raise InvalidGeometryError(
            f"floorplan.json: {where} is not a simple polygon ({shapely.is_valid_reason(poly)})")
    return [(p[0], p[1]) for p in np.asarray(orient(poly, 1.0).exterior.coords)[:-1].tolist()]


def read_floorplan(path: str | PathLike[str]) -> Floorplan:
    """Read floorplan.json at `path` (SchemaError if missing, too big, not JSON or not a plan)."""
    return from_json(read_json_file(path, f"floorplan file {str(path)!r}", "floorplan"))


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
        a, b = shapely.STRtree(shapes).query(shapes, predicate="intersects")
        for i, j in zip(a.tolist(), b.tolist(), strict=True):  # candidate pairs only
            if i < j and shapes[i].intersection(shapes[j]).area > 1e-4:
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
