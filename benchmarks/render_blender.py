"""Render a generated scene's USD with Blender, headless on the CPU (a development aid).

    python benchmarks/render_blender.py SCENE_DIR [--out views/] [--size 640] [--samples 24] [--threads 0]

Run it with a Python that has Blender's `bpy` module from the package registry
(`pip install bpy`, which needs the Python version its release is built for); indoorgen itself
never imports bpy. It imports `SCENE_DIR/scene.usdc` (or .usda), and for each room (one
`indoorgen:room` value) renders a view from a high corner of the room looking at its centre, plus
one overhead view of the whole scene, with Cycles on the CPU. Ceilings are hidden so the camera
sees in. The pictures are what a person would judge the layout by: a coffee table beside the
sofa or a TV facing the wall shows at once.
"""
from __future__ import annotations

import argparse
import json
import logging
import math
import sys
from pathlib import Path

log = logging.getLogger("render_blender")


def _bpy():
    """Blender's module, with a one-line message if this Python lacks it."""
    try:
        import bpy  # a dev-only dependency: imported here so the script's --help works without it
    except ImportError:
        sys.exit("render_blender: this Python has no `bpy`; install it with `pip install bpy` "
                 "in a separate environment")
    return bpy


def _reset(bpy) -> None:
    """An empty scene rendered by Cycles on the CPU, denoised, with a soft grey sky."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.engine = "CYCLES"
    sc.cycles.device = "CPU"
    sc.cycles.use_denoising = True
    sc.view_settings.view_transform = "AgX" if "AgX" in [
        v.identifier for v in sc.view_settings.bl_rna.properties["view_transform"].enum_items
    ] else "Filmic"
    world = bpy.data.worlds.new("sky")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs[0].default_value = (0.8, 0.85, 0.9, 1.0)
    bg.inputs[1].default_value = 0.6
    sc.world = world


def _room_boxes(bpy) -> dict[str, tuple[list[float], list[float]]]:
    """Per room, the world bounding box (min, max) of its objects' meshes."""
    from mathutils import Vector  # ships with bpy

    boxes: dict[str, tuple[list[float], list[float]]] = {}
    for ob in bpy.data.objects:
        if ob.type != "MESH":
            continue
        room = ob.get("indoorgen:room") or (ob.parent.get("indoorgen:room") if ob.parent else None)
        if not room:
            continue
        pts = [ob.matrix_world @ Vector(c) for c in ob.bound_box]
        lo, hi = boxes.get(room, ([math.inf] * 3, [-math.inf] * 3))
        boxes[room] = ([min(lo[i], *(p[i] for p in pts)) for i in range(3)],
                       [max(hi[i], *(p[i] for p in pts)) for i in range(3)])
    return boxes


def _hide_ceilings(bpy) -> None:
    """Hide the rooms' ceiling slabs from the camera (the views look in from above); ceiling
    lights stay in view."""
    for ob in bpy.data.objects:
        if ob.name.lower().endswith("_ceiling") or ob.name.lower() == "ceiling":
            ob.hide_render = True
            ob.hide_set(True)  # out of the sight-line rays too


def _hide_near_walls(bpy, front_y: float) -> None:
    """Hide the walls along the side the overview camera looks in from (those running along x
    with their far face before `front_y`): a kitchen run along that wall shows."""
    from mathutils import Vector

    for ob in bpy.data.objects:
        if ob.type != "MESH" or "wall" not in ob.name.lower():
            continue
        pts = [ob.matrix_world @ Vector(c) for c in ob.bound_box]
        ys = [p[1] for p in pts]
        if max(ys) - min(ys) < 0.6 and max(ys) < front_y:
            ob.hide_render = True


def _camera(bpy, eye: tuple[float, float, float], target: tuple[float, float, float],
            lens: float = 18.0):
    """A camera at `eye` looking at `target`."""
    from mathutils import Vector

    cam = bpy.data.objects.get("view_camera")
    if cam is None:
        cam = bpy.data.objects.new("view_camera", bpy.data.cameras.new("view_camera"))
        bpy.context.scene.collection.objects.link(cam)
    cam.data.lens = lens
    cam.location = eye
    cam.rotation_euler = (Vector(target) - Vector(eye)).to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.camera = cam
    return cam


def _open_length(bpy, eye, target) -> float:
    """How far the straight line from `target` towards `eye` runs before it meets geometry,
    as a share of their distance (1.0: the camera sees the room's centre)."""
    from mathutils import Vector

    depsgraph = bpy.context.evaluated_depsgraph_get()
    span = Vector(eye) - Vector(target)
    skip = min(0.5, 0.5 * span.length)  # a pendant lamp over the room's centre does not count
    start = Vector(target) + span.normalized() * skip
    hit, where, *_ = bpy.context.scene.ray_cast(depsgraph, start, span.normalized(),
                                                distance=span.length - skip)
    return (where - Vector(target)).length / span.length if hit else 1.0


