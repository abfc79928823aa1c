"""`ExportBundle`: everything the exporters read, gathered once.

Every exporter (USD, URDF, MJCF, glTF, OBJ) is a pure function of one bundle, so the same code
exports a single furnished room today and a whole home (many rooms, doors, windows, stairs)
tomorrow. A bundle holds:

- `scene`: the `Scene` (objects with generator, params, seed, pose, tags, room, relations);
- `assets`: object name -> full `Asset` (mesh in the object's local frame, links, joints,
  material slots, UVs, convex collision pieces);
- `materials`: object name -> {slot: `MatRef`}: one material (and texture seed) per slot,
  drawn deterministically from the object's `seed`, so re-exporting a saved scene.json gives
  the same materials;
- `elements`: the architecture as `ArchElement`s (floors, walls, ceilings, doors, windows,
  stairs...), meshes in world coordinates, each part with its material. A door's leaf is an
  element of its own below its door (path `(..., <door>, "leaf")`) carrying the `joint` it turns
  on (world coordinates, 0 = shut) and the `joint_value` it stands at: exporters make it a
  moving body jointed to the static architecture.

Builders: `bundle_from_generated` (a freshly generated scene), `bundle_from_scene` (a saved
scene: rooms rebuilt with `architecture.room.build_room`, assets from the generators) and
`elements_from_architecture` (a solidified home from `architecture.solidify`).
"""
from __future__ import annotations

import json
import logging
import zlib
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import trimesh

from indoorgen.architecture.rebuild import scene_architecture
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.assets.materials import choose_materials
from indoorgen.assets.protocol import Asset, Joint
from indoorgen.constraints.relations import StableAgainst, parse_relation
from indoorgen.export.convex import convex_parts, sound_pieces
from indoorgen.export.physics import Inertial, link_inertials, object_inertials
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.scene import Scene, SceneObject
from indoorgen.model.tags import Subpart

log = logging.getLogger(__name__)

#: slots whose faces emit light (bulbs, diffusers, LED faces, flames)
EMISSIVE_SLOTS = ("emissive", "bulb")
#: tags of objects that hang from walls or ceilings, or lie on the floor under furniture (fixed
#: in simulators)
FIXED_TAGS = {"wall_mounted", "ceiling_mounted", "floor_covering"}
#: tags of objects other objects stand on the floor through (rugs): written without collision
#: pieces, since furniture legs pass through their centimetre of pile
UNDER_TAGS = {"floor_covering"}


@dataclass(frozen=True)
class MatRef:
    """A material and the seed its textures are baked with: the unit textures are shared by."""

    name: str
    seed: int

    @property
    def key(self) -> str:
        """File-name-safe identifier, e.g. ``oak_3``."""
        return f"{self.name}_{self.seed}"


@dataclass
class ArchPart:
    """One mesh of an architectural element (world coordinates) and its material."""

    name: str
    mesh: trimesh.Trimesh
    material: MatRef
    slot: str


@dataclass
class ArchElement:
    """An architectural element: `path` (names under /World/Architecture, the last one the
    element's own), `kind` (floor | wall | ceiling | door | window | stair | railing ...), the
    `room` it belongs to, its semantic tags and its parts."""

    name: str
    kind: str
    room: str
    path: tuple[str, ...]
    parts: list[ArchPart]
    semantics: list[str] = field(default_factory=list)
    parent: str = ""
    #: convex collision pieces (world coordinates) when the element brings its own (catalogue
    #: doors, windows, stairs); otherwise they are cut from `parts` on demand
    collision: list[trimesh.Trimesh] = field(default_factory=list)
    #: a moving element (a door leaf): its joint to the static architecture (world
    #: coordinates, 0 = shut) and the value its meshes stand at
    joint: Joint | None = None
    joint_value: float = 0.0


