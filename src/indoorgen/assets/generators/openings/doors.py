"""Doors: a hinged interior door set, a barn-style sliding door and a front door.

Frame conventions (see shapes/architectural.py): the wall is the YZ plane centred on x=0, the
opening's width along Y, its bottom at z=0; hinged leaves sit in the middle of the wall (so that
their handles reach equally far out of both faces and the bounding box stays symmetric about the
wall) in front of a stop on their -X side, and swing into +X about the +X edge on their hinge
side.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.architectural import (
    CASING_REVEAL,
    GLASS,
    LEAF_GAP,
    MEMBER_OVERLAP,
    casing,
    grid_cells,
    hull,
    lever,
    opening_surface,
    round_knob,
    slab,
)
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import DoorJoint, bar_handle, hinge_motion, make_joint
from indoorgen.assets.shapes.primitives import Part, box, box_between, rod, torus
from indoorgen.model.tags import Semantics as S

#: how far a handle's front stands off the leaf face (m)
STANDOFF = 0.065
#: distance from the latch edge to the handle's centre (m)
BACKSET = 0.065
#: door slots and their materials
DOOR_MATERIALS = {"frame": {"painted_wood": 4.0, "oak": 1.5, "walnut": 0.7},
                  "door": {"painted_wood": 3.0, "oak": 1.5, "walnut": 1.0, "pine_planks": 0.5},
                  "handle": {"brushed_steel": 2.0, "chrome": 1.5, "brass": 1.0, "painted_metal": 0.7}}


# ------------------------------------------------------------------------------- leaves
@dataclass(frozen=True)
class Zone:
    """A band of a leaf between rails, z0..z1, holding a cols x rows grid of `kind` cells:
    "raised" or "recessed" panels, "glass" lites or "louver" slats."""

    z0: float
    z1: float
    kind: str
    cols: int = 1
    rows: int = 1


def leaf(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float, zones: list[Zone],
         stile: float, link: str, slot: str = "door", bar: float = 0.09) -> list[Part]:
    """A door leaf x0..x1 thick over y0..y1 x z0..z1: a slab whose `zones` (between stiles
    `stile` wide) are cut into panels (pockets on both faces, with a bevelled field when
    raised), glazed lites (through holes with a pane and beads) or louvres (through holes with
    slanted slats). Cells of a zone are separated by bars (`bar` wide for panels)."""
    t = x1 - x0
    body = slab(y0, y1, z0, z1, x0, x1, True, 0.002)
    cuts: list[m3d.Manifold] = []
    extra: list[Part] = []
    for zone in zones:
        gap = bar if zone.kind in ("raised", "recessed") else 0.03 if zone.kind == "glass" else 0.08
        for cy0, cy1, cz0, cz1 in grid_cells(y0 + stile, y1 - stile, zone.z0, zone.z1,
                                             zone.cols, zone.rows, gap):
            if zone.kind in ("raised", "recessed"):
                dp = min(0.008, 0.2 * t)
                for side in (1, -1):
                    xf = x1 if side > 0 else x0
                    xa, xb = xf - side * dp, xf + side * 0.01
                    cuts.append(box_between((min(xa, xb), cy0, cz0), (max(xa, xb), cy1, cz1)))
                    if zone.kind == "raised":
                        bw = min(0.04, 0.25 * (cy1 - cy0), 0.25 * (cz1 - cz0))
                        xb, xt = xf - side * (dp + MEMBER_OVERLAP), xf - side * 0.002
                        pts = [(xb, cy0 + 0.003, cz0 + 0.003), (xb, cy1 - 0.003, cz0 + 0.003),
                               (xb, cy0 + 0.003, cz1 - 0.003), (xb, cy1 - 0.003, cz1 - 0.003),
                               (xt, cy0 + bw, cz0 + bw), (xt, cy1 - bw, cz0 + bw),
                               (xt, cy0 + bw, cz1 - bw), (xt, cy1 - bw, cz1 - bw)]
                        extra.append(Part(hull(pts), slot, link))
            else:
                cuts.append(box_between((x0 - 0.01, cy0, cz0), (x1 + 0.01, cy1, cz1)))
                extra += (_glazing(x0, x1, cy0, cy1, cz0, cz1, slot, link) if zone.kind == "glass"
                          else _louvres(x0, x1, cy0, cy1, cz0, cz1, slot, link))
    if cuts:
        body = body - m3d.Manifold.batch_boolean(cuts, m3d.OpType.Add)
    return [Part(body, slot, link)] + extra


def _glazing(x0, x1, y0, y1, z0, z1, slot, link) -> list[Part]:
    """A pane in a through hole, its edges sunk 6 mm into the leaf, held by beads on both faces."""
    xm, b = (x0 + x1) / 2, 0.012
    out = [Part(box_between((xm - GLASS / 2, y0 - 0.006, z0 - 0.006),
                            (xm + GLASS / 2, y1 + 0.006, z1 + 0.006)), "glass", link)]
    for xa, xb in ((x1 - b, x1), (x0, x0 + b)):
        beads = [box_between((xa, y0 - MEMBER_OVERLAP, z0 - MEMBER_OVERLAP),
                             (xb, y0 + b, z1 + MEMBER_OVERLAP)),
                 box_between((xa, y1 - b, z0 - MEMBER_OVERLAP),
                             (xb, y1 + MEMBER_OVERLAP, z1 + MEMBER_OVERLAP)),
                 box_between((xa, y0, z0 - MEMBER_OVERLAP), (xb, y1, z0 + b)),
                 box_between((xa, y0, z1 - b), (xb, y1, z1 + MEMBER_OVERLAP))]
        out.append(Part(solid_union(beads), slot, link))
    return out


def _louvres(x0, x1, y0, y1, z0, z1, slot, link) -> list[Part]:
    """Slats tilted 45 degrees across a through hole, within the leaf's thickness, their ends
    sunk 6 mm into the stiles."""
    t = x1 - x0
    st = 0.006
    w = (t - 0.004) / math.sqrt(2) - st
    zext = (w + st) / math.sqrt(2)
    pitch = 0.8 * zext
    n = max(1, int((z1 - z0 - zext) / pitch) + 1)
    xm = (x0 + x1) / 2
    slats = []
    for k in range(n):
        zc = z0 + zext / 2 + k * pitch
        s = box((w, y1 - y0 + 0.012, st)).rotate((0.0, 45.0, 0.0)).translate((xm, (y0 + y1) / 2, zc))
        slats.append(s)
    return [Part(solid_union(slats), slot, link)]


def leaf_zones(style: str, n: int, profile: str, z0: float, z1: float, z_lock: float,
               top_rail: float = 0.12, bottom_rail: float = 0.2, wide: bool = True) -> list[Zone]:
    """The zones of a leaf z0..z1 by style: "flat" none; "panel" n panels (2 columns when n is
    4 or 6 and the leaf is wide enough); "glass_panel" about n lites above the lock rail and one
    panel below; "louver" one louvred band, or two split at the lock rail when n >= 4."""
    lo, hi = z0 + bottom_rail, z1 - top_rail
    lock0, lock1 = z_lock - 0.08, z_lock + 0.08
    if style == "panel":
        cols = 2 if (n in (4, 6) and wide) else 1
        return [Zone(lo, hi, profile, cols, max(1, n // cols))]
    if style == "glass_panel":
        cols = 2 if (n >= 4 and wide) else 1
        return [Zone(lock1, hi, "glass", cols, int(math.ceil(n / cols))),
                Zone(lo, lock0, profile, 1, 1)]
    if style == "louver":
        if n >= 4:
            return [Zone(lo, lock0, "louver"), Zone(lock1, hi, "louver")]
        return [Zone(lo, hi, "louver")]
    return []


def handle_pair(style: str, face_x: float, y: float, z: float, toward: float) -> m3d.Manifold:
    """The same handle on both faces of a leaf centred on x=0 (fronts at +-face_x+STANDOFF):
    "lever" (pointing `toward` the hinge), "knob" or "pull" (a vertical bar)."""
    if style == "knob":
        one = round_knob(face_x, y, z, STANDOFF)
    elif style == "pull":
        one = bar_handle((face_x, y, z), 0.32, True, STANDOFF, 0.02)
    else:
        one = lever(face_x, y, z, toward, STANDOFF)
    return solid_union([one, one.mirror((1.0, 0.0, 0.0))])


def max_swing(wall: float, leaf_face: float, casing_t: float, gap: float) -> float:
    """The widest opening (rad, 90 to 100 degrees) at which a leaf hinged at its +X face
    `leaf_face`, `gap` from the jamb, clears the jamb's corner at the wall face and the casing
    standing CASING_REVEAL back from it."""
    margin = 0.0007
    a = math.atan((gap - margin) / max(wall / 2 - leaf_face, 1e-6))
    b = math.atan((gap + CASING_REVEAL - margin) / max(wall / 2 + casing_t - leaf_face, 1e-6))
    return min(math.radians(100.0), math.pi / 2 + min(a, b))


def _frame_block(g: dict[str, Any], wall: float, casing_t: float, casing_w: float) -> Part:
    """A door set's frame as one block (its placeholder): the lining across the wall and the
    casings on both faces, whose inner edges are at +-g["cy"] and head at g["cz"]."""
    return Part(box_between((-wall / 2 - casing_t, -g["cy"] - casing_w, 0.0),
                            (wall / 2 + casing_t, g["cy"] + casing_w, g["cz"] + casing_w)), "frame")


def _casings(g: dict[str, Any], wall: float, casing_t: float, casing_w: float) -> list[m3d.Manifold]:
    """The architraves on both faces of a wall `wall` thick around a door set's opening."""
    out: list[m3d.Manifold] = []
    for side in (1, -1):
        out += casing(side * wall / 2, side, -g["cy"], g["cy"], 0.0, g["cz"], casing_w, casing_t, True)
    return out


