"""More storage: cabinets, wardrobes, dressers, nightstands, cube shelves, wall shelves, corner
shelves and shoe racks (fronts / open sides facing +X).

The closed pieces share one case builder (`_case_layout`): a carcass of boards split into rows
(drawers, doors or open cells) whose fronts either cover the board edges ("overlay") or sit in
front of the openings only ("framed"). Every drawer and door leaf is its own link with a joint;
the placeholder is the carcass boards plus one block per closed row (fronts and handles
included), so open shelves stay open for the solver.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import frame, legs
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, drawer, hinged_door
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between, rod
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

REVEAL = 0.002    # gap left around every front (so neighbouring fronts never touch)
FRONT_T = 0.018   # door / drawer front thickness (m)
#: how far handles stand proud of a front (parts.bar_handle / parts.knob defaults)
HANDLE_STANDOFF = {"bar": 0.03, "knob": 0.025}
DOOR_OPEN = math.radians(100)


# ----------------------------------------------------------------------------- case builder
@dataclass(frozen=True)
class _Row:
    """One horizontal band of a case: `kind` "drawer", "door" or "open", a share `weight` of the
    interior height, `n` drawers / doors / open cells side by side, and whether physical
    dividers separate them (always for drawers and open cells)."""

    kind: str
    weight: float
    n: int = 1
    dividers: bool = True


@dataclass(frozen=True)
class _Cell:
    """An opening (y0..y1, z0..z1) of a row, the extent of its front (fy0..fz1) and its kind:
    "drawer", "left" / "right" (a door hinged on that side) or "open"."""

    y0: float
    y1: float
    z0: float
    z1: float
    fy0: float
    fy1: float
    fz0: float
    fz1: float
    kind: str
    row: int


@dataclass
class _Case:
    """A laid-out case: its boards (design frame), its cells and the rows' z openings."""

    W: float
    D: float
    t: float
    back: float
    z_bot: float
    z_top: float
    boards: list
    cells: list
    rows: list  # (row, z0, z1) per row, bottom first

    @property
    def front_x(self) -> float:
        return self.D / 2

    def inner(self) -> tuple[float, float]:
        return -self.W / 2 + self.t, self.W / 2 - self.t


def _door_hinges(n: int) -> list[str]:
    """Hinge sides for n doors side by side: a single door on the left, pairs opening outwards."""
    if n == 1:
        return ["left"]
    out = []
    for i in range(n):
        out.append("left" if i % 2 == 0 else "right")
    if n % 2 == 1:  # an odd door out: the last one hinges on the outer (right) side
        out[-1] = "right"
    return out


def _case_layout(W: float, D: float, t: float, back: float, z_bot: float, z_top: float,
                 rows: Sequence[_Row], overlay: bool, door_dividers: Sequence[float] = ()) -> _Case:
    """Lay out a case spanning x in [-D/2, D/2], y in [-W/2, W/2], z in [z_bot, z_top] (the top
    board, if any, sits above z_top): two sides, a bottom board, a back panel, a separator board
    between rows and dividers between the cells of a row. `rows` are listed bottom first.
    `door_dividers` are y positions of full-height dividers inside door rows (the doors then
    split the width evenly regardless)."""
    o = OVERLAP
    w2, d2 = W / 2, D / 2
    yi0, yi1 = -w2 + t, w2 - t
    boards = [
        box_between((-d2, -w2, z_bot), (d2, -w2 + t, z_top + o)),
        box_between((-d2, w2 - t, z_bot), (d2, w2, z_top + o)),
        box_between((-d2, yi0 - o, z_bot), (d2, yi1 + o, z_bot + t)),
        box_between((-d2, yi0 - o, z_bot + t - o), (-d2 + back, yi1 + o, z_top + o)),
    ]
    free = z_top - (z_bot + t) - (len(rows) - 1) * t
    total = sum(r.weight for r in rows)
    z = z_bot + t
    cells, zrows = [], []
    xb = -d2 + back - o
    for ri, row in enumerate(rows):
        h = free * row.weight / total
        z0, z1 = z, z + h
        zrows.append((row, z0, z1))
        if ri < len(rows) - 1:
            boards.append(box_between((xb, yi0 - o, z1), (d2, yi1 + o, z1 + t)))
        fz0 = (z_bot if ri == 0 else z0 - t / 2) if overlay else z0
        fz1 = (z_top if ri == len(rows) - 1 else z1 + t / 2) if overlay else z1
        divided = row.kind != "door" and row.n > 1
        if divided:
            cw = (yi1 - yi0 - (row.n - 1) * t) / row.n
            for j in range(row.n):
                y0 = yi0 + j * (cw + t)
                y1 = y0 + cw
                if j:
                    boards.append(box_between((xb, y0 - t, z0 - o), (d2, y0, z1 + o)))
                fy0 = (-w2 if j == 0 else y0 - t / 2) if overlay else y0
                fy1 = (w2 if j == row.n - 1 else y1 + t / 2) if overlay else y1
                kind = "drawer" if row.kind == "drawer" else "open"
                cells.append(_Cell(y0, y1, z0, z1, fy0, fy1, fz0, fz1, kind, ri))
        elif row.kind == "door":
            for yd in door_dividers:
                boards.append(box_between((xb, yd - t / 2, z0 - o), (d2, yd + t / 2, z1 + o)))
            fy0, fy1 = (-w2, w2) if overlay else (yi0, yi1)
            step = (fy1 - fy0) / row.n
            for j, hinge in enumerate(_door_hinges(row.n)):
                a, b = fy0 + j * step, fy0 + (j + 1) * step
                cells.append(_Cell(max(a, yi0), min(b, yi1), z0, z1, a, b, fz0, fz1, hinge, ri))
        else:
            fy0, fy1 = (-w2, w2) if overlay else (yi0, yi1)
            cells.append(_Cell(yi0, yi1, z0, z1, fy0, fy1, fz0, fz1,
                               "drawer" if row.kind == "drawer" else "open", ri))
        z = z1 + t
    return _Case(W, D, t, back, z_bot, z_top, boards, cells, zrows)


def _front_decor(x1: float, y0: float, y1: float, z0: float, z1: float, style: str,
                 link: str) -> list[Part]:
    """Decoration on a front's outer face at x1: a raised shaker frame or a mirror panel."""
    w, h = y1 - y0, z1 - z0
    if style == "shaker" and min(w, h) > 0.1:
        border = min(0.07, 0.22 * min(w, h))
        return [Part(frame(w, h, border, 0.007, (x1 + 0.0025, (y0 + y1) / 2, (z0 + z1) / 2)),
                     "front", link)]
    if style == "mirror" and min(w, h) > 0.3:
        m = 0.09
        return [Part(box_between((x1 - 0.001, y0 + m, z0 + m), (x1 + 0.004, y1 - m, z1 - m)),
                     "mirror", link)]
    return []


