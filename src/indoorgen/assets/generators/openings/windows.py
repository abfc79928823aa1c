"""Windows: casement, sliding, awning and fixed windows, and a bay window.

Frame conventions (see shapes/architectural.py): the wall is the YZ plane centred on x=0, +X the
room, -X the outside; the window's width runs along Y and its rough opening's bottom is at z=0
(the caller lifts it to the sill height). The window frame sits near the outside face; lining boards
wrap the rest of the wall thickness, an interior sill board (stool) and architraves finish the
room side. Hinged sashes open outward (-X), about their outer edge.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.architectural import (
    CASING_REVEAL,
    LEAF_GAP,
    MEMBER_OVERLAP,
    casing,
    glazed_sash,
    hull,
    opening_surface,
    prism,
    ring,
)
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import DoorJoint, bar_handle, make_joint
from indoorgen.assets.shapes.primitives import Part, box_between, rod
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
from indoorgen.model.tags import Semantics as S

#: lining board thickness (m)
LINING = 0.015
#: interior sill board (stool) thickness (m)
STOOL = 0.025
#: architrave thickness (m)
CASING_T = 0.018
#: how far the stool's ends (horns) reach past the architraves (m)
HORN = 0.015
#: width of the stop lip a hinged sash closes against (m)
STOP = 0.006
#: smallest lite between glazing bars (m)
MIN_LITE = 0.2

WINDOW_MATERIALS = {"frame": {"painted_wood": 3.0, "oak": 1.0, "painted_metal": 1.5,
                              "matte_plastic": 1.5, "brushed_steel": 0.5},
                    "wood": {"painted_wood": 2.0, "oak": 2.0, "walnut": 1.0, "marble": 0.7},
                    "stone": {"slate": 1.0, "granite": 1.0, "concrete": 1.0, "marble": 0.5},
                    "handle": {"brushed_steel": 2.0, "chrome": 1.0, "brass": 1.0, "matte_plastic": 1.0}}


def _grid(n: int, span: float) -> int:
    """Glazing bars can split `span` into at most this many lites of MIN_LITE."""
    return max(1, min(n, int(span / MIN_LITE)))


@register
class Window(PartsFactory):
    """A window in a wall: the frame near the outside face with mullions between 1-3 columns,
    lining boards across the wall, an interior sill board (surface ``sill``), architraves and an
    optional sloped exterior sill. Styles: casement (side-hung sashes opening outward, revolute;
    with three columns the middle one is fixed), sliding (sashes in two tracks, the operable
    ones on prismatic joints along Y), awning (top-hung sashes opening outward) and fixed
    (glazed in the frame). Panes are real 6 mm solids divided by glazing bars.
    Surfaces: ``opening`` (the rough opening; see shapes.architectural.opening_size) and ``sill``."""

    name = "window"
    tags = frozenset({S.Object, S.Architecture, S.Window})
    size_class = "large"
    slots = ["frame", "glass", "wood", "handle", "stone"]
    material_choices = WINDOW_MATERIALS
    params = {
        "width": Param(0.5, 2.4, doc="rough opening width (m)"),
        "height": Param(0.5, 1.6, doc="rough opening height (m)"),
        "wall_thickness": Param(0.1, 0.35, doc="wall thickness the lining spans (m)"),
        "style": Param(kind="choice", choices=("casement", "sliding", "awning", "fixed"),
                       doc="how the sashes open"),
        "n_sashes": Param(1, 3, kind="int", doc="columns of sashes (reduced on narrow windows; "
                                                "sliding windows have 2 or 3)"),
        "grid_rows": Param(1, 3, kind="int", doc="rows of lites per pane (glazing bars)"),
        "grid_cols": Param(1, 3, kind="int", doc="columns of lites per pane"),
        "frame_width": Param(0.04, 0.08, doc="frame and mullion face width (m)"),
        "sash_width": Param(0.045, 0.07, doc="sash stile and rail width (m)"),
        "exterior_sill": Param(kind="bool", doc="a sloped sill projecting outside"),
        "sill_projection": Param(0.02, 0.06, doc="how far the interior sill projects from the wall (m)"),
        "casing_width": Param(0.05, 0.1, doc="architrave face width (m)"),
        "hinge_side": Param(kind="choice", choices=("left", "right"),
                            doc="hinge side of a single casement / side of the sliding sash"),
    }

    # ---- layout
    def _g(self, p: dict[str, Any]) -> dict[str, Any]:
        W, H, T = p["width"], p["height"], p["wall_thickness"]
        style, fw = p["style"], p["frame_width"]
        fd = min(0.09 if style == "sliding" else 0.07, T - 0.01)
        xf0 = -T / 2 + min(0.03, max(0.0, (T - fd) * 0.4))
        xf1 = xf0 + fd
        Y0, Y1 = -W / 2 + LINING + fw, W / 2 - LINING - fw
        Z0, Z1 = STOOL + fw, H - LINING - fw
        if style == "sliding":
            n = 3 if (p["n_sashes"] >= 3 and Y1 - Y0 >= 1.3) else 2
        else:
            n = max(1, min(int(p["n_sashes"]), int((Y1 - Y0 + fw) / 0.4)))
        cw = (Y1 - Y0 - (n - 1) * fw) / n
        cols = [(Y0 + i * (cw + fw), Y0 + i * (cw + fw) + cw) for i in range(n)]
        sd = min(0.05, fd - LEAF_GAP - 0.012)
        sd2 = (fd - 0.024 - 4 * LEAF_GAP) / 2
        tracks = (xf0 + 0.008 + LEAF_GAP, xf0 + 0.016 + 3 * LEAF_GAP + sd2)  # sash A and B low x
        tip = {"casement": xf0 + sd + 0.037, "awning": xf0 + sd + 0.037,
               "sliding": tracks[1] + sd2 + 0.022, "fixed": xf1}[style]
        R = max(T / 2 + max(p["sill_projection"], CASING_T + 0.01), tip + 0.005)
        return {"W": W, "H": H, "T": T, "fd": fd, "xf0": xf0, "xf1": xf1, "Y0": Y0, "Y1": Y1,
                "Z0": Z0, "Z1": Z1, "n": n, "cols": cols, "sd": sd, "sd2": sd2, "tracks": tracks,
                "R": R, "ct_ex": CASING_T if p["exterior_sill"] else R - T / 2,
                "cy": W / 2 - LINING + CASING_REVEAL, "cz": H - LINING + CASING_REVEAL}

    def _moving(self, p, g) -> list[int]:
        """Indices of the columns (casement, awning) or sashes (sliding) that move."""
        if p["style"] in ("casement", "awning"):
            return [i for i in range(g["n"]) if not (p["style"] == "casement" and g["n"] == 3 and i == 1)]
        if p["style"] == "sliding":
            return [0, 2] if g["n"] == 3 else [0]
        return []

    # ---- parts
    def parts(self, p, detail):
        """The window's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        if not detail:
            half_w = g["cy"] + p["casing_width"] + HORN
            return [Part(box_between((-g["R"], -half_w, 0.0), (g["R"], half_w, g["cz"] + p["casing_width"])),
                         "frame")]
        out = self._surround(p, g)
        style = p["style"]
        if style == "sliding":
            out += self._sliding(p, g)
        else:
            out += self._columns(p, g)
        return out

    def _surround(self, p, g) -> list[Part]:
        """Linings, frame and mullions, stool, architraves and the exterior sill or trim."""
        W, H, T, R, fw = g["W"], g["H"], g["T"], g["R"], p["frame_width"]
        cw, cy, cz = p["casing_width"], g["cy"], g["cz"]
        half_w = cy + cw + HORN
        ext = p["exterior_sill"]
        x_stool = g["xf0"] if ext else -T / 2
        wood = [box_between((x_stool, -W / 2, 0.0), (T / 2, W / 2, STOOL)),
                box_between((T / 2 - MEMBER_OVERLAP, -half_w, 0.0), (R, half_w, STOOL))]
        lining = [box_between((-T / 2, -W / 2, STOOL - MEMBER_OVERLAP),
                              (T / 2, -W / 2 + LINING, H - LINING + MEMBER_OVERLAP)),
                  box_between((-T / 2, W / 2 - LINING, STOOL - MEMBER_OVERLAP),
                              (T / 2, W / 2, H - LINING + MEMBER_OVERLAP)),
                  box_between((-T / 2, -W / 2, H - LINING), (T / 2, W / 2, H))]
        frame = [ring(-W / 2 + LINING - MEMBER_OVERLAP, W / 2 - LINING + MEMBER_OVERLAP,
                      STOOL - MEMBER_OVERLAP, H - LINING + MEMBER_OVERLAP,
                      g["xf0"], g["xf1"], fw + MEMBER_OVERLAP)]
        mullions = [] if p["style"] == "sliding" else zip(g["cols"][:-1], g["cols"][1:], strict=True)
        for (_, a1), (b0, _) in mullions:
            # set 3 mm back from both frame faces: no faces flush with the frame's
            frame.append(box_between((g["xf0"] + 0.003, a1 - MEMBER_OVERLAP, g["Z0"] - MEMBER_OVERLAP),
                                     (g["xf1"] - 0.003, b0 + MEMBER_OVERLAP, g["Z1"] + MEMBER_OVERLAP)))
        trims = casing(T / 2, 1, -cy, cy, STOOL - MEMBER_OVERLAP, cz, cw, CASING_T, True)
        out = [Part(s, "wood") for s in wood] + [Part(s, "frame") for s in lining + frame + trims]
        z_ex = 0.0
        if ext:
            x_in = g["xf0"] + MEMBER_OVERLAP

            def top(x: float) -> float:  # the sill's upper face slopes down outward
                return STOOL * (0.55 + 0.45 * (x + R) / (x_in + R))

            for xa, xb, hw in ((-T / 2, x_in, W / 2), (-R, -T / 2 + MEMBER_OVERLAP, half_w)):
                out.append(Part(prism([(xa, 0.0), (xb, 0.0), (xb, top(xb)), (xa, top(xa))], -hw, hw, "y"),
                                "stone"))
            z_ex = top(-T / 2 - g["ct_ex"]) - MEMBER_OVERLAP
        out += [Part(s, "frame") for s in casing(-T / 2, -1, -cy, cy, z_ex, cz, cw, g["ct_ex"], True)]
        return out

    def _columns(self, p, g) -> list[Part]:
        """Casement / awning sashes or fixed panes, one per column."""
        out: list[Part] = []
        moving = self._moving(p, g)
        xf0, xf1, sd, sw = g["xf0"], g["xf1"], g["sd"], p["sash_width"]
        Z0, Z1 = g["Z0"], g["Z1"]
        rows = _grid(int(p["grid_rows"]), Z1 - Z0)
        for i, (c0, c1) in enumerate(g["cols"]):
            cols = _grid(int(p["grid_cols"]), c1 - c0)
            if i in moving:
                link = f"sash_{i}"
                out += glazed_sash(xf0, xf0 + sd, *self._sash_box(p, g, i), sw, cols, rows, link)
                out.append(Part(ring(c0 - MEMBER_OVERLAP, c1 + MEMBER_OVERLAP, Z0 - MEMBER_OVERLAP,
                                     Z1 + MEMBER_OVERLAP, xf0 + sd + LEAF_GAP, xf1, STOP + MEMBER_OVERLAP),
                                "frame"))
                out.append(Part(self._handle(p, g, i), "handle", link))
            elif p["style"] == "fixed":  # glazed into the frame between beads
                xm = (xf0 + xf1) / 2  # (sunk 2 mm into the frame: no face flush with a mullion's)
                out += glazed_sash(xm - 0.015, xm + 0.015, c0 - 2 * MEMBER_OVERLAP, c1 + 2 * MEMBER_OVERLAP,
                                   Z0 - 2 * MEMBER_OVERLAP, Z1 + 2 * MEMBER_OVERLAP,
                                   0.015 + 2 * MEMBER_OVERLAP, cols, rows, "base")
            else:  # the fixed middle light of a three-column casement
                out += glazed_sash(xf0, xf0 + sd, c0 - 2 * MEMBER_OVERLAP, c1 + 2 * MEMBER_OVERLAP,
                                   Z0 - 2 * MEMBER_OVERLAP, Z1 + 2 * MEMBER_OVERLAP, sw, cols, rows, "base")
        return out

    def _hinge(self, p, g, i: int) -> str:
        if p["style"] == "awning":
            return "top"
        if g["n"] == 1:
            return p["hinge_side"]
        return "left" if i == 0 else "right"

    def _sash_box(self, p, g, i: int) -> tuple[float, float, float, float]:
        """The extent (y0, y1, z0, z1) of the hinged sash in column i: LEAF_GAP inside the frame, more
        on the side that swings away from the hinge, whose inner corner first moves toward the
        frame by up to depth^2 / (2 span) as the sash opens."""
        c0, c1 = g["cols"][i]
        hinge = self._hinge(p, g, i)
        span = (g["Z1"] - g["Z0"]) if hinge == "top" else (c1 - c0)
        free = max(LEAF_GAP, g["sd"] ** 2 / (2 * (span - 2 * LEAF_GAP)) + 0.0015)
        y0, y1, z0, z1 = c0 + LEAF_GAP, c1 - LEAF_GAP, g["Z0"] + LEAF_GAP, g["Z1"] - LEAF_GAP
        if hinge == "top":
            z0 = g["Z0"] + free
        elif hinge == "left":
            y1 = c1 - free
        else:
            y0 = c0 + free
        return y0, y1, z0, z1

    def _handle(self, p, g, i: int) -> m3d.Manifold:
        """A small lever on the sash's room face: on the latch stile (casement, arm down) or the
        bottom rail (awning, arm sideways)."""
        y0, y1, z0, z1 = self._sash_box(p, g, i)
        x1, sw = g["xf0"] + g["sd"], p["sash_width"]
        hinge = self._hinge(p, g, i)
        if hinge == "top":
            y, z = (y0 + y1) / 2, z0 + sw / 2
            arm = box_between((x1 + 0.025, y - 0.005, z - 0.006), (x1 + 0.037, y + 0.07, z + 0.006))
        else:
            y = y1 - sw / 2 if hinge == "left" else y0 + sw / 2
            z = (z0 + z1) / 2
            arm = box_between((x1 + 0.025, y - 0.006, z - 0.09), (x1 + 0.037, y + 0.006, z + 0.008))
        return solid_union([rod((x1 - MEMBER_OVERLAP, y, z), (x1 + 0.01, y, z), 0.011, 12),
                            box_between((x1 + 0.008, y - 0.006, z - 0.008),
                                        (x1 + 0.03, y + 0.006, z + 0.008)), arm])

    def _sliding_layout(self, p, g) -> list[tuple[float, float, str, float]]:
        """Sashes (y0, y1, track "A" fixed outside / "B" sliding inside, direction of opening)."""
        Y0, Y1, ov = g["Y0"], g["Y1"], 0.03
        if g["n"] == 3:
            L = (Y1 - Y0) / 3
            return [(Y0 + LEAF_GAP, Y0 + L + ov, "B", 1.0), (Y0 + L - ov, Y1 - L + ov, "A", 0.0),
                    (Y1 - L - ov, Y1 - LEAF_GAP, "B", -1.0)]
        ym = (Y0 + Y1) / 2
        if p["hinge_side"] == "left":
            return [(Y0 + LEAF_GAP, ym + ov, "B", 1.0), (ym - ov, Y1 + MEMBER_OVERLAP, "A", 0.0)]
        return [(ym - ov, Y1 - LEAF_GAP, "B", -1.0), (Y0 - MEMBER_OVERLAP, ym + ov, "A", 0.0)]

    def _travel(self, p, g) -> float:
        if g["n"] == 3:
            return 0.45 * (g["Y1"] - g["Y0"]) / 3
        return 0.9 * ((g["Y1"] - g["Y0"]) / 2 - 0.03 - 2 * LEAF_GAP)

    def _sliding(self, p, g) -> list[Part]:
        """Two tracks between lips on the head and sill: a fixed sash outside, the sliding
        sash(es) inside, each with a pull."""
        out: list[Part] = []
        xf0, xf1, sd2 = g["xf0"], g["xf1"], g["sd2"]
        Y0, Y1, Z0, Z1, sw = g["Y0"], g["Y1"], g["Z0"], g["Z1"], p["sash_width"]
        xa, xb = g["tracks"]
        lips = [(xf0, xf0 + 0.008), (xa + sd2 + LEAF_GAP, xb - LEAF_GAP), (xb + sd2 + LEAF_GAP, xf1)]
        for l0, l1 in lips:
            for za, zb in ((Z0 - MEMBER_OVERLAP, Z0 + 0.012), (Z1 - 0.012, Z1 + MEMBER_OVERLAP)):
                out.append(Part(box_between((l0, Y0 - MEMBER_OVERLAP, za), (l1, Y1 + MEMBER_OVERLAP, zb)),
                                "frame"))
        rows = _grid(int(p["grid_rows"]), Z1 - Z0)
        for i, (y0, y1, track, direction) in enumerate(self._sliding_layout(p, g)):
            cols = _grid(int(p["grid_cols"]), y1 - y0)
            if track == "A":
                out += glazed_sash(xa, xa + sd2, y0, y1, Z0 - MEMBER_OVERLAP, Z1 + MEMBER_OVERLAP, sw, cols,
                                   rows, "base")
                continue
            link = f"sash_{i}"
            out += glazed_sash(xb, xb + sd2, y0, y1, Z0 + LEAF_GAP, Z1 - LEAF_GAP, sw, cols, rows, link)
            yh = y0 + sw / 2 if direction > 0 else y1 - sw / 2
            out.append(Part(bar_handle((xb + sd2, yh, (Z0 + Z1) / 2), min(0.16, 0.4 * (Z1 - Z0)), True,
                                       0.022, 0.012), "handle", link))
        return out

    # ---- joints and surfaces
    def joints(self, p):
        """The window's joints, one per opening sash (sash_<i>_joint)."""
        g = self._g(p)
        out = []
        if p["style"] == "sliding":
            travel = self._travel(p, g)
            for i, (y0, y1, track, direction) in enumerate(self._sliding_layout(p, g)):
                if track == "B":
                    m = DoorJoint("prismatic", np.array([0.0, direction, 0.0]),
                                  np.array([g["tracks"][1], (y0 + y1) / 2, g["Z0"]]), f"sash_{i}")
                    out.append(make_joint(f"sash_{i}_joint", m, 0.0, travel))
            return out
        xf0 = g["xf0"]
        for i in self._moving(p, g):
            y0, y1, _, z1 = self._sash_box(p, g, i)
            hinge = self._hinge(p, g, i)
            if hinge == "top":
                m = DoorJoint("revolute", np.array([0.0, 1.0, 0.0]), np.array([xf0, y0, z1]), f"sash_{i}")
                upper = math.radians(50.0)
            elif hinge == "left":
                m = DoorJoint("revolute", np.array([0.0, 0.0, 1.0]), np.array([xf0, y0, 0.0]), f"sash_{i}")
                upper = math.pi / 2
            else:
                m = DoorJoint("revolute", np.array([0.0, 0.0, -1.0]), np.array([xf0, y1, 0.0]), f"sash_{i}")
                upper = math.pi / 2
            out.append(make_joint(f"sash_{i}_joint", m, 0.0, upper))
        return out

    def extra_surfaces(self, p):
        """The window's surfaces besides its bounding box's: opening, sill."""
        g = self._g(p)
        x0, x1 = g["xf1"] + 0.01, g["R"] - 0.005
        hw = g["W"] / 2 - LINING - 0.01
        return [opening_surface(-g["W"] / 2, g["W"] / 2, 0.0, g["H"]),
                support_rect("sill", ((x0 + x1) / 2, 0.0, STOOL), (x1 - x0) / 2, hw)]