def _hinged_placeholder(g: dict[str, Any], wall: float, casing_t: float, casing_w: float
                        ) -> list[Part]:
    """The placeholder of a hinged door set: its frame block and a leaf block reaching out of
    both wall faces as far as the casings or the handles."""
    reach = max(wall / 2 + casing_t, g["lx1"] + STANDOFF)
    return [_frame_block(g, wall, casing_t, casing_w),
            Part(box_between((-reach, g["ly0"], g["lz0"]), (reach, g["ly1"], g["lz1"])), "door", "leaf")]


def _leaf_joint(hinge_side: str, g: dict[str, Any], wall: float, casing_t: float) -> Joint:
    """The revolute joint of a hinged leaf (g["lx0"..."lz1"]), swinging into +X as far as the
    jamb and the casings let it (`max_swing`)."""
    upper = max_swing(wall, g["lx1"], casing_t, LEAF_GAP)
    m = hinge_motion(hinge_side, g["lx1"], g["ly0"], g["ly1"], 0.0, 0.0, "leaf")
    return make_joint("leaf_joint", m, 0.0, upper)


# ------------------------------------------------------------------------- interior door
@register
class InteriorDoor(PartsFactory):
    """An interior door set: jamb lining across the wall thickness, a stop, architraves on both
    wall faces and a leaf on a revolute joint (hinged left or right, swinging into +X up to
    about 95 degrees). Leaves are flat, panelled (2-6 raised or recessed panels), glazed (lites
    above a panel) or louvred, with a lever or knob on both faces. Surfaces: ``opening`` (the
    rough opening in the wall's centre plane; see shapes.architectural.opening_size)."""

    name = "interior_door"
    tags = frozenset({S.Object, S.Architecture, S.Door, S.InteriorDoor})
    size_class = "large"
    slots = ["frame", "door", "handle", "glass"]
    material_choices = DOOR_MATERIALS
    params = {
        "width": Param(0.7, 1.0, doc="rough opening width in the wall (m)"),
        "height": Param(1.95, 2.2, doc="rough opening height (m)"),
        "wall_thickness": Param(0.08, 0.3, doc="thickness of the wall the lining spans (m)"),
        "style": Param(kind="choice", choices=("flat", "panel", "glass_panel", "louver"),
                       doc="leaf style"),
        "n_panels": Param(2, 6, kind="int", doc="panels (panel), lites (glass_panel) or louvre "
                                                "bands (>= 4: two) of the leaf"),
        "panel_profile": Param(kind="choice", choices=("recessed", "raised"),
                               doc="flat recessed or bevelled raised panels"),
        "hinge_side": Param(kind="choice", choices=("left", "right"),
                            doc="hinge side seen from +X (left = low y)"),
        "leaf_thickness": Param(0.035, 0.045, doc="leaf thickness (m)"),
        "jamb_thickness": Param(0.018, 0.03, doc="jamb lining board thickness (m)"),
        "casing_width": Param(0.05, 0.1, doc="architrave face width (m)"),
        "casing_thickness": Param(0.012, 0.022, doc="how far the architrave stands off the wall (m)"),
        "handle": Param(kind="choice", choices=("lever", "knob"), doc="handle on both faces"),
        "handle_height": Param(0.9, 1.05, doc="handle centre height (m)"),
    }

    def _g(self, p: dict[str, Any]) -> dict[str, float]:
        W, H, jt, lt = p["width"], p["height"], p["jamb_thickness"], p["leaf_thickness"]
        return {"ly0": -W / 2 + jt + LEAF_GAP, "ly1": W / 2 - jt - LEAF_GAP,
                "lz0": 0.01, "lz1": H - jt - LEAF_GAP,
                "lx0": -lt / 2, "lx1": lt / 2,
                "cy": W / 2 - jt + CASING_REVEAL, "cz": H - jt + CASING_REVEAL}

    def parts(self, p, detail):
        """The interior door's solids: detailed, or the blocks of its placeholder."""
        T, ct, cw = p["wall_thickness"], p["casing_thickness"], p["casing_width"]
        g = self._g(p)
        if not detail:
            return _hinged_placeholder(g, T, ct, cw)
        return self._frame(p, g) + self._leaf(p, g)

    def _frame(self, p, g) -> list[Part]:
        W, H, T = p["width"], p["height"], p["wall_thickness"]
        jt, ct, cw = p["jamb_thickness"], p["casing_thickness"], p["casing_width"]
        sx0, sx1 = g["lx0"] - LEAF_GAP - 0.012, g["lx0"] - LEAF_GAP
        sp = 0.012  # how far the stop reaches into the opening
        pieces = [box_between((-T / 2, -W / 2, 0.0), (T / 2, -W / 2 + jt, H - jt + MEMBER_OVERLAP)),
                  box_between((-T / 2, W / 2 - jt, 0.0), (T / 2, W / 2, H - jt + MEMBER_OVERLAP)),
                  box_between((-T / 2, -W / 2, H - jt), (T / 2, W / 2, H)),
                  box_between((sx0, -W / 2 + jt - MEMBER_OVERLAP, 0.0),
                              (sx1, -W / 2 + jt + sp, H - jt + MEMBER_OVERLAP)),
                  box_between((sx0, W / 2 - jt - sp, 0.0),
                              (sx1, W / 2 - jt + MEMBER_OVERLAP, H - jt + MEMBER_OVERLAP)),
                  box_between((sx0, -W / 2 + jt, H - jt - sp), (sx1, W / 2 - jt, H - jt + MEMBER_OVERLAP))]
        pieces += _casings(g, T, ct, cw)
        return [Part(s, "frame") for s in pieces]

    def _leaf(self, p, g) -> list[Part]:
        W = g["ly1"] - g["ly0"]
        stile = min(0.12, 0.15 * W)
        zones = leaf_zones(p["style"], int(p["n_panels"]), p["panel_profile"], g["lz0"], g["lz1"],
                           p["handle_height"], wide=W >= 0.7)
        parts = leaf(g["lx0"], g["lx1"], g["ly0"], g["ly1"], g["lz0"], g["lz1"], zones, stile, "leaf")
        left = p["hinge_side"] == "left"
        yh = g["ly1"] - BACKSET if left else g["ly0"] + BACKSET
        parts.append(Part(handle_pair(p["handle"], g["lx1"], yh, p["handle_height"], -1.0 if left else 1.0),
                          "handle", "leaf"))
        return parts

    def joints(self, p):
        """The interior door's joint: its leaf's hinge."""
        return [_leaf_joint(p["hinge_side"], self._g(p), p["wall_thickness"], p["casing_thickness"])]

    def extra_surfaces(self, p):
        """The interior door's surfaces besides its bounding box's: opening."""
        return [opening_surface(-p["width"] / 2, p["width"] / 2, 0.0, p["height"])]


