"""Clearance rules on hand-built rooms: drawers opening into a wall, free space before fronts,
and a toilet's side and front clearances."""
from __future__ import annotations

import numpy as np

from indoorgen.model.scene import RelationInstance
from indoorgen.quality.clearance import front_clearance, joint_sweep, toilet_clearance
from support.qualityscene import FACE_DOWN, FACE_UP, context, new_scene, put, size


def _dresser(yaw: float, y: float):
    sc = new_scene("bedroom")
    put(sc, "dresser", 3.0, y, yaw, joints=True)
    return sc


def test_drawers_opening_into_a_wall_fail_joint_sweep():
    ctx = context(_dresser(FACE_DOWN, 0.0))
    depth = ctx.placed["dresser_0"].hi[0]
    ctx = context(_dresser(FACE_DOWN, depth + 0.02))  # front 2 cm from wall_0
    checks = joint_sweep(ctx)
    assert checks and not any(c.ok for c in checks)
    assert max(c.detail["into_wall"] for c in checks) > 0.1


def test_drawers_opening_into_the_room_pass_joint_sweep():
    ctx = context(_dresser(FACE_UP, 0.0))
    depth = ctx.placed["dresser_0"].hi[0]
    checks = joint_sweep(context(_dresser(FACE_UP, depth + 0.02)))  # back to wall_0
    assert checks and all(c.ok for c in checks)


def test_an_object_in_front_of_a_drawer_is_hit_and_named():
    sc = _dresser(FACE_UP, 0.3)
    put(sc, "bed", 3.0, 1.45, FACE_UP)
    checks = [c for c in joint_sweep(context(sc)) if not c.ok]
    assert checks and all(c.objects[-1] == "bed_1" for c in checks)


def test_front_clearance_measures_free_depth_to_the_next_object():
    sc = new_scene("bedroom")
    put(sc, "wardrobe", 3.0, 0.35, FACE_UP)
    ctx = context(sc)
    front = ctx.placed["wardrobe_0"].world_point((ctx.placed["wardrobe_0"].hi[0], 0))[1]
    (open_room,) = front_clearance(ctx)
    assert open_room.ok and abs(open_room.value - 3.0) < 1e-6  # nothing within the probe
    put(sc, "bed", 3.0, 0.0, FACE_UP, name="bed_x")
    ctx = context(sc)
    bed_near = ctx.placed["bed_x"].footprint.bounds[1]
    sc.objects["bed_x"].pose = type(sc.objects["bed_x"].pose)((3.0, front + 0.25 - bed_near, 0.0), FACE_UP)
    (blocked,) = front_clearance(context(sc))
    assert not blocked.ok and abs(blocked.value - 0.25) < 1e-3


def test_toilet_beside_a_wall_fails_and_centred_passes():
    depth = size("toilet")[0]
    sc = new_scene("bathroom", 3.0, 3.0)
    put(sc, "toilet", 0.3, depth / 2, FACE_UP)  # backs to wall_0, centreline 0.3 m from wall_3
    put(sc, "toilet", 1.5, depth / 2, FACE_UP)
    near, mid = toilet_clearance(context(sc))
    assert not near.ok and abs(near.value - 0.3) < 1e-6
    assert mid.ok and mid.detail["front"] >= 0.53


def test_a_chair_pulled_up_to_the_furniture_is_pushed_back_not_in_its_way():
    sc = _dresser(FACE_UP, 0.3)
    front = context(sc).placed["dresser_0"].footprint.bounds[3]
    chair = put(sc, "side_chair", 3.0, front + 0.25, FACE_DOWN)
    assert any(not c.ok and c.objects[-1] == chair for c in joint_sweep(context(sc)))
    # the same chair at the dresser (its relation's parent): one pushes it back to open a drawer
    pulled_up = RelationInstance("Touching(front,front,0)", "dresser_0", "front", "front")
    sc.objects[chair].relations.append(pulled_up)
    assert all(c.ok for c in joint_sweep(context(sc)))


def test_an_objects_footprint_in_a_height_band_is_only_what_rises_into_it():
    # a bed: only its headboard (at its back, local -X) rises past a 0.9 m window sill
    sc = new_scene("bedroom")
    put(sc, "bed", 2.0, 2.0, FACE_UP)
    bed = context(sc).placed["bed_0"]
    whole, high = bed.footprint_between(bed.bottom, bed.top), bed.footprint_between(0.9, 2.0)
    assert abs(whole.area - bed.footprint.area) < 0.02 * bed.footprint.area
    assert 0 < high.area < 0.25 * whole.area
    local = [bed.local_point(np.array(p)) for p in high.exterior.coords]
    assert max(q[0] for q in local) < bed.lo[0] + 0.25  # at the head end
    assert bed.footprint_between(bed.top + 0.1, bed.top + 1.0).is_empty


def test_a_stool_pulled_up_to_an_island_does_not_block_its_front_but_a_stray_one_does():
    sc = new_scene("kitchen", 6.0, 6.0)
    put(sc, "kitchen_island", 3.0, 3.0, FACE_UP)
    ctx = context(sc)
    island = ctx.placed["kitchen_island_0"]
    front = island.world_point((island.hi[0] + 0.2, 0.0))
    stool = put(sc, "stool", float(front[0]), float(front[1]), FACE_UP)
    (stray,) = [c for c in front_clearance(context(sc)) if c.objects == ("kitchen_island_0",)]
    assert not stray.ok and stray.value < 0.2
    sc.objects[stool].relations.append(
        RelationInstance("SupportedBy(front,side,-0.04)", "kitchen_island_0", "front", "side"))
    (pulled,) = [c for c in front_clearance(context(sc)) if c.objects == ("kitchen_island_0",)]
    assert pulled.ok