@dataclass
class ExportBundle:
    """The input of every exporter (see module docstring)."""

    scene: Scene
    assets: dict[str, Asset]
    materials: dict[str, dict[str, MatRef]]
    elements: list[ArchElement]
    #: room name -> room type, for tagging the room prims of the architecture
    room_types: dict[str, str] = field(default_factory=dict)
    #: derived data memoised for all exporters of one bundle (inertials, convex pieces)
    _memo: dict = field(default_factory=dict, repr=False)

    def inertials(self, name: str) -> dict[str, Inertial]:
        """Per-link `physics.Inertial` of object `name` (computed once per distinct look)."""
        key = ("inertial", self.proto_key(name))
        if key not in self._memo:
            slot_materials = {slot: ref.name for slot, ref in self.materials[name].items()}
            self._memo[key] = object_inertials(self.assets[name], slot_materials,
                                               self.scene.objects[name].tags)
        inertials: dict[str, Inertial] = self._memo[key]
        return inertials

    def element_pieces(self, element: ArchElement) -> list[trimesh.Trimesh]:
        """Convex collision pieces (world coordinates) of an architectural element."""
        key = ("pieces", element.path)
        if key not in self._memo:
            self._memo[key] = sound_pieces(list(element.collision)) or [
                p for part in element.parts for p in convex_parts(part.mesh)]
        return self._memo[key]

    def element_inertial(self, element: ArchElement) -> Inertial:
        """Mass, centre of mass and inertia (world coordinates) of a moving element (a door
        leaf) from its convex pieces and its first part's material."""
        key = ("element_inertial", element.path)
        if key not in self._memo:
            mesh = trimesh.util.concatenate([p.mesh for p in element.parts])
            assert isinstance(mesh, trimesh.Trimesh)  # parts are triangle meshes
            body = Asset(mesh, [], collision=[("base", p)
                                              for p in self.element_pieces(element)])
            self._memo[key] = link_inertials(body, {"body": element.parts[0].material.name}
                                             )["base"]
        inertial: Inertial = self._memo[key]
        return inertial

    @property
    def static_elements(self) -> list[ArchElement]:
        """The elements that never move (everything but door leaves)."""
        return [e for e in self.elements if e.joint is None]

    @property
    def moving_elements(self) -> list[ArchElement]:
        """The elements on a joint (door leaves)."""
        return [e for e in self.elements if e.joint is not None]

    @property
    def objects(self) -> list[SceneObject]:
        """Objects that have an asset, in placement order."""
        return [o for n, o in self.scene.objects.items() if n in self.assets]

    def is_fixed(self, obj: SceneObject) -> bool:
        """Whether `obj` hangs from a wall or ceiling (static in simulators) rather than resting
        on something (a free, movable body)."""
        return is_fixed(obj, set(self.scene.rooms) | set(self.room_types))

    def attachment(self, obj: SceneObject) -> Attachment | None:
        """The link of another object `obj` is fixed to (a garment to the wardrobe it hangs
        in), or None for an object standing on its own."""
        return attachment(obj, self.scene.objects, self.assets)

    def lies_under(self, obj: SceneObject) -> bool:
        """Whether `obj` lies under other objects (a rug): fixed, and written without collision
        pieces (what stands on it stands on the floor through it)."""
        return bool(UNDER_TAGS & set(obj.tags))

    def all_matrefs(self) -> list[MatRef]:
        """Every material used, deduplicated, in a stable order."""
        refs = [r for m in self.materials.values() for r in m.values()]
        refs += [p.material for e in self.elements for p in e.parts]
        return list(dict.fromkeys(refs))

    def proto_key(self, name: str) -> tuple:
        """Identity of an object's look: objects with equal keys have identical meshes and
        materials and may share one prototype."""
        key = ("proto", name)
        if key not in self._memo:
            o = self.scene.objects[name]
            mats = tuple(sorted((s, r.key) for s, r in self.materials[name].items()))
            self._memo[key] = (o.generator, params_json(o.params), mats)
        return self._memo[key]

    def mesh_key(self, name: str) -> str:
        """Short stable identifier of an object's geometry (generator + params), used to share
        mesh files between identical objects."""
        gen, params, _ = self.proto_key(name)
        return f"{gen}_{zlib.crc32(params.encode()) & 0xFFFFFFFF:08x}"


def params_json(params: dict[str, Any]) -> str:
    """Canonical JSON text of a parameter dict (sorted keys, stable float repr): equal params,
    equal text, so it keys an object's look together with its generator."""
    return json.dumps(params, sort_keys=True, default=str)


def is_fixed(obj: SceneObject, rooms: Iterable[str]) -> bool:
    """True for objects tagged wall/ceiling mounted, or whose every relation attaches them to a
    room's wall or ceiling (wall art, sconces)."""
    if FIXED_TAGS & set(obj.tags):
        return True
    rooms = set(rooms)
    rels = obj.relations
    return bool(rels) and all(
        r.parent in rooms and (r.parent_surface.startswith("wall") or r.parent_surface == "ceiling")
        for r in rels)


@dataclass(frozen=True)
class Attachment:
    """An object fixed to a link of another (exporters weld it there, so it moves with the
    link): the other object, its link, and the object's pose in that object's frame."""

    parent: str
    link: str
    position: np.ndarray
    yaw: float