def _floor_view(bpy, eye, lo, hi) -> float:
    """The mean open share of the lines from `eye` to nine points low over the room's floor."""
    # low when the camera stands over a fridge or beside a pendant lamp
    from mathutils import Vector

    depsgraph = bpy.context.evaluated_depsgraph_get()
    shares = []
    for fx in (0.2, 0.5, 0.8):
        for fy in (0.2, 0.5, 0.8):
            span = Vector((lo[0] + fx * (hi[0] - lo[0]), lo[1] + fy * (hi[1] - lo[1]),
                           lo[2] + 0.3)) - Vector(eye)
            hit, where, *_ = bpy.context.scene.ray_cast(depsgraph, Vector(eye), span.normalized(),
                                                        distance=span.length)
            shares.append((where - Vector(eye)).length / span.length if hit else 1.0)
    return sum(shares) / len(shares)


def _clear_corner(bpy, lo, hi, target) -> tuple[float, float, float]:
    """The high corner of a room's box from which the camera sees its centre: of the four
    corners, the one whose sight line is open (not inside a wardrobe or behind a wall), and
    among those the one with the most open view of the floor, the farthest along it where none is."""
    height = lo[2] + min(2.3, max(1.2, hi[2] - lo[2] - 0.2))
    corners = [(lo[0] + fx * (hi[0] - lo[0]), lo[1] + fy * (hi[1] - lo[1]), height)
               for fx in (0.15, 0.85) for fy in (0.15, 0.85)]
    # the sight line is probed from above the furniture: the look target may be inside a bed
    probe = (target[0], target[1], lo[2] + 1.3)
    eye = max(corners, key=lambda e: (_open_length(bpy, e, probe), _floor_view(bpy, e, lo, hi)))
    share = _open_length(bpy, eye, probe)
    if share < 1.0:  # every corner's line meets something: stand short of it, on the open part
        eye = tuple(t + (e - t) * max(0.3, 0.85 * share) for e, t in zip(eye, probe, strict=True))
    return eye


def _render(bpy, path: Path) -> None:
    """Render the scene's camera to `path`."""
    bpy.context.scene.render.filepath = str(path)
    bpy.ops.render.render(write_still=True)


def main(argv: list[str] | None = None) -> int:
    """Render one view per room and an overhead view of SCENE_DIR."""
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene_dir", type=Path)
    ap.add_argument("--out", type=Path, default=None, help="where the PNGs go (default SCENE_DIR/views)")
    ap.add_argument("--size", type=int, default=640, help="image width in pixels (height 3/4 of it)")
    ap.add_argument("--samples", type=int, default=24, help="Cycles samples per pixel")
    ap.add_argument("--rooms", default="", help="comma-separated rooms to render (default all)")
    ap.add_argument("--threads", type=int, default=0,
                    help="CPU threads Blender renders with (default 0: Blender's automatic count)")
    args = ap.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    usd = next((args.scene_dir / n for n in ("scene.usdc", "scene.usda", "scene.usd")
                if (args.scene_dir / n).exists()), None)
    if usd is None:
        sys.exit(f"render_blender: no scene.usdc/usda in {args.scene_dir}")
    out = args.out or args.scene_dir / "views"
    out.mkdir(parents=True, exist_ok=True)
    bpy = _bpy()
    _reset(bpy)
    bpy.ops.wm.usd_import(filepath=str(usd))
    _hide_ceilings(bpy)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y = args.size, args.size * 3 // 4
    sc.cycles.samples = args.samples
    if args.threads > 0:
        sc.render.threads_mode = "FIXED"
        sc.render.threads = args.threads
    boxes = _room_boxes(bpy)
    wanted = [r for r in args.rooms.split(",") if r] or sorted(boxes)
    done = {}
    for room in wanted:
        if room not in boxes:
            log.warning("no objects for room %s", room)
            continue
        lo, hi = boxes[room]
        target = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2] + 0.5)
        _camera(bpy, _clear_corner(bpy, lo, hi, target), target)
        path = out / f"{room}.png"
        _render(bpy, path)
        done[room] = str(path)
        log.info("rendered %s", path)
    all_lo = [min(b[0][i] for b in boxes.values()) for i in range(3)]
    all_hi = [max(b[1][i] for b in boxes.values()) for i in range(3)]
    span = max(all_hi[0] - all_lo[0], all_hi[1] - all_lo[1])
    centre = ((all_lo[0] + all_hi[0]) / 2, (all_lo[1] + all_hi[1]) / 2, all_lo[2])
    _hide_near_walls(bpy, all_lo[1] + 0.3)
    _camera(bpy, (centre[0], centre[1] - 0.6 * span, all_lo[2] + 1.1 * span), centre, lens=24.0)
    _render(bpy, out / "overview.png")
    done["overview"] = str(out / "overview.png")
    (out / "views.json").write_text(json.dumps(done, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
