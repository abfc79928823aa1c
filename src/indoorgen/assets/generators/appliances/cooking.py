"""Cooking appliances: built-in wall ovens, cooktops (hobs), freestanding ranges and range
hoods. Fronts face +X. Oven doors drop down (revolute about their lower edge); the grates of a
gas hob and the glass of a ceramic hob are support surfaces.
"""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.appliances._parts import (
    rack_surface,
    rects_polygon,
    slotted_plate,
    wire_rack,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.cabinet_parts import interior_rect, joint_for, open_shell, pull_bar, window_leaf
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, hinge_motion, knob, slide_motion
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between, cylinder, lathe
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: per burner count: burners (u, v, size class) and their grate cells (u0, u1, v0, v1), in
#: fractions of the burner area's half extents (u along X, v along Y)
BURNER_LAYOUTS: dict[int, tuple[list[tuple[float, float, int]], list[tuple[float, float, float, float]]]] = {
    2: ([(-0.5, 0.0, 1), (0.5, 0.0, 0)], [(-1, 0, -1, 1), (0, 1, -1, 1)]),
    3: ([(-0.5, -0.5, 0), (0.5, -0.5, 1), (0.0, 0.5, 2)], [(-1, 0, -1, 0), (0, 1, -1, 0), (-1, 1, 0, 1)]),
    4: ([(-0.5, -0.5, 1), (0.5, -0.5, 0), (-0.5, 0.5, 0), (0.5, 0.5, 2)],
        [(-1, 0, -1, 0), (0, 1, -1, 0), (-1, 0, 0, 1), (0, 1, 0, 1)]),
    5: ([(-0.5, -0.65, 1), (0.5, -0.65, 0), (-0.5, 0.65, 0), (0.5, 0.65, 1), (0.0, 0.0, 2)],
        [(-1, 0, -1, -0.3), (0, 1, -1, -0.3), (-1, 0, 0.3, 1), (0, 1, 0.3, 1), (-1, 1, -0.3, 0.3)]),
}
BURNER_RADII = (0.03, 0.04, 0.05)  # small, medium, wok burner caps (glass zones: 1.8x)
#: minimum hob width for each burner count (m)
MIN_HOB_WIDTH = {2: 0.28, 3: 0.45, 4: 0.55, 5: 0.7}
GRATE_BAR = 0.012
GRATE_HEIGHT = 0.035  # grate top above the hob
KNOB_BAND = 0.07      # front strip of a gas hob that holds its knobs


def hob_layout(region: tuple[float, float, float, float], n: int, knobs: bool
               ) -> tuple[list[tuple[float, float, float]], list[tuple[float, float, float, float]]]:
    """Burners (x, y, cap radius) and grate cells (x0, x1, y0, y1) of an n-burner hob whose
    top spans `region` = (x0, x1, y0, y1); a front band is kept free for knobs when `knobs`."""
    x0, x1, y0, y1 = region
    m = 0.012
    ax0, ax1, ay0, ay1 = x0 + m, x1 - (KNOB_BAND if knobs else m), y0 + m, y1 - m
    cx, cy, hx, hy = (ax0 + ax1) / 2, (ay0 + ay1) / 2, (ax1 - ax0) / 2, (ay1 - ay0) / 2
    burners, cells = BURNER_LAYOUTS[n]
    cells = [(cx + a * hx, cx + b * hx, cy + c * hy, cy + d * hy) for a, b, c, d in cells]
    out = []
    for (u, v, k), (a, b, c, d) in zip(burners, cells, strict=True):
        r = min(BURNER_RADII[k], 0.3 * (b - a), 0.3 * (d - c))
        out.append((cx + u * hx, cy + v * hy, r))
    return out, cells


def _grate_bars(cell: tuple[float, float, float, float], burner: tuple[float, float, float]
                ) -> list[tuple[float, float, float, float]]:
    """The bars (x0, x1, y0, y1) of one grate cell: its frame and four arms from the frame
    towards the burner, stopping short of its cap."""
    x0, x1, y0, y1 = cell
    x, y, r = burner
    b, gap = GRATE_BAR, r * 0.8
    bars = [(x0, x1, y0, y0 + b), (x0, x1, y1 - b, y1), (x0, x0 + b, y0, y1), (x1 - b, x1, y0, y1),
            (x - b / 2, x + b / 2, y0, y - gap), (x - b / 2, x + b / 2, y + gap, y1),
            (x0, x - gap, y - b / 2, y + b / 2), (x + gap, x1, y - b / 2, y + b / 2)]
    return [q for q in bars if q[1] - q[0] > 0.004 and q[3] - q[2] > 0.004]


def _grates(cells, burners, continuous: bool) -> list[list[tuple[float, float, float, float]]]:
    """The bars of each separate grate: one grate per cell (shrunk apart by a few mm), or one
    continuous grate whose cells share their frame bars."""
    if continuous:
        return [[q for c, bn in zip(cells, burners, strict=True) for q in _grate_bars(c, bn)]]
    g = 0.004
    return [_grate_bars((a + g, b - g, c + g, d - g), bn)
            for (a, b, c, d), bn in zip(cells, burners, strict=True)]


def hob_parts(style: str, region: tuple[float, float, float, float], z_top: float, n: int,
              continuous: bool, detail: bool, knobs: bool) -> list[Part]:
    """What sits on a hob's top (upper face at `z_top`, spanning `region`): printed zones and
    touch keys (glass), or burner caps, rubber-footed cast-iron grates and, when `knobs`, a row
    of knobs along the front (gas). The slab itself is not included."""
    burners, cells = hob_layout(region, n, knobs and style == "gas")
    x0, x1, y0, y1 = region
    out: list[Part] = []
    if style == "glass":
        if not detail:
            return out
        for x, y, r in burners:
            ro = r * 1.8
            ring = lathe([(ro - 0.003, 0.0), (ro, 0.0), (ro, 0.0004), (ro - 0.003, 0.0004)], 48)
            out.append(Part(ring.translate((x, y, z_top - 0.0001)), "plastic"))
        xf = x1 - 0.03
        k = min(n + 2, 7)
        for i in range(k):
            y = (y0 + y1) / 2 + (i - (k - 1) / 2) * 0.035
            out.append(Part(box_between((xf - 0.008, y - 0.008, z_top - 0.0001),
                                        (xf + 0.008, y + 0.008, z_top + 0.0004)),
                            "plastic"))
        return out
    zg = z_top + GRATE_HEIGHT
    grates = _grates(cells, burners, continuous)
    for bars in grates:
        bx0, bx1 = min(q[0] for q in bars), max(q[1] for q in bars)
        by0, by1 = min(q[2] for q in bars), max(q[3] for q in bars)
        if not detail:
            out.append(Part(box_between((bx0, by0, z_top - 0.001), (bx1, by1, zg)), "rubber"))
            continue
        solids = [box_between((a, c, zg - GRATE_BAR), (b, d, zg)) for a, b, c, d in bars]
        solids += [box_between((xa, ya, z_top - 0.001), (xa + 0.01, ya + 0.01, zg - GRATE_BAR + 0.001))
                   for xa in (bx0 + 0.001, bx1 - 0.011) for ya in (by0 + 0.001, by1 - 0.011)]
        out.append(Part(solid_union(solids), "rubber"))
    if detail:
        for x, y, r in burners:
            cap = lathe([(0.0, 0.0), (r * 1.15, 0.0), (r * 1.15, 0.008), (r, 0.014), (r, 0.018),
                         (r * 0.95, 0.024),
                         (0.0, 0.024)], 24)
            out.append(Part(cap.translate((x, y, z_top - 0.001)), "metal"))
    if knobs:
        xk = x1 - KNOB_BAND / 2
        pitch = min(0.06, (y1 - y0 - 0.06) / n)
        ys = [(y0 + y1) / 2 + (i - (n - 1) / 2) * pitch for i in range(n)]
        if detail:
            out += [Part(cylinder(0.017, 0.022, (xk, y, z_top - 0.001), 24), "plastic") for y in ys]
        else:  # the row of knobs as one block
            out.append(Part(box_between((xk - 0.017, ys[0] - 0.017, z_top - 0.001),
                                        (xk + 0.017, ys[-1] + 0.017, z_top + 0.021)),
                            "plastic"))
    return out


def hob_surfaces(style: str, region: tuple[float, float, float, float], z_top: float, n: int,
                 continuous: bool, knobs: bool, margin: float = 0.02) -> list[Surface]:
    """The support surfaces of a hob: its glass (`cooktop`), or each grate's top (`grate_i`,
    the union of its bars' upper faces)."""
    x0, x1, y0, y1 = region
    if style == "glass":
        return [support_rect("cooktop", ((x0 + x1) / 2, (y0 + y1) / 2, z_top), (x1 - x0) / 2 - margin,
                             (y1 - y0) / 2 - margin)]
    burners, cells = hob_layout(region, n, knobs)
    out = []
    for i, bars in enumerate(_grates(cells, burners, continuous)):
        out.append(support_polygon(f"grate_{i}", (0.0, 0.0, z_top + GRATE_HEIGHT),
                                   rects_polygon(bars, (), 0.0005)))
    return out


def back_surface(x_back: float, region_yz: sg.Polygon) -> Surface:
    """A `back` surface (normal -X) on the plane x = x_back covering `region_yz` (a polygon in
    (y, z)): for wall-mounted objects whose back is not the whole bounding rectangle."""
    c = region_yz.centroid
    oy, oz = float(c.x), float(c.y)
    # u = +Y, v = n x u = -Z: 2D coordinates are (y - oy, oz - z)
    poly = sg.Polygon([(y - oy, oz - z) for y, z in region_yz.exterior.coords])
    return Surface("back", Subpart.Back, np.array([x_back, oy, oz]), np.array([-1.0, 0.0, 0.0]),
                   np.array([0.0, 1.0, 0.0]), poly)


# ------------------------------------------------------------------------------- cooktop
@register
class Cooktop(PartsFactory):
    """A hob that sits on a countertop: a black ceramic-glass slab with printed cooking zones
    and touch controls (optionally in a steel frame), or a steel gas hob with 2-5 burners under
    individual or continuous rubber-footed cast-iron grates and a row of knobs. The glass (or
    each grate's top) is a support surface."""

    name = "cooktop"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Cooktop})
    size_class = "small"
    slots = ["glass", "metal", "plastic", "rubber"]
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=("glass", "gas"), doc="ceramic glass or gas"),
        "width": Param(0.28, 0.9, doc="Y extent (m); raised to fit the burners"),
        "depth": Param(0.45, 0.53, doc="X extent (m)"),
        "n_burners": Param(2, 5, kind="int", doc="burners or cooking zones"),
        "thickness": Param(0.006, 0.04, doc="slab thickness (glass: capped at 1 cm) (m)"),
        "frame": Param(kind="bool", doc="a steel frame around a glass slab"),
        "grates": Param(kind="choice", choices=("individual", "continuous"), doc="gas grate layout"),
        "corner_radius": Param(0.0, 0.02, doc="rounding of the slab's corners (m)"),
    }

    def _dims(self, p) -> tuple[float, float, float, int]:
        n = int(p["n_burners"])
        W = max(p["width"], MIN_HOB_WIDTH[n])
        t = min(p["thickness"], 0.01) if p["style"] == "glass" else max(p["thickness"], 0.012)
        return p["depth"], W, t, n

    def parts(self, p, detail):
        """The cooktop's solids: detailed, or the blocks of its placeholder."""
        D, W, t, n = self._dims(p)
        glass = p["style"] == "glass"
        r = min(p["corner_radius"], 0.3 * t) if detail else 0.0
        slab = bevel_box((D, W, t), (0, 0, t / 2), r, 2) if r > 1e-4 else box((D, W, t), (0, 0, t / 2))
        out = [Part(slab, "glass" if glass else "metal")]
        if glass and p["frame"]:
            fw = 0.008
            ring = box((D, W, t + 0.001),
                       (0, 0, (t + 0.001) / 2)) - box((D - 2 * fw, W - 2 * fw, 1.0), (0, 0, 0))
            out.append(Part(ring if detail else box((D, W, t + 0.001), (0, 0, (t + 0.001) / 2)), "metal"))
        out += hob_parts(p["style"], (-D / 2, D / 2, -W / 2, W / 2), t, n, p["grates"] == "continuous",
                         detail, not glass)
        return out

    def extra_surfaces(self, p):
        """The cooktop's surfaces besides its bounding box's: the hob's (grates or glass) and bottom."""
        D, W, t, n = self._dims(p)
        m = 0.02 if not (p["style"] == "glass" and p["frame"]) else 0.025
        return [*hob_surfaces(p["style"], (-D / 2, D / 2, -W / 2, W / 2), t, n, p["grates"] == "continuous",
                              p["style"] == "gas", m),
                bottom_rect((0, 0, 0), D / 2, W / 2)]


