"""Mirrors: framed wall mirrors (rectangular, round or arched) and full-length floor mirrors
(leaning, on an easel leg or tilting between cheval posts)."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.decor._parts import back_surface, wall_outline, yz_extrude
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.outlines import largest_polygon
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, box_between, rod
from indoorgen.model.tags import Semantics as S


def _framed_mirror(p: dict[str, Any], detail: bool, shape: str, W: float, H: float,
                   D: float) -> list[Part]:
    """A framed mirror standing in the plane x in [-D/2, D/2], z in [0, H], facing +X: backing
    board, frame ring (flat, stepped or rounded moulding) and the glass recessed behind the
    frame's front."""
    fw = min(p["frame_width"], 0.2 * W)
    bk = 0.004
    if not detail:
        cs = wall_outline(shape, W, H, 16, circumscribed=True)
        return [Part(yz_extrude(cs, -D / 2, D / 2), "frame")]
    cs = wall_outline(shape, W, H)
    out = [Part(yz_extrude(cs, -D / 2, -D / 2 + bk), "back")]
    steps = {"flat": [(0.0, 0.0, 1.0)], "stepped": [(0.0, 0.0, 0.55), (0.25, 0.15, 1.0)],
             "rounded": [(0.0, 0.0, 0.6), (0.08, 0.08, 0.8), (0.25, 0.25, 0.93), (0.42, 0.42, 1.0)]}
    x0 = -D / 2 + bk - SMALL_OVERLAP
    for out_in, in_in, xf in steps[p["frame_profile"]]:
        # each step a ring inset from the outer edge by out_in*fw and the inner edge by in_in*fw
        outer = cs.offset(-out_in * fw, m3d.JoinType.Round, 2.0, 64) if out_in else cs
        hole = cs.offset(-fw * (1 - in_in), m3d.JoinType.Round, 2.0, 64)
        out.append(Part(yz_extrude(outer - hole, x0, -D / 2 + xf * D), "frame"))
        x0 = -D / 2 + xf * D - SMALL_OVERLAP
    glass = cs.offset(-fw + 0.004, m3d.JoinType.Round, 2.0, 64)
    xg = D / 2 - max(p["glass_recess"], D * 0.2)
    out.append(Part(yz_extrude(glass, -D / 2 + bk - SMALL_OVERLAP, xg), "mirror"))
    return out


MIRROR_PARAMS = {
    "shape": Param(kind="choice", choices=("rect", "round", "arched"), doc="outline"),
    "frame_width": Param(0.015, 0.08, doc="frame moulding width (m)"),
    "frame_depth": Param(0.02, 0.05, doc="X extent of the frame (m)"),
    "frame_profile": Param(kind="choice", choices=("flat", "stepped", "rounded"),
                           doc="frame moulding profile"),
    "glass_recess": Param(0.004, 0.012, doc="how far the glass sits behind the frame front (m)"),
}


@register
class Mirror(PartsFactory):
    """A framed wall mirror: rectangular, round or arched, with a flat, stepped or rounded
    frame moulding and the glass set back behind it. Its flat backing board hangs on the wall."""

    name = "mirror"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.Mirror, S.WallMounted})
    size_class = "medium"
    slots = ["frame", "mirror", "back"]
    params = {
        **MIRROR_PARAMS,
        "width": Param(0.35, 1.0, doc="Y extent (m); a round mirror's diameter"),
        "height": Param(0.5, 1.4, doc="Z extent of rect/arched mirrors (m, >= width for arched)"),
    }

    def _dims(self, p) -> tuple[float, float]:
        W = p["width"]
        H = W if p["shape"] == "round" else (max(p["height"], W) if p["shape"] == "arched"
                                             else p["height"])
        return W, H

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Backing board, frame moulding and recessed glass."""
        W, H = self._dims(p)
        return _framed_mirror(p, detail, p["shape"], W, H, p["frame_depth"])

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The backing board's outline as the `back` against the wall."""
        W, H = self._dims(p)
        cs = wall_outline(p["shape"], W, H).offset(-0.001, m3d.JoinType.Miter, 2.0)
        return [back_surface(largest_polygon(cs), -p["frame_depth"] / 2)]


