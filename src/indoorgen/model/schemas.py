"""The schemas of the data files indoorgen reads: scene.json, floorplan.json, a room's polygon,
a home's contour and a room graph (pydantic v2 models), and the one way to read them.

Every reader goes through `read_json_text` / `read_json_file` and then `parse`: the file's size
and the nesting depth of its brackets are capped before the JSON is parsed (so a hostile file
costs neither memory nor a RecursionError), then the model checks types and shapes, finite numbers
in physical ranges (the ranges the command line's options allow), caps on vertex and room counts,
and references inside the file (rooms, relation parents, door walls). What needs the layers above
`model` (generator names, relation grammar) is checked by the readers there. Any problem raises
`SchemaError` (an `IndoorGenError`): one line naming the entry, the bad value and what is valid.

The JSON Schema of each file is in docs/schemas/ (`json_schemas`, `write_json_schemas`).
"""
from __future__ import annotations

import json
import math
import re
import reprlib
from os import PathLike
from pathlib import Path
from typing import Annotated, Any, Literal, TypeVar

import numpy as np
import shapely
from pydantic import BaseModel, ConfigDict, Field, Strict, ValidationError, model_validator

from indoorgen.errors import ConfigError
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.rng import MAX_SEED

#: the version of every file's schema: scene.json's `format_version`, and floorplan.json's, a
#: contour's and a room graph's (optional there, 1 when absent)
SCHEMA_VERSION = 1

#: a single room's sides (m): `generate --size W D` and a `--polygon`'s bounding box
MIN_ROOM_SIDE = 2.0
MAX_ROOM_SIDE = 30.0
#: a home's extent (m) along x or y, and the largest ground-floor area (m^2) `--area` and a
#: contour may ask for (a large detached house is ~500 m^2; the grid stays far below 1 GB)
MAX_HOME_SPAN = 100.0
MAX_HOME_AREA = 2000.0
#: any coordinate (m) in a file: homes are placed near the origin
MAX_COORD = 1000.0
#: storeys of a home (`--floors`)
MAX_STOREYS = 3
#: heights (m): a storey's ceiling, a single room's walls (`generate` defaults 2.4-3.0)
MIN_STOREY_HEIGHT, MAX_STOREY_HEIGHT = 2.0, 6.0
MIN_WALL_HEIGHT, MAX_WALL_HEIGHT = 1.8, 12.0
#: highest z (m) anything stands at: three storeys of the tallest walls
MAX_Z = MAX_STOREYS * MAX_WALL_HEIGHT
#: widths of doors, windows and openings, and their heights (m)
MAX_OPENING = 10.0
#: caps read before or while parsing
MAX_VERTICES = 256          # one room's polygon or a contour
MAX_ROOMS = 200             # rooms in one file
MAX_OBJECTS = 20_000        # objects in one scene
MAX_LIST = 256              # doors, windows, tags, relations, list parameters...
MAX_NAME = 200              # characters of a name or a relation string
MAX_DEPTH = 20              # nesting of brackets
#: file size caps (bytes) by file kind; a two-storey home of 21 rooms and 281 objects writes a
#: 0.26 MB scene.json
MAX_BYTES = {"scene": 32 << 20, "floorplan": 8 << 20, "polygon": 1 << 20, "contour": 1 << 20,
             "graph": 1 << 20}
#: arrays (points, lists) a file of each kind may hold, counted before parsing: what the caps
#: above allow with room to spare (a floorplan: 3 storeys of 200 rooms of 256 points...)
_PLAN_ARRAYS = MAX_STOREYS * MAX_ROOMS * (MAX_VERTICES + 1) + 4 * MAX_STOREYS * MAX_LIST * 4
MAX_ARRAYS = {"scene": _PLAN_ARRAYS + MAX_ROOMS * (MAX_VERTICES + 2) + MAX_OBJECTS * 8,
              "floorplan": _PLAN_ARRAYS, "polygon": 2 * MAX_VERTICES, "contour": 2 * MAX_VERTICES,
              "graph": MAX_STOREYS * MAX_ROOMS * 6}
