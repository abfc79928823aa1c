"""The case builder shared by the closed storage pieces (cabinets, dressers, nightstands,
wardrobes).

`case_layout` lays out a carcass of boards split into rows (drawers, doors or open cells) whose
fronts either cover the board edges ("overlay") or sit in front of the openings only
("framed"). Every drawer and door leaf is its own link with a joint; the placeholder is the
carcass boards plus one block per closed row (fronts and handles included), so open shelves stay
open for the solver. `CaseFactory` is the generators' skeleton.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Surface
from indoorgen.assets.shapes.frames import frame, legs
from indoorgen.assets.shapes.moving_parts import (
    DOOR_OPEN,
    FRONT_T,
    HANDLE_STANDOFF,
    MOVING_GAP,
    REVEAL,
    DoorJoint,
    drawer,
    drawer_floor,
    hinged_door,
    make_joint,
)
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_rect
from indoorgen.model.tags import Subpart


@dataclass(frozen=True)
class Row:
    """One horizontal band of a case: `kind` "drawer", "door" or "open", a share `weight` of the
    interior height, `n` drawers / doors / open cells side by side, and whether physical
    dividers separate them (always for drawers and open cells)."""

    kind: str
    weight: float
    n: int = 1
    dividers: bool = True


@dataclass(frozen=True)
class Cell:
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
class Case:
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
        """The x of the carcass front (fronts stand in front of it)."""
        return self.D / 2

    def inner(self) -> tuple[float, float]:
        """The y range between the two sides."""
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


def case_layout(W: float, D: float, t: float, back: float, z_bot: float, z_top: float,
                 rows: Sequence[Row], overlay: bool, door_dividers: Sequence[float] = ()) -> Case:
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
                cells.append(Cell(y0, y1, z0, z1, fy0, fy1, fz0, fz1, kind, ri))
        elif row.kind == "door":
            for yd in door_dividers:
                boards.append(box_between((xb, yd - t / 2, z0 - o), (d2, yd + t / 2, z1 + o)))
            fy0, fy1 = (-w2, w2) if overlay else (yi0, yi1)
            step = (fy1 - fy0) / row.n
            for j, hinge in enumerate(_door_hinges(row.n)):
                a, b = fy0 + j * step, fy0 + (j + 1) * step
                cells.append(Cell(max(a, yi0), min(b, yi1), z0, z1, a, b, fz0, fz1, hinge, ri))
        else:
            fy0, fy1 = (-w2, w2) if overlay else (yi0, yi1)
            cells.append(Cell(yi0, yi1, z0, z1, fy0, fy1, fz0, fz1,
                               "drawer" if row.kind == "drawer" else "open", ri))
        z = z1 + t
    return Case(W, D, t, back, z_bot, z_top, boards, cells, zrows)


def front_decor(x1: float, y0: float, y1: float, z0: float, z1: float, style: str,
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
        parts += front_decor(x1, y0, y1, z0, z1, style, link)
    return parts, motion


def case_fronts(case: Case, handle: str, style: str, drawer_depth: float | None = None,
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
            parts += front_decor(x0 + FRONT_T, fy0, fy1, fz0, fz1,
                                  "shaker" if style in ("shaker", "glass") else "flat", link)
            out.append((parts, motion))
        else:
            out.append(_door(fx, fy0, fy1, fz0, fz1, c.kind, f"door_{i}", handle, style))
    return out


def _case_blocks(case: Case, x_front: float) -> list[Part]:
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


def case_body(case: Case, detail: bool, x_front: float) -> list[Part]:
    """The case's boards (detail), or its placeholder: one block to `x_front` when every row is
    closed, else the boards plus one block per closed row."""
    if detail or any(row.kind == "open" for row, _, _ in case.rows):
        out = [Part(b, "back" if i == 3 else "wood") for i, b in enumerate(case.boards)]
        return out if detail else out + _case_blocks(case, x_front)
    return [Part(box_between((-case.D / 2, -case.W / 2, case.z_bot),
                             (x_front, case.W / 2, case.z_top + OVERLAP)), "front")]


def front_proud(handle: str) -> float:
    """How far a case's fronts with `handle`s stand in front of the carcass (m)."""
    return MOVING_GAP + FRONT_T + HANDLE_STANDOFF[handle]


def case_joints(fronts: list[tuple[list[Part], DoorJoint]], drawer_travel: float) -> list[Joint]:
    """A joint per front: doors swing to DOOR_OPEN, drawers slide out by `drawer_travel`."""
    return [make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN) if m.kind == "revolute"
            else make_joint(f"{m.link}_joint", m, 0.0, drawer_travel) for _, m in fronts]


