"""Top-down plan picture of a scene (`plan.png`).

The renderer is deliberately ignorant of assets: callers pass each object's world XY footprint,
so drawing a plan never builds a mesh. It uses matplotlib's object-oriented API with the Agg
canvas only (never pyplot), so it is thread-safe and leaves no global figure state behind.
A home's storeys sit side by side at one scale, drawn from its floorplan record as built (walls,
doors at their leaf's width, open connections as gaps, windows, stairs, the front door). Text
never collides (`labels`): rooms are named inside themselves, abbreviated or numbered (and named
in the legend) when small; object labels that do not fit are left out.
"""
from __future__ import annotations

import logging
import re
from collections import Counter
from collections.abc import Iterable
from os import PathLike

import matplotlib.patheffects as pe
import numpy as np
import shapely.geometry as sg
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import FancyArrow, Patch, PathPatch

from indoorgen.architecture.walls import WallFrame, WallThickness
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.floorplan_io import from_json
from indoorgen.model.scene import Door, Room, Scene, SceneObject
from indoorgen.model.tags import Semantics
from indoorgen.render.drawing import (
    DPI,
    WALL_COLOUR,
    numbered_handles,
    panel_figure,
    polygon_path,
    side_legend,
)
from indoorgen.render.labels import LabelPlacer, place_room, room_abbreviation, room_label
from indoorgen.render.symbols import (
    door_symbol,
    draw_storey_openings,
    entrance_box,
    label_fixtures,
    nice_length,
    patch,
    scale_bar,
    stair_symbol,
    symbol_handles,
)

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
ZONE_COLOUR = "#d62728"
ROOM_TEXT = "#6b6254"
LEGEND_PX = 210
#: objects of a home smaller than this (m^2 of footprint) go unlabelled: furniture only
HOME_LABEL_AREA = 0.3
#: objects smaller than this (m^2) get the small label font
SMALL_AREA = 0.15
#: free space under a plan for its scale bar, m
BAR_MARGIN = 0.5


def draw_plan(scene: Scene, footprints: dict[str, sg.Polygon], path: str | PathLike, *,
              door_zones: dict[str, list[sg.Polygon]] | None = None,
              title: str | None = None) -> None:
    """Draw `scene` seen from above and save it as a PNG at `path` (see `plan_figure`)."""
    plan_figure(scene, footprints, door_zones=door_zones, title=title).savefig(
        path, dpi=DPI, facecolor="white")
    log.debug("plan written to %s", path)