def _door(front_x: float, y0: float, y1: float, z0: float, z1: float, hinge: str, link: str,
          handle: str, style: str) -> tuple[list[Part], DoorJoint]:
    """A door leaf (flat, shaker, glass or mirror) hinged on its outer `hinge` edge."""
    parts, motion = hinged_door(front_x, y0, y1, z0, z1, FRONT_T, hinge, link, handle=handle)
    x0 = front_x + MOVING_GAP
    x1 = x0 + FRONT_T
    if style == "glass" and min(y1 - y0, z1 - z0) > 0.2:
        border = min(0.07, 0.3 * min(y1 - y0, z1 - z0))
        w, h = y1 - y0, z1 - z0
        yc, zc = (y0 + y1) / 2, (z0 + z1) / 2
        pane = box((0.006, w - 2 * border + 2 * 0.004, h - 2 * border + 2 * 0.004),
                   ((x0 + x1) / 2, yc, zc))
        parts[0] = Part(frame(w, h, border, FRONT_T, ((x0 + x1) / 2, yc, zc)), "front", link)
        parts.append(Part(pane, "glass", link))
    else:
        parts += _front_decor(x1, y0, y1, z0, z1, style, link)
    return parts, motion


def _case_fronts(case: _Case, handle: str, style: str, drawer_depth: float | None = None,
                 drawers_only: bool = False) -> list[tuple[list[Part], DoorJoint]]:
    """Doors and drawers for the case's cells (each on its own link, `door_i` / `drawer_i`;
    only the drawers with `drawers_only`)."""
    out = []
    fx = case.front_x
    depth = drawer_depth if drawer_depth is not None else case.D - case.back - 0.02
    r = REVEAL
    for i, c in enumerate(case.cells):
        if c.kind == "open" or (drawers_only and c.kind != "drawer"):
            continue
        fy0, fy1, fz0, fz1 = c.fy0 + r, c.fy1 - r, c.fz0 + r, c.fz1 - r
        if c.kind == "drawer":
            link = f"drawer_{i}"
            parts, motion = drawer(fx, c.y0 + r, c.y1 - r, c.z0 + r, c.z1 - r, depth, FRONT_T,
                                   link, handle=handle)
            x0 = fx + MOVING_GAP
            parts.append(Part(box_between((x0, fy0, fz0), (x0 + FRONT_T, fy1, fz1)), "front", link))
            parts += _front_decor(x0 + FRONT_T, fy0, fy1, fz0, fz1,
                                  "shaker" if style in ("shaker", "glass") else "flat", link)
            out.append((parts, motion))
        else:
            out.append(_door(fx, fy0, fy1, fz0, fz1, c.kind, f"door_{i}", handle, style))
    return out


def _case_blocks(case: _Case, x_front: float) -> list[Part]:
    """Placeholder blocks: one per row that has fronts, from the back panel to `x_front`, over
    the row's opening and front extents (contents, fronts and handles)."""
    out = []
    for ri, (row, z0, z1) in enumerate(case.rows):
        if row.kind == "open":
            continue
        mine = [c for c in case.cells if c.row == ri]
        za = min(min(c.fz0 for c in mine), z0)
        zb = max(max(c.fz1 for c in mine), z1)
        ya = min(c.fy0 for c in mine)
        yb = max(c.fy1 for c in mine)
        out.append(Part(box_between((-case.D / 2 + case.back, ya, za), (x_front, yb, zb)), "front"))
    return out


def _case_body(case: _Case, detail: bool, x_front: float) -> list[Part]:
    """The case's boards (detail), or its placeholder: one block to `x_front` when every row is
    closed, else the boards plus one block per closed row."""
    if detail or any(row.kind == "open" for row, _, _ in case.rows):
        out = [Part(b, "back" if i == 3 else "wood") for i, b in enumerate(case.boards)]
        return out if detail else out + _case_blocks(case, x_front)
    return [Part(box_between((-case.D / 2, -case.W / 2, case.z_bot), (x_front, case.W / 2, case.z_top + OVERLAP)),
                 "front")]


def front_proud(handle: str) -> float:
    """How far a case's fronts with `handle`s stand in front of the carcass (m)."""
    return MOVING_GAP + FRONT_T + HANDLE_STANDOFF[handle]


def _joints(fronts: list[tuple[list[Part], DoorJoint]], drawer_travel: float) -> list[Joint]:
    return [make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN) if m.kind == "revolute"
            else make_joint(f"{m.link}_joint", m, 0.0, drawer_travel) for _, m in fronts]


def _base(D: float, W: float, zb: float, style: str, detail: bool, leg: float = 0.04,
          slot: str = "wood") -> list[Part]:
    """What a case stands on: a plinth set back 3 cm at the front and 1 cm at the sides, or four
    legs (tapered square in detail; boxes in the placeholder)."""
    if style == "plinth":
        return [Part(box_between((-D / 2, -W / 2 + 0.01, 0.0), (D / 2 - 0.03, W / 2 - 0.01, zb + OVERLAP)),
                     slot)]
    if style == "round_legs":
        return [Part(lg, "metal") for lg in legs((D, W), 0.015, leg, 0.0, zb + OVERLAP,
                                                 taper=0.7 if detail else 1.0, round_legs=True,
                                                 circumscribed=not detail,
                                                 sections=16 if detail else 8)]
    return [Part(lg, slot) for lg in legs((D, W), 0.01, leg, 0.0, zb + OVERLAP,
                                          taper=0.6 if detail else 1.0)]


def _base_bottom(D: float, W: float, style: str) -> Surface:
    if style == "plinth":
        return bottom_rect((-0.015, 0, 0), D / 2 - 0.015 - 0.0005, W / 2 - 0.01 - 0.0005)
    return bottom_rect((0, 0, 0), D / 2, W / 2)


def _top_board(D: float, W: float, z: float, tt: float, overhang: float, detail: bool,
               radius: float = 0.004) -> Part:
    """A top board flush with the back, overhanging the front and sides by `overhang`."""
    ext = (D + overhang, W + 2 * overhang, tt)
    c = (overhang / 2, 0.0, z + tt / 2)
    return Part(bevel_box(ext, c, radius, 2) if detail else box(ext, c), "wood")


def _top_surface(D: float, W: float, H: float, overhang: float) -> Surface:
    return support_rect("top", (overhang / 2, 0, H), (D + overhang) / 2 - 0.02,
                        W / 2 + overhang - 0.02)


def _back_surface(W: float, z0: float, z1: float, D: float) -> Surface:
    """The carcass back (x = -D/2) over its height: what stands against the wall."""
    return Surface.rect("back", Subpart.Back, (-D / 2, 0, (z0 + z1) / 2), (-1, 0, 0), (0, 1, 0),
                        W / 2, (z1 - z0) / 2)


def _interior(name: str, case: _Case, y0: float, y1: float, z: float) -> Surface:
    """An Interior surface (upward) on a board top at z inside the case, between y0 and y1."""
    x0, x1 = -case.D / 2 + case.back, case.D / 2 - 0.01
    return Surface.rect(name, Subpart.Interior, ((x0 + x1) / 2, (y0 + y1) / 2, z), (0, 0, 1),
                        (1, 0, 0), (x1 - x0) / 2 - 0.01, (y1 - y0) / 2 - 0.01)