# ---------------------------------------------------------------------------------- oven
def _oven_door(x_face: float, y0: float, y1: float, z0: float, z1: float, t: float, window: float,
               handle: str, link: str) -> tuple[list[Part], Any]:
    """A drop-down oven door: a leaf with a window `window` wide (fraction), a bar handle
    across its top (or a recessed grip), hinged along its lower outer edge."""
    x0, x1 = x_face + MOVING_GAP, x_face + MOVING_GAP + t
    w, h = y1 - y0, z1 - z0
    side = (1 - window) * w / 2
    parts = window_leaf(x0, x1, y0, y1, z0, z1, (side, side, 0.08 * h + 0.03, 0.22 * h + 0.02), link,
                        "appliance")
    zh = z1 - 0.045
    if handle == "bar":
        parts.append(Part(pull_bar(x1, (y0 + 0.06, zh), (y1 - 0.06, zh), 0.05, 0.011, 16), "metal", link))
    else:  # a steel grip strip along the top edge
        parts.append(Part(box_between((x1 - 0.001, y0 + 0.04, z1 - 0.035),
                                      (x1 + 0.015, y1 - 0.04, z1 - 0.01)),
                          "metal", link))
    return parts, hinge_motion("bottom", x1, y0, y1, z0, z1, link)


RACK_R, RACK_PITCH = 0.0025, 0.03  # oven rack bar half-thickness and pitch (m)


