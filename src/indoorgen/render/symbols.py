"""Architectural plan symbols shared by `plan.py` and `floorplan.py`: a storey's walls cut by
its openings, doors (leaf and swing arc at the leaf's real width), open connections (a plain
gap), windows (a thin double line in the wall), garages' vehicle doors (the closed sectional door
in the wall and, dashed, where it runs overhead when open), stairs, the front door and a scale
bar."""
from __future__ import annotations

import math

import matplotlib.patheffects as pe
import numpy as np
import shapely.geometry as sg
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.lines import Line2D
from matplotlib.patches import Arc, FancyArrow, PathPatch

from indoorgen.architecture.walls import (
    WallFrame,
    WallThickness,
    door_frame,
    entrance_frame,
    exterior_frame,
    wall_footprint,
    window_frame,
)
from indoorgen.assets.shapes.architectural import LEAF_GAP
from indoorgen.model.floorplan import Floorplan, StairSpec, Storey, VehicleDoor
from indoorgen.render.drawing import WALL_COLOUR, polygon_path
from indoorgen.render.labels import LabelPlacer

WINDOW_COLOUR = "#3b8fd0"
DOOR_COLOUR = "#7a4b1e"
ENTRANCE_COLOUR = "#c0392b"
STAIR_EDGE = "#555555"
#: a door set's jamb lining board: the middle of interior_door's jamb_thickness range (m)
JAMB = 0.024


def leaf_width(opening: float) -> float:
    """The width of the leaf hung in a rough opening `opening` m wide: the opening less a jamb
    lining and a leaf gap on each side (as the catalogue's door sets build it)."""
    return max(opening - 2 * (JAMB + LEAF_GAP), 0.1)


def patch(ax: Axes, geom: sg.base.BaseGeometry, **kw: object) -> None:
    """Fill the shapely (multi)polygon `geom`, one patch per polygon (so that matplotlib snaps
    each axis-aligned piece to the pixel grid on its own)."""
    for p in getattr(geom, "geoms", [geom]):
        if isinstance(p, sg.Polygon) and not p.is_empty:
            ax.add_patch(PathPatch(polygon_path(p), **kw))


def door_symbol(ax: Axes, f: WallFrame, width: float, into: np.ndarray) -> sg.Polygon:
    """A hinged door in the opening `width` wide at `f`, opening towards `into`: the leaf drawn
    open at 90 degrees from the hinge jamb, and the quarter circle its edge sweeps (radius the
    leaf's width). Returns the square the swing fills, for labels to keep clear of."""
    leaf = leaf_width(width)
    hinge = f.center - (width / 2 - JAMB) * f.u + into * f.thickness / 2
    tip = hinge + into * leaf
    ax.plot([hinge[0], tip[0]], [hinge[1], tip[1]], color=DOOR_COLOUR, linewidth=1.4,
            solid_capstyle="butt", zorder=5)
    a0 = math.degrees(math.atan2(f.u[1], f.u[0]))
    a1 = math.degrees(math.atan2(into[1], into[0]))
    lo, hi = (a0, a1) if (a1 - a0) % 360 <= 180 else (a1, a0)
    ax.add_patch(Arc((hinge[0], hinge[1]), 2 * leaf, 2 * leaf, theta1=lo, theta2=hi,
                     color=DOOR_COLOUR, linewidth=0.7, linestyle=(0, (3, 2)), zorder=5))
    return sg.Polygon([hinge, hinge + leaf * f.u, tip + leaf * f.u, tip])


def window_symbol(ax: Axes, f: WallFrame, width: float) -> None:
    """A window: the wall gap, left white, bridged by a thin double line (the glazing)."""
    patch(ax, f.rect(width, -f.thickness / 2, f.thickness / 2), facecolor="white",
          edgecolor="none", zorder=4)
    for s in (-0.2, 0.2):
        p = f.center - width / 2 * f.u + s * f.thickness * f.n
        q = p + width * f.u
        ax.plot([p[0], q[0]], [p[1], q[1]], color=WINDOW_COLOUR, linewidth=1.0,
                solid_capstyle="butt", zorder=5)
    for e in (-1, 1):  # the reveals, so the window reads as set in the wall
        a = f.center + e * width / 2 * f.u - f.thickness / 2 * f.n
        b = a + f.thickness * f.n
        ax.plot([a[0], b[0]], [a[1], b[1]], color=WALL_COLOUR, linewidth=0.6, zorder=5)


