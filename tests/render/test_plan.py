"""Tests for the top-down plan renderer (indoorgen.render.plan)."""
from __future__ import annotations

import math

import matplotlib.image as mpimg
import numpy as np
import shapely.affinity as sa
import shapely.geometry as sg

from indoorgen.model.scene import Door, Pose, Room, Scene, SceneObject
from indoorgen.render.plan import draw_plan, object_class, short_label


def _footprint(x: float, y: float, yaw: float, depth: float, width: float) -> sg.Polygon:
    box = sg.box(-depth / 2, -width / 2, depth / 2, width / 2)
    return sa.translate(sa.rotate(box, yaw, origin=(0, 0), use_radians=True), x, y)


def _scene() -> tuple[Scene, dict[str, sg.Polygon]]:
    room = Room("living_room", "living_room", [(0, 0), (5, 0), (5, 4), (0, 4)],
                doors=[Door("door_0", 0, 1.5)])
    scene = Scene(seed=3, rooms={room.name: room})
    sofa = SceneObject("sofa_0", "sofa", {}, 1, Pose((0.5, 2.0, 0.0), 0.0),
                       ["furniture", "seating", "sofa"], room.name)
    cup = SceneObject("cup_12", "cup", {}, 2, Pose((0.5, 2.0, 0.45), math.pi / 2),
                      ["small_object", "tableware", "cup"], room.name)
    scene.add_object(sofa)
    scene.add_object(cup)
    fps = {"sofa_0": _footprint(0.5, 2.0, 0.0, 0.9, 2.0),
           "cup_12": _footprint(0.5, 2.0, math.pi / 2, 0.1, 0.1)}
    return scene, fps


def test_draw_plan_writes_png(tmp_path):
    scene, fps = _scene()
    zones = {"living_room": [sg.box(0.95, 0.0, 2.05, 1.0)]}
    out = tmp_path / "plan.png"
    draw_plan(scene, fps, out, door_zones=zones, title="test plan")
    assert out.exists()
    img = mpimg.imread(out)
    assert img.ndim == 3 and 900 <= img.shape[1] <= 1100
    rgb = img[..., :3]
    assert (rgb < 0.95).any(axis=-1).mean() > 0.05  # plenty of non-white pixels
    # the sofa's colour (seating blue) appears in the picture
    assert (np.abs(rgb - np.array([0.40, 0.54, 0.71])).max(axis=-1) < 0.08).sum() > 100


def test_draw_plan_handles_missing_footprints_and_no_objects(tmp_path):
    scene, _ = _scene()
    draw_plan(scene, {}, tmp_path / "empty.png")
    assert mpimg.imread(tmp_path / "empty.png").shape[1] > 0
    draw_plan(Scene(seed=0), {}, tmp_path / "nothing.png")
    assert (tmp_path / "nothing.png").exists()


def test_object_class_prefers_specific_classes():
    assert object_class(["furniture", "seating", "chair"])[0] == "seating"
    assert object_class(["furniture", "table"])[0] == "table"
    assert object_class(["furniture"])[0] == "furniture"
    assert object_class(["small_object", "book"])[0] == "small objects"
    assert object_class(["mystery"])[0] == "other"


def test_short_label():
    assert short_label("dining_chair_03") == "dining chair"
    assert short_label("sofa") == "sofa"
    assert short_label("tv2") == "tv"
