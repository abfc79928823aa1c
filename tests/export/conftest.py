"""Shared fixtures of the export tests: generated rooms and their exports (built once per
session: a generation takes several seconds) and a hand-built scene of articulated objects."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen import generate
from indoorgen.architecture.room import rectangle
from indoorgen.assets import get_factory
from indoorgen.constraints.relations import CONTACT_GAP
from indoorgen.export import write_formats
from indoorgen.export.bundle import bundle_from_scene
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.scene import Door, Pose, RelationInstance, Room, Scene, SceneObject
from indoorgen.model.tags import Subpart
from indoorgen.pipeline import GenerateConfig
from indoorgen.programs.relations import hung_from, inside
from support.exports import export_each

#: texture size used by the tests (small: baking is not what they check)
TEX = 128
ALL = "usd,urdf,mjcf,glb,obj"
ROOMS = {"living_room": 0, "dining_room": 0}

#: articulated generators laid out on the floor of a test room (wall cabinet on a wall)
ARTICULATED = ["cabinet", "dresser", "nightstand", "tv_stand", "wardrobe", "desk", "oven",
               "dishwasher", "microwave", "laptop", "storage_box", "toilet",
               "kitchen_wall_cabinet", "fridge", "washing_machine", "cooking_pot"]


@pytest.fixture(scope="session")
def generated():
    """room type -> Generated (default config, seed from ROOMS)."""
    return {rt: generate(seed, GenerateConfig(room_type=rt)) for rt, seed in ROOMS.items()}


@pytest.fixture(scope="session")
def exported(generated, tmp_path_factory):
    """room type -> (bundle, directory with every format, timings)."""
    return export_each(generated, tmp_path_factory, ALL, TEX)


def articulated_scene() -> Scene:
    """A 12 x 10 m room with one object of each articulated generator, spaced out."""
    room = Room("test_room_0", "living_room", rectangle(12.0, 10.0),
                doors=[Door("door_0", 0, 1.0)])
    sc = Scene(seed=1, rooms={room.name: room})
    for i, g in enumerate(ARTICULATED):
        f = get_factory(g)
        p = next(p for p in (f.sample_params(np.random.default_rng(s)) for s in range(30))
                 if f.joints(f.resolve(p)))
        x, y = 1.5 + 2.5 * (i % 4), 1.5 + 2.2 * (i // 4)
        on_wall = g == "kitchen_wall_cabinet"
        rel = (RelationInstance("StableAgainst(back,wall,0)", room.name, "back", "wall_0")
               if on_wall else
               RelationInstance("StableAgainst(bottom,floor,0)", room.name, "bottom", "floor"))
        sc.add_object(SceneObject(f"{g}_0", g, p, 100 + i,
                                  Pose((x, y, 1.4 if on_wall else 0.001), 0.3 * i),
                                  sorted(t.value for t in f.tags), room.name, [rel]))
    hang_garments(sc, sc.objects["wardrobe_0"], GARMENTS)
    put_in_drawer(sc, sc.objects["dresser_0"])
    return sc


def put_in_drawer(sc: Scene, dresser: SceneObject) -> None:
    """Lay a small stack of folded clothes in the middle of `dresser`'s first drawer."""
    floor = next(s for s in get_factory("dresser").create(dresser.params).surfaces
                 if s.subpart == Subpart.Interior and s.link != "base")
    floor = floor.transformed(dresser.pose.rotation(), np.asarray(dresser.pose.position))
    f = get_factory("folded_clothes")
    p = f.resolve(dict(f.sample_params(np.random.default_rng(0)), n_items=2, width=0.25,
                       depth=0.2, item_thickness=0.02))
    pos = floor.origin + [0.0, 0.0, CONTACT_GAP]
    rel = RelationInstance(repr(inside), dresser.name, "bottom", floor.name)
    sc.add_object(SceneObject("folded_clothes_0", "folded_clothes", p, 300,
                              Pose(tuple(float(v) for v in pos), dresser.pose.yaw),
                              sorted(t.value for t in f.tags),
                              dresser.room, [rel]))


#: the garments hung in the articulated scene's wardrobe
GARMENTS = ("shirt", "dress", "coat")


def hang_garments(sc: Scene, wardrobe: SceneObject, kinds: tuple[str, ...]) -> None:
    """Hang one `hung_garment` of each kind from `wardrobe`'s first rail, 12 cm apart from its
    middle on, turned across it (as the solver hangs them)."""
    rail = next(s for s in get_factory("wardrobe").create(wardrobe.params).surfaces
                if s.subpart == Subpart.Rail).transformed(wardrobe.pose.rotation(),
                                                          np.asarray(wardrobe.pose.position))
    f = get_factory("hung_garment")
    yaw = float(np.arctan2(rail.u[1], rail.u[0]))
    for k, kind in enumerate(kinds):
        p = f.resolve(dict(f.sample_params(np.random.default_rng(k)), garment=kind, length=0.6))
        hook = f.placeholder(p).surface("hook")
        spot = rail.origin + (k * 0.12 - 0.12) * rail.u + [0.0, 0.0, CONTACT_GAP]
        pos = spot - yaw_matrix(yaw) @ hook.origin
        rel = RelationInstance(repr(hung_from), wardrobe.name, "hook", rail.name)
        sc.add_object(SceneObject(f"hung_garment_{k}", "hung_garment", p, 200 + k,
                                  Pose(tuple(float(v) for v in pos), yaw),
                                  sorted(t.value for t in f.tags),
                                  wardrobe.room, [rel]))


@pytest.fixture(scope="session")
def articulated(tmp_path_factory):
    """(bundle, directory) of `articulated_scene()` exported as usd, urdf and mjcf."""
    bundle = bundle_from_scene(articulated_scene())
    d = tmp_path_factory.mktemp("articulated")
    write_formats(bundle, d, "usd,urdf,mjcf", texture_resolution=TEX)
    return bundle, d