def _bar(p0, p1, width: float, thick: float) -> m3d.Manifold:
    """A rectangular bar from p0 to p1 lying in an XZ plane: `width` along Y, `thick` across."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = p1 - p0
    d /= np.linalg.norm(d)
    n = np.cross(d, [0.0, 1.0, 0.0])
    n /= np.linalg.norm(n)
    y = np.array([0.0, width / 2, 0.0])
    pts = [q + sy * y + sn * n * thick / 2 for q in (p0, p1) for sy in (-1, 1) for sn in (-1, 1)]
    return m3d.Manifold.hull_points(np.array(pts))


@register
class FloorMirror(PartsFactory):
    """A full-length floor mirror: `leaning` against the wall (resting on its bottom edge),
    on an `easel` (a rear leg hinged at the top) or a `cheval` (tilting between two posts on
    feet). Rectangular or arched, framed like the wall mirror."""

    name = "floor_mirror"
    tags = frozenset({S.Object, S.Furniture, S.Decor, S.Mirror})
    size_class = "large"
    slots = ["frame", "mirror", "back", "wood"]
    params = {
        "style": Param(kind="choice", choices=("leaning", "easel", "cheval"), doc="how it stands"),
        "shape": Param(kind="choice", choices=("rect", "arched"), doc="outline"),
        "width": Param(0.4, 0.8, doc="mirror Y extent (m)"),
        "height": Param(1.4, 1.85, doc="mirror Z extent (m)"),
        "frame_width": Param(0.02, 0.07, doc="frame moulding width (m)"),
        "frame_depth": Param(0.02, 0.04, doc="X extent of the frame (m)"),
        "frame_profile": Param(kind="choice", choices=("flat", "stepped", "rounded"),
                               doc="frame moulding profile"),
        "glass_recess": Param(0.004, 0.01, doc="how far the glass sits behind the frame front (m)"),
        "tilt": Param(3.0, 12.0, doc="backwards lean of the mirror (degrees)"),
        "foot_depth": Param(0.3, 0.5, doc="X extent of the easel's stance / cheval's feet (m)"),
    }

    def _panel(self, p, detail: bool) -> tuple[list[Part], float]:
        """The mirror parts, tilted, plus the height of their lowest point before trimming."""
        W, H, D = p["width"], p["height"], p["frame_depth"]
        style = p["style"]
        Hp = H - 0.14 if style == "cheval" else H
        parts = _framed_mirror(p, True, p["shape"], W, Hp, D)
        if not detail:  # the convex hull of the detailed panel: exact bounds once tilted
            parts = [Part(m3d.Manifold.batch_hull([q.solid for q in parts]), "frame")]
        t = p["tilt"]
        if style == "cheval":
            # tilt about a horizontal axis at mid height, 12 cm off the floor
            zc = 0.12 + Hp / 2
            return [Part(q.solid.translate((0, 0, -Hp / 2)).rotate((0, -t, 0))
                         .translate((0, 0, zc)), q.slot) for q in parts], 0.0
        # lean back about the bottom back edge, sunk 2 mm into the floor then trimmed flat
        moved = [Part(q.solid.translate((D / 2, 0, 0)).rotate((0, -t, 0))
                      .translate((0, 0, -0.002)).trim_by_plane((0, 0, 1), 0.0), q.slot)
                 for q in parts]
        return moved, 0.0

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The tilted framed panel and its easel leg or cheval posts and feet."""
        out, _ = self._panel(p, detail)
        W, H, t = p["width"], p["height"], math.radians(p["tilt"])
        style, fd = p["style"], p["foot_depth"]
        if style == "easel":
            # a rear leg from behind the top of the frame down to the floor
            h = 0.9 * H  # where the leg is hinged on the back, 6 mm into the panel
            top = np.array([-h * math.sin(t) + 0.006 * math.cos(t), 0.0,
                            h * math.cos(t) + 0.006 * math.sin(t) - 0.002])
            foot = np.array([-fd, 0.0, -0.01])
            leg = _bar(top, foot, 0.045, 0.022).trim_by_plane((0, 0, 1), 0.0)
            out.append(Part(leg, "wood"))
        elif style == "cheval":
            Hp = H - 0.14
            zc = 0.12 + Hp / 2
            pw, yp = 0.035, W / 2 + 0.006 + 0.035 / 2
            for s in (-1, 1):
                post = box_between((-pw / 2, s * yp - pw / 2, 0.02), (pw / 2, s * yp + pw / 2,
                                                                      zc + 0.12))
                feet = box_between((-fd / 2, s * yp - pw / 2, 0.0), (fd / 2, s * yp + pw / 2,
                                                                     0.025))
                pin = (rod((0, s * (W / 2 - 0.01), zc), (0, s * (yp + 0.005), zc), 0.006, 12)
                       if detail else box_between((-0.006, s * (W / 2 - 0.01) - 0.006, zc - 0.006),
                                                  (0.006, s * (yp + 0.005) + 0.006, zc + 0.006)))
                out += [Part(post, "wood"), Part(feet, "wood"), Part(pin, "wood")]
        return out
