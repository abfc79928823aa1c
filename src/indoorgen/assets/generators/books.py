"""Books, standing upright: spine facing +X (out of a shelf), thickness along Y."""
from __future__ import annotations

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, box, box_between
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Book(PartsFactory):
    """A hardback: two covers and a spine (flat or rounded) around a page block that is recessed
    at the top and fore-edge and flush at the bottom (so the whole footprint rests)."""

    name = "book"
    tags = frozenset({S.Object, S.SmallObject, S.Book})
    size_class = "small"
    slots = ["cover", "pages"]
    solid_bottom = True
    params = {
        "height": Param(0.18, 0.30, doc="Z extent (m)"),
        "depth": Param(0.12, 0.22, doc="X extent: page width (m)"),
        "thickness": Param(0.015, 0.06, doc="Y extent (m)"),
        "cover_thickness": Param(0.0015, 0.004, doc="board thickness (m)"),
        "page_inset": Param(0.002, 0.005, doc="how far pages sit inside the covers (m)"),
        "spine_style": Param(kind="choice", choices=("flat", "rounded"), doc="spine shape"),
    }

    def _spine_bulge(self, p) -> float:
        return min(0.006, p["thickness"] * 0.15) if p["spine_style"] == "rounded" else 0.0

    def parts(self, p, detail):
        H, D, T = p["height"], p["depth"], p["thickness"]
        ct, pi = p["cover_thickness"], p["page_inset"]
        if not detail:
            return [Part(box((D, T, H), (0, 0, H / 2)), "cover")]
        a = self._spine_bulge(p)
        xs = D / 2 - a  # back face of the spine's flat part / base of the bulge
        out = []
        for s in (-1, 1):
            out.append(Part(box_between((-D / 2, min(s * T / 2, s * (T / 2 - ct)), 0.0),
                                        (xs, max(s * T / 2, s * (T / 2 - ct)), H)), "cover"))
        out.append(Part(box_between((xs - ct, -T / 2 + SMALL_OVERLAP, 0.0), (xs, T / 2 - SMALL_OVERLAP, H)), "cover"))
        if a > 0:
            cyl = m3d.Manifold.cylinder(H, 1.0, -1.0, 32).scale((a, T / 2, 1.0)).translate((xs, 0.0, 0.0))
            out.append(Part(cyl, "cover"))
        out.append(Part(box_between((-D / 2 + pi, -T / 2 + ct - SMALL_OVERLAP, 0.0),
                                    (xs - ct + SMALL_OVERLAP, T / 2 - ct + SMALL_OVERLAP, H - pi)), "pages"))
        return out

    def extra_surfaces(self, p):
        D, T = p["depth"], p["thickness"]
        a = self._spine_bulge(p)
        poly = sg.box(-D / 2, -T / 2, D / 2 - a, T / 2)
        if a > 0:
            ang = np.arange(32) * 2 * np.pi / 32
            ell = sg.Polygon(np.c_[D / 2 - a + a * np.cos(ang), T / 2 * np.sin(ang)])
            poly = poly.union(ell).buffer(-0.0003, join_style="mitre")
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]
