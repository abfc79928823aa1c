"""`plan.png` of a bare floorplan (what `indoorgen floorplan` writes): the storeys side by side
at one scale, rooms coloured by type and named inside themselves (abbreviated, or numbered and
named in the legend, when they are small), walls, doors with their swing, open connections,
windows, garages' vehicle doors, stairs, the front door and a scale bar. Like `plan.py`, it
draws on an Agg canvas without pyplot."""
from __future__ import annotations

from collections import Counter
from os import PathLike

import numpy as np
import shapely.geometry as sg
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from indoorgen.architecture.walls import WallThickness
from indoorgen.model.floorplan import Floorplan, Storey
from indoorgen.render.drawing import DPI, numbered_handles, panel_figure, room_colour, side_legend
from indoorgen.render.labels import LabelPlacer, place_room, room_abbreviation, room_label
from indoorgen.render.symbols import (
    draw_storey_openings,
    entrance_box,
    label_fixtures,
    nice_length,
    patch,
    scale_bar,
    stair_symbol,
    symbol_handles,
)

#: free space around the plan (m), besides the front door's arrow and label; the scale bar's
MARGIN, BAR_MARGIN = 0.6, 0.8
LEGEND_PX = 200
LABEL_STYLE = {"fontsize": 7, "color": "#1f1f1f", "linespacing": 1.0}


def draw_floorplan(fp: Floorplan, path: str | PathLike, walls: WallThickness | None = None,
                   title: str = "", dpi: int = DPI) -> None:
    """Render `fp` to a PNG at `path`."""
    floorplan_figure(fp, walls, title).savefig(path, dpi=dpi, facecolor="white")


def floorplan_figure(fp: Floorplan, walls: WallThickness | None = None,
                     title: str = "") -> Figure:
    """The figure `draw_floorplan` saves: one panel per storey, side by side, and a legend."""
    t = walls or WallThickness()
    b = np.array([r.shape().bounds for _, r in fp.rooms()])
    bounds = np.array([b[:, 0].min() - MARGIN, b[:, 1].min() - MARGIN,
                       b[:, 2].max() + MARGIN, b[:, 3].max() + MARGIN])
    door = entrance_box(fp, t)
    if door is not None:
        bounds = np.concatenate([np.minimum(bounds[:2], door[:2]),
                                 np.maximum(bounds[2:], door[2:])])
    bounds[1] -= BAR_MARGIN
    fig, axes = panel_figure(bounds, len(fp.storeys), LEGEND_PX)
    depth = fp.room_depths()
    kinds = Counter(r.type for _, r in fp.rooms())
    numbered: list[tuple[int, str]] = []
    for ax, storey in zip(axes, fp.storeys, strict=True):
        swings = _draw_storey(ax, fp, storey, t, depth)
        placer = LabelPlacer(ax)
        placer.keep_clear(swings)
        length = nice_length(float(bounds[2] - bounds[0]))
        at = scale_bar(ax, bounds[0] + 0.4, bounds[1] + 0.3, length)
        placer.place([f"{length:g} m"], [at], fontsize=7, va="bottom")
        for r in storey.rooms:
            label = room_label(r.name, r.type, kinds[r.type] > 1)
            short = room_abbreviation(r.name, r.type, kinds[r.type] > 1)
            area = f"\n{r.shape().area:.1f} m²"
            if place_room(placer, r.shape(), [label + area, label, short + area, short],
                          len(numbered) + 1, **LABEL_STYLE) is False:
                numbered.append((len(numbered) + 1, label))
        label_fixtures(placer, fp, storey, t)
        ax.set_title(f"storey {storey.level}  (floor at {storey.elevation:.2f} m)", fontsize=10)
        ax.tick_params(labelsize=7)
    if title:
        fig.suptitle(title, fontsize=11)
    _legend(fig, axes[-1], sorted(kinds), numbered, bool(fp.vehicle_doors))
    return fig


def _draw_storey(ax: Axes, fp: Floorplan, storey: Storey, t: WallThickness,
                 depth: dict[str, int]) -> list[sg.Polygon]:
    """One storey's drawing: rooms filled by type, stairs, walls and their openings; returns
    what labels should keep clear of: the doors' swings and the stairs."""
    for r in storey.rooms:
        patch(ax, r.shape(), facecolor=room_colour(r.type), edgecolor="none", zorder=1)
    stairs = [st for st in fp.stairs if storey.level in (st.from_level, st.to_level)]
    for st in stairs:
        stair_symbol(ax, st, storey.level)
    return draw_storey_openings(ax, fp, storey, t, depth) + [st.shape() for st in stairs]


def _legend(fig: Figure, last: Axes, types: list[str], numbered: list[tuple[int, str]],
            vehicle_doors: bool) -> None:
    """Room-type colours, the symbols, and the names of rooms labelled by number, right of the
    panels."""
    handles: list[Artist] = [Patch(facecolor=room_colour(k), edgecolor="none",
                                   label=k.replace("_", " ")) for k in types]
    handles += symbol_handles(vehicle_doors=vehicle_doors)
    side_legend(fig, last, handles + numbered_handles(numbered), "legend")
