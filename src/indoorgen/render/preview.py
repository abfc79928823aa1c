"""Shaded previews of assets, drawn headless with matplotlib, and the catalogue's contact sheet.

A preview is the asset's full mesh seen from the front-left at 3/4 height, each face coloured by
its material (the mean colour of the material its slot draws for this seed) and shaded by a
key light and a fill light, so that shape reads without a GPU. Like the plan, it uses
matplotlib's object-oriented API with the Agg canvas only (never pyplot): no global backend or
figure state.
"""
from __future__ import annotations

import logging
import math
from collections.abc import Iterable, Sequence
from pathlib import Path

import numpy as np
import trimesh
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from mpl_toolkits.mplot3d.axes3d import Axes3D

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.materials import bake, choose_materials
from indoorgen.assets.protocol import Asset

log = logging.getLogger(__name__)

#: where the camera looks from (unit vector, asset frame): front-left, above
VIEW_DIR = np.array([1.0, 0.75, 0.65])
KEY_LIGHT = np.array([0.6, 0.3, 1.0])
FILL_LIGHT = np.array([1.0, -0.8, 0.3])


def slot_colors(asset: Asset, seed: int = 0) -> np.ndarray:
    """An RGB colour per material slot of `asset`: the mean colour of the material the slot
    draws from the material library for `seed`."""
    rng = np.random.default_rng(seed)
    chosen = choose_materials(list(asset.slots), rng)
    return np.array([bake(chosen[s], seed, 32).mean_color for s in asset.slots], float)


def shaded_face_colors(mesh: trimesh.Trimesh, base: np.ndarray) -> np.ndarray:
    """Per-face RGB: `base` (F, 3) lit by a key and a fill light (Lambert) plus ambient."""
    n = mesh.face_normals
    key = np.clip(n @ (KEY_LIGHT / np.linalg.norm(KEY_LIGHT)), 0, 1)
    fill = np.clip(n @ (FILL_LIGHT / np.linalg.norm(FILL_LIGHT)), 0, 1)
    light = 0.35 + 0.55 * key + 0.25 * fill
    return np.clip(base * light[:, None], 0, 1)


def draw_mesh(ax: Axes3D, mesh: trimesh.Trimesh, face_rgb: np.ndarray) -> None:
    """Draw `mesh` on a 3D axes: back faces culled, painter-sorted by matplotlib, equal aspect."""
    view = VIEW_DIR / np.linalg.norm(VIEW_DIR)
    front = mesh.face_normals @ view > -1e-3
    tris = mesh.triangles[front]
    rgb = face_rgb[front]
    # edges drawn in the face colour hide the hairline seams antialiasing leaves between faces
    coll = Poly3DCollection(tris, facecolors=rgb, edgecolors=rgb, linewidths=0.3)
    ax.add_collection3d(coll)
    lo, hi = mesh.bounds
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1), zoom=1.35)
    ax.view_init(elev=math.degrees(math.asin(view[2])), azim=math.degrees(math.atan2(view[1], view[0])))
    ax.set_axis_off()


def asset_face_rgb(asset: Asset, mesh: trimesh.Trimesh | None = None, seed: int = 0) -> np.ndarray:
    """Shaded face colours of `asset` (or of a posed copy `mesh` with the same faces)."""
    mesh = asset.mesh if mesh is None else mesh
    colors = slot_colors(asset, seed)
    slots = asset.face_slots if asset.face_slots is not None else np.zeros(len(mesh.faces), int)
    return shaded_face_colors(mesh, colors[slots])


def render_asset(asset: Asset, path: Path, *, seed: int = 0, size_px: int = 512,
                 open_joints: bool = False, title: str | None = None) -> Path:
    """Write a PNG preview of one asset (optionally with every joint at its upper limit)."""
    mesh = asset.posed({j.name: j.upper for j in asset.joints}) if open_joints else asset.mesh
    fig = Figure(figsize=(size_px / 100, size_px / 100), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(projection="3d")
    draw_mesh(ax, mesh, asset_face_rgb(asset, mesh, seed))
    if title:
        ax.set_title(title, fontsize=9)
    fig.subplots_adjust(0, 0, 1, 0.95)
    fig.savefig(path)
    return Path(path)


def contact_sheet(names: Sequence[str], path: Path, *, seed: int = 0, cols: int = 10,
                  cell_px: int = 200, progress: Iterable | None = None) -> Path:
    """Draw every named generator (sampled with `seed`) in a grid, labelled, as one PNG.
    Articulated assets are drawn with their joints half open, so doors and drawers show."""
    rows = math.ceil(len(names) / cols)
    fig = Figure(figsize=(cols * cell_px / 100, rows * cell_px / 100), dpi=100)
    FigureCanvasAgg(fig)
    it = progress if progress is not None else names
    for i, name in enumerate(it):
        fac = get_factory(name)
        params = fac.sample_params(np.random.default_rng(seed))
        asset = fac.create(params)
        mesh = asset.posed({j.name: 0.5 * j.upper for j in asset.joints})
        ax = fig.add_subplot(rows, cols, i + 1, projection="3d")
        draw_mesh(ax, mesh, asset_face_rgb(asset, mesh, seed))
        # the label under its drawing (a title would sit closer to the cell above)
        ax.text2D(0.5, 0.01, name, transform=ax.transAxes, ha="center", va="bottom", fontsize=8)
    fig.subplots_adjust(0, 0, 1, 1, wspace=0, hspace=0.05)
    fig.savefig(path)
    return Path(path)