def attachment(obj: SceneObject, objects: dict[str, SceneObject],
               assets: dict[str, Asset]) -> Attachment | None:
    """Where `obj` is fixed to another object: on a surface moving with one of its links (in a
    drawer: that drawer), or hung from its rail by a hook (its base link); None for an object
    standing, lying or hanging on its own (a book on a shelf is a free body)."""
    for r in obj.relations:
        if r.parent not in objects:
            continue
        rel = parse_relation(r.relation)
        hung = isinstance(rel, StableAgainst) and rel.child == Subpart.Hook
        link = next((s.link for s in assets[r.parent].surfaces if s.name == r.parent_surface),
                    "base") if r.parent in assets else "base"
        if hung or link != "base":
            po = objects[r.parent].pose
            local = po.rotation().T @ (np.asarray(obj.pose.position, float)
                                       - np.asarray(po.position, float))
            return Attachment(r.parent, link, local, obj.pose.yaw - po.yaw)
    return None


#: distinct baked looks (colour, grain, weave) each material may take: an object draws one from its
#: seed and a room from its name, so leather sofas and plaster walls differ between scenes while
#: the baked textures stay few enough to cache (export/textures.py)
TEXTURE_VARIANTS = 4


def texture_seed(material: str, variant: int) -> int:
    """The seed a material's textures are baked with for `variant` (0..variants-1)."""
    return (zlib.crc32(material.encode()) + 7919 * int(variant)) % 100_000


def object_materials(obj: SceneObject, asset: Asset, variants: int = TEXTURE_VARIANTS,
                     style: str | None = None) -> dict[str, MatRef]:
    """One `MatRef` per slot of `asset`, deterministic from `obj.seed`: the material name from
    `choose_materials(asset.slots, default_rng(obj.seed), factory.material_choices, style)` (the
    scene's home style), the texture variant from the same stream (`variants` distinct textures
    per material in a scene)."""
    try:
        overrides = get_factory(obj.generator).material_choices
    except Exception:  # an unregistered generator: library defaults
        overrides = {}
    rng = np.random.default_rng(int(obj.seed))
    names = choose_materials(list(asset.slots), rng, overrides, style)
    out = {}
    for slot, mat in names.items():
        v = int(rng.integers(variants)) if variants > 1 else 0
        out[slot] = MatRef(mat, texture_seed(mat, v))
    return out


# --------------------------------------------------------------------------------------------
# architecture

#: material slot of each architectural part kind
PART_SLOTS = {"floor": "floor", "wall": "wall", "walls": "wall", "ceiling": "ceiling",
              "leaf": "door", "casing": "door", "frame": "frame", "glass": "glass",
              "flight": "wood", "rail": "metal"}


def _room_materials(scene: Scene, room: str) -> dict[str, MatRef]:
    """Floor, wall, ceiling, door, frame, glass, wood and metal materials of one room, drawn
    from the scene seed and the room name (the same room always looks the same), the floor one
    its type is laid with (`RoomTypeSpec.floors`: a garage's concrete), the doors' and frames'
    woods and metals in the home's style."""
    rng = np.random.default_rng([int(scene.seed), zlib.crc32(room.encode())])
    slots = ["floor", "wall", "ceiling", "door", "frame", "glass", "wood", "metal"]
    known = scene.rooms.get(room)
    floors = ROOM_TYPES[known.room_type].floors if known and known.room_type in ROOM_TYPES else ()
    overrides = {"floor": dict.fromkeys(floors, 1.0)} if floors else None
    names = choose_materials(slots, rng, overrides, style=scene.style)
    return {s: MatRef(m, texture_seed(m, int(rng.integers(TEXTURE_VARIANTS)))) for s, m in names.items()}


def elements_from_rooms(scene: Scene, rooms: dict) -> list[ArchElement]:
    """Floor, ceiling and walls of each `RoomGeometry` in `rooms` (single-room layout:
    /World/Architecture/<room>/{floor, ceiling, wall_<i>})."""
    out = []
    for room_name, geo in rooms.items():
        mats = _room_materials(scene, room_name)
        parts = [("floor", "floor", geo.floor), ("ceiling", "ceiling", geo.ceiling)]
        walls = list(geo.walls)
        parts += [(f"wall_{i}", "wall", w) for i, w in enumerate(walls)]
        for name, kind, mesh in parts:
            slot = PART_SLOTS[kind]
            out.append(ArchElement(name, kind, room_name, (room_name, name),
                                   [ArchPart("mesh", mesh, mats[slot], slot)], [kind]))
    return out