def plan_figure(scene: Scene, footprints: dict[str, sg.Polygon], *,
                door_zones: dict[str, list[sg.Polygon]] | None = None,
                title: str | None = None) -> Figure:
    """The plan of `scene` as a figure: one panel per storey, side by side at one scale (a
    single room's plan about 1000 px wide), a scale bar and a legend on the right.

    `footprints` maps object names to world-XY footprint polygons; objects without one are
    skipped. `door_zones` maps room names to door clearance polygons, drawn hatched. Objects are
    filled by class colour, lowest first, each with a front arrow and, where it fits, a label.
    """
    storeys = sorted({r.storey for r in scene.rooms.values()}) or [0]
    fp = from_json(scene.floorplan) if scene.floorplan is not None else None
    bounds = _scene_bounds(scene, footprints,
                           entrance_box(fp, WallThickness()) if fp is not None else None)
    fig, axes = panel_figure(bounds, len(storeys), LEGEND_PX)
    home = len(scene.rooms) > 1
    kinds = Counter(r.room_type for r in scene.rooms.values())
    classes: dict[str, str] = {}
    numbered: list[tuple[int, str]] = []
    for ax, level in zip(axes, storeys, strict=True):
        rooms = [r for r in scene.rooms.values() if r.storey == level]
        names = {r.name for r in rooms}
        if fp is not None:
            swings = _draw_storey(ax, fp, level)
        else:
            swings = [s for room in rooms for s in _draw_room(ax, room)]
        for rn, zones in (door_zones or {}).items():
            if rn in names or not scene.rooms:
                for z in zones:
                    _draw_zone(ax, z)
        mine = [o for o in scene.objects.values() if o.name in footprints
                and not footprints[o.name].is_empty and (o.room in names or not scene.rooms)]
        classes.update(_draw_objects(ax, mine, footprints))
        placer = LabelPlacer(ax)
        placer.keep_clear(swings)
        length = nice_length(float(bounds[2] - bounds[0]))
        at = scale_bar(ax, bounds[0] + 0.15 * length, bounds[1] + 0.12, length)
        placer.place([f"{length:g} m"], [at], fontsize=7, va="bottom")
        _label_rooms(placer, rooms, kinds, numbered, 9 if home else 12)
        storey = next((s for s in fp.storeys if s.level == level), None) if fp else None
        if fp is not None and storey is not None:
            label_fixtures(placer, fp, storey, WallThickness())
        _label_objects(placer, mine, footprints, HOME_LABEL_AREA if home else 0.0)
        heading = f"storey {level}" if len(storeys) > 1 else ""
        _finish_axes(ax, heading)
    heading = title if title is not None else _default_title(scene)
    if heading:
        fig.suptitle(heading, fontsize=11)
    _draw_legend(fig, axes[-1], dict(sorted(classes.items())),
                 bool(door_zones and any(door_zones.values())), numbered,
                 fp is not None and any(s.windows for s in fp.storeys),
                 fp is not None and bool(fp.vehicle_doors))
    return fig


# --------------------------------------------------------------------------------------------
# layout


def _scene_bounds(scene: Scene, footprints: dict[str, sg.Polygon],
                  door: np.ndarray | None) -> np.ndarray:
    """[xmin, ymin, xmax, ymax] of every room (with walls) and footprint with a margin (4 % of
    the plan), the box `door` (the front door's arrow and label) and room for the scale bar
    below."""
    boxes = [np.asarray(sg.Polygon(r.polygon).buffer(r.wall_thickness, join_style="mitre").bounds)
             for r in scene.rooms.values() if len(r.polygon) >= 3]
    boxes += [np.asarray(f.bounds) for f in footprints.values() if not f.is_empty]
    if not boxes:
        return np.array([-1.0, -1.0 - BAR_MARGIN, 1.0, 1.0])
    b = np.stack(boxes)
    lo, hi = b[:, :2].min(axis=0), b[:, 2:].max(axis=0)
    pad = 0.04 * max(float((hi - lo).max()), 1.0)
    lo, hi = lo - pad, hi + pad
    if door is not None:
        lo, hi = np.minimum(lo, door[:2]), np.maximum(hi, door[2:])
    return np.concatenate([lo - [0.0, BAR_MARGIN], hi])


def _default_title(scene: Scene) -> str:
    n_rooms, n_obj = len(scene.rooms), len(scene.objects)
    return (f"seed {scene.seed}: {n_rooms} room{'s' * (n_rooms != 1)}, "
            f"{n_obj} object{'s' * (n_obj != 1)}")


def _finish_axes(ax: Axes, title: str) -> None:
    ax.tick_params(labelsize=7, colors="#666666")
    ax.grid(True, color="#e6e6e6", linewidth=0.5, zorder=0)
    ax.set_axisbelow(True)
    for s in ax.spines.values():
        s.set_color("#bbbbbb")
    if title:
        ax.set_title(title, fontsize=10)


def _draw_legend(fig: Figure, last: Axes, classes: dict[str, str], zones: bool,
                 numbered: list[tuple[int, str]], windows: bool, vehicle_doors: bool) -> None:
    """Walls, doors (and windows and vehicle doors), door clearances, object classes and the rooms labelled by
    number."""
    handles: list[Artist] = [Patch(facecolor=WALL_COLOUR, edgecolor=WALL_COLOUR, label="wall")]
    handles += symbol_handles(windows, vehicle_doors)
    if zones:
        handles.append(Patch(facecolor="none", edgecolor=ZONE_COLOUR, hatch="///",
                             label="door clearance"))
    handles += [Patch(facecolor=c, edgecolor=_darker(c), label=name)
                for name, c in classes.items()]
    side_legend(fig, last, handles + numbered_handles(numbered), "legend")