def _rack_extent(lo, hi) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) of the racks of an oven cavity lo..hi (ends sunk into the liner)."""
    return lo[0] + 0.02, hi[0] - 0.03, lo[1] + 0.002, hi[1] - 0.002


def _cavity_surfaces(lo, hi, racks: list[float], first: int = 0) -> list[Surface]:
    """The `interior_i` surfaces of an oven cavity lo..hi: its enamel floor and each rack
    (the tops of its bars, between the liner's side walls)."""
    out = [interior_rect(f"interior_{first}", lo[0] + 0.02, hi[0] - 0.04, lo[1] + 0.015, hi[1] - 0.015,
                         lo[2] + 0.003, 0.005)]
    x0, x1, y0, y1 = _rack_extent(lo, hi)
    for i, zr in enumerate(racks):
        out.append(rack_surface(f"interior_{first + i + 1}", x0, x1, y0, y1, zr, RACK_R, RACK_PITCH,
                                (x0, x1, lo[1] + 0.003, hi[1] - 0.003)))
    return out


def _oven_cavity(lo, hi, racks: list[float], detail: bool) -> tuple[list[m3d.Manifold], list[Part]]:
    """(cutters, parts) of an oven cavity lo..hi open at +X: an enamel liner, side rails and
    wire racks whose tops are at the heights `racks`."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    cut = [box_between((x0, y0, z0), (x1 + 0.01, y1, z1))]
    if not detail:
        return cut, []
    parts = [Part(open_shell((x0 - 0.001, y0 - 0.001, z0 - 0.001), (x1 - 0.004, y1 + 0.001, z1 + 0.001),
                             0.004),
                  "ceramic")]
    for zr in racks:
        parts.append(Part(wire_rack(*_rack_extent(lo, hi), zr, RACK_R, RACK_PITCH), "metal"))
        for s in (-1, 1):  # runners the rack rests on
            ya, yb = (y0 - 0.001, y0 + 0.012) if s < 0 else (y1 - 0.012, y1 + 0.001)
            parts.append(Part(box_between((x0 + 0.01, ya, zr - 0.011), (x1 - 0.02, yb, zr - 0.004)),
                              "metal"))
    return cut, parts


def _controls(x_face: float, y0: float, y1: float, zc: float, n_knobs: int, style: str,
              proud: float = 0.03) -> list[Part]:
    """A control strip on a +X face: knobs spread over y0..y1 around a central display, or a
    touch strip (display and a row of touch keys)."""
    out = []
    w = y1 - y0
    out.append(Part(box_between((x_face - 0.001, -0.06, zc - 0.018), (x_face + 0.002, 0.06, zc + 0.018)),
                    "screen"))
    if style == "knobs":  # split either side of the display
        nl = n_knobs // 2
        ys = list(np.linspace(y0 + 0.05, -0.1, nl + 2)[1:-1]) if nl else []
        ys += list(np.linspace(0.1, y1 - 0.05, n_knobs - nl + 2)[1:-1])
        for y in ys:
            out.append(Part(knob((x_face, y, zc), 0.02, proud), "metal"))
    else:
        for i in range(6):
            y = 0.09 + i * min(0.03, (w / 2 - 0.12) / 6)
            for s in (-1, 1):
                out.append(Part(box_between((x_face - 0.001, s * y - 0.008, zc - 0.008),
                                            (x_face + 0.002, s * y + 0.008, zc + 0.008)),
                                "plastic"))
    return out


@register
class Oven(PartsFactory):
    """A built-in wall oven (single or double): a front fascia wider than the box that slides
    into a tall cabinet, a control strip (knobs or touch keys around a display), and per
    cavity a drop-down door with a window and bar or strip handle, an enamelled cavity with
    rack runners and 1-3 wire racks (`interior_i` surfaces)."""

    name = "oven"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Oven})
    size_class = "large"
    slots = ["appliance", "metal", "glass", "ceramic", "plastic", "screen"]
    params = {
        "width": Param(0.56, 0.76, doc="Y extent of the fascia (m)"),
        "depth": Param(0.53, 0.58, doc="X extent of the box behind the fascia (m)"),
        "cavities": Param(kind="choice", choices=("single", "double"), doc="one or two ovens"),
        "door_height": Param(0.42, 0.5, doc="height of each door (m)"),
        "control_height": Param(0.08, 0.14, doc="height of the control strip (m)"),
        "controls": Param(kind="choice", choices=("knobs", "touch"), doc="knobs or touch keys"),
        "n_knobs": Param(2, 4, kind="int", doc="knobs on a knob strip"),
        "window_frac": Param(0.5, 0.8, doc="window width / door width"),
        "handle": Param(kind="choice", choices=("bar", "strip"), doc="bar handle or grip strip"),
        "door_thickness": Param(0.045, 0.065, doc="door thickness (m)"),
        "n_racks": Param(1, 3, kind="int", doc="wire racks per cavity"),
    }

    FASCIA = 0.02

    def _doors(self, p) -> list[tuple[float, float]]:
        dh = p["door_height"]
        n = 2 if p["cavities"] == "double" else 1
        return [(0.002 + i * (dh + 0.004), 0.002 + i * (dh + 0.004) + dh) for i in range(n)]

    def _height(self, p) -> float:
        return self._doors(p)[-1][1] + 0.002 + p["control_height"]

    def _cavity_box(self, p, z0: float, z1: float):
        D, W = p["depth"], p["width"]
        return (-D / 2 + 0.03, -W / 2 + 0.05, z0 + 0.04), (D / 2 + self.FASCIA, W / 2 - 0.05, z1 - 0.03)

    def _racks(self, p, lo, hi) -> list[float]:
        k = int(p["n_racks"])
        return [lo[2] + (hi[2] - lo[2]) * (i + 1) / (k + 1) for i in range(k)]

    def _door_parts(self, p):
        W = p["width"]
        fx = p["depth"] / 2 + self.FASCIA
        return [_oven_door(fx, -W / 2 + 0.002, W / 2 - 0.002, z0, z1, p["door_thickness"], p["window_frac"],
                           p["handle"], f"door_{i}") for i, (z0, z1) in enumerate(self._doors(p))]

    def parts(self, p, detail):
        """The oven's solids: detailed, or the blocks of its placeholder."""
        D, W = p["depth"], p["width"]
        H = self._height(p)
        fx = D / 2 + self.FASCIA
        proud = MOVING_GAP + p["door_thickness"] + (0.05 if p["handle"] == "bar" else 0.015)
        box_part = box_between((-D / 2, -W / 2 + 0.02, 0.01), (D / 2 + 0.001, W / 2 - 0.02, H - 0.01))
        fascia = box_between((D / 2, -W / 2, 0.0), (fx, W / 2, H))
        if not detail:
            return [Part(box_part, "appliance"), Part(fascia, "appliance"),
                    Part(box_between((fx - 0.01, -W / 2, 0.0),
                                     (fx + proud, W / 2, H - p["control_height"])), "appliance"),
                    Part(box_between((fx - 0.01, -W / 2, H - p["control_height"]), (fx + 0.03, W / 2, H)),
                         "metal")]
        cutters, inner = [], []
        for z0, z1 in self._doors(p):
            lo, hi = self._cavity_box(p, z0, z1)
            c, ps = _oven_cavity(lo, hi, self._racks(p, lo, hi), True)
            cutters += c
            inner += ps
        body = m3d.Manifold.batch_boolean([solid_union([box_part, fascia])] + cutters, m3d.OpType.Subtract)
        out = [Part(body, "appliance"), *inner]
        out += _controls(fx, -W / 2, W / 2, H - p["control_height"] / 2, int(p["n_knobs"]), p["controls"])
        for parts, _ in self._door_parts(p):
            out += parts
        return out

    def joints(self, p):
        """The oven's joints: each drop-down door's."""
        return [joint_for(m) for _, m in self._door_parts(p)]

    def extra_surfaces(self, p):
        """The oven's surfaces besides its bounding box's: each cavity's floor and racks (interior_<i>)."""
        out: list[Surface] = []
        for z0, z1 in self._doors(p):
            lo, hi = self._cavity_box(p, z0, z1)
            out += _cavity_surfaces(lo, hi, self._racks(p, lo, hi), len(out))
        return out


# --------------------------------------------------------------------------------- range
@register
class Range(PartsFactory):
    """A freestanding range (cooker): an oven body on a recessed plinth with a gas or glass
    hob on top (4 burners, 5 from 75 cm wide), a backguard along the back (with the knobs and a
    clock display, or plain with the controls on a front strip), a drop-down windowed oven door
    over an optional storage drawer, and wire racks inside (`interior_i`). The hob's glass or
    grates are support surfaces."""

    name = "range"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Range})
    size_class = "large"
    slots = ["appliance", "metal", "glass", "ceramic", "plastic", "rubber", "screen"]
    solid_bottom = True
    params = {
        "width": Param(0.55, 0.92, doc="Y extent (m); 5 burners from 0.75 m"),
        "depth": Param(0.6, 0.7, doc="X extent of the body (m)"),
        "height": Param(0.88, 0.93, doc="height of the hob's upper face (m)"),
        "hob": Param(kind="choice", choices=("gas", "glass"), doc="gas burners or ceramic glass"),
        "grates": Param(kind="choice", choices=("individual", "continuous"), doc="gas grate layout"),
        "controls": Param(kind="choice", choices=("backguard", "front"),
                          doc="knobs on the backguard or on a strip above the door"),
        "backguard_height": Param(0.06, 0.22, doc="height of the backguard above the hob (m)"),
        "drawer": Param(kind="bool", doc="a storage drawer under the oven door"),
        "window_frac": Param(0.4, 0.8, doc="oven window width / door width"),
        "n_racks": Param(1, 3, kind="int", doc="oven racks"),
        "foot_height": Param(0.02, 0.06, doc="height of the recessed plinth (m)"),
        "handle": Param(kind="choice", choices=("bar", "strip"), doc="oven door bar or grip strip"),
    }

    TOP_T = 0.02
    BG_D = 0.05
    DOOR_T = 0.05

    def _geom(self, p) -> dict[str, Any]:
        D, W, H, zf = p["depth"], p["width"], p["height"], p["foot_height"]
        z_hob0 = H - self.TOP_T
        z_top = z_hob0 - (0.1 if p["controls"] == "front" else 0.0)  # top of the door zone
        z0 = zf + (0.15 if p["drawer"] else 0.0)
        n = 5 if W >= 0.75 else 4
        return dict(z_door=(z0 + 0.003, z_top - 0.003), z_drawer=(zf + 0.003, z0 - 0.003), n=n,
                    region=(-D / 2 + self.BG_D, D / 2, -W / 2, W / 2))

    def _cavity(self, p):
        D, W = p["depth"], p["width"]
        z0, z1 = self._geom(p)["z_door"]
        return (-D / 2 + 0.05, -W / 2 + 0.05, z0 + 0.05), (D / 2, W / 2 - 0.05, z1 - 0.04)

    def _racks(self, p) -> list[float]:
        lo, hi = self._cavity(p)
        k = int(p["n_racks"])
        return [lo[2] + (hi[2] - lo[2]) * (i + 1) / (k + 1) for i in range(k)]

    def _moving(self, p) -> list[tuple[list[Part], Any, float]]:
        D, W = p["depth"], p["width"]
        g = self._geom(p)
        z0, z1 = g["z_door"]
        parts, m = _oven_door(D / 2, -W / 2 + 0.002, W / 2 - 0.002, z0, z1, self.DOOR_T, p["window_frac"],
                              p["handle"], "door")
        out = [(parts, m, 0.0)]
        if p["drawer"]:
            a, b = g["z_drawer"]
            x0, x1 = D / 2 + MOVING_GAP, D / 2 + MOVING_GAP + 0.025
            dparts = [Part(box_between((x0, -W / 2 + 0.002, a), (x1, W / 2 - 0.002, b)), "appliance",
                           "drawer"),
                      Part(pull_bar(x1, (-0.15, b - 0.04), (0.15, b - 0.04), 0.035, 0.008, 12), "metal",
                           "drawer"),
                      Part(open_shell((-D / 2 + 0.12, -W / 2 + 0.05, a + 0.01),
                                      (x0 + 0.001, W / 2 - 0.05, b - 0.02), 0.004,
                                      open_top=True), "metal", "drawer")]
            out.append((dparts, slide_motion("drawer", (x1, 0.0, b)), 0.7 * (D - 0.12)))
        return out

    def parts(self, p, detail):
        """The range's solids: detailed, or the blocks of its placeholder."""
        D, W, H, zf = p["depth"], p["width"], p["height"], p["foot_height"]
        g = self._geom(p)
        bgh = p["backguard_height"]
        hob_style = p["hob"]
        proud = MOVING_GAP + self.DOOR_T + (0.05 if p["handle"] == "bar" else 0.015)
        plinth = box_between((-D / 2 + 0.02, -W / 2 + 0.02, 0.0),
                             (D / 2 - 0.06, W / 2 - 0.02, zf + OVERLAP))
        body = box_between((-D / 2, -W / 2, zf), (D / 2, W / 2, H - self.TOP_T + 0.001))
        top = box_between((-D / 2, -W / 2, H - self.TOP_T), (D / 2, W / 2, H))
        guard = box_between((-D / 2, -W / 2, H - 0.001), (-D / 2 + self.BG_D, W / 2, H + bgh))
        out = [Part(plinth, "plastic"), Part(top, "glass" if hob_style == "glass" else "appliance"),
               Part(guard, "appliance")]
        out += hob_parts(hob_style, g["region"], H, g["n"], p["grates"] == "continuous", detail, False)
        if not detail:
            z_front1 = g["z_door"][1] if p["controls"] == "backguard" else H - self.TOP_T
            return out + [Part(body, "appliance"),
                          Part(box_between((D / 2 - 0.01, -W / 2, zf), (D / 2 + proud, W / 2, z_front1)),
                               "appliance"),
                          *([Part(box_between((-D / 2 + self.BG_D - 0.01, -W / 2 + 0.04, H),
                                              (-D / 2 + self.BG_D + 0.03, W / 2 - 0.04, H + bgh)),
                                  "metal")] if p["controls"] == "backguard" else [])]
        lo, hi = self._cavity(p)
        cutters, inner = _oven_cavity(lo, hi, self._racks(p), True)
        if p["drawer"]:
            a, b = g["z_drawer"]
            cutters.append(box_between((-D / 2 + 0.1, -W / 2 + 0.04, a + 0.005),
                                       (D / 2 + 0.01, W / 2 - 0.04, b)))
        out.append(Part(m3d.Manifold.batch_boolean([body] + cutters, m3d.OpType.Subtract), "appliance"))
        out += inner
        n_knobs = g["n"] + 1
        if p["controls"] == "backguard":
            xg = -D / 2 + self.BG_D
            zc = H + bgh / 2
            kr = min(0.02, 0.3 * bgh)
            for i in range(n_knobs):
                y = (i - (n_knobs - 1) / 2) * min(0.08, (W - 0.2) / n_knobs)
                y += 0.06 * np.sign(y)
                out.append(Part(knob((xg, y, zc), kr, 0.03), "metal"))
            out.append(Part(box_between((xg - 0.001, -0.04, zc - 0.012), (xg + 0.002, 0.04, zc + 0.012)),
                            "screen"))
        else:
            out += _controls(D / 2, -W / 2, W / 2, H - self.TOP_T - 0.05, n_knobs, "knobs")
        for parts, _, _ in self._moving(p):
            out += parts
        return out

    def joints(self, p):
        """The range's joints: the oven door's and, with a drawer, the drawer's."""
        return [joint_for(m, slide=s) for _, m, s in self._moving(p)]

    def extra_surfaces(self, p):
        """The range's surfaces besides its bounding box's: the hob's, bottom, the oven's floor and racks."""
        D, W, H = p["depth"], p["width"], p["height"]
        g = self._geom(p)
        lo, hi = self._cavity(p)
        out = [*hob_surfaces(p["hob"], g["region"], H, g["n"], p["grates"] == "continuous", False),
               bottom_rect((-0.02, 0, 0), D / 2 - 0.04, W / 2 - 0.02)]  # the plinth
        return out + _cavity_surfaces(lo, hi, self._racks(p))


