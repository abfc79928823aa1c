"""`plan.png` of a bare floorplan (what `indoorgen floorplan` writes): one panel per storey
with rooms coloured by type and labelled, walls, doors with their swing, open connections,
windows, stairs and the front door. Like `plan.py`, it draws on an Agg canvas without pyplot.
"""
from __future__ import annotations

import math
from os import PathLike
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Arc, FancyArrow, PathPatch

from indoorgen.architecture.walls import (
    WallFrame,
    WallThickness,
    door_frame,
    entrance_frame,
    wall_footprint,
    window_frame,
)
from indoorgen.model.floorplan import Floorplan, StairSpec, Storey
from indoorgen.render.drawing import WALL_COLOUR, polygon_path, room_colour

WINDOW_COLOUR = "#4aa3df"


def draw_floorplan(fp: Floorplan, path: str | PathLike, walls: WallThickness | None = None,
                   title: str = "", dpi: int = 110) -> None:
    """Render `fp` to a PNG at `path`."""
    t = walls or WallThickness()
    n = len(fp.storeys)
    x0, y0, x1, y1 = _bounds(fp)
    w, h = x1 - x0, y1 - y0
    size = 6.0
    fig = Figure(figsize=(size * n * max(0.6, w / h) + 0.5, size + 0.6))
    FigureCanvasAgg(fig)
    axes = fig.subplots(1, n, squeeze=False)
    depth = fp.room_depths()
    for ax, storey in zip(axes[0], fp.storeys, strict=True):
        _draw_storey(ax, fp, storey, t, depth)
        ax.set_xlim(x0 - 1.0, x1 + 1.0)
        ax.set_ylim(y0 - 1.0, y1 + 1.0)
        ax.set_aspect("equal")
        ax.set_title(f"storey {storey.level}  (floor at {storey.elevation:.2f} m)", fontsize=10)
        ax.tick_params(labelsize=7)
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)


def _bounds(fp: Floorplan) -> tuple[float, float, float, float]:
    b = np.array([r.shape().bounds for _, r in fp.rooms()])
    return b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()


def _patch(ax: Axes, poly: Any, **kw: Any) -> None:
    """Fill the shapely (multi)polygon `poly`, holes left open, one patch per polygon (so that
    matplotlib snaps each axis-aligned piece to the pixel grid on its own)."""
    for p in getattr(poly, "geoms", [poly]):
        ax.add_patch(PathPatch(polygon_path(p), **kw))