def _shelf_board(case: _Case, y0: float, y1: float, z: float) -> Part:
    """A fixed shelf whose upper face is at z, from the back panel to 1 cm short of the front."""
    o = OVERLAP
    return Part(box_between((-case.D / 2 + case.back - o, y0 - o, z - case.t),
                            (case.D / 2 - 0.01, y1 + o, z)), "wood")


def _shelf_heights(z0: float, z1: float, n: int, t: float, min_clear: float) -> list[float]:
    """Upper faces of up to n evenly spaced shelves between z0 and z1, as many as keep
    `min_clear` between them."""
    while n > 0 and (z1 - z0 - n * t) / (n + 1) < min_clear:
        n -= 1
    step = (z1 - z0 - n * t) / (n + 1)
    return [z0 + (i + 1) * step + (i + 1) * t for i in range(n)]


class _CaseFactory(PartsFactory):
    """Shared skeleton of the case-built generators: subclasses return the layout."""

    slots = ["wood", "front", "metal", "back", "glass", "mirror"]

    def layout(self, p: dict[str, Any]) -> _Case:
        raise NotImplementedError

    def bottom_is_solid(self, params):
        return self.resolve(params).get("base_style") == "plinth"

    def drawer_depth(self, case: _Case) -> float:
        return case.D - case.back - 0.02

    def fronts(self, p):
        case = self.layout(p)
        return _case_fronts(case, p["handle"], p.get("door_style", "flat"), self.drawer_depth(case))

    def joints(self, p):
        case = self.layout(p)
        return _joints(self.fronts(p), 0.8 * self.drawer_depth(case))


