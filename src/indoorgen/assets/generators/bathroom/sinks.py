"""Bathroom washbasins: pedestal sinks, vessel basins on a countertop, and vanities.

Fronts face +X; a fixture against a wall has its back at -X. Basins are real hollows
(manifold3d subtraction), open at the top.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.bathroom._parts import (
    FAUCET_STYLES,
    FIXTURE_MATERIALS,
    bowl_cavity_levels,
    bowl_skin,
    ellipse,
    faucet_footprint,
    faucet_parts,
    hollow,
    hull_stack,
    outline_polygon,
    polygon_pieces,
    rounded_rect,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass, legs
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, MOVING_GAP, Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, circle_polygon, cylinder, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class BathroomSinkPedestal(PartsFactory):
    """A pedestal washbasin: a ceramic basin (rectangular, oval or round bowl, hollowed) with a
    flat tap deck along its back, standing on a column, tapered or flared pedestal; a deck
    tap (lever mixer, gooseneck or two handles). The basin's back sits against the wall."""

    name = "bathroom_sink_pedestal"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.BathroomSink})
    size_class = "large"
    slots = ["porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("porcelain", "metal")}
    solid_bottom = True
    params = {
        "basin_shape": Param(kind="choice", choices=("rect", "oval", "round"), doc="bowl and basin outline"),
        "width": Param(0.45, 0.65, doc="basin Y extent (m)"),
        "depth": Param(0.38, 0.52, doc="basin X extent, wall to front (m)"),
        "height": Param(0.8, 0.88, doc="height of the basin rim (m)"),
        "basin_thickness": Param(0.16, 0.22, doc="Z extent of the basin body (m)"),
        "bowl_depth": Param(0.1, 0.15, doc="depth of the bowl below the rim (m)"),
        "deck_depth": Param(0.07, 0.11, doc="depth of the flat tap deck at the back (m)"),
        "pedestal_style": Param(kind="choice", choices=("column", "tapered", "flared"),
                                doc="pedestal profile"),
        "pedestal_radius": Param(0.07, 0.12, doc="pedestal radius at its waist (m)"),
        "faucet_style": Param(kind="choice", choices=FAUCET_STYLES, doc="tap type"),
        "corner_radius": Param(0.02, 0.08, doc="corner rounding of the basin outline (m)"),
    }

    def _geometry(self, p) -> dict[str, Any]:
        W, D, H = p["width"], p["depth"], p["height"]
        deck, rim = p["deck_depth"], 0.03
        lx = D - deck - rim
        ly = W - 2 * rim
        if p["basin_shape"] == "round":
            lx = ly = min(lx, ly)
        cx = -D / 2 + deck + lx / 2
        depth = min(p["bowl_depth"], p["basin_thickness"] - 0.03)
        return dict(W=W, D=D, H=H, deck=deck, lx=lx, ly=ly, cx=cx, depth=depth,
                    T=p["basin_thickness"], wall=0.012, fx=-D / 2 + deck / 2)

    def _outline(self, p, g) -> m3d.CrossSection:
        W, D, r = g["W"], g["D"], p["corner_radius"]
        if p["basin_shape"] == "rect":
            return rounded_rect(D, W, r)
        back = rounded_rect(g["deck"] + 0.02, W, min(r, 0.03), (-D / 2 + (g["deck"] + 0.02) / 2, 0.0))
        a = (D - g["deck"]) / 2
        front = ellipse(a, W / 2, (D / 2 - a, 0.0), 64)
        return m3d.CrossSection.batch_hull([back, front])

    def _cavity(self, p, g):
        return bowl_cavity_levels(p["basin_shape"], g["lx"], g["ly"], g["depth"], g["cx"], 0.0,
                                  g["H"], radius=max(p["corner_radius"], 0.03))

    def parts(self, p, detail):
        """The pedestal sink's solids: detailed, or the blocks of its placeholder."""
        g = self._geometry(p)
        H, W, D = g["H"], g["W"], g["D"]
        # the basin's underside reaches the bowl's skin (a wall below the bowl's floor)
        basin_bottom = max(H - g["T"], H - g["depth"] - g["wall"])
        rp = p["pedestal_radius"]
        z_top = basin_bottom + 0.006
        prof = {"column": (1.25, 1.0, 1.15), "tapered": (1.35, 1.1, 0.85),
                "flared": (1.6, 1.0, 1.2)}[p["pedestal_style"]]
        r_foot, r_mid, r_top = (rp * k for k in prof)
        cx = g["cx"]
        out: list[Part] = []
        if detail:
            outline = self._outline(p, g)
            cav = self._cavity(p, g)
            skin = bowl_skin(cav, g["wall"], H - 0.03)
            under = outline.offset(-0.04, m3d.JoinType.Round, 2.0, 24)
            outer = hull_stack([(H, outline), (H - 0.025, outline), (basin_bottom + 0.02, under)]
                                + [(max(z, basin_bottom), cs) for z, cs in skin])
            out.append(Part(hollow(outer, cav), "porcelain"))
            pts = [(0.0, 0.0), (r_foot, 0.0), (r_foot, 0.015), (r_mid, z_top * 0.5),
                   (r_top, z_top), (0.0, z_top)]
            out.append(Part(lathe(pts, 48).translate((cx, 0.0, 0.0)), "porcelain"))
            out.append(Part(cylinder(0.02, 0.004, (cx, 0.0, H - g["depth"] - 0.003), 24), "metal"))
        else:
            out.append(Part(box_between((-D / 2, -W / 2, basin_bottom), (D / 2, W / 2, H)), "porcelain"))
            rmax = max(r_foot, r_mid, r_top)
            out.append(Part(cylinder(rmax, z_top + OVERLAP, (cx, 0.0, 0.0), 12, circumscribed=True),
                            "porcelain"))
        out += faucet_parts(g["fx"], 0.0, H, p["faucet_style"], 0.16, g["deck"] / 2 + 0.1, detail)
        return out

    def extra_surfaces(self, p):
        """The pedestal sink's surfaces besides its bounding box's: bottom, deck_<i>."""
        g = self._geometry(p)
        rp = p["pedestal_radius"] * {"column": 1.25, "tapered": 1.35, "flared": 1.6}[p["pedestal_style"]]
        out = [support_polygon("bottom", (g["cx"], 0, 0), circle_polygon(rp * 0.995, 48),
                               subpart=Subpart.Bottom, up=False)]
        # the tap deck either side of the tap
        x0, x1 = -g["D"] / 2 + 0.01, g["cx"] - g["lx"] / 2 - 0.01
        deck = sg.box(x0, -g["W"] / 2 + 0.05, x1, g["W"] / 2 - 0.05)
        deck = deck.difference(faucet_footprint(g["fx"], 0.0, p["faucet_style"]).buffer(0.01))
        if x1 - x0 > 0.02:
            out += [support_polygon(f"deck_{i}", (0, 0, g["H"]), q)
                    for i, q in enumerate(polygon_pieces(deck, 4e-4))]
        return out


VESSEL_SHAPES = ("round", "oval", "rect", "square")


def _vessel_section(shape: str, lx: float, ly: float, r: float, center=(0.0, 0.0)):
    """A section of a vessel of full size lx (X) by ly (Y) at scale 1."""
    if shape in ("rect", "square"):
        return lambda s: rounded_rect(lx * s, ly * s, r * s, center)
    return lambda s: ellipse(lx * s / 2, ly * s / 2, center, 64)


def vessel_bounds(lx: float, ly: float, height: float, lip: bool,
                  center: tuple[float, float, float] = (0.0, 0.0, 0.0)
                  ) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(lo, hi) corners of the box around a `vessel` (its rim, or lip, is its widest part)."""
    e = 0.012 if lip else 0.0
    c = np.asarray(center, float)
    return tuple(c - (lx / 2 + e, ly / 2 + e, 0.0)), tuple(c + (lx / 2 + e, ly / 2 + e, height))


def vessel(shape: str, lx: float, ly: float, height: float, wall: float, flare: float,
           curve: float, foot: float, lip: bool, radius: float = 0.04,
           center: tuple[float, float, float] = (0.0, 0.0, 0.0)
           ) -> tuple[m3d.Manifold, m3d.CrossSection, m3d.CrossSection, float]:
    """A vessel basin standing at `center` (x, y, floor z): a hollow bowl lx (X) by ly (Y) at
    its rim, `height` tall, whose sections shrink to `flare` at the bottom along u^curve
    (curve < 1: a rounded belly), on an optional foot `foot` tall (>= 5 mm) and with an
    optional flat lip. Returns (solid, footprint on the floor, section of the hollow's flat
    floor, z of that floor); the solid is a function, so that it is only built when needed."""
    cx, cy, cz = center
    sec = _vessel_section(shape, lx, ly, radius, (cx, cy))
    has_foot = foot >= 0.005
    zb = cz + (foot if has_foot else 0.0)
    zt = cz + height

    def size(u: float) -> float:  # section scale at height fraction u
        return flare + (1.0 - flare) * u ** curve

    def zu(u: float) -> float:  # height at fraction u
        return zb + 0.012 + u * (zt - zb - 0.012)

    us = (0.0, 0.08, 0.2, 0.4, 0.6, 0.8, 1.0)
    z_floor = zb + max(wall, 0.012) + 0.006
    floor = sec(size(0.08)).offset(-wall - 0.02, m3d.JoinType.Round, 2.0, 24)
    footprint = sec(flare * 0.85) if has_foot else sec(flare - 0.03)

    def solid() -> m3d.Manifold:
        body = hull_stack([(zb, sec(flare - 0.03))] + [(zu(u), sec(size(u))) for u in us])

        def inset(u: float) -> m3d.CrossSection:
            return sec(size(u)).offset(-wall, m3d.JoinType.Round, 2.0, 24)

        cav = [(zt + 0.05, inset(1.0))] + [(zu(u), inset(u)) for u in reversed(us)
                                           if zu(u) > z_floor + 0.02] + [(z_floor, floor)]
        if lip:
            body = body + m3d.Manifold.extrude(sec(1.0).offset(0.012, m3d.JoinType.Round, 2.0, 24),
                                               0.01).translate((0.0, 0.0, zt - 0.01))
        if has_foot:
            body = body + m3d.Manifold.extrude(footprint, zb - cz + OVERLAP).translate((0.0, 0.0, cz))
        return body - hull_stack(cav)

    return solid, footprint, floor, z_floor


def _vessel_args(p: dict[str, Any]) -> tuple[str, float, float]:
    """(shape, lx, ly) of a vessel basin's params (round and square ignore the aspect)."""
    L = p["length"]
    aspect = 1.0 if p["shape"] in ("round", "square") else p["aspect"]
    return p["shape"], L * aspect, L


@register
class CountertopBasin(PartsFactory):
    """A vessel washbasin that sits on a countertop: a hollow round, oval, rectangular or square
    bowl with straight or bellied walls, optionally on a foot and with a flat lip, and a
    drain in its floor. Its bottom (the foot) rests on the counter."""

    name = "countertop_basin"
    tags = frozenset({S.Object, S.BathroomFixture, S.BathroomSink})
    size_class = "small"
    slots = ["porcelain", "metal"]
    material_choices = {"porcelain": {"porcelain": 3.0, "glazed_ceramic": 1.0, "marble": 1.0,
                                      "concrete": 0.5},
                        "metal": FIXTURE_MATERIALS["metal"]}
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=VESSEL_SHAPES, doc="outline of the bowl"),
        "length": Param(0.35, 0.6, doc="Y extent at the rim (m)"),
        "aspect": Param(0.6, 0.85, doc="X extent / Y extent (oval and rect; round and square: 1)"),
        "height": Param(0.1, 0.2, doc="Z extent (m)"),
        "wall_thickness": Param(0.006, 0.014, doc="wall thickness (m)"),
        "flare": Param(0.45, 0.85, doc="bottom section / rim section (taper of the walls)"),
        "curve": Param(0.35, 1.0, doc="wall profile exponent (1 straight, < 1 bellied)"),
        "foot_height": Param(0.0, 0.03, doc="height of a foot under the bowl (< 5 mm: none) (m)"),
        "lip": Param(kind="bool", doc="flat lip around the rim"),
        "corner_radius": Param(0.02, 0.06, doc="corner rounding of rect and square bowls (m)"),
    }

    def _build(self, p):
        shape, lx, ly = _vessel_args(p)
        return vessel(shape, lx, ly, p["height"], p["wall_thickness"], p["flare"], p["curve"],
                      p["foot_height"], p["lip"], p["corner_radius"])

    def parts(self, p, detail):
        """The countertop basin's solids: detailed, or the blocks of its placeholder."""
        shape, lx, ly = _vessel_args(p)
        if not detail:
            return [Part(box_between(*vessel_bounds(lx, ly, p["height"], p["lip"])), "porcelain")]
        shell, _, _, z_floor = self._build(p)
        return [Part(shell(), "porcelain"),
                Part(cylinder(0.022, 0.0035, (0.0, 0.0, z_floor - 0.003), 24), "metal")]

    def extra_surfaces(self, p):
        """The countertop basin's surfaces besides its bounding box's: bottom, basin."""
        _, footprint, floor, z_floor = self._build(p)
        basin = outline_polygon(floor, 0.003).difference(sg.Point(0, 0).buffer(0.026, 16))
        return [support_polygon("bottom", (0, 0, 0), outline_polygon(footprint, 0.0005),
                                subpart=Subpart.Bottom, up=False),
                support_polygon("basin", (0, 0, z_floor), basin, subpart=Subpart.Interior)]


