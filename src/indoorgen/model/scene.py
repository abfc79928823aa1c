"""The data that flows through the pipeline: `Scene`, `Room`, `Door`, `SceneObject`, `Pose`,
`RelationInstance`.

Everything here is plain data with a stable JSON form. Meshes are never stored: they are derived
from (generator, params) and cached elsewhere. All objects stand upright, so a pose is a position
and a rotation (yaw) about +Z.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from indoorgen.model.frames import yaw_matrix
from indoorgen.model.schemas import SCHEMA_VERSION, SceneFile, parse

#: scene.json's schema version (`schemas.SceneFile.format_version`)
SCENE_FORMAT_VERSION = SCHEMA_VERSION


def _r(x: float | np.floating[Any], nd: int = 6) -> float:
    """Round for serialisation so that JSON is stable and readable."""
    v = round(float(x), nd)
    return 0.0 if v == 0 else v


def as_saved(params: dict[str, Any]) -> dict[str, Any]:
    """`params` as scene.json stores them (numbers rounded as saved): what anything derived
    from params (a seed, a shape) must be computed from to come out the same when a saved scene
    is read back."""
    return _params_json(params)


@dataclass(frozen=True)
class Pose:
    """World placement of an object's local frame: translation plus rotation `yaw` about +Z."""

    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    yaw: float = 0.0

    def matrix(self) -> np.ndarray:
        """4x4 homogeneous transform from local to world."""
        m = np.eye(4)
        m[:3, :3] = yaw_matrix(self.yaw)
        m[:3, 3] = self.position
        return m

    def rotation(self) -> np.ndarray:
        """3x3 rotation of this pose (about +Z)."""
        return yaw_matrix(self.yaw)

    def apply(self, points: np.ndarray) -> np.ndarray:
        """Transform local points (N,3) to world."""
        world: np.ndarray = np.asarray(points, float) @ self.rotation().T + np.asarray(self.position)
        return world

    def front(self) -> np.ndarray:
        """World direction of the local +X (the object's front)."""
        return np.array([math.cos(self.yaw), math.sin(self.yaw), 0.0])

    def to_json(self) -> dict[str, Any]:
        """The pose's scene.json record (rounded)."""
        return {"position": [_r(v) for v in self.position], "yaw": _r(self.yaw)}

    @staticmethod
    def from_json(d: dict[str, Any]) -> Pose:
        """A pose from its scene.json record."""
        x, y, z = (float(v) for v in d["position"])
        return Pose((x, y, z), float(d["yaw"]))


@dataclass(frozen=True)
class RelationInstance:
    """One declared relation of an object: `relation` (its DSL repr) between the child's surface
    `child_surface` and `parent_surface` of `parent` (an object name or a room name)."""

    relation: str
    parent: str
    child_surface: str
    parent_surface: str
    margin: float = 0.0

    def to_json(self) -> dict[str, Any]:
        """The relation's scene.json record."""
        return {
            "relation": self.relation,
            "parent": self.parent,
            "child_surface": self.child_surface,
            "parent_surface": self.parent_surface,
            "margin": _r(self.margin),
        }

    @staticmethod
    def from_json(d: dict[str, Any]) -> RelationInstance:
        """A relation from its scene.json record."""
        return RelationInstance(d["relation"], d["parent"], d["child_surface"],
                                d["parent_surface"], float(d.get("margin", 0.0)))


@dataclass
class SceneObject:
    """A placed object: which generator made it, with what params and seed, where, and why."""

    name: str
    generator: str
    params: dict[str, Any]
    seed: int
    pose: Pose
    tags: list[str]
    room: str
    relations: list[RelationInstance] = field(default_factory=list)
    stage: str = ""

    @property
    def parent(self) -> str:
        """The object or room this one rests on or hangs from (its first relation's parent)."""
        return self.relations[0].parent if self.relations else ""

    def to_json(self) -> dict[str, Any]:
        """The object's scene.json record (params and pose rounded, tags sorted)."""
        return {
            "name": self.name,
            "generator": self.generator,
            "params": _params_json(self.params),
            "seed": int(self.seed),
            "pose": self.pose.to_json(),
            "tags": sorted(self.tags),
            "room": self.room,
            "stage": self.stage,
            "relations": [r.to_json() for r in self.relations],
        }

    @staticmethod
    def from_json(d: dict[str, Any]) -> SceneObject:
        """An object from its scene.json record."""
        return SceneObject(
            name=d["name"], generator=d["generator"], params=dict(d["params"]),
            seed=int(d["seed"]), pose=Pose.from_json(d["pose"]), tags=list(d["tags"]),
            room=d["room"], relations=[RelationInstance.from_json(r) for r in d["relations"]],
            stage=d.get("stage", ""),
        )


def _params_json(params: dict[str, Any]) -> dict[str, Any]:
    """Params as plain JSON values, in sorted order, floats rounded."""
    out: dict[str, Any] = {}
    for k in sorted(params):
        v = params[k]
        if isinstance(v, (bool, np.bool_)):
            out[k] = bool(v)
        elif isinstance(v, (int, np.integer)):
            out[k] = int(v)
        elif isinstance(v, (float, np.floating)):
            out[k] = _r(v)
        elif isinstance(v, (list, tuple)):
            out[k] = [_r(x) if isinstance(x, (float, np.floating)) else x for x in v]
        else:
            out[k] = v
    return out