# ----------------------------------------------------------------------------------- cabinet
@register
class Cabinet(_CaseFactory):
    """A freestanding cabinet: 1-2 hinged doors (flat, shaker or glazed) over fixed interior
    shelves, an optional row of drawers on top, on legs or a plinth. Its `top` is a support
    surface; the compartment floor and shelves are Interior surfaces."""

    name = "cabinet"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Cabinet})
    size_class = "large"
    params = {
        "width": Param(0.4, 1.0, doc="carcass Y extent (m)"),
        "depth": Param(0.32, 0.6, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.7, 1.9, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_doors": Param(1, 2, kind="int", doc="doors side by side"),
        "drawer_row": Param(kind="bool", doc="a row of drawers above the doors"),
        "n_shelves": Param(0, 4, kind="int",
                           doc="interior shelves behind the doors (fewer if < 18 cm apart)"),
        "door_style": Param(kind="choice", choices=("flat", "shaker", "glass"), doc="door design"),
        "base_style": Param(kind="choice", choices=("plinth", "legs", "round_legs"),
                            doc="what the carcass stands on"),
        "base_height": Param(0.04, 0.18, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "top_overhang": Param(0.0, 0.03, doc="how far the top overhangs the front and sides (m)"),
    }

    def _n_doors(self, p) -> int:
        return 1 if p["width"] < 0.5 else int(p["n_doors"])

    def layout(self, p):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        nd = self._n_doors(p)
        free = z_top - p["base_height"] - 2 * t  # interior height less one separator board
        rows = [_Row("door", 1.0, nd)]
        if p["drawer_row"]:
            dh = 0.16 if free < 0.8 else 0.2
            rows = [_Row("door", free - dh, nd), _Row("drawer", dh, nd)]
        return _case_layout(W, D, t, 0.006, p["base_height"], z_top, rows, overlay=True)

    def _shelves(self, p, case):
        _, z0, z1 = case.rows[0]
        return _shelf_heights(z0, z1, int(p["n_shelves"]), case.t, 0.18)

    def parts(self, p, detail):
        case = self.layout(p)
        W, D, t = p["width"], p["depth"], p["board_thickness"]
        out = _case_body(case, detail, D / 2 + front_proud(p["handle"]))
        out.append(_top_board(D, W, case.z_top - OVERLAP, t + OVERLAP, p["top_overhang"], detail))
        out += _base(D, W, p["base_height"], p["base_style"], detail)
        if detail:
            yi0, yi1 = case.inner()
            out += [_shelf_board(case, yi0, yi1, z) for z in self._shelves(p, case)]
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out

    def extra_surfaces(self, p):
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        yi0, yi1 = case.inner()
        _, z0, _ = case.rows[0]
        out = [_top_surface(D, W, H, p["top_overhang"]),
               _base_bottom(D, W, p["base_style"]),
               _back_surface(W, p["base_height"], H, D)]
        for i, z in enumerate([z0] + self._shelves(p, case)):
            out.append(_interior(f"interior_{i}", case, yi0, yi1, z))
        return out


# ---------------------------------------------------------------------------------- wardrobe
SLIDE_SPACING = 0.006   # between the two sliding-door tracks (room for the inner door's pull)
SLIDE_OVERLAP = 0.04    # how far the closed sliding doors overlap at the middle


@register
class Wardrobe(_CaseFactory):
    """A tall wardrobe: 2-4 hinged doors (flat, shaker or mirrored) or two sliding doors on
    separate tracks, a hanging rail under a hat shelf, a shelf column behind the third/fourth
    door, optional drawer rows at the bottom; on a plinth or legs. Interior shelves and floors
    are Interior surfaces; `top` is a support surface (boxes on the wardrobe)."""

    name = "wardrobe"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Wardrobe})
    size_class = "large"
    params = {
        "width": Param(0.8, 2.4, doc="carcass Y extent (m)"),
        "depth": Param(0.52, 0.65, doc="carcass X extent, doors excluded (m)"),
        "height": Param(1.8, 2.4, doc="overall height (m)"),
        "board_thickness": Param(0.018, 0.025, doc="board thickness (m)"),
        "door_type": Param(kind="choice", choices=("hinged", "sliding"), doc="door mechanism"),
        "n_doors": Param(2, 4, kind="int",
                         doc="hinged doors (kept to 30-65 cm each); sliding wardrobes have two"),
        "door_style": Param(kind="choice", choices=("flat", "shaker", "mirror"), doc="door design"),
        "drawer_rows": Param(0, 2, kind="int", doc="rows of drawers at the bottom"),
        "shelf_drop": Param(0.25, 0.45, doc="hat shelf distance below the carcass top (m)"),
        "base_style": Param(kind="choice", choices=("plinth", "legs"), doc="plinth or legs"),
        "base_height": Param(0.05, 0.12, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type (hinged doors "
                                                                    "and drawers)"),
    }

    def _n_doors(self, p) -> int:
        if p["door_type"] == "sliding":
            return 2
        W = p["width"]
        return int(min(max(int(p["n_doors"]), math.ceil(W / 0.65)), math.floor(W / 0.3)))

    def _sliding(self, p) -> bool:
        return p["door_type"] == "sliding"

    def _divider(self, p) -> float | None:
        """The y of the full-height divider: between doors 2 and 3 of a 3-4 door wardrobe, at
        the middle of a wide sliding one; None without one."""
        W, n = p["width"], self._n_doors(p)
        if self._sliding(p):
            return 0.0 if W > 1.3 else None
        if n >= 3:
            return -W / 2 + 2 * W / n
        return None

    def layout(self, p):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        nr = int(p["drawer_rows"])
        nd = 3 if W > 1.3 else 2
        free = z_top - p["base_height"] - t - nr * t
        rows = [_Row("drawer", 0.22, nd) for _ in range(nr)]
        rows.append(_Row("door", free - 0.22 * nr, self._n_doors(p)))
        yd = self._divider(p)
        return _case_layout(W, D, t, 0.008, p["base_height"], z_top, rows,
                            overlay=not self._sliding(p), door_dividers=() if yd is None else (yd,))

    # ---- sliding doors
    def _track_depth(self) -> float:
        return 2 * MOVING_GAP + 2 * FRONT_T + SLIDE_SPACING + 0.004

    def _slide_proud(self) -> float:
        """How far the outer sliding door's pull stands in front of the carcass."""
        return MOVING_GAP + 2 * FRONT_T + SLIDE_SPACING + 0.01

    def _door_zone(self, p, case) -> tuple[float, float]:
        """z range of the sliding doors: above the bottom track, below the top board."""
        _, z0, z1 = case.rows[-1]
        return z0 + 0.02 + MOVING_GAP, case.z_top - MOVING_GAP

    def _sliding_doors(self, p, case) -> list[tuple[list[Part], DoorJoint]]:
        W, fx = p["width"], case.front_x
        za, zb = self._door_zone(p, case)
        out = []
        for k, (ya, yb) in enumerate(((-W / 2 + REVEAL, SLIDE_OVERLAP / 2),
                                      (-SLIDE_OVERLAP / 2, W / 2 - REVEAL))):
            x0 = fx + MOVING_GAP + k * (FRONT_T + SLIDE_SPACING)
            x1 = x0 + FRONT_T
            link = f"door_{k}"
            parts = [Part(box_between((x0, ya, za), (x1, yb, zb)), "front", link)]
            # a flush pull strip at the outer edge (the inner door's fits between the tracks)
            yp = ya + 0.03 if k == 0 else yb - 0.03
            proud = 0.004 if k == 0 else 0.01
            parts.append(Part(box_between((x1 - 0.001, yp - 0.01, za + 0.3 * (zb - za)),
                                          (x1 + proud, yp + 0.01, za + 0.7 * (zb - za))),
                              "metal", link))
            parts += _front_decor(x1, ya, yb, za, zb, p["door_style"], link)
            axis = np.array([0.0, 1.0 if k == 0 else -1.0, 0.0])
            out.append((parts, DoorJoint("prismatic", axis, np.array([x1, (ya + yb) / 2, za]), link)))
        return out

    def _tracks(self, p, case) -> list[Part]:
        """Top and bottom tracks in front of the carcass, full width."""
        W, fx = p["width"], case.front_x
        td = self._track_depth()
        _, z0, _ = case.rows[-1]
        return [Part(box_between((fx - OVERLAP, -W / 2, z0 - case.t), (fx + td, W / 2, z0 + 0.02)),
                     "metal")]

    def fronts(self, p):
        case = self.layout(p)
        if not self._sliding(p):
            return super().fronts(p)
        drawers = _case_fronts(case, p["handle"], "flat", self.drawer_depth(case), drawers_only=True)
        return drawers + self._sliding_doors(p, case)

    def joints(self, p):
        case = self.layout(p)
        out = []
        for parts, m in self.fronts(p):
            if m.kind == "prismatic" and m.link.startswith("door"):
                out.append(make_joint(f"{m.link}_joint", m, 0.0, 0.9 * (p["width"] / 2 - SLIDE_OVERLAP)))
            elif m.kind == "prismatic":
                out.append(make_joint(f"{m.link}_joint", m, 0.0, 0.8 * self.drawer_depth(case)))
            else:
                out.append(make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN))
        return out

    # ---- interior
    def _sections(self, p, case) -> list[tuple[float, float, str]]:
        """(y0, y1, "hanging" | "shelves") of the door zone's sections."""
        yi0, yi1 = case.inner()
        yd = self._divider(p)
        if yd is None:
            return [(yi0, yi1, "hanging")]
        t = case.t
        right = "hanging" if self._sliding(p) else "shelves"
        return [(yi0, yd - t / 2, "hanging"), (yd + t / 2, yi1, right)]

    def _hat_shelf(self, p, case) -> float:
        return case.z_top - p["shelf_drop"]

    def _column_shelves(self, p, case) -> list[float]:
        _, z0, z1 = case.rows[-1]
        n = max(1, int(round((z1 - z0) / 0.38)) - 1)
        return _shelf_heights(z0, z1, n, case.t, 0.25)

    def _interior_parts(self, p, case) -> list[Part]:
        out = []
        zs = self._hat_shelf(p, case)
        for y0, y1, kind in self._sections(p, case):
            if kind == "hanging":
                out.append(_shelf_board(case, y0, y1, zs))
                zr = zs - case.t - 0.06
                out.append(Part(rod((0.0, y0 - 0.001, zr), (0.0, y1 + 0.001, zr), 0.0125, 16), "metal"))
            else:
                out += [_shelf_board(case, y0, y1, z) for z in self._column_shelves(p, case)]
        return out

    def parts(self, p, detail):
        case = self.layout(p)
        W, D = p["width"], p["depth"]
        sliding = self._sliding(p)
        proud = front_proud(p["handle"]) if case.rows[0][0].kind == "drawer" or not sliding else 0.0
        if sliding:
            proud = max(proud, self._slide_proud())
        out = _case_body(case, detail, D / 2 + proud)
        over = self._track_depth() if sliding else 0.0
        out.append(Part(box_between((-D / 2, -W / 2, case.z_top - OVERLAP), (D / 2 + over, W / 2, p["height"])),
                        "wood"))
        out += _base(D, W, p["base_height"], p["base_style"], detail)
        if detail:
            out += self._interior_parts(p, case)
            if sliding:
                out += self._tracks(p, case)
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out

    def extra_surfaces(self, p):
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        over = self._track_depth() if self._sliding(p) else 0.0
        out = [support_rect("top", (over / 2, 0, H), (D + over) / 2 - 0.02, W / 2 - 0.02),
               _base_bottom(D, W, p["base_style"]),
               _back_surface(W, p["base_height"], H, D)]
        _, z0, _ = case.rows[-1]
        zs = self._hat_shelf(p, case)
        k = 0
        for y0, y1, kind in self._sections(p, case):
            for z in [z0] + ([zs] if kind == "hanging" else self._column_shelves(p, case)):
                out.append(_interior(f"interior_{k}", case, y0, y1, z))
                k += 1
        return out


# ----------------------------------------------------------------------------------- dresser
def _graduated_rows(n: int, graduated: bool) -> list[float]:
    """Row weights bottom first: graduated dressers have deeper drawers lower down."""
    return [1.0 + (0.18 * (n - 1 - i) if graduated else 0.0) for i in range(n)]


