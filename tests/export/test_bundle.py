"""The export bundle's identities and choices: look keys, deterministic materials, which objects
hang fixed, the architecture's elements."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets import get_factory
from indoorgen.assets.materials import STYLES, materials_in_family
from indoorgen.export.bundle import (
    TEXTURE_VARIANTS,
    MatRef,
    elements_from_rooms,
    is_fixed,
    make_bundle,
    object_materials,
    params_json,
    texture_seed,
)
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.scene import Pose, RelationInstance, Room, Scene, SceneObject


def _object(name="cabinet_0", generator="cabinet", seed=5, relations=(), tags=()):
    f = get_factory(generator)
    params = f.sample_params(np.random.default_rng(seed))
    obj = SceneObject(name, generator, params, seed, Pose(), list(tags), "r", list(relations))
    return obj, f.create(params)


def test_params_json_is_canonical():
    assert params_json({"b": 1.5, "a": [1, 2]}) == params_json({"a": [1, 2], "b": 1.5})
    assert params_json({"a": 1}) != params_json({"a": 2})


def test_materials_are_drawn_from_the_object_seed():
    obj, asset = _object()
    mats = object_materials(obj, asset)
    assert set(mats) == set(asset.slots)
    assert mats == object_materials(obj, asset)  # the same seed, the same looks
    ref = next(iter(mats.values()))
    assert ref.key == f"{ref.name}_{ref.seed}"
    assert ref.seed in {texture_seed(ref.name, v) for v in range(TEXTURE_VARIANTS)}
    assert 0 <= texture_seed("oak", 3) < 100_000 and texture_seed("oak", 3) != texture_seed("oak", 4)


def test_one_material_takes_several_looks_across_scenes():
    """Leather sofas are not all one colour: the texture variant is drawn with the materials."""
    looks: dict[str, set[int]] = {}
    for seed in range(40):
        obj, asset = _object("sofa_0", "sofa", seed=seed)
        for ref in object_materials(obj, asset).values():
            looks.setdefault(ref.name, set()).add(ref.seed)
    common = max(looks, key=lambda m: len(looks[m]))
    assert len(looks[common]) == TEXTURE_VARIANTS, looks


def test_identical_objects_share_a_look_and_a_mesh_key():
    a, asset = _object("cabinet_0")
    b, _ = _object("cabinet_1")
    c, other = _object("cabinet_2", seed=6)
    scene = Scene(seed=0)
    for o in (a, b, c):
        scene.add_object(o)
    bundle = make_bundle(scene, {"cabinet_0": asset, "cabinet_1": asset, "cabinet_2": other}, [])
    assert bundle.proto_key("cabinet_0") == bundle.proto_key("cabinet_1")
    assert bundle.mesh_key("cabinet_0") == bundle.mesh_key("cabinet_1") != bundle.mesh_key("cabinet_2")
    assert bundle.mesh_key("cabinet_0").startswith("cabinet_")
    assert [o.name for o in bundle.objects] == ["cabinet_0", "cabinet_1", "cabinet_2"]
    assert all(isinstance(r, MatRef) for r in bundle.all_matrefs())


def test_wall_and_ceiling_mounted_objects_are_fixed():
    on_wall = RelationInstance("StableAgainst(back,wall,0)", "r", "back", "wall_0")
    on_floor = RelationInstance("StableAgainst(bottom,floor,0)", "r", "bottom", "floor")
    assert is_fixed(_object(relations=[on_wall])[0], ["r"])
    assert not is_fixed(_object(relations=[on_floor])[0], ["r"])
    assert not is_fixed(_object()[0], ["r"])  # no relation: free
    assert is_fixed(_object(tags=["ceiling_mounted"])[0], [])


def test_a_rooms_elements_are_its_floor_ceiling_and_walls():
    room = Room("r", "bedroom", rectangle(4.0, 3.0))
    scene = Scene(seed=2, rooms={"r": room})
    geo = build_room(room)
    els = elements_from_rooms(scene, {"r": geo})
    assert [e.kind for e in els[:2]] == ["floor", "ceiling"]
    assert len(els) == 2 + len(geo.walls) and all(e.path[0] == "r" for e in els)
    again = elements_from_rooms(scene, {"r": geo})
    assert [e.parts[0].material for e in again] == [e.parts[0].material for e in els]
    mats = {e.parts[0].material for e in els if e.kind == "wall"}
    assert len(mats) == 1  # every wall of a room in the same material


@pytest.mark.parametrize("room_type", ["garage", "bathroom", "utility", "warehouse", "balcony"])
def test_a_rooms_floor_is_one_its_type_is_laid_with(room_type):
    """A garage's floor is concrete and a bathroom's tile or stone, whatever the seed; the
    walls and ceilings draw as in any other room."""
    floors = ROOM_TYPES[room_type].floors
    seen = set()
    for seed in range(12):
        room = Room("r", room_type, rectangle(4.0, 3.0))
        geo = build_room(room)
        els = elements_from_rooms(Scene(seed=seed, rooms={"r": room}), {"r": geo})
        seen.add(next(e for e in els if e.kind == "floor").parts[0].material.name)
    assert seen <= set(floors) and (len(seen) > 1 or len(floors) == 1), seen


@pytest.mark.xdist_group("export_homes")
def test_a_homes_curtains_hang_fixed_and_its_furniture_shares_one_style(exported_homes):
    bundle, d = exported_homes["home1"]
    curtains = [o for o in bundle.scene.objects.values() if o.generator == "curtain"]
    assert curtains, "a home's living room and bedrooms have windows with curtains"
    mjcf = (d / "scene.xml").read_text()
    for c in curtains:  # fixed (every format's exporter asks is_fixed): no free body in MJCF
        assert bundle.is_fixed(c) and f"{c.name}__free" not in mjcf
    style = bundle.scene.style
    assert style in STYLES
    woods = [r.name for refs in bundle.materials.values() for slot, r in refs.items()
             if r.name in materials_in_family("wood")]
    in_style = sum(w in STYLES[style]["wood"] for w in woods)
    assert woods and in_style >= 0.9 * len(woods), (style, sorted(set(woods)))