#: values and keys (counted as commas before parsing) a file of each kind may hold: a
#: floorplan's points and lists, and 64 per object of a scene (a furnished object writes ~35)
_PLAN_ITEMS = MAX_STOREYS * MAX_ROOMS * (2 * MAX_VERTICES + 8) + 4 * MAX_STOREYS * MAX_LIST * 8
MAX_ITEMS = {"scene": _PLAN_ITEMS + MAX_ROOMS * (2 * MAX_VERTICES + 16) + MAX_OBJECTS * 64,
             "floorplan": _PLAN_ITEMS, "polygon": 4 * MAX_VERTICES, "contour": 4 * MAX_VERTICES,
             "graph": MAX_STOREYS * MAX_ROOMS * 12}

Coord = Annotated[float, Strict(), Field(ge=-MAX_COORD, le=MAX_COORD, allow_inf_nan=False)]
Point = tuple[Coord, Coord]
Name = Annotated[str, Strict(), Field(min_length=1, max_length=MAX_NAME)]
Text = Annotated[str, Strict(), Field(max_length=MAX_NAME)]
Length = Annotated[float, Strict(), Field(gt=0, le=MAX_OPENING, allow_inf_nan=False)]
Level = Annotated[int, Strict(), Field(ge=0, lt=MAX_STOREYS)]
Polygon = Annotated[list[Point], Field(min_length=3, max_length=MAX_VERTICES)]
Scalar = (Annotated[bool, Strict()] | Annotated[int, Strict(), Field(ge=-10**6, le=10**6)]
          | Annotated[float, Strict(), Field(ge=-1e6, le=1e6, allow_inf_nan=False)] | Text)
ParamValue = Scalar | Annotated[list[Scalar], Field(max_length=MAX_LIST)]


class SchemaError(ConfigError):
    """A data file that breaks its schema (too big, too deep, wrong types, bad values)."""


class _Model(BaseModel):
    """Unknown keys are refused: a misspelt key would otherwise be silently ignored."""

    model_config = ConfigDict(extra="forbid", frozen=True)


def _span(points: list[Point]) -> tuple[float, float]:
    """Width and depth (m) of `points`' bounding box."""
    p = np.asarray(points, float)
    w, d = p.max(axis=0) - p.min(axis=0)
    return float(w), float(d)


def _fits_a_home(points: list[Point], what: str) -> None:
    """ValueError unless `points` (`what`: "room 'x'", "the contour") fit in a home's extent."""
    w, d = _span(points)
    if max(w, d) > MAX_HOME_SPAN:
        raise ValueError(f"{what} spans {w:g} x {d:g} m; a home fits in {MAX_HOME_SPAN:g} x "
                         f"{MAX_HOME_SPAN:g} m")


# --------------------------------------------------------------------------------------------
# floorplan.json


class FloorplanRoom(_Model):
    """One room of a storey: a unique name, a floorplan room type, its partition polygon."""

    name: Name
    type: Name
    polygon: Polygon

    @model_validator(mode="after")
    def _size(self) -> FloorplanRoom:
        _fits_a_home(self.polygon, f"room {self.name!r}")
        return self


class FloorplanDoor(_Model):
    """A door or open connection between two rooms, centred on their shared wall."""

    name: Name
    rooms: tuple[Name, Name]
    center: Point
    width: Length
    height: Length


class FloorplanWindow(_Model):
    """A window in an exterior wall of `room`, `sill` above the floor."""

    name: Name
    room: Name
    center: Point
    width: Length
    height: Length
    sill: Annotated[float, Strict(), Field(ge=0, le=MAX_STOREY_HEIGHT, allow_inf_nan=False)]


class FloorplanStorey(_Model):
    """One storey: level, floor elevation, ceiling height, rooms and their openings (the rooms
    doors and windows name, levels and the entrance are checked by `floorplan_io.check_predefined`,
    which generated plans go through too)."""

    level: Level
    elevation: Annotated[float, Strict(), Field(ge=-MAX_STOREY_HEIGHT, le=MAX_Z, allow_inf_nan=False)]
    height: Annotated[float, Strict(), Field(ge=MIN_STOREY_HEIGHT, le=MAX_STOREY_HEIGHT,
                                   allow_inf_nan=False)]
    rooms: Annotated[list[FloorplanRoom], Field(min_length=1, max_length=MAX_ROOMS)]
    doors: Annotated[list[FloorplanDoor], Field(max_length=MAX_LIST)] = []
    windows: Annotated[list[FloorplanWindow], Field(max_length=MAX_LIST)] = []
    openings: Annotated[list[FloorplanDoor], Field(max_length=MAX_LIST)] = []