@register
class Dresser(_CaseFactory):
    """A chest of drawers: 3-6 rows of 1-3 drawers (optionally graduated, the top row split into
    smaller drawers), overlay or framed fronts, flat or shaker, on a plinth or legs. Every drawer
    is articulated; `top` is a support surface."""

    name = "dresser"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Dresser})
    size_class = "large"
    params = {
        "width": Param(0.6, 1.6, doc="carcass Y extent (m)"),
        "depth": Param(0.4, 0.55, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.7, 1.3, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_rows": Param(3, 6, kind="int", doc="drawer rows (fewer if a row would be < 11 cm)"),
        "drawers_per_row": Param(1, 3, kind="int", doc="drawers side by side (capped by width)"),
        "top_split": Param(kind="bool", doc="split the top row into one more, smaller drawers"),
        "graduated": Param(kind="bool", doc="deeper drawers towards the bottom"),
        "fit": Param(kind="choice", choices=("overlay", "framed"),
                     doc="fronts cover the board edges or sit within the frame"),
        "door_style": Param(kind="choice", choices=("flat", "shaker"), doc="drawer front design"),
        "base_style": Param(kind="choice", choices=("plinth", "legs", "round_legs"),
                            doc="what the carcass stands on"),
        "base_height": Param(0.04, 0.16, doc="plinth / leg height (m)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "top_overhang": Param(0.0, 0.03, doc="how far the top overhangs the front and sides (m)"),
    }

    def layout(self, p):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        z_top = H - t
        inner = z_top - p["base_height"] - t
        n = int(p["n_rows"])
        while n > 1 and (inner - (n - 1) * t) / n < 0.11:
            n -= 1
        cols = int(min(p["drawers_per_row"], max(1, math.floor(W / 0.3))))
        weights = _graduated_rows(n, p["graduated"])
        rows = [_Row("drawer", w, cols) for w in weights]
        if p["top_split"] and (W - 2 * t) / (cols + 1) >= 0.2:
            rows[-1] = _Row("drawer", weights[-1] * 0.8, cols + 1)
        return _case_layout(W, D, t, 0.006, p["base_height"], z_top, rows,
                            overlay=p["fit"] == "overlay")

    def parts(self, p, detail):
        case = self.layout(p)
        W, D, t = p["width"], p["depth"], p["board_thickness"]
        out = _case_body(case, detail, D / 2 + front_proud(p["handle"]))
        out.append(_top_board(D, W, case.z_top - OVERLAP, t + OVERLAP, p["top_overhang"], detail))
        out += _base(D, W, p["base_height"], p["base_style"], detail)
        if detail:
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out

    def extra_surfaces(self, p):
        W, D, H = p["width"], p["depth"], p["height"]
        return [_top_surface(D, W, H, p["top_overhang"]),
                _base_bottom(D, W, p["base_style"]),
                _back_surface(W, p["base_height"], H, D)]


# -------------------------------------------------------------------------------- nightstand
NIGHTSTAND_LAYOUTS = {
    # rows bottom first
    "drawer_shelf": (_Row("open", 1.3), _Row("drawer", 1.0)),
    "two_drawers": (_Row("drawer", 1.0), _Row("drawer", 1.0)),
    "drawer_door": (_Row("door", 2.0), _Row("drawer", 1.0)),
    "open": (_Row("open", 1.0), _Row("open", 1.0)),
    "three_drawers": (_Row("drawer", 1.0), _Row("drawer", 1.0), _Row("drawer", 1.0)),
}


@register
class Nightstand(_CaseFactory):
    """A bedside table: a small case with a drawer over an open shelf, two or three drawers, a
    drawer over a door, or two open shelves; on tall legs or a plinth. `top` is a support
    surface, as is the floor of every open shelf (`shelf_i`); a door compartment's floor is an
    Interior surface."""

    name = "nightstand"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Nightstand})
    size_class = "medium"
    params = {
        "width": Param(0.35, 0.6, doc="carcass Y extent (m)"),
        "depth": Param(0.3, 0.45, doc="carcass X extent, fronts excluded (m)"),
        "height": Param(0.45, 0.7, doc="overall height to the top's upper face (m)"),
        "board_thickness": Param(0.015, 0.022, doc="board thickness (m)"),
        "layout": Param(kind="choice", choices=tuple(NIGHTSTAND_LAYOUTS),
                        doc="what fills the case, top to bottom"),
        "base_style": Param(kind="choice", choices=("legs", "round_legs", "plinth"),
                            doc="what the case stands on"),
        "base_height": Param(0.03, 0.22, doc="leg / plinth height (m; plinths capped at 8 cm)"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="handle type"),
        "door_style": Param(kind="choice", choices=("flat", "shaker"), doc="front design"),
        "top_overhang": Param(0.0, 0.025, doc="how far the top overhangs the front and sides (m)"),
    }

    def _zb(self, p) -> float:
        return min(p["base_height"], 0.08) if p["base_style"] == "plinth" else p["base_height"]

    def _rows(self, p) -> tuple[_Row, ...]:
        rows = NIGHTSTAND_LAYOUTS[p["layout"]]
        inner = p["height"] - p["board_thickness"] - self._zb(p) - p["board_thickness"]
        if len(rows) == 3 and inner < 0.36:
            rows = rows[1:]
        return rows

    def layout(self, p):
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        return _case_layout(W, D, t, 0.005, self._zb(p), H - t, self._rows(p), overlay=True)

    def parts(self, p, detail):
        case = self.layout(p)
        W, D, t = p["width"], p["depth"], p["board_thickness"]
        out = _case_body(case, detail, D / 2 + front_proud(p["handle"]))
        out.append(_top_board(D, W, case.z_top - OVERLAP, t + OVERLAP, p["top_overhang"], detail))
        out += _base(D, W, self._zb(p), p["base_style"], detail, leg=0.032)
        if detail:
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out

    def extra_surfaces(self, p):
        case = self.layout(p)
        W, D, H = p["width"], p["depth"], p["height"]
        out = [_top_surface(D, W, H, p["top_overhang"]),
               _base_bottom(D, W, p["base_style"]),
               _back_surface(W, self._zb(p), H, D)]
        yi0, yi1 = case.inner()
        k = 0
        for row, z0, _ in case.rows:
            if row.kind == "open":
                x0, x1 = -D / 2 + case.back, D / 2
                out.append(support_rect(f"shelf_{k}", ((x0 + x1) / 2, 0, z0), (x1 - x0) / 2 - 0.02,
                                        (yi1 - yi0) / 2 - 0.02))
                k += 1
            elif row.kind == "door":
                out.append(_interior("interior_0", case, yi0, yi1, z0))
        return out