def vehicle_door_frame(storey: Storey, v: VehicleDoor, t: WallThickness) -> WallFrame:
    """The frame of a garage's vehicle door in its exterior wall; `n` points out."""
    return exterior_frame(storey, v.room, v.center, t, f"the vehicle door of {v.room!r}")


def vehicle_door_symbol(ax: Axes, f: WallFrame, v: VehicleDoor) -> sg.Polygon:
    """A garage's sectional door: the closed door as a heavy line in the outer half of the wall
    (where `architecture.solidify` builds its panels) and, dashed, the panels' place overhead
    when it stands open (`v.height` deep into the garage). Returns the door's line in the wall,
    for labels to keep clear of."""
    outer = f.thickness / 4
    a, b = f.center - v.width / 2 * f.u + outer * f.n, f.center + v.width / 2 * f.u + outer * f.n
    ax.plot([a[0], b[0]], [a[1], b[1]], color=DOOR_COLOUR, linewidth=2.2,
            solid_capstyle="butt", zorder=5)
    overhead = f.rect(v.width, -f.thickness / 2 - v.height, -f.thickness / 2)
    patch(ax, overhead, facecolor="none", edgecolor=DOOR_COLOUR, linewidth=0.7,
          linestyle=(0, (3, 2)), zorder=5)
    return f.rect(v.width, -f.thickness / 2, f.thickness / 2)


def storey_walls(fp: Floorplan, storey: Storey, t: WallThickness) -> sg.base.BaseGeometry:
    """The storey's walls with a gap at every door, open connection, window and (on the ground
    floor) the front door."""
    gaps = [door_frame(storey, d, t).rect(d.width, -t.exterior, t.exterior)
            for d in storey.doors + storey.openings]
    gaps += [window_frame(storey, w, t).rect(w.width, -t.exterior, t.exterior)
             for w in storey.windows]
    if fp.entrance is not None and storey.level == 0:
        gaps.append(entrance_frame(storey, fp.entrance, t).rect(
            fp.entrance.width, -t.exterior, t.exterior))
    if storey.level == 0:
        gaps += [vehicle_door_frame(storey, v, t).rect(v.width, -t.exterior, t.exterior)
                 for v in fp.vehicle_doors]
    walls = wall_footprint(storey, t)
    return walls.difference(sg.MultiPolygon(gaps).buffer(0)) if gaps else walls


def draw_storey_openings(ax: Axes, fp: Floorplan, storey: Storey, t: WallThickness,
                         depth: dict[str, int]) -> list[sg.Polygon]:
    """Walls, doors (swinging into the room farther from the front door, as built), open
    connections as plain gaps, windows, garages' vehicle doors and the front door of `storey`;
    returns the doors' swings, the vehicle doors and the front door's arrow."""
    patch(ax, storey_walls(fp, storey, t), facecolor=WALL_COLOUR, edgecolor="none", zorder=3)
    for w in storey.windows:
        window_symbol(ax, window_frame(storey, w, t), w.width)
    swings = []
    for d in storey.doors:
        f = door_frame(storey, d, t)
        a, b = d.rooms
        into = b if depth.get(b, 0) >= depth.get(a, 0) else a
        swings.append(door_symbol(ax, f, d.width, f.n if into == b else -f.n))
    if storey.level == 0:
        swings += [vehicle_door_symbol(ax, vehicle_door_frame(storey, v, t), v)
                   for v in fp.vehicle_doors]
    if fp.entrance is not None and storey.level == 0:
        f = entrance_frame(storey, fp.entrance, t)
        swings.append(door_symbol(ax, f, fp.entrance.width, -f.n))
        tail = f.center + f.n * 1.1
        ax.add_patch(FancyArrow(tail[0], tail[1], *(-f.n * 0.7), width=0.1, head_width=0.35,
                                head_length=0.28, color=ENTRANCE_COLOUR, zorder=6))
        swings.append(f.rect(0.35, 0.3, 1.15))  # the arrow, for labels to keep clear of
    return swings


def entrance_anchors(fp: Floorplan, t: WallThickness) -> list[tuple[float, float]]:
    """Where the front door's label may go, best first: outside the house beyond its arrow,
    then beside the arrow."""
    if fp.entrance is None:
        return []
    f = entrance_frame(fp.storeys[0], fp.entrance, t)
    pts = [f.center + f.n * d for d in (1.5, 2.0)] + [f.center + f.n * d + s * f.u
                                                      for d in (1.0, 0.75)
                                                      for s in (0.9, -0.9, 1.4, -1.4)]
    return [(float(x), float(y)) for x, y in pts]


