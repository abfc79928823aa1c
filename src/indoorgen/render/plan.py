"""Top-down plan picture of a scene (`plan.png`).

The renderer is deliberately ignorant of assets: callers pass each object's world XY footprint,
so drawing a plan never builds a mesh. It uses matplotlib's object-oriented API with the Agg
canvas only (never pyplot), so it is thread-safe and leaves no global figure state behind.
"""
from __future__ import annotations

import logging
import math
import re
from collections.abc import Iterable
from os import PathLike
from typing import Any

import matplotlib.patheffects as pe
import numpy as np
import shapely.geometry as sg
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Arc, FancyArrow, Patch, PathPatch

from indoorgen.model.scene import Room, Scene, SceneObject
from indoorgen.model.tags import Semantics
from indoorgen.render.drawing import WALL_COLOUR, polygon_path

log = logging.getLogger(__name__)

#: Object classes in the order they are matched (specific before general) with their colours.
CLASS_COLOURS: tuple[tuple[str, str, str], ...] = (
    (Semantics.FloorCovering.value, "floor covering", "#e3d5b8"),
    (Semantics.Seating.value, "seating", "#4e79a7"),
    (Semantics.Table.value, "table", "#f28e2b"),
    (Semantics.Storage.value, "storage", "#59a14f"),
    (Semantics.Electronics.value, "electronics", "#76b7b2"),
    (Semantics.Lighting.value, "lighting", "#edc948"),
    (Semantics.Decor.value, "decor", "#b07aa1"),
    (Semantics.WallDecoration.value, "decor", "#b07aa1"),
    (Semantics.SmallObject.value, "small objects", "#e15759"),
    (Semantics.Tableware.value, "small objects", "#e15759"),
    (Semantics.Furniture.value, "furniture", "#9c755f"),
)
OTHER_COLOUR = ("other", "#bab0ac")

FLOOR_COLOUR = "#faf8f3"
DOOR_COLOUR = "#7a7a7a"
ZONE_COLOUR = "#d62728"
TARGET_WIDTH_PX = 1000
DPI = 125


def draw_plan(scene: Scene, footprints: dict[str, sg.Polygon], path: str | PathLike, *,
              door_zones: dict[str, list[sg.Polygon]] | None = None,
              title: str | None = None) -> None:
    """Draw `scene` seen from above and save it as a PNG at `path` (about 1000 px wide).

    `footprints` maps object names to world-XY footprint polygons; objects without one are
    skipped. `door_zones` maps room names to door clearance polygons, drawn hatched. Rooms are
    drawn with their walls (outside the polygon, as built), doors as a gap with a swing arc, and
    objects filled by class colour, lowest first, each with a short label and a front arrow.
    """
    fig = Figure(dpi=DPI)
    FigureCanvasAgg(fig)
    storeys = sorted({r.storey for r in scene.rooms.values()}) or [0]
    bounds = _scene_bounds(scene, footprints)
    _size_figure(fig, bounds, len(storeys))
    home = len(scene.rooms) > 1
    classes: dict[str, str] = {}
    for k, level in enumerate(storeys):
        ax = fig.add_subplot(len(storeys), 1, k + 1)
        rooms = [r for r in scene.rooms.values() if r.storey == level]
        names = {r.name for r in rooms}
        for room in rooms:
            _draw_room(ax, room)
        for rn, zones in (door_zones or {}).items():
            if rn in names or not scene.rooms:
                for z in zones:
                    _draw_zone(ax, z)
        mine = {n: f for n, f in footprints.items()
                if n in scene.objects and (scene.objects[n].room in names or not scene.rooms)}
        classes.update(_draw_objects(ax, scene, mine, bounds, label_small=not home))
        if scene.floorplan is not None:
            _draw_openings(ax, scene, scene.floorplan, level)
        for room in rooms:
            _draw_room_label(ax, room, 9 if home else 13)
        heading = title if title is not None else _default_title(scene)
        if len(storeys) > 1:
            heading = f"{heading}  (storey {level})"
        _finish_axes(ax, bounds, heading)
        if k == 0:
            _draw_legend(ax, dict(sorted(classes.items())),
                         bool(door_zones and any(door_zones.values())))
    fig.savefig(path, dpi=DPI, facecolor="white")
    log.debug("plan written to %s", path)