# -------------------------------------------------------------------------------- cell shelf
@register
class CellShelf(PartsFactory):
    """Cube storage: a grid of 2x2 to 5x5 square cells (thick outer frame, thinner inner
    boards), optional back panel, standing on the floor, a plinth or legs. Every cell floor is
    a support surface `cell_<row>_<col>`, and so is the `top`."""

    name = "cell_shelf"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Shelf, S.CellShelf})
    size_class = "large"
    slots = ["wood", "back", "metal"]
    params = {
        "n_rows": Param(2, 5, kind="int", doc="cells stacked vertically"),
        "n_cols": Param(2, 5, kind="int", doc="cells side by side"),
        "cell_size": Param(0.28, 0.36, doc="inner width and height of a cell (m)"),
        "depth": Param(0.3, 0.4, doc="X extent (m)"),
        "outer_thickness": Param(0.02, 0.04, doc="outer frame board thickness (m)"),
        "inner_thickness": Param(0.012, 0.02, doc="inner board thickness (m)"),
        "back_panel": Param(kind="bool", doc="close the back with a thin panel"),
        "base_style": Param(kind="choice", choices=("none", "plinth", "legs"),
                            doc="what the frame stands on"),
        "base_height": Param(0.03, 0.15, doc="plinth / leg height (m)"),
    }

    def bottom_is_solid(self, params):
        return self.resolve(params)["base_style"] != "legs"

    def _dims(self, p) -> tuple[float, float, float, float]:
        """(width, frame height, base height, back panel thickness)."""
        c, to, ti = p["cell_size"], p["outer_thickness"], p["inner_thickness"]
        nr, nc = int(p["n_rows"]), int(p["n_cols"])
        W = nc * c + (nc - 1) * ti + 2 * to
        Hf = nr * c + (nr - 1) * ti + 2 * to
        zb = 0.0 if p["base_style"] == "none" else p["base_height"]
        return W, Hf, zb, (0.005 if p["back_panel"] else 0.0)

    def _cell(self, p, r: int, k: int) -> tuple[float, float, float]:
        """(y0, y1, floor z) of cell (row r, column k)."""
        c, to, ti = p["cell_size"], p["outer_thickness"], p["inner_thickness"]
        W, _, zb, _ = self._dims(p)
        y0 = -W / 2 + to + k * (c + ti)
        return y0, y0 + c, zb + to + r * (c + ti)

    def parts(self, p, detail):
        D, to, ti = p["depth"], p["outer_thickness"], p["inner_thickness"]
        W, Hf, zb, bp = self._dims(p)
        nr, nc = int(p["n_rows"]), int(p["n_cols"])
        o, d2, w2 = OVERLAP, D / 2, W / 2
        H = zb + Hf
        if detail:  # the frame as one block with the cells cut through it (no coplanar seams)
            cells = [box_between((-d2 + bp, y0, z), (d2 + 0.01, y1, z + p["cell_size"]))
                     for r in range(nr) for k in range(nc)
                     for y0, y1, z in [self._cell(p, r, k)]]
            block = box_between((-d2, -w2, zb), (d2, w2, H))
            out = [Part(m3d.Manifold.batch_boolean([block] + cells, m3d.OpType.Subtract), "wood")]
        else:
            out = [Part(box_between((-d2, -w2, zb), (d2, w2, zb + to)), "wood"),
                   Part(box_between((-d2, -w2, H - to), (d2, w2, H)), "wood"),
                   Part(box_between((-d2, -w2, zb + to - o), (d2, -w2 + to, H - to + o)), "wood"),
                   Part(box_between((-d2, w2 - to, zb + to - o), (d2, w2, H - to + o)), "wood")]
            for i in range(1, nr):
                z = self._cell(p, i, 0)[2]
                out.append(Part(box_between((-d2, -w2 + to - o, z - ti), (d2, w2 - to + o, z)), "wood"))
            for k in range(1, nc):
                y = self._cell(p, 0, k)[0]
                out.append(Part(box_between((-d2, y - ti, zb + to - o), (d2, y, H - to + o)), "wood"))
        if bp and not detail:
            out.append(Part(box_between((-d2, -w2 + to - o, zb + to - o), (-d2 + bp, w2 - to + o, H - to + o)),
                            "back"))
        if p["base_style"] == "plinth":
            out.append(Part(box_between((-d2, -w2 + 0.01, 0.0), (d2 - 0.03, w2 - 0.01, zb + o)), "wood"))
        elif p["base_style"] == "legs":
            out += [Part(lg, "metal") for lg in legs((D, W), 0.02, 0.04, 0.0, zb + o, round_legs=True,
                                                     circumscribed=not detail,
                                                     sections=16 if detail else 8)]
        return out

    def extra_surfaces(self, p):
        D = p["depth"]
        W, Hf, zb, bp = self._dims(p)
        out = [support_rect("top", (0, 0, zb + Hf), D / 2 - 0.02, W / 2 - 0.02)]
        x0, x1 = -D / 2 + bp, D / 2
        for r in range(int(p["n_rows"])):
            for k in range(int(p["n_cols"])):
                y0, y1, z = self._cell(p, r, k)
                out.append(support_rect(f"cell_{r}_{k}", ((x0 + x1) / 2, (y0 + y1) / 2, z),
                                        (x1 - x0) / 2 - 0.01, (y1 - y0) / 2 - 0.01))
        if p["base_style"] == "plinth":
            out.append(bottom_rect((-0.015, 0, 0), D / 2 - 0.0155, W / 2 - 0.0105))
        return out