class FloorplanStair(_Model):
    """A straight flight: its footprint's 4 corners, bottom-left first, walking up."""

    from_level: Level
    to_level: Level
    polygon: Annotated[list[Point], Field(min_length=4, max_length=4)]


class FloorplanEntrance(_Model):
    """The front door: its ground-floor room and centre."""

    room: Name
    center: Point


class FloorplanVehicleDoor(_Model):
    """A garage's door to the outside: its room, centre on the exterior wall, width, height."""

    room: Name
    center: Point
    width: Length
    height: Length


class FloorplanFile(_Model):
    """floorplan.json (see `model.floorplan_io` for its meaning)."""

    format_version: Literal[1] = 1
    storeys: Annotated[list[FloorplanStorey], Field(min_length=1, max_length=MAX_STOREYS)]
    stairs: Annotated[list[FloorplanStair], Field(max_length=MAX_STOREYS)] = []
    entrance: FloorplanEntrance | None = None
    vehicle_doors: Annotated[list[FloorplanVehicleDoor], Field(max_length=MAX_LIST)] = []

    @model_validator(mode="after")
    def _references(self) -> FloorplanFile:
        names = [r.name for s in self.storeys for r in s.rooms]
        dup = sorted({n for n in names if names.count(n) > 1}) if len(set(names)) < len(names) \
            else []
        if dup:
            raise ValueError(f"room name {dup[0]!r} is used twice")
        _fits_a_home([p for s in self.storeys for r in s.rooms for p in r.polygon], "the home")
        return self


# --------------------------------------------------------------------------------------------
# scene.json


class ScenePose(_Model):
    """An object's position (m) and yaw (rad) about +Z."""

    position: tuple[Coord, Coord, Annotated[float, Strict(), Field(ge=-MAX_WALL_HEIGHT, le=MAX_Z,
                                                         allow_inf_nan=False)]]
    yaw: Annotated[float, Strict(), Field(ge=-4 * math.pi, le=4 * math.pi, allow_inf_nan=False)]


class SceneRelation(_Model):
    """A declared relation: its DSL text, the parent (object or room) and the two surfaces."""

    relation: Name
    parent: Name
    child_surface: Name
    parent_surface: Name
    #: metres; negative where the child reaches under its parent (a rug 1.4 m under a bed)
    margin: Annotated[float, Strict(), Field(ge=-3.0, le=10.0, allow_inf_nan=False)] = 0.0


class SceneObjectRecord(_Model):
    """A placed object: generator, parameters, seed, pose, tags, room, relations."""

    name: Name
    generator: Name
    params: Annotated[dict[Name, ParamValue], Field(max_length=MAX_LIST)]
    seed: Annotated[int, Strict(), Field(ge=0, le=MAX_SEED)]
    pose: ScenePose
    tags: Annotated[list[Name], Field(max_length=MAX_LIST)]
    room: Name
    stage: Text = ""
    relations: Annotated[list[SceneRelation], Field(max_length=MAX_LIST)]


class SceneDoor(_Model):
    """A door in wall `wall` of a room, centred `offset` metres along it."""

    name: Name
    wall: Annotated[int, Strict(), Field(ge=0, lt=MAX_VERTICES)]
    offset: Annotated[float, Strict(), Field(ge=0, le=MAX_HOME_SPAN, allow_inf_nan=False)]
    width: Length
    height: Length
    clearance_depth: Annotated[float, Strict(), Field(ge=0, le=MAX_OPENING, allow_inf_nan=False)]


class SceneRoom(_Model):
    """A room: type, polygon, wall height and thickness, storey, doors."""

    name: Name
    type: Name
    polygon: Polygon
    height: Annotated[float, Strict(), Field(ge=MIN_WALL_HEIGHT, le=MAX_WALL_HEIGHT, allow_inf_nan=False)]
    wall_thickness: Annotated[float, Strict(), Field(gt=0, le=1.0, allow_inf_nan=False)]
    storey: Level
    doors: Annotated[list[SceneDoor], Field(max_length=MAX_LIST)]
    elevation: Annotated[float, Strict(), Field(ge=-MAX_STOREY_HEIGHT, le=MAX_Z, allow_inf_nan=False)] = 0.0

    @model_validator(mode="after")
    def _doors_on_walls(self) -> SceneRoom:
        _fits_a_home(self.polygon, f"room {self.name!r}")
        outline = shapely.Polygon(self.polygon)
        if not outline.is_valid or outline.area <= 0:
            raise ValueError(f"room {self.name!r} is not a simple polygon "
                             f"({shapely.is_valid_reason(outline)}); list its corners in order")
        for door in self.doors:
            if door.wall >= len(self.polygon):
                raise ValueError(f"door {door.name!r} is on wall {door.wall}; room "
                                 f"{self.name!r} has walls 0 to {len(self.polygon) - 1}")
        return self