def case_base(D: float, W: float, zb: float, style: str, detail: bool, leg: float = 0.04,
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


def base_bottom(D: float, W: float, style: str) -> Surface:
    """The `bottom`: the plinth's footprint (set back like the plinth) or the whole box's."""
    if style == "plinth":
        return bottom_rect((-0.015, 0, 0), D / 2 - 0.015 - 0.0005, W / 2 - 0.01 - 0.0005)
    return bottom_rect((0, 0, 0), D / 2, W / 2)


def top_board(D: float, W: float, z: float, tt: float, overhang: float, detail: bool,
               radius: float = 0.004) -> Part:
    """A top board flush with the back, overhanging the front and sides by `overhang`."""
    ext = (D + overhang, W + 2 * overhang, tt)
    c = (overhang / 2, 0.0, z + tt / 2)
    return Part(bevel_box(ext, c, radius, 2) if detail else box(ext, c), "wood")


def top_surface(D: float, W: float, H: float, overhang: float) -> Surface:
    """The `top` support surface on a top board overhanging by `overhang`, 2 cm in from its edge."""
    return support_rect("top", (overhang / 2, 0, H), (D + overhang) / 2 - 0.02,
                        W / 2 + overhang - 0.02)


def back_surface(W: float, z0: float, z1: float, D: float) -> Surface:
    """The carcass back (x = -D/2) over its height: what stands against the wall."""
    return Surface.rect("back", Subpart.Back, (-D / 2, 0, (z0 + z1) / 2), (-1, 0, 0), (0, 1, 0),
                        W / 2, (z1 - z0) / 2)


def interior_surface(name: str, case: Case, y0: float, y1: float, z: float) -> Surface:
    """An Interior surface (upward) on a board top at z inside the case, between y0 and y1."""
    x0, x1 = -case.D / 2 + case.back, case.D / 2 - 0.01
    return Surface.rect(name, Subpart.Interior, ((x0 + x1) / 2, (y0 + y1) / 2, z), (0, 0, 1),
                        (1, 0, 0), (x1 - x0) / 2 - 0.01, (y1 - y0) / 2 - 0.01)


def shelf_board(case: Case, y0: float, y1: float, z: float) -> Part:
    """A fixed shelf whose upper face is at z, from the back panel to 1 cm short of the front."""
    o = OVERLAP
    return Part(box_between((-case.D / 2 + case.back - o, y0 - o, z - case.t),
                            (case.D / 2 - 0.01, y1 + o, z)), "wood")


def shelf_heights(z0: float, z1: float, n: int, t: float, min_clear: float) -> list[float]:
    """Upper faces of up to n evenly spaced shelves between z0 and z1, as many as keep
    `min_clear` between them."""
    while n > 0 and (z1 - z0 - n * t) / (n + 1) < min_clear:
        n -= 1
    step = (z1 - z0 - n * t) / (n + 1)
    return [z0 + (i + 1) * step + (i + 1) * t for i in range(n)]


class CaseFactory(PartsFactory):
    """Shared skeleton of the case-built generators: subclasses return the layout."""

    slots = ["wood", "front", "metal", "back", "glass", "mirror"]

    def layout(self, p: dict[str, Any]) -> Case:
        """The case for resolved params `p`."""
        raise NotImplementedError

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """Whether the case stands on a plinth (its footprint rests on mesh)."""
        return self.resolve(params).get("base_style") == "plinth"

    def drawer_floors(self, case: Case) -> list[Surface]:
        """Each drawer's floor (`drawer_<i>_floor`), an Interior surface moving with its drawer."""
        depth, r = self.drawer_depth(case), REVEAL
        return [drawer_floor(f"drawer_{i}_floor", case.front_x, c.y0 + r, c.y1 - r, c.z0 + r,
                             depth, f"drawer_{i}")
                for i, c in enumerate(case.cells) if c.kind == "drawer"]

    def drawer_depth(self, case: Case) -> float:
        """How deep the drawers reach into the case (back panel and 2 cm clear)."""
        return case.D - case.back - 0.02

    def fronts(self, p: dict[str, Any]) -> list[tuple[list[Part], DoorJoint]]:
        """The doors and drawers of the case's cells, each on its own link."""
        case = self.layout(p)
        return case_fronts(case, p["handle"], p.get("door_style", "flat"), self.drawer_depth(case))

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """A joint per front: doors swing, drawers slide out to 80% of their depth."""
        case = self.layout(p)
        return case_joints(self.fronts(p), 0.8 * self.drawer_depth(case))

    def _interior_parts(self, p: dict[str, Any], case: Case) -> list[Part]:
        """Fixed pieces inside the case (shelves, a rail), detailed asset only; none here."""
        return []

    def _topped_case(self, p: dict[str, Any], detail: bool, zb: float, leg: float = 0.04) -> list[Part]:
        """The parts of a case under a top board that stands `zb` high on `base_style`: the
        carcass (placeholder: its blocks), the top, the base, and in the detailed asset the
        interior pieces and every front."""
        case = self.layout(p)
        W, D, t = p["width"], p["depth"], p["board_thickness"]
        out = case_body(case, detail, D / 2 + front_proud(p["handle"]))
        out.append(top_board(D, W, case.z_top - OVERLAP, t + OVERLAP, p["top_overhang"], detail))
        out += case_base(D, W, zb, p["base_style"], detail, leg=leg)
        if detail:
            out += self._interior_parts(p, case)
            out += [q for parts, _ in self.fronts(p) for q in parts]
        return out