# -------------------------------------------------------------------------------- wall shelf
@register
class WallShelf(PartsFactory):
    """A wall-mounted shelf: 1-3 floating boards (several share a back panel), boards on
    brackets hanging from a wall track, or an open wall box with sides, top and bottom. Its
    `back` is a flat face against the wall; every board top is a support surface `shelf_i`."""

    name = "wall_shelf"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Shelf, S.WallShelf, S.WallMounted})
    size_class = "medium"
    slots = ["wood", "metal", "back"]
    params = {
        "width": Param(0.4, 1.2, doc="Y extent (m)"),
        "depth": Param(0.15, 0.3, doc="X extent (m)"),
        "n_boards": Param(1, 3, kind="int", doc="shelf boards (a boxed shelf adds a top)"),
        "spacing": Param(0.2, 0.35, doc="clear height between boards (m)"),
        "board_thickness": Param(0.018, 0.05, doc="board thickness (m; boxed shelves cap it at "
                                                   "25 mm)"),
        "style": Param(kind="choice", choices=("floating", "bracketed", "boxed"),
                       doc="how the boards are held"),
        "bracket_inset": Param(0.06, 0.2, doc="bracket / track inset from the board ends (m)"),
        "edge_radius": Param(0.0, 0.006, doc="rounding of the board edges (m)"),
    }

    BACK = 0.012   # back panel / wall track thickness (m)
    TRACK_H = 0.03  # height of the bracketed style's wall track (m)

    def _bt(self, p) -> float:
        return min(p["board_thickness"], 0.025) if p["style"] == "boxed" else p["board_thickness"]

    def _bracket_h(self, p) -> float:
        return min(0.6 * p["depth"], 0.15)

    def _levels(self, p) -> list[float]:
        """The upper face z of each board, bottom first (boxed: bottom board first, top last)."""
        bt, n, s = self._bt(p), int(p["n_boards"]), p["spacing"]
        z0 = self._bracket_h(p) if p["style"] == "bracketed" else 0.0
        if p["style"] == "boxed":
            n += 1
        return [z0 + bt + i * (s + bt) for i in range(n)]

    def _back_x(self, p) -> float:
        """x of the boards' back edge (in front of the back panel / track, if any)."""
        D = p["depth"]
        if p["style"] == "floating" and int(p["n_boards"]) == 1:
            return -D / 2
        return -D / 2 + self.BACK - OVERLAP

    def parts(self, p, detail):
        W, D = p["width"], p["depth"]
        bt, st = self._bt(p), p["style"]
        zs = self._levels(p)
        H = zs[-1]
        o, d2, w2 = OVERLAP, D / 2, W / 2
        xb = self._back_x(p)
        r = p["edge_radius"] if detail else 0.0
        out = []
        y_end = w2 - bt if st == "boxed" else w2
        for i, z in enumerate(zs):
            if st == "boxed" and i in (0, len(zs) - 1):
                y_a = w2
            else:
                y_a = y_end + (o if st == "boxed" else 0.0)
            lo, hi = np.array([xb, -y_a, z - bt]), np.array([d2, y_a, z])
            out.append(Part(bevel_box(hi - lo, (lo + hi) / 2, r, 2) if r > 1e-4 else box_between(lo, hi),
                            "wood"))
        if st == "floating" and len(zs) > 1:
            out.append(Part(box_between((-d2, -w2, 0.0), (-d2 + self.BACK, w2, H)), "back"))
        elif st == "boxed":
            out.append(Part(box_between((-d2, -w2 + bt - o, 0.0), (-d2 + self.BACK, w2 - bt + o, H)), "back"))
            for s in (-1, 1):
                out.append(Part(box_between((-d2, min(s * w2, s * (w2 - bt)), zs[0] - o),
                                            (d2, max(s * w2, s * (w2 - bt)), H - bt + o)), "wood"))
        elif st == "bracketed":
            out += self._hardware(p, zs, detail)
        return out

    def _bracket_ys(self, p) -> tuple[float, float]:
        W = p["width"]
        a = min(p["bracket_inset"], 0.3 * W)
        return -W / 2 + a, W / 2 - a

    def _hardware(self, p, zs, detail) -> list[Part]:
        """Wall track, two standards and a pair of brackets under each board."""
        D, bt = p["depth"], self._bt(p)
        H, o, d2 = zs[-1], OVERLAP, p["depth"] / 2
        xw = -d2 + self.BACK
        out = []
        ya, yb = self._bracket_ys(p)
        sw = 0.025
        out.append(Part(box_between((-d2, ya - sw / 2, H - self.TRACK_H), (xw, yb + sw / 2, H)), "metal"))
        hb = self._bracket_h(p)
        for y in (ya, yb):
            out.append(Part(box_between((-d2, y - sw / 2, 0.0), (xw, y + sw / 2, H)), "metal"))
            for z in zs:
                zt = z - bt + o  # board underside (brackets reach 2 mm into the board)
                pts = np.array([(xw - o, y + s * 0.003, zz) for s in (-1, 1) for zz in (zt - hb, zt)]
                               + [(-d2 + 0.85 * D, y + s * 0.003, zt - 0.012 * k)
                                  for s in (-1, 1) for k in (0, 1)])
                br = m3d.Manifold.hull_points(pts)
                if not detail:
                    lo, hi = br.bounding_box()[:3], br.bounding_box()[3:]
                    br = box_between(lo, hi)
                out.append(Part(br, "metal"))
        return out

    def extra_surfaces(self, p):
        W, D, st = p["width"], p["depth"], p["style"]
        bt = self._bt(p)
        zs = self._levels(p)
        xb = max(self._back_x(p), -D / 2 + self.BACK) if st != "floating" or len(zs) > 1 else -D / 2
        out = []
        for i, z in enumerate(zs):
            hy = W / 2 - (bt if st == "boxed" and 0 < i < len(zs) - 1 else 0.0)
            if st == "boxed" and i == 0:
                hy = W / 2 - bt
            out.append(support_rect(f"shelf_{i}", ((xb + D / 2) / 2, 0, z), (D / 2 - xb) / 2 - 0.015,
                                    hy - 0.015))
        H = zs[-1]
        r = p["edge_radius"] if p["edge_radius"] > 1e-4 else 0.0
        if st == "floating" and len(zs) == 1 and r:  # the flat part of the rounded board's back
            out.append(Surface.rect("back", Subpart.Back, (-D / 2, 0, H - bt / 2), (-1, 0, 0), (0, 1, 0),
                                    W / 2 - r - 0.0005, bt / 2 - r - 0.0005))
        if st == "bracketed":  # the wall track is what lies flat against the wall
            ya, yb = self._bracket_ys(p)
            out.append(Surface.rect("back", Subpart.Back, (-D / 2, (ya + yb) / 2, H - self.TRACK_H / 2),
                                    (-1, 0, 0), (0, 1, 0), (yb - ya) / 2 + 0.0125 - 0.0005,
                                    self.TRACK_H / 2 - 0.0005))
        return out


# ------------------------------------------------------------------------------ corner shelf
CORNER_SHAPES = ("triangle", "quarter_round", "pentagon")


def _corner_outline(shape: str, R: float, arc_segments: int = 16, enclose: bool = False) -> np.ndarray:
    """The shelf outline in corner coordinates (a, b) >= 0 (a along the back wall's normal, b
    along the side wall's), counter-clockwise from the corner. `enclose` makes the curved edge
    a circumscribed polygon (for placeholders: contains the fine arc, same extents)."""
    if shape == "triangle":
        return np.array([(0.0, 0.0), (R, 0.0), (0.0, R)])
    if shape == "pentagon":
        c = 0.45 * R
        return np.array([(0.0, 0.0), (R, 0.0), (R, c), (c, R), (0.0, R)])
    n = arc_segments
    ang = np.linspace(0.0, math.pi / 2, n + 1)
    if enclose:  # tangent-line intersections between the exact end points
        mid = (ang[:-1] + ang[1:]) / 2
        rr = R / math.cos(math.pi / 4 / n)
        arc = np.vstack([[R, 0.0], np.c_[rr * np.cos(mid), rr * np.sin(mid)], [0.0, R]])
    else:
        arc = np.c_[R * np.cos(ang), R * np.sin(ang)]
    return np.vstack([[0.0, 0.0], arc])


