"""Tests for the top-down plan renderer (indoorgen.render.plan)."""
from __future__ import annotations

import math
from collections import Counter

import matplotlib.image as mpimg
import numpy as np
import shapely.affinity as sa
import shapely.geometry as sg
from matplotlib.patches import Arc

from indoorgen.model.floorplan_io import to_json as floorplan_to_json
from indoorgen.model.scene import Door, Pose, Room, Scene, SceneObject
from indoorgen.render.labels import room_abbreviation, room_label
from indoorgen.render.plan import draw_plan, object_class, plan_figure, short_label
from indoorgen.render.symbols import leaf_width
from support.plans import two_storey_home


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


def _crowded_home() -> tuple[Scene, dict[str, sg.Polygon]]:
    """The test two-storey home with every room packed with long-named 0.45 m boxes."""
    fp, _ = two_storey_home()
    rooms = {r.name: Room(r.name, r.type, [tuple(p) for p in r.polygon], storey=s.level)
             for s, r in fp.rooms()}
    scene = Scene(seed=1, rooms=rooms, floorplan=floorplan_to_json(fp))
    fps: dict[str, sg.Polygon] = {}
    for name, room in rooms.items():
        poly = sg.Polygon(room.polygon)
        x0, y0, x1, y1 = poly.bounds
        k = 0
        for x in np.arange(x0 + 0.4, x1 - 0.4, 0.7):
            for y in np.arange(y0 + 0.4, y1 - 0.4, 0.7):
                box = _footprint(x, y, 0.0, 0.45, 0.9 if k % 3 == 0 else 0.45)
                if poly.contains(box):
                    obj = f"kitchen_wall_cabinet_{len(fps)}"
                    scene.add_object(SceneObject(obj, "cabinet", {}, k, Pose((x, y, 0.0), 0.0),
                                                 ["furniture", "storage"], name))
                    fps[obj] = box
                    k += 1
    return scene, fps


def test_home_plan_text_never_collides_and_rooms_are_named(tmp_path, drawn_text,
                                                            text_overlaps):
    scene, fps = _crowded_home()
    fig = plan_figure(scene, fps, title="crowded")
    fig.canvas.draw()
    axes = fig.axes
    assert len(axes) == 2  # storeys side by side: same height, left to right
    a, b = (ax.get_position() for ax in axes)
    assert abs(a.y0 - b.y0) < 1e-9 and a.x1 < b.x0
    legend = " ".join(t.get_text() for leg in fig.legends for t in leg.get_texts())
    kinds = Counter(r.room_type for r in scene.rooms.values())
    for ax, level in zip(axes, (0, 1), strict=True):
        boxes = drawn_text(ax)
        assert len(boxes) > 5
        assert text_overlaps(boxes) == []
        texts = {t.get_text() for t, _ in boxes}
        inv = ax.transData.inverted()
        for room in (r for r in scene.rooms.values() if r.storey == level):
            several = kinds[room.room_type] > 1
            names = {room_label(room.name, room.room_type, several),
                     room_abbreviation(room.name, room.room_type, several)}
            mine = [(t, p) for t, p in boxes if t.get_text().replace("\n", " ") in names]
            numbered = [n for n in texts if n.isdigit() and any(
                f"{n}: {k}" in legend for k in names)]
            assert len(mine) + len(numbered) == 1, room.name
            for _, p in mine:  # a room's name lies inside the room
                (x0, y0), (x1, y1) = inv.transform(p.get_points())
                assert sg.Polygon(room.polygon).contains(sg.box(x0, y0, x1, y1)), room.name
    draw_plan(scene, fps, tmp_path / "plan.png")
    img = mpimg.imread(tmp_path / "plan.png")
    assert img.shape[1] > 1.4 * img.shape[0]  # two storeys side by side, not stacked


def test_home_plan_draws_openings_at_their_real_width():
    scene, fps = _crowded_home()
    fig = plan_figure(scene, fps)
    fp, _ = two_storey_home()
    for ax, storey in zip(fig.axes, fp.storeys, strict=True):
        arcs = [p for p in ax.patches if isinstance(p, Arc)]
        hinged = storey.doors + ([fp.entrance] if storey.level == 0 and fp.entrance else [])
        assert len(arcs) == len(hinged)  # open connections get no arc
        assert sorted(round(a.width / 2, 6) for a in arcs) == sorted(
            round(leaf_width(d.width), 6) for d in hinged)


def test_single_room_door_swings_at_the_leaf_width():
    scene, fps = _scene()
    fig = plan_figure(scene, fps)
    arcs = [p for p in fig.axes[0].patches if isinstance(p, Arc)]
    assert len(arcs) == 1 and abs(arcs[0].width / 2 - leaf_width(0.9)) < 1e-9
    assert abs(arcs[0].center[1] - 0.0) < 1e-9  # hinged at the wall's inner face (y = 0)
