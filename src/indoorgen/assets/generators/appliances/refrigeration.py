"""Cold appliances: fridges and beverage fridges. Fronts face +X; every door and drawer is its
own link with a joint.

They are open-fronted insulated shells (so opening a door shows the inside), with their
shelves and racks as `Subpart.Interior` surfaces.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.appliances._parts import rack_surface, wire_rack
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.cabinet_parts import interior_rect, joint_for, open_shell, pull_bar, window_leaf
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, hinge_motion, slide_motion
from indoorgen.assets.shapes.primitives import Part, bevel_box, box_between
from indoorgen.assets.shapes.surfaces import bottom_rect, support_rect
from indoorgen.model.tags import Semantics as S

#: insulated wall thickness of cold appliances (m)
COLD_WALL = 0.04
#: plastic liner thickness inside their compartments (m)
LINER = 0.003


def _vent_slots(x_face: float, y0: float, y1: float, z0: float, z1: float, pitch: float = 0.012
                ) -> list[m3d.Manifold]:
    """Horizontal slots (cutters) of a kick-plate grille on a +X face between z0 and z1."""
    n = max(1, int((z1 - z0) / pitch))
    zs = z0 + (np.arange(n) + 0.5) * (z1 - z0) / n
    h = min(0.005, 0.45 * (z1 - z0) / n)
    return [box_between((x_face - 0.012, y0, z - h / 2), (x_face + 0.01, y1, z + h / 2)) for z in zs]



def _shelf_levels(z0: float, z1: float, n: int) -> list[float]:
    """Upper faces of `n` shelves evenly spaced in a compartment from z0 to z1."""
    return [z0 + (z1 - z0) * (i + 1) / (n + 1) for i in range(n)]


def _grip(x_face: float, y_edge: float, toward: float, z0: float, z1: float, style: str,
          standoff: float) -> m3d.Manifold:
    """A vertical door handle near a free edge at y_edge (`toward` = +-1 points into the
    leaf): a round bar on posts ("bar") or an L-profile strip ("edge")."""
    if style == "bar":
        y = y_edge + toward * 0.045
        return pull_bar(x_face, (y, z0), (y, z1), standoff, 0.011, 12)
    y_out = y_edge + toward * 0.012
    strip = box_between((x_face - 0.001, min(y_out, y_out + toward * 0.018), z0),
                        (x_face + standoff, max(y_out, y_out + toward * 0.018), z1))
    lip = box_between((x_face + standoff - 0.008, min(y_out, y_out + toward * 0.045), z0),
                      (x_face + standoff, max(y_out, y_out + toward * 0.045), z1))
    return strip + lip


# ------------------------------------------------------------------------------- fridge
FRIDGE_STYLES = ("single", "top_freezer", "bottom_freezer", "french")


@dataclass(frozen=True)
class _Leaf:
    """A fridge door ("left"/"right": its hinge side) or drawer ("drawer") covering y0..y1,
    z0..z1 of the front; `fridge` when it closes the fridge (not the freezer) compartment."""

    link: str
    kind: str
    y0: float
    y1: float
    z0: float
    z1: float
    fridge: bool


def _dispenser(slab: m3d.Manifold, x1: float, leaf: _Leaf) -> tuple[m3d.Manifold, list[Part]]:
    """A water/ice dispenser in a door leaf whose front is at x1: a recess cut into the slab
    (at most 1.2 m up), its dark back plate and a small display above it."""
    dw, dh = 0.17, 0.26
    yc, zc = (leaf.y0 + leaf.y1) / 2, min(leaf.z1 - 0.25 - dh / 2, 1.2)
    slab = slab - box_between((x1 - 0.025, yc - dw / 2, zc - dh / 2), (x1 + 0.01, yc + dw / 2, zc + dh / 2))
    plate = box_between((x1 - 0.026, yc - dw / 2 - 0.001, zc - dh / 2 - 0.001),
                        (x1 - 0.024, yc + dw / 2 + 0.001, zc + dh / 2 + 0.001))
    display = box_between((x1 - 0.001, yc - 0.04, zc + dh / 2 + 0.02),
                          (x1 + 0.001, yc + 0.04, zc + dh / 2 + 0.06))
    return slab, [Part(plate, "plastic", leaf.link), Part(display, "screen", leaf.link)]


@register
class Fridge(PartsFactory):
    """A refrigerator: an insulated open-fronted cabinet on a grilled kick plate with a single
    door, a top or bottom freezer door, or French doors over a freezer drawer. Doors are hinged
    at their outer edge (revolute joints) and carry handles and door bins; glass shelves inside
    are `interior_i` surfaces; `top` is a support surface. Optional water dispenser recess."""

    name = "fridge"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Fridge})
    size_class = "large"
    slots = ["appliance", "plastic", "glass", "metal", "rubber", "screen"]
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=FRIDGE_STYLES, doc="door arrangement"),
        "width": Param(0.55, 0.92, doc="Y extent of the cabinet (m)"),
        "depth": Param(0.58, 0.72, doc="X extent of the cabinet without doors (m)"),
        "height": Param(1.45, 1.95, doc="Z extent (m)"),
        "door_thickness": Param(0.045, 0.075, doc="door leaf thickness (m)"),
        "freezer_frac": Param(0.25, 0.38, doc="freezer compartment height / door height"),
        "handle": Param(kind="choice", choices=("bar", "edge"), doc="round bars or profile strips"),
        "handle_length": Param(0.25, 0.6, doc="fridge door handle length (m)"),
        "n_shelves": Param(2, 5, kind="int", doc="glass shelves in the fridge compartment"),
        "hinge_side": Param(kind="choice", choices=("left", "right"),
                            doc="hinge side of single-leaf doors"),
        "edge_radius": Param(0.003, 0.02, doc="rounding of the door edges (m)"),
        "base_height": Param(0.04, 0.1, doc="height of the grilled kick plate under the doors (m)"),
        "dispenser": Param(kind="bool", doc="water/ice dispenser recess in a fridge door"),
    }

    DOOR_GAP = 0.006  # the gasket sits in this gap

    def _compartments(self, p) -> dict[str, tuple[float, float]]:
        """Inner z-ranges of the fridge and freezer compartments."""
        H, zb, w = p["height"], p["base_height"], COLD_WALL
        z0, z1 = zb + w, H - w
        if p["style"] == "single":
            return {"fridge": (z0, z1)}
        zf = (H - zb) * p["freezer_frac"]
        if p["style"] == "top_freezer":
            zd = H - zf
            return {"fridge": (z0, zd - w / 2), "freezer": (zd + w / 2, z1)}
        zd = zb + zf
        return {"fridge": (zd + w / 2, z1), "freezer": (z0, zd - w / 2)}

    def _leaves(self, p) -> list[_Leaf]:
        """The doors and the freezer drawer, by style."""
        W, H, zb = p["width"], p["height"], p["base_height"]
        comp = self._compartments(p)
        r, hs, full = 0.002, p["hinge_side"], (-W / 2, W / 2)
        if p["style"] == "single":
            return [_Leaf("door_fridge", hs, *full, zb + r, H, True)]
        if p["style"] == "top_freezer":
            zd = (comp["fridge"][1] + comp["freezer"][0]) / 2
        else:
            zd = (comp["fridge"][0] + comp["freezer"][1]) / 2
        lo, hi = (zb + r, zd - r), (zd + r, H)
        if p["style"] == "top_freezer":
            return [_Leaf("door_fridge", hs, *full, *lo, True),
                    _Leaf("door_freezer", hs, *full, *hi, False)]
        if p["style"] == "bottom_freezer":
            return [_Leaf("door_fridge", hs, *full, *hi, True),
                    _Leaf("door_freezer", hs, *full, *lo, False)]
        return [_Leaf("door_left", "left", -W / 2, -r, *hi, True),
                _Leaf("door_right", "right", r, W / 2, *hi, True),
                _Leaf("drawer_freezer", "drawer", *full, *lo, False)]

    def _handle_proud(self, p) -> float:
        return 0.05 if p["handle"] == "bar" else 0.03

    def _leaf_parts(self, p, leaf: _Leaf) -> tuple[list[Part], DoorJoint]:
        """A leaf's parts (slab, gasket, handle, door bins or freezer basket) and its motion."""
        D, W, dt = p["depth"], p["width"], p["door_thickness"]
        fx = D / 2
        x0, x1 = fx + self.DOOR_GAP, fx + self.DOOR_GAP + dt
        y0, y1, z0, z1, link = leaf.y0, leaf.y1, leaf.z0, leaf.z1, leaf.link
        er = min(p["edge_radius"], 0.4 * dt)
        slab = bevel_box((dt, y1 - y0, z1 - z0), ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), er, 2)
        w = COLD_WALL
        cy0, cy1 = -W / 2 + w, W / 2 - w
        extra: list[Part] = []
        if p["dispenser"] and link in ("door_fridge", "door_left") and y1 - y0 > 0.3 and z1 - z0 > 0.7:
            slab, extra = _dispenser(slab, x1, leaf)
        out = [Part(slab, "appliance", link), *extra, Part(self._gasket(x0, leaf), "rubber", link)]
        hp = self._handle_proud(p)
        if leaf.kind == "drawer":
            zc = z1 - 0.06
            out.append(Part(pull_bar(x1, (y0 + 0.12, zc), (y1 - 0.12, zc), hp, 0.011, 12), "metal", link))
            f0, f1 = self._compartments(p)["freezer"]
            c = 2 * MOVING_GAP  # clear of the liner all round
            out.append(Part(open_shell((-D / 2 + w + 0.05, cy0 + c, f0 + c),
                                       (x0 + 0.001, cy1 - c, f1 - 0.03),
                                       0.005, open_top=True), "plastic", link))
            return out, slide_motion(link, (x1, 0.0, zc))
        free_edge, toward = (y1, -1.0) if leaf.kind == "left" else (y0, 1.0)
        L = self._handle_z(p, leaf)
        out.append(Part(_grip(x1, free_edge, toward, L[0], L[1], p["handle"], hp), "metal", link))
        if leaf.fridge:  # door bins: open-topped trays on the inner face reaching into the cavity
            by0 = max(y0, cy0) + 0.012
            by1 = min(y1, cy1) - 0.012
            for zt in _shelf_levels(z0 + 0.05, z1 - 0.1, 3):
                out.append(Part(open_shell((fx - 0.05, by0, zt - 0.09), (x0 + 0.001, by1, zt), 0.004,
                                           open_top=True),
                                "plastic", link))
        return out, hinge_motion(leaf.kind, x1, y0, y1, z0, z1, link)

    def _gasket(self, x0: float, leaf: _Leaf) -> m3d.Manifold:
        """A rubber ring on the back of a leaf (whose back is at x0), standing in the door gap."""
        g, m = 0.02, 0.01
        outer = box_between((x0 - self.DOOR_GAP + 0.0015, leaf.y0 + m, leaf.z0 + m),
                            (x0 + 0.001, leaf.y1 - m, leaf.z1 - m))
        return outer - box_between((x0 - 0.02, leaf.y0 + m + g, leaf.z0 + m + g),
                                   (x0 + 0.01, leaf.y1 - m - g, leaf.z1 - m - g))

    def _handle_z(self, p, leaf: _Leaf) -> tuple[float, float]:
        """(bottom, top) of a door's handle: fridge doors' around chest height (or next to the
        freezer door's), freezer doors' next to the split between the two doors."""
        z0, z1 = leaf.z0, leaf.z1
        h = z1 - z0
        if leaf.fridge:
            L = min(p["handle_length"], 0.7 * h)
            if p["style"] == "top_freezer":
                za = z1 - 0.05 - L
            else:
                za = min(max(1.1 - L / 2, z0 + 0.08), z1 - 0.08 - L)
        else:
            L = min(0.25, 0.6 * h)
            za = z0 + 0.05 if p["style"] == "top_freezer" else z1 - 0.05 - L
        return za, za + L

    def parts(self, p, detail):
        """The fridge's solids: detailed, or the blocks of its placeholder."""
        D, W, H, zb, dt = p["depth"], p["width"], p["height"], p["base_height"], p["door_thickness"]
        if not detail:
            x1 = D / 2 + self.DOOR_GAP + dt + self._handle_proud(p)
            return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, H)), "appliance"),
                    Part(box_between((D / 2 - 0.01, -W / 2, zb), (x1, W / 2, H)), "appliance")]
        w = COLD_WALL
        comp = self._compartments(p)
        body = box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, H))
        cutters = [box_between((-D / 2 + w, -W / 2 + w, z0), (D / 2 + 0.01, W / 2 - w, z1))
                   for z0, z1 in comp.values()]
        cutters += _vent_slots(D / 2, -W / 2 + 0.05, W / 2 - 0.05, 0.012, zb - 0.01)
        out = [Part(m3d.Manifold.batch_boolean([body] + cutters, m3d.OpType.Subtract), "appliance")]
        # a plastic liner inside each compartment (its visible faces are the cavity's)
        for z0, z1 in comp.values():
            out.append(Part(open_shell((-D / 2 + w - 0.001, -W / 2 + w - 0.001, z0 - 0.001),
                                       (D / 2 - 0.003, W / 2 - w + 0.001,
                                        z1 + 0.001), LINER + 0.001), "plastic"))
        for zs in self._shelves(p):
            out.append(Part(box_between((-D / 2 + w - 0.001, -W / 2 + w - 0.002, zs - 0.006),
                                        (D / 2 - 0.075, W / 2 - w + 0.002, zs)), "glass"))
        for leaf in self._leaves(p):
            out += self._leaf_parts(p, leaf)[0]
        return out

    def _shelves(self, p) -> list[float]:
        z0, z1 = self._compartments(p)["fridge"]
        levels = _shelf_levels(z0, z1, int(p["n_shelves"]))
        if "freezer" in self._compartments(p) and p["style"] != "french":
            f0, f1 = self._compartments(p)["freezer"]
            if f1 - f0 > 0.35:
                levels.append((f0 + f1) / 2)
        return levels

    def joints(self, p):
        """The fridge's joints, one per door and freezer drawer."""
        D = p["depth"]
        return [joint_for(self._leaf_parts(p, leaf)[1], slide=0.7 * (D - COLD_WALL - 0.05))
                for leaf in self._leaves(p)]

    def extra_surfaces(self, p):
        """The fridge's surfaces besides its bounding box's: top, bottom, interior_<i> (floors, shelves)."""
        D, W, H = p["depth"], p["width"], p["height"]
        w = COLD_WALL
        levels = [(z0 + LINER, D / 2 - 0.06) for z0, _ in self._compartments(p).values()]
        levels += [(z, D / 2 - 0.075) for z in self._shelves(p)]
        out = [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02),
               bottom_rect((0, 0, 0), D / 2, W / 2)]
        for i, (z, x1) in enumerate(sorted(levels)):
            out.append(interior_rect(f"interior_{i}", -D / 2 + w + LINER, x1, -W / 2 + w + LINER,
                                     W / 2 - w - LINER, z))
        return out