#: the largest door joint value a scene may record (a hinge's half turn, in rad)
MAX_JOINT = math.pi


class SceneFile(_Model):
    """scene.json (see `model.scene`)."""

    format_version: Literal[1]
    seed: Annotated[int, Strict(), Field(ge=0, le=MAX_SEED)]
    config: dict[Name, Any] = {}
    rooms: Annotated[list[SceneRoom], Field(min_length=1, max_length=MAX_ROOMS)]
    objects: Annotated[list[SceneObjectRecord], Field(max_length=MAX_OBJECTS)]
    floorplan: FloorplanFile | None = None
    #: each door leaf's joint value (rad, or m for a slide; 0 = shut) in a home
    doors: Annotated[dict[Name, Annotated[float, Strict(), Field(ge=-MAX_JOINT, le=MAX_JOINT,
                                                                 allow_inf_nan=False)]],
                     Field(max_length=MAX_LIST)] | None = None

    @model_validator(mode="before")
    @classmethod
    def _objects_one_by_one(cls, data: Any) -> Any:
        """Objects checked one at a time, up to the first bad one: 20,000 hostile objects can
        hold a million errors, too many to list (they would cost seconds and a GB)."""
        objects = data.get("objects") if isinstance(data, dict) else None
        if not isinstance(objects, list) or len(objects) > MAX_OBJECTS:
            return data  # the field's own check names the fault
        checked = []
        for i, record in enumerate(objects):
            try:
                checked.append(SceneObjectRecord.model_validate(record))
            except ValidationError as e:
                raise ValueError(describe(e, f"objects[{i}]", record)) from None
        return {**data, "objects": checked}

    @model_validator(mode="after")
    def _references(self) -> SceneFile:
        rooms = {r.name for r in self.rooms}
        if len(rooms) < len(self.rooms):
            raise ValueError("two rooms share a name")
        custom = bool(self.config.get("program"))
        for r in self.rooms:
            if r.type not in ROOM_TYPES and not custom:
                raise ValueError(f"room {r.name!r} has type {r.type!r}, which is unknown; valid: "
                                 f"{', '.join(ROOM_TYPES)}")
        objects = {o.name for o in self.objects}
        if len(objects) < len(self.objects):
            raise ValueError("two objects share a name")
        clash = sorted(rooms & objects)
        if clash:
            raise ValueError(f"{clash[0]!r} names both a room and an object")
        for o in self.objects:
            if o.room not in rooms:
                raise ValueError(f"object {o.name!r} is in room {o.room!r}, which is not in the "
                                 "scene")
            for rel in o.relations:
                if rel.parent not in rooms and rel.parent not in objects:
                    raise ValueError(f"object {o.name!r} relates to {rel.parent!r}, which is "
                                     "neither a room nor an object of the scene")
                if rel.parent == o.name:
                    raise ValueError(f"object {o.name!r} relates to itself")
        return self


# --------------------------------------------------------------------------------------------
# a room's polygon, a home's contour, a room graph


class RoomPolygon(_Model):
    """`generate --polygon`: a single room's outline, its bounding box as `--size` allows."""

    polygon: Polygon

    @model_validator(mode="after")
    def _size(self) -> RoomPolygon:
        w, d = _span(self.polygon)
        if not (MIN_ROOM_SIDE <= w <= MAX_ROOM_SIDE and MIN_ROOM_SIDE <= d <= MAX_ROOM_SIDE):
            raise ValueError(f"the polygon spans {w:g} x {d:g} m; each side of a room must be "
                             f"between {MIN_ROOM_SIDE:g} and {MAX_ROOM_SIDE:g} m (as --size)")
        return self