def _label_rooms(placer: LabelPlacer, rooms: list[Room], kinds: Counter[str],
                 numbered: list[tuple[int, str]], size: float) -> None:
    """Name each room inside itself (abbreviated if need be); rooms that get a number instead
    are appended to `numbered` for the legend. `kinds` counts the home's rooms by type."""
    for room in sorted(rooms, key=lambda r: r.name):
        if len(room.polygon) < 3:
            continue
        several = kinds[room.room_type] > 1
        label = room_label(room.name, room.room_type, several)
        got = place_room(placer, sg.Polygon(room.polygon),
                         [label, room_abbreviation(room.name, room.room_type, several)],
                         len(numbered) + 1, fontsize=size, color=ROOM_TEXT, fontweight="bold",
                         path_effects=[pe.withStroke(linewidth=2.5, foreground="white")])
        if got is False:
            numbered.append((len(numbered) + 1, label))


# --------------------------------------------------------------------------------------------
# architecture


def _draw_storey(ax: Axes, fp: Floorplan, level: int) -> list[sg.Polygon]:
    """A home's storey from its floorplan record: floors, stairs, walls and their openings;
    returns what labels should keep clear of: the doors' swings and the stairs."""
    storey = next((s for s in fp.storeys if s.level == level), None)
    if storey is None:
        return []
    for r in storey.rooms:
        patch(ax, r.shape(), facecolor=FLOOR_COLOUR, edgecolor="none", zorder=1)
    stairs = [st for st in fp.stairs if level in (st.from_level, st.to_level)]
    for st in stairs:
        stair_symbol(ax, st, level)
    return (draw_storey_openings(ax, fp, storey, WallThickness(), fp.room_depths())
            + [st.shape() for st in stairs])


def _draw_room(ax: Axes, room: Room) -> list[sg.Polygon]:
    """A single room: floor, wall band (the polygon grown by the wall thickness) and doors;
    returns the doors' swings."""
    if len(room.polygon) < 3:
        return []
    poly = sg.Polygon(room.polygon)
    band = poly.buffer(room.wall_thickness, join_style="mitre").difference(poly)
    ax.add_patch(PathPatch(polygon_path(poly), facecolor=FLOOR_COLOUR, edgecolor="none",
                           zorder=1))
    ax.add_patch(PathPatch(polygon_path(band), facecolor=WALL_COLOUR, edgecolor=WALL_COLOUR,
                           linewidth=0.8, zorder=3))
    swings = []
    for door in room.doors:
        f = _door_frame(room, door)
        if f is not None:
            patch(ax, f.rect(door.width, -f.thickness / 2 - 0.01, f.thickness / 2 + 0.01),
                  facecolor=FLOOR_COLOUR, edgecolor="none", zorder=4)
            swings.append(door_symbol(ax, f, door.width, f.n))
    return swings


def _door_frame(room: Room, door: Door) -> WallFrame | None:
    """The frame of a single room's door: centred in its wall band, `n` pointing in."""
    p = np.asarray(room.polygon, float)
    if not 0 <= door.wall < len(p):
        return None
    d = p[(door.wall + 1) % len(p)] - p[door.wall]
    d = d / np.linalg.norm(d)
    inward = np.array([-d[1], d[0]])  # polygons are counter-clockwise
    t = room.wall_thickness
    return WallFrame(p[door.wall] + door.offset * d - t / 2 * inward, d, inward, t)


