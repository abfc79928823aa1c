"""Open shelving: bookcases, cube storage (cell shelves), wall shelves, corner shelves and shoe
racks. Every shelf, cell floor or tier top is a support surface."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import legs
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

MIN_SHELF_CLEARANCE = 0.25  # books up to ~24 cm tall fit on every shelf


def bookcase_levels(p: dict[str, Any]) -> tuple[int, float, float]:
    """(number of shelf levels, clearance between them, top of the bottom board). Levels are
    `n_shelves` reduced until each gets >= 25 cm of clearance (the height range ensures >= 3)."""
    H, t, ph = p["height"], p["board_thickness"], p["plinth_height"]
    z_b = ph + t
    k = int(p["n_shelves"])
    while k > 1:
        clear = (H - t - z_b - (k - 1) * t) / k
        if clear >= MIN_SHELF_CLEARANCE:
            break
        k -= 1
    clear = (H - t - z_b - (k - 1) * t) / k
    return k, clear, z_b


@register
class Bookcase(PartsFactory):
    """An open bookcase: sides, back panel, top, a solid plinth and 3-6 shelf levels, each a
    support surface `shelf_i` (shelf_0 = the bottom board)."""

    name = "bookcase"
    tags = frozenset({S.Object, S.Furniture, S.Storage, S.Bookcase})
    size_class = "large"
    slots = ["wood", "back"]
    solid_bottom = True
    params = {
        "width": Param(0.6, 1.2, doc="Y extent (m)"),
        "depth": Param(0.25, 0.4, doc="X extent (m)"),
        "height": Param(0.95, 2.1, doc="Z extent (m)"),
        "board_thickness": Param(0.016, 0.025, doc="board thickness (m)"),
        "n_shelves": Param(3, 6, kind="int",
                           doc="shelf levels incl. the bottom board; reduced if the height cannot "
                               "give each >= 0.25 m of clearance"),
        "plinth_height": Param(0.04, 0.1, doc="plinth height under the bottom board (m)"),
        "back_thickness": Param(0.004, 0.012, doc="back panel thickness (m)"),
        "shelf_setback": Param(0.0, 0.02, doc="how far shelves stop short of the front (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Top, back, plinth, sides and shelf boards."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        bt, sb = p["back_thickness"], p["shelf_setback"]
        k, clear, z_b = bookcase_levels(p)
        out: list[Part] = [
            Part(box_between((-D / 2, -W / 2, H - t), (D / 2, W / 2, H)), "wood"),  # top
            Part(box_between((-D / 2, -W / 2, 0.0), (-D / 2 + bt, W / 2, H - t + OVERLAP)), "back"),
            Part(box_between((-D / 2 + bt - OVERLAP, -W / 2 + t - OVERLAP, 0.0),
                             (D / 2, W / 2 - t + OVERLAP, p["plinth_height"] + OVERLAP)), "wood"),
        ]
        for s in (-1, 1):
            out.append(Part(box_between((-D / 2 + bt - OVERLAP, min(s * W / 2, s * (W / 2 - t)), 0.0),
                                        (D / 2, max(s * W / 2, s * (W / 2 - t)), H - t + OVERLAP)), "wood"))
        for i in range(k):
            zt = z_b + i * (clear + t)
            x1 = D / 2 if i == 0 else D / 2 - sb
            out.append(Part(box_between((-D / 2 + bt - OVERLAP, -W / 2 + t - OVERLAP, zt - t),
                                        (x1, W / 2 - t + OVERLAP, zt)), "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and each shelf level (`shelf_i`)."""
        W, D, H, t = p["width"], p["depth"], p["height"], p["board_thickness"]
        bt, sb = p["back_thickness"], p["shelf_setback"]
        k, clear, z_b = bookcase_levels(p)
        out = [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02)]
        iw = W - 2 * t
        for i in range(k):
            zt = z_b + i * (clear + t)
            x0, x1 = -D / 2 + bt, (D / 2 if i == 0 else D / 2 - sb)
            out.append(support_rect(f"shelf_{i}", ((x0 + x1) / 2, 0, zt), (x1 - x0 - 0.02) / 2,
                                    (iw - 0.02) / 2))
        return out


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

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """Whether it stands on its frame or a plinth (not on legs)."""
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The frame with its cells cut out (placeholder: its boards), back and base."""
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
            out.append(Part(box_between((-d2, -w2 + to - o, zb + to - o),
                                        (-d2 + bp, w2 - to + o, H - to + o)), "back"))
        if p["base_style"] == "plinth":
            out.append(Part(box_between((-d2, -w2 + 0.01, 0.0), (d2 - 0.03, w2 - 0.01, zb + o)), "wood"))
        elif p["base_style"] == "legs":
            out += [Part(lg, "metal") for lg in legs((D, W), 0.02, 0.04, 0.0, zb + o, round_legs=True,
                                                     circumscribed=not detail,
                                                     sections=16 if detail else 8)]
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The `top` and every cell floor (`cell_<row>_<col>`)."""
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The boards and their back panel, side boards or brackets and track."""
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
            boxed_end = st == "boxed" and i in (0, len(zs) - 1)  # a box's bottom and top: full width
            y_a = w2 if boxed_end else y_end + (o if st == "boxed" else 0.0)
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Every board top (`shelf_i`) and the flat `back` on the wall."""
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Two wall panels and the shelves, with aprons if asked."""
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Every shelf top (`shelf_i`), inset from its outline."""
        poly = self._shelf_polygon(p).buffer(-0.015, join_style="mitre")
        poly = sg.Polygon(np.asarray(poly.exterior.coords))
        return [support_polygon(f"shelf_{i}", (0, 0, z), poly) for i, z in enumerate(self._levels(p))]


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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Side panels or corner posts and the tiers (slats cut from one board)."""
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
        return [(a[1], b[0], -yi + self.RAIL, yi - self.RAIL) for a, b in zip(sl, sl[1:], strict=False)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """Every tier top (`tier_i`), the gaps between slats as holes."""
        D = p["depth"]
        yi = self._inner(p)
        m = 0.005
        outer = [(-D / 2 + m, -yi + m), (D / 2 - m, -yi + m), (D / 2 - m, yi - m), (-D / 2 + m, yi - m)]
        holes = []
        if p["tier_style"] == "slats":
            holes = [[(a, ya), (b, ya), (b, yb), (a, yb)] for a, b, ya, yb in self._gaps(p)]
        poly = sg.Polygon(outer, holes)
        return [support_polygon(f"tier_{i}", (0, 0, z), poly) for i, z in enumerate(self._levels(p))]