# --------------------------------------------------------------------------------------------
# layout


def _scene_bounds(scene: Scene, footprints: dict[str, sg.Polygon]) -> np.ndarray:
    """[xmin, ymin, xmax, ymax] of every room (with walls) and footprint, with a margin."""
    boxes = [np.asarray(sg.Polygon(r.polygon).buffer(r.wall_thickness, join_style="mitre").bounds)
             for r in scene.rooms.values() if len(r.polygon) >= 3]
    boxes += [np.asarray(f.bounds) for f in footprints.values() if not f.is_empty]
    if not boxes:
        return np.array([-1.0, -1.0, 1.0, 1.0])
    b = np.stack(boxes)
    lo, hi = b[:, :2].min(axis=0), b[:, 2:].max(axis=0)
    pad = 0.04 * max(float((hi - lo).max()), 1.0)
    return np.concatenate([lo - pad, hi + pad])


def _size_figure(fig: Figure, bounds: np.ndarray, panels: int = 1) -> None:
    """Fix the width at TARGET_WIDTH_PX and pick a height that suits the plan's aspect, one
    panel per storey stacked (the legend sits to the right, so the plan gets roughly 70 % of
    the width)."""
    w, h = bounds[2] - bounds[0], bounds[3] - bounds[1]
    width_in = TARGET_WIDTH_PX / DPI
    height_in = float(np.clip(0.7 * width_in * h / max(w, 1e-6) + 0.9, 4.0, 12.0)) * panels
    fig.set_size_inches(width_in, height_in)
    fig.set_layout_engine("constrained")


def _default_title(scene: Scene) -> str:
    n_rooms, n_obj = len(scene.rooms), len(scene.objects)
    return (f"seed {scene.seed}: {n_rooms} room{'s' * (n_rooms != 1)}, "
            f"{n_obj} object{'s' * (n_obj != 1)}")


def _finish_axes(ax, bounds: np.ndarray, title: str) -> None:
    ax.set_xlim(bounds[0], bounds[2])
    ax.set_ylim(bounds[1], bounds[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)", fontsize=8)
    ax.set_ylabel("y (m)", fontsize=8)
    ax.tick_params(labelsize=7, colors="#666666")
    ax.grid(True, color="#e6e6e6", linewidth=0.5, zorder=0)
    ax.set_axisbelow(True)
    for s in ax.spines.values():
        s.set_color("#bbbbbb")
    if title:
        ax.set_title(title, fontsize=10)


def _draw_legend(ax, classes: dict[str, str], zones: bool) -> None:
    handles = [Patch(facecolor=WALL_COLOUR, edgecolor=WALL_COLOUR, label="wall")]
    if zones:
        handles.append(Patch(facecolor="none", edgecolor=ZONE_COLOUR, hatch="///",
                             label="door clearance"))
    handles += [Patch(facecolor=c, edgecolor=_darker(c), label=name)
                for name, c in classes.items()]
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8,
              frameon=False, title="legend", title_fontsize=8, alignment="left")


# --------------------------------------------------------------------------------------------
# architecture