# ----------------------------------------------------------------------------- bay window
@register
class BayWindow(PartsFactory):
    """A three-sided bay window projecting outward (-X) from the wall: a front of 1-3 lites and
    two angled (or square) side lites in a frame with corner posts, an optional transom bar,
    a deep board across the bay's floor reaching into the room as a seat or sill (surface
    ``seat``), a head board, a hipped or flat roof outside, lining and architraves. The bay makes
    the bounding box asymmetric: the ``opening`` surface marks the wall's centre plane."""

    name = "bay_window"
    tags = frozenset({S.Object, S.Architecture, S.Window})
    size_class = "large"
    slots = ["frame", "glass", "wood", "stone"]
    material_choices = {**WINDOW_MATERIALS, "stone": {"slate": 2.0, "painted_metal": 1.0, "concrete": 0.5}}
    params = {
        "width": Param(1.4, 3.0, doc="rough opening width at the wall (m)"),
        "height": Param(1.0, 1.8, doc="rough opening height (m)"),
        "depth": Param(0.35, 0.75, doc="projection beyond the wall's outer face (m; reduced so "
                                       "the front stays >= 0.6 m wide)"),
        "side_angle": Param(40.0, 90.0, doc="angle between the side lites and the wall (degrees)"),
        "wall_thickness": Param(0.15, 0.35, doc="wall thickness (m)"),
        "n_front_lites": Param(1, 3, kind="int", doc="lites across the front"),
        "transom": Param(kind="bool", doc="a transom bar across every lite near the top"),
        "frame_width": Param(0.05, 0.08, doc="frame member face width (m)"),
        "seat_overhang": Param(0.02, 0.35, doc="how far the board reaches into the room (m)"),
        "roof_style": Param(kind="choice", choices=("hipped", "flat"), doc="the bay's roof"),
        "casing_width": Param(0.06, 0.1, doc="architrave face width (m)"),
    }

    BOARD = 0.03
    FRAME_D = 0.07
    EAVE = 0.05

    def _g(self, p) -> dict[str, Any]:
        W, H, T = p["width"], p["height"], p["wall_thickness"]
        a = math.radians(p["side_angle"])
        D = p["depth"]
        inset = 0.0
        if p["side_angle"] < 89.9:
            D = min(D, (W - 0.6) * math.tan(a) / 2)
            inset = D / math.tan(a)
        xo = -T / 2
        pts = [(xo, -W / 2), (xo - D, -W / 2 + inset), (xo - D, W / 2 - inset), (xo, W / 2)]
        roof_h = (0.06 + (D + self.EAVE) * math.tan(math.radians(28.0)) if p["roof_style"] == "hipped"
                  else 0.09)
        return {"W": W, "H": H, "T": T, "D": D, "pts": np.array(pts), "roof_h": roof_h,
                "cy": W / 2 - LINING + CASING_REVEAL, "cz": H - self.BOARD + CASING_REVEAL}

    def _outside(self, g, grow: float) -> sg.Polygon:
        """The bay's plan outside the wall face, grown by `grow` beyond its glazing."""
        T = g["T"]
        poly = sg.Polygon(np.vstack([g["pts"], [(-T / 2 + 0.5, g["W"] / 2), (-T / 2 + 0.5, -g["W"] / 2)]]))
        grown = poly.buffer(grow, join_style=2)
        return grown.intersection(sg.box(-10.0, -10.0, -T / 2, 10.0))

    def parts(self, p, detail):
        """The bay window's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        W, H, T = g["W"], g["H"], g["T"]
        cw = p["casing_width"]
        half_w = g["cy"] + cw + 0.02
        x_room = T / 2 + max(p["seat_overhang"], CASING_T)
        if not detail:
            outer = np.asarray(self._outside(g, self.EAVE).exterior.coords)[:-1]
            top = H + g["roof_h"]
            pts = [(x, y, z) for x, y in outer for z in (0.0, top)]
            return [Part(hull(pts), "frame"),
                    Part(box_between((-T / 2 - MEMBER_OVERLAP, -half_w, 0.0),
                                     (x_room, half_w, g["cz"] + cw)), "wood")]
        head_outline = self._outside(g, 0.03).union(sg.box(-T / 2 - MEMBER_OVERLAP, -W / 2, T / 2, W / 2))
        board_outline = head_outline.union(sg.box(T / 2 - MEMBER_OVERLAP, -half_w, x_room, half_w))
        out = [Part(prism(_coords(board_outline), 0.0, self.BOARD), "wood"),
               Part(prism(_coords(head_outline), H - self.BOARD, H), "wood")]
        lining = [box_between((-T / 2, -W / 2, self.BOARD - MEMBER_OVERLAP),
                              (T / 2, -W / 2 + LINING, H - self.BOARD + MEMBER_OVERLAP)),
                  box_between((-T / 2, W / 2 - LINING, self.BOARD - MEMBER_OVERLAP),
                              (T / 2, W / 2, H - self.BOARD + MEMBER_OVERLAP))]
        lining += casing(T / 2, 1, -g["cy"], g["cy"], self.BOARD - MEMBER_OVERLAP, g["cz"], cw, CASING_T,
                         True)
        out += [Part(s, "frame") for s in lining]
        out += self._glazing(p, g)
        out += self._roof(p, g)
        return out

    def _glazing(self, p, g) -> list[Part]:
        """The three glazed panels along the bay's edges and the posts at its corners."""
        pts, fd, fw = g["pts"], self.FRAME_D, p["frame_width"]
        zb, zt = self.BOARD - MEMBER_OVERLAP, g["H"] - self.BOARD + MEMBER_OVERLAP
        out: list[Part] = []
        edges = list(zip(pts[:-1], pts[1:], strict=True))
        for k, (a, b) in enumerate(edges):
            e = (b - a) / np.linalg.norm(b - a)
            n_in = np.array([e[1], -e[0]])
            L = float(np.linalg.norm(b - a))
            s0 = -0.02 if k == 0 else 0.0
            s1 = L + (0.02 if k == len(edges) - 1 else 0.0)
            lites = int(p["n_front_lites"]) if k == 1 else 1
            mat = np.array([[n_in[0], e[0], 0.0, a[0]], [n_in[1], e[1], 0.0, a[1]], [0.0, 0.0, 1.0, 0.0]])
            for solid, slot in _panel(s0, s1, zb, zt, fd, fw, lites, bool(p["transom"])):
                out.append(Part(solid.transform(mat), slot))
        for (a, b), (_, c) in zip(edges[:-1], edges[1:], strict=True):
            e1 = (b - a) / np.linalg.norm(b - a)
            e2 = (c - b) / np.linalg.norm(c - b)
            n1, n2 = np.array([e1[1], -e1[0]]), np.array([e2[1], -e2[0]])
            k = 0.7 * fw  # within the frames' end members, clear of their inner faces
            ring_pts = [b, b - e1 * k, b + e2 * k, b + n1 * fd, b + n2 * fd, b - e1 * k + n1 * fd,
                        b + e2 * k + n2 * fd]
            out.append(Part(hull([(x, y, z) for x, y in ring_pts for z in (zb, zt)]), "frame"))
        return out

    def _roof(self, p, g) -> list[Part]:
        """A fascia round the bay's top and a hipped roof rising to the wall (or a flat cap)."""
        H, T, W = g["H"], g["T"], g["W"]
        eave = self._outside(g, self.EAVE)
        coords = np.asarray(eave.exterior.coords)[:-1]
        fascia = prism(_coords(eave), H - 0.05, H + MEMBER_OVERLAP)
        if p["roof_style"] == "flat":
            cap = prism(_coords(eave), H, H + g["roof_h"])
            return [Part(fascia, "frame"), Part(cap, "stone")]
        y_r = W / 2 + self.EAVE
        ridge = [(-T / 2, -y_r, H + g["roof_h"]), (-T / 2, y_r, H + g["roof_h"])]
        roof = hull([(x, y, H) for x, y in coords] + ridge)
        return [Part(fascia, "frame"), Part(roof, "stone")]

    def extra_surfaces(self, p):
        """The bay window's surfaces besides its bounding box's: opening, seat."""
        g = self._g(p)
        W, T = g["W"], g["T"]
        x_room = T / 2 + max(p["seat_overhang"], CASING_T)
        pts = g["pts"]
        plan = sg.Polygon(np.vstack([pts, [(x_room, W / 2), (x_room, -W / 2)]]))
        edge_line = sg.LineString(np.vstack([pts[0] + (0.05, 0.0), pts, pts[-1] + (0.05, 0.0)]))
        hw = W / 2 - LINING - 0.02
        free = plan.intersection(sg.box(-10.0, -hw, x_room - 0.02, hw)).difference(
            edge_line.buffer(self.FRAME_D + 0.02))
        if free.geom_type != "Polygon":
            free = max(free.geoms, key=lambda q: q.area)
        free = free.simplify(0.001)
        return [opening_surface(-W / 2, W / 2, 0.0, g["H"]),
                support_polygon("seat", (0.0, 0.0, self.BOARD), free)]