# ----------------------------------------------------------------------- beverage fridge
@register
class BeverageFridge(PartsFactory):
    """An under-counter beverage fridge: an insulated cabinet on a vented kick plate, a
    full-height glass door in a frame (hinged left or right, bar or profile handle), wire or
    glass shelves visible through it, and an optional LED strip lighting the cavity. Shelves
    are `interior_i` surfaces; `top` is a support surface."""

    name = "beverage_fridge"
    # not tagged Fridge: a kitchen's one fridge ("a fridge" in programs) must be a full one
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.BeverageFridge})
    size_class = "large"
    slots = ["appliance", "plastic", "glass", "metal", "emissive"]
    solid_bottom = True
    params = {
        "width": Param(0.38, 0.61, doc="Y extent (m)"),
        "depth": Param(0.5, 0.6, doc="X extent of the cabinet without its door (m)"),
        "height": Param(0.82, 0.88, doc="Z extent (fits under a countertop) (m)"),
        "frame_width": Param(0.03, 0.07, doc="width of the door frame around the glass (m)"),
        "n_shelves": Param(3, 6, kind="int", doc="shelves inside"),
        "shelf_style": Param(kind="choice", choices=("wire", "glass"), doc="wire racks or glass shelves"),
        "hinge_side": Param(kind="choice", choices=("left", "right"), doc="door hinge side"),
        "handle": Param(kind="choice", choices=("bar", "edge"), doc="round bar or profile strip"),
        "base_height": Param(0.06, 0.11, doc="height of the vented kick plate (m)"),
        "light": Param(kind="bool", doc="LED strip under the cavity's ceiling"),
    }

    DOOR_T = 0.04
    RACK = (0.0025, 0.028)  # wire shelf bar half-thickness and pitch (m)

    def _cavity(self, p) -> tuple[float, float, float, float, float, float]:
        D, W, H, zb, w = p["depth"], p["width"], p["height"], p["base_height"], COLD_WALL
        return -D / 2 + w, D / 2, -W / 2 + w, W / 2 - w, zb, H - w

    def _shelves(self, p) -> list[float]:
        _, _, _, _, z0, z1 = self._cavity(p)
        return _shelf_levels(z0, z1 - 0.05, int(p["n_shelves"]))

    def _door(self, p) -> tuple[list[Part], Any]:
        D, W, H, zb = p["depth"], p["width"], p["height"], p["base_height"]
        x0, x1 = D / 2 + MOVING_GAP, D / 2 + MOVING_GAP + self.DOOR_T
        y0, y1, z0, z1 = -W / 2, W / 2, zb - 0.03, H
        fw = p["frame_width"]
        parts = window_leaf(x0, x1, y0, y1, z0, z1, (fw, fw, fw + 0.02, fw), "door", "metal")
        hs = p["hinge_side"]
        edge, toward = (y1, -1.0) if hs == "left" else (y0, 1.0)
        zh = z0 + 0.5 * (z1 - z0)
        proud = 0.045 if p["handle"] == "bar" else 0.03
        if p["handle"] == "bar":  # on the frame's stile
            y = edge + toward * fw / 2
            parts.append(Part(pull_bar(x1, (y, zh - 0.18), (y, zh + 0.2), proud, 0.009, 12), "metal",
                              "door"))
        else:
            parts.append(Part(_grip(x1, edge, toward, zh - 0.2, zh + 0.2, "edge", proud), "metal", "door"))
        return parts, hinge_motion(hs, x1, y0, y1, z0, z1, "door")

    def parts(self, p, detail):
        """The beverage fridge's solids: detailed, or the blocks of its placeholder."""
        D, W, H, zb = p["depth"], p["width"], p["height"], p["base_height"]
        if not detail:
            proud = 0.045 if p["handle"] == "bar" else 0.03
            return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, H)), "appliance"),
                    Part(box_between((D / 2 - 0.01, -W / 2, zb - 0.03),
                                     (D / 2 + MOVING_GAP + self.DOOR_T + proud, W / 2, H)),
                         "appliance")]
        cx0, cx1, cy0, cy1, cz0, cz1 = self._cavity(p)
        # cabinet: the cavity from the kick plate up; the kick plate itself is recessed and vented
        body = box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, H))
        cutters = [box_between((cx0, cy0, cz0), (cx1 + 0.01, cy1, cz1)),
                   box_between((D / 2 - 0.03, -W / 2 - 0.01, -0.01),
                               (D / 2 + 0.01, W / 2 + 0.01, zb - 0.03))]
        cutters += _vent_slots(D / 2 - 0.03, -W / 2 + 0.04, W / 2 - 0.04, 0.01, zb - 0.04)
        out = [Part(m3d.Manifold.batch_boolean([body] + cutters, m3d.OpType.Subtract), "appliance"),
               Part(open_shell((cx0 - 0.001, cy0 - 0.001, cz0 - 0.001),
                               (cx1 - 0.003, cy1 + 0.001, cz1 + 0.001),
                               LINER + 0.001), "plastic")]
        sx1 = cx1 - 0.03
        for zs in self._shelves(p):
            if p["shelf_style"] == "wire":
                out.append(Part(wire_rack(*self._rack_extent(p), zs, *self.RACK), "metal"))
            else:
                out.append(Part(box_between((cx0, cy0 - 0.001, zs - 0.006), (sx1, cy1 + 0.001, zs)),
                                "glass"))
        if p["light"]:
            out.append(Part(box_between((cx0 + 0.02, cy0 + 0.03, cz1 - 0.008),
                                        (cx0 + 0.06, cy1 - 0.03, cz1 + 0.001)),
                            "emissive"))
        out += self._door(p)[0]
        return out

    def joints(self, p):
        """The beverage fridge's joint: its glass door's."""
        return [joint_for(self._door(p)[1])]

    def extra_surfaces(self, p):
        """The beverage fridge's surfaces besides its bounding box's: top, bottom, interior_<i>."""
        D, W, H = p["depth"], p["width"], p["height"]
        cx0, cx1, cy0, cy1, cz0, _ = self._cavity(p)
        out = [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02),
               bottom_rect((-0.015, 0, 0), D / 2 - 0.015, W / 2)]
        out.append(interior_rect("interior_0", cx0 + LINER, cx1 - 0.03, cy0 + LINER, cy1 - LINER,
                                 cz0 + LINER))
        x0, x1, y0, y1 = self._rack_extent(p)
        for i, z in enumerate(self._shelves(p)):
            if p["shelf_style"] == "wire":
                out.append(rack_surface(f"interior_{i + 1}", x0, x1, y0, y1, z, *self.RACK,
                                        (x0, x1, cy0 + LINER, cy1 - LINER)))
            else:
                out.append(interior_rect(f"interior_{i + 1}", cx0 + LINER, cx1 - 0.03, cy0 + LINER,
                                         cy1 - LINER, z))
        return out

    def _rack_extent(self, p) -> tuple[float, float, float, float]:
        """(x0, x1, y0, y1) of the wire shelves (their ends sunk into the liner)."""
        cx0, cx1, cy0, cy1, _, _ = self._cavity(p)
        return cx0 + 0.005, cx1 - 0.03, cy0 - 0.001, cy1 + 0.001