def _edge_frames(room: Room) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Per edge: start point, unit direction, inward normal (CCW polygon) and length."""
    p = np.asarray(room.polygon, float)
    d = np.roll(p, -1, axis=0) - p
    length = np.linalg.norm(d, axis=1)
    d = d / length[:, None]
    return p, d, np.stack([-d[:, 1], d[:, 0]], axis=1), length


def _draw_room(ax, room: Room) -> None:
    """Floor fill, wall band (polygon grown by the wall thickness) and doors."""
    if len(room.polygon) < 3:
        return
    poly = sg.Polygon(room.polygon)
    band = poly.buffer(room.wall_thickness, join_style="mitre").difference(poly)
    ax.add_patch(PathPatch(polygon_path(poly), facecolor=FLOOR_COLOUR, edgecolor="none",
                           zorder=1))
    ax.add_patch(PathPatch(polygon_path(band), facecolor=WALL_COLOUR, edgecolor=WALL_COLOUR,
                           linewidth=0.8, zorder=3))
    for door in room.doors:
        _draw_door(ax, room, door)


def _draw_door(ax, room: Room, door) -> None:
    """A gap in the wall band, the open door leaf and its quarter-circle swing into the room."""
    p, d, n, length = _edge_frames(room)
    if not 0 <= door.wall < len(p):
        return
    i, t, w = door.wall, room.wall_thickness, door.width
    a = p[i] + (door.offset - w / 2) * d[i]
    b = p[i] + (door.offset + w / 2) * d[i]
    eps = 0.01
    gap = np.array([a, b, b - (t + eps) * n[i], a - (t + eps) * n[i]]) + eps * n[i]
    ax.fill(gap[:, 0], gap[:, 1], facecolor=FLOOR_COLOUR, edgecolor="none", zorder=4)
    for jamb in (a, b):  # thin jamb lines keep the opening readable
        seg = np.array([jamb, jamb - t * n[i]])
        ax.plot(seg[:, 0], seg[:, 1], color=WALL_COLOUR, linewidth=1.0, zorder=4)
    leaf = np.array([a, a + w * n[i]])
    ax.plot(leaf[:, 0], leaf[:, 1], color=DOOR_COLOUR, linewidth=1.6, zorder=4,
            solid_capstyle="butt")
    theta = math.degrees(math.atan2(d[i, 1], d[i, 0]))
    ax.add_patch(Arc(tuple(a), 2 * w, 2 * w, theta1=theta, theta2=theta + 90.0,
                     color=DOOR_COLOUR, linewidth=0.9, linestyle=(0, (3, 2)), zorder=4))


def _nearest_edge(rooms: list[Room], point: np.ndarray) -> tuple[np.ndarray, float]:
    """Unit direction of the room edge nearest `point` and the wall thickness there."""
    best = (np.inf, np.array([1.0, 0.0]), 0.12)
    for room in rooms:
        p, d, _, length = _edge_frames(room)
        t = np.clip(np.einsum("ij,ij->i", point - p, d), 0, length)
        dist = np.linalg.norm(p + t[:, None] * d - point, axis=1)
        i = int(np.argmin(dist))
        if dist[i] < best[0]:
            best = (dist[i], d[i], room.wall_thickness)
    return best[1], best[2]


def _draw_openings(ax, scene: Scene, fp: dict[str, Any], level: int) -> None:
    """A home's doors (brown), open connections (dashed), windows (blue), stairs (hatched) and
    front entrance (triangle) on storey `level`, from the floorplan scene.json records `fp`."""
    storey = next((s for s in fp["storeys"] if s["level"] == level), None)
    if storey is None:
        return
    rooms = [r for r in scene.rooms.values() if r.storey == level]
    for kind, colour, lw in (("doors", "#8c564b", 3.0), ("windows", "#4a90d9", 3.0),
                             ("openings", "#8c564b", 1.2)):
        for o in storey.get(kind, []):
            c = np.asarray(o["center"], float)
            d, t = _nearest_edge(rooms, c)
            seg = np.array([c - d * o["width"] / 2, c + d * o["width"] / 2])
            ax.plot(seg[:, 0], seg[:, 1], color=colour, linewidth=lw, zorder=6,
                    solid_capstyle="butt", linestyle="--" if kind == "openings" else "-")
    for st in fp.get("stairs", []):
        if level in (st["from_level"], st["to_level"]):
            poly = sg.Polygon(st["polygon"])
            ax.add_patch(PathPatch(polygon_path(poly), facecolor="#cfcfcf", edgecolor="#555555",
                                   hatch="---", linewidth=0.8, alpha=0.9, zorder=5))
            pt = poly.representative_point()
            ax.text(pt.x, pt.y, "stairs", fontsize=7, ha="center", va="center", zorder=7,
                    path_effects=[pe.withStroke(linewidth=1.8, foreground="white")])
    ent = fp.get("entrance")
    if ent and level == 0:
        ax.plot(*ent["center"], marker="^", markersize=9, color="#2ca02c", zorder=8)


def _draw_zone(ax, zone: sg.Polygon) -> None:
    """A door clearance zone: light hatched area with a dashed outline."""
    if zone.is_empty:
        return
    ax.add_patch(PathPatch(polygon_path(zone), facecolor=ZONE_COLOUR, alpha=0.07,
                           edgecolor="none", zorder=2))
    ax.add_patch(PathPatch(polygon_path(zone), facecolor="none", edgecolor=ZONE_COLOUR,
                           hatch="///", linewidth=0.6, linestyle="--", alpha=0.45, zorder=2))


def _draw_room_label(ax, room: Room, size: float = 13) -> None:
    """The room's name, large and faint, under the furniture at the room's centre."""
    if len(room.polygon) < 3:
        return
    poly = sg.Polygon(room.polygon)
    pt = poly.centroid if poly.contains(poly.centroid) else poly.representative_point()
    ax.text(pt.x, pt.y, room.name.replace("_", " "), fontsize=size, color="#d0cbc0",
            ha="center", va="center", zorder=1.5, fontweight="bold")


# --------------------------------------------------------------------------------------------
# objects


def object_class(tags: Iterable[str]) -> tuple[str, str]:
    """(legend name, colour) of the first class in CLASS_COLOURS that `tags` contain."""
    tagset = {t.value if isinstance(t, Semantics) else str(t) for t in tags}
    for tag, name, colour in CLASS_COLOURS:
        if tag in tagset:
            return name, colour
    return OTHER_COLOUR


def short_label(name: str) -> str:
    """An object's name without its trailing instance number: "dining_chair_03" -> "dining chair"."""
    base = re.sub(r"[_\-\s.]*\d+$", "", name) or name
    return base.replace("_", " ")