class HomeContour(_Model):
    """`floorplan --contour`: the ground floor's outline, as large as `--area` allows."""

    format_version: Literal[1] = 1
    contour: Polygon

    @model_validator(mode="after")
    def _size(self) -> HomeContour:
        _fits_a_home(self.contour, "the contour")
        p = np.asarray(self.contour, float)
        area = 0.5 * abs(float(np.dot(p[:, 0], np.roll(p[:, 1], -1))
                               - np.dot(np.roll(p[:, 0], -1), p[:, 1])))
        if area > MAX_HOME_AREA:
            raise ValueError(f"the contour encloses {area:.0f} m^2; at most {MAX_HOME_AREA:g} "
                             "m^2 (as --area)")
        return self


class GraphStorey(_Model):
    """One storey of a room graph: room names `<type>_<k>` and the doors between them."""

    rooms: Annotated[list[Name], Field(min_length=1, max_length=MAX_ROOMS)]
    edges: Annotated[list[tuple[Name, Name]], Field(max_length=MAX_ROOMS * 4)] = []


class RoomGraph(_Model):
    """`floorplan --graph`: a fixed room graph (`floorplan.graph.graph_from_spec` reads it)."""

    format_version: Literal[1] = 1
    storeys: Annotated[list[GraphStorey], Field(min_length=1, max_length=MAX_STOREYS)]
    entrance: Name | None = None
    stairs: Annotated[list[Text], Field(max_length=MAX_STOREYS)] | None = None

    @model_validator(mode="after")
    def _references(self) -> RoomGraph:
        for k, s in enumerate(self.storeys):
            here = set(s.rooms)
            for a, b in s.edges:
                if a not in here or b not in here:
                    raise ValueError(f"edge {a!r}-{b!r} names a room not on storey {k}")
        return self


#: the files' schemas by the name of their JSON Schema in docs/schemas/
SCHEMAS: dict[str, type[BaseModel]] = {
    "scene": SceneFile, "floorplan": FloorplanFile, "polygon": RoomPolygon,
    "contour": HomeContour, "graph": RoomGraph,
}

M = TypeVar("M", bound=BaseModel)


# --------------------------------------------------------------------------------------------
# reading


#: bytes of JSON text scanned at once (`_scan`)
_SCAN_CHUNK = 1 << 22
_STRING = re.compile(r'"(?:[^"\\]|\\.)*"', re.S)


def nesting_depth(text: str) -> int:
    """The deepest nesting of brackets in JSON `text` (brackets inside strings not counted), by
    a scan that never recurses."""
    return _scan(text)[0]


def _scan(text: str) -> tuple[int, int, int]:
    """(deepest nesting of brackets, number of arrays, number of commas: about the number of
    values and keys) in JSON `text`, strings left out; in chunks, so a file's scan costs a few
    tens of MB whatever its size."""
    bare = np.frombuffer(_STRING.sub('""', text).encode("utf-8", "replace"), np.uint8)
    depth = deepest = arrays = commas = 0
    for i in range(0, len(bare), _SCAN_CHUNK):
        b = bare[i:i + _SCAN_CHUNK]
        opens = b == ord("[")
        arrays += int(opens.sum())
        commas += int(np.count_nonzero(b == ord(",")))
        step = (opens | (b == ord("{"))).astype(np.int8) \
            - ((b == ord("]")) | (b == ord("}"))).astype(np.int8)
        run = np.cumsum(step, dtype=np.int64) + depth
        deepest, depth = max(deepest, int(run.max())), int(run[-1])
    return deepest, arrays, commas


def read_json_text(text: str, what: str, kind: str) -> Any:
    """Parse JSON `text` (the contents of `what`, a file of `kind`) with its size, nesting and
    numbers of arrays and values capped first; SchemaError names the cap or the JSON error."""
    cap = MAX_BYTES[kind]
    if len(text) > cap:
        raise SchemaError(f"{what} is {len(text)} bytes; a {kind} file holds at most {cap} bytes")
    depth, arrays, commas = _scan(text)
    if depth > MAX_DEPTH:
        raise SchemaError(f"{what} nests brackets {depth} deep; a {kind} file nests at most "
                          f"{MAX_DEPTH} deep")
    if arrays > MAX_ARRAYS[kind]:
        raise SchemaError(f"{what} holds {arrays} arrays (points, lists); a {kind} file holds "
                          f"at most {MAX_ARRAYS[kind]}")
    if commas >= MAX_ITEMS[kind]:
        raise SchemaError(f"{what} holds over {commas} values and keys; a {kind} file holds at "
                          f"most {MAX_ITEMS[kind]}")
    try:
        return json.loads(text)
    except (ValueError, RecursionError) as e:
        raise SchemaError(f"{what} is not readable JSON ({e})") from None


