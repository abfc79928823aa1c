"""What the plan drawings (`plan.py` for scenes, `floorplan.py` for bare floorplans) share:
shapely polygons as matplotlib paths, the wall colour, the room-type colours and the figure of
storey panels side by side at one scale."""
from __future__ import annotations

from typing import Any

import numpy as np
import shapely.geometry as sg
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from matplotlib.path import Path

from indoorgen.model.room_types import DEFAULT_COLOUR, ROOM_TYPES

WALL_COLOUR = "#3b3b3b"


def polygon_path(geom: Any) -> Path:
    """A matplotlib Path for a shapely Polygon or MultiPolygon, holes included."""
    polys = list(geom.geoms) if hasattr(geom, "geoms") else [geom]
    verts, codes = [], []
    for p in polys:
        if not isinstance(p, sg.Polygon) or p.is_empty:
            continue
        for ring in (p.exterior, *p.interiors):
            xy = np.asarray(ring.coords)[:, :2]
            verts.append(xy)
            c = np.full(len(xy), Path.LINETO, dtype=Path.code_type)
            c[0], c[-1] = Path.MOVETO, Path.CLOSEPOLY
            codes.append(c)
    if not verts:
        return Path(np.zeros((1, 2)), [Path.MOVETO])
    return Path(np.concatenate(verts), np.concatenate(codes))


def room_colour(room_type: str) -> str:
    """The fill colour of a room of `room_type` in plan drawings (the table's, or a neutral
    grey for types it does not know)."""
    spec = ROOM_TYPES.get(room_type)
    return spec.colour if spec is not None else DEFAULT_COLOUR


#: the plan drawings' resolution, the size a panel's plan gets at most and the most all the
#: panels side by side take (pixels)
DPI = 125
PANEL_MAX_W, PANEL_MAX_H, ALL_PANELS_MAX_W = 700, 860, 1800
#: margins around the panels (pixels): tick labels left and below, titles above
LEFT_PX, BOTTOM_PX, TOP_PX, GAP_PX, TITLE_PX = 58, 42, 40, 58, 26


def panel_figure(bounds: np.ndarray, panels: int, legend_px: int = 0,
                 min_height_px: int = 360) -> tuple[Figure, list[Axes]]:
    """A figure (Agg canvas, no layout engine: positions are final when this returns) with
    `panels` equal plan panels side by side, each showing `bounds` [xmin, ymin, xmax, ymax] at
    the same scale, and `legend_px` pixels kept free on the right."""
    w, h = float(bounds[2] - bounds[0]), float(bounds[3] - bounds[1])
    most_w = min(PANEL_MAX_W, ALL_PANELS_MAX_W / panels)
    scale = min(most_w / max(w, 1e-6), PANEL_MAX_H / max(h, 1e-6))  # pixels per metre
    pw, ph = w * scale, h * scale
    width = LEFT_PX + panels * pw + (panels - 1) * GAP_PX + legend_px + 12
    height = max(BOTTOM_PX + ph + TITLE_PX + TOP_PX, min_height_px)
    fig = Figure(figsize=(width / DPI, height / DPI), dpi=DPI)
    FigureCanvasAgg(fig)
    y0 = (height - TOP_PX - TITLE_PX - ph + BOTTOM_PX) / 2
    axes = []
    for k in range(panels):
        x0 = LEFT_PX + k * (pw + GAP_PX)
        ax = fig.add_axes((x0 / width, y0 / height, pw / width, ph / height))
        ax.set_xlim(bounds[0], bounds[2])
        ax.set_ylim(bounds[1], bounds[3])
        ax.set_aspect("equal")
        ax.apply_aspect()
        axes.append(ax)
    return fig, axes


def side_legend(fig: Figure, last: Axes, handles: list[Artist], title: str) -> None:
    """A legend of `handles` right of the panels (beside `last`, the rightmost)."""
    box = last.get_position()
    fig.legend(handles=handles, loc="upper left", bbox_to_anchor=(box.x1 + 0.01, box.y1),
               fontsize=7, frameon=False, title=title, title_fontsize=8, alignment="left")


def numbered_handles(numbered: list[tuple[int, str]]) -> list[Artist]:
    """Legend rows (no swatch) naming the rooms a plan labels only by number."""
    return [Patch(facecolor="none", edgecolor="none", label=f"{n}: {name}")
            for n, name in numbered]