def _draw_objects(ax, scene: Scene, footprints: dict[str, sg.Polygon],
                  bounds: np.ndarray, label_small: bool = True) -> dict[str, str]:
    """Fill every footprint by class, lowest and largest first so that small objects on top of
    furniture stay visible; return the classes drawn (legend name -> colour). Without
    `label_small` (a whole home), only furniture-sized footprints are labelled."""
    objs = [o for o in scene.objects.values()
            if o.name in footprints and not footprints[o.name].is_empty]
    missing = len(scene.objects) - len(objs)
    if missing:
        log.debug("plan: %d objects have no footprint and are not drawn", missing)
    objs.sort(key=lambda o: (float(o.pose.position[2]), -footprints[o.name].area, o.name))
    scale = float(max(bounds[2] - bounds[0], bounds[3] - bounds[1]))
    classes: dict[str, str] = {}
    for k, obj in enumerate(objs):
        name, colour = object_class(obj.tags)
        classes.setdefault(name, colour)
        _draw_object(ax, obj, footprints[obj.name], colour, 10 + 3 * k, scale,
                     label=label_small or footprints[obj.name].area >= 0.15)
    return dict(sorted(classes.items()))


def _draw_object(ax, obj: SceneObject, fp: sg.Polygon, colour: str, z: float,
                 scale: float, label: bool = True) -> None:
    """One footprint: fill, outline, front arrow and label, stacked at z-order `z`."""
    floor_cover = colour == CLASS_COLOURS[0][2]
    ax.add_patch(PathPatch(polygon_path(fp), facecolor=colour, edgecolor=_darker(colour),
                           linewidth=0.8, alpha=0.6 if floor_cover else 0.85, zorder=z))
    c = np.asarray(fp.centroid.coords[0])
    size = math.sqrt(max(fp.area, 1e-6))
    front = obj.pose.front()[:2]
    px = scale / (0.7 * TARGET_WIDTH_PX)  # metres per pixel, roughly
    arrow_len = float(np.clip(0.45 * size, 10 * px, 0.5))
    ax.add_patch(FancyArrow(c[0], c[1], *(arrow_len * front), width=2.0 * px,
                            head_width=8.0 * px, head_length=min(7.0 * px, 0.5 * arrow_len),
                            length_includes_head=True, color="#1f1f1f", alpha=0.7,
                            linewidth=0, zorder=z + 500))
    small = fp.area < 0.15
    if not label:
        return
    # the label sits behind the arrow's tail so the two never overlap
    at = c - front * (9.0 * px)
    ax.text(at[0], at[1], short_label(obj.name), fontsize=5.5 if small else 6.5,
            ha="center", va="center", color="#202020", zorder=z + 1000,
            path_effects=[pe.withStroke(linewidth=1.8, foreground="white")])


def _darker(colour: str, factor: float = 0.65) -> tuple[float, float, float]:
    """`colour` (hex) scaled towards black, for outlines."""
    h = colour.lstrip("#")
    rgb = np.array([int(h[i:i + 2], 16) for i in (0, 2, 4)]) / 255.0
    return tuple((rgb * factor).tolist())