def read_json_file(path: str | PathLike[str], what: str, kind: str) -> Any:
    """Read and parse the JSON file at `path` (`what` names it in errors: "--contour file
    'x.json'"), its size checked with stat before it is read."""
    p = Path(path)
    try:
        size = p.stat().st_size
        if not p.is_file():
            raise SchemaError(f"{what} is not a file")
        if size > MAX_BYTES[kind]:
            raise SchemaError(f"{what} is {size} bytes; a {kind} file holds at most "
                              f"{MAX_BYTES[kind]} bytes")
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SchemaError(f"{what} does not exist") from None
    except UnicodeDecodeError:
        raise SchemaError(f"{what} is not UTF-8 text") from None
    except OSError as e:
        raise SchemaError(f"{what} cannot be read ({e.strerror})") from None
    return read_json_text(text, what, kind)


def parse(schema: type[M], data: Any, what: str) -> M:
    """`data` checked against `schema`; SchemaError names the first entry at fault, its value and
    what is valid (and how many other problems there are)."""
    try:
        return schema.model_validate(data)
    except ValidationError as e:
        raise SchemaError(describe(e, what, data)) from None
    except RecursionError:
        raise SchemaError(f"{what} nests too deep") from None


def describe(error: ValidationError, what: str, data: Any = None) -> str:
    """One line for a ValidationError: where, what is wrong, the value given (looked up in
    `data`). Only the first error is decoded: a hostile file can hold a million of them."""
    errors = error.json(include_url=False, include_context=False, include_input=False)
    first, _ = json.JSONDecoder().raw_decode(errors, 1)
    path = list(first["loc"])
    if first["type"] == "missing":
        key = path.pop()
        msg = f"lacks item {key} (too short)" if isinstance(key, int) else f"has no {key!r}"
    else:
        msg = first["msg"].removeprefix("Value error, ")
    loc = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in path).lstrip(".")
    where = f"{what}: {loc}: " if loc else f"{what}: "
    if first["type"] == "missing":
        where = f"{what}: {loc} " if loc else f"{what} "
    got = "" if first["type"] in ("value_error", "missing") else \
        _got(data, first["loc"])
    n = error.error_count()
    more = f" (and {n - 1} more problem(s))" if n > 1 else ""
    return f"{where}{msg}{got}{more}"


def _got(data: Any, loc: list[Any]) -> str:
    """' (got VALUE)' for the value at `loc` in `data`, or '' where the path leads nowhere (a
    location pydantic names by a tag or an alias)."""
    for key in loc:
        try:
            data = data[key]
        except (KeyError, IndexError, TypeError):
            return ""
    return f" (got {_short(data)})"


def _short(value: Any) -> str:
    """`value`'s repr cut to one short line (bounded work, whatever `value`'s size)."""
    short = reprlib.Repr()
    short.maxlevel, short.maxlist, short.maxdict, short.maxstring = 2, 6, 4, 50
    r = short.repr(value).replace("\n", " ")
    return r if len(r) <= 60 else r[:57] + "..."


def json_schemas() -> dict[str, dict[str, Any]]:
    """The JSON Schema of every file, by name (what docs/schemas/NAME.schema.json holds)."""
    return {name: {"$schema": "https://json-schema.org/draft/2020-12/schema",
                   "$id": f"indoorgen/{name}/v{SCHEMA_VERSION}",
                   **model.model_json_schema()}
            for name, model in SCHEMAS.items()}


def write_json_schemas(directory: str | PathLike[str]) -> list[Path]:
    """Write docs/schemas/NAME.schema.json for every file's schema; returns the paths."""
    out = []
    for name, schema in json_schemas().items():
        p = Path(directory) / f"{name}.schema.json"
        p.write_text(json.dumps(schema, indent=1, sort_keys=True) + "\n")
        out.append(p)
    return out