# -------------------------------------------------------------------------------- vanity
BOARD = 0.018
BOWL_DEPTH = 0.16  # depth of an undermount bowl below the countertop's top face


@register
class Vanity(PartsFactory):
    """A bathroom vanity: a cabinet on a plinth or legs under a stone countertop with one or
    two basins (undermount bowls cut into the top, or vessel bowls standing on it) and a deck
    tap behind each; under each basin doors, or a fixed false front over drawers, optionally
    beside a column of drawers. Doors and drawers are articulated; the countertop around the
    basins is a support surface and the cabinet floor behind doors an interior surface."""

    name = "vanity"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.BathroomSink, S.Vanity,
                      S.Storage, S.Cabinet})
    size_class = "large"
    slots = ["wood", "front", "countertop", "porcelain", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("wood", "front", "countertop",
                                                         "porcelain", "metal")}
    params = {
        "width": Param(0.6, 1.6, doc="Y extent (m)"),
        "depth": Param(0.45, 0.56, doc="cabinet X extent (m); the top overhangs 15 mm"),
        "height": Param(0.8, 0.9, doc="height of the countertop's top face (m)"),
        "n_basins": Param(1, 2, kind="int", doc="basins (2 only when width >= 1.2 m)"),
        "basin_type": Param(kind="choice", choices=("undermount", "vessel"),
                            doc="bowl under the top or standing on it"),
        "basin_shape": Param(kind="choice", choices=("oval", "rect", "round"), doc="bowl outline"),
        "front_style": Param(kind="choice", choices=("doors", "drawers", "doors_drawers"),
                             doc="doors under the basin, drawers (under a false front), or doors "
                                 "beside a drawer column (one basin, width >= 0.8 m)"),
        "base_style": Param(kind="choice", choices=("plinth", "legs"), doc="recessed plinth or legs"),
        "base_height": Param(0.08, 0.2, doc="plinth or leg height (m)"),
        "top_thickness": Param(0.02, 0.04, doc="countertop thickness (m)"),
        "backsplash": Param(kind="bool", doc="upstand along the back of the top"),
        "faucet_style": Param(kind="choice", choices=FAUCET_STYLES, doc="tap type"),
        "handle": Param(kind="choice", choices=("bar", "knob"), doc="door and drawer pulls"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        W, D, H, tt = p["width"], p["depth"], p["height"], p["top_thickness"]
        n = int(p["n_basins"]) if W >= 1.2 else 1
        inner0, inner1 = -W / 2 + BOARD, W / 2 - BOARD
        # side sections: a drawer column (doors_drawers, drawers) or a cupboard (doors), on one
        # side when there is room (doors_drawers) and on both sides of a basin bay that would
        # otherwise be wider than 0.9 m
        side = "cupboard" if p["front_style"] == "doors" else "column"
        span = inner1 - inner0
        n_side = 0
        if n == 1 and span > 0.9 + 0.3 + BOARD:
            n_side = 2 if span > 0.9 + 2 * (0.3 + BOARD) else 1
        elif n == 1 and p["front_style"] == "doors_drawers" and W >= 0.8:
            n_side = 1
        wc = 0.0
        if n_side:
            wc = min(max(0.3 * W, 0.3), 0.45)
            wc = max(wc, (span - 0.9 - n_side * BOARD) / n_side)
        bays: list[tuple[float, float, str]] = []  # (y0, y1, kind) of the inner openings
        y = inner0
        if n_side:
            bays.append((y, y + wc, side))
            y += wc + BOARD
        bw = (inner1 - y - (n - 1) * BOARD - (wc + BOARD if n_side == 2 else 0.0)) / n
        for _ in range(n):
            bays.append((y, y + bw, "basin"))
            y += bw + BOARD
        if n_side == 2:
            bays.append((y, y + wc, side))
        zb = p["base_height"]
        return dict(W=W, D=D, H=H, tt=tt, n=n, bays=bays, zb=zb, z0=zb + BOARD, z1=H - tt,
                    oh=0.015, bs=0.015 if p["backsplash"] else 0.0)

    def _basins(self, p, g) -> list[dict[str, float]]:
        """Each basin's opening centre (cx, cy) and size (lx, ly), and its tap's base x."""
        D, oh = g["D"], g["oh"]
        out = []
        for y0, y1, kind in g["bays"]:
            if kind != "basin":
                continue
            bw = y1 - y0
            lx, ly = min(0.42, D - 0.19), min(0.55, bw - 0.16)
            if p["basin_type"] == "vessel":
                lx, ly = min(0.4, D - 0.17), min(0.5, bw - 0.1)
            if p["basin_shape"] == "round":
                lx = ly = min(lx, ly)
            cx = D / 2 + oh - 0.06 - lx / 2
            fx = max(cx - lx / 2 - 0.05, -D / 2 + g["bs"] + 0.045)
            out.append(dict(cx=cx, cy=(y0 + y1) / 2, lx=lx, ly=ly, fx=fx))
        return out

    def _cells(self, p, g) -> tuple[list[Front], list[tuple[float, float, float, float]]]:
        """The moving fronts, and the fixed false fronts (y0, y1, z0, z1) over undermount bowls."""
        z0, z1 = g["z0"], g["z1"]
        cells, fixed = [], []
        under = p["basin_type"] == "undermount"
        for y0, y1, kind in g["bays"]:
            if kind == "cupboard":
                cells.append(Front(y0, y1, z0, z1, "right" if y0 > 0 else "left"))
            elif kind == "column":
                k = 3 if z1 - z0 > 0.5 else 2
                hs = np.linspace(z0, z1, k + 1)
                cells += [Front(y0, y1, float(a), float(b), "drawer")
                          for a, b in zip(hs[:-1], hs[1:], strict=True)]
            elif p["front_style"] == "drawers":
                top = z1
                if under:
                    top = z1 - BOWL_DEPTH + g["tt"] - 0.03
                    fixed.append((y0, y1, top, z1))
                k = 2 if top - z0 > 0.3 else 1
                hs = np.linspace(z0, top, k + 1)
                cells += [Front(y0, y1, float(a), float(b), "drawer")
                          for a, b in zip(hs[:-1], hs[1:], strict=True)]
            elif y1 - y0 > 0.55:
                ym = (y0 + y1) / 2
                cells += [Front(y0, ym, z0, z1, "left"), Front(ym, y1, z0, z1, "right")]
            else:
                cells.append(Front(y0, y1, z0, z1, "left"))
        return cells, fixed

    def _fronts(self, p, g):
        cells, _ = self._cells(p, g)
        return cabinet_fronts(g["D"] / 2, cells, g["D"] - 0.006 - 0.03, handle=p["handle"])

    # ---- geometry
    def _basin_solids(self, p, g, b) -> tuple[list[tuple[m3d.Manifold, str]], m3d.Manifold | None]:
        """(solid, slot) pieces of one basin, and the cut it makes in the countertop."""
        H, tt = g["H"], g["tt"]
        shape = p["basin_shape"]
        if p["basin_type"] == "vessel":
            shell, _, _, zf = vessel(shape, b["lx"], b["ly"], 0.14, 0.01, 0.6, 0.6, 0.0, False,
                                     0.04, (b["cx"], b["cy"], H - OVERLAP))
            return [(shell(), "porcelain"),
                    (cylinder(0.022, 0.0035, (b["cx"], b["cy"], zf - 0.003), 24), "metal")], None
        cav = bowl_cavity_levels(shape, b["lx"], b["ly"], BOWL_DEPTH, b["cx"], b["cy"], H, 0.05)
        skin = bowl_skin(cav, 0.012, H - tt + OVERLAP)
        cut = hull_stack(cav)
        drain = cylinder(0.022, 0.0035, (b["cx"], b["cy"], H - BOWL_DEPTH - 0.003), 24)
        return [(hull_stack(skin) - cut, "porcelain"), (drain, "metal")], cut

    def parts(self, p, detail):
        """The vanity's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        W, D, H, tt, zb = g["W"], g["D"], g["H"], g["tt"], g["zb"]
        dividers = [y1 + BOARD / 2 for (_, y1, _), _n in zip(g["bays"][:-1], g["bays"][1:], strict=True)]
        # (the placeholder's block of carcass and fronts stands for the boards)
        out = [Part(s.solid, "wood") for s in carcass(D, W, zb, H - tt + OVERLAP, BOARD, back=0.006,
                                                      dividers=dividers, top=False)] if detail else []
        top = box_between((-D / 2, -W / 2, H - tt), (D / 2 + g["oh"], W / 2, H))
        cuts = []
        for b in self._basins(p, g):
            if detail:
                pieces, cut = self._basin_solids(p, g, b)
                cuts += [cut] if cut is not None else []
                out += [Part(s, slot) for s, slot in pieces]
            elif p["basin_type"] == "vessel":
                out.append(Part(box_between(*vessel_bounds(b["lx"], b["ly"], 0.14, False,
                                                           (b["cx"], b["cy"], H - OVERLAP))), "porcelain"))
            else:
                hx, hy = b["lx"] / 2 + 0.012, b["ly"] / 2 + 0.012
                out.append(Part(box_between((b["cx"] - hx, b["cy"] - hy, H - BOWL_DEPTH - 0.012),
                                            (b["cx"] + hx, b["cy"] + hy, H - tt + OVERLAP)), "porcelain"))
            fh = 0.3 if p["basin_type"] == "vessel" else 0.16
            # a vessel's tap reaches over the bowl's middle, an undermount's 8 cm past its edge
            reach = (b["cx"] - b["fx"] if p["basin_type"] == "vessel"
                     else b["cx"] - b["lx"] / 2 - b["fx"] + 0.08)
            out += faucet_parts(b["fx"], b["cy"], H, p["faucet_style"], fh, reach, detail)
        out.append(Part(top - solid_union(cuts) if detail and cuts else top, "countertop"))
        if g["bs"]:
            out.append(Part(box_between((-D / 2, -W / 2, H - OVERLAP), (-D / 2 + g["bs"], W / 2, H + 0.1)),
                            "countertop"))
        _, fixed = self._cells(p, g)
        for y0, y1, z0, z1 in (fixed if detail else ()):
            out.append(Part(box_between((D / 2 - OVERLAP, y0 - OVERLAP, z0 + 0.002),
                                        (D / 2 + MOVING_GAP + 0.018, y1 + OVERLAP, z1 - 0.002)), "front"))
        if detail:
            out += [part for parts, _ in self._fronts(p, g) for part in parts]
        else:
            proud = FRONT_PROUD if p["handle"] == "bar" else MOVING_GAP + 0.018 + 0.025
            out.append(Part(box_between((-D / 2, -W / 2, zb), (D / 2 + proud, W / 2, H - tt + OVERLAP)),
                            "front"))
        if p["base_style"] == "plinth":
            out.append(Part(box_between((-D / 2, -W / 2, 0.0), (D / 2 - 0.05, W / 2, zb + OVERLAP)), "wood"))
        else:
            for leg in legs((D, W), 0.01, 0.04, 0.0, zb + OVERLAP, taper=0.6 if detail else 1.0,
                            round_legs=True, circumscribed=not detail, sections=16 if detail else 8):
                out.append(Part(leg, "metal"))
        return out

    def joints(self, p):
        """The vanity's joints, one per door and drawer."""
        g = self._g(p)
        depth = g["D"] - 0.006 - 0.03
        return [make_joint(f"{m.link}_joint", m, 0.0, math.radians(100)) if m.kind == "revolute"
                else make_joint(f"{m.link}_joint", m, 0.0, 0.8 * depth)
                for _, m in self._fronts(p, g)]

    def extra_surfaces(self, p):
        """The vanity's surfaces besides its bounding box's: countertop(_<i>), interior_<k>, back, bottom."""
        g = self._g(p)
        W, D, H = g["W"], g["D"], g["H"]
        top = sg.box(-D / 2 + g["bs"] + 0.01, -W / 2 + 0.01, D / 2 + g["oh"] - 0.01, W / 2 - 0.01)
        for b in self._basins(p, g):
            if p["basin_type"] == "vessel":
                hole = outline_polygon(ellipse(b["lx"] / 2, b["ly"] / 2, (b["cx"], b["cy"]))
                                if p["basin_shape"] != "rect" else
                                rounded_rect(b["lx"], b["ly"], 0.04, (b["cx"], b["cy"])))
            else:
                hole = outline_polygon(bowl_cavity_levels(p["basin_shape"], b["lx"], b["ly"], BOWL_DEPTH,
                                                   b["cx"], b["cy"], H, 0.05)[0][1])
            top = top.difference(hole.buffer(0.02)).difference(
                faucet_footprint(b["fx"], b["cy"], p["faucet_style"]).buffer(0.01))
        out = [support_polygon(f"countertop_{i}" if i else "countertop", (0, 0, H), q)
               for i, q in enumerate(polygon_pieces(top, 4e-3))]
        cells, _ = self._cells(p, g)
        k = 0
        for y0, y1, kind in g["bays"]:
            if kind == "cupboard" or (kind == "basin" and p["front_style"] != "drawers"):
                out.append(Surface.rect(f"interior_{k}", Subpart.Interior,
                                        (0.0, (y0 + y1) / 2, g["z0"]), (0, 0, 1), (1, 0, 0),
                                        D / 2 - 0.02, (y1 - y0) / 2 - 0.01))
                k += 1
        out.append(Surface.rect("back", Subpart.Back, (-D / 2, 0, (g["zb"] + H) / 2), (-1, 0, 0),
                                (0, 1, 0), W / 2, (H - g["zb"]) / 2))
        if p["base_style"] == "plinth":
            out.append(Surface.rect("bottom", Subpart.Bottom, (-0.025, 0, 0), (0, 0, -1), (1, 0, 0),
                                    D / 2 - 0.025, W / 2))
        return out

    def bottom_is_solid(self, params):
        """Whether the vanity stands on a plinth (its whole bottom), not on legs."""
        return self.resolve(params)["base_style"] == "plinth"