# -------------------------------------------------------------------------- sliding door
@register
class SlidingDoor(PartsFactory):
    """A barn-style sliding door: a leaf hung by two hangers with wheels from a flat track
    mounted on the +X wall face above the opening, sliding along Y (prismatic joint) past the
    opening to clear it; jamb lining and architraves around the opening. Leaves of vertical
    boards, an X- or Z-braced frame, or a glazed grid; a bar or flush pull. The track makes the
    bounding box asymmetric: the ``opening`` surface marks the wall's opening and centre plane."""

    name = "sliding_door"
    tags = frozenset({S.Object, S.Architecture, S.Door, S.InteriorDoor})
    size_class = "large"
    slots = ["frame", "door", "metal", "handle", "glass"]
    material_choices = {**DOOR_MATERIALS, "metal": {"painted_metal": 3.0, "brushed_steel": 1.5,
                                                    "rusty_metal": 0.5}}
    params = {
        "width": Param(0.7, 1.1, doc="rough opening width in the wall (m)"),
        "height": Param(1.95, 2.2, doc="rough opening height (m)"),
        "wall_thickness": Param(0.08, 0.3, doc="wall thickness the lining spans (m)"),
        "leaf_style": Param(kind="choice", choices=("boards", "x_brace", "z_brace", "glass_grid"),
                            doc="vertical boards, braced frame, or a glazed grid"),
        "n_boards": Param(3, 8, kind="int", doc="boards across the leaf (boards) or lite rows "
                                                "(glass_grid)"),
        "slide_direction": Param(kind="choice", choices=("left", "right"),
                                 doc="the side it slides to open (left = +Y)"),
        "leaf_thickness": Param(0.03, 0.045, doc="leaf thickness (m)"),
        "overlap": Param(0.03, 0.08, doc="how far the leaf laps past the opening each side (m)"),
        "handle": Param(kind="choice", choices=("bar", "flush"), doc="bar pull or flush pulls"),
        "casing_width": Param(0.04, 0.09, doc="architrave face width (m)"),
        "wheel_radius": Param(0.035, 0.06, doc="hanger wheel radius (m)"),
    }

    def _g(self, p) -> dict[str, float]:
        W, H, T = p["width"], p["height"], p["wall_thickness"]
        lt, ov, ct = p["leaf_thickness"], p["overlap"], 0.015
        lx0 = T / 2 + ct + 0.01
        ly0, ly1 = -W / 2 - ov, W / 2 + ov
        lz0, lz1 = 0.01, H + 0.03
        rail_z0 = lz1 + 0.05
        rail_z1 = rail_z0 + 0.04
        wr = p["wheel_radius"]
        sgn = 1.0 if p["slide_direction"] == "left" else -1.0
        travel = W + ov  # the trailing edge clears the opening
        wheel_in = 0.12
        # the rail covers both wheels over the whole travel, plus end stops
        lo_y = ly0 + wheel_in - wr - 0.045 - (0.0 if sgn > 0 else travel)
        hi_y = ly1 - wheel_in + wr + 0.045 + (travel if sgn > 0 else 0.0)
        return {"W": W, "H": H, "T": T, "lt": lt, "ct": ct, "lx0": lx0, "lx1": lx0 + lt,
                "ly0": ly0, "ly1": ly1, "lz0": lz0, "lz1": lz1, "rz0": rail_z0, "rz1": rail_z1,
                "rx": lx0 + lt / 2, "wr": wr, "sgn": sgn, "travel": travel, "wheel_in": wheel_in,
                "ry0": lo_y, "ry1": hi_y, "cy": W / 2 - 0.02 + CASING_REVEAL, "cz": H - 0.02 + CASING_REVEAL}

    def parts(self, p, detail):
        """The sliding door's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        T, cw, ct = g["T"], p["casing_width"], g["ct"]
        wheel_top = g["rz1"] + LEAF_GAP + 2 * g["wr"]
        front = g["lx1"] + (0.06 if p["handle"] == "bar" else 0.012)  # the pull, or hanger bolts
        if p["leaf_style"] in ("x_brace", "z_brace"):
            front = max(front, g["lx1"] + 0.017)  # the applied frame and a flush cup in it
        if not detail:
            return [_frame_block(g, T, ct, cw),
                    Part(box_between((T / 2 - MEMBER_OVERLAP, g["ry0"], self._board_z0(p, g)),
                                     (g["rx"] + 0.012, g["ry1"], g["rz1"] + 0.025)), "metal"),
                    Part(box_between((g["lx0"], g["ly0"], g["lz0"]), (front, g["ly1"], wheel_top)), "door",
                         "leaf")]
        return self._frame(p, g) + self._track(p, g) + self._leaf(p, g)

    def _frame(self, p, g) -> list[Part]:
        T, W, H, cw, ct = g["T"], g["W"], g["H"], p["casing_width"], g["ct"]
        jt = 0.02
        pieces = [box_between((-T / 2, -W / 2, 0.0), (T / 2, -W / 2 + jt, H - jt + MEMBER_OVERLAP)),
                  box_between((-T / 2, W / 2 - jt, 0.0), (T / 2, W / 2, H - jt + MEMBER_OVERLAP)),
                  box_between((-T / 2, -W / 2, H - jt), (T / 2, W / 2, H))]
        pieces += _casings(g, T, ct, cw)
        return [Part(s, "frame") for s in pieces]

    @staticmethod
    def _board_z0(p, g) -> float:
        """Bottom of the mounting board along the wall face that carries the track's spacers;
        it reaches down over the casing head to join it."""
        return min(g["rz0"] - 0.02, g["cz"] + p["casing_width"] - 0.03)

    def _track(self, p, g) -> list[Part]:
        """The flat rail on spacers bolted through to the casing head / wall face, and end stops."""
        T, rx = g["T"], g["rx"]
        rail = box_between((rx - 0.004, g["ry0"], g["rz0"]), (rx + 0.004, g["ry1"], g["rz1"]))
        bz0 = self._board_z0(p, g)
        board = box_between((T / 2 - MEMBER_OVERLAP, g["ry0"], bz0),
                            (T / 2 + g["ct"], g["ry1"], g["rz1"] + 0.02))
        n = max(2, int((g["ry1"] - g["ry0"]) / 0.4) + 1)
        zc = (g["rz0"] + g["rz1"]) / 2
        spacers = [rod((T / 2 + g["ct"] - MEMBER_OVERLAP, y, zc), (rx + 0.006, y, zc), 0.01, 12)
                   for y in np.linspace(g["ry0"] + 0.05, g["ry1"] - 0.05, n)]
        stops = [box_between((rx - 0.012, y - 0.015, g["rz1"] - MEMBER_OVERLAP),
                             (rx + 0.012, y + 0.015, g["rz1"] + 0.025))
                 for y in (g["ry0"] + 0.015, g["ry1"] - 0.015)]
        return [Part(board, "frame"), Part(solid_union([rail] + spacers + stops), "metal")]

    def _leaf(self, p, g) -> list[Part]:
        x0, x1, y0, y1, z0, z1 = g["lx0"], g["lx1"], g["ly0"], g["ly1"], g["lz0"], g["lz1"]
        style, n = p["leaf_style"], int(p["n_boards"])
        out: list[Part]
        if style == "glass_grid":
            out = leaf(x0, x1, y0, y1, z0, z1,
                       [Zone(z0 + 0.1, z1 - 0.1, "glass", 2 if y1 - y0 > 0.8 else 1, n)],
                       0.09, "leaf")
        else:
            body = slab(y0, y1, z0, z1, x0, x1, True, 0.002)
            if style == "boards":  # V-grooves between boards on both faces
                grooves = []
                for yb in np.linspace(y0, y1, n + 1)[1:-1]:
                    for xf in (x0, x1):
                        grooves.append(box_between((xf - 0.003, yb - 0.002, z0 - 0.01),
                                                   (xf + 0.003, yb + 0.002, z1 + 0.01)))
                body = body - m3d.Manifold.batch_boolean(grooves, m3d.OpType.Add)
            out = [Part(body, "door", "leaf")]
            if style in ("x_brace", "z_brace"):
                out.append(Part(self._braces(x1, y0, y1, z0, z1, style), "door", "leaf"))
        return self._pull(p, g, out) + self._hangers(p, g)

    @staticmethod
    def _braces(x1, y0, y1, z0, z1, style) -> m3d.Manifold:
        """An applied frame (stiles and rails 15 mm proud of the +X face) with diagonal braces."""
        b, d = 0.11, 0.015
        xa, xb = x1 - MEMBER_OVERLAP, x1 + d
        zm = (z0 + z1) / 2
        pieces = [box_between((xa, y0, z0), (xb, y0 + b, z1)), box_between((xa, y1 - b, z0), (xb, y1, z1)),
                  box_between((xa, y0, z0), (xb, y1, z0 + b)), box_between((xa, y0, z1 - b), (xb, y1, z1)),
                  box_between((xa, y0, zm - b / 2), (xb, y1, zm + b / 2))]
        bays = [(z0 + b, zm - b / 2), (zm + b / 2, z1 - b)]
        for za, zb in bays:
            diags = [(1, -1)] if style == "z_brace" else [(1, -1), (-1, 1)]
            for flip in diags[:2]:
                ya, yb = (y0 + b, y1 - b) if flip[0] > 0 else (y1 - b, y0 + b)
                pieces.append(_diagonal(xa, xb, ya, za, yb, zb, 0.09))
        return solid_union(pieces)

    def _hangers(self, p, g) -> list[Part]:
        """Two strap hangers bolted to the leaf's +X face, rising past the rail to wheels that
        roll on it."""
        out = []
        x1, wr, rx = g["lx1"], g["wr"], g["rx"]
        zw = g["rz1"] + LEAF_GAP + wr
        for y in (g["ly0"] + g["wheel_in"], g["ly1"] - g["wheel_in"]):
            strap = box_between((x1 - MEMBER_OVERLAP, y - 0.02, g["lz1"] - 0.18),
                                (x1 + 0.006, y + 0.02, zw + 0.02))
            axle = rod((rx - 0.01, y, zw), (x1 + 0.006, y, zw), 0.008, 12)
            wheel = rod((rx - 0.009, y, zw), (rx + 0.009, y, zw), wr, 24)
            bolts = [rod((x1, y, z), (x1 + 0.012, y, z), 0.008, 8)
                     for z in (g["lz1"] - 0.14, g["lz1"] - 0.06)]
            out.append(Part(solid_union([strap, axle, wheel] + bolts), "metal", "leaf"))
        return out

    def _pull(self, p, g, leaf_parts: list[Part]) -> list[Part]:
        """A bar pull on +X near the edge that leads when opening, or a flush cup sunk into each
        face (cut out of the leaf's wooden parts). Returns the leaf's parts with the pull."""
        y = g["ly1"] - 0.08 if g["sgn"] > 0 else g["ly0"] + 0.08
        z = 1.0
        if p["handle"] == "bar":
            return leaf_parts + [Part(bar_handle((g["lx1"], y, z), 0.3, True, 0.06, 0.02), "handle", "leaf")]
        x0, x1 = g["lx0"], g["lx1"]
        if p["leaf_style"] in ("x_brace", "z_brace"):
            x1 += 0.015  # the cup sits in the applied stile
        cut = solid_union([box_between((x1 - 0.008, y - 0.018, z - 0.08), (x1 + 0.01, y + 0.018, z + 0.08)),
                           box_between((x0 - 0.01, y - 0.018, z - 0.08), (x0 + 0.008, y + 0.018, z + 0.08))])
        cups = solid_union([box_between((x1 - 0.01, y - 0.025, z - 0.09), (x1 + 0.002, y + 0.025, z + 0.09)),
                            box_between((x0 - 0.002, y - 0.025, z - 0.09), (x0 + 0.01, y + 0.025, z + 0.09))])
        cut_parts = [Part(q.solid - cut, q.slot, q.link) if q.slot == "door" else q for q in leaf_parts]
        return cut_parts + [Part(cups - cut, "handle", "leaf")]

    def joints(self, p):
        """The sliding door's joint: its leaf's slide."""
        g = self._g(p)
        m = DoorJoint("prismatic", np.array([0.0, g["sgn"], 0.0]),
                      np.array([g["rx"], (g["ly0"] + g["ly1"]) / 2, g["rz1"]]), "leaf")
        return [make_joint("leaf_joint", m, 0.0, g["travel"])]

    def extra_surfaces(self, p):
        """The sliding door's surfaces besides its bounding box's: opening."""
        return [opening_surface(-p["width"] / 2, p["width"] / 2, 0.0, p["height"])]


def _diagonal(xa: float, xb: float, ya: float, za: float, yb: float, zb: float, w: float) -> m3d.Manifold:
    """A flat board xa..xb thick running from (ya, za) to (yb, zb) in the YZ plane, `w` wide,
    its ends cut square to the rails it runs between (clipped to za..zb)."""
    d = np.array([yb - ya, zb - za])
    n = np.array([-d[1], d[0]]) / np.linalg.norm(d) * w / 2
    pts = [(x, y + s * n[0], z + s * n[1]) for (y, z) in ((ya, za), (yb, zb)) for s in (-1, 1)
           for x in (xa, xb)]
    clip = box_between((xa - 0.01, min(ya, yb) - 0.01, min(za, zb) - MEMBER_OVERLAP),
                       (xb + 0.01, max(ya, yb) + 0.01, max(za, zb) + MEMBER_OVERLAP))
    return hull(pts) ^ clip


# ------------------------------------------------------------------------- exterior door
@register
class ExteriorDoor(PartsFactory):
    """A front door: a heavy frame across the wall with a stop and a sloped threshold,
    architraves on both faces, optional fixed side lites (glazed over a panel) beside the leaf,
    and a thick leaf on a revolute joint swinging into +X (inside; -X is outside). Leaves are
    raised-panel, half-lite (lites over panels), full-lite (a gridded pane) or craftsman (a row
    of lites over tall panels), with a lever, knob or pull bar on both faces, a deadbolt and an
    optional knocker outside. Surfaces: ``opening``."""

    name = "exterior_door"
    tags = frozenset({S.Object, S.Architecture, S.Door, S.ExteriorDoor})
    size_class = "large"
    slots = ["frame", "door", "handle", "glass", "stone"]
    material_choices = {**DOOR_MATERIALS,
                        "door": {"painted_wood": 3.0, "oak": 2.0, "walnut": 1.5, "painted_metal": 1.0},
                        "stone": {"oak": 2.0, "slate": 1.0, "granite": 1.0, "concrete": 0.5}}
    params = {
        "width": Param(0.85, 1.1, doc="rough opening width of the door itself (m)"),
        "height": Param(2.0, 2.4, doc="rough opening height (m)"),
        "wall_thickness": Param(0.15, 0.35, doc="exterior wall thickness (m)"),
        "style": Param(kind="choice", choices=("panel", "half_lite", "full_lite", "craftsman"),
                       doc="leaf style"),
        "n_panels": Param(2, 6, kind="int", doc="panels (panel), lites (half_lite, craftsman) or "
                                                "pane grid rows (full_lite)"),
        "sidelites": Param(kind="choice", choices=("none", "left", "right", "both"),
                           doc="fixed glazed side lites"),
        "sidelite_width": Param(0.25, 0.45, doc="width each side lite adds to the opening (m)"),
        "hinge_side": Param(kind="choice", choices=("left", "right"), doc="hinge side seen from +X"),
        "handle": Param(kind="choice", choices=("lever", "knob", "pull"), doc="handle on both faces"),
        "knocker": Param(kind="bool", doc="a ring knocker outside"),
        "leaf_thickness": Param(0.045, 0.06, doc="leaf thickness (m)"),
        "frame_thickness": Param(0.04, 0.06, doc="jamb and mullion thickness (m)"),
        "casing_width": Param(0.07, 0.13, doc="architrave face width (m)"),
        "threshold_height": Param(0.015, 0.035, doc="threshold height above the floor (m)"),
    }

    CASING_T = 0.022

    def _g(self, p) -> dict[str, Any]:
        W, H, T = p["width"], p["height"], p["wall_thickness"]
        jt, lt, th = p["frame_thickness"], p["leaf_thickness"], p["threshold_height"]
        sw, side = p["sidelite_width"], p["sidelites"]
        nl = (1 if side in ("left", "both") else 0)
        nr = (1 if side in ("right", "both") else 0)
        total = W + (nl + nr) * sw
        y_left = -total / 2
        d0 = y_left + nl * sw  # the door module's low edge (its post is inside it)
        d1 = d0 + W
        lites = []
        if nl:
            lites.append((y_left + jt, d0 + MEMBER_OVERLAP))
        if nr:
            lites.append((d1 - MEMBER_OVERLAP, total / 2 - jt))
        return {"W": W, "H": H, "T": T, "jt": jt, "lt": lt, "th": th, "total": total,
                "d0": d0, "d1": d1, "lites": lites,
                "posts": [d0, d1 - jt] + ([y_left] if nl else []) + ([total / 2 - jt] if nr else []),
                "ly0": d0 + jt + LEAF_GAP, "ly1": d1 - jt - LEAF_GAP,
                "lz0": th + LEAF_GAP, "lz1": H - jt - LEAF_GAP,
                "lx0": -lt / 2, "lx1": lt / 2,
                "cy": total / 2 - jt + CASING_REVEAL, "cz": H - jt + CASING_REVEAL}

    def parts(self, p, detail):
        """The exterior door's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        T, ct, cw = g["T"], self.CASING_T, p["casing_width"]
        if not detail:
            return _hinged_placeholder(g, T, ct, cw)
        return self._frame(p, g) + self._leaf(p, g)

    def _frame(self, p, g) -> list[Part]:
        T, H, jt, th, ct, cw = g["T"], g["H"], g["jt"], g["th"], self.CASING_T, p["casing_width"]
        total = g["total"]
        lx0 = g["lx0"]
        sx0, sx1 = lx0 - LEAF_GAP - 0.015, lx0 - LEAF_GAP
        sp = 0.015
        out = [Part(self._threshold(g, ct), "stone")]
        pieces = [box_between((-T / 2, -total / 2, H - jt), (T / 2, total / 2, H))]
        for y in g["posts"]:
            pieces.append(box_between((-T / 2, y, 0.3 * th), (T / 2, y + jt, H - jt + MEMBER_OVERLAP)))
        d0, d1 = g["d0"] + jt, g["d1"] - jt
        pieces += [box_between((sx0, d0 - MEMBER_OVERLAP, th - MEMBER_OVERLAP),
                               (sx1, d0 + sp, H - jt + MEMBER_OVERLAP)),
                   box_between((sx0, d1 - sp, th - MEMBER_OVERLAP),
                               (sx1, d1 + MEMBER_OVERLAP, H - jt + MEMBER_OVERLAP)),
                   box_between((sx0, d0, H - jt - sp), (sx1, d1, H - jt + MEMBER_OVERLAP))]
        pieces += _casings(g, T, ct, cw)
        out += [Part(s, "frame") for s in pieces]
        for ya, yb in g["lites"]:  # fixed side lites: glass over a raised panel
            zb = th - MEMBER_OVERLAP
            zt = H - jt + MEMBER_OVERLAP
            zones = [Zone(zb + 0.12 + 0.35 + 0.08, zt - 0.1, "glass", 1, 1),
                     Zone(zb + 0.12, zb + 0.12 + 0.35, "raised")]
            out += leaf(g["lx0"], g["lx1"], ya, yb, zb, zt, zones, min(0.07, 0.25 * (yb - ya)), "base",
                        slot="frame")
        return out

    @staticmethod
    def _threshold(g, ct) -> m3d.Manifold:
        """A sill across the opening: flat under the leaf and inside, sloping down outside."""
        T, th, lt = g["T"], g["th"], g["lt"]
        a = T / 2 + ct
        prof = [(-a, 0.0), (a, 0.0), (a, 0.5 * th), (a - 0.01, th), (-lt / 2 - 0.02, th), (-a, 0.4 * th)]
        return _xz_prism(prof, -g["total"] / 2, g["total"] / 2)

    def _leaf(self, p, g) -> list[Part]:
        W = g["ly1"] - g["ly0"]
        x0, x1, y0, y1, z0, z1 = g["lx0"], g["lx1"], g["ly0"], g["ly1"], g["lz0"], g["lz1"]
        n, style = int(p["n_panels"]), p["style"]
        zl = 1.0
        lo, hi = z0 + 0.22, z1 - 0.13
        if style == "panel":
            zones = [Zone(lo, hi, "raised", 2 if n >= 4 else 1, max(2, n // 2) if n >= 4 else n)]
        elif style == "half_lite":
            cols = 2 if n >= 4 else 1
            zones = [Zone(zl + 0.12, hi, "glass", cols, int(math.ceil(n / cols))),
                     Zone(lo, zl - 0.08, "raised", 2, 1)]
        elif style == "full_lite":
            zones = [Zone(lo, hi, "glass", 1 if n < 4 else 2, n)]
        else:  # craftsman: a row of lites over tall vertical panels
            zt = hi - 0.45
            zones = [Zone(zt + 0.1, hi, "glass", max(2, min(n, 4)), 1),
                     Zone(lo, zt - 0.04, "recessed", 3 if W > 0.8 else 2, 1)]
        stile = min(0.13, 0.15 * W)
        parts = leaf(x0, x1, y0, y1, z0, z1, zones, stile, "leaf")
        if style == "craftsman":  # the dentil shelf under the lites, outside only (on the +X
            zt = hi - 0.45        # face it would hit the hinge jamb when the leaf is open)
            parts.append(Part(box_between((x0 - 0.025, y0 + stile - 0.02, zt + 0.02),
                                          (x0 + MEMBER_OVERLAP, y1 - stile + 0.02, zt + 0.05)),
                              "door", "leaf"))
        left = p["hinge_side"] == "left"
        yh = y1 - BACKSET if left else y0 + BACKSET
        hw = [handle_pair(p["handle"], x1, yh, zl, -1.0 if left else 1.0),
              solid_union([rod((x1 - MEMBER_OVERLAP, yh, zl + 0.16), (x1 + 0.012, yh, zl + 0.16), 0.024, 16),
                           rod((x0 + MEMBER_OVERLAP, yh, zl + 0.16), (x0 - 0.012, yh, zl + 0.16), 0.024, 16),
                           box_between((x1 + 0.011, yh - 0.004, zl + 0.145),
                                       (x1 + 0.025, yh + 0.004, zl + 0.175))])]
        if p["knocker"]:
            hw.append(self._knocker(x0, yh if style in ("half_lite", "full_lite") else (y0 + y1) / 2,
                                    min(1.5, z1 - 0.3) if style != "craftsman" else (hi - 0.45 - 0.12)))
        parts.append(Part(solid_union(hw), "handle", "leaf"))
        return parts

    @staticmethod
    def _knocker(x0: float, y: float, z: float) -> m3d.Manifold:
        """A ring knocker on the -X (outside) face: a back plate, a pivot and a hanging ring."""
        # the plate's back sinks past the depth of a panel's pocket, so it holds on anywhere
        plate = box_between((x0 - 0.01, y - 0.03, z - 0.06), (x0 + 0.009, y + 0.03, z + 0.05))
        pivot = box_between((x0 - 0.03, y - 0.008, z + 0.01), (x0 - 0.009, y + 0.008, z + 0.03))
        ring_ = torus(0.04, 0.007, (0.0, 0.0, 0.0), 24, 8).rotate((0.0, 90.0, 0.0)).translate(
            (x0 - 0.024, y, z - 0.02))
        return solid_union([plate, pivot, ring_])

    def joints(self, p):
        """The exterior door's joint: its leaf's hinge."""
        g = self._g(p)
        return [_leaf_joint(p["hinge_side"], g, g["T"], self.CASING_T)]

    def extra_surfaces(self, p):
        """The exterior door's surfaces besides its bounding box's: opening."""
        g = self._g(p)
        return [opening_surface(-g["total"] / 2, g["total"] / 2, 0.0, p["height"])]


def _xz_prism(profile, y0: float, y1: float) -> m3d.Manifold:
    """A convex (x, z) profile extruded from y0 to y1."""
    pts = [(x, y, z) for x, z in profile for y in (y0, y1)]
    return hull(pts)