def _draw_zone(ax, zone: sg.Polygon) -> None:
    """A door clearance zone: light hatched area with a dashed outline."""
    if zone.is_empty:
        return
    ax.add_patch(PathPatch(polygon_path(zone), facecolor=ZONE_COLOUR, alpha=0.07,
                           edgecolor="none", zorder=2))
    ax.add_patch(PathPatch(polygon_path(zone), facecolor="none", edgecolor=ZONE_COLOUR,
                           hatch="///", linewidth=0.6, linestyle="--", alpha=0.45, zorder=2))


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


def _draw_objects(ax: Axes, objs: list[SceneObject],
                  footprints: dict[str, sg.Polygon]) -> dict[str, str]:
    """Fill every footprint by class, lowest and largest first so that small objects on top of
    furniture stay visible, each with its front arrow; return the classes drawn (legend name ->
    colour)."""
    objs = sorted(objs, key=lambda o: (float(o.pose.position[2]), -footprints[o.name].area,
                                       o.name))
    px = _metres_per_pixel(ax)
    classes: dict[str, str] = {}
    for k, obj in enumerate(objs):
        name, colour = object_class(obj.tags)
        classes.setdefault(name, colour)
        _draw_object(ax, obj, footprints[obj.name], colour, 10 + 3 * k, px)
    return dict(sorted(classes.items()))


def _draw_object(ax: Axes, obj: SceneObject, fp: sg.Polygon, colour: str, z: float,
                 px: float) -> None:
    """One footprint: fill, outline and front arrow, stacked at z-order `z` (`px`: metres per
    pixel)."""
    floor_cover = colour == CLASS_COLOURS[0][2]
    ax.add_patch(PathPatch(polygon_path(fp), facecolor=colour, edgecolor=_darker(colour),
                           linewidth=0.8, alpha=0.6 if floor_cover else 0.85, zorder=z))
    c = np.asarray(fp.centroid.coords[0])
    front = obj.pose.front()[:2]
    arrow_len = float(np.clip(0.45 * np.sqrt(max(fp.area, 1e-6)), 10 * px, 0.5))
    ax.add_patch(FancyArrow(c[0], c[1], *(arrow_len * front), width=2.0 * px,
                            head_width=8.0 * px, head_length=min(7.0 * px, 0.5 * arrow_len),
                            length_includes_head=True, color="#1f1f1f", alpha=0.7,
                            linewidth=0, zorder=z + 500))


def _label_objects(placer: LabelPlacer, objs: list[SceneObject],
                   footprints: dict[str, sg.Polygon], min_area: float) -> None:
    """Label objects of at least `min_area` m^2, largest first, each behind its front arrow's
    tail (or on its centre) where the label collides with no other; the rest go unlabelled."""
    px = _metres_per_pixel(placer.ax)
    big = sorted((o for o in objs if footprints[o.name].area >= min_area),
                 key=lambda o: (-footprints[o.name].area, o.name))
    for obj in big:
        fp = footprints[obj.name]
        c = np.asarray(fp.centroid.coords[0])
        tail = c - obj.pose.front()[:2] * (9.0 * px)
        placer.place([short_label(obj.name)], [(tail[0], tail[1]), (c[0], c[1])],
                     fontsize=5.5 if fp.area < SMALL_AREA else 6.5, color="#202020",
                     path_effects=[pe.withStroke(linewidth=1.8, foreground="white")])


def _metres_per_pixel(ax: Axes) -> float:
    """The plan's scale on `ax` (equal aspect, final position)."""
    (x0, _), (x1, _) = ax.transData.transform([(0.0, 0.0), (1.0, 0.0)])
    return 1.0 / max(float(x1 - x0), 1e-9)


def _darker(colour: str, factor: float = 0.65) -> tuple[float, float, float]:
    """`colour` (hex) scaled towards black, for outlines."""
    h = colour.lstrip("#")
    rgb = np.array([int(h[i:i + 2], 16) for i in (0, 2, 4)]) / 255.0
    return tuple((rgb * factor).tolist())