def _coords(poly: sg.Polygon) -> np.ndarray:
    return np.asarray(poly.exterior.coords)[:-1]


def _panel(s0: float, s1: float, zb: float, zt: float, fd: float, fw: float, lites: int,
           transom: bool) -> list[tuple[m3d.Manifold, str]]:
    """A fixed glazed panel in its local frame (x = depth inward 0..fd, y = along its edge
    s0..s1, z): a frame with `lites` lites (mullions between), an optional transom bar near the
    top, and a pane through them."""
    out = [(ring(s0, s1, zb, zt, 0.0, fd, fw), "frame")]
    iy0, iy1, iz0, iz1 = s0 + fw, s1 - fw, zb + fw, zt - fw
    xm = fd / 2
    out.append((box_between((xm - 0.003, iy0 - 0.006, iz0 - 0.006), (xm + 0.003, iy1 + 0.006, iz1 + 0.006)),
                "glass"))
    bars = []  # a little thinner than the frame, so that no faces lie flush with its faces
    for i in range(1, lites):
        y = iy0 + (iy1 - iy0) * i / lites
        bars.append(box_between((0.002, y - fw / 2, iz0 - MEMBER_OVERLAP),
                                (fd - 0.002, y + fw / 2, iz1 + MEMBER_OVERLAP)))
    if transom:
        z = iz1 - 0.22 * (iz1 - iz0)
        bars.append(box_between((0.004, iy0 - MEMBER_OVERLAP, z - fw / 3),
                                (fd - 0.004, iy1 + MEMBER_OVERLAP, z + fw / 3)))
    out += [(b, "frame") for b in bars]
    return out