# ----------------------------------------------------------------------------- range hood
@register
class RangeHood(PartsFactory):
    """A wall-mounted cooker hood: a flat box canopy or a sloped (pyramid) canopy with a
    chimney duct cover up the wall, or a slim under-cabinet hood. Grease filters and lights
    (emissive) are set into its underside, buttons or a slider on its front edge. Its back
    (the canopy's and the chimney's, flush) lies on the wall."""

    name = "range_hood"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.RangeHood, S.WallMounted})
    size_class = "medium"
    slots = ["appliance", "metal", "plastic", "emissive"]
    params = {
        "style": Param(kind="choice", choices=("chimney_box", "chimney_pyramid", "under_cabinet"),
                       doc="canopy shape"),
        "width": Param(0.6, 0.9, doc="Y extent of the canopy (m)"),
        "depth": Param(0.45, 0.55, doc="X extent of the canopy (m)"),
        "canopy_height": Param(0.06, 0.14, doc="height of the canopy's box (its rim) (m)"),
        "taper_height": Param(0.15, 0.3, doc="height of a pyramid canopy's sloped part (m)"),
        "chimney_width": Param(0.22, 0.32, doc="Y extent of the chimney (m)"),
        "chimney_depth": Param(0.2, 0.3, doc="X extent of the chimney (m)"),
        "chimney_height": Param(0.4, 0.9, doc="height of the chimney above the canopy (m)"),
        "n_lights": Param(1, 3, kind="int", doc="lights in the underside"),
        "controls": Param(kind="choice", choices=("buttons", "slider"), doc="control style"),
    }

    def _profile(self, p) -> tuple[float, float, float]:
        """(rim height, top of the canopy, overall height)."""
        ch = p["canopy_height"]
        if p["style"] == "under_cabinet":
            ch = max(ch, 0.12)
            return ch, ch, ch
        top = ch + (p["taper_height"] if p["style"] == "chimney_pyramid" else 0.0)
        return ch, top, top + p["chimney_height"]

    def parts(self, p, detail):
        """The range hood's solids: detailed, or the blocks of its placeholder."""
        D, W = p["depth"], p["width"]
        cw, cd = p["chimney_width"], min(p["chimney_depth"], D - 0.1)
        ch, top, H = self._profile(p)
        rim = box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, ch))
        out = []
        if p["style"] == "chimney_pyramid":
            pts = [(x, y, z) for x, hw, z in ((-D / 2, W / 2, ch - 0.001), (D / 2, W / 2, ch - 0.001))
                   for y in (-hw, hw)]
            pts += [(x, y, top) for x in (-D / 2, -D / 2 + cd) for y in (-cw / 2, cw / 2)]
            out.append(Part(m3d.Manifold.hull_points(np.array(pts, float)), "appliance"))
        if p["style"] != "under_cabinet":
            out.append(Part(box_between((-D / 2, -cw / 2, top - 0.001), (-D / 2 + cd, cw / 2, H)),
                            "appliance"))
        if not detail:
            return out + [Part(rim, "appliance"),
                          Part(box_between((D / 2 - 0.01, -W / 2 + 0.05, 0.0),
                                           (D / 2 + 0.004, W / 2 - 0.05, ch)), "plastic")]
        # underside: filters in recesses, lights
        fw = (W - 0.12) / 2
        recesses, inserts = [], []
        for s in (-1, 1):
            y0, y1 = (-W / 2 + 0.04, -W / 2 + 0.04 + fw) if s < 0 else (W / 2 - 0.04 - fw, W / 2 - 0.04)
            lo, hi = (-D / 2 + 0.04, y0, -0.01), (D / 2 - 0.1, y1, 0.004)
            recesses.append(box_between(lo, hi))
            inserts.append(Part(slotted_plate(hi[0] - lo[0] + 0.002, y1 - y0 + 0.002, 0.003, 0.012, 0.004)
                                .translate((lo[0] - 0.001, y0 - 0.001, 0.0015)), "metal"))
        nl = int(p["n_lights"])
        for i in range(nl):  # lights: discs set 0.5 mm into their own recesses
            y = (i - (nl - 1) / 2) * (W - 0.2) / max(nl - 1, 1)
            recesses.append(cylinder(0.026, 0.013, (D / 2 - 0.05, y, -0.01), 24))
            inserts.append(Part(cylinder(0.025, 0.003, (D / 2 - 0.05, y, 0.0005), 24), "emissive"))
        out.append(Part(rim - m3d.Manifold.batch_boolean(recesses, m3d.OpType.Add), "appliance"))
        out += inserts
        # controls on the front edge
        if p["controls"] == "buttons":
            for i in range(4):
                y = 0.1 + i * 0.035
                out.append(Part(box_between((D / 2 - 0.001, y - 0.012, ch / 2 - 0.008),
                                            (D / 2 + 0.004, y + 0.012, ch / 2 + 0.008)),
                                "plastic"))
        else:
            out.append(Part(box_between((D / 2 - 0.001, 0.08, ch / 2 - 0.006),
                                        (D / 2 + 0.002, 0.24, ch / 2 + 0.006)),
                            "plastic"))
            out.append(Part(box_between((D / 2 + 0.001, 0.14, ch / 2 - 0.01),
                                        (D / 2 + 0.004, 0.155, ch / 2 + 0.01)),
                            "metal"))
        return out

    def extra_surfaces(self, p):
        """The range hood's surfaces besides its bounding box's: back (its outline on the wall)."""
        D, W = p["depth"], p["width"]
        cw = p["chimney_width"]
        ch, top, H = self._profile(p)
        region = sg.box(-W / 2, 0.0, W / 2, ch)
        if p["style"] != "under_cabinet":
            region = region.union(sg.box(-cw / 2, top - 0.001, cw / 2, H))
        if p["style"] == "chimney_pyramid":
            region = region.union(sg.Polygon([(-W / 2, ch - 0.001), (W / 2, ch - 0.001), (cw / 2, top),
                                              (-cw / 2, top)]))
        region = region.buffer(-0.002, join_style="mitre")
        return [back_surface(-D / 2, region)]