def elements_from_architecture(scene: Scene, arch) -> list[ArchElement]:
    """Every element of a solidified home (`architecture.solidify.Architecture`): each room's
    floor, ceiling and walls under storey_<k>/<room>, and the doors, windows, stairs and rails
    under storey_<k>/{doors, windows} or stairs/."""
    out: list[ArchElement] = []
    for room_name, geo in arch.rooms.items():
        mats = _room_materials(scene, room_name)
        storey = f"storey_{getattr(geo, 'storey', 0)}"
        parts = [("floor", "floor", geo.floor), ("ceiling", "ceiling", geo.ceiling)]
        parts += [(f"walls_{i}" if i else "walls", "wall", w) for i, w in enumerate(geo.walls)]
        for name, kind, mesh in parts:
            slot = PART_SLOTS[kind]
            out.append(ArchElement(name, kind, room_name, (storey, room_name, name),
                                   [ArchPart("mesh", mesh, mats[slot], slot)],
                                   [kind, "architecture"]))
    groups = {"door": "doors", "entrance": "doors", "window": "windows"}
    for el in arch.elements:
        mats = _room_materials(scene, el.room or "home")
        path: tuple[str, ...]
        if el.kind in ("stair", "railing"):
            path = ("stairs", el.name)
        else:
            path = (f"storey_{el.storey}", groups.get(el.kind, "elements"), el.name)
        el_parts = []
        leaf = None
        for pname, mesh in el.meshes.items():
            slot = PART_SLOTS.get(pname, "frame")
            part = ArchPart(pname, mesh, mats[slot], slot)
            if pname == "leaf" and el.joint is not None:
                leaf = part
            else:
                el_parts.append(part)
        semantics = list(el.semantics) or [el.kind, "architecture"]
        out.append(ArchElement(el.name, el.kind, el.room, path, el_parts, semantics, el.room,
                               list(el.collision)))
        if leaf is not None:
            out.append(ArchElement(f"{el.name}_leaf", "door_leaf", el.room, (*path, "leaf"),
                                   [leaf], [*semantics, "door_leaf"], el.name,
                                   list(el.leaf_collision), el.joint, el.state))
    return out


# --------------------------------------------------------------------------------------------
# builders


def make_bundle(scene: Scene, assets: dict[str, Asset], elements: list[ArchElement], *,
                variants: int = TEXTURE_VARIANTS, room_types: dict[str, str] | None = None) -> ExportBundle:
    """A bundle from its parts; per-object materials are drawn here (see `object_materials`)."""
    mats = {n: object_materials(scene.objects[n], a, variants, scene.style)
            for n, a in assets.items()
            if n in scene.objects}
    types = {r.name: r.room_type for r in scene.rooms.values()}
    types.update(room_types or {})
    return ExportBundle(scene, dict(assets), mats, elements, types)


def bundle_from_generated(gen, *, variants: int = TEXTURE_VARIANTS) -> ExportBundle:
    """The bundle of a `pipeline.Generated` (full assets from its cache; architecture from its
    rooms, or from `gen.architecture` when it is a whole home)."""
    arch = getattr(gen, "architecture", None)
    if arch is not None:
        elements = elements_from_architecture(gen.scene, arch)
        types = {n: g.room.room_type for n, g in arch.rooms.items()}
    else:
        elements = elements_from_rooms(gen.scene, gen.rooms)
        types = {n: g.room.room_type for n, g in gen.rooms.items()}
    return make_bundle(gen.scene, gen.full_assets(), elements, variants=variants,
                       room_types=types)


def bundle_from_scene(scene: Scene, *, rooms: dict | None = None, cache=None,
                      variants: int = TEXTURE_VARIANTS, doors: str | None = None) -> ExportBundle:
    """The bundle of a saved scene without solving: the architecture rebuilt from the scene
    (a home's floorplan solidified again, its door leaves as recorded or as `doors` says; a
    room's polygon; unless `rooms` are given) and assets from their generators (through
    `cache`, an `AssetCache`, so identical objects are built once)."""
    cache = cache or AssetCache()
    arch = None
    if rooms is None:
        rooms, arch = scene_architecture(scene, doors)
    assets = {n: cache.full(o.generator, o.params) for n, o in scene.objects.items()}
    if arch is not None:
        return make_bundle(scene, assets, elements_from_architecture(scene, arch),
                           variants=variants,
                           room_types={n: g.room.room_type for n, g in arch.rooms.items()})
    return make_bundle(scene, assets, elements_from_rooms(scene, rooms), variants=variants)