@register
class CornerShelf(PartsFactory):
    """A floor-standing corner shelf unit: two perpendicular panels against the walls (its
    `back` at -X and `side_left` at +Y, both flat faces on the mesh) holding 3-5 triangular,
    quarter-round or cut-corner shelves (each a support surface `shelf_i`), optionally with a
    front apron under every shelf."""

    name = "corner_shelf"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Shelf, S.CornerShelf})
    size_class = "large"
    slots = ["wood", "back"]
    params = {
        "size": Param(0.28, 0.5, doc="X and Y extent: shelf reach along each wall (m)"),
        "level_spacing": Param(0.25, 0.42, doc="height from one shelf's top to the next (m)"),
        "n_levels": Param(3, 5, kind="int", doc="shelves, the top one included"),
        "shape": Param(kind="choice", choices=CORNER_SHAPES, doc="shelf outline"),
        "board_thickness": Param(0.015, 0.03, doc="shelf thickness (m)"),
        "panel_thickness": Param(0.012, 0.02, doc="wall panel thickness (m)"),
        "bottom_height": Param(0.0, 0.1, doc="height of the lowest shelf's underside (m)"),
        "apron": Param(kind="bool", doc="a 4 cm apron under each shelf's front edge"),
    }

    def _levels(self, p) -> list[float]:
        """Upper faces of the shelves, bottom first (the last is the unit's top)."""
        z0 = p["bottom_height"] + p["board_thickness"]
        return [z0 + i * p["level_spacing"] for i in range(int(p["n_levels"]))]

    def _to_design(self, ab: np.ndarray, R: float) -> np.ndarray:
        """Corner coords (a from the back wall, b from the side wall) -> design (x, y)."""
        return np.c_[-R / 2 + ab[:, 0], R / 2 - ab[:, 1]]

    def _shelf_polygon(self, p, detail: bool = True) -> sg.Polygon:
        """A shelf's outline in the design frame, starting 2 mm inside the wall panels (so that
        no shelf face is coplanar with a panel face)."""
        R, tp = p["size"], p["panel_thickness"]
        ab = _corner_outline(p["shape"], R, 16 if detail else 4, enclose=not detail)
        a0 = tp - OVERLAP
        clipped = sg.Polygon(ab).intersection(sg.box(a0, a0, 2 * R, 2 * R))
        xy = self._to_design(np.asarray(clipped.exterior.coords)[:-1], R)
        return sg.polygon.orient(sg.Polygon(xy), 1.0)

    def parts(self, p, detail):
        R, bt, tp = p["size"], p["board_thickness"], p["panel_thickness"]
        H = self._levels(p)[-1]
        o = OVERLAP
        cs = m3d.CrossSection([np.asarray(self._shelf_polygon(p, detail).exterior.coords)[:-1]])
        out = [Part(box_between((-R / 2, -R / 2, 0.0), (-R / 2 + tp, R / 2, H)), "back"),
               Part(box_between((-R / 2, R / 2 - tp, 0.0), (R / 2, R / 2, H)), "back")]
        # the apron: a 1 cm band just inside the shelf's outline (0.5 mm in: no coplanar faces)
        band = cs.offset(-0.0005, m3d.JoinType.Miter) - cs.offset(-0.01, m3d.JoinType.Miter)
        for z in self._levels(p):
            out.append(Part(m3d.Manifold.extrude(cs, bt).translate((0.0, 0.0, z - bt)), "wood"))
            if p["apron"]:
                ah = min(0.04, z - bt)
                if ah > 0.01:
                    piece = band if detail else cs
                    out.append(Part(m3d.Manifold.extrude(piece, ah + o).translate((0.0, 0.0, z - bt - ah)),
                                    "wood"))
        return out

    def extra_surfaces(self, p):
        poly = self._shelf_polygon(p).buffer(-0.015, join_style="mitre")
        poly = sg.Polygon(np.asarray(poly.exterior.coords))
        return [support_polygon(f"shelf_{i}", (0, 0, z), poly) for i, z in enumerate(self._levels(p))]


# ---------------------------------------------------------------------------------- shoe rack
@register
class ShoeRack(PartsFactory):
    """A shoe rack: 2-5 tiers, each a frame of slats flush with its side rails (or a solid
    board), between two side panels or four corner posts. Every tier top is a support surface
    `tier_i`; a slatted tier's surface has the gaps between slats as holes."""

    name = "shoe_rack"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Shelf, S.ShoeRack})
    size_class = "large"
    slots = ["wood", "metal"]
    params = {
        "width": Param(0.5, 1.2, doc="Y extent (m)"),
        "depth": Param(0.26, 0.38, doc="X extent (m)"),
        "n_tiers": Param(2, 5, kind="int", doc="tiers"),
        "tier_spacing": Param(0.14, 0.22, doc="height from one tier's top to the next (m)"),
        "tier_style": Param(kind="choice", choices=("slats", "solid"), doc="slatted or solid tiers"),
        "frame_style": Param(kind="choice", choices=("panels", "posts"),
                             doc="side panels or four corner posts"),
        "frame_thickness": Param(0.015, 0.03, doc="side panel thickness / post section (m)"),
        "n_slats": Param(3, 7, kind="int", doc="slats per slatted tier"),
        "foot_height": Param(0.0, 0.06, doc="height of the lowest tier's underside (m)"),
    }

    BT = 0.018  # tier thickness (m)
    RAIL = 0.03  # side rail width of a slatted tier (m)

    def _levels(self, p) -> list[float]:
        return [p["foot_height"] + self.BT + i * p["tier_spacing"] for i in range(int(p["n_tiers"]))]

    def _inner(self, p) -> float:
        """Half the width between the side panels (or posts)."""
        return p["width"] / 2 - p["frame_thickness"]

    def _slats(self, p) -> list[tuple[float, float]]:
        """(x0, x1) of each slat of a slatted tier, front and back slats at the edges."""
        D, n = p["depth"], int(p["n_slats"])
        sw = 0.6 * D / n
        xs = np.linspace(-D / 2 + 0.001, D / 2 - 0.001 - sw, n)
        return [(float(x), float(x) + sw) for x in xs]

    def parts(self, p, detail):
        D, W, ft = p["depth"], p["width"], p["frame_thickness"]
        zs = self._levels(p)
        H = zs[-1]
        o, d2, w2 = OVERLAP, D / 2, W / 2
        yi = self._inner(p)
        out = []
        if p["frame_style"] == "panels":
            for s in (-1, 1):
                out.append(Part(box_between((-d2, min(s * w2, s * yi), 0.0), (d2, max(s * w2, s * yi), H)),
                                "wood"))
        else:
            for sx in (-1, 1):
                for sy in (-1, 1):
                    cx, cy = sx * (d2 - ft / 2), sy * (w2 - ft / 2)
                    out.append(Part(box((ft, ft, H), (cx, cy, H / 2)), "metal"))
            yi = w2 - ft
        e = 0.001  # tiers stop 1 mm inside the frame's faces (no coplanar seams)
        for z in zs:
            tier = box_between((-d2 + e, -yi - o, z - self.BT), (d2 - e, yi + o, z))
            if p["tier_style"] == "slats" and detail:  # one board with the gaps cut through
                gaps = self._gaps(p)
                tier = m3d.Manifold.batch_boolean(
                    [tier] + [box_between((a, ya, z - 0.1), (b, yb, z + 0.1)) for a, b, ya, yb in gaps],
                    m3d.OpType.Subtract)
            out.append(Part(tier, "wood"))
        return out

    def _gaps(self, p) -> list[tuple[float, float, float, float]]:
        """(x0, x1, y0, y1) of the gaps between the slats of a slatted tier."""
        yi = self._inner(p)
        sl = self._slats(p)
        return [(a[1], b[0], -yi + self.RAIL, yi - self.RAIL) for a, b in zip(sl, sl[1:])]

    def extra_surfaces(self, p):
        D = p["depth"]
        yi = self._inner(p)
        m = 0.005
        outer = [(-D / 2 + m, -yi + m), (D / 2 - m, -yi + m), (D / 2 - m, yi - m), (-D / 2 + m, yi - m)]
        holes = []
        if p["tier_style"] == "slats":
            holes = [[(a, ya), (b, ya), (b, yb), (a, yb)] for a, b, ya, yb in self._gaps(p)]
        poly = sg.Polygon(outer, holes)
        return [support_polygon(f"tier_{i}", (0, 0, z), poly) for i, z in enumerate(self._levels(p))]