def _draw_storey(ax: Axes, fp: Floorplan, storey: Storey, t: WallThickness,
                 depth: dict[str, int]) -> None:
    """One storey's panel: rooms, walls with their openings, doors, windows, stairs, labels."""
    for r in storey.rooms:
        _patch(ax, r.shape(), facecolor=room_colour(r.type), edgecolor="none", zorder=1)
    walls = wall_footprint(storey, t)
    gaps = []
    for d in storey.doors + storey.openings:
        f = door_frame(storey, d, t)
        gaps.append(f.rect(d.width, -f.thickness, f.thickness))
    for wdw in storey.windows:
        f = window_frame(storey, wdw, t)
        gaps.append(f.rect(wdw.width, -f.thickness, f.thickness))
    if fp.entrance is not None and storey.level == 0:
        f = entrance_frame(storey, fp.entrance, t)
        gaps.append(f.rect(fp.entrance.width, -f.thickness, f.thickness))
    for g in gaps:
        walls = walls.difference(g)
    _patch(ax, walls, facecolor=WALL_COLOUR, edgecolor="none", zorder=3)
    for wdw in storey.windows:
        f = window_frame(storey, wdw, t)
        _patch(ax, f.rect(wdw.width, -f.thickness / 2, f.thickness / 2),
               facecolor="white", edgecolor=WINDOW_COLOUR, linewidth=1.0, zorder=4)
        p, q = f.center - wdw.width / 2 * f.u, f.center + wdw.width / 2 * f.u
        ax.plot([p[0], q[0]], [p[1], q[1]], color=WINDOW_COLOUR, linewidth=1.2, zorder=5)
    for d in storey.doors:
        f = door_frame(storey, d, t)
        a, b = d.rooms
        into = b if depth.get(b, 0) >= depth.get(a, 0) else a
        _door_symbol(ax, f, d.width, f.n if into == b else -f.n)
    for o in storey.openings:
        f = door_frame(storey, o, t)
        p, q = f.center - o.width / 2 * f.u, f.center + o.width / 2 * f.u
        ax.plot([p[0], q[0]], [p[1], q[1]], color=WALL_COLOUR, linewidth=0.8, linestyle=":",
                zorder=4)
    if fp.entrance is not None and storey.level == 0:
        f = entrance_frame(storey, fp.entrance, t)
        _door_symbol(ax, f, fp.entrance.width, -f.n)
        tail = f.center + f.n * 1.2
        ax.add_patch(FancyArrow(tail[0], tail[1], *(-f.n * 0.8), width=0.12, head_width=0.4,
                                head_length=0.3, color="#c0392b", zorder=6))
        x, y = f.center + f.n * 1.45
        ax.text(x, y, "entrance", fontsize=7, color="#c0392b", ha="center", va="center",
                zorder=6)
    for st in fp.stairs:
        if st.from_level == storey.level:
            _stair_symbol(ax, st)
        if st.to_level == storey.level:
            _patch(ax, st.shape(), facecolor="none", edgecolor="#555555",
                   linestyle="--", linewidth=0.8, hatch="//", zorder=2)
            c = st.shape().centroid
            ax.text(c.x, c.y, "open to\nbelow", fontsize=6, ha="center", va="center", zorder=6)
    for r in storey.rooms:
        poly = r.shape()
        p = poly.representative_point() if not poly.contains(poly.centroid) else poly.centroid
        label = r.name.replace("_room", "").replace("_", " ")
        ax.text(p.x, p.y, f"{label}\n{poly.area:.1f} m²", fontsize=7, ha="center", va="center",
                zorder=7, bbox=dict(boxstyle="round,pad=0.15", facecolor="white", alpha=0.6,
                                    edgecolor="none"))


def _door_symbol(ax: Axes, f: WallFrame, width: float, into: np.ndarray) -> None:
    """The open leaf (hinged at one jamb, perpendicular to the wall) and its swing arc."""
    hinge = f.center - width / 2 * f.u + into * f.thickness / 2
    tip = hinge + into * width
    ax.plot([hinge[0], tip[0]], [hinge[1], tip[1]], color="#7a4b1e", linewidth=1.2, zorder=5)
    a0 = math.degrees(math.atan2(f.u[1], f.u[0]))
    a1 = math.degrees(math.atan2(into[1], into[0]))
    lo, hi = (a0, a1) if (a1 - a0) % 360 <= 180 else (a1, a0)
    ax.add_patch(Arc((hinge[0], hinge[1]), 2 * width, 2 * width, theta1=lo, theta2=hi, color="#7a4b1e",
                     linewidth=0.6, linestyle="-", zorder=5))


def _stair_symbol(ax: Axes, st: StairSpec) -> None:
    """A flight seen from its lower storey: treads and an arrow pointing up it."""
    p0, up, right, run, width = st.frame()
    _patch(ax, st.shape(), facecolor="#f5f5f5", edgecolor="#333333",
           linewidth=0.8, zorder=2)
    n = max(2, int(round(run / 0.27)))
    for i in range(1, n):
        a = p0 + up * run * i / n
        b = a + right * width
        ax.plot([a[0], b[0]], [a[1], b[1]], color="#777777", linewidth=0.5, zorder=3)
    mid = p0 + right * width / 2
    ax.add_patch(FancyArrow(*(mid + up * 0.2), *(up * (run - 0.6)), width=0.03,
                            head_width=0.25, head_length=0.25, color="#333333", zorder=4))
    x, y = mid + up * 0.1
    ax.text(x, y, "up", fontsize=6, ha="center", va="top", zorder=6)