def entrance_box(fp: Floorplan, t: WallThickness) -> np.ndarray | None:
    """[xmin, ymin, xmax, ymax] of what is drawn outside the front door (its arrow and label),
    for the plan's bounds to include."""
    if fp.entrance is None:
        return None
    f = entrance_frame(fp.storeys[0], fp.entrance, t)
    pts = np.array([f.center + f.n * 2.6 + s * f.u for s in (-0.8, 0.8)] + [f.center])
    return np.concatenate([pts.min(axis=0), pts.max(axis=0)])


def stair_symbol(ax: Axes, st: StairSpec, level: int) -> None:
    """A flight seen from storey `level`: from below, treads and an arrow pointing up it; from
    above, the hatched well it climbs into."""
    if st.to_level == level:
        patch(ax, st.shape(), facecolor="none", edgecolor=STAIR_EDGE, linestyle="--",
              linewidth=0.8, hatch="//", zorder=2)
        return
    p0, up, right, run, width = st.frame()
    patch(ax, st.shape(), facecolor="#f5f5f5", edgecolor="#333333", linewidth=0.8, zorder=2)
    n = max(2, int(round(run / 0.27)))
    k = np.arange(1, n)[:, None]
    a = p0 + up * run * k / n
    b = a + right * width
    for s, e in zip(a, b, strict=True):
        ax.plot([s[0], e[0]], [s[1], e[1]], color="#777777", linewidth=0.5, zorder=3)
    mid = p0 + right * width / 2
    ax.add_patch(FancyArrow(*(mid + up * 0.2), *(up * max(run - 0.6, 0.2)), width=0.03,
                            head_width=0.25, head_length=0.25, color="#333333", zorder=4))


def nice_length(span: float) -> float:
    """A round scale-bar length (1, 2 or 5 times a power of ten) near a fifth of `span` m."""
    target = max(span / 5, 1e-3)
    base = 10 ** math.floor(math.log10(target))
    return float(max(m * base for m in (1, 2, 5) if m * base <= target))


def scale_bar(ax: Axes, x: float, y: float, length: float) -> tuple[float, float]:
    """A black-and-white scale bar `length` m long from (x, y), in two halves; returns where
    its label (`length` m) belongs, just above the bar's middle."""
    h = length / 25
    for i in range(2):
        ax.add_patch(PathPatch(polygon_path(sg.box(x + i * length / 2, y,
                                                   x + (i + 1) * length / 2, y + h)),
                               facecolor="#222222" if i == 0 else "white",
                               edgecolor="#222222", linewidth=0.7, zorder=8))
    return x + length / 2, y + 2.2 * h


def label_fixtures(placer: LabelPlacer, fp: Floorplan, storey: Storey,
                   t: WallThickness) -> None:
    """The stairs' and the front door's words, where they fit."""
    halo = [pe.withStroke(linewidth=2.0, foreground="white")]
    for st in fp.stairs:
        c = st.shape().centroid
        if st.from_level == storey.level:
            p0, up, right, run, width = st.frame()
            beside = [p0 + right * width * s + up * run / 2 for s in (0.25, 0.75)]
            placer.place(["up"], [(float(x), float(y)) for x, y in beside] + [(c.x, c.y)],
                         fontsize=6, path_effects=halo)
        elif st.to_level == storey.level:
            placer.place(["open to\nbelow", "well"], [(c.x, c.y)], fontsize=6,
                         path_effects=halo)
    if storey.level == 0:
        placer.place(["entrance"], entrance_anchors(fp, t), fontsize=7, color=ENTRANCE_COLOUR)


def symbol_handles(windows: bool = True, vehicle_doors: bool = False) -> list[Artist]:
    """Legend rows for the door symbol and (when the plan has any) the window and vehicle-door
    symbols."""
    rows: list[Artist] = [Line2D([], [], color=DOOR_COLOUR, linewidth=0.9,
                                 linestyle=(0, (3, 2)), label="door and its swing")]
    if windows:
        rows.append(Line2D([], [], color=WINDOW_COLOUR, linewidth=1.0, label="window"))
    if vehicle_doors:
        rows.append(Line2D([], [], color=DOOR_COLOUR, linewidth=2.2,
                           label="vehicle door"))
    return rows