@dataclass
class Door:
    """A door opening in wall `wall` of a room: centred `offset` metres along that wall."""

    name: str
    wall: int
    offset: float
    width: float = 0.9
    height: float = 2.05
    clearance_depth: float = 1.0

    def to_json(self) -> dict[str, Any]:
        """The door's scene.json record (rounded)."""
        return {"name": self.name, "wall": self.wall, "offset": _r(self.offset),
                "width": _r(self.width), "height": _r(self.height),
                "clearance_depth": _r(self.clearance_depth)}

    @staticmethod
    def from_json(d: dict[str, Any]) -> Door:
        """A door from its scene.json record."""
        return Door(d["name"], int(d["wall"]), float(d["offset"]), float(d["width"]),
                    float(d["height"]), float(d["clearance_depth"]))


@dataclass
class Room:
    """A room: a simple polygon (counter-clockwise, metres) extruded to `height`. In a home,
    `storey` is its storey's level and `elevation` the z of its floor (written to JSON only when
    not 0, so single rooms serialise as before)."""

    name: str
    room_type: str
    polygon: list[tuple[float, float]]
    height: float = 2.7
    wall_thickness: float = 0.12
    storey: int = 0
    doors: list[Door] = field(default_factory=list)
    elevation: float = 0.0

    def to_json(self) -> dict[str, Any]:
        """The room's scene.json record (rounded; `elevation` only when not 0)."""
        out: dict[str, Any] = {"name": self.name, "type": self.room_type,
               "polygon": [[_r(x), _r(y)] for x, y in self.polygon],
               "height": _r(self.height), "wall_thickness": _r(self.wall_thickness),
               "storey": self.storey, "doors": [d.to_json() for d in self.doors]}
        if self.elevation:
            out["elevation"] = _r(self.elevation)
        return out

    @staticmethod
    def from_json(d: dict[str, Any]) -> Room:
        """A room from its scene.json record."""
        return Room(d["name"], d["type"], [tuple(p) for p in d["polygon"]], float(d["height"]),
                    float(d["wall_thickness"]), int(d["storey"]),
                    [Door.from_json(x) for x in d["doors"]], float(d.get("elevation", 0.0)))


@dataclass
class Scene:
    """One generated scene: its rooms and its placed objects, in placement order."""

    seed: int
    rooms: dict[str, Room] = field(default_factory=dict)
    objects: dict[str, SceneObject] = field(default_factory=dict)
    config: dict[str, Any] = field(default_factory=dict)
    #: for a whole home, its floorplan in the floorplan.json schema (architecture is rebuilt
    #: from it); None for a single room
    floorplan: dict[str, Any] | None = None
    #: for a whole home, each door leaf's joint value by door name (0 = shut; radians for a
    #: hinge), so a re-export stands every leaf where it stood; None for a single room
    doors: dict[str, float] | None = None

    @property
    def style(self) -> str | None:
        """The home style its furniture's materials are drawn from (`config.style`; None in a
        scene written before styles, whose materials are drawn unstyled)."""
        style = self.config.get("style")
        return style if isinstance(style, str) else None

    def add_object(self, obj: SceneObject) -> None:
        """Add (or replace) `obj`, keyed by its name."""
        self.objects[obj.name] = obj

    def objects_in(self, room: str) -> list[SceneObject]:
        """The objects placed in `room`, in placement order."""
        return [o for o in self.objects.values() if o.room == room]

    def to_json(self) -> dict[str, Any]:
        """The scene.json object (see `dumps` for its canonical text)."""
        return {
            "format_version": SCENE_FORMAT_VERSION,
            "seed": int(self.seed),
            "config": self.config,
            "rooms": [r.to_json() for r in self.rooms.values()],
            "objects": [o.to_json() for o in self.objects.values()],
            **({"floorplan": self.floorplan} if self.floorplan is not None else {}),
            **({"doors": {k: _r(v) for k, v in self.doors.items()}}
               if self.doors is not None else {}),
        }

    def dumps(self) -> str:
        """The canonical `scene.json` text (sorted keys, fixed float rounding)."""
        return json.dumps(self.to_json(), indent=1, sort_keys=True) + "\n"

    @staticmethod
    def from_json(d: Any) -> Scene:
        """A scene from its scene.json object, checked first against `schemas.SceneFile`
        (SchemaError naming the entry at fault)."""
        parse(SceneFile, d, "scene.json")
        s = Scene(seed=int(d["seed"]), config=dict(d.get("config", {})))
        for r in d["rooms"]:
            room = Room.from_json(r)
            s.rooms[room.name] = room
        for o in d["objects"]:
            s.add_object(SceneObject.from_json(o))
        s.floorplan = d.get("floorplan")
        if d.get("doors") is not None:
            s.doors = {str(k): float(v) for k, v in d["doors"].items()}
        return s
